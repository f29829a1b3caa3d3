// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/grid/tria.h>

#include <dealvem/postprocessing/fe_transfer.h>
#include <dealvem/vem/virtual_element.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace dealvem
{
  namespace FETransfer
  {
    namespace
    {
      // The checks both transfers share: the map is made and its
      // triangulation unchanged, the DoF handlers and vectors belong to it.
      template <int dim>
      void
      check_arguments(const TriangulationMap<dim>        &map,
                      const VEMDoFHandler<dim>           &vem_dof_handler,
                      const dealii::Vector<double>       &vem_solution,
                      const dealii::DoFHandler<dim, dim> &dof_handler,
                      const std::string                  &function)
      {
        const std::string where = "FETransfer::" + function + ": ";
        AssertThrow(map.triangulation_unchanged(),
                    dealii::ExcMessage(where + "the triangulation was changed (or never mapped) since "
                                               "PolygonalMeshGenerators::from_triangulation(mesh, tria, map) made "
                                               "the map; make the mesh and the map again."));
        AssertThrow(&dof_handler.get_triangulation() == &map.get_triangulation(),
                    dealii::ExcMessage(where + "the DoFHandler is not built on the map's triangulation."));
        AssertThrow(dof_handler.get_fe_collection().size() == 1,
                    dealii::ExcMessage(where + "hp DoFHandlers (several elements) are not supported."));
        AssertThrow(&vem_dof_handler.get_mesh() == &map.get_mesh(),
                    dealii::ExcMessage(where + "the VEMDoFHandler is not built on the map's mesh."));
        vem_dof_handler.check_mesh_unchanged();
        AssertThrow(vem_solution.size() == vem_dof_handler.n_dofs(),
                    dealii::ExcMessage(where + "the VEM solution has " + std::to_string(vem_solution.size()) +
                                       " entries, the VEMDoFHandler " +
                                       std::to_string(vem_dof_handler.n_dofs()) + " DoFs."));
        AssertThrow(map.get_mesh().n_cells() >= map.n_active_cells(),
                    dealii::ExcMessage(where + "the mesh has fewer polygons than the triangulation has cells."));
        const auto &fe = dof_handler.get_fe();
        AssertThrow(fe.n_components() == 2,
                    dealii::ExcMessage(where + "the finite element (" + fe.get_name() +
                                       ") must have two vector components (the displacement)."));
        AssertThrow(fe.has_support_points(),
                    dealii::ExcMessage(where + "the finite element (" + fe.get_name() +
                                       ") has no support points (it must be a Lagrange element)."));
      }
    } // namespace



    template <int dim>
    void
    interpolate_to_discontinuous(const dealii::Mapping<dim, dim>    &mapping,
                                 const TriangulationMap<dim>        &map,
                                 const VEMDoFHandler<dim>           &vem_dof_handler,
                                 const dealii::Vector<double>       &vem_solution,
                                 const dealii::DoFHandler<dim, dim> &dof_handler,
                                 dealii::Vector<double>             &fe_solution)
    {
      check_arguments(map, vem_dof_handler, vem_solution, dof_handler, "interpolate_to_discontinuous");
      const auto &fe = dof_handler.get_fe();
      AssertThrow(fe.n_dofs_per_vertex() == 0 && fe.n_dofs_per_line() == 0,
                  dealii::ExcMessage("FETransfer::interpolate_to_discontinuous: the finite element (" +
                                     fe.get_name() +
                                     ") shares DoFs between cells; use a discontinuous element such as "
                                     "FESystem<2>(FE_DGQ<2>(k), 2), or interpolate_to_continuous()."));

      const auto &mesh = map.get_mesh();
      VirtualElement<dim>                          element(vem_dof_handler.get_degree());
      const dealii::Quadrature<dim>                support(fe.get_unit_support_points());
      dealii::FEValues<dim>                        fe_values(mapping, fe, support, dealii::update_quadrature_points);
      std::vector<dealii::types::global_dof_index> indices(fe.n_dofs_per_cell());
      std::vector<dealii::Point<dim>>              vertices;
      dealii::Vector<double>                       local, coefficients;

      fe_solution.reinit(dof_handler.n_dofs());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const unsigned int p = map.polygon_of(cell);
          mesh.cell_vertices(p, vertices);
          element.reinit(vertices);
          vem_dof_handler.get_dof_values(p, vem_solution, local);
          element.project(local, coefficients);
          fe_values.reinit(cell);
          cell->get_dof_indices(indices);
          for (unsigned int i = 0; i < indices.size(); ++i)
            {
              const unsigned int comp = fe.system_to_component_index(i).first;
              fe_solution[indices[i]] =
                element.projection_value(coefficients, fe_values.quadrature_point(i))[comp];
            }
        }
    }



    template <int dim>
    void
    interpolate_to_discontinuous(const TriangulationMap<dim>        &map,
                                 const VEMDoFHandler<dim>           &vem_dof_handler,
                                 const dealii::Vector<double>       &vem_solution,
                                 const dealii::DoFHandler<dim, dim> &dof_handler,
                                 dealii::Vector<double>             &fe_solution)
    {
      const auto &tria = map.get_triangulation();
      AssertThrow(tria.n_active_cells() > 0,
                  dealii::ExcMessage("FETransfer::interpolate_to_discontinuous: empty triangulation."));
      const auto reference_cells = tria.get_reference_cells();
      AssertThrow(reference_cells.size() == 1,
                  dealii::ExcMessage("FETransfer::interpolate_to_discontinuous: a triangulation of mixed cell "
                                     "types needs an explicit mapping."));
      interpolate_to_discontinuous(reference_cells[0].template get_default_linear_mapping<dim, dim>(), map,
                                   vem_dof_handler, vem_solution, dof_handler, fe_solution);
    }



    template <int dim>
    void
    interpolate_to_continuous(const TriangulationMap<dim>        &map,
                              const VEMDoFHandler<dim>           &vem_dof_handler,
                              const dealii::Vector<double>       &vem_solution,
                              const dealii::DoFHandler<dim, dim> &dof_handler,
                              dealii::Vector<double>             &fe_solution)
    {
      const std::string where = "FETransfer::interpolate_to_continuous: ";
      check_arguments(map, vem_dof_handler, vem_solution, dof_handler, "interpolate_to_continuous");
      const auto        &fe   = dof_handler.get_fe();
      const auto        &tria = map.get_triangulation();
      const auto        &mesh = map.get_mesh();
      const unsigned int k    = vem_dof_handler.get_degree();
      // the VEM layout: point values at the vertices and at the edge nodes
      // (the Gauss-Lobatto points, as FE_Q(k)'s support points on a line),
      // and the cell moments; the interior FE_Q DoFs are fixed by the cell
      // mean alone, which is one moment per component
      const VEMElementData &layout = vem_dof_handler.get_element_data();
      AssertThrow(layout.nodes_per_cell() <= 1,
                  dealii::ExcMessage(where + "implemented for at most one moment per cell (k = 1 and 2); " +
                                     layout.get_name() + " has " + std::to_string(layout.nodes_per_cell()) +
                                     ". Use interpolate_to_discontinuous()."));
      AssertThrow(tria.all_reference_cells_are_hyper_cube(),
                  dealii::ExcMessage(where + "the triangulation must consist of quadrilaterals."));
      AssertThrow(!tria.has_hanging_nodes(),
                  dealii::ExcMessage(where + "the triangulation has hanging nodes; the VEM trace on a coarse "
                                             "edge with a hanging vertex is not a polynomial, so no continuous "
                                             "FE_Q field matches it. Use interpolate_to_discontinuous()."));
      // FE_Q(k)^2: one DoF per vertex and component, k - 1 per line, (k-1)^2
      // per quad.
      AssertThrow(fe.degree == k && fe.n_dofs_per_vertex() == 2 && fe.n_dofs_per_line() == 2 * layout.nodes_per_edge() &&
                    fe.n_dofs_per_quad(0) == 2 * (k - 1) * (k - 1),
                  dealii::ExcMessage(where + "the finite element must be FESystem(FE_Q(" + std::to_string(k) +
                                     "), 2) for virtual elements of order " + std::to_string(k) + ", not " +
                                     fe.get_name() + "."));

      // the Gauss rule for the cell moment: exact for Q_k times the Jacobian
      // of the bilinear map
      const dealii::QGauss<dim>       quadrature(k + 2);
      const auto                     &mapping = tria.get_reference_cells()[0].template get_default_linear_mapping<dim, dim>();
      dealii::FEValues<dim>           fe_values(mapping, fe, quadrature, dealii::update_values | dealii::update_JxW_values);
      const unsigned int              n_dofs_per_cell = fe.n_dofs_per_cell();
      const auto                     &unit_points     = fe.get_unit_support_points();
      std::vector<dealii::types::global_dof_index> indices(n_dofs_per_cell);
      std::vector<double>             values(n_dofs_per_cell);
      dealii::Vector<double>          local;
      constexpr double                tol = 1e-12;
      auto on_side = [&](const double s) { return std::abs(s) < tol || std::abs(s - 1) < tol; };

      fe_solution.reinit(dof_handler.n_dofs());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const unsigned int p    = map.polygon_of(cell);
          const auto        &loop = mesh.cell(p).vertices;
          const unsigned int N    = loop.size();
          AssertThrow(N == cell->n_vertices(),
                      dealii::ExcMessage(where + "polygon " + std::to_string(p) + " has " + std::to_string(N) +
                                         " vertices, its cell " + std::to_string(cell->n_vertices()) +
                                         " (node insertion or hanging vertices); use "
                                         "interpolate_to_discontinuous()."));
          // local polygon vertex of each cell vertex, and the coordinates
          std::array<unsigned int, 4> local_vertex;
          for (const unsigned int v : cell->vertex_indices())
            {
              const unsigned int mv = map.mesh_vertex(cell->vertex_index(v));
              local_vertex[v]       = std::find(loop.begin(), loop.end(), mv) - loop.begin();
              AssertThrow(local_vertex[v] < N && mesh.vertex(mv) == cell->vertex(v),
                          dealii::ExcMessage(where + "vertex " + std::to_string(v) + " of cell " +
                                             std::to_string(cell->active_cell_index()) +
                                             " is not (or no longer) a vertex of polygon " + std::to_string(p) +
                                             " at the same place."));
            }
          vem_dof_handler.get_dof_values(p, vem_solution, local);
          cell->get_dof_indices(indices);

          // the cell-centre DoFs (one cell moment), one per component
          std::array<unsigned int, 2> centre = {{dealii::numbers::invalid_unsigned_int,
                                                 dealii::numbers::invalid_unsigned_int}};
          for (unsigned int i = 0; i < n_dofs_per_cell; ++i)
            {
              const unsigned int        comp = fe.system_to_component_index(i).first;
              const dealii::Point<dim> &s    = unit_points[i];
              if (on_side(s[0]) && on_side(s[1]))
                {
                  // a vertex: deal.II numbers the vertices of the unit
                  // square lexicographically
                  const unsigned int v = (s[0] > 0.5 ? 1 : 0) + (s[1] > 0.5 ? 2 : 0);
                  values[i]            = local[2 * local_vertex[v] + comp];
                }
              else if (on_side(s[0]) || on_side(s[1]))
                {
                  // a point inside a face: faces 0, 1 at x = 0, 1, faces
                  // 2, 3 at y = 0, 1; the VEM edge node of the polygon edge
                  // joining the face's vertices at the same place
                  const unsigned int f = on_side(s[0]) ? (s[0] > 0.5 ? 1 : 0) : (s[1] > 0.5 ? 3 : 2);
                  const unsigned int a = local_vertex[dealii::GeometryInfo<dim>::face_to_cell_vertices(f, 0)];
                  const unsigned int b = local_vertex[dealii::GeometryInfo<dim>::face_to_cell_vertices(f, 1)];
                  // polygon edge i joins loop[i] and loop[i + 1]
                  const unsigned int edge = ((a + 1) % N == b) ? a : b;
                  AssertThrow((edge + 1) % N == (edge == a ? b : a), dealii::ExcInternalError());
                  // the position along the face from its vertex 0, then
                  // along the polygon edge
                  const double t_face = on_side(s[0]) ? s[1] : s[0];
                  const double t      = (edge == a ? t_face : 1. - t_face);
                  const auto  &positions = layout.edge_node_positions();
                  unsigned int j         = 0;
                  while (j < positions.size() && std::abs(positions[j] - t) > tol)
                    ++j;
                  AssertThrow(j < positions.size(), dealii::ExcInternalError());
                  values[i] = local[2 * layout.edge_node(N, edge, j) + comp];
                }
              else
                {
                  AssertThrow(layout.nodes_per_cell() == 1, dealii::ExcInternalError());
                  centre[comp] = i;
                  values[i]    = 0.;
                }
            }

          if (layout.nodes_per_cell() == 1)
            {
              // choose the centre values so that the cell mean of each
              // component is the VEM cell moment (local node 2N)
              fe_values.reinit(cell);
              std::array<double, 2> integral_without_centre = {{0., 0.}}, integral_of_centre = {{0., 0.}};
              double                area = 0;
              for (const unsigned int q : fe_values.quadrature_point_indices())
                {
                  area += fe_values.JxW(q);
                  for (unsigned int i = 0; i < n_dofs_per_cell; ++i)
                    {
                      const unsigned int comp = fe.system_to_component_index(i).first;
                      const double       phi  = fe_values.shape_value(i, q) * fe_values.JxW(q);
                      if (i == centre[comp])
                        integral_of_centre[comp] += phi;
                      else
                        integral_without_centre[comp] += values[i] * phi;
                    }
                }
              for (unsigned int comp = 0; comp < 2; ++comp)
                {
                  AssertThrow(centre[comp] != dealii::numbers::invalid_unsigned_int, dealii::ExcInternalError());
                  values[centre[comp]] =
                    (area * local[2 * layout.cell_node(N, 0) + comp] - integral_without_centre[comp]) / integral_of_centre[comp];
                }
            }

          // shared DoFs receive the same (global VEM) value from every cell
          for (unsigned int i = 0; i < n_dofs_per_cell; ++i)
            fe_solution[indices[i]] = values[i];
        }
    }



    template void
    interpolate_to_discontinuous(const dealii::Mapping<2, 2> &, const TriangulationMap<2> &, const VEMDoFHandler<2> &,
                                 const dealii::Vector<double> &, const dealii::DoFHandler<2, 2> &,
                                 dealii::Vector<double> &);
    template void
    interpolate_to_discontinuous(const TriangulationMap<2> &, const VEMDoFHandler<2> &, const dealii::Vector<double> &,
                                 const dealii::DoFHandler<2, 2> &, dealii::Vector<double> &);
    template void
    interpolate_to_continuous(const TriangulationMap<2> &, const VEMDoFHandler<2> &, const dealii::Vector<double> &,
                              const dealii::DoFHandler<2, 2> &, dealii::Vector<double> &);
  } // namespace FETransfer
} // namespace dealvem
