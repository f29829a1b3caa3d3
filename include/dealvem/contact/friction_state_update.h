// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_friction_state_update_h
#define dealvem_contact_friction_state_update_h

#include <deal.II/lac/vector.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/node_insertion.h>

#include <array>
#include <set>
#include <vector>

namespace dealvem
{
  class RigidBodySupport;

  /**
   * The rule of the semismooth Newton (primal-dual active set) method of
   * Coulomb friction, with no loop and no linear solve: given the solution
   * of the system assembled for the current pair states (open / stick /
   * slip, ContactAssembler::assemble_friction()), update() proposes the
   * next states, says whether the iteration has converged and stops with a
   * message when it cycles, runs out of iterations or finds no static
   * equilibrium. FrictionSolver::solve() is the driver that owns the loop;
   * a Newton method for finite strain can own it instead.
   *
   * <h3>The rule</h3>
   * With the pressure $p_i = -\lambda_{n,i}/w_i$, the friction traction
   * $\tau_i = \lambda_{t,i}/w_i$, the gap $g_i$ and the slip increment
   * $\Delta s_i = s_i - r_i$ against the reference $r_i$ of the last
   * converged load step, the trial values are $\hat p_i = p_i - c\,g_i$ and
   * $\hat\tau_i = \tau_i + c\,\Delta s_i$ (with the penalty variant
   * ContactSettings::coulomb_penalty, $\hat\tau_i = \varepsilon_t\Delta s_i$).
   * The next state of pair $i$ is
   * - open where $\hat p_i \le 0$;
   * - stick where $|\hat\tau_i| \le \mu\hat p_i$ (Coulomb's cone);
   * - slip in the direction $\mathrm{sign}\,\hat\tau_i$ elsewhere, except
   *   that a pair slipping one way whose trial traction turned round
   *   sticks first (no ping-pong between the two slip directions);
   * values below $10^{-10}$ of the largest $|p_i|$, $c|g_i|$, $|\hat\tau_i|$
   * count as zero. See FrictionSolver for the complementarity functions
   * this is the semismooth Newton step of. The iteration has converged when
   * the states repeat.
   *
   * With a RigidBodySupport, states that would leave a body free (every
   * pair that holds it tangentially slipping) get the would-be slipping
   * pairs closest to the cone (smallest $|\hat\tau_i|/(\mu\hat p_i)$)
   * sticking until every body is held; if that safeguard is needed at the
   * converged states, at states visited before or three times in a row, or
   * a body is free even so, update() throws "No static equilibrium".
   */
  template <int dim>
  class FrictionStateUpdate
  {
  public:
    /**
     * What the iteration carries from one step to the next; the driver
     * owns it.
     */
    struct State
    {
      /// The states to solve with next.
      std::vector<PairState> state;
      /// Updates taken so far (= linear solves of the driver).
      unsigned int n_iterations = 0;
      /// Per update, the numbers of open, sticking and slipping pairs of
      /// the states solved with.
      std::vector<std::array<unsigned int, 3>> history;
      /// True once the states repeat.
      bool converged = false;
      /// Pairs whose state the last update changed.
      unsigned int n_changed = 0;
      /// @var std::vector<double> slip
      /// Of the last solution, per pair: the slip
      /// $s_i = (u_B-u_A)\cdot t_i$.
      /// @var std::vector<double> tangential_multiplier
      /// Of the last solution, per pair: the friction nodal force
      /// $\lambda_{t,i}$ (of the states solved with).
      std::vector<double> slip, tangential_multiplier;

      /// States from which a step was taken (cycle detection).
      std::set<std::vector<PairState>> visited;
      /// Consecutive updates that needed the support safeguard.
      unsigned int n_safeguarded = 0;
    };

    /**
     * What a converged load step passes on (see converged_step()).
     */
    struct StepResult
    {
      /// @var std::vector<double> slip
      /// Per pair, the slip $s_i = (u_B-u_A)\cdot t_i$ of the converged
      /// solution.
      /// @var std::vector<double> slip_increment
      /// Per pair, the increment of the slip over the step: $s_i$ minus the
      /// reference with multipliers, the increment of the plastic slip with
      /// the penalty; zero for open pairs.
      /// @var std::vector<double> tangential_multiplier
      /// Per pair, the friction nodal force $\lambda_{t,i}$.
      /// @var std::vector<double> reference
      /// Per pair, the reference for the next step: the relative tangential
      /// displacement, or the plastic slip with the penalty.
      std::vector<double> slip, slip_increment, tangential_multiplier, reference;
      /// $\sum_{\text{slip}} \lambda_{t,i}\,\Delta s_i$.
      double dissipated_energy = 0;
    };

    /**
     * @p pairs (copied), @p settings (Coulomb model, friction coefficients, iteration limit),
     * the constant @p c of the complementarity functions (units $E/h$) and
     * the tangential penalty $\varepsilon_t$ (used by the penalty variant;
     * ContactAssembler::get_penalty()).
     */
    FrictionStateUpdate(const std::vector<ContactNodePair> &pairs,
                        const ContactSettings              &settings,
                        const double                        c,
                        const double                        penalty);

    /// Check every set of states against the rigid-body motions; @p support
    /// may be nullptr.
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

    /// A state to start a load step from @p states (those of the last
    /// converged step, or initial_state()).
    State
    start(const std::vector<PairState> &states) const;

    /**
     * One step of the rule from the solution computed with @p state.state:
     * gaps $g_i$, slips $s_i$, normal multipliers $\lambda_{n,i}$,
     * tangential multipliers $\lambda_{t,i}$ (only read with
     * ContactSettings::coulomb; may be empty with coulomb_penalty, where the
     * friction force follows from the state) and the references $r_i$.
     * Records the step, replaces State::state by the next states unless the
     * iteration has converged, and returns State::converged.
     */
    bool
    update(State                     &state,
           const std::vector<double> &gaps,
           const std::vector<double> &slips,
           const std::vector<double> &normal_multipliers,
           const std::vector<double> &tangential_multipliers,
           const std::vector<double> &reference) const;

    /// The same from the solution vector @p x of the saddle-point system of
    /// @p contact (displacements, normal and tangential multipliers).
    bool
    update(State                        &state,
           const ContactAssembler<dim>  &contact,
           const dealii::Vector<double> &x,
           const std::vector<double>    &reference) const;

    /**
     * The quantities of the converged @p state for the next load step:
     * slips and friction forces of the last solution, and the new
     * references (an open pair starts from where it is; with the penalty
     * the plastic slip is kept while sticking and becomes
     * $s_i - \lambda_{t,i}/(\varepsilon_t w_i)$ while slipping).
     */
    StepResult
    converged_step(const State &state, const std::vector<double> &reference) const;

    /**
     * Multiply every friction coefficient by @p factor (positive, finite;
     * 1, the default, is the model as set) in the rule. The continuation of
     * FrictionSolver::solve() uses it together with the same factor in
     * ContactAssembler::assemble_friction().
     */
    void
    set_friction_factor(const double factor);

    /// The factor of set_friction_factor().
    double
    get_friction_factor() const
    {
      return friction_factor;
    }

    /// The friction coefficient of pair @p i the rule uses: the one of its
    /// interface times the factor of set_friction_factor().
    double
    friction_coefficient(const unsigned int i) const
    {
      return friction_factor * settings.friction_coefficient_of(pairs[i].interface);
    }

  private:
    std::vector<ContactNodePair>        pairs;
    ContactSettings                     settings;
    double                              c;
    double                              penalty;
    const RigidBodySupport             *support = nullptr;
    double                              friction_factor = 1.;
  };
} // namespace dealvem

#endif
