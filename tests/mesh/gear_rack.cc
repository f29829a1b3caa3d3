// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// GearRack and PolygonalMeshGenerators::gear_rack (issue 41, item 1), on
// three racks: a basic ISO 53 one (m = 2, five teeth), an offset one with
// backlash, a thin fillet, 25 degrees and an off-origin position (m = 1.5,
// x = 0.3), and one with sharp root corners and a negative offset (m = 0.8,
// x = -0.2, rho_f = 0). Checked against what the geometry fixes, computed
// here from the data by other formulas than the class uses:
// - the outline is continuous at every joint, its tangent continuous at
//   both ends of each fillet;
// - every flank point (of the outline, and every mesh vertex on a flank)
//   lies on the flank line, the line through the point of the pitch line
//   half a tooth thickness from the axis at the angle alpha from the normal
//   of the pitch line (1e-13 relative);
// - the tooth thickness at the pitch line, measured on the outline, is
//   m (pi/2 + 2 x tan alpha) - backlash (1e-13 relative);
// - the fillet is an arc of radius rho_f whose centre lies rho_f from the
//   flank line and from the root line, tangent to both;
// - area() is the closed form of the rack's area (body, teeth, fillets);
//   outline_coordinate() inverts outline_point();
// - the meshes: tooth vertices on the exact outline, back line and sides
//   with ids 0, 2, 3, the flank zones' edges at most 1.3 times the requested
//   size, and a linear displacement reproduced to round-off with k = 1 and
//   k = 2 on the graded meshes;
// - data that give no rack are refused with a message naming the cause.
#include <deal.II/base/function.h>

#include <dealvem/mesh/gear_rack.h>
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

  /// The distance of @p q from the flank line of tooth @p k on side @p side
  /// (-1 left, +1 right), from the data alone.
  double
  flank_line_distance(const GearRack::Parameters &prm, const unsigned int k, const int side, const dealii::Point<2> &q)
  {
    const double m = prm.module, a = prm.pressure_angle;
    const double s = m * (pi / 2 + 2 * prm.profile_shift * std::tan(a)) - prm.backlash;
    // the point of the pitch line on the flank, and the flank's unit normal
    const dealii::Point<2>     o(prm.position + k * pi * m + side * s / 2, prm.pitch_line_height);
    const dealii::Tensor<1, 2> n({side * std::cos(a), std::sin(a)});
    return std::abs((q - o) * n);
  }

  void
  check_geometry(const GearRack &rack, const std::string &name)
  {
    const auto        &prm = rack.parameters();
    const auto        &st  = rack.piece_starts();
    const double       L = rack.outline_pitch_length(), m = prm.module, a = prm.pressure_angle;
    const unsigned int n   = rack.n_teeth();
    const auto         P   = [&](const double s) { return rack.outline_point(s); };
    const double       rho = prm.root_fillet_radius * m;

    // continuity at every joint of every tooth; tangents at the fillets' ends
    double jump = 0, kink = 0;
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int j = 0; j <= 7; ++j)
        {
          const double s = k * L + st[j], h = 1e-7 * L;
          const auto   left = 2 * P(s - h) - P(s - 2 * h), right = 2 * P(s + h) - P(s + 2 * h);
          jump = std::max(jump, (left - right).norm() / L);
          if (rho > 0 && (j == 1 || j == 2 || j == 5 || j == 6))
            {
              const auto t0 = rack.outline_tangent(s - 1e-9 * L), t1 = rack.outline_tangent(s + 1e-9 * L);
              kink = std::max(kink, std::acos(std::min(1., t0 * t1)));
            }
        }
    check_small(jump, 1e-12, name + ": outline continuous at the joints (relative to the pitch)");
    check_small(kink, 1e-7, name + ": tangent continuous where the fillets meet flank and root line (radians)");

    // flank points on the flank lines
    double off = 0;
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int i = 0; i <= 40; ++i)
        {
          off = std::max(off, flank_line_distance(prm, k, -1, P(k * L + st[2] + (st[3] - st[2]) * i / 40.)));
          off = std::max(off, flank_line_distance(prm, k, +1, P(k * L + st[4] + (st[5] - st[4]) * i / 40.)));
        }
    check_small(off / m, 1e-13, name + ": flank points on the straight flank lines (relative to m)");

    // the thickness at the pitch line, where the flanks cross it (bisection on each flank)
    {
      const auto crossing = [&](double lo, double hi) {
        const bool rising = P(hi)[1] > P(lo)[1];
        for (unsigned int it = 0; it < 200; ++it)
          {
            const double mid                                          = 0.5 * (lo + hi);
            ((P(mid)[1] < prm.pitch_line_height) == rising ? lo : hi) = mid;
          }
        return P(0.5 * (lo + hi))[0];
      };
      const unsigned int k         = n / 2;
      const double       thickness = crossing(k * L + st[4], k * L + st[5]) - crossing(k * L + st[2], k * L + st[3]);
      const double       expected  = m * (pi / 2 + 2 * prm.profile_shift * std::tan(a)) - prm.backlash;
      std::cout << "      " << name << ": thickness at the pitch line " << thickness << " (" << expected << ")"
                << std::endl;
      check_small(thickness / expected - 1, 1e-13, name + ": tooth thickness at the pitch line (relative)");
    }

    // the fillet: an arc of radius rho tangent to flank and root line
    if (rho > 0)
      {
        const double y_f    = prm.pitch_line_height - (prm.dedendum - prm.profile_shift) * m;
        double       radius = 0;
        for (unsigned int k = 0; k < n; ++k)
          {
            const dealii::Point<2> c = rack.fillet_center(k), cl(2 * rack.tooth_axis(k) - c[0], c[1]);
            for (unsigned int i = 0; i <= 20; ++i)
              {
                radius = std::max(radius, std::abs(P(k * L + st[5] + (st[6] - st[5]) * i / 20.).distance(c) - rho));
                radius = std::max(radius, std::abs(P(k * L + st[1] + (st[2] - st[1]) * i / 20.).distance(cl) - rho));
              }
            check_small(flank_line_distance(prm, k, +1, c) / rho - 1, 1e-13,
                        name + ": fillet centre rho from the flank line (relative), tooth " + std::to_string(k));
            check_small((c[1] - y_f) / rho - 1, 1e-13,
                        name + ": fillet centre rho above the root line (relative), tooth " + std::to_string(k));
          }
        check_small(radius / rho, 1e-13, name + ": fillet points rho from the centre (relative)");
        // tangency: the tangent at the form point is the flank's direction, at the root the root line's
        const auto t_form = rack.outline_tangent(st[5]), t_root = rack.outline_tangent(st[6]);
        check_small(std::abs(t_form[0] - std::sin(a)) + std::abs(t_form[1] + std::cos(a)), 1e-14,
                    name + ": fillet tangent to the flank");
        check_small(std::abs(t_root[0] - 1) + std::abs(t_root[1]), 1e-14, name + ": fillet tangent to the root line");
      }

    // the area in closed form: per pitch the body below the root line, and
    // per half tooth the tip land, the trapezoid under the flank and the
    // region under the fillet (a rectangle less a circular segment)
    {
      const double tan_a = std::tan(a), y_t = (prm.addendum + prm.profile_shift) * m,
                   y_f        = -(prm.dedendum - prm.profile_shift) * m;
      const double s_p        = m * (pi / 2 + 2 * prm.profile_shift * tan_a) - prm.backlash;
      const double w_t        = s_p / 2 - y_t * tan_a;         // half the tip land
      const double y_T        = y_f + rho * (1 - std::sin(a)); // form point
      const double x_T        = s_p / 2 - y_T * tan_a;         // ... on the flank line
      const double half_tooth = w_t * (y_t - y_f) + (x_T - w_t) * (y_t - y_f + y_T - y_f) / 2 +
                                rho * rho * (std::cos(a) - 0.5 * std::sin(a) * std::cos(a) - 0.5 * (pi / 2 - a));
      const double exact = n * (pi * m * prm.body_depth + 2 * half_tooth);
      check_small(rack.area() / exact - 1, 1e-14, name + ": area() against the closed form (relative)");
    }

    // the inverse
    double back = 0;
    for (unsigned int i = 0; i < 500; ++i)
      {
        const double s = n * L * (i + 0.37) / 500;
        back           = std::max(back, std::abs(rack.outline_coordinate(P(s)) - s) / L);
      }
    check_small(back, 1e-13, name + ": outline_coordinate inverts outline_point (relative to the pitch)");

    // outline(): from the left end to the right end on the root line, at
    // most the spacing apart, every point on the outline
    {
      const double spacing = 0.07 * m;
      const auto   pts     = rack.outline(spacing);
      const auto   ext     = rack.extent();
      double       gap = 0, dist = 0;
      for (unsigned int i = 0; i < pts.size(); ++i)
        {
          dist = std::max(dist, rack.distance_to_outline(pts[i]));
          if (i > 0)
            gap = std::max(gap, pts[i].distance(pts[i - 1]));
        }
      check(gap <= spacing * (1 + 1e-12) && dist < 1e-13 * m &&
              pts.front().distance(dealii::Point<2>(ext[0], rack.root_height())) < 1e-13 * m &&
              pts.back().distance(dealii::Point<2>(ext[1], rack.root_height())) < 1e-13 * m,
            name + ": outline() runs from side to side on the outline, points at most the spacing apart (" +
              std::to_string(pts.size()) + " points)");
    }
  }

  void
  check_mesh(const GearRack                                  &rack,
             const PolygonalMeshGenerators::RackMeshSettings &settings,
             const std::string                               &name,
             const bool                                       patch_test)
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::gear_rack(mesh, rack, settings);
    const auto  &prm = rack.parameters();
    const double m   = prm.module;
    const auto   ext = rack.extent();
    double       off = 0, flank_off = 0, bottom = 0, sides = 0, longest = 0, longest_fillet = 0;
    unsigned int n_ids[4] = {0, 0, 0, 0};
    // the refined zones (none given: both whole flanks of every tooth)
    auto zones = settings.zones;
    if (zones.empty())
      for (unsigned int k = 0; k < rack.n_teeth(); ++k)
        zones.push_back({k});
    for (const auto &e : mesh.get_edges())
      {
        if (!e.at_boundary())
          continue;
        AssertThrow(e.boundary_id < 4, dealii::ExcInternalError());
        ++n_ids[e.boundary_id];
        const auto a = mesh.vertex(e.vertices[0]), b = mesh.vertex(e.vertices[1]);
        if (e.boundary_id == 1)
          {
            off                = std::max({off, rack.distance_to_outline(a), rack.distance_to_outline(b)});
            const double s_mid = rack.outline_coordinate(0.5 * (a + b));
            const auto   piece = rack.piece(s_mid);
            // the tooth and side of the edge
            const unsigned int k    = std::lround((0.5 * (a[0] + b[0]) - prm.position) / rack.pitch());
            const int          side = 0.5 * (a[0] + b[0]) > rack.tooth_axis(k) ? 1 : -1;
            if (piece == GearRack::Piece::flank)
              flank_off =
                std::max({flank_off, flank_line_distance(prm, k, side, a), flank_line_distance(prm, k, side, b)});
            // in a refined zone?
            for (const auto &z : zones)
              if (z.tooth == k && (z.flank == PolygonalMeshGenerators::RackMeshSettings::Flank::both ||
                                   (side < 0) == (z.flank == PolygonalMeshGenerators::RackMeshSettings::Flank::left)))
                {
                  const double y = 0.5 * (a[1] + b[1]) - prm.pitch_line_height;
                  if (piece == GearRack::Piece::flank && y > z.from_height && y < z.to_height)
                    longest = std::max(longest, a.distance(b));
                  if (piece == GearRack::Piece::fillet)
                    longest_fillet = std::max(longest_fillet, a.distance(b));
                }
          }
        if (e.boundary_id == 0)
          bottom = std::max({bottom, std::abs(a[1] - rack.bottom_height()), std::abs(b[1] - rack.bottom_height())});
        if (e.boundary_id >= 2)
          {
            const double x = ext[e.boundary_id - 2];
            sides          = std::max({sides, std::abs(a[0] - x), std::abs(b[0] - x)});
          }
      }
    check_small(off / m, 1e-13, name + ": tooth vertices on the exact outline (relative to m)");
    check_small(flank_off / m, 1e-13, name + ": flank vertices on the straight flank lines (relative to m)");
    check_small((bottom + sides) / m, 1e-13, name + ": back line and side vertices in place");
    check(n_ids[0] > 0 && n_ids[1] > 0 && n_ids[2] > 0 && n_ids[3] > 0,
          name + ": boundary ids 0 back, 1 teeth, 2 and 3 the sides (" + std::to_string(n_ids[0]) + ", " +
            std::to_string(n_ids[1]) + ", " + std::to_string(n_ids[2]) + ", " + std::to_string(n_ids[3]) + " edges)");
    if (settings.flank_cell_size > 0)
      check(longest <= 1.3 * settings.flank_cell_size * (1 + 1e-9) && longest > 0.3 * settings.flank_cell_size,
            name + ": flank zone edges at most 1.3 h (" + std::to_string(longest / settings.flank_cell_size) + " h)");
    if (settings.fillet_cell_size > 0)
      check(longest_fillet <= 1.3 * settings.fillet_cell_size * (1 + 1e-9) &&
              longest_fillet > 0.3 * settings.fillet_cell_size,
            name + ": fillet edges at most 1.3 h_fillet (" +
              std::to_string(longest_fillet / settings.fillet_cell_size) + " h_fillet)");
    std::cout << "      " << name << ": " << mesh.n_cells() << " polygons, " << mesh.n_vertices() << " vertices"
              << std::endl;

    if (patch_test)
      for (const unsigned int k : {1u, 2u})
        {
          const double error = testing::linear_patch_test_error(mesh, k);
          std::cout << "      " << name << ": patch test k = " << k << ", relative error " << error << std::endl;
          check_small(error, 1e-11, name + ": linear patch test, k = " + std::to_string(k));
        }
  }
} // namespace


int
main()
{
  try
    {
      GearRack::Parameters a;
      a.module = 2;
      const GearRack basic(a);

      GearRack::Parameters b;
      b.module             = 1.5;
      b.n_teeth            = 4;
      b.pressure_angle     = 25 * pi / 180;
      b.profile_shift      = 0.3;
      b.root_fillet_radius = 0.2;
      b.backlash           = 0.08;
      b.body_depth         = 5;
      b.pitch_line_height  = -37.5;
      b.position           = 120.25;
      const GearRack offset(b);

      GearRack::Parameters c;
      c.module             = 0.8;
      c.n_teeth            = 3;
      c.profile_shift      = -0.2;
      c.root_fillet_radius = 0;
      c.addendum           = 0.9;
      const GearRack sharp(c);

      check_geometry(basic, "m 2, 5 teeth");
      check_geometry(offset, "m 1.5, x 0.3, 25 deg, backlash, off-origin");
      check_geometry(sharp, "m 0.8, x -0.2, sharp root corners");

      using Settings = PolygonalMeshGenerators::RackMeshSettings;
      {
        Settings s;
        s.n_global_refinements = 0;
        check_mesh(basic, s, "m 2, coarse", true);
      }
      {
        Settings s;
        s.n_global_refinements = 1;
        s.flank_cell_size      = 0.04 * a.module;
        s.fillet_cell_size     = 0.1 * a.module;
        s.zones.push_back({2, -0.3 * a.module, 0.3 * a.module, Settings::Flank::left});
        check_mesh(basic, s, "m 2, left flank of tooth 2 graded", true);
      }
      {
        Settings s;
        s.n_global_refinements = 0;
        s.flank_cell_size      = 0.05;
        s.zones.push_back({1, -1e300, 1e300, Settings::Flank::both});
        s.zones.push_back({3, 0, 1e300, Settings::Flank::right});
        check_mesh(offset, s, "m 1.5, offset, two teeth graded", true);
      }
      {
        Settings s;
        s.flank_cell_size = 0.05;
        check_mesh(sharp, s, "m 0.8, sharp corners, every flank graded", true);
      }

      // data that give no rack
      using testing::check_throws;
      GearRack::Parameters bad = a;
      bad.module               = -1;
      check_throws([&] { GearRack r(bad); }, "GearRack: the module must be positive", "negative module");
      bad         = a;
      bad.n_teeth = 0;
      check_throws([&] { GearRack r(bad); }, "number of teeth", "no teeth");
      bad                = a;
      bad.pressure_angle = 50 * pi / 180;
      check_throws([&] { GearRack r(bad); }, "pressure angle must lie between 0 and 45", "pressure angle 50 degrees");
      bad                    = a;
      bad.root_fillet_radius = 0.8;
      check_throws([&] { GearRack r(bad); }, "does not fit in the tooth space", "root fillet radius 0.8 m");
      bad                    = a;
      bad.root_fillet_radius = -0.1;
      check_throws([&] { GearRack r(bad); }, "root fillet radius coefficient must not be negative",
                   "negative fillet radius");
      bad          = a;
      bad.backlash = -1.5;
      check_throws([&] { GearRack r(bad); }, "teeth overlap at the root line", "backlash -1.5 (thicker teeth)");
      bad          = a;
      bad.backlash = 3.2;
      check_throws([&] { GearRack r(bad); }, "thins the teeth to nothing", "backlash 3.2 (more than the tooth)");
      bad          = a;
      bad.addendum = 2.5;
      check_throws([&] { GearRack r(bad); }, "teeth are pointed", "addendum 2.5: pointed teeth");
      bad          = a;
      bad.addendum = 0;
      bad.dedendum = 0.1;
      check_throws([&] { GearRack r(bad); }, "the fillet would reach the tip line",
                   "addendum 0, dedendum 0.1: the fillet reaches the tip");
      bad            = a;
      bad.body_depth = -1;
      check_throws([&] { GearRack r(bad); }, "body depth must not be negative", "negative body depth");
      bad            = a;
      bad.body_depth = 0.05;
      {
        const GearRack thin(bad);
        Settings       s;
        check_throws(
          [&] {
            PolygonalMesh<2> mesh;
            PolygonalMeshGenerators::gear_rack(mesh, thin, s);
          },
          "leaves no body under the teeth", "mesher: body depth 0.05");
        s.zones.push_back({1, 3., 4., Settings::Flank::both});
        s.flank_cell_size = 0.1;
        bad.body_depth    = 0;
        const GearRack ok(bad);
        check_throws(
          [&] {
            PolygonalMesh<2> mesh;
            PolygonalMeshGenerators::gear_rack(mesh, ok, s);
          },
          "holds no point of the flank", "mesher: zone above the tip");
        s.zones[0] = {7, -1., 1., Settings::Flank::both};
        check_throws(
          [&] {
            PolygonalMesh<2> mesh;
            PolygonalMeshGenerators::gear_rack(mesh, ok, s);
          },
          "is not one of the rack's 5 teeth", "mesher: zone on tooth 7");
      }
    }
  catch (const std::exception &e)
    {
      std::cerr << "Exception: " << e.what() << std::endl;
      return 1;
    }
  return testing::finish();
}
