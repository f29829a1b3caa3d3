// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/elasticity/boundary_conditions.h>

#include <Eigen/Dense>

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
      const auto nodes = dof_handler.boundary_nodes({id});
      for (const unsigned int node : nodes)
        {
          const auto dx = VEMDoFHandler<dim>::node_dof(node, 0);
          const auto dy = VEMDoFHandler<dim>::node_dof(node, 1);
          if (std::abs(normal[0]) >= std::abs(normal[1]))
            {
              if (constraints.is_constrained(dx))
                continue;
              constraints.add_line(dx);
              if (std::abs(normal[1]) > 1e-14)
                constraints.add_entry(dx, dy, -normal[1] / normal[0]);
            }
          else
            {
              if (constraints.is_constrained(dy))
                continue;
              constraints.add_line(dy);
              if (std::abs(normal[0]) > 1e-14)
                constraints.add_entry(dy, dx, -normal[0] / normal[1]);
            }
        }
    }



    template <int dim>
    unsigned int
    add_point_constraint(const VEMDoFHandler<dim>          &dof_handler,
                         const dealii::Point<dim>          &p,
                         const unsigned int                 component,
                         const double                       value,
                         dealii::AffineConstraints<double> &constraints,
                         const double                       relative_tolerance)
    {
      const auto &mesh = dof_handler.get_mesh();
      AssertThrow(component < 2,
                  dealii::ExcMessage("Point constraint: component must be 0 (x) or 1 (y), got " +
                                     std::to_string(component) + "."));
      unsigned int best = dealii::numbers::invalid_unsigned_int;
      double       dist = std::numeric_limits<double>::max();
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        if (mesh.vertex(v).distance(p) < dist)
          {
            dist = mesh.vertex(v).distance(p);
            best = v;
          }
      const double       h = mesh.cell_diameter_range().first;
      std::ostringstream msg;
      msg << "Point constraint at (" << p << ") on mesh '" << mesh.name
          << "': no mesh vertex there";
      if (best != dealii::numbers::invalid_unsigned_int)
        msg << " (nearest vertex " << best << " at (" << mesh.vertex(best)
            << "), distance " << dist << ")";
      msg << ".";
      AssertThrow(best != dealii::numbers::invalid_unsigned_int && dist <= relative_tolerance * h,
                  dealii::ExcMessage(msg.str()));
      const auto dof = VEMDoFHandler<dim>::node_dof(best, component);
      if (!constraints.is_constrained(dof))
        {
          constraints.add_line(dof);
          constraints.set_inhomogeneity(dof, value);
        }
      return best;
    }



    template <int dim>
    void
    check_rigid_body_support(
      const VEMDoFHandler<dim>                &dof_handler,
      const dealii::AffineConstraints<double> &constraints,
      const std::map<dealii::types::material_id, std::vector<std::array<double, 3>>>
        &extra_restraints)
    {
      const auto &mesh = dof_handler.get_mesh();
      // body of each node (vertices first, then edges and cells)
      std::vector<dealii::types::material_id> node_body(dof_handler.n_nodes(),
                                                        dealii::numbers::invalid_material_id);
      std::vector<unsigned int> nodes;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          dof_handler.get_node_indices(c, nodes);
          for (const auto n : nodes)
            node_body[n] = mesh.cell(c).material_id;
        }
      const auto modes = dof_handler.rigid_body_modes();
      // Gram matrix of the restrictions per body: rows r of the constraint
      // operator applied to the three modes, M^T M accumulated.
      std::map<dealii::types::material_id, Eigen::Matrix3d> gram;
      for (const auto id : mesh.get_material_ids())
        gram[id].setZero();
      double scale = 0;
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        scale = std::max(scale, mesh.vertex(v).norm());
      scale = std::max(scale, 1e-300);
      for (const auto &line : constraints.get_lines())
        {
          const auto node = line.index / 2;
          if (node >= node_body.size())
            continue;
          Eigen::Vector3d row;
          for (unsigned int m = 0; m < 3; ++m)
            {
              double r = modes[m][line.index];
              for (const auto &entry : line.entries)
                r -= entry.second * modes[m][entry.first];
              row(m) = (m == 2 ? r / scale : r);
            }
          gram[node_body[node]] += row * row.transpose();
        }
      for (const auto &b : extra_restraints)
        for (const auto &r : b.second)
          {
            const Eigen::Vector3d row(r[0], r[1], r[2] / scale);
            gram[b.first] += row * row.transpose();
          }
      for (const auto &g : gram)
        {
          const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(g.second);
          const auto &vals = eig.eigenvalues();
          const double vmax = std::max(vals(2), 1e-300);
          if (vals(0) > 1e-10 * vmax && vals(2) > 0)
            continue;
          // describe the free motion(s)
          std::ostringstream msg;
          msg << "Unsupported body / rigid-body mode: body (material id " << int(g.first)
              << ") of mesh '" << mesh.name << "' can move as a rigid body";
          const Eigen::Matrix3d &vecs = eig.eigenvectors();
          for (unsigned int k = 0; k < 3; ++k)
            if (vals(k) <= 1e-10 * vmax || vals(2) == 0)
              {
                const Eigen::Vector3d v = vecs.col(k);
                msg << " [";
                const char *names[3] = {"x-translation", "y-translation", "rotation"};
                bool        first    = true;
                for (unsigned int m = 0; m < 3; ++m)
                  if (std::abs(v(m)) > 1e-3)
                    {
                      msg << (first ? "" : " + ") << names[m];
                      first = false;
                    }
                msg << "]";
              }
          msg << ": its constraints do not hold it. Add Dirichlet, roller or point "
                 "constraints (or contact) that fix these motions.";
          AssertThrow(false, dealii::ExcMessage(msg.str()));
        }
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
                         const double, dealii::AffineConstraints<double> &, const double);
    template void
    check_rigid_body_support(
      const VEMDoFHandler<2> &, const dealii::AffineConstraints<double> &,
      const std::map<dealii::types::material_id, std::vector<std::array<double, 3>>> &);
  } // namespace BoundaryConditions
} // namespace dealvem
