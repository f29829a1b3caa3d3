// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// A loop written by the user (as in examples/step-6) around the update
// rules gives the library drivers' iterates. Hertz-like problem at k = 2: a
// body [-1/2, 1/2] x [0, 1/2] (9 x 3 quads) whose bottom is bent onto the
// circle y = R - sqrt(R^2 - x^2), R = 1, pressed by p = 50 on its top onto
// a block [-1, 1] x [-1, 0] (6 x 3 quads, non-matching), E = 1000,
// nu = 0.3; block bottom held vertically, its corner horizontally, the body
// only by contact (its first active set closed by RigidBodySupport).
// Every linear solve goes through a recording SaddlePointSolver, which
// reads the active set from the matrix it is given (an active pair's
// multiplier row couples displacements, an inactive one is lambda = 0).
// Checked, for frictionless-normal contact with the stick penalty
// (ActiveSetUpdate vs ActiveSetSolver::solve; with and without the
// acceleration) and for Coulomb friction mu = 0.2 by multipliers with a
// shear traction 5 (a tenth of the pressure) added on the top
// (FrictionStateUpdate vs FrictionSolver::solve):
// - the same number of iterations (> 1: the set changes) and, per
//   iteration, the same set solved with;
// - the same displacements and multipliers to 1e-12 of their size;
// - the same converged set (states), and for friction the same references
//   and dissipated energy (1e-12).
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/contact/active_set_solver.h>
#include <dealvem/contact/active_set_update.h>
#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/contact_solver.h>
#include <dealvem/contact/friction_solver.h>
#include <dealvem/contact/friction_state_update.h>
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
  /// UMFPACK, recording per solve which multiplier rows couple
  /// displacements (the constraints enforced in that solve).
  class RecordingSolver : public SaddlePointSolver
  {
  public:
    RecordingSolver()
      : SaddlePointSolver(Settings{})
    {}

    void
    solve(const dealii::SparseMatrix<double> &A,
          const unsigned int                  n,
          dealii::Vector<double>             &x,
          const dealii::Vector<double>       &b) override
    {
      std::vector<bool> enforced(A.m() - n, false);
      for (unsigned int r = n; r < A.m(); ++r)
        for (auto it = A.begin(r); it != A.end(r); ++it)
          if (it->column() < n && it->value() != 0.)
            enforced[r - n] = true;
      sets.push_back(enforced);
      SaddlePointSolver::solve(A, n, x, b);
    }

    std::vector<std::vector<bool>> sets;
  };

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

    Problem(const ContactSettings &s, const double shear)
      : settings(s)
    {
      const unsigned int degree = 2;
      PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(-1, -1), dealii::Point<2>(1, 0), 6, 3);
      PolygonalMesh<2> body;
      PolygonalMeshGenerators::structured_quads(body, dealii::Point<2>(-0.5, 0), dealii::Point<2>(0.5, 0.5), 9, 3);
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
      dealii::Functions::ConstantFunction<2> traction(std::vector<double>{shear, 0.});
      if (shear != 0)
        assembler.add_traction(13, traction);
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
        size = std::max(size, std::abs(a[i]));
      }
    return d / size;
  }

  void
  compare_active_set(const bool accelerate)
  {
    const std::string name = accelerate ? "accelerated" : "plain";
    ContactSettings   s;
    s.normal                = ContactSettings::Normal::unilateral;
    s.tangential            = ContactSettings::Tangential::penalty;
    s.accelerate_active_set = accelerate;
    Problem                      pb(s, 0.);
    const auto                   neighbours = ActiveSetSolver<2>::pair_neighbours(pb.interfaces);
    const double                 c          = pb.scales->complementarity_constant();
    dealii::SparseMatrix<double> matrix(pb.sparsity);

    // the library's driver
    RecordingSolver    library_solver;
    ActiveSetSolver<2> driver(*pb.contact, pb.constraints, library_solver, s, c);
    driver.set_support(pb.support.get());
    driver.set_pair_neighbours(neighbours);
    dealii::Vector<double> x_library;
    const auto             result = driver.solve(pb.system_matrix, pb.system_rhs, matrix, x_library);

    // the user's loop
    RecordingSolver    user_solver;
    ActiveSetUpdate<2> update(pb.contact->get_pairs(), s, c);
    update.set_support(pb.support.get());
    update.set_pair_neighbours(neighbours);
    auto                   state = update.initial_state();
    dealii::Vector<double> x, rhs;
    do
      {
        matrix.copy_from(pb.system_matrix);
        rhs = pb.system_rhs;
        pb.contact->assemble(pb.constraints, state.active, matrix, rhs);
        user_solver.solve(matrix, pb.n, x, rhs);
        pb.constraints.distribute(x);
      }
    while (!update.update(state, *pb.contact, x));

    std::cout << name << ": " << pb.contact->n_pairs() << " pairs, active pairs per iteration:";
    for (const auto k : state.n_active_history)
      std::cout << " " << k;
    std::cout << std::endl;
    testing::check(state.n_iterations == result.n_iterations && result.n_iterations > 1 &&
                     user_solver.sets.size() == state.n_iterations,
                   name + ": the same number of iterations (" + std::to_string(state.n_iterations) + ", library " +
                     std::to_string(result.n_iterations) + ")");
    testing::check(user_solver.sets == library_solver.sets && state.n_active_history == result.n_active_history,
                   name + ": the same active set in every iteration");
    testing::check(state.active == result.active && state.n_accelerated == result.n_accelerated &&
                     state.n_closed_for_support == result.n_closed_for_support && state.n_closed_for_support > 0,
                   name + ": the same converged set, accelerated steps and pairs closed for support");
    testing::check_small(relative_difference(x, x_library), 1e-12, name + ": max |x_loop - x_solver| / max |x|");
    testing::check_small(state.residual, 1e-10 * 50, name + ": complementarity residual at convergence");

    // the same solve through the common seam (ContactSolver::create(),
    // solve_step()): the factory picks the active set for this model and
    // the result is that of solve(), with the pair states filled
    RecordingSolver seam_solver;
    const auto      seam = ContactSolver<2>::create(*pb.contact, pb.constraints, seam_solver, s, c);
    seam->set_support(pb.support.get());
    seam->set_pair_neighbours(neighbours);
    dealii::Vector<double> x_seam;
    const auto            &r = seam->solve_step(pb.system_matrix, pb.system_rhs, matrix, x_seam);
    bool                   states_match = (r.state.size() == r.active.size());
    for (unsigned int i = 0; states_match && i < r.state.size(); ++i)
      states_match = ((r.state[i] != PairState::open) == r.active[i]);
    testing::check(dynamic_cast<ActiveSetSolver<2> *>(seam.get()) != nullptr && seam->name() == "active set" &&
                     r.n_iterations == result.n_iterations && r.active == result.active &&
                     seam_solver.sets == library_solver.sets && &r == &seam->last_result() && states_match,
                   name + ": ContactSolver::create() gives the active set; solve_step() = solve(), states filled");
    testing::check_small(relative_difference(x_seam, x_library), 0., name + ": max |x_seam - x_solver| / max |x|");
  }

  void
  compare_friction()
  {
    ContactSettings s;
    s.normal               = ContactSettings::Normal::unilateral;
    s.tangential           = ContactSettings::Tangential::coulomb;
    s.friction_coefficient = 0.2;
    Problem                      pb(s, 5.);
    const double                 c = pb.scales->complementarity_constant();
    dealii::SparseMatrix<double> matrix(pb.sparsity);
    const std::vector<double>    reference(pb.contact->n_pairs(), 0.);

    RecordingSolver   library_solver;
    FrictionSolver<2> driver(*pb.contact, pb.constraints, library_solver, s, c);
    driver.set_support(pb.support.get());
    dealii::Vector<double> x_library;
    const auto result = driver.solve(pb.system_matrix, pb.system_rhs, matrix, x_library, driver.initial_state(),
                                     reference);

    RecordingSolver        user_solver;
    FrictionStateUpdate<2> update(pb.contact->get_pairs(), s, c, pb.contact->get_penalty());
    update.set_support(pb.support.get());
    auto                   state = update.start(update.initial_state());
    dealii::Vector<double> x, rhs;
    do
      {
        matrix.copy_from(pb.system_matrix);
        rhs = pb.system_rhs;
        pb.contact->assemble_friction(pb.constraints, state.state, reference, matrix, rhs);
        user_solver.solve(matrix, pb.n, x, rhs);
        pb.constraints.distribute(x);
      }
    while (!update.update(state, *pb.contact, x, reference));
    const auto step = update.converged_step(state, reference);

    unsigned int n_slip = 0;
    for (const auto st : state.state)
      n_slip += (st == PairState::slip_positive || st == PairState::slip_negative);
    std::cout << "friction: " << state.n_iterations << " iterations, " << n_slip << " slipping pairs" << std::endl;
    testing::check(state.n_iterations == result.n_iterations && result.n_iterations > 1 &&
                     user_solver.sets == library_solver.sets && state.history == result.history,
                   "friction: the same iterations (" + std::to_string(state.n_iterations) +
                     ") with the same constraints and state counts");
    testing::check(state.state == result.state && n_slip > 0, "friction: the same converged states, some slipping");
    testing::check_small(relative_difference(x, x_library), 1e-12, "friction: max |x_loop - x_solver| / max |x|");
    double dr = 0;
    for (unsigned int i = 0; i < reference.size(); ++i)
      dr = std::max(dr, std::abs(step.reference[i] - result.reference[i]));
    testing::check_small(dr + std::abs(step.dissipated_energy - result.dissipated_energy), 1e-12,
                         "friction: the same references and dissipated energy");

    // through the common seam: the factory picks the friction solver, the
    // first step starts from the initial states, and the second step starts
    // from the states and references the first ended in (carried by the
    // solver) -- the same as passing them to solve() by hand
    RecordingSolver seam_solver;
    const auto      seam = ContactSolver<2>::create(*pb.contact, pb.constraints, seam_solver, s, c);
    seam->set_support(pb.support.get());
    dealii::Vector<double> x_seam;
    const auto            &first = seam->solve_step(pb.system_matrix, pb.system_rhs, matrix, x_seam);
    testing::check(dynamic_cast<FrictionSolver<2> *>(seam.get()) != nullptr && seam->name() == "Coulomb friction" &&
                     first.state == result.state && first.history == result.history &&
                     first.n_active_history.size() == first.history.size() &&
                     first.active.size() == first.state.size(),
                   "friction: ContactSolver::create() gives the friction solver; its first step = solve()");
    testing::check_small(relative_difference(x_seam, x_library), 0., "friction: max |x_seam - x_solver| / max |x|");
    const auto             first_state = first.state;
    const auto             first_reference = first.reference;
    const auto            &second = seam->solve_step(pb.system_matrix, pb.system_rhs, matrix, x_seam);
    dealii::Vector<double> x_second;
    const auto             by_hand = driver.solve(pb.system_matrix, pb.system_rhs, matrix, x_second, first_state,
                                      first_reference);
    testing::check(second.state == by_hand.state && second.n_iterations == by_hand.n_iterations &&
                     second.reference == by_hand.reference,
                   "friction: the second solve_step() starts from the first one's states and references");
    testing::check_small(relative_difference(x_seam, x_second), 0., "friction: second step, seam vs by hand");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare_active_set(true);
  compare_active_set(false);
  compare_friction();
  return testing::finish();
}
