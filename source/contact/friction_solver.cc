// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/friction_solver.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace dealvem
{
  template <int dim>
  FrictionSolver<dim>::FrictionSolver(const ContactAssembler<dim>             &contact,
                                      const dealii::AffineConstraints<double> &constraints,
                                      SaddlePointSolver                       &solver,
                                      const ContactSettings                   &settings,
                                      const double                             c)
    : contact(contact)
    , constraints(constraints)
    , solver(solver)
    , settings(settings)
    , c(c)
  {
    AssertThrow(c > 0, dealii::ExcMessage("The constant of the friction complementarity functions must be positive."));
    AssertThrow(settings.is_coulomb(),
                dealii::ExcMessage("FrictionSolver needs 'Tangential = coulomb' or 'coulomb penalty'."));
    AssertThrow(settings.normal == ContactSettings::Normal::unilateral,
                dealii::ExcMessage("Coulomb friction needs unilateral normal contact ('Normal = unilateral')."));
  }



  template <int dim>
  std::vector<PairState>
  FrictionSolver<dim>::initial_state() const
  {
    const auto &pairs = contact.get_pairs();
    double      length = 0;
    for (const auto &p : pairs)
      length = std::max(length, p.weight);
    std::vector<bool> closed(pairs.size());
    for (unsigned int i = 0; i < pairs.size(); ++i)
      closed[i] = pairs[i].initial_gap <= 1e-12 * length;
    if (support != nullptr && !support->holds(closed))
      support->close_smallest_gaps(closed);
    std::vector<PairState> state(pairs.size());
    for (unsigned int i = 0; i < pairs.size(); ++i)
      state[i] = closed[i] ? PairState::stick : PairState::open;
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
  } // namespace



  template <int dim>
  typename FrictionSolver<dim>::Result
  FrictionSolver<dim>::solve(const dealii::SparseMatrix<double> &system_matrix,
                             const dealii::Vector<double>       &system_rhs,
                             dealii::SparseMatrix<double>       &matrix,
                             dealii::Vector<double>             &x,
                             const std::vector<PairState>       &start,
                             const std::vector<double>          &reference)
  {
    const auto        &pairs       = contact.get_pairs();
    const unsigned int n_pairs     = pairs.size();
    const auto         n           = system_matrix.m() - contact.n_multipliers();
    const bool         multipliers = (settings.tangential == ContactSettings::Tangential::coulomb);
    const double       eps         = contact.get_penalty();
    AssertDimension(start.size(), n_pairs);
    AssertDimension(reference.size(), n_pairs);

    Result result;
    result.state = start;
    std::set<std::vector<PairState>> visited;
    std::ostringstream               log;
    dealii::Vector<double>           rhs;
    std::vector<double>              lambda_t(n_pairs), s;
    unsigned int                     n_safeguarded = 0;
    for (unsigned int it = 1;; ++it)
      {
        AssertThrow(it <= settings.max_active_set_iterations,
                    dealii::ExcMessage("The friction active set (semismooth Newton) did not settle within " +
                                       std::to_string(settings.max_active_set_iterations) +
                                       " iterations (open/stick/slip pairs per iteration:" + log.str() +
                                       "). Increase 'Maximum active set iterations', use more load steps, "
                                       "or check the loads and supports."));
        matrix.copy_from(system_matrix);
        rhs = system_rhs;
        contact.assemble_friction(constraints, result.state, reference, matrix, rhs);
        if (!multipliers)
          {
            // the stick springs: the condensed solvers precondition them by
            // tying their ends
            std::vector<bool> sticking(n_pairs);
            for (unsigned int i = 0; i < n_pairs; ++i)
              sticking[i] = (result.state[i] == PairState::stick);
            solver.set_stick_directions(contact.stick_penalty_rows(constraints, sticking));
          }
        solver.set_context("Newton iteration " + std::to_string(it) + " of the friction solve");
        solver.solve(matrix, n, x, rhs);
        constraints.distribute(x);
        result.n_iterations = it;
        result.linear_iterations += solver.last_iterations();
        const auto counts = count_states(result.state);
        result.history.push_back(counts);
        log << " " << counts[0] << "/" << counts[1] << "/" << counts[2];

        // the quantities of the complementarity functions
        const auto gaps = contact.gaps(x);
        s               = contact.slips(x);
        std::vector<double> p(n_pairs), tau(n_pairs), tau_hat(n_pairs);
        double              scale = 0;
        for (unsigned int i = 0; i < n_pairs; ++i)
          {
            const double w     = pairs[i].weight;
            const double ln    = x[n + i];
            const double mu    = contact.friction_coefficient(i);
            const auto   state = result.state[i];
            const double sigma = (state == PairState::slip_positive ? 1. : -1.);
            if (multipliers)
              lambda_t[i] = x[n + n_pairs + i];
            else if (state == PairState::stick)
              lambda_t[i] = eps * w * (s[i] - reference[i]);
            else if (state == PairState::open)
              lambda_t[i] = 0;
            else
              lambda_t[i] = -mu * sigma * ln;
            p[i]       = -ln / w;
            tau[i]     = lambda_t[i] / w;
            tau_hat[i] = multipliers ? tau[i] + c * (s[i] - reference[i]) : eps * (s[i] - reference[i]);
            scale      = std::max({scale, std::abs(p[i]), c * std::abs(gaps[i]), std::abs(tau_hat[i])});
          }
        std::vector<PairState> next(n_pairs);
        for (unsigned int i = 0; i < n_pairs; ++i)
          {
            const double p_hat = p[i] - c * gaps[i];
            if (!(p_hat > 1e-10 * scale))
              next[i] = PairState::open;
            else if (std::abs(tau_hat[i]) <= contact.friction_coefficient(i) * p_hat + 1e-10 * scale)
              next[i] = PairState::stick;
            else
              {
                next[i] = (tau_hat[i] > 0 ? PairState::slip_positive : PairState::slip_negative);
                // a slipping pair whose trial traction turned round sticks
                // first: slip reversal goes through stick (no ping-pong
                // between the two slip directions)
                if ((result.state[i] == PairState::slip_positive && next[i] == PairState::slip_negative) ||
                    (result.state[i] == PairState::slip_negative && next[i] == PairState::slip_positive))
                  next[i] = PairState::stick;
              }
          }
        // A body that the next states would leave free: either there is no
        // static equilibrium (the load exceeds what friction can carry), or
        // the iterate passes through an all-slip set on its way to one. Keep
        // the would-be slipping pairs closest to the friction cone (smallest
        // |tau_hat| / (mu p_hat)) sticking until every body is held. If that
        // safeguard is needed at the converged set, at a set visited before,
        // or in three iterations in a row, there is no equilibrium.
        bool        safeguarded = false;
        std::string free;
        if (support != nullptr)
          {
            std::vector<bool> closed(n_pairs), held(n_pairs);
            for (unsigned int i = 0; i < n_pairs; ++i)
              {
                closed[i] = (next[i] != PairState::open);
                held[i]   = (next[i] == PairState::stick);
              }
            free = support->free_motions(closed, held);
            if (!free.empty())
              {
                std::vector<std::pair<double, unsigned int>> candidates;
                for (unsigned int i = 0; i < n_pairs; ++i)
                  if (closed[i] && !held[i])
                    {
                      const double bound = contact.friction_coefficient(i) * (p[i] - c * gaps[i]);
                      candidates.emplace_back(bound > 0 ? std::abs(tau_hat[i]) / bound : 1e300, i);
                    }
                std::sort(candidates.begin(), candidates.end());
                for (const auto &cand : candidates)
                  {
                    next[cand.second] = PairState::stick;
                    held[cand.second] = true;
                    if (support->free_motions(closed, held).empty())
                      break;
                  }
                safeguarded = true;
                ++n_safeguarded;
              }
            else
              n_safeguarded = 0;
            const std::string still_free = support->free_motions(closed, held);
            AssertThrow(still_free.empty() &&
                          !(safeguarded && (next == result.state || visited.count(next) > 0 || n_safeguarded >= 3)),
                        dealii::ExcMessage(
                          "No static equilibrium: in friction iteration " + std::to_string(it) +
                          " every contact pair that held these rigid-body motions came out slipping or open: " +
                          (still_free.empty() ? free : still_free) + " (open/stick/slip pairs per iteration:" +
                          log.str() +
                          "). The tangential load exceeds the friction coefficient times the normal load "
                          "on a body held only by friction, or the loads pull the body off its partner; "
                          "hold the body by Dirichlet, roller or point constraints, or reduce the load."));
          }
        if (next == result.state)
          break;
        AssertThrow(visited.count(next) == 0,
                    dealii::ExcMessage("The friction active set cycles: the states of iteration " +
                                       std::to_string(it + 1) +
                                       " were already visited (open/stick/slip pairs per iteration:" + log.str() +
                                       "). Use more load steps or another mesh."));
        visited.insert(result.state);
        result.state = next;
      }

    // converged: slips, friction forces, references for the next step and
    // the dissipated energy
    result.slip                  = s;
    result.tangential_multiplier = lambda_t;
    result.slip_increment.assign(n_pairs, 0.);
    result.reference.assign(n_pairs, 0.);
    for (unsigned int i = 0; i < n_pairs; ++i)
      {
        const auto state = result.state[i];
        if (multipliers)
          {
            // an open pair does not slip; it starts from where it is
            result.reference[i]      = s[i];
            result.slip_increment[i] = (state == PairState::open ? 0. : s[i] - reference[i]);
          }
        else
          {
            // plastic slip: unchanged while sticking, s - tau/eps while
            // slipping, reset to s when open
            const double w      = pairs[i].weight;
            result.reference[i] = (state == PairState::stick ? reference[i] :
                                   state == PairState::open  ? s[i] :
                                                               s[i] - lambda_t[i] / (eps * w));
            result.slip_increment[i] = (state == PairState::open ? 0. : result.reference[i] - reference[i]);
          }
        if (state == PairState::slip_positive || state == PairState::slip_negative)
          result.dissipated_energy += lambda_t[i] * result.slip_increment[i];
      }
    return result;
  }

  template class FrictionSolver<2>;
} // namespace dealvem
