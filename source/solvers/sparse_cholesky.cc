// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include "sparse_cholesky.h"

#include <suitesparse/cholmod.h>

#include <algorithm>
#include <utility>

namespace dealvem
{
  namespace internal
  {
    struct SparseCholesky::Data
    {
      cholmod_common           common;
      cholmod_factor          *factor = nullptr;
      /// the pattern (lower triangle, by columns) the factor was analysed for
      std::vector<SuiteSparse_long> analysed_start, analysed_rows;
    };



    SparseCholesky::SparseCholesky()
      : data(std::make_unique<Data>())
    {
      cholmod_l_start(&data->common);
      // errors are reported through the status, not printed
      data->common.print = 0;
      // the simplicial (left-looking) factorization: Debian's default
      // reference BLAS makes the supernodal one slower (Hertz, k = 2,
      // 44k DoFs: 3.0 s against 3.9 s for the six factorizations)
      data->common.supernodal = CHOLMOD_SIMPLICIAL;
    }



    SparseCholesky::~SparseCholesky()
    {
      if (data->factor != nullptr)
        cholmod_l_free_factor(&data->factor, &data->common);
      cholmod_l_finish(&data->common);
    }



    bool
    SparseCholesky::factorize(const dealii::SparseMatrix<double> &A)
    {
      AssertThrow(A.m() == A.n(), dealii::ExcMessage("SparseCholesky: the matrix must be square."));
      const std::size_t n = A.m();
      // the lower triangle column by column: for a symmetric matrix, row i's
      // entries j >= i of the row-major storage (sorted, as CHOLMOD wants)
      std::size_t nnz = 0;
      for (std::size_t i = 0; i < n; ++i)
        for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it)
          nnz += (it->column() >= i);
      cholmod_sparse *M = cholmod_l_allocate_sparse(n, n, nnz, 1, 1, -1, CHOLMOD_REAL, &data->common);
      AssertThrow(M != nullptr, dealii::ExcMessage("SparseCholesky: CHOLMOD could not allocate the matrix."));
      auto *p = static_cast<SuiteSparse_long *>(M->p);
      auto *r = static_cast<SuiteSparse_long *>(M->i);
      auto *v = static_cast<double *>(M->x);
      std::vector<std::pair<SuiteSparse_long, double>> column;
      std::size_t                                      k = 0;
      for (std::size_t i = 0; i < n; ++i)
        {
          p[i] = k;
          column.clear();
          for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it)
            if (it->column() >= i)
              column.emplace_back(it->column(), it->value());
          std::sort(column.begin(), column.end());
          for (const auto &e : column)
            {
              r[k] = e.first;
              v[k] = e.second;
              ++k;
            }
        }
      p[n] = k;

      // The fill-reducing ordering and the symbolic factorization are
      // computed for each new pattern: the first active set's ordering
      // ignores the couplings that later contact constraints bring across
      // the interface (Hertz, k = 2: 3.7 times the flops of a fresh one).
      // A matrix with the pattern of the last one (a design iteration, a
      // Newton step that keeps its active set) keeps them: the analysis
      // takes about a fifth of a simplicial factorization at 4e5 DoFs.
      const bool same_pattern = data->factor != nullptr && data->analysed_start.size() == n + 1 &&
                                std::equal(p, p + n + 1, data->analysed_start.begin()) &&
                                std::equal(r, r + nnz, data->analysed_rows.begin(), data->analysed_rows.end());
      if (!same_pattern)
        {
          if (data->factor != nullptr)
            cholmod_l_free_factor(&data->factor, &data->common);
          data->analysed_start.clear();
          data->analysed_rows.clear();
          data->factor = cholmod_l_analyze(M, &data->common);
          if (data->factor == nullptr)
            cholmod_l_free_sparse(&M, &data->common);
          AssertThrow(data->factor != nullptr,
                      dealii::ExcMessage("SparseCholesky: CHOLMOD's analysis failed (status " +
                                         std::to_string(data->common.status) + ")."));
        }
      ++(same_pattern ? n_reused_analyses : n_analyses);
      cholmod_l_factorize(M, data->factor, &data->common);
      const int status = data->common.status;
      if (status >= CHOLMOD_OK && status != CHOLMOD_NOT_POSDEF && !same_pattern)
        {
          data->analysed_start.assign(p, p + n + 1);
          data->analysed_rows.assign(r, r + nnz);
        }
      cholmod_l_free_sparse(&M, &data->common);
      if (status < CHOLMOD_OK || status == CHOLMOD_NOT_POSDEF)
        {
          // (a failed factor is analysed afresh next time)
          cholmod_l_free_factor(&data->factor, &data->common);
          data->analysed_start.clear();
          data->analysed_rows.clear();
        }
      if (status == CHOLMOD_NOT_POSDEF)
        return false;
      AssertThrow(status >= CHOLMOD_OK,
                  dealii::ExcMessage("SparseCholesky: CHOLMOD's factorization failed (status " +
                                     std::to_string(status) + ")."));
      return true;
    }



    void
    SparseCholesky::solve(dealii::Vector<double> &x, const dealii::Vector<double> &b) const
    {
      Assert(data->factor != nullptr, dealii::ExcMessage("SparseCholesky: factorize() first."));
      const std::size_t n = b.size();
      cholmod_dense    *B = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, &data->common);
      std::copy(b.begin(), b.end(), static_cast<double *>(B->x));
      cholmod_dense *X = cholmod_l_solve(CHOLMOD_A, data->factor, B, &data->common);
      AssertThrow(X != nullptr, dealii::ExcMessage("SparseCholesky: CHOLMOD's solve failed."));
      x.reinit(n);
      const double *xv = static_cast<const double *>(X->x);
      std::copy(xv, xv + n, x.begin());
      cholmod_l_free_dense(&B, &data->common);
      cholmod_l_free_dense(&X, &data->common);
    }
  } // namespace internal
} // namespace dealvem
