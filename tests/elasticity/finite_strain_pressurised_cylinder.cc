// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// A thick cylinder under internal pressure at finite strain, with the
// pressure as a dead load and as a follower load
// (FiniteStrainAssembler::add_pressure(), PressureLoad).
//
// The body: the quarter annulus a = 1 <= R <= b = 2 (deal.II's
// quarter_hyper_shell, 3 cells refined NREF times: polar quads with their
// vertices on the circles, straight edges), rollers on the symmetry lines
// x = 0 (u_x = 0) and y = 0 (u_y = 0), the outer circle free, the pressure
// p = 0.8 on the inner circle; compressible Neo-Hooke in plane strain,
// E = 10, nu = 0.3 (mu = E/(2(1+nu)), Lambda = E nu/((1+nu)(1-2nu))),
// psi = mu/2 (I1 - 3) - mu ln J + Lambda/2 (ln J)^2; k = 2; 4 load steps.
//
// The reference: the deformation is radial, r = r(R), with the principal
// stretches l_r = r'(R), l_t = r/R, l_z = 1, J = l_r l_t, and the principal
// nominal (first Piola-Kirchhoff) stresses
//   P_i = mu (l_i - 1/l_i) + Lambda ln(J) / l_i,   i = r, t.
// Equilibrium in the reference configuration, Div P = 0, is
//   dP_r/dR = (P_t - P_r) / R,
// and the Cauchy stress is sigma_rr = P_r l_r / J = P_r / l_t. The boundary
// conditions: P_r(b) = 0 (free outer surface) and at the inner surface
// (reference normal N = -E_R)
//   dead:     P_r(a) = -p            (the nominal traction -p N: force p per
//                                     unit reference length),
//   follower: sigma_rr(r(a)) = -p,   i.e. P_r(a) = -p r(a)/a (force p per
//                                     unit current length).
// The test solves this boundary value problem by shooting on r(a): from
// (r(a), P_r(a)), P_r = P_r(l_r, r/R) is solved for l_r (Newton, P_r
// increases with l_r), the system (r, P_r)' = (l_r, (P_t - P_r)/R) is
// integrated by RK4 with 4000 steps to R = b, and r(a) is bisected until
// P_r(b) = 0 (to 1e-14). The RK4 solution is converged to better than
// 1e-10 (halving the steps changes u(a) by less).
//
// Checked (measured with NREF = 3: 192 cells, 1666 DoFs, 2 s):
// - the VEM inner displacement (the mean of |X + u| - a over the inner
//   vertices) against the reference u(a) = r(a) - a, for both load kinds,
//   within 0.3 % (measured: 0.056 % dead, 0.056 % follower; the reference
//   values are u(a) = 0.159973 dead and 0.192474 follower);
// - the two load kinds differ by far more than that (the follower load is
//   larger by the stretch r(a)/a of the inner surface; measured: 20 %):
//   |u_f - u_d| > 20 times the tolerance, so the test fails if the
//   follower load is taken as dead;
// - the Cauchy output (compute_finite_strain_fields(), the function the VTU
//   writer uses), follower load: sigma_rr = e_r . sigma e_r of the cells of
//   the innermost layer against the reference sigma_rr averaged over the
//   same radial band (weighted by R dR, as the cell mean weighs by
//   reference area) within 1 % of p (measured 0.10 %); the quadratic
//   extrapolation to R = a of the mean sigma_rr of the three innermost
//   layers (taken at their mid radii) is -p, the boundary value of the
//   follower load, within 1 % of p (measured 0.65 %: the extrapolation of
//   cell means has an O(h^2) error of its own); the innermost cells' det_F
//   and principal stretches against the reference's l_r l_t and
//   (l_t, l_r, 1) at the band's mid radius within 1e-3 relative (measured
//   2e-5 and 1.1e-4);
// - Newton converges quadratically with either load: for successive
//   relative residuals e_i < 1e-2, e_{i+1} > 1e-12, e_{i+1}/e_i^2 < 100
//   (measured at most 0.07 dead, 0.14 follower; 3 or 4 updates per step);
// - the tangent with the follower pressure (a varying p = 0.8 + 0.3 x) on a
//   coarser mesh at a state of 10 % stretch plus a random part, load
//   factor 0.7: K d against the central difference
//   -(r(u + h d) - r(u - h d)) / (2h), h = 1e-6, for k = 1 and 2, relative
//   error below 1e-6 (measured 9e-11, 2.5e-10), and so for the follower
//   part alone (K and r with the pressure minus those without it; measured
//   1.4e-10, 3.7e-10); the follower load at u = 0 equals the dead one
//   (1e-14).
#include <deal.II/base/function.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/finite_strain_solver.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/postprocessing/finite_strain_output.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>

#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
  constexpr double a = 1., b = 2., pressure = 0.8, E = 10., nu = 0.3;
  constexpr unsigned int n_refinements = 3;

  // ---- the 1D radial reference
  struct Radial
  {
    double mu, Lambda;

    // P_i at the stretches (l_i, l_other)
    double
    nominal(const double l_i, const double l_other) const
    {
      return mu * (l_i - 1. / l_i) + Lambda * std::log(l_i * l_other) / l_i;
    }

    // l_r with P_r(l_r, l_t) = P
    double
    radial_stretch(const double P, const double l_t) const
    {
      double l = 1.;
      for (unsigned int it = 0; it < 100; ++it)
        {
          const double f  = nominal(l, l_t) - P;
          const double df = mu * (1. + 1. / (l * l)) + Lambda * (1. - std::log(l * l_t)) / (l * l);
          double       dl = -f / df;
          // (keep the stretch positive)
          while (l + dl <= 0.)
            dl *= 0.5;
          l += dl;
          if (std::abs(dl) < 1e-15 * l)
            break;
        }
      return l;
    }

    // (r, P_r)' at R
    std::array<double, 2>
    rhs(const double R, const std::array<double, 2> &y) const
    {
      const double l_t = y[0] / R, l_r = radial_stretch(y[1], l_t);
      return {{l_r, (nominal(l_t, l_r) - y[1]) / R}};
    }

    // integrate from a with r(a) = r0 and the inner boundary condition;
    // the samples (R, r, P_r) at the n + 1 nodes go to @p path if not null
    std::array<double, 2>
    shoot(const double r0, const bool follower, const unsigned int n,
          std::vector<std::array<double, 3>> *path = nullptr) const
    {
      std::array<double, 2> y = {{r0, follower ? -pressure * r0 / a : -pressure}};
      const double          h = (b - a) / n;
      if (path)
        path->assign(1, {{a, y[0], y[1]}});
      for (unsigned int i = 0; i < n; ++i)
        {
          const double R  = a + i * h;
          const auto   k1 = rhs(R, y);
          const auto   k2 = rhs(R + h / 2, {{y[0] + h / 2 * k1[0], y[1] + h / 2 * k1[1]}});
          const auto   k3 = rhs(R + h / 2, {{y[0] + h / 2 * k2[0], y[1] + h / 2 * k2[1]}});
          const auto   k4 = rhs(R + h, {{y[0] + h * k3[0], y[1] + h * k3[1]}});
          for (unsigned int c = 0; c < 2; ++c)
            y[c] += h / 6 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
          if (path)
            path->push_back({{R + h, y[0], y[1]}});
        }
      return y;
    }

    // r(a) with P_r(b) = 0, by bisection
    double
    inner_radius(const bool follower, const unsigned int n) const
    {
      double lo = a, hi = 1.5 * a; // P_r(b) < 0 at lo, > 0 at hi
      for (unsigned int it = 0; it < 100 && hi - lo > 1e-14; ++it)
        {
          const double mid = 0.5 * (lo + hi);
          (shoot(mid, follower, n)[1] < 0 ? lo : hi) = mid;
        }
      return 0.5 * (lo + hi);
    }
  };

  // the reference fields at R (linear interpolation of the RK4 samples,
  // with the stretches from the equations at the interpolated state)
  struct RadialSolution
  {
    const Radial                      &radial;
    std::vector<std::array<double, 3>> path;

    // (sigma_rr, l_r, l_t) at R
    std::array<double, 3>
    at(const double R) const
    {
      const double h = (b - a) / (path.size() - 1);
      const auto   i = std::min<std::size_t>(std::size_t((R - a) / h), path.size() - 2);
      const double s = (R - path[i][0]) / h;
      const double r = (1 - s) * path[i][1] + s * path[i + 1][1], P = (1 - s) * path[i][2] + s * path[i + 1][2];
      const double l_t = r / R, l_r = radial.radial_stretch(P, l_t);
      return {{P / l_t, l_r, l_t}};
    }

    // the mean of sigma_rr over R0 <= R <= R1 weighted by R dR
    double
    band_mean_sigma_rr(const double R0, const double R1) const
    {
      const unsigned int n   = 400;
      double             num = 0, den = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double R = R0 + (i + 0.5) * (R1 - R0) / n;
          num += at(R)[0] * R;
          den += R;
        }
      return num / den;
    }
  };

  class ConstantPressure : public dealii::Function<2>
  {
  public:
    ConstantPressure(const double p)
      : dealii::Function<2>(1)
      , p(p)
    {}
    double
    value(const dealii::Point<2> &, const unsigned int = 0) const override
    {
      return p;
    }
    double p;
  };

  class LinearPressure : public dealii::Function<2>
  {
  public:
    LinearPressure()
      : dealii::Function<2>(1)
    {}
    double
    value(const dealii::Point<2> &x, const unsigned int = 0) const override
    {
      return 0.8 + 0.3 * x[0];
    }
  };

  // the quarter annulus; boundary ids 0 inner, 1 outer, 2 on x = 0, 3 on y = 0
  void
  make_annulus(PolygonalMesh<2> &mesh, const unsigned int n_refinements)
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::quarter_hyper_shell(tria, dealii::Point<2>(), a, b, 3);
    tria.refine_global(n_refinements);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const auto   c = cell->face(f)->center();
            const double R = c.norm();
            cell->face(f)->set_boundary_id(std::abs(c[0]) < 1e-10 ? 2 :
                                           std::abs(c[1]) < 1e-10 ? 3 :
                                           R < 0.5 * (a + b)      ? 0 :
                                                                    1);
          }
    PolygonalMeshGenerators::from_triangulation(mesh, tria);
  }

  // the mean radial displacement of the vertices on the inner circle
  double
  inner_displacement(const VEMDoFHandler<2> &dof_handler, const dealii::Vector<double> &u)
  {
    const auto  &mesh = dof_handler.get_mesh();
    double       sum  = 0;
    unsigned int n    = 0;
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      if (std::abs(mesh.vertex(v).norm() - a) < 1e-10)
        {
          const unsigned int node = dof_handler.vertex_node(v);
          dealii::Point<2>   x    = mesh.vertex(v);
          for (unsigned int d = 0; d < 2; ++d)
            x[d] += u[VEMDoFHandler<2>::node_dof(node, d)];
          sum += x.norm() - a;
          ++n;
        }
    return sum / n;
  }
} // namespace

int
main()
{
  const NeoHookeMaterial law(E, nu);
  const Radial           radial{law.mu(), law.lambda()};

  // ---- the reference: converged in the number of RK4 steps
  double u_ref[2];
  for (const bool follower : {false, true})
    {
      const double r_fine = radial.inner_radius(follower, 4000), r_coarse = radial.inner_radius(follower, 2000);
      u_ref[follower] = r_fine - a;
      std::cout << "reference u(a), " << (follower ? "follower" : "dead") << " pressure: " << std::setprecision(12)
                << u_ref[follower] << std::endl;
      testing::check_small(std::abs(r_fine - r_coarse) / u_ref[follower], 1e-9,
                           std::string(follower ? "follower" : "dead") + ": the 1D reference is converged in the RK4 steps");
    }
  std::vector<std::array<double, 3>> path;
  radial.shoot(u_ref[1] + a, true, 4000, &path);
  const RadialSolution reference{radial, path};
  testing::check_small(std::abs(path.back()[2]), 1e-10, "follower: the reference has P_r(b) = 0");
  testing::check_small(std::abs(reference.at(a)[0] + pressure) / pressure, 1e-12,
                       "follower: the reference has sigma_rr(a) = -p");

  // ---- the VEM solution for both load kinds
  PolygonalMesh<2> mesh;
  make_annulus(mesh, n_refinements);
  VEMDoFHandler<2> dof_handler(mesh);
  dof_handler.distribute_dofs(2);
  std::cout << mesh.n_cells() << " cells, " << dof_handler.n_dofs() << " DoFs" << std::endl;
  dealii::AffineConstraints<double> constraints;
  BoundaryConditions::add_roller(dof_handler, 2, constraints);
  BoundaryConditions::add_roller(dof_handler, 3, constraints);
  constraints.close();
  const MaterialLibrary<2> laws = testing::one_law_library(dof_handler, law);
  const ConstantPressure   p(pressure);
  const double             tolerance = 3e-3;
  double                   u_vem[2];
  for (const bool follower : {false, true})
    {
      const std::string        name = follower ? "follower" : "dead";
      FiniteStrainAssembler<2> assembler(dof_handler, laws);
      assembler.add_pressure(0, p, follower ? PressureLoad::follower : PressureLoad::dead);
      FiniteStrainSolver<2>::Parameters parameters;
      parameters.n_load_steps = 4;
      FiniteStrainSolver<2> solver(assembler, constraints, parameters);
      solver.run();
      solver.print_history(std::cout);
      testing::check(solver.get_history().size() == 4 && solver.get_history().back().converged,
                     name + ": all load steps converged");
      double       worst_ratio = 0;
      unsigned int n_pairs     = 0;
      for (const auto &step : solver.get_history())
        for (unsigned int i = 0; i + 1 < step.iterations.size(); ++i)
          {
            const double e0 = step.iterations[i].relative_residual, e1 = step.iterations[i + 1].relative_residual;
            if (e1 > 1e-12 && e0 < 1e-2)
              {
                worst_ratio = std::max(worst_ratio, e1 / (e0 * e0));
                ++n_pairs;
              }
          }
      testing::check(n_pairs > 0 && worst_ratio < 100,
                     name + ": quadratic convergence, max e_{i+1}/e_i^2 = " + std::to_string(worst_ratio) + " over " +
                       std::to_string(n_pairs) + " pairs");
      u_vem[follower] = inner_displacement(dof_handler, solver.get_solution());
      testing::check_small(std::abs(u_vem[follower] - u_ref[follower]) / u_ref[follower], tolerance,
                           name + ": inner displacement " + std::to_string(u_vem[follower]) +
                             " against the radial solution, relative error");

      if (follower)
        {
          // the Cauchy output of the innermost layers against the reference
          const FiniteStrainFields fields = compute_finite_strain_fields(dof_handler, laws, solver.get_solution());
          const double             h      = (b - a) / (1u << n_refinements);
          double                   err_sigma = 0, err_J = 0, err_l = 0, layer_mean[3] = {0, 0, 0};
          unsigned int             layer_count[3] = {0, 0, 0};
          for (unsigned int c = 0; c < mesh.n_cells(); ++c)
            {
              const auto  &vertices = mesh.cell_vertices(c);
              double       R_min = 1e300, R_max = 0;
              dealii::Point<2> centre;
              for (const auto &v : vertices)
                {
                  R_min = std::min(R_min, v.norm());
                  R_max = std::max(R_max, v.norm());
                  centre += v / double(vertices.size());
                }
              const unsigned int layer = std::lround((R_min - a) / h);
              if (layer > 2)
                continue;
              const dealii::Tensor<1, 2> e_r = centre / centre.norm();
              const auto                &s   = fields.cells[c].cauchy_stress;
              const double sigma_rr = s[0] * e_r[0] * e_r[0] + s[1] * e_r[1] * e_r[1] + 2 * s[2] * e_r[0] * e_r[1];
              layer_mean[layer] += sigma_rr;
              ++layer_count[layer];
              if (layer == 0)
                {
                  err_sigma = std::max(err_sigma, std::abs(sigma_rr - reference.band_mean_sigma_rr(R_min, R_max)));
                  const auto mid = reference.at(0.5 * (R_min + R_max));
                  err_J          = std::max(err_J, std::abs(fields.cells[c].det_F / (mid[1] * mid[2]) - 1));
                  // l_t > l_r at the inner surface
                  err_l = std::max({err_l, std::abs(fields.cells[c].principal_stretches[0] / mid[2] - 1),
                                    std::abs(fields.cells[c].principal_stretches[1] / mid[1] - 1),
                                    std::abs(fields.cells[c].principal_stretches[2] - 1)});
                }
            }
          testing::check_small(err_sigma / pressure, 1e-2,
                               "follower: innermost cells' Cauchy sigma_rr against the reference band mean, / p");
          // the quadratic through the layer means at the layers' mid radii
          // a + (j + 1/2) h, at R = a
          const double m0 = layer_mean[0] / layer_count[0], m1 = layer_mean[1] / layer_count[1],
                       m2   = layer_mean[2] / layer_count[2];
          const double at_a = 1.875 * m0 - 1.25 * m1 + 0.375 * m2;
          testing::check_small(std::abs(at_a + pressure) / pressure, 1e-2,
                               "follower: sigma_rr extrapolated to the inner surface = " + std::to_string(at_a) +
                                 ", against -p, / p");
          testing::check_small(err_J, 1e-3, "follower: innermost cells' det_F against l_r l_t, relative");
          testing::check_small(err_l, 1e-3,
                               "follower: innermost cells' principal stretches against (l_t, l_r, 1), relative");
        }
    }
  testing::check(std::abs(u_vem[1] - u_vem[0]) > 20 * tolerance * u_ref[0],
                 "the follower and dead loads differ: u(a) = " + std::to_string(u_vem[1]) + " and " +
                   std::to_string(u_vem[0]) + " (relative difference " +
                   std::to_string((u_vem[1] - u_vem[0]) / u_vem[0]) + ")");

  // ---- the tangent with the follower pressure, by central differences
  {
    PolygonalMesh<2> coarse;
    make_annulus(coarse, 1);
    const LinearPressure varying;
    for (const unsigned int k : {1u, 2u})
      {
        const std::string name = "k = " + std::to_string(k);
        VEMDoFHandler<2>  dofs(coarse);
        dofs.distribute_dofs(k);
        const MaterialLibrary<2> coarse_laws = testing::one_law_library(dofs, law);
        // the load vector at u = 0 is that of the dead pressure
        {
          FiniteStrainAssembler<2> dead(dofs, coarse_laws), follower(dofs, coarse_laws);
          dead.add_pressure(0, varying, PressureLoad::dead);
          follower.add_pressure(0, varying, PressureLoad::follower);
          dealii::Vector<double> f_dead, f_follower;
          dead.assemble_load_vector(f_dead);
          follower.assemble_load_vector(f_follower);
          f_follower -= f_dead;
          testing::check_small(f_follower.linfty_norm() / f_dead.linfty_norm(), 1e-14,
                               name + ": follower load at u = 0 equals the dead load");
        }
        FiniteStrainAssembler<2> assembler(dofs, coarse_laws);
        assembler.add_pressure(0, varying, PressureLoad::follower);
        dealii::AffineConstraints<double> none;
        none.close();
        dealii::DynamicSparsityPattern dsp(dofs.n_dofs());
        dofs.make_sparsity_pattern(dsp, none);
        dealii::SparsityPattern sparsity;
        sparsity.copy_from(dsp);
        dealii::SparseMatrix<double> K(sparsity);
        // a smooth state of about 10 % strain plus a random part
        std::mt19937                           rng(7);
        std::uniform_real_distribution<double> unit(-1., 1.);
        dealii::Vector<double>                 u(dofs.n_dofs()), d(dofs.n_dofs());
        for (unsigned int i = 0; i < u.size(); ++i)
          {
            u[i] = 0.01 * unit(rng);
            d[i] = unit(rng);
          }
        for (unsigned int v = 0; v < coarse.n_vertices(); ++v)
          for (unsigned int c = 0; c < 2; ++c)
            u[VEMDoFHandler<2>::node_dof(dofs.vertex_node(v), c)] += 0.1 * coarse.vertex(v)[c];
        assembler.freeze_stabilization(u);
        dealii::Vector<double> r, rhs, r_plus, r_minus, Kd(dofs.n_dofs());
        const double           load_factor = 0.7;
        assembler.assemble(u, load_factor, r, none, &K, &rhs);
        K.vmult(Kd, d);
        const double           eps = 1e-6;
        dealii::Vector<double> w   = u;
        w.add(eps, d);
        assembler.assemble(w, load_factor, r_plus, none, nullptr, nullptr);
        w = u;
        w.add(-eps, d);
        assembler.assemble(w, load_factor, r_minus, none, nullptr, nullptr);
        // K = -dr/du
        dealii::Vector<double> fd = r_minus;
        fd -= r_plus;
        fd /= 2 * eps;
        fd -= Kd;
        testing::check_small(fd.l2_norm() / Kd.l2_norm(), 1e-6,
                             name + ": tangent with the follower pressure against central differences, relative");
        // the follower part alone: the residual and tangent with the
        // pressure minus those without it
        FiniteStrainAssembler<2> plain(dofs, coarse_laws);
        plain.freeze_stabilization(u);
        dealii::SparseMatrix<double> K0(sparsity);
        dealii::Vector<double>       r0, rhs0, K0d(dofs.n_dofs()), Kfd(dofs.n_dofs()), r0_plus, r0_minus;
        plain.assemble(u, load_factor, r0, none, &K0, &rhs0);
        K0.vmult(K0d, d);
        K.vmult(Kfd, d);
        Kfd -= K0d;
        w = u;
        w.add(eps, d);
        plain.assemble(w, load_factor, r0_plus, none, nullptr, nullptr);
        w = u;
        w.add(-eps, d);
        plain.assemble(w, load_factor, r0_minus, none, nullptr, nullptr);
        dealii::Vector<double> fd_follower = r_minus;
        fd_follower -= r_plus;
        fd_follower -= r0_minus;
        fd_follower += r0_plus;
        fd_follower /= 2 * eps;
        std::cout << name << ": |K_follower d| / |K_material d| = " << Kfd.l2_norm() / K0d.l2_norm() << std::endl;
        fd_follower -= Kfd;
        testing::check(Kfd.l2_norm() > 0, name + ": the follower tangent is not zero");
        testing::check_small(fd_follower.l2_norm() / Kfd.l2_norm(), 1e-6,
                             name + ": the follower part of the tangent against central differences, relative");
      }
  }
  return testing::finish();
}
