// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// PolygonalMeshGenerators::from_triangulation on locally refined deal.II
// meshes whose hanging vertices the manifolds put off the chord of the coarse
// face (TransfiniteInterpolationManifold, SphericalManifold), and on meshes
// where they lie on it (flat interior, anisotropic refinement):
// - the old conversion (each cell's own vertices, hanging vertices left to
//   PolygonalMesh::finalize(), which finds them on straight edges only) is
//   wrong on every curved mesh: rejected ("overlapping cells") where a
//   hanging vertex bulges into the coarse cell, a mesh with holes (more
//   boundary edges than the triangulation has boundary faces) where it
//   bulges the other way: these meshes are the ones the face walk is for;
// - one polygon per active cell, counter-clockwise, with the cell's
//   vertices plus the hanging vertices of its refined faces in order; its
//   area is the cell's (straight-sided) measure plus the signed triangles
//   (a, m, b) that each hanging vertex m adds to the coarse face (a, b),
//   to round-off;
// - the polygons tile the domain: their areas sum to the area enclosed by
//   the triangulation's active boundary faces (shoelace), every interior
//   edge has two polygons, the boundary edges are the active boundary faces
//   with their boundary ids, and every hanging vertex is a vertex of exactly
//   three polygons (the coarse cell and the two fine cells beside it);
// - material ids are kept, the TriangulationMap maps cells to polygons;
// - VEM patch tests on each mesh (k = 1 and 2): a linear displacement with
//   Dirichlet data on the whole boundary, and for k = 2 a quadratic one
//   with its body force, are reproduced to round-off (1e-10 relative);
// - FETransfer on these meshes: the discontinuous transfer of the patch
//   solution into FE_DGQ(k)^2 on the triangulation is the exact field at
//   every support point (1e-10 relative), the continuous one is refused
//   with a message (a VEM trace with a hanging vertex is no FE_Q trace).
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>

#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/triangulation_map.h>
#include <dealvem/postprocessing/fe_transfer.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/virtual_element.h>

#include "../tests.h"

#include <functional>
#include <map>
#include <set>

using namespace dealvem;
using dealii::Point;
using Tria = dealii::Triangulation<2>;

namespace
{
  double
  cross(const Point<2> &a, const Point<2> &b, const Point<2> &c)
  {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }

  double
  polygon_area(const PolygonalMesh<2> &mesh, const unsigned int c)
  {
    const auto &loop = mesh.cell(c).vertices;
    double      a    = 0;
    for (unsigned int i = 0; i < loop.size(); ++i)
      {
        const auto &p = mesh.vertex(loop[i]), &q = mesh.vertex(loop[(i + 1) % loop.size()]);
        a += p[0] * q[1] - q[0] * p[1];
      }
    return 0.5 * a;
  }

  // Refine the active cells with a vertex within @p d of the curve given by
  // the distance function, @p cycles times, the distance halved each time.
  void
  refine_near(Tria &tria, const std::function<double(const Point<2> &)> &distance, double d,
              const unsigned int cycles,
              const dealii::RefinementCase<2> how = dealii::RefinementCase<2>::isotropic_refinement)
  {
    for (unsigned int c = 0; c < cycles; ++c, d /= 2)
      {
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            if (distance(cell->vertex(v)) < d)
              {
                cell->set_refine_flag(how);
                break;
              }
        tria.execute_coarsening_and_refinement();
      }
  }

  // The old conversion: each cell's own vertices, nothing else; finalize()
  // then inserts only the hanging vertices that lie on a straight edge.
  void
  convert_cell_vertices_only(PolygonalMesh<2> &mesh, const Tria &tria)
  {
    mesh.clear();
    for (const auto &v : tria.get_vertices())
      mesh.add_vertex(v);
    for (const auto &cell : tria.active_cell_iterators())
      mesh.add_cell({cell->vertex_index(0), cell->vertex_index(1), cell->vertex_index(3), cell->vertex_index(2)},
                    cell->material_id());
    mesh.finalize();
  }

  // u = (1e-3 + 2e-3 x - 1e-3 y + q(3x^2 - xy + 2y^2), -2e-3 + 1.5e-3 x + 0.5e-3 y + q(x^2 + 4xy - y^2))
  class Field : public dealii::Function<2>
  {
  public:
    explicit Field(const double q)
      : dealii::Function<2>(2)
      , q(q)
    {}
    double
    value(const Point<2> &p, const unsigned int c) const override
    {
      const double x = p[0], y = p[1];
      if (c == 0)
        return 1e-3 + 2e-3 * x - 1e-3 * y + q * (3 * x * x - x * y + 2 * y * y);
      return -2e-3 + 1.5e-3 * x + 0.5e-3 * y + q * (x * x + 4 * x * y - y * y);
    }
    double q;
  };

  // f = -div sigma(u) for the field above: -[(lambda + mu) grad div u + mu Laplace u]
  class BodyForce : public dealii::Function<2>
  {
  public:
    BodyForce(const double q, const ElasticMaterial &m)
      : dealii::Function<2>(2)
      , q(q)
      , l(m.lambda())
      , mu(m.mu())
    {}
    double
    value(const Point<2> &, const unsigned int c) const override
    {
      const double grad_div[2] = {10 * q, -3 * q};
      const double lap[2]      = {10 * q, 0.};
      return -((l + mu) * grad_div[c] + mu * lap[c]);
    }
    double q, l, mu;
  };

  // Dirichlet data u on every boundary part; the largest DoF error relative
  // to the largest |DoF|. With @p map, also the transfers to finite element
  // fields on the triangulation (see the top of the file).
  double
  patch_test(const PolygonalMesh<2> &mesh, const unsigned int k, const double q,
             const TriangulationMap<2> *map = nullptr, const std::string &name = "")
  {
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(k);
    const ElasticMaterial             material(7000, 0.3, ElasticMaterial::Model::plane_strain);
    const Field                       u(q);
    const BodyForce                   f(q, material);
    dealii::AffineConstraints<double> constraints;
    const auto                        ids = mesh.get_boundary_ids();
    BoundaryConditions::interpolate_boundary_values(dof_handler, std::set<dealii::types::boundary_id>(ids.begin(), ids.end()),
                                                    u, {{true, true}}, constraints);
    constraints.close();
    dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
    dof_handler.make_sparsity_pattern(dsp, constraints);
    dealii::SparsityPattern sp;
    sp.copy_from(dsp);
    dealii::SparseMatrix<double> A(sp);
    dealii::Vector<double>       b, x(dof_handler.n_dofs());
    std::map<dealii::types::material_id, ElasticMaterial> materials;
    for (const auto id : mesh.get_material_ids())
      materials.emplace(id, material);
    ElasticityAssembler<2> assembler(dof_handler, materials, 1.0);
    if (q != 0)
      assembler.set_body_force(f);
    assembler.assemble(constraints, A, b);
    dealii::SparseDirectUMFPACK solver;
    solver.initialize(A);
    solver.vmult(x, b);
    constraints.distribute(x);

    double                                       err = 0, umax = 0;
    VirtualElement<2>                            element(k);
    std::vector<dealii::types::global_dof_index> indices;
    dealii::Vector<double>                       exact;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        element.reinit(mesh.cell_vertices(c));
        element.interpolate(u, exact);
        dof_handler.get_dof_indices(c, indices);
        for (unsigned int i = 0; i < indices.size(); ++i)
          {
            err  = std::max(err, std::abs(x[indices[i]] - exact[i]));
            umax = std::max(umax, std::abs(exact[i]));
          }
      }

    if (map)
      {
        const auto                    &tria = map->get_triangulation();
        const dealii::FESystem<2>      fe_dg(dealii::FE_DGQ<2>(k), 2);
        dealii::DoFHandler<2>          dg(tria);
        dg.distribute_dofs(fe_dg);
        dealii::Vector<double> field;
        FETransfer::interpolate_to_discontinuous(*map, dof_handler, x, dg, field);
        const dealii::Quadrature<2> support(fe_dg.get_unit_support_points());
        const dealii::MappingQ1<2>  mapping;
        dealii::FEValues<2>         values(mapping, fe_dg, support, dealii::update_quadrature_points);
        std::vector<dealii::types::global_dof_index> dg_indices(fe_dg.n_dofs_per_cell());
        double                                       transfer_err = 0;
        for (const auto &cell : dg.active_cell_iterators())
          {
            values.reinit(cell);
            cell->get_dof_indices(dg_indices);
            for (unsigned int i = 0; i < dg_indices.size(); ++i)
              transfer_err = std::max(transfer_err, std::abs(field[dg_indices[i]] -
                                                             u.value(values.quadrature_point(i),
                                                                     fe_dg.system_to_component_index(i).first)));
          }
        testing::check_small(transfer_err / umax, 1e-10,
                             name + ", k = " + std::to_string(k) +
                               ": FETransfer::interpolate_to_discontinuous of the patch solution, max error / max |u|");
        const dealii::FESystem<2> fe_q(dealii::FE_Q<2>(k), 2);
        dealii::DoFHandler<2>     cg(tria);
        cg.distribute_dofs(fe_q);
        testing::check_throws([&] { FETransfer::interpolate_to_continuous(*map, dof_handler, x, cg, field); },
                              "the triangulation has hanging nodes",
                              name + ", k = " + std::to_string(k) + ": FETransfer::interpolate_to_continuous refuses");
      }
    return err / umax;
  }

  // All checks on one triangulation. @p curved: its hanging vertices are off
  // the chords, and the old conversion must fail.
  void
  check_mesh(const std::string &name, const Tria &tria, const bool curved)
  {
    std::cout << "--- " << name << ": " << tria.n_active_cells() << " active cells, " << tria.n_levels()
              << " levels" << std::endl;
    testing::check(tria.has_hanging_nodes(), name + ": the triangulation has hanging nodes");

    // the old conversion: where a hanging vertex bulges into the coarse
    // cell, the fine cells overlap it and finalize() throws; where it bulges
    // the other way, the mesh is accepted with a sliver-shaped hole, which
    // shows as boundary edges inside the domain
    if (curved)
      {
        unsigned int n_boundary_faces = 0;
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            n_boundary_faces += cell->face(f)->at_boundary() ? 1 : 0;
        std::string outcome;
        try
          {
            PolygonalMesh<2> old_mesh;
            convert_cell_vertices_only(old_mesh, tria);
            unsigned int n_boundary_edges = 0;
            for (unsigned int e = 0; e < old_mesh.n_edges(); ++e)
              n_boundary_edges += old_mesh.edge(e).at_boundary() ? 1 : 0;
            if (n_boundary_edges > n_boundary_faces)
              outcome = "accepted with holes (" + std::to_string(n_boundary_edges) + " boundary edges for " +
                        std::to_string(n_boundary_faces) + " boundary faces)";
          }
        catch (const std::exception &e)
          {
            if (std::string(e.what()).find("overlapping cells") != std::string::npos)
              outcome = "rejected (overlapping cells)";
          }
        testing::check(!outcome.empty(), name + ": the conversion from the cells' own vertices is wrong: " +
                                            (outcome.empty() ? std::string("no") : outcome));
      }

    PolygonalMesh<2>    mesh;
    TriangulationMap<2> map;
    try
      {
        PolygonalMeshGenerators::from_triangulation(mesh, tria, map);
      }
    catch (const std::exception &e)
      {
        testing::check(false, name + ": from_triangulation throws: " + testing::collapse_white_space(e.what()));
        return;
      }
    testing::check(mesh.n_cells() == tria.n_active_cells(),
                   name + ": " + std::to_string(mesh.n_cells()) + " polygons for " +
                     std::to_string(tria.n_active_cells()) + " active cells");

    // the hanging vertices: the shared vertex of the children of a face of
    // an active cell; each with the coarse cell's polygon, and the largest
    // distance from the chord relative to the chord's length
    std::map<unsigned int, unsigned int> coarse_polygon_of_hanging;
    double                               off_chord = 0;
    double                               worst_area = 0, worst_ccw = 1e300;
    bool                                 loops_ok = true;
    double                               total_area = 0, total_measure = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        const unsigned int p    = map.polygon_of(cell);
        const auto        &loop = mesh.cell(p).vertices;
        const double       A    = polygon_area(mesh, p);
        worst_ccw               = std::min(worst_ccw, A);
        total_area += A;
        total_measure += cell->measure();
        // the expected area: the straight cell and a signed triangle per
        // hanging vertex, oriented along the cell's counter-clockwise boundary
        double             expected   = cell->measure();
        unsigned int       n_expected = cell->n_vertices();
        const unsigned int corner[4]  = {0, 1, 3, 2};
        for (unsigned int i = 0; i < 4; ++i)
          {
            const unsigned int a = cell->vertex_index(corner[i]), b = cell->vertex_index(corner[(i + 1) % 4]);
            for (const unsigned int f : cell->face_indices())
              {
                const auto face = cell->face(f);
                if (!face->has_children() ||
                    !((face->vertex_index(0) == a && face->vertex_index(1) == b) ||
                      (face->vertex_index(0) == b && face->vertex_index(1) == a)))
                  continue;
                const unsigned int m = face->child(0)->vertex_index(1);
                const Point<2>    &pa = tria.get_vertices()[a], &pb = tria.get_vertices()[b],
                               &pm = tria.get_vertices()[m];
                expected += 0.5 * cross(pa, pm, pb);
                off_chord = std::max(off_chord, std::abs(cross(pa, pb, pm)) / pa.distance_square(pb));
                ++n_expected;
                coarse_polygon_of_hanging[m] = p;
                // in the loop between a and b
                const auto ia = std::find(loop.begin(), loop.end(), map.mesh_vertex(a)) - loop.begin();
                loops_ok      = loops_ok && loop[(ia + 1) % loop.size()] == map.mesh_vertex(m) &&
                           loop[(ia + 2) % loop.size()] == map.mesh_vertex(b);
              }
          }
        loops_ok   = loops_ok && loop.size() == n_expected;
        worst_area = std::max(worst_area, std::abs(A - expected) / cell->measure());
      }
    testing::check(loops_ok, name + ": every polygon is its cell's vertices with the hanging vertices of its "
                                    "refined faces in between, in order");
    testing::check(worst_ccw > 0, name + ": every polygon is counter-clockwise (smallest area " +
                                    std::to_string(worst_ccw) + ")");
    testing::check_small(worst_area, 1e-13,
                         name + ": |polygon area - (cell measure + hanging triangles)| / cell measure");
    testing::check(!coarse_polygon_of_hanging.empty(),
                   name + ": " + std::to_string(coarse_polygon_of_hanging.size()) + " hanging vertices");
    if (curved)
      testing::check(off_chord > 1e-4, name + ": hanging vertices lie off the chord (largest offset / chord " +
                                         std::to_string(off_chord) + ")");
    else
      testing::check_small(off_chord, 1e-14, name + ": hanging vertices on the chord (offset / chord)");

    // the area enclosed by the active boundary faces, oriented along their
    // cells' counter-clockwise boundaries
    double                                                         boundary_area = 0;
    std::map<std::pair<unsigned int, unsigned int>, unsigned int>  boundary_face_id;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const auto    face = cell->face(f);
            const Point<2> c    = cell->center();
            Point<2>       a = face->vertex(0), b = face->vertex(1);
            if (cross(a, b, c) < 0)
              std::swap(a, b);
            boundary_area += 0.5 * (a[0] * b[1] - b[0] * a[1]);
            const unsigned int va = map.mesh_vertex(face->vertex_index(0)), vb = map.mesh_vertex(face->vertex_index(1));
            boundary_face_id[{std::min(va, vb), std::max(va, vb)}] = face->boundary_id();
          }
    testing::check_small(std::abs(total_area - boundary_area) / boundary_area, 1e-13,
                         name + ": sum of polygon areas vs the area enclosed by the boundary faces (relative)");
    std::cout << "      (polygon areas " << std::setprecision(15) << total_area << ", straight cells "
              << total_measure << ")" << std::endl;

    // edges: an edge with one polygon must be an active boundary face (with
    // its id), so no gap inside the mesh; the others have two polygons
    unsigned int n_boundary = 0, wrong_id = 0, not_a_face = 0;
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      if (mesh.edge(e).at_boundary())
        {
          ++n_boundary;
          const auto &v  = mesh.edge(e).vertices;
          const auto  it = boundary_face_id.find({std::min(v[0], v[1]), std::max(v[0], v[1])});
          if (it == boundary_face_id.end())
            ++not_a_face;
          else if (it->second != mesh.edge(e).boundary_id)
            ++wrong_id;
        }
    testing::check(n_boundary == boundary_face_id.size() && not_a_face == 0 && wrong_id == 0,
                   name + ": the " + std::to_string(n_boundary) + " boundary edges are the " +
                     std::to_string(boundary_face_id.size()) + " active boundary faces with their boundary ids (" +
                     std::to_string(not_a_face) + " others, " + std::to_string(wrong_id) + " wrong ids)");

    // every hanging vertex: three polygons, one of them the coarse cell's
    std::vector<std::vector<unsigned int>> polygons_of_vertex(mesh.n_vertices());
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      for (const auto v : mesh.cell(c).vertices)
        polygons_of_vertex[v].push_back(c);
    unsigned int bad_hanging = 0;
    for (const auto &[m, coarse] : coarse_polygon_of_hanging)
      {
        const auto &users = polygons_of_vertex[map.mesh_vertex(m)];
        if (users.size() != 3 || std::find(users.begin(), users.end(), coarse) == users.end())
          ++bad_hanging;
      }
    testing::check(bad_hanging == 0, name + ": every hanging vertex is a vertex of exactly three polygons, "
                                            "the coarse one among them (" +
                                       std::to_string(bad_hanging) + " not)");

    for (const unsigned int k : {1u, 2u})
      {
        testing::check_small(patch_test(mesh, k, 0., &map, name), 1e-10,
                             name + ", k = " + std::to_string(k) + ": linear patch test, max DoF error / max |u|");
        if (k == 2)
          testing::check_small(patch_test(mesh, k, 1e-3), 1e-10,
                               name + ", k = 2: quadratic patch test with body force, max DoF error / max |u|");
      }
  }
} // namespace

int
main()
{
  // a plate with a hole (PolarManifold on the hole, TFI around it), refined
  // three times toward the hole: TFI puts the hanging vertices between the
  // ring layers off the chords
  {
    Tria tria;
    dealii::GridGenerator::plate_with_a_hole(tria, 0.4, 1., 2., 2., 1., 1., Point<2>(), 0, 1, 1., 2, true);
    for (const auto &cell : tria.active_cell_iterators()) // colorize also numbers the cells
      cell->set_material_id(0);
    tria.refine_global(1);
    refine_near(tria, [](const Point<2> &p) { return std::abs(p.norm() - 0.4); }, 0.3, 3);
    check_mesh("plate_with_a_hole, 3 local refinements", tria, true);
  }
  // the same with material id 7 everywhere: ids are kept
  {
    Tria tria;
    dealii::GridGenerator::plate_with_a_hole(tria);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(7);
    refine_near(tria, [](const Point<2> &p) { return std::abs(p.norm() - 0.4); }, 0.2, 2);
    PolygonalMesh<2> mesh;
    try
      {
        PolygonalMeshGenerators::from_triangulation(mesh, tria);
        testing::check(mesh.get_material_ids() == std::vector<dealii::types::material_id>{7},
                       "plate_with_a_hole with material id 7: every polygon has id 7");
      }
    catch (const std::exception &e)
      {
        testing::check(false, "plate_with_a_hole with material id 7: from_triangulation throws");
      }
  }
  // a square with a cylindrical hole (PolarManifold on the hole only, the
  // interior flat), refined toward the hole: hanging vertices on the chords
  {
    Tria tria;
    dealii::GridGenerator::hyper_cube_with_cylindrical_hole(tria, 0.25, 0.5, 0.5, 1, true);
    tria.refine_global(1);
    refine_near(tria, [](const Point<2> &p) { return std::abs(p.norm() - 0.25); }, 0.15, 3);
    check_mesh("hyper_cube_with_cylindrical_hole, 3 local refinements", tria, false);
  }
  // a disk (SphericalManifold on the boundary cells, TFI inside), refined toward
  // the circle
  {
    Tria tria;
    dealii::GridGenerator::hyper_ball(tria, Point<2>(0.3, -0.2), 2., true);
    tria.refine_global(1);
    refine_near(tria, [](const Point<2> &p) { return std::abs(p.distance(Point<2>(0.3, -0.2)) - 2.); }, 0.6, 3);
    check_mesh("hyper_ball, 3 local refinements", tria, true);
  }
  // a quarter shell (SphericalManifold on every cell and face), refined
  // toward the inner circle
  {
    Tria tria;
    dealii::GridGenerator::quarter_hyper_shell(tria, Point<2>(), 1., 2., 3, true);
    refine_near(tria, [](const Point<2> &p) { return std::abs(p.norm() - 1.); }, 0.4, 3);
    check_mesh("quarter_hyper_shell, 3 local refinements", tria, true);
  }
  // the quarter shell refined anisotropically (cells cut in their first
  // direction only) toward the inner circle: hanging vertices on the
  // circular faces of the neighbours
  {
    Tria tria;
    dealii::GridGenerator::quarter_hyper_shell(tria, Point<2>(), 1., 2., 3, true);
    tria.refine_global(1);
    refine_near(tria, [](const Point<2> &p) { return std::abs(p.norm() - 1.); }, 0.3, 2,
                dealii::RefinementCase<2>::cut_x);
    check_mesh("quarter_hyper_shell, 2 anisotropic (cut_x) refinements", tria, true);
  }
  // two levels in all: a plate with a hole whose cells at the hole are
  // refined twice, the rest not at all
  {
    Tria tria;
    dealii::GridGenerator::plate_with_a_hole(tria);
    refine_near(tria, [](const Point<2> &p) { return std::abs(p.norm() - 0.4); }, 0.05, 2);
    check_mesh("plate_with_a_hole, refined twice at the hole only", tria, true);
  }
  return testing::finish();
}
