// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The tolerances of node insertion follow the model, not the origin (issue
// 41). Two curved contacts, small strain, non-matching meshes, unilateral
// frictionless contact, k = 2 (the default, with its default diagonal
// stabilization), one material (E = 1000, nu = 0.3):
// - Hertz: the lower half of a ring 0.5 <= r <= 1 centred at (0, 1)
//   (64 x 4 quads in the polar map) pressed by a displacement 0.02 of its
//   inner arc onto the block [-1, 1] x [-1, 0] (48 x 8 quads, bottom
//   clamped). The two sides first touch at the origin.
// - Two circles of different radii: the lower half of the same ring
//   centred at the origin (the failing class of the issue: a curved body
//   centred at the origin, the contact where x = 0) pressed by 0.02 into a
//   concave seat, a sector of the ring 1.25 <= r <= 1.75 (angles
//   225..315 degrees, 40 x 6 quads) centred at (0, 0.25), whose outer arc
//   is clamped: internal contact, effective radius 5.
// Every coordinate is computed in double precision, so the data carries
// no decimal rounding. Each model runs as given, shifted by 1e3 times its
// size, scaled by 1e-3 and 1e3 (the prescribed displacement scaled alike,
// so the strains and pressures stay the same), rotated by 90 and by 30
// degrees (the displacement rotated too; the clamped parts are clamped in
// both directions), and shifted, scaled and rotated at once. Asserted
// against the model as given: the same number of pairs and of active
// pairs, the largest recovered pressure to 1e-8 relative and the sorted
// pair pressures to 1e-8 of it (measured: 1e-10 shifted, 1e-13 scaled and
// rotated by 90 degrees). Under the old gap tolerance, 1e-5 (|x| + |y|),
// the shifted models closed real gaps near the edge of the contact zone.
// The turn by 30 degrees also checks the elements: the diagonal
// stabilization weighted the x and y components of a node by their own
// consistency stiffness, which depends on the frame; rotated by 30
// degrees, Hertz had p_max 0.79 % lower and 22 instead of 23 active pairs
// (the pairs themselves, positions, normals and weights, were the same to
// 1e-15). It now weights both by half the trace of the node's block.
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

#include "../contact_common.h"
#include "../tests.h"

namespace
{
  const double E = 1000., pi = std::acos(-1.);

  /// Translation by c, rotation by theta and scaling by s of the model.
  struct Placement
  {
    std::string name;
    double      cx = 0, cy = 0, s = 1, theta = 0;

    /// The map of the point (X, Y) (muparser expressions) as a
    /// 'Transformation' entry.
    std::string
    map(const std::string &X, const std::string &Y) const
    {
      std::ostringstream m;
      m << std::setprecision(17) << cx << " + " << s * std::cos(theta) << "*(" << X << ") - "
        << s * std::sin(theta) << "*(" << Y << "), " << cy << " + " << s * std::sin(theta) << "*(" << X
        << ") + " << s * std::cos(theta) << "*(" << Y << ")";
      return m.str();
    }

    /// The prescribed displacement (0, -d) of the model placed.
    std::string
    displacement(const double d) const
    {
      std::ostringstream m;
      m << std::setprecision(17) << s * d * std::sin(theta) << ", " << -s * d * std::cos(theta);
      return m.str();
    }
  };

  struct Outcome
  {
    std::vector<double> pressures; ///< of the active pairs, sorted
    unsigned int        n_pairs = 0, n_active = 0;
    double              p_max = 0;
  };

  /// The lower half of the ring 0.5 <= r <= 1 centred at (0, yc), from the
  /// block [0, 1]^2: x the angle (pi .. 2 pi), y inwards; its outer arc is
  /// id 12, its inner arc id 13.
  std::string
  ring_body(const Placement &place, const double yc)
  {
    std::ostringstream s;
    s << std::setprecision(17) << "subsection Body 1\n"
      << testing::block_mesh("structured quads", 0, 0, 1, 1, 64, 4, 10)
      << "subsection Mesh\n  set Transformation = "
      << place.map("(1 - 0.5*y)*cos(pi*(1 + x))", std::to_string(yc) + " + (1 - 0.5*y)*sin(pi*(1 + x))")
      << "\nend\n"
      << "subsection Material\n  set Young's modulus = " << E << "\n  set Poisson's ratio = 0.3\nend\nend\n";
    return s.str();
  }

  Outcome
  run(const bool seat, const Placement &place)
  {
    std::ostringstream prm;
    prm << std::setprecision(17) << "set Number of bodies = 2\n";
    if (seat)
      prm << testing::block_mesh("structured quads", 0, 0, 1, 1, 40, 6, 0) << "subsection Mesh\n  set Transformation = "
          << place.map("(1.75 - 0.5*y)*cos(pi*(1.25 + 0.5*x))", "0.25 + (1.75 - 0.5*y)*sin(pi*(1.25 + 0.5*x))")
          << "\nend\n";
    else
      prm << testing::block_mesh("structured quads", -1, -1, 1, 0, 48, 8, 0)
          << "subsection Mesh\n  set Transformation = " << place.map("x", "y") << "\nend\n";
    prm << "subsection Material\n  set Young's modulus = " << E << "\n  set Poisson's ratio = 0.3\nend\n"
        << ring_body(place, seat ? 0. : 1.)
        << "subsection Contact\n  set Pairs = 3 : 12\n  set Normal = unilateral\n"
        << "  set Tangential = frictionless\nend\n"
        << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : xy : 0, 0; 13 : xy : "
        << place.displacement(0.02) << "\nend\n"
        << "subsection Output\n  set Write VTU = false\n  set Write JSON = false\n"
        << "  set Write pictures = false\n  set Write CSV = false\nend\n";
    const auto r = testing::run_contact(prm.str());
    Outcome    o;
    o.n_pairs = r.pairs.size();
    for (const auto &p : r.pairs)
      if (p.active)
        {
          ++o.n_active;
          o.pressures.push_back(p.pressure);
          o.p_max = std::max(o.p_max, p.pressure);
        }
    std::sort(o.pressures.begin(), o.pressures.end());
    return o;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const std::vector<Placement> placements = {{"shifted by 1e3 sizes", 2000., -3000., 1., 0.},
                                             {"scaled by 1e-3", 0., 0., 1e-3, 0.},
                                             {"scaled by 1e3", 0., 0., 1e3, 0.},
                                             {"rotated by 90 degrees", 0., 0., 1., pi / 2},
                                             {"rotated by 30 degrees", 0., 0., 1., pi / 6},
                                             {"shifted, scaled by 1e-3 and rotated by 30 degrees", 1.5, -2.5, 1e-3,
                                              pi / 6},
                                             {"shifted, scaled by 1e3 and rotated by 90 degrees", -7e5, 4e5, 1e3,
                                              pi / 2}};
  for (const bool seat : {false, true})
    {
      const std::string model = seat ? "circles of radii 1 and 1.25" : "Hertz, cylinder on a block";
      const Outcome     given = run(seat, Placement{"as given", 0., 0., 1., 0.});
      std::cout << model << ": " << given.n_pairs << " pairs, " << given.n_active
                << " active, p_max = " << std::setprecision(10) << given.p_max << std::endl;
      testing::check(given.n_active >= 5 && given.n_active < given.n_pairs,
                     model + ": a contact zone of several pairs inside the paired part");
      for (const auto &place : placements)
        {
          const Outcome     o   = run(seat, place);
          const std::string tag = model + ", " + place.name;
          testing::check(o.n_pairs == given.n_pairs && o.n_active == given.n_active,
                         tag + ": " + std::to_string(o.n_pairs) + " pairs, " + std::to_string(o.n_active) +
                           " active (as given: " + std::to_string(given.n_pairs) + ", " +
                           std::to_string(given.n_active) + ")");
          testing::check_small(o.p_max / given.p_max - 1, 1e-8, tag + ": p_max relative difference");
          double worst = 0;
          if (o.pressures.size() == given.pressures.size())
            for (unsigned int i = 0; i < o.pressures.size(); ++i)
              worst = std::max(worst, std::abs(o.pressures[i] - given.pressures[i]) / given.p_max);
          else
            worst = 1;
          testing::check_small(worst, 1e-8, tag + ": largest pressure difference / p_max");
        }
    }
  return testing::finish();
}
