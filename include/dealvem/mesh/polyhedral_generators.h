// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_mesh_polyhedral_generators_h
#define dealvem_mesh_polyhedral_generators_h

#include <deal.II/base/point.h>

#include <dealvem/mesh/polyhedral_mesh.h>

#include <array>

namespace dealvem
{
  /**
   * Functions that fill a PolyhedralMesh with a mesh of the box
   * [lower, upper]. The mesh is cleared first, and the generated mesh is
   * finalized (faces matched, validated).
   *
   * Boundary ids follow deal.II's GridGenerator::hyper_rectangle with
   * colorize = true, by the side of the box a boundary face lies on:
   * 0 = x-side (x = lower[0]), 1 = x+ side (x = upper[0]),
   * 2 = y- side, 3 = y+ side, 4 = z- side, 5 = z+ side.
   * Random generators take a seed and give the same mesh for the same seed.
   */
  namespace PolyhedralMeshGenerators
  {
    /**
     * The structured mesh of subdivisions[0] by subdivisions[1] by
     * subdivisions[2] equal hexahedra (boxes) of the box [lower, upper],
     * built directly (no deal.II Triangulation). The vertices are numbered
     * lexicographically, x fastest, then y, then z; the cells likewise.
     * Every face is a quadrilateral: a hexahedron has six faces.
     *
     * Throws ExcMessage unless lower < upper in every coordinate and every
     * subdivision is at least 1.
     */
    void
    hyper_rectangle(PolyhedralMesh                   &mesh,
                    const dealii::Point<3>           &lower,
                    const dealii::Point<3>           &upper,
                    const std::array<unsigned int, 3> subdivisions);

    /**
     * A centroidal Voronoi mesh of the box [lower, upper] with @p n_cells
     * convex polyhedral cells: @p n_cells generators drawn uniformly in the
     * box by a std::mt19937 seeded with @p seed, then @p lloyd_iterations
     * iterations of Lloyd's algorithm, each moving every generator to the
     * centroid of its Voronoi cell. The CVT energy of the mesh,
     * sum_c int_c |x - g_c|^2 dx (g_c: the centroid of cell c), does not
     * increase from one iteration to the next.
     *
     * The Voronoi cell of a generator is the box cut by the bisector planes
     * between the generator and its neighbours in CGAL's 3D Delaunay
     * triangulation of the generators. The cells of the last iteration make
     * the mesh, conforming: each interior face is one planar polygon shared
     * by two cells; each boundary face lies on one side of the box and
     * carries its boundary id (see above). With @p n_cells = 1 the mesh is
     * the box itself, one hexahedron.
     *
     * Nearly degenerate diagrams: Lloyd's iteration tends to symmetric
     * configurations, where more than four generators are nearly
     * cospherical, and the diagram has edges and faces of any small size.
     * A vertex is identified across the cells by the four planes it is the
     * intersection of (not by its position, which the cells compute
     * differently). Vertices closer than 1e-7 times the box's size (the
     * larger of its diagonal and its largest coordinate) are merged, and
     * vertices that close to a side of the box are put on it: a smaller face
     * would not pass the planarity check of PolyhedralMesh::finalize() (the
     * round-off of its coordinates would reach 1e-8 of its diameter). Faces
     * that the merge reduces to fewer than three vertices are dropped, and a
     * face the merge leaves non-planar (beyond a quarter of the planarity
     * tolerance of finalize()) is split into triangles, in both its cells.
     *
     * The mesh is computed on the box moved to the origin and moved back at
     * the end, so that a box far from the origin gets the same cells,
     * translated (but for the merge, whose tolerance grows with the
     * coordinates).
     *
     * Only this generator needs CGAL: in a dealvem configured without it
     * (DEALVEM_WITH_CGAL undefined in dealvem/config.h) it throws an
     * ExcMessage saying so. Throws ExcMessage unless lower < upper in every
     * coordinate and @p n_cells is at least 1.
     */
    void
    voronoi_box(PolyhedralMesh         &mesh,
                const dealii::Point<3> &lower,
                const dealii::Point<3> &upper,
                const unsigned int      n_cells,
                const unsigned int      lloyd_iterations = 20,
                const unsigned int      seed             = 0);

    /**
     * A mesh of non-convex polyhedra: the n x n x n cubes of the unit cube
     * grouped, in each layer and each 2 x 2 block of columns, into an L of
     * three cubes and one single cube (the single cube at a corner that turns
     * from block to block and layer to layer; cubes of an odd n's last row
     * and column stay single). An L cell has coplanar faces side by side and
     * a reflex edge. Boundary ids as in hyper_rectangle(). The family the
     * patch tests and the convergence tests of tests/vem3d use for
     * non-convex cells; map it with PolyhedralMesh::transform() for other
     * shapes (an affine map keeps the faces planar).
     */
    void
    l_shaped_cells(PolyhedralMesh &mesh, const unsigned int n);
  } // namespace PolyhedralMeshGenerators
} // namespace dealvem

#endif
