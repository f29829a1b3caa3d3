// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/active_set_solver.h>

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



  // The driver: the loop over linear solves, with every decision about the
  // active set (first set, update, acceleration, convergence, cycles,
  // iteration limit, equilibrium) taken by ActiveSetUpdate.
  template <int dim>
  typename ActiveSetSolver<dim>::Result
  ActiveSetSolver<dim>::solve(const dealii::SparseMatrix<double> &system_matrix,
                              const dealii::Vector<double>       &system_rhs,
                              dealii::SparseMatrix<double>       &matrix,
                              dealii::Vector<double>             &x)
  {
    ActiveSetUpdate<dim> update(contact.get_pairs(), settings, c);
    update.set_support(support);
    update.set_pair_neighbours(neighbours);
    auto                   state = update.initial_state();
    const auto             n     = system_matrix.m() - contact.n_multipliers();
    Result                 result;
    dealii::Vector<double> rhs;
    do
      {
        matrix.copy_from(system_matrix);
        rhs = system_rhs;
        contact.assemble(constraints, state.active, matrix, rhs);
        // the condensed solver preconditions stick springs by tying them
        if (solver.get_type() == SaddlePointSolver::Type::cg_amg_constraints)
          solver.set_stick_directions(contact.stick_penalty_rows(constraints, state.active));
        solver.set_context("active-set iteration " + std::to_string(state.n_iterations + 1));
        solver.solve(matrix, n, x, rhs);
        constraints.distribute(x);
        result.linear_iterations += solver.last_iterations();
      }
    while (!update.update(state, contact, x));
    result.active               = state.active;
    result.n_iterations         = state.n_iterations;
    result.n_active_history     = state.n_active_history;
    result.n_closed_for_support = state.n_closed_for_support;
    result.n_accelerated        = state.n_accelerated;
    return result;
  }

  template class ActiveSetSolver<2>;
} // namespace dealvem
