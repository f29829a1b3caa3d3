// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_solvers_p_multigrid_h
#define dealvem_solvers_p_multigrid_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <vector>

namespace dealvem
{
  template <int dim>
  class VEMDoFHandler;

  class VEMElementData;

  /**
   * The coarse space of the two-level p-multigrid preconditioner of
   * LinearSolver: the order-1 virtual element space on the same polygons as
   * an order-2 one.
   */
  namespace PMultigrid
  {
    /**
     * Whether make_prolongation() applies to a fine space of layout
     * @p layout: edge nodes (k >= 2; for k = 1 there is no coarser space)
     * and at most one moment per cell (the mean, whose value on a k = 1
     * function the prolongation writes from the k = 1 projection). True
     * for k = 2. The programs ask this, not the order, before they build
     * the p-multigrid.
     */
    bool
    applies_to(const VEMElementData &layout);

    /**
     * The prolongation P from the k = 1 space to the k = 2 space of
     * @p dof_handler (whose layout must satisfy applies_to()), as an
     * n_dofs(k=2) x n_dofs(k=1) matrix, and the three rigid-body modes of
     * the k = 1 space (the near-null space of the coarse AMG).
     *
     * A k = 1 virtual element function u1 is linear on every edge, so its
     * k = 2 degrees of freedom are exact: the vertex values are copied, an
     * edge node at the fraction t of its edge gets (1 - t) and t of the
     * edge's two end vertices (the mean for the midpoint), and the
     * cell moment is the mean over the polygon of the k = 1 projection
     * Pi u1. The projection is linear, so its mean is its value at the
     * centroid, written as an affine combination of its vertex values
     * (weights w_i = 1/N + (x_i - xbar)^T M^{-1} (x_c - xbar) with the vertex
     * mean xbar, the centroid x_c and M = sum (x_i - xbar)(x_i - xbar)^T).
     * Pi reproduces linear fields, hence so does P: for a linear field f,
     * P times the k = 1 interpolant of f is the k = 2 interpolant of f.
     * Both DoF numberings are VEMDoFHandler's.
     *
     * P is stored in @p P on the pattern @p sparsity (both owned by the
     * caller; @p sparsity must outlive @p P's use).
     */
    void
    make_prolongation(const VEMDoFHandler<2>           &dof_handler,
                      dealii::SparsityPattern          &sparsity,
                      dealii::SparseMatrix<double>     &P,
                      std::vector<std::vector<double>> &coarse_modes);
  } // namespace PMultigrid
} // namespace dealvem

#endif
