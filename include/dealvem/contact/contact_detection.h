// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_contact_detection_h
#define dealvem_contact_contact_detection_h

#include <deal.II/base/types.h>

#include <dealvem/mesh/polygonal_mesh.h>

#include <set>
#include <string>
#include <vector>

namespace dealvem
{
  /**
   * Automatic detection of the contact interfaces of an assembly: the
   * boundary parts of different bodies (material ids) of one mesh that face
   * each other, each given a boundary id of its own so that node insertion
   * (NodeInsertion::insert()) can make it matching.
   *
   * The rule, for boundary edges e (body A) and f (body B != A) whose
   * boundary id is not excluded (ids that carry boundary conditions or
   * explicit contact pairs are never taken):
   * 1. <b>Facing.</b> e and f face each other when their outward normals
   *    are more than Settings::max_angle apart from opposite (n_e . n_f <=
   *    -cos(max_angle)), the distance between the two segments is at most
   *    Settings::distance times the longer of the two edges (the distance
   *    follows the meshes: a gap or an overlap is accepted up to a fraction
   *    of the local edge length), and the projections of the two edges onto
   *    each other's lines overlap over more than Settings::min_overlap times
   *    the shorter edge (two blocks that touch at a corner only do not face).
   *    Candidates are found with an R-tree of the edges' boxes, so the cost
   *    is O(n log n) in the number of boundary edges.
   * 2. <b>One body per edge.</b> An edge that faces edges of several bodies
   *    (the top of a block under two blocks in running bond) is split where
   *    the facing ranges of the bodies meet (PolygonalMesh::split_edge(), a
   *    new vertex of the polygon: virtual elements allow it), unless the
   *    split point lies within Settings::merge_fraction of an end; each
   *    piece then faces one body, the body it overlaps most.
   * 3. <b>Interfaces.</b> The edges of A facing B form chains (consecutive
   *    edges sharing a vertex), broken at corners where the boundary turns
   *    by more than Settings::corner_angle. Chains of A and of B that face
   *    each other are joined into one interface (union-find): the three
   *    faces of a tenon in its mortise are three interfaces, a ring in a
   *    hole is one.
   * 4. <b>Master.</b> The side with the longer mean edge (the coarser mesh)
   *    is the master; within 1e-9 relative, the body with the lower index.
   *    Interfaces are numbered by (lower body, higher body, first edge), so
   *    the result does not depend on the order of the search.
   * 5. <b>Ids.</b> Interface k gets the boundary ids first_id + 2k (master)
   *    and first_id + 2k + 1 (slave) on its edges.
   */
  namespace ContactDetection
  {
    /// The tolerances of the detection (see the namespace description).
    struct Settings
    {
      /// Largest distance between facing edges, relative to the longer one.
      double distance = 0.5;
      /// Largest deviation of the normals from opposite, in degrees.
      double max_angle = 45;
      /// Least overlap of facing edges, relative to the shorter one.
      double min_overlap = 0.01;
      /// A boundary turning by more than this (degrees) ends a chain.
      double corner_angle = 30;
      /// No split closer than this fraction of the edge to its ends.
      double merge_fraction = 0.05;
      /// Rule 2 on: split an edge that faces several bodies. Off, the edge
      /// faces only the body it overlaps most and the mesh keeps its
      /// vertices and edges (FiniteSliding detects on copies of its
      /// original mesh and needs their numbering).
      bool split_edges = true;
    };

    /// One detected interface.
    struct Interface
    {
      unsigned int               master_body = 0; ///< material id of the master side
      unsigned int               slave_body  = 0; ///< material id of the slave side
      dealii::types::boundary_id master_id   = 0; ///< boundary id given to the master edges
      dealii::types::boundary_id slave_id    = 0; ///< boundary id given to the slave edges
      unsigned int               n_master_edges = 0; ///< edges on the master side
      unsigned int               n_slave_edges  = 0; ///< edges on the slave side
      /// Length of the shared interface: the length of the shorter side.
      double                     length = 0;
      /// Mean edge length of the master side (the larger of the two).
      double                     master_h = 0;
      /// Mean edge length of the slave side.
      double                     slave_h = 0;
    };

    /// What detect() did.
    struct Result
    {
      std::vector<Interface> interfaces; ///< in the order of their ids
      /// Edges split because they faced more than one body.
      unsigned int           n_split_edges = 0;
      /// Boundary edges that were candidates (ids not excluded).
      unsigned int           n_candidate_edges = 0;
    };

    /**
     * Detect the interfaces between the bodies (material ids) of @p mesh
     * and give their edges new boundary ids from @p first_id on (rule
     * above). Edges whose id is in @p excluded_ids are left alone. The mesh
     * is changed: boundary ids, and split edges (rule 2). @p first_id must
     * exceed every boundary id in use (AssertThrow).
     */
    Result
    detect(PolygonalMesh<2>                           &mesh,
           const std::set<dealii::types::boundary_id> &excluded_ids,
           const dealii::types::boundary_id            first_id,
           const Settings                             &settings = Settings());

    /// The first id detect() may use on @p mesh: above every boundary id in
    /// use and at least 1000 (so that the ids of detected interfaces are
    /// recognisable in the output).
    dealii::types::boundary_id
    first_free_id(const PolygonalMesh<2> &mesh);

    /// A table of the interfaces, one line each (bodies, ids, edges,
    /// length), for the program's report.
    std::string
    describe(const Result &result);
  } // namespace ContactDetection
} // namespace dealvem

#endif
