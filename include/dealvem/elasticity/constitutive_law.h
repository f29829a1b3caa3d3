// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_constitutive_law_h
#define dealvem_elasticity_constitutive_law_h

#include <deal.II/base/subscriptor.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>

namespace dealvem
{
  /**
   * The constitutive law of a body: what the elasticity code asks of a
   * material at one point. It is the seam between the element computations
   * (ElasticityOperator, StressRecovery, compute_errors, ContactScales),
   * which call only the functions below, and the materials, which implement
   * them: ElasticMaterial (linear isotropic, plane strain or plane stress)
   * is the first; a user writes another one by deriving from this class.
   * Laws are kept per material id in a MaterialLibrary.
   *
   * <h3>Small strain</h3>
   * A law gives the in-plane stress $\sigma(\varepsilon)$ and its tangent
   * $\mathbb{C}(\varepsilon) = \partial\sigma/\partial\varepsilon$ (a
   * SymmetricTensor<4,dim>, so that $d\sigma = \mathbb{C} : d\varepsilon$
   * with the tensor components of the strain, not the engineering shear
   * strain) at a strain $\varepsilon$, the out-of-plane stress
   * $\sigma_{zz}(\varepsilon)$ (zero in plane stress), whether it is linear
   * ($\mathbb{C}$ independent of $\varepsilon$, $\sigma = \mathbb{C}:\varepsilon$),
   * and a characteristic stiffness (a modulus, in units of stress) for the
   * scalings that need one. Who calls what:
   * - ElasticityOperator: the tangent at zero strain of a linear law, in the
   *   consistency term $\int_E \varepsilon(\Pi u):\mathbb{C}:\varepsilon(\Pi v)$.
   *   It refuses a non-linear law: linearizing it is the job of a Newton
   *   driver, which does not exist yet.
   * - StressRecovery: stress() and stress_zz() of the projected strain.
   * - compute_errors(): stress() in the energy norm (linear laws only).
   * - ContactScales: characteristic_stiffness(), the $E$ of the rule
   *   $E_{min}/h_{min}$.
   * The stabilization of the element scales with the trace of the
   * consistency matrix, hence with the tangent, and needs nothing else.
   *
   * <h3>Finite strain</h3>
   * A hyperelastic law for large deformations (Saint Venant-Kirchhoff,
   * Neo-Hooke) gives the first Piola-Kirchhoff stress $P(F)$ and its
   * tangent $\partial P/\partial F$ (a general Tensor<4,dim>: $P$ is not
   * symmetric) at a deformation gradient $F$. These are virtual functions of
   * this same class, whose defaults throw "not implemented for this law":
   * a finite-strain law overrides them and says so by
   * has_finite_strain_response(), and also implements the small-strain
   * functions (its linearization at $F = I$, with is_linear() false if its
   * small-strain stress is not linear), so every small-strain caller above
   * keeps working with it. The total Lagrangian operator
   * (FiniteStrainOperator) evaluates $F = I + \Pi^0\nabla u$ at the
   * polygon's quadrature points from the full-gradient projection of the
   * space (VirtualElement::get_gradient_projector(),
   * VEMValues::shape_gradient_projection()) and integrates
   * $P(F):\Pi^0\nabla v$; FiniteStrainAssembler and FiniteStrainSolver
   * (Newton with load steps) drive it; nothing in the small-strain callers
   * changes. The laws: NeoHookeMaterial and SaintVenantKirchhoffMaterial
   * (HyperelasticMaterial). One interface rather than two keeps one
   * MaterialLibrary per body for both kinds of analysis. In plane strain
   * $F_{zz} = 1$; a plane-stress finite-strain law must solve $P_{zz} = 0$
   * for $F_{zz}$ itself.
   *
   * Laws are immutable (every function is const) and carry no history, so
   * one object may be shared by many cells and threads; a law with internal
   * variables (plasticity) will need a state per quadrature point, which
   * this interface does not hold.
   *
   * The class derives from dealii::Subscriptor, so that objects holding a
   * law by dealii::SmartPointer are checked for outliving it.
   */
  template <int dim>
  class ConstitutiveLaw : public dealii::Subscriptor
  {
  public:
    virtual ~ConstitutiveLaw() override = default;

    /// A name for messages, e.g. "linear isotropic (E = 7000, nu = 0.3,
    /// plane strain)".
    virtual std::string
    get_name() const = 0;

    /// A copy of the law (MaterialLibrary stores copies).
    virtual std::unique_ptr<ConstitutiveLaw<dim>>
    clone() const = 0;

    /// Whether the tangent is independent of the strain, so that
    /// $\sigma(\varepsilon) = \mathbb{C}:\varepsilon$ with
    /// $\mathbb{C}$ = tangent() at any strain.
    virtual bool
    is_linear() const = 0;

    /**
     * A stiffness in units of stress for the scalings that need one: the
     * contact scales $E_{min}/h_{min}$ (ContactScales), where it plays the
     * part of Young's modulus. ElasticMaterial returns $E$; an anisotropic
     * law should return a modulus of its softest direction, so that the
     * penalty and complementarity constants derived from it are not too
     * stiff for the body.
     */
    virtual double
    characteristic_stiffness() const = 0;

    /// The in-plane stress $\sigma(\varepsilon)$ at the strain @p strain.
    virtual dealii::SymmetricTensor<2, dim>
    stress(const dealii::SymmetricTensor<2, dim> &strain) const = 0;

    /// The tangent $\mathbb{C} = \partial\sigma/\partial\varepsilon$ at the
    /// strain @p strain (for a linear law the same at every strain). It
    /// must have the major symmetry $\mathbb{C}_{ijkl} = \mathbb{C}_{klij}$
    /// of a law with a strain energy; ElasticityOperator checks this.
    virtual dealii::SymmetricTensor<4, dim>
    tangent(const dealii::SymmetricTensor<2, dim> &strain) const = 0;

    /// The out-of-plane stress $\sigma_{zz}$ at the in-plane strain
    /// @p strain (zero in plane stress).
    virtual double
    stress_zz(const dealii::SymmetricTensor<2, dim> &strain) const = 0;

    /// Whether the law implements the finite-strain functions below.
    /// Default: false.
    virtual bool
    has_finite_strain_response() const;

    /// The first Piola-Kirchhoff stress $P(F)$ at the deformation gradient
    /// @p F. The default throws: not implemented for this law.
    virtual dealii::Tensor<2, dim>
    first_piola_kirchhoff_stress(const dealii::Tensor<2, dim> &F) const;

    /// The tangent $\partial P/\partial F$ at @p F, such that
    /// $dP_{iJ} = A_{iJkL}\,dF_{kL}$. The default throws: not implemented
    /// for this law.
    virtual dealii::Tensor<4, dim>
    first_piola_kirchhoff_tangent(const dealii::Tensor<2, dim> &F) const;

    /// The stress @p P and the tangent @p A at @p F in one call, with the
    /// values of first_piola_kirchhoff_stress() and
    /// first_piola_kirchhoff_tangent() (for the assembly of a tangent,
    /// which needs both at every quadrature point). The default calls the
    /// two; a law that shares work between them (HyperelasticMaterial)
    /// evaluates itself once.
    virtual void
    first_piola_kirchhoff_stress_and_tangent(const dealii::Tensor<2, dim> &F,
                                             dealii::Tensor<2, dim>       &P,
                                             dealii::Tensor<4, dim>       &A) const;
  };



  /**
   * The von Mises stress
   * $\sqrt{\frac12((\sigma_{xx}-\sigma_{yy})^2+(\sigma_{yy}-\sigma_{zz})^2+(\sigma_{zz}-\sigma_{xx})^2)+3\sigma_{xy}^2}$
   * of a 2D stress state with the out-of-plane stress @p sigma_zz (any law).
   */
  double
  von_mises_stress(const dealii::SymmetricTensor<2, 2> &stress, const double sigma_zz);
} // namespace dealvem

#endif
