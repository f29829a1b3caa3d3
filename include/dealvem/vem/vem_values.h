// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_vem_vem_values_h
#define dealvem_vem_vem_values_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/fe/fe_update_flags.h>
#include <deal.II/lac/vector.h>

#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/virtual_element.h>

#include <vector>

namespace dealvem
{
  /**
   * The virtual element space evaluated on one cell of a VEMDoFHandler's
   * mesh: what deal.II's FEValues is for a finite element. A user's
   * assembly loop reads like step-8:
   * @code
   *   VEMValues<2> vem_values(dof_handler, update_gradients | update_JxW_values);
   *   for (unsigned int c = 0; c < mesh.n_cells(); ++c)
   *     {
   *       vem_values.reinit(c);
   *       // the tangent of the cell's ConstitutiveLaw; for ElasticMaterial
   *       // eps_i : C : eps_j = lambda div_i div_j + 2 mu eps_i : eps_j
   *       const SymmetricTensor<4, 2> C =
   *         laws.get_law(vem_values.material_id()).tangent(SymmetricTensor<2, 2>());
   *       for (unsigned int q = 0; q < vem_values.n_quadrature_points(); ++q)
   *         for (unsigned int i = 0; i < vem_values.dofs_per_cell(); ++i)
   *           for (unsigned int j = 0; j < vem_values.dofs_per_cell(); ++j)
   *             cell_matrix(i, j) += vem_values.shape_symmetric_gradient(i, q) *
   *                                  (C * vem_values.shape_symmetric_gradient(j, q)) *
   *                                  vem_values.JxW(q);
   *       ElasticityOperator<2>::add_stabilization(vem_values.get_element(), cell_matrix);
   *       vem_values.get_dof_indices(local_dof_indices);
   *       constraints.distribute_local_to_global(cell_matrix, cell_rhs, local_dof_indices,
   *                                              system_matrix, system_rhs);
   *     }
   * @endcode
   *
   * The "shape functions" are the projections $\Pi\varphi_i$ of the
   * virtual basis functions (the functions themselves are not known inside
   * the cell): integrals of their products with a quadrature of degree
   * $\ge 2k$ are exact, so the consistency matrix assembled as above equals
   * ElasticityOperator's $\Pi_*^T A\,\Pi_*$ to round-off
   * (tests/vem/vem_values checks this). Quadrature points and weights are
   * those of PolygonGeometry::quadrature() (a triangle fan).
   *
   * Only what the UpdateFlags ask for is computed: with update_default,
   * reinit() computes the space's matrices, the DoF indices and nothing per
   * quadrature point, which is what the matrix-based ElasticityOperator
   * needs.
   */
  template <int dim>
  class VEMValues
  {
  public:
    /**
     * @p flags: any of update_values, update_gradients,
     * update_quadrature_points, update_JxW_values.
     * @p quadrature_degree: the degree of polynomials the cell rule
     * integrates exactly; 0 means 2k.
     */
    VEMValues(const VEMDoFHandler<dim> &dof_handler,
              const dealii::UpdateFlags flags             = dealii::update_default,
              const unsigned int        quadrature_degree = 0);

    /// Evaluate on cell @p c of the DoF handler's mesh.
    void
    reinit(const unsigned int c);

    /// The cell of the last reinit().
    unsigned int
    get_cell() const
    {
      return cell;
    }

    /// The space on the current cell: D, B, the projectors, Gram matrices,
    /// the stabilization form, loads.
    const VirtualElement<dim> &
    get_element() const
    {
      return element;
    }

    /// Switch the reuse of the space's matrices on translated cells on or
    /// off (VirtualElement::set_cell_similarity()).
    void
    set_cell_similarity(const bool enable)
    {
      element.set_cell_similarity(enable);
    }

    /// The DoF handler given to the constructor.
    const VEMDoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /// Material id of the current cell (PolygonalMesh::Cell::material_id);
    /// in debug mode asserts that reinit() has been called.
    dealii::types::material_id
    material_id() const;

    /// Number of DoFs of the current cell: two per node (the vertices, and
    /// for k = 2 also the edge midpoints and the cell moment).
    unsigned int
    dofs_per_cell() const
    {
      return element.n_dofs_per_cell();
    }

    /// Number of points of the cell's quadrature rule; 0 when neither
    /// quadrature points nor JxW values were asked for in the UpdateFlags.
    unsigned int
    n_quadrature_points() const
    {
      return weights.size();
    }

    /// Global DoF indices of the cell in the local order.
    void
    get_dof_indices(std::vector<dealii::types::global_dof_index> &indices) const
    {
      indices = dof_indices;
    }

    /// Global DoF indices of the cell in the local order, without a copy.
    const std::vector<dealii::types::global_dof_index> &
    get_dof_indices() const
    {
      return dof_indices;
    }

    /// Quadrature point @p q of the cell, in physical coordinates. Throws
    /// ExcMessage when update_quadrature_points (or update_values,
    /// update_gradients, which imply it) was not requested.
    const dealii::Point<dim> &
    quadrature_point(const unsigned int q) const;

    /// All quadrature points of the cell; throws as quadrature_point().
    const std::vector<dealii::Point<dim>> &
    get_quadrature_points() const;

    /// Weight of quadrature point @p q, the Jacobian already included (the
    /// weights of a cell sum to its area). Throws ExcMessage when
    /// update_JxW_values was not requested.
    double
    JxW(const unsigned int q) const;

    /// $\Pi\varphi_i$ at quadrature point @p q (needs update_values).
    const dealii::Tensor<1, dim> &
    shape_value(const unsigned int i, const unsigned int q) const;

    /// $\nabla\Pi\varphi_i$ (row = component; needs update_gradients).
    const dealii::Tensor<2, dim> &
    shape_grad(const unsigned int i, const unsigned int q) const;

    /// $\varepsilon(\Pi\varphi_i)$ (needs update_gradients).
    dealii::SymmetricTensor<2, dim>
    shape_symmetric_gradient(const unsigned int i, const unsigned int q) const
    {
      return dealii::symmetrize(shape_grad(i, q));
    }

    /// $\mathrm{div}\,\Pi\varphi_i$ (needs update_gradients).
    double
    shape_divergence(const unsigned int i, const unsigned int q) const
    {
      return dealii::trace(shape_grad(i, q));
    }

    /// Values of $\Pi u_h$ at the quadrature points for a global vector
    /// @p u (needs update_quadrature_points).
    void
    get_function_values(const dealii::Vector<double>        &u,
                        std::vector<dealii::Tensor<1, dim>> &values) const;

    /// Gradients of $\Pi u_h$ at the quadrature points (needs
    /// update_quadrature_points).
    void
    get_function_gradients(const dealii::Vector<double>        &u,
                           std::vector<dealii::Tensor<2, dim>> &gradients) const;

    /// $\Pi^0\nabla\varphi_i$, the full-gradient projection of the shape
    /// function $\varphi_i$ (VirtualElement::get_gradient_projector()), at
    /// quadrature point @p q (row = component; needs
    /// update_quadrature_points). Its symmetric part is
    /// shape_symmetric_gradient(); the antisymmetric part is the projected
    /// rotation, which $\nabla\Pi\varphi_i$ does not carry.
    dealii::Tensor<2, dim>
    shape_gradient_projection(const unsigned int i, const unsigned int q) const;

    /// $\Pi^0\nabla u_h$ at the quadrature points for a global vector
    /// @p u (needs update_quadrature_points): the deformation gradient of a
    /// finite-strain computation is $I$ plus these.
    void
    get_function_gradient_projections(const dealii::Vector<double>        &u,
                                      std::vector<dealii::Tensor<2, dim>> &gradients) const;

    /// Number of edges of the cell (= vertices).
    unsigned int
    n_edges() const;

    /// Boundary id of local edge @p e, or
    /// dealii::numbers::internal_face_boundary_id for an interior edge.
    dealii::types::boundary_id
    edge_boundary_id(const unsigned int e) const;

    /// Local body-force vector (VirtualElement::body_force_vector()).
    void
    body_force_vector(const dealii::Function<dim> &f, dealii::Vector<double> &F) const
    {
      element.body_force_vector(f, F);
    }

    /// Add a traction on local edge @p e (VirtualElement::add_edge_traction()).
    void
    add_edge_traction(const unsigned int           e,
                      const dealii::Function<dim> &g,
                      dealii::Vector<double>      &F) const
    {
      element.add_edge_traction(e, g, F);
    }

    /// Add a normal pressure on local edge @p e.
    void
    add_edge_pressure(const unsigned int           e,
                      const dealii::Function<dim> &p,
                      dealii::Vector<double>      &F) const
    {
      element.add_edge_pressure(e, p, F);
    }

  private:
    const VEMDoFHandler<dim>                    &dof_handler;
    dealii::UpdateFlags                          flags;
    unsigned int                                 quadrature_degree;
    VirtualElement<dim>                          element;
    unsigned int                                 cell = dealii::numbers::invalid_unsigned_int;
    std::vector<dealii::types::global_dof_index> dof_indices;
    std::vector<dealii::Point<dim>>              vertices, points;
    std::vector<double>                          weights;
    // values[q * n_dofs + i], gradients[q * n_dofs + i]
    std::vector<dealii::Tensor<1, dim>> values;
    std::vector<dealii::Tensor<2, dim>> gradients;
    mutable dealii::Vector<double>      local, coefficients;
  };
} // namespace dealvem

#endif
