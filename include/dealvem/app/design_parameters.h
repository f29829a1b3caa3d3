// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_app_design_parameters_h
#define dealvem_app_design_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/design/topology_optimizer.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/mesh/polygonal_mesh.h>

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace dealvem
{
  class BoundaryConditionParameters;

  /**
   * The section 'Design' of the parameter programs: topology optimization
   * of the bodies the file defines (one body through ElasticityProblem,
   * several in contact through ContactProblem) instead of one analysis.
   * With 'Objective = none' (the default) the section is ignored.
   *
   * The analysis of every design is the problem of the file at 'Final time'
   * (one load step): its Dirichlet data must be zero (the compliance of a
   * prescribed displacement is not the work of the loads), its loads are
   * those of 'Boundary conditions and loads', its contact model that of
   * 'Contact' (tied, or unilateral frictionless or with stick; Coulomb
   * friction is refused). Every cell of a body whose index (its material
   * id) is not in 'Solid bodies' or 'Void bodies' is designed.
   *
   * Outputs under the output prefix: "<prefix>-design-NNNN.vtu" every
   * 'Output interval' iterations and for the final design (cell fields
   * "density" and "material_id"), "<prefix>-design.svg" (the final
   * densities), "<prefix>-design.csv" (objective, volume, change, sharpness
   * and grey fraction per iteration, and the constraint g <= 0 when there
   * is one).
   */
  struct DesignParameters
  {
    /// 'Objective': "none", "compliance", "interface force" or "largest
    /// pressure".
    std::string objective = "none";
    /// 'Interface': the contact interface of the force and pressure
    /// objectives (in the order of 'Contact/Pairs', then the detected ones).
    unsigned int interface = 0;
    /// 'Pressure norm exponent': P of the largest-pressure objective and
    /// constraint.
    double pressure_exponent = 8;
    /// 'Constraint': "none", "compliance", "interface force" or "largest
    /// pressure" (ElasticDesignProblem::add_constraint()).
    std::string constraint = "none";
    /// 'Constraint interface'.
    unsigned int constraint_interface = 0;
    /// 'Constraint bound' (> 0).
    double constraint_bound = 1;
    /// 'Constraint sense' = "at least" (otherwise "at most").
    bool constraint_at_least = false;
    /// The optimizer's settings (volume, filter, interpolation, ...).
    Design::TopologyOptimizer::Settings settings;
    /// 'Output interval': a VTU file every this many iterations (0: the
    /// final design only).
    unsigned int output_interval = 10;

    /// Declare the section 'Design'.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Read it; throws, naming the entry, on values out of range.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Whether the section asks for a design ('Objective' is not "none").
    bool
    enabled() const
    {
      return objective != "none";
    }
  };

  /// What a parameter program hands to run_design(): its bodies and their
  /// data, as it would analyse them.
  struct DesignInputs
  {
    /// The bodies (material id = body), before node insertion.
    const PolygonalMesh<2> *mesh = nullptr;
    /// Their laws by material id.
    const MaterialLibrary<2> *laws = nullptr;
    /// The order k.
    unsigned int degree = 2;
    /// The contact interfaces (master id, slave id), maybe none.
    std::vector<std::pair<dealii::types::boundary_id, dealii::types::boundary_id>> interfaces;
    /// The contact model.
    ContactSettings contact;
    /// The node insertion settings.
    NodeInsertion::Settings insertion;
    /// The supports and loads (at the time they were set to).
    const BoundaryConditionParameters *bc = nullptr;
    /// 'Solver/Type' ("automatic", "direct constraints", "CG-AMG", ...).
    std::string solver = "automatic";
    /// 'Solver/Tolerance'.
    double solver_tolerance = 1e-12;
    /// The output prefix "<folder>/<base>".
    std::string prefix;
    /// Write the VTU files of the densities.
    bool write_vtu = true;
    /// Write the SVG picture of the final design.
    bool write_pictures = true;
    /// Write the CSV history.
    bool write_csv = true;
  };

  /// Run the optimization of @p parameters on @p inputs, printing a line
  /// every 'Output interval' iterations and a summary to @p out.
  Design::TopologyOptimizer::Result
  run_design(const DesignParameters &parameters, const DesignInputs &inputs, std::ostream &out);
} // namespace dealvem

#endif
