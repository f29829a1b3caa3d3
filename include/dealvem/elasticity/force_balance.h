// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_force_balance_h
#define dealvem_elasticity_force_balance_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/elasticity_assembler.h>

#include <string>
#include <utility>
#include <vector>

namespace dealvem
{
  /**
   * The verification after a solve: the residual of the equations and the
   * global force and moment balance of every body.
   *
   * With $K$ and $f$ the unconstrained stiffness and load vector (body
   * force, tractions, pressures, nodal loads), $e$ the nodal forces of the
   * contact (normal multipliers, tangential multipliers or stick springs,
   * friction forces) and $u$ the solution (constraints distributed), the
   * unbalanced nodal force is $\rho = f + e - Ku$. A constraint line
   * $u_s = \sum_j a_{sj} u_j + g_s$ carries the reaction
   * $P = -\rho_s (e_s - \sum_j a_{sj} e_j)$ (Dirichlet data, rollers, point
   * constraints; the lines of a rigid boundary part pass the force on to
   * the part's reference nodes and so cancel within the body), and
   * $r = \rho + P$ is the residual of the condensed equations (zero on
   * constrained DoFs). Per body b:
   * - the residual $R_b = \sum_{i\in b} |r_i|$;
   * - the net force and the moment about the body's area centroid of
   *   $f + e + P$ (applied loads + contact + support reactions), which must
   *   vanish; the imbalance is $|F_x| + |F_y| + |M|/s_b$ ($s_b$ the largest
   *   distance of a vertex from the centroid);
   * - both relative to the forces that act, $A_b = \sum_{i\in b}
   *   (|f_i| + |e_i| + |P_i|)$.
   *
   * The tolerance (doc/architecture.md, "Verification after every solve")
   * is what the arithmetic can attain:
   * @f[ \tau_b = \frac{c_\varepsilon\,\varepsilon\,Q_b + c_{it}\,
   *     \mathrm{tol}\,\sqrt{N}\,\|f + e + P\|_2}{A_b},\qquad
   *     Q_b = \sum_{i\in b} \big(|K||u|\big)_i + |f_i| + |e_i| + |P_i| @f]
   * with $c_\varepsilon = 10^4$, $c_{it} = 10$, tol the relative tolerance
   * of an iterative solver (0 for a direct one) and N the number of DoFs.
   * $Q_b / A_b$ is the measured condition of the balance of body b: it is
   * about the number of DoFs for a body loaded at its boundary and grows
   * with $E_{\max}/E_{\min}$ when a stiff body rides on a soft one (its
   * rigid displacement $U \sim pL/E_{\min}$ enters $|K||u|$ with
   * $E_{\max}$): the a-priori estimate $(E_{\max}/E_{\min})(L/h)^2$.
   * Where $\varepsilon Q_b / A_b$ exceeds max_attainable (1e-6) the forces
   * of the body are not resolved by double precision at all (a stiff body
   * riding on one 1e9 times softer: its strain drowns in its rigid
   * displacement), and the body is refused as unverifiable.
   *
   * Zero forces are exact: a body that carries no applied load and whose
   * contact forces and reactions together stay below
   * zero_force_factor $\varepsilon Q_b$ is in equilibrium with no force at
   * all (a body moved rigidly by its Dirichlet data, or resting untouched
   * on another: the exact forces are zero, and the computed ones are the
   * rounding of $K u$ for a rigid $u$, which is not a force). Its figures are
   * taken relative to zero_force_factor $\varepsilon Q_b$ instead of
   * $A_b$ (and reported as 0 where they meet the tolerance), its condition
   * is 0 (nothing to resolve) and Body::zero_forces is set. This holds only where the Young's moduli of the problem lie within
   * max_stiffness_ratio of each other: beyond, forces that a prescribed
   * motion imposes on a soft body through a stiff one can drown in the stiff
   * body's rounding and be indistinguishable from zero, and the body is
   * refused as unverifiable as before.
   */
  class ForceBalance
  {
  public:
    /// The balance of one body.
    struct Body
    {
      /// The body: the material id of its cells.
      dealii::types::material_id body = 0;
      /// The area centroid of the body's cells, the point the moments are
      /// taken about.
      dealii::Point<2>           centroid;
      /// $s_b$: the largest distance of a vertex of the body from centroid
      /// (length units); the lever arm that turns the moment into a force
      /// in the imbalance.
      double                     size = 0;
      /// @var dealii::Tensor<1, 2> applied
      /// Net force of the applied loads $f$ on the body (body force,
      /// tractions, pressures, nodal loads).
      /// @var dealii::Tensor<1, 2> reaction
      /// Net force of the support reactions $P$ on the body (Dirichlet data,
      /// rollers, point constraints).
      /// @var dealii::Tensor<1, 2> contact
      /// Net force of the contact forces $e$ on the body.
      dealii::Tensor<1, 2> applied, reaction, contact;
      /// @var double applied_moment
      /// Moment of the applied loads about centroid (counter-clockwise
      /// positive, force times length).
      /// @var double reaction_moment
      /// Moment of the support reactions about centroid.
      /// @var double contact_moment
      /// Moment of the contact forces about centroid.
      double               applied_moment = 0, reaction_moment = 0, contact_moment = 0;
      /// @var double forces
      /// $A_b$, the sum of the magnitudes of the nodal forces that act on
      /// the body (see the class documentation); the scale of the relative
      /// quantities below.
      /// @var double condition
      /// $Q_b/A_b$, the measured condition of the balance of the body.
      double forces = 0, condition = 0;
      /// @var double imbalance
      /// Relative imbalance $(|F_x| + |F_y| + |M|/s_b)/A_b$ of the net force
      /// F and moment M of all forces; 0 for a body on which nothing acts.
      /// @var double residual
      /// Relative residual $R_b/A_b$ of the condensed equations on the
      /// body's DoFs; 0 for a body on which nothing acts.
      /// @var double tolerance
      /// Relative tolerance $\tau_b$ that imbalance and residual must meet.
      double imbalance = 0, residual = 0, tolerance = 0;
      /// No applied load acts on the body and its contact forces and
      /// reactions are zero to the rounding of its magnitudes (see the class
      /// documentation): the relative figures are taken relative to that
      /// rounding, and the condition is 0.
      bool zero_forces = false;

      /// The relative accuracy the arithmetic attains for the forces of
      /// the body: eps times the condition.
      double
      attainable() const;

      /// Whether the body passes the verification: imbalance and residual
      /// within tolerance, and attainable() at most max_attainable.
      bool
      ok() const
      {
        return imbalance <= tolerance && residual <= tolerance && attainable() <= max_attainable;
      }
    };

    /// The constant $c_\varepsilon$ of the tolerance.
    static constexpr double rounding_factor = 1e4;
    /// The constant $c_{it}$ of the tolerance.
    static constexpr double iterative_factor = 10;
    /// A body whose forces double precision resolves only to worse than
    /// this (eps times the condition $Q_b/A_b$) cannot be verified and is
    /// refused: its contact forces and reactions carry errors of that size.
    static constexpr double max_attainable = 1e-6;
    /// A body without applied loads whose forces sum to at most this times
    /// $\varepsilon Q_b$ carries no force (Body::zero_forces).
    static constexpr double zero_force_factor = 10;
    /// Zero forces are recognised only where the largest Young's modulus
    /// (ConstitutiveLaw::characteristic_stiffness()) of the problem is at
    /// most this times the smallest: the stiffness ratio that the
    /// verification resolves.
    static constexpr double max_stiffness_ratio = 1e6;

    /**
     * The balance of every body. @p u: the solution with the constraints
     * distributed (on the cells @p cells and their DoFs at least);
     * @p contact_forces: the nodal contact forces (n_dofs entries, or empty
     * without contact); @p solver_tolerance: the relative tolerance of an
     * iterative solver, 0 for a direct one. @p cells: the cells this process
     * adds (nullptr: all); the sums over the processes of @p comm are taken
     * (collective), so every process gets the same result.
     * @p couplings: pairs of DoFs whose bodies exchange a force (the two
     * nodes of a contact pair, per component): a contact force is fixed by
     * the equations of both bodies, so its rounding carries the larger
     * $|K||u|$ of the two nodes, and each side's $Q_b$ gets the other's.
     * If @p unbalanced is not null, it gets the unbalanced nodal force
     * $\rho = f + e - Ku$ (n_dofs entries, summed over the processes), from
     * which SupportReactions takes the reaction of each support.
     */
    static std::vector<Body>
    compute(const ElasticityAssembler<2>            &assembler,
            const dealii::AffineConstraints<double> &constraints,
            const dealii::Vector<double>            &u,
            const dealii::Vector<double>            &contact_forces,
            const double                             solver_tolerance,
            const std::vector<unsigned int>         *cells = nullptr,
            const MPI_Comm                           comm  = MPI_COMM_SELF,
            const std::vector<std::pair<dealii::types::global_dof_index, dealii::types::global_dof_index>>
                                   &couplings  = {},
            dealii::Vector<double> *unbalanced = nullptr);

    /// The largest relative imbalance and residual over the bodies.
    static std::pair<double, double>
    worst(const std::vector<Body> &bodies);

    /**
     * Throws (AssertThrow) with the figures of the first body whose
     * imbalance or residual exceeds its tolerance; @p where names the solve
     * ("load step 2 (t = 0.5)").
     */
    static void
    check(const std::vector<Body> &bodies, const std::string &where);
  };
} // namespace dealvem

#endif
