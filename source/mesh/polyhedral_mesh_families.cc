// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Families of polyhedral meshes for tests and studies (non-convex cells).
#include <deal.II/base/exceptions.h>

#include <dealvem/mesh/polyhedral_generators.h>
#include <dealvem/mesh/polyhedral_mesh.h>

#include <string>
#include <vector>

namespace dealvem
{
  namespace PolyhedralMeshGenerators
  {
    void
    l_shaped_cells(PolyhedralMesh &mesh, const unsigned int n)
    {
      AssertThrow(n >= 1, dealii::ExcMessage("l_shaped_cells: at least one cube along each side is needed."));
      mesh.clear();
      mesh.name = "L-shaped cells of " + std::to_string(n) + "^3 cubes";
      const auto vertex = [n](unsigned int i, unsigned int j, unsigned int k) {
        return (k * (n + 1) + j) * (n + 1) + i;
      };
      for (unsigned int k = 0; k <= n; ++k)
        for (unsigned int j = 0; j <= n; ++j)
          for (unsigned int i = 0; i <= n; ++i)
            mesh.add_vertex(dealii::Point<3>(i, j, k) / double(n));
      // the cell of each cube
      const auto       cube = [n](unsigned int i, unsigned int j, unsigned int k) { return (k * n + j) * n + i; };
      std::vector<int> owner(n * n * n, -1);
      int              next = 0;
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int j = 0; j + 1 < n; j += 2)
          for (unsigned int i = 0; i + 1 < n; i += 2)
            {
              const unsigned int single = (i / 2 + j / 2 + k) % 4;
              const unsigned int di[4] = {0, 1, 0, 1}, dj[4] = {0, 0, 1, 1};
              for (unsigned int q = 0; q < 4; ++q)
                owner[cube(i + di[q], j + dj[q], k)] = (q == single ? next + 1 : next);
              next += 2;
            }
      for (auto &o : owner)
        if (o < 0)
          o = next++;
      // each cell: the faces of its cubes not shared with a cube of the same
      // cell, oriented outward
      std::vector<std::vector<std::vector<unsigned int>>> cells(next);
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            {
              const int  o    = owner[cube(i, j, k)];
              const auto same = [&](const int a, const int b, const int c) {
                return a >= 0 && b >= 0 && c >= 0 && a < int(n) && b < int(n) && c < int(n) &&
                       owner[cube(a, b, c)] == o;
              };
              const auto v = vertex;
              if (!same(i - 1, j, k))
                cells[o].push_back({v(i, j, k), v(i, j, k + 1), v(i, j + 1, k + 1), v(i, j + 1, k)});
              if (!same(i + 1, j, k))
                cells[o].push_back({v(i + 1, j, k), v(i + 1, j + 1, k), v(i + 1, j + 1, k + 1), v(i + 1, j, k + 1)});
              if (!same(i, j - 1, k))
                cells[o].push_back({v(i, j, k), v(i + 1, j, k), v(i + 1, j, k + 1), v(i, j, k + 1)});
              if (!same(i, j + 1, k))
                cells[o].push_back({v(i, j + 1, k), v(i, j + 1, k + 1), v(i + 1, j + 1, k + 1), v(i + 1, j + 1, k)});
              if (!same(i, j, k - 1))
                cells[o].push_back({v(i, j, k), v(i, j + 1, k), v(i + 1, j + 1, k), v(i + 1, j, k)});
              if (!same(i, j, k + 1))
                cells[o].push_back({v(i, j, k + 1), v(i + 1, j, k + 1), v(i + 1, j + 1, k + 1), v(i, j + 1, k + 1)});
            }
      for (const auto &faces : cells)
        mesh.add_cell(faces);
      mesh.finalize();
      // boundary ids by side, as hyper_rectangle()
      for (unsigned int s = 0; s < 6; ++s)
        mesh.set_boundary_ids(
          [s](const dealii::Point<3> &x, const dealii::Tensor<1, 3> &) {
            const double plane = (s % 2 == 0 ? 0. : 1.);
            return std::abs(x[s / 2] - plane) < 1e-12;
          },
          s);
    }
  } // namespace PolyhedralMeshGenerators
} // namespace dealvem
