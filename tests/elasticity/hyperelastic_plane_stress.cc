// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The hyperelastic laws in plane stress (E = 7000): the out-of-plane
// stretch f solves P_zz(F, f) = 0 per point, P is the in-plane block of the
// 3D stress at diag(F, f), A the tangent condensed by the implicit function
// theorem.
// - P against central differences of psi (h = 1e-6), A against central
//   differences of P, both <= 1e-8 E, at 12 random F near I (entries of
//   F - I uniform in [-0.1, 0.1]) and 6 large-strain states (for Saint
//   Venant-Kirchhoff, states inside its range lambda tr(E_2D) < lambda/2 + mu,
//   which the test checks); nu = 0.3 and 0.45 for both laws, nu = -0.2 for
//   Neo-Hooke (the branch f > f_* of a law with lambda < 0); measured
//   1.4e-10 E and 3.3e-9 E (round-off, ~1/h: at nu = 0.45 the error of f,
//   a few eps, enters P through dP/df ~ lambda ~ 3 E and is divided by 2h;
//   the truncation error is ~1e-11 E at this h);
// - P_zz at the solved f, from the 3D formulas written out here, <= 1e-12 E
//   (measured 8e-15 E); psi = the 3D energy at that f (1e-14 E); Saint
//   Venant-Kirchhoff's f against its closed form
//   sqrt(1 - lambda tr(E_2D) / (lambda/2 + mu)), 1e-13 (measured 1.1e-15);
// - uniaxial stress: F = diag(l1, l2) with P_22 = 0 solved here by Newton;
//   isotropy makes l2 = f, and the 3D uniaxial state is known: Neo-Hooke,
//   t = l2 = f solves mu (t^2 - 1) + lambda ln(l1 t^2) = 0 (bisection
//   here), P_11 = mu l1 + (lambda ln(l1 t^2) - mu) / l1; Saint
//   Venant-Kirchhoff, t^2 = 1 - nu (l1^2 - 1), P_11 = E l1 (l1^2 - 1) / 2;
//   stretches to 1e-12, stresses to 1e-12 E (measured 3.6e-15, 1.4e-15 E);
// - at F = I: f = 1, P = 0, and A equals the plane-stress linear C
//   (ElasticMaterial in plane stress, lambda -> E nu / (1 - nu^2)) to
//   1e-12 E (measured 1.3e-16 E); the small-strain functions are
//   ElasticMaterial's in plane stress (sigma_zz = 0);
// - the finite-strain patch test in plane stress: u = (F - I) X + c,
//   F = [[1.1, 0.3], [0.05, 0.7]], Dirichlet data on the whole boundary,
//   4 load steps, Voronoi mesh, k = 1, 2, both laws: every DoF exact to
//   1e-10 of max |u| (measured 2.1e-15);
// - no plane-stress state: Saint Venant-Kirchhoff at an equibiaxial stretch
//   1.6 (nu = 0.3: lambda tr(E_2D) = 1.56 lambda > lambda/2 + mu = 1.17 lambda)
//   and Neo-Hooke with nu = -0.2 at an equibiaxial compression 0.3 throw
//   ExcNoPlaneStressState naming the law and F (psi, P, A, f, sigma).
#include <deal.II/base/tensor.h>

#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/material.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <random>
#include <vector>

#include "../elasticity_common.h"
#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;
using T2 = dealii::Tensor<2, 2>;

namespace
{
  T2
  tensor(const double a, const double b, const double c, const double d)
  {
    T2 F;
    F[0][0] = a;
    F[0][1] = b;
    F[1][0] = c;
    F[1][1] = d;
    return F;
  }

  T2
  rotation(const double angle)
  {
    return tensor(std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle));
  }

  double
  max_abs(const T2 &A)
  {
    double m = 0;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        m = std::max(m, std::abs(A[i][j]));
    return m;
  }

  // tr of the in-plane Green-Lagrange strain, (F:F - 2) / 2
  double
  trace_E2(const T2 &F)
  {
    return 0.5 * (dealii::scalar_product(F, F) - 2.);
  }

  bool
  is_neo_hooke(const HyperelasticMaterial &law)
  {
    return dynamic_cast<const NeoHookeMaterial *>(&law) != nullptr;
  }

  // the 3D laws at diag(F, f), written out independently of the library
  double
  P_zz_3d(const HyperelasticMaterial &law, const T2 &F, const double f)
  {
    const double l = law.lambda(), m = law.mu();
    if (is_neo_hooke(law))
      return m * f + (l * std::log(f * dealii::determinant(F)) - m) / f;
    const double E_zz = 0.5 * (f * f - 1.);
    return f * (l * (trace_E2(F) + E_zz) + 2. * m * E_zz);
  }

  double
  psi_3d(const HyperelasticMaterial &law, const T2 &F, const double f)
  {
    const double l = law.lambda(), m = law.mu();
    if (is_neo_hooke(law))
      {
        const double lnJ = std::log(f * dealii::determinant(F));
        return 0.5 * m * (dealii::scalar_product(F, F) + f * f - 3.) - m * lnJ + 0.5 * l * lnJ * lnJ;
      }
    T2 E2 = 0.5 * (dealii::transpose(F) * F);
    E2[0][0] -= 0.5;
    E2[1][1] -= 0.5;
    const double E_zz = 0.5 * (f * f - 1.);
    const double tr   = dealii::trace(E2) + E_zz;
    return 0.5 * l * tr * tr + m * (dealii::scalar_product(E2, E2) + E_zz * E_zz);
  }
} // namespace

int
main()
{
  const double                 E  = 7000.;
  const ElasticMaterial::Model PS = ElasticMaterial::Model::plane_stress;

  std::vector<T2> near_identity;
  {
    std::mt19937                           rng(20261125);
    std::uniform_real_distribution<double> u(-0.1, 0.1);
    for (unsigned int s = 0; s < 12; ++s)
      near_identity.push_back(tensor(1 + u(rng), u(rng), u(rng), 1 + u(rng)));
  }
  const std::vector<T2> large_neo_hooke = {tensor(1.3, 0, 0, 0.9),
                                           tensor(1, 0, 0, 0.7),
                                           tensor(1, 0.5, 0, 1),
                                           tensor(1.1, 0.3, -0.2, 0.8),
                                           rotation(70. * M_PI / 180.) * tensor(1.2, 0.1, 0.1, 0.75),
                                           tensor(2.0, 0.4, 0.1, 0.6)};
  // Saint Venant-Kirchhoff: states with lambda tr(E_2D) < lambda/2 + mu for
  // nu = 0.45 (tr(E_2D) < 0.611) and hence for nu = 0.3 (< 1.167)
  const std::vector<T2> large_svk = {tensor(1.3, 0, 0, 0.9),
                                     tensor(1, 0, 0, 0.7),
                                     tensor(1, 0.5, 0, 1),
                                     tensor(1.1, 0.3, -0.2, 0.8),
                                     rotation(70. * M_PI / 180.) * tensor(1.2, 0.1, 0.1, 0.75),
                                     tensor(0.6, 0.2, -0.1, 0.5)};

  std::vector<std::unique_ptr<HyperelasticMaterial>> laws;
  for (const double nu : {0.3, 0.45, -0.2})
    laws.push_back(std::make_unique<NeoHookeMaterial>(E, nu, PS));
  for (const double nu : {0.3, 0.45})
    laws.push_back(std::make_unique<SaintVenantKirchhoffMaterial>(E, nu, PS));

  for (const auto &law : laws)
    {
      const bool   neo = is_neo_hooke(*law);
      const double nu  = law->poissons_ratio();
      const double l = law->lambda(), m = law->mu();
      std::cout << "--- " << law->get_name() << std::endl;
      testing::check(law->get_name().find("plane stress") != std::string::npos &&
                       law->model() == PS && law->linearization().model() == PS,
                     "the name, the model and the linearization say plane stress");

      std::vector<T2> states = near_identity;
      for (const T2 &F : (neo ? large_neo_hooke : large_svk))
        states.push_back(F);
      if (!neo)
        {
          double worst = -1e300;
          for (const T2 &F : states)
            worst = std::max(worst, l * trace_E2(F) / (0.5 * l + m));
          testing::check(worst < 1, "all states inside the range of Saint Venant-Kirchhoff in plane stress "
                                    "(max lambda tr(E_2D) / (lambda/2 + mu) = " +
                                      std::to_string(worst) + " < 1)");
        }

      double err_P = 0, err_A = 0, err_zz = 0, err_psi = 0, err_closed = 0, err_sym = 0, f_min = 1e300,
             f_max = 0, dPzz_df_min = 1e300;
      const double h = 1e-6;
      for (const T2 &F : states)
        {
          const T2                   P = law->first_piola_kirchhoff_stress(F);
          const dealii::Tensor<4, 2> A = law->first_piola_kirchhoff_tangent(F);
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int L = 0; L < 2; ++L)
              {
                T2 Fp = F, Fm = F;
                Fp[k][L] += h;
                Fm[k][L] -= h;
                const double dpsi = (law->strain_energy(Fp) - law->strain_energy(Fm)) / (2 * h);
                err_P             = std::max(err_P, std::abs(P[k][L] - dpsi));
                const T2 dP =
                  (law->first_piola_kirchhoff_stress(Fp) - law->first_piola_kirchhoff_stress(Fm)) / (2 * h);
                for (unsigned int i = 0; i < 2; ++i)
                  for (unsigned int J = 0; J < 2; ++J)
                    err_A = std::max(err_A, std::abs(A[i][J][k][L] - dP[i][J]));
              }
          const double f = law->out_of_plane_stretch(F);
          f_min          = std::min(f_min, f);
          f_max          = std::max(f_max, f);
          err_zz         = std::max(err_zz, std::abs(P_zz_3d(*law, F, f)));
          err_psi        = std::max(err_psi, std::abs(law->strain_energy(F) - psi_3d(*law, F, f)));
          // the branch taken is a minimum of psi_3 in f: dP_zz/df > 0
          const double df = 1e-6 * f;
          dPzz_df_min     = std::min(dPzz_df_min, (P_zz_3d(*law, F, f + df) - P_zz_3d(*law, F, f - df)) / (2 * df));
          if (!neo)
            err_closed = std::max(err_closed, std::abs(f - std::sqrt(1. - l * trace_E2(F) / (0.5 * l + m))));
          const T2 sigma = law->cauchy_stress(F);
          err_sym        = std::max(err_sym, max_abs(sigma - dealii::transpose(sigma)));
        }
      std::cout << "    out-of-plane stretch f in [" << f_min << ", " << f_max << "] over " << states.size()
                << " states" << std::endl;
      testing::check_small(err_P / E, 1e-8, "P against differences of psi, / E");
      testing::check_small(err_A / E, 1e-8, "dP/dF (condensed) against differences of P, / E");
      testing::check_small(err_zz / E, 1e-12, "P_zz(F, f) at the solved f (3D formula), / E");
      testing::check_small(err_psi / E, 1e-14, "psi = the 3D energy at the solved f, / E");
      testing::check_small(err_sym / E, 1e-12, "symmetry of the Cauchy stress, / E");
      testing::check(dPzz_df_min > 0, "dP_zz/df > 0 at every solved f (min " + std::to_string(dPzz_df_min / E) +
                                        " E): the stable branch");
      if (!neo)
        testing::check_small(err_closed, 1e-13, "f against sqrt(1 - lambda tr(E_2D) / (lambda/2 + mu))");

      // uniaxial stress: F = diag(l1, l2), P_22 = 0 solved by Newton on l2
      double err_stretch = 0, err_P11 = 0, err_side = 0;
      for (const double l1 : {0.7, 1.5, neo ? 2.5 : 1.2})
        {
          double l2 = 1. / std::sqrt(l1); // the incompressible guess
          for (unsigned int it = 0; it < 50; ++it)
            {
              const T2     F    = tensor(l1, 0, 0, l2);
              const double P22  = law->first_piola_kirchhoff_stress(F)[1][1];
              const double dP22 = law->first_piola_kirchhoff_tangent(F)[1][1][1][1];
              const double step = P22 / dP22;
              l2 -= step;
              if (std::abs(step) <= 1e-15 * l2)
                break;
            }
          const T2     F = tensor(l1, 0, 0, l2);
          const T2     P = law->first_piola_kirchhoff_stress(F);
          const double f = law->out_of_plane_stretch(F);
          double       t = 0, P11 = 0;
          if (neo)
            {
              // mu (t^2 - 1) + lambda ln(l1 t^2) = 0, increasing in t on the
              // branch t > sqrt(max(0, -lambda / mu))
              double lo = std::sqrt(std::max(0., -l / m)), hi = 10.;
              for (unsigned int it = 0; it < 200; ++it)
                {
                  const double mid = 0.5 * (lo + hi);
                  (m * (mid * mid - 1.) + l * std::log(l1 * mid * mid) < 0 ? lo : hi) = mid;
                }
              t   = 0.5 * (lo + hi);
              P11 = m * l1 + (l * std::log(l1 * t * t) - m) / l1;
            }
          else
            {
              t   = std::sqrt(1. - nu * (l1 * l1 - 1.));
              P11 = E * l1 * (l1 * l1 - 1.) / 2.;
            }
          std::cout << "    uniaxial stress l1 = " << l1 << ": l2 = " << std::setprecision(15) << l2
                    << ", f = " << f << ", exact " << t << std::setprecision(6) << std::endl;
          err_stretch = std::max({err_stretch, std::abs(l2 - t), std::abs(f - t), std::abs(l2 - f)});
          err_P11     = std::max(err_P11, std::abs(P[0][0] - P11));
          err_side    = std::max({err_side, std::abs(P[1][1]), std::abs(P[0][1]), std::abs(P[1][0])});
        }
      testing::check_small(err_stretch, 1e-12, "uniaxial stress: l2 = f = the 3D transverse stretch");
      testing::check_small(err_P11 / E, 1e-12, "uniaxial stress: P_11 = the 3D uniaxial value, / E");
      testing::check_small(err_side / E, 1e-12, "uniaxial stress: P_22 = P_12 = P_21 = 0, / E");

      // the linearization at F = I
      const T2                            I     = tensor(1, 0, 0, 1);
      const ElasticMaterial               plane_stress_linear(E, nu, PS);
      const dealii::Tensor<4, 2>          A0    = law->first_piola_kirchhoff_tangent(I);
      const dealii::SymmetricTensor<4, 2> C_lin = plane_stress_linear.tangent(dealii::SymmetricTensor<2, 2>());
      const dealii::SymmetricTensor<4, 2> C_law = law->tangent(dealii::SymmetricTensor<2, 2>());
      const double                        ls    = E * nu / (1. - nu * nu);
      double                              err_C = 0;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int J = 0; J < 2; ++J)
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int L = 0; L < 2; ++L)
              {
                const double expected = ls * (i == J) * (k == L) + m * ((i == k) * (J == L) + (i == L) * (J == k));
                err_C                 = std::max({err_C,
                                                  std::abs(A0[i][J][k][L] - expected),
                                                  std::abs(A0[i][J][k][L] - C_lin[i][J][k][L]),
                                                  std::abs(C_law[i][J][k][L] - C_lin[i][J][k][L])});
              }
      testing::check_small(err_C / E, 1e-12, "dP/dF at F = I equals the plane-stress linear C, / E");
      testing::check_near(law->out_of_plane_stretch(I), 1., 1e-15, "f(I) = 1");
      testing::check_small(max_abs(law->first_piola_kirchhoff_stress(I)) / E, 1e-14, "P(I) = 0, / E");
      dealii::SymmetricTensor<2, 2> eps;
      eps[0][0] = 1e-3;
      eps[1][1] = -2e-3;
      eps[0][1] = 0.7e-3;
      testing::check_small((law->stress(eps) - plane_stress_linear.stress(eps)).norm() / E, 1e-15,
                           "small-strain stress equals ElasticMaterial's in plane stress, / E");
      testing::check(law->stress_zz(eps) == 0. && plane_stress_linear.stress_zz(eps) == 0.,
                     "small-strain sigma_zz = 0 in plane stress");
    }

  // the finite-strain patch test in plane stress
  {
    T2 F = tensor(1.1, 0.3, 0.05, 0.7);
    dealii::Tensor<1, 2> c;
    c[0] = 0.02;
    c[1] = -0.01;
    const testing::HomogeneousDeformation exact(F, c);
    const NeoHookeMaterial                neo_hooke(E, 0.3, PS);
    const SaintVenantKirchhoffMaterial    svk(E, 0.3, PS);
    PolygonalMesh<2>                      mesh;
    testing::make_mesh(mesh, "voronoi", 0);
    for (const unsigned int k : {1u, 2u})
      {
        VEMDoFHandler<2> dof_handler(mesh);
        dof_handler.distribute_dofs(k);
        std::vector<dealii::Point<2>> support;
        dof_handler.map_dofs_to_support_points(support);
        double u_max = 0;
        for (const auto &p : support)
          u_max = std::max(u_max, std::hypot(exact.value(p, 0), exact.value(p, 1)));
        for (const HyperelasticMaterial *law :
             {static_cast<const HyperelasticMaterial *>(&neo_hooke), static_cast<const HyperelasticMaterial *>(&svk)})
          {
            FiniteStrainAssembler<2>          assembler(dof_handler, testing::one_law_library(dof_handler, *law));
            dealii::AffineConstraints<double> constraints;
            testing::dirichlet_constraints(dof_handler, {0, 1, 2, 3}, exact, constraints);
            FiniteStrainSolver<2>::Parameters parameters;
            parameters.n_load_steps = 4;
            FiniteStrainSolver<2> solver(assembler, constraints, parameters);
            solver.run();
            bool converged = solver.get_history().size() == parameters.n_load_steps;
            for (const auto &s : solver.get_history())
              converged = converged && s.converged;
            const dealii::Vector<double> &u   = solver.get_solution();
            double                        err = 0;
            for (unsigned int i = 0; i < u.size(); ++i)
              err = std::max(err, std::abs(u[i] - exact.value(support[i], i % 2)));
            const std::string what = "patch test, voronoi, k = " + std::to_string(k) + ", " +
                                     law->get_name().substr(0, law->get_name().find(" (")) + " (f = " +
                                     std::to_string(law->out_of_plane_stretch(F)) + "): ";
            testing::check(converged, what + "all load steps converged");
            testing::check_small(err / u_max, 1e-10, what + "max DoF error / max |u|");
          }
      }
  }

  // no plane-stress state: a clear exception, not NaN
  {
    const SaintVenantKirchhoffMaterial svk(E, 0.3, PS);
    const T2                           F = tensor(1.6, 0, 0, 1.6);
    const std::string fragment = "the law 'Saint Venant-Kirchhoff (E = 7000, nu = 0.3, plane stress)' has no "
                                 "plane-stress state at the in-plane deformation gradient F = [[1.6, 0], [0, 1.6]]";
    testing::check_throws([&]() { svk.first_piola_kirchhoff_stress(F); }, fragment,
                          "Saint Venant-Kirchhoff, equibiaxial stretch 1.6: P throws naming the law and F");
    testing::check_throws([&]() { svk.first_piola_kirchhoff_tangent(F); }, "the in-plane stretch is too large",
                          "  dP/dF throws with the reason");
    testing::check_throws([&]() { svk.strain_energy(F); }, fragment, "  psi throws");
    testing::check_throws([&]() { svk.out_of_plane_stretch(F); }, fragment, "  f throws");
    testing::check_throws([&]() { svk.cauchy_stress(F); }, fragment, "  sigma throws");
    // just inside the range (tr(E_2D) = 1.1 < 7/6): a finite f
    const double f_in = svk.out_of_plane_stretch(tensor(std::sqrt(2.1), 0, 0, std::sqrt(2.1)));
    testing::check_near(f_in, std::sqrt(1. - 1.1 / (0.5 + 1. / 1.5)), 1e-13,
                        "Saint Venant-Kirchhoff at tr(E_2D) = 1.1 (inside): f = sqrt(1 - 1.1 / (7/6))");

    const NeoHookeMaterial auxetic(E, -0.2, PS);
    testing::check_throws([&]() { auxetic.first_piola_kirchhoff_stress(tensor(0.3, 0, 0, 0.3)); },
                          "the law 'Neo-Hooke (E = 7000, nu = -0.2, plane stress)' has no plane-stress state at "
                          "the in-plane deformation gradient F = [[0.3, 0], [0, 0.3]]",
                          "Neo-Hooke, nu = -0.2, equibiaxial compression 0.3: P throws naming the law and F");
    const double f_half = auxetic.out_of_plane_stretch(tensor(0.5, 0, 0, 0.5));
    testing::check(f_half > std::sqrt(-auxetic.lambda() / (2. * auxetic.mu())),
                   "  at compression 0.5 a plane-stress state exists on the branch f > f_* (f = " +
                     std::to_string(f_half) + ")");
    testing::check_small(P_zz_3d(auxetic, tensor(0.5, 0, 0, 0.5), f_half) / E, 1e-12, "  with P_zz = 0, / E");
  }
  return testing::finish();
}
