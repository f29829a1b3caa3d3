// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The contact patch test on a curved interface. Two bodies of one
// material share the curve y = 1 + f(x), x in [0, 1]: the lower body is
// [0,1]^2 mapped by (x, y (1 + f(x))), the upper one [0,1]x[1,2] mapped by
// (x, y + (2 - y) f(x)); uniform pressure p on the flat top y = 2 (id 13),
// the flat bottom y = 0 (id 2) held vertically, the corner (0, 0)
// horizontally. The uniform stress sigma_yy = -p, sigma_xx = sigma_xy = 0
// is the exact solution of the glued bodies (free sides x = 0, 1; the
// traction -p n_y e_y is continuous across any curve). On the interface it
// is compressive (-n.sigma.n = p n_y^2 > 0) with a tangential part, so it
// is also the solution of unilateral contact with sticking (tangential
// multipliers), with every pair active.
//
// The two polygonal sides are different chords of the same curve. Node
// insertion places every inserted vertex on the circle of the side's
// curvature and closes the remaining discretisation gaps (the partners
// coincide), so the discrete interface is conforming and the VEM, which
// passes the patch test on any conforming polygonal mesh, reproduces the
// uniform stress to round-off. Checked: max |sigma - sigma_exact| / p <=
// 1e-10 in every cell, |contact force + applied load| / |load| <= 1e-10,
// all pairs active, for
//   curves f = 0.15 sin(pi x) and f = 0.2 (1 - (x - 1/2)^2) + 0.25 x
//   (tilted and curved);
//   meshes quads 7x5 / Voronoi 40 cells and structured triangles 6x4 /
//   perturbed quads 5x4;
//   curves with inflections (S-curve, waves; coarse and fine meshes, down
//   to 4 chords per wavelength on the Voronoi side);
//   k = 1, 2; tied + tangential multipliers and unilateral + tangential
//   multipliers.
// A real gap on a wavy interface (upper body lifted by 0.03) is kept, and a
// mesh too coarse for the curve (two waves over 6 and about 4 chords)
// reports the gaps it cannot tell from discretisation gaps, whether it
// closes or keeps them (one decision per interface, never a mix).
// With 'Close discretisation gaps = false' the chord gaps remain and the
// tied case is not uniform: the stress error exceeds 1e-3 p.
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <sstream>

#include "../contact_common.h"
#include "../tests.h"

namespace
{
  struct Curve
  {
    std::string name;
    std::string f; ///< f(x), muparser
  };

  struct Meshes
  {
    std::string lower_type;
    unsigned int lower_nx, lower_ny;
    std::string  upper_type;
    unsigned int upper_nx, upper_ny;
  };

  struct Errors
  {
    double       stress = 0, force = 0;
    unsigned int n_pairs = 0, n_active = 0, n_closed = 0, n_unresolved = 0, n_closed_unresolved = 0;
  };

  const double p = 10.;

  Errors
  run(const Curve &curve, const Meshes &m, const unsigned int k, const std::string &normal,
      const bool close_gaps = true, const double gap = 0)
  {
    std::ostringstream prm;
    prm << "set Number of bodies = 2\n"
        << testing::block_mesh(m.lower_type, 0, 0, 1, 1, m.lower_nx, m.lower_ny, 0, 3)
        << "subsection Mesh\n  set Transformation = x, y*(1 + " << curve.f << ")\nend\n"
        << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\n"
        << "subsection Body 1\n"
        << testing::block_mesh(m.upper_type, 0, 1, 1, 2, m.upper_nx, m.upper_ny, 10, 7)
        << "subsection Mesh\n  set Transformation = x, y + (2 - y)*(" << curve.f << " + " << gap << ")\nend\n"
        << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\nend\n"
        << "subsection Discretization\n  set Order = " << k << "\nend\n"
        << "subsection Contact\n  set Pairs = 3 : 12\n  set Normal = " << normal
        << "\n  set Tangential = multipliers\n  set Close discretisation gaps = "
        << (close_gaps ? "true" : "false") << "\nend\n"
        << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : y : 0\n"
        << "  set Point constraints = 0, 0 : x : 0\n  set Pressure = 13 : " << p << "\nend\n"
        << "subsection Output\n  set Write VTU = false\n  set Write JSON = false\n"
        << "  set Write pictures = false\n  set Write CSV = false\nend\n";
    const auto r = testing::run_contact(prm.str());
    Errors     e;
    for (const auto &s : r.cell_stress)
      e.stress = std::max({e.stress, std::abs(s[0]) / p, std::abs(s[1] + p) / p, std::abs(s[2]) / p});
    const double load = r.applied_load_per_body[1].norm();
    e.force           = (r.total_contact_force + r.applied_load_per_body[1]).norm() / load;
    e.n_pairs         = r.pairs.size();
    for (const auto &pr : r.pairs)
      e.n_active += pr.active;
    for (const auto &rep : r.insertion_reports)
      {
        e.n_closed += rep.n_closed_gaps;
        e.n_unresolved += rep.unresolved_gaps.size();
        e.n_closed_unresolved += rep.closed_unresolved_gaps.size();
      }
    return e;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<Curve>  curves = {{"sine 0.15 sin(pi x)", "0.15*sin(pi*x)"},
                                      {"tilted parabola 0.2 (1 - (x - 0.5)^2) + 0.25 x",
                                       "0.2*(1 - (x - 0.5)^2) + 0.25*x"}};
  const std::vector<Meshes> meshes = {{"structured quads", 7, 5, "voronoi", 8, 5},
                                      {"structured triangles", 6, 4, "perturbed quads", 5, 4}};
  for (const auto &curve : curves)
    for (const auto &m : meshes)
      for (const unsigned int k : {1u, 2u})
        for (const std::string normal : {"tied", "unilateral"})
          {
            std::ostringstream tag;
            tag << curve.name << ", " << m.lower_type << " " << m.lower_nx << "x" << m.lower_ny << " / "
                << m.upper_type << " " << m.upper_nx * m.upper_ny << ", k = " << k << ", " << normal
                << " + tangential multipliers";
            const Errors e = run(curve, m, k, normal);
            std::cout << tag.str() << ": " << e.n_pairs << " pairs, " << e.n_active << " active, "
                      << e.n_closed << " gaps closed" << std::endl;
            testing::check(e.n_pairs > 0 && e.n_active == e.n_pairs, tag.str() + ": all pairs active");
            testing::check_small(e.stress, 1e-10, tag.str() + ": max |sigma - sigma_exact| / p");
            testing::check_small(e.force, 1e-10, tag.str() + ": |contact force + load| / |load|");
          }

  // curves whose curvature changes sign (inflections inside the interface
  // and at its ends), on coarse and fine meshes: the gap rule must see the
  // one curve although the two sides' vertex curvatures differ in sign and
  // size near an inflection (at 9x4 against 23 cells the Voronoi side has
  // 4 chords per wavelength and turns by 43 degrees at a vertex)
  const std::vector<std::pair<Curve, Meshes>> inflections = {
    {{"S-curve 0.1 sin(2 pi x)", "0.1*sin(2*pi*x)"}, {"structured triangles", 9, 4, "voronoi", 23, 1}},
    {{"S-curve 0.1 sin(2 pi x)", "0.1*sin(2*pi*x)"}, {"structured triangles", 24, 8, "voronoi", 15, 10}},
    {{"wave 0.1 cos(2 pi x)", "0.1*cos(2*pi*x)"}, {"structured quads", 12, 4, "voronoi", 12, 5}},
    {{"wave 0.08 sin(3 pi x + 0.5)", "0.08*sin(3*pi*x + 0.5)"}, {"structured quads", 12, 4, "voronoi", 12, 5}},
    {{"two waves 0.05 sin(4 pi x)", "0.05*sin(4*pi*x)"}, {"structured triangles", 24, 8, "voronoi", 15, 10}}};
  for (const auto &c : inflections)
    for (const unsigned int k : {1u, 2u})
      for (const std::string normal : {"tied", "unilateral"})
        {
          const auto        &m = c.second;
          std::ostringstream tag;
          tag << c.first.name << ", " << m.lower_type << " " << m.lower_nx << "x" << m.lower_ny << " / "
              << m.upper_type << " " << m.upper_nx * m.upper_ny << ", k = " << k << ", " << normal
              << " + tangential multipliers";
          const Errors e = run(c.first, m, k, normal);
          std::cout << tag.str() << ": " << e.n_pairs << " pairs, " << e.n_active << " active, " << e.n_closed
                    << " gaps closed" << std::endl;
          testing::check(e.n_pairs > 0 && e.n_active == e.n_pairs, tag.str() + ": all pairs active");
          testing::check(e.n_unresolved == 0, tag.str() + ": no unresolved gap");
          testing::check_small(e.stress, 1e-10, tag.str() + ": max |sigma - sigma_exact| / p");
          testing::check_small(e.force, 1e-10, tag.str() + ": |contact force + load| / |load|");
        }

  // a real gap on a wavy interface is kept: the upper body lifted by 0.03
  // (the chord deviation of the fine sides is below 0.005), so no pair may
  // be closed and nothing is ambiguous
  {
    const Errors e = run(inflections[1].first, inflections[1].second, 1, "tied", true, 0.03);
    std::cout << "S-curve, fine meshes, upper body lifted by 0.03: " << e.n_pairs << " pairs, " << e.n_closed
              << " gaps closed, " << e.n_unresolved << " unresolved" << std::endl;
    testing::check(e.n_pairs >= 30, "lifted S-curve: the pairs are found across the gap");
    testing::check(e.n_closed == 0, "lifted S-curve: no real gap closed");
    testing::check(e.n_unresolved == 0, "lifted S-curve: no gap reported as ambiguous");
  }

  // too coarse to tell: 1.5 to 2 waves over 6 chords below and about 4
  // above. The gap rule decides once per interface: either it finds no
  // real gap and closes every gap (exact stress; gaps beyond the curvature
  // band next to an inflection are reported as closed although unresolved),
  // or it keeps the gaps and reports those it cannot tell from
  // discretisation gaps (a warning). Never a non-uniform stress without a
  // warning, never a silent decision on these meshes.
  {
    unsigned int n_warned = 0;
    for (const Curve &c : std::vector<Curve>{{"two waves 0.05 sin(4 pi x)", "0.05*sin(4*pi*x)"},
                                             {"1.5 waves 0.08 sin(3 pi x + 0.5)", "0.08*sin(3*pi*x + 0.5)"},
                                             {"wave 0.1 cos(2 pi x)", "0.1*cos(2*pi*x)"}})
      for (const auto &m : std::vector<Meshes>{{"perturbed quads", 6, 3, "voronoi", 17, 1},
                                               {"perturbed quads", 6, 3, "voronoi", 13, 1}})
        {
          const Errors e = run(c, m, 1, "tied");
          std::ostringstream tag;
          tag << c.name << ", perturbed quads 6x3 / Voronoi " << m.upper_nx << ", k = 1, tied";
          std::cout << tag.str() << ": " << e.n_pairs << " pairs, " << e.n_closed << " gaps closed ("
                    << e.n_closed_unresolved << " of them unresolved), " << e.n_unresolved
                    << " kept unresolved, stress error " << e.stress << std::endl;
          testing::check(e.stress <= 1e-10 || e.n_unresolved > 0,
                         tag.str() + ": a non-uniform stress comes with unresolved gaps");
          testing::check(e.n_closed == e.n_pairs || e.n_unresolved > 0 || e.n_closed == 0,
                         tag.str() + ": all gaps closed, or the kept ones reported");
          n_warned += (e.n_unresolved + e.n_closed_unresolved > 0);
        }
    testing::check(n_warned > 0, "too coarse: some of these meshes report unresolved gaps");
  }

  // without closing the discretisation gaps, the chords of the two sides
  // do not coincide: the tied solution is not the uniform stress
  for (const auto &curve : curves)
    for (const unsigned int k : {1u, 2u})
      {
        std::ostringstream tag;
        tag << curve.name << ", quads / Voronoi, k = " << k
            << ", tied, Close discretisation gaps = false";
        const Errors e = run(curve, meshes[0], k, "tied", false);
        std::cout << tag.str() << ": " << e.n_pairs << " pairs, " << e.n_closed << " gaps closed" << std::endl;
        testing::check(e.n_closed == 0, tag.str() + ": no gap closed");
        testing::check(e.stress > 1e-3, tag.str() + ": stress not uniform, max |sigma - sigma_exact| / p = " +
                                          std::to_string(e.stress) + " > 1e-3");
      }
  return testing::finish();
}
