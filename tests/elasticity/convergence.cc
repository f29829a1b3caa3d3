// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Convergence on a smooth manufactured solution with a non-zero body force,
//   u = (sin(pi x) sin(pi y), 0.5 cos(pi x) sin(pi y)),  f = -div sigma(u),
// Dirichlet data on the whole boundary of the unit square, plane strain,
// on centroidal Voronoi meshes (16, 64, 256, 1024 cells) and perturbed quads
// (8^2 ... 64^2 cells), k = 1 and 2. The rates with respect to
// h ~ n_dofs^{-1/2} on the finest pair must be within 0.15 of k + 1 (L2 of
// u - Pi u_h) and k (H1 seminorm and energy). The table is printed.
#include <deal.II/base/convergence_table.h>

#include <dealvem/postprocessing/error_norms.h>

#include <cmath>

#include "../elasticity_common.h"
#include "../tests.h"

using namespace dealvem;

class Exact : public dealii::Function<2>
{
public:
  Exact()
    : dealii::Function<2>(2)
  {}
  double
  value(const dealii::Point<2> &p, const unsigned int c) const override
  {
    const double s = M_PI, x = p[0], y = p[1];
    return c == 0 ? std::sin(s * x) * std::sin(s * y) : 0.5 * std::cos(s * x) * std::sin(s * y);
  }
  dealii::Tensor<1, 2>
  gradient(const dealii::Point<2> &p, const unsigned int c) const override
  {
    const double         s = M_PI, x = p[0], y = p[1];
    dealii::Tensor<1, 2> g;
    if (c == 0)
      {
        g[0] = s * std::cos(s * x) * std::sin(s * y);
        g[1] = s * std::sin(s * x) * std::cos(s * y);
      }
    else
      {
        g[0] = -0.5 * s * std::sin(s * x) * std::sin(s * y);
        g[1] = 0.5 * s * std::cos(s * x) * std::cos(s * y);
      }
    return g;
  }
};

class BodyForce : public dealii::Function<2>
{
public:
  explicit BodyForce(const ElasticMaterial &m)
    : dealii::Function<2>(2)
    , l(m.lambda())
    , mu(m.mu())
  {}
  double
  value(const dealii::Point<2> &p, const unsigned int c) const override
  {
    const double s = M_PI, Sx = std::sin(s * p[0]), Sy = std::sin(s * p[1]), Cx = std::cos(s * p[0]),
                 Cy = std::cos(s * p[1]);
    if (c == 0)
      return (l + mu) * s * s * (Sx * Sy + 0.5 * Sx * Cy) + 2 * mu * s * s * Sx * Sy;
    return -(l + mu) * s * s * (Cx * Cy - 0.5 * Cx * Sy) + mu * s * s * Cx * Sy;
  }
  double l, mu;
};

int
main()
{
  const ElasticMaterial material(1000, 0.3);
  const Exact           exact;
  const BodyForce       f(material);
  const std::map<dealii::types::material_id, ElasticMaterial> materials = {{0, material}};
  for (const std::string family : {"voronoi", "perturbed quads"})
    for (const unsigned int k : {1u, 2u})
      {
        dealii::ConvergenceTable table;
        std::vector<double>      n_dofs, l2, h1, energy;
        for (unsigned int level = 0; level < 4; ++level)
          {
            PolygonalMesh<2> mesh;
            if (family == "voronoi")
              PolygonalMeshGenerators::voronoi(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1),
                                               16u << (2 * level), 40, 1 + level);
            else
              PolygonalMeshGenerators::perturbed_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1),
                                                       8u << level, 8u << level, 0.25, 1 + level);
            VEMDoFHandler<2> dof_handler(mesh);
            dof_handler.distribute_dofs(k);
            const auto x = testing::solve_dirichlet_problem(dof_handler, material, exact, &f);
            const auto e = compute_errors(dof_handler, materials, x, exact);
            n_dofs.push_back(dof_handler.n_dofs());
            l2.push_back(e.l2 / e.l2_exact);
            h1.push_back(e.h1_seminorm / e.h1_exact);
            energy.push_back(e.energy / e.energy_exact);
            table.add_value("cells", mesh.n_cells());
            table.add_value("dofs", dof_handler.n_dofs());
            table.add_value("L2 rel", l2.back());
            table.add_value("H1 rel", h1.back());
            table.add_value("energy rel", energy.back());
          }
        for (const std::string c : {"L2 rel", "H1 rel", "energy rel"})
          {
            table.set_scientific(c, true);
            table.set_precision(c, 3);
            table.evaluate_convergence_rates(c, "dofs", dealii::ConvergenceTable::reduction_rate_log2, 2);
          }
        std::cout << family << ", k = " << k << ":" << std::endl;
        table.write_text(std::cout, dealii::TableHandler::org_mode_table);
        auto rate = [&](const std::vector<double> &e) {
          const unsigned int n = e.size();
          return -2 * std::log(e[n - 1] / e[n - 2]) / std::log(n_dofs[n - 1] / n_dofs[n - 2]);
        };
        const std::string tag = family + " k=" + std::to_string(k);
        testing::check_near(rate(l2), k + 1, 0.15, tag + ": L2 rate on the finest pair");
        testing::check_near(rate(h1), k, 0.15, tag + ": H1 rate on the finest pair");
        testing::check_near(rate(energy), k, 0.15, tag + ": energy rate on the finest pair");
      }
  return testing::finish();
}
