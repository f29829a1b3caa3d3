// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Timing of the stages of a linear elasticity solve, VEM k = 2 against
// deal.II's own FE_Q(2)^2 (assembled the step-8 way) on similar numbers of
// DoFs, on the unit square: left side clamped, body force (0, -1).
//
//   benchmark_elasticity --case voronoi|quads|quads-full|feq --dofs N
//
// "quads" reuses the element matrices of translated cells (the default, as
// deal.II's FEValues does for FE_Q); "quads-full" computes every element.
//
// prints one line "RESULT case cells dofs t_mesh t_dofs t_assembly t_solve
// iterations peak_MB" (wall seconds; peak memory of the process from
// getrusage). benchmarks/run_benchmarks.sh runs every case and size in its
// own process and writes doc/benchmarks.md.
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
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/solvers/linear_solver.h>
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
    double       mesh = 0, setup = 0, assembly = 0, solve = 0;
  };

  Times
  run_vem(const bool voronoi, const bool cell_similarity, const unsigned int target_dofs)
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
    dealvem::LinearSolver::Settings settings;
    settings.type               = dealvem::LinearSolver::Type::cg_amg;
    settings.relative_tolerance = 1e-8;
    dealvem::LinearSolver solver(settings);
    solver.set_near_null_space(dof_handler.rigid_body_modes());
    solver.solve(A, x, b);
    t.solve      = timer.wall_time();
    t.iterations = solver.last_iterations();
    t.cells      = mesh.n_cells();
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
    t.solve      = timer.wall_time();
    t.iterations = solver.last_iterations();
    t.cells      = tria.n_active_cells();
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
      std::string                      which = "voronoi";
      unsigned int                     dofs  = 10000;
      for (int i = 1; i + 1 < argc; i += 2)
        {
          const std::string a = argv[i];
          if (a == "--case")
            which = argv[i + 1];
          else if (a == "--dofs")
            dofs = std::stoul(argv[i + 1]);
          else
            AssertThrow(false, ExcMessage("unknown option " + a));
        }
      AssertThrow(which == "voronoi" || which == "quads" || which == "quads-full" || which == "feq",
                  ExcMessage("--case must be voronoi, quads, quads-full or feq"));
      const Times t =
        (which == "feq" ? run_feq(dofs) : run_vem(which == "voronoi", which != "quads-full", dofs));
      std::cout << "RESULT " << which << " " << t.cells << " " << t.dofs << " " << t.mesh << " " << t.setup << " "
                << t.assembly << " " << t.solve << " " << t.iterations << " " << peak_memory_mb() << std::endl;
    }
  catch (std::exception &e)
    {
      std::cerr << "benchmark_elasticity: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
