// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// step-10: virtual elements at finite strain.
//
// Build (from a dealvem build directory):   make step-10
// Run:                                      ./examples/step-10 [--study] [--write-doc-picture]
// What it does, in three parts:
// 1. A rigid rotation by 90 degrees, imposed through the boundary of the
//    unit square (64 Voronoi cells, k = 2, Neo-Hooke): the finite-strain
//    element reproduces it with zero stress to round-off; the linear law
//    under the same boundary data gives the spurious stress -2 (lambda + mu) I.
// 2. Cook's membrane (compressible Neo-Hooke, a dead shear load on the
//    free end, 10 load steps) on mapped quad and Voronoi meshes, k = 1 and
//    2: the tip displacement against the deal.II FE_Q(2) reference 8.69919
//    (doc/benchmarks.md), a convergence table, and the Newton history of
//    the last load step.
// 3. Pictures: the deformed polygons of Cook's membrane at several load
//    steps as an SVG, and one VTU file per load step with a .pvd that
//    ParaView plays as a time series.
// The program exits with an error (AssertThrow) if a check fails: the
// stress of the rotation, the error decreasing under refinement, the
// finest mesh within a stated tolerance of the reference, and the
// quadratic convergence of Newton's method.
// --study runs finer meshes (k = 1 and 2 on both mesh families);
// --write-doc-picture writes the SVG into doc/ of the source tree.

// @sect3{Include files}
//
// deal.II for the triangulation that is mapped onto Cook's panel, the
// constraints, the sparse direct solver of the linear comparison and the
// timer; dealvem for the meshes, the virtual element DoFs and
// the three finite-strain classes: the laws (hyperelastic_material.h), the
// assembler of residual and tangent, and the Newton solver with load
// steps.
#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/finite_strain_solver.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/postprocessing/finite_strain_output.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/vem_values.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace Step10
{
  using namespace dealvem;
  using Point  = dealii::Point<2>;
  using Tensor = dealii::Tensor<2, 2>;

  // @sect3{Small helpers}
  //
  // One law for every material id of a mesh (the meshes here have one
  // body), and a Function for a displacement that is affine in the
  // reference position, $u(X) = (M - I)(X - X_0)$: the boundary data of the
  // rotation.
  MaterialLibrary<2>
  one_law(const PolygonalMesh<2> &mesh, const ConstitutiveLaw<2> &law)
  {
    MaterialLibrary<2>                          laws;
    std::shared_ptr<const ConstitutiveLaw<2>> shared(law.clone().release());
    for (const auto id : mesh.get_material_ids())
      laws.add(id, shared);
    return laws;
  }

  class AffineDisplacement : public dealii::Function<2>
  {
  public:
    AffineDisplacement(const Tensor &M, const Point &X0)
      : dealii::Function<2>(2)
      , M(M)
      , X0(X0)
    {}

    double
    value(const Point &X, const unsigned int component) const override
    {
      const dealii::Tensor<1, 2> d = X - X0;
      return M[component] * d - d[component];
    }

  private:
    const Tensor M;
    const Point  X0;
  };

  // The deformation gradients $F_q = I + \Pi^0_{k-1}\nabla u_h(x_q)$ at the
  // quadrature points of cell @p c: what FiniteStrainOperator computes
  // inside the assembler, here from VEMValues for the post-processing.
  std::vector<Tensor>
  deformation_gradients(VEMValues<2> &values, const unsigned int c, const dealii::Vector<double> &u)
  {
    std::vector<Tensor> F;
    values.reinit(c);
    values.get_function_gradient_projections(u, F);
    for (Tensor &f : F)
      for (unsigned int d = 0; d < 2; ++d)
        f[d][d] += 1.;
    return F;
  }

  // @sect3{Part 1: a rigid rotation}
  //
  // The unit square on 64 centroidal Voronoi cells, $k = 2$, Neo-Hooke with
  // $E = 7000$, $\nu = 0.3$ in plane strain. The whole boundary gets the
  // displacement of the rotation by $90^\circ$ about $X_0 = (0.3, 0.2)$,
  // $u = (R - I)(X - X_0)$, in 6 load steps: FiniteStrainSolver scales the
  // boundary data by the load factor $\lambda$, so the intermediate states
  // are $F = (1-\lambda)I + \lambda R$, a rotation combined with a shrinking
  // ($J = 1/2$ at $\lambda = 1/2$), and the last is the rotation. The exact
  // solution of every step is affine, which the virtual element space holds:
  // the DoFs must be exact, $F = R$ at every quadrature point, and the stress
  // zero, to round-off.
  //
  // The linear law (ElasticMaterial, the same $E$ and $\nu$) under the same
  // boundary data also reproduces the displacement, since it is linear, but
  // its strain $\varepsilon = \mathrm{sym}(R - I) = -I$ is not zero: its
  // stress is $C:\varepsilon = -2(\lambda+\mu)I = -1.92\,E\,I$, a stress in a
  // body that has only turned.
  void
  rigid_rotation()
  {
    std::cout << "=== Part 1: rigid rotation by 90 degrees through the boundary ===" << std::endl;
    const double E = 7000., nu = 0.3;
    const Point  X0(0.3, 0.2);
    Tensor       R;
    R[0][1] = -1.;
    R[1][0] = 1.;
    const AffineDisplacement rotation(R, X0);

    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::voronoi(mesh, Point(0, 0), Point(1, 1), 64, 30, 4);
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(2);
    std::cout << "mesh: " << mesh.n_cells() << " Voronoi cells, k = 2, " << dof_handler.n_dofs() << " DoFs"
              << std::endl;

    // The constraints of the full rotation on the four sides (ids 0 to 3):
    // the solver imposes $\lambda$ times them at the load factor $\lambda$.
    dealii::AffineConstraints<double> constraints;
    BoundaryConditions::interpolate_boundary_values(dof_handler, {0, 1, 2, 3}, rotation, {{true, true}},
                                                    constraints);
    constraints.close();

    const NeoHookeMaterial   neo_hooke(E, nu);
    FiniteStrainAssembler<2> assembler(dof_handler, one_law(mesh, neo_hooke));
    FiniteStrainSolver<2>::Parameters parameters;
    parameters.n_load_steps = 6;
    FiniteStrainSolver<2> solver(assembler, constraints, parameters);
    solver.run();
    const dealii::Vector<double> &u = solver.get_solution();

    // The errors: every DoF against the rotation at its support point (the
    // vertex, the edge midpoint or, for the cell moment, the centroid: the
    // moment of an affine field is its value at the centroid), and at every
    // quadrature point $|F - R|$, $|P|$ and $|\sigma|$.
    std::vector<Point> support;
    dof_handler.map_dofs_to_support_points(support);
    double err_u = 0, u_max = 0;
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        err_u = std::max(err_u, std::abs(u[i] - rotation.value(support[i], i % 2)));
        u_max = std::max(u_max, std::abs(rotation.value(support[i], i % 2)));
      }
    VEMValues<2> values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values);
    double       err_F = 0, max_P = 0, max_sigma = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      for (const Tensor &F : deformation_gradients(values, c, u))
        {
          err_F     = std::max(err_F, (F - R).norm());
          max_P     = std::max(max_P, neo_hooke.first_piola_kirchhoff_stress(F).norm());
          max_sigma = std::max(max_sigma, neo_hooke.cauchy_stress(F).norm());
        }
    std::cout << "Neo-Hooke, Newton updates per load step:";
    for (const auto &s : solver.get_history())
      std::cout << ' ' << s.iterations.size() - 1;
    std::cout << std::endl
              << std::scientific << std::setprecision(2) << "  max |u_h - u| / max |u| = " << err_u / u_max
              << "\n  max |F - R|              = " << err_F << "\n  max |P| / E              = " << max_P / E
              << "\n  max |sigma| / E          = " << max_sigma / E << std::defaultfloat << std::endl;
    AssertThrow(err_u <= 1e-10 * u_max,
                dealii::ExcMessage("rotation: the displacement is not the rotation to 1e-10 of max |u|"));
    AssertThrow(err_F <= 1e-10, dealii::ExcMessage("rotation: F is not R to 1e-10 at every quadrature point"));
    AssertThrow(max_P <= 1e-10 * E && max_sigma <= 1e-10 * E,
                dealii::ExcMessage("rotation: the finite-strain stress of a rigid rotation is not zero to 1e-10 E"));

    // The linear law: one linear solve with the same constraints (the full
    // rotation at once), ElasticityAssembler and UMFPACK, and its stress
    // $C:\varepsilon(\Pi u_h)$ at the quadrature points.
    const ElasticMaterial          linear(E, nu, ElasticMaterial::Model::plane_strain);
    dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
    dof_handler.make_sparsity_pattern(dsp, constraints);
    dealii::SparsityPattern sparsity;
    sparsity.copy_from(dsp);
    dealii::SparseMatrix<double> A(sparsity);
    dealii::Vector<double>       b, x(dof_handler.n_dofs());
    ElasticityAssembler<2>       linear_assembler(dof_handler, one_law(mesh, linear));
    linear_assembler.assemble(constraints, A, b);
    dealii::SparseDirectUMFPACK direct;
    direct.initialize(A);
    direct.vmult(x, b);
    constraints.distribute(x);
    const double expected = -2. * (linear.lambda() + linear.mu());
    double       max_linear = 0, err_linear = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      for (const Tensor &F : deformation_gradients(values, c, x))
        {
          Tensor grad = F; // the gradient of the projection, F - I
          grad[0][0] -= 1.;
          grad[1][1] -= 1.;
          const dealii::SymmetricTensor<2, 2> s = linear.stress(dealii::symmetrize(grad));
          max_linear = std::max(max_linear, s.norm());
          err_linear = std::max({err_linear, std::abs(s[0][0] - expected), std::abs(s[1][1] - expected),
                                 std::abs(s[0][1])});
        }
    std::cout << "linear law under the same boundary data:\n  max |sigma| / E          = " << std::setprecision(4)
              << max_linear / E << "  (sigma = -2 (lambda + mu) I = " << expected / E << " E I)" << std::endl;
    AssertThrow(err_linear <= 1e-8 * std::abs(expected),
                dealii::ExcMessage("rotation: the stress of the linear law is not -2 (lambda + mu) I to 1e-8"));
  }

  // @sect3{Part 2: Cook's membrane}
  //
  // The tapered panel with corners $(0,0)$, $(48,44)$, $(48,60)$, $(0,44)$:
  // the unit square mapped onto it, $x = 48s$,
  // $y = 44s + t\,(44 - 28s)$. Two mesh families, both mapped by this
  // function: the $n\times n$ grid of deal.II (colorized: boundary id 0 on
  // the left side, 1 on the right), and centroidal Voronoi meshes of the
  // unit square (30 Lloyd iterations, seed 5) with their vertices moved.
  // Only the vertices are mapped, the edges stay straight between them;
  // the sides of the square are lines $s$ or $t$ = const, which the
  // bilinear map keeps straight, so both meshes cover the panel exactly.
  Point
  panel_point(const Point &p)
  {
    return Point(48. * p[0], 44. * p[0] + p[1] * (44. - 28. * p[0]));
  }

  const Point  tip(48., 60.);
  const double reference_tip = 8.69919; // deal.II FE_Q(2), extrapolated (doc/benchmarks.md)

  void
  make_panel(PolygonalMesh<2> &mesh, const std::string &family, const unsigned int n)
  {
    if (family == "quads")
      {
        dealii::Triangulation<2> tria;
        dealii::GridGenerator::subdivided_hyper_rectangle(tria, {n, n}, Point(0, 0), Point(1, 1), true);
        dealii::GridTools::transform(panel_point, tria);
        PolygonalMeshGenerators::from_triangulation(mesh, tria);
      }
    else
      {
        PolygonalMeshGenerators::voronoi(mesh, Point(0, 0), Point(1, 1), n, 30, 5);
        for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
          mesh.move_vertex(v, panel_point(mesh.vertex(v)));
        mesh.validate();
      }
  }

  // The load: a vertical nominal traction on the right edge (length 16 in
  // the reference configuration) with resultant 100, a dead load: per unit
  // reference length, always vertical, whatever the edge does.
  class ShearLoad : public dealii::Function<2>
  {
  public:
    ShearLoad()
      : dealii::Function<2>(2)
    {}

    double
    value(const Point &, const unsigned int component) const override
    {
      return component == 1 ? 100. / 16. : 0.;
    }
  };

  // @sect4{What one run keeps}
  //
  // For the picture: the deformed position of every node (vertex, edge
  // midpoint) at some of the load steps.
  struct DeformedState
  {
    double             load_factor = 0;
    std::vector<Point> node_position;
  };

  struct CookRun
  {
    std::string                             family;
    unsigned int                            k = 0, n = 0, n_cells = 0, n_dofs = 0;
    double                                  tip_u_y = 0;
    std::vector<unsigned int>               updates; // Newton updates per load step
    std::vector<FiniteStrainSolver<2>::StepRecord> history;
    std::vector<DeformedState>              states;  // only when asked for

    double
    error() const
    {
      return (tip_u_y - reference_tip) / reference_tip;
    }
  };

  std::vector<Point>
  node_positions(const VEMDoFHandler<2> &dof_handler, const dealii::Vector<double> &u)
  {
    std::vector<Point> x(dof_handler.n_nodes());
    for (unsigned int node = 0; node < dof_handler.n_nodes(); ++node)
      {
        x[node] = dof_handler.node_location(node);
        for (unsigned int d = 0; d < 2; ++d)
          x[node][d] += u[VEMDoFHandler<2>::node_dof(node, d)];
      }
    return x;
  }

  // @sect4{One run}
  //
  // Mesh, DoFs, the law, the assembler with the traction on boundary id 1,
  // the clamped left side (id 0) as constraints, and the solver with 10 load
  // steps, driven step by step with FiniteStrainSolver::solve_step() (what
  // FiniteStrainSolver::run() does) so that the states between the steps
  // can be written: with @p output_prefix not empty, one VTU file per load
  // step (the reference state as step 0) and the .pvd that lists them with
  // their load factors, and the deformed nodes of every second step for
  // the SVG.
  CookRun
  solve_cook(const std::string &family, const unsigned int n, const unsigned int k, const std::string &output_prefix)
  {
    PolygonalMesh<2> mesh;
    make_panel(mesh, family, n);
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(k);

    const NeoHookeMaterial   law(2. * 80.194 * 1.3, 0.3); // mu = E / (2 (1 + nu)) = 80.194
    const MaterialLibrary<2> laws = one_law(mesh, law);
    FiniteStrainAssembler<2> assembler(dof_handler, laws);
    const ShearLoad          load;
    assembler.add_traction(1, load);
    dealii::AffineConstraints<double> constraints;
    BoundaryConditions::interpolate_boundary_values(dof_handler, {0}, dealii::Functions::ZeroFunction<2>(2),
                                                    {{true, true}}, constraints);
    constraints.close();

    FiniteStrainSolver<2>::Parameters parameters;
    parameters.n_load_steps = 10;
    FiniteStrainSolver<2> solver(assembler, constraints, parameters);

    CookRun run;
    run.family  = family;
    run.k       = k;
    run.n       = n;
    run.n_cells = mesh.n_cells();
    run.n_dofs  = dof_handler.n_dofs();

    std::vector<std::pair<double, std::string>> series;
    const auto write_state = [&](const unsigned int step) {
      if (output_prefix.empty())
        return;
      std::ostringstream name;
      name << output_prefix << "-" << std::setw(2) << std::setfill('0') << step << ".vtu";
      write_finite_strain_vtu_file(name.str(), dof_handler, laws, solver.get_solution());
      series.emplace_back(solver.get_load_factor(), name.str());
      if (step % 2 == 0)
        run.states.push_back({solver.get_load_factor(), node_positions(dof_handler, solver.get_solution())});
    };
    write_state(0);
    for (unsigned int step = 1; step <= parameters.n_load_steps; ++step)
      {
        solver.solve_step(step, static_cast<double>(step) / parameters.n_load_steps);
        write_state(step);
      }
    if (!output_prefix.empty())
      write_pvd_record(output_prefix + ".pvd", series);

    run.history = solver.get_history();
    for (const auto &s : run.history)
      run.updates.push_back(s.iterations.size() - 1);
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      if (mesh.vertex(v).distance(tip) < 1e-10)
        {
          run.tip_u_y = solver.get_solution()(VEMDoFHandler<2>::node_dof(dof_handler.vertex_node(v), 1));
          return run;
        }
    AssertThrow(false, dealii::ExcMessage("Cook's membrane: no mesh vertex at the tip (48, 60)"));
    return run;
  }

  // @sect4{Newton's convergence}
  //
  // Newton's method with an exact tangent converges quadratically near the
  // solution: the relative residuals $e_i = \|r_i\|/F_{ref}$ satisfy
  // $e_{i+1} \le C e_i^2$. The check takes each pair of successive
  // iterates of a load step with $10^{-6} \le e_i < 10^{-2}$: below
  // $10^{-2}$ the iteration is in its quadratic region, and from $10^{-6}$
  // on $e_i^2 \ge 10^{-12}$, so the round-off floor of the residual (about
  // $10^{-12}$ here) cannot inflate the ratio beyond 1. The ratio
  // $e_{i+1}/e_i^2$ must be at most 100. A linearly converging iteration
  // with the rate $\rho$ has $e_{i+1}/e_i^2 = \rho/e_i$, above 100 once
  // $e_i < \rho/100$; and it would need about ten updates per load step
  // to go from 1 to $10^{-10}$ with $\rho = 0.1$, so the number of updates
  // per step is bounded too (at most 8; Newton needs 4 to 5 here).
  // Returns the largest ratio and counts the pairs.
  double
  largest_quadratic_ratio(const FiniteStrainSolver<2>::StepRecord &step, unsigned int &n_pairs)
  {
    double ratio = 0;
    for (unsigned int i = 0; i + 1 < step.iterations.size(); ++i)
      {
        const double e0 = step.iterations[i].relative_residual, e1 = step.iterations[i + 1].relative_residual;
        if (e0 >= 1e-6 && e0 < 1e-2)
          {
            ratio = std::max(ratio, e1 / (e0 * e0));
            ++n_pairs;
          }
      }
    return ratio;
  }

  // @sect4{A refinement sequence}
  //
  // One mesh family and order on a list of sizes ($n$ the cells per side
  // for quads, the number of cells for Voronoi). The table has, per mesh,
  // the cells, the DoFs, the tip displacement, the relative error against
  // the reference, the order of convergence in $h \sim N_{DoF}^{-1/2}$
  // from the previous mesh, and the Newton updates per load step (the
  // fewest and the most, and the total). Checks: the error falls from mesh to mesh, the
  // finest mesh is within @p tolerance of the reference, every step of
  // every run converges quadratically.
  struct Sequence
  {
    std::string               family;
    unsigned int              k;
    std::vector<unsigned int> sizes;
    double                    tolerance; // |relative error| on the finest mesh
  };

  std::vector<CookRun>
  run_sequence(const Sequence &seq, const std::string &output_prefix, const unsigned int output_size)
  {
    std::cout << "\n--- Cook's membrane, " << seq.family << ", k = " << seq.k << std::endl;
    std::vector<CookRun> runs;
    std::cout << "| cells | DoFs  | tip u_y  | rel. error | order in h | Newton updates per step (total) |\n"
              << "|------:|------:|---------:|-----------:|-----------:|--------------------------------:|\n";
    for (const unsigned int n : seq.sizes)
      {
        runs.push_back(solve_cook(seq.family, n, seq.k, n == output_size ? output_prefix : std::string()));
        const CookRun &r = runs.back();
        const auto [lo, hi] = std::minmax_element(r.updates.begin(), r.updates.end());
        unsigned int total  = 0;
        for (const unsigned int u : r.updates)
          total += u;
        // the order in h ~ N_DoF^(-1/2) from the previous mesh
        std::string order = "-";
        if (runs.size() > 1)
          {
            const CookRun     &p = runs[runs.size() - 2];
            std::ostringstream o;
            o << std::fixed << std::setprecision(2)
              << -2 * std::log(std::abs(r.error() / p.error())) / std::log(double(r.n_dofs) / p.n_dofs);
            order = o.str();
          }
        std::cout << "| " << std::setw(5) << r.n_cells << " | " << std::setw(5) << r.n_dofs << " | " << std::fixed
                  << std::setprecision(5) << std::setw(8) << r.tip_u_y << " | " << std::scientific
                  << std::setprecision(2) << std::setw(10) << r.error() << " | " << std::setw(10) << order << " | "
                  << std::setw(31) << (std::to_string(*lo) + "-" + std::to_string(*hi) + " (" + std::to_string(total) + ")")
                  << " |" << std::defaultfloat << std::endl;
      }

    const std::string name = "Cook's membrane, " + seq.family + ", k = " + std::to_string(seq.k);
    for (unsigned int i = 1; i < runs.size(); ++i)
      AssertThrow(std::abs(runs[i].error()) < std::abs(runs[i - 1].error()),
                  dealii::ExcMessage(name + ": the error of the tip displacement does not decrease from " +
                                     std::to_string(runs[i - 1].n_dofs) + " to " + std::to_string(runs[i].n_dofs) +
                                     " DoFs"));
    AssertThrow(std::abs(runs.back().error()) <= seq.tolerance,
                dealii::ExcMessage(name + ": the finest mesh is not within " + std::to_string(100 * seq.tolerance) +
                                   " % of the reference tip displacement (error " +
                                   std::to_string(100 * runs.back().error()) + " %)"));
    for (const CookRun &r : runs)
      for (const auto &step : r.history)
        {
          unsigned int n_pairs = 0;
          const double ratio   = largest_quadratic_ratio(step, n_pairs);
          AssertThrow(step.converged && ratio <= 100. && step.iterations.size() - 1 <= 8,
                      dealii::ExcMessage(name + ", " + std::to_string(r.n_dofs) + " DoFs, load step " +
                                         std::to_string(step.step) +
                                         ": Newton does not converge quadratically (largest e_{i+1}/e_i^2 = " +
                                         std::to_string(ratio) + ", at most 100 allowed; at most 8 updates allowed):\n" +
                                         FiniteStrainSolver<2>::step_history_text(step)));
        }
    return runs;
  }

  // @sect3{Part 3: the picture}
  //
  // The deformed polygons, drawn with their edges: for $k = 1$ the trace of
  // the displacement on an edge is linear, a straight segment between the
  // deformed vertices; for $k = 2$ it is quadratic, and the deformed edge is
  // the parabola through the deformed end points $a$, $b$ and midpoint $m$,
  // which SVG draws exactly as the quadratic Bézier curve with the control
  // point $2m - (a + b)/2$. The picture shows the boundary of the panel at
  // every second load step (the reference configuration grey) and the whole
  // mesh at the full load; the tip is marked.
  void
  write_svg(const std::string &filename, const PolygonalMesh<2> &mesh, const VEMDoFHandler<2> &dof_handler,
            const std::vector<DeformedState> &states, const CookRun &run)
  {
    // the bounding box of all states, and the map to pixels (y up)
    double x_min = 1e300, x_max = -1e300, y_min = 1e300, y_max = -1e300;
    for (const auto &s : states)
      for (const Point &p : s.node_position)
        {
          x_min = std::min(x_min, p[0]);
          x_max = std::max(x_max, p[0]);
          y_min = std::min(y_min, p[1]);
          y_max = std::max(y_max, p[1]);
        }
    const double scale = 6, margin = 20, width = std::max(scale * (x_max - x_min) + 2 * margin + 120, 470.),
                 height = scale * (y_max - y_min) + 2 * margin + 50;
    std::ostringstream out;
    out << std::fixed << std::setprecision(1);
    const auto px = [&](const Point &p) {
      std::ostringstream s;
      s << std::fixed << std::setprecision(1) << margin + scale * (p[0] - x_min) << ","
        << margin + 30 + scale * (y_max - p[1]);
      return s.str();
    };
    // the path of edge e in state s, from its first vertex (or reversed)
    const auto edge_path = [&](const DeformedState &s, const unsigned int e, const bool reversed, const bool move) {
      const auto &edge = mesh.edge(e);
      const Point a    = s.node_position[dof_handler.vertex_node(edge.vertices[reversed ? 1 : 0])];
      const Point b    = s.node_position[dof_handler.vertex_node(edge.vertices[reversed ? 0 : 1])];
      std::string path = move ? "M" + px(a) : "";
      if (run.k == 2)
        {
          const Point m = s.node_position[dof_handler.edge_node(e)];
          const Point c(2 * m[0] - 0.5 * (a[0] + b[0]), 2 * m[1] - 0.5 * (a[1] + b[1]));
          return path + "Q" + px(c) + " " + px(b);
        }
      return path + "L" + px(b);
    };
    // the boundary as one closed loop: the boundary edges are oriented
    // counter-clockwise, chain them by their first vertex
    std::map<unsigned int, unsigned int> edge_from;
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      if (mesh.edge(e).at_boundary())
        edge_from[mesh.edge(e).vertices[0]] = e;
    const auto outline = [&](const DeformedState &s) {
      std::string  path;
      unsigned int e = edge_from.begin()->second;
      for (unsigned int i = 0; i < edge_from.size(); ++i)
        {
          path += edge_path(s, e, false, i == 0);
          e = edge_from.at(mesh.edge(e).vertices[1]);
        }
      return path + "Z";
    };

    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << margin << "\" y=\"18\">Cook's membrane, Neo-Hooke, " << run.n << " x " << run.n
        << " quads, k = " << run.k << "</text>\n<text x=\"" << margin << "\" y=\"" << height - 8
        << "\" font-size=\"11\">grey: reference; blue: the boundary every second load step; orange: full load</text>\n";
    const char *colours[] = {"#999999", "#9ecae1", "#6baed6", "#3182bd", "#08519c", "#08306b"};
    for (unsigned int i = 0; i < states.size(); ++i)
      {
        const bool last = (i + 1 == states.size());
        out << "<path d=\"" << outline(states[i]) << "\" fill=\"" << (i == 0 ? "#eeeeee" : last ? "#fdd0a2" : "none")
            << "\" stroke=\"" << colours[std::min<std::size_t>(i, 5)] << "\" stroke-width=\"" << (last ? 1.5 : 1)
            << "\"/>\n";
      }
    // the whole mesh at the full load, every edge once
    out << "<path fill=\"none\" stroke=\"#7f2704\" stroke-width=\"0.6\" d=\"";
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      if (!mesh.edge(e).at_boundary())
        out << edge_path(states.back(), e, false, true);
    out << "\"/>\n";
    // the tip in every state, with its load factor
    unsigned int tip_node = 0;
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      if (mesh.vertex(v).distance(tip) < 1e-10)
        tip_node = dof_handler.vertex_node(v);
    for (const auto &s : states)
      {
        const std::string p = px(s.node_position[tip_node]);
        const auto        comma = p.find(',');
        out << "<circle cx=\"" << p.substr(0, comma) << "\" cy=\"" << p.substr(comma + 1)
            << "\" r=\"2\"/><text x=\"" << std::stod(p.substr(0, comma)) + 6 << "\" y=\""
            << std::stod(p.substr(comma + 1)) + 4 << "\" font-size=\"10\">load " << std::setprecision(1) << s.load_factor << "</text>\n";
      }
    out << "</svg>\n";
    std::ofstream file(filename);
    file << out.str();
    file.close();
    AssertThrow(file, dealii::ExcMessage("step-10: cannot write the picture " + filename +
                                         " (with --write-doc-picture the path comes from __FILE__, which "
                                         "may be relative to the build directory: run from there)"));
  }
} // namespace Step10


// @sect3{The main function}
//
// Part 1, then the refinement sequences of Cook's membrane: the default
// run takes quads with $k = 1$ ($n = 4 \ldots 32$) and $k = 2$
// ($n = 4 \ldots 16$) and Voronoi meshes with $k = 2$ (16 to 256 cells);
// --study goes two or more refinements further and adds Voronoi with
// $k = 1$. The tolerances on the finest mesh: 0.5 % for the default
// sequences (the measured errors are 0.47 %, 0.36 % and 0.28 %), 0.2 %
// ($k = 1$) and 0.1 % ($k = 2$) for the study's (measured: 0.15 %,
// 0.054 %, 0.12 %, 0.046 %, doc/benchmarks.md). The outputs come from the
// $8\times 8$ quad mesh with $k = 2$; the Newton history printed is the last
// load step of the finest quad mesh with $k = 2$.
int
main(int argc, char **argv)
{
  using namespace Step10;
  try
    {
      bool study = false, doc_picture = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string a = argv[i];
          if (a == "--study")
            study = true;
          else if (a == "--write-doc-picture")
            doc_picture = true;
          else
            {
              std::cerr << "usage: step-10 [--study] [--write-doc-picture]" << std::endl;
              return 2;
            }
        }
      dealii::Timer timer;

      rigid_rotation();

      std::cout << "\n=== Part 2: Cook's membrane (Neo-Hooke, mu = 80.194, nu = 0.3, shear load 100, 10 load steps) ==="
                << "\nreference tip u_y = " << std::setprecision(6) << reference_tip << " (deal.II FE_Q(2), extrapolated)" << std::endl;
      std::vector<Sequence> sequences;
      if (!study)
        sequences = {{"quads", 1, {4, 8, 16, 32}, 5e-3},
                     {"quads", 2, {4, 8, 16}, 5e-3},
                     {"voronoi", 2, {16, 64, 256}, 5e-3}};
      else
        sequences = {{"quads", 1, {4, 8, 16, 32, 64}, 2e-3},
                     {"quads", 2, {4, 8, 16, 32, 64}, 1e-3},
                     {"voronoi", 1, {16, 64, 256, 1024, 4096}, 2e-3},
                     {"voronoi", 2, {16, 64, 256, 1024, 4096}, 1e-3}};
      std::vector<CookRun> quads_k2;
      for (const Sequence &seq : sequences)
        {
          const bool with_output = (seq.family == "quads" && seq.k == 2);
          auto       runs        = run_sequence(seq, with_output ? "cook" : "", with_output ? 8 : 0);
          if (with_output)
            quads_k2 = runs;
        }

      // The Newton history of the last load step, finest quads, k = 2.
      const CookRun &finest = quads_k2.back();
      std::cout << "\n--- Newton history of the last load step, " << finest.n << " x " << finest.n
                << " quads, k = 2 (" << finest.n_dofs << " DoFs)\n"
                << FiniteStrainSolver<2>::step_history_text(finest.history.back());
      unsigned int n_pairs = 0;
      const double ratio   = largest_quadratic_ratio(finest.history.back(), n_pairs);
      std::cout << "largest e_{i+1} / e_i^2 = " << std::setprecision(3) << ratio << " over " << n_pairs
                << " pair(s) of iterates with 1e-6 <= e_i < 1e-2" << std::endl;
      AssertThrow(n_pairs >= 1,
                  dealii::ExcMessage("Newton history: no pair of iterates in the quadratic region to judge the rate"));

      // Part 3: the picture, from the 8 x 8 run (the VTU files and the .pvd
      // were written during the run).
      const auto it = std::find_if(quads_k2.begin(), quads_k2.end(), [](const CookRun &r) { return r.n == 8; });
      AssertThrow(it != quads_k2.end() && !it->states.empty(), dealii::ExcMessage("no 8 x 8 run with output"));
      PolygonalMesh<2> mesh;
      make_panel(mesh, "quads", 8);
      VEMDoFHandler<2> dof_handler(mesh);
      dof_handler.distribute_dofs(2);
      const std::string picture =
        doc_picture ? (std::filesystem::path(__FILE__).parent_path() / "doc" / "cook-deformed.svg").string() :
                      std::string("cook-deformed.svg");
      write_svg(picture, mesh, dof_handler, it->states, *it);
      std::cout << "\npictures: " << picture << "; cook-00.vtu ... cook-10.vtu with cook.pvd (ParaView)"
                << std::endl;
      std::cout << "run time: " << std::fixed << std::setprecision(1) << timer.wall_time() << " s" << std::endl;
    }
  catch (std::exception &exc)
    {
      std::cerr << std::endl << "Exception: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
