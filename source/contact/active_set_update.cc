// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/active_set_update.h>
#include <dealvem/contact/rigid_body_support.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace dealvem
{
  template <int dim>
  ActiveSetUpdate<dim>::ActiveSetUpdate(const std::vector<ContactNodePair> &pairs,
                                        const ContactSettings              &settings,
                                        const double                        c)
    : pairs(pairs)
    , settings(settings)
    , c(c)
  {
    AssertThrow(c > 0 && std::isfinite(c),
                dealii::ExcMessage("The active-set constant must be positive (and finite), not " +
                                   std::to_string(c) + "."));
  }



  template <int dim>
  typename ActiveSetUpdate<dim>::State
  ActiveSetUpdate<dim>::initial_state() const
  {
    State      state;
    const bool tied = (settings.normal == ContactSettings::Normal::tied);
    state.active.resize(pairs.size());
    // tolerance for "closed" gaps, relative to the interface size
    double length = 0;
    for (const auto &p : pairs)
      length = std::max(length, p.weight);
    const double gap_tol = 1e-12 * length;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      state.active[i] = tied || (pairs[i].initial_gap <= gap_tol && !pairs[i].junction);
    if (support != nullptr && !tied && !support->holds(state.active))
      {
        state.n_closed_for_support = support->close_smallest_gaps(state.active);
        for (unsigned int i = 0; i < pairs.size(); ++i)
          state.active[i] = state.active[i] && !pairs[i].junction;
        const std::string free     = support->free_motions(state.active);
        AssertThrow(free.empty(),
                    dealii::ExcMessage("Contact: even with every contact pair closed, these rigid-body motions "
                                       "are free: " + free +
                                       ". Add Dirichlet, roller or point constraints (with frictionless contact, "
                                       "each body must be held against sliding along the interface)."));
      }
    state.extrapolate = settings.accelerate_active_set;
    state.extrapolated.assign(pairs.size(), false);
    return state;
  }



  template <int dim>
  std::string
  ActiveSetUpdate<dim>::history_string(const State &state)
  {
    std::ostringstream log;
    for (const auto n : state.n_active_history)
      log << " " << n;
    return log.str();
  }



  template <int dim>
  double
  ActiveSetUpdate<dim>::residual(const std::vector<double> &gaps, const std::vector<double> &multipliers) const
  {
    AssertThrow(gaps.size() == pairs.size() && multipliers.size() == pairs.size(),
                dealii::ExcMessage("ActiveSetUpdate: " + std::to_string(gaps.size()) + " gaps and " +
                                   std::to_string(multipliers.size()) + " multipliers given for " +
                                   std::to_string(pairs.size()) + " contact pairs."));
    double r = 0;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const double p = -multipliers[i] / pairs[i].weight;
        r              = std::max(r, std::abs(p - std::max(0., p - c * gaps[i])));
      }
    return r;
  }



  template <int dim>
  bool
  ActiveSetUpdate<dim>::accelerate(const std::vector<bool>   &active,
                                   const std::vector<double> &gaps,
                                   const std::vector<double> &values,
                                   std::vector<bool>         &next,
                                   std::vector<bool>         &extrapolated) const
  {
    const unsigned int n     = pairs.size();
    auto               holds = [&](const std::vector<bool> &set) { return support == nullptr || support->holds(set); };

    // 1. a step that more than doubles the set adds the deeper half only
    unsigned int n_active = 0, n_added = 0;
    double       deepest  = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        n_active += active[i];
        if (next[i] && !active[i])
          {
            ++n_added;
            deepest = std::max(deepest, -gaps[i]);
          }
      }
    if (n_added > n_active && deepest > 0)
      {
        std::vector<bool> deeper = next;
        for (unsigned int i = 0; i < n; ++i)
          if (next[i] && !active[i] && -gaps[i] < 0.5 * deepest)
            deeper[i] = false;
        if (holds(deeper))
          next = deeper;
        return false;
      }

    // 2. a releasing step releases each run of released pairs once more
    // inwards, over the run's length
    if (neighbours.size() != n)
      return false;
    std::vector<bool> released(n), seen(n, false), extra(n, false);
    bool              any = false;
    for (unsigned int i = 0; i < n; ++i)
      {
        released[i] = active[i] && !next[i];
        any         = any || released[i];
      }
    if (!any)
      return false;
    std::vector<unsigned int>                    run, stack;
    std::vector<std::pair<unsigned int, double>> front;
    for (unsigned int i = 0; i < n; ++i)
      if (released[i] && !seen[i])
        {
          // the run of released pairs through i: its length is the sum of
          // the tributary lengths of its pairs
          run.assign(1, i);
          stack.assign(1, i);
          seen[i] = true;
          while (!stack.empty())
            {
              const unsigned int j = stack.back();
              stack.pop_back();
              for (const auto k : neighbours[j])
                if (released[k] && !seen[k])
                  {
                    seen[k] = true;
                    run.push_back(k);
                    stack.push_back(k);
                  }
            }
          double length = 0, tension = 0;
          for (const auto j : run)
            {
              length += pairs[j].weight;
              tension = std::max(tension, -values[j]);
            }
          // walk from the run into the pairs that stay active, as far as
          // the run's length and only through pairs whose compression
          // (p - c g) is no larger than the largest tension in the run: near
          // the edge of a zone that is too large the decision value runs
          // about linearly through zero, so the band to release mirrors the
          // tension band; a pair carrying more is not at that edge (a head
          // joint that opens beside a bed joint in full compression)
          front.clear();
          for (const auto j : run)
            front.emplace_back(j, 0.);
          while (!front.empty())
            {
              const auto [j, distance] = front.back();
              front.pop_back();
              for (const auto k : neighbours[j])
                if (next[k] && !extra[k] && values[k] <= tension)
                  {
                    const double d = distance + (pairs[k].slave_location - pairs[j].slave_location).norm();
                    if (d <= length)
                      {
                        extra[k] = true;
                        front.emplace_back(k, d);
                      }
                  }
            }
        }
    std::vector<bool> corrected = next;
    bool              changed   = false;
    for (unsigned int i = 0; i < n; ++i)
      if (extra[i])
        {
          corrected[i] = false;
          changed      = true;
        }
    // never release a whole interface's contact, nor a body's hold
    bool kept = false;
    for (unsigned int i = 0; i < n; ++i)
      kept = kept || corrected[i];
    if (!changed || !kept || !holds(corrected))
      return false;
    next = corrected;
    for (unsigned int i = 0; i < n; ++i)
      if (extra[i])
        extrapolated[i] = true;
    return true;
  }



  namespace
  {
    // The pairs that switch between the set @p current and @p next (the
    // first 10 by index and location, and how many more).
    std::string
    switching_pairs(const std::vector<ContactNodePair> &pairs,
                    const std::vector<bool>            &current,
                    const std::vector<bool>            &next)
    {
      std::ostringstream switching;
      unsigned int       n_switching = 0;
      for (unsigned int i = 0; i < pairs.size(); ++i)
        if (next[i] != current[i])
          {
            if (n_switching < 10)
              switching << (n_switching > 0 ? ", " : "") << "pair " << i << " at (" << pairs[i].slave_location
                        << ") " << (next[i] ? "closes" : "opens");
            ++n_switching;
          }
      if (n_switching > 10)
        switching << " and " << n_switching - 10 << " more";
      return switching.str();
    }
  } // namespace



  template <int dim>
  bool
  ActiveSetUpdate<dim>::update(State                     &state,
                               const std::vector<double> &gaps,
                               const std::vector<double> &multipliers) const
  {
    const unsigned int n_pairs = pairs.size();
    AssertThrow(state.active.size() == n_pairs,
                dealii::ExcMessage("ActiveSetUpdate: the state has " + std::to_string(state.active.size()) +
                                   " pairs, the contact " + std::to_string(n_pairs) +
                                   " (make it with initial_state())."));
    AssertThrow(!state.converged,
                dealii::ExcMessage("ActiveSetUpdate: update() called on a converged state."));
    state.residual = residual(gaps, multipliers); // (checks the sizes)
    if (state.extrapolated.size() != n_pairs)
      state.extrapolated.assign(n_pairs, false);

    ++state.n_iterations;
    const unsigned int it       = state.n_iterations;
    const bool ties_on_cycle = (settings.tangential == ContactSettings::Tangential::penalty ||
                                settings.tangential == ContactSettings::Tangential::multipliers);
    unsigned int       n_active = 0;
    for (const bool a : state.active)
      n_active += a;
    state.n_active_history.push_back(n_active);
    state.n_closed = state.n_opened = 0;
    if (settings.normal == ContactSettings::Normal::tied)
      {
        state.converged = true;
        return true;
      }

    // the plain proposal; the scale of the test quantities, to ignore
    // round-off sized values
    std::vector<bool> next(n_pairs);
    double            scale = 0, length = 0;
    for (unsigned int i = 0; i < n_pairs; ++i)
      {
        scale  = std::max({scale, std::abs(multipliers[i]) / pairs[i].weight, c * std::abs(gaps[i])});
        length = std::max(length, pairs[i].weight);
      }
    // (an absolute floor too: the pressure of a gap of 1e-12 of the
    // longest tributary length, the closed-gap tolerance of
    // initial_state(); where every value is round-off the relative test
    // alone follows the noise until the set cycles)
    const double threshold = std::max(1e-10 * scale, 1e-12 * c * length);
    std::vector<double> values(n_pairs);
    for (unsigned int i = 0; i < n_pairs; ++i)
      {
        const double mu = -multipliers[i];
        values[i]       = mu / pairs[i].weight - c * gaps[i];
        next[i]         = (values[i] > threshold) && !pairs[i].junction;
      }
    if (next == state.active)
      {
        state.converged = true;
        return true;
      }
    // a pair released by extrapolation that penetrates again: the edge is
    // found, plain steps from here on
    for (unsigned int i = 0; i < n_pairs && state.extrapolate; ++i)
      if (state.extrapolated[i] && next[i])
        state.extrapolate = false;
    bool                    plain    = true;
    const std::vector<bool> proposed = next;
    if (settings.accelerate_active_set)
      {
        std::vector<bool> marks(n_pairs, false);
        if (accelerate(state.active, gaps, values, next, marks) && !state.extrapolate)
          next = proposed; // extrapolation switched off: keep the plain set
        else
          for (unsigned int i = 0; i < n_pairs; ++i)
            state.extrapolated[i] = state.extrapolated[i] || marks[i];
        if (next != proposed)
          {
            plain = false;
            ++state.n_accelerated;
          }
        // a corrected set seen before falls back to the plain one
        if (!plain && state.visited.count(next) > 0)
          {
            next  = proposed;
            plain = true;
            --state.n_accelerated;
          }
      }
    // a failure: thrown, or recorded for the driver
    const auto fail = [&](const std::string &message) {
      AssertThrow(report_failures, dealii::ExcMessage(message));
      state.failure = message;
      return true;
    };
    // after a step that goes on: the iteration limit
    const auto go_on = [&]() {
      if (it >= settings.max_active_set_iterations)
        return fail("The contact active set did not settle within " +
                    std::to_string(settings.max_active_set_iterations) +
                    " iterations (active pairs per iteration:" + history_string(state) +
                    "). Increase 'Maximum active set iterations' or check the loads and supports.");
      return false;
    };
    if (support != nullptr)
      {
        const std::string free = support->free_motions(next);
        if (!free.empty())
          return fail(
                      "No static equilibrium: in active-set iteration " + std::to_string(it) +
                      " every contact pair that held these rigid-body motions came out in tension or "
                      "open: " + free + " (active pairs per iteration:" + history_string(state) +
                      "). The loads pull the body off its contact partner, or the bodies are too far "
                      "apart for the load to close the gap; hold the body by Dirichlet, roller or point "
                      "constraints, or check the sign of the loads.");
      }
    // with stick, a pair that the plain updates switched max_alternations
    // - 1 times in a row (at most switch_window updates apart) and that
    // would switch again is tied (held tangentially from now on, open or
    // closed) and keeps its state for the next solve, as the pairs of a
    // cycle below; the other pairs take their step
    if (ties_on_cycle)
      {
        if (state.alternations.size() != n_pairs)
          state.alternations.assign(n_pairs, 0);
        if (state.tied_open.size() != n_pairs)
          state.tied_open.assign(n_pairs, false);
        if (state.last_switch.size() != n_pairs)
          state.last_switch.assign(n_pairs, 0);
        bool tied_now = false;
        for (unsigned int i = 0; i < n_pairs; ++i)
          {
            if (next[i] == state.active[i] || proposed[i] == state.active[i])
              {
                // (kept, or switched by the acceleration only)
                if (it > state.last_switch[i] + switch_window)
                  state.alternations[i] = 0;
                continue;
              }
            if (state.alternations[i] + 1u >= max_alternations && !state.tied_open[i])
              {
                state.tied_open[i]    = true;
                state.alternations[i] = 0;
                next[i]               = state.active[i];
                ++state.n_tied_alternating;
                tied_now = true;
                continue;
              }
            state.alternations[i] = (it <= state.last_switch[i] + switch_window)
                                      ? std::min<unsigned int>(state.alternations[i] + 1u, 255u)
                                      : 1;
            state.last_switch[i]  = it;
          }
        if (tied_now)
          {
            // (the model changed: the sets seen before say nothing of it)
            state.visited.clear();
            if (next == state.active)
              return go_on();
          }
      }
    if (plain && state.visited.count(next) > 0 && ties_on_cycle && state.n_tie_rounds < max_tie_rounds)
      {
        // the stick model cycles: tie the pairs this step switches (see
        // State::tied_open) and go on with the same set, so that the
        // next solve is one of the changed model
        if (state.tied_open.size() != n_pairs)
          state.tied_open.assign(n_pairs, false);
        for (unsigned int i = 0; i < n_pairs; ++i)
          if (next[i] != state.active[i])
            state.tied_open[i] = true;
        ++state.n_tie_rounds;
        state.visited.clear();
        return go_on();
      }
    if (plain && state.visited.count(next) > 0)
      {
        return fail("The contact active set cycles: the set of iteration " + std::to_string(it + 1) +
                    " was already visited (active pairs per iteration:" + history_string(state) +
                    "; switching back: " + switching_pairs(pairs, state.active, next) +
                    "). Try another active-set constant or finer meshes.");
      }
    if (plain)
      state.visited.insert(state.active);
    for (unsigned int i = 0; i < n_pairs; ++i)
      {
        state.n_closed += (next[i] && !state.active[i]);
        state.n_opened += (!next[i] && state.active[i]);
      }
    state.active = next;
    return go_on();
  }



  template <int dim>
  bool
  ActiveSetUpdate<dim>::update(State                        &state,
                               const ContactAssembler<dim>  &contact,
                               const dealii::Vector<double> &x) const
  {
    const ContactRows rows = contact.rows();
    AssertThrow(rows.n_pairs() == pairs.size() && x.size() == rows.n_unknowns(),
                dealii::ExcMessage("ActiveSetUpdate: the contact assembler has " + std::to_string(contact.n_pairs()) +
                                   " pairs, this update " + std::to_string(pairs.size()) + ", and the solution " +
                                   std::to_string(x.size()) + " entries."));
    std::vector<double> multipliers(pairs.size());
    for (unsigned int i = 0; i < pairs.size(); ++i)
      multipliers[i] = rows.normal_multiplier(x, i);
    return update(state, contact.gaps(x), multipliers);
  }

  template <int dim>
  std::vector<bool>
  ActiveSetUpdate<dim>::tangential_set(const State &state)
  {
    std::vector<bool> t = state.active;
    for (unsigned int i = 0; i < t.size() && i < state.tied_open.size(); ++i)
      t[i] = t[i] || state.tied_open[i];
    return t;
  }

  template class ActiveSetUpdate<2>;
} // namespace dealvem
