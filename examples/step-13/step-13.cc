// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// step-13: topology optimization of bodies in contact.
//
// Build (from a dealvem build directory):   make step-13
// Run:                                      ./examples/step-13 [--fine]
// What it does:
// 1. The MBB beam of deal.II's step-79 (a 6 x 1 beam on two bottom
//    corners, a downward traction of 1 on the top's middle 0.5, lambda =
//    mu = 1, half the volume, SIMP exponent 3, filter radius 0.251) on a
//    centroidal Voronoi mesh with virtual elements of order 1, optimized by
//    NLopt's MMA. Writes step-13-mbb.svg (the design), step-13-mbb-NNNN.vtu
//    every tenth iteration and step-13-mbb-history.svg (compliance and
//    volume against the iteration).
// 2. A bracket on a support: a 2 x 1 design domain (Voronoi) clamped to a
//    wall at its left and standing on a solid support block (quads, a
//    non-matching interface), pulled upwards at its top near x = 1.5.
//    Designed twice: with the interface bonded (tied) and with unilateral
//    contact (stick where closed). Each design is then analysed with the
//    real, unilateral contact. Writes
//    step-13-tied.svg, step-13-unilateral.svg and step-13-traction.svg
//    (the interface traction of each design with its own model).
// 3. The bracket pushed down onto the support, designed without and with
//    its largest contact pressure bounded by half of the unbounded
//    design's (an MMA constraint beside the volume). Writes
//    step-13-pushed.svg, step-13-bounded.svg and step-13-pressure.svg.
// The program stops with an error unless: the MBB design meets the volume
// to 1e-3 and its compliance fell below 40 % of the uniform design's; the
// unilateral design is stiffer under unilateral contact than the tied
// design is (by at least 2 %); the tied design pulls on its support
// (tensile multipliers) and the unilateral one does not; the two designs
// differ in at least 5 % of the domain; the pressure-bounded design meets
// its bound to 1 %, lowers the largest pair pressure by a quarter and is
// not stiffer than the unbounded one.

// @sect3{Include files}
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dealvem/design/design_output.h>
#include <dealvem/design/design_problem.h>
#include <dealvem/design/topology_optimizer.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/postprocessing/svg_plots.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace Step13
{
  using namespace dealvem;
  using Point  = dealii::Point<2>;
  using Vector = dealii::Tensor<1, 2>;

  // @sect3{Marking a loaded segment}
  //
  // The load of both problems acts on a piece of the top side. On a Voronoi
  // mesh the ends of that piece are not vertices, so the boundary edges
  // whose midpoints lie in [x0, x1] on the line y = y_top get the id @p id,
  // and the function returns their length: a traction of F / length then
  // puts exactly the force F on them.
  double
  mark_top_segment(PolygonalMesh<2> &mesh, const double y_top, const double x0, const double x1,
                   const dealii::types::boundary_id id)
  {
    double length = 0;
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      {
        const auto &edge = mesh.edge(e);
        if (!edge.at_boundary())
          continue;
        const Point a = mesh.vertex(edge.vertices[0]), b = mesh.vertex(edge.vertices[1]);
        const Point m = 0.5 * (a + b);
        if (std::abs(a[1] - y_top) < 1e-12 && std::abs(b[1] - y_top) < 1e-12 && m[0] >= x0 && m[0] <= x1)
          {
            mesh.set_edge_boundary_id(e, id);
            length += a.distance(b);
          }
      }
    AssertThrow(length > 0, dealii::ExcMessage("No boundary edge on the loaded segment."));
    return length;
  }

  // @sect3{Part 1: the MBB beam of step-79}
  //
  // step-79 solves this problem with Q1 elements on 48 x 8 squares by a
  // SAND interior-point method; here the same data go on polygons. The
  // supports are two vertices, which a Voronoi mesh of a rectangle has at
  // its corners.
  double
  mbb(const unsigned int n_cells)
  {
    std::cout << "Part 1: the MBB beam of step-79 on " << n_cells << " Voronoi cells, k = 1, MMA" << std::endl;
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::voronoi(mesh, Point(0, 0), Point(6, 1), n_cells, 30, 1);
    const double length = mark_top_segment(mesh, 1., 2.75, 3.25, 4);

    MaterialLibrary<2> laws;
    laws.add(0, ElasticMaterial(2.5, 0.25)); // lambda = mu = 1
    Design::ElasticDesignProblem problem(mesh, laws, 1);
    problem.add_point_support(Point(0, 0), 0);
    problem.add_point_support(Point(0, 0), 1);
    problem.add_point_support(Point(6, 0), 1);
    problem.add_traction(4, Vector({0., -0.5 / length})); // the force of step-79: 0.5
    problem.setup();

    Design::TopologyOptimizer::Settings settings;
    settings.volume_fraction       = 0.5;
    settings.filter_radius         = 0.251;
    settings.interpolation.penalty = 3;
    settings.interpolation.minimum = 1e-4;
    settings.optimizer             = Design::TopologyOptimizer::Optimizer::mma;
    settings.max_iterations        = 300;
    settings.tolerance             = 1e-2;
    Design::TopologyOptimizer optimizer(settings);
    // every tenth iteration: a line of output and a VTU file of the
    // densities (ParaView opens the series step-13-mbb-*.vtu at once)
    optimizer.set_callback(
      [&mesh](const unsigned int it, const Design::TopologyOptimizer::Iteration &record,
              const std::vector<double> &density) {
        if (it % 10 != 1)
          return;
        std::cout << "   iteration " << std::setw(3) << it << ": compliance " << std::setprecision(6)
                  << record.objective << ", volume " << record.volume << ", change " << record.change
                  << std::endl;
        char name[64];
        std::snprintf(name, sizeof(name), "step-13-mbb-%04u.vtu", it);
        Design::write_density_vtu(name, mesh, density);
      });
    const auto result = optimizer.run(problem);

    const double c0 = result.history.front().objective;
    std::cout << "   " << result.history.size() << " iterations (" << result.stop_reason << "), compliance "
              << result.objective << " (uniform design: " << c0 << "), volume " << result.volume << ", "
              << std::setprecision(3) << result.time << " s (" << result.analysis_time << " s in the analyses)"
              << std::setprecision(6) << std::endl;
    Design::write_density_svg("step-13-mbb.svg", problem.get_mesh(), result.densities,
                              "step-13: the MBB beam of step-79 on " + std::to_string(n_cells) +
                                " Voronoi cells, compliance " + std::to_string(result.objective));
    SVGPlots::Series compliance, volume;
    compliance.name = "compliance / compliance of the uniform design";
    volume.name     = "volume fraction";
    for (unsigned int i = 0; i < result.history.size(); ++i)
      {
        compliance.points.emplace_back(i + 1, result.history[i].objective / c0);
        volume.points.emplace_back(i + 1, result.history[i].volume);
      }
    compliance.marker_radius = volume.marker_radius = 0;
    SVGPlots::write_line_plot("step-13-mbb-history.svg", {compliance, volume}, "iteration", "",
                              "step-13: MMA on the MBB beam");

    AssertThrow(std::abs(result.volume - 0.5) <= 1e-3,
                dealii::ExcMessage("The MBB design does not meet its volume fraction."));
    AssertThrow(result.objective < 0.4 * c0,
                dealii::ExcMessage("The MBB design is not stiffer than 40 % of the uniform design's compliance."));
    return result.objective;
  }

  // @sect3{Part 2: a bracket on a support}
  //
  // The support block [0, 2] x [-0.25, 0] (material id 1, 16 x 2 quads) is
  // held at its bottom and kept solid (a passive material id); the design
  // domain [0, 2] x [0, 1] (material id 0, Voronoi) is clamped at its left
  // side and stands on the block, and the two meshes do not match at
  // y = 0. The load (0, 1) pulls on the top edges within 0.05 of x = 1.5.
  // Bonded to the block, the bracket can hang the load on it by a short
  // tie; resting on it, it cannot pull on the block and must carry the load
  // to the wall.
  struct PartOnSupport
  {
    PolygonalMesh<2>   mesh;
    MaterialLibrary<2> laws;
    double             load_length = 0;

    PartOnSupport(const unsigned int n_cells)
    {
      PolygonalMesh<2> part;
      PolygonalMeshGenerators::structured_quads(mesh, Point(0, -0.25), Point(2, 0), 16, 2);
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        mesh.set_material_id(c, 1);
      PolygonalMeshGenerators::voronoi(part, Point(0, 0), Point(2, 1), n_cells, 30, 3);
      // the part's boundary ids become 10 .. 13 (left, right, bottom, top)
      for (unsigned int e = 0; e < part.n_edges(); ++e)
        if (part.edge(e).at_boundary())
          part.set_edge_boundary_id(e, part.edge(e).boundary_id + 10);
      load_length = mark_top_segment(part, 1., 1.45, 1.55, 20);
      mesh.append(part);
      laws.add(0, ElasticMaterial(1., 0.3));
      laws.add(1, ElasticMaterial(1., 0.3));
    }

    // The design problem with the interface model @p normal (stick
    // tangentially by multipliers where closed). With @p pressure_bound
    // > 0 the largest contact pressure of the interface (the 8-norm of the
    // pair pressures) is constrained to at most that value; the constraint
    // is evaluated (and reported by last_state()) in any case when
    // @p pressure_bound is negative, with a bound that does not matter.
    std::unique_ptr<Design::ElasticDesignProblem>
    problem(const ContactSettings::Normal normal, const double pressure_bound = 0, const bool push = false) const
    {
      auto p = std::make_unique<Design::ElasticDesignProblem>(mesh, laws, 1);
      p->contact_settings().normal     = normal;
      p->contact_settings().tangential = ContactSettings::Tangential::multipliers;
      p->add_contact_interface(3, 12); // the support's top (master), the part's bottom
      p->add_support(2);  // the block's bottom
      p->add_support(10); // the bracket's left side, on the wall
      p->add_traction(20, Vector({0., (push ? -1. : 1.) / load_length}));
      if (pressure_bound != 0)
        p->add_constraint(Design::ElasticDesignProblem::Response::max_pressure, std::abs(pressure_bound));
      p->setup();
      return p;
    }
  };

  // Optimize for the compliance with the model @p normal.
  Design::TopologyOptimizer::Result
  design(const PartOnSupport &setup, const ContactSettings::Normal normal, const std::string &name,
         const double pressure_bound = 0, const bool push = false)
  {
    auto                                problem = setup.problem(normal, pressure_bound, push);
    Design::TopologyOptimizer::Settings settings;
    settings.volume_fraction       = 0.3;
    settings.filter_radius         = 0.12;
    settings.interpolation.penalty = 3;
    settings.interpolation.minimum = 1e-4;
    settings.solid_ids             = {1};
    settings.max_iterations        = 200;
    settings.tolerance             = 1e-2;
    Design::TopologyOptimizer optimizer(settings);
    const auto                result = optimizer.run(*problem);
    std::cout << "   " << name << " design: " << result.history.size() << " iterations (" << result.stop_reason
              << "), compliance " << result.objective << ", volume " << result.volume << ", "
              << std::setprecision(3) << result.time << " s" << std::setprecision(6) << std::endl;
    return result;
  }

  // The compliance of the densities @p density with the interface model
  // @p normal, the interface traction -lambda_i / w_i along x (positive:
  // the bracket presses on the block) into @p traction, and the largest
  // tensile multiplier into @p tension.
  double
  analyse(const PartOnSupport &setup, const std::vector<double> &density, const ContactSettings::Normal normal,
          SVGPlots::Series &traction, double &tension, double *pressure_norm = nullptr, const bool push = false)
  {
    auto                          problem = setup.problem(normal, -1., push);
    Design::MaterialInterpolation interpolation;
    interpolation.penalty = 3;
    interpolation.minimum = 1e-4;
    std::vector<double> s(density.size()), g;
    for (unsigned int c = 0; c < s.size(); ++c)
      s[c] = interpolation.factor(density[c]);
    const double compliance = problem->evaluate(s, g);
    const auto  &pairs      = problem->get_pairs();
    tension                 = 0;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const double lambda = problem->last_state().normal_multipliers[i];
        traction.points.emplace_back(pairs[i].slave_location[0], -lambda / pairs[i].weight);
        tension = std::max(tension, lambda);
      }
    std::sort(traction.points.begin(), traction.points.end());
    if (pressure_norm)
      *pressure_norm = problem->last_state().constraint_responses[0];
    return compliance;
  }

  void
  part_on_support(const unsigned int n_cells)
  {
    std::cout << "Part 2: a bracket on a support, " << n_cells << " Voronoi cells, k = 1, MMA" << std::endl;
    const PartOnSupport setup(n_cells);
    const auto          tied       = design(setup, ContactSettings::Normal::tied, "tied (bonded)");
    const auto          unilateral = design(setup, ContactSettings::Normal::unilateral, "unilateral");

    // each design with its own interface model (the traction picture), and
    // the tied design resting on the block, as it will be built
    SVGPlots::Series t_tied, t_unilateral, ignored;
    t_tied.name       = "bonded design, bonded";
    t_unilateral.name = "resting design, resting";
    double       tension_tied = 0, tension_unilateral = 0, tension_ignored = 0;
    analyse(setup, tied.densities, ContactSettings::Normal::tied, t_tied, tension_tied);
    const double c_unilateral =
      analyse(setup, unilateral.densities, ContactSettings::Normal::unilateral, t_unilateral, tension_unilateral);
    const double c_tied =
      analyse(setup, tied.densities, ContactSettings::Normal::unilateral, ignored, tension_ignored);
    t_tied.marker_radius = t_unilateral.marker_radius = 2;
    SVGPlots::write_line_plot("step-13-traction.svg", {t_tied, t_unilateral}, "x",
                              "normal traction on the block (> 0: pressure)",
                              "step-13: the interface of the two designs");
    unsigned int n_differ = 0, n_design = 0;
    for (unsigned int c = 0; c < tied.densities.size(); ++c)
      if (setup.mesh.cell(c).material_id == 0)
        {
          ++n_design;
          n_differ += (std::abs(tied.densities[c] - unilateral.densities[c]) > 0.5);
        }
    std::cout << "   under unilateral contact: compliance of the tied design " << c_tied
              << ", of the unilateral design " << c_unilateral << " (ratio " << c_tied / c_unilateral << ")"
              << std::endl
              << "   largest tensile multiplier: bonded design bonded " << tension_tied
              << ", resting design resting " << tension_unilateral << std::endl
              << "   the designs differ (|rho_t - rho_u| > 0.5) in " << n_differ << " of " << n_design << " cells"
              << std::endl;
    Design::write_density_svg("step-13-tied.svg", setup.mesh, tied.densities,
                              "step-13: designed bonded to the support");
    Design::write_density_svg("step-13-unilateral.svg", setup.mesh, unilateral.densities,
                              "step-13: designed resting on the support");

    AssertThrow(c_unilateral < 0.98 * c_tied,
                dealii::ExcMessage("The contact-aware design is not stiffer under unilateral contact than the "
                                   "bonded design."));
    AssertThrow(tension_tied > 0, dealii::ExcMessage("The bonded design does not pull on its support."));
    AssertThrow(tension_unilateral <= 0, dealii::ExcMessage("The resting design pulls on its support."));
    AssertThrow(n_differ >= 0.05 * n_design, dealii::ExcMessage("The two designs do not differ."));
  }

  // @sect3{Part 3: a bound on the contact pressure}
  //
  // The bracket pushed down instead (the load reversed) rests on the block
  // and carries the load into it, over a short stretch of the interface
  // below the load. Designed again with its largest contact pressure (the
  // 8-norm of the pair pressures, an MMA constraint beside the volume, its
  // gradient by the adjoint of the converged contact problem, which reuses
  // the state's factorization) at most half of the unconstrained design's,
  // it must spread the contact, at some cost in stiffness.
  void
  pressure_bound(const unsigned int n_cells)
  {
    const PartOnSupport setup(n_cells);
    std::cout << "Part 3: the bracket pushed down onto the support, " << n_cells << " Voronoi cells" << std::endl;
    const auto       free = design(setup, ContactSettings::Normal::unilateral, "unbounded", 0, true);
    SVGPlots::Series t_free, t_bounded;
    double           tension_free = 0, tension_bounded = 0, p_free = 0, p_bounded = 0;
    const double     c_free =
      analyse(setup, free.densities, ContactSettings::Normal::unilateral, t_free, tension_free, &p_free, true);
    const double bound = 0.7 * p_free;
    std::cout << "   largest pressure (8-norm) " << p_free << "; designed again with it at most " << bound
              << std::endl;
    const auto bounded = design(setup, ContactSettings::Normal::unilateral, "pressure-bounded", bound, true);
    const double c_bounded = analyse(setup, bounded.densities, ContactSettings::Normal::unilateral, t_bounded,
                                     tension_bounded, &p_bounded, true);
    double peak_free = 0, peak_bounded = 0;
    for (const auto &q : t_free.points)
      peak_free = std::max(peak_free, q.second);
    for (const auto &q : t_bounded.points)
      peak_bounded = std::max(peak_bounded, q.second);
    std::cout << "   pressure 8-norm " << p_bounded << " (bound " << bound << "), largest pair pressure "
              << peak_bounded << " against " << peak_free << " unbounded; compliance " << c_bounded << " against "
              << c_free << " (ratio " << c_bounded / c_free << ")" << std::endl;
    t_free.name    = "unbounded design";
    t_bounded.name = "pressure-bounded design";
    t_free.marker_radius = t_bounded.marker_radius = 2;
    SVGPlots::write_line_plot("step-13-pressure.svg", {t_free, t_bounded}, "x",
                              "normal traction on the block (> 0: pressure)",
                              "step-13: pushed down, with and without a pressure bound");
    Design::write_density_svg("step-13-pushed.svg", setup.mesh, free.densities,
                              "step-13: pushed down onto the support");
    Design::write_density_svg("step-13-bounded.svg", setup.mesh, bounded.densities,
                              "step-13: pushed down, contact pressure bounded");
    AssertThrow(p_free > 0, dealii::ExcMessage("The bracket pushed down does not press on its support."));
    AssertThrow(p_bounded <= 1.01 * bound,
                dealii::ExcMessage("The pressure-bounded design violates its bound by more than 1 %."));
    AssertThrow(peak_bounded < 0.75 * peak_free,
                dealii::ExcMessage("The pressure-bounded design does not lower the largest pair pressure."));
    AssertThrow(c_bounded >= 0.98 * c_free,
                dealii::ExcMessage("The pressure-bounded design is stiffer than the unbounded one: the unbounded "
                                   "optimization stopped far from its optimum."));
  }
} // namespace Step13


// @sect3{The main function}
int
main(int argc, char **argv)
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const bool fine = (argc == 2 && std::strcmp(argv[1], "--fine") == 0);
      if (argc > 2 || (argc == 2 && !fine))
        {
          std::cerr << "step-13: " << (argc > 2 ? std::string("too many arguments") :
                                                  "unknown argument '" + std::string(argv[1]) + "'")
                    << ".\nusage: step-13 [--fine]   (--fine: 1536 and 3200 cells instead of 384 and 800)"
                    << std::endl;
          return 2;
        }
      Step13::mbb(fine ? 1536 : 384);
      Step13::part_on_support(fine ? 3200 : 800);
      Step13::pressure_bound(fine ? 3200 : 800);
    }
  catch (std::exception &exc)
    {
      std::cerr << std::endl
                << "----------------------------------------------------" << std::endl
                << "Exception on processing: " << std::endl
                << exc.what() << std::endl
                << "Aborting!" << std::endl
                << "----------------------------------------------------" << std::endl;
      return 1;
    }
  return 0;
}
