// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Convergence at finite strain, manufactured solution: on the unit square,
// Neo-Hooke (E = 1, nu = 0.3, plane strain), the displacement
//   u_x = 0.1 sin(pi x) sin(pi y) + 0.15 y^2,
//   u_y = -0.1 x y^2 + 0.05 cos(pi x) cos(pi y)
// (displacement gradients up to about 0.45), with the body force
// f_0 = -Div P(F(X)) per unit reference area, the nominal traction
// P(F(X)) N on the right side (id 1) and Dirichlet data u on the other
// three sides, in 3 load steps. Div P is evaluated by central differences
// of the exact P(F(X)) (h = 1e-4: error about 1e-8 relative, far below the
// discretization errors measured). Voronoi meshes of 16, 64, 256, 1024
// cells (levels 0..3), k = 1 and 2. Errors:
//   L2: |u - Pi u_h|,  H1: |grad u - Pi^0 grad u_h|,
// by a quadrature of degree 2k + 6 on each polygon. Rates are computed
// with h = 1/sqrt(n_cells) and checked between levels 2 and 3: H1 rate
// within 0.15 of k and L2 rate within 0.15 of k + 1 (measured: 1.01 and
// 2.03 for k = 1, 2.08 and 3.09 for k = 2; 16 Newton updates per level).
#include <deal.II/base/function.h>

#include <dealvem/vem/vem_values.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "../elasticity_common.h"
#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
  dealii::Tensor<1, 2>
  exact_u(const dealii::Point<2> &p)
  {
    const double         x = p[0], y = p[1];
    dealii::Tensor<1, 2> u;
    u[0] = 0.1 * std::sin(M_PI * x) * std::sin(M_PI * y) + 0.15 * y * y;
    u[1] = -0.1 * x * y * y + 0.05 * std::cos(M_PI * x) * std::cos(M_PI * y);
    return u;
  }

  dealii::Tensor<2, 2>
  exact_grad(const dealii::Point<2> &p)
  {
    const double         x = p[0], y = p[1];
    dealii::Tensor<2, 2> g;
    g[0][0] = 0.1 * M_PI * std::cos(M_PI * x) * std::sin(M_PI * y);
    g[0][1] = 0.1 * M_PI * std::sin(M_PI * x) * std::cos(M_PI * y) + 0.3 * y;
    g[1][0] = -0.1 * y * y - 0.05 * M_PI * std::sin(M_PI * x) * std::cos(M_PI * y);
    g[1][1] = -0.2 * x * y - 0.05 * M_PI * std::cos(M_PI * x) * std::sin(M_PI * y);
    return g;
  }

  dealii::Tensor<2, 2>
  exact_P(const HyperelasticMaterial &law, const dealii::Point<2> &p)
  {
    dealii::Tensor<2, 2> F = exact_grad(p);
    F[0][0] += 1.;
    F[1][1] += 1.;
    return law.first_piola_kirchhoff_stress(F);
  }

  class Displacement : public dealii::Function<2>
  {
  public:
    Displacement()
      : dealii::Function<2>(2)
    {}
    double
    value(const dealii::Point<2> &p, const unsigned int c) const override
    {
      return exact_u(p)[c];
    }
  };

  // f_0 = -Div P, Div P_i = sum_J dP_iJ / dX_J, by central differences
  class BodyForce : public dealii::Function<2>
  {
  public:
    explicit BodyForce(const HyperelasticMaterial &law)
      : dealii::Function<2>(2)
      , law(law)
    {}
    double
    value(const dealii::Point<2> &p, const unsigned int c) const override
    {
      const double h   = 1e-4;
      double       div = 0;
      for (unsigned int J = 0; J < 2; ++J)
        {
          dealii::Point<2> pp = p, pm = p;
          pp[J] += h;
          pm[J] -= h;
          div += (exact_P(law, pp)[c][J] - exact_P(law, pm)[c][J]) / (2 * h);
        }
      return -div;
    }
    const HyperelasticMaterial &law;
  };

  // P N on the right side (N = e_x)
  class Traction : public dealii::Function<2>
  {
  public:
    explicit Traction(const HyperelasticMaterial &law)
      : dealii::Function<2>(2)
      , law(law)
    {}
    double
    value(const dealii::Point<2> &p, const unsigned int c) const override
    {
      return exact_P(law, p)[c][0];
    }
    const HyperelasticMaterial &law;
  };
} // namespace

int
main()
{
  const NeoHookeMaterial law(1., 0.3);
  const Displacement     g;
  const BodyForce        f(law);
  const Traction         t(law);
  for (const unsigned int k : {1u, 2u})
    {
      std::cout << "k = " << k << "\n  cells   DoFs     L2 error     rate   H1 error     rate   Newton updates"
                << std::endl;
      std::vector<double> h, e_l2, e_h1;
      for (unsigned int level = 0; level < 4; ++level)
        {
          PolygonalMesh<2> mesh;
          testing::make_mesh(mesh, "voronoi", level);
          VEMDoFHandler<2> dof_handler(mesh);
          dof_handler.distribute_dofs(k);
          FiniteStrainAssembler<2> assembler(dof_handler, testing::one_law_library(dof_handler, law));
          assembler.set_body_force(f);
          assembler.add_traction(1, t);
          dealii::AffineConstraints<double> constraints;
          testing::dirichlet_constraints(dof_handler, {0, 2, 3}, g, constraints);
          FiniteStrainSolver<2>::Parameters parameters;
          parameters.n_load_steps = 3;
          FiniteStrainSolver<2> solver(assembler, constraints, parameters);
          solver.run();
          unsigned int updates = 0;
          for (const auto &s : solver.get_history())
            updates += s.iterations.size() - 1;

          VEMValues<2> values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values, 2 * k + 6);
          std::vector<dealii::Tensor<1, 2>> u_h;
          std::vector<dealii::Tensor<2, 2>> grad_h;
          double                            l2 = 0, h1 = 0;
          for (unsigned int c = 0; c < mesh.n_cells(); ++c)
            {
              values.reinit(c);
              values.get_function_values(solver.get_solution(), u_h);
              values.get_function_gradient_projections(solver.get_solution(), grad_h);
              for (unsigned int q = 0; q < values.n_quadrature_points(); ++q)
                {
                  const auto &x = values.quadrature_point(q);
                  l2 += (exact_u(x) - u_h[q]).norm_square() * values.JxW(q);
                  h1 += (exact_grad(x) - grad_h[q]).norm_square() * values.JxW(q);
                }
            }
          h.push_back(1. / std::sqrt(static_cast<double>(mesh.n_cells())));
          e_l2.push_back(std::sqrt(l2));
          e_h1.push_back(std::sqrt(h1));
          const unsigned int i = h.size() - 1;
          std::cout << std::setw(7) << mesh.n_cells() << std::setw(7) << dof_handler.n_dofs() << "   "
                    << std::scientific << std::setprecision(3) << e_l2[i] << "   " << std::fixed << std::setprecision(2)
                    << (i > 0 ? std::log(e_l2[i - 1] / e_l2[i]) / std::log(h[i - 1] / h[i]) : 0.) << "   "
                    << std::scientific << std::setprecision(3) << e_h1[i] << "   " << std::fixed
                    << std::setprecision(2)
                    << (i > 0 ? std::log(e_h1[i - 1] / e_h1[i]) / std::log(h[i - 1] / h[i]) : 0.) << "   "
                    << updates << std::defaultfloat << std::endl;
        }
      const double rate_l2 = std::log(e_l2[2] / e_l2[3]) / std::log(h[2] / h[3]);
      const double rate_h1 = std::log(e_h1[2] / e_h1[3]) / std::log(h[2] / h[3]);
      testing::check(std::abs(rate_l2 - (k + 1)) <= 0.15,
                     "k = " + std::to_string(k) + ": L2 rate " + std::to_string(rate_l2) + " within 0.15 of " +
                       std::to_string(k + 1));
      testing::check(std::abs(rate_h1 - k) <= 0.15,
                     "k = " + std::to_string(k) + ": H1 rate " + std::to_string(rate_h1) + " within 0.15 of " +
                       std::to_string(k));
    }
  return testing::finish();
}
