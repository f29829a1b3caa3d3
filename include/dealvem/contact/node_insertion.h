// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_node_insertion_h
#define dealvem_contact_node_insertion_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <dealvem/mesh/polygonal_mesh.h>

#include <string>
#include <vector>

namespace dealvem
{
  /**
   * One node-to-node contact pair on a matched interface.
   *
   * The master side gives the normal: $n$ is the outward unit normal of the
   * master body at the master node (for a vertex between two master edges
   * the normalized average of their normals), $t = (-n_y, n_x)$. The gap
   * $g = (u_B - u_A)\cdot n + g_0$ with $g_0 = (x_B - x_A)\cdot n$, A =
   * master, B = slave; $g \ge 0$ means the bodies do not penetrate.
   *
   * Nodes are mesh entities: a vertex (is_midpoint = false, entity = vertex
   * index) or, for k = 2, the midpoint of an edge (is_midpoint = true,
   * entity = edge index).
   */
  struct ContactNodePair
  {
    unsigned int           master_entity;
    unsigned int           slave_entity;
    bool                   is_midpoint = false;
    dealii::Point<2>       master_location;
    dealii::Point<2>       slave_location;
    dealii::Tensor<1, 2>   normal;
    dealii::Tensor<1, 2>   tangent;
    double                 initial_gap = 0;
    /// Tributary weight (length) of the node on the interface: the sum over
    /// the slave sub-edges at the node of L/2 (k = 1) or L/6 at an end and
    /// 2L/3 at the midpoint (k = 2, Simpson).
    double                 weight = 0;
    /// Index of the contact pair description this node pair belongs to.
    unsigned int           interface = 0;
  };

  /**
   * Node insertion on the contact interface between two bodies of one
   * PolygonalMesh (see DESIGN.md, "Node insertion and node-to-node
   * contact").
   *
   * A contact interface names a boundary part of the master body (boundary
   * id @p master_id) and one of the slave body (@p slave_id). The vertices
   * of each side are projected onto the other side's edges (closest point);
   * a projection is used if its distance is at most @p search_distance
   * times the length of the edge it lands on. A projection that lands
   * within @p snap_tolerance times the edge length of an existing vertex
   * snaps to it; otherwise the edge is split there (PolygonalMesh::split_edge)
   * and the polygon owning it gains a vertex. After both passes both sides
   * carry the same vertices along the overlapping part of the interface
   * (and, for k = 2, the same sub-edge midpoints), so every node there has
   * exactly one partner. Parts of the interface without a counterpart
   * within the search distance (partial overlap) get no pairs.
   */
  class NodeInsertion
  {
  public:
    struct Settings
    {
      /// Snap tolerance relative to the edge length (0 < tol < 0.5).
      double snap_tolerance = 1e-6;
      /// Largest normal distance of a projection, relative to the length of
      /// the edge it lands on (for curved interfaces with initial gaps).
      double search_distance = 0.5;
    };

    /// What insert() did.
    struct Report
    {
      unsigned int n_inserted_master = 0; ///< new vertices on the master side
      unsigned int n_inserted_slave  = 0; ///< new vertices on the slave side
      unsigned int n_snapped         = 0; ///< projections snapped to existing vertices
      unsigned int n_master_edges    = 0; ///< master interface edges after insertion
      unsigned int n_slave_edges     = 0; ///< slave interface edges after insertion
    };

    /**
     * Make the interface (master_id, slave_id) matching by inserting
     * vertices into @p mesh. Throws (AssertThrow, naming the ids) if a
     * boundary id has no edges, if both ids belong to the same body, or if
     * the two parts do not face or overlap each other at all (no projection
     * within the search distance).
     */
    static Report
    insert(PolygonalMesh<2>                &mesh,
           const dealii::types::boundary_id master_id,
           const dealii::types::boundary_id slave_id,
           const Settings                  &settings);

    /**
     * The node pairs of a matched interface for order @p degree (1: vertex
     * pairs; 2: vertex and midpoint pairs). Slave nodes whose partner is
     * not found (outside the overlap) are skipped. @p interface is stored
     * in the pairs.
     */
    static std::vector<ContactNodePair>
    make_pairs(const PolygonalMesh<2>          &mesh,
               const dealii::types::boundary_id master_id,
               const dealii::types::boundary_id slave_id,
               const unsigned int               degree,
               const Settings                  &settings,
               const unsigned int               interface = 0);
  };
} // namespace dealvem

#endif
