// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// The cost of a design iteration (issue 42, item 5).
//
//   benchmark_design_scale contact [n_cells]        (default 3200)
//   benchmark_design_scale mbb n_cells [iterations] [solver] [tolerance]
//   benchmark_design_scale contrast n_cells [solver]
//   benchmark_design_scale mbb-multilevel n_cells [fine iterations] [solver]
//
// contact: the bracket of examples/step-13 (a 2 x 1 design domain of
// n_cells Voronoi cells, clamped at its left, standing on a solid block,
// pulled up near x = 1.5), k = 1, resting (unilateral, stick where closed)
// and bonded (tied). Prints the time of one contact solve of the uniform
// design from the initial gaps (the analysis a user runs once), then the
// optimization's mean time per design iteration split into assembly, state
// (the active-set iterations, warm-started from the last design's set),
// adjoint and sensitivities, and the ratio iteration / one contact solve.
//
// mbb: the MBB beam of step-79 on n_cells Voronoi cells (k = 1, the filter
// radius scaled with the cell size: 2 cells), MMA for at most `iterations`
// iterations (default 100), solver "CG-AMG" (default) or "direct
// constraints", iterative solves to the relative `tolerance` (default
// 1e-8). Prints the mesh and setup times, the time per iteration and its
// parts, and the peak memory (VmHWM).
//
// contrast: one solve (from zero) of a black-and-white design of n_cells
// cells (the MBB design of n_cells / 16 cells carried over): the CG
// iterations that the late design iterations meet.
//
// mbb-multilevel: the same beam in two levels: designed on n_cells / 16
// cells first (to the change tolerance), the densities carried to the
// n_cells mesh (Design::transfer_densities), then at most `iterations`
// (default 60) MMA iterations there from that start. Prints both levels
// and the whole time.
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dealvem/design/design_problem.h>
#include <dealvem/design/topology_optimizer.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/mesh/generators.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

using namespace dealvem;
using Point  = dealii::Point<2>;
using Vector = dealii::Tensor<1, 2>;

namespace
{
  // the relative tolerance of the iterative solves (mbb's fifth argument)
  double solve_tolerance = 1e-8;

  double
  peak_memory_mb()
  {
    std::ifstream f("/proc/self/status");
    std::string   line;
    while (std::getline(f, line))
      if (line.rfind("VmHWM:", 0) == 0)
        return std::stod(line.substr(6)) / 1024.;
    return 0;
  }

  double
  since(const std::chrono::steady_clock::time_point t)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  // the top edges whose midpoints lie in [x0, x1] get the id; their length
  double
  mark_top(PolygonalMesh<2> &mesh, const double y, const double x0, const double x1, const unsigned int id)
  {
    double length = 0;
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      {
        const auto &edge = mesh.edge(e);
        if (!edge.at_boundary())
          continue;
        const Point a = mesh.vertex(edge.vertices[0]), b = mesh.vertex(edge.vertices[1]);
        const Point m = 0.5 * (a + b);
        if (std::abs(a[1] - y) < 1e-12 && std::abs(b[1] - y) < 1e-12 && m[0] >= x0 && m[0] <= x1)
          {
            mesh.set_edge_boundary_id(e, id);
            length += a.distance(b);
          }
      }
    return length;
  }

  // mean times of the iterations' parts
  struct Means
  {
    unsigned int n = 0;
    double       assembly = 0, state = 0, adjoint = 0, sensitivities = 0, iteration = 0;
    unsigned int active_set = 0, linear = 0;
    void
    add(const Design::ElasticDesignProblem::State &s)
    {
      ++n;
      linear += s.linear_iterations;
      assembly += s.time_assembly;
      state += s.time_state;
      adjoint += s.time_adjoint;
      sensitivities += s.time_sensitivities;
      active_set += s.n_contact_iterations;
    }
  };

  void
  contact(const unsigned int n_cells)
  {
    for (const auto normal : {ContactSettings::Normal::unilateral, ContactSettings::Normal::tied})
      {
        PolygonalMesh<2> mesh, part;
        PolygonalMeshGenerators::structured_quads(mesh, Point(0, -0.25), Point(2, 0), 16, 2);
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          mesh.set_material_id(c, 1);
        PolygonalMeshGenerators::voronoi(part, Point(0, 0), Point(2, 1), n_cells, 30, 3);
        for (unsigned int e = 0; e < part.n_edges(); ++e)
          if (part.edge(e).at_boundary())
            part.set_edge_boundary_id(e, part.edge(e).boundary_id + 10);
        const double length = mark_top(part, 1., 1.45, 1.55, 20);
        mesh.append(part);
        MaterialLibrary<2> laws;
        laws.add(0, ElasticMaterial(1., 0.3));
        laws.add(1, ElasticMaterial(1., 0.3));
        auto make = [&]() {
          auto p = std::make_unique<Design::ElasticDesignProblem>(mesh, laws, 1);
          p->contact_settings().normal     = normal;
          p->contact_settings().tangential = ContactSettings::Tangential::multipliers;
          p->add_contact_interface(3, 12);
          p->add_support(2);
          p->add_support(10);
          p->add_traction(20, Vector({0., 1. / length}));
          p->setup();
          return p;
        };
        // one contact solve of the uniform (solid) design, cold
        auto                problem = make();
        std::vector<double> s(problem->get_mesh().n_cells(), 1.), g;
        auto                start = std::chrono::steady_clock::now();
        problem->evaluate(s, g);
        const double one_solve = problem->last_state().time_state;
        const double one_total = since(start);
        const unsigned int one_iterations = problem->last_state().n_contact_iterations;

        auto                                optimized = make();
        Design::TopologyOptimizer::Settings settings;
        settings.volume_fraction       = 0.3;
        settings.filter_radius         = 0.12 * std::sqrt(800. / n_cells);
        settings.interpolation.minimum = 1e-4;
        settings.solid_ids             = {1};
        settings.max_iterations        = 200;
        Design::TopologyOptimizer optimizer(settings);
        Means                     means;
        optimizer.set_callback([&](unsigned int, const Design::TopologyOptimizer::Iteration &,
                                   const std::vector<double> &) { means.add(optimized->last_state()); });
        const auto r = optimizer.run(*optimized);
        const double per_iteration = r.time / r.history.size();
        std::cout << std::setprecision(4) << "bracket, "
                  << (normal == ContactSettings::Normal::tied ? "bonded" : "resting") << ", " << n_cells
                  << " cells, " << optimized->get_dof_handler().n_dofs() << " DoFs, " << optimized->n_pairs()
                  << " pairs\n  one contact solve of the solid design: " << one_solve << " s (" << one_iterations
                  << " active-set iterations; with assembly and sensitivities " << one_total << " s)\n  design: "
                  << r.history.size() << " iterations, " << r.time << " s, per iteration " << per_iteration
                  << " s = " << per_iteration / one_solve << " x one contact solve\n  per iteration: assembly "
                  << means.assembly / means.n << ", state " << means.state / means.n << " ("
                  << double(means.active_set) / means.n << " active-set iterations), adjoint "
                  << means.adjoint / means.n << ", sensitivities " << means.sensitivities / means.n
                  << ", optimizer and filter " << (r.time - r.analysis_time) / r.history.size() << " s\n";
      }
    std::cout << "peak memory " << peak_memory_mb() << " MB" << std::endl;
  }

  // The MBB beam of step-79 on n_cells Voronoi cells: its problem (set up)
  std::unique_ptr<Design::ElasticDesignProblem>
  mbb_problem(const unsigned int n_cells, const std::string &solver, double &t_mesh, double &t_setup)
  {
    auto             start = std::chrono::steady_clock::now();
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::voronoi(mesh, Point(0, 0), Point(6, 1), n_cells, 10, 1);
    const double length = mark_top(mesh, 1., 2.75, 3.25, 4);
    t_mesh              = since(start);
    start               = std::chrono::steady_clock::now();
    MaterialLibrary<2> laws;
    laws.add(0, ElasticMaterial(2.5, 0.25));
    auto problem = std::make_unique<Design::ElasticDesignProblem>(mesh, laws, 1);
    problem->solver_settings().type               = SaddlePointSolver::parse_type(solver);
    problem->solver_settings().relative_tolerance = solve_tolerance;
    problem->add_point_support(Point(0, 0), 0);
    problem->add_point_support(Point(0, 0), 1);
    problem->add_point_support(Point(6, 0), 1);
    problem->add_traction(4, Vector({0., -0.5 / length}));
    problem->setup();
    t_setup = since(start);
    return problem;
  }

  // MMA on the MBB problem from @p initial (empty: uniform); prints the
  // summary line
  Design::TopologyOptimizer::Result
  mbb_run(Design::ElasticDesignProblem &problem, const unsigned int n_cells, const unsigned int iterations,
          const std::vector<double> &initial, const double move, const std::string &label)
  {
    Design::TopologyOptimizer::Settings settings;
    settings.volume_fraction       = 0.5;
    settings.filter_radius         = 2 * std::sqrt(6. / n_cells);
    settings.interpolation.minimum = 1e-4;
    settings.max_iterations        = iterations;
    settings.move                  = move;
    Design::TopologyOptimizer optimizer(settings);
    Means                     means;
    optimizer.set_callback([&](unsigned int it, const Design::TopologyOptimizer::Iteration &record,
                               const std::vector<double> &) {
      means.add(problem.last_state());
      if (it % 10 == 1)
        std::cout << "  iteration " << it << ": compliance " << record.objective << ", change " << record.change
                  << ", solve " << problem.last_state().time_state << " s, "
                  << problem.last_state().linear_iterations << " CG iterations" << std::endl;
    });
    const auto r = initial.empty() ? optimizer.run(problem) : optimizer.run(problem, initial);
    std::cout << std::setprecision(5) << label << ", " << n_cells << " Voronoi cells, "
              << problem.get_dof_handler().n_dofs() << " DoFs: " << r.history.size() << " iterations ("
              << r.stop_reason << "), compliance " << r.objective << ", volume " << r.volume << ", " << r.time
              << " s, per iteration " << r.time / r.history.size() << " s: assembly " << means.assembly / means.n
              << ", solve " << means.state / means.n << " (" << double(means.linear) / means.n
              << " CG iterations), sensitivities " << means.sensitivities / means.n << ", optimizer and filter "
              << (r.time - r.analysis_time) / r.history.size() << std::endl;
    return r;
  }

  void
  mbb(const unsigned int n_cells, const unsigned int iterations, const std::string &solver)
  {
    double     t_mesh = 0, t_setup = 0;
    auto       problem = mbb_problem(n_cells, solver, t_mesh, t_setup);
    std::cout << "MBB, " << solver << "\n  mesh " << t_mesh << " s, setup " << t_setup << " s" << std::endl;
    mbb_run(*problem, n_cells, iterations, {}, 0.2, "MBB");
    std::cout << "  peak memory " << peak_memory_mb() << " MB" << std::endl;
  }

  // Two levels: the design of n_cells / 16 cells (to the change tolerance,
  // at most 300 iterations), its densities carried to the n_cells mesh
  // (transfer_densities over one coarse cell size), then at most
  // `iterations` there, starting with a smaller step (0.05).
  void
  mbb_multilevel(const unsigned int n_cells, const unsigned int iterations, const std::string &solver)
  {
    const auto         start  = std::chrono::steady_clock::now();
    const unsigned int coarse = n_cells / 16;
    double             t_mesh = 0, t_setup = 0;
    auto               coarse_problem = mbb_problem(coarse, solver, t_mesh, t_setup);
    std::cout << "MBB multilevel, " << solver << "\n  coarse mesh " << t_mesh << " s, setup " << t_setup << " s"
              << std::endl;
    const auto r_coarse = mbb_run(*coarse_problem, coarse, 300, {}, 0.2, "  coarse level");
    auto       problem  = mbb_problem(n_cells, solver, t_mesh, t_setup);
    std::cout << "  fine mesh " << t_mesh << " s, setup " << t_setup << " s" << std::endl;
    const auto t0      = std::chrono::steady_clock::now();
    const auto initial = Design::transfer_densities(coarse_problem->get_mesh(), r_coarse.densities,
                                                    problem->get_mesh(), std::sqrt(6. / coarse));
    std::cout << "  transfer " << since(t0) << " s" << std::endl;
    coarse_problem.reset();
    mbb_run(*problem, n_cells, iterations, initial, 0.05, "  fine level");
    std::cout << "  whole run " << since(start) << " s, peak memory " << peak_memory_mb() << " MB" << std::endl;
  }

  // One solve of a black-and-white design on n_cells cells: the MBB design
  // of n_cells / 16 cells (to the change tolerance) carried to the fine
  // mesh, its SIMP factors (p = 3, minimum 1e-4). Prints the CG iterations
  // and the solve time: the contrast that the design iterations meet
  // late in a run, without the run.
  void
  contrast(const unsigned int n_cells, const std::string &solver)
  {
    const unsigned int coarse = n_cells / 16;
    double             t_mesh = 0, t_setup = 0;
    auto               coarse_problem = mbb_problem(coarse, solver, t_mesh, t_setup);
    const auto         r_coarse = mbb_run(*coarse_problem, coarse, 300, {}, 0.2, "  coarse level");
    auto               problem  = mbb_problem(n_cells, solver, t_mesh, t_setup);
    const auto         rho      = Design::transfer_densities(coarse_problem->get_mesh(), r_coarse.densities,
                                                             problem->get_mesh(), std::sqrt(6. / coarse));
    std::vector<double> factors(rho.size());
    for (unsigned int c = 0; c < rho.size(); ++c)
      factors[c] = 1e-4 + (1 - 1e-4) * rho[c] * rho[c] * rho[c];
    std::vector<double> g;
    const double        J = problem->evaluate(factors, g);
    std::cout << "  black and white design: compliance " << J << ", solve " << problem->last_state().time_state
              << " s, " << problem->last_state().linear_iterations << " CG iterations" << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        mode = argc > 1 ? argv[1] : "";
  if (mode == "contact")
    contact(argc > 2 ? std::stoi(argv[2]) : 3200);
  else if (mode == "mbb" && argc > 2)
    {
      if (argc > 5)
        solve_tolerance = std::stod(argv[5]);
      mbb(std::stoi(argv[2]), argc > 3 ? std::stoi(argv[3]) : 100, argc > 4 ? argv[4] : "CG-AMG");
    }
  else if (mode == "contrast" && argc > 2)
    contrast(std::stoi(argv[2]), argc > 3 ? argv[3] : "CG-AMG");
  else if (mode == "mbb-multilevel" && argc > 2)
    mbb_multilevel(std::stoi(argv[2]), argc > 3 ? std::stoi(argv[3]) : 60, argc > 4 ? argv[4] : "CG-AMG");
  else
    {
      std::cerr << "usage: benchmark_design_scale contact [n_cells] | mbb n_cells [iterations] [solver] "
                   "[tolerance] | contrast n_cells [solver] | mbb-multilevel n_cells [fine iterations] [solver]"
                << std::endl;
      return 2;
    }
  return 0;
}
