// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
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
  ElasticityProblem::ElasticityProblem(const MPI_Comm comm, const Parallelism parallelism)
    : mpi_communicator(comm)
    , this_process(dealii::Utilities::MPI::this_mpi_process(comm))
    , n_processes(dealii::Utilities::MPI::n_mpi_processes(comm))
    , pcout(std::cout, this_process == 0)
  {
    distributed = parallelism == Parallelism::distributed ||
                  (parallelism == Parallelism::automatic && n_processes > 1);
  }



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
    prm.declare_entry("Law", "linear", Anything(), MaterialLaws::law_documentation);
    prm.leave_subsection();

    prm.enter_subsection("Discretization");
    prm.declare_entry("Order", "2", Integer(1, 2), "Order k of the virtual elements (1 or 2).");
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
                      "Preconditioner of CG for one body (serial and distributed): automatic (the "
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
  }



  void
  ElasticityProblem::parse_parameters(dealii::ParameterHandler &prm, const std::string &dir)
  {
    prm_directory = dir;
    // the sections that only contact problems (Number of bodies > 1) read:
    // a file that sets them describes another problem than this one
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
        AssertThrow(steps >= 1 && steps <= 100000,
                    dealii::ExcMessage("Parameter 'Load steps/Number of steps' is " + std::to_string(steps) +
                                       ": it must be at least 1 (and at most 100000)."));
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

    prm.enter_subsection("Discretization");
    degree = prm.get_integer("Order");
    gamma  = prm.get_double("Stabilization factor");
    stabilization = (prm.get("Stabilization") == "trace"    ? Stabilization::trace :
                     prm.get("Stabilization") == "diagonal" ? Stabilization::diagonal :
                     prm.get("Stabilization") == "boundary" ? Stabilization::boundary :
                                                              Stabilization::automatic);
    prm.leave_subsection();
    InputParsing::check_range(gamma, 1e-6, 1e6, "Discretization/Stabilization factor");

    bc.parse_parameters(prm);

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
    AssertThrow(solver_preconditioner != "p-multigrid" || degree == 2,
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



  // One cycle: the mesh of the cycle; its cells must carry the material id
  // the parameter file defines, its boundary the ids the conditions name.
  void
  ElasticityProblem::make_mesh(const unsigned int cycle)
  {
    dealii::TimerOutput::Scope t(*timer, "mesh");
    mesh.clear();
    mesh_parameters.create_mesh(mesh, cycle, prm_directory);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      if (materials.count(mesh.cell(c).material_id) == 0)
        {
          // the ids the mesh has (with their physical names) and the one
          // the parameter file expects, and how to make them agree
          const auto named = [&](const unsigned int id) {
            std::string s = std::to_string(id);
            for (const auto &[n, i] : mesh_parameters.physical_names.material_ids)
              if (i == id)
                s += " ('" + n + "')";
            return s;
          };
          std::string have;
          for (const auto id : mesh.get_material_ids())
            have += (have.empty() ? "" : ", ") + named(id);
          const bool file = mesh_parameters.type.find("file") != std::string::npos;
          AssertThrow(false,
                      dealii::ExcMessage(
                        "Cell " + std::to_string(c) + " of mesh '" + mesh.name + "' has material id " +
                        named(mesh.cell(c).material_id) + ", but the parameter file defines a material for id " +
                        named(mesh_parameters.material_id) + " only ('Mesh/Material id'). The material ids of the " +
                        "mesh are " + have + "." +
                        (file ? " Set 'Mesh/Material id' to the id (or the physical name) of the mesh's cells; "
                                "a one-body problem has one material id, so a file with several must be read "
                                "as a contact problem with 'Mesh/Parts as bodies = true', or its physical "
                                "surfaces merged into one." :
                                "")));
        }
    bc.check_boundary_ids(mesh);
    if (distributed && n_processes > 1)
      {
        // every process built the mesh itself: check that they agree
        // (a generator that depended on the process would give a wrong
        // partition and assembly without any other error)
        double sum = 0;
        for (const auto &v : mesh.get_vertices())
          sum += v[0] + 1.61803398875 * v[1];
        const std::vector<double> key = {double(mesh.n_cells()), double(mesh.n_vertices()), sum};
        std::vector<double>       lo(3), hi(3);
        int ierr = MPI_Allreduce(key.data(), lo.data(), 3, MPI_DOUBLE, MPI_MIN, mpi_communicator);
        AssertThrowMPI(ierr);
        ierr = MPI_Allreduce(key.data(), hi.data(), 3, MPI_DOUBLE, MPI_MAX, mpi_communicator);
        AssertThrowMPI(ierr);
        AssertThrow(lo == hi, dealii::ExcMessage("The MPI processes built different meshes for '" + mesh.name +
                                                 "' (cells, vertices or coordinates differ); the replicated "
                                                 "mesh must be the same on every process."));
      }
  }



  // DoFs, the constraints of the Dirichlet, roller and point conditions
  // (checked to hold the body), and the sparsity pattern with the
  // constraints' entries, as in step-8.
  void
  ElasticityProblem::setup_system()
  {
    dealii::TimerOutput::Scope t(*timer, "setup");
    dof_handler.reinit(mesh);
    dof_handler.distribute_dofs(degree);
    constraints.clear();
    bc.apply_constraints(dof_handler, constraints);
    constraints.close();
    BoundaryConditions::check_rigid_body_support(dof_handler, constraints);
    dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
    dof_handler.make_sparsity_pattern(dsp, constraints);
    system_matrix.clear();
    sparsity_pattern.copy_from(dsp);
    system_matrix.reinit(sparsity_pattern);
    solution.reinit(dof_handler.n_dofs());
  }



  void
  ElasticityProblem::assemble_system()
  {
    dealii::TimerOutput::Scope t(*timer, "assembly");
    ElasticityAssembler<2>     assembler(dof_handler, materials, gamma, stabilization);
    bc.add_loads(assembler);
    assembler.assemble(constraints, system_matrix, system_rhs);
    for (unsigned int i = 0; i < system_rhs.size(); ++i)
      check_load_entry(i, system_rhs[i]);
    check_load_scale(assembler);
  }



  // A load vector entry that overflowed: the loads, not the solver or the
  // support, are the cause.
  void
  ElasticityProblem::check_load_entry(const dealii::types::global_dof_index i, const double value) const
  {
    if (std::isfinite(value))
      return;
    std::ostringstream msg;
    msg << "The assembled load vector is " << value << " at DoF " << i
        << ": the loads overflow double precision when integrated. Check 'Boundary conditions and "
           "loads' (Body force, Traction, Pressure, Rigid boundary) for values far from the units of the "
           "problem.";
    AssertThrow(false, dealii::ExcMessage(msg.str()));
  }



  // 'Solver/Type = automatic': a direct factorization where it is as fast
  // as CG and fits into memory, CG with AMG or the p-multigrid elsewhere
  // (printed with the reason); the other types as given.
  std::string
  ElasticityProblem::chosen_solver_type() const
  {
    if (solver_type != "automatic")
      return solver_type;
    const double n = dof_handler.n_dofs();
    std::string  reason;
    std::string  type;
    if (distributed)
      {
        type   = "CG-AMG";
        reason = "several MPI processes: the distributed CG (a direct solver would gather the matrix on one "
                 "process)";
      }
    else
      {
        std::string  source;
        const double limit = InputParsing::memory_limit(memory_limit_GB, source);
        type = InputParsing::automatic_solver_is_direct(n, degree, limit, reason) ? "UMFPACK" : "CG-AMG";
      }
    pcout << "  solver (Solver/Type = automatic): " << type << ", " << reason << std::endl;
    return type;
  }



  void
  ElasticityProblem::solve()
  {
    dealii::TimerOutput::Scope t(*timer, "solve");
    LinearSolver::Settings     settings;
    settings.type               = LinearSolver::parse_type(used_solver_type = chosen_solver_type());
    settings.relative_tolerance = solver_tolerance;
    settings.max_iterations     = solver_max_iterations;
    settings.preconditioner     = LinearSolver::parse_preconditioner(solver_preconditioner);
    LinearSolver solver(settings);
    // k = 2 with CG: the k = 1 space on the same polygons as the coarse
    // level (p-multigrid)
    dealii::SparsityPattern          prolongation_sparsity;
    dealii::SparseMatrix<double>     prolongation;
    std::vector<std::vector<double>> coarse_modes;
    if (settings.type == LinearSolver::Type::cg_amg)
      solver.set_near_null_space(dof_handler.rigid_body_modes());
    if (settings.type == LinearSolver::Type::cg_amg && degree == 2)
      {
        PMultigrid::make_prolongation(dof_handler, prolongation_sparsity, prolongation, coarse_modes);
        solver.set_coarse_space(prolongation, coarse_modes);
      }
    solver.solve(system_matrix, solution, system_rhs);
    constraints.distribute(solution);
    solver_description = solver.description();
    solver_iterations  = solver.last_iterations();
    solver_setup_time  = solver.last_setup_time();
  }



  // The distributed path, as step-40: the partition of the cells, the owned
  // and relevant DoFs, the constraints (on the replicated DoF numbering,
  // every process holds all lines: they are few, boundary DoFs only), and
  // the sparsity pattern of the owned cells with the rows of other
  // processes sent to them.
  void
  ElasticityProblem::setup_distributed_system()
  {
    dealii::TimerOutput::Scope t(*timer, "setup");
    dof_handler.reinit(mesh);
    dof_handler.distribute_dofs(degree);
    partition.reinit(dof_handler, mpi_communicator);
    constraints.clear();
    bc.apply_constraints(dof_handler, constraints);
    constraints.close();
    BoundaryConditions::check_rigid_body_support(dof_handler, constraints);
    locally_owned_dofs    = partition.locally_owned_dofs();
    locally_relevant_dofs = partition.locally_relevant_dofs(constraints);
    dealii::DynamicSparsityPattern dsp(locally_relevant_dofs);
    partition.make_sparsity_pattern(dsp, constraints);
    dealii::SparsityTools::distribute_sparsity_pattern(dsp, locally_owned_dofs, mpi_communicator,
                                                       locally_relevant_dofs);
    distributed_matrix.reinit(locally_owned_dofs, locally_owned_dofs, dsp, mpi_communicator);
    distributed_rhs.reinit(locally_owned_dofs, mpi_communicator);
    distributed_solution.reinit(locally_owned_dofs, mpi_communicator);
  }



  void
  ElasticityProblem::assemble_distributed_system()
  {
    dealii::TimerOutput::Scope t(*timer, "assembly");
    ElasticityAssembler<2>     assembler(dof_handler, materials, gamma, stabilization);
    bc.add_loads(assembler);
    assembler.assemble(constraints, partition.locally_owned_cells(), distributed_matrix, distributed_rhs);
    for (const auto i : distributed_rhs.locally_owned_elements())
      check_load_entry(i, distributed_rhs(i));
    // (the whole load vector on every process: the mesh is replicated)
    check_load_scale(assembler);
  }



  // Loads out of scale with the stiffness: named before the solver
  // overflows on them (ScaleCheck).
  void
  ElasticityProblem::check_load_scale(const ElasticityAssembler<2> &assembler) const
  {
    dealii::Vector<double> f;
    assembler.assemble_load_vector(f);
    std::ostringstream when;
    when << "at t = " << final_time;
    ScaleCheck::check(dof_handler, f,
                      {{mesh_parameters.material_id, "the body", "Material/Young's modulus", youngs_modulus}},
                      when.str(), false);
  }



  // Solve, set the constrained DoFs, and copy what this process's cells and
  // their ghost layer need into the serial vector `solution` (zero at the
  // other DoFs) for the stresses, errors and the output piece.
  void
  ElasticityProblem::solve_distributed()
  {
    {
      dealii::TimerOutput::Scope t(*timer, "solve");
      LinearSolver::Settings     settings;
      settings.type               = LinearSolver::parse_type(used_solver_type = chosen_solver_type());
      settings.relative_tolerance = solver_tolerance;
      settings.max_iterations     = solver_max_iterations;
      settings.preconditioner     = LinearSolver::parse_preconditioner(solver_preconditioner);
      ParallelLinearSolver solver(settings);
      if (settings.type == LinearSolver::Type::cg_amg)
        solver.set_near_null_space(dof_handler.rigid_body_modes(), locally_owned_dofs);
      // k = 2 with CG: the p-multigrid, as on the serial path
      dealii::SparsityPattern          prolongation_sparsity;
      dealii::SparseMatrix<double>     prolongation;
      std::vector<std::vector<double>> coarse_modes;
      if (settings.type == LinearSolver::Type::cg_amg && degree == 2)
        {
          PMultigrid::make_prolongation(dof_handler, prolongation_sparsity, prolongation, coarse_modes);
          solver.set_coarse_space(prolongation, coarse_modes);
        }
      solver.solve(distributed_matrix, distributed_solution, distributed_rhs);
      constraints.distribute(distributed_solution);
      solver_description = solver.description();
      solver_iterations  = solver.last_iterations();
      solver_setup_time  = solver.last_setup_time();
    }
    dealii::TimerOutput::Scope t(*timer, "ghost exchange");
    std::vector<unsigned int>  cells = partition.locally_owned_cells();
    cells.insert(cells.end(), partition.ghost_cells().begin(), partition.ghost_cells().end());
    const dealii::IndexSet                needed = partition.dofs_of_cells(cells);
    dealii::TrilinosWrappers::MPI::Vector ghosted(locally_owned_dofs, needed, mpi_communicator);
    ghosted = distributed_solution;
    solution.reinit(dof_handler.n_dofs());
    for (const auto i : needed)
      solution[i] = ghosted(i);
  }



  // Stresses, errors against the exact solution (if given), the VTU file,
  // a line of the convergence table and of the JSON summary; the summary
  // is rewritten after every cycle, so that a later failure keeps it.
  void
  ElasticityProblem::output_results(const unsigned int cycle)
  {
    // a displacement far beyond the size of the body means loads far too
    // large for the stiffness (or a prescribed value out of scale): say so
    // before the stresses or the error integrals overflow and take the blame
    {
      const double size = mesh.extent();
      std::vector<dealii::types::global_dof_index> dofs;
      const auto check_cell = [&](const unsigned int c) {
        dof_handler.get_dof_indices(c, dofs);
        for (const auto i : dofs)
          if (!(std::abs(solution[i]) <= BoundaryConditionParameters::max_displacement_ratio * size))
            {
              std::ostringstream msg;
              msg << "Cycle " << cycle << ": the displacement of DoF " << i << " (cell " << c << ") is "
                  << solution[i] << ", more than " << BoundaryConditionParameters::max_displacement_ratio
                  << " times the size of the mesh (" << size
                  << "): far outside the small-displacement model, and the stresses and error integrals "
                     "would overflow. The loads and prescribed displacements are out of scale with the "
                     "stiffness: check 'Boundary conditions and loads' (Traction, Pressure, Body force, "
                     "Rigid boundary, Dirichlet, Point constraints) against 'Material/Young's modulus' = "
                  << youngs_modulus << ".";
              AssertThrow(false, dealii::ExcMessage(msg.str()));
            }
      };
      if (distributed)
        for (const unsigned int c : partition.locally_owned_cells())
          check_cell(c);
      else
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          check_cell(c);
    }

    // the verification of the solve: residual and the force and moment
    // balance of the body (every edge-connected piece is part of it)
    // (at finite strain the Newton solver's residual test is the check:
    // the linear balance does not hold for the deformed body)
    std::vector<ForceBalance::Body> balance;
    if (!finite_strain.enabled)
    {
      ElasticityAssembler<2> assembler(dof_handler, materials, gamma, stabilization);
      bc.add_loads(assembler);
      const double tolerance =
        (LinearSolver::parse_type(used_solver_type) == LinearSolver::Type::cg_amg ? solver_tolerance : 0.);
      balance = distributed ? ForceBalance::compute(assembler, constraints, solution, dealii::Vector<double>(),
                                                    tolerance, &partition.locally_owned_cells(), mpi_communicator) :
                              ForceBalance::compute(assembler, constraints, solution, dealii::Vector<double>(),
                                                    tolerance);
      ForceBalance::check(balance, "cycle " + std::to_string(cycle) + " (solver " + solver_description + ")");
    }

    // the cells this process computes: all, or (distributed) its own, with
    // the ghost layer for the nodal stress averages
    std::vector<unsigned int> stress_cells;
    if (distributed)
      {
        std::set_union(partition.locally_owned_cells().begin(), partition.locally_owned_cells().end(),
                       partition.ghost_cells().begin(), partition.ghost_cells().end(),
                       std::back_inserter(stress_cells));
      }
    const StressRecovery<2> stresses = distributed ? StressRecovery<2>(dof_handler, materials, solution, stress_cells) :
                                                     StressRecovery<2>(dof_handler, materials, solution);
    ErrorNorms              errors;
    if (exact)
      {
        dealii::TimerOutput::Scope t(*timer, "errors");
        if (distributed)
          errors = sum_over_processes(compute_errors(dof_handler, materials, solution, *exact,
                                                     partition.locally_owned_cells()),
                                      mpi_communicator);
        else
          errors = compute_errors(dof_handler, materials, solution, *exact);
      }
    // nothing non-finite is reported or written
    {
      std::vector<unsigned int> own_cells;
      if (distributed)
        own_cells = partition.locally_owned_cells();
      else
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          own_cells.push_back(c);
      for (const unsigned int c : own_cells)
        if (!std::isfinite(stresses.cell_von_mises(c)))
          {
            std::ostringstream msg;
            msg << "Cycle " << cycle << ": the von Mises stress of cell " << c << " (first vertex at ("
                << mesh.vertex(mesh.cell(c).vertices[0])[0] << ", " << mesh.vertex(mesh.cell(c).vertices[0])[1]
                << ")) is " << stresses.cell_von_mises(c)
                << ": the displacements or the stresses overflow double precision. Check the loads, the "
                   "Dirichlet values and 'Material/Young's modulus' for values far from 1 in the units of the "
                   "problem.";
            AssertThrow(false, dealii::ExcMessage(msg.str()));
          }
      if (exact)
        for (const auto &[name, v] : std::vector<std::pair<std::string, double>>{
               {"L2", errors.l2}, {"H1 seminorm", errors.h1_seminorm}, {"energy", errors.energy}})
          if (!std::isfinite(v) || !std::isfinite(errors.l2_exact) || !std::isfinite(errors.h1_exact))
            {
              dealii::Point<2> lo = mesh.vertex(0), hi = mesh.vertex(0);
              for (const auto &p : mesh.get_vertices())
                for (unsigned int d = 0; d < 2; ++d)
                  {
                    lo[d] = std::min(lo[d], p[d]);
                    hi[d] = std::max(hi[d], p[d]);
                  }
              std::ostringstream msg;
              msg << "Cycle " << cycle << ": the " << name << " error against 'Exact solution/Displacement' = '"
                  << exact_displacement << "' is " << v << " (norms of the exact solution: L2 " << errors.l2_exact
                  << ", H1 " << errors.h1_exact
                  << "). The integrals of the error overflow double precision: the mesh spans (" << lo[0] << ", "
                  << lo[1] << ") to (" << hi[0] << ", " << hi[1]
                  << "); give the coordinates, loads and the exact solution in units that bring them nearer "
                     "to 1.";
              AssertThrow(false, dealii::ExcMessage(msg.str()));
            }
    }
    const std::string prefix = output_prefix(output_folder, base_name, cycle, n_cycles);
    const std::string vtu    = prefix + (distributed ? ".pvtu" : finite_strain.enabled ? ".pvd" : ".vtu");
    // (finite strain: every load step wrote its file and the series)
    if (write_vtu && !finite_strain.enabled)
      {
        dealii::TimerOutput::Scope t(*timer, "output");
        if (distributed)
          {
            // one piece per process, named <prefix>.<process>.vtu, and the
            // record that joins them (process 0)
            const std::string stem = std::filesystem::path(prefix).filename().string();
            write_vtu_piece(prefix + "." + std::to_string(this_process) + ".vtu", dof_handler, solution, stresses,
                            partition.locally_owned_cells(), this_process);
            if (this_process == 0)
              {
                std::vector<std::string> pieces;
                for (unsigned int p = 0; p < n_processes; ++p)
                  pieces.push_back(stem + "." + std::to_string(p) + ".vtu");
                write_pvtu_record(vtu, pieces);
                // the pieces of the other processes belong to the run too
                for (const auto &piece : pieces)
                  RunFiles::record(output_folder + "/" + piece);
              }
          }
        else
          write_vtu_file(vtu, dof_handler, solution, stresses);
      }

    const auto [hmin, hmax] = mesh.cell_diameter_range();
    double max_vm           = 0;
    if (distributed)
      {
        for (const unsigned int c : partition.locally_owned_cells())
          max_vm = std::max(max_vm, stresses.cell_von_mises(c));
        max_vm = dealii::Utilities::MPI::max(max_vm, mpi_communicator);
      }
    else
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        max_vm = std::max(max_vm, stresses.cell_von_mises(c));
    pcout << "Cycle " << cycle << ": " << mesh.n_cells() << " cells, " << dof_handler.n_dofs()
          << " DoFs, h = " << hmax << ", solver " << solver_description;
    if (solver_iterations > 1)
      pcout << " (" << solver_iterations << " iterations)";
    if (finite_strain.enabled)
      pcout << ", max |Cauchy stress| " << max_cauchy_norm << std::endl;
    else
      pcout << ", max von Mises " << max_vm << std::endl;
    if (!balance.empty())
    {
      const auto [imbalance, residual] = ForceBalance::worst(balance);
      pcout << "  verification: in equilibrium (relative imbalance " << imbalance << ", residual " << residual
            << ", tolerance " << balance.front().tolerance << "; condition " << balance.front().condition << ")"
            << std::endl;
    }
    if (distributed)
      {
        const auto per_part = partition.cells_per_part();
        const auto owned    = dealii::Utilities::MPI::all_gather(mpi_communicator, locally_owned_dofs.n_elements());
        pcout << "  partition (METIS on the cell graph): cells per process "
              << *std::min_element(per_part.begin(), per_part.end()) << " to "
              << *std::max_element(per_part.begin(), per_part.end()) << ", owned DoFs per process "
              << *std::min_element(owned.begin(), owned.end()) << " to " << *std::max_element(owned.begin(), owned.end())
              << ", " << partition.n_cut_edges() << " edges between processes" << std::endl;
      }

    table.add_value("cycle", cycle);
    table.add_value("cells", mesh.n_cells());
    table.add_value("dofs", dof_handler.n_dofs());
    table.add_value("h", hmax);
    const std::string key = "cycles." + std::to_string(cycle) + ".";
    json.set(key + "cells", double(mesh.n_cells()));
    json.set(key + "dofs", double(dof_handler.n_dofs()));
    json.set(key + "h_max", hmax);
    json.set(key + "h_min", hmin);
    if (finite_strain.enabled)
      json.set(key + "max_cauchy_norm", max_cauchy_norm);
    else
      json.set(key + "max_von_mises", max_vm);
    json.set(key + "solver", solver_description);
    json.set(key + "solver_iterations", double(solver_iterations));
    json.set(key + "solver_setup_seconds", solver_setup_time);
    json.set(key + "mpi_processes", double(distributed ? n_processes : 1));
    for (const auto &b : balance)
      {
        const std::string k = key + "verification.body" + std::to_string(b.body) + ".";
        json.set(k + "imbalance", b.imbalance);
        json.set(k + "residual", b.residual);
        json.set(k + "tolerance", b.tolerance);
        json.set(k + "condition", b.condition);
      }
    if (write_vtu)
      json.set(key + "vtu", vtu);
    for (const auto &s : timer->get_summary_data(dealii::TimerOutput::total_wall_time))
      json.set(key + "timings." + s.first, s.second);
    if (exact)
      {
        table.add_value("L2", errors.l2);
        table.add_value("H1", errors.h1_seminorm);
        table.add_value("energy", errors.energy);
        cycle_errors["L2"].push_back(errors.l2);
        cycle_errors["H1"].push_back(errors.h1_seminorm);
        cycle_errors["energy"].push_back(errors.energy);
        json.set(key + "errors.L2", errors.l2);
        json.set(key + "errors.H1_seminorm", errors.h1_seminorm);
        json.set(key + "errors.energy", errors.energy);
        last_errors = {errors.l2, errors.h1_seminorm, errors.energy};
      }
    if (!cycle_dofs.empty() && dof_handler.n_dofs() <= cycle_dofs.back())
      pcout << "warning: cycle " << cycle << " has " << dof_handler.n_dofs() << " DoFs, no more than cycle "
            << cycle - 1 << " (" << cycle_dofs.back()
            << "): the meshes of a convergence study must be refined from cycle to cycle (are two cycles "
               "reading the same mesh file?); the convergence rate of this cycle is not defined."
            << std::endl;
    cycle_dofs.push_back(dof_handler.n_dofs());
    last_n_dofs = dof_handler.n_dofs();
    last_timings.clear();
    for (const auto &s : timer->get_summary_data(dealii::TimerOutput::total_wall_time))
      last_timings[s.first] = s.second;
    if (gather_solution)
      {
        if (distributed)
          {
            dealii::TrilinosWrappers::MPI::Vector all(locally_owned_dofs, dealii::complete_index_set(dof_handler.n_dofs()),
                                                      mpi_communicator);
            all = distributed_solution;
            last_solution.reinit(dof_handler.n_dofs());
            for (dealii::types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
              last_solution[i] = all(i);
          }
        else
          last_solution = solution;
      }
    if (write_json && this_process == 0)
      {
        json.set("status", cycle + 1 < n_cycles ? "running" : "complete");
        json.write(output_folder + "/" + base_name + ".json");
        json_written = true;
      }
  }



  void
  ElasticityProblem::run()
  {
    check_output_names(output_folder, base_name);
    if (this_process == 0 || !distributed)
      create_output_folder(output_folder);
    // the files under the output prefix belong to this run only: those of
    // an earlier run go first (process 0, before any process writes)
    RunFiles run_files(output_folder, base_name, this_process == 0, write_vtu || write_json);
    pcout << run_files.removal_note(run_files.start());
    if (distributed)
      {
        const int ierr = MPI_Barrier(mpi_communicator);
        AssertThrowMPI(ierr);
      }
    try
      {
        run_cycles();
      }
    catch (...)
      {
        // the JSON summary (if any was written) and the manifest say
        // "failed"; the user learns which files the run wrote
        if (write_json && this_process == 0 && json_written)
          {
            json.set("status", "failed");
            try
              {
                json.write(output_folder + "/" + base_name + ".json");
              }
            catch (...)
              {}
          }
        // the program prints the list after the error
        run_files.failed();
        throw;
      }
    run_files.complete();
  }



  void
  ElasticityProblem::run_cycles()
  {
    json_written = false;
    // a hyperelastic law enters the small-strain paths (assembly, stresses,
    // errors) by its linearization, the linear law of the same E and nu
    materials = {{dealii::types::material_id(mesh_parameters.material_id),
                  ElasticMaterial(youngs_modulus, poissons_ratio, model)}};
    laws      = MaterialLibrary<2>();
    laws.add(dealii::types::material_id(mesh_parameters.material_id),
             MaterialLaws::make_law(law, youngs_modulus, poissons_ratio, model));
    exact.reset();
    if (!InputParsing::trim(exact_displacement).empty())
      exact = std::make_unique<InputParsing::ParsedFunction>(InputParsing::split(exact_displacement, ','),
                                                             bc.get_constants(), "Exact solution/Displacement");
    AssertThrow(!exact || exact->n_components == 2,
                dealii::ExcMessage("Parameter 'Exact solution/Displacement' needs two expressions 'ux, uy'."));
    // (the solution compared with it is that of t = Final time)
    if (exact)
      exact->set_time(final_time);

    table = dealii::ConvergenceTable();
    cycle_dofs.clear();
    cycle_errors.clear();
    json  = JsonSummary();
    json.set("program", "dealvem");
    json.set("mesh.type", mesh_parameters.description());
    json.set("material.E", youngs_modulus);
    json.set("material.nu", poissons_ratio);
    json.set("material.model", ElasticMaterial::model_name(model));
    json.set("material.law", MaterialLaws::name(law));
    json.set("finite_strain.enabled", finite_strain.enabled ? "true" : "false");
    json.set("final_time", final_time);
    if (finite_strain.enabled)
      {
        json.set("finite_strain.load_steps", double(n_load_steps));
        json.set("finite_strain.final_time", final_time);
        json.set("finite_strain.max_newton_iterations", double(finite_strain.solver.max_iterations));
        json.set("finite_strain.residual_tolerance", finite_strain.solver.residual_tolerance);
        json.set("finite_strain.update_tolerance", finite_strain.solver.update_tolerance);
        json.set("finite_strain.line_search", finite_strain.solver.line_search ? "true" : "false");
        json.set("finite_strain.pressure_load", pressure_load_name(finite_strain.pressure_load));
      }
    json.set("discretization.order", double(degree));
    json.set("discretization.gamma", gamma);
    json.set("discretization.stabilization",
             std::string(stabilization == Stabilization::boundary ? "boundary" :
                         stabilization == Stabilization::trace ||
                             (stabilization == Stabilization::automatic && (degree == 1 || finite_strain.enabled)) ?
                                                                    "trace" :
                                                                    "diagonal"));
    json.set("solver.type", solver_type);

    for (unsigned int cycle = 0; cycle < n_cycles; ++cycle)
      {
        timer = std::make_unique<dealii::TimerOutput>(std::cout, dealii::TimerOutput::never,
                                                      dealii::TimerOutput::wall_times);
        make_mesh(cycle);
        if (distributed)
          {
            setup_distributed_system();
            assemble_distributed_system();
            solve_distributed();
          }
        else if (finite_strain.enabled)
          {
            setup_system();
            solve_finite_strain(cycle);
          }
        else
          {
            setup_system();
            assemble_system();
            solve();
          }
        output_results(cycle);
      }

    if (exact)
      {
        for (const std::string c : {"L2", "H1", "energy", "h"})
          {
            table.set_scientific(c, true);
            table.set_precision(c, 3);
          }
        if (n_cycles > 1)
          for (const std::string c : {"L2", "H1", "energy"})
            add_convergence_rates(table, c, cycle_errors[c], cycle_dofs);
        pcout << std::endl;
        if (this_process == 0)
          table.write_text(std::cout, dealii::TableHandler::org_mode_table);
      }

    // peak resident memory of each process (the replicated mesh makes it
    // grow with the whole problem; see doc/benchmarks.md)
    dealii::Utilities::System::MemoryStats stats;
    dealii::Utilities::System::get_memory_stats(stats);
    const auto peaks = distributed ? dealii::Utilities::MPI::all_gather(mpi_communicator, stats.VmHWM) :
                                     std::vector<unsigned long int>{stats.VmHWM};
    peak_memory_per_process.clear();
    for (const auto kB : peaks)
      peak_memory_per_process.push_back(kB / 1024.);
    pcout << "Peak memory (VmHWM) per process:";
    for (unsigned int p = 0; p < peak_memory_per_process.size(); ++p)
      {
        pcout << (p > 0 ? "," : "") << " " << std::fixed << std::setprecision(1) << peak_memory_per_process[p]
              << " MB";
        json.set("memory.peak_MB_process_" + std::to_string(p), peak_memory_per_process[p]);
      }
    pcout << std::defaultfloat << std::setprecision(6) << std::endl;
    if (write_json && this_process == 0)
      {
        json.set("status", "complete");
        json.write(output_folder + "/" + base_name + ".json");
      }

    if (write_json)
      pcout << "Summary written to " << output_folder + "/" + base_name + ".json" << std::endl;
    if (write_vtu)
      pcout << "ParaView files: " << output_folder << "/" << base_name
            << (n_cycles > 1 ? "-cycle*" : "")
            << (distributed           ? ".pvtu (one .vtu piece per process)" :
                finite_strain.enabled ? ".pvd (the load steps, <base name>-step-NNN.vtu)" :
                                        ".vtu")
            << std::endl;
  }



  namespace
  {
    std::string
    step_suffix(const unsigned int step)
    {
      std::ostringstream s;
      s << "-step-" << std::setw(3) << std::setfill('0') << step;
      return s.str();
    }
  } // namespace



  void
  ElasticityProblem::solve_finite_strain(const unsigned int cycle)
  {
    dealii::TimerOutput::Scope t(*timer, "finite strain solve");
    // the trace rule is the finite-strain default for both orders (see
    // FiniteStrainAssembler); an explicit choice is passed on
    const Stabilization      rule = (stabilization == Stabilization::automatic ? Stabilization::trace : stabilization);
    FiniteStrainAssembler<2> assembler(dof_handler, laws, gamma, rule);
    bc.add_finite_strain_loads(assembler, "Finite strain/Enabled", finite_strain.pressure_load);
    // The load steps: step n solves at t_n = n * Final time / N. Where an
    // expression uses t, the data of the step are those of t_n, unscaled (as
    // in contact problems); else the data are fixed and step n applies n/N
    // of the loads and prescribed displacements (the load factor).
    const bool timed = bc.uses_time();
    {
      dealii::Vector<double> f_ext;
      assembler.assemble_load_vector(f_ext);
      for (unsigned int i = 0; i < f_ext.size(); ++i)
        check_load_entry(i, f_ext[i]);
    }
    // the scales of modulus, size and loads, before Newton squares them
    // (the loads at the time the functions are set to: the final time)
    {
      std::ostringstream when;
      when << "at t = " << final_time;
      dealii::Vector<double> f_ext;
      assembler.assemble_load_vector(f_ext);
      ScaleCheck::check(dof_handler, f_ext,
                        {{mesh_parameters.material_id, "the body", "Material/Young's modulus", youngs_modulus}},
                        when.str(), true);
    }
    FiniteStrainSolver<2>::Parameters parameters = finite_strain.solver;
    parameters.n_load_steps                     = n_load_steps;
    parameters.scale_prescribed_motion          = !timed;
    FiniteStrainSolver<2> solver(assembler, constraints, parameters);

    // the monitor point: a vertex of the mesh
    unsigned int monitor = dealii::numbers::invalid_unsigned_int;
    if (finite_strain.has_monitor_point)
      {
        double nearest = 1e300;
        for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
          {
            const double d = mesh.vertex(v).distance(finite_strain.monitor_point);
            if (d < nearest)
              {
                nearest = d;
                monitor = v;
              }
          }
        std::ostringstream msg;
        msg << "Parameter 'Finite strain/Monitor point' = (" << finite_strain.monitor_point
            << ") is not a vertex of the mesh of cycle " << cycle << ": the nearest vertex (" << mesh.vertex(monitor)
            << ") is " << nearest << " away. Give the coordinates of a vertex (a corner of the domain, say).";
        AssertThrow(nearest <= 1e-8 * mesh.extent(), dealii::ExcMessage(msg.str()));
      }

    const std::string prefix = output_prefix(output_folder, base_name, cycle, n_cycles);
    const std::string key    = "cycles." + std::to_string(cycle) + ".finite_strain.";
    std::vector<std::pair<double, std::string>> series;
    newton_updates  = 0;
    max_cauchy_norm = 0;
    pcout << "  finite strain: " << laws.get_law(mesh_parameters.material_id).get_name() << ", " << n_load_steps
          << " load step" << (n_load_steps > 1 ? "s" : "")
          << (timed ? " at the times t of the expressions" : " (load factors n/N of the data)")
          << (bc.has_pressure() ? ", " + pressure_load_name(finite_strain.pressure_load) + " pressure" : "")
          << std::endl;
    // the JSON record of a step (also of the failed one)
    const auto record_step = [&](const FiniteStrainSolver<2>::StepRecord &r) {
      const std::string k = key + "steps." + std::to_string(r.step) + ".";
      json.set(k + "load_factor", r.load_factor);
      json.set(k + "time", r.step * final_time / n_load_steps);
      json.set(k + "converged", r.converged ? "true" : "false");
      json.set(k + "newton_iterations", double(r.iterations.empty() ? 0 : r.iterations.size() - 1));
      if (!r.iterations.empty())
        {
          json.set(k + "residual", r.iterations.back().residual_norm);
          json.set(k + "relative_residual", r.iterations.back().relative_residual);
        }
    };
    const auto write_summary = [&](const std::string &status) {
      if (write_json && this_process == 0)
        {
          json.set("status", status);
          json.write(output_folder + "/" + base_name + ".json");
          json_written = true;
        }
    };

    for (unsigned int n = 1; n <= n_load_steps; ++n)
      {
        const double load_factor = timed ? 1. : double(n) / n_load_steps;
        const double time        = n * final_time / n_load_steps;
        try
          {
            if (timed)
              {
                // the data of t_n: loads (evaluated by the assembler at
                // their functions' time) and prescribed displacements
                bc.set_time(time);
                dealii::AffineConstraints<double> step_constraints;
                bc.apply_constraints(dof_handler, step_constraints);
                step_constraints.close();
                solver.set_constraints(step_constraints);
              }
            solver.solve_step(n, load_factor);
          }
        catch (...)
          {
            // the converged steps stay as written; the failed step is
            // recorded, the history printed, and the solver's message
            // (step, load factor, reason) goes on to the program
            solution = solver.get_solution();
            if (!solver.get_history().empty())
              record_step(solver.get_history().back());
            json.set(key + "converged_steps", double(n - 1));
            // (a failure to write the summary must not hide the solver's
            // message; run() tries again with the status 'failed')
            try
              {
                write_summary("running");
              }
            catch (...)
              {}
            if (this_process == 0)
              {
                std::cout << "Newton history (cycle " << cycle << "):" << std::endl;
                solver.print_history(std::cout);
              }
            throw;
          }
        const auto &r = solver.get_history().back();
        record_step(r);
        newton_updates += r.iterations.size() - 1;
        solution = solver.get_solution();
        const FiniteStrainFields fields = compute_finite_strain_fields(dof_handler, laws, solution);
        max_cauchy_norm                 = fields.max_cell_cauchy_norm;
        json.set(key + "steps." + std::to_string(n) + ".max_cauchy_norm", max_cauchy_norm);
        pcout << "  load step " << n << " of " << n_load_steps << " (load factor " << load_factor << ", t = " << time
              << "): " << r.iterations.size() - 1 << " Newton update" << (r.iterations.size() == 2 ? "" : "s")
              << ", residual " << r.iterations.back().residual_norm << " (relative "
              << r.iterations.back().relative_residual << "), max |Cauchy stress| " << max_cauchy_norm;
        if (monitor != dealii::numbers::invalid_unsigned_int)
          {
            const unsigned int node = dof_handler.vertex_node(monitor);
            const double       ux   = solution(VEMDoFHandler<2>::node_dof(node, 0));
            const double       uy   = solution(VEMDoFHandler<2>::node_dof(node, 1));
            pcout << ", u(" << mesh.vertex(monitor) << ") = (" << ux << ", " << uy << ")";
            json.set(key + "steps." + std::to_string(n) + ".monitor_ux", ux);
            json.set(key + "steps." + std::to_string(n) + ".monitor_uy", uy);
            if (n == n_load_steps)
              {
                json.set(key + "monitor_point.x", mesh.vertex(monitor)[0]);
                json.set(key + "monitor_point.y", mesh.vertex(monitor)[1]);
                json.set(key + "monitor_point.ux", ux);
                json.set(key + "monitor_point.uy", uy);
              }
          }
        pcout << std::endl;
        if (write_vtu)
          {
            const std::string       file = prefix + step_suffix(n) + ".vtu";
            write_finite_strain_vtu_file(file, dof_handler, laws, solution);
            series.emplace_back(time, std::filesystem::path(file).filename().string());
            write_pvd_record(prefix + ".pvd", series);
          }
        json.set(key + "converged_steps", double(n));
        write_summary("running");
      }
    json.set(key + "newton_iterations", double(newton_updates));
    if (!solver.get_history().empty())
      {
        json.set(key + "final_residual", solver.get_history().back().iterations.back().residual_norm);
        json.set(key + "final_relative_residual", solver.get_history().back().iterations.back().relative_residual);
      }
    if (this_process == 0)
      {
        std::cout << "Newton history (cycle " << cycle << "):" << std::endl;
        solver.print_history(std::cout);
      }
    solver_description = "Newton with UMFPACK, " + std::to_string(n_load_steps) + " load step" +
                         (n_load_steps > 1 ? "s" : "");
    solver_iterations  = newton_updates;
    used_solver_type   = "UMFPACK";
  }
} // namespace dealvem
