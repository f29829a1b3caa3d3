// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Boundary parts turned rigidly about a centre (a gear's bore):
// BoundaryConditions::add_torque_rotation() (the angle an unknown, loaded by
// rotation_torque_load()) and add_prescribed_rotation() (the exact rotation
// as Dirichlet data), with SupportReactions::rotation().
//
// - The annulus r1 = 0.5 <= r <= r2 = 1 about c = (0.3, -0.2) (a structured
//   polar quad mesh, vertices at r_i, 2 pi j / n exactly), the outer circle
//   clamped, the bore loaded by the torque M: the rotation of the bore is
//   theta = M/(4 pi mu) (1/r1^2 - 1/r2^2) (plane strain, u_theta = A r + B/r,
//   independent of lambda). The relative error of theta decreases at rate
//   2 in h for k = 1 and k = 2 (the polygonal circles bound k = 2 to the
//   geometric error O(h^2)) on three meshes (measured 1.97, 2.02 for k = 1;
//   2.33, 2.08 for k = 2), and is below 1.5e-3 (k = 1; 1.11e-3 measured)
//   and 2e-3 (k = 2; 1.59e-3) on the finest mesh, 64 x 8 cells. The moment of the clamped circle's reactions about c is
//   -M (1e-10 relative), and the bearing force of the bore (the torque a
//   pure couple) vanishes by the symmetry of the mesh.
// - The bore turned by a prescribed angle theta: the reaction moment about
//   c is 4 pi mu theta / (1/r1^2 - 1/r2^2) within the same errors; and the
//   two conditions are inverse to each other on one mesh: the angle solved
//   for under M, prescribed exactly, gives the reaction moment
//   M sin(theta)/theta (1e-10; the exact rotation is the linearized one by
//   sin(theta) plus a radial part without moment on the mirror-symmetric
//   mesh).
// - An exact rotation of the whole boundary about c (four parts, the same
//   angle and centre) gives the affine field u = (R - I)(x - c) at every
//   node and the uniform stress 2 (lambda + mu)(cos theta - 1) I of its
//   linear strain (cos theta - 1) I, to round-off; at theta = 1e-4 that is
//   5e-9 E: an exact rotation is stress free up to O(theta^2) at small
//   strain. The linearized rotation u = theta perp(x - c) (the lines of
//   add_torque_rotation() on all four sides, theta set through the master
//   DoF by a point value) is stress free to round-off.
// - Errors: unknown boundary id, centre not finite, angle not finite, a
//   DoF of the part constrained by another condition (both named), a torque
//   load on a part with a prescribed angle.
#include <deal.II/base/function.h>
#include <deal.II/base/numbers.h>

#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/support_reactions.h>
#include <dealvem/postprocessing/stress_recovery.h>

#include <functional>
#include <limits>

#include "../elasticity_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
  const double           E = 1000, nu = 0.3;
  const double           mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double           r1 = 0.5, r2 = 1.0;
  const dealii::Point<2> centre(0.3, -0.2);
  const std::map<dealii::types::material_id, ElasticMaterial> materials = {
    {0, ElasticMaterial(E, nu, ElasticMaterial::Model::plane_strain)}};

  // the annulus r1 <= |x - c| <= r2, n_r x n_t polar quads; boundary id 0
  // on the bore, 1 on the outer circle
  void
  make_annulus(PolygonalMesh<2> &mesh, const unsigned int n_r, const unsigned int n_t)
  {
    mesh.clear();
    mesh.name = "annulus " + std::to_string(n_r) + "x" + std::to_string(n_t);
    for (unsigned int i = 0; i <= n_r; ++i)
      for (unsigned int j = 0; j < n_t; ++j)
        {
          const double r = r1 + (r2 - r1) * i / n_r, t = 2 * dealii::numbers::PI * j / n_t;
          mesh.add_vertex(dealii::Point<2>(centre[0] + r * std::cos(t), centre[1] + r * std::sin(t)));
        }
    const auto v = [n_t](const unsigned int i, const unsigned int j) { return i * n_t + j % n_t; };
    for (unsigned int i = 0; i < n_r; ++i)
      for (unsigned int j = 0; j < n_t; ++j)
        mesh.add_cell({v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
    for (unsigned int j = 0; j < n_t; ++j)
      {
        mesh.set_boundary_id(v(0, j), v(0, j + 1), 0);
        mesh.set_boundary_id(v(n_r, j), v(n_r, j + 1), 1);
      }
    mesh.finalize();
  }

  struct Result
  {
    dealii::Vector<double> u;
    dealii::Vector<double> unbalanced; // f - K u without constraints
  };

  // Solve with the (closed here) constraints and nodal loads; also return
  // f - K u of the unconstrained system.
  Result
  solve(const VEMDoFHandler<2>                                                &dh,
        dealii::AffineConstraints<double>                                     &constraints,
        const std::vector<std::pair<dealii::types::global_dof_index, double>> &nodal_loads)
  {
    constraints.close();
    ElasticityAssembler<2> assembler(dh, materials);
    for (const auto &l : nodal_loads)
      assembler.add_nodal_load(l.first, l.second);
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
    r.unbalanced.reinit(dh.n_dofs());
    K.vmult(r.unbalanced, r.u);
    r.unbalanced.sadd(-1., f);
    return r;
  }

  std::vector<dealii::Point<2>>
  node_positions(const VEMDoFHandler<2> &dh)
  {
    std::vector<dealii::Point<2>> p(dh.n_nodes());
    for (unsigned int m = 0; m < p.size(); ++m)
      p[m] = dh.node_location(m);
    return p;
  }

  // the lines of the outer circle, as a support
  SupportReactions::Support
  outer_support(const dealii::AffineConstraints<double> &constraints)
  {
    SupportReactions::Support s;
    s.name = "outer circle";
    s.key  = "outer";
    for (const auto &line : constraints.get_lines())
      s.lines.push_back(line.index);
    return s;
  }

  class Zero2 : public dealii::Function<2>
  {
  public:
    Zero2()
      : dealii::Function<2>(2)
    {}
    double
    value(const dealii::Point<2> &, const unsigned int = 0) const override
    {
      return 0;
    }
  };

  const double M = 7.5; // the torque on the bore

  double
  theta_exact(const double torque)
  {
    return torque / (4 * dealii::numbers::PI * mu) * (1 / (r1 * r1) - 1 / (r2 * r2));
  }

  // theta under M and the rotations' reactions on the annulus n_r x 8 n_r
  struct AnnulusResult
  {
    double theta_torque;       // solved for under M
    double outer_moment;       // the clamped circle's reaction moment about c
    double moment_of_angle;    // the reaction moment about c of theta_torque prescribed
    double moment_exact_angle; // the reaction moment of the exact theta prescribed
    double torque_reported;    // SupportReactions::rotation() of the torque case
    double reaction_of_torque_lines;
    double bearing_force; // |force| of the torque case: 0 by the symmetry
    double h;
  };

  AnnulusResult
  annulus(const unsigned int k, const unsigned int n_r)
  {
    PolygonalMesh<2> mesh;
    make_annulus(mesh, n_r, 8 * n_r);
    VEMDoFHandler<2> dh(mesh);
    dh.distribute_dofs(k);
    const auto    positions = node_positions(dh);
    AnnulusResult out;
    out.h = mesh.cell_diameter_range().second;
    const Zero2 zero;
    // torque
    {
      dealii::AffineConstraints<double> cons;
      BoundaryConditions::interpolate_boundary_values(dh, {1}, zero, {{true, true}}, cons);
      const auto outer    = outer_support(cons);
      const auto part     = BoundaryConditions::add_torque_rotation(dh, 0, centre, cons);
      const auto r        = solve(dh, cons, BoundaryConditions::rotation_torque_load(part, M));
      out.theta_torque    = part.angle(r.u);
      out.outer_moment    = SupportReactions::compute({outer}, cons, r.unbalanced, positions, centre).front().moment;
      const auto rot      = SupportReactions::rotation(part, M, cons, r.u, r.unbalanced, positions);
      out.torque_reported = rot.moment_about_centre;
      out.reaction_of_torque_lines = rot.reaction_moment;
      out.bearing_force            = rot.force.norm();
    }
    // the angle found, and the exact one, prescribed
    for (const bool exact : {false, true})
      {
        const double                      theta = exact ? theta_exact(M) : out.theta_torque;
        dealii::AffineConstraints<double> cons;
        BoundaryConditions::interpolate_boundary_values(dh, {1}, zero, {{true, true}}, cons);
        const auto part = BoundaryConditions::add_prescribed_rotation(dh, 0, centre, theta, cons);
        const auto r    = solve(dh, cons, {});
        const auto rot  = SupportReactions::rotation(part, 0., cons, r.u, r.unbalanced, positions);
        (exact ? out.moment_exact_angle : out.moment_of_angle) = rot.reaction_moment;
      }
    return out;
  }

  void
  annulus_tests()
  {
    const double theta_ex = theta_exact(M);
    // the moment an exactly prescribed theta_ex needs is M
    for (const unsigned int k : {1u, 2u})
      {
        const std::string   tag = "k = " + std::to_string(k) + ": ";
        std::vector<double> err_theta, err_moment, hs;
        for (const unsigned int n_r : {2u, 4u, 8u})
          {
            const auto r = annulus(k, n_r);
            err_theta.push_back(std::abs(r.theta_torque - theta_ex) / theta_ex);
            err_moment.push_back(std::abs(r.moment_exact_angle - M) / M);
            hs.push_back(r.h);
            std::cout << "  " << tag << "n_r = " << n_r << ", h = " << r.h << ": theta = " << std::setprecision(12)
                      << r.theta_torque << " (exact " << theta_ex << "), relative error " << std::setprecision(4)
                      << err_theta.back() << "; moment of the exact angle " << std::setprecision(12)
                      << r.moment_exact_angle << " (exact " << M << "), relative error " << std::setprecision(4)
                      << err_moment.back() << std::endl;
            const std::string t = tag + "n_r = " + std::to_string(n_r) + ": ";
            testing::check_small((r.outer_moment + M) / M, 1e-10,
                                 t + "moment of the clamped circle's reactions about the centre + M, relative");
            // the exact rotation by theta is the linearized one by sin(theta)
            // plus the radial (cos(theta) - 1)(x - c), whose moment vanishes
            // by the mirror symmetry of the mesh: the inverse of the torque
            // case is M sin(theta)/theta (M - theta^2/6 M, 3.6e-6 M here)
            const double inverse = M * std::sin(r.theta_torque) / r.theta_torque;
            testing::check_small((r.moment_of_angle - inverse) / M, 1e-10,
                                 t + "the angle solved for under M, prescribed, needs the moment M sin(theta)/theta "
                                     "(relative)");
            testing::check_small((r.torque_reported - M) / M, 1e-14,
                                 t + "SupportReactions::rotation(): moment about centre of the torque case = M");
            testing::check_small(r.reaction_of_torque_lines / M, 1e-10,
                                 t + "the lines of a torque-driven part transmit no moment about the centre");
            testing::check_small(r.bearing_force * r1 / M, 1e-10,
                                 t + "a pure torque on the symmetric annulus needs no bearing force (|F| r1 / M)");
          }
        for (unsigned int i = 1; i < hs.size(); ++i)
          {
            const double rate_t = std::log(err_theta[i - 1] / err_theta[i]) / std::log(hs[i - 1] / hs[i]);
            const double rate_m = std::log(err_moment[i - 1] / err_moment[i]) / std::log(hs[i - 1] / hs[i]);
            std::cout << "  " << tag << "rates: theta " << rate_t << ", moment " << rate_m << std::endl;
            testing::check(rate_t > 1.8,
                           tag + "theta under a torque converges at rate 2 (measured " + std::to_string(rate_t) + ")");
            testing::check(rate_m > 1.8, tag +
                                           "the reaction moment of a prescribed angle converges at rate 2 "
                                           "(measured " +
                                           std::to_string(rate_m) + ")");
          }
        // the bounds on the finest mesh (n_r = 8, 64 cells around)
        const double bound = (k == 1 ? 1.5e-3 : 2e-3);
        testing::check_small(err_theta.back(), bound, tag + "relative error of theta on the finest mesh");
        testing::check_small(err_moment.back(), bound, tag + "relative error of the moment on the finest mesh");
      }
  }

  // (R - I)(x - c)
  class ExactRotation : public dealii::Function<2>
  {
  public:
    explicit ExactRotation(const double theta)
      : dealii::Function<2>(2)
      , theta(theta)
    {}
    double
    value(const dealii::Point<2> &x, const unsigned int c = 0) const override
    {
      const double dx = x[0] - centre[0], dy = x[1] - centre[1];
      return c == 0 ? (std::cos(theta) - 1) * dx - std::sin(theta) * dy
                    : std::sin(theta) * dx + (std::cos(theta) - 1) * dy;
    }
    double theta;
  };

  void
  whole_body_rotation()
  {
    for (const std::string family : {"voronoi", "nonconvex"})
      for (const unsigned int k : {1u, 2u})
        {
          const std::string tag = family + ", k = " + std::to_string(k) + ": ";
          PolygonalMesh<2>  mesh;
          testing::make_mesh(mesh, family, 1);
          VEMDoFHandler<2> dh(mesh);
          dh.distribute_dofs(k);
          const double theta = 1e-4;
          // the exact rotation on the four sides, written as four parts
          // (the corners shared: the same value is accepted)
          {
            dealii::AffineConstraints<double> cons;
            for (const dealii::types::boundary_id id : {0, 1, 2, 3})
              BoundaryConditions::add_prescribed_rotation(dh, id, centre, theta, cons);
            const auto          r = solve(dh, cons, {});
            const ExactRotation g(theta);
            double              du = 0, scale = 0;
            for (unsigned int m = 0; m < dh.n_nodes(); ++m)
              for (unsigned int c = 0; c < 2; ++c)
                {
                  du = std::max(du, std::abs(r.u[VEMDoFHandler<2>::node_dof(m, c)] - g.value(dh.node_location(m), c)));
                  scale = std::max(scale, std::abs(g.value(dh.node_location(m), c)));
                }
            testing::check_small(du / scale, 1e-10, tag + "an exact rotation of the boundary gives u = (R - I)(x - c)");
            const StressRecovery<2> stresses(dh, materials, r.u);
            const double            s0 = 2 * (lambda + mu) * (std::cos(theta) - 1);
            double                  ds = 0;
            for (unsigned int c = 0; c < mesh.n_cells(); ++c)
              {
                const auto s = stresses.cell_stress(c);
                ds           = std::max({ds, std::abs(s[0][0] - s0), std::abs(s[1][1] - s0), std::abs(s[0][1])});
              }
            testing::check_small(ds / std::abs(s0), 1e-8,
                                 tag + "its stress is the uniform 2 (lambda + mu)(cos theta - 1) I (relative)");
            testing::check_small(std::abs(s0) / (E * theta), 2 * theta,
                                 tag + "which is O(theta^2): |sigma| / (E theta) below 2 theta");
          }
          // the linearized rotation u = theta perp(x - c): the lines of
          // add_torque_rotation() on all sides as one part, the master DoF
          // prescribed
          {
            dealii::AffineConstraints<double> cons;
            // the left side the torque part, the others prescribed by the
            // linearized field
            const auto part = BoundaryConditions::add_torque_rotation(dh, 0, centre, cons);
            cons.add_line(part.master_dof);
            cons.set_inhomogeneity(part.master_dof, theta * part.master_arm);
            const dealii::types::boundary_id others[] = {1, 2, 3};
            class Linear : public dealii::Function<2>
            {
            public:
              explicit Linear(const double theta)
                : dealii::Function<2>(2)
                , theta(theta)
              {}
              double
              value(const dealii::Point<2> &x, const unsigned int c = 0) const override
              {
                return c == 0 ? -theta * (x[1] - centre[1]) : theta * (x[0] - centre[0]);
              }
              double theta;
            } linear(theta);
            BoundaryConditions::interpolate_boundary_values(dh, {others[0], others[1], others[2]}, linear,
                                                            {{true, true}}, cons);
            const auto              r = solve(dh, cons, {});
            const StressRecovery<2> stresses(dh, materials, r.u);
            double                  smax = 0;
            for (unsigned int c = 0; c < mesh.n_cells(); ++c)
              smax = std::max(smax, stresses.cell_stress(c).norm());
            testing::check_small(smax / (E * theta), 1e-10,
                                 tag +
                                   "the linearized rotation theta perp(x - c) is stress free (|sigma| / (E theta))");
            testing::check_small(std::abs(part.angle(r.u) - theta) / theta, 1e-12,
                                 tag + "RotationAboutCentre::angle() reads theta back");
          }
        }
  }

  void
  errors()
  {
    PolygonalMesh<2> mesh;
    testing::make_mesh(mesh, "structured quads", 0);
    VEMDoFHandler<2> dh(mesh);
    dh.distribute_dofs(2);
    {
      dealii::AffineConstraints<double> cons;
      testing::check_throws([&] { BoundaryConditions::add_torque_rotation(dh, 13, centre, cons); },
                            "Rotation of boundary id 13 about (0.3, -0.2): no boundary edge of mesh",
                            "unknown boundary id");
      const dealii::Point<2> bad(std::numeric_limits<double>::quiet_NaN(), 0);
      testing::check_throws([&] { BoundaryConditions::add_prescribed_rotation(dh, 3, bad, 0.1, cons, "bore"); },
                            "Parameter 'bore': the centre of the rotation is not finite", "centre not finite");
      testing::check_throws(
        [&] {
          BoundaryConditions::add_prescribed_rotation(dh, 3, centre, std::numeric_limits<double>::infinity(), cons);
        },
        "the angle of the rotation is not finite", "angle not finite");
    }
    {
      // the top (id 3) meets the left side (id 0) at (0, 1)
      dealii::AffineConstraints<double>     cons;
      BoundaryConditions::ConstraintOrigins origins;
      BoundaryConditions::interpolate_boundary_values(dh, {0}, Zero2(), {{true, true}}, cons);
      for (const auto &line : cons.get_lines())
        origins[line.index] = "the clamped left side";
      testing::check_throws(
        [&] {
          BoundaryConditions::add_torque_rotation(dh, 3, dealii::Point<2>(0.5, 1), cons, "gear 1 bore", &origins);
        },
        "Parameter 'gear 1 bore' on mesh 'structured quads 4x4': component x of the node at (0 1) is already "
        "constrained by the clamped left side",
        "torque part on a constrained node: both conditions named");
      testing::check_throws(
        [&] {
          BoundaryConditions::add_prescribed_rotation(dh, 3, dealii::Point<2>(0.5, 1), 0.1, cons, "gear 1 bore",
                                                      &origins);
        },
        "is already constrained by the clamped left side to the value 0",
        "prescribed angle on a node held at another value: both conditions named");
      // a zero angle about a centre agrees with the clamped corner
      dealii::AffineConstraints<double> copy;
      copy.copy_from(cons);
      BoundaryConditions::add_prescribed_rotation(dh, 3, dealii::Point<2>(0.5, 1), 0., copy, "gear 1 bore", &origins);
      testing::check(true, "a zero angle agrees with the clamped corner");
      const auto geometry = BoundaryConditions::rotation_geometry(dh, 3, dealii::Point<2>(0.5, 1));
      testing::check_throws([&] { BoundaryConditions::rotation_torque_load(geometry, 1.); },
                            "is not a torque-driven rotation", "torque load on a part without the torque lines");
      // the master DoF: the largest arm, here x = 0 or 1 at y = 1: a y DoF
      testing::check(geometry.master_dof % 2 == 1 && std::abs(std::abs(geometry.master_arm) - 0.5) < 1e-14,
                     "the master DoF is a component of the largest arm (0.5)");
    }
  }
} // namespace

int
main()
{
  try
    {
      annulus_tests();
      whole_body_rotation();
      errors();
    }
  catch (const std::exception &e)
    {
      std::cout << "FAIL  exception: " << e.what() << std::endl;
      return 1;
    }
  return testing::finish();
}
