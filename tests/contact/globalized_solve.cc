// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The globalized contact solve (PrimalActiveSetSolver behind
// ActiveSetSolver's fast path) and its collapse mechanism.
// Throughout: a lower block [0,1]^2 (4 x 4 quads, bottom held), an upper
// block on it, unilateral contact (Pairs = 3 : 12), E = 7000, nu = 0.3.
//
// 1. Same solution as the fast path. The upper block [0,1]x[1,2] (7 x 7
//    quads) pressed by 10 on the left part of its top (x < 0.3), so that
//    the right part of the interface opens, for k = 1, 2 and Tangential =
//    frictionless (a point constraint against sliding at (0,2)), penalty
//    and multipliers: solved once normally (the fast path converges, in
//    >= 2 iterations) and once with 'Maximum active set iterations = 1', so
//    that the fast path gives up and the globalized solve takes over
//    (asserted from the printed report: "globalized solve: the active-set
//    iteration gave up"). Frictionless: the globalized solve minimises the
//    fast path's convex model, whose solution is unique (K positive
//    definite on the motions the constraints leave); stick: its convex
//    solution is polished back to the fast path's model. Both must end
//    with the same active set (some pairs open, some closed), and
//    displacements and nodal normal and tangential contact forces equal to
//    1e-10 of their largest value (measured: 0, both end with a direct
//    solve of the same system; 1e-10 leaves room for a different last
//    solve path, and a different solution differs by far more).
// 2. A mechanism by frictionless sliding. With only the base, nothing
//    holds a frictionless block along the straight interface even with
//    every pair closed, and ContactProblem refuses the model at set-up
//    ("Unsupported body / rigid-body mode", checked). Since every body must
//    be held with all pairs closed, a mechanism always opens some pair: a
//    motion that keeps every pair closed would be free with all pairs
//    closed. So the sliding mechanism is set up with a wall: body 2,
//    [-0.5,0]x[1,2] (2 x 4 quads, its left side held), in frictionless
//    contact with the upper block's left side (Pairs 21 : 10); the upper
//    block pressed down (10) and pushed away from the wall (traction 1
//    along x) on its top. Any equilibrium would need a horizontal contact
//    force pulling towards the wall: "No static equilibrium" (found by the
//    globalized solve), failing condition "no-tension joints and
//    frictionless sliding" (the wall pairs open, the base pairs slide), the
//    upper block alone moving, by the translation (1, 0) (largest
//    displacement 1; rotation and |t_y| / |t_x| below 1e-12: a null vector
//    of the closed pairs' rows, computed to round-off), the work of the
//    loads on it 1 (the traction 1 over the top's length 1; 1e-12), the
//    largest violation of the contact conditions below 1e-12 (round-off of
//    a motion of size 1), the 21 base pairs (k = 2) closed and sliding and
//    the 21 wall pairs opening; the files <prefix>-mechanism.vtu and .svg
//    are written.
// 3. A mechanism by opening: the upper block pulled off its base
//    (pressure -10 on its top), stick by multipliers: the upper block
//    translates upwards (|t_x| / |t_y| and rotation below 1e-12), every one
//    of the 11 pairs opens (none stays closed, none slides), the work is
//    10 (1e-11), and the failing condition is "no-tension joints" (the
//    code's name for a mechanism that opens pairs and slides none; "no
//    support" is for a moving body with no pair at all, which the set-up
//    check excludes as in 2).
// 4. A block that tips over: an upper block [0,1]x[1,3] (4 x 8 quads),
//    stick by multipliers, body force (0, -b), b = 10, and a traction
//    (q, 0) on its top (y = 3). Statics of the rigid block about its
//    bottom right corner (1,1): the traction's resultant q acts 2 above
//    the corner (tipping moment 2 q, clockwise); the weight 2 b acts at
//    x = 0.5, 0.5 left of the corner (restoring moment 2 b * 0.5 = b). It
//    tips iff 2 q > b: q_crit = b / 2. The contact forces are nodal forces
//    at the pairs, the corner pair among them, and stick carries any
//    tangential force, so the discrete problem has an equilibrium iff the
//    rigid block has one (linear elasticity with unilateral constraints:
//    Farkas), and the discrete loads of a constant body force and traction
//    have the exact resultant and moment (rectangular cells). So, for
//    k = 1, 2: at 0.99 q_crit the block stands (a solution, contact force
//    + load = 0 to 1e-10 of the load, part of the joint open); at
//    1.01 q_crit "No static equilibrium" (found by the globalized solve),
//    the upper block alone rotating (rotates, clockwise) about (1,1) to
//    1e-8 of the block size (measured: round-off), by -1/sqrt(5) (the far
//    corner (0,3), sqrt(5) from the hinge, moves by 1; 1e-12), the work
//    (2.02 q_crit - b) / sqrt(5) = 0.02 q_crit / sqrt(5) (1e-12), largest
//    violation below 1e-12, exactly one closed pair, at (1,1) (1e-12),
//    every other pair opening, failing condition "no-tension joints".
//    The centre is computed here from the motion's translation, rotation
//    and centroid, and PieceMotion::centre must be the same point (1e-8).
// 5. Energy monotone: PrimalActiveSetSolver called directly on the tipping
//    block of 4 (k = 2; 0.99 and 1.01 q_crit) and on that block,
//    frictionless, pressed by 10 on x < 0.3 and held in x at its top left
//    corner: the energy 1/2 u.K u - f.u after each step never rises (1e-12
//    of its largest magnitude: round-off of the energy sums), there is
//    more than one step, the solve ends as 4 says (converged at 0.99, a
//    mechanism at 1.01), and at convergence the KKT conditions hold (gap
//    >= -1e-10 of the largest displacement, normal multipliers compressive
//    to 1e-10 of the largest). At 1.01 the motion field itself is checked:
//    0 at the upper block's vertex (1,1), (2,1)/sqrt(5) at its vertex
//    (0,3) (1e-12).
// 6. The friction limit of a block on a slope (Coulomb friction, the
//    Tresca fixed point of FrictionSolver and its certificate): the upper
//    block [0,1]x[1,1.5] (5 x 2 quads, not matching the lower block's 4
//    cells) under the body force (q, -b), b = 10 (the weight on a slope of
//    tan(theta) = q/b), mu = 0.4, Tangential = coulomb and coulomb penalty,
//    k = 1, 2. Statics of the rigid block: the joint carries the normal
//    force b A (A = 0.5) and must carry the tangential force q A, so it
//    stands iff q <= mu b (it would tip only for q > 2 b). At 0.99 mu b it
//    stands (contact force + load = 0 to 1e-10 of the load; |tau| <= mu p
//    at every pair, 1e-10 of the largest pressure). At 1.01 mu b: "No
//    static equilibrium" with the mechanism of the Tresca problem whose
//    bounds mu |N| hold no equilibrium: failing condition "friction", the
//    upper block alone translating by (1, 0) (1e-10; rotation below
//    1e-10), the work of the loads q A (1e-10 relative) against at most
//    mu b A that friction can absorb (1e-8 relative: the normal forces sum
//    to b A whatever their distribution), largest violation below 1e-10.
// All runs are small (at most a few hundred DoFs): about 2 s in Release.
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/contact/active_set_solver.h>
#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/contact/primal_active_set.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/solvers/saddle_point_solver.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>

#include "../contact_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
  /// A run of ContactProblem: its printed report, the exception (if any),
  /// the results and the collapse mechanism.
  struct Run
  {
    bool                                threw = false;
    std::string                         message, report;
    ContactProblem::Results             results;
    std::unique_ptr<CollapseMechanism>  mechanism;

    bool
    globalized() const
    {
      return report.find("globalized solve: the active-set iteration gave up") != std::string::npos;
    }
  };

  Run
  run(const std::string &prm_text)
  {
    dealii::ParameterHandler prm;
    ElasticityProblem::declare_parameters(prm);
    ContactProblem::declare_parameters(prm);
    prm.parse_input_from_string(prm_text);
    ContactProblem problem(MPI_COMM_SELF, ElasticityProblem::Parallelism::automatic);
    problem.parse_parameters(prm);
    Run                r;
    std::ostringstream captured;
    auto              *old = std::cout.rdbuf(captured.rdbuf());
    try
      {
        problem.run();
      }
    catch (const std::exception &e)
      {
        r.threw   = true;
        r.message = testing::collapse_white_space(e.what());
      }
    std::cout.rdbuf(old);
    r.report = captured.str();
    if (!r.threw)
      r.results = problem.get_results();
    if (problem.collapse_mechanism() != nullptr)
      r.mechanism = std::make_unique<CollapseMechanism>(*problem.collapse_mechanism());
    return r;
  }

  const char *material = "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\n";

  /// The lower block [0,1]^2 and an upper block [0,1]x[1,1+h] (nx x ny),
  /// with the given contact models, loads and output.
  std::string
  prm(const unsigned int k, const std::string &tangential, const double h, const unsigned int nx,
      const unsigned int ny, const std::string &loads, const std::string &extra_contact = "",
      const std::string &folder = "output", const bool files = false)
  {
    std::ostringstream s;
    s << "set Number of bodies = 2\n"
      << testing::block_mesh("structured quads", 0, 0, 1, 1, 4, 4, 0) << material << "subsection Body 1\n"
      << testing::block_mesh("structured quads", 0, 1, 1, 1 + h, nx, ny, 10) << material << "end\n"
      << "subsection Discretization\n  set Order = " << k << "\nend\n"
      << "subsection Contact\n  set Pairs = 3 : 12\n  set Normal = unilateral\n  set Tangential = " << tangential
      << "\n" << extra_contact << "end\n"
      << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : xy : 0, 0\n" << loads << "end\n"
      << "subsection Output\n  set Folder = " << folder << "\n  set Write VTU = " << (files ? "true" : "false")
      << "\n  set Write pictures = " << (files ? "true" : "false")
      << "\n  set Write CSV = false\n  set Write JSON = false\nend\n";
    return s.str();
  }

  /// max_i |a_i - b_i| / max_i |a_i|
  template <typename A, typename B>
  double
  relative_difference(const unsigned int n, const A &a, const B &b)
  {
    double d = 0, size = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        d    = std::max(d, std::abs(a(i) - b(i)));
        size = std::max(size, std::abs(a(i)));
      }
    return size > 0 ? d / size : d;
  }

  /// The point a rigid motion (translation t of the centroid G, rotation
  /// theta counter-clockwise) leaves in place: t + theta (-(c - G)_y,
  /// (c - G)_x) = 0, i.e. c = G + (-t_y, t_x) / theta (the check of
  /// PieceMotion::centre).
  dealii::Point<2>
  centre(const CollapseMechanism::PieceMotion &p)
  {
    return p.centroid + dealii::Tensor<1, 2>({-p.translation[1] / p.rotation, p.translation[0] / p.rotation});
  }

  std::string
  show(const dealii::Tensor<1, 2> &t)
  {
    std::ostringstream s;
    s << std::setprecision(6) << "(" << t[0] << ", " << t[1] << ")";
    return s.str();
  }

  // ---------------------------------------------------------------------
  // 1. the globalized solve gives the fast path's solution
  void
  same_solution()
  {
    for (const unsigned int k : {1u, 2u})
      for (const std::string tangential : {"frictionless", "penalty", "multipliers"})
        {
          const std::string tag   = "1. k=" + std::to_string(k) + ", " + tangential;
          std::string       loads = "  set Pressure = 13 : 10 * (x < 0.3)\n";
          if (tangential == "frictionless")
            loads += "  set Point constraints = 0, 2 : x : 0 : 1\n";
          const Run fast = run(prm(k, tangential, 1, 7, 7, loads));
          const Run glob = run(prm(k, tangential, 1, 7, 7, loads, "  set Maximum active set iterations = 1\n"));
          if (fast.threw || glob.threw)
            {
              testing::check(false, tag + ": both runs solve (" + fast.message + " / " + glob.message + ")");
              continue;
            }
          const auto &a = fast.results, &b = glob.results;
          std::cout << tag << ": fast path " << a.active_set_iterations << " iterations; globalized:"
                    << glob.report.substr(glob.report.find("globalized solve:") + 17,
                                          glob.report.find('\n', glob.report.find("globalized solve:")) -
                                            glob.report.find("globalized solve:") - 17)
                    << std::endl;
          testing::check(!fast.globalized() && a.active_set_iterations >= 2,
                         tag + ": the fast path converges by itself, in " +
                           std::to_string(a.active_set_iterations) + " (>= 2) iterations");
          testing::check(glob.globalized(), tag + ": with 1 iteration allowed, the globalized solve takes over");
          bool         same_set = a.pairs.size() == b.pairs.size() && !a.pairs.empty();
          unsigned int n_open   = 0;
          for (unsigned int i = 0; same_set && i < a.pairs.size(); ++i)
            {
              same_set = same_set && a.pairs[i].active == b.pairs[i].active &&
                         a.pairs[i].location.distance(b.pairs[i].location) < 1e-14;
              n_open += !a.pairs[i].active;
            }
          testing::check(same_set && n_open > 0 && n_open < a.pairs.size(),
                         tag + ": the same active set (" + std::to_string(n_open) + " of " +
                           std::to_string(a.pairs.size()) + " pairs open)");
          if (!same_set)
            continue;
          testing::check_small(relative_difference(
                                 a.solution.size(), [&](unsigned i) { return a.solution[i]; },
                                 [&](unsigned i) { return i < b.solution.size() ? b.solution[i] : 1e300; }),
                               1e-10, tag + ": max |u_fast - u_globalized| / max |u_fast|");
          testing::check_small(relative_difference(
                                 a.pairs.size(), [&](unsigned i) { return a.pairs[i].multiplier; },
                                 [&](unsigned i) { return b.pairs[i].multiplier; }),
                               1e-10, tag + ": max |lambda_fast - lambda_globalized| / max |lambda_fast|");
          // the tangential nodal forces against the normal ones' size
          double tdiff = 0, lmax = 0;
          for (unsigned int i = 0; i < a.pairs.size(); ++i)
            {
              tdiff = std::max(tdiff, std::abs(a.pairs[i].tangential_traction * a.pairs[i].weight -
                                               b.pairs[i].tangential_traction * b.pairs[i].weight));
              lmax  = std::max(lmax, std::abs(a.pairs[i].multiplier));
            }
          testing::check_small(tdiff / lmax, 1e-10,
                               tag + ": max |tangential force difference| / max |lambda_fast|");
        }
  }

  // ---------------------------------------------------------------------
  // 2. frictionless sliding: the upper block between its base and a wall
  // (body 2, [-0.5,0]x[1,2], its left side held) on its left, pushed away
  // from the wall
  void
  frictionless_sliding()
  {
    // without the wall nothing holds the block along the interface even
    // with every pair closed: ContactProblem refuses the model before any
    // solve (so a mechanism in which closed pairs slide and none opens
    // cannot arise: every body is held with all pairs closed)
    testing::check_throws(
      [&] { testing::run_contact(prm(2, "frictionless", 1, 7, 7, "  set Pressure = 13 : 10\n  set Traction = 13 : 1, 0\n")); },
      "Unsupported body / rigid-body mode", "2. frictionless, nothing against sliding: refused at set-up");
    const std::string folder = "output-sliding";
    std::filesystem::remove_all(folder);
    std::string text = prm(2, "frictionless", 1, 7, 7,
                           "  set Dirichlet = 2 : xy : 0, 0; 20 : xy : 0, 0\n"
                           "  set Pressure = 13 : 10\n  set Traction = 13 : 1, 0\n",
                           "", folder, true);
    text.replace(text.find("set Number of bodies = 2"), 24, "set Number of bodies = 3");
    text.replace(text.find("set Pairs = 3 : 12"), 18, "set Pairs = 3 : 12; 21 : 10");
    text.insert(text.find("subsection Discretization"),
                "subsection Body 2\n" + testing::block_mesh("structured quads", -0.5, 1, 0, 2, 2, 4, 20) +
                  material + "end\n");
    const Run         r   = run(text);
    const std::string tag = "2. frictionless sliding";
    testing::check(r.threw && r.message.find("No static equilibrium") != std::string::npos,
                   tag + ": no static equilibrium (" + r.message.substr(0, 200) + ")");
    testing::check(r.message.find("The globalized solve then found the mechanism") != std::string::npos,
                   tag + ": found by the globalized solve");
    testing::check(r.mechanism != nullptr, tag + ": ContactProblem keeps the collapse mechanism");
    if (r.mechanism == nullptr)
      return;
    const auto &m = *r.mechanism;
    std::cout << tag << ": failing condition '" << m.failing_condition << "', " << m.moving.size()
              << " moving piece(s), work " << m.work << ", relative work " << m.relative_work << ", "
              << m.sliding_pairs.size() << " sliding, " << m.opening_pairs.size() << " opening, "
              << m.closed_pairs.size() << " closed pairs" << std::endl;
    // the wall pairs open, the base pairs slide: both conditions fail
    testing::check(m.failing_condition.rfind("no-tension joints and frictionless sliding", 0) == 0,
                   tag + ": failing condition starts with 'no-tension joints and frictionless sliding' ('" +
                     m.failing_condition + "')");
    testing::check(m.moving.size() == 1 && m.moving[0].body == 1, tag + ": the upper block (body 1) moves, alone");
    if (m.moving.size() == 1)
      {
        const auto &p = m.moving[0];
        std::cout << tag << ": translation " << show(p.translation) << ", rotation " << p.rotation << std::endl;
        testing::check(!p.rotates && p.translation[0] > 0, tag + ": a translation along +x (the load's direction)");
        testing::check_small(p.rotation, 1e-12, tag + ": rotation");
        testing::check_small(std::abs(p.translation[1]) / std::abs(p.translation[0]), 1e-12,
                             tag + ": |t_y| / |t_x|");
        testing::check_near(p.translation[0], 1., 1e-12, tag + ": t_x (largest displacement 1)");
        // work of the loads on the unit translation: the traction 1 on
        // the top of length 1 (the pressure is normal to it)
        testing::check_near(m.work, 1., 1e-12, tag + ": work of the loads");
      }
    testing::check_small(m.largest_violation, 1e-12, tag + ": largest violation of the contact conditions");
    // pairs along the interfaces (structured meshes: the union of both
    // sides' nodes, the ends shared; k = 2 adds the midpoints): the base
    // 8 + 5 - 2 = 11 vertices and 10 midpoints slide (every one stays closed
    // and moves along the interface), the wall 8 + 5 - 2 = 11 vertices and
    // 10 midpoints open
    testing::check(m.sliding_pairs.size() == 21 && m.closed_pairs.size() == 21 && m.opening_pairs.size() == 21,
                   tag + ": the 21 base pairs slide (" + std::to_string(m.sliding_pairs.size()) +
                     ", closed " + std::to_string(m.closed_pairs.size()) + "), the 21 wall pairs open (" +
                     std::to_string(m.opening_pairs.size()) + ")");
    for (const std::string f : {"-mechanism.vtu", "-mechanism.svg"})
      testing::check(std::filesystem::exists(folder + "/solution" + f),
                     tag + ": " + folder + "/solution" + f + " written");
  }

  // ---------------------------------------------------------------------
  // 3. pulled off: every pair opens
  void
  pulled_off()
  {
    const std::string tag = "3. pulled off, stick";
    const Run         r   = run(prm(1, "multipliers", 1, 7, 7, "  set Pressure = 13 : -10\n"));
    testing::check(r.threw && r.message.find("No static equilibrium") != std::string::npos,
                   tag + ": no static equilibrium (" + r.message.substr(0, 200) + ")");
    testing::check(r.message.find("The globalized solve then found the mechanism") != std::string::npos,
                   tag + ": found by the globalized solve");
    testing::check(r.mechanism != nullptr, tag + ": ContactProblem keeps the collapse mechanism");
    if (r.mechanism == nullptr)
      return;
    const auto &m = *r.mechanism;
    std::cout << tag << ": failing condition '" << m.failing_condition << "', work " << m.work << ", "
              << m.opening_pairs.size() << " opening, " << m.closed_pairs.size() << " closed, "
              << m.sliding_pairs.size() << " sliding pairs" << std::endl;
    testing::check(m.failing_condition.rfind("no-tension joints", 0) == 0,
                   tag + ": failing condition starts with 'no-tension joints' ('" + m.failing_condition + "')");
    testing::check(m.moving.size() == 1 && m.moving[0].body == 1, tag + ": the upper block (body 1) moves, alone");
    if (m.moving.size() == 1)
      {
        const auto &p = m.moving[0];
        std::cout << tag << ": translation " << show(p.translation) << ", rotation " << p.rotation << std::endl;
        testing::check(!p.rotates && p.translation[1] > 0, tag + ": a translation upwards");
        testing::check_small(p.rotation, 1e-12, tag + ": rotation");
        testing::check_small(std::abs(p.translation[0]) / std::abs(p.translation[1]), 1e-12,
                             tag + ": |t_x| / |t_y|");
      }
    // the pairs along the interface: the union of both sides' vertices,
    // the ends shared (8 + 5 - 2 = 11)
    testing::check(m.opening_pairs.size() == 11 && m.closed_pairs.empty() && m.sliding_pairs.empty(),
                   tag + ": every pair (11) opens (" + std::to_string(m.opening_pairs.size()) + "), none stays closed (" +
                     std::to_string(m.closed_pairs.size()) + ")");
    // the pressure -10 on the top of length 1, on the unit translation
    testing::check_near(m.work, 10., 1e-11, tag + ": work of the loads");
    testing::check_small(m.largest_violation, 1e-12, tag + ": largest violation of the contact conditions");
  }

  // ---------------------------------------------------------------------
  // 4. the tipping block
  const double b      = 10;    // body force (0, -b)
  const double q_crit = b / 2; // tipping traction on the top (see the header)

  std::string
  tipping_loads(const double q)
  {
    std::ostringstream s;
    s << std::setprecision(17) << "  set Body force = 0, " << -b << "\n  set Traction = 13 : " << q << ", 0\n";
    return s.str();
  }

  void
  tipping()
  {
    for (const unsigned int k : {1u, 2u})
      {
        const std::string tag = "4. tipping block, k=" + std::to_string(k);
        // just below the tipping load: it stands
        const Run    stand = run(prm(k, "multipliers", 2, 4, 8, tipping_loads(0.99 * q_crit)));
        unsigned int n_open = 0, n_pairs = 0;
        if (stand.threw)
          testing::check(false, tag + ", 0.99 q_crit: the block stands (" + stand.message.substr(0, 300) + ")");
        else
          {
            const auto &r = stand.results;
            n_pairs       = r.pairs.size();
            for (const auto &pr : r.pairs)
              n_open += !pr.active;
            const double load = r.applied_load_per_body[1].norm();
            std::cout << tag << ", 0.99 q_crit: " << n_open << " of " << n_pairs << " pairs open, "
                      << (stand.globalized() ? "globalized solve" : "fast path") << ", "
                      << r.active_set_iterations << " active-set iterations" << std::endl;
            testing::check(true, tag + ", 0.99 q_crit: the block stands");
            testing::check_small((r.total_contact_force + r.applied_load_per_body[1]).norm() / load, 1e-10,
                                 tag + ", 0.99 q_crit: |contact force + load| / |load|");
            testing::check(n_open > 0, tag + ", 0.99 q_crit: part of the joint opens");
          }
        // just above: it tips about (1,1)
        const Run r = run(prm(k, "multipliers", 2, 4, 8, tipping_loads(1.01 * q_crit)));
        testing::check(r.threw && r.message.find("No static equilibrium") != std::string::npos,
                       tag + ", 1.01 q_crit: no static equilibrium (" + r.message.substr(0, 200) + ")");
        testing::check(r.message.find("The globalized solve then found the mechanism") != std::string::npos,
                       tag + ", 1.01 q_crit: found by the globalized solve");
        testing::check(r.mechanism != nullptr, tag + ", 1.01 q_crit: ContactProblem keeps the collapse mechanism");
        if (r.mechanism == nullptr)
          continue;
        const auto &m = *r.mechanism;
        std::cout << tag << ", 1.01 q_crit: failing condition '" << m.failing_condition << "', work " << m.work
                  << ", " << m.opening_pairs.size() << " opening, " << m.closed_pairs.size() << " closed pairs"
                  << std::endl;
        testing::check(m.moving.size() == 1 && m.moving[0].body == 1,
                       tag + ", 1.01 q_crit: the upper block (body 1) moves, alone");
        if (m.moving.size() == 1)
          {
            const auto &p = m.moving[0];
            const auto c = centre(p);
            std::cout << tag << ", 1.01 q_crit: rotation " << p.rotation << ", translation " << show(p.translation)
                      << " of the centroid (" << p.centroid << "): a rotation about (" << c
                      << "); PieceMotion::centre says (" << p.centre << ")" << std::endl;
            testing::check(p.rotates && p.rotation < 0, tag + ", 1.01 q_crit: a rotation (clockwise)");
            testing::check_small(c.distance(dealii::Point<2>(1, 1)) / 2, 1e-8,
                                 tag + ", 1.01 q_crit: |centre - (1,1)| / block height");
            testing::check_small(p.centre.distance(dealii::Point<2>(1, 1)) / 2, 1e-8,
                                 tag + ", 1.01 q_crit: |PieceMotion::centre - (1,1)| / block height");
            // the far corner (0,3), sqrt(5) from the centre, moves by 1
            testing::check_near(p.rotation, -1 / std::sqrt(5.), 1e-12, tag + ", 1.01 q_crit: rotation");
          }
        // the work on that rotation: traction 1.01 q_crit, 2 above the
        // corner, minus the weight 2 b, 0.5 beside it, times 1/sqrt(5):
        // (2.02 q_crit - b) / sqrt(5) = 0.02 q_crit / sqrt(5)
        testing::check_near(m.work, 0.02 * q_crit / std::sqrt(5.), 1e-12, tag + ", 1.01 q_crit: work of the loads");
        testing::check_small(m.largest_violation, 1e-12, tag + ", 1.01 q_crit: largest violation");
        testing::check(m.closed_pairs.size() == 1 &&
                         m.closed_pair_locations[0].distance(dealii::Point<2>(1, 1)) <= 1e-12,
                       tag + ", 1.01 q_crit: one closed pair (the hinge), at (1,1)");
        testing::check(n_pairs > 0 && m.opening_pairs.size() + 1 == n_pairs && m.sliding_pairs.empty(),
                       tag + ", 1.01 q_crit: every other pair opens (" + std::to_string(m.opening_pairs.size()) +
                         " of " + std::to_string(n_pairs) + ")");
        testing::check(m.failing_condition.rfind("no-tension joints", 0) == 0,
                       tag + ", 1.01 q_crit: failing condition 'no-tension joints' ('" + m.failing_condition +
                         "')");
      }
  }

  // ---------------------------------------------------------------------
  // 5. PrimalActiveSetSolver directly: the energy never rises
  struct Direct
  {
    std::map<dealii::types::material_id, ElasticMaterial> materials{{0, ElasticMaterial(7000, 0.3)},
                                                                    {1, ElasticMaterial(7000, 0.3)}};
    PolygonalMesh<2>                                      mesh;
    VEMDoFHandler<2>                                      dof_handler;
    std::vector<NodeInsertion::Interface>                 interfaces;
    ContactSettings                                       settings;
    std::unique_ptr<ContactScales>                        scales;
    std::unique_ptr<ContactAssembler<2>>                  contact;
    dealii::AffineConstraints<double>                     constraints;
    dealii::SparsityPattern                               sparsity;
    dealii::SparseMatrix<double>                          system_matrix;
    dealii::Vector<double>                                system_rhs;
    unsigned int                                          n = 0;

    // the tipping block of case 4 (k = 2): q > 0 with stick by
    // multipliers; q = 0: frictionless, pressure 10 (x < 0.3), held in x at
    // its top left corner
    Direct(const double q)
    {
      settings.normal     = ContactSettings::Normal::unilateral;
      settings.tangential = q > 0 ? ContactSettings::Tangential::multipliers :
                                    ContactSettings::Tangential::frictionless;
      const unsigned int degree = 2;
      PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 4, 4);
      PolygonalMesh<2> body;
      PolygonalMeshGenerators::structured_quads(body, dealii::Point<2>(0, 1), dealii::Point<2>(1, 3), 4, 8);
      for (unsigned int c = 0; c < body.n_cells(); ++c)
        body.set_material_id(c, 1);
      for (unsigned int e = 0; e < body.n_edges(); ++e)
        if (body.edge(e).at_boundary())
          body.set_edge_boundary_id(e, body.edge(e).boundary_id + 10);
      mesh.append(body);
      interfaces = {NodeInsertion::insert(mesh, 3, 12, degree, NodeInsertion::Settings())};
      dof_handler.reinit(mesh);
      dof_handler.distribute_dofs(degree);
      scales  = std::make_unique<ContactScales>(std::vector<double>{7000, 7000}, interfaces);
      contact = std::make_unique<ContactAssembler<2>>(dof_handler, interfaces[0].pairs, settings,
                                                      scales->penalty(settings));
      dealii::Functions::ZeroFunction<2> zero(2);
      BoundaryConditions::interpolate_boundary_values(dof_handler, {2}, zero, {{true, true}}, constraints);
      if (q == 0)
        BoundaryConditions::add_point_constraint(dof_handler, dealii::Point<2>(0, 3), 0, 0., constraints);
      constraints.close();
      n = dof_handler.n_dofs();
      dealii::DynamicSparsityPattern dsp(n + contact->n_multipliers());
      dof_handler.make_sparsity_pattern(dsp);
      contact->add_sparsity(dsp);
      constraints.condense(dsp);
      sparsity.copy_from(dsp);
      system_matrix.reinit(sparsity);
      system_rhs.reinit(n + contact->n_multipliers());
      ElasticityAssembler<2>                 assembler(dof_handler, materials);
      dealii::Functions::ConstantFunction<2> force(std::vector<double>{0., -b});
      dealii::Functions::ConstantFunction<2> traction(std::vector<double>{q, 0.});
      dealii::ScalarFunctionFromFunctionObject<2> pressure(
        [](const dealii::Point<2> &p) { return p[0] < 0.3 ? 10. : 0.; });
      if (q > 0)
        {
          assembler.set_body_force(force);
          assembler.add_traction(13, traction);
        }
      else
        assembler.add_pressure(13, pressure);
      assembler.assemble(constraints, system_matrix, system_rhs);
    }
  };

  // 6. a block on a slope at its friction limit
  void
  slope()
  {
    const double mu = 0.4, b = 10, A = 0.5;
    for (const unsigned int k : {1u, 2u})
      for (const std::string tangential : {"coulomb", "coulomb penalty"})
        for (const double ratio : {0.99, 1.01})
          {
            const double      q   = ratio * mu * b;
            const std::string tag = "6. slope, k=" + std::to_string(k) + ", " + tangential + ", q = " +
                                    std::to_string(ratio).substr(0, 4) + " mu b";
            std::ostringstream loads, contact;
            loads << std::setprecision(17) << "  set Body force = " << q << ", " << -b << "\n";
            contact << "  set Friction coefficient = " << mu << "\n";
            const Run r = run(prm(k, tangential, 0.5, 5, 2, loads.str(), contact.str()));
            if (ratio < 1)
              {
                testing::check(!r.threw, tag + ": the block stands" +
                                           (r.threw ? " (" + r.message.substr(0, 300) + ")" : std::string()));
                if (r.threw)
                  continue;
                const auto  &res  = r.results;
                const double load = res.applied_load_per_body[1].norm();
                testing::check_small((res.total_contact_force + res.applied_load_per_body[1]).norm() / load,
                                     1e-10, tag + ": |contact force + load| / |load|");
                // the nodal values: friction traction and pressure of each
                // pair's forces (force / tributary weight)
                double pmax = 0, excess = -1e300, ratio_max = 0;
                for (const auto &pr : res.pairs)
                  pmax = std::max(pmax, std::abs(pr.lumped_pressure));
                for (const auto &pr : res.pairs)
                  {
                    excess = std::max(excess, std::abs(pr.tangential_traction) - mu * pr.lumped_pressure);
                    if (pr.lumped_pressure > 0)
                      ratio_max = std::max(ratio_max, std::abs(pr.tangential_traction) / pr.lumped_pressure);
                  }
                std::cout << tag << ": largest |tau| / p " << ratio_max << std::endl;
                testing::check(excess <= 1e-10 * pmax, tag + ": |tau| <= mu p at every pair");
                continue;
              }
            testing::check(r.threw && r.message.find("No static equilibrium") != std::string::npos,
                           tag + ": no static equilibrium");
            testing::check(r.message.find("failing condition: friction") != std::string::npos,
                           tag + ": the message names friction as the failing condition");
            testing::check(r.mechanism != nullptr, tag + ": a collapse mechanism");
            if (r.mechanism == nullptr)
              continue;
            const auto &m = *r.mechanism;
            std::cout << tag << ": failing condition '" << m.failing_condition << "', work " << m.work
                      << ", friction absorbs at most " << m.friction_dissipation << std::endl;
            testing::check(m.failing_condition.find("friction") == 0, tag + ": failing condition friction");
            testing::check(m.moving.size() == 1 && m.moving[0].body == 1, tag + ": the upper block moves, alone");
            if (m.moving.size() == 1)
              {
                const auto &p = m.moving[0];
                testing::check_small(std::abs(p.translation[0] - 1) + std::abs(p.translation[1]), 1e-10,
                                     tag + ": it translates by (1, 0)");
                testing::check_small(std::abs(p.rotation), 1e-10, tag + ": it does not rotate");
              }
            testing::check_near(m.work, q * A, 1e-10 * q * A, tag + ": work of the loads q A");
            testing::check_near(m.friction_dissipation, mu * b * A, 1e-8 * mu * b * A,
                                tag + ": friction absorbs at most mu b A");
            testing::check_small(m.largest_violation, 1e-10, tag + ": largest violation");
          }
  }

  void
  energy_monotone()
  {
    for (const double factor : {0.99, 1.01, 0.})
      {
        const std::string tag =
          factor > 0 ? "5. direct, tipping block, " + std::to_string(factor).substr(0, 4) + " q_crit" :
                       "5. direct, frictionless, pressure on x < 0.3";
        Direct                       pb(factor * q_crit);
        dealii::SparseMatrix<double> matrix(pb.sparsity);
        SaddlePointSolver            solver(SaddlePointSolver::Settings{});
        PrimalActiveSetSolver<2>     primal(*pb.contact, pb.constraints, solver, pb.settings);
        // (x sized by the caller: PrimalActiveSetSolver sizes its rigid
        // steps by x.size(), see the report)
        dealii::Vector<double>       x(pb.system_matrix.m());
        const auto                   r = primal.solve(pb.system_matrix, pb.system_rhs, matrix, x);
        double                       scale = 0, rise = 0;
        for (const double e : r.energy)
          scale = std::max(scale, std::abs(e));
        for (unsigned int i = 1; i < r.energy.size(); ++i)
          rise = std::max(rise, r.energy[i] - r.energy[i - 1]);
        std::cout << tag << ": " << (r.converged ? "converged" : "mechanism") << ", " << r.n_solves
                  << " solves, " << r.n_rigid_steps << " rigid steps, energies:";
        for (const double e : r.energy)
          std::cout << " " << std::setprecision(10) << e;
        std::cout << std::endl;
        testing::check(r.converged == (factor < 1), tag + (factor < 1 ? ": converges" : ": a mechanism"));
        testing::check(r.energy.size() >= 2, tag + ": more than one step (" + std::to_string(r.energy.size()) +
                                               " energies)");
        testing::check_small(std::max(rise, 0.) / scale, 1e-12, tag + ": largest rise of the energy / max |energy|");
        if (factor >= 1)
          {
            // the motion field itself: the upper block's vertex at (1,1)
            // stays, its vertex at (0,3) moves by 1, perpendicular to the
            // radius from (1,1), clockwise: (2, 1) / sqrt(5)
            const auto &m = r.mechanism;
            testing::check(m.moving.size() == 1 && m.moving[0].rotates &&
                             centre(m.moving[0]).distance(dealii::Point<2>(1, 1)) <= 2e-8,
                           tag + ": the mechanism is the rotation about (1,1)");
            double hinge = 1e300, corner = 1e300;
            for (unsigned int c = 0; c < pb.mesh.n_cells(); ++c)
              if (pb.mesh.cell(c).material_id == 1)
                for (const auto v : pb.mesh.cell(c).vertices)
                  {
                    const dealii::Tensor<1, 2> d({m.displacement[2 * v], m.displacement[2 * v + 1]});
                    if (pb.mesh.vertex(v).distance(dealii::Point<2>(1, 1)) < 1e-12)
                      hinge = d.norm();
                    if (pb.mesh.vertex(v).distance(dealii::Point<2>(0, 3)) < 1e-12)
                      corner = (d - dealii::Tensor<1, 2>({2 / std::sqrt(5.), 1 / std::sqrt(5.)})).norm();
                  }
            testing::check_small(hinge, 1e-12, tag + ": |motion| at the upper block's vertex (1,1)");
            testing::check_small(corner, 1e-12, tag + ": |motion - (2,1)/sqrt(5)| at its vertex (0,3)");
          }
        if (r.converged)
          {
            const auto   g    = pb.contact->gaps(x);
            double       umax = 0, lmax = 0, gmin = 0, lpos = 0;
            for (unsigned int i = 0; i < pb.n; ++i)
              umax = std::max(umax, std::abs(x[i]));
            for (unsigned int i = 0; i < pb.contact->n_pairs(); ++i)
              {
                lmax = std::max(lmax, std::abs(x[pb.n + i]));
                gmin = std::min(gmin, g[i]);
                lpos = std::max(lpos, x[pb.n + i]);
              }
            testing::check_small(gmin / umax, 1e-10, tag + ": largest penetration / max |u|");
            testing::check_small(lpos / lmax, 1e-10, tag + ": largest tensile normal multiplier / max |lambda|");
          }
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  same_solution();
  frictionless_sliding();
  pulled_off();
  tipping();
  energy_monotone();
  slope();
  return testing::finish();
}
