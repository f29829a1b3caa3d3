// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/app/problem_setup.h>
#include <dealvem/base/output_file.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/law_factory.h>

#include <deal.II/base/function.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace dealvem
{
  namespace
  {
    const std::string section = "Boundary conditions and loads";

    // a boundary id, as a number or a physical name of the mesh file(s)
    dealii::types::boundary_id
    parse_id(const std::string &s, const std::string &parameter, const MeshIO::PhysicalNames &names)
    {
      const unsigned int id =
        InputParsing::parse_id_or_name(s, parameter, names.boundary_ids, "boundary id", names.list());
      AssertThrow(id <= InputParsing::max_boundary_id,
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

    // A function given in code, with the checks a parsed expression has:
    // every value it returns must be finite, or the error names the
    // condition, the point and the time. set_time() reaches the function.
    class CheckedFunction : public dealii::Function<2>
    {
    public:
      CheckedFunction(const std::shared_ptr<dealii::Function<2>> &function, const std::string &name)
        : dealii::Function<2>(function->n_components, function->get_time())
        , function(function)
        , name(name)
      {}

      double
      value(const dealii::Point<2> &p, const unsigned int component = 0) const override
      {
        const double v = function->value(p, component);
        if (!std::isfinite(v))
          report(p, component, v);
        return v;
      }

      void
      vector_value(const dealii::Point<2> &p, dealii::Vector<double> &values) const override
      {
        function->vector_value(p, values);
        for (unsigned int c = 0; c < values.size(); ++c)
          if (!std::isfinite(values[c]))
            report(p, c, values[c]);
      }

      void
      set_time(const double t) override
      {
        dealii::Function<2>::set_time(t);
        function->set_time(t);
      }

    private:
      [[noreturn]] void
      report(const dealii::Point<2> &p, const unsigned int component, const double v) const
      {
        std::ostringstream msg;
        msg << name << ": the function returns " << v << " for component " << component << " at (" << p[0]
            << ", " << p[1] << "), t = " << get_time() << "; every value must be finite.";
        AssertThrow(false, dealii::ExcMessage(msg.str()));
        std::abort();
      }

      std::shared_ptr<dealii::Function<2>> function;
      std::string                          name;
    };

    // A parsed expression checks itself; anything else gets the wrapper.
    std::shared_ptr<dealii::Function<2>>
    checked(const std::shared_ptr<dealii::Function<2>> &f,
            const unsigned int                          n_components,
            const std::string                          &name)
    {
      AssertThrow(f != nullptr, dealii::ExcMessage(name + ": the function is a null pointer."));
      AssertThrow(f->n_components == n_components,
                  dealii::ExcMessage(name + ": the function has " + std::to_string(f->n_components) +
                                     " component(s), " + std::to_string(n_components) + " expected."));
      if (dynamic_cast<const InputParsing::ParsedFunction *>(f.get()) != nullptr)
        return f;
      return std::make_shared<CheckedFunction>(f, name);
    }

    void
    check_id(const dealii::types::boundary_id id, const std::string &name)
    {
      AssertThrow(id <= InputParsing::max_boundary_id,
                  dealii::ExcMessage(name + ": boundary id " + std::to_string(int(id)) +
                                     " is out of range (0..254)."));
    }

    std::string
    default_name(const std::string &given, const std::string &what, const dealii::types::boundary_id id)
    {
      return given.empty() ? what + " on boundary id " + std::to_string(int(id)) : given;
    }
  } // namespace



  void
  BoundaryConditionParameters::clear()
  {
    constants.clear();
    dirichlet.clear();
    rollers.clear();
    tractions.clear();
    pressures.clear();
    points.clear();
    rigid_boundaries.clear();
    rotations.clear();
    body_force.reset();
    body_force_name.clear();
  }



  void
  BoundaryConditionParameters::add_dirichlet(const dealii::types::boundary_id            id,
                                             const std::array<bool, 2>                   &mask,
                                             const std::shared_ptr<dealii::Function<2>> &displacement,
                                             const std::string                           &name)
  {
    Dirichlet d;
    d.name = default_name(name, "Dirichlet condition", id);
    check_id(id, d.name);
    AssertThrow(mask[0] || mask[1], dealii::ExcMessage(d.name + ": the component mask selects no component."));
    d.id       = id;
    d.mask     = mask;
    d.function = checked(displacement, 2, d.name);
    dirichlet.push_back(std::move(d));
  }



  void
  BoundaryConditionParameters::add_roller(const dealii::types::boundary_id id, const std::string &name)
  {
    const std::string n = default_name(name, "Roller condition", id);
    check_id(id, n);
    rollers.push_back({n, id});
  }



  void
  BoundaryConditionParameters::add_traction(const dealii::types::boundary_id            id,
                                            const std::shared_ptr<dealii::Function<2>> &traction,
                                            const std::string                           &name)
  {
    Load l;
    l.name = default_name(name, "Traction", id);
    check_id(id, l.name);
    l.id       = id;
    l.function = checked(traction, 2, l.name);
    tractions.push_back(std::move(l));
  }



  void
  BoundaryConditionParameters::add_pressure(const dealii::types::boundary_id            id,
                                            const std::shared_ptr<dealii::Function<2>> &pressure,
                                            const std::string                           &name)
  {
    Load l;
    l.name = default_name(name, "Pressure", id);
    check_id(id, l.name);
    l.id       = id;
    l.function = checked(pressure, 1, l.name);
    pressures.push_back(std::move(l));
  }



  void
  BoundaryConditionParameters::add_point_constraint(const dealii::Point<2>                      &point,
                                                    const unsigned int                           component,
                                                    const std::shared_ptr<dealii::Function<2>> &value,
                                                    const dealii::types::material_id             body,
                                                    const std::string                           &name)
  {
    PointConstraint pc;
    {
      std::ostringstream n;
      n << "Point constraint at (" << point[0] << ", " << point[1] << ")";
      pc.name = name.empty() ? n.str() : name;
    }
    AssertThrow(component < 2,
                dealii::ExcMessage(pc.name + ": component " + std::to_string(component) + " must be 0 (x) or 1 (y)."));
    AssertThrow(std::isfinite(point[0]) && std::isfinite(point[1]),
                dealii::ExcMessage(pc.name + ": the point is not finite."));
    pc.point     = point;
    pc.component = component;
    pc.value     = checked(value, 1, pc.name);
    pc.body      = body;
    points.push_back(std::move(pc));
  }



  void
  BoundaryConditionParameters::add_rigid_boundary(const dealii::types::boundary_id            id,
                                                  const std::shared_ptr<dealii::Function<2>> &force,
                                                  const std::shared_ptr<dealii::Function<2>> &moment,
                                                  const std::string                           &name)
  {
    RigidBoundary r;
    r.name = default_name(name, "Rigid boundary", id);
    check_id(id, r.name);
    for (const auto &other : rigid_boundaries)
      AssertThrow(other.id != id, dealii::ExcMessage(r.name + ": boundary id " + std::to_string(int(id)) +
                                                     " is rigid already ('" + other.name + "')."));
    r.id     = id;
    r.force  = checked(force, 2, r.name);
    r.moment = moment ? checked(moment, 1, r.name) : std::make_shared<dealii::Functions::ZeroFunction<2>>(1);
    rigid_boundaries.push_back(std::move(r));
  }



  void
  BoundaryConditionParameters::add_rotation_about_centre(const dealii::types::boundary_id            id,
                                                         const dealii::Point<2>                     &centre,
                                                         const std::shared_ptr<dealii::Function<2>> &value,
                                                         const bool                                  torque_driven,
                                                         const std::string                          &name)
  {
    Rotation r;
    r.name = default_name(name, torque_driven ? "Torque" : "Rotation", id);
    check_id(id, r.name);
    AssertThrow(std::isfinite(centre[0]) && std::isfinite(centre[1]),
                dealii::ExcMessage(r.name + ": the centre of the rotation is not finite."));
    for (const auto &other : rotations)
      AssertThrow(other.id != id, dealii::ExcMessage(r.name + ": boundary id " + std::to_string(int(id)) +
                                                     " is turned about a centre already ('" + other.name + "')."));
    for (const auto &other : rigid_boundaries)
      AssertThrow(other.id != id, dealii::ExcMessage(r.name + ": boundary id " + std::to_string(int(id)) +
                                                     " is a rigid boundary already ('" + other.name + "')."));
    r.id            = id;
    r.centre        = centre;
    r.value         = checked(value, 1, r.name);
    r.torque_driven = torque_driven;
    rotations.push_back(std::move(r));
  }



  void
  BoundaryConditionParameters::set_body_force(const std::shared_ptr<dealii::Function<2>> &force,
                                              const std::string                           &name)
  {
    body_force_name = name.empty() ? std::string("Body force") : name;
    body_force      = force ? checked(force, 2, body_force_name) : nullptr;
  }



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
                      "(expressions in x, y, t; t = 1, or the time of the load step). At finite strain "
                      "'Finite strain/Pressure load' says whether p follows the deformed boundary "
                      "(follower, the default; x, y are then the reference coordinates of the point) or "
                      "is the dead nominal traction -p N.");
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
    declare_rotation_entry(prm);
    prm.declare_entry("Body force", "", Anything(),
                      "Body force 'fx, fy' (force per area; expressions in x, y, t; t = 1, or the time of the load step); empty "
                      "for none.");
    prm.leave_subsection();
  }



  void
  BoundaryConditionParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection(section);
    clear();
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
        d.id   = parse_id(fields[0], name, physical_names);
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
        add_dirichlet(d.id, d.mask, std::make_shared<InputParsing::ParsedFunction>(full, constants, name), name);
      }
    for (const auto &s : InputParsing::split(prm.get("Roller"), ','))
      {
        const std::string name = section + "/Roller entry '" + s + "'";
        add_roller(parse_id(s, name, physical_names), name);
      }
    for (const bool is_pressure : {false, true})
      for (const auto &entry : InputParsing::split(prm.get(is_pressure ? "Pressure" : "Traction"), ';'))
        {
          const std::string name =
            section + (is_pressure ? "/Pressure" : "/Traction") + " entry '" + entry + "'";
          const auto fields = InputParsing::split(entry, ':', true);
          AssertThrow(fields.size() == 2,
                      dealii::ExcMessage("Parameter '" + name + "': expected 'id : " +
                                         (is_pressure ? "p" : "gx, gy") + "'."));
          const auto id    = parse_id(fields[0], name, physical_names);
          const auto exprs = InputParsing::split(fields[1], ',');
          AssertThrow(exprs.size() == (is_pressure ? 1u : 2u),
                      dealii::ExcMessage("Parameter '" + name + "': expected " +
                                         (is_pressure ? "one expression." : "two expressions gx, gy.")));
          const auto f = std::make_shared<InputParsing::ParsedFunction>(exprs, constants, name);
          if (is_pressure)
            add_pressure(id, f, name);
          else
            add_traction(id, f, name);
        }
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
        const dealii::Point<2> point(InputParsing::parse_double(xy[0], name),
                                     InputParsing::parse_double(xy[1], name));
        const unsigned int     component = parse_component(fields[1], name);
        const auto             value =
          std::make_shared<InputParsing::ParsedFunction>(std::vector<std::string>{fields[2]}, constants, name);
        dealii::types::material_id body = dealii::numbers::invalid_material_id;
        if (fields.size() == 4)
          {
            const unsigned int b = InputParsing::parse_id_or_name(fields[3], name + " (body)",
                                                                  physical_names.material_ids, "material id",
                                                                  physical_names.list());
            AssertThrow(b < dealii::numbers::invalid_material_id,
                        dealii::ExcMessage("Parameter '" + name + "': body " + fields[3] +
                                           " is out of range (0..254)."));
            body = dealii::types::material_id(b);
          }
        add_point_constraint(point, component, value, body, name);
      }
    for (const auto &entry : InputParsing::split(prm.get("Rigid boundary"), ';'))
      {
        const std::string name   = section + "/Rigid boundary entry '" + entry + "'";
        const auto        fields = InputParsing::split(entry, ':', true);
        AssertThrow(fields.size() == 2 || fields.size() == 3,
                    dealii::ExcMessage("Parameter '" + name + "': expected 'id : Fx, Fy' or 'id : Fx, Fy : M'."));
        const auto id    = parse_id(fields[0], name, physical_names);
        const auto exprs = InputParsing::split(fields[1], ',');
        AssertThrow(exprs.size() == 2,
                    dealii::ExcMessage("Parameter '" + name + "': expected two expressions Fx, Fy."));
        const auto force = std::make_shared<InputParsing::ParsedFunction>(exprs, constants, name);
        AssertThrow(fields.size() == 2 || !fields[2].empty(),
                    dealii::ExcMessage("Parameter '" + name + "': the moment after the second ':' is empty."));
        const auto moment = std::make_shared<InputParsing::ParsedFunction>(
          std::vector<std::string>{fields.size() == 3 ? fields[2] : std::string("0")}, constants, name);
        for (const auto &other : rigid_boundaries)
          AssertThrow(other.id != id,
                      dealii::ExcMessage("Parameter '" + name + "': boundary id " + fields[0] +
                                         " is rigid already (entry '" + other.name + "')."));
        add_rigid_boundary(id, force, moment, name);
      }
    parse_rotation_entries(prm.get("Rotation about centre"));
    const std::string bf = prm.get("Body force");
    if (!InputParsing::trim(bf).empty())
      {
        const auto exprs = InputParsing::split(bf, ',');
        AssertThrow(exprs.size() == 2,
                    dealii::ExcMessage("Parameter '" + section + "/Body force': expected 'fx, fy'."));
        set_body_force(std::make_shared<InputParsing::ParsedFunction>(exprs, constants, section + "/Body force"),
                       section + "/Body force");
      }
    prm.leave_subsection();
  }



  void
  BoundaryConditionParameters::check_boundary_ids(const PolygonalMesh<2> &mesh) const
  {
    const auto  ids = mesh.get_boundary_ids();
    // the ids of the mesh, each with its physical names
    const auto named = [&](const dealii::types::boundary_id id) {
      std::string s = std::to_string(int(id));
      for (const auto &[n, i] : physical_names.boundary_ids)
        if (i == id)
          s += " ('" + n + "')";
      return s;
    };
    std::string have;
    for (const auto id : ids)
      have += (have.empty() ? "" : ", ") + named(id);
    auto check = [&](const dealii::types::boundary_id id, const std::string &name) {
      AssertThrow(std::find(ids.begin(), ids.end(), id) != ids.end(),
                  dealii::ExcMessage("Parameter '" + name + "': no boundary edge of mesh '" + mesh.name +
                                     "' has boundary id " + named(id) + "; the boundary ids of the mesh are " +
                                     (have.empty() ? std::string("(none)") : have) +
                                     ". Name one of these ids (or its physical name) in the entry, or give the "
                                     "edges the id in the mesh (for a gmsh file: a physical curve with this "
                                     "tag; for the generated rectangles: 0 left, 1 right, 2 bottom, 3 top, plus "
                                     "'Mesh/Boundary id offset')."));
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
    for (const auto &r : rotations)
      check(r.id, r.name);
  }



  void
  BoundaryConditionParameters::apply_constraints(const VEMDoFHandler<2>                                  &dof_handler,
                                                 dealii::AffineConstraints<double>                       &constraints,
                                                 std::vector<SupportReactions::Support>                  *supports,
                                                 std::vector<BoundaryConditions::RotationAboutCentre<2>> *parts) const
  {
    check_boundary_ids(dof_handler.get_mesh());
    // who wrote each line, for the messages of later, colliding entries
    BoundaryConditions::ConstraintOrigins origins;
    // the supports (reported if supports is not null): one per boundary id
    // with Dirichlet data or a roller, one per point constraint
    std::map<dealii::types::boundary_id, unsigned int> support_of_id;
    if (supports != nullptr)
      supports->clear();
    const auto support_index = [&](const std::string &name, const std::string &key,
                                   const dealii::types::boundary_id id) {
      if (id != dealii::numbers::invalid_boundary_id && support_of_id.count(id) > 0)
        return support_of_id[id];
      supports->push_back({name, key, id, {}});
      if (id != dealii::numbers::invalid_boundary_id)
        support_of_id[id] = supports->size() - 1;
      return static_cast<unsigned int>(supports->size() - 1);
    };
    // the lines not recorded yet go to @p name, and to the support with
    // index @p support (none: invalid_unsigned_int)
    const unsigned int none   = dealii::numbers::invalid_unsigned_int;
    auto               record = [&](const std::string &name, const unsigned int support) {
      for (const auto &line : constraints.get_lines())
        if (origins.emplace(line.index, name).second && support != none) // keeps the first writer
          (*supports)[support].lines.push_back(line.index);
    };
    record("a constraint set before the boundary conditions", none);
    for (const auto &d : dirichlet)
      {
        BoundaryConditions::interpolate_boundary_values(dof_handler, {d.id}, *d.function, d.mask,
                                                        constraints);
        record(d.name, supports != nullptr ? support_index("boundary " + std::to_string(int(d.id)),
                                                                "boundary_" + std::to_string(int(d.id)), d.id) : none);
      }
    for (const auto &r : rollers)
      {
        BoundaryConditions::add_roller(dof_handler, r.id, constraints);
        record(r.name, supports != nullptr ? support_index("boundary " + std::to_string(int(r.id)),
                                                                "boundary_" + std::to_string(int(r.id)), r.id) : none);
      }
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const auto &p = points[k];
        BoundaryConditions::add_point_constraint(dof_handler, p.point, p.component,
                                                 p.value->value(p.point), constraints, 1e-6, p.body,
                                                 p.name, &origins);
        std::ostringstream name;
        name << "point " << k << " (" << p.point[0] << ", " << p.point[1] << ")";
        record(p.name, supports != nullptr ? support_index(name.str(), "point_" + std::to_string(k),
                                                                dealii::numbers::invalid_boundary_id) : none);
      }
    for (const auto &r : rigid_boundaries)
      {
        BoundaryConditions::add_rigid_boundary(dof_handler, r.id, constraints, r.name, &origins);
        record(r.name, none); // passes the load on within the body: no support
      }
    if (parts != nullptr)
      parts->clear();
    for (const auto &r : rotations)
      {
        BoundaryConditions::RotationAboutCentre<2> part;
        if (r.torque_driven)
          {
            part = BoundaryConditions::add_torque_rotation(dof_handler, r.id, r.centre, constraints, r.name, &origins);
            record(r.name, none); // the lines turn the part; the torque is a load
          }
        else
          {
            part = BoundaryConditions::add_prescribed_rotation(dof_handler, r.id, r.centre,
                                                               angle_factor * r.value->value(r.centre), constraints,
                                                               r.name, &origins);
            record(r.name, supports != nullptr ? support_index("boundary " + std::to_string(int(r.id)),
                                                               "boundary_" + std::to_string(int(r.id)), r.id)
                                               : none);
          }
        if (parts != nullptr)
          parts->push_back(std::move(part));
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
    for (const auto &r : rotations)
      if (r.torque_driven)
        {
          auto part = BoundaryConditions::rotation_geometry(assembler.get_dof_handler(), r.id, r.centre, r.name);
          part.torque_driven = true; // (the master DoF of add_torque_rotation())
          for (const auto &l : BoundaryConditions::rotation_torque_load(part, r.value->value(r.centre)))
            assembler.add_nodal_load(l.first, l.second);
        }
  }



  void
  BoundaryConditionParameters::add_finite_strain_loads(FiniteStrainAssembler<2> &assembler,
                                                       const std::string        &switch_name,
                                                       const PressureLoad        pressure_load) const
  {
    for (const auto &r : rigid_boundaries)
      AssertThrow(false, dealii::ExcMessage(
                           "Parameter '" + r.name + "': a rigid boundary part is a small-displacement "
                           "condition (its constraints and resultant do not follow a finite rotation), and '" +
                           switch_name + "' is true. Use Dirichlet conditions or tractions, or solve at small "
                           "strain."));
    for (const auto &r : rotations)
      AssertThrow(!r.torque_driven,
                  dealii::ExcMessage("Parameter '" + r.name +
                                     "': a torque about a centre (the angle an unknown) "
                                     "is a small-strain condition (its constraints u = theta perp(x - c) do not "
                                     "follow a finite rotation), and '" +
                                     switch_name +
                                     "' is true. Prescribe the angle instead ('angle a'), or solve at small "
                                     "strain."));
    if (body_force)
      assembler.set_body_force(*body_force);
    for (const auto &t : tractions)
      assembler.add_traction(t.id, *t.function);
    for (const auto &p : pressures)
      assembler.add_pressure(p.id, *p.function, pressure_load);
  }



  bool
  BoundaryConditionParameters::uses_time() const
  {
    return !time_dependent_entries().empty();
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
    for (auto &r : rotations)
      r.value->set_time(t);
    if (body_force)
      body_force->set_time(t);
  }



  std::vector<std::string>
  BoundaryConditionParameters::time_dependent_entries() const
  {
    std::vector<std::string> names;
    const auto check = [&names](const dealii::Function<2> *function) {
      // functions given in code are not parsed: the time they use is unknown
      const auto *f = dynamic_cast<const InputParsing::ParsedFunction *>(function);
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
    for (const auto &r : rotations)
      check(r.value.get());
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
    for (const auto &r : rotations)
      ids.insert(r.id);
    return ids;
  }



  namespace MaterialLaws
  {
    std::string
    law_documentation()
    {
      return "Constitutive law: " + LawFactory::documentation() +
             ", each with this section's Young's modulus and "
             "Poisson's ratio (mu = E/(2(1+nu)), lambda = E nu/((1+nu)(1-2nu))). The hyperelastic laws need "
             "'Model = plane strain'. Their finite-strain response is used with 'Finite strain/Enabled = true' "
             "(one body); at small strain (the default, and always in contact problems, where this entry applies "
             "to every body) the program solves linear elasticity with the law's linearization at F = I, which "
             "is the linear law of the same E and nu.";
    }



    Law
    parse(const std::string &value, const std::string &parameter)
    {
      return LawFactory::find(value, parameter).name;
    }



    bool
    is_hyperelastic(const Law &law)
    {
      return LawFactory::find(law, "Material/Law").hyperelastic;
    }



    std::shared_ptr<const ConstitutiveLaw<2>>
    make_law(const Law &law, const double E, const double nu, const ElasticMaterial::Model model)
    {
      return LawFactory::create(law, "Material/Law", E, nu, model);
    }
  } // namespace MaterialLaws



  void
  FiniteStrainParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    prm.enter_subsection("Finite strain");
    prm.declare_entry("Enabled", "false", Bool(),
                      "One body: solve at finite strain (total Lagrangian hyperelasticity, Newton's method "
                      "with the load steps of 'Load steps': step n of N solves at the time t = n * 'Final "
                      "time' / N of the expressions; where no load or Dirichlet expression uses t, step n "
                      "applies n/N of the loads and of the Dirichlet values) with the hyperelastic "
                      "'Material/Law' (not 'linear', which has no finite-strain response). Body force per "
                      "unit reference area, 'Traction' per unit reference length (nominal, dead); "
                      "'Pressure' as 'Pressure load' says; 'Rigid boundary' is refused. One MPI process; "
                      "each Newton update is solved by UMFPACK. Every step writes <base name>-step-NNN.vtu "
                      "(point and cell fields cauchy_stress (xx, yy, xy), cauchy_stress_zz, "
                      "cauchy_von_mises, det_F and principal_stretches; no small-strain stress), the series "
                      "<base name>.pvd, and the Newton history is printed and kept in the JSON summary. "
                      "false: small strain. With several bodies: finite sliding contact (see 'Contact').");
    prm.declare_entry("Pressure load", "follower", Anything(),
                      "How the 'Boundary conditions and loads/Pressure' entries act at finite strain: "
                      "'follower' (the default: the pressure acts on the deformed boundary along its current "
                      "normal, force p per unit current length, t = -p n da, as a gas or liquid pressure "
                      "does; its load turns and stretches with the boundary and Newton uses its tangent) or "
                      "'dead' (the nominal traction -p N: p per unit reference length along the reference "
                      "normal, fixed in direction and size). At small strain the two are the same load.");
    prm.declare_entry("Maximum Newton iterations", "30", Integer(1, 1000),
                      "Largest number of Newton updates (linear solves) per load step; a step that does not "
                      "converge within them stops the run (the converged steps' files are kept).");
    prm.declare_entry("Residual tolerance", "1e-10", Double(0, 1),
                      "Newton: the free residual norm must fall below this times the larger of the external "
                      "and internal force norms (0 < tolerance < 1).");
    prm.declare_entry("Update tolerance", "1e-10", Double(0, 1),
                      "Newton: the next update, estimated from the contraction of the last iteration "
                      "(else the last update), must be below this times the displacement norm "
                      "(0 < tolerance < 1).");
    prm.declare_entry("Line search", "true", Bool(),
                      "Newton: backtrack along the update (step lengths 1, 1/2, ..., 2^-10) until the "
                      "residual norm decreases; false takes every update whole (shortened only where it "
                      "would invert a cell).");
    prm.declare_entry("Monitor point", "", Anything(),
                      "A mesh vertex 'x, y' whose displacement is printed after every load step and written "
                      "to the JSON summary (e.g. the tip of Cook's membrane). Empty: none.");
    prm.leave_subsection();
  }



  void
  FiniteStrainParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Finite strain");
    enabled                   = prm.get_bool("Enabled");
    solver.max_iterations     = prm.get_integer("Maximum Newton iterations");
    solver.residual_tolerance = prm.get_double("Residual tolerance");
    solver.update_tolerance   = prm.get_double("Update tolerance");
    solver.line_search        = prm.get_bool("Line search");
    const std::string point   = prm.get("Monitor point");
    pressure_load             = parse_pressure_load(prm.get("Pressure load"), "Finite strain/Pressure load");
    prm.leave_subsection();
    InputParsing::check_range(solver.residual_tolerance, 0, 1, "Finite strain/Residual tolerance", true, true);
    InputParsing::check_range(solver.update_tolerance, 0, 1, "Finite strain/Update tolerance", true, true);
    has_monitor_point = !InputParsing::trim(point).empty();
    if (has_monitor_point)
      {
        const auto xy = InputParsing::split(point, ',');
        AssertThrow(xy.size() == 2, dealii::ExcMessage("Parameter 'Finite strain/Monitor point' = '" + point +
                                                       "': expected two coordinates 'x, y'."));
        for (unsigned int d = 0; d < 2; ++d)
          monitor_point[d] = InputParsing::parse_double(xy[d], "Finite strain/Monitor point");
      }
  }



  void
  FiniteStrainParameters::refuse(dealii::ParameterHandler &prm, const std::string &reason)
  {
    prm.enter_subsection("Finite strain");
    const bool on = prm.get_bool("Enabled");
    prm.leave_subsection();
    AssertThrow(!on, dealii::ExcMessage("Parameter 'Finite strain/Enabled' is true, but " + reason));
  }
  void
  ScaleCheck::check(const VEMDoFHandler<2>       &dof_handler,
                    const dealii::Vector<double> &f,
                    const std::vector<Body>      &bodies,
                    const std::string            &when,
                    const bool                    finite_strain)
  {
    const auto &mesh = dof_handler.get_mesh();
    // per body: the bounding box of its cells and the sum of the
    // magnitudes of the nodal loads on its DoFs
    std::map<dealii::types::material_id, unsigned int> index;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      index[bodies[b].material_id] = b;
    std::vector<dealii::Point<2>> lo(bodies.size()), hi(bodies.size());
    std::vector<bool>             seen(bodies.size(), false);
    std::vector<int>              dof_body(dof_handler.n_dofs(), -1);
    std::vector<dealii::types::global_dof_index> dofs;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const auto it = index.find(mesh.cell(c).material_id);
        if (it == index.end())
          continue;
        const unsigned int b = it->second;
        for (const auto v : mesh.cell(c).vertices)
          for (unsigned int d = 0; d < 2; ++d)
            {
              const double x = mesh.vertex(v)[d];
              lo[b][d]       = seen[b] ? std::min(lo[b][d], x) : x;
              hi[b][d]       = seen[b] ? std::max(hi[b][d], x) : x;
              if (d == 1)
                seen[b] = true;
            }
        dof_handler.get_dof_indices(c, dofs);
        for (const auto i : dofs)
          dof_body[i] = b;
      }
    std::vector<double> load(bodies.size(), 0.);
    for (unsigned int i = 0; i < f.size(); ++i)
      if (dof_body[i] >= 0)
        load[dof_body[i]] += std::abs(f[i]);

    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        if (!seen[b])
          continue;
        const auto        &body  = bodies[b];
        const double       E     = body.youngs_modulus;
        const double       size  = lo[b].distance(hi[b]);
        const double       force = E * size;
        std::ostringstream msg;
        msg << "Parameter '" << body.modulus_parameter << "' = " << E << ": at finite strain the forces of "
            << body.name << " are of the order of its Young's modulus times its size (" << size << "), " << force
            << ", and its stresses of the order of E; Newton's residual norms and the Cauchy stress norms square "
               "them, which "
            << (std::min(E, force) < min_force_scale ? "underflows" : "overflows")
            << " double precision. The finite-strain paths need E and E times the size of every body between "
            << min_force_scale << " and " << max_force_scale
            << ". Choose units that bring them nearer to 1 (scaling the moduli and the loads by one factor "
               "leaves the strains as they are).";
        AssertThrow(!finite_strain || (E >= min_force_scale && E <= max_force_scale && force >= min_force_scale &&
                                       force <= max_force_scale),
                    dealii::ExcMessage(msg.str()));
        AssertThrow(std::isfinite(load[b]),
                    dealii::ExcMessage("The loads on " + body.name + " overflow double precision when integrated " +
                                       when + " (the sum of the magnitudes of its nodal loads is " +
                                       std::to_string(load[b]) +
                                       "). Check 'Boundary conditions and loads' (Body force, Traction, Pressure) "
                                       "for values far from the units of the problem."));
        const double ratio = load[b] / force;
        // at finite strain, a load that Newton's round-off floor (1e-12 E
        // times the size) cannot tell from none: the body would stay where
        // it is, a wrong answer without a word
        if (finite_strain && ratio > 0 && ratio < min_load_ratio)
          {
            std::ostringstream m;
            m << "The loads on " << body.name << " " << when << " (the sum of the magnitudes of its nodal loads, "
              << load[b] << ") are " << ratio << " times its Young's modulus times its size (" << size
              << "): below " << min_load_ratio
              << ", where the finite-strain Newton solve cannot tell them from round-off (its residual floor is "
                 "1e-12 times E times the size), so the body would not move. Check 'Boundary conditions and "
                 "loads' (Body force, Traction, Pressure) against '"
              << body.modulus_parameter << "' = " << E
              << " (the units of the two), or solve at small strain, where the response is linear in the load.";
            AssertThrow(false, dealii::ExcMessage(m.str()));
          }
        if (ratio > BoundaryConditionParameters::max_displacement_ratio)
          {
            std::ostringstream m;
            m << "The loads on " << body.name << " " << when << " (the sum of the magnitudes of its nodal loads, "
              << load[b] << ") are " << ratio << " times its Young's modulus times its size: they would move it by "
              << "more than " << BoundaryConditionParameters::max_displacement_ratio << " times the size of "
              << (bodies.size() == 1 ? std::string("the mesh") : body.name) << " (" << size << "): "
              << (finite_strain ? "out of scale for any strain" : "far outside the small-displacement model")
              << ", and the solve would overflow or fail for that reason. Check 'Boundary conditions and loads' "
                 "(Body force, Traction, Pressure, Rigid boundary) against '"
              << body.modulus_parameter << "' = " << E << " (the units of the two).";
            AssertThrow(false, dealii::ExcMessage(m.str()));
          }
      }
  }



} // namespace dealvem
