// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/active_set_solver.h>

#include <cstdint>
#include <cstring>
#include <exception>

namespace dealvem
{
  template <int dim>
  ActiveSetSolver<dim>::ActiveSetSolver(const ContactAssembler<dim>             &contact,
                                        const dealii::AffineConstraints<double> &constraints,
                                        SaddlePointSolver                       &solver,
                                        const ContactSettings                   &settings,
                                        const double                             c)
    : ContactSolver<dim>(contact, constraints, solver, settings, c)
  {
    AssertThrow(c > 0, dealii::ExcMessage("The active-set constant must be positive."));
  }



  template <int dim>
  std::vector<std::vector<unsigned int>>
  ActiveSetSolver<dim>::pair_neighbours(const std::vector<NodeInsertion::Interface> &interfaces)
  {
    unsigned int n_pairs = 0;
    for (const auto &itf : interfaces)
      n_pairs += itf.pairs.size();
    std::vector<std::vector<unsigned int>> neighbours(n_pairs);
    unsigned int                           offset = 0;
    for (const auto &itf : interfaces)
      {
        for (const auto &segment : itf.segments)
          {
            std::vector<unsigned int> chain{segment.first + offset};
            if (segment.midpoint != dealii::numbers::invalid_unsigned_int)
              chain.push_back(segment.midpoint + offset);
            chain.push_back(segment.second + offset);
            for (unsigned int j = 0; j + 1 < chain.size(); ++j)
              {
                neighbours[chain[j]].push_back(chain[j + 1]);
                neighbours[chain[j + 1]].push_back(chain[j]);
              }
          }
        offset += itf.pairs.size();
      }
    return neighbours;
  }



  namespace
  {
    // The values of the rows of a matrix that the contact assembly writes,
    // taken before the first assembly: restore() puts them back, so the
    // system matrix itself serves as the matrix of every iteration (no
    // working copy: at 1e6 DoFs a copy is 250 MB of fresh pages). Debug
    // builds check, by a hash of every value, that the matrix is restored
    // exactly, i.e. that the assembly wrote no other row.
    class RowSnapshot
    {
    public:
      RowSnapshot(dealii::SparseMatrix<double> &matrix, std::vector<unsigned int> rows)
        : matrix(matrix)
        , rows(std::move(rows))
      {
        for (const unsigned int r : this->rows)
          for (auto it = matrix.begin(r), it_end = matrix.end(r); it != it_end; ++it)
            values.push_back(it->value());
#ifdef DEBUG
        hash = value_hash();
#endif
      }

      void
      restore()
      {
        std::size_t k = 0;
        for (const unsigned int r : rows)
          for (auto it = matrix.begin(r), it_end = matrix.end(r); it != it_end; ++it)
            it->value() = values[k++];
#ifdef DEBUG
        Assert(value_hash() == hash,
               dealii::ExcMessage("ActiveSetSolver: the system matrix differs after the contact blocks were "
                                  "taken out: the contact assembly wrote a row that "
                                  "ContactAssembler::rows_written() does not list."));
#endif
      }

    private:
#ifdef DEBUG
      std::uint64_t
      value_hash() const
      {
        std::uint64_t h = 1469598103934665603ull;
        for (auto it = matrix.begin(), it_end = matrix.end(); it != it_end; ++it)
          {
            std::uint64_t bits;
            const double  v = it->value();
            std::memcpy(&bits, &v, sizeof bits);
            h = (h ^ bits) * 1099511628211ull;
          }
        return h;
      }
      std::uint64_t hash = 0;
#endif
      dealii::SparseMatrix<double> &matrix;
      const std::vector<unsigned int> rows;
      std::vector<double>             values;
    };

    // Restores a snapshot (if any) when it goes out of scope, also when
    // the solve throws.
    struct RestoreOnExit
    {
      RowSnapshot *snapshot;
      ~RestoreOnExit()
      {
        if (snapshot != nullptr)
          snapshot->restore();
      }
    };



    // The loop over linear solves of an active-set iteration, with every
    // decision about the set taken by an ActiveSetUpdate (the rule). The
    // solves of a set that is not the last one only choose the next set:
    // with `inexact` they may stop at the solver's inexact tolerance (see
    // ActiveSetSolver); the solver is exact again when the loop ends.
    template <int dim>
    struct UpdateLoop
    {
      const ContactAssembler<dim>             &contact;
      const dealii::AffineConstraints<double> &constraints;
      SaddlePointSolver                       &solver;
      const dealii::SparseMatrix<double>      &system_matrix;
      const dealii::Vector<double>            &system_rhs;
      dealii::SparseMatrix<double>            &matrix;
      dealii::Vector<double>                  &x;
      const unsigned int                       n;
      const bool                               inexact;
      typename ActiveSetSolver<dim>::Result   &result;
      // set when @p matrix is the system matrix itself (solved in place)
      RowSnapshot                             *snapshot = nullptr;
      dealii::Vector<double>                   rhs;

      // Whether the update that made @p next from @p st tied no pairs after
      // a cycle (that changes the model on a repeated set: decided on the
      // completed solve only). Pairs tied because they alternate
      // (ActiveSetUpdate::State::alternations) are decided like the set:
      // on a proposal that a solve continued by a decade repeats.
      static bool
      same_model(const typename ActiveSetUpdate<dim>::State &next, const typename ActiveSetUpdate<dim>::State &st)
      {
        return next.n_tie_rounds == st.n_tie_rounds;
      }

      // Whether @p next opens or closes at least 32 pairs of @p st (see
      // run(): in the traces of the walls of benchmarks/assembly, a solve
      // continued from 1e-3 to 1e-5 moved at most 4 pairs of a proposal).
      static bool
      large_change(const typename ActiveSetUpdate<dim>::State &next, const typename ActiveSetUpdate<dim>::State &st)
      {
        const std::size_t n       = std::min(next.active.size(), st.active.size());
        std::size_t       changed = 0;
        for (std::size_t i = 0; i < n && changed < 32; ++i)
          changed += (next.active[i] != st.active[i]);
        return changed >= 32;
      }

      // Solve and update the state @p st by @p rule until the rule stops;
      // @p name and the iteration number are the solver's context.
      void
      run(ActiveSetUpdate<dim> &rule, typename ActiveSetUpdate<dim>::State &st, const std::string &name)
      {
        solver.set_inexact(inexact);
        while (true)
          {
            if (snapshot != nullptr)
              snapshot->restore();
            else
              matrix.copy_from(system_matrix);
            rhs = system_rhs;
            // (tangentially: the closed pairs and those tied after a cycle)
            const std::vector<bool> tangential = ActiveSetUpdate<dim>::tangential_set(st);
            contact.assemble(constraints, st.active, tangential, matrix, rhs);
            // the condensed solver preconditions stick springs by tying them
            if (solver.get_type() == SaddlePointSolver::Type::cg_amg_constraints)
              solver.set_stick_directions(contact.stick_penalty_rows(constraints, tangential));
            solver.set_context(name + " " + std::to_string(st.n_iterations + 1));
            solver.solve(matrix, n, x, rhs);
            constraints.distribute(x);
            result.linear_iterations += solver.last_iterations();
            if (solver.last_solve_inexact())
              {
                // the rule on a copy of the state: its next set is taken
                // unless it would stop (converge, or fail), which only a
                // solution at the full tolerance may decide
                const auto propose = [&](typename ActiveSetUpdate<dim>::State &trial) {
                  try
                    {
                      return rule.update(trial, contact, x);
                    }
                  catch (const std::exception &)
                    {
                      return true;
                    }
                };
                auto trial = st;
                bool stops = propose(trial);
                // A proposal that opens or closes many pairs is taken at
                // once: the set is far from the last one, and the few pairs
                // whose decision lies within the solve's error can change
                // the path, not the set accepted (the last set is decided
                // on completed solves), as the forcing term of an inexact
                // Newton step far from the solution (the 100-block wall of
                // benchmarks/assembly: 1 of the 150 pairs of the first
                // proposal moved when its solve went on by two decades,
                // 0 of the 34 of the second; 39 CG iterations instead of
                // 46, the same sets). Near the last set the proposals are
                // checked as below.
                if (!stops && same_model(trial, st) && large_change(trial, st))
                  {
                    st = std::move(trial);
                    continue;
                  }
                // The first solve stops at SaddlePointSolver::Settings::
                // inexact_start_tolerance. Its proposal is taken once the
                // solve continued by a decade proposes the same next set
                // (the pairs' decisions did not move with the solve's
                // error); else, and when the rule would stop or tie pairs,
                // the solve goes on by decades down to the inexact
                // tolerance, where the rule decides as before. A first
                // proposal to stop goes straight to the completed solve,
                // which decides anyway: refining first only restarted CG
                // (at 1e6 DoFs, 3 restarts and 4 of 25 CG iterations of a
                // set that was already the last).
                while (!stops && solver.refine_last_solve(matrix, x, rhs))
                  {
                    constraints.distribute(x);
                    result.linear_iterations += solver.last_iterations();
                    auto       again       = st;
                    const bool stops_again = propose(again);
                    const bool same        = !stops && !stops_again && same_model(trial, st) && same_model(again, st) &&
                                      again.active == trial.active && again.tied_open == trial.tied_open;
                    trial = std::move(again);
                    stops = stops_again;
                    if (same)
                      break;
                  }
                // (tying pairs after a cycle changes the model: decided on
                // the completed solve too)
                if (!stops && same_model(trial, st))
                  {
                    st = std::move(trial);
                    continue;
                  }
                solver.complete_last_solve(matrix, x, rhs);
                constraints.distribute(x);
                result.linear_iterations += solver.last_iterations();
                ++result.n_completed_solves;
              }
            if (rule.update(st, contact, x))
              break;
          }
        solver.set_inexact(false);
      }
    };



    // Polish the convex stick solution of the globalized solve (closed pairs
    // @p convex_active) to the model of the fast path (open pairs free
    // tangentially), from its set: first by the same primal iteration, then
    // by the fast path's update (plain, at most 10 iterations); if neither
    // settles, the convex solution stays (Result::convex_stick_model).
    template <int dim>
    void
    polish_stick_solution(UpdateLoop<dim>            &loop,
                          PrimalActiveSetSolver<dim> &primal,
                          const ContactSettings      &settings,
                          const RigidBodySupport     *support,
                          const double                c,
                          const std::vector<bool>    &convex_active)
    {
      auto                        &x      = loop.x;
      auto                        &result = loop.result;
      const dealii::Vector<double> convex = x;
      bool                         done   = false;
      try
        {
          const auto pc =
            primal.solve_stick_on_closed(loop.system_matrix, loop.system_rhs, loop.matrix, x, convex_active);
          result.n_polish_iterations = pc.n_solves;
          result.linear_iterations += pc.linear_iterations;
          if (pc.converged)
            {
              result.active = pc.active;
              done          = true;
            }
        }
      catch (const dealii::ExceptionBase &)
        {
          // (a degenerate tie: the fast path's update polishes instead)
        }
      if (done)
        return;
      x                               = convex;
      ContactSettings plain           = settings;
      plain.accelerate_active_set     = false;
      plain.max_active_set_iterations = 10;
      ActiveSetUpdate<dim> polish(loop.contact.get_pairs(), plain, c);
      polish.set_support(support);
      polish.set_report_failures(true);
      auto pstate   = polish.initial_state();
      pstate.active = convex_active;
      loop.run(polish, pstate, "polish of the globalized solve, iteration");
      result.n_polish_iterations += pstate.n_iterations;
      if (pstate.converged)
        {
          result.active    = pstate.active;
          result.tied_open = pstate.tied_open; // (pairs it held after a cycle)
        }
      else
        {
          x                         = convex;
          result.convex_stick_model = true;
        }
    }
  } // namespace



  // The driver: the loop over linear solves, with every decision about the
  // active set (first set, update, acceleration, convergence, cycles,
  // iteration limit, equilibrium) taken by ActiveSetUpdate; when that
  // iteration gives up, the globalized solve (PrimalActiveSetSolver).
  template <int dim>
  typename ActiveSetSolver<dim>::Result
  ActiveSetSolver<dim>::solve(const dealii::SparseMatrix<double> &system_matrix,
                              const dealii::Vector<double>       &system_rhs,
                              dealii::SparseMatrix<double>       &matrix,
                              dealii::Vector<double>             &x)
  {
    mechanism.reset();
    const bool globalize = settings.globalize && settings.normal == ContactSettings::Normal::unilateral &&
                           !settings.is_coulomb() && support != nullptr;
    ActiveSetUpdate<dim> update(contact.get_pairs(), settings, c);
    update.set_support(support);
    update.set_pair_neighbours(neighbours);
    update.set_report_failures(globalize);
    auto   state = update.initial_state();
    Result result;
    // the solves of a set that is not the last one only choose the next
    // set: they may stop at the solver's inexact tolerance (see the class
    // documentation); the solver is exact again when solve() returns or
    // throws
    const bool inexact = (settings.normal != ContactSettings::Normal::tied);
    struct ExactOnExit
    {
      SaddlePointSolver &solver;
      ~ExactOnExit()
      {
        solver.set_inexact(false);
      }
    } exact_on_exit{solver};
    // in place: the system matrix is the matrix of every iteration, its
    // rows the contact blocks write restored before each assembly and when
    // the fast path ends (or throws); the globalized solve below works on a
    // copy of its own
    std::unique_ptr<RowSnapshot> snapshot;
    if (&matrix == &system_matrix)
      snapshot = std::make_unique<RowSnapshot>(matrix, contact.rows_written(constraints));
    UpdateLoop<dim> loop{contact,
                         constraints,
                         solver,
                         system_matrix,
                         system_rhs,
                         matrix,
                         x,
                         static_cast<unsigned int>(system_matrix.m() - contact.n_multipliers()),
                         inexact,
                         result,
                         snapshot.get(),
                         {}};
    {
      const RestoreOnExit restore_on_exit{snapshot.get()};
      loop.run(update, state, "active-set iteration");
    }
    result.active               = state.active;
    result.n_iterations         = state.n_iterations;
    result.n_active_history     = state.n_active_history;
    result.n_closed_for_support = state.n_closed_for_support;
    result.n_accelerated        = state.n_accelerated;
    result.tied_open            = state.tied_open;
    if (state.converged)
      return result;
    result.tied_open.clear(); // (the globalized solve has its own model)

    // the fast path gave up: the globalized solve (only with the assembled
    // matrix at hand; a distributed solver assembles its own)
    result.fast_path_failure = state.failure;
    AssertThrow(system_matrix.frobenius_norm() > 0, dealii::ExcMessage(state.failure));
    dealii::SparseMatrix<double> own_matrix;
    if (snapshot)
      own_matrix.reinit(system_matrix.get_sparsity_pattern());
    dealii::SparseMatrix<double> &work = (snapshot ? own_matrix : matrix);
    PrimalActiveSetSolver<dim>    primal(contact, constraints, solver, settings);
    const auto                    pr = primal.solve(system_matrix, system_rhs, work, x);
    result.n_globalized_solves      = pr.n_solves;
    result.n_globalized_rigid_steps = pr.n_rigid_steps;
    result.linear_iterations += pr.linear_iterations;
    if (!pr.converged)
      {
        mechanism = std::make_unique<CollapseMechanism>(pr.mechanism);
        AssertThrow(false,
                    dealii::ExcMessage("No static equilibrium: " +
                                       pr.mechanism.describe(contact.get_pairs()) +
                                       "\n  (the active-set iteration had given up: " + state.failure +
                                       " The globalized solve then found the mechanism after " +
                                       std::to_string(pr.n_solves) + " solves and " +
                                       std::to_string(pr.n_rigid_steps) + " rigid steps.)"));
      }
    result.active = pr.active;
    if (settings.tangential != ContactSettings::Tangential::frictionless)
      {
        UpdateLoop<dim> work_loop{contact, constraints, solver,   system_matrix, system_rhs, work, x,
                                  loop.n,  inexact,     result,   nullptr,       {}};
        polish_stick_solution(work_loop, primal, settings, support, c, pr.active);
      }
    return result;
  }

  template <int dim>
  const typename ActiveSetSolver<dim>::Result &
  ActiveSetSolver<dim>::solve_step(const dealii::SparseMatrix<double> &system_matrix,
                                   const dealii::Vector<double>       &system_rhs,
                                   dealii::SparseMatrix<double>       &matrix,
                                   dealii::Vector<double>             &x)
  {
    this->result = Result();
    this->result = solve(system_matrix, system_rhs, matrix, x);
    this->complete_common_fields(this->result);
    return this->result;
  }



  template <int dim>
  bool
  ActiveSetSolver<dim>::solves_in_place() const
  {
    return true;
  }



  template <int dim>
  std::string
  ActiveSetSolver<dim>::name() const
  {
    return settings.normal == ContactSettings::Normal::tied ? "tied" : "active set";
  }



  template class ActiveSetSolver<2>;
} // namespace dealvem
