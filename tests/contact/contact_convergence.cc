// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Error norms per body and convergence studies in contact problems, on a
// mesh read from a file: pure bending (plane strain, sigma_xx = c y, all
// other stresses zero) across a tied, non-matching interface.
//   u_x = A x y,  u_y = -A x^2/2 - B y^2/2,  A = (1 - nu^2) c / E,
//   B = nu (1 + nu) c / E.
// Body 0 is the gmsh file tests/mesh/data/rectangle.msh ([0,2]x[0,1], ids
// 2 bottom, 3 right, 4 top, 1 left; two
// quads; its triangulation is refined before conversion in each cycle),
// body 1 a Voronoi mesh of [0,2]x[1,2]; Dirichlet data = the exact solution
// on the outer boundary; tied contact with tangential multipliers.
// Checked: k = 2 reproduces the quadratic field to round-off (relative
// errors <= 1e-9 in both bodies and both cycles); k = 1 converges at the
// textbook rates in each body (finest pair: L2 rate >= 1.8, H1 >= 0.85).
#include <sstream>

#include "../contact_common.h"
#include "../tests.h"

namespace
{
  std::string
  prm_text(const unsigned int k, const unsigned int cycles)
  {
    const std::string src = testing::source_dir();
    const std::string u   = "A*x*y, -A*x^2/2 - B*y^2/2";
    std::ostringstream prm;
    prm << "set Number of bodies = 2\n"
        << "subsection Mesh\n  set Type = gridin file\n  set File name = " << src
        << "/tests/mesh/data/rectangle.msh\nend\n"
        << "subsection Material\n  set Young's modulus = 1000\n  set Poisson's ratio = 0.3\nend\n"
        << "subsection Body 1\n"
        << testing::block_mesh("voronoi", 0, 1, 2, 2, 3, 3, 10, 3)
        << "subsection Material\n  set Young's modulus = 1000\n  set Poisson's ratio = 0.3\nend\nend\n"
        << "subsection Discretization\n  set Order = " << k << "\nend\n"
        << "subsection Contact\n  set Pairs = 4 : 12\n  set Normal = tied\n  set Tangential = multipliers\nend\n"
        << "subsection Boundary conditions and loads\n"
        << "  set Function constants = A=" << (1 - 0.09) / 1000 << ", B=" << 0.3 * 1.3 / 1000 << "\n"
        << "  set Dirichlet = 1 : xy : " << u << "; 2 : xy : " << u << "; 3 : xy : " << u << "; 10 : xy : "
        << u << "; 11 : xy : " << u << "; 13 : xy : " << u << "\nend\n"
        << "subsection Exact solution\n  set Displacement = " << u << "\nend\n"
        << "subsection Convergence study\n  set Refinement cycles = " << cycles << "\nend\n"
        << "subsection Output\n  set Folder = output-k" << k
        << "\n  set Write VTU = false\n  set Write pictures = false\nend\n";
    return prm.str();
  }

  std::vector<std::vector<dealvem::ErrorNorms>>
  run(const unsigned int k, const unsigned int cycles)
  {
    dealii::ParameterHandler prm;
    dealvem::ElasticityProblem::declare_parameters(prm);
    dealvem::ContactProblem::declare_parameters(prm);
    prm.parse_input_from_string(prm_text(k, cycles));
    dealvem::ContactProblem problem;
    problem.parse_parameters(prm);
    problem.run();
    return problem.convergence_history();
  }
} // namespace

int
main()
{
  {
    const auto h = run(2, 2);
    testing::check(h.size() == 2 && h[0].size() == 2, "k=2: two cycles, two bodies");
    for (unsigned int c = 0; c < h.size(); ++c)
      for (unsigned int b = 0; b < 2; ++b)
        {
          const std::string tag = "k=2 cycle " + std::to_string(c) + " body " + std::to_string(b);
          testing::check(h[c][b].l2_exact > 0, tag + ": the exact solution was measured");
          testing::check_small(h[c][b].l2 / h[c][b].l2_exact, 1e-9, tag + ": relative L2 error");
          testing::check_small(h[c][b].h1_seminorm / h[c][b].h1_exact, 1e-9, tag + ": relative H1 error");
        }
  }
  {
    const auto h = run(1, 3);
    for (unsigned int b = 0; b < 2; ++b)
      {
        const std::string tag = "k=1 body " + std::to_string(b);
        // the DoFs grow by 4 per cycle (2x in h): rate = log2(e_1 / e_2)
        const double rl2 = std::log2(h[1][b].l2 / h[2][b].l2);
        const double rh1 = std::log2(h[1][b].h1_seminorm / h[2][b].h1_seminorm);
        std::cout << tag << ": L2 " << h[1][b].l2 / h[1][b].l2_exact << " -> " << h[2][b].l2 / h[2][b].l2_exact
                  << " (rate " << rl2 << "), H1 rate " << rh1 << std::endl;
        testing::check(rl2 >= 1.8, tag + ": L2 rate >= 1.8");
        testing::check(rh1 >= 0.85, tag + ": H1 rate >= 0.85");
      }
  }
  return testing::finish();
}
