// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_mesh_generators_h
#define dealvem_mesh_generators_h

#include <deal.II/base/point.h>

#include <dealvem/mesh/polygonal_mesh.h>

#include <functional>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace dealvem
{
  template <int dim>
  class TriangulationMap;

  /**
   * Functions that fill a PolygonalMesh. Every generated mesh is finalized
   * (conforming, edges built, validated).
   *
   * Boundary ids of the rectangle generators follow deal.II's
   * GridGenerator::hyper_rectangle with colorize = true:
   * 0 = left (x = x0), 1 = right (x = x1), 2 = bottom (y = y0), 3 = top (y = y1).
   * Random generators take a seed and give the same mesh for the same seed.
   */
  namespace PolygonalMeshGenerators
  {
    /// nx by ny structured quadrilaterals on the rectangle [p0, p1].
    template <int dim>
    void
    structured_quads(PolygonalMesh<dim>       &mesh,
                     const dealii::Point<dim> &p0,
                     const dealii::Point<dim> &p1,
                     const unsigned int        nx,
                     const unsigned int        ny);

    /// nx by ny squares on [p0, p1], each cut into two triangles along
    /// alternating diagonals.
    template <int dim>
    void
    structured_triangles(PolygonalMesh<dim>       &mesh,
                         const dealii::Point<dim> &p0,
                         const dealii::Point<dim> &p1,
                         const unsigned int        nx,
                         const unsigned int        ny);

    /**
     * Structured quads whose interior vertices are moved randomly by up to
     * @p amplitude times the cell size in each direction (0 <= amplitude <
     * 0.5); boundary vertices slide along their side only.
     */
    template <int dim>
    void
    perturbed_quads(PolygonalMesh<dim>       &mesh,
                    const dealii::Point<dim> &p0,
                    const dealii::Point<dim> &p1,
                    const unsigned int        nx,
                    const unsigned int        ny,
                    const double              amplitude,
                    const unsigned int        seed);

    /**
     * Centroidal Voronoi mesh of the rectangle [p0, p1] with @p n_cells
     * cells: random seeds (seeded), then @p n_lloyd_iterations Lloyd
     * iterations, each moving the generators to the centroids of their
     * cells. The Voronoi diagram comes from CGAL's Delaunay triangulation
     * of the generators and their mirror images across the four sides, so
     * that the cells are clipped exactly by the rectangle.
     *
     * Only this generator needs CGAL: in a dealvem configured without it
     * (DEALVEM_WITH_CGAL undefined in dealvem/config.h) it throws an
     * ExcMessage saying so.
     */
    template <int dim>
    void
    voronoi(PolygonalMesh<dim>       &mesh,
            const dealii::Point<dim> &p0,
            const dealii::Point<dim> &p1,
            const unsigned int        n_cells,
            const unsigned int        n_lloyd_iterations,
            const unsigned int        seed);

    /**
     * A family of meshes with non-convex cells: nx by ny structured cells
     * whose horizontal interior edges get a midpoint pushed down by
     * @p depth times the cell height (0 < depth < 0.5), so every cell has a
     * reflex vertex at the middle of its top edge (except the top row) and
     * a collinear midpoint on the domain's top and bottom sides.
     */
    template <int dim>
    void
    nonconvex(PolygonalMesh<dim>       &mesh,
              const dealii::Point<dim> &p0,
              const dealii::Point<dim> &p1,
              const unsigned int        nx,
              const unsigned int        ny,
              const double              depth = 0.3);

    /**
     * Convert the active cells of a deal.II triangulation (from
     * GridGenerator, GridIn, gmsh files, adaptively refined meshes) into
     * polygons, one per active cell in the order of
     * Triangulation::active_cell_iterators(). Boundary ids and material ids
     * are copied.
     *
     * <b>Material ids are bodies.</b> In a PolygonalMesh the material id of
     * a cell names the body it belongs to: finalize() (called here) throws
     * ExcInvalidMesh if two cells of different material ids share an edge,
     * since bodies interact through contact only. ContactProblem::add_body()
     * then gives all cells of a body its index as material id, and the
     * single-body program needs the material id of 'Mesh/Material id' on
     * every cell. A GridGenerator function called with `colorize = true`
     * may set material ids as well as boundary ids: in deal.II 9.4,
     * plate_with_a_hole(..., colorize = true) with radii 0.4 and 1 and pads
     * of 1 gives its 20 cells the material ids 0 (the 11 cells around the
     * hole) and 1, 2, 3 (three cells each in the pads) besides the boundary ids 0
     * left, 1 right, 2 bottom, 3 top and 4 on the hole; converting it throws
     * (four bodies that share edges). Reset the material ids, e.g.
     * `for (auto &cell : tria.active_cell_iterators()) cell->set_material_id(0);`,
     * to keep the boundary ids of the colorization in one body.
     *
     * With @p separate_material_ids, cells of different material ids get
     * vertices of their own where they meet (the vertices are copied), so
     * that a conforming mesh of an assembly, one material id per part,
     * becomes separate bodies whose interfaces match node for node (and
     * the faces between parts become boundary edges with id 0).
     *
     * Each polygon is made by walking the faces of its cell in
     * counter-clockwise order. Where a face has children (the neighbour
     * behind it is finer), the vertex the two children share is inserted
     * between the face's ends, recursively for a face refined more than
     * once. So the hanging vertices of a locally refined triangulation
     * become vertices of the coarse polygons wherever the manifold of the
     * face placed them: on the straight chord (flat manifold), on a circle
     * (SphericalManifold, PolarManifold) or anywhere inside
     * (TransfiniteInterpolationManifold); the coarse polygon then has five
     * or more vertices and the polygonal mesh is conforming. The pieces of
     * a refined boundary face get the boundary ids of the child faces.
     *
     * The polygons join the triangulation's vertices by straight edges: the
     * area of a polygon is the measure of its straight-sided cell plus the
     * signed triangle $(a, m, b)$ of every hanging vertex $m$ on a face
     * $(a, b)$. (finalize() also inserts vertices that lie on a neighbour's
     * straight edge; the face walk does not depend on that.) Tutorial
     * step-7 refines adaptively with this function.
     */
    template <int dim>
    void
    from_triangulation(PolygonalMesh<dim>                    &mesh,
                       const dealii::Triangulation<dim, dim> &tria,
                       const bool                             separate_material_ids = false);

    /**
     * The same, and keep the correspondence of active cells and polygons
     * and of triangulation and mesh vertices in @p map (see
     * TriangulationMap), so that a VEM solution can be transferred back to
     * finite element fields on @p tria (FETransfer).
     */
    template <int dim>
    void
    from_triangulation(PolygonalMesh<dim>                    &mesh,
                       const dealii::Triangulation<dim, dim> &tria,
                       TriangulationMap<dim>                 &map);

    /**
     * Refine @p tria toward a zone, the way graded contact meshes are made:
     * an active cell is refined while its longest edge exceeds 1.3 @p h and
     * its centre lies closer to the zone than @p layers times that edge
     * (@p distance: the distance of a point to the zone), until no cell is
     * left to refine. Cells then halve layer by layer away from the zone;
     * the hanging vertices this leaves become vertices of the coarse
     * neighbours in from_triangulation().
     */
    void
    refine_toward(dealii::Triangulation<2, 2>                            &tria,
                  const std::function<double(const dealii::Point<2> &)> &distance,
                  const double                                           h,
                  const double                                           layers = 2.);

    /// Read a mesh file (format from the extension). A gmsh .msh file is
    /// read by MeshIO::read_msh() (formats 2.2 and 4.1, ASCII and binary,
    /// any mix of triangles and quadrangles, refined natively @p
    /// n_refinements times). The other formats (.inp, .ucd, .vtk of
    /// deal.II's own kind, ...) go through deal.II's GridIn: the
    /// triangulation is refined @p n_refinements times
    /// (Triangulation::refine_global: new vertices on the straight edges,
    /// since a file carries no manifold) and converted.
    template <int dim>
    void
    from_gridin_file(PolygonalMesh<dim> &mesh,
                     const std::string  &filename,
                     const unsigned int  n_refinements         = 0,
                     const bool          separate_material_ids = false);

    /// The largest material id a mesh file may give a cell (gmsh physical
    /// surface, VTK "material_id"): an assembly read from one file has a
    /// part per id. (Boundary ids in files stay 0..254.)
    constexpr unsigned int max_material_id = 65535;
  } // namespace PolygonalMeshGenerators
} // namespace dealvem

#endif
