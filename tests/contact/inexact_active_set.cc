// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The active-set iteration with CG-AMG's inexact solves and its AMG
// hierarchy kept across the iterations (issue 39), against UMFPACK and
// against CG-AMG with both switched off. Hertz-like problem at k = 2: a
// body [-1/2, 1/2] x [0, 1/2] (27 x 9 quads) whose bottom is bent onto the
// circle y = R - sqrt(R^2 - x^2), R = 1, pressed by p = 50 on its top onto
// a block [-1, 1] x [-1, 0] (24 x 12 quads, non-matching), E = 1000,
// nu = 0.3, block bottom held vertically and its corner horizontally, the
// body held by contact alone, stick by multipliers. (Large enough for a
// multilevel hierarchy: ML's coarsest level takes up to 2000 rows.)
// Checked, with the default reuse fraction and with every change corrected
// however many rows change:
// - CG-AMG (inexact solves, hierarchy kept and corrected on the changed
//   rows) takes the same iterations, sets and final set as UMFPACK and as
//   CG-AMG without either, and gives the same displacements and
//   multipliers (1e-8 of their size);
// - exactly one inexact solve is completed (the one the iteration accepts),
//   and the hierarchy was corrected at least once;
// - SaddlePointSolver directly: an inexact solve stops early
//   (last_solve_inexact()), complete_last_solve() brings it to the solution
//   of an exact solve (1e-9), and completing a solve that was not inexact
//   throws.
// The same with stick by penalty (the solves go through the preconditioner
// of the stick springs, which the completion keeps): the same sets and
// solution as UMFPACK and as CG-AMG without inexact solves, one completed
// solve, and the direct use.
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/contact/active_set_solver.h>
#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/contact/rigid_body_support.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/solvers/saddle_point_solver.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <cmath>
#include <map>

#include "../tests.h"

using namespace dealvem;

namespace
{
  struct Problem
  {
    std::map<dealii::types::material_id, ElasticMaterial> materials{{0, ElasticMaterial(1000, 0.3)},
                                                                    {1, ElasticMaterial(1000, 0.3)}};
    PolygonalMesh<2>                                      mesh;
    VEMDoFHandler<2>                                      dof_handler;
    std::vector<NodeInsertion::Interface>                 interfaces;
    ContactSettings                                       settings;
    std::unique_ptr<ContactScales>                        scales;
    std::unique_ptr<ContactAssembler<2>>                  contact;
    std::unique_ptr<RigidBodySupport>                     support;
    dealii::AffineConstraints<double>                     constraints;
    dealii::SparsityPattern                               sparsity;
    dealii::SparseMatrix<double>                          system_matrix;
    dealii::Vector<double>                                system_rhs;
    unsigned int                                          n = 0;

    explicit Problem(const ContactSettings &s)
      : settings(s)
    {
      const unsigned int degree = 2;
      PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(-1, -1), dealii::Point<2>(1, 0), 24, 12);
      PolygonalMesh<2> body;
      PolygonalMeshGenerators::structured_quads(body, dealii::Point<2>(-0.5, 0), dealii::Point<2>(0.5, 0.5), 27, 9);
      for (unsigned int v = 0; v < body.n_vertices(); ++v)
        {
          const auto   q = body.vertex(v);
          const double f = 1 - std::sqrt(1 - q[0] * q[0]);
          body.move_vertex(v, dealii::Point<2>(q[0], q[1] + (1 - 2 * q[1]) * f));
        }
      body.validate();
      for (unsigned int c = 0; c < body.n_cells(); ++c)
        body.set_material_id(c, 1);
      for (unsigned int e = 0; e < body.n_edges(); ++e)
        if (body.edge(e).at_boundary())
          body.set_edge_boundary_id(e, body.edge(e).boundary_id + 10);
      mesh.append(body);
      NodeInsertion::Settings insertion;
      insertion.close_discretisation_gaps = false;
      interfaces = {NodeInsertion::insert(mesh, 3, 12, degree, insertion)};
      dof_handler.reinit(mesh);
      dof_handler.distribute_dofs(degree);

      scales  = std::make_unique<ContactScales>(std::vector<double>{1000, 1000}, interfaces);
      contact = std::make_unique<ContactAssembler<2>>(dof_handler, interfaces[0].pairs, settings,
                                                      scales->penalty(settings));
      dealii::Functions::ZeroFunction<2> zero(2);
      BoundaryConditions::interpolate_boundary_values(dof_handler, {2}, zero, {{false, true}}, constraints);
      BoundaryConditions::add_point_constraint(dof_handler, dealii::Point<2>(-1, -1), 0, 0., constraints);
      constraints.close();
      support = std::make_unique<RigidBodySupport>(dof_handler, constraints, *contact, true);

      n = dof_handler.n_dofs();
      dealii::DynamicSparsityPattern dsp(n + contact->n_multipliers());
      dof_handler.make_sparsity_pattern(dsp);
      contact->add_sparsity(dsp);
      constraints.condense(dsp);
      sparsity.copy_from(dsp);
      system_matrix.reinit(sparsity);
      system_rhs.reinit(n + contact->n_multipliers());
      ElasticityAssembler<2>                 assembler(dof_handler, materials);
      dealii::Functions::ConstantFunction<2> pressure(50.);
      assembler.add_pressure(13, pressure);
      assembler.assemble(constraints, system_matrix, system_rhs);
    }
  };

  double
  relative_difference(const dealii::Vector<double> &a, const dealii::Vector<double> &b)
  {
    if (a.size() != b.size())
      return 1e300;
    double d = 0, size = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        d    = std::max(d, std::abs(a[i] - b[i]));
        size = std::max(size, std::abs(b[i]));
      }
    return d / size;
  }

  struct Run
  {
    ActiveSetSolver<2>::Result result;
    dealii::Vector<double>     x;
    std::string                description;
  };

  Run
  run(Problem &pb, const SaddlePointSolver::Settings &settings)
  {
    SaddlePointSolver solver(settings);
    if (settings.type != SaddlePointSolver::Type::umfpack)
      solver.set_near_null_space(pb.dof_handler.rigid_body_modes());
    ActiveSetSolver<2> driver(*pb.contact, pb.constraints, solver, pb.settings,
                              pb.scales->complementarity_constant());
    driver.set_support(pb.support.get());
    driver.set_pair_neighbours(ActiveSetSolver<2>::pair_neighbours(pb.interfaces));
    dealii::SparseMatrix<double> matrix(pb.sparsity);
    Run                          r;
    r.result      = driver.solve(pb.system_matrix, pb.system_rhs, matrix, r.x);
    r.description = solver.description();
    return r;
  }

  void
  compare(const double                      reuse_fraction,
          const std::string                &name,
          const ContactSettings::Tangential tangential = ContactSettings::Tangential::multipliers)
  {
    ContactSettings s;
    s.normal     = ContactSettings::Normal::unilateral;
    s.tangential = tangential;
    Problem pb(s);

    SaddlePointSolver::Settings direct;
    direct.type = SaddlePointSolver::Type::umfpack;
    SaddlePointSolver::Settings fast;
    fast.type               = SaddlePointSolver::Type::cg_amg_constraints;
    fast.relative_tolerance = 1e-12;
    fast.amg_reuse_fraction           = reuse_fraction;
    SaddlePointSolver::Settings plain = fast;
    plain.inexact_tolerance           = 0;
    plain.amg_reuse_fraction          = 0;

    const Run reference = run(pb, direct), r = run(pb, fast), p = run(pb, plain);
    std::cout << name << ": " << pb.contact->n_pairs() << " pairs, active pairs per iteration:";
    for (const auto k : r.result.n_active_history)
      std::cout << " " << k;
    std::cout << "; CG iterations " << r.result.linear_iterations << " (without inexact solves and reuse "
              << p.result.linear_iterations << ")" << std::endl
              << "  " << r.description << std::endl;
    for (const auto *other : {&reference, &p})
      {
        const std::string against = (other == &reference ? "UMFPACK" : "CG-AMG without inexact solves or reuse");
        testing::check(r.result.n_active_history == other->result.n_active_history &&
                         r.result.active == other->result.active && r.result.n_iterations > 1,
                       name + ": the same sets in every iteration and the same final set as " + against);
        testing::check_small(relative_difference(r.x, other->x), 1e-8,
                             name + ": max |x - x_" + against + "| / max |x|");
      }
    testing::check(r.result.n_completed_solves == 1 && p.result.n_completed_solves == 0,
                   name + ": one inexact solve completed (the accepted one), none without inexact solves");
    if (tangential == ContactSettings::Tangential::penalty)
      testing::check(r.description.find("stick springs preconditioned by tying them") != std::string::npos,
                     name + ": the solves went through the preconditioner of the stick springs");
    else
      testing::check(r.description.find(", 0 time(s) corrected") == std::string::npos &&
                       p.description.find(", 0 time(s) corrected") != std::string::npos,
                     name + ": the hierarchy corrected at least once (not without reuse)");
  }

  void
  direct_use(const ContactSettings::Tangential tangential, const std::string &name)
  {
    ContactSettings s;
    s.normal     = ContactSettings::Normal::unilateral;
    s.tangential = tangential;
    Problem pb(s);
    // every pair closed (the body is held by contact alone)
    dealii::SparseMatrix<double> matrix(pb.sparsity);
    dealii::Vector<double>       rhs;
    matrix.copy_from(pb.system_matrix);
    rhs = pb.system_rhs;
    std::vector<bool> all(pb.contact->n_pairs(), true);
    pb.contact->assemble(pb.constraints, all, matrix, rhs);

    SaddlePointSolver::Settings settings;
    settings.type               = SaddlePointSolver::Type::cg_amg_constraints;
    settings.relative_tolerance = 1e-12;
    SaddlePointSolver exact(settings), inexact(settings);
    exact.set_near_null_space(pb.dof_handler.rigid_body_modes());
    inexact.set_near_null_space(pb.dof_handler.rigid_body_modes());
    // (with stick by penalty: the directions of the springs, for their
    // preconditioner; a solve uses them once)
    const auto stick_rows = pb.contact->stick_penalty_rows(pb.constraints, all);
    const bool penalty    = (tangential == ContactSettings::Tangential::penalty);
    testing::check(penalty == !stick_rows.empty(), name + ": stick rows with the penalty only");
    dealii::Vector<double> x_exact, x;
    exact.set_stick_directions(stick_rows);
    exact.solve(matrix, pb.n, x_exact, rhs);
    inexact.set_inexact(true);
    inexact.set_stick_directions(stick_rows);
    inexact.solve(matrix, pb.n, x, rhs);
    const unsigned int early = inexact.last_iterations();
    testing::check(inexact.last_solve_inexact() && !exact.last_solve_inexact() && early < exact.last_iterations(),
                   name + ": the inexact solve stops early (" + std::to_string(early) + " against " +
                     std::to_string(exact.last_iterations()) + " iterations)");
    testing::check(relative_difference(x, x_exact) > 1e-9, name + ": ... and its solution is inexact");
    inexact.complete_last_solve(matrix, x, rhs);
    testing::check_small(relative_difference(x, x_exact), 1e-9,
                         name + ": the completed solve gives the exact one's displacements and multipliers");
    testing::check(!inexact.last_solve_inexact(), name + ": nothing left to complete");
    bool thrown = false;
    try
      {
        exact.complete_last_solve(matrix, x, rhs);
      }
    catch (const std::exception &)
      {
        thrown = true;
      }
    testing::check(thrown, name + ": completing an exact solve throws");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare(1., "every change corrected");
  compare(SaddlePointSolver::Settings().amg_reuse_fraction, "default reuse");
  compare(SaddlePointSolver::Settings().amg_reuse_fraction, "stick by penalty", ContactSettings::Tangential::penalty);
  direct_use(ContactSettings::Tangential::multipliers, "direct use");
  direct_use(ContactSettings::Tangential::penalty, "direct use, stick by penalty");
  return testing::n_failures() == 0 ? 0 : 1;
}
