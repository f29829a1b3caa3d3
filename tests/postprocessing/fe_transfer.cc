// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Transfer of a VEM solution to finite element fields on the deal.II
// triangulation the polygons came from (FETransfer, TriangulationMap), on a
// randomly distorted 6x6 quadrilateral mesh, k = 1 and 2, for a smooth
// manufactured solution:
// - the maps: every polygon has its cell's vertices (same coordinates) and
//   area;
// - discontinuous FE_DGQ(k)^2: the field equals Pi u_h at Gauss points of
//   every cell to 1e-12 relative (exact, see fe_transfer.h), so
//   VectorTools::integrate_difference gives compute_errors()'s L2 and H1
//   errors to 1e-8 relative (two different quadratures);
// - continuous FE_Q(k)^2: the field has the VEM degrees of freedom of u_h
//   (values at vertices and edge midpoints through FEFieldFunction, cell
//   means by quadrature) to 1e-12; for k = 1 the cell mean of its gradient
//   is the gradient of Pi u_h;
// - a locally refined triangulation: the discontinuous transfer is exact
//   there too, the continuous one refuses (hanging nodes);
// - refining the triangulation after the map was made is refused;
// - a triangle mesh: FE_SimplexDGP(k)^2 field = Pi u_h (exact on affine
//   triangles), integrate_difference = compute_errors.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/fe_field_function.h>
#include <deal.II/numerics/vector_tools.h>

#include <dealvem/mesh/triangulation_map.h>
#include <dealvem/postprocessing/error_norms.h>
#include <dealvem/postprocessing/fe_transfer.h>
#include <dealvem/vem/virtual_element.h>

#include <cmath>

#include "../elasticity_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
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

  // its body force f = -div sigma(u) in plane strain
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

  // the largest |FE field - Pi u_h| at the 3x3 Gauss points of every cell
  double
  max_difference_to_projection(const TriangulationMap<2> &map, const VEMDoFHandler<2> &vem_dofs,
                               const dealii::Vector<double> &u_h, const dealii::DoFHandler<2> &dof_handler,
                               const dealii::Vector<double> &field)
  {
    const auto &reference_cell = dof_handler.get_triangulation().get_reference_cells()[0];
    const dealii::Quadrature<2> q = reference_cell.is_hyper_cube() ? dealii::Quadrature<2>(dealii::QGauss<2>(3)) :
                                                                     dealii::Quadrature<2>(dealii::QGaussSimplex<2>(3));
    dealii::FEValues<2> fe_values(reference_cell.get_default_linear_mapping<2, 2>(), dof_handler.get_fe(), q,
                                  dealii::update_values | dealii::update_quadrature_points);
    std::vector<dealii::Vector<double>> values(q.size(), dealii::Vector<double>(2));
    VirtualElement<2>                   element(vem_dofs.get_degree());
    dealii::Vector<double>              local, coef;
    double                              diff = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int p = map.polygon_of(cell);
        element.reinit(map.get_mesh().cell_vertices(p));
        vem_dofs.get_dof_values(p, u_h, local);
        element.project(local, coef);
        fe_values.reinit(cell);
        fe_values.get_function_values(field, values);
        for (unsigned int i = 0; i < q.size(); ++i)
          {
            const auto pi = element.projection_value(coef, fe_values.quadrature_point(i));
            for (unsigned int c = 0; c < 2; ++c)
              diff = std::max(diff, std::abs(values[i][c] - pi[c]));
          }
      }
    return diff;
  }

  double
  integrate_difference(const dealii::DoFHandler<2> &dof_handler, const dealii::Vector<double> &field,
                       const Exact &exact, const dealii::VectorTools::NormType norm)
  {
    dealii::Vector<double> per_cell(dof_handler.get_triangulation().n_active_cells());
    const dealii::QGauss<2> q(8);
    dealii::VectorTools::integrate_difference(dof_handler, field, exact, per_cell, q, norm);
    return dealii::VectorTools::compute_global_error(dof_handler.get_triangulation(), per_cell, norm);
  }
} // namespace

int
main()
{
  const ElasticMaterial material(1000, 0.3);
  const std::map<dealii::types::material_id, ElasticMaterial> materials = {{0, material}};
  const Exact exact;
  const BodyForce f(material);

  for (const unsigned int k : {1u, 2u})
    {
      const std::string  tag = "k = " + std::to_string(k) + ": ";
      dealii::Triangulation<2> tria;
      dealii::GridGenerator::subdivided_hyper_rectangle(tria, {6, 6}, dealii::Point<2>(0, 0),
                                                        dealii::Point<2>(1, 1), true);
      // colorize also numbers the cells by quadrant: one material here
      for (const auto &cell : tria.active_cell_iterators())
        cell->set_material_id(0);
      dealii::GridTools::distort_random(0.25, tria, true, 42);
      PolygonalMesh<2>    mesh;
      TriangulationMap<2> map;
      PolygonalMeshGenerators::from_triangulation(mesh, tria, map);

      bool maps_ok = map.n_active_cells() == 36 && mesh.n_cells() == 36;
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int p = map.polygon_of(cell);
          maps_ok = maps_ok && map.active_cell_index(p) == cell->active_cell_index() &&
                    std::abs(PolygonGeometry<2>(mesh.cell_vertices(p)).area() - cell->measure()) < 1e-14;
          for (const unsigned int v : cell->vertex_indices())
            maps_ok = maps_ok && mesh.vertex(map.mesh_vertex(cell->vertex_index(v))) == cell->vertex(v) &&
                      map.triangulation_vertex(map.mesh_vertex(cell->vertex_index(v))) == cell->vertex_index(v);
        }
      testing::check(maps_ok, tag + "cell and vertex maps agree with the triangulation (coordinates, areas)");

      VEMDoFHandler<2> vem_dofs(mesh);
      vem_dofs.distribute_dofs(k);
      const dealii::Vector<double> u_h = testing::solve_dirichlet_problem(vem_dofs, material, exact, &f);
      const ErrorNorms e = compute_errors(vem_dofs, materials, u_h, exact);

      // discontinuous
      {
        const dealii::FESystem<2> fe(dealii::FE_DGQ<2>(k), 2);
        dealii::DoFHandler<2>     dof_handler(tria);
        dof_handler.distribute_dofs(fe);
        dealii::Vector<double> field;
        FETransfer::interpolate_to_discontinuous(map, vem_dofs, u_h, dof_handler, field);
        const double diff = max_difference_to_projection(map, vem_dofs, u_h, dof_handler, field);
        testing::check_small(diff / u_h.linfty_norm(), 1e-12, tag + "FE_DGQ field = Pi u_h at Gauss points (relative)");
        const double l2 = integrate_difference(dof_handler, field, exact, dealii::VectorTools::L2_norm);
        const double h1 = integrate_difference(dof_handler, field, exact, dealii::VectorTools::H1_seminorm);
        testing::check_small(std::abs(l2 / e.l2 - 1), 1e-8, tag + "integrate_difference L2 = compute_errors L2 (" +
                                                              std::to_string(l2) + ")");
        testing::check_small(std::abs(h1 / e.h1_seminorm - 1), 1e-8,
                             tag + "integrate_difference H1 = compute_errors H1 (" + std::to_string(h1) + ")");
      }

      // continuous
      {
        const dealii::FESystem<2> fe(dealii::FE_Q<2>(k), 2);
        dealii::DoFHandler<2>     dof_handler(tria);
        dof_handler.distribute_dofs(fe);
        dealii::Vector<double> field;
        FETransfer::interpolate_to_continuous(map, vem_dofs, u_h, dof_handler, field);
        dealii::Functions::FEFieldFunction<2> field_function(dof_handler, field);
        double                                diff = 0;
        dealii::Vector<double>                value(2);
        for (unsigned int node = 0; node < vem_dofs.n_nodes(); ++node)
          if (!vem_dofs.is_moment_node(node))
            {
              field_function.vector_value(vem_dofs.node_location(node), value);
              for (unsigned int c = 0; c < 2; ++c)
                diff = std::max(diff, std::abs(value[c] - u_h[2 * node + c]));
            }
        // cell means (k = 2: the moment DoFs) and mean gradients (k = 1)
        const dealii::QGauss<2>  q(k + 2);
        dealii::FEValues<2>      fe_values(fe, q, dealii::update_values | dealii::update_gradients | dealii::update_JxW_values);
        std::vector<dealii::Vector<double>>              values(q.size(), dealii::Vector<double>(2));
        std::vector<std::vector<dealii::Tensor<1, 2>>>   grads(q.size(), std::vector<dealii::Tensor<1, 2>>(2));
        VirtualElement<2>      element(k);
        dealii::Vector<double> local, coef;
        double                 grad_diff = 0;
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            const unsigned int p = map.polygon_of(cell);
            fe_values.reinit(cell);
            fe_values.get_function_values(field, values);
            fe_values.get_function_gradients(field, grads);
            dealii::Tensor<1, 2> mean;
            dealii::Tensor<2, 2> mean_grad;
            double               area = 0;
            for (unsigned int i = 0; i < q.size(); ++i)
              {
                area += fe_values.JxW(i);
                for (unsigned int c = 0; c < 2; ++c)
                  {
                    mean[c] += values[i][c] * fe_values.JxW(i);
                    mean_grad[c] += grads[i][c] * fe_values.JxW(i);
                  }
              }
            if (k == 2)
              for (unsigned int c = 0; c < 2; ++c)
                diff = std::max(diff, std::abs(mean[c] / area - u_h[2 * vem_dofs.cell_node(p) + c]));
            else
              {
                element.reinit(mesh.cell_vertices(p));
                vem_dofs.get_dof_values(p, u_h, local);
                element.project(local, coef);
                // k = 1: the gradient of Pi u_h is constant
                const dealii::Tensor<2, 2> g = element.projection_gradient(coef, cell->center());
                grad_diff = std::max(grad_diff, (mean_grad / area - g).norm());
              }
          }
        testing::check_small(diff / u_h.linfty_norm(), 1e-12,
                             tag + "the FE_Q field has the VEM DoFs of u_h (vertex, midpoint values, cell means)");
        if (k == 1)
          testing::check_small(grad_diff, 1e-11, tag + "cell mean of the FE_Q(1) gradient = grad Pi u_h");
        const double l2 = integrate_difference(dof_handler, field, exact, dealii::VectorTools::L2_norm);
        const double h1 = integrate_difference(dof_handler, field, exact, dealii::VectorTools::H1_seminorm);
        std::cout << "   " << tag << "errors of the FE_Q field L2 " << l2 << " H1 " << h1 << "; of Pi u_h L2 "
                  << e.l2 << " H1 " << e.h1_seminorm << std::endl;
        testing::check(l2 < 2 * e.l2 && h1 < 2 * e.h1_seminorm,
                       tag + "the FE_Q field's errors are of the size of those of Pi u_h");
      }

      // a locally refined triangulation (hanging nodes: pentagons)
      {
        tria.begin_active()->set_refine_flag();
        tria.execute_coarsening_and_refinement();
        testing::check_throws(
          [&] {
            dealii::DoFHandler<2> dof_handler(tria);
            dof_handler.distribute_dofs(dealii::FESystem<2>(dealii::FE_DGQ<2>(k), 2));
            dealii::Vector<double> field;
            FETransfer::interpolate_to_discontinuous(map, vem_dofs, u_h, dof_handler, field);
          },
          "the triangulation was changed", tag + "a map made before refinement is refused");
        PolygonalMesh<2>    mesh2;
        TriangulationMap<2> map2;
        PolygonalMeshGenerators::from_triangulation(mesh2, tria, map2);
        VEMDoFHandler<2> vem_dofs2(mesh2);
        vem_dofs2.distribute_dofs(k);
        const dealii::Vector<double> u_h2 = testing::solve_dirichlet_problem(vem_dofs2, material, exact, &f);
        dealii::DoFHandler<2>        dof_handler(tria);
        dof_handler.distribute_dofs(dealii::FESystem<2>(dealii::FE_DGQ<2>(k), 2));
        dealii::Vector<double> field;
        FETransfer::interpolate_to_discontinuous(map2, vem_dofs2, u_h2, dof_handler, field);
        testing::check_small(max_difference_to_projection(map2, vem_dofs2, u_h2, dof_handler, field) /
                               u_h2.linfty_norm(),
                             1e-12, tag + "hanging nodes: FE_DGQ field = Pi u_h");
        dealii::DoFHandler<2> dof_handler_q(tria);
        dof_handler_q.distribute_dofs(dealii::FESystem<2>(dealii::FE_Q<2>(k), 2));
        testing::check_throws([&] { FETransfer::interpolate_to_continuous(map2, vem_dofs2, u_h2, dof_handler_q, field); },
                              "the triangulation has hanging nodes", tag + "hanging nodes: continuous transfer refused");
      }
    }
  for (const unsigned int k : {1u, 2u})
    {
      const std::string        tag = "triangles, k = " + std::to_string(k) + ": ";
      dealii::Triangulation<2> tria;
      dealii::GridGenerator::subdivided_hyper_rectangle_with_simplices(tria, {5, 5}, dealii::Point<2>(0, 0),
                                                                       dealii::Point<2>(1, 1));
      // (boundary id 0 everywhere: the Dirichlet data of solve_dirichlet_problem)
      PolygonalMesh<2>    mesh;
      TriangulationMap<2> map;
      PolygonalMeshGenerators::from_triangulation(mesh, tria, map);
      VEMDoFHandler<2> vem_dofs(mesh);
      vem_dofs.distribute_dofs(k);
      const dealii::Vector<double> u_h = testing::solve_dirichlet_problem(vem_dofs, material, exact, &f);
      const ErrorNorms             e   = compute_errors(vem_dofs, materials, u_h, exact);
      dealii::DoFHandler<2>        dof_handler(tria);
      dof_handler.distribute_dofs(dealii::FESystem<2>(dealii::FE_SimplexDGP<2>(k), 2));
      dealii::Vector<double> field;
      FETransfer::interpolate_to_discontinuous(map, vem_dofs, u_h, dof_handler, field);
      testing::check_small(max_difference_to_projection(map, vem_dofs, u_h, dof_handler, field) / u_h.linfty_norm(),
                           1e-12, tag + "FE_SimplexDGP field = Pi u_h (relative)");
      dealii::Vector<double> per_cell(tria.n_active_cells());
      const auto &mapping = tria.get_reference_cells()[0].get_default_linear_mapping<2, 2>();
      dealii::VectorTools::integrate_difference(mapping, dof_handler, field, exact, per_cell,
                                                dealii::QWitherdenVincentSimplex<2>(6), dealii::VectorTools::L2_norm);
      const double l2 = dealii::VectorTools::compute_global_error(tria, per_cell, dealii::VectorTools::L2_norm);
      testing::check_small(std::abs(l2 / e.l2 - 1), 1e-8, tag + "integrate_difference L2 = compute_errors L2 (" +
                                                            std::to_string(l2) + ")");
    }
  return testing::finish();
}
