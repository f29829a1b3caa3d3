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
    edge_nodes.push_back(0.);
    edge_nodes.insert(edge_nodes.end(), edge_positions.begin(), edge_positions.end());
    edge_nodes.push_back(1.);
    // the edge stiffness: written out for k = 1 and 2 (the correctly
    // rounded fractions the boundary stabilization always used), else by
    // the k-point Gauss rule
    const unsigned int n = degree + 1;
    if (degree == 1)
      edge_stiffness_matrix = {1., -1., -1., 1.};
    else if (degree == 2)
      edge_stiffness_matrix = {7. / 3, -8. / 3, 1. / 3, -8. / 3, 16. / 3, -8. / 3, 1. / 3, -8. / 3, 7. / 3};
    else
      {
        const dealii::QGauss<1> gauss(degree);
        std::vector<double>     d;
        edge_stiffness_matrix.assign(n * n, 0.);
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            edge_shape_derivatives(gauss.point(q)[0], d);
            for (unsigned int a = 0; a < n; ++a)
              for (unsigned int b = 0; b < n; ++b)
                edge_stiffness_matrix[a * n + b] += gauss.weight(q) * d[a] * d[b];
          }
      }
  }



  void
  VEMElementData::edge_shape_values(const double s, std::vector<double> &values) const
  {
    // k = 1 and 2 written out as the element's edge loads always evaluated
    // them (the same roundings)
    if (degree == 1)
      {
        values = {1. - s, s};
        return;
      }
    if (degree == 2)
      {
        values = {(1. - s) * (1. - 2. * s), 4. * s * (1. - s), s * (2. * s - 1.)};
        return;
      }
    const unsigned int n = edge_nodes.size();
    values.assign(n, 1.);
    for (unsigned int a = 0; a < n; ++a)
      for (unsigned int b = 0; b < n; ++b)
        if (b != a)
          values[a] *= (s - edge_nodes[b]) / (edge_nodes[a] - edge_nodes[b]);
  }



  void
  VEMElementData::edge_shape_derivatives(const double s, std::vector<double> &derivatives) const
  {
    if (degree == 1)
      {
        derivatives = {-1., 1.};
        return;
      }
    if (degree == 2)
      {
        derivatives = {4. * s - 3., 4. - 8. * s, 4. * s - 1.};
        return;
      }
    // the product rule on the Lagrange polynomial: one factor differentiated
    // at a time
    const unsigned int n = edge_nodes.size();
    derivatives.assign(n, 0.);
    for (unsigned int a = 0; a < n; ++a)
      for (unsigned int c = 0; c < n; ++c)
        if (c != a)
          {
            double term = 1. / (edge_nodes[a] - edge_nodes[c]);
            for (unsigned int b = 0; b < n; ++b)
              if (b != a && b != c)
                term *= (s - edge_nodes[b]) / (edge_nodes[a] - edge_nodes[b]);
            derivatives[a] += term;
          }
  }



  std::string
  VEMElementData::get_name() const
  {
    return "VEM<2>(" + std::to_string(degree) + ")";
  }
} // namespace dealvem
