// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_solvers_sparse_cholesky_h
#define dealvem_solvers_sparse_cholesky_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace dealvem
{
  namespace internal
  {
    /**
     * Sparse Cholesky factorization of a symmetric positive definite
     * dealii::SparseMatrix by SuiteSparse's CHOLMOD (simplicial; the
     * fill-reducing ordering and the symbolic analysis are computed for
     * each new pattern and kept while the pattern repeats; see the .cc file
     * for the measurements behind both choices). factorize() returns false when the
     * matrix is not positive definite (the caller then falls back to an LU
     * factorization).
     */
    class SparseCholesky
    {
    public:
      SparseCholesky();
      ~SparseCholesky();
      SparseCholesky(const SparseCholesky &) = delete;
      SparseCholesky &
      operator=(const SparseCholesky &) = delete;

      bool
      factorize(const dealii::SparseMatrix<double> &A);

      void
      solve(dealii::Vector<double> &x, const dealii::Vector<double> &b) const;

      /// Factorizations with a new ordering and symbolic analysis, and
      /// those that kept the analysis of the last pattern.
      unsigned int n_analyses = 0, n_reused_analyses = 0;

    private:
      struct Data;
      std::unique_ptr<Data> data;
    };
  } // namespace internal
} // namespace dealvem

#endif
