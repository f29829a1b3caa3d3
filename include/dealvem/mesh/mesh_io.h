// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_mesh_mesh_io_h
#define dealvem_mesh_mesh_io_h

#include <dealvem/mesh/polygonal_mesh.h>

#include <iosfwd>
#include <string>

namespace dealvem
{
  /**
   * Reading and writing polygonal meshes.
   *
   * The file format is the legacy ASCII VTK format (version 2.0 or later),
   * dataset UNSTRUCTURED_GRID, which ParaView reads:
   * - POINTS with x y z (z ignored, must be 0 up to round-off);
   * - CELLS with VTK_POLYGON (type 7) cells, the polygons, and VTK_LINE
   *   (type 3) cells, boundary edges that carry a boundary id;
   *   VTK_TRIANGLE (5) and VTK_QUAD (9) are also accepted as polygons;
   * - CELL_DATA with an integer SCALARS field "material_id" (value for the
   *   polygons, ignored on lines) and "boundary_id" (value for the lines,
   *   ignored on polygons). Both fields are optional (default 0) for a file
   *   of polygons only; when the file has line cells, the boundary_id field
   *   is required (write_vtk() always writes both), so that a file that lost
   *   its end is not read with every id 0. Boundary ids must be integers
   *   0..254, material ids 0..65535 (PolygonalMeshGenerators::max_material_id).
   * Polygons given clockwise are rejected (not silently reversed): the
   * message names the file, line and cell.
   *
   * The reader trusts nothing in the file: every count is checked against
   * the size of the file before anything is allocated for it, and counts,
   * indices, coordinates (finite, at most 1e100 in magnitude), section
   * lengths and line cells (each must be an edge of a polygon) are checked;
   * every error names the file and line.
   */
  namespace MeshIO
  {
    /// Read a mesh from a legacy VTK file; errors name the file and line.
    template <int dim>
    void
    read_vtk(PolygonalMesh<dim> &mesh, const std::string &filename);

    /// Read from a stream; @p name is used in error messages.
    template <int dim>
    void
    read_vtk(PolygonalMesh<dim> &mesh,
             std::istream       &in,
             const std::string  &name);

    /// Write a mesh to a legacy VTK file (polygons, boundary edges as lines,
    /// material and boundary ids).
    template <int dim>
    void
    write_vtk(const PolygonalMesh<dim> &mesh, const std::string &filename);

    template <int dim>
    void
    write_vtk(const PolygonalMesh<dim> &mesh, std::ostream &out);

    /// The size of a mesh file as its header says, see count_entities().
    struct FileCounts
    {
      /// Points (VTK) or nodes (gmsh) declared in the header.
      unsigned long long n_vertices = 0;
      /// Cells declared (VTK: CELLS, gmsh: $Elements; both include the
      /// boundary line cells); 0 if the count was not found.
      unsigned long long n_cells = 0;
      /// Whether the vertex count was found and is plausible (at most what
      /// the size of the file can hold). If not, the reader will say what
      /// is wrong.
      bool valid = false;
      /// The line of the file with the vertex count.
      std::size_t line = 0;
    };

    /**
     * Read only the counts of a legacy VTK file (@p format "vtk") or a gmsh
     * .msh file (@p format "msh", versions 2.2 and 4.x): the POINTS and
     * CELLS counts or the counts after $Nodes and $Elements. The lines in
     * between are skipped, not parsed, and nothing is stored, so that a
     * program can estimate the size of a run before it reads a large
     * file. Throws only if the file cannot be opened.
     */
    FileCounts
    count_entities(const std::string &filename, const std::string &format);
  } // namespace MeshIO
} // namespace dealvem

#endif
