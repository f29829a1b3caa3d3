// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/base/number_string.h>
#include <dealvem/design/density_filter.h>
#include <dealvem/mesh/polygonal_mesh.h>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace dealvem
{
  namespace Design
  {
    namespace
    {
      namespace bg  = boost::geometry;
      namespace bgi = boost::geometry::index;
      using FilterPoint = bg::model::point<double, 2, bg::cs::cartesian>;
      using FilterBox   = bg::model::box<FilterPoint>;
      using FilterEntry = std::pair<FilterPoint, unsigned int>;
      using FilterTree  = bgi::rtree<FilterEntry, bgi::quadratic<16>>;

      // an R-tree over @p points (the packing constructor, bulk loading,
      // builds a balanced tree)
      FilterTree
      filter_tree(const std::vector<dealii::Point<2>> &points)
      {
        std::vector<FilterEntry> entries;
        entries.reserve(points.size());
        for (unsigned int i = 0; i < points.size(); ++i)
          entries.emplace_back(FilterPoint(points[i][0], points[i][1]), i);
        return FilterTree(entries.begin(), entries.end());
      }

      // the linear filter's weights 1 - |x - p_j| / R > 0 at @p x over the
      // points of @p tree (indices into @p points), unnormalized
      void
      filter_weights(const FilterTree                    &tree,
                     const std::vector<dealii::Point<2>> &points,
                     const dealii::Point<2>              &x,
                     const double                         radius,
                     std::vector<FilterEntry>            &found,
                     std::vector<std::pair<unsigned int, double>> &weights)
      {
        found.clear();
        weights.clear();
        tree.query(bgi::intersects(FilterBox(FilterPoint(x[0] - radius, x[1] - radius),
                                             FilterPoint(x[0] + radius, x[1] + radius))),
                   std::back_inserter(found));
        for (const auto &f : found)
          {
            const double w = 1 - x.distance(points[f.second]) / radius;
            if (w > 0)
              weights.emplace_back(f.second, w);
          }
      }
    } // namespace



    DensityFilter::DensityFilter(const std::vector<dealii::Point<2>> &centroids, const double radius)
    {
      reinit(centroids, radius);
    }



    void
    DensityFilter::reinit(const std::vector<dealii::Point<2>> &centroids, const double radius)
    {
      AssertThrow(std::isfinite(radius) && radius > 0,
                  dealii::ExcMessage("Design/Filter radius: the radius must be positive, got " +
                                     internal::number_string(radius) + "."));
      this->radius = radius;
      const FilterTree tree = filter_tree(centroids);

      row_start.assign(1, 0);
      columns.clear();
      values.clear();
      std::vector<FilterEntry>                     found;
      std::vector<std::pair<unsigned int, double>> weights;
      for (unsigned int i = 0; i < centroids.size(); ++i)
        {
          filter_weights(tree, centroids, centroids[i], radius, found, weights);
          // the cell itself is always found (w = 1), so the sum is >= 1
          double sum = 0;
          for (const auto &w : weights)
            sum += w.second;
          for (const auto &w : weights)
            {
              columns.push_back(w.first);
              values.push_back(w.second / sum);
            }
          row_start.push_back(columns.size());
        }
    }



    void
    DensityFilter::apply(const std::vector<double> &x, std::vector<double> &y) const
    {
      AssertThrow(x.size() == size(), dealii::ExcDimensionMismatch(x.size(), size()));
      y.assign(size(), 0.);
      for (unsigned int i = 0; i < size(); ++i)
        for (std::size_t k = row_start[i]; k < row_start[i + 1]; ++k)
          y[i] += values[k] * x[columns[k]];
    }



    void
    DensityFilter::apply_transpose(const std::vector<double> &x, std::vector<double> &y) const
    {
      AssertThrow(x.size() == size(), dealii::ExcDimensionMismatch(x.size(), size()));
      y.assign(size(), 0.);
      for (unsigned int i = 0; i < size(); ++i)
        for (std::size_t k = row_start[i]; k < row_start[i + 1]; ++k)
          y[columns[k]] += values[k] * x[i];
    }



    void
    DensityFilter::row(const unsigned int i, std::vector<unsigned int> &cols, std::vector<double> &vals) const
    {
      AssertThrow(i < size(), dealii::ExcIndexRange(i, 0, size()));
      cols.assign(columns.begin() + row_start[i], columns.begin() + row_start[i + 1]);
      vals.assign(values.begin() + row_start[i], values.begin() + row_start[i + 1]);
    }



    std::vector<dealii::Point<2>>
    cell_centroids(const PolygonalMesh<2> &mesh, const std::vector<unsigned int> &cells)
    {
      std::vector<dealii::Point<2>> result;
      result.reserve(cells.size());
      std::vector<dealii::Point<2>> p;
      for (const unsigned int c : cells)
        {
          mesh.cell_vertices(c, p);
          // the area centroid by the shoelace formula, about the first
          // vertex (no cancellation far from the origin)
          double           a = 0;
          dealii::Point<2> s;
          for (unsigned int i = 1; i + 1 < p.size(); ++i)
            {
              const dealii::Tensor<1, 2> u = p[i] - p[0], v = p[i + 1] - p[0];
              const double               t = u[0] * v[1] - u[1] * v[0];
              a += t;
              s += t * (u + v) / 3.;
            }
          result.push_back(p[0] + s / a);
        }
      return result;
    }



    std::vector<double>
    cell_areas(const PolygonalMesh<2> &mesh, const std::vector<unsigned int> &cells)
    {
      std::vector<double>           result;
      std::vector<dealii::Point<2>> p;
      result.reserve(cells.size());
      for (const unsigned int c : cells)
        {
          mesh.cell_vertices(c, p);
          double a = 0;
          for (unsigned int i = 1; i + 1 < p.size(); ++i)
            {
              const dealii::Tensor<1, 2> u = p[i] - p[0], v = p[i + 1] - p[0];
              a += u[0] * v[1] - u[1] * v[0];
            }
          result.push_back(a / 2);
        }
      return result;
    }


    std::vector<double>
    transfer_densities(const PolygonalMesh<2>    &from,
                       const std::vector<double> &from_density,
                       const PolygonalMesh<2>    &to,
                       const double               radius)
    {
      AssertThrow(from.n_cells() > 0, dealii::ExcMessage("transfer_densities(): the source mesh has no cells."));
      AssertThrow(from_density.size() == from.n_cells(),
                  dealii::ExcMessage("transfer_densities(): " + std::to_string(from_density.size()) +
                                     " densities for " + std::to_string(from.n_cells()) + " cells."));
      AssertThrow(std::isfinite(radius) && radius > 0,
                  dealii::ExcMessage("transfer_densities(): the radius must be positive, got " +
                                     internal::number_string(radius) + "."));
      std::vector<unsigned int> all_from(from.n_cells()), all_to(to.n_cells());
      for (unsigned int c = 0; c < all_from.size(); ++c)
        all_from[c] = c;
      for (unsigned int c = 0; c < all_to.size(); ++c)
        all_to[c] = c;
      const auto               source = cell_centroids(from, all_from);
      const auto               target = cell_centroids(to, all_to);
      const FilterTree tree = filter_tree(source);
      const double     lo   = *std::min_element(from_density.begin(), from_density.end());
      const double     hi   = *std::max_element(from_density.begin(), from_density.end());
      std::vector<double>                          result(target.size(), 0.);
      std::vector<FilterEntry>                     found;
      std::vector<std::pair<unsigned int, double>> weights;
      for (unsigned int i = 0; i < target.size(); ++i)
        {
          const dealii::Point<2> &x = target[i];
          filter_weights(tree, source, x, radius, found, weights);
          double sum = 0, value = 0;
          for (const auto &w : weights)
            {
              sum += w.second;
              value += w.second * from_density[w.first];
            }
          // (an average of values in [lo, hi] lies there: kept there
          // against rounding, so that densities of 1 stay at most 1)
          if (sum > 0)
            result[i] = std::clamp(value / sum, lo, hi);
          else
            {
              found.clear();
              tree.query(bgi::nearest(FilterPoint(x[0], x[1]), 1), std::back_inserter(found));
              result[i] = from_density[found.front().second];
            }
        }
      return result;
    }

  } // namespace Design
} // namespace dealvem
