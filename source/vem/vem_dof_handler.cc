// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <dealvem/vem/polygon_geometry.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/virtual_element.h>

namespace dealvem
{
  template <int dim>
  VEMDoFHandler<dim>::VEMDoFHandler(const PolygonalMesh<dim> &mesh)
  {
    reinit(mesh);
  }



  template <int dim>
  void
  VEMDoFHandler<dim>::reinit(const PolygonalMesh<dim> &m)
  {
    mesh          = &m;
    degree        = 0;
    n_dofs_       = 0;
    mesh_revision = 0;
  }



  template <int dim>
  void
  VEMDoFHandler<dim>::check_mesh_unchanged() const
  {
    AssertThrow(mesh != nullptr && degree != 0, ExcNoDoFsDistributed());
    AssertThrow(mesh->get_revision() == mesh_revision,
                ExcMeshChangedAfterDistributeDofs(mesh->name, mesh->get_last_change()));
  }



  template <int dim>
  void
  VEMDoFHandler<dim>::distribute_dofs(const unsigned int k)
  {
    AssertThrow(mesh != nullptr, dealii::ExcMessage("VEMDoFHandler: no mesh attached; call reinit(mesh) first."));
    // the layout of every order is numbered alike; the element checks the
    // orders it implements (VirtualElement::max_degree())
    AssertThrow(k >= 1 && k <= VirtualElement<dim>::max_degree(),
                dealii::ExcMessage("VEMDoFHandler: the order must lie in 1 to " +
                                   std::to_string(VirtualElement<dim>::max_degree()) + ", got " + std::to_string(k) +
                                   "."));
    distribute_dofs(VEMElementData(k));
  }



  template <int dim>
  void
  VEMDoFHandler<dim>::distribute_dofs(const VirtualElement<dim> &element)
  {
    distribute_dofs(element.get_element_data());
  }



  template <int dim>
  void
  VEMDoFHandler<dim>::distribute_dofs(const VEMElementData &layout)
  {
    AssertThrow(mesh != nullptr, dealii::ExcMessage("VEMDoFHandler: no mesh attached; call reinit(mesh) first."));
    AssertThrow(mesh->n_edges() > 0 || mesh->n_cells() == 0,
                dealii::ExcMessage("VEMDoFHandler: the mesh '" + mesh->name +
                                   "' has no edges; call finalize() first."));
    data           = layout;
    degree         = layout.get_degree();
    mesh_revision  = mesh->get_revision();
    n_vertex_nodes = mesh->n_vertices();
    n_edge_nodes   = layout.nodes_per_edge() * mesh->n_edges();
    const unsigned int n_cell_nodes = layout.nodes_per_cell() * mesh->n_cells();
    n_dofs_ = 2 * dealii::types::global_dof_index(n_vertex_nodes + n_edge_nodes + n_cell_nodes);

    cell_centroids.resize(mesh->n_cells());
    for (unsigned int c = 0; c < mesh->n_cells(); ++c)
      cell_centroids[c] = PolygonGeometry<dim>(mesh->cell_vertices(c)).centroid();
  }



  template <int dim>
  unsigned int
  VEMDoFHandler<dim>::n_dofs_per_cell(const unsigned int c) const
  {
    check_mesh_unchanged();
    return data.n_dofs_per_cell(mesh->cell(c).vertices.size());
  }



  template <int dim>
  unsigned int
  VEMDoFHandler<dim>::edge_node(const unsigned int e) const
  {
    Assert(data.nodes_per_edge() == 1, dealii::ExcMessage("Edge midpoint nodes exist for k = 2 only."));
    return n_vertex_nodes + e;
  }



  template <int dim>
  unsigned int
  VEMDoFHandler<dim>::edge_node(const unsigned int e, const unsigned int j) const
  {
    Assert(j < data.nodes_per_edge(), dealii::ExcIndexRange(j, 0, data.nodes_per_edge()));
    return n_vertex_nodes + e * data.nodes_per_edge() + j;
  }



  template <int dim>
  unsigned int
  VEMDoFHandler<dim>::cell_node(const unsigned int c) const
  {
    Assert(data.nodes_per_cell() == 1, dealii::ExcMessage("Cell nodes exist for k = 2 only."));
    return n_vertex_nodes + n_edge_nodes + c;
  }



  template <int dim>
  unsigned int
  VEMDoFHandler<dim>::cell_node(const unsigned int c, const unsigned int j) const
  {
    Assert(j < data.nodes_per_cell(), dealii::ExcIndexRange(j, 0, data.nodes_per_cell()));
    return n_vertex_nodes + n_edge_nodes + c * data.nodes_per_cell() + j;
  }



  template <int dim>
  bool
  VEMDoFHandler<dim>::is_moment_node(const unsigned int node) const
  {
    return node >= n_vertex_nodes + n_edge_nodes;
  }



  template <int dim>
  dealii::Point<dim>
  VEMDoFHandler<dim>::node_location(const unsigned int node) const
  {
    check_mesh_unchanged();
    if (node < n_vertex_nodes)
      return mesh->vertex(node);
    if (node < n_vertex_nodes + n_edge_nodes)
      {
        const unsigned int per_edge = data.nodes_per_edge();
        const auto        &e        = mesh->edge((node - n_vertex_nodes) / per_edge);
        const double       t        = data.edge_node_positions()[(node - n_vertex_nodes) % per_edge];
        const auto        &a = mesh->vertex(e.vertices[0]), &b = mesh->vertex(e.vertices[1]);
        return t == 0.5 ? 0.5 * (a + b) : (1 - t) * a + t * b;
      }
    return cell_centroids[(node - n_vertex_nodes - n_edge_nodes) / data.nodes_per_cell()];
  }



  template <int dim>
  template <typename F>
  void
  VEMDoFHandler<dim>::for_each_node(const unsigned int c, const F &f) const
  {
    const auto        &cell = mesh->cell(c);
    const unsigned int n    = cell.vertices.size();
    const unsigned int per_edge = data.nodes_per_edge(), per_cell = data.nodes_per_cell();
    for (unsigned int i = 0; i < n; ++i)
      f(i, vertex_node(cell.vertices[i]));
    for (unsigned int i = 0; i < n; ++i)
      {
        // the cell runs along its edge i from its vertex i; the mesh's edge
        // may run the other way, and its nodes are counted from its first
        // vertex
        const unsigned int e        = cell.edges[i];
        const bool         reversed = per_edge > 1 && (mesh->edge(e).vertices[0] != cell.vertices[i]);
        for (unsigned int j = 0; j < per_edge; ++j)
          f(data.edge_node(n, i, j), edge_node(e, reversed ? per_edge - 1 - j : j));
      }
    for (unsigned int j = 0; j < per_cell; ++j)
      f(data.cell_node(n, j), cell_node(c, j));
  }



  template <int dim>
  void
  VEMDoFHandler<dim>::get_node_indices(const unsigned int         c,
                                       std::vector<unsigned int> &nodes) const
  {
    check_mesh_unchanged();
    nodes.resize(n_dofs_per_cell(c) / 2);
    for_each_node(c, [&](const unsigned int j, const unsigned int node) { nodes[j] = node; });
  }



  template <int dim>
  void
  VEMDoFHandler<dim>::get_dof_indices(
    const unsigned int                            c,
    std::vector<dealii::types::global_dof_index> &indices) const
  {
    check_mesh_unchanged();
    indices.resize(n_dofs_per_cell(c));
    for_each_node(c, [&](const unsigned int j, const unsigned int node) {
      indices[2 * j]     = node_dof(node, 0);
      indices[2 * j + 1] = node_dof(node, 1);
    });
  }



  template <int dim>
  void
  VEMDoFHandler<dim>::get_dof_values(const unsigned int            c,
                                     const dealii::Vector<double> &global,
                                     dealii::Vector<double>       &local) const
  {
    std::vector<dealii::types::global_dof_index> indices;
    get_dof_indices(c, indices);
    local.reinit(indices.size());
    for (unsigned int i = 0; i < indices.size(); ++i)
      local[i] = global[indices[i]];
  }



  template <int dim>
  void
  VEMDoFHandler<dim>::map_dofs_to_support_points(std::vector<dealii::Point<dim>> &points) const
  {
    check_mesh_unchanged();
    points.resize(n_dofs_);
    for (unsigned int node = 0; node < n_nodes(); ++node)
      points[2 * node] = points[2 * node + 1] = node_location(node);
  }



  template <int dim>
  std::vector<unsigned int>
  VEMDoFHandler<dim>::boundary_nodes(const std::set<dealii::types::boundary_id> &ids) const
  {
    check_mesh_unchanged();
    std::vector<unsigned int> nodes;
    for (unsigned int e = 0; e < mesh->n_edges(); ++e)
      {
        const auto &edge = mesh->edge(e);
        if (!edge.at_boundary() || ids.count(edge.boundary_id) == 0)
          continue;
        nodes.push_back(vertex_node(edge.vertices[0]));
        nodes.push_back(vertex_node(edge.vertices[1]));
        for (unsigned int j = 0; j < data.nodes_per_edge(); ++j)
          nodes.push_back(edge_node(e, j));
      }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return nodes;
  }



  template <int dim>
  void
  VEMDoFHandler<dim>::make_sparsity_pattern(dealii::DynamicSparsityPattern &dsp) const
  {
    check_mesh_unchanged();
    std::vector<dealii::types::global_dof_index> indices;
    for (unsigned int c = 0; c < mesh->n_cells(); ++c)
      {
        get_dof_indices(c, indices);
        std::vector<dealii::types::global_dof_index> sorted = indices;
        std::sort(sorted.begin(), sorted.end());
        for (const auto i : indices)
          dsp.add_entries(i, sorted.begin(), sorted.end(), true);
      }
  }



  template <int dim>
  void
  VEMDoFHandler<dim>::make_sparsity_pattern(dealii::DynamicSparsityPattern          &dsp,
                                            const dealii::AffineConstraints<double> &constraints,
                                            const bool keep_constrained_dofs) const
  {
    check_mesh_unchanged();
    std::vector<dealii::types::global_dof_index> indices;
    for (unsigned int c = 0; c < mesh->n_cells(); ++c)
      {
        get_dof_indices(c, indices);
        constraints.add_entries_local_to_global(indices, dsp, keep_constrained_dofs);
      }
  }



  template <int dim>
  std::vector<std::vector<double>>
  VEMDoFHandler<dim>::rigid_body_modes() const
  {
    check_mesh_unchanged();
    AssertThrow(data.nodes_per_cell() <= 1,
                dealii::ExcMessage("VEMDoFHandler::rigid_body_modes(): implemented for at most one moment per "
                                   "cell (k <= 2); the layout has " +
                                   std::to_string(data.nodes_per_cell()) + "."));
    std::vector<std::vector<double>> modes(3, std::vector<double>(n_dofs_, 0.));
    for (unsigned int node = 0; node < n_nodes(); ++node)
      {
        // For moment nodes the average of a linear field over the cell is its
        // value at the centroid: node_location() returns the centroid.
        const dealii::Point<dim> x = node_location(node);
        modes[0][2 * node]         = 1.;
        modes[1][2 * node + 1]     = 1.;
        modes[2][2 * node]         = -x[1];
        modes[2][2 * node + 1]     = x[0];
      }
    return modes;
  }

  template class VEMDoFHandler<2>;
} // namespace dealvem
