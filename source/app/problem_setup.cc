// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/app/problem_setup.h>
#include <dealvem/elasticity/boundary_conditions.h>

namespace dealvem
{
  namespace
  {
    const std::string section = "Boundary conditions and loads";

    dealii::types::boundary_id
    parse_id(const std::string &s, const std::string &parameter)
    {
      const unsigned int id = InputParsing::parse_unsigned(s, parameter);
      AssertThrow(id < dealii::numbers::internal_face_boundary_id,
                  dealii::ExcMessage("Parameter '" + parameter + "': boundary id " + s +
                                     " is out of range (0..254)."));
      return dealii::types::boundary_id(id);
    }

    unsigned int
    parse_component(const std::string &s, const std::string &parameter)
    {
      if (s == "x")
        return 0;
      if (s == "y")
        return 1;
      AssertThrow(false, dealii::ExcMessage("Parameter '" + parameter + "': component '" + s +
                                            "' must be x or y."));
      return 0;
    }
  } // namespace



  void
  BoundaryConditionParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    prm.enter_subsection(section);
    prm.declare_entry("Function constants", "", Anything(),
                      "Constants usable in every expression of this section and of the exact "
                      "solution, as 'name=value, name=value'.");
    prm.declare_entry("Dirichlet", "", Anything(),
                      "Prescribed displacements: 'id : components : expressions; ...' with "
                      "components x, y or xy and one expression per component, e.g. "
                      "'0 : xy : 0, 0; 2 : y : 0'.");
    prm.declare_entry("Roller", "", Anything(),
                      "Boundary ids of straight boundary parts (any inclination) with zero normal "
                      "displacement, comma separated.");
    prm.declare_entry("Traction", "", Anything(),
                      "Tractions 'id : gx, gy; ...' (force per length).");
    prm.declare_entry("Pressure", "", Anything(),
                      "Normal pressures 'id : p; ...'; positive pressure pushes into the body.");
    prm.declare_entry("Point constraints", "", Anything(),
                      "Single-point constraints 'x, y : component : value; ...' on the mesh vertex "
                      "at (x, y), component x or y.");
    prm.declare_entry("Body force", "", Anything(),
                      "Body force 'fx, fy' (force per area); empty for none.");
    prm.leave_subsection();
  }



  void
  BoundaryConditionParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection(section);
    constants = InputParsing::parse_constants(prm.get("Function constants"),
                                              section + "/Function constants");
    dirichlet.clear();
    for (const auto &entry : InputParsing::split(prm.get("Dirichlet"), ';'))
      {
        const std::string name   = section + "/Dirichlet entry '" + entry + "'";
        const auto        fields = InputParsing::split(entry, ':', true);
        AssertThrow(fields.size() == 3,
                    dealii::ExcMessage("Parameter '" + name + "': expected 'id : components : expressions'."));
        Dirichlet d;
        d.id = parse_id(fields[0], name);
        AssertThrow(fields[1] == "x" || fields[1] == "y" || fields[1] == "xy",
                    dealii::ExcMessage("Parameter '" + name + "': components must be x, y or xy, got '" +
                                       fields[1] + "'."));
        d.mask           = {{fields[1].find('x') != std::string::npos,
                             fields[1].find('y') != std::string::npos}};
        const auto exprs = InputParsing::split(fields[2], ',');
        AssertThrow(exprs.size() == (d.mask[0] && d.mask[1] ? 2u : 1u),
                    dealii::ExcMessage("Parameter '" + name + "': expected one expression per component."));
        std::vector<std::string> full = (d.mask[0] && d.mask[1]) ? exprs :
                                        (d.mask[0] ? std::vector<std::string>{exprs[0], "0"} :
                                                     std::vector<std::string>{"0", exprs[0]});
        d.function = std::make_unique<InputParsing::ParsedFunction>(full, constants, name);
        dirichlet.push_back(std::move(d));
      }
    rollers.clear();
    for (const auto &s : InputParsing::split(prm.get("Roller"), ','))
      rollers.push_back(parse_id(s, section + "/Roller"));
    tractions.clear();
    pressures.clear();
    for (const bool is_pressure : {false, true})
      for (const auto &entry : InputParsing::split(prm.get(is_pressure ? "Pressure" : "Traction"), ';'))
        {
          const std::string name =
            section + (is_pressure ? "/Pressure" : "/Traction") + " entry '" + entry + "'";
          const auto fields = InputParsing::split(entry, ':', true);
          AssertThrow(fields.size() == 2,
                      dealii::ExcMessage("Parameter '" + name + "': expected 'id : " +
                                         (is_pressure ? "p" : "gx, gy") + "'."));
          Load l;
          l.id             = parse_id(fields[0], name);
          const auto exprs = InputParsing::split(fields[1], ',');
          AssertThrow(exprs.size() == (is_pressure ? 1u : 2u),
                      dealii::ExcMessage("Parameter '" + name + "': expected " +
                                         (is_pressure ? "one expression." : "two expressions gx, gy.")));
          l.function = std::make_unique<InputParsing::ParsedFunction>(exprs, constants, name);
          (is_pressure ? pressures : tractions).push_back(std::move(l));
        }
    points.clear();
    for (const auto &entry : InputParsing::split(prm.get("Point constraints"), ';'))
      {
        const std::string name   = section + "/Point constraints entry '" + entry + "'";
        const auto        fields = InputParsing::split(entry, ':', true);
        AssertThrow(fields.size() == 3,
                    dealii::ExcMessage("Parameter '" + name + "': expected 'x, y : component : value'."));
        const auto xy = InputParsing::split(fields[0], ',');
        AssertThrow(xy.size() == 2, dealii::ExcMessage("Parameter '" + name + "': expected a point 'x, y'."));
        PointConstraint pc;
        pc.point     = dealii::Point<2>(InputParsing::parse_double(xy[0], name),
                                    InputParsing::parse_double(xy[1], name));
        pc.component = parse_component(fields[1], name);
        pc.value     = InputParsing::parse_double(fields[2], name);
        points.push_back(pc);
      }
    body_force.reset();
    const std::string bf = prm.get("Body force");
    if (!InputParsing::trim(bf).empty())
      {
        const auto exprs = InputParsing::split(bf, ',');
        AssertThrow(exprs.size() == 2,
                    dealii::ExcMessage("Parameter '" + section + "/Body force': expected 'fx, fy'."));
        body_force = std::make_unique<InputParsing::ParsedFunction>(exprs, constants, section + "/Body force");
      }
    prm.leave_subsection();
  }



  void
  BoundaryConditionParameters::apply_constraints(const VEMDoFHandler<2>            &dof_handler,
                                                 dealii::AffineConstraints<double> &constraints) const
  {
    for (const auto &d : dirichlet)
      BoundaryConditions::interpolate_boundary_values(dof_handler, {d.id}, *d.function, d.mask,
                                                      constraints);
    for (const auto id : rollers)
      BoundaryConditions::add_roller(dof_handler, id, constraints);
    for (const auto &p : points)
      BoundaryConditions::add_point_constraint(dof_handler, p.point, p.component, p.value,
                                               constraints);
  }



  void
  BoundaryConditionParameters::add_loads(ElasticityAssembler<2> &assembler) const
  {
    if (body_force)
      assembler.set_body_force(*body_force);
    for (const auto &t : tractions)
      assembler.add_traction(t.id, *t.function);
    for (const auto &p : pressures)
      assembler.add_pressure(p.id, *p.function);
  }



  std::set<dealii::types::boundary_id>
  BoundaryConditionParameters::used_boundary_ids() const
  {
    std::set<dealii::types::boundary_id> ids(rollers.begin(), rollers.end());
    for (const auto &d : dirichlet)
      ids.insert(d.id);
    for (const auto &t : tractions)
      ids.insert(t.id);
    for (const auto &p : pressures)
      ids.insert(p.id);
    return ids;
  }
} // namespace dealvem
