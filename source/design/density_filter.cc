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
      std::vector<FilterEntry> entries;
      entries.reserve(centroids.size());
      for (unsigned int i = 0; i < centroids.size(); ++i)
        entries.emplace_back(FilterPoint(centroids[i][0], centroids[i][1]), i);
      // the packing constructor (bulk loading) builds a balanced tree
      const bgi::rtree<FilterEntry, bgi::quadratic<16>> tree(entries.begin(), entries.end());

      row_start.assign(1, 0);
      columns.clear();
      values.clear();
      std::vector<FilterEntry> found;
      for (unsigned int i = 0; i < centroids.size(); ++i)
        {
          const dealii::Point<2> &x = centroids[i];
          found.clear();
          tree.query(bgi::intersects(FilterBox(FilterPoint(x[0] - radius, x[1] - radius),
                                               FilterPoint(x[0] + radius, x[1] + radius))),
                     std::back_inserter(found));
          double sum = 0;
          const std::size_t first = columns.size();
          for (const auto &f : found)
            {
              const double w = 1 - x.distance(centroids[f.second]) / radius;
              if (w > 0)
                {
                  columns.push_back(f.second);
                  values.push_back(w);
                  sum += w;
                }
            }
          // the cell itself is always found (w = 1), so sum >= 1
          for (std::size_t k = first; k < values.size(); ++k)
            values[k] /= sum;
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
      std::vector<FilterEntry> entries;
      entries.reserve(source.size());
      for (unsigned int i = 0; i < source.size(); ++i)
        entries.emplace_back(FilterPoint(source[i][0], source[i][1]), i);
      const bgi::rtree<FilterEntry, bgi::quadratic<16>> tree(entries.begin(), entries.end());

      const double             lo = *std::min_element(from_density.begin(), from_density.end());
      const double             hi = *std::max_element(from_density.begin(), from_density.end());
      std::vector<double>      result(target.size(), 0.);
      std::vector<FilterEntry> found;
      for (unsigned int i = 0; i < target.size(); ++i)
        {
          const dealii::Point<2> &x = target[i];
          found.clear();
          tree.query(bgi::intersects(FilterBox(FilterPoint(x[0] - radius, x[1] - radius),
                                               FilterPoint(x[0] + radius, x[1] + radius))),
                     std::back_inserter(found));
          double sum = 0, value = 0;
          for (const auto &f : found)
            {
              const double w = 1 - x.distance(source[f.second]) / radius;
              if (w > 0)
                {
                  sum += w;
                  value += w * from_density[f.second];
                }
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
