// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// A pinion on a rack, in contact at the pitch point (issue 41, item 1):
// pinion z = 20, module 2, 20 degrees, its centre at (0, r) above the pitch
// point (the origin); a rack of three teeth with its pitch line along the
// x axis, the addendum 0.8 m (with the full addendum the pitch point lies
// 0.05 mm inside the end of the single-contact zone, where the next pair's
// rack tip corner nearly touches; 0.8 m puts it 1.3 mm inside), backlash
// allowance 0.1 on each, steel (E = 210000, nu = 0.3, plane strain), k = 2,
// frictionless unilateral contact between the pinion's three-tooth sector
// and the rack, the two flanks through the pitch point graded. The pinion's
// bore turns by 4e-4 rad about the centre (counter-clockwise: the pinion
// drives the rack toward +x); the rack's back line is clamped. Asserted,
// from what the geometry and equilibrium fix:
// - the contact force on the rack lies along the line of action, the
//   normal of the straight rack flank: (cos alpha, -sin alpha), at the
//   pressure angle from the pitch line: angle below 1e-4 rad;
// - moment balance of the pinion: with T the moment the bore's constraints
//   exert about the centre, T = F (r_b - s_cp), r_b = r cos alpha and s_cp
//   the centre of pressure's offset from the pitch point along the rack
//   flank (the pair forces are parallel, each with its own lever): 1e-8
//   relative; the normal force is T / r_b and the rack's support reaction
//   along the pitch line T / r to 5e-5 (s_cp / r_b = -2.1e-5: the pressure
//   is not quite symmetric about the pitch point, as the involute's
//   curvature changes across the zone);
// - the peak of the recovered pressure against Hertz for the pinion's
//   involute (radius of curvature sqrt(rho^2 - r_b^2) at the centre of
//   pressure, radius rho from the pinion's centre) on the flat rack flank
//   (R2 infinite), within 1 %, with a/h >= 8 for the mean edge length h of
//   the closed zone;
// - one tooth pair carries the load (every closed pair within 1.5 a of the
//   pitch point), and the centre of pressure is the pitch point to a fifth
//   of an edge.
#include <deal.II/base/function.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/elasticity/support_reactions.h>
#include <dealvem/mesh/gear_rack.h>
#include <dealvem/mesh/spur_gear.h>

#include "../tests.h"

#include <chrono>
#include <cmath>
#include <iostream>

using namespace dealvem;
using testing::check;
using testing::check_small;

namespace
{
  const double       pi = std::acos(-1.);
  const double       m = 2, E = 210e3, nu = 0.3, theta = 4e-4, h = 0.015, j = 0.1, alpha = 20 * pi / 180;
  const unsigned int z = 20;
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               start = std::chrono::steady_clock::now();
  try
    {
      const double           r = m * z / 2, rb = r * std::cos(alpha);
      const dealii::Point<2> c1(0, r), pitch_point(0, 0);

      // the pinion: tooth 0 points down, its counter-clockwise flank through the pitch point
      SpurGear::Parameters p1;
      p1.module      = m;
      p1.n_teeth     = z;
      p1.backlash    = j;
      p1.center      = c1;
      p1.rotation    = -pi / 2 - (m * pi / 2 - j) / (2 * r);
      p1.bore_radius = 0.5 * r;
      const SpurGear pinion(p1);

      // the rack: tooth 1's left flank through the pitch point
      GearRack::Parameters p2;
      p2.module   = m;
      p2.n_teeth  = 3;
      p2.addendum = 0.8;
      p2.backlash = j;
      p2.position = (m * pi / 2 - j) / 2 - pi * m;
      const GearRack rack(p2);

      PolygonalMeshGenerators::GearMeshSettings m1;
      m1.first_tooth          = z - 1;
      m1.n_teeth              = 3;
      m1.n_global_refinements = 1;
      m1.flank_cell_size      = h;
      m1.zones.push_back(
        {0, r - 0.15 * m, r + 0.15 * m, PolygonalMeshGenerators::GearMeshSettings::Flank::counter_clockwise});
      PolygonalMeshGenerators::RackMeshSettings m2;
      m2.n_global_refinements = 1;
      m2.flank_cell_size      = h;
      m2.zones.push_back({1, -0.15 * m, 0.15 * m, PolygonalMeshGenerators::RackMeshSettings::Flank::left});
      PolygonalMesh<2> mesh1, mesh2;
      PolygonalMeshGenerators::spur_gear(mesh1, pinion, m1);
      PolygonalMeshGenerators::gear_rack(mesh2, rack, m2);

      ContactProblem problem(MPI_COMM_SELF);
      problem.add_body(mesh1, ElasticMaterial(E, nu, ElasticMaterial::Model::plane_strain));
      problem.add_body(mesh2, ElasticMaterial(E, nu, ElasticMaterial::Model::plane_strain), 10);
      problem.add_contact_pair(1, 11);
      auto &bc = problem.boundary_conditions();
      bc.add_rotation_about_centre(0, c1, std::make_shared<dealii::Functions::ConstantFunction<2>>(theta), false,
                                   "pinion bore");
      bc.add_dirichlet(10, {{true, true}}, std::make_shared<dealii::Functions::ZeroFunction<2>>(2));
      auto &o              = problem.options();
      o.contact.normal     = ContactSettings::Normal::unilateral;
      o.contact.tangential = ContactSettings::Tangential::frictionless;
      o.write_vtu = o.write_json = o.write_pictures = o.write_csv = false;
      o.base_name                                                 = "rack_pinion";
      problem.run();
      const auto &res = problem.get_results();

      // the closed pairs: force on the rack (the slave), centre of pressure, peak pressure
      dealii::Tensor<1, 2>       force;
      dealii::Point<2>           centre;
      double                     normal_force = 0, p_max = 0, lo = 1e300, hi = -1e300, farthest = 0;
      unsigned int               n_active = 0;
      const dealii::Tensor<1, 2> along_flank({std::sin(alpha), std::cos(alpha)});
      for (const auto &pr : res.pairs)
        if (pr.active)
          {
            ++n_active;
            force += -pr.multiplier * pr.normal;
            normal_force += -pr.multiplier;
            centre += -pr.multiplier * dealii::Tensor<1, 2>(pr.location);
            p_max    = std::max(p_max, pr.pressure);
            farthest = std::max(farthest, pr.location.distance(pitch_point));
            lo       = std::min(lo, dealii::Tensor<1, 2>(pr.location) * along_flank);
            hi       = std::max(hi, dealii::Tensor<1, 2>(pr.location) * along_flank);
          }
      centre /= normal_force;
      const double mean_edge = 2 * (hi - lo) / std::max(1u, n_active - 1);
      std::cout << "      " << res.n_dofs << " DoFs, " << n_active << " closed pairs, p_max " << p_max
                << ", normal force " << normal_force << ", |force| " << force.norm() << std::endl;
      check(n_active >= 10, "the flanks touch over a zone (" + std::to_string(n_active) + " closed pairs)");

      // (a) the line of action: the rack flank's normal, pushing the rack toward +x and down
      const dealii::Tensor<1, 2> line({std::cos(alpha), -std::sin(alpha)});
      const double               angle = std::acos(std::min(1., force * line / force.norm()));
      std::cout << "      force direction off the line of action by " << angle << " rad" << std::endl;
      check_small(angle, 1e-4, "contact force along the line of action (radians)");

      // (b) moment balance: F = T / r_b, and the rack's support takes T / r along the pitch line
      check(!res.steps.empty() && res.steps.back().rotations.size() == 1, "one rotation about a centre");
      const double torque = res.steps.back().rotations.at(0).reaction_moment;
      double       rack_x = 0;
      for (const auto &reaction : res.steps.back().reactions)
        if (reaction.boundary_id == 10)
          rack_x += reaction.force[0];
      std::cout << "      bore torque " << torque << " (rotation " << res.steps.back().rotations.at(0).angle
                << "), normal force x r_b / T - 1 = " << force.norm() * rb / torque - 1
                << ", rack support force along the pitch line x r / T + 1 = " << rack_x * r / torque + 1 << std::endl;
      check(torque > 0,
            "the bore's constraints turn the pinion counter-clockwise (T = " + std::to_string(torque) + ")");
      // the pair forces are parallel (the rack flank's normal), so each one's
      // lever about the centre is r_b less its point's offset along the
      // flank: the pinion's moment balance is T = F (r_b - s_cp) with s_cp
      // the centre of pressure's offset from the pitch point along the flank
      const double s_cp = dealii::Tensor<1, 2>(centre) * along_flank;
      std::cout << "      centre of pressure along the flank " << s_cp << ", s_cp / r_b " << s_cp / rb << std::endl;
      check_small(force.norm() * (rb - s_cp) / torque - 1, 1e-8,
                  "pinion moment balance: T = F (r_b - s_cp) (relative)");
      // F = T / r_b up to s_cp / r_b: the Hertz zone's pressure is not quite
      // symmetric about the pitch point (the involute's curvature changes
      // across it), 2.1e-5 here
      check_small(force.norm() * rb / torque - 1, 5e-5, "normal force = T / r_b (relative)");
      check_small(rack_x * r / torque + 1, 5e-5,
                  "rack support reaction along the pitch line = -T / r, the tangential force (relative)");

      // (c) Hertz: the involute's radius of curvature at the centre of pressure on a flat flank
      const double R = std::sqrt(centre.distance_square(c1) - rb * rb), Es = E / (2 * (1 - nu * nu));
      const double p0 = std::sqrt(normal_force * Es / (pi * R)), a = std::sqrt(4 * normal_force * R / (pi * Es));
      std::cout << "      Hertz: R " << R << " (r sin alpha " << r * std::sin(alpha) << "), p0 " << p0 << ", a " << a
                << ", a/h " << a / mean_edge << ", p_max / p0 - 1 = " << p_max / p0 - 1 << std::endl;
      check(a / mean_edge >= 8, "the contact zone is resolved: a/h = " + std::to_string(a / mean_edge));
      check(farthest < 1.5 * a, "one tooth pair carries the load: every closed pair within 1.5 a of the pitch point (" +
                                  std::to_string(farthest / a) + " a)");
      check_small(p_max / p0 - 1, 0.01, "peak pressure against Hertz, involute on a flat flank (relative)");
      std::cout << "      centre of pressure " << centre << ", off the pitch point by "
                << centre.distance(pitch_point) / mean_edge << " edges" << std::endl;
      check_small(centre.distance(pitch_point) / mean_edge, 0.2, "centre of pressure at the pitch point (in edges)");
    }
  catch (const std::exception &e)
    {
      std::cerr << "Exception: " << e.what() << std::endl;
      return 1;
    }
  std::cout << "      run time " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s" << std::endl;
  return testing::finish();
}
