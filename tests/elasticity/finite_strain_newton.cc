// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Newton's method on a non-homogeneous finite-strain problem: the unit
// square (Voronoi, 64 cells) clamped on the left side, under a downward
// body force b = 0.04 E per unit reference area and a downward nominal
// traction 0.02 E on the right side, in 4 load steps (Neo-Hooke and Saint
// Venant-Kirchhoff, E = 1, nu = 0.3, k = 1 and 2). The block sags by more
// than 20 % of its size (checked: max |u| > 0.2). The Newton histories are
// printed.
// Quadratic convergence: in every load step, for each pair of successive
// relative residuals e_i = |r_i| / F_ref, e_{i+1} with 1e-12 < e_{i+1}
// (above round-off) and e_i < 1e-2 (inside the region of quadratic
// convergence), the ratio e_{i+1} / e_i^2 must be below 100 (measured:
// at most 2.2; a linearly converging iteration with rate 0.1 would give
// e_{i+1} / e_i^2 = 0.1 / e_i > 1e3 once e_i < 1e-4). The order estimate
// log(e_{i+1}/e_i) / log(e_i/e_{i-1}) of the last triple above round-off is
// printed, not checked: from one triple it is noisy (1.4 to 2.0 here).
// Every step must converge within 12 Newton updates.
#include <cmath>
#include <iostream>

#include "../elasticity_common.h"
#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;

int
main()
{
  const double E = 1., nu = 0.3;
  PolygonalMesh<2> mesh;
  testing::make_mesh(mesh, "voronoi", 1);
  dealii::Tensor<1, 2> b, t;
  b[1] = -0.04 * E;
  t[1] = -0.02 * E;
  const testing::ConstantTraction body_force(b), traction(t);
  const testing::HomogeneousDeformation zero(dealii::Tensor<2, 2>(dealii::unit_symmetric_tensor<2>()));

  const NeoHookeMaterial             neo_hooke(E, nu);
  const SaintVenantKirchhoffMaterial svk(E, nu);
  for (const unsigned int k : {1u, 2u})
    for (const HyperelasticMaterial *law :
         {static_cast<const HyperelasticMaterial *>(&neo_hooke), static_cast<const HyperelasticMaterial *>(&svk)})
      {
        const std::string name = "k = " + std::to_string(k) + ", " + law->get_name().substr(0, law->get_name().find(" ("));
        std::cout << "--- " << name << std::endl;
        VEMDoFHandler<2> dof_handler(mesh);
        dof_handler.distribute_dofs(k);
        FiniteStrainAssembler<2> assembler(dof_handler, testing::one_law_library(dof_handler, *law));
        assembler.set_body_force(body_force);
        assembler.add_traction(1, traction);
        dealii::AffineConstraints<double> constraints;
        testing::dirichlet_constraints(dof_handler, {0}, zero, constraints);
        FiniteStrainSolver<2>::Parameters parameters;
        parameters.n_load_steps = 4;
        FiniteStrainSolver<2> solver(assembler, constraints, parameters);
        solver.run();
        solver.print_history(std::cout);
        testing::check(solver.get_history().size() == 4 && solver.get_history().back().converged,
                       name + ": all load steps converged");
        testing::check(solver.get_solution().linfty_norm() > 0.2,
                       name + ": a large deformation, max |u_i| = " + std::to_string(solver.get_solution().linfty_norm()));
        double       worst_ratio = 0;
        unsigned int n_pairs = 0, max_updates = 0;
        double       last_order = -1;
        for (const auto &step : solver.get_history())
          {
            const auto &its = step.iterations;
            max_updates     = std::max<unsigned int>(max_updates, its.size() - 1);
            for (unsigned int i = 0; i + 1 < its.size(); ++i)
              {
                const double e0 = its[i].relative_residual, e1 = its[i + 1].relative_residual;
                if (e1 > 1e-12 && e0 < 1e-2)
                  {
                    worst_ratio = std::max(worst_ratio, e1 / (e0 * e0));
                    ++n_pairs;
                  }
                if (i >= 1 && e1 > 1e-12 && its[i - 1].relative_residual < 1e-1)
                  last_order = std::log(e1 / e0) / std::log(e0 / its[i - 1].relative_residual);
              }
          }
        std::cout << "  " << n_pairs << " pairs in the quadratic region; largest e_{i+1}/e_i^2 = " << worst_ratio
                  << "; last order estimate = " << last_order << std::endl;
        testing::check(n_pairs >= 2, name + ": at least two pairs of iterates to judge the rate");
        testing::check_small(worst_ratio, 100., name + ": largest e_{i+1} / e_i^2");
        testing::check(max_updates <= 12, name + ": at most 12 Newton updates per step");
      }
  return testing::finish();
}
