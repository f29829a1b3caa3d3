// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_vem_polygon_geometry_h
#define dealvem_vem_polygon_geometry_h

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <vector>

namespace dealvem
{
  namespace internal
  {
    /// The Gauss rule with @p n_points points on [0,1] (1 to 12), built once.
    const dealii::Quadrature<1> &
    gauss_rule(const unsigned int n_points);
  } // namespace internal

  /**
   * Geometric data of one polygon $E$ given by its counter-clockwise
   * vertices $v_0,\dots,v_{N-1}$: area $|E|$, centroid $\bar x$, diameter
   * $h$ (largest distance between two vertices), edges $e_i = [v_i,
   * v_{i+1}]$ with length $L_i$, unit tangent $t_i$ and outward unit normal
   * $n_i = (t_{i,y}, -t_{i,x})$.
   *
   * Integrals of the scaled monomials
   * $m_{ab} = \xi^a\eta^b$, $\xi = (x-\bar x)/h$, $\eta = (y-\bar y)/h$
   * are computed exactly by the divergence theorem: $m_{ab}$ is
   * homogeneous of degree $d = a+b$ in $x-\bar x$, so
   * @f[ \int_E m_{ab}\,dx = \frac{1}{d+2}\sum_i ((v_i-\bar x)\cdot n_i) \int_{e_i} m_{ab}\,ds, @f]
   * with Gauss quadrature on each edge. This holds for any simple polygon,
   * convex or not.
   *
   * quadrature() returns a rule on a fan of (signed) triangles from the
   * centroid; it integrates polynomials of the requested degree exactly on
   * any simple polygon (weights of triangles lying outside a non-convex
   * polygon are negative and cancel), and smooth functions defined around
   * the polygon to the usual order.
   */
  template <int dim>
  class PolygonGeometry
  {
  public:
    /// The geometry of the polygon with the given counter-clockwise
    /// @p vertices (at least three; asserted in debug mode), as reinit().
    explicit PolygonGeometry(const std::vector<dealii::Point<dim>> &vertices);

    /// An empty geometry, to be set by reinit().
    PolygonGeometry() = default;

    /// Recompute everything for new vertices. The storage is reused, so a
    /// geometry object that is reinitialized cell after cell does not
    /// allocate once its vectors are large enough.
    void
    reinit(const std::vector<dealii::Point<dim>> &vertices);

    /// Number of vertices N (= number of edges).
    unsigned int
    n_vertices() const
    {
      return vertices.size();
    }

    /// Vertex @p i, 0 <= i < n_vertices() (not checked).
    const dealii::Point<dim> &
    vertex(const unsigned int i) const
    {
      return vertices[i];
    }

    /// Area $|E|$ by the shoelace formula; positive for counter-clockwise
    /// vertices (negative if they are given clockwise).
    double
    area() const
    {
      return area_;
    }

    /// Centroid $\bar x$ (center of mass of the polygon's area, not the
    /// mean of its vertices).
    const dealii::Point<dim> &
    centroid() const
    {
      return centroid_;
    }

    /// Diameter $h$: the largest distance between two vertices.
    double
    diameter() const
    {
      return diameter_;
    }

    /// Length $L_i$ of edge @p i, from vertex i to vertex i+1.
    double
    edge_length(const unsigned int i) const
    {
      return lengths[i];
    }

    /// Unit tangent of edge i (from vertex i to vertex i+1).
    const dealii::Tensor<1, dim> &
    edge_tangent(const unsigned int i) const
    {
      return tangents[i];
    }

    /// Outward unit normal of edge i.
    dealii::Tensor<1, dim>
    edge_normal(const unsigned int i) const
    {
      dealii::Tensor<1, dim> n;
      n[0] = tangents[i][1];
      n[1] = -tangents[i][0];
      return n;
    }

    /// Midpoint of edge @p i, $(v_i + v_{i+1})/2$.
    dealii::Point<dim>
    edge_midpoint(const unsigned int i) const
    {
      return 0.5 * (vertices[i] + vertices[(i + 1) % vertices.size()]);
    }

    /// Perimeter $|\partial E|$.
    double
    perimeter() const;

    /// Scaled coordinates $((x-\bar x)/h, (y-\bar y)/h)$ of a point.
    dealii::Point<dim>
    scaled(const dealii::Point<dim> &p) const
    {
      return dealii::Point<dim>((p - centroid_) / diameter_);
    }

    /// $\int_E \xi^a\eta^b\,dx$, exact.
    double
    integrate_scaled_monomial(const unsigned int a, const unsigned int b) const;

    /// The integrals of all scaled monomials of degree <= 2, in the order
    /// $1, \xi, \eta, \xi^2, \xi\eta, \eta^2$ (one pass over the edges).
    void
    integrate_scaled_monomials(std::array<double, 6> &integrals) const;

    /// A quadrature rule on the polygon exact for polynomials of degree
    /// @p degree <= 13 (signed triangle fan from the centroid; on each
    /// triangle deal.II's QGaussSimplex<2>, above degree 7
    /// QWitherdenVincentSimplex<2>).
    dealii::Quadrature<dim>
    quadrature(const unsigned int degree) const;

    /// The same rule written into @p points and @p weights (storage reused).
    void
    quadrature(const unsigned int               degree,
               std::vector<dealii::Point<dim>> &points,
               std::vector<double>             &weights) const;

  private:
    std::vector<dealii::Point<dim>>     vertices;
    std::vector<double>                 lengths;
    std::vector<dealii::Tensor<1, dim>> tangents;
    double                              area_     = 0;
    dealii::Point<dim>                  centroid_;
    double                              diameter_ = 0;
  };
} // namespace dealvem

#endif
