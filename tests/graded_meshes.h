// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Meshes refined toward a contact zone, shared by the Hertz and punch tests:
// deal.II quadrilaterals refined locally, converted to polygons and written
// as VTK polygon files (read back by the program through 'vtk file').
#ifndef dealvem_tests_graded_meshes_h
#define dealvem_tests_graded_meshes_h

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/mesh_io.h>

#include <functional>
#include <string>

namespace testing
{
  /// Refine cells longer than 1.3 @p h whose centre is within two cell sizes
  /// of the contact zone (@p distance to it), until none is left.
  inline void
  refine_toward(dealii::Triangulation<2>                                  &tria,
                const double                                               h,
                const std::function<double(const dealii::Point<2> &)> &distance)
  {
    dealvem::PolygonalMeshGenerators::refine_toward(tria, distance, h, 2.);
  }

  /// The block [-100,100]x[-100,0] (ids 0 left, 1 right, 2 bottom, 3 top),
  /// refined to @p h along the top for |x| <= @p x_strip, written to @p file.
  inline void
  write_graded_block(const std::string &file, const double h, const double x_strip)
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {25u, 12u}, dealii::Point<2>(-100, -100),
                                                      dealii::Point<2>(100, 0), true);
    // colorize also numbers the cells: one body has one material id
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
    refine_toward(tria, h, [x_strip](const dealii::Point<2> &p) {
      const double dx = std::max(std::abs(p[0]) - x_strip, 0.);
      return std::sqrt(dx * dx + p[1] * p[1]);
    });
    dealvem::PolygonalMesh<2> mesh;
    dealvem::PolygonalMeshGenerators::from_triangulation(mesh, tria);
    dealvem::MeshIO::write_vtk(mesh, file);
  }
} // namespace testing

#endif
