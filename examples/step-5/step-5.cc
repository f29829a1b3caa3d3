// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// step-5: embedding dealvem in a deal.II program.
//
// Build (from a dealvem build directory):   make step-5
// Run:                                      ./examples/step-5 [k [cycles]]
//                                           (k = 1 or 2, both if omitted; 2 to 8 cycles, default 5)
// What it does: a deal.II program owns a Triangulation (a distorted square,
// refined globally cycle by cycle), hands it to dealvem, which solves plane
// strain elasticity with a manufactured solution by virtual elements on the
// cells (as polygons), and takes the solution back as deal.II finite
// element fields on its own triangulation. Those fields then go through
// deal.II's tools: VectorTools::integrate_difference for the errors,
// KellyErrorEstimator for error indicators and DataOut for step-5-k<k>-<cycle>.vtu.
// The program stops with an error unless
// - integrate_difference on the discontinuous field gives dealvem's own
//   error norms of Pi u_h to 1e-8 relative, every cycle, and
// - the rates on the two finest meshes are within 0.2 of k + 1 (L2) and k
//   (H1 seminorm) for the projection, and between 0.2 below and 0.5 above
//   them for the continuous field (which superconverges on the first meshes).
// The mathematics is in doc/intro.dox, the measured table in doc/results.dox.

// @sect3{Include files}
//
// The deal.II side: a triangulation, finite elements, DoF handlers and the
// tools that work on them.
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools.h>

// The dealvem side: the polygonal mesh made from the triangulation (with
// the maps between the two), the VEM DoFs, assembly, solver, error norms
// and the transfer back.
#include <dealvem/app/input_parsing.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/triangulation_map.h>
#include <dealvem/postprocessing/error_norms.h>
#include <dealvem/postprocessing/fe_transfer.h>
#include <dealvem/solvers/linear_solver.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/vem_values.h>

#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>
#include <iostream>

namespace Step5
{
  using namespace dealii;

  // @sect3{The manufactured solution}
  //
  // $u = (\sin\pi x\sin\pi y,\ \frac12\cos\pi x\sin\pi y)$ on the unit
  // square, with the body force $f = -\mathrm{div}\,\sigma(u)$ for the
  // material's Lamé constants and $u$ itself as Dirichlet data on the whole
  // boundary. The gradient is written out: both dealvem's error norms and
  // integrate_difference's H1 seminorm need it.
  class ExactDisplacement : public Function<2>
  {
  public:
    ExactDisplacement()
      : Function<2>(2)
    {}

    double
    value(const Point<2> &p, const unsigned int c) const override
    {
      const double s = numbers::PI, x = p[0], y = p[1];
      return c == 0 ? std::sin(s * x) * std::sin(s * y) : 0.5 * std::cos(s * x) * std::sin(s * y);
    }

    Tensor<1, 2>
    gradient(const Point<2> &p, const unsigned int c) const override
    {
      const double s = numbers::PI, x = p[0], y = p[1];
      Tensor<1, 2> g;
      if (c == 0)
        {
          g[0] = s * std::cos(s * x) * std::sin(s * y);
          g[1] = s * std::sin(s * x) * std::cos(s * y);
        }
      else
        {
          g[0] = -0.5 * s * std::sin(s * x) * std::sin(s * y);
          g[1] = 0.5 * s * std::cos(s * x) * std::cos(s * y);
        }
      return g;
    }
  };

  class BodyForce : public Function<2>
  {
  public:
    explicit BodyForce(const dealvem::ElasticMaterial &material)
      : Function<2>(2)
      , lambda(material.lambda())
      , mu(material.mu())
    {}

    double
    value(const Point<2> &p, const unsigned int c) const override
    {
      const double s = numbers::PI, Sx = std::sin(s * p[0]), Sy = std::sin(s * p[1]), Cx = std::cos(s * p[0]),
                   Cy = std::cos(s * p[1]);
      if (c == 0)
        return (lambda + mu) * s * s * (Sx * Sy + 0.5 * Sx * Cy) + 2 * mu * s * s * Sx * Sy;
      return -(lambda + mu) * s * s * (Cx * Cy - 0.5 * Cx * Sy) + mu * s * s * Cx * Sy;
    }

  private:
    const double lambda, mu;
  };

  // @sect3{The EmbeddingProblem class}
  //
  // A deal.II program's members -- triangulation, finite elements, DoF
  // handlers, finite element vectors -- next to dealvem's: the polygonal
  // mesh, the TriangulationMap that ties its polygons and vertices to the
  // triangulation's cells and vertices, the VEM DoF handler and the linear
  // system. The DoF handlers come after what they point to (triangulation,
  // mesh), so they are destroyed first.
  class EmbeddingProblem
  {
  public:
    EmbeddingProblem(const unsigned int degree, const unsigned int n_cycles);
    void
    run();

  private:
    void
    make_grid(const unsigned int cycle);
    void
    setup_system();
    void
    assemble_system();
    void
    solve();
    void
    transfer_solution();
    void
    compute_errors(const unsigned int cycle);
    void
    output_results(const unsigned int cycle) const;
    void
    check_results() const;

    const unsigned int degree, n_cycles;

    // the deal.II program
    Triangulation<2> triangulation;
    const FESystem<2> fe_discontinuous, fe_continuous;
    DoFHandler<2>     dof_handler_discontinuous, dof_handler_continuous;
    Vector<double>    projection, continuous_field;
    Vector<float>     kelly_indicators;

    // dealvem
    const dealvem::ElasticMaterial                                 material;
    const std::map<types::material_id, dealvem::ElasticMaterial>   materials;
    const ExactDisplacement                                        exact;
    const BodyForce                                                body_force;
    dealvem::PolygonalMesh<2>                                      mesh;
    dealvem::TriangulationMap<2>                                   map;
    dealvem::VEMDoFHandler<2>                                      vem_dof_handler;
    AffineConstraints<double>                                      constraints;
    SparsityPattern                                                sparsity_pattern;
    SparseMatrix<double>                                           system_matrix;
    Vector<double>                                                 solution, system_rhs;

    ConvergenceTable                             table;
    std::map<std::string, std::vector<double>>   history;
    // relative differences |integrate_difference / compute_errors - 1|
    double max_l2_mismatch = 0, max_h1_mismatch = 0;
  };



  EmbeddingProblem::EmbeddingProblem(const unsigned int degree, const unsigned int n_cycles)
    : degree(degree)
    , n_cycles(n_cycles)
    , fe_discontinuous(FE_DGQ<2>(degree), 2)
    , fe_continuous(FE_Q<2>(degree), 2)
    , dof_handler_discontinuous(triangulation)
    , dof_handler_continuous(triangulation)
    , material(1000, 0.3, dealvem::ElasticMaterial::Model::plane_strain)
    , materials({{0, material}})
    , body_force(material)
  {}

  // @sect4{EmbeddingProblem::make_grid}
  //
  // This is the user's part: any deal.II triangulation of quadrilaterals
  // will do. Here a 4x4 square whose interior vertices are moved at random
  // by up to 20% of the cell size (so the cells are general quadrilaterals,
  // not parallelograms), then refined globally on each further cycle.
  // The colorized generator numbers the sides 0 (left), 1 (right),
  // 2 (bottom), 3 (top) -- dealvem's convention too -- and the cells by
  // quadrant, which we undo: one material.
  void
  EmbeddingProblem::make_grid(const unsigned int cycle)
  {
    if (cycle == 0)
      {
        GridGenerator::subdivided_hyper_rectangle(triangulation, {4, 4}, Point<2>(0, 0), Point<2>(1, 1), true);
        for (const auto &cell : triangulation.active_cell_iterators())
          cell->set_material_id(0);
        GridTools::distort_random(0.2, triangulation, true, 5);
      }
    else
      triangulation.refine_global(1);
  }

  // @sect4{EmbeddingProblem::setup_system}
  //
  // The triangulation becomes a PolygonalMesh: every active cell one
  // polygon. The three-argument from_triangulation() also fills the
  // TriangulationMap, which the transfer back needs. Then the usual setup
  // of step-8, on the VEM DoFs: Dirichlet constraints from the exact
  // solution on all four sides, a sparsity pattern with the constraints'
  // entries. The deal.II DoF handlers are set up at the same time.
  void
  EmbeddingProblem::setup_system()
  {
    dealvem::PolygonalMeshGenerators::from_triangulation(mesh, triangulation, map);
    vem_dof_handler.reinit(mesh);
    vem_dof_handler.distribute_dofs(degree);

    constraints.clear();
    dealvem::BoundaryConditions::interpolate_boundary_values(vem_dof_handler, {0, 1, 2, 3}, exact, {{true, true}},
                                                             constraints);
    constraints.close();
    DynamicSparsityPattern dsp(vem_dof_handler.n_dofs());
    vem_dof_handler.make_sparsity_pattern(dsp, constraints);
    sparsity_pattern.copy_from(dsp);
    system_matrix.reinit(sparsity_pattern);
    solution.reinit(vem_dof_handler.n_dofs());

    dof_handler_discontinuous.distribute_dofs(fe_discontinuous);
    dof_handler_continuous.distribute_dofs(fe_continuous);
  }

  // @sect4{EmbeddingProblem::assemble_system}
  //
  // The loop of step-8 over the polygons: VEMValues evaluates the space on
  // the polygon, ElasticityOperator gives the stiffness $K_E = K_c + K_s$
  // (step-1 builds the same matrix by quadrature), the space the body-force
  // load $F_i = \int_E f\cdot\Pi^0\varphi_i$; AffineConstraints condenses.
  void
  EmbeddingProblem::assemble_system()
  {
    system_matrix = 0;
    system_rhs.reinit(vem_dof_handler.n_dofs());
    dealvem::VEMValues<2>          vem_values(vem_dof_handler);
    dealvem::ElasticityOperator<2> elasticity;
    Vector<double>                 cell_rhs;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        vem_values.reinit(c);
        elasticity.reinit(vem_values.get_element(), materials.at(vem_values.material_id()));
        vem_values.body_force_vector(body_force, cell_rhs);
        constraints.distribute_local_to_global(elasticity.get_stiffness_matrix(), cell_rhs,
                                               vem_values.get_dof_indices(), system_matrix, system_rhs);
      }
  }

  // @sect4{EmbeddingProblem::solve}
  void
  EmbeddingProblem::solve()
  {
    dealvem::LinearSolver solver(dealvem::LinearSolver::Settings{});
    solver.solve(system_matrix, solution, system_rhs);
    constraints.distribute(solution);
  }

  // @sect4{EmbeddingProblem::transfer_solution}
  //
  // The step this program is about. Two finite element fields on the
  // user's triangulation:
  // - `projection`, in FE_DGQ(k)^2: on every cell the polynomial
  //   $\Pi^\nabla_k u_h$ of its polygon, evaluated at the FE_DGQ support
  //   points. Since $P_k\circ F_K \subset Q_k$ for the bilinear map $F_K$,
  //   the field IS $\Pi^\nabla_k u_h$ on every cell.
  // - `continuous_field`, in FE_Q(k)^2: the continuous field with the VEM
  //   degrees of freedom of $u_h$ (vertex and edge midpoint values; the
  //   centre value of FE_Q(2) gives the VEM cell mean).
  // Kelly's indicators need the jumps of the gradient across faces of a
  // continuous field; they are computed on the second one.
  void
  EmbeddingProblem::transfer_solution()
  {
    dealvem::FETransfer::interpolate_to_discontinuous(map, vem_dof_handler, solution, dof_handler_discontinuous,
                                                      projection);
    dealvem::FETransfer::interpolate_to_continuous(map, vem_dof_handler, solution, dof_handler_continuous,
                                                   continuous_field);
    kelly_indicators.reinit(triangulation.n_active_cells());
    KellyErrorEstimator<2>::estimate(dof_handler_continuous, QGauss<1>(degree + 1), {}, continuous_field,
                                     kelly_indicators);
  }

  // @sect4{EmbeddingProblem::compute_errors}
  //
  // The same errors twice: by dealvem's compute_errors() on the polygons
  // (a triangle-fan quadrature of degree 2k + 6) and by deal.II's
  // integrate_difference() on the discontinuous field (a 2k + 4-point
  // Gauss rule per cell). Both integrate $u - \Pi^\nabla_k u_h$, so they
  // differ by quadrature only. The continuous field's errors are measured
  // as well; they are not those of the projection.
  void
  EmbeddingProblem::compute_errors(const unsigned int cycle)
  {
    const dealvem::ErrorNorms e = dealvem::compute_errors(vem_dof_handler, materials, solution, exact);

    const QGauss<2> quadrature(degree + 4);
    auto            error = [&](const DoFHandler<2> &dof_handler, const Vector<double> &field,
                     const VectorTools::NormType norm) {
      Vector<double> per_cell(triangulation.n_active_cells());
      VectorTools::integrate_difference(dof_handler, field, exact, per_cell, quadrature, norm);
      return VectorTools::compute_global_error(triangulation, per_cell, norm);
    };
    const double l2_dg = error(dof_handler_discontinuous, projection, VectorTools::L2_norm);
    const double h1_dg = error(dof_handler_discontinuous, projection, VectorTools::H1_seminorm);
    const double l2_q  = error(dof_handler_continuous, continuous_field, VectorTools::L2_norm);
    const double h1_q  = error(dof_handler_continuous, continuous_field, VectorTools::H1_seminorm);
    max_l2_mismatch    = std::max(max_l2_mismatch, std::abs(l2_dg / e.l2 - 1));
    max_h1_mismatch    = std::max(max_h1_mismatch, std::abs(h1_dg / e.h1_seminorm - 1));

    double kelly = 0;
    for (const float eta : kelly_indicators)
      kelly += double(eta) * eta;

    history["L2 (dealvem)"].push_back(e.l2);
    history["H1 (dealvem)"].push_back(e.h1_seminorm);
    history["L2 (FE_Q)"].push_back(l2_q);
    history["H1 (FE_Q)"].push_back(h1_q);

    table.add_value("cycle", cycle);
    table.add_value("cells", triangulation.n_active_cells());
    table.add_value("VEM dofs", vem_dof_handler.n_dofs());
    table.add_value("L2 (dealvem)", e.l2);
    table.add_value("L2 (deal.II, DGQ)", l2_dg);
    table.add_value("H1 (dealvem)", e.h1_seminorm);
    table.add_value("H1 (deal.II, DGQ)", h1_dg);
    table.add_value("L2 (FE_Q)", l2_q);
    table.add_value("H1 (FE_Q)", h1_q);
    table.add_value("Kelly", std::sqrt(kelly));
  }

  // @sect4{EmbeddingProblem::output_results}
  //
  // DataOut on the user's triangulation, with both fields (DataOut takes
  // vectors of several DoF handlers on one triangulation) and Kelly's
  // indicators as cell data.
  void
  EmbeddingProblem::output_results(const unsigned int cycle) const
  {
    DataOut<2> data_out;
    data_out.attach_triangulation(triangulation);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector(
      2, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(dof_handler_continuous, continuous_field,
                             std::vector<std::string>(2, "displacement"), vector);
    data_out.add_data_vector(dof_handler_discontinuous, projection, std::vector<std::string>(2, "projection"),
                             vector);
    data_out.add_data_vector(kelly_indicators, "kelly_indicator", DataOut<2>::type_cell_data);
    data_out.build_patches(degree);
    std::ofstream out("step-5-k" + std::to_string(degree) + "-" + std::to_string(cycle) + ".vtu");
    data_out.write_vtu(out);
    AssertThrow(out, ExcMessage("Writing the VTU file failed."));
  }

  // @sect4{EmbeddingProblem::check_results}
  //
  // What this program guarantees (it runs as a test): the two ways of
  // measuring the projection's error agree, and all fields converge at the
  // textbook rates on the two finest meshes.
  void
  EmbeddingProblem::check_results() const
  {
    AssertThrow(max_l2_mismatch < 1e-8 && max_h1_mismatch < 1e-8,
                ExcMessage("integrate_difference and dealvem's compute_errors disagree: relative differences " +
                           std::to_string(max_l2_mismatch) + " (L2), " + std::to_string(max_h1_mismatch) +
                           " (H1)."));
    // Rates against h, which halves from cycle to cycle. The projection
    // must show the textbook rates, k + 1 and k, within 0.2. The continuous
    // field converges faster than that on the first meshes (the refined cells
    // become parallelograms, on which nodal values superconverge) and
    // approaches the textbook rates from above (results.dox shows six
    // cycles): its rates must lie between 0.2 below and 0.5 above them.
    struct Expected
    {
      std::string column;
      double      rate, below, above;
    };
    for (const Expected &x : {Expected{"L2 (dealvem)", degree + 1., 0.2, 0.2},
                              Expected{"H1 (dealvem)", 1. * degree, 0.2, 0.2},
                              Expected{"L2 (FE_Q)", degree + 1., 0.2, 0.5},
                              Expected{"H1 (FE_Q)", 1. * degree, 0.2, 0.5}})
      {
        const std::vector<double> &e    = history.at(x.column);
        const double               rate = std::log2(e[e.size() - 2] / e.back());
        AssertThrow(rate >= x.rate - x.below && rate <= x.rate + x.above,
                    ExcMessage("k = " + std::to_string(degree) + ": the " + x.column +
                               " rate on the two finest meshes is " + std::to_string(rate) + ", expected " +
                               std::to_string(x.rate) + " (-" + std::to_string(x.below) + ", +" +
                               std::to_string(x.above) + ")."));
        std::cout << "k = " << degree << ": " << x.column << " rate on the two finest meshes " << rate
                  << ", expected " << x.rate << " (-" << x.below << ", +" << x.above << "): OK" << std::endl;
      }
  }



  // @sect4{EmbeddingProblem::run}
  void
  EmbeddingProblem::run()
  {
    for (unsigned int cycle = 0; cycle < n_cycles; ++cycle)
      {
        make_grid(cycle);
        setup_system();
        std::cout << "Cycle " << cycle << ": " << triangulation.n_active_cells() << " cells, "
                  << vem_dof_handler.n_dofs() << " VEM DoFs, " << dof_handler_continuous.n_dofs()
                  << " FE_Q DoFs" << std::endl;
        assemble_system();
        solve();
        transfer_solution();
        compute_errors(cycle);
        output_results(cycle);
      }
    for (const std::string c : {"L2 (dealvem)", "L2 (deal.II, DGQ)", "H1 (dealvem)", "H1 (deal.II, DGQ)",
                                "L2 (FE_Q)", "H1 (FE_Q)", "Kelly"})
      {
        table.set_scientific(c, true);
        table.set_precision(c, 3);
        table.evaluate_convergence_rates(c, "cells", ConvergenceTable::reduction_rate_log2, 2);
      }
    std::cout << std::endl << "Errors and rates (k = " << degree << "):" << std::endl;
    table.write_text(std::cout, TableHandler::org_mode_table);
    std::cout << "integrate_difference vs compute_errors, largest relative difference: L2 " << max_l2_mismatch
              << ", H1 " << max_h1_mismatch << std::endl;
    check_results();
  }
} // namespace Step5


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
      std::vector<unsigned int>                degrees = {1, 2};
      unsigned int                             k = 0, n_cycles = 5;
      // at least two cycles for the rates; cycle 7 has 16 * 4^7 = 262144 cells
      std::string error;
      if (argc > 3)
        error = "too many arguments";
      else if (argc > 1 && !dealvem::InputParsing::parse_count(argv[1], 1, 2, k))
        error = "the order k must be 1 or 2, not '" + std::string(argv[1]) + "'";
      else if (argc > 2 && !dealvem::InputParsing::parse_count(argv[2], 2, 8, n_cycles))
        error = "the number of cycles must be a whole number from 2 to 8, not '" + std::string(argv[2]) + "'";
      if (!error.empty())
        {
          std::cerr << "step-5: " << error
                    << ".\nusage: step-5 [k [cycles]]   (k = 1 or 2, both if omitted; cycles from 2 to 8, "
                       "default 5)"
                    << std::endl;
          return 2;
        }
      if (argc > 1)
        degrees = {k};
      for (const unsigned int k : degrees)
        {
          Step5::EmbeddingProblem problem(k, n_cycles);
          problem.run();
          std::cout << std::endl;
        }
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
