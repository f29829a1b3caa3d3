// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_design_material_interpolation_h
#define dealvem_design_material_interpolation_h

#include <string>

namespace dealvem
{
  namespace Design
  {
    /**
     * The interpolation of the stiffness between void and solid in density
     * topology optimization: the factor $s(\rho)$ by which a cell of density
     * $\rho \in [0, 1]$ multiplies the constitutive law of its body.
     * - SIMP: $s(\rho) = s_{min} + \rho^p (1 - s_{min})$ (Bendsøe 1989);
     * - RAMP: $s(\rho) = s_{min} + \frac{\rho}{1 + q(1-\rho)} (1 - s_{min})$
     *   (Stolpe and Svanberg 2001), concave-free for $q \ge 0$ and with a
     *   non-zero slope at $\rho = 0$.
     *
     * $s_{min}$ (minimum, default $10^{-9}$) keeps a void cell's stiffness
     * positive so that the stiffness matrix stays definite.
     *
     * <h3>Why a factor of the law is exact for virtual elements</h3>
     * For a linear law $\mathbb{C}$, the consistency part of the VEM
     * stiffness is linear in $\mathbb{C}$ and the stabilization is scaled
     * by the trace of the consistency matrix (ElasticityOperator), so the
     * whole cell matrix of the law $s\,\mathbb{C}$ is $s K_E$ with $K_E$ the
     * matrix of $\mathbb{C}$: the derivative with respect to the density is
     * $s'(\rho) K_E$, exactly (tests/design/sensitivities checks it
     * against finite differences).
     */
    struct MaterialInterpolation
    {
      /// The interpolation scheme.
      enum class Type
      {
        simp, ///< solid isotropic material with penalization
        ramp  ///< rational approximation of material properties
      };

      /// The scheme ("Design/Interpolation": "SIMP" or "RAMP").
      Type   type    = Type::simp;
      /// The penalization: the exponent p of SIMP (>= 1), the q of RAMP (>= 0).
      double penalty = 3.;
      /// The stiffness factor of a void cell, in (0, 1).
      double minimum = 1e-9;

      /// Throw, naming the parameter, unless the penalty and the minimum
      /// are in range.
      void
      check() const;

      /// The stiffness factor $s(\rho)$ ($\rho$ in [0, 1]).
      double
      factor(const double rho) const;

      /// Its derivative $s'(\rho)$.
      double
      derivative(const double rho) const;

      /// "SIMP" or "RAMP" (case-insensitive); throws otherwise.
      static Type
      parse(const std::string &name);

      /// The name parse() reads.
      static std::string
      name(const Type t);
    };

    /**
     * The smoothed Heaviside projection of filtered densities
     * (Wang, Lazarov and Sigmund 2011):
     * $\bar\rho = \frac{\tanh(\beta\eta) + \tanh(\beta(\tilde\rho-\eta))}
     *               {\tanh(\beta\eta) + \tanh(\beta(1-\eta))}$,
     * which maps 0 to 0 and 1 to 1 for every sharpness $\beta > 0$ and
     * threshold $\eta \in (0, 1)$, and tends to a step at $\eta$ as $\beta$
     * grows. TopologyOptimizer raises $\beta$ by continuation.
     */
    struct HeavisideProjection
    {
      /// The sharpness $\beta > 0$.
      double beta = 1.;
      /// The threshold $\eta$ in (0, 1).
      double eta = 0.5;

      /// Throw unless beta > 0 and 0 < eta < 1.
      void
      check() const;

      /// $\bar\rho(\tilde\rho)$.
      double
      value(const double x) const;

      /// $d\bar\rho/d\tilde\rho$.
      double
      derivative(const double x) const;
    };
  } // namespace Design
} // namespace dealvem

#endif
