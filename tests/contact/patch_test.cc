// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The contact patch test (Taylor & Papadopoulos 1991) with node insertion
// and node-to-node multipliers: two stacked blocks [0,1]x[0,1] (body 0,
// master side on top, id 3) and [0,1]x[1,2] (body 1, slave side at the
// bottom, id 12) with non-matching meshes; uniform pressure p on top
// (id 13); the bottom (id 2) held vertically, the corner (0,0) held
// horizontally; unilateral normal contact.
// Checked to 1e-10 relative: sigma_yy = -p and sigma_xx = sigma_xy = 0 in
// every cell, contact pressure p at every interface node, gaps 0; the total
// contact force balances the load on the upper block to 1e-12.
// Variants: k = 1, 2; plane strain and plane stress; mesh ratios 1:1, 1:3,
// 2:7 (quads on quads), Voronoi on quads, Voronoi on Voronoi; UMFPACK, KLU
// and GMRES-AMG; stick by penalty with one material, and frictionless with
// two materials (each body then held against sliding at one point).
#include <deal.II/base/mpi.h>

#include <sstream>

#include "../contact_common.h"
#include "../tests.h"

struct Variant
{
  unsigned int k;
  std::string  model;
  std::string  lower_type, upper_type;
  unsigned int n_lower, n_upper;
  std::string  solver;
  bool         two_materials;
};

void
run_variant(const Variant &v)
{
  const double       p = 10.;
  std::ostringstream prm;
  prm << "set Number of bodies = 2\n"
      << testing::block_mesh(v.lower_type, 0, 0, 1, 1, v.n_lower, v.n_lower, 0, 11)
      << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\n  set Model = "
      << v.model << "\nend\n"
      << "subsection Body 1\n"
      << testing::block_mesh(v.upper_type, 0, 1, 1, 2, v.n_upper, v.n_upper, 10, 5)
      << "subsection Material\n  set Young's modulus = " << (v.two_materials ? 2100 : 7000)
      << "\n  set Poisson's ratio = " << (v.two_materials ? 0.2 : 0.3) << "\nend\nend\n"
      << "subsection Discretization\n  set Order = " << v.k << "\nend\n"
      << "subsection Contact\n  set Pairs = 3 : 12\n  set Normal = unilateral\n  set Tangential = "
      << (v.two_materials ? "frictionless" : "penalty") << "\nend\n"
      << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : y : 0\n"
      << "  set Point constraints = 0, 0 : x : 0" << (v.two_materials ? "; 0, 2 : x : 0" : "") << "\n"
      << "  set Pressure = 13 : " << p << "\nend\n"
      << "subsection Solver\n  set Type = " << v.solver << "\n  set Relative tolerance = 1e-14\nend\n"
      << "subsection Output\n  set Write VTU = false\n  set Write JSON = false\n  set Write pictures = "
         "false\n  set Write CSV = false\nend\n";
  const auto r = testing::run_contact(prm.str());

  double stress_err = 0;
  for (const auto &s : r.cell_stress)
    stress_err = std::max({stress_err, std::abs(s[0]), std::abs(s[1] + p), std::abs(s[2])});
  double pressure_err = 0, gap_err = 0;
  for (const auto &pr : r.pairs)
    {
      pressure_err = std::max(pressure_err, std::abs(pr.pressure - p));
      gap_err      = std::max(gap_err, std::abs(pr.gap));
    }
  const double load       = r.applied_load_per_body[1][1];
  const double force_err  = (r.total_contact_force + r.applied_load_per_body[1]).norm() / std::abs(load);
  std::ostringstream tag;
  tag << "k=" << v.k << " " << v.model << ", " << v.lower_type << " " << v.n_lower << " / "
      << v.upper_type << " " << v.n_upper << ", " << v.solver
      << (v.two_materials ? ", two materials, frictionless" : ", stick by penalty") << " ("
      << r.pairs.size() << " pairs)";
  testing::check(!r.pairs.empty(), tag.str() + ": node pairs were made");
  testing::check_small(stress_err / p, 1e-10, tag.str() + ": max stress error / p");
  testing::check_small(pressure_err / p, 1e-10, tag.str() + ": max contact pressure error / p");
  testing::check_small(gap_err, 1e-12, tag.str() + ": max |gap|");
  testing::check_small(force_err, 1e-12, tag.str() + ": |contact force + load| / load");
  testing::check_near(load, -p, 1e-12 * p, tag.str() + ": applied load on the upper block");
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<Variant>                     variants;
  for (const unsigned int k : {1u, 2u})
    for (const std::string model : {"plane strain", "plane stress"})
      {
        variants.push_back({k, model, "structured quads", "structured quads", 3, 3, "UMFPACK", false});
        variants.push_back({k, model, "structured quads", "structured quads", 2, 6, "UMFPACK", false});
        variants.push_back({k, model, "structured quads", "structured quads", 2, 7, "KLU", false});
        variants.push_back({k, model, "structured quads", "voronoi", 3, 4, "UMFPACK", false});
        variants.push_back({k, model, "voronoi", "voronoi", 4, 3, "GMRES-AMG", false});
        variants.push_back({k, model, "structured quads", "voronoi", 3, 5, "UMFPACK", true});
      }
  variants.push_back({2, "plane strain", "voronoi", "structured quads", 5, 3, "KLU", true});
  variants.push_back({2, "plane stress", "structured quads", "structured quads", 2, 7, "GMRES-AMG", true});
  for (const auto &v : variants)
    run_variant(v);
  return testing::finish();
}
