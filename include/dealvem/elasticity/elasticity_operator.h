// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_elasticity_operator_h
#define dealvem_elasticity_elasticity_operator_h

#include <deal.II/lac/full_matrix.h>

#include <dealvem/elasticity/constitutive_law.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/vem/virtual_element.h>

#include <array>
#include <cstdint>

namespace dealvem
{
  /**
   * The two stabilizations of the virtual element stiffness (see
   * ElasticityOperator).
   */
  enum class Stabilization
  {
    /// The default: trace for k = 1, diagonal for k = 2 (see
    /// ElasticityOperator for the measurements behind it).
    automatic,
    /// "D-recipe": $K_s = \gamma\,c_k\,(I-\Pi)^T\,\mathrm{diag}(d_i)\,(I-\Pi)$
    /// with $d_i = \max(\tfrac12\mathrm{tr}(K_c)_{aa}, 10^{-3}\tau)$ for both
    /// components $i$ of node $a$ ($(K_c)_{aa}$ its $2\times 2$ diagonal
    /// block): every node is stabilized like its own consistency stiffness,
    /// the same in every orientation of the model.
    diagonal,
    /// "dofi-dofi": $K_s = \gamma\,\tau\,(I-\Pi)^T(I-\Pi)$ with one scale
    /// $\tau = \mathrm{tr}(K_c)/n_{dofs}$ for all degrees of freedom.
    trace,
    /// Boundary rule: $K_s = \gamma\,\tau\,(I-\Pi)^T S_\partial(I-\Pi)$ with
    /// the tangential-derivative form of the boundary,
    /// $S_\partial(u, v) = \sum_e \frac{\bar\ell}{m}\int_e \partial_s u\cdot\partial_s v$
    /// ($\bar\ell$ the mean edge length of the polygon, $m$ the mean
    /// diagonal of that form on a polygon of equal edges, so that it has
    /// the size of the trace rule there) plus the identity on the cell
    /// moments ($k = 2$). An edge of length $\delta$ stiffens the relative
    /// motion of its nodes by $\bar\ell/\delta$, as the elasticity of the
    /// material it bounds would: the rule for polygons with short edges (the
    /// sub-edges node insertion makes), where the trace and diagonal rules
    /// leave that motion as soft as any other (ElasticityOperator::
    /// boundary_stabilization_form()).
    boundary
  };

  /**
   * The element matrices of linear elasticity on one polygon, built from
   * the virtual element space of that polygon and a linear constitutive law
   * (ConstitutiveLaw): the bilinear form of deal.II's step-8, written for
   * the VEM.
   *
   * With the space's projector $\Pi_*$ and its projector onto the degrees
   * of freedom $\Pi = D\Pi_*$ (see VirtualElement), and the tangent
   * $\mathbb{C}$ of the law (ConstitutiveLaw::tangent() at zero strain):
   * - consistency $K_c = \Pi_*^T A\,\Pi_*$, i.e. $a_E(\Pi u,\Pi v)$ with
   *   $a_E(u,v) = \int_E\varepsilon(u):\mathbb{C}:\varepsilon(v)$, where
   *   $A_{\alpha\beta} = a_E(p_\alpha,p_\beta)$ on the strain modes. For a
   *   general (anisotropic) tangent, $A$ comes from the gradients of the
   *   basis polynomials in the scaled monomials of degree $k-1$ and their
   *   exact Gram matrix $M$
   *   (VirtualElement::polynomial_gradient_coefficients(),
   *   VirtualElement::get_monomial_gram()):
   *   $A_{\alpha\beta} = \sum_{m,n} M_{mn}\,\varepsilon_{\alpha,m}:\mathbb{C}:\varepsilon_{\beta,n}$.
   *   When the tangent has exactly the isotropic form
   *   $\mathbb{C} = \lambda I\otimes I + 2\mu\mathbb{I}$ (as ElasticMaterial's:
   *   $C_{0000} = C_{1111} = C_{0011}+2C_{0101}$, $C_{0011} = C_{1100}$, no
   *   shear coupling), $A = \lambda T + 2\mu E$ with the Gram matrices $T$
   *   (divergence) and $E$ (strain) of the space and $\lambda = C_{0011}$,
   *   $\mu = C_{0101}$: the same matrix to round-off, fewer operations.
   *   The space's projector is the elliptic projector of every such law,
   *   isotropic or not: $\mathbb{C}$ is constant on the polygon and maps the
   *   symmetric tensor fields of degree $k-1$, which are all strains of
   *   $[P_k]^2$, into themselves.
   *   The tangent must have the major symmetry and be positive definite
   *   (checked, AssertThrow). A non-linear law (ConstitutiveLaw::is_linear()
   *   false) is refused with AssertThrow: its stiffness depends on the
   *   current strain, and linearizing it belongs to a Newton driver, which
   *   does not exist yet;
   * - stabilization $K_s$, zero on $[P_k]^2$, one of (Stabilization;
   *   the default Stabilization::automatic takes the trace rule for k = 1
   *   and the diagonal rule for k = 2):
   *   - Stabilization::diagonal, the "D-recipe" of Beirao da
   *     Veiga, Dassi and Russo (2017):
   *     $K_s = \gamma\,c_k\,(I-\Pi)^T\mathrm{diag}(d_i)(I-\Pi)$,
   *     $d_i = \max(\tfrac12\mathrm{tr}(K_c)_{aa}, 10^{-3}\tau)$ for both
   *     components $i$ of node $a$ (the trace of the node's $2\times 2$
   *     block does not change when the model is rotated, the single
   *     diagonal entries do), $c_1 = 1$, $c_2 = 1/5$;
   *   - Stabilization::trace, "dofi-dofi": $K_s = \gamma\,\tau\,(I-\Pi)^T(I-\Pi)$,
   *   with $\tau = \mathrm{tr}(K_c)/n_{dofs}$; both scale with the material
   *   and the cell like $K_c$;
   * - stiffness $K_E = K_c + K_s$ (symmetric).
   *
   * Why the diagonal rule is the default: a degree of freedom on a short
   * edge (node insertion creates edges down to 5 % of their neighbours) has
   * a small consistency stiffness, and the trace rule stabilizes it as
   * strongly as every other one. At a contact interface the nodal forces,
   * hence the multipliers, then carry a stabilization pattern: on the
   * Hertz problem of step-3 at k = 2 the raw multipliers per length are off
   * by 9.9 % / 4.5 % of p0 (levels 0 / 1) with the trace rule and 0.67 % /
   * 0.53 % with the diagonal rule (c_2 = 1/5; 0.74 % / 0.57 % with
   * c_2 = 1/4, 1.07 % / 0.74 % with c_2 = 1/2, 1.74 % / 1.09 % with
   * c_2 = 1; c_2 = 1/8 is too weak to keep the accuracy of the
   * FE_Q transfer of the solution), see doc/architecture.md,
   * "Contact pressure". At k = 1 the two rules are equally accurate there
   * (1.60 % / 1.46 % trace, 1.41 % / 1.37 % diagonal), and the trace rule
   * keeps the Newton iteration counts of the friction tutorial (step-4,
   * which needs one more iteration in one load step with the diagonal
   * rule), so k = 1 keeps it by default.
   *
   * The matrices depend on the polygon's shape (through the space), on
   * the tangent $\mathbb{C}$, $\gamma$ and the rule only, and reinit()
   * recomputes them only when one of these changed: on a structured mesh of
   * one material, translated cells cost nothing.
   *
   * References: @cite BeiraoBrezziMarini2013 (elasticity),
   * @cite ArtioliBeiraoLovadinaSacco2017 (k >= 2).
   */
  template <int dim>
  class ElasticityOperator
  {
  public:
    /**
     * Compute the matrices for the polygon @p element was last reinit()ed
     * on, with the tangent of the linear law @p law (an ElasticMaterial,
     * or any other ConstitutiveLaw). Throws unless $\gamma > 0$, unless
     * @p law is linear, and unless its tangent has the major symmetry and
     * is positive definite.
     */
    void
    reinit(const VirtualElement<dim>  &element,
           const ConstitutiveLaw<dim> &law,
           const double                gamma         = 1.0,
           const Stabilization         stabilization = Stabilization::automatic);

    /// Whether the last reinit() kept the matrices of the previous call.
    bool
    last_reinit_reused() const
    {
      return reused;
    }

    /// Consistency part $K_c$.
    const dealii::FullMatrix<double> &
    get_consistency_matrix() const
    {
      return K_c;
    }

    /// Stabilization part $K_s$.
    const dealii::FullMatrix<double> &
    get_stabilization_matrix() const
    {
      return K_s;
    }

    /// Element stiffness $K_E = K_c + K_s$.
    const dealii::FullMatrix<double> &
    get_stiffness_matrix() const
    {
      return K;
    }

    /// The stabilization scaling $\gamma\tau$ of the trace rule (with the
    /// diagonal rule: $\gamma\tau$ too, the scale of its floor).
    double
    get_stabilization_scaling() const
    {
      return stab_scaling;
    }

    /**
     * Add the stabilization of the rule @p stabilization to a consistency
     * matrix @p K (on input $K_c$ of the polygon @p element was last
     * reinit()ed on; on output $K_c + K_s$): the one place the rules are
     * written, for loops that build $K_c$ themselves (step-1 does, by
     * quadrature).
     */
    static void
    add_stabilization(const VirtualElement<dim>  &element,
                      dealii::FullMatrix<double> &K,
                      const double                gamma         = 1.0,
                      const Stabilization         stabilization = Stabilization::automatic);

    /**
     * The stabilization scaling $\tau = \mathrm{tr}(K_c)/n_{dofs}$ of a
     * consistency matrix @p K_c: the one place this rule is written, for
     * loops that build $K_c$ themselves (step-1 does, by quadrature).
     */
    static double
    stabilization_scaling(const dealii::FullMatrix<double> &K_c, const double gamma);

    /**
     * The form $S_\partial$ of Stabilization::boundary on the local DoFs of
     * the polygon @p element was last reinit()ed on (before the projection
     * $(I-\Pi)$): on each edge $e$ and for each component, the stiffness
     * matrix of $\int_e \partial_s u\,\partial_s v$ of the edge's trace
     * (linear or quadratic in its nodes) times $\bar\ell/m$, with the mean
     * edge length $\bar\ell$ and $m = 2$ ($k = 1$) or $5$ ($k = 2$), the
     * mean diagonal of the sum over the edges when all have the same length;
     * and 1 on the diagonal of the cell moments ($k = 2$). Positive
     * semidefinite with the constants on the boundary as its kernel (a
     * constant is also in the kernel of $I-\Pi$), so
     * $(I-\Pi)^TS_\partial(I-\Pi)$ vanishes on $[P_k]^2$ and is positive on
     * the kernel of $\Pi$, as a stabilization must be. The edge integral
     * scales like the $H^{1/2}$ norm of the boundary trace, robust under
     * short edges (Beirao da Veiga, Lovadina, Russo, M3AS 2017).
     */
    static void
    boundary_stabilization_form(const VirtualElement<dim> &element, dealii::FullMatrix<double> &S);

  private:
    /// The form $A$ on the strain modes for the tangent @p C:
    /// $\lambda T + 2\mu E$ for an isotropic tangent, the general formula
    /// otherwise (see the class documentation).
    void
    compute_strain_mode_form(const VirtualElement<dim> &element, const dealii::SymmetricTensor<4, dim> &C);

    dealii::FullMatrix<double> K_c, K_s, K, A;
    double                     stab_scaling = 0;
    // the inputs of the last computation: the space's revision, the
    // tangent's components (unrolled), gamma and the rule
    std::uint64_t         revision = 0;
    std::array<double, dealii::SymmetricTensor<4, dim>::n_independent_components> tangent{};
    double                                                                         gamma = 0;
    Stabilization rule   = Stabilization::automatic;
    bool          valid  = false;
    bool          reused = false;
  };
} // namespace dealvem

#endif
