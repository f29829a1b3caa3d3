// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_piece_support_h
#define dealvem_elasticity_piece_support_h

#include <deal.II/base/types.h>

#include <dealvem/mesh/connected_pieces.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace dealvem
{
  /**
   * The rigid-body modes of the edge-connected pieces of a mesh
   * (ConnectedPieces) and the rank test that tells which of them a set of
   * linear restrictions leaves free.
   *
   * Piece p has three modes: the translations in x and y and the rotation
   * about its area centroid $\bar x_p$, scaled by its size $s_p$:
   * $r_{p,2}(x) = (-(y - \bar y_p), x - \bar x_p)/s_p$. A linear form
   * $\sum_d c_d u_d$ (a constraint line $u_i - \sum_j a_{ij} u_j$, or a
   * contact row) restricts the modes by its values on them, one row of
   * 3 n_pieces numbers. A node shared by two pieces (a hinge vertex) carries
   * the modes of both; a form through it gives one row per piece there, so
   * that a support at a hinge holds each piece and a hinge alone couples
   * nothing. A form that every rigid motion of the pieces satisfies (the
   * lines of a rigid boundary part) restricts nothing and gives no row.
   *
   * free_motions(): the pieces are held when the rows have full rank
   * 3 n_pieces. Each piece whose own rows (those touching it alone) have
   * rank 3 is held whatever the others do and drops out; the rest are
   * tested together through the eigenvalues of the Gram matrix of the rows
   * (a motion is free when its eigenvalue is below 1e-10 times the largest),
   * so the dense part stays as small as the pieces held only by others
   * (through contact).
   */
  class PieceSupport
  {
  public:
    /// A sparse row over the 3 n_pieces modes (mode 3 p + k).
    using Row = std::vector<std::pair<unsigned int, double>>;
    /// A linear form over displacement DoFs.
    using Form = std::vector<std::pair<dealii::types::global_dof_index, double>>;

    /// The pieces of @p dof_handler's mesh and, per node, the pieces whose
    /// cells use it. @p dof_handler needs distributed DoFs and is held by
    /// reference: it must outlive this object.
    explicit PieceSupport(const VEMDoFHandler<2> &dof_handler);

    /// The edge-connected pieces of the mesh.
    const ConnectedPieces &
    get_pieces() const
    {
      return pieces;
    }

    /// Number of rigid-body modes, 3 n_pieces (mode 3 p + k of piece p:
    /// k = 0, 1 the translations, k = 2 the scaled rotation).
    unsigned int
    n_modes() const
    {
      return 3 * pieces.n_pieces();
    }

    /// The value of mode k of piece p at the displacement DoF @p dof.
    double
    mode(const unsigned int p, const unsigned int k, const dealii::types::global_dof_index dof) const;

    /// The pieces whose cells use node @p node.
    const std::vector<unsigned int> &
    pieces_of_node(const unsigned int node) const
    {
      return node_pieces[node];
    }

    /// Append the rows by which @p form restricts the modes to @p rows.
    void
    add_rows(const Form &form, std::vector<Row> &rows) const;

    /// The free motions left by @p rows, each as the modes (3 p + k) it
    /// moves noticeably (eigenvector entries above 1e-3); empty when every
    /// piece is held.
    std::vector<std::vector<unsigned int>>
    free_motions(const std::vector<const Row *> &rows) const;

    /**
     * The free motions as text: "[x-translation + rotation]" when
     * @p with_body is false (one body), "[x-translation of body 1]" when
     * true; a body of several pieces adds ", piece i" to each name and
     * describe_pieces() the pieces named.
     */
    std::string
    describe(const std::vector<std::vector<unsigned int>> &motions, const bool with_body) const;

    /// The pieces that @p motions move, described (ConnectedPieces::describe),
    /// when their body has several pieces; empty otherwise.
    std::string
    describe_pieces(const std::vector<std::vector<unsigned int>> &motions) const;

    /// For the pieces that @p motions move: where they touch another piece
    /// at a vertex only ("piece 1 of body 0 touches piece 0 at the vertex
    /// (1, 1) only: a hinge, not a connection."); empty if nowhere.
    std::string
    describe_hinges(const std::vector<std::vector<unsigned int>> &motions) const;

  private:
    ConnectedPieces                        pieces;
    const VEMDoFHandler<2>                &dof_handler;
    std::vector<std::vector<unsigned int>> node_pieces;
  };
} // namespace dealvem

#endif
