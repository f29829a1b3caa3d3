// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_elasticity_operator_h
#define dealvem_elasticity_elasticity_operator_h

#include <deal.II/lac/full_matrix.h>

#include <dealvem/elasticity/material.h>
#include <dealvem/vem/virtual_element.h>

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
    /// with $d_i = \max((K_c)_{ii}, 10^{-3}\tau)$: every degree of freedom
    /// is stabilized like its own consistency stiffness.
    diagonal,
    /// "dofi-dofi": $K_s = \gamma\,\tau\,(I-\Pi)^T(I-\Pi)$ with one scale
    /// $\tau = \mathrm{tr}(K_c)/n_{dofs}$ for all degrees of freedom.
    trace
  };

  /**
   * The element matrices of isotropic linear elasticity on one polygon,
   * built from the virtual element space of that polygon and a material:
   * the bilinear form of deal.II's step-8, written for the VEM.
   *
   * With the space's projector $\Pi_*$, its Gram matrices $E$ (strain) and
   * $T$ (divergence) and its projector onto the degrees of freedom
   * $\Pi = D\Pi_*$ (see VirtualElement):
   * - consistency $K_c = \Pi_*^T(\lambda T + 2\mu E)\Pi_*$, i.e.
   *   $a_E(\Pi u,\Pi v)$ with
   *   $a_E(u,v) = \int_E\lambda\,\mathrm{div}\,u\,\mathrm{div}\,v + 2\mu\,\varepsilon(u):\varepsilon(v)$;
   * - stabilization $K_s$, zero on $[P_k]^2$, one of (Stabilization;
   *   the default Stabilization::automatic takes the trace rule for k = 1
   *   and the diagonal rule for k = 2):
   *   - Stabilization::diagonal, the "D-recipe" of Beirao da
   *     Veiga, Dassi and Russo (2017):
   *     $K_s = \gamma\,c_k\,(I-\Pi)^T\mathrm{diag}(d_i)(I-\Pi)$,
   *     $d_i = \max((K_c)_{ii}, 10^{-3}\tau)$, $c_1 = 1$, $c_2 = 1/5$;
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
   * $\lambda$, $\mu$, $\gamma$ and the rule only, and reinit() recomputes
   * them only when one of these changed: on a structured mesh of one
   * material, translated cells cost nothing.
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
     * on. Throws unless $\gamma > 0$.
     */
    void
    reinit(const VirtualElement<dim> &element,
           const ElasticMaterial     &material,
           const double               gamma         = 1.0,
           const Stabilization        stabilization = Stabilization::automatic);

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

  private:
    dealii::FullMatrix<double> K_c, K_s, K, A;
    double                     stab_scaling = 0;
    // the inputs of the last computation
    std::uint64_t revision = 0;
    double        lambda = 0, mu = 0, gamma = 0;
    Stabilization rule   = Stabilization::automatic;
    bool          valid  = false;
    bool          reused = false;
  };
} // namespace dealvem

#endif
