// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Finite sliding on a curved interface, and contact that opens and closes.
//
// 1. A ring shrunk onto a shaft and turned on it (the study of
//    doc/finite-sliding.md, "Curved sliding"). Shaft: the annulus of radii
//    0.5 and 1, its inner circle held; ring: radii 1 - delta and 1.5,
//    delta = 2e-3 (an interference fit), its outer circle turned rigidly
//    by theta(t). Both from GridGenerator::hyper_shell (vertices on the
//    circles), meshed independently (12 and 10 cells around, refined
//    twice: 48 and 40 edges on the interface). Neo-Hooke E = 1, nu = 0.3,
//    plane strain. Step 1 (t = 0) closes the fit; then the ring is turned
//    in steps of 15 degrees (or 30) to 90 degrees.
//    Plane-strain Lame with u = 0 at r = 0.5 and at r = 1.5 gives the fit
//    pressure p; the friction of full slip gives the torque mu N R,
//    N = 2 pi R p. Checked at every step: every pair active, every pair's
//    pressure within 1 % of p (the polygons' sag would be kept as
//    roughness without the reference arcs: 22 % of the pairs active,
//    0.3 to 2.3 p); with mu = 0.3 every pair slips and the torque of the
//    friction forces is mu N R within 1 %; frictionless, the normal force
//    does not drift (1e-6) and the torque is zero (1e-6 of mu N R);
//    steps of 30 degrees end where steps of 15 do (1e-6); k = 1 and 2,
//    either body the master.
// 2. A block pressed onto a base and dragged off its end and back: once
//    its contact part has left the base the interface has no pairs and
//    the force is zero (to round-off); pushed back, it closes and the force
//    is that of the same position on the way out (1e-8).
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <dealvem/contact/contact_pressure.h>
#include <dealvem/contact/finite_sliding.h>
#include <dealvem/contact/finite_strain_contact.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "../finite_sliding_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  // Lame, plane strain: the contact pressure of a fit with interference
  // delta at radius R between a shaft (a, R) held at r = a and a ring (R, b)
  // held at r = b
  double
  lame_pressure(const double E, const double nu, const double a, const double R, const double b,
                const double delta)
  {
    const double mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    // u = A r + B / r, sigma_rr = 2 (lambda + mu) A - 2 mu B / r^2
    const double shaft = (R - a * a / R) / (2 * (lambda + mu) + 2 * mu * a * a / (R * R));
    const double ring  = (b * b / R - R) / (2 * (lambda + mu) + 2 * mu * b * b / (R * R));
    return delta / (shaft + ring);
  }

  struct TurnResult
  {
    bool                converged = true;
    std::vector<double> normal_force, torque, spread, active_fraction;
    std::vector<unsigned int> passes;
    unsigned int        n_not_slipping = 0;
  };

  TurnResult
  turn(const unsigned int degree, const bool shaft_is_master, const double mu, const double step_degrees,
       const double delta, const double p_lame)
  {
    const std::string what = "k = " + std::to_string(degree) + ", " + (shaft_is_master ? "shaft" : "ring") +
                             " master, mu = " + std::to_string(mu) + ", steps of " +
                             std::to_string(int(step_degrees)) + " degrees: ";
    // shaft: ids 0 (held), 1 (contact); ring: 10 (contact), 11 (turned)
    PolygonalMesh<2> mesh = testing::annulus(0.5, 1.0, 12, 2, 0, 0, 1);
    mesh.append(testing::annulus(1.0 - delta, 1.5, 10, 2, 1, 10, 11));
    const NeoHookeMaterial law(1.0, 0.3);
    MaterialLibrary<2>     laws;
    laws.add(0, law);
    laws.add(1, law);
    FiniteSliding::Parameters parameters;
    parameters.degree            = degree;
    parameters.pairing_tolerance = 1e-8;
    const FiniteSliding::InterfaceData interface = shaft_is_master ? FiniteSliding::InterfaceData{1, 10, mu} :
                                                                     FiniteSliding::InterfaceData{10, 1, mu};
    FiniteSliding sliding(mesh, laws, {interface}, parameters);
    // time t: the turn in degrees
    sliding.set_constraints_function(
      testing::prescribe({0, 11}, [](const dealii::types::boundary_id id, const dealii::Point<2> &X, const double t) {
        dealii::Tensor<1, 2> u;
        if (id == 11)
          {
            const double theta = t * pi / 180;
            u[0]               = std::cos(theta) * X[0] - std::sin(theta) * X[1] - X[0];
            u[1]               = std::sin(theta) * X[0] + std::cos(theta) * X[1] - X[1];
          }
        return u;
      }));

    TurnResult         result;
    const unsigned int n_turns = static_cast<unsigned int>(std::lround(90 / step_degrees));
    for (unsigned int n = 0; n <= n_turns; ++n)
      {
        try
          {
            sliding.solve_step(n + 1, n * step_degrees);
          }
        catch (const std::exception &e)
          {
            std::cout << what << "step " << n + 1 << " failed: " << e.what() << std::endl;
            result.converged = false;
            break;
          }
        const auto  &record  = sliding.get_history().back();
        const auto  &u       = sliding.get_solution();
        const auto  &lambda  = sliding.get_multipliers();
        const auto  &contact = sliding.get_contact();
        const auto   np      = contact.n_pairs();
        const auto   w       = contact.current_weights(u);
        const bool   two     = contact.n_constraints() == 2 * np;
        double       N = 0, T = 0, spread = 0;
        unsigned int active = 0, counted = 0, sticking = 0;
        for (unsigned int i = 0; i < np; ++i)
          {
            if (contact.is_left_out(i))
              continue;
            ++counted;
            const auto x = contact.current_positions(i, u)[1];
            const auto nrm = contact.current_normal(i, u);
            dealii::Tensor<1, 2> t;
            t[0] = -nrm[1];
            t[1] = nrm[0];
            // the force on the slave side
            dealii::Tensor<1, 2> f = -lambda[i] * nrm;
            if (two)
              f -= lambda[np + i] * t;
            // the torque on the ring (the slave side when the shaft is the
            // master)
            const double moment = x[0] * f[1] - x[1] * f[0];
            T += shaft_is_master ? moment : -moment;
            N += std::abs(lambda[i]);
            if (lambda[i] != 0)
              ++active;
            spread = std::max(spread, std::abs(-lambda[i] / w[i] - p_lame) / p_lame);
            if (n > 0 && mu > 0 && two && std::abs(lambda[np + i]) < mu * std::abs(lambda[i]) * (1 - 1e-9))
              {
                ++result.n_not_slipping;
                ++sticking;
              }
          }
        // the pressure the program reports: ContactPressure::recover()
        std::vector<double> force(np);
        for (unsigned int i = 0; i < np; ++i)
          force[i] = -lambda[i];
        const auto   recovered = ContactPressure::recover(sliding.get_interfaces()[0], force);
        double       raw       = spread;
        spread                 = 0;
        for (unsigned int i = 0; i < np; ++i)
          if (!contact.is_left_out(i))
            spread = std::max(spread, std::abs(recovered[i] - p_lame) / p_lame);
        result.normal_force.push_back(N);
        result.torque.push_back(T);
        result.spread.push_back(spread);
        result.active_fraction.push_back(counted > 0 ? double(active) / counted : 0.);
        result.passes.push_back(record.n_passes);
        std::cout << "  " << what << "theta = " << n * step_degrees << ": " << active << " of " << counted
                  << " pairs active, " << record.n_passes << " passes, " << record.n_substeps
                  << " sub-steps, " << sticking << " sticking, N / (2 pi R p) = " << N / (2 * pi * p_lame) << ", pressure spread "
                  << spread << " (raw " << raw << ")" << ", torque / (mu N R) = " << (mu > 0 ? T / (mu * N) : T / N) << std::endl;
      }
    return result;
  }

  // A block on a base, pressed down by 0.01 and moved along it by its top
  // (held in both directions): out by s = 0.35 per step until it has left
  // the base, then back. Returns the vertical contact force per step (0 for
  // an interface without pairs) and the number of pairs.
  std::vector<std::pair<double, unsigned int>>
  slide_off(const unsigned int degree)
  {
    PolygonalMesh<2> mesh, block;
    // the base [0, 2] x [-0.4, 0], its bottom held: ids 0-3
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, -0.4), dealii::Point<2>(2, 0), 10, 2);
    // the block [0.45, 1.45] x [0, 0.4] (7 edges against the base's 10
    // over its width): ids 10-13
    PolygonalMeshGenerators::structured_quads(block, dealii::Point<2>(0.45, 0), dealii::Point<2>(1.45, 0.4), 7, 2);
    for (unsigned int c = 0; c < block.n_cells(); ++c)
      block.set_material_id(c, 1);
    for (unsigned int e = 0; e < block.n_edges(); ++e)
      if (block.edge(e).at_boundary())
        block.set_edge_boundary_id(e, block.edge(e).boundary_id + 10);
    mesh.append(block);
    const NeoHookeMaterial law(1.0, 0.3);
    MaterialLibrary<2>     laws;
    laws.add(0, law);
    laws.add(1, law);
    FiniteSliding::Parameters parameters;
    parameters.degree            = degree;
    parameters.pairing_tolerance = 1e-8;
    FiniteSliding sliding(mesh, laws, {FiniteSliding::InterfaceData{3, 12, 0.}}, parameters);
    // the time: the step; out for steps 1-6, back for 7-9
    const auto shift = [](const double t) { return 0.35 * (t <= 6 ? t : 12 - t); };
    sliding.set_constraints_function(
      testing::prescribe({2, 13}, [shift](const dealii::types::boundary_id id, const dealii::Point<2> &, const double t) {
        dealii::Tensor<1, 2> u;
        if (id == 13)
          {
            u[0] = shift(t);
            u[1] = -0.01;
          }
        return u;
      }));
    std::vector<std::pair<double, unsigned int>> forces;
    for (unsigned int n = 1; n <= 9; ++n)
      {
        try
          {
            sliding.solve_step(n, n);
          }
        catch (const std::exception &e)
          {
            std::cout << "slide off, k = " << degree << ": step " << n << " failed: " << e.what() << std::endl;
            break;
          }
        const auto &record = sliding.get_history().back();
        forces.emplace_back(record.normal_force[0][1], record.n_pairs);
        std::cout << "  slide off, k = " << degree << ", shift " << shift(n) << ": " << record.n_pairs
                  << " pairs, " << record.n_active << " active, " << record.n_passes << " passes, "
                  << record.n_substeps << " sub-steps, normal force " << record.normal_force[0] << std::endl;
      }
    return forces;
  }
} // namespace

int
main(int argc, char **argv)
{
  const double delta = 2e-3;
  if (argc > 1 && std::string(argv[1]) == "--study")
    {
      // the ring-on-shaft study (ctest label "long"): k = 2, the shaft the
      // master, mu = 0.3, the ring turned by 90 degrees in steps of 5, 15
      // and 30 degrees; per step the pressure spread, the torque against
      // mu N R (Lame's N) and the pairing passes
      const double p = lame_pressure(1.0, 0.3, 0.5, 1.0, 1.5, delta);
      for (const double step : {5., 15., 30.})
        {
          const auto r = turn(2, true, 0.3, step, delta, p);
          std::cout << "steps of " << step << " degrees: | theta | passes | pressure spread | torque / (mu N R) |"
                    << std::endl;
          for (unsigned int n = 1; n < r.torque.size(); ++n)
            std::cout << "| " << n * step << " | " << r.passes[n] << " | " << r.spread[n] << " | "
                      << std::abs(r.torque[n]) / (0.3 * 2 * pi * p) << " |" << std::endl;
          testing::check(r.converged && r.n_not_slipping == 0,
                         "study, steps of " + std::to_string(int(step)) + " degrees: every step converges, every "
                                                                           "pair slips");
        }
      return testing::finish();
    }
  // (the interface at R = 1; the ring's bore at 1 - delta)
  const double p = lame_pressure(1.0, 0.3, 0.5, 1.0, 1.5, delta), mu = 0.3;
  std::cout << "Lame pressure " << p << std::endl;
  const double N_lame = 2 * pi * p, T_lame = mu * N_lame;

  const auto check_turn = [&](const TurnResult &r, const std::string &what, const bool frictional) {
    testing::check(r.converged && r.normal_force.size() >= 4, what + ": every step converges");
    double fewest_active = 1, spread = 0, torque = 0, drift = 0;
    for (unsigned int n = 0; n < r.normal_force.size(); ++n)
      {
        fewest_active = std::min(fewest_active, r.active_fraction[n]);
        spread        = std::max(spread, r.spread[n]);
        if (frictional && n > 0)
          torque = std::max(torque, std::abs(std::abs(r.torque[n]) / T_lame - 1));
        if (!frictional)
          {
            torque = std::max(torque, std::abs(r.torque[n]) / r.normal_force[n]);
            drift  = std::max(drift, std::abs(r.normal_force[n] / r.normal_force[0] - 1));
          }
      }
    testing::check(fewest_active == 1, what + ": every pair active at every step");
    testing::check_small(spread, 0.01, what + ": pressure against Lame's at every pair and step (relative)");
    if (frictional)
      {
        testing::check(r.n_not_slipping == 0, what + ": every pair slips while the ring turns");
        testing::check_small(torque, 0.01, what + ": friction torque against mu N R of Lame's N (relative)");
      }
    else
      {
        testing::check_small(torque, 1e-9, what + ": frictionless, the torque over N R");
        testing::check_small(drift, 1e-6, what + ": frictionless, the drift of the normal force");
      }
  };

  const auto a = turn(2, true, mu, 15, delta, p);
  check_turn(a, "k = 2, shaft master, 15 degree steps", true);
  const auto b = turn(2, true, mu, 30, delta, p);
  check_turn(b, "k = 2, shaft master, 30 degree steps", true);
  const auto c = turn(2, false, mu, 30, delta, p);
  check_turn(c, "k = 2, ring master, 30 degree steps", true);
  const auto d = turn(1, false, mu, 30, delta, p);
  check_turn(d, "k = 1, ring master, 30 degree steps", true);
  const auto e = turn(2, true, 0., 30, delta, p);
  check_turn(e, "k = 2, frictionless, 30 degree steps", false);
  // steps of 30 degrees end where steps of 15 do; the master choice does
  // not matter
  double step_size = a.normal_force.size() == 7 && b.normal_force.size() == 4 ? 0 : 1, bias = step_size;
  for (unsigned int n = 1; n < 4 && step_size < 1; ++n)
    step_size = std::max({step_size, std::abs(b.normal_force[n] / a.normal_force[2 * n] - 1),
                          std::abs(b.torque[n] / a.torque[2 * n] - 1)});
  testing::check_small(step_size, 1e-6, "steps of 30 degrees against steps of 15: normal force and torque");
  for (unsigned int n = 0; n < 4 && bias < 1 && c.normal_force.size() == 4; ++n)
    bias = std::max({bias, std::abs(c.normal_force[n] / b.normal_force[n] - 1),
                     n == 0 ? 0. : std::abs(c.torque[n] / b.torque[n] - 1)});
  testing::check_small(bias, 1e-4, "ring as master against shaft as master: normal force and torque");

  // a block dragged off its base and back
  for (const unsigned int degree : {1u, 2u})
    {
      const std::string what = "slide off, k = " + std::to_string(degree) + ": ";
      const auto        f    = slide_off(degree);
      testing::check(f.size() == 9, what + "every step converges");
      if (f.size() != 9)
        continue;
      testing::check(f[0].first > 0.01 && f[3].first > 0.001, what + "pressed while on the base");
      for (const unsigned int n : {4u, 5u, 6u})
        testing::check(f[n].second == 0 && f[n].first == 0, what + "no pair and zero force off the base (step " +
                                                               std::to_string(n + 1) + ")");
      testing::check(f[7].second > 0, what + "the contact closes again when the block comes back");
      testing::check_small(std::abs(f[8].first / f[2].first - 1), 1e-8,
                           what + "back at the shift 1.05: the force of the way out (relative)");
    }
  return testing::finish();
}
