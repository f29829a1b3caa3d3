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

#include <dealvem/app/contact_problem.h>
#include <dealvem/app/input_parsing.h>
#include <dealvem/contact/active_set_solver.h>
#include <dealvem/contact/finite_sliding.h>
#include <dealvem/contact/finite_strain_contact.h>
#include <dealvem/contact/contact_pressure.h>
#include <dealvem/contact/distributed_contact_solver.h>
#include <dealvem/contact/friction_solver.h>
#include <dealvem/contact/rigid_body_support.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/elasticity/force_balance.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/postprocessing/error_norms.h>
#include <dealvem/postprocessing/finite_strain_output.h>
#include <dealvem/postprocessing/json_summary.h>
#include <dealvem/base/number_string.h>
#include <dealvem/base/output_file.h>
#include <dealvem/base/run_files.h>
#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/postprocessing/svg_plots.h>
#include <dealvem/postprocessing/vtu_output.h>
#include <dealvem/solvers/saddle_point_solver.h>
#include <dealvem/vem/partitioning.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/vem/vem_values.h>


#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <map>
#include <set>
#include <sstream>

namespace dealvem
{
  namespace
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

    // One line per support on the terminal: its reaction and moment about
    // @p point (the first @p max ones, then their number).
    void
    print_reactions(const std::vector<SupportReactions::Reaction> &reactions, const dealii::Point<2> &point,
                    const std::string &indent, const unsigned int max = 12)
    {
      for (unsigned int k = 0; k < reactions.size() && k < max; ++k)
        std::cout << indent << "reaction on " << reactions[k].name << ": force (" << reactions[k].force[0] << ", "
                  << reactions[k].force[1] << "), moment " << reactions[k].moment << " about (" << point[0]
                  << ", " << point[1] << ")" << std::endl;
      if (reactions.size() > max)
        std::cout << indent << "... " << reactions.size() - max << " more supports (-reactions.csv)" << std::endl;
    }

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
          dealii::Tensor<1, 2> t;
          t[0]            = -row.normal[1];
          t[1]            = row.normal[0];
          const double ln = lambda[i], lt = (two ? lambda[np + i] : 0.);
          // the slave node receives -lambda_n n - lambda_t t
          const dealii::Tensor<1, 2> f = -ln * row.normal - lt * t;
          if (w[i] > 0)
            {
              row.pressure            = -ln / w[i];
              row.tangential_traction = -lt / w[i];
            }
          // (on body_b of a detected pair of bodies, whichever side is the
          // slave: at an active pair the two nodes coincide)
          const double sign = sliding.reported_sign(pair.interface);
          out.force[k] += sign * f;
          out.moment[k] += sign * SupportReactions::moment(row.x, f, point);
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

      // the reactions: the unbalanced force external + contact - internal
      // at the constrained DoFs, summed per support (the supports of the
      // step's mesh, from the same entries as its constraints)
      bc.set_time(time);
      const auto                             &dofs = sliding.get_dof_handler();
      dealii::AffineConstraints<double>       lines;
      std::vector<SupportReactions::Support> supports;
      bc.apply_constraints(dofs, lines, &supports);
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
    // A material name: letters, digits, '_', '-', '.' (not empty).
    void
    check_material_name(const std::string &name, const std::string &where)
    {
      if (name.empty() && where.find("Material/Name") != std::string::npos)
        return; // the entry may stay empty
      const bool valid = !name.empty() && std::all_of(name.begin(), name.end(), [](const char c) {
                           return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
                         });
      AssertThrow(valid, dealii::ExcMessage(where + ": the material name '" + name + "' is not valid: use letters, "
                                            "digits, '_', '-' and '.' (and '*' in a friction entry for any "
                                            "material)."));
    }
  } // namespace



  void
  ContactProblem::declare_parameters(dealii::ParameterHandler &prm, const unsigned int n_body_sections)
  {
    using namespace dealii::Patterns;
    prm.declare_entry("Number of bodies", "1", Integer(1, max_body_sections),
                      "Number of body sections. Body 0 is given by the sections 'Mesh' and "
                      "'Material', bodies 1, 2, ... by the sections 'Body 1', 'Body 2', ... (any number). "
                      "Each body's cells get the body index as material id. A mesh section with "
                      "'Parts as bodies = true' adds one body per part of its file.");
    const std::string part_materials_doc =
      "With 'Mesh/Parts as bodies': the materials of the parts, 'material id : E : nu; ...' (the "
      "ids of the mesh file), or 'material id : E : nu : name' with a material name for 'Contact/Friction "
      "between materials'; parts not listed take this section's Young's modulus, Poisson's ratio and name.";
    const std::string material_name_doc =
      "A name of this body's material (letters, digits, '_', '-', '.'), for 'Contact/Friction between "
      "materials'. Empty: none.";
    prm.enter_subsection("Material");
    prm.declare_entry("Part materials", "", Anything(), part_materials_doc);
    prm.declare_entry("Name", "", Anything(), material_name_doc);
    prm.leave_subsection();
    for (unsigned int b = 1; b < std::max(n_body_sections, 2u); ++b)
      {
        prm.enter_subsection("Body " + std::to_string(b));
        prm.enter_subsection("Mesh");
        MeshParameters::declare_parameters(prm);
        prm.leave_subsection();
        prm.enter_subsection("Material");
        prm.declare_entry("Young's modulus", "1000", Double(0), "Young's modulus E (> 0).");
        prm.declare_entry("Poisson's ratio", "0.3", Double(-0.999, 0.499),
                          "Poisson's ratio nu, -1 < nu < 0.5.");
        prm.declare_entry("Part materials", "", Anything(), part_materials_doc);
        prm.declare_entry("Name", "", Anything(), material_name_doc);
        prm.leave_subsection();
        prm.enter_subsection("Exact solution");
        prm.declare_entry("Displacement", "", Anything(),
                          "Exact displacement 'ux, uy' of this body (muparser in x, y, t with the "
                          "function constants), compared with the solution of the last load step at "
                          "t = 'Load steps/Final time' (1 by default). Empty: the top-level 'Exact "
                          "solution' applies to this body too.");
        prm.leave_subsection();
        prm.leave_subsection();
      }
    prm.enter_subsection("Contact");
    prm.declare_entry("Pairs", "", Anything(),
                      "Contact interfaces 'master id : slave id; ...': boundary parts of two "
                      "different bodies. The master side gives the normal. With Coulomb friction an "
                      "entry may give its own friction coefficient: 'master id : slave id : mu'. The "
                      "entry 'auto' adds the interfaces found by contact detection: boundary edges of "
                      "different bodies that face each other (normals opposite within 'Detection "
                      "angle', apart by at most 'Detection distance' times the edge length), except "
                      "those whose ids carry boundary conditions or explicit pairs; the coarser side "
                      "is the master. The list is printed; <base name>-resultants.csv gives each interface's bodies, "
                      "ids, length and contact force. With finite sliding ('Finite strain/Enabled = true') "
                      "the detection runs in the current configuration at every pairing pass, so contacts "
                      "that open and close anywhere on the free boundary are found, and the results sum "
                      "the detected interfaces of each pair of bodies.");
    prm.declare_entry("Detection distance", "0.5", Double(0, 10),
                      "Pairs = auto: largest distance (gap or overlap) between facing boundary edges, "
                      "relative to the longer of the two edges.");
    prm.declare_entry("Detection angle", "45", Double(1, 89),
                      "Pairs = auto: largest deviation (degrees) of the outward normals of facing "
                      "edges from opposite.");
    prm.declare_entry("Friction between bodies", "", Anything(),
                      "Coulomb friction coefficients by pairs of bodies, 'body a : body b : mu; ...' "
                      "(body indices, '*' for any body; a pair of bodies beats a '*' entry, a later "
                      "entry an earlier one). They apply to detected interfaces and to pairs that give "
                      "no coefficient of their own; others take 'Friction coefficient'.");
    prm.declare_entry("Friction between materials", "", Anything(),
                      "Coulomb friction coefficients by pairs of materials, 'name a : name b : mu; ...' "
                      "(the names of 'Material/Name' or of 'Part materials', '*' for any material). "
                      "They apply where 'Friction between bodies' gives nothing; a pair of names beats a "
                      "'*' entry, a later entry an earlier one.");
    prm.declare_entry("Normal", "unilateral", Selection("tied|unilateral"),
                      "tied: g = 0 at every pair (bilateral); unilateral: g >= 0, pressure >= 0, "
                      "complementarity, by a primal-dual active set.");
    prm.declare_entry("Tangential", "penalty",
                      Selection("frictionless|penalty|multipliers|coulomb|coulomb penalty"),
                      "frictionless; stick by a penalty (see 'Penalty'); stick by Lagrange "
                      "multipliers (exactly tied); Coulomb friction with exact stick by multipliers "
                      "(coulomb) or regularised by the penalty (coulomb penalty): each pair is open, "
                      "sticking or slipping, |tangential traction| <= mu * pressure, solved by a "
                      "semismooth Newton (active set) method per load step.");
    prm.declare_entry("Friction coefficient", "0", Double(),
                      "Coulomb friction coefficient mu >= 0 of the contact pairs that do not give "
                      "their own in 'Pairs' (only with 'Tangential = coulomb' or 'coulomb penalty').");
    prm.declare_entry("Penalty", "0", Double(0),
                      "Tangential stick penalty (stiffness per length and slip, units of E/h). "
                      "0 selects the default rule 'Penalty factor' * E_min / h_min, with E_min the "
                      "smallest Young's modulus and h_min the shortest interface sub-edge.");
    prm.declare_entry("Penalty factor", "1000", Double(0), "Factor of the default penalty rule.");
    prm.declare_entry("Merge fraction", "0.05", Double(1e-6, 0.49),
                      "Node insertion: a node whose closest point on the other side lies closer "
                      "than this times the local edge length to a node of that side is paired with "
                      "it (the two are merged) instead of splitting the edge: no sub-edge shorter "
                      "than this fraction is created.");
    prm.declare_entry("Search distance", "0.25", Double(0),
                      "Node insertion: largest distance between a node and its partner, relative to "
                      "the size of the interface (the diagonal of the bounding box of both contact "
                      "parts). Nodes inside the overlap but farther apart are reported.");
    prm.declare_entry("Coordinate precision", "auto", Anything(),
                      "Node insertion: precision of the mesh coordinates; a gap within it is round-off "
                      "of the mesh files and is closed. 'auto': each contact part's own, the decimal "
                      "grid its coordinates were written on (a file with six significant digits: a "
                      "unit of the sixth digit; none for coordinates computed in double precision, for "
                      "all short binary fractions such as 0.125, and for a grid coarser than 1/100 of "
                      "the part's shortest edge, a lattice the vertices were placed on), a gap within half the two parts' "
                      "grids being closed. A number in [0, 0.01) replaces the detection, for data "
                      "rounded more coarsely than written (coordinates exported in double from a "
                      "six-digit CAD model): the coordinates are rounded to at most this times the size "
                      "of the interface (the diagonal of the bounding box of both contact parts); 0 "
                      "takes them as exact. Double round-off is always allowed for. No tolerance "
                      "depends on where the model lies.");
    prm.declare_entry("Close discretisation gaps", "true", Bool(),
                      "Node insertion: close the gaps between an inserted node and its partner that "
                      "come from two polygons approximating the same curve (below 1.5 times the "
                      "chord deviation of the edge, or below the coordinate precision), by moving "
                      "the inserted node onto its partner. Larger gaps (bodies apart, or surfaces of "
                      "different curvature as in Hertz contact) are kept. false keeps every gap.");
    prm.declare_entry("Pairing tolerance", "1e-8", Double(1e-14, 0.1),
                      "Finite strain ('Finite strain/Enabled = true', finite sliding): the pairs are made again "
                      "at the converged state of each step until the partners of every active pair are closer "
                      "than this fraction of the slave sub-edges at the pair.");
    prm.declare_entry("Maximum pairing passes", "12", Integer(1, 1000),
                      "Finite strain (finite sliding): at most this many passes (pairing and Newton solve) per "
                      "load step; a step that does not meet 'Pairing tolerance' then stops the program with the "
                      "offset of every pass.");
    prm.declare_entry("Maximum cutbacks", "4", Integer(0, 20),
                      "Finite strain (finite sliding): a load step whose Newton solve or pairing passes fail is "
                      "solved again from its start as two half steps, each cut again if it fails, down to "
                      "2^-(this) of the step; then the program stops naming the sub-step. 0: stop at once.");
    prm.declare_entry("Maximum active set iterations", "50", Integer(1),
                      "Iteration limit of the active set (per load step; with Coulomb friction, of the "
                      "semismooth Newton iteration over open/stick/slip).");
    prm.declare_entry("Active set acceleration", "true", Bool(),
                      "Correct the primal-dual active-set update where it crawls: a step that more than "
                      "doubles the set adds the deeper half of the penetrating pairs; a releasing step "
                      "also releases, next to each run of released pairs, the active pairs over the run's "
                      "length, until such a pair penetrates again. The solution is the same; false runs "
                      "the plain update.");
    prm.declare_entry("Globalized solve", "true", Bool(),
                      "Unilateral contact without Coulomb friction: when the active set cycles, reaches its "
                      "iteration limit or holds no equilibrium, solve again with the primal active-set method, "
                      "which converges whenever a solution exists and otherwise stops with 'No static "
                      "equilibrium' and the collapse mechanism that proves it (printed, and written as "
                      "<prefix>-mechanism.vtu and .svg). false: the active set's failure is the answer.");
    prm.leave_subsection();
    prm.enter_subsection("Load steps");
    prm.declare_entry("Number of steps", "1", Integer(),
                      "Contact problems: number of quasi-static load steps. Step k solves at the time "
                      "t = k * 'Final time' / 'Number of steps' of the load and Dirichlet expressions; "
                      "Coulomb friction measures the slip against the previous step. With more than one "
                      "step every step writes its VTU and CSV files (base name + '-step-NNN') and a "
                      "ParaView time series (base name + '.pvd'). One body with 'Finite strain/Enabled = "
                      "true': the load steps of the Newton solve at the same times t; where no load or "
                      "Dirichlet expression uses t, step k applies k/N of the loads and Dirichlet values "
                      "instead; each step is written to base name + '-step-NNN.vtu' and the series base "
                      "name + '.pvd'. One body at small strain: the problem is linear and static, so it is "
                      "solved once at t = 'Final time' (a note says so when the number is above 1).");
    prm.declare_entry("Final time", "1", Double(),
                      "The time t of the last load step (> 0), in every problem: step k is at "
                      "t = k * 'Final time' / 'Number of steps' (the .pvd series and the JSON summary "
                      "carry these times). A one-body problem at small strain is solved at t = 'Final "
                      "time', with the exact solution compared there.");
    prm.leave_subsection();
    prm.enter_subsection("Output");
    prm.declare_entry("Write pictures", "true", Bool(),
                      "Contact problems: write SVG pictures of the deformed bodies (coloured by "
                      "sigma_yy, inserted nodes marked) and of the contact pressure.");
    prm.declare_entry("Write CSV", "true", Bool(),
                      "Contact problems: write the interface results as CSV.");
    prm.declare_entry("Moment point", "0, 0", Anything(),
                      "Contact problems: the point 'x, y' (two finite numbers) the moments are taken about, "
                      "counter-clockwise positive: the moment of each interface's contact forces on its slave "
                      "body (sum over the node pairs of (x - x0) x f, x the slave node) and of each support's "
                      "reaction on the bodies (sum over its constrained nodes of (x - x0) x R). A support is a "
                      "boundary id with Dirichlet data or a roller, or a point constraint; its reaction is the "
                      "internal force minus the applied loads and the contact forces at the DoFs it constrains. "
                      "Small strain: the positions of the undeformed configuration; the moments go to "
                      "<base name>-resultants.csv (column moment), <base name>-reactions.csv (step, time, support, "
                      "boundary_id, force_x, force_y, moment) and the JSON summary (interfaces.i.moment, "
                      "reactions.<support>.force_x, force_y, moment; with load steps also per step). Finite "
                      "sliding: the current positions x = X + u; per step to <base name>-history.csv (columns "
                      "force_x_i, force_y_i, moment_i per interface, reaction_x_<support>, reaction_y_<support>, "
                      "reaction_moment_<support> per support, load_x, load_y, load_moment of the applied loads), "
                      "<base name>-step-NNN-interface.csv (the node pairs) and the JSON summary "
                      "(steps.N.interfaces.i, steps.N.reactions.<support>, steps.N.loads). The supports are named "
                      "boundary_<id> and point_<k> (k: the index of the entry in 'Point constraints').");
    prm.leave_subsection();
  }



  unsigned int
  ContactProblem::n_bodies(dealii::ParameterHandler &prm)
  {
    return prm.get_integer("Number of bodies");
  }



  bool
  ContactProblem::is_contact_problem(dealii::ParameterHandler &prm)
  {
    const unsigned int n = n_bodies(prm);
    if (n > 1)
      return true;
    prm.enter_subsection("Mesh");
    const bool parts = prm.get_bool("Parts as bodies");
    prm.leave_subsection();
    return parts;
  }



  unsigned int
  ContactProblem::body_sections(const std::string &filename)
  {
    // a plain scan of the lines (ParameterHandler parses the file later and
    // reports its errors): "subsection Body b" at the top level, "set Number
    // of bodies = n" and "include file", recursively. Each body b >= 1 of
    // 'Number of bodies' is described by its own section 'Body b', given
    // once: a section written twice (a copy whose number was not changed)
    // would merge into one body and leave another without a section, that
    // is the default mesh, and a missing section would do the same.
    unsigned int                 needed = default_body_sections;
    unsigned int                 largest = 0;
    std::vector<std::string>     files{filename};
    std::set<std::string>        seen;
    std::map<unsigned long, std::vector<std::string>> sections; // body -> "file:line" of each section
    long                         n_set = -1;                    // the last 'Number of bodies' given
    while (!files.empty() && seen.size() < 100)
      {
        const std::string file = files.back();
        files.pop_back();
        if (!seen.insert(file).second)
          continue;
        std::ifstream in(file);
        std::string   line;
        std::size_t   line_number = 0;
        int           depth       = 0;
        while (std::getline(in, line))
          {
            ++line_number;
            std::istringstream words(line.substr(0, line.find('#')));
            std::string        w0, w1, w2;
            words >> w0 >> w1;
            if (w0 == "subsection")
              {
                if (depth == 0 && w1 == "Body" && (words >> w2))
                  {
                    unsigned long b = 0;
                    std::string   rest;
                    if (InputParsing::trim(w2).find_first_not_of("0123456789") == std::string::npos &&
                        w2.size() <= 6 && !(words >> rest))
                      {
                        b = std::stoul(w2);
                        sections[b].push_back(file + ":" + std::to_string(line_number));
                      }
                    needed  = std::max<unsigned int>(needed, b + 1);
                    largest = std::max<unsigned int>(largest, b);
                  }
                ++depth;
              }
            else if (w0 == "end")
              depth = std::max(depth - 1, 0);
            else if (w0 == "set" && w1 == "Number" && depth == 0)
              {
                const auto eq = line.find('=');
                if (line.find("Number of bodies") != std::string::npos && eq != std::string::npos)
                  {
                    const std::string v = InputParsing::trim(line.substr(eq + 1, line.find('#') - eq - 1));
                    if (!v.empty() && v.size() <= 6 && v.find_first_not_of("0123456789") == std::string::npos)
                      {
                        needed = std::max<unsigned int>(needed, std::stoul(v));
                        n_set  = static_cast<long>(std::stoul(v));
                      }
                  }
              }
            else if (w0 == "include" && !w1.empty())
              {
                const std::string dir = std::filesystem::path(file).parent_path().string();
                files.push_back(w1[0] == '/' || dir.empty() ? w1 : dir + "/" + w1);
              }
          }
      }
    AssertThrow(needed <= max_body_sections,
                dealii::ExcMessage("Parameter file '" + filename + "': it names section 'Body " +
                                   std::to_string(largest) + "' or sets 'Number of bodies' to " +
                                   std::to_string(needed) + "; a parameter file describes at most " +
                                   std::to_string(max_body_sections) +
                                   " bodies by sections. Read an assembly of more bodies from one mesh file, a "
                                   "body per material id ('Mesh/Parts as bodies = true')."));
    for (const auto &[b, where] : sections)
      AssertThrow(where.size() == 1,
                  dealii::ExcMessage("Parameter file '" + filename + "': section 'Body " + std::to_string(b) +
                                     "' is given " + std::to_string(where.size()) + " times (" + where[0] +
                                     " and " + where[1] +
                                     "). Each body has one section; was one of them meant for another body?"));
    if (n_set >= 2 && n_set <= static_cast<long>(max_body_sections))
      for (long b = 1; b < n_set; ++b)
        AssertThrow(sections.count(b) > 0,
                    dealii::ExcMessage("Parameter file '" + filename + "': 'Number of bodies' is " +
                                       std::to_string(n_set) + ", but there is no section 'Body " +
                                       std::to_string(b) + "' (body 0 is described by the top-level sections, body " +
                                       "b >= 1 by 'subsection Body b'). Without it body " + std::to_string(b) +
                                       " would silently be the default mesh; add the section, or lower "
                                       "'Number of bodies'."));
    return needed;
  }



  void
  ContactProblem::parse_parameters(dealii::ParameterHandler &prm, const std::string &dir)
  {
    clear();
    prm_directory    = dir;
    const unsigned n = n_bodies(prm);
    {
      unsigned int declared = 1;
      while (prm.subsection_path_exists({"Body " + std::to_string(declared)}))
        ++declared;
      AssertThrow(n <= declared,
                  dealii::ExcMessage("Parameter 'Number of bodies' is " + std::to_string(n) + ", but only " +
                                     std::to_string(declared) + " body sections are declared; call "
                                     "ContactProblem::declare_parameters(prm, ContactProblem::body_sections(file)) "
                                     "(the program does)."));
    }
    // sections of bodies beyond the number of bodies would be ignored (one
    // listing of the changed entries for all sections: a file may declare
    // many)
    for (const auto &path : InputParsing::changed_entries(prm, ""))
      if (path.compare(0, 5, "Body ") == 0)
        {
          const std::string  section = path.substr(0, path.find('/'));
          const unsigned int b       = std::stoul(section.substr(5));
          if (b >= n)
            InputParsing::check_section_unused(prm, section,
                                               "'Number of bodies' is " + std::to_string(n) + ": section '" +
                                                 section + "' is read only with 'Number of bodies' at least " +
                                                 std::to_string(b + 1) + ".");
        }
    prm.enter_subsection("Convergence study");
    n_cycles = prm.get_integer("Refinement cycles");
    prm.leave_subsection();
    prm.enter_subsection("Material");
    const auto model = ElasticMaterial::parse_model(prm.get("Model"));
    const auto law   = MaterialLaws::parse(prm.get("Law"), "Material/Law");
    prm.leave_subsection();
    // 'Material/Law' applies to every body. With 'Finite strain/Enabled'
    // the problem is solved at finite strain with finite sliding
    // (run_finite_sliding()); else at small strain, where a hyperelastic law
    // is its linearization at F = I, the linear law of the same E and nu
    // (ElasticMaterial, built below)
    {
      FiniteStrainParameters finite_strain;
      finite_strain.parse_parameters(prm);
      opt.finite_strain = finite_strain.enabled;
      opt.newton        = finite_strain.solver;
      opt.pressure_load = finite_strain.pressure_load;
      AssertThrow(!finite_strain.enabled || MaterialLaws::is_hyperelastic(law),
                  dealii::ExcMessage("Parameter 'Finite strain/Enabled' is true, but 'Material/Law' is 'linear': "
                                     "finite strain needs a hyperelastic law ('neo-hooke' or "
                                     "'saint venant-kirchhoff')."));
      AssertThrow(!finite_strain.enabled || !finite_strain.has_monitor_point,
                  dealii::ExcMessage("Parameter 'Finite strain/Monitor point' is set, but contact problems do "
                                     "not use it: the history of the contact forces is written to "
                                     "<base name>-history.csv."));
      if (!finite_strain.enabled)
        InputParsing::check_section_unused(prm, "Finite strain",
                                           "'Finite strain/Enabled' is false: the program solves the contact "
                                           "problem at small strain, without the Newton controls of finite "
                                           "strain.");
    }
    const auto body_law = [&](const double E, const double nu) -> std::shared_ptr<const ConstitutiveLaw<2>> {
      if (opt.finite_strain)
        return MaterialLaws::make_law(law, E, nu, model);
      return std::make_shared<const ElasticMaterial>(E, nu, model);
    };
    if (MaterialLaws::is_hyperelastic(law) && !opt.finite_strain && root)
      std::cout << "note: 'Material/Law = " << MaterialLaws::name(law)
                << "': contact problems are solved at small strain, with the law's linearization at F = I "
                   "(the linear law of the same E and nu) for every body."
                << std::endl;
    std::string exact0;
    // the physical names of the bodies' gmsh files: boundary ids by name
    // (with each body's boundary id offset) for the conditions and pairs
    MeshIO::PhysicalNames names;
    std::map<std::string, std::string> name_file;
    for (unsigned int b = 0; b < n; ++b)
      {
        // body section b: the top-level sections for b = 0, 'Body b' else
        const std::string name   = (b == 0 ? std::string() : "Body " + std::to_string(b));
        const std::string prefix = (b == 0 ? std::string() : name + "/");
        if (b > 0)
          prm.enter_subsection(name);
        Body body;
        prm.enter_subsection("Mesh");
        body.mesh.parse_parameters(prm, prefix + "Mesh");
        prm.leave_subsection();
        body.mesh.load_physical_names(prm_directory);
        // a name that means two ids (two bodies from one file with an
        // offset) cannot be used; numbers can
        for (const auto &[key, id] : body.mesh.physical_names.boundary_ids)
          {
            if (names.unusable.count(key))
              continue;
            const auto it = names.boundary_ids.emplace(key, id);
            if (!it.second && it.first->second != id)
              {
                names.unusable[key] = "it is boundary id " + std::to_string(it.first->second) + " in '" +
                                      name_file[key] + "' and " + std::to_string(id) + " in '" +
                                      body.mesh.file_name + "' (" + prefix +
                                      "Mesh, with its 'Boundary id offset'); give the id by number";
                names.boundary_ids.erase(it.first);
              }
            name_file.emplace(key, body.mesh.file_name);
          }
        prm.enter_subsection("Material");
        const double      E     = prm.get_double("Young's modulus");
        const double      nu    = prm.get_double("Poisson's ratio");
        const std::string parts = prm.get("Part materials");
        const std::string material_name = InputParsing::trim(prm.get("Name"));
        prm.leave_subsection();
        prm.enter_subsection("Exact solution");
        body.exact = prm.get("Displacement");
        prm.leave_subsection();
        if (b > 0)
          prm.leave_subsection();
        if (b == 0)
          exact0 = body.exact;
        else if (InputParsing::trim(body.exact).empty())
          body.exact = exact0;
        InputParsing::check_range(E, ElasticMaterial::min_youngs_modulus, ElasticMaterial::max_youngs_modulus,
                                  prefix + "Material/Young's modulus", false, false,
                                  "Choose units that bring E nearer to 1.");
        body.material = body_law(E, nu);
        check_material_name(material_name, "Parameter '" + prefix + "Material/Name'");
        body.material_name = material_name;
        // 'Part materials': material id : E : nu [: name]
        std::map<dealii::types::material_id, std::shared_ptr<const ConstitutiveLaw<2>>> part_laws;
        std::map<dealii::types::material_id, std::string>                              part_names;
        for (const auto &entry : InputParsing::split(parts, ';'))
          {
            const std::string what   = prefix + "Material/Part materials entry '" + entry + "'";
            const auto        fields = InputParsing::split(entry, ':', true);
            AssertThrow(fields.size() == 3 || fields.size() == 4,
                        dealii::ExcMessage("Parameter '" + what +
                                           "': expected 'material id : E : nu' or 'material id : E : nu : name'."));
            const unsigned int id   = InputParsing::parse_id_or_name(
              fields[0], what, body.mesh.physical_names.material_ids, "material id",
              body.mesh.physical_names.list() + " (file '" + body.mesh.file_name + "')");
            const double       E_id = InputParsing::parse_double(fields[1], what);
            const double       nu_id = InputParsing::parse_double(fields[2], what);
            InputParsing::check_range(E_id, ElasticMaterial::min_youngs_modulus,
                                      ElasticMaterial::max_youngs_modulus, what + " (Young's modulus)", false,
                                      false, "Choose units that bring E nearer to 1.");
            InputParsing::check_range(nu_id, -1, 0.5, what + " (Poisson's ratio)", true, true);
            AssertThrow(part_laws.count(id) == 0,
                        dealii::ExcMessage("Parameter '" + what + "': material id " + std::to_string(id) +
                                           " is listed twice."));
            part_laws[id] = body_law(E_id, nu_id);
            if (fields.size() == 4)
              {
                part_names[id] = InputParsing::trim(fields[3]);
                check_material_name(part_names[id], "Parameter '" + what + "' (name)");
              }
          }
        AssertThrow(part_names.empty() || body.mesh.parts_as_bodies, dealii::ExcInternalError());
        AssertThrow(part_laws.empty() || body.mesh.parts_as_bodies,
                    dealii::ExcMessage("Parameter '" + prefix + "Material/Part materials' is set, but '" + prefix +
                                       "Mesh/Parts as bodies' is false: parts are read only from a mesh file "
                                       "with 'Parts as bodies = true'."));
        if (!body.mesh.parts_as_bodies)
          {
            body.mesh.material_id = bodies.size();
            body.name             = "body " + std::to_string(bodies.size());
            body.modulus_parameter = prefix + "Material/Young's modulus";
            bodies.push_back(std::move(body));
            continue;
          }
        // an assembly in one file: each material id a body
        AssertThrow(n_cycles == 1,
                    dealii::ExcMessage("Parameter '" + prefix + "Mesh/Parts as bodies' is true: the parts are read "
                                       "once, so 'Convergence study/Refinement cycles' must be 1."));
        PolygonalMesh<2> assembly;
        body.mesh.create_mesh(assembly, 0, prm_directory);
        const auto ids = assembly.get_material_ids();
        for (const auto &law : part_laws)
          AssertThrow(std::binary_search(ids.begin(), ids.end(), law.first),
                      dealii::ExcMessage([&] {
                        std::string have;
                        for (const auto id : ids)
                          {
                            have += (have.empty() ? "" : ", ") + std::to_string(id);
                            for (const auto &[nm, i] : body.mesh.physical_names.material_ids)
                              if (i == id)
                                have += " ('" + nm + "')";
                          }
                        return "Parameter '" + prefix + "Material/Part materials' gives material id " +
                               std::to_string(law.first) + ", which no cell of the mesh file '" +
                               body.mesh.file_name + "' has; the material ids of the file are " + have +
                               ". Give the parts by these ids or by their physical names.";
                      }()));
        const auto added = add_parts(assembly, *body.material, part_laws, 0);
        for (unsigned int i = 0; i < added.size(); ++i)
          {
            bodies[added[i]].exact = body.exact;
            bodies[added[i]].modulus_parameter =
              prefix + (part_laws.count(ids[i]) ? "Material/Part materials" : "Material/Young's modulus");
            const auto name        = part_names.find(ids[i]);
            bodies[added[i]].material_name = (name != part_names.end() ? name->second : body.material_name);
            bodies[added[i]].name  = "body " + std::to_string(added[i]) + " (material id " +
                                    std::to_string(ids[i]) + " of " + body.mesh.file_name + ")";
          }
        std::cout << "  " << prefix << "Mesh: " << added.size() << " parts of '" << body.mesh.file_name
                  << "' are bodies " << added.front() << " to " << added.back() << std::endl;
      }

    prm.enter_subsection("Discretization");
    opt.degree               = prm.get_integer("Order");
    opt.stabilization_factor = prm.get_double("Stabilization factor");
    opt.stabilization = (prm.get("Stabilization") == "trace"    ? Stabilization::trace :
                         prm.get("Stabilization") == "diagonal" ? Stabilization::diagonal :
                     prm.get("Stabilization") == "boundary" ? Stabilization::boundary :
                                                                  Stabilization::automatic);
    prm.leave_subsection();
    bc.set_physical_names(names);
    bc.parse_parameters(prm);

    prm.enter_subsection("Contact");
    for (const auto &entry : InputParsing::split(prm.get("Pairs"), ';'))
      {
        if (InputParsing::trim(entry) == "auto")
          {
            AssertThrow(!opt.detect_pairs,
                        dealii::ExcMessage("Parameter 'Contact/Pairs': 'auto' is given twice."));
            opt.detect_pairs = true;
            continue;
          }
        const std::string name   = "Contact/Pairs entry '" + entry + "'";
        const auto        fields = InputParsing::split(entry, ':', true);
        AssertThrow(fields.size() == 2 || fields.size() == 3,
                    dealii::ExcMessage("Parameter '" + name +
                                       "': expected 'master id : slave id', 'master id : slave id : "
                                       "friction coefficient', or 'auto' (the interfaces found by contact "
                                       "detection)."));
        double mu = -1;
        if (fields.size() == 3)
          {
            mu = InputParsing::parse_double(fields[2], name);
            InputParsing::check_range(mu, 0, 1e6, name + " (friction coefficient)", false, false,
                                      "The Coulomb friction coefficient is a number >= 0.");
          }
        const unsigned int a =
          InputParsing::parse_id_or_name(fields[0], name, names.boundary_ids, "boundary id", names.list());
        const unsigned int s =
          InputParsing::parse_id_or_name(fields[1], name, names.boundary_ids, "boundary id", names.list());
        AssertThrow(a < 255 && s < 255 && a != s,
                    dealii::ExcMessage("Parameter '" + name + "': two different boundary ids below 255 expected."));
        add_contact_pair(a, s, mu, "Parameter '" + name + "'");
      }
    auto &cs          = opt.contact;
    cs.normal         = ContactSettings::parse_normal(prm.get("Normal"));
    cs.tangential     = ContactSettings::parse_tangential(prm.get("Tangential"));
    cs.friction_coefficient      = prm.get_double("Friction coefficient");
    cs.penalty                   = prm.get_double("Penalty");
    cs.penalty_factor            = prm.get_double("Penalty factor");
    cs.max_active_set_iterations = prm.get_integer("Maximum active set iterations");
    cs.accelerate_active_set     = prm.get_bool("Active set acceleration");
    cs.globalize                 = prm.get_bool("Globalized solve");
    opt.insertion.merge_fraction            = prm.get_double("Merge fraction");
    opt.insertion.search_distance           = prm.get_double("Search distance");
    {
      const std::string precision = InputParsing::trim(prm.get("Coordinate precision"));
      opt.insertion.coordinate_precision =
        (precision == "auto" ? NodeInsertion::Settings::detect_precision :
                               InputParsing::parse_double(precision, "Contact/Coordinate precision"));
    }
    opt.insertion.close_discretisation_gaps = prm.get_bool("Close discretisation gaps");
    opt.detection.distance                  = prm.get_double("Detection distance");
    opt.detection.max_angle                 = prm.get_double("Detection angle");
    opt.detection.merge_fraction            = opt.insertion.merge_fraction;
    opt.pairing_tolerance                   = prm.get_double("Pairing tolerance");
    opt.max_pairing_passes                  = prm.get_integer("Maximum pairing passes");
    opt.max_cutbacks                        = prm.get_integer("Maximum cutbacks");
    for (const auto &entry : InputParsing::split(prm.get("Friction between bodies"), ';'))
      {
        const std::string what   = "Contact/Friction between bodies entry '" + entry + "'";
        const auto        fields = InputParsing::split(entry, ':', true);
        AssertThrow(fields.size() == 3,
                    dealii::ExcMessage("Parameter '" + what + "': expected 'body a : body b : mu' (body "
                                       "indices or '*')."));
        unsigned int body[2];
        for (unsigned int k = 0; k < 2; ++k)
          {
            body[k] = (InputParsing::trim(fields[k]) == "*") ? dealii::numbers::invalid_unsigned_int :
                                                                InputParsing::parse_unsigned(fields[k], what);
            AssertThrow(body[k] == dealii::numbers::invalid_unsigned_int || body[k] < bodies.size(),
                        dealii::ExcMessage("Parameter '" + what + "': there is no body " +
                                           std::to_string(body[k]) + " (the bodies are 0 to " +
                                           std::to_string(bodies.size() - 1) + ")."));
          }
        const double mu = InputParsing::parse_double(fields[2], what);
        InputParsing::check_range(mu, 0, 1e6, what + " (friction coefficient)", false, false,
                                  "The Coulomb friction coefficient is a number >= 0.");
        set_friction_coefficient(body[0], body[1], mu);
      }
    for (const auto &entry : InputParsing::split(prm.get("Friction between materials"), ';'))
      {
        const std::string what   = "Contact/Friction between materials entry '" + entry + "'";
        const auto        fields = InputParsing::split(entry, ':', true);
        AssertThrow(fields.size() == 3,
                    dealii::ExcMessage("Parameter '" + what + "': expected 'name a : name b : mu' (material "
                                       "names from 'Material/Name' or 'Part materials', or '*')."));
        std::string name[2];
        for (unsigned int k = 0; k < 2; ++k)
          {
            name[k] = InputParsing::trim(fields[k]);
            if (name[k] != "*")
              check_material_name(name[k], "Parameter '" + what + "'");
          }
        const double mu = InputParsing::parse_double(fields[2], what);
        InputParsing::check_range(mu, 0, 1e6, what + " (friction coefficient)", false, false,
                                  "The Coulomb friction coefficient is a number >= 0.");
        set_friction_coefficient(name[0], name[1], mu);
      }
    const std::string tangential_name       = prm.get("Tangential");
    prm.leave_subsection();
    if (root && cs.tangential != ContactSettings::Tangential::penalty &&
        cs.tangential != ContactSettings::Tangential::coulomb_penalty)
      for (const auto &e : InputParsing::changed_entries(prm, "Contact"))
        if (e == "Contact/Penalty" || e == "Contact/Penalty factor")
          std::cout << "warning: the parameter file sets '" << e << "', but 'Contact/Tangential' is '"
                    << tangential_name << "', which uses no stick penalty; the setting has no effect." << std::endl;
    // finite sliding (run_finite_sliding()) reads the pairs, the normal and
    // tangential rule, the friction coefficient, the pairing controls, the
    // cutbacks and the search distance; the settings of the small-strain
    // contact loop and of node insertion in the reference configuration
    // are refused by name (after the contact rule: a rule that finite
    // sliding does not take is named first, by run_finite_sliding())
    const bool sliding_rule =
      cs.normal == ContactSettings::Normal::tied ?
        cs.tangential == ContactSettings::Tangential::multipliers :
        (cs.tangential == ContactSettings::Tangential::frictionless ||
         cs.tangential == ContactSettings::Tangential::coulomb);
    if (opt.finite_strain && sliding_rule)
      {
        static const std::map<std::string, std::string> unread = {
          {"Contact/Merge fraction", "node insertion at finite strain merges only nodes within 1e-9 of an edge"},
          {"Contact/Coordinate precision", "finite sliding keeps every gap (no gap closing)"},
          {"Contact/Close discretisation gaps", "finite sliding keeps every gap (no gap closing)"},
          {"Contact/Maximum active set iterations",
           "the contact conditions are part of the Newton iteration ('Finite strain/Maximum Newton iterations')"},
          {"Contact/Active set acceleration",
           "the contact conditions are part of the Newton iteration ('Finite strain/Maximum Newton iterations')"},
          {"Contact/Globalized solve",
           "the contact conditions are part of the Newton iteration ('Finite strain/Maximum Newton iterations')"},
          {"Contact/Penalty", "finite sliding has no stick penalty (friction by Lagrange multipliers)"},
          {"Contact/Penalty factor", "finite sliding has no stick penalty (friction by Lagrange multipliers)"},
          {"Discretization/Stabilization factor", "finite sliding scales the stabilization by the tangent, with "
                                                  "the factor 1"},
        };
        std::vector<std::string> set = InputParsing::changed_entries(prm, "Contact");
        for (const auto &e : InputParsing::changed_entries(prm, "Discretization"))
          set.push_back(e);
        for (const auto &e : InputParsing::changed_entries(prm, "Solver"))
          set.push_back(e);
        for (const auto &e : set)
          {
            const auto it = unread.find(e);
            const bool solver = e.compare(0, 7, "Solver/") == 0;
            AssertThrow(it == unread.end() && !solver,
                        dealii::ExcMessage(
                          "Parameter '" + e + "' is set, but 'Finite strain/Enabled' is true (finite sliding), which "
                          "does not read it: " +
                          (solver ? std::string("every Newton update is solved by UMFPACK") : it->second) +
                          ". Remove the entry, or set 'Finite strain/Enabled = false' (small strain)."));
          }
      }

    prm.enter_subsection("Load steps");
    {
      const long steps = prm.get_integer("Number of steps");
      AssertThrow(steps >= 1 && steps <= 100000,
                  dealii::ExcMessage("Parameter 'Load steps/Number of steps' is " + std::to_string(steps) +
                                     ": it must be at least 1 (and at most 100000)."));
      opt.n_load_steps = steps;
    }
    opt.final_time = prm.get_double("Final time");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    opt.solver = prm.get("Type");
    // 'automatic' is resolved in setup_system(), when the size is known
    opt.solver_tolerance      = prm.get_double("Relative tolerance");
    opt.solver_max_iterations = prm.get_integer("Maximum iterations");
    opt.warm_start            = prm.get_bool("Warm start");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    opt.output_folder  = prm.get("Folder");
    opt.base_name      = prm.get("Base name");
    opt.write_vtu      = prm.get_bool("Write VTU");
    opt.write_json     = prm.get_bool("Write JSON");
    opt.write_pictures = prm.get_bool("Write pictures");
    opt.write_csv      = prm.get_bool("Write CSV");
    {
      const std::string name  = "Output/Moment point";
      const auto        parts = InputParsing::split(prm.get("Moment point"), ',');
      AssertThrow(parts.size() == 2, dealii::ExcMessage("Parameter '" + name + "': expected 'x, y', got '" +
                                                        prm.get("Moment point") + "'."));
      // (parse_double refuses what is not a finite number, naming the entry)
      for (unsigned int c = 0; c < 2; ++c)
        opt.moment_point[c] = InputParsing::parse_double(parts[c], name);
    }
    prm.leave_subsection();

    check_setup();
    {
      // (the parts of an assembly file are read already)
      std::vector<const MeshParameters *> meshes;
      for (const auto &b : bodies)
        if (b.given == nullptr)
          meshes.push_back(&b.mesh);
      InputParsing::check_run_size(meshes, n_cycles, opt.degree, prm.get_bool("Allow large runs"), prm_directory,
                                   opt.solver == "UMFPACK" || opt.solver == "KLU" ?
                                     InputParsing::SolverKind::direct :
                                     InputParsing::SolverKind::iterative,
                                   prm.get_double("Memory limit"));
    }
    create_output_folder(opt.output_folder);
  }



  unsigned int
  ContactProblem::add_body(const PolygonalMesh<2>   &mesh,
                           const ConstitutiveLaw<2> &material,
                           const unsigned int        boundary_id_offset)
  {
    const unsigned int b = bodies.size();
    AssertThrow(b < max_bodies,
                dealii::ExcMessage("ContactProblem::add_body(): at most " + std::to_string(max_bodies) +
                                   " bodies."));
    AssertThrow(mesh.n_cells() > 0,
                dealii::ExcMessage("ContactProblem::add_body(): the mesh of body " + std::to_string(b) +
                                   (mesh.name.empty() ? std::string() : " ('" + mesh.name + "')") +
                                   " has no cells."));
    AssertThrow(material.is_linear(),
                dealii::ExcMessage("ContactProblem::add_body(): the material of body " + std::to_string(b) + " ('" +
                                   material.get_name() +
                                   "') is not linear; the contact problem solves linear elasticity."));
    {
      const auto *mine  = dynamic_cast<const ElasticMaterial *>(&material);
      const auto *first = bodies.empty() ? nullptr : dynamic_cast<const ElasticMaterial *>(bodies[0].material.get());
      AssertThrow(mine == nullptr || first == nullptr || first->model() == mine->model(),
                  dealii::ExcMessage("ContactProblem::add_body(): body " + std::to_string(b) + " is in " +
                                     ElasticMaterial::model_name(mine->model()) + ", body 0 in " +
                                     ElasticMaterial::model_name(first->model()) +
                                     ": all bodies of a problem share the model."));
    }
    Body body;
    auto given = std::make_shared<PolygonalMesh<2>>(mesh);
    MeshParameters::shift_boundary_ids(*given, boundary_id_offset,
                                       "ContactProblem::add_body(): body " + std::to_string(b) +
                                         ", boundary id offset " + std::to_string(boundary_id_offset));
    body.given    = given;
    body.material = material.clone();
    body.mesh.material_id = b;
    body.name             = "body " + std::to_string(b);
    bodies.push_back(std::move(body));
    return b;
  }



  std::vector<unsigned int>
  ContactProblem::add_parts(const PolygonalMesh<2>                                                         &mesh,
                            const ConstitutiveLaw<2>                                                       &material,
                            const std::map<dealii::types::material_id, std::shared_ptr<const ConstitutiveLaw<2>>> &part_laws,
                            const unsigned int boundary_id_offset)
  {
    std::vector<unsigned int> added;
    const auto                ids   = mesh.get_material_ids();
    const auto                parts = mesh.split_by_material_id();
    for (unsigned int i = 0; i < parts.size(); ++i)
      {
        const auto         it  = part_laws.find(ids[i]);
        const unsigned int b   = add_body(parts[i], it != part_laws.end() && it->second ? *it->second : material,
                                        boundary_id_offset);
        bodies[b].name = "body " + std::to_string(b) + " (material id " + std::to_string(ids[i]) + ")";
        added.push_back(b);
      }
    return added;
  }



  void
  ContactProblem::set_friction_coefficient(const unsigned int body_a, const unsigned int body_b, const double mu)
  {
    AssertThrow(std::isfinite(mu) && mu >= 0 && mu <= 1e6,
                dealii::ExcMessage("ContactProblem::set_friction_coefficient(" + std::to_string(body_a) + ", " +
                                   std::to_string(body_b) + ", mu): the friction coefficient must be a number "
                                   "from 0 to 1e6."));
    body_friction.insert(body_friction.begin(), std::make_tuple(body_a, body_b, mu));
  }



  void
  ContactProblem::set_material_name(const unsigned int body, const std::string &name)
  {
    AssertThrow(body < bodies.size(),
                dealii::ExcMessage("ContactProblem::set_material_name(" + std::to_string(body) +
                                   ", ...): there is no body " + std::to_string(body) + " (there are " +
                                   std::to_string(bodies.size()) + ")."));
    check_material_name(name, "ContactProblem::set_material_name()");
    bodies[body].material_name = name;
  }



  void
  ContactProblem::set_friction_coefficient(const std::string &material_a,
                                           const std::string &material_b,
                                           const double       mu)
  {
    for (const std::string &name : {material_a, material_b})
      if (name != "*")
        check_material_name(name, "ContactProblem::set_friction_coefficient(\"" + material_a + "\", \"" +
                                    material_b + "\", mu)");
    AssertThrow(std::isfinite(mu) && mu >= 0 && mu <= 1e6,
                dealii::ExcMessage("ContactProblem::set_friction_coefficient(\"" + material_a + "\", \"" +
                                   material_b + "\", mu): the friction coefficient must be a number from 0 to 1e6."));
    material_friction.insert(material_friction.begin(), std::make_tuple(material_a, material_b, mu));
  }



  double
  ContactProblem::friction_between(const unsigned int a, const unsigned int b) const
  {
    const unsigned int any = dealii::numbers::invalid_unsigned_int;
    // a pair of bodies first, then one body and a wildcard, then two
    // wildcards; the latest entry of a kind wins (body_friction is latest
    // first)
    for (const unsigned int wildcards : {0u, 1u, 2u})
      for (const auto &[x, y, mu] : body_friction)
        {
          const unsigned int n_any = (x == any) + (y == any);
          if (n_any != wildcards)
            continue;
          const auto matches = [&](const unsigned int p, const unsigned int q) {
            return (x == any || x == p) && (y == any || y == q);
          };
          if (matches(a, b) || matches(b, a))
            return mu;
        }
    // then the materials, in the same order of precedence
    const std::string &name_a = bodies[a].material_name, &name_b = bodies[b].material_name;
    for (const unsigned int wildcards : {0u, 1u, 2u})
      for (const auto &[x, y, mu] : material_friction)
        {
          const unsigned int n_any = (x == "*") + (y == "*");
          if (n_any != wildcards)
            continue;
          const auto matches = [&](const std::string &p, const std::string &q) {
            return (x == "*" || (!p.empty() && x == p)) && (y == "*" || (!q.empty() && y == q));
          };
          if (matches(name_a, name_b) || matches(name_b, name_a))
            return mu;
        }
    return -1;
  }



  unsigned int
  ContactProblem::add_body(const dealii::Triangulation<2, 2> &tria,
                           const ConstitutiveLaw<2>          &material,
                           const unsigned int                 boundary_id_offset)
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::from_triangulation(mesh, tria);
    mesh.name = "body " + std::to_string(bodies.size());
    return add_body(mesh, material, boundary_id_offset);
  }



  void
  ContactProblem::add_contact_pair(const dealii::types::boundary_id master,
                                   const dealii::types::boundary_id slave,
                                   const double                     friction_coefficient,
                                   const std::string               &name)
  {
    const std::string who = name.empty() ? "ContactProblem::add_contact_pair(" + std::to_string(int(master)) +
                                             ", " + std::to_string(int(slave)) + ")" :
                                           name;
    AssertThrow(master <= InputParsing::max_boundary_id &&
                  slave <= InputParsing::max_boundary_id && master != slave,
                dealii::ExcMessage(who + ": two different boundary ids below 255 expected."));
    AssertThrow(std::isfinite(friction_coefficient) && friction_coefficient <= 1e6,
                dealii::ExcMessage(who + ": the friction coefficient " + std::to_string(friction_coefficient) +
                                   " is not a number from 0 to 1e6 (negative: the default of the contact settings)."));
    for (const auto &other : contact_pairs)
      for (const unsigned int id : {other.first, other.second})
        AssertThrow(id != master && id != slave,
                    dealii::ExcMessage(who + ": boundary id " + std::to_string(id) +
                                       " is already part of the contact pair " + std::to_string(other.first) +
                                       " : " + std::to_string(other.second) +
                                       "; a boundary part can belong to one contact pair only."));
    contact_pairs.emplace_back(master, slave);
    pair_friction.push_back(friction_coefficient < 0 ? -1. : friction_coefficient);
  }



  void
  ContactProblem::clear()
  {
    bodies.clear();
    contact_pairs.clear();
    pair_friction.clear();
    body_friction.clear();
    material_friction.clear();
    opt.detect_pairs = false;
    bc.clear();
    n_cycles = 1;
    prm_directory.clear();
  }



  void
  ContactProblem::check_setup() const
  {
    AssertThrow(!bodies.empty(),
                dealii::ExcMessage("ContactProblem: no body; add one with add_body() or read a parameter file."));
    AssertThrow(opt.degree == 1 || opt.degree == 2,
                dealii::ExcMessage("Parameter 'Discretization/Order' is " + std::to_string(opt.degree) +
                                   ": the order k of the virtual elements must be 1 or 2."));
    InputParsing::check_range(opt.stabilization_factor, 1e-6, 1e6, "Discretization/Stabilization factor");
    const auto &cs = opt.contact;
    InputParsing::check_range(cs.friction_coefficient, 0, 1e6, "Contact/Friction coefficient", false, false,
                              "The Coulomb friction coefficient is a number >= 0.");
    const std::string tangential_name = ContactSettings::tangential_name(cs.tangential);
    if (!cs.is_coulomb())
      {
        std::ostringstream mu;
        mu << cs.friction_coefficient;
        AssertThrow(cs.friction_coefficient == 0,
                    dealii::ExcMessage("Parameter 'Contact/Friction coefficient' is " + mu.str() +
                                       ", but 'Contact/Tangential' is '" +
                                       tangential_name +
                                       "': a friction coefficient needs 'Tangential = coulomb' or "
                                       "'coulomb penalty'."));
        AssertThrow(body_friction.empty(),
                    dealii::ExcMessage("Parameter 'Contact/Friction between bodies' gives friction coefficients, "
                                       "but 'Contact/Tangential' is '" + tangential_name +
                                       "': a friction coefficient needs 'Tangential = coulomb' or "
                                       "'coulomb penalty'."));
        AssertThrow(material_friction.empty(),
                    dealii::ExcMessage("Parameter 'Contact/Friction between materials' gives friction "
                                       "coefficients, but 'Contact/Tangential' is '" + tangential_name +
                                       "': a friction coefficient needs 'Tangential = coulomb' or "
                                       "'coulomb penalty'."));
        for (unsigned int i = 0; i < pair_friction.size(); ++i)
          AssertThrow(pair_friction[i] < 0,
                      dealii::ExcMessage("Parameter 'Contact/Pairs': the entry of interface " + std::to_string(i) +
                                         " gives a friction coefficient, but 'Contact/Tangential' is '" +
                                         tangential_name +
                                         "': a friction coefficient needs 'Tangential = coulomb' or "
                                         "'coulomb penalty'."));
      }
    else
      AssertThrow(cs.normal == ContactSettings::Normal::unilateral,
                  dealii::ExcMessage("Parameter 'Contact/Tangential' is '" + tangential_name +
                                     "' (Coulomb friction) but 'Contact/Normal' is 'tied': friction needs "
                                     "unilateral normal contact, where a pair can open and the pressure "
                                     "bounds the friction force. Use 'Normal = unilateral', or "
                                     "'Tangential = multipliers' for a tied interface that sticks."));
    // the penalty itself is bounded relative to E_min / h_min once the
    // interfaces are known (setup_system()); its factor is dimensionless
    InputParsing::check_range(cs.penalty, 0, std::numeric_limits<double>::max(), "Contact/Penalty", false, false,
                              "0 selects the default rule 'Penalty factor' * E_min / h_min.");
    InputParsing::check_range(cs.penalty_factor, ContactScales::min_penalty_factor,
                              ContactScales::max_penalty_factor, "Contact/Penalty factor", false, false,
                              "The stick penalty is this factor times E_min / h_min: a much smaller one leaves "
                              "the stick direction nearly free, a larger one makes the system too "
                              "ill-conditioned for correct pressures.");
    AssertThrow(cs.max_active_set_iterations >= 1,
                dealii::ExcMessage("Parameter 'Contact/Maximum active set iterations' must be at least 1."));
    InputParsing::check_range(opt.insertion.merge_fraction, 1e-6, 0.49, "Contact/Merge fraction");
    InputParsing::check_range(opt.insertion.search_distance, 0, 1e300, "Contact/Search distance", false, false);
    if (opt.insertion.coordinate_precision != NodeInsertion::Settings::detect_precision)
      InputParsing::check_range(opt.insertion.coordinate_precision, 0, 0.01, "Contact/Coordinate precision", false,
                                true, "Give 'auto' for the precision of the data, or a fraction of the interface size.");
    AssertThrow(bodies.size() == 1 || !contact_pairs.empty() || opt.detect_pairs,
                dealii::ExcMessage("Parameter 'Contact/Pairs' is empty but there are " +
                                   std::to_string(bodies.size()) + " bodies: name at least one contact pair, or "
                                   "'auto' to detect them."));
    for (const auto &[a, b, mu] : body_friction)
      for (const unsigned int body : {a, b})
        AssertThrow(body == dealii::numbers::invalid_unsigned_int || body < bodies.size(),
                    dealii::ExcMessage("ContactProblem::set_friction_coefficient(): there is no body " +
                                       std::to_string(body) + " (there are " + std::to_string(bodies.size()) +
                                       ")."));
    {
      std::set<std::string> names;
      for (const Body &body : bodies)
        names.insert(body.material_name);
      for (const auto &[a, b, mu] : material_friction)
        for (const std::string &name : {a, b})
          AssertThrow(name == "*" || names.count(name) != 0,
                      dealii::ExcMessage("Friction between materials (parameter 'Contact/Friction between "
                                         "materials' or ContactProblem::set_friction_coefficient()): no body has "
                                         "the material '" + name + "' (names come from 'Material/Name', the "
                                         "fourth field of 'Material/Part materials', or set_material_name())."));
    }
    InputParsing::check_range(opt.detection.distance, 0, 10, "Contact/Detection distance");
    InputParsing::check_range(opt.detection.max_angle, 1, 89, "Contact/Detection angle");
    AssertThrow(opt.n_load_steps >= 1 && opt.n_load_steps <= 100000,
                dealii::ExcMessage("Parameter 'Load steps/Number of steps' is " + std::to_string(opt.n_load_steps) +
                                   ": it must be at least 1 (and at most 100000)."));
    InputParsing::check_range(opt.final_time, 0, 1e300, "Load steps/Final time", true, false,
                              "The load steps run from t = 0 to the final time.");
    InputParsing::check_range(opt.solver_tolerance, 0, 1, "Solver/Relative tolerance", true, true);
    AssertThrow(opt.solver_max_iterations >= 1,
                dealii::ExcMessage("Parameter 'Solver/Maximum iterations' must be at least 1."));
    if (opt.solver != "automatic")
      (void)SaddlePointSolver::parse_type(opt.solver);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      AssertThrow(bodies[b].given == nullptr || n_cycles == 1,
                  dealii::ExcMessage("ContactProblem: body " + std::to_string(b) +
                                     " was given as a mesh, which has no refinement cycles; refine it in "
                                     "your program and run once per mesh."));
    check_output_names(opt.output_folder, opt.base_name);
  }



  void
  ContactProblem::run()
  {
    check_setup();
    // (the friction coefficients of the pairs are set per cycle, when the
    // detected interfaces are known: insert_nodes())
    contact_settings = opt.contact;
    // with several MPI processes every process computes the same
    // postprocessing from the gathered solution; process 0 alone prints and
    // writes (the flags and std::cout are restored on the way out, also
    // after an error)
    struct Silence
    {
      struct NullBuffer : std::streambuf
      {
        int
        overflow(const int c) override
        {
          return c;
        }
      };
      NullBuffer              sink;
      std::streambuf         *old = nullptr;
      ContactProblem         &p;
      std::array<bool, 4>     flags;
      Silence(ContactProblem &p)
        : p(p)
        , flags{{p.opt.write_vtu, p.opt.write_csv, p.opt.write_json, p.opt.write_pictures}}
      {
        if (p.root)
          return;
        old = std::cout.rdbuf(&sink);
        p.opt.write_vtu = p.opt.write_csv = p.opt.write_json = p.opt.write_pictures = false;
      }
      ~Silence()
      {
        if (old != nullptr)
          std::cout.rdbuf(old);
        p.opt.write_vtu      = flags[0];
        p.opt.write_csv      = flags[1];
        p.opt.write_json     = flags[2];
        p.opt.write_pictures = flags[3];
      }
    } silence(*this);
    if (root)
      std::filesystem::create_directories(opt.output_folder);
    // the files under the output prefix belong to this run only: those of
    // an earlier run go first (process 0 writes every file)
    RunFiles run_files(opt.output_folder, opt.base_name, root, opt.write_vtu || opt.write_csv || opt.write_json || opt.write_pictures);
    std::cout << run_files.removal_note(run_files.start());
    try
      {
        if (opt.finite_strain)
          run_finite_sliding();
        else
          run_cycles();
      }
    catch (...)
      {
        // the program prints the list after the error
        run_files.failed();
        throw;
      }
    run_files.complete();
  }



  std::vector<ScaleCheck::Body>
  ContactProblem::scale_check_bodies() const
  {
    // each body by its material id (= its index), its name, the parameter
    // that sets its modulus, and its characteristic stiffness
    std::vector<ScaleCheck::Body> result;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      result.push_back({dealii::types::material_id(b), bodies[b].name,
                        bodies[b].modulus_parameter.empty() ? "Young's modulus of " + bodies[b].name :
                                                              bodies[b].modulus_parameter,
                        bodies[b].material->characteristic_stiffness()});
    return result;
  }



  void
  ContactProblem::run_finite_sliding()
  {
    const auto &cs = opt.contact;
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

    // the bodies in one mesh, their laws by material id (= body index)
    PolygonalMesh<2>   mesh;
    MaterialLibrary<2> laws;
    make_body_meshes(0, mesh, laws);
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
      dofs.distribute_dofs(opt.degree);
      FiniteStrainAssembler<2> assembler(dofs, laws);
      bc.set_time(opt.final_time);
      bc.add_finite_strain_loads(assembler, "Finite strain/Enabled", opt.pressure_load);
      const std::vector<ScaleCheck::Body> scale_bodies = scale_check_bodies();
      std::ostringstream when;
      when << "at t = " << opt.final_time;
      dealii::Vector<double> f;
      assembler.assemble_load_vector(f);
      ScaleCheck::check(dofs, f, scale_bodies, when.str(), true);
    }
    // the friction coefficient between two bodies: 'Friction between
    // bodies', then 'between materials', then 'Friction coefficient'
    const auto body_mu = [this, &cs](const unsigned int a, const unsigned int b) {
      if (!cs.is_coulomb())
        return 0.;
      const double mu = (a < bodies.size() && b < bodies.size()) ? friction_between(a, b) : -1.;
      return mu >= 0 ? mu : cs.friction_coefficient;
    };
    std::vector<FiniteSliding::InterfaceData> interfaces;
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
    FiniteSliding::Parameters parameters;
    if (opt.detect_pairs)
      {
        // the free boundary of the bodies: every boundary id without a
        // boundary condition or a named pair
        auto &d    = parameters.detection;
        d.enabled  = true;
        d.settings = opt.detection;
        d.friction = body_mu;
        std::set<dealii::types::boundary_id> excluded = bc.used_boundary_ids();
        for (const auto &p : contact_pairs)
          excluded.insert({p.first, p.second});
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
    FiniteSliding sliding(mesh, laws, interfaces, parameters);
    // the Dirichlet data and the loads are expressions of t, as in the
    // small-strain path: the loads at the time of the step, unscaled
    sliding.set_constraints_function(
      [this](const VEMDoFHandler<2> &dofs, const double t, dealii::AffineConstraints<double> &constraints) {
        bc.set_time(t);
        bc.apply_constraints(dofs, constraints);
        constraints.close();
      });
    sliding.set_loads([this](FiniteStrainAssembler<2> &assembler) {
      bc.add_finite_strain_loads(assembler, "Finite strain/Enabled", opt.pressure_load);
    },
                      [](const double) { return 1.; });

    const std::string prefix = opt.output_folder + "/" + opt.base_name;
    std::vector<std::pair<double, std::string>> series;
    JsonSummary                                 json;
    json.set("program", "dealvem");
    json.set("problem", "finite sliding");
    json.set("bodies", double(bodies.size()));
    json.set("order", double(opt.degree));
    json.set("load_steps", double(opt.n_load_steps));
    const auto write_json = [&](const std::string &status) {
      if (opt.write_json)
        {
          json.set("status", status);
          json.write(prefix + ".json");
        }
    };
    json.set("moment_point.x", opt.moment_point[0]);
    json.set("moment_point.y", opt.moment_point[1]);
    // the history CSV; its header is written with the first step, which
    // names the supports
    std::ostringstream csv;
    if (opt.write_pictures)
      std::cout << "note: finite sliding writes no SVG pictures ('Output/Write pictures' applies to the "
                   "small-strain path); the bodies of every step are in the VTU files, the forces in the history "
                   "CSV"
                << std::endl;
    // the interfaces of the results: the named pairs, then (Pairs = auto)
    // every pair of bodies, whose detected interfaces are summed
    const auto        &reported   = sliding.get_reported_interfaces();
    const unsigned int n_reported = reported.size();
    std::cout << "Finite strain with finite sliding: " << bodies.size() << " bodies, " << interfaces.size()
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
        std::cout << "  interface " << i << ": "
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
    for (unsigned int n = 1; n <= opt.n_load_steps; ++n)
      {
        const double time = opt.final_time * n / opt.n_load_steps;
        try
          {
            sliding.solve_step(n, time);
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
        const auto  &r       = sliding.get_history().back();
        unsigned int updates = 0;
        for (const auto &pass : r.newton)
          updates += pass.iterations.empty() ? 0 : pass.iterations.size() - 1;
        std::cout << "  step " << n << " (t = " << time << "): " << r.n_passes << " pairing pass"
                  << (r.n_passes == 1 ? "" : "es") << ", " << updates << " Newton updates, " << r.n_active
                  << " active pairs (" << r.n_slipping << " slipping), offset " << r.pairing_offset;
        if (opt.detect_pairs)
          std::cout << ", " << r.n_detected << " interface" << (r.n_detected == 1 ? "" : "s") << " detected";
        for (unsigned int i = 0; i < n_reported; ++i)
          std::cout << "; interface " << i << ": normal force (" << r.normal_force[i] << "), friction force ("
                    << r.friction_force[i] << ")";
        std::cout << std::endl;
        const auto outputs = finite_sliding_step_outputs(sliding, n_reported, time, bc, opt.moment_point);
        for (unsigned int i = 0; i < n_reported; ++i)
          std::cout << "    interface " << i << ": force on the slave side (" << outputs.force[i][0] << ", "
                    << outputs.force[i][1] << "), moment " << outputs.moment[i] << " about ("
                    << opt.moment_point[0] << ", " << opt.moment_point[1] << ")" << std::endl;
        print_reactions(outputs.reactions, opt.moment_point, "    ");
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
        csv << ',' << full(outputs.load[0]) << ',' << full(outputs.load[1]) << ',' << full(outputs.load_moment)
            << "\n";
        json.set(key + "loads.force_x", outputs.load[0]);
        json.set(key + "loads.force_y", outputs.load[1]);
        json.set(key + "loads.moment", outputs.load_moment);
        if (opt.write_csv)
          write_finite_sliding_pairs(step_prefix(prefix, n) + "-interface.csv", outputs.pairs);
        json.set("converged_steps", double(n));
        if (opt.write_vtu)
          {
            std::ostringstream file;
            file << prefix << "-step-" << std::setw(3) << std::setfill('0') << n << ".vtu";
            write_finite_strain_vtu_file(file.str(), sliding.get_dof_handler(), laws, sliding.get_solution());
            series.emplace_back(time, std::filesystem::path(file.str()).filename().string());
            write_pvd_record(prefix + ".pvd", series);
          }
        if (opt.write_csv)
          {
            OutputFile out(prefix + "-history.csv");
            out.stream() << csv.str();
            out.commit();
          }
        write_json("running");
      }
    write_json("complete");
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
          std::cout << "Cycle " << cycle << ":" << std::endl;
        run_cycle(cycle);
        convergence.push_back(results.errors);
        for (unsigned int b = 0; b < bodies.size(); ++b)
          {
            if (cycle > 0 && results.dofs_per_body[b] <= dofs_per_cycle[b].back())
              std::cout << "warning: body " << b << " has " << results.dofs_per_body[b]
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
            std::cout << "Relative errors of body " << b << " (against its exact solution):" << std::endl;
            t.write_text(std::cout, dealii::TableHandler::org_mode_table);
          }
  }



  // The state of one cycle: everything built on the mesh of the cycle,
  // declared in the order it is built, so that it is destroyed in the
  // reverse order (the solvers before the assembler before the DoF
  // handler before the mesh, which lives in Results).
  struct ContactProblem::CycleData
  {
    dealii::TimerOutput timer{std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times};
    MaterialLibrary<2>                                    materials;
    std::vector<dealii::Point<2>>                         original_vertices;
    VEMDoFHandler<2>                                      dof_handler;
    std::vector<ContactNodePair>                          pairs;
    /// Master and slave body of each interface (from the boundary ids).
    std::vector<std::array<unsigned int, 2>>              interface_bodies;
    double                                                complementarity = 0;
    std::unique_ptr<ContactAssembler<2>>                  contact;
    dealii::AffineConstraints<double>                     constraints;
    /// The supports of the constraints (their reactions per step).
    std::vector<SupportReactions::Support>                supports;
    std::unique_ptr<RigidBodySupport>                     support;
    // the distributed path: partition, the elasticity part of the step,
    // and the solver (also held as `solver`)
    std::unique_ptr<VEMPartition<2>>                      partition;
    std::unique_ptr<ElasticityAssembler<2>>               assembler;
    DistributedContactSolver                             *distributed_solver = nullptr;
    unsigned int                                          n = 0, m = 0;
    dealii::SparsityPattern                               sparsity;
    dealii::SparseMatrix<double>                          system_matrix, work_matrix;
    dealii::Vector<double>                                system_rhs, x;
    std::unique_ptr<SaddlePointSolver>                    solver;
    std::unique_ptr<ActiveSetSolver<2>>                   active_set;
    std::unique_ptr<FrictionSolver<2>>                    friction_solver;
    std::vector<PairState>                                state;
    std::vector<double>                                   reference;
    typename ActiveSetSolver<2>::Result                   as;
    typename FrictionSolver<2>::Result                    fr;
    std::unique_ptr<StressRecovery<2>>                    stresses;
    std::string                                           prefix;
  };

  ContactProblem::ContactProblem(const MPI_Comm comm, const ElasticityProblem::Parallelism parallelism)
    : mpi_communicator(comm)
    // (a program that never initialised MPI runs serially)
    , n_processes(dealii::Utilities::MPI::job_supports_mpi() ? dealii::Utilities::MPI::n_mpi_processes(comm) : 1)
    , distributed(parallelism == ElasticityProblem::Parallelism::distributed ||
                  (parallelism == ElasticityProblem::Parallelism::automatic && n_processes > 1))
    , root(!dealii::Utilities::MPI::job_supports_mpi() || dealii::Utilities::MPI::this_mpi_process(comm) == 0)
  {
    AssertThrow(!distributed || dealii::Utilities::MPI::job_supports_mpi(),
                dealii::ExcMessage("ContactProblem: the distributed path needs MPI to be initialised "
                                   "(dealii::Utilities::MPI::MPI_InitFinalize in main())."));
  }

  ContactProblem::~ContactProblem() = default;



  void
  ContactProblem::run_cycle(const unsigned int cycle)
  {
    // the previous cycle's objects refer to the previous mesh: release
    // them before the mesh goes
    data.reset();
    results = Results();
    data    = std::make_unique<CycleData>();
    data->prefix = output_prefix(opt.output_folder, opt.base_name, cycle, n_cycles);

    make_meshes(cycle);
    insert_nodes();
    setup_system();
    for (unsigned int step = 1; step <= opt.n_load_steps; ++step)
      {
        const double time = opt.final_time * step / opt.n_load_steps;
        assemble_system(time);
        solve(step, time);
        process_step(step, time);
      }
    postprocess();
    output_results();
  }



  // The bodies' meshes, one material id per body, appended into one mesh.
  void
  ContactProblem::make_meshes(const unsigned int cycle)
  {
    dealii::TimerOutput::Scope t(data->timer, "mesh");
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
    dealii::TimerOutput::Scope t(data->timer, "node insertion");
    PolygonalMesh<2>          &mesh       = results.mesh;
    auto                      &interfaces = results.interfaces;
    // the explicit pairs, then the detected ones
    cycle_pairs    = contact_pairs;
    cycle_friction = pair_friction;
    if (opt.detect_pairs)
      {
        dealii::TimerOutput::Scope detection_timer(data->timer, "contact detection");
        std::set<dealii::types::boundary_id> excluded = bc.used_boundary_ids();
        for (const auto &p : contact_pairs)
          excluded.insert({p.first, p.second});
        results.detection = ContactDetection::detect(mesh, excluded, ContactDetection::first_free_id(mesh),
                                                     opt.detection);
        std::cout << ContactDetection::describe(results.detection);
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



  // DoFs; the contact scales (one rule, ContactScales); the contact
  // assembler; the displacement constraints at the first load step,
  // checked with the contact pairs to hold every body; the sparsity
  // pattern of the saddle-point system; the solvers.
  void
  ContactProblem::setup_system()
  {
    CycleData &d = *data;
    d.dof_handler.reinit(results.mesh);
    d.dof_handler.distribute_dofs(opt.degree);

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
      dealii::TimerOutput::Scope     t(d.timer, "assembly");
      dealii::DynamicSparsityPattern dsp(d.n + d.m);
      // distributed: the stiffness is assembled per process by the solver,
      // this matrix holds only the contact blocks
      if (!distributed)
        d.dof_handler.make_sparsity_pattern(dsp);
      d.contact->add_sparsity(dsp);
      d.constraints.condense(dsp);
      d.sparsity.copy_from(dsp);
      d.system_matrix.reinit(d.sparsity);
      d.work_matrix.reinit(d.sparsity);
    }

    SaddlePointSolver::Settings settings;
    if (opt.solver == "automatic")
      {
        // the condensed solves need symmetric contact rows; Coulomb's slip
        // rows are not: the whole saddle point by UMFPACK
        std::ostringstream why;
        if (d.n <= InputParsing::contact_direct_solver_max_dofs)
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
        std::cout << "  solver (Solver/Type = automatic): " << SaddlePointSolver::type_name(settings.type) << ", "
                    << why.str() << std::endl;
      }
    else
      settings.type = SaddlePointSolver::parse_type(opt.solver);
    settings.relative_tolerance = opt.solver_tolerance;
    settings.max_iterations     = opt.solver_max_iterations;
    settings.warm_start         = opt.warm_start;
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
    if (settings.type != SaddlePointSolver::Type::umfpack && settings.type != SaddlePointSolver::Type::klu &&
        settings.type != SaddlePointSolver::Type::direct_constraints)
      d.solver->set_near_null_space(d.dof_handler.rigid_body_modes());
    d.active_set = std::make_unique<ActiveSetSolver<2>>(*d.contact, d.constraints, *d.solver, contact_settings,
                                                        d.complementarity);
    d.active_set->set_support(d.support.get());
    d.active_set->set_pair_neighbours(ActiveSetSolver<2>::pair_neighbours(results.interfaces));
    d.reference.assign(d.pairs.size(), 0.);
    if (contact_settings.is_coulomb())
      {
        d.friction_solver = std::make_unique<FrictionSolver<2>>(*d.contact, d.constraints, *d.solver,
                                                                contact_settings, d.complementarity);
        d.friction_solver->set_support(d.support.get());
        d.state = d.friction_solver->initial_state();
      }
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
    dealii::TimerOutput::Scope t(d.timer, "assembly");
    bc.set_time(time);
    d.constraints.clear();
    bc.apply_constraints(d.dof_handler, d.constraints, &d.supports);
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
        dealii::TimerOutput::Scope t(d.timer, "solve");
        if (d.friction_solver)
          {
            d.fr        = d.friction_solver->solve(d.system_matrix, d.system_rhs, d.work_matrix, d.x, d.state,
                                            d.reference);
            d.state     = d.fr.state;
            d.reference = d.fr.reference;
            d.as        = typename ActiveSetSolver<2>::Result();
            d.as.n_iterations      = d.fr.n_iterations;
            d.as.linear_iterations = d.fr.linear_iterations;
            for (const auto &h : d.fr.history)
              d.as.n_active_history.push_back(h[1] + h[2]);
            for (const auto s : d.fr.state)
              d.as.active.push_back(s != PairState::open);
          }
        else
          d.as = d.active_set->solve(d.system_matrix, d.system_rhs, d.work_matrix, d.x);
      }
    catch (...)
      {
        const CollapseMechanism *found =
          d.friction_solver ? d.friction_solver->last_mechanism() :
          d.active_set      ? d.active_set->last_mechanism() :
                              nullptr;
        if (found != nullptr)
          {
            mechanism = std::make_shared<const CollapseMechanism>(*found);
            write_mechanism();
          }
        if (opt.n_load_steps > 1)
          {
            std::cout << "  load step " << step << " of " << opt.n_load_steps << " (t = " << time
                      << ") failed; the results of the " << step - 1 << " converged step(s) are kept";
            if (opt.write_vtu || opt.write_csv)
              std::cout << " (" << d.prefix << "-step-*, " << d.prefix << ".pvd)";
            std::cout << "." << std::endl;
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
    std::cout << "  collapse mechanism: " << mechanism->failing_condition;
    if (opt.write_vtu)
      {
        StressRecovery<2> zero(dh, d.materials, field);
        write_vtu_file(d.prefix + "-mechanism.vtu", dh, field, zero);
        std::cout << "; " << d.prefix << "-mechanism.vtu";
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
        std::cout << "; " << d.prefix << "-mechanism.svg";
      }
    std::cout << std::endl;
  }



  // The interface results of a load step: gaps, slips, multipliers,
  // recovered pressure and shear per node pair, the step's counts, its
  // progress line and (with several steps) its files.
  void
  ContactProblem::process_step(const unsigned int step, const double time)
  {
    CycleData  &d          = *data;
    const auto &n          = d.n;
    const auto &x          = d.x;
    const auto &as         = d.as;
    const auto &fr         = d.fr;
    const auto &state      = d.state;
    const auto &pairs      = d.pairs;
    const auto &contact    = *d.contact;
    const auto &interfaces = results.interfaces;
    const bool  friction   = (d.friction_solver != nullptr);
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

    // interface results
    const auto gaps  = contact.gaps(x);
    const auto slips = contact.slips(x);
    const auto ft    = friction ? std::vector<double>() : contact.tangential_forces(x);
    // the pressure per interface is recovered from the nodal forces -lambda
    // by ContactPressure::recover(): at each closed pair, a least-squares fit
    // of a polynomial of degree k whose nodal forces match those of the
    // closed pairs within three sub-edges on each side (not the consistent
    // solve M_Gamma p = -lambda, which amplifies the node-by-node patterns);
    // the tangential nodal force on the slave node, along t
    std::vector<double> tangential_force(pairs.size(), 0.);
    for (unsigned int i = 0; i < pairs.size(); ++i)
      tangential_force[i] = (friction ? -fr.tangential_multiplier[i] : ft[i]);
    // the same recovery for the tangential traction
    std::vector<double> recovered, recovered_shear;
    {
      unsigned int offset = 0;
      for (const auto &itf : interfaces)
        {
          std::vector<double> force(itf.pairs.size()), force_t(itf.pairs.size());
          std::vector<bool>   closed(itf.pairs.size());
          for (unsigned int j = 0; j < force.size(); ++j)
            {
              force[j]   = -x[n + offset + j];
              force_t[j] = tangential_force[offset + j];
              closed[j]  = as.active[offset + j];
            }
          // a fit of degree k: linear for k = 1, where it filters the
          // node-by-node kink pattern of the raw forces; quadratic for k = 2,
          // whose raw forces carry no such pattern (diagonal stabilization)
          // and where a linear fit over the patch misses the curvature of
          // the pressure (Hertz, level 0: 1.20 % against 0.47 % of p0)
          const unsigned int fit = itf.degree;
          const auto p = ContactPressure::recover(itf, force, closed, 3, fit);
          recovered.insert(recovered.end(), p.begin(), p.end());
          const auto q = ContactPressure::recover(itf, force_t, closed, 3, fit);
          recovered_shear.insert(recovered_shear.end(), q.begin(), q.end());
          offset += itf.pairs.size();
        }
    }
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
        r.midpoint        = p.is_midpoint;
        r.active          = as.active[i];
        r.weight          = p.weight;
        r.gap             = gaps[i];
        r.multiplier      = x[n + i];
        r.lumped_pressure = -x[n + i] / p.weight;
        r.pressure        = recovered[i];
        r.at_open_end     = p.at_open_end;
        r.slip            = slips[i];
        r.tangent         = p.tangent;
        r.shear           = recovered_shear[i];
        r.normal          = p.normal;
        // (the convex stick model of the globalized solve ties open pairs
        // tangentially too: their tangential force counts)
        r.tangential_traction =
          (as.active[i] || as.convex_stick_model ? tangential_force[i] / p.weight : 0.);
        if (friction)
          {
            r.slip_increment      = fr.slip_increment[i];
            r.status              = (state[i] == PairState::open ? "open" :
                                     state[i] == PairState::stick ? "stick" :
                                                                    "slip");
          }
        else
          r.status = (as.active[i] ? "closed" : as.convex_stick_model ? "open-tied" : "open");
        step_result.n_open += (!r.active);
        step_result.n_stick += (r.active && r.status != "slip");
        step_result.n_slip += (r.status == "slip");
        results.pairs.push_back(r);
        results.total_contact_force +=
          (-x[n + i]) * p.normal + r.tangential_traction * p.weight * p.tangent;
      }
    // the resultant of each interface
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
          const double       N  = -x[n + i];
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
    results.interface_results = step_result.interfaces;
    step_result.dissipated_energy   = (friction ? fr.dissipated_energy : 0.);
    step_result.total_contact_force = results.total_contact_force;
    step_result.pairs               = results.pairs;
    results.dissipated_energy += step_result.dissipated_energy;
    // nothing non-finite is reported or written: a quantity that overflowed
    // stops the run here, named, before any file of the step is written
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
    verify_step(step, time, tangential_force, step_result);
    results.steps.push_back(step_result);

    if (opt.n_load_steps > 1 || friction)
      {
        std::cout << "  load step " << step << " of " << opt.n_load_steps << ", t = " << time << ": "
                  << as.n_iterations << (friction ? " Newton" : " active-set") << " iteration(s), "
                  << step_result.n_open << " open / " << step_result.n_stick
                  << (friction ? " stick / " : " closed") ;
        if (friction)
          {
            std::cout << step_result.n_slip << " slip, dissipated energy " << step_result.dissipated_energy;
            if (fr.history.size() > 1)
              {
                // the states each iteration solved with
                std::cout << " (open/stick/slip per iteration:";
                for (const auto &h : fr.history)
                  std::cout << " " << h[0] << "/" << h[1] << "/" << h[2];
                std::cout << ")";
              }
            if (!fr.continuation_factors.empty())
              {
                // the plain Newton iteration failed; the continuation in the
                // friction coefficient passed these factors of mu
                std::cout << "; continuation in the friction coefficient, " << fr.n_failed_attempts
                          << " failed attempt(s), converged with mu times";
                for (const double f : fr.continuation_factors)
                  std::cout << " " << f;
              }
            else if (fr.globalized_start)
              std::cout << "; the Newton iteration failed, solved as a fixed point of "
                        << fr.n_fixed_point_iterations << " Tresca problem(s) (globally convergent; "
                        << fr.n_globalized_solves << " solves with the stick solve)";
          }
        std::cout << std::endl;
        print_reactions(step_result.reactions, opt.moment_point, "    ");
      }
    if (opt.n_load_steps > 1)
      output_step(step);
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
    const CycleData &d     = *data;
    const auto      &n     = d.n;
    const auto      &x     = d.x;
    const auto      &pairs = d.pairs;
    std::ostringstream where;
    where << (opt.n_load_steps > 1 ? "load step " + std::to_string(step) + " of " + std::to_string(opt.n_load_steps) : "the contact problem")
          << " (t = " << time << ", " << d.as.n_iterations
          << (d.friction_solver ? " Newton" : " active-set") << " iteration(s), solver " << d.solver->description()
          << ")";
    // the nodal contact forces: on the slave node -lambda_n n + f_t t, the
    // opposite on the master node (as the reported contact force)
    dealii::Vector<double> contact_forces(n);
    std::vector<std::pair<dealii::types::global_dof_index, dealii::types::global_dof_index>> couplings;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto                 dofs = d.contact->pair_dofs(i);
        const bool                 transmits = d.as.active[i] || d.as.convex_stick_model;
        if (transmits)
          for (unsigned int c = 0; c < 2; ++c)
            couplings.emplace_back(dofs[c], dofs[2 + c]);
        const dealii::Tensor<1, 2> F    = (-x[n + i]) * pairs[i].normal +
                                       (transmits ? tangential_force[i] : 0.) * pairs[i].tangent;
        for (unsigned int c = 0; c < 2; ++c)
          {
            contact_forces[dofs[2 + c]] += F[c];
            contact_forces[dofs[c]] -= F[c];
          }
      }
    dealii::Vector<double> u(n);
    for (unsigned int i = 0; i < n; ++i)
      u[i] = x[i];
    const bool   direct    = (d.solver->get_type() == SaddlePointSolver::Type::umfpack ||
                         d.solver->get_type() == SaddlePointSolver::Type::klu);
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
    }

    // an active pair of unilateral contact in tension contradicts the
    // converged active set (and friction's open/stick/slip states)
    if (contact_settings.normal == ContactSettings::Normal::unilateral)
      {
        double largest = 0;
        for (unsigned int i = 0; i < pairs.size(); ++i)
          largest = std::max(largest, std::abs(x[n + i]) / pairs[i].weight);
        for (unsigned int i = 0; i < pairs.size(); ++i)
          if (d.as.active[i] && -x[n + i] / pairs[i].weight < -1e-8 * largest)
            {
              std::ostringstream msg;
              msg << "Verification failed after the solve of " << where.str() << ": the active contact pair at ("
                  << pairs[i].slave_location[0] << ", " << pairs[i].slave_location[1] << ") of interface "
                  << pairs[i].interface << " carries a tensile normal force (pressure " << -x[n + i] / pairs[i].weight
                  << ", largest magnitude " << largest
                  << "), although the converged active set keeps only pairs in compression. The solve is not "
                     "accurate enough for the contact decisions; bring the Young's moduli of the bodies closer "
                     "together.";
              AssertThrow(false, dealii::ExcMessage(msg.str()));
            }
      }
  }



  // The files of load step @p step: the interface CSV, the VTU file and the
  // .pvd time series of the steps so far (rewritten after every step).
  void
  ContactProblem::output_step(const unsigned int step) const
  {
    const CycleData &d = *data;
    if (opt.write_csv)
      {
        write_interface_csv(step_prefix(d.prefix, step) + "-interface.csv", results.pairs);
        write_resultants_csv(step_prefix(d.prefix, step) + "-resultants.csv", results.interface_results);
        write_reactions_csv(d.prefix + "-reactions.csv", results.steps);
      }
    if (opt.write_vtu)
      {
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

    for (const auto &s : d.timer.get_summary_data(dealii::TimerOutput::total_wall_time))
      results.timings[s.first] = s.second;

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
    print_report();
    if (opt.write_csv)
      {
        write_interface_csv(data->prefix + "-interface.csv", results.pairs);
        write_resultants_csv(data->prefix + "-resultants.csv", results.interface_results);
        write_reactions_csv(data->prefix + "-reactions.csv", results.steps);
        std::cout << "  interface results: " << data->prefix << "-interface.csv (node pairs), " << data->prefix
                  << "-resultants.csv (force per interface), " << data->prefix
                  << "-reactions.csv (force and moment per support)" << std::endl;
      }
    if (opt.write_vtu)
      {
        write_vtu_file(data->prefix + ".vtu", data->dof_handler, results.solution, *data->stresses);
        std::cout << "  ParaView file (all bodies, field body_id): " << data->prefix << ".vtu" << std::endl;
        if (opt.n_load_steps > 1)
          std::cout << "  load steps: " << data->prefix << "-step-NNN.vtu, -interface.csv; time series " << data->prefix
                    << ".pvd" << std::endl;
      }
    if (opt.write_pictures)
      write_pictures_files();
    if (opt.write_json)
      write_json_summary();
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
    const auto &as         = d.as;
    const auto &n          = d.n;
    const auto &m          = d.m;
    const unsigned int n_inserted = inserted_nodes(results.insertion_reports);
    std::cout << "Contact problem: " << bodies.size() << " bodies, " << mesh.n_cells() << " cells, "
              << n << " DoFs, " << m << " multipliers" << std::endl
              << "  node insertion: " << n_inserted << " nodes inserted, " << pairs.size() << " node pairs"
              << (results.n_junction_pairs > 0 ?
                    " (" + std::to_string(results.n_junction_pairs) +
                      " where three bodies meet repeat two others and stay open)" :
                    std::string())
              << std::endl;
    // (an assembly of many interfaces: the first ones, and the warnings of all)
    const unsigned int n_listed = 20;
    for (unsigned int i = 0; i < interfaces.size(); ++i)
      {
        const auto &r = interfaces[i].report;
        if (i == n_listed)
          std::cout << "    ... " << interfaces.size() - n_listed << " more interfaces (-resultants.csv)"
                    << std::endl;
        if (i >= n_listed && r.unpaired.empty())
          continue;
        std::cout << "    interface " << i << " (" << cycle_pairs[i].first << " : " << cycle_pairs[i].second
                  << "): " << r.n_inserted_master << " + " << r.n_inserted_slave << " inserted, " << r.n_merged
                  << " merged; " << r.n_closed_gaps << " pairs coincide (largest discretisation gap closed: "
                  << r.max_closed_gap << ")";
        std::cout << std::endl;
        if (!r.unpaired.empty())
          {
            std::cout << "  warning: " << r.unpaired.size() << " node(s) of interface " << i
                      << " inside the overlap of its parts have no partner:" << std::endl;
            for (unsigned int k = 0; k < std::min<std::size_t>(r.unpaired.size(), 5); ++k)
              {
                const auto &u = r.unpaired[k];
                std::cout << "    " << (u.on_master ? "master" : "slave") << " vertex " << u.vertex << " at ("
                          << u.location[0] << ", " << u.location[1] << "): " << u.reason << std::endl;
              }
            if (r.unpaired.size() > 5)
              std::cout << "    ... (" << r.unpaired.size() - 5 << " more)" << std::endl;
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
              std::cout << "  warning: interface " << i << " has real gaps or overlaps (up to " << r.max_kept_gap
                        << ") and keeps them all as measured, but at " << list.size()
                        << " pair(s) the gap (largest " << worst->gap << " at (" << worst->location[0] << ", "
                        << worst->location[1] << ")) is no larger than the chord deviation of the meshes there (up to "
                        << deviation
                        << "): there it cannot be told from a discretisation gap. If the two sides are meant to "
                           "touch along one curve there, refine the interface meshes (the chord deviation falls "
                           "with h^2); to keep every gap without this check, set Close discretisation gaps = false."
                        << std::endl;
            else
              std::cout << "  warning: interface " << i << " has no real gap, so its sides are taken to sample one "
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
    for (const auto &d : contact.get_dropped_constraints())
      std::cout << "  note: the " << (d.tangential ? "tangential" : "normal") << " constraint of the pair at ("
                << d.location[0] << ", " << d.location[1]
                << ") is already imposed by the displacement constraints (value " << d.imposed_value
                << "); its multiplier is dropped." << std::endl;
    for (const auto &r : results.pairs)
      if (r.active && r.at_open_end)
        {
          std::cout << "  warning: the contact pair at (" << r.location[0] << ", " << r.location[1]
                    << ") of interface " << r.interface
                    << " is active and ends the paired part of the interface where the bodies' boundaries "
                       "go on: the contact zone may be cut off. Enlarge the contact parts (boundary ids) "
                       "or the 'Search distance'."
                    << std::endl;
        }
    std::cout
              << "  active set: " << as.n_iterations << " iteration(s), active pairs per iteration:";
    for (const auto a : as.n_active_history)
      std::cout << " " << a;
    if (as.n_closed_for_support > 0)
      std::cout << " (the first set closes the " << as.n_closed_for_support
                << " pair(s) of smallest initial gap, so that every body is held)";
    if (as.n_accelerated > 0)
      std::cout << " (" << as.n_accelerated << " step(s) corrected by the active-set acceleration)";
    if (!as.fast_path_failure.empty())
      {
        std::cout << "\n  globalized solve: the active-set iteration gave up ("
                  << as.fast_path_failure.substr(0, as.fast_path_failure.find(':')) << "); the primal active-set "
                  << "method converged in " << as.n_globalized_solves << " solve(s) and "
                  << as.n_globalized_rigid_steps << " rigid step(s)";
        if (as.n_polish_iterations > 0 || as.convex_stick_model)
          std::cout << (as.convex_stick_model ?
                          ", convex stick model kept (open pairs tied tangentially: the polish to stick at "
                          "closed pairs only did not converge)" :
                          ", polished to stick at closed pairs only in " + std::to_string(as.n_polish_iterations) +
                            " solve(s)");
      }
    std::cout << std::endl << "  solver: " << d.solver->description();
    if (as.linear_iterations > as.n_iterations)
      std::cout << ", " << as.linear_iterations << " linear iterations in all";
    std::cout << std::endl;
    if (distributed)
      std::cout << "  MPI: " << n_processes << " processes, cells per process:" << [&] {
        std::string list;
        for (const auto c : d.partition->cells_per_part())
          list += " " + std::to_string(c);
        return list;
      }() << "; " << results.n_rows_across_processes
                << " contact constraint row(s) couple DoFs of different processes" << std::endl;
    const auto [pmin, pmax] = pressure_range(results.pairs);
    if (pmax >= pmin)
      std::cout << "  contact pressure on active pairs: min " << pmin << ", max " << pmax << std::endl;
    {
      std::array<double, 3> lo{{1e300, 1e300, 1e300}}, hi{{-1e300, -1e300, -1e300}};
      for (const auto &st : results.cell_stress)
        for (unsigned int i = 0; i < 3; ++i)
          {
            lo[i] = std::min(lo[i], st[i]);
            hi[i] = std::max(hi[i], st[i]);
          }
      std::cout << "  cell stresses: sigma_xx in [" << lo[0] << ", " << hi[0] << "], sigma_yy in ["
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
      std::cout << "  verification: every body in equilibrium after every step (largest relative imbalance "
                << worst_imbalance << ", residual " << worst_residual << "; smallest tolerance " << tolerance
                << "; condition up to " << condition << ")" << std::endl;
    }
    std::cout << "  total contact force on the slave side: (" << results.total_contact_force[0]
              << ", " << results.total_contact_force[1] << ")" << std::endl;
    // (with load steps the progress line of each step lists them)
    if (!results.steps.empty() && opt.n_load_steps == 1 && d.friction_solver == nullptr)
      print_reactions(results.steps.back().reactions, opt.moment_point, "  ");

  }



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
    std::vector<SVGPlots::Series> series;
    // (the first 12 interfaces of an assembly; all are in -interface.csv)
    for (unsigned int i = 0; i < std::min<std::size_t>(cycle_pairs.size(), 12); ++i)
      {
        SVGPlots::Series s;
        s.name = "interface " + std::to_string(i) + " (" + std::to_string(cycle_pairs[i].first) +
                 ":" + std::to_string(cycle_pairs[i].second) + ")";
        for (const auto &r : results.pairs)
          if (r.interface == i)
            s.points.emplace_back(r.location[0], r.pressure);
        std::sort(s.points.begin(), s.points.end());
        series.push_back(s);
      }
    SVGPlots::write_line_plot(prefix + "-pressure.svg", series, "x", "contact pressure",
                              "Contact pressure along the interface");
    // the assembly: bodies and the contact force of each interface (on its
    // slave body, at the centre of pressure)
    std::vector<SVGPlots::Arrow> arrows;
    for (const auto &ir : results.interface_results)
      arrows.push_back({ir.centre_of_pressure, ir.force});
    SVGPlots::write_assembly(prefix + "-assembly.svg", mesh, arrows,
                             std::to_string(bodies.size()) + " bodies, " +
                               std::to_string(results.interface_results.size()) +
                               " interfaces: contact force on the slave body at the centre of pressure");
    std::cout << "  pictures: " << prefix << "-stress.svg, " << prefix << "-pressure.svg, " << prefix
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
    const auto &as         = d.as;
    const auto &n          = d.n;
    const auto &m          = d.m;
    const auto &prefix     = d.prefix;
    const bool  friction   = (d.friction_solver != nullptr);
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
    {
      unsigned int n_unpaired = 0, n_closed = 0, n_merged = 0, n_unresolved = 0;
      double       max_closed = 0;
      for (const auto &r : results.insertion_reports)
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
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (!InputParsing::trim(bodies[b].exact).empty())
        {
          const auto       &e = results.errors[b];
          const std::string k = "errors.body" + std::to_string(b) + ".";
          json.set(k + "L2", e.l2 / std::max(e.l2_exact, 1e-300));
          json.set(k + "H1", e.h1_seminorm / std::max(e.h1_exact, 1e-300));
          json.set(k + "energy", e.energy / std::max(e.energy_exact, 1e-300));
        }
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
          }
      }
    {
      // the verification of every converged step (ForceBalance)
      double worst_imbalance = 0, worst_residual = 0, margin = std::numeric_limits<double>::infinity();
      for (const auto &sr : results.steps)
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
    json.set("contact.total_force_x", results.total_contact_force[0]);
    json.set("contact.total_force_y", results.total_contact_force[1]);
    json.set("contact.interfaces", double(results.interface_results.size()));
    json.set("contact.detected_interfaces", double(results.detection.interfaces.size()));
    for (unsigned int k = 0; k < results.interface_results.size(); ++k)
      {
        const auto       &r   = results.interface_results[k];
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
    for (const auto &s : d.timer.get_summary_data(dealii::TimerOutput::total_wall_time))
      json.set("timings." + s.first, s.second);
    json.write(prefix + ".json");
    std::cout << "  summary: " << prefix << ".json" << std::endl;
  }

} // namespace dealvem
