// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_material_h
#define dealvem_elasticity_material_h

#include <deal.II/base/symmetric_tensor.h>

#include <dealvem/elasticity/constitutive_law.h>

#include <memory>
#include <string>

namespace dealvem
{
  /**
   * Isotropic linear elastic material for 2D problems, in plane strain or
   * plane stress.
   *
   * With Young's modulus $E$ and Poisson's ratio $\nu$,
   * $\mu = E/(2(1+\nu))$ and, in plane strain, $\lambda = E\nu/((1+\nu)(1-2\nu))$;
   * in plane stress $\lambda$ is replaced by $\lambda^* = 2\lambda\mu/(\lambda+2\mu)$.
   * The stress is $\sigma = \lambda\,\mathrm{tr}(\varepsilon) I + 2\mu\varepsilon$.
   * In Voigt notation with engineering shear strain,
   * $(\sigma_{xx},\sigma_{yy},\sigma_{xy}) = C(\varepsilon_{xx},\varepsilon_{yy},2\varepsilon_{xy})$ with
   * @f[ C = \begin{pmatrix}\lambda+2\mu & \lambda & 0\\ \lambda & \lambda+2\mu & 0\\ 0&0&\mu\end{pmatrix}. @f]
   *
   * It is the linear isotropic ConstitutiveLaw: the tangent is
   * $\lambda I\otimes I + 2\mu\,\mathbb{I}$ at every strain, and the
   * characteristic stiffness is $E$. It has no finite-strain response (the
   * finite-strain functions of ConstitutiveLaw throw).
   */
  class ElasticMaterial : public ConstitutiveLaw<2>
  {
  public:
    /// The 2D reduction of the 3D isotropic law.
    enum class Model
    {
      plane_strain, ///< $\varepsilon_{zz} = 0$: thick bodies; $\sigma_{zz} = \lambda\,\mathrm{tr}\,\varepsilon$
      plane_stress  ///< $\sigma_{zz} = 0$: thin plates; $\lambda$ replaced by $2\lambda\mu/(\lambda+2\mu)$
    };

    /// The range of Young's modulus the element computations support:
    /// outside it, products such as E * h^2 underflow to zero or
    /// overflow (zero stresses or "degenerate polygon" errors).
    static constexpr double min_youngs_modulus = 1e-200;
    static constexpr double max_youngs_modulus = 1e200; ///< see min_youngs_modulus

    /**
     * Constructor. Throws (AssertThrow, also in Release builds) unless
     * min_youngs_modulus <= E <= max_youngs_modulus and -1 < nu < 0.5.
     */
    ElasticMaterial(const double E = 1.0,
                    const double nu = 0.3,
                    const Model  model = Model::plane_strain);

    /// Young's modulus E (units of a stress; tractions and pressures are
    /// given in the same units).
    double
    youngs_modulus() const
    {
      return E;
    }

    /// Poisson's ratio $\nu$, $-1 < \nu < 0.5$ (dimensionless).
    double
    poissons_ratio() const
    {
      return nu;
    }

    /// Plane strain or plane stress.
    Model
    model() const
    {
      return model_;
    }

    /// The effective first Lamé parameter (plane-stress corrected).
    double
    lambda() const;

    /// Shear modulus.
    double
    mu() const;

    /// $\sigma = C\varepsilon$.
    dealii::SymmetricTensor<2, 2>
    stress(const dealii::SymmetricTensor<2, 2> &strain) const override;

    /// The out-of-plane stress $\sigma_{zz}$ for a given in-plane strain
    /// (zero in plane stress, $\nu(\sigma_{xx}+\sigma_{yy})$ in plane strain).
    double
    stress_zz(const dealii::SymmetricTensor<2, 2> &strain) const override;

    /// The tangent $\lambda I\otimes I + 2\mu\,\mathbb{I}$ (the same at
    /// every strain): components $C_{0000} = C_{1111} = \lambda+2\mu$,
    /// $C_{0011} = \lambda$, $C_{0101} = \mu$.
    dealii::SymmetricTensor<4, 2>
    tangent(const dealii::SymmetricTensor<2, 2> &strain) const override;

    /// True.
    bool
    is_linear() const override;

    /// Young's modulus $E$.
    double
    characteristic_stiffness() const override;

    /// "linear isotropic (E = ..., nu = ..., plane strain)".
    std::string
    get_name() const override;

    /// A copy.
    std::unique_ptr<ConstitutiveLaw<2>>
    clone() const override;

    /// Von Mises stress of a 2D stress state with the given $\sigma_{zz}$
    /// (von_mises_stress()).
    static double
    von_mises(const dealii::SymmetricTensor<2, 2> &stress, const double sigma_zz);

    /// "plane strain" or "plane stress".
    static std::string
    model_name(const Model m);

    /// Parse "plane strain" / "plane stress"; throws for anything else.
    static Model
    parse_model(const std::string &name);

  private:
    double E;
    double nu;
    Model  model_;
  };
} // namespace dealvem

#endif
