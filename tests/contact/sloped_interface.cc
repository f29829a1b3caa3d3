// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Sloped interface: two blocks with horizontal bottom (y = 0) and top
// (y = 2) and an interface inclined at theta = 30 degrees,
// y = 1 + tan(theta) (x - 0.5), non-matching meshes; pressure p on top,
// bottom held vertically, one point horizontally.
// - Stick by multipliers: the stress is uniform to round-off
//   (sigma_yy = -p, sigma_xx = sigma_xy = 0) and every interface node
//   carries the normal pressure p cos^2(theta) and the shear
//   p sin(theta) cos(theta) (1e-10 relative).
// - Stick by penalty: the shear is carried by a uniform slip of the upper
//   block along the interface, so the stress stays uniform for every
//   penalty, while the slip (the error of the displacement against the
//   exactly stuck solution) falls like 1/eps_t: checked to fall by at
//   least 5x per factor 10 of the penalty.
#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "../contact_common.h"
#include "../tests.h"

std::string
sloped_prm(const unsigned int k, const std::string &tangential, const double penalty)
{
  const double       t = std::tan(M_PI / 6);
  std::ostringstream prm, lower_map, upper_map;
  lower_map << std::setprecision(17);
  upper_map << std::setprecision(17);
  // lower body: unit square mapped to 0 <= y <= 1 + t (x - 0.5)
  lower_map << "x, y*(1 + " << t << "*(x - 0.5))";
  // upper body: unit square [0,1]x[1,2] mapped to 1 + t(x-0.5) <= y <= 2
  upper_map << "x, (1 + " << t << "*(x - 0.5)) + (y - 1)*(1 - " << t << "*(x - 0.5))";
  prm << "set Number of bodies = 2\n"
      << "subsection Mesh\n  set Type = structured quads\n  set Subdivisions = 3, 3\n"
      << "  set Transformation = " << lower_map.str() << "\nend\n"
      << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\n"
      << "subsection Body 1\n  subsection Mesh\n    set Type = structured quads\n"
      << "    set Lower left corner = 0, 1\n    set Upper right corner = 1, 2\n"
      << "    set Subdivisions = 5, 4\n    set Boundary id offset = 10\n"
      << "    set Transformation = " << upper_map.str() << "\n  end\n"
      << "  subsection Material\n    set Young's modulus = 7000\n    set Poisson's ratio = 0.3\n  end\nend\n"
      << "subsection Discretization\n  set Order = " << k << "\nend\n"
      << "subsection Contact\n  set Pairs = 3 : 12\n  set Normal = unilateral\n  set Tangential = "
      << tangential << "\n  set Penalty = " << penalty << "\nend\n"
      << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : y : 0\n"
      << "  set Point constraints = 0, 0 : x : 0\n  set Pressure = 13 : 10\nend\n"
      << "subsection Output\n  set Write VTU = false\n  set Write JSON = false\n  set Write pictures = "
         "false\n  set Write CSV = false\nend\n";
  return prm.str();
}

double
stress_error(const dealvem::ContactProblem::Results &r, const double p)
{
  double e = 0;
  for (const auto &s : r.cell_stress)
    e = std::max({e, std::abs(s[0]), std::abs(s[1] + p), std::abs(s[2])});
  return e / p;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double p = 10, theta = M_PI / 6;
  for (const unsigned int k : {1u, 2u})
    {
      const auto r = testing::run_contact(sloped_prm(k, "multipliers", 0));
      double     pn = 0, pt = 0;
      for (const auto &pr : r.pairs)
        {
          pn = std::max(pn, std::abs(pr.pressure - p * std::cos(theta) * std::cos(theta)));
          pt = std::max(pt, std::abs(std::abs(pr.tangential_traction) - p * std::sin(theta) * std::cos(theta)));
        }
      const std::string tag = "k=" + std::to_string(k) + " stick by multipliers";
      testing::check(r.pairs.size() > 3, tag + ": pairs made");
      testing::check_small(stress_error(r, p), 1e-10, tag + ": max stress error / p");
      testing::check_small(pn / p, 1e-10, tag + ": normal pressure - p cos^2 / p");
      testing::check_small(pt / p, 1e-10, tag + ": |shear| - p sin cos / p");

      double previous = 0;
      for (const double eps : {7e2, 7e3, 7e4, 7e5})
        {
          const auto rp = testing::run_contact(sloped_prm(k, "penalty", eps));
          double     slip = 0;
          for (const auto &pr : rp.pairs)
            slip = std::max(slip, std::abs(pr.slip));
          const std::string t = "k=" + std::to_string(k) + " penalty " + std::to_string(int(eps));
          std::cout << "      " << t << ": max |slip| = " << slip << ", max stress error / p = "
                    << stress_error(rp, p) << std::endl;
          testing::check_small(stress_error(rp, p), 1e-9, t + ": stress uniform");
          if (previous > 0)
            testing::check(slip < previous / 5, t + ": slip falls by at least 5x per factor 10");
          previous = slip;
        }
    }
  return testing::finish();
}
