// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Cook's membrane at finite strain: the tapered panel (0,0), (48,44),
// (48,60), (0,44), clamped on x = 0, a dead vertical traction of total force
// 100 on x = 48; compressible Neo-Hooke in plane strain, mu = 80.194,
// nu = 0.3 (E = 208.5044), 10 load steps. The vertical displacement of the
// corner (48, 60) on n x n quad meshes (the structured grid of the unit
// square mapped bilinearly onto the panel) is compared with the reference
// of benchmarks/cook_membrane (cook_membrane.cc): deal.II FE_Q(2), QGauss(3),
// the same energy and load steps, on the 4 x 4 ... 128 x 128 meshes
// (132098 DoFs on the finest: 8.698201), extrapolated by Richardson from
// the three finest (32, 64, 128; observed order 1.31): 8.69919. The
// extrapolation moves the 128 x 128 value by 1.1e-4 relative, and the
// extrapolation from 16, 32, 64 gives 8.69910 (1e-5 lower): five digits,
// 8.6992, are converged.
// Checks: k = 2 on 8 x 8 and 16 x 16 quads, k = 1 on 16 x 16 and 32 x 32
// (578 and 2178 DoFs for both): the error decreases under refinement, and
// the tip displacement of the finer mesh is within 0.5 % of the reference
// (measured: k = 2 -1.02 % -> -0.362 %, k = 1 -1.50 % -> -0.471 %; 46-47
// Newton updates per solve; about 6 s in Release).
#include <deal.II/base/function.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/finite_strain_solver.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
  const double reference = 8.69919;

  dealii::Point<2>
  panel_point(const dealii::Point<2> &p)
  {
    return dealii::Point<2>(48. * p[0], 44. * p[0] + p[1] * (44. - 28. * p[0]));
  }

  // the tip displacement u_y(48, 60) of the n x n mesh, order k
  double
  tip_displacement(const unsigned int n, const unsigned int k, unsigned int &n_dofs, unsigned int &updates)
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {n, n}, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1),
                                                      true);
    dealii::GridTools::transform(panel_point, tria);
    for (auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::from_triangulation(mesh, tria);
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(k);

    const NeoHookeMaterial           law(2. * 80.194 * 1.3, 0.3);
    FiniteStrainAssembler<2>         assembler(dof_handler, testing::one_law_library(dof_handler, law));
    dealii::Tensor<1, 2> t;
    t[1] = 100. / 16.; // total force 100 on the edge of length 16
    const testing::ConstantTraction traction(t);
    assembler.add_traction(1, traction);
    dealii::AffineConstraints<double> constraints;
    testing::dirichlet_constraints(dof_handler, {0}, dealii::Functions::ZeroFunction<2>(2), constraints);
    FiniteStrainSolver<2>::Parameters parameters;
    parameters.n_load_steps = 10;
    FiniteStrainSolver<2> solver(assembler, constraints, parameters);
    solver.run();

    updates = 0;
    for (const auto &s : solver.get_history())
      updates += s.iterations.size() - 1;
    n_dofs = dof_handler.n_dofs();
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      if (mesh.vertex(v).distance(dealii::Point<2>(48, 60)) < 1e-10)
        return solver.get_solution()(VEMDoFHandler<2>::node_dof(dof_handler.vertex_node(v), 1));
    AssertThrow(false, dealii::ExcMessage("no vertex at (48, 60)"));
    return 0;
  }
} // namespace

int
main()
{
  std::cout << "reference tip u_y (FE_Q(2), extrapolated) = " << std::setprecision(8) << reference << std::endl;
  for (const unsigned int k : {1u, 2u})
    {
      std::vector<double> errors;
      for (const unsigned int n : (k == 1 ? std::vector<unsigned int>{16, 32} : std::vector<unsigned int>{8, 16}))
        {
          unsigned int n_dofs = 0, updates = 0;
          const double tip   = tip_displacement(n, k, n_dofs, updates);
          const double error = (tip - reference) / reference;
          errors.push_back(std::abs(error));
          // Newton updates are printed for the reader (not part of any check)
          std::cout << "k = " << k << ", " << n << " x " << n << " quads, " << n_dofs << " DoFs: tip u_y = "
                    << std::setprecision(6) << tip << ", relative error " << std::scientific << std::setprecision(2)
                    << error << std::defaultfloat << " (" << updates << " Newton updates)" << std::endl;
        }
      testing::check(errors[1] < errors[0],
                     "k = " + std::to_string(k) + ": the error decreases under refinement (" +
                       std::to_string(errors[0]) + " -> " + std::to_string(errors[1]) + ")");
      testing::check(errors[1] <= 5e-3, "k = " + std::to_string(k) +
                                           ", finer mesh: the tip displacement within 0.5 % of the reference (" +
                                           std::to_string(errors[1]) + ")");
    }
  return testing::finish();
}
