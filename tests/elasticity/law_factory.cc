// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// LawFactory: the constitutive laws by name, the one seam a new law joins.
//   1. the built-in names and an alias are found however the parameter file
//      spells them (case, blanks), with the right class (get_name()) and
//      the same tangent at zero strain as the class made directly
//      (E = 7000, nu = 0.3: the difference is 0 exactly);
//   2. an unknown name is refused with the parameter, the value and the list
//      of laws;
//   3. a user's law joins with add(): found by its name, listed last,
//      created; a taken name or alias and a law without create function are
//      refused.
#include <deal.II/base/symmetric_tensor.h>

#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/law_factory.h>

#include "../tests.h"

using namespace dealvem;

namespace
{
  double
  tangent_difference(const ConstitutiveLaw<2> &a, const ConstitutiveLaw<2> &b)
  {
    const dealii::SymmetricTensor<2, 2> zero;
    return (a.tangent(zero) - b.tangent(zero)).norm();
  }
} // namespace

int
main()
{
  const auto ps = ElasticMaterial::Model::plane_strain;
  // 1. built-in laws
  {
    const auto linear = LawFactory::create("Linear", "Material/Law", 7000, 0.3, ps);
    const auto neo    = LawFactory::create("  Neo-Hookean ", "Material/Law", 7000, 0.3, ps);
    const auto svk    = LawFactory::create("saint   Venant-Kirchhoff", "Material/Law", 7000, 0.3, ps);
    testing::check(linear->get_name() == ElasticMaterial(7000, 0.3, ps).get_name(),
                   "'Linear' makes " + linear->get_name());
    testing::check(neo->get_name() == NeoHookeMaterial(7000, 0.3, ps).get_name(),
                   "'  Neo-Hookean ' (alias) makes " + neo->get_name());
    testing::check(svk->get_name() == SaintVenantKirchhoffMaterial(7000, 0.3, ps).get_name(),
                   "'saint   Venant-Kirchhoff' makes " + svk->get_name());
    testing::check_small(tangent_difference(*linear, ElasticMaterial(7000, 0.3, ps)), 0.,
                         "linear: tangent as ElasticMaterial's");
    testing::check_small(tangent_difference(*neo, NeoHookeMaterial(7000, 0.3, ps)), 0.,
                         "neo-hooke: tangent as NeoHookeMaterial's");
    testing::check(!LawFactory::find("linear", "x").hyperelastic && LawFactory::find("neo-hooke", "x").hyperelastic &&
                     LawFactory::find("saint venant-kirchhoff", "x").hyperelastic,
                   "only the linear law has no finite-strain response");
    testing::check(LawFactory::names() == std::vector<std::string>{"linear", "neo-hooke", "saint venant-kirchhoff"},
                   "the built-in names, in order");
  }

  // 2. unknown names
  testing::check_throws([] { LawFactory::create("mooney-rivlin", "Body 2/Material/Law", 1, 0.3, ps); },
                        "Parameter 'Body 2/Material/Law' = 'mooney-rivlin' is not a law of the program: use "
                        "'linear', 'neo-hooke' or 'saint venant-kirchhoff'.",
                        "an unknown law is refused with the parameter and the list");

  // 3. a user's law
  LawFactory::add({"Stiff Linear",
                   {"stiff"},
                   false,
                   [](const double E, const double nu, const ElasticMaterial::Model model) {
                     return std::shared_ptr<const ConstitutiveLaw<2>>(
                       std::make_shared<const ElasticMaterial>(2 * E, nu, model));
                   },
                   "linear, twice as stiff"});
  const auto stiff = LawFactory::create("stiff", "Material/Law", 7000, 0.3, ps);
  testing::check_small(tangent_difference(*stiff, ElasticMaterial(14000, 0.3, ps)), 0.,
                       "a user's law is created by its alias");
  testing::check(LawFactory::names().back() == "stiff linear" &&
                   LawFactory::documentation().find("'stiff linear' (linear, twice as stiff)") != std::string::npos,
                 "a user's law is listed last, with its description");
  testing::check_throws(
    [] {
      LawFactory::add({"elastic", {"LINEAR"}, false, [](double E, double nu, ElasticMaterial::Model m) {
                         return std::shared_ptr<const ConstitutiveLaw<2>>(std::make_shared<const ElasticMaterial>(E, nu, m));
                       }, ""});
    },
    "the name 'linear' is taken by the law 'linear'", "a taken alias is refused");
  testing::check_throws([] { LawFactory::add({"no create", {}, false, nullptr, ""}); }, "has no create function",
                        "a law without create function is refused");
  return testing::finish();
}
