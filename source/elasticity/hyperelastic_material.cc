// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/elasticity/hyperelastic_material.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace dealvem
{
  namespace
  {
    bool
    valid_parameters(const double E, const double nu)
    {
      return std::isfinite(E) && E > 0 && std::isfinite(nu) && nu > -1. && nu < 0.5;
    }

    // "[[F00, F01], [F10, F11]]" for messages
    std::string
    tensor_text(const dealii::Tensor<2, 2> &F)
    {
      std::ostringstream s;
      s.precision(12);
      s << "[[" << F[0][0] << ", " << F[0][1] << "], [" << F[1][0] << ", " << F[1][1] << "]]";
      return s.str();
    }
  } // namespace



  HyperelasticMaterial::HyperelasticMaterial(const double E, const double nu, const ElasticMaterial::Model model)
    : E(E)
    , nu(nu)
    , model_(model)
    , linear(valid_parameters(E, nu) ? E : 1., valid_parameters(E, nu) ? nu : 0., model)
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
    AssertThrow(model == ElasticMaterial::Model::plane_strain || model == ElasticMaterial::Model::plane_stress,
                dealii::ExcMessage("Hyperelastic law: unknown model (expected plane strain or plane stress)."));
  }



  double
  HyperelasticMaterial::mu() const
  {
    return linear.mu();
  }




  double
  HyperelasticMaterial::lambda() const
  {
    // the 3D parameter, as ElasticMaterial computes it in plane strain
    return E * nu / ((1. + nu) * (1. - 2. * nu));
  }




  ElasticMaterial
  HyperelasticMaterial::linearization() const
  {
    return linear;
  }



  double
  HyperelasticMaterial::stretch(const dealii::Tensor<2, 2> &F, const double det_F) const
  {
    if (model_ == ElasticMaterial::Model::plane_strain)
      return 1.;

    // The law gives g(f), with the sign of P_zz(F, f), strictly increasing
    // on (f_min, infinity) and tending to +infinity: a root exists iff
    // g(f_min+) < 0, and then it is unique on that branch.
    double       g_min = 0;
    const double f_min = stretch_branch(F, det_F, g_min);
    AssertThrow(g_min < 0, ExcNoPlaneStressState(get_name(), tensor_text(F), no_stretch_explanation(F, det_F, g_min)));

    // Bracket [lo, hi] with g(lo) < 0 < g(hi) (lo = f_min stands for the
    // limit), starting at f = 1, the root at F = I.
    constexpr double eps = std::numeric_limits<double>::epsilon();
    double           lo = f_min, hi = std::numeric_limits<double>::infinity();
    double           f  = std::max(1., 2. * f_min);
    double           dg = 0;
    double           g  = stretch_function(F, det_F, f, dg);
    if (g < 0)
      {
        // double f until g changes sign (g grows without bound)
        lo = f;
        double f_up = f, dg_up = 0, g_up = g;
        for (unsigned int i = 0; i < 2000 && g_up < 0 && std::isfinite(f_up); ++i)
          {
            lo   = f_up;
            f_up = 2. * f_up;
            g_up = stretch_function(F, det_F, f_up, dg_up);
          }
        AssertThrow(std::isfinite(f_up) && std::isfinite(g_up) && g_up >= 0,
                    ExcNoPlaneStressState(get_name(), tensor_text(F), "no sign change of P_zz found up to f = " +
                                                                        std::to_string(f_up)));
        hi = f_up;
        // start the Newton iteration from the nearer end
        if (-g > g_up)
          {
            f  = f_up;
            g  = g_up;
            dg = dg_up;
          }
      }

    // Newton steps kept inside the bracket (bisection otherwise), until the
    // step or the bracket is at round-off
    bool converged = (g == 0);
    for (unsigned int it = 0; it < 300 && !converged; ++it)
      {
        if (g < 0)
          lo = f;
        else
          hi = f;
        double f_new = (dg > 0 && std::isfinite(dg)) ? f - g / dg : lo;
        if (!(f_new > lo && f_new < hi))
          f_new = 0.5 * (lo + hi);
        const double step = std::abs(f_new - f);
        f                 = f_new;
        g                 = stretch_function(F, det_F, f, dg);
        converged         = (g == 0) || step <= 4. * eps * f || (hi - lo) <= 4. * eps * hi;
      }
    AssertThrow(converged && std::isfinite(f) && f > 0,
                dealii::ExcMessage("the law '" + get_name() +
                                   "': the iteration for the out-of-plane stretch did not converge at the in-plane "
                                   "F = " +
                                   tensor_text(F) + " (last f = " + std::to_string(f) +
                                   ", g(f) = " + std::to_string(g) + ")."));
    return f;
  }



  double
  HyperelasticMaterial::out_of_plane_stretch(const dealii::Tensor<2, 2> &F) const
  {
    return stretch(F, checked_determinant(F));
  }



  double
  HyperelasticMaterial::strain_energy(const dealii::Tensor<2, 2> &F) const
  {
    const double det_F = checked_determinant(F);
    Response3D   r;
    evaluate_3d(F, det_F, stretch(F, det_F), Level::energy, r);
    return r.psi;
  }



  dealii::Tensor<2, 2>
  HyperelasticMaterial::first_piola_kirchhoff_stress(const dealii::Tensor<2, 2> &F) const
  {
    const double det_F = checked_determinant(F);
    Response3D   r;
    evaluate_3d(F, det_F, stretch(F, det_F), Level::stress, r);
    return r.P;
  }



  dealii::Tensor<4, 2>
  HyperelasticMaterial::first_piola_kirchhoff_tangent(const dealii::Tensor<2, 2> &F) const
  {
    dealii::Tensor<2, 2> P;
    dealii::Tensor<4, 2> A;
    first_piola_kirchhoff_stress_and_tangent(F, P, A);
    return A;
  }



  void
  HyperelasticMaterial::first_piola_kirchhoff_stress_and_tangent(const dealii::Tensor<2, 2> &F,
                                                                 dealii::Tensor<2, 2>       &P,
                                                                 dealii::Tensor<4, 2>       &A) const
  {
    const double det_F = checked_determinant(F);
    Response3D   r;
    evaluate_3d(F, det_F, stretch(F, det_F), Level::tangent, r);
    // evaluate_3d() computes P the same way at every level
    P = r.P;
    A = r.dP_dF;
    if (model_ == ElasticMaterial::Model::plane_strain)
      return;
    // plane stress: f = f(F) with df/dF = -(dP_zz/dF) / (dP_zz/df)
    for (unsigned int a = 0; a < 2; ++a)
      for (unsigned int b = 0; b < 2; ++b)
        for (unsigned int c = 0; c < 2; ++c)
          for (unsigned int d = 0; d < 2; ++d)
            A[a][b][c][d] -= r.dP_df[a][b] * r.dP_df[c][d] / r.dPzz_df;
  }



  dealii::Tensor<2, 2>
  HyperelasticMaterial::cauchy_stress(const dealii::Tensor<2, 2> &F) const
  {
    const double det_F = checked_determinant(F);
    const double f     = stretch(F, det_F);
    Response3D   r;
    evaluate_3d(F, det_F, f, Level::stress, r);
    return r.P * dealii::transpose(F) / (f * det_F);
  }



  double
  HyperelasticMaterial::cauchy_stress_zz(const dealii::Tensor<2, 2> &F) const
  {
    const double det_F = checked_determinant(F);
    if (model_ == ElasticMaterial::Model::plane_stress)
      {
        // the stretch f is the root of P_zz = 0; evaluating it checks that
        // the state exists (and throws as the other functions do if not)
        (void)stretch(F, det_F);
        return 0.;
      }
    Response3D r;
    evaluate_3d(F, det_F, 1., Level::stress, r);
    return r.P_zz / det_F;
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
    s << "E = " << E << ", nu = " << nu << ", " << ElasticMaterial::model_name(model_);
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



  void
  NeoHookeMaterial::evaluate_3d(const dealii::Tensor<2, 2> &F,
                                const double                det_F,
                                const double                f,
                                const Level                 level,
                                Response3D                 &r) const
  {
    const double m   = mu();
    const double l   = lambda();
    const double lnJ = std::log(f * det_F);
    const double I1  = dealii::scalar_product(F, F) + f * f;
    r.psi            = 0.5 * m * (I1 - 3.) - m * lnJ + 0.5 * l * lnJ * lnJ;
    if (level == Level::energy)
      return;

    const double               c     = l * lnJ - m;
    const dealii::Tensor<2, 2> Finv  = dealii::invert(F);
    const dealii::Tensor<2, 2> FinvT = dealii::transpose(Finv);
    r.P                              = m * F + c * FinvT;
    r.P_zz                           = m * f + c / f;
    if (level == Level::stress)
      return;

    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int J_ = 0; J_ < 2; ++J_)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int L = 0; L < 2; ++L)
            r.dP_dF[i][J_][k][L] = (i == k && J_ == L ? m : 0.) + l * Finv[J_][i] * Finv[L][k] -
                                   c * Finv[J_][k] * Finv[L][i];
    // d ln J / df = 1/f and d ln J / dF = F^{-T}
    r.dP_df   = (l / f) * FinvT;
    r.dPzz_df = m + (l - c) / (f * f);
  }



  double
  NeoHookeMaterial::stretch_function(const dealii::Tensor<2, 2> &,
                                     const double det_F,
                                     const double f,
                                     double      &derivative) const
  {
    // g = f P_zz: same sign as P_zz for f > 0
    const double m = mu(), l = lambda();
    derivative     = 2. * m * f + l / f;
    return m * (f * f - 1.) + l * std::log(f * det_F);
  }



  double
  NeoHookeMaterial::stretch_branch(const dealii::Tensor<2, 2> &F, const double det_F, double &g_min) const
  {
    // g' = 2 mu f + lambda / f: positive on (0, inf) for lambda >= 0, with
    // g(0+) = -inf (lambda > 0) or -mu (lambda = 0); for lambda < 0, g
    // decreases from +inf to its minimum at f_* = sqrt(-lambda / (2 mu)),
    // then increases.
    const double l = lambda();
    if (l > 0)
      {
        g_min = -std::numeric_limits<double>::infinity();
        return 0.;
      }
    if (l == 0)
      {
        g_min = -mu();
        return 0.;
      }
    const double f_star = std::sqrt(-l / (2. * mu()));
    double       dg     = 0;
    g_min               = stretch_function(F, det_F, f_star, dg);
    return f_star;
  }



  std::string
  NeoHookeMaterial::no_stretch_explanation(const dealii::Tensor<2, 2> &, const double det_F, const double g_min) const
  {
    std::ostringstream s;
    s.precision(6);
    s << "with nu < 0, f P_zz = mu (f^2 - 1) + lambda ln(f det F) has its minimum " << g_min
      << " >= 0 at f = " << std::sqrt(-lambda() / (2. * mu())) << " for det F = " << det_F
      << ": the in-plane compression is too strong, the energy decreases without bound as f -> 0";
    return s.str();
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
    // the in-plane block of the Green-Lagrange strain, (F^T F - I) / 2
    dealii::Tensor<2, 2>
    green_lagrange(const dealii::Tensor<2, 2> &F)
    {
      dealii::Tensor<2, 2> E = 0.5 * (dealii::transpose(F) * F);
      E[0][0] -= 0.5;
      E[1][1] -= 0.5;
      return E;
    }
  } // namespace



  void
  SaintVenantKirchhoffMaterial::evaluate_3d(const dealii::Tensor<2, 2> &F,
                                            const double,
                                            const double f,
                                            const Level  level,
                                            Response3D  &r) const
  {
    const double               l = lambda(), m = mu();
    const dealii::Tensor<2, 2> E    = green_lagrange(F);
    const double               E_zz = 0.5 * (f * f - 1.);
    const double               tr   = dealii::trace(E) + E_zz;
    r.psi                           = 0.5 * l * tr * tr + m * (dealii::scalar_product(E, E) + E_zz * E_zz);
    if (level == Level::energy)
      return;

    // the in-plane block of S = lambda tr(E) I + 2 mu E, and S_zz
    dealii::Tensor<2, 2> S = 2. * m * E;
    S[0][0] += l * tr;
    S[1][1] += l * tr;
    const double S_zz = l * tr + 2. * m * E_zz;
    r.P               = F * S;
    r.P_zz            = f * S_zz;
    if (level == Level::stress)
      return;

    // F_iM C_MJNL F_kN = lambda F_iJ F_kL + mu (F_iN F_kN delta_JL + F_iL F_kJ)
    // (M, N = z do not contribute: F_iz = 0 for in-plane i)
    const dealii::Tensor<2, 2> FFt = F * dealii::transpose(F);
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int J = 0; J < 2; ++J)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int L = 0; L < 2; ++L)
            r.dP_dF[i][J][k][L] = (i == k ? S[J][L] : 0.) + l * F[i][J] * F[k][L] +
                                  m * ((J == L ? FFt[i][k] : 0.) + F[i][L] * F[k][J]);
    // d tr(E) / df = f, d tr(E) / dF = F
    r.dP_df   = (l * f) * F;
    r.dPzz_df = S_zz + (l + 2. * m) * f * f;
  }



  double
  SaintVenantKirchhoffMaterial::stretch_function(const dealii::Tensor<2, 2> &F,
                                                 const double,
                                                 const double f,
                                                 double      &derivative) const
  {
    // g = S_zz = P_zz / f
    const double l = lambda(), m = mu();
    derivative     = (l + 2. * m) * f;
    return l * dealii::trace(green_lagrange(F)) + (0.5 * l + m) * (f * f - 1.);
  }



  double
  SaintVenantKirchhoffMaterial::stretch_branch(const dealii::Tensor<2, 2> &F, const double, double &g_min) const
  {
    // g' = (lambda + 2 mu) f > 0 on (0, inf)
    const double l = lambda(), m = mu();
    g_min          = l * dealii::trace(green_lagrange(F)) - (0.5 * l + m);
    return 0.;
  }



  std::string
  SaintVenantKirchhoffMaterial::no_stretch_explanation(const dealii::Tensor<2, 2> &F,
                                                       const double,
                                                       const double) const
  {
    const double       l = lambda(), m = mu();
    std::ostringstream s;
    s.precision(6);
    s << "S_zz = lambda tr(E_2D) + (lambda/2 + mu)(f^2 - 1) > 0 for every f > 0 since lambda tr(E_2D) = "
      << l * dealii::trace(green_lagrange(F)) << " >= lambda/2 + mu = " << 0.5 * l + m
      << ": the in-plane stretch is too large, the sheet's thickness would have to vanish";
    return s.str();
  }
} // namespace dealvem
