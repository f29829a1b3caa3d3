// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// step-1: linear elasticity with second-order virtual elements on
// centroidal Voronoi meshes -- a cantilever against Timoshenko's solution.
//
// Build (from a dealvem build directory):   make step-1
// Run:                                      ./examples/step-1 [k]
// What it does: solves a plane-stress cantilever [0,L]x[-D/2,D/2] loaded by
// a parabolic shear traction at its free end, on four Voronoi meshes, and
// prints the convergence table of the errors against the exact solution
// (Timoshenko & Goodier, Theory of Elasticity, sec. 21). Writes
// step-1-<cycle>.vtu for ParaView and step-1-von-mises.svg.
//
// The matrices D, B, G, the projector and the stabilization that the
// VirtualElement class builds are defined in doc/intro.dox.

// @sect3{Include files}
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <dealvem/app/input_parsing.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/constitutive_law.h>
#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/postprocessing/error_norms.h>
#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/postprocessing/svg_plots.h>
#include <dealvem/postprocessing/vtu_output.h>
#include <dealvem/solvers/linear_solver.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/vem_values.h>

#include <fstream>
#include <iostream>
#include <string>

namespace Step1
{
  using namespace dealvem;

  // @sect3{The exact solution}
  //
  // Timoshenko's cantilever: with $I = D^3/12$ (unit thickness),
  // $u_x = -\frac{Py}{6EI}\left[(6L-3x)x + (2+\nu)(y^2 - D^2/4)\right]$,
  // $u_y = \frac{P}{6EI}\left[3\nu y^2(L-x) + (4+5\nu)\frac{D^2x}{4} + (3L-x)x^2\right]$,
  // so $\sigma_{xx} = -P(L-x)y/I$, $\sigma_{yy} = 0$,
  // $\sigma_{xy} = \frac{P}{2I}(D^2/4 - y^2)$. The gradient is written out
  // because the error norms need it.
  struct BeamData
  {
    double L = 10, D = 2, P = 1, E = 1000, nu = 0.3;
    double
    I() const
    {
      return D * D * D / 12.;
    }
  };

  class ExactDisplacement : public dealii::Function<2>
  {
  public:
    explicit ExactDisplacement(const BeamData &b)
      : dealii::Function<2>(2)
      , b(b)
    {}

    double
    value(const dealii::Point<2> &p, const unsigned int c) const override
    {
      const double x = p[0], y = p[1], L = b.L, D = b.D, k = b.P / (6 * b.E * b.I());
      if (c == 0)
        return -k * y * ((6 * L - 3 * x) * x + (2 + b.nu) * (y * y - D * D / 4));
      return k * (3 * b.nu * y * y * (L - x) + (4 + 5 * b.nu) * D * D * x / 4 + (3 * L - x) * x * x);
    }

    dealii::Tensor<1, 2>
    gradient(const dealii::Point<2> &p, const unsigned int c) const override
    {
      const double x = p[0], y = p[1], L = b.L, D = b.D, k = b.P / (6 * b.E * b.I());
      dealii::Tensor<1, 2> g;
      if (c == 0)
        {
          g[0] = -k * y * (6 * L - 6 * x);
          g[1] = -k * ((6 * L - 3 * x) * x + (2 + b.nu) * (3 * y * y - D * D / 4));
        }
      else
        {
          g[0] = k * (-3 * b.nu * y * y + (4 + 5 * b.nu) * D * D / 4 + 6 * L * x - 3 * x * x);
          g[1] = k * 6 * b.nu * y * (L - x);
        }
      return g;
    }

  private:
    BeamData b;
  };

  // The end traction $t = \sigma n$ with $n = (1,0)$ at $x = L$.
  class EndTraction : public dealii::Function<2>
  {
  public:
    explicit EndTraction(const BeamData &b)
      : dealii::Function<2>(2)
      , b(b)
    {}
    double
    value(const dealii::Point<2> &p, const unsigned int c) const override
    {
      return c == 0 ? 0. : b.P / (2 * b.I()) * (b.D * b.D / 4 - p[1] * p[1]);
    }

  private:
    BeamData b;
  };

  // @sect3{The CantileverProblem class}
  //
  // The usual structure of a deal.II tutorial: setup_system(),
  // assemble_system(), solve(), compute_errors(), output_results(), run().
  class CantileverProblem
  {
  public:
    explicit CantileverProblem(const unsigned int degree);
    void
    run();

  private:
    void
    make_mesh(const unsigned int cycle);
    void
    setup_system();
    void
    assemble_system();
    void
    solve();
    void
    compute_errors(const unsigned int cycle);
    void
    output_results(const unsigned int cycle) const;

    const unsigned int                                        degree;
    BeamData                                                  beam;
    std::map<dealii::types::material_id, ElasticMaterial>     materials;
    const ExactDisplacement                                   exact;
    const EndTraction                                         traction;
    PolygonalMesh<2>                                          mesh;
    VEMDoFHandler<2>                                          dof_handler;
    dealii::AffineConstraints<double>                         constraints;
    dealii::SparsityPattern                                   sparsity_pattern;
    dealii::SparseMatrix<double>                              system_matrix;
    dealii::Vector<double>                                    solution, system_rhs;
    dealii::ConvergenceTable                                  table;
  };

  CantileverProblem::CantileverProblem(const unsigned int degree)
    : degree(degree)
    , materials({{0, ElasticMaterial(beam.E, beam.nu, ElasticMaterial::Model::plane_stress)}})
    , exact(beam)
    , traction(beam)
  {}

  // @sect4{CantileverProblem::make_mesh}
  //
  // A centroidal Voronoi mesh of the beam: 40 cells on the coarsest mesh,
  // four times as many on each further cycle; 20 Lloyd iterations. The
  // generator gives boundary ids 0 (left, clamped), 1 (right, loaded),
  // 2 and 3 (bottom and top, free).
  void
  CantileverProblem::make_mesh(const unsigned int cycle)
  {
    PolygonalMeshGenerators::voronoi(mesh, dealii::Point<2>(0, -beam.D / 2),
                                     dealii::Point<2>(beam.L, beam.D / 2), 40u << (2 * cycle), 20, 1);
  }

  // @sect4{CantileverProblem::setup_system}
  //
  // Vertex, edge-midpoint and cell-moment DoFs; the exact displacement is
  // prescribed on the left end (a "clamp" that matches Timoshenko's
  // solution), then the sparsity pattern gets the constraints' entries as in step-8.
  void
  CantileverProblem::setup_system()
  {
    dof_handler.reinit(mesh);
    dof_handler.distribute_dofs(degree);
    constraints.clear();
    BoundaryConditions::interpolate_boundary_values(dof_handler, {0}, exact, {{true, true}}, constraints);
    constraints.close();
    dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
    dof_handler.make_sparsity_pattern(dsp, constraints);
    sparsity_pattern.copy_from(dsp);
    system_matrix.reinit(sparsity_pattern);
    solution.reinit(dof_handler.n_dofs());
  }

  // @sect4{CantileverProblem::assemble_system}
  //
  // The loop of deal.II's step-8, on polygons. VEMValues evaluates the
  // space on one cell: its "shape functions" are the projections
  // $\Pi\varphi_i$ of the virtual basis functions, which are polynomials of
  // degree $k$, so the consistency part
  // @f[ (K_c)_{ij} = \int_E \lambda\,\mathrm{div}\,\Pi\varphi_i\,\mathrm{div}\,\Pi\varphi_j
  //     + 2\mu\,\varepsilon(\Pi\varphi_i):\varepsilon(\Pi\varphi_j) @f]
  // is integrated exactly by the cell's quadrature rule (degree $2k$).
  // What step-8 does not have is the stabilization: $K_c$ vanishes on the
  // part $(I-\Pi)$ of each function that the projection cannot see, and
  // a term $\gamma(I-\Pi)^T W (I-\Pi)$ restores coercivity there, with a
  // diagonal weight $W$ that scales like $K_c$: for k = 1 the mean diagonal
  // entry $\tau$ of $K_c$ for every degree of freedom, for k = 2 each
  // degree of freedom's own $(K_c)_{ii}/5$ (bounded below by $10^{-3}\tau$),
  // which matters where node insertion has made edges short (see
  // ElasticityOperator). ElasticityOperator::add_stabilization() is the one
  // place the rules are written; it uses the space's projector onto the
  // degrees of freedom $\Pi = D\Pi_*$. (ElasticityOperator computes the same
  // $K_c = \Pi_*^T(\lambda T+2\mu E)\Pi_*$ from the space's Gram matrices
  // without quadrature; ElasticityAssembler uses it. tests/vem/vem_values
  // checks that the two agree to round-off.)
  //
  // The traction is applied on the edges with boundary id 1, edge by edge
  // as step-8 does on faces.
  void
  CantileverProblem::assemble_system()
  {
    system_matrix = 0;
    system_rhs.reinit(dof_handler.n_dofs());
    VEMValues<2> vem_values(dof_handler, dealii::update_gradients | dealii::update_JxW_values);
    const double gamma = 1.0;
    dealii::FullMatrix<double> cell_matrix;
    dealii::Vector<double>     cell_rhs;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        vem_values.reinit(c);
        // The material enters through its constitutive law only: the
        // tangent C = d sigma / d eps (for the isotropic ElasticMaterial
        // lambda I x I + 2 mu II, so that eps_i : C : eps_j is
        // lambda div_i div_j + 2 mu eps_i : eps_j, the form of step-8).
        const ConstitutiveLaw<2> &law = materials.at(vem_values.material_id());
        const dealii::SymmetricTensor<4, 2> C = law.tangent(dealii::SymmetricTensor<2, 2>());
        const unsigned int                  n = vem_values.dofs_per_cell();
        cell_matrix.reinit(n, n);
        cell_rhs.reinit(n);
        for (unsigned int q = 0; q < vem_values.n_quadrature_points(); ++q)
          for (unsigned int j = 0; j < n; ++j)
            {
              const dealii::SymmetricTensor<2, 2> sigma_j = C * vem_values.shape_symmetric_gradient(j, q);
              for (unsigned int i = 0; i < n; ++i)
                cell_matrix(i, j) += (vem_values.shape_symmetric_gradient(i, q) * sigma_j) * vem_values.JxW(q);
            }
        ElasticityOperator<2>::add_stabilization(vem_values.get_element(), cell_matrix, gamma);

        for (unsigned int e = 0; e < vem_values.n_edges(); ++e)
          if (vem_values.edge_boundary_id(e) == 1)
            vem_values.add_edge_traction(e, traction, cell_rhs);

        constraints.distribute_local_to_global(cell_matrix, cell_rhs, vem_values.get_dof_indices(),
                                               system_matrix, system_rhs);
      }
  }

  // @sect4{CantileverProblem::solve}
  //
  // CG with an algebraic multigrid preconditioner whose near-null space is
  // the three rigid-body modes.
  void
  CantileverProblem::solve()
  {
    LinearSolver::Settings settings;
    settings.type = LinearSolver::Type::cg_amg;
    LinearSolver solver(settings);
    solver.set_near_null_space(dof_handler.rigid_body_modes());
    solver.solve(system_matrix, solution, system_rhs);
    constraints.distribute(solution);
    std::cout << "   " << solver.last_iterations() << " CG iterations" << std::endl;
  }

  // @sect4{CantileverProblem::compute_errors}
  //
  // The virtual functions are not known inside a polygon, so the errors
  // are measured with the projection $\Pi u_h$.
  void
  CantileverProblem::compute_errors(const unsigned int cycle)
  {
    const ErrorNorms e = dealvem::compute_errors(dof_handler, materials, solution, exact);
    table.add_value("cycle", cycle);
    table.add_value("cells", mesh.n_cells());
    table.add_value("dofs", dof_handler.n_dofs());
    table.add_value("L2", e.l2 / e.l2_exact);
    table.add_value("H1", e.h1_seminorm / e.h1_exact);
    table.add_value("energy", e.energy / e.energy_exact);
  }

  // @sect4{CantileverProblem::output_results}
  void
  CantileverProblem::output_results(const unsigned int cycle) const
  {
    const StressRecovery<2> stresses(dof_handler, materials, solution);
    write_vtu_file("step-1-" + std::to_string(cycle) + ".vtu", dof_handler, solution, stresses);
    if (cycle == 1)
      {
        std::vector<dealii::Tensor<1, 2>> u(mesh.n_vertices());
        std::vector<double>               vm(mesh.n_cells());
        for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
          u[v] = dealii::Tensor<1, 2>({solution[2 * v], solution[2 * v + 1]});
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          vm[c] = stresses.cell_von_mises(c);
        SVGPlots::write_mesh("step-1-von-mises.svg", mesh, u, 1.0, vm, "von Mises",
                             std::vector<bool>(), "Cantilever on a Voronoi mesh: von Mises stress, true-scale displacement");
      }
  }

  // @sect4{CantileverProblem::run}
  void
  CantileverProblem::run()
  {
    for (unsigned int cycle = 0; cycle < 4; ++cycle)
      {
        make_mesh(cycle);
        setup_system();
        std::cout << "Cycle " << cycle << ": " << mesh.n_cells() << " Voronoi cells, "
                  << dof_handler.n_dofs() << " DoFs" << std::endl;
        assemble_system();
        solve();
        compute_errors(cycle);
        output_results(cycle);
      }
    for (const std::string c : {"L2", "H1", "energy"})
      {
        table.set_scientific(c, true);
        table.set_precision(c, 3);
        table.evaluate_convergence_rates(c, "dofs", dealii::ConvergenceTable::reduction_rate_log2, 2);
      }
    std::cout << std::endl << "Relative errors and rates (k = " << degree << "):" << std::endl;
    table.write_text(std::cout, dealii::TableHandler::org_mode_table);
  }
} // namespace Step1


// @sect3{The command line}
//
// An argument is a whole number in a given range; anything else (a sign, a
// letter, a number too large for the type) stops the program with the usage
// instead of a wrapped or misread value (InputParsing::parse_count()).

// @sect3{The main function}
int
main(int argc, char **argv)
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      unsigned int                             degree = 2;
      if (argc > 2 || (argc == 2 && !dealvem::InputParsing::parse_count(argv[1], 1, 2, degree)))
        {
          std::cerr << "step-1: " << (argc > 2 ? "too many arguments" : "the order k must be 1 or 2, not '" +
                                                                             std::string(argv[1]) + "'")
                    << ".\nusage: step-1 [k]   (k = 1 or 2, the order of the virtual elements; default 2)"
                    << std::endl;
          return 2;
        }
      Step1::CantileverProblem problem(degree);
      problem.run();
    }
  catch (std::exception &exc)
    {
      std::cerr << std::endl
                << "----------------------------------------------------" << std::endl
                << "Exception on processing: " << std::endl
                << exc.what() << std::endl
                << "Aborting!" << std::endl
                << "----------------------------------------------------" << std::endl;
      return 1;
    }
  return 0;
}
