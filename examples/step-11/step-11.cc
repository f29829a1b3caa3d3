// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// step-11: ironing, contact with finite sliding.
//
// Build (from a dealvem build directory):   make step-11
// Run:                                      ./examples/step-11 [--study] [--write-doc-picture]
// What it does: a stiff rounded die (a half disk of radius 1, a polygon of
// 16 sides, E = 1000) is pressed 0.2 into a soft Neo-Hooke slab (8 x 1,
// 64 x 8 squares, E = 1, nu = 0.3) and then slid along it by 1, eight
// element lengths of the slab, the setup of the ironing benchmarks of
// Yang, Laursen and Meng (2005) and Puso and Laursen (2004) at the scale
// of this slab. FiniteSliding makes the node pairs again in the current
// configuration at every step (node insertion where the die now stands,
// a vertex of the slab moved along its straight top where it faces a
// corner of the die), so the die slides over the slab's nodes. Two runs:
// frictionless and Coulomb friction mu = 0.3.
// Output: the force of the slab on the die at every step
// (ironing-history.csv, and the SVG plots ironing-horizontal.svg and
// ironing-vertical.svg), one VTU file per step with a .pvd
// (ParaView plays ironing.pvd as a time series; the mesh of each file is
// that step's, with its inserted nodes), and the table of the checks:
// - frictionless: the horizontal force averages to zero over the slide
//   (an elastic slab without friction does not resist steady sliding):
//   |mean Fx| / mean Fy <= 0.01;
// - frictionless: the vertical force oscillates by at most 2 % of its
//   mean as the die passes the slab's nodes;
// - energy: at the end of the press, the work of the die equals the
//   stored energy to 2 % (the trapezoidal rule over four steps);
// - with friction: once the die slides steadily, every active pair slips
//   (Coulomb's law in steady sliding: the friction multiplier of each pair
//   is mu times its normal one), and the horizontal force opposes the
//   slide;
// - with friction: work of the die = stored energy + friction dissipation
//   (the balance of every step is in the CSV file) to 5 % of the work;
// - the whole slide in one step is cut back and ends with the force of the
//   40-step run; pressed to 0.25 the run completes, with the same checks
//   of the force's direction and the balance.
// The program exits with an error if a check fails.
// --study repeats the friction run at 10, 20, 40 and 80 steps per unit
// slide, with the die refined once more, on a slab of 128 x 16 squares,
// with both refined (the remainder of the slide's balance must stay below
// 1 % and the frictionless mean horizontal force below 1e-3 F_y on both),
// and pressed to 0.3 (the balance must hold to 5 % in each; the steps
// where a pair in contact sticks are counted);
// --write-doc-picture writes the SVG into doc/ of the source tree.

// @sect3{Include files}
//
// deal.II for the die's mesh (a half disk refined with its circle); dealvem
// for the meshes, the hyperelastic laws, FiniteSliding (node insertion in
// the current configuration, the semismooth Newton solver of each step)
// and the output.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <dealvem/contact/finite_sliding.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/polygonal_mesh.h>
#include <dealvem/postprocessing/finite_strain_output.h>
#include <dealvem/postprocessing/svg_plots.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace Step11
{
  using namespace dealvem;

  // @sect3{The problem}
  //
  // The slab occupies [0, 8] x [0, 1]; its bottom (boundary id 2 of the
  // structured mesh) is clamped, its top (id 3) is the master side of the
  // contact. The die is a half disk of radius 1 centred at (1.5, 2), its
  // flat side up: its curved side (id 10) is the slave side, its flat side
  // (id 11) follows the prescribed motion: down by the depth during the
  // press (time 0 to 1), then along x by the slide (time 1 to 2).
  struct Ironing
  {
    unsigned int degree       = 1;
    unsigned int die_refine   = 2;
    unsigned int slab_cells   = 64; // along the slab; an eighth of it across
    double       mu           = 0.3;
    double       depth        = 0.2;
    double       slide        = 1.0;
    unsigned int press_steps  = 4;
    unsigned int slide_steps  = 40;
    double       E_slab       = 1.0;
    double       E_die        = 1000.0;
    double       nu           = 0.3;
    double       tolerance    = 1e-5;
    unsigned int max_cutbacks = 4;
    dealii::Point<2> centre   = dealii::Point<2>(1.5, 2.0);

    // the motion of the die's top at time t
    dealii::Tensor<1, 2>
    motion(const double t) const
    {
      dealii::Tensor<1, 2> d;
      d[1] = -depth * std::min(t, 1.0);
      d[0] = slide * std::max(0.0, t - 1.0);
      return d;
    }
  };

  // The state after one step: the time, the die's displacement, the force
  // of the slab on the die (the contact force on the die's side), the
  // pairing passes and Newton updates, and the energy: the work of the die
  // so far (trapezoidal rule), the stored energy, the dissipation so far.
  struct StepState
  {
    double               t = 0;
    dealii::Tensor<1, 2> d, force;
    unsigned int         passes = 0, updates = 0, moved = 0, n_dofs = 0, sticking = 0, substeps = 0;
    double               offset = 0, work = 0, stored = 0, dissipated = 0;
  };

  struct Run
  {
    Ironing                problem;
    std::vector<StepState> steps;
    double                 setup_time = 0, solve_time = 0;

    // the steps of the slide after its first quarter (the transient as
    // the die starts to move)
    std::vector<const StepState *>
    steady() const
    {
      std::vector<const StepState *> s;
      for (const auto &st : steps)
        if (st.t >= 1.25)
          s.push_back(&st);
      return s;
    }
    double
    mean(const unsigned int comp) const
    {
      double sum = 0;
      for (const auto *s : steady())
        sum += s->force[comp];
      return sum / steady().size();
    }
    double
    range(const unsigned int comp) const
    {
      double lo = 1e300, hi = -1e300;
      for (const auto *s : steady())
        {
          lo = std::min(lo, s->force[comp]);
          hi = std::max(hi, s->force[comp]);
        }
      return hi - lo;
    }
    // the energy remainder W - E - D over the work W at the end
    double
    remainder() const
    {
      const auto &s = steps.back();
      return (s.work - s.stored - s.dissipated) / s.work;
    }
    // the same over the slide alone, from the end of the press: the press
    // adds the trapezoidal rule's error over its few steps, the slide the
    // error of carrying the state from mesh to mesh
    double
    slide_remainder() const
    {
      const StepState *press = nullptr;
      for (const auto &st : steps)
        if (st.t <= 1.0 + 1e-12)
          press = &st;
      AssertThrow(press != nullptr, dealii::ExcInternalError());
      const auto  &s    = steps.back();
      const double work = s.work - press->work;
      return (work - (s.stored - press->stored) - (s.dissipated - press->dissipated)) / work;
    }
  };

  // @sect3{The meshes}
  //
  // One PolygonalMesh holds both bodies: the slab as structured squares and
  // the die from a deal.II half disk, refined with a SphericalManifold on
  // its circle so that its boundary vertices lie on the circle. Material
  // id 0 is the slab, 1 the die; the die's boundary ids are shifted by 10.
  void
  make_mesh(const Ironing &p, PolygonalMesh<2> &mesh)
  {
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(8, 1), p.slab_cells,
                                              p.slab_cells / 8);
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::half_hyper_ball(tria, dealii::Point<2>(), 1.0);
    dealii::GridTools::rotate(-M_PI / 2, tria);
    dealii::GridTools::shift(dealii::Tensor<1, 2>(p.centre), tria);
    tria.reset_all_manifolds();
    tria.set_all_manifold_ids(dealii::numbers::flat_manifold_id);
    tria.set_all_manifold_ids_on_boundary(0, 1);
    const dealii::SphericalManifold<2> circle(p.centre);
    tria.set_manifold(1, circle);
    tria.refine_global(p.die_refine);
    PolygonalMesh<2> die;
    PolygonalMeshGenerators::from_triangulation(die, tria);
    for (unsigned int c = 0; c < die.n_cells(); ++c)
      die.set_material_id(c, 1);
    for (unsigned int e = 0; e < die.n_edges(); ++e)
      if (die.edge(e).at_boundary())
        die.set_edge_boundary_id(e, die.edge(e).boundary_id + 10);
    mesh.append(die);
  }

  // @sect3{One run}
  //
  // FiniteSliding gets the original mesh, the laws, the interface (the
  // slab's top as master, the die's circle as slave) and its settings; the
  // constraints function clamps the slab's bottom and moves the die's top
  // at the time of each step, on the mesh of that step (its DoFs change
  // from step to step as nodes are inserted and removed).
  Run
  iron(const Ironing &p, const std::string &output_prefix)
  {
    PolygonalMesh<2> mesh;
    make_mesh(p, mesh);
    const NeoHookeMaterial slab_law(p.E_slab, p.nu), die_law(p.E_die, p.nu);
    MaterialLibrary<2>     laws;
    laws.add(0, slab_law);
    laws.add(1, die_law);
    FiniteSliding::Parameters parameters;
    parameters.degree             = p.degree;
    parameters.pairing_tolerance  = p.tolerance;
    parameters.max_pairing_passes = 30;
    parameters.max_cutbacks       = p.max_cutbacks;
    FiniteSliding sliding(mesh, laws, {FiniteSliding::InterfaceData{3, 10, p.mu}}, parameters);
    sliding.set_constraints_function(
      [&p](const VEMDoFHandler<2> &dofs, const double t, dealii::AffineConstraints<double> &c) {
        const auto &m = dofs.get_mesh();
        const auto  d = p.motion(t);
        for (unsigned int e = 0; e < m.n_edges(); ++e)
          {
            const auto &edge = m.edge(e);
            if (!edge.at_boundary() || (edge.boundary_id != 2 && edge.boundary_id != 11))
              continue;
            std::vector<unsigned int> nodes = {dofs.vertex_node(edge.vertices[0]),
                                               dofs.vertex_node(edge.vertices[1])};
            if (dofs.get_degree() == 2)
              nodes.push_back(dofs.edge_node(e));
            for (const unsigned int node : nodes)
              for (unsigned int comp = 0; comp < 2; ++comp)
                {
                  const auto dof = VEMDoFHandler<2>::node_dof(node, comp);
                  if (c.is_constrained(dof))
                    continue;
                  c.add_line(dof);
                  c.set_inhomogeneity(dof, edge.boundary_id == 2 ? 0. : d[comp]);
                }
          }
        c.close();
      });

    Run run;
    run.problem = p;
    std::vector<std::pair<double, std::string>> series;
    StepState                                   last;
    const unsigned int                          n = p.press_steps + p.slide_steps;
    for (unsigned int step = 1; step <= n; ++step)
      {
        const double t = step <= p.press_steps ? double(step) / p.press_steps :
                                                 1.0 + double(step - p.press_steps) / p.slide_steps;
        sliding.solve_step(step, t);
        const auto &r = sliding.get_history().back();

        // The contact force on the die (the slave side) is the force of the
        // slab on the die: Fy > 0 resists the press, Fx < 0 the slide. The
        // die's top balances it, so the prescribed motion does the work of
        // minus that force.
        StepState s;
        s.t     = t;
        s.d     = p.motion(t);
        s.force = r.normal_force[0] + r.friction_force[0];
        s.passes = r.n_passes;
        for (const auto &newton : r.newton)
          s.updates += newton.iterations.size() - 1;
        s.moved      = r.n_moved;
        s.sticking   = r.n_sticking_in_contact;
        s.substeps   = r.n_substeps;
        s.n_dofs     = r.n_dofs;
        s.offset     = r.pairing_offset;
        s.work       = last.work - 0.5 * (s.force + last.force) * (s.d - last.d);
        s.stored     = sliding.strain_energy();
        s.dissipated = last.dissipated + r.dissipation;
        run.setup_time += r.setup_time;
        run.solve_time += r.solve_time;
        run.steps.push_back(s);
        last = s;

        if (!output_prefix.empty())
          {
            std::ostringstream name;
            name << output_prefix << "-" << std::setw(3) << std::setfill('0') << step << ".vtu";
            write_finite_strain_vtu_file(name.str(), sliding.get_dof_handler(), laws, sliding.get_solution());
            series.emplace_back(t, name.str());
          }
      }
    if (!output_prefix.empty())
      write_pvd_record(output_prefix + ".pvd", series);
    return run;
  }

  void
  check(const bool condition, const std::string &message, std::vector<std::string> &failures)
  {
    if (!condition)
      failures.push_back(message);
  }

  void
  print_summary(const std::string &name, const Run &run)
  {
    const double Fy = run.mean(1);
    unsigned int passes = 0, updates = 0, max_passes = 0, moved = 0;
    for (const auto &s : run.steps)
      {
        passes += s.passes;
        updates += s.updates;
        max_passes = std::max(max_passes, s.passes);
        moved += (s.moved > 0);
      }
    const auto nst = run.steps.size();
    std::cout << std::fixed << std::setprecision(4) << name << ": " << run.problem.slide_steps
              << " slide steps; over the slide Fy = " << Fy << " (oscillation " << std::setprecision(2)
              << 100 * run.range(1) / Fy << " %), Fx/Fy = " << std::setprecision(4) << run.mean(0) / Fy
              << " (oscillation " << std::setprecision(2) << 100 * run.range(0) / Fy << " % of Fy); "
              << std::setprecision(1) << double(passes) / nst << " pairing passes and " << double(updates) / nst
              << " Newton updates per step (at most " << max_passes << "), a slab vertex moved to face a die corner in "
              << moved << " of " << nst << " steps; energy: W = " << std::setprecision(5) << run.steps.back().work
              << ", E = " << run.steps.back().stored << ", D = " << run.steps.back().dissipated
              << ", (W - E - D)/W = " << std::setprecision(4) << run.remainder();
    if (run.problem.mu > 0)
      std::cout << ", over the slide alone " << run.slide_remainder();
    std::cout << std::endl;
  }

  // The force history as two SVG plots over the die's slide: the
  // horizontal force and the vertical one, each over the mean vertical
  // force of its run.
  void
  write_svg(const std::vector<const Run *> &runs, const std::vector<std::string> &names, const std::string &prefix)
  {
    for (const unsigned int comp : {0u, 1u})
      {
        std::vector<SVGPlots::Series> series;
        for (unsigned int i = 0; i < runs.size(); ++i)
          {
            SVGPlots::Series f;
            f.name          = names[i];
            f.marker_radius = 2;
            const double Fy = runs[i]->mean(1);
            for (const auto &s : runs[i]->steps)
              if (s.t >= 1.0)
                f.points.emplace_back(s.d[0], s.force[comp] / Fy);
            series.push_back(f);
          }
        SVGPlots::write_line_plot(prefix + (comp == 0 ? "-horizontal.svg" : "-vertical.svg"), series,
                                  "slide of the die",
                                  comp == 0 ? "Fx / mean Fy" : "Fy / mean Fy",
                                  comp == 0 ? "Ironing: horizontal force of the slab on the die (step-11)" :
                                              "Ironing: vertical force of the slab on the die (step-11)");
      }
  }
} // namespace Step11


// @sect3{The main function}
int
main(int argc, char **argv)
{
  using namespace Step11;
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      bool                                     study = false, doc_picture = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string a = argv[i];
          if (a == "--study")
            study = true;
          else if (a == "--write-doc-picture")
            doc_picture = true;
          else
            {
              std::cerr << "usage: step-11 [--study] [--write-doc-picture]" << std::endl;
              return 2;
            }
        }
      std::vector<std::string> failures;

      // The frictionless run: 20 slide steps (0.4 of a slab element each).
      Ironing frictionless;
      frictionless.mu          = 0;
      frictionless.slide_steps = 20;
      const Run free_run = iron(frictionless, "");
      print_summary("frictionless", free_run);
      const double Fy0 = free_run.mean(1);
      check(std::abs(free_run.mean(0)) <= 0.01 * Fy0,
            "frictionless: the mean horizontal force is not below 1 % of the vertical force", failures);
      check(free_run.range(1) <= 0.02 * Fy0,
            "frictionless: the vertical force oscillates by more than 2 % of its mean", failures);
      {
        const auto &end_of_press = free_run.steps[frictionless.press_steps - 1];
        check(std::abs(end_of_press.work - end_of_press.stored) <= 0.02 * end_of_press.work,
              "frictionless: at the end of the press, the work of the die and the stored energy differ by more "
              "than 2 %",
              failures);
      }

      // The run with friction, 40 slide steps, written as VTU files.
      const Ironing friction;
      const Run     friction_run = iron(friction, "ironing");
      print_summary("mu = 0.3", friction_run);
      // Once the die slides steadily, every point under it slips: Coulomb's
      // law then fixes the friction multiplier of every active pair to mu
      // times its normal one. (A pair whose contact begins within a step
      // counts its slip from where that step's first pass paired it, so it
      // sticks in that step: StepRecord::n_sticking_in_contact leaves those
      // out.) The horizontal force opposes the slide.
      {
        unsigned int sticking = 0;
        for (const auto *s : friction_run.steady())
          sticking += s->sticking;
        check(sticking == 0,
              "with friction: " + std::to_string(sticking) + " active pairs stick during the steady slide",
              failures);
      }
      check(friction_run.mean(0) < 0, "with friction: the horizontal force does not oppose the slide", failures);
      check(std::abs(friction_run.remainder()) <= 0.05,
            "with friction: work - stored energy - dissipation is not within 5 % of the work", failures);
      // The whole slide in one step: FiniteSliding cuts a step whose
      // pairing or Newton solve fails into halves (Parameters::
      // max_cutbacks). Steady sliding with full slip forgets its path, so
      // the die ends with the force of the 40-step run. Without cutbacks
      // the step fails (the slab's cells under the die invert in the first
      // Newton solve, whose pairs are those of the start) and says so.
      {
        Ironing one     = friction;
        one.slide_steps = 1;
        const Run  r    = iron(one, "");
        const auto &end = r.steps.back();
        std::cout << "the slide in one step: " << end.substeps << " sub-steps, " << end.passes
                  << " pairing passes; force at the end " << end.force << " against " << friction_run.steps.back().force
                  << " after 40 steps" << std::endl;
        check(end.substeps > 1, "one-step slide: the step was not cut back", failures);
        check((end.force - friction_run.steps.back().force).norm() <= 1e-4 * end.force.norm(),
              "one-step slide: the force at the end differs from the 40-step run's by more than 1e-4", failures);
        one.max_cutbacks = 0;
        bool failed      = false;
        try
          {
            iron(one, "");
          }
        catch (const dealii::ExceptionBase &)
          {
            failed = true;
          }
        check(failed, "one-step slide without cutbacks: the step did not fail", failures);
      }
      // Pressed deeper, to 0.25 (five press steps): the slab bulges ahead of
      // the die and its vertices face die corners at other places. The
      // pairing passes stalled there (offsets of 1e-3 in sub-steps of 1/16,
      // step 30) until they got a safeguard: where the residual grows, the
      // Anderson history starts again with a half step (FiniteSliding,
      // "Pairing passes" in doc/architecture.md).
      {
        Ironing deeper     = friction;
        deeper.depth       = 0.25;
        deeper.press_steps = 5;
        const Run r        = iron(deeper, "");
        print_summary("mu = 0.3, pressed to 0.25", r);
        check(r.mean(0) < 0, "pressed to 0.25: the horizontal force does not oppose the slide", failures);
        check(std::abs(r.remainder()) <= 0.05,
              "pressed to 0.25: work - stored energy - dissipation is not within 5 % of the work", failures);
      }
      {
        std::ofstream csv("ironing-history.csv");
        csv << "mu,step,t,die_x,die_y,Fx,Fy,passes,newton_updates,moved_vertices,pairing_offset,substeps,work,stored,"
               "dissipated,work_minus_stored_minus_dissipated\n";
        for (const auto *run : {&free_run, &friction_run})
          for (unsigned int i = 0; i < run->steps.size(); ++i)
            {
              const auto &s = run->steps[i];
              csv << std::setprecision(10) << run->problem.mu << "," << i + 1 << "," << s.t << "," << s.d[0] << ","
                  << s.d[1] << "," << s.force[0] << "," << s.force[1] << "," << s.passes << "," << s.updates << ","
                  << s.moved << "," << s.offset << "," << s.substeps << "," << s.work << "," << s.stored << ","
                  << s.dissipated << ","
                  << s.work - s.stored - s.dissipated << "\n";
            }
      }
      std::cout << "time: pairing and set-up " << std::setprecision(1) << friction_run.setup_time
                << " s, Newton solves " << friction_run.solve_time << " s (the run with friction)" << std::endl;

      if (study)
        {
          std::cout << "\nStudy: mu = 0.3 and the step size\n"
                    << "  steps per unit slide | die refined | slab | Fx/Fy   | Fy oscillation | (W - E - D)/W | steps "
                       "with a pair in contact sticking | the slide's (W - E - D)/W\n";
          // every run: the balance to 5 %; the pairs in contact since the
          // start of a step that stick in the steady slide are counted (at
          // small steps the die's lowest corner, which carries about 1.4
          // times the pressure of its neighbours, sticks for a few steps
          // each time it passes a slab element: a stick-slip of the
          // discrete geometry)
          const auto study_run = [&](const Ironing &p) {
            const Run    r        = iron(p, "");
            unsigned int sticking = 0;
            for (const auto *st : r.steady())
              sticking += (st->sticking > 0);
            std::cout << "  " << std::setw(20) << p.slide_steps << " | " << std::setw(11) << p.die_refine << " | "
                      << std::setw(4) << p.slab_cells << " | " << std::setprecision(4) << r.mean(0) / r.mean(1)
                      << " | " << std::setw(12) << std::setprecision(2) << 100 * r.range(1) / r.mean(1) << " % | "
                      << std::setprecision(4) << r.remainder() << " | " << sticking << " of " << r.steady().size()
                      << " | " << r.slide_remainder() << std::endl;
            const std::string what = "study (" + std::to_string(p.slide_steps) + " steps, die refined " +
                                     std::to_string(p.die_refine) + ", slab " + std::to_string(p.slab_cells) + "): ";
            check(std::abs(r.remainder()) <= 0.05,
                  what + "work - stored energy - dissipation is not within 5 % of the work", failures);
            return r.slide_remainder();
          };
          double base = 0;
          for (const unsigned int steps : {10u, 20u, 40u, 80u})
            {
              Ironing p     = friction;
              p.slide_steps = steps;
              const double r = study_run(p);
              if (steps == friction.slide_steps)
                base = r;
            }
          // the die refined once more, then the slab (128 x 16 squares)
          Ironing p    = friction;
          p.die_refine = 3;
          study_run(p);
          p.die_refine = 2;
          p.slab_cells = 128;
          study_run(p);
          // Both meshes refined, at the same fraction of a slab element per
          // step (0.2): the remainder of the slide is the error of carrying
          // the state from mesh to mesh (a slab vertex moved to face a die
          // corner and back, an inserted node removed; neither keeps the
          // trace it replaces). With the die's inserted nodes on its arcs
          // (issue 36) it is a few 1e-3 of the slide's work on both meshes
          // (measured 0.0015 and 0.0046; before, on the die's chords, 0.034
          // and 0.011): asserted below 1 % on both.
          p.die_refine  = 3;
          p.slide_steps = 2 * friction.slide_steps;
          const double refined = study_run(p);
          check(std::abs(base) <= 0.01 && std::abs(refined) <= 0.01,
                "study: the remainder of the slide is not below 1 % of its work on both meshes", failures);
          // The same without friction: the mean horizontal force, which is
          // what the energy balance of a frictionless slide leaves over, is
          // zero to the meshes' error on both (measured below 5e-5 and
          // 2e-4 of F_y; 0.0041 and 0.0005 on the die's chords): asserted
          // below 1e-3 of F_y on both.
          Ironing q     = frictionless;
          q.die_refine  = 3;
          q.slab_cells  = 128;
          q.slide_steps = 2 * frictionless.slide_steps;
          const Run fine = iron(q, "");
          print_summary("frictionless, both meshes refined", fine);
          check(std::abs(fine.mean(0) / fine.mean(1)) <= 1e-3 && std::abs(free_run.mean(0) / free_run.mean(1)) <= 1e-3,
                "study: the mean horizontal force without friction is not below 1e-3 of the vertical one on both "
                "meshes",
                failures);
          // Pressed to 0.3 (six press steps): three slab vertices face die
          // corners at once; steps are cut back, and pairs in contact stick
          // in some of the small sub-steps (as at 80 steps per unit slide)
          Ironing deepest     = friction;
          deepest.depth       = 0.3;
          deepest.press_steps = 6;
          study_run(deepest);
        }

      const std::string picture =
        doc_picture ? (std::filesystem::path(__FILE__).parent_path() / "doc" / "ironing").string() :
                      std::string("ironing");
      write_svg({&free_run, &friction_run}, {"frictionless", "mu = 0.3"}, picture);
      std::cout << "pictures: " << picture << "-horizontal.svg, " << picture
                << "-vertical.svg; ParaView: ironing.pvd; history: ironing-history.csv" << std::endl;

      for (const auto &m : failures)
        std::cerr << "step-11 check failed: " << m << std::endl;
      return failures.empty() ? 0 : 1;
    }
  catch (std::exception &exc)
    {
      std::cerr << std::endl << "Exception: " << exc.what() << std::endl;
      return 1;
    }
}
