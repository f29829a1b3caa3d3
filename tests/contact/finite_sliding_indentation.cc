// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Finite sliding where the contact zone forms within a step on a curved
// side: a polygonal die (GridGenerator::half_hyper_ball, radius 1, refined
// twice, rounded side down, Neo-Hooke E = 1000, nu = 0.3) pressed into a
// soft Neo-Hooke slab (E = 1, nu = 0.3, [0, 8] x [0, 1], quads 64 x 8,
// bottom fixed) by 0.05 per step, Coulomb friction mu = 0.3, pairing
// tolerance 1e-6; k = 1 (4 steps) and k = 2 (3 steps).
// Two faults this test found:
// - the inserted vertices were mapped back by their parameter on the chord
//   of the original edge, not on the current trace of the last mesh: for
//   k = 1 the pairing stalled at an offset of 1.4e-3 of the sub-edges
//   (the sag of the kinked trace) in the first step;
// - with the die 1000 times stiffer than the slab, Newton's residual
//   floored at 1.3e-10 F_ref, above its tolerance, with updates of 1e-16
//   |u| (k = 2, step 3): FiniteStrainSolver now accepts round-off updates
//   with a residual up to 100 times the tolerance.
// Checked at every step: the step converges (at most 12 passes of the
// pairing, partners of active pairs within 1e-6 of the sub-edges), the
// contact conditions hold at every pair (gap >= -1e-10, pressure >= 0,
// gap = 0 to 1e-10 where the pressure is positive; lengths relative to
// the die radius), the Coulomb cone |lambda_t| <= mu |lambda_n| (to 1e-9),
// the contact force on the die grows from step to step and pushes it up,
// and k = 1 and k = 2 give the same force to 3 % (measured 2.7, 2.0 and
// 1.0 % at the three depths: the first step has three pairs in contact;
// 0.1-0.5 % while the die's inserted nodes lay on its chords, before
// issue 36 put them on its arcs: both orders then shared the chords'
// error, about 5e-3 of sag against a depth of 0.05).
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <dealvem/contact/finite_sliding.h>
#include <dealvem/contact/finite_strain_contact.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "../tests.h"

using namespace dealvem;

namespace
{
  std::vector<double>
  indent(const unsigned int degree, const unsigned int n_steps, const bool extrapolate = true)
  {
    std::vector<double> forces;
    const std::string what =
      "k = " + std::to_string(degree) + (extrapolate ? "" : ", first passes where the steps start") + ": ";
    const double      mu = 0.3, depth_per_step = 0.05;
    PolygonalMesh<2>  mesh, die;
    // slab ids: 0 left, 1 right, 2 bottom, 3 top
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(8, 1), 64, 8);
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::half_hyper_ball(tria, dealii::Point<2>(), 1.0);
    dealii::GridTools::rotate(-M_PI / 2, tria);
    const dealii::Point<2> centre(1.5, 2.0);
    dealii::GridTools::shift(dealii::Tensor<1, 2>(centre), tria);
    tria.reset_all_manifolds();
    tria.set_all_manifold_ids(dealii::numbers::flat_manifold_id);
    tria.set_all_manifold_ids_on_boundary(0, 1);
    const dealii::SphericalManifold<2> circle(centre);
    tria.set_manifold(1, circle);
    tria.refine_global(2);
    PolygonalMeshGenerators::from_triangulation(die, tria);
    // die ids: 10 the rounded side, 11 the flat top
    for (unsigned int c = 0; c < die.n_cells(); ++c)
      die.set_material_id(c, 1);
    for (unsigned int e = 0; e < die.n_edges(); ++e)
      if (die.edge(e).at_boundary())
        die.set_edge_boundary_id(e, die.edge(e).boundary_id + 10);
    mesh.append(die);

    const NeoHookeMaterial slab_law(1.0, 0.3), die_law(1000., 0.3);
    MaterialLibrary<2>     laws;
    laws.add(0, slab_law);
    laws.add(1, die_law);
    FiniteSliding::Parameters parameters;
    parameters.degree             = degree;
    parameters.pairing_tolerance  = 1e-6;
    parameters.max_pairing_passes = 12;
    parameters.extrapolate        = extrapolate;
    FiniteSliding sliding(mesh, laws, {{3, 10, mu}}, parameters);
    sliding.set_constraints_function(
      [&](const VEMDoFHandler<2> &dofs, const double t, dealii::AffineConstraints<double> &constraints) {
        const auto &m = dofs.get_mesh();
        for (unsigned int e = 0; e < m.n_edges(); ++e)
          {
            const auto &edge = m.edge(e);
            if (!edge.at_boundary() || (edge.boundary_id != 2 && edge.boundary_id != 11))
              continue;
            std::vector<unsigned int> nodes = {dofs.vertex_node(edge.vertices[0]),
                                               dofs.vertex_node(edge.vertices[1])};
            if (degree == 2)
              nodes.push_back(dofs.edge_node(e));
            for (const auto node : nodes)
              for (unsigned int comp = 0; comp < 2; ++comp)
                {
                  const auto dof = VEMDoFHandler<2>::node_dof(node, comp);
                  if (constraints.is_constrained(dof))
                    continue;
                  constraints.add_line(dof);
                  constraints.set_inhomogeneity(dof, (edge.boundary_id == 11 && comp == 1) ? -depth_per_step * t : 0.);
                }
          }
        constraints.close();
      });

    double       worst_gap = 0, worst_complementarity = 0, worst_cone = 0, worst_offset = 0;
    double       last_force = 0, min_pressure = 0;
    unsigned int max_passes = 0;
    bool         growing = true, converged = true;
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        try
          {
            sliding.solve_step(n, n);
          }
        catch (const std::exception &e)
          {
            std::cout << what << "step " << n << " failed: " << e.what() << std::endl;
            converged = false;
            break;
          }
        const auto &record  = sliding.get_history().back();
        const auto &u       = sliding.get_solution();
        const auto &lambda  = sliding.get_multipliers();
        const auto &contact = sliding.get_contact();
        const auto  np      = contact.n_pairs();
        for (unsigned int i = 0; i < np; ++i)
          {
            if (contact.is_left_out(i))
              continue;
            const double g = contact.value(i, u);
            worst_gap      = std::max(worst_gap, -g);
            min_pressure   = std::min(min_pressure, -lambda[i]);
            if (lambda[i] != 0)
              worst_complementarity = std::max(worst_complementarity, std::abs(g));
            worst_cone = std::max(worst_cone, std::abs(lambda[np + i]) - mu * std::abs(lambda[i]) *
                                                                             (1 + 1e-9));
          }
        worst_offset = std::max(worst_offset, record.pairing_offset);
        max_passes   = std::max(max_passes, record.n_passes);
        // the contact force on the die (the slave side) pushes it up
        const double force = record.normal_force[0][1];
        forces.push_back(force);
        growing            = growing && force > last_force;
        last_force         = force;
        std::cout << "  " << what << "step " << n << ": " << record.n_active << " active, " << record.n_slipping
                  << " slipping, " << record.n_passes << " passes (offsets";
        for (const double o : record.pairing_offsets)
          std::cout << " " << o;
        std::cout << "), normal force " << record.normal_force[0] << ", friction force " << record.friction_force[0]
                  << std::endl;
      }
    testing::check(converged, what + "every step converges");
    testing::check(max_passes <= 12, what + "at most 12 passes of the pairing per step (" +
                                       std::to_string(max_passes) + ")");
    testing::check_small(worst_offset, 1e-6, what + "partners of active pairs coincide at convergence");
    testing::check_small(worst_gap, 1e-10, what + "no pair penetrates (gap / die radius)");
    testing::check_small(worst_complementarity, 1e-10, what + "pairs that carry a pressure are closed");
    testing::check(min_pressure >= 0, what + "no pair pulls");
    testing::check(worst_cone <= 1e-12, what + "the friction force stays in the Coulomb cone");
    testing::check(growing && last_force > 0, what + "the contact force on the die grows with the depth and pushes it up");
    return forces;
  }
} // namespace

int
main()
{
  const auto f1 = indent(1, 4);
  const auto f2 = indent(2, 3);
  // two discretizations of one problem: the die forces agree to a few
  // percent (measured 2.7, 2.0, 1.0 %, falling as the contact zone grows)
  double worst = 0;
  for (unsigned int n = 0; n < std::min(f1.size(), f2.size()); ++n)
    worst = std::max(worst, std::abs(f1[n] - f2[n]) / f2[n]);
  testing::check(f1.size() >= 3 && f2.size() >= 3, "both runs reach the depth 0.15");
  testing::check_small(worst, 0.03, "k = 1 and k = 2 give the same die force (relative difference)");
  // the same k = 1 run with no predictor: each step's first pass pairs
  // where the step starts; the die's new contacts (its edge pairs close
  // step by step) and the slab's snapped vertices end where they did
  const auto f0   = indent(1, 4, false);
  double     diff = f0.size() == f1.size() ? 0. : 1.;
  for (unsigned int n = 0; n < f1.size() && diff < 1; ++n)
    diff = std::max(diff, std::abs(f0[n] - f1[n]) / f1[n]);
  std::cout << "k = 1, die force with and without the predictor: " << diff << std::endl;
  // (measured 2.5e-8, with the pairing tolerance 1e-6)
  testing::check_small(diff, 1e-6, "k = 1: die force with the first passes unpredicted against predicted");
  return testing::finish();
}
