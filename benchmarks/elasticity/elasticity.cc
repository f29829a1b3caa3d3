// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Timing of the stages of a linear elasticity solve, VEM k = 2 against
// deal.II's own FE_Q(2)^2 (assembled the step-8 way) on similar numbers of
// DoFs, on the unit square: left side clamped, body force (0, -1).
//
//   benchmark_elasticity --case voronoi|quads|quads-full|feq --dofs N
//                        [--precond amg|pmg] [--smoother NAME] [--sweeps n]
//                        [--threshold t] [--uncoupled 0|1] [--elliptic 0|1]
//                        [--rotation 0|1] [--degree d] [--range r]
//                        [--renumber none|cm] [--single-precision-smoother 0|1]
//
// "quads" reuses the element matrices of translated cells (the default, as
// deal.II's FEValues does for FE_Q); "quads-full" computes every element.
// --precond chooses CG's preconditioner for VEM (default amg: ML on the whole
// matrix; pmg: LinearSolver's two-level p-multigrid with ML on the Galerkin
// k = 1 level); --smoother, --sweeps, --threshold, --uncoupled, --elliptic,
// --rotation set the ML parameters (of the whole matrix or of the coarse
// level), --degree and --range the Chebyshev smoother of the p-multigrid,
// --single-precision-smoother 0 its matrix in double precision (default 1);
// --renumber cm renumbers the VEM system by Cuthill-McKee before the solve.
// FE_Q(2) is always solved with the default ML settings.
//
// prints one line "RESULT case cells dofs t_mesh t_dofs t_assembly t_solve
// iterations peak_MB t_precond_setup precond t_prolongation nnz_per_row"
// (wall seconds;
// t_solve includes t_precond_setup and, for pmg, t_prolongation, building
// the prolongation from the DoF handler; peak
// memory of the process from getrusage). benchmarks/run_benchmarks.sh runs
// every case and size in its own process and writes doc/benchmarks.md.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/solvers/linear_solver.h>
#include <dealvem/solvers/p_multigrid.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <sys/resource.h>

#include <cmath>
#include <iostream>
#include <string>

using namespace dealii;

namespace
{
  const double E = 1000, nu = 0.3;

  double
  peak_memory_mb()
  {
    rusage r;
    getrusage(RUSAGE_SELF, &r);
    return r.ru_maxrss / 1024.;
  }

  struct Times
  {
    unsigned int cells = 0, dofs = 0, iterations = 0;
    double       mesh = 0, setup = 0, assembly = 0, solve = 0, precond_setup = 0, prolongation = 0;
    double       nonzeros_per_row = 0;
  };

  struct Options
  {
    dealvem::LinearSolver::Settings solver;
    bool                            renumber = false;
  };

  // Cuthill-McKee renumbering of the condensed system (matrix, right-hand
  // side, near-null space and the rows of P), to see whether locality
  // changes the solve time.
  void
  renumber_cuthill_mckee(SparsityPattern                  &sp,
                         SparseMatrix<double>             &A,
                         Vector<double>                   &b,
                         std::vector<std::vector<double>> &modes,
                         SparsityPattern                  &sp_P,
                         SparseMatrix<double>             &P,
                         const bool                        with_P)
  {
    DynamicSparsityPattern dsp(sp.n_rows());
    for (unsigned int i = 0; i < sp.n_rows(); ++i)
      for (auto it = sp.begin(i); it != sp.end(i); ++it)
        dsp.add(i, it->column());
    std::vector<types::global_dof_index> new_index(sp.n_rows());
    SparsityTools::reorder_Cuthill_McKee(dsp, new_index);
    DynamicSparsityPattern dsp_new(sp.n_rows());
    for (unsigned int i = 0; i < sp.n_rows(); ++i)
      for (auto it = sp.begin(i); it != sp.end(i); ++it)
        dsp_new.add(new_index[i], new_index[it->column()]);
    SparsityPattern sp_new;
    sp_new.copy_from(dsp_new);
    SparseMatrix<double> A_new(sp_new);
    for (unsigned int i = 0; i < sp.n_rows(); ++i)
      for (auto it = A.begin(i); it != A.end(i); ++it)
        A_new.set(new_index[i], new_index[it->column()], it->value());
    Vector<double> b_new(b.size());
    for (unsigned int i = 0; i < b.size(); ++i)
      b_new[new_index[i]] = b[i];
    for (auto &m : modes)
      {
        std::vector<double> m_new(m.size());
        for (unsigned int i = 0; i < m.size(); ++i)
          m_new[new_index[i]] = m[i];
        m = m_new;
      }
    if (with_P)
      {
        DynamicSparsityPattern dsp_P(P.m(), P.n());
        for (unsigned int i = 0; i < P.m(); ++i)
          for (auto it = P.begin(i); it != P.end(i); ++it)
            dsp_P.add(new_index[i], it->column());
        SparsityPattern sp_P_new;
        sp_P_new.copy_from(dsp_P);
        SparseMatrix<double> P_new(sp_P_new);
        for (unsigned int i = 0; i < P.m(); ++i)
          for (auto it = P.begin(i); it != P.end(i); ++it)
            P_new.set(new_index[i], it->column(), it->value());
        P.clear();
        sp_P.copy_from(sp_P_new);
        P.reinit(sp_P);
        P.copy_from(P_new);
      }
    A.clear();
    sp.copy_from(sp_new);
    A.reinit(sp);
    A.copy_from(A_new);
    b = b_new;
  }

  Times
  run_vem(const bool voronoi, const bool cell_similarity, const unsigned int target_dofs, const Options &options)
  {
    Times                     t;
    Timer                     timer;
    dealvem::PolygonalMesh<2> mesh;
    if (voronoi)
      {
        // about 12 DoFs per Voronoi cell for k = 2
        const unsigned int n_cells = std::max(4u, target_dofs / 12);
        dealvem::PolygonalMeshGenerators::voronoi(mesh, Point<2>(0, 0), Point<2>(1, 1), n_cells, 5, 1);
      }
    else
      {
        const unsigned int n = std::max(2u, unsigned(std::sqrt(target_dofs / 8.)));
        dealvem::PolygonalMeshGenerators::structured_quads(mesh, Point<2>(0, 0), Point<2>(1, 1), n, n);
      }
    t.mesh = timer.wall_time();

    timer.restart();
    dealvem::VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(2);
    AffineConstraints<double> constraints;
    Functions::ZeroFunction<2> zero(2);
    dealvem::BoundaryConditions::interpolate_boundary_values(dof_handler, {0}, zero, {{true, true}}, constraints);
    constraints.close();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    dof_handler.make_sparsity_pattern(dsp, constraints);
    SparsityPattern sp;
    sp.copy_from(dsp);
    SparseMatrix<double> A(sp);
    Vector<double>       b, x;
    t.setup = timer.wall_time();

    timer.restart();
    const std::map<types::material_id, dealvem::ElasticMaterial> materials = {{0, dealvem::ElasticMaterial(E, nu)}};
    dealvem::ElasticityAssembler<2>                              assembler(dof_handler, materials);
    assembler.set_cell_similarity(cell_similarity);
    Functions::ConstantFunction<2>                               f(std::vector<double>{0., -1.});
    assembler.set_body_force(f);
    assembler.assemble(constraints, A, b);
    t.assembly = timer.wall_time();

    timer.restart();
    dealvem::LinearSolver::Settings settings = options.solver;
    settings.type                            = dealvem::LinearSolver::Type::cg_amg;
    settings.relative_tolerance              = 1e-8;
    std::vector<std::vector<double>> modes = dof_handler.rigid_body_modes(), coarse_modes;
    SparsityPattern                  sp_P;
    SparseMatrix<double>             P;
    const bool pmg = settings.preconditioner == dealvem::LinearSolver::Preconditioner::p_multigrid;
    if (pmg)
      dealvem::PMultigrid::make_prolongation(dof_handler, sp_P, P, coarse_modes);
    t.prolongation = timer.wall_time();
    if (options.renumber)
      {
        // not timed: a numbering the DoF handler would produce directly
        timer.stop();
        renumber_cuthill_mckee(sp, A, b, modes, sp_P, P, pmg);
        timer.start();
      }
    dealvem::LinearSolver solver(settings);
    if (pmg)
      solver.set_coarse_space(P, coarse_modes);
    solver.set_near_null_space(modes);
    solver.solve(A, x, b);
    t.solve         = timer.wall_time();
    t.precond_setup = solver.last_setup_time();
    t.iterations    = solver.last_iterations();
    t.nonzeros_per_row = double(sp.n_nonzero_elements()) / sp.n_rows();
    t.cells         = mesh.n_cells();
    t.dofs       = dof_handler.n_dofs();
    return t;
  }

  Times
  run_feq(const unsigned int target_dofs)
  {
    Times              t;
    Timer              timer;
    Triangulation<2>   tria;
    const unsigned int n = std::max(2u, unsigned(std::sqrt(target_dofs / 8.)));
    GridGenerator::subdivided_hyper_cube(tria, n, 0, 1, true);
    t.mesh = timer.wall_time();

    timer.restart();
    const FESystem<2> fe(FE_Q<2>(2), 2);
    DoFHandler<2>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    AffineConstraints<double> constraints;
    VectorTools::interpolate_boundary_values(dof_handler, 0, Functions::ZeroFunction<2>(2), constraints);
    constraints.close();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityPattern sp;
    sp.copy_from(dsp);
    SparseMatrix<double> A(sp);
    Vector<double>       b(dof_handler.n_dofs()), x;
    t.setup = timer.wall_time();

    // step-8's assembly
    timer.restart();
    const dealvem::ElasticMaterial material(E, nu);
    const double                   lambda = material.lambda(), mu = material.mu();
    const QGauss<2>                quadrature(3);
    FEValues<2> fe_values(fe, quadrature, update_values | update_gradients | update_JxW_values);
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(dofs_per_cell, dofs_per_cell);
    Vector<double>                       cell_rhs(dofs_per_cell);
    std::vector<types::global_dof_index> local_dof_indices(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell_matrix = 0;
        cell_rhs    = 0;
        fe_values.reinit(cell);
        for (const unsigned int i : fe_values.dof_indices())
          {
            const unsigned int component_i = fe.system_to_component_index(i).first;
            for (const unsigned int j : fe_values.dof_indices())
              {
                const unsigned int component_j = fe.system_to_component_index(j).first;
                for (const unsigned int q : fe_values.quadrature_point_indices())
                  cell_matrix(i, j) +=
                    ((fe_values.shape_grad(i, q)[component_i] * fe_values.shape_grad(j, q)[component_j] * lambda) +
                     (fe_values.shape_grad(i, q)[component_j] * fe_values.shape_grad(j, q)[component_i] * mu) +
                     ((component_i == component_j) ?
                        (fe_values.shape_grad(i, q) * fe_values.shape_grad(j, q) * mu) :
                        0)) *
                    fe_values.JxW(q);
              }
            for (const unsigned int q : fe_values.quadrature_point_indices())
              cell_rhs(i) += fe_values.shape_value(i, q) * (component_i == 1 ? -1. : 0.) * fe_values.JxW(q);
          }
        cell->get_dof_indices(local_dof_indices);
        constraints.distribute_local_to_global(cell_matrix, cell_rhs, local_dof_indices, A, b);
      }
    t.assembly = timer.wall_time();

    timer.restart();
    // rigid-body modes from the support points
    std::vector<Point<2>> points(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dof_handler, points);
    std::vector<std::vector<double>> modes(3, std::vector<double>(dof_handler.n_dofs()));
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local_dof_indices);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            const auto         d = local_dof_indices[i];
            modes[c][d]          = 1;
            modes[2][d]          = (c == 0 ? -points[d][1] : points[d][0]);
          }
      }
    dealvem::LinearSolver::Settings settings;
    settings.type               = dealvem::LinearSolver::Type::cg_amg;
    settings.relative_tolerance = 1e-8;
    dealvem::LinearSolver solver(settings);
    solver.set_near_null_space(modes);
    solver.solve(A, x, b);
    t.solve         = timer.wall_time();
    t.precond_setup = solver.last_setup_time();
    t.iterations    = solver.last_iterations();
    t.nonzeros_per_row = double(sp.n_nonzero_elements()) / sp.n_rows();
    t.cells         = tria.n_active_cells();
    t.dofs       = dof_handler.n_dofs();
    return t;
  }
} // namespace

int
main(int argc, char **argv)
{
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      std::string                      which = "voronoi", precond = "amg";
      unsigned int                     dofs  = 10000;
      Options                          options;
      options.solver.preconditioner = dealvem::LinearSolver::Preconditioner::amg;
      for (int i = 1; i + 1 < argc; i += 2)
        {
          const std::string a = argv[i], v = argv[i + 1];
          if (a == "--case")
            which = v;
          else if (a == "--dofs")
            dofs = std::stoul(v);
          else if (a == "--precond")
            {
              AssertThrow(v == "amg" || v == "pmg", ExcMessage("--precond must be amg or pmg"));
              precond                       = v;
              options.solver.preconditioner = (v == "amg" ? dealvem::LinearSolver::Preconditioner::amg :
                                                            dealvem::LinearSolver::Preconditioner::p_multigrid);
            }
          else if (a == "--smoother")
            options.solver.amg.smoother_type = v;
          else if (a == "--sweeps")
            options.solver.amg.smoother_sweeps = std::stoul(v);
          else if (a == "--threshold")
            options.solver.amg.aggregation_threshold = std::stod(v);
          else if (a == "--uncoupled")
            options.solver.amg.uncoupled_aggregation = (v == "1");
          else if (a == "--elliptic")
            options.solver.amg.elliptic = (v == "1");
          else if (a == "--rotation")
            options.solver.amg.use_rotation = (v == "1");
          else if (a == "--degree")
            options.solver.smoother_degree = std::stoul(v);
          else if (a == "--range")
            options.solver.smoothing_range = std::stod(v);
          else if (a == "--single-precision-smoother")
            options.solver.single_precision_smoother = (v == "1");
          else if (a == "--renumber")
            {
              AssertThrow(v == "none" || v == "cm", ExcMessage("--renumber must be none or cm"));
              options.renumber = (v == "cm");
            }
          else
            AssertThrow(false, ExcMessage("unknown option " + a));
        }
      AssertThrow(which == "voronoi" || which == "quads" || which == "quads-full" || which == "feq",
                  ExcMessage("--case must be voronoi, quads, quads-full or feq"));
      AssertThrow(which != "feq" || precond == "amg", ExcMessage("FE_Q(2) is solved with AMG only"));
      const Times t =
        (which == "feq" ? run_feq(dofs) : run_vem(which == "voronoi", which != "quads-full", dofs, options));
      std::cout << "RESULT " << which << " " << t.cells << " " << t.dofs << " " << t.mesh << " " << t.setup << " "
                << t.assembly << " " << t.solve << " " << t.iterations << " " << peak_memory_mb() << " "
                << t.precond_setup << " " << precond << " " << t.prolongation << " " << t.nonzeros_per_row << std::endl;
    }
  catch (std::exception &e)
    {
      std::cerr << "benchmark_elasticity: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
