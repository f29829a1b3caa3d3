// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/elasticity/constitutive_law.h>

#include <cmath>

namespace dealvem
{
  template <int dim>
  bool
  ConstitutiveLaw<dim>::has_finite_strain_response() const
  {
    return false;
  }



  template <int dim>
  dealii::Tensor<2, dim>
  ConstitutiveLaw<dim>::first_piola_kirchhoff_stress(const dealii::Tensor<2, dim> &) const
  {
    AssertThrow(false,
                dealii::ExcMessage("The constitutive law '" + get_name() +
                                   "' has no finite-strain response: the first Piola-Kirchhoff stress P(F) "
                                   "is not implemented for this law."));
    return {};
  }



  template <int dim>
  dealii::Tensor<4, dim>
  ConstitutiveLaw<dim>::first_piola_kirchhoff_tangent(const dealii::Tensor<2, dim> &) const
  {
    AssertThrow(false,
                dealii::ExcMessage("The constitutive law '" + get_name() +
                                   "' has no finite-strain response: the tangent dP/dF "
                                   "is not implemented for this law."));
    return {};
  }



  template <int dim>
  void
  ConstitutiveLaw<dim>::first_piola_kirchhoff_stress_and_tangent(const dealii::Tensor<2, dim> &F,
                                                                 dealii::Tensor<2, dim>       &P,
                                                                 dealii::Tensor<4, dim>       &A) const
  {
    P = first_piola_kirchhoff_stress(F);
    A = first_piola_kirchhoff_tangent(F);
  }



  double
  von_mises_stress(const dealii::SymmetricTensor<2, 2> &s, const double szz)
  {
    const double sxx = s[0][0], syy = s[1][1], sxy = s[0][1];
    return std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) +
                            (szz - sxx) * (szz - sxx)) +
                     3. * sxy * sxy);
  }



  template class ConstitutiveLaw<2>;
} // namespace dealvem
