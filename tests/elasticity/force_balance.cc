// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The verification after a solve (ForceBalance, internal::check_residual,
// the iterative refinement of internal::solve_direct) and the support per
// edge-connected piece (BoundaryConditions::check_rigid_body_support):
// - a block on [0,2] x [0,1] clamped on the left, a traction (0, -1) on the
//   right and a body force (0.3, -0.5), k = 1, 2, solved by UMFPACK, KLU and
//   CG-AMG: the applied force is (0.6, -2), the reactions balance it and
//   the imbalance and residual are below 1e-12 relative (direct);
// - the same solution checked against a load 1 % larger: the imbalance is
//   0.005 relative and the check fires with "is not in equilibrium";
// - a solution perturbed at one interior DoF fires on the residual, and
//   check_residual refuses it;
// - solve_direct reaches a componentwise backward error of a few eps;
// - two squares meeting at a vertex (a hinge) and two disjoint squares of
//   one body: the unheld piece is named with its cells, centroid and box;
//   clamping both pieces passes.
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/elasticity/force_balance.h>
#include <dealvem/mesh/connected_pieces.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/solvers/linear_solver.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "../tests.h"

using namespace dealvem;

namespace
{
  const std::map<dealii::types::material_id, ElasticMaterial> materials = {
    {0, ElasticMaterial(200, 0.3, ElasticMaterial::Model::plane_strain)}};

  struct Solved
  {
    dealii::SparsityPattern      sparsity;
    dealii::SparseMatrix<double> A;
    dealii::Vector<double>       b, x;
  };

  void
  add_loads(ElasticityAssembler<2> &a, const dealii::Function<2> &traction, const dealii::Function<2> &body_force)
  {
    a.add_traction(1, traction);
    a.set_body_force(body_force);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const dealii::Functions::ConstantFunction<2> traction(std::vector<double>{0., -1.});
  const dealii::Functions::ConstantFunction<2> traction_more(std::vector<double>{0., -1.01});
  const dealii::Functions::ConstantFunction<2> body_force(std::vector<double>{0.3, -0.5});
  for (const unsigned int k : {1u, 2u})
    for (const auto type : {LinearSolver::Type::umfpack, LinearSolver::Type::klu, LinearSolver::Type::cg_amg})
      {
        const std::string tag = "k=" + std::to_string(k) + " " +
                                (type == LinearSolver::Type::umfpack ? "UMFPACK" :
                                 type == LinearSolver::Type::klu     ? "KLU" :
                                                                       "CG-AMG");
        PolygonalMesh<2> mesh;
        PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(2, 1), 8, 4);
        VEMDoFHandler<2> dh(mesh);
        dh.distribute_dofs(k);
        dealii::AffineConstraints<double>            cons;
        const dealii::Functions::ZeroFunction<2>     zero(2);
        BoundaryConditions::interpolate_boundary_values(dh, {0}, zero, {{true, true}}, cons);
        cons.close();
        BoundaryConditions::check_rigid_body_support(dh, cons);
        Solved                         s;
        dealii::DynamicSparsityPattern dsp(dh.n_dofs());
        dh.make_sparsity_pattern(dsp, cons);
        s.sparsity.copy_from(dsp);
        s.A.reinit(s.sparsity);
        ElasticityAssembler<2> assembler(dh, materials);
        add_loads(assembler, traction, body_force);
        assembler.assemble(cons, s.A, s.b);
        LinearSolver::Settings settings;
        settings.type               = type;
        settings.relative_tolerance = 1e-12;
        LinearSolver solver(settings);
        if (type == LinearSolver::Type::cg_amg)
          solver.set_near_null_space(dh.rigid_body_modes());
        solver.solve(s.A, s.x, s.b);
        cons.distribute(s.x);
        const double tol = (type == LinearSolver::Type::cg_amg ? 1e-12 : 0.);
        const auto   balance = ForceBalance::compute(assembler, cons, s.x, dealii::Vector<double>(), tol);
        testing::check(balance.size() == 1, tag + ": one body");
        const auto &b = balance[0];
        testing::check_near(b.applied[0], 0.6, 1e-13, tag + ": applied force x (body force 0.3 times area 2)");
        testing::check_near(b.applied[1], -2., 1e-13, tag + ": applied force y (-1 on the right side, -0.5 times 2)");
        testing::check_near(b.reaction[0], -0.6, 1e-10, tag + ": the reactions balance x");
        testing::check_near(b.reaction[1], 2., 1e-10, tag + ": the reactions balance y");
        if (type != LinearSolver::Type::cg_amg)
          {
            testing::check_small(b.imbalance, 1e-12, tag + ": relative imbalance of force and moment");
            testing::check_small(b.residual, 1e-12, tag + ": relative residual");
          }
        else
          {
            testing::check_small(b.imbalance, 1e-9, tag + ": relative imbalance of force and moment");
            testing::check_small(b.residual, 1e-9, tag + ": relative residual");
          }
        {
          std::ostringstream t;
          t << tag << ": within the tolerance " << b.tolerance << " (condition " << b.condition << ")";
          testing::check(b.ok() && b.tolerance < 1e-7, t.str());
        }
        ForceBalance::check(balance, "the test");

        // the same solution against a traction 1 % larger: the right side
        // lacks 0.01 of force, 0.005 of the 2 applied
        ElasticityAssembler<2> wrong(dh, materials);
        add_loads(wrong, traction_more, body_force);
        const auto off = ForceBalance::compute(wrong, cons, s.x, dealii::Vector<double>(), tol);
        // (the missing force -0.01 at x = 2 has the moment -0.01 about the
        // centroid (1, 0.5), whose distance to a corner is sqrt(1.25))
        testing::check_near(off[0].imbalance, (0.01 + 0.01 / std::sqrt(1.25)) / off[0].forces,
                            1e-9 / off[0].forces, tag + ": relative imbalance of the missing force and moment");
        testing::check(!off[0].ok(), tag + ": out of balance");
        testing::check_throws([&] { ForceBalance::check(off, "the test"); }, "body 0 is not in equilibrium",
                              tag + ": the check fires with the figures");

        // one interior DoF perturbed: the residual fires
        dealii::Vector<double> y = s.x;
        const unsigned int     i = 2 * 22 + 1; // y of an interior vertex
        y[i] += 1e-3 * s.x.linfty_norm();
        const auto bad = ForceBalance::compute(assembler, cons, y, dealii::Vector<double>(), tol);
        testing::check(bad[0].residual > 1e3 * bad[0].tolerance, tag + ": perturbed solution, residual " +
                                                                   std::to_string(bad[0].residual));
        testing::check_throws([&] { ForceBalance::check(bad, "the test"); }, "the residual of its equations is",
                              tag + ": the residual check fires");
        testing::check_throws([&] { internal::check_residual(s.A, y, s.b, 0., "UMFPACK"); },
                              "is inaccurate", tag + ": check_residual refuses the perturbed solution");
        if (type == LinearSolver::Type::umfpack)
          {
            dealii::Vector<double> z;
            const double           omega = internal::solve_direct(s.A, z, s.b, false);
            testing::check_small(omega, 8 * std::numeric_limits<double>::epsilon(),
                                 tag + ": componentwise backward error after refinement");
          }
      }

  // pieces: a hinge and a disjoint square
  for (const double dx : {1., 2.})
    {
      const std::string tag = (dx == 1 ? "hinge" : "disjoint squares");
      PolygonalMesh<2>  mesh;
      for (const auto &p : {dealii::Point<2>(0, 0), dealii::Point<2>(1, 0), dealii::Point<2>(1, 1),
                            dealii::Point<2>(0, 1), dealii::Point<2>(dx + 1, 1), dealii::Point<2>(dx + 1, 2),
                            dealii::Point<2>(dx, 2)})
        mesh.add_vertex(p);
      if (dx == 1)
        mesh.add_cell({0, 1, 2, 3});
      else
        mesh.add_vertex(dealii::Point<2>(dx, 1));
      if (dx == 1)
        mesh.add_cell({2, 4, 5, 6});
      else
        {
          mesh.add_cell({0, 1, 2, 3});
          mesh.add_cell({7, 4, 5, 6});
        }
      mesh.set_boundary_id(0, 1, 1);
      mesh.set_boundary_id(5, 6, 2);
      mesh.finalize();
      const ConnectedPieces pieces(mesh);
      testing::check(pieces.n_pieces() == 2, tag + ": two pieces");
      VEMDoFHandler<2> dh(mesh);
      dh.distribute_dofs(2);
      const dealii::Functions::ZeroFunction<2> zero(2);
      dealii::AffineConstraints<double>        cons;
      BoundaryConditions::interpolate_boundary_values(dh, {1}, zero, {{true, true}}, cons);
      cons.close();
      testing::check_throws([&] { BoundaryConditions::check_rigid_body_support(dh, cons); },
                            std::string("piece 1 of body 0 (1 cell; cell 1, centroid (") + (dx == 1 ? "1.5" : "2.5") +
                              ", 1.5); bounding box [" + (dx == 1 ? "1, 2" : "2, 3") + "] x [1, 2])",
                            tag + ": the unheld piece is named");
      testing::check_throws([&] { BoundaryConditions::check_rigid_body_support(dh, cons); }, "[rotation of piece 1]",
                            tag + ": with its free motions");
      dealii::AffineConstraints<double> both;
      BoundaryConditions::interpolate_boundary_values(dh, {1, 2}, zero, {{true, true}}, both);
      both.close();
      bool passed = true;
      try
        {
          BoundaryConditions::check_rigid_body_support(dh, both);
        }
      catch (...)
        {
          passed = false;
        }
      testing::check(passed, tag + ": both pieces clamped: supported");
    }
  return testing::n_failures() == 0 ? 0 : 1;
}
