// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// ContactProblem: the report on the terminal and the output files (CSV,
// VTU, SVG pictures, JSON summary).
#include "contact_problem_internal.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <numeric>

namespace dealvem
{
  using namespace internal::ContactProblemImplementation;

  namespace internal
  {
    namespace ContactProblemImplementation
    {
      // The interface results of one solve (or load step) as CSV.
      void
      write_interface_csv(const std::string &filename, const std::vector<ContactProblem::PairResult> &pairs)
      {
        OutputFile    csv_file(filename);
        std::ostream &csv = csv_file.stream();
        csv << "interface,pair,x,y,normal_x,normal_y,midpoint,active,weight,gap,pressure,lumped_pressure,multiplier,"
               "tangential_traction,slip,status,slip_increment,shear\n";
        csv << std::setprecision(15);
        // (pair: the index of the node pair within its interface)
        std::map<unsigned int, unsigned int> n_written;
        for (const auto &r : pairs)
          csv << r.interface << "," << n_written[r.interface]++ << "," << r.location[0] << "," << r.location[1] << ","
              << r.normal[0] << "," << r.normal[1] << "," << r.midpoint << "," << r.active << "," << r.weight << ","
              << r.gap << "," << r.pressure << "," << r.lumped_pressure << "," << r.multiplier << ","
              << r.tangential_traction << "," << r.slip << "," << r.status << "," << r.slip_increment << ","
              << r.shear << "\n";
        csv_file.commit();
      }

      // The resultant of each interface, one line each.
      void
      write_resultants_csv(const std::string                                   &filename,
                           const std::vector<ContactProblem::InterfaceResult> &interfaces)
      {
        OutputFile    csv_file(filename);
        std::ostream &csv = csv_file.stream();
        csv << "interface,master_body,slave_body,master_id,slave_id,detected,length,normal_force,"
               "tangential_force,force_x,force_y,moment,centre_x,centre_y,open,stick,slip,friction_coefficient\n";
        csv << std::setprecision(15);
        for (unsigned int k = 0; k < interfaces.size(); ++k)
          {
            const auto &r = interfaces[k];
            csv << k << "," << r.master_body << "," << r.slave_body << "," << r.master_id << "," << r.slave_id << ","
                << r.detected << "," << r.length << "," << r.normal_force << "," << r.tangential_force << ","
                << r.force[0] << "," << r.force[1] << "," << r.moment << "," << r.centre_of_pressure[0] << ","
                << r.centre_of_pressure[1] << "," << r.n_open << "," << r.n_stick << "," << r.n_slip << ","
                << r.friction_coefficient << "\n";
          }
        csv_file.commit();
      }

      // The reactions of the supports, one line per support and load step.
      void
      write_reactions_csv(const std::string &filename, const std::vector<ContactProblem::StepResult> &steps)
      {
        OutputFile    csv_file(filename);
        std::ostream &csv = csv_file.stream();
        csv << "step,time,support,boundary_id,force_x,force_y,moment\n";
        csv << std::setprecision(15);
        for (const auto &sr : steps)
          for (const auto &r : sr.reactions)
            csv << sr.step << "," << sr.time << "," << r.key << ","
                << (r.boundary_id == dealii::numbers::invalid_boundary_id ? -1 : int(r.boundary_id)) << ","
                << r.force[0] << "," << r.force[1] << "," << r.moment << "\n";
        csv_file.commit();
      }

      // The rotation parts (angle, torque, moment about the centre), one
      // line per part and load step; no file without such parts.
      void
      write_rotations_csv(const std::string &filename, const std::vector<ContactProblem::StepResult> &steps)
      {
        if (steps.empty() || steps.front().rotations.empty())
          return;
        OutputFile    csv_file(filename);
        std::ostream &csv = csv_file.stream();
        csv << RotationOutput::csv_header();
        for (const auto &sr : steps)
          for (const auto &r : sr.rotations)
            csv << RotationOutput::csv_line(sr.step, sr.time, r);
        csv_file.commit();
      }

      // One line per support on the terminal: its reaction and moment about
      // @p point (the first @p max ones, then their number).
      void
      print_reactions(const dealii::ConditionalOStream                &out,
                      const std::vector<SupportReactions::Reaction> &reactions,
                      const dealii::Point<2>                        &point,
                      const std::string                             &indent,
                      const unsigned int                             max)
      {
        for (unsigned int k = 0; k < reactions.size() && k < max; ++k)
          out << indent << "reaction on " << reactions[k].name << ": force (" << reactions[k].force[0] << ", "
                    << reactions[k].force[1] << "), moment " << reactions[k].moment << " about (" << point[0]
                    << ", " << point[1] << ")" << std::endl;
        if (reactions.size() > max)
          out << indent << "... " << reactions.size() - max << " more supports (-reactions.csv)" << std::endl;
      }

    } // namespace ContactProblemImplementation
  } // namespace internal

  namespace internal
  {
    namespace ContactProblemImplementation
    {
      // The number of nodes node insertion added on all interfaces.
      unsigned int
      inserted_nodes(const std::vector<NodeInsertion::Report> &reports)
      {
        unsigned int n = 0;
        for (const auto &r : reports)
          n += r.n_inserted_master + r.n_inserted_slave;
        return n;
      }

      // The smallest and largest recovered pressure of the active pairs
      // (min > max when no pair is active).
      std::pair<double, double>
      pressure_range(const std::vector<ContactProblem::PairResult> &pairs)
      {
        double pmin = 1e300, pmax = -1e300;
        for (const auto &r : pairs)
          if (r.active)
            {
              pmin = std::min(pmin, r.pressure);
              pmax = std::max(pmax, r.pressure);
            }
        return {pmin, pmax};
      }

      // The file name prefix of load step @p step.
      std::string
      step_prefix(const std::string &prefix, const unsigned int step)
      {
        std::ostringstream s;
        s << prefix << "-step-" << std::setw(3) << std::setfill('0') << step;
        return s.str();
      }
    } // namespace ContactProblemImplementation
  } // namespace internal



  namespace
  {
    // The report of node insertion per interface (the first 20, and the
    // warnings of all): inserted and merged nodes, closed gaps, unpaired
    // nodes, gaps that cannot be told from discretisation gaps.
    void
    print_interfaces(const dealii::ConditionalOStream             &out,
                     const std::vector<NodeInsertion::Interface> &interfaces,
                     const std::vector<std::pair<dealii::types::boundary_id, dealii::types::boundary_id>> &cycle_pairs)
    {
      // (an assembly of many interfaces: the first ones, and the warnings of all)
      const unsigned int n_listed = 20;
      for (unsigned int i = 0; i < interfaces.size(); ++i)
        {
          const auto &r = interfaces[i].report;
          if (i == n_listed)
            out << "    ... " << interfaces.size() - n_listed << " more interfaces (-resultants.csv)"
                      << std::endl;
          if (i >= n_listed && r.unpaired.empty())
            continue;
          out << "    interface " << i << " (" << cycle_pairs[i].first << " : " << cycle_pairs[i].second
                    << "): " << r.n_inserted_master << " + " << r.n_inserted_slave << " inserted, " << r.n_merged
                    << " merged; " << r.n_closed_gaps << " pairs coincide (largest discretisation gap closed: "
                    << r.max_closed_gap << ")";
          out << std::endl;
          if (!r.unpaired.empty())
            {
              out << "  warning: " << r.unpaired.size() << " node(s) of interface " << i
                        << " inside the overlap of its parts have no partner:" << std::endl;
              for (unsigned int k = 0; k < std::min<std::size_t>(r.unpaired.size(), 5); ++k)
                {
                  const auto &u = r.unpaired[k];
                  out << "    " << (u.on_master ? "master" : "slave") << " vertex " << u.vertex << " at ("
                            << u.location[0] << ", " << u.location[1] << "): " << u.reason << std::endl;
                }
              if (r.unpaired.size() > 5)
                out << "    ... (" << r.unpaired.size() - 5 << " more)" << std::endl;
            }
          for (const bool closed : {false, true})
            {
              const auto &list = closed ? r.closed_unresolved_gaps : r.unresolved_gaps;
              if (list.empty())
                continue;
              const auto worst = std::max_element(list.begin(), list.end(), [](const auto &a, const auto &b) {
                return std::abs(a.gap) < std::abs(b.gap);
              });
              double deviation = 0;
              for (const auto &g : list)
                deviation = std::max(deviation, g.chord_deviation);
              if (!closed)
                out << "  warning: interface " << i << " has real gaps or overlaps (up to " << r.max_kept_gap
                          << ") and keeps them all as measured, but at " << list.size()
                          << " pair(s) the gap (largest " << worst->gap << " at (" << worst->location[0] << ", "
                          << worst->location[1] << ")) is no larger than the chord deviation of the meshes there (up to "
                          << deviation
                          << "): there it cannot be told from a discretisation gap. If the two sides are meant to "
                             "touch along one curve there, refine the interface meshes (the chord deviation falls "
                             "with h^2); to keep every gap without this check, set Close discretisation gaps = false."
                          << std::endl;
              else
                out << "  warning: interface " << i << " has no real gap, so its sides are taken to sample one "
                          << "curve and every gap is closed, but " << list.size()
                          << " gap(s) next to an inflection exceed the curvature band there (largest " << worst->gap
                          << " at (" << worst->location[0] << ", " << worst->location[1]
                          << "), chord deviation up to " << deviation
                          << "): the curve changes its curvature between too few vertices. If the sides are meant "
                             "to stand apart there, refine the interface meshes, or set Close discretisation gaps = "
                             "false to keep every gap."
                          << std::endl;
            }
        }
    }

    // The active-set iterations of the last solve, and the globalized solve
    // if it took over.
    void
    print_active_set(const dealii::ConditionalOStream &out, const ContactSolveResult &as)
    {
      out
                << "  active set: " << as.n_iterations << " iteration(s), active pairs per iteration:";
      for (const auto a : as.n_active_history)
        out << " " << a;
      if (as.n_closed_for_support > 0)
        out << " (the first set closes the " << as.n_closed_for_support
                  << " pair(s) of smallest initial gap, so that every body is held)";
      if (as.n_accelerated > 0)
        out << " (" << as.n_accelerated << " step(s) corrected by the active-set acceleration)";
      if (const auto n_tied = std::count(as.tied_open.begin(), as.tied_open.end(), true); n_tied > 0)
        out << "\n  stick held at " << n_tied
            << " pair(s) whose switching made the active set cycle or alternate, also "
            << "where they end open (status open-tied; the convex stick model on those pairs)";
      if (!as.fast_path_failure.empty())
        {
          out << "\n  globalized solve: the active-set iteration gave up ("
                    << as.fast_path_failure.substr(0, as.fast_path_failure.find(':')) << "); the primal active-set "
                    << "method converged in " << as.n_globalized_solves << " solve(s) and "
                    << as.n_globalized_rigid_steps << " rigid step(s)";
          if (as.n_polish_iterations > 0 || as.convex_stick_model)
            out << (as.convex_stick_model ?
                            ", convex stick model kept (open pairs tied tangentially: the polish to stick at "
                            "closed pairs only did not converge)" :
                            ", polished to stick at closed pairs only in " + std::to_string(as.n_polish_iterations) +
                              " solve(s)");
        }
    }

    // The range of the contact pressure and of the cell stresses, the
    // verification of the steps and the total contact force.
    void
    print_ranges(const dealii::ConditionalOStream &out, const ContactProblem::Results &results)
    {
      const auto [pmin, pmax] = pressure_range(results.pairs);
      if (pmax >= pmin)
        out << "  contact pressure on active pairs: min " << pmin << ", max " << pmax << std::endl;
      {
        std::array<double, 3> lo{{1e300, 1e300, 1e300}}, hi{{-1e300, -1e300, -1e300}};
        for (const auto &st : results.cell_stress)
          for (unsigned int i = 0; i < 3; ++i)
            {
              lo[i] = std::min(lo[i], st[i]);
              hi[i] = std::max(hi[i], st[i]);
            }
        out << "  cell stresses: sigma_xx in [" << lo[0] << ", " << hi[0] << "], sigma_yy in ["
                  << lo[1] << ", " << hi[1] << "], sigma_xy in [" << lo[2] << ", " << hi[2] << "]"
                  << std::endl;
      }
      {
        double worst_imbalance = 0, worst_residual = 0, tolerance = std::numeric_limits<double>::infinity(),
               condition = 0;
        for (const auto &sr : results.steps)
          for (const auto &b : sr.balance)
            {
              worst_imbalance = std::max(worst_imbalance, b.imbalance);
              worst_residual  = std::max(worst_residual, b.residual);
              tolerance       = std::min(tolerance, b.tolerance);
              condition       = std::max(condition, b.condition);
            }
        out << "  verification: every body in equilibrium after every step (largest relative imbalance "
                  << worst_imbalance << ", residual " << worst_residual << "; smallest tolerance " << tolerance
                  << "; condition up to " << condition << ")" << std::endl;
      }
      out << "  total contact force on the slave side: (" << results.total_contact_force[0]
                << ", " << results.total_contact_force[1] << ")" << std::endl;
    }

    // Node insertion's counts over all interfaces in the JSON summary.
    void
    json_insertion(JsonSummary &json, const std::vector<NodeInsertion::Report> &reports)
    {
      {
        unsigned int n_unpaired = 0, n_closed = 0, n_merged = 0, n_unresolved = 0;
        double       max_closed = 0;
        for (const auto &r : reports)
          {
            n_unpaired += r.unpaired.size();
            n_unresolved += r.unresolved_gaps.size() + r.closed_unresolved_gaps.size();
            n_closed += r.n_closed_gaps;
            n_merged += r.n_merged;
            max_closed = std::max(max_closed, r.max_closed_gap);
          }
        json.set("contact.unpaired_nodes", double(n_unpaired));
        json.set("contact.unresolved_gaps", double(n_unresolved));
        json.set("contact.merged_pairs", double(n_merged));
        json.set("contact.closed_gaps", double(n_closed));
        json.set("contact.max_closed_gap", max_closed);
      }
    }

    // The load steps in the JSON summary (with friction or several steps).
    void
    json_steps(JsonSummary &json, const ContactProblem::Results &results, const bool friction,
               const ContactProblem::Options &opt)
    {
      if (friction || opt.n_load_steps > 1)
        {
          json.set("contact.tangential", friction ? "coulomb" : "stick or frictionless");
          json.set("load_steps.requested", double(opt.n_load_steps));
          json.set("load_steps.converged", double(results.steps.size()));
          json.set("load_steps.final_time", opt.final_time);
          json.set("contact.dissipated_energy", results.dissipated_energy);
          for (const auto &sr : results.steps)
            {
              const std::string k = "steps." + std::to_string(sr.step) + ".";
              json.set(k + "time", sr.time);
              json.set(k + "iterations", double(sr.iterations));
              json.set(k + "tresca_problems", double(sr.fixed_point_iterations));
              json.set(k + "continuation_factors", double(sr.continuation_factors));
              json.set(k + "open", double(sr.n_open));
              json.set(k + "stick", double(sr.n_stick));
              json.set(k + "slip", double(sr.n_slip));
              json.set(k + "dissipated_energy", sr.dissipated_energy);
              json.set(k + "force_x", sr.total_contact_force[0]);
              json.set(k + "force_y", sr.total_contact_force[1]);
              for (unsigned int i = 0; i < sr.interfaces.size(); ++i)
                {
                  const std::string ki = k + "interfaces." + std::to_string(i) + ".";
                  json.set(ki + "force_x", sr.interfaces[i].force[0]);
                  json.set(ki + "force_y", sr.interfaces[i].force[1]);
                  json.set(ki + "moment", sr.interfaces[i].moment);
                }
              for (const auto &r : sr.reactions)
                {
                  const std::string kr = k + "reactions." + r.key + ".";
                  json.set(kr + "force_x", r.force[0]);
                  json.set(kr + "force_y", r.force[1]);
                  json.set(kr + "moment", r.moment);
                }
              RotationOutput::json(json, k + "rotations.", sr.rotations);
            }
        }
    }

    // The verification of every converged step in the JSON summary.
    void
    json_verification(JsonSummary &json, const std::vector<ContactProblem::StepResult> &steps)
    {
      {
        // the verification of every converged step (ForceBalance)
        double worst_imbalance = 0, worst_residual = 0, margin = std::numeric_limits<double>::infinity();
        for (const auto &sr : steps)
          for (const auto &b : sr.balance)
            {
              const std::string k =
                "verification.steps." + std::to_string(sr.step) + ".body" + std::to_string(b.body) + ".";
              json.set(k + "imbalance", b.imbalance);
              json.set(k + "residual", b.residual);
              json.set(k + "tolerance", b.tolerance);
              json.set(k + "condition", b.condition);
              worst_imbalance = std::max(worst_imbalance, b.imbalance);
              worst_residual  = std::max(worst_residual, b.residual);
              margin          = std::min(margin, b.tolerance / std::max({b.imbalance, b.residual, 1e-300}));
            }
        json.set("verification.max_relative_imbalance", worst_imbalance);
        json.set("verification.max_relative_residual", worst_residual);
        if (std::isfinite(margin))
          json.set("verification.smallest_margin", margin);
      }
    }

    // The resultant of every interface in the JSON summary.
    void
    json_interfaces(JsonSummary &json, const std::vector<ContactProblem::InterfaceResult> &interface_results)
    {
      for (unsigned int k = 0; k < interface_results.size(); ++k)
        {
          const auto       &r   = interface_results[k];
          const std::string key = "interfaces." + std::to_string(k) + ".";
          json.set(key + "master_body", double(r.master_body));
          json.set(key + "slave_body", double(r.slave_body));
          json.set(key + "master_id", double(r.master_id));
          json.set(key + "slave_id", double(r.slave_id));
          json.set(key + "detected", r.detected ? "true" : "false");
          json.set(key + "length", r.length);
          json.set(key + "normal_force", r.normal_force);
          json.set(key + "tangential_force", r.tangential_force);
          json.set(key + "force_x", r.force[0]);
          json.set(key + "force_y", r.force[1]);
          json.set(key + "moment", r.moment);
          json.set(key + "centre_x", r.centre_of_pressure[0]);
          json.set(key + "centre_y", r.centre_of_pressure[1]);
          json.set(key + "open", double(r.n_open));
          json.set(key + "stick", double(r.n_stick));
          json.set(key + "slip", double(r.n_slip));
          json.set(key + "friction_coefficient", r.friction_coefficient);
        }
    }
  } // namespace



  // The files of load step @p step: the interface CSV, the VTU file and the
  // .pvd time series of the steps so far (rewritten after every step).
  void
  ContactProblem::output_step(const unsigned int step) const
  {
    const CycleData &d = *data;
    if (opt.write_csv)
      {
        StageTimer::Scope t(data->timer, "output csv");
        write_interface_csv(step_prefix(d.prefix, step) + "-interface.csv", results.pairs);
        write_resultants_csv(step_prefix(d.prefix, step) + "-resultants.csv", results.interface_results);
        write_reactions_csv(d.prefix + "-reactions.csv", results.steps);
        write_rotations_csv(d.prefix + "-rotations.csv", results.steps);
      }
    if (opt.write_vtu)
      {
        StageTimer::Scope t(data->timer, "output vtu");
        StressRecovery<2> step_stresses(d.dof_handler, d.materials, results.solution);
        write_vtu_file(step_prefix(d.prefix, step) + ".vtu", d.dof_handler, results.solution, step_stresses);
        // the time series so far, rewritten after every step
        OutputFile    pvd_file(d.prefix + ".pvd");
        std::ostream &pvd = pvd_file.stream();
        pvd << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            << "  <Collection>\n";
        for (const auto &sr : results.steps)
          pvd << "    <DataSet timestep=\"" << std::setprecision(17) << sr.time
              << "\" group=\"\" part=\"0\" file=\""
              << std::filesystem::path(step_prefix(d.prefix, sr.step) + ".vtu").filename().string() << "\"/>\n";
        pvd << "  </Collection>\n</VTKFile>\n";
        pvd_file.commit();
      }
  }



  // The report on the terminal and the files: interface CSV, VTU,
  // pictures, JSON summary.
  void
  ContactProblem::output_results()
  {
    // peak resident memory of each process (collective on the distributed
    // path; the mesh and contact data are replicated, see doc/benchmarks.md)
    {
      dealii::Utilities::System::MemoryStats stats;
      dealii::Utilities::System::get_memory_stats(stats);
      const auto peaks = distributed ? dealii::Utilities::MPI::all_gather(mpi_communicator, stats.VmHWM) :
                                       std::vector<unsigned long int>{stats.VmHWM};
      results.peak_memory_MB.clear();
      for (const auto kB : peaks)
        results.peak_memory_MB.push_back(kB / 1024.);
    }
    {
      StageTimer::Scope t(data->timer, "report");
      print_report();
    }
    if (opt.write_csv)
      {
        StageTimer::Scope t(data->timer, "output csv");
        write_interface_csv(data->prefix + "-interface.csv", results.pairs);
        write_resultants_csv(data->prefix + "-resultants.csv", results.interface_results);
        write_reactions_csv(data->prefix + "-reactions.csv", results.steps);
        write_rotations_csv(data->prefix + "-rotations.csv", results.steps);
        pcout << "  interface results: " << data->prefix << "-interface.csv (node pairs), " << data->prefix
                  << "-resultants.csv (force per interface), " << data->prefix
                  << "-reactions.csv (force and moment per support)" << std::endl;
        if (!results.steps.empty() && !results.steps.back().rotations.empty())
          pcout << "  rotations about centres: " << data->prefix
                << "-rotations.csv (angle, torque and moment about the centre per part and step)" << std::endl;
      }
    if (opt.write_vtu)
      {
        StageTimer::Scope t(data->timer, "output vtu");
        write_vtu_file(data->prefix + ".vtu", data->dof_handler, results.solution, *data->stresses);
        pcout << "  ParaView file (all bodies, field body_id): " << data->prefix << ".vtu" << std::endl;
        if (opt.n_load_steps > 1)
          pcout << "  load steps: " << data->prefix << "-step-NNN.vtu, -interface.csv; time series " << data->prefix
                    << ".pvd" << std::endl;
      }
    if (opt.write_pictures)
      {
        StageTimer::Scope t(data->timer, "output svg");
        write_pictures_files();
      }
    if (opt.write_json)
      {
        StageTimer::Scope t(data->timer, "output json");
        write_json_summary();
      }
  }



  // What the run found, on the terminal: sizes, node insertion (with its
  // warnings), the active set, the solver, pressures, stresses, forces.
  void
  ContactProblem::print_report() const
  {
    const CycleData &d     = *data;
    const auto &mesh       = results.mesh;
    const auto &interfaces = results.interfaces;
    const auto &pairs      = d.pairs;
    const auto &contact    = *d.contact;
    const auto &as         = d.solve_result;
    const auto &n          = d.n;
    const auto &m          = d.m;
    const unsigned int n_inserted = inserted_nodes(results.insertion_reports);
    pcout << "Contact problem: " << bodies.size() << " bodies, " << mesh.n_cells() << " cells, "
              << n << " DoFs, " << m << " multipliers" << std::endl
              << "  node insertion: " << n_inserted << " nodes inserted, " << pairs.size() << " node pairs"
              << (results.n_junction_pairs > 0 ?
                    " (" + std::to_string(results.n_junction_pairs) +
                      " where three bodies meet repeat two others and stay open)" :
                    std::string())
              << std::endl;
    print_interfaces(pcout, interfaces, cycle_pairs);
    for (const auto &d : contact.get_dropped_constraints())
      pcout << "  note: the " << (d.tangential ? "tangential" : "normal") << " constraint of the pair at ("
                << d.location[0] << ", " << d.location[1]
                << ") is already imposed by the displacement constraints (value " << d.imposed_value
                << "); its multiplier is dropped." << std::endl;
    for (const auto &r : results.pairs)
      if (r.active && r.at_open_end)
        {
          pcout << "  warning: the contact pair at (" << r.location[0] << ", " << r.location[1]
                    << ") of interface " << r.interface
                    << " is active and ends the paired part of the interface where the bodies' boundaries "
                       "go on: the contact zone may be cut off. Enlarge the contact parts (boundary ids) "
                       "or the 'Search distance'."
                    << std::endl;
        }
    print_active_set(pcout, as);
    pcout << std::endl << "  solver: " << d.solver->description();
    if (as.linear_iterations > as.n_iterations)
      pcout << ", " << as.linear_iterations << " linear iterations in all";
    pcout << std::endl;
    if (distributed)
      pcout << "  MPI: " << n_processes << " processes, cells per process:" << [&] {
        std::string list;
        for (const auto c : d.partition->cells_per_part())
          list += " " + std::to_string(c);
        return list;
      }() << "; " << results.n_rows_across_processes
                << " contact constraint row(s) couple DoFs of different processes" << std::endl;
    print_ranges(pcout, results);
    // (with load steps the progress line of each step lists them)
    if (!results.steps.empty() && opt.n_load_steps == 1 && !contact_settings.is_coulomb())
      {
        print_reactions(pcout, results.steps.back().reactions, opt.moment_point, "  ");
        RotationOutput::print(pcout, results.steps.back().rotations, "  ");
      }
  }



  namespace
  {
    /**
     * The pressure plots of the interfaces: one series per closed zone
     * (closed pairs joined when they lie within five typical spacings of
     * each other), over the position along the zone's tangent measured
     * from its centre of pressure, with the pairs within twice the zone's
     * reach of that centre. A plot over x alone squeezes the closed zone
     * of a curved or long interface (gear flanks, an assembly's joints)
     * into a spike, and two tooth pairs in contact are two zones. An
     * interface with nothing closed is plotted over x. At most 12 series.
     */
    std::vector<SVGPlots::Series>
    pressure_series(const std::vector<ContactPairResult>                     &pairs,
                    const std::vector<std::pair<dealii::types::boundary_id, dealii::types::boundary_id>> &interfaces)
    {
      std::vector<SVGPlots::Series> series;
      for (unsigned int i = 0; i < interfaces.size() && series.size() < 12; ++i)
        {
          const std::string name = "interface " + std::to_string(i) + " (" + std::to_string(interfaces[i].first) +
                                   ":" + std::to_string(interfaces[i].second) + ")";
          std::vector<unsigned int> closed, all;
          for (unsigned int p = 0; p < pairs.size(); ++p)
            if (pairs[p].interface == i)
              {
                all.push_back(p);
                if (pairs[p].active)
                  closed.push_back(p);
              }
          if (closed.empty())
            {
              SVGPlots::Series s;
              s.name = name;
              for (const unsigned int p : all)
                s.points.emplace_back(pairs[p].location[0], pairs[p].pressure);
              std::sort(s.points.begin(), s.points.end());
              series.push_back(s);
              continue;
            }
          // zones: single linkage within five typical spacings
          std::vector<double> spacing(closed.size(), std::numeric_limits<double>::max());
          for (unsigned int a = 0; a < closed.size(); ++a)
            for (unsigned int b = 0; b < closed.size(); ++b)
              if (a != b)
                spacing[a] =
                  std::min(spacing[a], pairs[closed[a]].location.distance(pairs[closed[b]].location));
          std::vector<double> sorted = spacing;
          std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
          const double              link = 5 * (closed.size() > 1 ? sorted[sorted.size() / 2] : 0.);
          std::vector<unsigned int> zone(closed.size());
          std::iota(zone.begin(), zone.end(), 0u);
          const std::function<unsigned int(unsigned int)> root = [&](unsigned int a) {
            return zone[a] == a ? a : zone[a] = root(zone[a]);
          };
          for (unsigned int a = 0; a < closed.size(); ++a)
            for (unsigned int b = a + 1; b < closed.size(); ++b)
              if (pairs[closed[a]].location.distance(pairs[closed[b]].location) <= link)
                zone[root(a)] = root(b);
          std::map<unsigned int, std::vector<unsigned int>> zones;
          for (unsigned int a = 0; a < closed.size(); ++a)
            zones[root(a)].push_back(closed[a]);
          unsigned int k = 0;
          for (const auto &[r, members] : zones)
            {
              if (series.size() == 12)
                break;
              // centre of pressure (pressure times tributary length), reach, tangent
              dealii::Point<2> centre;
              double           force = 0, reach = 0, nearest = std::numeric_limits<double>::max();
              for (const unsigned int p : members)
                {
                  const double f = std::max(pairs[p].pressure, 0.) * pairs[p].weight;
                  centre += f * dealii::Tensor<1, 2>(pairs[p].location);
                  force += f;
                }
              if (force > 0)
                centre /= force;
              else
                centre = pairs[members.front()].location;
              dealii::Tensor<1, 2> tangent = pairs[members.front()].tangent;
              for (const unsigned int p : members)
                {
                  reach = std::max(reach, pairs[p].location.distance(centre));
                  if (pairs[p].location.distance(centre) < nearest)
                    nearest = pairs[p].location.distance(centre), tangent = pairs[p].tangent;
                }
              SVGPlots::Series s;
              s.name = name + (zones.size() > 1 ? ", zone " + std::to_string(++k) : std::string());
              for (const unsigned int p : all)
                if (pairs[p].location.distance(centre) <= 2 * reach + 1e-12 * (1 + reach))
                  s.points.emplace_back((pairs[p].location - centre) * tangent, pairs[p].pressure);
              std::sort(s.points.begin(), s.points.end());
              series.push_back(s);
            }
        }
      return series;
    }
  } // namespace



  // The deformed bodies coloured by sigma_yy (inserted nodes marked) and
  // the contact pressure along each interface, as SVG.
  void
  ContactProblem::write_pictures_files() const
  {
    const CycleData &d     = *data;
    const auto &mesh       = results.mesh;
    const auto &prefix     = d.prefix;
    std::vector<bool> inserted(mesh.n_vertices(), false);
    for (unsigned int v = d.original_vertices.size(); v < mesh.n_vertices(); ++v)
      inserted[v] = true;
    std::vector<dealii::Tensor<1, 2>> displacement(mesh.n_vertices());
    double umax = 0, size = 0;
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      {
        displacement[v][0] = results.solution[2 * v];
        displacement[v][1] = results.solution[2 * v + 1];
        umax               = std::max(umax, displacement[v].norm());
        size = std::max(size, mesh.vertex(v).distance(mesh.vertex(0)));
      }
    const double scale = (umax > 0 ? 0.05 * size / umax : 1.);
    std::vector<double> syy(mesh.n_cells());
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      syy[c] = results.cell_stress[c][1];
    std::ostringstream title;
    title << "sigma_yy on the deformed bodies (displacement x " << std::setprecision(3) << scale
          << "), inserted nodes marked";
    SVGPlots::write_mesh(prefix + "-stress.svg", mesh, displacement, scale, syy, "sigma_yy",
                         inserted, title.str());
    SVGPlots::write_line_plot(prefix + "-pressure.svg", pressure_series(results.pairs, cycle_pairs),
                              "position from the zone's centre of pressure", "contact pressure",
                              "Contact pressure near each closed zone");
    // the assembly: bodies and the contact force of each interface (on its
    // slave body, at the centre of pressure)
    std::vector<SVGPlots::Arrow> arrows;
    for (const auto &ir : results.interface_results)
      arrows.push_back({ir.centre_of_pressure, ir.force});
    SVGPlots::write_assembly(prefix + "-assembly.svg", mesh, arrows,
                             std::to_string(bodies.size()) + " bodies, " +
                               std::to_string(results.interface_results.size()) +
                               " interfaces: contact force on the slave body at the centre of pressure");
    pcout << "  pictures: " << prefix << "-stress.svg, " << prefix << "-pressure.svg, " << prefix
              << "-assembly.svg" << std::endl;
  }



  // The JSON summary of the run (sizes, contact counts, pressures, errors,
  // load steps, timings).
  void
  ContactProblem::write_json_summary() const
  {
    const CycleData &d     = *data;
    const auto &mesh       = results.mesh;
    const auto &pairs      = d.pairs;
    const auto &as         = d.solve_result;
    const auto &n          = d.n;
    const auto &m          = d.m;
    const auto &prefix     = d.prefix;
    const bool  friction   = contact_settings.is_coulomb();
    const double penalty  = results.penalty;
    const unsigned int n_inserted = inserted_nodes(results.insertion_reports);
    const auto [pmin, pmax] = pressure_range(results.pairs);
    JsonSummary json;
    json.set("program", "dealvem");
    json.set("problem", "contact");
    json.set("status", "complete");
    json.set("bodies", double(bodies.size()));
    json.set("cells", double(mesh.n_cells()));
    json.set("dofs", double(n));
    json.set("multipliers", double(m));
    json.set("order", double(opt.degree));
    json.set("solver", d.solver->description());
    json.set("mpi.processes", double(n_processes));
    for (unsigned int p = 0; p < results.peak_memory_MB.size(); ++p)
      json.set("memory.peak_MB_process_" + std::to_string(p), results.peak_memory_MB[p]);
    json.set("contact.rows_across_processes", double(results.n_rows_across_processes));
    json.set("contact.node_pairs", double(pairs.size()));
    json.set("contact.inserted_nodes", double(n_inserted));
    json.set("contact.active_set_iterations", double(as.n_iterations));
    json.set("contact.linear_iterations", double(as.linear_iterations));
    json.set("contact.penalty", penalty);
    unsigned int n_active = 0;
    for (const auto &r : results.pairs)
      n_active += r.active;
    json.set("contact.active_pairs", double(n_active));
    if (pmax >= pmin)
      {
        json.set("contact.pressure_min", pmin);
        json.set("contact.pressure_max", pmax);
      }
    json.set("contact.open_end_warnings", double(results.n_open_end_warnings));
    json.set("contact.junction_pairs", double(results.n_junction_pairs));
    json_insertion(json, results.insertion_reports);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (!InputParsing::trim(bodies[b].exact).empty())
        {
          const auto       &e = results.errors[b];
          const std::string k = "errors.body" + std::to_string(b) + ".";
          json.set(k + "L2", e.l2 / std::max(e.l2_exact, 1e-300));
          json.set(k + "H1", e.h1_seminorm / std::max(e.h1_exact, 1e-300));
          json.set(k + "energy", e.energy / std::max(e.energy_exact, 1e-300));
        }
    json_steps(json, results, friction, opt);
    json_verification(json, results.steps);
    json.set("contact.total_force_x", results.total_contact_force[0]);
    json.set("contact.total_force_y", results.total_contact_force[1]);
    json.set("contact.interfaces", double(results.interface_results.size()));
    json.set("contact.detected_interfaces", double(results.detection.interfaces.size()));
    json_interfaces(json, results.interface_results);
    // the supports' reactions of the last step, and the point of the moments
    json.set("moment_point.x", opt.moment_point[0]);
    json.set("moment_point.y", opt.moment_point[1]);
    if (!results.steps.empty())
      for (const auto &r : results.steps.back().reactions)
        {
          const std::string key = "reactions." + r.key + ".";
          json.set(key + "boundary_id",
                   r.boundary_id == dealii::numbers::invalid_boundary_id ? -1. : double(r.boundary_id));
          json.set(key + "force_x", r.force[0]);
          json.set(key + "force_y", r.force[1]);
          json.set(key + "moment", r.moment);
        }
    if (!results.steps.empty())
      RotationOutput::json(json, "rotations.", results.steps.back().rotations);
    // the stages of the cycle so far (writing this file itself is not in
    // them)
    json.set("timings.", d.timer.breakdown());
    json.write(prefix + ".json");
    pcout << "  summary: " << prefix << ".json" << std::endl;
  }
} // namespace dealvem
