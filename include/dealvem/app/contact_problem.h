// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_app_contact_problem_h
#define dealvem_app_contact_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <dealvem/app/elasticity_problem.h>
#include <dealvem/app/mesh_parameters.h>
#include <dealvem/app/problem_setup.h>
#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/contact_detection.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/contact/primal_active_set.h>
#include <dealvem/elasticity/constitutive_law.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/elasticity/support_reactions.h>
#include <dealvem/mesh/polygonal_mesh.h>
#include <dealvem/postprocessing/error_norms.h>

#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace dealvem
{
  /**
   * The multi-body contact problem behind `dealvem input.prm` when the
   * parameter file has more than one body.
   *
   * Body 0 is described by the top-level sections "Mesh" and "Material"
   * (as for one body), bodies 1, 2, ... by the sections "Body 1", ... each
   * with its own "Mesh" and "Material" subsections (any number: the program
   * declares as many sections as the file uses, see body_sections()). A
   * mesh section with "Parts as bodies = true" reads an assembly from one
   * file: each material id (gmsh physical surface) is a body, with its
   * material from "Material/Part materials". Every body gets its index as
   * material id; the "Boundary id offset" of a body's mesh keeps the
   * boundary ids of the bodies apart. The section "Contact" lists the
   * contact pairs "master id : slave id; ..." (with Coulomb friction
   * optionally "master id : slave id : friction coefficient"), or "auto"
   * for the interfaces ContactDetection finds (both may be mixed), and the
   * contact options. The section "Load steps" runs the problem as a
   * sequence of quasi-static steps in the time t of the load expressions;
   * Coulomb friction (FrictionSolver) carries the pair states and slips
   * from step to step.
   *
   * Data flow of run(): meshes of the bodies -> one mesh -> node insertion
   * on each contact pair -> DoFs -> constraints -> assembly of K and f ->
   * contact blocks -> active-set loop of saddle-point solves -> stresses,
   * contact pressures -> VTU, CSV, JSON, SVG pictures.
   *
   * <h3>MPI</h3>
   * With more than one process in the communicator (`mpirun -np N
   * dealvem contact.prm`), every process builds the whole mesh, the node
   * pairs and the contact blocks (replicated, as ElasticityProblem's
   * distributed path), the cells are partitioned by METIS (VEMPartition),
   * and each active-set iteration is solved by DistributedContactSolver:
   * the active constraints become AffineConstraints lines, the condensed
   * stiffness of each process's cells goes into a Trilinos matrix, and CG +
   * ML AMG (or Amesos KLU for UMFPACK/KLU) solves it. The displacements and
   * multipliers are then known on every process, so the stresses and
   * pressures are computed as in the serial path and process 0 alone prints
   * and writes the files.
   *
   * <h3>In code</h3>
   * The parameter file is one client of a C++ interface that any program
   * can use instead: add_body() takes a PolygonalMesh or a deal.II
   * Triangulation and an ElasticMaterial, add_contact_pair() names the
   * boundary parts in contact, boundary_conditions() takes
   * dealii::Function objects, options() holds the discretization, contact,
   * node insertion, solver, load step and output settings; run() checks the
   * whole set-up (check_setup()) and solves. For example:
   * @code
   * ContactProblem problem;
   * problem.add_body(block_mesh, ElasticMaterial(210000, 0.3));  // body 0
   * problem.add_body(punch_tria, ElasticMaterial(70000, 0.3));   // body 1
   * problem.add_contact_pair(3, 12);                               // master : slave
   * problem.boundary_conditions().add_dirichlet(
   *   2, {{true, true}}, std::make_shared<dealii::Functions::ZeroFunction<2>>(2));
   * problem.boundary_conditions().add_pressure(
   *   13, std::make_shared<dealii::Functions::ConstantFunction<2>>(10.));
   * problem.options().contact.tangential = ContactSettings::Tangential::frictionless;
   * problem.run();
   * const auto &r = problem.get_results();
   * @endcode
   * The bodies' boundary ids must be distinct across bodies (shift them
   * before adding a mesh; the parameter file's "Boundary id offset" does
   * this). Examples step-3 and step-4 set up their problems this way.
   */
  class ContactProblem
  {
  public:
    /// The number of body sections ("Body 0" is the top level, then
    /// "Body 1" to "Body 3") declare_parameters() declares by default.
    static constexpr unsigned int default_body_sections = 4;

    /// The largest number of bodies (add_body(), add_parts()).
    static constexpr unsigned int max_bodies = 100000;

    /// The largest number of body sections of a parameter file (more
    /// bodies come from one mesh file with 'Parts as bodies').
    static constexpr unsigned int max_body_sections = 500;

    /// Everything but the bodies, the contact pairs and the boundary
    /// conditions: the settings of sections "Discretization", "Contact",
    /// "Solver", "Load steps" and "Output" of the parameter file.
    struct Options
    {
      /// Order k of the virtual elements (1 or 2).
      unsigned int  degree               = 2;
      /// Stabilization rule of the element matrices (see
      /// ElasticityOperator).
      Stabilization stabilization        = Stabilization::automatic;
      /// Factor $\gamma$ of the stabilization (dimensionless);
      /// check_setup() throws unless $10^{-6}\le\gamma\le 10^6$.
      double        stabilization_factor = 1.0;
      /// Normal and tangential model, penalty, friction coefficient of the
      /// pairs that give none, active-set limits. (The per-pair friction
      /// coefficients come from add_contact_pair().)
      ContactSettings         contact;
      /// Node insertion on every contact pair: merge fraction, search
      /// distance, coordinate precision, closing of discretisation gaps
      /// (section "Contact" of the parameter file).
      NodeInsertion::Settings insertion;
      /// Detect the contact interfaces between the bodies (ContactDetection,
      /// "Pairs = auto"), besides the pairs added by add_contact_pair().
      bool                        detect_pairs = false;
      /// The tolerances of the detection.
      ContactDetection::Settings detection;
      /// A name of parameter 'Solver/Type' (SaddlePointSolver::parse_type()),
      /// or "automatic": the direct condensed solve up to
      /// InputParsing::contact_direct_solver_max_dofs, CG-AMG above.
      std::string  solver                = "automatic";
      /// Relative residual tolerance of an iterative solve,
      /// 0 < tolerance < 1 (a direct solve does not use it).
      double       solver_tolerance      = 1e-12;
      /// Iteration limit of an iterative solve (at least 1).
      unsigned int solver_max_iterations = 10000;
      /// CG-AMG: start each Krylov solve from the displacements of the
      /// previous one (active-set or Newton iteration, load step) instead
      /// of from zero.
      bool         warm_start            = true;
      /// Number of quasi-static load steps (at least 1): step k = 1, ...,
      /// n_load_steps solves at t = final_time * k / n_load_steps.
      unsigned int n_load_steps = 1;
      /// The time t of the last load step (> 0); the load and Dirichlet
      /// expressions are functions of t.
      double       final_time   = 1;
      /// Folder of the output files (relative to the working directory,
      /// not empty), created if needed.
      std::string output_folder = "output";
      /// Base name of the output files (not empty, no '/'): with several
      /// refinement cycles the files of cycle c are `base_name-cycle<c>.*`,
      /// with several load steps each step adds files `base_name-step-NNN.*`.
      std::string base_name     = "contact";
      /// @var bool write_vtu
      /// Write the displacements and stresses for ParaView (.vtu; with
      /// several load steps one per step and a .pvd time series). With all
      /// four write_* false nothing is written (the results stay in
      /// get_results()).
      /// @var bool write_json
      /// Write the JSON summary `base_name.json` (with several refinement
      /// cycles one per cycle, named as the other files).
      /// @var bool write_pictures
      /// Write SVG pictures of the deformed bodies (coloured by
      /// $\sigma_{yy}$, inserted nodes marked) and of the contact pressure.
      /// @var bool write_csv
      /// Write the results of the node pairs (PairResult) as CSV
      /// (`base_name-interface.csv`; with several load steps also one per
      /// step).
      bool        write_vtu = true, write_json = true, write_pictures = true, write_csv = true;
      /// The point the moments of the interface resultants
      /// (InterfaceResult::moment) and of the support reactions
      /// (StepResult::reactions) are taken about ('Output/Moment point'),
      /// counter-clockwise positive.
      dealii::Point<2> moment_point;
      /// Finite strain with finite sliding ('Finite strain/Enabled =
      /// true'): run() solves the load steps with FiniteSliding (the bodies'
      /// hyperelastic laws, the pairs made again in the current
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
      double       pairing_tolerance  = 1e-8;
      /// Finite sliding: the most pairing passes per step
      /// ('Contact/Maximum pairing passes').
      unsigned int max_pairing_passes = 12;
      /// Finite sliding: how often a failed step is cut into halves
      /// ('Contact/Maximum cutbacks', FiniteSliding::Parameters::max_cutbacks).
      unsigned int max_cutbacks = 4;
    };

    /// The distributed path runs when @p comm has more than one process
    /// (Parallelism::automatic), or always (distributed), or never (serial).
    explicit ContactProblem(const MPI_Comm                       comm        = MPI_COMM_WORLD,
                            const ElasticityProblem::Parallelism parallelism = ElasticityProblem::Parallelism::automatic);
    ~ContactProblem();

    /// Declare the sections of the extra bodies ("Body 1" to "Body
    /// n_body_sections - 1") and of contact (the common sections come from
    /// ElasticityProblem::declare_parameters()).
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const unsigned int        n_body_sections = default_body_sections);

    /**
     * The number of body sections the parameter file @p filename (and the
     * files it includes) needs: one more than the largest b of a
     * "subsection Body b", at least 'Number of bodies' and at least
     * default_body_sections. Call it before declare_parameters() to read a
     * file with any number of bodies (up to max_body_sections: more is an
     * error naming the file). It also checks that every body b >= 1 of
     * 'Number of bodies' has its section 'Body b' at the top level, and
     * only one (a section given twice, or missing, would leave a body
     * described by the defaults): an error names the file, the section
     * and the lines.
     */
    static unsigned int
    body_sections(const std::string &filename);

    /// Number of body sections ('Number of bodies') in a parsed parameter
    /// handler.
    static unsigned int
    n_bodies(dealii::ParameterHandler &prm);

    /// Whether a parsed parameter handler describes a contact problem:
    /// more than one body section, or a mesh read with 'Parts as bodies'.
    static bool
    is_contact_problem(dealii::ParameterHandler &prm);

    /// Set the problem up from a parameter file: bodies, pairs,
    /// conditions and options (replacing anything set before).
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &prm_directory = "");

    /// @name Setting the problem up in code
    /// @{

    /**
     * Add a body meshed by @p mesh, of the material @p material (any linear
     * ConstitutiveLaw: an ElasticMaterial, or a law of your own; it is
     * copied with clone()); returns its index, which becomes the material
     * id of its cells. The mesh is copied, its boundary ids raised by
     * @p boundary_id_offset (the ids must differ from body to body).
     * ElasticMaterial bodies must share the model (plane strain or plane
     * stress). Up to max_bodies bodies.
     */
    unsigned int
    add_body(const PolygonalMesh<2>      &mesh,
             const ConstitutiveLaw<2>    &material,
             const unsigned int           boundary_id_offset = 0);

    /// The same for the active cells of a deal.II triangulation (converted
    /// by PolygonalMeshGenerators::from_triangulation()).
    unsigned int
    add_body(const dealii::Triangulation<2, 2> &tria,
             const ConstitutiveLaw<2>          &material,
             const unsigned int                 boundary_id_offset = 0);

    /**
     * Add every material id of @p mesh (an assembly: a part per id) as a
     * body, in increasing order of the ids, of the material @p part_laws
     * gives for its id or else @p material; returns the body indices (the
     * i-th for the i-th id). The parts keep the mesh's boundary ids (plus
     * @p boundary_id_offset). Splitting costs time linear in the mesh.
     */
    std::vector<unsigned int>
    add_parts(const PolygonalMesh<2>                                                         &mesh,
              const ConstitutiveLaw<2>                                                       &material,
              const std::map<dealii::types::material_id, std::shared_ptr<const ConstitutiveLaw<2>>> &part_laws = {},
              const unsigned int boundary_id_offset = 0);

    /**
     * The Coulomb friction coefficient of the interfaces between bodies
     * @p body_a and @p body_b (either order; numbers::invalid_unsigned_int
     * for "any body"). It applies to detected interfaces and to pairs added
     * without a coefficient of their own; a later call overrides an
     * earlier one for the same bodies, a pair of bodies beats a wildcard.
     */
    void
    set_friction_coefficient(const unsigned int body_a, const unsigned int body_b, const double mu);

    /**
     * Give body @p body the material name @p name (letters, digits, '_',
     * '-', '.'), used only to look up friction coefficients by pairs of
     * materials (the parameter 'Material/Name', or the fourth field of
     * 'Material/Part materials'). Several bodies may share a name. Bodies
     * without a name match only the wildcard "*".
     */
    void
    set_material_name(const unsigned int body, const std::string &name);

    /**
     * The Coulomb friction coefficient of the interfaces between bodies of
     * the materials @p material_a and @p material_b (names given by
     * set_material_name(), either order; "*" for any material). It applies
     * where no coefficient between the two bodies is given (a pair's own
     * coefficient beats set_friction_coefficient() by bodies, which beats
     * this); among these entries a pair of names beats a wildcard and a
     * later call an earlier one. run() stops with an error naming the
     * material if no body has it.
     */
    void
    set_friction_coefficient(const std::string &material_a, const std::string &material_b, const double mu);

    /// Number of bodies added (or read from the parameter file).
    unsigned int
    n_bodies() const
    {
      return bodies.size();
    }

    /**
     * Declare the boundary parts @p master and @p slave (of two different
     * bodies) an interface, with its own Coulomb friction coefficient
     * @p friction_coefficient (negative: options().contact's). Pairs are
     * numbered in the order they are added (the interface index of the
     * results). @p name names the pair in error messages.
     */
    void
    add_contact_pair(const dealii::types::boundary_id master,
                     const dealii::types::boundary_id slave,
                     const double                     friction_coefficient = -1,
                     const std::string               &name                 = "");

    /// Detect the contact interfaces between the bodies when run() meshes
    /// them (the same as options().detect_pairs = true).
    void
    detect_contact_pairs(const ContactDetection::Settings &settings = ContactDetection::Settings())
    {
      opt.detect_pairs = true;
      opt.detection    = settings;
    }

    /// The boundary conditions and loads (add to them in code).
    BoundaryConditionParameters &
    boundary_conditions()
    {
      return bc;
    }

    /// The settings (change them in code before run()).
    Options &
    options()
    {
      return opt;
    }

    /// The settings, read-only.
    const Options &
    options() const
    {
      return opt;
    }

    /**
     * Check the set-up as a whole and stop with a message naming the
     * setting (its parameter name) at the first error: at least one body,
     * a contact pair when there are several, consistent friction settings,
     * values in range. run() calls it; parse_parameters() too.
     */
    void
    check_setup() const;

    /// Remove the bodies, pairs and conditions (the options stay).
    void
    clear();

    /// @}

    /// Solve (every refinement cycle of the convergence study; results()
    /// then holds the last cycle, convergence_history() the errors of all).
    void
    run();

    /// One cycle: meshes refined @p cycle times; make_meshes(), insert_nodes(),
    /// setup_system(), then per load step assemble_system(), solve() and
    /// process_step(), then postprocess() and output_results().
    void
    run_cycle(const unsigned int cycle);

    /// Results of one contact node pair.
    struct PairResult
    {
      /// Index of the contact pair (interface) of the node pair, in the
      /// order of add_contact_pair().
      unsigned int     interface;
      /// Position of the slave node in the undeformed mesh (after node
      /// insertion).
      dealii::Point<2> location;
      /// True for a pair of edge midpoints (k = 2), false for a pair of
      /// vertices.
      bool             midpoint;
      /// Whether the pair is closed (in contact) in the converged solution.
      bool             active;
      /// Tributary length $w$ of the node on the interface
      /// (ContactNodePair::weight); forces divided by it are tractions.
      double           weight;
      /// Gap $g = (u_B - u_A)\cdot n + g_0$ of the converged solution
      /// (length units; positive: open, negative: penetration).
      double           gap;
      /// Recovered contact pressure, compression > 0: ContactPressure::recover()
      /// applied to the nodal forces -lambda of the interface, i.e. at this
      /// pair the value of the polynomial of degree k fitted in the
      /// least-squares sense to the nodal forces of the closed pairs within
      /// three sub-edges on each side (a patch fit, not the consistent solve
      /// M_Gamma p = -lambda of ContactPressure::consistent()); zero when open.
      double           pressure;
      double           lumped_pressure;     ///< -lambda / weight
      double           multiplier;          ///< raw multiplier lambda (a nodal force)
      bool             at_open_end;         ///< see ContactNodePair::at_open_end
      double           tangential_traction; ///< tangential force / weight
      double           slip;                ///< relative tangential displacement (u_B - u_A).t
      /// "open", "stick" or "slip" with Coulomb friction; "open" or
      /// "closed" with the frictionless and stick models.
      std::string      status;
      /// Coulomb friction: the slip of this load step (with the penalty
      /// variant, the increment of the plastic slip); zero for open pairs
      /// and without friction.
      double           slip_increment = 0;
      /// Tangent t of the pair (tangential traction and slip are along it).
      dealii::Tensor<1, 2> tangent;
      /// Tangential traction recovered as the pressure (ContactPressure::recover
      /// applied to the tangential nodal forces); tangential_traction is the
      /// raw force per tributary length.
      double           shear = 0;
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
    struct InterfaceResult
    {
      unsigned int               master_body = 0; ///< body index of the master side
      unsigned int               slave_body  = 0; ///< body index of the slave side
      dealii::types::boundary_id master_id   = 0; ///< boundary id of the master side
      dealii::types::boundary_id slave_id    = 0; ///< boundary id of the slave side
      /// Length of the paired interface (sum of its segments on the slave side).
      double                     length = 0;
      /// Sum of the normal nodal forces (compression > 0).
      double                     normal_force = 0;
      /// Sum of the tangential nodal forces (along each pair's tangent).
      double                     tangential_force = 0;
      /// Resultant force vector on the slave body.
      dealii::Tensor<1, 2>       force;
      /// Moment of the nodal forces on the slave body about
      /// Options::moment_point, $\sum_i (x_i - x_0)\times f_i$ with the
      /// slave node's position $x_i$ (counter-clockwise positive).
      double                     moment = 0;
      /// Centre of the normal forces (the midpoint of the interface when
      /// nothing is transmitted).
      dealii::Point<2>           centre_of_pressure;
      /// Pairs open.
      unsigned int               n_open = 0;
      /// Pairs closed and sticking (without Coulomb friction: every closed
      /// pair).
      unsigned int               n_stick = 0;
      /// Pairs closed and slipping (Coulomb friction).
      unsigned int               n_slip = 0;
      /// Whether ContactDetection found the interface ("Pairs = auto").
      bool                       detected = false;
      /// The Coulomb friction coefficient of the interface (its pair's own,
      /// else by bodies, else by materials, else the common one; 0 without
      /// Coulomb friction).
      double                     friction_coefficient = 0;
    };

    /// One converged load step.
    struct StepResult
    {
      /// Number of the load step, 1 to Options::n_load_steps.
      unsigned int step;
      /// Its time, t = final_time * step / n_load_steps.
      double       time;
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
      double       dissipated_energy = 0;
      /// Resultant of the contact forces (normal and tangential) on the
      /// slave bodies at the end of the step (force units).
      dealii::Tensor<1, 2> total_contact_force;
      /// The result of every node pair at the end of the step.
      std::vector<PairResult> pairs;
      /// The resultant of each interface (index: the interface).
      std::vector<InterfaceResult> interfaces;
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
        double       imbalance, residual, tolerance, condition;
      };
      /// One entry per body.
      std::vector<Balance> balance;
      /// The reaction (force and moment about Options::moment_point) of
      /// every support: each boundary id with Dirichlet data or a roller,
      /// each point constraint (SupportReactions).
      std::vector<SupportReactions::Reaction> reactions;
    };

    /// Everything a test or a user program wants to look at after run().
    struct Results
    {
      /// The mesh of all bodies after node insertion (material id = body
      /// index), of the last refinement cycle.
      PolygonalMesh<2>             mesh;
      /// The node pairs at the end of the last load step.
      std::vector<PairResult>      pairs;
      /// What node insertion did, one report per contact pair.
      std::vector<NodeInsertion::Report> insertion_reports;
      /// The matched interfaces (pairs and segments) of node insertion.
      std::vector<NodeInsertion::Interface> interfaces;
      /// The interfaces ContactDetection found ("Pairs = auto"), after the
      /// explicit ones in the numbering of the interfaces.
      ContactDetection::Result     detection;
      /// The resultant of each interface in the last load step.
      std::vector<InterfaceResult> interface_results;
      /// Number of active pairs at an open end (each printed as a warning).
      unsigned int                 n_open_end_warnings = 0;
      /// Contact constraints already imposed by the displacement constraints
      /// (see ContactAssembler::get_dropped_constraints()).
      unsigned int                 n_dropped_constraints = 0;
      /// Pairs that close a triangle of pairs where three bodies meet
      /// (NodeInsertion::mark_junctions()); unilateral and Coulomb contact
      /// keep them open.
      unsigned int                 n_junction_pairs = 0;
      /// @var unsigned int n_dofs
      /// Number of displacement DoFs (the size of solution).
      /// @var unsigned int n_multipliers
      /// Number of contact multipliers (normal, and tangential ones with
      /// multiplier-based tangential models); the saddle-point system has
      /// n_dofs + n_multipliers unknowns.
      unsigned int                 n_dofs = 0, n_multipliers = 0;
      /// Active-set (Newton) iterations of the last load step.
      unsigned int                 active_set_iterations = 0;
      /// Per iteration of the last load step, the number of active pairs.
      std::vector<unsigned int>    active_set_history;
      /// Iterations of the linear solver summed over the last load step
      /// (1 per direct solve).
      unsigned int                 linear_iterations = 0;
      dealii::Tensor<1, 2>         total_contact_force; ///< on the slave bodies
      /// Per body, the resultant (x, y) of the assembled loads (body force,
      /// tractions, pressures, nodal loads) of the last load step; neither
      /// reactions nor contact forces.
      std::vector<dealii::Tensor<1, 2>> applied_load_per_body;
      /// The stick penalty of the contact assembler (ContactScales::penalty(),
      /// units of E/h); only the penalty tangential models (penalty,
      /// coulomb_penalty) use it.
      double                       penalty = 0;
      /// Cell-average stresses (xx, yy, xy) per cell.
      std::vector<std::array<double, 3>> cell_stress;
      /// Displacements of the last load step (n_dofs entries, constraints
      /// distributed).
      dealii::Vector<double>       solution;
      /// One line on the saddle-point solver and its last solve
      /// (SaddlePointSolver::description()).
      std::string                  solver;
      /// @var std::vector<unsigned int> cells_per_body
      /// Per body, the number of cells.
      /// @var std::vector<unsigned int> dofs_per_body
      /// Per body, the number of DoFs (two per node of its cells).
      std::vector<unsigned int>    cells_per_body, dofs_per_body;
      /// Per body, the errors against its exact solution (zero where none
      /// is given).
      std::vector<ErrorNorms>      errors;
      /// Wall times of the stages (mesh, node insertion, assembly, solve).
      std::map<std::string, double> timings;
      /// The converged load steps (one for a static problem); pairs, solution
      /// and stresses above are those of the last one.
      std::vector<StepResult>      steps;
      /// Sum of the dissipated energy of the steps.
      double                       dissipated_energy = 0;
      /// @var unsigned int n_processes
      /// MPI processes of the run.
      /// @var unsigned int n_rows_across_processes
      /// Contact constraint rows of the last solve whose DoFs are owned by
      /// more than one process (0 on the serial path).
      unsigned int                 n_processes = 1, n_rows_across_processes = 0;
      /// Peak resident memory (VmHWM) of each process at the end of the
      /// cycle, in MB.
      std::vector<double>          peak_memory_MB;
    };

    /// The results of the last refinement cycle of run() or of the last
    /// run_cycle(); empty before.
    const Results &
    get_results() const
    {
      return results;
    }

    /**
     * The collapse mechanism of the last solve that ended in "No static
     * equilibrium" (the proof the globalized contact solve returns, see
     * ActiveSetSolver), or nullptr. run() writes it as
     * `<prefix>-mechanism.vtu` (the motion as the displacement field,
     * largest nodal displacement 1) and `<prefix>-mechanism.svg` (the
     * bodies moved by it, hinges marked) before it passes the exception on.
     */
    const CollapseMechanism *
    collapse_mechanism() const
    {
      return mechanism.get();
    }

    /// The per-body errors of every cycle of run().
    const std::vector<std::vector<ErrorNorms>> &
    convergence_history() const
    {
      return convergence;
    }

  private:
    /// See collapse_mechanism().
    std::shared_ptr<const CollapseMechanism> mechanism;

    /// Write the collapse mechanism's files (see collapse_mechanism()).
    void
    write_mechanism() const;

    /// The refinement cycles of run(), after the output files of an
    /// earlier run were removed.
    void
    run_cycles();

    /// Options::finite_strain: the load steps with FiniteSliding, their
    /// report and output files (VTU per step with a .pvd, the step history
    /// as CSV and JSON, the node pairs of each step as CSV); per step the
    /// resultant and moment of every interface, the reaction and moment of
    /// every support (SupportReactions, from FiniteSliding::nodal_forces())
    /// and the applied loads, in the current configuration.
    void
    run_finite_sliding();

    /// The bodies' meshes of refinement cycle @p cycle appended into
    /// @p mesh, the material id of each body's cells its index, and the
    /// bodies' laws added to @p laws by that id.
    void
    make_body_meshes(const unsigned int cycle, PolygonalMesh<2> &mesh, MaterialLibrary<2> &laws) const;

    /// The steps of one cycle, in the order run_cycle() calls them.
    void
    make_meshes(const unsigned int cycle);
    void
    insert_nodes();
    void
    setup_system();
    void
    assemble_system(const double time);
    void
    solve(const unsigned int step, const double time);
    void
    process_step(const unsigned int step, const double time);
    /// The steps of process_step(), in its order.
    void
    store_solve_results();
    StepResult
    make_pair_results(const unsigned int step, const double time, const std::vector<double> &tangential_force);
    void
    make_interface_resultants(StepResult &step_result) const;
    void
    check_step_finite(const unsigned int step, const double time, const StepResult &step_result) const;
    void
    print_step(const unsigned int step, const double time, const StepResult &step_result) const;
    void
    verify_step(const unsigned int         step,
                const double               time,
                const std::vector<double> &tangential_force,
                StepResult                &step_result) const;
    void
    output_step(const unsigned int step) const;
    void
    postprocess();
    void
    output_results();
    void
    print_report() const;
    void
    write_pictures_files() const;
    void
    write_json_summary() const;

    struct Body
    {
      /// The mesh from the parameter file (used when @p given is null).
      MeshParameters                          mesh;
      /// How messages name the body ("body 3", "body 3 (part 12 of
      /// assembly.msh)").
      std::string                             name;
      std::shared_ptr<const PolygonalMesh<2>>    given;
      std::shared_ptr<const ConstitutiveLaw<2>> material;
      std::string                             exact; ///< exact displacement 'ux, uy' (may be empty)
      /// The material name for friction by pairs of materials (may be
      /// empty).
      std::string                             material_name;
      /// The parameter that gives the body's Young's modulus (empty for a
      /// body added in code).
      std::string                             modulus_parameter;
    };
    std::vector<Body>          bodies;
    BoundaryConditionParameters bc;
    std::vector<std::pair<dealii::types::boundary_id, dealii::types::boundary_id>> contact_pairs;
    /// Friction coefficient per pair (negative: opt.contact's).
    std::vector<double>        pair_friction;
    /// Friction coefficients by pairs of bodies (set_friction_coefficient();
    /// invalid_unsigned_int: any body), the later entries first.
    std::vector<std::tuple<unsigned int, unsigned int, double>> body_friction;
    /// Friction coefficients by pairs of material names ("*": any
    /// material), the later entries first.
    std::vector<std::tuple<std::string, std::string, double>> material_friction;
    /// The pairs and friction coefficients of the current cycle: the
    /// explicit ones, then the detected ones (made by insert_nodes()).
    std::vector<std::pair<dealii::types::boundary_id, dealii::types::boundary_id>> cycle_pairs;
    std::vector<double>        cycle_friction;
    /// The friction coefficient between two bodies from body_friction,
    /// else from material_friction (negative: none given).
    double
    friction_between(const unsigned int a, const unsigned int b) const;

    /// The bodies as ScaleCheck names them (material id = body index).
    std::vector<ScaleCheck::Body>
    scale_check_bodies() const;
    Options                    opt;
    /// The contact settings of the run: opt.contact with the pairs'
    /// friction coefficients (made by run()).
    ContactSettings            contact_settings;
    std::string                prm_directory;
    unsigned int               n_cycles = 1;
    Results                    results;
    std::vector<std::vector<ErrorNorms>> convergence;
    MPI_Comm                   mpi_communicator;
    unsigned int               n_processes = 1;
    bool                       distributed = false;
    /// Process 0 prints and writes files; the others compute silently.
    bool                       root = true;
    /// The terminal output of the run: std::cout on process 0, nothing on
    /// the others (the same policy as ElasticityProblem).
    dealii::ConditionalOStream pcout;
    /// The DoF handler, assembler, matrices and solvers of the current
    /// cycle (defined in the .cc file); declared after @p results so that it
    /// is destroyed before the mesh it refers to.
    struct CycleData;
    /// The steps of parse_parameters(), one per part of the parameter file
    /// (defined in the .cc file).
    struct ParameterReader;
    /// The steps of run_finite_sliding() and their state (defined in the
    /// .cc file).
    struct FiniteSlidingRun;
    std::unique_ptr<CycleData> data;
  };
} // namespace dealvem

#endif
