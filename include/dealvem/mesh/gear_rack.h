// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_mesh_gear_rack_h
#define dealvem_mesh_gear_rack_h

#include <deal.II/base/point.h>

#include <dealvem/mesh/polygonal_mesh.h>

#include <array>
#include <limits>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace dealvem
{
  /**
   * The exact outline of a straight-toothed gear rack (the basic rack of an
   * involute gear, the partner of a SpurGear pinion), in the plane.
   *
   * <b>Geometry.</b> The rack lies along the x axis with its teeth pointing
   * toward +y and its body below them. The pitch line (the line that rolls
   * on a pinion's reference circle without slipping) is the line
   * y = Parameters::pitch_line_height. With module $m$, pressure angle
   * $\alpha$, profile offset $x$ and backlash allowance $j$: the pitch is
   * $p = \pi m$; the datum line of the profile lies $x m$ above the pitch
   * line; the tip line $(h_a^* + x) m$ above and the root line
   * $(h_f^* - x) m$ below the pitch line. The flanks are straight, at the
   * angle $\alpha$ from the normal of the pitch line, so that the tooth
   * thickness at the height $y$ above the pitch line is
   * $s(y) = s_p - 2 y \tan\alpha$ with the thickness at the pitch line
   * $s_p = m(\pi/2 + 2x\tan\alpha) - j$ (the backlash allowance thins each
   * tooth by $j$, measured along the pitch line). Each root corner is
   * rounded by the circle of radius $\rho_f = \rho_f^* m$ tangent to the
   * flank and to the root line; the tip corners are sharp. Tooth $k$
   * (k = 0, ..., n - 1) has its axis at x = Parameters::position + k p.
   *
   * <b>Checks.</b> The constructor stops with a message naming the
   * parameter when the data give no rack: a module, addendum, dedendum,
   * fillet radius or body depth that is negative or not finite, a pressure
   * angle outside (0, 45) degrees, no teeth, a backlash that thins the
   * teeth to nothing or thickens them until neighbours overlap at the root
   * line, pointed teeth (no tip land), and root fillets that do not fit
   * (the two fillets of a space cross, or a fillet reaches the tip).
   *
   * <b>Parameterization.</b> One pitch of the outline, from the middle of
   * the space before a tooth to the middle of the space after it (left to
   * right, in the direction +x), is seven pieces: root line, fillet,
   * flank (rising), tip line, flank (falling), fillet, root line. The
   * outline coordinate of outline_point() is the arc length along the
   * outline from the middle of the space before tooth 0 (exact: the pieces
   * are straight lines and circular arcs), from 0 to n_teeth()
   * outline_pitch_length(); beyond either end the outline continues along
   * the root line. PolygonalMeshGenerators::gear_rack() uses it as the
   * chart of the deal.II manifold on the teeth.
   */
  class GearRack
  {
  public:
    /// The data of the rack (lengths in model units, angles in radians).
    struct Parameters
    {
      /// Module m.
      double module = 1.;
      /// Number of teeth (at least 1).
      unsigned int n_teeth = 5;
      /// Pressure angle alpha: the flanks' angle from the normal of the
      /// pitch line (radians, 0 < alpha < 45 degrees).
      double pressure_angle = 20. * 3.14159265358979323846 / 180.;
      /// Addendum coefficient h_a^*: the tip line (h_a^* + x) m above the pitch line.
      double addendum = 1.;
      /// Dedendum coefficient h_f^*: the root line (h_f^* - x) m below the pitch line.
      double dedendum = 1.25;
      /// Root fillet radius coefficient rho_f^* (the fillet radius rho_f^* m).
      double root_fillet_radius = 0.38;
      /// Profile offset coefficient x: the datum line of the profile x m
      /// above the pitch line (toward the tips); the teeth thicken at the
      /// pitch line by 2 x m tan(alpha).
      double profile_shift = 0.;
      /// Backlash allowance: each tooth thinned by this length along the pitch line.
      double backlash = 0.;
      /// Depth of the rack body below the root line (the back line of the
      /// rack lies this far below it); 0: 3 modules.
      double body_depth = 0.;
      /// Height (y) of the pitch line.
      double pitch_line_height = 0.;
      /// Position (x) of the axis of tooth 0.
      double position = 0.;
    };

    /// Where a point of the outline lies.
    enum class Piece
    {
      /// the root line between two fillets
      root_line,
      /// a root fillet (circular arc)
      fillet,
      /// a straight flank
      flank,
      /// the tip line
      tip_line
    };

    /// Check the data (throws with a message on data that give no rack; see
    /// the class documentation) and compute the derived dimensions.
    explicit GearRack(const Parameters &parameters);

    /// The data the rack was made from (body_depth resolved).
    const Parameters &
    parameters() const;

    /// Number of teeth.
    unsigned int
    n_teeth() const;

    /// Pitch pi m.
    double
    pitch() const;

    /// Base pitch pi m cos(alpha): the normal distance between the flanks
    /// of the same hand of neighbouring teeth.
    double
    base_pitch() const;

    /// Height (y) of the tip line.
    double
    tip_height() const;

    /// Height (y) of the root line.
    double
    root_height() const;

    /// Height (y) of the form line: where the fillets meet the flanks (the
    /// lowest point of the straight flank).
    double
    form_height() const;

    /// Height (y) of the back line of the rack (the bottom of the body).
    double
    bottom_height() const;

    /// The x coordinate of the axis of tooth @p k.
    double
    tooth_axis(const unsigned int k) const;

    /// Tooth thickness at the height @p y (absolute), measured between the
    /// straight flank lines (extended below the form line).
    double
    tooth_thickness(const double y) const;

    /// Centre of the root fillet on the right (+x) side of tooth @p k
    /// (mirror image about the tooth's axis for the left side).
    dealii::Point<2>
    fillet_center(const unsigned int k) const;

    /// The x range [left, right] of the rack: from the middle of the space
    /// before tooth 0 to the middle of the space after the last tooth.
    std::array<double, 2>
    extent() const;

    /// Length of the outline of one pitch.
    double
    outline_pitch_length() const;

    /// The outline coordinate of the start of each piece of a pitch and of
    /// its end: eight values from 0 to outline_pitch_length() (root line,
    /// fillet, flank, tip line, flank, fillet, root line).
    const std::array<double, 8> &
    piece_starts() const;

    /// The point of the outline at outline coordinate @p s (any real
    /// number: the root line continues beyond the ends).
    dealii::Point<2>
    outline_point(const double s) const;

    /// The unit tangent of the outline at @p s (in the direction of growing s).
    dealii::Tensor<1, 2>
    outline_tangent(const double s) const;

    /// The outline coordinate of the point of the outline closest to @p p
    /// (among the pieces of the tooth nearest to @p p).
    double
    outline_coordinate(const dealii::Point<2> &p) const;

    /// The distance of @p p from the outline point at outline_coordinate(p).
    double
    distance_to_outline(const dealii::Point<2> &p) const;

    /// The piece the outline coordinate @p s lies on.
    Piece
    piece(const double s) const;

    /// Points of the outline at spacing at most @p spacing, from left to
    /// right, both ends included.
    std::vector<dealii::Point<2>>
    outline(const double spacing) const;

    /// The area of the rack (body and teeth between the sides at extent()),
    /// by Gauss quadrature of the boundary integral along the exact outline.
    double
    area() const;

  private:
    Parameters prm;
    /// Derived dimensions, in the frame of a tooth (its axis at x = 0, the
    /// pitch line at y = 0): half the tip land, tip, form and root heights,
    /// the fillet centre (right side) and the form point's x.
    double half_tip, y_tip, y_form, y_root, fillet_x, fillet_y, form_x;
    /// Lengths of the root line half, the fillet and the flank of a pitch.
    double                root_length, fillet_length, flank_length;
    std::array<double, 8> starts;

    /// The point and the unit tangent at the outline coordinate @p u of
    /// the first half of a pitch (0 <= u <= outline_pitch_length() / 2; u < 0
    /// continues the root line), in the tooth frame.
    std::pair<dealii::Point<2>, dealii::Tensor<1, 2>>
    half_pitch_point(const double u) const;

    /// The outline coordinate, in the first half of a pitch, of the point
    /// closest to @p q (tooth frame, q[0] <= 0).
    double
    half_pitch_coordinate(const dealii::Point<2> &q) const;
  };

  namespace PolygonalMeshGenerators
  {
    /// How fine to mesh a rack, and where to grade the mesh.
    struct RackMeshSettings
    {
      /// Global refinements of the block mesh (about 6 cells across a tooth at 0).
      unsigned int n_global_refinements = 1;
      /// Cell size at the flank zones after the local refinement (0: none).
      double flank_cell_size = 0.;
      /// Cell size at the root fillets below the zones' flanks (0: none).
      double fillet_cell_size = 0.;
      /// Refined cells within this many cell sizes of a zone (as refine_toward()).
      double layers = 2.;

      /// Which flank of a tooth a zone refines.
      enum class Flank
      {
        /// both flanks
        both,
        /// the flank facing -x
        left,
        /// the flank facing +x
        right
      };

      /// A refined zone of the flank(s) of one tooth.
      struct FlankZone
      {
        /// The tooth (0, ..., n_teeth - 1).
        unsigned int tooth = 0;
        /// Heights above the pitch line from (clipped to the form line) ...
        double from_height = std::numeric_limits<double>::lowest();
        /// ... to (clipped to the tip line).
        double to_height = std::numeric_limits<double>::max();
        /// The flank(s).
        Flank flank = Flank::both;
      };

      /// Zones refined to flank_cell_size (and their fillets to
      /// fillet_cell_size). Empty: both whole flanks of every tooth.
      std::vector<FlankZone> zones;
    };

    /**
     * Mesh a gear rack into the quadrilaterals of a deal.II triangulation,
     * the way spur_gear() meshes a gear: a block mesh per half tooth (flank
     * blocks between the tooth axis and the flank, a fillet block, two root
     * blocks under the fillet and the space, and a body of two columns in
     * layers down to the back line), with the exact outline (GearRack's
     * outline coordinate as the chart of a deal.II ChartManifold) on the
     * teeth, refined globally and then toward the flank zones of the
     * settings (refine_toward()). The cells are flat. Boundary ids: 0 the
     * back line (bottom), 1 the teeth (root lines, fillets, flanks, tips),
     * 2 the left side, 3 the right side; all material ids are 0. The
     * triangulation holds a copy of the manifold (with a copy of the rack).
     */
    void
    gear_rack(dealii::Triangulation<2, 2> &tria, const GearRack &rack, const RackMeshSettings &settings);

    /// The same as polygons (from_triangulation(): hanging vertices of the
    /// graded mesh become vertices of the coarse neighbours), with the same
    /// boundary ids, material id 0.
    template <int dim>
    void
    gear_rack(PolygonalMesh<dim> &mesh, const GearRack &rack, const RackMeshSettings &settings);
  } // namespace PolygonalMeshGenerators
} // namespace dealvem

#endif
