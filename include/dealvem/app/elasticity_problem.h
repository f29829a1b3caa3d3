// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_app_elasticity_problem_h
#define dealvem_app_elasticity_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <dealvem/app/design_parameters.h>
#include <dealvem/app/mesh_parameters.h>
#include <dealvem/app/problem_setup.h>
#include <dealvem/base/stage_timer.h>
#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/elasticity/force_balance.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/mesh/polygonal_mesh.h>
#include <dealvem/postprocessing/error_norms.h>
#include <dealvem/postprocessing/json_summary.h>
#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/solvers/linear_solver.h>
#include <dealvem/vem/partitioning.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dealvem
{
  /**
   * The parameter-file driven elasticity problem behind `dealvem
   * input.prm` (one body): mesh, material, order k and $\gamma$, boundary
   * conditions and loads by boundary id, body force, optional exact
   * solution with a convergence study, solver, and output (VTU, JSON).
   *
   * Data flow of run(), once per refinement cycle, in the functions of a
   * deal.II tutorial: make_mesh() -> setup_system() (DoFs, constraints,
   * sparsity) -> assemble_system() (ElasticityAssembler: VEMValues and
   * ElasticityOperator per cell) -> solve() -> output_results() (stresses,
   * errors, VTU, convergence table, JSON).
   *
   * <h3>MPI</h3>
   * Run by `mpirun -np N dealvem input.prm` (N > 1), the problem takes the
   * distributed path of step-40: every process builds the whole polygon
   * mesh and DoF numbering (replicated), VEMPartition splits the cells by
   * METIS, each process assembles its cells into a
   * dealii::TrilinosWrappers::SparseMatrix and MPI::Vector
   * (ElasticityAssembler's overload), ParallelLinearSolver solves (CG + ML
   * AMG, or Amesos KLU for the direct types), and each process writes the
   * .vtu piece of its cells; process 0 writes the .pvtu record, the JSON
   * summary and the console output. Errors are summed over the processes,
   * so the convergence table is the serial one. With one process the serial
   * path runs, unless the constructor asks for the distributed one.
   *
   * <h3>Finite strain</h3>
   * With 'Finite strain/Enabled = true' and a hyperelastic 'Material/Law'
   * (FiniteStrainParameters, MaterialLaws), solve() is replaced by
   * solve_finite_strain(): FiniteStrainAssembler and FiniteStrainSolver
   * with the 'Load steps/Number of steps' load steps, one VTU file per step
   * (write_finite_strain_vtu_file(): Cauchy stress, its von Mises value,
   * det F and the principal stretches) and a .pvd series, the Newton
   * history on the console and in the JSON summary. Serial only. Pressures
   * act as 'Finite strain/Pressure load' says (PressureLoad: follower by
   * default, or dead).
   *
   * <h3>Load steps and the time t</h3>
   * The expressions of the boundary conditions, loads and exact solution
   * may use the time t with the meaning it has in contact problems: load
   * step n of N ('Load steps/Number of steps') is at $t_n = n\,T/N$, $T$ =
   * 'Load steps/Final time'. At finite strain, step n solves with the data
   * of $t_n$ when an expression uses t (unscaled, set_time() of every
   * function and the Dirichlet values of $t_n$), and with the load factor
   * n/N of fixed data otherwise. The linear (small-strain) problem is
   * static: it is solved once, with every expression at $t = T$ (its
   * solution does not depend on the steps before), and a note says so when
   * N > 1.
   * A hyperelastic law without the switch is solved at small strain with
   * its linearization (the linear law of the same E and nu).
   */
  class ElasticityProblem
  {
  public:
    /// Which path run() takes.
    enum class Parallelism
    {
      /// distributed with more than one process in the communicator
      automatic,
      /// serial (dealii::SparseMatrix) on every process of the communicator
      serial,
      /// distributed, also on one process
      distributed
    };

    /// A problem on the processes of @p comm, serial or distributed as
    /// @p parallelism says; parse_parameters() sets it up.
    explicit ElasticityProblem(const MPI_Comm    comm        = MPI_COMM_WORLD,
                               const Parallelism parallelism = Parallelism::automatic);

    /// Declare every parameter (with its help string).
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Read the parameters; @p prm_directory is where relative file names
    /// are looked up.
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &prm_directory = "");

    /// Solve (all refinement cycles), write the output, return 0.
    void
    run();

    /// Errors of the last cycle (NaN without exact solution): L2, H1, energy.
    std::vector<double> last_errors;

    /// Number of DoFs of the last cycle.
    unsigned int last_n_dofs = 0;

    /// Iterations of the last cycle's linear solve (1 for a direct solver;
    /// finite strain: the Newton updates).
    unsigned int last_iterations = 0;

    /// If true, run() leaves the whole solution of the last cycle in
    /// last_solution on every process (in the distributed path this
    /// gathers all entries, which costs a vector of all DoFs per process).
    bool gather_solution = false;

    /// The solution of the last cycle (with gather_solution).
    dealii::Vector<double> last_solution;

    /// Peak resident memory (VmHWM) of each process at the end of run(), MB.
    std::vector<double> peak_memory_per_process;

    /// Whether run() takes the distributed path.
    bool
    is_distributed() const
    {
      return distributed;
    }

    /// Wall times of the stages of the last cycle (mesh, setup, assembly,
    /// solve, ...).
    std::map<std::string, double> last_timings;

  private:
    /// The refinement cycles and the summary of run(), after the output
    /// files of an earlier run were removed.
    void
    run_cycles();

    /// 'Design/Objective' set: topology optimization of the body on the
    /// mesh of cycle 0 (run_design()) instead of the cycles.
    void
    run_design_cycle();
    /// The steps of parse_parameters(), in its order.
    void
    check_contact_sections(dealii::ParameterHandler &prm) const;
    void
    parse_load_steps(dealii::ParameterHandler &prm);
    void
    parse_mesh_and_material(dealii::ParameterHandler &prm, const std::string &dir);
    /// The solver type of this cycle: 'Solver/Type', or for 'automatic'
    /// the choice by the size (printed with the reason).
    std::string
    chosen_solver_type() const;
    void
    make_mesh(const unsigned int cycle);
    void
    setup_system();
    /// Throw if the loads are out of scale with the stiffness
    /// (ScaleCheck::check(), small strain), naming both.
    void
    check_load_scale(const ElasticityAssembler<2> &assembler) const;
    /// Throw, naming the loads, if entry @p i of the load vector is not
    /// finite.
    void
    check_load_entry(const dealii::types::global_dof_index i, const double value) const;
    void
    assemble_system();
    void
    solve();
    // the distributed path (MPI): same stages on the locally owned cells
    void
    setup_distributed_system();
    void
    assemble_distributed_system();
    void
    solve_distributed();
    void
    output_results(const unsigned int cycle);
    /// The steps of output_results(), in its order.
    void
    check_displacement_scale(const unsigned int cycle) const;
    std::vector<ForceBalance::Body>
    verify_balance(const unsigned int cycle, dealii::Vector<double> *unbalanced = nullptr) const;
    /// The 'Rotation about centre' parts after a solve or a load step: the
    /// terminal lines and the JSON entries under @p key ("cycles.N." or
    /// "cycles.N.finite_strain.steps.n."); @p unbalanced as ForceBalance
    /// gives it, the node positions current ones if @p deformed.
    void
    report_rotations(const std::string &key, const dealii::Vector<double> &unbalanced, const bool deformed);
    void
    check_finite_results(const unsigned int cycle, const StressRecovery<2> &stresses, const ErrorNorms &errors) const;
    void
    write_vtu_output(const std::string &prefix, const std::string &vtu, const StressRecovery<2> &stresses);
    void
    print_cycle(const unsigned int                     cycle,
                const double                           hmax,
                const double                           max_vm,
                const std::vector<ForceBalance::Body> &balance) const;
    void
    record_cycle(const unsigned int                     cycle,
                 const double                           hmin,
                 const double                           hmax,
                 const double                           max_vm,
                 const std::vector<ForceBalance::Body> &balance,
                 const std::string                     &vtu,
                 const ErrorNorms                      &errors);
    void
    finish_cycle(const unsigned int cycle);
    /// The finite-strain solve of one cycle: Newton with load steps, the
    /// files of every converged step and the JSON record of every step
    /// (a failed step is recorded before its error is passed on).
    void
    solve_finite_strain(const unsigned int cycle);
    /// The steps of solve_finite_strain().
    void
    check_finite_strain_loads(FiniteStrainAssembler<2> &assembler) const;
    unsigned int
    monitor_vertex(const unsigned int cycle) const;
    void
    report_load_step(const unsigned int                        n,
                     const double                              load_factor,
                     const double                              time,
                     const FiniteStrainSolver<2>::StepRecord &r,
                     const unsigned int                        monitor,
                     const std::string                        &key);
    /// The settings of the linear solve (serial and distributed), the
    /// method recorded for the report.
    LinearSolver::Settings
    linear_solver_settings();
    void
    print_newton_history(const FiniteStrainSolver<2> &solver, const unsigned int cycle) const;

    MeshParameters         mesh_parameters;
    double                 youngs_modulus = 1000, poissons_ratio = 0.3;
    ElasticMaterial::Model model = ElasticMaterial::Model::plane_strain;
    /// 'Material/Law'.
    MaterialLaws::Law      law = "linear";
    /// The section 'Finite strain'.
    FiniteStrainParameters finite_strain;
    /// 'Load steps/Number of steps' and 'Final time' (the time t of the
    /// last step; the linear problem is solved at it).
    unsigned int           n_load_steps = 1;
    double                 final_time   = 1;
    unsigned int           degree = 2;
    double                 gamma  = 1.0;
    Stabilization          stabilization = Stabilization::automatic;
    BoundaryConditionParameters bc;
    DesignParameters            design;
    std::string                 exact_displacement;
    std::string  solver_type = "automatic";
    /// The solver type of the last solve (automatic resolved).
    std::string  used_solver_type = "UMFPACK";
    double       memory_limit_GB = 0;
    double       solver_tolerance = 1e-12;
    unsigned int solver_max_iterations = 10000;
    std::string  solver_preconditioner = "automatic";
    unsigned int n_cycles = 1;
    std::string  output_folder = "output", base_name = "solution";
    bool         write_vtu = true, write_json = true;
    std::string  prm_directory;
    /// Whether this run has written its JSON summary yet.
    bool         json_written = false;

    MPI_Comm                   mpi_communicator;
    bool                       distributed = false;
    unsigned int               this_process = 0, n_processes = 1;
    dealii::ConditionalOStream pcout;

    // the state of a run
    std::map<dealii::types::material_id, ElasticMaterial> materials;
    /// The law of 'Material/Law' by material id (finite strain).
    MaterialLibrary<2>                                    laws;
    /// Finite strain, last cycle: Newton updates summed over the steps, and
    /// the largest norm of the cell-averaged Cauchy stress of the last step.
    unsigned int                                          newton_updates   = 0;
    double                                                max_cauchy_norm  = 0;
    std::unique_ptr<dealii::Function<2>>                  exact;
    /// The stages of the whole run (the JSON's `timings`), and their times
    /// when the current cycle began (the cycle's own `timings` are the
    /// difference).
    std::unique_ptr<StageTimer>                           timer;
    std::map<std::string, double>                         cycle_start_stages;
    PolygonalMesh<2>                                      mesh;
    VEMDoFHandler<2>                                      dof_handler;
    dealii::AffineConstraints<double>                     constraints;
    /// The parts of the 'Rotation about centre' entries (apply_constraints()).
    std::vector<BoundaryConditions::RotationAboutCentre<2>> rotation_parts;
    dealii::SparsityPattern                               sparsity_pattern;
    dealii::SparseMatrix<double>                          system_matrix;
    dealii::Vector<double>                                system_rhs, solution;
    // distributed path: partition, index sets, Trilinos objects
    VEMPartition<2>                                       partition;
    dealii::IndexSet                                      locally_owned_dofs, locally_relevant_dofs;
    dealii::TrilinosWrappers::SparseMatrix                distributed_matrix;
    dealii::TrilinosWrappers::MPI::Vector                 distributed_rhs, distributed_solution;
    std::string                                           solver_description;
    unsigned int                                          solver_iterations = 0;
    /// Wall time of the preconditioner set-up within the solve.
    double                                                solver_setup_time = 0;
    dealii::ConvergenceTable                              table;
    /// Per cycle: the DoFs and the errors L2, H1, energy (for the rates).
    std::vector<double>                                   cycle_dofs;
    std::map<std::string, std::vector<double>>            cycle_errors;
    JsonSummary                                           json;
  };
} // namespace dealvem

#endif
