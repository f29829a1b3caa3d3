// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Helpers of the finite-sliding tests.
#ifndef dealvem_tests_finite_sliding_common_h
#define dealvem_tests_finite_sliding_common_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>

#include <dealvem/contact/finite_sliding.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <functional>
#include <set>
#include <vector>

namespace testing
{
  /// The displacement of a node of an edge with one of the prescribed
  /// boundary ids: a function of the id, the node's reference position and
  /// the time.
  using Motion = std::function<dealii::Tensor<1, 2>(dealii::types::boundary_id, const dealii::Point<2> &, double)>;

  /// A FiniteSliding constraints function that prescribes @p motion at
  /// every node (vertices, and edge midpoints for k = 2) of the boundary
  /// edges with the ids @p ids (a node on two such edges takes the value
  /// of the first).
  inline dealvem::FiniteSliding::ConstraintsFunction
  prescribe(const std::set<dealii::types::boundary_id> &ids, const Motion &motion)
  {
    return [ids, motion](const dealvem::VEMDoFHandler<2> &dofs, const double t,
                         dealii::AffineConstraints<double> &constraints) {
      const auto &m = dofs.get_mesh();
      for (unsigned int e = 0; e < m.n_edges(); ++e)
        {
          const auto &edge = m.edge(e);
          if (!edge.at_boundary() || ids.count(edge.boundary_id) == 0)
            continue;
          std::vector<unsigned int> nodes{dofs.vertex_node(edge.vertices[0]), dofs.vertex_node(edge.vertices[1])};
          if (dofs.get_degree() == 2)
            nodes.push_back(dofs.edge_node(e));
          for (const auto node : nodes)
            {
              const auto u = motion(edge.boundary_id, dofs.node_location(node), t);
              for (unsigned int comp = 0; comp < 2; ++comp)
                {
                  const auto dof = dealvem::VEMDoFHandler<2>::node_dof(node, comp);
                  if (constraints.is_constrained(dof))
                    continue;
                  constraints.add_line(dof);
                  constraints.set_inhomogeneity(dof, u[comp]);
                }
            }
        }
      constraints.close();
    };
  }
} // namespace testing

#endif
