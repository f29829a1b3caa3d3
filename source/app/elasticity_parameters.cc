// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// ElasticityProblem: the parameter file (declaration and parsing).
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>

#include <dealvem/app/elasticity_problem.h>
#include <dealvem/app/input_parsing.h>
#include <dealvem/app/problem_setup.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/finite_strain_solver.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/force_balance.h>
#include <dealvem/postprocessing/error_norms.h>
#include <dealvem/postprocessing/finite_strain_output.h>
#include <dealvem/postprocessing/json_summary.h>
#include <dealvem/base/output_file.h>
#include <dealvem/base/run_files.h>
#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/postprocessing/vtu_output.h>
#include <dealvem/solvers/linear_solver.h>
#include <dealvem/solvers/p_multigrid.h>
#include <dealvem/solvers/parallel_solver.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/vem_values.h>
#include <dealvem/vem/virtual_element.h>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace dealvem
{
  void
  ElasticityProblem::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    prm.declare_entry("Allow large runs", "false", Bool(),
                      "Before a run starts, its size is estimated from the mesh parameters and the "
                      "refinement cycles; runs estimated above 2e7 DoFs, 1e7 Voronoi cells, 1e5 Lloyd "
                      "iterations or 1e8 Lloyd iterations x cells (summed over the cycles) are refused unless this is true. "
                      "Mesh files enter with the counts in their header (read before the file). So are "
                      "runs whose estimated memory with the chosen solver exceeds 'Memory limit'.");
    prm.declare_entry("Memory limit", "0", Double(0),
                      "Memory (GB) a run may use, for the size check before the run; 0: 80 % of the "
                      "smallest of the physical memory, the process limits (ulimit -v, -d) and the "
                      "control group's limit.");
    prm.enter_subsection("Mesh");
    MeshParameters::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Material");
    prm.declare_entry("Young's modulus", "1000", Double(0), "Young's modulus E, 1e-200 <= E <= 1e200.");
    prm.declare_entry("Poisson's ratio", "0.3", Double(-0.999, 0.499),
                      "Poisson's ratio nu, -1 < nu < 0.5.");
    prm.declare_entry("Model", "plane strain", Selection("plane strain|plane stress"),
                      "2D model of the material.");
    prm.declare_entry("Law", "linear", Anything(), MaterialLaws::law_documentation());
    prm.leave_subsection();

    prm.enter_subsection("Discretization");
    prm.declare_entry("Order", "2", Integer(1, VirtualElement<2>::max_degree()),
                      "Order k of the virtual elements (1 to " + std::to_string(VirtualElement<2>::max_degree()) + ").");
    prm.declare_entry("Stabilization", "automatic", Selection("automatic|diagonal|trace|boundary"),
                      "Stabilization of the element stiffness: 'automatic' (trace for k = 1, diagonal "
                      "for k = 2; trace for both at finite strain, where the diagonal rule is too weak), "
                      "'diagonal' (the D-recipe, "
                      "gamma c_k (I-Pi)^T diag(max(K_c,aa, 1e-3 tau)) (I-Pi), c_1 = 1, c_2 = 1/5, K_c,aa half "
                      "the trace of node a's 2 x 2 block of the consistency stiffness, for both components: "
                      "every node stabilized like its own consistency stiffness, in any orientation), 'trace' "
                      "(dofi-dofi, gamma tau (I-Pi)^T (I-Pi), tau = trace(K_c)/n_dofs) or 'boundary' "
                      "(gamma tau (I-Pi)^T S (I-Pi), S the tangential derivatives along the edges, each "
                      "edge weighted by the mean edge length over its own: robust to short edges; the "
                      "default of finite sliding, whose node insertion makes them).");
    prm.declare_entry("Stabilization factor", "1.0", Double(1e-8),
                      "Factor gamma of the stabilization; 1e-6 <= gamma <= 1e6.");
    prm.leave_subsection();

    BoundaryConditionParameters::declare_parameters(prm);

    prm.enter_subsection("Exact solution");
    prm.declare_entry("Displacement", "", Anything(),
                      "Exact displacement 'ux, uy' (muparser expressions in x, y and t with "
                      "the function constants; one body: t = 1; contact problems: the time of the "
                      "last load step, 'Load steps/Final time'). Empty: no error computation.");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    prm.declare_entry("Type", "automatic",
                      Selection("automatic|UMFPACK|KLU|CG-AMG|direct constraints|GMRES-AMG|CG-AMG constraints"),
                      "Each name is one algorithm, in one process and under mpirun alike. "
                      "automatic: the choice and its reason are printed; one body: UMFPACK up to 1e4 DoFs "
                      "(where it fits into 'Memory limit'), CG-AMG above; contact: direct constraints up "
                      "to 1.2e5 DoFs, CG-AMG above (with or without Coulomb friction); the crossovers are "
                      "measured in doc/benchmarks.md. "
                      "UMFPACK / KLU: a direct LU factorization (SuiteSparse / Trilinos Amesos) of the "
                      "stiffness, with contact of the whole saddle-point matrix (one process only). "
                      "CG-AMG: deal.II's SolverCG preconditioned by Trilinos ML algebraic multigrid with "
                      "the rigid-body modes as near-null space (for k = 2 by default a two-level "
                      "p-multigrid: Chebyshev smoothing on k = 2, ML AMG on the Galerkin k = 1 level); with "
                      "contact on the stiffness condensed by the active contact constraints (each becomes "
                      "an affine constraint on one slave DoF, multipliers recovered from the residual); "
                      "'CG-AMG constraints' is its former name. direct constraints: the same condensed "
                      "stiffness factored directly (CHOLMOD's Cholesky in one process, a fresh ordering "
                      "per active set; Amesos KLU under mpirun); one body: UMFPACK. GMRES-AMG: contact "
                      "only, GMRES on the whole saddle point with a block preconditioner (AMG on the "
                      "displacement block, exact approximate Schur complement), one process only; one "
                      "body: CG-AMG. With Coulomb friction, slipping pairs make the condensed matrix "
                      "non-symmetric (Petrov-Galerkin condensation): CG-AMG then runs GMRES, direct "
                      "constraints UMFPACK's LU (Amesos KLU under mpirun).");
    prm.declare_entry("Warm start", "true", Bool(),
                      "Contact, CG-AMG: start each Krylov solve from the displacements of the previous one "
                      "(active-set or Newton iteration, load step) instead of from zero.");
    prm.declare_entry("Preconditioner", "automatic", Selection("automatic|AMG|p-multigrid"),
                      "Preconditioner of CG for one body and of CG-AMG on the condensed contact stiffness "
                      "(serial and distributed, with the stick springs of a penalty tied): automatic (the "
                      "p-multigrid for k = 2, ML AMG for k = 1), AMG (one ML V-cycle on the whole "
                      "matrix) or p-multigrid (k = 2 only).");
    prm.declare_entry("Relative tolerance", "1e-12", Double(1e-16, 1),
                      "Relative residual tolerance of the iterative solver, 0 < tolerance < 1.");
    prm.declare_entry("Maximum iterations", "10000", Integer(1), "Iteration limit of the iterative solver.");
    prm.leave_subsection();

    prm.enter_subsection("Convergence study");
    prm.declare_entry("Refinement cycles", "1", Integer(1, 8),
                      "Number of meshes: each cycle doubles the subdivisions (four times the "
                      "Voronoi cells). With an exact solution a convergence table is printed.");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Folder", "output", Anything(),
                      "Output folder (relative to the working directory, not empty), created if "
                      "needed.");
    prm.declare_entry("Base name", "solution", Anything(),
                      "Base name of the output files (not empty, no '/'). With several refinement "
                      "cycles the files of cycle c are <base name>-cycle<c>.*.");
    prm.declare_entry("Write VTU", "true", Bool(),
                      "Write <base name>.vtu (one cycle) or <base name>-cycle<c>.vtu for ParaView.");
    prm.declare_entry("Write JSON", "true", Bool(),
                      "Write the summary <base name>.json (one body: all cycles in one file, "
                      "rewritten after each cycle).");
    prm.leave_subsection();

    FiniteStrainParameters::declare_parameters(prm);
    DesignParameters::declare_parameters(prm);
  }



  void
  ElasticityProblem::parse_parameters(dealii::ParameterHandler &prm, const std::string &dir)
  {
    prm_directory = dir;
    check_contact_sections(prm);
    parse_load_steps(prm);

    parse_mesh_and_material(prm, dir);

    prm.enter_subsection("Discretization");
    degree = prm.get_integer("Order");
    gamma  = prm.get_double("Stabilization factor");
    stabilization = InputParsing::parse_stabilization(prm.get("Stabilization"));
    prm.leave_subsection();
    InputParsing::check_range(gamma, 1e-6, 1e6, "Discretization/Stabilization factor");

    bc.parse_parameters(prm);
    design.parse_parameters(prm);
    AssertThrow(!design.enabled() || !finite_strain.enabled,
                dealii::ExcMessage("Design/Objective = " + design.objective +
                                   ": topology optimization is implemented for small strain; set "
                                   "'Finite strain/Enabled = false'."));

    prm.enter_subsection("Exact solution");
    exact_displacement = prm.get("Displacement");
    prm.leave_subsection();
    // an expression in t: at finite strain the steps solve at their times;
    // the linear problem is solved at t = Final time (and its exact
    // solution compared there)
    bc.set_time(final_time);

    if (finite_strain.enabled)
      for (const auto &e : InputParsing::changed_entries(prm, "Solver"))
        pcout << "warning: the parameter file sets '" << e
              << "', but with 'Finite strain/Enabled = true' every Newton update is solved by UMFPACK; "
                 "the setting has no effect."
              << std::endl;
    prm.enter_subsection("Solver");
    solver_type           = prm.get("Type");
    if (solver_type == "GMRES-AMG" || solver_type == "CG-AMG constraints")
      solver_type = "CG-AMG";
    if (solver_type == "direct constraints")
      solver_type = "UMFPACK";
    solver_tolerance      = prm.get_double("Relative tolerance");
    solver_max_iterations = prm.get_integer("Maximum iterations");
    solver_preconditioner = prm.get("Preconditioner");
    AssertThrow(solver_preconditioner != "p-multigrid" || PMultigrid::applies_to(VEMElementData(degree)),
                dealii::ExcMessage("Solver/Preconditioner = p-multigrid needs Discretization/Order = 2 (the "
                                   "coarse level is the order-1 space on the same polygons)."));
    prm.leave_subsection();
    InputParsing::check_range(solver_tolerance, 0, 1, "Solver/Relative tolerance", true, true);

    prm.enter_subsection("Convergence study");
    n_cycles = prm.get_integer("Refinement cycles");
    prm.leave_subsection();
    memory_limit_GB = prm.get_double("Memory limit");
    const auto size = InputParsing::check_run_size({&mesh_parameters}, n_cycles, degree, prm.get_bool("Allow large runs"),
                                 prm_directory,
                                 solver_type == "automatic" ? InputParsing::SolverKind::automatic :
                                 solver_type == "CG-AMG"    ? InputParsing::SolverKind::iterative :
                                                              InputParsing::SolverKind::direct,
                                 memory_limit_GB);
    // a direct solver asked for far above the crossover: it fits, but slowly
    if ((solver_type == "UMFPACK" || solver_type == "KLU") && size.dofs > 1e6)
      pcout << "warning: 'Solver/Type = " << solver_type << "' with about " << std::setprecision(3) << size.dofs
            << " DoFs in the last cycle: the factorization takes minutes (UMFPACK is 4.5x slower than CG at "
               "2e5 DoFs already, doc/benchmarks.md); 'Solver/Type = automatic' or 'CG-AMG' would be faster."
            << std::setprecision(6) << std::endl;

    prm.enter_subsection("Output");
    output_folder = prm.get("Folder");
    base_name     = prm.get("Base name");
    write_vtu     = prm.get_bool("Write VTU");
    write_json    = prm.get_bool("Write JSON");
    prm.leave_subsection();
    check_output_names(output_folder, base_name);
  }



  // The sections that only contact problems (Number of bodies > 1) read: a
  // file that sets them describes another problem than this one.
  void
  ElasticityProblem::check_contact_sections(dealii::ParameterHandler &prm) const
  {
    {
      // (the sections with a changed entry, from one listing)
      std::set<std::string> body_sections;
      for (const auto &path : InputParsing::changed_entries(prm, ""))
        if (path.compare(0, 5, "Body ") == 0)
          body_sections.insert(path.substr(0, path.find('/')));
      for (const auto &section : body_sections)
        InputParsing::check_section_unused(prm, section,
                                           "'Number of bodies' is 1: section '" + section +
                                             "' is read only with 'Number of bodies' at least " +
                                             std::to_string(std::stoi(section.substr(5)) + 1) + ".");
    }
    InputParsing::check_section_unused(prm, "Contact",
                                       "'Number of bodies' is 1, and contact needs at least two bodies.");
  }



  // 'Finite strain' and 'Load steps' (the steps as contact problems read
  // them), with the notes and warnings on entries this problem does not
  // use.
  void
  ElasticityProblem::parse_load_steps(dealii::ParameterHandler &prm)
  {
    finite_strain.parse_parameters(prm);
    // the load steps, as contact problems read them: step n of N at the
    // time t = n * Final time / N of the expressions. At finite strain the
    // Newton solve runs them (solve_finite_strain()); the linear static
    // problem is solved once, at t = Final time
    // (a ParameterHandler without the section, declared by
    // ContactProblem::declare_parameters() as the program does, means one
    // step to t = 1; finite strain needs it)
    AssertThrow(!finite_strain.enabled || prm.subsection_path_exists({"Load steps"}),
                dealii::ExcMessage("Parameter 'Finite strain/Enabled' is true, but the section 'Load steps' "
                                   "(its number of load steps) is not declared: call "
                                   "ContactProblem::declare_parameters() on the ParameterHandler too, as "
                                   "the program does."));
    n_load_steps = 1;
    final_time   = 1;
    if (prm.subsection_path_exists({"Load steps"}))
      {
        prm.enter_subsection("Load steps");
        const long steps = prm.get_integer("Number of steps");
        final_time       = prm.get_double("Final time");
        prm.leave_subsection();
        InputParsing::check_number_of_load_steps(steps);
        n_load_steps = steps;
        InputParsing::check_range(final_time, 0, 1e300, "Load steps/Final time", true, false,
                                  "It is the time t of the last load step.");
      }
    if (finite_strain.enabled)
      {
        AssertThrow(!distributed,
                    dealii::ExcMessage("Parameter 'Finite strain/Enabled' is true, but the run has " +
                                       std::to_string(n_processes) +
                                       " MPI processes: the finite-strain solve runs in one process (run "
                                       "the program without mpirun)."));
      }
    else
      {
        InputParsing::check_section_unused(prm, "Finite strain",
                                           "'Finite strain/Enabled' is false: the Newton controls, the "
                                           "pressure load and the monitor point are read only at finite "
                                           "strain.");
        if (n_load_steps > 1)
          pcout << "note: 'Load steps/Number of steps' is " << n_load_steps
                << ": the one-body problem at small strain is linear and static, and its solution at t = "
                   "'Final time' does not depend on the steps before; the program solves it once, with every "
                   "expression at t = "
                << final_time << "." << std::endl;
      }
    for (const auto &e : InputParsing::changed_entries(prm, "Output"))
      if (e == "Output/Write pictures" || e == "Output/Write CSV")
        pcout << "warning: the parameter file sets '" << e
              << "', which only contact problems read; it has no effect on this one-body problem." << std::endl;

  }



  // 'Mesh' (with the physical names of a gmsh file) and 'Material'.
  void
  ElasticityProblem::parse_mesh_and_material(dealii::ParameterHandler &prm, const std::string &dir)
  {
    prm.enter_subsection("Mesh");
    mesh_parameters.parse_parameters(prm, "Mesh");
    prm.leave_subsection();
    // the physical names of a gmsh file name ids in the other sections
    mesh_parameters.load_physical_names(dir);
    bc.set_physical_names(mesh_parameters.physical_names);
    AssertThrow(!mesh_parameters.parts_as_bodies,
                dealii::ExcMessage("Parameter 'Mesh/Parts as bodies' is true: the parts of the mesh file are "
                                   "bodies in contact, which ContactProblem solves (the program does so)."));
    for (const auto &e : InputParsing::changed_entries(prm, "Material"))
      AssertThrow(e != "Material/Part materials",
                  dealii::ExcMessage("Parameter 'Material/Part materials' is set, but it is read only with "
                                     "'Mesh/Parts as bodies = true' (a contact problem)."));

    prm.enter_subsection("Material");
    youngs_modulus = prm.get_double("Young's modulus");
    poissons_ratio = prm.get_double("Poisson's ratio");
    model          = ElasticMaterial::parse_model(prm.get("Model"));
    law            = MaterialLaws::parse(prm.get("Law"), "Material/Law");
    prm.leave_subsection();
    InputParsing::check_range(youngs_modulus, ElasticMaterial::min_youngs_modulus,
                              ElasticMaterial::max_youngs_modulus, "Material/Young's modulus", false,
                              false, "Choose units that bring E nearer to 1.");
    AssertThrow(!finite_strain.enabled || MaterialLaws::is_hyperelastic(law),
                dealii::ExcMessage("Parameter 'Finite strain/Enabled' is true, but 'Material/Law' is 'linear': "
                                   "the linear law has no finite-strain response. Set 'Material/Law' to "
                                   "'neo-hooke' or 'saint venant-kirchhoff', or 'Finite strain/Enabled' to "
                                   "false."));
    // validates E and nu
    (void)MaterialLaws::make_law(law, youngs_modulus, poissons_ratio, model);
    if (MaterialLaws::is_hyperelastic(law) && !finite_strain.enabled)
      pcout << "note: 'Material/Law = " << MaterialLaws::name(law)
            << "' at small strain ('Finite strain/Enabled = false'): the program solves linear elasticity with "
               "the law's linearization at F = I, the linear law of the same E and nu. Set 'Finite "
               "strain/Enabled = true' for the hyperelastic response."
            << std::endl;

  }
} // namespace dealvem
