// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// ContactProblem: construction, run() and the solve pipeline of one
// refinement cycle (meshes, node insertion, DoFs, assembly, solve).
#include "contact_problem_internal.h"

#include <dealvem/solvers/p_multigrid.h>
#include <dealvem/vem/vem_element_data.h>

namespace dealvem
{
  using namespace internal::ContactProblemImplementation;

  ContactProblem::ContactProblem(const MPI_Comm comm, const ElasticityProblem::Parallelism parallelism)
    : mpi_communicator(comm)
    // (a program that never initialised MPI runs serially)
    , n_processes(dealii::Utilities::MPI::job_supports_mpi() ? dealii::Utilities::MPI::n_mpi_processes(comm) : 1)
    , distributed(parallelism == ElasticityProblem::Parallelism::distributed ||
                  (parallelism == ElasticityProblem::Parallelism::automatic && n_processes > 1))
    , root(!dealii::Utilities::MPI::job_supports_mpi() || dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    , pcout(std::cout, root)
  {
    AssertThrow(!distributed || dealii::Utilities::MPI::job_supports_mpi(),
                dealii::ExcMessage("ContactProblem: the distributed path needs MPI to be initialised "
                                   "(dealii::Utilities::MPI::MPI_InitFinalize in main())."));
  }

  ContactProblem::~ContactProblem() = default;



  void
  ContactProblem::run()
  {
    check_setup();
    // (the friction coefficients of the pairs are set per cycle, when the
    // detected interfaces are known: insert_nodes())
    contact_settings = opt.contact;
    // with several MPI processes every process computes the same
    // postprocessing from the gathered solution; process 0 alone prints
    // (pcout) and writes: the other processes' write flags are off during
    // the run (restored on the way out, also after an error)
    struct QuietFiles
    {
      ContactProblem     &p;
      std::array<bool, 4> flags;
      QuietFiles(ContactProblem &p)
        : p(p)
        , flags{{p.opt.write_vtu, p.opt.write_csv, p.opt.write_json, p.opt.write_pictures}}
      {
        if (!p.root)
          p.opt.write_vtu = p.opt.write_csv = p.opt.write_json = p.opt.write_pictures = false;
      }
      ~QuietFiles()
      {
        p.opt.write_vtu      = flags[0];
        p.opt.write_csv      = flags[1];
        p.opt.write_json     = flags[2];
        p.opt.write_pictures = flags[3];
      }
    } quiet_files(*this);
    // the files under the output prefix belong to this run only: those of
    // an earlier run go first (process 0 writes every file)
    RunOutput output;
    output.folder       = opt.output_folder;
    output.base_name    = opt.base_name;
    output.writer       = root;
    output.writes_files = opt.write_vtu || opt.write_csv || opt.write_json || opt.write_pictures;
    run_with_files(output, [this](const std::string &note) { pcout << note; },
                   [this]() {
                     if (design.enabled())
                       run_design_cycle();
                     else if (opt.finite_strain)
                       run_finite_sliding();
                     else
                       run_cycles();
                   });
  }



  void
  ContactProblem::run_cycles()
  {
    convergence.clear();
    bool any_exact = false;
    for (const auto &b : bodies)
      any_exact = any_exact || !InputParsing::trim(b.exact).empty();
    std::vector<dealii::ConvergenceTable> tables(bodies.size());
    std::vector<std::vector<double>>      dofs_per_cycle(bodies.size());
    for (unsigned int cycle = 0; cycle < n_cycles; ++cycle)
      {
        if (n_cycles > 1)
          pcout << "Cycle " << cycle << ":" << std::endl;
        run_cycle(cycle);
        convergence.push_back(results.errors);
        for (unsigned int b = 0; b < bodies.size(); ++b)
          {
            if (cycle > 0 && results.dofs_per_body[b] <= dofs_per_cycle[b].back())
              pcout << "warning: body " << b << " has " << results.dofs_per_body[b]
                        << " DoFs in cycle " << cycle << ", no more than in cycle " << cycle - 1
                        << ": the meshes of a convergence study must be refined from cycle to cycle (are "
                           "two cycles reading the same mesh file?); the convergence rate of this cycle is "
                           "not defined."
                        << std::endl;
            dofs_per_cycle[b].push_back(results.dofs_per_body[b]);
          }
        if (any_exact)
          for (unsigned int b = 0; b < bodies.size(); ++b)
            if (!InputParsing::trim(bodies[b].exact).empty())
              {
                const auto &e = results.errors[b];
                tables[b].add_value("cycle", cycle);
                tables[b].add_value("cells", results.cells_per_body[b]);
                tables[b].add_value("dofs", results.dofs_per_body[b]);
                tables[b].add_value("L2", e.l2 / std::max(e.l2_exact, 1e-300));
                tables[b].add_value("H1", e.h1_seminorm / std::max(e.h1_exact, 1e-300));
                tables[b].add_value("energy", e.energy / std::max(e.energy_exact, 1e-300));
              }
      }
    if (any_exact)
      for (unsigned int b = 0; b < bodies.size(); ++b)
        if (!InputParsing::trim(bodies[b].exact).empty())
          {
            auto &t = tables[b];
            for (const char *c : {"L2", "H1", "energy"})
              {
                t.set_scientific(c, true);
                t.set_precision(c, 3);
              }
            if (n_cycles > 1)
              {
                std::vector<double> dofs;
                std::map<std::string, std::vector<double>> errors;
                for (const auto &e : convergence)
                  {
                    errors["L2"].push_back(e[b].l2 / std::max(e[b].l2_exact, 1e-300));
                    errors["H1"].push_back(e[b].h1_seminorm / std::max(e[b].h1_exact, 1e-300));
                    errors["energy"].push_back(e[b].energy / std::max(e[b].energy_exact, 1e-300));
                  }
                for (const double n : dofs_per_cycle[b])
                  dofs.push_back(n);
                for (const char *c : {"L2", "H1", "energy"})
                  add_convergence_rates(t, c, errors[c], dofs);
              }
            pcout << "Relative errors of body " << b << " (against its exact solution):" << std::endl;
            if (pcout.is_active())
              t.write_text(pcout.get_stream(), dealii::TableHandler::org_mode_table);
          }
  }



  void
  ContactProblem::run_cycle(const unsigned int cycle)
  {
    // the previous cycle's objects refer to the previous mesh: release
    // them before the mesh goes
    data.reset();
    results = Results();
    data    = std::make_unique<CycleData>();
    data->prefix = output_prefix(opt.output_folder, opt.base_name, cycle, n_cycles);

    // the stages of the cycle's timings (the functions time the parts that
    // belong to another stage themselves: contact detection, the sparsity
    // pattern as assembly, the verification and files of a step)
    StageTimer &timer = data->timer;
    make_meshes(cycle);
    insert_nodes();
    {
      StageTimer::Scope t(timer, "setup");
      setup_system();
    }
    for (unsigned int step = 1; step <= opt.n_load_steps; ++step)
      {
        const double time = opt.final_time * step / opt.n_load_steps;
        assemble_system(time);
        solve(step, time);
        StageTimer::Scope t(timer, "postprocessing");
        process_step(step, time);
      }
    {
      StageTimer::Scope t(timer, "postprocessing");
      postprocess();
    }
    output_results();
  }



  // Topology optimization of the bodies of cycle 0 with their contact
  // pairs (explicit and detected), supports and loads at the final time.
  void
  ContactProblem::run_design_cycle()
  {
    AssertThrow(dealii::Utilities::MPI::n_mpi_processes(mpi_communicator) == 1,
                dealii::ExcMessage("Design/Objective: topology optimization runs on one MPI process."));
    data.reset();
    results      = Results();
    data         = std::make_unique<CycleData>();
    data->prefix = output_prefix(opt.output_folder, opt.base_name, 0, 1);
    make_meshes(0);
    find_contact_pairs();
    bc.set_time(opt.final_time);
    DesignInputs inputs;
    inputs.mesh             = &results.mesh;
    inputs.laws             = &data->materials;
    inputs.degree           = opt.degree;
    inputs.interfaces       = cycle_pairs;
    inputs.contact          = contact_settings;
    inputs.insertion        = opt.insertion;
    inputs.bc               = &bc;
    inputs.solver           = opt.solver;
    inputs.solver_tolerance = opt.solver_tolerance;
    inputs.prefix           = data->prefix;
    inputs.write_vtu        = opt.write_vtu;
    inputs.write_pictures   = opt.write_pictures;
    inputs.write_csv        = opt.write_csv;
    std::ostream null_stream(nullptr); // not process 0: print nothing
    run_design(design, inputs, pcout.is_active() ? pcout.get_stream() : null_stream);
  }



  // The bodies' meshes, one material id per body, appended into one mesh.
  void
  ContactProblem::make_meshes(const unsigned int cycle)
  {
    StageTimer::Scope t(data->timer, "mesh");
    make_body_meshes(cycle, results.mesh, data->materials);
    data->original_vertices = results.mesh.get_vertices();
  }



  void
  ContactProblem::make_body_meshes(const unsigned int cycle, PolygonalMesh<2> &mesh, MaterialLibrary<2> &laws) const
  {
    // the meshes of the bodies, appended at once (one validation)
    std::vector<PolygonalMesh<2>> made(bodies.size());
    std::vector<const PolygonalMesh<2> *> parts;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        if (bodies[b].given)
          made[b] = *bodies[b].given;
        else
          bodies[b].mesh.create_mesh(made[b], cycle, prm_directory);
        for (unsigned int c = 0; c < made[b].n_cells(); ++c)
          made[b].set_material_id(c, b);
        if (b > 0)
          parts.push_back(&made[b]);
        laws.add(b, bodies[b].material);
      }
    mesh = std::move(made[0]);
    if (!parts.empty())
      mesh.append(parts);
    mesh.name = "bodies";
  }



  // Node insertion on every contact pair of boundary ids, then the node
  // pairs of all interfaces in one list.
  void
  ContactProblem::insert_nodes()
  {
    StageTimer::Scope t(data->timer, "node insertion");
    find_contact_pairs();
    PolygonalMesh<2> &mesh       = results.mesh;
    auto             &interfaces = results.interfaces;
    // the interfaces one after the other on one search structure of the
    // boundary edges, the mesh validated once after the last (the cost
    // grows with the interfaces' sizes, not their number times the mesh)
    {
      NodeInsertion::Settings settings = opt.insertion;
      settings.validate_mesh           = false;
      auto edges                       = NodeInsertion::boundary_edges(mesh);
      for (unsigned int i = 0; i < cycle_pairs.size(); ++i)
        interfaces.push_back(NodeInsertion::insert(mesh, cycle_pairs[i].first, cycle_pairs[i].second, opt.degree,
                                                   settings, i, &edges));
      try
        {
          mesh.validate();
        }
      catch (const std::exception &e)
        {
          AssertThrow(false, dealii::ExcMessage("Node insertion: moving the interface vertices onto their "
                                                "partners made a cell invalid (the meshes of the two sides are "
                                                "too far apart for their cells, or too coarse for the "
                                                "curvature): " +
                                                std::string(e.what())));
        }
    }
    // a later interface may have moved a vertex shared with an earlier one
    for (auto &itf : interfaces)
      NodeInsertion::update_geometry(mesh, itf);
    for (const auto &itf : interfaces)
      {
        results.insertion_reports.push_back(itf.report);
        data->pairs.insert(data->pairs.end(), itf.pairs.begin(), itf.pairs.end());
      }
    // where three bodies meet, the pair that repeats the two others stays
    // open (unilateral and Coulomb contact)
    results.n_junction_pairs = NodeInsertion::mark_junctions(data->pairs, mesh);
    bool any_segment = false;
    for (const auto &itf : interfaces)
      any_segment = any_segment || !itf.segments.empty();
    AssertThrow(!data->pairs.empty() && any_segment,
                dealii::ExcMessage("Contact: node insertion found no paired interface edge on any contact "
                                   "pair; check the 'Contact/Pairs' ids and the 'Search distance'."));
  }



  // The contact pairs of boundary ids of this cycle: the explicit ones, then
  // those ContactDetection finds on the mesh before node insertion; the
  // friction coefficient of each.
  void
  ContactProblem::find_contact_pairs()
  {
    PolygonalMesh<2> &mesh = results.mesh;
    // the explicit pairs, then the detected ones
    cycle_pairs    = contact_pairs;
    cycle_friction = pair_friction;
    if (opt.detect_pairs)
      {
        StageTimer::Scope detection_timer(data->timer, "contact detection");
        std::set<dealii::types::boundary_id> excluded = bc.used_boundary_ids();
        for (const auto &p : contact_pairs)
          excluded.insert({p.first, p.second});
        results.detection = ContactDetection::detect(mesh, excluded, ContactDetection::first_free_id(mesh),
                                                     opt.detection);
        pcout << ContactDetection::describe(results.detection);
        AssertThrow(!results.detection.interfaces.empty() || !contact_pairs.empty(),
                    dealii::ExcMessage("Contact/Pairs = auto: no boundary parts of different bodies face each "
                                       "other within 'Contact/Detection distance' (" +
                                       internal::number_string(opt.detection.distance) +
                                       " times the edge length) and 'Detection angle' (" +
                                       internal::number_string(opt.detection.max_angle) +
                                       " degrees); the edges whose ids carry boundary conditions are not "
                                       "candidates."));
        for (const auto &itf : results.detection.interfaces)
          {
            cycle_pairs.emplace_back(itf.master_id, itf.slave_id);
            cycle_friction.push_back(-1);
          }
      }
    // the bodies of each interface; friction between bodies for the pairs
    // without a coefficient of their own
    {
      std::map<dealii::types::boundary_id, unsigned int> body_of_id;
      for (unsigned int e = 0; e < mesh.n_edges(); ++e)
        if (mesh.edge(e).at_boundary())
          body_of_id.emplace(mesh.edge(e).boundary_id, mesh.cell(mesh.edge(e).cells[0]).material_id);
      const unsigned int none = dealii::numbers::invalid_unsigned_int;
      data->interface_bodies.clear();
      for (unsigned int i = 0; i < cycle_pairs.size(); ++i)
        {
          const auto a = body_of_id.find(cycle_pairs[i].first), b = body_of_id.find(cycle_pairs[i].second);
          data->interface_bodies.push_back({{a == body_of_id.end() ? none : a->second,
                                             b == body_of_id.end() ? none : b->second}});
          if (cycle_friction[i] < 0 && a != body_of_id.end() && b != body_of_id.end())
            cycle_friction[i] = friction_between(a->second, b->second);
        }
    }
    contact_settings.friction_coefficients = cycle_friction;
  }



  // DoFs; the contact scales (one rule, ContactScales); the contact
  // assembler; the displacement constraints at the first load step,
  // checked with the contact pairs to hold every body; the sparsity
  // pattern of the saddle-point system; the solvers.
  void
  ContactProblem::setup_system()
  {
    CycleData &d = *data;
    d.dof_handler.reinit(results.mesh);
    d.dof_handler.distribute_dofs(VEMElementData(opt.degree));

    const ContactScales scales(d.materials, results.interfaces);
    if (contact_settings.tangential == ContactSettings::Tangential::penalty ||
        contact_settings.tangential == ContactSettings::Tangential::coulomb_penalty)
      scales.check_penalty(contact_settings, "Contact/Penalty", "Contact/Penalty factor");
    d.complementarity = scales.complementarity_constant();
    results.penalty   = scales.penalty(contact_settings);
    d.contact = std::make_unique<ContactAssembler<2>>(d.dof_handler, d.pairs, contact_settings, results.penalty);

    bc.check_boundary_ids(results.mesh);
    bc.set_time(opt.final_time / opt.n_load_steps);
    d.constraints.clear();
    bc.apply_constraints(d.dof_handler, d.constraints);
    d.constraints.close();
    // every body must be held by the constraints and the contact pairs
    // together (with every pair closed); the active set checks its sets too
    d.support = std::make_unique<RigidBodySupport>(d.dof_handler, d.constraints, *d.contact,
                                                   contact_settings.tangential !=
                                                     ContactSettings::Tangential::frictionless);
    {
      const std::string free = d.support->free_motions(std::vector<bool>(d.contact->n_pairs(), true));
      AssertThrow(free.empty(),
                  dealii::ExcMessage("Unsupported body / rigid-body mode: the constraints and contact pairs "
                                     "leave these rigid-body motions free: " + free +
                                     ". Add Dirichlet, roller or point constraints (with frictionless contact, "
                                     "each body must be held against sliding along the interface)."));
    }

    d.n = d.dof_handler.n_dofs();
    d.m = d.contact->n_multipliers();
    {
      StageTimer::Scope t(d.timer, "assembly");
      dealii::DynamicSparsityPattern dsp(d.n + d.m);
      // distributed: the stiffness is assembled per process by the solver,
      // this matrix holds only the contact blocks
      if (!distributed)
        d.dof_handler.make_sparsity_pattern(dsp);
      d.contact->add_sparsity(dsp);
      d.constraints.condense(dsp);
      d.sparsity.copy_from(dsp);
      d.system_matrix.reinit(d.sparsity);
      // (made at the first solve, for a contact solver that needs one)
      d.work_matrix.clear();
    }

    SaddlePointSolver::Settings settings;
    if (opt.solver == "automatic")
      {
        // the condensed solves need symmetric contact rows; Coulomb's slip
        // rows are not: the whole saddle point by UMFPACK
        std::ostringstream why;
        if (!dealii::Utilities::MPI::job_supports_mpi())
          {
            // (a program without MPI_InitFinalize: Trilinos' AMG would abort)
            settings.type = SaddlePointSolver::Type::direct_constraints;
            why << "MPI is not initialized (no dealii::Utilities::MPI::MPI_InitFinalize in main()), so "
                   "Trilinos' AMG cannot run";
          }
        else if (d.n <= InputParsing::contact_direct_solver_max_dofs)
          {
            settings.type = SaddlePointSolver::Type::direct_constraints;
            why << d.n << " DoFs <= " << InputParsing::contact_direct_solver_max_dofs
                << ": up to this size the Cholesky factorization of the condensed stiffness is faster than "
                   "CG-AMG (measured, doc/benchmarks.md)";
          }
        else
          {
            settings.type = SaddlePointSolver::Type::cg_amg_constraints;
            why << d.n << " DoFs > " << InputParsing::contact_direct_solver_max_dofs
                << ": above this size CG-AMG on the condensed stiffness is faster than its factorization "
                   "(measured, doc/benchmarks.md)";
          }
        pcout << "  solver (Solver/Type = automatic): " << SaddlePointSolver::type_name(settings.type) << ", "
                    << why.str() << std::endl;
      }
    else
      settings.type = SaddlePointSolver::parse_type(opt.solver);
    settings.relative_tolerance = opt.solver_tolerance;
    settings.max_iterations     = opt.solver_max_iterations;
    settings.warm_start         = opt.warm_start;
    settings.p_multigrid        = opt.solver_preconditioner != "AMG";
    if (distributed)
      {
        d.partition = std::make_unique<VEMPartition<2>>();
        d.partition->reinit(d.dof_handler, mpi_communicator);
        auto solver = std::make_unique<DistributedContactSolver>(settings, *d.partition, d.constraints,
                                                                 mpi_communicator);
        d.distributed_solver = solver.get();
        d.solver             = std::move(solver);
      }
    else
      d.solver = std::make_unique<SaddlePointSolver>(settings);
    if (SaddlePointSolver::is_iterative(settings.type))
      d.solver->set_near_null_space(d.dof_handler.rigid_body_modes());
    // CG-AMG on the condensed stiffness: the p-multigrid for k = 2, as for
    // one body (its coarse level ties the bodies as the contact does)
    if (settings.type == SaddlePointSolver::Type::cg_amg_constraints && settings.p_multigrid &&
        PMultigrid::applies_to(d.dof_handler.get_element_data()))
      {
        PMultigrid::make_prolongation(d.dof_handler, d.prolongation_sparsity, d.prolongation, d.coarse_modes);
        d.solver->set_coarse_space(d.prolongation, d.coarse_modes);
      }
    d.contact_solver = ContactSolver<2>::create(*d.contact, d.constraints, *d.solver, contact_settings,
                                                d.complementarity);
    d.contact_solver->set_support(d.support.get());
    d.contact_solver->set_pair_neighbours(ActiveSetSolver<2>::pair_neighbours(results.interfaces));
  }



  // The elasticity part at the time t of a load step, assembled directly
  // into the big system cell by cell (VEMValues, ElasticityOperator and the
  // assembler's local loads); the constraints are rebuilt because their
  // values may depend on t. The contact blocks are added by the active-set
  // or friction solver in each of its iterations.
  void
  ContactProblem::assemble_system(const double time)
  {
    CycleData                 &d = *data;
    StageTimer::Scope t(d.timer, "assembly");
    bc.set_time(time);
    d.constraints.clear();
    bc.apply_constraints(d.dof_handler, d.constraints, &d.supports, &d.rotation_parts);
    d.constraints.close();
    d.assembler = std::make_unique<ElasticityAssembler<2>>(d.dof_handler, d.materials, opt.stabilization_factor, opt.stabilization);
    ElasticityAssembler<2> &assembler = *d.assembler;
    bc.add_loads(assembler);
    // the first n unknowns of the saddle-point system are the displacements
    d.system_rhs.reinit(d.n + d.m);
    if (d.distributed_solver != nullptr)
      {
        // each process assembles its cells in the solver, per active set
        d.system_matrix = 0;
        d.distributed_solver->set_assembler(assembler);
      }
    else
      assembler.assemble(d.constraints, d.system_matrix, d.system_rhs);

    // the applied load per body, from the unconstrained load vector
    dealii::Vector<double> loads;
    assembler.assemble_load_vector(loads);
    std::vector<unsigned int> node_body(d.dof_handler.n_nodes(), 0), nodes;
    for (unsigned int c = 0; c < results.mesh.n_cells(); ++c)
      {
        d.dof_handler.get_node_indices(c, nodes);
        for (const auto nd : nodes)
          node_body[nd] = results.mesh.cell(c).material_id;
      }
    results.applied_load_per_body.assign(bodies.size(), dealii::Tensor<1, 2>());
    for (unsigned int i = 0; i < d.n; ++i)
      {
        // an overflowed load is named here, before a solver fails on it
        if (!std::isfinite(loads[i]))
          {
            std::ostringstream msg;
            msg << "Load step at t = " << time << ": the assembled load vector is " << loads[i] << " at DoF " << i
                << " (body " << node_body[i / 2]
                << "): the loads overflow double precision when integrated. Check 'Boundary conditions and "
                   "loads' (Body force, Traction, Pressure, Rigid boundary) for values far from the units of "
                   "the problem.";
            AssertThrow(false, dealii::ExcMessage(msg.str()));
          }
        results.applied_load_per_body[node_body[i / 2]][i % 2] += loads[i];
      }
    // loads out of scale with the stiffness of a body: named before the
    // solver overflows on them
    {
      const std::vector<ScaleCheck::Body> scale_bodies = scale_check_bodies();
      std::ostringstream when;
      when << "at t = " << time;
      ScaleCheck::check(d.dof_handler, loads, scale_bodies, when.str(), false);
    }
  }



  // One load step: the active-set method (frictionless, tied or stick by
  // penalty) or the semismooth Newton method of Coulomb friction. When a
  // step of several fails, the converged steps' results are kept (their
  // files and a JSON summary saying where it stopped) and the error is
  // passed on.
  void
  ContactProblem::solve(const unsigned int step, const double time)
  {
    CycleData &d = *data;
    try
      {
        StageTimer::Scope t(d.timer, "solve");
        // the active-set solver assembles into the system matrix and
        // restores it (at 1e6 DoFs a working copy is 250 MB of fresh pages,
        // 0.7 s); the others get a matrix of their own
        dealii::SparseMatrix<double> *work = &d.system_matrix;
        if (!d.contact_solver->solves_in_place())
          {
            if (d.work_matrix.empty())
              d.work_matrix.reinit(d.sparsity);
            work = &d.work_matrix;
          }
        d.solve_result = d.contact_solver->solve_step(d.system_matrix, d.system_rhs, *work, d.x);
      }
    catch (...)
      {
        const CollapseMechanism *found = d.contact_solver ? d.contact_solver->last_mechanism() : nullptr;
        if (found != nullptr)
          {
            mechanism = std::make_shared<const CollapseMechanism>(*found);
            write_mechanism();
          }
        if (opt.n_load_steps > 1)
          {
            pcout << "  load step " << step << " of " << opt.n_load_steps << " (t = " << time
                      << ") failed; the results of the " << step - 1 << " converged step(s) are kept";
            if (opt.write_vtu || opt.write_csv)
              pcout << " (" << d.prefix << "-step-*, " << d.prefix << ".pvd)";
            pcout << "." << std::endl;
            if (opt.write_json)
              {
                JsonSummary json;
                json.set("program", "dealvem");
                json.set("problem", "contact");
                json.set("load_steps.requested", double(opt.n_load_steps));
                json.set("load_steps.converged", double(step - 1));
                json.set("load_steps.failed_step", double(step));
                json.set("load_steps.failed_time", time);
                json.set("status", "failed");
                for (const auto &sr : results.steps)
                  {
                    const std::string k = "steps." + std::to_string(sr.step) + ".";
                    json.set(k + "time", sr.time);
                    json.set(k + "iterations", double(sr.iterations));
                    json.set(k + "dissipated_energy", sr.dissipated_energy);
                  }
                json.write(d.prefix + ".json");
              }
          }
        throw;
      }
  }



  // The collapse mechanism as a VTU file (the motion as the displacement,
  // so that ParaView's "Warp By Vector" moves the bodies by it; the
  // stresses of a rigid motion are zero) and an SVG picture of the bodies
  // moved by a tenth of the model's size, the hinge nodes marked.
  void
  ContactProblem::write_mechanism() const
  {
    const CycleData &d = *data;
    if (mechanism == nullptr || !(opt.write_vtu || opt.write_pictures))
      return;
    const auto     &dh = d.dof_handler;
    dealii::Vector<double> field(dh.n_dofs());
    for (unsigned int i = 0; i < dh.n_dofs() && i < mechanism->displacement.size(); ++i)
      field[i] = mechanism->displacement[i];
    pcout << "  collapse mechanism: " << mechanism->failing_condition;
    if (opt.write_vtu)
      {
        StressRecovery<2> zero(dh, d.materials, field);
        write_vtu_file(d.prefix + "-mechanism.vtu", dh, field, zero);
        pcout << "; " << d.prefix << "-mechanism.vtu";
      }
    if (opt.write_pictures)
      {
        const auto &mesh = dh.get_mesh();
        std::vector<dealii::Tensor<1, 2>> motion(mesh.n_vertices());
        std::vector<bool>                 marked(mesh.n_vertices(), false);
        for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
          for (unsigned int c = 0; c < 2; ++c)
            motion[v][c] = field[2 * v + c];
        for (const auto i : mechanism->closed_pairs)
          {
            const auto dofs = d.contact->pair_dofs(i);
            for (const auto dof : {dofs[0], dofs[2]})
              if (dof / 2 < mesh.n_vertices())
                marked[dof / 2] = true;
          }
        dealii::Point<2> lo = mesh.vertex(0), hi = mesh.vertex(0);
        for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
          for (unsigned int c = 0; c < 2; ++c)
            {
              lo[c] = std::min(lo[c], mesh.vertex(v)[c]);
              hi[c] = std::max(hi[c], mesh.vertex(v)[c]);
            }
        std::vector<double> body(mesh.n_cells());
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          body[c] = mesh.cell(c).material_id;
        SVGPlots::write_mesh(d.prefix + "-mechanism.svg", mesh, motion, 0.1 * (hi - lo).norm(), body, "body",
                             marked, "Collapse mechanism (" + mechanism->failing_condition + ")");
        pcout << "; " << d.prefix << "-mechanism.svg";
      }
    pcout << std::endl;
  }
} // namespace dealvem
