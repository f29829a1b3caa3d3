// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_design_density_filter_h
#define dealvem_design_density_filter_h

#include <deal.II/base/point.h>

#include <vector>

namespace dealvem
{
  template <int dim>
  class PolygonalMesh;

  namespace Design
  {
    /**
     * The linear density filter of PolyTop (Talischi, Paulino, Pereira and
     * Menezes 2012) over cell centroids: $\tilde\rho = P z$ with
     * @f[ P_{ij} = \frac{w_{ij}}{\sum_k w_{ik}}, \qquad
     *     w_{ij} = \max\bigl(0,\; 1 - |x_i - x_j| / R\bigr), @f]
     * $x_i$ the centroid of design cell $i$ and $R$ the filter radius. Each
     * row of $P$ sums to one, so a uniform design is left unchanged, and a
     * cell is its own neighbour ($w_{ii} = 1$), so $P$ is defined for any
     * $R > 0$ (with no other centroid within $R$, $P = I$).
     *
     * The neighbours within $R$ are found by a Boost.Geometry R-tree of the
     * centroids (a box query per cell, then the distance), in
     * $O(n \log n + n m)$ for $m$ neighbours per cell, never $O(n^2)$. The
     * matrix is stored row-wise (compressed); apply() gives $P z$ and
     * apply_transpose() $P^T g$, the chain rule of a gradient with respect
     * to $\tilde\rho$ back to $z$.
     */
    class DensityFilter
    {
    public:
      /// An empty filter (reinit() before use).
      DensityFilter() = default;

      /// The filter of the points @p centroids with radius @p radius
      /// (throws unless radius > 0 and finite).
      DensityFilter(const std::vector<dealii::Point<2>> &centroids, const double radius);

      /// Build the filter of @p centroids with radius @p radius.
      void
      reinit(const std::vector<dealii::Point<2>> &centroids, const double radius);

      /// The number of filtered values (rows of P).
      unsigned int
      size() const
      {
        return row_start.empty() ? 0 : row_start.size() - 1;
      }

      /// The number of stored weights (non-zeros of P).
      std::size_t
      n_nonzeros() const
      {
        return columns.size();
      }

      /// The radius R.
      double
      get_radius() const
      {
        return radius;
      }

      /// $y = P x$ (x and y of size size(); y is resized).
      void
      apply(const std::vector<double> &x, std::vector<double> &y) const;

      /// $y = P^T x$.
      void
      apply_transpose(const std::vector<double> &x, std::vector<double> &y) const;

      /// The weights of row @p i: its columns and values.
      void
      row(const unsigned int i, std::vector<unsigned int> &cols, std::vector<double> &values) const;

    private:
      double                    radius = 0;
      std::vector<std::size_t>  row_start;
      std::vector<unsigned int> columns;
      std::vector<double>       values;
    };

    /// The centroids of the cells @p cells of @p mesh (area centroids of the
    /// polygons).
    std::vector<dealii::Point<2>>
    cell_centroids(const PolygonalMesh<2> &mesh, const std::vector<unsigned int> &cells);

    /// The areas of the cells @p cells of @p mesh.
    std::vector<double>
    cell_areas(const PolygonalMesh<2> &mesh, const std::vector<unsigned int> &cells);

    /**
     * Densities on another mesh: for every cell of @p to, the linear
     * filter's average (weights $1 - |x - x_j|/R$, as DensityFilter) of the
     * densities @p from_density of the cells of @p from (one per cell) whose
     * centroids lie within @p radius of the cell's centroid; where none
     * does, the density of the cell of @p from with the nearest centroid.
     * To start a design on a fine mesh from the design of a coarse one
     * (TopologyOptimizer::run() with initial densities). Throws if the
     * sizes disagree, @p from has no cells or the radius is not positive.
     */
    std::vector<double>
    transfer_densities(const PolygonalMesh<2>    &from,
                       const std::vector<double> &from_density,
                       const PolygonalMesh<2>    &to,
                       const double               radius);
  } // namespace Design
} // namespace dealvem

#endif
