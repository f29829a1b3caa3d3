// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Why the finite-strain stabilization is the trace rule scaled by the
// current tangent (FiniteStrainOperator): the smallest eigenvalue of the
// tangent stiffness on the free DoFs at the homogeneous state
// u = (F(s) - I) X, F(s) = I + s [[0.1, 0.3], [0.05, -0.3]] (s = 1: 30 %
// compression with shear, the state of finite_strain_patch_test; s = 1.9:
// 57 % compression), Voronoi mesh of 16 cells, k = 2, Neo-Hooke (E = 7000,
// nu = 0.3), Dirichlet data on three sides (ids 0, 2, 3), the
// stabilization frozen at that state. The eigenvalues are properties of the
// discrete operator (dense symmetric eigensolver, exact to round-off):
// - at s = 0 (the small-strain operator) every rule is positive definite;
// - trace rule, current-tangent scaling: positive definite at s = 1 and
//   s = 1.9 (measured 441 and 243, largest 7.0e5 and 2.4e6);
// - diagonal rule (the small-strain default for k = 2, c_2 = 1/5), current
//   scaling: indefinite at s = 1 (measured -950): a spurious mode, along
//   which Newton finds a wrong equilibrium when the fourth side carries
//   the matching traction;
// - trace rule with the plain small-strain scaling (initial tangent):
//   indefinite at s = 1.9 (measured -1152): Neo-Hooke stiffens in
//   compression, the initial scale does not follow.
// - boundary rule (tangential derivatives on the edges), current scaling:
//   positive definite at s = 0, 1 and 1.9, like the trace rule.
// Checked: the signs, with the smallest eigenvalue beyond 20 in absolute
// value (round-off is about 1e-10 of the largest).
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <iostream>

#include "../elasticity_common.h"
#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;

double
smallest_eigenvalue(const VEMDoFHandler<2> &dof_handler,
                    const double            s,
                    const Stabilization     rule,
                    const StabilizationScaling scaling)
{
  dealii::Tensor<2, 2> F;
  F[0][0] = 1. + 0.1 * s;
  F[0][1] = 0.3 * s;
  F[1][0] = 0.05 * s;
  F[1][1] = 1. - 0.3 * s;
  const testing::HomogeneousDeformation exact(F);
  const NeoHookeMaterial                law(7000., 0.3);
  FiniteStrainAssembler<2> assembler(dof_handler, testing::one_law_library(dof_handler, law), 1.0, rule, scaling);
  dealii::AffineConstraints<double> constraints, homogeneous;
  testing::dirichlet_constraints(dof_handler, {0, 2, 3}, exact, constraints);
  homogeneous.copy_from(constraints);
  for (const auto &line : constraints.get_lines())
    homogeneous.set_inhomogeneity(line.index, 0.);
  std::vector<dealii::Point<2>> support;
  dof_handler.map_dofs_to_support_points(support);
  dealii::Vector<double> u(dof_handler.n_dofs()), r, rhs;
  for (unsigned int i = 0; i < u.size(); ++i)
    u[i] = exact.value(support[i], i % 2);
  assembler.freeze_stabilization(u);
  dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
  dof_handler.make_sparsity_pattern(dsp, homogeneous);
  dealii::SparsityPattern sp;
  sp.copy_from(dsp);
  dealii::SparseMatrix<double> K(sp);
  assembler.assemble(u, 1., r, homogeneous, &K, &rhs);
  std::vector<unsigned int> free_dofs;
  for (unsigned int i = 0; i < dof_handler.n_dofs(); ++i)
    if (!constraints.is_constrained(i))
      free_dofs.push_back(i);
  dealii::LAPACKFullMatrix<double> A(free_dofs.size(), free_dofs.size());
  for (unsigned int a = 0; a < free_dofs.size(); ++a)
    for (unsigned int b = 0; b < free_dofs.size(); ++b)
      A(a, b) = sp.exists(free_dofs[a], free_dofs[b]) ? K.el(free_dofs[a], free_dofs[b]) : 0.;
  dealii::Vector<double>     eigenvalues;
  dealii::FullMatrix<double> eigenvectors;
  A.compute_eigenvalues_symmetric(-1e300, 1e300, 0., eigenvalues, eigenvectors);
  std::cout << "  s = " << s << ", " << (rule == Stabilization::trace ? "trace" : rule == Stabilization::boundary ? "boundary" : "diagonal") << " rule, "
            << (scaling == StabilizationScaling::current_tangent ? "current" : "initial")
            << "-tangent scaling: smallest eigenvalue " << eigenvalues[0] << ", largest "
            << eigenvalues[eigenvalues.size() - 1] << std::endl;
  return eigenvalues[0];
}

int
main()
{
  PolygonalMesh<2> mesh;
  testing::make_mesh(mesh, "voronoi", 0);
  VEMDoFHandler<2> dof_handler(mesh);
  dof_handler.distribute_dofs(2);
  using S  = Stabilization;
  using SS = StabilizationScaling;

  for (const S rule : {S::trace, S::diagonal, S::boundary})
    testing::check(smallest_eigenvalue(dof_handler, 0., rule, SS::current_tangent) > 20.,
                   "s = 0: positive definite");
  // the boundary rule (FiniteSliding's) keeps the trace rule's scale by
  // the current tangent: positive definite where the trace rule is
  for (const double s : {1., 1.9})
    testing::check(smallest_eigenvalue(dof_handler, s, S::boundary, SS::current_tangent) > 20.,
                   "s = " + std::to_string(s) + ", boundary rule, current tangent: positive definite");
  testing::check(smallest_eigenvalue(dof_handler, 1., S::trace, SS::current_tangent) > 20.,
                 "s = 1, trace rule, current tangent: positive definite");
  testing::check(smallest_eigenvalue(dof_handler, 1.9, S::trace, SS::current_tangent) > 20.,
                 "s = 1.9, trace rule, current tangent: positive definite");
  testing::check(smallest_eigenvalue(dof_handler, 1., S::diagonal, SS::current_tangent) < -20.,
                 "s = 1, diagonal rule (small-strain default for k = 2): indefinite");
  testing::check(smallest_eigenvalue(dof_handler, 1.9, S::trace, SS::initial_tangent) < -20.,
                 "s = 1.9, trace rule, small-strain (initial) scaling: indefinite");
  return testing::finish();
}
