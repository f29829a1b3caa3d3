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
  ElasticityOperator<dim>::add_stabilization(const VirtualElement<dim>  &element,
                                             dealii::FullMatrix<double> &K,
                                             const double                gamma,
                                             const Stabilization         stabilization)
  {
    AssertThrow(gamma > 0 && std::isfinite(gamma),
                dealii::ExcMessage("The stabilization factor gamma must be positive, got " + std::to_string(gamma) +
                                   "."));
    const unsigned int n = K.m();
    AssertDimension(n, element.n_dofs_per_cell());
    const double tau = stabilization_scaling(K, 1.);
    if (stabilization == Stabilization::trace ||
        (stabilization == Stabilization::automatic && element.get_degree() == 1))
      {
        K.add(gamma * tau, element.get_stabilization_form());
        return;
      }
    // (I - Pi)^T diag(d) (I - Pi), d_i = c_k max(K_ii, 1e-3 tau)
    const double c_k   = (element.get_degree() == 1 ? 1. : 0.2);
    RowMatrix    I_Pi  = -view(element.get_projector_dof_basis());
    Eigen::VectorXd d(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        I_Pi(i, i) += 1.;
        d(i) = gamma * c_k * std::max(K(i, i), 1e-3 * tau);
      }
    const RowMatrix Ks = I_Pi.transpose() * d.asDiagonal() * I_Pi;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        K(i, j) += 0.5 * (Ks(i, j) + Ks(j, i));
  }



  template <int dim>
  void
  ElasticityOperator<dim>::reinit(const VirtualElement<dim> &element,
                                  const ElasticMaterial     &material,
                                  const double               gamma_in,
                                  const Stabilization        stabilization)
  {
    AssertThrow(gamma_in > 0 && std::isfinite(gamma_in),
                dealii::ExcMessage("The stabilization factor gamma must be positive, got " +
                                   std::to_string(gamma_in) + "."));
    const double l = material.lambda(), m = material.mu();
    reused = valid && revision == element.matrices_revision() && lambda == l && mu == m && gamma == gamma_in &&
             rule == stabilization;
    if (reused)
      return;
    valid    = false;
    revision = element.matrices_revision();
    lambda   = l;
    mu       = m;
    gamma    = gamma_in;
    rule     = stabilization;

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
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < i; ++j)
        K_c(i, j) = K_c(j, i) = 0.5 * (K_c(i, j) + K_c(j, i));

    stab_scaling = stabilization_scaling(K_c, gamma);
    K            = K_c;
    add_stabilization(element, K, gamma, stabilization);
    K_s.reinit(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        K_s(i, j) = K(i, j) - K_c(i, j);
    valid = true;
  }

  template class ElasticityOperator<2>;
} // namespace dealvem
