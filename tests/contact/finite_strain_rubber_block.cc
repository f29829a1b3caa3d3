// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// A rubber block pressed onto a stiff one at finite strain: the rubber
// [0.25,0.75]x[0.5,1] (Voronoi, Neo-Hooke E = 1, nu = 0.45, material id 1)
// stands on the base [0,1]x[0,0.5] (quads, Neo-Hooke E_b, nu = 0.3, bottom
// clamped); a rigid plate bonded to the rubber's top moves it down by
// 0.15 (30 % of its height) in 6 load steps. Contact between the base's top
// (master, id 3) and the rubber's bottom (slave, id 12): frictionless
// unilateral, or tied; non-matching meshes made matching by node insertion.
//
// As the base stiffens, the rubber must behave as on a rigid support:
// frictionless contact as a roller (u_y = 0) under its bottom, tied
// contact as a clamp. The references are the rubber alone, on the same
// mesh (split from the contact mesh after node insertion), with these
// supports. Checked for k = 1 and 2, for both models:
// - the plate force and the lateral displacement of the rubber's bottom
//   corners differ from the rigid-support values by less than 2e-3
//   (relative) at E_b = 1e4, and the difference falls by more than 30
//   times from E_b = 1e2 to 1e4 (it is of the order of the compliance);
// - the rubber is in equilibrium: the vertical contact force sum_j
//   -lambda_j n_j(u)_y (with tied contact also the tangential multipliers'
//   share) equals the force of the rubber on the plate to 1e-10 (relative);
// - every step converged, and the last iterations converge quadratically.
// The frictionless rubber slides outward over the base by about one base
// element at the corners: pairs stay those of the reference configuration
// (small sliding), exact here since the base stays nearly flat.
#include <deal.II/base/function.h>

#include <dealvem/contact/finite_strain_contact.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/finite_strain_solver.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/mesh/generators.h>

#include <cmath>
#include <iostream>

#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
  const double E_rubber = 1, nu_rubber = 0.45, plate = -0.15;

  struct Response
  {
    double force  = 0; ///< vertical force of the rubber on the plate (the sum of the plate's reactions)
    double spread = 0; ///< largest |u_x| on the rubber's bottom
    double contact_force = 0; ///< vertical contact force on the rubber
    unsigned int newton = 0;  ///< Newton updates, all steps
  };

  // sum of the reactions (residual entries) at the y DoFs of boundary id top
  double
  plate_force(const VEMDoFHandler<2> &dof_handler, const FiniteStrainAssembler<2> &assembler,
              const dealii::Vector<double> &u, const dealii::types::boundary_id top)
  {
    dealii::AffineConstraints<double>      top_dofs, none;
    dealii::Functions::ZeroFunction<2>     zero(2);
    BoundaryConditions::interpolate_boundary_values(dof_handler, {top}, zero, {{false, true}}, top_dofs);
    top_dofs.close();
    none.close();
    dealii::Vector<double> r;
    assembler.assemble(u, 1., r, none, nullptr, nullptr);
    double f = 0;
    for (const auto &line : top_dofs.get_lines())
      f += r[line.index];
    return f;
  }

  // largest |u_x| on the boundary id bottom
  double
  spread(const VEMDoFHandler<2> &dof_handler, const dealii::Vector<double> &u, const dealii::types::boundary_id bottom)
  {
    dealii::AffineConstraints<double>  dofs;
    dealii::Functions::ZeroFunction<2> zero(2);
    BoundaryConditions::interpolate_boundary_values(dof_handler, {bottom}, zero, {{true, false}}, dofs);
    dofs.close();
    double s = 0;
    for (const auto &line : dofs.get_lines())
      s = std::max(s, std::abs(u[line.index]));
    return s;
  }

  void
  make_mesh(PolygonalMesh<2> &mesh)
  {
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 0.5), 8, 4);
    PolygonalMesh<2> rubber;
    PolygonalMeshGenerators::voronoi(rubber, dealii::Point<2>(0.25, 0.5), dealii::Point<2>(0.75, 1.0), 30, 30, 4);
    for (unsigned int c = 0; c < rubber.n_cells(); ++c)
      rubber.set_material_id(c, 1);
    for (unsigned int e = 0; e < rubber.n_edges(); ++e)
      if (rubber.edge(e).at_boundary())
        rubber.set_edge_boundary_id(e, rubber.edge(e).boundary_id + 10);
    mesh.append(rubber);
  }

  FiniteStrainSolver<2>::Parameters
  parameters()
  {
    FiniteStrainSolver<2>::Parameters p;
    p.n_load_steps = 6;
    return p;
  }

  bool
  all_converged(const FiniteStrainSolver<2> &solver)
  {
    bool ok = solver.get_history().size() == parameters().n_load_steps;
    for (const auto &s : solver.get_history())
      ok = ok && s.converged;
    return ok;
  }

  unsigned int
  updates(const FiniteStrainSolver<2> &solver)
  {
    unsigned int n = 0;
    for (const auto &s : solver.get_history())
      n += s.iterations.size() - 1;
    return n;
  }

  // the rubber on the base of stiffness E_b, in contact
  Response
  on_base(const unsigned int k, const ContactSettings::Normal model, const double E_b, PolygonalMesh<2> &rubber)
  {
    PolygonalMesh<2> mesh;
    make_mesh(mesh);
    std::vector<NodeInsertion::Interface> interfaces = {NodeInsertion::insert(mesh, 3, 12, k, {})};
    rubber = mesh.split_by_material_id()[1];
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(k);
    MaterialLibrary<2> laws;
    laws.add(0, NeoHookeMaterial(E_b, 0.3));
    laws.add(1, NeoHookeMaterial(E_rubber, nu_rubber));
    FiniteStrainAssembler<2>              assembler(dof_handler, laws);
    dealii::AffineConstraints<double>     constraints;
    dealii::Functions::ZeroFunction<2>    zero(2);
    dealii::Functions::ConstantFunction<2> down(std::vector<double>{0., plate});
    BoundaryConditions::interpolate_boundary_values(dof_handler, {2}, zero, {{true, true}}, constraints);
    BoundaryConditions::interpolate_boundary_values(dof_handler, {13}, down, {{true, true}}, constraints);
    constraints.close();
    FiniteStrainContact   contact(dof_handler, interfaces, model, E_rubber / 0.05);
    FiniteStrainSolver<2> solver(assembler, constraints, parameters());
    solver.set_contact(contact);
    solver.run();
    testing::check(all_converged(solver), "every step converged");

    Response r;
    const auto &u = solver.get_solution();
    r.force       = plate_force(dof_handler, assembler, u, 13);
    r.spread      = spread(dof_handler, u, 12);
    for (unsigned int i = 0; i < contact.n_pairs(); ++i)
      {
        r.contact_force -= solver.get_multipliers()[i] * contact.current_normal(i, u)[1];
        if (contact.is_bilateral()) // the tangential multiplier acts along t = J n
          r.contact_force -= solver.get_multipliers()[contact.n_pairs() + i] * contact.current_normal(i, u)[0];
      }
    r.newton = updates(solver);
    const auto &it    = solver.get_history().back().iterations;
    double      worst = 0;
    for (unsigned int i = 1; i + 1 < it.size(); ++i)
      if (it[i].relative_residual > 1e-7 && it[i + 1].relative_residual > 1e-13)
        worst = std::max(worst, it[i + 1].relative_residual / std::pow(it[i].relative_residual, 2));
    testing::check(worst < 1e3, "quadratic convergence in the last step, max e_{i+1}/e_i^2 = " + std::to_string(worst));
    if (k == 2 && E_b == 1e4)
      std::cout << "k = 2, " << ContactSettings::normal_name(model) << ", E_b = 1e4: last step\n"
                << FiniteStrainSolver<2>::step_history_text(solver.get_history().back());
    return r;
  }

  // the rubber alone on a rigid support: roller (frictionless) or clamp (tied)
  Response
  rigid_support(const unsigned int k, const ContactSettings::Normal model, const PolygonalMesh<2> &rubber)
  {
    VEMDoFHandler<2> dof_handler(rubber);
    dof_handler.distribute_dofs(k);
    FiniteStrainAssembler<2> assembler(dof_handler,
                                       testing::one_law_library(dof_handler, NeoHookeMaterial(E_rubber, nu_rubber)));
    dealii::AffineConstraints<double>      constraints;
    dealii::Functions::ZeroFunction<2>     zero(2);
    dealii::Functions::ConstantFunction<2> down(std::vector<double>{0., plate});
    BoundaryConditions::interpolate_boundary_values(dof_handler, {13}, down, {{true, true}}, constraints);
    BoundaryConditions::interpolate_boundary_values(dof_handler, {12}, zero,
                                                    {{model == ContactSettings::Normal::tied, true}}, constraints);
    constraints.close();
    FiniteStrainSolver<2> solver(assembler, constraints, parameters());
    solver.run();
    testing::check(all_converged(solver), "rigid support: every step converged");
    Response r;
    r.force  = plate_force(dof_handler, assembler, solver.get_solution(), 13);
    r.spread = spread(dof_handler, solver.get_solution(), 12);
    r.newton = updates(solver);
    return r;
  }
} // namespace

int
main()
{
  for (const unsigned int k : {1u, 2u})
    for (const auto model : {ContactSettings::Normal::unilateral, ContactSettings::Normal::tied})
      {
        PolygonalMesh<2> rubber;
        const Response   soft  = on_base(k, model, 1e2, rubber);
        const Response   stiff = on_base(k, model, 1e4, rubber);
        const Response   ideal = rigid_support(k, model, rubber);
        const std::string what = "k = " + std::to_string(k) + ", " + ContactSettings::normal_name(model) + ": ";
        const double d_force_soft   = std::abs(soft.force / ideal.force - 1);
        const double d_force_stiff  = std::abs(stiff.force / ideal.force - 1);
        std::cout << what << "plate force " << ideal.force << " on the rigid support; relative difference "
                  << d_force_soft << " (E_b = 1e2), " << d_force_stiff << " (E_b = 1e4); bottom spread "
                  << ideal.spread << " / " << soft.spread << " / " << stiff.spread << "; Newton updates "
                  << ideal.newton << " / " << soft.newton << " / " << stiff.newton << std::endl;
        testing::check_small(d_force_stiff, 2e-3, what + "plate force, E_b = 1e4, against the rigid support");
        testing::check(d_force_soft > 30 * d_force_stiff, what + "the force difference falls with the compliance");
        if (model == ContactSettings::Normal::unilateral)
          {
            const double d_spread_soft  = std::abs(soft.spread / ideal.spread - 1);
            const double d_spread_stiff = std::abs(stiff.spread / ideal.spread - 1);
            testing::check_small(d_spread_stiff, 2e-3, what + "bottom spread, E_b = 1e4, against the roller");
            testing::check(d_spread_soft > 30 * d_spread_stiff,
                           what + "the spread difference falls with the compliance");
          }
        else
          {
            testing::check_small(stiff.spread, 1e-3 * std::abs(plate), what + "tied, E_b = 1e4: bottom spread / plate motion");
            testing::check(soft.spread > 30 * stiff.spread, what + "tied: the spread falls with the compliance");
          }
        for (const Response *r : {&soft, &stiff})
          testing::check_small(std::abs(r->contact_force - r->force) / std::abs(r->force), 1e-10,
                               what + "vertical contact force on the rubber - its force on the plate (equilibrium)");
      }
  return testing::finish();
}
