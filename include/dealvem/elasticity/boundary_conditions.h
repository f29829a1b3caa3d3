// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_boundary_conditions_h
#define dealvem_elasticity_boundary_conditions_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>

#include <dealvem/vem/vem_dof_handler.h>

#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

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
     * For error messages: who wrote the constraint of a DoF (for example
     * the parameter entry "Boundary conditions and loads/Roller entry '2'").
     * Functions that get such a map name the earlier condition when a new
     * one collides with it.
     */
    using ConstraintOrigins = std::map<dealii::types::global_dof_index, std::string>;

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
     * at @p p gets the value @p value.
     *
     * The vertex is searched among all vertices, or, if @p body is not
     * numbers::invalid_material_id, among the vertices of the cells with
     * material id @p body (needed where two bodies have vertices at the same
     * point). AssertThrow
     * - if no vertex (of the body) lies within @p relative_tolerance times
     *   the smallest cell diameter of @p p (the message gives the point and
     *   the nearest vertex);
     * - if no body is given and vertices of two bodies lie there (the
     *   message asks to name the body);
     * - if the DoF is constrained already in a way that differs from
     *   u = @p value: to another value, or to other DoFs (a roller). The
     *   message names the earlier condition through @p origins, if given.
     *   A constraint to the same value is redundant and accepted.
     *
     * @p name, if not empty, names the parameter entry in the messages.
     * Returns the vertex index.
     */
    template <int dim>
    unsigned int
    add_point_constraint(const VEMDoFHandler<dim>          &dof_handler,
                         const dealii::Point<dim>          &p,
                         const unsigned int                 component,
                         const double                       value,
                         dealii::AffineConstraints<double> &constraints,
                         const double                       relative_tolerance = 1e-6,
                         const dealii::types::material_id   body = dealii::numbers::invalid_material_id,
                         const std::string                 &name = "",
                         const ConstraintOrigins           *origins = nullptr);

    /**
     * The geometry of a rigid boundary part: its nodes (vertices and, for
     * k = 2, edge midpoints on the boundary edges with id @p id), the
     * arc-length weighted centroid, and the two reference nodes that carry
     * its motion: A, the node nearest to the centroid, and B, the node
     * farthest from A. With d = x_B - x_A, B keeps its component
     * @p b_free_component (the one in which d is smaller, "normal to AB"),
     * the other one is constrained so that |AB| stays fixed.
     */
    template <int dim>
    struct RigidBoundary
    {
      /// The boundary id of the part.
      dealii::types::boundary_id id;
      /// The nodes on its boundary edges (VEMDoFHandler::boundary_nodes()),
      /// sorted.
      std::vector<unsigned int>  nodes;
      /// Reference node A: the node of the part nearest to centroid.
      unsigned int               node_a;
      /// Reference node B: the node of the part farthest from A.
      unsigned int               node_b;
      /// The component (0 = x, 1 = y) of B left free: the one in which
      /// $x_B - x_A$ is smaller in magnitude (y on ties).
      unsigned int               b_free_component;
      /// Location of node A.
      dealii::Point<dim>         point_a;
      /// Location of node B.
      dealii::Point<dim>         point_b;
      /// Centroid of the part's boundary edges, weighted by arc length.
      dealii::Point<dim>         centroid;
      /// Total length of the part's boundary edges.
      double                     length;
    };

    /// Compute the RigidBoundary of boundary id @p id (AssertThrow if no
    /// boundary edge carries it).
    template <int dim>
    RigidBoundary<dim>
    rigid_boundary_geometry(const VEMDoFHandler<dim> &dof_handler, const dealii::types::boundary_id id);

    /**
     * Rigid boundary part: all nodes on the boundary edges with id @p id
     * move as one rigid body, u(x) = u_A + theta (-(y - y_A), x - x_A),
     * written as affine constraints on the three DoFs that stay free (both
     * components of A, component RigidBoundary::b_free_component of B):
     * with d = x_B - x_A, p = (-d_y, d_x) and o = b_free_component,
     * theta = (u_{B,o} - u_{A,o}) / p_o, and every other DoF of the part
     * (including the other component of B) is u_A + theta perp(x - x_A).
     * No new unknowns; rigid-body modes satisfy every line exactly, so the
     * lines hold no body (check_rigid_body_support() does not count them).
     *
     * The part may share constraints with other conditions only through A
     * and the kept component of B, and only with constraints of a single
     * node (Dirichlet, roller or point data, e.g. a hinge at A): any other
     * constrained DoF of the part stops with a message naming the part (by
     * @p name if not empty) and the earlier condition (through @p origins).
     */
    template <int dim>
    RigidBoundary<dim>
    add_rigid_boundary(const VEMDoFHandler<dim>          &dof_handler,
                       const dealii::types::boundary_id   id,
                       dealii::AffineConstraints<double> &constraints,
                       const std::string                 &name = "",
                       const ConstraintOrigins           *origins = nullptr);

    /**
     * The generalized forces of a resultant force @p force at the centroid
     * of the rigid part and a moment @p moment (counter-clockwise) about it,
     * on the free DoFs of A and B: the derivatives of the virtual work
     * force . u(x_0) + moment theta with respect to u_{A,x}, u_{A,y},
     * u_{B,o}. They are entries of the unconstrained load vector (as
     * ElasticityAssembler::add_nodal_load takes them).
     */
    template <int dim>
    std::vector<std::pair<dealii::types::global_dof_index, double>>
    rigid_boundary_load(const RigidBoundary<dim>     &part,
                        const dealii::Tensor<1, dim> &force,
                        const double                  moment);

    /**
     * A boundary part turned rigidly about a centre $c$ (a gear's bore
     * turned by an angle or loaded by a torque): what
     * add_prescribed_rotation() and add_torque_rotation() wrote, and what
     * reads the angle back from a solution.
     */
    template <int dim>
    struct RotationAboutCentre
    {
      /// The boundary id of the part.
      dealii::types::boundary_id id = dealii::numbers::invalid_boundary_id;
      /// The centre $c$ of the rotation.
      dealii::Point<dim> centre;
      /// The nodes on the part's boundary edges (vertices and, for k = 2,
      /// edge midpoints; VEMDoFHandler::boundary_nodes()), sorted.
      std::vector<unsigned int> nodes;
      /// Whether the angle is an unknown driven by a torque
      /// (add_torque_rotation()); false: prescribed (add_prescribed_rotation()).
      bool torque_driven = false;
      /// The prescribed angle (counter-clockwise, radians); 0 for a
      /// torque-driven part.
      double prescribed_angle = 0;
      /// The DoFs of the constraint lines this condition wrote (a DoF
      /// constrained before to the same value is not among them); their
      /// reactions are the part's (SupportReactions::rotation()).
      std::vector<dealii::types::global_dof_index> lines;
      /// Torque-driven part: the master DoF carrying the rotation,
      /// $u_m = \theta\,\mathrm{perp}(x_m - c)_{c_m}$; invalid otherwise.
      dealii::types::global_dof_index master_dof = dealii::numbers::invalid_dof_index;
      /// Torque-driven part: the arm $\mathrm{perp}(x_m - c)_{c_m}$ of the
      /// master DoF (the largest component in magnitude over the part).
      double master_arm = 0;

      /// The rotation angle of the part in the displacement @p u: the
      /// unknown $\theta = u_m / $ master_arm of a torque-driven part, the
      /// prescribed angle otherwise.
      template <typename VectorType>
      double
      angle(const VectorType &u) const
      {
        return torque_driven ? double(u[master_dof]) / master_arm : prescribed_angle;
      }
    };

    /**
     * The nodes of boundary part @p id and, for a torque, its master DoF
     * (the node and component with the largest $|\mathrm{perp}(x - c)|$
     * component, perp(v) = (-v_y, v_x); the first on ties). AssertThrow if
     * no boundary edge carries @p id, if @p centre is not finite, or if all
     * nodes of the part lie at the centre.
     */
    template <int dim>
    RotationAboutCentre<dim>
    rotation_geometry(const VEMDoFHandler<dim>        &dof_handler,
                      const dealii::types::boundary_id id,
                      const dealii::Point<dim>        &centre,
                      const std::string               &name = "");

    /**
     * Prescribed rotation of boundary part @p id about @p centre by the angle
     * @p angle (counter-clockwise, radians): Dirichlet data
     * $u(x) = (R(\theta) - I)(x - c)$ on both components of every node of
     * the part (vertices and, k = 2, edge midpoints), with the exact rotation
     * matrix (not linearized), so that the same data turn a bore at finite
     * strain or finite sliding. At small strain the data are the exact
     * rotation too: its linear strain $(\cos\theta - 1)I$ is $O(\theta^2)$.
     *
     * A DoF of the part constrained already (by another entry) must have the
     * same value and no coupling, else AssertThrow names the part (@p name,
     * if not empty) and the earlier condition (through @p origins). Also
     * AssertThrow for an unknown boundary id, a centre or angle that is not
     * finite.
     */
    template <int dim>
    RotationAboutCentre<dim>
    add_prescribed_rotation(const VEMDoFHandler<dim>          &dof_handler,
                            const dealii::types::boundary_id   id,
                            const dealii::Point<dim>          &centre,
                            const double                       angle,
                            dealii::AffineConstraints<double> &constraints,
                            const std::string                 &name    = "",
                            const ConstraintOrigins           *origins = nullptr);

    /**
     * Rotation of boundary part @p id about @p centre with the angle
     * $\theta$ an unknown (small strain): every DoF of the part is
     * constrained as $u = \theta\,\mathrm{perp}(x - c)$ through affine
     * constraints on one master DoF (RotationAboutCentre::master_dof, the
     * node and component of largest arm, for conditioning), so the part
     * keeps its shape and turns about $c$ without translating. Load it with
     * rotation_torque_load(); read $\theta$ with RotationAboutCentre::angle().
     * The lines hold the body against translations, not against the
     * rotation about $c$: that one the torque drives and something else
     * (a clamped rim, contact) must resist.
     *
     * Every DoF of the part must be free: a DoF constrained already stops
     * with a message naming the part (@p name if not empty) and the earlier
     * condition (through @p origins). AssertThrow also for an unknown
     * boundary id and a centre that is not finite.
     */
    template <int dim>
    RotationAboutCentre<dim>
    add_torque_rotation(const VEMDoFHandler<dim>          &dof_handler,
                        const dealii::types::boundary_id   id,
                        const dealii::Point<dim>          &centre,
                        dealii::AffineConstraints<double> &constraints,
                        const std::string                 &name    = "",
                        const ConstraintOrigins           *origins = nullptr);

    /**
     * The generalized force of a torque @p torque (counter-clockwise) about
     * the centre of a torque-driven part: one entry on the master DoF,
     * @p torque / master_arm, whose virtual work on $u_m = \theta$
     * master_arm is torque $\cdot\,\theta$. An entry of the unconstrained
     * load vector (ElasticityAssembler::add_nodal_load()).
     */
    template <int dim>
    std::vector<std::pair<dealii::types::global_dof_index, double>>
    rotation_torque_load(const RotationAboutCentre<dim> &part, const double torque);

    /**
     * Check that every body (material id) is held against all three
     * rigid-body motions by the constraints: the homogeneous constraints
     * restricted to the body's rigid-body modes must have rank 3. Throws
     * ExcMessage naming the body and the free motions ("unsupported body /
     * rigid-body mode") otherwise. @p extra_restraints may add, per
     * material id, further linear restrictions of the rigid-body modes
     * (rows of 3 numbers: the restriction applied to the x-translation,
     * y-translation and rotation modes), e.g. from contact constraints.
     * Constraint lines that vanish on the rigid-body modes up to round-off
     * (those of add_rigid_boundary()) restrain nothing and are skipped, so
     * that a body held by nothing else is reported.
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
