// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_finite_strain_operator_h
#define dealvem_elasticity_finite_strain_operator_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/constitutive_law.h>
#include <dealvem/elasticity/elasticity_operator.h>

#include <cmath>
#include <string>
#include <vector>

namespace dealvem
{
  template <int dim>
  class VEMValues;

  /**
   * A finite-strain element computation met a quadrature point with
   * $J = \det F \le 0$ (or a non-finite $J$: a displacement that overflows):
   * the message names the cell, the point and $J$.
   * FiniteStrainSolver catches it in its line search (a trial state that
   * inverts a cell is rejected) and reports it with the load step when the
   * step cannot avoid it.
   */
  DeclException3(ExcInvertedCell,
                 unsigned int,
                 unsigned int,
                 double,
                 << "cell " << arg1
                 << (std::isfinite(arg3) ? " is inverted or collapsed at its quadrature point " :
                                           " has a non-finite deformation gradient at its quadrature point ")
                 << arg2 << ": det F = J = " << arg3
                 << (std::isfinite(arg3) ? " <= 0." : " (the displacement is beyond double precision)."));

  /**
   * How the stabilization of the finite-strain element is scaled
   * (FiniteStrainOperator).
   */
  enum class StabilizationScaling
  {
    /// The default: by the material tangent at the last converged state,
    /// frozen during the Newton iterations of a load step, floored at
    /// FiniteStrainOperator::stabilization_floor times the small-strain
    /// scale.
    current_tangent,
    /// By the small-strain tangent ($F = I$) at every state: the
    /// stabilization of ElasticityOperator, unchanged.
    initial_tangent
  };

  /**
   * The element vectors and matrices of hyperelasticity on one polygon in
   * the total Lagrangian formulation, built from the virtual element space
   * of the polygon (VEMValues) and a ConstitutiveLaw with a finite-strain
   * response (ConstitutiveLaw::first_piola_kirchhoff_stress(),
   * ConstitutiveLaw::first_piola_kirchhoff_tangent()). This is the
   * finite-strain counterpart of ElasticityOperator, following
   * @cite ChiBeiraoPaulino2017 and @cite WriggersReddyRustHudobivnik2017.
   *
   * <h3>Consistency</h3>
   * With the full-gradient projection $G_{iq} = (\Pi^0_{k-1}\nabla\varphi_i)(x_q)$
   * of the shape functions at the quadrature points $x_q$ (weights $w_q$)
   * of the polygon (VEMValues::shape_gradient_projection()), the
   * deformation gradient of the local displacement $u$ is
   * $F_q = I + \sum_i u_i G_{iq}$, and
   * @f[
   *   (r_c)_i = \sum_q P(F_q) : G_{iq}\,w_q,\qquad
   *   (K_c)_{ij} = \sum_q G_{iq} : A(F_q) : G_{jq}\,w_q,
   * @f]
   * the internal force of the energy $\sum_q\psi(F_q)w_q$ and its exact
   * derivative. For $k = 1$, $F$ is constant on the polygon; for $k = 2$
   * linear. The quadrature has degree $2k$ (VEMValues' default). At
   * $u = 0$, $K_c$ is ElasticityOperator's consistency matrix of the
   * linearized law, since the symmetric part of $\Pi^0\nabla\varphi_i$ is
   * $\varepsilon(\Pi\varphi_i)$.
   *
   * <h3>Stabilization</h3>
   * $\Pi^0\nabla$ does not see the part of the displacement outside
   * $[P_k]^2$, so an energy on it is added, $\frac12 u^T K_s u$ with the
   * rules of ElasticityOperator (the same scalings, see
   * ElasticityOperator::stabilization_scaling()):
   * $K_s = \gamma\tau(I-\Pi^c)^T(I-\Pi^c)$, $\tau = \mathrm{tr}(\mathrm{diag}(d))/n_{dofs}$
   * (Stabilization::trace, the default of FiniteStrainAssembler for both
   * orders) or $(I-\Pi^c)^T \mathrm{diag}(\gamma c_k \max(d_i, 10^{-3}\tau))(I-\Pi^c)$
   * (Stabilization::diagonal), with the scales $d_i$ below. The projector is
   * not the strain-elliptic $\Pi$ of VirtualElement but the componentwise
   * H1 projector $\Pi^c$ onto $[P_k]^2$ in the DoF basis:
   * $\int_E\nabla\Pi^c v:\nabla p = \int_E\nabla v:\nabla p$ for all
   * $p\in[P_k]^2$ (computable: $\int_{\partial E}(\nabla p\,n)\cdot v
   * - \int_E\Delta p\cdot v$, Gauss-Lobatto on the edge nodes and, for
   * $k = 2$, the cell moment), and the mean of each component kept (vertex
   * mean for $k = 1$, cell moment for $k = 2$). For $k = 1$ the two are the
   * same; for $k = 2$ only $\Pi^c$ commutes with rotating the field,
   * $\Pi^c(Qv) = Q\,\Pi^c v$, because the strain product does not
   * ($\varepsilon(Qv) \ne Q\varepsilon(v)Q^T$). Both vanish on $[P_k]^2$,
   * so the stabilization does not act on rigid motions
   * ($u = (Q - I)X + c$, linear in $X$ for any rotation $Q$) nor on
   * homogeneous deformations: the patch test and the exact rotation hold at
   * any size of the motion. Its internal force is $K_s u$ and its tangent
   * $K_s$.
   *
   * The scale is what matters at large strain. The small-strain rule takes
   * it from the diagonal of $K_c$ at $F = I$ (StabilizationScaling::initial_tangent).
   * Under large stretch or compression the material's current stiffness
   * departs from the initial one (Neo-Hooke stiffens in compression,
   * Saint Venant-Kirchhoff softens), and a stabilization with the initial
   * scale becomes too stiff (locking the non-polynomial modes) or too soft
   * relative to the consistency part. The default
   * (StabilizationScaling::current_tangent) takes the diagonal of
   * $K_c^* = K_c(u^*)$ at a state $u^*$ instead, floored at
   * $\beta = $ stabilization_floor times the diagonal of $K_c(0)$:
   * @f[
   *   d_i = \max\bigl((K_c(u^*))_{ii},\ \beta\,(K_c(0))_{ii}\bigr)
   * @f]
   * (with the initial scaling $d_i = (K_c(0))_{ii}$). The floor keeps the stabilization positive where the
   * tangent loses definiteness (Saint Venant-Kirchhoff in strong
   * compression). FiniteStrainSolver sets $u^*$ to the last converged
   * state at the start of every load step
   * (FiniteStrainAssembler::freeze_stabilization()) and keeps it during the
   * Newton iterations of the step: the stabilization energy is then a fixed
   * quadratic form within the step, its tangent $K_s$ is exact and Newton
   * converges quadratically, and the scale still follows the deformation
   * from step to step. (Re-evaluating the scale at every iterate would make
   * the tangent inexact unless the derivative of the scale were added,
   * which involves the derivative of $A$.) The price: the solution of a
   * step depends on where the previous step ended, by a term of the size
   * of the stabilization force (zero on $[P_k]^2$, of the order of the
   * discretization error otherwise), so it depends slightly on the number
   * of load steps.
   *
   * Why the trace rule for $k = 2$ too (the small-strain default for
   * $k = 2$ is the diagonal rule with $c_2 = 1/5$, chosen for contact
   * pressures): at finite strain the tangent $A$ of a law that is only
   * rank-one convex (Neo-Hooke) is not positive on all tensors, so the
   * consistency energy of a polygon, which sees only the projection of the
   * field, can be negative on modes the conforming continuum would not
   * allow, and the stabilization must dominate it. tests/elasticity/finite_strain_stability measures the
   * smallest eigenvalue of the tangent at a homogeneous state (Voronoi,
   * 16 cells, $k = 2$, Neo-Hooke, $E = 7000$, $\nu = 0.3$; Dirichlet on
   * three sides): with the diagonal rule it is negative already at 30 %
   * compression with shear (a spurious equilibrium, which Newton finds when
   * the fourth side carries the matching traction), with the trace rule it
   * stays positive up to 57 % compression. The same test shows what the
   * plain small-strain scaling does: StabilizationScaling::initial_tangent
   * with the trace rule makes the tangent indefinite at 57 % compression,
   * the current-tangent scaling keeps it positive, because Neo-Hooke
   * stiffens in compression and the stabilization scale follows.
   *
   * Objectivity: the consistency part is objective
   * ($\Pi^0\nabla(Qv) = Q\,\Pi^0\nabla v$ for a constant rotation $Q$,
   * and the laws are objective), and so is the stabilization with the
   * trace rule: $(I-\Pi^c)(Qx) = Q(I-\Pi^c)x$ and $\tau$ is invariant (the
   * trace of $Q K_c Q^T$). tests/elasticity/finite_strain_objectivity checks
   * the whole internal force of a rotated general state to round-off for
   * $k = 1$ and $2$. (With $\Pi$ in place of $\Pi^c$, as first built,
   * $k = 2$ deviated by 2.5 % to 3.4 % of the largest force on that state.)
   * The diagonal rule scales each component of a node by its own diagonal
   * entry, which a rotation mixes: it is not exactly objective.
   */
  template <int dim>
  class FiniteStrainOperator
  {
  public:
    /// The floor $\beta$ of the current-tangent scaling, relative to the
    /// small-strain scale (see the class documentation).
    static constexpr double stabilization_floor = 0.1;

    /// Evaluate the shape-function gradient projections $G_{iq}$ of the
    /// cell @p vem_values was last reinit()ed on (it must have been built
    /// with update_quadrature_points and update_JxW_values).
    void
    reinit(const VEMValues<dim> &vem_values);

    /// Number of local DoFs of the current cell.
    unsigned int
    n_dofs() const
    {
      return n_dofs_cell;
    }

    /// The deformation gradients $F_q = I + \sum_i u_i G_{iq}$ at the
    /// quadrature points for the local displacement @p local_u.
    void
    deformation_gradients(const dealii::Vector<double> &local_u, std::vector<dealii::Tensor<2, dim>> &F) const;

    /// The strain energy of the consistency part, $\sum_q \psi(F_q) w_q$,
    /// of the hyperelastic law @p law (HyperelasticMaterial; throws for
    /// another law) at the local displacement @p local_u: the potential of
    /// compute_consistency()'s internal force. Throws ExcInvertedCell like
    /// compute_consistency().
    double
    strain_energy(const ConstitutiveLaw<dim> &law, const dealii::Vector<double> &local_u) const;

    /**
     * The consistency part: the internal force @p r_c and, if
     * @p with_tangent, the tangent @p K_c (symmetric) of the law @p law at
     * the local displacement @p local_u. Throws ExcInvertedCell if
     * $\det F_q \le 0$ at a quadrature point, and an ExcMessage naming the
     * cell if the law has no finite-strain response.
     */
    void
    compute_consistency(const ConstitutiveLaw<dim>   &law,
                        const dealii::Vector<double> &local_u,
                        const bool                    with_tangent,
                        dealii::Vector<double>       &r_c,
                        dealii::FullMatrix<double>   &K_c) const;

    /**
     * The stabilization matrix @p K_s of the current cell for the law
     * @p law, scaled by the tangent at the local displacement @p frozen_u
     * (StabilizationScaling::current_tangent) or at zero
     * (StabilizationScaling::initial_tangent), with the factor @p gamma and
     * the rule @p rule of ElasticityOperator (Stabilization::automatic
     * means the trace rule), acting on $(I-\Pi^c)u$ (see the class
     * documentation). @p element is the space of the cell
     * (VEMValues::get_element()). Throws unless $\gamma > 0$.
     */
    void
    compute_stabilization(const VirtualElement<dim>    &element,
                          const ConstitutiveLaw<dim>   &law,
                          const dealii::Vector<double> &frozen_u,
                          const double                  gamma,
                          const Stabilization           rule,
                          const StabilizationScaling    scaling,
                          dealii::FullMatrix<double>   &K_s) const;

    /**
     * $I - \Pi^c$ of @p element in its DoF basis ($n\times n$): the
     * complement of the componentwise H1 projector onto $[P_k]^2$ that the
     * stabilization acts on (see the class documentation). Throws naming
     * the polygon if the projector's matrix is singular to round-off.
     */
    static void
    projector_complement(const VirtualElement<dim> &element, dealii::FullMatrix<double> &I_Pi);

    /**
     * The part of the stabilization of @p element that does not depend on
     * the state, for the rule @p rule (Stabilization::automatic means the
     * trace rule): $(I-\Pi^c)^T(I-\Pi^c)$ for the trace rule, the symmetric
     * part of $(I-\Pi^c)^T S_\partial(I-\Pi^c)$ for the boundary rule
     * (ElasticityOperator::boundary_stabilization_form()), so that
     * $K_s = \gamma\tau$ times it; for the diagonal rule $I-\Pi^c$ itself
     * (projector_complement()), which scaled_stabilization() weighs row by
     * row. A function of the polygon only: FiniteStrainAssembler computes
     * it once per cell and mesh.
     */
    static void
    stabilization_base(const VirtualElement<dim> &element,
                       const Stabilization        rule,
                       dealii::FullMatrix<double> &base);

    /**
     * The scales $d_i$ of the stabilization (see the class documentation)
     * from the diagonal @p initial_diagonal of $K_c(0)$ and the diagonal
     * @p current_diagonal of $K_c(u^*)$ (not read for
     * StabilizationScaling::initial_tangent): $d_i = (K_c(0))_{ii}$, or
     * $\max((K_c(u^*))_{ii}, \beta(K_c(0))_{ii})$.
     */
    static void
    stabilization_scales(const dealii::Vector<double> &initial_diagonal,
                         const dealii::Vector<double> &current_diagonal,
                         const StabilizationScaling    scaling,
                         dealii::Vector<double>       &d);

    /**
     * The stabilization from its state-independent part @p base
     * (stabilization_base() for the rule @p rule) and the scales @p d:
     * returns $\gamma\tau = \gamma\sum_i d_i/n$ (@p gamma the factor of
     * ElasticityOperator). If @p K_s is not null it gets the matrix:
     * $\gamma\tau$ times @p base for the trace and boundary rules,
     * $B^T\mathrm{diag}(\gamma c_k\max(d_i, 10^{-3}\tau))B$ with
     * $B = $ @p base $= I-\Pi^c$ for the diagonal rule (@p c_k: the
     * diagonal weight of the element's StabilizationRules). Throws unless
     * $\gamma > 0$.
     */
    static double
    scaled_stabilization(const dealii::FullMatrix<double> &base,
                         const dealii::Vector<double>     &d,
                         const double                      gamma,
                         const Stabilization               rule,
                         const double                      c_k,
                         dealii::FullMatrix<double>       *K_s);

  private:
    unsigned int                        cell        = 0;
    unsigned int                        n_dofs_cell = 0;
    unsigned int                        n_q         = 0;
    std::vector<double>                 JxW;
    /// G[q * n_dofs + i] = Pi^0 grad phi_i at point q
    std::vector<dealii::Tensor<2, dim>> G;
  };
} // namespace dealvem

#endif
