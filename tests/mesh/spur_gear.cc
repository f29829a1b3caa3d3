// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// SpurGear and PolygonalMeshGenerators::spur_gear (issue 41, item 1), on
// three gears: a standard one (m = 2, z = 20, 20 degrees, x = 0), a shifted
// small one with a thin rack corner, backlash, parabolic tip relief, an
// off-origin centre and a rotation (m = 1, z = 13, 25 degrees, x = 0.3), and
// a large negatively shifted one (m = 0.5, z = 61, x = -0.2, linear relief).
// Checked against what the geometry fixes, by routes other than the
// formulas the class uses:
// - the outline is continuous at every joint of its seven pieces, and its
//   tangent is continuous where the fillet meets the flank and the root
//   circle (the rack's corner generates the fillet: it must join the
//   involute its straight flank generates, with the same tangent);
// - the flank below the relief is an involute of the base circle: polar
//   angle + inv(alpha_rho) is the same constant at every point (1e-12);
// - the tooth thickness on the reference circle, found on the outline by
//   bisection, is m (pi/2 + 2 x tan alpha) - backlash (1e-11 relative);
// - the root circle is reached at r_f with the tangent perpendicular to
//   the radius; the tip corner lies on the tip circle;
// - the tip relief at the corner, measured as the normal distance to the
//   unrelieved involute (involutes of one base circle are parallel curves:
//   r_b times the difference of their involute angles), is the amount the
//   relief law gives there;
// - the outline coordinate is the arc length (1e-5 relative) and
//   outline_coordinate() inverts outline_point() (1e-12 of the size);
// - the meshes (sector and whole gear, k = 1, 2 patch tests): every vertex
//   on a tooth lies on the exact outline (1e-12 of the tip radius), bore
//   vertices on the bore circle, the boundary ids are 0 bore, 1 teeth,
//   2 and 3 the sector sides; the flank zone's edges are at most 1.3 times
//   the requested size; the mesh area converges to the exact area at rate 2
//   (the polygon's sag); a linear displacement with Dirichlet data on the
//   whole boundary is reproduced to round-off (1e-10 relative) with k = 1
//   and k = 2 on the graded mesh with its hanging vertices;
// - the graded triangulation written by MeshIO::write_msh is
//   read back by MeshIO::read_msh as the same polygons, area and boundary
//   ids (the gmsh output);
// - internal gears (four rings, among them profile shifts +0.3 and -0.25
//   with parabolic and linear tip relief): the checks of
//   check_internal_geometry() below, the tip corner C_a from the involute
//   (its nearest point found by golden section, 1e-9 relative), and their
//   meshes;
// - data that give no gear are refused with a message naming the cause.
#include <deal.II/base/function.h>
#include <deal.II/grid/tria.h>

#include <dealvem/mesh/mesh_io.h>
#include <dealvem/mesh/spur_gear.h>
#include <dealvem/vem/vem_dof_handler.h>

#include "../elasticity_common.h"
#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace dealvem;
using testing::check;
using testing::check_small;

namespace
{
  const double pi = std::acos(-1.);

  double
  inv(const double a)
  {
    return std::tan(a) - a;
  }

  /// Polar angle of p about the gear's centre, relative to tooth k's axis.
  double
  angle_from_axis(const SpurGear &gear, const dealii::Point<2> &p, const unsigned int k)
  {
    const auto   rel = p - gear.parameters().center;
    const double a   = std::atan2(rel[1], rel[0]) - gear.parameters().rotation - gear.angular_pitch() * k;
    return a - 2 * pi * std::round(a / (2 * pi));
  }

  void
  check_geometry(const SpurGear &gear, const std::string &name)
  {
    const auto  &prm = gear.parameters();
    const auto  &st  = gear.piece_starts();
    const double L = gear.outline_pitch_length(), ra = gear.tip_radius(), rb = gear.base_radius();
    const auto   P   = [&](const double s) { return gear.outline_point(s); };
    const auto   rad = [&](const double s) { return P(s).distance(prm.center); };

    // continuity at every joint (the next tooth's start included), tangents at the fillet's ends
    double jump = 0, kink = 0;
    for (unsigned int j = 0; j <= 7; ++j)
      {
        const double s = st[j] + L; // tooth 1, so that s - h lies on tooth 0
        const double h = 1e-7 * L;
        // the left and right limits, extrapolated linearly from either side
        const auto left = 2 * P(s - h) - P(s - 2 * h), right = 2 * P(s + h) - P(s + 2 * h);
        jump = std::max(jump, (dealii::Tensor<1, 2>(left) - dealii::Tensor<1, 2>(right)).norm() / L);
        if (j == 1 || j == 2 || j == 5 || j == 6)
          {
            const double ht = 1e-5 * L;
            auto         t0 = gear.outline_tangent(s - ht), t1 = gear.outline_tangent(s + ht);
            kink = std::max(kink, std::acos(std::min(1., t0 * t1 / (t0.norm() * t1.norm()))));
          }
      }
    check_small(jump, 1e-10,
                name + ": outline continuous at the joints (left and right limits, relative to the pitch)");
    check_small(kink, 1e-3, name + ": tangent continuous where the fillet meets flank and root (radians)");

    // the flank is an involute: polar angle + inv(alpha_rho) constant below the relief
    const double relief_start = prm.tip_relief > 0 ? prm.tip_relief_radius : ra;
    double       spread       = 0;
    for (unsigned int i = 0; i <= 50; ++i)
      {
        const double s   = st[4] + (st[5] - st[4]) * i / 50.;
        const double rho = rad(s);
        if (rho > relief_start)
          continue;
        const double psi = angle_from_axis(gear, P(s), 0) + inv(std::acos(rb / rho));
        spread           = std::max(spread, std::abs(psi - gear.base_half_angle()));
      }
    check_small(spread, 1e-12, name + ": flank points lie on the base circle's involute (radians)");

    // tooth thickness on the reference circle, by bisection along the upper flank
    {
      double lo = st[4], hi = st[5];
      for (unsigned int it = 0; it < 200; ++it)
        {
          const double mid                               = 0.5 * (lo + hi);
          (rad(mid) > gear.reference_radius() ? lo : hi) = mid;
        }
      const double thickness = 2 * gear.reference_radius() * angle_from_axis(gear, P(0.5 * (lo + hi)), 0);
      const double expected =
        prm.module * (pi / 2 + 2 * prm.profile_shift * std::tan(prm.pressure_angle)) - prm.backlash;
      check_small(thickness / expected - 1, 1e-11, name + ": tooth thickness on the reference circle (relative)");
    }

    // root circle reached with a tangent perpendicular to the radius; tip corner on the tip circle
    check_small(rad(st[6]) / gear.root_radius() - 1, 1e-14, name + ": fillet ends on the root circle");
    {
      const auto t = gear.outline_tangent(st[6]);
      const auto r = P(st[6]) - prm.center;
      check_small(t * r / (t.norm() * r.norm()), 1e-5, name + ": fillet tangent to the root circle");
    }
    check_small(rad(st[4]) / ra - 1, 1e-14, name + ": tip corner on the tip circle");
    check(gear.form_radius() > rb && gear.form_radius() < gear.reference_radius(),
          name + ": base radius < form radius < reference radius");

    // tip relief at the corner: normal distance to the unrelieved involute
    if (prm.tip_relief > 0)
      {
        const auto   corner = P(st[4]);
        const double rho    = corner.distance(prm.center);
        const double removed =
          rb * (gear.base_half_angle() - angle_from_axis(gear, corner, 0) - inv(std::acos(rb / rho)));
        // the law evaluated at the unrelieved point of the same involute roll: the corner's own roll
        const double t_corner  = std::sqrt(rho * rho / (rb * rb) - 1) + removed / rb; // roll of the string
        const double rho_unrel = rb * std::sqrt(1 + t_corner * t_corner);
        check_small(removed / gear.tip_relief_at(rho_unrel) - 1, 1e-3,
                    name + ": tip relief at the corner, measured normal to the involute");
        check(removed > 0.9 * prm.tip_relief && removed <= prm.tip_relief * (1 + 1e-12),
              name + ": tip relief amount at the tip (" + std::to_string(removed) + " of " +
                std::to_string(prm.tip_relief) + ")");
      }

    // arc length and the inverse
    {
      double             chord = 0, back = 0;
      const unsigned int n = 20000;
      for (unsigned int i = 0; i < n; ++i)
        chord += P(L * i / n).distance(P(L * (i + 1) / n));
      check_small(chord / L - 1, 1e-4, name + ": the outline coordinate is the arc length (relative)");
      for (unsigned int i = 0; i < 300; ++i)
        {
          const double s = 3 * L * (i + 0.37) / 300 - L; // three teeth, across the periodic seam
          back           = std::max(back, P(gear.outline_coordinate(P(s), s)).distance(P(s)));
          back           = std::max(back, std::abs(gear.outline_coordinate(P(s), s) - s) * 1e-3);
        }
      check_small(back / ra, 1e-12, name + ": outline_coordinate inverts outline_point");
    }
  }

  /**
   * An internal gear: the flank is the involute whose polar angle from the
   * tooth's axis is base_half_angle() + inv(alpha_rho) (the tooth widens
   * outward), the space on the reference circle is half the circular
   * pitch plus the backlash, the fillet joins flank and root circle with a
   * continuous tangent and meets the root circle square to the radius, the
   * tip corner lies on the tip circle, the outline coordinate is the arc
   * length and inverts, and area() is the ring between outline and rim.
   */
  void
  check_internal_geometry(const SpurGear &gear, const std::string &name)
  {
    const auto  &prm = gear.parameters();
    const auto  &st  = gear.piece_starts();
    const double L = gear.outline_pitch_length(), rb = gear.base_radius(), r = gear.reference_radius();
    const auto   P    = [&](const double s) { return gear.outline_point(s); };
    const auto   rad  = [&](const double s) { return P(s).distance(prm.center); };
    double       jump = 0, kink = 0;
    for (unsigned int j = 0; j <= 7; ++j)
      {
        const double s = st[j] + L, h = 1e-7 * L;
        const auto   left = 2 * P(s - h) - P(s - 2 * h), right = 2 * P(s + h) - P(s + 2 * h);
        jump = std::max(jump, (dealii::Tensor<1, 2>(left) - dealii::Tensor<1, 2>(right)).norm() / L);
        if (j == 1 || j == 2 || j == 5 || j == 6)
          {
            const auto t0 = gear.outline_tangent(s - 1e-5 * L), t1 = gear.outline_tangent(s + 1e-5 * L);
            kink = std::max(kink, std::acos(std::min(1., t0 * t1 / (t0.norm() * t1.norm()))));
          }
      }
    check_small(jump, 1e-10, name + ": outline continuous at the joints (relative to the pitch)");
    check_small(kink, 1e-3, name + ": tangent continuous where the fillet meets flank and root (radians)");
    // the involute's polar angle at radius rho, and a point of it
    const auto involute_angle = [&](const double rho) { return gear.base_half_angle() + inv(std::acos(rb / rho)); };
    const auto involute_at    = [&](const double rho) {
      return dealii::Point<2>(rho * std::cos(involute_angle(rho)), rho * std::sin(involute_angle(rho)));
    };
    // the relieved part of the flank lies inside the relief radius
    const double relieved_below = prm.tip_relief > 0 ? prm.tip_relief_radius : 0.;
    double       spread         = 0;
    for (unsigned int i = 0; i <= 50; ++i)
      {
        const double s = st[4] + (st[5] - st[4]) * i / 50.;
        if (rad(s) >= relieved_below)
          spread = std::max(spread, std::abs(angle_from_axis(gear, P(s), 0) - involute_angle(rad(s))));
      }
    check_small(spread, 1e-12, name + ": flank points lie on the base circle's involute, widening outward (radians)");
    if (prm.tip_relief > 0)
      {
        // the tip corner's distance from the involute (golden section on
        // the radius of the involute's point) is the relief C_a
        const double           rho_q = rad(st[4]), theta_q = angle_from_axis(gear, P(st[4]), 0);
        const dealii::Point<2> q(rho_q * std::cos(theta_q), rho_q * std::sin(theta_q));
        double                 lo = std::max(rb, rho_q - 4 * prm.tip_relief), hi = rho_q + 4 * prm.tip_relief;
        const double           golden = 0.5 * (std::sqrt(5.) - 1);
        for (unsigned int it = 0; it < 200; ++it)
          {
            const double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
            if (involute_at(a).distance(q) < involute_at(b).distance(q))
              hi = b;
            else
              lo = a;
          }
        const double depth = involute_at(0.5 * (lo + hi)).distance(q);
        check_small(depth / prm.tip_relief - 1, 1e-9, name + ": the tip corner lies C_a inside the involute (relative)");
        check(angle_from_axis(gear, P(st[4]), 0) < involute_angle(rho_q),
              name + ": the relief removes material (the corner lies inside the tooth)");
      }
    {
      double lo = st[4], hi = st[5];
      for (unsigned int it = 0; it < 200; ++it)
        {
          const double mid         = 0.5 * (lo + hi);
          (rad(mid) < r ? lo : hi) = mid;
        }
      const double space = 2 * r * (gear.angular_pitch() / 2 - angle_from_axis(gear, P(0.5 * (lo + hi)), 0));
      const double expected = prm.module * (pi / 2 - 2 * prm.profile_shift * std::tan(prm.pressure_angle)) +
                              prm.backlash;
      check_small(space / expected - 1, 1e-11,
                  name + ": space width on the reference circle = m (pi / 2 - 2 x tan alpha) + backlash (relative)");
    }
    check_small(rad(st[6]) / gear.root_radius() - 1, 1e-14, name + ": fillet ends on the root circle");
    {
      const auto t = gear.outline_tangent(st[6]);
      const auto d = P(st[6]) - prm.center;
      check_small(t * d / (t.norm() * d.norm()), 1e-5, name + ": fillet tangent to the root circle");
    }
    check_small(rad(st[4]) / gear.tip_radius() - 1, 1e-14, name + ": tip corner on the tip circle");
    check(rb < gear.tip_radius() && gear.tip_radius() < r && r < gear.form_radius() &&
            gear.form_radius() < gear.root_radius(),
          name + ": base < tip < reference < form < root radius");
    {
      double back = 0;
      for (unsigned int i = 0; i < 300; ++i)
        {
          const double s = 3 * L * (i + 0.37) / 300 - L;
          back           = std::max(back, P(gear.outline_coordinate(P(s), s)).distance(P(s)));
        }
      check_small(back / gear.root_radius(), 1e-12, name + ": outline_coordinate inverts outline_point");
      // the ring's area against the shoelace formula on a fine sampling of the outline
      const auto pts   = gear.outline(0, gear.n_teeth(), 1e-3 * L);
      double     inner = 0;
      for (unsigned int i = 0; i + 1 < pts.size(); ++i)
        inner += 0.5 * ((pts[i] - prm.center)[0] * (pts[i + 1] - prm.center)[1] -
                        (pts[i] - prm.center)[1] * (pts[i + 1] - prm.center)[0]);
      const double R = gear.body_radius();
      check_small(gear.area(0, gear.n_teeth()) / (pi * R * R - inner) - 1, 1e-6,
                  name + ": area() is the ring between outline and rim (against 1000 chords a pitch)");
    }
  }

  void
  check_mesh(const SpurGear                                  &gear,
             const PolygonalMeshGenerators::GearMeshSettings &settings,
             const std::string                               &name,
             const bool                                       patch_test)
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::spur_gear(mesh, gear, settings);
    const auto  &prm = gear.parameters();
    const double ra  = gear.tip_radius();
    double       off = 0, bore = 0, longest = 0, longest_fillet = 0;
    unsigned int n_ids[4] = {0, 0, 0, 0};
    const bool   whole    = settings.n_teeth == 0;
    for (const auto &e : mesh.get_edges())
      {
        if (!e.at_boundary())
          continue;
        AssertThrow(e.boundary_id < 4, dealii::ExcInternalError());
        ++n_ids[e.boundary_id];
        const auto a = mesh.vertex(e.vertices[0]), b = mesh.vertex(e.vertices[1]);
        if (e.boundary_id == 1)
          {
            off                        = std::max({off, gear.distance_to_outline(a), gear.distance_to_outline(b)});
            const dealii::Point<2> mid = 0.5 * (a + b);
            const double           rm  = mid.distance(prm.center);
            // the tooth of the edge, among the refined ones?
            const auto   rel     = mid - prm.center;
            const double phi     = std::atan2(rel[1], rel[0]) - prm.rotation;
            const int    z       = gear.n_teeth();
            const int    tooth   = ((int(std::lround(phi / gear.angular_pitch())) % z) + z) % z;
            const int    first   = settings.n_refined_teeth == 0 ? settings.first_tooth : settings.first_refined_tooth;
            const int    n_ref   = settings.n_refined_teeth == 0 ? settings.n_teeth : settings.n_refined_teeth;
            const bool   refined = (tooth - first + z) % z < n_ref;
            const double lo = std::min(gear.form_radius(), ra), hi = std::max(gear.form_radius(), ra);
            if (settings.flank_cell_size > 0 && refined && rm > lo && rm < hi)
              longest = std::max(longest, a.distance(b));
            if (settings.fillet_cell_size > 0 && refined &&
                gear.piece(gear.outline_coordinate(mid)) == SpurGear::Piece::fillet)
              longest_fillet = std::max(longest_fillet, a.distance(b));
          }
        if (e.boundary_id == 0)
          bore = std::max({bore, std::abs(a.distance(prm.center) - gear.body_radius()),
                           std::abs(b.distance(prm.center) - gear.body_radius())});
      }
    check_small(off / ra, 1e-12, name + ": tooth vertices on the exact outline (relative to the tip radius)");
    check_small(bore / ra, 1e-12,
                name +
                  (gear.is_internal() ? ": rim vertices on the rim circle" : ": bore vertices on the bore circle"));
    check(n_ids[0] > 0 && n_ids[1] > 0 && (whole ? n_ids[2] + n_ids[3] == 0 : n_ids[2] > 0 && n_ids[3] > 0),
          name + ": boundary ids 0 bore, 1 teeth" + (whole ? ", no sides" : ", 2 and 3 the sides") + " (" +
            std::to_string(n_ids[0]) + ", " + std::to_string(n_ids[1]) + ", " + std::to_string(n_ids[2]) + ", " +
            std::to_string(n_ids[3]) + " edges)");
    if (settings.flank_cell_size > 0)
      check(longest <= 1.3 * settings.flank_cell_size * (1 + 1e-9) && longest > 0.3 * settings.flank_cell_size,
            name + ": flank edges at most 1.3 h (" + std::to_string(longest / settings.flank_cell_size) + " h)");
    if (settings.fillet_cell_size > 0)
      check(longest_fillet <= 1.3 * settings.fillet_cell_size * (1 + 1e-9) &&
              longest_fillet > 0.3 * settings.fillet_cell_size,
            name + ": fillet edges at most 1.3 h_fillet (" +
              std::to_string(longest_fillet / settings.fillet_cell_size) + " h_fillet)");
    std::cout << "      " << name << ": " << mesh.n_cells() << " polygons, " << mesh.n_vertices() << " vertices"
              << std::endl;

    if (patch_test)
      for (const unsigned int k : {1u, 2u})
        check_small(testing::linear_patch_test_error(mesh, k), 1e-10,
                    name + ": linear patch test, k = " + std::to_string(k));
  }
} // namespace


int
main()
{
  try
    {
      SpurGear::Parameters a;
      a.module  = 2;
      a.n_teeth = 20;
      const SpurGear standard(a);

      SpurGear::Parameters b;
      b.module            = 1;
      b.n_teeth           = 13;
      b.pressure_angle    = 25 * pi / 180;
      b.profile_shift     = 0.3;
      b.rack_tip_radius   = 0.25;
      b.backlash          = 0.05;
      b.tip_relief        = 0.02;
      b.tip_relief_radius = 7.;
      b.relief_shape      = SpurGear::ReliefShape::parabolic;
      b.center            = dealii::Point<2>(3e2, -2e2);
      b.rotation          = 0.3;
      b.bore_radius       = 2.;
      const SpurGear small(b);

      SpurGear::Parameters c;
      c.module        = 0.5;
      c.n_teeth       = 61;
      c.profile_shift = -0.2;
      c.tip_relief    = 0.004;
      c.bore_radius   = 10.;
      const SpurGear large(c);

      check_geometry(standard, "m 2, z 20");
      check_geometry(small, "m 1, z 13, x 0.3, 25 deg");
      check_geometry(large, "m 0.5, z 61, x -0.2");

      {
        // a sector of more than half the gear: its sides still get ids 2
        // (before the first tooth) and 3 (after the last); they were both
        // 2 when the side's angle was taken from the first tooth's axis
        PolygonalMeshGenerators::GearMeshSettings s;
        s.first_tooth          = 3;
        s.n_teeth              = 12;
        s.n_global_refinements = 0;
        check_mesh(standard, s, "sector of 12 of 20 teeth", false);
      }

      // internal gears (ring gears)
      SpurGear::Parameters ia;
      ia.module   = 2;
      ia.n_teeth  = 40;
      ia.internal = true;
      const SpurGear       ring(ia);
      SpurGear::Parameters ib = ia;
      ib.n_teeth              = 57;
      ib.module               = 0.8;
      ib.pressure_angle       = 25 * pi / 180;
      ib.backlash             = 0.03;
      ib.rack_tip_radius      = 0.25;
      ib.center               = dealii::Point<2>(-40., 25.);
      ib.rotation             = -0.7;
      ib.rim_radius           = 30.;
      const SpurGear ring_b(ib);
      // profile shifts of both signs, and tip relief (linear, parabolic)
      SpurGear::Parameters ic = ia;
      ic.module               = 1.5;
      ic.n_teeth              = 48;
      ic.profile_shift        = 0.3;
      ic.tip_relief           = 0.015;
      ic.relief_shape         = SpurGear::ReliefShape::parabolic;
      ic.center               = dealii::Point<2>(3e3, -1e3);
      const SpurGear       ring_c(ic);
      SpurGear::Parameters id = ia;
      id.n_teeth              = 61;
      id.profile_shift        = -0.25;
      id.tip_relief           = 0.02;
      id.tip_relief_radius    = 60.2;
      id.backlash             = 0.05;
      const SpurGear ring_d(id);
      check_internal_geometry(ring, "internal m 2, z 40");
      check_internal_geometry(ring_b, "internal m 0.8, z 57, 25 deg, backlash, off-centre");
      check_internal_geometry(ring_c, "internal m 1.5, z 48, x 0.3, parabolic relief 0.015, far from the origin");
      check_internal_geometry(ring_d, "internal m 2, z 61, x -0.25, linear relief 0.02 from radius 60.2, backlash");
      check(std::abs(ring_c.tip_radius() - (36. - 1.5 * 1.3)) < 1e-12 &&
              std::abs(ring_c.root_radius() - (36. + 1.5 * 0.95)) < 1e-12,
            "internal, x 0.3: tip radius r - m (h_a + x), root radius r + m (h_f - x)");
      {
        PolygonalMeshGenerators::GearMeshSettings s;
        s.n_global_refinements = 0;
        check_mesh(ring, s, "internal whole ring", false);
        s.first_tooth          = 55;
        s.n_teeth              = 4;
        s.n_global_refinements = 1;
        s.flank_cell_size      = 0.05;
        s.first_refined_tooth  = 56;
        s.n_refined_teeth      = 2;
        check_mesh(ring_b, s, "internal sector, graded flanks", true);
        s.first_tooth         = 46;
        s.n_teeth             = 3;
        s.flank_cell_size     = 0.1;
        s.first_refined_tooth = 47;
        s.n_refined_teeth     = 1;
        check_mesh(ring_c, s, "internal sector with shift and tip relief, graded flanks", true);
      }

      // sector meshes graded toward the flanks, with patch tests
      PolygonalMeshGenerators::GearMeshSettings s;
      s.first_tooth          = 2;
      s.n_teeth              = 3;
      s.n_global_refinements = 0;
      s.flank_cell_size      = 0.05 * a.module;
      s.fillet_cell_size     = 0.1 * a.module;
      s.first_refined_tooth  = 3;
      s.n_refined_teeth      = 1;
      check_mesh(standard, s, "m 2, z 20, three teeth, fillets graded", true);
      s.fillet_cell_size    = 0;
      s.first_tooth         = 12;
      s.n_teeth             = 2;
      s.flank_cell_size     = 0.05;
      s.first_refined_tooth = 0;
      s.n_refined_teeth     = 0;
      check_mesh(small, s, "m 1, z 13, two teeth", true);
      // the whole gear
      PolygonalMeshGenerators::GearMeshSettings w;
      w.n_global_refinements = 0;
      check_mesh(small, w, "m 1, z 13, whole", true);
      check_mesh(large, w, "m 0.5, z 61, whole", false);

      // the boundary converges to the exact one at rate 2: the sag of the
      // straight edges on the teeth (their midpoints' distance from the
      // outline), and the area between the bore polygon and the centre
      {
        double       error[2][4];
        const double tau = standard.angular_pitch() / 2, rb = standard.parameters().bore_radius;
        const double bore_exact = -0.5 * rb * rb * 4 * tau;
        for (unsigned int l = 0; l < 4; ++l)
          {
            PolygonalMeshGenerators::GearMeshSettings u;
            u.first_tooth          = 4;
            u.n_teeth              = 2;
            u.n_global_refinements = l;
            PolygonalMesh<2> mesh;
            PolygonalMeshGenerators::spur_gear(mesh, standard, u);
            double part[4] = {0, 0, 0, 0}, sag = 0;
            for (const auto &e : mesh.get_edges())
              if (e.at_boundary())
                {
                  const auto p = mesh.vertex(e.vertices[0]), q = mesh.vertex(e.vertices[1]);
                  part[e.boundary_id] += 0.5 * (p[0] * q[1] - p[1] * q[0]);
                  if (e.boundary_id == 1)
                    sag = std::max(sag, standard.distance_to_outline(0.5 * (p + q)));
                }
            check_small(mesh.total_area() / (part[0] + part[1] + part[2] + part[3]) - 1, 1e-13,
                        "level " + std::to_string(l) + ": the polygons tile the region their boundary encloses");
            error[0][l] = std::abs(part[0] / bore_exact - 1);
            error[1][l] = sag / standard.tip_radius();
            std::cout << "      level " << l << ": bore area error " << error[0][l] << ", largest sag on the teeth "
                      << error[1][l] << " (relative)" << std::endl;
          }
        // rates from level 1 to 3; the largest sag is pre-asymptotic (the
        // finer edges sample the fillet's largest curvature better): 1.80
        const double bore_rate = std::log2(error[0][1] / error[0][3]) / 2;
        const double sag_rate  = std::log2(error[1][1] / error[1][3]) / 2;
        check(bore_rate > 1.98 && bore_rate < 2.02,
              "bore polygon converges at rate 2 (" + std::to_string(bore_rate) + ")");
        check(sag_rate > 1.75 && sag_rate < 2.1,
              "largest sag on the teeth converges at rate 2 (" + std::to_string(sag_rate) + ")");
        PolygonalMesh<2> whole;
        PolygonalMeshGenerators::spur_gear(whole, standard, w);
        check_small(standard.area(0, 20) / (20 * standard.area(7, 1)) - 1, 1e-12, "sector areas add to the gear's");
      }

      // gmsh output: MeshIO::write_msh writes the graded triangulation,
      // MeshIO::read_msh reads it back as the same polygons
      {
        PolygonalMeshGenerators::GearMeshSettings g;
        g.first_tooth     = 0;
        g.n_teeth         = 2;
        g.flank_cell_size = 0.1;
        dealii::Triangulation<2> tria;
        PolygonalMeshGenerators::spur_gear(tria, standard, g);
        MeshIO::write_msh(tria, "gear.msh");
        PolygonalMesh<2> direct, from_file;
        PolygonalMeshGenerators::from_triangulation(direct, tria);
        MeshIO::read_msh(from_file, "gear.msh");
        check(direct.n_cells() == from_file.n_cells() && direct.n_vertices() == from_file.n_vertices() &&
                direct.n_edges() == from_file.n_edges(),
              "gmsh round trip: the same numbers of polygons, vertices and edges (" +
                std::to_string(from_file.n_cells()) + ", " + std::to_string(from_file.n_vertices()) + ", " +
                std::to_string(from_file.n_edges()) + ")");
        check_small(from_file.total_area() / direct.total_area() - 1, 1e-12, "gmsh round trip: the same area");
        unsigned int ids_direct[4] = {0, 0, 0, 0}, ids_file[4] = {0, 0, 0, 0};
        for (const auto &e : direct.get_edges())
          if (e.at_boundary())
            ++ids_direct[e.boundary_id];
        for (const auto &e : from_file.get_edges())
          if (e.at_boundary() && e.boundary_id < 4)
            ++ids_file[e.boundary_id];
        check(std::equal(ids_direct, ids_direct + 4, ids_file), "gmsh round trip: the same boundary ids");
      }

      // data that give no gear
      using testing::check_throws;
      SpurGear::Parameters bad = a;
      bad.n_teeth              = 9;
      check_throws([&] { SpurGear g(bad); }, "undercut", "9 teeth without shift: undercut");
      bad.profile_shift = 0.6;
      (void)SpurGear(bad);
      check(true, "9 teeth with shift 0.6: no undercut");
      bad                 = a;
      bad.rack_tip_radius = 0.7;
      check_throws([&] { SpurGear g(bad); }, "rack tip is too round", "rack tip radius 0.7");
      bad               = a;
      bad.addendum      = 1.6;
      bad.profile_shift = 0.6;
      check_throws([&] { SpurGear g(bad); }, "pointed", "addendum 1.6 with shift 0.6: pointed teeth");
      bad             = a;
      bad.bore_radius = 18;
      check_throws([&] { SpurGear g(bad); }, "bore radius", "bore beyond the root circle");
      bad            = a;
      bad.tip_relief = 0.5;
      check_throws([&] { SpurGear g(bad); }, "tip relief", "tip relief larger than the tip land");
      bad                = a;
      bad.pressure_angle = 40 * pi / 180;
      check_throws([&] { SpurGear g(bad); }, "pressure angle", "pressure angle 40 degrees");
      bad         = ia;
      bad.n_teeth = 14;
      check_throws([&] { SpurGear g(bad); }, "outside the base circle",
                   "internal, 14 teeth: tip inside the base circle");
      bad                   = ia;
      bad.tip_relief        = 0.02;
      bad.tip_relief_radius = 43;
      check_throws([&] { SpurGear g(bad); }, "tip relief radius 43 of an internal gear must lie between",
                   "internal, relief radius beyond the form radius");
      bad            = ia;
      bad.tip_relief = 0.8;
      check_throws([&] { SpurGear g(bad); }, "removes the tooth's tip land", "internal, relief larger than the land");
      bad             = ia;
      bad.bore_radius = 10;
      check_throws([&] { SpurGear g(bad); }, "no bore", "internal with a bore radius");
      bad            = ia;
      bad.rim_radius = 42;
      check_throws([&] { SpurGear g(bad); }, "rim radius", "internal, rim inside root + m");
      bad            = a;
      bad.rim_radius = 40;
      check_throws([&] { SpurGear g(bad); }, "rim radius is for internal gears", "external with a rim radius");
    }
  catch (const std::exception &e)
    {
      std::cerr << "Exception: " << e.what() << std::endl;
      return 1;
    }
  return testing::finish();
}
