// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/contact_rows.h>
#include <dealvem/contact/node_insertion.h>

namespace dealvem
{
  ContactRows::ContactRows(const unsigned int                  n_dofs,
                           const std::vector<ContactNodePair> &pairs,
                           const bool                          tangential_rows)
    : n_displacement_dofs(n_dofs)
    , n_node_pairs(pairs.size())
    , tangential(tangential_rows)
    , pair_list(&pairs)
  {}



  double
  ContactRows::gap0(const unsigned int pair) const
  {
    AssertIndexRange(pair, n_node_pairs);
    return (*pair_list)[pair].initial_gap;
  }



  double
  ContactRows::weight(const unsigned int pair) const
  {
    AssertIndexRange(pair, n_node_pairs);
    return (*pair_list)[pair].weight;
  }



  const dealii::Tensor<1, 2> &
  ContactRows::normal(const unsigned int pair) const
  {
    AssertIndexRange(pair, n_node_pairs);
    return (*pair_list)[pair].normal;
  }



  const dealii::Tensor<1, 2> &
  ContactRows::tangent(const unsigned int pair) const
  {
    AssertIndexRange(pair, n_node_pairs);
    return (*pair_list)[pair].tangent;
  }
} // namespace dealvem
