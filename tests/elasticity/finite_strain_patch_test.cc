// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The finite-strain patch test: the homogeneous deformation
// u = (F - I) X + c with the non-symmetric F = [[1.1, 0.3], [0.05, 0.7]]
// (30 % compression in y, 10 % stretch in x, shear; J = 0.755), on Voronoi,
// non-convex and hanging-node meshes of the unit square, k = 1 and 2,
// Neo-Hooke and Saint Venant-Kirchhoff (E = 7000, nu = 0.3, plane strain),
// (a) Dirichlet data on the whole boundary, in 4 load steps (the
//     intermediate states lambda (F - I) X are homogeneous too);
// (b) Dirichlet data on the left, bottom and top sides (ids 0, 2, 3) and
//     the matching nominal traction P(F) N on the right side (id 1) as a
//     dead load, in 4 load steps (the states at lambda < 1, displacement
//     lambda (F - I) X on three sides and traction lambda P(F) N on the
//     fourth, are not homogeneous; the last one is). (With Dirichlet data on
//     two sides and the traction on the other two, the path of these
//     intermediate states folds near lambda = 0.7 for this F: Newton fails
//     there with 4, 8 and 16 steps, k = 1.)
// Every DoF (vertices, midpoints, cell moments) must equal the exact value
// to 1e-10 of the largest displacement, and every step must converge.
#include <iostream>

#include "../elasticity_common.h"
#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;

int
main()
{
  const double         E = 7000., nu = 0.3;
  dealii::Tensor<2, 2> F;
  F[0][0] = 1.1;
  F[0][1] = 0.3;
  F[1][0] = 0.05;
  F[1][1] = 0.7;
  dealii::Tensor<1, 2> c;
  c[0] = 0.02;
  c[1] = -0.01;
  const testing::HomogeneousDeformation exact(F, c);

  const NeoHookeMaterial             neo_hooke(E, nu);
  const SaintVenantKirchhoffMaterial svk(E, nu);
  for (const std::string family : {"voronoi", "nonconvex", "hanging nodes"})
    {
      PolygonalMesh<2> mesh;
      testing::make_mesh(mesh, family, 0);
      for (const unsigned int k : {1u, 2u})
        {
          VEMDoFHandler<2> dof_handler(mesh);
          dof_handler.distribute_dofs(k);
          std::vector<dealii::Point<2>> support;
          dof_handler.map_dofs_to_support_points(support);
          double u_max = 0;
          for (const auto &p : support)
            u_max = std::max(u_max, std::hypot(exact.value(p, 0), exact.value(p, 1)));
          for (const HyperelasticMaterial *law : {static_cast<const HyperelasticMaterial *>(&neo_hooke),
                                                  static_cast<const HyperelasticMaterial *>(&svk)})
            {
              const dealii::Tensor<2, 2> P = law->first_piola_kirchhoff_stress(F);
              dealii::Tensor<1, 2>       t_right, t_top; // P N with N = e_x, e_y
              for (unsigned int i = 0; i < 2; ++i)
                {
                  t_right[i] = P[i][0];
                  t_top[i]   = P[i][1];
                }
              const testing::ConstantTraction traction_right(t_right), traction_top(t_top);
              for (const bool with_traction : {false, true})
                {
                  FiniteStrainAssembler<2> assembler(dof_handler, testing::one_law_library(dof_handler, *law));
                  dealii::AffineConstraints<double> constraints;
                  if (with_traction)
                    {
                      testing::dirichlet_constraints(dof_handler, {0, 2, 3}, exact, constraints);
                      assembler.add_traction(1, traction_right);
                    }
                  else
                    testing::dirichlet_constraints(dof_handler, {0, 1, 2, 3}, exact, constraints);
                  FiniteStrainSolver<2>::Parameters parameters;
                  parameters.n_load_steps = 4;
                  FiniteStrainSolver<2> solver(assembler, constraints, parameters);
                  solver.run();
                  bool converged = solver.get_history().size() == parameters.n_load_steps;
                  for (const auto &s : solver.get_history())
                    converged = converged && s.converged;
                  const dealii::Vector<double> &u   = solver.get_solution();
                  double                        err = 0;
                  for (unsigned int i = 0; i < u.size(); ++i)
                    err = std::max(err, std::abs(u[i] - exact.value(support[i], i % 2)));
                  const std::string what = family + ", k = " + std::to_string(k) + ", " +
                                           law->get_name().substr(0, law->get_name().find(" (")) +
                                           (with_traction ? ", Dirichlet + traction" : ", Dirichlet") + ": ";
                  testing::check(converged, what + "all load steps converged");
                  testing::check_small(err / u_max, 1e-10, what + "max DoF error / max |u|");
                }
            }
        }
    }
  return testing::finish();
}
