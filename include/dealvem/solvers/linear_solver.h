// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_solvers_linear_solver_h
#define dealvem_solvers_linear_solver_h

#include <deal.II/base/smartpointer.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <string>
#include <vector>

namespace dealvem
{
  /**
   * Solvers for the symmetric positive definite elasticity system (after
   * the constraints have been condensed), behind one interface:
   * - UMFPACK: SuiteSparse's sparse LU (dealii::SparseDirectUMFPACK);
   * - KLU: Trilinos Amesos KLU (dealii::TrilinosWrappers::SolverDirect);
   * - CG-AMG: deal.II's SolverCG on the matrix copied into Trilinos,
   *   preconditioned by one ML smoothed-aggregation V-cycle whose
   *   near-null space is the three rigid-body modes
   *   (set_near_null_space(), e.g. VEMDoFHandler::rigid_body_modes()),
   *   or by the two-level p-multigrid described below.
   *
   * <h3>Preconditioners of CG</h3>
   * - Preconditioner::amg: one ML V-cycle on the whole matrix (AMGSettings).
   * - Preconditioner::p_multigrid: a symmetric two-level V-cycle for order-2
   *   virtual elements. The coarse level is the k = 1 space on the same
   *   polygons, given by set_coarse_space() as a prolongation P (e.g.
   *   PMultigrid::make_prolongation()) and its rigid-body modes; the coarse
   *   operator is the Galerkin product P^T A P (so constraints condensed
   *   into A are respected, see below), approximately inverted by one ML
   *   V-cycle with the coarse modes as near-null space. On the fine level a
   *   Chebyshev smoother of degree Settings::smoother_degree with the
   *   diagonal (Jacobi) as inner preconditioner runs before and after the
   *   coarse correction (on one process it reads the matrix in single
   *   precision, Settings::single_precision_smoother). Pre- and post-smoother are the same symmetric
   *   polynomial, so the cycle is symmetric positive definite and CG
   *   applies. Rows of A without off-diagonal entries (DoFs constrained by
   *   AffineConstraints::distribute_local_to_global) are left to the
   *   smoother: the coarse functions vanish there, except that a
   *   constrained vertex DoF keeps its own decoupled coarse DoF.
   * - Preconditioner::automatic (the default): p_multigrid when a coarse
   *   space has been given, amg otherwise. So "CG-AMG" on an order-2 problem
   *   whose caller provides the k = 1 space (ElasticityProblem does) runs
   *   CG with the p-multigrid, which needs 2.5-3.5x fewer CG iterations
   *   than plain AMG on VEM k = 2 and no more than FE_Q(2) with AMG
   *   (doc/benchmarks.md); a matrix with only a near-null space (a
   *   condensed contact system, say) gets plain AMG.
   *
   * The Trilinos solvers need MPI to be initialized
   * (dealii::Utilities::MPI::MPI_InitFinalize in main()).
   */
  class LinearSolver
  {
  public:
    /// The method (see the class documentation).
    enum class Type
    {
      umfpack, ///< sparse LU (UMFPACK)
      klu,     ///< sparse LU (KLU)
      cg_amg   ///< conjugate gradients, preconditioned as Preconditioner says
    };

    /// The preconditioner of Type::cg_amg.
    enum class Preconditioner
    {
      automatic,  ///< p_multigrid with a coarse space, amg otherwise
      amg,        ///< one AMG V-cycle of the whole matrix
      p_multigrid ///< two-level: smoother on A, AMG on the coarse space
    };

    /// ML parameters (smoothed aggregation) of the AMG V-cycles.
    struct AMGSettings
    {
      /// ML smoother: "Chebyshev" or "symmetric Gauss-Seidel" (any ML name).
      std::string  smoother_type = "Chebyshev";
      /// ML "smoother: sweeps": the polynomial degree for Chebyshev.
      unsigned int smoother_sweeps = 2;
      /// ML "aggregation: threshold": drop weak couplings when aggregating.
      double       aggregation_threshold = 1e-4;
      /// ML "aggregation: type" Uncoupled instead of the default
      /// Uncoupled-MIS (what deal.II's higher_order_elements flag sets).
      bool         uncoupled_aggregation = false;
      /// Smoothed aggregation ("SA" defaults); false: "NSSA" defaults
      /// (deal.II's elliptic = false).
      bool         elliptic = true;
      /// Use the rotation too when three near-null-space modes are given;
      /// false: the two translations only (constant modes).
      bool         use_rotation = true;
    };

    /// How to solve.
    struct Settings
    {
      /// The method.
      Type           type               = Type::umfpack;
      /// CG: stop at this residual relative to the right-hand side.
      double         relative_tolerance = 1e-12;
      /// CG: at most this many iterations (then solve() throws).
      unsigned int   max_iterations     = 10000;
      /// Preconditioner of CG (ignored by the direct solvers).
      Preconditioner preconditioner = Preconditioner::automatic;
      /// The AMG (of the whole matrix, or of the coarse level of the
      /// p-multigrid).
      AMGSettings    amg;
      /// p-multigrid: degree of the Chebyshev smoother on the fine level
      /// (matrix-vector products per smoothing step).
      unsigned int   smoother_degree = 3;
      /// p-multigrid: the smoother damps the eigenvalues in
      /// [lambda_max / smoothing_range, lambda_max] of D^{-1} A.
      double         smoothing_range = 15.;
      /// p-multigrid, one process: the fine level's smoother and the
      /// residual it hands to the coarse level read a single-precision copy
      /// of the matrix (half the bytes per value: the smoother is most of
      /// the memory traffic of an iteration). CG itself, its residual and
      /// the coarse level stay in double precision, so the solution reaches
      /// the same tolerance; the preconditioner is a symmetric positive
      /// definite operator either way. As deal.II's matrix-free multigrid
      /// (step-37) runs its levels in float. false: double precision
      /// throughout (the Trilinos copy).
      bool single_precision_smoother = true;
      /// false: the matrix is not symmetric (the condensed contact problem
      /// with slipping pairs), the iterative solvers use GMRES (right
      /// preconditioned, restart 200) instead of CG. ParallelLinearSolver
      /// reads it.
      bool           symmetric = true;
    };

    /// "UMFPACK", "KLU", "CG-AMG" (case-insensitive); throws otherwise.
    static Type
    parse_type(const std::string &name);

    /// The name of @p t as parse_type() reads it.
    static std::string
    type_name(const Type t);

    /// "automatic", "AMG", "p-multigrid" (case-insensitive); throws otherwise.
    static Preconditioner
    parse_preconditioner(const std::string &name);

    /// The name of @p p as parse_preconditioner() reads it.
    static std::string
    preconditioner_name(const Preconditioner p);

    /// A solver with @p settings; nothing is factored before solve().
    explicit LinearSolver(const Settings &settings);

    /// Rigid-body modes for the AMG: 3 vectors of the system size in 2D,
    /// 6 in 3D (three translations, three rotations; PolyhedralElasticity).
    void
    set_near_null_space(const std::vector<std::vector<double>> &modes);

    /**
     * The coarse level of the p-multigrid: the prolongation @p P (rows: the
     * system's DoFs, columns: the coarse DoFs) and the near-null space of
     * the coarse level (e.g. the three rigid-body modes of the k = 1 space).
     * @p P is referenced, not copied: it must live until the last solve.
     * Throws unless every coarse mode has P.n() entries.
     */
    void
    set_coarse_space(const dealii::SparseMatrix<double>     &P,
                     const std::vector<std::vector<double>> &coarse_modes);

    /// Solve A x = b (throws with the residual if CG does not converge).
    void
    solve(const dealii::SparseMatrix<double> &A,
          dealii::Vector<double>             &x,
          const dealii::Vector<double>       &b);

    /// CG iterations of the last solve (1 for the direct solvers).
    unsigned int
    last_iterations() const
    {
      return iterations;
    }

    /// Wall seconds of the last solve spent in setting up the
    /// preconditioner or factorization (copies into Trilinos, P^T A P, AMG
    /// hierarchy, eigenvalue estimate); the rest was the iteration.
    double
    last_setup_time() const
    {
      return setup_time;
    }

    /// The preconditioner the next CG solve uses (automatic resolved).
    Preconditioner
    effective_preconditioner() const;

    /// One line for the output: the method and its preconditioner.
    std::string
    description() const;

  private:
    Settings                                                          settings;
    std::vector<std::vector<double>>                                  modes;
    dealii::SmartPointer<const dealii::SparseMatrix<double>, LinearSolver> prolongation;
    std::vector<std::vector<double>>                                  coarse_modes;
    unsigned int                                                      iterations = 0;
    double                                                            setup_time = 0;
  };

  namespace internal
  {
    /// ML parameters shared by the AMG preconditioners: smoothed
    /// aggregation, Chebyshev smoothing, KLU on the coarsest level, and the
    /// given near-null space (stored in @p storage, which must outlive the
    /// preconditioner).
    void
    set_ml_parameters(void                                   *teuchos_parameter_list,
                      const std::vector<std::vector<double>> &modes,
                      const unsigned int                      n,
                      std::vector<double>                    &storage);

    /// The same with the choices of @p amg.
    void
    set_ml_parameters(void                                   *teuchos_parameter_list,
                      const std::vector<std::vector<double>> &modes,
                      const unsigned int                      n,
                      std::vector<double>                    &storage,
                      const LinearSolver::AMGSettings        &amg);

    /**
     * Factor @p A and solve A x = b directly: UMFPACK, or Trilinos Amesos
     * KLU if @p use_klu; then iterative refinement with the same factors
     * (Higham, Accuracy and Stability of Numerical Algorithms, ch. 12):
     * while the componentwise backward error
     * $\omega = \max_i |b - Ax|_i / (|A||x| + |b|)_i$ exceeds 4 eps, solve
     * $A d = b - Ax$, and keep $x + d$ while it at least halves $\omega$
     * (at most three steps). Returns the final $\omega$.
     */
    double
    solve_direct(const dealii::SparseMatrix<double> &A,
                 dealii::Vector<double>             &x,
                 const dealii::Vector<double>       &b,
                 const bool                          use_klu);

    /**
     * Throws with the figures unless the solution @p x of A x = b is
     * accurate: for a direct solver (@p relative_tolerance = 0) the normwise
     * backward error $\|b - Ax\|_\infty / (\|A\|_\infty \|x\|_\infty +
     * \|b\|_\infty)$ at most 1e-10 (a stable factorisation gives about eps
     * times the growth factor), for an iterative one $\|b - Ax\|_2 \le
     * 10\,\mathrm{tol}\,\|b\|_2$ or that backward error (the floor of the
     * true residual when tol asks for less than the arithmetic attains). @p solver names the solver in the
     * message. Returns the relative residual $\|b - Ax\|_2 / \|b\|_2$.
     */
    double
    check_residual(const dealii::SparseMatrix<double> &A,
                   const dealii::Vector<double>       &x,
                   const dealii::Vector<double>       &b,
                   const double                        relative_tolerance,
                   const std::string                  &solver);

    /// check_residual() with the residual @p r = b - A x already computed
    /// and $\|A\|_\infty$ from @p matrix_norm (called only when the
    /// backward error is needed).
    double
    check_residual(const dealii::Vector<double>  &r,
                   const dealii::Vector<double>  &x,
                   const dealii::Vector<double>  &b,
                   const double                   relative_tolerance,
                   const std::string             &solver,
                   const std::function<double()> &matrix_norm);

    /// Upper-case copy of a solver name, for case-insensitive parsing.
    std::string
    upper_case(const std::string &name);
  } // namespace internal
} // namespace dealvem

#endif
