// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// step-4: Coulomb friction and partial slip -- the Cattaneo-Mindlin problem.
//
// Build (from a dealvem build directory):   make step-4
// Run:                                      ./examples/step-4 [--quick | --study] [--write-doc-picture]
// What it does: an elastic half cylinder (R = 50 mm) is pressed onto a block
// of the same material (E = 70 GPa, nu = 0.3, plane strain) by a resultant
// P = 35 kN/mm, then sheared by a tangential resultant Q that rises to
// 0.75 mu P (mu = 0.3) in load steps, with Coulomb friction on the
// independently meshed contact surfaces. With identical materials the normal
// and the tangential problems decouple, and Cattaneo's and Mindlin's solution
// gives a central stick zone |x| <= c, c/a = sqrt(1 - Q/(mu P)), surrounded
// by slip zones. The program compares the stick zone and the shear traction
// with that solution at Q/(mu P) = 0.25, 0.5, 0.75 and exits with an error if
// they miss the accuracy stated below. --quick: the coarse level, k = 1 (run
// by ctest); default: two mesh levels, k = 1; --study: two mesh levels,
// k = 1 and 2.

// @sect3{Include files}
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/mesh_io.h>
#include <dealvem/postprocessing/svg_plots.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace Step4
{
  using namespace dealvem;

  // @sect3{The data and the analytical solution}
  //
  // Hertz's solution for the normal load (step-3) with the effective
  // modulus $E^* = E/(2(1-\nu^2))$ of two bodies of one material, and the
  // Cattaneo-Mindlin shear traction for the tangential load $Q \le \mu P$:
  // @f[ q(x) = \mu p_0\left[\sqrt{1 - x^2/a^2} - \frac{c}{a}\sqrt{1 - x^2/c^2}\right],
  //     \ |x| \le c, \qquad q(x) = \mu p(x),\ c < |x| \le a, @f]
  // with $c/a = \sqrt{1 - Q/(\mu P)}$.
  namespace CM
  {
    constexpr double R       = 200.;
    constexpr double E       = 70000.;
    constexpr double nu      = 0.3;
    constexpr double P       = 8750.;
    constexpr double mu      = 0.3;
    constexpr double x_strip = 10.; // fine mesh on |x| <= x_strip

    double
    E_star()
    {
      return E / (2. * (1. - nu * nu));
    }
    double
    a()
    {
      return std::sqrt(4. * P * R / (M_PI * E_star()));
    }
    double
    p0()
    {
      return 2. * P / (M_PI * a());
    }
    double
    pressure(const double x)
    {
      return (std::abs(x) < a() ? p0() * std::sqrt(1. - x * x / (a() * a())) : 0.);
    }
    // the stick zone half-width at the load ratio q = Q/(mu P)
    double
    c(const double q)
    {
      return a() * std::sqrt(1. - q);
    }
    double
    shear(const double x, const double q)
    {
      const double cc = c(q);
      if (std::abs(x) >= a())
        return 0.;
      if (std::abs(x) >= cc)
        return mu * pressure(x);
      return mu * p0() * (std::sqrt(1. - x * x / (a() * a())) - (cc / a()) * std::sqrt(1. - x * x / (cc * cc)));
    }
  } // namespace CM

  // @sect3{Meshes}
  //
  // As in step-3: deal.II quadrilaterals refined by
  // PolygonalMeshGenerators::refine_toward() while their longest edge
  // exceeds $1.3h$ and their centre lies within two cell sizes of the
  // contact strip, converted to polygons.

  // The block $[-250,250]\times[-250,0]$ (ids 0 left, 1 right, 2 bottom,
  // 3 top), refined toward $|x| \le$ x_strip on its top.
  PolygonalMesh<2>
  block_mesh(const double h)
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {25u, 25u}, dealii::Point<2>(-250, -250),
                                                      dealii::Point<2>(250, 0), true);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
    PolygonalMeshGenerators::refine_toward(
      tria,
      [](const dealii::Point<2> &p) {
        const double dx = std::max(std::abs(p[0]) - CM::x_strip, 0.);
        return std::sqrt(dx * dx + p[1] * p[1]);
      },
      h);
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::from_triangulation(mesh, tria);
    return mesh;
  }

  // The lower half of the disk of radius R about (0, R) (ids 0 arc, 1 the
  // flat cut y = R), vertices on the arc kept on the circle.
  PolygonalMesh<2>
  cylinder_mesh(const double h)
  {
    using dealii::Point;
    const Point<2>           centre(0, CM::R);
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::half_hyper_ball(tria, Point<2>(), CM::R);
    dealii::GridTools::rotate(-M_PI / 2, tria);
    dealii::GridTools::shift(centre - Point<2>(), tria);
    tria.set_manifold(0, dealii::SphericalManifold<2>(centre));
    tria.refine_global(3);
    const double s = CM::x_strip;
    PolygonalMeshGenerators::refine_toward(
      tria,
      [&](const Point<2> &p) {
        const auto   q = p - centre;
        const double r = q.norm();
        if (r > 1e-12 * CM::R)
          {
            const Point<2> on_arc = centre + (CM::R / r) * q;
            if (std::abs(on_arc[0]) <= s && on_arc[1] < CM::R)
              return std::abs(r - CM::R);
          }
        const double ye = CM::R - std::sqrt(CM::R * CM::R - s * s);
        return std::min(p.distance(Point<2>(-s, ye)), p.distance(Point<2>(s, ye)));
      },
      h);
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::from_triangulation(mesh, tria);
    return mesh;
  }

  // The longest boundary edge with id @p id whose midpoint lies in
  // $|x| \le s$.
  double
  local_edge_length(const PolygonalMesh<2> &mesh, const unsigned int id, const double s)
  {
    double h = 0;
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      {
        const auto &edge = mesh.edge(e);
        if (!edge.at_boundary() || edge.boundary_id != id)
          continue;
        const auto &a = mesh.vertex(edge.vertices[0]);
        const auto &b = mesh.vertex(edge.vertices[1]);
        if (std::abs(0.5 * (a[0] + b[0])) <= s)
          h = std::max(h, a.distance(b));
      }
    return h;
  }

  // @sect3{The loads as functions of time}
  //
  // $7m$ load steps in the time $t$: steps 1 to $4m$ press with
  // $P\,(t/4m)^2$ (the contact half-width grows like $\sqrt{P}$, so by equal
  // amounts per step), steps $4m+1$ to $7m$ add
  // $Q = 0.25\,\mu P\,(t/m - 4)$, reaching $Q/(\mu P) = 0.25, 0.5, 0.75$ at
  // the steps $5m$, $6m$, $7m$. The flat cut of the cylinder is a rigid part
  // loaded by $(Q, -P)$ at its centroid $(0, R)$ and by the moment $M = QR$,
  // so that the resultant passes through the centre of the contact (the
  // Cattaneo-Mindlin setting: no tilting moment on the contact). Nothing but
  // friction holds the cylinder horizontally.
  //
  // The loads are ordinary deal.II functions whose value depends on
  // get_time(): ContactProblem sets the time of every load before each
  // step.
  class RigidPartLoad : public dealii::Function<2>
  {
  public:
    /// The force (Q, -P) (two components) or the moment Q R (one).
    RigidPartLoad(const unsigned int m, const bool moment)
      : dealii::Function<2>(moment ? 1 : 2)
      , m(m)
      , moment(moment)
    {}

    double
    value(const dealii::Point<2> &, const unsigned int component) const override
    {
      const double t = get_time();
      const double P = CM::P * std::pow(std::min(t / (4. * m), 1.), 2);
      const double Q = 0.25 * CM::mu * CM::P * std::max(t / m - 4., 0.);
      if (moment)
        return Q * CM::R;
      return component == 0 ? Q : -P;
    }

  private:
    const unsigned int m;
    const bool         moment;
  };

  // @sect3{The contact problem in code}
  //
  // Body 0 is the block (master side, its top has boundary id 3, its bottom
  // 2), body 1 the cylinder with its boundary ids moved by 10 (arc 10, cut
  // 11). Coulomb friction with multipliers (exact stick), the friction
  // coefficient of CM::mu on the one pair.
  ContactProblem::Results
  solve(const PolygonalMesh<2> &block,
        const PolygonalMesh<2> &cylinder,
        const unsigned int      degree,
        const unsigned int      m,
        const std::string      &base_name)
  {
    ContactProblem problem;
    const ElasticMaterial material(CM::E, CM::nu, ElasticMaterial::Model::plane_strain);
    problem.add_body(block, material);
    problem.add_body(cylinder, material, 10);
    problem.add_contact_pair(3, 10, CM::mu);

    auto &bc = problem.boundary_conditions();
    bc.add_dirichlet(2, {{true, true}}, std::make_shared<dealii::Functions::ZeroFunction<2>>(2));
    bc.add_rigid_boundary(11, std::make_shared<RigidPartLoad>(m, false), std::make_shared<RigidPartLoad>(m, true));

    auto &o              = problem.options();
    o.degree             = degree;
    o.contact.normal     = ContactSettings::Normal::unilateral;
    o.contact.tangential = ContactSettings::Tangential::coulomb;
    o.n_load_steps       = 7 * m;
    o.final_time         = 7 * m;
    o.base_name          = base_name;
    o.write_vtu = o.write_pictures = false;
    o.write_json = o.write_csv = true;
    problem.run();
    return problem.get_results();
  }

  // The number of load steps per stage (a quarter of the pressing, a
  // quarter of mu P of shearing) grows with the number of interface nodes,
  // $m = 2^{level} k$: the contact and stick zones then move by about the
  // same number of nodes per step on every mesh, and so does the work of the
  // active set.
  unsigned int
  steps_per_stage(const unsigned int level, const unsigned int degree)
  {
    return (1u << level) * degree;
  }

  // @sect3{Comparison with Cattaneo and Mindlin}
  //
  // Per load level: the numerical stick zone half-width $c_h$ (the middle
  // between the outermost sticking and the first slipping pair, averaged
  // over both sides) against $c$, in units of the local edge length $h$;
  // the largest error of the recovered shear traction (and of the raw
  // tangential force per tributary length) at the pairs with
  // $|x| < 0.8c$, in percent of $\mu p_0$; the Newton iterations of the step.
  // The shear traction transmitted to the block is $q_h = -\tau\,t_x$, the
  // friction traction on the cylinder being $\tau t$.
  struct LoadLevel
  {
    double       q;
    double       c, c_h, c_error_in_h;
    double       shear_error, raw_error, slip_zone_error;
    unsigned int iterations, n_stick, n_slip;
    double       dissipated;
  };

  struct Run
  {
    unsigned int            level, degree, dofs;
    double                  h, seconds;
    std::vector<LoadLevel>  loads;
    /// the most Newton iterations of a pressing and of a shearing step
    unsigned int            press_iterations, shear_iterations;
    /// the smallest energy dissipated in a load step (must not be negative)
    double                  min_step_dissipation;
    ContactProblem::Results results;
  };

  LoadLevel
  evaluate(const ContactProblem::StepResult &step, const double q, const double h)
  {
    LoadLevel l{q, CM::c(q), 0, 0, 0, 0, 0, step.iterations, step.n_stick, step.n_slip, step.dissipated_energy};
    double    x_min = 1e10, x_max = -1e10;
    for (const auto &pr : step.pairs)
      if (pr.status == "stick")
        {
          x_min = std::min(x_min, pr.location[0]);
          x_max = std::max(x_max, pr.location[0]);
        }
    double slip_left = -1e10, slip_right = 1e10;
    for (const auto &pr : step.pairs)
      if (pr.status != "stick")
        {
          if (pr.location[0] > x_max)
            slip_right = std::min(slip_right, pr.location[0]);
          if (pr.location[0] < x_min)
            slip_left = std::max(slip_left, pr.location[0]);
        }
    l.c_h          = 0.25 * (x_max + slip_right - x_min - slip_left);
    l.c_error_in_h = (l.c_h - l.c) / h;
    const double scale = CM::mu * CM::p0();
    for (const auto &pr : step.pairs)
      {
        const double x     = pr.location[0];
        const double exact = CM::shear(x, q);
        if (std::abs(x) < 0.8 * l.c)
          {
            l.shear_error = std::max(l.shear_error, std::abs(-pr.shear * pr.tangent[0] - exact));
            l.raw_error   = std::max(l.raw_error, std::abs(-pr.tangential_traction * pr.tangent[0] - exact));
          }
        // in the slip zone the traction is mu p_h by construction; compare
        // with mu p of Hertz, away from the edges of the contact zone
        if (std::abs(x) > 1.1 * l.c && std::abs(x) < 0.9 * CM::a())
          l.slip_zone_error = std::max(l.slip_zone_error, std::abs(-pr.shear * pr.tangent[0] - exact));
      }
    l.shear_error *= 100. / scale;
    l.raw_error *= 100. / scale;
    l.slip_zone_error *= 100. / scale;
    return l;
  }

  Run
  run(const unsigned int level, const unsigned int degree)
  {
    const auto   start = std::chrono::steady_clock::now();
    const double h     = 0.25 / (1 << level);
    const auto   block = block_mesh(h);
    const auto   cyl   = cylinder_mesh(h);
    const double h_local =
      std::max(local_edge_length(block, 3, CM::a() + 1), local_edge_length(cyl, 0, CM::a() + 1));
    Run r;
    r.level   = level;
    r.degree  = degree;
    r.h       = h_local;
    r.results = solve(block, cyl, degree, steps_per_stage(level, degree),
                      "cm-" + std::to_string(level) + "-k" + std::to_string(degree));
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.dofs    = r.results.n_dofs;
    const unsigned int m = steps_per_stage(level, degree);
    AssertThrow(r.results.steps.size() == 7 * m, dealii::ExcMessage("7m load steps expected"));
    r.press_iterations = 0;
    for (unsigned int s = 0; s < 4 * m; ++s)
      r.press_iterations = std::max(r.press_iterations, r.results.steps[s].iterations);
    r.shear_iterations = 0;
    for (unsigned int s = 4 * m; s < 7 * m; ++s)
      r.shear_iterations = std::max(r.shear_iterations, r.results.steps[s].iterations);
    for (unsigned int j = 1; j <= 3; ++j)
      {
        const unsigned int s = 4 * m + j * m - 1;
        r.loads.push_back(evaluate(r.results.steps[s], 0.25 * j, h_local));
        // the energy dissipated up to this load level
        r.loads.back().dissipated = 0;
        for (unsigned int i = 0; i <= s; ++i)
          r.loads.back().dissipated += r.results.steps[i].dissipated_energy;
      }
    r.min_step_dissipation = 0;
    for (const auto &step : r.results.steps)
      r.min_step_dissipation = std::min(r.min_step_dissipation, step.dissipated_energy);
    return r;
  }

  // The shear traction profiles at the three load levels against the
  // formulas, as an SVG line plot: the computed (recovered) tractions of all
  // three levels as one series of dots, the three analytical curves on top.
  // The plot starts at -2.8a so that the legend (upper left) covers no data.
  void
  write_shear_picture(const std::string &filename, const Run &run)
  {
    const double       left = -2.8 * CM::a(), right = 1.2 * CM::a();
    const unsigned int m    = steps_per_stage(run.level, run.degree);
    SVGPlots::Series   computed{"computed, Q/(mu P) = 0.25, 0.5, 0.75", {}, false, 2.};
    std::vector<SVGPlots::Series> exact;
    for (unsigned int j = 1; j <= 3; ++j)
      {
        const double q = 0.25 * j;
        for (const auto &pr : run.results.steps[4 * m + j * m - 1].pairs)
          if (pr.location[0] >= left && pr.location[0] <= right)
            computed.points.emplace_back(pr.location[0], -pr.shear * pr.tangent[0]);
        SVGPlots::Series e{"formula, Q/(mu P) = " + std::to_string(q).substr(0, 4), {}, true, 0};
        for (unsigned int i = 0; i <= 400; ++i)
          {
            const double x = left + (right - left) * i / 400.;
            e.points.emplace_back(x, CM::shear(x, q));
          }
        exact.push_back(e);
      }
    std::vector<SVGPlots::Series> series{computed};
    series.insert(series.end(), exact.begin(), exact.end());
    SVGPlots::write_line_plot(filename, series, "x [mm]", "shear traction q [MPa]",
                              "Cattaneo-Mindlin: shear traction, mu = 0.3, k = " + std::to_string(run.degree) +
                                ", h = " + std::to_string(run.h).substr(0, 5) + " mm");
  }
} // namespace Step4

// @sect3{The main function}
int
main(int argc, char **argv)
{
  using namespace Step4;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      bool quick = false, study = false, doc_picture = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--quick")
            quick = true;
          else if (arg == "--study")
            study = true;
          else if (arg == "--write-doc-picture")
            doc_picture = true;
          else
            {
              std::cerr << "usage: step-4 [--quick | --study] [--write-doc-picture]" << std::endl;
              return 2;
            }
        }
      std::filesystem::create_directories("output");
      std::cout << "Cattaneo-Mindlin: E* = " << CM::E_star() << " MPa, a = " << CM::a() << " mm, p0 = " << CM::p0()
                << " MPa, mu = " << CM::mu << std::endl;

      std::vector<Run> runs;
      for (unsigned int level = 0; level <= (quick ? 0u : 1u); ++level)
        for (const unsigned int k : (study ? std::vector<unsigned int>{1, 2} : std::vector<unsigned int>{1}))
          runs.push_back(run(level, k));

      std::cout << "\n level | k |     h |  DoFs | Q/(mu P) | c/a formula | c_h/a  | (c_h-c)/h | stick | slip | "
                   "Newton it. | shear err <0.8c % (recovered, raw) | slip zone err % | dissipated  | time s\n";
      for (const auto &r : runs)
        for (const auto &l : r.loads)
          std::cout << std::setw(6) << r.level << " | " << r.degree << " | " << std::fixed << std::setprecision(3)
                    << std::setw(5) << r.h << " | " << std::setw(5) << r.dofs << " | " << std::setw(8)
                    << std::setprecision(2) << l.q << " | " << std::setw(11) << std::setprecision(4) << l.c / CM::a()
                    << " | " << std::setw(6) << l.c_h / CM::a() << " | " << std::setw(9) << std::setprecision(2)
                    << l.c_error_in_h << " | " << std::setw(5) << l.n_stick << " | " << std::setw(4) << l.n_slip
                    << " | " << std::setw(10) << l.iterations << " | " << std::setw(16) << l.shear_error << ", "
                    << std::setw(16) << l.raw_error << " | " << std::setw(15) << l.slip_zone_error << " | "
                    << std::scientific << std::setprecision(3) << std::setw(11) << l.dissipated << " | "
                    << std::fixed << std::setprecision(1) << std::setw(6) << r.seconds << std::endl;
      for (const auto &r : runs)
        std::cout << "level " << r.level << ", k = " << r.degree << ": " << 7 * steps_per_stage(r.level, r.degree)
                  << " load steps; at most " << r.press_iterations << " Newton iterations per pressing step, "
                  << r.shear_iterations << " per shearing step" << std::endl;

      const std::string picture =
        doc_picture ? (std::filesystem::path(__FILE__).parent_path() / "doc" / "cattaneo-mindlin-shear.svg").string() :
                      std::string("cattaneo-mindlin-shear.svg");
      write_shear_picture(picture, runs.back());
      std::cout << "shear traction profiles: " << picture << std::endl;

      // The checks, on every run: the stick zone within one local edge of
      // the formula at Q/(mu P) = 0.5, the recovered shear traction within
      // 5 % of mu p0 inside 0.8c at every load level, at most 6 Newton
      // iterations per load step for k = 1 (10 for k = 2), no negative
      // dissipation in any step.
      std::vector<std::string> failures;
      for (const auto &r : runs)
        {
          const std::string tag = "level " + std::to_string(r.level) + ", k = " + std::to_string(r.degree) + ": ";
          if (r.min_step_dissipation < 0)
            failures.push_back(tag + "a load step dissipates a negative energy");
          // k = 1: at most 6 Newton iterations per load step; k = 2 has twice
          // the pairs and needs more (measured: 7 to 9), bounded by 10
          const unsigned int max_iterations = (r.degree == 1 ? 6 : 10);
          if (r.press_iterations > max_iterations || r.shear_iterations > max_iterations)
            failures.push_back(tag + "more than " + std::to_string(max_iterations) +
                               " Newton iterations in a load step");
          for (const auto &l : r.loads)
            {
              const std::string at = tag + "Q/(mu P) = " + std::to_string(l.q).substr(0, 4) + ": ";
              if (l.q == 0.5 && std::abs(l.c_error_in_h) > 1.)
                failures.push_back(at + "stick zone off by more than one edge");
              if (l.shear_error > 5.)
                failures.push_back(at + "shear traction inside 0.8c off by more than 5 % of mu p0");
            }
        }
      for (const auto &m : failures)
        std::cerr << "step-4 check failed: " << m << std::endl;
      return failures.empty() ? 0 : 1;
    }
  catch (std::exception &exc)
    {
      std::cerr << std::endl << "Exception: " << exc.what() << std::endl;
      return 1;
    }
}
