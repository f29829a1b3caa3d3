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
   * A hyperelastic law in plane stress was evaluated at an in-plane
   * deformation gradient $F$ for which no admissible out-of-plane stretch
   * $f > 0$ makes $P_{zz}(F, f) = 0$ (the sheet has no plane-stress state
   * there): the message gives the law, $F$ and the law's reason.
   */
  DeclException3(ExcNoPlaneStressState,
                 std::string,
                 std::string,
                 std::string,
                 << "the law '" << arg1 << "' has no plane-stress state at the in-plane deformation gradient F = "
                 << arg2 << ": no out-of-plane stretch f > 0 solves P_zz(F, f) = 0 (" << arg3 << ").");

  /**
   * The common part of the isotropic hyperelastic laws
   * (NeoHookeMaterial, SaintVenantKirchhoffMaterial) in plane strain and
   * plane stress: Young's modulus $E$ and Poisson's ratio $\nu$, converted
   * to the Lamé parameters $\mu = E/(2(1+\nu))$ and
   * $\lambda = E\nu/((1+\nu)(1-2\nu))$ of the 3D law, the range checks,
   * the reduction of the 3D law to the plane, and the small-strain
   * response.
   *
   * <h3>Finite strain</h3>
   * A derived law gives its 3D strain energy, first Piola-Kirchhoff stress
   * and tangent at the block-diagonal deformation gradient
   * @f[
   *   F_3 = \begin{pmatrix} F & 0 \\ 0 & f \end{pmatrix}
   * @f]
   * (an in-plane 2x2 tensor $F$, no out-of-plane shear, out-of-plane
   * stretch $f > 0$). This class turns it into the in-plane law:
   * the strain energy $\psi(F)$ per unit reference volume, the first
   * Piola-Kirchhoff stress $P = \partial\psi/\partial F$ and its tangent
   * $A_{iJkL} = \partial P_{iJ}/\partial F_{kL}$
   * (ConstitutiveLaw::first_piola_kirchhoff_stress(),
   * ConstitutiveLaw::first_piola_kirchhoff_tangent()), 2x2 blocks of the
   * 3D ones:
   * - plane strain: $f = 1$; $\psi$, $P$ and $A$ are the in-plane blocks
   *   of the 3D law at $F_3$;
   * - plane stress: $f = f(F)$ is the root of $P_{zz}(F, f) = 0$ (a thin
   *   sheet free of out-of-plane traction), found per call by a safeguarded
   *   Newton iteration (a bracket on the branch of the law where a
   *   function with the roots of $P_{zz}$ increases strictly with $f$,
   *   Newton steps, bisection when a step leaves the bracket, stopped when
   *   the step is at round-off). Then $\psi(F) = \psi_3(F_3)$, $P$ is the
   *   in-plane block of $P_3$ (since $\partial\psi_3/\partial f = P_{zz} =
   *   0$, the total derivative of $\psi$ is the partial one), and the
   *   tangent is condensed by the implicit function theorem,
   *   @f[
   *     A_{abcd} = \frac{\partial P_{ab}}{\partial F_{cd}}
   *       - \frac{\partial P_{ab}}{\partial f}\,
   *         \frac{\partial P_{zz}}{\partial F_{cd}} \Big/
   *         \frac{\partial P_{zz}}{\partial f},
   *   @f]
   *   where $\partial P_{ab}/\partial f = \partial P_{zz}/\partial F_{ab}
   *   = \partial^2\psi_3/\partial F_{ab}\partial f$ and
   *   $\partial P_{zz}/\partial f > 0$ at the root the iteration takes.
   *   Where the law has no such root (see the derived classes), the
   *   functions throw ExcNoPlaneStressState naming the law and $F$.
   *
   * Each function throws ExcNonPositiveJacobian when $\det F \le 0$,
   * rather than returning a NaN (Neo-Hooke) or a meaningless number (Saint
   * Venant-Kirchhoff, whose energy is finite for inverted states). The 3D
   * Jacobian is $J = f\det F$; cauchy_stress() divides by it.
   *
   * <h3>Small strain</h3>
   * The small-strain functions of ConstitutiveLaw (stress(), tangent(),
   * stress_zz()) are those of linearization(), the ElasticMaterial of the
   * same $E$, $\nu$ and model. For both laws and both models this is the
   * linearization of the finite-strain law at $F = I$: in plane strain
   * $A(I) = \lambda I\otimes I + 2\mu\mathbb{I}$; in plane stress $f(I) = 1$,
   * $\partial P_{ab}/\partial f = \partial P_{zz}/\partial F_{ab} = \lambda
   * \delta_{ab}$, $\partial P_{zz}/\partial f = \lambda + 2\mu$, so the
   * condensation replaces $\lambda$ by $2\lambda\mu/(\lambda + 2\mu) =
   * E\nu/(1-\nu^2)$, ElasticMaterial's plane-stress parameter. So is_linear()
   * is true and a small-strain analysis (ElasticityAssembler,
   * StressRecovery) takes these laws as it takes ElasticMaterial.
   */
  class HyperelasticMaterial : public ConstitutiveLaw<2>
  {
  public:
    /**
     * Constructor. Throws (AssertThrow) unless $E$ is finite and in the
     * range of ElasticMaterial (ElasticMaterial::min_youngs_modulus to
     * ElasticMaterial::max_youngs_modulus) and unless $-1 < \nu < 0.5$.
     * @p model is plane strain ($f = 1$) or plane stress ($P_{zz} = 0$).
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

    /// Plane strain or plane stress.
    ElasticMaterial::Model
    model() const
    {
      return model_;
    }

    /// The first Lamé parameter $\lambda = E\nu/((1+\nu)(1-2\nu))$ of the
    /// 3D law (in both models; the plane-stress parameter of the
    /// linearization is linearization().lambda()).
    double
    lambda() const;

    /// The shear modulus $\mu = E/(2(1+\nu))$.
    double
    mu() const;

    /// The linear law of the linearization at $F = I$: an ElasticMaterial
    /// with the same $E$, $\nu$ and model (plane strain or plane stress).
    ElasticMaterial
    linearization() const;

    /// The strain energy $\psi(F)$ per unit reference volume at the
    /// in-plane deformation gradient @p F (in plane stress, the 3D energy
    /// at the out-of-plane stretch $f(F)$). Throws ExcNonPositiveJacobian if
    /// $\det F \le 0$, ExcNoPlaneStressState if plane stress has no state
    /// at @p F.
    double
    strain_energy(const dealii::Tensor<2, 2> &F) const;

    /// The in-plane block of the first Piola-Kirchhoff stress at
    /// $\mathrm{diag}(F, f)$ (see the class documentation). Throws like
    /// strain_energy().
    dealii::Tensor<2, 2>
    first_piola_kirchhoff_stress(const dealii::Tensor<2, 2> &F) const override;

    /// $A = dP/dF$: in plane strain the in-plane block of the 3D tangent,
    /// in plane stress the condensed tangent of the class documentation.
    /// Throws like strain_energy().
    dealii::Tensor<4, 2>
    first_piola_kirchhoff_tangent(const dealii::Tensor<2, 2> &F) const override;

    /// first_piola_kirchhoff_stress() and first_piola_kirchhoff_tangent()
    /// from one evaluation of the law (the same values). Throws like
    /// strain_energy().
    void
    first_piola_kirchhoff_stress_and_tangent(const dealii::Tensor<2, 2> &F,
                                             dealii::Tensor<2, 2>       &P,
                                             dealii::Tensor<4, 2>       &A) const override;

    /// The out-of-plane stretch $f = F_{zz}$ at the in-plane deformation
    /// gradient @p F: 1 in plane strain, the root of $P_{zz}(F, f) = 0$ in
    /// plane stress (the ratio of current to reference thickness of the
    /// sheet). Throws like strain_energy().
    double
    out_of_plane_stretch(const dealii::Tensor<2, 2> &F) const;

    /// The in-plane Cauchy stress $\sigma = J^{-1} P F^T$ at the
    /// deformation gradient @p F, with the 3D Jacobian $J = f\det F$
    /// (symmetric for these laws; returned as a general tensor so that a
    /// test sees any asymmetry). $\sigma_{zz}$ is zero in plane stress.
    dealii::Tensor<2, 2>
    cauchy_stress(const dealii::Tensor<2, 2> &F) const;

    /// The out-of-plane Cauchy stress $\sigma_{zz} = f P_{zz}/J$ at the
    /// in-plane deformation gradient @p F, with $J = f\det F$ (the zz
    /// entry of $J^{-1}P_3F_3^T$): the law's $P_{zz}$ at $f = 1$ in plane
    /// strain, divided by $\det F$ (for Neo-Hooke $\lambda\ln J/J$), and 0 in
    /// plane stress (the root of $P_{zz} = 0$ that defines $f$; returned as
    /// exactly 0). Throws like strain_energy().
    double
    cauchy_stress_zz(const dealii::Tensor<2, 2> &F) const;

    /// True: the laws implement P(F) and dP/dF.
    bool
    has_finite_strain_response() const override;

    /// True: the small-strain response is the linearization at $F = I$.
    bool
    is_linear() const override;

    /// Young's modulus $E$.
    double
    characteristic_stiffness() const override;

    /// The stress of linearization(): $\sigma = \lambda'\,\mathrm{tr}(\varepsilon)
    /// I + 2\mu\varepsilon$ with $\lambda' = \lambda$ (plane strain) or
    /// $E\nu/(1-\nu^2)$ (plane stress).
    dealii::SymmetricTensor<2, 2>
    stress(const dealii::SymmetricTensor<2, 2> &strain) const override;

    /// $\lambda' I\otimes I + 2\mu\mathbb{I}$, the tangent of
    /// linearization() (at any @p strain).
    dealii::SymmetricTensor<4, 2>
    tangent(const dealii::SymmetricTensor<2, 2> &strain) const override;

    /// $\sigma_{zz}$ of linearization(): $\lambda\,\mathrm{tr}\,\varepsilon$
    /// in plane strain, 0 in plane stress.
    double
    stress_zz(const dealii::SymmetricTensor<2, 2> &strain) const override;

  protected:
    /// The 3D law at $F_3 = \mathrm{diag}(F, f)$: what evaluate_3d() gives.
    struct Response3D
    {
      /// $\psi_3(F_3)$.
      double psi = 0;
      /// The in-plane block $P_{ab}$ of $P_3$.
      dealii::Tensor<2, 2> P;
      /// $P_{zz}$.
      double P_zz = 0;
      /// $\partial P_{ab}/\partial F_{cd}$ at fixed $f$.
      dealii::Tensor<4, 2> dP_dF;
      /// $\partial P_{ab}/\partial f$, equal to $\partial P_{zz}/\partial
      /// F_{ab}$ (both are $\partial^2\psi_3/\partial F_{ab}\partial f$).
      dealii::Tensor<2, 2> dP_df;
      /// $\partial P_{zz}/\partial f$.
      double dPzz_df = 0;
    };

    /// What evaluate_3d() must fill (each level includes the ones before).
    enum class Level
    {
      energy,  ///< psi only
      stress,  ///< psi, P, P_zz
      tangent  ///< everything
    };

    /// The 3D law at $\mathrm{diag}(F, f)$ with $\det F = $ @p det_F $> 0$
    /// and @p f $> 0$.
    virtual void
    evaluate_3d(const dealii::Tensor<2, 2> &F,
                const double                det_F,
                const double                f,
                const Level                 level,
                Response3D                 &response) const = 0;

    /**
     * A function $g(f)$ with the same sign as $P_{zz}(F, f)$ on the branch
     * $f > f_{\min}$ returned by stretch_branch(), strictly increasing
     * there, so that its root is the plane-stress stretch; @p derivative
     * is set to $g'(f)$.
     */
    virtual double
    stretch_function(const dealii::Tensor<2, 2> &F, const double det_F, const double f, double &derivative) const = 0;

    /**
     * The lower end $f_{\min} \ge 0$ of the branch on which
     * stretch_function() increases strictly; @p g_min is set to its limit
     * $g(f_{\min}^+)$ (possibly $-\infty$). There is a root iff
     * $g(f_{\min}^+) < 0$ (as $g \to +\infty$ for $f \to \infty$ for
     * both laws).
     */
    virtual double
    stretch_branch(const dealii::Tensor<2, 2> &F, const double det_F, double &g_min) const = 0;

    /// Why the law has no plane-stress state at @p F (for
    /// ExcNoPlaneStressState), given $g(f_{\min}^+) = $ @p g_min $\ge 0$.
    virtual std::string
    no_stretch_explanation(const dealii::Tensor<2, 2> &F, const double det_F, const double g_min) const = 0;

    /// $\det F$ of @p F; throws ExcNonPositiveJacobian (naming the law) if
    /// it is not positive or not finite.
    double
    checked_determinant(const dealii::Tensor<2, 2> &F) const;

    /// The parameters as text for get_name(): "E = ..., nu = ..., plane
    /// strain" (or "plane stress").
    std::string
    parameter_text() const;

  private:
    /// $f$ at @p F: 1 in plane strain, the safeguarded Newton iteration in
    /// plane stress.
    double
    stretch(const dealii::Tensor<2, 2> &F, const double det_F) const;

    double                 E;
    double                 nu;
    ElasticMaterial::Model model_;
    /// The linearization at $F = I$, which answers the small-strain
    /// functions.
    ElasticMaterial linear;
  };



  /**
   * The compressible Neo-Hooke law, with the 3D strain energy (as in
   * deal.II's code-gallery finite-strain examples and in
   * @cite ChiBeiraoPaulino2017)
   * @f[
   *   \psi_3(F_3) = \frac{\mu}{2}(I_1 - 3) - \mu\ln J + \frac{\lambda}{2}(\ln J)^2,
   *   \qquad I_1 = \mathrm{tr}(F_3^TF_3),\quad J = \det F_3,
   * @f]
   * and $P_3 = \mu F_3 + (\lambda\ln J - \mu)F_3^{-T}$. At
   * $F_3 = \mathrm{diag}(F, f)$: $I_1 = \mathrm{tr}(F^TF) + f^2$,
   * $J = f\det F$, and with $c = \lambda\ln J - \mu$
   * @f[
   *   P = \mu F + c\,F^{-T},\qquad
   *   \frac{\partial P_{iJ}}{\partial F_{kL}} = \mu\,\delta_{ik}\delta_{JL}
   *   + \lambda F^{-1}_{Ji}F^{-1}_{Lk} - c\,F^{-1}_{Jk}F^{-1}_{Li},
   * @f]
   * @f[
   *   P_{zz} = \mu f + \frac{c}{f},\qquad
   *   \frac{\partial P_{iJ}}{\partial f} = \frac{\partial P_{zz}}{\partial F_{iJ}}
   *   = \frac{\lambda}{f}F^{-T}_{iJ},\qquad
   *   \frac{\partial P_{zz}}{\partial f} = \mu + \frac{\lambda - c}{f^2}.
   * @f]
   * Plane strain ($f = 1$): at $F = I$, $A = \lambda I\otimes I +
   * 2\mu\mathbb{I}$ on symmetric gradients, the linear law.
   *
   * Plane stress: $P_{zz} = 0$ has the roots of
   * $g(f) = f P_{zz} = \mu(f^2 - 1) + \lambda\ln(f\det F)$, with
   * $g'(f) = 2\mu f + \lambda/f$. For $\nu \ge 0$ ($\lambda \ge 0$), $g$
   * increases strictly on $(0, \infty)$ from $-\infty$ ($\lambda > 0$) or
   * $-\mu$ ($\lambda = 0$) to $+\infty$: there is exactly one root for
   * every $\det F > 0$, and $\partial P_{zz}/\partial f = g'(f)/f > 0$ there.
   * ($P_{zz}$ itself need not be monotone in $f$: its derivative is negative
   * for $\ln J > 1 + \mu(1+f^2)/\lambda$; $f P_{zz}$ is.) For $\nu < 0$,
   * $g$ decreases from $+\infty$ down to its minimum at
   * $f_* = \sqrt{-\lambda/(2\mu)}$ and then increases: the iteration takes
   * the root above $f_*$ (a minimum of $\psi_3$ in $f$); it exists iff
   * $g(f_*) < 0$, which fails under strong in-plane compression, where
   * $\psi_3 \to -\infty$ as $f \to 0$ and the law throws
   * ExcNoPlaneStressState. In uniaxial stress
   * ($F = \mathrm{diag}(\lambda_1, \lambda_2)$, $P_{22} = 0$) isotropy
   * gives $\lambda_2 = f$.
   *
   * The energy grows without bound as $J \to 0^+$ ($\nu \ge 0$), so a
   * converged state never has an inverted point; an evaluation at
   * $\det F \le 0$ throws ExcNonPositiveJacobian.
   */
  class NeoHookeMaterial : public HyperelasticMaterial
  {
  public:
    /// Constructor: see HyperelasticMaterial.
    NeoHookeMaterial(const double                 E     = 1.0,
                     const double                 nu    = 0.3,
                     const ElasticMaterial::Model model = ElasticMaterial::Model::plane_strain);

    /// "Neo-Hooke (E = ..., nu = ..., plane strain)" (or "plane stress").
    std::string
    get_name() const override;

    /// A copy.
    std::unique_ptr<ConstitutiveLaw<2>>
    clone() const override;

  protected:
    /// The formulas of the class documentation.
    void
    evaluate_3d(const dealii::Tensor<2, 2> &F,
                const double                det_F,
                const double                f,
                const Level                 level,
                Response3D                 &response) const override;

    /// $g(f) = \mu(f^2 - 1) + \lambda\ln(f\det F)$.
    double
    stretch_function(const dealii::Tensor<2, 2> &F,
                     const double                det_F,
                     const double                f,
                     double                     &derivative) const override;

    /// $f_* = \sqrt{\max(0, -\lambda/(2\mu))}$ and $g(f_*^+)$.
    double
    stretch_branch(const dealii::Tensor<2, 2> &F, const double det_F, double &g_min) const override;

    /// The minimum of $g$ and where it is.
    std::string
    no_stretch_explanation(const dealii::Tensor<2, 2> &F, const double det_F, const double g_min) const override;
  };



  /**
   * The Saint Venant-Kirchhoff law: the linear isotropic law written
   * between the Green-Lagrange strain $\mathsf{E} = \frac12(F_3^TF_3 - I)$
   * and the second Piola-Kirchhoff stress,
   * @f[
   *   \psi_3 = \frac{\lambda}{2}(\mathrm{tr}\,\mathsf{E})^2 + \mu\,\mathsf{E}:\mathsf{E},\qquad
   *   S = \lambda\,\mathrm{tr}(\mathsf{E})I + 2\mu\mathsf{E},\qquad P_3 = F_3S.
   * @f]
   * At $F_3 = \mathrm{diag}(F, f)$: $\mathsf{E}$ has the in-plane block
   * $\frac12(F^TF - I)$ and $\mathsf{E}_{zz} = (f^2 - 1)/2$,
   * $\mathrm{tr}\,\mathsf{E} = e + \mathsf{E}_{zz}$ with
   * $e = \mathrm{tr}\,\mathsf{E}_{2D}$, and
   * @f[
   *   P = FS_{2D},\qquad
   *   \frac{\partial P_{iJ}}{\partial F_{kL}} = \delta_{ik}S_{JL} + F_{iM}\,\mathbb{C}_{MJNL}\,F_{kN}
   *   = \delta_{ik}S_{JL} + \lambda F_{iJ}F_{kL} + \mu\big((FF^T)_{ik}\delta_{JL} + F_{iL}F_{kJ}\big),
   * @f]
   * @f[
   *   P_{zz} = fS_{zz},\quad S_{zz} = \lambda\,\mathrm{tr}\,\mathsf{E} + 2\mu\mathsf{E}_{zz},\qquad
   *   \frac{\partial P_{iJ}}{\partial f} = \frac{\partial P_{zz}}{\partial F_{iJ}} = \lambda f F_{iJ},\qquad
   *   \frac{\partial P_{zz}}{\partial f} = S_{zz} + (\lambda + 2\mu)f^2.
   * @f]
   * In plane strain $f = 1$, $\mathsf{E}_{zz} = 0$. The law is objective
   * and exact for large rotations, but not polyconvex: under strong
   * compression (stretches below $1/\sqrt{3}$ in uniaxial plane strain)
   * its tangent loses definiteness.
   *
   * Plane stress: $P_{zz} = 0$ with $f > 0$ means $S_{zz} = g(f) = \lambda e
   * + (\lambda/2 + \mu)(f^2 - 1) = 0$, and $g$ increases strictly in $f$, so
   * there is at most one root, $f^2 = 1 - \lambda e/(\lambda/2 + \mu)$
   * (the iteration finds it like Neo-Hooke's; a test checks it against
   * this closed form). It exists iff $\lambda e < \lambda/2 + \mu$: for
   * $\nu > 0$ a large enough in-plane stretch (for $\nu = 0.3$, an
   * equibiaxial stretch beyond $\sqrt{13/6} \approx 1.47$) would need the
   * sheet's thickness to vanish, and the law throws ExcNoPlaneStressState
   * there. In compression ($e < 0$, $\nu \ge 0$) the root exists, $f > 1$,
   * but the in-plane tangent may lose definiteness as in plane strain.
   *
   * The energy is finite for $\det F \le 0$, but the law refuses such
   * states (ExcNonPositiveJacobian) like NeoHookeMaterial: an inverted
   * point is a failed computation, not a result.
   */
  class SaintVenantKirchhoffMaterial : public HyperelasticMaterial
  {
  public:
    /// Constructor: see HyperelasticMaterial.
    SaintVenantKirchhoffMaterial(const double                 E     = 1.0,
                                 const double                 nu    = 0.3,
                                 const ElasticMaterial::Model model = ElasticMaterial::Model::plane_strain);

    /// "Saint Venant-Kirchhoff (E = ..., nu = ..., plane strain)" (or
    /// "plane stress").
    std::string
    get_name() const override;

    /// A copy.
    std::unique_ptr<ConstitutiveLaw<2>>
    clone() const override;

  protected:
    /// The formulas of the class documentation.
    void
    evaluate_3d(const dealii::Tensor<2, 2> &F,
                const double                det_F,
                const double                f,
                const Level                 level,
                Response3D                 &response) const override;

    /// $g(f) = S_{zz} = \lambda e + (\lambda/2 + \mu)(f^2 - 1)$.
    double
    stretch_function(const dealii::Tensor<2, 2> &F,
                     const double                det_F,
                     const double                f,
                     double                     &derivative) const override;

    /// $f_{\min} = 0$, $g(0) = \lambda e - \lambda/2 - \mu$.
    double
    stretch_branch(const dealii::Tensor<2, 2> &F, const double det_F, double &g_min) const override;

    /// The in-plane trace $e$ and the bound it exceeds.
    std::string
    no_stretch_explanation(const dealii::Tensor<2, 2> &F, const double det_F, const double g_min) const override;
  };
} // namespace dealvem

#endif
