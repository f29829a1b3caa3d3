// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The element describes its own DoF layout (VEMElementData) and the DoF
// handler reads it:
//   1. the counts of orders 1, 2 and 3 (nodes per vertex, edge and cell,
//      local nodes and DoFs of an n-gon) and the edge nodes' positions (the
//      interior Gauss-Lobatto points: 1/2 for k = 2, (1 -+ 1/sqrt 5)/2 for
//      k = 3);
//   2. distribute_dofs(element) numbers exactly as distribute_dofs(k) on a
//      Voronoi mesh (same indices cell by cell, same support points);
//   3. a layout with two nodes per edge (k = 3) on a Voronoi mesh, where
//      neighbouring cells run along their shared edges in opposite
//      directions: every local edge node sits where the cell's own edge
//      parametrisation puts it (to 4e-15 on the 2 x 1 domain), every global
//      node is used, n_dofs = 2 (V + 2 E + 3 C);
//   4. the Lagrange basis of an edge (k = 1 to 4) and its d/ds stiffness,
//      against the closed forms for k = 1 and 2; the stabilization rules;
//   5. misuse is refused: order 0, VirtualElement of order 3, rigid-body
//      modes of a layout with three moments per cell.
#include <deal.II/base/point.h>

#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/vem_element_data.h>
#include <dealvem/vem/virtual_element.h>

#include <algorithm>
#include <cmath>

#include "../tests.h"

using namespace dealvem;

int
main()
{
  // 1. counts and positions
  {
    const VEMElementData k1(1), k2(2), k3(3);
    testing::check(k1.nodes_per_edge() == 0 && k1.nodes_per_cell() == 0 && k1.n_dofs_per_cell(5) == 10,
                   "k = 1: vertex nodes only, 10 DoFs on a pentagon");
    testing::check(k2.nodes_per_edge() == 1 && k2.nodes_per_cell() == 1 && k2.n_nodes(5) == 11 &&
                     k2.n_dofs_per_cell(5) == 22 && k2.edge_node_positions() == std::vector<double>{0.5},
                   "k = 2: one midpoint per edge, one moment, 22 DoFs on a pentagon");
    testing::check(k3.nodes_per_edge() == 2 && k3.nodes_per_cell() == 3 && k3.n_nodes(4) == 15 &&
                     k3.edge_node(4, 1, 1) == 7 && k3.cell_node(4, 2) == 14,
                   "k = 3: two nodes per edge, three moments; local order vertices, edges, moments");
    testing::check_near(k3.edge_node_positions()[0], 0.5 * (1 - 1 / std::sqrt(5.)), 1e-15,
                        "k = 3: first edge node at (1 - 1/sqrt 5)/2");
    testing::check_near(k3.edge_node_positions()[1], 0.5 * (1 + 1 / std::sqrt(5.)), 1e-15,
                        "k = 3: second edge node at (1 + 1/sqrt 5)/2");
    // the edge rule of the layout: Gauss-Lobatto on the edge's k + 1 nodes
    testing::check(k1.edge_quadrature_weights() == std::vector<double>{0.5, 0.5},
                   "k = 1: the trapezoidal rule on an edge");
    testing::check(k2.edge_quadrature_weights() == std::vector<double>{1. / 6., 2. / 3., 1. / 6.},
                   "k = 2: Simpson's rule on an edge");
    {
      const std::vector<double> &w = k3.edge_quadrature_weights();
      testing::check(w.size() == 4, "k = 3: four edge weights");
      testing::check_near(w[0], 1. / 12., 1e-15, "k = 3: first end weight 1/12");
      testing::check_near(w[1], 5. / 12., 1e-15, "k = 3: first interior weight 5/12");
      testing::check_near(w[2] - w[1] + w[3] - w[0], 0., 1e-15, "k = 3: the weights are symmetric");
    }
    testing::check(k3.node_kind(4, 3) == VEMElementData::NodeKind::vertex &&
                     k3.node_kind(4, 4) == VEMElementData::NodeKind::edge &&
                     k3.node_kind(4, 11) == VEMElementData::NodeKind::edge &&
                     k3.node_kind(4, 12) == VEMElementData::NodeKind::cell &&
                     k2.node_kind(5, 9) == VEMElementData::NodeKind::edge,
                   "node kinds follow the local order");
    for (const unsigned int k : {1u, 2u})
      {
        const VirtualElement<2> element(k);
        testing::check(element.get_element_data().get_degree() == k &&
                         element.n_dofs_per_cell(7) == element.get_element_data().n_dofs_per_cell(7),
                       "VirtualElement(" + std::to_string(k) + ") reports its layout");
      }
  }

  PolygonalMesh<2> mesh;
  PolygonalMeshGenerators::voronoi(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(2, 1), 40, 3, 7);

  // 2. the element's layout numbers as the integer order did
  for (const unsigned int k : {1u, 2u})
    {
      VEMDoFHandler<2> by_order(mesh), by_element(mesh);
      by_order.distribute_dofs(k);
      by_element.distribute_dofs(VirtualElement<2>(k));
      bool same = by_order.n_dofs() == by_element.n_dofs();
      std::vector<dealii::types::global_dof_index> a, b;
      for (unsigned int c = 0; c < mesh.n_cells() && same; ++c)
        {
          by_order.get_dof_indices(c, a);
          by_element.get_dof_indices(c, b);
          same = (a == b);
        }
      std::vector<dealii::Point<2>> pa, pb;
      by_order.map_dofs_to_support_points(pa);
      by_element.map_dofs_to_support_points(pb);
      testing::check(same && pa == pb, "k = " + std::to_string(k) +
                                         ": distribute_dofs(element) gives the numbering and support points of "
                                         "distribute_dofs(k)");
    }

  // 3. two nodes per edge: orientation of shared edges
  {
    VEMDoFHandler<2> dofs(mesh);
    const VEMElementData k3(3);
    dofs.distribute_dofs(k3);
    testing::check(dofs.n_dofs() == 2 * (mesh.n_vertices() + 2 * mesh.n_edges() + 3 * mesh.n_cells()),
                   "k = 3 layout: n_dofs = 2 (V + 2 E + 3 C) = " + std::to_string(dofs.n_dofs()));
    std::vector<unsigned int> nodes;
    std::vector<bool>         used(dofs.n_nodes(), false);
    double                    worst    = 0;
    unsigned int              reversed = 0;
    bool                      moments_ok = true;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        dofs.get_node_indices(c, nodes);
        const auto        &cell = mesh.cell(c);
        const unsigned int n    = cell.vertices.size();
        for (const auto node : nodes)
          used[node] = true;
        for (unsigned int i = 0; i < n; ++i)
          {
            reversed += (mesh.edge(cell.edges[i]).vertices[0] != cell.vertices[i]);
            const auto &a = mesh.vertex(cell.vertices[i]), &b = mesh.vertex(cell.vertices[(i + 1) % n]);
            for (unsigned int j = 0; j < 2; ++j)
              {
                const double t = k3.edge_node_positions()[j];
                worst          = std::max(worst, (dofs.node_location(nodes[k3.edge_node(n, i, j)]) -
                                         ((1 - t) * a + t * b)).norm());
              }
          }
        for (unsigned int j = 0; j < 3; ++j)
          moments_ok = moments_ok && dofs.is_moment_node(nodes[k3.cell_node(n, j)]) &&
                       nodes[k3.cell_node(n, j)] == dofs.cell_node(c, j);
      }
    testing::check(moments_ok, "the three moments of each cell are its own moment nodes, in order");
    testing::check(reversed > 0, "the mesh has cells that run along a shared edge against its direction (" +
                                   std::to_string(reversed) + " cell edges)");
    testing::check_small(worst, 4e-15, "every local edge node lies on the cell's own edge parametrisation (2 x 1 "
                                       "domain)");
    testing::check(std::find(used.begin(), used.end(), false) == used.end(), "every node belongs to a cell");
    testing::check_throws([&] { dofs.rigid_body_modes(); }, "at most one moment per cell",
                          "rigid-body modes of three moments per cell are refused");
  }

  // 4. the edge basis, k = 1 to 4: one at its own node and zero at the
  // others, a partition of unity whose derivatives sum to zero, the
  // derivatives against central differences with step 1e-4 (within
  // 1e-8 / 6 times the third derivative, below 1e-6), and the
  // edge stiffness against its closed form for k = 1 and 2 and, for every
  // k, zero on constants and s^T K s = 1 for the trace s (int_0^1 1 ds)
  {
    double worst_kronecker = 0, worst_unity = 0, worst_difference = 0, worst_stiffness = 0;
    for (unsigned int k = 1; k <= 4; ++k)
      {
        const VEMElementData layout(k);
        std::vector<double>  nodes{0.};
        nodes.insert(nodes.end(), layout.edge_node_positions().begin(), layout.edge_node_positions().end());
        nodes.push_back(1.);
        std::vector<double> phi, dphi, plus, minus;
        for (unsigned int a = 0; a <= k; ++a)
          {
            layout.edge_shape_values(nodes[a], phi);
            for (unsigned int b = 0; b <= k; ++b)
              worst_kronecker = std::max(worst_kronecker, std::abs(phi[b] - (a == b ? 1. : 0.)));
          }
        for (const double s : {0.13, 0.5, 0.77})
          {
            layout.edge_shape_values(s, phi);
            layout.edge_shape_derivatives(s, dphi);
            layout.edge_shape_values(s + 1e-4, plus);
            layout.edge_shape_values(s - 1e-4, minus);
            double sum = 0, dsum = 0;
            for (unsigned int a = 0; a <= k; ++a)
              {
                sum += phi[a];
                dsum += dphi[a];
                worst_difference = std::max(worst_difference, std::abs((plus[a] - minus[a]) / 2e-4 - dphi[a]));
              }
            worst_unity = std::max({worst_unity, std::abs(sum - 1), std::abs(dsum)});
          }
        const std::vector<double> &K = layout.edge_stiffness();
        double                     sKs = 0;
        for (unsigned int a = 0; a <= k; ++a)
          {
            double row = 0;
            for (unsigned int b = 0; b <= k; ++b)
              {
                row += K[a * (k + 1) + b];
                sKs += nodes[a] * K[a * (k + 1) + b] * nodes[b];
              }
            worst_stiffness = std::max(worst_stiffness, std::abs(row));
          }
        worst_stiffness = std::max(worst_stiffness, std::abs(sKs - 1));
      }
    testing::check_small(worst_kronecker, 1e-14, "edge basis: one at its node, zero at the others (k = 1 to 4)");
    testing::check_small(worst_unity, 1e-13, "edge basis: a partition of unity, derivatives summing to zero");
    testing::check_small(worst_difference, 1e-6, "edge basis: derivatives against central differences");
    testing::check_small(worst_stiffness, 1e-13, "edge stiffness: zero on constants, 1 on the trace s");
    const std::vector<double> linear{1., -1., -1., 1.},
      quadratic{7. / 3, -8. / 3, 1. / 3, -8. / 3, 16. / 3, -8. / 3, 1. / 3, -8. / 3, 7. / 3};
    double closed_form = 0;
    for (unsigned int i = 0; i < 4; ++i)
      closed_form = std::max(closed_form, std::abs(VEMElementData(1).edge_stiffness()[i] - linear[i]));
    for (unsigned int i = 0; i < 9; ++i)
      closed_form = std::max(closed_form, std::abs(VEMElementData(2).edge_stiffness()[i] - quadratic[i]));
    testing::check_small(closed_form, 4e-15, "edge stiffness of k = 1 and 2 against the closed forms");
    testing::check(VirtualElement<2>::stabilization_rules(1).automatic_is_trace &&
                     !VirtualElement<2>::stabilization_rules(2).automatic_is_trace &&
                     VirtualElement<2>::stabilization_rules(2).diagonal_weight == 0.2 &&
                     VirtualElement<2>::stabilization_rules(2).boundary_edge_divisor == 5.,
                   "the stabilization rules of k = 1 and 2");
  }

  // 5. misuse
  testing::check_throws([] { VEMElementData(0); }, "order k must be at least 1", "order 0 is refused");
  testing::check_throws([] { VirtualElement<2>(3); }, "order k must lie in 1 to 2, got 3",
                        "VirtualElement of order 3 is refused");
  testing::check_throws([] { VirtualElement<2>::stabilization_rules(3); }, "no stabilization rules for the order 3",
                        "stabilization rules of order 3 are refused");
  return testing::finish();
}
