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
#include <dealvem/contact/contact_solver.h>
#include <dealvem/contact/friction_state_update.h>
#include <dealvem/contact/primal_active_set.h>
#include <dealvem/contact/rigid_body_support.h>
#include <dealvem/solvers/saddle_point_solver.h>

#include <array>
#include <memory>
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
   * times the normal load on a body held only by friction), as far as this
   * iteration can tell: near the friction limit it can also fail where an
   * equilibrium exists, so solve() then takes the globalized path below
   * (and, only if that does not find the solution, the continuation after
   * it), and throws "No static equilibrium" only when they end without one.
   *
   * <h3>The globalized path: sticking joints, then a fixed point of Tresca problems</h3>
   * With ContactSettings::globalize (the default), a failed plain iteration
   * first solves the same step with every closed pair sticking (at the
   * reference slips of the step: unlimited friction) by the globally
   * convergent PrimalActiveSetSolver. If that problem has no equilibrium,
   * the Coulomb problem has none either (finite friction allows fewer
   * force distributions), and solve() throws "No static equilibrium" with
   * the collapse mechanism (last_mechanism()): the joints open (no
   * tension), whatever the friction.
   *
   * Otherwise Coulomb friction is solved as a fixed point of Tresca
   * problems (friction bounds given): with the bounds
   * $b_i = \mu_i|\lambda_{n,i}|$ of the last solution (0 at open pairs),
   * PrimalActiveSetSolver::solve_tresca() minimises the convex energy with
   * the friction terms $b_i|\Delta s_i|$ (Huber terms with the penalty
   * variant) under the normal contact constraints, from the last solution
   * and its pair states; then the bounds are updated. A Tresca solution
   * whose bounds reproduce themselves ($10^{-11}$ relative) is a Coulomb
   * solution. Each Tresca problem is solved by a method that cannot cycle
   * (its energy falls at every step), so the pairs whose normal force
   * tends to zero at the ends of a contact zone, which throw the
   * semismooth Newton iteration out of their friction cones, get a bound
   * that tends to zero too and simply slip. As soon as the pair states
   * repeat and the bounds change by less than $10^{-6}$, the semismooth
   * Newton iteration is tried once from those states: with the right
   * states it solves the coupled problem in one linear solve. Result
   * counts the Tresca problems (n_fixed_point_iterations) and all solves
   * of this path (n_globalized_solves); at most 60 Tresca problems.
   *
   * If a Tresca problem has no solution, its mechanism is a rigid motion
   * allowed by the normal contacts on which the loads do more work than the
   * bounds can absorb, $f\cdot d > \sum_i b_i|C_{t,i}d|$ (failing
   * condition "friction" when pairs slide against their bound). It proves
   * that friction cannot hold the bodies with the normal forces of that
   * iterate; where statics fixes the normal forces on the sliding pairs
   * (a block on a slope, the row of blocks between jaws of
   * tests/contact/friction_limit) that is the exact friction limit, in
   * general it is not a proof for Coulomb friction (the normal forces of
   * another equilibrium may be larger). So the continuation below still
   * decides, and its refusal carries that mechanism (last_mechanism()).
   *
   * <h3>Continuation in the friction coefficient</h3>
   * Close to the friction limit the plain iteration can stop without an
   * answer either way: a cycle or the iteration limit says nothing about
   * whether an equilibrium exists, and the safeguard judges the iterates,
   * not the problem (below the limit of the row of blocks of
   * tests/contact/friction_limit the iteration cycled rather than saying
   * that there is no equilibrium). With larger friction coefficients the
   * stick zone is larger and the iteration easy, and the solution changes
   * little with a small change of the coefficients. So when the iteration
   * fails, solve() continues in a factor $f$ that multiplies every
   * friction coefficient, inside the load step:
   * 1. solve with $f = f_0$ (Continuation::first_factor, 2) from the states
   *    the step started from; if that fails too, double $f$ up to
   *    Continuation::max_doublings times; if no factor converges, the
   *    failure of the plain iteration is passed on;
   * 2. from the converged factor $f$ try $f' = \max(1, f - \delta)$,
   *    starting from the states converged at $f$ ($\delta = f - 1$
   *    first, i.e. straight to the target). If it converges, $f'$ becomes
   *    the current factor and $\delta$ is doubled; if not, $\delta$ is
   *    halved to half the distance just tried;
   * 3. stop at $f = 1$, or, when $\delta$ falls below
   *    Continuation::min_step, with "No static equilibrium": the
   *    iteration converged with every coefficient multiplied by $f$ but not
   *    from there with any factor down to 1. The message gives $f$, the
   *    last failure, and the bodies and rigid-body motions that the closed
   *    pairs hold only by friction.
   *
   * A failure a small step away from a converged neighbour is so taken as
   * the absence of an equilibrium; the limit found this way is sharp to
   * about $2\cdot 10^{-3}$ relative (the test finds it within that of the
   * limits of statics, a friction limit and a friction-and-rocking one).
   *
   * Every attempt solves the same load step: the same load, the reference
   * slips $r_i$ of the start of the step, and only the pair states carried
   * from one factor to the next. The converged answer at $f = 1$ is
   * therefore a solution of the original step, and the slip increments and
   * the dissipated energy are those of the start-of-step reference (no
   * energy of the intermediate factors is counted). A step that the plain
   * iteration solves never enters the continuation, so its answer is
   * unchanged.
   *
   * <h3>Driver and rule</h3>
   * solve() only owns the loop (assemble_friction() for the current
   * states, the linear solve); every rule above lives in
   * FrictionStateUpdate, which a program or a Newton method for finite
   * strain can call from its own loop.
   */
  template <int dim>
  class FrictionSolver : public ContactSolver<dim>
  {
  public:
    /// What solve() returns for one load step besides the solution (the
    /// fields of ContactSolveResult's first and last groups).
    using Result = ContactSolveResult;

    /// The parameters of the continuation in the friction coefficient (see
    /// the class documentation).
    struct Continuation
    {
      /// Whether solve() continues in the friction coefficient when the
      /// plain iteration fails; false passes its failure on.
      bool enabled = true;
      /// The first factor of the friction coefficients tried.
      double first_factor = 2.;
      /// How often that factor is doubled when it does not converge either.
      unsigned int max_doublings = 4;
      /// The smallest decrement of the factor; the step has no static
      /// equilibrium when the factor cannot be lowered by this much.
      double min_step = 1e-3;
      /// At most this many Newton iterations (attempts) in one continuation.
      unsigned int max_attempts = 200;
    };

    /// @p c is the constant of the complementarity functions (units E/h).
    FrictionSolver(const ContactAssembler<dim>             &contact,
                   const dealii::AffineConstraints<double> &constraints,
                   SaddlePointSolver                       &solver,
                   const ContactSettings                   &settings,
                   const double                             c);

    /**
     * The states of a first load step: pairs whose initial gap is closed
     * stick, the others are open; with a support, further pairs of smallest
     * gap are closed until every body is held.
     */
    std::vector<PairState>
    initial_state() const;

    /// Set the parameters of the continuation in the friction coefficient.
    void
    set_continuation(const Continuation &continuation);

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

    /**
     * Set the states and reference slips the next solve_step() starts
     * from (by default the first starts from initial_state() and zero
     * references, and each later one from where the last ended).
     */
    void
    set_start(const std::vector<PairState> &state, const std::vector<double> &reference);

    /// Solve one load step from the carried states and references
    /// (set_start()), then carry the converged ones to the next step. The
    /// collapse mechanism of a step that found no equilibrium, even with
    /// sticking joints, or (failing condition "friction") with the friction
    /// bounds of the Tresca fixed point (see the class documentation), is
    /// last_mechanism().
    const Result &
    solve_step(const dealii::SparseMatrix<double> &system_matrix,
               const dealii::Vector<double>       &system_rhs,
               dealii::SparseMatrix<double>       &matrix,
               dealii::Vector<double>             &x) override;

    /// "Coulomb friction".
    std::string
    name() const override;

  private:
    /**
     * One semismooth Newton iteration from @p start with the friction
     * coefficients multiplied by the factor set in @p update; adds its
     * saddle-point solves to @p result (n_iterations, linear_iterations,
     * history) also when it throws. Returns the converged state.
     */
    typename FrictionStateUpdate<dim>::State
    iterate(FrictionStateUpdate<dim>           &update,
            const dealii::SparseMatrix<double> &system_matrix,
            const dealii::Vector<double>       &system_rhs,
            dealii::SparseMatrix<double>       &matrix,
            dealii::Vector<double>             &x,
            const std::vector<PairState>       &start,
            const std::vector<double>          &reference,
            Result                             &result) const;

    using ContactSolver<dim>::contact;
    using ContactSolver<dim>::constraints;
    using ContactSolver<dim>::solver;
    using ContactSolver<dim>::settings;
    using ContactSolver<dim>::c;
    using ContactSolver<dim>::support;
    using ContactSolver<dim>::mechanism;
    /// The states and references the next solve_step() starts from
    /// (empty: initial_state() and zeros).
    std::vector<PairState> start_state;
    /// See start_state.
    std::vector<double>    start_reference;
    /// At most this many Tresca problems in the fixed point of solve().
    static constexpr unsigned int            max_fixed_point_iterations = 60;
    Continuation                             continuation;
  };
} // namespace dealvem

#endif
