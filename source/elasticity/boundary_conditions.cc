// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/piece_support.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace dealvem
{
  namespace BoundaryConditions
  {
    template <int dim>
    void
    interpolate_boundary_values(const VEMDoFHandler<dim>                   &dof_handler,
                                const std::set<dealii::types::boundary_id> &ids,
                                const dealii::Function<dim>                &g,
                                const std::array<bool, 2>                  &mask,
                                dealii::AffineConstraints<double>          &constraints)
    {
      AssertThrow(g.n_components == 2,
                  dealii::ExcMessage("Dirichlet data must have 2 components."));
      const auto nodes = dof_handler.boundary_nodes(ids);
      AssertThrow(!nodes.empty(),
                  dealii::ExcMessage("Dirichlet condition: no boundary edge of mesh '" +
                                     dof_handler.get_mesh().name +
                                     "' has the given boundary id(s)."));
      for (const unsigned int node : nodes)
        {
          const dealii::Point<dim> x = dof_handler.node_location(node);
          for (unsigned int c = 0; c < 2; ++c)
            if (mask[c])
              {
                const auto dof = VEMDoFHandler<dim>::node_dof(node, c);
                if (constraints.is_constrained(dof))
                  continue;
                constraints.add_line(dof);
                constraints.set_inhomogeneity(dof, g.value(x, c));
              }
        }
    }



    template <int dim>
    void
    add_roller(const VEMDoFHandler<dim>          &dof_handler,
               const dealii::types::boundary_id   id,
               dealii::AffineConstraints<double> &constraints)
    {
      const auto            &mesh = dof_handler.get_mesh();
      dealii::Tensor<1, dim> normal;
      dealii::Point<dim>     origin;
      bool                   first = true;
      double                 length_scale = 0;
      for (unsigned int e = 0; e < mesh.n_edges(); ++e)
        {
          const auto &edge = mesh.edge(e);
          if (!edge.at_boundary() || edge.boundary_id != id)
            continue;
          const auto &a = mesh.vertex(edge.vertices[0]);
          const auto &b = mesh.vertex(edge.vertices[1]);
          dealii::Tensor<1, dim> t = b - a;
          const double           L = t.norm();
          t /= L;
          dealii::Tensor<1, dim> n;
          n[0] = t[1];
          n[1] = -t[0];
          if (first)
            {
              normal       = n;
              origin       = a;
              first        = false;
              length_scale = L;
              continue;
            }
          length_scale = std::max(length_scale, std::max(a.distance(origin), b.distance(origin)));
          const double cross = normal[0] * n[1] - normal[1] * n[0];
          const double off_a = std::abs((a - origin) * normal);
          const double off_b = std::abs((b - origin) * normal);
          std::ostringstream msg;
          msg << "Roller condition on boundary id " << int(id) << " of mesh '" << mesh.name
              << "': the boundary part is not straight (edge " << e << " from (" << a
              << ") to (" << b << ") is not aligned with the first edge).";
          AssertThrow(std::abs(cross) <= 1e-10 && off_a <= 1e-10 * length_scale &&
                        off_b <= 1e-10 * length_scale,
                      dealii::ExcMessage(msg.str()));
        }
      AssertThrow(!first,
                  dealii::ExcMessage("Roller condition: no boundary edge of mesh '" + mesh.name +
                                     "' has boundary id " + std::to_string(int(id)) + "."));
      // At each node impose n.u = 0 on the component with the larger normal
      // component, u_c = -(n_o/n_c) u_o. Where a component is constrained
      // already (a corner with another roller or with Dirichlet data), the
      // two conditions are combined into a value for the free component, so
      // that no cycle of constraints (u_x -> u_y -> u_x) can arise.
      const auto nodes = dof_handler.boundary_nodes({id});
      for (const unsigned int node : nodes)
        {
          const unsigned int c = (std::abs(normal[0]) >= std::abs(normal[1]) ? 0 : 1), o = 1 - c;
          const auto         dc = VEMDoFHandler<dim>::node_dof(node, c);
          const auto         do_ = VEMDoFHandler<dim>::node_dof(node, o);
          const double       nc = normal[c], no = normal[o];
          // a line u_d = a u_other + b of a constrained DoF d of this node
          // (entries on other DoFs are not expected here)
          auto line_of = [&](const dealii::types::global_dof_index d,
                             const dealii::types::global_dof_index other, double &a, double &b) {
            a = 0;
            b = constraints.get_inhomogeneity(d);
            if (const auto *entries = constraints.get_constraint_entries(d))
              for (const auto &e : *entries)
                {
                  AssertThrow(e.first == other,
                              dealii::ExcMessage("Roller condition on boundary id " + std::to_string(int(id)) +
                                                 ": a node carries a constraint coupling it to other nodes."));
                  a += e.second;
                }
          };
          const bool c_constrained = constraints.is_constrained(dc);
          const bool o_constrained = constraints.is_constrained(do_);
          if (c_constrained && o_constrained)
            continue;
          double a, b;
          if (!c_constrained && !o_constrained)
            {
              constraints.add_line(dc);
              if (std::abs(no) > 1e-14)
                constraints.add_entry(dc, do_, -no / nc);
            }
          else if (c_constrained)
            {
              // u_c = a u_o + b  and  nc u_c + no u_o = 0
              line_of(dc, do_, a, b);
              const double denominator = nc * a + no;
              if (std::abs(denominator) <= 1e-12)
                continue; // the existing constraint already implies n.u = 0 up to b
              constraints.add_line(do_);
              constraints.set_inhomogeneity(do_, -nc * b / denominator);
            }
          else
            {
              // u_o = a u_c + b  and  nc u_c + no u_o = 0
              line_of(do_, dc, a, b);
              const double denominator = nc + no * a;
              if (std::abs(denominator) <= 1e-12)
                continue;
              constraints.add_line(dc);
              constraints.set_inhomogeneity(dc, -no * b / denominator);
            }
        }
    }



    namespace
    {
      // "Point constraint at (p)" plus the parameter entry, for messages
      template <int dim>
      std::string
      point_constraint_label(const dealii::Point<dim> &p, const std::string &name)
      {
        std::ostringstream s;
        s << "Point constraint at (" << p << ")";
        if (!name.empty())
          s << " (parameter '" << name << "')";
        return s.str();
      }

      std::string
      origin_of(const dealii::types::global_dof_index dof, const ConstraintOrigins *origins)
      {
        if (origins != nullptr)
          if (const auto it = origins->find(dof); it != origins->end())
            return it->second;
        return "an earlier condition";
      }

      // the body (material id) of each vertex
      template <int dim>
      std::vector<dealii::types::material_id>
      vertex_bodies(const PolygonalMesh<dim> &mesh)
      {
        std::vector<dealii::types::material_id> body(mesh.n_vertices(),
                                                     dealii::numbers::invalid_material_id);
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          for (const auto v : mesh.cell(c).vertices)
            body[v] = mesh.cell(c).material_id;
        return body;
      }
    } // namespace



    template <int dim>
    unsigned int
    add_point_constraint(const VEMDoFHandler<dim>          &dof_handler,
                         const dealii::Point<dim>          &p,
                         const unsigned int                 component,
                         const double                       value,
                         dealii::AffineConstraints<double> &constraints,
                         const double                       relative_tolerance,
                         const dealii::types::material_id   body,
                         const std::string                 &name,
                         const ConstraintOrigins           *origins)
    {
      const auto       &mesh  = dof_handler.get_mesh();
      const std::string label = point_constraint_label(p, name);
      AssertThrow(component < 2,
                  dealii::ExcMessage(label + ": component must be 0 (x) or 1 (y), got " +
                                     std::to_string(component) + "."));
      AssertThrow(std::isfinite(value),
                  dealii::ExcMessage(label + ": the value is not a finite number."));
      const auto bodies   = vertex_bodies(mesh);
      const bool any_body = (body == dealii::numbers::invalid_material_id);
      AssertThrow(any_body || std::find(bodies.begin(), bodies.end(), body) != bodies.end(),
                  dealii::ExcMessage(label + ": no cell of mesh '" + mesh.name + "' has material id (body) " +
                                     std::to_string(int(body)) + "."));
      const double tolerance = relative_tolerance * mesh.cell_diameter_range().first;
      unsigned int best      = dealii::numbers::invalid_unsigned_int;
      double       dist      = std::numeric_limits<double>::max();
      std::set<dealii::types::material_id> bodies_at_point;
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        {
          if (!any_body && bodies[v] != body)
            continue;
          const double d = mesh.vertex(v).distance(p);
          if (d <= tolerance)
            bodies_at_point.insert(bodies[v]);
          if (d < dist)
            {
              dist = d;
              best = v;
            }
        }
      std::ostringstream msg;
      msg << label << " on mesh '" << mesh.name << "': no mesh vertex there";
      if (!any_body)
        msg << " among the vertices of body " << int(body);
      if (best != dealii::numbers::invalid_unsigned_int)
        msg << " (nearest vertex " << best << " at (" << mesh.vertex(best) << "), distance " << dist
            << ")";
      msg << ".";
      AssertThrow(best != dealii::numbers::invalid_unsigned_int && dist <= tolerance,
                  dealii::ExcMessage(msg.str()));
      if (any_body && bodies_at_point.size() > 1)
        {
          std::ostringstream m;
          m << label << " on mesh '" << mesh.name << "': vertices of several bodies (material ids";
          for (const auto b : bodies_at_point)
            m << " " << int(b);
          m << ") lie at this point. Name the body with a fourth field: "
               "'x, y : component : value : body'.";
          AssertThrow(false, dealii::ExcMessage(m.str()));
        }
      const auto dof = VEMDoFHandler<dim>::node_dof(dof_handler.vertex_node(best), component);
      if (!constraints.is_constrained(dof))
        {
          constraints.add_line(dof);
          constraints.set_inhomogeneity(dof, value);
          return best;
        }
      // constrained already: accept only the same fixed value
      const auto  *entries  = constraints.get_constraint_entries(dof);
      const bool   coupled  = entries != nullptr && !entries->empty();
      const double existing = constraints.get_inhomogeneity(dof);
      const bool   same =
        !coupled && (existing == value ||
                     std::abs(existing - value) <= 1e-12 * std::max(std::abs(existing), std::abs(value)));
      if (!same)
        {
          std::ostringstream m;
          m << label << " on mesh '" << mesh.name << "': component " << (component == 0 ? "x" : "y")
            << " of vertex " << best << " at (" << mesh.vertex(best) << ") is already constrained by "
            << origin_of(dof, origins);
          if (coupled)
            m << ", which couples it to other displacement components, so the value " << value
              << " cannot be imposed on its own.";
          else
            m << " to the value " << existing << ", which conflicts with the value " << value << ".";
          AssertThrow(false, dealii::ExcMessage(m.str()));
        }
      return best;
    }



    template <int dim>
    RigidBoundary<dim>
    rigid_boundary_geometry(const VEMDoFHandler<dim> &dof_handler, const dealii::types::boundary_id id)
    {
      const auto        &mesh = dof_handler.get_mesh();
      RigidBoundary<dim> part;
      part.id     = id;
      part.length = 0;
      dealii::Tensor<1, dim> moment;
      for (unsigned int e = 0; e < mesh.n_edges(); ++e)
        {
          const auto &edge = mesh.edge(e);
          if (!edge.at_boundary() || edge.boundary_id != id)
            continue;
          const auto  &a = mesh.vertex(edge.vertices[0]);
          const auto  &b = mesh.vertex(edge.vertices[1]);
          const double L = a.distance(b);
          part.length += L;
          moment += L * 0.5 * ((a - dealii::Point<dim>()) + (b - dealii::Point<dim>()));
        }
      AssertThrow(part.length > 0,
                  dealii::ExcMessage("Rigid boundary: no boundary edge of mesh '" + mesh.name +
                                     "' has boundary id " + std::to_string(int(id)) + "."));
      part.centroid = dealii::Point<dim>() + moment / part.length;
      part.nodes    = dof_handler.boundary_nodes({id});
      // A: nearest to the centroid; B: farthest from A (first one on ties)
      double best = std::numeric_limits<double>::max();
      for (const auto n : part.nodes)
        if (const double d = dof_handler.node_location(n).distance(part.centroid); d < best)
          {
            best        = d;
            part.node_a = n;
          }
      part.point_a = dof_handler.node_location(part.node_a);
      best         = -1;
      for (const auto n : part.nodes)
        if (const double d = dof_handler.node_location(n).distance(part.point_a); d > best)
          {
            best        = d;
            part.node_b = n;
          }
      part.point_b                 = dof_handler.node_location(part.node_b);
      const auto d                 = part.point_b - part.point_a;
      part.b_free_component        = (std::abs(d[0]) >= std::abs(d[1]) ? 1 : 0);
      return part;
    }



    template <int dim>
    RigidBoundary<dim>
    add_rigid_boundary(const VEMDoFHandler<dim>          &dof_handler,
                       const dealii::types::boundary_id   id,
                       dealii::AffineConstraints<double> &constraints,
                       const std::string                 &name,
                       const ConstraintOrigins           *origins)
    {
      const auto part  = rigid_boundary_geometry(dof_handler, id);
      const auto label = (name.empty() ? "Rigid boundary id " + std::to_string(int(id)) :
                                         "Parameter '" + name + "'");
      using dof_type   = dealii::types::global_dof_index;
      const unsigned int o = part.b_free_component, c_b = 1 - o;
      const dof_type     a_dof[2] = {VEMDoFHandler<dim>::node_dof(part.node_a, 0),
                                     VEMDoFHandler<dim>::node_dof(part.node_a, 1)};
      const dof_type     b_free   = VEMDoFHandler<dim>::node_dof(part.node_b, o);

      // collisions with earlier constraints
      auto collision = [&](const unsigned int node, const unsigned int c, const std::string &why) {
        std::ostringstream m;
        m << label << " on mesh '" << dof_handler.get_mesh().name << "': component "
          << (c == 0 ? "x" : "y") << " of the node at (" << dof_handler.node_location(node)
          << ") is already constrained by " << origin_of(VEMDoFHandler<dim>::node_dof(node, c), origins)
          << ". " << why;
        AssertThrow(false, dealii::ExcMessage(m.str()));
      };
      for (const auto node : part.nodes)
        for (unsigned int c = 0; c < 2; ++c)
          {
            const auto dof = VEMDoFHandler<dim>::node_dof(node, c);
            if (!constraints.is_constrained(dof))
              continue;
            const bool reference = (node == part.node_a) || (node == part.node_b && c == o);
            if (!reference)
              collision(node, c,
                        "A rigid boundary may share constrained DoFs with other conditions only at "
                        "its reference nodes A (the node nearest to its centroid) and B (the node "
                        "farthest from A), and only in the component of B normal to AB.");
            if (const auto *entries = constraints.get_constraint_entries(dof))
              for (const auto &e : *entries)
                if (e.first / 2 != node)
                  collision(node, c,
                            "That constraint couples the node to other nodes; a reference node of a "
                            "rigid boundary may carry only constraints of its own displacement.");
          }

      // the lines: u_{i,c} = u_{A,c} + theta perp(x_i - x_A)_c with
      // theta = (u_{B,o} - u_{A,o}) / p_o, coefficients merged per DoF
      const auto   d   = part.point_b - part.point_a;
      const double p_o = (o == 0 ? -d[1] : d[0]);
      std::vector<std::pair<dof_type, double>> entries;
      auto write_line = [&](const unsigned int node, const unsigned int c) {
        const auto   r      = dof_handler.node_location(node) - part.point_a;
        const double perp_c = (c == 0 ? -r[1] : r[0]);
        const double s      = perp_c / p_o;
        std::map<dof_type, double> coefficients;
        coefficients[a_dof[c]] += 1.;
        coefficients[b_free] += s;
        coefficients[a_dof[o]] -= s;
        entries.clear();
        for (const auto &e : coefficients)
          if (e.second != 0.)
            entries.emplace_back(e);
        const auto dof = VEMDoFHandler<dim>::node_dof(node, c);
        constraints.add_line(dof);
        constraints.add_entries(dof, entries);
      };
      for (const auto node : part.nodes)
        {
          if (node == part.node_a)
            continue;
          if (node == part.node_b)
            write_line(node, c_b);
          else
            for (unsigned int c = 0; c < 2; ++c)
              write_line(node, c);
        }
      return part;
    }



    template <int dim>
    std::vector<std::pair<dealii::types::global_dof_index, double>>
    rigid_boundary_load(const RigidBoundary<dim>     &part,
                        const dealii::Tensor<1, dim> &force,
                        const double                  moment)
    {
      // work = F.u_A + theta (F.perp(x_0 - x_A) + M), theta = (u_{B,o} - u_{A,o}) / p_o
      const unsigned int o  = part.b_free_component;
      const auto         d  = part.point_b - part.point_a;
      const auto         r  = part.centroid - part.point_a;
      const double       p_o = (o == 0 ? -d[1] : d[0]);
      const double       T   = -force[0] * r[1] + force[1] * r[0] + moment;
      std::map<dealii::types::global_dof_index, double> f;
      f[VEMDoFHandler<dim>::node_dof(part.node_a, 0)] += force[0];
      f[VEMDoFHandler<dim>::node_dof(part.node_a, 1)] += force[1];
      f[VEMDoFHandler<dim>::node_dof(part.node_a, o)] -= T / p_o;
      f[VEMDoFHandler<dim>::node_dof(part.node_b, o)] += T / p_o;
      return {f.begin(), f.end()};
    }



    namespace
    {
      // "Rotation of boundary id 3 about (0, 0)" or the parameter entry
      template <int dim>
      std::string
      rotation_label(const dealii::types::boundary_id id, const dealii::Point<dim> &centre, const std::string &name)
      {
        if (!name.empty())
          return "Parameter '" + name + "'";
        std::ostringstream s;
        s << "Rotation of boundary id " << int(id) << " about (" << centre[0] << ", " << centre[1] << ")";
        return s.str();
      }

      // perp(x - c) = (-(y - c_y), x - c_x), component c
      template <int dim>
      double
      arm(const dealii::Point<dim> &x, const dealii::Point<dim> &centre, const unsigned int c)
      {
        return c == 0 ? -(x[1] - centre[1]) : x[0] - centre[0];
      }
    } // namespace



    template <int dim>
    RotationAboutCentre<dim>
    rotation_geometry(const VEMDoFHandler<dim>        &dof_handler,
                      const dealii::types::boundary_id id,
                      const dealii::Point<dim>        &centre,
                      const std::string               &name)
    {
      const auto &mesh  = dof_handler.get_mesh();
      const auto  label = rotation_label(id, centre, name);
      AssertThrow(std::isfinite(centre[0]) && std::isfinite(centre[1]),
                  dealii::ExcMessage(label + ": the centre of the rotation is not finite."));
      RotationAboutCentre<dim> part;
      part.id     = id;
      part.centre = centre;
      part.nodes  = dof_handler.boundary_nodes({id});
      AssertThrow(!part.nodes.empty(), dealii::ExcMessage(label + ": no boundary edge of mesh '" + mesh.name +
                                                          "' has boundary id " + std::to_string(int(id)) + "."));
      // the master: the largest arm in magnitude (the first on ties)
      double       largest = -1;
      unsigned int node = part.nodes.front(), component = 0;
      for (const auto n : part.nodes)
        for (unsigned int c = 0; c < 2; ++c)
          if (const double a = std::abs(arm(dof_handler.node_location(n), centre, c)); a > largest)
            {
              largest   = a;
              node      = n;
              component = c;
            }
      AssertThrow(largest > 0,
                  dealii::ExcMessage(label + ": every node of the boundary part lies at the centre of the rotation."));
      part.master_dof = VEMDoFHandler<dim>::node_dof(node, component);
      part.master_arm = arm(dof_handler.node_location(node), centre, component);
      return part;
    }



    template <int dim>
    RotationAboutCentre<dim>
    add_prescribed_rotation(const VEMDoFHandler<dim>          &dof_handler,
                            const dealii::types::boundary_id   id,
                            const dealii::Point<dim>          &centre,
                            const double                       angle,
                            dealii::AffineConstraints<double> &constraints,
                            const std::string                 &name,
                            const ConstraintOrigins           *origins)
    {
      auto       part  = rotation_geometry(dof_handler, id, centre, name);
      const auto label = rotation_label(id, centre, name);
      AssertThrow(std::isfinite(angle), dealii::ExcMessage(label + ": the angle of the rotation is not finite."));
      part.torque_driven    = false;
      part.prescribed_angle = angle;
      part.master_dof       = dealii::numbers::invalid_dof_index;
      part.master_arm       = 0;
      const double cs = std::cos(angle), sn = std::sin(angle);
      for (const auto node : part.nodes)
        {
          const auto   x  = dof_handler.node_location(node);
          const double dx = x[0] - centre[0], dy = x[1] - centre[1];
          // (R - I)(x - c), exact
          const double value[2] = {(cs - 1.) * dx - sn * dy, sn * dx + (cs - 1.) * dy};
          for (unsigned int c = 0; c < 2; ++c)
            {
              const auto dof = VEMDoFHandler<dim>::node_dof(node, c);
              if (!constraints.is_constrained(dof))
                {
                  constraints.add_line(dof);
                  constraints.set_inhomogeneity(dof, value[c]);
                  part.lines.push_back(dof);
                  continue;
                }
              // constrained already: accept the same fixed value only
              const auto  *entries  = constraints.get_constraint_entries(dof);
              const bool   coupled  = entries != nullptr && !entries->empty();
              const double existing = constraints.get_inhomogeneity(dof);
              const double scale    = std::max(std::abs(existing), std::abs(value[c]));
              if (!coupled && std::abs(existing - value[c]) <= 1e-12 * std::max(scale, 1e-300))
                continue;
              std::ostringstream m;
              m << label << " on mesh '" << dof_handler.get_mesh().name << "': component " << (c == 0 ? "x" : "y")
                << " of the node at (" << x << ") is already constrained by " << origin_of(dof, origins);
              if (coupled)
                m << ", which couples it to other displacement components";
              else
                m << " to the value " << existing;
              m << "; the rotation by " << angle << " about (" << centre[0] << ", " << centre[1] << ") prescribes "
                << value[c] << " there. Give the nodes of the rotating part to one condition only.";
              AssertThrow(false, dealii::ExcMessage(m.str()));
            }
        }
      return part;
    }



    template <int dim>
    RotationAboutCentre<dim>
    add_torque_rotation(const VEMDoFHandler<dim>          &dof_handler,
                        const dealii::types::boundary_id   id,
                        const dealii::Point<dim>          &centre,
                        dealii::AffineConstraints<double> &constraints,
                        const std::string                 &name,
                        const ConstraintOrigins           *origins)
    {
      auto       part    = rotation_geometry(dof_handler, id, centre, name);
      const auto label   = rotation_label(id, centre, name);
      part.torque_driven = true;
      for (const auto node : part.nodes)
        for (unsigned int c = 0; c < 2; ++c)
          {
            const auto dof = VEMDoFHandler<dim>::node_dof(node, c);
            if (!constraints.is_constrained(dof))
              continue;
            std::ostringstream m;
            m << label << " on mesh '" << dof_handler.get_mesh().name << "': component " << (c == 0 ? "x" : "y")
              << " of the node at (" << dof_handler.node_location(node) << ") is already constrained by "
              << origin_of(dof, origins)
              << ". A part turned by a torque (its angle an unknown) must have every node free; give its "
                 "nodes to one condition only.";
            AssertThrow(false, dealii::ExcMessage(m.str()));
          }
      // u_d = (arm_d / arm_m) u_m for every DoF d but the master
      for (const auto node : part.nodes)
        for (unsigned int c = 0; c < 2; ++c)
          {
            const auto dof = VEMDoFHandler<dim>::node_dof(node, c);
            if (dof == part.master_dof)
              continue;
            constraints.add_line(dof);
            part.lines.push_back(dof);
            const double s = arm(dof_handler.node_location(node), centre, c) / part.master_arm;
            if (s != 0.)
              constraints.add_entry(dof, part.master_dof, s);
          }
      return part;
    }



    template <int dim>
    std::vector<std::pair<dealii::types::global_dof_index, double>>
    rotation_torque_load(const RotationAboutCentre<dim> &part, const double torque)
    {
      AssertThrow(part.torque_driven && part.master_dof != dealii::numbers::invalid_dof_index,
                  dealii::ExcMessage("rotation_torque_load(): boundary id " + std::to_string(int(part.id)) +
                                     " is not a torque-driven rotation (add_torque_rotation())."));
      AssertThrow(std::isfinite(torque), dealii::ExcMessage("rotation_torque_load(): the torque on boundary id " +
                                                            std::to_string(int(part.id)) + " is not finite."));
      return {{part.master_dof, torque / part.master_arm}};
    }



    template <int dim>
    void
    check_rigid_body_support(
      const VEMDoFHandler<dim>                &dof_handler,
      const dealii::AffineConstraints<double> &constraints,
      const std::map<dealii::types::material_id, std::vector<std::array<double, 3>>>
        &extra_restraints)
    {
      const auto        &mesh = dof_handler.get_mesh();
      const PieceSupport support(dof_handler);
      const auto        &pieces = support.get_pieces();
      // the rows of the constraint lines (homogeneous parts) and of the
      // extra restraints on each piece of their body
      std::vector<PieceSupport::Row> rows;
      PieceSupport::Form              form;
      for (const auto &line : constraints.get_lines())
        {
          if (line.index / 2 >= dof_handler.n_nodes())
            continue;
          form.assign(1, {line.index, 1.});
          for (const auto &entry : line.entries)
            form.emplace_back(entry.first, -entry.second);
          support.add_rows(form, rows);
        }
      for (const auto &b : extra_restraints)
        for (unsigned int p = 0; p < pieces.n_pieces(); ++p)
          if (pieces.body(p) == b.first)
            for (const auto &r : b.second)
              rows.push_back({{3 * p, r[0]}, {3 * p + 1, r[1]}, {3 * p + 2, r[2] / pieces.size(p)}});
      std::vector<const PieceSupport::Row *> row_pointers;
      for (const auto &r : rows)
        row_pointers.push_back(&r);
      const auto motions = support.free_motions(row_pointers);
      if (motions.empty())
        return;
      // name the first body (or piece) that moves, and its free motions
      const unsigned int p     = motions.front().front() / 3;
      const auto         b     = pieces.body(p);
      const bool         split = pieces.n_pieces_of_body(b) > 1;
      std::vector<std::vector<unsigned int>> own;
      for (const auto &m : motions)
        if (pieces.body(m.front() / 3) == b)
          own.push_back(m);
      std::ostringstream msg;
      msg << "Unsupported body / rigid-body mode: body (material id " << int(b) << ") of mesh '" << mesh.name
          << "' can move as a rigid body " << support.describe(own, false) << ": its constraints do not hold it.";
      if (split)
        msg << " The body consists of " << pieces.n_pieces_of_body(b)
            << " pieces that share no edge (cells touching at a vertex only, a hinge, are not connected), and "
               "each piece must be held by its own constraints: "
            << support.describe_pieces(own) << "." << support.describe_hinges(own);
      msg << " Add Dirichlet, roller or point constraints (or contact) that fix these motions"
          << (split ? ", or connect the pieces through shared edges." : ".");
      AssertThrow(false, dealii::ExcMessage(msg.str()));
    }

    template void
    interpolate_boundary_values(const VEMDoFHandler<2> &,
                                const std::set<dealii::types::boundary_id> &,
                                const dealii::Function<2> &,
                                const std::array<bool, 2> &,
                                dealii::AffineConstraints<double> &);
    template void
    add_roller(const VEMDoFHandler<2> &, const dealii::types::boundary_id,
               dealii::AffineConstraints<double> &);
    template unsigned int
    add_point_constraint(const VEMDoFHandler<2> &, const dealii::Point<2> &, const unsigned int,
                         const double, dealii::AffineConstraints<double> &, const double,
                         const dealii::types::material_id, const std::string &,
                         const ConstraintOrigins *);
    template RigidBoundary<2>
    rigid_boundary_geometry(const VEMDoFHandler<2> &, const dealii::types::boundary_id);
    template RigidBoundary<2>
    add_rigid_boundary(const VEMDoFHandler<2> &, const dealii::types::boundary_id,
                       dealii::AffineConstraints<double> &, const std::string &,
                       const ConstraintOrigins *);
    template std::vector<std::pair<dealii::types::global_dof_index, double>>
    rigid_boundary_load(const RigidBoundary<2> &, const dealii::Tensor<1, 2> &, const double);
    template RotationAboutCentre<2>
    rotation_geometry(const VEMDoFHandler<2> &,
                      const dealii::types::boundary_id,
                      const dealii::Point<2> &,
                      const std::string &);
    template RotationAboutCentre<2>
    add_prescribed_rotation(const VEMDoFHandler<2> &,
                            const dealii::types::boundary_id,
                            const dealii::Point<2> &,
                            const double,
                            dealii::AffineConstraints<double> &,
                            const std::string &,
                            const ConstraintOrigins *);
    template RotationAboutCentre<2>
    add_torque_rotation(const VEMDoFHandler<2> &,
                        const dealii::types::boundary_id,
                        const dealii::Point<2> &,
                        dealii::AffineConstraints<double> &,
                        const std::string &,
                        const ConstraintOrigins *);
    template std::vector<std::pair<dealii::types::global_dof_index, double>>
    rotation_torque_load(const RotationAboutCentre<2> &, const double);
    template void
    check_rigid_body_support(
      const VEMDoFHandler<2> &, const dealii::AffineConstraints<double> &,
      const std::map<dealii::types::material_id, std::vector<std::array<double, 3>>> &);
  } // namespace BoundaryConditions
} // namespace dealvem
