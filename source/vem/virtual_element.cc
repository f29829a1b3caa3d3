// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>

#include <dealvem/vem/virtual_element.h>

#include <Eigen/Dense>

#include <atomic>
#include <cmath>
#include <limits>

namespace dealvem
{
  namespace
  {
    // Exponents (a, b) of the scaled monomials xi^a eta^b.
    constexpr unsigned int monomial_exponents[6][2] = {{0, 0}, {1, 0}, {0, 1},
                                                       {2, 0}, {1, 1}, {0, 2}};

    inline double
    ipow(const double x, const unsigned int n)
    {
      double r = 1;
      for (unsigned int i = 0; i < n; ++i)
        r *= x;
      return r;
    }

    // Value of monomial m at scaled point s.
    inline double
    monomial_value(const unsigned int m, const dealii::Point<2> &s)
    {
      return ipow(s[0], monomial_exponents[m][0]) * ipow(s[1], monomial_exponents[m][1]);
    }

    // Gradient with respect to the scaled coordinates.
    inline dealii::Tensor<1, 2>
    monomial_scaled_gradient(const unsigned int m, const dealii::Point<2> &s)
    {
      const unsigned int   a = monomial_exponents[m][0], b = monomial_exponents[m][1];
      dealii::Tensor<1, 2> g;
      if (a > 0)
        g[0] = a * ipow(s[0], a - 1) * ipow(s[1], b);
      if (b > 0)
        g[1] = b * ipow(s[0], a) * ipow(s[1], b - 1);
      return g;
    }

    // Hessian with respect to the scaled coordinates (constant for the
    // monomials used here, degree <= 2).
    inline dealii::Tensor<2, 2>
    monomial_scaled_hessian(const unsigned int m)
    {
      const unsigned int   a = monomial_exponents[m][0], b = monomial_exponents[m][1];
      dealii::Tensor<2, 2> H;
      if (a == 2)
        H[0][0] = 2;
      if (b == 2)
        H[1][1] = 2;
      if (a == 1 && b == 1)
        H[0][1] = H[1][0] = 1;
      return H;
    }

    // Index of the product of the monomials i, j in {1, xi, eta}, among
    // 1, xi, eta, xi^2, xi eta, eta^2.
    constexpr unsigned int monomial_product[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};

    // Row-major views of dealii::FullMatrix storage and of scratch buffers:
    // the Eigen products below write straight into the element's matrices.
    using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    using RowMap    = Eigen::Map<RowMatrix>;

    RowMap
    view(dealii::FullMatrix<double> &A)
    {
      return RowMap(&A(0, 0), A.m(), A.n());
    }

    RowMap
    view(std::vector<double> &buffer, const unsigned int rows, const unsigned int cols)
    {
      if (buffer.size() < std::size_t(rows) * cols)
        buffer.resize(std::size_t(rows) * cols);
      return RowMap(buffer.data(), rows, cols);
    }
  } // namespace



  template <int dim>
  struct VirtualElement<dim>::Workspace
  {
    Eigen::MatrixXd                   Gs; // equilibrated G
    Eigen::VectorXd                   row_scale, col_scale;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    std::vector<double>               rhs, q; // R B, I - D Pi_*
    std::vector<dealii::Point<dim>>   q_points;
    std::vector<double>               q_weights;
    dealii::Vector<double>            f_value, moments;
    // the polygon of the last full computation: vertices relative to the
    // first one
    std::vector<dealii::Tensor<1, dim>> shape;
    bool                                valid = false;
  };



  template <int dim>
  VirtualElement<dim>::~VirtualElement() = default;



  template <int dim>
  VirtualElement<dim>::VirtualElement(const unsigned int degree)
    : degree(degree)
    , data([](const unsigned int k) {
      AssertThrow(k >= 1 && k <= max_degree(),
                  dealii::ExcMessage("VirtualElement: the order k must lie in 1 to " + std::to_string(max_degree()) +
                                     ", got " + std::to_string(k) + "."));
      return k;
    }(degree))
    , n_vertices(0)
    , n_dofs(0)
    , geometry(std::make_unique<PolygonGeometry<dim>>())
    , workspace(std::make_unique<Workspace>())
  {
    // The vector polynomial basis, rigid-body modes first.
    const unsigned int n_p = n_polynomials();
    coef.resize(n_p);
    for (auto &c : coef)
      for (auto &comp : c)
        comp.fill(0.);
    coef[0][0][0] = 1;  // (1, 0)
    coef[1][1][0] = 1;  // (0, 1)
    coef[2][0][2] = -1; // (-eta, xi)
    coef[2][1][1] = 1;
    coef[3][0][1] = 1; // (xi, 0)
    coef[4][1][2] = 1; // (0, eta)
    coef[5][0][2] = 1; // (eta, xi)
    coef[5][1][1] = 1;
    if (degree == 2)
      for (unsigned int m = 0; m < 3; ++m)
        {
          coef[6 + m][0][3 + m] = 1; // (xi^2, 0), (xi eta, 0), (eta^2, 0)
          coef[9 + m][1][3 + m] = 1; // (0, xi^2), (0, xi eta), (0, eta^2)
        }
  }



  template <int dim>
  dealii::Tensor<1, dim>
  VirtualElement<dim>::polynomial_value(const unsigned int        alpha,
                                        const dealii::Point<dim> &p) const
  {
    const dealii::Point<dim> s = geometry->scaled(p);
    dealii::Tensor<1, dim>   v;
    for (unsigned int c = 0; c < 2; ++c)
      for (unsigned int m = 0; m < 6; ++m)
        if (coef[alpha][c][m] != 0.)
          v[c] += coef[alpha][c][m] * monomial_value(m, s);
    return v;
  }



  template <int dim>
  dealii::Tensor<2, dim>
  VirtualElement<dim>::polynomial_gradient(const unsigned int        alpha,
                                           const dealii::Point<dim> &p) const
  {
    const dealii::Point<dim> s = geometry->scaled(p);
    dealii::Tensor<2, dim>   g;
    for (unsigned int c = 0; c < 2; ++c)
      for (unsigned int m = 0; m < 6; ++m)
        if (coef[alpha][c][m] != 0.)
          g[c] += coef[alpha][c][m] * monomial_scaled_gradient(m, s);
    return g / geometry->diameter();
  }



  template <int dim>
  std::string
  VirtualElement<dim>::get_name() const
  {
    return "VEM<" + std::to_string(dim) + ">(" + std::to_string(degree) + ")";
  }



  template <int dim>
  dealii::Tensor<1, dim>
  VirtualElement<dim>::projected_shape_value(const unsigned int        i,
                                             const dealii::Point<dim> &p) const
  {
    AssertIndexRange(i, n_dofs);
    dealii::Tensor<1, dim> v;
    for (unsigned int a = 0; a < n_polynomials(); ++a)
      v += Pi_star(a, i) * polynomial_value(a, p);
    return v;
  }



  template <int dim>
  dealii::Tensor<2, dim>
  VirtualElement<dim>::projected_shape_grad(const unsigned int        i,
                                            const dealii::Point<dim> &p) const
  {
    AssertIndexRange(i, n_dofs);
    dealii::Tensor<2, dim> g;
    for (unsigned int a = 0; a < n_polynomials(); ++a)
      g += Pi_star(a, i) * polynomial_gradient(a, p);
    return g;
  }



  template <int dim>
  std::vector<unsigned int>
  VirtualElement<dim>::edge_nodes(const unsigned int edge) const
  {
    // the Gauss-Lobatto order: first vertex, edge nodes, second vertex
    std::vector<unsigned int> nodes(1, edge);
    for (unsigned int j = 0; j < data.nodes_per_edge(); ++j)
      nodes.push_back(data.edge_node(n_vertices, edge, j));
    nodes.push_back((edge + 1) % n_vertices);
    return nodes;
  }



  template <int dim>
  dealii::Point<dim>
  VirtualElement<dim>::node_location(const unsigned int j) const
  {
    if (j < n_vertices)
      return geometry->vertex(j);
    // (the element implements k = 1 and 2: at most one edge node, the midpoint)
    if (data.node_kind(n_vertices, j) == VEMElementData::NodeKind::edge)
      return geometry->edge_midpoint(j - n_vertices);
    return geometry->centroid();
  }



  template <int dim>
  void
  VirtualElement<dim>::reinit(const std::vector<dealii::Point<dim>> &vertices)
  {
    // Everything below writes into storage kept from the previous cell:
    // this function runs once per cell in every assembly loop. The steps
    // are those of the class documentation: geometry, D, B (rigid rows,
    // strain rows), G and Pi_*, the Gram matrices, the stabilization form,
    // the full-gradient projector.
    n_vertices = vertices.size();
    n_dofs     = n_dofs_per_cell(n_vertices);
    geometry->reinit(vertices);
    // Cell similarity: a translate of the last polygon keeps all matrices.
    reused = is_translate_of_last(vertices);
    if (reused)
      return;
    workspace->valid = false; // until the computation below has completed
    compute_monomial_integrals();
    compute_D();
    compute_B_rigid_rows();
    compute_B_strain_rows();
    compute_projector();
    compute_gram_matrices();
    compute_stabilization_form();
    compute_gradient_projector();
    // unique over all objects, so that a cache keyed on it cannot confuse
    // two spaces
    static std::atomic<std::uint64_t> counter{0};
    revision         = ++counter;
    workspace->valid = true;
  }



  template <int dim>
  bool
  VirtualElement<dim>::is_translate_of_last(const std::vector<dealii::Point<dim>> &vertices)
  {
    Workspace         &ws = *workspace;
    const unsigned int N  = n_vertices;
    bool               same = use_similarity && ws.valid && ws.shape.size() == N;
    if (same)
      {
        // The shape vectors carry the rounding of the coordinates: two
        // congruent cells at different places differ in them by a few
        // units in the last place of |x| (on [1, 2] with 281 cells along
        // a side, by up to 4.4e-16 against 1e-14 h = 5e-17), so that
        // away from the origin a test at 1e-14 h alone recomputed one cell
        // in seven of a structured mesh, and how often depended on where
        // the model sits. Shapes within that rounding are the same cell to
        // the precision of the data; the matrices of either differ by as
        // much as a recomputation from the rounded coordinates does.
        double x_max = 0;
        for (const auto &v : vertices)
          for (unsigned int d = 0; d < dim; ++d)
            x_max = std::max(x_max, std::abs(v[d]));
        const double tol  = 1e-14 * geometry->diameter() + 8 * std::numeric_limits<double>::epsilon() * x_max;
        const double tol2 = tol * tol;
        for (unsigned int i = 1; i < N && same; ++i)
          same = ((vertices[i] - vertices[0]) - ws.shape[i]).norm_square() <= tol2;
      }
    if (same)
      return true;
    ws.shape.resize(N);
    for (unsigned int i = 0; i < N; ++i)
      ws.shape[i] = vertices[i] - vertices[0];
    return false;
  }



  template <int dim>
  void
  VirtualElement<dim>::compute_monomial_integrals()
  {
    monomial_integrals.fill(0.);
    if (degree == 2)
      geometry->integrate_scaled_monomials(monomial_integrals);
    else
      monomial_integrals[0] = geometry->area();
  }



  template <int dim>
  void
  VirtualElement<dim>::compute_D()
  {
    const PolygonGeometry<dim> &geo = *geometry;
    const unsigned int          n_p = n_polynomials(), N = n_vertices;
    const double                area = geo.area();
    D.reinit(n_dofs, n_p);
    const unsigned int n_point_nodes = data.cell_node(N, 0);
    for (unsigned int j = 0; j < n_point_nodes; ++j)
      {
        const dealii::Point<dim> s = geo.scaled(node_location(j));
        double                   m[6];
        for (unsigned int i = 0; i < 6; ++i)
          m[i] = monomial_value(i, s);
        for (unsigned int alpha = 0; alpha < n_p; ++alpha)
          for (unsigned int c = 0; c < 2; ++c)
            {
              double v = 0;
              for (unsigned int i = 0; i < 6; ++i)
                v += coef[alpha][c][i] * m[i];
              D(2 * j + c, alpha) = v;
            }
      }
    // the cell moments (k = 2)
    if (degree == 2)
      for (unsigned int alpha = 0; alpha < n_p; ++alpha)
        for (unsigned int c = 0; c < 2; ++c)
          {
            double moment = 0;
            for (unsigned int m = 0; m < 6; ++m)
              moment += coef[alpha][c][m] * monomial_integrals[m];
            D(2 * data.cell_node(N, 0) + c, alpha) = moment / area;
          }
  }



  template <int dim>
  void
  VirtualElement<dim>::compute_B_rigid_rows()
  {
    const PolygonGeometry<dim> &geo = *geometry;
    const unsigned int          N   = n_vertices;
    const double                h = geo.diameter(), area = geo.area();
    B.reinit(n_polynomials(), n_dofs);
    // rows 0, 1: translations
    if (degree == 2)
      {
        B(0, 2 * data.cell_node(N, 0) + 0) = 1.;
        B(1, 2 * data.cell_node(N, 0) + 1) = 1.;
      }
    else
      for (unsigned int i = 0; i < N; ++i)
        {
          B(0, 2 * i + 0) = 1. / N;
          B(1, 2 * i + 1) = 1. / N;
        }
    // row 2: mean rotation h/(2|E|) int_dE v.t, by Gauss-Lobatto on the
    // edge nodes
    const std::vector<double> &lobatto      = data.edge_quadrature_weights();
    const unsigned int         n_edge_nodes = lobatto.size();
    for (unsigned int e = 0; e < N; ++e)
      {
        const auto         nodes = edge_node_triple(e);
        const auto        &t     = geo.edge_tangent(e);
        const double       L     = geo.edge_length(e);
        for (unsigned int q = 0; q < n_edge_nodes; ++q)
          {
            const double w = lobatto[q] * L;
            for (unsigned int c = 0; c < 2; ++c)
              B(2, 2 * nodes[q] + c) += h / (2. * area) * w * t[c];
          }
      }
  }



  template <int dim>
  void
  VirtualElement<dim>::compute_B_strain_rows()
  {
    const PolygonGeometry<dim> &geo = *geometry;
    const unsigned int          n_p = n_polynomials(), N = n_vertices;
    const double                h = geo.diameter(), area = geo.area();
    const std::vector<double>  &lobatto      = data.edge_quadrature_weights();
    const unsigned int          n_edge_nodes = lobatto.size();
    for (unsigned int e = 0; e < N; ++e)
      {
        const auto                   nodes = edge_node_triple(e);
        const dealii::Tensor<1, dim> n     = geo.edge_normal(e);
        const double                 L     = geo.edge_length(e);
        for (unsigned int q = 0; q < n_edge_nodes; ++q)
          {
            const unsigned int node = nodes[q];
            const double       w    = lobatto[q] * L;
            // int_E eps(p_alpha) : eps(phi_i)
            // = int_dE eps(p_alpha) n . phi_i (+ the cell term below), by
            // Gauss-Lobatto on the edge nodes
            const dealii::Point<dim> s = geo.scaled(node_location(node));
            double                   grad_m[6][2];
            for (unsigned int m = 0; m < 6; ++m)
              {
                const dealii::Tensor<1, 2> g = monomial_scaled_gradient(m, s);
                grad_m[m][0]                 = g[0] / h;
                grad_m[m][1]                 = g[1] / h;
              }
            for (unsigned int alpha = 3; alpha < n_p; ++alpha)
              {
                double grad[2][2] = {{0, 0}, {0, 0}};
                for (unsigned int c = 0; c < 2; ++c)
                  for (unsigned int m = 1; m < 6; ++m)
                    if (coef[alpha][c][m] != 0.)
                      {
                        grad[c][0] += coef[alpha][c][m] * grad_m[m][0];
                        grad[c][1] += coef[alpha][c][m] * grad_m[m][1];
                      }
                const double exy = 0.5 * (grad[0][1] + grad[1][0]);
                B(alpha, 2 * node) += w * (grad[0][0] * n[0] + exy * n[1]);
                B(alpha, 2 * node + 1) += w * (exy * n[0] + grad[1][1] * n[1]);
              }
          }
      }
    if (degree == 2)
      for (unsigned int alpha = 3; alpha < n_p; ++alpha)
        {
          // div eps(p) = (grad(div p) + Laplace(p)) / 2, constant
          dealii::Tensor<1, dim> grad_div, laplace;
          for (unsigned int c = 0; c < 2; ++c)
            for (unsigned int m = 3; m < 6; ++m)
              if (coef[alpha][c][m] != 0.)
                {
                  const dealii::Tensor<2, dim> H =
                    coef[alpha][c][m] * monomial_scaled_hessian(m) / (h * h);
                  laplace[c] += H[0][0] + H[1][1];
                  // div p = sum_c d_c p_c ; grad_j div p = sum_c H_c[c][j]
                  for (unsigned int j = 0; j < 2; ++j)
                    grad_div[j] += H[c][j];
                }
          const dealii::Tensor<1, dim> div_eps = 0.5 * (grad_div + laplace);
          for (unsigned int c = 0; c < 2; ++c)
            B(alpha, 2 * data.cell_node(N, 0) + c) -= area * div_eps[c];
        }
  }



  template <int dim>
  void
  VirtualElement<dim>::compute_projector()
  {
    Workspace         &ws  = *workspace;
    const unsigned int n_p = n_polynomials();
    // G = B D
    G.reinit(n_p, n_p);
    RowMap Dm = view(D), Bm = view(B), Gm = view(G);
    Gm.noalias() = Bm * Dm;

    // Pi_* = G^{-1} B. G is equilibrated by rows and columns before it is
    // factored: its rows (energies versus means) and columns (monomials of
    // different degree, tiny on elongated cells) have very different sizes.
    // Row scaling r leaves the solution unchanged; column scaling c gives
    // Pi_* = C (R G C)^{-1} R B.
    ws.row_scale.resize(n_p);
    ws.col_scale.resize(n_p);
    for (unsigned int a = 0; a < n_p; ++a)
      {
        const double s = Gm.row(a).cwiseAbs().maxCoeff();
        AssertThrow(s > 0 && std::isfinite(s),
                    dealii::ExcMessage("VirtualElement: degenerate polygon (zero row in G)."));
        ws.row_scale(a) = 1. / s;
      }
    ws.Gs = ws.row_scale.asDiagonal() * Gm;
    for (unsigned int b = 0; b < n_p; ++b)
      ws.col_scale(b) = 1. / ws.Gs.col(b).cwiseAbs().maxCoeff();
    ws.Gs.array().rowwise() *= ws.col_scale.transpose().array();
    ws.lu.compute(ws.Gs);
    RowMap RB = view(ws.rhs, n_p, n_dofs);
    RB        = ws.row_scale.asDiagonal() * Bm;
    Pi_star.reinit(n_p, n_dofs);
    RowMap Pm = view(Pi_star);
    Pm        = ws.lu.solve(RB);
    Pm.array().colwise() *= ws.col_scale.array();
  }



  template <int dim>
  void
  VirtualElement<dim>::compute_gram_matrices()
  {
    const unsigned int n_p = n_polynomials();
    const double       h   = geometry->diameter();
    // E: the (symmetrized) strain block of G, which is int eps(p_alpha) :
    // eps(p_beta) because the boundary rule of B is exact on polynomials.
    // T: int div p_alpha div p_beta from the exact monomial integrals (div p
    // has degree k - 1, so the products have degree <= 2).
    E_gram.reinit(n_p, n_p);
    T_gram.reinit(n_p, n_p);
    for (unsigned int a = 3; a < n_p; ++a)
      for (unsigned int b = 3; b < n_p; ++b)
        E_gram(a, b) = 0.5 * (G(a, b) + G(b, a));
    // div p_alpha = sum_m d[alpha][m] * (1, xi, eta)_m, in physical units
    double d[12][3];
    for (unsigned int a = 0; a < n_p; ++a)
      {
        // d/dxi of component 0 plus d/deta of component 1, divided by h
        const auto &cx = coef[a][0], &cy = coef[a][1];
        d[a][0]        = (cx[1] + cy[2]) / h;
        d[a][1]        = (2. * cx[3] + cy[4]) / h;
        d[a][2]        = (cx[4] + 2. * cy[5]) / h;
      }
    for (unsigned int a = 3; a < n_p; ++a)
      for (unsigned int b = 3; b < n_p; ++b)
        {
          double v = 0;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              if (d[a][i] != 0. && d[b][j] != 0.)
                v += d[a][i] * d[b][j] * monomial_integrals[monomial_product[i][j]];
          T_gram(a, b) = v;
        }
    // M: int q_m q_n for the scaled monomials of degree <= k - 1
    const unsigned int n_m = n_gradient_monomials();
    M_gram.reinit(n_m, n_m);
    for (unsigned int m = 0; m < n_m; ++m)
      for (unsigned int n = 0; n < n_m; ++n)
        M_gram(m, n) = monomial_integrals[monomial_product[m][n]];
  }



  template <int dim>
  void
  VirtualElement<dim>::compute_stabilization_form()
  {
    // S = (I - D Pi_*)^T (I - D Pi_*), by a rank update of the lower
    // triangle, then mirrored
    Workspace &ws = *workspace;
    RowMap     Dm = view(D), Pm = view(Pi_star);
    RowMap     Q  = view(ws.q, n_dofs, n_dofs);
    Q.noalias()   = -Dm * Pm;
    Q.diagonal().array() += 1.;
    S.reinit(n_dofs, n_dofs);
    RowMap Sm = view(S);
    Sm.selfadjointView<Eigen::Lower>().rankUpdate(Q.transpose(), 1.);
    for (unsigned int i = 0; i < n_dofs; ++i)
      for (unsigned int j = 0; j < i; ++j)
        S(j, i) = S(i, j);
  }



  template <int dim>
  void
  VirtualElement<dim>::compute_gradient_projector()
  {
    const PolygonGeometry<dim> &geo = *geometry;
    const unsigned int          N = n_vertices, n_m = n_gradient_monomials();
    const double                h = geo.diameter(), area = geo.area();
    // The right-hand side int_E d_j v_c q_m = int_dE v_c n_j q_m
    // - int_E v_c d_j q_m in the rows (2c + j) n_m + m: the edge integrals
    // by Gauss-Lobatto on the edge nodes (exact, degree <= 2k - 1) ...
    Pi_grad.reinit(4 * n_m, n_dofs);
    const std::vector<double> &lobatto      = data.edge_quadrature_weights();
    const unsigned int         n_edge_nodes = lobatto.size();
    for (unsigned int e = 0; e < N; ++e)
      {
        const auto                   nodes = edge_node_triple(e);
        const dealii::Tensor<1, dim> n     = geo.edge_normal(e);
        const double                 L     = geo.edge_length(e);
        for (unsigned int q = 0; q < n_edge_nodes; ++q)
          {
            const unsigned int       node = nodes[q];
            const dealii::Point<dim> s    = geo.scaled(node_location(node));
            for (unsigned int m = 0; m < n_m; ++m)
              {
                const double wq = lobatto[q] * L * monomial_value(m, s);
                for (unsigned int c = 0; c < 2; ++c)
                  for (unsigned int j = 0; j < 2; ++j)
                    Pi_grad((2 * c + j) * n_m + m, 2 * node + c) += wq * n[j];
              }
          }
      }
    // ... and for k = 2 the cell term: d xi / dx = d eta / dy = 1 / h, and
    // int_E v_c = |E| times the cell-moment DoF
    if (degree == 2)
      for (unsigned int c = 0; c < 2; ++c)
        {
          Pi_grad((2 * c + 0) * n_m + 1, 2 * data.cell_node(N, 0) + c) -= area / h;
          Pi_grad((2 * c + 1) * n_m + 2, 2 * data.cell_node(N, 0) + c) -= area / h;
        }
    // the coefficients: M^{-1} times each block of n_m rows
    Eigen::Matrix3d M = Eigen::Matrix3d::Identity();
    for (unsigned int m = 0; m < n_m; ++m)
      for (unsigned int k = 0; k < n_m; ++k)
        M(m, k) = M_gram(m, k);
    const Eigen::Matrix3d M_inv = M.inverse();
    double                column[3];
    for (unsigned int block = 0; block < 4; ++block)
      for (unsigned int i = 0; i < n_dofs; ++i)
        {
          for (unsigned int m = 0; m < n_m; ++m)
            {
              column[m] = 0;
              for (unsigned int k = 0; k < n_m; ++k)
                column[m] += M_inv(m, k) * Pi_grad(block * n_m + k, i);
            }
          for (unsigned int m = 0; m < n_m; ++m)
            Pi_grad(block * n_m + m, i) = column[m];
        }
  }



  template <int dim>
  const typename VirtualElement<dim>::StabilizationRules &
  VirtualElement<dim>::stabilization_rules(const unsigned int degree)
  {
    // one entry per order, 1 to max_degree()
    static const StabilizationRules rules[] = {{true, 1., 2.}, {false, 0.2, 5.}};
    static_assert(sizeof(rules) / sizeof(rules[0]) == max_degree(), "one entry of rules per order");
    AssertThrow(degree >= 1 && degree <= max_degree(),
                dealii::ExcMessage("VirtualElement: no stabilization rules for the order " + std::to_string(degree) +
                                   " (1 to " + std::to_string(max_degree()) + ")."));
    return rules[degree - 1];
  }



  template <int dim>
  void
  VirtualElement<dim>::add_cell_laplacian_term(const unsigned int          alpha,
                                               const double                factor,
                                               dealii::FullMatrix<double> &B_out) const
  {
    AssertIndexRange(alpha, n_polynomials());
    AssertDimension(B_out.n(), n_dofs);
    if (data.nodes_per_cell() == 0)
      return; // k = 1: p is linear
    // k = 2: the Laplacian is constant and int_E phi_j is |E| times the
    // cell-mean DoF
    const double h = geometry->diameter();
    for (unsigned int c = 0; c < 2; ++c)
      {
        double laplacian = 0;
        for (unsigned int m = 3; m < 6; ++m)
          if (coef[alpha][c][m] != 0.)
            {
              const dealii::Tensor<2, 2> H = monomial_scaled_hessian(m);
              laplacian += coef[alpha][c][m] * (H[0][0] + H[1][1]) / (h * h);
            }
        B_out(alpha, 2 * data.cell_node(n_vertices, 0) + c) += factor * geometry->area() * laplacian;
      }
  }



  template <int dim>
  void
  VirtualElement<dim>::set_cell_similarity(const bool enable)
  {
    use_similarity = enable;
    workspace->valid = false;
  }



  template <int dim>
  dealii::FullMatrix<double>
  VirtualElement<dim>::get_projector_dof_basis() const
  {
    dealii::FullMatrix<double> P(n_dofs, n_dofs);
    D.mmult(P, Pi_star);
    return P;
  }



  template <int dim>
  void
  VirtualElement<dim>::interpolate(const dealii::Function<dim> &f,
                                   dealii::Vector<double>      &local) const
  {
    AssertDimension(f.n_components, 2);
    local.reinit(n_dofs);
    const unsigned int n_point_nodes = data.cell_node(n_vertices, 0);
    for (unsigned int j = 0; j < n_point_nodes; ++j)
      {
        const dealii::Point<dim> x = node_location(j);
        local[2 * j]               = f.value(x, 0);
        local[2 * j + 1]           = f.value(x, 1);
      }
    if (degree == 2)
      {
        const dealii::Quadrature<dim> q = geometry->quadrature(8);
        double                        m0 = 0, m1 = 0;
        for (unsigned int k = 0; k < q.size(); ++k)
          {
            m0 += q.weight(k) * f.value(q.point(k), 0);
            m1 += q.weight(k) * f.value(q.point(k), 1);
          }
        local[2 * data.cell_node(n_vertices, 0)]     = m0 / geometry->area();
        local[2 * data.cell_node(n_vertices, 0) + 1] = m1 / geometry->area();
      }
  }



  template <int dim>
  void
  VirtualElement<dim>::project(const dealii::Vector<double> &local,
                               dealii::Vector<double>       &coefficients) const
  {
    AssertDimension(local.size(), n_dofs);
    coefficients.reinit(n_polynomials());
    Pi_star.vmult(coefficients, local);
  }



  template <int dim>
  dealii::Tensor<1, dim>
  VirtualElement<dim>::projection_value(const dealii::Vector<double> &c,
                                        const dealii::Point<dim>     &p) const
  {
    dealii::Tensor<1, dim> v;
    for (unsigned int a = 0; a < n_polynomials(); ++a)
      v += c[a] * polynomial_value(a, p);
    return v;
  }



  template <int dim>
  dealii::Tensor<2, dim>
  VirtualElement<dim>::projection_gradient(const dealii::Vector<double> &c,
                                           const dealii::Point<dim>     &p) const
  {
    dealii::Tensor<2, dim> g;
    for (unsigned int a = 0; a < n_polynomials(); ++a)
      g += c[a] * polynomial_gradient(a, p);
    return g;
  }



  template <int dim>
  dealii::SymmetricTensor<2, dim>
  VirtualElement<dim>::projection_strain(const dealii::Vector<double> &c,
                                         const dealii::Point<dim>     &p) const
  {
    return dealii::symmetrize(projection_gradient(c, p));
  }



  template <int dim>
  void
  VirtualElement<dim>::project_gradient(const dealii::Vector<double> &local,
                                        dealii::Vector<double>       &coefficients) const
  {
    AssertDimension(local.size(), n_dofs);
    coefficients.reinit(Pi_grad.m());
    Pi_grad.vmult(coefficients, local);
  }



  template <int dim>
  dealii::Tensor<2, dim>
  VirtualElement<dim>::gradient_projection_value(const dealii::Vector<double> &c,
                                                 const dealii::Point<dim>     &p) const
  {
    const unsigned int n_m = n_gradient_monomials();
    AssertDimension(c.size(), 4 * n_m);
    const dealii::Point<dim> s = geometry->scaled(p);
    dealii::Tensor<2, dim>   g;
    for (unsigned int m = 0; m < n_m; ++m)
      {
        const double q = monomial_value(m, s);
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int j = 0; j < 2; ++j)
            g[a][j] += c[(2 * a + j) * n_m + m] * q;
      }
    return g;
  }



  template <int dim>
  dealii::Tensor<2, dim>
  VirtualElement<dim>::shape_gradient_projection(const unsigned int i, const dealii::Point<dim> &p) const
  {
    AssertIndexRange(i, n_dofs);
    const unsigned int       n_m = n_gradient_monomials();
    const dealii::Point<dim> s   = geometry->scaled(p);
    dealii::Tensor<2, dim>   g;
    for (unsigned int m = 0; m < n_m; ++m)
      {
        const double q = monomial_value(m, s);
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int j = 0; j < 2; ++j)
            g[a][j] += Pi_grad((2 * a + j) * n_m + m, i) * q;
      }
    return g;
  }



  template <int dim>
  void
  VirtualElement<dim>::polynomial_gradient_coefficients(const unsigned int                   alpha,
                                                        std::vector<dealii::Tensor<2, dim>> &G) const
  {
    AssertIndexRange(alpha, n_polynomials());
    // d(monomial)/d(xi_j) in the monomials 1, xi, eta: entries
    // {monomial, direction j, target monomial, factor}
    struct Term
    {
      unsigned int monomial, j, target;
      double       factor;
    };
    static constexpr Term terms[] = {{1, 0, 0, 1.}, {2, 1, 0, 1.}, {3, 0, 1, 2.},
                                     {4, 0, 2, 1.}, {4, 1, 1, 1.}, {5, 1, 2, 2.}};
    const double h = geometry->diameter();
    G.assign(n_gradient_monomials(), dealii::Tensor<2, dim>());
    for (unsigned int c = 0; c < 2; ++c)
      for (const Term &t : terms)
        if (coef[alpha][c][t.monomial] != 0.)
          {
            Assert(t.target < G.size(), dealii::ExcInternalError());
            G[t.target][c][t.j] += coef[alpha][c][t.monomial] * t.factor / h;
          }
  }



  template <int dim>
  void
  VirtualElement<dim>::body_force_vector(const dealii::Function<dim> &f,
                                         dealii::Vector<double>      &F,
                                         const unsigned int           extra_degree) const
  {
    AssertDimension(f.n_components, 2);
    Workspace &ws = *workspace;
    geometry->quadrature(degree + extra_degree, ws.q_points, ws.q_weights);
    dealii::Vector<double> &moments = ws.moments;
    dealii::Vector<double> &fv      = ws.f_value;
    moments.reinit(n_polynomials());
    fv.reinit(2);
    // integrals of f_c times each monomial, then combined per polynomial
    double fm[2][6] = {{0, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 0}};
    for (unsigned int k = 0; k < ws.q_points.size(); ++k)
      {
        f.vector_value(ws.q_points[k], fv);
        const dealii::Point<dim> s = geometry->scaled(ws.q_points[k]);
        for (unsigned int i = 0; i < 6; ++i)
          {
            const double m = ws.q_weights[k] * monomial_value(i, s);
            fm[0][i] += fv[0] * m;
            fm[1][i] += fv[1] * m;
          }
      }
    for (unsigned int a = 0; a < n_polynomials(); ++a)
      for (unsigned int c = 0; c < 2; ++c)
        for (unsigned int i = 0; i < 6; ++i)
          moments[a] += coef[a][c][i] * fm[c][i];
    F.reinit(n_dofs);
    Pi_star.Tvmult(F, moments);
  }



  template <int dim>
  void
  VirtualElement<dim>::body_force_moment_map(dealii::FullMatrix<double> &W) const
  {
    // F = Pi_*^T m, m_a = sum_c sum_m coef[a][c][m] mu_cm (body_force_vector())
    W.reinit(n_dofs, 12);
    for (unsigned int i = 0; i < n_dofs; ++i)
      for (unsigned int a = 0; a < n_polynomials(); ++a)
        for (unsigned int c = 0; c < 2; ++c)
          for (unsigned int m = 0; m < 6; ++m)
            W(i, 6 * c + m) += Pi_star(a, i) * coef[a][c][m];
  }



  template class VirtualElement<2>;
} // namespace dealvem
