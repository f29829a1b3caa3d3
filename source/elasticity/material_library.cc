// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/elasticity/material.h>
#include <dealvem/elasticity/material_library.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace dealvem
{
  template <int dim>
  MaterialLibrary<dim>::MaterialLibrary(
    const std::map<dealii::types::material_id, ElasticMaterial> &materials)
  {
    for (const auto &m : materials)
      laws.emplace(m.first, std::make_shared<const ElasticMaterial>(m.second));
  }



  template <int dim>
  void
  MaterialLibrary<dim>::add(const dealii::types::material_id id, const ConstitutiveLaw<dim> &law)
  {
    add(id, std::shared_ptr<const ConstitutiveLaw<dim>>(law.clone()));
  }



  template <int dim>
  void
  MaterialLibrary<dim>::add(const dealii::types::material_id                   id,
                            const std::shared_ptr<const ConstitutiveLaw<dim>> &law)
  {
    AssertThrow(law != nullptr,
                dealii::ExcMessage("MaterialLibrary::add(): the law given for material id " +
                                   std::to_string(id) + " is null."));
    AssertThrow(laws.count(id) == 0,
                dealii::ExcMessage("MaterialLibrary::add(): material id " + std::to_string(id) +
                                   " has a law already ('" + laws.at(id)->get_name() + "')."));
    laws.emplace(id, law);
  }



  template <int dim>
  const std::shared_ptr<const ConstitutiveLaw<dim>> &
  MaterialLibrary<dim>::get_shared_law(const dealii::types::material_id id) const
  {
    const auto it = laws.find(id);
    AssertThrow(it != laws.end(),
                dealii::ExcMessage("No constitutive law is defined for material id " + std::to_string(id) +
                                   " (the material library has " + std::to_string(laws.size()) + " law(s))."));
    return it->second;
  }



  template <int dim>
  const ConstitutiveLaw<dim> &
  MaterialLibrary<dim>::get_law(const dealii::types::material_id id) const
  {
    return *get_shared_law(id);
  }



  template <int dim>
  std::vector<dealii::types::material_id>
  MaterialLibrary<dim>::get_material_ids() const
  {
    std::vector<dealii::types::material_id> ids;
    for (const auto &l : laws)
      ids.push_back(l.first);
    return ids;
  }



  template <int dim>
  bool
  MaterialLibrary<dim>::all_linear() const
  {
    return std::all_of(laws.begin(), laws.end(), [](const auto &l) { return l.second->is_linear(); });
  }



  template <int dim>
  double
  MaterialLibrary<dim>::min_characteristic_stiffness() const
  {
    AssertThrow(!laws.empty(), dealii::ExcMessage("MaterialLibrary: no law, so no characteristic stiffness."));
    double s = laws.begin()->second->characteristic_stiffness();
    for (const auto &l : laws)
      s = std::min(s, l.second->characteristic_stiffness());
    return s;
  }



  template class MaterialLibrary<2>;
} // namespace dealvem
