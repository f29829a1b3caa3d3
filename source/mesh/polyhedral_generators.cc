// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// PolyhedralMeshGenerators: the structured hexahedra of a box, and a
// centroidal Voronoi mesh of a box by Lloyd's iteration. The neighbours of a
// generator come from CGAL's 3D Delaunay triangulation; its Voronoi cell is
// the box cut by the bisector planes, computed here on a list of face
// polygons. The only file of the 3D mesh layer that includes CGAL.
#include <deal.II/base/tensor.h>

#include <dealvem/config.h>
#include <dealvem/mesh/polyhedral_generators.h>

#ifdef DEALVEM_WITH_CGAL
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace dealvem
{
  // file-local (the library is a unity build: a name of its own)
  namespace polyhedral_generators_internal
  {
    namespace
    {
      using Pt  = dealii::Point<3>;
      using Vec = dealii::Tensor<1, 3>;

      // Throws unless @p upper lies above @p lower in every coordinate.
      void
      check_box(const Pt &lower, const Pt &upper, const std::string &what)
      {
        for (unsigned int d = 0; d < 3; ++d)
          AssertThrow(std::isfinite(lower[d]) && std::isfinite(upper[d]) && upper[d] > lower[d],
                      dealii::ExcMessage(what + ": the upper corner of the box must lie above the lower corner "
                                                "in every coordinate."));
      }

      // Finalizes @p mesh and gives every boundary face the boundary id of the
      // side of the box [lower, upper] its vertices lie on (0: x = lower[0],
      // 1: x = upper[0], 2, 3 for y and 4, 5 for z), as deal.II's colorize.
      void
      finish_box(PolyhedralMesh &mesh, const Pt &lower, const Pt &upper)
      {
        mesh.finalize();
        const double tol = 1e-10 * lower.distance(upper);
        for (unsigned int f = 0; f < mesh.n_faces(); ++f)
          if (mesh.face(f).at_boundary())
            {
              int side = -1;
              for (unsigned int s = 0; s < 6 && side < 0; ++s)
                {
                  const unsigned int d     = s / 2;
                  const double       plane = (s % 2 == 0 ? lower[d] : upper[d]);
                  bool               on    = true;
                  for (const unsigned int v : mesh.face(f).vertices)
                    on = on && std::abs(mesh.vertex(v)[d] - plane) <= tol;
                  if (on)
                    side = s;
                }
              AssertThrow(side >= 0, dealii::ExcMessage("PolyhedralMeshGenerators: boundary face " + std::to_string(f) +
                                                        " lies on no side of the box; internal error."));
              mesh.set_face_boundary_id(f, side);
            }
      }

#ifdef DEALVEM_WITH_CGAL
      // The planes a cell is cut by are named by labels: label >= 0 is the
      // bisector between the cell's generator and generator `label`,
      // label = -1 - s the side s of the box.
      //
      // A vertex of a cell while it is being cut: its position and the labels
      // of the three planes it is the intersection of, sorted. The cell's
      // generator and these three name the vertex in every cell it belongs
      // to (the point equidistant from four generators, or from three on a
      // side of the box, ...): add_cells() identifies the copies of a vertex
      // computed in different cells by this name, not by their positions,
      // which may differ by much more than round-off where the planes meet
      // at small angles (a nearly degenerate diagram). planes[0] = no_plane:
      // a vertex where more than three planes meet, whose two edges give no
      // name; only its position identifies it.
      constexpr int no_plane = std::numeric_limits<int>::min();
      struct ClipVertex
      {
        Pt                 x;
        std::array<int, 3> planes;
      };

      // A face of a convex polyhedron while it is being cut: the vertex loop,
      // oriented by the right-hand rule with the normal pointing out, and the
      // label of its plane. A vertex common to several faces is stored in
      // each of them with the same bits (the cuts compute it the same way
      // from the same points), so that comparing points exactly recognises
      // it.
      struct ClipFace
      {
        int                     label;
        std::vector<ClipVertex> points;
      };
      using ClipPolyhedron = std::vector<ClipFace>;

      // The box [0, L] as six outward-oriented quadrilaterals.
      ClipPolyhedron
      box_polyhedron(const Pt &L)
      {
        auto c = [&L](const int i, const int j, const int k) {
          return ClipVertex{Pt(i * L[0], j * L[1], k * L[2]), {{-5 - k, -3 - j, -1 - i}}};
        };
        return {{-1, {c(0, 0, 0), c(0, 0, 1), c(0, 1, 1), c(0, 1, 0)}},  // x-: z then y, normal -x
                {-2, {c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)}},  // x+
                {-3, {c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)}},  // y-: x then z, normal -y
                {-4, {c(0, 1, 0), c(0, 1, 1), c(1, 1, 1), c(1, 1, 0)}},  // y+
                {-5, {c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)}},  // z-: y then x, normal -z
                {-6, {c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)}}}; // z+
      }

      bool
      lexicographically_less(const Pt &a, const Pt &b)
      {
        return std::lexicographical_compare(a.begin_raw(), a.end_raw(), b.begin_raw(), b.end_raw());
      }

      bool
      lexicographically_less_vertex(const ClipVertex &a, const ClipVertex &b)
      {
        return lexicographically_less(a.x, b.x);
      }

      // The point where the edge [a, b] crosses the plane @p label, from the
      // signed distances @p da, @p db of its ends (of opposite signs), and
      // its planes: the two the ends have in common (those of the edge) and
      // the new one. Computed from the lexicographically smaller end, so
      // that the two faces sharing the edge (which run along it in opposite
      // directions) get the same bits.
      ClipVertex
      crossing(const ClipVertex &a, const double da, const ClipVertex &b, const double db, const int label)
      {
        if (lexicographically_less(b.x, a.x))
          return crossing(b, db, a, da, label);
        const double t = da / (da - db);
        ClipVertex   v{a.x + t * (b.x - a.x), {{no_plane, no_plane, no_plane}}};
        if (a.planes[0] != no_plane && b.planes[0] != no_plane)
          {
            std::array<int, 3> common;
            const auto         end =
              std::set_intersection(a.planes.begin(), a.planes.end(), b.planes.begin(), b.planes.end(), common.begin());
            if (end - common.begin() == 2)
              {
                v.planes = {{common[0], common[1], label}};
                std::sort(v.planes.begin(), v.planes.end());
              }
          }
        return v;
      }

      // Buffers of clip(), kept from one call to the next.
      struct ClipScratch
      {
        std::vector<double>                          d;
        std::vector<ClipVertex>                      kept;
        std::vector<ClipVertex>                      cap;
        std::vector<std::pair<double, unsigned int>> by_angle;
      };

      // Cut @p poly by the plane n.x = c (n: unit normal) and keep the part
      // n.x <= c; the new face lies in the plane and gets @p label. A vertex
      // within @p eps of the plane counts as on it: it is kept and becomes a
      // vertex of the new face, and no edge is cut next to it (otherwise it
      // would come back as a second vertex a round-off away). The new face is
      // made of the kept on-plane vertices and the edge crossings, each once,
      // ordered counterclockwise about n (its outward normal). Returns false
      // if the plane cuts nothing off.
      bool
      clip(ClipPolyhedron &poly, const Vec &n, const double c, const int label, const double eps, ClipScratch &scratch)
      {
        auto distance = [&](const ClipVertex &p) { return n * p.x - c; };
        bool any_out  = false;
        for (const auto &face : poly)
          {
            for (const auto &p : face.points)
              if (distance(p) > eps)
                {
                  any_out = true;
                  break;
                }
            if (any_out)
              break;
          }
        if (!any_out)
          return false;

        std::vector<double>     &d    = scratch.d;
        std::vector<ClipVertex> &kept = scratch.kept;
        std::vector<ClipVertex> &cap  = scratch.cap;
        cap.clear();
        unsigned int n_faces = 0;
        for (unsigned int f = 0; f < poly.size(); ++f)
          {
            ClipFace          &face = poly[f];
            const unsigned int m    = face.points.size();
            d.resize(m);
            bool strictly_inside = false, outside = false;
            for (unsigned int k = 0; k < m; ++k)
              {
                d[k] = distance(face.points[k]);
                strictly_inside |= (d[k] < -eps);
                outside |= (d[k] > eps);
              }
            // a face with no vertex strictly inside lies in the cutting plane
            // (it is part of the new face) or beyond it: dropped
            if (!strictly_inside)
              {
                for (unsigned int k = 0; k < m; ++k)
                  if (d[k] >= -eps && d[k] <= eps)
                    cap.push_back(face.points[k]);
                continue;
              }
            if (!outside)
              {
                for (unsigned int k = 0; k < m; ++k)
                  if (d[k] >= -eps)
                    cap.push_back(face.points[k]);
              }
            else
              {
                kept.clear();
                for (unsigned int k = 0; k < m; ++k)
                  {
                    const unsigned int l = (k + 1) % m;
                    if (d[k] <= eps)
                      {
                        kept.push_back(face.points[k]);
                        if (d[k] >= -eps)
                          cap.push_back(face.points[k]);
                      }
                    if ((d[k] < -eps && d[l] > eps) || (d[k] > eps && d[l] < -eps))
                      {
                        const ClipVertex x = crossing(face.points[k], d[k], face.points[l], d[l], label);
                        kept.push_back(x);
                        cap.push_back(x);
                      }
                  }
                // (the face's old buffer becomes the next face's scratch)
                face.points.swap(kept);
              }
            if (face.points.size() >= 3)
              {
                if (n_faces != f)
                  std::swap(poly[n_faces], face);
                ++n_faces;
              }
          }
        poly.resize(n_faces);

        std::sort(cap.begin(), cap.end(), lexicographically_less_vertex);
        cap.erase(std::unique(cap.begin(), cap.end(),
                              [](const ClipVertex &a, const ClipVertex &b) { return a.x == b.x; }),
                  cap.end());
        if (cap.size() >= 3)
          {
            Pt centre;
            for (const auto &p : cap)
              centre += p.x;
            centre /= cap.size();
            // an in-plane basis u, v with u x v = n: increasing angle is
            // counterclockwise about n
            unsigned int far = 0;
            for (unsigned int k = 1; k < cap.size(); ++k)
              if (cap[k].x.distance_square(centre) > cap[far].x.distance_square(centre))
                far = k;
            Vec u = cap[far].x - centre;
            u -= (u * n) * n;
            u /= u.norm();
            const Vec v        = dealii::cross_product_3d(n, u);
            auto     &by_angle = scratch.by_angle;
            by_angle.resize(cap.size());
            for (unsigned int k = 0; k < cap.size(); ++k)
              {
                const Vec r = cap[k].x - centre;
                by_angle[k] = {std::atan2(r * v, r * u), k};
              }
            std::sort(by_angle.begin(), by_angle.end());
            ClipFace new_face{label, {}};
            new_face.points.reserve(cap.size());
            for (const auto &a : by_angle)
              new_face.points.push_back(cap[a.second]);
            poly.push_back(std::move(new_face));
          }
        return true;
      }

      // Volume and centroid of a closed outward-oriented polyhedron: the
      // tetrahedra from the point @p o to the triangles of a fan of each face.
      std::pair<double, Pt>
      volume_and_centroid(const ClipPolyhedron &poly, const Pt &o)
      {
        double volume = 0;
        Vec    moment;
        for (const auto &face : poly)
          {
            const auto &q = face.points;
            for (unsigned int k = 1; k + 1 < q.size(); ++k)
              {
                const Vec    a = q[0].x - o, b = q[k].x - o, c = q[k + 1].x - o;
                const double v = a * dealii::cross_product_3d(b, c) / 6;
                volume += v;
                moment += v * (a + b + c) / 4;
              }
          }
        return {volume, volume > 0 ? o + moment / volume : o};
      }

      // The Voronoi cells of @p sites in the box [0, L], each cut from the box
      // by the bisector planes with its neighbours in the Delaunay
      // triangulation, nearest first.
      std::vector<ClipPolyhedron>
      voronoi_cells(const std::vector<Pt> &sites, const Pt &L, const unsigned int seed)
      {
        using K   = CGAL::Exact_predicates_inexact_constructions_kernel;
        using Vb  = CGAL::Triangulation_vertex_base_with_info_3<unsigned int, K>;
        using Tds = CGAL::Triangulation_data_structure_3<Vb>;
        using DT  = CGAL::Delaunay_triangulation_3<K, Tds>;
        using CP  = K::Point_3;

        const unsigned int n    = sites.size();
        const double       diag = L.norm();
        const double       eps  = 1e-13 * diag;

        std::vector<std::pair<CP, unsigned int>> points;
        points.reserve(n);
        for (unsigned int i = 0; i < n; ++i)
          points.emplace_back(CP(sites[i][0], sites[i][1], sites[i][2]), i);
        DT dt(points.begin(), points.end());
        AssertThrow(dt.number_of_vertices() == n,
                    dealii::ExcMessage("voronoi_box: two generators coincide (seed " + std::to_string(seed) + ")."));

        std::vector<std::vector<unsigned int>> neighbours(n);
        if (dt.dimension() == 3)
          for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
            {
              const unsigned int a = e->first->vertex(e->second)->info(), b = e->first->vertex(e->third)->info();
              neighbours[a].push_back(b);
              neighbours[b].push_back(a);
            }
        else
          // the generators lie in a plane or on a line (three or fewer, or a
          // degenerate set): every other generator is a candidate
          for (unsigned int a = 0; a < n; ++a)
            for (unsigned int b = 0; b < n; ++b)
              if (a != b)
                neighbours[a].push_back(b);

        const ClipPolyhedron        box = box_polyhedron(L);
        std::vector<ClipPolyhedron> cells(n);
        ClipScratch                 scratch;
        for (unsigned int i = 0; i < n; ++i)
          {
            const Pt &z   = sites[i];
            auto     &nbs = neighbours[i];
            std::sort(nbs.begin(), nbs.end(), [&](const unsigned int a, const unsigned int b) {
              return z.distance_square(sites[a]) < z.distance_square(sites[b]);
            });
            ClipPolyhedron cell = box;
            // the cell lies in the ball about z through its farthest vertex:
            // a bisector beyond it (and every later one, farther still) cuts
            // nothing
            double radius = 0;
            for (const auto &face : cell)
              for (const auto &p : face.points)
                radius = std::max(radius, z.distance(p.x));
            for (const unsigned int j : nbs)
              {
                const double half = z.distance(sites[j]) / 2;
                if (half > radius + eps)
                  break;
                const Vec n_ij = (sites[j] - z) / (2 * half);
                const Pt  mid  = z + 0.5 * (sites[j] - z);
                if (clip(cell, n_ij, n_ij * mid, int(j), eps, scratch))
                  {
                    radius = 0;
                    for (const auto &face : cell)
                      for (const auto &p : face.points)
                        radius = std::max(radius, z.distance(p.x));
                  }
              }
            cells[i] = std::move(cell);
          }
        return cells;
      }

      // A spatial hash of points: a point within @p tol of one inserted
      // before is given that point's index.
      class PointMerger
      {
      public:
        explicit PointMerger(const double tol)
          : tol(tol)
        {}

        unsigned int
        find_or_add(const Pt &p)
        {
          const std::array<std::int64_t, 3> b = bucket(p);
          for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
              for (std::int64_t dz = -1; dz <= 1; ++dz)
                {
                  const auto it = buckets.find(key({{b[0] + dx, b[1] + dy, b[2] + dz}}));
                  if (it != buckets.end())
                    for (const unsigned int v : it->second)
                      if (points[v].distance(p) <= tol)
                        return v;
                }
          points.push_back(p);
          buckets[key(b)].push_back(points.size() - 1);
          return points.size() - 1;
        }

        const Pt &
        point(const unsigned int v) const
        {
          return points[v];
        }

      private:
        std::array<std::int64_t, 3>
        bucket(const Pt &p) const
        {
          return {{std::int64_t(std::floor(p[0] / tol)), std::int64_t(std::floor(p[1] / tol)),
                   std::int64_t(std::floor(p[2] / tol))}};
        }

        static std::uint64_t
        key(const std::array<std::int64_t, 3> &b)
        {
          // (a hash of the three bucket numbers: two buckets of the same
          // hash share a list, whose points are compared by their distance)
          std::uint64_t h = 1469598103934665603ull;
          for (const std::int64_t c : b)
            h = (h ^ std::uint64_t(c)) * 1099511628211ull;
          return h;
        }

        double                                                   tol;
        std::vector<Pt>                                          points;
        std::unordered_map<std::uint64_t, std::vector<unsigned>> buckets;
      };

      // @p loop itself if its points @p p lie in a plane to round-off
      // (@p round_off) and to a quarter of the planarity tolerance of
      // PolyhedralMesh::finalize() (1e-8 times the diameter), otherwise a fan
      // of triangles. A Voronoi face is planar to round-off, but where the
      // diagram is nearly degenerate (Lloyd's iteration near a symmetric
      // configuration: more than four generators nearly cospherical) the
      // vertices of a face are merged ones or computed at planes meeting at
      // small angles, and a face can be warped by 1e-9 of the box. The fan
      // starts at the vertex whose smallest triangle is largest (no sliver
      // from three nearly collinear vertices where another apex avoids it).
      std::vector<std::vector<unsigned int>>
      planar_pieces(const std::vector<unsigned int> &loop, const std::vector<Pt> &p, const double round_off)
      {
        const unsigned int m = loop.size();
        if (m == 3)
          return {loop};
        Vec    area;
        Pt     average;
        double diameter = 0;
        for (unsigned int k = 0; k < m; ++k)
          {
            if (k >= 1 && k + 1 < m)
              area += dealii::cross_product_3d(p[k] - p[0], p[k + 1] - p[0]);
            average += (p[k] - Pt()) / m;
            for (unsigned int l = k + 1; l < m; ++l)
              diameter = std::max(diameter, p[k].distance(p[l]));
          }
        double warp = 0;
        if (area.norm() > 0)
          for (unsigned int k = 0; k < m; ++k)
            warp = std::max(warp, std::abs(area * (p[k] - average)) / area.norm());
        if (area.norm() > 0 && warp <= std::min(round_off, 0.25e-8 * diameter))
          return {loop};

        unsigned int apex = 0;
        double       best = -1;
        for (unsigned int a = 0; a < m; ++a)
          {
            double smallest = std::numeric_limits<double>::max();
            for (unsigned int k = 1; k + 1 < m; ++k)
              smallest =
                std::min(smallest, dealii::cross_product_3d(p[(a + k) % m] - p[a], p[(a + k + 1) % m] - p[a]).norm());
            if (smallest > best)
              {
                best = smallest;
                apex = a;
              }
          }
        std::vector<std::vector<unsigned int>> triangles;
        for (unsigned int k = 1; k + 1 < m; ++k)
          triangles.push_back({loop[apex], loop[(apex + k) % m], loop[(apex + k + 1) % m]});
        return triangles;
      }

      // The cells of the last iteration into @p mesh (not finalized): the
      // vertices merged within @p tol and put on the sides of the box [0, L]
      // within @p tol, then moved by @p lower (a coordinate on the upper side
      // becomes upper[d] exactly). Each interior face is taken from the cell
      // of smaller index and reversed for the other one; a face that is not
      // planar to @p round_off is split into triangles (planar_pieces()).
      void
      add_cells(PolyhedralMesh                    &mesh,
                const std::vector<ClipPolyhedron> &cells,
                const Pt                          &L,
                const Pt                          &lower,
                const Pt                          &upper,
                const double                       tol,
                const double                       round_off)
      {
        const unsigned int n = cells.size();
        PointMerger        merger(tol);
        // a vertex named by its four planes (ClipVertex) is placed where it
        // was computed first, and every copy of it is given that point
        struct NameHash
        {
          std::size_t
          operator()(const std::array<int, 4> &a) const
          {
            std::size_t h = 0;
            for (const int x : a)
              h = h * 1000003u + std::size_t(std::uint32_t(x));
            return h;
          }
        };
        std::unordered_map<std::array<int, 4>, unsigned int, NameHash> point_of_name;
        auto                                                           find_or_add = [&](Pt p) {
          for (unsigned int d = 0; d < 3; ++d)
            if (std::abs(p[d]) <= tol)
              p[d] = 0;
            else if (std::abs(p[d] - L[d]) <= tol)
              p[d] = L[d];
          return merger.find_or_add(p);
        };

        // the face loops of every cell, as merged point indices, with labels
        std::vector<std::vector<std::pair<int, std::vector<unsigned int>>>> loops(n);
        for (unsigned int i = 0; i < n; ++i)
          for (const auto &face : cells[i])
            {
              std::vector<unsigned int> loop;
              for (const ClipVertex &cv : face.points)
                {
                  unsigned int v;
                  if (cv.planes[0] == no_plane)
                    v = find_or_add(cv.x);
                  else
                    {
                      std::array<int, 4> name{{int(i), cv.planes[0], cv.planes[1], cv.planes[2]}};
                      std::sort(name.begin(), name.end());
                      const auto found = point_of_name.find(name);
                      if (found != point_of_name.end())
                        v = found->second;
                      else
                        {
                          v = find_or_add(cv.x);
                          point_of_name.emplace(name, v);
                        }
                    }
                  if (loop.empty() || loop.back() != v)
                    loop.push_back(v);
                }
              while (loop.size() > 1 && loop.front() == loop.back())
                loop.pop_back();
              if (loop.size() >= 3)
                loops[i].emplace_back(face.label, std::move(loop));
            }

        // the mesh's vertices: in the order of first use
        std::vector<unsigned int> mesh_index;
        std::vector<Pt>           mesh_point;
        auto                      vertex = [&](const unsigned int v) {
          if (v >= mesh_index.size())
            mesh_index.resize(v + 1, dealii::numbers::invalid_unsigned_int);
          if (mesh_index[v] == dealii::numbers::invalid_unsigned_int)
            {
              const Pt &p = merger.point(v);
              Pt        q;
              for (unsigned int d = 0; d < 3; ++d)
                q[d] = (p[d] == 0 ? lower[d] : p[d] == L[d] ? upper[d] : lower[d] + p[d]);
              mesh_index[v] = mesh.add_vertex(q);
              mesh_point.push_back(q);
            }
          return mesh_index[v];
        };
        // a loop of merged points as planar loops of mesh vertices
        std::vector<Pt> p;
        auto            pieces = [&](const std::vector<unsigned int> &merged_loop) {
          std::vector<unsigned int> loop;
          p.clear();
          for (const unsigned int v : merged_loop)
            {
              loop.push_back(vertex(v));
              p.push_back(mesh_point[loop.back()]);
            }
          return planar_pieces(loop, p, round_off);
        };

        // interior faces: the loop of the cell of smaller index, its
        // vertex set for the check of the other side, its planar pieces
        struct SharedFace
        {
          std::vector<unsigned int>              sorted;
          std::vector<std::vector<unsigned int>> pieces;
          bool                                   matched = false;
        };
        std::map<std::pair<unsigned int, unsigned int>, SharedFace> shared;

        for (unsigned int i = 0; i < n; ++i)
          {
            std::vector<std::vector<unsigned int>> face_loops;
            for (const auto &lf : loops[i])
              {
                if (lf.first >= 0 && unsigned(lf.first) < i)
                  {
                    const unsigned int j   = lf.first;
                    const auto         it  = shared.find({j, i});
                    auto               own = lf.second;
                    std::sort(own.begin(), own.end());
                    AssertThrow(it != shared.end() && it->second.sorted == own,
                                dealii::ExcMessage("voronoi_box: the common face of cells " + std::to_string(j) +
                                                   " and " + std::to_string(i) +
                                                   " has different vertices in the two cells after merging "
                                                   "(a nearly degenerate Voronoi diagram); internal error."));
                    it->second.matched = true;
                    for (const auto &piece : it->second.pieces)
                      face_loops.emplace_back(piece.rbegin(), piece.rend());
                  }
                else
                  {
                    auto face_pieces = pieces(lf.second);
                    face_loops.insert(face_loops.end(), face_pieces.begin(), face_pieces.end());
                    if (lf.first >= 0)
                      {
                        SharedFace &sf = shared[{i, unsigned(lf.first)}];
                        sf.sorted      = lf.second;
                        std::sort(sf.sorted.begin(), sf.sorted.end());
                        sf.pieces = std::move(face_pieces);
                      }
                  }
              }
            mesh.add_cell(face_loops);
          }
        for (const auto &[pair, sf] : shared)
          AssertThrow(sf.matched, dealii::ExcMessage(
                                    "voronoi_box: the common face of cells " + std::to_string(pair.first) + " and " +
                                    std::to_string(pair.second) + " is missing in cell " + std::to_string(pair.second) +
                                    " after merging the vertices (a nearly degenerate Voronoi diagram); "
                                    "internal error."));
      }
#endif
    } // namespace
  }   // namespace polyhedral_generators_internal



  namespace PolyhedralMeshGenerators
  {
    void
    hyper_rectangle(PolyhedralMesh                   &mesh,
                    const dealii::Point<3>           &lower,
                    const dealii::Point<3>           &upper,
                    const std::array<unsigned int, 3> subdivisions)
    {
      using namespace polyhedral_generators_internal;
      check_box(lower, upper, "hyper_rectangle");
      const unsigned int nx = subdivisions[0], ny = subdivisions[1], nz = subdivisions[2];
      AssertThrow(nx >= 1 && ny >= 1 && nz >= 1,
                  dealii::ExcMessage("hyper_rectangle: the numbers of subdivisions must be at least 1."));
      mesh.clear();
      mesh.name = "hyper_rectangle " + std::to_string(nx) + "x" + std::to_string(ny) + "x" + std::to_string(nz);
      // (the last vertex of a row is the upper corner's coordinate exactly)
      auto coordinate = [&](const unsigned int d, const unsigned int i) {
        return i == subdivisions[d] ? upper[d] : lower[d] + (upper[d] - lower[d]) * i / subdivisions[d];
      };
      for (unsigned int k = 0; k <= nz; ++k)
        for (unsigned int j = 0; j <= ny; ++j)
          for (unsigned int i = 0; i <= nx; ++i)
            mesh.add_vertex(Pt(coordinate(0, i), coordinate(1, j), coordinate(2, k)));
      auto v = [&](const unsigned int i, const unsigned int j, const unsigned int k) {
        return (k * (ny + 1) + j) * (nx + 1) + i;
      };
      for (unsigned int k = 0; k < nz; ++k)
        for (unsigned int j = 0; j < ny; ++j)
          for (unsigned int i = 0; i < nx; ++i)
            mesh.add_cell({{v(i, j, k), v(i, j, k + 1), v(i, j + 1, k + 1), v(i, j + 1, k)},                   // x-
                           {v(i + 1, j, k), v(i + 1, j + 1, k), v(i + 1, j + 1, k + 1), v(i + 1, j, k + 1)},   // x+
                           {v(i, j, k), v(i + 1, j, k), v(i + 1, j, k + 1), v(i, j, k + 1)},                   // y-
                           {v(i, j + 1, k), v(i, j + 1, k + 1), v(i + 1, j + 1, k + 1), v(i + 1, j + 1, k)},   // y+
                           {v(i, j, k), v(i, j + 1, k), v(i + 1, j + 1, k), v(i + 1, j, k)},                   // z-
                           {v(i, j, k + 1), v(i + 1, j, k + 1), v(i + 1, j + 1, k + 1), v(i, j + 1, k + 1)}}); // z+
      finish_box(mesh, lower, upper);
    }



    void
    voronoi_box(PolyhedralMesh         &mesh,
                const dealii::Point<3> &lower,
                const dealii::Point<3> &upper,
                const unsigned int      n_cells,
                const unsigned int      lloyd_iterations,
                const unsigned int      seed)
    {
      using namespace polyhedral_generators_internal;
      check_box(lower, upper, "voronoi_box");
      AssertThrow(n_cells >= 1, dealii::ExcMessage("voronoi_box: at least one cell is needed."));
#ifndef DEALVEM_WITH_CGAL
      (void)mesh;
      (void)lloyd_iterations;
      (void)seed;
      AssertThrow(false, dealii::ExcMessage("voronoi_box: dealvem was configured without CGAL; the Voronoi mesh "
                                            "generator needs it (install CGAL, e.g. apt-get install libcgal-dev, and "
                                            "configure dealvem again with -DDEALVEM_WITH_CGAL=ON), or use "
                                            "hyper_rectangle()."));
#else
      // computed on the box moved to the origin (see the documentation)
      const Pt     L(upper[0] - lower[0], upper[1] - lower[1], upper[2] - lower[2]);
      const double diag = L.norm();

      std::mt19937                           rng(seed);
      std::uniform_real_distribution<double> ux(0, L[0]), uy(0, L[1]), uz(0, L[2]);
      std::vector<Pt>                        sites(n_cells);
      for (auto &s : sites)
        {
          // (one draw per statement: the order of evaluation of the
          // arguments of a call is unspecified)
          const double x = ux(rng), y = uy(rng), z = uz(rng);
          s = Pt(x, y, z);
        }

      std::vector<ClipPolyhedron> cells;
      for (unsigned int iteration = 0; iteration <= lloyd_iterations; ++iteration)
        {
          cells = voronoi_cells(sites, L, seed);
          if (iteration == lloyd_iterations)
            break;
          for (unsigned int i = 0; i < n_cells; ++i)
            {
              const auto vc = volume_and_centroid(cells[i], sites[i]);
              if (vc.first > 0)
                sites[i] = vc.second;
            }
        }

      mesh.clear();
      mesh.name = "voronoi_box " + std::to_string(n_cells) + " cells, seed " + std::to_string(seed);
      // Vertices closer than 1e-7 of the box's size are merged: a face that
      // small would be refused by finalize() (the round-off of coordinates
      // of size |x| is 1e-16 |x|, 1e-8 of a face's diameter is the planarity
      // tolerance), and the nearly degenerate diagrams of Lloyd's iteration
      // near a symmetric configuration have edges of any small length.
      double size = diag;
      for (unsigned int d = 0; d < 3; ++d)
        size = std::max({size, std::abs(lower[d]), std::abs(upper[d])});
      // (a face warped by more than 1e-13 of it is split into triangles)
      add_cells(mesh, cells, L, lower, upper, 1e-7 * size, 1e-13 * size);
      finish_box(mesh, lower, upper);
      const double box_volume = L[0] * L[1] * L[2];
      AssertThrow(std::abs(mesh.total_volume() - box_volume) <= 1e-10 * box_volume,
                  dealii::ExcMessage("voronoi_box: the cells do not fill the box; internal error."));
#endif
    }
  } // namespace PolyhedralMeshGenerators
} // namespace dealvem
