// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The checks of the parameter values: ranges (naming the parameter and the
// value), the names of the function constants, the size estimate of a run
// and its limits (with the way around them, 'Allow large runs'), and the
// range of Young's modulus in ElasticMaterial itself.
#include <deal.II/base/parameter_handler.h>

#include <dealvem/app/input_parsing.h>
#include <dealvem/app/mesh_parameters.h>
#include <dealvem/contact/contact_assembler.h>
#include <dealvem/elasticity/material.h>

#include "../tests.h"

using namespace dealvem;

int
main()
{
  using namespace InputParsing;

  // ranges
  check_range(1e-12, 0, 1, "Solver/Relative tolerance", true, true);
  testing::check(true, "a value inside the range passes");
  testing::check_throws([] { check_range(1, 0, 1, "Solver/Relative tolerance", true, true); },
                        "Parameter 'Solver/Relative tolerance' = 1 is out of range: it must lie in (0, 1).",
                        "an open upper end excludes the end point");
  testing::check_throws([] { check_range(1e308, 0, 1e12, "Contact/Penalty"); },
                        "Parameter 'Contact/Penalty' = 1e+308 is out of range: it must lie in [0, 1e+12].",
                        "a closed range names the parameter, the value and the range");
  testing::check_throws([] { check_range(std::nan(""), 0, 1, "P"); }, "Parameter 'P' = nan",
                        "NaN is out of every range");

  // Young's modulus in the material
  testing::check_throws([] { ElasticMaterial m(1e-300, 0.3); }, "Young's modulus E = 1e-300 is outside",
                        "ElasticMaterial rejects E = 1e-300");
  testing::check_throws([] { ElasticMaterial m(1e308, 0.3); }, "Young's modulus E = 1e+308 is outside",
                        "ElasticMaterial rejects E = 1e308");
  testing::check(ElasticMaterial(1e-200, 0.3).mu() > 0 && std::isfinite(ElasticMaterial(1e200, 0.3).lambda()),
                 "E = 1e-200 and E = 1e200 are accepted");

  // function constants
  const std::string fc = "Boundary conditions and loads/Function constants";
  testing::check(parse_constants("a=1, b_2 = 2.5", fc).size() == 2, "good constants parse");
  testing::check_throws([&] { parse_constants("x=1", fc); },
                        "Parameter '" + fc + "': the name 'x' is reserved (a variable",
                        "the constant name x is rejected, naming the parameter");
  testing::check_throws([&] { parse_constants("1a=2", fc); }, "'1a' is not a valid constant name",
                        "the constant name 1a is rejected");
  testing::check_throws([&] { parse_constants("a=b", fc); }, "(a)': 'b' is not a finite real number",
                        "a constant value that is not a number is rejected");
  testing::check_throws([&] { parse_constants("sin=1", fc); }, "the name 'sin' is reserved",
                        "the constant name sin is rejected");
  testing::check_throws([&] { parse_constants("a=1, a=2", fc); }, "the constant 'a' is defined twice",
                        "a constant defined twice is rejected");
  testing::check_throws([] { ParsedFunction f({"foo(x)"}, {}, "Body force"); },
                        "Parameter 'Body force': cannot parse the expression(s) 'foo(x)'",
                        "an unknown function is reported naming the parameter");

  // the time t in an expression (a one-body run refuses it)
  testing::check(uses_variable("0, -5*t", "t") && uses_variable("exp(-t)+x", "t") && uses_variable("t", "t"),
                 "uses_variable finds t as a name of its own");
  testing::check(!uses_variable("tan(x) + 1e5 + .5e-3*y", "t") && !uses_variable("t2 + _t + sqrt(x)", "t") &&
                   !uses_variable("", "t"),
                 "uses_variable: not in other names or in numbers");

  // size estimates
  MeshParameters quads;
  quads.type = "structured quads";
  quads.nx   = 8;
  quads.ny   = 2;
  {
    const auto e = estimate_run_size({&quads}, 2, 2);
    // cycle 1: 16 x 4 quads, 17 x 5 vertices, 2*64 + 20 edges; k = 2: 594
    // DoFs, as tests/app/program.test.cmake's cantilever run reports
    testing::check(e.cells == 64 && e.dofs == 594, "quads: cells and DoFs of the last cycle");
  }
  MeshParameters voronoi;
  voronoi.type             = "voronoi";
  voronoi.n_cells          = 100;
  voronoi.lloyd_iterations = 10;
  {
    const auto e = estimate_run_size({&voronoi}, 3, 1);
    testing::check(e.voronoi_cells == 1600 && e.lloyd_work == 11 * (100 + 400 + 1600),
                   "voronoi: cells times 4^cycle, Lloyd work summed over cycles");
  }
  check_run_size({&quads, &voronoi}, 3, 2, false);
  testing::check(true, "a small run passes the size check");
  MeshParameters big = quads;
  big.nx = big.ny = 10000;
  testing::check_throws([&] { check_run_size({&big}, 1, 2, false); },
                        "This run is very large: more than 2e+07 DoFs;",
                        "10000 x 10000 quads are refused");
  testing::check_throws([&] { check_run_size({&big}, 1, 2, false); }, "set 'Allow large runs = true'",
                        "... naming the option to go ahead");
  check_run_size({&big}, 1, 2, true);
  testing::check(true, "... and accepted with 'Allow large runs'");
  MeshParameters huge = quads;
  huge.nx = huge.ny = 999999999;
  testing::check_throws([&] { check_run_size({&huge}, 1, 2, true); }, "more cells than the program can represent",
                        "a mesh beyond what can be represented is refused even with 'Allow large runs'");
  MeshParameters lloyd = voronoi;
  lloyd.lloyd_iterations = 200000;
  testing::check_throws([&] { check_run_size({&lloyd}, 1, 2, false); }, "more than 1e+05 Lloyd iterations",
                        "200000 Lloyd iterations are refused");
  MeshParameters slow = voronoi;
  slow.n_cells          = 1000000;
  slow.lloyd_iterations = 200;
  testing::check_throws([&] { check_run_size({&slow}, 1, 1, false); }, "Lloyd iterations x cells above 1e+08",
                        "1e6 cells with 200 Lloyd iterations are refused");
  MeshParameters many = voronoi;
  many.n_cells = 3000000;
  testing::check_throws([&] { check_run_size({&many}, 2, 1, false); }, "more than 1e+07 Voronoi cells",
                        "1.2e7 Voronoi cells are refused");
  // values in braces, which ParameterHandler leaves unchecked, and the
  // entries a file changed
  {
    const auto declare = [](dealii::ParameterHandler &prm) {
      prm.enter_subsection("Mesh");
      prm.declare_entry("Type", "voronoi", dealii::Patterns::Selection("structured quads|voronoi"));
      prm.declare_entry("File name", "", dealii::Patterns::Anything());
      prm.declare_entry("Perturbation", "0.2", dealii::Patterns::Double(0, 0.49));
      prm.leave_subsection();
      prm.enter_subsection("Body 1");
      prm.enter_subsection("Mesh");
      prm.declare_entry("Seed", "1", dealii::Patterns::Integer(0));
      prm.leave_subsection();
      prm.leave_subsection();
    };
    {
      dealii::ParameterHandler prm;
      declare(prm);
      prm.parse_input_from_string("subsection Mesh\n set File name = m-{cycle}.vtk\n"
                                  " set Perturbation = 0.3\nend\n");
      check_braced_values(prm);
      testing::check(true, "a file name with '{cycle}' (pattern Anything) passes the brace check");
      const auto changed = changed_entries(prm, "Mesh");
      testing::check(changed == std::vector<std::string>{"Mesh/File name", "Mesh/Perturbation"},
                     "changed_entries lists the two entries the input set");
      testing::check(changed_entries(prm, "Body 1").empty(), "... and none in a section it did not set");
    }
    {
      dealii::ParameterHandler prm;
      declare(prm);
      prm.parse_input_from_string("subsection Mesh\n set Type = {voronoi}\nend\n");
      testing::check_throws([&] { check_braced_values(prm); },
                            "Parameter 'Mesh/Type' = '{voronoi}' does not match its pattern [Selection",
                            "a selection in braces is refused, naming the entry");
    }
    {
      dealii::ParameterHandler prm;
      declare(prm);
      prm.parse_input_from_string("subsection Body 1\n subsection Mesh\n set Seed = {-3}\n end\nend\n");
      testing::check_throws([&] { check_braced_values(prm); },
                            "Parameter 'Body 1/Mesh/Seed' = '{-3}' does not match its pattern [Integer",
                            "an integer in braces in a nested section is refused, naming the path");
      testing::check(changed_entries(prm, "Body 1") == std::vector<std::string>{"Body 1/Mesh/Seed"},
                     "changed_entries finds an entry two sections deep");
    }
  }

  // the stick penalty relative to E_min / h_min: E_min = 1000, h_min = 0.1
  {
    NodeInsertion::Interface itf;
    itf.segments.push_back(ContactSegment{0, 1, dealii::numbers::invalid_unsigned_int, 0.1});
    itf.segments.push_back(ContactSegment{1, 2, dealii::numbers::invalid_unsigned_int, 0.25});
    const ContactScales scales({4000, 1000}, {itf});
    testing::check(std::abs(scales.penalty(ContactSettings()) - 1e7) < 1e-6,
                   "the default penalty is 1000 * E_min / h_min = 1e7");
    ContactSettings s;
    s.penalty = 1e-2; // 1e-6 * 1e4
    scales.check_penalty(s, "Contact/Penalty", "Contact/Penalty factor");
    s.penalty = 1e12; // 1e8 * 1e4
    scales.check_penalty(s, "Contact/Penalty", "Contact/Penalty factor");
    testing::check(true, "penalties at both ends of [1e-6, 1e8] * E_min / h_min pass");
    s.penalty = 1e-300;
    testing::check_throws([&] { scales.check_penalty(s, "Contact/Penalty", "Contact/Penalty factor"); },
                          "Parameter 'Contact/Penalty' = 1e-300 is out of range for this problem: the stick "
                          "penalty must lie in [0.01, 1e+12], that is 1e-06 to 1e+08 times E_min / h_min = 10000",
                          "a penalty of 1e-300 is refused, naming the parameter and the bounds");
    s.penalty = 1.01e12;
    testing::check_throws([&] { scales.check_penalty(s, "Contact/Penalty", "Contact/Penalty factor"); },
                          "Parameter 'Contact/Penalty' = 1.01e+12 is out of range",
                          "a penalty just above 1e8 * E_min / h_min is refused");
    s.penalty        = 0;
    s.penalty_factor = 1e-300;
    testing::check_throws([&] { scales.check_penalty(s, "Contact/Penalty", "Contact/Penalty factor"); },
                          "Parameter 'Contact/Penalty factor' = 1e-300 is out of range for this problem",
                          "the factor of the default rule is named when Penalty = 0");
  }
  return testing::finish();
}
