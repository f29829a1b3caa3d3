// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// PolyhedralMeshGenerators::voronoi_convex(), the centroidal Voronoi mesh of
// a convex domain given by half-spaces, and convex_hull_half_spaces(),
// checked against numbers the geometry fixes (cell volumes, areas and
// second moments computed here from the face loops, not by the mesh). The
// domains: a tetrahedron with the legs 2, 1, 1.5 (volume 1/2; its oblique
// normal not of unit length); a regular hexagonal prism (circumradius 1,
// height 0.8; its normals of length 3 and 2); the truncated octahedron, the
// convex hull of the 24 permutations of (0, +-1, +-2) (volume 32, six squares
// of area 2, eight regular hexagons of area 3 sqrt(3)); the unit cube cut by
// x + y + z <= 2 (volume 5/6), with three redundant half-spaces: x <= 5, a
// second x <= 1, and -x - y - z <= 0, which touches the cube at a corner;
// the unit cube with a redundant x <= 1 + 1e-9 listed before its faces.
// Checked on each:
// - as many cells as asked for, each of positive volume; the volumes sum to
//   the domain's (1e-12 relative); every cell closed (the sum of its faces'
//   area vectors vanishes, 1e-12 relative to its area); every face planar
//   (1e-12 of the domain's diagonal); every interior face listed by its two
//   cells, every boundary face by one;
// - every boundary face lies on the plane of the half-space its boundary id
//   names (each vertex within 1e-12 of the diagonal) with that half-space's
//   outward normal (1e-12), and the boundary faces of each id have the area
//   of the domain's facet on that plane (1e-12 relative): zero, no face, for
//   the redundant half-spaces (of the two x <= 1, the first takes the faces);
// - one cell is the domain itself (4 faces and 4 vertices for the
//   tetrahedron, 7 and 7 for the cut cube); 2, 3 and 4 cells (CGAL's lower
//   dimensional Delaunay triangulations) pass the same checks;
// - the hexagonal prism moved by 1e3 times its diagonal gives the same cells
//   (each cell's volume to 1e-9 of the mean cell volume, each vertex moved
//   by the shift to 1e-9 of the diagonal) and passes the same checks;
// - Lloyd's iteration does not increase the CVT energy
//   E = sum_c int_c |x - g_c|^2 dx on the tetrahedron (0..8 iterations, 100
//   cells; 1e-12 relative), and E falls by more than 10 %;
// - the same seed gives the same mesh, another seed another one; a nearly
//   degenerate diagram (8 cells of the unit cube after 100 iterations, near
//   the 2 x 2 x 2 cubes) is the same at the start of the program and after
//   all the other meshes (it had depended on the calls made before);
// - convex_hull_half_spaces() of the truncated octahedron's vertices: 14
//   unit normals, 6 along the axes with b = 2 and 8 along (+-1, +-1, +-1)
//   with b = sqrt(3) (1e-14);
// - the VEM patch test on Voronoi meshes of the tetrahedron and the
//   truncated octahedron (dealvem::PolyhedralElasticity, UMFPACK): a linear
//   displacement prescribed on all boundary ids, and prescribed on some
//   facets with the exact tractions sigma n on the others, is reproduced at
//   every vertex (1e-10 of the largest displacement), errors() gives
//   L2 and H1 errors of round-off (1e-10 relative);
// - bad input throws, naming the problem: no half-space, more than 255, a
//   zero normal, a NaN in a normal, an infinite offset, an empty domain, an
//   unbounded one (naming the direction), a flat one, 0 cells; points in a
//   plane for convex_hull_half_spaces().
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dealvem/app/polyhedral_elasticity.h>
#include <dealvem/mesh/polyhedral_generators.h>
#include <dealvem/mesh/polyhedral_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <string>
#include <vector>

#include "../polyhedral_common.h"
#include "../tests.h"

using namespace dealvem;
using P3         = dealii::Point<3>;
using T3         = dealii::Tensor<1, 3>;
using HalfSpaces = std::vector<std::pair<T3, double>>;

namespace
{
  using testing::cell_moments;
  using testing::CellMoments;
  using testing::cvt_energy;
  using testing::outward_loop;

  // A convex domain, its volume and the area of its facet on the plane of
  // each half-space (0 for a redundant one).
  struct Domain
  {
    std::string         name;
    HalfSpaces          half_spaces;
    double              volume;
    std::vector<double> facet_area;
  };

  Domain
  tetrahedron()
  {
    // legs a = 2, b = 1, c = 1.5 along the axes: x/a + y/b + z/c <= 1
    const double a = 2, b = 1, c = 1.5;
    return {"tetrahedron",
            {{T3({-1, 0, 0}), 0}, {T3({0, -1, 0}), 0}, {T3({0, 0, -1}), 0}, {T3({1 / a, 1 / b, 1 / c}), 1}},
            a * b * c / 6,
            {b * c / 2, a * c / 2, a * b / 2, 0.5 * std::sqrt(a * a * b * b + b * b * c * c + c * c * a * a)}};
  }

  Domain
  hexagonal_prism()
  {
    // circumradius 1 (side 1, apothem sqrt(3)/2), height 0.8
    const double h = 0.8, apothem = std::sqrt(3.) / 2;
    Domain       d{"hexagonal prism", {}, 3 * std::sqrt(3.) / 2 * h, {}};
    for (unsigned int k = 0; k < 6; ++k)
      {
        const double angle = M_PI / 6 + k * M_PI / 3;
        d.half_spaces.push_back({3. * T3({std::cos(angle), std::sin(angle), 0}), 3 * apothem});
        d.facet_area.push_back(h);
      }
    d.half_spaces.push_back({T3({0, 0, -2}), 0});
    d.half_spaces.push_back({T3({0, 0, 1}), h});
    d.facet_area.push_back(3 * std::sqrt(3.) / 2);
    d.facet_area.push_back(3 * std::sqrt(3.) / 2);
    return d;
  }

  std::vector<P3>
  truncated_octahedron_vertices()
  {
    std::vector<P3>    points;
    const unsigned int permutation[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto &p : permutation)
      for (const double s : {-1., 1.})
        for (const double t : {-2., 2.})
          {
            const double c[3] = {0, s, t};
            points.emplace_back(c[p[0]], c[p[1]], c[p[2]]);
          }
    return points;
  }

  Domain
  truncated_octahedron()
  {
    Domain d{"truncated octahedron",
             PolyhedralMeshGenerators::convex_hull_half_spaces(truncated_octahedron_vertices()),
             32,
             {}};
    // a square (normal along an axis, side sqrt(2)) or a regular hexagon
    for (const auto &h : d.half_spaces)
      d.facet_area.push_back(std::abs(std::abs(h.first[0]) + std::abs(h.first[1]) + std::abs(h.first[2]) - 1) < 1e-12
                               ? 2.
                               : 3 * std::sqrt(3.));
    return d;
  }

  Domain
  cut_cube()
  {
    const double cut_area = std::sqrt(3.) / 2; // the cut: an equilateral triangle of side sqrt(2)
    return {"cube cut by x + y + z <= 2, three redundant half-spaces",
            {{T3({-1, 0, 0}), 0},
             {T3({1, 0, 0}), 1},
             {T3({0, -1, 0}), 0},
             {T3({0, 1, 0}), 1},
             {T3({0, 0, -1}), 0},
             {T3({0, 0, 1}), 1},
             {T3({1, 1, 1}), 2},
             {T3({5, 0, 0}), 25},
             {T3({2, 0, 0}), 2},
             {T3({-1, -1, -1}), 0}},
            5. / 6,
            {1, 0.5, 1, 0.5, 1, 0.5, cut_area, 0, 0, 0}};
  }

  PolyhedralMesh
  voronoi(const HalfSpaces  &half_spaces,
          const unsigned int n_cells,
          const unsigned int iterations,
          const unsigned int seed)
  {
    PolyhedralMesh mesh;
    PolyhedralMeshGenerators::voronoi_convex(mesh, half_spaces, n_cells, iterations, seed);
    return mesh;
  }

  // The diagonal of the bounding box of the mesh's vertices.
  double
  diagonal(const PolyhedralMesh &mesh)
  {
    P3 lo = mesh.vertex(0), hi = mesh.vertex(0);
    for (const P3 &p : mesh.get_vertices())
      for (unsigned int d = 0; d < 3; ++d)
        {
          lo[d] = std::min(lo[d], p[d]);
          hi[d] = std::max(hi[d], p[d]);
        }
    return lo.distance(hi);
  }

  // The checks of a mesh of @p domain with @p n_cells cells.
  void
  check_domain_mesh(const PolyhedralMesh &mesh,
                    const Domain         &domain,
                    const unsigned int    n_cells,
                    const std::string    &what)
  {
    const double diag = diagonal(mesh);
    std::cout << what << ": " << mesh.n_cells() << " cells, " << mesh.n_faces() << " faces, " << mesh.n_vertices()
              << " vertices" << std::endl;
    testing::check(mesh.n_cells() == n_cells, what + ": " + std::to_string(n_cells) + " cells");

    double                    total = 0, min_volume = 1e300, worst_closure = 0;
    unsigned int              bad_listing = 0;
    std::vector<unsigned int> listed(mesh.n_faces(), 0);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const CellMoments m = cell_moments(mesh, c);
        total += m.volume;
        min_volume    = std::min({min_volume, m.volume, mesh.cell_volume(c)});
        worst_closure = std::max(worst_closure, m.area_vector.norm() / m.area);
        for (const unsigned int f : mesh.cell(c).faces)
          {
            ++listed[f];
            const auto &cells = mesh.face(f).cells;
            if (cells[0] != c && !(!mesh.face(f).at_boundary() && cells[1] == c))
              ++bad_listing;
          }
      }
    testing::check(min_volume > 0, what + ": every cell has a positive volume (smallest " +
                                     std::to_string(min_volume / domain.volume) + " of the domain)");
    testing::check_small((total - domain.volume) / domain.volume, 1e-12, what + ": the volumes sum to the domain's");
    testing::check_small(worst_closure, 1e-12, what + ": every cell is closed (sum of area vectors / area)");

    double worst_warp = 0;
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      {
        const auto g = mesh.face_geometry(f);
        for (const unsigned int v : mesh.face(f).vertices)
          worst_warp = std::max(worst_warp, std::abs(g.normal * (mesh.vertex(v) - g.centroid)));
      }
    testing::check_small(worst_warp / diag, 1e-12,
                         what + ": every face is planar (largest distance of a vertex from its face's plane / "
                                "diagonal)");

    const unsigned int  n_planes   = domain.half_spaces.size();
    unsigned int        n_interior = 0, n_boundary = 0, bad_count = 0, bad_id = 0, inward = 0;
    double              worst_distance = 0, worst_normal = 0;
    std::vector<double> area(n_planes, 0.);
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      {
        const auto &face = mesh.face(f);
        if (!face.at_boundary())
          {
            ++n_interior;
            if (listed[f] != 2 || face.cells[0] == face.cells[1])
              ++bad_count;
            continue;
          }
        ++n_boundary;
        if (listed[f] != 1)
          ++bad_count;
        if (face.boundary_id >= n_planes)
          {
            ++bad_id;
            continue;
          }
        const T3     n = domain.half_spaces[face.boundary_id].first / domain.half_spaces[face.boundary_id].first.norm();
        const double b =
          domain.half_spaces[face.boundary_id].second / domain.half_spaces[face.boundary_id].first.norm();
        for (const unsigned int v : face.vertices)
          worst_distance = std::max(worst_distance, std::abs(n * mesh.vertex(v) - b));
        // (the area vector: the normal of a small face far from the origin
        // carries the round-off of the coordinates divided by its size)
        const auto g = mesh.face_geometry(f);
        worst_normal = std::max(worst_normal, g.area * (g.normal - n).norm() / (diag * diag));
        inward += (g.normal * n < 0.5);
        area[face.boundary_id] += g.area;
      }
    testing::check(bad_count == 0 && bad_listing == 0,
                   what + ": each of the " + std::to_string(n_interior) +
                     " interior faces is listed by exactly its two cells, each of the " + std::to_string(n_boundary) +
                     " boundary faces by its cell");
    testing::check(bad_id == 0, what + ": every boundary face has the id of one of the " + std::to_string(n_planes) +
                                  " half-spaces");
    testing::check_small(worst_distance / diag, 1e-12,
                         what + ": every boundary face lies on the plane of its id (largest distance / diagonal)");
    testing::check(inward == 0, what + ": every boundary face points out of the domain");
    testing::check_small(worst_normal, 1e-12,
                         what + ": every boundary face's area vector is its area times its half-space's unit normal "
                                "(largest difference / diagonal^2)");
    double worst_area = 0;
    for (unsigned int i = 0; i < n_planes; ++i)
      worst_area = std::max(worst_area, std::abs(area[i] - domain.facet_area[i]) /
                                          *std::max_element(domain.facet_area.begin(), domain.facet_area.end()));
    testing::check_small(worst_area, 1e-12,
                         what + ": the boundary faces of each id have the area of the domain's facet on its plane "
                                "(relative to the largest facet; zero for a redundant half-space)");
  }

  // The linear field u = a + B x, its strain's stress and the patch tests.
  void
  patch_test(const PolyhedralMesh            &mesh,
             const std::vector<unsigned int> &held_ids,
             const std::vector<unsigned int> &traction_ids,
             const std::string               &what)
  {
    const double         size = diagonal(mesh);
    T3                   a({1e-3 * size, -2e-3 * size, 0.5e-3 * size});
    dealii::Tensor<2, 3> B;
    const double         entries[3][3] = {{1.0, -0.4, 0.3}, {0.2, -0.7, 0.6}, {-0.5, 0.9, 0.8}};
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        B[i][j] = 1e-3 * entries[i][j];
    const auto u = [a, B](const P3 &x) { return T3(a + B * x); };

    PolyhedralElasticity::Settings settings;
    settings.material                 = IsotropicMaterial3D{2.1e5, 0.3};
    const double               lambda = settings.material.lambda(), mu = settings.material.mu();
    const dealii::Tensor<2, 3> strain = 0.5 * (B + dealii::transpose(B));
    const dealii::Tensor<2, 3> sigma =
      lambda * dealii::trace(strain) * dealii::unit_symmetric_tensor<3>() + 2 * mu * strain;

    PolyhedralElasticity problem(mesh, settings);
    for (const unsigned int id : held_ids)
      problem.add_dirichlet(id, u);
    for (const unsigned int id : traction_ids)
      problem.add_traction(id, [sigma](const P3 &, const T3 &n) { return sigma * n; });
    problem.solve();

    double error = 0, scale = 0;
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      {
        const T3 exact = u(mesh.vertex(v));
        scale          = std::max(scale, exact.norm());
        for (unsigned int d = 0; d < 3; ++d)
          error = std::max(error, std::abs(problem.solution()[3 * v + d] - exact[d]));
      }
    const auto e = problem.errors(u, [B](const P3 &) { return B; });
    testing::check_small(error / scale, 1e-10, what + ": largest nodal error / largest displacement");
    testing::check_small(e.l2 / e.l2_exact, 1e-10, what + ": relative L2 error of Pi u_h");
    testing::check_small(e.h1_semi / e.h1_semi_exact, 1e-10, what + ": relative H1 error of Pi u_h");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const Domain     tet = tetrahedron(), prism = hexagonal_prism(), cut = cut_cube();
  const HalfSpaces unit_cube(cut.half_spaces.begin(), cut.half_spaces.begin() + 6);
  const auto       first_degenerate = voronoi(unit_cube, 8, 100, 1).get_vertices();

  // convex_hull_half_spaces() of the truncated octahedron
  const Domain octahedron = truncated_octahedron();
  {
    unsigned int squares = 0, hexagons = 0;
    double       worst = 0;
    for (const auto &[n, b] : octahedron.half_spaces)
      {
        worst           = std::max(worst, std::abs(n.norm() - 1));
        const double l1 = std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]);
        if (std::abs(l1 - 1) < 1e-14)
          {
            ++squares;
            worst = std::max(worst, std::abs(b - 2));
          }
        else
          {
            ++hexagons;
            worst = std::max({worst, std::abs(l1 - std::sqrt(3.)), std::abs(b - std::sqrt(3.))});
          }
      }
    testing::check(octahedron.half_spaces.size() == 14 && squares == 6 && hexagons == 8,
                   "convex_hull_half_spaces: the truncated octahedron has 6 square and 8 hexagonal facets (" +
                     std::to_string(octahedron.half_spaces.size()) + " facets)");
    testing::check_small(worst, 1e-14,
                         "convex_hull_half_spaces: unit normals (1, 0, 0), (1, 1, 1)/sqrt(3) and their "
                         "images, offsets 2 and sqrt(3)");
  }

  check_domain_mesh(voronoi(tet.half_spaces, 200, 20, 1), tet, 200, "tetrahedron, 200 cells");
  check_domain_mesh(voronoi(prism.half_spaces, 300, 20, 2), prism, 300, "hexagonal prism, 300 cells");
  check_domain_mesh(voronoi(octahedron.half_spaces, 250, 20, 3), octahedron, 250, "truncated octahedron, 250 cells");
  check_domain_mesh(voronoi(cut.half_spaces, 250, 20, 4), cut, 250, "cut cube, 250 cells");
  {
    // a redundant half-space 1e-9 outside a face, listed before it: the
    // vertices go onto the face's plane, not onto the nearer-listed one
    Domain near_face{"unit cube, x <= 1 + 1e-9 first", {{T3({1, 0, 0}), 1 + 1e-9}}, 1, {0}};
    near_face.half_spaces.insert(near_face.half_spaces.end(), unit_cube.begin(), unit_cube.end());
    near_face.facet_area.insert(near_face.facet_area.end(), 6, 1.);
    check_domain_mesh(voronoi(near_face.half_spaces, 100, 20, 12), near_face, 100,
                      "unit cube with a redundant x <= 1 + 1e-9 first, 100 cells");
  }
  for (const unsigned int n : {2u, 3u, 4u})
    check_domain_mesh(voronoi(tet.half_spaces, n, 20, 5), tet, n, "tetrahedron, " + std::to_string(n) + " cells");

  // one cell: the domain
  {
    const PolyhedralMesh mesh = voronoi(tet.half_spaces, 1, 20, 0);
    check_domain_mesh(mesh, tet, 1, "tetrahedron, one cell");
    testing::check(mesh.n_faces() == 4 && mesh.n_vertices() == 4, "one cell of the tetrahedron: 4 faces, 4 vertices");
  }
  {
    const PolyhedralMesh mesh = voronoi(cut.half_spaces, 1, 20, 0);
    check_domain_mesh(mesh, cut, 1, "cut cube, one cell");
    testing::check(mesh.n_faces() == 7 && mesh.n_vertices() == 7, "one cell of the cut cube: 7 faces, 7 vertices");
  }

  // far from the origin: the same cells, translated
  {
    const unsigned int   n     = 150;
    const PolyhedralMesh near  = voronoi(prism.half_spaces, n, 20, 6);
    const double         diag  = diagonal(near);
    const T3             shift = 1e3 * diag * T3({0.6, -0.64, 0.48});
    Domain               moved = prism;
    for (auto &h : moved.half_spaces)
      h.second += h.first * shift;
    const PolyhedralMesh far = voronoi(moved.half_spaces, n, 20, 6);
    check_domain_mesh(far, moved, n, "hexagonal prism moved by 1e3 diagonals, " + std::to_string(n) + " cells");
    double worst_volume = 0, worst_vertex = 0;
    bool   same_counts = far.n_vertices() == near.n_vertices() && far.n_faces() == near.n_faces();
    for (unsigned int c = 0; c < n; ++c)
      worst_volume = std::max(worst_volume, std::abs(cell_moments(far, c).volume - cell_moments(near, c).volume));
    // (the vertices may come in another order: a face loop may start at
    // another vertex where round-off turns an angle by 2 pi)
    for (unsigned int v = 0; same_counts && v < near.n_vertices(); ++v)
      {
        double nearest = std::numeric_limits<double>::max();
        for (unsigned int w = 0; w < far.n_vertices(); ++w)
          nearest = std::min(nearest, (far.vertex(w) - shift - near.vertex(v)).norm());
        worst_vertex = std::max(worst_vertex, nearest);
      }
    testing::check(same_counts, "moved: as many vertices and faces as near the origin (" +
                                  std::to_string(far.n_vertices()) + ", " + std::to_string(near.n_vertices()) + ")");
    testing::check_small(worst_volume / (prism.volume / n), 1e-9,
                         "moved: every cell's volume as near the origin (largest difference / mean cell volume)");
    testing::check_small(worst_vertex / diag, 1e-9,
                         "moved: every vertex moved by the shift (largest distance to the nearest moved vertex / "
                         "diagonal)");
  }

  // Lloyd's iteration does not increase the CVT energy
  {
    std::vector<double> energy;
    bool                monotone = true;
    for (unsigned int k = 0; k <= 8; ++k)
      {
        energy.push_back(cvt_energy(voronoi(tet.half_spaces, 100, k, 7)));
        std::cout << "  " << k << " Lloyd iterations: E = " << std::setprecision(12) << energy.back() << std::endl;
        if (k > 0 && energy[k] > energy[k - 1] * (1 + 1e-12))
          monotone = false;
      }
    testing::check(monotone, "Lloyd's iteration does not increase the CVT energy (tetrahedron, 100 cells, 0..8 "
                             "iterations)");
    testing::check(energy.back() < 0.9 * energy.front(),
                   "the CVT energy falls by more than 10 % from the random Voronoi mesh in 8 iterations");
  }

  // reproducible by seed
  {
    const auto vertices = [&](const unsigned int seed) {
      return voronoi(prism.half_spaces, 40, 5, seed).get_vertices();
    };
    testing::check(vertices(8) == vertices(8), "the same seed gives the same mesh");
    testing::check(vertices(8) != vertices(9), "different seeds give different meshes");
  }

  // the patch test: the tetrahedron held on its three legs' faces and
  // loaded on the oblique one; the truncated octahedron held on its squares
  // and loaded on its hexagons; both held everywhere
  {
    const PolyhedralMesh mesh = voronoi(tet.half_spaces, 80, 20, 10);
    patch_test(mesh, {0, 1, 2, 3}, {}, "patch test, tetrahedron, 80 cells, displacements on the whole boundary");
    patch_test(mesh, {0, 1, 2}, {3}, "patch test, tetrahedron, 80 cells, tractions on the oblique face");
  }
  {
    const PolyhedralMesh      mesh = voronoi(octahedron.half_spaces, 80, 20, 11);
    std::vector<unsigned int> squares, hexagons, all;
    for (unsigned int i = 0; i < octahedron.half_spaces.size(); ++i)
      {
        (octahedron.facet_area[i] == 2. ? squares : hexagons).push_back(i);
        all.push_back(i);
      }
    patch_test(mesh, all, {}, "patch test, truncated octahedron, 80 cells, displacements on the whole boundary");
    patch_test(mesh, squares, hexagons, "patch test, truncated octahedron, 80 cells, tractions on the hexagons");
  }

  testing::check(voronoi(unit_cube, 8, 100, 1).get_vertices() == first_degenerate,
                 "a nearly degenerate diagram (8 cells, 100 iterations) is the same after the other meshes as at the "
                 "start");

  // bad input
  {
    PolyhedralMesh   mesh;
    const HalfSpaces cube = {{T3({-1, 0, 0}), 0}, {T3({1, 0, 0}), 1},  {T3({0, -1, 0}), 0},
                             {T3({0, 1, 0}), 1},  {T3({0, 0, -1}), 0}, {T3({0, 0, 1}), 1}};
    auto             with = [&](const T3 &n, const double b) {
      HalfSpaces h = cube;
      h.emplace_back(n, b);
      return h;
    };
    auto convex = [&](const HalfSpaces &h, const unsigned int n_cells = 10) {
      return [&mesh, h, n_cells] { PolyhedralMeshGenerators::voronoi_convex(mesh, h, n_cells); };
    };
    testing::check_throws(convex({}), "voronoi_convex: the list of half-spaces is empty",
                          "voronoi_convex refuses an empty list of half-spaces");
    HalfSpaces many = cube;
    for (unsigned int i = 0; i < 250; ++i)
      many.emplace_back(T3({1, 1, 1}), 3. + i);
    testing::check_throws(convex(many), "voronoi_convex: 256 half-spaces; at most 255 are accepted",
                          "voronoi_convex refuses 256 half-spaces");
    many.pop_back();
    PolyhedralMeshGenerators::voronoi_convex(mesh, many, 5);
    testing::check(mesh.n_cells() == 5, "voronoi_convex accepts 255 half-spaces (249 of them redundant)");
    testing::check_throws(convex(with(T3(), 1)), "voronoi_convex: half-space 6 has a zero normal",
                          "voronoi_convex refuses a zero normal");
    testing::check_throws(convex(with(T3({1, std::numeric_limits<double>::quiet_NaN(), 0}), 1)),
                          "voronoi_convex: half-space 6 has a normal or an offset that is not a finite number",
                          "voronoi_convex refuses a NaN in a normal");
    testing::check_throws(convex(with(T3({1, 1, 0}), std::numeric_limits<double>::infinity())),
                          "voronoi_convex: half-space 6 has a normal or an offset that is not a finite number",
                          "voronoi_convex refuses an infinite offset");
    testing::check_throws(convex(with(T3({1, 1, 1}), -0.5)),
                          "voronoi_convex: the domain is empty: no point satisfies all 7 half-spaces",
                          "voronoi_convex refuses an empty domain");
    testing::check_throws(convex({{T3({-1, 0, 0}), 0}, {T3({0, -1, 0}), 0}, {T3({0, 0, -1}), 0}, {T3({1, 1, 0}), 1}}),
                          "voronoi_convex: the domain is unbounded: it extends without end towards +z",
                          "voronoi_convex refuses an unbounded domain, naming the direction");
    testing::check_throws(convex(with(T3({-1, 0, 0}), -1)),
                          "voronoi_convex: the domain has no interior or is too thin: its largest inscribed ball "
                          "has the radius 0",
                          "voronoi_convex refuses a flat domain");
    testing::check_throws(convex(cube, 0), "voronoi_convex: at least one cell is needed",
                          "voronoi_convex refuses 0 cells");
    testing::check_throws(
      [] {
        PolyhedralMeshGenerators::convex_hull_half_spaces({P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(2, 3, 0)});
      },
      "convex_hull_half_spaces: the points lie in a plane", "convex_hull_half_spaces refuses points in a plane");
  }

  return testing::finish();
}
