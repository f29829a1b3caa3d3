// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_support_reactions_h
#define dealvem_elasticity_support_reactions_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/boundary_conditions.h>

#include <string>
#include <vector>

namespace dealvem
{
  /**
   * The force and the moment that each support (a boundary id carrying
   * Dirichlet data or a roller, a point constraint) exerts on the bodies:
   * what holds a turned bore, a clamped end or a pressed punch.
   *
   * With the unbalanced nodal force $\rho = f_{ext} + e - f_{int}(u)$ of a
   * converged solve (applied loads $f_{ext}$, contact forces $e$, internal
   * forces $f_{int}$; at small strain $f_{int} = Ku$), every free DoF has
   * $\rho_i = 0$, and a constraint line $u_s = \sum_j a_{sj} u_j + g_s$
   * carries the nodal reaction
   * @f[ P = -\rho_s\Big(e_s - \sum_j a_{sj}\,e_j\Big), @f]
   * the force the constraint adds so that $\rho + P$ vanishes on the
   * condensed equations (ForceBalance uses the same rule). A plain
   * Dirichlet line gives $-\rho_s$ on its own DoF, which is
   * $f_{int} - f_{ext} - e$ there; a roller line $u_x = a\,u_y$ gives a force normal to the
   * roller on both components of its node. A DoF is one component of a
   * node (DoF $2m + c$ is component $c$ of node $m$), whatever the order
   * $k$: the reaction at a vertex or an edge midpoint of $k = 2$ is the
   * row of the residual at that node.
   *
   * compute() sums the nodal reactions of the lines each support wrote
   * (Support::lines) into its force $R = \sum P$ and its moment about a
   * point $x_0$,
   * @f[ M = \sum_m (x_m - x_0)\times P_m
   *      = \sum_m (x_m - x_0)_x P_{m,y} - (x_m - x_0)_y P_{m,x}, @f]
   * counter-clockwise positive, with $x_m$ the position of the node the
   * caller gives: the reference position at small strain, the current one
   * $X + u$ at finite strain. The forces and moments are those acting on
   * the bodies (a support that holds a body up against gravity pushes
   * upwards). With every support, the applied loads sum to minus the
   * reactions: the global balance of the assembly.
   */
  class SupportReactions
  {
  public:
    /// One support: the constraint lines it wrote.
    struct Support
    {
      /// How the messages name it: "boundary 2", "point 0 (0.5, 0)".
      std::string                                 name;
      /// A name without spaces for CSV columns and JSON keys: "boundary_2",
      /// "point_0".
      std::string                                 key;
      /// Its boundary id (Dirichlet data and rollers on that id), or
      /// dealii::numbers::invalid_boundary_id for a point constraint.
      dealii::types::boundary_id                  boundary_id = dealii::numbers::invalid_boundary_id;
      /// The DoFs of the constraint lines it wrote (the first writer of a
      /// line owns it).
      std::vector<dealii::types::global_dof_index> lines;
    };

    /// The reaction of one support.
    struct Reaction
    {
      /// @var std::string name
      /// Support::name.
      /// @var std::string key
      /// Support::key.
      std::string                name, key;
      /// Support::boundary_id.
      dealii::types::boundary_id boundary_id = dealii::numbers::invalid_boundary_id;
      /// The force on the bodies (force units per unit thickness).
      dealii::Tensor<1, 2>       force;
      /// The moment of the nodal reactions about the point given to
      /// compute() (counter-clockwise positive).
      double                     moment = 0;
    };

    /**
     * The reactions of @p supports: @p unbalanced is $\rho$ (n entries, the
     * number of displacement DoFs), @p constraints the closed constraints
     * of the solve (their lines with index below n are read), @p positions
     * the position of every node (at least n/2 entries) and @p point the
     * point the moments are taken about. Throws if a line of a support is
     * not a line of @p constraints or the sizes do not fit.
     */
    static std::vector<Reaction>
    compute(const std::vector<Support>              &supports,
            const dealii::AffineConstraints<double> &constraints,
            const dealii::Vector<double>            &unbalanced,
            const std::vector<dealii::Point<2>>     &positions,
            const dealii::Point<2>                  &point);

    /**
     * What a gear user reads of a boundary part turned about a centre
     * (BoundaryConditions::RotationAboutCentre): the angle, the torque and
     * the moment about the centre.
     */
    struct Rotation
    {
      /// How the messages name it: "rotation of boundary 3 about (0, 0)".
      std::string name;
      /// A name without spaces for CSV columns and JSON keys: "rotation_3".
      std::string key;
      /// The boundary id of the part.
      dealii::types::boundary_id boundary_id = dealii::numbers::invalid_boundary_id;
      /// The centre of the rotation.
      dealii::Point<2> centre;
      /// Whether the angle is an unknown driven by the torque (else it is
      /// prescribed).
      bool torque_driven = false;
      /// The rotation angle (counter-clockwise, radians): prescribed, or
      /// solved for (RotationAboutCentre::angle()).
      double angle = 0;
      /// The applied torque about the centre (counter-clockwise; 0 for a
      /// prescribed angle).
      double torque = 0;
      /// The force of the condition on the body: the reaction of the
      /// constraint lines (for a torque-driven part the bearing force that
      /// keeps the centre in place: the lines' reaction plus the net force
      /// torque / arm of the nodal force that carries the torque, so that
      /// the torque acts as a pure couple).
      dealii::Tensor<1, 2> force;
      /// The moment about the centre of the constraint reactions (for a
      /// prescribed angle: the torque needed to turn the part; for a
      /// torque-driven part 0 up to round-off, the lines transmit no moment).
      double reaction_moment = 0;
      /// The moment about the centre that the condition exerts on the
      /// body: reaction_moment + torque.
      double moment_about_centre = 0;
    };

    /**
     * The Rotation of @p part after a solve: @p torque is the torque applied
     * to a torque-driven part (ignored otherwise), @p u the displacement,
     * and @p constraints, @p unbalanced and @p positions as for compute();
     * the reaction is that of the lines the part wrote
     * (RotationAboutCentre::lines), its moment taken about the centre.
     */
    static Rotation
    rotation(const BoundaryConditions::RotationAboutCentre<2> &part,
             const double                                      torque,
             const dealii::AffineConstraints<double>          &constraints,
             const dealii::Vector<double>                     &u,
             const dealii::Vector<double>                     &unbalanced,
             const std::vector<dealii::Point<2>>              &positions);

    /// The moment about @p point of the force @p force acting at @p x
    /// (counter-clockwise positive).
    static double
    moment(const dealii::Point<2> &x, const dealii::Tensor<1, 2> &force, const dealii::Point<2> &point)
    {
      return (x[0] - point[0]) * force[1] - (x[1] - point[1]) * force[0];
    }
  };
} // namespace dealvem

#endif
