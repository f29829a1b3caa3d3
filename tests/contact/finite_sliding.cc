// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Finite sliding (FiniteSliding: node insertion made again in the current
// configuration at every step, Coulomb friction by multipliers).
//
// The two bodies: a base [0,3]x[0,1] (quads 12 x 4, Neo-Hooke E = 1000,
// nu = 0.3, top id 3: master) and a block [0.25,1.25]x[1,2] (a Voronoi mesh
// of 49 cells, Saint Venant-Kirchhoff E = 300, nu = 0.25, bottom id 12:
// slave); non-matching meshes. The exact solution: both bodies carry the
// same uniform Cauchy stress sigma = [[0, mu p], [mu p, -p]] (p = 30,
// mu = 0.3: the block pressed on the base with the pressure p and sliding
// to the right, the friction mu p against it), each with its own
// homogeneous deformation F = [[a, b], [0, c]] (solved from sigma(F) by
// Newton; F e_1 is horizontal, so the interface stays the line y = c_base),
// the block moved by (d(t), c_base - c_block) on top of it.
// The boundary except the contact sides gets the exact values (Dirichlet,
// at the time of the step), and so do the nodes of the base's top outside
// the part the block covers at the end of the step (the contact patch test
// of a part of the base: a free node of the base must have its whole
// tributary length under the block). The block slides by d(t) up to six of
// its element lengths in 24 steps (a quarter of an element per step).
// (a) k = 1 and 2, at every step: the DoFs equal the exact solution to 1e-9
//     of the largest displacement, every pair with a free node is active
//     and slips, the Cauchy pressure -lambda_n / w(u) is p and the friction
//     traction |lambda_t| / w(u) is mu p at every such pair to 1e-8 relative
//     (the friction force on the block against its slide), the
//     dissipation of every step after the first (StepRecord::dissipation)
//     the friction force times the slide of the step to 1e-8
//     (so the force history has no jump when the pairs change), the
//     partners coincide at convergence (pairing offset <= 1e-10 of the
//     sub-edges at the pair, the tolerance set here),
//     from the third step on (pairs made at the extrapolated state) at most
//     two passes of pairing and Newton per step (without the rotation),
//     the mesh gets new vertices every step, and the block has slid by at
//     least five element lengths in the end.
// (b) Objectivity: the same problem with both bodies turned rigidly by
//     R(90 degrees t) as they slide (k = 2, 12 steps): at every step the
//     contact forces are R times those of the unrotated run to 1e-9 of
//     their size.
// (c) Frictionless sliding (mu = 0) of the same block: the exact stress is
//     sigma = diag(0, -p); pressures p to 1e-8, no friction force.
// (d) Bad input: no constraints function, a negative friction coefficient,
//     friction with tied contact, degree 3.
#include <deal.II/base/function.h>

#include <dealvem/contact/finite_sliding.h>
#include <dealvem/contact/finite_strain_contact.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <cmath>
#include <iostream>

#include "../tests.h"

using namespace dealvem;

namespace
{
  constexpr double p_contact = 30;

  dealii::Tensor<2, 2>
  rotation(const double phi)
  {
    dealii::Tensor<2, 2> R;
    R[0][0] = std::cos(phi);
    R[0][1] = -std::sin(phi);
    R[1][0] = std::sin(phi);
    R[1][1] = std::cos(phi);
    return R;
  }

  // F = [[a, b], [0, c]] with sigma(F) = target, by Newton with a
  // difference Jacobian
  dealii::Tensor<2, 2>
  deformation_for(const HyperelasticMaterial &law, const dealii::Tensor<2, 2> &target)
  {
    double x[3] = {1, 0, 1};
    const auto residual = [&](const double *y, double *r) {
      dealii::Tensor<2, 2> F;
      F[0][0] = y[0];
      F[0][1] = y[1];
      F[1][1] = y[2];
      const auto s = law.cauchy_stress(F);
      r[0]         = s[0][0] - target[0][0];
      r[1]         = s[0][1] - target[0][1];
      r[2]         = s[1][1] - target[1][1];
    };
    for (unsigned int it = 0; it < 50; ++it)
      {
        double r[3], J[3][3];
        residual(x, r);
        if (std::abs(r[0]) + std::abs(r[1]) + std::abs(r[2]) < 1e-13 * law.characteristic_stiffness())
          break;
        for (unsigned int j = 0; j < 3; ++j)
          {
            double y[3] = {x[0], x[1], x[2]}, rp[3], rm[3];
            y[j] += 1e-7;
            residual(y, rp);
            y[j] -= 2e-7;
            residual(y, rm);
            for (unsigned int i = 0; i < 3; ++i)
              J[i][j] = (rp[i] - rm[i]) / 2e-7;
          }
        // 3x3 solve by Cramer's rule
        const auto det = [](const double M[3][3]) {
          return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                 M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
        };
        const double D = det(J);
        for (unsigned int j = 0; j < 3; ++j)
          {
            double M[3][3];
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                M[a][b] = (b == j) ? r[a] : J[a][b];
            x[j] -= det(M) / D;
          }
      }
    dealii::Tensor<2, 2> F;
    F[0][0] = x[0];
    F[0][1] = x[1];
    F[1][1] = x[2];
    const auto s = law.cauchy_stress(F);
    testing::check_small((s - target).norm() / target.norm(), 1e-11, "the homogeneous F has the target stress");
    return F;
  }

  struct Setup
  {
    unsigned int degree     = 1;
    double       mu         = 0.3;
    double       turn       = 0; // total rigid rotation (radians) over the run
    unsigned int n_steps    = 24;
    double       n_elements = 6; // slide, in block element lengths
  };

  struct Result
  {
    std::vector<dealii::Tensor<1, 2>> normal_force, friction_force;
  };

  Result
  slide(const Setup &setup)
  {
    const std::string what = "k = " + std::to_string(setup.degree) + ", mu = " + std::to_string(setup.mu) +
                             (setup.turn != 0 ? ", turning" : "") + ": ";
    PolygonalMesh<2> mesh, block;
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(3, 1), 12, 4);
    PolygonalMeshGenerators::voronoi(block, dealii::Point<2>(0.25, 1), dealii::Point<2>(1.25, 2), 49, 30, 7);
    for (unsigned int c = 0; c < block.n_cells(); ++c)
      block.set_material_id(c, 1);
    for (unsigned int e = 0; e < block.n_edges(); ++e)
      if (block.edge(e).at_boundary())
        block.set_edge_boundary_id(e, block.edge(e).boundary_id + 10);
    // the block's element length: its longest bottom edge
    double h_block = 0;
    for (unsigned int e = 0; e < block.n_edges(); ++e)
      if (block.edge(e).at_boundary() && block.edge(e).boundary_id == 12)
        h_block = std::max(h_block, block.vertex(block.edge(e).vertices[0]).distance(
                                      block.vertex(block.edge(e).vertices[1])));
    mesh.append(block);

    const NeoHookeMaterial             base_law(1000, 0.3);
    const SaintVenantKirchhoffMaterial block_law(300, 0.25);
    dealii::Tensor<2, 2>               sigma;
    sigma[0][1] = sigma[1][0] = setup.mu * p_contact;
    sigma[1][1]               = -p_contact;
    const auto F_base  = deformation_for(base_law, sigma);
    const auto F_block = deformation_for(block_law, sigma);
    MaterialLibrary<2> laws;
    laws.add(0, base_law);
    laws.add(1, block_law);

    // the slide d(t) (current configuration), the block's ends on the
    // base at the time t (unrotated frame), the rotation
    const double slide_total = setup.n_elements * h_block * F_block[0][0];
    const auto   d           = [&](const double t) { return slide_total * t; };
    const double x_left0 = F_block[0][0] * 0.25 + F_block[0][1] * 1, x_right0 = F_block[0][0] * 1.25 + F_block[0][1];
    const double shift_y = F_base[1][1] - F_block[1][1];
    // the exact position of a material point X of body b at time t
    const auto exact_position = [&](const dealii::Point<2> &X, const bool in_block, const double t) {
      dealii::Tensor<1, 2> x = (in_block ? F_block : F_base) * X;
      if (in_block)
        {
          x[0] += d(t);
          x[1] += shift_y;
        }
      return dealii::Point<2>(rotation(setup.turn * t) * x);
    };

    FiniteSliding::Parameters parameters;
    parameters.degree = setup.degree;
    // the homogeneous solution is found to round-off: pair to 1e-10 (the
    // default 1e-8 leaves pressure errors of that order)
    parameters.pairing_tolerance = 1e-10;
    FiniteSliding sliding(mesh, laws, {{3, 12, setup.mu}}, parameters);
    const double  h_tol = 1e-6 * h_block;
    sliding.set_constraints_function([&](const VEMDoFHandler<2> &dofs, const double t,
                                         dealii::AffineConstraints<double> &constraints) {
      const auto &m = dofs.get_mesh();
      // the nodes of the boundary except the contact sides, and of the
      // base's top outside the block's span at t
      std::vector<bool> prescribed(dofs.n_nodes(), false), on_block(dofs.n_nodes(), false);
      const double      xl = x_left0 + d(t), xr = x_right0 + d(t);
      for (unsigned int e = 0; e < m.n_edges(); ++e)
        {
          const auto &edge = m.edge(e);
          if (!edge.at_boundary())
            continue;
          const bool in_block = m.cell(edge.cells[0]).material_id == 1;
          std::vector<unsigned int> nodes = {dofs.vertex_node(edge.vertices[0]), dofs.vertex_node(edge.vertices[1])};
          if (setup.degree == 2)
            nodes.push_back(dofs.edge_node(e));
          for (const auto node : nodes)
            {
              on_block[node] = in_block;
              if (edge.boundary_id == 12)
                continue;
              if (edge.boundary_id == 3)
                {
                  const double x = (F_base * dofs.node_location(node))[0];
                  if (x > xl + h_tol && x < xr - h_tol)
                    continue;
                }
              prescribed[node] = true;
            }
        }
      for (unsigned int node = 0; node < dofs.n_nodes(); ++node)
        if (prescribed[node])
          {
            const dealii::Point<2> X = dofs.node_location(node);
            const dealii::Point<2> x = exact_position(X, on_block[node], t);
            for (unsigned int comp = 0; comp < 2; ++comp)
              {
                const auto dof = VEMDoFHandler<2>::node_dof(node, comp);
                constraints.add_line(dof);
                constraints.set_inhomogeneity(dof, x[comp] - X[comp]);
              }
          }
      constraints.close();
    });

    Result       result;
    double       worst_u = 0, worst_p = 0, worst_q = 0, worst_offset = 0, min_inserted = 1e9, worst_d = 0;
    unsigned int max_passes = 0, max_later_passes = 0, min_active = 1000000, min_slipping = 1000000, total_newton = 0;
    bool         all_active = true, against = true;
    for (unsigned int n = 1; n <= setup.n_steps; ++n)
      {
        const double t = static_cast<double>(n) / setup.n_steps;
        sliding.solve_step(n, t);
        const auto &record  = sliding.get_history().back();
        const auto &dofs    = sliding.get_dof_handler();
        const auto &u       = sliding.get_solution();
        const auto &lambda  = sliding.get_multipliers();
        const auto &contact = sliding.get_contact();
        // the displacement (at the moment nodes the mean of the affine
        // field: its value at the centroid, the node's location)
        double                    u_max = 0, err = 0;
        std::vector<int>          body(dofs.n_nodes(), -1);
        std::vector<unsigned int> cell_nodes;
        for (unsigned int c = 0; c < dofs.get_mesh().n_cells(); ++c)
          {
            dofs.get_node_indices(c, cell_nodes);
            for (const auto node : cell_nodes)
              body[node] = dofs.get_mesh().cell(c).material_id;
          }
        for (unsigned int node = 0; node < dofs.n_nodes(); ++node)
          {
            const dealii::Point<2> X = dofs.node_location(node);
            const dealii::Point<2> x = exact_position(X, body[node] == 1, t);
            for (unsigned int comp = 0; comp < 2; ++comp)
              {
                err   = std::max(err, std::abs(u[VEMDoFHandler<2>::node_dof(node, comp)] - (x[comp] - X[comp])));
                u_max = std::max(u_max, std::abs(x[comp] - X[comp]));
              }
          }
        worst_u = std::max(worst_u, err / u_max);
        // pressures and friction tractions
        const auto         w  = contact.current_weights(u);
        const unsigned int np = contact.n_pairs();
        for (unsigned int i = 0; i < np; ++i)
          {
            if (contact.is_left_out(i))
              continue;
            if (lambda[i] == 0)
              {
                all_active = false;
                continue;
              }
            worst_p = std::max(worst_p, std::abs(-lambda[i] / w[i] / p_contact - 1));
            if (setup.mu > 0)
              worst_q = std::max(worst_q, std::abs(std::abs(lambda[np + i]) / w[i] / (setup.mu * p_contact) - 1));
          }
        // the friction work of the step: every pair slips by the slide of
        // the step (the deformations are those of step 1 from then on)
        if (setup.mu > 0 && n >= 2)
          {
            double sum = 0;
            for (unsigned int i = 0; i < np; ++i)
              if (!contact.is_left_out(i))
                sum += std::abs(lambda[np + i]);
            worst_d = std::max(worst_d, std::abs(record.dissipation / (sum * slide_total / setup.n_steps) - 1));
          }
        worst_offset = std::max(worst_offset, record.pairing_offset);
        max_passes   = std::max(max_passes, record.n_passes);
        if (n >= 3)
          max_later_passes = std::max(max_later_passes, record.n_passes);
        min_active   = std::min(min_active, record.n_active);
        min_slipping = std::min(min_slipping, record.n_slipping);
        min_inserted = std::min<double>(min_inserted, record.n_inserted);
        for (const auto &r : record.newton)
          for (const auto &it : r.iterations)
            total_newton += (it.step_length > 0 ? 1 : 0);
        // the friction on the block opposes its slide (+x, turned)
        const dealii::Tensor<1, 2> slide_direction = rotation(setup.turn * t) * dealii::Tensor<1, 2>({1., 0.});
        if (setup.mu > 0)
          against = against && record.friction_force[0] * slide_direction < -0.99 * record.friction_force[0].norm();
        result.normal_force.push_back(record.normal_force[0]);
        result.friction_force.push_back(record.friction_force[0]);
        if (n == 1 || n == setup.n_steps || n % 6 == 0)
          std::cout << "  " << what << "step " << n << ": " << record.n_pairs << " pairs, " << record.n_active
                    << " active, " << record.n_slipping << " slipping, " << record.n_inserted << " inserted, "
                    << record.n_dofs << " DoFs, " << record.n_passes << " passes, pairing offset "
                    << record.pairing_offset << ", N = " << record.normal_force[0] << ", T = " << record.friction_force[0]
                    << std::endl;
      }
    std::cout << "  " << what << total_newton << " Newton updates in " << setup.n_steps << " steps, at most "
              << max_passes << " passes per step" << std::endl;
    testing::check_small(worst_u, 1e-9, what + "the displacement is the exact one at every node and step");
    testing::check(all_active && min_active > 4, what + "every pair with a free node is active");
    testing::check_small(worst_p, 1e-8, what + "pressure p at every pair and step");
    if (setup.mu > 0)
      {
        testing::check_small(worst_q, 1e-8, what + "friction traction mu p at every pair and step");
        testing::check(min_slipping == min_active, what + "every active pair slips");
        testing::check(against, what + "the friction force on the block opposes its slide");
        testing::check_small(worst_d, 1e-8,
                             what + "the dissipation of a step is the friction force times the slide of the step");
      }
    testing::check_small(worst_offset, 1e-10, what + "partners coincide at convergence");
    // from the third step on, the pairs are made where the extrapolation
    // of the last two steps puts the bodies: one pass (measured) or two
    // (the rotation of the turning run is not linear in time: its
    // extrapolation is off by the chord error, and a step takes up to
    // max_pairing_passes passes; only reported)
    if (setup.turn == 0)
      testing::check(max_later_passes <= 2, what + "at most two passes of the pairing per step from step 3 on (" +
                                              std::to_string(max_later_passes) + ")");
    testing::check(min_inserted > 0, what + "nodes are inserted at every step");
    testing::check(slide_total / (h_block * F_block[0][0]) >= 5, what + "the block slides five element lengths");
    return result;
  }
} // namespace



int
main()
{
  std::cout << "(a) sliding patch test" << std::endl;
  Setup setup;
  for (const unsigned int k : {1u, 2u})
    {
      setup.degree = k;
      slide(setup);
    }

  std::cout << "(b) objectivity" << std::endl;
  {
    Setup plain;
    plain.degree  = 2;
    plain.n_steps = 12;
    Setup turning = plain;
    turning.turn  = M_PI / 2;
    const Result a = slide(plain), b = slide(turning);
    double       worst = 0, scale = 0;
    for (unsigned int n = 0; n < a.normal_force.size(); ++n)
      {
        const auto R = rotation(turning.turn * (n + 1.) / plain.n_steps);
        worst        = std::max({worst, (R * a.normal_force[n] - b.normal_force[n]).norm(),
                                 (R * a.friction_force[n] - b.friction_force[n]).norm()});
        scale        = std::max(scale, a.normal_force[n].norm());
      }
    testing::check_small(worst / scale, 1e-9, "the contact forces turn with the bodies");
  }

  std::cout << "(c) frictionless" << std::endl;
  {
    Setup frictionless;
    frictionless.mu      = 0;
    frictionless.n_steps = 12;
    const Result r       = slide(frictionless);
    double       t_max   = 0;
    for (const auto &f : r.friction_force)
      t_max = std::max(t_max, f.norm());
    testing::check_small(t_max, 1e-12, "no friction force without friction");
  }

  std::cout << "(d) bad input" << std::endl;
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 2, 2);
    MaterialLibrary<2> laws;
    laws.add(0, NeoHookeMaterial(1000, 0.3));
    FiniteSliding::Parameters parameters;
    testing::check_throws([&] { FiniteSliding(mesh, laws, {{3, 12, -0.1}}, parameters); },
                          "has the friction coefficient -0.1", "negative friction coefficient");
    parameters.degree = 3;
    testing::check_throws([&] { FiniteSliding(mesh, laws, {{3, 12, 0}}, parameters); }, "the degree must be 1 or 2",
                          "degree 3");
    parameters.degree = 1;
    parameters.normal = ContactSettings::Normal::tied;
    testing::check_throws([&] { FiniteSliding(mesh, laws, {{3, 12, 0.2}}, parameters); },
                          "has friction, but the contact is tied", "friction with tied contact");
    parameters.normal = ContactSettings::Normal::unilateral;
    FiniteSliding sliding(mesh, laws, {{3, 12, 0}}, parameters);
    testing::check_throws([&] { sliding.solve_step(1, 0.1); }, "set_constraints_function() must be called",
                          "no constraints function");
  }
  return testing::finish();
}
