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
  ElasticityProblem::ElasticityProblem(const MPI_Comm comm, const Parallelism parallelism)
    : mpi_communicator(comm)
    , this_process(dealii::Utilities::MPI::this_mpi_process(comm))
    , n_processes(dealii::Utilities::MPI::n_mpi_processes(comm))
    , pcout(std::cout, this_process == 0)
  {
    distributed = parallelism == Parallelism::distributed ||
                  (parallelism == Parallelism::automatic && n_processes > 1);
  }



  // One cycle: the mesh of the cycle; its cells must carry the material id
  // the parameter file defines, its boundary the ids the conditions name.
  void
  ElasticityProblem::make_mesh(const unsigned int cycle)
  {
    StageTimer::Scope t(*timer, "mesh");
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
    StageTimer::Scope t(*timer, "setup");
    dof_handler.reinit(mesh);
    dof_handler.distribute_dofs(VEMElementData(degree));
    constraints.clear();
    bc.apply_constraints(dof_handler, constraints, nullptr, &rotation_parts);
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
    StageTimer::Scope t(*timer, "assembly");
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



  // The settings of the linear solve, serial or distributed: the method
  // chosen (recorded for the report), its tolerance, limit and preconditioner.
  LinearSolver::Settings
  ElasticityProblem::linear_solver_settings()
  {
    LinearSolver::Settings settings;
    settings.type               = LinearSolver::parse_type(used_solver_type = chosen_solver_type());
    settings.relative_tolerance = solver_tolerance;
    settings.max_iterations     = solver_max_iterations;
    settings.preconditioner     = LinearSolver::parse_preconditioner(solver_preconditioner);
    return settings;
  }



  void
  ElasticityProblem::solve()
  {
    StageTimer::Scope t(*timer, "solve");
    const LinearSolver::Settings settings = linear_solver_settings();
    LinearSolver                 solver(settings);
    // k = 2 with CG: the k = 1 space on the same polygons as the coarse
    // level (p-multigrid)
    dealii::SparsityPattern          prolongation_sparsity;
    dealii::SparseMatrix<double>     prolongation;
    std::vector<std::vector<double>> coarse_modes;
    if (settings.type == LinearSolver::Type::cg_amg)
      solver.set_near_null_space(dof_handler.rigid_body_modes());
    if (settings.type == LinearSolver::Type::cg_amg && PMultigrid::applies_to(dof_handler.get_element_data()))
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
    StageTimer::Scope t(*timer, "setup");
    dof_handler.reinit(mesh);
    dof_handler.distribute_dofs(VEMElementData(degree));
    partition.reinit(dof_handler, mpi_communicator);
    constraints.clear();
    bc.apply_constraints(dof_handler, constraints, nullptr, &rotation_parts);
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
    StageTimer::Scope t(*timer, "assembly");
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
      StageTimer::Scope t(*timer, "solve");
      const LinearSolver::Settings settings = linear_solver_settings();
      ParallelLinearSolver         solver(settings);
      if (settings.type == LinearSolver::Type::cg_amg)
        solver.set_near_null_space(dof_handler.rigid_body_modes(), locally_owned_dofs);
      // k = 2 with CG: the p-multigrid, as on the serial path
      dealii::SparsityPattern          prolongation_sparsity;
      dealii::SparseMatrix<double>     prolongation;
      std::vector<std::vector<double>> coarse_modes;
      if (settings.type == LinearSolver::Type::cg_amg && PMultigrid::applies_to(dof_handler.get_element_data()))
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
    StageTimer::Scope t(*timer, "ghost exchange");
    std::vector<unsigned int>  cells = partition.locally_owned_cells();
    cells.insert(cells.end(), partition.ghost_cells().begin(), partition.ghost_cells().end());
    const dealii::IndexSet                needed = partition.dofs_of_cells(cells);
    dealii::TrilinosWrappers::MPI::Vector ghosted(locally_owned_dofs, needed, mpi_communicator);
    ghosted = distributed_solution;
    solution.reinit(dof_handler.n_dofs());
    for (const auto i : needed)
      solution[i] = ghosted(i);
  }



  void
  ElasticityProblem::run()
  {
    // the files under the output prefix belong to this run only: those of
    // an earlier run go first (process 0, before any process writes)
    RunOutput output;
    output.folder       = output_folder;
    output.base_name    = base_name;
    output.writer       = (this_process == 0);
    output.writes_files = write_vtu || write_json;
    run_with_files(
      output, [this](const std::string &note) { pcout << note; },
      [this]() {
        if (design.enabled())
          run_design_cycle();
        else
          run_cycles();
      },
      // the JSON summary (if any was written) says "failed"; the manifest
      // too, and the user learns which files the run wrote
      [this]() {
        if (write_json && this_process == 0 && json_written)
          {
            json.set("status", "failed");
            json.write(output_folder + "/" + base_name + ".json");
          }
      },
      [this]() {
        if (distributed)
          {
            const int ierr = MPI_Barrier(mpi_communicator);
            AssertThrowMPI(ierr);
          }
      });
  }



  void
  ElasticityProblem::run_design_cycle()
  {
    AssertThrow(!distributed || n_processes == 1,
                dealii::ExcMessage("Design/Objective: topology optimization runs on one MPI process."));
    timer     = std::make_unique<StageTimer>();
    materials = {{dealii::types::material_id(mesh_parameters.material_id),
                  ElasticMaterial(youngs_modulus, poissons_ratio, model)}};
    make_mesh(0);
    MaterialLibrary<2> design_laws(materials);
    DesignInputs inputs;
    inputs.mesh             = &mesh;
    inputs.laws             = &design_laws;
    inputs.degree           = degree;
    inputs.bc               = &bc;
    inputs.solver           = solver_type;
    inputs.solver_tolerance = solver_tolerance;
    inputs.prefix           = output_folder + "/" + base_name;
    inputs.write_vtu        = write_vtu;
    inputs.write_pictures   = write_vtu;
    inputs.write_csv        = write_json;
    std::ostream null_stream(nullptr); // process > 0: print nothing
    run_design(design, inputs, pcout.is_active() ? pcout.get_stream() : null_stream);
  }



  void
  ElasticityProblem::print_newton_history(const FiniteStrainSolver<2> &solver, const unsigned int cycle) const
  {
    if (!pcout.is_active())
      return;
    pcout << "Newton history (cycle " << cycle << "):" << std::endl;
    solver.print_history(pcout.get_stream());
  }



  void
  ElasticityProblem::run_cycles()
  {
    timer        = std::make_unique<StageTimer>();
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
                             (stabilization == Stabilization::automatic &&
                              (VirtualElement<2>::stabilization_rules(degree).automatic_is_trace || finite_strain.enabled)) ?
                                                                    "trace" :
                                                                    "diagonal"));
    json.set("solver.type", solver_type);

    for (unsigned int cycle = 0; cycle < n_cycles; ++cycle)
      {
        cycle_start_stages = timer->stages();
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
        if (pcout.is_active())
          table.write_text(pcout.get_stream(), dealii::TableHandler::org_mode_table);
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
        // the stages of the whole run (writing this file itself is not
        // in them)
        json.set("status", "complete");
        json.set("timings.", timer->breakdown());
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

    // The JSON record under @p key of the finite-strain load step @p r at
    // the time @p time (also of the failed one).
    void
    record_newton_step(JsonSummary                             &json,
                       const std::string                       &key,
                       const FiniteStrainSolver<2>::StepRecord &r,
                       const double                             time)
    {
      const std::string k = key + "steps." + std::to_string(r.step) + ".";
      json.set(k + "load_factor", r.load_factor);
      json.set(k + "time", time);
      json.set(k + "converged", r.converged ? "true" : "false");
      json.set(k + "newton_iterations", double(r.iterations.empty() ? 0 : r.iterations.size() - 1));
      if (!r.iterations.empty())
        {
          json.set(k + "residual", r.iterations.back().residual_norm);
          json.set(k + "relative_residual", r.iterations.back().relative_residual);
        }
    }
  } // namespace



  void
  ElasticityProblem::solve_finite_strain(const unsigned int cycle)
  {
    StageTimer::Scope t(*timer, "finite strain solve");
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
    check_finite_strain_loads(assembler);
    FiniteStrainSolver<2>::Parameters parameters = finite_strain.solver;
    parameters.n_load_steps                     = n_load_steps;
    // an angle about a centre is prescribed as the exact rotation by the
    // load factor times the angle: the constraints of every step are
    // written for it, the other prescribed values scaled here
    const bool exact_rotations         = !timed && bc.has_rotations();
    parameters.scale_prescribed_motion = !timed && !exact_rotations;
    FiniteStrainSolver<2> solver(assembler, constraints, parameters);

    // the monitor point: a vertex of the mesh
    const unsigned int monitor = monitor_vertex(cycle);

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
    const auto record_step = [&](const FiniteStrainSolver<2>::StepRecord &r) {
      record_newton_step(json, key, r, r.step * final_time / n_load_steps);
    };
    const auto write_summary = [&](const std::string &status) {
      if (write_json && this_process == 0)
        {
          StageTimer::Scope o(*timer, "output json");
          json.set("status", status);
          json.set("timings.", timer->breakdown());
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
                bc.apply_constraints(dof_handler, step_constraints, nullptr, &rotation_parts);
                step_constraints.close();
                solver.set_constraints(step_constraints);
              }
            else if (exact_rotations)
              {
                bc.set_load_factor(load_factor);
                dealii::AffineConstraints<double> step_constraints;
                bc.apply_constraints(dof_handler, step_constraints, nullptr, &rotation_parts);
                bc.set_load_factor(1.);
                std::set<dealii::types::global_dof_index> turned;
                for (const auto &part : rotation_parts)
                  turned.insert(part.lines.begin(), part.lines.end());
                std::vector<std::pair<dealii::types::global_dof_index, double>> values;
                for (const auto &line : step_constraints.get_lines())
                  if (turned.count(line.index) == 0)
                    values.emplace_back(line.index, load_factor * line.inhomogeneity);
                for (const auto &v : values)
                  step_constraints.set_inhomogeneity(v.first, v.second);
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
            print_newton_history(solver, cycle);
            throw;
          }
        const auto &r = solver.get_history().back();
        record_step(r);
        newton_updates += r.iterations.size() - 1;
        solution = solver.get_solution();
        {
          StageTimer::Scope p(*timer, "postprocessing");
          max_cauchy_norm = compute_finite_strain_fields(dof_handler, laws, solution).max_cell_cauchy_norm;
          json.set(key + "steps." + std::to_string(n) + ".max_cauchy_norm", max_cauchy_norm);
          report_load_step(n, load_factor, time, r, monitor, key);
        }
        if (bc.has_rotations())
          {
            StageTimer::Scope v(*timer, "verification");
            // the reactions at the converged step: r = lambda f_ext - f_int(u)
            dealii::Vector<double> unbalanced;
            assembler.assemble(solution, load_factor, unbalanced, constraints, nullptr, nullptr);
            report_rotations(key + "steps." + std::to_string(n) + ".", unbalanced, true);
          }
        if (write_vtu)
          {
            StageTimer::Scope       o(*timer, "output vtu");
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
    print_newton_history(solver, cycle);
    solver_description = "Newton with UMFPACK, " + std::to_string(n_load_steps) + " load step" +
                         (n_load_steps > 1 ? "s" : "");
    solver_iterations  = newton_updates;
    used_solver_type   = "UMFPACK";
  }


  // The finite-strain loads: every entry of the load vector finite, and the
  // scales of modulus, size and loads checked before Newton squares them
  // (the loads at the time the functions are set to: the final time).
  void
  ElasticityProblem::check_finite_strain_loads(FiniteStrainAssembler<2> &assembler) const
  {
    {
      dealii::Vector<double> f_ext;
      assembler.assemble_load_vector(f_ext);
      for (unsigned int i = 0; i < f_ext.size(); ++i)
        check_load_entry(i, f_ext[i]);
    }
    {
      std::ostringstream when;
      when << "at t = " << final_time;
      dealii::Vector<double> f_ext;
      assembler.assemble_load_vector(f_ext);
      ScaleCheck::check(dof_handler, f_ext,
                        {{mesh_parameters.material_id, "the body", "Material/Young's modulus", youngs_modulus}},
                        when.str(), true);
    }
  }



  // The vertex of 'Finite strain/Monitor point' (invalid_unsigned_int when
  // none is given); a point that is no vertex of the mesh is an error.
  unsigned int
  ElasticityProblem::monitor_vertex(const unsigned int cycle) const
  {
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
    return monitor;
  }



  // The line of a converged load step on the terminal (Newton updates,
  // residual, largest Cauchy stress, the displacement of the monitor
  // point) and the monitor point's entries of the JSON summary.
  void
  ElasticityProblem::report_load_step(const unsigned int                        n,
                                      const double                              load_factor,
                                      const double                              time,
                                      const FiniteStrainSolver<2>::StepRecord &r,
                                      const unsigned int                        monitor,
                                      const std::string                        &key)
  {
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
  }

} // namespace dealvem
