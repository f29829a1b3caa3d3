// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_rigid_body_support_h
#define dealvem_contact_rigid_body_support_h

#include <deal.II/lac/affine_constraints.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <memory>
#include <string>
#include <vector>

namespace dealvem
{
  class PieceSupport;

  /**
   * Which rigid-body motions of the bodies the displacement constraints and
   * a set of closed contact pairs hold.
   *
   * Every edge-connected piece of a body (ConnectedPieces: cells joined
   * through shared edges; a body is usually one piece) has three rigid-body
   * modes: the two translations and the rotation about its centroid
   * (scaled by its size). A piece is held by its own constraints or by
   * contact (PieceSupport has the rank test).
   * A constraint line, or the normal (and, with tangential stick, the
   * tangential) row of a closed contact pair, restricts the modes by its
   * values on them; the bodies are held when the restrictions have full
   * rank 3 n_bodies (the Gram matrix of the restrictions has no eigenvalue
   * below 1e-10 times its largest one). Only closed (active) pairs count:
   * an open pair transmits nothing.
   *
   * The contact solver uses this to start from a set of pairs that holds
   * every body (close_smallest_gaps(): bodies that start apart) and to
   * stop with a clear message when the active set would let a body fly off
   * (no static equilibrium under the load).
   */
  class RigidBodySupport
  {
  public:
    /// The supports of the bodies of @p dof_handler's mesh (material id =
    /// body) by the displacement @p constraints and the contact pairs of
    /// @p contact; with @p tangential_stick a closed pair also holds the
    /// tangential direction.
    RigidBodySupport(const VEMDoFHandler<2>                  &dof_handler,
                     const dealii::AffineConstraints<double> &constraints,
                     const ContactAssembler<2>               &contact,
                     const bool                               tangential_stick);

    ~RigidBodySupport();

    /// The free rigid-body motions with the closed pairs @p closed (one
    /// entry per pair), as a readable list "[y-translation of body 1] ...";
    /// empty when every body is held.
    std::string
    free_motions(const std::vector<bool> &closed) const;

    /**
     * As above, but the tangential row of a closed pair counts only where
     * @p tangential_held is true (friction: a sticking pair holds the
     * tangential direction, a slipping one does not). Needs an object built
     * with @p tangential_stick = true.
     */
    std::string
    free_motions(const std::vector<bool> &closed, const std::vector<bool> &tangential_held) const;

    /// Whether every body is held with the closed pairs @p closed.
    bool
    holds(const std::vector<bool> &closed) const
    {
      return free_motions(closed).empty();
    }

    /**
     * Close further pairs, in the order of increasing initial gap (pairs
     * with equal gaps, to 1e-9 of the largest gap, together), until every
     * body is held or every pair is closed. This is the contact that a
     * rigid approach of the bodies makes first. Returns the number of pairs
     * closed.
     */
    unsigned int
    close_smallest_gaps(std::vector<bool> &closed) const;

    /// The number of bodies (material ids) of the mesh.
    unsigned int
    n_bodies() const
    {
      return n_body;
    }

  private:
    unsigned int                  n_body;
    std::unique_ptr<PieceSupport> pieces;
    /// The restrictions of the piece modes by the constraint lines.
    std::vector<std::vector<std::pair<unsigned int, double>>> constraint_rows;
    /// Per pair, per direction (normal, tangential), its rows (more than
    /// one where a node is a hinge between pieces).
    std::vector<std::vector<std::vector<std::vector<std::pair<unsigned int, double>>>>> pair_rows;
    std::vector<double>                            initial_gaps;
  };
} // namespace dealvem

#endif
