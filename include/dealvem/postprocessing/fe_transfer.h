// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_postprocessing_fe_transfer_h
#define dealvem_postprocessing_fe_transfer_h

#include <deal.II/lac/vector.h>

#include <dealvem/mesh/triangulation_map.h>
#include <dealvem/vem/vem_dof_handler.h>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
  template <int dim, int spacedim>
  class Mapping;
} // namespace dealii

namespace dealvem
{
  /**
   * Transfer of a virtual element solution to finite element fields on the
   * deal.II triangulation the polygons were made from (see
   * TriangulationMap), so that a deal.II program can use its own tools on
   * it: DataOut, KellyErrorEstimator, VectorTools::integrate_difference,
   * FEFieldFunction, SolutionTransfer for the next mesh.
   *
   * Two transfers are offered.
   *
   * <h3>Discontinuous: the projection</h3>
   * interpolate_to_discontinuous() evaluates, on every active cell $K$, the
   * projection $\Pi^\nabla_k u_h$ of the polygon made from $K$ at the support
   * points of a discontinuous element (FE_DGQ, FE_DGP, FE_SimplexDGP, in an
   * FESystem with two components) and takes these values as the cell's
   * DoFs. For the enhanced virtual element space used by dealvem, the
   * $L^2$ projection $\Pi^0_k u_h$ is the same polynomial (the moments of
   * degree $k$ of $u_h$ are defined as those of $\Pi^\nabla_k u_h$), so
   * there is only one projection to transfer.
   *
   * With FE_DGQ(r), r >= k, on quadrilaterals and the bilinear mapping
   * MappingQ1 (the default) the transfer is exact: a polynomial of degree
   * $k$ in $x, y$ composed with the bilinear map $F_K$ is a polynomial of
   * degree $k$ in each reference coordinate, so $\Pi^\nabla_k u_h \in
   * Q_r\circ F_K^{-1}$ and the interpolant is $\Pi^\nabla_k u_h$ itself, on
   * parallelograms and on general straight-sided quadrilaterals alike.
   * Error norms computed with VectorTools::integrate_difference then equal
   * those of dealvem's compute_errors() up to quadrature. On triangles
   * with FE_SimplexDGP(r), r >= k, and the affine mapping the same holds.
   * Lower degrees interpolate.
   *
   * <h3>Continuous: the degrees of freedom</h3>
   * interpolate_to_continuous() builds a continuous FE_Q(k)^2 field (k the
   * order of the virtual elements) on a quadrilateral triangulation without
   * hanging nodes whose polygons are still its cells. Its nodal values are
   * the VEM degrees of freedom: vertex values, for k = 2 the edge-midpoint
   * values (the FE_Q(2) support point of an edge is its midpoint under
   * MappingQ1), and the FE_Q(2) cell-centre value is chosen so that the
   * field has the VEM cell moment $\frac1{|K|}\int_K u_h$. This is exact in
   * the following sense: on every edge the field's trace is the trace of the
   * virtual function $u_h$ (both are the polynomial of degree $k$ through
   * the edge's nodal values), and the field has all VEM degrees of freedom
   * of $u_h$, hence the same projection $\Pi^\nabla_k$ on every cell (which
   * is computed from the degrees of freedom only). It is not $u_h$ inside
   * the cells (u_h is not known there), and it is not $\Pi^\nabla_k u_h$
   * (which jumps across edges): its errors differ from those of the
   * projection and converge at the same rates. For k = 1 the vertex values
   * ARE the FE_Q(1) nodal values, and the cell average of the field's
   * gradient is $\nabla\Pi^\nabla_1 u_h$.
   *
   * Both functions check that the triangulation has not changed since the
   * map was made, that the DoFHandler is built on it, that the VEM DoF
   * handler belongs to the map's mesh and is up to date for it (see
   * VEMDoFHandler::check_mesh_unchanged()). The mesh itself may have been
   * changed after the map was made, as long as its polygons keep their
   * numbers: node insertion on a contact interface splits edges of the
   * polygons; the discontinuous transfer then evaluates the projection on
   * the changed polygon, and the continuous transfer refuses polygons that
   * are no longer the four vertices of their cell.
   */
  namespace FETransfer
  {
    /**
     * Set @p fe_solution (resized to dof_handler.n_dofs()) to the
     * interpolant of $\Pi^\nabla_k u_h$ on each cell (see above).
     * @p dof_handler must use a discontinuous element with two vector
     * components and support points (every DoF interior to a cell).
     * @p mapping maps the support points into the cell; use the mapping
     * that DataOut and integrate_difference use later.
     */
    template <int dim>
    void
    interpolate_to_discontinuous(const dealii::Mapping<dim, dim>    &mapping,
                                 const TriangulationMap<dim>        &map,
                                 const VEMDoFHandler<dim>           &vem_dof_handler,
                                 const dealii::Vector<double>       &vem_solution,
                                 const dealii::DoFHandler<dim, dim> &dof_handler,
                                 dealii::Vector<double>             &fe_solution);

    /// The same with the default linear mapping of the cells (MappingQ1 on
    /// quadrilaterals, MappingFE with FE_SimplexP(1) on triangles).
    template <int dim>
    void
    interpolate_to_discontinuous(const TriangulationMap<dim>        &map,
                                 const VEMDoFHandler<dim>           &vem_dof_handler,
                                 const dealii::Vector<double>       &vem_solution,
                                 const dealii::DoFHandler<dim, dim> &dof_handler,
                                 dealii::Vector<double>             &fe_solution);

    /**
     * Set @p fe_solution to the continuous FE_Q(k)^2 field with the VEM
     * degrees of freedom of @p vem_solution (see above). @p dof_handler must
     * use FESystem(FE_Q(k), 2) (or FE_Q(k)^2) with k =
     * vem_dof_handler.get_degree(), on quadrilaterals, without hanging nodes;
     * every polygon must still have exactly the four vertices of its cell
     * (node insertion adds vertices: then use the discontinuous transfer).
     */
    template <int dim>
    void
    interpolate_to_continuous(const TriangulationMap<dim>        &map,
                              const VEMDoFHandler<dim>           &vem_dof_handler,
                              const dealii::Vector<double>       &vem_solution,
                              const dealii::DoFHandler<dim, dim> &dof_handler,
                              dealii::Vector<double>             &fe_solution);
  } // namespace FETransfer
} // namespace dealvem

#endif
