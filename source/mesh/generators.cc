// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/masonry_wall.h>
#include <dealvem/mesh/mesh_io.h>

#include "generators_internal.h"

#include <array>
#include <iomanip>
#include <unordered_map>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <unordered_set>

namespace dealvem
{
  namespace PolygonalMeshGenerators
  {
    namespace
    {
      using P = dealii::Point<2>;

      // boundary id of the rectangle side a point lies on (-1: interior)
      int
      side_of(const P &a, const P &b, const P &p0, const P &p1)
      {
        const double t = 1e-10 * std::max(p1[0] - p0[0], p1[1] - p0[1]);
        if (std::abs(a[0] - p0[0]) < t && std::abs(b[0] - p0[0]) < t)
          return 0;
        if (std::abs(a[0] - p1[0]) < t && std::abs(b[0] - p1[0]) < t)
          return 1;
        if (std::abs(a[1] - p0[1]) < t && std::abs(b[1] - p0[1]) < t)
          return 2;
        if (std::abs(a[1] - p1[1]) < t && std::abs(b[1] - p1[1]) < t)
          return 3;
        return -1;
      }

      void
      grid_vertices(PolygonalMesh<2> &mesh, const P &p0, const P &p1, const unsigned int nx,
                    const unsigned int ny)
      {
        for (unsigned int j = 0; j <= ny; ++j)
          for (unsigned int i = 0; i <= nx; ++i)
            mesh.add_vertex(P(p0[0] + (p1[0] - p0[0]) * i / nx, p0[1] + (p1[1] - p0[1]) * j / ny));
      }
    } // namespace



    namespace internal
    {
      void
      check_rectangle(const P &p0, const P &p1, const unsigned int nx, const unsigned int ny,
                      const std::string &what)
      {
        AssertThrow(p1[0] > p0[0] && p1[1] > p0[1],
                    dealii::ExcMessage(what + ": the upper right corner must lie above and right of the "
                                              "lower left corner."));
        AssertThrow(nx >= 1 && ny >= 1,
                    dealii::ExcMessage(what + ": the numbers of subdivisions must be at least 1."));
      }

      void
      finish_rectangle(PolygonalMesh<2> &mesh, const P &p0, const P &p1)
      {
        mesh.finalize();
        for (unsigned int e = 0; e < mesh.n_edges(); ++e)
          if (mesh.edge(e).at_boundary())
            {
              const int s = side_of(mesh.vertex(mesh.edge(e).vertices[0]),
                                    mesh.vertex(mesh.edge(e).vertices[1]), p0, p1);
              mesh.set_edge_boundary_id(e, s < 0 ? 0 : s);
            }
      }
    } // namespace internal

    using internal::check_rectangle;
    using internal::finish_rectangle;



    template <int dim>
    void
    structured_quads(PolygonalMesh<dim> &mesh, const dealii::Point<dim> &p0,
                     const dealii::Point<dim> &p1, const unsigned int nx, const unsigned int ny)
    {
      check_rectangle(p0, p1, nx, ny, "structured_quads");
      mesh.clear();
      mesh.name = "structured quads " + std::to_string(nx) + "x" + std::to_string(ny);
      grid_vertices(mesh, p0, p1, nx, ny);
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            const unsigned int v = j * (nx + 1) + i;
            mesh.add_cell({v, v + 1, v + nx + 2, v + nx + 1});
          }
      finish_rectangle(mesh, p0, p1);
    }



    template <int dim>
    void
    structured_triangles(PolygonalMesh<dim> &mesh, const dealii::Point<dim> &p0,
                         const dealii::Point<dim> &p1, const unsigned int nx, const unsigned int ny)
    {
      check_rectangle(p0, p1, nx, ny, "structured_triangles");
      mesh.clear();
      mesh.name = "structured triangles " + std::to_string(nx) + "x" + std::to_string(ny);
      grid_vertices(mesh, p0, p1, nx, ny);
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            const unsigned int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 2, d = a + nx + 1;
            if ((i + j) % 2 == 0)
              {
                mesh.add_cell({a, b, c});
                mesh.add_cell({a, c, d});
              }
            else
              {
                mesh.add_cell({a, b, d});
                mesh.add_cell({b, c, d});
              }
          }
      finish_rectangle(mesh, p0, p1);
    }



    template <int dim>
    void
    perturbed_quads(PolygonalMesh<dim> &mesh, const dealii::Point<dim> &p0,
                    const dealii::Point<dim> &p1, const unsigned int nx, const unsigned int ny,
                    const double amplitude, const unsigned int seed)
    {
      check_rectangle(p0, p1, nx, ny, "perturbed_quads");
      AssertThrow(amplitude >= 0 && amplitude < 0.5,
                  dealii::ExcMessage("perturbed_quads: the perturbation amplitude must lie in [0, 0.5), got " +
                                     std::to_string(amplitude) + "."));
      PolygonalMesh<dim> q;
      structured_quads(q, p0, p1, nx, ny);
      std::mt19937                           rng(seed);
      std::uniform_real_distribution<double> u(-amplitude, amplitude);
      const double                           hx = (p1[0] - p0[0]) / nx, hy = (p1[1] - p0[1]) / ny;
      mesh.clear();
      mesh.name = "perturbed quads " + std::to_string(nx) + "x" + std::to_string(ny);
      for (unsigned int j = 0; j <= ny; ++j)
        for (unsigned int i = 0; i <= nx; ++i)
          {
            P            p  = q.vertex(j * (nx + 1) + i);
            const double dx = u(rng) * hx, dy = u(rng) * hy;
            if (i > 0 && i < nx)
              p[0] += dx;
            if (j > 0 && j < ny)
              p[1] += dy;
            mesh.add_vertex(p);
          }
      for (unsigned int c = 0; c < q.n_cells(); ++c)
        mesh.add_cell(q.cell(c).vertices);
      finish_rectangle(mesh, p0, p1);
    }



    template <int dim>
    void
    nonconvex(PolygonalMesh<dim> &mesh, const dealii::Point<dim> &p0, const dealii::Point<dim> &p1,
              const unsigned int nx, const unsigned int ny, const double depth)
    {
      check_rectangle(p0, p1, nx, ny, "nonconvex");
      AssertThrow(depth > 0 && depth < 0.5,
                  dealii::ExcMessage("nonconvex: the depth must lie in (0, 0.5), got " + std::to_string(depth) + "."));
      mesh.clear();
      mesh.name = "nonconvex " + std::to_string(nx) + "x" + std::to_string(ny);
      grid_vertices(mesh, p0, p1, nx, ny);
      const double hy = (p1[1] - p0[1]) / ny;
      // midpoints of the horizontal edges of row j: index mid0 + j*nx + i
      const unsigned int mid0 = mesh.n_vertices();
      for (unsigned int j = 0; j <= ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            const P a = mesh.vertex(j * (nx + 1) + i), b = mesh.vertex(j * (nx + 1) + i + 1);
            P       m = 0.5 * (a + b);
            if (j > 0 && j < ny)
              m[1] -= depth * hy;
            mesh.add_vertex(m);
          }
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            const unsigned int v = j * (nx + 1) + i;
            mesh.add_cell({v, mid0 + j * nx + i, v + 1, v + nx + 2, mid0 + (j + 1) * nx + i, v + nx + 1});
          }
      finish_rectangle(mesh, p0, p1);
    }



    namespace
    {
      // Whether a vertex of the triangulation belongs to an active cell.
      std::vector<bool>
      vertices_of_active_cells(const dealii::Triangulation<2, 2> &tria)
      {
        std::vector<bool> used(tria.n_vertices(), false);
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            used[cell->vertex_index(v)] = true;
        return used;
      }

      // The pieces of a face of an active cell as the finer cells behind it
      // see them: the vertices strictly inside the face in the order from
      // face->vertex_index(0) to face->vertex_index(1) (appended to
      // @p inside), and the leaf faces between consecutive vertices
      // (appended to @p leaves). A face is split where it has children whose
      // shared vertex an active cell uses, recursively; the vertex is where
      // the manifold of the face put it, on the chord or not.
      template <typename FaceIterator>
      void
      collect_face_pieces(const FaceIterator &face, const std::vector<bool> &active_vertex,
                          std::vector<unsigned int> &inside, std::vector<FaceIterator> &leaves)
      {
        if (face->has_children())
          {
            AssertThrow(face->n_children() == 2, dealii::ExcInternalError());
            FaceIterator first = face->child(0), second = face->child(1);
            if (first->vertex_index(0) != face->vertex_index(0) && first->vertex_index(1) != face->vertex_index(0))
              std::swap(first, second);
            const unsigned int shared =
              (first->vertex_index(0) == face->vertex_index(0) ? first->vertex_index(1) : first->vertex_index(0));
            AssertThrow(second->vertex_index(0) == shared || second->vertex_index(1) == shared,
                        dealii::ExcInternalError());
            if (active_vertex[shared])
              {
                // each child in the direction of its parent
                auto add_child = [&](const FaceIterator &child, const unsigned int start) {
                  std::vector<unsigned int> piece;
                  std::vector<FaceIterator> piece_leaves;
                  collect_face_pieces(child, active_vertex, piece, piece_leaves);
                  if (child->vertex_index(0) != start)
                    {
                      std::reverse(piece.begin(), piece.end());
                      std::reverse(piece_leaves.begin(), piece_leaves.end());
                    }
                  inside.insert(inside.end(), piece.begin(), piece.end());
                  leaves.insert(leaves.end(), piece_leaves.begin(), piece_leaves.end());
                };
                add_child(first, face->vertex_index(0));
                inside.push_back(shared);
                add_child(second, shared);
                return;
              }
          }
        leaves.push_back(face);
      }
    } // namespace



    template <int dim>
    void
    from_triangulation(PolygonalMesh<dim>                    &mesh,
                       const dealii::Triangulation<dim, dim> &tria,
                       const bool                             separate_material_ids)
    {
      mesh.clear();
      mesh.name = "deal.II triangulation";
      for (const auto &v : tria.get_vertices())
        mesh.add_vertex(v);
      const std::vector<bool> active_vertex = vertices_of_active_cells(tria);
      using FaceIterator = typename dealii::Triangulation<dim, dim>::face_iterator;
      std::vector<unsigned int> corners, loop, inside;
      std::vector<FaceIterator> leaves;
      std::vector<std::pair<std::array<unsigned int, 2>, dealii::types::boundary_id>> boundary_pieces;
      // separate_material_ids: the material id that uses a vertex first,
      // and the copies of the vertex for the other ids
      std::map<unsigned int, dealii::types::material_id>                              vertex_owner;
      std::map<std::pair<unsigned int, dealii::types::material_id>, unsigned int> vertex_copies;
      for (const auto &cell : tria.active_cell_iterators())
        {
          // the cell's vertices around the cell (deal.II numbers the
          // vertices of a quadrilateral lexicographically)
          corners.clear();
          if (cell->n_vertices() == 4)
            corners = {cell->vertex_index(0), cell->vertex_index(1), cell->vertex_index(3), cell->vertex_index(2)};
          else
            for (const unsigned int v : cell->vertex_indices())
              corners.push_back(cell->vertex_index(v));

          // walk the faces from corner to corner; a face that has children
          // (the neighbour behind it is finer) contributes the vertices of
          // the children in between: the hanging vertices, wherever the
          // manifold placed them
          loop.clear();
          boundary_pieces.clear();
          const unsigned int n = corners.size();
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int a = corners[i], b = corners[(i + 1) % n];
              unsigned int       f = dealii::numbers::invalid_unsigned_int;
              for (const unsigned int g : cell->face_indices())
                if ((cell->face(g)->vertex_index(0) == a && cell->face(g)->vertex_index(1) == b) ||
                    (cell->face(g)->vertex_index(0) == b && cell->face(g)->vertex_index(1) == a))
                  f = g;
              AssertThrow(f != dealii::numbers::invalid_unsigned_int,
                          dealii::ExcMessage("from_triangulation: cell " + std::to_string(cell->active_cell_index()) +
                                             " has no face joining its vertices " + std::to_string(a) + " and " +
                                             std::to_string(b) + "."));
              const FaceIterator face = cell->face(f);
              inside.clear();
              leaves.clear();
              collect_face_pieces(face, active_vertex, inside, leaves);
              if (face->vertex_index(0) != a)
                {
                  std::reverse(inside.begin(), inside.end());
                  std::reverse(leaves.begin(), leaves.end());
                }
              loop.push_back(a);
              loop.insert(loop.end(), inside.begin(), inside.end());
              if (face->at_boundary())
                {
                  // every piece carries the boundary id of its own face
                  // (children of a boundary face have their ids)
                  unsigned int prev = a;
                  for (unsigned int j = 0; j < leaves.size(); ++j)
                    {
                      const unsigned int next = (j < inside.size() ? inside[j] : b);
                      boundary_pieces.emplace_back(std::array<unsigned int, 2>{{prev, next}}, leaves[j]->boundary_id());
                      prev = next;
                    }
                }
            }

          double area = 0;
          for (unsigned int i = 0; i < loop.size(); ++i)
            {
              const P &p = mesh.vertex(loop[i]), &q = mesh.vertex(loop[(i + 1) % loop.size()]);
              area += p[0] * q[1] - q[0] * p[1];
            }
          if (area < 0)
            std::reverse(loop.begin(), loop.end());
          if (separate_material_ids)
            {
              // each material id keeps vertices of its own: the first id
              // at a vertex uses the triangulation's, the others copies
              const auto own = [&](const unsigned int v) {
                const auto it = vertex_owner.try_emplace(v, cell->material_id()).first;
                if (it->second == cell->material_id())
                  return v;
                const auto copy = vertex_copies.try_emplace({v, cell->material_id()}, mesh.n_vertices());
                if (copy.second)
                  mesh.add_vertex(mesh.vertex(v));
                return copy.first->second;
              };
              for (auto &v : loop)
                v = own(v);
              for (auto &piece : boundary_pieces)
                for (auto &v : piece.first)
                  v = own(v);
            }
          mesh.add_cell(loop, cell->material_id());
          for (const auto &piece : boundary_pieces)
            mesh.set_boundary_id(piece.first[0], piece.first[1], piece.second);
        }
      mesh.finalize();
    }



    template <int dim>
    void
    from_gridin_file(PolygonalMesh<dim> &mesh,
                     const std::string  &filename,
                     const unsigned int  n_refinements,
                     const bool          separate_material_ids)
    {
      AssertThrow(std::filesystem::exists(filename),
                  dealii::ExcMessage("Mesh file '" + filename + "' does not exist."));
      AssertThrow(!std::filesystem::is_directory(filename),
                  dealii::ExcMessage("Mesh file '" + filename + "' is a directory."));
      const std::string ext    = std::filesystem::path(filename).extension().string();
      const std::string format = ext.empty() ? "msh" : ext.substr(1);
      // gmsh files: read natively (any mix of element kinds, binary files,
      // physical names; refined natively)
      if (format == "msh")
        {
          MeshIO::read_msh(mesh, filename, n_refinements, separate_material_ids);
          return;
        }
      dealii::Triangulation<dim> tria;
      dealii::GridIn<dim>        grid_in(tria);
      std::ifstream              in(filename);
      try
        {
          grid_in.read(in, dealii::GridIn<dim>::parse_format(format));
        }
      catch (const std::exception &e)
        {
          AssertThrow(false, dealii::ExcMessage("Cannot read the mesh file '" + filename + "': " + e.what()));
        }
      if (n_refinements > 0)
        tria.refine_global(n_refinements);
      try
        {
          from_triangulation(mesh, tria, separate_material_ids);
        }
      catch (const std::exception &e)
        {
          AssertThrow(false, dealii::ExcMessage("The mesh in the file '" + filename + "' is invalid: " + e.what()));
        }
      mesh.name = filename;
    }

    void
    refine_toward(dealii::Triangulation<2, 2>                            &tria,
                  const std::function<double(const dealii::Point<2> &)> &distance,
                  const double                                           h,
                  const double                                           layers)
    {
      AssertThrow(h > 0 && std::isfinite(h),
                  dealii::ExcMessage("refine_toward(): the target size h must be positive, not " +
                                     std::to_string(h) + "."));
      AssertThrow(layers > 0 && std::isfinite(layers),
                  dealii::ExcMessage("refine_toward(): the number of layers must be positive."));
      for (;;)
        {
          bool any = false;
          for (const auto &cell : tria.active_cell_iterators())
            {
              double size = 0;
              for (unsigned int l = 0; l < dealii::GeometryInfo<2>::lines_per_cell; ++l)
                size = std::max(size, cell->line(l)->vertex(0).distance(cell->line(l)->vertex(1)));
              if (size > 1.3 * h && distance(cell->center()) < layers * size)
                {
                  cell->set_refine_flag();
                  any = true;
                }
            }
          if (!any)
            break;
          tria.execute_coarsening_and_refinement();
        }
    }


    void
    masonry_wall(PolygonalMesh<2> &mesh, const MasonryWall &wall)
    {
      const auto positive = [](const double x, const char *name) {
        AssertThrow(std::isfinite(x) && x > 0,
                    dealii::ExcMessage(std::string("masonry_wall: the ") + name + " must be positive and finite, not " +
                                       std::to_string(x) + "."));
      };
      const auto nonzero = [](const unsigned int n, const char *name) {
        AssertThrow(n > 0, dealii::ExcMessage(std::string("masonry_wall: the ") + name + " must be at least 1."));
      };
      positive(wall.block_width, "block width");
      positive(wall.block_height, "block height");
      nonzero(wall.blocks_per_course, "number of blocks per course");
      nonzero(wall.n_blocks, "number of blocks");
      nonzero(wall.quads_along, "number of quads along a block");
      nonzero(wall.base_quads_across, "number of quads across the base");
      AssertThrow(wall.block_boundary_offset >= 4 && wall.block_boundary_offset <= 65531,
                  dealii::ExcMessage("masonry_wall: the block boundary offset must lie in [4, 65531] (the base "
                                     "uses the ids 0 to 3), not " +
                                     std::to_string(wall.block_boundary_offset) + "."));
      const double       w = wall.block_width, h = wall.block_height;
      const unsigned int m = wall.blocks_per_course;
      structured_quads(mesh, P(-w, -1), P((m + 1) * w, 0), wall.base_quads_along > 0 ? wall.base_quads_along : 4 * (m + 2),
                       wall.base_quads_across);
      std::vector<PolygonalMesh<2>> made;
      made.reserve(wall.n_blocks);
      unsigned int id = 1;
      for (unsigned int c = 0; id <= wall.n_blocks; ++c)
        {
          // the spans of the course, in block widths
          std::vector<std::pair<double, double>> spans;
          if (c % 2 == 0)
            for (unsigned int k = 0; k < m; ++k)
              spans.emplace_back(k, k + 1);
          else
            {
              spans.emplace_back(0, 0.5);
              for (unsigned int k = 0; k + 1 < m; ++k)
                spans.emplace_back(k + 0.5, k + 1.5);
              spans.emplace_back(m - 0.5, m);
            }
          for (const auto &span : spans)
            {
              if (id > wall.n_blocks)
                break;
              const unsigned int along = (id % 2 == 0 ? wall.quads_along : wall.quads_along + 1);
              const double       length = span.second - span.first;
              const unsigned int nx =
                wall.scale_half_blocks ? std::max(1u, static_cast<unsigned int>(along * length + 0.5)) : along;
              const unsigned int ny = wall.quads_across > 0 ? wall.quads_across : std::max(1u, along / 2);
              made.emplace_back();
              structured_quads(made.back(), P(span.first * w, c * h), P(span.second * w, (c + 1) * h), nx, ny);
              for (unsigned int cell = 0; cell < made.back().n_cells(); ++cell)
                made.back().set_material_id(cell, id);
              for (unsigned int e = 0; e < made.back().n_edges(); ++e)
                if (made.back().edge(e).at_boundary())
                  made.back().set_edge_boundary_id(e, made.back().edge(e).boundary_id + wall.block_boundary_offset);
              ++id;
            }
        }
      std::vector<const PolygonalMesh<2> *> parts;
      parts.reserve(made.size());
      for (const auto &block : made)
        parts.push_back(&block);
      mesh.append(parts);
      mesh.name = "masonry wall, " + std::to_string(wall.n_blocks) + " blocks";
    }


    template void structured_quads(PolygonalMesh<2> &, const P &, const P &, const unsigned int, const unsigned int);
    template void structured_triangles(PolygonalMesh<2> &, const P &, const P &, const unsigned int, const unsigned int);
    template void perturbed_quads(PolygonalMesh<2> &, const P &, const P &, const unsigned int, const unsigned int,
                                  const double, const unsigned int);
    template void nonconvex(PolygonalMesh<2> &, const P &, const P &, const unsigned int, const unsigned int,
                            const double);
    template void from_triangulation(PolygonalMesh<2> &, const dealii::Triangulation<2, 2> &, const bool);
    template void from_gridin_file(PolygonalMesh<2> &, const std::string &, const unsigned int, const bool);
  } // namespace PolygonalMeshGenerators
} // namespace dealvem
