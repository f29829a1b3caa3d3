// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/active_set_solver.h>

#include <set>
#include <sstream>

namespace dealvem
{
  template <int dim>
  ActiveSetSolver<dim>::ActiveSetSolver(const ContactAssembler<dim>             &contact,
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



  template <int dim>
  bool
  ActiveSetSolver<dim>::accelerate(const std::vector<bool>   &active,
                                   const std::vector<double> &gaps,
                                   std::vector<bool>         &next,
                                   std::vector<bool>         &extrapolated) const
  {
    const auto        &pairs = contact.get_pairs();
    const unsigned int n     = pairs.size();
    auto holds = [&](const std::vector<bool> &set) { return support == nullptr || support->holds(set); };

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
          double length = 0;
          for (const auto j : run)
            length += pairs[j].weight;
          // walk from the run into the pairs that stay active
          front.clear();
          for (const auto j : run)
            front.emplace_back(j, 0.);
          while (!front.empty())
            {
              const auto [j, distance] = front.back();
              front.pop_back();
              for (const auto k : neighbours[j])
                if (next[k] && !extra[k])
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



  template <int dim>
  typename ActiveSetSolver<dim>::Result
  ActiveSetSolver<dim>::solve(const dealii::SparseMatrix<double> &system_matrix,
                              const dealii::Vector<double>       &system_rhs,
                              dealii::SparseMatrix<double>       &matrix,
                              dealii::Vector<double>             &x)
  {
    const auto &pairs = contact.get_pairs();
    const auto  n     = system_matrix.m() - contact.n_multipliers();
    Result      result;
    result.active.resize(pairs.size());
    const bool tied = (settings.normal == ContactSettings::Normal::tied);
    // tolerance for "closed" gaps, relative to the interface size
    double length = 0;
    for (const auto &p : pairs)
      length = std::max(length, p.weight);
    const double gap_tol = 1e-12 * length;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      result.active[i] = tied || pairs[i].initial_gap <= gap_tol;
    if (support != nullptr && !tied && !support->holds(result.active))
      {
        result.n_closed_for_support = support->close_smallest_gaps(result.active);
        const std::string free = support->free_motions(result.active);
        AssertThrow(free.empty(),
                    dealii::ExcMessage("Contact: even with every contact pair closed, these rigid-body motions "
                                       "are free: " + free +
                                       ". Add Dirichlet, roller or point constraints (with frictionless contact, "
                                       "each body must be held against sliding along the interface)."));
      }

    // sets from which a plain step was taken: a plain step back to one of
    // them is a cycle
    std::set<std::vector<bool>> history;
    std::ostringstream          log;
    dealii::Vector<double>      rhs;
    bool                        extrapolate = settings.accelerate_active_set;
    std::vector<bool>           extrapolated(pairs.size(), false);
    for (unsigned int it = 1;; ++it)
      {
        AssertThrow(it <= settings.max_active_set_iterations,
                    dealii::ExcMessage("The contact active set did not settle within " +
                                       std::to_string(settings.max_active_set_iterations) +
                                       " iterations (active pairs per iteration:" + log.str() +
                                       "). Increase 'Maximum active set iterations' or check the "
                                       "loads and supports."));
        matrix.copy_from(system_matrix);
        rhs = system_rhs;
        contact.assemble(constraints, result.active, matrix, rhs);
        // the condensed solver preconditions stick springs by tying them
        if (solver.get_type() == SaddlePointSolver::Type::cg_amg_constraints)
          solver.set_stick_directions(contact.stick_penalty_rows(constraints, result.active));
        solver.set_context("active-set iteration " + std::to_string(it));
        solver.solve(matrix, n, x, rhs);
        constraints.distribute(x);
        result.n_iterations = it;
        result.linear_iterations += solver.last_iterations();
        unsigned int n_active = 0;
        for (const bool a : result.active)
          n_active += a;
        result.n_active_history.push_back(n_active);
        log << " " << n_active;
        if (tied)
          break;

        const auto        gaps = contact.gaps(x);
        std::vector<bool> next(pairs.size());
        // scale of the test quantities, to ignore round-off sized values
        double scale = 0;
        for (unsigned int i = 0; i < pairs.size(); ++i)
          scale = std::max({scale, std::abs(x[n + i]) / pairs[i].weight, c * std::abs(gaps[i])});
        for (unsigned int i = 0; i < pairs.size(); ++i)
          {
            const double mu = -x[n + i];
            next[i]         = (mu / pairs[i].weight - c * gaps[i] > 1e-10 * scale);
          }
        if (next == result.active)
          break;
        // a pair released by extrapolation that penetrates again: the edge
        // is found, plain steps from here on
        for (unsigned int i = 0; i < pairs.size() && extrapolate; ++i)
          if (extrapolated[i] && next[i])
            extrapolate = false;
        bool plain = true;
        if (settings.accelerate_active_set && !tied)
          {
            const std::vector<bool> proposed = next;
            std::vector<bool>       marks(pairs.size(), false);
            if (accelerate(result.active, gaps, next, marks) && !extrapolate)
              next = proposed; // extrapolation switched off: keep the plain set
            else
              for (unsigned int i = 0; i < pairs.size(); ++i)
                extrapolated[i] = extrapolated[i] || marks[i];
            if (next != proposed)
              {
                plain = false;
                ++result.n_accelerated;
              }
            // a corrected set seen before falls back to the plain one
            if (!plain && history.count(next) > 0)
              {
                next  = proposed;
                plain = true;
                --result.n_accelerated;
              }
          }
        if (support != nullptr)
          {
            const std::string free = support->free_motions(next);
            AssertThrow(free.empty(),
                        dealii::ExcMessage(
                          "No static equilibrium: in active-set iteration " + std::to_string(it) +
                          " every contact pair that held these rigid-body motions came out in tension or "
                          "open: " + free + " (active pairs per iteration:" + log.str() +
                          "). The loads pull the body off its contact partner, or the bodies are too far "
                          "apart for the load to close the gap; hold the body by Dirichlet, roller or point "
                          "constraints, or check the sign of the loads."));
          }
        AssertThrow(!plain || history.count(next) == 0,
                    dealii::ExcMessage("The contact active set cycles: the set of iteration " +
                                       std::to_string(it + 1) +
                                       " was already visited (active pairs per iteration:" +
                                       log.str() + "). Try another active-set constant or finer meshes."));
        if (plain)
          history.insert(result.active);
        result.active = next;
      }
    return result;
  }

  template class ActiveSetSolver<2>;
} // namespace dealvem
