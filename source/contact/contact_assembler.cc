// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/lac/full_matrix.h>

#include <dealvem/contact/contact_assembler.h>

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
    AssertThrow(false, dealii::ExcMessage("Unknown tangential contact model '" + s +
                                          "': expected 'frictionless', 'penalty' or 'multipliers'."));
    return Tangential::frictionless;
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
    , n_tangential(settings.tangential == ContactSettings::Tangential::multipliers ? pairs.size() : 0)
  {
    AssertThrow(settings.tangential != ContactSettings::Tangential::penalty || penalty > 0,
                dealii::ExcMessage("The tangential penalty must be positive."));
    for (const auto &p : pairs)
      AssertThrow(p.is_midpoint == false || dof_handler.get_degree() == 2,
                  dealii::ExcMessage("Midpoint contact pairs need order k = 2."));
  }



  template <int dim>
  std::array<dealii::types::global_dof_index, 4>
  ContactAssembler<dim>::pair_dofs(const unsigned int i) const
  {
    const auto  &p = pairs[i];
    unsigned int a = p.is_midpoint ? dof_handler.edge_node(p.master_entity) :
                                     dof_handler.vertex_node(p.master_entity);
    unsigned int b = p.is_midpoint ? dof_handler.edge_node(p.slave_entity) :
                                     dof_handler.vertex_node(p.slave_entity);
    return {{VEMDoFHandler<dim>::node_dof(a, 0), VEMDoFHandler<dim>::node_dof(a, 1),
             VEMDoFHandler<dim>::node_dof(b, 0), VEMDoFHandler<dim>::node_dof(b, 1)}};
  }



  template <int dim>
  void
  ContactAssembler<dim>::add_sparsity(dealii::DynamicSparsityPattern &dsp) const
  {
    const auto n = dof_handler.n_dofs();
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto d = pair_dofs(i);
        std::vector<dealii::types::global_dof_index> rows(d.begin(), d.end());
        rows.push_back(n + i);
        if (n_tangential > 0)
          rows.push_back(n + n_normal + i);
        for (const auto r : rows)
          for (const auto c : rows)
            dsp.add(r, c);
      }
  }



  template <int dim>
  void
  ContactAssembler<dim>::assemble(const dealii::AffineConstraints<double> &constraints,
                                  const std::vector<bool>                 &active,
                                  dealii::SparseMatrix<double>            &matrix,
                                  dealii::Vector<double>                  &rhs) const
  {
    AssertDimension(active.size(), pairs.size());
    const auto n = dof_handler.n_dofs();
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto &p  = pairs[i];
        const auto  d  = pair_dofs(i);
        // c_n u = (u_B - u_A).n, c_t u = (u_B - u_A).t
        const double cn[4] = {-p.normal[0], -p.normal[1], p.normal[0], p.normal[1]};
        const double ct[4] = {-p.tangent[0], -p.tangent[1], p.tangent[0], p.tangent[1]};

        std::vector<dealii::types::global_dof_index> idx(d.begin(), d.end());
        idx.push_back(n + i);
        if (n_tangential > 0)
          idx.push_back(n + n_normal + i);
        dealii::FullMatrix<double> M(idx.size(), idx.size());
        dealii::Vector<double>     F(idx.size());
        if (active[i])
          {
            for (unsigned int j = 0; j < 4; ++j)
              M(4, j) = M(j, 4) = cn[j];
            F(4) = -p.initial_gap;
          }
        else
          M(4, 4) = 1.;
        if (settings.tangential == ContactSettings::Tangential::multipliers)
          {
            // tangential stick only where the normal constraint is active
            if (active[i])
              for (unsigned int j = 0; j < 4; ++j)
                M(5, j) = M(j, 5) = ct[j];
            else
              M(5, 5) = 1.;
          }
        else if (settings.tangential == ContactSettings::Tangential::penalty && active[i])
          for (unsigned int j = 0; j < 4; ++j)
            for (unsigned int k = 0; k < 4; ++k)
              M(j, k) += penalty * p.weight * ct[j] * ct[k];
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
    if (settings.tangential == ContactSettings::Tangential::multipliers)
      {
        // the force on the slave node is -lambda_t t
        for (unsigned int i = 0; i < pairs.size(); ++i)
          f[i] = -x[dof_handler.n_dofs() + n_normal + i];
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
} // namespace dealvem
