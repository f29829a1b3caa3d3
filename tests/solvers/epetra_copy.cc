// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The Epetra copies behind every ML hierarchy and p-multigrid
// (internal::epetra_copy(), which writes Epetra's compressed rows in place
// through its expert interface) against deal.II's own copy,
// TrilinosWrappers::SparseMatrix::reinit(A, drop_tolerance):
// - a square matrix (deal.II lists its diagonal first) and a rectangular one,
//   with rows of one entry, long rows and entries below the drop tolerance:
//   every row has the same columns in the same order and the same values,
//   bit for bit; the same number of entries, of diagonal entries and the
//   same maps; the products with a vector agree bit for bit;
// - copy_to_trilinos() gives a deal.II matrix whose product agrees as well;
// - an ML V-cycle built on either copy gives the same result to round-off
//   (ML's set-up is deterministic for one matrix).
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include "../../source/solvers/two_level_cycle.h"
#include "../tests.h"

#include <Epetra_CrsMatrix.h>
#include <Epetra_Vector.h>

#include <random>

using namespace dealvem;

namespace
{
  // A random matrix m x n: a band with random extra entries, some rows
  // with the diagonal alone, some entries below the drop tolerance.
  void
  make_matrix(const unsigned int m, const unsigned int n, dealii::SparsityPattern &sp, dealii::SparseMatrix<double> &A)
  {
    std::mt19937                            random(m + 7 * n);
    std::uniform_int_distribution<unsigned> column(0, n - 1);
    std::uniform_real_distribution<double>  value(-1., 1.);
    dealii::DynamicSparsityPattern          dsp(m, n);
    for (unsigned int i = 0; i < m; ++i)
      {
        if (i < n)
          dsp.add(i, i);
        if (i % 17 == 3)
          continue; // (the diagonal alone)
        for (unsigned int d = 1; d < 4; ++d)
          {
            if (i + d < n)
              dsp.add(i, i + d);
            if (i >= d && i - d < n)
              dsp.add(i, i - d);
          }
        for (unsigned int k = 0; k < (i % 5 == 0 ? 40u : 3u); ++k)
          dsp.add(i, column(random));
      }
    sp.copy_from(dsp);
    A.reinit(sp);
    for (unsigned int i = 0; i < m; ++i)
      for (auto it = A.begin(i); it != A.end(i); ++it)
        {
          const double v = value(random);
          // (every seventh entry tiny: dropped to a zero)
          it->value() = (std::distance(A.begin(i), it) % 7 == 5 ? 1e-16 * v : v) + (it->column() == i ? 10. : 0.);
        }
  }

  void
  compare(const unsigned int m, const unsigned int n, const std::string &name)
  {
    dealii::SparsityPattern      sp;
    dealii::SparseMatrix<double> A;
    make_matrix(m, n, sp, A);
    const double drop = 1e-13;

    const std::unique_ptr<Epetra_CrsMatrix> fast = internal::epetra_copy(A, drop);
    dealii::TrilinosWrappers::SparseMatrix  reference;
    reference.reinit(A, drop);
    const Epetra_CrsMatrix &E = reference.trilinos_matrix();

    testing::check(fast->Filled() && fast->StorageOptimized(), name + ": the copy is filled, storage optimized");
    testing::check(fast->NumMyRows() == E.NumMyRows() && fast->NumMyCols() == E.NumMyCols() &&
                     fast->NumGlobalRows() == E.NumGlobalRows() && fast->NumGlobalCols() == E.NumGlobalCols(),
                   name + ": the same numbers of rows and columns");
    testing::check(fast->NumMyNonzeros() == E.NumMyNonzeros() && fast->NumMyDiagonals() == E.NumMyDiagonals() &&
                     fast->MaxNumEntries() == E.MaxNumEntries(),
                   name + ": the same numbers of entries (" + std::to_string(E.NumMyNonzeros()) + "), diagonals (" +
                     std::to_string(E.NumMyDiagonals()) + ") and longest row");
    testing::check(fast->RowMap().SameAs(E.RowMap()) && fast->DomainMap().SameAs(E.DomainMap()) &&
                     fast->RangeMap().SameAs(E.RangeMap()),
                   name + ": the same maps");
    bool         same_rows = true;
    unsigned int zeros     = 0;
    for (int i = 0; i < E.NumMyRows(); ++i)
      {
        int     la = 0, lb = 0;
        double *va = nullptr, *vb = nullptr;
        int    *ca = nullptr, *cb = nullptr;
        fast->ExtractMyRowView(i, la, va, ca);
        E.ExtractMyRowView(i, lb, vb, cb);
        same_rows = same_rows && la == lb;
        for (int k = 0; same_rows && k < la; ++k)
          {
            same_rows = fast->GCID(ca[k]) == E.GCID(cb[k]) && va[k] == vb[k];
            zeros += (va[k] == 0.);
          }
      }
    testing::check(same_rows, name + ": every row has the same columns in the same order and the same values");
    if (m > 1)
      testing::check(zeros > 0,
                     name + ": entries below the drop tolerance are kept as zeros (" + std::to_string(zeros) + ")");

    Epetra_Vector x(fast->DomainMap()), y_fast(fast->RangeMap()), y_ref(E.RangeMap());
    for (int j = 0; j < x.MyLength(); ++j)
      x[j] = std::sin(0.37 * j + 1.);
    fast->Multiply(false, x, y_fast);
    E.Multiply(false, x, y_ref);
    bool same_product = true;
    for (int i = 0; i < y_ref.MyLength(); ++i)
      same_product = same_product && y_fast[i] == y_ref[i];
    testing::check(same_product, name + ": the products with a vector agree bit for bit");

    dealii::TrilinosWrappers::SparseMatrix copied;
    internal::copy_to_trilinos(A, copied, drop);
    dealii::Vector<double> u(n), v(m), w(m);
    for (unsigned int j = 0; j < n; ++j)
      u[j] = std::cos(0.11 * j);
    copied.vmult(v, u);
    reference.vmult(w, u);
    v -= w;
    testing::check(v.linfty_norm() == 0., name + ": copy_to_trilinos() multiplies as deal.II's copy");

    if (m == n)
      {
        dealii::TrilinosWrappers::PreconditionAMG amg_fast, amg_ref;
        amg_fast.initialize(copied);
        amg_ref.initialize(reference);
        dealii::Vector<double> r(m), s(m);
        amg_fast.vmult(r, u);
        amg_ref.vmult(s, u);
        r -= s;
        testing::check_small(r.linfty_norm() / std::max(s.linfty_norm(), 1e-300), 1e-14,
                             name + ": an ML V-cycle on either copy, relative difference");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare(700, 700, "square 700");
  compare(300, 120, "rectangular 300 x 120");
  compare(1, 1, "square 1");
  return testing::finish();
}
