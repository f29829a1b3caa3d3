// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The section "Boundary conditions and loads" (BoundaryConditionParameters)
// on the block [0,1]^2 (structured quads, ids 0 left, 1 right, 2 bottom,
// 3 top):
// - every kind of entry on a boundary id the mesh lacks stops with a
//   message naming the entry, the id and the ids of the mesh;
// - t = 1 in the expressions: 'Traction = 3 : 0, -10*t' gives the same
//   solution as '3 : 0, -10' (difference 0 up to 1e-14), likewise for the
//   rigid resultant; ParsedFunction follows set_time(), and so do the loads
//   and Dirichlet values of the section (Traction 10*t at t = 2, Dirichlet
//   0.01*t at t = 0.5, Pressure p*t) while expressions without t stay put;
//   pi and Pi are known, a constant of that name is refused, constants reach
//   the parser to the last bit;
// - expressions that are not finite where they are evaluated stop with the
//   parameter, the expression and the point;
// - a point constraint or rigid boundary colliding with an earlier entry
//   names both entries; a redundant point constraint is accepted;
// - a rigid boundary with 'id : Fx, Fy : M' through the parameters: the
//   top under a moment turns rigidly.
#include <deal.II/base/parameter_handler.h>

#include <dealvem/app/problem_setup.h>

#include "../elasticity_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
  const std::string section = "Boundary conditions and loads";

  std::unique_ptr<BoundaryConditionParameters>
  parse(const std::string &entries)
  {
    dealii::ParameterHandler prm;
    BoundaryConditionParameters::declare_parameters(prm);
    prm.parse_input_from_string("subsection " + section + "\n" + entries + "\nend\n");
    auto bc = std::make_unique<BoundaryConditionParameters>();
    bc->parse_parameters(prm);
    return bc;
  }

  // Solve the block problem given by the entries at the time t, k = 2.
  dealii::Vector<double>
  solve(const std::string &entries, const VEMDoFHandler<2> &dh, const double t = 1)
  {
    const auto bc = parse(entries);
    if (t != 1)
      bc->set_time(t);
    bc->check_boundary_ids(dh.get_mesh());
    dealii::AffineConstraints<double> cons;
    bc->apply_constraints(dh, cons);
    cons.close();
    BoundaryConditions::check_rigid_body_support(dh, cons);
    const std::map<dealii::types::material_id, ElasticMaterial> materials = {
      {0, ElasticMaterial(1000, 0.25, ElasticMaterial::Model::plane_stress)}};
    ElasticityAssembler<2> assembler(dh, materials);
    bc->add_loads(assembler);
    dealii::DynamicSparsityPattern dsp(dh.n_dofs());
    dh.make_sparsity_pattern(dsp, cons);
    dealii::SparsityPattern sp;
    sp.copy_from(dsp);
    dealii::SparseMatrix<double> A(sp);
    dealii::Vector<double>       b, u(dh.n_dofs());
    assembler.assemble(cons, A, b);
    dealii::SparseDirectUMFPACK direct;
    direct.initialize(A);
    direct.vmult(u, b);
    cons.distribute(u);
    return u;
  }

  double
  relative_difference(const dealii::Vector<double> &a, const dealii::Vector<double> &b)
  {
    dealii::Vector<double> d = a;
    d -= b;
    return d.linfty_norm() / a.linfty_norm();
  }
} // namespace

int
main()
{
  PolygonalMesh<2> mesh;
  testing::make_mesh(mesh, "structured quads", 0);
  VEMDoFHandler<2> dh(mesh);
  dh.distribute_dofs(2);
  const std::string fixed_bottom = "set Dirichlet = 2 : xy : 0, 0\n";

  // 1. boundary ids the mesh does not have
  for (const auto &[parameter, value, entry] :
       std::vector<std::array<std::string, 3>>{{{"Dirichlet", "13 : xy : 0, 0", "Dirichlet entry '13 : xy : 0, 0'"}},
                                               {{"Roller", "2, 13", "Roller entry '13'"}},
                                               {{"Traction", "13 : 0, 1", "Traction entry '13 : 0, 1'"}},
                                               {{"Pressure", "13 : p", "Pressure entry '13 : p'"}},
                                               {{"Rigid boundary", "13 : 0, 1 : 2", "Rigid boundary entry '13 : 0, 1 : 2'"}}})
    {
      const auto bc = parse("set Function constants = p=1\nset " + parameter + " = " + value + "\n");
      testing::check_throws([&] { bc->check_boundary_ids(mesh); },
                            "Parameter '" + section + "/" + entry + "': no boundary edge of mesh",
                            parameter + " on a missing id: the message names the entry");
      testing::check_throws([&] { bc->check_boundary_ids(mesh); },
                            "has boundary id 13; the boundary ids of the mesh are 0, 1, 2, 3.",
                            parameter + " on a missing id: the message names the id and the mesh's ids");
      dealii::AffineConstraints<double> cons;
      testing::check_throws([&] { bc->apply_constraints(dh, cons); }, "has boundary id 13",
                            parameter + " on a missing id: apply_constraints checks as well");
    }

  // 4. t = 1
  {
    const auto a = solve(fixed_bottom + "set Traction = 3 : 0, -10*t", dh);
    const auto b = solve(fixed_bottom + "set Traction = 3 : 0, -10", dh);
    testing::check_small(relative_difference(a, b), 1e-14, "Traction 0, -10*t equals 0, -10");
    const auto c = solve(fixed_bottom + "set Rigid boundary = 3 : 0, -10*t : 2*t", dh);
    const auto d = solve(fixed_bottom + "set Rigid boundary = 3 : 0, -10 : 2", dh);
    testing::check_small(relative_difference(c, d), 1e-14, "Rigid boundary 0, -10*t : 2*t equals 0, -10 : 2");
    InputParsing::ParsedFunction f({"x + 2*t"}, {}, "test");
    testing::check_near(f.value(dealii::Point<2>(0.5, 0)), 2.5, 1e-15, "x + 2*t at x = 0.5 (t = 1)");
    f.set_time(3);
    testing::check_near(f.value(dealii::Point<2>(0.5, 0)), 6.5, 1e-15, "x + 2*t at x = 0.5 after set_time(3)");
    testing::check_near(f.gradient(dealii::Point<2>(0.5, 0))[0], 1., 1e-8, "its x-derivative");
  }

  // 4b. t through set_time(), as load steps use it: the loads are linear
  // in the expressions' values, so 'Traction = 3 : 0, -10*t' at t = 2 gives
  // the solution of '3 : 0, -20', a Dirichlet value 0.01*t at t = 0.5 the
  // one of 0.005, and a constant times t the constant's product (to 1e-14
  // relative: two solves of the same matrix). Expressions without t (the
  // spelling before load steps) do not change with t.
  {
    const std::string top = "set Dirichlet = 2 : xy : 0, 0; 3 : y : ";
    testing::check_small(relative_difference(solve(fixed_bottom + "set Traction = 3 : 0, -10*t", dh, 2),
                                             solve(fixed_bottom + "set Traction = 3 : 0, -20", dh)),
                         1e-14, "Traction 0, -10*t at t = 2 equals 0, -20");
    testing::check_small(relative_difference(solve(top + "0.01*t", dh, 0.5), solve(top + "0.005", dh)), 1e-14,
                         "Dirichlet 0.01*t at t = 0.5 equals 0.005");
    testing::check_small(relative_difference(solve("set Function constants = p=10\n" + fixed_bottom +
                                                     "set Pressure = 3 : p*t",
                                                   dh, 0.25),
                                             solve(fixed_bottom + "set Pressure = 3 : 2.5", dh)),
                         1e-14, "Pressure p*t with p = 10 at t = 0.25 equals 2.5");
    testing::check_small(relative_difference(solve(fixed_bottom + "set Traction = 3 : 0, -10", dh, 7),
                                             solve(fixed_bottom + "set Traction = 3 : 0, -10", dh)),
                         0, "Traction 0, -10 (no t) is the same at t = 7 and t = 1");
    // the constants of Functions::ParsedFunction, and user constants
    // that would shadow them are refused
    // (muparser's own _pi carries about 13 digits only: 8e-13 below pi)
    InputParsing::ParsedFunction g({"pi + 0*t", "Pi", "_pi"}, {}, "test");
    testing::check(g.value(dealii::Point<2>(0, 0), 0) == M_PI && g.value(dealii::Point<2>(0, 0), 1) == M_PI,
                   "pi and Pi are pi to the last bit");
    testing::check_near(g.value(dealii::Point<2>(0, 0), 2), M_PI, 1e-12, "_pi is pi to 1e-12");
    testing::check_throws([] { InputParsing::parse_constants("pi=3", "Function constants"); },
                          "the name 'pi' is reserved", "a constant named pi is refused");
    InputParsing::ParsedFunction h({"a*t", "b + y*t"}, {{"a", 0.1}, {"b", 1. / 3}}, "test");
    h.set_time(4);
    dealii::Vector<double> v(2);
    h.vector_value(dealii::Point<2>(0, 2), v);
    testing::check(v[0] == 0.1 * 4 && v[1] == 1. / 3 + 8,
                   "constants reach the parser exactly: a*t = 0.4 and b + y*t = 1/3 + 8 at t = 4");
  }

  // 5. values that are not finite
  for (const auto &[entries, fragment] : std::vector<std::pair<std::string, std::string>>{
         {"set Traction = 1 : sqrt(x-2), 0",
          "Parameter '" + section + "/Traction entry '1 : sqrt(x-2), 0'': the expression 'sqrt(x-2)' evaluates to nan at the point (1, "},
         {"set Pressure = 1 : sqrt(-1)", "the expression 'sqrt(-1)' evaluates to"},
         {"set Body force = 0, 1/(x-x)", "Body force': the expression '1/(x-x)' evaluates to"},
         {"set Dirichlet = 2 : xy : 0, 0; 0 : x : sqrt(y-0.5)", "Dirichlet entry '0 : x : sqrt(y-0.5)'': the expression 'sqrt(y-0.5)' evaluates to"},
         {"set Rigid boundary = 3 : 1/(x-0.5), 0", "the expression '1/(x-0.5)' evaluates to inf at the point (0.5, 1), t = 1."},
         {"set Rigid boundary = 3 : 0, 0 : ln(x-0.5)", "the expression 'ln(x-0.5)' evaluates to -inf at the point (0.5, 1)"},
         {"set Point constraints = 1, 0 : y : 1/(x-1)", "Point constraints entry '1, 0 : y : 1/(x-1)'': the expression '1/(x-1)' evaluates to inf at the point (1, 0)"}})
    testing::check_throws([&] { solve(fixed_bottom + entries, dh); }, fragment,
                          "not finite: " + entries);
  testing::check_throws([&] { parse("set Traction = 1 : 0, q*x"); }, "cannot parse the expression(s) '0, q*x'",
                        "an unknown name is a parse error naming the expressions");

  // 2. point constraints next to other entries
  {
    const std::string load = "set Traction = 3 : 1, 0\n";
    const auto a = solve(fixed_bottom + load + "set Point constraints = 0.5, 0 : y : 0", dh);
    const auto b = solve(fixed_bottom + load, dh);
    testing::check_small(relative_difference(a, b), 0, "a redundant point constraint changes nothing");
    const std::string roller = "set Roller = 2\nset Point constraints = 0, 0 : x : 0; 0.5, 0 : y : 0.1\n";
    testing::check_throws([&] { solve(roller, dh); },
                          "Point constraint at (0.5 0) (parameter '" + section +
                            "/Point constraints entry '0.5, 0 : y : 0.1'')",
                          "a conflicting point constraint names its entry");
    testing::check_throws([&] { solve(roller, dh); },
                          "already constrained by " + section + "/Roller entry '2' to the value 0",
                          "... and the roller entry");
    testing::check_throws([&] { solve(fixed_bottom + "set Point constraints = 0.5, 0 : z : 0", dh); },
                          "component 'z' must be x or y", "a bad component");
    testing::check_throws([&] { solve(fixed_bottom + "set Point constraints = 0.5, 0 : x : 0 : 1 : 2", dh); },
                          "expected 'x, y : component : value' or 'x, y : component : value : body'",
                          "too many fields");
    const auto c = solve(fixed_bottom + "set Traction = 3 : 1, 0\nset Point constraints = 0.5, 0 : y : 0 : 0", dh);
    const auto d = solve(fixed_bottom + "set Traction = 3 : 1, 0", dh);
    testing::check_small(relative_difference(c, d), 0, "a point constraint naming body 0");
  }

  // 3. rigid boundary through the parameters
  {
    testing::check_throws([&] { solve("set Dirichlet = 0 : xy : 0, 0\nset Rigid boundary = 3 : 0, -1", dh); },
                          "Parameter '" + section + "/Rigid boundary entry '3 : 0, -1'' on mesh",
                          "a rigid part sharing a Dirichlet node names its entry");
    testing::check_throws([&] { solve("set Dirichlet = 0 : xy : 0, 0\nset Rigid boundary = 3 : 0, -1", dh); },
                          "already constrained by " + section + "/Dirichlet entry '0 : xy : 0, 0'",
                          "... and the Dirichlet entry");
    testing::check_throws([&] { parse("set Rigid boundary = 3 : 0, -1; 3 : 1, 1"); }, "is rigid already",
                          "the same id twice");
    testing::check_throws([&] { parse("set Rigid boundary = 3 : 0"); }, "expected two expressions Fx, Fy",
                          "a rigid resultant with one component");
    const auto u    = solve(fixed_bottom + "set Function constants = M=0.5\nset Rigid boundary = 3 : 0, 0 : M", dh);
    const auto part = BoundaryConditions::rigid_boundary_geometry(dh, 3);
    double     err = 0, size = 0;
    auto       U   = [&](const unsigned int n, const unsigned int c) { return u[VEMDoFHandler<2>::node_dof(n, c)]; };
    const double theta = (U(part.node_b, 1) - U(part.node_a, 1)) / (part.point_b[0] - part.point_a[0]);
    for (const auto n : part.nodes)
      {
        const auto x = dh.node_location(n) - part.point_a;
        err  = std::max({err, std::abs(U(n, 0) - U(part.node_a, 0) + theta * x[1]),
                         std::abs(U(n, 1) - U(part.node_a, 1) - theta * x[0])});
        size = std::max({size, std::abs(U(n, 0)), std::abs(U(n, 1))});
      }
    testing::check(theta > 0, "the moment turns the top counter-clockwise");
    testing::check_small(err / size, 1e-12, "the top turns rigidly (parameters 'id : Fx, Fy : M')");
  }
  return testing::finish();
}
