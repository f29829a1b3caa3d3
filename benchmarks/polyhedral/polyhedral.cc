// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// 3D linear elasticity on the unit cube (face x = 0 clamped, body force
// (0, 0, -1), E = 1, nu = 0.3) with first-order virtual elements on
// polyhedra against deal.II's own FE_Q(1)^3 and FE_Q(2)^3 (assembled the
// step-8 way) on about the same number of DoFs, all solved by CG with ML AMG
// (six rigid-body modes, dealvem's LinearSolver, relative tolerance 1e-8):
//
//   benchmark_polyhedral --case vem-hex|vem-voronoi|feq1|feq2 --dofs N
//
// vem-hex: the hexahedra of a deal.II mesh as polyhedra; vem-voronoi:
// centroidal Voronoi polyhedra (CGAL, 10 Lloyd iterations). Prints one line
// "RESULT case cells dofs t_mesh t_assembly t_solve iterations peak_MB
// nnz_per_row" (wall seconds; t_assembly includes the sparsity pattern and
// the constraints; t_solve the AMG set-up; peak memory of the process from
// getrusage). benchmarks/polyhedral/run.sh runs every case and size in its own
// process.
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

#include <dealvem/app/polyhedral_elasticity.h>
#include <dealvem/mesh/polyhedral_generators.h>
#include <dealvem/mesh/polyhedral_mesh.h>
#include <dealvem/solvers/linear_solver.h>

#include <sys/resource.h>

#include <cmath>
#include <iostream>
#include <string>

using namespace dealii;

namespace
{
  const double E = 1, nu = 0.3;

  struct Result
  {
    unsigned int cells = 0, dofs = 0, iterations = 0;
    double       mesh = 0, assembly = 0, solve = 0, nnz_per_row = 0;
  };

  double
  peak_mb()
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.;
  }

  Result
  vem(const bool voronoi, const unsigned int target_dofs)
  {
    Result                  r;
    Timer                   timer;
    dealvem::PolyhedralMesh mesh;
    if (voronoi)
      // a centroidal Voronoi mesh has about 5.9 vertices per cell
      dealvem::PolyhedralMeshGenerators::voronoi_box(mesh, Point<3>(0, 0, 0), Point<3>(1, 1, 1),
                                                     std::max(8u, unsigned(target_dofs / 3. / 5.9)), 10, 1);
    else
      {
        const unsigned int n = std::max(2u, unsigned(std::cbrt(target_dofs / 3.)) - 1);
        Triangulation<3>   tria;
        GridGenerator::subdivided_hyper_cube(tria, n, 0, 1, true);
        mesh = dealvem::PolyhedralMesh::from_triangulation(tria);
      }
    r.mesh = timer.wall_time();
    mesh.set_boundary_ids([](const Point<3> &x, const Tensor<1, 3> &) { return x[0] < 1e-12; }, 100);
    dealvem::PolyhedralElasticity::Settings settings;
    settings.material                  = {E, nu};
    settings.solver.type               = dealvem::LinearSolver::Type::cg_amg;
    settings.solver.relative_tolerance = 1e-8;
    dealvem::PolyhedralElasticity problem(mesh, settings);
    problem.add_dirichlet(100, [](const Point<3> &) { return Tensor<1, 3>(); });
    problem.set_body_force([](const Point<3> &) { return Tensor<1, 3>({0, 0, -1}); });
    problem.solve();
    r.assembly   = problem.last_times().first;
    r.solve      = problem.last_times().second;
    r.iterations = problem.last_iterations();
    r.cells      = mesh.n_cells();
    r.dofs       = problem.n_dofs();
    r.nnz_per_row = double(problem.n_matrix_entries()) / problem.n_dofs();
    return r;
  }

  Result
  feq(const unsigned int degree, const unsigned int target_dofs)
  {
    Result             r;
    Timer              timer;
    Triangulation<3>   tria;
    const unsigned int n = std::max(1u, unsigned(std::cbrt(target_dofs / 3.) / degree));
    GridGenerator::subdivided_hyper_cube(tria, n, 0, 1, true);
    r.mesh = timer.wall_time();

    timer.restart();
    const FESystem<3> fe(FE_Q<3>(degree), 3);
    DoFHandler<3>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    AffineConstraints<double> constraints;
    VectorTools::interpolate_boundary_values(dof_handler, 0, Functions::ZeroFunction<3>(3), constraints);
    constraints.close();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityPattern sp;
    sp.copy_from(dsp);
    SparseMatrix<double> A(sp);
    Vector<double>       b(dof_handler.n_dofs()), x;
    // step-8's assembly
    const double      lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    const QGauss<3>   quadrature(degree + 1);
    FEValues<3>       fe_values(fe, quadrature, update_values | update_gradients | update_JxW_values);
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
            const unsigned int ci = fe.system_to_component_index(i).first;
            for (const unsigned int j : fe_values.dof_indices())
              {
                const unsigned int cj = fe.system_to_component_index(j).first;
                for (const unsigned int q : fe_values.quadrature_point_indices())
                  cell_matrix(i, j) += ((fe_values.shape_grad(i, q)[ci] * fe_values.shape_grad(j, q)[cj] * lambda) +
                                        (fe_values.shape_grad(i, q)[cj] * fe_values.shape_grad(j, q)[ci] * mu) +
                                        (ci == cj ? fe_values.shape_grad(i, q) * fe_values.shape_grad(j, q) * mu : 0)) *
                                       fe_values.JxW(q);
              }
            for (const unsigned int q : fe_values.quadrature_point_indices())
              cell_rhs(i) += fe_values.shape_value(i, q) * (ci == 2 ? -1. : 0.) * fe_values.JxW(q);
          }
        cell->get_dof_indices(local_dof_indices);
        constraints.distribute_local_to_global(cell_matrix, cell_rhs, local_dof_indices, A, b);
      }
    r.assembly = timer.wall_time();

    timer.restart();
    std::vector<Point<3>> points(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(MappingQ1<3>(), dof_handler, points);
    std::vector<std::vector<double>> modes(6, std::vector<double>(dof_handler.n_dofs()));
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local_dof_indices);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            const auto         d = local_dof_indices[i];
            const Tensor<1, 3> x = points[d] - Point<3>(0.5, 0.5, 0.5);
            modes[c][d]          = 1;
            for (unsigned int a = 0; a < 3; ++a)
              {
                Tensor<1, 3> axis;
                axis[a]                   = 1;
                modes[3 + a][d]           = cross_product_3d(axis, x)[c];
              }
          }
      }
    dealvem::LinearSolver::Settings settings;
    settings.type               = dealvem::LinearSolver::Type::cg_amg;
    settings.relative_tolerance = 1e-8;
    dealvem::LinearSolver solver(settings);
    solver.set_near_null_space(modes);
    solver.solve(A, x, b);
    constraints.distribute(x);
    r.solve       = timer.wall_time();
    r.iterations  = solver.last_iterations();
    r.nnz_per_row = double(sp.n_nonzero_elements()) / sp.n_rows();
    r.cells       = tria.n_active_cells();
    r.dofs        = dof_handler.n_dofs();
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      std::string                      which = "vem-hex";
      unsigned int                     dofs  = 100000;
      for (int i = 1; i + 1 < argc; i += 2)
        {
          const std::string a = argv[i], v = argv[i + 1];
          if (a == "--case")
            which = v;
          else if (a == "--dofs")
            dofs = std::stoul(v);
          else
            AssertThrow(false, ExcMessage("unknown option " + a));
        }
      AssertThrow(which == "vem-hex" || which == "vem-voronoi" || which == "feq1" || which == "feq2",
                  ExcMessage("--case must be vem-hex, vem-voronoi, feq1 or feq2, not " + which));
      const Result r = which == "feq1" ? feq(1, dofs) :
                       which == "feq2" ? feq(2, dofs) :
                                         vem(which == "vem-voronoi", dofs);
      std::cout << "RESULT " << which << ' ' << r.cells << ' ' << r.dofs << ' ' << r.mesh << ' ' << r.assembly << ' '
                << r.solve << ' ' << r.iterations << ' ' << peak_mb() << ' ' << r.nnz_per_row << std::endl;
    }
  catch (std::exception &e)
    {
      std::cerr << "benchmark_polyhedral: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
