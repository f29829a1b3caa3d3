// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/law_factory.h>

#include <cctype>

namespace dealvem
{
  namespace LawFactory
  {
    namespace
    {
      // lower case, no blanks at the ends, runs of white space as one blank
      std::string
      normalized(const std::string &value)
      {
        std::string v;
        for (const char c : value)
          {
            const char l = std::tolower(static_cast<unsigned char>(c));
            if (std::isspace(static_cast<unsigned char>(l)))
              {
                if (!v.empty() && v.back() != ' ')
                  v += ' ';
              }
            else
              v += l;
          }
        if (!v.empty() && v.back() == ' ')
          v.pop_back();
        return v;
      }

      // the registry, made with the built-in laws on first use (no order
      // of static initialization to depend on)
      std::vector<Entry> &
      registry()
      {
        static std::vector<Entry> entries{
          {"linear",
           {},
           false,
           [](const double E, const double nu, const ElasticMaterial::Model model) {
             return std::shared_ptr<const ConstitutiveLaw<2>>(std::make_shared<const ElasticMaterial>(E, nu, model));
           },
           "isotropic linear elasticity"},
          {"neo-hooke",
           {"neo-hookean"},
           true,
           [](const double E, const double nu, const ElasticMaterial::Model model) {
             return std::shared_ptr<const ConstitutiveLaw<2>>(
               std::make_shared<const NeoHookeMaterial>(E, nu, model));
           },
           "compressible Neo-Hooke, psi = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2"},
          {"saint venant-kirchhoff",
           {},
           true,
           [](const double E, const double nu, const ElasticMaterial::Model model) {
             return std::shared_ptr<const ConstitutiveLaw<2>>(
               std::make_shared<const SaintVenantKirchhoffMaterial>(E, nu, model));
           },
           "psi = lambda/2 (tr E)^2 + mu E:E, E the Green-Lagrange strain"}};
        return entries;
      }

      // "'a', 'b' or 'c'"
      std::string
      listing(const bool with_descriptions)
      {
        const auto &entries = registry();
        std::string out;
        for (unsigned int i = 0; i < entries.size(); ++i)
          {
            if (i > 0)
              out += (i + 1 == entries.size() ? " or " : ", ");
            out += "'" + entries[i].name + "'";
            if (with_descriptions && !entries[i].description.empty())
              out += " (" + entries[i].description + ")";
          }
        return out;
      }
    } // namespace



    void
    add(const Entry &entry)
    {
      AssertThrow(entry.create != nullptr,
                  dealii::ExcMessage("LawFactory::add(): the law '" + entry.name + "' has no create function."));
      std::vector<std::string> keys{normalized(entry.name)};
      for (const auto &a : entry.aliases)
        keys.push_back(normalized(a));
      for (const auto &key : keys)
        {
          AssertThrow(!key.empty(), dealii::ExcMessage("LawFactory::add(): a law needs a non-empty name."));
          for (const auto &e : registry())
            {
              bool taken = (normalized(e.name) == key);
              for (const auto &a : e.aliases)
                taken = taken || normalized(a) == key;
              AssertThrow(!taken, dealii::ExcMessage("LawFactory::add(): the name '" + key +
                                                     "' is taken by the law '" + e.name + "'."));
            }
        }
      Entry copy = entry;
      copy.name  = keys[0];
      registry().push_back(copy);
    }



    const Entry &
    find(const std::string &value, const std::string &parameter)
    {
      const std::string v = normalized(value);
      for (const auto &e : registry())
        {
          if (e.name == v)
            return e;
          for (const auto &a : e.aliases)
            if (normalized(a) == v)
              return e;
        }
      AssertThrow(false, dealii::ExcMessage("Parameter '" + parameter + "' = '" + value +
                                            "' is not a law of the program: use " + listing(false) + "."));
      return registry().front();
    }



    std::vector<std::string>
    names()
    {
      std::vector<std::string> out;
      for (const auto &e : registry())
        out.push_back(e.name);
      return out;
    }



    std::string
    documentation()
    {
      return listing(true);
    }



    std::shared_ptr<const ConstitutiveLaw<2>>
    create(const std::string &value, const std::string &parameter, const double youngs_modulus,
           const double poissons_ratio, const ElasticMaterial::Model model)
    {
      return find(value, parameter).create(youngs_modulus, poissons_ratio, model);
    }
  } // namespace LawFactory
} // namespace dealvem
