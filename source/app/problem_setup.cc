// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/app/problem_setup.h>
#include <dealvem/elasticity/boundary_conditions.h>

#include <algorithm>
#include <sstream>

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
                      "solution, as 'name=value, name=value'. Expressions are muparser expressions "
                      "in x, y and the time t; t = 1 unless the contact problem has load steps (section 'Load steps': t runs over the steps).");
    prm.declare_entry("Dirichlet", "", Anything(),
                      "Prescribed displacements: 'id : components : expressions; ...' with "
                      "components x, y or xy and one expression per component (in x, y, t; t = 1, or the time of the load step), "
                      "e.g. '0 : xy : 0, 0; 2 : y : 0'.");
    prm.declare_entry("Roller", "", Anything(),
                      "Boundary ids of straight boundary parts (any inclination) with zero normal "
                      "displacement, comma separated.");
    prm.declare_entry("Traction", "", Anything(),
                      "Tractions 'id : gx, gy; ...' (force per length; expressions in x, y, t; t = 1, or the time of the load step).");
    prm.declare_entry("Pressure", "", Anything(),
                      "Normal pressures 'id : p; ...'; positive pressure pushes into the body "
                      "(expressions in x, y, t; t = 1, or the time of the load step).");
    prm.declare_entry("Point constraints", "", Anything(),
                      "Single-point constraints 'x, y : component : value; ...' on the mesh vertex "
                      "at (x, y), component x or y; the value is an expression evaluated at (x, y), "
                      "t = 1 (or the time of the load step). Where vertices of two bodies lie at (x, y), name the body (its "
                      "material id) in a fourth field: 'x, y : component : value : body'. A point "
                      "constraint on a displacement that a Dirichlet or roller condition fixes "
                      "already must agree with it.");
    prm.declare_entry("Rigid boundary", "", Anything(),
                      "Rigid boundary parts 'id : Fx, Fy : M; ...' (': M' optional, default 0): "
                      "all nodes on the boundary edges with this id move as one rigid body, "
                      "loaded by the force (Fx, Fy) at the arc-length centroid of the part and the "
                      "moment M (counter-clockwise) about it. Expressions with the function "
                      "constants, evaluated at the centroid, t = 1 (or the time of the load step). A rigid part does not hold its "
                      "body (add Dirichlet data elsewhere) and may share constrained nodes with "
                      "other conditions only at its two reference nodes.");
    prm.declare_entry("Body force", "", Anything(),
                      "Body force 'fx, fy' (force per area; expressions in x, y, t; t = 1, or the time of the load step); empty "
                      "for none.");
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
        d.name = name;
        d.id   = parse_id(fields[0], name);
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
      {
        const std::string name = section + "/Roller entry '" + s + "'";
        rollers.push_back({name, parse_id(s, name)});
      }
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
          l.name           = name;
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
        AssertThrow(fields.size() == 3 || fields.size() == 4,
                    dealii::ExcMessage("Parameter '" + name +
                                       "': expected 'x, y : component : value' or "
                                       "'x, y : component : value : body'."));
        const auto xy = InputParsing::split(fields[0], ',');
        AssertThrow(xy.size() == 2, dealii::ExcMessage("Parameter '" + name + "': expected a point 'x, y'."));
        PointConstraint pc;
        pc.name      = name;
        pc.point     = dealii::Point<2>(InputParsing::parse_double(xy[0], name),
                                    InputParsing::parse_double(xy[1], name));
        pc.component = parse_component(fields[1], name);
        pc.value     = std::make_unique<InputParsing::ParsedFunction>(std::vector<std::string>{fields[2]},
                                                                  constants, name);
        pc.body      = dealii::numbers::invalid_material_id;
        if (fields.size() == 4)
          {
            const unsigned int body = InputParsing::parse_unsigned(fields[3], name + " (body)");
            AssertThrow(body < dealii::numbers::invalid_material_id,
                        dealii::ExcMessage("Parameter '" + name + "': body " + fields[3] +
                                           " is out of range (0..254)."));
            pc.body = dealii::types::material_id(body);
          }
        points.push_back(std::move(pc));
      }
    rigid_boundaries.clear();
    for (const auto &entry : InputParsing::split(prm.get("Rigid boundary"), ';'))
      {
        const std::string name   = section + "/Rigid boundary entry '" + entry + "'";
        const auto        fields = InputParsing::split(entry, ':', true);
        AssertThrow(fields.size() == 2 || fields.size() == 3,
                    dealii::ExcMessage("Parameter '" + name + "': expected 'id : Fx, Fy' or 'id : Fx, Fy : M'."));
        RigidBoundary r;
        r.name           = name;
        r.id             = parse_id(fields[0], name);
        const auto exprs = InputParsing::split(fields[1], ',');
        AssertThrow(exprs.size() == 2,
                    dealii::ExcMessage("Parameter '" + name + "': expected two expressions Fx, Fy."));
        r.force = std::make_unique<InputParsing::ParsedFunction>(exprs, constants, name);
        AssertThrow(fields.size() == 2 || !fields[2].empty(),
                    dealii::ExcMessage("Parameter '" + name + "': the moment after the second ':' is empty."));
        r.moment = std::make_unique<InputParsing::ParsedFunction>(
          std::vector<std::string>{fields.size() == 3 ? fields[2] : std::string("0")}, constants, name);
        for (const auto &other : rigid_boundaries)
          AssertThrow(other.id != r.id,
                      dealii::ExcMessage("Parameter '" + name + "': boundary id " + fields[0] +
                                         " is rigid already (entry '" + other.name + "')."));
        rigid_boundaries.push_back(std::move(r));
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
  BoundaryConditionParameters::check_boundary_ids(const PolygonalMesh<2> &mesh) const
  {
    const auto  ids = mesh.get_boundary_ids();
    std::string have;
    for (const auto id : ids)
      have += (have.empty() ? "" : ", ") + std::to_string(int(id));
    auto check = [&](const dealii::types::boundary_id id, const std::string &name) {
      AssertThrow(std::find(ids.begin(), ids.end(), id) != ids.end(),
                  dealii::ExcMessage("Parameter '" + name + "': no boundary edge of mesh '" + mesh.name +
                                     "' has boundary id " + std::to_string(int(id)) +
                                     "; the boundary ids of the mesh are " +
                                     (have.empty() ? std::string("(none)") : have) + "."));
    };
    for (const auto &d : dirichlet)
      check(d.id, d.name);
    for (const auto &r : rollers)
      check(r.id, r.name);
    for (const auto &t : tractions)
      check(t.id, t.name);
    for (const auto &p : pressures)
      check(p.id, p.name);
    for (const auto &r : rigid_boundaries)
      check(r.id, r.name);
  }



  void
  BoundaryConditionParameters::apply_constraints(const VEMDoFHandler<2>            &dof_handler,
                                                 dealii::AffineConstraints<double> &constraints) const
  {
    check_boundary_ids(dof_handler.get_mesh());
    // who wrote each line, for the messages of later, colliding entries
    BoundaryConditions::ConstraintOrigins origins;
    auto record = [&](const std::string &name) {
      for (const auto &line : constraints.get_lines())
        origins.emplace(line.index, name); // keeps the first writer
    };
    record("a constraint set before the boundary conditions");
    for (const auto &d : dirichlet)
      {
        BoundaryConditions::interpolate_boundary_values(dof_handler, {d.id}, *d.function, d.mask,
                                                        constraints);
        record(d.name);
      }
    for (const auto &r : rollers)
      {
        BoundaryConditions::add_roller(dof_handler, r.id, constraints);
        record(r.name);
      }
    for (const auto &p : points)
      {
        BoundaryConditions::add_point_constraint(dof_handler, p.point, p.component,
                                                 p.value->value(p.point), constraints, 1e-6, p.body,
                                                 p.name, &origins);
        record(p.name);
      }
    for (const auto &r : rigid_boundaries)
      {
        BoundaryConditions::add_rigid_boundary(dof_handler, r.id, constraints, r.name, &origins);
        record(r.name);
      }
    // prescribed displacements far beyond the size of the mesh leave the
    // small-displacement model and make the solvers fail for reasons that
    // would not name the value (overflowing residuals, cycling active sets)
    const auto &mesh = dof_handler.get_mesh();
    if (mesh.n_vertices() > 0)
      {
        const double size = mesh.extent();
        for (const auto &line : constraints.get_lines())
          if (!(std::abs(line.inhomogeneity) <= max_displacement_ratio * size))
            {
              const auto        origin = origins.find(line.index);
              std::ostringstream msg;
              msg << "Parameter '" << (origin != origins.end() ? origin->second : std::string("?"))
                  << "': the prescribed displacement of DoF " << line.index << " is " << line.inhomogeneity
                  << ", more than " << max_displacement_ratio << " times the size of the mesh '" << mesh.name
                  << "' (" << size
                  << "). The small-displacement model does not hold there, and the solution would overflow; "
                     "check the value and its units.";
              AssertThrow(false, dealii::ExcMessage(msg.str()));
            }
      }
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
    for (const auto &r : rigid_boundaries)
      {
        const auto part =
          BoundaryConditions::rigid_boundary_geometry(assembler.get_dof_handler(), r.id);
        dealii::Tensor<1, 2> force;
        for (unsigned int c = 0; c < 2; ++c)
          force[c] = r.force->value(part.centroid, c);
        const double moment = r.moment->value(part.centroid);
        for (const auto &l : BoundaryConditions::rigid_boundary_load(part, force, moment))
          assembler.add_nodal_load(l.first, l.second);
      }
  }



  void
  BoundaryConditionParameters::set_time(const double t)
  {
    for (auto &d : dirichlet)
      d.function->set_time(t);
    for (auto *loads : {&tractions, &pressures})
      for (auto &l : *loads)
        l.function->set_time(t);
    for (auto &pc : points)
      pc.value->set_time(t);
    for (auto &r : rigid_boundaries)
      {
        r.force->set_time(t);
        r.moment->set_time(t);
      }
    if (body_force)
      body_force->set_time(t);
  }



  std::vector<std::string>
  BoundaryConditionParameters::time_dependent_entries() const
  {
    std::vector<std::string> names;
    const auto check = [&names](const InputParsing::ParsedFunction *f) {
      if (f != nullptr)
        for (const auto &e : f->get_expressions())
          if (InputParsing::uses_variable(e, "t"))
            {
              names.push_back(f->get_parameter());
              return;
            }
    };
    for (const auto &d : dirichlet)
      check(d.function.get());
    for (const auto *loads : {&tractions, &pressures})
      for (const auto &l : *loads)
        check(l.function.get());
    for (const auto &pc : points)
      check(pc.value.get());
    for (const auto &r : rigid_boundaries)
      {
        check(r.force.get());
        check(r.moment.get());
      }
    check(body_force.get());
    return names;
  }



  std::set<dealii::types::boundary_id>
  BoundaryConditionParameters::used_boundary_ids() const
  {
    std::set<dealii::types::boundary_id> ids;
    for (const auto &r : rollers)
      ids.insert(r.id);
    for (const auto &d : dirichlet)
      ids.insert(d.id);
    for (const auto &t : tractions)
      ids.insert(t.id);
    for (const auto &p : pressures)
      ids.insert(p.id);
    for (const auto &r : rigid_boundaries)
      ids.insert(r.id);
    return ids;
  }
} // namespace dealvem
