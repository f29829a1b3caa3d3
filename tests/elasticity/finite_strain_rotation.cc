// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// A rigid rotation by 90 degrees about the point (0.3, 0.2), imposed on the
// whole boundary of the unit square (Voronoi mesh, 64 cells) in 6 load
// steps: the prescribed displacement lambda (R - I)(X - X0) at the load
// factor lambda, so the intermediate states are the homogeneous
// deformations (1 - lambda) I + lambda R (a rotation with a shrink, J =
// 0.5 at lambda = 1/2) and the last one is the rotation. For k = 1 and 2,
// Neo-Hooke and Saint Venant-Kirchhoff (E = 7000, nu = 0.3, plane strain):
// - every DoF (vertices, midpoints, cell moments) equals (R - I)(X - X0) to
//   1e-10 of the largest displacement;
// - at every quadrature point F = I + Pi^0 grad u equals R to 1e-10, and
//   the first Piola-Kirchhoff and Cauchy stresses are zero to 1e-10 E;
// - every load step converged.
// For contrast, the linear law (ElasticMaterial, same E, nu) under the
// same imposed displacement: its stress is C : sym(R - I) = -2 (lambda +
// mu) I, printed and checked to equal that value to 1e-8 relative (the
// spurious stress of small-strain elasticity under a rotation: 1.92 E).
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>

#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/vem/vem_values.h>

#include <cmath>
#include <iostream>

#include "../elasticity_common.h"
#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;

int
main()
{
  const double           E = 7000., nu = 0.3;
  const dealii::Point<2> X0(0.3, 0.2);
  dealii::Tensor<2, 2>   R;
  R[0][1] = -1.;
  R[1][0] = 1.;
  dealii::Tensor<1, 2> c; // u = (R - I)(X - X0) = (R - I) X - (R - I) X0
  for (unsigned int i = 0; i < 2; ++i)
    for (unsigned int j = 0; j < 2; ++j)
      c[i] -= (R[i][j] - (i == j)) * X0[j];
  const testing::HomogeneousDeformation rotation(R, c);

  PolygonalMesh<2> mesh;
  testing::make_mesh(mesh, "voronoi", 1);
  std::cout << "mesh: " << mesh.n_cells() << " Voronoi cells" << std::endl;

  for (const unsigned int k : {1u, 2u})
    {
      VEMDoFHandler<2> dof_handler(mesh);
      dof_handler.distribute_dofs(k);
      dealii::AffineConstraints<double> constraints;
      testing::dirichlet_constraints(dof_handler, {0, 1, 2, 3}, rotation, constraints);
      std::vector<dealii::Point<2>> support;
      dof_handler.map_dofs_to_support_points(support);
      double u_max = 0;
      for (const auto &p : support)
        u_max = std::max(u_max, std::hypot(rotation.value(p, 0), rotation.value(p, 1)));

      const NeoHookeMaterial             neo_hooke(E, nu);
      const SaintVenantKirchhoffMaterial svk(E, nu);
      for (const HyperelasticMaterial *law : {static_cast<const HyperelasticMaterial *>(&neo_hooke),
                                              static_cast<const HyperelasticMaterial *>(&svk)})
        {
          std::cout << "--- k = " << k << ", " << law->get_name() << std::endl;
          FiniteStrainAssembler<2>              assembler(dof_handler, testing::one_law_library(dof_handler, *law));
          FiniteStrainSolver<2>::Parameters     parameters;
          parameters.n_load_steps = 6;
          FiniteStrainSolver<2> solver(assembler, constraints, parameters);
          solver.run();
          bool all_converged = solver.get_history().size() == 6;
          for (const auto &s : solver.get_history())
            all_converged = all_converged && s.converged;
          testing::check(all_converged, "all 6 load steps converged");
          std::cout << "  Newton updates per step:";
          for (const auto &s : solver.get_history())
            std::cout << ' ' << s.iterations.size() - 1;
          std::cout << std::endl;

          const dealii::Vector<double> &u     = solver.get_solution();
          double                        err_u = 0;
          for (unsigned int i = 0; i < u.size(); ++i)
            err_u = std::max(err_u, std::abs(u[i] - rotation.value(support[i], i % 2)));
          testing::check_small(err_u / u_max, 1e-10, "max DoF error / max |u|");

          VEMValues<2> values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values);
          std::vector<dealii::Tensor<2, 2>> grads;
          double                            err_F = 0, max_P = 0, max_sigma = 0;
          for (unsigned int cell = 0; cell < mesh.n_cells(); ++cell)
            {
              values.reinit(cell);
              values.get_function_gradient_projections(u, grads);
              for (const auto &g : grads)
                {
                  dealii::Tensor<2, 2> F = g;
                  F[0][0] += 1.;
                  F[1][1] += 1.;
                  err_F     = std::max(err_F, (F - R).norm());
                  max_P     = std::max(max_P, law->first_piola_kirchhoff_stress(F).norm());
                  max_sigma = std::max(max_sigma, law->cauchy_stress(F).norm());
                }
            }
          testing::check_small(err_F, 1e-10, "max |F - R| at the quadrature points");
          testing::check_small(max_P / E, 1e-10, "max |P| / E");
          testing::check_small(max_sigma / E, 1e-10, "max |sigma| / E (Cauchy)");
        }

      // the linear law under the same imposed displacement
      const ElasticMaterial linear(E, nu, ElasticMaterial::Model::plane_strain);
      dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
      dof_handler.make_sparsity_pattern(dsp, constraints);
      dealii::SparsityPattern sp;
      sp.copy_from(dsp);
      dealii::SparseMatrix<double> A(sp);
      dealii::Vector<double>       b, x(dof_handler.n_dofs());
      ElasticityAssembler<2> linear_assembler(dof_handler, testing::one_law_library(dof_handler, linear));
      linear_assembler.assemble(constraints, A, b);
      dealii::SparseDirectUMFPACK direct;
      direct.initialize(A);
      direct.vmult(x, b);
      constraints.distribute(x);
      VEMValues<2> values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values);
      std::vector<dealii::Tensor<2, 2>> grads;
      double                            max_stress = 0, err_stress = 0;
      const double                      expected = -2. * (linear.lambda() + linear.mu());
      for (unsigned int cell = 0; cell < mesh.n_cells(); ++cell)
        {
          values.reinit(cell);
          values.get_function_gradient_projections(x, grads);
          for (const auto &g : grads)
            {
              const dealii::SymmetricTensor<2, 2> s = linear.stress(dealii::symmetrize(g));
              max_stress = std::max(max_stress, s.norm());
              err_stress = std::max({err_stress, std::abs(s[0][0] - expected), std::abs(s[1][1] - expected),
                                     std::abs(s[0][1])});
            }
        }
      std::cout << "  linear law under the same rotation: max |sigma| / E = " << max_stress / E
                << " (spurious; sigma = -2 (lambda + mu) I = " << expected / E << " E I)" << std::endl;
      testing::check_small(err_stress / std::abs(expected), 1e-8,
                           "linear law: sigma = -2 (lambda + mu) I under the rotation, relative error");
    }
  return testing::finish();
}
