// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// VEMValues, the per-cell evaluation of the space, against the matrix
// forms of VirtualElement and ElasticityOperator, for k = 1, 2 on a
// Voronoi mesh, a mesh of non-convex cells and a triangle mesh:
// - the consistency matrix assembled by quadrature from the projected
//   shape gradients (as step-1 does) equals ElasticityOperator's
//   Pi_*^T (lambda T + 2 mu E) Pi_* to 1e-12 relative, for two materials
//   (plane strain and plane stress);
// - shape values reproduce the space's projection: for DoF values of a
//   polynomial field p in [P_k]^2, sum_i u_i shape_value(i, q) = p(x_q) and
//   get_function_values/gradients give p and grad p (1e-12 relative);
// - the projected shape functions sum to the constant: sum over the
//   x-component DoFs of shape_value(i, q) = (1, 0), since the DoFs of (1, 0)
//   are 1 on x-components and 0 on y-components (1e-13);
// - the local DoF indices are those of the DoF handler, the boundary ids of
//   the edges those of the mesh;
// - asking for a value that was not requested in the UpdateFlags throws;
// - a VEMValues made from a DoF handler whose distribute_dofs() was not
//   called throws ExcNoDoFsDistributed (not a message about the order).
#include <deal.II/base/function.h>
#include <deal.II/lac/full_matrix.h>

#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/vem_values.h>

#include <cmath>

#include "../tests.h"

using namespace dealvem;
using P = dealii::Point<2>;

// a quadratic vector field (linear for k = 1)
class Field : public dealii::Function<2>
{
public:
  explicit Field(const unsigned int k)
    : dealii::Function<2>(2)
    , q(k == 2 ? 1. : 0.)
  {}
  double
  value(const P &p, const unsigned int c) const override
  {
    const double x = p[0], y = p[1];
    return c == 0 ? 0.3 + 1.1 * x - 0.4 * y + q * (0.7 * x * x - 0.2 * x * y + 0.5 * y * y) :
                    -0.2 + 0.6 * x + 0.9 * y + q * (-0.3 * x * x + 0.8 * x * y - 0.1 * y * y);
  }
  dealii::Tensor<2, 2>
  gradient_of(const P &p) const
  {
    const double         x = p[0], y = p[1];
    dealii::Tensor<2, 2> g;
    g[0][0] = 1.1 + q * (1.4 * x - 0.2 * y);
    g[0][1] = -0.4 + q * (-0.2 * x + 1.0 * y);
    g[1][0] = 0.6 + q * (-0.6 * x + 0.8 * y);
    g[1][1] = 0.9 + q * (0.8 * x - 0.2 * y);
    return g;
  }

private:
  const double q;
};

double
relative_difference(const dealii::FullMatrix<double> &A, const dealii::FullMatrix<double> &B)
{
  double d = 0, a = 0;
  for (unsigned int i = 0; i < A.m(); ++i)
    for (unsigned int j = 0; j < A.n(); ++j)
      {
        d = std::max(d, std::abs(A(i, j) - B(i, j)));
        a = std::max(a, std::abs(B(i, j)));
      }
  return d / a;
}

void
check_mesh(const std::string &name, const PolygonalMesh<2> &mesh)
{
  for (const unsigned int k : {1u, 2u})
    {
      const std::string tag = name + " k=" + std::to_string(k) + ": ";
      VEMDoFHandler<2>  dof_handler(mesh);
      dof_handler.distribute_dofs(k);
      const Field field(k);
      // the global DoF vector of the field
      dealii::Vector<double> u(dof_handler.n_dofs()), local;
      {
        VirtualElement<2>                            element(k);
        std::vector<dealii::types::global_dof_index> indices;
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          {
            element.reinit(mesh.cell_vertices(c));
            element.interpolate(field, local);
            dof_handler.get_dof_indices(c, indices);
            for (unsigned int i = 0; i < indices.size(); ++i)
              u[indices[i]] = local[i];
          }
      }

      VEMValues<2> vem_values(dof_handler,
                              dealii::update_values | dealii::update_gradients | dealii::update_JxW_values);
      ElasticityOperator<2> elasticity;
      const ElasticMaterial materials[2] = {ElasticMaterial(210e3, 0.3, ElasticMaterial::Model::plane_strain),
                                            ElasticMaterial(70e3, 0.45, ElasticMaterial::Model::plane_stress)};
      double err_kc = 0, err_value = 0, err_grad = 0, err_function = 0, err_unity = 0;
      bool   indices_ok = true, ids_ok = true;
      std::vector<dealii::types::global_dof_index> indices;
      std::vector<dealii::Tensor<1, 2>>           values;
      std::vector<dealii::Tensor<2, 2>>           gradients;
      dealii::FullMatrix<double>                  Kc;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          vem_values.reinit(c);
          const unsigned int n = vem_values.dofs_per_cell();
          for (const auto &material : materials)
            {
              Kc.reinit(n, n);
              for (unsigned int q = 0; q < vem_values.n_quadrature_points(); ++q)
                for (unsigned int i = 0; i < n; ++i)
                  for (unsigned int j = 0; j < n; ++j)
                    Kc(i, j) += (material.lambda() * vem_values.shape_divergence(i, q) *
                                   vem_values.shape_divergence(j, q) +
                                 2 * material.mu() *
                                   (vem_values.shape_symmetric_gradient(i, q) *
                                    vem_values.shape_symmetric_gradient(j, q))) *
                                vem_values.JxW(q);
              elasticity.reinit(vem_values.get_element(), material);
              err_kc = std::max(err_kc, relative_difference(Kc, elasticity.get_consistency_matrix()));
            }

          dof_handler.get_dof_indices(c, indices);
          indices_ok = indices_ok && indices == vem_values.get_dof_indices();
          dof_handler.get_dof_values(c, u, local);
          vem_values.get_function_values(u, values);
          vem_values.get_function_gradients(u, gradients);
          for (unsigned int q = 0; q < vem_values.n_quadrature_points(); ++q)
            {
              const P             &x = vem_values.quadrature_point(q);
              dealii::Tensor<1, 2> v, exact, unity;
              dealii::Tensor<2, 2> g;
              for (unsigned int i = 0; i < n; ++i)
                {
                  v += local[i] * vem_values.shape_value(i, q);
                  g += local[i] * vem_values.shape_grad(i, q);
                  if (i % 2 == 0)
                    unity += vem_values.shape_value(i, q);
                }
              exact[0]      = field.value(x, 0);
              exact[1]      = field.value(x, 1);
              const auto ge = field.gradient_of(x);
              err_value     = std::max(err_value, (v - exact).norm() / exact.norm());
              err_grad      = std::max(err_grad, (g - ge).norm() / ge.norm());
              err_function  = std::max(err_function, (values[q] - exact).norm() / exact.norm() +
                                                      (gradients[q] - ge).norm() / ge.norm());
              unity[0] -= 1;
              err_unity = std::max(err_unity, unity.norm());
            }
          const auto &cell = mesh.cell(c);
          for (unsigned int e = 0; e < vem_values.n_edges(); ++e)
            {
              const auto &edge = mesh.edge(cell.edges[e]);
              ids_ok           = ids_ok && vem_values.edge_boundary_id(e) ==
                                     (edge.at_boundary() ? edge.boundary_id :
                                                           dealii::numbers::internal_face_boundary_id);
            }
        }
      testing::check_small(err_kc, 1e-12, tag + "K_c by quadrature = ElasticityOperator's K_c");
      testing::check_small(err_value, 1e-12, tag + "sum u_i shape_value = field");
      testing::check_small(err_grad, 1e-11, tag + "sum u_i shape_grad = grad field");
      testing::check_small(err_function, 1e-11, tag + "get_function_values/gradients = field");
      testing::check_small(err_unity, 1e-13, tag + "x-shape values sum to (1, 0)");
      testing::check(indices_ok, tag + "local DoF indices are the DoF handler's");
      testing::check(ids_ok, tag + "edge boundary ids are the mesh's");
    }
}

int
main()
{
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::voronoi(mesh, P(0, 0), P(2, 1), 40, 10, 3);
    check_mesh("Voronoi", mesh);
  }
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::nonconvex(mesh, P(0, 0), P(1, 1), 4, 3);
    check_mesh("non-convex", mesh);
  }
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::structured_triangles(mesh, P(-1, 0), P(1, 1), 4, 3);
    check_mesh("triangles", mesh);
  }
  // asking for what was not requested
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::structured_quads(mesh, P(0, 0), P(1, 1), 2, 2);
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(2);
    VEMValues<2> vem_values(dof_handler, dealii::update_JxW_values);
    vem_values.reinit(0);
    bool thrown = false;
    try
      {
        (void)vem_values.shape_grad(0, 0);
      }
    catch (const std::exception &e)
      {
        thrown = std::string(e.what()).find("update_gradients") != std::string::npos;
      }
    testing::check(thrown, "shape_grad without update_gradients throws naming the flag");
    thrown = false;
    try
      {
        vem_values.reinit(4);
      }
    catch (const std::exception &e)
      {
        thrown = std::string(e.what()).find("cell 4") != std::string::npos;
      }
    testing::check(thrown, "reinit on a cell that does not exist throws naming it");
  }
  // a DoF handler without DoFs: both with the default quadrature degree
  // (which is derived from the order) and with an explicit one
  for (const unsigned int quadrature_degree : {0u, 4u})
    {
      PolygonalMesh<2> mesh;
      PolygonalMeshGenerators::structured_quads(mesh, P(0, 0), P(1, 1), 2, 2);
      VEMDoFHandler<2> dof_handler(mesh);
      bool             thrown = false;
      try
        {
          VEMValues<2> vem_values(dof_handler, dealii::update_gradients, quadrature_degree);
        }
      catch (const ExcNoDoFsDistributed &)
        {
          thrown = true;
        }
      catch (const std::exception &)
        {}
      testing::check(thrown, "VEMValues before distribute_dofs() throws ExcNoDoFsDistributed (quadrature degree " +
                               std::to_string(quadrature_degree) + ")");
    }
  return testing::finish();
}
