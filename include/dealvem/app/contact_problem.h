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

#include <dealvem/app/contact_parameters.h>
#include <dealvem/app/contact_results.h>
#include <dealvem/app/design_parameters.h>
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
   * declares as many sections as the file uses, see body_sections()); a
   * body whose "Material" leaves Young's modulus or Poisson's ratio empty
   * takes body 0's. A
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

    /// The settings besides the bodies, the contact pairs and the boundary
    /// conditions (ContactParameters).
    using Options = ContactParameters;

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

    /// Results of one contact node pair (ContactPairResult).
    using PairResult = ContactPairResult;

    /// The resultant of one interface in a load step (ContactInterfaceResult).
    using InterfaceResult = ContactInterfaceResult;

    /// One converged load step (ContactStepResult).
    using StepResult = ContactStepResult;

    /// Everything a test or a user program wants to look at after run()
    /// (ContactResults).
    using Results = ContactResults;

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
    find_contact_pairs();
    void
    insert_nodes();
    /// 'Design/Objective' set: topology optimization of the bodies (cycle
    /// 0, run_design()) instead of the analysis.
    void
    run_design_cycle();
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
    DesignParameters           design;
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
