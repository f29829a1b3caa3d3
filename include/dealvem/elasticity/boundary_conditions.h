// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_boundary_conditions_h
#define dealvem_elasticity_boundary_conditions_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>

#include <dealvem/vem/vem_dof_handler.h>

#include <array>
#include <map>
#include <set>

namespace dealvem
{
  /**
   * Constraints on the displacement, written into a
   * dealii::AffineConstraints object (the deal.II way: the assembler then
   * condenses them with distribute_local_to_global).
   *
   * All functions leave DoFs that are already constrained alone, so the
   * order of the calls sets the priority (first call wins), as with
   * deal.II's VectorTools::interpolate_boundary_values.
   */
  namespace BoundaryConditions
  {
    /**
     * Dirichlet data: the components selected by @p mask of the nodes
     * (vertices and, for k = 2, edge midpoints) on the boundary edges with
     * the given ids are set to the values of @p g (2 components).
     * For k = 2 the midpoint DoF is a point value, so this interpolates the
     * data exactly for quadratic g.
     */
    template <int dim>
    void
    interpolate_boundary_values(const VEMDoFHandler<dim>                  &dof_handler,
                                const std::set<dealii::types::boundary_id> &ids,
                                const dealii::Function<dim>               &g,
                                const std::array<bool, 2>                 &mask,
                                dealii::AffineConstraints<double>         &constraints);

    /**
     * Roller: zero normal displacement $u\cdot n = 0$ on the boundary part
     * @p id, which must be straight (any inclination); AssertThrow names the
     * boundary id and the first edge that is not aligned otherwise.
     * Each node gets the constraint $u_x = -(n_y/n_x)u_y$ if $|n_x|\ge|n_y|$,
     * else $u_y = -(n_x/n_y)u_x$.
     */
    template <int dim>
    void
    add_roller(const VEMDoFHandler<dim>          &dof_handler,
               const dealii::types::boundary_id   id,
               dealii::AffineConstraints<double> &constraints);

    /**
     * Single-point constraint: component @p component of the mesh vertex
     * nearest to @p p gets the value @p value. AssertThrow if no vertex
     * lies within @p relative_tolerance times the smallest cell diameter
     * of @p p (the message gives the point and the nearest vertex).
     * Returns the vertex index.
     */
    template <int dim>
    unsigned int
    add_point_constraint(const VEMDoFHandler<dim>          &dof_handler,
                         const dealii::Point<dim>          &p,
                         const unsigned int                 component,
                         const double                       value,
                         dealii::AffineConstraints<double> &constraints,
                         const double                       relative_tolerance = 1e-6);

    /**
     * Check that every body (material id) is held against all three
     * rigid-body motions by the constraints: the homogeneous constraints
     * restricted to the body's rigid-body modes must have rank 3. Throws
     * ExcMessage naming the body and the free motions ("unsupported body /
     * rigid-body mode") otherwise. @p extra_restraints may add, per
     * material id, further linear restrictions of the rigid-body modes
     * (rows of 3 numbers: the restriction applied to the x-translation,
     * y-translation and rotation modes), e.g. from contact constraints.
     */
    template <int dim>
    void
    check_rigid_body_support(
      const VEMDoFHandler<dim>                                               &dof_handler,
      const dealii::AffineConstraints<double>                                &constraints,
      const std::map<dealii::types::material_id, std::vector<std::array<double, 3>>> &extra_restraints = {});
  } // namespace BoundaryConditions
} // namespace dealvem

#endif
