// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// Private to the library (not installed): what the source files of
// ContactProblem share, namely the state of one refinement cycle and a few
// small output helpers.
#ifndef dealvem_source_app_contact_problem_internal_h
#define dealvem_source_app_contact_problem_internal_h

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
#include <dealvem/contact/contact_solver.h>
#include <dealvem/contact/friction_solver.h>
#include <dealvem/contact/interface_tractions.h>
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
#include <dealvem/base/stage_timer.h>
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



  // The state of one cycle: everything built on the mesh of the cycle,
  // declared in the order it is built, so that it is destroyed in the
  // reverse order (the solvers before the assembler before the DoF
  // handler before the mesh, which lives in Results).
  struct ContactProblem::CycleData
  {
    /// The stages of the cycle, timed from the start of the cycle (the
    /// JSON's `timings`).
    StageTimer timer;
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
    /// The parts of the 'Rotation about centre' entries of the step.
    std::vector<BoundaryConditions::RotationAboutCentre<2>> rotation_parts;
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
    /// CG-AMG with the p-multigrid: the prolongation from k = 1 to k = 2
    /// on the polygons of all bodies, and the coarse rigid-body modes.
    dealii::SparsityPattern                               prolongation_sparsity;
    dealii::SparseMatrix<double>                          prolongation;
    std::vector<std::vector<double>>                      coarse_modes;
    /// The contact solver the settings ask for (ContactSolver::create()).
    std::unique_ptr<ContactSolver<2>>                     contact_solver;
    /// What the last load step's contact solve reported.
    ContactSolveResult                                    solve_result;
    std::unique_ptr<StressRecovery<2>>                    stresses;
    std::string                                           prefix;
  };

  namespace internal
  {
    namespace ContactProblemImplementation
    {
      // The interface results of one solve (or load step) as CSV.
      void
      write_interface_csv(const std::string &filename, const std::vector<ContactProblem::PairResult> &pairs);

      // The resultant of each interface, one line each.
      void
      write_resultants_csv(const std::string                                   &filename,
                           const std::vector<ContactProblem::InterfaceResult> &interfaces);

      // The reactions of the supports, one line per support and load step.
      void
      write_reactions_csv(const std::string &filename, const std::vector<ContactProblem::StepResult> &steps);

      // One line per support on @p out: its reaction and moment about
      // @p point (the first @p max ones, then their number).
      void
      print_reactions(const dealii::ConditionalOStream                &out,
                      const std::vector<SupportReactions::Reaction> &reactions,
                      const dealii::Point<2>                        &point,
                      const std::string                             &indent,
                      const unsigned int                             max = 12);

      // The number of nodes node insertion added on all interfaces.
      unsigned int
      inserted_nodes(const std::vector<NodeInsertion::Report> &reports);

      // The smallest and largest recovered pressure of the active pairs
      // (min > max when no pair is active).
      std::pair<double, double>
      pressure_range(const std::vector<ContactProblem::PairResult> &pairs);

      // The file name prefix of load step @p step.
      std::string
      step_prefix(const std::string &prefix, const unsigned int step);

      // A material name: letters, digits, '_', '-', '.' (not empty); @p where
      // names the setting in the error message.
      void
      check_material_name(const std::string &name, const std::string &where);
    } // namespace ContactProblemImplementation
  } // namespace internal
} // namespace dealvem

#endif
