// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Bad polyhedral meshes and bad 3D problems get a clear error naming the
// cell, face or parameter (ExcInvalidPolyhedralMesh, or ExcMessage), never a
// wrong answer: a cell given with inward faces, one face turned, a missing
// face, a warped face, a face crossing itself, a face of three cells, a
// shared face oriented the same way twice, two cells that touch without
// sharing their faces, a vertex out of range, a face of two vertices, a
// coordinate that is not a number, a distorted hexahedron from deal.II
// (non-planar faces); a body held against translations only, a second body
// that no support reaches, a boundary id no face has, Poisson's ratio 0.5.
// And the good cases around them pass: the unit cube's volume, area and
// boundary ids; a cube beside two prisms that share its face's diagonal,
// once the cube's face is split the same way; two cubes that meet along an
// edge only.
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <dealvem/app/polyhedral_elasticity.h>
#include <dealvem/mesh/polyhedral_mesh.h>

#include <cmath>
#include <limits>

#include "../tests.h"

using namespace dealvem;
using P     = dealii::Point<3>;
using Loops = std::vector<std::vector<unsigned int>>;

namespace
{
  // the unit cube's eight vertices, shifted by x0 along x; returns the
  // index of the first
  unsigned int
  add_cube_vertices(PolyhedralMesh &mesh, const double x0 = 0)
  {
    const unsigned int first = mesh.n_vertices();
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int j = 0; j < 2; ++j)
        for (unsigned int i = 0; i < 2; ++i)
          mesh.add_vertex(P(x0 + i, j, k));
    return first;
  }

  // the outward faces of the cube whose vertices start at v
  Loops
  cube_faces(const unsigned int v)
  {
    return {{v + 0, v + 4, v + 6, v + 2}, {v + 1, v + 3, v + 7, v + 5}, {v + 0, v + 1, v + 5, v + 4},
            {v + 2, v + 6, v + 7, v + 3}, {v + 0, v + 2, v + 3, v + 1}, {v + 4, v + 5, v + 7, v + 6}};
  }

  Loops
  reversed(Loops loops)
  {
    for (auto &l : loops)
      std::reverse(l.begin(), l.end());
    return loops;
  }

  void
  expect_invalid(const std::function<void(PolyhedralMesh &)> &build, const std::string &fragment,
                 const std::string &what)
  {
    testing::check_throws(
      [&] {
        PolyhedralMesh mesh;
        mesh.name = "test mesh";
        build(mesh);
        mesh.finalize();
      },
      fragment, what);
  }
} // namespace

int
main()
{
  // the good cube
  {
    PolyhedralMesh mesh;
    mesh.add_cell(cube_faces(add_cube_vertices(mesh)));
    mesh.finalize();
    testing::check_near(mesh.total_volume(), 1, 1e-15, "unit cube: volume");
    double area = 0;
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      area += mesh.face_geometry(f).area;
    testing::check_near(area, 6, 1e-15, "unit cube: surface area");
    testing::check(mesh.set_boundary_ids([](const P &x, const dealii::Tensor<1, 3> &) { return x[2] > 0.9; }, 5) == 1,
                   "unit cube: one face selected by its centroid");
    testing::check(mesh.get_boundary_ids() == std::vector<dealii::types::boundary_id>({0, 5}),
                   "unit cube: boundary ids 0 and 5");
  }

  expect_invalid([](PolyhedralMesh &m) { m.add_cell(reversed(cube_faces(add_cube_vertices(m)))); },
                 "cell 0 has a negative volume", "a cube given with inward faces");
  expect_invalid(
    [](PolyhedralMesh &m) {
      auto f = cube_faces(add_cube_vertices(m));
      std::reverse(f[3].begin(), f[3].end());
      m.add_cell(f);
    },
    "cell 0 is not a closed, consistently oriented surface", "a cube with one face turned inward");
  expect_invalid(
    [](PolyhedralMesh &m) {
      auto f = cube_faces(add_cube_vertices(m));
      f.pop_back();
      m.add_cell(f);
    },
    "cell 0 is not a closed, consistently oriented surface", "a cube without its top face");
  expect_invalid(
    [](PolyhedralMesh &m) {
      const unsigned int v = add_cube_vertices(m);
      m.move_vertex(v + 7, P(1, 1, 1.01));
      m.add_cell(cube_faces(v));
    },
    "is not planar", "a cube with a corner lifted by 1 % (warped faces)");
  expect_invalid(
    [](PolyhedralMesh &m) {
      const unsigned int v = add_cube_vertices(m);
      auto               f = cube_faces(v);
      f[5]                 = {v + 4, v + 5, v + 6, v + 7}; // a symmetric bow tie
      m.add_cell(f);
    },
    "has zero area", "a face whose loop crosses itself into two equal halves");
  expect_invalid(
    [](PolyhedralMesh &m) {
      // an unequal bow tie (0,0) (2,0) (0,1) (1,1), net area 1/2
      const unsigned int a = m.add_vertex(P(0, 0, 1)), b = m.add_vertex(P(2, 0, 1)), c = m.add_vertex(P(0, 1, 1)),
                         d = m.add_vertex(P(1, 1, 1)), e = m.add_vertex(P(0, 0, 0));
      m.add_cell({{a, b, c, d}, {a, e, b}, {b, e, c}, {c, e, d}, {d, e, a}});
    },
    "crosses itself", "a face whose loop crosses itself");
  expect_invalid(
    [](PolyhedralMesh &m) {
      const unsigned int v = add_cube_vertices(m), w = add_cube_vertices(m, 1);
      // the second cube uses the first one's right face with the same
      // orientation instead of the opposite one
      auto g = cube_faces(w);
      g[0]   = {v + 1, v + 3, v + 7, v + 5};
      m.add_cell(cube_faces(v));
      m.add_cell(g);
    },
    "with the same orientation", "two cells orienting their common face the same way");
  expect_invalid(
    [](PolyhedralMesh &m) {
      const unsigned int v = add_cube_vertices(m);
      m.add_cell(cube_faces(v));
      m.add_cell(reversed(cube_faces(v)));
      m.add_cell(cube_faces(v));
    },
    "a face is shared by at most two cells", "a face of three cells");
  // a cube beside two prisms that split their common square along its
  // diagonal, while the cube keeps the square whole: the cells touch
  // without sharing faces
  const auto cube_and_prisms = [](PolyhedralMesh &m, const bool split_cube_face) {
    const unsigned int v = add_cube_vertices(m), w = add_cube_vertices(m, 1);
    auto               f = cube_faces(v);
    if (split_cube_face)
      {
        // the right face (x = 1) split along the diagonal (1,0,0)-(1,1,1)
        f[1] = {v + 1, v + 3, v + 7};
        f.push_back({v + 1, v + 7, v + 5});
      }
    m.add_cell(f);
    // the right cube [1,2]x[0,1]^2 cut by the plane y = z into two prisms;
    // each loop turned to point away from a point inside its prism
    const auto outward = [&m](std::vector<unsigned int> loop, const P &inside) {
      const auto a = m.vertex(loop[0]), b = m.vertex(loop[1]), c = m.vertex(loop[2]);
      if (dealii::cross_product_3d(b - a, c - a) * (a - inside) < 0)
        std::reverse(loop.begin(), loop.end());
      return loop;
    };
    // the left face's vertices are the cube's (shared), the right ones new
    const unsigned int a = v + 1, b = w + 1, c = v + 3, d = w + 3, e = v + 5, g = w + 5, h = v + 7, i = w + 7;
    const P            in1(1.5, 0.7, 0.3), in2(1.5, 0.3, 0.7);
    m.add_cell({outward({a, c, h}, in1), outward({b, d, i}, in1), outward({a, b, d, c}, in1),
                outward({c, d, i, h}, in1), outward({a, b, i, h}, in1)});
    m.add_cell({outward({a, h, e}, in2), outward({b, i, g}, in2), outward({a, b, g, e}, in2),
                outward({e, g, i, h}, in2), outward({a, h, i, b}, in2)});
  };
  expect_invalid([&](PolyhedralMesh &m) { cube_and_prisms(m, false); }, "lie on each other",
                 "a cube beside two prisms that split the common square (not conforming)");
  {
    PolyhedralMesh mesh;
    cube_and_prisms(mesh, true);
    mesh.finalize();
    unsigned int n_interior = 0;
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      n_interior += !mesh.face(f).at_boundary();
    testing::check(mesh.n_cells() == 3 && std::abs(mesh.total_volume() - 2) < 1e-14 && n_interior == 3,
                   "the same with the cube's square split the same way: valid, volume 2, three interior faces");
  }
  {
    // two cubes that meet along one edge only: coplanar faces with opposite
    // normals on the two sides of that edge, allowed
    PolyhedralMesh     mesh;
    const unsigned int v = add_cube_vertices(mesh);
    unsigned int       w[8];
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int j = 0; j < 2; ++j)
        for (unsigned int i = 0; i < 2; ++i)
          w[i + 2 * j + 4 * k] = (i == 0 && j == 0) ? v + 3 + 4 * k : mesh.add_vertex(P(1 + i, 1 + j, k));
    mesh.add_cell(cube_faces(v));
    Loops b = cube_faces(0);
    for (auto &loop : b)
      for (auto &x : loop)
        x = w[x];
    mesh.add_cell(b);
    mesh.finalize();
    testing::check(mesh.n_vertices() == 14 && std::abs(mesh.total_volume() - 2) < 1e-14,
                   "two cubes meeting along an edge only: valid, 14 vertices, volume 2");
  }
  testing::check_throws(
    [] {
      PolyhedralMesh m;
      add_cube_vertices(m);
      m.add_cell({{0, 1, 2}, {0, 1, 9}, {1, 2, 3}, {0, 2, 3}});
    },
    "uses vertex 9, but the mesh has 8 vertices", "a vertex index out of range");
  expect_invalid(
    [](PolyhedralMesh &m) {
      const unsigned int v = add_cube_vertices(m);
      m.add_cell({{v, v + 1}, {v, v + 1, v + 2}, {v + 1, v + 2, v + 3}, {v, v + 2, v + 3}});
    },
    "has 2 vertices; a face needs at least three", "a face of two vertices");
  expect_invalid(
    [](PolyhedralMesh &m) {
      const unsigned int v = add_cube_vertices(m);
      m.move_vertex(v + 3, P(1, std::numeric_limits<double>::quiet_NaN(), 0));
      m.add_cell(cube_faces(v));
    },
    "vertex 3 has a coordinate that is not a finite number", "a NaN coordinate");
  testing::check_throws(
    [] {
      dealii::Triangulation<3> tria;
      dealii::GridGenerator::subdivided_hyper_cube(tria, 2);
      dealii::GridTools::distort_random(0.2, tria, false, 7);
      PolyhedralMesh::from_triangulation(tria);
    },
    "is not planar", "a distorted hexahedral Triangulation (warped faces)");

  // bad problems
  {
    PolyhedralMesh mesh;
    mesh.add_cell(cube_faces(add_cube_vertices(mesh)));
    mesh.finalize();
    mesh.set_boundary_ids([](const P &x, const dealii::Tensor<1, 3> &) { return x[2] < 0.1; }, 1);
    PolyhedralElasticity::Settings settings;
    testing::check_throws(
      [&] {
        PolyhedralElasticity problem(mesh, settings);
        // the bottom held vertically only: free to slide and to turn about z
        problem.add_dirichlet(1, [](const P &) { return dealii::Tensor<1, 3>(); }, {{false, false, true}});
        problem.solve();
      },
      "do not hold the body against all six rigid motions", "a body free to slide");
    testing::check_throws(
      [&] {
        PolyhedralElasticity problem(mesh, settings);
        problem.add_dirichlet(7, [](const P &) { return dealii::Tensor<1, 3>(); });
        problem.solve();
      },
      "has the boundary id 7", "a boundary id that no face has");
    {
      // a second cube beside the first, not touching it: supporting the
      // first leaves the second free (UMFPACK had returned displacements of
      // 1e16 for it)
      PolyhedralMesh two;
      two.add_cell(cube_faces(add_cube_vertices(two)));
      two.add_cell(cube_faces(add_cube_vertices(two, 2)));
      two.finalize();
      two.set_boundary_ids([](const P &x, const dealii::Tensor<1, 3> &) { return x[2] < 0.1 && x[0] < 1.5; }, 1);
      testing::check_throws(
        [&] {
          PolyhedralElasticity problem(two, settings);
          problem.add_dirichlet(1, [](const P &) { return dealii::Tensor<1, 3>(); });
          problem.solve();
        },
        "do not hold the piece of cell 1 (8 vertices; the mesh has 2 pieces)", "a second body without support");
    }
    settings.material.poisson_ratio = 0.5;
    testing::check_throws([&] { PolyhedralElasticity problem(mesh, settings); }, "Poisson's ratio must lie in (-1, 0.5)",
                          "Poisson's ratio 0.5");
  }
  return testing::finish();
}
