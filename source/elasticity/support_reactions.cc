// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/elasticity/support_reactions.h>

#include <map>
#include <sstream>

namespace dealvem
{
  std::vector<SupportReactions::Reaction>
  SupportReactions::compute(const std::vector<Support>              &supports,
                            const dealii::AffineConstraints<double> &constraints,
                            const dealii::Vector<double>            &unbalanced,
                            const std::vector<dealii::Point<2>>     &positions,
                            const dealii::Point<2>                  &point)
  {
    const unsigned int n = unbalanced.size();
    AssertThrow(positions.size() >= (n + 1) / 2,
                dealii::ExcMessage("SupportReactions::compute(): " + std::to_string(positions.size()) +
                                   " node positions for " + std::to_string(n) + " DoFs."));
    // the lines by their DoF
    std::map<dealii::types::global_dof_index, const dealii::AffineConstraints<double>::ConstraintLine *> line_of;
    for (const auto &line : constraints.get_lines())
      if (line.index < n)
        line_of[line.index] = &line;

    std::vector<Reaction> reactions;
    for (const auto &s : supports)
      {
        Reaction r;
        r.name        = s.name;
        r.key         = s.key;
        r.boundary_id = s.boundary_id;
        // the nodal reaction P_i added at DoF i: its force component and
        // its moment about the point
        const auto add = [&](const dealii::types::global_dof_index i, const double P) {
          dealii::Tensor<1, 2> f;
          f[i % 2] = P;
          r.force += f;
          r.moment += moment(positions[i / 2], f, point);
        };
        for (const auto s_line : s.lines)
          {
            const auto it = line_of.find(s_line);
            AssertThrow(it != line_of.end(),
                        dealii::ExcMessage("SupportReactions::compute(): DoF " + std::to_string(s_line) + " of " +
                                           s.name + " has no constraint line."));
            const auto  &line = *it->second;
            const double rho  = unbalanced[line.index];
            add(line.index, -rho);
            for (const auto &entry : line.entries)
              if (entry.first < n)
                add(entry.first, entry.second * rho);
          }
        reactions.push_back(r);
      }
    return reactions;
  }


  SupportReactions::Rotation
  SupportReactions::rotation(const BoundaryConditions::RotationAboutCentre<2> &part,
                             const double                                      torque,
                             const dealii::AffineConstraints<double>          &constraints,
                             const dealii::Vector<double>                     &u,
                             const dealii::Vector<double>                     &unbalanced,
                             const std::vector<dealii::Point<2>>              &positions)
  {
    Rotation r;
    {
      std::ostringstream name;
      name << "rotation of boundary " << int(part.id) << " about (" << part.centre[0] << ", " << part.centre[1] << ")";
      r.name = name.str();
    }
    r.key           = "rotation_" + std::to_string(int(part.id));
    r.boundary_id   = part.id;
    r.centre        = part.centre;
    r.torque_driven = part.torque_driven;
    r.angle         = part.angle(u);
    r.torque        = part.torque_driven ? torque : 0.;
    Support support;
    support.name        = r.name;
    support.key         = r.key;
    support.boundary_id = part.id;
    support.lines       = part.lines;
    const auto reaction = compute({support}, constraints, unbalanced, positions, part.centre).front();
    r.force             = reaction.force;
    // the torque enters the loads as the force torque/arm on the master
    // DoF; the lines carry its net force back, which belongs to the couple,
    // not to the bearing
    if (part.torque_driven)
      r.force[part.master_dof % 2] += torque / part.master_arm;
    r.reaction_moment     = reaction.moment;
    r.moment_about_centre = r.reaction_moment + r.torque;
    return r;
  }
} // namespace dealvem
