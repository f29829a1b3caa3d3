// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// 3D linear elasticity on the unit cube (face x = 0 clamped, body force
// (0, 0, -1), E = 1, nu = 0.3) with first-order virtual elements on
// polyhedra against deal.II's own FE_Q(1)^3 and FE_Q(2)^3 (assembled the
// step-8 way) on about the same number of DoFs, all solved by CG with ML AMG
// (six rigid-body modes, relative tolerance 1e-8):
//
//   [mpirun -np N] benchmark_polyhedral --case vem-hex|vem-voronoi|feq1|feq2 --dofs N
//                                       [--path serial|distributed]
//
// vem-hex: the hexahedra of a deal.II mesh as polyhedra; vem-voronoi:
// centroidal Voronoi polyhedra (CGAL, 10 Lloyd iterations). Process 0
// prints one line "RESULT case cells dofs t_mesh t_assembly t_solve
// iterations peak_MB nnz_per_row" (wall seconds; t_assembly includes the
// sparsity pattern and the constraints; t_solve the AMG set-up), and one
// line "CHECK case processes N path P l2 |u|_2 linf |u|_inf" with norms of
// the displacement vector (independent of the DoF numbering, for comparing
// runs on different numbers of processes). benchmarks/polyhedral/run.sh runs
// every case and size in its own process (or mpirun).
//
// On one process (the default --path serial) every case runs as before MPI
// was added: FE_Q(k) on a dealii::Triangulation with a dealii::SparseMatrix
// solved by dealvem::LinearSolver, so the numbers stay comparable with the
// tables in doc/benchmarks.md. On N > 1 processes (feq1/feq2 also with
// --path distributed on one):
// - feq1/feq2 run the step-40 way on a parallel::shared::Triangulation
//   partitioned by METIS: every process keeps the whole mesh, as
//   PolyhedralElasticity keeps the whole PolyhedralMesh on every process,
//   so the two sides are distributed alike; each process assembles its own
//   cells into the locally owned rows of a TrilinosWrappers::SparseMatrix,
//   and dealvem::ParallelLinearSolver solves (the same ML settings as
//   LinearSolver);
// - vem-hex/vem-voronoi hand MPI_COMM_WORLD to PolyhedralElasticity.
// The times are the maximum over the processes of each stage (the stages
// start together, after a barrier); the peak memory is the sum over the
// processes of their peak resident sizes (getrusage), so that memory per
// DoF compares with one process.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/shared_tria.h>
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
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <dealvem/app/polyhedral_elasticity.h>
#include <dealvem/mesh/polyhedral_generators.h>
#include <dealvem/mesh/polyhedral_mesh.h>
#include <dealvem/solvers/linear_solver.h>
#include <dealvem/solvers/parallel_solver.h>

#include <sys/resource.h>

#include <cmath>
#include <iomanip>
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
    // norms of the displacement vector (the CHECK line)
    double l2 = 0, linf = 0;
  };

  /// This process's peak resident size in MB.
  double
  peak_mb()
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.;
  }

  /// Wait for all processes, so that a stage's timer starts on all together.
  void
  barrier()
  {
    const int ierr = MPI_Barrier(MPI_COMM_WORLD);
    AssertThrowMPI(ierr);
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
    // (on one process the communicator has one process: the serial path)
    dealvem::PolyhedralElasticity problem(mesh, settings, MPI_COMM_WORLD);
    problem.add_dirichlet(100, [](const Point<3> &) { return Tensor<1, 3>(); });
    problem.set_body_force([](const Point<3> &) { return Tensor<1, 3>({0, 0, -1}); });
    // (solve() times assembly and solve on each process; they start together)
    barrier();
    problem.solve();
    r.assembly    = problem.last_times().first;
    r.solve       = problem.last_times().second;
    r.iterations  = problem.last_iterations();
    r.cells       = mesh.n_cells();
    r.dofs        = problem.n_dofs();
    r.nnz_per_row = double(problem.n_matrix_entries()) / problem.n_dofs();
    r.l2          = problem.solution().l2_norm();
    r.linf        = problem.solution().linfty_norm();
    return r;
  }

  /// step-8's cell matrix and right-hand side (body force (0, 0, -1)) on
  /// the cell fe_values was reinitialized on.
  void
  assemble_cell(const FESystem<3>  &fe,
                const FEValues<3>  &fe_values,
                FullMatrix<double> &cell_matrix,
                Vector<double>     &cell_rhs)
  {
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    cell_matrix = 0;
    cell_rhs    = 0;
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
  }

  /// Component c of the six rigid-body modes at x (translations, then
  /// rotations about the centre of the cube), as entries of @p modes at @p d.
  void
  set_rigid_modes(std::vector<std::vector<double>> &modes,
                  const types::global_dof_index     d,
                  const unsigned int                c,
                  const Point<3>                   &point)
  {
    const Tensor<1, 3> x = point - Point<3>(0.5, 0.5, 0.5);
    modes[c][d]          = 1;
    for (unsigned int a = 0; a < 3; ++a)
      {
        Tensor<1, 3> axis;
        axis[a]         = 1;
        modes[3 + a][d] = cross_product_3d(axis, x)[c];
      }
  }

  /// The cells per direction of FE_Q(degree)^3 on about target_dofs DoFs.
  unsigned int
  feq_subdivisions(const unsigned int degree, const unsigned int target_dofs)
  {
    return std::max(1u, unsigned(std::cbrt(target_dofs / 3.) / degree));
  }

  /// FE_Q(degree)^3 on one process: a dealii::SparseMatrix solved by
  /// LinearSolver (the path of the stored tables).
  Result
  feq(const unsigned int degree, const unsigned int target_dofs)
  {
    Result           r;
    Timer            timer;
    Triangulation<3> tria;
    GridGenerator::subdivided_hyper_cube(tria, feq_subdivisions(degree, target_dofs), 0, 1, true);
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
    const QGauss<3>    quadrature(degree + 1);
    FEValues<3>        fe_values(fe, quadrature, update_values | update_gradients | update_JxW_values);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
    Vector<double>     cell_rhs(dofs_per_cell);
    std::vector<types::global_dof_index> local_dof_indices(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        assemble_cell(fe, fe_values, cell_matrix, cell_rhs);
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
          set_rigid_modes(modes, local_dof_indices[i], fe.system_to_component_index(i).first,
                          points[local_dof_indices[i]]);
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
    r.l2          = x.l2_norm();
    r.linf        = x.linfty_norm();
    return r;
  }

  /// FE_Q(degree)^3 on the processes of MPI_COMM_WORLD, the step-40 way on
  /// a parallel::shared::Triangulation partitioned by METIS. Times are this
  /// process's (main() takes the maximum).
  Result
  feq_distributed(const unsigned int degree, const unsigned int target_dofs)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    Result         r;
    barrier();
    Timer                              timer;
    parallel::shared::Triangulation<3> tria(comm, Triangulation<3>::none, false,
                                            parallel::shared::Triangulation<3>::partition_metis);
    GridGenerator::subdivided_hyper_cube(tria, feq_subdivisions(degree, target_dofs), 0, 1, true);
    r.mesh = timer.wall_time();

    barrier();
    timer.restart();
    const FESystem<3> fe(FE_Q<3>(degree), 3);
    DoFHandler<3>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    AffineConstraints<double> constraints(relevant);
    VectorTools::interpolate_boundary_values(dof_handler, 0, Functions::ZeroFunction<3>(3), constraints);
    constraints.close();
    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
    TrilinosWrappers::SparseMatrix A;
    A.reinit(owned, owned, dsp, comm);
    TrilinosWrappers::MPI::Vector b(owned, comm), x(owned, comm);
    const QGauss<3>               quadrature(degree + 1);
    FEValues<3>                   fe_values(fe, quadrature, update_values | update_gradients | update_JxW_values);
    const unsigned int            dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double>            cell_matrix(dofs_per_cell, dofs_per_cell);
    Vector<double>                cell_rhs(dofs_per_cell);
    std::vector<types::global_dof_index> local_dof_indices(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          assemble_cell(fe, fe_values, cell_matrix, cell_rhs);
          cell->get_dof_indices(local_dof_indices);
          constraints.distribute_local_to_global(cell_matrix, cell_rhs, local_dof_indices, A, b);
        }
    A.compress(VectorOperation::add);
    b.compress(VectorOperation::add);
    r.assembly = timer.wall_time();

    barrier();
    timer.restart();
    // the rigid-body modes at the support points of the own cells' DoFs
    // (these include every owned DoF; ParallelLinearSolver reads only the
    // owned entries of the full-length vectors)
    std::vector<std::vector<double>> modes(6, std::vector<double>(dof_handler.n_dofs()));
    const MappingQ1<3>               mapping;
    FEValues<3> support_values(mapping, fe, Quadrature<3>(fe.get_unit_support_points()), update_quadrature_points);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          support_values.reinit(cell);
          cell->get_dof_indices(local_dof_indices);
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            set_rigid_modes(modes, local_dof_indices[i], fe.system_to_component_index(i).first,
                            support_values.quadrature_point(i));
        }
    dealvem::LinearSolver::Settings settings;
    settings.type               = dealvem::LinearSolver::Type::cg_amg;
    settings.relative_tolerance = 1e-8;
    dealvem::ParallelLinearSolver solver(settings);
    solver.set_near_null_space(modes, owned);
    solver.solve(A, x, b);
    constraints.distribute(x);
    r.solve       = timer.wall_time();
    r.iterations  = solver.last_iterations();
    r.nnz_per_row = double(A.n_nonzero_elements()) / A.m();
    r.cells       = tria.n_active_cells();
    r.dofs        = dof_handler.n_dofs();
    r.l2          = x.l2_norm();
    r.linf        = x.linfty_norm();
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  // (outside the try: a process that throws aborts the others, see below)
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               n_processes = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  const bool                       rank_0      = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  try
    {
      std::string  which = "vem-hex", path = n_processes > 1 ? "distributed" : "serial";
      unsigned int dofs = 100000;
      for (int i = 1; i < argc; i += 2)
        {
          const std::string a = argv[i];
          AssertThrow(i + 1 < argc, ExcMessage("option " + a + " needs a value"));
          const std::string v = argv[i + 1];
          if (a == "--case")
            which = v;
          else if (a == "--dofs")
            dofs = std::stoul(v);
          else if (a == "--path")
            path = v;
          else
            AssertThrow(false, ExcMessage("unknown option " + a));
        }
      AssertThrow(which == "vem-hex" || which == "vem-voronoi" || which == "feq1" || which == "feq2",
                  ExcMessage("--case must be vem-hex, vem-voronoi, feq1 or feq2, not " + which));
      AssertThrow(path == "distributed" || (path == "serial" && n_processes == 1),
                  ExcMessage("--path must be serial (one process only) or distributed, not " + path));
      const bool   distributed = path == "distributed";
      const Result r           = which == "feq1"   ? (distributed ? feq_distributed(1, dofs) : feq(1, dofs))
                                 : which == "feq2" ? (distributed ? feq_distributed(2, dofs) : feq(2, dofs))
                                                   : vem(which == "vem-voronoi", dofs);
      // the slowest process's stage times; the memory of all processes
      const double t_mesh     = Utilities::MPI::max(r.mesh, MPI_COMM_WORLD);
      const double t_assembly = Utilities::MPI::max(r.assembly, MPI_COMM_WORLD);
      const double t_solve    = Utilities::MPI::max(r.solve, MPI_COMM_WORLD);
      const double memory     = Utilities::MPI::sum(peak_mb(), MPI_COMM_WORLD);
      if (rank_0)
        {
          std::cout << "RESULT " << which << ' ' << r.cells << ' ' << r.dofs << ' ' << t_mesh << ' ' << t_assembly
                    << ' ' << t_solve << ' ' << r.iterations << ' ' << memory << ' ' << r.nnz_per_row << std::endl;
          std::cout << "CHECK " << which << " processes " << n_processes << " path " << path << std::setprecision(12)
                    << " l2 " << r.l2 << " linf " << r.linf << std::endl;
        }
    }
  catch (std::exception &e)
    {
      std::cerr << "benchmark_polyhedral: " << e.what() << std::endl;
      // the other processes may wait in a collective call for this one
      if (n_processes > 1)
        MPI_Abort(MPI_COMM_WORLD, 1);
      return 1;
    }
  return 0;
}
