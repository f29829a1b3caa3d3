// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_vem_vem_element_data_h
#define dealvem_vem_vem_element_data_h

#include <string>
#include <vector>

namespace dealvem
{
  /**
   * The layout of the degrees of freedom of the order-k virtual element
   * space on a polygon, in the role deal.II's FiniteElementData plays for a
   * finite element: how many nodes sit on each vertex, on each edge and
   * inside each cell, where the edge nodes lie, and in which order a cell
   * lists its nodes. Every node carries the two displacement components
   * (DoFs 2 j and 2 j + 1 of local node j).
   *
   * For order k the space has
   * - one node per vertex (the point value),
   * - k - 1 nodes per edge, the interior Gauss-Lobatto points of the edge
   *   (the midpoint for k = 2),
   * - k (k - 1) / 2 nodes per cell, the moments against the scaled
   *   monomials of degree at most k - 2 (one, the cell average, for k = 2).
   *
   * A cell with n vertices numbers its local nodes as VirtualElement does:
   * the vertices in counter-clockwise order, then the edge nodes edge by edge
   * (edge i runs from vertex i to vertex i + 1, its nodes in that direction),
   * then the cell moments. VEMDoFHandler enumerates the global nodes from
   * this description alone, so a new degree changes this class and the
   * element's projector, not the handler. (VirtualElement itself implements
   * k = 1 and 2.)
   */
  class VEMElementData
  {
  public:
    /// The layout of the order-@p degree space (AssertThrow for 0).
    explicit VEMElementData(const unsigned int degree);

    /// The order k.
    unsigned int
    get_degree() const
    {
      return degree;
    }

    /// Displacement components per node (2).
    static constexpr unsigned int
    n_components()
    {
      return 2;
    }

    /// Nodes on each vertex (1).
    unsigned int
    nodes_per_vertex() const
    {
      return 1;
    }

    /// Nodes inside each edge (k - 1).
    unsigned int
    nodes_per_edge() const
    {
      return degree - 1;
    }

    /// Moment nodes inside each cell (k (k - 1) / 2).
    unsigned int
    nodes_per_cell() const
    {
      return degree * (degree - 1) / 2;
    }

    /// The positions of the edge nodes along an edge, as fractions in (0, 1)
    /// of its length from its first vertex, in increasing order.
    const std::vector<double> &
    edge_node_positions() const
    {
      return edge_positions;
    }

    /// Local nodes of a cell with @p n_vertices vertices.
    unsigned int
    n_nodes(const unsigned int n_vertices) const
    {
      return n_vertices * (1 + nodes_per_edge()) + nodes_per_cell();
    }

    /// Local DoFs of a cell with @p n_vertices vertices.
    unsigned int
    n_dofs_per_cell(const unsigned int n_vertices) const
    {
      return n_components() * n_nodes(n_vertices);
    }

    /// The local node of the @p j-th node inside edge @p e of a cell with
    /// @p n_vertices vertices (counted from vertex e towards vertex e + 1).
    unsigned int
    edge_node(const unsigned int n_vertices, const unsigned int e, const unsigned int j) const
    {
      return n_vertices + e * nodes_per_edge() + j;
    }

    /// The local node of the @p j-th moment of a cell with @p n_vertices
    /// vertices.
    unsigned int
    cell_node(const unsigned int n_vertices, const unsigned int j) const
    {
      return n_vertices * (1 + nodes_per_edge()) + j;
    }

    /// "VEM<2>(k)", in the style of FiniteElement::get_name().
    std::string
    get_name() const;

  private:
    unsigned int        degree;
    std::vector<double> edge_positions;
  };
} // namespace dealvem

#endif
