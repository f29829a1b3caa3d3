// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// ContactProblem: the finite-strain, finite-sliding program
// (Options::finite_strain) and its step outputs.
#include "contact_problem_internal.h"

namespace dealvem
{
  using namespace internal::ContactProblemImplementation;

  namespace
  {
    // Finite sliding: one node pair at the end of a step, in the current
    // configuration.
    struct SlidingPair
    {
      unsigned int         interface = 0, pair = 0;
      dealii::Point<2>     x;      // the slave node
      dealii::Tensor<1, 2> normal; // the current normal n (t = (-n_y, n_x))
      double               weight = 0, gap = 0, pressure = 0, tangential_traction = 0;
      std::string          status;
    };

    // Finite sliding: what a user reads after a step.
    struct SlidingStepOutputs
    {
      std::vector<SlidingPair>                pairs;
      std::vector<dealii::Tensor<1, 2>>       force;  // on the slave side, per interface
      std::vector<double>                     moment; // of those forces about the moment point
      std::vector<SupportReactions::Reaction> reactions;
      std::vector<SupportReactions::Rotation> rotations; // the 'Rotation about centre' parts
      dealii::Tensor<1, 2>                    load; // the applied loads and their moment
      double                                  load_moment = 0;
    };

    // The pairs, interface resultants, support reactions and applied loads
    // of the last converged step of @p sliding at the time @p time, the
    // moments about @p point, all in the current configuration.
    SlidingStepOutputs
    finite_sliding_step_outputs(const FiniteSliding          &sliding,
                                const unsigned int           n_interfaces,
                                const double                 time,
                                BoundaryConditionParameters &bc,
                                const dealii::Point<2>      &point)
    {
      SlidingStepOutputs out;
      out.force.assign(n_interfaces, dealii::Tensor<1, 2>());
      out.moment.assign(n_interfaces, 0.);
      const FiniteStrainContact    &contact = sliding.get_contact();
      const dealii::Vector<double> &u       = sliding.get_solution();
      const dealii::Vector<double> &lambda  = sliding.get_multipliers();
      const unsigned int            np      = contact.n_pairs();
      // a tangential multiplier per pair: tied contact or Coulomb friction
      const bool                    two     = (contact.n_constraints() == 2 * np);
      const std::vector<double>     w       = contact.current_weights(u);
      std::vector<unsigned int>     n_in_interface(n_interfaces, 0);
      for (unsigned int i = 0; i < np; ++i)
        {
          const auto  &pair = contact.get_pairs()[i];
          SlidingPair  row;
          const unsigned int k = sliding.reported_interface(pair.interface);
          row.interface = k;
          row.pair      = n_in_interface[k]++;
          const auto x  = contact.current_positions(i, u);
          row.x         = x[1];
          row.normal    = contact.current_normal(i, u);
          row.weight    = w[i];
          row.gap       = (x[1] - x[0]) * row.normal;
          if (contact.is_pair_left_out(i))
            {
              // no multiplier: both nodes prescribed (the force is in the
              // reactions), or a pair repeating two others where three
              // bodies meet
              row.status = (contact.is_fixed(i) ? "fixed" : "junction");
              out.pairs.push_back(row);
              continue;
            }
          // (the slave node receives -lambda_n n - lambda_t t, t = (-n_y,
          // n_x): the traction of the row)
          const double ln = lambda[i], lt = (two ? lambda[np + i] : 0.);
          if (w[i] > 0)
            {
              row.pressure            = -ln / w[i];
              row.tangential_traction = -lt / w[i];
            }
          const double mu = contact.friction_coefficient(i);
          if (contact.is_bilateral())
            row.status = "closed";
          else if (ln == 0)
            row.status = "open";
          else if (contact.is_frictional() && mu > 0)
            // slipping at the Coulomb bound (as FiniteSliding counts it)
            row.status = (lt != 0 && std::abs(lt) >= mu * std::abs(ln) * (1 - 1e-9) ? "slip" : "stick");
          else
            row.status = "closed";
          out.pairs.push_back(row);
        }

      // The force and moment of each interface on its reported side: the
      // nodal forces -lambda_j dg_j/du of its constraints at the nodes of
      // that side. Not the pair forces -lambda_n n - lambda_t t at the
      // pairs' positions: a pair whose nodes are apart along the interface
      // (a midpoint pair of k = 2 beside a slipping vertex, a merged pair)
      // also turns the normal and the tangent of its neighbours, a couple
      // on their nodes (measured: 6.7e-6 of the moment of a pressed block
      // whose end pairs slip and the rest stick).
      {
        const auto &dofs_here = sliding.get_dof_handler();
        // the nodes of each interface's slave and master sides
        unsigned int n_itf = 0;
        for (unsigned int i = 0; i < np; ++i)
          n_itf = std::max(n_itf, contact.get_pairs()[i].interface + 1);
        std::vector<std::set<unsigned int>> slave_nodes(n_itf), master_nodes(n_itf);
        const auto node_of = [&](const unsigned int entity, const bool on_edge) {
          return on_edge ? dofs_here.edge_node(entity) : dofs_here.vertex_node(entity);
        };
        for (unsigned int i = 0; i < np; ++i)
          {
            const auto &pair = contact.get_pairs()[i];
            slave_nodes[pair.interface].insert(node_of(pair.slave_entity, pair.on_edge()));
            master_nodes[pair.interface].insert(node_of(pair.master_entity, pair.on_edge()));
          }
        FiniteStrainConstraints::Linearization lin;
        for (unsigned int j = 0; j < contact.n_constraints(); ++j)
          {
            const unsigned int i = j % np;
            if (contact.is_left_out(j) || lambda[j] == 0)
              continue;
            const unsigned int itf  = contact.get_pairs()[i].interface;
            const unsigned int k    = sliding.reported_interface(itf);
            // (the slave side when the sign is +1: body_b of a detected pair
            // of bodies, whichever side is the slave)
            const double       sign = sliding.reported_sign(itf);
            const auto        &side = sign > 0 ? slave_nodes[itf] : master_nodes[itf];
            contact.linearize(j, u, lin, false);
            for (unsigned int d = 0; d < lin.dofs.size(); ++d)
              {
                const unsigned int node = lin.dofs[d] / 2;
                if (side.count(node) == 0)
                  continue;
                dealii::Tensor<1, 2> f;
                f[lin.dofs[d] % 2] = -lambda[j] * lin.gradient[d];
                auto x             = dofs_here.node_location(node);
                for (unsigned int c = 0; c < 2; ++c)
                  x[c] += u[2 * node + c];
                out.force[k] += f;
                out.moment[k] += SupportReactions::moment(x, f, point);
              }
          }
      }

      // the reactions: the unbalanced force external + contact - internal
      // at the constrained DoFs, summed per support (the supports of the
      // step's mesh, from the same entries as its constraints)
      bc.set_time(time);
      const auto                             &dofs = sliding.get_dof_handler();
      dealii::AffineConstraints<double>       lines;
      std::vector<SupportReactions::Support> supports;
      std::vector<BoundaryConditions::RotationAboutCentre<2>> parts;
      bc.apply_constraints(dofs, lines, &supports, &parts);
      const auto             forces = sliding.nodal_forces();
      dealii::Vector<double> unbalanced(forces.external);
      unbalanced += forces.contact;
      unbalanced -= forces.internal;
      std::vector<dealii::Point<2>> positions(dofs.n_nodes());
      for (unsigned int m = 0; m < positions.size(); ++m)
        {
          positions[m] = dofs.node_location(m);
          for (unsigned int c = 0; c < 2; ++c)
            if (2 * m + c < u.size())
              positions[m][c] += u[2 * m + c];
        }
      out.reactions = SupportReactions::compute(supports, sliding.get_constraints(), unbalanced, positions, point);
      out.rotations = bc.rotation_results(parts, sliding.get_constraints(), u, unbalanced, positions);
      for (unsigned int i = 0; i < forces.external.size(); ++i)
        {
          dealii::Tensor<1, 2> f;
          f[i % 2] = forces.external[i];
          out.load += f;
          out.load_moment += SupportReactions::moment(positions[i / 2], f, point);
        }
      return out;
    }

    // Finite sliding: the node pairs of a step as CSV.
    void
    write_finite_sliding_pairs(const std::string &filename, const std::vector<SlidingPair> &pairs)
    {
      OutputFile    csv_file(filename);
      std::ostream &csv = csv_file.stream();
      csv << "interface,pair,x,y,normal_x,normal_y,weight,gap,pressure,tangential_traction,status\n";
      csv << std::setprecision(15);
      for (const auto &r : pairs)
        csv << r.interface << "," << r.pair << "," << r.x[0] << "," << r.x[1] << "," << r.normal[0] << ","
            << r.normal[1] << "," << r.weight << "," << r.gap << "," << r.pressure << "," << r.tangential_traction
            << "," << r.status << "\n";
      csv_file.commit();
    }

  } // namespace



  // The finite-sliding program of run_finite_sliding(), in its steps: the
  // checks of the set-up, the one mesh of the bodies, the interfaces and
  // FiniteSliding's parameters, the heading of the report, then per load
  // step the solve, its report, its record in the history (CSV and JSON)
  // and its files.
  struct ContactProblem::FiniteSlidingRun
  {
    explicit FiniteSlidingRun(ContactProblem &p)
      : p(p)
      , opt(p.opt)
      , cs(p.opt.contact)
      , bodies(p.bodies)
      , bc(p.bc)
      , contact_pairs(p.contact_pairs)
    {}

    void
    check_settings() const;
    void
    make_mesh();
    double
    body_mu(const unsigned int a, const unsigned int b) const;
    void
    make_interfaces();
    FiniteSliding::Parameters
    make_parameters() const;
    void
    make_sliding();
    void
    start_report();
    void
    solve_step(const unsigned int n, const double time);
    SlidingStepOutputs
    report_step(const unsigned int n, const double time, const FiniteSliding::StepRecord &r, unsigned int &updates) const;
    void
    record_step(const unsigned int                 n,
                const double                       time,
                const FiniteSliding::StepRecord   &r,
                const unsigned int                 updates,
                const SlidingStepOutputs          &outputs);
    void
    write_step_files(const unsigned int n, const double time, const SlidingStepOutputs &outputs);
    void
    write_json(const std::string &status);

    ContactProblem                    &p;
    const ContactProblem::Options     &opt;
    const ContactSettings             &cs;
    const std::vector<Body>           &bodies;
    BoundaryConditionParameters       &bc;
    const std::vector<std::pair<dealii::types::boundary_id, dealii::types::boundary_id>> &contact_pairs;
    /// The bodies in one mesh, their laws by material id (= body index).
    PolygonalMesh<2>                          mesh;
    MaterialLibrary<2>                        laws;
    std::vector<FiniteSliding::InterfaceData> interfaces;
    std::unique_ptr<FiniteSliding>            sliding;
    /// The interfaces of the results: the named pairs, then (Pairs = auto)
    /// every pair of bodies, whose detected interfaces are summed.
    unsigned int                              n_reported = 0;
    std::string                               prefix;
    std::vector<std::pair<double, std::string>> series;
    JsonSummary                               json;
    /// The history CSV; its header is written with the first step, which
    /// names the supports.
    std::ostringstream                        csv;
    /// The stages of the run, timed from its start (the JSON's `timings`).
    StageTimer                                timer;
  };



  void
  ContactProblem::run_finite_sliding()
  {
    FiniteSlidingRun run(*this);
    // the stages of the timings (the solve of a step is FiniteSliding's
    // pairing passes and Newton iterations together; the files time
    // themselves)
    StageTimer &timer = run.timer;
    {
      StageTimer::Scope t(timer, "mesh");
      run.check_settings();
      run.make_mesh();
    }
    {
      StageTimer::Scope t(timer, "contact detection");
      run.make_interfaces();
    }
    {
      StageTimer::Scope t(timer, "setup");
      run.make_sliding();
    }
    {
      StageTimer::Scope t(timer, "report");
      run.start_report();
    }
    for (unsigned int n = 1; n <= opt.n_load_steps; ++n)
      {
        const double time = opt.final_time * n / opt.n_load_steps;
        {
          StageTimer::Scope t(timer, "finite sliding solve");
          run.solve_step(n, time);
        }
        SlidingStepOutputs outputs;
        {
          StageTimer::Scope t(timer, "postprocessing");
          const auto       &r       = run.sliding->get_history().back();
          unsigned int      updates = 0;
          outputs                   = run.report_step(n, time, r, updates);
          run.record_step(n, time, r, updates, outputs);
        }
        run.write_step_files(n, time, outputs);
        run.write_json("running");
      }
    run.write_json("complete");
  }



  // The settings finite sliding cannot run with: several processes or
  // cycles, no pairs, a contact rule it does not take, a law without a
  // finite-strain response.
  void
  ContactProblem::FiniteSlidingRun::check_settings() const
  {
    const auto &n_processes = p.n_processes;
    const auto &n_cycles    = p.n_cycles;
    const auto  refuse = [](const bool ok, const std::string &what) {
      AssertThrow(ok, dealii::ExcMessage("Parameter 'Finite strain/Enabled' is true (finite sliding), but " + what));
    };
    refuse(n_processes == 1, "the program runs on " + std::to_string(n_processes) +
                               " MPI processes: finite sliding runs on one (each Newton update is solved by "
                               "UMFPACK).");
    refuse(n_cycles == 1, "'Convergence study/Refinement cycles' is " + std::to_string(n_cycles) +
                            ": finite sliding solves one mesh.");
    refuse(!contact_pairs.empty() || opt.detect_pairs,
           "'Contact/Pairs' is empty: give the interfaces as 'master id : slave id', or 'auto'.");
    const bool tied = cs.normal == ContactSettings::Normal::tied;
    refuse(tied ? cs.tangential == ContactSettings::Tangential::multipliers :
                  (cs.tangential == ContactSettings::Tangential::frictionless ||
                   cs.tangential == ContactSettings::Tangential::coulomb),
           "'Contact/Normal' is '" + std::string(tied ? "tied" : "unilateral") + "' with 'Contact/Tangential = " +
             ContactSettings::tangential_name(cs.tangential) +
             "': finite sliding takes 'frictionless' or 'coulomb' (friction by Lagrange multipliers) with a "
             "unilateral normal, and 'multipliers' with a tied one.");
    for (const auto &b : bodies)
      refuse(b.material->has_finite_strain_response(),
             "the law of " + b.name + " ('" + b.material->get_name() + "') has no finite-strain response.");
  }



  // The bodies in one mesh; the pairs checked to join two bodies, no exact
  // solution, and the scales of moduli, sizes and loads.
  void
  ContactProblem::FiniteSlidingRun::make_mesh()
  {
    const auto refuse = [](const bool ok, const std::string &what) {
      AssertThrow(ok, dealii::ExcMessage("Parameter 'Finite strain/Enabled' is true (finite sliding), but " + what));
    };
    p.make_body_meshes(0, mesh, laws);
    bc.check_boundary_ids(mesh);
    // the pairs join two bodies: checked here, before the first step, as
    // node insertion checks them at small strain (a step would take the
    // error for a failed sub-step and cut it back)
    {
      std::map<dealii::types::boundary_id, std::set<unsigned int>> bodies_of_id;
      for (unsigned int e = 0; e < mesh.n_edges(); ++e)
        if (mesh.edge(e).at_boundary())
          bodies_of_id[mesh.edge(e).boundary_id].insert(mesh.cell(mesh.edge(e).cells[0]).material_id);
      for (const auto &[master_id, slave_id] : contact_pairs)
        {
          const std::string name = "Parameter 'Contact/Pairs' entry '" + std::to_string(int(master_id)) + " : " +
                                   std::to_string(int(slave_id)) + "': ";
          for (const auto id : {master_id, slave_id})
            {
              const auto it = bodies_of_id.find(id);
              AssertThrow(it != bodies_of_id.end(),
                          dealii::ExcMessage(name + "no boundary edge has the boundary id " +
                                             std::to_string(int(id)) + "."));
              AssertThrow(it->second.size() == 1,
                          dealii::ExcMessage(name + "the boundary edges with id " + std::to_string(int(id)) +
                                             " belong to more than one body; each side of a contact interface "
                                             "must lie on one body."));
            }
          const unsigned int a = *bodies_of_id[master_id].begin(), b = *bodies_of_id[slave_id].begin();
          AssertThrow(a != b,
                      dealii::ExcMessage(name + "both boundary ids belong to the same body (" +
                                         (a < bodies.size() ? bodies[a].name : "material id " + std::to_string(a)) +
                                         "); a contact interface joins two different bodies."));
        }
    }
    // settings that finite sliding does not read: refused by name
    for (const auto &b : bodies)
      refuse(InputParsing::trim(b.exact).empty(),
             "an exact solution is given for " + b.name + " ('" + b.exact +
               "', 'Exact solution/Displacement'): finite sliding computes no errors against one. Remove the "
               "entry, or solve at small strain.");
    // the scales of moduli, sizes and loads, before Newton squares them
    // (the loads at the final time, on the reference configuration)
    {
      VEMDoFHandler<2> dofs;
      dofs.reinit(mesh);
      dofs.distribute_dofs(VEMElementData(opt.degree));
      FiniteStrainAssembler<2> assembler(dofs, laws);
      bc.set_time(opt.final_time);
      bc.add_finite_strain_loads(assembler, "Finite strain/Enabled", opt.pressure_load);
      const std::vector<ScaleCheck::Body> scale_bodies = p.scale_check_bodies();
      std::ostringstream when;
      when << "at t = " << opt.final_time;
      dealii::Vector<double> f;
      assembler.assemble_load_vector(f);
      ScaleCheck::check(dofs, f, scale_bodies, when.str(), true);
    }
  }



  // The friction coefficient between two bodies: 'Friction between
  // bodies', then 'between materials', then 'Friction coefficient'.
  double
  ContactProblem::FiniteSlidingRun::body_mu(const unsigned int a, const unsigned int b) const
  {
    if (!cs.is_coulomb())
      return 0.;
    const double mu = (a < bodies.size() && b < bodies.size()) ? p.friction_between(a, b) : -1.;
    return mu >= 0 ? mu : cs.friction_coefficient;
  }



  // The named interfaces with their friction coefficients.
  void
  ContactProblem::FiniteSlidingRun::make_interfaces()
  {
    const auto &pair_friction = p.pair_friction;
    {
      std::map<dealii::types::boundary_id, unsigned int> body_of_id;
      for (unsigned int e = 0; e < mesh.n_edges(); ++e)
        if (mesh.edge(e).at_boundary())
          body_of_id.emplace(mesh.edge(e).boundary_id, mesh.cell(mesh.edge(e).cells[0]).material_id);
      for (unsigned int i = 0; i < contact_pairs.size(); ++i)
        interfaces.push_back({contact_pairs[i].first, contact_pairs[i].second,
                              !cs.is_coulomb()        ? 0. :
                              pair_friction[i] >= 0 ? pair_friction[i] :
                                                      body_mu(body_of_id.at(contact_pairs[i].first),
                                                              body_of_id.at(contact_pairs[i].second))});
    }
  }



  // FiniteSliding's parameters: detection of the free boundary (Pairs =
  // auto), order, contact rule, Newton and pairing controls.
  FiniteSliding::Parameters
  ContactProblem::FiniteSlidingRun::make_parameters() const
  {
    FiniteSliding::Parameters parameters;
    if (opt.detect_pairs)
      {
        // the free boundary of the bodies: every boundary id without a
        // boundary condition or a named pair
        auto &d    = parameters.detection;
        d.enabled  = true;
        d.settings = opt.detection;
        d.friction = [this](const unsigned int a, const unsigned int b) { return body_mu(a, b); };
        std::set<dealii::types::boundary_id> excluded = bc.used_boundary_ids();
        for (const auto &pair : contact_pairs)
          excluded.insert({pair.first, pair.second});
        for (const auto id : mesh.get_boundary_ids())
          if (excluded.count(id) == 0)
            d.candidate_ids.insert(id);
        AssertThrow(!d.candidate_ids.empty(),
                    dealii::ExcMessage("Contact/Pairs = auto: every boundary edge carries a boundary condition "
                                       "or a named pair, so no part of the bodies can come into contact."));
      }
    parameters.degree             = opt.degree;
    parameters.normal             = cs.normal;
    parameters.newton             = opt.newton;
    parameters.pairing_tolerance  = opt.pairing_tolerance;
    parameters.max_pairing_passes = opt.max_pairing_passes;
    parameters.max_cutbacks       = opt.max_cutbacks;
    // node insertion in the current configuration: the search distance of
    // the parameter file (the other insertion rules are finite sliding's own)
    parameters.insertion.search_distance = opt.insertion.search_distance;
    if (opt.stabilization != Stabilization::automatic)
      parameters.stabilization = opt.stabilization;
    return parameters;
  }



  // The solver, with the Dirichlet data and loads as functions of t.
  void
  ContactProblem::FiniteSlidingRun::make_sliding()
  {
    sliding = std::make_unique<FiniteSliding>(mesh, laws, interfaces, make_parameters());
    // the Dirichlet data and the loads are expressions of t, as in the
    // small-strain path: the loads at the time of the step, unscaled
    sliding->set_constraints_function(
      [&bc = p.bc](const VEMDoFHandler<2> &dofs, const double t, dealii::AffineConstraints<double> &constraints) {
        bc.set_time(t);
        bc.apply_constraints(dofs, constraints);
        constraints.close();
      });
    sliding->set_loads([&bc = p.bc, &opt = p.opt](FiniteStrainAssembler<2> &assembler) {
      bc.add_finite_strain_loads(assembler, "Finite strain/Enabled", opt.pressure_load);
    },
                      [](const double) { return 1.; });
  }



  // The JSON summary's heading and the report's heading: bodies,
  // interfaces, order, load steps.
  void
  ContactProblem::FiniteSlidingRun::start_report()
  {
    prefix = opt.output_folder + "/" + opt.base_name;
    json.set("program", "dealvem");
    json.set("problem", "finite sliding");
    json.set("bodies", double(bodies.size()));
    json.set("order", double(opt.degree));
    json.set("load_steps", double(opt.n_load_steps));
    json.set("moment_point.x", opt.moment_point[0]);
    json.set("moment_point.y", opt.moment_point[1]);
    if (opt.write_pictures)
      p.pcout << "note: finite sliding writes no SVG pictures ('Output/Write pictures' applies to the "
                   "small-strain path); the bodies of every step are in the VTU files, the forces in the history "
                   "CSV"
                << std::endl;
    const auto &reported = sliding->get_reported_interfaces();
    n_reported           = reported.size();
    p.pcout << "Finite strain with finite sliding: " << bodies.size() << " bodies, " << interfaces.size()
              << " named interface" << (interfaces.size() == 1 ? "" : "s")
              << (opt.detect_pairs ? ", the others detected in the current configuration at every pairing pass" : "")
              << ", k = " << opt.degree << ", " << opt.n_load_steps << " load step"
              << (opt.n_load_steps == 1 ? "" : "s") << std::endl;
    for (unsigned int i = 0; i < n_reported; ++i)
      {
        const auto &r = reported[i];
        const auto  name = [&](const unsigned int b) {
          return b < bodies.size() ? bodies[b].name : "material id " + std::to_string(b);
        };
        p.pcout << "  interface " << i << ": "
                  << (r.detected ? "between " + name(r.body_a) + " and " + name(r.body_b) + " (detected)" :
                                   "boundary ids " + std::to_string(int(r.master_id)) + " : " +
                                     std::to_string(int(r.slave_id)))
                  << std::endl;
        json.set("interfaces." + std::to_string(i) + ".detected", r.detected ? 1. : 0.);
        if (r.detected)
          {
            json.set("interfaces." + std::to_string(i) + ".body_a", double(r.body_a));
            json.set("interfaces." + std::to_string(i) + ".body_b", double(r.body_b));
          }
      }
  }



  // The JSON summary with @p status, if it is written.
  void
  ContactProblem::FiniteSlidingRun::write_json(const std::string &status)
  {
    if (opt.write_json)
      {
        // (writing this file itself is not in its timings)
        StageTimer::Scope t(timer, "output json");
        json.set("status", status);
        json.set("timings.", timer.breakdown());
        json.write(prefix + ".json");
      }
  }



  // Load step @p n at @p time; a failed step leaves the JSON summary
  // 'failed' with the steps that converged.
  void
  ContactProblem::FiniteSlidingRun::solve_step(const unsigned int n, const double time)
  {
    try
      {
        sliding->solve_step(n, time);
      }
    catch (...)
      {
        json.set("converged_steps", double(n - 1));
        try
          {
            write_json("failed");
          }
        catch (...)
          {}
        throw;
      }
  }



  // The report of a step on the terminal: pairing passes, Newton updates
  // (returned in @p updates), pairs, interface forces and moments, support
  // reactions.
  SlidingStepOutputs
  ContactProblem::FiniteSlidingRun::report_step(const unsigned int               n,
                                                const double                     time,
                                                const FiniteSliding::StepRecord &r,
                                                unsigned int                    &updates) const
  {
    for (const auto &pass : r.newton)
      updates += pass.iterations.empty() ? 0 : pass.iterations.size() - 1;
    p.pcout << "  step " << n << " (t = " << time << "): " << r.n_passes << " pairing pass"
              << (r.n_passes == 1 ? "" : "es") << ", " << updates << " Newton updates, " << r.n_active
              << " active pairs (" << r.n_slipping << " slipping), offset " << r.pairing_offset;
    if (opt.detect_pairs)
      p.pcout << ", " << r.n_detected << " interface" << (r.n_detected == 1 ? "" : "s") << " detected";
    for (unsigned int i = 0; i < n_reported; ++i)
      p.pcout << "; interface " << i << ": normal force (" << r.normal_force[i] << "), friction force ("
                << r.friction_force[i] << ")";
    p.pcout << std::endl;
    const auto outputs = finite_sliding_step_outputs(*sliding, n_reported, time, bc, opt.moment_point);
    for (unsigned int i = 0; i < n_reported; ++i)
      p.pcout << "    interface " << i << ": force on the slave side (" << outputs.force[i][0] << ", "
                << outputs.force[i][1] << "), moment " << outputs.moment[i] << " about ("
                << opt.moment_point[0] << ", " << opt.moment_point[1] << ")" << std::endl;
    print_reactions(p.pcout, outputs.reactions, opt.moment_point, "    ");
    RotationOutput::print(p.pcout, outputs.rotations, "    ");
    return outputs;
  }



  // A step's line of the history CSV and its entries of the JSON summary
  // (the forces and moments with 15 digits: balances are read from them).
  void
  ContactProblem::FiniteSlidingRun::record_step(const unsigned int               n,
                                                const double                     time,
                                                const FiniteSliding::StepRecord &r,
                                                const unsigned int               updates,
                                                const SlidingStepOutputs        &outputs)
  {
    if (n == 1)
      {
        csv << "step,time,passes,newton_updates,pairing_offset,dofs,pairs,active,slipping";
        for (unsigned int i = 0; i < n_reported; ++i)
          csv << ",normal_x_" << i << ",normal_y_" << i << ",friction_x_" << i << ",friction_y_" << i;
        for (unsigned int i = 0; i < n_reported; ++i)
          csv << ",force_x_" << i << ",force_y_" << i << ",moment_" << i;
        for (const auto &reaction : outputs.reactions)
          csv << ",reaction_x_" << reaction.key << ",reaction_y_" << reaction.key << ",reaction_moment_"
              << reaction.key;
        for (const auto &rotation : outputs.rotations)
          csv << ",angle_" << rotation.key << ",torque_" << rotation.key << ",moment_about_centre_" << rotation.key;
        csv << ",load_x,load_y,load_moment\n";
      }
    csv << n << ',' << internal::number_string(time) << ',' << r.n_passes << ',' << updates << ','
        << internal::number_string(r.pairing_offset) << ',' << r.n_dofs << ',' << r.n_pairs << ',' << r.n_active << ','
        << r.n_slipping;
    const std::string key = "steps." + std::to_string(n) + ".";
    json.set(key + "time", time);
    json.set(key + "passes", double(r.n_passes));
    json.set(key + "newton_updates", double(updates));
    json.set(key + "pairing_offset", r.pairing_offset);
    json.set(key + "pairs", double(r.n_pairs));
    if (opt.detect_pairs)
      json.set(key + "detected_interfaces", double(r.n_detected));
    json.set(key + "active_pairs", double(r.n_active));
    json.set(key + "slipping_pairs", double(r.n_slipping));
    for (unsigned int i = 0; i < n_reported; ++i)
      {
        for (unsigned int d = 0; d < 2; ++d)
          csv << ',' << internal::number_string(r.normal_force[i][d]);
        for (unsigned int d = 0; d < 2; ++d)
          csv << ',' << internal::number_string(r.friction_force[i][d]);
        const std::string k = key + "interfaces." + std::to_string(i) + ".";
        json.set(k + "normal_force_x", r.normal_force[i][0]);
        json.set(k + "normal_force_y", r.normal_force[i][1]);
        json.set(k + "friction_force_x", r.friction_force[i][0]);
        json.set(k + "friction_force_y", r.friction_force[i][1]);
        // (mu where every active pair of the interface slips)
        if (r.normal_force[i].norm() > 0)
          json.set(k + "friction_to_normal", r.friction_force[i].norm() / r.normal_force[i].norm());
        json.set(k + "force_x", outputs.force[i][0]);
        json.set(k + "force_y", outputs.force[i][1]);
        json.set(k + "moment", outputs.moment[i]);
      }
    // (the forces and moments with 15 digits: balances are read from
    // them)
    const auto full = [](const double v) {
      std::ostringstream s;
      s << std::setprecision(15) << v;
      return s.str();
    };
    for (unsigned int i = 0; i < n_reported; ++i)
      csv << ',' << full(outputs.force[i][0]) << ',' << full(outputs.force[i][1]) << ','
          << full(outputs.moment[i]);
    for (const auto &reaction : outputs.reactions)
      {
        csv << ',' << full(reaction.force[0]) << ',' << full(reaction.force[1]) << ','
            << full(reaction.moment);
        const std::string k = key + "reactions." + reaction.key + ".";
        json.set(k + "force_x", reaction.force[0]);
        json.set(k + "force_y", reaction.force[1]);
        json.set(k + "moment", reaction.moment);
      }
    for (const auto &rotation : outputs.rotations)
      csv << ',' << full(rotation.angle) << ',' << full(rotation.torque) << ',' << full(rotation.moment_about_centre);
    RotationOutput::json(json, key + "rotations.", outputs.rotations);
    csv << ',' << full(outputs.load[0]) << ',' << full(outputs.load[1]) << ',' << full(outputs.load_moment)
        << "\n";
    json.set(key + "loads.force_x", outputs.load[0]);
    json.set(key + "loads.force_y", outputs.load[1]);
    json.set(key + "loads.moment", outputs.load_moment);
  }



  // The files of a step: the node pairs as CSV, the VTU file with the .pvd
  // series, the history CSV so far.
  void
  ContactProblem::FiniteSlidingRun::write_step_files(const unsigned int        n,
                                                     const double              time,
                                                     const SlidingStepOutputs &outputs)
  {
    if (opt.write_csv)
      {
        StageTimer::Scope t(timer, "output csv");
        write_finite_sliding_pairs(step_prefix(prefix, n) + "-interface.csv", outputs.pairs);
      }
    json.set("converged_steps", double(n));
    if (opt.write_vtu)
      {
        StageTimer::Scope  t(timer, "output vtu");
        std::ostringstream file;
        file << prefix << "-step-" << std::setw(3) << std::setfill('0') << n << ".vtu";
        write_finite_strain_vtu_file(file.str(), sliding->get_dof_handler(), laws, sliding->get_solution());
        series.emplace_back(time, std::filesystem::path(file.str()).filename().string());
        write_pvd_record(prefix + ".pvd", series);
      }
    if (opt.write_csv)
      {
        StageTimer::Scope t(timer, "output csv");
        OutputFile        out(prefix + "-history.csv");
        out.stream() << csv.str();
        out.commit();
      }
  }
} // namespace dealvem
