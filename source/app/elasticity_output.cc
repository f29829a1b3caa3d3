// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// ElasticityProblem: the results of a cycle (stresses, errors, VTU file,
// convergence table, JSON summary).
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
  // Stresses, errors against the exact solution (if given), the VTU file,
  // a line of the convergence table and of the JSON summary; the summary
  // is rewritten after every cycle, so that a later failure keeps it.
  void
  ElasticityProblem::output_results(const unsigned int cycle)
  {
    // (what the stages below do not take is postprocessing)
    StageTimer::Scope               t(*timer, "postprocessing");
    std::vector<ForceBalance::Body> balance;
    dealii::Vector<double>          unbalanced;
    {
      StageTimer::Scope v(*timer, "verification");
      check_displacement_scale(cycle);
      balance = verify_balance(cycle, &unbalanced);
      if (bc.has_rotations() && !finite_strain.enabled)
        report_rotations("cycles." + std::to_string(cycle) + ".", unbalanced, false);
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
        StageTimer::Scope t(*timer, "errors");
        if (distributed)
          errors = sum_over_processes(compute_errors(dof_handler, materials, solution, *exact,
                                                     partition.locally_owned_cells()),
                                      mpi_communicator);
        else
          errors = compute_errors(dof_handler, materials, solution, *exact);
      }
    {
      StageTimer::Scope v(*timer, "verification");
      check_finite_results(cycle, stresses, errors);
    }
    const std::string prefix = output_prefix(output_folder, base_name, cycle, n_cycles);
    const std::string vtu    = prefix + (distributed ? ".pvtu" : finite_strain.enabled ? ".pvd" : ".vtu");
    write_vtu_output(prefix, vtu, stresses);

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
    print_cycle(cycle, hmax, max_vm, balance);
    record_cycle(cycle, hmin, hmax, max_vm, balance, vtu, errors);
    finish_cycle(cycle);
  }



  // A displacement far beyond the size of the body means loads far too
  // large for the stiffness (or a prescribed value out of scale): say so
  // before the stresses or the error integrals overflow and take the blame.
  void
  ElasticityProblem::check_displacement_scale(const unsigned int cycle) const
  {
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
  }



  // The verification of the solve: residual and the force and moment
  // balance of the body (every edge-connected piece is part of it). At
  // finite strain the Newton solver's residual test is the check (the
  // linear balance does not hold for the deformed body): none here.
  std::vector<ForceBalance::Body>
  ElasticityProblem::verify_balance(const unsigned int cycle, dealii::Vector<double> *unbalanced) const
  {
    std::vector<ForceBalance::Body> balance;
    if (!finite_strain.enabled)
    {
      ElasticityAssembler<2> assembler(dof_handler, materials, gamma, stabilization);
      bc.add_loads(assembler);
      const double tolerance =
        (LinearSolver::parse_type(used_solver_type) == LinearSolver::Type::cg_amg ? solver_tolerance : 0.);
      balance = distributed
                  ? ForceBalance::compute(assembler, constraints, solution, dealii::Vector<double>(), tolerance,
                                          &partition.locally_owned_cells(), mpi_communicator, {}, unbalanced)
                  : ForceBalance::compute(assembler, constraints, solution, dealii::Vector<double>(), tolerance,
                                          nullptr, MPI_COMM_SELF, {}, unbalanced);
      ForceBalance::check(balance, "cycle " + std::to_string(cycle) + " (solver " + solver_description + ")");
    }
    return balance;
  }



  // Nothing non-finite is reported or written: the stresses of the cells
  // this process owns and the errors against the exact solution.
  void
  ElasticityProblem::check_finite_results(const unsigned int       cycle,
                                          const StressRecovery<2> &stresses,
                                          const ErrorNorms        &errors) const
  {
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
  }



  // The VTU file of the cycle (distributed: one piece per process and the
  // record that joins them); at finite strain every load step wrote its
  // file and the series already.
  void
  ElasticityProblem::write_vtu_output(const std::string &prefix, const std::string &vtu, const StressRecovery<2> &stresses)
  {
    if (write_vtu && !finite_strain.enabled)
      {
        StageTimer::Scope t(*timer, "output vtu");
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

  }



  // The cycle's lines on the terminal: size, solver, largest stress, the
  // verification and (distributed) the partition.
  void
  ElasticityProblem::print_cycle(const unsigned int                     cycle,
                                 const double                           hmax,
                                 const double                           max_vm,
                                 const std::vector<ForceBalance::Body> &balance) const
  {
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

  }



  // The cycle's line of the convergence table and its entries of the JSON
  // summary.
  void
  ElasticityProblem::record_cycle(const unsigned int                     cycle,
                                  const double                           hmin,
                                  const double                           hmax,
                                  const double                           max_vm,
                                  const std::vector<ForceBalance::Body> &balance,
                                  const std::string                     &vtu,
                                  const ErrorNorms                      &errors)
  {
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
    json.set(key + "timings.", timer->stages_since(cycle_start_stages));
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
  }



  // After a cycle: a warning for a mesh not finer than the last one, the
  // results kept for the program (DoFs, timings, the gathered solution),
  // the JSON summary written.
  void
  ElasticityProblem::finish_cycle(const unsigned int cycle)
  {
    if (!cycle_dofs.empty() && dof_handler.n_dofs() <= cycle_dofs.back())
      pcout << "warning: cycle " << cycle << " has " << dof_handler.n_dofs() << " DoFs, no more than cycle "
            << cycle - 1 << " (" << cycle_dofs.back()
            << "): the meshes of a convergence study must be refined from cycle to cycle (are two cycles "
               "reading the same mesh file?); the convergence rate of this cycle is not defined."
            << std::endl;
    cycle_dofs.push_back(dof_handler.n_dofs());
    last_n_dofs     = dof_handler.n_dofs();
    last_iterations = solver_iterations;
    last_timings = timer->stages_since(cycle_start_stages);
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
        StageTimer::Scope t(*timer, "output json");
        json.set("status", cycle + 1 < n_cycles ? "running" : "complete");
        json.set("timings.", timer->breakdown());
        json.write(output_folder + "/" + base_name + ".json");
        json_written = true;
      }
  }


  // The rotation parts: angle, torque and moment about the centre of each,
  // on the terminal and in the JSON summary.
  void
  ElasticityProblem::report_rotations(const std::string            &key,
                                      const dealii::Vector<double> &unbalanced,
                                      const bool                    deformed)
  {
    std::vector<dealii::Point<2>> positions(dof_handler.n_nodes());
    for (unsigned int m = 0; m < positions.size(); ++m)
      {
        positions[m] = dof_handler.node_location(m);
        if (deformed)
          for (unsigned int c = 0; c < 2; ++c)
            positions[m][c] += solution[VEMDoFHandler<2>::node_dof(m, c)];
      }
    const auto rotations = bc.rotation_results(rotation_parts, constraints, solution, unbalanced, positions);
    RotationOutput::print(pcout, rotations, "    ");
    RotationOutput::json(json, key + "rotations.", rotations);
  }
} // namespace dealvem
