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
    : vertices(vertices)
  {
    const unsigned int n = vertices.size();
    Assert(n >= 3, dealii::ExcMessage("A polygon needs at least three vertices."));
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

    diameter_ = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        diameter_ = std::max(diameter_, vertices[i].distance(vertices[j]));
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
  dealii::Quadrature<dim>
  PolygonGeometry<dim>::quadrature(const unsigned int degree) const
  {
    // Collapsed (Duffy) Gauss rule on the reference triangle
    // (x, y) = (u (1 - v), v), weight (1 - v): exact for polynomials of the
    // given degree (degree + 1 in v with n Gauss points, 2n - 1 >= degree + 1).
    const dealii::Quadrature<1>    &g = internal::gauss_rule((degree + 3) / 2);
    std::vector<dealii::Point<dim>> ref_points;
    std::vector<double>             ref_weights;
    for (unsigned int i = 0; i < g.size(); ++i)
      for (unsigned int j = 0; j < g.size(); ++j)
        {
          const double u = g.point(i)[0], v = g.point(j)[0];
          ref_points.emplace_back(u * (1 - v), v);
          ref_weights.push_back(g.weight(i) * g.weight(j) * (1 - v));
        }
    const dealii::Quadrature<dim> ref(ref_points, ref_weights);
    const unsigned int               n = vertices.size();
    std::vector<dealii::Point<dim>>  points;
    std::vector<double>              weights;
    points.reserve(n * ref.size());
    weights.reserve(n * ref.size());
    for (unsigned int i = 0; i < n; ++i)
      {
        const dealii::Point<dim>    &p0 = centroid_;
        const dealii::Tensor<1, dim> e1 = vertices[i] - p0;
        const dealii::Tensor<1, dim> e2 = vertices[(i + 1) % n] - p0;
        const double                 det = e1[0] * e2[1] - e1[1] * e2[0];
        if (det == 0.)
          continue;
        for (unsigned int k = 0; k < ref.size(); ++k)
          {
            const dealii::Point<dim> &r = ref.point(k);
            points.emplace_back(p0 + r[0] * e1 + r[1] * e2);
            // the reference weights sum to 1/2 (the reference area); det is
            // twice the signed area
            weights.push_back(ref.weight(k) * det);
          }
      }
    return dealii::Quadrature<dim>(points, weights);
  }

  template class PolygonGeometry<2>;
} // namespace dealvem
