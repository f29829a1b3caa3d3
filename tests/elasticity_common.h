// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Shared pieces of the elasticity tests: the mesh families and a solve with
// Dirichlet data on the whole boundary.
#ifndef dealvem_tests_elasticity_common_h
#define dealvem_tests_elasticity_common_h

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace testing
{
  /// The mesh families of the tests on the unit square, at refinement
  /// level @p level (0 = coarsest).
  inline std::vector<std::string>
  mesh_families()
  {
    return {"structured quads", "structured triangles", "perturbed quads", "voronoi",
            "nonconvex", "hanging nodes"};
  }

  inline void
  make_mesh(dealvem::PolygonalMesh<2> &mesh, const std::string &family, const unsigned int level)
  {
    namespace G            = dealvem::PolygonalMeshGenerators;
    const dealii::Point<2> p0(0, 0), p1(1, 1);
    const unsigned int     n = 4u << level;
    if (family == "structured quads")
      G::structured_quads(mesh, p0, p1, n, n);
    else if (family == "structured triangles")
      G::structured_triangles(mesh, p0, p1, n, n);
    else if (family == "perturbed quads")
      G::perturbed_quads(mesh, p0, p1, n, n, 0.25, 7 + level);
    else if (family == "voronoi")
      G::voronoi(mesh, p0, p1, n * n, 30, 3 + level);
    else if (family == "nonconvex")
      G::nonconvex(mesh, p0, p1, n, n, 0.3);
    else if (family == "hanging nodes")
      {
        // a deal.II mesh refined in one corner: coarse cells next to refined
        // ones become pentagons with a collinear vertex
        dealii::Triangulation<2> tria;
        dealii::GridGenerator::hyper_cube(tria, 0, 1, true);
        tria.refine_global(2 + level);
        for (auto &cell : tria.active_cell_iterators())
          if (cell->center()[0] < 0.5 && cell->center()[1] < 0.5)
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
        G::from_triangulation(mesh, tria);
      }
    else
      AssertThrow(false, dealii::ExcMessage("unknown mesh family " + family));
  }

  /**
   * Solve with Dirichlet data g on all four sides (ids 0..3), body force f
   * (may be null), by UMFPACK. Returns the solution (constraints
   * distributed).
   */
  inline dealii::Vector<double>
  solve_dirichlet_problem(const dealvem::VEMDoFHandler<2>     &dof_handler,
                          const dealvem::ElasticMaterial      &material,
                          const dealii::Function<2>           &g,
                          const dealii::Function<2>           *f,
                          const double                         gamma = 1.0)
  {
    dealii::AffineConstraints<double> constraints;
    dealvem::BoundaryConditions::interpolate_boundary_values(
      dof_handler, {0, 1, 2, 3}, g, {{true, true}}, constraints);
    constraints.close();
    dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
    dof_handler.make_sparsity_pattern(dsp, constraints);
    dealii::SparsityPattern sp;
    sp.copy_from(dsp);
    dealii::SparseMatrix<double> A(sp);
    dealii::Vector<double>       b, x(dof_handler.n_dofs());
    std::map<dealii::types::material_id, dealvem::ElasticMaterial> materials;
    for (const auto id : dof_handler.get_mesh().get_material_ids())
      materials.emplace(id, material);
    dealvem::ElasticityAssembler<2> assembler(dof_handler, materials, gamma);
    if (f)
      assembler.set_body_force(*f);
    assembler.assemble(constraints, A, b);
    dealii::SparseDirectUMFPACK solver;
    solver.initialize(A);
    solver.vmult(x, b);
    constraints.distribute(x);
    return x;
  }

  /**
   * The linear patch test on @p mesh at order @p k: the linear field
   * 1e-3 (0.3 + 2x - 0.7y, -0.2 + 0.4x + 1.1y) as Dirichlet data on the
   * boundary ids 0 to 3 (the whole boundary of the meshes that call it),
   * plane strain, UMFPACK. Returns the largest vertex error over the
   * largest vertex value, round-off when the element passes.
   */
  inline double
  linear_patch_test_error(const dealvem::PolygonalMesh<2> &mesh, const unsigned int k)
  {
    class Linear : public dealii::Function<2>
    {
    public:
      Linear()
        : dealii::Function<2>(2)
      {}
      double
      value(const dealii::Point<2> &p, const unsigned int c) const override
      {
        return c == 0 ? 1e-3 * (0.3 + 2 * p[0] - 0.7 * p[1]) : 1e-3 * (-0.2 + 0.4 * p[0] + 1.1 * p[1]);
      }
    };
    dealvem::VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(k);
    const dealvem::ElasticMaterial material(200e3, 0.3, dealvem::ElasticMaterial::Model::plane_strain);
    const Linear                   exact;
    const auto                     x   = solve_dirichlet_problem(dof_handler, material, exact, nullptr);
    double                         err = 0, size = 0;
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      for (unsigned int c = 0; c < 2; ++c)
        {
          err  = std::max(err, std::abs(x[2 * v + c] - exact.value(mesh.vertex(v), c)));
          size = std::max(size, std::abs(exact.value(mesh.vertex(v), c)));
        }
    return err / size;
  }
} // namespace testing

#endif
