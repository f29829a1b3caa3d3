// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <dealvem/config.h>
#include <dealvem/mesh/generators.h>

#ifdef DEALVEM_WITH_CGAL
#  include <CGAL/Delaunay_triangulation_2.h>
#  include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#  include <CGAL/Triangulation_vertex_base_with_info_2.h>
#endif

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

      // Give boundary ids 0..3 to the boundary edges on the sides of the
      // rectangle and finalize.
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

      void
      grid_vertices(PolygonalMesh<2> &mesh, const P &p0, const P &p1, const unsigned int nx,
                    const unsigned int ny)
      {
        for (unsigned int j = 0; j <= ny; ++j)
          for (unsigned int i = 0; i <= nx; ++i)
            mesh.add_vertex(P(p0[0] + (p1[0] - p0[0]) * i / nx, p0[1] + (p1[1] - p0[1]) * j / ny));
      }
    } // namespace



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



    template <int dim>
    void
    voronoi(PolygonalMesh<dim> &mesh, const dealii::Point<dim> &p0, const dealii::Point<dim> &p1,
            const unsigned int n_cells, const unsigned int n_lloyd_iterations, const unsigned int seed)
    {
      check_rectangle(p0, p1, 1, 1, "voronoi");
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
      using K     = CGAL::Exact_predicates_inexact_constructions_kernel;
      using Vb    = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
      using Tds   = CGAL::Triangulation_data_structure_2<Vb>;
      using DT    = CGAL::Delaunay_triangulation_2<K, Tds>;
      using CP    = K::Point_2;
      const double W = p1[0] - p0[0], H = p1[1] - p0[1], size = std::max(W, H);

      std::mt19937                           rng(seed);
      std::uniform_real_distribution<double> ux(p0[0], p1[0]), uy(p0[1], p1[1]);
      std::vector<P>                         sites(n_cells);
      for (auto &s : sites)
        {
          const double x = ux(rng), y = uy(rng);
          s              = P(x, y);
        }

      std::vector<std::vector<P>> polygons;
      for (unsigned int iteration = 0; iteration <= n_lloyd_iterations; ++iteration)
        {
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
          polygons.assign(n_cells, {});
          std::vector<bool> found(n_cells, false);
          for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
            {
              const int i = v->info();
              if (i < 0)
                continue;
              AssertThrow(!found[i], dealii::ExcMessage("voronoi: two generators coincide (seed " +
                                                         std::to_string(seed) + ")."));
              found[i]  = true;
              auto f    = dt.incident_faces(v), done = f;
              do
                {
                  AssertThrow(!dt.is_infinite(f),
                              dealii::ExcMessage("voronoi: unbounded cell; internal error."));
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
          if (iteration == n_lloyd_iterations)
            break;
          // Lloyd: move the sites to the centroids
          for (unsigned int i = 0; i < n_cells; ++i)
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

      // merge coincident Voronoi vertices (mirror images make cocircular
      // quadruples) and snap vertices onto the sides
      mesh.clear();
      mesh.name = "voronoi " + std::to_string(n_cells) + " cells, seed " + std::to_string(seed);
      const double tol = 1e-9 * size;
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
      finish_rectangle(mesh, p0, p1);
      AssertThrow(std::abs(mesh.total_area() - W * H) <= 1e-10 * W * H,
                  dealii::ExcMessage("voronoi: the cells do not cover the rectangle; internal error."));
#endif
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



    namespace
    {
      // Coordinates beyond this magnitude are refused (PolygonalMesh uses
      // the same limit): products of coordinate differences would overflow.
      constexpr double max_gmsh_coordinate = 1e100;

      // Checks a gmsh .msh file before deal.II's GridIn reads it. GridIn
      // trusts the counts and the version in the file (a wrong count or
      // version corrupts memory or hangs it, ids out of range are silently
      // truncated), so everything GridIn relies on is checked here, one line
      // at a time: the header, the section markers, the counts (against the
      // size of the file and the lines actually present), node tags, the
      // element types and the physical ids used as material and boundary
      // ids. Memory is proportional to the number of nodes actually present.
      class GmshChecker
      {
      public:
        // separate_parts: cells of different physical surfaces may share
        // edges (the parts of a conforming assembly mesh, given their own
        // nodes afterwards)
        explicit GmshChecker(const std::string &filename, const bool separate_parts = false)
          : filename(filename)
          , separate_parts(separate_parts)
          , in(filename)
        {
          AssertThrow(in, dealii::ExcMessage("Cannot open the mesh file '" + filename + "'."));
          std::error_code ec;
          file_size = std::filesystem::file_size(filename, ec);
          if (ec)
            file_size = std::numeric_limits<std::uintmax_t>::max();
        }

        void
        run()
        {
          read_line("$MeshFormat");
          AssertThrow(words.size() == 1 && words[0] == "$MeshFormat",
                      error(words.size() == 1 && words[0] == "$NOD" ?
                              "gmsh format 1 ($NOD) is not supported; save the mesh in format 2.2 or 4.1." :
                              "expected $MeshFormat (a gmsh .msh file), found '" + text + "'."));
          read_header();
          read_line("$EndMeshFormat");
          expect_marker("$EndMeshFormat");
          read_line("$Nodes");
          if (words[0] == "$PhysicalNames")
            {
              skip_physical_names();
              read_line("$Nodes");
            }
          if (words[0] == "$Entities")
            {
              AssertThrow(version >= 40,
                          error("an $Entities section in a gmsh " + version_text + " file; is the version in "
                                "$MeshFormat right?"));
              read_entities();
              read_line("$Nodes");
            }
          if (words[0] == "$PartitionedEntities")
            {
              skip_section("$EndPartitionedEntities");
              read_line("$Nodes");
            }
          expect_marker("$Nodes");
          if (version < 40)
            read_nodes_2();
          else
            read_nodes_4();
          read_line("$EndNodes");
          expect_marker("$EndNodes");
          read_line("$Elements");
          expect_marker("$Elements");
          if (version < 40)
            read_elements_2();
          else
            read_elements_4();
          read_line("$EndElements");
          expect_marker("$EndElements");
          AssertThrow(n_triangles + n_quads > 0,
                      error("the file has no triangles or quadrangles (element types 2 and 3): no cells."));
          AssertThrow(n_triangles == 0 || n_quads == 0,
                      error("the file mixes " + std::to_string(n_triangles) + " triangles and " +
                            std::to_string(n_quads) + " quadrangles; deal.II reads one kind only."));
          check_cells();
          check_lines();
        }

      private:
        std::string           filename;
        bool                  separate_parts = false;
        std::ifstream         in;
        std::uintmax_t        file_size = 0;
        std::size_t           line = 0;
        std::string           text;
        std::vector<std::string> words;
        int                   version = 0; // 22, 40, 41
        std::string           version_text;
        // node tag -> coordinates (x, y)
        std::unordered_map<long long, std::array<double, 2>> nodes;
        // an element as the file gives it, for the checks of check_topology()
        struct Element
        {
          long long              number   = 0;  // element number (2.x) or tag (4.x)
          std::size_t            line     = 0;  // line in the file
          long long              physical = 0;  // physical tag (material or boundary id)
          unsigned int           type     = 0;  // 1 line, 2 triangle, 3 quadrangle
          std::array<long long, 4> node   = {{0, 0, 0, 0}};
        };
        std::vector<Element>  cells, lines;
        // physical tag of each entity (dimension, tag) of a version 4 file
        std::map<std::pair<long long, long long>, long long> entity_physical;
        // (dimension, tag) of the entities of a version 4 file
        std::set<std::pair<long long, long long>> entities;
        bool                  have_entities = false;
        unsigned long long    n_triangles = 0, n_quads = 0;

        dealii::ExcMessage
        error(const std::string &what) const
        {
          return dealii::ExcMessage("Invalid gmsh file " + filename + ":" + std::to_string(line) + ": " + what);
        }

        // the next line that is not blank, split into words
        void
        read_line(const std::string &expected)
        {
          while (true)
            {
              AssertThrow(static_cast<bool>(std::getline(in, text)),
                          error("unexpected end of file, expected " + expected +
                                "; the file is truncated."));
              ++line;
              if (!text.empty() && text.back() == '\r')
                text.pop_back();
              words.clear();
              std::istringstream s(text);
              std::string        w;
              while (s >> w)
                words.push_back(w);
              if (!words.empty())
                return;
            }
        }

        void
        expect_marker(const std::string &marker)
        {
          AssertThrow(words.size() == 1 && words[0] == marker,
                      error("expected " + marker + ", found '" + text + "'."));
        }

        void
        expect_words(const std::size_t n, const std::string &what)
        {
          AssertThrow(words.size() == n, error("expected " + what + " (" + std::to_string(n) +
                                               (n == 1 ? " number" : " numbers") + " on the line), found '" +
                                               text + "'."));
        }

        long long
        integer(const std::string &word, const std::string &what, const long long min, const long long max) const
        {
          long long  v = 0;
          const auto r = std::from_chars(word.data(), word.data() + word.size(), v);
          AssertThrow(r.ec == std::errc() && r.ptr == word.data() + word.size() && v >= min && v <= max,
                      error("expected " + what + " (an integer from " + std::to_string(min) + " to " +
                            std::to_string(max) + "), found '" + word + "'."));
          return v;
        }

        // A count of records that follow, each on a line of its own of at
        // least @p min_bytes bytes: bounded by the size of the file.
        long long
        count(const std::string &word, const std::string &what, const std::uintmax_t min_bytes = 2) const
        {
          long long  n = 0;
          const auto r = std::from_chars(word.data(), word.data() + word.size(), n);
          AssertThrow(r.ec == std::errc() && r.ptr == word.data() + word.size() && n >= 0,
                      error("expected " + what + " (a non-negative integer), found '" + word + "'."));
          const std::uintmax_t capacity = file_size / min_bytes;
          AssertThrow(static_cast<std::uintmax_t>(n) <= capacity,
                      error(what + " is " + word + ", but the file has only " + std::to_string(file_size) +
                            " bytes, room for at most " + std::to_string(capacity) +
                            "; the count is wrong or the file is truncated."));
          return n;
        }

        double
        coordinate(const std::string &word, const std::string &what) const
        {
          char        *end = nullptr;
          const double v   = std::strtod(word.c_str(), &end);
          AssertThrow(end == word.c_str() + word.size() && std::isfinite(v),
                      error("expected " + what + " (a finite number), found '" + word + "'."));
          AssertThrow(std::abs(v) <= max_gmsh_coordinate,
                      error(what + " is " + word + "; coordinates larger than 1e100 in magnitude are not "
                            "supported."));
          return v;
        }

        // a physical tag that deal.II turns into a material or boundary id
        // (material ids of cells: 0..max_material_id, so that an assembly
        // of many parts, one physical surface each, can be read; boundary
        // ids: 0..254, the range of the parameter files)
        void
        check_id(const std::string &word, const std::string &what, const bool material = false) const
        {
          long long        v   = 0;
          const auto       r   = std::from_chars(word.data(), word.data() + word.size(), v);
          const long long  max = material ? PolygonalMeshGenerators::max_material_id : 254;
          AssertThrow(r.ec == std::errc() && r.ptr == word.data() + word.size() && v >= 0 && v <= max,
                      error(what + " is '" + word + "', but it becomes " +
                            (material ? std::string("a material id, which must be an integer from 0 to ") +
                                          std::to_string(max) :
                                        std::string("a boundary id, which must be an integer from 0 to 254")) +
                            "."));
        }

        void
        read_header()
        {
          read_line("the version line");
          expect_words(3, "'version file-type data-size'");
          version_text = words[0];
          if (words[0] == "2.2" || words[0] == "2.1" || words[0] == "2" || words[0] == "2.0")
            version = 22;
          else if (words[0] == "4" || words[0] == "4.0")
            version = 40;
          else if (words[0] == "4.1")
            version = 41;
          else
            AssertThrow(false, error("unsupported gmsh format version '" + words[0] +
                                     "' (supported: 2.2 and 4.x, that is 4.0 and 4.1)."));
          AssertThrow(words[1] == "0",
                      error(words[1] == "1" ? "binary gmsh files (file-type 1) are not supported; save the mesh "
                                              "as ASCII (file-type 0)." :
                                              "expected the file-type 0 (ASCII), found '" + words[1] + "'."));
          AssertThrow(words[2] == "8", error("expected the data size 8, found '" + words[2] + "'."));
        }

        void
        skip_physical_names()
        {
          read_line("the number of physical names");
          expect_words(1, "the number of physical names");
          const long long n = count(words[0], "the number of physical names", 6);
          for (long long i = 0; i < n; ++i)
            {
              read_line("physical name " + std::to_string(i + 1) + " of " + std::to_string(n));
              AssertThrow(words.size() >= 3 && words[0][0] != '$',
                          error("expected physical name " + std::to_string(i + 1) + " of " +
                                std::to_string(n) + " ('dimension tag \"name\"'), found '" + text + "'."));
              integer(words[0], "the dimension of a physical name", 0, 3);
            }
          read_line("$EndPhysicalNames");
          expect_marker("$EndPhysicalNames");
        }

        void
        skip_section(const std::string &end)
        {
          const std::string begin = words[0];
          do
            {
              read_line(end);
              AssertThrow(words[0] == end || words[0][0] != '$',
                          error("expected " + end + " to close " + begin + ", found '" + text + "'."));
            }
          while (words[0] != end);
          expect_marker(end);
        }

        void
        read_entities()
        {
          read_line("the numbers of points, curves, surfaces and volumes");
          expect_words(4, "the numbers of points, curves, surfaces and volumes");
          long long n[4];
          for (unsigned int d = 0; d < 4; ++d)
            n[d] = count(words[d], "the number of entities of dimension " + std::to_string(d), 8);
          have_entities = true;
          for (unsigned int d = 0; d < 4; ++d)
            for (long long i = 0; i < n[d]; ++i)
              {
                const std::string what = "entity " + std::to_string(i + 1) + " of " + std::to_string(n[d]) +
                                         " of dimension " + std::to_string(d);
                read_line(what);
                // tag, a box (one point for points in 4.1), physical tags,
                // and bounding entities for curves and up
                const std::size_t n_box = (d == 0 && version == 41) ? 3 : 6;
                AssertThrow(words.size() >= 2 + n_box && words[0][0] != '$',
                            error("expected " + what + ", found '" + text + "'."));
                const long long tag = integer(words[0], "the tag of " + what, std::numeric_limits<int>::min(),
                                              std::numeric_limits<int>::max());
                for (std::size_t k = 1; k <= n_box; ++k)
                  coordinate(words[k], "a bounding box coordinate of " + what);
                const long long n_physicals =
                  integer(words[1 + n_box], "the number of physical tags of " + what, 0, 1);
                std::size_t w = 2 + n_box;
                AssertThrow(words.size() >= w + n_physicals,
                            error("expected " + what + ", found '" + text + "'."));
                for (long long k = 0; k < n_physicals; ++k)
                  {
                    check_id(words[w], "the physical tag of " + what, d == 2);
                    entity_physical[{d, tag}] = integer(words[w++], "the physical tag of " + what, 0,
                                                        d == 2 ? PolygonalMeshGenerators::max_material_id : 254);
                  }
                if (d > 0)
                  {
                    AssertThrow(words.size() > w, error("expected the number of bounding entities of " + what +
                                                        ", found '" + text + "'."));
                    const long long n_bounding = integer(words[w++], "the number of bounding entities of " + what,
                                                         0, std::numeric_limits<int>::max());
                    AssertThrow(words.size() == w + n_bounding,
                                error("expected " + std::to_string(n_bounding) + " bounding entities of " + what +
                                      ", found '" + text + "'."));
                    for (; w < words.size(); ++w)
                      integer(words[w], "a bounding entity of " + what, std::numeric_limits<int>::min(),
                              std::numeric_limits<int>::max());
                  }
                else
                  AssertThrow(words.size() == w, error("expected " + what + ", found '" + text + "'."));
                entities.insert({d, tag});
              }
          read_line("$EndEntities");
          expect_marker("$EndEntities");
        }

        long long
        add_node(const std::string &tag_word, const std::string &what)
        {
          const long long tag = integer(tag_word, "the tag of " + what, 1, std::numeric_limits<int>::max());
          AssertThrow(nodes.emplace(tag, std::array<double, 2>{{0., 0.}}).second,
                      error("node tag " + tag_word + " is used twice."));
          return tag;
        }

        void
        set_node(const long long tag, const std::string &x, const std::string &y, const std::string &z,
                 const std::string &what)
        {
          nodes[tag] = {{coordinate(x, "x of " + what), coordinate(y, "y of " + what)}};
          coordinate(z, "z of " + what);
        }

        void
        read_nodes_2()
        {
          read_line("the number of nodes");
          expect_words(1, "the number of nodes after $Nodes");
          // "tag x y z": at least 8 bytes a node
          const long long n = count(words[0], "the number of nodes", 8);
          for (long long i = 0; i < n; ++i)
            {
              const std::string what = "node " + std::to_string(i + 1) + " of " + std::to_string(n);
              read_line(what);
              AssertThrow(words.size() == 4 && words[0][0] != '$',
                          error("expected " + what + " ('tag x y z'), found '" + text + "'."));
              set_node(add_node(words[0], what), words[1], words[2], words[3], what);
            }
        }

        void
        read_nodes_4()
        {
          read_line("the node counts");
          const bool v41 = (version == 41);
          expect_words(v41 ? 4 : 2, v41 ? "'numEntityBlocks numNodes minNodeTag maxNodeTag' after $Nodes, as "
                                          "format 4.1 in $MeshFormat says" :
                                          "'numEntityBlocks numNodes' after $Nodes, as format 4.0 in $MeshFormat "
                                          "says");
          const long long n_blocks = count(words[0], "the number of node blocks", 8);
          const long long n        = count(words[1], "the number of nodes", 8);
          long long       n_read   = 0;
          for (long long b = 0; b < n_blocks; ++b)
            {
              const std::string block = "node block " + std::to_string(b + 1) + " of " + std::to_string(n_blocks);
              read_line(block);
              expect_words(4, "the header of " + block);
              // 4.1: dim tag parametric count; 4.0: tag dim parametric count
              integer(words[v41 ? 0 : 1], "the entity dimension of " + block, 0, 3);
              const long long parametric = integer(words[2], "the parametric flag of " + block, 0, 1);
              AssertThrow(parametric == 0, error("parametric nodes are not supported; save the mesh without "
                                                 "parametric coordinates."));
              const long long m = count(words[3], "the number of nodes in " + block, 8);
              AssertThrow(n_read + m <= n, error(block + " goes beyond the " + std::to_string(n) +
                                                 " nodes announced after $Nodes."));
              if (v41)
                {
                  std::vector<long long> tags(m);
                  for (long long i = 0; i < m; ++i)
                    {
                      const std::string what = "node " + std::to_string(n_read + i + 1) + " of " + std::to_string(n);
                      read_line("the tag of " + what);
                      expect_words(1, "the tag of " + what);
                      tags[i] = add_node(words[0], what);
                    }
                  for (long long i = 0; i < m; ++i)
                    {
                      const std::string what = "node " + std::to_string(n_read + i + 1) + " of " + std::to_string(n);
                      read_line("the coordinates of " + what);
                      expect_words(3, "the coordinates 'x y z' of " + what);
                      set_node(tags[i], words[0], words[1], words[2], what);
                    }
                }
              else
                for (long long i = 0; i < m; ++i)
                  {
                    const std::string what = "node " + std::to_string(n_read + i + 1) + " of " + std::to_string(n);
                    read_line(what);
                    expect_words(4, what + " ('tag x y z')");
                    set_node(add_node(words[0], what), words[1], words[2], words[3], what);
                  }
              n_read += m;
            }
          AssertThrow(n_read == n, error("the node blocks hold " + std::to_string(n_read) + " nodes, but " +
                                         std::to_string(n) + " are announced after $Nodes."));
        }

        // number of nodes of a gmsh element type deal.II can read in 2d
        unsigned int
        nodes_of_type(const std::string &word, const std::string &what)
        {
          const long long type = integer(word, "the element type of " + what, 0, std::numeric_limits<int>::max());
          AssertThrow(type == 1 || type == 2 || type == 3 || type == 15,
                      error("element type " + word + " of " + what + " is not supported in 2d (supported: 1 line, "
                            "2 triangle, 3 quadrangle, 15 point)."));
          n_triangles += (type == 2);
          n_quads += (type == 3);
          return type == 1 ? 2 : type == 2 ? 3 : type == 3 ? 4 : 1;
        }

        void
        check_element_nodes(const std::size_t first, const std::string &what)
        {
          for (std::size_t k = first; k < words.size(); ++k)
            {
              long long  v = 0;
              const auto r = std::from_chars(words[k].data(), words[k].data() + words[k].size(), v);
              AssertThrow(r.ec == std::errc() && r.ptr == words[k].data() + words[k].size() &&
                            nodes.count(v) == 1,
                          error(what + " refers to node '" + words[k] + "', which is not in $Nodes."));
              for (std::size_t j = first; j < k; ++j)
                AssertThrow(words[j] != words[k], error(what + " uses node " + words[k] + " twice."));
            }
        }

        // Keeps a line, triangle or quadrangle whose node tags are words
        // first, first + 1, ... of the current line (points are not kept).
        void
        keep_element(const long long number, const long long physical, const std::string &type_word,
                     const std::size_t first)
        {
          Element e;
          e.number   = number;
          e.line     = line;
          e.physical = physical;
          e.type     = static_cast<unsigned int>(std::stoi(type_word));
          if (e.type != 1 && e.type != 2 && e.type != 3)
            return;
          const unsigned int n = (e.type == 1 ? 2 : e.type == 2 ? 3 : 4);
          for (unsigned int k = 0; k < n; ++k)
            std::from_chars(words[first + k].data(), words[first + k].data() + words[first + k].size(), e.node[k]);
          (e.type == 1 ? lines : cells).push_back(e);
        }

        unsigned int
        n_nodes(const Element &e) const
        {
          return e.type == 1 ? 2 : e.type == 2 ? 3 : 4;
        }

        // "quadrangle 7", with " (line 23)" if @p at_line
        std::string
        name(const Element &e, const bool at_line = true) const
        {
          return std::string(e.type == 1 ? "line element " : e.type == 2 ? "triangle " : "quadrangle ") +
                 std::to_string(e.number) + (at_line ? " (line " + std::to_string(e.line) + ")" : std::string());
        }

        std::string
        node_list(const Element &e) const
        {
          std::ostringstream s;
          s << std::setprecision(15);
          for (unsigned int k = 0; k < n_nodes(e); ++k)
            {
              const auto &x = nodes.at(e.node[k]);
              s << (k > 0 ? ", " : "") << e.node[k] << " (" << x[0] << ", " << x[1] << ")";
            }
          return s.str();
        }

        static std::pair<long long, long long>
        edge_key(const long long a, const long long b)
        {
          return {std::min(a, b), std::max(a, b)};
        }

        // The error for element @p e, with the file and its line first.
        dealii::ExcMessage
        element_error(const Element &e, const std::string &what) const
        {
          return dealii::ExcMessage("Invalid gmsh file " + filename + ":" + std::to_string(e.line) + ": " + what);
        }

        // Cells before deal.II builds its triangulation from them: no cell
        // without area (collinear or coincident nodes, which deal.II turns
        // into wrong neighbours and "boundary id for an internal face"), no
        // self-intersecting quadrangle, no cell given twice, no edge of
        // more than two cells, no edge between two bodies (physical
        // surfaces: they interact through contact only).
        void
        check_cells()
        {
          // the size of the mesh, for the tolerance of the area test
          double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
          double hi[2] = {-lo[0], -lo[1]};
          for (const auto &c : cells)
            for (unsigned int k = 0; k < n_nodes(c); ++k)
              for (unsigned int d = 0; d < 2; ++d)
                {
                  lo[d] = std::min(lo[d], nodes.at(c.node[k])[d]);
                  hi[d] = std::max(hi[d], nodes.at(c.node[k])[d]);
                }
          std::map<std::vector<long long>, std::size_t> seen;
          for (std::size_t i = 0; i < cells.size(); ++i)
            {
              const Element &c = cells[i];
              const unsigned int n = n_nodes(c);
              // signed area and the turn at each corner
              double       area = 0, length = 0;
              unsigned int left = 0, right = 0;
              for (unsigned int k = 0; k < n; ++k)
                {
                  const auto &a = nodes.at(c.node[k]), &b = nodes.at(c.node[(k + 1) % n]),
                             &q = nodes.at(c.node[(k + 2) % n]);
                  area += a[0] * b[1] - b[0] * a[1];
                  length = std::max(length, std::hypot(b[0] - a[0], b[1] - a[1]));
                  const double turn = (b[0] - a[0]) * (q[1] - b[1]) - (b[1] - a[1]) * (q[0] - b[0]);
                  left += (turn > 0);
                  right += (turn < 0);
                }
              area /= 2;
              // two corners of the cell at one point (distinct node tags)
              for (unsigned int k = 0; k < n && length > 0; ++k)
                {
                  const auto &a = nodes.at(c.node[k]), &b = nodes.at(c.node[(k + 1) % n]);
                  AssertThrow(a != b,
                              element_error(c, name(c, false) + " has its nodes " + std::to_string(c.node[k]) +
                                                 " and " + std::to_string(c.node[(k + 1) % n]) +
                                                 " at the same point (" + node_list(c) +
                                                 "): a side of length zero. Merge the two nodes or remove "
                                                 "the cell."));
                }
              AssertThrow(n == 3 || (left != 2 || right != 2) || length == 0,
                          element_error(c, name(c, false) + " crosses itself (its sides cross like a bow tie): "
                                             "nodes " + node_list(c) +
                                             ". List the nodes in their order around the cell."));
              AssertThrow(std::abs(area) > 1e-12 * length * length && length > 0,
                          element_error(c, name(c, false) + " has zero area: its nodes " + node_list(c) +
                                             (length == 0 ? " lie at one point." :
                                              n == 3      ? " lie on one line." :
                                                            " enclose no area.") +
                                             " Remove the cell or move its nodes apart."));
              std::vector<long long> key(c.node.begin(), c.node.begin() + n);
              std::sort(key.begin(), key.end());
              const auto it = seen.emplace(key, i);
              AssertThrow(it.second,
                          element_error(c, name(c, false) + " has the same nodes as " + name(cells[it.first->second]) +
                                             ": a cell is given twice. Remove one of them."));
            }
          for (std::size_t i = 0; i < cells.size(); ++i)
            {
              const Element &c = cells[i];
              for (unsigned int k = 0; k < n_nodes(c); ++k)
                edge_cells[edge_key(c.node[k], c.node[(k + 1) % n_nodes(c)])].push_back(i);
            }
          for (const auto &e : edge_cells)
            {
              if (e.second.size() > 2)
                {
                  const Element &c = cells[e.second[2]];
                  AssertThrow(false,
                              element_error(c, "the edge from node " + std::to_string(e.first.first) + " to node " +
                                                 std::to_string(e.first.second) + " belongs to three cells: " +
                                                 name(cells[e.second[0]]) + ", " + name(cells[e.second[1]]) +
                                                 " and " + name(c) + "; cells overlap there."));
                }
              if (e.second.size() == 2)
                {
                  const Element &a = cells[e.second[0]], &b = cells[e.second[1]];
                  AssertThrow(a.physical == b.physical || separate_parts,
                              element_error(b, name(a) + " (physical surface " + std::to_string(a.physical) +
                                                 ") and " + name(b) + " (physical surface " +
                                                 std::to_string(b.physical) + ") share the edge from node " +
                                                 std::to_string(e.first.first) + " to node " +
                                                 std::to_string(e.first.second) +
                                                 ". Different physical surfaces are different bodies (material "
                                                 "ids), and bodies interact through contact only: give each "
                                                 "body its own nodes along the interface (separate curves in "
                                                 "gmsh), put both in one physical surface, or read the parts as separate bodies "
                                                 "('Mesh/Parts as bodies = true')."));
                }
            }
        }

        // Line elements become boundary ids of the edges they lie on
        // (deal.II asserts in tria.cc otherwise): each must be an edge of
        // exactly one cell, and an edge gets one id.
        void
        check_lines()
        {
          std::map<std::pair<long long, long long>, std::size_t> seen;
          for (std::size_t i = 0; i < lines.size(); ++i)
            {
              const Element &l   = lines[i];
              const auto     key = edge_key(l.node[0], l.node[1]);
              const auto     it  = edge_cells.find(key);
              AssertThrow(it != edge_cells.end(),
                          element_error(l, name(l, false) + " (physical line " + std::to_string(l.physical) +
                                             ") joins the nodes " + node_list(l) +
                                             ", which are not the two ends of an edge of any cell; a boundary "
                                             "id can only go to a cell side. Is the curve meshed with other "
                                             "nodes than the surface (a missing 'Coherence', or a curve not "
                                             "part of the surface)?"));
              AssertThrow(it->second.size() == 1,
                          element_error(l, name(l, false) + " (physical line " + std::to_string(l.physical) +
                                             ") lies on the edge from node " + std::to_string(key.first) +
                                             " to node " + std::to_string(key.second) +
                                             " inside the mesh, between " + name(cells[it->second[0]]) + " and " +
                                             name(cells[it->second[1]]) +
                                             "; boundary ids go to boundary edges only. Remove the curve from "
                                             "the physical group (or the line from the file)."));
              const auto s = seen.emplace(key, i);
              AssertThrow(s.second || lines[s.first->second].physical == l.physical,
                          element_error(l, name(l, false) + " (physical line " + std::to_string(l.physical) +
                                             ") and " + name(lines[s.first->second]) + " (physical line " +
                                             std::to_string(lines[s.first->second].physical) +
                                             ") give the edge from node " + std::to_string(key.first) +
                                             " to node " + std::to_string(key.second) +
                                             " two boundary ids. Keep one of them."));
            }
        }

        // the cells (indices into cells) at each edge, by its node tags
        std::map<std::pair<long long, long long>, std::vector<std::size_t>> edge_cells;

        void
        read_elements_2()
        {
          read_line("the number of elements");
          expect_words(1, "the number of elements after $Elements");
          const long long n = count(words[0], "the number of elements", 8);
          for (long long i = 0; i < n; ++i)
            {
              const std::string what = "element " + std::to_string(i + 1) + " of " + std::to_string(n);
              read_line(what);
              AssertThrow(words.size() >= 3 && words[0][0] != '$',
                          error("expected " + what + " ('number type n-tags tags... nodes...'), found '" + text +
                                "'."));
              const long long number = integer(words[0], "the number of " + what, 0, std::numeric_limits<int>::max());
              const unsigned int n_nodes = nodes_of_type(words[1], what);
              const long long    n_tags  = integer(words[2], "the number of tags of " + what, 0, 1000);
              AssertThrow(words.size() == std::size_t(3 + n_tags + n_nodes),
                          error("expected " + std::to_string(n_tags) + " tags and " + std::to_string(n_nodes) +
                                " nodes for " + what + ", found '" + text + "'."));
              // the first tag (the physical group) becomes the id
              long long physical = 0;
              if (n_tags > 0)
                {
                  // triangles and quadrangles: material ids; lines: boundary ids
                  const bool cell = (words[1] == "2" || words[1] == "3");
                  check_id(words[3], "the physical tag of " + what, cell);
                  physical = integer(words[3], "the physical tag of " + what, 0,
                                     cell ? PolygonalMeshGenerators::max_material_id : 254);
                }
              for (long long k = 1; k < n_tags; ++k)
                integer(words[3 + k], "a tag of " + what, std::numeric_limits<int>::min(),
                        std::numeric_limits<int>::max());
              check_element_nodes(3 + n_tags, what);
              keep_element(number, physical, words[1], 3 + n_tags);
            }
        }

        void
        read_elements_4()
        {
          read_line("the element counts");
          const bool v41 = (version == 41);
          expect_words(v41 ? 4 : 2, v41 ? "'numEntityBlocks numElements minElementTag maxElementTag' after "
                                          "$Elements in format 4.1" :
                                          "'numEntityBlocks numElements' after $Elements in format 4.0");
          const long long n_blocks = count(words[0], "the number of element blocks", 8);
          const long long n        = count(words[1], "the number of elements", 4);
          long long       n_read   = 0;
          for (long long b = 0; b < n_blocks; ++b)
            {
              const std::string block =
                "element block " + std::to_string(b + 1) + " of " + std::to_string(n_blocks);
              read_line(block);
              expect_words(4, "the header of " + block);
              // 4.1: dim tag type count; 4.0: tag dim type count
              const long long dim = integer(words[v41 ? 0 : 1], "the entity dimension of " + block, 0, 3);
              const long long tag = integer(words[v41 ? 1 : 0], "the entity tag of " + block,
                                            std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
              AssertThrow(!have_entities || entities.count({dim, tag}) == 1,
                          error(block + " refers to the entity of dimension " + std::to_string(dim) +
                                " and tag " + std::to_string(tag) + ", which is not in $Entities."));
              const std::string  type_word = words[2];
              const long long    m         = count(words[3], "the number of elements in " + block, 4);
              AssertThrow(n_read + m <= n, error(block + " goes beyond the " + std::to_string(n) +
                                                 " elements announced after $Elements."));
              for (long long i = 0; i < m; ++i)
                {
                  const std::string what =
                    "element " + std::to_string(n_read + i + 1) + " of " + std::to_string(n);
                  const unsigned int n_nodes = nodes_of_type(type_word, block);
                  read_line(what);
                  AssertThrow(words.size() == 1 + n_nodes,
                              error("expected " + what + " ('tag' and " + std::to_string(n_nodes) +
                                    " nodes), found '" + text + "'."));
                  const long long number = integer(words[0], "the tag of " + what, 1, std::numeric_limits<int>::max());
                  check_element_nodes(1, what);
                  const auto p = entity_physical.find({dim, tag});
                  keep_element(number, p == entity_physical.end() ? 0 : p->second, type_word, 1);
                }
              n_read += m;
            }
          AssertThrow(n_read == n, error("the element blocks hold " + std::to_string(n_read) + " elements, but " +
                                         std::to_string(n) + " are announced after $Elements."));
        }
      };
    } // namespace



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
      // deal.II's gmsh reader trusts the file: check it first
      if (format == "msh")
        GmshChecker(filename, separate_material_ids).run();
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


    template void structured_quads(PolygonalMesh<2> &, const P &, const P &, const unsigned int, const unsigned int);
    template void structured_triangles(PolygonalMesh<2> &, const P &, const P &, const unsigned int, const unsigned int);
    template void perturbed_quads(PolygonalMesh<2> &, const P &, const P &, const unsigned int, const unsigned int,
                                  const double, const unsigned int);
    template void nonconvex(PolygonalMesh<2> &, const P &, const P &, const unsigned int, const unsigned int,
                            const double);
    template void voronoi(PolygonalMesh<2> &, const P &, const P &, const unsigned int, const unsigned int,
                         const unsigned int);
    template void from_triangulation(PolygonalMesh<2> &, const dealii::Triangulation<2, 2> &, const bool);
    template void from_gridin_file(PolygonalMesh<2> &, const std::string &, const unsigned int, const bool);
  } // namespace PolygonalMeshGenerators
} // namespace dealvem
