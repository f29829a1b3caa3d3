// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_source_contact_node_insertion_side_h
#define dealvem_source_contact_node_insertion_side_h

// The pieces of NodeInsertion shared by source/contact/node_insertion*.cc
// (not installed): the geometry of a side of an interface (its edges, normals
// and arcs), the projections onto a side, and the rules of the insertion,
// each defined in the file of its job:
//  - node_insertion_side.cc: collecting a side, checking an interface, the
//    projections and casts onto a side;
//  - node_insertion_rules.cc: rules 1-3 (partners, merges, splits) and
//    rule 5 (the pairs of the slave chains);
//  - node_insertion_gaps.cc: rule 4 (gaps);
//  - node_insertion.cc: NodeInsertion's public functions.

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/numerics/rtree.h>

#include <dealvem/base/number_string.h>
#include <dealvem/contact/node_insertion.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <utility>

namespace dealvem
{
  namespace internal
  {
    namespace node_insertion
    {
    using Mesh       = PolygonalMesh<2>;



    using Point      = dealii::Point<2>;



    using Vector     = dealii::Tensor<1, 2>;



    using VertexPair = std::pair<unsigned int, unsigned int>;



    constexpr unsigned int invalid = dealii::numbers::invalid_unsigned_int;



    inline VertexPair
    key(const unsigned int a, const unsigned int b)
    {
      return a < b ? VertexPair(a, b) : VertexPair(b, a);
    }



    inline double
    cross(const Vector &a, const Vector &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }



    inline std::string
    interface_name(const dealii::types::boundary_id master_id,
                   const dealii::types::boundary_id slave_id)
    {
      return "contact interface (master id " + std::to_string(master_id) + ", slave id " +
             std::to_string(slave_id) + "): ";
    }



    using internal::number_string;



    using internal::point_string;



    /// Outward unit normal of a boundary edge a -> b (counter-clockwise
    /// order of its cell: the body lies on the left).
    inline Vector
    edge_normal(const Point &a, const Point &b)
    {
      Vector t = b - a;
      t /= t.norm();
      Vector n;
      n[0] = t[1];
      n[1] = -t[0];
      return n;
    }



    inline Vector
    tangent_of(const Vector &n)
    {
      Vector t;
      t[0] = -n[1];
      t[1] = n[0];
      return t;
    }



    /**
     * One side of an interface: its boundary edges (vertex pairs in the
     * counter-clockwise order of the owning cell), the chains they form,
     * and per vertex the local edge length, outward normal and curvature.
     */
    struct Side
    {
      dealii::types::boundary_id               id = 0;
      std::vector<std::array<unsigned int, 2>> edges;
      std::vector<unsigned int>                edge_indices; ///< mesh edge of edges[i], ascending
      /// The number of mesh edges when the side was collected (the edges
      /// added since are the only new candidates of a later collection).
      unsigned int                             n_mesh_edges = 0;
      std::set<dealii::types::material_id>     materials;
      std::map<VertexPair, unsigned int>       edge_by_pair; ///< -> index into edges
      std::map<unsigned int, unsigned int>     outgoing, incoming; ///< vertex -> index into edges
      /// Vertices in chain order; a closed chain does not repeat its first vertex.
      std::vector<std::vector<unsigned int>>   chains;
      std::vector<bool>                        closed;
      std::map<unsigned int, double>           h;      ///< shortest side edge at the vertex
      std::map<unsigned int, Vector>           normal; ///< averaged outward normal
      std::map<unsigned int, double>           kappa;  ///< smooth signed curvature, 0 at kinks
      std::vector<double>                      edge_kappa;     ///< smooth, for placing new vertices
      /// Circle through the vertex and its neighbours for the gap rule:
      /// interior vertices turning by less than 60 degrees (a coarse
      /// sampling of a curve turns that much); absent at chain ends and
      /// sharper corners.
      std::map<unsigned int, double>           kappa_gap;
      /// The edges' bounding boxes grown by half the edge length on every
      /// side (a hit of cast() lies at most merge_fraction < 1/2 edge lengths
      /// beyond an end), with the index into edges: the candidate search of
      /// project() and cast().
      dealii::RTree<std::pair<dealii::BoundingBox<2>, unsigned int>> edge_tree;
      Point lo, hi; ///< corners of the union of those boxes

      bool
      is_end(const unsigned int v) const
      {
        return outgoing.count(v) == 0 || incoming.count(v) == 0;
      }
    };



    /// Signed curvature (convex > 0) of the circle through a, b, c, or 0 if
    /// the side turns at b by more than the angle whose sine is
    /// @p corner_sine (default 30 degrees: a corner, not a curve).
    inline double
    menger_curvature(const Point &a, const Point &b, const Point &c, const double corner_sine = 0.5)
    {
      const Vector d1 = b - a, d2 = c - b;
      const double l1 = d1.norm(), l2 = d2.norm(), l3 = (c - a).norm();
      if (l1 == 0 || l2 == 0 || l3 == 0)
        return 0;
      const double sine = cross(d1, d2) / (l1 * l2);
      // a turn of round-off size is a straight side, not a circle of
      // enormous radius: the arc through points 1e16 away from its centre
      // would place a new vertex wrongly by the size of the coordinates
      if ((d1 * d2) <= 0 || std::abs(sine) > corner_sine || std::abs(sine) < 1e-9)
        return 0;
      return 2 * cross(d1, d2) / (l1 * l2 * l3);
    }



    /**
     * The circle through the ends a, b of a chord with signed curvature
     * @p kappa (convex > 0 for the side whose outward chord normal is
     * edge_normal(a, b)): the curve a side is taken to follow between two
     * vertices where it approximates a smooth curve.
     */
    struct Arc
    {
      bool   valid = false;
      Point  centre;
      double radius = 0;
    };



    inline Arc
    arc_of(const Point &a, const Point &b, const double kappa)
    {
      Arc          arc;
      const double L = a.distance(b);
      // (|kappa| L below 1e-9: straight to round-off, see menger_curvature())
      if (kappa == 0 || !std::isfinite(kappa) || std::abs(kappa) * L >= 2 || std::abs(kappa) * L < 1e-9)
        return arc;
      arc.radius     = 1. / std::abs(kappa);
      const double s = std::sqrt(arc.radius * arc.radius - 0.25 * L * L);
      arc.centre     = 0.5 * (a + b) - (kappa > 0 ? s : -s) * edge_normal(a, b);
      arc.valid      = true;
      return arc;
    }



    /// Chord parameter of the foot of @p x on the chord a -> b.
    inline double
    chord_parameter(const Point &a, const Point &b, const Point &x)
    {
      return ((x - a) * (b - a)) / a.distance_square(b);
    }



    /**
     * The point of the arc of the chord a -> b (curvature @p kappa) nearest
     * to @p p: the foot of p along the arc's normal. Returns false (and
     * leaves @p x) if there is no arc or the foot falls off the chord's
     * span.
     */
    inline bool
    closest_on_arc(const Point &a, const Point &b, const double kappa, const Point &p, Point &x)
    {
      const Arc arc = arc_of(a, b, kappa);
      if (!arc.valid || p.distance(arc.centre) == 0)
        return false;
      const Point  y = arc.centre + (arc.radius / p.distance(arc.centre)) * (p - arc.centre);
      const double t = chord_parameter(a, b, y);
      if (!(t > 0 && t < 1))
        return false;
      x = y;
      return true;
    }



    /**
     * The point where the line through @p p along @p direction meets the
     * arc of the chord a -> b (curvature @p kappa), the one nearer to p.
     * Returns false if there is no arc, the line misses it, or the hit falls
     * off the chord's span.
     */
    inline bool
    cast_on_arc(const Point &a, const Point &b, const double kappa, const Point &p, const Vector &direction,
                Point &x)
    {
      const Arc arc = arc_of(a, b, kappa);
      if (!arc.valid)
        return false;
      const Vector d    = direction / direction.norm();
      const Vector pc   = p - arc.centre;
      const double half = d * pc;
      const double disc = half * half - (pc * pc - arc.radius * arc.radius);
      if (disc < 0)
        return false;
      const double root = std::sqrt(disc);
      const double tau1 = -half - root, tau2 = -half + root;
      const Point  y    = p + (std::abs(tau1) < std::abs(tau2) ? tau1 : tau2) * d;
      const double t    = chord_parameter(a, b, y);
      if (!(t > 0 && t < 1))
        return false;
      x = y;
      return true;
    }



    /// The closest point of a vertex on the other side.
    struct Projection
    {
      unsigned int edge = invalid; ///< index into Side::edges
      double       t    = 0;       ///< clamped parameter along the edge
      double       length = 0;
      double       distance = 0;
      Point        point;
      bool         inside = false; ///< not beyond an end of the side
      bool         facing = false; ///< outward normals opposed
      double       normal_cosine = 1; ///< cosine of the angle between them
    };



    /// What happens to one vertex of a side.
    struct Candidate
    {
      Projection projection;
      bool       accepted = false;
    };



    /// A vertex inserted by rule 3 (splits), for the gap rule 4.
    struct Inserted
    {
      unsigned int vertex;  ///< the new vertex
      unsigned int partner; ///< its partner on the other side
      bool         on_master;
      unsigned int edge;    ///< the split edge of the receiving side (before insertion)
      Point        chord;   ///< the point of the chord at the split
      Vector       normal;  ///< outward normal of the chord
      double       q;       ///< t(1 - t) L^2 / 2: chord deviation per unit curvature
    };



    // Rule 4 (gaps) in three passes, one function each, called in this order
    // after the splits (the rule itself is item 3 of the class documentation
    // of NodeInsertion, "Discretisation gaps are closed, real gaps are kept"):
    //  (a) judge_gaps(): every pair is classified on the geometry the splits
    //      left, before any merged vertex moves: its gap is zero (round-off
    //      of the coordinates), a discretisation gap (the partner's offset
    //      from the receiving chord is what a curvature both sides show
    //      around the pair would give), unresolved (next to an inflection,
    //      within twice the chord deviation) or real;
    //  (b) face_merged_vertices(): two merged original vertices are placed
    //      opposite each other along the master normal, the slave vertex
    //      sliding along its own curve (the master vertex instead when the
    //      slave vertex ends its side), so a merge never carries a node
    //      across a gap;
    //  (c) close_or_keep_gaps(): one decision for the whole interface. With
    //      no real gap the two sides sample one curve and every gap is
    //      closed (the partners coincide; unless the settings switch the
    //      closing off, which keeps every gap); with a real gap anywhere only
    //      the zero gaps are closed, the others are kept as measured and the
    //      ones that could have been discretisation gaps are reported with
    //      their chord deviation. A smooth interface thus never has closed
    //      and kept gaps above round-off side by side.
    // The passes share the vertices rule 3 inserted, looked up by vertex.
    using InsertedByVertex = std::map<unsigned int, const Inserted *>;



    /// The class pass (a) of rule 4 puts the gap of a pair in.
    enum class GapVerdict
    {
      zero,           ///< within the coordinate precision
      discretisation, ///< inside the curvature band of the two sides
      unresolved,     ///< outside the band, but next to an inflection and within twice the deviation
      real            ///< anything else
    };



    /// One pair as pass (a) of rule 4 judged it.
    struct JudgedPair
    {
      unsigned int m, s;      ///< master and slave vertex
      GapVerdict   verdict;
      double       deviation; ///< chord deviation at the pair: q times the largest |kappa| (0 if not compared)
    };



    // Defined in node_insertion_side.cc.
    // The edges with boundary id @p id: those of @p known (ascending mesh
    // edge indices) that still carry it, and the edges from @p first_new on;
    // without @p known every edge of the mesh is looked at.
    Side
    collect_side(const Mesh                      &mesh,
                 const dealii::types::boundary_id id,
                 const std::vector<unsigned int> *known,
                 const unsigned int               first_new);

    // every edge of the mesh looked at
    Side
    collect_side(const Mesh &mesh, const dealii::types::boundary_id id);

    // the side again after the mesh changed: its edges (split edges keep
    // their index) and the edges added since
    Side
    collect_side(const Mesh &mesh, const Side &previous);

    void
    check_interface(const Mesh                      &mesh,
                    const dealii::types::boundary_id master_id,
                    const dealii::types::boundary_id slave_id,
                    const Side                      &master,
                    const Side                      &slave,
                    const NodeInsertion::Settings   &settings);

    Projection
    project(const Mesh &mesh, const Side &side, const Point &p, const Vector &own_normal,
            const double merge_fraction);

    /**
     * The point of @p side hit by the line through @p p along @p direction
     * (the master normal at a master vertex), nearest to @p p. Master
     * vertices are carried over to the slave side this way, and slave
     * vertices onto the master side by their closest point, which is the
     * same map (along the master normals) read backwards: the two cannot
     * cross.
     */
    Projection
    cast(const Mesh &mesh, const Side &side, const Point &p, const Vector &direction,
         const double merge_fraction);



    // Defined in node_insertion_rules.cc.
    // Rule 1 (partners): project every vertex of @p from that has a normal
    // onto the side @p onto (master vertices cast along their normal, slave
    // vertices projected) and keep, per vertex, the candidate partner point;
    // a vertex outside the overlap is skipped, one beyond the search distance
    // or on a part that does not face the other side is reported unpaired.
    void
    propose_partners(const PolygonalMesh<2>             &mesh,
                     const Side                         &from,
                     const Side                         &onto,
                     const bool                          from_master,
                     const NodeInsertion::Settings      &settings,
                     const double                        search,
                     const double                        interface_size,
                     NodeInsertion::Report              &report,
                     std::map<unsigned int, Candidate>  &out);

    // Rule 2 (merges): a vertex whose candidate point lies within the merge
    // fraction times the local edge length of a vertex of the other side is
    // paired with that vertex instead of splitting an edge; the closest
    // candidates are merged first, each vertex at most once. Fills the
    // partner maps (vertex -> partner vertex) of both sides.
    void
    merge_close_vertices(const PolygonalMesh<2>                  &mesh,
                         const Side                              &master,
                         const Side                              &slave,
                         const double                             f,
                         const std::map<unsigned int, Candidate> &on_master,
                         const std::map<unsigned int, Candidate> &on_slave,
                         NodeInsertion::Report                   &report,
                         std::map<unsigned int, unsigned int>    &master_partner,
                         std::map<unsigned int, unsigned int>    &slave_partner);

    // Rule 3 (splits): every accepted candidate of @p cands (vertices of
    // @p from) without a partner yet splits the edge of @p onto it projects
    // on; on a curved side the new vertex is moved onto the circle of the
    // side's curvature. A candidate that falls on a vertex of @p onto that
    // is paired already, or that would make a sub-edge shorter than 1e-3 of
    // an edge length, is reported unpaired. The new pairs go into the
    // partner maps, the new vertices into @p inserted.
    void
    split_edges(PolygonalMesh<2>                        &mesh,
                const Side                              &onto,
                const Side                              &from,
                const std::map<unsigned int, Candidate> &cands,
                std::map<unsigned int, unsigned int>    &partner_onto,
                std::map<unsigned int, unsigned int>    &partner_from,
                const bool                               onto_master,
                NodeInsertion::Report                   &report,
                std::vector<Inserted>                   &inserted);

    // Rule 5 (pairs): walk the chains of the slave side after insertion;
    // every slave edge whose two end vertices are paired with the two ends
    // of one master edge becomes a paired sub-edge (ContactSegment; for
    // k = 2 with the pair of the two edge midpoints), and the vertex pairs
    // are made in the order of the slave chains. The first and the last
    // pair of a run of paired sub-edges are marked at_open_end where both
    // boundaries go on smoothly beyond them. A paired slave vertex on no
    // paired sub-edge is reported unpaired.
    void
    pair_slave_chains(const PolygonalMesh<2>                     &mesh,
                      const Side                                 &master_after,
                      const Side                                 &slave_after,
                      const std::map<unsigned int, unsigned int> &slave_partner,
                      const unsigned int                          degree,
                      const unsigned int                          index,
                      NodeInsertion::Interface                   &result);



    // Defined in node_insertion_gaps.cc.
    /**
     * The decimal grid the coordinates of @p side were written on, for the
     * zero gaps of rule 3 ('Coordinate precision = auto'): the coarsest
     * power of ten $10^e$ of which every nonzero coordinate of the side's
     * vertices is an integer multiple to within two units in the last
     * place of a double, searched over at most 12 significant digits.
     * Returns 0 (no rounding beyond double's own) if some coordinate needs
     * more digits (coordinates computed in double precision: generators,
     * transformations, rotations) or if every coordinate is a binary
     * fraction of at most 32 significant bits (integers, halves, the
     * vertices of a generator's dyadic steps such as 0.125: exact values,
     * not rounded ones, although their decimals are short too). It is 0
     * as well if the grid exceeds 1/100 of the side's shortest edge: data
     * rounded that coarsely would not be a usable mesh, so vertices on such
     * a lattice were placed on it (a generator's steps of 0.1 or 0.05 over
     * the unit square) and are exact; taking 0.1 as their rounding would
     * close real gaps of up to half an element. The grid depends on the
     * data only, not on where the model lies: a shift by a multiple of the
     * grid keeps it, a scaling by a power of ten scales it and the edges
     * alike.
     */
    double
    decimal_grid(const Mesh &mesh, const Side &side);

    /**
     * Rule 4, pass (a): judge the gap of every pair of @p master_partner
     * (master vertex -> slave vertex) on the current mesh, i.e. after the
     * splits and before any merged vertex moves. @p master and @p slave are
     * the sides as collected before insertion (their edges are the chords
     * of rule 3), @p by_vertex the vertices rule 3 inserted, @p grid the
     * decimal grids of the master and the slave side (decimal_grid(); with
     * 'Coordinate precision' set, that value times @p size, the interface
     * size, on both). A gap within half the sum of the two grids, plus four
     * units in the last place of the pair's largest coordinate and
     * $10^{-12}$ of the local edge length (double round-off), is zero; otherwise a pair with an inserted
     * vertex is judged against the chord it split, and two merged original
     * vertices against the edge at the master vertex that the slave vertex
     * lies least beyond (along the edge). Returns the pairs in the order of @p master_partner.
     */
    std::vector<JudgedPair>
    judge_gaps(const Mesh                                 &mesh,
               const Side                                 &master,
               const Side                                 &slave,
               const std::map<unsigned int, unsigned int> &master_partner,
               const InsertedByVertex                     &by_vertex,
               const std::array<double, 2>                &grid,
               const NodeInsertion::Settings              &settings);

    /**
     * Rule 4, pass (b): place every pair of two merged original vertices
     * (pairs without a vertex of @p by_vertex) opposite each other. The
     * slave vertex moves along its side (on the arc of either of its edges,
     * or the edge itself if straight) to where the line through the master
     * vertex along the master normal meets it; if the slave vertex ends its
     * side, the master vertex moves instead, to the point of its side
     * closest to the slave vertex. Nothing moves if both vertices end their
     * sides, or if no target lies within half an edge length of the moving
     * vertex (a corner). @p master and @p slave are the sides collected before
     * insertion. Updates Report::max_merge_shift.
     */
    void
    face_merged_vertices(PolygonalMesh<2>                           &mesh,
                         const Side                                 &master,
                         const Side                                 &slave,
                         const std::map<unsigned int, unsigned int> &master_partner,
                         const InsertedByVertex                     &by_vertex,
                         NodeInsertion::Report                      &report);

    /**
     * Rule 4, pass (c): one decision for the interface on the pairs
     * @p judged by pass (a), with the gaps measured on the current mesh
     * (after pass (b)) along the master normals. The interface is one curve
     * if Settings::close_discretisation_gaps is set and no pair is real;
     * then every pair is closed (unresolved ones are also listed in
     * Report::closed_unresolved_gaps). Otherwise only the zero gaps are
     * closed (none if close_discretisation_gaps is false), and, with
     * close_discretisation_gaps set, the kept discretisation and
     * unresolved gaps are listed in Report::unresolved_gaps. Closing moves the inserted vertex
     * (@p by_vertex) onto its partner; for two original vertices the slave
     * one onto the master one, unless only the slave vertex ends its side.
     * @p master and @p slave are the sides collected before insertion.
     * Updates the gap and merge-shift counters of @p report.
     */
    void
    close_or_keep_gaps(PolygonalMesh<2>               &mesh,
                       const Side                     &master,
                       const Side                     &slave,
                       const std::vector<JudgedPair>  &judged,
                       const InsertedByVertex         &by_vertex,
                       const NodeInsertion::Settings  &settings,
                       NodeInsertion::Report          &report);
    } // namespace node_insertion
  } // namespace internal
} // namespace dealvem

#endif
