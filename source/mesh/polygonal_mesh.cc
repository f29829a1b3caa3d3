// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/base/number_string.h>
#include <dealvem/mesh/polygonal_mesh.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <unordered_map>

namespace dealvem
{
  namespace
  {
    using P = dealii::Point<2>;

    // Coordinates beyond this magnitude are refused: the geometric checks
    // multiply coordinate differences and sum such products over a loop,
    // which must stay far from overflow.
    constexpr double max_coordinate = 1e100;
    // The smallest extent of a mesh (largest side of its bounding box).
    constexpr double min_extent = 1e-100;

    inline double
    cross(const P &o, const P &a, const P &b)
    {
      return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    }

    inline std::pair<unsigned int, unsigned int>
    key(const unsigned int a, const unsigned int b)
    {
      return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
    }

    using internal::point_string;

    // finite coordinates of at most max_coordinate in magnitude
    void
    check_coordinates(const std::string &mesh_name, const unsigned int v, const P &p)
    {
      AssertThrow(std::isfinite(p[0]) && std::isfinite(p[1]),
                  ExcInvalidMesh("mesh '" + mesh_name + "': vertex " + std::to_string(v) +
                                 " has a non-finite coordinate."));
      AssertThrow(std::abs(p[0]) <= max_coordinate && std::abs(p[1]) <= max_coordinate,
                  ExcInvalidMesh("mesh '" + mesh_name + "': vertex " + std::to_string(v) + " at " + point_string(p) +
                                 " has a coordinate larger than 1e100 in magnitude; such coordinates are not "
                                 "supported."));
    }

    // Proper crossing of segments ab and cd (interiors cross at one point),
    // with a tolerance relative to the segment lengths.
    bool
    segments_cross(const P &a, const P &b, const P &c, const P &d)
    {
      const double l  = std::max(a.distance(b), c.distance(d));
      const double t  = 1e-12 * l * l;
      const double d1 = cross(a, b, c), d2 = cross(a, b, d);
      const double d3 = cross(c, d, a), d4 = cross(c, d, b);
      return ((d1 > t && d2 < -t) || (d1 < -t && d2 > t)) &&
             ((d3 > t && d4 < -t) || (d3 < -t && d4 > t));
    }

    // Collinear overlap of segments ab and cd (sharing more than a point).
    bool
    segments_overlap(const P &a, const P &b, const P &c, const P &d)
    {
      const double l = std::max(a.distance(b), c.distance(d));
      const double t = 1e-12 * l * l;
      if (std::abs(cross(a, b, c)) > t || std::abs(cross(a, b, d)) > t)
        return false;
      const dealii::Tensor<1, 2> u  = (b - a) / a.distance(b);
      const double               s0 = 0, s1 = (b - a) * u;
      double                     r0 = (c - a) * u, r1 = (d - a) * u;
      if (r0 > r1)
        std::swap(r0, r1);
      return std::min(s1, r1) - std::max(s0, r0) > 1e-10 * l;
    }

    // A uniform bucket grid over a bounding box. Items outside the box (or
    // with NaN coordinates) go to the nearest bucket, so any input gives a
    // valid bucket index; a box that is empty, a single point or not finite
    // gets a single bucket (correct, only slower).
    struct Grid
    {
      P            lo;
      double       h  = 1;
      unsigned int nx = 1, ny = 1;
      std::vector<std::vector<unsigned int>> buckets;

      Grid(const P &lo_, const P &hi, const unsigned int n_items)
        : lo(lo_)
      {
        const double w = hi[0] - lo[0], ht = hi[1] - lo[1];
        const double extent = std::max(w, ht);
        const bool   usable = std::isfinite(lo[0]) && std::isfinite(lo[1]) && std::isfinite(w) &&
                            std::isfinite(ht) && w >= 0 && ht >= 0 && extent > 0;
        if (usable)
          {
            // about one item per bucket, at most 2048 buckets along a side;
            // sqrt of each factor avoids overflowing w * ht
            const double n = std::max(1u, n_items);
            h              = std::max(std::sqrt(w / n) * std::sqrt(ht), extent / 2048.);
            if (h > 0 && std::isfinite(h))
              {
                nx = 1 + static_cast<unsigned int>(std::min(2048., std::floor(w / h)));
                ny = 1 + static_cast<unsigned int>(std::min(2048., std::floor(ht / h)));
              }
            else
              h = 1;
          }
        buckets.resize(std::size_t(nx) * ny);
      }

      // bucket index of the scaled coordinate r in 0..n-1: clamped in double
      // before the conversion (NaN and r <= 0 give 0)
      static unsigned int
      index(const double r, const unsigned int n)
      {
        if (!(r > 0))
          return 0;
        if (r >= double(n - 1))
          return n - 1;
        return static_cast<unsigned int>(r);
      }
      unsigned int
      ix(const double x) const
      {
        return index((x - lo[0]) / h, nx);
      }
      unsigned int
      iy(const double y) const
      {
        return index((y - lo[1]) / h, ny);
      }
      void
      insert_box(const P &a, const P &b, const unsigned int item)
      {
        for (unsigned int i = ix(std::min(a[0], b[0])); i <= ix(std::max(a[0], b[0])); ++i)
          for (unsigned int j = iy(std::min(a[1], b[1])); j <= iy(std::max(a[1], b[1])); ++j)
            buckets[std::size_t(j) * nx + i].push_back(item);
      }
      template <typename F>
      void
      query_box(const P &a, const P &b, F &&f) const
      {
        for (unsigned int i = ix(std::min(a[0], b[0])); i <= ix(std::max(a[0], b[0])); ++i)
          for (unsigned int j = iy(std::min(a[1], b[1])); j <= iy(std::max(a[1], b[1])); ++j)
            for (const auto item : buckets[std::size_t(j) * nx + i])
              f(item);
      }
    };



    // validate(), for each cell: no edge of the loop crosses, touches or
    // folds back onto another one (@p cname names the cell in messages).
    void
    check_loop_is_simple(const std::string &cname, const std::vector<P> &vertices,
                         const std::vector<unsigned int> &loop)
    {
      const unsigned int n = loop.size();
      for (unsigned int i = 0; i < n; ++i)
        {
          const P &a = vertices[loop[i]], &b = vertices[loop[(i + 1) % n]];
          for (unsigned int j = i + 1; j < n; ++j)
            {
              const P   &c2 = vertices[loop[j]], &d = vertices[loop[(j + 1) % n]];
              const bool adjacent = (j == i + 1) || (i == 0 && j == n - 1);
              bool       bad      = segments_overlap(a, b, c2, d);
              if (!adjacent)
                {
                  bad = bad || segments_cross(a, b, c2, d);
                  // a vertex of one edge on the other edge
                  const double L = std::max(a.distance(b), c2.distance(d));
                  auto on = [&](const P &p, const P &s0, const P &s1) {
                    const double len = s0.distance(s1);
                    const double s   = (p - s0) * (s1 - s0) / (len * len);
                    return s > 1e-12 && s < 1 - 1e-12 && std::abs(cross(s0, s1, p)) <= 1e-12 * L * len;
                  };
                  bad = bad || on(c2, a, b) || on(d, a, b) || on(a, c2, d) || on(b, c2, d);
                }
              AssertThrow(!bad, ExcInvalidMesh(cname + " is self-intersecting (edges " + std::to_string(i) +
                                               " and " + std::to_string(j) + " of its loop intersect)."));
            }
        }
    }



    // validate(), step 1: cell @p c (vertex loop @p loop) has at least 3
    // vertices, finite coordinates, no repeated vertex, a simple loop and a
    // positive area. Returns its diameter; widens the box [@p lo, @p hi].
    double
    check_cell(const std::string &mesh_name, const std::vector<P> &vertices, const unsigned int c,
               const std::vector<unsigned int> &loop, P &lo, P &hi)
    {
      const unsigned int n     = loop.size();
      const std::string  cname = "mesh '" + mesh_name + "': cell " + std::to_string(c);
      AssertThrow(n >= 3, ExcInvalidMesh(cname + " has fewer than 3 vertices."));
      double h = 0, area = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          const P &p = vertices[loop[i]];
          check_coordinates(mesh_name, loop[i], p);
          for (unsigned int d = 0; d < 2; ++d)
            {
              lo[d] = std::min(lo[d], p[d]);
              hi[d] = std::max(hi[d], p[d]);
            }
          for (unsigned int j = i + 1; j < n; ++j)
            h = std::max(h, p.distance(vertices[loop[j]]));
          area += cross(vertices[loop[0]], p, vertices[loop[(i + 1) % n]]);
        }
      area *= 0.5;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = i + 1; j < n; ++j)
          AssertThrow(loop[i] != loop[j] && vertices[loop[i]].distance(vertices[loop[j]]) > 1e-12 * h,
                      ExcInvalidMesh(cname + " has a repeated vertex (" + std::to_string(loop[i]) + " and " +
                                     std::to_string(loop[j]) + " at " + point_string(vertices[loop[j]]) + ")."));
      {
        // all vertices on one line: zero area (reported before the
        // self-intersection that such a loop also has)
        unsigned int far = 0;
        for (unsigned int i = 1; i < n; ++i)
          if (vertices[loop[i]].distance(vertices[loop[0]]) > vertices[loop[far]].distance(vertices[loop[0]]))
            far = i;
        bool collinear = true;
        for (unsigned int i = 0; i < n; ++i)
          collinear = collinear && std::abs(cross(vertices[loop[0]], vertices[loop[far]], vertices[loop[i]])) <=
                                     1e-12 * h * h;
        AssertThrow(!collinear, ExcInvalidMesh(cname + " has zero area (its vertices are collinear)."));
      }
      // self-intersection: non-adjacent edges crossing or touching, or
      // adjacent edges folding back onto each other
      check_loop_is_simple(cname, vertices, loop);
      AssertThrow(std::abs(area) > 1e-14 * h * h,
                  ExcInvalidMesh(cname + " has zero area (its vertices are collinear)."));
      AssertThrow(area > 0, ExcInvalidMesh(cname + " is clockwise (signed area " + std::to_string(area) +
                                           "); cells must be counter-clockwise vertex loops."));
      return h;
    }



    // validate(), step 2: no two distinct vertices of one body at the same
    // point (within 1e-10 of the smaller diameter @p diam of the cells
    // around them): the body would be cut there (a slit) where the mesh
    // looks connected. Found through a bucket grid of the vertices.
    template <typename CellType>
    void
    check_no_slits(const std::string &mesh_name, const std::vector<P> &vertices, const std::vector<CellType> &cells,
                   const std::vector<std::vector<unsigned int>> &vertex_cells, const std::vector<double> &diam,
                   const P &lo, const P &hi)
    {
      std::vector<double> vertex_h(vertices.size(), 0);
      for (unsigned int v = 0; v < vertices.size(); ++v)
        for (const unsigned int c : vertex_cells[v])
          vertex_h[v] = (vertex_h[v] == 0 ? diam[c] : std::min(vertex_h[v], diam[c]));
      Grid vertex_grid(lo, hi, vertices.size());
      for (unsigned int v = 0; v < vertices.size(); ++v)
        if (!vertex_cells[v].empty())
          vertex_grid.insert_box(vertices[v], vertices[v], v);
      const auto same_body = [&](const unsigned int v, const unsigned int w) {
        for (const unsigned int c : vertex_cells[v])
          for (const unsigned int d : vertex_cells[w])
            if (cells[c].material_id == cells[d].material_id)
              return true;
        return false;
      };
      for (unsigned int v = 0; v < vertices.size(); ++v)
        {
          if (vertex_cells[v].empty())
            continue;
          const P                   &p   = vertices[v];
          const double               tol = 1e-10 * vertex_h[v];
          const dealii::Tensor<1, 2> r({tol, tol});
          vertex_grid.query_box(p - r, p + r, [&](const unsigned int w) {
            if (w <= v || p.distance(vertices[w]) > 1e-10 * std::min(vertex_h[v], vertex_h[w]) || !same_body(v, w))
              return;
            AssertThrow(false,
                        ExcInvalidMesh("mesh '" + mesh_name + "': the distinct vertices " + std::to_string(v) +
                                       " and " + std::to_string(w) + " lie at the same point " + point_string(p) +
                                       " (cell " + std::to_string(vertex_cells[v][0]) + " uses the first, cell " +
                                       std::to_string(vertex_cells[w][0]) +
                                       " the second), so the body is cut there although its cells touch. "
                                       "Merge the duplicated vertex (node) in the mesh."));
          });
        }
    }



    // validate(), step 3: no two edges of cells of one body (one material
    // id) cross or overlap unless they share a vertex.
    template <typename CellType, typename EdgeType>
    void
    check_no_crossing_edges(const std::string &mesh_name, const std::vector<P> &vertices,
                            const std::vector<CellType> &cells, const std::vector<EdgeType> &edges, const P &lo,
                            const P &hi)
    {
      Grid edge_grid(lo, hi, edges.size());
      for (unsigned int e = 0; e < edges.size(); ++e)
        edge_grid.insert_box(vertices[edges[e].vertices[0]], vertices[edges[e].vertices[1]], e);
      std::vector<unsigned int> stamp(edges.size(), dealii::numbers::invalid_unsigned_int);
      for (unsigned int e = 0; e < edges.size(); ++e)
        {
          const auto &E = edges[e];
          const P    &a = vertices[E.vertices[0]], &b = vertices[E.vertices[1]];
          const auto  m = cells[E.cells[0]].material_id;
          edge_grid.query_box(a, b, [&](const unsigned int f) {
            if (f <= e || stamp[f] == e)
              return;
            stamp[f]      = e;
            const auto &F = edges[f];
            if (cells[F.cells[0]].material_id != m)
              return;
            if (F.vertices[0] == E.vertices[0] || F.vertices[0] == E.vertices[1] || F.vertices[1] == E.vertices[0] ||
                F.vertices[1] == E.vertices[1])
              return;
            const P &c2 = vertices[F.vertices[0]], &d = vertices[F.vertices[1]];
            AssertThrow(!segments_cross(a, b, c2, d) && !segments_overlap(a, b, c2, d),
                        ExcInvalidMesh("mesh '" + mesh_name + "': overlapping cells " + std::to_string(E.cells[0]) +
                                       " and " + std::to_string(F.cells[0]) + " (their edges cross near " +
                                       point_string(a) + ")."));
          });
        }
    }



    // validate(), step 4: no vertex lies strictly inside a cell of its own
    // body that does not use it (by the winding number).
    template <typename CellType>
    void
    check_no_vertex_inside_cells(const std::string &mesh_name, const std::vector<P> &vertices,
                                 const std::vector<CellType>                  &cells,
                                 const std::vector<std::vector<unsigned int>> &vertex_cells,
                                 const std::vector<double> &diam, const P &lo, const P &hi)
    {
      Grid cell_grid(lo, hi, cells.size());
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          P clo(1e300, 1e300), chi(-1e300, -1e300);
          for (const auto v : cells[c].vertices)
            for (unsigned int d = 0; d < 2; ++d)
              {
                clo[d] = std::min(clo[d], vertices[v][d]);
                chi[d] = std::max(chi[d], vertices[v][d]);
              }
          cell_grid.insert_box(clo, chi, c);
        }
      for (unsigned int v = 0; v < vertices.size(); ++v)
        {
          if (vertex_cells[v].empty())
            continue;
          const P   &p = vertices[v];
          const auto m = cells[vertex_cells[v][0]].material_id;
          cell_grid.query_box(p, p, [&](const unsigned int c) {
            if (cells[c].material_id != m)
              return;
            const auto &loop = cells[c].vertices;
            if (std::find(loop.begin(), loop.end(), v) != loop.end())
              return;
            // strictly inside: winding number != 0 and not on the boundary
            const unsigned int n       = loop.size();
            int                winding = 0;
            for (unsigned int i = 0; i < n; ++i)
              {
                const P     &a = vertices[loop[i]], &b = vertices[loop[(i + 1) % n]];
                const double L = a.distance(b);
                const double s = (p - a) * (b - a) / (L * L);
                if (s >= -1e-12 && s <= 1 + 1e-12 && std::abs(cross(a, b, p)) <= 1e-10 * L * diam[c])
                  return; // on the boundary
                if (a[1] <= p[1])
                  {
                    if (b[1] > p[1] && cross(a, b, p) > 0)
                      ++winding;
                  }
                else if (b[1] <= p[1] && cross(a, b, p) < 0)
                  --winding;
              }
            AssertThrow(winding == 0,
                        ExcInvalidMesh("mesh '" + mesh_name + "': overlapping cells: vertex " + std::to_string(v) +
                                       " " + point_string(p) + " of cell " + std::to_string(vertex_cells[v][0]) +
                                       " lies inside cell " + std::to_string(c) + "."));
          });
        }
    }
  } // namespace



  namespace internal
  {
    std::uint64_t
    new_mesh_revision()
    {
      static std::atomic<std::uint64_t> counter{0};
      return ++counter;
    }
  } // namespace internal



  template <int dim>
  void
  PolygonalMesh<dim>::clear()
  {
    vertices.clear();
    cells.clear();
    edges.clear();
    boundary_ids_by_pair.clear();
    changed("clear()");
  }



  template <int dim>
  unsigned int
  PolygonalMesh<dim>::add_vertex(const dealii::Point<dim> &p)
  {
    vertices.push_back(p);
    changed("add_vertex()");
    return vertices.size() - 1;
  }



  template <int dim>
  unsigned int
  PolygonalMesh<dim>::add_cell(const std::vector<unsigned int>  &loop,
                               const dealii::types::material_id material_id)
  {
    Cell c;
    c.vertices    = loop;
    c.material_id = material_id;
    cells.push_back(c);
    edges.clear();
    changed("add_cell()");
    return cells.size() - 1;
  }



  template <int dim>
  void
  PolygonalMesh<dim>::set_boundary_id(const unsigned int               v0,
                                      const unsigned int               v1,
                                      const dealii::types::boundary_id id)
  {
    boundary_ids_by_pair[key(v0, v1)] = id;
    for (auto &e : edges)
      if (key(e.vertices[0], e.vertices[1]) == key(v0, v1) && e.at_boundary())
        e.boundary_id = id;
  }



  template <int dim>
  void
  PolygonalMesh<dim>::set_edge_boundary_id(const unsigned int e, const dealii::types::boundary_id id)
  {
    AssertThrow(e < edges.size() && edges[e].at_boundary(),
                dealii::ExcMessage("set_edge_boundary_id: edge " + std::to_string(e) +
                                   " is not a boundary edge of mesh '" + name + "'."));
    edges[e].boundary_id = id;
    boundary_ids_by_pair[key(edges[e].vertices[0], edges[e].vertices[1])] = id;
  }



  template <int dim>
  std::vector<dealii::Point<dim>>
  PolygonalMesh<dim>::cell_vertices(const unsigned int c) const
  {
    std::vector<dealii::Point<dim>> p;
    cell_vertices(c, p);
    return p;
  }



  template <int dim>
  void
  PolygonalMesh<dim>::cell_vertices(const unsigned int               c,
                                    std::vector<dealii::Point<dim>> &points) const
  {
    points.resize(cells[c].vertices.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      points[i] = vertices[cells[c].vertices[i]];
  }



  template <int dim>
  void
  PolygonalMesh<dim>::finalize(const double relative_tolerance)
  {
    // (1) checks on the raw loops that the later steps rely on
    for (unsigned int v = 0; v < vertices.size(); ++v)
      check_coordinates(name, v, vertices[v]);
    // a mesh far below the scale of double precision: areas and the
    // geometric tolerances (products of coordinate differences) underflow,
    // and the checks below would report zero areas or repeated vertices
    if (!vertices.empty())
      {
        P lo = vertices[0], hi = vertices[0];
        for (const auto &p : vertices)
          for (unsigned int d = 0; d < 2; ++d)
            {
              lo[d] = std::min(lo[d], p[d]);
              hi[d] = std::max(hi[d], p[d]);
            }
        const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
        AssertThrow(extent == 0 || extent >= min_extent,
                    ExcInvalidMesh("mesh '" + name + "': its vertices span only " + [&] {
                      std::ostringstream e;
                      e << extent << " (from " << point_string(lo) << " to " << point_string(hi) << ")";
                      return e.str();
                    }() + "; meshes smaller than 1e-100 are not supported, because the areas and geometric "
                          "tolerances (products of coordinate differences) underflow. Give the coordinates "
                          "in a length unit nearer to the size of the mesh."));
      }
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        const auto &loop = cells[c].vertices;
        AssertThrow(loop.size() >= 3,
                    ExcInvalidMesh("mesh '" + name + "': cell " + std::to_string(c) + " has " +
                                   std::to_string(loop.size()) +
                                   " vertices; a polygon needs at least 3."));
        std::set<unsigned int> seen;
        for (const auto v : loop)
          {
            AssertThrow(v < vertices.size(),
                        ExcInvalidMesh("mesh '" + name + "': cell " + std::to_string(c) +
                                       " refers to vertex " + std::to_string(v) + ", but there are only " +
                                       std::to_string(vertices.size()) + " vertices."));
            AssertThrow(seen.insert(v).second,
                        ExcInvalidMesh("mesh '" + name + "': cell " + std::to_string(c) +
                                       " has a repeated vertex " + std::to_string(v) + " in its loop."));
          }
      }
    insert_hanging_vertices(relative_tolerance);
    remove_unused_vertices();
    build_edges();
    validate();
    changed("finalize()");
  }



  template <int dim>
  void
  PolygonalMesh<dim>::insert_hanging_vertices(const double tol)
  {
    if (cells.empty())
      return;
    // materials using each vertex
    std::vector<std::vector<dealii::types::material_id>> vmat(vertices.size());
    for (const auto &c : cells)
      for (const auto v : c.vertices)
        if (std::find(vmat[v].begin(), vmat[v].end(), c.material_id) == vmat[v].end())
          vmat[v].push_back(c.material_id);
    P lo(1e300, 1e300), hi(-1e300, -1e300);
    unsigned int n_used = 0;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (!vmat[v].empty())
        {
          ++n_used;
          for (unsigned int d = 0; d < 2; ++d)
            {
              lo[d] = std::min(lo[d], vertices[v][d]);
              hi[d] = std::max(hi[d], vertices[v][d]);
            }
        }
    Grid grid(lo, hi, n_used);
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (!vmat[v].empty())
        grid.insert_box(vertices[v], vertices[v], v);

    for (auto &cell : cells)
      {
        std::vector<unsigned int> new_loop;
        const unsigned int        n = cell.vertices.size();
        bool                      changed = false;
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int a = cell.vertices[i], b = cell.vertices[(i + 1) % n];
            new_loop.push_back(a);
            const P                          &pa = vertices[a], &pb = vertices[b];
            const double                      L  = pa.distance(pb);
            if (L == 0)
              continue;
            const dealii::Tensor<1, 2>        t  = (pb - pa) / L;
            std::vector<std::pair<double, unsigned int>> found;
            P lo_e(std::min(pa[0], pb[0]) - tol * L, std::min(pa[1], pb[1]) - tol * L);
            P hi_e(std::max(pa[0], pb[0]) + tol * L, std::max(pa[1], pb[1]) + tol * L);
            grid.query_box(lo_e, hi_e, [&](const unsigned int v) {
              if (v == a || v == b ||
                  std::find(cell.vertices.begin(), cell.vertices.end(), v) != cell.vertices.end())
                return;
              if (std::find(vmat[v].begin(), vmat[v].end(), cell.material_id) == vmat[v].end())
                return;
              const double s = (vertices[v] - pa) * t;
              if (s <= tol * L || s >= (1 - tol) * L)
                return;
              const double d = std::abs((vertices[v] - pa)[0] * t[1] - (vertices[v] - pa)[1] * t[0]);
              if (d <= tol * L)
                found.emplace_back(s, v);
            });
            if (found.empty())
              continue;
            std::sort(found.begin(), found.end());
            found.erase(std::unique(found.begin(), found.end(),
                                    [](const auto &x, const auto &y) { return x.second == y.second; }),
                        found.end());
            changed = true;
            // the pieces inherit a boundary id given to the whole edge
            const auto it = boundary_ids_by_pair.find(key(a, b));
            unsigned int prev = a;
            for (const auto &f : found)
              {
                if (it != boundary_ids_by_pair.end())
                  boundary_ids_by_pair[key(prev, f.second)] = it->second;
                new_loop.push_back(f.second);
                prev = f.second;
              }
            if (it != boundary_ids_by_pair.end())
              boundary_ids_by_pair[key(prev, b)] = it->second;
          }
        if (changed)
          cell.vertices = new_loop;
      }
  }



  template <int dim>
  void
  PolygonalMesh<dim>::remove_unused_vertices()
  {
    std::vector<unsigned int> new_index(vertices.size(), dealii::numbers::invalid_unsigned_int);
    for (const auto &c : cells)
      for (const auto v : c.vertices)
        new_index[v] = 0;
    std::vector<P> kept;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (new_index[v] == 0)
        {
          new_index[v] = kept.size();
          kept.push_back(vertices[v]);
        }
    if (kept.size() == vertices.size())
      return;
    vertices = kept;
    for (auto &c : cells)
      for (auto &v : c.vertices)
        v = new_index[v];
    std::map<std::pair<unsigned int, unsigned int>, dealii::types::boundary_id> ids;
    for (const auto &e : boundary_ids_by_pair)
      if (e.first.first < new_index.size() && e.first.second < new_index.size() &&
          new_index[e.first.first] != dealii::numbers::invalid_unsigned_int &&
          new_index[e.first.second] != dealii::numbers::invalid_unsigned_int)
        ids[key(new_index[e.first.first], new_index[e.first.second])] = e.second;
    boundary_ids_by_pair = ids;
  }



  template <int dim>
  void
  PolygonalMesh<dim>::build_edges()
  {
    edges.clear();
    std::unordered_map<std::uint64_t, unsigned int> index;
    index.reserve(4 * cells.size());
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        auto              &cell = cells[c];
        const unsigned int n    = cell.vertices.size();
        cell.edges.resize(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int  a = cell.vertices[i], b = cell.vertices[(i + 1) % n];
            const auto          k = key(a, b);
            const std::uint64_t h = (std::uint64_t(k.first) << 32) | k.second;
            const auto          it = index.find(h);
            if (it == index.end())
              {
                Edge e;
                e.vertices    = {{a, b}};
                e.cells       = {{c, dealii::numbers::invalid_unsigned_int}};
                e.boundary_id = 0;
                index[h]      = edges.size();
                cell.edges[i] = edges.size();
                edges.push_back(e);
              }
            else
              {
                Edge &e = edges[it->second];
                AssertThrow(e.at_boundary(),
                            ExcInvalidMesh("mesh '" + name + "': the edge from vertex " +
                                           std::to_string(a) + " " + point_string(vertices[a]) +
                                           " to vertex " + std::to_string(b) + " " +
                                           point_string(vertices[b]) + " is shared by more than two cells (" +
                                           std::to_string(e.cells[0]) + ", " + std::to_string(e.cells[1]) +
                                           ", " + std::to_string(c) + ")."));
                AssertThrow(e.vertices[0] == b && e.vertices[1] == a,
                            ExcInvalidMesh("mesh '" + name + "': overlapping or inconsistently oriented cells " +
                                           std::to_string(e.cells[0]) + " and " + std::to_string(c) +
                                           " (both run along the edge from vertex " + std::to_string(a) +
                                           " to vertex " + std::to_string(b) + " in the same direction)."));
                AssertThrow(cells[e.cells[0]].material_id == cell.material_id,
                            ExcInvalidMesh("mesh '" + name + "': cells " + std::to_string(e.cells[0]) +
                                           " and " + std::to_string(c) +
                                           " of different bodies (material ids) share an edge; bodies "
                                           "interact through contact only."));
                e.cells[1]    = c;
                cell.edges[i] = it->second;
              }
          }
      }
    for (auto &e : edges)
      {
        if (!e.at_boundary())
          e.boundary_id = dealii::numbers::internal_face_boundary_id;
        else
          {
            const auto it = boundary_ids_by_pair.find(key(e.vertices[0], e.vertices[1]));
            e.boundary_id = (it == boundary_ids_by_pair.end() ? 0 : it->second);
          }
      }
  }



  template <int dim>
  void
  PolygonalMesh<dim>::validate() const
  {
    std::vector<double> diam(cells.size());
    P                   lo(1e300, 1e300), hi(-1e300, -1e300);
    for (unsigned int c = 0; c < cells.size(); ++c)
      diam[c] = check_cell(name, vertices, c, cells[c].vertices, lo, hi);
    if (cells.size() < 2)
      return;

    std::vector<std::vector<unsigned int>> vertex_cells(vertices.size());
    for (unsigned int c = 0; c < cells.size(); ++c)
      for (const auto v : cells[c].vertices)
        vertex_cells[v].push_back(c);

    check_no_slits(name, vertices, cells, vertex_cells, diam, lo, hi);
    // overlapping cells of one body: crossing edges, or a vertex strictly
    // inside another cell
    check_no_crossing_edges(name, vertices, cells, edges, lo, hi);
    check_no_vertex_inside_cells(name, vertices, cells, vertex_cells, diam, lo, hi);
  }



  template <int dim>
  std::vector<dealii::types::boundary_id>
  PolygonalMesh<dim>::get_boundary_ids() const
  {
    std::set<dealii::types::boundary_id> ids;
    for (const auto &e : edges)
      if (e.at_boundary())
        ids.insert(e.boundary_id);
    return {ids.begin(), ids.end()};
  }



  template <int dim>
  std::vector<dealii::types::material_id>
  PolygonalMesh<dim>::get_material_ids() const
  {
    std::set<dealii::types::material_id> ids;
    for (const auto &c : cells)
      ids.insert(c.material_id);
    return {ids.begin(), ids.end()};
  }



  template <int dim>
  void
  PolygonalMesh<dim>::shift(const dealii::Tensor<1, dim> &s)
  {
    for (auto &v : vertices)
      v += s;
    changed("shift()");
  }



  template <int dim>
  void
  PolygonalMesh<dim>::append(const PolygonalMesh<dim> &other)
  {
    append(std::vector<const PolygonalMesh<dim> *>{&other});
  }



  template <int dim>
  void
  PolygonalMesh<dim>::append(const std::vector<const PolygonalMesh<dim> *> &others)
  {
    for (const PolygonalMesh<dim> *other : others)
      {
        const unsigned int offset = vertices.size();
        vertices.insert(vertices.end(), other->vertices.begin(), other->vertices.end());
        for (const auto &c : other->cells)
          {
            Cell n = c;
            for (auto &v : n.vertices)
              v += offset;
            cells.push_back(std::move(n));
          }
        for (const auto &e : other->edges)
          if (e.at_boundary())
            boundary_ids_by_pair[key(e.vertices[0] + offset, e.vertices[1] + offset)] = e.boundary_id;
        for (const auto &b : other->boundary_ids_by_pair)
          boundary_ids_by_pair.try_emplace(key(b.first.first + offset, b.first.second + offset), b.second);
      }
    build_edges();
    validate();
    changed("append()");
  }



  template <int dim>
  std::vector<PolygonalMesh<dim>>
  PolygonalMesh<dim>::split_by_material_id() const
  {
    const auto                                          ids = get_material_ids();
    std::map<dealii::types::material_id, unsigned int> part;
    for (unsigned int i = 0; i < ids.size(); ++i)
      part[ids[i]] = i;
    std::vector<PolygonalMesh<dim>> parts(ids.size());
    // vertex v of this mesh in each part that uses it (one pass over the
    // cells: the cost is linear in the size of the mesh, not in the
    // number of parts times it)
    std::vector<std::vector<std::pair<unsigned int, unsigned int>>> local(vertices.size());
    for (const auto &cell : cells)
      {
        const unsigned int p = part[cell.material_id];
        std::vector<unsigned int> loop;
        for (const unsigned int v : cell.vertices)
          {
            unsigned int w = dealii::numbers::invalid_unsigned_int;
            for (const auto &l : local[v])
              if (l.first == p)
                w = l.second;
            if (w == dealii::numbers::invalid_unsigned_int)
              {
                w = parts[p].add_vertex(vertices[v]);
                local[v].emplace_back(p, w);
              }
            loop.push_back(w);
          }
        parts[p].add_cell(loop, cell.material_id);
      }
    for (const auto &e : edges)
      if (e.at_boundary())
        {
          const unsigned int p = part[cells[e.cells[0]].material_id];
          unsigned int       w[2];
          for (unsigned int k = 0; k < 2; ++k)
            for (const auto &l : local[e.vertices[k]])
              if (l.first == p)
                w[k] = l.second;
          parts[p].set_boundary_id(w[0], w[1], e.boundary_id);
        }
    for (unsigned int p = 0; p < parts.size(); ++p)
      {
        parts[p].name = name + ", material id " + std::to_string(ids[p]);
        parts[p].finalize();
      }
    return parts;
  }



  template <int dim>
  unsigned int
  PolygonalMesh<dim>::split_edge(const unsigned int e, const dealii::Point<dim> &p)
  {
    AssertThrow(e < edges.size(), dealii::ExcMessage("split_edge: no edge " + std::to_string(e) + "."));
    const Edge         edge = edges[e];
    const unsigned int a = edge.vertices[0], b = edge.vertices[1];
    const double       L = vertices[a].distance(vertices[b]);
    const double       s = (p - vertices[a]) * (vertices[b] - vertices[a]) / (L * L);
    // on the edge: to 1e-9 of its length, or to the rounding of coordinates
    // of size |x| (a point computed on the chord carries eps |x| in each
    // coordinate, so its cross product with the edge carries about eps |x| L)
    double X = 0;
    for (const auto &q : {vertices[a], vertices[b], p})
      X = std::max({X, std::abs(q[0]), std::abs(q[1])});
    const double off_tolerance = std::max(1e-9 * L * L, 16 * std::numeric_limits<double>::epsilon() * X * L);
    AssertThrow(s > 0 && s < 1 && std::abs(cross(vertices[a], vertices[b], p)) <= off_tolerance,
                dealii::ExcMessage("split_edge: the point " + point_string(p) + " does not lie strictly inside edge " +
                                   std::to_string(e) + " of mesh '" + name + "'."));
    // Insert the vertex into the owning cells and update the edges in
    // place (no rebuild, so inserting many nodes stays linear): edge e
    // becomes the piece (first vertex, v), the piece (v, second vertex) is
    // appended as the last edge.
    const unsigned int v     = add_vertex(p);
    const unsigned int e_new = edges.size();
    Edge               piece = edge;
    piece.vertices           = {{v, b}};
    edges[e].vertices        = {{a, v}};
    edges.push_back(piece);
    for (const unsigned int c : edge.cells)
      {
        if (c == dealii::numbers::invalid_unsigned_int)
          continue;
        auto              &cell = cells[c];
        const unsigned int n    = cell.vertices.size();
        for (unsigned int i = 0; i < n; ++i)
          if (key(cell.vertices[i], cell.vertices[(i + 1) % n]) == key(a, b))
            {
              const bool forward = (cell.vertices[i] == a);
              cell.vertices.insert(cell.vertices.begin() + i + 1, v);
              // the cell now runs x_i -> v -> x_{i+1}
              cell.edges[i] = forward ? e : e_new;
              cell.edges.insert(cell.edges.begin() + i + 1, forward ? e_new : e);
              break;
            }
      }
    // keep the orientation convention of boundary edges: (a, v) and (v, b)
    // follow the owning cell's counter-clockwise order as (a, b) did
    if (edge.at_boundary())
      {
        boundary_ids_by_pair[key(a, v)] = edge.boundary_id;
        boundary_ids_by_pair[key(v, b)] = edge.boundary_id;
      }
    changed("split_edge()");
    return v;
  }



  template <int dim>
  std::pair<double, double>
  PolygonalMesh<dim>::cell_diameter_range() const
  {
    double hmin = std::numeric_limits<double>::max(), hmax = 0;
    for (const auto &c : cells)
      {
        double h = 0;
        for (unsigned int i = 0; i < c.vertices.size(); ++i)
          for (unsigned int j = i + 1; j < c.vertices.size(); ++j)
            h = std::max(h, vertices[c.vertices[i]].distance(vertices[c.vertices[j]]));
        hmin = std::min(hmin, h);
        hmax = std::max(hmax, h);
      }
    return {hmin, hmax};
  }



  template <int dim>
  double
  PolygonalMesh<dim>::extent() const
  {
    if (vertices.empty())
      return 0.;
    dealii::Point<dim> lo = vertices[0], hi = vertices[0];
    for (const auto &p : vertices)
      for (unsigned int d = 0; d < dim; ++d)
        {
          lo[d] = std::min(lo[d], p[d]);
          hi[d] = std::max(hi[d], p[d]);
        }
    return lo.distance(hi);
  }



  template <int dim>
  double
  PolygonalMesh<dim>::total_area() const
  {
    double a = 0;
    for (const auto &c : cells)
      {
        const unsigned int n = c.vertices.size();
        for (unsigned int i = 0; i < n; ++i)
          a += 0.5 * cross(vertices[c.vertices[0]], vertices[c.vertices[i]], vertices[c.vertices[(i + 1) % n]]);
      }
    return a;
  }

  template class PolygonalMesh<2>;
} // namespace dealvem
