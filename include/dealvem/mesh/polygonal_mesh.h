// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_mesh_polygonal_mesh_h
#define dealvem_mesh_polygonal_mesh_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/subscriptor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <string>
#include <vector>

namespace dealvem
{
  namespace internal
  {
    /// A number never handed out before in this program run (thread-safe):
    /// the revision stamps of PolygonalMesh.
    std::uint64_t
    new_mesh_revision();
  } // namespace internal

  /**
   * A conforming mesh of arbitrary polygons.
   *
   * The mesh stores
   * - vertices (points in the plane),
   * - cells, each a counter-clockwise loop of vertex indices with a
   *   material id (which is also the id of the body the cell belongs to),
   * - edges, the shared one-dimensional entities: every cell edge is stored
   *   once, with the (one or two) cells that use it, and a boundary id for
   *   edges used by a single cell.
   *
   * Cells are added with add_cell(); then finalize() (or the constructor of
   * a generator) makes the mesh conforming, builds the edges and validates
   * the mesh. A vertex lying inside the edge of a neighbouring cell of the
   * same body (a "hanging node" in finite element language) is inserted into
   * that neighbour's vertex loop: for virtual elements such a cell simply has
   * one more (collinear) vertex, so the mesh stays conforming.
   *
   * Validation throws ExcInvalidMesh, naming the cell or vertex, for
   * clockwise, self-intersecting or zero-area polygons, repeated vertices in
   * a loop, non-finite coordinates, an edge shared by more than two cells,
   * and overlapping cells of the same body.
   *
   * Cells of different bodies (different material ids) never share vertices
   * or edges: bodies interact only through contact.
   *
   * <h3>Revisions</h3>
   * Objects that cache data computed from the mesh (VEMDoFHandler) hold it
   * through a dealii::SmartPointer (the class is a dealii::Subscriptor, like
   * dealii::Triangulation) and remember get_revision(). Every operation that
   * changes the topology or the geometry -- clear(), add_vertex(),
   * add_cell(), finalize(), shift(), append(), split_edge(), move_vertex(),
   * and assigning another mesh -- gives the mesh a new revision, a number
   * no other mesh of the program run has had; get_last_change() names the
   * operation. Changing material or boundary ids does not count: the DoFs do
   * not depend on them.
   *
   * Only dim == 2 is implemented; the template parameter follows deal.II's
   * convention.
   */
  template <int dim>
  class PolygonalMesh : public dealii::Subscriptor
  {
  public:
    static_assert(dim == 2, "PolygonalMesh is implemented for dim == 2 only.");

    /**
     * An edge: two vertex indices, the cells on either side, and the
     * boundary id (meaningful for boundary edges only).
     */
    struct Edge
    {
      /// The two end vertices; for a boundary edge in the counter-clockwise
      /// order of its cell.
      std::array<unsigned int, 2> vertices;
      /// The cells using the edge; cells[1] is numbers::invalid_unsigned_int
      /// for a boundary edge.
      std::array<unsigned int, 2> cells;
      /// Boundary id, 0 unless set; numbers::internal_face_boundary_id for
      /// interior edges.
      dealii::types::boundary_id boundary_id;

      /// Whether the edge has one cell only (cells[1] invalid).
      bool
      at_boundary() const
      {
        return cells[1] == dealii::numbers::invalid_unsigned_int;
      }
    };

    /**
     * A polygonal cell.
     */
    struct Cell
    {
      /// Counter-clockwise loop of vertex indices (no repetition of the
      /// first vertex at the end).
      std::vector<unsigned int> vertices;
      /// Indices of the edges, edges[i] joining vertices[i] and
      /// vertices[(i+1) % n].
      std::vector<unsigned int> edges;
      /// Material id; cells of different material ids belong to different
      /// bodies.
      dealii::types::material_id material_id = 0;
    };

    PolygonalMesh() = default;

    /// Remove everything.
    void
    clear();

    /// Add a vertex and return its index.
    unsigned int
    add_vertex(const dealii::Point<dim> &p);

    /**
     * Add a cell with a counter-clockwise loop of (already added) vertex
     * indices. The mesh is not usable until finalize() is called.
     */
    unsigned int
    add_cell(const std::vector<unsigned int> &vertex_loop,
             const dealii::types::material_id material_id = 0);

    /**
     * Set the boundary id of the boundary edge joining vertices @p v0 and
     * @p v1 (in either order). Can be called before finalize(): the ids are
     * remembered and applied when edges are built (also to the pieces of an
     * edge split by a hanging vertex).
     */
    void
    set_boundary_id(const unsigned int                v0,
                    const unsigned int                v1,
                    const dealii::types::boundary_id id);

    /**
     * Make the mesh conforming (insert hanging vertices into the loops of
     * the neighbouring cells of the same body), remove vertices that no cell
     * uses, build the edges and validate everything. Throws ExcInvalidMesh
     * with a message naming the offending cell or vertex.
     *
     * @p relative_tolerance is relative to the length of the edge: a vertex
     * closer than this to an edge is considered to lie on it.
     */
    void
    finalize(const double relative_tolerance = 1e-10);

    /// Run the validity checks again (finalize() calls this).
    void
    validate() const;

    /// Number of vertices.
    unsigned int
    n_vertices() const
    {
      return vertices.size();
    }

    /// Number of cells.
    unsigned int
    n_cells() const
    {
      return cells.size();
    }

    /// Number of edges (valid after finalize()).
    unsigned int
    n_edges() const
    {
      return edges.size();
    }

    /// Vertex @p i.
    const dealii::Point<dim> &
    vertex(const unsigned int i) const
    {
      return vertices[i];
    }

    /// All vertices, in the order of their indices.
    const std::vector<dealii::Point<dim>> &
    get_vertices() const
    {
      return vertices;
    }

    /// Cell @p c.
    const Cell &
    cell(const unsigned int c) const
    {
      return cells[c];
    }

    /// All cells, in the order of their indices.
    const std::vector<Cell> &
    get_cells() const
    {
      return cells;
    }

    /// Edge @p e (after finalize()).
    const Edge &
    edge(const unsigned int e) const
    {
      return edges[e];
    }

    /// All edges (after finalize()), in the order of their indices.
    const std::vector<Edge> &
    get_edges() const
    {
      return edges;
    }

    /// The coordinates of the vertices of cell @p c, counter-clockwise.
    std::vector<dealii::Point<dim>>
    cell_vertices(const unsigned int c) const;

    /// Same, written into @p points (whose storage is reused: no allocation
    /// in assembly loops once it is large enough).
    void
    cell_vertices(const unsigned int c, std::vector<dealii::Point<dim>> &points) const;

    /// Change the material id of a cell.
    void
    set_material_id(const unsigned int c, const dealii::types::material_id id)
    {
      cells[c].material_id = id;
    }

    /// Set the boundary id of edge @p e (must be a boundary edge).
    void
    set_edge_boundary_id(const unsigned int                e,
                         const dealii::types::boundary_id id);

    /// The set of boundary ids in use, sorted.
    std::vector<dealii::types::boundary_id>
    get_boundary_ids() const;

    /// The set of material ids in use, sorted.
    std::vector<dealii::types::material_id>
    get_material_ids() const;

    /// Move every vertex by @p shift.
    void
    shift(const dealii::Tensor<1, dim> &shift);

    /**
     * Append another mesh (a second body). The other mesh's vertex and cell
     * indices are offset; its boundary ids are kept. Both meshes must be
     * finalized; the result is finalized again.
     */
    void
    append(const PolygonalMesh<dim> &other);

    /// Append several meshes at once (the meshes are validated once, so
    /// that appending many bodies costs time linear in their size).
    void
    append(const std::vector<const PolygonalMesh<dim> *> &others);

    /**
     * The cells of each material id as a mesh of its own (with the
     * vertices it uses, its boundary ids, its material id), in the order of
     * get_material_ids(); the cost is linear in the size of the mesh.
     * Used to make one body of each part of an assembly read from one file.
     */
    std::vector<PolygonalMesh<dim>>
    split_by_material_id() const;

    /**
     * Split the edge @p e at the point @p p (which must lie on the edge,
     * strictly between its ends): a new vertex is created and inserted into
     * the vertex loops of the cells owning the edge; both pieces keep the
     * boundary id. Returns the index of the new vertex. Used by node
     * insertion on contact interfaces. The edges are updated in place:
     * edge @p e becomes the piece from its first vertex to the new one, and
     * the piece from the new vertex to the second vertex is appended as
     * edge n_edges() - 1; no other edge index changes.
     */
    unsigned int
    split_edge(const unsigned int e, const dealii::Point<dim> &p);

    /**
     * Move vertex @p v to @p p. Nothing else changes (edges and cells keep
     * their indices); the caller checks the cells afterwards with
     * validate(). Used by node insertion to make the two sides of a
     * contact interface coincide.
     */
    void
    move_vertex(const unsigned int v, const dealii::Point<dim> &p)
    {
      AssertThrow(v < vertices.size(), dealii::ExcMessage("move_vertex: no vertex " + std::to_string(v) + "."));
      vertices[v] = p;
      changed("move_vertex()");
    }

    /**
     * The revision of the mesh: a new value after every change of its
     * vertices, cells or edges (see the class documentation). Two meshes
     * never share a revision unless one is a copy of the other.
     */
    std::uint64_t
    get_revision() const
    {
      return revision;
    }

    /// The operation that gave the mesh its current revision, for example
    /// "split_edge()" (used in error messages).
    const std::string &
    get_last_change() const
    {
      return last_change;
    }

    /// Smallest and largest cell diameter.
    std::pair<double, double>
    cell_diameter_range() const;

    /// Length of the diagonal of the bounding box of all vertices (0 for
    /// a mesh without vertices): the size of the mesh.
    double
    extent() const;

    /// Total area of all cells.
    double
    total_area() const;

    /// Source description (file name or generator), used in error messages.
    std::string name = "mesh";

  private:
    /// Record a change of topology or geometry made by @p what.
    void
    changed(const char *what)
    {
      revision    = internal::new_mesh_revision();
      last_change = what;
    }

    void
    build_edges();

    void
    insert_hanging_vertices(const double relative_tolerance);

    void
    remove_unused_vertices();

    std::vector<dealii::Point<dim>> vertices;
    std::vector<Cell>               cells;
    std::vector<Edge>               edges;

    /// Boundary ids by vertex pair (smaller, larger): set with
    /// set_boundary_id() or set_edge_boundary_id(), handed on to the pieces
    /// of split edges, and applied whenever the edges are built.
    std::map<std::pair<unsigned int, unsigned int>, dealii::types::boundary_id>
      boundary_ids_by_pair;

    std::uint64_t revision    = internal::new_mesh_revision();
    std::string   last_change = "construction";
  };

  /**
   * An invalid mesh: the message names the mesh, and the cell or vertex.
   */
  DeclException1(ExcInvalidMesh,
                 std::string,
                 << "Invalid polygonal mesh: " << arg1);
} // namespace dealvem

#endif
