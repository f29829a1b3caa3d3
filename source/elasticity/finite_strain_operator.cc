// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/elasticity/finite_strain_operator.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/vem/vem_values.h>

#include <algorithm>
#include <cmath>
#include <sstream>
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
  double
  FiniteStrainOperator<dim>::strain_energy(const ConstitutiveLaw<dim> &law, const dealii::Vector<double> &local_u) const
  {
    const auto *hyperelastic = dynamic_cast<const HyperelasticMaterial *>(&law);
    AssertThrow(hyperelastic != nullptr,
                dealii::ExcMessage("FiniteStrainOperator::strain_energy(): the law '" + law.get_name() +
                                   "' of cell " + std::to_string(cell) + " is not a hyperelastic law with an energy."));
    std::vector<dealii::Tensor<2, dim>> F;
    deformation_gradients(local_u, F);
    double energy = 0;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const double J = dealii::determinant(F[q]);
        AssertThrow(J > 0 && std::isfinite(J), ExcInvertedCell(cell, q, J));
        energy += hyperelastic->strain_energy(F[q]) * JxW[q];
      }
    return energy;
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
        // (the stress of the combined call is first_piola_kirchhoff_stress()'s)
        dealii::Tensor<2, dim> P;
        dealii::Tensor<4, dim> A;
        if (with_tangent)
          law.first_piola_kirchhoff_stress_and_tangent(F[q], P, A);
        else
          P = law.first_piola_kirchhoff_stress(F[q]);
        const auto *G_q = &G[q * n_dofs_cell];
        for (unsigned int i = 0; i < n_dofs_cell; ++i)
          r_c[i] += dealii::scalar_product(P, G_q[i]) * JxW[q];
        if (!with_tangent)
          continue;
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



  namespace finite_strain_operator_projector
  {
    // I - D Pi^c, with Pi^c the componentwise H1 projector onto [P_k]^2:
    // int grad Pi^c v : grad p = int grad v : grad p for every p, and the
    // mean of each component (vertex mean for k = 1, cell moment for
    // k = 2) kept. It commutes with rotating the field (see the class
    // documentation). Rows alpha >= 2 of B^c:
    // int grad p_a : grad phi_i = int_dE (grad p_a n) . phi_i - int_E lap p_a . phi_i,
    // the edge term by Gauss-Lobatto on the edge's nodes (exact: the
    // integrand has degree 2k - 1), the cell term from the cell moments
    // (VirtualElement::add_cell_laplacian_term()).
    template <int dim>
    void
    componentwise_projector_complement(const VirtualElement<dim> &element, dealii::FullMatrix<double> &I_Pi)
    {
      const PolygonGeometry<dim> &geometry = element.get_geometry();
      const VEMElementData       &layout   = element.get_element_data();
      const unsigned int          n = element.n_dofs_per_cell(), n_p = element.n_polynomials(),
                         N = geometry.n_vertices();
      const std::vector<double>  &edge_weights = layout.edge_quadrature_weights();
      dealii::FullMatrix<double> Bc(n_p, n);
      if (layout.nodes_per_cell() == 0)
        for (unsigned int v = 0; v < N; ++v)
          {
            Bc(0, 2 * v)     = 1. / N;
            Bc(1, 2 * v + 1) = 1. / N;
          }
      else
        {
          Bc(0, 2 * layout.cell_node(N, 0))     = 1.;
          Bc(1, 2 * layout.cell_node(N, 0) + 1) = 1.;
        }
      for (unsigned int alpha = 2; alpha < n_p; ++alpha)
        {
          for (unsigned int e = 0; e < N; ++e)
            {
              const std::vector<unsigned int> nodes = element.edge_nodes(e);
              const double                    L     = geometry.edge_length(e);
              const dealii::Tensor<1, dim>    normal = geometry.edge_normal(e);
              // edge_nodes() lists the nodes in the order of the weights
              for (unsigned int a = 0; a < nodes.size(); ++a)
                {
                  const dealii::Tensor<1, dim> flux =
                    element.polynomial_gradient(alpha, element.node_location(nodes[a])) * normal;
                  for (unsigned int c = 0; c < dim; ++c)
                    Bc(alpha, 2 * nodes[a] + c) += edge_weights[a] * L * flux[c];
                }
            }
          element.add_cell_laplacian_term(alpha, -1., Bc);
        }
      const dealii::FullMatrix<double> &D = element.get_D();
      dealii::FullMatrix<double>        Gc(n_p, n_p), Pi_c(n_p, n), DPi(n, n);
      Bc.mmult(Gc, D);
      // (a cell far too thin for the scaled monomials makes G^c singular to
      // round-off: deal.II's gauss_jordan() checks its pivots only in Debug
      // builds, so the smallest pivot of partial-pivot elimination is
      // checked here, with deal.II's threshold, and the cell named)
      {
        dealii::FullMatrix<double> lu(Gc);
        double                     typical = 0;
        for (unsigned int i = 0; i < n_p; ++i)
          typical = std::max(typical, std::abs(lu(i, i)));
        bool regular = std::isfinite(typical) && typical > 0;
        for (unsigned int j = 0; j < n_p && regular; ++j)
          {
            unsigned int pivot = j;
            for (unsigned int i = j + 1; i < n_p; ++i)
              if (std::abs(lu(i, j)) > std::abs(lu(pivot, j)))
                pivot = i;
            if (!(std::abs(lu(pivot, j)) > 1e-16 * typical))
              regular = false;
            else
              {
                if (pivot != j)
                  for (unsigned int c = 0; c < n_p; ++c)
                    std::swap(lu(j, c), lu(pivot, c));
                for (unsigned int i = j + 1; i < n_p; ++i)
                  {
                    const double f = lu(i, j) / lu(j, j);
                    for (unsigned int c = j; c < n_p; ++c)
                      lu(i, c) -= f * lu(j, c);
                  }
              }
          }
        AssertThrow(regular,
                    dealii::ExcMessage("FiniteStrainOperator: the polygon with centroid " +
                                       [&] {
                                         std::ostringstream p;
                                         p << "(" << geometry.centroid() << ")";
                                         return p.str();
                                       }() +
                                       ", diameter " + std::to_string(geometry.diameter()) + " and area " +
                                       std::to_string(geometry.area()) +
                                       " is too thin for the virtual element's projector (its matrix is singular "
                                       "to round-off): refine the mesh across its long side, or check the "
                                       "mesh's coordinates."));
      }
      Gc.gauss_jordan();
      Gc.mmult(Pi_c, Bc);
      D.mmult(DPi, Pi_c);
      I_Pi.reinit(n, n);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          I_Pi(i, j) = (i == j ? 1. : 0.) - DPi(i, j);
    }
  } // namespace finite_strain_operator_projector



  template <int dim>
  void
  FiniteStrainOperator<dim>::projector_complement(const VirtualElement<dim> &element, dealii::FullMatrix<double> &I_Pi)
  {
    finite_strain_operator_projector::componentwise_projector_complement(element, I_Pi);
  }



  template <int dim>
  void
  FiniteStrainOperator<dim>::stabilization_base(const VirtualElement<dim>  &element,
                                                const Stabilization         rule,
                                                dealii::FullMatrix<double> &base)
  {
    dealii::FullMatrix<double> I_Pi;
    projector_complement(element, I_Pi);
    if (rule == Stabilization::diagonal)
      {
        base = I_Pi;
        return;
      }
    const unsigned int n = I_Pi.m();
    base.reinit(n, n);
    if (rule == Stabilization::boundary)
      {
        // the symmetric part of (I - Pi^c)^T S (I - Pi^c)
        dealii::FullMatrix<double> S, SI(n, n);
        ElasticityOperator<dim>::boundary_stabilization_form(element, S);
        S.mmult(SI, I_Pi);
        I_Pi.Tmmult(base, SI);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            base(i, j) = base(j, i) = 0.5 * (base(i, j) + base(j, i));
        return;
      }
    // trace (and automatic): (I - Pi^c)^T (I - Pi^c)
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j <= i; ++j)
        {
          double v = 0;
          for (unsigned int m = 0; m < n; ++m)
            v += I_Pi(m, i) * I_Pi(m, j);
          base(i, j) = base(j, i) = v;
        }
  }



  template <int dim>
  void
  FiniteStrainOperator<dim>::stabilization_scales(const dealii::Vector<double> &initial_diagonal,
                                                  const dealii::Vector<double> &current_diagonal,
                                                  const StabilizationScaling    scaling,
                                                  dealii::Vector<double>       &d)
  {
    const unsigned int n = initial_diagonal.size();
    d.reinit(n);
    if (scaling == StabilizationScaling::initial_tangent)
      {
        d = initial_diagonal;
        return;
      }
    AssertDimension(current_diagonal.size(), n);
    for (unsigned int i = 0; i < n; ++i)
      d[i] = std::max(current_diagonal[i], stabilization_floor * initial_diagonal[i]);
  }



  template <int dim>
  double
  FiniteStrainOperator<dim>::scaled_stabilization(const dealii::FullMatrix<double> &base,
                                                  const dealii::Vector<double>     &d,
                                                  const double                      gamma,
                                                  const Stabilization               rule,
                                                  const double                      c_k,
                                                  dealii::FullMatrix<double>       *K_s)
  {
    AssertThrow(gamma > 0 && std::isfinite(gamma),
                dealii::ExcMessage("The stabilization factor gamma must be positive, got " + std::to_string(gamma) +
                                   "."));
    const unsigned int n = d.size();
    AssertDimension(base.m(), n);
    AssertDimension(base.n(), n);
    // gamma tau = gamma tr(diag(d)) / n, ElasticityOperator::stabilization_scaling()'s rule
    double trace = 0;
    for (unsigned int i = 0; i < n; ++i)
      trace += d[i];
    const double gamma_tau = gamma * trace / n;
    if (K_s == nullptr)
      return gamma_tau;
    K_s->reinit(n, n);
    if (rule != Stabilization::diagonal)
      {
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            (*K_s)(i, j) = gamma_tau * base(i, j);
        return gamma_tau;
      }
    // (I - Pi^c)^T diag(gamma c_k max(d_i, 1e-3 tau)) (I - Pi^c)
    dealii::Vector<double> s(n);
    for (unsigned int i = 0; i < n; ++i)
      s[i] = gamma * c_k * std::max(d[i], 1e-3 * gamma_tau / gamma);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j <= i; ++j)
        {
          double v = 0;
          for (unsigned int m = 0; m < n; ++m)
            v += base(m, i) * s[m] * base(m, j);
          (*K_s)(i, j) = (*K_s)(j, i) = v;
        }
    return gamma_tau;
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
    AssertThrow(gamma > 0 && std::isfinite(gamma),
                dealii::ExcMessage("The stabilization factor gamma must be positive, got " + std::to_string(gamma) +
                                   "."));
    const unsigned int         n = n_dofs_cell;
    dealii::Vector<double>     zero(n), r, initial_diagonal(n), current_diagonal(n), d;
    dealii::FullMatrix<double> K;
    compute_consistency(law, zero, true, r, K);
    for (unsigned int i = 0; i < n; ++i)
      initial_diagonal[i] = K(i, i);
    if (scaling == StabilizationScaling::current_tangent)
      {
        compute_consistency(law, frozen_u, true, r, K);
        for (unsigned int i = 0; i < n; ++i)
          current_diagonal[i] = K(i, i);
      }
    stabilization_scales(initial_diagonal, current_diagonal, scaling, d);
    // the rules of ElasticityOperator on (I - Pi^c): trace,
    // gamma tau (I - Pi^c)^T (I - Pi^c), boundary, gamma tau times the
    // symmetric part of (I - Pi^c)^T S (I - Pi^c), or diagonal,
    // (I - Pi^c)^T diag(gamma c_k max(d_i, 1e-3 tau)) (I - Pi^c)
    const Stabilization        the_rule = (rule == Stabilization::automatic ? Stabilization::trace : rule);
    dealii::FullMatrix<double> base;
    stabilization_base(element, the_rule, base);
    scaled_stabilization(base, d, gamma, the_rule, element.get_stabilization_rules().diagonal_weight, &K_s);
  }



  template class FiniteStrainOperator<2>;
} // namespace dealvem
