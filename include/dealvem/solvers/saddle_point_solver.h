// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_solvers_saddle_point_solver_h
#define dealvem_solvers_saddle_point_solver_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace dealvem
{
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
   *   exactly (it is small: one row per multiplier).
   */
  class SaddlePointSolver
  {
  public:
    enum class Type
    {
      umfpack,
      klu,
      gmres_amg
    };

    struct Settings
    {
      Type         type               = Type::umfpack;
      double       relative_tolerance = 1e-12;
      unsigned int max_iterations     = 2000;
    };

    /// "UMFPACK", "KLU", "GMRES-AMG" (case-insensitive); throws otherwise.
    static Type
    parse_type(const std::string &name);

    static std::string
    type_name(const Type t);

    explicit SaddlePointSolver(const Settings &settings);

    /// Near-null space (rigid-body modes, size n_displacements each) for AMG.
    void
    set_near_null_space(const std::vector<std::vector<double>> &modes);

    /// Solve A x = b.
    void
    solve(const dealii::SparseMatrix<double> &A,
          const unsigned int                  n_displacements,
          dealii::Vector<double>             &x,
          const dealii::Vector<double>       &b);

    /// Iterations of the last solve (1 for direct solvers).
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
} // namespace dealvem

#endif
