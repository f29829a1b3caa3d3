// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// 3D gmsh files (MSH 2.2, through deal.II's GridIn<3>) as polyhedral meshes:
// - tests/vem3d/data/cube-tetrahedra.msh: the unit cube as 2 x 2 x 2 cubes
//   of six tetrahedra each: 48 cells, volume 1 to 1e-14, the displacement
//   patch test to 1e-10;
// - tests/vem3d/data/box-hexahedra.msh: the box [0,3]x[0,2]x[0,1] as six
//   hexahedra of physical tag 7 with the six bottom quadrilaterals tagged 4:
//   material id 7 on every cell, boundary id 4 on exactly the six faces at
//   z = 0 (0 elsewhere), volume 6;
// - a missing file and a truncated one: errors naming the file.
#include <deal.II/base/mpi.h>

#include <dealvem/app/polyhedral_elasticity.h>
#include <dealvem/mesh/polyhedral_mesh.h>

#include <cmath>
#include <fstream>

#include "../tests.h"

using namespace dealvem;
using P = dealii::Point<3>;
using T = dealii::Tensor<1, 3>;

int
main()
{
  const std::string data = testing::source_dir() + "/tests/vem3d/data/";
  {
    PolyhedralMesh mesh = PolyhedralMesh::read_gmsh(data + "cube-tetrahedra.msh");
    testing::check(mesh.n_cells() == 48 && mesh.n_vertices() == 27, "tetrahedra: 48 cells, 27 vertices");
    testing::check_near(mesh.total_volume(), 1, 1e-14, "tetrahedra: volume");
    // the displacement patch test
    const auto field = [](const P &x) {
      return T({1e-3 + 2e-3 * x[0] - 1e-3 * x[1] + 4e-3 * x[2], -2e-3 + 1e-3 * x[0] + 3e-3 * x[1],
                5e-4 - 3e-3 * x[1] + 1e-3 * x[2]});
    };
    PolyhedralElasticity problem(mesh, PolyhedralElasticity::Settings());
    problem.add_dirichlet(0, field);
    problem.solve();
    double error = 0;
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      for (unsigned int d = 0; d < 3; ++d)
        error = std::max(error, std::abs(problem.solution()[3 * v + d] - field(mesh.vertex(v))[d]));
    testing::check_small(error / 1e-2, 1e-10, "tetrahedra: patch test, largest nodal error relative to 1e-2");
  }
  {
    PolyhedralMesh mesh = PolyhedralMesh::read_gmsh(data + "box-hexahedra.msh");
    testing::check(mesh.n_cells() == 6, "hexahedra: 6 cells");
    testing::check_near(mesh.total_volume(), 6, 1e-14, "hexahedra: volume");
    bool         materials = true;
    unsigned int bottom = 0, wrong = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      materials = materials && mesh.cell(c).material_id == 7;
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      if (mesh.face(f).at_boundary())
        {
          const bool at_bottom = std::abs(mesh.face_geometry(f).centroid[2]) < 1e-12;
          bottom += at_bottom && mesh.face(f).boundary_id == 4;
          wrong += at_bottom != (mesh.face(f).boundary_id == 4);
        }
    testing::check(materials, "hexahedra: material id 7 (the physical tag) on every cell");
    testing::check(bottom == 6 && wrong == 0, "hexahedra: boundary id 4 on the six bottom faces, 0 elsewhere");
  }
  testing::check_throws([&] { PolyhedralMesh::read_gmsh(data + "no-such-file.msh"); },
                        "cannot open the gmsh file " + data + "no-such-file.msh", "a missing file");
  {
    // the tetrahedra file cut in the middle of its node list
    std::ifstream     in(data + "cube-tetrahedra.msh");
    std::ofstream     out("truncated-tetrahedra.msh");
    std::string       line;
    for (unsigned int i = 0; i < 20 && std::getline(in, line); ++i)
      out << line << '\n';
    out.close();
    testing::check_throws([] { PolyhedralMesh::read_gmsh("truncated-tetrahedra.msh"); },
                          "the gmsh file truncated-tetrahedra.msh could not be read", "a truncated file");
  }
  return testing::finish();
}
