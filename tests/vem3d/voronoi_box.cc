// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The polyhedral mesh generators of a box (PolyhedralMeshGenerators),
// checked against numbers fixed by the geometry, with the cell volumes,
// centroids and second moments computed here from the face loops (the
// tetrahedra from a point to the fans of the faces), not by the mesh:
// - voronoi_box() on the unit cube (200 cells) and on the non-cubic box
//   [0,2]x[-1,0]x[0,0.5] (150 cells): as many cells as asked for, each of
//   positive volume (here and by PolyhedralMesh::cell_volume()), the volumes
//   summing to the box's (1e-12 relative), every cell closed (the sum of
//   its faces' outward area vectors vanishes, 1e-12 relative), every face
//   planar (to 1e-12 of the box's diagonal), every interior face listed by exactly its two cells and every boundary
//   face by one, every boundary face lying on the side of the box named by its boundary id (0..5 as deal.II's colorize)
//   with the side's outward normal, the areas of the boundary faces summing to each side's area and to the box's
//   surface area (1e-12 relative);
// - 2, 3 and 4 cells (generators on a line, in a plane: CGAL's lower
//   dimensional triangulations) and a box far from the origin pass the same
//   checks;
// - so do nearly degenerate diagrams: Lloyd's iteration run long on few
//   cells approaches a symmetric configuration (8 cells, 100 iterations:
//   near the 2x2x2 cubes, whose vertices two cells compute 1e-7 apart and
//   whose faces the merged vertices warp by 1e-9; 6 cells, 300 iterations:
//   faces of diameter 1e-9 the generator must merge away);
// - one cell is the box itself: 8 vertices, 6 boundary faces with the ids
//   0..5, the box's volume;
// - Lloyd's iteration does not increase the CVT energy
//   E = sum_c int_c |x - g_c|^2 dx (g_c the centroid of cell c): the meshes
//   after 0, 1, ..., 8 iterations (100 cells) have non-increasing E (to
//   1e-12 relative), and E falls by more than 10 % from the random
//   Voronoi mesh to the eighth iteration;
// - the same seed gives the same mesh, different seeds different meshes;
// - hyper_rectangle() 2x3x4 on the non-cubic box: 24 hexahedra of equal
//   volume, 60 vertices, 98 faces, the same boundary checks;
// - bad arguments throw, naming the generator.
// The Voronoi generator needs CGAL: the calls go through the helper
// voronoi(...) below (tests/CMakeLists.txt disables the test without CGAL).
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dealvem/mesh/polyhedral_generators.h>
#include <dealvem/mesh/polyhedral_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "../polyhedral_common.h"
#include "../tests.h"

using namespace dealvem;
using P3 = dealii::Point<3>;
using T3 = dealii::Tensor<1, 3>;

namespace
{
  using testing::cell_moments;
  using testing::CellMoments;
  using testing::cvt_energy;
  using testing::outward_loop;

  PolyhedralMesh
  voronoi(const P3          &lower,
          const P3          &upper,
          const unsigned int n_cells,
          const unsigned int lloyd_iterations,
          const unsigned int seed)
  {
    PolyhedralMesh mesh;
    PolyhedralMeshGenerators::voronoi_box(mesh, lower, upper, n_cells, lloyd_iterations, seed);
    return mesh;
  }


  // The checks of a mesh of the box [lower, upper] with n_cells cells.
  void
  check_box_mesh(const PolyhedralMesh &mesh,
                 const P3             &lower,
                 const P3             &upper,
                 const unsigned int    n_cells,
                 const std::string    &what)
  {
    const T3     L          = upper - lower;
    const double box_volume = L[0] * L[1] * L[2];
    const double diag       = L.norm();
    std::cout << what << ": " << mesh.n_cells() << " cells, " << mesh.n_faces() << " faces, " << mesh.n_vertices()
              << " vertices" << std::endl;
    testing::check(mesh.n_cells() == n_cells, what + ": " + std::to_string(n_cells) + " cells");

    double                    total = 0, min_volume = 1e300, min_mesh_volume = 1e300, worst_closure = 0;
    unsigned int              bad_listing = 0;
    std::vector<unsigned int> listed(mesh.n_faces(), 0);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const CellMoments m = cell_moments(mesh, c);
        total += m.volume;
        min_volume      = std::min(min_volume, m.volume);
        min_mesh_volume = std::min(min_mesh_volume, mesh.cell_volume(c));
        worst_closure   = std::max(worst_closure, m.area_vector.norm() / m.area);
        for (const unsigned int f : mesh.cell(c).faces)
          {
            ++listed[f];
            const auto &cells = mesh.face(f).cells;
            if (cells[0] != c && !(!mesh.face(f).at_boundary() && cells[1] == c))
              ++bad_listing;
          }
      }
    testing::check(min_volume > 0 && min_mesh_volume > 0, what + ": every cell has a positive volume (smallest " +
                                                            std::to_string(min_volume / box_volume) + " of the box)");
    testing::check_small((total - box_volume) / box_volume, 1e-12, what + ": the volumes sum to the box's");
    testing::check_small((mesh.total_volume() - box_volume) / box_volume, 1e-12,
                         what + ": PolyhedralMesh::total_volume() is the box's");
    testing::check_small(worst_closure, 1e-12, what + ": every cell is closed (sum of area vectors / area)");

    double worst_warp = 0;
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      {
        const auto g = mesh.face_geometry(f);
        for (const unsigned int v : mesh.face(f).vertices)
          worst_warp = std::max(worst_warp, std::abs(g.normal * (mesh.vertex(v) - g.centroid)));
      }
    testing::check_small(worst_warp / diag, 1e-12,
                         what + ": every face is planar (largest distance of a vertex from "
                                "its face's plane / box diagonal)");

    unsigned int          n_interior = 0, n_boundary = 0, bad_count = 0, bad_side = 0;
    std::array<double, 6> side_area{};
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
        const unsigned int s = face.boundary_id;
        if (s > 5)
          {
            ++bad_side;
            continue;
          }
        const unsigned int d     = s / 2;
        const double       plane = (s % 2 == 0 ? lower[d] : upper[d]);
        for (const unsigned int v : face.vertices)
          if (std::abs(mesh.vertex(v)[d] - plane) > 1e-12 * diag)
            ++bad_side;
        const auto g = mesh.face_geometry(f);
        if (std::abs(g.normal[d] - (s % 2 == 0 ? -1. : 1.)) > 1e-12)
          ++bad_side;
        side_area[s] += g.area;
      }
    testing::check(bad_count == 0 && bad_listing == 0,
                   what + ": each of the " + std::to_string(n_interior) +
                     " interior faces is listed by exactly its two cells, each of the " + std::to_string(n_boundary) +
                     " boundary faces by its cell");
    testing::check(bad_side == 0, what + ": every boundary face lies on the side of its boundary id (0..5), "
                                         "normal pointing out");
    double surface = 0, worst_side = 0;
    for (unsigned int s = 0; s < 6; ++s)
      {
        const unsigned int d          = s / 2;
        const double       exact_side = box_volume / L[d];
        surface += side_area[s];
        worst_side = std::max(worst_side, std::abs(side_area[s] - exact_side) / exact_side);
      }
    const double exact_surface = 2 * (L[0] * L[1] + L[1] * L[2] + L[2] * L[0]);
    testing::check_small(worst_side, 1e-12, what + ": the boundary faces of each side sum to its area");
    testing::check_small((surface - exact_surface) / exact_surface, 1e-12,
                         what + ": the boundary faces sum to the box's surface area");
  }

  // The sorted vertex coordinates: equal for equal meshes.
  std::vector<std::array<double, 3>>
  sorted_vertices(const PolyhedralMesh &mesh)
  {
    std::vector<std::array<double, 3>> v;
    for (const auto &p : mesh.get_vertices())
      v.push_back({{p[0], p[1], p[2]}});
    std::sort(v.begin(), v.end());
    return v;
  }
} // namespace

int
main()
{
  const P3 o(0, 0, 0), one(1, 1, 1);

  {
    const PolyhedralMesh mesh = voronoi(o, one, 200, 20, 0);
    check_box_mesh(mesh, o, one, 200, "unit cube, 200 cells");
  }
  {
    const P3             lower(0, -1, 0), upper(2, 0, 0.5);
    const PolyhedralMesh mesh = voronoi(lower, upper, 150, 20, 3);
    check_box_mesh(mesh, lower, upper, 150, "[0,2]x[-1,0]x[0,0.5], 150 cells");
  }
  for (const unsigned int n : {2u, 3u, 4u})
    {
      const PolyhedralMesh mesh = voronoi(o, one, n, 20, 1);
      check_box_mesh(mesh, o, one, n, "unit cube, " + std::to_string(n) + " cells");
    }
  for (const auto &[n, iterations, seed] :
       std::vector<std::array<unsigned int, 3>>{{{8, 100, 1}}, {{6, 300, 2}}, {{6, 300, 3}}})
    {
      const PolyhedralMesh mesh = voronoi(o, one, n, iterations, seed);
      check_box_mesh(mesh, o, one, n,
                     "unit cube, " + std::to_string(n) + " cells, " + std::to_string(iterations) +
                       " iterations, seed " + std::to_string(seed));
    }
  {
    const P3             lower(1000, -2000, 3000), upper(1001, -1999, 3002);
    const PolyhedralMesh mesh = voronoi(lower, upper, 60, 10, 2);
    check_box_mesh(mesh, lower, upper, 60, "box far from the origin, 60 cells");
  }

  // one cell: the box
  {
    const P3             lower(0, -1, 0), upper(2, 0, 0.5);
    const PolyhedralMesh mesh = voronoi(lower, upper, 1, 20, 0);
    check_box_mesh(mesh, lower, upper, 1, "one cell");
    std::vector<unsigned int> ids;
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      ids.push_back(mesh.face(f).boundary_id);
    std::sort(ids.begin(), ids.end());
    testing::check(mesh.n_vertices() == 8 && mesh.n_faces() == 6 &&
                     ids == std::vector<unsigned int>({0, 1, 2, 3, 4, 5}),
                   "one cell is the box: 8 vertices, 6 faces with the boundary ids 0..5");
    testing::check_near(mesh.cell_volume(0), 1., 1e-14, "one cell: its volume is the box's");
  }

  // Lloyd's iteration does not increase the CVT energy
  {
    std::vector<double> energy;
    bool                monotone = true;
    for (unsigned int k = 0; k <= 8; ++k)
      {
        energy.push_back(cvt_energy(voronoi(o, one, 100, k, 5)));
        std::cout << "  " << k << " Lloyd iterations: E = " << std::setprecision(12) << energy.back() << std::endl;
        if (k > 0 && energy[k] > energy[k - 1] * (1 + 1e-12))
          monotone = false;
      }
    testing::check(monotone, "Lloyd's iteration does not increase the CVT energy (100 cells, 0..8 iterations)");
    testing::check(energy.back() < 0.9 * energy.front(),
                   "the CVT energy falls by more than 10 % from the random Voronoi mesh in 8 iterations");
  }

  // reproducible by seed, different for different seeds
  {
    const auto a = sorted_vertices(voronoi(o, one, 50, 5, 7));
    const auto b = sorted_vertices(voronoi(o, one, 50, 5, 7));
    const auto c = sorted_vertices(voronoi(o, one, 50, 5, 8));
    testing::check(a == b, "the same seed gives the same mesh");
    testing::check(a != c, "different seeds give different meshes");
  }

  // the structured hexahedra
  {
    const P3       lower(0, -1, 0), upper(2, 0, 0.5);
    PolyhedralMesh mesh;
    PolyhedralMeshGenerators::hyper_rectangle(mesh, lower, upper, {{2, 3, 4}});
    check_box_mesh(mesh, lower, upper, 24, "hyper_rectangle 2x3x4");
    double worst = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      worst = std::max(worst, std::abs(mesh.cell_volume(c) - 1. / 24) * 24);
    testing::check(mesh.n_vertices() == 60 && mesh.n_faces() == 98, "hyper_rectangle 2x3x4: 60 vertices, 98 faces (" +
                                                                      std::to_string(mesh.n_vertices()) + ", " +
                                                                      std::to_string(mesh.n_faces()) + ")");
    testing::check_small(worst, 1e-14, "hyper_rectangle 2x3x4: every cell has the volume 1/24");
  }

  // bad arguments
  {
    PolyhedralMesh mesh;
    testing::check_throws([&] { PolyhedralMeshGenerators::voronoi_box(mesh, o, one, 0); },
                          "voronoi_box: at least one cell is needed", "voronoi_box refuses 0 cells");
    testing::check_throws([&] { PolyhedralMeshGenerators::voronoi_box(mesh, one, o, 10); },
                          "voronoi_box: the upper corner of the box must lie above the lower corner",
                          "voronoi_box refuses an inverted box");
    testing::check_throws(
      [&] {
        PolyhedralMeshGenerators::hyper_rectangle(mesh, o, one, {{1, 0, 1}});
      },
      "hyper_rectangle: the numbers of subdivisions must be at least 1", "hyper_rectangle refuses 0 subdivisions");
  }

  return testing::finish();
}
