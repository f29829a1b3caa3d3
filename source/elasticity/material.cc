// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/elasticity/material.h>

#include <cmath>
#include <sstream>

namespace dealvem
{
  ElasticMaterial::ElasticMaterial(const double E, const double nu, const Model model)
    : E(E)
    , nu(nu)
    , model_(model)
  {
    std::ostringstream e_text;
    e_text << E;
    AssertThrow(std::isfinite(E) && E > 0,
                dealii::ExcMessage("Young's modulus must be positive, got E = " + e_text.str()));
    AssertThrow(E >= min_youngs_modulus && E <= max_youngs_modulus,
                dealii::ExcMessage("Young's modulus E = " + e_text.str() +
                                   " is outside the supported range [1e-200, 1e200] (choose units "
                                   "that bring E nearer to 1)."));
    AssertThrow(std::isfinite(nu) && nu > -1.0 && nu < 0.5,
                dealii::ExcMessage("Poisson's ratio must lie in (-1, 0.5), got nu = " +
                                   std::to_string(nu)));
  }

  double
  ElasticMaterial::mu() const
  {
    return E / (2. * (1. + nu));
  }

  double
  ElasticMaterial::lambda() const
  {
    const double lambda_3d = E * nu / ((1. + nu) * (1. - 2. * nu));
    if (model_ == Model::plane_strain)
      return lambda_3d;
    // plane stress: lambda* = 2 lambda mu / (lambda + 2 mu) = E nu / (1 - nu^2)
    return E * nu / (1. - nu * nu);
  }

  dealii::SymmetricTensor<2, 2>
  ElasticMaterial::stress(const dealii::SymmetricTensor<2, 2> &strain) const
  {
    const double                  l = lambda(), m = mu();
    dealii::SymmetricTensor<2, 2> s = 2. * m * strain;
    const double                  tr = dealii::trace(strain);
    s[0][0] += l * tr;
    s[1][1] += l * tr;
    return s;
  }

  double
  ElasticMaterial::stress_zz(const dealii::SymmetricTensor<2, 2> &strain) const
  {
    if (model_ == Model::plane_stress)
      return 0.;
    const auto s = stress(strain);
    return nu * (s[0][0] + s[1][1]);
  }

  dealii::SymmetricTensor<4, 2>
  ElasticMaterial::tangent(const dealii::SymmetricTensor<2, 2> &) const
  {
    const double                  l = lambda(), m = mu();
    dealii::SymmetricTensor<4, 2> C;
    C[0][0][0][0] = C[1][1][1][1] = l + 2. * m;
    C[0][0][1][1] = C[1][1][0][0] = l;
    C[0][1][0][1]                 = m;
    return C;
  }



  bool
  ElasticMaterial::is_linear() const
  {
    return true;
  }



  double
  ElasticMaterial::characteristic_stiffness() const
  {
    return E;
  }



  std::string
  ElasticMaterial::get_name() const
  {
    std::ostringstream s;
    s << "linear isotropic (E = " << E << ", nu = " << nu << ", " << model_name(model_) << ")";
    return s.str();
  }



  std::unique_ptr<ConstitutiveLaw<2>>
  ElasticMaterial::clone() const
  {
    return std::make_unique<ElasticMaterial>(*this);
  }



  double
  ElasticMaterial::von_mises(const dealii::SymmetricTensor<2, 2> &s, const double szz)
  {
    return von_mises_stress(s, szz);
  }



  std::string
  ElasticMaterial::model_name(const Model m)
  {
    return m == Model::plane_strain ? "plane strain" : "plane stress";
  }

  ElasticMaterial::Model
  ElasticMaterial::parse_model(const std::string &name)
  {
    if (name == "plane strain")
      return Model::plane_strain;
    if (name == "plane stress")
      return Model::plane_stress;
    AssertThrow(false,
                dealii::ExcMessage("Unknown material model '" + name +
                                   "': expected 'plane strain' or 'plane stress'."));
    return Model::plane_strain;
  }
} // namespace dealvem
