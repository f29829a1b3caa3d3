// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_mesh_connected_pieces_h
#define dealvem_mesh_connected_pieces_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <dealvem/mesh/polygonal_mesh.h>

#include <string>
#include <vector>

namespace dealvem
{
  /**
   * The edge-connected pieces of a PolygonalMesh: two cells belong to the
   * same piece when a chain of cells, each sharing an edge with the next,
   * joins them. Cells that touch at a vertex only (a hinge) are not
   * connected, and cells of different material ids (bodies) never share an
   * edge, so every piece lies in one body.
   *
   * A piece is the unit that must be held against rigid-body motion: the
   * stiffness of a piece has the three rigid-body modes of the piece in its
   * kernel whatever the rest of its body does (BoundaryConditions::
   * check_rigid_body_support(), RigidBodySupport).
   *
   * The pieces come from a union-find over the interior edges, O(n_edges).
   * Under MPI every process holds the whole (replicated) mesh, so every
   * process computes the same pieces without communication.
   */
  class ConnectedPieces
  {
  public:
    /// Find the pieces of @p mesh (which must be finalized).
    explicit ConnectedPieces(const PolygonalMesh<2> &mesh);

    /// The number of pieces, over all bodies.
    unsigned int
    n_pieces() const
    {
      return cells_in_piece.size();
    }

    /// The piece of cell @p c.
    unsigned int
    piece_of_cell(const unsigned int c) const
    {
      return cell_piece[c];
    }

    /// The body (material id) of piece @p p.
    dealii::types::material_id
    body(const unsigned int p) const
    {
      return piece_body[p];
    }

    /// The number of pieces of body @p b.
    unsigned int
    n_pieces_of_body(const dealii::types::material_id b) const;

    /// The index of piece @p p among the pieces of its body (0, 1, ...: in
    /// the order of their lowest cell index).
    unsigned int
    index_in_body(const unsigned int p) const
    {
      return piece_index_in_body[p];
    }

    /// The number of cells of piece @p p.
    unsigned int
    n_cells(const unsigned int p) const
    {
      return cells_in_piece[p];
    }

    /// The lowest cell index of piece @p p.
    unsigned int
    first_cell(const unsigned int p) const
    {
      return piece_first_cell[p];
    }

    /// Area centroid of piece @p p.
    const dealii::Point<2> &
    centroid(const unsigned int p) const
    {
      return piece_centroid[p];
    }

    /// Largest distance of a vertex of piece @p p from its centroid.
    double
    size(const unsigned int p) const
    {
      return piece_size[p];
    }

    /// Lower left and upper right corner of the bounding box of piece @p p.
    const std::pair<dealii::Point<2>, dealii::Point<2>> &
    bounding_box(const unsigned int p) const
    {
      return piece_box[p];
    }

    /**
     * "piece 1 of body 0 (4 cells; cell 37, centroid (2.5, 0.5); bounding
     * box [2, 3] x [0, 1])": what a message names. The cell is the piece's
     * first, numbered among the cells of its body (as in the body's mesh).
     */
    std::string
    describe(const unsigned int p) const;

  private:
    std::vector<unsigned int>                                  cell_piece;
    std::vector<dealii::types::material_id>                    piece_body;
    std::vector<unsigned int>                                  piece_index_in_body;
    std::vector<unsigned int>                                  cells_in_piece;
    std::vector<unsigned int>                                  piece_first_cell;
    std::vector<unsigned int>                                  piece_first_cell_in_body;
    std::vector<dealii::Point<2>>                              piece_centroid;
    std::vector<double>                                        piece_size;
    std::vector<std::pair<dealii::Point<2>, dealii::Point<2>>> piece_box;
  };
} // namespace dealvem

#endif
