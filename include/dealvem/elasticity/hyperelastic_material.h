// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_hyperelastic_material_h
#define dealvem_elasticity_hyperelastic_material_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <dealvem/elasticity/constitutive_law.h>
#include <dealvem/elasticity/material.h>

#include <memory>
#include <string>

namespace dealvem
{
  /**
   * A deformation gradient with $J = \det F \le 0$ (an inverted or
   * collapsed material point) was given to a hyperelastic law: the
   * message gives $J$ and the law. FiniteStrainAssembler adds the cell,
   * FiniteStrainSolver the load step.
   */
  DeclException2(ExcNonPositiveJacobian,
                 double,
                 std::string,
                 << "the deformation gradient has det F = J = " << arg1
                 << " <= 0 (an inverted or collapsed material point) in the law '" << arg2
                 << "': a hyperelastic stress is only defined for J > 0.");

  /**
   * The common part of the isotropic hyperelastic laws for plane strain
   * (NeoHookeMaterial, SaintVenantKirchhoffMaterial): Young's modulus $E$
   * and Poisson's ratio $\nu$, converted to the Lamé parameters
   * $\mu = E/(2(1+\nu))$ and $\lambda = E\nu/((1+\nu)(1-2\nu))$ of the 3D
   * law, the range checks, and the small-strain response.
   *
   * <h3>Finite strain</h3>
   * A derived law gives the strain energy $\psi(F)$ per unit reference
   * volume, the first Piola-Kirchhoff stress
   * $P = \partial\psi/\partial F$ and its tangent
   * $A_{iJkL} = \partial P_{iJ}/\partial F_{kL}$
   * (ConstitutiveLaw::first_piola_kirchhoff_stress(),
   * ConstitutiveLaw::first_piola_kirchhoff_tangent()) at an in-plane
   * deformation gradient $F$ (a 2x2 tensor; plane strain: $F_{zz} = 1$,
   * $F_{iz} = F_{zi} = 0$). Each of them throws ExcNonPositiveJacobian
   * when $J = \det F \le 0$, rather than returning a NaN (Neo-Hooke) or a
   * meaningless number (Saint Venant-Kirchhoff, whose energy is finite
   * for inverted states).
   *
   * <h3>Small strain</h3>
   * The small-strain functions of ConstitutiveLaw (stress(), tangent(),
   * stress_zz()) are the linearization at $F = I$, which for both laws is
   * the linear isotropic law of the same $\lambda$, $\mu$
   * ($\mathbb{C} = \lambda I\otimes I + 2\mu\mathbb{I}$, ElasticMaterial in
   * plane strain with the same $E$, $\nu$): so is_linear() is true and a
   * small-strain analysis (ElasticityAssembler, StressRecovery) takes these
   * laws as it takes ElasticMaterial.
   *
   * <h3>Plane stress</h3>
   * Plane stress at finite strain needs the out-of-plane stretch from
   * $P_{zz}(F_{zz}) = 0$ at every point (a local Newton iteration and a
   * condensed tangent). That is not implemented: the constructor refuses
   * ElasticMaterial::Model::plane_stress with a message saying so.
   */
  class HyperelasticMaterial : public ConstitutiveLaw<2>
  {
  public:
    /**
     * Constructor. Throws (AssertThrow) unless $E$ is finite and in the
     * range of ElasticMaterial (ElasticMaterial::min_youngs_modulus to
     * ElasticMaterial::max_youngs_modulus), unless $-1 < \nu < 0.5$, and
     * for @p model = plane stress (not implemented, see the class
     * documentation).
     */
    HyperelasticMaterial(const double E, const double nu, const ElasticMaterial::Model model);

    /// Young's modulus $E$ of the linearization.
    double
    youngs_modulus() const
    {
      return E;
    }

    /// Poisson's ratio $\nu$ of the linearization.
    double
    poissons_ratio() const
    {
      return nu;
    }

    /// The first Lamé parameter $\lambda = E\nu/((1+\nu)(1-2\nu))$.
    double
    lambda() const;

    /// The shear modulus $\mu = E/(2(1+\nu))$.
    double
    mu() const;

    /// The linear law of the linearization at $F = I$: an ElasticMaterial
    /// in plane strain with the same $E$ and $\nu$.
    ElasticMaterial
    linearization() const;

    /// The strain energy $\psi(F)$ per unit reference volume at the
    /// deformation gradient @p F. Throws ExcNonPositiveJacobian if
    /// $\det F \le 0$.
    virtual double
    strain_energy(const dealii::Tensor<2, 2> &F) const = 0;

    /// The in-plane Cauchy stress $\sigma = J^{-1} P F^T$ at the
    /// deformation gradient @p F (symmetric for these laws; returned as
    /// a general tensor so that a test sees any asymmetry).
    dealii::Tensor<2, 2>
    cauchy_stress(const dealii::Tensor<2, 2> &F) const;

    /// True: the laws implement P(F) and dP/dF.
    bool
    has_finite_strain_response() const override;

    /// True: the small-strain response is the linearization at $F = I$.
    bool
    is_linear() const override;

    /// Young's modulus $E$.
    double
    characteristic_stiffness() const override;

    /// $\sigma = \lambda\,\mathrm{tr}(\varepsilon) I + 2\mu\varepsilon$
    /// (the linearization at $F = I$).
    dealii::SymmetricTensor<2, 2>
    stress(const dealii::SymmetricTensor<2, 2> &strain) const override;

    /// $\lambda I\otimes I + 2\mu\mathbb{I}$, the tangent of the
    /// linearization (at any @p strain).
    dealii::SymmetricTensor<4, 2>
    tangent(const dealii::SymmetricTensor<2, 2> &strain) const override;

    /// $\sigma_{zz} = \lambda\,\mathrm{tr}\,\varepsilon$ of the
    /// linearization in plane strain.
    double
    stress_zz(const dealii::SymmetricTensor<2, 2> &strain) const override;

  protected:
    /// $\det F$ of @p F; throws ExcNonPositiveJacobian (naming the law) if
    /// it is not positive or not finite.
    double
    checked_determinant(const dealii::Tensor<2, 2> &F) const;

    /// The parameters as text for get_name(): "E = ..., nu = ..., plane
    /// strain".
    std::string
    parameter_text() const;

  private:
    double E;
    double nu;
    /// The linearization at $F = I$, which answers the small-strain
    /// functions.
    ElasticMaterial linear;
  };



  /**
   * The compressible Neo-Hooke law in plane strain ($F_{zz} = 1$), with
   * the strain energy (as in deal.II's code-gallery finite-strain
   * examples and in @cite ChiBeiraoPaulino2017)
   * @f[
   *   \psi(F) = \frac{\mu}{2}(I_1 - 3) - \mu\ln J + \frac{\lambda}{2}(\ln J)^2,
   *   \qquad I_1 = \mathrm{tr}(F^TF) + 1,\quad J = \det F,
   * @f]
   * where $I_1$ is the first invariant of the 3D right Cauchy-Green tensor
   * (its $zz$ entry is 1). Then
   * @f[
   *   P = \mu F + (\lambda\ln J - \mu)F^{-T},\qquad
   *   A_{iJkL} = \mu\,\delta_{ik}\delta_{JL} + \lambda F^{-1}_{Ji}F^{-1}_{Lk}
   *   - (\lambda\ln J - \mu)\,F^{-1}_{Jk}F^{-1}_{Li},
   * @f]
   * and at $F = I$, $A = \lambda I\otimes I + 2\mu\mathbb{I}$ on symmetric
   * gradients: the linear law. The energy grows without bound as
   * $J \to 0^+$, so a converged state never has an inverted point; an
   * evaluation at $J \le 0$ throws ExcNonPositiveJacobian.
   */
  class NeoHookeMaterial : public HyperelasticMaterial
  {
  public:
    /// Constructor: see HyperelasticMaterial (plane strain only).
    NeoHookeMaterial(const double                 E     = 1.0,
                     const double                 nu    = 0.3,
                     const ElasticMaterial::Model model = ElasticMaterial::Model::plane_strain);

    /// "Neo-Hooke (E = ..., nu = ..., plane strain)".
    std::string
    get_name() const override;

    /// A copy.
    std::unique_ptr<ConstitutiveLaw<2>>
    clone() const override;

    /// $\psi(F)$ of the class documentation.
    double
    strain_energy(const dealii::Tensor<2, 2> &F) const override;

    /// $P(F) = \mu F + (\lambda\ln J - \mu)F^{-T}$.
    dealii::Tensor<2, 2>
    first_piola_kirchhoff_stress(const dealii::Tensor<2, 2> &F) const override;

    /// $A_{iJkL}(F)$ of the class documentation.
    dealii::Tensor<4, 2>
    first_piola_kirchhoff_tangent(const dealii::Tensor<2, 2> &F) const override;
  };



  /**
   * The Saint Venant-Kirchhoff law in plane strain: the linear isotropic
   * law written between the Green-Lagrange strain
   * $\mathsf{E} = \frac12(F^TF - I)$ and the second Piola-Kirchhoff stress,
   * @f[
   *   \psi = \frac{\lambda}{2}(\mathrm{tr}\,\mathsf{E})^2 + \mu\,\mathsf{E}:\mathsf{E},\qquad
   *   S = \lambda\,\mathrm{tr}(\mathsf{E})I + 2\mu\mathsf{E},\qquad P = FS,
   * @f]
   * @f[
   *   A_{iJkL} = \delta_{ik}S_{JL} + F_{iM}\,\mathbb{C}_{MJNL}\,F_{kN},\qquad
   *   \mathbb{C}_{MJNL} = \lambda\delta_{MJ}\delta_{NL} + \mu(\delta_{MN}\delta_{JL} + \delta_{ML}\delta_{JN}).
   * @f]
   * In plane strain $\mathsf{E}_{zz} = 0$, so the 2x2 formulas are the
   * whole law. It is objective and exact for large rotations, but not
   * polyconvex: under strong compression (stretches below
   * $1/\sqrt{3}$ in uniaxial plane strain) its tangent loses definiteness.
   * The energy is finite for $J \le 0$, but the law refuses such states
   * (ExcNonPositiveJacobian) like NeoHookeMaterial: an inverted point is a
   * failed computation, not a result.
   */
  class SaintVenantKirchhoffMaterial : public HyperelasticMaterial
  {
  public:
    /// Constructor: see HyperelasticMaterial (plane strain only).
    SaintVenantKirchhoffMaterial(const double                 E     = 1.0,
                                 const double                 nu    = 0.3,
                                 const ElasticMaterial::Model model = ElasticMaterial::Model::plane_strain);

    /// "Saint Venant-Kirchhoff (E = ..., nu = ..., plane strain)".
    std::string
    get_name() const override;

    /// A copy.
    std::unique_ptr<ConstitutiveLaw<2>>
    clone() const override;

    /// $\psi(F)$ of the class documentation.
    double
    strain_energy(const dealii::Tensor<2, 2> &F) const override;

    /// $P(F) = F S(F)$.
    dealii::Tensor<2, 2>
    first_piola_kirchhoff_stress(const dealii::Tensor<2, 2> &F) const override;

    /// $A_{iJkL}(F)$ of the class documentation.
    dealii::Tensor<4, 2>
    first_piola_kirchhoff_tangent(const dealii::Tensor<2, 2> &F) const override;
  };
} // namespace dealvem

#endif
