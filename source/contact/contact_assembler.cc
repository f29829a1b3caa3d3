// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/lac/full_matrix.h>

#include <dealvem/base/number_string.h>
#include <dealvem/contact/contact_assembler.h>
#include <dealvem/elasticity/material_library.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace dealvem
{
  ContactSettings::Normal
  ContactSettings::parse_normal(const std::string &s)
  {
    if (s == "tied")
      return Normal::tied;
    if (s == "unilateral")
      return Normal::unilateral;
    AssertThrow(false, dealii::ExcMessage("Unknown normal contact model '" + s +
                                          "': expected 'tied' or 'unilateral'."));
    return Normal::tied;
  }



  ContactSettings::Tangential
  ContactSettings::parse_tangential(const std::string &s)
  {
    if (s == "frictionless")
      return Tangential::frictionless;
    if (s == "penalty")
      return Tangential::penalty;
    if (s == "multipliers")
      return Tangential::multipliers;
    if (s == "coulomb")
      return Tangential::coulomb;
    if (s == "coulomb penalty")
      return Tangential::coulomb_penalty;
    AssertThrow(false, dealii::ExcMessage("Unknown tangential contact model '" + s +
                                          "': expected 'frictionless', 'penalty', 'multipliers', "
                                          "'coulomb' or 'coulomb penalty'."));
    return Tangential::frictionless;
  }



  std::string
  ContactSettings::normal_name(const Normal n)
  {
    return n == Normal::tied ? "tied" : "unilateral";
  }



  std::string
  ContactSettings::tangential_name(const Tangential t)
  {
    switch (t)
      {
        case Tangential::frictionless:
          return "frictionless";
        case Tangential::penalty:
          return "penalty";
        case Tangential::multipliers:
          return "multipliers";
        case Tangential::coulomb:
          return "coulomb";
        case Tangential::coulomb_penalty:
          return "coulomb penalty";
      }
    return "?";
  }



  template <int dim>
  ContactAssembler<dim>::ContactAssembler(const VEMDoFHandler<dim>            &dof_handler,
                                          const std::vector<ContactNodePair> &pairs,
                                          const ContactSettings              &settings,
                                          const double                        penalty)
    : dof_handler(dof_handler)
    , pairs(pairs)
    , settings(settings)
    , penalty(penalty)
    , n_normal(pairs.size())
    , n_tangential((settings.tangential == ContactSettings::Tangential::multipliers ||
                    settings.tangential == ContactSettings::Tangential::coulomb) ?
                     pairs.size() :
                     0)
  {
    AssertThrow((settings.tangential != ContactSettings::Tangential::penalty &&
                 settings.tangential != ContactSettings::Tangential::coulomb_penalty) ||
                  penalty > 0,
                dealii::ExcMessage("ContactAssembler: the tangential stick penalty is " + std::to_string(penalty) +
                                   ", but the tangential model uses a penalty, which must be positive "
                                   "(see ContactScales::penalty())."));
    for (const auto &p : pairs)
      AssertThrow(std::isfinite(settings.friction_coefficient_of(p.interface)) &&
                    settings.friction_coefficient_of(p.interface) >= 0,
                  dealii::ExcMessage("The friction coefficient of contact interface " +
                                     std::to_string(p.interface) + " must be finite and >= 0."));
    for (const auto &p : pairs)
      AssertThrow(!p.on_edge() || dof_handler.get_element_data().nodes_per_edge() == 1,
                  dealii::ExcMessage("Contact pairs of edge nodes need a layout with one node per edge "
                                     "(order k = 2)."));
  }



  template <int dim>
  std::array<dealii::types::global_dof_index, 4>
  ContactAssembler<dim>::pair_dofs(const unsigned int i) const
  {
    const auto  &p = pairs[i];
    const unsigned int a = p.node(dof_handler, true);
    const unsigned int b = p.node(dof_handler, false);
    return {{VEMDoFHandler<dim>::node_dof(a, 0), VEMDoFHandler<dim>::node_dof(a, 1),
             VEMDoFHandler<dim>::node_dof(b, 0), VEMDoFHandler<dim>::node_dof(b, 1)}};
  }



  template <int dim>
  std::vector<unsigned int>
  ContactAssembler<dim>::rows_written(const dealii::AffineConstraints<double> &constraints) const
  {
    // distribute_local_to_global() writes the rows of unconstrained local
    // DoFs, the rows of the DoFs a constrained one refers to, and the
    // diagonal of a constrained one
    std::vector<unsigned int> written;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      for (const auto dof : pair_dofs(i))
        {
          written.push_back(dof);
          if (const auto *entries = constraints.get_constraint_entries(dof))
            for (const auto &e : *entries)
              written.push_back(e.first);
        }
    const unsigned int n = dof_handler.n_dofs();
    for (unsigned int r = 0; r < n_multipliers(); ++r)
      written.push_back(n + r);
    std::sort(written.begin(), written.end());
    written.erase(std::unique(written.begin(), written.end()), written.end());
    return written;
  }



  template <int dim>
  void
  ContactAssembler<dim>::add_sparsity(dealii::DynamicSparsityPattern &dsp) const
  {
    const ContactRows layout = rows();
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto d = pair_dofs(i);
        std::vector<dealii::types::global_dof_index> idx(d.begin(), d.end());
        idx.push_back(layout.normal_row(i));
        if (layout.has_tangential_rows())
          idx.push_back(layout.tangential_row(i));
        for (const auto r : idx)
          for (const auto c : idx)
            dsp.add(r, c);
      }
  }



  template <int dim>
  bool
  ContactAssembler<dim>::is_fixed_by_constraints(const dealii::AffineConstraints<double> &constraints,
                                                 const unsigned int                       i,
                                                 const double                             c[4],
                                                 double                                  &value) const
  {
    // Write the row in the unconstrained DoFs: u_d = sum_k a_k u_k + b for
    // a constrained d (after close(), the u_k are unconstrained). The row
    // is fixed if no unconstrained DoF keeps a coefficient.
    const auto                                       d = pair_dofs(i);
    std::map<dealii::types::global_dof_index, double> row;
    double                                           scale = 0;
    value                                                  = 0;
    for (unsigned int j = 0; j < 4; ++j)
      {
        if (c[j] == 0)
          continue;
        scale = std::max(scale, std::abs(c[j]));
        if (!constraints.is_constrained(d[j]))
          return false;
        if (const auto *entries = constraints.get_constraint_entries(d[j]))
          for (const auto &e : *entries)
            row[e.first] += c[j] * e.second;
        value += c[j] * constraints.get_inhomogeneity(d[j]);
      }
    for (const auto &r : row)
      if (std::abs(r.second) > 1e-12 * scale)
        return false;
    return true;
  }



  template <int dim>
  bool
  ContactAssembler<dim>::drop_if_fixed(const dealii::AffineConstraints<double> &constraints,
                                       const unsigned int                       i,
                                       const double                             c[4],
                                       const bool                               tangential,
                                       const double                             required,
                                       const bool                               unilateral) const
  {
    double value = 0;
    if (!is_fixed_by_constraints(constraints, i, c, value))
      return false;
    const auto  &p   = pairs[i];
    const double tol = 1e-12 * std::max({std::abs(value), std::abs(required), p.weight});
    const bool   open_gap = !tangential && unilateral && value >= required - tol;
    if (!open_gap && std::abs(value - required) > tol)
      {
        using internal::number_string;
        const std::string where = internal::point_string(p.slave_location);
        // the normal row reads (u_B - u_A).n = -g0, so the gap it leaves is
        // value + g0, and contact requires required + g0 (0 for a tied or
        // closed pair)
        const std::string demand =
          tangential ? number_string(required) + " (stick)" :
                       (unilateral ? std::string("a gap >= ") + number_string(required + p.initial_gap) :
                                     number_string(required + p.initial_gap) + " (tied)");
        AssertThrow(false,
                    dealii::ExcMessage(
                      "Contact pair " + std::to_string(i) + " at " + where + " (interface " +
                      std::to_string(p.interface) + "): the " + (tangential ? "tangential" : "normal") +
                      " contact constraint involves only displacements fixed by the Dirichlet, roller "
                      "or point constraints, and they disagree: the Dirichlet/roller data force a " +
                      (tangential ? "tangential slip" : "gap") + " of " +
                      number_string(tangential ? value : value + p.initial_gap) + " at pair " + where +
                      " but contact requires " + demand + ". Remove one of the two conditions or make them agree."));
      }
    dropped.push_back({i, p.slave_location, tangential, value});
    return true;
  }



  template <int dim>
  void
  ContactAssembler<dim>::assemble(const dealii::AffineConstraints<double> &constraints,
                                  const std::vector<bool>                 &active,
                                  dealii::SparseMatrix<double>            &matrix,
                                  dealii::Vector<double>                  &rhs) const
  {
    assemble(constraints, active, active, matrix, rhs);
  }



  template <int dim>
  void
  ContactAssembler<dim>::assemble(const dealii::AffineConstraints<double> &constraints,
                                  const std::vector<bool>                 &active,
                                  const std::vector<bool>                 &tangential_active,
                                  dealii::SparseMatrix<double>            &matrix,
                                  dealii::Vector<double>                  &rhs,
                                  const std::vector<double>               *reference) const
  {
    AssertDimension(active.size(), pairs.size());
    AssertDimension(tangential_active.size(), pairs.size());
    Assert(reference == nullptr || reference->size() == pairs.size(),
           dealii::ExcDimensionMismatch(reference->size(), pairs.size()));
    const ContactRows layout = rows();
    dropped.clear();
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto &p  = pairs[i];
        const auto  d  = pair_dofs(i);
        // c_n u = (u_B - u_A).n, c_t u = (u_B - u_A).t
        const double cn[4] = {-p.normal[0], -p.normal[1], p.normal[0], p.normal[1]};
        const double ct[4] = {-p.tangent[0], -p.tangent[1], p.tangent[0], p.tangent[1]};

        // an enforced constraint whose DoFs the displacement constraints
        // fix already is dropped if the two agree (drop_if_fixed())
        const bool unilateral = (settings.normal == ContactSettings::Normal::unilateral);
        std::vector<dealii::types::global_dof_index> idx(d.begin(), d.end());
        idx.push_back(layout.normal_row(i));
        if (layout.has_tangential_rows())
          idx.push_back(layout.tangential_row(i));
        dealii::FullMatrix<double> M(idx.size(), idx.size());
        dealii::Vector<double>     F(idx.size());
        if (active[i] && !drop_if_fixed(constraints, i, cn, false, -p.initial_gap, unilateral))
          {
            for (unsigned int j = 0; j < 4; ++j)
              M(4, j) = M(j, 4) = cn[j];
            F(4) = -p.initial_gap;
          }
        else
          M(4, 4) = 1.;
        if (settings.tangential == ContactSettings::Tangential::multipliers)
          {
            // tangential stick where asked (assemble(): where the normal
            // constraint is active)
            const double r = (reference != nullptr ? (*reference)[i] : 0.);
            if (tangential_active[i] && !drop_if_fixed(constraints, i, ct, true, r, unilateral))
              {
                for (unsigned int j = 0; j < 4; ++j)
                  M(5, j) = M(j, 5) = ct[j];
                F(5) = r;
              }
            else
              M(5, 5) = 1.;
          }
        else if (settings.tangential == ContactSettings::Tangential::penalty && tangential_active[i])
          {
            const double r = (reference != nullptr ? (*reference)[i] : 0.);
            for (unsigned int j = 0; j < 4; ++j)
              {
                for (unsigned int k = 0; k < 4; ++k)
                  M(j, k) += penalty * p.weight * ct[j] * ct[k];
                F(j) += penalty * p.weight * r * ct[j];
              }
          }
        constraints.distribute_local_to_global(M, F, idx, matrix, rhs);
      }
  }



  template <int dim>
  std::vector<std::vector<std::pair<unsigned int, double>>>
  ContactAssembler<dim>::stick_penalty_rows(const dealii::AffineConstraints<double> &constraints,
                                            const std::vector<bool>                 &active) const
  {
    AssertDimension(active.size(), pairs.size());
    std::vector<std::vector<std::pair<unsigned int, double>>> rows;
    if (settings.tangential != ContactSettings::Tangential::penalty &&
        settings.tangential != ContactSettings::Tangential::coulomb_penalty)
      return rows;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      if (active[i])
        {
          const auto                     &p    = pairs[i];
          const auto                      d    = pair_dofs(i);
          const double                    ct[4] = {-p.tangent[0], -p.tangent[1], p.tangent[0], p.tangent[1]};
          std::map<unsigned int, double>  row;
          for (unsigned int j = 0; j < 4; ++j)
            if (constraints.is_constrained(d[j]))
              {
                for (const auto &e : *constraints.get_constraint_entries(d[j]))
                  row[e.first] += ct[j] * e.second;
              }
            else
              row[d[j]] += ct[j];
          std::vector<std::pair<unsigned int, double>> r;
          for (const auto &e : row)
            if (e.second != 0.)
              r.emplace_back(e.first, e.second);
          if (!r.empty())
            rows.push_back(std::move(r));
        }
    return rows;
  }



  template <int dim>
  void
  ContactAssembler<dim>::assemble_friction(const dealii::AffineConstraints<double> &constraints,
                                           const std::vector<PairState>            &state,
                                           const std::vector<double>               &reference,
                                           dealii::SparseMatrix<double>            &matrix,
                                           dealii::Vector<double>                  &rhs,
                                           const double                             friction_factor) const
  {
    AssertThrow(std::isfinite(friction_factor) && friction_factor > 0,
                dealii::ExcMessage("assemble_friction(): the factor of the friction coefficients must be "
                                   "positive and finite, not " + std::to_string(friction_factor) + "."));
    AssertThrow(settings.is_coulomb(),
                dealii::ExcMessage("assemble_friction() needs 'Tangential = coulomb' or 'coulomb penalty'."));
    AssertDimension(state.size(), pairs.size());
    AssertDimension(reference.size(), pairs.size());
    const bool multipliers = (settings.tangential == ContactSettings::Tangential::coulomb);
    const ContactRows layout      = rows();
    dropped.clear();
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto  &p      = pairs[i];
        const auto   d      = pair_dofs(i);
        const double cn[4]  = {-p.normal[0], -p.normal[1], p.normal[0], p.normal[1]};
        const double ct[4]  = {-p.tangent[0], -p.tangent[1], p.tangent[0], p.tangent[1]};
        const bool   closed = (state[i] != PairState::open);
        const double sigma  = (state[i] == PairState::slip_positive ? 1. : -1.);
        const double mu     = friction_factor * friction_coefficient(i);

        // a closed normal or sticking tangential row that the displacement
        // constraints fix already: as in assemble(), dropped if they agree
        // (Coulomb friction is unilateral: an open gap is admissible)
        std::vector<dealii::types::global_dof_index> idx(d.begin(), d.end());
        idx.push_back(layout.normal_row(i));
        if (multipliers)
          idx.push_back(layout.tangential_row(i));
        dealii::FullMatrix<double> M(idx.size(), idx.size());
        dealii::Vector<double>     F(idx.size());
        const bool normal_on = closed && !drop_if_fixed(constraints, i, cn, false, -p.initial_gap, true);
        if (normal_on)
          {
            for (unsigned int j = 0; j < 4; ++j)
              M(4, j) = M(j, 4) = cn[j];
            F(4) = -p.initial_gap;
          }
        else
          M(4, 4) = 1.;
        if (multipliers)
          {
            if (state[i] == PairState::stick && !drop_if_fixed(constraints, i, ct, true, reference[i], true))
              {
                for (unsigned int j = 0; j < 4; ++j)
                  M(5, j) = M(j, 5) = ct[j];
                F(5) = reference[i];
              }
            else if (closed && state[i] != PairState::stick)
              {
                // slip: lambda_t + mu sigma lambda_n = 0; lambda_t still acts
                // on the displacements
                for (unsigned int j = 0; j < 4; ++j)
                  M(j, 5) = ct[j];
                M(5, 5) = 1.;
                M(5, 4) = mu * sigma;
              }
            else
              M(5, 5) = 1.;
          }
        else if (state[i] == PairState::stick)
          {
            const double eps = penalty * p.weight;
            for (unsigned int j = 0; j < 4; ++j)
              {
                for (unsigned int k = 0; k < 4; ++k)
                  M(j, k) += eps * ct[j] * ct[k];
                F(j) += eps * reference[i] * ct[j];
              }
          }
        else if (closed && normal_on)
          // slip: the tangential force -mu sigma lambda_n acts through c_t
          for (unsigned int j = 0; j < 4; ++j)
            M(j, 4) += -mu * sigma * ct[j];
        constraints.distribute_local_to_global(M, F, idx, matrix, rhs);
      }
  }



  template <int dim>
  std::vector<double>
  ContactAssembler<dim>::gaps(const dealii::Vector<double> &u) const
  {
    std::vector<double> g(pairs.size());
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto d = pair_dofs(i);
        g[i]         = (u[d[2]] - u[d[0]]) * pairs[i].normal[0] +
               (u[d[3]] - u[d[1]]) * pairs[i].normal[1] + pairs[i].initial_gap;
      }
    return g;
  }



  template <int dim>
  std::vector<double>
  ContactAssembler<dim>::slips(const dealii::Vector<double> &u) const
  {
    std::vector<double> s(pairs.size());
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto d = pair_dofs(i);
        s[i] = (u[d[2]] - u[d[0]]) * pairs[i].tangent[0] + (u[d[3]] - u[d[1]]) * pairs[i].tangent[1];
      }
    return s;
  }



  template <int dim>
  std::vector<double>
  ContactAssembler<dim>::tangential_forces(const dealii::Vector<double> &x) const
  {
    std::vector<double> f(pairs.size(), 0.);
    if (settings.tangential == ContactSettings::Tangential::multipliers ||
        settings.tangential == ContactSettings::Tangential::coulomb)
      {
        // the force on the slave node is -lambda_t t
        const ContactRows layout = rows();
        for (unsigned int i = 0; i < pairs.size(); ++i)
          f[i] = -layout.tangential_multiplier(x, i);
      }
    else if (settings.tangential == ContactSettings::Tangential::penalty)
      {
        const auto s = slips(x);
        for (unsigned int i = 0; i < pairs.size(); ++i)
          f[i] = -penalty * pairs[i].weight * s[i];
      }
    return f;
  }

  template class ContactAssembler<2>;



  ContactScales::ContactScales(const std::vector<double>                   &youngs_moduli,
                               const std::vector<NodeInsertion::Interface> &interfaces)
  {
    AssertThrow(!youngs_moduli.empty(), dealii::ExcMessage("ContactScales: no Young's modulus given."));
    E_min = *std::min_element(youngs_moduli.begin(), youngs_moduli.end());
    AssertThrow(E_min > 0 && std::isfinite(E_min),
                dealii::ExcMessage("ContactScales: the Young's moduli must be positive and finite."));
    h_min = std::numeric_limits<double>::infinity();
    for (const auto &itf : interfaces)
      for (const auto &s : itf.segments)
        h_min = std::min(h_min, s.length);
    AssertThrow(h_min > 0 && std::isfinite(h_min),
                dealii::ExcMessage("ContactScales: node insertion paired no interface edge, so the contact "
                                   "scale E_min / h_min is undefined."));
  }



  ContactScales::ContactScales(const MaterialLibrary<2>                    &laws,
                               const std::vector<NodeInsertion::Interface> &interfaces)
    : ContactScales(std::vector<double>{laws.min_characteristic_stiffness()}, interfaces)
  {}



  void
  ContactScales::check_penalty(const ContactSettings &settings,
                               const std::string     &penalty_parameter,
                               const std::string     &factor_parameter) const
  {
    const double scale  = E_min / h_min;
    const bool   given  = settings.penalty > 0;
    const double factor = given ? settings.penalty / scale : settings.penalty_factor;
    if (std::isfinite(factor) && factor >= min_penalty_factor && factor <= max_penalty_factor)
      return;
    std::ostringstream msg;
    msg << "Parameter '" << (given ? penalty_parameter : factor_parameter) << "' = "
        << (given ? settings.penalty : settings.penalty_factor) << " is out of range for this problem: ";
    if (given)
      msg << "the stick penalty must lie in [" << min_penalty_factor * scale << ", " << max_penalty_factor * scale
          << "], that is " << min_penalty_factor << " to " << max_penalty_factor
          << " times E_min / h_min = " << scale << " (it is " << factor << " times that)";
    else
      msg << "the factor of the default penalty rule 'penalty = factor * E_min / h_min' must lie in ["
          << min_penalty_factor << ", " << max_penalty_factor << "] (E_min / h_min = " << scale << ")";
    msg << "; E_min = " << E_min << " is the smallest Young's modulus of the bodies and h_min = " << h_min
        << " the shortest paired interface sub-edge. A smaller penalty leaves the stick direction "
           "nearly free (a body held there by the springs alone moves by about 1 / factor times its "
           "elastic deformation, computed from a nearly singular system), a larger one makes the "
           "system too ill-conditioned for correct pressures.";
    AssertThrow(false, dealii::ExcMessage(msg.str()));
  }
} // namespace dealvem
