// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// step-3: Hertz contact of a cylinder on a block (the NAFEMS benchmark) and
// a flat punch, with curved, independently meshed contact surfaces.
//
// Build (from a dealvem build directory):   make step-3
// Run:                                      ./examples/step-3 [--quick | --study] [--write-doc-picture]
// What it does: a half cylinder (R = 50 mm, E = 70 GPa) is pressed by a
// resultant P = 35 kN/mm onto a block (E = 210 GPa), nu = 0.3, plane
// strain, frictionless unilateral contact. Both bodies are meshed by deal.II
// (quadrilaterals refined toward the contact zone, the arc kept on the circle
// by a SphericalManifold) and converted to polygonal meshes; the two
// surfaces do not match, node insertion makes them match. The loaded flat
// cut of the cylinder is a rigid boundary part. The program compares the
// contact pressure with Hertz's solution for k = 1, 2 on two mesh levels,
// then solves a flat punch problem, and exits with an error if the finest
// k = 2 Hertz solution or the punch misses the accuracy it is expected to
// reach. --quick runs the coarse level only (a few seconds less).

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

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace Step3
{
  using namespace dealvem;

  // @sect3{The data of the Hertz problem}
  //
  // The NAFEMS values. The effective modulus of the pair,
  // $1/E^* = (1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2$, gives the half-width
  // $a = \sqrt{4PR/(\pi E^*)}$ and the peak pressure $p_0 = 2P/(\pi a)$.
  namespace Hertz
  {
    constexpr double R        = 50.;
    constexpr double E_cyl    = 70000.;
    constexpr double E_block  = 210000.;
    constexpr double nu       = 0.3;
    constexpr double P        = 35000.;
    constexpr double x_strip  = 8.; // fine mesh on |x| <= x_strip

    double
    E_star()
    {
      return 1. / ((1. - nu * nu) / E_cyl + (1. - nu * nu) / E_block);
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
  } // namespace Hertz

  // @sect3{Meshes}
  //
  // Both bodies start from a coarse deal.II triangulation.
  // PolygonalMeshGenerators::refine_toward() refines cells while their
  // longest edge exceeds the target size $h$ by more than 30 % (so that both
  // bodies end up near $h$ although their coarse meshes have unrelated
  // sizes) and their centre lies within `layers` cell sizes of the contact
  // strip (given by a distance function). deal.II keeps neighbouring cells
  // within one level of each other, so the mesh grades from $h$ at the
  // contact to the coarse size away from it; the hanging vertices that this
  // leaves become vertices of the coarse polygons in
  // PolygonalMeshGenerators::from_triangulation().

  // Distance to the segment $|x| \le s$, $y = y_0$.
  double
  distance_to_segment(const dealii::Point<2> &p, const double s, const double y0)
  {
    const double dx = std::max(std::abs(p[0]) - s, 0.);
    return std::sqrt(dx * dx + (p[1] - y0) * (p[1] - y0));
  }

  // The block $[-100,100]\times[-100,0]$ from 25 x 12 cells (h = 8), refined
  // toward the part $|x| \le s$ of its top. Boundary ids (colorize):
  // 0 left, 1 right, 2 bottom, 3 top.
  PolygonalMesh<2>
  block_mesh(const double h, const double s)
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {25u, 12u}, dealii::Point<2>(-100, -100),
                                                      dealii::Point<2>(100, 0), true);
    for (const auto &cell : tria.active_cell_iterators()) // colorize also numbers the cells
      cell->set_material_id(0);
    PolygonalMeshGenerators::refine_toward(tria, [s](const dealii::Point<2> &p) { return distance_to_segment(p, s, 0.); }, h, 2.);
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::from_triangulation(mesh, tria);
    return mesh;
  }

  // The lower half of the disk of radius R about (0, R): deal.II's half
  // ball (cut perpendicular to x) turned by -90 degrees and moved up.
  // Boundary ids: 0 the arc, 1 the flat cut y = R. The arc carries manifold
  // id 0, to which a SphericalManifold about the new centre is attached, so
  // every vertex created on the arc lies on the circle. The distance used for
  // the refinement is the one to the arc piece $|x| \le s$.
  PolygonalMesh<2>
  cylinder_mesh(const double h, const double s)
  {
    using dealii::Point;
    const Point<2>           centre(0, Hertz::R);
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::half_hyper_ball(tria, Point<2>(), Hertz::R);
    dealii::GridTools::rotate(-M_PI / 2, tria);
    dealii::GridTools::shift(centre - Point<2>(), tria);
    tria.set_manifold(0, dealii::SphericalManifold<2>(centre));
    tria.refine_global(3);
    auto distance = [&](const Point<2> &p) {
      const auto   q = p - centre;
      const double r = q.norm();
      if (r > 1e-12 * Hertz::R)
        {
          const Point<2> on_arc = centre + (Hertz::R / r) * q;
          if (std::abs(on_arc[0]) <= s && on_arc[1] < Hertz::R)
            return std::abs(r - Hertz::R);
        }
      const double ye = Hertz::R - std::sqrt(Hertz::R * Hertz::R - s * s);
      return std::min(p.distance(Point<2>(-s, ye)), p.distance(Point<2>(s, ye)));
    };
    PolygonalMeshGenerators::refine_toward(tria, distance, h, 2.);
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::from_triangulation(mesh, tria);
    return mesh;
  }

  // The longest boundary edge with id @p id whose midpoint lies in |x| <= s:
  // the local edge length of the contact surface.
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

  // @sect3{The contact problem in code}
  //
  // The two bodies, their materials, the contact pair, the boundary
  // conditions and the options are handed to ContactProblem through its C++
  // interface (the `dealvem` program fills the same interface from a
  // parameter file). Body 0 is the block (the master side of the pair: its
  // flat top gives the normal), body 1 the cylinder with its boundary ids
  // moved by 10 (arc 10, cut 11). The block's bottom is fixed. The cylinder
  // is held by nothing but the contact and by one point constraint against
  // the horizontal rigid motion that frictionless contact cannot stop; it
  // sits at the centre of the cut, the reference node of the rigid part.
  // The cut itself is a rigid boundary part loaded by the resultant (0, -P).
  struct TwoBodySetup
  {
    const PolygonalMesh<2> *master, *slave;
    double                  E_master, E_slave;
    unsigned int            master_id, slave_id, fixed_id, rigid_id;
    double                  load;
    dealii::Point<2>        x_constraint;
    unsigned int            degree;
    std::string             base_name;
  };

  ContactProblem::Results
  solve(const TwoBodySetup &s)
  {
    ContactProblem problem;
    problem.add_body(*s.master, ElasticMaterial(s.E_master, Hertz::nu, ElasticMaterial::Model::plane_strain));
    problem.add_body(*s.slave, ElasticMaterial(s.E_slave, Hertz::nu, ElasticMaterial::Model::plane_strain),
                     10);
    problem.add_contact_pair(s.master_id, s.slave_id);

    auto &bc = problem.boundary_conditions();
    bc.add_dirichlet(s.fixed_id, {{true, true}}, std::make_shared<dealii::Functions::ZeroFunction<2>>(2));
    bc.add_rigid_boundary(s.rigid_id, std::make_shared<dealii::Functions::ConstantFunction<2>>(
                                        std::vector<double>{0., -s.load}));
    bc.add_point_constraint(s.x_constraint, 0, std::make_shared<dealii::Functions::ZeroFunction<2>>(1),
                            /*body=*/1);

    auto &o              = problem.options();
    o.degree             = s.degree;
    o.contact.normal     = ContactSettings::Normal::unilateral;
    o.contact.tangential = ContactSettings::Tangential::frictionless;
    o.base_name          = s.base_name;
    o.write_vtu = o.write_json = o.write_pictures = false;
    o.write_csv                                   = true;
    problem.run();
    return problem.get_results();
  }

  // @sect3{Comparison with Hertz's solution}
  //
  // One row of the table. The numerical peak pressure is the largest
  // recovered pressure; the numerical half-width is measured from the middle
  // between the outermost closed and the first open pair on each side, its error is given in units of the local edge
  // length h of the contact surfaces. The nodal errors are measured at every
  // pair with $|x| < 0.8a$, away from the edges of the contact zone where the
  // exact pressure has a square-root behaviour that no mesh resolves.
  struct Row
  {
    unsigned int level, degree;
    double       h;
    unsigned int cells, dofs, iterations;
    double       p0_error, a_error_in_h, recovered_error, lumped_error, force_error;
    unsigned int open_inside;
    unsigned int open_end_warnings;
    double       seconds;
    /// root mean square of the nodal errors inside 0.8a (% of p0)
    double       recovered_rms = 0, lumped_rms = 0;
  };

  Row
  evaluate(const ContactProblem::Results &r, const unsigned int level, const unsigned int degree,
           const double h, const double seconds)
  {
    const double a = Hertz::a(), p0 = Hertz::p0();
    Row          row{level, degree, h, r.mesh.n_cells(), r.n_dofs, r.active_set_iterations, 0, 0, 0, 0, 0, 0,
            r.n_open_end_warnings, seconds};
    double       p_max = 0, x_min = 0, x_max = 0, sum_r = 0, sum_l = 0;
    unsigned int n_inside = 0;
    for (const auto &pair : r.pairs)
      if (pair.active)
        {
          x_min = std::min(x_min, pair.location[0]);
          x_max = std::max(x_max, pair.location[0]);
        }
    double open_left = -1e10, open_right = 1e10;
    for (const auto &pair : r.pairs)
      {
        const double x = pair.location[0];
        if (!pair.active)
          {
            if (std::abs(x) < a - h)
              ++row.open_inside;
            if (x > x_max)
              open_right = std::min(open_right, x);
            if (x < x_min)
              open_left = std::max(open_left, x);
          }
        p_max = std::max(p_max, pair.pressure);
        if (std::abs(x) < 0.8 * a)
          {
            row.recovered_error = std::max(row.recovered_error, std::abs(pair.pressure - Hertz::pressure(x)));
            row.lumped_error = std::max(row.lumped_error, std::abs(pair.lumped_pressure - Hertz::pressure(x)));
            sum_r += std::pow(pair.pressure - Hertz::pressure(x), 2);
            sum_l += std::pow(pair.lumped_pressure - Hertz::pressure(x), 2);
            ++n_inside;
          }
      }
    row.p0_error        = 100. * (p_max / p0 - 1.);
    // the edge of the contact zone lies between the last closed and the
    // first open pair on either side: take the middle
    row.a_error_in_h    = (0.25 * (x_max + open_right - x_min - open_left) - a) / h;
    row.recovered_error = 100. * row.recovered_error / p0;
    row.lumped_error    = 100. * row.lumped_error / p0;
    row.recovered_rms   = 100. * std::sqrt(sum_r / std::max(n_inside, 1u)) / p0;
    row.lumped_rms      = 100. * std::sqrt(sum_l / std::max(n_inside, 1u)) / p0;
    row.force_error     = r.total_contact_force.norm() / Hertz::P - 1.;
    return row;
  }

  // The pressure profile as an SVG line plot: the recovered pressure, the
  // lumped raw multipliers and Hertz's curve, all over x.
  void
  write_pressure_picture(const std::string &filename, const ContactProblem::Results &r, const std::string &title)
  {
    SVGPlots::Series recovered{"recovered pressure", {}, false, 2.5},
      lumped{"raw multipliers -lambda/w", {}, false, 1.5}, exact{"Hertz: p0 sqrt(1 - x^2/a^2)", {}, true, 0};
    const double     range = 1.25 * Hertz::a();
    for (const auto &pair : r.pairs)
      if (std::abs(pair.location[0]) <= range)
        {
          recovered.points.emplace_back(pair.location[0], pair.pressure);
          lumped.points.emplace_back(pair.location[0], pair.lumped_pressure);
        }
    auto by_x = [](const auto &u, const auto &v) { return u.first < v.first; };
    std::sort(recovered.points.begin(), recovered.points.end(), by_x);
    std::sort(lumped.points.begin(), lumped.points.end(), by_x);
    for (unsigned int i = 0; i <= 100; ++i)
      {
        const double x = -range + 2. * range * i / 100.;
        exact.points.emplace_back(x, Hertz::pressure(x));
      }
    // drawn in this order: the analytical curve on top
    SVGPlots::write_line_plot(filename, {lumped, recovered, exact}, "x [mm]", "contact pressure [MPa]", title);
  }

  // @sect3{The Hertz study}
  Row
  run_hertz(const unsigned int level, const unsigned int degree, ContactProblem::Results *results = nullptr)
  {
    const auto   start = std::chrono::steady_clock::now();
    const double h     = 0.25 / (1 << level);
    const auto   block = block_mesh(h, Hertz::x_strip);
    const auto   cyl   = cylinder_mesh(h, Hertz::x_strip);
    // the meshes also go to files, for the `dealvem` program and the peer
    // benchmark (benchmarks/hertz_peer), which read them
    MeshIO::write_vtk(block, "hertz-block-" + std::to_string(level) + ".vtk");
    MeshIO::write_vtk(cyl, "hertz-cylinder-" + std::to_string(level) + ".vtk");
    const double h_local =
      std::max(local_edge_length(block, 3, Hertz::a() + 1), local_edge_length(cyl, 0, Hertz::a() + 1));

    const TwoBodySetup s{&block, &cyl, Hertz::E_block, Hertz::E_cyl, 3, 10, 2, 11, Hertz::P,
                         dealii::Point<2>(0, 50), degree, "hertz-" + std::to_string(level) + "-k" + std::to_string(degree)};
    const auto r = solve(s);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (results)
      *results = r;
    return evaluate(r, level, degree, h_local, seconds);
  }

  // @sect3{The flat punch}
  //
  // A punch of half-width b = 10 and height 10, 1000 times stiffer than the
  // block, is pressed on the same block by a rigid top loaded by (0, -P).
  // On a half-space a rigid flat punch gives
  // $p(x) = P / (\pi\sqrt{b^2 - x^2})$, infinite at the corners. The
  // recovered pressure is compared at $|x| \le b/2$.
  struct PunchResult
  {
    double max_error, seconds, force_error;
    unsigned int dofs;
  };

  PunchResult
  run_punch(const unsigned int degree, const double h, ContactProblem::Results *results = nullptr)
  {
    const auto   start = std::chrono::steady_clock::now();
    const double b = 10., P = 10000.;
    const auto   block = block_mesh(h, 1.2 * b);
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {4u, 2u}, dealii::Point<2>(-b, 0),
                                                      dealii::Point<2>(b, b), true);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
    PolygonalMeshGenerators::refine_toward(tria, [](const dealii::Point<2> &p) { return std::abs(p[1]); }, h, 2.);
    PolygonalMesh<2> punch;
    PolygonalMeshGenerators::from_triangulation(punch, tria);
    // punch ids after the offset: 12 bottom, 13 top
    const TwoBodySetup s{&block, &punch, Hertz::E_block, 1000. * Hertz::E_block, 3, 12, 2, 13, P,
                         dealii::Point<2>(0, 10), degree, "punch-k" + std::to_string(degree)};
    const auto r = solve(s);
    if (results)
      *results = r;
    PunchResult result{0, 0, r.total_contact_force.norm() / P - 1., r.n_dofs};
    for (const auto &pair : r.pairs)
      if (const double x = pair.location[0]; std::abs(x) <= 0.5 * b)
        {
          const double exact = P / (M_PI * std::sqrt(b * b - x * x));
          result.max_error   = std::max(result.max_error, std::abs(pair.pressure / exact - 1.));
        }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
} // namespace Step3

// @sect3{The main function}
int
main(int argc, char **argv)
{
  using namespace Step3;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      bool quick = false, doc_picture = false, study = false;
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
              std::cerr << "usage: step-3 [--quick | --study] [--write-doc-picture]" << std::endl;
              return 2;
            }
        }
      std::filesystem::create_directories("output");
      std::cout << "Hertz contact: E* = " << Hertz::E_star() << " MPa, a = " << Hertz::a()
                << " mm, p0 = " << Hertz::p0() << " MPa" << std::endl;

      const unsigned int      finest = (quick ? 0 : (study ? 2 : 1));
      std::vector<Row>        rows;
      ContactProblem::Results finest_k2;
      for (unsigned int level = 0; level <= finest; ++level)
        for (const unsigned int k : {1u, 2u})
          rows.push_back(run_hertz(level, k, (level == finest && k == 2) ? &finest_k2 : nullptr));

      std::cout << "\n level | k |     h | cells |  DoFs | AS it. | p0 err % | (a_h-a)/h | "
                   "max err <0.8a % (recovered, raw) | rms err <0.8a % (recovered, raw) | F/P - 1   | time s\n";
      for (const auto &r : rows)
        std::cout << std::setw(6) << r.level << " | " << r.degree << " | " << std::fixed << std::setprecision(3)
                  << std::setw(5) << r.h << " | " << std::setw(5) << r.cells << " | " << std::setw(5) << r.dofs
                  << " | " << std::setw(6) << r.iterations << " | " << std::setprecision(2) << std::setw(8)
                  << r.p0_error << " | " << std::setw(9) << r.a_error_in_h << " | " << std::setw(16)
                  << r.recovered_error << ", " << std::setw(16) << r.lumped_error << " | " << std::setw(16)
                  << r.recovered_rms << ", " << std::setw(15) << r.lumped_rms << " | " << std::scientific
                  << std::setprecision(1) << std::setw(9) << r.force_error << " | " << std::fixed
                  << std::setprecision(1) << std::setw(6) << r.seconds << std::endl;

      const std::string picture =
        doc_picture ? (std::filesystem::path(__FILE__).parent_path() / "doc" / "hertz-pressure.svg").string() :
                      std::string("hertz-pressure.svg");
      if (doc_picture)
        std::filesystem::create_directories(std::filesystem::path(picture).parent_path());
      write_pressure_picture(picture, finest_k2,
                             "Hertz contact, k = 2, h = " + std::to_string(rows.back().h).substr(0, 5));
      std::cout << "pressure profile: " << picture << std::endl;

      // The checks on the finest k = 2 solution.
      std::vector<std::string> failures;
      const Row               &f = rows.back();
      if (std::abs(f.p0_error) > 1.)
        failures.push_back("peak pressure off by more than 1 %");
      if (std::abs(f.a_error_in_h) > 1.)
        failures.push_back("half-width off by more than one edge");
      if (f.recovered_error > 3.)
        failures.push_back("recovered pressure inside 0.8a off by more than 3 % of p0");
      if (f.open_inside > 0)
        failures.push_back("open pairs inside the contact zone");
      if (std::abs(f.force_error) > 1e-10)
        failures.push_back("total contact force differs from P");
      if (f.open_end_warnings > 0)
        failures.push_back("open-end warnings");

      // The refinement study. The computed solution converges to the
      // solution of the finite bodies (a cylinder of R = 50 is not a
      // half-space: its peak pressure settles about 0.5 % above Hertz's
      // p0), so the errors against Hertz's formula level off at that
      // model error. Checked: the rms of the raw nodal errors falls from
      // level to level for both orders, and the recovered pressure stays
      // within 1.5 % of p0 on the refined levels.
      // The multipliers themselves converge node by node: at k = 2 (with the
      // diagonal stabilization, see ElasticityOperator) the raw values per
      // tributary length are within 1.0 / 0.7 / 0.6 % of p0 inside 0.8a on
      // levels 0 / 1 / 2 (measured 0.62 / 0.50 / 0.44 %), and the recovered
      // pressure is no worse than the raw one.
      // The active-set iterations (issue targets: k = 1 at most 8, k = 2 at
      // most 9 at every level; measured 5 / 4 / 5 and 6 / 4 / 6 with the
      // accelerated update, 8 / 10 / 10 and 8 / 9 / 11 with the plain one).
      for (const auto &r : rows)
        if (r.iterations > (r.degree == 1 ? 8u : 9u))
          failures.push_back("k = " + std::to_string(r.degree) + ", level " + std::to_string(r.level) + ": " +
                             std::to_string(r.iterations) + " active-set iterations, more than " +
                             (r.degree == 1 ? "8" : "9"));
      for (const auto &r : rows)
        if (r.degree == 2)
          {
            const double bound = (r.level == 0 ? 1.0 : r.level == 1 ? 0.7 : 0.6);
            if (r.lumped_error > bound)
              failures.push_back("k = 2, level " + std::to_string(r.level) + ": raw nodal pressure error above " +
                                 std::to_string(bound) + " % of p0");
            if (r.recovered_error > r.lumped_error)
              failures.push_back("k = 2, level " + std::to_string(r.level) +
                                 ": the recovered pressure is worse than the raw multipliers");
          }
      if (study)
        for (const unsigned int k : {1u, 2u})
          {
            std::vector<const Row *> by_level;
            for (const auto &r : rows)
              if (r.degree == k)
                by_level.push_back(&r);
            for (unsigned int l = 1; l < by_level.size(); ++l)
              if (!(by_level[l]->lumped_rms < by_level[l - 1]->lumped_rms))
                failures.push_back("k = " + std::to_string(k) + ": the rms raw nodal pressure error did not fall from level " +
                                   std::to_string(l - 1) + " to " + std::to_string(l));
            for (const Row *r : by_level)
              if (r->level > 0 && r->recovered_error > 1.5)
                failures.push_back("k = " + std::to_string(k) + ", level " + std::to_string(r->level) +
                                   ": recovered pressure off by more than 1.5 % of p0");
          }

      // The punch.
      std::cout << "\nFlat punch (b = 10, E_punch = 1000 E_block):" << std::endl;
      for (const unsigned int k : {1u, 2u})
        {
          const auto punch = run_punch(k, quick ? 0.25 : 0.125);
          std::cout << "  k = " << k << ": " << punch.dofs << " DoFs, max |p/p_exact - 1| on |x| <= b/2: "
                    << std::setprecision(2) << 100. * punch.max_error << " %, F/P - 1 = " << std::scientific
                    << std::setprecision(1) << punch.force_error << std::fixed << ", " << std::setprecision(1)
                    << punch.seconds << " s" << std::endl;
          // measured: 0.7 % at both h; the bound leaves room for other meshes
          if (punch.max_error > 0.02)
            failures.push_back("punch pressure off by more than 2 % at |x| <= b/2");
          if (std::abs(punch.force_error) > 1e-7)
            failures.push_back("punch contact force differs from P");
        }

      for (const auto &m : failures)
        std::cerr << "step-3 check failed: " << m << std::endl;
      return failures.empty() ? 0 : 1;
    }
  catch (std::exception &exc)
    {
      std::cerr << std::endl << "Exception: " << exc.what() << std::endl;
      return 1;
    }
}
