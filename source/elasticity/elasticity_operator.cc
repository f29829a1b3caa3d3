// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/elasticity/elasticity_operator.h>

#include <Eigen/Dense>

#include <cmath>
#include <string>

namespace dealvem
{
  namespace
  {
    using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    using RowMap    = Eigen::Map<RowMatrix>;
    using ConstMap  = Eigen::Map<const RowMatrix>;

    RowMap
    view(dealii::FullMatrix<double> &A)
    {
      return RowMap(&A(0, 0), A.m(), A.n());
    }

    ConstMap
    view(const dealii::FullMatrix<double> &A)
    {
      return ConstMap(&A(0, 0), A.m(), A.n());
    }
  } // namespace



  template <int dim>
  double
  ElasticityOperator<dim>::stabilization_scaling(const dealii::FullMatrix<double> &K_c,
                                                 const double                      gamma)
  {
    double trace = 0;
    for (unsigned int i = 0; i < K_c.m(); ++i)
      trace += K_c(i, i);
    return gamma * trace / K_c.m();
  }



  template <int dim>
  void
  ElasticityOperator<dim>::reinit(const VirtualElement<dim> &element,
                                  const ElasticMaterial     &material,
                                  const double               gamma_in)
  {
    AssertThrow(gamma_in > 0 && std::isfinite(gamma_in),
                dealii::ExcMessage("The stabilization factor gamma must be positive, got " +
                                   std::to_string(gamma_in) + "."));
    const double l = material.lambda(), m = material.mu();
    reused = valid && revision == element.matrices_revision() &&
             lambda == l && mu == m && gamma == gamma_in;
    if (reused)
      return;
    valid    = false;
    revision = element.matrices_revision();
    lambda   = l;
    mu       = m;
    gamma    = gamma_in;

    const unsigned int n_p = element.n_polynomials(), n_s = n_p - 3;
    const unsigned int n   = element.n_dofs_per_cell();
    // the form on the strain modes: lambda T + 2 mu E (the rigid modes are
    // in the kernel of both Gram matrices)
    A.reinit(n_s, n_s);
    const auto &T = element.get_divergence_gram(), &E = element.get_strain_gram();
    for (unsigned int a = 0; a < n_s; ++a)
      for (unsigned int b = 0; b < n_s; ++b)
        A(a, b) = l * T(a + 3, b + 3) + 2. * m * E(a + 3, b + 3);
    const auto P = view(element.get_projector()).bottomRows(n_s);
    K_c.reinit(n, n);
    RowMap Kc = view(K_c);
    Kc.noalias() = P.transpose() * (view(static_cast<const dealii::FullMatrix<double> &>(A)) * P);

    stab_scaling = stabilization_scaling(K_c, gamma);
    const auto &S = element.get_stabilization_form();
    K_s.reinit(n, n);
    K.reinit(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j <= i; ++j)
        {
          const double kc = 0.5 * (K_c(i, j) + K_c(j, i)), ks = stab_scaling * S(i, j);
          K_c(i, j) = K_c(j, i) = kc;
          K_s(i, j) = K_s(j, i) = ks;
          K(i, j) = K(j, i) = kc + ks;
        }
    valid = true;
  }

  template class ElasticityOperator<2>;
} // namespace dealvem
