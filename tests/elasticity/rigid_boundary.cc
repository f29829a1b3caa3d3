// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Rigid boundary parts (BoundaryConditions::add_rigid_boundary) on the
// block [0,1]^2 (structured quads), bottom (id 2) clamped, top (id 3) rigid,
// for k = 1 and k = 2:
// - a resultant (0, -P) at the centroid of the top: by the symmetry of the
//   mesh the top translates, all its nodes have the same displacement
//   (1e-12 relative), and the reactions at the bottom add up to P (1e-10);
// - a moment M only: the top nodes move exactly as a rigid body,
//   u_i - u_A = theta perp(x_i - x_A) (1e-12 relative), and the moment of
//   the bottom reactions is -M (1e-10);
// - writing the rigid lines before or after the Dirichlet lines gives the
//   same solution (1e-12), and a rigid part whose node A is held by point
//   constraints written before it (a hinge, constraint chains resolved by
//   close()) rotates about A;
// - a rigid part does not hold a body (unsupported body), and a rigid part
//   may not take over nodes that other conditions constrain.
#include <dealvem/elasticity/boundary_conditions.h>

#include <functional>

#include "../elasticity_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
  const std::map<dealii::types::material_id, ElasticMaterial> materials = {
    {0, ElasticMaterial(1000, 0.3, ElasticMaterial::Model::plane_strain)}};

  struct Result
  {
    dealii::Vector<double> u;
    dealii::Vector<double> residual; // K u - f without constraints: the reactions
  };

  // Solve with the constraints (closed here) and the loads; also return
  // K u - f of the unconstrained system.
  Result
  solve(const VEMDoFHandler<2>                               &dh,
        dealii::AffineConstraints<double>                    &constraints,
        const std::function<void(ElasticityAssembler<2> &)> &add_loads)
  {
    constraints.close();
    ElasticityAssembler<2> assembler(dh, materials);
    add_loads(assembler);
    dealii::DynamicSparsityPattern dsp(dh.n_dofs());
    dh.make_sparsity_pattern(dsp, constraints);
    dealii::SparsityPattern sp;
    sp.copy_from(dsp);
    dealii::SparseMatrix<double> A(sp);
    dealii::Vector<double>       b;
    assembler.assemble(constraints, A, b);
    Result r;
    r.u.reinit(dh.n_dofs());
    dealii::SparseDirectUMFPACK direct;
    direct.initialize(A);
    direct.vmult(r.u, b);
    constraints.distribute(r.u);

    dealii::AffineConstraints<double> none;
    none.close();
    dealii::DynamicSparsityPattern dsp0(dh.n_dofs());
    dh.make_sparsity_pattern(dsp0);
    dealii::SparsityPattern sp0;
    sp0.copy_from(dsp0);
    dealii::SparseMatrix<double> K(sp0);
    dealii::Vector<double>       f;
    assembler.assemble(none, K, f);
    r.residual.reinit(dh.n_dofs());
    K.vmult(r.residual, r.u);
    r.residual -= f;
    return r;
  }

  dealii::Tensor<1, 2>
  displacement(const Result &r, const unsigned int node)
  {
    dealii::Tensor<1, 2> u;
    u[0] = r.u[VEMDoFHandler<2>::node_dof(node, 0)];
    u[1] = r.u[VEMDoFHandler<2>::node_dof(node, 1)];
    return u;
  }

  // largest |u_i - u_A - theta perp(x_i - x_A)| over the part, relative to
  // the largest displacement of the part; theta from A and B
  double
  rigidity_error(const VEMDoFHandler<2> &dh, const BoundaryConditions::RigidBoundary<2> &part,
                 const Result &r, double &theta)
  {
    const auto d  = part.point_b - part.point_a;
    const auto uA = displacement(r, part.node_a);
    const auto du = displacement(r, part.node_b) - uA;
    theta         = (d[0] * du[1] - d[1] * du[0]) / d.norm_square();
    double err = 0, size = 0;
    for (const auto n : part.nodes)
      {
        const auto           x = dh.node_location(n) - part.point_a;
        dealii::Tensor<1, 2> rigid;
        rigid[0] = uA[0] - theta * x[1];
        rigid[1] = uA[1] + theta * x[0];
        err      = std::max(err, (displacement(r, n) - rigid).norm());
        size     = std::max(size, displacement(r, n).norm());
      }
    return err / size;
  }

  // sum of the reactions (force and moment about the origin) on the nodes
  // of boundary id 2
  void
  bottom_reactions(const VEMDoFHandler<2> &dh, const Result &r, dealii::Tensor<1, 2> &force,
                   double &moment)
  {
    force  = 0;
    moment = 0;
    for (const auto n : dh.boundary_nodes({2}))
      {
        const auto x  = dh.node_location(n);
        const auto rx = r.residual[VEMDoFHandler<2>::node_dof(n, 0)];
        const auto ry = r.residual[VEMDoFHandler<2>::node_dof(n, 1)];
        force[0] += rx;
        force[1] += ry;
        moment += x[0] * ry - x[1] * rx;
      }
  }
} // namespace

int
main()
{
  PolygonalMesh<2> mesh;
  testing::make_mesh(mesh, "structured quads", 0);
  const dealii::Functions::ZeroFunction<2> zero(2);
  const double                             P = 3.5, M = 0.8;
  for (const unsigned int k : {1u, 2u})
    {
      const std::string tag = "k=" + std::to_string(k) + " ";
      VEMDoFHandler<2>  dh(mesh);
      dh.distribute_dofs(k);

      // (i) resultant (0, -P) at the centroid
      {
        dealii::AffineConstraints<double> cons;
        BoundaryConditions::interpolate_boundary_values(dh, {2}, zero, {{true, true}}, cons);
        const auto part = BoundaryConditions::add_rigid_boundary(dh, 3, cons);
        testing::check(std::abs(part.centroid[0] - 0.5) < 1e-15 && std::abs(part.centroid[1] - 1) < 1e-15,
                       tag + "centroid of the top is (0.5, 1)");
        testing::check(part.nodes.size() == (k == 1 ? 5u : 9u), tag + "the top has " +
                                                                  std::to_string(part.nodes.size()) + " nodes");
        cons.close();
        BoundaryConditions::check_rigid_body_support(dh, cons);
        dealii::Tensor<1, 2> F;
        F[1]         = -P;
        const auto r = solve(dh, cons, [&](ElasticityAssembler<2> &a) {
          for (const auto &l : BoundaryConditions::rigid_boundary_load(part, F, 0.))
            a.add_nodal_load(l.first, l.second);
        });
        const auto uA   = displacement(r, part.node_a);
        double     diff = 0;
        for (const auto n : part.nodes)
          diff = std::max(diff, (displacement(r, n) - uA).norm());
        testing::check(uA[1] < 0, tag + "the top moves down");
        testing::check_small(diff / uA.norm(), 1e-12, tag + "top under (0, -P): max |u_i - u_A| / |u_A|");
        dealii::Tensor<1, 2> R;
        double               MR;
        bottom_reactions(dh, r, R, MR);
        testing::check_small(R[1] / P - 1, 1e-10, tag + "bottom reaction R_y / P - 1");
        testing::check_small(R[0] / P, 1e-10, tag + "bottom reaction R_x / P");

        // the same with the rigid lines written before the Dirichlet lines
        dealii::AffineConstraints<double> cons2;
        BoundaryConditions::add_rigid_boundary(dh, 3, cons2);
        BoundaryConditions::interpolate_boundary_values(dh, {2}, zero, {{true, true}}, cons2);
        const auto r2 = solve(dh, cons2, [&](ElasticityAssembler<2> &a) {
          for (const auto &l : BoundaryConditions::rigid_boundary_load(part, F, 0.))
            a.add_nodal_load(l.first, l.second);
        });
        dealii::Vector<double> d = r2.u;
        d -= r.u;
        testing::check_small(d.linfty_norm() / r.u.linfty_norm(), 1e-12,
                             tag + "rigid lines before / after Dirichlet: solution difference");
      }

      // (ii) a moment only
      {
        dealii::AffineConstraints<double> cons;
        BoundaryConditions::interpolate_boundary_values(dh, {2}, zero, {{true, true}}, cons);
        const auto part = BoundaryConditions::add_rigid_boundary(dh, 3, cons);
        const auto r    = solve(dh, cons, [&](ElasticityAssembler<2> &a) {
          for (const auto &l : BoundaryConditions::rigid_boundary_load(part, dealii::Tensor<1, 2>(), M))
            a.add_nodal_load(l.first, l.second);
        });
        double theta = 0;
        testing::check_small(rigidity_error(dh, part, r, theta), 1e-12,
                             tag + "top under a moment: |u_i - u_A - theta perp(x_i - x_A)| / max |u|");
        testing::check(theta > 0, tag + "a counter-clockwise moment turns the top counter-clockwise");
        dealii::Tensor<1, 2> R;
        double               MR;
        bottom_reactions(dh, r, R, MR);
        testing::check_small(MR / M + 1, 1e-10, tag + "moment of the bottom reactions / M + 1");
        testing::check_small(R.norm() / M, 1e-10, tag + "force of the bottom reactions / M");
      }

      // a hinge at A (point constraints written before the rigid part):
      // the top turns about A
      {
        dealii::AffineConstraints<double> cons;
        const dealii::Point<2>            A(0.5, 1);
        BoundaryConditions::add_point_constraint(dh, A, 0, 0., cons);
        BoundaryConditions::add_point_constraint(dh, A, 1, 0., cons);
        const auto part = BoundaryConditions::add_rigid_boundary(dh, 3, cons);
        testing::check(part.point_a.distance(A) < 1e-15, tag + "node A is the middle of the top");
        BoundaryConditions::interpolate_boundary_values(dh, {2}, zero, {{true, true}}, cons);
        const auto r = solve(dh, cons, [&](ElasticityAssembler<2> &a) {
          for (const auto &l : BoundaryConditions::rigid_boundary_load(part, dealii::Tensor<1, 2>(), M))
            a.add_nodal_load(l.first, l.second);
        });
        double theta = 0;
        testing::check(displacement(r, part.node_a).norm() == 0., tag + "hinge: u_A = 0");
        testing::check_small(rigidity_error(dh, part, r, theta), 1e-12, tag + "hinge: the top turns about A");
        testing::check(theta > 0, tag + "hinge: theta > 0");
      }

      // a rigid part holds no body
      {
        dealii::AffineConstraints<double> cons;
        BoundaryConditions::add_rigid_boundary(dh, 3, cons);
        cons.close();
        testing::check_throws([&] { BoundaryConditions::check_rigid_body_support(dh, cons); },
                              "Unsupported body", tag + "a body with only a rigid boundary is unsupported");
        dealii::AffineConstraints<double> hinge;
        BoundaryConditions::add_point_constraint(dh, dealii::Point<2>(0.5, 1), 0, 0., hinge);
        BoundaryConditions::add_point_constraint(dh, dealii::Point<2>(0.5, 1), 1, 0., hinge);
        BoundaryConditions::add_rigid_boundary(dh, 3, hinge);
        hinge.close();
        testing::check_throws([&] { BoundaryConditions::check_rigid_body_support(dh, hinge); },
                              "+ rotation]", tag + "a body hinged at one point of a rigid part can rotate about it");
      }

      // collisions: the left side (id 0) fixed shares the corner (0, 1)
      {
        dealii::AffineConstraints<double>     cons;
        BoundaryConditions::ConstraintOrigins origins;
        BoundaryConditions::interpolate_boundary_values(dh, {0}, zero, {{true, true}}, cons);
        for (const auto &line : cons.get_lines())
          origins[line.index] = "Dirichlet id 0";
        testing::check_throws([&] { BoundaryConditions::add_rigid_boundary(dh, 3, cons, "rigid top", &origins); },
                              "Parameter 'rigid top' on mesh", tag + "rigid part on a constrained node: error");
        testing::check_throws([&] { BoundaryConditions::add_rigid_boundary(dh, 3, cons, "rigid top", &origins); },
                              "already constrained by Dirichlet id 0", tag + "the error names the other condition");
      }
    }
  return testing::finish();
}
