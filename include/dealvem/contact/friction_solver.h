// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_friction_solver_h
#define dealvem_contact_friction_solver_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/friction_state_update.h>
#include <dealvem/contact/rigid_body_support.h>
#include <dealvem/solvers/saddle_point_solver.h>

#include <array>
#include <vector>

namespace dealvem
{
  /**
   * One quasi-static load step of node-to-node contact with Coulomb
   * friction, solved by a semismooth Newton method, written as a
   * primal-dual active set over the pair states open / stick / slip
   * (Hüeber, Stadler and Wohlmuth, SIAM J. Sci. Comput. 30, 2008,
   * @cite HueeberStadlerWohlmuth2008). Its test against the partial slip
   * of Cattaneo and Mindlin (tutorial step-4) follows
   * @cite Mindlin1949 and @cite Johnson1985.
   *
   * Per pair $i$ (tributary weight $w_i$, normal multiplier $\lambda_{n,i}$,
   * tangential nodal force $\lambda_{t,i}$, see
   * ContactAssembler::assemble_friction()) let
   * $p_i = -\lambda_{n,i}/w_i$ be the pressure, $\tau_i = \lambda_{t,i}/w_i$
   * the friction traction, $g_i$ the gap and $\Delta s_i$ the slip increment
   * against the last converged step. Coulomb's law,
   * $g_i\ge 0,\ p_i\ge 0,\ g_ip_i = 0$, $|\tau_i|\le\mu p_i$,
   * $|\tau_i| < \mu p_i \Rightarrow \Delta s_i = 0$,
   * $|\tau_i| = \mu p_i \Rightarrow \tau_i\Delta s_i \ge 0$, is equivalent to
   * the two complementarity functions (any $c > 0$)
   * @f[ C_n = p_i - \max(0,\ \hat p_i) = 0,\qquad \hat p_i = p_i - c\,g_i, @f]
   * @f[ C_t = \max(\mu\hat p_i^+,\ |\hat\tau_i|)\,\tau_i - \mu\hat p_i^+\,\hat\tau_i = 0,
   *     \qquad \hat\tau_i = \tau_i + c\,\Delta s_i . @f]
   * A semismooth Newton step on them is: open where $\hat p_i \le 0$;
   * otherwise stick where $|\hat\tau_i|\le\mu\hat p_i$, and slip in the
   * direction $\sigma_i = \mathrm{sign}\,\hat\tau_i$ elsewhere, with the
   * linear equations of ContactAssembler::assemble_friction(). In 2D the
   * slip direction is a sign, whose derivative vanishes, so the Newton step
   * and the active-set step are the same and every iteration is one linear
   * saddle-point solve. The iteration stops when the states repeat; a set
   * of states seen before means a cycle and stops with the history, and so
   * does the iteration limit.
   *
   * Two rules keep the iteration from oscillating. A slipping pair whose
   * trial traction $\hat\tau_i$ turned round is set to stick, not to slip
   * the other way: with $c = E/h$ the term $c\,\Delta s_i$ of an iterate
   * that still carries the old friction force dominates $\hat\tau_i$, and
   * without the rule a reversed load (unloading) makes whole groups of pairs
   * jump between the two slip directions. And where the next states would
   * leave a body free (every pair that holds it tangentially slipping), the
   * would-be slipping pairs closest to the friction cone (smallest
   * $|\hat\tau_i|/(\mu\hat p_i)$) stick until every body is held; an
   * iterate may pass through such a set on its way to equilibrium.
   *
   * With the penalty variant (ContactSettings::coulomb_penalty) the trial
   * traction is $\hat\tau_i = \varepsilon_t (s_i - s^p_i)$ (return mapping
   * of elasto-plastic slip; $s^p_i$ the plastic slip of the last step), and
   * stick means $\tau_i = \varepsilon_t (s_i - s^p_i)$.
   *
   * If that safeguard is needed at the converged states, at states visited
   * before, or in three iterations in a row, or if a body would be free even
   * with every closed pair sticking (pulled off its partner), the load step
   * has no static equilibrium (for example a tangential load above $\mu$
   * times the normal load on a body held only by friction) and solve()
   * throws a message saying so.
   *
   * <h3>Driver and rule</h3>
   * solve() only owns the loop (assemble_friction() for the current
   * states, the linear solve); every rule above lives in
   * FrictionStateUpdate, which a program or a Newton method for finite
   * strain can call from its own loop.
   */
  template <int dim>
  class FrictionSolver
  {
  public:
    /// What solve() returns for one load step besides the solution.
    struct Result
    {
      /// The converged state of each pair (open, stick, slip along +t or
      /// -t); the states to start the next load step from.
      std::vector<PairState> state;
      /// Newton (active-set) iterations, i.e. saddle-point solves.
      unsigned int                              n_iterations = 0;
      /// Per iteration, the numbers of open, sticking and slipping pairs of
      /// the states it solved with.
      std::vector<std::array<unsigned int, 3>> history;
      /// Iterations of the linear solver summed over all saddle-point
      /// solves (SaddlePointSolver::last_iterations(): 1 per direct solve).
      unsigned int                              linear_iterations = 0;
      /// @var std::vector<double> slip
      /// Per pair, the relative tangential displacement
      /// $s_i = (u_B-u_A)\cdot t_i$ at the end of the step (length units).
      /// @var std::vector<double> slip_increment
      /// Per pair, the slip of this step against the reference of the last
      /// one: $s_i$ minus the reference with multipliers, the increment of
      /// the plastic slip with the penalty variant; zero for open pairs.
      /// @var std::vector<double> tangential_multiplier
      /// Per pair, the friction nodal force $\lambda_{t,i}$ (the slave node
      /// receives $-\lambda_{t,i} t_i$).
      /// @var std::vector<double> reference
      /// Per pair, the reference for the next step, to pass to its solve():
      /// the relative tangential displacement, or the plastic slip with the
      /// penalty variant.
      std::vector<double> slip, slip_increment, tangential_multiplier, reference;
      /// Energy dissipated by friction in this step,
      /// $\sum_{\text{slip}} \lambda_{t,i}\,\Delta s_i$ (with the penalty, the
      /// plastic slip increment).
      double dissipated_energy = 0;
    };

    /// @p c is the constant of the complementarity functions (units E/h).
    FrictionSolver(const ContactAssembler<dim>             &contact,
                   const dealii::AffineConstraints<double> &constraints,
                   SaddlePointSolver                       &solver,
                   const ContactSettings                   &settings,
                   const double                             c);

    /// Check every set of states against the rigid-body motions.
    void
    set_support(const RigidBodySupport *support)
    {
      this->support = support;
    }

    /**
     * The states of a first load step: pairs whose initial gap is closed
     * stick, the others are open; with a support, further pairs of smallest
     * gap are closed until every body is held.
     */
    std::vector<PairState>
    initial_state() const;

    /**
     * Solve one load step. @p system_matrix and @p system_rhs hold the
     * elasticity part (as for ActiveSetSolver); @p state holds the states to
     * start from (those of the last converged step, or initial_state()), and
     * @p reference the Result::reference of the last converged step (zeros
     * for the first). On return @p x holds displacements and multipliers.
     */
    Result
    solve(const dealii::SparseMatrix<double> &system_matrix,
          const dealii::Vector<double>       &system_rhs,
          dealii::SparseMatrix<double>       &matrix,
          dealii::Vector<double>             &x,
          const std::vector<PairState>       &state,
          const std::vector<double>          &reference);

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
