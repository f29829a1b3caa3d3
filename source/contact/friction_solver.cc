// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/friction_solver.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <functional>
#include <iomanip>
#include <iostream>
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
    : ContactSolver<dim>(contact, constraints, solver, settings, c)
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
    FrictionStateUpdate<dim> update(contact.get_pairs(), settings, c, contact.get_penalty());
    update.set_support(support);
    return update.initial_state();
  }



  template <int dim>
  void
  FrictionSolver<dim>::set_continuation(const Continuation &c)
  {
    AssertThrow(std::isfinite(c.first_factor) && c.first_factor > 1 && c.first_factor < 1e6,
                dealii::ExcMessage("FrictionSolver: the first factor of the friction continuation must be above 1 "
                                   "(and below 1e6), not " + std::to_string(c.first_factor) + "."));
    AssertThrow(c.max_doublings <= 20,
                dealii::ExcMessage("FrictionSolver: at most 20 doublings of the friction factor, not " +
                                   std::to_string(c.max_doublings) + "."));
    AssertThrow(std::isfinite(c.min_step) && c.min_step > 0 && c.min_step < 1,
                dealii::ExcMessage("FrictionSolver: the smallest step of the friction continuation must lie in "
                                   "(0, 1), not " + std::to_string(c.min_step) + "."));
    AssertThrow(c.max_attempts >= 2,
                dealii::ExcMessage("FrictionSolver: the friction continuation needs at least 2 attempts."));
    continuation = c;
  }



  namespace
  {
    // The text of an exception without deal.II's location header.
    std::string
    reason_of(const std::exception &e)
    {
      std::string       what = e.what();
      const std::string key  = "Additional information:";
      const auto        pos  = what.find(key);
      if (pos != std::string::npos)
        what = what.substr(pos + key.size());
      const auto trace = what.find("Stacktrace:");
      if (trace != std::string::npos)
        what = what.substr(0, trace);
      // deal.II breaks the message into lines: one line again
      std::string line;
      for (const char ch : what)
        if (ch == '\n' || ch == '\t' || ch == ' ')
          {
            if (!line.empty() && line.back() != ' ')
              line += ' ';
          }
        else
          line += ch;
      what = line;
      const auto first = what.find_first_not_of(" \t\n");
      const auto last  = what.find_last_not_of(" \t\n");
      return first == std::string::npos ? std::string() : what.substr(first, last - first + 1);
    }

    // The motions of RigidBodySupport::free_motions() ("[...] [...]"), each
    // once, and the bodies they move.
    std::string
    motions_and_bodies(const std::string &motions)
    {
      std::vector<std::string> groups;
      std::set<unsigned int>   bodies;
      std::size_t              pos = 0;
      while ((pos = motions.find('[', pos)) != std::string::npos)
        {
          const auto end = motions.find(']', pos);
          if (end == std::string::npos)
            break;
          const std::string group = motions.substr(pos, end - pos + 1);
          if (std::find(groups.begin(), groups.end(), group) == groups.end())
            groups.push_back(group);
          pos = end + 1;
        }
      const std::string key = "body ";
      for (pos = motions.find(key); pos != std::string::npos; pos = motions.find(key, pos + 1))
        {
          std::size_t end = pos + key.size();
          while (end < motions.size() && std::isdigit(static_cast<unsigned char>(motions[end])))
            ++end;
          if (end > pos + key.size())
            bodies.insert(std::stoul(motions.substr(pos + key.size(), end - pos - key.size())));
        }
      if (groups.empty())
        return motions;
      std::string text = "bodies";
      for (const auto b : bodies)
        text += (b == *bodies.begin() ? " " : ", ") + std::to_string(b);
      text += " (motions";
      for (const auto &g : groups)
        text += " " + g;
      return text + ")";
    }

    // The first clause of a message, at most about 200 characters.
    std::string
    headline(const std::string &message)
    {
      auto end = std::min(message.find(" ("), message.find(". "));
      if (end == std::string::npos)
        end = message.size();
      if (end > 200)
        {
          const auto space = message.rfind(' ', 200);
          return message.substr(0, space == std::string::npos ? 200 : space) + " ...";
        }
      return message.substr(0, end);
    }

    std::string
    factor_string(const double f)
    {
      std::ostringstream s;
      s << std::setprecision(6) << f;
      return s.str();
    }



    // The refusal with the mechanism of the last Tresca problem.
    std::string
    friction_collapse(const CollapseMechanism            &mechanism,
                      const std::vector<ContactNodePair> &pairs,
                      const std::string                  &reason,
                      const bool                          continued)
    {
      return "No static equilibrium: the friction cannot hold the bodies. With the friction bounds mu |N| of "
             "the normal forces N of the last iterate of the Tresca fixed point, " +
             mechanism.describe(pairs) + "\n  (the semismooth Newton iteration had failed: " + headline(reason) +
             (continued ? "; the continuation in the friction coefficient found no equilibrium either)" : ")");
    }



    // What the fallbacks of FrictionSolver::solve() share: the step's
    // system, its solution and result, the last converged state, the
    // evidence of a collapse, and the semismooth Newton iteration of the
    // solver from a given state (with the factor set in `update`).
    template <int dim>
    struct FrictionStep
    {
      using State = typename FrictionStateUpdate<dim>::State;

      const ContactAssembler<dim>                                &contact;
      const dealii::AffineConstraints<double>                    &constraints;
      SaddlePointSolver                                          &solver;
      const ContactSettings                                      &settings;
      const dealii::SparseMatrix<double>                         &system_matrix;
      const dealii::Vector<double>                               &system_rhs;
      dealii::SparseMatrix<double>                               &matrix;
      dealii::Vector<double>                                     &x;
      const std::vector<double>                                  &reference;
      FrictionStateUpdate<dim>                                   &update;
      typename FrictionSolver<dim>::Result                       &result;
      State                                                      &state;
      std::shared_ptr<CollapseMechanism>                         &mechanism;
      std::function<State(const std::vector<PairState> &start)> newton;
    };



    // Coulomb as a fixed point of Tresca problems: the friction bounds
    // b_i = mu_i |lambda_n,i| of the last solution, each Tresca problem
    // solved by the globally convergent iteration from the last one's
    // solution and states, starting from the stick solution with the closed
    // pairs `closed`. Sets result.globalized_start when it found a solution
    // (a fixed point, or Newton from settled states); keeps the mechanism
    // when a Tresca problem has no equilibrium.
    template <int dim>
    void
    tresca_fixed_point(FrictionStep<dim>          &step,
                       PrimalActiveSetSolver<dim> &primal,
                       std::vector<bool>           closed,
                       const unsigned int          max_iterations)
    {
      const auto        &contact = step.contact;
      auto              &result  = step.result;
      auto              &x       = step.x;
      const unsigned int n_pairs = contact.n_pairs();
      const ContactRows  rows      = contact.rows();
      const auto         bounds_of = [&](const dealii::Vector<double> &y, const std::vector<bool> &closed_pairs) {
        std::vector<double> b(n_pairs, 0.);
        for (unsigned int i = 0; i < n_pairs; ++i)
          if (closed_pairs[i])
            b[i] = contact.friction_coefficient(i) * std::max(0., -rows.normal_multiplier(y, i));
        return b;
      };
      std::vector<double>    bound = bounds_of(x, closed);
      std::vector<PairState> tstate(n_pairs, PairState::stick);
      bool                   newton_tried = false;
      for (unsigned int k = 0; k < max_iterations && !result.globalized_start; ++k)
        {
          const auto tr =
            primal.solve_tresca(step.system_matrix, step.system_rhs, step.matrix, x, bound, closed, tstate);
          ++result.n_fixed_point_iterations;
          result.n_globalized_solves += tr.n_solves;
          result.n_iterations += tr.n_solves;
          result.linear_iterations += tr.linear_iterations;
          if (!tr.converged)
            {
              // no equilibrium with these bounds: the evidence, if the
              // continuation finds none either
              step.mechanism = std::make_shared<CollapseMechanism>(tr.mechanism);
              break;
            }
          const auto next   = bounds_of(x, tr.active);
          double     change = 0, largest = 0;
          for (unsigned int i = 0; i < n_pairs; ++i)
            {
              change  = std::max(change, std::abs(next[i] - bound[i]));
              largest = std::max(largest, next[i]);
            }
          const bool same_states = (tr.active == closed && tr.state == tstate);
          closed                 = tr.active;
          tstate                 = tr.state;
          if (change <= 1e-11 * largest)
            {
              // a fixed point: the Tresca solution with b = mu |lambda_n| is
              // a Coulomb solution
              auto &state                 = step.state;
              state                       = step.update.start(tstate);
              state.slip                  = contact.slips(x);
              state.tangential_multiplier = tr.tangential_force;
              state.converged             = true;
              state.n_iterations          = tr.n_solves;
              if (step.settings.tangential == ContactSettings::Tangential::coulomb)
                for (unsigned int i = 0; i < n_pairs; ++i)
                  x[rows.tangential_row(i)] = tr.tangential_force[i];
              result.globalized_start = true;
              break;
            }
          bound = next;
          if (same_states && !newton_tried && change <= 1e-6 * largest)
            {
              // the states have settled: Newton from them solves the coupled
              // problem at once
              newton_tried                      = true;
              const dealii::Vector<double> x_fp = x;
              try
                {
                  step.state              = step.newton(tstate);
                  result.globalized_start = true;
                }
              catch (const std::exception &)
                {
                  ++result.n_failed_attempts;
                  x = x_fp;
                }
            }
        }
    }



    // The globalized path after a failed semismooth Newton iteration: the
    // sticking joints, solved by the globally convergent method (no
    // equilibrium there is none with friction: throws with the mechanism),
    // then the Tresca fixed point from that solution.
    template <int dim>
    void
    solve_globalized(FrictionStep<dim>            &step,
                     const dealii::Vector<double> &x_start,
                     const std::string            &plain_reason,
                     const unsigned int            max_fixed_point_iterations)
    {
      const auto     &settings       = step.settings;
      auto           &result         = step.result;
      ContactSettings stick_settings = settings;
      stick_settings.tangential =
        (settings.tangential == ContactSettings::Tangential::coulomb ? ContactSettings::Tangential::multipliers :
                                                                       ContactSettings::Tangential::penalty);
      const ContactAssembler<dim> stick(step.contact.get_dof_handler(), step.contact.get_pairs(), stick_settings,
                                        step.contact.get_penalty());
      PrimalActiveSetSolver<dim>  primal(stick, step.constraints, step.solver, stick_settings);
      primal.set_tangential_reference(step.reference);
      step.x                     = x_start;
      auto pr                    = primal.solve(step.system_matrix, step.system_rhs, step.matrix, step.x);
      result.n_globalized_solves = pr.n_solves;
      result.n_iterations += pr.n_solves;
      if (!pr.converged)
        {
          step.mechanism = std::make_shared<CollapseMechanism>(pr.mechanism);
          AssertThrow(false,
                      dealii::ExcMessage("No static equilibrium, even with unlimited friction (every closed pair "
                                         "sticking): " +
                                         pr.mechanism.describe(step.contact.get_pairs()) +
                                         "\n  (the semismooth Newton iteration had failed: " +
                                         headline(plain_reason) + ")"));
        }
      tresca_fixed_point(step, primal, pr.active, max_fixed_point_iterations);
      if (result.globalized_start)
        step.mechanism.reset();
    }



    // The continuation, part 1: a factor of the friction coefficients at
    // which the iteration converges, from continuation.first_factor,
    // doubled up to continuation.max_doublings times. Returns whether one
    // converged (then in `factor`; step.state is its solution); counts the
    // attempts.
    template <int dim>
    bool
    find_converging_factor(FrictionStep<dim>                                 &step,
                           const typename FrictionSolver<dim>::Continuation &continuation,
                           const std::vector<PairState>                      &start,
                           const dealii::Vector<double>                      &x_start,
                           double                                            &factor,
                           unsigned int                                      &attempts)
    {
      factor         = continuation.first_factor;
      bool converged = false;
      for (unsigned int k = 0; k <= continuation.max_doublings && !converged; ++k, factor *= 2)
        {
          step.update.set_friction_factor(factor);
          step.x = x_start;
          ++attempts;
          try
            {
              step.state = step.newton(start);
              converged  = true;
            }
          catch (const std::exception &)
            {
              ++step.result.n_failed_attempts;
            }
          if (converged)
            break;
        }
      return converged;
    }



    // The continuation, part 2: lower the factor to 1, each attempt from
    // the states of the last factor that converged; throws (naming the
    // motions held only by friction) when the step falls below
    // continuation.min_step.
    template <int dim>
    void
    lower_factor_to_one(FrictionStep<dim>                                 &step,
                        const typename FrictionSolver<dim>::Continuation &continuation,
                        const RigidBodySupport                            *support,
                        const std::string                                 &plain_reason,
                        double                                             factor,
                        unsigned int                                       attempts)
    {
      auto              &result  = step.result;
      auto              &state   = step.state;
      auto              &x       = step.x;
      const unsigned int n_pairs = step.contact.n_pairs();
      double             size    = factor - 1;
      std::string        last_reason;
      double             last_target = 1;
      while (factor > 1)
        {
          const double target = std::max(1., factor - size);
          AssertThrow(attempts < continuation.max_attempts,
                      dealii::ExcMessage(
                        "The friction continuation did not reach the friction coefficients as set within " +
                        std::to_string(continuation.max_attempts) +
                        " Newton iterations; it converged last with every coefficient multiplied by " +
                        factor_string(factor) + ". The semismooth Newton iteration itself failed with: " +
                        plain_reason));
          ++attempts;
          step.update.set_friction_factor(target);
          const dealii::Vector<double> x_converged = x;
          try
            {
              state  = step.newton(state.state);
              factor = target;
              size *= 2;
              result.continuation_factors.push_back(factor);
              continue;
            }
          catch (const std::exception &e)
            {
              ++result.n_failed_attempts;
              last_reason = reason_of(e);
              last_target = target;
              x           = x_converged;
            }
          size = (factor - target) / 2;
          if (size < continuation.min_step)
            {
              // name the rigid-body motions that the closed pairs hold only
              // by friction
              std::string motions;
              if (support != nullptr)
                {
                  std::vector<bool> closed(n_pairs), held(n_pairs, false);
                  for (unsigned int i = 0; i < n_pairs; ++i)
                    closed[i] = (state.state[i] != PairState::open);
                  motions = support->free_motions(closed, held);
                }
              AssertThrow(false,
                          dealii::ExcMessage(
                            "No static equilibrium: the loads need more friction than the contact "
                            "interfaces can carry. The semismooth Newton iteration failed (" +
                            headline(plain_reason) +
                            "); continued in the friction coefficient, it converged with every coefficient "
                            "multiplied by " +
                            factor_string(factor) + " but not from there with any smaller factor (steps down to " +
                            factor_string(continuation.min_step) + "; the last attempt, with the factor " +
                            factor_string(last_target) + ", failed with: " + headline(last_reason) + ")." +
                            (motions.empty() ? std::string() :
                                               " Held only by friction: " + motions_and_bodies(motions) + ".") +
                            (step.mechanism ? "\n  With the friction bounds mu |N| of the normal forces N found, " +
                                                step.mechanism->describe(step.contact.get_pairs()) + "\n " :
                                              std::string()) +
                            " Raise the friction coefficient, hold the bodies by Dirichlet, roller or point "
                            "constraints, or reduce the load."));
            }
        }
    }
  } // namespace



  // The driver: the loop over linear solves; the states, the Coulomb test,
  // convergence, cycles, the iteration limit and the equilibrium safeguard
  // are FrictionStateUpdate's.
  template <int dim>
  typename FrictionStateUpdate<dim>::State
  FrictionSolver<dim>::iterate(FrictionStateUpdate<dim>           &update,
                               const dealii::SparseMatrix<double> &system_matrix,
                               const dealii::Vector<double>       &system_rhs,
                               dealii::SparseMatrix<double>       &matrix,
                               dealii::Vector<double>             &x,
                               const std::vector<PairState>       &start,
                               const std::vector<double>          &reference,
                               Result                             &result) const
  {
    const unsigned int n_pairs     = contact.n_pairs();
    const auto         n           = system_matrix.m() - contact.n_multipliers();
    const bool         multipliers = (settings.tangential == ContactSettings::Tangential::coulomb);
    const double       factor      = update.get_friction_factor();
    auto               state       = update.start(start);
    dealii::Vector<double> rhs;
    // count the solves of this attempt also when it fails
    unsigned int n_counted = 0;
    const auto   count     = [&]() {
      result.n_iterations += state.n_iterations - n_counted;
      for (unsigned int k = n_counted; k < state.history.size(); ++k)
        result.history.push_back(state.history[k]);
      n_counted = state.n_iterations;
    };
    try
      {
        do
          {
            matrix.copy_from(system_matrix);
            rhs = system_rhs;
            contact.assemble_friction(constraints, state.state, reference, matrix, rhs, factor);
            if (!multipliers)
              {
                // the stick springs: the condensed solvers precondition them
                // by tying their ends
                std::vector<bool> sticking(n_pairs);
                for (unsigned int i = 0; i < n_pairs; ++i)
                  sticking[i] = (state.state[i] == PairState::stick);
                solver.set_stick_directions(contact.stick_penalty_rows(constraints, sticking));
              }
            solver.set_context("Newton iteration " + std::to_string(state.n_iterations + 1) +
                               " of the friction solve" +
                               (factor != 1. ? " (friction coefficients times " + factor_string(factor) + ")" :
                                               std::string()));
            solver.solve(matrix, n, x, rhs);
            constraints.distribute(x);
            result.linear_iterations += solver.last_iterations();
          }
        while (!update.update(state, contact, x, reference));
      }
    catch (...)
      {
        count();
        throw;
      }
    count();
    return state;
  }



  // Solve the step; if the plain iteration fails, solve it with every
  // closed pair sticking and as a fixed point of Tresca problems
  // (solve_globalized()), else continue in the factor of the friction
  // coefficients from a converging factor above 1 down to 1.
  template <int dim>
  typename FrictionSolver<dim>::Result
  FrictionSolver<dim>::solve(const dealii::SparseMatrix<double> &system_matrix,
                             const dealii::Vector<double>       &system_rhs,
                             dealii::SparseMatrix<double>       &matrix,
                             dealii::Vector<double>             &x,
                             const std::vector<PairState>       &start,
                             const std::vector<double>          &reference)
  {
    AssertDimension(start.size(), contact.n_pairs());
    AssertDimension(reference.size(), contact.n_pairs());
    FrictionStateUpdate<dim> update(contact.get_pairs(), settings, c, contact.get_penalty());
    update.set_support(support);
    Result                                   result;
    typename FrictionStateUpdate<dim>::State state;
    const dealii::Vector<double>             x_start = x;
    std::exception_ptr                       plain_failure_ptr;
    std::string                              plain_reason;
    FrictionStep<dim>                        step{contact,
                           constraints,
                           solver,
                           settings,
                           system_matrix,
                           system_rhs,
                           matrix,
                           x,
                           reference,
                           update,
                           result,
                           state,
                           mechanism,
                           [&](const std::vector<PairState> &from) {
                             return iterate(update, system_matrix, system_rhs, matrix, x, from, reference, result);
                           }};
    try
      {
        state = iterate(update, system_matrix, system_rhs, matrix, x, start, reference, result);
      }
    catch (const std::exception &plain_failure)
      {
        ++result.n_failed_attempts;
        plain_reason      = reason_of(plain_failure);
        plain_failure_ptr = std::current_exception();
        mechanism.reset();
        if (settings.globalize && settings.normal == ContactSettings::Normal::unilateral && support != nullptr &&
            system_matrix.frobenius_norm() > 0)
          solve_globalized(step, x_start, plain_reason, max_fixed_point_iterations);
        if (!result.globalized_start && !continuation.enabled)
          {
            if (mechanism)
              AssertThrow(false,
                          dealii::ExcMessage(
                            friction_collapse(*mechanism, contact.get_pairs(), plain_reason, continuation.enabled)));
            throw;
          }
      }
    if (!result.globalized_start && plain_failure_ptr)
      {
        double       factor   = 0;
        unsigned int attempts = 1;
        if (!find_converging_factor(step, continuation, start, x_start, factor, attempts))
          {
            if (mechanism)
              AssertThrow(false,
                          dealii::ExcMessage(
                            friction_collapse(*mechanism, contact.get_pairs(), plain_reason, continuation.enabled)));
            std::rethrow_exception(plain_failure_ptr);
          }
        result.continuation_factors.push_back(factor);
        lower_factor_to_one(step, continuation, support, plain_reason, factor, attempts);
      }

    mechanism.reset();
    // converged: slips, friction forces, references for the next step and
    // the dissipated energy, all against the reference of the start of the
    // step
    auto converged               = update.converged_step(state, reference);
    result.state                 = state.state;
    result.slip                  = std::move(converged.slip);
    result.slip_increment        = std::move(converged.slip_increment);
    result.tangential_multiplier = std::move(converged.tangential_multiplier);
    result.reference             = std::move(converged.reference);
    result.dissipated_energy     = converged.dissipated_energy;
    return result;
  }

  template <int dim>
  void
  FrictionSolver<dim>::set_start(const std::vector<PairState> &state, const std::vector<double> &reference)
  {
    AssertThrow(state.size() == contact.n_pairs() && reference.size() == contact.n_pairs(),
                dealii::ExcMessage("FrictionSolver::set_start(): one state and one reference per contact pair "
                                   "are needed (" + std::to_string(contact.n_pairs()) + " pairs, " +
                                   std::to_string(state.size()) + " states, " + std::to_string(reference.size()) +
                                   " references)."));
    start_state     = state;
    start_reference = reference;
  }



  template <int dim>
  const typename FrictionSolver<dim>::Result &
  FrictionSolver<dim>::solve_step(const dealii::SparseMatrix<double> &system_matrix,
                                  const dealii::Vector<double>       &system_rhs,
                                  dealii::SparseMatrix<double>       &matrix,
                                  dealii::Vector<double>             &x)
  {
    AssertThrow(&matrix != &system_matrix,
                dealii::ExcMessage("FrictionSolver::solve_step(): the work matrix must be a matrix of its own "
                                   "(this solver does not solve in place, see solves_in_place())."));
    if (start_state.empty())
      {
        start_state = initial_state();
        start_reference.assign(contact.n_pairs(), 0.);
      }
    this->result = Result();
    this->result = solve(system_matrix, system_rhs, matrix, x, start_state, start_reference);
    this->complete_common_fields(this->result);
    start_state     = this->result.state;
    start_reference = this->result.reference;
    return this->result;
  }



  template <int dim>
  std::string
  FrictionSolver<dim>::name() const
  {
    return "Coulomb friction";
  }



  template class FrictionSolver<2>;
} // namespace dealvem
