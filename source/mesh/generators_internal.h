// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// What the rectangle generators of generators.cc and the Voronoi generator
// of voronoi_generator.cc share, private to the library.
#ifndef dealvem_mesh_generators_internal_h
#define dealvem_mesh_generators_internal_h

#include <deal.II/base/point.h>

#include <dealvem/mesh/polygonal_mesh.h>

#include <string>

namespace dealvem
{
  namespace PolygonalMeshGenerators
  {
    namespace internal
    {
      // Throws unless @p p1 lies above and right of @p p0 and @p nx, @p ny
      // are at least 1; @p what names the generator in the message.
      void
      check_rectangle(const dealii::Point<2> &p0, const dealii::Point<2> &p1, const unsigned int nx,
                      const unsigned int ny, const std::string &what);

      // Finalizes @p mesh and gives boundary ids 0..3 to the boundary edges
      // on the sides x = p0[0], x = p1[0], y = p0[1] and y = p1[1] of the
      // rectangle (0 to a boundary edge on none of them).
      void
      finish_rectangle(PolygonalMesh<2> &mesh, const dealii::Point<2> &p0, const dealii::Point<2> &p1);
    } // namespace internal
  } // namespace PolygonalMeshGenerators
} // namespace dealvem

#endif
