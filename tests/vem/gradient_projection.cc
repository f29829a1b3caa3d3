// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The full-gradient projector Pi^0 grad of VirtualElement (and its
// evaluation through VEMValues), k = 1 and 2, on convex, non-convex,
// Voronoi, elongated and hanging-vertex (collinear vertices) polygons:
// (a) for u in [P_k]^2, interpolated into the DoFs, Pi^0 grad u = grad u at
//     arbitrary points (vertices, centroid, points outside), relative to
//     max |grad u|: 1e-12 (1e-9 on the 1:100 cell, whose monomial Gram
//     matrix has a condition number of 1e4); the same through the
//     shape functions and through VEMValues at the quadrature points;
// (b) for a non-polynomial u (sin, exp), the symmetric part of Pi^0 grad u_h
//     equals the strain of the elliptic projection, eps(Pi u_h), which the
//     operator uses, to 1e-12 relative; and Pi^0 grad is the L2 projection:
//     on axis-parallel polygons (non-convex, with a collinear vertex), a u
//     whose traces on axis-parallel edges have degree k (x y for k = 1,
//     x^2 y^2 for k = 2: not in [P_k]^2) has the interpolant with the same
//     boundary traces and cell moments, so Pi^0 grad I_h u must equal the L2
//     projection of grad u onto P_{k-1} computed by quadrature, 1e-12
//     relative (and differ from grad u by far more: the check has teeth);
// (c) for an infinitesimal rotation theta (-(y-y0), x-x0) plus a
//     translation, Pi^0 grad u = theta [[0,-1],[1,0]]: antisymmetric part
//     the rotation, symmetric part zero, to 1e-12 (1:100 cell: 1e-9) of
//     the data's scale max |u_i| / h (the translation makes the DoF values
//     O(1) while theta = 1e-3; the k = 2 projection subtracts the cell
//     moment term from the edge terms, so its round-off follows |u| / h).
#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/full_matrix.h>

#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/vem_values.h>
#include <dealvem/vem/virtual_element.h>

#include <cmath>
#include <random>

#include "../tests.h"

using namespace dealvem;
using P = dealii::Point<2>;

// A vector polynomial of degree k with random coefficients in the
// physical coordinates (about the point x0, so the monomials are not
// centred on the polygon).
class PolynomialField : public dealii::Function<2>
{
public:
  PolynomialField(const unsigned int k, const unsigned int seed, const P x0)
    : dealii::Function<2>(2)
    , x0(x0)
  {
    std::mt19937                           rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    for (auto &comp : a)
      for (unsigned int m = 0; m < 6; ++m)
        comp[m] = (m < 3 || k == 2) ? u(rng) : 0.;
  }
  double
  value(const P &p, const unsigned int c) const override
  {
    const double x = p[0] - x0[0], y = p[1] - x0[1];
    const auto  &b = a[c];
    return b[0] + b[1] * x + b[2] * y + b[3] * x * x + b[4] * x * y + b[5] * y * y;
  }
  dealii::Tensor<2, 2>
  gradient_of(const P &p) const
  {
    const double         x = p[0] - x0[0], y = p[1] - x0[1];
    dealii::Tensor<2, 2> g;
    for (unsigned int c = 0; c < 2; ++c)
      {
        const auto &b = a[c];
        g[c][0]       = b[1] + 2 * b[3] * x + b[4] * y;
        g[c][1]       = b[2] + b[4] * x + 2 * b[5] * y;
      }
    return g;
  }

private:
  P                                    x0;
  std::array<std::array<double, 6>, 2> a;
};

// smooth, non-polynomial
class SmoothField : public dealii::Function<2>
{
public:
  SmoothField()
    : dealii::Function<2>(2)
  {}
  double
  value(const P &p, const unsigned int c) const override
  {
    const double x = p[0], y = p[1];
    return c == 0 ? std::sin(1.3 * x + 2.1 * y) * std::exp(0.4 * y) : std::cos(0.7 * x * y) + std::exp(-x);
  }
};

// u with traces of degree k on axis-parallel edges, not in [P_k]^2
class AxisTraceField : public dealii::Function<2>
{
public:
  explicit AxisTraceField(const unsigned int k)
    : dealii::Function<2>(2)
    , k(k)
  {}
  double
  value(const P &p, const unsigned int c) const override
  {
    const double x = p[0], y = p[1];
    if (k == 1)
      return c == 0 ? x * y + 0.5 * x : 2 * x * y - y;
    return c == 0 ? x * x * y * y : x * x * y - 3 * x * y * y;
  }
  dealii::Tensor<2, 2>
  gradient_of(const P &p) const
  {
    const double         x = p[0], y = p[1];
    dealii::Tensor<2, 2> g;
    if (k == 1)
      {
        g[0][0] = y + 0.5;
        g[0][1] = x;
        g[1][0] = 2 * y;
        g[1][1] = 2 * x - 1;
      }
    else
      {
        g[0][0] = 2 * x * y * y;
        g[0][1] = 2 * x * x * y;
        g[1][0] = 2 * x * y - 3 * y * y;
        g[1][1] = x * x - 6 * x * y;
      }
    return g;
  }

private:
  unsigned int k;
};

// infinitesimal rotation about x0 plus a translation
class Rotation : public dealii::Function<2>
{
public:
  Rotation(const double theta, const P x0)
    : dealii::Function<2>(2)
    , theta(theta)
    , x0(x0)
  {}
  double
  value(const P &p, const unsigned int c) const override
  {
    return c == 0 ? 0.3 - theta * (p[1] - x0[1]) : -0.7 + theta * (p[0] - x0[0]);
  }
  double theta;
  P      x0;
};

std::vector<P>
translated(const std::vector<P> &v, const P shift)
{
  std::vector<P> r;
  for (const auto &p : v)
    r.emplace_back(p[0] + shift[0], p[1] + shift[1]);
  return r;
}

// the points where the projections are compared: the vertices, the
// centroid and two points outside the polygon
std::vector<P>
test_points(const VirtualElement<2> &element)
{
  const auto    &geo = element.get_geometry();
  std::vector<P> points;
  for (unsigned int i = 0; i < geo.n_vertices(); ++i)
    points.push_back(geo.vertex(i));
  const double h = geo.diameter();
  points.push_back(geo.centroid());
  points.push_back(geo.centroid() + dealii::Tensor<1, 2>({0.9 * h, -0.4 * h}));
  points.push_back(geo.centroid() + dealii::Tensor<1, 2>({-0.3 * h, 1.1 * h}));
  return points;
}

void
check_polygon(const std::string &name, const std::vector<P> &vertices, const double tolerance = 1e-12)
{
  for (const unsigned int k : {1u, 2u})
    {
      const std::string tag = name + " k=" + std::to_string(k) + ": ";
      VirtualElement<2> element(k);
      element.reinit(vertices);
      const unsigned int n = element.n_dofs_per_cell();
      const auto        &Pg = element.get_gradient_projector();
      testing::check(Pg.m() == 4 * element.n_gradient_monomials() && Pg.n() == n,
                     tag + "the gradient projector is 4 n_m x n_dofs");
      dealii::Vector<double> local, coefficients, projection;

      // (a) exact on [P_k]^2, through the coefficients and the shape functions
      double err_a = 0, err_shape = 0;
      for (const unsigned int seed : {1u, 2u, 3u})
        {
          const PolynomialField u(k, seed, P(0.37, -0.81));
          element.interpolate(u, local);
          element.project_gradient(local, coefficients);
          double gmax = 0;
          for (const P &x : test_points(element))
            gmax = std::max(gmax, u.gradient_of(x).norm());
          for (const P &x : test_points(element))
            {
              const dealii::Tensor<2, 2> g = element.gradient_projection_value(coefficients, x);
              dealii::Tensor<2, 2>       gs;
              for (unsigned int i = 0; i < n; ++i)
                gs += local[i] * element.shape_gradient_projection(i, x);
              err_a     = std::max(err_a, (g - u.gradient_of(x)).norm() / gmax);
              err_shape = std::max(err_shape, (gs - g).norm() / gmax);
            }
        }
      testing::check_small(err_a, tolerance, tag + "(a) Pi0 grad u = grad u for u in [P_k]^2, max rel. error");
      testing::check_small(err_shape, tolerance, tag + "(a) sum u_i Pi0 grad phi_i = Pi0 grad u");

      // (b) symmetric part = strain of the elliptic projection
      {
        const SmoothField u;
        element.interpolate(u, local);
        element.project_gradient(local, coefficients);
        element.project(local, projection);
        double err = 0, emax = 0;
        for (const P &x : test_points(element))
          {
            const auto eps = element.projection_strain(projection, x);
            emax           = std::max(emax, eps.norm());
            err = std::max(err, (dealii::symmetrize(element.gradient_projection_value(coefficients, x)) - eps).norm());
          }
        testing::check_small(err / emax, tolerance,
                             tag + "(b) sym(Pi0 grad u_h) = eps(Pi u_h) for a non-polynomial u");
      }

      // (c) infinitesimal rotation
      {
        const double   theta = 1e-3;
        const Rotation u(theta, P(0.2, 0.1));
        element.interpolate(u, local);
        element.project_gradient(local, coefficients);
        // the scale of the data: the DoF values (the translation makes them
        // O(1)) over the diameter
        const double scale = local.linfty_norm() / element.get_geometry().diameter();
        double       err_skew = 0, err_sym = 0;
        for (const P &x : test_points(element))
          {
            const dealii::Tensor<2, 2> g = element.gradient_projection_value(coefficients, x);
            err_skew = std::max(err_skew, std::abs(0.5 * (g[1][0] - g[0][1]) - theta) / scale);
            err_sym  = std::max(err_sym, dealii::symmetrize(g).norm() / scale);
          }
        testing::check_small(err_skew, tolerance,
                             tag + "(c) skew(Pi0 grad u) = rotation theta = 1e-3, error / (max |u_i| / h)");
        testing::check_small(err_sym, tolerance, tag + "(c) sym(Pi0 grad u) = 0 for a rotation, / (max |u_i| / h)");
      }
    }
}

// (b) the L2 projection property, on an axis-parallel polygon
void
check_l2_projection(const std::string &name, const std::vector<P> &vertices)
{
  for (const unsigned int k : {1u, 2u})
    {
      const std::string    tag = name + " k=" + std::to_string(k) + ": ";
      VirtualElement<2>    element(k);
      element.reinit(vertices);
      const AxisTraceField u(k);
      dealii::Vector<double> local, coefficients;
      element.interpolate(u, local);
      element.project_gradient(local, coefficients);
      // the L2 projection of grad u onto P_{k-1} by quadrature (own Gram
      // matrix of the scaled monomials 1, xi, eta)
      const auto                   &geo = element.get_geometry();
      const dealii::Quadrature<2>   q   = geo.quadrature(8);
      const unsigned int            n_m = element.n_gradient_monomials();
      dealii::FullMatrix<double>    M(n_m, n_m), M_inv(n_m, n_m);
      std::vector<dealii::Vector<double>> rhs(4, dealii::Vector<double>(n_m));
      for (unsigned int i = 0; i < q.size(); ++i)
        {
          const P      s     = geo.scaled(q.point(i));
          const double qm[3] = {1., s[0], s[1]};
          const auto   g     = u.gradient_of(q.point(i));
          for (unsigned int m = 0; m < n_m; ++m)
            {
              for (unsigned int l = 0; l < n_m; ++l)
                M(m, l) += q.weight(i) * qm[m] * qm[l];
              for (unsigned int c = 0; c < 2; ++c)
                for (unsigned int j = 0; j < 2; ++j)
                  rhs[2 * c + j][m] += q.weight(i) * g[c][j] * qm[m];
            }
        }
      M_inv.invert(M);
      double err = 0, cmax = 0, gap = 0;
      for (unsigned int b = 0; b < 4; ++b)
        {
          dealii::Vector<double> l2(n_m);
          M_inv.vmult(l2, rhs[b]);
          for (unsigned int m = 0; m < n_m; ++m)
            {
              err  = std::max(err, std::abs(coefficients[b * n_m + m] - l2[m]));
              cmax = std::max(cmax, std::abs(l2[m]));
            }
        }
      for (unsigned int i = 0; i < geo.n_vertices(); ++i)
        gap = std::max(gap, (element.gradient_projection_value(coefficients, geo.vertex(i)) -
                             u.gradient_of(geo.vertex(i)))
                              .norm());
      testing::check_small(err / cmax, 1e-12, tag + "(b) Pi0 grad I_h u = L2 projection of grad u (coefficients)");
      testing::check(gap > 1e-2 * cmax, tag + "(b) ... and grad u is not in P_{k-1} (|Pi0 grad u - grad u| = " +
                                           std::to_string(gap) + " at a vertex)");
    }
}

// VEMValues: function and shape evaluations at the quadrature points
void
check_vem_values(const std::string &name, const PolygonalMesh<2> &mesh)
{
  for (const unsigned int k : {1u, 2u})
    {
      const std::string tag = name + " k=" + std::to_string(k) + ": ";
      VEMDoFHandler<2>  dof_handler(mesh);
      dof_handler.distribute_dofs(k);
      const PolynomialField u(k, 7, P(0.1, 0.2));
      // the global DoF vector of the interpolant
      dealii::Vector<double>                       U(dof_handler.n_dofs()), local;
      std::vector<dealii::types::global_dof_index> indices;
      VirtualElement<2>                            element(k);
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          element.reinit(mesh.cell_vertices(c));
          element.interpolate(u, local);
          dof_handler.get_dof_indices(c, indices);
          for (unsigned int i = 0; i < indices.size(); ++i)
            U[indices[i]] = local[i];
        }
      VEMValues<2> vem_values(dof_handler, dealii::update_quadrature_points | dealii::update_gradients);
      std::vector<dealii::Tensor<2, 2>> gradients;
      double                            err = 0, err_shape = 0, err_sym = 0, gmax = 0, smax = 0;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          vem_values.reinit(c);
          vem_values.get_function_gradient_projections(U, gradients);
          dof_handler.get_dof_values(c, U, local);
          for (unsigned int q = 0; q < vem_values.n_quadrature_points(); ++q)
            {
              const auto ge = u.gradient_of(vem_values.quadrature_point(q));
              gmax          = std::max(gmax, ge.norm());
              err           = std::max(err, (gradients[q] - ge).norm());
              dealii::Tensor<2, 2> gs;
              for (unsigned int i = 0; i < local.size(); ++i)
                {
                  gs += local[i] * vem_values.shape_gradient_projection(i, q);
                  // the symmetric part of each shape function's projection
                  // is the strain of its elliptic projection
                  const auto eps = vem_values.shape_symmetric_gradient(i, q);
                  smax           = std::max(smax, eps.norm());
                  err_sym =
                    std::max(err_sym, (dealii::symmetrize(vem_values.shape_gradient_projection(i, q)) - eps).norm());
                }
              err_shape = std::max(err_shape, (gs - gradients[q]).norm());
            }
        }
      testing::check_small(err / gmax, 1e-12, tag + "VEMValues: Pi0 grad u_h = grad u at the quadrature points");
      testing::check_small(err_shape / gmax, 1e-12, tag + "VEMValues: sum u_i shape_gradient_projection = same");
      testing::check_small(err_sym / smax, 1e-12,
                           tag + "VEMValues: sym(shape_gradient_projection) = shape_symmetric_gradient");
    }
}

int
main()
{
  const P shift(3.0, -2.0);
  // convex
  {
    std::vector<P> hexagon;
    for (unsigned int i = 0; i < 6; ++i)
      hexagon.emplace_back(std::cos(M_PI * i / 3 + 0.3), std::sin(M_PI * i / 3 + 0.3));
    check_polygon("regular hexagon", translated(hexagon, shift));
    check_polygon("triangle", {P(0, 0), P(2, 0.3), P(0.4, 1.1)});
  }
  // non-convex (reflex vertex) and a collinear ("hanging") vertex
  check_polygon("non-convex pentagon", translated({P(0, 0), P(2, 0), P(2, 2), P(1, 0.8), P(0, 2)}, shift));
  check_polygon("square with a hanging vertex", {P(0, 0), P(0.5, 0), P(1, 0), P(1, 1), P(0, 1)});
  check_polygon("L-shape with collinear vertices",
                {P(0, 0), P(1, 0), P(2, 0), P(2, 1), P(1, 1), P(1, 2), P(0.5, 2), P(0, 2)});
  // elongated (1:100)
  check_polygon("1:100 rectangle", {P(0, 0), P(1, 0), P(1, 0.01), P(0, 0.01)}, 1e-9);
  // cells of a Voronoi mesh
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::voronoi(mesh, P(0, 0), P(1, 1), 12, 10, 5);
    for (const unsigned int c : {0u, 5u, 11u})
      check_polygon("Voronoi cell " + std::to_string(c), mesh.cell_vertices(c));
    check_vem_values("Voronoi mesh (12 cells)", mesh);
  }
  // the L2 projection on axis-parallel polygons: a non-convex L-shape with
  // collinear vertices, and a square with a hanging vertex
  check_l2_projection("L-shape", {P(0.2, 0.1), P(1.2, 0.1), P(2.2, 0.1), P(2.2, 1.1), P(1.2, 1.1), P(1.2, 2.1),
                                  P(0.2, 2.1)});
  check_l2_projection("square with a hanging vertex", {P(0.5, 0.5), P(1, 0.5), P(1.5, 0.5), P(1.5, 1.5),
                                                       P(0.5, 1.5)});
  // VEMValues on a non-convex mesh
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::nonconvex(mesh, P(0, 0), P(1, 1), 3, 3, 0.3);
    check_vem_values("non-convex mesh (9 cells)", mesh);
  }
  return testing::finish();
}
