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
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/vem_element_data.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace dealvem
{
  /**
   * One node-to-node contact pair on a matched interface.
   *
   * The normal does not depend on which side is called master: it is the
   * outward unit normal $n_A$ of the master (A) or $-n_B$ of the slave (B),
   * whichever side is flatter over the interface (the smaller mean
   * curvature at the paired vertices, by more than 10 %), or, where both
   * curve alike, the bisector $n = (n_A - n_B)/|n_A - n_B|$, either normal
   * where the sides coincide; two straight sides keep the master's normal
   * (see NodeInsertion::Interface::normal_side; at
   * a vertex a side's normal is the normal of the curve where the side
   * follows a smooth curve, else the normalized average of the two edge
   * normals); $t = (-n_y, n_x)$. The gap
   * $g = (u_B - u_A)\cdot n + g_0$ with $g_0 = (x_B - x_A)\cdot n$, A =
   * master, B = slave; $g \ge 0$ means the bodies do not penetrate.
   *
   * Nodes are mesh entities, of the kind the element's layout
   * (VEMElementData) gives them: a vertex (kind = vertex, entity = vertex
   * index) or the node inside an edge (kind = edge, entity = edge index;
   * the midpoint for k = 2). NodeInsertion pairs edge nodes only for
   * layouts with at most one node per edge (k = 1 and 2), so an edge and its
   * node are the same thing here.
   */
  struct ContactNodePair
  {
    unsigned int           master_entity;      ///< vertex or edge index (see kind) on the master side
    unsigned int           slave_entity;       ///< vertex or edge index on the slave side
    /**
     * The kind of node of both sides, in the terms of the element's layout:
     * VEMElementData::NodeKind::vertex (the entities are vertices) or
     * VEMElementData::NodeKind::edge (the entities are edges, each with its
     * one interior node, the midpoint for k = 2). Cell nodes are never
     * paired.
     */
    VEMElementData::NodeKind kind = VEMElementData::NodeKind::vertex;
    dealii::Point<2>       master_location;    ///< position of the master node
    dealii::Point<2>       slave_location;     ///< position of the slave node
    dealii::Tensor<1, 2>   normal;             ///< contact normal n
    dealii::Tensor<1, 2>   tangent;            ///< tangent t = (-n_y, n_x)
    double                 initial_gap = 0;    ///< g_0 = (x_B - x_A).n
    /// Tributary weight (length) of the node on the interface: the sum over
    /// the slave sub-edges at the node of L/2 (k = 1) or L/6 at an end and
    /// 2L/3 at the midpoint (k = 2, Simpson); the diagonal of the lumped
    /// interface mass matrix.
    double                 weight = 0;
    /// Index of the contact pair description this node pair belongs to.
    unsigned int           interface = 0;
    /// True for the first and the last pair of a chain of paired sub-edges
    /// where one side's contact part goes on beyond the pairs (the overlap
    /// of the two parts ends there, not both parts): an active pair there
    /// means the contact zone may be cut off by the extent of a part.
    bool                   at_open_end = false;
    /// True for a pair that closes a triangle of pairs where three bodies
    /// meet (NodeInsertion::mark_junctions()): its constraints repeat those
    /// of the two other pairs, and the unilateral and Coulomb iterations
    /// keep it open (with tied normal contact it stays a constraint).
    bool                   junction = false;

    /**
     * True for a pair of edge nodes (kind is VEMElementData::NodeKind::edge),
     * false for a pair of vertices.
     */
    bool
    on_edge() const
    {
      return kind == VEMElementData::NodeKind::edge;
    }

    /**
     * The global node of the master side (@p master true) or of the slave
     * side of this pair in @p dof_handler: the node of the vertex, or the
     * interior node of the edge.
     */
    template <int dim>
    unsigned int
    node(const VEMDoFHandler<dim> &dof_handler, const bool master) const
    {
      const unsigned int entity = master ? master_entity : slave_entity;
      return on_edge() ? dof_handler.edge_node(entity) : dof_handler.vertex_node(entity);
    }
  };

  /**
   * One paired sub-edge of a matched interface: the two vertex pairs at its
   * ends and, for k = 2, the midpoint pair (indices into the pair list), and
   * its length (on the slave side). The interface mass matrix is assembled
   * over these segments.
   */
  struct ContactSegment
  {
    unsigned int first;  ///< the pair at one end
    unsigned int second; ///< the pair at the other end
    unsigned int midpoint = dealii::numbers::invalid_unsigned_int; ///< the midpoint pair (k = 2), else invalid
    double       length   = 0; ///< length on the slave side
  };

  /**
   * Node insertion on the contact interface between two bodies of one
   * PolygonalMesh (see doc/architecture.md, "Node insertion").
   *
   * A contact interface names a boundary part of the master body (boundary
   * id @p master_id) and one of the slave body (@p slave_id). insert() makes
   * the two parts matching and returns the node pairs it creates; there is
   * no second geometric search. The rule, with $h$ the local edge length
   * (the shorter of the two side edges at the node pair):
   *
   * 1. <b>Partners.</b> Every vertex of either side whose closest point on
   *    the other side lies inside that side (not beyond its ends), within
   *    the search distance, and on a part facing it (outward normals at
   *    more than 120 degrees; 90 for a vertex in Settings::keep_facing)
   *    gets exactly one partner on the other side.
   *    Vertices that lie inside the overlap but fail the distance or facing
   *    test are listed in Report::unpaired with the reason.
   * 2. <b>Merge, never split short.</b> A vertex whose closest point on the
   *    other side lies within Settings::merge_fraction times $h$ of a vertex
   *    of that side, or closer than $10^{-3}$ of an edge length (the
   *    shortest sub-edge rule 3 makes), is paired with that vertex (the
   *    closest such pairs first); no sub-edge shorter than merge_fraction
   *    times $h$ is created. (With a merge fraction below $10^{-3}$ a vertex
   *    between the two distances would otherwise get no partner at all.)
   *    The other vertices split the edge they project onto; on a side that
   *    approximates a smooth curve (consecutive turning angles of the same
   *    sign and similar curvature) the new vertex is placed on the circle
   *    through the neighbouring vertices, not on the chord.
   * 3. <b>Discretisation gaps are closed, real gaps are kept.</b> If both
   *    sides sample one curve, the partner of a node inserted on a chord of
   *    length $L$ (at parameter $t$) lies off the chord by
   *    $\delta = \tfrac12 t(1-t)L^2\kappa$ for a curvature $\kappa$ the
   *    curve takes between the chord's ends. The pair's gap is therefore a
   *    discretisation gap if the partner's offset $\delta$ (along the
   *    chord's outward normal) lies in $\tfrac12 t(1-t)L^2\,[\kappa_-,
   *    \kappa_+]$, up to $\varepsilon_x$, where $[\kappa_-,
   *    \kappa_+]$ spans the vertex curvatures (circles through three
   *    neighbours; turns above 60 degrees are corners) of the chord's ends
   *    and their neighbours on the receiving side and of the partner and its
   *    neighbours on the other side (in the receiving side's sign, convex
   *    positive), always reaching 0, made symmetric next to the end of a
   *    side or an inflection (the extremes of either sign may lie between
   *    the samples), and widened by Settings::curvature_factor. Two merged
   *    original vertices are judged the same way against the master edge
   *    next to the slave vertex. A flat block under a cylinder does not
   *    qualify (the block shows no curvature, the cylinder the other sign);
   *    a real gap on a curved interface is kept if it exceeds about the
   *    chord deviation. $\varepsilon_x$ is the precision of the
   *    coordinates of the pair: half the sum of the decimal grids the two
   *    sides' coordinates were written on (the coarsest power of ten of
   *    which every coordinate of a side is a multiple, up to 12 significant
   *    digits; none for coordinates computed in double precision, for all
   *    short binary fractions such as 0.125, which are exact, and for a
   *    grid coarser than 1/100 of the side's shortest edge, a lattice the
   *    vertices were placed on), or
   *    Settings::coordinate_precision times the interface size if set, plus
   *    four units in the last place of the pair's coordinates and
   *    $10^{-12}$ of the local edge length (double round-off). It never
   *    grows with the distance from the origin, so a model gives the same
   *    pairs wherever it lies, at every scale and rotation. A gap within
   *    $\varepsilon_x$ (a zero gap) is closed. A discretisation gap is
   *    closed by moving the inserted vertex onto its partner (for two
   *    merged original vertices, the slave vertex onto the master vertex),
   *    so both sides share the node; every other gap or penetration is kept
   *    as $g_0$. A gap kept next to an inflection although it is at most
   *    twice the largest chord deviation there is listed in
   *    Report::unresolved_gaps (the curve changes sign between too few
   *    vertices to tell; the program prints a warning).
   *
   * After insertion both sides carry the same vertices along the overlap
   * (and, for k = 2, the same sub-edges, whose midpoints are paired too).
   * Splitting the edges of the polygons so that contact can be enforced
   * node to node follows @cite WriggersRustReddy2016.
   */
  class NodeInsertion
  {
  public:
    /// The tolerances of the insertion rules ('Contact' section).
    struct Settings
    {
      /// Nodes closer than this times the local edge length are merged
      /// (paired without a split); 0 < merge_fraction < 0.5.
      double merge_fraction = 0.05;
      /// Largest distance between a node and its partner, relative to the
      /// size of the interface (the diagonal of the bounding box of both
      /// sides). Larger gaps leave the node unpaired (reported).
      double search_distance = 0.25;
      /// The value of coordinate_precision that detects the precision
      /// from the data (the default, 'auto' in the parameter file).
      static constexpr double detect_precision = -1;
      /// Precision of the vertex coordinates (rule 3, zero gaps).
      /// detect_precision: each side's own, the decimal grid its
      /// coordinates were written on (0 for coordinates computed in double
      /// precision, or all short binary fractions). A value in [0, 0.01)
      /// replaces the detection: the coordinates are rounded to at most
      /// this times the interface size (the diagonal of the bounding box
      /// of both sides), for data rounded more coarsely than written (0:
      /// exact data). A gap below half the two sides' grids plus double
      /// round-off is taken as round-off of the mesh files. No tolerance
      /// grows with the distance of the model from the origin.
      double coordinate_precision = detect_precision;
      /// Factor by which the range of the sides' curvatures is widened in
      /// the gap rule (rule 3); 0 closes only gaps of coordinate precision.
      double curvature_factor = 1.5;
      /// Close discretisation gaps (rule 3). false keeps every gap.
      bool close_discretisation_gaps = true;
      /// Validate the whole mesh after the vertices moved (every cell).
      /// A caller that inserts many interfaces into one mesh turns this off
      /// and calls PolygonalMesh::validate() once after the last, so that
      /// the cost does not grow with the number of interfaces times the
      /// size of the mesh.
      bool validate_mesh = true;
      /// Vertices that had a partner in an earlier insertion into a mesh
      /// with the same original vertices (FiniteSliding: an earlier
      /// pairing pass of the same load step). For them the facing test of
      /// rule 1 accepts outward normals at more than 90 degrees instead of
      /// 120: a threshold with a band, so that a vertex whose normals sit
      /// at the threshold does not gain and lose its partner from one pass
      /// to the next.
      std::set<unsigned int> keep_facing;
      /// Two parts that do not face each other anywhere make an interface
      /// without pairs instead of an error (FiniteSliding: a body that
      /// slid off its partner, or that has not reached it yet, is simply
      /// not in contact there), unless a vertex lies in their overlap behind
      /// the other side but failed the distance or facing test
      /// (Report::unpaired, UnpairedNode::behind: a penetration beyond the
      /// search distance would go unseen).
      bool allow_no_pairs = false;
    };

    /// The boundary edges of a mesh by boundary id (ascending edge
    /// indices): the search structure of insert() for many interfaces on
    /// one mesh.
    using BoundaryEdges = std::map<dealii::types::boundary_id, std::vector<unsigned int>>;

    /// The boundary edges of @p mesh by id (one pass over the edges).
    static BoundaryEdges
    boundary_edges(const PolygonalMesh<2> &mesh);

    /// A node inside the overlap that did not get a partner.
    struct UnpairedNode
    {
      bool             on_master; ///< the node is on the master side
      unsigned int     vertex;    ///< its vertex index in the mesh
      dealii::Point<2> location;  ///< its position
      std::string      reason;    ///< why it has no partner (for the messages)
      /// it lies behind the other side (inside the other body, locally)
      bool             behind = false;
    };

    /// A gap that the rule could not tell from a discretisation gap.
    struct GapRecord
    {
      dealii::Point<2> location;        ///< midpoint of the pair
      double           gap = 0;         ///< g_0
      double           chord_deviation = 0; ///< q max|kappa| at the pair (length)
    };

    /// What insert() did.
    struct Report
    {
      unsigned int n_inserted_master = 0; ///< new vertices on the master side
      unsigned int n_inserted_slave  = 0; ///< new vertices on the slave side
      unsigned int n_merged          = 0; ///< pairs of existing vertices (no split)
      /// pairs whose gap was a discretisation gap (zero gaps included):
      /// their two nodes now coincide
      unsigned int n_closed_gaps     = 0;
      double       max_closed_gap    = 0; ///< largest |g_0| closed (length)
      double       max_merge_shift   = 0; ///< largest vertex move by a merge
      unsigned int n_master_edges    = 0; ///< master interface edges after insertion
      unsigned int n_slave_edges     = 0; ///< slave interface edges after insertion
      std::vector<UnpairedNode> unpaired; ///< nodes of the overlap left without a partner
      /// pairs whose gap is kept (above the coordinate precision): real
      /// gaps and penetrations, and the undecided ones below
      unsigned int n_kept_gaps  = 0;
      double       max_kept_gap = 0; ///< largest |g_0| kept (length)
      /// Gaps kept on an interface that also has real gaps, although each
      /// of them alone could be a discretisation gap (its size is within
      /// the chord deviation the sides' curvatures give there): the
      /// interface is not one curve, so they are kept as measured, and the
      /// program says so with the numbers.
      std::vector<GapRecord> unresolved_gaps;
      /// Gaps closed on an interface without real gaps although they lie
      /// next to an inflection and exceed the curvature band there (up to
      /// twice the chord deviation): closed with the rest of the curve,
      /// reported.
      std::vector<GapRecord> closed_unresolved_gaps;
    };

    /// Everything insert() creates for one interface.
    struct Interface
    {
      dealii::types::boundary_id   master_id = 0; ///< boundary id of the master side
      dealii::types::boundary_id   slave_id  = 0; ///< boundary id of the slave side
      unsigned int                 degree    = 1; ///< the order k (k = 2 pairs the midpoints too)
      unsigned int                 index     = 0; ///< ContactNodePair::interface of its pairs
      std::vector<ContactNodePair> pairs;         ///< the node pairs, along the interface
      std::vector<ContactSegment>  segments;      ///< the paired sub-edges
      Report                       report;        ///< what insert() did
      /// Whose normal gives the contact direction (see ContactNodePair):
      /// the flatter side's, or the bisector where both curve alike.
      enum class NormalSide
      {
        master,  ///< the master's outward normal
        slave,   ///< minus the slave's outward normal
        bisector ///< the normalized difference of the two
      };
      /// The side this interface takes its normal from.
      NormalSide normal_side = NormalSide::master;
      /// The mesh edges of the master side after insert() (update_geometry()
      /// uses them while they still carry the master id).
      std::vector<unsigned int> master_edges;
      /// The mesh edges of the slave side after insert().
      std::vector<unsigned int> slave_edges;
    };

    /**
     * Make the interface (master_id, slave_id) matching by inserting,
     * merging and moving vertices of @p mesh, and return the node pairs for
     * order @p degree (1: vertex pairs; 2: vertex and midpoint pairs) in
     * the order of the slave side, with @p index stored in the pairs.
     * Throws (AssertThrow, naming the ids) if a boundary id has no edges,
     * if both ids belong to the same body, if the settings are out of
     * range, if the two parts do not face each other within the search
     * distance at all, or if moving vertices would invalidate a cell.
     *
     * With @p edges (boundary_edges() of the mesh, kept by the caller for
     * all its interfaces), the two sides are taken from it instead of a
     * search of the whole mesh, and the edges insert() creates are added to
     * it; together with Settings::validate_mesh = false, inserting n
     * interfaces costs time proportional to their sizes, not n times the
     * mesh (an assembly of 1000 bodies has thousands of interfaces).
     */
    static Interface
    insert(PolygonalMesh<2>                &mesh,
           const dealii::types::boundary_id master_id,
           const dealii::types::boundary_id slave_id,
           const unsigned int               degree,
           const Settings                  &settings,
           const unsigned int               index = 0,
           BoundaryEdges                   *edges = nullptr);

    /**
     * The curve that rule 2 takes the boundary part @p id of @p mesh to
     * follow: for each edge of the part (by edge index; a boundary edge's
     * vertices run along its cell's loop, so the body lies to the left of
     * the edge), the signed curvature (convex > 0) of the circle arc
     * through the edge's two ends onto which a new vertex goes, 0 where the
     * part is straight, turns at a corner, or where the vertex curvatures
     * at the two ends disagree (circles through each vertex and its two
     * neighbours, kept where the neighbours agree; the smaller of the two).
     * FiniteSliding takes the same arcs as the shape of the interface in
     * the reference configuration.
     */
    static std::map<unsigned int, double>
    edge_curvatures(const PolygonalMesh<2> &mesh, const dealii::types::boundary_id id);

    /**
     * Recompute locations, normals, initial gaps and weights of the pairs
     * of @p interface from the current mesh (after other interfaces moved
     * shared vertices).
     */
    static void
    update_geometry(const PolygonalMesh<2> &mesh, Interface &interface);

    /**
     * Mark the pairs of @p pairs (of all interfaces, on @p mesh) that close
     * a triangle of vertex pairs where three bodies meet, and return their
     * number. Pair P of one interface joins vertices a and b, and a and b
     * are both paired, through other interfaces, with one vertex c: where a
     * head joint of a wall ends on a bed joint, P is the head joint's end
     * pair and c the point of the straight side below. While the two pairs
     * at c are closed and stick, P imposes nothing they do not, and the
     * force has no unique split among the three; a unilateral or Coulomb
     * iteration that judges P's share cycles. Of each triangle the pair
     * opposite the one vertex where the boundary runs straight (|sine| of
     * the turn below 1e-9) is marked; without exactly one such vertex
     * (corners of three bodies meeting), the pair of the latest interface.
     * Midpoint pairs (k = 2) never close a triangle.
     */
    static unsigned int
    mark_junctions(std::vector<ContactNodePair> &pairs, const PolygonalMesh<2> &mesh);
  };
} // namespace dealvem

#endif
