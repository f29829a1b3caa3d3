// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_finite_strain_constraints_h
#define dealvem_elasticity_finite_strain_constraints_h

#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace dealvem
{
  /**
   * What FiniteStrainSolver needs of nonlinear constraints $g_j(u)$
   * enforced by Lagrange multipliers $\lambda_j$ (FiniteStrainSolver::
   * set_contact()): their values, gradients and Hessians, and the kind of
   * each. The solver lives in elasticity/, the contact constraints in
   * contact/ (FiniteStrainContact implements this interface), so the
   * solver does not depend on the module above it.
   *
   * A multiplier is a force: the residual gets
   * $-\sum_j\lambda_j\,\partial g_j/\partial u$. Three kinds:
   * - Kind::equality: $g_j = 0$ (tied contact);
   * - Kind::unilateral: $g_j \ge 0$, $\lambda_j \le 0$, $g_j\lambda_j = 0$
   *   (normal contact);
   * - Kind::friction: Coulomb friction,
   *   $\lambda_j = \mathrm{proj}_{[-b,b]}(\lambda_j + c\,w_j g_j)$ with the
   *   bound $b = \mu_j\max(0, -\lambda_{\nu(j)})$ from the unilateral
   *   constraint $\nu(j)$ = normal_of(j), $g_j$ the slip.
   */
  class FiniteStrainConstraints
  {
  public:
    virtual ~FiniteStrainConstraints() = default;

    /// The kind of a constraint (see the class documentation).
    enum class Kind
    {
      equality,
      unilateral,
      friction
    };

    /// The value, gradient and Hessian of one constraint.
    struct Linearization
    {
      /// $g_j(u)$.
      double value = 0;
      /// The displacement DoFs the constraint depends on.
      std::vector<dealii::types::global_dof_index> dofs;
      /// $\partial g_j/\partial u$ at dofs.
      dealii::Vector<double> gradient;
      /// $\partial^2 g_j/\partial u^2$ over dofs.
      dealii::FullMatrix<double> hessian;
    };

    /// Number of constraints (multipliers).
    virtual unsigned int
    n_constraints() const = 0;

    /// The kind of constraint @p j.
    virtual Kind
    kind(const unsigned int j) const = 0;

    /// For a friction constraint: the unilateral constraint whose
    /// multiplier bounds it.
    virtual unsigned int
    normal_of(const unsigned int j) const = 0;

    /// For a friction constraint: its friction coefficient.
    virtual double
    friction_coefficient_of(const unsigned int j) const = 0;

    /// The length that scales constraint @p j in the complementarity
    /// function (a tributary length), $w_j > 0$.
    virtual double
    weight(const unsigned int j) const = 0;

    /// The complementarity constant $c$ (a stiffness per length).
    virtual double
    complementarity_constant() const = 0;

    /// Whether constraint @p j is left out (its multiplier stays zero).
    virtual bool
    is_left_out(const unsigned int j) const = 0;

    /// Take note of the displacement constraints: a constraint whose DoFs
    /// they prescribe completely is left out (is_prescribed()).
    virtual void
    mark_prescribed(const dealii::AffineConstraints<double> &constraints) = 0;

    /// Whether the displacement constraints prescribe every DoF of
    /// constraint @p j (see mark_prescribed()); the solver then checks that
    /// the prescribed motion does not violate it.
    virtual bool
    is_prescribed(const unsigned int j) const = 0;

    /// The value of constraint @p j at the displacement @p u.
    virtual double
    value(const unsigned int j, const dealii::Vector<double> &u) const = 0;

    /// Value, gradient and Hessian of constraint @p j at @p u; the Hessian
    /// only if @p with_hessian.
    virtual void
    linearize(const unsigned int            j,
              const dealii::Vector<double> &u,
              Linearization                &result,
              const bool                    with_hessian = true) const = 0;

    /// Add the couplings of the constraints to @p dsp (size n_dofs() +
    /// n_constraints(), constraint j is unknown n_dofs() + j), with the
    /// displacement constraints @p constraints condensed.
    virtual void
    add_sparsity(dealii::DynamicSparsityPattern &dsp, const dealii::AffineConstraints<double> &constraints) const = 0;

    /// Where constraint @p j acts, for error messages (for example "the
    /// contact pair at (0.5, 1) of interface 0").
    virtual std::string
    describe(const unsigned int j) const = 0;
  };
} // namespace dealvem

#endif
