// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Mirror symmetry of the contact results. A flat punch [-1,1]x[0,1] (E =
// 70000) pressed by a pressure p = 10 on its top into a wider block
// [-2,2]x[-1,0] (E = 7000), nu = 0.3, plane strain, frictionless
// unilateral contact, the block's bottom fixed, the punch held horizontally
// at the middle of its top. Both meshes are structured quadrilaterals
// symmetric about x = 0 and do not match at the interface (10 and 14 cells
// across). The pressure varies strongly (it is singular at the punch's
// corners), so every quantity of a pair must equal that of its mirror
// image: checked, for k = 1 and 2, that every pair has a mirror pair and
// that the recovered pressure, the raw multiplier per length and the gap
// agree with it to 1e-10 relative (the recovery patch reaches equally far
// to both sides of a node; it once grew from one side only).
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "../contact_common.h"
#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int k : {1u, 2u})
    {
      std::ostringstream prm;
      prm << "set Number of bodies = 2\n"
          << testing::block_mesh("structured quads", -2, -1, 2, 0, 14, 4, 0)
          << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\n"
          << "subsection Body 1\n"
          << testing::block_mesh("structured quads", -1, 0, 1, 1, 10, 5, 10)
          << "subsection Material\n  set Young's modulus = 70000\n  set Poisson's ratio = 0.3\nend\nend\n"
          << "subsection Discretization\n  set Order = " << k << "\nend\n"
          << "subsection Contact\n  set Pairs = 3 : 12\n  set Normal = unilateral\n"
          << "  set Tangential = frictionless\nend\n"
          << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : xy : 0, 0\n"
          << "  set Point constraints = 0, 1 : x : 0\n  set Pressure = 13 : 10\nend\n"
          << "subsection Output\n  set Write VTU = false\n  set Write JSON = false\n"
          << "  set Write pictures = false\n  set Write CSV = false\nend\n";
      const auto r = testing::run_contact(prm.str());

      const std::string tag   = "flat punch, structured quads 14 / 10 across, k = " + std::to_string(k);
      double            p_max = 0;
      for (const auto &pr : r.pairs)
        p_max = std::max({p_max, std::abs(pr.pressure), std::abs(pr.lumped_pressure)});
      unsigned int n_unmatched = 0;
      double       d_pressure = 0, d_raw = 0, d_gap = 0;
      for (const auto &pr : r.pairs)
        {
          const auto mirror = std::min_element(r.pairs.begin(), r.pairs.end(), [&](const auto &a, const auto &b) {
            return std::hypot(a.location[0] + pr.location[0], a.location[1] - pr.location[1]) <
                   std::hypot(b.location[0] + pr.location[0], b.location[1] - pr.location[1]);
          });
          if (std::hypot(mirror->location[0] + pr.location[0], mirror->location[1] - pr.location[1]) > 1e-12)
            {
              ++n_unmatched;
              std::cout << "  no mirror pair for the pair at (" << pr.location[0] << ", " << pr.location[1] << ")"
                        << std::endl;
              continue;
            }
          d_pressure = std::max(d_pressure, std::abs(mirror->pressure - pr.pressure) / p_max);
          d_raw      = std::max(d_raw, std::abs(mirror->lumped_pressure - pr.lumped_pressure) / p_max);
          d_gap      = std::max(d_gap, std::abs(mirror->gap - pr.gap));
        }
      double p_min_active = 1e300, p_max_active = 0;
      for (const auto &pr : r.pairs)
        if (pr.active)
          p_min_active = std::min(p_min_active, pr.pressure), p_max_active = std::max(p_max_active, pr.pressure);
      std::cout << tag << ": " << r.pairs.size() << " pairs, recovered pressure in [" << p_min_active << ", "
                << p_max_active << "], mirror differences: pressure " << d_pressure << ", raw " << d_raw
                << ", gap " << d_gap << std::endl;
      testing::check(r.pairs.size() > 15 && n_unmatched == 0, tag + ": every pair has a mirror pair");
      testing::check(p_max_active > 1.2 * p_min_active, tag + ": the pressure varies (a test of the recovery)");
      testing::check_small(d_pressure, 1e-10, tag + ": recovered pressure mirror-symmetric, relative to its maximum");
      testing::check_small(d_raw, 1e-10, tag + ": raw pressure mirror-symmetric, relative to its maximum");
      testing::check_small(d_gap, 1e-12, tag + ": gaps mirror-symmetric");
    }
  return testing::finish();
}
