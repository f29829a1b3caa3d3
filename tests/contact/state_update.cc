// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The contact update rules on their own (no mesh, no solve): hand-made node
// pairs (weight w, initial gap) and hand-made gaps and multipliers, for
// which the next set follows from the rule by hand.
// ActiveSetUpdate (c = 2, w = 1 and 0.5; next active iff -lambda/w - c g > 0):
// - a pair with positive gap and zero multiplier stays open, a penetrating
//   one closes, a compressed active one stays, one in tension opens; the
//   counts of closed/opened pairs and the complementarity residual
//   max |p - max(0, p - c g)| (0.5 / 0.5 = 1 here) are the hand values;
// - a consistent solution (active: g = 0, p > 0; inactive: g > 0,
//   lambda = 0) repeats the set: converged, residual exactly 0;
// - A -> B -> A throws "cycles" naming both switching pairs (index and
//   location); A -> B -> C with a limit of 2 iterations throws
//   "did not settle within 2"; tied contact converges in one update;
// - with stick, A -> B -> A ties the switching pairs; a pair that switches
//   three times in a row and would switch again is tied on its own while
//   the whole set never repeats (frictionless: it switches);
// - the first correction of the acceleration: a step that would more than
//   double the set adds only the pairs penetrating by more than half the
//   deepest;
// - bad sizes and c <= 0 are refused with a message.
// FrictionStateUpdate (mu = 0.5, c = 1, tangential multipliers):
// - |tau_hat| < mu p_hat sticks, above slips in the sign of tau_hat (both
//   signs), tension and a positive gap open, a slipping pair whose trial
//   traction turned round sticks;
// - repeated states converge and converged_step() gives the references,
//   slip increments and the dissipated energy sum lambda_t ds by hand;
// - stick -> open -> stick throws "cycles" naming the pair and its states.
#include <dealvem/contact/active_set_update.h>
#include <dealvem/contact/friction_state_update.h>

#include <algorithm>

#include "../tests.h"

using namespace dealvem;

namespace
{
  std::vector<ContactNodePair>
  make_pairs(const std::vector<double> &initial_gaps, const std::vector<double> &weights)
  {
    std::vector<ContactNodePair> pairs(initial_gaps.size());
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        pairs[i].initial_gap    = initial_gaps[i];
        pairs[i].weight         = weights[i];
        pairs[i].slave_location = dealii::Point<2>(0.25 * i, 0.);
        pairs[i].normal         = dealii::Tensor<1, 2>({0., 1.});
        pairs[i].tangent        = dealii::Tensor<1, 2>({1., 0.});
      }
    return pairs;
  }

  std::string
  to_string(const std::vector<bool> &set)
  {
    std::string s;
    for (const bool a : set)
      s += a ? '1' : '0';
    return s;
  }

  void
  test_active_set_rule()
  {
    ContactSettings settings;
    settings.accelerate_active_set = false;
    const auto pairs               = make_pairs({0, 0, 0.1, 0.1, 0}, {1, 1, 1, 0.5, 0.5});
    const ActiveSetUpdate<2> update(pairs, settings, 2.);
    auto                     state = update.initial_state();
    testing::check(to_string(state.active) == "11001", "first set: the pairs of zero initial gap (11001)");

    // pair 0: compressed (p = 1), stays; pair 1: tension (p = -0.5), opens;
    // pair 2: g = 0.05, lambda = 0, stays open; pair 3: g = -0.01, closes;
    // pair 4: w = 0.5, p = 0.4, g = 0, stays
    bool converged = update.update(state, {0, 0, 0.05, -0.01, 0}, {-1, 0.5, 0, 0, -0.2});
    testing::check(!converged && to_string(state.active) == "10011",
                   "open / penetrating / compressed / tension pairs: next set 10011 (got " +
                     to_string(state.active) + ")");
    testing::check(state.n_closed == 1 && state.n_opened == 1, "one pair closed, one opened");
    // residual: pair 1 |p - max(0, p)| = 0.5, pair 3 |0 - max(0, 0.02)| = 0.02
    testing::check_near(state.residual, 0.5, 1e-15, "complementarity residual of the first iterate");

    // a consistent solution: the set repeats, the residual vanishes
    converged = update.update(state, {0, 0.02, 0.05, 0, 0}, {-1, 0, 0, -0.3, -0.1});
    testing::check(converged && state.converged && to_string(state.active) == "10011",
                   "the set repeats: converged on 10011");
    testing::check_small(state.residual, 0, "complementarity residual at convergence");
    testing::check(state.n_iterations == 2 && state.n_active_history == std::vector<unsigned int>{3, 3},
                   "two updates, 3 active pairs in each solve");
    testing::check_small(update.residual({0, 0.02, 0.05, 0, 0}, {-1, 0, 0, -0.3, -0.1}), 0,
                         "residual() of the converged iterate");

    // round-off sized values count as zero: a pair with p - c g = 1e-14
    // (relative to the largest value 1) stays open
    auto s2 = update.initial_state();
    update.update(s2, {0, 0, -0.5e-14, 0.1, 0}, {-1, -1, 0, 0, -0.5});
    testing::check(to_string(s2.active) == "11001" && s2.converged,
                   "a penetration of 1e-14 of the scale does not close a pair");
  }

  // With stick (Tangential penalty or multipliers) a plain step that
  // would return to a visited set ties the pairs it switches tangentially
  // (State::tied_open) and keeps the set; after max_tie_rounds such
  // rounds the next cycle is the failure.
  void
  test_stick_cycle_ties()
  {
    for (const auto t : {ContactSettings::Tangential::penalty, ContactSettings::Tangential::multipliers})
      {
        ContactSettings settings;
        settings.accelerate_active_set = false;
        settings.tangential            = t;
        const auto               pairs = make_pairs({0, 0.1, 0.1}, {1, 1, 1});
        const ActiveSetUpdate<2> update(pairs, settings, 1.);
        auto                     state = update.initial_state();
        // A = 100 -> B = 010, then B would go back to A
        update.update(state, {0, -0.1, 0.1}, {1, 0, 0});
        const bool stops = update.update(state, {-0.1, 0, 0.1}, {0, 1, 0});
        testing::check(!stops && !state.converged && to_string(state.active) == "010" &&
                         to_string(state.tied_open) == "110" && state.n_tie_rounds == 1 &&
                         state.visited.empty() && state.failure.empty(),
                       "stick: A -> B -> A ties the two switching pairs (110), keeps B (010) and goes on");
        testing::check(ActiveSetUpdate<2>::tangential_set(state) == std::vector<bool>{true, true, false},
                       "the tangential set: active or tied (110)");
        // the same two solutions again, each sending A to B and B to A:
        // every cycle is one more round, until the rounds are spent and the
        // next cycle is the failure
        const auto step = [&](ActiveSetUpdate<2>::State &st) {
          return to_string(st.active) == "100" ? update.update(st, {0, -0.1, 0.1}, {1, 0, 0}) :
                                                 update.update(st, {-0.1, 0, 0.1}, {0, 1, 0});
        };
        for (unsigned int round = 1; round < ActiveSetUpdate<2>::max_tie_rounds; ++round)
          {
            step(state);
            step(state);
          }
        testing::check(state.n_tie_rounds == ActiveSetUpdate<2>::max_tie_rounds && !state.converged &&
                         to_string(state.tied_open) == "110",
                       "three rounds of ties (got " + std::to_string(state.n_tie_rounds) + "), the same pairs tied");
        testing::check_throws(
          [&]() {
            auto st = state;
            step(st);
            step(st);
          },
          "The contact active set cycles",
          "after three rounds of ties a cycle is the failure");
      }
  }

  // With stick, a pair that the plain updates switch three times in a row
  // and that would switch a fourth time is tied on its own (State::
  // alternations), even though the whole set never repeats (other pairs
  // close one per iteration); frictionless, the same solutions only switch.
  void
  test_stick_alternation_ties()
  {
    for (const auto t : {ContactSettings::Tangential::multipliers, ContactSettings::Tangential::penalty,
                         ContactSettings::Tangential::frictionless})
      {
        ContactSettings settings;
        settings.accelerate_active_set = false;
        settings.tangential            = t;
        const auto               pairs = make_pairs({0, 0.1, 0.1, 0.1, 0.1}, {1, 1, 1, 1, 1});
        const ActiveSetUpdate<2> update(pairs, settings, 1.);
        auto                     state = update.initial_state();
        // pair 0 in tension when closed and penetrating when open; pair k
        // penetrates in iteration k and is compressed after
        for (unsigned int k = 1; k <= 4; ++k)
          {
            std::vector<double> gaps(5, 0.1), multipliers(5, 0.);
            for (unsigned int j = 1; j < k; ++j)
              {
                gaps[j]        = 0;
                multipliers[j] = -1;
              }
            gaps[k] = -0.1;
            if (state.active[0])
              {
                gaps[0]        = 0;
                multipliers[0] = 1;
              }
            else
              gaps[0] = -0.1;
            const bool stops = update.update(state, gaps, multipliers);
            testing::check(!stops && !state.converged && state.failure.empty(),
                           "iteration " + std::to_string(k) + " goes on");
          }
        if (t == ContactSettings::Tangential::frictionless)
          testing::check(to_string(state.active) == "11111" &&
                           std::count(state.tied_open.begin(), state.tied_open.end(), true) == 0,
                         "frictionless: pair 0 switches a fourth time, nothing tied (got " + to_string(state.active) +
                           ")");
        else
          testing::check(to_string(state.active) == "01111" && to_string(state.tied_open) == "10000" &&
                           state.n_tied_alternating == 1 && state.n_tie_rounds == 0,
                         "stick: the fourth switch of pair 0 ties it and keeps it open (got " +
                           to_string(state.active) + ", tied " + to_string(state.tied_open) + ")");
      }
  }

  void
  test_active_set_failures()
  {
    ContactSettings settings;
    settings.accelerate_active_set = false;
    // (frictionless: with stick a cycle first ties the switching pairs,
    // test_stick_cycle_ties)
    settings.tangential = ContactSettings::Tangential::frictionless;
    const auto pairs    = make_pairs({0, 0.1, 0.1}, {1, 1, 1});
    const ActiveSetUpdate<2> update(pairs, settings, 1.);
    // A = 100 -> B = 010 -> A
    testing::check_throws(
      [&]() {
        auto state = update.initial_state();
        update.update(state, {0, -0.1, 0.1}, {1, 0, 0});
        update.update(state, {-0.1, 0, 0.1}, {0, 1, 0});
      },
      "The contact active set cycles: the set of iteration 3 was already visited (active pairs per iteration: 1 1; "
      "switching back: pair 0 at (0 0) closes, pair 1 at (0.25 0) opens)",
      "A -> B -> A is a cycle, reported with the switching pairs");
    // A -> B -> C with at most 2 iterations
    ContactSettings limited = settings;
    limited.max_active_set_iterations = 2;
    const ActiveSetUpdate<2> short_update(pairs, limited, 1.);
    testing::check_throws(
      [&]() {
        auto state = short_update.initial_state();
        short_update.update(state, {0, -0.1, 0.1}, {1, 0, 0});
        short_update.update(state, {0.1, 0, -0.1}, {0, 1, 0});
      },
      "The contact active set did not settle within 2 iterations (active pairs per iteration: 1 1)",
      "the iteration limit");
    // tied: every pair active, one update
    ContactSettings tied = settings;
    tied.normal          = ContactSettings::Normal::tied;
    const ActiveSetUpdate<2> tied_update(pairs, tied, 1.);
    auto                     state = tied_update.initial_state();
    testing::check(to_string(state.active) == "111" && tied_update.update(state, {0, 0, 0}, {1, -1, 0}),
                   "tied contact: all pairs, converged after one update");
    // bad input
    testing::check_throws([&]() { ActiveSetUpdate<2>(pairs, settings, 0.); }, "must be positive",
                          "c = 0 is refused");
    testing::check_throws(
      [&]() {
        auto st = update.initial_state();
        update.update(st, {0, 0}, {0, 0, 0});
      },
      "2 gaps and 3 multipliers given for 3 contact pairs", "wrong sizes are refused");
  }

  void
  test_acceleration()
  {
    // 1 active pair; the plain rule would add 4 (more than double): only
    // those penetrating by more than half the deepest (0.1) are added
    ContactSettings settings;
    const auto      pairs = make_pairs({0, 0.1, 0.1, 0.1, 0.1}, {1, 1, 1, 1, 1});
    const ActiveSetUpdate<2> update(pairs, settings, 1.);
    auto                     state = update.initial_state();
    update.update(state, {0, -0.1, -0.06, -0.04, -0.01}, {-1, 0, 0, 0, 0});
    testing::check(to_string(state.active) == "11100" && state.n_accelerated == 1,
                   "acceleration: only the deeper half added (11100, got " + to_string(state.active) + ")");
  }

  void
  test_friction_rule()
  {
    ContactSettings settings;
    settings.tangential           = ContactSettings::Tangential::coulomb;
    settings.friction_coefficient = 0.5;
    const auto pairs              = make_pairs({0, 0, 0, 0.1, 0, 0}, {1, 1, 1, 1, 1, 1});
    const FrictionStateUpdate<2> update(pairs, settings, 1., 0.);
    const auto                   first = update.initial_state();
    testing::check(std::count(first.begin(), first.end(), PairState::stick) == 5 &&
                     first[3] == PairState::open,
                   "first states: closed pairs stick, the open one is open");

    // pair 5 slips forward in the last iterate, its trial traction turned
    std::vector<PairState> start = first;
    start[5]                     = PairState::slip_positive;
    auto state                   = update.start(start);
    const std::vector<double> reference(6, 0.);
    // p = 1 (lambda_n = -1) on the closed pairs; tau_hat = tau + c ds:
    // pair 0: 0.3 + 0 (stick), pair 1: 0.4 + 0.2 = 0.6 (slip +), pair 2:
    // -0.6 (slip -), pair 3: gap 0.1 (open), pair 4: tension (open),
    // pair 5: -0.8 (turned round: stick)
    const bool converged = update.update(state, {0, 0, 0, 0.1, 0, 0}, {0, 0.2, 0, 0, 0, 0},
                                         {-1, -1, -1, 0, 0.5, -1}, {0.3, 0.4, -0.6, 0, 0, -0.8}, reference);
    const std::vector<PairState> expected{PairState::stick, PairState::slip_positive, PairState::slip_negative,
                                          PairState::open,  PairState::open,          PairState::stick};
    testing::check(!converged && state.state == expected,
                   "stick inside the cone, slip outside in the sign of tau_hat, open in tension or with a gap, "
                   "a turned slip sticks");
    testing::check(state.n_changed == 4 && state.history.size() == 1 && state.history[0][0] == 1 &&
                     state.history[0][1] == 4 && state.history[0][2] == 1,
                   "four pairs changed; the first solve had 1 open / 4 stick / 1 slip pairs");

    // the slipping pairs carry lambda_t = -mu sigma lambda_n and slip on,
    // the others are consistent: the states repeat
    const bool done = update.update(state, {0, 0, 0, 0.1, 0.2, 0}, {0.1, 0.3, -0.2, 0.05, 0.07, 0},
                                    {-1, -1, -1, 0, 0, -2}, {0.2, 0.5, -0.5, 0, 0, 0.1}, reference);
    testing::check(done && state.state == expected, "repeated states: converged");
    const auto step = update.converged_step(state, reference);
    // multipliers: reference = slip; increment 0 for open pairs; energy =
    // lambda_t ds over the slipping pairs = (0.5)(0.3) + (-0.5)(-0.2) = 0.25
    testing::check(step.reference == std::vector<double>({0.1, 0.3, -0.2, 0.05, 0.07, 0}) &&
                     step.slip_increment == std::vector<double>({0.1, 0.3, -0.2, 0, 0, 0}),
                   "references and slip increments of the converged step");
    testing::check_near(step.dissipated_energy, 0.25, 1e-15, "dissipated energy sum lambda_t ds");

    // stick -> open -> stick
    const auto one = make_pairs({0}, {1});
    const FrictionStateUpdate<2> single(one, settings, 1., 0.);
    testing::check_throws(
      [&]() {
        auto st = single.start(single.initial_state());
        single.update(st, {0}, {0}, {1}, {0}, {0});
        single.update(st, {-0.1}, {0}, {0}, {0}, {0});
      },
      "The friction active set cycles: the states of iteration 3 were already visited (open/stick/slip pairs per "
      "iteration: 0/1/0 1/0/0; switching back: pair 0 at (0 0) open -> stick)",
      "stick -> open -> stick is a cycle, reported with the pair");
  }
} // namespace

int
main()
{
  test_active_set_rule();
  test_stick_cycle_ties();
  test_stick_alternation_ties();
  test_active_set_failures();
  test_acceleration();
  test_friction_rule();
  return testing::finish();
}
