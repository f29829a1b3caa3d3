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
   * The element matrices of isotropic linear elasticity on one polygon,
   * built from the virtual element space of that polygon and a material:
   * the bilinear form of deal.II's step-8, written for the VEM.
   *
   * With the space's projector $\Pi_*$, its Gram matrices $E$ (strain) and
   * $T$ (divergence) and its stabilization form $S = (I-\Pi)^T(I-\Pi)$
   * (see VirtualElement):
   * - consistency $K_c = \Pi_*^T(\lambda T + 2\mu E)\Pi_*$, i.e.
   *   $a_E(\Pi u,\Pi v)$ with
   *   $a_E(u,v) = \int_E\lambda\,\mathrm{div}\,u\,\mathrm{div}\,v + 2\mu\,\varepsilon(u):\varepsilon(v)$;
   * - stabilization $K_s = \gamma\,\tau\,S$ with $\tau = \mathrm{tr}(K_c)/n_{dofs}$,
   *   which makes $K_s$ scale with the material and the cell like $K_c$;
   * - stiffness $K_E = K_c + K_s$ (symmetric).
   *
   * The matrices depend on the polygon's shape (through the space), on
   * $\lambda$, $\mu$ and on $\gamma$ only, and reinit() recomputes them only
   * when one of these changed: on a structured mesh of one material,
   * translated cells cost nothing.
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
           const double               gamma = 1.0);

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

    /// The stabilization scaling $\gamma\tau$ used.
    double
    get_stabilization_scaling() const
    {
      return stab_scaling;
    }

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
    bool          valid  = false;
    bool          reused = false;
  };
} // namespace dealvem

#endif
