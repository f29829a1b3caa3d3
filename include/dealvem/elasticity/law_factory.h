// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_law_factory_h
#define dealvem_elasticity_law_factory_h

#include <dealvem/elasticity/constitutive_law.h>
#include <dealvem/elasticity/material.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dealvem
{
  /**
   * The constitutive laws a program can create by name: the one place a new
   * law is registered for the parameter files ('Material/Law'), for
   * ElasticityProblem and ContactProblem alike.
   *
   * Each law is made from Young's modulus, Poisson's ratio and the 2D model
   * (plane strain or plane stress). Built in are
   * - `linear`: ElasticMaterial,
   * - `neo-hooke` (also `neo-hookean`): NeoHookeMaterial,
   * - `saint venant-kirchhoff`: SaintVenantKirchhoffMaterial.
   *
   * Names are compared in lower case with runs of white space as one blank,
   * so 'Neo-Hooke' and 'saint  Venant-Kirchhoff' are found. A user's law
   * joins with add() before the parameter file is read:
   * @code
   *   LawFactory::add({"my law", {}, true,
   *                    [](double E, double nu, ElasticMaterial::Model m) {
   *                      return std::make_shared<const MyLaw>(E, nu, m);
   *                    },
   *                    "my hyperelastic law"});
   * @endcode
   * The registry is shared by the whole program; add() is not thread-safe
   * (call it from main() before the solves start).
   */
  namespace LawFactory
  {
    /// How a law is made and described.
    struct Entry
    {
      /// The name in the parameter file (lower case, single blanks).
      std::string name;
      /// Further names accepted for it.
      std::vector<std::string> aliases;
      /// Whether it has a finite-strain response (can run with
      /// 'Finite strain/Enabled').
      bool hyperelastic = false;
      /// Make the law from E, nu and the 2D model.
      std::function<std::shared_ptr<const ConstitutiveLaw<2>>(double, double, ElasticMaterial::Model)> create;
      /// One line for the parameter documentation.
      std::string description;
    };

    /// Register a law (AssertThrow if its name or an alias is taken, or it
    /// has no create function).
    void
    add(const Entry &entry);

    /**
     * The law called @p value (as the parameter file spells it). Unknown
     * names are refused with an ExcMessage that names @p parameter, the
     * value and the laws on offer.
     */
    const Entry &
    find(const std::string &value, const std::string &parameter);

    /// The registered names, in the order they were added.
    std::vector<std::string>
    names();

    /// The documentation of the parameter: every law with its description.
    std::string
    documentation();

    /// Make the law called @p value (find(value, parameter).create).
    std::shared_ptr<const ConstitutiveLaw<2>>
    create(const std::string &value, const std::string &parameter, double youngs_modulus, double poissons_ratio,
           ElasticMaterial::Model model);
  } // namespace LawFactory
} // namespace dealvem

#endif
