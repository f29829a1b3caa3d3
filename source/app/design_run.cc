// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/lac/affine_constraints.h>

#include <dealvem/app/design_parameters.h>
#include <dealvem/app/input_parsing.h>
#include <dealvem/app/problem_setup.h>
#include <dealvem/design/design_output.h>
#include <dealvem/design/design_problem.h>
#include <dealvem/elasticity/elasticity_assembler.h>

#include <cstdio>
#include <fstream>
#include <iomanip>

namespace dealvem
{
  void
  DesignParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    prm.enter_subsection("Design");
    prm.declare_entry("Objective", "none", Selection("none|compliance|interface force|largest pressure"),
                      "Topology optimization of the bodies instead of one analysis: minimize the compliance "
                      "(the work of the loads), the normal force of one contact interface, or its largest "
                      "contact pressure (a P-norm of the pair pressures), under a volume constraint. 'none': "
                      "analyse only.");
    prm.declare_entry("Interface", "0", Integer(0),
                      "The interface of 'Objective = interface force' or 'largest pressure' (in the order of "
                      "'Contact/Pairs', then the detected ones).");
    prm.declare_entry("Pressure norm exponent", "8", Double(1),
                      "The exponent P of 'Objective = largest pressure': (sum p_i^P)^(1/P) over the pairs.");
    prm.declare_entry("Constraint", "none", Selection("none|compliance|interface force|largest pressure"),
                      "A constraint besides the volume (MMA only): the compliance, the normal force of "
                      "'Constraint interface' or its largest pressure (the P-norm of 'Pressure norm exponent') "
                      "at most or at least 'Constraint bound'.");
    prm.declare_entry("Constraint interface", "0", Integer(0), "The interface of the force and pressure constraints.");
    prm.declare_entry("Constraint bound", "1", Double(0), "The bound of 'Constraint' (positive).");
    prm.declare_entry("Constraint sense", "at most", Selection("at most|at least"),
                      "Whether 'Constraint' is an upper or a lower bound.");
    prm.declare_entry("Volume fraction", "0.5", Double(0, 1), "The volume fraction of the designed cells.");
    prm.declare_entry("Filter radius", "0.1", Double(0),
                      "The radius of the density filter (length; PolyTop's linear filter over cell centroids). "
                      "About two to three cell sizes.");
    prm.declare_entry("Interpolation", "SIMP", Selection("SIMP|RAMP"), "The stiffness interpolation.");
    prm.declare_entry("Penalization", "3", Double(0), "The SIMP exponent p (>= 1) or the RAMP parameter q.");
    prm.declare_entry("Minimum stiffness", "1e-9", Double(0, 1),
                      "The stiffness factor of a void cell (relative to the body's law), in (0, 1).");
    prm.declare_entry("Optimizer", "MMA", Selection("MMA|OC"),
                      "MMA: NLopt's method of moving asymptotes. OC: optimality criteria (compliance).");
    prm.declare_entry("Iterations", "200", Integer(1), "The most design iterations (analyses).");
    prm.declare_entry("Tolerance", "0.01", Double(0, 1),
                      "Stop when no design variable changes by more than this between two iterations.");
    prm.declare_entry("Move limit", "0.2", Double(0, 1), "OC's move limit, MMA's first step.");
    prm.declare_entry("Projection", "false", Bool(), "Heaviside projection of the filtered densities.");
    prm.declare_entry("Projection sharpness", "1", Double(0), "The first sharpness beta of the projection.");
    prm.declare_entry("Maximum sharpness", "32", Double(0),
                      "beta is doubled every 'Projection interval' iterations up to this value.");
    prm.declare_entry("Projection interval", "40", Integer(1), "Iterations per sharpness.");
    prm.declare_entry("Projection threshold", "0.5", Double(0, 1), "The threshold eta of the projection.");
    prm.declare_entry("Initial density", "-1", Double(-1, 1),
                      "The starting density of the designed cells (negative: the volume fraction).");
    prm.declare_entry("Solid bodies", "", Anything(),
                      "Bodies (material ids) kept solid: a comma-separated list of indices.");
    prm.declare_entry("Void bodies", "", Anything(), "Bodies (material ids) kept void.");
    prm.declare_entry("Output interval", "10", Integer(0),
                      "Write the densities as VTU every this many iterations (0: the final design only).");
    prm.leave_subsection();
  }



  namespace
  {
    std::set<dealii::types::material_id>
    design_id_list(const std::string &text, const std::string &parameter)
    {
      std::set<dealii::types::material_id> ids;
      for (const auto &piece : InputParsing::split(text, ','))
        ids.insert(InputParsing::parse_unsigned(piece, parameter));
      return ids;
    }
  } // namespace



  void
  DesignParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Design");
    objective       = prm.get("Objective");
    interface       = prm.get_integer("Interface");
    pressure_exponent = prm.get_double("Pressure norm exponent");
    constraint           = prm.get("Constraint");
    constraint_interface = prm.get_integer("Constraint interface");
    constraint_bound     = prm.get_double("Constraint bound");
    constraint_at_least  = (prm.get("Constraint sense") == "at least");
    auto &s         = settings;
    s.volume_fraction = prm.get_double("Volume fraction");
    s.filter_radius   = prm.get_double("Filter radius");
    s.interpolation.type    = Design::MaterialInterpolation::parse(prm.get("Interpolation"));
    s.interpolation.penalty = prm.get_double("Penalization");
    s.interpolation.minimum = prm.get_double("Minimum stiffness");
    s.optimizer             = Design::parse_optimizer(prm.get("Optimizer"));
    s.max_iterations        = prm.get_integer("Iterations");
    s.tolerance             = prm.get_double("Tolerance");
    s.move                  = prm.get_double("Move limit");
    s.projection            = prm.get_bool("Projection");
    s.heaviside.beta        = prm.get_double("Projection sharpness");
    s.max_beta              = prm.get_double("Maximum sharpness");
    s.projection_interval   = prm.get_integer("Projection interval");
    s.heaviside.eta         = prm.get_double("Projection threshold");
    s.initial_density       = prm.get_double("Initial density");
    s.solid_ids             = design_id_list(prm.get("Solid bodies"), "Design/Solid bodies");
    s.void_ids              = design_id_list(prm.get("Void bodies"), "Design/Void bodies");
    output_interval         = prm.get_integer("Output interval");
    prm.leave_subsection();
    if (enabled())
      {
        settings.check();
        AssertThrow(constraint == "none" || constraint_bound > 0,
                    dealii::ExcMessage("Design/Constraint bound must be positive, got " +
                                       std::to_string(constraint_bound) + "."));
        AssertThrow(constraint == "none" || settings.optimizer == Design::TopologyOptimizer::Optimizer::mma,
                    dealii::ExcMessage("Design/Constraint = " + constraint +
                                       " needs Design/Optimizer = MMA (OC handles the volume constraint only)."));
      }
  }



  Design::TopologyOptimizer::Result
  run_design(const DesignParameters &parameters, const DesignInputs &inputs, std::ostream &out)
  {
    AssertThrow(inputs.mesh != nullptr && inputs.laws != nullptr && inputs.bc != nullptr,
                dealii::ExcMessage("run_design(): the mesh, the laws and the boundary conditions are needed."));
    for (const auto id : parameters.settings.solid_ids)
      AssertThrow(inputs.laws->has_law(id),
                  dealii::ExcMessage("Design/Solid bodies: there is no body " + std::to_string(id) + "."));
    for (const auto id : parameters.settings.void_ids)
      AssertThrow(inputs.laws->has_law(id),
                  dealii::ExcMessage("Design/Void bodies: there is no body " + std::to_string(id) + "."));
    AssertThrow(parameters.objective == "compliance" || parameters.interface < inputs.interfaces.size(),
                dealii::ExcMessage("Design/Interface = " + std::to_string(parameters.interface) + ", but the problem has " +
                                   std::to_string(inputs.interfaces.size()) + " contact interfaces."));
    AssertThrow(parameters.constraint == "none" || parameters.constraint == "compliance" ||
                  parameters.constraint_interface < inputs.interfaces.size(),
                dealii::ExcMessage("Design/Constraint interface = " + std::to_string(parameters.constraint_interface) +
                                   ", but the problem has " + std::to_string(inputs.interfaces.size()) +
                                   " contact interfaces."));

    Design::ElasticDesignProblem problem(*inputs.mesh, *inputs.laws, inputs.degree);
    problem.contact_settings()   = inputs.contact;
    problem.insertion_settings() = inputs.insertion;
    for (const auto &p : inputs.interfaces)
      problem.add_contact_interface(p.first, p.second);
    const BoundaryConditionParameters &bc = *inputs.bc;
    problem.add_boundary_conditions(
      [&bc](const VEMDoFHandler<2> &dofs, dealii::AffineConstraints<double> &c) { bc.apply_constraints(dofs, c); },
      [&bc](ElasticityAssembler<2> &assembler) { bc.add_loads(assembler); });
    if (parameters.objective == "interface force")
      problem.set_objective(Design::ElasticDesignProblem::Objective::interface_force, parameters.interface);
    else if (parameters.objective == "largest pressure")
      {
        problem.set_objective(Design::ElasticDesignProblem::Objective::max_pressure, parameters.interface);
      }
    problem.set_pressure_norm_exponent(parameters.pressure_exponent);
    if (parameters.constraint != "none")
      {
        using R = Design::ElasticDesignProblem::Response;
        const R response = parameters.constraint == "compliance"      ? R::compliance :
                           parameters.constraint == "interface force" ? R::interface_force :
                                                                        R::max_pressure;
        problem.add_constraint(response, parameters.constraint_bound,
                               parameters.constraint_at_least ? Design::ElasticDesignProblem::Bound::at_least :
                                                                Design::ElasticDesignProblem::Bound::at_most,
                               parameters.constraint_interface);
      }
    problem.setup();
    // the solver: 'automatic' follows the rule of the analyses, the
    // factorization of the condensed stiffness up to the size where CG-AMG
    // beats it (doc/benchmarks.md)
    auto &solver = problem.solver_settings();
    if (inputs.solver == "automatic")
      solver.type = problem.get_dof_handler().n_dofs() > InputParsing::contact_direct_solver_max_dofs ?
                      SaddlePointSolver::Type::cg_amg_constraints :
                      SaddlePointSolver::Type::direct_constraints;
    else
      solver.type = SaddlePointSolver::parse_type(inputs.solver);
    solver.relative_tolerance = inputs.solver_tolerance;

    unsigned int n_design = 0;
    for (unsigned int c = 0; c < problem.get_mesh().n_cells(); ++c)
      {
        const auto id = problem.get_mesh().cell(c).material_id;
        n_design += !parameters.settings.solid_ids.count(id) && !parameters.settings.void_ids.count(id);
      }
    out << "Design: " << problem.objective_name() << ", " << n_design << " designed cells of "
        << problem.get_mesh().n_cells() << ", " << problem.get_dof_handler().n_dofs() << " DoFs, "
        << inputs.interfaces.size() << " contact interfaces, "
        << (parameters.settings.optimizer == Design::TopologyOptimizer::Optimizer::mma ? "MMA" : "OC")
        << ", volume fraction " << parameters.settings.volume_fraction << ", filter radius "
        << parameters.settings.filter_radius
        << (problem.n_constraints() > 0 ? ", constraint " + problem.constraint_name(0) : std::string()) << std::endl;

    Design::TopologyOptimizer optimizer(parameters.settings);
    const PolygonalMesh<2>   &mesh = problem.get_mesh();
    optimizer.set_callback([&](const unsigned int it, const Design::TopologyOptimizer::Iteration &record,
                               const std::vector<double> &density) {
      if (parameters.output_interval > 0 && (it - 1) % parameters.output_interval == 0)
        {
          out << "  iteration " << std::setw(4) << it << ": objective " << std::setprecision(8) << record.objective
              << ", volume " << std::setprecision(6) << record.volume << ", change " << record.change;
          if (!record.constraints.empty())
            out << ", constraint " << record.constraints[0];
          out << std::endl;
          if (inputs.write_vtu)
            {
              char name[32];
              std::snprintf(name, sizeof(name), "-design-%04u.vtu", it);
              Design::write_density_vtu(inputs.prefix + name, mesh, density);
            }
        }
    });
    const auto result = optimizer.run(problem);
    out << "  " << result.history.size() << " iterations (" << result.stop_reason << "): objective "
        << std::setprecision(8) << result.objective << ", volume " << std::setprecision(6) << result.volume << ", "
        << std::setprecision(3) << result.time << " s (" << result.analysis_time << " s in the analyses)"
        << std::setprecision(6) << std::endl;
    if (problem.n_constraints() > 0)
      out << "  constraint " << problem.constraint_name(0) << ": response "
          << std::setprecision(8) << problem.last_state().constraint_responses[0] << " ("
          << (result.constraints[0] <= 1e-6 ? "satisfied" : "violated by " + std::to_string(result.constraints[0]))
          << ")" << std::setprecision(6) << std::endl;
    if (inputs.write_vtu)
      Design::write_density_vtu(inputs.prefix + "-design-final.vtu", mesh, result.densities);
    if (inputs.write_pictures)
      Design::write_density_svg(inputs.prefix + "-design.svg", mesh, result.densities,
                                "dealvem design: " + problem.objective_name() + " " +
                                  std::to_string(result.objective));
    if (inputs.write_csv)
      {
        std::ofstream csv(inputs.prefix + "-design.csv");
        AssertThrow(csv, dealii::ExcMessage("Cannot write '" + inputs.prefix + "-design.csv'."));
        csv << "iteration,objective,volume,change,beta,grey" << (problem.n_constraints() > 0 ? ",constraint" : "")
            << "\n"
            << std::setprecision(12);
        for (unsigned int i = 0; i < result.history.size(); ++i)
          {
            const auto &r = result.history[i];
            csv << i + 1 << "," << r.objective << "," << r.volume << "," << r.change << "," << r.beta << ","
                << r.grey;
            if (!r.constraints.empty())
              csv << "," << r.constraints[0];
            csv << "\n";
          }
      }
    // an infeasible design is not an answer: the outputs are written for
    // inspection, and the run fails naming the constraint
    AssertThrow(result.feasible,
                dealii::ExcMessage("Design: the optimization ended with an infeasible design (" + result.stop_reason +
                                   "). The bound may be out of reach from this start (a force or pressure "
                                   "constraint has no gradient while its interface is open); relax it, or "
                                   "change the start ('Initial density') or 'Iterations'." +
                                   (inputs.write_vtu ? " The last design is in " + inputs.prefix +
                                                         "-design-final.vtu." :
                                                       std::string())));
    return result;
  }
} // namespace dealvem
