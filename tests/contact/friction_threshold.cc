// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The stick/slip threshold, written with the library classes (as step-2):
// a block [0,1] x [1,2] (5x4 quads) on a support [0,1] x [0,1] (3x3 quads,
// non-matching), same material, under the uniform stress
// sigma = [[0, tau], [tau, -p]] (tractions sigma n on every side), Coulomb
// friction mu = 0.3 by multipliers. The block is also held by a spring of
// stiffness k between the mean tangential displacements of the two sides of
// the interface (weighted by the tributary lengths, so its force is spread
// over the interface as a uniform traction and the stress stays uniform):
// - tau = 0.99 mu p: every pair sticks, no slip (1e-12 of the elastic
//   displacement), the spring carries nothing;
// - tau = 1.01 mu p: every pair slips forward, friction carries mu p and the
//   spring the excess: slip = (tau - mu p) L / k at every pair to 1e-8
//   relative, dissipated energy mu p L slip;
// for k = 1 and 2. Without the spring the friction solver, told which
// rigid-body motions the supports hold, stops with "No static equilibrium".
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/friction_solver.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/contact/rigid_body_support.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/solvers/saddle_point_solver.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/vem/vem_values.h>

#include <cmath>
#include <map>

#include "../tests.h"

using namespace dealvem;

struct Outcome
{
  unsigned int        n_stick = 0, n_slip_forward = 0, iterations = 0;
  std::vector<double> slip;
  double              dissipated = 0;
};

Outcome
run(const unsigned int degree, const double tau, const double spring, const bool with_support)
{
  const double E = 7000, nu = 0.3, p = 10, mu = 0.3;
  PolygonalMesh<2> mesh, upper;
  PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 3, 3);
  PolygonalMeshGenerators::structured_quads(upper, dealii::Point<2>(0, 1), dealii::Point<2>(1, 2), 5, 4);
  for (unsigned int c = 0; c < upper.n_cells(); ++c)
    upper.set_material_id(c, 1);
  for (unsigned int e = 0; e < upper.n_edges(); ++e)
    if (upper.edge(e).at_boundary())
      upper.set_edge_boundary_id(e, upper.edge(e).boundary_id + 10);
  mesh.append(upper);
  const auto interface = NodeInsertion::insert(mesh, 3, 12, degree, NodeInsertion::Settings());
  VEMDoFHandler<2> dof_handler(mesh);
  dof_handler.distribute_dofs(degree);
  const auto &pairs = interface.pairs;

  std::map<dealii::types::material_id, ElasticMaterial> materials{{0, ElasticMaterial(E, nu)},
                                                                  {1, ElasticMaterial(E, nu)}};
  ContactSettings settings;
  settings.normal               = ContactSettings::Normal::unilateral;
  settings.tangential           = ContactSettings::Tangential::coulomb;
  settings.friction_coefficient = mu;
  ContactAssembler<2> contact(dof_handler, pairs, settings, 0.);

  // bottom held vertically, the support's corner (0,0) horizontally
  dealii::AffineConstraints<double> constraints;
  dealii::Functions::ZeroFunction<2> zero(2);
  BoundaryConditions::interpolate_boundary_values(dof_handler, {2}, zero, {{false, true}}, constraints);
  BoundaryConditions::add_point_constraint(dof_handler, dealii::Point<2>(0, 0), 0, 0., constraints);
  constraints.close();

  // the spring: k (a.u)^2 / 2 with a.u the tributary-weighted mean of the
  // tangential (x) relative displacement (u_B - u_A) over the interface
  double L = 0;
  for (const auto &pr : pairs)
    L += pr.weight;
  std::vector<dealii::types::global_dof_index> spring_dofs;
  std::vector<double>                          a;
  for (unsigned int i = 0; i < pairs.size(); ++i)
    {
      const auto d = contact.pair_dofs(i);
      spring_dofs.push_back(d[0]);
      a.push_back(-pairs[i].weight / L);
      spring_dofs.push_back(d[2]);
      a.push_back(pairs[i].weight / L);
    }

  const unsigned int             n = dof_handler.n_dofs(), m = contact.n_multipliers();
  dealii::DynamicSparsityPattern dsp(n + m);
  dof_handler.make_sparsity_pattern(dsp);
  contact.add_sparsity(dsp);
  for (const auto i : spring_dofs)
    for (const auto j : spring_dofs)
      dsp.add(i, j);
  constraints.condense(dsp);
  dealii::SparsityPattern sparsity;
  sparsity.copy_from(dsp);
  dealii::SparseMatrix<double> system_matrix(sparsity), work_matrix(sparsity);
  dealii::Vector<double>       system_rhs(n + m);

  // tractions sigma n: top (tau, -p), sides (0, -+tau), bottom (-tau, 0)
  ElasticityAssembler<2>                 assembler(dof_handler, materials);
  dealii::Functions::ConstantFunction<2> top(std::vector<double>{tau, -p}), left(std::vector<double>{0, -tau}),
    right(std::vector<double>{0, tau}), bottom(std::vector<double>{-tau, 0});
  assembler.add_traction(13, top);
  for (const unsigned int id : {0u, 10u})
    assembler.add_traction(id, left);
  for (const unsigned int id : {1u, 11u})
    assembler.add_traction(id, right);
  assembler.add_traction(2, bottom);
  VEMValues<2>          vem_values(dof_handler);
  ElasticityOperator<2> elasticity;
  for (unsigned int c = 0; c < mesh.n_cells(); ++c)
    {
      vem_values.reinit(c);
      elasticity.reinit(vem_values.get_element(), assembler.get_material(c));
      dealii::Vector<double> F;
      assembler.local_load(vem_values, F);
      constraints.distribute_local_to_global(elasticity.get_stiffness_matrix(), F, vem_values.get_dof_indices(),
                                             system_matrix, system_rhs);
    }
  if (spring > 0)
    {
      dealii::FullMatrix<double> K(spring_dofs.size(), spring_dofs.size());
      for (unsigned int i = 0; i < a.size(); ++i)
        for (unsigned int j = 0; j < a.size(); ++j)
          K(i, j) = spring * a[i] * a[j];
      constraints.distribute_local_to_global(K, spring_dofs, system_matrix);
    }

  double h_min = 1e300;
  for (const auto &s : interface.segments)
    h_min = std::min(h_min, s.length);
  SaddlePointSolver      solver(SaddlePointSolver::Settings{});
  FrictionSolver<2>      friction(contact, constraints, solver, settings, E / h_min);
  RigidBodySupport       support(dof_handler, constraints, contact, true);
  if (with_support)
    friction.set_support(&support);
  dealii::Vector<double> x;
  const auto r = friction.solve(system_matrix, system_rhs, work_matrix, x, friction.initial_state(),
                                std::vector<double>(pairs.size(), 0.));
  Outcome o;
  o.iterations = r.n_iterations;
  o.dissipated = r.dissipated_energy;
  // slip and its direction along +x (the pair tangent may point either way)
  for (unsigned int i = 0; i < pairs.size(); ++i)
    {
      const double tx = pairs[i].tangent[0];
      o.slip.push_back(r.slip[i] * tx);
      o.n_stick += (r.state[i] == PairState::stick);
      o.n_slip_forward += ((r.state[i] == PairState::slip_positive && tx > 0) ||
                           (r.state[i] == PairState::slip_negative && tx < 0));
    }
  std::cout << "   k = " << degree << ", tau/(mu p) = " << tau / 3. << (spring > 0 ? ", spring" : ", no spring")
            << ": " << pairs.size() << " pairs, " << r.n_iterations << " Newton iteration(s), " << o.n_stick
            << " stick, " << o.n_slip_forward << " slip forward" << std::endl;
  return o;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             p = 10, mu = 0.3, G = 7000 / (2 * 1.3), k_spring = 70;
  for (const unsigned int degree : {1u, 2u})
    {
      const std::string tag = "k = " + std::to_string(degree) + ": ";
      // below the threshold: stick, no slip
      {
        const double tau = 0.99 * mu * p;
        const auto   o   = run(degree, tau, k_spring, false);
        double       s   = 0;
        for (const double v : o.slip)
          s = std::max(s, std::abs(v));
        testing::check(o.n_stick == o.slip.size(), tag + "0.99 mu N: every pair sticks");
        testing::check_small(s / (tau / G), 1e-12, tag + "0.99 mu N: max |slip| / (tau/G)");
        testing::check_small(o.dissipated, 1e-14, tag + "0.99 mu N: nothing dissipated");
      }
      // above: slides until the spring carries the excess
      {
        const double tau    = 1.01 * mu * p;
        const double excess = (tau - mu * p) * 1.0; // per unit interface length L = 1
        const double slip   = excess / k_spring;
        const auto   o      = run(degree, tau, k_spring, false);
        double       err    = 0;
        for (const double v : o.slip)
          err = std::max(err, std::abs(v / slip - 1.));
        testing::check(o.n_slip_forward == o.slip.size(), tag + "1.01 mu N: every pair slips forward");
        testing::check_small(err, 1e-8, tag + "1.01 mu N: max |slip / (excess/k) - 1|");
        testing::check_near(o.dissipated, mu * p * 1.0 * slip, 1e-8 * mu * p * slip,
                            tag + "1.01 mu N: dissipated energy = mu N slip");
        testing::check(o.iterations <= 3, tag + "1.01 mu N: at most 3 Newton iterations (" +
                                            std::to_string(o.iterations) + ")");
      }
      // without the spring the block has no equilibrium
      testing::check_throws([&]() { run(degree, 1.01 * mu * p, 0, true); }, "No static equilibrium",
                            tag + "1.01 mu N without the spring: no static equilibrium");
    }
  return testing::finish();
}
