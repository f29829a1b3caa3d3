// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_solvers_saddle_point_solver_h
#define dealvem_solvers_saddle_point_solver_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  template <typename number>
  class AffineConstraints;
}

namespace dealvem
{
  namespace internal
  {
    class SparseCholesky;
    class AMGCache;
    class CondensedMatrix;
    struct CondensedSystem;
  }

  /**
   * Solvers for the contact saddle-point system
   * @f[ A = \begin{pmatrix} K & B^T \\ B & D \end{pmatrix} @f]
   * stored as one dealii::SparseMatrix whose first @p n_displacements
   * unknowns are displacements and the rest Lagrange multipliers ($D$ is
   * zero on active constraints and the identity on inactive ones).
   *
   * - UMFPACK: SuiteSparse LU of the whole matrix.
   * - KLU: Trilinos Amesos KLU of the whole matrix.
   * - GMRES-AMG: GMRES (right preconditioned) with the block lower
   *   triangular preconditioner
   *   $P = \begin{pmatrix} \hat K_\rho & 0 \\ B & \hat S \end{pmatrix}$,
   *   where $\hat K_\rho^{-1}$ is one ML algebraic-multigrid V-cycle (rigid-body
   *   modes as near-null space) for the augmented block
   *   $K_\rho = K + \rho B^TB$ ($\rho$ = mean diagonal of $K$; augmentation
   *   makes the block definite even when a body is held only by contact),
   *   and $\hat S = D - B\,\mathrm{diag}(K_\rho)^{-1}B^T$ is factored
   *   exactly (it is small: one row per multiplier). The system is solved as
   *   a 2 x 2 BlockSparseMatrix, and P^{-1} is deal.II's
   *   block_forward_substitution over the two inverses as LinearOperators.
   * - CG-AMG constraints: no saddle point at all. Each active constraint
   *   row of $B$ becomes an AffineConstraints line on one slave DoF
   *   (ContactConstraints: pivoted elimination, redundant rows dropped when
   *   consistent and an error when not), $K$ and the right-hand side are
   *   condensed as deal.II's step-41/42 impose their active sets, the
   *   symmetric positive definite result is solved by LinearSolver's CG +
   *   ML AMG (rigid-body near-null space), and the multipliers are
   *   recovered from the residual $f - Ku$ on the slave DoFs. Needs
   *   symmetric contact rows: the slip rows of Coulomb friction are
   *   refused with a message.
   * - direct constraints: the same condensed system factored by CHOLMOD's
   *   Cholesky (internal::SparseCholesky; LU by UMFPACK if it is not
   *   positive definite). On Hertz (step-3, k = 2, 44k DoFs) the six
   *   factorizations take about half the time of UMFPACK's on the whole
   *   saddle point.
   */
  class SaddlePointSolver
  {
  public:
    /// The method (see the class documentation).
    enum class Type
    {
      umfpack,            ///< sparse LU of the whole saddle point (UMFPACK)
      klu,                ///< sparse LU of the whole saddle point (KLU)
      gmres_amg,          ///< GMRES with a block AMG preconditioner
      cg_amg_constraints, ///< constraints condensed, CG with AMG
      direct_constraints  ///< constraints condensed, sparse Cholesky
    };

    /// How to solve.
    struct Settings
    {
      /// The method.
      Type         type               = Type::umfpack;
      /// Iterative methods: stop at this residual relative to the right-hand side.
      double       relative_tolerance = 1e-12;
      /// Iterative methods: at most this many iterations.
      unsigned int max_iterations     = 2000;
      /// CG-AMG: start each Krylov iteration from the displacements of the
      /// previous solve (an active-set or Newton iteration, a load step;
      /// the slave DoFs of the new constraints at their condensed value)
      /// instead of from zero, when the sizes agree and that start has the
      /// smaller residual.
      bool warm_start = true;
      /// CG-AMG: keep the AMG hierarchy of an earlier solve while at most
      /// this fraction of the rows of the condensed matrix differ from the
      /// matrix it was built on (an active-set or Newton step that opens,
      /// closes or releases a few pairs), corrected by an exact solve on
      /// the changed rows (see solve()); 0 keeps it only for an unchanged
      /// matrix.
      double amg_reuse_fraction = 0.05;
      /// CG-AMG: the relative tolerance of the solves made while
      /// set_inexact() is on (when it is larger than relative_tolerance;
      /// 0 switches inexact solves off).
      double inexact_tolerance = 1e-6;
      /// CG-AMG: where an inexact solve stops first (when it is larger than
      /// inexact_tolerance); refine_last_solve() goes on by decades down to
      /// inexact_tolerance.
      double inexact_start_tolerance = 1e-3;
      /// CG-AMG: precondition by the two-level p-multigrid when a coarse
      /// space is set (set_coarse_space()); false: ML AMG on the whole
      /// condensed matrix.
      bool p_multigrid = true;
    };

    /// "UMFPACK", "KLU", "GMRES-AMG", "CG-AMG" (or its former name "CG-AMG
    /// constraints"), "direct constraints" (case-insensitive); throws
    /// otherwise.
    static Type
    parse_type(const std::string &name);

    /// The name of @p t as parse_type() reads it ("UMFPACK", ...).
    static std::string
    type_name(const Type t);

    /// A solver with @p settings; nothing is factored before solve(). Throws
    /// if Settings::amg_reuse_fraction is outside [0, 1] or
    /// Settings::inexact_tolerance outside [0, 1).
    explicit SaddlePointSolver(const Settings &settings);

    virtual ~SaddlePointSolver() = default;

    /// Near-null space (rigid-body modes, size n_displacements each) for AMG.
    void
    set_near_null_space(const std::vector<std::vector<double>> &modes);

    /**
     * CG-AMG: the coarse space of the two-level p-multigrid that then
     * preconditions CG on the condensed stiffness (unless
     * Settings::p_multigrid is false), as LinearSolver::set_coarse_space()
     * does for one body: the prolongation @p P from the k = 1 to the k = 2
     * space of all bodies (PMultigrid::make_prolongation() on the DoF
     * handler of the bodies) and the coarse rigid-body modes. @p P is
     * referenced and must outlive the solves.
     *
     * The condensed matrix has the rows of the slave DoFs decoupled; the
     * prolongation is fitted to it for each hierarchy: where a contact
     * constraint ties a slave vertex value to vertex values of the other
     * body, the coarse level gets the same constraint (the coarse functions
     * of the master side extend across the interface as the fine ones do),
     * so that the coarse space spans the motion of the bodies together. The
     * stick-penalty preconditioner (set_stick_directions()) uses the
     * p-multigrid on its tied matrix likewise. With it, CG on the condensed
     * contact patch test takes the iterations of one body with the
     * p-multigrid (doc/benchmarks.md).
     */
    void
    set_coarse_space(const dealii::SparseMatrix<double>     &P,
                     const std::vector<std::vector<double>> &coarse_modes);

    /// Whether the CG-AMG solves use the p-multigrid: a coarse space is
    /// set and Settings::p_multigrid is true.
    bool
    uses_p_multigrid() const
    {
      return coarse_prolongation != nullptr && settings.p_multigrid;
    }

    /**
     * CG-AMG constraints with stick by penalty: the spring directions (rows
     * over displacement DoFs, ContactAssembler::stick_penalty_rows()) of the
     * next solve. The condensed stiffness then carries springs of stiffness
     * 1e3 E/h, which AMG alone resolves poorly (9-11 times the iterations).
     * With them the preconditioner is the additive two-subspace one
     * $M^{-1} = Z (Z^T K Z)^{-1}_{AMG} Z^T + \sum_s e_s e_s^T / K_{ss}$: $Z$
     * ties the spring ends (the springs' directions as extra slave lines, so
     * that $Z^T K Z$ holds no spring and is the stick-by-multipliers
     * matrix), and the slave DoFs $s$ of those lines get a diagonal
     * correction. Every $u$ splits stably into a tied part and a jump at the
     * slaves whatever the penalty, so the iterations stay those of the tied
     * problem. The solution is that of the penalty system (CG on the
     * unchanged condensed matrix). Ignored by the other solver types.
     */
    void
    set_stick_directions(const std::vector<std::vector<std::pair<unsigned int, double>>> &rows);

    /// What the next solve is part of ("active-set iteration 3"), for the
    /// messages of its verification.
    void
    set_context(const std::string &text)
    {
      context = text;
    }

    /**
     * Solve A x = b and check the residual (internal::check_residual(); the
     * direct solves are refined iteratively first). (DistributedContactSolver
     * overrides it.)
     *
     * CG-AMG keeps its ML AMG hierarchy between solves. A solve whose
     * condensed matrix equals the one the hierarchy was built on (pattern
     * and values) uses it as it is; one whose matrix differs in at most
     * Settings::amg_reuse_fraction of the rows uses it with an exact solve
     * on those rows before and after the AMG cycle (a symmetric
     * multiplicative Schwarz method, symmetric positive definite like the
     * cycle); if CG then needs more than twice the iterations per decade of
     * residual reduction of the last fresh hierarchy (and 10 more), the
     * hierarchy is built again for this matrix and CG goes on from its
     * iterate. Otherwise the hierarchy is built again.
     */
    virtual void
    solve(const dealii::SparseMatrix<double> &A,
          const unsigned int                  n_displacements,
          dealii::Vector<double>             &x,
          const dealii::Vector<double>       &b);

    /**
     * CG-AMG on a symmetric condensed matrix (with or without stick
     * springs; with them, CG with the stick preconditioner): while
     * @p inexact is true, solve() stops at Settings::inexact_tolerance (when
     * that is larger than Settings::relative_tolerance) and keeps the
     * condensed system, so that complete_last_solve() can go on to the full
     * tolerance. For the iterations of a nonlinear method whose solutions
     * only choose the next iterate (an active-set iteration whose set still
     * changes, ActiveSetSolver); the solution it accepts must be completed.
     * The other solver types and the non-symmetric solves ignore it
     * (last_solve_inexact() is false after them).
     */
    void
    set_inexact(const bool inexact);

    /// Whether the last solve() stopped at Settings::inexact_tolerance
    /// (see set_inexact()).
    bool
    last_solve_inexact() const
    {
      return last_inexact;
    }

    /**
     * Continue the last solve(), which stopped at the inexact tolerance
     * (last_solve_inexact()), to Settings::relative_tolerance: CG from its
     * condensed solution with its condensed matrix and preconditioner.
     * @p A and @p b must be the matrix and right-hand side of that solve;
     * @p x (its size) receives the displacements and multipliers, as from
     * solve(). last_iterations() then counts the iterations of the
     * continuation. Throws if the last solve was not inexact.
     */
    void
    complete_last_solve(const dealii::SparseMatrix<double> &A,
                        dealii::Vector<double>             &x,
                        const dealii::Vector<double>       &b);

    /**
     * Continue the last solve(), which stopped at an inexact tolerance
     * (last_solve_inexact()), by one decade, to at most
     * Settings::inexact_tolerance; it stays inexact. Returns false, and
     * does nothing, when it had reached Settings::inexact_tolerance
     * already. Arguments and last_iterations() as complete_last_solve().
     */
    bool
    refine_last_solve(const dealii::SparseMatrix<double> &A,
                      dealii::Vector<double>             &x,
                      const dealii::Vector<double>       &b);

    /// The method of the settings.
    Type
    get_type() const
    {
      return settings.type;
    }

    /// CG-AMG constraints: constraint rows of the last solve dropped as
    /// redundant (consistent and linearly dependent on others).
    unsigned int
    last_dropped_constraints() const
    {
      return n_dropped;
    }

    /// Iterations of the last solve (1 for direct solvers).
    unsigned int
    last_iterations() const
    {
      return iterations;
    }

    /// Direct constraints: the Cholesky factorizations computed, and the
    /// solves that reused the factorization of an earlier solve because
    /// their condensed matrix was the same (pattern and values; an adjoint
    /// solve with the matrix of the converged state, a load step with an
    /// unchanged active set).
    std::pair<unsigned int, unsigned int>
    factorization_counts() const
    {
      return {n_factorizations, n_factorization_reuses};
    }

    /// Direct constraints: of the Cholesky factorizations, those that
    /// computed a fill-reducing ordering and symbolic analysis for a new
    /// pattern, and those that kept the analysis of the last one because
    /// the condensed matrix had its pattern (a design iteration, a Newton
    /// or load step with the same active set).
    std::pair<unsigned int, unsigned int>
    analysis_counts() const;

    /// One line for the output: the method, its preconditioner and what the
    /// last solve used (iterations, fallbacks).
    virtual std::string
    description() const;

    /// Whether @p t condenses the contact constraints (no saddle point).
    static bool
    is_condensed(const Type t)
    {
      return t == Type::cg_amg_constraints || t == Type::direct_constraints;
    }

    /// Whether @p t is an iterative method (with an AMG preconditioner,
    /// which wants the near-null space: set_near_null_space()); the others
    /// factorize and solve to round-off.
    static bool
    is_iterative(const Type t)
    {
      return t == Type::gmres_amg || t == Type::cg_amg_constraints;
    }

  protected:
    /// The settings of the constructor.
    Settings                         settings;
    /// The near-null space of set_near_null_space().
    std::vector<std::vector<double>> modes;
    /// The prolongation of set_coarse_space() (null: none).
    const dealii::SparseMatrix<double> *coarse_prolongation = nullptr;
    /// The coarse rigid-body modes of set_coarse_space().
    std::vector<std::vector<double>> coarse_modes;
    /// The spring directions of set_stick_directions().
    std::vector<std::vector<std::pair<unsigned int, double>>> stick_rows;
    /// The last solve preconditioned the stick springs by tying them.
    bool                             used_stick_preconditioner = false;
    /// See last_iterations().
    unsigned int                     iterations = 0;
    /// See last_dropped_constraints().
    unsigned int                     n_dropped  = 0;
    /// direct constraints: the factorization (its workspace kept between
    /// active sets)
    std::shared_ptr<internal::SparseCholesky> cholesky;
    /// direct constraints: the condensed system that cholesky factors (its
    /// matrix is compared with the next one's)
    std::shared_ptr<internal::CondensedSystem> factored_system;
    /// Direct constraints: the Cholesky factorizations computed.
    unsigned int                        n_factorizations       = 0;
    /// Direct constraints: the solves that reused a factorization.
    unsigned int                        n_factorization_reuses = 0;
    /// CG-AMG: the AMG hierarchy of an earlier solve with a copy of the
    /// matrix it was built on: reused as it is for the same matrix (load
    /// steps, Newton iterations that keep the closed pairs), corrected on
    /// the changed rows when few differ (see solve())
    std::shared_ptr<internal::AMGCache> amg_cache;
    /// CG-AMG: AMG hierarchies built over the solves.
    unsigned int                        n_amg_setups = 0;
    /// CG-AMG: solves that reused the hierarchy of amg_cache.
    unsigned int                        n_amg_reuses = 0;
    /// CG-AMG: solves that used the hierarchy of an earlier matrix with the
    /// exact correction on the changed rows.
    unsigned int                        n_amg_corrections = 0;
    /// CG-AMG: corrected solves that converged too slowly and built the
    /// hierarchy again (counted in n_amg_setups too).
    unsigned int                        n_amg_slow_corrections = 0;
    /// CG-AMG: CG iterations per decade of residual reduction of the last
    /// solve with a freshly built hierarchy (0: none yet).
    double                              amg_iterations_per_decade = 0;
    /// CG-AMG: the time spent building AMG hierarchies.
    double                              amg_setup_seconds = 0;
    /// direct constraints: the last solve fell back to LU (the condensed
    /// matrix was not symmetric positive definite).
    bool                             used_lu_fallback = false;
    /// the condensed matrix was not symmetric (slipping pairs): GMRES / LU
    bool                             used_gmres = false;
    /// the displacements of the last iterative solve (warm start)
    dealii::Vector<double>           previous;
    /// See set_inexact().
    bool                             inexact_solves = false;
    /// See last_solve_inexact().
    bool                             last_inexact = false;
    /// The tolerance the last inexact solve reached.
    double                           last_inexact_tolerance = 0;
    /// complete_last_solve() and refine_last_solve(): go on to @p tolerance.
    void
    continue_last_solve(const dealii::SparseMatrix<double> &A,
                        dealii::Vector<double>             &x,
                        const dealii::Vector<double>       &b,
                        double                              tolerance,
                        const std::string                  &what);
    /// The condensed system of the last solve if it was inexact.
    std::shared_ptr<internal::CondensedSystem> inexact_system;
    /// The preconditioner of the stick springs of the last solve if it was
    /// inexact and had stick rows (the .cc's StickPreconditioner, kept
    /// for the continuation; null otherwise).
    std::shared_ptr<const void> inexact_stick;
    /// See set_context().
    std::string                      context;

  private:
    /// solve() for the condensed types (direct_constraints,
    /// cg_amg_constraints): eliminates the constraint rows, solves the
    /// condensed system directly or iteratively, and recovers the
    /// multipliers into @p x.
    void
    solve_condensed(const dealii::SparseMatrix<double> &A,
                    const unsigned int                  n_displacements,
                    dealii::Vector<double>             &x,
                    const dealii::Vector<double>       &b);

    /// The iterative solve of the condensed @p system of A x = b: warm
    /// start, inexact tolerance, and CG or GMRES preconditioned by the
    /// stick springs or by AMG; @p length is the length scale of the
    /// rotation mode.
    void
    solve_condensed_iteratively(internal::CondensedSystem          &system,
                                const dealii::SparseMatrix<double> &A,
                                const dealii::Vector<double>       &b,
                                const double                        length);

    /// solve() for gmres_amg: GMRES on the saddle-point system split into
    /// its displacement and multiplier blocks, with the block
    /// preconditioner.
    void
    solve_block_gmres(const dealii::SparseMatrix<double> &A,
                      const unsigned int                  n_displacements,
                      dealii::Vector<double>             &x,
                      const dealii::Vector<double>       &b);

    /// CG (GMRES if not @p symmetric) on K u = f from @p u to
    /// @p relative_tolerance, preconditioned by the AMG hierarchy (or the
    /// p-multigrid, see set_coarse_space()) of @p K_amg (K or its symmetric
    /// part) from amg_cache, built, reused or corrected as solve()
    /// describes; @p lines are the constraints K was condensed with.
    /// Returns the iterations.
    unsigned int
    solve_with_amg(const internal::CondensedMatrix         &K,
                   const internal::CondensedMatrix         &K_amg,
                   dealii::Vector<double>                  &u,
                   const dealii::Vector<double>            &f,
                   const double                             relative_tolerance,
                   const bool                               symmetric,
                   const dealii::AffineConstraints<double> &lines);
  };
} // namespace dealvem

#endif
