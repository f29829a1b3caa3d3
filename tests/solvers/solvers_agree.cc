// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The three solvers of LinearSolver (UMFPACK, Amesos KLU, CG + ML AMG with
// the rigid-body modes) on one VEM k = 2 elasticity system (Voronoi mesh,
// left side clamped, traction on the right, body force): pairwise relative
// differences <= 1e-8, backward errors of the direct solvers <= 1e-14; and an
// unknown solver name is rejected with the valid choices.
#include <deal.II/base/mpi.h>

#include <dealvem/solvers/linear_solver.h>

#include "../elasticity_common.h"
#include "../tests.h"

using namespace dealvem;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  PolygonalMesh<2>                         mesh;
  PolygonalMeshGenerators::voronoi(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(4, 1), 500, 10, 1);
  VEMDoFHandler<2> dof_handler(mesh);
  dof_handler.distribute_dofs(2);
  dealii::AffineConstraints<double> constraints;
  const dealii::Functions::ZeroFunction<2> zero(2);
  BoundaryConditions::interpolate_boundary_values(dof_handler, {0}, zero, {{true, true}}, constraints);
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

  std::vector<dealii::Vector<double>> x(3);
  const LinearSolver::Type            types[3] = {LinearSolver::Type::umfpack, LinearSolver::Type::klu,
                                                  LinearSolver::Type::cg_amg};
  for (unsigned int i = 0; i < 3; ++i)
    {
      LinearSolver::Settings s;
      s.type               = types[i];
      s.relative_tolerance = 1e-12;
      LinearSolver solver(s);
      solver.set_near_null_space(dof_handler.rigid_body_modes());
      solver.solve(A, x[i], b);
      std::cout << "      " << solver.description() << ": " << solver.last_iterations() << " iteration(s)"
                << std::endl;
      if (i < 2)
        {
          dealii::Vector<double> r(b.size());
          A.vmult(r, x[i]);
          r -= b;
          // normwise backward error |r| / (|A| |x| + |b|) (infinity norms)
          testing::check_small(r.linfty_norm() / (A.linfty_norm() * x[i].linfty_norm() + b.linfty_norm()), 1e-14,
                               LinearSolver::type_name(types[i]) + ": backward error");
        }
    }
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = i + 1; j < 3; ++j)
      {
        dealii::Vector<double> d = x[i];
        d -= x[j];
        testing::check_small(d.l2_norm() / x[j].l2_norm(), 1e-8,
                             LinearSolver::type_name(types[i]) + " vs " + LinearSolver::type_name(types[j]) +
                               ": relative difference");
      }
  testing::check_throws([] { LinearSolver::parse_type("foo"); }, "expected UMFPACK, KLU or CG-AMG",
                        "unknown solver name");
  return testing::finish();
}
