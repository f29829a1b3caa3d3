// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_app_contact_results_h
#define dealvem_app_contact_results_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <dealvem/contact/contact_detection.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/elasticity/support_reactions.h>
#include <dealvem/mesh/polygonal_mesh.h>
#include <dealvem/postprocessing/error_norms.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace dealvem
{
  /// ContactResults of one contact node pair.
  struct ContactPairResult
  {
    /// Index of the contact pair (interface) of the node pair, in the
    /// order of ContactProblem::add_contact_pair().
    unsigned int interface;
    /// Position of the slave node in the undeformed mesh (after node
    /// insertion).
    dealii::Point<2> location;
    /// True for a pair of edge midpoints (k = 2), false for a pair of
    /// vertices.
    bool midpoint;
    /// Whether the pair is closed (in contact) in the converged solution.
    bool active;
    /// Tributary length $w$ of the node on the interface
    /// (ContactNodePair::weight); forces divided by it are tractions.
    double weight;
    /// Gap $g = (u_B - u_A)\cdot n + g_0$ of the converged solution
    /// (length units; positive: open, negative: penetration).
    double gap;
    /// Recovered contact pressure, compression > 0: ContactPressure::recover()
    /// applied to the nodal forces -lambda of the interface, i.e. at this
    /// pair the value of the polynomial of degree k fitted in the
    /// least-squares sense to the nodal forces of the closed pairs within
    /// three sub-edges on each side (a patch fit, not the consistent solve
    /// M_Gamma p = -lambda of ContactPressure::consistent()); zero when open.
    double pressure;
    double lumped_pressure;     ///< -lambda / weight
    double multiplier;          ///< raw multiplier lambda (a nodal force)
    bool   at_open_end;         ///< see ContactNodePair::at_open_end
    double tangential_traction; ///< tangential force / weight
    double slip;                ///< relative tangential displacement (u_B - u_A).t
    /// "open", "stick" or "slip" with Coulomb friction; "open" or
    /// "closed" with the frictionless and stick models.
    std::string status;
    /// Coulomb friction: the slip of this load step (with the penalty
    /// variant, the increment of the plastic slip); zero for open pairs
    /// and without friction.
    double slip_increment = 0;
    /// Tangent t of the pair (tangential traction and slip are along it).
    dealii::Tensor<1, 2> tangent;
    /// Tangential traction recovered as the pressure (ContactPressure::recover
    /// applied to the tangential nodal forces); tangential_traction is the
    /// raw force per tributary length.
    double shear = 0;
    /// Normal n of the pair (the force $-\lambda$ on the slave node acts
    /// along it; tangent = (-n_y, n_x)).
    dealii::Tensor<1, 2> normal;
  };

  /**
   * The resultant of one interface in a load step, from the nodal
   * contact forces of its pairs: the force on the slave body (normal
   * part: compression > 0; tangential part along the pairs' tangents),
   * the centre of pressure (the normal forces' centre on the interface),
   * and the pair states.
   */
  struct ContactInterfaceResult
  {
    unsigned int               master_body = 0; ///< body index of the master side
    unsigned int               slave_body  = 0; ///< body index of the slave side
    dealii::types::boundary_id master_id   = 0; ///< boundary id of the master side
    dealii::types::boundary_id slave_id    = 0; ///< boundary id of the slave side
    /// Length of the paired interface (sum of its segments on the slave side).
    double length = 0;
    /// Sum of the normal nodal forces (compression > 0).
    double normal_force = 0;
    /// Sum of the tangential nodal forces (along each pair's tangent).
    double tangential_force = 0;
    /// Resultant force vector on the slave body.
    dealii::Tensor<1, 2> force;
    /// Moment of the nodal forces on the slave body about
    /// ContactParameters::moment_point, $\sum_i (x_i - x_0)\times f_i$ with the
    /// slave node's position $x_i$ (counter-clockwise positive).
    double moment = 0;
    /// Centre of the normal forces (the midpoint of the interface when
    /// nothing is transmitted).
    dealii::Point<2> centre_of_pressure;
    /// Pairs open.
    unsigned int n_open = 0;
    /// Pairs closed and sticking (without Coulomb friction: every closed
    /// pair).
    unsigned int n_stick = 0;
    /// Pairs closed and slipping (Coulomb friction).
    unsigned int n_slip = 0;
    /// Whether ContactDetection found the interface ("Pairs = auto").
    bool detected = false;
    /// The Coulomb friction coefficient of the interface (its pair's own,
    /// else by bodies, else by materials, else the common one; 0 without
    /// Coulomb friction).
    double friction_coefficient = 0;
  };

  /// One converged load step.
  struct ContactStepResult
  {
    /// Number of the load step, 1 to ContactParameters::n_load_steps.
    unsigned int step;
    /// Its time, t = final_time * step / n_load_steps.
    double time;
    /// Newton (active-set) iterations of the step.
    unsigned int iterations;
    /// Coulomb friction: Tresca problems of the fixed point that solved
    /// the step after the semismooth Newton iteration failed (0: not
    /// needed; FrictionSolver::Result::n_fixed_point_iterations).
    unsigned int fixed_point_iterations = 0;
    /// Coulomb friction: factors of the friction continuation passed (0:
    /// none; FrictionSolver::Result::continuation_factors).
    unsigned int continuation_factors = 0;
    /// @var unsigned int n_open
    /// Pairs open at the end of the step.
    /// @var unsigned int n_stick
    /// Pairs closed and not slipping (sticking, or closed without
    /// Coulomb friction).
    /// @var unsigned int n_slip
    /// Pairs slipping (Coulomb friction).
    unsigned int n_open = 0, n_stick = 0, n_slip = 0;
    /// Energy dissipated by friction in the step (zero without friction).
    double dissipated_energy = 0;
    /// Resultant of the contact forces (normal and tangential) on the
    /// slave bodies at the end of the step (force units).
    dealii::Tensor<1, 2> total_contact_force;
    /// The result of every node pair at the end of the step.
    std::vector<ContactPairResult> pairs;
    /// The resultant of each interface (index: the interface).
    std::vector<ContactInterfaceResult> interfaces;
    /// The verification of the step per body (ForceBalance): relative
    /// imbalance of force and moment, relative residual, their tolerance
    /// and the condition of the balance.
    struct Balance
    {
      /// Index of the body (its material id).
      unsigned int body;
      /// @var double imbalance
      /// Relative force and moment imbalance (ForceBalance::Body::imbalance).
      /// @var double residual
      /// Relative residual of the equations (ForceBalance::Body::residual).
      /// @var double tolerance
      /// The tolerance both must meet (ForceBalance::Body::tolerance).
      /// @var double condition
      /// Measured condition of the balance (ForceBalance::Body::condition).
      double imbalance, residual, tolerance, condition;
    };
    /// One entry per body.
    std::vector<Balance> balance;
    /// The reaction (force and moment about ContactParameters::moment_point) of
    /// every support: each boundary id with Dirichlet data or a roller,
    /// each point constraint (SupportReactions).
    std::vector<SupportReactions::Reaction> reactions;
    /// Each 'Rotation about centre' part: its centre, angle (prescribed or
    /// solved for), torque and moment about the centre
    /// (SupportReactions::rotation()).
    std::vector<SupportReactions::Rotation> rotations;
  };

  /// Everything a test or a user program wants to look at after
  /// ContactProblem::run() (ContactProblem::get_results()): the results of
  /// the last refinement cycle, per node pair, per interface, per load step
  /// and per body.
  struct ContactResults
  {
    /// The mesh of all bodies after node insertion (material id = body
    /// index), of the last refinement cycle.
    PolygonalMesh<2> mesh;
    /// The node pairs at the end of the last load step.
    std::vector<ContactPairResult> pairs;
    /// What node insertion did, one report per contact pair.
    std::vector<NodeInsertion::Report> insertion_reports;
    /// The matched interfaces (pairs and segments) of node insertion.
    std::vector<NodeInsertion::Interface> interfaces;
    /// The interfaces ContactDetection found ("Pairs = auto"), after the
    /// explicit ones in the numbering of the interfaces.
    ContactDetection::Result detection;
    /// The resultant of each interface in the last load step.
    std::vector<ContactInterfaceResult> interface_results;
    /// Number of active pairs at an open end (each printed as a warning).
    unsigned int n_open_end_warnings = 0;
    /// Contact constraints already imposed by the displacement constraints
    /// (see ContactAssembler::get_dropped_constraints()).
    unsigned int n_dropped_constraints = 0;
    /// Pairs that close a triangle of pairs where three bodies meet
    /// (NodeInsertion::mark_junctions()); unilateral and Coulomb contact
    /// keep them open.
    unsigned int n_junction_pairs = 0;
    /// @var unsigned int n_dofs
    /// Number of displacement DoFs (the size of solution).
    /// @var unsigned int n_multipliers
    /// Number of contact multipliers (normal, and tangential ones with
    /// multiplier-based tangential models); the saddle-point system has
    /// n_dofs + n_multipliers unknowns.
    unsigned int n_dofs = 0, n_multipliers = 0;
    /// Active-set (Newton) iterations of the last load step.
    unsigned int active_set_iterations = 0;
    /// Per iteration of the last load step, the number of active pairs.
    std::vector<unsigned int> active_set_history;
    /// Iterations of the linear solver summed over the last load step
    /// (1 per direct solve).
    unsigned int         linear_iterations = 0;
    dealii::Tensor<1, 2> total_contact_force; ///< on the slave bodies
    /// Per body, the resultant (x, y) of the assembled loads (body force,
    /// tractions, pressures, nodal loads) of the last load step; neither
    /// reactions nor contact forces.
    std::vector<dealii::Tensor<1, 2>> applied_load_per_body;
    /// The stick penalty of the contact assembler (ContactScales::penalty(),
    /// units of E/h); only the penalty tangential models (penalty,
    /// coulomb_penalty) use it.
    double penalty = 0;
    /// Cell-average stresses (xx, yy, xy) per cell.
    std::vector<std::array<double, 3>> cell_stress;
    /// Displacements of the last load step (n_dofs entries, constraints
    /// distributed).
    dealii::Vector<double> solution;
    /// One line on the saddle-point solver and its last solve
    /// (SaddlePointSolver::description()).
    std::string solver;
    /// @var std::vector<unsigned int> cells_per_body
    /// Per body, the number of cells.
    /// @var std::vector<unsigned int> dofs_per_body
    /// Per body, the number of DoFs (two per node of its cells).
    std::vector<unsigned int> cells_per_body, dofs_per_body;
    /// Per body, the errors against its exact solution (zero where none
    /// is given).
    std::vector<ErrorNorms> errors;
    /// Wall times of the stages (mesh, node insertion, assembly, solve).
    std::map<std::string, double> timings;
    /// The converged load steps (one for a static problem); pairs, solution
    /// and stresses above are those of the last one.
    std::vector<ContactStepResult> steps;
    /// Sum of the dissipated energy of the steps.
    double dissipated_energy = 0;
    /// @var unsigned int n_processes
    /// MPI processes of the run.
    /// @var unsigned int n_rows_across_processes
    /// Contact constraint rows of the last solve whose DoFs are owned by
    /// more than one process (0 on the serial path).
    unsigned int n_processes = 1, n_rows_across_processes = 0;
    /// Peak resident memory (VmHWM) of each process at the end of the
    /// cycle, in MB.
    std::vector<double> peak_memory_MB;
  };
} // namespace dealvem

#endif
