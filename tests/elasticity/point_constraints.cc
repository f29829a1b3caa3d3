// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Point constraints (BoundaryConditions::add_point_constraint) next to other
// constraints and on meshes of two bodies:
// - on a displacement that a Dirichlet condition or an axis-parallel roller
//   fixes already: the same value is accepted (the line keeps its value),
//   another value stops with a message naming the earlier condition;
// - on a node of an inclined roller (30 degrees): the component the roller
//   writes cannot take a value of its own (error), the other one can, and
//   then u.n = 0 gives the first: u_x = -tan(30 deg) u_y (1e-14);
// - two bodies with vertices at the same point: without a body an error
//   asks for it, with the body the vertex of that body is taken;
// - a point that is not a vertex: an error naming the nearest vertex.
#include <dealvem/elasticity/boundary_conditions.h>

#include <cmath>

#include "../elasticity_common.h"
#include "../tests.h"

using namespace dealvem;

int
main()
{
  namespace BC = BoundaryConditions;
  const dealii::Functions::ZeroFunction<2> zero(2);
  // Dirichlet and axis-parallel roller
  {
    PolygonalMesh<2> mesh;
    testing::make_mesh(mesh, "structured quads", 0);
    VEMDoFHandler<2> dh(mesh);
    dh.distribute_dofs(2);
    dealii::AffineConstraints<double> cons;
    BC::ConstraintOrigins             origins;
    BC::interpolate_boundary_values(dh, {2}, zero, {{false, true}}, cons);
    for (const auto &l : cons.get_lines())
      origins.emplace(l.index, "Dirichlet on id 2");
    BC::add_roller(dh, 0, cons);
    for (const auto &l : cons.get_lines())
      origins.emplace(l.index, "Roller on id 0");
    // (0, 0) has u_y = 0 (Dirichlet) and u_x = 0 (roller)
    const auto v = BC::add_point_constraint(dh, dealii::Point<2>(0, 0), 1, 0., cons, 1e-6,
                                            dealii::numbers::invalid_material_id, "p1", &origins);
    testing::check(cons.get_inhomogeneity(VEMDoFHandler<2>::node_dof(v, 1)) == 0.,
                   "a point value equal to the Dirichlet value is accepted");
    BC::add_point_constraint(dh, dealii::Point<2>(0, 0.5), 0, 0., cons, 1e-6,
                             dealii::numbers::invalid_material_id, "p2", &origins);
    testing::check(true, "a zero point value on an axis-parallel roller node is accepted");
    testing::check_throws(
      [&] {
        BC::add_point_constraint(dh, dealii::Point<2>(0.25, 0), 1, 0.1, cons, 1e-6,
                                 dealii::numbers::invalid_material_id, "p3", &origins);
      },
      "Point constraint at (0.25 0) (parameter 'p3')", "a point value that differs from Dirichlet: error");
    testing::check_throws(
      [&] {
        BC::add_point_constraint(dh, dealii::Point<2>(0.25, 0), 1, 0.1, cons, 1e-6,
                                 dealii::numbers::invalid_material_id, "p3", &origins);
      },
      "already constrained by Dirichlet on id 2 to the value 0, which conflicts with the value 0.1",
      "the message names the Dirichlet condition and both values");
    testing::check_throws(
      [&] {
        BC::add_point_constraint(dh, dealii::Point<2>(0, 0.75), 0, -1., cons, 1e-6,
                                 dealii::numbers::invalid_material_id, "p4", &origins);
      },
      "already constrained by Roller on id 0", "a point value that differs from a roller: error");
    // not a vertex
    testing::check_throws([&] { BC::add_point_constraint(dh, dealii::Point<2>(0.1, 0.1), 0, 0., cons); },
                          "no mesh vertex there (nearest vertex 0 at (0 0), distance 0.1414",
                          "a point away from the vertices names the nearest vertex");
  }
  // inclined roller: the square rotated by 30 degrees
  {
    PolygonalMesh<2> q;
    testing::make_mesh(q, "structured quads", 0);
    PolygonalMesh<2> mesh;
    const double     th = M_PI / 6;
    for (const auto &v : q.get_vertices())
      mesh.add_vertex(dealii::Point<2>(std::cos(th) * v[0] - std::sin(th) * v[1],
                                       std::sin(th) * v[0] + std::cos(th) * v[1]));
    for (const auto &c : q.get_cells())
      mesh.add_cell(c.vertices);
    for (const auto &e : q.get_edges())
      if (e.at_boundary())
        mesh.set_boundary_id(e.vertices[0], e.vertices[1], e.boundary_id);
    mesh.finalize();
    VEMDoFHandler<2> dh(mesh);
    dh.distribute_dofs(1);
    dealii::AffineConstraints<double> cons;
    BC::ConstraintOrigins             origins;
    BC::add_roller(dh, 0, cons); // normal -(cos 30, sin 30): the roller writes u_x
    for (const auto &l : cons.get_lines())
      origins.emplace(l.index, "inclined roller");
    // the image of (0, 0.5)
    const dealii::Point<2> p(-0.5 * std::sin(th), 0.5 * std::cos(th));
    testing::check_throws([&] { BC::add_point_constraint(dh, p, 0, 0., cons, 1e-6, dealii::numbers::invalid_material_id, "p", &origins); },
                          "inclined roller, which couples it to other displacement components",
                          "a point value on the component an inclined roller writes: error");
    const auto v = BC::add_point_constraint(dh, p, 1, 0.1, cons, 1e-6, dealii::numbers::invalid_material_id, "p", &origins);
    cons.close();
    testing::check_near(cons.get_inhomogeneity(VEMDoFHandler<2>::node_dof(v, 0)), -0.1 * std::tan(th), 1e-14,
                        "u_y = 0.1 at an inclined roller node gives u_x = -tan(30 deg) 0.1");
  }
  // two bodies with vertices at the same points (y = 1)
  {
    PolygonalMesh<2> mesh, upper;
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 4, 4);
    PolygonalMeshGenerators::structured_quads(upper, dealii::Point<2>(0, 1), dealii::Point<2>(1, 2), 4, 4);
    for (unsigned int c = 0; c < upper.n_cells(); ++c)
      upper.set_material_id(c, 1);
    mesh.append(upper);
    VEMDoFHandler<2> dh(mesh);
    dh.distribute_dofs(2);
    dealii::AffineConstraints<double> cons;
    const dealii::Point<2>            p(0.5, 1);
    testing::check_throws([&] { BC::add_point_constraint(dh, p, 1, 0., cons); },
                          "vertices of several bodies (material ids 0 1) lie at this point. Name the body",
                          "two bodies at the point and no body given: error");
    auto body_of_vertex = [&](const unsigned int v) {
      for (const auto &c : mesh.get_cells())
        for (const auto w : c.vertices)
          if (w == v)
            return int(c.material_id);
      return -1;
    };
    for (const int body : {0, 1})
      {
        const auto v = BC::add_point_constraint(dh, p, 1, 0.01 * body, cons, 1e-6, body);
        testing::check(body_of_vertex(v) == body && mesh.vertex(v).distance(p) < 1e-15,
                       "body " + std::to_string(body) + " named: its vertex at (0.5, 1) is constrained");
      }
    testing::check_throws([&] { BC::add_point_constraint(dh, p, 1, 0., cons, 1e-6, 5); },
                          "no cell of mesh", "a body that does not exist: error");
  }
  return testing::finish();
}
