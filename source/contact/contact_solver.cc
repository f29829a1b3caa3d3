// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/active_set_solver.h>
#include <dealvem/contact/contact_solver.h>
#include <dealvem/contact/friction_solver.h>

namespace dealvem
{
  template <int dim>
  ContactSolver<dim>::ContactSolver(const ContactAssembler<dim>             &contact,
                                    const dealii::AffineConstraints<double> &constraints,
                                    SaddlePointSolver                       &solver,
                                    const ContactSettings                   &settings,
                                    const double                             c)
    : contact(contact)
    , constraints(constraints)
    , solver(solver)
    , settings(settings)
    , c(c)
  {}

  template <int dim>
  ContactSolver<dim>::~ContactSolver() = default;



  template <int dim>
  bool
  ContactSolver<dim>::solves_in_place() const
  {
    return false;
  }

  // The one place that maps the contact model to its solver.
  template <int dim>
  std::unique_ptr<ContactSolver<dim>>
  ContactSolver<dim>::create(const ContactAssembler<dim>             &contact,
                             const dealii::AffineConstraints<double> &constraints,
                             SaddlePointSolver                       &solver,
                             const ContactSettings                   &settings,
                             const double                             c)
  {
    if (settings.is_coulomb())
      return std::make_unique<FrictionSolver<dim>>(contact, constraints, solver, settings, c);
    return std::make_unique<ActiveSetSolver<dim>>(contact, constraints, solver, settings, c);
  }

  template <int dim>
  void
  ContactSolver<dim>::complete_common_fields(Result &r)
  {
    if (r.state.empty())
      for (const bool closed : r.active)
        r.state.push_back(closed ? PairState::stick : PairState::open);
    if (r.active.empty())
      for (const PairState s : r.state)
        r.active.push_back(s != PairState::open);
    if (r.n_active_history.empty())
      for (const auto &h : r.history)
        r.n_active_history.push_back(h[1] + h[2]);
  }

  template class ContactSolver<2>;
} // namespace dealvem
