// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <dealvem/app/elasticity_problem.h>
#include <dealvem/app/input_parsing.h>
#include <dealvem/app/problem_setup.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/postprocessing/error_norms.h>
#include <dealvem/postprocessing/json_summary.h>
#include <dealvem/base/output_file.h>
#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/postprocessing/vtu_output.h>
#include <dealvem/solvers/linear_solver.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <filesystem>
#include <iomanip>
#include <iostream>

namespace dealvem
{
  void
  ElasticityProblem::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    prm.declare_entry("Allow large runs", "false", Bool(),
                      "Before a run starts, its size is estimated from the mesh parameters and the "
                      "refinement cycles; runs estimated above 2e7 DoFs, 1e7 Voronoi cells, 1e5 Lloyd "
                      "iterations or 1e8 Lloyd iterations x cells (summed over the cycles) are refused unless this is true.");
    prm.enter_subsection("Mesh");
    MeshParameters::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Material");
    prm.declare_entry("Young's modulus", "1000", Double(0), "Young's modulus E, 1e-200 <= E <= 1e200.");
    prm.declare_entry("Poisson's ratio", "0.3", Double(-0.999, 0.499),
                      "Poisson's ratio nu, -1 < nu < 0.5.");
    prm.declare_entry("Model", "plane strain", Selection("plane strain|plane stress"),
                      "2D model of the material.");
    prm.leave_subsection();

    prm.enter_subsection("Discretization");
    prm.declare_entry("Order", "2", Integer(1, 2), "Order k of the virtual elements (1 or 2).");
    prm.declare_entry("Stabilization factor", "1.0", Double(1e-8),
                      "Factor gamma of the dofi-dofi stabilization gamma*tau*(I-Pi)^T(I-Pi), "
                      "tau = trace(consistency matrix)/n_dofs; 1e-6 <= gamma <= 1e6.");
    prm.leave_subsection();

    BoundaryConditionParameters::declare_parameters(prm);

    prm.enter_subsection("Exact solution");
    prm.declare_entry("Displacement", "", Anything(),
                      "Exact displacement 'ux, uy' (muparser expressions in x, y and t with "
                      "the function constants; static problem: t = 1). Empty: no error "
                      "computation.");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    prm.declare_entry("Type", "UMFPACK", Selection("UMFPACK|KLU|CG-AMG|GMRES-AMG"),
                      "UMFPACK: SuiteSparse direct; KLU: Trilinos Amesos KLU direct; CG-AMG: "
                      "deal.II's SolverCG preconditioned by Trilinos ML algebraic multigrid with the rigid-body "
                      "modes as near-null space. Contact problems: UMFPACK and KLU factor the whole "
                      "saddle-point matrix, and CG-AMG or GMRES-AMG both mean GMRES with a block "
                      "preconditioner (AMG on the displacement block, exact approximate Schur "
                      "complement); one body: GMRES-AMG means CG-AMG.");
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
  }



  void
  ElasticityProblem::parse_parameters(dealii::ParameterHandler &prm, const std::string &dir)
  {
    prm_directory = dir;
    prm.enter_subsection("Mesh");
    mesh_parameters.parse_parameters(prm, "Mesh");
    prm.leave_subsection();

    prm.enter_subsection("Material");
    youngs_modulus = prm.get_double("Young's modulus");
    poissons_ratio = prm.get_double("Poisson's ratio");
    model          = ElasticMaterial::parse_model(prm.get("Model"));
    prm.leave_subsection();
    InputParsing::check_range(youngs_modulus, ElasticMaterial::min_youngs_modulus,
                              ElasticMaterial::max_youngs_modulus, "Material/Young's modulus", false,
                              false, "Choose units that bring E nearer to 1.");
    // validates E and nu
    (void)ElasticMaterial(youngs_modulus, poissons_ratio, model);

    prm.enter_subsection("Discretization");
    degree = prm.get_integer("Order");
    gamma  = prm.get_double("Stabilization factor");
    prm.leave_subsection();
    InputParsing::check_range(gamma, 1e-6, 1e6, "Discretization/Stabilization factor");

    bc.parse_parameters(prm);

    prm.enter_subsection("Exact solution");
    exact_displacement = prm.get("Displacement");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    solver_type           = prm.get("Type");
    if (solver_type == "GMRES-AMG")
      solver_type = "CG-AMG";
    solver_tolerance      = prm.get_double("Relative tolerance");
    solver_max_iterations = prm.get_integer("Maximum iterations");
    prm.leave_subsection();
    InputParsing::check_range(solver_tolerance, 0, 1, "Solver/Relative tolerance", true, true);

    prm.enter_subsection("Convergence study");
    n_cycles = prm.get_integer("Refinement cycles");
    prm.leave_subsection();
    InputParsing::check_run_size({&mesh_parameters}, n_cycles, degree, prm.get_bool("Allow large runs"));

    prm.enter_subsection("Output");
    output_folder = prm.get("Folder");
    base_name     = prm.get("Base name");
    write_vtu     = prm.get_bool("Write VTU");
    write_json    = prm.get_bool("Write JSON");
    prm.leave_subsection();
    check_output_names(output_folder, base_name);
  }



  void
  ElasticityProblem::run()
  {
    check_output_names(output_folder, base_name);
    create_output_folder(output_folder);
    const ElasticMaterial                                 material(youngs_modulus, poissons_ratio, model);
    const std::map<dealii::types::material_id, ElasticMaterial> materials = {
      {dealii::types::material_id(mesh_parameters.material_id), material}};

    std::unique_ptr<InputParsing::ParsedFunction> exact;
    if (!InputParsing::trim(exact_displacement).empty())
      exact = std::make_unique<InputParsing::ParsedFunction>(
        InputParsing::split(exact_displacement, ','), bc.get_constants(),
        "Exact solution/Displacement");
    AssertThrow(!exact || exact->n_components == 2,
                dealii::ExcMessage("Parameter 'Exact solution/Displacement' needs two expressions 'ux, uy'."));

    dealii::ConvergenceTable table;
    JsonSummary              json;
    json.set("program", "dealvem");
    json.set("mesh.type", mesh_parameters.description());
    json.set("material.E", youngs_modulus);
    json.set("material.nu", poissons_ratio);
    json.set("material.model", ElasticMaterial::model_name(model));
    json.set("discretization.order", double(degree));
    json.set("discretization.gamma", gamma);
    json.set("solver.type", solver_type);

    for (unsigned int cycle = 0; cycle < n_cycles; ++cycle)
      {
        dealii::TimerOutput timer(std::cout, dealii::TimerOutput::never,
                                  dealii::TimerOutput::wall_times);
        PolygonalMesh<2> mesh;
        {
          dealii::TimerOutput::Scope t(timer, "mesh");
          mesh_parameters.create_mesh(mesh, cycle, prm_directory);
          for (unsigned int c = 0; c < mesh.n_cells(); ++c)
            AssertThrow(materials.count(mesh.cell(c).material_id),
                        dealii::ExcMessage("Cell " + std::to_string(c) + " of mesh '" + mesh.name +
                                           "' has material id " +
                                           std::to_string(mesh.cell(c).material_id) +
                                           " but the parameter file defines a material for id " +
                                           std::to_string(mesh_parameters.material_id) + " only."));
          bc.check_boundary_ids(mesh);
        }

        VEMDoFHandler<2>                   dof_handler(mesh);
        dealii::AffineConstraints<double>  constraints;
        dealii::SparsityPattern            sparsity;
        dealii::SparseMatrix<double>       matrix;
        dealii::Vector<double>             rhs, solution;
        {
          dealii::TimerOutput::Scope t(timer, "setup");
          dof_handler.distribute_dofs(degree);
          bc.apply_constraints(dof_handler, constraints);
          constraints.close();
          BoundaryConditions::check_rigid_body_support(dof_handler, constraints);
          dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
          dof_handler.make_sparsity_pattern(dsp, constraints);
          sparsity.copy_from(dsp);
          matrix.reinit(sparsity);
        }
        {
          dealii::TimerOutput::Scope t(timer, "assembly");
          ElasticityAssembler<2>     assembler(dof_handler, materials, gamma);
          bc.add_loads(assembler);
          assembler.assemble(constraints, matrix, rhs);
        }
        LinearSolver::Settings settings;
        settings.type               = LinearSolver::parse_type(solver_type);
        settings.relative_tolerance = solver_tolerance;
        settings.max_iterations     = solver_max_iterations;
        LinearSolver solver(settings);
        {
          dealii::TimerOutput::Scope t(timer, "solve");
          solution.reinit(dof_handler.n_dofs());
          if (settings.type == LinearSolver::Type::cg_amg)
            solver.set_near_null_space(dof_handler.rigid_body_modes());
          solver.solve(matrix, solution, rhs);
          constraints.distribute(solution);
        }
        StressRecovery<2> stresses(dof_handler, materials, solution);
        ErrorNorms        errors;
        if (exact)
          {
            dealii::TimerOutput::Scope t(timer, "errors");
            errors = compute_errors(dof_handler, materials, solution, *exact);
          }
        const std::string vtu = output_prefix(output_folder, base_name, cycle, n_cycles) + ".vtu";
        if (write_vtu)
          {
            dealii::TimerOutput::Scope t(timer, "output");
            write_vtu_file(vtu, dof_handler, solution, stresses);
          }

        const auto   [hmin, hmax] = mesh.cell_diameter_range();
        double       max_vm       = 0;
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          max_vm = std::max(max_vm, stresses.cell_von_mises(c));
        std::cout << "Cycle " << cycle << ": " << mesh.n_cells() << " cells, "
                  << dof_handler.n_dofs() << " DoFs, h = " << hmax << ", solver "
                  << solver.description();
        if (solver.last_iterations() > 1)
          std::cout << " (" << solver.last_iterations() << " iterations)";
        std::cout << ", max von Mises " << max_vm << std::endl;

        table.add_value("cycle", cycle);
        table.add_value("cells", mesh.n_cells());
        table.add_value("dofs", dof_handler.n_dofs());
        table.add_value("h", hmax);
        const std::string key = "cycles." + std::to_string(cycle) + ".";
        json.set(key + "cells", double(mesh.n_cells()));
        json.set(key + "dofs", double(dof_handler.n_dofs()));
        json.set(key + "h_max", hmax);
        json.set(key + "h_min", hmin);
        json.set(key + "max_von_mises", max_vm);
        json.set(key + "solver_iterations", double(solver.last_iterations()));
        if (write_vtu)
          json.set(key + "vtu", vtu);
        for (const auto &s : timer.get_summary_data(dealii::TimerOutput::total_wall_time))
          json.set(key + "timings." + s.first, s.second);
        if (exact)
          {
            table.add_value("L2", errors.l2);
            table.add_value("H1", errors.h1_seminorm);
            table.add_value("energy", errors.energy);
            json.set(key + "errors.L2", errors.l2);
            json.set(key + "errors.H1_seminorm", errors.h1_seminorm);
            json.set(key + "errors.energy", errors.energy);
            last_errors = {errors.l2, errors.h1_seminorm, errors.energy};
          }
        last_n_dofs = dof_handler.n_dofs();
        last_timings.clear();
        for (const auto &s : timer.get_summary_data(dealii::TimerOutput::total_wall_time))
          last_timings[s.first] = s.second;
        // the summary of the cycles so far: a later failure keeps it
        if (write_json)
          json.write(output_folder + "/" + base_name + ".json");
      }

    if (exact)
      {
        table.set_scientific("L2", true);
        table.set_scientific("H1", true);
        table.set_scientific("energy", true);
        table.set_scientific("h", true);
        table.set_precision("L2", 3);
        table.set_precision("H1", 3);
        table.set_precision("energy", 3);
        table.set_precision("h", 3);
        if (n_cycles > 1)
          {
            table.evaluate_convergence_rates("L2", "dofs", dealii::ConvergenceTable::reduction_rate_log2, 2);
            table.evaluate_convergence_rates("H1", "dofs", dealii::ConvergenceTable::reduction_rate_log2, 2);
            table.evaluate_convergence_rates("energy", "dofs", dealii::ConvergenceTable::reduction_rate_log2, 2);
          }
        std::cout << std::endl;
        table.write_text(std::cout, dealii::TableHandler::org_mode_table);
      }
    if (write_json)
      {
        const std::string file = output_folder + "/" + base_name + ".json";
        std::cout << "Summary written to " << file << std::endl;
      }
    if (write_vtu)
      std::cout << "ParaView files: " << output_folder << "/" << base_name
                << (n_cycles > 1 ? "-cycle*.vtu" : ".vtu") << std::endl;
  }
} // namespace dealvem
