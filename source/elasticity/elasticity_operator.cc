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

    // Whether the tangent C has exactly the isotropic form lambda I x I +
    // 2 mu II; then lambda and mu are set to C_0011 and C_0101.
    bool
    is_isotropic(const dealii::SymmetricTensor<4, 2> &C, double &lambda, double &mu)
    {
      lambda = C[0][0][1][1];
      mu     = C[0][1][0][1];
      return C[1][1][0][0] == lambda && C[0][0][0][0] == lambda + 2. * mu && C[1][1][1][1] == lambda + 2. * mu &&
             C[0][0][0][1] == 0. && C[1][1][0][1] == 0. && C[0][1][0][0] == 0. && C[0][1][1][1] == 0.;
    }

    // The tangent as a symmetric 3 x 3 matrix in the orthonormal basis
    // e_x e_x, e_y e_y, (e_x e_y + e_y e_x) / sqrt(2) of the symmetric
    // tensors (Mandel's form): its symmetry is the major symmetry of C, its
    // definiteness that of the strain energy.
    void
    check_tangent(const dealii::SymmetricTensor<4, 2> &C, const std::string &name)
    {
      constexpr unsigned int idx[3][2] = {{0, 0}, {1, 1}, {0, 1}};
      const double           f[3]      = {1., 1., std::sqrt(2.)};
      Eigen::Matrix3d        K;
      for (unsigned int I = 0; I < 3; ++I)
        for (unsigned int J = 0; J < 3; ++J)
          K(I, J) = f[I] * f[J] * C[idx[I][0]][idx[I][1]][idx[J][0]][idx[J][1]];
      const double scale = K.cwiseAbs().maxCoeff();
      AssertThrow(std::isfinite(scale) && scale > 0,
                  dealii::ExcMessage("ElasticityOperator: the tangent of the constitutive law '" + name +
                                     "' is zero or not finite."));
      const double asymmetry = (K - K.transpose()).cwiseAbs().maxCoeff();
      AssertThrow(asymmetry <= 1e-12 * scale,
                  dealii::ExcMessage("ElasticityOperator: the tangent of the constitutive law '" + name +
                                     "' lacks the major symmetry C_ijkl = C_klij (relative asymmetry " +
                                     std::to_string(asymmetry / scale) +
                                     "); a law with a strain energy has it, and the stiffness matrix needs it."));
      const Eigen::Vector3d eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(
                                            0.5 * (K + K.transpose()), Eigen::EigenvaluesOnly)
                                            .eigenvalues();
      AssertThrow(eigenvalues(0) > 1e-12 * scale,
                  dealii::ExcMessage("ElasticityOperator: the tangent of the constitutive law '" + name +
                                     "' is not positive definite (smallest eigenvalue " +
                                     std::to_string(eigenvalues(0) / scale) +
                                     " of its largest entry): the strain energy must be positive for every "
                                     "strain."));
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
  ElasticityOperator<dim>::boundary_stabilization_form(const VirtualElement<dim> &element,
                                                       dealii::FullMatrix<double> &S)
  {
    const PolygonGeometry<dim> &geometry = element.get_geometry();
    const unsigned int          n = element.n_dofs_per_cell(), N = geometry.n_vertices();
    S.reinit(n, n);
    double perimeter = 0;
    for (unsigned int e = 0; e < N; ++e)
      perimeter += geometry.edge_length(e);
    const double mean_length = perimeter / N;
    // the stiffness of d/ds on an edge of unit length, in the order of
    // VirtualElement::edge_nodes() (first vertex, edge nodes, second vertex)
    const std::vector<double> &edge_stiffness = element.get_element_data().edge_stiffness();
    const double               divisor        = element.get_stabilization_rules().boundary_edge_divisor;
    for (unsigned int e = 0; e < N; ++e)
      {
        const std::vector<unsigned int> nodes = element.edge_nodes(e);
        const unsigned int              n_e   = nodes.size();
        const double                    w     = std::min(mean_length / geometry.edge_length(e), 1e3) / divisor;
        for (unsigned int a = 0; a < n_e; ++a)
          for (unsigned int b = 0; b < n_e; ++b)
            {
              const double v = w * edge_stiffness[a * n_e + b];
              for (unsigned int c = 0; c < 2; ++c)
                S(2 * nodes[a] + c, 2 * nodes[b] + c) += v;
            }
      }
    // the cell moments enter with unit weight
    const VEMElementData &layout = element.get_element_data();
    for (unsigned int j = 0; j < layout.nodes_per_cell(); ++j)
      for (unsigned int c = 0; c < 2; ++c)
        S(2 * layout.cell_node(N, j) + c, 2 * layout.cell_node(N, j) + c) = 1.;
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
        (stabilization == Stabilization::automatic && element.get_stabilization_rules().automatic_is_trace))
      {
        K.add(gamma * tau, element.get_stabilization_form());
        return;
      }
    if (stabilization == Stabilization::boundary)
      {
        dealii::FullMatrix<double> S;
        boundary_stabilization_form(element, S);
        RowMatrix I_Pi = -view(element.get_projector_dof_basis());
        for (unsigned int i = 0; i < n; ++i)
          I_Pi(i, i) += 1.;
        const RowMatrix Ks = I_Pi.transpose() * view(S) * I_Pi;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            K(i, j) += gamma * tau * 0.5 * (Ks(i, j) + Ks(j, i));
        return;
      }
    // (I - Pi)^T diag(d) (I - Pi), d the same for the two components of a
    // node (DoFs 2a, 2a + 1): c_k max(K_aa, 1e-3 tau) with K_aa half the
    // trace of the node's 2 x 2 diagonal block. The block turns with the
    // frame (R K_aa R^T), its trace does not; the single entries K_ii of
    // the x and y components do, so weighting them one by one made the
    // solution depend on the orientation of the model (exact only under
    // turns by multiples of 90 degrees, which swap x and y).
    const double c_k   = element.get_stabilization_rules().diagonal_weight;
    RowMatrix    I_Pi  = -view(element.get_projector_dof_basis());
    Eigen::VectorXd d(n);
    AssertThrow(n % 2 == 0, dealii::ExcInternalError());
    for (unsigned int i = 0; i < n; ++i)
      I_Pi(i, i) += 1.;
    for (unsigned int a = 0; a < n; a += 2)
      d(a) = d(a + 1) = gamma * c_k * std::max(0.5 * (K(a, a) + K(a + 1, a + 1)), 1e-3 * tau);
    const RowMatrix Ks = I_Pi.transpose() * d.asDiagonal() * I_Pi;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        K(i, j) += 0.5 * (Ks(i, j) + Ks(j, i));
  }



  template <int dim>
  void
  ElasticityOperator<dim>::reinit(const VirtualElement<dim>  &element,
                                  const ConstitutiveLaw<dim> &law,
                                  const double                gamma_in,
                                  const Stabilization         stabilization)
  {
    AssertThrow(gamma_in > 0 && std::isfinite(gamma_in),
                dealii::ExcMessage("The stabilization factor gamma must be positive, got " +
                                   std::to_string(gamma_in) + "."));
    AssertThrow(law.is_linear(),
                dealii::ExcMessage("ElasticityOperator: the constitutive law '" + law.get_name() +
                                   "' is not linear (its tangent depends on the strain). The operator builds "
                                   "the stiffness of a linear law from its tangent; a non-linear law needs a "
                                   "Newton iteration on its tangent at the current strain, which does not "
                                   "exist yet."));
    const dealii::SymmetricTensor<4, dim> C = law.tangent(dealii::SymmetricTensor<2, dim>());
    bool same_tangent = true;
    for (unsigned int i = 0; i < tangent.size(); ++i)
      same_tangent = same_tangent && C.access_raw_entry(i) == tangent[i];
    reused = valid && revision == element.matrices_revision() && same_tangent && gamma == gamma_in &&
             rule == stabilization;
    if (reused)
      return;
    if (!same_tangent || !valid)
      check_tangent(C, law.get_name());
    valid    = false;
    revision = element.matrices_revision();
    for (unsigned int i = 0; i < tangent.size(); ++i)
      tangent[i] = C.access_raw_entry(i);
    gamma = gamma_in;
    rule  = stabilization;

    const unsigned int n_s = element.n_polynomials() - 3;
    const unsigned int n   = element.n_dofs_per_cell();
    compute_strain_mode_form(element, C);
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



  template <int dim>
  void
  ElasticityOperator<dim>::compute_strain_mode_form(const VirtualElement<dim>             &element,
                                                    const dealii::SymmetricTensor<4, dim> &C)
  {
    const unsigned int n_p = element.n_polynomials(), n_s = n_p - 3;
    A.reinit(n_s, n_s);
    double l = 0, m = 0;
    if (is_isotropic(C, l, m))
      {
        // lambda T + 2 mu E (the rigid modes are in the kernel of both Gram
        // matrices)
        const auto &T = element.get_divergence_gram(), &E = element.get_strain_gram();
        for (unsigned int a = 0; a < n_s; ++a)
          for (unsigned int b = 0; b < n_s; ++b)
            A(a, b) = l * T(a + 3, b + 3) + 2. * m * E(a + 3, b + 3);
        return;
      }
    // A_ab = sum_{m,n} M_mn eps_{a,m} : C : eps_{b,n}, with eps(p_a) =
    // sum_m eps_{a,m} q_m in the scaled monomials q_m of degree k - 1
    const unsigned int n_m = element.n_gradient_monomials();
    const auto        &M   = element.get_monomial_gram();
    std::vector<dealii::Tensor<2, dim>>               G;
    std::vector<std::vector<dealii::SymmetricTensor<2, dim>>> eps(n_s), stress(n_s);
    for (unsigned int a = 0; a < n_s; ++a)
      {
        element.polynomial_gradient_coefficients(a + 3, G);
        eps[a].resize(n_m);
        stress[a].resize(n_m);
        for (unsigned int k = 0; k < n_m; ++k)
          {
            eps[a][k]    = dealii::symmetrize(G[k]);
            stress[a][k] = C * eps[a][k];
          }
      }
    for (unsigned int a = 0; a < n_s; ++a)
      for (unsigned int b = 0; b < n_s; ++b)
        {
          double v = 0;
          for (unsigned int i = 0; i < n_m; ++i)
            for (unsigned int j = 0; j < n_m; ++j)
              v += M(i, j) * (stress[a][i] * eps[b][j]);
          A(a, b) = v;
        }
  }

  template class ElasticityOperator<2>;
} // namespace dealvem
