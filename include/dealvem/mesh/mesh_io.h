// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_mesh_mesh_io_h
#define dealvem_mesh_mesh_io_h

#include <dealvem/mesh/polygonal_mesh.h>

#include <iosfwd>
#include <map>
#include <string>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

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

    /// The same, written to a stream.
    template <int dim>
    void
    write_vtk(const PolygonalMesh<dim> &mesh, std::ostream &out);

    /**
     * The physical names of a gmsh file (\$PhysicalNames): the name of each
     * physical curve (dimension 1), which is a boundary id, and of each
     * physical surface (dimension 2), which is a material id. Names of
     * points and volumes are not kept.
     */
    struct PhysicalNames
    {
      /// Name -> boundary id (physical curves).
      std::map<std::string, dealii::types::boundary_id> boundary_ids;
      /// Name -> material id (physical surfaces).
      std::map<std::string, dealii::types::material_id> material_ids;
      /// Names that cannot be used, with the reason (the parameter program
      /// merges the names of several files: a name that means different
      /// ids in two of them is listed here instead).
      std::map<std::string, std::string> unusable;

      /// All names with their ids, for messages: "boundaries (dimension
      /// 1): 'clamped' = 1, ...; surfaces (dimension 2): ...".
      std::string
      list() const;
    };

    /**
     * Read a gmsh .msh file into @p mesh, without deal.II: formats 2.2 and
     * 4.1, ASCII and binary (file-type 1: the endianness marker must be the
     * integer 1 in the byte order of this machine; MSH 2.2 element blocks
     * with their header type/count/number of tags, MSH 4.1 entity blocks
     * with 8-byte tags), data size 8. Returns the physical names.
     *
     * What the file gives:
     * - every two-dimensional element is a polygon, whatever the mix:
     *   triangles (type 2) and quadrangles (type 3), and their higher-order
     *   variants (types 9, 10, 16, 20-25, 36-61) by their corner nodes (the
     *   first three or four; the other nodes are dropped and the sides are
     *   straight). Cells must be counter-clockwise, as gmsh writes them for
     *   a surface with the normal +z; a clockwise cell is refused, not
     *   reversed, with the file, line and element, like read_vtk();
     * - the physical surface of a cell is its material id (0 to
     *   PolygonalMeshGenerators::max_material_id); a cell without a
     *   physical group (gmsh saves those when the file has no physical
     *   groups at all, or with Mesh.SaveAll) gets material id 0;
     * - a line element (types 1, 8, 26-28, 62-66) on a physical curve gives
     *   its edge the physical tag as boundary id (0 to 254); it must be the
     *   side of exactly one cell. Lines without a physical group and points
     *   (type 15) are skipped;
     * - the other sections (\$Periodic, \$NodeData, ...) are skipped.
     *
     * Nothing in the file is trusted: every count is checked against the
     * size of the file before anything is allocated for it; node tags must
     * be unique and known; coordinates finite and at most 1e100 in
     * magnitude; cells must have area, no side of length zero, no bow tie,
     * must not be given twice; an edge has at most two cells, and two cells
     * of different physical surfaces share no edge unless
     * @p separate_material_ids (then each material id gets vertices of its
     * own, as PolygonalMeshGenerators::from_triangulation() does). Errors
     * name the file and the line (for binary data: the line and the byte)
     * and are thrown with AssertThrow, in Release too.
     *
     * @p n_refinements refines the mesh natively, without deal.II, the way
     * Triangulation::refine_global() would: each triangle into four by its
     * edge midpoints, each quadrangle into four by its edge midpoints and
     * its centre (new vertices on the straight sides: a file carries no
     * manifold); a boundary edge gives its id to both halves.
     */
    template <int dim>
    PhysicalNames
    read_msh(PolygonalMesh<dim> &mesh,
             const std::string  &filename,
             const unsigned int  n_refinements         = 0,
             const bool          separate_material_ids = false);

    /**
     * Write the active cells of a two-dimensional triangulation as a gmsh
     * file of format 2.2 (ASCII), the format read_msh() reads: its used
     * vertices, every active cell as a quadrangle (or triangle) on the
     * physical surface of its material id, and every boundary face with a
     * non-zero boundary id as a line on that physical curve. Hanging
     * vertices stay as they are (gmsh cells are conforming only where the
     * triangulation is); read_msh() makes them vertices of the coarse
     * neighbours' polygons, as from_triangulation() does. (deal.II's own
     * GridOut::write_msh() writes gmsh's format 1, which read_msh() refuses.)
     */
    void
    write_msh(const dealii::Triangulation<2, 2> &tria, const std::string &filename);

    /// The physical names of a gmsh file only (the head of the file up to
    /// \$EndPhysicalNames is read and checked); empty maps for a file
    /// without \$PhysicalNames.
    PhysicalNames
    read_msh_physical_names(const std::string &filename);

    /// The size of a mesh file as its header says, see count_entities().
    struct FileCounts
    {
      /// Points (VTK) or nodes (gmsh) declared in the header.
      unsigned long long n_vertices = 0;
      /// Cells declared (VTK: CELLS, gmsh: \$Elements; both include the
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
     * .msh file (@p format "msh", versions 2.2 and 4.1, ASCII or binary):
     * the POINTS and
     * CELLS counts or the counts after \$Nodes and \$Elements. The lines in
     * between are skipped, not parsed, and nothing is stored, so that a
     * program can estimate the size of a run before it reads a large
     * file. Throws only if the file cannot be opened.
     */
    FileCounts
    count_entities(const std::string &filename, const std::string &format);
  } // namespace MeshIO
} // namespace dealvem

#endif
