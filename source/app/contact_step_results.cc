// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// ContactProblem: the results of a converged load step (pair results,
// interface resultants, verification) and of the cycle.
#include "contact_problem_internal.h"

namespace dealvem
{
  using namespace internal::ContactProblemImplementation;



  // The results of a converged load step, in five steps: (1) the solve's
  // figures into Results, (2) the result of every node pair with the
  // recovered tractions, (3) the resultant of every interface, (4) the
  // refusal of anything non-finite and the verification, (5) the progress
  // line and (with several steps) the step's files.
  void
  ContactProblem::process_step(const unsigned int step, const double time)
  {
    const CycleData &d        = *data;
    const bool       friction = contact_settings.is_coulomb();
    store_solve_results();

    // the tangential nodal force on the slave node, along t
    std::vector<double> tangential_force(d.pairs.size(), 0.);
    {
      const auto ft = friction ? std::vector<double>() : d.contact->tangential_forces(d.x);
      for (unsigned int i = 0; i < d.pairs.size(); ++i)
        tangential_force[i] = (friction ? -d.solve_result.tangential_multiplier[i] : ft[i]);
    }
    StepResult step_result = make_pair_results(step, time, tangential_force);
    make_interface_resultants(step_result);
    results.interface_results       = step_result.interfaces;
    step_result.dissipated_energy   = (friction ? d.solve_result.dissipated_energy : 0.);
    step_result.total_contact_force = results.total_contact_force;
    step_result.pairs               = results.pairs;
    results.dissipated_energy += step_result.dissipated_energy;

    {
      StageTimer::Scope t(data->timer, "verification");
      check_step_finite(step, time, step_result);
      verify_step(step, time, tangential_force, step_result);
    }
    results.steps.push_back(step_result);

    if (opt.n_load_steps > 1 || friction)
      print_step(step, time, step_result);
    if (opt.n_load_steps > 1)
      output_step(step);
  }



  // Step 1 of process_step(): the displacements, sizes, iteration counts
  // and solver of the solve into Results.
  void
  ContactProblem::store_solve_results()
  {
    const CycleData &d = *data;
    const auto      &n = d.n;
    const auto      &x  = d.x;
    const auto      &as = d.solve_result;
    results.solution.reinit(n);
    for (unsigned int i = 0; i < n; ++i)
      results.solution[i] = x[i];
    results.n_dofs                = n;
    results.n_multipliers         = d.m;
    results.active_set_iterations = as.n_iterations;
    results.active_set_history    = as.n_active_history;
    results.linear_iterations     = as.linear_iterations;
    results.solver                = d.solver->description();
    results.n_processes           = n_processes;
    if (d.distributed_solver != nullptr)
      results.n_rows_across_processes = d.distributed_solver->last_rows_across_processes();
  }



  // Step 2 of process_step(): per node pair the gap, slip, multiplier,
  // recovered pressure and shear (InterfaceTractions) and state; the
  // step's counts and the total contact force.
  ContactProblem::StepResult
  ContactProblem::make_pair_results(const unsigned int         step,
                                    const double               time,
                                    const std::vector<double> &tangential_force)
  {
    const CycleData &d        = *data;
    const auto      &x        = d.x;
    const auto      &as       = d.solve_result;
    const auto      &fr       = d.solve_result;
    const auto      &state    = d.solve_result.state;
    const auto      &pairs    = d.pairs;
    const bool       friction = contact_settings.is_coulomb();
    const auto       gaps     = d.contact->gaps(x);
    const auto       slips    = d.contact->slips(x);
    // the normal nodal forces -lambda and the tangential ones, recovered as
    // tractions interface by interface
    const ContactRows   rows = d.contact->rows();
    std::vector<double> normal_force(pairs.size());
    for (unsigned int i = 0; i < pairs.size(); ++i)
      normal_force[i] = -rows.normal_multiplier(x, i);
    const auto  tractions       = InterfaceTractions::recover(results.interfaces, normal_force, tangential_force, as.active);
    const auto &recovered       = tractions.pressure;
    const auto &recovered_shear = tractions.shear;
    results.pairs.clear();
    results.total_contact_force = dealii::Tensor<1, 2>();
    StepResult step_result;
    step_result.step       = step;
    step_result.time       = time;
    step_result.iterations = as.n_iterations;
    if (friction)
      {
        step_result.fixed_point_iterations = fr.n_fixed_point_iterations;
        step_result.continuation_factors   = fr.continuation_factors.size();
      }
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto &p = pairs[i];
        PairResult  r;
        r.interface       = p.interface;
        r.location        = p.slave_location;
        r.midpoint        = p.on_edge();
        r.active          = as.active[i];
        r.weight          = p.weight;
        r.gap             = gaps[i];
        r.multiplier      = rows.normal_multiplier(x, i);
        r.lumped_pressure = -rows.normal_multiplier(x, i) / p.weight;
        r.pressure        = recovered[i];
        r.at_open_end     = p.at_open_end;
        r.slip            = slips[i];
        r.tangent         = p.tangent;
        r.shear           = recovered_shear[i];
        r.normal          = p.normal;
        // (the convex stick model of the globalized solve ties open pairs
        // tangentially too, and the fast path the pairs it tied after a
        // cycle: their tangential force counts)
        r.tangential_traction = (as.tied_tangentially(i) ? tangential_force[i] / p.weight : 0.);
        if (friction)
          {
            r.slip_increment      = fr.slip_increment[i];
            r.status              = (state[i] == PairState::open ? "open" :
                                     state[i] == PairState::stick ? "stick" :
                                                                    "slip");
          }
        else
          r.status = (as.active[i] ? "closed" : as.tied_tangentially(i) ? "open-tied" : "open");
        step_result.n_open += (!r.active);
        step_result.n_stick += (r.active && r.status != "slip");
        step_result.n_slip += (r.status == "slip");
        results.pairs.push_back(r);
        results.total_contact_force +=
          (-rows.normal_multiplier(x, i)) * p.normal + r.tangential_traction * p.weight * p.tangent;
      }
    return step_result;
  }



  // Step 3 of process_step(): the resultant of every interface (force,
  // moment about Options::moment_point, centre of pressure, pair states)
  // from the node pairs' results of the step.
  void
  ContactProblem::make_interface_resultants(StepResult &step_result) const
  {
    const CycleData  &d          = *data;
    const auto       &x          = d.x;
    const auto       &pairs      = d.pairs;
    const auto       &interfaces = results.interfaces;
    const ContactRows rows       = d.contact->rows();
    step_result.interfaces.assign(interfaces.size(), InterfaceResult());
    {
      std::vector<double> moment_weight(interfaces.size(), 0.);
      std::vector<dealii::Tensor<1, 2>> weighted_location(interfaces.size()), mean_location(interfaces.size());
      std::vector<double> total_weight(interfaces.size(), 0.);
      for (unsigned int k = 0; k < interfaces.size(); ++k)
        {
          auto &ir       = step_result.interfaces[k];
          ir.master_body = d.interface_bodies[k][0];
          ir.slave_body  = d.interface_bodies[k][1];
          ir.master_id   = cycle_pairs[k].first;
          ir.slave_id    = cycle_pairs[k].second;
          ir.detected    = (k >= contact_pairs.size());
          if (contact_settings.tangential == ContactSettings::Tangential::coulomb ||
              contact_settings.tangential == ContactSettings::Tangential::coulomb_penalty)
            ir.friction_coefficient = contact_settings.friction_coefficient_of(k);
        }
      for (unsigned int i = 0; i < pairs.size(); ++i)
        {
          const auto        &p  = pairs[i];
          const PairResult  &r  = results.pairs[i];
          const unsigned int k  = p.interface;
          auto              &ir = step_result.interfaces[k];
          const double       N  = -rows.normal_multiplier(x, i);
          const double       T  = r.tangential_traction * p.weight;
          ir.length += p.weight;
          ir.normal_force += N;
          ir.tangential_force += T;
          ir.force += N * p.normal + T * p.tangent;
          ir.moment += SupportReactions::moment(r.location, N * p.normal + T * p.tangent, opt.moment_point);
          weighted_location[k] += N * r.location;
          moment_weight[k] += N;
          mean_location[k] += p.weight * r.location;
          total_weight[k] += p.weight;
          ir.n_open += (!r.active);
          ir.n_stick += (r.active && r.status != "slip");
          ir.n_slip += (r.status == "slip");
        }
      for (unsigned int k = 0; k < interfaces.size(); ++k)
        {
          auto &ir = step_result.interfaces[k];
          // the centre of the normal forces; without compression, the middle
          // of the interface
          ir.centre_of_pressure = (moment_weight[k] > 0 ?
                                     dealii::Point<2>(weighted_location[k] / moment_weight[k]) :
                                     dealii::Point<2>(mean_location[k] / std::max(total_weight[k], 1e-300)));
        }
    }
  }



  // Step 4 of process_step(): nothing non-finite is reported or written; a
  // quantity that overflowed stops the run here, named, before any file of
  // the step is written.
  void
  ContactProblem::check_step_finite(const unsigned int step, const double time, const StepResult &step_result) const
  {
    const auto &n = data->n;
    const auto &x = data->x;
    {
      const auto refuse = [&](const std::string &quantity, const double value) {
        std::ostringstream msg;
        msg << "Load step " << step << " (t = " << time << "): the " << quantity << " is " << value
            << ". The solution overflowed double precision (or the solve failed); check the loads, the "
               "Dirichlet values, 'Load steps/Final time' and the Young's moduli for values far from 1 in "
               "the units of the problem.";
        AssertThrow(false, dealii::ExcMessage(msg.str()));
      };
      for (unsigned int i = 0; i < x.size(); ++i)
        if (!std::isfinite(x[i]))
          refuse(i < n ? "displacement DoF " + std::to_string(i) :
                         "contact multiplier " + std::to_string(i - n),
                 x[i]);
      // a displacement far beyond the size of the bodies: loads out of
      // scale with the stiffness
      {
        const auto      &vertices = results.mesh.get_vertices();
        dealii::Point<2> lo = vertices[0], hi = vertices[0];
        for (const auto &p : vertices)
          for (unsigned int c = 0; c < 2; ++c)
            {
              lo[c] = std::min(lo[c], p[c]);
              hi[c] = std::max(hi[c], p[c]);
            }
        const double size = lo.distance(hi);
        for (unsigned int i = 0; i < n; ++i)
          if (std::abs(x[i]) > BoundaryConditionParameters::max_displacement_ratio * size)
            {
              std::ostringstream msg;
              msg << "Load step " << step << " (t = " << time << "): the displacement of DoF " << i << " is "
                  << x[i] << ", more than " << BoundaryConditionParameters::max_displacement_ratio
                  << " times the size of the meshes (" << size
                  << "): far outside the small-displacement model. The loads are out of scale with the "
                     "stiffness: check 'Boundary conditions and loads' (Traction, Pressure, Body force, Rigid "
                     "boundary) against the Young's moduli, or a body held by a stick penalty alone.";
              AssertThrow(false, dealii::ExcMessage(msg.str()));
            }
      }
      for (const auto &r : results.pairs)
        for (const auto &[name, v] : std::vector<std::pair<std::string, double>>{
               {"pressure", r.pressure}, {"shear", r.shear}, {"gap", r.gap}, {"slip", r.slip},
               {"slip increment", r.slip_increment}})
          if (!std::isfinite(v))
            {
              std::ostringstream where;
              where << name << " of the contact pair at (" << r.location[0] << ", " << r.location[1] << ")";
              refuse(where.str(), v);
            }
      if (!std::isfinite(step_result.dissipated_energy))
        refuse("dissipated energy of the step", step_result.dissipated_energy);
      if (!std::isfinite(results.dissipated_energy))
        refuse("dissipated energy summed over the steps", results.dissipated_energy);
      for (unsigned int d = 0; d < 2; ++d)
        if (!std::isfinite(results.total_contact_force[d]))
          refuse(std::string("total contact force (") + (d == 0 ? "x" : "y") + " component)",
                 results.total_contact_force[d]);
    }
  }



  // Step 5 of process_step(): the progress line of a load step (with
  // several steps or with Coulomb friction) and its support reactions.
  void
  ContactProblem::print_step(const unsigned int step, const double time, const StepResult &step_result) const
  {
    const auto &as       = data->solve_result;
    const auto &fr       = data->solve_result;
    const bool  friction = contact_settings.is_coulomb();
    pcout << "  load step " << step << " of " << opt.n_load_steps << ", t = " << time << ": "
              << as.n_iterations << (friction ? " Newton" : " active-set") << " iteration(s), "
              << step_result.n_open << " open / " << step_result.n_stick
              << (friction ? " stick / " : " closed") ;
    if (friction)
      {
        pcout << step_result.n_slip << " slip, dissipated energy " << step_result.dissipated_energy;
        if (fr.history.size() > 1)
          {
            // the states each iteration solved with
            pcout << " (open/stick/slip per iteration:";
            for (const auto &h : fr.history)
              pcout << " " << h[0] << "/" << h[1] << "/" << h[2];
            pcout << ")";
          }
        if (!fr.continuation_factors.empty())
          {
            // the plain Newton iteration failed; the continuation in the
            // friction coefficient passed these factors of mu
            pcout << "; continuation in the friction coefficient, " << fr.n_failed_attempts
                      << " failed attempt(s), converged with mu times";
            for (const double f : fr.continuation_factors)
              pcout << " " << f;
          }
        else if (fr.globalized_start)
          pcout << "; the Newton iteration failed, solved as a fixed point of "
                    << fr.n_fixed_point_iterations << " Tresca problem(s) (globally convergent; "
                    << fr.n_globalized_solves << " solves with the stick solve)";
      }
    pcout << std::endl;
    print_reactions(pcout, step_result.reactions, opt.moment_point, "    ");
    RotationOutput::print(pcout, step_result.rotations, "    ");
  }


  // The verification of a converged step: the residual and the force and
  // moment balance of every body (ForceBalance: applied loads, support
  // reactions and contact forces), and no active pair in tension at
  // convergence of unilateral contact. A violation stops the run with the
  // figures; the figures of a passed step go to the JSON summary.
  void
  ContactProblem::verify_step(const unsigned int         step,
                              const double               time,
                              const std::vector<double> &tangential_force,
                              StepResult                &step_result) const
  {
    const CycleData   &d     = *data;
    const auto        &n     = d.n;
    const ContactRows  rows  = d.contact->rows();
    const auto        &x     = d.x;
    const auto        &pairs = d.pairs;
    std::ostringstream where;
    where << (opt.n_load_steps > 1 ? "load step " + std::to_string(step) + " of " + std::to_string(opt.n_load_steps) : "the contact problem")
          << " (t = " << time << ", " << d.solve_result.n_iterations
          << (contact_settings.is_coulomb() ? " Newton" : " active-set") << " iteration(s), solver " << d.solver->description()
          << ")";
    // the nodal contact forces: on the slave node -lambda_n n + f_t t, the
    // opposite on the master node (as the reported contact force)
    dealii::Vector<double> contact_forces(n);
    std::vector<std::pair<dealii::types::global_dof_index, dealii::types::global_dof_index>> couplings;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto                 dofs = d.contact->pair_dofs(i);
        const bool                 transmits = d.solve_result.tied_tangentially(i);
        if (transmits)
          for (unsigned int c = 0; c < 2; ++c)
            couplings.emplace_back(dofs[c], dofs[2 + c]);
        const dealii::Tensor<1, 2> F =
          (-rows.normal_multiplier(x, i)) * pairs[i].normal + (transmits ? tangential_force[i] : 0.) * pairs[i].tangent;
        for (unsigned int c = 0; c < 2; ++c)
          {
            contact_forces[dofs[2 + c]] += F[c];
            contact_forces[dofs[c]] -= F[c];
          }
      }
    dealii::Vector<double> u(n);
    for (unsigned int i = 0; i < n; ++i)
      u[i] = x[i];
    // (a factorization of the whole saddle point)
    const bool   direct    = !SaddlePointSolver::is_iterative(d.solver->get_type()) &&
                         !SaddlePointSolver::is_condensed(d.solver->get_type());
    const double tolerance = direct ? 0. : opt.solver_tolerance;
    dealii::Vector<double> unbalanced;
    const auto             balance =
      (d.partition ? ForceBalance::compute(*d.assembler, d.constraints, u, contact_forces, tolerance,
                                           &d.partition->locally_owned_cells(), mpi_communicator, couplings,
                                           &unbalanced) :
                     ForceBalance::compute(*d.assembler, d.constraints, u, contact_forces, tolerance, nullptr,
                                           MPI_COMM_SELF, couplings, &unbalanced));
    ForceBalance::check(balance, where.str());
    for (const auto &b : balance)
      step_result.balance.push_back({b.body, b.imbalance, b.residual, b.tolerance, b.condition});
    // the reaction of every support (small strain: about the nodes'
    // positions in the undeformed configuration)
    {
      std::vector<dealii::Point<2>> positions(d.dof_handler.n_nodes());
      for (unsigned int m = 0; m < positions.size(); ++m)
        positions[m] = d.dof_handler.node_location(m);
      step_result.reactions =
        SupportReactions::compute(d.supports, d.constraints, unbalanced, positions, opt.moment_point);
      step_result.rotations = bc.rotation_results(d.rotation_parts, d.constraints, u, unbalanced, positions);
    }

    // an active pair of unilateral contact in tension contradicts the
    // converged active set (and friction's open/stick/slip states)
    if (contact_settings.normal == ContactSettings::Normal::unilateral)
      {
        double largest = 0;
        for (unsigned int i = 0; i < pairs.size(); ++i)
          largest = std::max(largest, std::abs(rows.normal_multiplier(x, i)) / pairs[i].weight);
        for (unsigned int i = 0; i < pairs.size(); ++i)
          if (d.solve_result.active[i] && -rows.normal_multiplier(x, i) / pairs[i].weight < -1e-8 * largest)
            {
              std::ostringstream msg;
              msg << "Verification failed after the solve of " << where.str() << ": the active contact pair at ("
                  << pairs[i].slave_location[0] << ", " << pairs[i].slave_location[1] << ") of interface "
                  << pairs[i].interface << " carries a tensile normal force (pressure "
                  << -rows.normal_multiplier(x, i) / pairs[i].weight << ", largest magnitude " << largest
                  << "), although the converged active set keeps only pairs in compression. The solve is not "
                     "accurate enough for the contact decisions; bring the Young's moduli of the bodies closer "
                     "together.";
              AssertThrow(false, dealii::ExcMessage(msg.str()));
            }
      }
  }



  // After the last step: cells and DoFs per body, the errors against the
  // exact solutions, the stresses.
  void
  ContactProblem::postprocess()
  {
    CycleData        &d    = *data;
    PolygonalMesh<2> &mesh = results.mesh;
    results.n_dropped_constraints = d.contact->get_dropped_constraints().size();
    results.n_open_end_warnings   = 0;
    for (const auto &r : results.pairs)
      results.n_open_end_warnings += (r.active && r.at_open_end);
    // per body: cells, DoFs, and errors against the exact solution
    results.cells_per_body.assign(bodies.size(), 0);
    results.dofs_per_body.assign(bodies.size(), 0);
    results.errors.assign(bodies.size(), ErrorNorms());
    {
      std::vector<unsigned int> node_body(d.dof_handler.n_nodes(), 0), nodes;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          ++results.cells_per_body[mesh.cell(c).material_id];
          d.dof_handler.get_node_indices(c, nodes);
          for (const auto nd : nodes)
            node_body[nd] = mesh.cell(c).material_id;
        }
      for (const auto b : node_body)
        results.dofs_per_body[b] += 2;
    }
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (!InputParsing::trim(bodies[b].exact).empty())
        {
          const std::string name = (b == 0 ? std::string("Exact solution/Displacement") :
                                             "Body " + std::to_string(b) + "/Exact solution/Displacement");
          const auto        parts = InputParsing::split(bodies[b].exact, ',');
          AssertThrow(parts.size() == 2,
                      dealii::ExcMessage("Parameter '" + name + "' needs two expressions 'ux, uy'."));
          // the solution is the one of the last load step, at t = final time
          InputParsing::ParsedFunction exact(parts, bc.get_constants(), name);
          exact.set_time(opt.final_time);
          results.errors[b] = compute_errors(d.dof_handler, d.materials, results.solution, exact,
                                             dealii::types::material_id(b));
          for (const double v : {results.errors[b].l2, results.errors[b].h1_seminorm, results.errors[b].energy})
            AssertThrow(std::isfinite(v),
                        dealii::ExcMessage("Parameter '" + name + "': the error against '" + bodies[b].exact +
                                           "' is not finite; the exact solution evaluates to inf or NaN "
                                           "somewhere in body " + std::to_string(b) + "."));
        }

    d.stresses = std::make_unique<StressRecovery<2>>(d.dof_handler, d.materials, results.solution);
    const auto &stresses = *d.stresses;
    results.cell_stress.resize(mesh.n_cells());
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const auto s          = stresses.cell_stress(c);
        results.cell_stress[c] = {{s[0][0], s[1][1], s[0][1]}};
      }

    results.timings = d.timer.stages();

  }
} // namespace dealvem
