// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// 'Rotation about centre' of the section 'Boundary conditions and loads'
// (BoundaryConditionParameters): the entry, its parsing and the report of
// the parts after a solve (RotationOutput).
#include <dealvem/app/problem_setup.h>

#include <iomanip>
#include <sstream>

namespace dealvem
{
  namespace
  {
    const std::string loads_section = "Boundary conditions and loads";
  } // namespace



  void
  BoundaryConditionParameters::declare_rotation_entry(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    prm.declare_entry("Rotation about centre", "", Anything(),
                      "Boundary parts turned rigidly about a centre (a gear's bore): 'id : cx, cy : angle a; "
                      "id : cx, cy : torque M; ...'. 'angle a' turns the part about (cx, cy) by the angle a "
                      "(counter-clockwise, radians): Dirichlet data u = (R(a) - I)(x - c) on every node of the "
                      "part, the exact rotation (also at finite strain, where each load step without t in the "
                      "data turns the part by its load factor times a, exactly). 'torque M' "
                      "loads the part by the torque M (counter-clockwise) about (cx, cy) and leaves its angle "
                      "an unknown: the part turns rigidly about the centre without translating (a bearing); "
                      "small strain only, and the body needs other support against that rotation (a clamped "
                      "rim, contact). Expressions with the function constants, evaluated at the centre, t = 1 "
                      "(or the time of the load step). Each load step reports per part the centre, the angle "
                      "(prescribed or solved for), the torque, and the moment about the centre "
                      "(the reaction moment of a prescribed angle) and the force on the body: on the terminal, "
                      "in the JSON summary (keys rotations.rotation_<id>: contact problems under steps.N. and at "
                      "the top level for the last step, one body under cycles.C. or "
                      "cycles.C.finite_strain.steps.N.) and, in contact problems with CSV output, in "
                      "<base name>-rotations.csv (finite sliding: columns angle_, torque_, "
                      "moment_about_centre_rotation_<id> of <base name>-history.csv). The nodes of the part may not be "
                      "constrained by other "
                      "entries (a node shared with Dirichlet data must have the same value).");
  }



  void
  BoundaryConditionParameters::parse_rotation_entries(const std::string &value)
  {
    for (const auto &entry : InputParsing::split(value, ';'))
      {
        const std::string name   = loads_section + "/Rotation about centre entry '" + entry + "'";
        const std::string syntax = "expected 'id : cx, cy : angle a' or 'id : cx, cy : torque M'";
        const auto        fields = InputParsing::split(entry, ':', true);
        AssertThrow(fields.size() == 3, dealii::ExcMessage("Parameter '" + name + "': " + syntax + "."));
        const unsigned int number = InputParsing::parse_id_or_name(fields[0], name, physical_names.boundary_ids,
                                                                   "boundary id", physical_names.list());
        AssertThrow(number <= InputParsing::max_boundary_id,
                    dealii::ExcMessage("Parameter '" + name + "': boundary id " + fields[0] +
                                       " is out of range (0..254)."));
        const auto id = dealii::types::boundary_id(number);
        const auto xy = InputParsing::split(fields[1], ',');
        AssertThrow(xy.size() == 2,
                    dealii::ExcMessage("Parameter '" + name + "': expected the centre 'cx, cy' after the id; " +
                                       syntax + "."));
        const dealii::Point<2> centre(InputParsing::parse_double(xy[0], name), InputParsing::parse_double(xy[1], name));
        // 'angle <expression>' or 'torque <expression>'
        const std::string load = InputParsing::trim(fields[2]);
        const auto        word = load.substr(0, load.find_first_of(" \t"));
        AssertThrow(word == "angle" || word == "torque",
                    dealii::ExcMessage("Parameter '" + name +
                                       "': the third field must start with 'angle' or "
                                       "'torque', got '" +
                                       load + "'; " + syntax + "."));
        const std::string expression = InputParsing::trim(load.substr(word.size()));
        AssertThrow(!expression.empty(), dealii::ExcMessage("Parameter '" + name + "': no expression after '" + word +
                                                            "'; " + syntax + "."));
        const auto value =
          std::make_shared<InputParsing::ParsedFunction>(std::vector<std::string>{expression}, constants, name);
        for (const auto &other : rotations)
          AssertThrow(other.id != id,
                      dealii::ExcMessage("Parameter '" + name + "': boundary id " + fields[0] +
                                         " is turned about a centre already (entry '" + other.name + "')."));
        add_rotation_about_centre(id, centre, value, word == "torque", name);
      }
  }



  std::vector<SupportReactions::Rotation>
  BoundaryConditionParameters::rotation_results(const std::vector<BoundaryConditions::RotationAboutCentre<2>> &parts,
                                                const dealii::AffineConstraints<double> &constraints,
                                                const dealii::Vector<double>            &u,
                                                const dealii::Vector<double>            &unbalanced,
                                                const std::vector<dealii::Point<2>>     &positions) const
  {
    AssertThrow(parts.size() == rotations.size(),
                dealii::ExcMessage("BoundaryConditionParameters::rotation_results(): " + std::to_string(parts.size()) +
                                   " parts for " + std::to_string(rotations.size()) +
                                   " 'Rotation about centre' entries."));
    std::vector<SupportReactions::Rotation> results;
    for (unsigned int k = 0; k < parts.size(); ++k)
      {
        const double torque = rotations[k].torque_driven ? rotations[k].value->value(rotations[k].centre) : 0.;
        results.push_back(SupportReactions::rotation(parts[k], torque, constraints, u, unbalanced, positions));
      }
    return results;
  }



  namespace RotationOutput
  {
    void
    print(const dealii::ConditionalOStream              &out,
          const std::vector<SupportReactions::Rotation> &rotations,
          const std::string                             &indent)
    {
      for (const auto &r : rotations)
        {
          out << indent << r.name << ": ";
          if (r.torque_driven)
            out << "torque " << r.torque << " (applied), angle " << r.angle << " (solved for), bearing force ("
                << r.force[0] << ", " << r.force[1] << ")";
          else
            out << "angle " << r.angle << " (prescribed), moment about centre " << r.reaction_moment
                << " (reaction), force (" << r.force[0] << ", " << r.force[1] << ")";
          out << std::endl;
        }
    }



    void
    json(JsonSummary &summary, const std::string &key, const std::vector<SupportReactions::Rotation> &rotations)
    {
      for (const auto &r : rotations)
        {
          const std::string k = key + r.key + ".";
          summary.set(k + "boundary_id", double(r.boundary_id));
          summary.set(k + "centre_x", r.centre[0]);
          summary.set(k + "centre_y", r.centre[1]);
          summary.set(k + "mode", r.torque_driven ? "torque" : "angle");
          summary.set(k + "angle", r.angle);
          summary.set(k + "torque", r.torque);
          summary.set(k + "reaction_moment_about_centre", r.reaction_moment);
          summary.set(k + "moment_about_centre", r.moment_about_centre);
          summary.set(k + "force_x", r.force[0]);
          summary.set(k + "force_y", r.force[1]);
        }
    }



    std::string
    csv_header()
    {
      return "step,time,rotation,boundary_id,centre_x,centre_y,mode,angle,torque,reaction_moment_about_centre,"
             "moment_about_centre,force_x,force_y\n";
    }



    std::string
    csv_line(const unsigned int step, const double time, const SupportReactions::Rotation &r)
    {
      std::ostringstream s;
      s << std::setprecision(15) << step << "," << time << "," << r.key << "," << int(r.boundary_id) << ","
        << r.centre[0] << "," << r.centre[1] << "," << (r.torque_driven ? "torque" : "angle") << "," << r.angle << ","
        << r.torque << "," << r.reaction_moment << "," << r.moment_about_centre << "," << r.force[0] << ","
        << r.force[1] << "\n";
      return s.str();
    }
  } // namespace RotationOutput
} // namespace dealvem
