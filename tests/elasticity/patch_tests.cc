// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Displacement patch tests on every mesh family (structured quads and
// triangles, perturbed quads, Voronoi, non-convex cells, meshes with hanging
// vertices), plane strain and plane stress:
// - k = 1 reproduces a linear field (no body force),
// - k = 2 reproduces a quadratic field with its constant body force
//   f = -div sigma(u),
// with Dirichlet data on the whole boundary. Every DoF (vertex, midpoint and
// cell-moment values) must equal the exact one to 1e-10 relative to the
// largest displacement.
#include <dealvem/vem/virtual_element.h>

#include "../elasticity_common.h"
#include "../tests.h"

using namespace dealvem;

// u = (1e-3 + 2e-3 x - 1e-3 y + q(3x^2 - xy + 2y^2),  -2e-3 + 1.5e-3 x + 0.5e-3 y + q(x^2 + 4xy - y^2))
class Field : public dealii::Function<2>
{
public:
  explicit Field(const double q)
    : dealii::Function<2>(2)
    , q(q)
  {}
  double
  value(const dealii::Point<2> &p, const unsigned int c) const override
  {
    const double x = p[0], y = p[1];
    if (c == 0)
      return 1e-3 + 2e-3 * x - 1e-3 * y + q * (3 * x * x - x * y + 2 * y * y);
    return -2e-3 + 1.5e-3 * x + 0.5e-3 * y + q * (x * x + 4 * x * y - y * y);
  }
  double q;
};

// f = -[(lambda + mu) grad div u + mu Laplace u] for the field above
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
  value(const dealii::Point<2> &, const unsigned int c) const override
  {
    // div u = q(6x - y + 4x - 2y) + const = q(10x - 3y) + ...
    const double grad_div[2] = {10 * q, -3 * q};
    // Laplace u_x = q(6 + 4) = 10 q, Laplace u_y = q(2 - 2) = 0
    const double lap[2] = {10 * q, 0.};
    return -((l + mu) * grad_div[c] + mu * lap[c]);
  }
  double q, l, mu;
};

int
main()
{
  for (const auto &family : testing::mesh_families())
    for (const unsigned int k : {1u, 2u})
      for (const auto model : {ElasticMaterial::Model::plane_strain, ElasticMaterial::Model::plane_stress})
        {
          PolygonalMesh<2> mesh;
          testing::make_mesh(mesh, family, 1);
          VEMDoFHandler<2> dof_handler(mesh);
          dof_handler.distribute_dofs(k);
          const ElasticMaterial material(7000, 0.3, model);
          const double          q = (k == 2 ? 1e-3 : 0.);
          const Field           u(q);
          const BodyForce       f(q, material);
          const auto            x = testing::solve_dirichlet_problem(dof_handler, material, u, &f);

          // compare every DoF with the exact DoF value of the field
          double           err = 0, umax = 0;
          VirtualElement<2> element(k);
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
          testing::check_small(err / umax, 1e-10,
                               family + " (" + std::to_string(mesh.n_cells()) + " cells) k=" +
                                 std::to_string(k) + " " + ElasticMaterial::model_name(model) +
                                 ": max DoF error / max |u|");
        }
  return testing::finish();
}
