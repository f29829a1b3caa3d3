// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The mesh module:
// - every generator on [0,2]x[0,1]: total area 2 (1e-12), positive cell
//   areas, Euler's formula V - E + F = 1, boundary ids 0..3 with the side
//   lengths 1, 1, 2, 2 (1e-12); Voronoi meshes are reproducible by seed and
//   convex; the non-convex family has reflex vertices;
// - hanging vertices of an adaptively refined deal.II mesh become extra
//   vertices of the coarse neighbours (pentagons), boundary ids survive;
// - a gmsh file with physical groups: boundary ids 1..4, material id 7;
// - material ids are bodies: deal.II's plate_with_a_hole(colorize = true)
//   gives the cells material ids 0..3, so its conversion throws (bodies
//   that share an edge); with the material ids reset to 0 it converts to
//   one body with the boundary ids 0..4 of the colorization;
// - the VTK polygon format: a hand-written file and a write/read round
//   trip with identical vertices, cells and ids;
// - masonry_wall(): 25 blocks in courses of 10 (10, 11, 4 pieces): 26
//   bodies, the area of the base and of the blocks (1e-12), the
//   quads per block (n or n + 1 along, halved on half blocks), the blocks'
//   boundary ids shifted by the offset; bad parameters throw, naming them;
// - bad meshes and bad files give messages naming the cell or file:line.
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/masonry_wall.h>
#include <dealvem/mesh/mesh_io.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>

#include "../tests.h"

using namespace dealvem;
using P = dealii::Point<2>;

void
check_rectangle_mesh(const PolygonalMesh<2> &mesh, const std::string &tag)
{
  testing::check_near(mesh.total_area(), 2.0, 1e-12 * 2, tag + ": total area");
  double amin = 1e300;
  for (unsigned int c = 0; c < mesh.n_cells(); ++c)
    {
      const auto  v = mesh.cell_vertices(c);
      double      a = 0;
      for (unsigned int i = 0; i < v.size(); ++i)
        a += 0.5 * (v[i][0] * v[(i + 1) % v.size()][1] - v[(i + 1) % v.size()][0] * v[i][1]);
      amin = std::min(amin, a);
    }
  testing::check(amin > 0, tag + ": every cell counter-clockwise with positive area");
  testing::check(int(mesh.n_vertices()) - int(mesh.n_edges()) + int(mesh.n_cells()) == 1,
                 tag + ": Euler V - E + F = 1");
  std::map<unsigned int, double> length;
  for (const auto &e : mesh.get_edges())
    if (e.at_boundary())
      length[e.boundary_id] += mesh.vertex(e.vertices[0]).distance(mesh.vertex(e.vertices[1]));
  testing::check(mesh.get_boundary_ids() == std::vector<dealii::types::boundary_id>{0, 1, 2, 3},
                 tag + ": boundary ids 0..3");
  const double expected[4] = {1, 1, 2, 2};
  double       err         = 0;
  for (unsigned int b = 0; b < 4; ++b)
    err = std::max(err, std::abs(length[b] - expected[b]));
  testing::check_small(err, 1e-12, tag + ": side lengths per boundary id");
}

bool
is_convex(const std::vector<P> &v)
{
  for (unsigned int i = 0; i < v.size(); ++i)
    {
      const P &a = v[i], &b = v[(i + 1) % v.size()], &c = v[(i + 2) % v.size()];
      if ((b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]) < -1e-12)
        return false;
    }
  return true;
}

int
main()
{
  namespace G = PolygonalMeshGenerators;
  const P p0(0, 0), p1(2, 1);
  for (const unsigned int n : {2u, 6u})
    {
      const std::string s = " (" + std::to_string(n) + ")";
      PolygonalMesh<2>  m;
      G::structured_quads(m, p0, p1, 2 * n, n);
      check_rectangle_mesh(m, "structured quads" + s);
      G::structured_triangles(m, p0, p1, 2 * n, n);
      check_rectangle_mesh(m, "structured triangles" + s);
      G::perturbed_quads(m, p0, p1, 2 * n, n, 0.3, 4);
      check_rectangle_mesh(m, "perturbed quads" + s);
      G::nonconvex(m, p0, p1, 2 * n, n, 0.3);
      check_rectangle_mesh(m, "nonconvex" + s);
      bool reflex = false;
      for (unsigned int c = 0; c < m.n_cells(); ++c)
        reflex = reflex || !is_convex(m.cell_vertices(c));
      testing::check(reflex, "nonconvex" + s + ": has non-convex cells");
      G::voronoi(m, p0, p1, 10 * n * n, 10, 7);
      check_rectangle_mesh(m, "voronoi" + s);
      testing::check(m.n_cells() == 10 * n * n, "voronoi" + s + ": number of cells");
      bool convex = true;
      for (unsigned int c = 0; c < m.n_cells(); ++c)
        convex = convex && is_convex(m.cell_vertices(c));
      testing::check(convex, "voronoi" + s + ": cells convex");
      PolygonalMesh<2> m2;
      G::voronoi(m2, p0, p1, 10 * n * n, 10, 7);
      testing::check(m2.get_vertices() == m.get_vertices(), "voronoi" + s + ": same seed, same mesh");
      G::voronoi(m2, p0, p1, 10 * n * n, 10, 8);
      testing::check(m2.get_vertices() != m.get_vertices(), "voronoi" + s + ": other seed, other mesh");
      {
        // far from the origin: the same mesh, translated (the same cells
        // and vertex order; the coordinates to the rounding of the shift)
        const dealii::Tensor<1, 2> shift({1000., -500.});
        G::voronoi(m2, p0 + shift, p1 + shift, 10 * n * n, 10, 7);
        bool   same_cells = m2.n_cells() == m.n_cells() && m2.n_vertices() == m.n_vertices();
        double err        = 0;
        for (unsigned int c = 0; same_cells && c < m.n_cells(); ++c)
          same_cells = m2.cell(c).vertices == m.cell(c).vertices;
        for (unsigned int v = 0; same_cells && v < m.n_vertices(); ++v)
          err = std::max(err, (m2.vertex(v) - shift).distance(m.vertex(v)));
        testing::check(same_cells, "voronoi" + s + ", shifted by (1000, -500): the same cells");
        testing::check_small(err, 1e-12, "voronoi" + s + ", shifted by (1000, -500): the vertices, translated");
      }
      dealii::Triangulation<2> tria;
      dealii::GridGenerator::subdivided_hyper_rectangle(tria, {2 * n, n}, p0, p1, true);
      G::from_triangulation(m, tria);
      check_rectangle_mesh(m, "from_triangulation" + s);
    }

  // hanging vertices
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::hyper_cube(tria, 0, 1, true);
    tria.refine_global(1);
    tria.begin_active()->set_refine_flag();
    tria.execute_coarsening_and_refinement();
    PolygonalMesh<2> m;
    G::from_triangulation(m, tria);
    unsigned int n_pentagons = 0;
    for (const auto &c : m.get_cells())
      n_pentagons += (c.vertices.size() == 5);
    testing::check(m.n_cells() == 7 && n_pentagons == 2, "hanging vertices: 7 cells, 2 pentagons");
    testing::check(int(m.n_vertices()) - int(m.n_edges()) + int(m.n_cells()) == 1, "hanging vertices: Euler");
    testing::check_near(m.total_area(), 1., 1e-14, "hanging vertices: area");
    double left = 0;
    for (const auto &e : m.get_edges())
      if (e.at_boundary() && e.boundary_id == 0)
        left += m.vertex(e.vertices[0]).distance(m.vertex(e.vertices[1]));
    testing::check_near(left, 1., 1e-14, "hanging vertices: left side keeps boundary id 0");
  }

  // a colorized deal.II mesh: material ids 0..3 are four bodies
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::plate_with_a_hole(tria, 0.4, 1., 1., 1., 1., 1., dealii::Point<2>(), 0, 1, 1., 2, true);
    PolygonalMesh<2> m;
    testing::check_throws([&] { G::from_triangulation(m, tria); }, "of different bodies (material ids) share an edge",
                          "plate_with_a_hole(colorize = true): the material ids 0..3 are bodies that share edges");
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
    PolygonalMesh<2> one;
    G::from_triangulation(one, tria);
    testing::check(one.get_material_ids() == std::vector<dealii::types::material_id>{0} && one.n_cells() == 20,
                   "plate_with_a_hole with the material ids reset: one body of 20 cells");
    testing::check(one.get_boundary_ids() == std::vector<dealii::types::boundary_id>{0, 1, 2, 3, 4},
                   "plate_with_a_hole with the material ids reset: boundary ids 0..4 kept");
  }

  // gmsh
  {
    PolygonalMesh<2> m;
    G::from_gridin_file(m, testing::source_dir() + "/tests/mesh/data/rectangle.msh");
    testing::check(m.get_boundary_ids() == std::vector<dealii::types::boundary_id>{1, 2, 3, 4},
                   "gmsh: boundary ids 1..4 from the physical lines");
    testing::check(m.get_material_ids() == std::vector<dealii::types::material_id>{7},
                   "gmsh: material id 7 from the physical surface");
    testing::check(m.n_cells() == 2, "gmsh: 2 cells");
    testing::check_near(m.total_area(), 2., 1e-14, "gmsh: area");
    testing::check_throws([] {
      PolygonalMesh<2> x;
      G::from_gridin_file(x, "no-such-file.msh");
    }, "no-such-file.msh", "gmsh: a missing file is named");
  }

  // VTK polygon files
  {
    PolygonalMesh<2> m;
    MeshIO::read_vtk(m, testing::source_dir() + "/tests/mesh/data/two_cells.vtk");
    testing::check(m.n_cells() == 2 && m.n_vertices() == 6 && m.n_edges() == 7, "two_cells.vtk: counts");
    testing::check(m.get_material_ids() == std::vector<dealii::types::material_id>{4}, "two_cells.vtk: material id");
    testing::check(m.get_boundary_ids() == std::vector<dealii::types::boundary_id>{0, 5, 6},
                   "two_cells.vtk: boundary ids");
    testing::check_near(m.total_area(), 0.5 + 1.25, 1e-14, "two_cells.vtk: area");
    for (const std::string family : {"voronoi", "nonconvex"})
      {
        PolygonalMesh<2> a, b;
        if (family == "voronoi")
          G::voronoi(a, p0, p1, 40, 5, 2);
        else
          G::nonconvex(a, p0, p1, 4, 3, 0.25);
        for (unsigned int c = 0; c < a.n_cells(); c += 2)
          a.set_material_id(c, 3);
        // materials must not split edges between bodies: use one id for all
        for (unsigned int c = 0; c < a.n_cells(); ++c)
          a.set_material_id(c, 3);
        MeshIO::write_vtk(a, family + ".vtk");
        MeshIO::read_vtk(b, family + ".vtk");
        bool same = a.get_vertices() == b.get_vertices() && a.n_cells() == b.n_cells();
        for (unsigned int c = 0; same && c < a.n_cells(); ++c)
          same = a.cell(c).vertices == b.cell(c).vertices && a.cell(c).material_id == b.cell(c).material_id;
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> ids;
        for (const auto &e : a.get_edges())
          if (e.at_boundary())
            ids[{std::min(e.vertices[0], e.vertices[1]), std::max(e.vertices[0], e.vertices[1])}] = e.boundary_id;
        for (const auto &e : b.get_edges())
          if (e.at_boundary())
            same = same && ids[{std::min(e.vertices[0], e.vertices[1]), std::max(e.vertices[0], e.vertices[1])}] ==
                             e.boundary_id;
        testing::check(same, family + ": VTK write/read round trip is exact");
      }
  }

  // a dry-stone wall: courses of 10 in running bond, 25 pieces (10 full
  // blocks; 2 half and 9 full; 4 full), 3 or 4 quads along a full block
  {
    G::MasonryWall layout;
    layout.n_blocks    = 25;
    layout.quads_along = 3;
    PolygonalMesh<2> wall;
    G::masonry_wall(wall, layout);
    testing::check(wall.get_material_ids().size() == 26, "masonry wall: the base and 25 blocks are bodies");
    // the base [-1, 11] x [-1, 0] and block lengths 10 + 10 + 4 of height 0.5
    testing::check_near(wall.total_area(), 12. + 0.5 * 24, 1e-12 * 24, "masonry wall: area");
    std::map<unsigned int, unsigned int> cells_of;
    for (unsigned int c = 0; c < wall.n_cells(); ++c)
      ++cells_of[wall.cell(c).material_id];
    // base 48 x 4; block j: (3 or 4) x 1 quads, a half block (ids 11 and
    // 21; 4 quads along) 2 x 2
    bool counts = cells_of[0] == 48 * 4;
    for (unsigned int j = 1; j <= 25; ++j)
      {
        const unsigned int along = (j % 2 == 0 ? 3 : 4), across = along / 2;
        const bool         half  = (j == 11 || j == 21);
        counts = counts && cells_of[j] == (half ? (along + 1) / 2 : along) * across;
      }
    testing::check(counts, "masonry wall: quads per block (n or n + 1 along, half on half blocks)");
    std::set<unsigned int> ids;
    for (unsigned int e = 0; e < wall.n_edges(); ++e)
      if (wall.edge(e).at_boundary())
        ids.insert(wall.edge(e).boundary_id);
    testing::check(ids == std::set<unsigned int>{0, 1, 2, 3, 10, 11, 12, 13}, "masonry wall: boundary ids 0..3 and 10..13");
    G::MasonryWall bad = layout;
    bad.blocks_per_course = 0;
    testing::check_throws([&] { G::masonry_wall(wall, bad); }, "number of blocks per course", "masonry wall: no block per course");
    bad = layout;
    bad.block_height = -0.5;
    testing::check_throws([&] { G::masonry_wall(wall, bad); }, "block height", "masonry wall: negative height");
    bad = layout;
    bad.block_boundary_offset = 2;
    testing::check_throws([&] { G::masonry_wall(wall, bad); }, "block boundary offset", "masonry wall: ids overlapping the base's");
  }

  // bad meshes
  auto build = [](const std::vector<P> &v, const std::vector<std::vector<unsigned int>> &cells) {
    PolygonalMesh<2> m;
    m.name = "bad";
    for (const auto &p : v)
      m.add_vertex(p);
    for (const auto &c : cells)
      m.add_cell(c);
    m.finalize();
  };
  const std::vector<P> sq = {P(0, 0), P(1, 0), P(1, 1), P(0, 1)};
  testing::check_throws([&] { build(sq, {{0, 3, 2, 1}}); }, "clockwise", "clockwise cell");
  testing::check_throws([&] { build(sq, {{0, 2, 1, 3}}); }, "self-intersecting", "bowtie");
  testing::check_throws([&] { build({P(0, 0), P(1, 0), P(2, 0)}, {{0, 1, 2}}); }, "zero area", "collinear triangle");
  testing::check_throws([&] { build(sq, {{0, 1, 2, 1}}); }, "repeated vertex", "repeated vertex in a loop");
  testing::check_throws([&] { build({P(0, 0), P(1, 0), P(std::numeric_limits<double>::quiet_NaN(), 1)}, {{0, 1, 2}}); },
                        "non-finite", "NaN coordinate");
  testing::check_throws([&] { build({P(0, 0), P(1, 0), P(0.5, 1), P(0.5, -1), P(0.5, 2)}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}); },
                        "more than two", "an edge of three cells");
  testing::check_throws([&] { build({P(0, 0), P(2, 0), P(2, 2), P(0, 2), P(1, -1), P(3, 1), P(1, 3)}, {{0, 1, 2, 3}, {4, 5, 6}}); },
                        "overlapping", "overlapping cells");
  testing::check_throws([&] { build({P(0, 0), P(4, 0), P(4, 4), P(0, 4), P(1, 1), P(2, 1), P(1, 2)}, {{0, 1, 2, 3}, {4, 5, 6}}); },
                        "overlapping", "a cell inside another");
  testing::check_throws([&] { build(sq, {{0, 1}}); }, "at least 3", "a cell with two vertices");

  // bad files: the message names file and line
  auto write = [](const std::string &name, const std::string &text) { std::ofstream(name) << text; };
  const std::string head = "# vtk DataFile Version 3.0\ntest\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  write("missing_points.vtk", head + "CELLS 1 4\n3 0 1 2\n");
  testing::check_throws([] { PolygonalMesh<2> m; MeshIO::read_vtk(m, "missing_points.vtk"); },
                        "missing_points.vtk:5: expected POINTS", "VTK without POINTS");
  write("truncated.vtk", head + "POINTS 3 double\n0 0 0\n1 0 0\n0 1 0\nCELLS 1 4\n3 0 1\n");
  testing::check_throws([] { PolygonalMesh<2> m; MeshIO::read_vtk(m, "truncated.vtk"); },
                        "truncated.vtk:10: unexpected end", "VTK with a truncated cell list");
  write("bad_type.vtk", head + "POINTS 3 double\n0 0 0\n1 0 0\n0 1 0\nCELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n42\n");
  testing::check_throws([] { PolygonalMesh<2> m; MeshIO::read_vtk(m, "bad_type.vtk"); },
                        "bad_type.vtk:12", "VTK with an unknown cell type");
  write("binary.vtk", "# vtk DataFile Version 3.0\ntest\nBINARY\n");
  testing::check_throws([] { PolygonalMesh<2> m; MeshIO::read_vtk(m, "binary.vtk"); }, "binary.vtk:3",
                        "binary VTK file");
  write("clockwise.vtk", head + "POINTS 3 double\n0 0 0\n1 0 0\n0 1 0\nCELLS 1 4\n3 0 2 1\nCELL_TYPES 1\n7\n");
  testing::check_throws([] { PolygonalMesh<2> m; MeshIO::read_vtk(m, "clockwise.vtk"); },
                        "clockwise.vtk:10: cell 0 is clockwise", "clockwise polygon in a file");
  return testing::finish();
}
