// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_mesh_spur_gear_h
#define dealvem_mesh_spur_gear_h

#include <deal.II/base/point.h>

#include <dealvem/mesh/polygonal_mesh.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace dealvem
{
  /**
   * The exact outline of an external involute spur gear, cut by a rack
   * (ISO 53 basic rack by default), in the plane.
   *
   * <b>Geometry.</b> With module $m$, $z$ teeth, pressure angle $\alpha$
   * and profile shift coefficient $x$:
   * reference radius $r = mz/2$, base radius $r_b = r\cos\alpha$, tip
   * radius $r_a = r + m(h_a^* + x)$, root radius $r_f = r - m(h_f^* - x)$.
   * The tooth thickness on the reference circle is
   * $s = m(\pi/2 + 2x\tan\alpha) - j$ with $j$ the backlash allowance of
   * this gear (a thinning measured along the reference circle). A flank is
   * the involute of the base circle; at radius $\rho$ (roll parameter
   * $t = \sqrt{\rho^2/r_b^2 - 1}$) its polar angle from the tooth axis is
   * $\psi = s/(2r) + \operatorname{inv}\alpha - \operatorname{inv}\alpha_\rho$,
   * $\operatorname{inv}\alpha = \tan\alpha - \alpha$. The root fillet is
   * the trochoid the rack's rounded tip corner (radius $\rho_f = \rho_f^* m$)
   * cuts while the rack rolls on the reference circle: the envelope of the
   * corner circle, whose contact normal passes through the pitch point. It
   * joins the involute with a continuous tangent at the form radius and the
   * root circle with a tangent perpendicular to the radius. The flat tip
   * of the rack cuts the root circle between the fillets. Tip relief
   * removes material along the flank normal near the tip: the amount
   * grows from 0 at the start radius to Parameters::tip_relief at the tip
   * radius, linearly or quadratically in the roll length $r_b t$.
   *
   * <b>Checks.</b> The constructor stops with a message naming the
   * parameter when the data give no gear: fewer than 5 teeth, an
   * undercut (the rack's straight flank would reach past the point where
   * the line of action touches the base circle: raise the profile shift),
   * a rack tip too round for the tooth space (the fillets
   * would cross), a pointed tooth (no tip land left), a tip relief larger
   * than the tooth, or a bore that does not fit below the root circle.
   *
   * <b>Parameterization.</b> The outline of one tooth pitch, from the
   * middle of the space before the tooth to the middle of the space after
   * it (counter-clockwise), is seven pieces: root arc, fillet, involute,
   * tip arc, involute, fillet, root arc. The outline coordinate
   * outline_point() takes is the arc length along the gear's outline from
   * the middle of the space before tooth 0 (to about 1e-5 relative: the
   * length of 512 chords per piece, each piece parameterized so that its
   * speed is nearly constant), periodic with
   * z outline_pitch_length(). PolygonalMeshGenerators::spur_gear() uses it
   * as the chart of the deal.II manifold on the outline, so every vertex
   * it makes on a tooth lies on the exact outline.
   *
   * Tooth $k$ has its axis at the polar angle
   * Parameters::rotation + $2\pi k/z$ about Parameters::center.
   *
   * <b>Internal gears</b> (Parameters::internal, a ring gear): the teeth
   * point toward the centre and the body reaches out to
   * Parameters::rim_radius. The tip circle lies inside, $r_a = r - m h_a^*$,
   * the root circle outside, $r_f = r + m h_f^*$; the flank is the involute
   * of the base circle unwound the other way, at polar angle
   * $\psi = s/(2r) - \operatorname{inv}\alpha + \operatorname{inv}\alpha_\rho$
   * from the tooth axis (the tooth widens outward; $s = m\pi/2 - j$, so the
   * space on the reference circle is $m\pi/2 + j$). Such a gear is cut by a
   * pinion-shaped cutter, whose tip rounds the root; here the root fillet
   * is the circle of radius $\rho_f = \rho_f^* m$ (Parameters::rack_tip_radius)
   * tangent to the flank and to the root circle, which the generated
   * fillet approaches for a cutter of many teeth. The tip circle must lie
   * outside the base circle (the flank starts there). Not yet for internal
   * gears: profile shift and tip relief (refused with a message). The
   * seven pieces of a pitch are the same, from the root arc outside to the
   * tip arc inside and back; form_radius() is where the fillet meets the
   * flank (now the flank's outer end) and base_half_angle() the
   * $s/(2r) - \operatorname{inv}\alpha$ above.
   */
  class SpurGear
  {
  public:
    /// How tip relief grows along the flank.
    enum class ReliefShape
    {
      /// linearly with the roll length from the start radius to the tip
      linear,
      /// quadratically with the roll length (a parabolic relief)
      parabolic
    };

    /// The data of the gear (lengths in model units, angles in radians).
    struct Parameters
    {
      /// Module m.
      double module = 1.;
      /// Number of teeth z (at least 5).
      unsigned int n_teeth = 20;
      /// Pressure angle alpha of the basic rack (radians, 0 < alpha < 35 degrees).
      double pressure_angle = 20. * 3.14159265358979323846 / 180.;
      /// Profile shift coefficient x (the rack datum line moved out by x m).
      double profile_shift = 0.;
      /// Addendum coefficient h_a^* of the gear (tip radius r + m (h_a^* + x)).
      double addendum = 1.;
      /// Dedendum coefficient h_f^* (the rack's addendum; root radius r - m (h_f^* - x)).
      double dedendum = 1.25;
      /// Tip radius coefficient rho_f^* of the rack (root fillet radius rho_f^* m).
      double rack_tip_radius = 0.38;
      /// Backlash allowance: the tooth thinned by this length along the reference circle.
      double backlash = 0.;
      /// Tip relief amount C_a (a length along the flank normal, at the tip).
      double tip_relief = 0.;
      /// Radius where tip relief starts (0: the middle between the reference and the tip radius).
      double tip_relief_radius = 0.;
      /// Shape of the tip relief.
      ReliefShape relief_shape = ReliefShape::linear;
      /// Bore radius (the inner boundary of a meshed external gear); 0:
      /// half the root radius. Must stay 0 for an internal gear.
      double bore_radius = 0.;
      /// An internal gear (a ring gear): the teeth point toward the centre,
      /// the body lies outside the outline, up to rim_radius.
      bool internal = false;
      /// Outer radius of an internal gear's rim; 0: the root radius plus
      /// 3 modules. Must stay 0 for an external gear.
      double rim_radius = 0.;
      /// Centre of the gear.
      dealii::Point<2> center;
      /// Polar angle of the axis of tooth 0 (radians, counter-clockwise).
      double rotation = 0.;
    };

    /// A point of the outline and where it lies.
    enum class Piece
    {
      /// the root circle between two fillets
      root_arc,
      /// the trochoid root fillet
      fillet,
      /// the involute flank (with its tip relief)
      involute,
      /// the tip circle
      tip_arc
    };

    /// Check the data and tabulate the outline (throws with a message on
    /// data that give no gear; see the class documentation).
    explicit SpurGear(const Parameters &parameters);

    /// Destructor.
    ~SpurGear();

    /// Copy constructor.
    SpurGear(const SpurGear &other);

    /// Copy assignment.
    SpurGear &
    operator=(const SpurGear &other);

    /// The data the gear was made from (with the defaults resolved:
    /// tip_relief_radius and bore_radius as used).
    const Parameters &
    parameters() const;

    /// Reference radius m z / 2.
    double
    reference_radius() const;

    /// Base radius r cos(alpha).
    double
    base_radius() const;

    /// Tip radius r + m (h_a^* + x) (internal gears: r - m h_a^*).
    double
    tip_radius() const;

    /// Root radius r - m (h_f^* - x) (internal gears: r + m h_f^*).
    double
    root_radius() const;

    /// Form radius: where the fillet joins the involute (the lowest point of the flank).
    double
    form_radius() const;

    /// Base pitch pi m cos(alpha): the normal distance between two flanks
    /// of the same hand of neighbouring teeth.
    double
    base_pitch() const;

    /// Angular pitch 2 pi / z.
    double
    angular_pitch() const;

    /// Half the tooth's angular thickness at the base circle,
    /// s / (2 r) + inv(alpha): the polar angle, from the tooth axis, where
    /// the flank's involute leaves the base circle (internal gears:
    /// s / (2 r) - inv(alpha), the flank's angle being this plus inv(alpha_rho)).
    double
    base_half_angle() const;

    /// Polar angle, from the tooth axis, of the unrelieved flank at radius
    /// @p radius (base radius <= radius): base_half_angle() - inv(alpha_radius)
    /// (internal gears: + inv(alpha_radius)).
    double
    flank_half_angle(const double radius) const;

    /// The normal amount of tip relief at radius @p radius on the flank
    /// (0 below the start radius).
    double
    tip_relief_at(const double radius) const;

    /// Length of the outline of one tooth pitch (the outline coordinate's
    /// period is n_teeth() times this).
    double
    outline_pitch_length() const;

    /// The outline coordinate of the start of each piece of tooth 0 and of
    /// its end: eight values from 0 to outline_pitch_length() (root arc,
    /// fillet, involute, tip arc, involute, fillet, root arc).
    const std::array<double, 8> &
    piece_starts() const;

    /// The point of the outline at outline coordinate @p s (any real
    /// number; periodic).
    dealii::Point<2>
    outline_point(const double s) const;

    /// The derivative of outline_point() with respect to the outline
    /// coordinate (a unit vector up to the arc-length tabulation).
    dealii::Tensor<1, 2>
    outline_tangent(const double s) const;

    /**
     * The outline coordinate of a point @p p on (or very near) the
     * outline: the coordinate of the closest point of the piece it lies
     * on, found from its tooth, its side and its radius (exact to
     * round-off for a point on the outline), with @p reference_s, if
     * given, choosing the period (the result lies within half a period of
     * it). Far from the outline the result is a coordinate but not the
     * closest point.
     */
    double
    outline_coordinate(const dealii::Point<2> &p, const double reference_s = 0.) const;

    /// The distance of @p p from the outline point at
    /// outline_coordinate(p): zero to round-off for a point on the outline.
    double
    distance_to_outline(const dealii::Point<2> &p) const;

    /// The piece the outline coordinate @p s lies on.
    Piece
    piece(const double s) const;

    /// Points of the outline of teeth [first, first + n) at spacing at
    /// most @p spacing, in counter-clockwise order, from the middle of the
    /// space before tooth @p first to the middle of the space after the
    /// last (both included).
    std::vector<dealii::Point<2>>
    outline(const unsigned int first, const unsigned int n, const double spacing) const;

    /// The area of the gear body between the bore and the outline of teeth
    /// [first, first + n), the sector between the middles of the spaces
    /// (all teeth: the whole gear with its bore), by Gauss quadrature of
    /// the boundary integral along the exact outline.
    double
    area(const unsigned int first, const unsigned int n) const;

    /// Number of teeth z.
    unsigned int
    n_teeth() const;

    /// Whether the gear is internal (Parameters::internal).
    bool
    is_internal() const;

    /// The radius of the meshed body's circle away from the teeth: the
    /// bore of an external gear, the outer rim of an internal one.
    double
    body_radius() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
  };

  namespace PolygonalMeshGenerators
  {
    /// Which part of a gear to mesh and how fine.
    struct GearMeshSettings
    {
      /// The first tooth of the mesh.
      unsigned int first_tooth = 0;
      /// Number of teeth meshed (0: the whole gear; otherwise a sector
      /// from the middle of the space before the first tooth to the middle
      /// of the space after the last one).
      unsigned int n_teeth = 0;
      /// Global refinements of the block mesh (about 6 cells across a tooth at 0).
      unsigned int n_global_refinements = 1;
      /// Cell size at the flanks after the local refinement (0: none).
      double flank_cell_size = 0.;
      /// Cell size at the root fillets below the refined flanks (the
      /// zones' flanks; 0: none): where the tooth root stress peaks, on the
      /// loaded flank's side.
      double fillet_cell_size = 0.;
      /// Flank zone refined to flank_cell_size: radii from this (0: the form radius) ...
      double refine_from_radius = 0.;
      /// ... to this (0: the tip radius).
      double refine_to_radius = 0.;
      /// The teeth whose flanks are refined: from this one (relative to
      /// the gear's tooth numbering) ...
      unsigned int first_refined_tooth = 0;
      /// ... this many (0: every meshed tooth).
      unsigned int n_refined_teeth = 0;
      /// Refined cells within this many cell sizes of the flank zone
      /// (as refine_toward()).
      double layers = 2.;

      /// Which flank of a tooth a zone refines.
      enum class Flank
      {
        /// both flanks
        both,
        /// the flank on the counter-clockwise side of the tooth's axis
        counter_clockwise,
        /// the flank on the clockwise side
        clockwise
      };

      /// A refined zone of one flank (or both flanks) of one tooth.
      struct FlankZone
      {
        /// The tooth (the gear's numbering, counter-clockwise from tooth 0; modulo z).
        int tooth = 0;
        /// Radii from (0: the form radius) ...
        double from_radius = 0.;
        /// ... to (0: the tip radius).
        double to_radius = 0.;
        /// The flank(s).
        Flank flank = Flank::both;
      };

      /// Zones refined to flank_cell_size. Empty: both flanks of the teeth
      /// first_refined_tooth, ... between refine_from_radius and
      /// refine_to_radius. A gear pair's contact zones of one position are
      /// a few such zones (one per tooth pair in contact, on the driving
      /// flanks).
      std::vector<FlankZone> zones;
    };

    /**
     * Mesh a spur gear, or a sector of it, into the quadrilaterals of a
     * deal.II triangulation with its manifolds attached: a block mesh per
     * half tooth (tip, flank, fillet, root and rim blocks, with lines
     * across the tooth at the block corners), with the exact outline
     * (SpurGear's outline coordinate as the chart of a deal.II
     * ChartManifold) on the teeth and circles (PolarManifold) on the bore
     * and on the arcs inside, refined globally and then toward the flank
     * zone of the settings (refine_toward()). The cells are flat: a refined
     * quadrilateral's centre is placed from its vertices and its (curved)
     * face midpoints by the transfinite interpolation weights.
     * An internal gear is meshed the same way outward: its root blocks and
     * rim lie outside the root circle, up to the rim radius.
     * Boundary ids: 0 the bore (internal gears: the rim circle), 1 the teeth (root, fillets, flanks, tips),
     * 2 the sector side before the first tooth, 3 the side after the last
     * one (a whole gear has none). The triangulation holds copies of the
     * manifolds (each with its own copy of the gear); all material ids are 0.
     * Write it to gmsh with deal.II's GridOut::write_msh(): MeshIO::read_msh()
     * reads it back (the hanging vertices of the graded mesh become
     * vertices of the coarse neighbours' polygons).
     */
    void
    spur_gear(dealii::Triangulation<2, 2> &tria, const SpurGear &gear, const GearMeshSettings &settings);

    /// The same as polygons (from_triangulation(): hanging vertices of
    /// the graded mesh become vertices of the coarse neighbours), with the
    /// same boundary ids, material id 0.
    template <int dim>
    void
    spur_gear(PolygonalMesh<dim> &mesh, const SpurGear &gear, const GearMeshSettings &settings);
  } // namespace PolygonalMeshGenerators
} // namespace dealvem

#endif
