// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// FiniteStrainAssembler keeps per cell what does not change with the
// displacement (DoF indices, the coefficients of Pi^0 grad phi_i in the
// monomials, the quadrature, the state-independent part of the
// stabilization) and folds the sums over the quadrature points into
// moments. Its residual, tangent (condensed with inhomogeneous
// constraints), right-hand side and stored energy are compared here with
// the cell-by-cell computation of FiniteStrainOperator at every quadrature
// point (compute_consistency(), compute_stabilization(),
// ElasticityAssembler::local_load(), the follower pressure of
// VirtualElement::add_edge_follower_pressure()), to 1e-12 relative, at a
// nonlinear state u with the stabilization frozen at another state u*:
// Voronoi (16 cells) and perturbed quads (4 x 4), k = 1 and 2, three
// cases (Neo-Hooke with the trace rule, a traction and a follower
// pressure; Saint Venant-Kirchhoff in plane stress with the diagonal rule,
// a body force and a traction; Neo-Hooke with the boundary rule and the
// initial-tangent scaling, no load). Then the mesh changes under the
// assembler (vertices moved, then a finer mesh): assemble() refuses until
// freeze_stabilization() is called, which computes the cell data for the
// new mesh, and the results match the reference again.
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/elasticity/finite_strain_operator.h>
#include <dealvem/vem/vem_values.h>

#include <cmath>
#include <random>

#include "../elasticity_common.h"
#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;

namespace finite_strain_cell_data_test
{
  // A smooth pressure (scalar) and body force (two components).
  class Pressure : public dealii::Function<2>
  {
  public:
    Pressure()
      : dealii::Function<2>(1)
    {}
    double
    value(const dealii::Point<2> &p, const unsigned int) const override
    {
      return 0.02 + 0.01 * p[0];
    }
  };

  class BodyForce : public dealii::Function<2>
  {
  public:
    BodyForce()
      : dealii::Function<2>(2)
    {}
    double
    value(const dealii::Point<2> &p, const unsigned int c) const override
    {
      return c == 0 ? 0.03 * p[1] : -0.05 + 0.02 * p[0] * p[0];
    }
  };

  // The small Dirichlet data on the bottom side (boundary id 2): an
  // inhomogeneity for the condensation.
  class Lift : public dealii::Function<2>
  {
  public:
    Lift()
      : dealii::Function<2>(2)
    {}
    double
    value(const dealii::Point<2> &p, const unsigned int c) const override
    {
      return c == 0 ? 0.004 * p[0] : -0.002 * p[0] * (1 - p[0]);
    }
  };

  struct Case
  {
    std::string          name;
    bool                 plane_stress_svk;
    Stabilization        rule;
    StabilizationScaling scaling;
    bool                 traction, follower, body_force;
  };

  const Pressure                  pressure;
  const BodyForce                 body_force;
  const testing::ConstantTraction traction(dealii::Tensor<1, 2>({0.01, -0.03}));

  void
  add_loads(const Case &cs, FiniteStrainAssembler<2> &assembler)
  {
    if (cs.traction)
      assembler.add_traction(1, traction);
    if (cs.follower)
      assembler.add_pressure(3, pressure, PressureLoad::follower);
    if (cs.body_force)
      assembler.set_body_force(body_force);
  }

  // u = a smooth nonlinear field plus random values of amplitude 0.003;
  // scale 0.5 and another seed for u*.
  dealii::Vector<double>
  state(const VEMDoFHandler<2> &dof_handler, const double scale, const unsigned int seed)
  {
    std::vector<dealii::Point<2>> support;
    dof_handler.map_dofs_to_support_points(support);
    std::mt19937                           rng(seed);
    std::uniform_real_distribution<double> random(-0.003, 0.003);
    dealii::Vector<double>                 u(dof_handler.n_dofs());
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        const dealii::Point<2> &X = support[i];
        u[i] = scale * (i % 2 == 0 ? 0.1 * std::sin(2 * X[0] + X[1]) + 0.05 * X[0] * X[0] :
                                     0.08 * X[0] * X[1] * X[1] - 0.03 * std::cos(X[1])) +
               random(rng);
      }
    return u;
  }

  // The assembler against the cell-by-cell, point-by-point computation at
  // u, the stabilization frozen at u_star (the assembler's freeze must have
  // been called with u_star).
  void
  compare(const VEMDoFHandler<2>         &dof_handler,
          const MaterialLibrary<2>       &laws,
          const Case                     &cs,
          const FiniteStrainAssembler<2> &assembler,
          const dealii::Vector<double>   &u,
          const dealii::Vector<double>   &u_star,
          const std::string              &name)
  {
    const double                      gamma = 1., load_factor = 0.7;
    dealii::AffineConstraints<double> constraints;
    constraints.clear();
    BoundaryConditions::interpolate_boundary_values(dof_handler, {0}, dealii::Functions::ZeroFunction<2>(2),
                                                    {{true, true}}, constraints);
    BoundaryConditions::interpolate_boundary_values(dof_handler, {2}, Lift(), {{true, true}}, constraints);
    constraints.close();
    dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
    dof_handler.make_sparsity_pattern(dsp, constraints, false);
    dealii::SparsityPattern sp;
    sp.copy_from(dsp);
    dealii::SparseMatrix<double> K(sp), K_ref(sp);
    dealii::Vector<double>       r, rhs, r_only;
    assembler.assemble(u, load_factor, r, constraints, &K, &rhs);
    assembler.assemble(u, load_factor, r_only, constraints, nullptr, nullptr);

    // the reference
    ElasticityAssembler<2> loads(dof_handler, laws, gamma, cs.rule);
    if (cs.traction)
      loads.add_traction(1, traction);
    if (cs.body_force)
      loads.set_body_force(body_force);
    dealii::Vector<double>     r_ref(dof_handler.n_dofs()), rhs_ref(dof_handler.n_dofs());
    dealii::Vector<double>     local_u, local_u_star, r_c, F, F_load, F_p, K_s_u;
    dealii::FullMatrix<double> K_c, K_s, K_p;
    VEMValues<2>               values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values);
    FiniteStrainOperator<2>    op;
    double                     energy_ref = 0, force_scale = 0;
    for (unsigned int c = 0; c < dof_handler.get_mesh().n_cells(); ++c)
      {
        values.reinit(c);
        op.reinit(values);
        const ConstitutiveLaw<2> &law = loads.get_law(c);
        dof_handler.get_dof_values(c, u, local_u);
        dof_handler.get_dof_values(c, u_star, local_u_star);
        const unsigned int n = local_u.size();
        op.compute_consistency(law, local_u, true, r_c, K_c);
        op.compute_stabilization(values.get_element(), law, local_u_star, gamma,
                                 cs.rule == Stabilization::automatic ? Stabilization::trace : cs.rule, cs.scaling,
                                 K_s);
        K_s_u.reinit(n);
        K_s.vmult(K_s_u, local_u);
        loads.local_load(values, F_load);
        F.reinit(n);
        F.add(load_factor, F_load);
        F -= r_c;
        F -= K_s_u;
        force_scale = std::max(force_scale, r_c.linfty_norm());
        K_c.add(1., K_s);
        if (cs.follower)
          for (unsigned int e = 0; e < values.n_edges(); ++e)
            if (values.edge_boundary_id(e) == 3)
              {
                F_p.reinit(n);
                K_p.reinit(n, n);
                values.get_element().add_edge_follower_pressure(e, pressure, local_u, F_p, &K_p);
                F.add(load_factor, F_p);
                K_c.add(-load_factor, K_p);
              }
        const auto &indices = values.get_dof_indices();
        for (unsigned int i = 0; i < n; ++i)
          r_ref[indices[i]] += F[i];
        constraints.distribute_local_to_global(K_c, F, indices, K_ref, rhs_ref);
        energy_ref += op.strain_energy(law, local_u) + 0.5 * (local_u * K_s_u);
      }

    double err_r = 0, err_rhs = 0, err_K = 0, max_K = 0, err_split = 0;
    for (unsigned int i = 0; i < r.size(); ++i)
      {
        err_r     = std::max(err_r, std::abs(r[i] - r_ref[i]));
        err_rhs   = std::max(err_rhs, std::abs(rhs[i] - rhs_ref[i]));
        err_split = std::max(err_split, std::abs(r[i] - r_only[i]));
      }
    for (auto it = K_ref.begin(); it != K_ref.end(); ++it)
      {
        max_K = std::max(max_K, std::abs(it->value()));
        err_K = std::max(err_K, std::abs(it->value() - K.el(it->row(), it->column())));
      }
    testing::check_small(err_r / force_scale, 1e-12, name + ": residual against the per-point computation");
    testing::check_small(err_rhs / force_scale, 1e-12, name + ": right-hand side against the per-point computation");
    testing::check_small(err_K / max_K, 1e-12, name + ": tangent against the per-point computation");
    testing::check_small(err_split, 0., name + ": the residual without the tangent is the same");
    const double energy = assembler.strain_energy(u);
    testing::check_small(std::abs(energy - energy_ref) / std::abs(energy_ref), 1e-12,
                         name + ": stored energy against the per-point computation");
    std::cout << "    " << name << ": |r - r_ref| / max |r_c| = " << err_r / force_scale
              << ", |K - K_ref| / max |K| = " << err_K / max_K << std::endl;
  }
} // namespace finite_strain_cell_data_test

int
main()
{
  using namespace finite_strain_cell_data_test;
  const std::vector<Case> cases = {
    {"Neo-Hooke, trace rule, traction and follower pressure", false, Stabilization::trace,
     StabilizationScaling::current_tangent, true, true, false},
    {"SVK plane stress, diagonal rule, body force and traction", true, Stabilization::diagonal,
     StabilizationScaling::current_tangent, true, false, true},
    {"Neo-Hooke, boundary rule, initial tangent, no load", false, Stabilization::boundary,
     StabilizationScaling::initial_tangent, false, false, false}};
  const NeoHookeMaterial             neo_hooke(1., 0.3);
  const SaintVenantKirchhoffMaterial svk(1., 0.3, ElasticMaterial::Model::plane_stress);
  for (const std::string family : {"voronoi", "perturbed quads"})
    for (const unsigned int k : {1u, 2u})
      for (const Case &cs : cases)
        {
          PolygonalMesh<2> mesh;
          testing::make_mesh(mesh, family, 0);
          VEMDoFHandler<2> dof_handler(mesh);
          dof_handler.distribute_dofs(k);
          const ConstitutiveLaw<2> &law  = cs.plane_stress_svk ? static_cast<const ConstitutiveLaw<2> &>(svk) :
                                                                 static_cast<const ConstitutiveLaw<2> &>(neo_hooke);
          const MaterialLibrary<2>  laws = testing::one_law_library(dof_handler, law);
          FiniteStrainAssembler<2>  assembler(dof_handler, laws, 1., cs.rule, cs.scaling);
          add_loads(cs, assembler);
          const std::string name = family + ", k = " + std::to_string(k) + ", " + cs.name;
          dealii::Vector<double> u = state(dof_handler, 1., 3), u_star = state(dof_handler, 0.5, 4);
          assembler.freeze_stabilization(u_star);
          compare(dof_handler, laws, cs, assembler, u, u_star, name);
          if (&cs != &cases.front())
            continue;

          // the vertices moved inside the square (the boundary stays): a new
          // revision of the mesh
          for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
            {
              const dealii::Point<2> X = mesh.vertex(v);
              mesh.move_vertex(v, X + 0.03 * std::sin(M_PI * X[0]) * std::sin(M_PI * X[1]) *
                                        dealii::Point<2>(1., 0.5));
            }
          mesh.validate();
          dof_handler.distribute_dofs(k);
          dealii::Vector<double>            r;
          dealii::AffineConstraints<double> none;
          none.close();
          testing::check_throws([&] { assembler.assemble(u, 1., r, none, nullptr, nullptr); },
                                "call freeze_stabilization() again",
                                name + ", moved vertices: assemble() refuses the stale cell data");
          assembler.freeze_stabilization(u_star);
          compare(dof_handler, laws, cs, assembler, u, u_star, name + ", moved vertices");

          // a finer mesh in its place
          testing::make_mesh(mesh, family, 1);
          dof_handler.distribute_dofs(k);
          u      = state(dof_handler, 1., 5);
          u_star = state(dof_handler, 0.5, 6);
          testing::check_throws([&] { assembler.strain_energy(u); }, "call freeze_stabilization() again",
                                name + ", finer mesh: strain_energy() refuses the stale cell data");
          assembler.freeze_stabilization(u_star);
          compare(dof_handler, laws, cs, assembler, u, u_star, name + ", finer mesh");
        }
  return testing::finish();
}
