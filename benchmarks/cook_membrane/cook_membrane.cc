// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Cook's membrane at finite strain: dealvem's virtual elements (k = 1, 2)
// against a plain deal.II FE_Q(2) solution of the same problem.
//
// The problem. The tapered panel with corners (0,0), (48,44), (48,60),
// (0,44), clamped on x = 0, loaded on x = 48 by a uniform vertical traction
// of total force F (per unit thickness) given in the reference configuration
// (a dead load). Compressible Neo-Hooke in plane strain (F_zz = 1),
//   psi = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,  I1 = tr(F^T F) + 1,
//   P   = mu F + (lambda ln J - mu) F^{-T},
//   A   = dP/dF = mu I + lambda F^{-T} (x) F^{-T} - (lambda ln J - mu) F^{-T} [x] F^{-1},
// the energy of dealvem::NeoHookeMaterial, with mu = 80.194 and nu = 0.3
// (E = 2 mu (1 + nu) = 208.5044, lambda = 120.291) and F = 100 (traction
// 6.25 on the edge of length 16). The quantity: the vertical displacement of
// the top right corner (48, 60).
//
// 1. The FE_Q(2) reference (class FEReference): a displacement-only total
//    Lagrangian formulation in the manner of deal.II's step-44 and of the
//    code gallery's compressible finite-strain example, with Q2 elements
//    (FESystem of two FE_Q(2)), QGauss(3), Newton's method in N equal load
//    steps, UMFPACK for each update. The mesh is the n x n structured grid
//    of the unit square mapped bilinearly onto the panel. The tip
//    displacement is extrapolated (Richardson) from the three finest meshes
//    with the observed order; that value is the reference.
// 2. dealvem: FiniteStrainAssembler / FiniteStrainSolver on the same quad
//    meshes (converted by PolygonalMeshGenerators::from_triangulation) and on
//    centroidal Voronoi meshes of the unit square whose vertices are mapped
//    onto the panel the same way, k = 1 and 2, the same load steps.
// 3. The cost of one tangent assembly (residual and tangent matrix, with the
//    constraints condensed, into a sparse matrix) per DoF, VEM k = 2 against
//    FE_Q(2) on the same quad mesh (for k = 2 both have 2 (2n + 1)^2 DoFs).
//
// Output: Markdown tables on stdout (benchmarks/cook_membrane/run.sh adds
// the machine notes). Options:
//   --fe-max n    finest FE_Q(2) mesh n x n (default 128; meshes 4, 8, ... n)
//   --vem-max n   finest VEM quad mesh (default 64)
//   --voronoi-max c  largest Voronoi mesh, cells (default 4096; 0: none)
//   --timing-n n  mesh of the assembly timing (default 64)
//   --steps N     load steps (default 10)
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/finite_strain_solver.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/polygonal_mesh.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace Cook
{
  using namespace dealii;

  // ------------------------------------------------------------ the problem
  const double mu_           = 80.194;
  const double nu_           = 0.3;
  const double E_            = 2. * mu_ * (1. + nu_);
  const double lambda_       = E_ * nu_ / ((1. + nu_) * (1. - 2. * nu_));
  const double total_force   = 100.;
  const double traction      = total_force / 16.; // the right edge is 16 long
  const Point<2> tip(48., 60.);

  // The unit square onto the panel: x = 48 s, y from the bottom edge
  // (44 s) to the top edge (44 + 16 s).
  Point<2>
  panel_point(const Point<2> &p)
  {
    const double s = p[0], t = p[1];
    return Point<2>(48. * s, 44. * s + t * (44. - 28. * s));
  }

  // n x n quads on the panel; boundary ids 0 (x = 0, clamped), 1 (x = 48,
  // loaded), 2 and 3 (free); one material id.
  void
  make_panel(Triangulation<2> &tria, const unsigned int n)
  {
    tria.clear();
    GridGenerator::subdivided_hyper_rectangle(tria, {n, n}, Point<2>(0, 0), Point<2>(1, 1), true);
    GridTools::transform(panel_point, tria);
    for (auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
  }

  // ------------------------------------------------ the FE_Q(2) reference
  struct NewtonRecord
  {
    std::vector<unsigned int> iterations_per_step;
  };

  class FEReference
  {
  public:
    FEReference(const unsigned int n, const unsigned int n_steps);
    // the load steps 1 .. last_step (default: all)
    void
    run(const unsigned int last_step = numbers::invalid_unsigned_int);
    // one assembly of residual and tangent at the current solution
    void
    assemble(const double load_factor, const bool with_tangent);
    double
    tip_displacement() const;
    types::global_dof_index
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    NewtonRecord record;

  private:
    void
    setup_system();
    bool
    state_is_admissible(const Vector<double> &u) const;

    const unsigned int        n, n_steps;
    Triangulation<2>          tria;
    const FESystem<2>         fe;
    DoFHandler<2>             dof_handler;
    const QGauss<2>           cell_quadrature;
    const QGauss<1>           face_quadrature;
    AffineConstraints<double> constraints;
    SparsityPattern           sparsity;
    SparseMatrix<double>      tangent;
    Vector<double>            solution, residual, f_ext;
  };

  FEReference::FEReference(const unsigned int n, const unsigned int n_steps)
    : n(n)
    , n_steps(n_steps)
    , fe(FE_Q<2>(2), 2)
    , dof_handler(tria)
    , cell_quadrature(3)
    , face_quadrature(3)
  {
    make_panel(tria, n);
    setup_system();
  }

  void
  FEReference::setup_system()
  {
    dof_handler.distribute_dofs(fe);
    constraints.clear();
    VectorTools::interpolate_boundary_values(dof_handler, 0, Functions::ZeroFunction<2>(2), constraints);
    constraints.close();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    sparsity.copy_from(dsp);
    tangent.reinit(sparsity);
    solution.reinit(dof_handler.n_dofs());
    residual.reinit(dof_handler.n_dofs());

    // the dead load: int_{x = 48} t . phi_i dS, t = (0, traction)
    f_ext.reinit(dof_handler.n_dofs());
    FEFaceValues<2> face_values(fe, face_quadrature, update_values | update_JxW_values);
    Vector<double>  local(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 1)
          {
            face_values.reinit(cell, f);
            local = 0;
            for (unsigned int q = 0; q < face_quadrature.size(); ++q)
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                if (fe.system_to_component_index(i).first == 1)
                  local(i) += traction * face_values.shape_value(i, q) * face_values.JxW(q);
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              f_ext(dofs[i]) += local(i);
          }
  }

  // J > 0 at every quadrature point
  bool
  FEReference::state_is_admissible(const Vector<double> &u) const
  {
    FEValues<2>                  values(fe, cell_quadrature, update_gradients);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, 2>>    grads(cell_quadrature.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        values.reinit(cell);
        values[displacement].get_function_gradients(u, grads);
        for (const auto &g : grads)
          if (determinant(unit_symmetric_tensor<2>() + g) <= 0)
            return false;
      }
    return true;
  }

  // r = lambda f_ext - int P : grad phi_i, and (optionally) the tangent
  // K_ij = int grad phi_i : A : grad phi_j, condensed with the (homogeneous)
  // constraints of the clamped edge.
  void
  FEReference::assemble(const double load_factor, const bool with_tangent)
  {
    FEValues<2> values(fe, cell_quadrature, update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n_q = cell_quadrature.size(), n_i = fe.n_dofs_per_cell();
    std::vector<Tensor<2, 2>>            grads(n_q);
    std::vector<Tensor<2, 2>>            grad_phi(n_i), A_grad_phi(n_i);
    FullMatrix<double>                   local_matrix(n_i, n_i);
    Vector<double>                       local_rhs(n_i);
    std::vector<types::global_dof_index> dofs(n_i);
    if (with_tangent)
      tangent = 0;
    residual = f_ext;
    residual *= load_factor;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        values.reinit(cell);
        values[displacement].get_function_gradients(solution, grads);
        local_matrix = 0;
        local_rhs    = 0;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            Tensor<2, 2> F = grads[q];
            F[0][0] += 1.;
            F[1][1] += 1.;
            const double J = determinant(F);
            AssertThrow(J > 0, ExcMessage("FE_Q(2) reference: an inverted quadrature point"));
            const Tensor<2, 2> F_inv_T = transpose(invert(F));
            const double       c       = lambda_ * std::log(J) - mu_;
            const Tensor<2, 2> P       = mu_ * F + c * F_inv_T;
            const double       w       = values.JxW(q);
            for (unsigned int i = 0; i < n_i; ++i)
              grad_phi[i] = values[displacement].gradient(i, q);
            for (unsigned int i = 0; i < n_i; ++i)
              local_rhs(i) -= scalar_product(P, grad_phi[i]) * w;
            if (!with_tangent)
              continue;
            // A : G = mu G + lambda (F^{-T} : G) F^{-T} - c F^{-T} G^T F^{-T}
            for (unsigned int i = 0; i < n_i; ++i)
              A_grad_phi[i] = mu_ * grad_phi[i] + (lambda_ * scalar_product(F_inv_T, grad_phi[i])) * F_inv_T -
                              c * (F_inv_T * transpose(grad_phi[i]) * F_inv_T);
            for (unsigned int i = 0; i < n_i; ++i)
              for (unsigned int j = 0; j <= i; ++j)
                local_matrix(i, j) += scalar_product(grad_phi[i], A_grad_phi[j]) * w;
          }
        if (with_tangent)
          for (unsigned int i = 0; i < n_i; ++i)
            for (unsigned int j = i + 1; j < n_i; ++j)
              local_matrix(i, j) = local_matrix(j, i);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n_i; ++i)
          residual(dofs[i]) += local_rhs(i);
        if (with_tangent)
          constraints.distribute_local_to_global(local_matrix, dofs, tangent);
      }
    constraints.set_zero(residual);
  }

  void
  FEReference::run(const unsigned int last_step)
  {
    SparseDirectUMFPACK direct;
    Vector<double>      update(dof_handler.n_dofs()), trial(dof_handler.n_dofs());
    for (unsigned int step = 1; step <= std::min(n_steps, last_step); ++step)
      {
        const double load_factor = double(step) / n_steps;
        const double f_norm      = load_factor * f_ext.l2_norm();
        unsigned int it          = 0;
        for (;; ++it)
          {
            AssertThrow(it < 30, ExcMessage("FE_Q(2) reference: Newton did not converge"));
            assemble(load_factor, true);
            if (residual.l2_norm() <= 1e-10 * f_norm)
              break;
            direct.initialize(tangent);
            direct.vmult(update, residual);
            constraints.distribute(update);
            // halve the step while it inverts a point
            double alpha = 1;
            for (unsigned int h = 0;; ++h)
              {
                AssertThrow(h < 20, ExcMessage("FE_Q(2) reference: the line search failed"));
                trial = solution;
                trial.add(alpha, update);
                if (state_is_admissible(trial))
                  break;
                alpha /= 2;
              }
            solution = trial;
          }
        record.iterations_per_step.push_back(it);
      }
  }

  double
  FEReference::tip_displacement() const
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto v : cell->vertex_indices())
        if (cell->vertex(v).distance(tip) < 1e-10)
          return solution(cell->vertex_dof_index(v, 1));
    AssertThrow(false, ExcMessage("no vertex at the tip"));
    return 0;
  }

  // ---------------------------------------------------------------- dealvem
  class ConstantTraction : public Function<2>
  {
  public:
    ConstantTraction()
      : Function<2>(2)
    {}
    double
    value(const Point<2> &, const unsigned int c) const override
    {
      return c == 1 ? traction : 0.;
    }
  };

  struct VEMResult
  {
    unsigned int            n_cells = 0;
    types::global_dof_index n_dofs  = 0;
    double                  tip     = 0;
    std::vector<unsigned int> iterations_per_step;
  };

  // The panel as a quad mesh (n x n) or a Voronoi mesh (n cells).
  void
  make_vem_panel(dealvem::PolygonalMesh<2> &mesh, const std::string &type, const unsigned int n)
  {
    if (type == "quads")
      {
        Triangulation<2> tria;
        make_panel(tria, n);
        dealvem::PolygonalMeshGenerators::from_triangulation(mesh, tria);
      }
    else
      {
        dealvem::PolygonalMeshGenerators::voronoi(mesh, Point<2>(0, 0), Point<2>(1, 1), n, 30, 5);
        for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
          mesh.move_vertex(v, panel_point(mesh.vertex(v)));
        mesh.validate();
      }
  }

  unsigned int
  tip_vertex(const dealvem::PolygonalMesh<2> &mesh)
  {
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      if (mesh.vertex(v).distance(tip) < 1e-10)
        return v;
    AssertThrow(false, ExcMessage("no mesh vertex at the tip"));
    return 0;
  }

  dealvem::MaterialLibrary<2>
  neo_hooke_library(const dealvem::PolygonalMesh<2> &mesh)
  {
    dealvem::MaterialLibrary<2> laws;
    const auto law = std::make_shared<const dealvem::NeoHookeMaterial>(E_, nu_);
    for (const auto id : mesh.get_material_ids())
      laws.add(id, law);
    return laws;
  }

  VEMResult
  run_vem(const std::string &type, const unsigned int n, const unsigned int k, const unsigned int n_steps)
  {
    dealvem::PolygonalMesh<2> mesh;
    make_vem_panel(mesh, type, n);
    dealvem::VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(k);
    const ConstantTraction           load;
    dealvem::FiniteStrainAssembler<2> assembler(dof_handler, neo_hooke_library(mesh));
    assembler.add_traction(1, load);
    AffineConstraints<double> constraints;
    dealvem::BoundaryConditions::interpolate_boundary_values(dof_handler, {0}, Functions::ZeroFunction<2>(2),
                                                             {{true, true}}, constraints);
    constraints.close();
    dealvem::FiniteStrainSolver<2>::Parameters parameters;
    parameters.n_load_steps = n_steps;
    dealvem::FiniteStrainSolver<2> solver(assembler, constraints, parameters);
    solver.run();
    VEMResult result;
    result.n_cells = mesh.n_cells();
    result.n_dofs  = dof_handler.n_dofs();
    result.tip     = solver.get_solution()(dealvem::VEMDoFHandler<2>::node_dof(dof_handler.vertex_node(tip_vertex(mesh)), 1));
    for (const auto &s : solver.get_history())
      result.iterations_per_step.push_back(s.iterations.size() - 1);
    return result;
  }

  std::string
  iteration_text(const std::vector<unsigned int> &its)
  {
    unsigned int lo = its.front(), hi = its.front(), sum = 0;
    for (const auto i : its)
      {
        lo = std::min(lo, i);
        hi = std::max(hi, i);
        sum += i;
      }
    std::ostringstream s;
    s << sum << " (" << lo << "-" << hi << " per step)";
    return s.str();
  }

  // ----------------------------------------------- the timing of assembly
  // Seconds per tangent assembly of VEM k = 2 and FE_Q(2) on the n x n quad
  // mesh at the solution of the first load step (so that F != I), best of
  // n_repeat.
  void
  time_assembly(const unsigned int n, const unsigned int n_repeat, TimerOutput &timer, std::ostream &out)
  {
    FEReference fe_problem(n, 10);
    fe_problem.run(1); // the first of ten load steps: a deformed state
    double fe_best = 1e300;
    for (unsigned int r = 0; r < n_repeat; ++r)
      {
        TimerOutput::Scope scope(timer, "FE_Q(2) tangent assembly");
        Timer              t;
        fe_problem.assemble(0.1, true);
        fe_best = std::min(fe_best, t.wall_time());
      }

    dealvem::PolygonalMesh<2> mesh;
    make_vem_panel(mesh, "quads", n);
    dealvem::VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(2);
    const ConstantTraction            load;
    dealvem::FiniteStrainAssembler<2> assembler(dof_handler, neo_hooke_library(mesh));
    assembler.add_traction(1, load);
    AffineConstraints<double> constraints;
    dealvem::BoundaryConditions::interpolate_boundary_values(dof_handler, {0}, Functions::ZeroFunction<2>(2),
                                                             {{true, true}}, constraints);
    constraints.close();
    dealvem::FiniteStrainSolver<2>::Parameters parameters;
    parameters.n_load_steps = 10;
    dealvem::FiniteStrainSolver<2> solver(assembler, constraints, parameters);
    solver.solve_step(1, 0.1);
    const Vector<double> u = solver.get_solution();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    dof_handler.make_sparsity_pattern(dsp, constraints, false);
    SparsityPattern sparsity;
    sparsity.copy_from(dsp);
    SparseMatrix<double> K(sparsity);
    Vector<double>       residual(dof_handler.n_dofs()), rhs(dof_handler.n_dofs());
    double               vem_best = 1e300;
    for (unsigned int r = 0; r < n_repeat; ++r)
      {
        TimerOutput::Scope scope(timer, "VEM k = 2 tangent assembly");
        Timer              t;
        K   = 0;
        rhs = 0;
        assembler.assemble(u, 0.1, residual, constraints, &K, &rhs);
        vem_best = std::min(vem_best, t.wall_time());
      }
    const double fe_per_dof  = fe_best / fe_problem.n_dofs();
    const double vem_per_dof = vem_best / dof_handler.n_dofs();
    out << "| code | mesh | DoFs | one assembly (s, best of " << n_repeat << ") | us per DoF |\n"
        << "|---|---|---:|---:|---:|\n"
        << "| dealvem VEM k = 2 | " << n << " x " << n << " quads | " << dof_handler.n_dofs() << " | "
        << std::setprecision(4) << vem_best << " | " << std::setprecision(3) << 1e6 * vem_per_dof << " |\n"
        << "| deal.II FE_Q(2), QGauss(3) | " << n << " x " << n << " quads | " << fe_problem.n_dofs() << " | "
        << std::setprecision(4) << fe_best << " | " << std::setprecision(3) << 1e6 * fe_per_dof << " |\n\n"
        << "**Tangent assembly per DoF, VEM k = 2 / FE_Q(2): " << std::setprecision(3) << vem_per_dof / fe_per_dof
        << "**\n\n";
  }
} // namespace Cook

int
main(int argc, char **argv)
{
  using namespace Cook;
  try
    {
      unsigned int fe_max = 128, vem_max = 64, voronoi_max = 4096, timing_n = 64, n_steps = 10;
      for (int a = 1; a + 1 < argc; a += 2)
        {
          const std::string  opt = argv[a];
          const unsigned int val = std::stoul(argv[a + 1]);
          if (opt == "--fe-max")
            fe_max = val;
          else if (opt == "--vem-max")
            vem_max = val;
          else if (opt == "--voronoi-max")
            voronoi_max = val;
          else if (opt == "--timing-n")
            timing_n = val;
          else if (opt == "--steps")
            n_steps = val;
          else
            AssertThrow(false, ExcMessage("unknown option " + opt));
        }
      std::cout << std::setprecision(10);
      std::cout << "Neo-Hooke, plane strain: mu = " << mu_ << ", lambda = " << lambda_ << " (E = " << E_
                << ", nu = " << nu_ << "); total force F = " << total_force << " (traction " << traction
                << "), " << n_steps << " load steps.\n\n";

      // 1. the FE_Q(2) reference
      std::cout << "### deal.II FE_Q(2) reference\n\n"
                << "| mesh | DoFs | tip u_y | difference to previous | observed order | Newton iterations |\n"
                << "|---|---:|---:|---:|---:|---|\n";
      std::vector<double> fe_tip;
      for (unsigned int n = 4; n <= fe_max; n *= 2)
        {
          FEReference problem(n, n_steps);
          problem.run();
          fe_tip.push_back(problem.tip_displacement());
          const unsigned int i = fe_tip.size() - 1;
          std::cout << "| " << n << " x " << n << " | " << problem.n_dofs() << " | " << std::setprecision(10)
                    << fe_tip[i] << " | ";
          if (i > 0)
            std::cout << std::scientific << std::setprecision(3) << fe_tip[i] - fe_tip[i - 1] << std::defaultfloat;
          std::cout << " | ";
          if (i > 1)
            std::cout << std::setprecision(3)
                      << std::log(std::abs((fe_tip[i - 1] - fe_tip[i - 2]) / (fe_tip[i] - fe_tip[i - 1]))) /
                           std::log(2.);
          std::cout << " | " << iteration_text(problem.record.iterations_per_step) << " |" << std::endl;
        }
      AssertThrow(fe_tip.size() >= 3, ExcMessage("--fe-max: at least three meshes (16) for the extrapolation"));
      const unsigned int m     = fe_tip.size() - 1;
      const double       ratio = (fe_tip[m - 1] - fe_tip[m - 2]) / (fe_tip[m] - fe_tip[m - 1]);
      const double       p     = std::log(std::abs(ratio)) / std::log(2.);
      const double       reference = fe_tip[m] + (fe_tip[m] - fe_tip[m - 1]) / (std::pow(2., p) - 1.);
      std::cout << "\nRichardson extrapolation from the three finest meshes (observed order " << std::setprecision(3)
                << p << "): **reference tip u_y = " << std::setprecision(8) << reference
                << "**; estimated error of the finest FE_Q(2) mesh: " << std::scientific << std::setprecision(2)
                << std::abs(reference - fe_tip[m]) / std::abs(reference) << " relative.\n\n"
                << std::defaultfloat;

      // 2. dealvem
      for (const std::string type : {"quads", "voronoi"})
        for (const unsigned int k : {1u, 2u})
          {
            if (type == "voronoi" && voronoi_max == 0)
              continue;
            std::cout << "### dealvem VEM k = " << k << ", " << (type == "quads" ? "mapped quads" : "mapped Voronoi")
                      << "\n\n| cells | DoFs | tip u_y | relative error | Newton iterations (all steps) |\n"
                      << "|---:|---:|---:|---:|---|\n";
            const unsigned int first = (type == "quads" ? 4 : 16);
            const unsigned int last  = (type == "quads" ? vem_max : voronoi_max);
            for (unsigned int n = first; n <= last; n *= (type == "quads" ? 2 : 4))
              {
                const VEMResult r = run_vem(type, n, k, n_steps);
                std::cout << "| " << r.n_cells << " | " << r.n_dofs << " | " << std::setprecision(8) << r.tip
                          << " | " << std::scientific << std::setprecision(2) << (r.tip - reference) / reference
                          << std::defaultfloat << " | " << iteration_text(r.iterations_per_step) << " |"
                          << std::endl;
              }
            std::cout << "\n";
          }

      // 3. the assembly timing
      std::cout << "### Tangent assembly: VEM k = 2 against FE_Q(2)\n\n";
      TimerOutput timer(std::cerr, TimerOutput::summary, TimerOutput::wall_times);
      time_assembly(timing_n, 5, timer, std::cout);
    }
  catch (std::exception &exc)
    {
      std::cerr << "\n----------------------------------------------------\n"
                << "Exception: " << exc.what() << "\n----------------------------------------------------"
                << std::endl;
      return 1;
    }
  return 0;
}
