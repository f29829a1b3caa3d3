// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Bad input of contact problems gives clear errors, and an initial
// penetration is handled through the gap:
// - contact parts that do not face each other: error naming the ids;
// - a body with no support (frictionless, upper block free to slide):
//   "Unsupported body / rigid-body mode" naming the body and the motion;
// - a contact pair naming a boundary id that does not exist;
// - an initial penetration delta: the patch test still gives the uniform
//   stress, and the upper block is pushed up by delta (gaps closed).
#include <deal.II/base/mpi.h>

#include <sstream>

#include "../contact_common.h"
#include "../tests.h"

std::string
patch_prm(const double upper_y0, const std::string &tangential, const std::string &pairs,
          const std::string &points)
{
  std::ostringstream prm;
  prm << "set Number of bodies = 2\n"
      << testing::block_mesh("structured quads", 0, 0, 1, 1, 3, 3, 0)
      << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\n"
      << "subsection Body 1\n"
      << testing::block_mesh("structured quads", 0, upper_y0, 1, upper_y0 + 1, 4, 4, 10)
      << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\nend\n"
      << "subsection Contact\n  set Pairs = " << pairs << "\n  set Tangential = " << tangential << "\nend\n"
      << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : y : 0\n"
      << "  set Point constraints = " << points << "\n"
      << "  set Pressure = 13 : 10\nend\n"
      << "subsection Output\n  set Write VTU = false\n  set Write JSON = false\n  set Write pictures = "
         "false\n  set Write CSV = false\nend\n";
  return prm.str();
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::check_throws([] { testing::run_contact(patch_prm(5.0, "penalty", "3 : 12", "0, 0 : x : 0")); },
                        "contact interface (master id 3, slave id 12)", "bodies far apart");
  testing::check_throws([] { testing::run_contact(patch_prm(1.0, "frictionless", "3 : 12", "0, 0 : x : 0")); },
                        "Unsupported body / rigid-body mode", "frictionless, upper block free to slide");
  testing::check_throws([] { testing::run_contact(patch_prm(1.0, "frictionless", "3 : 12", "0, 0 : x : 0")); },
                        "x-translation of body 1", "the message names the free motion and the body");
  testing::check_throws([] { testing::run_contact(patch_prm(1.0, "penalty", "3 : 42", "0, 0 : x : 0")); },
                        "42", "unknown boundary id in a contact pair");
  testing::check_throws([] { testing::run_contact(patch_prm(1.0, "penalty", "3 : 3", "0, 0 : x : 0")); },
                        "Contact/Pairs", "a pair with the same id twice");

  // initial penetration of delta = 1e-3
  const double delta = 1e-3;
  const auto   ref   = testing::run_contact(patch_prm(1.0, "penalty", "3 : 12", "0, 0 : x : 0"));
  const auto   pen   = testing::run_contact(patch_prm(1.0 - delta, "penalty", "3 : 12", "0, 0 : x : 0"));
  double       stress_err = 0, gap_err = 0, p_err = 0;
  for (const auto &s : pen.cell_stress)
    stress_err = std::max({stress_err, std::abs(s[0]), std::abs(s[1] + 10), std::abs(s[2])});
  for (const auto &pr : pen.pairs)
    {
      gap_err = std::max(gap_err, std::abs(pr.gap));
      p_err   = std::max(p_err, std::abs(pr.pressure - 10));
    }
  testing::check_small(stress_err / 10, 1e-10, "penetration: uniform stress");
  testing::check_small(gap_err, 1e-12, "penetration: gaps closed");
  testing::check_small(p_err / 10, 1e-10, "penetration: contact pressure p");
  // the upper block moved up by delta relative to the reference
  // (top-left corner: the last vertex of body 1 at (0, 2 - delta))
  const auto  &mesh = pen.mesh;
  double       uy_pen = 0, uy_ref = 0;
  for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
    if (mesh.vertex(v).distance(dealii::Point<2>(0, 2 - delta)) < 1e-12)
      uy_pen = pen.solution[2 * v + 1];
  for (unsigned int v = 0; v < ref.mesh.n_vertices(); ++v)
    if (ref.mesh.vertex(v).distance(dealii::Point<2>(0, 2)) < 1e-12)
      uy_ref = ref.solution[2 * v + 1];
  testing::check_near(uy_pen - uy_ref, delta, 1e-12, "penetration: upper block pushed up by delta");
  return testing::finish();
}
