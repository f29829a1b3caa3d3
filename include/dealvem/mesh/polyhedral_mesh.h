// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_mesh_polyhedral_mesh_h
#define dealvem_mesh_polyhedral_mesh_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/subscriptor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace dealvem
{
  /**
   * A conforming mesh of arbitrary polyhedra: the ground of the 3D virtual
   * elements (issue 43).
   *
   * The mesh stores
   * - vertices (points in space),
   * - faces: planar polygons, each a loop of vertex indices, stored once and
   *   shared by the one or two cells on its sides. A face's loop is oriented
   *   so that its normal (right-hand rule) points out of its first cell,
   *   cells[0], and into cells[1];
   * - cells: the list of their faces and a material id.
   *
   * A polyhedron may be non-convex, may have several coplanar faces side by
   * side and faces with collinear vertices (a face of a coarse hexahedron
   * whose edge a finer neighbour has split): the virtual element needs none
   * of the restrictions of a finite element. This is also how a locally
   * refined deal.II mesh is read (from_triangulation()): a coarse cell next to
   * refined ones becomes a polyhedron with the finer faces and edge midpoints
   * as its own faces and vertices, and the mesh is conforming without
   * hanging-node constraints.
   *
   * Why a class of its own rather than PolygonalMesh<3>: a 2D cell is a
   * vertex loop and its edges are derived from it; a 3D cell is a closed
   * surface of faces, and the shared entity that carries boundary ids is
   * the face. The two share the conventions (add, finalize, validate, an
   * exception naming the cell or face) but not their storage.
   *
   * <h3>Validation</h3>
   * finalize() matches the faces of the cells (a face given by two cells with
   * the same vertices is one face, which must be oriented oppositely in
   * them) and throws ExcInvalidPolyhedralMesh, naming the cell and face, for
   * - a face with fewer than three distinct vertices, zero area, or a loop
   *   that crosses itself in the face's plane;
   * - a face that is not planar: a vertex farther than
   *   `planarity_tolerance` times the face's diameter from the face's plane;
   * - a cell whose faces do not form a closed, consistently oriented surface
   *   (every edge of the cell must be used by exactly two of its faces, in
   *   opposite directions);
   * - a cell whose faces point inwards (negative volume) or whose volume is
   *   zero;
   * - a face used by more than two cells, or twice with the same
   *   orientation;
   * - non-finite coordinates.
   */
  class PolyhedralMesh : public dealii::Subscriptor
  {
  public:
    /// The space dimension.
    static constexpr int dimension = 3;

    /// A planar polygonal face shared by one or two cells.
    struct Face
    {
      /// The vertex loop, oriented outward from cells[0].
      std::vector<unsigned int> vertices;
      /// The cells on either side (cells[1] invalid at the boundary).
      std::array<unsigned int, 2> cells;
      /// The boundary id (meaningful for boundary faces only).
      dealii::types::boundary_id boundary_id = 0;

      /// True for a face of one cell.
      bool
      at_boundary() const;
    };

    /// A polyhedral cell: its faces and its material id.
    struct Cell
    {
      /// The indices of its faces.
      std::vector<unsigned int>  faces;
      /// The material id (the id of the body).
      dealii::types::material_id material_id = 0;
    };

    /// Geometric data of a face (computed, not stored).
    struct FaceGeometry
    {
      /// Area of the polygon.
      double area = 0;
      /// Unit normal by the right-hand rule of the stored loop.
      dealii::Tensor<1, 3> normal;
      /// Centroid (centre of area).
      dealii::Point<3> centroid;
      /// Largest distance between two vertices.
      double diameter = 0;
    };

    PolyhedralMesh() = default;

    /// Remove everything.
    void
    clear();

    /// Add a vertex; returns its index.
    unsigned int
    add_vertex(const dealii::Point<3> &p);

    /**
     * Add a cell from its faces, each a loop of (already added) vertex
     * indices oriented with the normal pointing out of the cell. A face
     * shared with a cell added before is recognised by its vertex set.
     * The mesh is not usable until finalize() is called.
     */
    unsigned int
    add_cell(const std::vector<std::vector<unsigned int>> &face_loops,
             const dealii::types::material_id              material_id = 0);

    /**
     * Match the faces, build the face-to-cell relations, give every
     * boundary face the boundary id 0, and validate the mesh (see the class
     * documentation). @p planarity_tolerance is relative to a face's
     * diameter.
     */
    void
    finalize(const double planarity_tolerance = 1e-8);

    /// The checks of finalize(), without changing the mesh.
    void
    validate() const;

    /// Number of vertices.
    unsigned int
    n_vertices() const
    {
      return vertices.size();
    }

    /// Number of faces (after finalize()).
    unsigned int
    n_faces() const
    {
      return faces.size();
    }

    /// Number of cells (after finalize()).
    unsigned int
    n_cells() const
    {
      return cells.size();
    }

    /// Vertex @p v.
    const dealii::Point<3> &
    vertex(const unsigned int v) const
    {
      return vertices[v];
    }

    /// All vertices.
    const std::vector<dealii::Point<3>> &
    get_vertices() const
    {
      return vertices;
    }

    /// Face @p f.
    const Face &
    face(const unsigned int f) const
    {
      return faces[f];
    }

    /// Cell @p c.
    const Cell &
    cell(const unsigned int c) const
    {
      return cells[c];
    }

    /// True if face @p f's stored loop points out of cell @p c.
    bool
    face_points_out_of(const unsigned int f, const unsigned int c) const
    {
      return faces[f].cells[0] == c;
    }

    /// The vertices of cell @p c, each once, sorted by index.
    std::vector<unsigned int>
    cell_vertex_indices(const unsigned int c) const;

    /// Area, normal, centroid and diameter of face @p f.
    FaceGeometry
    face_geometry(const unsigned int f) const;

    /// The volume of cell @p c (divergence theorem over its faces).
    double
    cell_volume(const unsigned int c) const;

    /// Set the boundary id of boundary face @p f.
    void
    set_face_boundary_id(const unsigned int f, const dealii::types::boundary_id id);

    /**
     * Give every boundary face the boundary id @p id for which
     * @p select(centroid, normal) is true (normal: outward unit normal of the
     * face). Returns the number of faces changed.
     */
    unsigned int
    set_boundary_ids(const std::function<bool(const dealii::Point<3> &, const dealii::Tensor<1, 3> &)> &select,
                     const dealii::types::boundary_id                                                   id);

    /// The boundary ids in use, sorted.
    std::vector<dealii::types::boundary_id>
    get_boundary_ids() const;

    /// Smallest and largest cell diameter (largest vertex distance).
    std::pair<double, double>
    cell_diameter_range() const;

    /// The diagonal of the bounding box of the vertices.
    double
    extent() const;

    /// The sum of the cell volumes.
    double
    total_volume() const;

    /// Move vertex @p v (the caller validates afterwards).
    void
    move_vertex(const unsigned int v, const dealii::Point<3> &p);

    /// Apply @p map to every vertex (the caller validates afterwards;
    /// an affine map keeps faces planar).
    void
    transform(const std::function<dealii::Point<3>(const dealii::Point<3> &)> &map);

    /**
     * The polyhedral mesh of a deal.II triangulation of hexahedra and/or
     * tetrahedra (active cells; material ids and boundary ids of the faces
     * are kept). Where a neighbour is refined further, the coarse cell takes
     * the neighbour's finer faces as its own faces, and a face whose edge was
     * split by a refined cell along that edge gets the edge's midpoint as a
     * vertex: the result is conforming without constraints.
     *
     * A quadrilateral face whose vertices are not coplanar (a distorted
     * hexahedron, a hexahedron of a curved shell) is refused by the
     * planarity check, naming the face and cell, unless
     * @p split_warped_faces is true: then it is split into two triangles
     * along the diagonal through its smallest vertex index, the same
     * diagonal in both cells that share it, and the hexahedron becomes a
     * polyhedron with up to twelve triangular faces. (A warped face with
     * the midpoint of a refined edge is still refused.) @p name names the
     * mesh in error messages.
     */
    static PolyhedralMesh
    from_triangulation(const dealii::Triangulation<3, 3> &tria,
                       const double                       planarity_tolerance = 1e-8,
                       const bool                         split_warped_faces  = false,
                       const std::string                 &name = "the polyhedral mesh of a Triangulation<3>");

    /**
     * The polyhedral mesh of a gmsh file of hexahedra and/or tetrahedra
     * (read by deal.II's GridIn<3>: physical tags become material and
     * boundary ids), through from_triangulation(). Errors of the reader
     * are reported with the file's name.
     */
    static PolyhedralMesh
    read_gmsh(const std::string &file_name,
              const double       planarity_tolerance = 1e-8,
              const bool         split_warped_faces  = false);

    /**
     * Write the mesh to a VTU file of VTK_POLYHEDRON cells (ParaView) with
     * the cell data material_id and cell_index, and the given point and cell
     * fields: each a name and one value per vertex (per cell), or three
     * values per vertex (per cell) interleaved for a vector field.
     */
    void
    write_vtu(const std::string                                                     &file_name,
              const std::vector<std::pair<std::string, std::vector<double>>> &point_fields = {},
              const std::vector<std::pair<std::string, std::vector<double>>> &cell_fields  = {}) const;

    /// Source description (file name or generator), used in error messages.
    std::string name = "polyhedral mesh";

  private:
    std::vector<dealii::Point<3>> vertices;
    std::vector<Face>             faces;
    std::vector<Cell>             cells;
    /// face loops as given to add_cell(), before finalize()
    std::vector<std::vector<std::vector<unsigned int>>> pending_cells;
    std::vector<dealii::types::material_id>              pending_material_ids;
    bool                                                  finalized = false;
    double                                                planarity = 1e-8;
  };

  /**
   * An invalid polyhedral mesh: the message names the mesh, and the cell,
   * face or vertex.
   */
  DeclException1(ExcInvalidPolyhedralMesh,
                 std::string,
                 << "Invalid polyhedral mesh: " << arg1);
} // namespace dealvem

#endif
