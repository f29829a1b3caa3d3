// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_mesh_polyhedral_generators_h
#define dealvem_mesh_polyhedral_generators_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dealvem/mesh/polyhedral_mesh.h>

#include <array>
#include <utility>
#include <vector>

namespace dealvem
{
  /**
   * Functions that fill a PolyhedralMesh with a mesh of the box
   * [lower, upper] or, voronoi_convex(), of a convex domain given by
   * half-spaces. The mesh is cleared first, and the generated mesh is
   * finalized (faces matched, validated).
   *
   * Boundary ids of the box generators follow deal.II's
   * GridGenerator::hyper_rectangle with colorize = true, by the side of the
   * box a boundary face lies on: 0 = x-side (x = lower[0]), 1 = x+ side
   * (x = upper[0]), 2 = y- side, 3 = y+ side, 4 = z- side, 5 = z+ side.
   * voronoi_convex() gives a boundary face the index of the half-space whose
   * plane it lies on. Random generators take a seed and give the same mesh
   * for the same seed.
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
     * This is voronoi_convex() on the six half-spaces of the box, in the
     * order of the boundary ids above (the box's vertices and its sides'
     * coordinates stay exact), with the merge tolerance of the box
     * generator's first version (the one place where voronoi_convex() uses
     * the diagonal alone): the same seed gives the same mesh as before,
     * except where neighbours lie at equal distances from a generator
     * (Lloyd's iteration near a symmetric configuration): they now cut its
     * cell in the order of their indices, so that such a nearly degenerate
     * mesh no longer depends on the calls made before in the program.
     *
     * Only the Voronoi generators need CGAL: in a dealvem configured without
     * it (DEALVEM_WITH_CGAL undefined in dealvem/config.h) they throw an
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
     * A centroidal Voronoi mesh, as voronoi_box(), of the bounded convex
     * domain {x : n_i . x <= b_i for every i}, the pairs (n_i, b_i) given in
     * @p half_spaces (the normals n_i of any non-zero length: they are
     * normalised here, b_i with them). The @p n_cells generators are drawn
     * uniformly in the domain's bounding box by a std::mt19937 seeded with
     * @p seed, and those outside the domain are drawn again; then
     * @p lloyd_iterations iterations of Lloyd's algorithm. The Voronoi cell
     * of a generator is the domain's polytope cut by the bisector planes with
     * its Delaunay neighbours.
     *
     * Boundary ids: a boundary face carries the index i of the half-space
     * on whose plane it lies, so at most 255 half-spaces are accepted (the
     * ids 0..254, those dealvem's programs read; deal.II 9.4's
     * types::boundary_id is an unsigned int and would hold more). A
     * redundant half-space, one whose plane touches the domain at most in an
     * edge or a vertex, or lies outside it, is allowed: no face lies on it,
     * and its id appears on no face. Of two half-spaces with the same plane,
     * the faces get the smaller index.
     *
     * The domain is checked before any cell is made, with CGAL's linear
     * programming in exact arithmetic on the normalised half-spaces (so the
     * answer does not depend on a tolerance or on the domain's size): the
     * smallest and largest x, y and z over the domain, which find an empty
     * domain and an unbounded one exactly, and the largest ball inside it.
     * The domain's polytope is then its bounding box, cut by the
     * half-spaces; a side of the bounding box on a half-space's plane
     * normal to an axis is that plane exactly, and a vertex of the mesh on
     * such a plane gets its coordinate exactly (so voronoi_box() makes the
     * same mesh as before it called this function).
     *
     * Tolerances are relative to the diagonal of the domain's bounding box,
     * not to the coordinates: vertices closer than 1e-7 of the diagonal are
     * merged, and a vertex that close to the plane of a half-space is put on
     * it (onto the common edge or corner where it is that close to two or
     * three planes at clear angles). The computation runs in coordinates
     * relative to the lower corner of the bounding box, so that a domain far
     * from the origin gets the same cells, translated, to round-off (a face
     * that the round-off of the larger coordinates warps beyond 1e-13 of
     * their size is split into triangles, as in voronoi_box()). With
     * @p n_cells = 1 the mesh is the domain itself, one cell.
     *
     * Throws ExcMessage, naming the half-space or the problem, for: no
     * half-space or more than 255; a normal or an offset that is not a
     * finite number; a zero normal; an empty domain; an unbounded domain
     * (naming a direction in which it extends without end); a domain
     * without interior or thinner than 1e-6 of its bounding box's diagonal
     * (its largest inscribed ball smaller); a domain filling less than 1e-6
     * of its bounding box (the generators are drawn by rejection: turn it to
     * the axes); @p n_cells = 0. Needs CGAL, as voronoi_box().
     *
     * A tetrahedron with the corners 0, e_x, e_y, e_z, for example, with
     * the boundary ids 0 (x = 0), 1 (y = 0), 2 (z = 0) and 3 (x + y + z = 1):
     * @code
     * using T = dealii::Tensor<1, 3>;
     * PolyhedralMeshGenerators::voronoi_convex(
     *   mesh, {{T({-1, 0, 0}), 0}, {T({0, -1, 0}), 0}, {T({0, 0, -1}), 0}, {T({1, 1, 1}), 1}}, 500);
     * @endcode
     */
    void
    voronoi_convex(PolyhedralMesh                                             &mesh,
                   const std::vector<std::pair<dealii::Tensor<1, 3>, double>> &half_spaces,
                   const unsigned int                                          n_cells,
                   const unsigned int                                          lloyd_iterations = 20,
                   const unsigned int                                          seed             = 0);

    /**
     * The half-spaces (n, b), n . x <= b with |n| = 1, of the facets of the
     * convex hull of @p points, for voronoi_convex(): the hull from CGAL
     * (the boundary of its 3D Delaunay triangulation), its triangles in one
     * plane (an exact test on the input coordinates) joined into one facet.
     * The normal of a facet is the sum of its triangles' area vectors,
     * normalised, and b the largest n . p of its vertices (every point
     * satisfies its half-spaces to round-off). The facets come in an order
     * of CGAL's, the same for the same points: find the boundary id of a
     * facet by its normal in the returned list. The hull of points of a
     * sphere or another curved surface has a facet per triangle:
     * voronoi_convex() takes at most 255.
     *
     * Throws ExcMessage for fewer than four points, coordinates that are
     * not finite numbers, points in one plane; needs CGAL.
     */
    std::vector<std::pair<dealii::Tensor<1, 3>, double>>
    convex_hull_half_spaces(const std::vector<dealii::Point<3>> &points);

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
