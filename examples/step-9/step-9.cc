// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// step-9: a mortise-and-tenon joint with an interference fit, pulled apart.
//
// Build (from a dealvem build directory):   make step-9
// Run:                                      ./examples/step-9 [--study] [--write-doc-picture]
// What it does: a post [0,3] x [-3,3], clamped at its top and bottom, has a
// blind mortise (a slot [1,3] x [-1/2,1/2] open to the right); a tenon
// [1.2,5] x [-1/2-delta, 1/2+delta] sits in it, delta = 1e-3 wider on each
// side than the slot (an interference fit: the two meshes overlap by delta
// in the reference configuration) and 0.2 short of the slot's bottom. The
// two meshes are deal.II grids of squares of different sizes (0.25 and
// 0.2): they do not match along the cheeks. ContactDetection finds the two
// cheek interfaces (and nothing at the bottom of the slot, 0.2 away); node
// insertion pairs the overlapping sides, Coulomb friction acts on them.
// Load step 1 only closes the interference (the tenon's end is held in
// place); then the end is pulled out by equal increments of displacement,
// until the tenon slides: the pull-out force, the normal force of the
// interference, and the friction law between them. A second run pulls by a
// force instead: just below the pull-out force the joint must hold, just
// above it the solver must say "No static equilibrium".
// The program exits with an error if a check fails (see the results).
// --study adds k = 1, nu = 0 and more friction coefficients;
// --write-doc-picture writes the pull-out curves into doc/.

// @sect3{Include files}
#include <deal.II/base/exceptions.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/elasticity/material.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace Step9
{
  using namespace dealvem;
  using Point = dealii::Point<2>;

  // @sect3{The data}
  //
  // Lengths in units of the tenon's width, stresses in units of the
  // modulus / 1000. The problem is linear in the interference as long as
  // the set of closed pairs does not change (small displacements, straight
  // cheeks): every force below is proportional to $E\,\delta$, and the
  // friction law is what decides whether the tenon moves.
  struct Joint
  {
    double       delta  = 1e-3; // interference on each cheek
    double       mu     = 0.3;  // friction coefficient
    double       nu     = 0.3;  // Poisson's ratio of both parts
    double       E      = 1000; // Young's modulus of both parts
    unsigned int degree = 2;    // order k of the virtual elements
    unsigned int refine = 1;    // the cells of both grids are 1 / refine times as large

    // the pull, per load step, that takes the tenon well into sliding: the
    // elastic stretch of the tenon at the pull-out force is about
    // mu * (E delta) * 1.8 * 2 / E * 3.8 ~ 14 mu delta
    double
    pull_increment() const
    {
      return 6 * mu * delta;
    }
  };

  // The boundary ids: the post's clamped top and bottom, the rest of its
  // boundary (the faces that ContactDetection may pair), the tenon's end
  // (where it is pulled) and the rest of the tenon.
  constexpr dealii::types::boundary_id post_clamped = 1, post_free = 0, tenon_end = 12, tenon_free = 10;

  // @sect3{The meshes}
  //
  // The post: 12 x 24 squares of side 0.25, less the 8 x 4 of the slot
  // (GridGenerator::create_triangulation_with_removed_cells()). The tenon:
  // 19 x 5 cells, of length 0.2 along the cheeks. The study refines both
  // grids by the factor r = 2 and 4. Both grids are symmetric
  // about y = 0, so the two cheeks carry the same forces to round-off (a
  // check below).
  void
  make_post(dealii::Triangulation<2> &tria, const unsigned int r)
  {
    dealii::Triangulation<2> full;
    dealii::GridGenerator::subdivided_hyper_rectangle(full, {12 * r, 24 * r}, Point(0, -3), Point(3, 3));
    std::set<dealii::Triangulation<2>::active_cell_iterator> slot;
    for (const auto &cell : full.active_cell_iterators())
      if (cell->center()[0] > 1 && std::abs(cell->center()[1]) < 0.5)
        slot.insert(cell);
    dealii::GridGenerator::create_triangulation_with_removed_cells(full, slot, tria);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          cell->face(f)->set_boundary_id(std::abs(std::abs(cell->face(f)->center()[1]) - 3) < 1e-12 ? post_clamped :
                                                                                                      post_free);
  }

  void
  make_tenon(dealii::Triangulation<2> &tria, const double delta, const unsigned int r)
  {
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {19 * r, 5 * r}, Point(1.2, -0.5 - delta), Point(5, 0.5 + delta));
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          cell->face(f)->set_boundary_id(std::abs(cell->face(f)->center()[0] - 5) < 1e-12 ? tenon_end : tenon_free);
  }

  // @sect3{The loading}
  //
  // Load step n solves at the time t = n. Step 1 closes the interference
  // with the tenon's end held (the pull is zero); from step 2 on the end is
  // pulled, by $d\,(t-1)$ (displacement control) or by a traction whose
  // resultant is $F\,(t-1)/n_{pull}$ (force control).
  class Ramp : public dealii::Function<2>
  {
  public:
    Ramp(const double x_value, const double y_value)
      : dealii::Function<2>(2)
      , x_value(x_value)
      , y_value(y_value)
    {}

    double
    value(const Point &, const unsigned int component) const override
    {
      return std::max(get_time() - 1., 0.) * (component == 0 ? x_value : y_value);
    }

  private:
    const double x_value, y_value;
  };

  enum class Control
  {
    displacement,
    force
  };

  // @sect3{One run}
  //
  // ContactProblem from code, as in step-8; the two parts are deal.II
  // triangulations (add_body() turns the squares into polygons). The
  // options are those of a Coulomb problem with load steps; nothing is
  // written, the results stay in memory.
  ContactProblem::Results
  solve(const Joint &joint, const Control control, const double amount, const unsigned int n_pull)
  {
    dealii::Triangulation<2> post, tenon;
    make_post(post, joint.refine);
    make_tenon(tenon, joint.delta, joint.refine);
    const ElasticMaterial law(joint.E, joint.nu, ElasticMaterial::Model::plane_strain);

    ContactProblem problem(MPI_COMM_SELF);
    problem.add_body(post, law);
    problem.add_body(tenon, law);
    problem.detect_contact_pairs();

    auto &bc = problem.boundary_conditions();
    bc.add_dirichlet(post_clamped, {{true, true}}, std::make_shared<dealii::Functions::ZeroFunction<2>>(2),
                     "clamped top and bottom of the post");
    if (control == Control::displacement)
      bc.add_dirichlet(tenon_end, {{true, true}}, std::make_shared<Ramp>(amount, 0.), "pulled end of the tenon");
    else
      {
        // the end face is 1 + 2 delta high
        bc.add_dirichlet(tenon_end, {{false, true}}, std::make_shared<dealii::Functions::ZeroFunction<2>>(2),
                         "end of the tenon, held vertically");
        bc.add_traction(tenon_end, std::make_shared<Ramp>(amount / n_pull / (1 + 2 * joint.delta), 0.),
                        "pull on the end of the tenon");
      }

    auto &o                        = problem.options();
    o.degree                       = joint.degree;
    o.contact.normal               = ContactSettings::Normal::unilateral;
    o.contact.tangential           = ContactSettings::Tangential::coulomb;
    o.contact.friction_coefficient = joint.mu;
    o.n_load_steps                 = 1 + n_pull;
    o.final_time                   = 1 + n_pull;
    o.write_vtu = o.write_json = o.write_pictures = o.write_csv = false;

    std::ostringstream sink; // the report of run() is not shown
    std::streambuf    *old = std::cout.rdbuf(sink.rdbuf());
    try
      {
        problem.run();
      }
    catch (...)
      {
        std::cout.rdbuf(old);
        throw;
      }
    std::cout.rdbuf(old);
    return problem.get_results();
  }

  // @sect3{What a load step says}
  //
  // The tenon is body 1. Per step: the force that the post exerts on the
  // tenon through the cheeks (InterfaceResult::force acts on the slave side,
  // so it changes sign where the tenon is the master), the normal force of
  // each cheek, and the pairs closed, sticking and slipping. The pull-out
  // force is the x component of the force that holds the tenon back, which
  // the end's support carries: $F = -F_x$.
  struct State
  {
    double       pull_force = 0;  // F = -F_x(post on tenon)
    double       shear      = 0;  // F_y(post on tenon)
    double       N_upper = 0, N_lower = 0;
    unsigned int n_open = 0, n_stick = 0, n_slip = 0, iterations = 0;

    double
    N() const
    {
      return N_upper + N_lower;
    }
  };

  State
  state(const ContactProblem::StepResult &step)
  {
    State s;
    for (const auto &i : step.interfaces)
      {
        const double sign = (i.slave_body == 1) ? 1. : -1.;
        s.pull_force -= sign * i.force[0];
        s.shear += sign * i.force[1];
        (i.centre_of_pressure[1] > 0 ? s.N_upper : s.N_lower) += i.normal_force;
      }
    s.n_open     = step.n_open;
    s.n_stick    = step.n_stick;
    s.n_slip     = step.n_slip;
    s.iterations = step.iterations;
    return s;
  }

  void
  check(const bool condition, const std::string &message, std::vector<std::string> &failures)
  {
    if (!condition)
      failures.push_back(message);
  }

  // @sect3{The pull-out curve}
  //
  // One joint pulled out by displacement: the history of the force, and the
  // checks that the mechanics fixes.
  // - The two cheeks carry the same normal force, and the tenon no net
  //   vertical force (the grids are symmetric): to 1e-9 relative.
  // - Every body is in equilibrium in every step (the library's
  //   ForceBalance, which run() already enforces; asserted again here).
  // - Once every closed pair slips, the friction law holds pair by pair,
  //   so the pull-out force is $\mu$ times the normal force at that moment:
  //   $F = \mu N$ to 1e-10 relative.
  // - While the tenon slides, nothing changes: the force of the last two
  //   steps agree to 1e-9 relative (small sliding: the pairs keep their
  //   partners and the cheeks are straight).
  // - The interference step closes both cheeks with a normal force and
  //   leaves nothing open there: the slot's bottom, 0.2 away, is not paired.
  struct Curve
  {
    Joint              joint;
    std::vector<double> pull;   // end displacement per step
    std::vector<State> states;  // per step, states[0] the interference
    unsigned int       n_pairs = 0, n_dofs = 0, n_interfaces = 0;

    double
    N0() const
    {
      return states.front().N();
    }
    const State &
    sliding() const
    {
      return states.back();
    }
  };

  Curve
  pull_out(const Joint &joint, std::vector<std::string> &failures, const unsigned int n_pull = 6)
  {
    Curve c;
    c.joint      = joint;
    const auto r = solve(joint, Control::displacement, joint.pull_increment(), n_pull);
    c.n_pairs      = r.pairs.size();
    c.n_dofs       = r.n_dofs;
    c.n_interfaces = r.interface_results.size();
    for (const auto &step : r.steps)
      {
        c.pull.push_back(joint.pull_increment() * (step.time - 1));
        c.states.push_back(state(step));
        for (const auto &b : step.balance)
          check(b.imbalance <= b.tolerance && b.residual <= b.tolerance,
                "step " + std::to_string(step.step) + ": body " + std::to_string(b.body) + " is not in equilibrium",
                failures);
      }
    const std::string name = "k = " + std::to_string(joint.degree) + ", mu = " + std::to_string(joint.mu) +
                             ", nu = " + std::to_string(joint.nu) + ": ";
    check(c.n_interfaces == 2, name + std::to_string(c.n_interfaces) + " interfaces detected, not 2 (the cheeks)",
          failures);
    for (const State &s : c.states)
      {
        check(std::abs(s.N_upper - s.N_lower) <= 1e-9 * s.N() && std::abs(s.shear) <= 1e-9 * s.N(),
              name + "the two cheeks do not carry the same forces", failures);
      }
    const State &first = c.states.front(), &last = c.sliding(), &before = c.states[c.states.size() - 2];
    check(first.N() > 0 && first.n_open == 0, name + "the interference does not close both cheeks", failures);
    check(last.n_stick == 0 && last.n_slip > 0 && std::abs(last.pull_force - joint.mu * last.N()) <= 1e-10 * last.N(),
          name + "the sliding tenon does not satisfy F = mu N (F = " + std::to_string(last.pull_force) +
            ", mu N = " + std::to_string(joint.mu * last.N()) + ")",
          failures);
    check(std::abs(last.pull_force - before.pull_force) <= 1e-9 * last.pull_force,
          name + "the force changes while the tenon slides", failures);
    return c;
  }

  // @sect3{Force control: holds or slides out}
  //
  // The same joint pulled by a force F in n_pull equal increments: the
  // outcome is "holds" (every step converged, the last one with the tenon
  // held by friction) or the solver's "No static equilibrium" (the
  // FrictionSolver found that the loads need more friction than the
  // interfaces can give). Any other exception is an error of the program
  // and passed on.
  bool
  holds(const Joint &joint, const double F, std::string &message)
  {
    try
      {
        solve(joint, Control::force, F, 4);
        return true;
      }
    catch (const std::exception &exc)
      {
        const std::string what = exc.what();
        const auto        from = what.find("No static equilibrium");
        if (from == std::string::npos)
          throw;
        // its first sentence, on one line
        message.clear();
        for (std::size_t i = from; i < what.size() && (message.empty() || message.back() != '.'); ++i)
          if (!std::isspace(static_cast<unsigned char>(what[i])))
            message += what[i];
          else if (message.back() != ' ')
            message += ' ';
        return false;
      }
  }

  // @sect3{Output}
  void
  print_curve(const Curve &c)
  {
    std::cout << "  step | pull / delta | F / (E delta) | N / (E delta) |  F / (mu N) | pairs open/stick/slip | "
                 "iterations\n";
    const double Ed = c.joint.E * c.joint.delta;
    for (unsigned int i = 0; i < c.states.size(); ++i)
      {
        const State &s = c.states[i];
        std::cout << std::setw(6) << i + 1 << " | " << std::fixed << std::setprecision(3) << std::setw(12)
                  << c.pull[i] / c.joint.delta << " | " << std::setprecision(5) << std::setw(13)
                  << s.pull_force / Ed << " | " << std::setw(13) << s.N() / Ed << " | " << std::setw(11)
                  << s.pull_force / (c.joint.mu * s.N()) << " | " << std::setw(21)
                  << (std::to_string(s.n_open) + "/" + std::to_string(s.n_stick) + "/" + std::to_string(s.n_slip))
                  << " | " << std::setw(10) << s.iterations << std::endl;
      }
  }

  // The pull-out curves of several friction coefficients: the force over
  // mu, F / (mu E delta), against the pull over mu, d / (mu delta) (the
  // stick phase of every curve then has about the same length), each with
  // its N0 / (E delta) dashed: Coulomb's estimate of the plateau.
  void
  write_svg(const std::vector<Curve> &curves, const std::string &filename)
  {
    double f_min = 0, f_max = 0, d_max = 0;
    auto   x_of  = [](const Curve &c, const unsigned int i) { return c.pull[i] / (c.joint.mu * c.joint.delta); };
    auto   y_of  = [](const Curve &c, const double F) { return F / (c.joint.mu * c.joint.E * c.joint.delta); };
    for (const Curve &c : curves)
      for (unsigned int i = 0; i < c.states.size(); ++i)
        {
          f_min = std::min(f_min, y_of(c, c.states[i].pull_force));
          f_max = std::max({f_max, y_of(c, c.states[i].pull_force), y_of(c, c.joint.mu * c.N0())});
          d_max = std::max(d_max, x_of(c, i));
        }
    f_max *= 1.1;
    const double  w = 480, h = 300, x0 = 70, y0 = 20;
    auto          X = [&](const double d) { return x0 + w * d / d_max; };
    auto          Y = [&](const double f) { return y0 + h * (f_max - f) / (f_max - f_min); };
    std::ofstream out(filename);
    AssertThrow(out, dealii::ExcMessage("step-9: cannot write " + filename));
    const char *colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"};
    out << std::fixed << std::setprecision(2) << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w + 150
        << "\" height=\"" << h + 100 << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<g font-family=\"sans-serif\" font-size=\"12\">\n";
    // axes, with ticks every 0.5 (force) and 6 (pull)
    out << "<line x1=\"" << x0 << "\" y1=\"" << Y(0) << "\" x2=\"" << X(d_max) << "\" y2=\"" << Y(0)
        << "\" stroke=\"black\"/>\n<line x1=\"" << x0 << "\" y1=\"" << Y(f_min) << "\" x2=\"" << x0 << "\" y2=\""
        << Y(f_max) << "\" stroke=\"black\"/>\n";
    for (double f = std::ceil(2 * f_min) / 2; f <= f_max; f += 0.5)
      out << "<line x1=\"" << x0 - 4 << "\" y1=\"" << Y(f) << "\" x2=\"" << x0 << "\" y2=\"" << Y(f)
          << "\" stroke=\"black\"/><text x=\"" << x0 - 8 << "\" y=\"" << Y(f) + 4 << "\" text-anchor=\"end\">"
          << std::setprecision(1) << f << std::setprecision(2) << "</text>\n";
    for (double d = 6; d <= d_max + 1e-9; d += 6)
      out << "<line x1=\"" << X(d) << "\" y1=\"" << Y(0) << "\" x2=\"" << X(d) << "\" y2=\"" << Y(0) + 4
          << "\" stroke=\"black\"/><text x=\"" << X(d) << "\" y=\"" << Y(0) + 16 << "\" text-anchor=\"middle\">"
          << std::setprecision(0) << d << std::setprecision(2) << "</text>\n";
    for (unsigned int k = 0; k < curves.size(); ++k)
      {
        const Curve &c = curves[k];
        out << "<polyline fill=\"none\" stroke=\"" << colours[k % 5] << "\" stroke-width=\"2\" points=\"";
        for (unsigned int i = 0; i < c.states.size(); ++i)
          out << X(x_of(c, i)) << "," << Y(y_of(c, c.states[i].pull_force)) << " ";
        const double n0 = y_of(c, c.joint.mu * c.N0());
        out << "\"/>\n<line stroke=\"" << colours[k % 5] << "\" stroke-dasharray=\"5,4\" x1=\"" << x0 << "\" y1=\""
            << Y(n0) << "\" x2=\"" << X(d_max) << "\" y2=\"" << Y(n0) << "\"/>\n<text x=\"" << X(d_max) + 6
            << "\" y=\"" << Y(y_of(c, c.sliding().pull_force)) + 4 << "\" fill=\"" << colours[k % 5] << "\">mu = "
            << std::setprecision(1) << c.joint.mu << std::setprecision(2) << "</text>\n";
      }
    out << "<text x=\"" << x0 + w / 2 << "\" y=\"" << y0 + h + 24 << "\" text-anchor=\"middle\">pull of the end / (mu "
        << "delta)</text>\n<text transform=\"translate(18," << y0 + h / 2
        << ") rotate(-90)\" text-anchor=\"middle\">F / (mu E delta)</text>\n<text x=\"" << x0 << "\" y=\"" << h + y0 + 52
        << "\">Solid: the pull-out force. Dashed: N0 / (E delta), the normal force of the interference:</text>\n"
        << "<text x=\"" << x0 << "\" y=\"" << h + y0 + 68
        << "\">Coulomb's estimate. The plateau is F = mu N exactly, with N below N0: friction bends the cheeks.</text>"
        << "\n</g>\n</svg>\n";
  }
} // namespace Step9


// @sect3{The main function}
int
main(int argc, char **argv)
{
  using namespace Step9;
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
              std::cerr << "usage: step-9 [--study] [--write-doc-picture]" << std::endl;
              return 2;
            }
        }
      std::vector<std::string> failures;

      // The default joint, k = 2, mu = 0.3, nu = 0.3: its pull-out curve.
      const Joint joint;
      const Curve c = pull_out(joint, failures);
      std::cout << "Mortise and tenon, interference delta = " << joint.delta << " per cheek, k = " << joint.degree
                << ", mu = " << joint.mu << ", nu = " << joint.nu << ": " << c.n_dofs << " DoFs, "
                << c.n_interfaces << " interfaces detected, " << c.n_pairs << " node pairs" << std::endl;
      print_curve(c);
      const double Ed = joint.E * joint.delta, F = c.sliding().pull_force;
      std::cout << "pull-out force F = " << std::setprecision(5) << F / Ed << " E delta; mu N0 = "
                << joint.mu * c.N0() / Ed << " E delta (N0 the normal force of the interference): F / (mu N0) = "
                << F / (joint.mu * c.N0()) << std::endl;

      // Force control: 0.99 F holds, 1.01 F pulls the tenon out.
      {
        std::string message;
        const bool  low  = holds(joint, 0.99 * F, message);
        std::cout << "force control: 0.99 F " << (low ? "holds" : "slides out: " + message);
        const bool high = holds(joint, 1.01 * F, message);
        std::cout << "; 1.01 F " << (high ? "holds" : "slides out (\"" + message + "\")") << std::endl;
        check(low, "the joint does not hold 0.99 times the pull-out force", failures);
        check(!high, "the joint holds 1.01 times the pull-out force", failures);
      }

      // The friction coefficients: F against mu N0. As mu -> 0 the ratio
      // goes to 1: a linear extrapolation from mu = 0.01 and 0.02 must give
      // 1 to 1e-3.
      std::vector<Curve> curves;
      std::cout << "\n    mu | k | nu  | N0/(E delta) | N/(E delta) sliding | F/(E delta) | F/(mu N) - 1 | F/(mu N0)\n";
      std::vector<double> mus = {0.01, 0.02, 0.1, 0.3, 0.6};
      std::vector<std::pair<unsigned int, double>> variants = {{2, 0.3}};
      if (study)
        variants = {{2, 0.3}, {1, 0.3}, {2, 0.0}, {1, 0.0}};
      for (const auto &[k, nu] : variants)
        {
          std::vector<double> ratio;
          for (const double mu : mus)
            {
              Joint j  = joint;
              j.mu     = mu;
              j.degree = k;
              j.nu     = nu;
              const Curve cm = pull_out(j, failures);
              const State &s = cm.sliding();
              ratio.push_back(s.pull_force / (mu * cm.N0()));
              std::cout << std::fixed << std::setw(6) << std::setprecision(2) << mu << " | " << k << " | "
                        << std::setprecision(1) << nu << " | " << std::setprecision(5) << std::setw(12)
                        << cm.N0() / Ed << " | " << std::setw(19) << s.N() / Ed << " | " << std::setw(11)
                        << s.pull_force / Ed << " | " << std::scientific << std::setprecision(1) << std::setw(12)
                        << s.pull_force / (mu * s.N()) - 1 << " | " << std::fixed << std::setprecision(4)
                        << ratio.back() << std::endl;
              if (k == 2 && nu == 0.3 && mu >= 0.1)
                curves.push_back(cm);
            }
          const double limit = 2 * ratio[0] - ratio[1];
          std::cout << "  k = " << k << ", nu = " << std::setprecision(1) << nu
                    << ": F/(mu N0) extrapolated to mu = 0: " << std::setprecision(5) << limit << std::endl;
          check(std::abs(limit - 1) <= 1e-3, "F/(mu N0) does not tend to 1 as mu -> 0", failures);
        }

      // The study: the pull-out force under mesh refinement.
      if (study)
        {
          std::cout << "\n  k | r | DoFs   | N0/(E delta) | F/(E delta) | F/(mu N0)\n";
          for (const unsigned int k : {1u, 2u})
            for (const unsigned int r : {1u, 2u, 4u})
              {
                Joint j  = joint;
                j.degree = k;
                j.refine = r;
                const Curve cr = pull_out(j, failures);
                std::cout << "  " << k << " | " << r << " | " << std::setw(6) << cr.n_dofs << " | " << std::fixed
                          << std::setprecision(5) << std::setw(12) << cr.N0() / Ed << " | " << std::setw(11)
                          << cr.sliding().pull_force / Ed << " | " << std::setprecision(4)
                          << cr.sliding().pull_force / (j.mu * cr.N0()) << std::endl;
              }
        }

      const std::string picture = doc_picture ?
                                    (std::filesystem::path(__FILE__).parent_path() / "doc" / "pull-out.svg").string() :
                                    std::string("pull-out.svg");
      write_svg(curves, picture);
      std::cout << "picture: " << picture << std::endl;

      for (const auto &m : failures)
        std::cerr << "step-9 check failed: " << m << std::endl;
      return failures.empty() ? 0 : 1;
    }
  catch (std::exception &exc)
    {
      std::cerr << std::endl << "Exception: " << exc.what() << std::endl;
      return 1;
    }
}
