// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_active_set_update_h
#define dealvem_contact_active_set_update_h

#include <deal.II/lac/vector.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/node_insertion.h>

#include <set>
#include <string>
#include <vector>

namespace dealvem
{
  class RigidBodySupport;

  /**
   * The rule of the primal-dual active set method for normal contact (tied
   * or unilateral, frictionless or with a stick penalty), with no loop and
   * no linear solve: given the solution of the system assembled for the
   * current active set, update() proposes the next set, says whether the
   * iteration has converged and stops with a message when it cycles or
   * runs out of iterations. The loop around it (assemble the contact blocks
   * for State::active, solve, call update()) belongs to the caller:
   * ActiveSetSolver::solve() is one such driver, the tutorial step-6 writes
   * the loop out, and a Newton method for finite strain can own the loop
   * and call update() once per Newton step.
   *
   * <h3>The rule</h3>
   * With the compressive pressure $p_i = -\lambda_i/w_i$ of pair $i$
   * (multiplier $\lambda_i$, tributary weight $w_i$) and its gap $g_i$,
   * the conditions $g_i\ge 0$, $p_i\ge 0$, $g_ip_i = 0$ are equivalent to
   * $C_i = p_i - \max(0,\ p_i - c\,g_i) = 0$ for any $c > 0$. A semismooth
   * Newton step on $C$ is the active-set step: solve with $g_i = 0$ on
   * $\mathcal A = \{i : p_i - c\,g_i > 0\}$ (evaluated at the last iterate)
   * and $\lambda_i = 0$ elsewhere (Hintermüller, Ito and Kunisch, SIAM J.
   * Optim. 13, 2002; Hüeber and Wohlmuth, 2005). Values below $10^{-10}$
   * of the largest $|p_i|$, $c|g_i|$, and below $10^{-12}\,c\,w_{max}$
   * (the pressure of a gap of $10^{-12}$ of the longest tributary length,
   * the gap initial_state() counts as closed), count as zero: where every
   * force and gap is round-off (a body moved rigidly onto its partner by
   * its constraints, touching without force) the set no longer follows
   * the noise from iteration to iteration until it cycles; the pairs open
   * and stay open. The iteration has
   * converged when the proposed set equals the set just solved with; the
   * solution then satisfies $C = 0$ (residual()).
   *
   * The first set (initial_state()) holds the pairs whose initial gap is
   * closed; with a RigidBodySupport, further pairs of smallest gap are
   * closed until every body is held. The acceleration of ActiveSetSolver
   * (see there) is applied to the proposed set when
   * ContactSettings::accelerate_active_set is set and the pairs'
   * neighbours are known (set_pair_neighbours()); convergence is always
   * judged on the plain proposal.
   *
   * <h3>Failures</h3>
   * A plain step back to a set from which a plain step was taken before
   * means the iteration cycles: update() throws, naming the iteration, the
   * history of set sizes and the pairs (index and slave location) that
   * switch between the two sets. It also throws when the iteration limit
   * ContactSettings::max_active_set_iterations is reached, and, with a
   * RigidBodySupport, when the proposed set leaves a body free (no static
   * equilibrium).
   */
  template <int dim>
  class ActiveSetUpdate
  {
  public:
    /**
     * What the iteration carries from one step to the next. The driver
     * owns it: initial_state() makes it, update() advances it.
     */
    struct State
    {
      /// The set to solve with next (per pair: normal constraint enforced).
      std::vector<bool> active;
      /// Updates taken so far (= linear solves of the driver).
      unsigned int n_iterations = 0;
      /// Per update, the number of active pairs of the set solved with.
      std::vector<unsigned int> n_active_history;
      /// True once the set repeats (or at once for tied contact).
      bool converged = false;
      /// @var unsigned int n_closed
      /// Pairs the last update closed (inactive to active).
      /// @var unsigned int n_opened
      /// Pairs the last update opened (active to inactive).
      unsigned int n_closed = 0, n_opened = 0;
      /// The complementarity residual residual() of the last solution.
      double residual = 0;
      /// Pairs with an open initial gap closed by initial_state() so that
      /// every body is held.
      unsigned int n_closed_for_support = 0;
      /// Steps whose proposed set the acceleration corrected.
      unsigned int n_accelerated = 0;

      /// Sets from which a plain step was taken (cycle detection).
      std::set<std::vector<bool>> visited;
      /// Per pair, whether the release extrapolation released it.
      std::vector<bool> extrapolated;
      /// With set_report_failures(): why the iteration gave up (a cycle,
      /// the iteration limit, a set that holds no equilibrium); empty while
      /// it goes on or once it has converged.
      std::string failure;
      /// Whether the release extrapolation is still switched on: starts as
      /// ContactSettings::accelerate_active_set, and is off for the rest of
      /// the solve once a pair it released penetrates again.
      bool              extrapolate = false;
      /// Per pair (empty: none), whether it is held tangentially although
      /// open. With stick (Tangential penalty or multipliers, not Coulomb)
      /// the model of the fast path, stick at closed pairs only, is not
      /// convex, and its plain update can cycle: a pair that closes is held,
      /// comes out in tension, opens, is free and penetrates again. When a
      /// plain step would return to a visited set, the pairs that step
      /// switches are tied tangentially from then on, open or closed (the
      /// convex model on those pairs only; a pair tied once stays tied),
      /// the visited sets are forgotten (the model has changed) and the
      /// iteration goes on, at most max_tie_rounds times; the next cycle
      /// is a failure as before. The driver must enforce the tangential
      /// constraint where active or tied_open holds.
      std::vector<bool> tied_open;
      /// How many times pairs were tied after a cycle.
      unsigned int n_tie_rounds = 0;
      /// Per pair (empty until the first update with stick), how many
      /// plain updates in a row switched it (closed, opened, closed, ...),
      /// counting switches at most switch_window updates apart; a switch
      /// made by the acceleration alone does not count. With stick, a pair
      /// that would switch for the max_alternations-th time in a row is
      /// tied like the pairs of a cycle (State::tied_open), on its own,
      /// and keeps its state for one solve: on a large wall the pairs near
      /// the open ends of many joints flip with the same period but in
      /// different phases, so that the whole set does not repeat for tens
      /// of iterations (measured on the 201-body wall of
      /// benchmark_assembly 200 5: 33 iterations before, 13 after).
      std::vector<unsigned char> alternations;
      /// Per pair, the update that last switched it (0: none yet).
      std::vector<unsigned int> last_switch;
      /// Pairs tied by the alternation rule (see alternations).
      unsigned int n_tied_alternating = 0;
    };

    /// With stick: the switch of a pair, in a row of switches, that ties
    /// it instead (see State::alternations): the fourth (closed, open,
    /// closed, open, and about to close again). On the walls of
    /// benchmark_assembly, tying at the third switch tied pairs that a
    /// converging iteration switches three times (100 blocks: 5
    /// iterations and 3 pairs tied, against 4 and none).
    static constexpr unsigned int max_alternations = 4;
    /// Switches at most this many updates apart count as in a row.
    static constexpr unsigned int switch_window = 2;

    /// The cycles of the plain update that tie pairs (State::tied_open)
    /// before a cycle is a failure.
    static constexpr unsigned int max_tie_rounds = 3;

    /// The pairs held tangentially in @p state: active or tied_open.
    static std::vector<bool>
    tangential_set(const State &state);

    /**
     * @p pairs (copied; e.g. ContactAssembler::get_pairs()), @p settings
     * (normal model, iteration limit, acceleration) and the constant @p c
     * of the complementarity function (units $E/h$,
     * ContactScales::complementarity_constant()).
     */
    ActiveSetUpdate(const std::vector<ContactNodePair> &pairs,
                    const ContactSettings              &settings,
                    const double                        c);

    /// Check the first set and every proposed set against the rigid-body
    /// motions (see the class documentation); @p support may be nullptr.
    void
    set_support(const RigidBodySupport *support)
    {
      this->support = support;
    }

    /**
     * Record a failure (cycle, iteration limit, a set that holds no
     * equilibrium) in State::failure and end the iteration (update()
     * returns true with State::converged false) instead of throwing, so
     * that a driver can go on with another method (ActiveSetSolver's
     * globalized solve).
     */
    void
    set_report_failures(const bool report)
    {
      report_failures = report;
    }

    /**
     * The neighbours of each pair along its interface, for the
     * acceleration (ActiveSetSolver::pair_neighbours() builds them). Without
     * them only the first correction (a step that would more than double
     * the set) is applied.
     */
    void
    set_pair_neighbours(const std::vector<std::vector<unsigned int>> &neighbours)
    {
      this->neighbours = neighbours;
    }

    /**
     * The state to start from: every pair active for tied contact;
     * otherwise the pairs with initial gap $\le 10^{-12}$ times the largest
     * weight, and with a support those of smallest gap until every body is
     * held (throws if not even all pairs hold them).
     */
    State
    initial_state() const;

    /**
     * One step of the rule: @p gaps and @p multipliers are $g_i$ and the
     * normal multipliers $\lambda_i$ (nodal forces, negative in
     * compression) of the solution computed with @p state.active. Records
     * the step in @p state, replaces State::active by the next set unless
     * the iteration has converged, and returns State::converged. Throws on
     * a cycle, at the iteration limit, and (with a support) when the next
     * set holds no equilibrium (with set_report_failures(): records it in
     * State::failure and returns true).
     */
    bool
    update(State &state, const std::vector<double> &gaps, const std::vector<double> &multipliers) const;

    /**
     * The same from the solution vector @p x of the saddle-point system
     * (displacements followed by the multipliers of @p contact, whose pairs
     * must be those of this object).
     */
    bool
    update(State &state, const ContactAssembler<dim> &contact, const dealii::Vector<double> &x) const;

    /**
     * The complementarity residual $\max_i |p_i - \max(0, p_i - c\,g_i)|$
     * (units of pressure) of the gaps and normal multipliers: zero exactly
     * at a solution of the contact conditions.
     */
    double
    residual(const std::vector<double> &gaps, const std::vector<double> &multipliers) const;

    /// The constant $c$.
    double
    get_constant() const
    {
      return c;
    }

  private:
    /// Apply the two corrections of the acceleration to the plain proposal
    /// @p next from the active set @p active; returns whether a release
    /// extrapolation was applied, and marks its pairs in @p extrapolated.
    bool
    accelerate(const std::vector<bool>   &active,
               const std::vector<double> &gaps,
               const std::vector<double> &values,
               std::vector<bool>         &next,
               std::vector<bool>         &extrapolated) const;

    /// " 12 14 13": the set sizes solved with so far, for messages.
    static std::string
    history_string(const State &state);

    std::vector<ContactNodePair>           pairs;
    ContactSettings                        settings;
    double                                 c;
    bool                                   report_failures = false;
    const RigidBodySupport                *support = nullptr;
    std::vector<std::vector<unsigned int>> neighbours;
  };
} // namespace dealvem

#endif
