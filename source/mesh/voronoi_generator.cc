// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// PolygonalMeshGenerators::voronoi(): a centroidal Voronoi mesh of a
// rectangle by Lloyd's iteration, the Voronoi cells computed by CGAL from the
// Delaunay triangulation of the sites and their mirror images across the
// sides. The only file of the mesh layer that includes CGAL.
#include <dealvem/config.h>
#include <dealvem/mesh/generators.h>

#include "generators_internal.h"

#ifdef DEALVEM_WITH_CGAL
#  include <CGAL/Delaunay_triangulation_2.h>
#  include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#  include <CGAL/Triangulation_vertex_base_with_info_2.h>
#  include <CGAL/hilbert_sort.h>
#endif

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace dealvem
{
  namespace PolygonalMeshGenerators
  {
    namespace
    {
      using P = dealii::Point<2>;

#ifdef DEALVEM_WITH_CGAL
      // Step 1: @p n_cells sites drawn uniformly in the rectangle from the
      // random number generator seeded with @p seed.
      std::vector<P>
      random_sites(const P &p0, const P &p1, const unsigned int n_cells, const unsigned int seed)
      {
        std::mt19937                           rng(seed);
        std::uniform_real_distribution<double> ux(p0[0], p1[0]), uy(p0[1], p1[1]);
        std::vector<P>                         sites(n_cells);
        for (auto &s : sites)
          {
            const double x = ux(rng), y = uy(rng);
            s              = P(x, y);
          }
        // along a Hilbert curve, so that neighbouring cells (and the
        // vertices and edges numbered in order of appearance) get close
        // numbers: locality of the matrix and of the vectors in a solve
        using K = CGAL::Exact_predicates_inexact_constructions_kernel;
        std::vector<K::Point_2> points;
        points.reserve(n_cells);
        for (const auto &s : sites)
          points.emplace_back(s[0], s[1]);
        CGAL::hilbert_sort(points.begin(), points.end());
        for (unsigned int i = 0; i < n_cells; ++i)
          sites[i] = P(points[i].x(), points[i].y());
        return sites;
      }

      // Step 2: the Voronoi cell of each site, clipped to the rectangle: the
      // circumcentres of the Delaunay triangles around the site, where the
      // mirror images of the sites across the four sides make the cells end
      // on the sides.
      std::vector<std::vector<P>>
      voronoi_polygons(const std::vector<P> &sites, const P &p0, const P &p1, const unsigned int seed)
      {
        using K                    = CGAL::Exact_predicates_inexact_constructions_kernel;
        using Vb                   = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
        using Tds                  = CGAL::Triangulation_data_structure_2<Vb>;
        using DT                   = CGAL::Delaunay_triangulation_2<K, Tds>;
        using CP                   = K::Point_2;
        const unsigned int n_cells = sites.size();

        // the sites and their mirror images across the four sides
        std::vector<std::pair<CP, int>> points;
        for (unsigned int i = 0; i < n_cells; ++i)
          {
            const P &s = sites[i];
            points.emplace_back(CP(s[0], s[1]), int(i));
            points.emplace_back(CP(2 * p0[0] - s[0], s[1]), -1);
            points.emplace_back(CP(2 * p1[0] - s[0], s[1]), -1);
            points.emplace_back(CP(s[0], 2 * p0[1] - s[1]), -1);
            points.emplace_back(CP(s[0], 2 * p1[1] - s[1]), -1);
          }
        DT dt;
        dt.insert(points.begin(), points.end());
        std::vector<std::vector<P>> polygons(n_cells);
        std::vector<bool>           found(n_cells, false);
        for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
          {
            const int i = v->info();
            if (i < 0)
              continue;
            AssertThrow(!found[i], dealii::ExcMessage("voronoi: two generators coincide (seed " +
                                                       std::to_string(seed) + ")."));
            found[i] = true;
            auto f = dt.incident_faces(v), done = f;
            do
              {
                AssertThrow(!dt.is_infinite(f), dealii::ExcMessage("voronoi: unbounded cell; internal error."));
                const CP c = dt.circumcenter(f);
                // clip round-off: keep the vertices in the rectangle
                polygons[i].emplace_back(std::min(p1[0], std::max(p0[0], c.x())),
                                         std::min(p1[1], std::max(p0[1], c.y())));
              }
            while (++f != done);
          }
        for (unsigned int i = 0; i < n_cells; ++i)
          AssertThrow(found[i], dealii::ExcMessage("voronoi: two generators coincide (seed " +
                                                    std::to_string(seed) + ")."));
        return polygons;
      }

      // Step 3 (Lloyd): each site moves to the centroid of its cell.
      void
      move_sites_to_centroids(const std::vector<std::vector<P>> &polygons, std::vector<P> &sites)
      {
        for (unsigned int i = 0; i < sites.size(); ++i)
          {
            const auto        &poly = polygons[i];
            double             a = 0, cx = 0, cy = 0;
            const unsigned int n = poly.size();
            for (unsigned int k = 0; k < n; ++k)
              {
                const P     &p = poly[k], &q = poly[(k + 1) % n];
                const double cr = p[0] * q[1] - q[0] * p[1];
                a += cr;
                cx += (p[0] + q[0]) * cr;
                cy += (p[1] + q[1]) * cr;
              }
            if (std::abs(a) > 0)
              sites[i] = P(cx / (3 * a), cy / (3 * a));
          }
      }

      // Step 4: the cells of the last iteration into @p mesh. Voronoi
      // vertices closer than @p tol are merged (the mirror images make
      // cocircular quadruples, whose circumcentres differ by round-off) and
      // vertices that close to a side are snapped onto it.
      void
      add_polygons(PolygonalMesh<2> &mesh, const std::vector<std::vector<P>> &polygons, const P &p0, const P &p1,
                   const double tol)
      {
        std::map<std::pair<long long, long long>, std::vector<unsigned int>> buckets;
        auto find_or_add = [&](P p) {
          for (unsigned int d = 0; d < 2; ++d)
            {
              if (std::abs(p[d] - p0[d]) < tol)
                p[d] = p0[d];
              if (std::abs(p[d] - p1[d]) < tol)
                p[d] = p1[d];
            }
          const long long bx = std::llround(p[0] / (10 * tol)), by = std::llround(p[1] / (10 * tol));
          for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
              {
                const auto it = buckets.find({bx + dx, by + dy});
                if (it != buckets.end())
                  for (const auto v : it->second)
                    if (mesh.vertex(v).distance(p) < tol)
                      return v;
              }
          const unsigned int v = mesh.add_vertex(p);
          buckets[{bx, by}].push_back(v);
          return v;
        };
        for (const auto &poly : polygons)
          {
            std::vector<unsigned int> loop;
            for (const auto &p : poly)
              {
                const unsigned int v = find_or_add(p);
                if (loop.empty() || loop.back() != v)
                  loop.push_back(v);
              }
            while (loop.size() > 1 && loop.front() == loop.back())
              loop.pop_back();
            mesh.add_cell(loop);
          }
      }
#endif
    } // namespace



    template <int dim>
    void
    voronoi(PolygonalMesh<dim> &mesh, const dealii::Point<dim> &p0, const dealii::Point<dim> &p1,
            const unsigned int n_cells, const unsigned int n_lloyd_iterations, const unsigned int seed)
    {
      internal::check_rectangle(p0, p1, 1, 1, "voronoi");
      AssertThrow(n_cells >= 1, dealii::ExcMessage("voronoi: at least one cell is needed."));
#ifndef DEALVEM_WITH_CGAL
      (void)mesh;
      (void)n_lloyd_iterations;
      (void)seed;
      AssertThrow(false,
                  dealii::ExcMessage("voronoi: dealvem was configured without CGAL; the Voronoi mesh generator "
                                     "needs it (install CGAL, e.g. apt-get install libcgal-dev, and configure "
                                     "dealvem again with -DDEALVEM_WITH_CGAL=ON), or choose another mesh type."));
#else
      const double W = p1[0] - p0[0], H = p1[1] - p0[1], size = std::max(W, H);

      // the sites, the cells and Lloyd's centroids are computed on the
      // rectangle moved to the origin and moved back at the end, so that a
      // rectangle far from the origin gets the same mesh, translated (in
      // absolute coordinates the circumcentres and centroids lose the digits
      // of |p0| and the iteration drifts apart)
      const P                     origin;
      const P                     extent(W, H);
      std::vector<P>              sites = random_sites(origin, extent, n_cells, seed);
      std::vector<std::vector<P>> polygons;
      for (unsigned int iteration = 0; iteration <= n_lloyd_iterations; ++iteration)
        {
          polygons = voronoi_polygons(sites, origin, extent, seed);
          if (iteration == n_lloyd_iterations)
            break;
          move_sites_to_centroids(polygons, sites);
        }
      for (auto &polygon : polygons)
        for (auto &v : polygon)
          v += p0;

      mesh.clear();
      mesh.name = "voronoi " + std::to_string(n_cells) + " cells, seed " + std::to_string(seed);
      add_polygons(mesh, polygons, p0, p1, 1e-9 * size);
      internal::finish_rectangle(mesh, p0, p1);
      AssertThrow(std::abs(mesh.total_area() - W * H) <= 1e-10 * W * H,
                  dealii::ExcMessage("voronoi: the cells do not cover the rectangle; internal error."));
#endif
    }



    template void voronoi(PolygonalMesh<2> &, const P &, const P &, const unsigned int, const unsigned int,
                          const unsigned int);
  } // namespace PolygonalMeshGenerators
} // namespace dealvem
