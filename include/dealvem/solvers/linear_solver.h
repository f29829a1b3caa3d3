// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_solvers_linear_solver_h
#define dealvem_solvers_linear_solver_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

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
   *   (set_near_null_space(), e.g. VEMDoFHandler::rigid_body_modes()).
   *
   * The Trilinos solvers need MPI to be initialized
   * (dealii::Utilities::MPI::MPI_InitFinalize in main()).
   */
  class LinearSolver
  {
  public:
    enum class Type
    {
      umfpack,
      klu,
      cg_amg
    };

    struct Settings
    {
      Type         type               = Type::umfpack;
      double       relative_tolerance = 1e-12;
      unsigned int max_iterations     = 10000;
    };

    /// "UMFPACK", "KLU", "CG-AMG" (case-insensitive); throws otherwise.
    static Type
    parse_type(const std::string &name);

    static std::string
    type_name(const Type t);

    explicit LinearSolver(const Settings &settings);

    /// Rigid-body modes (3 vectors of the system size) for the AMG.
    void
    set_near_null_space(const std::vector<std::vector<double>> &modes);

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

    std::string
    description() const;

  private:
    Settings                         settings;
    std::vector<std::vector<double>> modes;
    unsigned int                     iterations = 0;
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

    /// Factor @p A and solve A x = b directly: UMFPACK, or Trilinos Amesos
    /// KLU if @p use_klu.
    void
    solve_direct(const dealii::SparseMatrix<double> &A,
                 dealii::Vector<double>             &x,
                 const dealii::Vector<double>       &b,
                 const bool                          use_klu);

    /// Upper-case copy of a solver name, for case-insensitive parsing.
    std::string
    upper_case(const std::string &name);
  } // namespace internal
} // namespace dealvem

#endif
