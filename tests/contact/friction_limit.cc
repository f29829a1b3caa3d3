// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The friction limit of an assembly is sharp (FrictionSolver: semismooth
// Newton iteration, and its continuation in the friction coefficient when
// that fails). A row of n = 6 unit blocks (weight 1 each: body force
// (0, -1), unit area) stands between two jaws of width 0.5: the left jaw is
// fixed, the right one is pushed against the row by the pressure P = 10 on
// its right edge, where it is held vertically; the contact pairs are found
// automatically, Coulomb friction with multipliers, k = 2, and every block
// is meshed on its own (Voronoi cells and quads of different counts), so no
// interface matches. Every vertical interface carries the normal force P.
// a) Right jaw guided (held vertically on its top edge too, so it can only
//    translate): the jaws carry the weight n by friction, so the row stands
//    if and only if mu >= mu_crit = n/(2P) = 0.3.
// b) Right jaw held on its right edge only (free to turn about a point of
//    that edge): its moment balance fixes where block n presses on it,
//    y_n = 1/2 + 1/80 + F_n/20 (F_n the friction force it carries, 1/80
//    from its own weight), and the centre of pressure of every interface
//    must stay on the interface (no tension: 0 <= y_k <= 1). The thrust line
//    rises by ((n-k) F_n - (n-k)^2/2)/P towards the middle, most at k = 3,
//    so y_3 = 1 bounds F_n <= F* = (1/2 - 1/80 + 9/20)/(7/20) = 2.678571...;
//    the left jaw must carry the rest, n - F_n <= mu P: the row stands if
//    and only if mu >= mu_rock = (n - F*)/P = 0.3321429 (friction and
//    rocking together; the friction bound n/(2P) alone is not enough).
// For each: mu = 1.01 mu_limit converges; the vertical friction forces of
// the two jaws on the row add up to its weight n to 1e-8 relative, every
// interface carries the normal force P to 1e-8 relative and obeys
// |T| <= mu N (1 + 1e-10), and its centre of pressure lies on it; and
// mu = 0.99 mu_limit stops with "No static equilibrium" (in b) the plain
// iteration cycles there, and the continuation decides).
// The proof at 0.99 (the Tresca fixed point's mechanism, FrictionSolver):
// in a) the failing condition is named "friction", the six blocks move
// down together by (0, -1) (1e-10) and nothing else moves, the work of the
// weights on that motion is n = 6 (1e-10) and the friction of the two jaw
// interfaces can absorb at most mu 2 P = 0.99 n = 5.94 of it (1e-8: the
// normal forces P are fixed by statics, so this is the exact limit
// analysis of the row); in b) the failing condition names friction too and
// the work exceeds what the bounds absorb.
// The globally convergent path gives the semismooth Newton solution: a)
// and b) at 1.01 solved once normally and once with 'Maximum active set
// iterations = 1', so that the plain iteration fails and FrictionSolver
// solves the stick problem and then Coulomb as a fixed point of Tresca
// problems: the same displacements (1e-9 of the largest) and the same
// pressures and tangential tractions at every pair (1e-8 of the largest).
// (The step of the plain iteration converges without continuation.)
// a) again with Coulomb friction by a penalty ('coulomb penalty'): the same
// checks at 1.01 and 0.99 (the Tresca problems then have Huber terms).
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/mesh/generators.h>

#include "../tests.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

using namespace dealvem;
using testing::check;
using testing::check_near;
using testing::check_small;
using testing::check_throws;

namespace
{
  constexpr unsigned int n_blocks = 6;
  constexpr double       P        = 10.; // pressure on the right jaw
  // a) friction only
  constexpr double mu_crit = n_blocks * 1. / (2 * P);
  // b) friction and rocking: the largest friction force of the right jaw
  // for which the thrust line stays on interface 3 (see above)
  constexpr double F_star  = (0.5 - 1. / 80 + 9. / 20) / (7. / 20);
  constexpr double mu_rock = (n_blocks - F_star) / P;

  std::shared_ptr<dealii::Function<2>>
  constant(const std::vector<double> &values)
  {
    return std::make_shared<dealii::Functions::ConstantFunction<2>>(values);
  }

  // Bodies 0 (left jaw), 1..n (the blocks [i-1, i] x [0, 1]) and n + 1
  // (right jaw); the boundary ids of body b are offset by 10 b.
  // Coulomb friction by a penalty ('coulomb penalty') instead of multipliers
  bool penalty_model = false;

  void
  build(ContactProblem &problem, const double mu, const bool guided)
  {
    const ElasticMaterial material(1000, 0.25, ElasticMaterial::Model::plane_strain);
    {
      PolygonalMesh<2> jaw;
      PolygonalMeshGenerators::structured_quads(jaw, dealii::Point<2>(-0.5, 0), dealii::Point<2>(0, 1), 2, 4);
      problem.add_body(jaw, material, 0);
    }
    for (unsigned int b = 1; b <= n_blocks; ++b)
      {
        PolygonalMesh<2>       block;
        const dealii::Point<2> p0(b - 1., 0), p1(b, 1);
        if (b % 2 == 1)
          PolygonalMeshGenerators::voronoi(block, p0, p1, 10 + b, 20, b);
        else
          PolygonalMeshGenerators::structured_quads(block, p0, p1, 1 + b / 2, 2 + b / 2);
        problem.add_body(block, material, 10 * b);
      }
    {
      PolygonalMesh<2> jaw;
      PolygonalMeshGenerators::structured_quads(jaw, dealii::Point<2>(n_blocks, 0),
                                                dealii::Point<2>(n_blocks + 0.5, 1), 2, 3);
      problem.add_body(jaw, material, 10 * (n_blocks + 1));
    }
    problem.detect_contact_pairs();
    auto &bc = problem.boundary_conditions();
    const dealii::types::boundary_id right = 10 * (n_blocks + 1) + 1;
    bc.add_dirichlet(0, {{true, true}}, constant({0., 0.}));
    bc.add_dirichlet(right, {{false, true}}, constant({0., 0.}));
    if (guided)
      bc.add_dirichlet(right + 2, {{false, true}}, constant({0., 0.}));
    bc.add_pressure(right, constant({P}));
    bc.set_body_force(constant({0., -1.}), "weight");
    auto &o                       = problem.options();
    o.degree                      = 2;
    o.contact.normal              = ContactSettings::Normal::unilateral;
    o.contact.tangential          = penalty_model ? ContactSettings::Tangential::coulomb_penalty :
                                                    ContactSettings::Tangential::coulomb;
    o.contact.friction_coefficient = mu;
    o.base_name                   = "friction-limit";
    o.write_vtu = o.write_json = o.write_pictures = o.write_csv = false;
  }

  void
  standing_row(const bool guided, const double ratio, const bool forced_fallback = false)
  {
    const double      mu  = ratio * (guided ? mu_crit : mu_rock);
    const std::string tag = std::string(guided ? "a) " : "b) ") + "mu = " + std::to_string(ratio).substr(0, 4) +
                            (guided ? " mu_crit" : " mu_rock") + (forced_fallback ? " (fixed point): " : ": ");
    ContactProblem    problem;
    build(problem, mu, guided);
    if (forced_fallback)
      problem.options().contact.max_active_set_iterations = 1;
    problem.run();
    const auto &r = problem.get_results();
    std::cout << tag << r.active_set_iterations << " Newton iterations (continuation included)" << std::endl;

    check(r.interface_results.size() == n_blocks + 1,
          tag + std::to_string(r.interface_results.size()) + " interfaces found, one per neighbouring pair of bodies");
    double       jaw_lift = 0, worst_cone = 0;
    unsigned int n_jaws   = 0;
    for (const auto &ir : r.interface_results)
      {
        const unsigned int a = std::min(ir.master_body, ir.slave_body), b = std::max(ir.master_body, ir.slave_body);
        check(b == a + 1, tag + "an interface joins neighbours " + std::to_string(a) + " and " + std::to_string(b));
        check_near(ir.normal_force, P, 1e-8 * P,
                   tag + "normal force of interface " + std::to_string(a) + "-" + std::to_string(b));
        worst_cone = std::max(worst_cone, std::abs(ir.tangential_force) - mu * ir.normal_force * (1 + 1e-10));
        check(ir.centre_of_pressure[1] >= -1e-10 && ir.centre_of_pressure[1] <= 1 + 1e-10,
              tag + "the centre of pressure of interface " + std::to_string(a) + "-" + std::to_string(b) +
                " lies on it (y = " + std::to_string(ir.centre_of_pressure[1]) + ")");
        if (a == 0 || b == n_blocks + 1)
          {
            // the vertical force of the jaw on the row (the resultant acts
            // on the slave body)
            const bool slave_is_jaw = (ir.slave_body == 0 || ir.slave_body == n_blocks + 1);
            jaw_lift += slave_is_jaw ? -ir.force[1] : ir.force[1];
            check_near(std::abs(ir.tangential_force), std::abs(ir.force[1]), 1e-10 * P,
                       tag + "a jaw interface is vertical: |T| = |F_y|");
            ++n_jaws;
          }
      }
    check(n_jaws == 2, tag + "two jaw interfaces");
    check_near(jaw_lift, n_blocks, 1e-8 * n_blocks, tag + "the jaws carry the weight of the row");
    check(worst_cone <= 0, tag + "every interface has |T| <= mu N (1 + 1e-10)");
    if (!forced_fallback)
      {
        // the same step through the globally convergent path
        ContactProblem other;
        build(other, mu, guided);
        other.options().contact.max_active_set_iterations = 1;
        other.run();
        const auto &q = other.get_results();
        double      umax = 0, du = 0, pmax = 0, dp = 0;
        for (unsigned int i = 0; i < r.solution.size(); ++i)
          {
            umax = std::max(umax, std::abs(r.solution[i]));
            du   = std::max(du, std::abs(r.solution[i] - q.solution[i]));
          }
        check(q.pairs.size() == r.pairs.size(), tag + "the fixed point has the same pairs");
        for (unsigned int i = 0; i < std::min(r.pairs.size(), q.pairs.size()); ++i)
          {
            pmax = std::max({pmax, std::abs(r.pairs[i].pressure), std::abs(r.pairs[i].tangential_traction)});
            dp   = std::max({dp, std::abs(r.pairs[i].pressure - q.pairs[i].pressure),
                             std::abs(r.pairs[i].tangential_traction - q.pairs[i].tangential_traction)});
          }
        std::cout << tag << "fixed point against Newton: displacements " << du / umax << ", tractions "
                  << dp / pmax << " (relative)" << std::endl;
        check(du <= 1e-9 * umax, tag + "the fixed point gives Newton's displacements (1e-9)");
        check(dp <= 1e-8 * pmax, tag + "the fixed point gives Newton's pressures and tractions (1e-8)");
      }
  }

  // the refusal at 0.99 and its proof
  void
  falling_row(const bool guided, const double mu, const std::string &tag)
  {
    ContactProblem problem;
    build(problem, mu, guided);
    check_throws([&] { problem.run(); }, "No static equilibrium", tag + ": no static equilibrium");
    const CollapseMechanism *m = problem.collapse_mechanism();
    check(m != nullptr, tag + ": a collapse mechanism is given");
    if (m == nullptr)
      return;
    std::cout << tag << ": " << m->failing_condition << "; work " << m->work << ", friction can absorb "
              << m->friction_dissipation << std::endl;
    check(m->failing_condition.find("friction") == 0, tag + ": the failing condition is friction");
    check(m->work > m->friction_dissipation, tag + ": the loads do more work than friction can absorb");
    check_small(m->largest_violation, 1e-10, tag + ": the motion violates no contact condition");
    if (guided)
      {
        check(m->moving.size() == n_blocks, tag + ": the six blocks move, nothing else");
        double off = 0;
        for (const auto &pm : m->moving)
          {
            check(pm.body >= 1 && pm.body <= n_blocks, tag + ": body " + std::to_string(pm.body) + " is a block");
            off = std::max({off, std::abs(pm.translation[0]), std::abs(pm.translation[1] + 1),
                            std::abs(pm.rotation)});
          }
        check_small(off, 1e-10, tag + ": every block translates by (0, -1)");
        check_near(m->work, n_blocks, 1e-10 * n_blocks, tag + ": work of the weights n");
        check_near(m->friction_dissipation, mu * 2 * P, 1e-8 * n_blocks,
                   tag + ": friction of the jaws absorbs mu 2 P at most");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               start = std::chrono::steady_clock::now();

  for (const bool guided : {true, false})
    {
      standing_row(guided, 1.01);
      falling_row(guided, 0.99 * (guided ? mu_crit : mu_rock),
                  guided ? "a) mu = 0.99 mu_crit" : "b) mu = 0.99 mu_rock");
    }
  // a) with the penalty variant of Coulomb friction: the same limit (the
  // springs only add elastic slip), the same proof, and the fixed point
  // (Huber-type Tresca terms) gives Newton's solution
  penalty_model = true;
  standing_row(true, 1.01);
  falling_row(true, 0.99 * mu_crit, "a) penalty, mu = 0.99 mu_crit");
  penalty_model = false;
  // b) with the friction bound alone the row would stand at 1.01 mu_crit; it
  // does not, since it would rock
  {
    ContactProblem problem;
    build(problem, 1.01 * mu_crit, false);
    check_throws([&] { problem.run(); }, "No static equilibrium",
                 "b) mu = 1.01 mu_crit < mu_rock: no static equilibrium");
  }

  std::cout << "run time: " << std::fixed << std::setprecision(1)
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s" << std::endl;
  return testing::finish();
}
