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
    if (degree == 2)
      edge_positions = {0.5}; // exactly the midpoint
    else if (degree > 2)
      {
        // the interior points of the (k + 1)-point Gauss-Lobatto rule on
        // [0, 1]; its end points are the vertices
        const dealii::QGaussLobatto<1> rule(degree + 1);
        for (unsigned int q = 1; q < degree; ++q)
          edge_positions.push_back(rule.point(q)[0]);
      }
  }



  std::string
  VEMElementData::get_name() const
  {
    return "VEM<2>(" + std::to_string(degree) + ")";
  }
} // namespace dealvem
