// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/friction_state_update.h>
#include <dealvem/contact/rigid_body_support.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace dealvem
{
  template <int dim>
  FrictionStateUpdate<dim>::FrictionStateUpdate(const std::vector<ContactNodePair> &pairs,
                                                const ContactSettings              &settings,
                                                const double                        c,
                                                const double                        penalty)
    : pairs(pairs)
    , settings(settings)
    , c(c)
    , penalty(penalty)
  {
    AssertThrow(c > 0 && std::isfinite(c),
                dealii::ExcMessage("The constant of the friction complementarity functions must be positive."));
    AssertThrow(settings.is_coulomb(),
                dealii::ExcMessage("FrictionSolver needs 'Tangential = coulomb' or 'coulomb penalty'."));
    AssertThrow(settings.normal == ContactSettings::Normal::unilateral,
                dealii::ExcMessage("Coulomb friction needs unilateral normal contact ('Normal = unilateral')."));
    AssertThrow(settings.tangential != ContactSettings::Tangential::coulomb_penalty || penalty > 0,
                dealii::ExcMessage("Coulomb friction by a penalty ('coulomb penalty') needs a positive "
                                   "tangential penalty, not " + std::to_string(penalty) + "."));
  }



  template <int dim>
  void
  FrictionStateUpdate<dim>::set_friction_factor(const double factor)
  {
    AssertThrow(std::isfinite(factor) && factor > 0,
                dealii::ExcMessage("FrictionStateUpdate: the factor of the friction coefficients must be positive "
                                   "and finite, not " + std::to_string(factor) + "."));
    friction_factor = factor;
  }



  template <int dim>
  std::vector<PairState>
  FrictionStateUpdate<dim>::initial_state() const
  {
    double length = 0;
    for (const auto &p : pairs)
      length = std::max(length, p.weight);
    std::vector<bool> closed(pairs.size());
    for (unsigned int i = 0; i < pairs.size(); ++i)
      closed[i] = pairs[i].initial_gap <= 1e-12 * length && !pairs[i].junction;
    if (support != nullptr && !support->holds(closed))
      {
        support->close_smallest_gaps(closed);
        for (unsigned int i = 0; i < pairs.size(); ++i)
          closed[i] = closed[i] && !pairs[i].junction;
      }
    std::vector<PairState> state(pairs.size());
    for (unsigned int i = 0; i < pairs.size(); ++i)
      state[i] = closed[i] ? PairState::stick : PairState::open;
    return state;
  }



  template <int dim>
  typename FrictionStateUpdate<dim>::State
  FrictionStateUpdate<dim>::start(const std::vector<PairState> &states) const
  {
    AssertThrow(states.size() == pairs.size(),
                dealii::ExcMessage("FrictionStateUpdate: " + std::to_string(states.size()) +
                                   " pair states given for " + std::to_string(pairs.size()) + " contact pairs."));
    State state;
    state.state = states;
    return state;
  }



  namespace
  {
    std::array<unsigned int, 3>
    count_states(const std::vector<PairState> &state)
    {
      std::array<unsigned int, 3> n{{0, 0, 0}};
      for (const auto s : state)
        ++n[s == PairState::open ? 0 : (s == PairState::stick ? 1 : 2)];
      return n;
    }

    std::string
    history_string(const std::vector<std::array<unsigned int, 3>> &history)
    {
      std::ostringstream log;
      for (const auto &h : history)
        log << " " << h[0] << "/" << h[1] << "/" << h[2];
      return log.str();
    }

    const char *
    state_name(const PairState s)
    {
      return s == PairState::open ? "open" :
             s == PairState::stick ? "stick" :
             s == PairState::slip_positive ? "slip +t" :
                                             "slip -t";
    }


    // The Coulomb test of the semismooth Newton update: per pair open,
    // stick or slip from the trial pressure p - c g and the trial traction
    // tau_hat (a slip that turns round sticks first).
    template <int dim>
    std::vector<PairState>
    coulomb_test(const FrictionStateUpdate<dim>     &update,
                 const std::vector<ContactNodePair> &pairs,
                 const double                        c,
                 const std::vector<double>          &gaps,
                 const std::vector<double>          &p,
                 const std::vector<double>          &tau_hat,
                 const double                        scale,
                 const std::vector<PairState>       &current)
    {
      const unsigned int     n_pairs = pairs.size();
      std::vector<PairState> next(n_pairs);
      for (unsigned int i = 0; i < n_pairs; ++i)
        {
          const double p_hat = p[i] - c * gaps[i];
          if (!(p_hat > 1e-10 * scale) || pairs[i].junction)
            next[i] = PairState::open;
          else if (std::abs(tau_hat[i]) <= update.friction_coefficient(i) * p_hat + 1e-10 * scale)
            next[i] = PairState::stick;
          else
            {
              next[i] = (tau_hat[i] > 0 ? PairState::slip_positive : PairState::slip_negative);
              // a slipping pair whose trial traction turned round sticks
              // first: slip reversal goes through stick (no ping-pong
              // between the two slip directions)
              if ((current[i] == PairState::slip_positive && next[i] == PairState::slip_negative) ||
                  (current[i] == PairState::slip_negative && next[i] == PairState::slip_positive))
                next[i] = PairState::stick;
            }
        }
      return next;
    }



    // The equilibrium safeguard. A body that the next states would leave
    // free: either there is no static equilibrium (the load exceeds what
    // friction can carry), or the iterate passes through an all-slip set on
    // its way to one. Keep the would-be slipping pairs closest to the
    // friction cone (smallest |tau_hat| / (mu p_hat)) sticking until every
    // body is held. If that safeguard is needed at the converged set, at a
    // set visited before, or in three iterations in a row, there is no
    // equilibrium.
    template <int dim>
    void
    hold_every_body(const FrictionStateUpdate<dim>                   &update,
                    const RigidBodySupport                           &support,
                    const std::vector<ContactNodePair>               &pairs,
                    const double                                      c,
                    const std::vector<double>                        &gaps,
                    const std::vector<double>                        &p,
                    const std::vector<double>                        &tau_hat,
                    const unsigned int                                it,
                    typename FrictionStateUpdate<dim>::State         &state,
                    std::vector<PairState>                           &next)
    {
      const unsigned int n_pairs     = pairs.size();
      bool               safeguarded = false;
      std::vector<bool>  closed(n_pairs), held(n_pairs);
      for (unsigned int i = 0; i < n_pairs; ++i)
        {
          closed[i] = (next[i] != PairState::open);
          held[i]   = (next[i] == PairState::stick);
        }
      const std::string free = support.free_motions(closed, held);
      if (!free.empty())
        {
          std::vector<std::pair<double, unsigned int>> candidates;
          for (unsigned int i = 0; i < n_pairs; ++i)
            if (closed[i] && !held[i])
              {
                const double bound = update.friction_coefficient(i) * (p[i] - c * gaps[i]);
                candidates.emplace_back(bound > 0 ? std::abs(tau_hat[i]) / bound : 1e300, i);
              }
          std::sort(candidates.begin(), candidates.end());
          for (const auto &cand : candidates)
            {
              next[cand.second] = PairState::stick;
              held[cand.second] = true;
              if (support.free_motions(closed, held).empty())
                break;
            }
          safeguarded = true;
          ++state.n_safeguarded;
        }
      else
        state.n_safeguarded = 0;
      const std::string still_free = support.free_motions(closed, held);
      AssertThrow(still_free.empty() && !(safeguarded && (next == state.state || state.visited.count(next) > 0 ||
                                                          state.n_safeguarded >= 3)),
                  dealii::ExcMessage(
                    "No static equilibrium: in friction iteration " + std::to_string(it) +
                    " every contact pair that held these rigid-body motions came out slipping or open: " +
                    (still_free.empty() ? free : still_free) + " (open/stick/slip pairs per iteration:" +
                    history_string(state.history) +
                    "). The tangential load exceeds the friction coefficient times the normal load "
                    "on a body held only by friction, or the loads pull the body off its partner; "
                    "hold the body by Dirichlet, roller or point constraints, or reduce the load."));
    }



    // The refusal when the next states were visited before: a cycle, with
    // the pairs whose state switches back.
    void
    throw_cycle(const std::vector<ContactNodePair>           &pairs,
                const std::vector<PairState>                 &current,
                const std::vector<PairState>                 &next,
                const std::vector<std::array<unsigned int, 3>> &history,
                const unsigned int                            it)
    {
      std::ostringstream switching;
      unsigned int       n_switching = 0;
      for (unsigned int i = 0; i < pairs.size(); ++i)
        if (next[i] != current[i])
          {
            if (n_switching < 10)
              switching << (n_switching > 0 ? ", " : "") << "pair " << i << " at (" << pairs[i].slave_location
                        << ") " << state_name(current[i]) << " -> " << state_name(next[i]);
            ++n_switching;
          }
      if (n_switching > 10)
        switching << " and " << n_switching - 10 << " more";
      AssertThrow(false,
                  dealii::ExcMessage("The friction active set cycles: the states of iteration " +
                                     std::to_string(it + 1) +
                                     " were already visited (open/stick/slip pairs per iteration:" +
                                     history_string(history) + "; switching back: " + switching.str() +
                                     "). Use more load steps or another mesh."));
    }
  } // namespace



  template <int dim>
  bool
  FrictionStateUpdate<dim>::update(State                     &state,
                                   const std::vector<double> &gaps,
                                   const std::vector<double> &s,
                                   const std::vector<double> &normal_multipliers,
                                   const std::vector<double> &tangential_multipliers,
                                   const std::vector<double> &reference) const
  {
    const unsigned int n_pairs     = pairs.size();
    const bool         multipliers = (settings.tangential == ContactSettings::Tangential::coulomb);
    const double       eps         = penalty;
    AssertThrow(state.state.size() == n_pairs && gaps.size() == n_pairs && s.size() == n_pairs &&
                  normal_multipliers.size() == n_pairs && reference.size() == n_pairs &&
                  (!multipliers || tangential_multipliers.size() == n_pairs),
                dealii::ExcMessage("FrictionStateUpdate: for " + std::to_string(n_pairs) + " contact pairs, " +
                                   std::to_string(state.state.size()) + " states, " +
                                   std::to_string(gaps.size()) + " gaps, " + std::to_string(s.size()) +
                                   " slips, " + std::to_string(normal_multipliers.size()) +
                                   " normal and " + std::to_string(tangential_multipliers.size()) +
                                   " tangential multipliers and " + std::to_string(reference.size()) +
                                   " references given."));
    AssertThrow(!state.converged,
                dealii::ExcMessage("FrictionStateUpdate: update() called on a converged state."));
    ++state.n_iterations;
    const unsigned int it = state.n_iterations;
    state.history.push_back(count_states(state.state));
    state.n_changed = 0;

    // the quantities of the complementarity functions
    auto &lambda_t = state.tangential_multiplier;
    lambda_t.resize(n_pairs);
    state.slip = s;
    std::vector<double> p(n_pairs), tau(n_pairs), tau_hat(n_pairs);
    double              scale = 0;
    for (unsigned int i = 0; i < n_pairs; ++i)
      {
        const double w     = pairs[i].weight;
        const double ln    = normal_multipliers[i];
        const double mu    = friction_coefficient(i);
        const auto   st    = state.state[i];
        const double sigma = (st == PairState::slip_positive ? 1. : -1.);
        if (multipliers)
          lambda_t[i] = tangential_multipliers[i];
        else if (st == PairState::stick)
          lambda_t[i] = eps * w * (s[i] - reference[i]);
        else if (st == PairState::open)
          lambda_t[i] = 0;
        else
          lambda_t[i] = -mu * sigma * ln;
        p[i]       = -ln / w;
        tau[i]     = lambda_t[i] / w;
        tau_hat[i] = multipliers ? tau[i] + c * (s[i] - reference[i]) : eps * (s[i] - reference[i]);
        scale      = std::max({scale, std::abs(p[i]), c * std::abs(gaps[i]), std::abs(tau_hat[i])});
      }
    // the Coulomb test, and the equilibrium safeguard
    std::vector<PairState> next = coulomb_test(*this, pairs, c, gaps, p, tau_hat, scale, state.state);
    if (support != nullptr)
      hold_every_body(*this, *support, pairs, c, gaps, p, tau_hat, it, state, next);
    if (next == state.state)
      {
        state.converged = true;
        return true;
      }
    if (state.visited.count(next) > 0)
      throw_cycle(pairs, state.state, next, state.history, it);
    state.visited.insert(state.state);
    for (unsigned int i = 0; i < n_pairs; ++i)
      state.n_changed += (next[i] != state.state[i]);
    state.state = next;
    AssertThrow(it < settings.max_active_set_iterations,
                dealii::ExcMessage("The friction active set (semismooth Newton) did not settle within " +
                                   std::to_string(settings.max_active_set_iterations) +
                                   " iterations (open/stick/slip pairs per iteration:" +
                                   history_string(state.history) +
                                   "). Increase 'Maximum active set iterations', use more load steps, "
                                   "or check the loads and supports."));
    return false;
  }



  template <int dim>
  bool
  FrictionStateUpdate<dim>::update(State                        &state,
                                   const ContactAssembler<dim>  &contact,
                                   const dealii::Vector<double> &x,
                                   const std::vector<double>    &reference) const
  {
    const unsigned int n_pairs = pairs.size();
    const ContactRows  rows    = contact.rows();
    AssertThrow(rows.n_pairs() == n_pairs && x.size() == rows.n_unknowns(),
                dealii::ExcMessage("FrictionStateUpdate: the contact assembler has " +
                                   std::to_string(contact.n_pairs()) + " pairs, this update " +
                                   std::to_string(n_pairs) + ", and the solution " + std::to_string(x.size()) +
                                   " entries."));
    const bool          multipliers = (settings.tangential == ContactSettings::Tangential::coulomb);
    std::vector<double> ln(n_pairs), lt(multipliers ? n_pairs : 0);
    for (unsigned int i = 0; i < n_pairs; ++i)
      {
        ln[i] = rows.normal_multiplier(x, i);
        if (multipliers)
          lt[i] = rows.tangential_multiplier(x, i);
      }
    return update(state, contact.gaps(x), contact.slips(x), ln, lt, reference);
  }



  template <int dim>
  typename FrictionStateUpdate<dim>::StepResult
  FrictionStateUpdate<dim>::converged_step(const State &state, const std::vector<double> &reference) const
  {
    const unsigned int n_pairs     = pairs.size();
    const bool         multipliers = (settings.tangential == ContactSettings::Tangential::coulomb);
    const double       eps         = penalty;
    AssertThrow(state.converged && state.slip.size() == n_pairs && reference.size() == n_pairs,
                dealii::ExcMessage("FrictionStateUpdate::converged_step() needs a converged state and " +
                                   std::to_string(n_pairs) + " references."));
    StepResult result;
    result.slip                  = state.slip;
    result.tangential_multiplier = state.tangential_multiplier;
    result.slip_increment.assign(n_pairs, 0.);
    result.reference.assign(n_pairs, 0.);
    const auto &s        = state.slip;
    const auto &lambda_t = state.tangential_multiplier;
    for (unsigned int i = 0; i < n_pairs; ++i)
      {
        const auto st = state.state[i];
        if (multipliers)
          {
            // an open pair does not slip; it starts from where it is
            result.reference[i]      = s[i];
            result.slip_increment[i] = (st == PairState::open ? 0. : s[i] - reference[i]);
          }
        else
          {
            // plastic slip: unchanged while sticking, s - tau/eps while
            // slipping, reset to s when open
            const double w      = pairs[i].weight;
            result.reference[i] = (st == PairState::stick ? reference[i] :
                                   st == PairState::open  ? s[i] :
                                                            s[i] - lambda_t[i] / (eps * w));
            result.slip_increment[i] = (st == PairState::open ? 0. : result.reference[i] - reference[i]);
          }
        if (st == PairState::slip_positive || st == PairState::slip_negative)
          result.dissipated_energy += lambda_t[i] * result.slip_increment[i];
      }
    return result;
  }

  template class FrictionStateUpdate<2>;
} // namespace dealvem
