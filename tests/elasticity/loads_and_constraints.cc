// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Loads and constraints, checked against uniform or linear stress states
// that k = 1, 2 reproduce exactly (stresses of every cell to 1e-10):
// - tension by a traction on the right side, rollers on the left and
//   bottom sides: sigma_xx = s, sigma_yy = sigma_xy = 0;
// - a square rotated by 30 degrees, rollers on two inclined sides, pressure
//   p on the other two: sigma = -p I;
// - pure bending (k = 2) by the linear traction t = (a (y - 1/2), 0):
//   sigma_xx = a (y - 1/2) (the traction has the edge's polynomial degree, so
//   its load is exact);
// - a point constraint away from any vertex, a roller on a boundary part
//   that is not straight, and a body with no support give clear errors.
#include <deal.II/base/function.h>

#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/vem/polygon_geometry.h>

#include <functional>

#include <cmath>

#include "../elasticity_common.h"
#include "../tests.h"

using namespace dealvem;

class LinearTraction : public dealii::Function<2>
{
public:
  explicit LinearTraction(const double a)
    : dealii::Function<2>(2)
    , a(a)
  {}
  double
  value(const dealii::Point<2> &p, const unsigned int c) const override
  {
    return c == 0 ? a * (p[1] - 0.5) : 0.;
  }
  double a;
};

// Solve with the given constraints and loads, return the largest deviation
// of the cell stresses from sigma_exact(x_centroid).
template <typename Exact>
double
solve_and_compare(const VEMDoFHandler<2>                  &dof_handler,
                  dealii::AffineConstraints<double>       &constraints,
                  const std::function<void(ElasticityAssembler<2> &)> &add_loads,
                  const Exact                             &sigma_exact)
{
  const ElasticMaterial                                 material(200, 0.25, ElasticMaterial::Model::plane_stress);
  const std::map<dealii::types::material_id, ElasticMaterial> materials = {{0, material}};
  constraints.close();
  BoundaryConditions::check_rigid_body_support(dof_handler, constraints);
  dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
  dof_handler.make_sparsity_pattern(dsp, constraints);
  dealii::SparsityPattern sp;
  sp.copy_from(dsp);
  dealii::SparseMatrix<double> A(sp);
  dealii::Vector<double>       b, x(dof_handler.n_dofs());
  ElasticityAssembler<2>       assembler(dof_handler, materials);
  add_loads(assembler);
  assembler.assemble(constraints, A, b);
  dealii::SparseDirectUMFPACK solver;
  solver.initialize(A);
  solver.vmult(x, b);
  constraints.distribute(x);
  const StressRecovery<2> s(dof_handler, materials, x);
  double                  err = 0;
  const auto             &mesh = dof_handler.get_mesh();
  for (unsigned int c = 0; c < mesh.n_cells(); ++c)
    {
      const auto v = mesh.cell_vertices(c);
      // centroid of the polygon
      const dealvem::PolygonGeometry<2> g(v);
      const auto                        e = sigma_exact(g.centroid());
      const auto                        t = s.cell_stress(c);
      err = std::max({err, std::abs(t[0][0] - e[0]), std::abs(t[1][1] - e[1]), std::abs(t[0][1] - e[2])});
    }
  return err;
}

int
main()
{
  for (const unsigned int k : {1u, 2u})
    {
      const std::string tag = "k=" + std::to_string(k);
      // tension by a traction
      {
        PolygonalMesh<2> mesh;
        testing::make_mesh(mesh, "voronoi", 0);
        VEMDoFHandler<2> dh(mesh);
        dh.distribute_dofs(k);
        dealii::AffineConstraints<double> cons;
        BoundaryConditions::add_roller(dh, 0, cons);
        BoundaryConditions::add_roller(dh, 2, cons);
        const dealii::Functions::ConstantFunction<2> t(std::vector<double>{3.0, 0.0});
        const double err = solve_and_compare(dh, cons, [&](ElasticityAssembler<2> &a) { a.add_traction(1, t); },
                                             [](const dealii::Point<2> &) { return std::array<double, 3>{{3., 0., 0.}}; });
        testing::check_small(err / 3, 1e-10, tag + " Voronoi, rollers + traction: stress error / s");
      }
      // rotated square, inclined rollers, pressure
      {
        PolygonalMesh<2> q;
        testing::make_mesh(q, "perturbed quads", 0);
        PolygonalMesh<2> mesh;
        const double     th = M_PI / 6;
        for (const auto &v : q.get_vertices())
          mesh.add_vertex(dealii::Point<2>(std::cos(th) * v[0] - std::sin(th) * v[1] + 5,
                                           std::sin(th) * v[0] + std::cos(th) * v[1] - 2));
        for (const auto &c : q.get_cells())
          mesh.add_cell(c.vertices);
        for (const auto &e : q.get_edges())
          if (e.at_boundary())
            mesh.set_boundary_id(e.vertices[0], e.vertices[1], e.boundary_id);
        mesh.finalize();
        VEMDoFHandler<2> dh(mesh);
        dh.distribute_dofs(k);
        dealii::AffineConstraints<double> cons;
        BoundaryConditions::add_roller(dh, 0, cons);
        BoundaryConditions::add_roller(dh, 2, cons);
        const dealii::Functions::ConstantFunction<2> p(7.0);
        const double err = solve_and_compare(dh, cons,
                                             [&](ElasticityAssembler<2> &a) {
                                               a.add_pressure(1, p);
                                               a.add_pressure(3, p);
                                             },
                                             [](const dealii::Point<2> &) { return std::array<double, 3>{{-7., -7., 0.}}; });
        testing::check_small(err / 7, 1e-10, tag + " rotated square, inclined rollers + pressure: stress error / p");
      }
    }
  // pure bending by a linear traction (k = 2 reproduces the quadratic field)
  {
    PolygonalMesh<2> mesh;
    testing::make_mesh(mesh, "nonconvex", 0);
    VEMDoFHandler<2> dh(mesh);
    dh.distribute_dofs(2);
    dealii::AffineConstraints<double> cons;
    BoundaryConditions::add_roller(dh, 0, cons);
    BoundaryConditions::add_point_constraint(dh, dealii::Point<2>(0, 0), 1, 0., cons);
    const LinearTraction t(4.0);
    const double         err = solve_and_compare(dh, cons, [&](ElasticityAssembler<2> &a) { a.add_traction(1, t); },
                                         [](const dealii::Point<2> &x) {
                                           return std::array<double, 3>{{4. * (x[1] - 0.5), 0., 0.}};
                                         });
    testing::check_small(err / 2, 1e-10, "k=2 non-convex cells, pure bending by a linear traction: stress error / max");
  }
  // errors
  {
    PolygonalMesh<2> mesh;
    testing::make_mesh(mesh, "structured quads", 0);
    VEMDoFHandler<2> dh(mesh);
    dh.distribute_dofs(2);
    dealii::AffineConstraints<double> cons;
    testing::check_throws([&] { BoundaryConditions::add_point_constraint(dh, dealii::Point<2>(0.1, 0.1), 0, 0., cons); },
                          "Point constraint at", "point constraint away from the vertices");
    // make a boundary part that bends: give the bottom and right sides id 7
    PolygonalMesh<2> m2 = mesh;
    for (unsigned int e = 0; e < m2.n_edges(); ++e)
      if (m2.edge(e).at_boundary() && (m2.edge(e).boundary_id == 1 || m2.edge(e).boundary_id == 2))
        m2.set_edge_boundary_id(e, 7);
    VEMDoFHandler<2> dh2(m2);
    dh2.distribute_dofs(2);
    testing::check_throws([&] { BoundaryConditions::add_roller(dh2, 7, cons); }, "not straight",
                          "roller on a bent boundary part");
    dealii::AffineConstraints<double> only_roller;
    BoundaryConditions::add_roller(dh, 0, only_roller);
    only_roller.close();
    testing::check_throws([&] { BoundaryConditions::check_rigid_body_support(dh, only_roller); },
                          "Unsupported body", "a body held by one roller only");
    testing::check_throws([&] { BoundaryConditions::check_rigid_body_support(dh, only_roller); },
                          "y-translation", "the message names the free motion");
  }
  return testing::finish();
}
