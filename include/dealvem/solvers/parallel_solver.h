// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_solvers_parallel_solver_h
#define dealvem_solvers_parallel_solver_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>

#include <dealvem/solvers/linear_solver.h>

#include <string>
#include <vector>

namespace dealii
{
  namespace TrilinosWrappers
  {
    class SparseMatrix;
    namespace MPI
    {
      class Vector;
    }
  } // namespace TrilinosWrappers
} // namespace dealii

namespace dealvem
{
  /**
   * The solvers of LinearSolver for a system distributed over MPI
   * processes (a dealii::TrilinosWrappers::SparseMatrix and
   * TrilinosWrappers::MPI vectors with the same row map, as in step-40):
   * - CG-AMG: deal.II's SolverCG preconditioned by one ML
   *   smoothed-aggregation V-cycle with the ML settings of LinearSolver
   *   (internal::set_ml_parameters(), the one place they are written) and
   *   the three rigid-body modes as near-null space;
   * - UMFPACK and KLU: Trilinos Amesos KLU, which gathers the matrix on one
   *   process and factors it there (a reference for small systems and for
   *   comparing with the serial solve to round-off; it does not scale).
   */
  class ParallelLinearSolver
  {
  public:
    /// A solver with the @p settings of the serial LinearSolver (type,
    /// tolerance, iteration limit, AMG parameters).
    explicit ParallelLinearSolver(const LinearSolver::Settings &settings);

    /**
     * The rigid-body modes as full DoF vectors (every process holds all
     * entries, e.g. VEMDoFHandler::rigid_body_modes()); the entries of the
     * locally owned DoFs @p owned are kept, in the order of the matrix's
     * row map (increasing global index).
     */
    void
    set_near_null_space(const std::vector<std::vector<double>> &modes, const dealii::IndexSet &owned);

    /**
     * The coarse space of the two-level p-multigrid (as
     * LinearSolver::set_coarse_space(): the whole prolongation and coarse
     * modes on every process, e.g. from PMultigrid::make_prolongation()).
     * Each process keeps the rows of its owned DoFs; a coarse DoF belongs to
     * the process owning the fine DoF it is a copy of (its vertex value).
     * With it, CG's preconditioner is the p-multigrid unless
     * Settings::preconditioner says AMG. @p P must outlive solve().
     *
     * For a matrix condensed by constraints (the contact constraints of
     * DistributedContactSolver), @p lines (complete on every process; null
     * for none) carries the constraints between vertex values to the coarse
     * level (see the two-level cycle's restriction of P in the
     * documentation of SaddlePointSolver::set_coarse_space()); it must
     * outlive solve() too.
     */
    void
    set_coarse_space(const dealii::SparseMatrix<double>      &P,
                     const std::vector<std::vector<double>>  &coarse_modes,
                     const dealii::AffineConstraints<double> *lines = nullptr);

    /// Solve A x = b; x must have A's row map without ghosts. Collective.
    void
    solve(const dealii::TrilinosWrappers::SparseMatrix &A,
          dealii::TrilinosWrappers::MPI::Vector        &x,
          const dealii::TrilinosWrappers::MPI::Vector  &b);

    /// CG iterations of the last solve (1 for the direct solver).
    unsigned int
    last_iterations() const
    {
      return iterations;
    }

    /// Wall seconds of the last solve spent before the iteration: the AMG
    /// or p-multigrid set-up (0 for the direct solver).
    double
    last_setup_time() const
    {
      return setup_time;
    }

    /// One line for the output: the method, its preconditioner and the
    /// number of processes.
    std::string
    description() const;

  private:
    LinearSolver::Settings             settings;
    std::vector<std::vector<double>>   local_modes;
    const dealii::SparseMatrix<double> *prolongation = nullptr;
    const dealii::AffineConstraints<double> *coarse_lines = nullptr;
    std::vector<std::vector<double>>   coarse_modes;
    bool                               used_p_multigrid = false;
    unsigned int                     iterations = 0;
    double                           setup_time = 0;
    unsigned int                     n_processes = 1;
  };
} // namespace dealvem

#endif
