// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_active_set_solver_h
#define dealvem_contact_active_set_solver_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/rigid_body_support.h>
#include <dealvem/solvers/saddle_point_solver.h>

#include <vector>

namespace dealvem
{
  /**
   * Solves the contact problem: for tied normal contact one saddle-point
   * solve; for unilateral contact the primal-dual active set strategy of
   * Hüeber and Wohlmuth (2005).
   *
   * With the compressive nodal force $\mu_i = -\lambda_i \ge 0$, the
   * conditions $g_i\ge 0$, $\mu_i\ge 0$, $g_i\mu_i = 0$ are equivalent to
   * $\mu_i = \max(0, \mu_i - c\,w_i\,g_i)$ for any $c > 0$. Starting from the
   * pairs whose initial gap is closed ($g_{0,i}\le 0$), each iteration solves
   * with $g_i = 0$ on the active set and $\lambda_i = 0$ elsewhere, then
   * takes the new active set $\{i : \mu_i/w_i - c\,g_i > 0\}$, until it does
   * not change. A set seen before (other than the last one) means the
   * iteration cycles: this and exceeding the iteration limit throw an
   * exception with the iteration history.
   *
   * With a RigidBodySupport (set_support()), bodies that start apart or
   * touch at a single point get a first active set that holds them: the
   * pairs of smallest initial gap are closed until every body is held (the
   * contact a rigid approach makes first), so the first system is not
   * singular, whatever the solver. An active set that would leave a body
   * free (every pair that held it pulled open) means there is no static
   * equilibrium: solve() then stops with a message naming the free motions.
   */
  template <int dim>
  class ActiveSetSolver
  {
  public:
    struct Result
    {
      std::vector<bool>         active;
      unsigned int              n_iterations = 0;
      std::vector<unsigned int> n_active_history;
      unsigned int              linear_iterations = 0;
      /// Pairs with an open initial gap closed for the first iteration so
      /// that every body is held.
      unsigned int              n_closed_for_support = 0;
    };

    /// @p c is the constant of the active-set update, units of E/h.
    ActiveSetSolver(const ContactAssembler<dim>             &contact,
                    const dealii::AffineConstraints<double> &constraints,
                    SaddlePointSolver                       &solver,
                    const ContactSettings                   &settings,
                    const double                             c);

    /**
     * @p system_matrix and @p system_rhs hold the elasticity part (size
     * n_dofs + n_multipliers, assembled with the constraints). @p matrix
     * (same sparsity) is used as work space. On return @p x holds the
     * displacements followed by the multipliers.
     */
    /// Check every active set against the rigid-body motions (see above).
    void
    set_support(const RigidBodySupport *support)
    {
      this->support = support;
    }

    Result
    solve(const dealii::SparseMatrix<double> &system_matrix,
          const dealii::Vector<double>       &system_rhs,
          dealii::SparseMatrix<double>       &matrix,
          dealii::Vector<double>             &x);

  private:
    const ContactAssembler<dim>             &contact;
    const dealii::AffineConstraints<double> &constraints;
    SaddlePointSolver                       &solver;
    ContactSettings                          settings;
    double                                   c;
    const RigidBodySupport                  *support = nullptr;
  };
} // namespace dealvem

#endif
