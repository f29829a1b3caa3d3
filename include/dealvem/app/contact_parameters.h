// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_app_contact_parameters_h
#define dealvem_app_contact_parameters_h

#include <deal.II/base/point.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/contact_detection.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/finite_strain_solver.h>

#include <string>

namespace dealvem
{
  /**
   * The settings of a ContactProblem besides its bodies, contact pairs and
   * boundary conditions (ContactProblem::options()): the sections
   * "Discretization", "Contact", "Solver", "Load steps", "Output" and
   * "Finite strain" of the parameter file, which
   * ContactProblem::parse_parameters() reads into it
   * (source/app/contact_parameters.cc). A program that sets a problem up
   * in C++ sets these fields before ContactProblem::run(), which checks
   * them (ContactProblem::check_setup()).
   */
  struct ContactParameters
  {
    /// Order k of the virtual elements (1 or 2).
    unsigned int degree = 2;
    /// Stabilization rule of the element matrices (see
    /// ElasticityOperator).
    Stabilization stabilization = Stabilization::automatic;
    /// Factor $\gamma$ of the stabilization (dimensionless);
    /// ContactProblem::check_setup() throws unless $10^{-6}\le\gamma\le 10^6$.
    double stabilization_factor = 1.0;
    /// Normal and tangential model, penalty, friction coefficient of the
    /// pairs that give none, active-set limits. (The per-pair friction
    /// coefficients come from ContactProblem::add_contact_pair().)
    ContactSettings contact;
    /// Node insertion on every contact pair: merge fraction, search
    /// distance, coordinate precision, closing of discretisation gaps
    /// (section "Contact" of the parameter file).
    NodeInsertion::Settings insertion;
    /// Detect the contact interfaces between the bodies (ContactDetection,
    /// "Pairs = auto"), besides the pairs added by
    /// ContactProblem::add_contact_pair().
    bool detect_pairs = false;
    /// The tolerances of the detection.
    ContactDetection::Settings detection;
    /// A name of parameter 'Solver/Type' (SaddlePointSolver::parse_type()),
    /// or "automatic": the direct condensed solve up to
    /// InputParsing::contact_direct_solver_max_dofs, CG-AMG above.
    std::string solver = "automatic";
    /// Relative residual tolerance of an iterative solve,
    /// 0 < tolerance < 1 (a direct solve does not use it).
    double solver_tolerance = 1e-12;
    /// Iteration limit of an iterative solve (at least 1).
    unsigned int solver_max_iterations = 10000;
    /// CG-AMG: start each Krylov solve from the displacements of the
    /// previous one (active-set or Newton iteration, load step) instead
    /// of from zero.
    bool warm_start = true;
    /// Solver/Preconditioner: "automatic", "AMG" or "p-multigrid" (CG-AMG
    /// on the condensed contact stiffness; the p-multigrid for k = 2 unless
    /// "AMG").
    std::string solver_preconditioner = "automatic";
    /// Number of quasi-static load steps (at least 1): step k = 1, ...,
    /// n_load_steps solves at t = final_time * k / n_load_steps.
    unsigned int n_load_steps = 1;
    /// The time t of the last load step (> 0); the load and Dirichlet
    /// expressions are functions of t.
    double final_time = 1;
    /// Folder of the output files (relative to the working directory,
    /// not empty), created if needed.
    std::string output_folder = "output";
    /// Base name of the output files (not empty, no '/'): with several
    /// refinement cycles the files of cycle c are `base_name-cycle<c>.*`,
    /// with several load steps each step adds files `base_name-step-NNN.*`.
    std::string base_name = "contact";
    /// @var bool write_vtu
    /// Write the displacements and stresses for ParaView (.vtu; with
    /// several load steps one per step and a .pvd time series). With all
    /// four write_* false nothing is written (the results stay in
    /// ContactProblem::get_results()).
    /// @var bool write_json
    /// Write the JSON summary `base_name.json` (with several refinement
    /// cycles one per cycle, named as the other files).
    /// @var bool write_pictures
    /// Write SVG pictures of the deformed bodies (coloured by
    /// $\sigma_{yy}$, inserted nodes marked) and of the contact pressure.
    /// @var bool write_csv
    /// Write the results of the node pairs (ContactPairResult) as CSV
    /// (`base_name-interface.csv`; with several load steps also one per
    /// step).
    bool write_vtu = true, write_json = true, write_pictures = true, write_csv = true;
    /// The point the moments of the interface resultants
    /// (ContactInterfaceResult::moment) and of the support reactions
    /// (ContactStepResult::reactions) are taken about ('Output/Moment point'),
    /// counter-clockwise positive.
    dealii::Point<2> moment_point;
    /// Finite strain with finite sliding ('Finite strain/Enabled =
    /// true'): ContactProblem::run() solves the load steps with FiniteSliding
    /// (the bodies' hyperelastic laws, the pairs made again in the current
    /// configuration at every step, frictionless, Coulomb by multipliers
    /// or tied) instead of the small-strain contact solvers.
    bool finite_strain = false;
    /// Newton's controls of the finite-strain path ('Finite strain'
    /// section; the number of load steps is n_load_steps).
    FiniteStrainSolver<2>::Parameters newton;
    /// Finite sliding: how the pressures act ('Finite strain/Pressure
    /// load').
    PressureLoad pressure_load = PressureLoad::follower;
    /// Finite sliding: the pairing tolerance
    /// (FiniteSliding::Parameters::pairing_tolerance, 'Contact/Pairing
    /// tolerance').
    double pairing_tolerance = 1e-8;
    /// Finite sliding: the most pairing passes per step
    /// ('Contact/Maximum pairing passes').
    unsigned int max_pairing_passes = 12;
    /// Finite sliding: how often a failed step is cut into halves
    /// ('Contact/Maximum cutbacks', FiniteSliding::Parameters::max_cutbacks).
    unsigned int max_cutbacks = 4;
  };
} // namespace dealvem

#endif
