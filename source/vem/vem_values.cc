// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/base/number_string.h>
#include <dealvem/vem/vem_values.h>

#include <cmath>

#include <string>

namespace dealvem
{
  namespace
  {
    void
    check_flag(const dealii::UpdateFlags flags, const dealii::UpdateFlags needed, const char *what)
    {
      AssertThrow((flags & needed) != 0,
                  dealii::ExcMessage(std::string("VEMValues: ") + what +
                                     " was not requested in the UpdateFlags given to the constructor."));
    }

    // The order of the DoF handler's space; a handler whose distribute_dofs()
    // has not been called has order 0, which is reported as such rather than
    // as an invalid order of the element.
    template <int dim>
    unsigned int
    distributed_degree(const VEMDoFHandler<dim> &dof_handler)
    {
      AssertThrow(dof_handler.get_degree() != 0, ExcNoDoFsDistributed());
      return dof_handler.get_degree();
    }
  } // namespace



  template <int dim>
  VEMValues<dim>::VEMValues(const VEMDoFHandler<dim> &dof_handler,
                            const dealii::UpdateFlags flags,
                            const unsigned int        quadrature_degree)
    : dof_handler(dof_handler)
    , flags(flags)
    , quadrature_degree(quadrature_degree == 0 ? 2 * distributed_degree(dof_handler) : quadrature_degree)
    , element(distributed_degree(dof_handler))
  {
    // values and gradients are evaluated at the quadrature points
    if ((flags & (dealii::update_values | dealii::update_gradients)) != 0)
      this->flags = this->flags | dealii::update_quadrature_points;
  }



  template <int dim>
  void
  VEMValues<dim>::reinit(const unsigned int c)
  {
    const auto &mesh = dof_handler.get_mesh();
    AssertThrow(c < mesh.n_cells(),
                dealii::ExcMessage("VEMValues::reinit(): cell " + std::to_string(c) +
                                   " does not exist; mesh '" + mesh.name + "' has " +
                                   std::to_string(mesh.n_cells()) + " cells."));
    cell = c;
    mesh.cell_vertices(c, vertices);
    element.reinit(vertices);
    {
      // a cell so elongated that its scaled monomials are no longer
      // independent in double precision gives a projector of infinities or
      // NaNs, and every matrix assembled from it is useless
      const auto &P      = element.get_projector();
      bool        finite = true;
      for (unsigned int a = 0; a < P.m() && finite; ++a)
        for (unsigned int i = 0; i < P.n() && finite; ++i)
          finite = std::isfinite(P(a, i));
      if (!finite)
        {
          const auto       &g = element.get_geometry();
          const double      d = g.diameter(), A = g.area();
          const std::string what = "mesh '" + mesh.name + "': cell " + std::to_string(c) + " (diameter " +
                                   internal::number_string(d) + ", area " + internal::number_string(A) +
                                   ") is too elongated for the virtual element: its projector is not finite in "
                                   "double precision (its scaled monomials are not independent at diameter^2 / "
                                   "area = " +
                                   internal::number_string(d * d / A) +
                                   "). Subdivide the cell or the mesh along its long side.";
          AssertThrow(false, dealii::ExcMessage(what));
        }
    }
    dof_handler.get_dof_indices(c, dof_indices);
    if ((flags & (dealii::update_quadrature_points | dealii::update_JxW_values)) == 0)
      {
        points.clear();
        weights.clear();
        return;
      }
    element.get_geometry().quadrature(quadrature_degree, points, weights);
    const unsigned int n = element.n_dofs_per_cell(), n_q = points.size(),
                       n_p = element.n_polynomials();
    const auto &P = element.get_projector();
    if ((flags & dealii::update_values) != 0)
      {
        values.assign(std::size_t(n_q) * n, dealii::Tensor<1, dim>());
        for (unsigned int q = 0; q < n_q; ++q)
          for (unsigned int a = 0; a < n_p; ++a)
            {
              const dealii::Tensor<1, dim> p = element.polynomial_value(a, points[q]);
              for (unsigned int i = 0; i < n; ++i)
                if (P(a, i) != 0.)
                  values[std::size_t(q) * n + i] += P(a, i) * p;
            }
      }
    if ((flags & dealii::update_gradients) != 0)
      {
        gradients.assign(std::size_t(n_q) * n, dealii::Tensor<2, dim>());
        // the rigid translations have no gradient
        for (unsigned int q = 0; q < n_q; ++q)
          for (unsigned int a = 2; a < n_p; ++a)
            {
              const dealii::Tensor<2, dim> g = element.polynomial_gradient(a, points[q]);
              for (unsigned int i = 0; i < n; ++i)
                if (P(a, i) != 0.)
                  gradients[std::size_t(q) * n + i] += P(a, i) * g;
            }
      }
  }



  template <int dim>
  dealii::types::material_id
  VEMValues<dim>::material_id() const
  {
    Assert(cell != dealii::numbers::invalid_unsigned_int, dealii::ExcMessage("call reinit() first"));
    return dof_handler.get_mesh().cell(cell).material_id;
  }



  template <int dim>
  const dealii::Point<dim> &
  VEMValues<dim>::quadrature_point(const unsigned int q) const
  {
    check_flag(flags, dealii::update_quadrature_points, "update_quadrature_points");
    AssertIndexRange(q, points.size());
    return points[q];
  }



  template <int dim>
  const std::vector<dealii::Point<dim>> &
  VEMValues<dim>::get_quadrature_points() const
  {
    check_flag(flags, dealii::update_quadrature_points, "update_quadrature_points");
    return points;
  }



  template <int dim>
  double
  VEMValues<dim>::JxW(const unsigned int q) const
  {
    check_flag(flags, dealii::update_JxW_values, "update_JxW_values");
    AssertIndexRange(q, weights.size());
    return weights[q];
  }



  template <int dim>
  const dealii::Tensor<1, dim> &
  VEMValues<dim>::shape_value(const unsigned int i, const unsigned int q) const
  {
    check_flag(flags, dealii::update_values, "update_values");
    AssertIndexRange(i, dofs_per_cell());
    AssertIndexRange(q, points.size());
    return values[std::size_t(q) * dofs_per_cell() + i];
  }



  template <int dim>
  const dealii::Tensor<2, dim> &
  VEMValues<dim>::shape_grad(const unsigned int i, const unsigned int q) const
  {
    check_flag(flags, dealii::update_gradients, "update_gradients");
    AssertIndexRange(i, dofs_per_cell());
    AssertIndexRange(q, points.size());
    return gradients[std::size_t(q) * dofs_per_cell() + i];
  }



  template <int dim>
  void
  VEMValues<dim>::get_function_values(const dealii::Vector<double>        &u,
                                      std::vector<dealii::Tensor<1, dim>> &v) const
  {
    check_flag(flags, dealii::update_quadrature_points, "update_quadrature_points");
    dof_handler.get_dof_values(cell, u, local);
    element.project(local, coefficients);
    v.resize(points.size());
    for (unsigned int q = 0; q < points.size(); ++q)
      v[q] = element.projection_value(coefficients, points[q]);
  }



  template <int dim>
  void
  VEMValues<dim>::get_function_gradients(const dealii::Vector<double>        &u,
                                         std::vector<dealii::Tensor<2, dim>> &g) const
  {
    check_flag(flags, dealii::update_quadrature_points, "update_quadrature_points");
    dof_handler.get_dof_values(cell, u, local);
    element.project(local, coefficients);
    g.resize(points.size());
    for (unsigned int q = 0; q < points.size(); ++q)
      g[q] = element.projection_gradient(coefficients, points[q]);
  }



  template <int dim>
  dealii::Tensor<2, dim>
  VEMValues<dim>::shape_gradient_projection(const unsigned int i, const unsigned int q) const
  {
    check_flag(flags, dealii::update_quadrature_points, "update_quadrature_points");
    AssertIndexRange(i, dofs_per_cell());
    AssertIndexRange(q, points.size());
    return element.shape_gradient_projection(i, points[q]);
  }



  template <int dim>
  void
  VEMValues<dim>::get_function_gradient_projections(const dealii::Vector<double>        &u,
                                                    std::vector<dealii::Tensor<2, dim>> &g) const
  {
    check_flag(flags, dealii::update_quadrature_points, "update_quadrature_points");
    dof_handler.get_dof_values(cell, u, local);
    element.project_gradient(local, coefficients);
    g.resize(points.size());
    for (unsigned int q = 0; q < points.size(); ++q)
      g[q] = element.gradient_projection_value(coefficients, points[q]);
  }



  template <int dim>
  unsigned int
  VEMValues<dim>::n_edges() const
  {
    Assert(cell != dealii::numbers::invalid_unsigned_int, dealii::ExcMessage("call reinit() first"));
    return dof_handler.get_mesh().cell(cell).edges.size();
  }



  template <int dim>
  dealii::types::boundary_id
  VEMValues<dim>::edge_boundary_id(const unsigned int e) const
  {
    Assert(cell != dealii::numbers::invalid_unsigned_int, dealii::ExcMessage("call reinit() first"));
    const auto &mesh = dof_handler.get_mesh();
    const auto &c    = mesh.cell(cell);
    AssertIndexRange(e, c.edges.size());
    const auto &edge = mesh.edge(c.edges[e]);
    return edge.at_boundary() ? edge.boundary_id : dealii::numbers::internal_face_boundary_id;
  }

  template class VEMValues<2>;
} // namespace dealvem
