// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/grid/tria.h>

#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/triangulation_map.h>

#include <algorithm>
#include <string>

namespace dealvem
{
  template <int dim>
  TriangulationMap<dim>::TriangulationMap() = default;



  template <int dim>
  TriangulationMap<dim>::TriangulationMap(const TriangulationMap<dim> &other)
    : dealii::Subscriptor()
    , tria(other.tria)
    , mesh(other.mesh)
    , mesh_revision(other.mesh_revision)
    , polygon_of_cell(other.polygon_of_cell)
    , cell_of_polygon(other.cell_of_polygon)
    , level_and_index(other.level_and_index)
    , mesh_vertex_of_tria_vertex(other.mesh_vertex_of_tria_vertex)
    , tria_vertex_of_mesh_vertex(other.tria_vertex_of_mesh_vertex)
    , tria_changed(other.tria_changed)
    , connection(other.connection)
  {}



  template <int dim>
  TriangulationMap<dim> &
  TriangulationMap<dim>::operator=(const TriangulationMap<dim> &other)
  {
    tria                       = other.tria;
    mesh                       = other.mesh;
    mesh_revision              = other.mesh_revision;
    polygon_of_cell            = other.polygon_of_cell;
    cell_of_polygon            = other.cell_of_polygon;
    level_and_index            = other.level_and_index;
    mesh_vertex_of_tria_vertex = other.mesh_vertex_of_tria_vertex;
    tria_vertex_of_mesh_vertex = other.tria_vertex_of_mesh_vertex;
    tria_changed               = other.tria_changed;
    connection                 = other.connection;
    return *this;
  }



  template <int dim>
  TriangulationMap<dim>::~TriangulationMap()
  {
    // disconnect from the triangulation's signal first (if this is the last
    // copy), then let the smart pointers unsubscribe
    connection.reset();
    tria = nullptr;
    mesh = nullptr;
  }



  template <int dim>
  void
  TriangulationMap<dim>::reinit(const dealii::Triangulation<dim, dim> &t,
                                const PolygonalMesh<dim>              &m,
                                const std::vector<unsigned int>       &cells,
                                const std::vector<unsigned int>       &vertices)
  {
    AssertThrow(cells.size() == t.n_active_cells(),
                dealii::ExcMessage("TriangulationMap: " + std::to_string(cells.size()) +
                                   " polygons given for a triangulation with " +
                                   std::to_string(t.n_active_cells()) + " active cells."));
    AssertThrow(vertices.size() == t.n_vertices(),
                dealii::ExcMessage("TriangulationMap: the vertex map has " + std::to_string(vertices.size()) +
                                   " entries for a triangulation with " + std::to_string(t.n_vertices()) +
                                   " vertices."));
    tria                       = &t;
    mesh                       = &m;
    mesh_revision              = m.get_revision();
    polygon_of_cell            = cells;
    mesh_vertex_of_tria_vertex = vertices;

    cell_of_polygon.assign(m.n_cells(), dealii::numbers::invalid_unsigned_int);
    level_and_index.assign(m.n_cells(), {-1, -1});
    tria_vertex_of_mesh_vertex.assign(m.n_vertices(), dealii::numbers::invalid_unsigned_int);
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (vertices[v] != dealii::numbers::invalid_unsigned_int)
        {
          AssertThrow(vertices[v] < m.n_vertices() && m.vertex(vertices[v]) == t.get_vertices()[v],
                      dealii::ExcMessage("TriangulationMap: triangulation vertex " + std::to_string(v) +
                                         " is not mesh vertex " + std::to_string(vertices[v]) + "."));
          tria_vertex_of_mesh_vertex[vertices[v]] = v;
        }

    // every polygon must have the vertices of its cell (and, with hanging
    // vertices of refined neighbours, possibly more)
    for (const auto &cell : t.active_cell_iterators())
      {
        const unsigned int p = cells[cell->active_cell_index()];
        AssertThrow(p < m.n_cells() && cell_of_polygon[p] == dealii::numbers::invalid_unsigned_int,
                    dealii::ExcMessage("TriangulationMap: active cell " + std::to_string(cell->active_cell_index()) +
                                       " is mapped to polygon " + std::to_string(p) +
                                       ", which does not exist or is mapped twice."));
        cell_of_polygon[p] = cell->active_cell_index();
        level_and_index[p] = {cell->level(), cell->index()};
        const auto &loop   = m.cell(p).vertices;
        for (const unsigned int v : cell->vertex_indices())
          AssertThrow(std::find(loop.begin(), loop.end(), vertices[cell->vertex_index(v)]) != loop.end(),
                      dealii::ExcMessage("TriangulationMap: polygon " + std::to_string(p) +
                                         " lacks vertex " + std::to_string(cell->vertex_index(v)) +
                                         " of its cell."));
      }

    // watch the triangulation: refinement, coarsening, clear() and the like
    // fire any_change, after which the maps are stale
    tria_changed = std::make_shared<bool>(false);
    auto flag    = tria_changed;
    auto conn    = t.signals.any_change.connect([flag]() { *flag = true; });
    connection   = std::shared_ptr<void>(nullptr, [conn](void *) mutable { conn.disconnect(); });
  }



  template <int dim>
  const dealii::Triangulation<dim, dim> &
  TriangulationMap<dim>::get_triangulation() const
  {
    AssertThrow(tria != nullptr, dealii::ExcMessage("TriangulationMap: no triangulation; the map was not made."));
    return *tria;
  }



  template <int dim>
  const PolygonalMesh<dim> &
  TriangulationMap<dim>::get_mesh() const
  {
    AssertThrow(mesh != nullptr, dealii::ExcMessage("TriangulationMap: no mesh; the map was not made."));
    return *mesh;
  }



  template <int dim>
  bool
  TriangulationMap<dim>::triangulation_unchanged() const
  {
    return tria != nullptr && tria_changed && !*tria_changed;
  }



  template <int dim>
  bool
  TriangulationMap<dim>::mesh_unchanged() const
  {
    return mesh != nullptr && mesh->get_revision() == mesh_revision;
  }



  template <int dim>
  void
  TriangulationMap<dim>::check_valid() const
  {
    AssertThrow(tria != nullptr && mesh != nullptr,
                dealii::ExcMessage("TriangulationMap: the map was not made; use "
                                   "PolygonalMeshGenerators::from_triangulation(mesh, tria, map)."));
    AssertThrow(triangulation_unchanged(),
                dealii::ExcMessage("TriangulationMap: the triangulation was changed (refined, coarsened or "
                                   "recreated) after the map was made; make the mesh and the map again with "
                                   "PolygonalMeshGenerators::from_triangulation(mesh, tria, map)."));
    AssertThrow(mesh_unchanged(),
                dealii::ExcMessage("TriangulationMap: the mesh '" + mesh->name +
                                   "' was changed after the map was made (last change: " + mesh->get_last_change() +
                                   "); its polygons may no longer be the cells of the triangulation."));
  }



  namespace PolygonalMeshGenerators
  {
    template <int dim>
    void
    from_triangulation(PolygonalMesh<dim>                    &mesh,
                       const dealii::Triangulation<dim, dim> &tria,
                       TriangulationMap<dim>                 &map)
    {
      from_triangulation(mesh, tria);

      // from_triangulation() adds the cells in the order of the active cell
      // iterators and all vertices of the triangulation; finalize() then
      // drops the vertices no cell uses and keeps the order of the others.
      std::vector<unsigned int> polygon_of_cell(tria.n_active_cells());
      std::vector<bool>         used(tria.n_vertices(), false);
      unsigned int              p = 0;
      for (const auto &cell : tria.active_cell_iterators())
        {
          polygon_of_cell[cell->active_cell_index()] = p++;
          for (const unsigned int v : cell->vertex_indices())
            used[cell->vertex_index(v)] = true;
        }
      std::vector<unsigned int> mesh_vertex(tria.n_vertices(), dealii::numbers::invalid_unsigned_int);
      unsigned int              n_used = 0;
      for (unsigned int v = 0; v < used.size(); ++v)
        if (used[v])
          mesh_vertex[v] = n_used++;
      AssertThrow(n_used == mesh.n_vertices() && p == mesh.n_cells(),
                  dealii::ExcInternalError());
      // reinit() checks every vertex and cell of the maps
      map.reinit(tria, mesh, polygon_of_cell, mesh_vertex);
    }

    template void
    from_triangulation(PolygonalMesh<2> &, const dealii::Triangulation<2, 2> &, TriangulationMap<2> &);
  } // namespace PolygonalMeshGenerators

  template class TriangulationMap<2>;
} // namespace dealvem
