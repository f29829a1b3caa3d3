// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Flat punch: an elastic square [-b,b]x[0,b], b = 10, 1000 times stiffer
// than the block [-100,100]x[-100,0] (E = 210000, nu = 0.3, plane strain)
// below it, pressed down through its top, a rigid boundary part loaded by
// (0, -P); frictionless unilateral contact, the block's bottom fixed. Both
// meshes are deal.II quadrilaterals refined toward the interface (edges
// 0.25 on the block, 0.3125 on the punch: non-matching) and read through
// 'vtk file'. For k = 1 and k = 2:
// - every pair under the punch is closed, no open-end warning;
// - the recovered pressure is within 2 % of the half-space solution
//   P / (pi sqrt(b^2 - x^2)) at |x| <= b/2 (measured 0.5-0.7 %; the corners
//   are singular and are not checked);
// - the total contact force equals P to 1e-7 relative (the stiffness ratio
//   1000 costs about three digits of round-off against the Hertz test).
// The mesh code is a copy of the one in examples/step-3.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/mesh_io.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>

#include "../contact_common.h"
#include "../graded_meshes.h"
#include "../tests.h"

namespace
{
  constexpr double E_block = 210000., b = 10., P = 10000.;
  constexpr double h_target = 0.25, x_strip = 12.;

  // block: ids 0 left, 1 right, 2 bottom, 3 top
  void
  write_block(const std::string &file)
  {
    testing::write_graded_block(file, h_target, x_strip);
  }


  // punch: ids 0 left, 1 right, 2 bottom, 3 top (10..13 after the offset)
  void
  write_punch(const std::string &file)
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {4u, 2u}, dealii::Point<2>(-b, 0),
                                                      dealii::Point<2>(b, b), true);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
    testing::refine_toward(tria, h_target, [](const dealii::Point<2> &p) { return std::abs(p[1]); });
    dealvem::PolygonalMesh<2> mesh;
    dealvem::PolygonalMeshGenerators::from_triangulation(mesh, tria);
    dealvem::MeshIO::write_vtk(mesh, file);
  }

  std::string
  punch_prm(const unsigned int k)
  {
    std::ostringstream p;
    p << "set Number of bodies = 2\n"
      << "subsection Mesh\n  set Type = vtk file\n  set File name = block.vtk\nend\n"
      << "subsection Material\n  set Model = plane strain\n  set Young's modulus = " << E_block
      << "\n  set Poisson's ratio = 0.3\nend\n"
      << "subsection Body 1\n  subsection Mesh\n    set Type = vtk file\n    set File name = punch.vtk\n"
      << "    set Boundary id offset = 10\n  end\n  subsection Material\n    set Young's modulus = "
      << 1000. * E_block << "\n    set Poisson's ratio = 0.3\n  end\nend\n"
      << "subsection Discretization\n  set Order = " << k << "\nend\n"
      << "subsection Contact\n  set Pairs = 3 : 12\n  set Normal = unilateral\n"
      << "  set Tangential = frictionless\nend\n"
      << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : xy : 0, 0\n"
      << "  set Rigid boundary = 13 : 0, " << -P << "\n  set Point constraints = 0, 10 : x : 0 : 1\nend\n"
      << "subsection Output\n  set Write VTU = false\n  set Write JSON = false\n"
      << "  set Write pictures = false\n  set Write CSV = false\nend\n";
    return p.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  write_block("block.vtk");
  write_punch("punch.vtk");
  for (const unsigned int k : {1u, 2u})
    {
      const std::string tag = "k=" + std::to_string(k);
      const auto        r   = testing::run_contact(punch_prm(k));
      double            error = 0;
      unsigned int      open_under = 0, n_under = 0;
      for (const auto &pair : r.pairs)
        {
          const double x = pair.location[0];
          if (std::abs(x) <= b * (1 + 1e-12))
            {
              ++n_under;
              if (!pair.active)
                ++open_under;
            }
          if (std::abs(x) <= 0.5 * b)
            error = std::max(error, std::abs(pair.pressure * M_PI * std::sqrt(b * b - x * x) / P - 1.));
        }
      testing::check(n_under > 80 && open_under == 0,
                     tag + ": all " + std::to_string(n_under) + " pairs under the punch closed");
      testing::check(r.n_open_end_warnings == 0, tag + ": no open-end warnings");
      testing::check_small(error, 0.02, tag + ": max |p / p_exact - 1| on |x| <= b/2");
      testing::check_small(r.total_contact_force[1] / P - 1., 1e-7, tag + ": total contact force / P - 1");
    }
  return testing::finish();
}
