// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_mesh_masonry_wall_h
#define dealvem_mesh_masonry_wall_h

#include <dealvem/mesh/polygonal_mesh.h>

namespace dealvem
{
  namespace PolygonalMeshGenerators
  {
    /**
     * A dry-stone wall: rectangular blocks in courses of running bond on a
     * base, every block meshed on its own (structured quads), so that
     * neighbouring blocks meet along non-matching joints. The result is a
     * mesh of parts (material id 0 the base, 1, 2, ... the blocks in the
     * order they are laid: course by course from the bottom, left to right)
     * for ContactProblem::add_parts() and contact detection.
     *
     * Course c (from 0) lies in [c h, (c + 1) h] with h = block_height.
     * Even courses hold blocks_per_course blocks of width w = block_width
     * from x = 0; odd courses start and end with a half block and hold
     * blocks_per_course - 1 full blocks between. Courses are laid until
     * n_blocks pieces (a half block counts as one) are placed; the last
     * course may be incomplete, filled from the left.
     *
     * Block j (its material id) gets quads_along quads along its length if
     * j is even and quads_along + 1 if it is odd (the joints do not match);
     * a half block gets half of them (at least one) when scale_half_blocks
     * is true, else as many as a full block. Across: quads_across quads (0:
     * half of the block's quads along, at least one). The base is the
     * rectangle [-w, (blocks_per_course + 1) w] x [-1, 0] with
     * base_quads_along (0: 4 (blocks_per_course + 2)) by base_quads_across
     * quads. Boundary ids: the base's are those of structured_quads() (0
     * left, 1 right, 2 bottom, 3 top); a block's are those plus
     * block_boundary_offset.
     */
    struct MasonryWall
    {
      /// Full blocks in an even course.
      unsigned int blocks_per_course = 10;
      /// Pieces to lay (full and half blocks).
      unsigned int n_blocks = 100;
      /// The length of a full block.
      double block_width = 1.0;
      /// The height of a course.
      double block_height = 0.5;
      /// Quads along a full block with an even material id (one more for an
      /// odd id).
      unsigned int quads_along = 6;
      /// Quads across a block; 0: half the quads along (at least one).
      unsigned int quads_across = 0;
      /// Whether a half block gets half the quads along of a full one.
      bool scale_half_blocks = true;
      /// Quads along the base; 0: 4 (blocks_per_course + 2).
      unsigned int base_quads_along = 0;
      /// Quads across the base.
      unsigned int base_quads_across = 4;
      /// Added to the boundary ids of the blocks (structured_quads()'s 0 to
      /// 3), keeping them apart from the base's.
      dealii::types::boundary_id block_boundary_offset = 10;
    };

    /**
     * Fill @p mesh with the wall described by @p wall (see MasonryWall).
     * Throws, naming the parameter, if a count is zero, a size is not
     * positive and finite, or the block ids would overlap the base's
     * (block_boundary_offset < 4).
     */
    void
    masonry_wall(PolygonalMesh<2> &mesh, const MasonryWall &wall);
  } // namespace PolygonalMeshGenerators
} // namespace dealvem

#endif
