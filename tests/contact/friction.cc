// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Coulomb friction through the program's parameters (ContactProblem):
// - frictional patch test: the uniform stress sigma = [[0, tau], [tau, -p]]
//   across a non-matching flat interface (tau = 0.5 mu p) and a sloped one
//   (30 degrees; mu chosen so that the interface shear is half of mu times
//   the interface pressure), the upper block held tangentially by friction
//   only: every pair sticks, the interface pressure and shear equal n.sigma.n
//   and t.sigma.n to 1e-10 relative, the stress is uniform to 1e-10; k = 1, 2,
//   stick by multipliers and by the penalty (KLU and GMRES-AMG too);
// - a curved interface y = 1 + 0.15 sin(pi x) meshed independently on both
//   sides, mu = 1, tau = 0.1 p: every pair sticks, the stress is uniform to
//   1e-10, the contact force balances the load;
// - mu = 0 gives the frictionless solution, a large mu the stuck one (stick
//   by multipliers), both to 1e-10 relative in displacements;
// - a load cycle (a block sheared forth and back by a traction on its top
//   only, so that the interface shear concentrates at the ends and slips
//   there first): every step dissipates a non-negative energy, some steps
//   slip, and the Newton iterations per step stay at most 6;
// - no static equilibrium: a block held only by friction under a tangential
//   load of 1.01 mu N stops at that step with "No static equilibrium", and
//   the files of the converged steps are kept; with the shear applied on the
//   top only (partly open, partly sticking interface) 0.999 mu N converges
//   and 1.001 mu N stops.
#include <deal.II/base/mpi.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "../contact_common.h"
#include "../tests.h"

namespace
{
  struct Case
  {
    unsigned int k         = 1;
    std::string  tangential = "coulomb";
    double       mu         = 0.4;
    double       tau        = 2.; // uniform shear stress of the patch test
    double       p          = 10.;
    bool         sloped     = false;
    std::string  extra_loads;   // replaces the patch-test loads when not empty
    std::string  load_steps;    // contents of the section 'Load steps'
    std::string  output;        // contents of the section 'Output'
    std::string  point_constraints = "0, 0 : x : 0 : 0";
    std::string  solver            = "UMFPACK";
    std::string  curve;         // interface y = 1 + curve(x) (overrides sloped)
    bool         mu_in_pairs = false; // give mu in 'Pairs' instead of 'Friction coefficient'
  };

  // Two blocks: lower [0,1] x [0,1] (3x3 quads, ids 0..3), upper above it
  // (5x4 quads, ids 10..13); sloped: the interface is
  // y = 1 + tan(30 deg) (x - 0.5), the outer sides stay straight.
  std::string
  parameters(const Case &c)
  {
    const double       t = c.sloped ? std::tan(M_PI / 6) : 0.;
    std::ostringstream f, prm;
    f << std::setprecision(17);
    if (c.curve.empty())
      f << t << "*(x - 0.5)";
    else
      f << c.curve;
    prm << std::setprecision(17);
    prm << "set Number of bodies = 2\n"
        << "subsection Mesh\n  set Type = structured quads\n  set Subdivisions = " << (c.curve.empty() ? "3, 3" : "7, 5")
        << "\n  set Transformation = x, y*(1 + " << f.str() << ")\nend\n"
        << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\n"
        << "subsection Body 1\n  subsection Mesh\n    set Type = structured quads\n"
        << "    set Lower left corner = 0, 1\n    set Upper right corner = 1, 2\n"
        << "    set Subdivisions = " << (c.curve.empty() ? "5, 4" : "6, 4") << "\n    set Boundary id offset = 10\n"
        << "    set Transformation = x, (1 + " << f.str() << ") + (y - 1)*(1 - " << f.str() << ")\n"
        << "  end\n  subsection Material\n    set Young's modulus = 7000\n    set Poisson's ratio = 0.3\n"
        << "  end\nend\n"
        << "subsection Discretization\n  set Order = " << c.k << "\nend\n"
        << "subsection Contact\n  set Pairs = 3 : 12";
    if (c.mu_in_pairs)
      prm << " : " << c.mu;
    prm << "\n  set Normal = unilateral\n  set Tangential = " << c.tangential << "\n";
    if ((c.tangential == "coulomb" || c.tangential == "coulomb penalty") && !c.mu_in_pairs)
      prm << "  set Friction coefficient = " << c.mu << "\n";
    prm << "end\n"
        << "subsection Load steps\n" << c.load_steps << "end\n"
        << "subsection Boundary conditions and loads\n  set Function constants = p=" << c.p << ", tau=" << c.tau
        << "\n  set Dirichlet = 2 : y : 0\n  set Point constraints = " << c.point_constraints << "\n";
    if (c.extra_loads.empty())
      // sigma n on every side: top (tau, -p), left (0, -tau), right (0, tau)
      // on both bodies; the bottom is held vertically and gets (-tau, 0)
      prm << "  set Traction = 13 : tau, -p; 10 : 0, -tau; 11 : 0, tau; 0 : 0, -tau; 1 : 0, tau; "
             "2 : -tau, 0\n";
    else
      prm << c.extra_loads << "\n";
    prm << "end\n"
        << "subsection Solver\n  set Type = " << c.solver << "\n  set Relative tolerance = 1e-14\nend\n"
        << "subsection Output\n"
        << (c.output.empty() ? "  set Write VTU = false\n  set Write JSON = false\n  set Write pictures = false\n"
                               "  set Write CSV = false\n" :
                               c.output)
        << "end\n";
    return prm.str();
  }

  void
  patch_test(const Case &c)
  {
    const auto r = testing::run_contact(parameters(c));
    // the interface: normal n (upward), tangent t; traction sigma n on the
    // lower body
    const double theta = c.sloped ? std::atan(std::tan(M_PI / 6)) : 0.;
    const double nx = -std::sin(theta), ny = std::cos(theta), tx = ny, ty = -nx;
    const double sx = c.tau * ny, sy = c.tau * nx - c.p * ny; // sigma n
    const double pn = -(sx * nx + sy * ny), tn = std::abs(sx * tx + sy * ty);
    double       stress_err = 0, pn_err = 0, tn_err = 0;
    unsigned int n_stick    = 0;
    for (const auto &s : r.cell_stress)
      stress_err = std::max({stress_err, std::abs(s[0]), std::abs(s[1] + c.p), std::abs(s[2] - c.tau)});
    for (const auto &pr : r.pairs)
      {
        pn_err = std::max(pn_err, std::abs(pr.lumped_pressure - pn));
        tn_err = std::max(tn_err, std::abs(std::abs(pr.tangential_traction) - tn));
        n_stick += (pr.status == "stick");
      }
    std::ostringstream tag;
    tag << "patch test, " << (c.sloped ? "sloped" : "flat") << ", k = " << c.k << ", " << c.solver << ", "
        << c.tangential << (c.mu_in_pairs ? " (mu in 'Pairs')" : "")
        << ", mu = " << c.mu << " (pressure " << pn << ", shear " << tn << " = " << tn / (c.mu * pn)
        << " mu p)";
    testing::check(n_stick == r.pairs.size() && !r.pairs.empty(),
                   tag.str() + ": all " + std::to_string(r.pairs.size()) + " pairs stick");
    testing::check_small(stress_err / c.p, 1e-10, tag.str() + ": max stress error / p");
    testing::check_small(pn_err / pn, 1e-10, tag.str() + ": max |lambda_n / w - p_n| / p_n");
    testing::check_small(tn_err / tn, 1e-10, tag.str() + ": max ||lambda_t / w| - tau_n| / tau_n");
    testing::check(r.steps.size() == 1 && r.steps[0].iterations <= 2,
                   tag.str() + ": at most 2 Newton iterations (" + std::to_string(r.steps[0].iterations) + ")");
    testing::check_small(r.dissipated_energy, 1e-14, tag.str() + ": no energy dissipated");
  }

  double
  max_difference(const dealii::Vector<double> &a, const dealii::Vector<double> &b)
  {
    double d = 0, s = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        d = std::max(d, std::abs(a[i] - b[i]));
        s = std::max(s, std::abs(b[i]));
      }
    return d / s;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               start = std::chrono::steady_clock::now();

  // 1. The frictional patch test.
  for (const unsigned int k : {1u, 2u})
    for (const std::string tangential : {"coulomb", "coulomb penalty"})
      {
        Case flat;
        flat.k          = k;
        flat.tangential = tangential;
        patch_test(flat); // tau = 2 = 0.5 mu p with mu = 0.4, p = 10
        Case sloped = flat;
        sloped.sloped = true;
        // interface pressure 0.75 p + sqrt(3)/2 tau, shear
        // |0.5 tau - sqrt(3)/4 p|: mu = 2 shear / pressure
        const double pn = 0.75 * sloped.p + std::sqrt(3.) / 2 * sloped.tau;
        const double tn = std::abs(0.5 * sloped.tau - std::sqrt(3.) / 4 * sloped.p);
        sloped.mu       = 2 * tn / pn;
        patch_test(sloped);
      }

  // The flat patch test with the other solvers (the matrix of a slipping
  // pair is not symmetric; KLU and GMRES-AMG take it as it is).
  for (const std::string solver : {"KLU", "GMRES-AMG"})
    {
      Case c;
      c.solver = solver;
      patch_test(c);
    }
  // the friction coefficient given per pair ('3 : 12 : 0.4'; the default
  // coefficient is 0, which would let the block slide off)
  {
    Case c;
    c.mu_in_pairs = true;
    patch_test(c);
  }

  // A curved interface y = 1 + 0.15 sin(pi x), meshed independently on the
  // two sides: with tau = 0.1 p the interface shear stays below 0.6 times
  // the interface pressure, so with mu = 1 every pair sticks and the
  // uniform stress is the exact solution.
  for (const unsigned int k : {1u, 2u})
    {
      Case c;
      c.k     = k;
      c.mu    = 1.0;
      c.tau   = 1.0;
      c.curve = "0.15*sin(_pi*x)";
      const auto   r          = testing::run_contact(parameters(c));
      double       stress_err = 0, ratio = 0;
      unsigned int n_stick    = 0;
      for (const auto &st : r.cell_stress)
        stress_err = std::max({stress_err, std::abs(st[0]), std::abs(st[1] + c.p), std::abs(st[2] - c.tau)});
      for (const auto &pr : r.pairs)
        {
          n_stick += (pr.status == "stick");
          ratio = std::max(ratio, std::abs(pr.tangential_traction / pr.lumped_pressure));
        }
      const std::string tag = "curved interface, k = " + std::to_string(k) + ", mu = 1: ";
      testing::check(n_stick == r.pairs.size() && !r.pairs.empty(),
                     tag + "all " + std::to_string(r.pairs.size()) + " pairs stick");
      testing::check_small(stress_err / c.p, 1e-10, tag + "max stress error / p");
      testing::check(ratio < 0.7, tag + "max |shear / pressure| below 0.7 (" + std::to_string(ratio) + ")");
      testing::check_small((r.total_contact_force + r.applied_load_per_body[1]).norm() / c.p, 1e-10,
                           tag + "|contact force + load on the upper body| / p");
    }

  // 2. mu = 0 against frictionless, large mu against stick by multipliers:
  // the upper block sheared by its top only, held in x at one point.
  {
    Case c;
    c.extra_loads       = "  set Traction = 13 : 0.3*p, -p";
    c.point_constraints = "0, 0 : x : 0 : 0; 0, 2 : x : 0 : 1";
    c.tangential        = "coulomb";
    c.mu                = 0;
    const auto r0       = testing::run_contact(parameters(c));
    c.tangential        = "frictionless";
    const auto rf       = testing::run_contact(parameters(c));
    testing::check_small(max_difference(r0.solution, rf.solution), 1e-10,
                         "mu = 0 gives the frictionless displacements (max difference / max |u|)");
    unsigned int n_slip = 0;
    for (const auto &pr : r0.pairs)
      n_slip += (pr.status == "slip");
    testing::check(n_slip > 0, "mu = 0: pairs slip (" + std::to_string(n_slip) + ")");

    c.point_constraints = "0, 0 : x : 0 : 0";
    c.tangential        = "coulomb";
    c.mu                = 1e3;
    const auto rl       = testing::run_contact(parameters(c));
    c.tangential        = "multipliers";
    const auto rs       = testing::run_contact(parameters(c));
    testing::check_small(max_difference(rl.solution, rs.solution), 1e-10,
                         "mu = 1000 gives the stuck displacements (max difference / max |u|)");
  }

  // 3. A load cycle: shear forth and back, traction on the top only.
  for (const std::string tangential : {"coulomb", "coulomb penalty"})
    {
      Case c;
      c.tangential = tangential;
      c.mu         = 0.3;
      // Q/(mu p) = 0.8 sin(2 pi t / 8): forth, back to -0.8, and to 0
      c.extra_loads = "  set Traction = 13 : 0.8*0.3*p*sin(_pi*t/4), -p";
      c.load_steps  = "  set Number of steps = 8\n  set Final time = 8\n";
      const auto   r = testing::run_contact(parameters(c));
      double       d_min = 1e300, d_sum = 0;
      unsigned int max_it = 0, slip_steps = 0;
      for (const auto &s : r.steps)
        {
          d_min = std::min(d_min, s.dissipated_energy);
          d_sum += s.dissipated_energy;
          max_it = std::max(max_it, s.iterations);
          slip_steps += (s.n_slip > 0);
        }
      testing::check(r.steps.size() == 8, "load cycle (" + tangential + "): 8 steps");
      testing::check(d_min >= 0, "load cycle (" + tangential + "): the dissipated energy of every step is >= 0 (min " +
                                   std::to_string(d_min) + ")");
      testing::check(slip_steps >= 4 && d_sum > 0,
                     "load cycle (" + tangential + "): pairs slip in " + std::to_string(slip_steps) + " steps");
      testing::check(max_it <= 6, "load cycle (" + tangential + "): at most 6 Newton iterations per step (" +
                                    std::to_string(max_it) + ")");
      testing::check_near(r.dissipated_energy, d_sum, 1e-14 * d_sum, "load cycle: total = sum of the steps");
    }

  // 4. No static equilibrium at step 2 (1.01 mu N, uniform shear), files of
  // step 1 (0.505 mu N) kept.
  {
    Case c;
    c.mu         = 0.3;
    c.tau        = 0; // set through the load expression below
    c.extra_loads = "  set Traction = 13 : 0.505*0.3*p*t, -p; 10 : 0, -0.505*0.3*p*t; 11 : 0, 0.505*0.3*p*t; "
                    "0 : 0, -0.505*0.3*p*t; 1 : 0, 0.505*0.3*p*t; 2 : -0.505*0.3*p*t, 0";
    c.load_steps = "  set Number of steps = 2\n  set Final time = 2\n";
    c.output     = "  set Folder = output\n  set Base name = no-equilibrium\n  set Write VTU = true\n"
                   "  set Write JSON = true\n  set Write pictures = false\n  set Write CSV = true\n";
    std::filesystem::remove_all("output");
    testing::check_throws([&]() { testing::run_contact(parameters(c)); }, "No static equilibrium",
                          "1.01 mu N on a block held only by friction: no static equilibrium");
    for (const std::string f : {"output/no-equilibrium-step-001.vtu", "output/no-equilibrium-step-001-interface.csv",
                                "output/no-equilibrium.pvd", "output/no-equilibrium.json"})
      testing::check(std::filesystem::exists(f), "the converged step is kept: " + f);
    testing::check(!std::filesystem::exists("output/no-equilibrium-step-002.vtu"), "no file of the failed step");
    std::ifstream     json("output/no-equilibrium.json");
    const std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
    testing::check(text.find("\"failed_step\": 2") != std::string::npos, "the summary names the failed step 2");
  }

  // 5. The equilibrium limit is sharp also where the shear is not uniform
  // (traction on the top only: the interface opens at one end and sticks at
  // the other): 0.999 mu N converges, 1.001 mu N stops.
  for (const double ratio : {0.999, 1.001})
    {
      Case c;
      c.mu          = 0.3;
      c.extra_loads = "  set Traction = 13 : " + std::to_string(ratio) + "*0.3*p, -p";
      const std::string tag = "top traction " + std::to_string(ratio).substr(0, 5) + " mu N: ";
      if (ratio < 1)
        {
          const auto   r      = testing::run_contact(parameters(c));
          unsigned int n_open = 0, n_stick = 0;
          for (const auto &pr : r.pairs)
            {
              n_open += (pr.status == "open");
              n_stick += (pr.status == "stick");
            }
          testing::check(n_stick > 0 && n_open > 0, tag + "converges with " + std::to_string(n_stick) +
                                                      " sticking and " + std::to_string(n_open) + " open pairs");
          testing::check_small((r.total_contact_force + r.applied_load_per_body[1]).norm() / c.p, 1e-10,
                               tag + "|contact force + load on the upper block| / p");
        }
      else
        testing::check_throws([&]() { testing::run_contact(parameters(c)); }, "No static equilibrium",
                              tag + "no static equilibrium");
    }

  std::cout << "run time: " << std::fixed << std::setprecision(1)
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s" << std::endl;
  return testing::finish();
}
