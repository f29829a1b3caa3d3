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

    std::set<std::vector<bool>> history;
    std::ostringstream          log;
    dealii::Vector<double>      rhs;
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
        AssertThrow(history.count(next) == 0,
                    dealii::ExcMessage("The contact active set cycles: the set of iteration " +
                                       std::to_string(it + 1) +
                                       " was already visited (active pairs per iteration:" +
                                       log.str() + "). Try another active-set constant or finer meshes."));
        history.insert(result.active);
        result.active = next;
      }
    return result;
  }

  template class ActiveSetSolver<2>;
} // namespace dealvem
