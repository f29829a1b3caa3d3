// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/elasticity/finite_strain_operator.h>
#include <dealvem/vem/vem_values.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace dealvem
{
  template <int dim>
  void
  FiniteStrainOperator<dim>::reinit(const VEMValues<dim> &vem_values)
  {
    cell        = vem_values.get_cell();
    n_dofs_cell = vem_values.dofs_per_cell();
    n_q         = vem_values.n_quadrature_points();
    JxW.resize(n_q);
    G.resize(n_q * n_dofs_cell);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        JxW[q] = vem_values.JxW(q);
        for (unsigned int i = 0; i < n_dofs_cell; ++i)
          G[q * n_dofs_cell + i] = vem_values.shape_gradient_projection(i, q);
      }
  }



  template <int dim>
  void
  FiniteStrainOperator<dim>::deformation_gradients(const dealii::Vector<double>        &local_u,
                                                   std::vector<dealii::Tensor<2, dim>> &F) const
  {
    AssertDimension(local_u.size(), n_dofs_cell);
    F.resize(n_q);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        dealii::Tensor<2, dim> Fq;
        for (unsigned int d = 0; d < dim; ++d)
          Fq[d][d] = 1.;
        for (unsigned int i = 0; i < n_dofs_cell; ++i)
          Fq += local_u[i] * G[q * n_dofs_cell + i];
        F[q] = Fq;
      }
  }



  template <int dim>
  void
  FiniteStrainOperator<dim>::compute_consistency(const ConstitutiveLaw<dim>   &law,
                                                 const dealii::Vector<double> &local_u,
                                                 const bool                    with_tangent,
                                                 dealii::Vector<double>       &r_c,
                                                 dealii::FullMatrix<double>   &K_c) const
  {
    AssertThrow(law.has_finite_strain_response(),
                dealii::ExcMessage("FiniteStrainOperator: the constitutive law '" + law.get_name() + "' of cell " +
                                   std::to_string(cell) +
                                   " has no finite-strain response (first Piola-Kirchhoff stress and tangent)."));
    std::vector<dealii::Tensor<2, dim>> F;
    deformation_gradients(local_u, F);
    r_c.reinit(n_dofs_cell);
    if (with_tangent)
      K_c.reinit(n_dofs_cell, n_dofs_cell);
    std::vector<dealii::Tensor<2, dim>> AG(n_dofs_cell);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const double J = dealii::determinant(F[q]);
        AssertThrow(J > 0 && std::isfinite(J), ExcInvertedCell(cell, q, J));
        const dealii::Tensor<2, dim> P    = law.first_piola_kirchhoff_stress(F[q]);
        const auto                  *G_q  = &G[q * n_dofs_cell];
        for (unsigned int i = 0; i < n_dofs_cell; ++i)
          r_c[i] += dealii::scalar_product(P, G_q[i]) * JxW[q];
        if (!with_tangent)
          continue;
        const dealii::Tensor<4, dim> A = law.first_piola_kirchhoff_tangent(F[q]);
        for (unsigned int j = 0; j < n_dofs_cell; ++j)
          AG[j] = dealii::double_contract<2, 0, 3, 1>(A, G_q[j]);
        for (unsigned int i = 0; i < n_dofs_cell; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            K_c(i, j) += dealii::scalar_product(G_q[i], AG[j]) * JxW[q];
      }
    if (with_tangent)
      for (unsigned int i = 0; i < n_dofs_cell; ++i)
        for (unsigned int j = 0; j < i; ++j)
          K_c(j, i) = K_c(i, j);
  }



  template <int dim>
  void
  FiniteStrainOperator<dim>::compute_stabilization(const VirtualElement<dim>    &element,
                                                   const ConstitutiveLaw<dim>   &law,
                                                   const dealii::Vector<double> &frozen_u,
                                                   const double                  gamma,
                                                   const Stabilization           rule,
                                                   const StabilizationScaling    scaling,
                                                   dealii::FullMatrix<double>   &K_s) const
  {
    AssertDimension(element.n_dofs_per_cell(), n_dofs_cell);
    dealii::Vector<double>     zero(n_dofs_cell), r;
    dealii::FullMatrix<double> K_0, K_star;
    compute_consistency(law, zero, true, r, K_0);
    dealii::FullMatrix<double> D(n_dofs_cell, n_dofs_cell);
    if (scaling == StabilizationScaling::initial_tangent)
      for (unsigned int i = 0; i < n_dofs_cell; ++i)
        D(i, i) = K_0(i, i);
    else
      {
        compute_consistency(law, frozen_u, true, r, K_star);
        for (unsigned int i = 0; i < n_dofs_cell; ++i)
          D(i, i) = std::max(K_star(i, i), stabilization_floor * K_0(i, i));
      }
    // ElasticityOperator's rules read the diagonal (diagonal rule) or the
    // trace (trace rule) of the matrix they are given
    K_s = D;
    ElasticityOperator<dim>::add_stabilization(element, K_s, gamma, rule);
    for (unsigned int i = 0; i < n_dofs_cell; ++i)
      K_s(i, i) -= D(i, i);
  }



  template class FiniteStrainOperator<2>;
} // namespace dealvem
