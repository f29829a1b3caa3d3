// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The contact solver 'CG-AMG constraints' (active contact constraints
// written as affine constraints on slave DoFs, stiffness condensed, CG + ML
// AMG, multipliers from the residual) against the UMFPACK factorization of
// the saddle-point matrix, through ContactProblem with the same input:
//   - displacements: |u - u_ref| / |u_ref| <= 1e-8;
//   - multipliers: max_i |lambda_i - lambda_ref,i| / max_i |lambda_ref,i|
//     <= 1e-8, and the tangential nodal forces (multipliers or penalty
//     forces) to 1e-8 of the largest normal or tangential force;
//   - the same number of active-set iterations, the same active pairs per
//     iteration and the same final active set.
// The distributed solves (all processes of MPI_COMM_WORLD, also one) give the
// UMFPACK displacements and multipliers to 1e-10 (the tangential penalty
// forces of the iterative solve to 1e-8, see agree()).
// Cases:
//   a) the flat contact patch test of examples/step-2 (3x3 quads below, 12
//      Voronoi cells above), k = 1, 2, tied and unilateral, stick by penalty
//      and by multipliers. The upper block has no support of its own: it is
//      held only through contact. Also: uniform stress sigma_yy = -p to
//      1e-10 p with the condensed solver;
//   b) a curved interface y = 1 + 0.15 sin(pi x) meshed independently
//      (quads 7x5 against 40 Voronoi cells), k = 1, 2, tied and unilateral
//      with tangential multipliers; uniform stress to 1e-10 p;
//   c) rollers u_x = 0 on the left sides of both blocks (tests/contact/
//      redundant_constraints.cc): the tangential constraint of the pair at
//      the interface end (0, 1) is redundant and dropped; k = 1, 2, tied and
//      unilateral; uniform stress to 1e-10 p;
//   d) a Hertz-like case: the upper block's bottom is the parabola
//      y = 1 + 0.008 (x - 1/2)^2 on a flat block, pressed by p = 10 on top,
//      unilateral, stick by penalty, held sideways only by contact; the
//      active set grows over several iterations (k = 1, 2: 3 23 21 17 19
//      and 3 5 45 35 41 active pairs), the initial gaps, up to 0.002, being
//      kept as real gaps. (The flat block's interface vertices lie on the
//      decimal lattice 0.1, its 10 cells; such a lattice, as coarse as the
//      edges, is not taken for the rounding of the coordinates, which
//      would close every gap below 0.05 and leave one iteration with all
//      23 pairs active.) And the tipping
//      block of tests/contact/active_set.cc (pressure on x < 0.3 only),
//      where part of the interface lifts off.
//   e) Coulomb friction (slipping and opening pairs over three load steps,
//      flat and curved non-matching interfaces, stick by multipliers and by
//      the penalty, k = 1, 2; in a Debug build one case): every solver
//      type (also KLU and GMRES-AMG for k = 1)
//      gives UMFPACK's displacements, multipliers and tangential forces to
//      1e-8 (direct 1e-10), the same Newton iterations and open/stick/slip
//      counts per step and the same dissipated energy, serially and
//      distributed; the saddle-point solvers are refused on the distributed
//      path;
//   f) the stick-penalty preconditioner: on a patch test of 24,522 DoFs
//      (multilevel AMG) the penalty system needs at most 1.3 times the CG
//      iterations of the stick-by-multipliers one (measured 23 / 25 with the
//      p-multigrid, 80 / 76 with ML AMG); the p-multigrid (the default for
//      k = 2) at most half the iterations of ML AMG (measured 25 / 67).
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <sstream>
#include <vector>

#include "../contact_common.h"
#include "../tests.h"

namespace
{
  const double p = 10.;

  std::string
  output_section()
  {
    return "subsection Output\n  set Write VTU = false\n  set Write JSON = false\n"
           "  set Write pictures = false\n  set Write CSV = false\nend\n";
  }

  std::string
  solver_section(const std::string &type)
  {
    return "subsection Solver\n  set Type = " + type + "\n  set Relative tolerance = 1e-12\nend\n";
  }

  unsigned int total_rows_across = 0;

  /// Compare the result @p r of @p solver with the UMFPACK reference @p ref:
  /// displacements, multipliers, tangential forces to @p tol, and the same
  /// active-set history.
  void
  agree(const dealvem::ContactProblem::Results &r, const dealvem::ContactProblem::Results &ref, const double tol,
        const std::string &tag, const double tangential_tol)
  {
    dealii::Vector<double> d = r.solution;
    d -= ref.solution;
    testing::check_small(d.l2_norm() / ref.solution.l2_norm(), tol, tag + ": |u - u_UMFPACK| / |u_UMFPACK|");
    double dl = 0, l = 0, dt = 0, t = 0;
    bool   same_active = (r.pairs.size() == ref.pairs.size());
    for (unsigned int i = 0; same_active && i < r.pairs.size(); ++i)
      {
        dl = std::max(dl, std::abs(r.pairs[i].multiplier - ref.pairs[i].multiplier));
        l  = std::max(l, std::abs(ref.pairs[i].multiplier));
        dt = std::max(dt, std::abs(r.pairs[i].tangential_traction - ref.pairs[i].tangential_traction) *
                            ref.pairs[i].weight);
        t  = std::max(t, std::abs(ref.pairs[i].tangential_traction) * ref.pairs[i].weight);
        same_active = same_active && (r.pairs[i].active == ref.pairs[i].active);
      }
    testing::check_small(dl / l, tol, tag + ": max |lambda - lambda_UMFPACK| / max |lambda_UMFPACK|");
    // (relative to the larger of the tangential and normal forces: in the
    // flat patch test the tangential forces vanish up to round-off)
    testing::check_small(dt / std::max(t, l), tangential_tol,
                         tag + ": max |tangential force difference| / max |force_UMFPACK|");
    unsigned int n_active = 0;
    for (const auto &pr : r.pairs)
      n_active += pr.active;
    std::ostringstream h;
    for (const auto a : r.active_set_history)
      h << " " << a;
    testing::check(same_active && r.active_set_history == ref.active_set_history &&
                     r.active_set_iterations == ref.active_set_iterations,
                   tag + ": same active-set iterations (" + std::to_string(r.active_set_iterations) +
                     ", active pairs per iteration:" + h.str() + ") and final set (" +
                     std::to_string(n_active) + " of " + std::to_string(r.pairs.size()) + ") as UMFPACK");
    // load steps (Coulomb friction): the same Newton iterations, the same
    // numbers of open, sticking and slipping pairs, the same dissipation
    bool   same_steps = (r.steps.size() == ref.steps.size());
    double de = 0, e = 0;
    for (unsigned int s = 0; same_steps && s < r.steps.size(); ++s)
      {
        const auto &a = r.steps[s], &c = ref.steps[s];
        same_steps = a.iterations == c.iterations && a.n_open == c.n_open && a.n_stick == c.n_stick &&
                     a.n_slip == c.n_slip;
        de = std::max(de, std::abs(a.dissipated_energy - c.dissipated_energy));
        e  = std::max(e, std::abs(c.dissipated_energy));
      }
    if (r.steps.size() > 1 || r.dissipated_energy != 0.)
      {
        std::ostringstream states;
        for (const auto &s : r.steps)
          states << " " << s.n_open << "/" << s.n_stick << "/" << s.n_slip << " (" << s.iterations << ")";
        testing::check(same_steps, tag + ": the same Newton iterations and open/stick/slip pairs per load step as "
                                         "UMFPACK:" + states.str());
        if (e > 0)
          testing::check_small(de / e, tol, tag + ": dissipated energy per step against UMFPACK's");
      }
    std::cout << "      " << r.solver << ": " << r.linear_iterations << " linear iterations in "
              << r.active_set_iterations << " solve(s)" << std::endl;
  }

  /// Run @p prm with UMFPACK (serial, the reference), with CG-AMG (serial,
  /// 1e-8) and direct constraints (serial, CHOLMOD, 1e-10), and distributed
  /// over the processes of MPI_COMM_WORLD (also on one process) with the
  /// condensed system factored by KLU (direct constraints) and solved by
  /// CG + AMG (1e-10).
  dealvem::ContactProblem::Results
  compare(const std::string &prm, const std::string &tag, const bool uniform_stress, const bool every_type = false)
  {
    using Parallelism = dealvem::ElasticityProblem::Parallelism;
    const auto ref    = testing::run_contact(prm + solver_section("UMFPACK"));
    const auto r      = testing::run_contact(prm + solver_section("CG-AMG"));
    agree(r, ref, 1e-8, tag, 1e-8);
    const auto rc = testing::run_contact(prm + solver_section("direct constraints"));
    agree(rc, ref, 1e-10, tag + " [direct constraints]", 1e-10);
    if (every_type)
      {
        agree(testing::run_contact(prm + solver_section("KLU")), ref, 1e-10, tag + " [KLU]", 1e-10);
        agree(testing::run_contact(prm + solver_section("GMRES-AMG")), ref, 1e-8, tag + " [GMRES-AMG]", 1e-8);
      }
    const unsigned int np = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const std::string  on = " [distributed, " + std::to_string(np) + " process(es), ";
    for (const std::string type : {"direct constraints", "CG-AMG"})
      {
        const auto rd =
          testing::run_contact(prm + solver_section(type), MPI_COMM_WORLD, Parallelism::distributed);
        // (a penalty force is 1e3 E/h times a difference of displacements:
        // with an iterative solve it carries the residual tolerance times
        // the penalty factor, so it is held to the serial CG's 1e-8)
        agree(rd, ref, 1e-10, tag + on + type + "]", type == "CG-AMG" ? 1e-8 : 1e-10);
        total_rows_across += rd.n_rows_across_processes;
        std::cout << "      contact constraint rows cut by the partition: " << rd.n_rows_across_processes
                  << std::endl;
      }
    if (uniform_stress)
      {
        double e = 0;
        for (const auto &s : r.cell_stress)
          e = std::max({e, std::abs(s[0]), std::abs(s[1] + p), std::abs(s[2])});
        testing::check_small(e / p, 1e-10, tag + ": max |sigma - sigma_exact| / p");
      }
    return r;
  }

  std::string
  two_blocks(const std::string &lower, const std::string &upper, const unsigned int k, const std::string &normal,
             const std::string &tangential, const std::string &supports, const std::string &load)
  {
    std::ostringstream s;
    s << "set Number of bodies = 2\n"
      << lower << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\n"
      << "subsection Body 1\n"
      << upper << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\nend\n"
      << "subsection Discretization\n  set Order = " << k << "\nend\n"
      << "subsection Contact\n  set Pairs = 3 : 12\n  set Normal = " << normal
      << "\n  set Tangential = " << tangential << "\nend\n"
      << "subsection Boundary conditions and loads\n" << supports << "  set Pressure = 13 : " << load << "\nend\n"
      << output_section();
    return s.str();
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string flat_supports = "  set Dirichlet = 2 : y : 0\n  set Point constraints = 0, 0 : x : 0\n";
  for (const unsigned int k : {1u, 2u})
    {
      const std::string ks = "k = " + std::to_string(k);
      // a) flat patch test
      for (const std::string normal : {"tied", "unilateral"})
        for (const std::string tangential : {"penalty", "multipliers"})
          compare(two_blocks(testing::block_mesh("structured quads", 0, 0, 1, 1, 3, 3, 0),
                             testing::block_mesh("voronoi", 0, 1, 1, 2, 3, 4, 10), k, normal, tangential,
                             flat_supports, "10"),
                  "a) patch test, " + ks + ", " + normal + ", stick by " + tangential, true);
      // b) curved interface
      for (const std::string normal : {"tied", "unilateral"})
        compare(two_blocks(testing::block_mesh("structured quads", 0, 0, 1, 1, 7, 5, 0, 3) +
                             "subsection Mesh\n  set Transformation = x, y*(1 + 0.15*sin(pi*x))\nend\n",
                           testing::block_mesh("voronoi", 0, 1, 1, 2, 8, 5, 10, 7) +
                             "subsection Mesh\n  set Transformation = x, y + (2 - y)*(0.15*sin(pi*x))\nend\n",
                           k, normal, "multipliers", flat_supports, "10"),
                "b) curved interface, " + ks + ", " + normal + " + tangential multipliers", true);
      // c) rollers and a redundant constraint at the interface end
      for (const std::string normal : {"tied", "unilateral"})
        compare(two_blocks(testing::block_mesh("structured quads", 0, 0, 1, 1, 3, 3, 0),
                           testing::block_mesh("structured quads", 0, 1, 1, 2, 4, 4, 10), k, normal,
                           "multipliers", "  set Dirichlet = 2 : y : 0\n  set Roller = 0, 10\n", "10"),
                "c) rollers on both left sides, " + ks + ", " + normal, true);
      // d) active sets that change over the iterations
      const auto r =
        compare(two_blocks(testing::block_mesh("structured quads", 0, 0, 1, 1, 10, 4, 0),
                           testing::block_mesh("structured quads", 0, 1, 1, 2, 13, 5, 10) +
                             "subsection Mesh\n  set Transformation = x, y + (2 - y)*0.008*(x - 0.5)^2\nend\n",
                           k, "unilateral", "penalty", flat_supports, "10"),
                "d) parabola on a flat block, " + ks, false);
      testing::check(r.active_set_iterations >= 3, "d) parabola, " + ks + ": the active set changes (" +
                                                     std::to_string(r.active_set_iterations) + " iterations)");
      compare(two_blocks(testing::block_mesh("structured quads", 0, 0, 1, 1, 4, 4, 0),
                         testing::block_mesh("structured quads", 0, 1, 1, 2, 7, 7, 10), k, "unilateral", "penalty",
                         "  set Dirichlet = 2 : xy : 0, 0\n", "10 * (x < 0.3)"),
              "d) tipping block, " + ks, false);
    }
  // f) the preconditioner of the stick penalty: on a mesh large enough for
  //    a multilevel AMG (patch test, 24 x 24 quads below, 33 x 33 above,
  //    k = 2, 24,522 DoFs) the condensed penalty system needs about the CG
  //    iterations of the stick-by-multipliers one (AMG alone needed 9-11
  //    times as many), and gives the UMFPACK solution
  {
    const std::string big =
      two_blocks(testing::block_mesh("structured quads", 0, 0, 1, 1, 24, 24, 0),
                 testing::block_mesh("structured quads", 0, 1, 1, 2, 33, 33, 10), 2, "unilateral", "%T%",
                 flat_supports, "10");
    const auto with = [&](const std::string &tangential) {
      std::string t = big;
      t.replace(t.find("%T%"), 3, tangential);
      return t;
    };
    const auto penalty     = compare(with("penalty"), "f) large patch test, stick by penalty", true);
    const auto multipliers = testing::run_contact(with("multipliers") + solver_section("CG-AMG constraints"));
    std::cout << "      CG iterations: stick by penalty " << penalty.linear_iterations << ", by multipliers "
              << multipliers.linear_iterations << std::endl;
    // the stick springs' preconditioner ties them and solves the tied
    // matrix by the p-multigrid too, serially and distributed
    testing::check(penalty.solver.find("p-multigrid") != std::string::npos &&
                     penalty.solver.find("stick springs preconditioned by tying them") != std::string::npos,
                   "f) stick by penalty: the p-multigrid on the tied matrix (solver: " + penalty.solver + ")");
    // the default preconditioner for k = 2 is the p-multigrid, its coarse
    // level tied by the contact constraints between vertices; ML AMG on
    // the whole condensed matrix needs more than twice the iterations
    // (measured 25 against 67)
    const auto amg = testing::run_contact(with("multipliers") + solver_section("CG-AMG constraints") +
                                          "subsection Solver\n  set Preconditioner = AMG\nend\n");
    std::cout << "      CG iterations, stick by multipliers: p-multigrid " << multipliers.linear_iterations
              << ", ML AMG " << amg.linear_iterations << std::endl;
    testing::check(2 * multipliers.linear_iterations <= amg.linear_iterations,
                   "f) CG iterations with the p-multigrid (" + std::to_string(multipliers.linear_iterations) +
                     ") at most half those with ML AMG on the condensed matrix (" +
                     std::to_string(amg.linear_iterations) + ")");
    testing::check(multipliers.linear_iterations > 20 &&
                     penalty.linear_iterations <= 1.3 * multipliers.linear_iterations,
                   "f) CG iterations with the stick penalty (" + std::to_string(penalty.linear_iterations) +
                     ") at most 1.3 times those with stick by multipliers (" +
                     std::to_string(multipliers.linear_iterations) + ")");
  }
  // e) Coulomb friction: a block pressed and sheared through a rigid plate
  //    on top (resultant (Q t, -P), Q = 0.8 mu P, 0.53 mu P on the curved
  //    interface) over three load steps, on a
  //    non-matching interface (flat: quads against Voronoi cells; curved:
  //    y = 1 + 0.1 sin(pi x)); the interface ends slip and open while the
  //    middle sticks. Stick by multipliers and by the penalty, k = 1, 2.
  //    Every solver type against UMFPACK, serially and distributed.
  const auto friction = [&](const unsigned int k, const std::string &tangential, const bool curved) {
    std::ostringstream s;
    s << "set Number of bodies = 2\n"
      << testing::block_mesh("structured quads", 0, 0, 1, 1, 5, 3, 0, curved ? 3 : 1)
      << (curved ? "subsection Mesh\n  set Transformation = x, y*(1 + 0.1*sin(pi*x))\nend\n" : "")
      << "subsection Material\n  set Young's modulus = 1000\n  set Poisson's ratio = 0.3\nend\n"
      << "subsection Body 1\n"
      << testing::block_mesh("voronoi", 0, 1, 1, 2, 4, 3, 10, 3)
      << (curved ? "subsection Mesh\n  set Transformation = x, y + (2 - y)*0.1*sin(pi*x)\nend\n" : "")
      << "subsection Material\n  set Young's modulus = 2000\n  set Poisson's ratio = 0.25\nend\nend\n"
      << "subsection Discretization\n  set Order = " << k << "\nend\n"
      << "subsection Contact\n  set Pairs = 3 : 12\n  set Tangential = " << tangential
      << "\n  set Friction coefficient = 0.3\nend\n"
      << "subsection Load steps\n  set Number of steps = 3\n  set Final time = 1\nend\n"
      << "subsection Boundary conditions and loads\n  set Function constants = P=10, Q="
      << (curved ? "1.6" : "2.4") << "\n"
      << "  set Dirichlet = 2 : xy : 0, 0\n  set Rigid boundary = 13 : Q*t, -P : 0\nend\n"
      << output_section();
    return s.str();
  };
  // (four of the eight combinations, every solver type on the k = 1 ones;
  // a Debug build -- the sanitizer run, some 30 times slower -- the first
  // one only, and none in its np = 2 run)
  struct FrictionCase
  {
    unsigned int k;
    std::string  tangential;
    bool         curved;
  };
  std::vector<FrictionCase> friction_cases = {{1, "coulomb", false}};
#ifndef DEBUG
  friction_cases.push_back({1, "coulomb penalty", true});
  friction_cases.push_back({2, "coulomb", true});
  friction_cases.push_back({2, "coulomb penalty", false});
#else
  // (under mpirun the serial run's distributed cases cover the paths)
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    friction_cases.clear();
#endif
  for (const auto &fc : friction_cases)
        {
          const unsigned int k = fc.k;
          const std::string &tangential = fc.tangential;
          const bool         curved     = fc.curved;
          const auto r = compare(friction(k, tangential, curved),
                                 "e) Coulomb friction (" + tangential + "), " + (curved ? "curved" : "flat") +
                                   " interface, k = " + std::to_string(k),
                                 false, k == 1);
          unsigned int slip = 0;
          for (const auto &s : r.steps)
            slip += s.n_slip;
          testing::check(slip > 0 && r.dissipated_energy > 0,
                         "e) pairs slip in some load step (" + std::to_string(slip) + " slipping pair-steps)");
        }
  // the solvers the distributed path refuses
  const auto small = [&](const std::string &tangential) {
    return two_blocks(testing::block_mesh("structured quads", 0, 0, 1, 1, 3, 3, 0),
                      testing::block_mesh("structured quads", 0, 1, 1, 2, 4, 4, 10), 1, "unilateral", tangential,
                      flat_supports, "10");
  };
  testing::check_throws(
    [&] {
      testing::run_contact(small("penalty") +
                             solver_section("GMRES-AMG"),
                           MPI_COMM_WORLD, dealvem::ElasticityProblem::Parallelism::distributed);
    },
    "GMRES-AMG works on the whole saddle-point system, which is not distributed",
    "GMRES-AMG is refused on the distributed path");
  testing::check_throws(
    [&] {
      testing::run_contact(small("penalty") + solver_section("UMFPACK"), MPI_COMM_WORLD,
                           dealvem::ElasticityProblem::Parallelism::distributed);
    },
    "UMFPACK works on the whole saddle-point system, which is not distributed",
    "UMFPACK (the saddle point factored as a whole) is refused on the distributed path");
  // under mpirun: the partition cuts contact constraints (pairs whose two
  // nodes are owned by different processes)
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    testing::check(total_rows_across > 0, "contact constraint rows cut by the partition over all cases: " +
                                            std::to_string(total_rows_across));
  return testing::finish();
}
