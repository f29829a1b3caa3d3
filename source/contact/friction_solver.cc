// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/friction_solver.h>

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
    FrictionStateUpdate<dim> update(contact.get_pairs(), settings, c, contact.get_penalty());
    update.set_support(support);
    return update.initial_state();
  }



  // The driver: the loop over linear solves; the states, the Coulomb test,
  // convergence, cycles, the iteration limit and the equilibrium safeguard
  // are FrictionStateUpdate's.
  template <int dim>
  typename FrictionSolver<dim>::Result
  FrictionSolver<dim>::solve(const dealii::SparseMatrix<double> &system_matrix,
                             const dealii::Vector<double>       &system_rhs,
                             dealii::SparseMatrix<double>       &matrix,
                             dealii::Vector<double>             &x,
                             const std::vector<PairState>       &start,
                             const std::vector<double>          &reference)
  {
    const unsigned int n_pairs     = contact.n_pairs();
    const auto         n           = system_matrix.m() - contact.n_multipliers();
    const bool         multipliers = (settings.tangential == ContactSettings::Tangential::coulomb);
    AssertDimension(start.size(), n_pairs);
    AssertDimension(reference.size(), n_pairs);
    FrictionStateUpdate<dim> update(contact.get_pairs(), settings, c, contact.get_penalty());
    update.set_support(support);
    auto                   state = update.start(start);
    Result                 result;
    dealii::Vector<double> rhs;
    do
      {
        matrix.copy_from(system_matrix);
        rhs = system_rhs;
        contact.assemble_friction(constraints, state.state, reference, matrix, rhs);
        if (!multipliers)
          {
            // the stick springs: the condensed solvers precondition them by
            // tying their ends
            std::vector<bool> sticking(n_pairs);
            for (unsigned int i = 0; i < n_pairs; ++i)
              sticking[i] = (state.state[i] == PairState::stick);
            solver.set_stick_directions(contact.stick_penalty_rows(constraints, sticking));
          }
        solver.set_context("Newton iteration " + std::to_string(state.n_iterations + 1) + " of the friction solve");
        solver.solve(matrix, n, x, rhs);
        constraints.distribute(x);
        result.linear_iterations += solver.last_iterations();
      }
    while (!update.update(state, contact, x, reference));

    // converged: slips, friction forces, references for the next step and
    // the dissipated energy
    auto step                    = update.converged_step(state, reference);
    result.state                 = state.state;
    result.n_iterations          = state.n_iterations;
    result.history               = state.history;
    result.slip                  = std::move(step.slip);
    result.slip_increment        = std::move(step.slip_increment);
    result.tangential_multiplier = std::move(step.tangential_multiplier);
    result.reference             = std::move(step.reference);
    result.dissipated_energy     = step.dissipated_energy;
    return result;
  }

  template class FrictionSolver<2>;
} // namespace dealvem
