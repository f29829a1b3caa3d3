// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <dealvem/vem/vem_element_data.h>

namespace dealvem
{
  VEMElementData::VEMElementData(const unsigned int degree)
    : degree(degree)
  {
    AssertThrow(degree >= 1, dealii::ExcMessage("VEMElementData: the order k must be at least 1, got 0."));
    // The (k + 1)-point Gauss-Lobatto rule on [0, 1]: its end points are
    // the vertices, its interior points the edge nodes. The rules of k = 1
    // and 2 are written out, so that their points and weights are the
    // correctly rounded 1/2, 1/6 and 2/3 the formulas of the element always
    // used (deal.II computes the general rule by Newton's method).
    if (degree == 1)
      edge_weights = {0.5, 0.5};
    else if (degree == 2)
      {
        edge_positions = {0.5};
        edge_weights   = {1. / 6., 2. / 3., 1. / 6.};
      }
    else
      {
        const dealii::QGaussLobatto<1> rule(degree + 1);
        for (unsigned int q = 1; q < degree; ++q)
          edge_positions.push_back(rule.point(q)[0]);
        edge_weights = rule.get_weights();
      }
  }



  std::string
  VEMElementData::get_name() const
  {
    return "VEM<2>(" + std::to_string(degree) + ")";
  }
} // namespace dealvem
