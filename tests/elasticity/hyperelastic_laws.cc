// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The hyperelastic laws NeoHookeMaterial and SaintVenantKirchhoffMaterial
// (plane strain, E = 7000, nu = 0.3 and 0.45) at six deformation gradients
// (identity, stretch, compression by 30 %, simple shear, a general
// non-symmetric F, and a rotation by 70 degrees times a stretch):
// - P against central differences of psi (h = 1e-6): |P - P_fd| <= 1e-8 E
//   (truncation h^2 |psi'''| ~ 1e-12 E, round-off |psi| eps / h ~ 1e-10 E;
//   measured 4e-11 E);
// - A = dP/dF against central differences of P: |A - A_fd| <= 1e-8 E
//   (measured 2e-10 E);
// - objectivity: psi(QF) = psi(F), P(QF) = Q P(F) for a rotation Q, 1e-12 E;
//   the Cauchy stress is symmetric, 1e-12 E;
// - at F = I: P = 0, and A equals the linear law's tangent
//   lambda d_iJ d_kL + mu (d_ik d_JL + d_iL d_Jk) and ElasticMaterial's
//   components (same E, nu, plane strain), 1e-12 E; the small-strain stress
//   equals ElasticMaterial's;
// - bad input: det F <= 0 throws ExcNonPositiveJacobian (not NaN), and
//   E <= 0 and nu = 0.5 are refused with messages naming them; plane stress
//   is accepted (its tests: hyperelastic_plane_stress).
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/material.h>

#include <cmath>
#include <memory>
#include <vector>

#include "../tests.h"

using namespace dealvem;
using T2 = dealii::Tensor<2, 2>;

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

template <typename F>
std::string
message_of(const F &f)
{
  try
    {
      f();
    }
  catch (const std::exception &e)
    {
      return testing::collapse_white_space(e.what());
    }
  return "";
}

int
main()
{
  const double E = 7000.;
  const std::vector<std::pair<std::string, T2>> states = {
    {"identity", tensor(1, 0, 0, 1)},
    {"stretch", tensor(1.3, 0, 0, 0.9)},
    {"compression 30 %", tensor(1, 0, 0, 0.7)},
    {"simple shear", tensor(1, 0.5, 0, 1)},
    {"general", tensor(1.1, 0.3, -0.2, 0.8)},
    {"rotation x stretch", rotation(70. * M_PI / 180.) * tensor(1.2, 0.1, 0.1, 0.75)}};

  for (const double nu : {0.3, 0.45})
    {
      std::vector<std::unique_ptr<HyperelasticMaterial>> laws;
      laws.push_back(std::make_unique<NeoHookeMaterial>(E, nu));
      laws.push_back(std::make_unique<SaintVenantKirchhoffMaterial>(E, nu));
      const ElasticMaterial linear(E, nu, ElasticMaterial::Model::plane_strain);
      for (const auto &law : laws)
        {
          std::cout << "--- " << law->get_name() << std::endl;
          double err_P = 0, err_A = 0, err_obj = 0, err_sym = 0;
          const double h = 1e-6;
          const T2     Q = rotation(0.8);
          for (const auto &state : states)
            {
              const T2                   F = state.second;
              const T2                   P = law->first_piola_kirchhoff_stress(F);
              const dealii::Tensor<4, 2> A = law->first_piola_kirchhoff_tangent(F);
              for (unsigned int k = 0; k < 2; ++k)
                for (unsigned int L = 0; L < 2; ++L)
                  {
                    T2 Fp = F, Fm = F;
                    Fp[k][L] += h;
                    Fm[k][L] -= h;
                    const double dpsi = (law->strain_energy(Fp) - law->strain_energy(Fm)) / (2 * h);
                    err_P = std::max(err_P, std::abs(P[k][L] - dpsi));
                    const T2 dP =
                      (law->first_piola_kirchhoff_stress(Fp) - law->first_piola_kirchhoff_stress(Fm)) / (2 * h);
                    for (unsigned int i = 0; i < 2; ++i)
                      for (unsigned int J = 0; J < 2; ++J)
                        err_A = std::max(err_A, std::abs(A[i][J][k][L] - dP[i][J]));
                  }
              err_obj = std::max(err_obj, std::abs(law->strain_energy(Q * F) - law->strain_energy(F)));
              err_obj = std::max(err_obj, max_abs(law->first_piola_kirchhoff_stress(Q * F) - Q * P));
              const T2 sigma = law->cauchy_stress(F);
              err_sym        = std::max(err_sym, max_abs(sigma - dealii::transpose(sigma)));
            }
          testing::check_small(err_P / E, 1e-8, "P against differences of psi, / E");
          testing::check_small(err_A / E, 1e-8, "dP/dF against differences of P, / E");
          testing::check_small(err_obj / E, 1e-12, "objectivity psi(QF) = psi(F), P(QF) = Q P(F), / E");
          testing::check_small(err_sym / E, 1e-12, "symmetry of the Cauchy stress, / E");

          // the linearization at F = I
          const T2                            I     = tensor(1, 0, 0, 1);
          const dealii::Tensor<4, 2>          A0    = law->first_piola_kirchhoff_tangent(I);
          const dealii::SymmetricTensor<4, 2> C_lin = linear.tangent(dealii::SymmetricTensor<2, 2>());
          const double                        l = law->lambda(), m = law->mu();
          double                              err_C = 0;
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int J = 0; J < 2; ++J)
              for (unsigned int k = 0; k < 2; ++k)
                for (unsigned int L = 0; L < 2; ++L)
                  {
                    const double expected = l * (i == J) * (k == L) + m * ((i == k) * (J == L) + (i == L) * (J == k));
                    err_C = std::max(err_C, std::abs(A0[i][J][k][L] - expected));
                    err_C = std::max(err_C, std::abs(A0[i][J][k][L] - C_lin[i][J][k][L]));
                  }
          testing::check_small(err_C / E, 1e-12, "dP/dF at F = I equals the linear law's C, / E");
          testing::check_small(max_abs(law->first_piola_kirchhoff_stress(I)) / E, 1e-14, "P(I) = 0, / E");
          testing::check_near(l, linear.lambda(), 1e-12 * E, "lambda of the linearization");
          dealii::SymmetricTensor<2, 2> eps;
          eps[0][0] = 1e-3;
          eps[1][1] = -2e-3;
          eps[0][1] = 0.7e-3;
          testing::check_small((law->stress(eps) - linear.stress(eps)).norm() / E, 1e-15,
                               "small-strain stress equals ElasticMaterial's, / E");
          testing::check_small(std::abs(law->stress_zz(eps) - linear.stress_zz(eps)) / E, 1e-15,
                               "small-strain sigma_zz equals ElasticMaterial's, / E");
          testing::check(law->has_finite_strain_response() && law->is_linear(),
                         "finite-strain response, linear small-strain response");

          // det F <= 0: an exception, not NaN
          for (const T2 &bad : {tensor(1, 0, 0, -0.5), tensor(0, 0, 0, 0), tensor(1, 2, 1, 2)})
            {
              const std::string msg = message_of([&]() { law->first_piola_kirchhoff_stress(bad); });
              testing::check(msg.find("det F = J") != std::string::npos &&
                               msg.find(law->get_name()) != std::string::npos,
                             "det F = " + std::to_string(dealii::determinant(bad)) +
                               ": P throws naming J and the law");
              testing::check(!message_of([&]() { law->first_piola_kirchhoff_tangent(bad); }).empty() &&
                               !message_of([&]() { law->strain_energy(bad); }).empty(),
                             "  and so do dP/dF and psi");
            }
        }
    }

  // parameters out of range
  const std::string m1 = message_of([]() { NeoHookeMaterial(-1., 0.3); });
  testing::check(m1.find("Young's modulus must be positive, got E = -1") != std::string::npos,
                 "E = -1 refused: " + m1.substr(0, 200));
  const std::string m2 = message_of([]() { SaintVenantKirchhoffMaterial(1., 0.5); });
  testing::check(m2.find("Poisson's ratio must lie in (-1, 0.5), got nu = 0.5") != std::string::npos,
                 "nu = 0.5 refused");
  const NeoHookeMaterial plane_stress(1., 0.3, ElasticMaterial::Model::plane_stress);
  testing::check(plane_stress.get_name() == "Neo-Hooke (E = 1, nu = 0.3, plane stress)" &&
                   NeoHookeMaterial(1., 0.3).get_name() == "Neo-Hooke (E = 1, nu = 0.3, plane strain)",
                 "plane stress is accepted and named; plane strain is the default");
  return testing::finish();
}
