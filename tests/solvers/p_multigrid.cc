// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The two-level p-multigrid preconditioner of LinearSolver (k = 2 smoothed by
// Chebyshev, Galerkin k = 1 level solved by ML AMG):
// - the prolongation k = 1 -> k = 2 maps the k = 1 interpolant of a linear
//   field to its k = 2 interpolant to 1e-12, on every mesh family of the
//   tests (convex, non-convex, collinear vertices), and maps the coarse
//   rigid-body modes to the fine ones;
// - CG with the p-multigrid solves a VEM k = 2 Voronoi problem (left side
//   clamped, a roller on the bottom, traction and body force) to the
//   UMFPACK solution within 1e-8, and "automatic" picks it once a coarse
//   space is given; its smoother in single precision (the default) and in
//   double precision need the same CG iterations;
// - the iteration count on that fixed mesh stays below a measured bound
//   (regression guard), and below plain AMG's;
// - misuse is rejected: degree-1 DoF handler, p-multigrid without a coarse
//   space, coarse modes of the wrong size, an unknown preconditioner name.
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <dealvem/solvers/linear_solver.h>
#include <dealvem/solvers/p_multigrid.h>

#include "../elasticity_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
  // a linear vector field, component c at p
  double
  linear_field(const dealii::Point<2> &p, const unsigned int c)
  {
    return c == 0 ? 1.0 + 2.0 * p[0] - 3.0 * p[1] : -0.5 + 0.7 * p[0] + 1.3 * p[1];
  }

  void
  check_linear_reproduction(const std::string &family)
  {
    PolygonalMesh<2> mesh;
    testing::make_mesh(mesh, family, 1);
    VEMDoFHandler<2> fine(mesh), coarse(mesh);
    fine.distribute_dofs(2);
    coarse.distribute_dofs(1);
    dealii::SparsityPattern          sp;
    dealii::SparseMatrix<double>     P;
    std::vector<std::vector<double>> coarse_modes;
    PMultigrid::make_prolongation(fine, sp, P, coarse_modes);
    testing::check(P.m() == fine.n_dofs() && P.n() == coarse.n_dofs(), family + ": P is n_dofs(2) x n_dofs(1)");

    // Interpolants: point values at vertices and midpoints; the cell moment
    // of a linear field is its value at the centroid (the node location).
    dealii::Vector<double> u1(coarse.n_dofs()), u2(fine.n_dofs()), Pu1(fine.n_dofs());
    for (unsigned int node = 0; node < coarse.n_nodes(); ++node)
      for (unsigned int c = 0; c < 2; ++c)
        u1[VEMDoFHandler<2>::node_dof(node, c)] = linear_field(coarse.node_location(node), c);
    for (unsigned int node = 0; node < fine.n_nodes(); ++node)
      for (unsigned int c = 0; c < 2; ++c)
        u2[VEMDoFHandler<2>::node_dof(node, c)] = linear_field(fine.node_location(node), c);
    P.vmult(Pu1, u1);
    Pu1 -= u2;
    testing::check_small(Pu1.linfty_norm() / u2.linfty_norm(), 1e-12,
                         family + ": P reproduces a linear field (relative max error)");

    // the rigid-body modes are linear fields too
    const auto fine_modes = fine.rigid_body_modes();
    double     mode_error = 0;
    for (unsigned int k = 0; k < 3; ++k)
      {
        dealii::Vector<double> m1(coarse_modes[k].begin(), coarse_modes[k].end()), m2(fine.n_dofs());
        P.vmult(m2, m1);
        for (unsigned int i = 0; i < fine.n_dofs(); ++i)
          mode_error = std::max(mode_error, std::abs(m2[i] - fine_modes[k][i]));
      }
    testing::check_small(mode_error, 1e-12, family + ": P maps the coarse rigid-body modes to the fine ones");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  for (const auto &family : testing::mesh_families())
    check_linear_reproduction(family);

  // The fixed mid-size problem: 2000 Voronoi cells on [0,4]x[0,1] (about
  // 24,000 DoFs), left side clamped, bottom on rollers (u_y = 0), traction
  // on the right, body force.
  PolygonalMesh<2> mesh;
  PolygonalMeshGenerators::voronoi(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(4, 1), 2000, 10, 1);
  VEMDoFHandler<2> dof_handler(mesh);
  dof_handler.distribute_dofs(2);
  dealii::AffineConstraints<double>        constraints;
  const dealii::Functions::ZeroFunction<2> zero(2);
  BoundaryConditions::interpolate_boundary_values(dof_handler, {0}, zero, {{true, true}}, constraints);
  BoundaryConditions::interpolate_boundary_values(dof_handler, {2}, zero, {{false, true}}, constraints);
  constraints.close();
  dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
  dof_handler.make_sparsity_pattern(dsp, constraints);
  dealii::SparsityPattern sp;
  sp.copy_from(dsp);
  dealii::SparseMatrix<double> A(sp);
  dealii::Vector<double>       b;
  const std::map<dealii::types::material_id, ElasticMaterial> materials = {{0, ElasticMaterial(1000, 0.3)}};
  ElasticityAssembler<2>                                      assembler(dof_handler, materials);
  const dealii::Functions::ConstantFunction<2>                f(std::vector<double>{0.5, -1.0});
  const dealii::Functions::ConstantFunction<2>                t(std::vector<double>{0.0, -2.0});
  assembler.set_body_force(f);
  assembler.add_traction(1, t);
  assembler.assemble(constraints, A, b);
  std::cout << "      mid-size problem: " << mesh.n_cells() << " Voronoi cells, " << dof_handler.n_dofs() << " DoFs"
            << std::endl;

  dealii::Vector<double> x_direct;
  {
    LinearSolver::Settings s;
    s.type = LinearSolver::Type::umfpack;
    LinearSolver solver(s);
    solver.solve(A, x_direct, b);
  }

  dealii::SparsityPattern          sp_P;
  dealii::SparseMatrix<double>     P;
  std::vector<std::vector<double>> coarse_modes;
  PMultigrid::make_prolongation(dof_handler, sp_P, P, coarse_modes);

  // the third run: the p-multigrid with its smoother in double precision
  unsigned int                       iterations[3]      = {0, 0, 0};
  const LinearSolver::Preconditioner preconditioners[3] = {LinearSolver::Preconditioner::amg,
                                                           LinearSolver::Preconditioner::automatic,
                                                           LinearSolver::Preconditioner::automatic};
  for (unsigned int k = 0; k < 3; ++k)
    {
      LinearSolver::Settings s;
      s.type                      = LinearSolver::Type::cg_amg;
      s.relative_tolerance        = 1e-12;
      s.preconditioner            = preconditioners[k];
      s.single_precision_smoother = (k != 2);
      LinearSolver solver(s);
      solver.set_near_null_space(dof_handler.rigid_body_modes());
      solver.set_coarse_space(P, coarse_modes);
      dealii::Vector<double> x;
      dealii::Timer          timer;
      solver.solve(A, x, b);
      iterations[k] = solver.last_iterations();
      std::cout << "      " << solver.description() << ": " << iterations[k] << " iterations, "
                << timer.wall_time() << " s" << std::endl;
      x -= x_direct;
      testing::check_small(x.l2_norm() / x_direct.l2_norm(), 1e-8,
                           LinearSolver::preconditioner_name(preconditioners[k]) +
                             ": CG solution against UMFPACK (relative)");
      if (k >= 1)
        testing::check(solver.effective_preconditioner() == LinearSolver::Preconditioner::p_multigrid,
                       "automatic means p-multigrid once a coarse space is given");
    }
  // Regression guard. Measured on this problem (deterministic: fixed Voronoi
  // seed, ML is deterministic) to the relative tolerance 1e-12: 26 CG
  // iterations with the p-multigrid (Chebyshev degree 3), 73 with plain
  // AMG. The bound 34 leaves 30 % for other ML/CGAL versions and round-off;
  // more means the preconditioner got worse (plain AMG is far above it).
  testing::check(iterations[1] <= 34, "p-multigrid iterations <= 34 (measured 26): " +
                                        std::to_string(iterations[1]));
  testing::check(iterations[1] < iterations[0], "p-multigrid needs fewer iterations than plain AMG");
  // The smoother reads the matrix in single precision by default: a
  // preconditioner that differs from the double-precision one by about 1e-7
  // relative, so CG needs the same iterations (measured: 30 both; one more
  // or less is allowed for round-off) and reaches the same tolerance (above).
  testing::check(iterations[1] + 1 >= iterations[2] && iterations[2] + 1 >= iterations[1],
                 "single- and double-precision smoother: the same CG iterations (" + std::to_string(iterations[1]) +
                   " and " + std::to_string(iterations[2]) + ")");

  // misuse
  testing::check_throws(
    [&] {
      VEMDoFHandler<2> k1(mesh);
      k1.distribute_dofs(1);
      dealii::SparsityPattern          s;
      dealii::SparseMatrix<double>     m;
      std::vector<std::vector<double>> cm;
      PMultigrid::make_prolongation(k1, s, m, cm);
    },
    "needs edge nodes and at most one moment per cell (k = 2); it has 0 node(s) per edge",
    "prolongation from a degree-1 DoF handler");
  testing::check_throws(
    [&] {
      LinearSolver::Settings s;
      s.type           = LinearSolver::Type::cg_amg;
      s.preconditioner = LinearSolver::Preconditioner::p_multigrid;
      LinearSolver           solver(s);
      dealii::Vector<double> x;
      solver.solve(A, x, b);
    },
    "needs the coarse space", "p-multigrid without a coarse space");
  testing::check_throws(
    [&] {
      LinearSolver::Settings s;
      LinearSolver           solver(s);
      solver.set_coarse_space(P, {std::vector<double>(3)});
    },
    "a coarse mode has 3 entries", "coarse mode of the wrong size");
  testing::check_throws([] { LinearSolver::parse_preconditioner("ilu"); }, "expected automatic, AMG or p-multigrid",
                        "unknown preconditioner name");
  return testing::finish();
}
