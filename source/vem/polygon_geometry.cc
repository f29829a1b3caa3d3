// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>

#include <dealvem/vem/polygon_geometry.h>

#include <cmath>

namespace dealvem
{
  namespace internal
  {
    // Gauss rules on [0,1] with 1..12 points, built once: constructing a
    // QGauss computes its points as roots of Legendre polynomials, which
    // would dominate the cost of a polygon's geometry.
    const dealii::Quadrature<1> &
    gauss_rule(const unsigned int n_points)
    {
      static const std::vector<dealii::Quadrature<1>> rules = [] {
        std::vector<dealii::Quadrature<1>> r;
        for (unsigned int n = 1; n <= 12; ++n)
          r.emplace_back(dealii::QGauss<1>(n));
        return r;
      }();
      AssertThrow(n_points >= 1 && n_points <= 12,
                  dealii::ExcMessage("Gauss rules with 1 to 12 points are available."));
      return rules[n_points - 1];
    }
  } // namespace internal

  template <int dim>
  PolygonGeometry<dim>::PolygonGeometry(const std::vector<dealii::Point<dim>> &vertices)
  {
    reinit(vertices);
  }



  template <int dim>
  void
  PolygonGeometry<dim>::reinit(const std::vector<dealii::Point<dim>> &new_vertices)
  {
    const unsigned int n = new_vertices.size();
    Assert(n >= 3, dealii::ExcMessage("A polygon needs at least three vertices."));
    vertices.assign(new_vertices.begin(), new_vertices.end());
    lengths.resize(n);
    tangents.resize(n);

    // Area and centroid relative to the first vertex (reduces cancellation
    // for polygons far from the origin).
    const dealii::Point<dim> &o = vertices[0];
    double                    a = 0, cx = 0, cy = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        const dealii::Point<dim> &p = vertices[i], &q = vertices[(i + 1) % n];
        const dealii::Tensor<1, dim> e = q - p;
        lengths[i]                     = e.norm();
        tangents[i]                    = e / lengths[i];
        const double x0 = p[0] - o[0], y0 = p[1] - o[1], x1 = q[0] - o[0],
                     y1 = q[1] - o[1];
        const double cr = x0 * y1 - x1 * y0;
        a += cr;
        cx += (x0 + x1) * cr;
        cy += (y0 + y1) * cr;
      }
    area_        = 0.5 * a;
    centroid_[0] = o[0] + cx / (6. * area_);
    centroid_[1] = o[1] + cy / (6. * area_);

    double d2 = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        d2 = std::max(d2, vertices[i].distance_square(vertices[j]));
    diameter_ = std::sqrt(d2);
  }



  template <int dim>
  double
  PolygonGeometry<dim>::perimeter() const
  {
    double p = 0;
    for (const double l : lengths)
      p += l;
    return p;
  }



  template <int dim>
  double
  PolygonGeometry<dim>::integrate_scaled_monomial(const unsigned int a,
                                                  const unsigned int b) const
  {
    const unsigned int d = a + b;
    // Gauss rule exact for degree d on each edge.
    const dealii::Quadrature<1> &q = internal::gauss_rule(d / 2 + 1);
    const unsigned int      n = vertices.size();
    double                  result = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        const dealii::Point<dim> p0 = scaled(vertices[i]);
        const dealii::Point<dim> p1 = scaled(vertices[(i + 1) % n]);
        // (x - xbar).n in physical units: h * (p0 . n)
        const dealii::Tensor<1, dim> nrm = edge_normal(i);
        const double                 xn  = diameter_ * (p0[0] * nrm[0] + p0[1] * nrm[1]);
        if (xn == 0.)
          continue;
        double edge_integral = 0;
        for (unsigned int k = 0; k < q.size(); ++k)
          {
            const double s  = q.point(k)[0];
            const double xi = p0[0] + s * (p1[0] - p0[0]);
            const double et = p0[1] + s * (p1[1] - p0[1]);
            edge_integral += q.weight(k) * std::pow(xi, a) * std::pow(et, b);
          }
        result += xn * edge_integral * lengths[i];
      }
    return result / (d + 2);
  }



  template <int dim>
  void
  PolygonGeometry<dim>::integrate_scaled_monomials(std::array<double, 6> &integrals) const
  {
    // The formula of integrate_scaled_monomial() for all six monomials at
    // once, with the 2-point Gauss rule (exact up to degree 3 on an edge).
    integrals.fill(0.);
    const dealii::Quadrature<1> &q = internal::gauss_rule(2);
    const unsigned int           n = vertices.size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const dealii::Point<dim>     p0  = scaled(vertices[i]);
        const dealii::Point<dim>     p1  = scaled(vertices[(i + 1) % n]);
        const dealii::Tensor<1, dim> nrm = edge_normal(i);
        const double xn = diameter_ * (p0[0] * nrm[0] + p0[1] * nrm[1]) * lengths[i];
        double       e[6] = {0, 0, 0, 0, 0, 0};
        for (unsigned int k = 0; k < q.size(); ++k)
          {
            const double s  = q.point(k)[0], w = q.weight(k);
            const double xi = p0[0] + s * (p1[0] - p0[0]);
            const double et = p0[1] + s * (p1[1] - p0[1]);
            e[0] += w;
            e[1] += w * xi;
            e[2] += w * et;
            e[3] += w * xi * xi;
            e[4] += w * xi * et;
            e[5] += w * et * et;
          }
        for (unsigned int m = 0; m < 6; ++m)
          integrals[m] += xn * e[m];
      }
    // divide by d + 2
    integrals[0] /= 2.;
    integrals[1] /= 3.;
    integrals[2] /= 3.;
    for (unsigned int m = 3; m < 6; ++m)
      integrals[m] /= 4.;
  }



  template <int dim>
  dealii::Quadrature<dim>
  PolygonGeometry<dim>::quadrature(const unsigned int degree) const
  {
    std::vector<dealii::Point<dim>> points;
    std::vector<double>             weights;
    quadrature(degree, points, weights);
    return dealii::Quadrature<dim>(points, weights);
  }



  namespace
  {
    // The largest degree the triangle rules below integrate exactly.
    constexpr unsigned int max_simplex_degree = 13;

    // deal.II's rules on the reference triangle (0,0), (1,0), (0,1) (weights
    // summing to 1/2), by the degree they integrate exactly, built once:
    // QGaussSimplex<2>(n) is exact for degree 2n - 1 and available for
    // n <= 4 (degree 7); above, QWitherdenVincentSimplex<2>(n) (also
    // 2n - 1, positive weights, n <= 7 in 2D).
    const dealii::Quadrature<2> &
    triangle_rule(const unsigned int degree)
    {
      static const std::vector<dealii::Quadrature<2>> rules = [] {
        std::vector<dealii::Quadrature<2>> r;
        for (unsigned int d = 0; d <= max_simplex_degree; ++d)
          {
            const unsigned int n = std::max(1u, (d + 2) / 2); // 2n - 1 >= d
            if (n <= 4)
              r.emplace_back(dealii::QGaussSimplex<2>(n));
            else
              r.emplace_back(dealii::QWitherdenVincentSimplex<2>(n));
          }
        return r;
      }();
      AssertThrow(degree <= max_simplex_degree,
                  dealii::ExcMessage("Polygon quadrature: degree " + std::to_string(degree) +
                                     " is above the largest available (" + std::to_string(max_simplex_degree) +
                                     ")."));
      return rules[degree];
    }
  } // namespace



  template <int dim>
  void
  PolygonGeometry<dim>::quadrature(const unsigned int               degree,
                                   std::vector<dealii::Point<dim>> &points,
                                   std::vector<double>             &weights) const
  {
    // A rule exact for the given degree on every triangle of the fan
    // (centroid, v_i, v_{i+1}), mapped affinely; the signed weights make the
    // sum exact on non-convex polygons too.
    const dealii::Quadrature<2> &ref = triangle_rule(degree);
    const unsigned int n   = vertices.size();
    points.clear();
    weights.clear();
    for (unsigned int i = 0; i < n; ++i)
      {
        const dealii::Point<dim>    &p0 = centroid_;
        const dealii::Tensor<1, dim> e1 = vertices[i] - p0;
        const dealii::Tensor<1, dim> e2 = vertices[(i + 1) % n] - p0;
        const double                 det = e1[0] * e2[1] - e1[1] * e2[0];
        if (det == 0.)
          continue;
        for (unsigned int q = 0; q < ref.size(); ++q)
          {
            const dealii::Point<2> &r = ref.point(q);
            points.emplace_back(p0 + r[0] * e1 + r[1] * e2);
            // the reference weights sum to 1/2 (the reference area); det is
            // twice the signed area
            weights.push_back(ref.weight(q) * det);
          }
      }
  }

  template class PolygonGeometry<2>;
} // namespace dealvem
