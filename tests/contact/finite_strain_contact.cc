// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Contact at finite strain, small sliding (FiniteStrainContact with
// FiniteStrainSolver): two stacked blocks [0,1]x[0,1] (body 0, quads,
// master side on top, id 3) and [0,1]x[1,2] (body 1, Voronoi, slave side
// at the bottom, id 12), non-matching meshes made matching by node
// insertion; plane strain Neo-Hooke, E = 7000, nu = 0.3.
// (a) The linearization: the gradient and the Hessian of every constraint
//     (unilateral and tied, normal from the master, the slave or the
//     bisector, k = 1 and 2) at a random displacement of 5 % of the size
//     against central differences: relative error below 1e-6, and the
//     Hessian symmetric to 1e-12.
// (b) The contact patch test at finite strain: the bottom (id 2) and the
//     top (id 13) get the homogeneous deformation F = R(phi) diag(l1, 0.7)
//     (30 % compression; l1 the lateral stretch of plane strain uniaxial
//     stress, so the sides are free of traction), phi = 0, 30 and 90
//     degrees, in 10 load steps; unilateral and tied contact, k = 1 and 2.
//     Every DoF equals (F - I) X to 1e-10 of the largest displacement, every
//     pair is active with |g| <= 1e-12, the Cauchy pressure -lambda/w(u) is
//     the exact -sigma_yy of diag(l1, 0.7) at every pair to 1e-8 relative,
//     and tied tangential multipliers vanish to 1e-8 of the normal ones.
// (c) Two materials (E = 7000 below, 700 above), confined (rollers on the
//     sides, bottom held, top moved down by 0.6: 30 % of the height):
//     each block is homogeneous, F = diag(1, l_a) and diag(1, l_b), with
//     l_a + l_b = 1.4 and equal sigma_yy; the pressure at every pair matches
//     to 1e-8.
// (d) Newton: the last iterations of the last step converge quadratically
//     (|r_{i+1}| / |r_i|^2 bounded, relative to F_ref).
// (f) Where the slip of Coulomb friction starts, on a curved interface:
//     both blocks bent onto a circle of radius 1.5 (the base configuration,
//     partners on top of each other); at the slip origin the upper block's
//     interface nodes lie on the lower block's side (its polygon, k = 1, or
//     its quadratic pieces, k = 2) shifted along it by delta = 0.15. Every
//     pair was in contact there, so its slip at the base is the shift:
//     |s| = delta to 10 % (measured 3 % for k = 1, 4 % for k = 2: the chord
//     between the two material points and the turned tangent are not the
//     arc). A pair taken for a new contact has s = 0: the chord between two
//     points of a curved side, read as a gap, once did that (k = 2 here;
//     k = 1 across the corners of a polygon, examples/step-11). With the
//     upper side lifted off the lower one by 0.02 at the origin instead,
//     every pair is a new contact: s = 0 to 1e-12. The pairs whose slave
//     point was beyond the end of the lower side at the origin are left
//     out.
// (g) A sub-edge far shorter than the others: a vertex of the lower side
//     moved to 5e-4 from a vertex of the upper side, node insertion with
//     merge_fraction 1e-12 (FiniteSliding inserts with 1e-9), so that the
//     interface has a sub-edge 5e-4 long (and, for k = 2, a midpoint pair
//     on it, whose chord is that sub-edge; node insertion merges closer
//     vertices). Every gradient stays of the size of the geometry (below 10
//     at a random affine displacement of size 1e-2 and a slide of the slave
//     nodes by 0.02 along the interface) and agrees with central differences
//     to 1e-6: the normal of a pair is not turned by a chord much shorter
//     than the sub-edges (without the lengthening of such chords the
//     midpoint pair's gradient is 40 here, 20 with the bisector normal;
//     measured 1.0-1.1 with it; a chord 7e-12 long on a gear
//     flank gave gap derivatives of 5e5, and Newton cycled between two
//     active sets in a finite-sliding step of
//     contact/finite_sliding_gear_cycle graded to 0.005.)
// (e) Bad input: set_constraints() with constraints on other DoFs, and a
//     prescribed motion that pushes the fully constrained interface nodes
//     of the two blocks into each other (both blocks held on their whole
//     boundary), are errors that say what is wrong; so are the Trilinos
//     solvers of SaddlePointSolver in a program without MPI_Init (this
//     test has none), which used to abort inside Epetra.
#include <deal.II/base/function.h>

#include <dealvem/contact/finite_strain_contact.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/finite_strain_solver.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/solvers/saddle_point_solver.h>

#include <cmath>
#include <iostream>
#include <random>
#include <set>
#include <algorithm>

#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
  // lower block quads, upper block Voronoi (material id 1, ids + 10)
  void
  two_blocks(PolygonalMesh<2> &mesh, const unsigned int n_lower, const unsigned int n_upper)
  {
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), n_lower, n_lower);
    PolygonalMesh<2> upper;
    PolygonalMeshGenerators::voronoi(upper, dealii::Point<2>(0, 1), dealii::Point<2>(1, 2), n_upper, 30, 5);
    for (unsigned int c = 0; c < upper.n_cells(); ++c)
      upper.set_material_id(c, 1);
    for (unsigned int e = 0; e < upper.n_edges(); ++e)
      if (upper.edge(e).at_boundary())
        upper.set_edge_boundary_id(e, upper.edge(e).boundary_id + 10);
    mesh.append(upper);
  }

  // the lateral stretch l1 with sigma_xx(diag(l1, l2)) = 0
  double
  lateral_stretch(const HyperelasticMaterial &law, const double l2)
  {
    double lo = 0.5, hi = 2.0;
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double         mid = 0.5 * (lo + hi);
        dealii::Tensor<2, 2> F;
        F[0][0] = mid;
        F[1][1] = l2;
        (law.cauchy_stress(F)[0][0] > 0 ? hi : lo) = mid;
      }
    return 0.5 * (lo + hi);
  }

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

  // u moved by +-h in the DoF @p dof, and the central difference of
  // constraint @p j there
  struct Perturbed
  {
    dealii::Vector<double> up, um;
    double                 difference;
  };

  Perturbed
  perturb(const FiniteStrainContact &contact, const unsigned int j, const dealii::Vector<double> &u,
          const unsigned int dof, const double h)
  {
    Perturbed p{u, u, 0.};
    p.up[dof] += h;
    p.um[dof] -= h;
    p.difference = (contact.value(j, p.up) - contact.value(j, p.um)) / (2 * h);
    return p;
  }

  // (a)
  void
  check_linearization(const unsigned int k, const ContactSettings::Normal model,
                      const NodeInsertion::Interface::NormalSide side)
  {
    PolygonalMesh<2> mesh;
    two_blocks(mesh, 3, 9);
    std::vector<NodeInsertion::Interface> interfaces = {NodeInsertion::insert(mesh, 3, 12, k, {})};
    interfaces[0].normal_side = side;
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(k);
    FiniteStrainContact contact(dof_handler, interfaces, model, 7000.);
    std::mt19937                           gen(17 + k);
    std::uniform_real_distribution<double> dist(-0.05, 0.05);
    dealii::Vector<double>                 u(dof_handler.n_dofs());
    for (auto &x : u)
      x = dist(gen);
    const double h = 1e-6;
    double       grad_err = 0, hess_err = 0, asym = 0, grad_scale = 0, hess_scale = 0;
    FiniteStrainContact::Linearization lin, lp, lm;
    for (unsigned int j = 0; j < contact.n_constraints(); ++j)
      {
        contact.linearize(j, u, lin, true);
        testing::check_near(lin.value, contact.value(j, u), 1e-15, "value() and linearize() agree");
        for (unsigned int a = 0; a < lin.dofs.size(); ++a)
          {
            const Perturbed p = perturb(contact, j, u, lin.dofs[a], h);
            grad_err          = std::max(grad_err, std::abs(p.difference - lin.gradient[a]));
            grad_scale        = std::max(grad_scale, std::abs(lin.gradient[a]));
            contact.linearize(j, p.up, lp, false);
            contact.linearize(j, p.um, lm, false);
            for (unsigned int b = 0; b < lin.dofs.size(); ++b)
              {
                const double fd2 = (lp.gradient[b] - lm.gradient[b]) / (2 * h);
                hess_err         = std::max(hess_err, std::abs(fd2 - lin.hessian(b, a)));
                hess_scale       = std::max(hess_scale, std::abs(lin.hessian(b, a)));
                asym             = std::max(asym, std::abs(lin.hessian(a, b) - lin.hessian(b, a)));
              }
          }
      }
    const std::string what = "k = " + std::to_string(k) + ", " + ContactSettings::normal_name(model) +
                             ", normal side " + std::to_string(static_cast<int>(side)) + ": ";
    testing::check(hess_scale > 1e-3, what + "the Hessians are not zero (the normals turn)");
    testing::check_small(grad_err / grad_scale, 1e-6, what + "gradient against central differences");
    testing::check_small(hess_err / hess_scale, 1e-6, what + "Hessian against central differences");
    testing::check_small(asym / hess_scale, 1e-12, what + "Hessian symmetry");
  }

  // (g)
  void
  short_sub_edge(const unsigned int k, const NodeInsertion::Interface::NormalSide side)
  {
    PolygonalMesh<2> mesh;
    two_blocks(mesh, 3, 9);
    // the upper side's interface vertex closest to x = 1/3 or 2/3, and the
    // lower side's vertex there, moved along y = 1 to 1e-10 from it
    unsigned int upper = 0, lower = 0;
    double       best  = 1;
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      if (std::abs(mesh.vertex(v)[1] - 1) < 1e-12)
        for (const double x : {1. / 3, 2. / 3})
          if (std::abs(mesh.vertex(v)[0] - x) > 1e-9 && std::abs(mesh.vertex(v)[0] - x) < best &&
              mesh.vertex(v)[0] > 0 && mesh.vertex(v)[0] < 1)
            {
              // (the upper block's vertices on y = 1 are not at 1/3, 2/3)
              best  = std::abs(mesh.vertex(v)[0] - x);
              upper = v;
              for (unsigned int w = 0; w < mesh.n_vertices(); ++w)
                if (std::abs(mesh.vertex(w)[1] - 1) < 1e-12 && std::abs(mesh.vertex(w)[0] - x) < 1e-12)
                  lower = w;
            }
    AssertThrow(best < 0.15, dealii::ExcMessage("short_sub_edge(): no upper vertex near 1/3 or 2/3"));
    mesh.move_vertex(lower, mesh.vertex(upper) - dealii::Tensor<1, 2>({5e-4, 0.}));
    NodeInsertion::Settings settings;
    settings.merge_fraction = 1e-12;
    std::vector<NodeInsertion::Interface> interfaces = {NodeInsertion::insert(mesh, 3, 12, k, settings)};
    interfaces[0].normal_side = side;
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(k);
    const std::string what = "short sub-edge, k = " + std::to_string(k) + ", normal side " +
                             std::to_string(static_cast<int>(side)) + ": ";
    // the interface has the short sub-edge
    double shortest = 1;
    for (const auto &segment : interfaces[0].segments)
      shortest = std::min(shortest, interfaces[0].pairs[segment.first].slave_location.distance(
                                      interfaces[0].pairs[segment.second].slave_location));
    testing::check(shortest < 1e-3, what + "a sub-edge 5e-4 long (shortest " + std::to_string(shortest) + ")");
    FiniteStrainContact                    contact(dof_handler, interfaces, ContactSettings::Normal::unilateral, 7000.);
    // a smooth displacement (a random affine map of size 1e-2: the
    // chords keep their lengths to 2 %), and every slave node slid along
    // the interface by 0.02 (a tangential offset a.t of 0.02 at every
    // pair: 40 times the short sub-edge)
    std::mt19937                           gen(5 + k);
    std::uniform_real_distribution<double> dist(-1e-2, 1e-2);
    dealii::Tensor<2, 2>                   G;
    for (unsigned int a = 0; a < 2; ++a)
      for (unsigned int b = 0; b < 2; ++b)
        G[a][b] = dist(gen);
    dealii::Vector<double> u(dof_handler.n_dofs());
    for (unsigned int node = 0; node < dof_handler.n_dofs() / 2; ++node)
      {
        const dealii::Tensor<1, 2> v = G * dof_handler.node_location(node);
        for (unsigned int comp = 0; comp < 2; ++comp)
          u[VEMDoFHandler<2>::node_dof(node, comp)] = v[comp];
      }
    for (const auto &pair : interfaces[0].pairs)
      u[VEMDoFHandler<2>::node_dof(pair.node(dof_handler, false), 0)] += 0.02;
    const double                       h = 1e-7;
    double                             largest = 0, grad_err = 0;
    FiniteStrainContact::Linearization lin;
    for (unsigned int j = 0; j < contact.n_constraints(); ++j)
      {
        contact.linearize(j, u, lin, false);
        for (unsigned int a = 0; a < lin.dofs.size(); ++a)
          {
            grad_err = std::max(grad_err, std::abs(perturb(contact, j, u, lin.dofs[a], h).difference - lin.gradient[a]));
            largest  = std::max(largest, std::abs(lin.gradient[a]));
          }
      }
    testing::check(largest < 10, what + "largest gradient entry " + std::to_string(largest) + " (below 10)");
    testing::check_small(grad_err / largest, 1e-6, what + "gradient against central differences");
  }

  // the pressure -lambda/w(u) at every normal constraint
  std::vector<double>
  pressures(const FiniteStrainContact &contact, const FiniteStrainSolver<2> &solver)
  {
    const auto          w = contact.current_weights(solver.get_solution());
    std::vector<double> p(contact.n_pairs());
    for (unsigned int i = 0; i < contact.n_pairs(); ++i)
      p[i] = -solver.get_multipliers()[i] / w[i];
    return p;
  }

  void
  check_quadratic(const FiniteStrainSolver<2> &solver, const std::string &what)
  {
    const auto &it = solver.get_history().back().iterations;
    // the relative residuals above round-off: e_{i+1} <= C e_i^2
    double worst = 0;
    for (unsigned int i = 1; i + 1 < it.size(); ++i)
      if (it[i].relative_residual > 1e-7 && it[i + 1].relative_residual > 1e-13)
        worst = std::max(worst, it[i + 1].relative_residual / std::pow(it[i].relative_residual, 2));
    testing::check(worst < 1e3, what + "quadratic convergence, max e_{i+1}/e_i^2 = " + std::to_string(worst));
  }

  // (b)
  void
  patch_test(const unsigned int k, const ContactSettings::Normal model, const double phi_degrees)
  {
    const double      E = 7000, nu = 0.3;
    NeoHookeMaterial  law(E, nu);
    PolygonalMesh<2>  mesh;
    two_blocks(mesh, 3, 12);
    std::vector<NodeInsertion::Interface> interfaces = {NodeInsertion::insert(mesh, 3, 12, k, {})};
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(k);

    // the homogeneous deformation at the time t: compression 1 - 0.3 t, the
    // lateral stretch of uniaxial stress, the rotation phi t
    const double phi = phi_degrees * M_PI / 180;
    const auto   deformation = [&](const double t) {
      dealii::Tensor<2, 2> D;
      D[0][0] = lateral_stretch(law, 1 - 0.3 * t);
      D[1][1] = 1 - 0.3 * t;
      return std::make_pair(rotation(phi * t) * D, D);
    };

    FiniteStrainAssembler<2>          assembler(dof_handler, testing::one_law_library(dof_handler, law));
    dealii::AffineConstraints<double> constraints;
    testing::dirichlet_constraints(dof_handler, {2, 13}, testing::HomogeneousDeformation(deformation(0.1).first),
                                   constraints);
    FiniteStrainContact               contact(dof_handler, interfaces, model, E / 0.1);
    FiniteStrainSolver<2>::Parameters parameters;
    FiniteStrainSolver<2>             solver(assembler, constraints, parameters);
    solver.set_contact(contact);
    std::vector<dealii::Point<2>> support;
    dof_handler.map_dofs_to_support_points(support);
    // ten steps; each one's boundary data is the homogeneous deformation
    // of its time, so every step is a patch test
    double dof_err = 0, p_err = 0, g_max = 0, t_max = 0, n_max = 0, p_exact = 0, l1 = 0;
    bool   all_active = true;
    for (unsigned int n = 1; n <= 10; ++n)
      {
        const auto [F, D] = deformation(0.1 * n);
        const testing::HomogeneousDeformation exact(F);
        testing::dirichlet_constraints(dof_handler, {2, 13}, exact, constraints);
        solver.set_constraints(constraints);
        solver.solve_step(n, 1.);
        const auto &u     = solver.get_solution();
        double      u_max = 0, err = 0;
        for (unsigned int i = 0; i < u.size(); ++i)
          {
            u_max = std::max(u_max, std::abs(exact.value(support[i], i % 2)));
            err   = std::max(err, std::abs(u[i] - exact.value(support[i], i % 2)));
          }
        dof_err    = std::max(dof_err, err / u_max);
        p_exact    = -law.cauchy_stress(D)[1][1];
        l1         = D[0][0];
        const auto p = pressures(contact, solver);
        for (unsigned int i = 0; i < contact.n_pairs(); ++i)
          {
            p_err = std::max(p_err, std::abs(p[i] - p_exact) / p_exact);
            g_max = std::max(g_max, std::abs(contact.value(i, u)));
            n_max = std::max(n_max, std::abs(solver.get_multipliers()[i]));
            if (contact.is_bilateral())
              t_max = std::max(t_max, std::abs(solver.get_multipliers()[contact.n_pairs() + i]));
          }
        all_active = all_active &&
                     solver.get_history().back().iterations.back().n_active == contact.n_constraints();
      }

    const std::string what = "patch test, k = " + std::to_string(k) + ", " +
                             ContactSettings::normal_name(model) + ", rotation " +
                             std::to_string(static_cast<int>(phi_degrees)) + " degrees (" +
                             std::to_string(contact.n_pairs()) + " pairs): ";
    testing::check_small(dof_err, 1e-10, what + "max DoF error / max |u| over the steps");
    testing::check(all_active, what + "every constraint active at every step");
    testing::check_small(p_err, 1e-8, what + "max |p - p_exact| / p_exact over the steps");
    testing::check_small(g_max, 1e-12, what + "max |g|");
    testing::check_small(t_max / n_max, 1e-8, what + "tangential multipliers / normal ones");
    check_quadratic(solver, what);
    std::cout << what << "Newton updates per step:";
    for (const auto &record : solver.get_history())
      std::cout << " " << record.iterations.size() - 1;
    std::cout << std::endl;
    if (phi_degrees == 90 && model == ContactSettings::Normal::unilateral)
      {
        std::cout << "pressure p = " << p_exact << " (E = " << E << ", lateral stretch " << l1
                  << "); Newton history of the last step:\n";
        std::cout << FiniteStrainSolver<2>::step_history_text(solver.get_history().back());
      }
  }

  // (c)
  void
  confined_two_materials(const unsigned int k)
  {
    const double     nu = 0.3;
    NeoHookeMaterial lower(7000, nu), upper(700, nu);
    PolygonalMesh<2> mesh;
    two_blocks(mesh, 4, 10);
    std::vector<NodeInsertion::Interface> interfaces = {NodeInsertion::insert(mesh, 3, 12, k, {})};
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(k);
    MaterialLibrary<2> laws;
    laws.add(0, lower);
    laws.add(1, upper);

    // sigma_yy of diag(1, l)
    const auto sigma = [](const HyperelasticMaterial &law, const double l) {
      dealii::Tensor<2, 2> F;
      F[0][0] = 1;
      F[1][1] = l;
      return law.cauchy_stress(F)[1][1];
    };
    // l_a + l_b = 1.4 and sigma_a(l_a) = sigma_b(l_b): bisection in l_a
    double lo = 0.7, hi = 1.0;
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (sigma(lower, mid) - sigma(upper, 1.4 - mid) > 0 ? hi : lo) = mid;
      }
    const double la = 0.5 * (lo + hi), p_exact = -sigma(lower, la);

    FiniteStrainAssembler<2>          assembler(dof_handler, laws);
    dealii::AffineConstraints<double> constraints;
    for (const dealii::types::boundary_id id : {0, 1, 10, 11})
      BoundaryConditions::add_roller(dof_handler, id, constraints);
    dealii::Functions::ConstantFunction<2> zero(0., 2);
    BoundaryConditions::interpolate_boundary_values(dof_handler, {2}, zero, {{false, true}}, constraints);
    dealii::Functions::ConstantFunction<2> top(-0.6, 2);
    BoundaryConditions::interpolate_boundary_values(dof_handler, {13}, top, {{false, true}}, constraints);
    constraints.close();
    FiniteStrainContact               contact(dof_handler, interfaces, ContactSettings::Normal::unilateral, 7000 / 0.1);
    FiniteStrainSolver<2>::Parameters parameters;
    parameters.n_load_steps = 6;
    FiniteStrainSolver<2> solver(assembler, constraints, parameters);
    solver.set_contact(contact);
    solver.run();

    const std::string what = "confined, two materials, k = " + std::to_string(k) + ": ";
    const auto        p    = pressures(contact, solver);
    double            err  = 0;
    for (const double pi : p)
      err = std::max(err, std::abs(pi - p_exact));
    testing::check_small(err / p_exact, 1e-8, what + "max |p - p_exact| / p_exact");
    // the interface has moved to y = l_a
    double y_err = 0;
    for (unsigned int i = 0; i < contact.n_pairs(); ++i)
      y_err = std::max(y_err, std::abs(contact.current_positions(i, solver.get_solution())[1][1] - la));
    testing::check_small(y_err, 1e-10, what + "interface at y = l_a");
    check_quadratic(solver, what);
  }
  // (e)
  void
  bad_input()
  {
    NeoHookeMaterial law(7000, 0.3);
    PolygonalMesh<2> mesh;
    two_blocks(mesh, 3, 12);
    std::vector<NodeInsertion::Interface> interfaces = {NodeInsertion::insert(mesh, 3, 12, 1, {})};
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(1);
    FiniteStrainAssembler<2>          assembler(dof_handler, testing::one_law_library(dof_handler, law));
    dealii::AffineConstraints<double> constraints, other;
    dealii::Functions::ZeroFunction<2> zero(2);
    testing::dirichlet_constraints(dof_handler, {2, 13}, zero, constraints);
    testing::dirichlet_constraints(dof_handler, {2}, zero, other);
    FiniteStrainSolver<2>::Parameters parameters;
    FiniteStrainSolver<2>             solver(assembler, constraints, parameters);
    testing::check_throws([&]() { solver.set_constraints(other); }, "they must constrain the same DoFs",
                          "set_constraints() with other DoFs");

    // every boundary held: the lower block lifted by 0.01 into the upper one
    dealii::AffineConstraints<double>      held;
    dealii::Functions::ConstantFunction<2> up(std::vector<double>{0., 0.01});
    BoundaryConditions::interpolate_boundary_values(dof_handler, {0, 1, 2, 3}, up, {{true, true}}, held);
    BoundaryConditions::interpolate_boundary_values(dof_handler, {10, 11, 12, 13}, zero, {{true, true}}, held);
    held.close();
    FiniteStrainContact   contact(dof_handler, interfaces, ContactSettings::Normal::unilateral, 7e4);
    FiniteStrainSolver<2> held_solver(assembler, held, parameters);
    held_solver.set_contact(contact);
    testing::check_throws([&]() { held_solver.solve_step(1, 1.); }, "the prescribed motions of the two bodies contradict the contact",
                          "fixed pairs pushed into each other");
    testing::check(held_solver.get_history().size() == 1 && !held_solver.get_history()[0].converged,
                   "the failed step is recorded as not converged");
  }
  // (f)
  void
  slip_origin_on_a_curve(const unsigned int k)
  {
    const std::string what = "slip origin, k = " + std::to_string(k) + ": ";
    PolygonalMesh<2>  mesh;
    two_blocks(mesh, 4, 12);
    std::vector<NodeInsertion::Interface> interfaces = {NodeInsertion::insert(mesh, 3, 12, k, {})};
    VEMDoFHandler<2> dofs(mesh);
    dofs.distribute_dofs(k);
    // the body of every node
    std::vector<unsigned int> body(dofs.n_nodes(), 0);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        for (const unsigned int v : mesh.cell(c).vertices)
          body[dofs.vertex_node(v)] = mesh.cell(c).material_id;
        if (k == 2)
          for (const unsigned int e : mesh.cell(c).edges)
            body[dofs.edge_node(e)] = mesh.cell(c).material_id;
      }
    // the bending: x along the circle (arc length from x = 0.5), y along
    // its radius; the interface y = 1 onto the circle itself
    const double R = 1.5;
    const auto   bend = [&](const double sigma, const double y) {
      const double angle = (sigma - 0.5) / R;
      return dealii::Point<2>(0.5 + (R + y - 1) * std::sin(angle), 1 - R + (R + y - 1) * std::cos(angle));
    };
    dealii::Vector<double> u_base(dofs.n_dofs());
    for (unsigned int node = 0; node < dofs.n_nodes(); ++node)
      {
        const auto X = dofs.node_location(node);
        const auto x = bend(X[0], X[1]);
        for (unsigned int comp = 0; comp < 2; ++comp)
          u_base[VEMDoFHandler<2>::node_dof(node, comp)] = x[comp] - X[comp];
      }
    // the lower side's nodes (x, position), by x: its polygon, or its
    // quadratic pieces, at the base (the lower block does not move)
    std::vector<std::pair<double, dealii::Point<2>>> side;
    for (const auto &pair : interfaces[0].pairs)
      {
        const unsigned int node = pair.on_edge() ? dofs.edge_node(pair.master_entity) :
                                                     dofs.vertex_node(pair.master_entity);
        side.emplace_back(dofs.node_location(node)[0], bend(dofs.node_location(node)[0], 1.));
      }
    std::sort(side.begin(), side.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
    const unsigned int stride = k; // k = 2: (end, midpoint, end) pieces
    const auto         on_side = [&](const double sigma) {
      unsigned int i = 0;
      while (i + stride + 1 < side.size() && sigma > side[i + stride].first)
        i += stride;
      if (k == 1)
        {
          const double t = (sigma - side[i].first) / (side[i + 1].first - side[i].first);
          return dealii::Point<2>(side[i].second + t * (side[i + 1].second - side[i].second));
        }
      // the quadratic through the three nodes, in x
      const double x0 = side[i].first, x1 = side[i + 1].first, x2 = side[i + 2].first;
      const double l0 = (sigma - x1) * (sigma - x2) / ((x0 - x1) * (x0 - x2));
      const double l1 = (sigma - x0) * (sigma - x2) / ((x1 - x0) * (x1 - x2));
      const double l2 = (sigma - x0) * (sigma - x1) / ((x2 - x0) * (x2 - x1));
      return dealii::Point<2>(l0 * side[i].second + l1 * side[i + 1].second + l2 * side[i + 2].second);
    };
    std::set<unsigned int> slave_nodes;
    for (const auto &pair : interfaces[0].pairs)
      slave_nodes.insert(pair.on_edge() ? dofs.edge_node(pair.slave_entity) : dofs.vertex_node(pair.slave_entity));
    const double delta = 0.15;
    for (const double lift : {0., 0.02})
      {
        dealii::Vector<double> u_origin = u_base;
        for (unsigned int node = 0; node < dofs.n_nodes(); ++node)
          if (body[node] == 1)
            {
              const auto X = dofs.node_location(node);
              // the upper side on the lower one's polygon (or lifted off it
              // along the radius); the rest of the upper block bent along
              dealii::Point<2> x = bend(X[0] + delta, X[1]);
              if (slave_nodes.count(node) > 0)
                {
                  x = on_side(X[0] + delta);
                  x += lift * (bend(X[0] + delta, 2.) - bend(X[0] + delta, 1.));
                }
              for (unsigned int comp = 0; comp < 2; ++comp)
                u_origin[VEMDoFHandler<2>::node_dof(node, comp)] = x[comp] - X[comp];
            }
        FiniteStrainContact::Options options;
        options.friction_coefficient = 0.3;
        options.base                 = &u_base;
        options.slip_origin          = &u_origin;
        FiniteStrainContact contact(dofs, interfaces, ContactSettings::Normal::unilateral, 7000., options);
        const unsigned int  np = contact.n_pairs();
        testing::check(contact.n_constraints() == 2 * np, what + "a friction constraint per pair");
        // Lifted off or not, the slip counts from the origin: the new
        // contacts (lifted by 0.02, twice the touching threshold) slid by
        // delta as much as the others. (They once counted it from where they
        // were paired, which made a converged friction answer depend on the
        // predictor of the step.)
        double       worst     = 0;
        unsigned int n_checked = 0, n_new = 0;
        for (unsigned int i = 0; i < np; ++i)
          {
            // (the pairs that were beyond the end of the lower side at the
            // origin are left out: where the side is continued is a guess)
            if (contact.get_pairs()[i].slave_location[0] + delta > 1)
              continue;
            const double slip = contact.value(np + i, u_base);
            worst             = std::max(worst, std::abs(std::abs(slip) - delta) / delta);
            ++n_checked;
            n_new += contact.is_new_contact(i) ? 1 : 0;
          }
        const std::string state = lift == 0 ? "touching at the origin: " : "lifted off at the origin: ";
        testing::check_small(worst, 0.1, what + state + "sliding along the curve: |slip| - delta, relative");
        testing::check(n_checked > 0 && n_new == (lift == 0 ? 0 : n_checked),
                       what + state + (lift == 0 ? "no pair is a new contact" : "every pair is a new contact"));
      }
  }
} // namespace

int
main()
{
  using Side = NodeInsertion::Interface::NormalSide;
  for (const unsigned int k : {1u, 2u})
    for (const auto model : {ContactSettings::Normal::unilateral, ContactSettings::Normal::tied})
      for (const auto side : {Side::master, Side::slave, Side::bisector})
        check_linearization(k, model, side);
  for (const unsigned int k : {1u, 2u})
    for (const auto model : {ContactSettings::Normal::tied, ContactSettings::Normal::unilateral})
      for (const double phi : {0., 30., 90.})
        patch_test(k, model, phi);
  for (const unsigned int k : {1u, 2u})
    confined_two_materials(k);
  for (const unsigned int k : {1u, 2u})
    slip_origin_on_a_curve(k);
  for (const unsigned int k : {1u, 2u})
    for (const auto side : {Side::master, Side::slave, Side::bisector})
      short_sub_edge(k, side);
  bad_input();
  // (this test runs without MPI: the Trilinos solvers say so instead of
  // letting Epetra abort the process)
  for (const auto type : {SaddlePointSolver::Type::cg_amg_constraints, SaddlePointSolver::Type::gmres_amg,
                          SaddlePointSolver::Type::klu})
    {
      SaddlePointSolver::Settings settings;
      settings.type = type;
      testing::check_throws([&]() { SaddlePointSolver solver(settings); }, "needs MPI to be initialized",
                            "without MPI_Init, " + SaddlePointSolver::type_name(type) + " is refused");
    }
  return testing::finish();
}
