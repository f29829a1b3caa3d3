// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <dealvem/mesh/polyhedral_mesh.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>

namespace dealvem
{
  namespace polyhedral_mesh_internal
  {
    using Point  = dealii::Point<3>;
    using Vector = dealii::Tensor<1, 3>;

    // The area vector (Newell's formula: half the sum of the cross
    // products of consecutive vertices), exact for a planar polygon of any
    // shape and the best-fit normal of a slightly warped one. Coordinates
    // are taken relative to the first vertex: a small face far from the
    // origin would otherwise lose the digits of its size against those of
    // its position (a cell of size 1e-3 at distance 10 lost 5 digits).
    Vector
    area_vector(const std::vector<Point> &p)
    {
      Vector a;
      for (unsigned int i = 1; i + 1 < p.size(); ++i)
        a += dealii::cross_product_3d(p[i] - p[0], p[i + 1] - p[0]);
      return 0.5 * a;
    }

    PolyhedralMesh::FaceGeometry
    polygon_geometry(const std::vector<Point> &p)
    {
      PolyhedralMesh::FaceGeometry g;
      const Vector                 a = area_vector(p);
      g.area                         = a.norm();
      g.normal                       = g.area > 0 ? a / g.area : Vector();
      for (unsigned int i = 0; i < p.size(); ++i)
        for (unsigned int j = i + 1; j < p.size(); ++j)
          g.diameter = std::max(g.diameter, p[i].distance(p[j]));
      // centre of area: fan of signed triangles from the vertex average
      Point c0;
      for (const Point &x : p)
        c0 += x / double(p.size());
      double sum = 0;
      Vector moment;
      for (unsigned int i = 0; i < p.size(); ++i)
        {
          const Vector u = p[i] - c0, v = p[(i + 1) % p.size()] - c0;
          const double t = 0.5 * (g.normal * dealii::cross_product_3d(u, v));
          sum += t;
          moment += t * (u + v) / 3.;
        }
      g.centroid = sum != 0 ? c0 + moment / sum : c0;
      return g;
    }

    std::vector<unsigned int>
    sorted_key(std::vector<unsigned int> loop)
    {
      std::sort(loop.begin(), loop.end());
      return loop;
    }

    struct KeyHash
    {
      std::size_t
      operator()(const std::vector<unsigned int> &k) const
      {
        std::size_t h = k.size();
        for (const unsigned int v : k)
          h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        return h;
      }
    };

    // Is loop b the reverse of loop a (same cyclic sequence read backwards)?
    bool
    is_reversed_loop(const std::vector<unsigned int> &a, const std::vector<unsigned int> &b)
    {
      const unsigned int n = a.size();
      if (b.size() != n)
        return false;
      const auto start = std::find(b.begin(), b.end(), a[0]);
      if (start == b.end())
        return false;
      const unsigned int s = start - b.begin();
      for (unsigned int i = 0; i < n; ++i)
        if (a[i] != b[(s + n - i) % n])
          return false;
      return true;
    }

    // Do the closed segments [p0, p1] and [q0, q1] of the plane meet?
    bool
    segments_meet(const double *p0, const double *p1, const double *q0, const double *q1, const double eps)
    {
      const auto orient = [](const double *a, const double *b, const double *c) {
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      };
      const auto on_segment = [eps](const double *a, const double *b, const double *c) {
        return std::min(a[0], b[0]) - eps <= c[0] && c[0] <= std::max(a[0], b[0]) + eps &&
               std::min(a[1], b[1]) - eps <= c[1] && c[1] <= std::max(a[1], b[1]) + eps;
      };
      const double d1 = orient(q0, q1, p0), d2 = orient(q0, q1, p1), d3 = orient(p0, p1, q0),
                   d4 = orient(p0, p1, q1);
      const double e = eps * eps;
      if (((d1 > e && d2 < -e) || (d1 < -e && d2 > e)) && ((d3 > e && d4 < -e) || (d3 < -e && d4 > e)))
        return true;
      return (std::abs(d1) <= e && on_segment(q0, q1, p0)) || (std::abs(d2) <= e && on_segment(q0, q1, p1)) ||
             (std::abs(d3) <= e && on_segment(p0, p1, q0)) || (std::abs(d4) <= e && on_segment(p0, p1, q1));
    }
  } // namespace polyhedral_mesh_internal



  bool
  PolyhedralMesh::Face::at_boundary() const
  {
    return cells[1] == dealii::numbers::invalid_unsigned_int;
  }



  void
  PolyhedralMesh::clear()
  {
    vertices.clear();
    faces.clear();
    cells.clear();
    pending_cells.clear();
    pending_material_ids.clear();
    finalized = false;
  }



  unsigned int
  PolyhedralMesh::add_vertex(const dealii::Point<3> &p)
  {
    AssertThrow(!finalized, ExcInvalidPolyhedralMesh(name + ": add_vertex() after finalize(); call clear() first"));
    vertices.push_back(p);
    return vertices.size() - 1;
  }



  unsigned int
  PolyhedralMesh::add_cell(const std::vector<std::vector<unsigned int>> &face_loops,
                           const dealii::types::material_id              material_id)
  {
    AssertThrow(!finalized, ExcInvalidPolyhedralMesh(name + ": add_cell() after finalize(); call clear() first"));
    const unsigned int c = pending_cells.size();
    AssertThrow(face_loops.size() >= 4,
                ExcInvalidPolyhedralMesh(name + ": cell " + std::to_string(c) + " has " +
                                         std::to_string(face_loops.size()) +
                                         " face(s); a polyhedron has at least four"));
    for (unsigned int f = 0; f < face_loops.size(); ++f)
      for (const unsigned int v : face_loops[f])
        AssertThrow(v < vertices.size(),
                    ExcInvalidPolyhedralMesh(name + ": cell " + std::to_string(c) + ", face " + std::to_string(f) +
                                             " uses vertex " + std::to_string(v) + ", but the mesh has " +
                                             std::to_string(vertices.size()) + " vertices"));
    pending_cells.push_back(face_loops);
    pending_material_ids.push_back(material_id);
    return c;
  }



  void
  PolyhedralMesh::finalize(const double planarity_tolerance)
  {
    using namespace polyhedral_mesh_internal;
    AssertThrow(!finalized, ExcInvalidPolyhedralMesh(name + ": finalize() called twice"));
    AssertThrow(planarity_tolerance > 0 && planarity_tolerance < 1,
                ExcInvalidPolyhedralMesh(name + ": the planarity tolerance must lie in (0, 1), not " +
                                         std::to_string(planarity_tolerance)));
    planarity = planarity_tolerance;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      for (unsigned int d = 0; d < 3; ++d)
        AssertThrow(std::isfinite(vertices[v][d]),
                    ExcInvalidPolyhedralMesh(name + ": vertex " + std::to_string(v) +
                                             " has a coordinate that is not a finite number"));

    // vertices no cell uses are removed (they would carry DoFs without
    // stiffness); the others keep their order
    std::vector<unsigned int> new_index(vertices.size(), dealii::numbers::invalid_unsigned_int);
    for (const auto &cell : pending_cells)
      for (const auto &loop : cell)
        for (const unsigned int v : loop)
          new_index[v] = 0;
    unsigned int n_used = 0;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (new_index[v] == 0)
        {
          vertices[n_used] = vertices[v];
          new_index[v]     = n_used++;
        }
    vertices.resize(n_used);

    faces.clear();
    cells.assign(pending_cells.size(), Cell());
    std::unordered_map<std::vector<unsigned int>, unsigned int, KeyHash> face_of_key;
    face_of_key.reserve(4 * pending_cells.size());
    for (unsigned int c = 0; c < pending_cells.size(); ++c)
      {
        cells[c].material_id = pending_material_ids[c];
        for (unsigned int lf = 0; lf < pending_cells[c].size(); ++lf)
          {
            std::vector<unsigned int> loop = pending_cells[c][lf];
            for (unsigned int &v : loop)
              v = new_index[v];
            const std::string where =
              name + ": cell " + std::to_string(c) + ", face " + std::to_string(lf) + " (local)";
            AssertThrow(loop.size() >= 3,
                        ExcInvalidPolyhedralMesh(where + " has " + std::to_string(loop.size()) +
                                                 " vertices; a face needs at least three"));
            const auto key = sorted_key(loop);
            AssertThrow(std::adjacent_find(key.begin(), key.end()) == key.end(),
                        ExcInvalidPolyhedralMesh(where + " lists a vertex twice"));
            const auto found = face_of_key.find(key);
            if (found == face_of_key.end())
              {
                face_of_key.emplace(key, faces.size());
                Face face;
                face.vertices = loop;
                face.cells    = {{c, dealii::numbers::invalid_unsigned_int}};
                cells[c].faces.push_back(faces.size());
                faces.push_back(std::move(face));
                continue;
              }
            Face &face = faces[found->second];
            AssertThrow(face.cells[0] != c,
                        ExcInvalidPolyhedralMesh(where + " is listed twice by the cell"));
            AssertThrow(face.at_boundary(),
                        ExcInvalidPolyhedralMesh(where + " is also a face of cells " + std::to_string(face.cells[0]) +
                                                 " and " + std::to_string(face.cells[1]) +
                                                 ": a face is shared by at most two cells"));
            AssertThrow(is_reversed_loop(face.vertices, loop),
                        ExcInvalidPolyhedralMesh(
                          where + " has the vertices of a face of cell " + std::to_string(face.cells[0]) +
                          (is_reversed_loop(face.vertices, std::vector<unsigned int>(loop.rbegin(), loop.rend())) ?
                             " with the same orientation: a shared face must point out of one cell and into the "
                             "other (is one of the two cells given with inward normals?)" :
                             " in a different order")));
            face.cells[1] = c;
            cells[c].faces.push_back(found->second);
          }
      }
    pending_cells.clear();
    pending_material_ids.clear();
    finalized = true;
    validate();
  }



  void
  PolyhedralMesh::validate() const
  {
    using namespace polyhedral_mesh_internal;
    AssertThrow(finalized, ExcInvalidPolyhedralMesh(name + ": validate() before finalize()"));
    AssertThrow(!cells.empty(), ExcInvalidPolyhedralMesh(name + ": the mesh has no cells"));
    const double size = extent();
    std::vector<Point>        p;
    std::vector<FaceGeometry> geometry(faces.size());
    for (unsigned int f = 0; f < faces.size(); ++f)
      {
        const Face &face = faces[f];
        p.clear();
        for (const unsigned int v : face.vertices)
          p.push_back(vertices[v]);
        const FaceGeometry g = polygon_geometry(p);
        geometry[f]          = g;
        const std::string where =
          name + ": face " + std::to_string(f) + " of cell " + std::to_string(face.cells[0]) + " (centroid " +
          std::to_string(g.centroid[0]) + ", " + std::to_string(g.centroid[1]) + ", " +
          std::to_string(g.centroid[2]) + ")";
        AssertThrow(g.diameter > 1e-14 * size && g.area > 1e-14 * g.diameter * g.diameter,
                    ExcInvalidPolyhedralMesh(where + " has zero area (or a loop whose parts cancel, as a "
                                                     "symmetric bow tie does)"));
        double warp = 0;
        for (const Point &x : p)
          warp = std::max(warp, std::abs(g.normal * (x - g.centroid)));
        if (warp > planarity * g.diameter)
          {
            std::ostringstream msg;
            msg << where << " is not planar: a vertex lies " << warp
                << " from its plane, more than the planarity tolerance (" << planarity
                << ") times the face's diameter (" << g.diameter
                << "); split it into planar faces (e.g. triangles)";
            AssertThrow(false, ExcInvalidPolyhedralMesh(msg.str()));
          }
        // the loop must not cross itself: test in the face's plane
        Vector e1 = p[1] - p[0];
        e1 -= (e1 * g.normal) * g.normal;
        e1 /= e1.norm();
        const Vector        e2 = dealii::cross_product_3d(g.normal, e1);
        std::vector<double> xy(2 * p.size());
        for (unsigned int i = 0; i < p.size(); ++i)
          {
            xy[2 * i]     = (p[i] - p[0]) * e1;
            xy[2 * i + 1] = (p[i] - p[0]) * e2;
          }
        const unsigned int n   = p.size();
        const double       eps = 1e-12 * g.diameter;
        for (unsigned int i = 0; i < n; ++i)
          {
            // a loop that turns back along its own edge
            const unsigned int j = (i + 1) % n, k = (i + 2) % n;
            const Vector       a = p[j] - p[i], b = p[k] - p[j];
            AssertThrow(!(dealii::cross_product_3d(a, b).norm() <= 1e-12 * a.norm() * b.norm() && a * b < 0),
                        ExcInvalidPolyhedralMesh(where + " turns back on itself at vertex " +
                                                 std::to_string(face.vertices[j])));
            for (unsigned int l = i + 2; l < n; ++l)
              {
                if ((l + 1) % n == i)
                  continue;
                AssertThrow(!segments_meet(&xy[2 * i], &xy[2 * j], &xy[2 * l], &xy[2 * ((l + 1) % n)], eps),
                            ExcInvalidPolyhedralMesh(where + " crosses itself (its edges from vertex " +
                                                     std::to_string(face.vertices[i]) + " and from vertex " +
                                                     std::to_string(face.vertices[l]) + " meet)"));
              }
          }
      }

    // each cell: a closed surface, every edge used once in each direction
    std::map<std::pair<unsigned int, unsigned int>, int> directed;
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        const std::string where = name + ": cell " + std::to_string(c);
        AssertThrow(cells[c].faces.size() >= 4,
                    ExcInvalidPolyhedralMesh(where + " has fewer than four faces"));
        directed.clear();
        for (const unsigned int f : cells[c].faces)
          {
            const auto &loop = faces[f].vertices;
            const bool  out  = face_points_out_of(f, c);
            for (unsigned int i = 0; i < loop.size(); ++i)
              {
                unsigned int a = loop[i], b = loop[(i + 1) % loop.size()];
                if (!out)
                  std::swap(a, b);
                ++directed[{a, b}];
              }
          }
        for (const auto &[edge, count] : directed)
          {
            const auto back = directed.find({edge.second, edge.first});
            AssertThrow(count == 1 && back != directed.end() && back->second == 1,
                        ExcInvalidPolyhedralMesh(
                          where + " is not a closed, consistently oriented surface: its edge from vertex " +
                          std::to_string(edge.first) + " to vertex " + std::to_string(edge.second) + " is used " +
                          std::to_string(count) + " time(s) in this direction and " +
                          std::to_string(back == directed.end() ? 0 : back->second) +
                          " time(s) in the other by its faces (each edge must be used once each way; a vertex "
                          "on an edge must be in the loops of both faces at that edge)"));
          }
        const double volume = cell_volume(c);
        double       h      = 0;
        for (const unsigned int f : cells[c].faces)
          h = std::max(h, geometry[f].diameter);
        AssertThrow(volume > 1e-14 * h * h * h,
                    ExcInvalidPolyhedralMesh(where + (volume < 0 ? " has a negative volume (" : " has zero volume (") +
                                             std::to_string(volume) +
                                             ")" +
                                             (volume < 0 ? ": its faces point into the cell; give each face loop "
                                                           "counter-clockwise seen from outside" :
                                                           "")));
      }

    // Two boundary faces that share an edge, face opposite ways and lie on
    // the same side of that edge lie on each other: the surface folds back,
    // the sign of two cells that touch without sharing their faces (a
    // non-conforming mesh). Coplanar faces with opposite normals on the two
    // sides of a shared edge (cells meeting only at that edge) are allowed.
    std::map<std::pair<unsigned int, unsigned int>, std::vector<unsigned int>> boundary_edge;
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (faces[f].at_boundary())
        {
          const auto &loop = faces[f].vertices;
          for (unsigned int i = 0; i < loop.size(); ++i)
            boundary_edge[{loop[i], loop[(i + 1) % loop.size()]}].push_back(f);
        }
    for (const auto &[edge, edge_faces] : boundary_edge)
      {
        const auto other = boundary_edge.find({edge.second, edge.first});
        if (other == boundary_edge.end())
          continue;
        const Point  a = vertices[edge.first], b = vertices[edge.second];
        const Point  middle = 0.5 * (a + b);
        const Vector t      = (b - a) / (b - a).norm();
        for (const unsigned int f : edge_faces)
          for (const unsigned int g : other->second)
            {
              if (g <= f || geometry[f].normal * geometry[g].normal > -1 + 1e-10)
                continue;
              Vector side_f = geometry[f].centroid - middle, side_g = geometry[g].centroid - middle;
              side_f -= (side_f * t) * t;
              side_g -= (side_g * t) * t;
              AssertThrow(side_f * side_g <= 0,
                          ExcInvalidPolyhedralMesh(
                            name + ": boundary faces " + std::to_string(f) + " (cell " +
                            std::to_string(faces[f].cells[0]) + ") and " + std::to_string(g) + " (cell " +
                            std::to_string(faces[g].cells[0]) +
                            ") lie on each other: the cells touch without sharing a face (the mesh is not "
                            "conforming there)"));
            }
      }
  }



  std::vector<unsigned int>
  PolyhedralMesh::cell_vertex_indices(const unsigned int c) const
  {
    std::vector<unsigned int> v;
    for (const unsigned int f : cells[c].faces)
      v.insert(v.end(), faces[f].vertices.begin(), faces[f].vertices.end());
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  }



  PolyhedralMesh::FaceGeometry
  PolyhedralMesh::face_geometry(const unsigned int f) const
  {
    std::vector<dealii::Point<3>> p;
    for (const unsigned int v : faces[f].vertices)
      p.push_back(vertices[v]);
    return polyhedral_mesh_internal::polygon_geometry(p);
  }



  double
  PolyhedralMesh::cell_volume(const unsigned int c) const
  {
    // (1/3) sum over the faces of (x_F - x_0) . n_F |F|, x_0 a vertex of
    // the cell (for round-off), n_F outward
    const dealii::Point<3> x0     = vertices[faces[cells[c].faces[0]].vertices[0]];
    double                 volume = 0;
    for (const unsigned int f : cells[c].faces)
      {
        const FaceGeometry g = face_geometry(f);
        volume += (face_points_out_of(f, c) ? 1. : -1.) * g.area * (g.normal * (g.centroid - x0)) / 3.;
      }
    return volume;
  }



  void
  PolyhedralMesh::set_face_boundary_id(const unsigned int f, const dealii::types::boundary_id id)
  {
    AssertThrow(f < faces.size() && faces[f].at_boundary(),
                ExcInvalidPolyhedralMesh(name + ": face " + std::to_string(f) + " is not a boundary face"));
    faces[f].boundary_id = id;
  }



  unsigned int
  PolyhedralMesh::set_boundary_ids(
    const std::function<bool(const dealii::Point<3> &, const dealii::Tensor<1, 3> &)> &select,
    const dealii::types::boundary_id                                                   id)
  {
    unsigned int n = 0;
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (faces[f].at_boundary())
        {
          const FaceGeometry g = face_geometry(f);
          if (select(g.centroid, g.normal))
            {
              faces[f].boundary_id = id;
              ++n;
            }
        }
    return n;
  }



  std::vector<dealii::types::boundary_id>
  PolyhedralMesh::get_boundary_ids() const
  {
    std::vector<dealii::types::boundary_id> ids;
    for (const Face &f : faces)
      if (f.at_boundary())
        ids.push_back(f.boundary_id);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
  }



  std::pair<double, double>
  PolyhedralMesh::cell_diameter_range() const
  {
    double lo = std::numeric_limits<double>::max(), hi = 0;
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        const auto v = cell_vertex_indices(c);
        double     d = 0;
        for (unsigned int i = 0; i < v.size(); ++i)
          for (unsigned int j = i + 1; j < v.size(); ++j)
            d = std::max(d, vertices[v[i]].distance(vertices[v[j]]));
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      }
    return {cells.empty() ? 0. : lo, hi};
  }



  double
  PolyhedralMesh::extent() const
  {
    if (vertices.empty())
      return 0;
    dealii::Point<3> lo = vertices[0], hi = vertices[0];
    for (const auto &p : vertices)
      for (unsigned int d = 0; d < 3; ++d)
        {
          lo[d] = std::min(lo[d], p[d]);
          hi[d] = std::max(hi[d], p[d]);
        }
    return lo.distance(hi);
  }



  double
  PolyhedralMesh::total_volume() const
  {
    double v = 0;
    for (unsigned int c = 0; c < cells.size(); ++c)
      v += cell_volume(c);
    return v;
  }



  void
  PolyhedralMesh::move_vertex(const unsigned int v, const dealii::Point<3> &p)
  {
    AssertThrow(v < vertices.size(), ExcInvalidPolyhedralMesh(name + ": no vertex " + std::to_string(v)));
    vertices[v] = p;
  }



  void
  PolyhedralMesh::transform(const std::function<dealii::Point<3>(const dealii::Point<3> &)> &map)
  {
    for (auto &p : vertices)
      p = map(p);
  }



  namespace polyhedral_mesh_internal
  {
    // Append to @p loop the vertices strictly inside @p line, in order from
    // its vertex @p from (the midpoints of a refined line, recursively).
    void
    append_line_interior(const dealii::TriaIterator<dealii::TriaAccessor<1, 3, 3>> &line,
                         const unsigned int                                         from,
                         std::vector<unsigned int>                                 &loop)
    {
      if (!line->has_children())
        return;
      const bool forward = line->vertex_index(0) == from;
      const auto first = line->child(forward ? 0 : 1), second = line->child(forward ? 1 : 0);
      const unsigned int middle = line->child(0)->vertex_index(1);
      append_line_interior(first, from, loop);
      loop.push_back(middle);
      append_line_interior(second, middle, loop);
    }

    // The loop of a face of a triangulation, with the interior vertices of
    // its refined lines, oriented along @p normal_out.
    std::vector<unsigned int>
    face_loop(const dealii::TriaIterator<dealii::TriaAccessor<2, 3, 3>> &face,
              const Vector                                                &normal_out,
              const std::vector<Point>                                    &points)
    {
      std::vector<unsigned int> corners;
      if (face->n_vertices() == 4)
        corners = {face->vertex_index(0), face->vertex_index(1), face->vertex_index(3), face->vertex_index(2)};
      else
        for (unsigned int i = 0; i < face->n_vertices(); ++i)
          corners.push_back(face->vertex_index(i));
      std::vector<Point> p;
      for (const unsigned int v : corners)
        p.push_back(points[v]);
      if (area_vector(p) * normal_out < 0)
        std::reverse(corners.begin(), corners.end());
      std::vector<unsigned int> loop;
      for (unsigned int i = 0; i < corners.size(); ++i)
        {
          const unsigned int a = corners[i], b = corners[(i + 1) % corners.size()];
          loop.push_back(a);
          for (unsigned int l = 0; l < face->n_lines(); ++l)
            {
              const auto line = face->line(l);
              if ((line->vertex_index(0) == a && line->vertex_index(1) == b) ||
                  (line->vertex_index(0) == b && line->vertex_index(1) == a))
                append_line_interior(line, a, loop);
            }
        }
      return loop;
    }

    // The active descendants of a face (the face itself if it has none).
    void
    active_descendants(const dealii::TriaIterator<dealii::TriaAccessor<2, 3, 3>>               &face,
                       std::vector<dealii::TriaIterator<dealii::TriaAccessor<2, 3, 3>>> &out)
    {
      if (!face->has_children())
        out.push_back(face);
      else
        for (unsigned int i = 0; i < face->n_children(); ++i)
          active_descendants(face->child(i), out);
    }
  } // namespace polyhedral_mesh_internal



  PolyhedralMesh
  PolyhedralMesh::from_triangulation(const dealii::Triangulation<3, 3> &tria,
                                     const double                       planarity_tolerance,
                                     const bool                         split_warped_faces,
                                     const std::string                 &name)
  {
    using namespace polyhedral_mesh_internal;
    PolyhedralMesh mesh;
    mesh.name                        = name;
    const std::vector<Point> &points = tria.get_vertices();
    // only the vertices the active cells use, in deal.II's order
    std::vector<unsigned int> index(points.size(), dealii::numbers::invalid_unsigned_int);
    std::vector<std::vector<std::vector<unsigned int>>> cell_faces;
    std::map<std::vector<unsigned int>, dealii::types::boundary_id> boundary_ids;
    std::vector<dealii::TriaIterator<dealii::TriaAccessor<2, 3, 3>>> pieces;
    for (const auto &cell : tria.active_cell_iterators())
      {
        std::vector<std::vector<unsigned int>> loops;
        const Point                            centre = cell->center();
        for (unsigned int f = 0; f < cell->n_faces(); ++f)
          {
            const auto   face   = cell->face(f);
            const Vector normal = area_vector([&] {
              std::vector<Point> p;
              if (face->n_vertices() == 4)
                for (const unsigned int i : {0u, 1u, 3u, 2u})
                  p.push_back(face->vertex(i));
              else
                for (unsigned int i = 0; i < face->n_vertices(); ++i)
                  p.push_back(face->vertex(i));
              return p;
            }());
            const Vector out = (normal * (face->center() - centre) >= 0 ? 1. : -1.) * normal;
            pieces.clear();
            active_descendants(face, pieces);
            for (const auto &piece : pieces)
              {
                std::vector<unsigned int> loop = face_loop(piece, out, points);
                std::vector<std::vector<unsigned int>> split;
                if (split_warped_faces && loop.size() == 4)
                  {
                    std::vector<Point> p;
                    for (const unsigned int v : loop)
                      p.push_back(points[v]);
                    const auto g    = polygon_geometry(p);
                    double     warp = 0;
                    for (const Point &x : p)
                      warp = std::max(warp, std::abs(g.normal * (x - g.centroid)));
                    if (warp > planarity_tolerance * g.diameter)
                      {
                        // the diagonal through the face's smallest vertex
                        // index: the cell on the other side splits the same way
                        const unsigned int m =
                          std::min_element(loop.begin(), loop.end()) - loop.begin();
                        split.push_back({loop[m], loop[(m + 1) % 4], loop[(m + 2) % 4]});
                        split.push_back({loop[m], loop[(m + 2) % 4], loop[(m + 3) % 4]});
                      }
                  }
                if (split.empty())
                  split.push_back(std::move(loop));
                for (auto &piece_loop : split)
                  {
                    if (face->at_boundary())
                      boundary_ids[sorted_key(piece_loop)] = face->boundary_id();
                    loops.push_back(std::move(piece_loop));
                  }
              }
          }
        for (const auto &loop : loops)
          for (const unsigned int v : loop)
            index[v] = 0;
        cell_faces.push_back(std::move(loops));
      }
    for (unsigned int v = 0; v < points.size(); ++v)
      if (index[v] == 0)
        index[v] = mesh.add_vertex(points[v]);
    unsigned int c = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        auto &loops = cell_faces[c++];
        for (auto &loop : loops)
          for (unsigned int &v : loop)
            v = index[v];
        mesh.add_cell(loops, cell->material_id());
      }
    {
      // boundary ids by the faces' keys (in the new vertex numbers)
      std::map<std::vector<unsigned int>, dealii::types::boundary_id> renamed;
      for (const auto &[key, id] : boundary_ids)
        {
          std::vector<unsigned int> k = key;
          for (unsigned int &v : k)
            v = index[v];
          renamed[sorted_key(k)] = id;
        }
      boundary_ids.swap(renamed);
    }
    mesh.finalize(planarity_tolerance);
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      if (mesh.faces[f].at_boundary())
        {
          const auto found = boundary_ids.find(sorted_key(mesh.faces[f].vertices));
          if (found != boundary_ids.end())
            mesh.faces[f].boundary_id = found->second;
        }
    return mesh;
  }



  PolyhedralMesh
  PolyhedralMesh::read_gmsh(const std::string &file_name,
                            const double       planarity_tolerance,
                            const bool         split_warped_faces)
  {
    std::ifstream in(file_name);
    AssertThrow(in, ExcInvalidPolyhedralMesh("cannot open the gmsh file " + file_name));
    dealii::Triangulation<3> tria;
    dealii::GridIn<3>        reader;
    reader.attach_triangulation(tria);
    try
      {
        reader.read_msh(in);
      }
    catch (const std::exception &e)
      {
        AssertThrow(false, ExcInvalidPolyhedralMesh("the gmsh file " + file_name +
                                                    " could not be read as a 3D mesh of hexahedra or "
                                                    "tetrahedra: " +
                                                    e.what()));
      }
    return from_triangulation(tria, planarity_tolerance, split_warped_faces, "the gmsh file " + file_name);
  }



  void
  PolyhedralMesh::write_vtu(const std::string                                               &file_name,
                            const std::vector<std::pair<std::string, std::vector<double>>> &point_fields,
                            const std::vector<std::pair<std::string, std::vector<double>>> &cell_fields) const
  {
    std::ofstream out(file_name);
    AssertThrow(out, dealii::ExcMessage("Cannot open the file " + file_name + " for writing."));
    out << std::setprecision(16);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\""
        << vertices.size() << "\" NumberOfCells=\"" << cells.size() << "\">\n";
    out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto &p : vertices)
      out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    std::vector<std::size_t> offsets, face_offsets;
    std::size_t              n_connectivity = 0, n_face_stream = 0;
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        const auto v = cell_vertex_indices(c);
        for (const unsigned int i : v)
          out << i << ' ';
        out << '\n';
        n_connectivity += v.size();
        offsets.push_back(n_connectivity);
      }
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (const std::size_t o : offsets)
      out << o << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < cells.size(); ++c)
      out << "42\n"; // VTK_POLYHEDRON
    // per cell: the number of faces, then each face's vertex count and
    // vertices, outward
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"faces\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        out << cells[c].faces.size();
        ++n_face_stream;
        for (const unsigned int f : cells[c].faces)
          {
            const auto &loop = faces[f].vertices;
            out << ' ' << loop.size();
            if (face_points_out_of(f, c))
              for (const unsigned int v : loop)
                out << ' ' << v;
            else
              for (auto v = loop.rbegin(); v != loop.rend(); ++v)
                out << ' ' << *v;
            n_face_stream += 1 + loop.size();
          }
        out << '\n';
        face_offsets.push_back(n_face_stream);
      }
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"faceoffsets\" format=\"ascii\">\n";
    for (const std::size_t o : face_offsets)
      out << o << '\n';
    out << "</DataArray>\n</Cells>\n";

    const auto write_fields = [&](const std::vector<std::pair<std::string, std::vector<double>>> &fields,
                                  const std::size_t n, const char *where) {
      for (const auto &[field_name, values] : fields)
        {
          AssertThrow(values.size() == n || values.size() == 3 * n,
                      dealii::ExcMessage("write_vtu: the " + std::string(where) + " field '" + field_name + "' has " +
                                         std::to_string(values.size()) + " values, not " + std::to_string(n) +
                                         " or " + std::to_string(3 * n) + "."));
          out << "<DataArray type=\"Float64\" Name=\"" << field_name << "\" NumberOfComponents=\""
              << (values.size() == n ? 1 : 3) << "\" format=\"ascii\">\n";
          for (std::size_t i = 0; i < values.size(); ++i)
            out << values[i] << ((i + 1) % (values.size() == n ? 1 : 3) == 0 ? '\n' : ' ');
          out << "</DataArray>\n";
        }
    };
    out << "<PointData>\n";
    write_fields(point_fields, vertices.size(), "point");
    out << "</PointData>\n<CellData>\n";
    out << "<DataArray type=\"Int32\" Name=\"material_id\" format=\"ascii\">\n";
    for (const Cell &cell : cells)
      out << int(cell.material_id) << '\n';
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"cell_index\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < cells.size(); ++c)
      out << c << '\n';
    out << "</DataArray>\n";
    write_fields(cell_fields, cells.size(), "cell");
    out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    AssertThrow(out, dealii::ExcMessage("Writing the file " + file_name + " failed (disk full?)."));
  }
} // namespace dealvem
