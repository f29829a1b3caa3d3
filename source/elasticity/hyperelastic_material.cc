// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/elasticity/hyperelastic_material.h>

#include <cmath>
#include <sstream>

namespace dealvem
{
  HyperelasticMaterial::HyperelasticMaterial(const double E, const double nu, const ElasticMaterial::Model model)
    : E(E)
    , nu(nu)
    , linear(std::isfinite(E) && E > 0 && std::isfinite(nu) && nu > -1. && nu < 0.5 ? E : 1.,
             std::isfinite(E) && E > 0 && std::isfinite(nu) && nu > -1. && nu < 0.5 ? nu : 0.,
             ElasticMaterial::Model::plane_strain)
  {
    std::ostringstream e_text;
    e_text << E;
    AssertThrow(std::isfinite(E) && E > 0,
                dealii::ExcMessage("Hyperelastic law: Young's modulus must be positive, got E = " + e_text.str()));
    AssertThrow(E >= ElasticMaterial::min_youngs_modulus && E <= ElasticMaterial::max_youngs_modulus,
                dealii::ExcMessage("Hyperelastic law: Young's modulus E = " + e_text.str() +
                                   " is outside the supported range [1e-200, 1e200] (choose units "
                                   "that bring E nearer to 1)."));
    AssertThrow(std::isfinite(nu) && nu > -1.0 && nu < 0.5,
                dealii::ExcMessage("Hyperelastic law: Poisson's ratio must lie in (-1, 0.5), got nu = " +
                                   std::to_string(nu)));
    AssertThrow(model == ElasticMaterial::Model::plane_strain,
                dealii::ExcMessage("Hyperelastic law: plane stress at finite strain is not implemented (it "
                                   "needs the out-of-plane stretch F_zz from P_zz = 0 at every point); use "
                                   "plane strain."));
  }



  double
  HyperelasticMaterial::mu() const
  {
    return linear.mu();
  }




  double
  HyperelasticMaterial::lambda() const
  {
    return linear.lambda();
  }




  ElasticMaterial
  HyperelasticMaterial::linearization() const
  {
    return linear;
  }




  dealii::Tensor<2, 2>
  HyperelasticMaterial::cauchy_stress(const dealii::Tensor<2, 2> &F) const
  {
    const double J = checked_determinant(F);
    return first_piola_kirchhoff_stress(F) * dealii::transpose(F) / J;
  }



  bool
  HyperelasticMaterial::has_finite_strain_response() const
  {
    return true;
  }



  bool
  HyperelasticMaterial::is_linear() const
  {
    return true;
  }



  double
  HyperelasticMaterial::characteristic_stiffness() const
  {
    return E;
  }



  dealii::SymmetricTensor<2, 2>
  HyperelasticMaterial::stress(const dealii::SymmetricTensor<2, 2> &strain) const
  {
    return linear.stress(strain);
  }




  dealii::SymmetricTensor<4, 2>
  HyperelasticMaterial::tangent(const dealii::SymmetricTensor<2, 2> &) const
  {
    return linear.tangent(dealii::SymmetricTensor<2, 2>());
  }




  double
  HyperelasticMaterial::stress_zz(const dealii::SymmetricTensor<2, 2> &strain) const
  {
    return linear.stress_zz(strain);
  }




  double
  HyperelasticMaterial::checked_determinant(const dealii::Tensor<2, 2> &F) const
  {
    const double J = dealii::determinant(F);
    AssertThrow(J > 0 && std::isfinite(J), ExcNonPositiveJacobian(J, get_name()));
    return J;
  }



  std::string
  HyperelasticMaterial::parameter_text() const
  {
    std::ostringstream s;
    s << "E = " << E << ", nu = " << nu << ", plane strain";
    return s.str();
  }



  // ----------------------------------------------------------- Neo-Hooke

  NeoHookeMaterial::NeoHookeMaterial(const double E, const double nu, const ElasticMaterial::Model model)
    : HyperelasticMaterial(E, nu, model)
  {}



  std::string
  NeoHookeMaterial::get_name() const
  {
    return "Neo-Hooke (" + parameter_text() + ")";
  }



  std::unique_ptr<ConstitutiveLaw<2>>
  NeoHookeMaterial::clone() const
  {
    return std::make_unique<NeoHookeMaterial>(*this);
  }



  double
  NeoHookeMaterial::strain_energy(const dealii::Tensor<2, 2> &F) const
  {
    const double J   = checked_determinant(F);
    const double lnJ = std::log(J);
    const double I1  = dealii::scalar_product(F, F) + 1.;
    return 0.5 * mu() * (I1 - 3.) - mu() * lnJ + 0.5 * lambda() * lnJ * lnJ;
  }



  dealii::Tensor<2, 2>
  NeoHookeMaterial::first_piola_kirchhoff_stress(const dealii::Tensor<2, 2> &F) const
  {
    const double J = checked_determinant(F);
    return mu() * F + (lambda() * std::log(J) - mu()) * dealii::transpose(dealii::invert(F));
  }



  dealii::Tensor<4, 2>
  NeoHookeMaterial::first_piola_kirchhoff_tangent(const dealii::Tensor<2, 2> &F) const
  {
    const double               J    = checked_determinant(F);
    const double               m    = mu();
    const double               l    = lambda();
    const double               c    = l * std::log(J) - m;
    const dealii::Tensor<2, 2> Finv = dealii::invert(F);
    dealii::Tensor<4, 2>       A;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int J_ = 0; J_ < 2; ++J_)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int L = 0; L < 2; ++L)
            A[i][J_][k][L] = (i == k && J_ == L ? m : 0.) + l * Finv[J_][i] * Finv[L][k] -
                             c * Finv[J_][k] * Finv[L][i];
    return A;
  }



  // ---------------------------------------------- Saint Venant-Kirchhoff

  SaintVenantKirchhoffMaterial::SaintVenantKirchhoffMaterial(const double                 E,
                                                             const double                 nu,
                                                             const ElasticMaterial::Model model)
    : HyperelasticMaterial(E, nu, model)
  {}



  std::string
  SaintVenantKirchhoffMaterial::get_name() const
  {
    return "Saint Venant-Kirchhoff (" + parameter_text() + ")";
  }



  std::unique_ptr<ConstitutiveLaw<2>>
  SaintVenantKirchhoffMaterial::clone() const
  {
    return std::make_unique<SaintVenantKirchhoffMaterial>(*this);
  }



  namespace
  {
    // Green-Lagrange strain E = (F^T F - I) / 2 and S = lambda tr(E) I + 2 mu E
    dealii::Tensor<2, 2>
    green_lagrange(const dealii::Tensor<2, 2> &F)
    {
      dealii::Tensor<2, 2> E = 0.5 * (dealii::transpose(F) * F);
      E[0][0] -= 0.5;
      E[1][1] -= 0.5;
      return E;
    }

    dealii::Tensor<2, 2>
    second_piola(const dealii::Tensor<2, 2> &E, const double lambda, const double mu)
    {
      dealii::Tensor<2, 2> S  = 2. * mu * E;
      const double         tr = dealii::trace(E);
      S[0][0] += lambda * tr;
      S[1][1] += lambda * tr;
      return S;
    }
  } // namespace



  double
  SaintVenantKirchhoffMaterial::strain_energy(const dealii::Tensor<2, 2> &F) const
  {
    checked_determinant(F);
    const dealii::Tensor<2, 2> E  = green_lagrange(F);
    const double               tr = dealii::trace(E);
    return 0.5 * lambda() * tr * tr + mu() * dealii::scalar_product(E, E);
  }



  dealii::Tensor<2, 2>
  SaintVenantKirchhoffMaterial::first_piola_kirchhoff_stress(const dealii::Tensor<2, 2> &F) const
  {
    checked_determinant(F);
    return F * second_piola(green_lagrange(F), lambda(), mu());
  }



  dealii::Tensor<4, 2>
  SaintVenantKirchhoffMaterial::first_piola_kirchhoff_tangent(const dealii::Tensor<2, 2> &F) const
  {
    checked_determinant(F);
    const double               l = lambda(), m = mu();
    const dealii::Tensor<2, 2> S = second_piola(green_lagrange(F), l, m);
    // F_iM C_MJNL F_kN = lambda F_iJ F_kL + mu (F_iN F_kN delta_JL + F_iL F_kJ)
    const dealii::Tensor<2, 2> FFt = F * dealii::transpose(F);
    dealii::Tensor<4, 2>       A;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int J = 0; J < 2; ++J)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int L = 0; L < 2; ++L)
            A[i][J][k][L] = (i == k ? S[J][L] : 0.) + l * F[i][J] * F[k][L] +
                            m * ((J == L ? FFt[i][k] : 0.) + F[i][L] * F[k][J]);
    return A;
  }
} // namespace dealvem
