// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Unilateral contact with a partly open interface: the upper block
// [0,1]x[1,2] is pressed only on the left part of its top (x < 0.3), so it
// tips and the right part of the interface lifts off. Checked for k = 1, 2:
// gap >= 0 and pressure >= 0 at every pair, complementarity gap * pressure
// = 0 (all to round-off relative to the data), some pairs open and some
// closed, and the total contact force balances the applied load (1e-11:
// the penalty-stiffened system loses about one digit more than the patch
// test).
// The active-set iteration counts are printed; the accelerated update
// (default) must end with the plain update's active set and pressures
// (1e-10 of p) in no more iterations.
#include <deal.II/base/mpi.h>

#include <sstream>

#include "../contact_common.h"
#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int k : {1u, 2u})
    for (const std::string lower : {"structured quads", "voronoi"})
      {
        const double       p = 10.;
        std::ostringstream prm;
        prm << "set Number of bodies = 2\n"
            << testing::block_mesh(lower, 0, 0, 1, 1, 4, 4, 0)
            << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\n"
            << "subsection Body 1\n"
            << testing::block_mesh("structured quads", 0, 1, 1, 2, 7, 7, 10)
            << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\nend\n"
            << "subsection Discretization\n  set Order = " << k << "\nend\n"
            << "subsection Contact\n  set Pairs = 3 : 12\n  set Normal = unilateral\n  set Tangential = penalty\nend\n"
            << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : xy : 0, 0\n"
            << "  set Pressure = 13 : " << p << " * (x < 0.3)\nend\n"
            << "subsection Output\n  set Folder = output-k" << k << "\n  set Write VTU = false\nend\n";
        const auto r = testing::run_contact(prm.str());

        double       min_gap = 0, min_p = 0, compl_err = 0, gap_scale = 0;
        unsigned int n_open = 0, n_closed = 0;
        for (const auto &pr : r.pairs)
          gap_scale = std::max(gap_scale, std::abs(pr.gap));
        for (const auto &pr : r.pairs)
          {
            min_gap   = std::min(min_gap, pr.gap);
            min_p     = std::min(min_p, pr.pressure);
            compl_err = std::max(compl_err, std::abs(pr.gap * pr.pressure));
            (pr.active ? n_closed : n_open) += 1;
          }
        const std::string tag = "k=" + std::to_string(k) + ", lower " + lower;
        std::cout << tag << ": " << r.pairs.size() << " pairs, " << n_closed << " closed, " << n_open
                  << " open; active-set iterations " << r.active_set_iterations << " (active pairs:";
        for (const auto a : r.active_set_history)
          std::cout << " " << a;
        std::cout << ")" << std::endl;
        testing::check(n_open > 0 && n_closed > 0, tag + ": part of the interface opens");
        testing::check(min_gap >= -1e-12 * gap_scale, tag + ": gap >= 0 (round-off)");
        testing::check(min_p >= -1e-10 * p, tag + ": pressure >= 0 (round-off)");
        testing::check_small(compl_err / (p * gap_scale), 1e-10,
                             tag + ": max |gap * pressure| / (p max|gap|)");
        const double load = r.applied_load_per_body[1].norm();
        testing::check_small((r.total_contact_force + r.applied_load_per_body[1]).norm() / load, 1e-11,
                             tag + ": |contact force + load| / |load|");
        testing::check(r.active_set_iterations >= 2, tag + ": the active set changed at least once");

        // the plain update (no acceleration) reaches the same solution, in
        // no fewer iterations
        std::string plain = prm.str();
        plain.replace(plain.find("set Tangential = penalty"), 24,
                      "set Tangential = penalty\n  set Active set acceleration = false");
        const auto   q     = testing::run_contact(plain);
        bool         same  = (q.pairs.size() == r.pairs.size());
        double       dp    = 0;
        for (unsigned int i = 0; same && i < q.pairs.size(); ++i)
          {
            same = same && (q.pairs[i].active == r.pairs[i].active);
            dp   = std::max(dp, std::abs(q.pairs[i].pressure - r.pairs[i].pressure));
          }
        std::cout << tag << ": plain update " << q.active_set_iterations << " iterations" << std::endl;
        testing::check(same, tag + ": the accelerated and the plain update end with the same active set");
        testing::check_small(dp / p, 1e-10, tag + ": max |p_accelerated - p_plain| / p");
        testing::check(r.active_set_iterations <= q.active_set_iterations,
                       tag + ": the acceleration takes no more iterations than the plain update");
      }
  // an iteration limit too small for the active set to settle gives a clear
  // error (the same path reports a cycling active set)
  {
    std::ostringstream prm;
    prm << "set Number of bodies = 2\n"
        << testing::block_mesh("structured quads", 0, 0, 1, 1, 4, 4, 0)
        << "subsection Material\n  set Young's modulus = 7000\nend\n"
        << "subsection Body 1\n" << testing::block_mesh("structured quads", 0, 1, 1, 2, 7, 7, 10)
        << "subsection Material\n  set Young's modulus = 7000\nend\nend\n"
        << "subsection Contact\n  set Pairs = 3 : 12\n  set Maximum active set iterations = 1\n"
        << "  set Globalized solve = false\nend\n"
        << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : xy : 0, 0\n"
        << "  set Pressure = 13 : 10 * (x < 0.3)\nend\n"
        << "subsection Output\n  set Folder = output-limit\n  set Write VTU = false\nend\n";
    testing::check_throws([&] { testing::run_contact(prm.str()); }, "did not settle",
                          "active set iteration limit reached");
  }
  return testing::finish();
}
