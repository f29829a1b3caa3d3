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

    /**
     * The weights on [0, 1] of the (k + 1)-point Gauss-Lobatto rule whose
     * points are the nodes of an edge: the first vertex, the edge nodes of
     * edge_node_positions(), the second vertex, in this order. Multiplied by
     * the edge length they integrate a trace over an edge from its nodal
     * values, exactly for polynomials of degree up to 2k - 1: the
     * trapezoidal rule (1/2, 1/2) for k = 1, Simpson's rule (1/6, 2/3, 1/6)
     * for k = 2. The weights sum to one.
     */
    const std::vector<double> &
    edge_quadrature_weights() const
    {
      return edge_weights;
    }

    /**
     * The Lagrange basis of the trace on an edge: the polynomials of degree
     * k that are one at one node of the edge and zero at the others, the
     * nodes in the order of edge_quadrature_weights() (first vertex, edge
     * nodes, second vertex). @p s is the fraction in [0, 1] of the edge's
     * length from its first vertex; @p values gets k + 1 entries. The trace
     * of every function of the space on an edge is a polynomial of degree k,
     * so these interpolate it exactly: (1 - s, s) for k = 1.
     */
    void
    edge_shape_values(const double s, std::vector<double> &values) const;

    /// The derivatives of edge_shape_values() with respect to @p s (per unit
    /// fraction of the edge; divide by the edge length for d/dx along it).
    void
    edge_shape_derivatives(const double s, std::vector<double> &derivatives) const;

    /**
     * The stiffness of d/ds on an edge of unit length in the edge basis,
     * $\int_0^1 \phi_a'(s)\,\phi_b'(s)\,ds$, row-major (k + 1) x (k + 1),
     * computed once by the k-point Gauss rule (exact: the integrand has
     * degree 2k - 2). ElasticityOperator's boundary stabilization sums it
     * over the edges.
     */
    const std::vector<double> &
    edge_stiffness() const
    {
      return edge_stiffness_matrix;
    }

    /**
     * The kind of entity a local node belongs to: a vertex, the interior of
     * an edge, or the interior of the cell (a moment).
     */
    enum class NodeKind
    {
      /// The point value at a vertex.
      vertex,
      /// A point value inside an edge (edge_node_positions()).
      edge,
      /// A moment of the cell.
      cell
    };

    /**
     * The kind of local node @p node of a cell with @p n_vertices vertices,
     * from the local order described in the class documentation.
     */
    NodeKind
    node_kind(const unsigned int n_vertices, const unsigned int node) const
    {
      if (node < n_vertices)
        return NodeKind::vertex;
      if (node < n_vertices * (1 + nodes_per_edge()))
        return NodeKind::edge;
      return NodeKind::cell;
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
    std::vector<double> edge_weights;
    // the nodes of an edge on [0, 1] (0, the edge positions, 1), and the
    // matrix of edge_stiffness()
    std::vector<double> edge_nodes;
    std::vector<double> edge_stiffness_matrix;
  };
} // namespace dealvem

#endif
