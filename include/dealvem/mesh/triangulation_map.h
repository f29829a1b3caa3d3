// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_mesh_triangulation_map_h
#define dealvem_mesh_triangulation_map_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/smartpointer.h>
#include <deal.II/base/subscriptor.h>
#include <deal.II/base/types.h>

#include <dealvem/mesh/polygonal_mesh.h>

#include <cstdint>
#include <memory>
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
   * The correspondence between a deal.II triangulation and the
   * PolygonalMesh made from its active cells by
   * PolygonalMeshGenerators::from_triangulation(mesh, tria, map):
   * - every active cell of the triangulation is one polygon (the polygons
   *   are numbered in the order of Triangulation::active_cell_iterators());
   * - every vertex of the triangulation that an active cell uses is one
   *   vertex of the mesh (vertices that only belonged to coarsened cells are
   *   not in the mesh).
   *
   * Hanging vertices of a locally refined triangulation are ordinary
   * vertices of the polygons of the coarse neighbours (which then have five
   * or more vertices): from_triangulation() reads them from the children
   * of the coarse cell's faces, wherever the manifold put them, on the
   * chord of the coarse face or off it. A hanging vertex is a vertex of the
   * fine cells, so it has its mesh vertex like any other; the maps are
   * unaffected. FETransfer::interpolate_to_discontinuous() is exact on
   * such polygons as on any other; FETransfer::interpolate_to_continuous()
   * refuses triangulations with hanging nodes (the VEM trace on a coarse
   * edge with a hanging vertex is two polynomial pieces, an FE_Q trace
   * with a hanging-node constraint one polynomial). Tutorial step-7.
   *
   * The object holds the triangulation and the mesh through
   * dealii::SmartPointer, remembers the mesh's revision and watches the
   * triangulation's change signal. is_valid() tells whether both are still
   * what they were when the map was made: a refined or cleared
   * triangulation, or a mesh that node insertion has changed, invalidates
   * the map, and the functions that use it (for example
   * FETransfer::interpolate_to_discontinuous) refuse it with a message.
   *
   * This is how a deal.II program keeps its own triangulation, DoFHandler
   * and finite element vectors (for DataOut, KellyErrorEstimator,
   * VectorTools::integrate_difference) while dealvem solves on the
   * polygons; tutorial step-5 shows the whole round trip.
   */
  template <int dim>
  class TriangulationMap : public dealii::Subscriptor
  {
  public:
    TriangulationMap();
    /// A copy refers to the same triangulation and mesh as @p other.
    TriangulationMap(const TriangulationMap<dim> &other);
    /// Refer to the triangulation and mesh of @p other, with its maps.
    TriangulationMap<dim> &
    operator=(const TriangulationMap<dim> &other);
    ~TriangulationMap() override;

    /**
     * Record the maps (called by from_triangulation()). @p polygon_of_cell
     * is indexed by the active cell index, @p mesh_vertex_of_tria_vertex by
     * the triangulation's vertex index (numbers::invalid_unsigned_int for
     * vertices no active cell uses). Both are checked against @p tria and
     * @p mesh: the polygon of each active cell has the cell's vertices, at
     * the same coordinates.
     */
    void
    reinit(const dealii::Triangulation<dim, dim> &tria,
           const PolygonalMesh<dim>              &mesh,
           const std::vector<unsigned int>       &polygon_of_cell,
           const std::vector<unsigned int>       &mesh_vertex_of_tria_vertex);

    /// Number of active cells of the triangulation (= polygons mapped).
    unsigned int
    n_active_cells() const
    {
      return polygon_of_cell.size();
    }

    /// The polygon made from the active cell with index @p active_cell_index.
    unsigned int
    polygon(const unsigned int active_cell_index) const
    {
      AssertIndexRange(active_cell_index, polygon_of_cell.size());
      return polygon_of_cell[active_cell_index];
    }

    /// The polygon made from an active cell (any iterator or accessor with
    /// active_cell_index(): a Triangulation or DoFHandler cell).
    template <typename CellIterator>
    unsigned int
    polygon_of(const CellIterator &cell) const
    {
      return polygon(cell->active_cell_index());
    }

    /// The active cell index of the cell that polygon @p p was made from.
    unsigned int
    active_cell_index(const unsigned int p) const
    {
      AssertIndexRange(p, cell_of_polygon.size());
      return cell_of_polygon[p];
    }

    /**
     * Level and index of the cell that polygon @p p was made from, so that
     * the user can make an iterator:
     * `typename Triangulation<dim>::active_cell_iterator cell(&tria, level, index)`.
     */
    std::pair<int, int>
    cell_level_and_index(const unsigned int p) const
    {
      AssertIndexRange(p, level_and_index.size());
      return level_and_index[p];
    }

    /// Mesh vertex of triangulation vertex @p v (numbers::invalid_unsigned_int
    /// if no active cell uses @p v).
    unsigned int
    mesh_vertex(const unsigned int v) const
    {
      AssertIndexRange(v, mesh_vertex_of_tria_vertex.size());
      return mesh_vertex_of_tria_vertex[v];
    }

    /// Triangulation vertex of mesh vertex @p v (vertices added to the mesh
    /// later, by node insertion for example, have none: invalid_unsigned_int).
    unsigned int
    triangulation_vertex(const unsigned int v) const
    {
      return v < tria_vertex_of_mesh_vertex.size() ? tria_vertex_of_mesh_vertex[v] :
                                                     dealii::numbers::invalid_unsigned_int;
    }

    /// The triangulation the map was made from (throws if there is none).
    const dealii::Triangulation<dim, dim> &
    get_triangulation() const;

    /// The mesh the map was made for (throws if there is none).
    const PolygonalMesh<dim> &
    get_mesh() const;

    /// The revision of the mesh when the map was made.
    std::uint64_t
    get_mesh_revision() const
    {
      return mesh_revision;
    }

    /// Whether the triangulation has not changed since the map was made
    /// (Triangulation::Signals::any_change has not fired).
    bool
    triangulation_unchanged() const;

    /// Whether the mesh has the revision it had when the map was made.
    bool
    mesh_unchanged() const;

    /// Throw (AssertThrow) unless the map was made and neither the
    /// triangulation nor the mesh has changed since; the message says which
    /// one changed and how.
    void
    check_valid() const;

  private:
    dealii::SmartPointer<const dealii::Triangulation<dim, dim>, TriangulationMap<dim>> tria;
    dealii::SmartPointer<const PolygonalMesh<dim>, TriangulationMap<dim>>            mesh;
    std::uint64_t                                                                     mesh_revision = 0;
    std::vector<unsigned int>                                                         polygon_of_cell;
    std::vector<unsigned int>                                                         cell_of_polygon;
    std::vector<std::pair<int, int>>                                                  level_and_index;
    std::vector<unsigned int> mesh_vertex_of_tria_vertex;
    std::vector<unsigned int> tria_vertex_of_mesh_vertex;

    /// Set to true by the triangulation's any_change signal; shared by the
    /// copies of a map, like the connection (disconnected when the last copy
    /// goes).
    std::shared_ptr<bool> tria_changed;
    std::shared_ptr<void> connection;
  };
} // namespace dealvem

#endif
