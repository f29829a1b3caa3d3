// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_material_library_h
#define dealvem_elasticity_material_library_h

#include <deal.II/base/types.h>

#include <dealvem/elasticity/constitutive_law.h>

#include <map>
#include <memory>
#include <vector>

namespace dealvem
{
  class ElasticMaterial;

  /**
   * One constitutive law per material id: what ElasticityAssembler,
   * StressRecovery, compute_errors() and ContactScales take. The laws are
   * held polymorphically (ConstitutiveLaw), shared and immutable, so copying
   * a library is cheap and the copies share the law objects.
   *
   * Programs that use only the linear isotropic law keep writing
   * `std::map<material_id, ElasticMaterial>`: every function that takes a
   * library has an overload for that map, which converts it with the
   * constructor below.
   */
  template <int dim>
  class MaterialLibrary
  {
  public:
    /// An empty library.
    MaterialLibrary() = default;

    /// A library holding a copy of each ElasticMaterial of @p materials
    /// under its material id (dim = 2 only, as ElasticMaterial).
    explicit MaterialLibrary(
      const std::map<dealii::types::material_id, ElasticMaterial> &materials);

    /// Add a copy (ConstitutiveLaw::clone()) of @p law for material id
    /// @p id. Throws if @p id has a law already.
    void
    add(const dealii::types::material_id id, const ConstitutiveLaw<dim> &law);

    /// Add the shared law @p law for material id @p id. Throws if @p law is
    /// null or @p id has a law already.
    void
    add(const dealii::types::material_id id, const std::shared_ptr<const ConstitutiveLaw<dim>> &law);

    /// Whether material id @p id has a law.
    bool
    has_law(const dealii::types::material_id id) const
    {
      return laws.count(id) > 0;
    }

    /// The law of material id @p id; throws, naming the id, if there is
    /// none.
    const ConstitutiveLaw<dim> &
    get_law(const dealii::types::material_id id) const;

    /// The law of material id @p id, shared.
    const std::shared_ptr<const ConstitutiveLaw<dim>> &
    get_shared_law(const dealii::types::material_id id) const;

    /// Number of material ids with a law.
    unsigned int
    size() const
    {
      return laws.size();
    }

    /// The material ids with a law, increasing.
    std::vector<dealii::types::material_id>
    get_material_ids() const;

    /// Whether every law is linear (ConstitutiveLaw::is_linear()).
    bool
    all_linear() const;

    /// The smallest ConstitutiveLaw::characteristic_stiffness() of the
    /// laws (throws if the library is empty).
    double
    min_characteristic_stiffness() const;

    /// The laws by material id.
    const std::map<dealii::types::material_id, std::shared_ptr<const ConstitutiveLaw<dim>>> &
    get_laws() const
    {
      return laws;
    }

  private:
    std::map<dealii::types::material_id, std::shared_ptr<const ConstitutiveLaw<dim>>> laws;
  };
} // namespace dealvem

#endif
