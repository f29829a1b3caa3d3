// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The cost of an assembly of many bodies against one body of the same
// size, in one process:
//   assembly  a wall of B blocks (courses of 10 blocks in running bond, half
//             blocks at the ends of every other course; each block 1 x 0.5
//             meshed on its own by n x n/2 quads, n
//             alternating between two values so no two neighbours match)
//             on a base, contact pairs found by ContactDetection, tied
//             interfaces (normal tied, or unilateral by the active set;
//             stick by multipliers, or by penalty), self weight; every block floats (held by
//             contact only);
//   one body  the base and the same wall as one body of about the same
//             number of DoFs (structured quads), the same load and support;
// both with k = 2 and the same solver (Solver/Type: CG-AMG on the stiffness
// condensed by the contact constraints, or direct). Prints DoFs, the wall
// time of each stage (mesh, contact detection, node insertion, assembly,
// solve), the end-to-end time, the active-set iterations and the ratio of
// the assembly to the one body, and the peak memory (VmHWM) per run; last,
// the unilateral assembly against the tied one (issue 39: at most 2x).
// Single runs of a fraction of a second scatter by up to 30 % on a VM, so
// the unilateral/tied ratio is also given as the median of `repeats` more
// alternating pairs (tied, unilateral) in the same process (0: none).
//   benchmark_assembly [blocks=100] [cells along a block=6] [solver=CG-AMG]
//                      [stick by=multipliers|penalty] [repeats=5]
#include <deal.II/base/function.h>
#include <deal.II/base/utilities.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/app/mesh_parameters.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/masonry_wall.h>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace dealvem;
using P = dealii::Point<2>;

namespace
{
  struct Run
  {
    unsigned int                  bodies = 0, dofs = 0, multipliers = 0, interfaces = 0, iterations = 0,
                                  linear_iterations = 0;
    double                        seconds = 0;
    std::map<std::string, double> timings;
    double                        memory_MB = 0;
  };

  Run
  solve(ContactProblem &problem, const std::string &solver, const bool tied, const bool penalty)
  {
    problem.boundary_conditions().add_dirichlet(2, {{true, true}},
                                                std::make_shared<dealii::Functions::ZeroFunction<2>>(2));
    problem.boundary_conditions().set_body_force(
      std::make_shared<dealii::Functions::ConstantFunction<2>>(std::vector<double>{0., -1.}));
    auto &o              = problem.options();
    o.degree             = 2;
    o.contact.tangential = penalty ? ContactSettings::Tangential::penalty : ContactSettings::Tangential::multipliers;
    o.contact.normal     = tied ? ContactSettings::Normal::tied : ContactSettings::Normal::unilateral;
    o.solver             = solver;
    o.solver_tolerance   = 1e-10;
    o.write_vtu = o.write_json = o.write_pictures = o.write_csv = false;
    const auto start = std::chrono::steady_clock::now();
    problem.run();
    Run r;
    r.seconds             = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto &res       = problem.get_results();
    r.bodies              = problem.n_bodies();
    r.dofs                = res.n_dofs;
    r.multipliers         = res.n_multipliers;
    r.interfaces          = res.interface_results.size();
    r.iterations          = res.active_set_iterations;
    r.linear_iterations   = res.linear_iterations;
    r.timings             = res.timings;
    r.memory_MB           = res.peak_memory_MB.empty() ? 0. : res.peak_memory_MB[0];
    return r;
  }

  PolygonalMesh<2>
  brick(const P &lo, const P &hi, const unsigned int nx, const unsigned int ny)
  {
    PolygonalMesh<2> m;
    PolygonalMeshGenerators::structured_quads(m, lo, hi, nx, ny);
    return m;
  }

  // the command-line argument @p i (1-based) as a count, @p fallback if absent
  unsigned int
  count_argument(const int argc, char **argv, const int i, const char *name, const unsigned int fallback)
  {
    if (argc <= i)
      return fallback;
    const std::string text   = argv[i];
    const bool        digits = !text.empty() && text.size() <= 9 &&
                        std::all_of(text.begin(), text.end(), [](const char c) { return c >= '0' && c <= '9'; });
    AssertThrow(digits, dealii::ExcMessage("benchmark_assembly: argument " + std::to_string(i) + " (" + name +
                                           ") must be a non-negative whole number, not '" + text + "'."));
    return static_cast<unsigned int>(std::stoul(text));
  }

  void
  print(const std::string &name, const Run &r)
  {
    std::cout << std::left << std::setw(10) << name << std::right << std::setw(7) << r.bodies << std::setw(9)
              << r.dofs << std::setw(8) << r.multipliers << std::setw(7) << r.interfaces << std::setw(5)
              << r.iterations;
    for (const char *stage : {"mesh", "contact detection", "node insertion", "assembly", "solve"})
      {
        const auto it = r.timings.find(stage);
        std::cout << std::setw(10) << std::fixed << std::setprecision(3) << (it == r.timings.end() ? 0. : it->second);
      }
    std::cout << std::setw(9) << std::setprecision(2) << r.seconds << std::setw(9) << std::setprecision(0)
              << r.memory_MB << std::defaultfloat << std::endl;
  }
} // namespace

namespace
{
  int
  run_benchmark(int argc, char **argv)
  {
    const unsigned int blocks = count_argument(argc, argv, 1, "blocks", 100);
    const unsigned int n      = count_argument(argc, argv, 2, "cells along a block", 6);
    const std::string  solver = (argc > 3 ? argv[3] : "CG-AMG");
    const std::string  stick  = (argc > 4 ? argv[4] : "multipliers");
    AssertThrow(stick == "multipliers" || stick == "penalty",
                dealii::ExcMessage("benchmark_assembly: the fourth argument (stick by) is 'multipliers' or 'penalty', "
                                   "not '" +
                                   stick + "'."));
    const unsigned int repeats    = count_argument(argc, argv, 5, "repeats", 5);
    const bool         penalty    = (stick == "penalty");
    const unsigned int per_course = 10;
    double             height     = 0;

    // the assembly: the base and the blocks as a mesh of parts (material id
    // = part), then add_parts(); courses of 10 blocks in running bond
    PolygonalMeshGenerators::MasonryWall layout;
    layout.blocks_per_course = per_course;
    layout.n_blocks          = blocks;
    layout.quads_along       = n;
    PolygonalMesh<2> wall;
    PolygonalMeshGenerators::masonry_wall(wall, layout);
    for (unsigned int v = 0; v < wall.n_vertices(); ++v)
      height = std::max(height, wall.vertex(v)[1]);

    std::cout << "Assembly of " << blocks << " blocks (" << n << " or " << n + 1
              << " quads along a block) on a base against one body of the same DoFs; k = 2, solver " << solver
              << ", stick by " << stick << ", one process" << std::endl;
    // a warm-up solve of the tied assembly, not reported: the first solve
    // of a process pays for the first touch of its memory and the set-up of
    // the libraries (measured: its assembly stage 0.10 s against 0.035 s
    // after), which would otherwise count against the tied model only
    const auto solve_wall = [&](const bool tied) {
      ContactProblem problem(MPI_COMM_SELF);
      problem.add_parts(wall, ElasticMaterial(1000, 0.2));
      problem.detect_contact_pairs();
      return solve(problem, solver, tied, penalty);
    };
    solve_wall(true);
    Run tied_assembly;
    for (const bool tied : {true, false})
      {
        std::cout << (tied ? "tied interfaces (one solve):"
                           : "unilateral contact, stick (active set: the bodies settle, head joints open):")
                  << std::endl;
        std::cout << "model      bodies     DoFs    mult  itfs  its      mesh    detect    insert  assembly     solve"
                     "    total  peak MB"
                  << std::endl;
        Run a = solve_wall(tied);
        print("assembly", a);
        // one body: the base and a wall-sized block on it (two bodies, one
        // interface) with about the assembly's DoFs
        Run b;
        {
          // k = 2 quads: about 8 DoFs per cell, so m x my cells with
          // 8 m my = DoFs of the assembly and cells about square
          const double       width = per_course;
          const unsigned int m = std::max(2u, static_cast<unsigned int>(std::sqrt(a.dofs / 8. * width / height) + 0.5));
          const unsigned int my   = std::max(1u, static_cast<unsigned int>(m * height / width + 0.5));
          PolygonalMesh<2>   both = brick(P(-1, -1), P(per_course + 1, 0), 4 * (per_course + 2), 4);
          PolygonalMesh<2>   body = brick(P(0, 0), P(width, height), m, my);
          for (unsigned int cell = 0; cell < body.n_cells(); ++cell)
            body.set_material_id(cell, 1);
          MeshParameters::shift_boundary_ids(body, 10);
          both.append(body);
          ContactProblem problem(MPI_COMM_SELF);
          problem.add_parts(both, ElasticMaterial(1000, 0.2));
          problem.detect_contact_pairs();
          b = solve(problem, solver, tied, penalty);
        }
        print("one body", b);
        std::cout << "ratio assembly / one body: DoFs " << std::setprecision(3) << double(a.dofs) / b.dofs
                  << ", assembly + solve "
                  << (a.timings["assembly"] + a.timings["solve"]) / (b.timings["assembly"] + b.timings["solve"])
                  << ", end to end " << a.seconds / b.seconds << ", peak memory " << a.memory_MB / b.memory_MB
                  << std::endl;
        if (tied)
          tied_assembly = a;
        else
          std::cout << "ratio unilateral / tied assembly: end to end " << a.seconds / tied_assembly.seconds
                    << ", solve " << a.timings["solve"] / tied_assembly.timings["solve"] << " (active-set iterations "
                    << a.iterations << " / " << tied_assembly.iterations << ", linear iterations "
                    << a.linear_iterations << " / " << tied_assembly.linear_iterations << ") [one pair]" << std::endl;
      }
    if (repeats > 0)
      {
        // alternating pairs; the medians of the end-to-end and solve times and
        // of the pairs' ratios
        std::vector<double> tied_total, unilateral_total, tied_solve, unilateral_solve, ratios;
        for (unsigned int r = 0; r < repeats; ++r)
          {
            Run t = solve_wall(true);
            Run u = solve_wall(false);
            tied_total.push_back(t.seconds);
            unilateral_total.push_back(u.seconds);
            tied_solve.push_back(t.timings["solve"]);
            unilateral_solve.push_back(u.timings["solve"]);
            ratios.push_back(u.seconds / t.seconds);
          }
        const auto median = [](std::vector<double> v) {
          std::sort(v.begin(), v.end());
          return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
        };
        std::cout << "ratio unilateral / tied assembly, medians of " << repeats << " alternating pairs: end to end "
                  << std::setprecision(3) << median(unilateral_total) / median(tied_total) << " ("
                  << median(unilateral_total) << " / " << median(tied_total) << " s; median of the pair ratios "
                  << median(ratios) << ", pairs";
        for (const double x : ratios)
          std::cout << " " << x;
        std::cout << "), solve " << median(unilateral_solve) / median(tied_solve) << std::endl;
      }
    return 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      return run_benchmark(argc, argv);
    }
  catch (const std::exception &e)
    {
      std::cerr << "benchmark_assembly: " << e.what() << std::endl;
      return 1;
    }
}
