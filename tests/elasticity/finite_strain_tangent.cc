// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The assembled tangent of FiniteStrainAssembler is the derivative of its
// internal force: at a state u = (0.2 sin(2x + y), 0.15 x y^2) plus random
// values of amplitude 0.005 at every DoF (Voronoi mesh of 16 cells, the
// stabilization frozen at u), every column j of K is compared with the
// central difference -(r(u + h e_j) - r(u - h e_j)) / (2h), h = 1e-6, of the
// assembled residual (no constraints). Neo-Hooke and Saint Venant-Kirchhoff
// (E = 1, nu = 0.3), k = 1 and 2; |K - K_fd| <= 1e-7 max |K| (difference
// error about h^2 |r'''| + eps |r| / h; measured 2e-11 for k = 1 and
// 8e-10 for k = 2). Also: the right-hand side assembled with the tangent equals
// the residual when nothing is constrained.
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <random>

#include "../elasticity_common.h"
#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;

int
main()
{
  PolygonalMesh<2> mesh;
  testing::make_mesh(mesh, "voronoi", 0);
  const NeoHookeMaterial             neo_hooke(1., 0.3);
  const SaintVenantKirchhoffMaterial svk(1., 0.3);
  for (const unsigned int k : {1u, 2u})
    for (const HyperelasticMaterial *law :
         {static_cast<const HyperelasticMaterial *>(&neo_hooke), static_cast<const HyperelasticMaterial *>(&svk)})
      {
        const std::string name =
          "k = " + std::to_string(k) + ", " + law->get_name().substr(0, law->get_name().find(" ("));
        VEMDoFHandler<2> dof_handler(mesh);
        dof_handler.distribute_dofs(k);
        FiniteStrainAssembler<2>          assembler(dof_handler, testing::one_law_library(dof_handler, *law));
        dealii::AffineConstraints<double> none;
        none.close();
        dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
        dof_handler.make_sparsity_pattern(dsp, none);
        dealii::SparsityPattern sp;
        sp.copy_from(dsp);
        dealii::SparseMatrix<double> K(sp);
        std::vector<dealii::Point<2>> support;
        dof_handler.map_dofs_to_support_points(support);
        std::mt19937                           rng(3);
        std::uniform_real_distribution<double> random(-0.005, 0.005);
        dealii::Vector<double>                 u(dof_handler.n_dofs()), r, rhs, r_plus, r_minus;
        for (unsigned int i = 0; i < u.size(); ++i)
          {
            const dealii::Point<2> &X = support[i];
            u[i] = (i % 2 == 0 ? 0.2 * std::sin(2 * X[0] + X[1]) : 0.15 * X[0] * X[1] * X[1]) + random(rng);
          }
        assembler.freeze_stabilization(u);
        assembler.assemble(u, 1., r, none, &K, &rhs);
        const double h = 1e-6;
        double       err = 0, max_K = 0;
        for (unsigned int j = 0; j < u.size(); ++j)
          {
            dealii::Vector<double> up = u, um = u;
            up[j] += h;
            um[j] -= h;
            assembler.assemble(up, 1., r_plus, none, nullptr, nullptr);
            assembler.assemble(um, 1., r_minus, none, nullptr, nullptr);
            for (unsigned int i = 0; i < u.size(); ++i)
              {
                const double K_ij = sp.exists(i, j) ? K.el(i, j) : 0.;
                err               = std::max(err, std::abs(K_ij + (r_plus[i] - r_minus[i]) / (2 * h)));
                max_K             = std::max(max_K, std::abs(K_ij));
              }
          }
        testing::check_small(err / max_K, 1e-7, name + ": |K - K_fd| / max |K|");
        rhs -= r;
        testing::check_small(rhs.linfty_norm() / r.linfty_norm(), 1e-15,
                             name + ": right-hand side = residual without constraints");
      }
  return testing::finish();
}
