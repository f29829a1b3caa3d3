// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Design sensitivities (dealvem/design) against central finite differences,
// k = 1 and 2, on random designs (stiffness factors in [0.2, 1]):
// - one body (a cantilever on perturbed quads, tip load): the compliance,
//   self-adjoint;
// - two blocks on non-matching meshes, tied: the compliance;
// - two blocks, unilateral with stick by multipliers, the upper block
//   pressed down by a traction and overlapping the lower one by an
//   interference (every pair has a non-zero right-hand side): the
//   compliance, which is not self-adjoint there (the adjoint solve runs);
// - a block on a curved base (the contact opens towards the ends, some
//   pairs open), unilateral: the compliance (the closed pairs have positive
//   initial gaps: not self-adjoint), the same with stick by a penalty
//   (springs in the stiffness, independent of the design) and, with the
//   block also held at its side, the normal force of the interface; the
//   largest pressure of the interface (its 8-norm, a J non-linear in the
//   state);
// - constraints besides the objective on the curved base: the interface's
//   force at least, its largest pressure at most, the compliance at most a
//   bound; their gradients, and the adjoint solves reusing the state's
//   factorization;
// - the factorization of another design keeping the ordering (symbolic
//   analysis) of the first: the same compliance and gradient as a fresh
//   solver's;
// - the whole chain of TopologyOptimizer: variables z -> filter -> Heaviside
//   projection -> SIMP / RAMP -> factors -> compliance, against finite
//   differences in z.
// Each derivative of a sample of cells must agree with the difference
// quotient (step 1e-5 relative; truncation and round-off both below 1e-9)
// to 1e-6 relative. The active sets must be the same at every perturbed
// design and no pair may be degenerate (strict complementarity).
// Also: MaterialInterpolation and HeavisideProjection derivatives, the
// filter's rows summing to one and P^T as the transpose of P, and bad
// parameters throwing with the parameter's name.
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dealvem/design/design_problem.h>
#include <dealvem/design/topology_optimizer.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/mesh/generators.h>

#include <cmath>
#include <memory>
#include <random>
#include <utility>

#include "../tests.h"

using namespace dealvem;
using P = dealii::Point<2>;
using T = dealii::Tensor<1, 2>;

namespace
{
  MaterialLibrary<2>
  two_laws()
  {
    MaterialLibrary<2> laws;
    laws.add(0, ElasticMaterial(1000., 0.3));
    laws.add(1, ElasticMaterial(700., 0.25));
    return laws;
  }

  // the second body: material id 1, boundary ids + 10
  void
  add_body(PolygonalMesh<2> &mesh, PolygonalMesh<2> body)
  {
    for (unsigned int c = 0; c < body.n_cells(); ++c)
      body.set_material_id(c, 1);
    for (unsigned int e = 0; e < body.n_edges(); ++e)
      if (body.edge(e).at_boundary())
        body.set_edge_boundary_id(e, body.edge(e).boundary_id + 10);
    mesh.append(body);
  }

  std::vector<double>
  random_factors(const unsigned int n, const unsigned int seed)
  {
    std::mt19937                           gen(seed);
    std::uniform_real_distribution<double> d(0.2, 1.0);
    std::vector<double>                    s(n);
    for (double &x : s)
      x = d(gen);
    return s;
  }

  // the derivative of @p problem at @p s against central differences, on
  // the cells with the largest |gradient| and a few others
  void
  check_gradient(Design::ElasticDesignProblem &problem, const std::vector<double> &s, const std::string &tag,
                 const bool expect_adjoint)
  {
    std::vector<double> g, dummy;
    const double        J        = problem.evaluate(s, g);
    const auto          active   = problem.last_state().active;
    testing::check(problem.last_state().n_degenerate_pairs == 0, tag + ": no degenerate pair");
    testing::check(problem.last_state().adjoint_solved == expect_adjoint,
                   tag + ": adjoint solve " + (expect_adjoint ? "needed" : "not needed"));
    unsigned int imax = 0;
    for (unsigned int c = 0; c < g.size(); ++c)
      if (std::abs(g[c]) > std::abs(g[imax]))
        imax = c;
    std::vector<unsigned int> cells = {imax, 0, static_cast<unsigned int>(g.size() / 3),
                                       static_cast<unsigned int>(g.size() / 2),
                                       static_cast<unsigned int>(g.size() - 1)};
    double worst = 0;
    for (const unsigned int c : cells)
      {
        if (std::abs(g[c]) < 1e-3 * std::abs(g[imax]))
          continue;
        // central differences D(h) and D(h/2), extrapolated:
        // (4 D(h/2) - D(h)) / 3 = J' + O(h^4)
        auto difference = [&](const double h) {
          std::vector<double> sp = s, sm = s;
          sp[c] += h;
          sm[c] -= h;
          const double Jp = problem.evaluate(sp, dummy);
          testing::check(problem.last_state().active == active, tag + ": same active set at s + h");
          const double Jm = problem.evaluate(sm, dummy);
          testing::check(problem.last_state().active == active, tag + ": same active set at s - h");
          return (Jp - Jm) / (2 * h);
        };
        const double h  = 2e-3 * s[c];
        const double fd = (4 * difference(h / 2) - difference(h)) / 3;
        worst           = std::max(worst, std::abs(fd - g[c]) / std::abs(g[c]));
      }
    std::cout << tag << ": J = " << J << ", worst relative error of dJ/ds against differences " << worst
              << std::endl;
    testing::check_small(worst, 1e-6, tag + ": gradient against central differences");
  }

  void
  one_body(const unsigned int k)
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::perturbed_quads(mesh, P(0, 0), P(4, 1), 16, 4, 0.2, 7);
    Design::ElasticDesignProblem problem(mesh, two_laws(), k);
    problem.add_support(0);
    problem.add_point_load(P(4, 0), T({0., -1.}));
    problem.setup();
    const auto s = random_factors(mesh.n_cells(), 11 + k);
    check_gradient(problem, s, "one body, k = " + std::to_string(k), false);
    // the compliance is f^T u = u^T K u
    std::vector<double> g;
    const double        J = problem.evaluate(s, g);
    double              energy = 0;
    for (unsigned int c = 0; c < g.size(); ++c)
      energy -= s[c] * g[c];
    testing::check_near(energy / J, 1., 1e-10, "one body, k = " + std::to_string(k) + ": sum s_c u_c^T K_c u_c = f^T u");
  }

  // two blocks, the upper one [0.2, 0.8] x [0, 0.5] + (0, lift) on the
  // lower [0, 1] x [-0.5, 0], meshes that do not match
  PolygonalMesh<2>
  two_blocks(const double lift)
  {
    PolygonalMesh<2> mesh, upper;
    PolygonalMeshGenerators::perturbed_quads(mesh, P(0, -0.5), P(1, 0), 9, 5, 0.15, 3);
    PolygonalMeshGenerators::structured_quads(upper, P(0.2, lift), P(0.8, 0.5 + lift), 7, 5);
    add_body(mesh, upper);
    return mesh;
  }

  void
  two_blocks_tied(const unsigned int k)
  {
    const auto make = [k]() {
      auto problem = std::make_unique<Design::ElasticDesignProblem>(two_blocks(0), two_laws(), k);
      problem->contact_settings().normal     = ContactSettings::Normal::tied;
      problem->contact_settings().tangential = ContactSettings::Tangential::multipliers;
      problem->add_contact_interface(3, 12);
      problem->add_support(2);
      problem->add_traction(13, T({0.5, -1.}));
      problem->setup();
      return problem;
    };
    const auto                    owner   = make();
    Design::ElasticDesignProblem &problem = *owner;
    const auto                    s       = random_factors(problem.get_mesh().n_cells(), 21 + k);
    const std::string             tag     = "tied blocks, k = " + std::to_string(k);
    check_gradient(problem, s, tag, false);
    // the condensed pattern does not depend on the design: the factorization
    // of another design keeps the ordering of the first, and gives what a
    // fresh solver computes for that design
    std::vector<double> other = s, g, g_fresh;
    for (unsigned int c = 0; c < other.size(); c += 3)
      other[c] = 1.2 - other[c];
    const double J = problem.evaluate(other, g);
    testing::check(problem.last_state().n_factorizations == 1 && problem.last_state().n_analyses == 0,
                   tag + ": another design, factored with the kept ordering");
    const auto   fresh   = make();
    const double J_fresh = fresh->evaluate(other, g_fresh);
    testing::check(fresh->last_state().n_analyses == 1, tag + ": a fresh solver analyses its pattern");
    double dg = 0, gmax = 0;
    for (unsigned int c = 0; c < g.size(); ++c)
      {
        dg   = std::max(dg, std::abs(g[c] - g_fresh[c]));
        gmax = std::max(gmax, std::abs(g_fresh[c]));
      }
    testing::check_near(J, J_fresh, 1e-14 * J_fresh, tag + ": the kept ordering, the same compliance");
    testing::check_small(dg / gmax, 1e-13, tag + ": the kept ordering, the same gradient");
  }

  void
  two_blocks_interference(const unsigned int k)
  {
    Design::ElasticDesignProblem problem(two_blocks(-1e-4), two_laws(), k);
    problem.contact_settings().normal     = ContactSettings::Normal::unilateral;
    problem.contact_settings().tangential = ContactSettings::Tangential::multipliers;
    // the gaps (the overlap, the bulge) are real, not two discretizations
    // of one curve
    problem.insertion_settings().close_discretisation_gaps = false;
    problem.add_contact_interface(3, 12);
    problem.add_support(2);
    problem.add_traction(13, T({0., -1.}));
    problem.add_traction(10, T({0.3, 0.}));
    problem.setup();
    const auto s = random_factors(problem.get_mesh().n_cells(), 31 + k);
    check_gradient(problem, s, "interference, unilateral + stick, k = " + std::to_string(k), true);
    std::vector<double> g;
    problem.evaluate(s, g);
    unsigned int n_active = 0;
    for (const bool a : problem.last_state().active)
      n_active += a;
    std::cout << "interference, k = " << k << ": " << n_active << " of " << problem.n_pairs() << " pairs closed"
              << std::endl;
    testing::check(2 * n_active > problem.n_pairs(), "interference: most pairs closed");
  }

  // a block on a base whose top bulges, y = 0.02 (1 - 4 (x - 0.5)^2): the
  // contact closes in the middle and opens towards the block's ends
  PolygonalMesh<2>
  curved_base_mesh()
  {
    PolygonalMesh<2> mesh, upper;
    PolygonalMeshGenerators::structured_quads(mesh, P(0, -0.5), P(1, 0), 12, 5);
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      {
        const P x = mesh.vertex(v);
        mesh.move_vertex(v, P(x[0], x[1] + (x[1] + 0.5) / 0.5 * 0.02 * (1 - 4 * (x[0] - 0.5) * (x[0] - 0.5))));
      }
    PolygonalMeshGenerators::perturbed_quads(upper, P(0.1, 0.02), P(0.9, 0.4), 9, 4, 0.15, 5);
    add_body(mesh, upper);
    return mesh;
  }

  void
  curved_base(const unsigned int k, const Design::ElasticDesignProblem::Objective objective,
              const ContactSettings::Tangential tangential = ContactSettings::Tangential::multipliers)
  {
    Design::ElasticDesignProblem problem(curved_base_mesh(), two_laws(), k);
    problem.contact_settings().normal     = ContactSettings::Normal::unilateral;
    problem.contact_settings().tangential = tangential;
    // the gaps (the overlap, the bulge) are real, not two discretizations
    // of one curve
    problem.insertion_settings().close_discretisation_gaps = false;
    problem.add_contact_interface(3, 12);
    problem.add_support(2);
    problem.add_traction(13, T({0., -2.}));
    problem.set_objective(objective);
    // for the force: the block also held at its left side, so that the
    // interface's share of the load depends on the design
    const bool force    = objective == Design::ElasticDesignProblem::Objective::interface_force;
    const bool pressure = objective == Design::ElasticDesignProblem::Objective::max_pressure;
    if (force)
      problem.add_support(10, {{false, true}});
    problem.setup();
    const auto          s = random_factors(problem.get_mesh().n_cells(), 41 + k);
    std::vector<double> g;
    problem.evaluate(s, g);
    unsigned int n_active = 0;
    for (const bool a : problem.last_state().active)
      n_active += a;
    std::cout << "curved base, k = " << k << ": " << n_active << " of " << problem.n_pairs() << " pairs closed"
              << std::endl;
    testing::check(n_active > 2 && n_active < problem.n_pairs(), "curved base: some pairs open, some closed");
    if (pressure)
      {
        // the 8-norm lies between the largest pair pressure and n^(1/8) times it
        double p_max = 0;
        for (unsigned int i = 0; i < problem.n_pairs(); ++i)
          p_max = std::max(p_max, -problem.last_state().normal_multipliers[i] / problem.get_pairs()[i].weight);
        std::vector<double> gp;
        const double        Jp = problem.evaluate(s, gp);
        testing::check(Jp >= p_max && Jp <= std::pow(double(n_active), 1. / 8) * p_max,
                       "curved base: max <= the pressure norm <= n^(1/8) max");
      }
    if (!force)
      testing::check_near(problem.last_state().interface_forces[0], 2. * 0.8, 1e-10 * 1.6,
                          "curved base: the interface carries the load");
    else
      testing::check(problem.last_state().interface_forces[0] < 0.95 * 1.6,
                     "curved base, held at the side: the interface carries part of the load");
    // the closed pairs have positive initial gaps: not self-adjoint
    const bool penalty = tangential == ContactSettings::Tangential::penalty;
    check_gradient(problem, s,
                   std::string("curved base, ") +
                     (force ? "interface force" : pressure ? "largest pressure (8-norm)" : "compliance") +
                     (penalty ? ", stick by penalty" : "") + ", k = " + std::to_string(k),
                   true);
  }

  // constraints besides the objective (the compliance) on the curved base
  // held at its side: the interface's force at least a bound, its largest
  // pressure at most one, the compliance at most one. Each constraint's
  // value against its response, its gradient against differences of the
  // value; the adjoint solves reuse the factorization of the state, and
  // the compliance constraint reuses the objective's adjoint.
  void
  constrained(const unsigned int k)
  {
    using R = Design::ElasticDesignProblem::Response;
    using B = Design::ElasticDesignProblem::Bound;
    const auto make = [&](const bool with_constraints) {
      auto problem = std::make_unique<Design::ElasticDesignProblem>(curved_base_mesh(), two_laws(), k);
      problem->contact_settings().normal                   = ContactSettings::Normal::unilateral;
      problem->insertion_settings().close_discretisation_gaps = false;
      problem->add_contact_interface(3, 12);
      problem->add_support(2);
      problem->add_support(10, {{false, true}});
      problem->add_traction(13, T({0., -2.}));
      if (with_constraints)
        {
          problem->add_constraint(R::interface_force, 1.0, B::at_least, 0);
          problem->add_constraint(R::max_pressure, 4.0, B::at_most, 0);
          problem->add_constraint(R::compliance, 0.05);
        }
      else
        problem->set_objective(R::max_pressure, 0);
      problem->setup();
      return problem;
    };
    auto       problem   = make(true);
    auto       reference = make(false);
    const auto s         = random_factors(problem->get_mesh().n_cells(), 51 + k);
    const std::string tag = "constraints, k = " + std::to_string(k);

    std::vector<double>              g, values;
    std::vector<std::vector<double>> grads;
    const double                     J = problem->evaluate(s, g);
    problem->constraints(values, grads);
    const auto state  = problem->last_state();
    const auto active = state.active;
    testing::check(values.size() == 3 && grads.size() == 3, tag + ": three constraints");
    testing::check(state.n_degenerate_pairs == 0, tag + ": no degenerate pair");
    const double F = state.interface_forces[0];
    testing::check_near(values[0], 1.0 - F, 1e-14, tag + ": force >= 1 as g = 1 - F");
    testing::check_near(state.constraint_responses[2], J, 1e-14 * J, tag + ": the compliance constraint's response");
    testing::check_near(values[2], (J - 0.05) / 0.05, 1e-12, tag + ": compliance <= 0.05 as g = C / 0.05 - 1");
    std::vector<double> gp;
    const double        Pn = reference->evaluate(s, gp);
    testing::check_near(state.constraint_responses[1], Pn, 1e-12 * Pn, tag + ": the pressure constraint's response");
    testing::check_near(values[1], (Pn - 4.) / 4., 1e-12, tag + ": pressure <= 4 as g = P / 4 - 1");
    double g_max = 0, g_diff = 0;
    for (unsigned int c = 0; c < g.size(); ++c)
      {
        g_max  = std::max(g_max, std::abs(g[c] / 0.05));
        g_diff = std::max(g_diff, std::abs(grads[2][c] - g[c] / 0.05));
      }
    testing::check_small(g_diff / g_max, 1e-15, tag + ": the compliance constraint's gradient is the objective's / 0.05");
    // the objective (compliance, not self-adjoint here), the force and the
    // pressure: three adjoint solves, none factored again
    std::cout << tag << ": " << state.n_contact_iterations << " active-set iterations, " << state.n_solves
              << " solves, " << state.n_factorizations << " factorizations; F = " << F << ", P-norm = " << Pn
              << ", C = " << J << std::endl;
    testing::check(state.n_solves == state.n_contact_iterations + 3, tag + ": three adjoint solves");
    testing::check(state.n_factorizations <= state.n_contact_iterations,
                   tag + ": the adjoint solves reuse the state's factorization");

    double worst = 0;
    for (unsigned int j = 0; j < 2; ++j)
      {
        unsigned int imax = 0;
        for (unsigned int c = 0; c < grads[j].size(); ++c)
          if (std::abs(grads[j][c]) > std::abs(grads[j][imax]))
            imax = c;
        for (const unsigned int c : {imax, 5u, static_cast<unsigned int>(g.size() / 2),
                                     static_cast<unsigned int>(g.size() - 3)})
          {
            if (std::abs(grads[j][c]) < 1e-3 * std::abs(grads[j][imax]))
              continue;
            auto difference = [&](const double h) {
              std::vector<double>              sp = s, sm = s, vp, vm, dummy;
              std::vector<std::vector<double>> unused;
              sp[c] += h;
              sm[c] -= h;
              problem->evaluate(sp, dummy);
              testing::check(problem->last_state().active == active, tag + ": same active set at s + h");
              problem->constraints(vp, unused);
              problem->evaluate(sm, dummy);
              testing::check(problem->last_state().active == active, tag + ": same active set at s - h");
              problem->constraints(vm, unused);
              return (vp[j] - vm[j]) / (2 * h);
            };
            const double h  = 2e-3 * s[c];
            const double fd = (4 * difference(h / 2) - difference(h)) / 3;
            worst           = std::max(worst, std::abs(fd - grads[j][c]) / std::abs(grads[j][c]));
          }
      }
    std::cout << tag << ": worst relative error of dg/ds against differences " << worst << std::endl;
    testing::check_small(worst, 1e-6, tag + ": constraint gradients against central differences");
  }

  // the optimizer's chain z -> factors -> J against differences in z
  void
  chain(const unsigned int k, const Design::MaterialInterpolation::Type type)
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::perturbed_quads(mesh, P(0, 0), P(3, 1), 12, 4, 0.2, 9);
    Design::ElasticDesignProblem problem(mesh, two_laws(), k);
    problem.add_support(0);
    problem.add_traction(1, T({0., -1.}));
    problem.setup();
    Design::TopologyOptimizer::Settings settings;
    settings.filter_radius              = 0.6;
    settings.interpolation.type         = type;
    settings.interpolation.penalty      = type == Design::MaterialInterpolation::Type::simp ? 3. : 4.;
    settings.interpolation.minimum      = 1e-3;
    settings.projection                 = true;
    settings.heaviside.beta             = 4;
    settings.heaviside.eta              = 0.4;
    auto                chain = Design::TopologyOptimizer::make_chain(problem.get_mesh(), settings);
    std::mt19937        gen(5 + k);
    std::uniform_real_distribution<double> d(0.1, 0.9);
    std::vector<double> z(chain.design_cells.size());
    for (double &x : z)
      x = d(gen);
    auto J_of = [&](const std::vector<double> &zz, std::vector<double> *gz) {
      std::vector<double> ds;
      const double        J = problem.evaluate(chain.factors(zz, settings.interpolation, &settings.heaviside), ds);
      if (gz)
        *gz = chain.variable_gradient(ds, settings.interpolation, &settings.heaviside);
      return J;
    };
    std::vector<double> gz, gv;
    J_of(z, &gz);
    const double V = chain.volume(&gv, &settings.heaviside);
    double       worst = 0, worst_v = 0;
    for (const unsigned int i : {0u, 7u, 20u, 31u, 47u})
      {
        // extrapolated central differences, as in check_gradient()
        auto difference = [&](const double h) {
          std::vector<double> zp = z, zm = z;
          zp[i] += h;
          zm[i] -= h;
          const double Jp = J_of(zp, nullptr);
          const double Vp = chain.volume(nullptr, &settings.heaviside);
          const double Jm = J_of(zm, nullptr);
          const double Vm = chain.volume(nullptr, &settings.heaviside);
          return std::make_pair((Jp - Jm) / (2 * h), (Vp - Vm) / (2 * h));
        };
        const auto d1 = difference(1e-3), d2 = difference(5e-4);
        worst   = std::max(worst, std::abs((4 * d2.first - d1.first) / 3 - gz[i]) / std::abs(gz[i]));
        worst_v = std::max(worst_v, std::abs((4 * d2.second - d1.second) / 3 - gv[i]) / std::abs(gv[i]));
      }
    const std::string tag = "chain (" + Design::MaterialInterpolation::name(type) + ", filter, projection), k = " +
                            std::to_string(k);
    std::cout << tag << ": V = " << V << ", worst relative errors: dJ/dz " << worst << ", dV/dz " << worst_v
              << std::endl;
    testing::check_small(worst, 1e-6, tag + ": dJ/dz against central differences");
    testing::check_small(worst_v, 1e-6, tag + ": dV/dz against central differences");
  }

  void
  pieces()
  {
    for (const auto type : {Design::MaterialInterpolation::Type::simp, Design::MaterialInterpolation::Type::ramp})
      {
        Design::MaterialInterpolation m;
        m.type    = type;
        m.penalty = 3;
        m.minimum = 1e-4;
        testing::check_near(m.factor(0), 1e-4, 1e-16, "interpolation: s(0) = minimum");
        testing::check_near(m.factor(1), 1., 1e-15, "interpolation: s(1) = 1");
        for (const double r : {0.1, 0.5, 0.93})
          testing::check_near(m.derivative(r), (m.factor(r + 1e-6) - m.factor(r - 1e-6)) / 2e-6, 1e-8,
                              "interpolation: s'(" + std::to_string(r) + ")");
      }
    Design::HeavisideProjection h;
    h.beta = 8;
    h.eta  = 0.3;
    testing::check_near(h.value(0), 0., 1e-15, "projection: H(0) = 0");
    testing::check_near(h.value(1), 1., 1e-15, "projection: H(1) = 1");
    testing::check_near(h.derivative(0.4), (h.value(0.4 + 1e-6) - h.value(0.4 - 1e-6)) / 2e-6, 1e-7,
                        "projection: H'(0.4)");

    // the filter: rows sum to one, P^T is the transpose, R below the
    // spacing gives P = I
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::perturbed_quads(mesh, P(0, 0), P(2, 1), 20, 10, 0.25, 1);
    std::vector<unsigned int> cells(mesh.n_cells());
    for (unsigned int c = 0; c < cells.size(); ++c)
      cells[c] = c;
    const auto            x = Design::cell_centroids(mesh, cells);
    Design::DensityFilter filter(x, 0.25);
    std::vector<double>   one(cells.size(), 1.), y, a = random_factors(cells.size(), 1),
                                                    b = random_factors(cells.size(), 2), Pa, PTb;
    filter.apply(one, y);
    double worst = 0;
    for (const double v : y)
      worst = std::max(worst, std::abs(v - 1));
    testing::check_small(worst, 1e-14, "filter: P 1 = 1");
    filter.apply(a, Pa);
    filter.apply_transpose(b, PTb);
    double bPa = 0, aPTb = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        bPa += b[i] * Pa[i];
        aPTb += a[i] * PTb[i];
      }
    testing::check_near(bPa, aPTb, 1e-12 * std::abs(bPa), "filter: b.(P a) = (P^T b).a");
    // with R = 0.25 and cells of about 0.1, every cell has neighbours
    testing::check(filter.n_nonzeros() > 5 * cells.size(), "filter: neighbours found");
    // against the O(n^2) definition on one row
    {
      std::vector<unsigned int> cols;
      std::vector<double>       vals;
      filter.row(57, cols, vals);
      double sum = 0;
      unsigned int n = 0;
      for (unsigned int j = 0; j < x.size(); ++j)
        if (x[57].distance(x[j]) < 0.25)
          {
            sum += 1 - x[57].distance(x[j]) / 0.25;
            ++n;
          }
      testing::check(cols.size() == n, "filter: row 57 has the neighbours of the definition");
      for (unsigned int k = 0; k < cols.size(); ++k)
        testing::check_near(vals[k], (1 - x[57].distance(x[cols[k]]) / 0.25) / sum, 1e-15,
                            "filter: weight of row 57");
    }
    Design::DensityFilter tight(x, 1e-3);
    testing::check(tight.n_nonzeros() == cells.size(), "filter: a radius below the spacing gives P = I");

    testing::check_throws([&] { Design::DensityFilter f(x, -1.); }, "Filter radius", "filter: negative radius");
    Design::TopologyOptimizer::Settings s;
    s.volume_fraction = 1.5;
    testing::check_throws([&] { Design::TopologyOptimizer o(s); }, "Volume fraction", "optimizer: volume fraction");
    s.volume_fraction            = 0.5;
    s.interpolation.penalty      = 0.5;
    testing::check_throws([&] { Design::TopologyOptimizer o(s); }, "Penalization", "optimizer: SIMP exponent < 1");
    testing::check_throws([] { Design::parse_optimizer("SGD"); }, "Design/Optimizer", "optimizer: unknown name");

    // an unsupported body and a point load off the mesh
    PolygonalMesh<2> m2;
    PolygonalMeshGenerators::structured_quads(m2, P(0, 0), P(1, 1), 3, 3);
    Design::ElasticDesignProblem free(m2, two_laws(), 1);
    free.add_traction(1, T({1., 0.}));
    testing::check_throws([&] { free.setup(); }, "rigid-body motions free", "design problem: body without support");
    Design::ElasticDesignProblem off(m2, two_laws(), 1);
    off.add_support(0);
    off.add_point_load(P(0.5, 0.55), T({1., 0.}));
    testing::check_throws([&] { off.setup(); }, "no vertex of the mesh at (0.5, 0.55)",
                          "design problem: point load off the vertices");

    // densities carried between meshes: a constant stays constant; onto
    // the same mesh with a radius below the centroid spacing, the identity;
    // a coarse two-valued design onto a fine mesh keeps its values away
    // from the jump and averages across it
    {
      PolygonalMesh<2> coarse, fine;
      PolygonalMeshGenerators::structured_quads(coarse, P(0, 0), P(2, 1), 4, 2);
      PolygonalMeshGenerators::perturbed_quads(fine, P(0, 0), P(2, 1), 16, 8, 0.2, 3);
      const std::vector<double> c(coarse.n_cells(), 0.37);
      double                    err = 0;
      for (const double v : Design::transfer_densities(coarse, c, fine, 0.6))
        err = std::max(err, std::abs(v - 0.37));
      testing::check_small(err, 1e-15, "transfer: a constant stays constant");
      std::vector<double> r(fine.n_cells());
      for (unsigned int i = 0; i < r.size(); ++i)
        r[i] = (i % 7) / 7.;
      const auto same = Design::transfer_densities(fine, r, fine, 1e-3);
      testing::check(same == r, "transfer: onto the same mesh with a small radius, the identity");
      const auto centroids = [](const PolygonalMesh<2> &m) {
        std::vector<unsigned int> all(m.n_cells());
        for (unsigned int i = 0; i < all.size(); ++i)
          all[i] = i;
        return Design::cell_centroids(m, all);
      };
      const auto          coarse_x = centroids(coarse), fine_x = centroids(fine);
      std::vector<double> step(coarse.n_cells());
      for (unsigned int i = 0; i < step.size(); ++i)
        step[i] = coarse_x[i][0] < 1 ? 1. : 0.;
      const auto   carried = Design::transfer_densities(coarse, step, fine, 0.5);
      double       far_err = 0;
      unsigned int between = 0;
      for (unsigned int i = 0; i < carried.size(); ++i)
        {
          const double x = fine_x[i][0];
          if (std::abs(x - 1) > 0.8)
            far_err = std::max(far_err, std::abs(carried[i] - (x < 1 ? 1. : 0.)));
          else if (carried[i] > 0.01 && carried[i] < 0.99)
            ++between;
        }
      testing::check_small(far_err, 1e-15, "transfer: a two-valued design away from its jump");
      testing::check(between > 0, "transfer: averaged across the jump");
      testing::check_throws([&] { Design::transfer_densities(coarse, r, fine, 0.5); }, "densities for",
                            "transfer: wrong number of densities");
      testing::check_throws([&] { Design::transfer_densities(coarse, c, fine, 0.); }, "radius must be positive",
                            "transfer: zero radius");
      // the optimizer refuses initial densities of the wrong size or range
      Design::ElasticDesignProblem beam(fine, two_laws(), 1);
      beam.add_support(0);
      beam.add_traction(1, T({0., -1.}));
      beam.setup();
      Design::TopologyOptimizer::Settings settings;
      settings.filter_radius = 0.3;
      Design::TopologyOptimizer optimizer(settings);
      testing::check_throws([&] { optimizer.run(beam, std::vector<double>(3, 0.5)); }, "initial densities for",
                            "optimizer: initial densities of the wrong size");
      std::vector<double> bad(fine.n_cells(), 0.5);
      bad[5] = 1.5;
      testing::check_throws([&] { optimizer.run(beam, bad); }, "initial density of cell 5",
                            "optimizer: an initial density above 1");
    }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  pieces();
  for (const unsigned int k : {1u, 2u})
    {
      one_body(k);
      two_blocks_tied(k);
      two_blocks_interference(k);
      curved_base(k, Design::ElasticDesignProblem::Objective::compliance);
      curved_base(k, Design::ElasticDesignProblem::Objective::interface_force);
      curved_base(k, Design::ElasticDesignProblem::Objective::max_pressure);
      curved_base(k, Design::ElasticDesignProblem::Objective::compliance, ContactSettings::Tangential::penalty);
      constrained(k);
      chain(k, k == 1 ? Design::MaterialInterpolation::Type::simp : Design::MaterialInterpolation::Type::ramp);
    }
  return testing::finish();
}
