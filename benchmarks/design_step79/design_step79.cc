// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Topology optimization of the MBB beam of deal.II's step-79, by dealvem's
// nested analysis (Design::ElasticDesignProblem, Design::TopologyOptimizer),
// on the same quadrilaterals as step-79 and on centroidal Voronoi meshes
// (issue 42). benchmarks/design_step79/run.sh runs step-79 itself next to
// it and prints the comparison.
//
// The problem, as step-79's: the domain [0, 6] x [0, 1]; a downward traction
// of 1 on the top boundary for 2.75 <= x <= 3.25 (total force 0.5); the
// vertex (0, 0) held in x and y, the vertex (6, 0) in y; lambda = mu = 1
// (E = 2.5, nu = 0.25, plane strain); volume fraction 0.5 (the start is the
// uniform density 0.5, as in step-79); SIMP with exponent 3; the linear
// ("cone") filter of radius 0.251 over cell centres, weights
// max(0, 1 - d/R) normalized per row, which on the 48 x 8 quads is exactly
// step-79's filter matrix (weights R - d for d < R, normalized); the
// objective, the compliance f^T u.
//
// What differs from step-79 (see doc/benchmarks.md):
//  - nested analysis: every iteration solves the state for the current
//    densities and takes the compliance's gradient (self-adjoint); the
//    design is updated by NLopt's MMA or by optimality criteria (OC, move
//    0.2), stopping when no design variable moves by more than 0.01 (or
//    after --max-iterations evaluations). step-79 is SAND: density,
//    displacement and their multipliers are unknowns of one KKT system
//    solved by a log-barrier interior-point Newton method;
//  - the stiffness factor is s(rho) = s_min + rho^3 (1 - s_min) with
//    s_min = 1e-4 by default (--minimum): the nested analysis needs a
//    positive definite stiffness. step-79 uses rho^3 with no minimum (its
//    KKT system stays regular through the barrier's bounds on the
//    unfiltered densities);
//  - volume constraint: <= 0.5 here, = 0.5 in step-79 (its Newton steps
//    keep the sum of the densities).
//
// The meshes and the load segment: the 48 x 8 quads have vertices at
// x = 2.75 and 3.25 on the top. The Voronoi meshes (30 Lloyd iterations,
// seed 1) have the four corners as vertices but in general no vertex at the
// segment's ends: the top edge containing x = 2.75 (and 3.25) is split
// there (PolygonalMesh::split_edge; the cell gains a vertex on a straight
// side), unless an end of that edge is closer than 10 % of its length, in
// which case that vertex is moved to the point instead (no tiny edges).
// So the loaded segment is exactly [2.75, 3.25] on every mesh and the total
// force 0.5; the program prints the loaded length of every run (the force
// is the traction 1 times it; design_step79.csv has both).
//
// Runs (one row each): quads 48 x 8 with k = 1 (882 DoFs, as step-79's Q1)
// and k = 2, Voronoi 384 and 1536 cells with k = 1 and k = 2, each with MMA
// and OC. Columns: mesh, cells, DoFs, optimizer, iterations (evaluations of
// the state, the linear solves of the nested analysis), final compliance,
// volume fraction, grey fraction (share of cells with density in
// (0.1, 0.9)), whether the tolerance was reached, setup time (mesh, DoFs,
// problem setup), optimizer wall time, time per iteration.
//
// Output (working directory): the Markdown table on stdout,
// design_step79.csv (the same rows), and SVG pictures of the final
// densities (black = 1, white = 0): design-mbb-quads-48x8-k1-mma.svg and
// design-mbb-voronoi-<n>-k1-mma.svg for every Voronoi mesh
// (Design::write_density_svg).
//
// Options:
//   --quick                  only the quads and Voronoi 384
//   --voronoi n1,n2,...      Voronoi cell counts (default 384,1536)
//   --degrees k1,k2          (default 1,2)
//   --max-iterations N       (default 500)
//   --minimum s_min          SIMP's minimum stiffness factor (default 1e-4)
//   --tolerance t            the largest design change to stop at (default 0.01)
//   --only-quads             the quads only (k = 1 and 2)
//   --history                print every iteration
//   --evaluate FILE          instead of optimizing: read step-79's final
//                            filtered densities (lines "x y rho", the cell
//                            centres; the patched step-79 of run.sh writes
//                            step79_densities.txt) and print the compliance
//                            of that design by dealvem on the same 48 x 8
//                            quads, k = 1 and 2, with s(rho) = rho^3 (and
//                            s_min = 1e-9): the difference of the
//                            discretizations (VEM against Q1) on one design,
//                            apart from the optimizers; and draw it
//                            (design-mbb-step79-quads-48x8.svg)
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dealvem/design/density_filter.h>
#include <dealvem/design/design_output.h>
#include <dealvem/design/design_problem.h>
#include <dealvem/design/topology_optimizer.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/polygonal_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace dealvem;

namespace
{
  constexpr double       length = 6, height = 1;
  constexpr double       x_load_0 = 2.75, x_load_1 = 3.25;
  constexpr double       traction = 1;
  constexpr unsigned int load_id = 4; // the generators use 0 to 3

  bool
  on_top(const dealii::Point<2> &p)
  {
    return std::abs(p[1] - height) < 1e-10;
  }

  // Make x (on the top side) a vertex of the mesh; returns what was done.
  std::string
  top_vertex_at(PolygonalMesh<2> &mesh, const double x)
  {
    const dealii::Point<2> target(x, height);
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      if (mesh.vertex(v).distance(target) < 1e-10)
        return "vertex";
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      {
        const auto &edge = mesh.edge(e);
        if (!edge.at_boundary())
          continue;
        const unsigned int     va = edge.vertices[0], vb = edge.vertices[1];
        const dealii::Point<2> a = mesh.vertex(va), b = mesh.vertex(vb);
        if (!on_top(a) || !on_top(b))
          continue;
        if (x <= std::min(a[0], b[0]) || x >= std::max(a[0], b[0]))
          continue;
        const double len = a.distance(b);
        const double da = std::abs(a[0] - x), db = std::abs(b[0] - x);
        if (std::min(da, db) < 0.1 * len)
          {
            // move the nearer end, unless that shortens its other top edge
            // by more than half
            const unsigned int v    = (da < db ? va : vb);
            const double       move = std::min(da, db);
            double             other = 1e300;
            for (unsigned int f = 0; f < mesh.n_edges(); ++f)
              {
                const auto &g = mesh.edge(f);
                if (f == e || !g.at_boundary() || (g.vertices[0] != v && g.vertices[1] != v))
                  continue;
                other = std::min(other, mesh.vertex(g.vertices[0]).distance(mesh.vertex(g.vertices[1])));
              }
            if (move < 0.5 * other && !(std::abs(mesh.vertex(v)[0]) < 1e-10 || std::abs(mesh.vertex(v)[0] - length) < 1e-10))
              {
                mesh.move_vertex(v, target);
                mesh.validate();
                std::ostringstream s;
                s << "moved by " << std::setprecision(2) << move;
                return s.str();
              }
          }
        mesh.split_edge(e, target);
        std::ostringstream s;
        s << "split (" << std::setprecision(3) << std::fixed << da << " + " << db << ")";
        return s.str();
      }
    throw std::runtime_error("no top edge contains x = " + std::to_string(x));
  }

  // Boundary id load_id on the top edges within [x_load_0, x_load_1];
  // returns their total length.
  double
  mark_load(PolygonalMesh<2> &mesh)
  {
    double loaded = 0;
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      {
        const auto &edge = mesh.edge(e);
        if (!edge.at_boundary())
          continue;
        const auto a = mesh.vertex(edge.vertices[0]), b = mesh.vertex(edge.vertices[1]);
        const auto c = 0.5 * (a + b);
        if (on_top(a) && on_top(b) && c[0] > x_load_0 && c[0] < x_load_1)
          {
            mesh.set_edge_boundary_id(e, load_id);
            loaded += a.distance(b);
          }
      }
    return loaded;
  }

  struct Run
  {
    std::string  mesh_name;
    unsigned int cells = 0, dofs = 0, degree = 1;
    std::string  optimizer;
    unsigned int iterations = 0;
    double       compliance = 0, volume = 0, grey = 0, min_density = 0;
    bool         converged = false;
    double       setup_time = 0, time = 0, analysis_time = 0;
    double       loaded_length = 0, force = 0;
    std::string  load_note;
  };

  // The quads and the problem of step-79 (k = degree).
  void
  make_quads(PolygonalMesh<2> &mesh)
  {
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(length, height), 48, 8);
  }

  void
  add_loads_and_supports(Design::ElasticDesignProblem &problem)
  {
    problem.add_point_support(dealii::Point<2>(0, 0), 0);
    problem.add_point_support(dealii::Point<2>(0, 0), 1);
    problem.add_point_support(dealii::Point<2>(length, 0), 1);
    problem.add_traction(load_id, dealii::Tensor<1, 2>({0., -traction}));
  }

  // --evaluate: the compliance of step-79's final design on our quads
  void
  evaluate_step79_design(const std::string &filename, const MaterialLibrary<2> &laws,
                         const std::vector<unsigned int> &degrees)
  {
    std::ifstream                 in(filename);
    std::vector<dealii::Point<2>> centres;
    std::vector<double>           values;
    double                        x, y, rho;
    while (in >> x >> y >> rho)
      {
        centres.emplace_back(x, y);
        values.push_back(rho);
      }
    if (centres.empty())
      throw std::runtime_error("no densities in " + filename);
    PolygonalMesh<2> mesh;
    make_quads(mesh);
    mark_load(mesh);
    std::vector<unsigned int> all(mesh.n_cells());
    for (unsigned int c = 0; c < all.size(); ++c)
      all[c] = c;
    const auto centroids = Design::cell_centroids(mesh, all);
    const auto areas     = Design::cell_areas(mesh, all);
    std::vector<double> density(mesh.n_cells(), -1);
    double              volume = 0, area = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        for (unsigned int j = 0; j < centres.size(); ++j)
          if (centres[j].distance(centroids[c]) < 1e-8)
            density[c] = values[j];
        if (density[c] < 0)
          throw std::runtime_error("no density for the cell at " + std::to_string(centroids[c][0]) + ", " +
                                   std::to_string(centroids[c][1]) + " in " + filename);
        volume += areas[c] * density[c];
        area += areas[c];
      }
    Design::MaterialInterpolation simp;
    simp.penalty = 3;
    simp.minimum = 1e-9;
    std::vector<double> factors(mesh.n_cells());
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      factors[c] = simp.factor(std::clamp(density[c], 0., 1.));
    std::cout << "# step-79's final design (" << filename << ", volume fraction " << volume / area
              << ") evaluated by dealvem on the 48 x 8 quads, s(rho) = 1e-9 + rho^3 (1 - 1e-9)\n\n"
              << "| k | DoFs | compliance |\n|---:|---:|---:|\n";
    {
      std::ostringstream title;
      title << "deal.II step-79 (SAND, Q1), quads 48x8: filtered densities, volume " << std::fixed
            << std::setprecision(3) << volume / area;
      Design::write_density_svg("design-mbb-step79-quads-48x8.svg", mesh, density, title.str());
    }
    std::ofstream csv("design_step79_eval.csv");
    csv << "k,dofs,compliance,volume\n";
    for (const unsigned int k : degrees)
      {
        Design::ElasticDesignProblem problem(mesh, laws, k);
        add_loads_and_supports(problem);
        problem.setup();
        std::vector<double> gradient;
        const double        J = problem.evaluate(factors, gradient);
        std::cout << "| " << k << " | " << problem.get_dof_handler().n_dofs() << " | " << std::setprecision(8) << J
                  << " |\n";
        csv << k << ',' << problem.get_dof_handler().n_dofs() << ',' << std::setprecision(12) << J << ','
            << volume / area << '\n';
      }
  }

  std::vector<unsigned int>
  parse_list(const std::string &s)
  {
    std::vector<unsigned int> v;
    std::stringstream         in(s);
    std::string               item;
    while (std::getline(in, item, ','))
      if (!item.empty())
        v.push_back(std::stoul(item));
    return v;
  }
} // namespace

int
main(int argc, char **argv)
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

      std::vector<unsigned int> voronoi_cells = {384, 1536}, degrees = {1, 2};
      unsigned int              max_iterations = 500;
      double                    minimum = 1e-4, tolerance = 1e-2;
      bool                      history = false;
      std::string               evaluate_file;
      for (int i = 1; i < argc; ++i)
        {
          const std::string a = argv[i];
          auto              next = [&]() -> std::string {
            if (i + 1 >= argc)
              throw std::runtime_error(a + " needs a value");
            return argv[++i];
          };
          if (a == "--quick")
            voronoi_cells = {384};
          else if (a == "--only-quads")
            voronoi_cells.clear();
          else if (a == "--voronoi")
            voronoi_cells = parse_list(next());
          else if (a == "--degrees")
            degrees = parse_list(next());
          else if (a == "--max-iterations")
            max_iterations = std::stoul(next());
          else if (a == "--minimum")
            minimum = std::stod(next());
          else if (a == "--tolerance")
            tolerance = std::stod(next());
          else if (a == "--history")
            history = true;
          else if (a == "--evaluate")
            evaluate_file = next();
          else
            throw std::runtime_error("unknown option " + a + " (see the header of design_step79.cc)");
        }

      const ElasticMaterial material(2.5, 0.25); // plane strain
      MaterialLibrary<2>    laws;
      laws.add(0, material);
      if (!evaluate_file.empty())
        {
          evaluate_step79_design(evaluate_file, laws, degrees);
          return 0;
        }
      std::cout << "# MBB beam of step-79: [0, 6] x [0, 1], traction " << traction << " down on x in [" << x_load_0
                << ", " << x_load_1 << "], lambda = " << material.lambda() << ", mu = " << material.mu()
                << " (E = 2.5, nu = 0.25, plane strain), volume fraction 0.5, SIMP p = 3, s_min = " << minimum
                << ", filter radius 0.251, tolerance " << tolerance << ", at most " << max_iterations << " evaluations\n\n";

      std::vector<Run> runs;
      struct MeshCase
      {
        std::string  name;
        unsigned int n; // 0: the quads
      };
      std::vector<MeshCase> meshes = {{"quads 48x8", 0}};
      for (const unsigned int n : voronoi_cells)
        meshes.push_back({"Voronoi " + std::to_string(n), n});

      for (const auto &mc : meshes)
        for (const unsigned int k : degrees)
          for (const std::string opt : {"MMA", "OC"})
            {
              Run        run;
              const auto t0 = std::chrono::steady_clock::now();
              PolygonalMesh<2> mesh;
              if (mc.n == 0)
                make_quads(mesh);
              else
                PolygonalMeshGenerators::voronoi(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(length, height), mc.n,
                                                 30, 1);
              run.load_note = "x = 2.75: " + top_vertex_at(mesh, x_load_0);
              run.load_note += "; x = 3.25: " + top_vertex_at(mesh, x_load_1);
              run.loaded_length = mark_load(mesh);

              Design::ElasticDesignProblem problem(mesh, laws, k);
              add_loads_and_supports(problem);
              problem.setup();
              run.setup_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
              run.force      = traction * run.loaded_length;

              Design::TopologyOptimizer::Settings s;
              s.volume_fraction       = 0.5;
              s.filter_radius         = 0.251;
              s.interpolation.penalty = 3;
              s.interpolation.minimum = minimum;
              s.optimizer             = Design::parse_optimizer(opt);
              s.max_iterations        = max_iterations;
              s.tolerance             = tolerance;
              Design::TopologyOptimizer optimizer(s);
              if (history)
                optimizer.set_callback(
                  [](unsigned int i, const Design::TopologyOptimizer::Iteration &it, const std::vector<double> &) {
                    std::cout << "  " << i << " J " << it.objective << " V " << it.volume << " change " << it.change
                              << " grey " << it.grey << '\n';
                  });
              const auto r = optimizer.run(problem);

              run.mesh_name  = mc.name;
              run.cells      = problem.get_mesh().n_cells();
              run.dofs       = problem.get_dof_handler().n_dofs();
              run.degree     = k;
              run.optimizer  = opt;
              run.iterations = r.history.size();
              run.compliance = r.objective;
              run.volume     = r.volume;
              run.converged  = r.converged;
              run.time       = r.time;
              run.analysis_time = r.analysis_time;
              unsigned int n_grey = 0;
              run.min_density     = 1;
              for (const double rho : r.densities)
                {
                  n_grey += (rho > 0.1 && rho < 0.9);
                  run.min_density = std::min(run.min_density, rho);
                }
              run.grey = double(n_grey) / r.densities.size();
              // the compliance from the state, as a check of the objective
              const double fu = problem.last_state().compliance;
              if (std::abs(fu - run.compliance) > 1e-8 * std::abs(fu))
                std::cout << "  note: last state's compliance " << fu << " differs from the objective "
                          << run.compliance << '\n';
              std::cout << "  " << mc.name << ", k = " << k << ", " << opt << ": " << run.cells << " cells, "
                        << run.dofs << " DoFs, loaded length " << run.loaded_length << " (" << run.load_note
                        << "), " << run.iterations << " evaluations, J = " << std::setprecision(6) << run.compliance
                        << ", " << r.stop_reason << ", " << std::setprecision(3) << run.time << " s" << std::endl;

              if (k == 1 && opt == "MMA")
                {
                  std::string tag = (mc.n == 0 ? "quads-48x8" : "voronoi-" + std::to_string(mc.n));
                  std::ostringstream title;
                  title << "dealvem, " << mc.name << ", k = 1, MMA: compliance " << std::fixed << std::setprecision(3)
                        << run.compliance << ", volume " << run.volume << ", " << run.iterations << " iterations";
                  Design::write_density_svg("design-mbb-" + tag + "-k1-mma.svg", problem.get_mesh(), r.densities, title.str());
                }
              runs.push_back(run);
            }

      std::cout << "\n| mesh | cells | k | DoFs | optimizer | iterations | compliance | volume | grey | converged | "
                   "setup (s) | optimizer (s) | per iteration (ms) |\n"
                << "|---|---:|---:|---:|---|---:|---:|---:|---:|---|---:|---:|---:|\n";
      std::ofstream csv("design_step79.csv");
      csv << "mesh,cells,k,dofs,optimizer,iterations,compliance,volume,grey,min_density,converged,setup_time,time,"
             "analysis_time,loaded_length,force\n";
      for (const auto &r : runs)
        {
          std::cout << "| " << r.mesh_name << " | " << r.cells << " | " << r.degree << " | " << r.dofs << " | "
                    << r.optimizer << " | " << r.iterations << " | " << std::fixed << std::setprecision(3)
                    << r.compliance << " | " << std::setprecision(4) << r.volume << " | " << std::setprecision(3)
                    << r.grey << " | " << (r.converged ? "yes" : "no") << " | " << std::setprecision(2)
                    << r.setup_time << " | " << std::setprecision(2) << r.time << " | " << std::setprecision(2)
                    << 1e3 * r.time / std::max(1u, r.iterations) << " |\n";
          std::cout.unsetf(std::ios::floatfield);
          csv << std::setprecision(10) << r.mesh_name << ',' << r.cells << ',' << r.degree << ',' << r.dofs << ','
              << r.optimizer << ',' << r.iterations << ',' << r.compliance << ',' << r.volume << ',' << r.grey << ','
              << r.min_density << ',' << (r.converged ? 1 : 0) << ',' << r.setup_time << ',' << r.time << ','
              << r.analysis_time << ',' << r.loaded_length << ',' << r.force << '\n';
        }
      std::cout << std::flush;
    }
  catch (const std::exception &e)
    {
      std::cerr << "design_step79: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
