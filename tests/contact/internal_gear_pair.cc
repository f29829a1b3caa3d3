// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// A pinion inside a ring gear, in contact at the pitch point (issue 41,
// item 1): pinion z1 = 20, internal gear z2 = 50, module 1, 20 degrees,
// centre distance r2 - r1, the ring's addendum 0.6 m (so that one tooth
// pair carries the load at the pitch point), backlash allowance 0.05 on
// each, steel
// (E = 210000, nu = 0.3, plane strain), k = 2, frictionless unilateral
// contact between the tooth outlines of three-tooth sectors (the middle
// teeth graded toward the flanks around the pitch circle). The pinion's
// bore turns by 4e-4 rad about its centre (the origin); the ring's rim is
// clamped. Asserted, from what the geometry and equilibrium fix:
// - the contact force lies along the line of action (the normal of both
//   involutes at the pitch point, tangent to both base circles on the same
//   side): angle below 2e-4 rad;
// - its moment about each centre is the normal force times that gear's
//   base radius, both in the same sense (a ring turns the way its pinion
//   does): 5e-4 relative;
// - the peak of the recovered pressure against Hertz for a convex flank
//   (radius r1 sin(alpha)) in a concave one (r2 sin(alpha)):
//   R = rho1 rho2 / (rho2 - rho1), within 1 %, with a/h >= 8 for the mean
//   edge length h of the closed zone;
// - the centre of pressure is the pitch point to a tenth of an edge.
#include <deal.II/base/function.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/elasticity/support_reactions.h>
#include <dealvem/mesh/spur_gear.h>

#include "../tests.h"

#include <cmath>
#include <iostream>

using namespace dealvem;
using testing::check;
using testing::check_small;

namespace
{
  const double       pi = std::acos(-1.);
  const double       m = 1, E = 210e3, nu = 0.3, theta = 4e-4, h = 0.005, j = 0.05, alpha = 20 * pi / 180;
  const unsigned int z1 = 20, z2 = 50;
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const double           r1 = m * z1 / 2, r2 = m * z2 / 2, rb1 = r1 * std::cos(alpha), rb2 = r2 * std::cos(alpha);
      const dealii::Point<2> c1(0, 0), c2(-(r2 - r1), 0); // the pitch point (r1, 0)
      SpurGear::Parameters   p1, p2;
      p1.module = p2.module = m;
      p1.n_teeth            = z1;
      p2.n_teeth            = z2;
      p1.backlash = p2.backlash = j;
      p2.internal               = true;
      // with the full addendum the contact ratio is 2.0 and the pitch point
      // lies where two tooth pairs touch; 0.6 m shortens the approach to
      // 1.95 m, so one pair carries the load there
      p2.addendum = 0.6;
      // the pinion's upper flank and the ring tooth's lower flank through the pitch point
      p1.center      = c1;
      p1.rotation    = -(m * pi / 2 - j) / (2 * r1);
      p2.center      = c2;
      p2.rotation    = (m * pi / 2 - j) / (2 * r2);
      p1.bore_radius = 0.5 * r1;
      p2.rim_radius  = r2 + 4 * m;
      const SpurGear g1(p1), g2(p2);

      PolygonalMeshGenerators::GearMeshSettings m1;
      m1.first_tooth          = z1 - 1;
      m1.n_teeth              = 3;
      m1.n_global_refinements = 1;
      m1.flank_cell_size      = h;
      m1.first_refined_tooth  = 0;
      m1.n_refined_teeth      = 1;
      m1.refine_from_radius   = r1 - 0.15 * m;
      m1.refine_to_radius     = r1 + 0.15 * m;
      auto m2                 = m1;
      m2.first_tooth          = z2 - 1;
      m2.refine_from_radius   = r2 - 0.15 * m;
      m2.refine_to_radius     = r2 + 0.15 * m;
      PolygonalMesh<2> mesh1, mesh2;
      PolygonalMeshGenerators::spur_gear(mesh1, g1, m1);
      PolygonalMeshGenerators::spur_gear(mesh2, g2, m2);

      ContactProblem problem(MPI_COMM_SELF);
      problem.add_body(mesh1, ElasticMaterial(E, nu, ElasticMaterial::Model::plane_strain));
      problem.add_body(mesh2, ElasticMaterial(E, nu, ElasticMaterial::Model::plane_strain), 10);
      problem.add_contact_pair(1, 11);
      auto &bc = problem.boundary_conditions();
      // the bore turned rigidly by theta (the exact rotation as Dirichlet data)
      bc.add_rotation_about_centre(0, c1, std::make_shared<dealii::Functions::ConstantFunction<2>>(theta), false,
                                   "pinion bore");
      bc.add_dirichlet(10, {{true, true}}, std::make_shared<dealii::Functions::ZeroFunction<2>>(2));
      auto &o              = problem.options();
      o.contact.normal     = ContactSettings::Normal::unilateral;
      o.contact.tangential = ContactSettings::Tangential::frictionless;
      o.write_vtu = o.write_json = o.write_pictures = o.write_csv = false;
      o.base_name                                                 = "internal_gear_pair";
      problem.run();
      const auto &r = problem.get_results();

      dealii::Tensor<1, 2>       force;
      dealii::Point<2>           centre;
      double                     normal_force = 0, moment_1 = 0, moment_2 = 0, p_max = 0, lo = 1e300, hi = -1e300;
      unsigned int               n_active = 0;
      const dealii::Tensor<1, 2> tangent({std::cos(alpha), -std::sin(alpha)});
      for (const auto &pr : r.pairs)
        if (pr.active)
          {
            ++n_active;
            const dealii::Tensor<1, 2> f = -pr.multiplier * pr.normal; // on the ring (the slave)
            force += f;
            normal_force += -pr.multiplier;
            moment_1 += SupportReactions::moment(pr.location, -f, c1);
            moment_2 += SupportReactions::moment(pr.location, f, c2);
            centre += -pr.multiplier * dealii::Tensor<1, 2>(pr.location);
            p_max = std::max(p_max, pr.pressure);
            lo    = std::min(lo, dealii::Tensor<1, 2>(pr.location) * tangent);
            hi    = std::max(hi, dealii::Tensor<1, 2>(pr.location) * tangent);
          }
      centre /= normal_force;
      const double mean_edge = 2 * (hi - lo) / std::max(1u, n_active - 1);
      std::cout << "      " << r.n_dofs << " DoFs, " << n_active << " closed pairs, p_max " << p_max
                << ", normal force " << normal_force << std::endl;
      check(n_active >= 10, "the flanks touch over a zone (" + std::to_string(n_active) + " closed pairs)");

      const dealii::Tensor<1, 2> line({std::sin(alpha), std::cos(alpha)});
      check_small(std::acos(std::min(1., force * line / force.norm())), 2e-4,
                  "contact force along the line of action (radians)");
      check_small(-moment_1 / (normal_force * rb1) - 1, 5e-4, "pinion torque = normal force x r_b1");
      check_small(moment_2 / (normal_force * rb2) - 1, 5e-4,
                  "ring torque = normal force x r_b2, in the pinion's sense of rotation");

      const double rho1 = r1 * std::sin(alpha), rho2 = r2 * std::sin(alpha);
      const double R = rho1 * rho2 / (rho2 - rho1), Es = E / (2 * (1 - nu * nu));
      const double p0 = std::sqrt(normal_force * Es / (pi * R)), a = std::sqrt(4 * normal_force * R / (pi * Es));
      std::cout << "      Hertz: R " << R << ", p0 " << p0 << ", a " << a << ", a/h " << a / mean_edge << std::endl;
      check(a / mean_edge >= 8, "the contact zone is resolved: a/h = " + std::to_string(a / mean_edge));
      check_small(p_max / p0 - 1, 0.01, "peak pressure against Hertz, convex in concave flank (relative)");
      check_small(centre.distance(dealii::Point<2>(r1, 0)) / mean_edge, 0.1,
                  "centre of pressure at the pitch point (in edge lengths)");
    }
  catch (const std::exception &e)
    {
      std::cerr << "Exception: " << e.what() << std::endl;
      return 1;
    }
  return testing::finish();
}
