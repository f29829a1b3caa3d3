// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// ContactProblem: the set-up API for programs (bodies, pairs, friction
// coefficients) and the check of the set-up as a whole.
#include "contact_problem_internal.h"

#include <dealvem/vem/virtual_element.h>

namespace dealvem
{
  using namespace internal::ContactProblemImplementation;

  namespace internal
  {
    namespace ContactProblemImplementation
    {
      // A material name: letters, digits, '_', '-', '.' (not empty).
      void
      check_material_name(const std::string &name, const std::string &where)
      {
        if (name.empty() && where.find("Material/Name") != std::string::npos)
          return; // the entry may stay empty
        const bool valid = !name.empty() && std::all_of(name.begin(), name.end(), [](const char c) {
                             return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
                           });
        AssertThrow(valid, dealii::ExcMessage(where + ": the material name '" + name + "' is not valid: use letters, "
                                              "digits, '_', '-' and '.' (and '*' in a friction entry for any "
                                              "material)."));
      }
    } // namespace ContactProblemImplementation
  } // namespace internal



  unsigned int
  ContactProblem::add_body(const PolygonalMesh<2>   &mesh,
                           const ConstitutiveLaw<2> &material,
                           const unsigned int        boundary_id_offset)
  {
    const unsigned int b = bodies.size();
    AssertThrow(b < max_bodies,
                dealii::ExcMessage("ContactProblem::add_body(): at most " + std::to_string(max_bodies) +
                                   " bodies."));
    AssertThrow(mesh.n_cells() > 0,
                dealii::ExcMessage("ContactProblem::add_body(): the mesh of body " + std::to_string(b) +
                                   (mesh.name.empty() ? std::string() : " ('" + mesh.name + "')") +
                                   " has no cells."));
    AssertThrow(material.is_linear(),
                dealii::ExcMessage("ContactProblem::add_body(): the material of body " + std::to_string(b) + " ('" +
                                   material.get_name() +
                                   "') is not linear; the contact problem solves linear elasticity."));
    {
      const auto *mine  = dynamic_cast<const ElasticMaterial *>(&material);
      const auto *first = bodies.empty() ? nullptr : dynamic_cast<const ElasticMaterial *>(bodies[0].material.get());
      AssertThrow(mine == nullptr || first == nullptr || first->model() == mine->model(),
                  dealii::ExcMessage("ContactProblem::add_body(): body " + std::to_string(b) + " is in " +
                                     ElasticMaterial::model_name(mine->model()) + ", body 0 in " +
                                     ElasticMaterial::model_name(first->model()) +
                                     ": all bodies of a problem share the model."));
    }
    Body body;
    auto given = std::make_shared<PolygonalMesh<2>>(mesh);
    MeshParameters::shift_boundary_ids(*given, boundary_id_offset,
                                       "ContactProblem::add_body(): body " + std::to_string(b) +
                                         ", boundary id offset " + std::to_string(boundary_id_offset));
    body.given    = given;
    body.material = material.clone();
    body.mesh.material_id = b;
    body.name             = "body " + std::to_string(b);
    bodies.push_back(std::move(body));
    return b;
  }



  std::vector<unsigned int>
  ContactProblem::add_parts(const PolygonalMesh<2>                                                         &mesh,
                            const ConstitutiveLaw<2>                                                       &material,
                            const std::map<dealii::types::material_id, std::shared_ptr<const ConstitutiveLaw<2>>> &part_laws,
                            const unsigned int boundary_id_offset)
  {
    std::vector<unsigned int> added;
    const auto                ids   = mesh.get_material_ids();
    const auto                parts = mesh.split_by_material_id();
    for (unsigned int i = 0; i < parts.size(); ++i)
      {
        const auto         it  = part_laws.find(ids[i]);
        const unsigned int b   = add_body(parts[i], it != part_laws.end() && it->second ? *it->second : material,
                                        boundary_id_offset);
        bodies[b].name = "body " + std::to_string(b) + " (material id " + std::to_string(ids[i]) + ")";
        added.push_back(b);
      }
    return added;
  }



  void
  ContactProblem::set_friction_coefficient(const unsigned int body_a, const unsigned int body_b, const double mu)
  {
    AssertThrow(std::isfinite(mu) && mu >= 0 && mu <= 1e6,
                dealii::ExcMessage("ContactProblem::set_friction_coefficient(" + std::to_string(body_a) + ", " +
                                   std::to_string(body_b) + ", mu): the friction coefficient must be a number "
                                   "from 0 to 1e6."));
    body_friction.insert(body_friction.begin(), std::make_tuple(body_a, body_b, mu));
  }



  void
  ContactProblem::set_material_name(const unsigned int body, const std::string &name)
  {
    AssertThrow(body < bodies.size(),
                dealii::ExcMessage("ContactProblem::set_material_name(" + std::to_string(body) +
                                   ", ...): there is no body " + std::to_string(body) + " (there are " +
                                   std::to_string(bodies.size()) + ")."));
    check_material_name(name, "ContactProblem::set_material_name()");
    bodies[body].material_name = name;
  }



  void
  ContactProblem::set_friction_coefficient(const std::string &material_a,
                                           const std::string &material_b,
                                           const double       mu)
  {
    for (const std::string &name : {material_a, material_b})
      if (name != "*")
        check_material_name(name, "ContactProblem::set_friction_coefficient(\"" + material_a + "\", \"" +
                                    material_b + "\", mu)");
    AssertThrow(std::isfinite(mu) && mu >= 0 && mu <= 1e6,
                dealii::ExcMessage("ContactProblem::set_friction_coefficient(\"" + material_a + "\", \"" +
                                   material_b + "\", mu): the friction coefficient must be a number from 0 to 1e6."));
    material_friction.insert(material_friction.begin(), std::make_tuple(material_a, material_b, mu));
  }



  double
  ContactProblem::friction_between(const unsigned int a, const unsigned int b) const
  {
    const unsigned int any = dealii::numbers::invalid_unsigned_int;
    // a pair of bodies first, then one body and a wildcard, then two
    // wildcards; the latest entry of a kind wins (body_friction is latest
    // first)
    for (const unsigned int wildcards : {0u, 1u, 2u})
      for (const auto &[x, y, mu] : body_friction)
        {
          const unsigned int n_any = (x == any) + (y == any);
          if (n_any != wildcards)
            continue;
          const auto matches = [&](const unsigned int p, const unsigned int q) {
            return (x == any || x == p) && (y == any || y == q);
          };
          if (matches(a, b) || matches(b, a))
            return mu;
        }
    // then the materials, in the same order of precedence
    const std::string &name_a = bodies[a].material_name, &name_b = bodies[b].material_name;
    for (const unsigned int wildcards : {0u, 1u, 2u})
      for (const auto &[x, y, mu] : material_friction)
        {
          const unsigned int n_any = (x == "*") + (y == "*");
          if (n_any != wildcards)
            continue;
          const auto matches = [&](const std::string &p, const std::string &q) {
            return (x == "*" || (!p.empty() && x == p)) && (y == "*" || (!q.empty() && y == q));
          };
          if (matches(name_a, name_b) || matches(name_b, name_a))
            return mu;
        }
    return -1;
  }



  unsigned int
  ContactProblem::add_body(const dealii::Triangulation<2, 2> &tria,
                           const ConstitutiveLaw<2>          &material,
                           const unsigned int                 boundary_id_offset)
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::from_triangulation(mesh, tria);
    mesh.name = "body " + std::to_string(bodies.size());
    return add_body(mesh, material, boundary_id_offset);
  }



  void
  ContactProblem::add_contact_pair(const dealii::types::boundary_id master,
                                   const dealii::types::boundary_id slave,
                                   const double                     friction_coefficient,
                                   const std::string               &name)
  {
    const std::string who = name.empty() ? "ContactProblem::add_contact_pair(" + std::to_string(int(master)) +
                                             ", " + std::to_string(int(slave)) + ")" :
                                           name;
    AssertThrow(master <= InputParsing::max_boundary_id &&
                  slave <= InputParsing::max_boundary_id && master != slave,
                dealii::ExcMessage(who + ": two different boundary ids below 255 expected."));
    AssertThrow(std::isfinite(friction_coefficient) && friction_coefficient <= 1e6,
                dealii::ExcMessage(who + ": the friction coefficient " + std::to_string(friction_coefficient) +
                                   " is not a number from 0 to 1e6 (negative: the default of the contact settings)."));
    for (const auto &other : contact_pairs)
      for (const unsigned int id : {other.first, other.second})
        AssertThrow(id != master && id != slave,
                    dealii::ExcMessage(who + ": boundary id " + std::to_string(id) +
                                       " is already part of the contact pair " + std::to_string(other.first) +
                                       " : " + std::to_string(other.second) +
                                       "; a boundary part can belong to one contact pair only."));
    contact_pairs.emplace_back(master, slave);
    pair_friction.push_back(friction_coefficient < 0 ? -1. : friction_coefficient);
  }



  void
  ContactProblem::clear()
  {
    bodies.clear();
    contact_pairs.clear();
    pair_friction.clear();
    body_friction.clear();
    material_friction.clear();
    opt.detect_pairs = false;
    bc.clear();
    n_cycles = 1;
    prm_directory.clear();
  }



  void
  ContactProblem::check_setup() const
  {
    AssertThrow(!bodies.empty(),
                dealii::ExcMessage("ContactProblem: no body; add one with add_body() or read a parameter file."));
    AssertThrow(opt.degree >= 1 && opt.degree <= VirtualElement<2>::max_degree(),
                dealii::ExcMessage("Parameter 'Discretization/Order' is " + std::to_string(opt.degree) +
                                   ": the order k of the virtual elements must lie in 1 to " +
                                   std::to_string(VirtualElement<2>::max_degree()) + "."));
    InputParsing::check_range(opt.stabilization_factor, 1e-6, 1e6, "Discretization/Stabilization factor");
    const auto &cs = opt.contact;
    InputParsing::check_range(cs.friction_coefficient, 0, 1e6, "Contact/Friction coefficient", false, false,
                              "The Coulomb friction coefficient is a number >= 0.");
    const std::string tangential_name = ContactSettings::tangential_name(cs.tangential);
    if (!cs.is_coulomb())
      {
        std::ostringstream mu;
        mu << cs.friction_coefficient;
        AssertThrow(cs.friction_coefficient == 0,
                    dealii::ExcMessage("Parameter 'Contact/Friction coefficient' is " + mu.str() +
                                       ", but 'Contact/Tangential' is '" +
                                       tangential_name +
                                       "': a friction coefficient needs 'Tangential = coulomb' or "
                                       "'coulomb penalty'."));
        AssertThrow(body_friction.empty(),
                    dealii::ExcMessage("Parameter 'Contact/Friction between bodies' gives friction coefficients, "
                                       "but 'Contact/Tangential' is '" + tangential_name +
                                       "': a friction coefficient needs 'Tangential = coulomb' or "
                                       "'coulomb penalty'."));
        AssertThrow(material_friction.empty(),
                    dealii::ExcMessage("Parameter 'Contact/Friction between materials' gives friction "
                                       "coefficients, but 'Contact/Tangential' is '" + tangential_name +
                                       "': a friction coefficient needs 'Tangential = coulomb' or "
                                       "'coulomb penalty'."));
        for (unsigned int i = 0; i < pair_friction.size(); ++i)
          AssertThrow(pair_friction[i] < 0,
                      dealii::ExcMessage("Parameter 'Contact/Pairs': the entry of interface " + std::to_string(i) +
                                         " gives a friction coefficient, but 'Contact/Tangential' is '" +
                                         tangential_name +
                                         "': a friction coefficient needs 'Tangential = coulomb' or "
                                         "'coulomb penalty'."));
      }
    else
      AssertThrow(cs.normal == ContactSettings::Normal::unilateral,
                  dealii::ExcMessage("Parameter 'Contact/Tangential' is '" + tangential_name +
                                     "' (Coulomb friction) but 'Contact/Normal' is 'tied': friction needs "
                                     "unilateral normal contact, where a pair can open and the pressure "
                                     "bounds the friction force. Use 'Normal = unilateral', or "
                                     "'Tangential = multipliers' for a tied interface that sticks."));
    // the penalty itself is bounded relative to E_min / h_min once the
    // interfaces are known (setup_system()); its factor is dimensionless
    InputParsing::check_range(cs.penalty, 0, std::numeric_limits<double>::max(), "Contact/Penalty", false, false,
                              "0 selects the default rule 'Penalty factor' * E_min / h_min.");
    InputParsing::check_range(cs.penalty_factor, ContactScales::min_penalty_factor,
                              ContactScales::max_penalty_factor, "Contact/Penalty factor", false, false,
                              "The stick penalty is this factor times E_min / h_min: a much smaller one leaves "
                              "the stick direction nearly free, a larger one makes the system too "
                              "ill-conditioned for correct pressures.");
    AssertThrow(cs.max_active_set_iterations >= 1,
                dealii::ExcMessage("Parameter 'Contact/Maximum active set iterations' must be at least 1."));
    InputParsing::check_range(opt.insertion.merge_fraction, 1e-6, 0.49, "Contact/Merge fraction");
    InputParsing::check_range(opt.insertion.search_distance, 0, 1e300, "Contact/Search distance", false, false);
    if (opt.insertion.coordinate_precision != NodeInsertion::Settings::detect_precision)
      InputParsing::check_range(opt.insertion.coordinate_precision, 0, 0.01, "Contact/Coordinate precision", false,
                                true, "Give 'auto' for the precision of the data, or a fraction of the interface size.");
    AssertThrow(bodies.size() == 1 || !contact_pairs.empty() || opt.detect_pairs,
                dealii::ExcMessage("Parameter 'Contact/Pairs' is empty but there are " +
                                   std::to_string(bodies.size()) + " bodies: name at least one contact pair, or "
                                   "'auto' to detect them."));
    for (const auto &[a, b, mu] : body_friction)
      for (const unsigned int body : {a, b})
        AssertThrow(body == dealii::numbers::invalid_unsigned_int || body < bodies.size(),
                    dealii::ExcMessage("ContactProblem::set_friction_coefficient(): there is no body " +
                                       std::to_string(body) + " (there are " + std::to_string(bodies.size()) +
                                       ")."));
    {
      std::set<std::string> names;
      for (const Body &body : bodies)
        names.insert(body.material_name);
      for (const auto &[a, b, mu] : material_friction)
        for (const std::string &name : {a, b})
          AssertThrow(name == "*" || names.count(name) != 0,
                      dealii::ExcMessage("Friction between materials (parameter 'Contact/Friction between "
                                         "materials' or ContactProblem::set_friction_coefficient()): no body has "
                                         "the material '" + name + "' (names come from 'Material/Name', the "
                                         "fourth field of 'Material/Part materials', or set_material_name())."));
    }
    InputParsing::check_range(opt.detection.distance, 0, 10, "Contact/Detection distance");
    InputParsing::check_range(opt.detection.max_angle, 1, 89, "Contact/Detection angle");
    InputParsing::check_number_of_load_steps(opt.n_load_steps);
    InputParsing::check_range(opt.final_time, 0, 1e300, "Load steps/Final time", true, false,
                              "The load steps run from t = 0 to the final time.");
    InputParsing::check_range(opt.solver_tolerance, 0, 1, "Solver/Relative tolerance", true, true);
    AssertThrow(opt.solver_max_iterations >= 1,
                dealii::ExcMessage("Parameter 'Solver/Maximum iterations' must be at least 1."));
    if (opt.solver != "automatic")
      (void)SaddlePointSolver::parse_type(opt.solver);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      AssertThrow(bodies[b].given == nullptr || n_cycles == 1,
                  dealii::ExcMessage("ContactProblem: body " + std::to_string(b) +
                                     " was given as a mesh, which has no refinement cycles; refine it in "
                                     "your program and run once per mesh."));
    check_output_names(opt.output_folder, opt.base_name);
  }



  std::vector<ScaleCheck::Body>
  ContactProblem::scale_check_bodies() const
  {
    // each body by its material id (= its index), its name, the parameter
    // that sets its modulus, and its characteristic stiffness
    std::vector<ScaleCheck::Body> result;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      result.push_back({dealii::types::material_id(b), bodies[b].name,
                        bodies[b].modulus_parameter.empty() ? "Young's modulus of " + bodies[b].name :
                                                              bodies[b].modulus_parameter,
                        bodies[b].material->characteristic_stiffness()});
    return result;
  }
} // namespace dealvem
