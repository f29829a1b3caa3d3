// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Helpers of the finite-sliding tests.
#ifndef dealvem_tests_finite_sliding_common_h
#define dealvem_tests_finite_sliding_common_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <dealvem/contact/finite_sliding.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <functional>
#include <set>
#include <vector>

namespace testing
{
  /// A mesh of the annulus r0 < |x - centre| < r1 from
  /// GridGenerator::hyper_shell (n_cells around, refined @p refinements
  /// times, vertices on the circles), material id @p body, its inner circle
  /// with boundary id @p inner_id and its outer one @p outer_id.
  inline dealvem::PolygonalMesh<2>
  annulus(const double r0, const double r1, const unsigned int n_cells, const unsigned int refinements,
          const unsigned int body, const dealii::types::boundary_id inner_id,
          const dealii::types::boundary_id outer_id, const dealii::Point<2> &centre = dealii::Point<2>())
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::hyper_shell(tria, centre, r0, r1, n_cells, true);
    tria.refine_global(refinements);
    dealvem::PolygonalMesh<2> mesh;
    dealvem::PolygonalMeshGenerators::from_triangulation(mesh, tria);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      mesh.set_material_id(c, body);
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      if (mesh.edge(e).at_boundary())
        mesh.set_edge_boundary_id(e, mesh.edge(e).boundary_id == 0 ? inner_id : outer_id);
    return mesh;
  }

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
