// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The symmetric two-level V-cycle of the p-multigrid preconditioner, shared
// by the serial LinearSolver (dealii::Vector) and ParallelLinearSolver
// (TrilinosWrappers::MPI::Vector). Internal to the library (not installed).
#ifndef dealvem_source_solvers_two_level_cycle_h
#define dealvem_source_solvers_two_level_cycle_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <dealvem/solvers/linear_solver.h>

#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

class Epetra_CrsMatrix;

namespace dealvem
{
  namespace internal
  {
    /**
     * An Epetra copy of @p A on one process (MPI_COMM_SELF; rows and
     * columns numbered as in @p A, square or not): every entry of the
     * pattern of @p A, those of magnitude at most @p drop_tolerance as
     * zeros, which is the matrix dealii::TrilinosWrappers::SparseMatrix::
     * reinit() makes of a deal.II matrix with that drop tolerance. Written
     * row by row with local indices in ascending order, without the
     * global-index look-ups and the sorting of that reinit() (measured:
     * a one-body set-up of 27k DoFs 0.069 -> 0.055 s; no difference above
     * the noise at 2.3e5 DoFs).
     */
    std::unique_ptr<Epetra_CrsMatrix>
    epetra_copy(const dealii::SparseMatrix<double> &A, double drop_tolerance);

    /**
     * An Epetra matrix on one process with @p m rows and @p n columns
     * whose compressed rows are written in place: row i has
     * @p lengths[i] entries, which @p fill(i, columns, values) writes in
     * ascending column order (local indices are the global ones). No
     * insertion per row and no sorting or storage optimization by
     * FillComplete(): the arrays are Epetra's own (its expert interface).
     */
    std::unique_ptr<Epetra_CrsMatrix>
    epetra_from_rows(unsigned int                                              m,
                     unsigned int                                              n,
                     const std::vector<int>                                   &lengths,
                     const std::function<void(unsigned int, int *, double *)> &fill);

    /// @p At made the matrix of epetra_copy() (the fast equivalent of
    /// At.reinit(A, drop_tolerance)).
    void
    copy_to_trilinos(const dealii::SparseMatrix<double>     &A,
                     dealii::TrilinosWrappers::SparseMatrix &At,
                     double                                  drop_tolerance = 1e-13);

    inline void
    reinit_like(dealii::Vector<double> &v, const dealii::IndexSet &owned, const MPI_Comm)
    {
      v.reinit(owned.size());
    }

    inline void
    reinit_like(dealii::TrilinosWrappers::MPI::Vector &v, const dealii::IndexSet &owned, const MPI_Comm comm)
    {
      v.reinit(owned, comm);
    }

    /// Throw unless every coarse mode has one entry per column of @p P.
    inline void
    check_coarse_space(const dealii::SparseMatrix<double> &P, const std::vector<std::vector<double>> &modes)
    {
      for (const auto &mode : modes)
        AssertThrow(mode.size() == P.n(), dealii::ExcMessage("set_coarse_space: a coarse mode has " +
                                                             std::to_string(mode.size()) + " entries, P has " +
                                                             std::to_string(P.n()) + " columns."));
    }

    /**
     * The prolongation @p P (fine DoFs x coarse DoFs) made to fit a matrix
     * whose rows flagged @p decoupled carry no coupling (constrained DoFs,
     * condensed as AffineConstraints::condense() leaves them: the diagonal
     * only), written into @p Pc on the new pattern @p sparsity.
     *
     * A decoupled fine DoF that is the copy of one coarse DoF (a vertex
     * value) keeps that coarse DoF as a decoupled coarse DoF of its own (the
     * unit vector at the fine DoF), so that the result has full column
     * rank. Where such a fine DoF is constrained by a line of @p lines (may
     * be null) whose other DoFs are vertex values too, the constraint is
     * carried to the coarse level: every other fine row that P interpolates
     * from that coarse DoF is interpolated from the coarse copies of the
     * line's DoFs instead, with the line's weights. A contact constraint
     * between two vertices of two bodies then ties the coarse functions of
     * the two bodies as it ties the fine ones, and the coarse space spans
     * the motions of the bodies together (without @p lines, or for other
     * decoupled DoFs such as Dirichlet values, coarse functions vanish at
     * the decoupled DoF, and the coarse space of a body in contact behaves
     * as if clamped along the interface). Decoupled fine DoFs that are not
     * vertex copies (edge nodes) get empty rows.
     */
    void
    restrict_prolongation(const dealii::SparseMatrix<double>      &P,
                          const std::vector<bool>                 &decoupled,
                          const dealii::AffineConstraints<double> *lines,
                          dealii::SparsityPattern                 &sparsity,
                          dealii::SparseMatrix<double>            &Pc);

    /**
     * The values of the matrix @p A of one process in single precision, in
     * the order of its Epetra storage, with pointers to that storage's row
     * offsets and (local = global) column indices: a CSR matrix of 8 bytes
     * per entry instead of 12 that shares A's indices. Returns false, with
     * @p values null, where A's storage is not one contiguous block or its
     * columns are not numbered as its rows.
     */
    bool
    single_precision_values(const dealii::TrilinosWrappers::SparseMatrix &A,
                            const int                                   *&offsets,
                            const int                                   *&indices,
                            std::unique_ptr<float[]>                     &values);

    template <typename VectorType>
    class TwoLevelCycle;

    /**
     * The serial two-level cycle on @p A (its Trilinos copy @p At, which
     * must outlive the result): the prolongation @p P restricted to the
     * decoupled rows of @p A with restrict_prolongation() (constraint lines
     * @p lines, may be null), its Trilinos copy written into @p Pt, and the
     * cycle with @p settings. Used by LinearSolver and by
     * SaddlePointSolver's condensed contact solves.
     */
    std::unique_ptr<TwoLevelCycle<dealii::Vector<double>>>
    make_serial_two_level(const dealii::SparseMatrix<double>           &A,
                          const dealii::TrilinosWrappers::SparseMatrix &At,
                          const dealii::SparseMatrix<double>           &P,
                          const std::vector<std::vector<double>>       &coarse_modes,
                          const dealii::AffineConstraints<double>      *lines,
                          const LinearSolver::Settings                 &settings,
                          dealii::TrilinosWrappers::SparseMatrix       &Pt);

    /// make_serial_two_level() with the decoupled rows (those without an
    /// off-diagonal nonzero) given instead of read from a deal.II matrix.
    std::unique_ptr<TwoLevelCycle<dealii::Vector<double>>>
    make_serial_two_level(const std::vector<bool>                      &decoupled,
                          const dealii::TrilinosWrappers::SparseMatrix &At,
                          const dealii::SparseMatrix<double>           &P,
                          const std::vector<std::vector<double>>       &coarse_modes,
                          const dealii::AffineConstraints<double>      *lines,
                          const LinearSolver::Settings                 &settings,
                          dealii::TrilinosWrappers::SparseMatrix       &Pt);

    /**
     * The distributed two-level cycle on @p A: the prolongation @p P (all
     * rows, on every process) restricted to the decoupled rows of @p A with
     * restrict_prolongation() (constraint lines @p lines, may be null), as
     * a distributed Trilinos matrix in @p Pt (owned fine rows; each coarse
     * DoF owned with the fine vertex DoF it copies; @p Pt must outlive the
     * result), and the cycle with @p settings on @p comm. Used by
     * ParallelLinearSolver and by the stick-penalty preconditioner of
     * DistributedContactSolver.
     */
    std::unique_ptr<TwoLevelCycle<dealii::TrilinosWrappers::MPI::Vector>>
    make_distributed_two_level(const dealii::TrilinosWrappers::SparseMatrix &A,
                               const dealii::SparseMatrix<double>           &P,
                               const std::vector<std::vector<double>>       &coarse_modes,
                               const dealii::AffineConstraints<double>      *lines,
                               const LinearSolver::Settings                 &settings,
                               const MPI_Comm                                comm,
                               dealii::TrilinosWrappers::SparseMatrix       &Pt);

    /// The inverse diagonal around which the Chebyshev smoother works:
    /// deal.II's DiagonalMatrix for serial vectors (PreconditionChebyshev
    /// has a fused update for it), a plain scaling for Trilinos vectors
    /// (DiagonalMatrix's set-up there is written for serial vectors only).
    template <typename VectorType>
    class InverseDiagonal
    {
    public:
      VectorType &
      get_vector()
      {
        return diagonal;
      }

      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        dst = src;
        dst.scale(diagonal);
      }

    private:
      VectorType diagonal;
    };

    template <typename VectorType>
    struct SmootherDiagonal
    {
      using type = InverseDiagonal<VectorType>;
    };

    template <>
    struct SmootherDiagonal<dealii::Vector<double>>
    {
      using type = dealii::DiagonalMatrix<dealii::Vector<double>>;
    };

    /**
     * x = S b, then x += P C^{-1} P^T (b - A x), then x += S (b - A x), with
     * S the Chebyshev smoother around the inverse diagonal and C^{-1} one ML
     * V-cycle on the Galerkin operator C = P^T A P. Per application:
     * 2 (degree - 1) products with A in the smoother, one for the first
     * residual, one with AP for the second.
     *
     * @p A and @p P are Trilinos matrices with the same row map; P's domain
     * map is the coarse space's (on several processes, the coarse DoFs each
     * process owns). @p local_coarse_modes are the coarse rigid-body modes
     * at the locally owned coarse DoFs, in increasing global order.
     */
    template <typename VectorType>
    class TwoLevelCycle
    {
    public:
      using Diagonal = typename SmootherDiagonal<VectorType>::type;
      /// One process: the smoother reads a single-precision copy of A
      /// (LinearSolver::Settings::single_precision_smoother) or the Trilinos
      /// matrix, through SmoothingMatrix; several: the Trilinos matrix.
      static constexpr bool serial = std::is_same_v<VectorType, dealii::Vector<double>>;

      /// The fine-level matrix of the smoother and of the residual the
      /// coarse level gets: A itself, or its single-precision copy.
      class SmoothingMatrix : public dealii::Subscriptor
      {
      public:
        const dealii::TrilinosWrappers::SparseMatrix *full = nullptr;
        /// The single-precision CSR matrix (values null: not used).
        const int               *offsets = nullptr, *indices = nullptr;
        std::unique_ptr<float[]> values;

        void
        vmult(VectorType &dst, const VectorType &src) const
        {
          if constexpr (serial)
            if (values)
              {
                const unsigned int m = dst.size();
                const double      *x = src.begin();
                double            *y = dst.begin();
                for (unsigned int i = 0; i < m; ++i)
                  {
                    double sum = 0;
                    for (int k = offsets[i], end = offsets[i + 1]; k < end; ++k)
                      sum += values[k] * x[indices[k]];
                    y[i] = sum;
                  }
                return;
              }
          full->vmult(dst, src);
        }

        void
        Tvmult(VectorType &dst, const VectorType &src) const
        {
          if constexpr (serial)
            if (values)
              {
                const unsigned int m = src.size();
                const double      *x = src.begin();
                dst                  = 0.;
                double *y            = dst.begin();
                for (unsigned int i = 0; i < m; ++i)
                  for (int k = offsets[i], end = offsets[i + 1]; k < end; ++k)
                    y[indices[k]] += values[k] * x[i];
                return;
              }
          full->Tvmult(dst, src);
        }

        dealii::types::global_dof_index
        m() const
        {
          return full->m();
        }

        dealii::types::global_dof_index
        n() const
        {
          return full->n();
        }

        double
        el(const dealii::types::global_dof_index i, const dealii::types::global_dof_index j) const
        {
          return full->el(i, j);
        }
      };
      using Smoother = dealii::PreconditionChebyshev<SmoothingMatrix, VectorType, Diagonal>;

      TwoLevelCycle(const dealii::TrilinosWrappers::SparseMatrix &A,
                    const dealii::TrilinosWrappers::SparseMatrix &P,
                    const std::vector<std::vector<double>>       &local_coarse_modes,
                    const LinearSolver::Settings                 &settings,
                    const MPI_Comm                                comm)
        : A(A)
        , P(P)
      {
        AssertThrow(settings.smoother_degree >= 1 && settings.smoothing_range > 1,
                    dealii::ExcMessage("p-multigrid: the smoother degree must be >= 1 and the smoothing "
                                       "range > 1."));
        const dealii::IndexSet fine   = A.locally_owned_range_indices();
        const dealii::IndexSet coarse = P.locally_owned_domain_indices();

        // Galerkin coarse operator P^T A P
        A.mmult(AP, P);
        P.Tmmult(coarse_matrix, AP);
        set_ml_parameters(&list, local_coarse_modes, coarse.n_elements(), storage, settings.amg);
        coarse_amg.initialize(coarse_matrix.trilinos_matrix(), list);

        // Chebyshev smoother around the inverse diagonal
        typename Smoother::AdditionalData data;
        data.degree              = settings.smoother_degree;
        data.smoothing_range     = settings.smoothing_range;
        data.eig_cg_n_iterations = 12;
        data.preconditioner      = std::make_shared<Diagonal>();
        VectorType &inverse_diagonal = data.preconditioner->get_vector();
        reinit_like(inverse_diagonal, fine, comm);
        for (const auto i : fine)
          {
            const double d = A.diag_element(i);
            AssertThrow(d > 0, dealii::ExcMessage("p-multigrid: the diagonal entry " + std::to_string(i) +
                                                  " is not positive (" + std::to_string(d) +
                                                  "): the matrix is not positive definite."));
            inverse_diagonal(i) = 1. / d;
          }
        inverse_diagonal.compress(dealii::VectorOperation::insert);
        smoothing_matrix.full = &A;
        if constexpr (serial)
          if (settings.single_precision_smoother)
            single_precision_values(A, smoothing_matrix.offsets, smoothing_matrix.indices, smoothing_matrix.values);
        smoother.initialize(smoothing_matrix, data);
        reinit_like(r, fine, comm);
        reinit_like(e, fine, comm);
        reinit_like(rc, coarse, comm);
        reinit_like(ec, coarse, comm);
      }

      void
      vmult(VectorType &x, const VectorType &b) const
      {
        smoother.vmult(x, b);
        smoothing_matrix.vmult(r, x);
        r.sadd(-1., 1., b);
        P.Tvmult(rc, r);
        coarse_amg.vmult(ec, rc);
        P.vmult(e, ec);
        x += e;
        // the new residual r - A P ec, with the product AP kept from the
        // setup (about half the nonzeros of A: coarse columns only)
        AP.vmult(e, ec);
        r -= e;
        smoother.vmult(e, r);
        x += e;
      }

    private:
      const dealii::TrilinosWrappers::SparseMatrix &A;
      const dealii::TrilinosWrappers::SparseMatrix &P;
      dealii::TrilinosWrappers::SparseMatrix        AP, coarse_matrix;
      Teuchos::ParameterList                        list;
      std::vector<double>                           storage;
      dealii::TrilinosWrappers::PreconditionAMG     coarse_amg;
      // (declared before the smoother, which refers to it)
      SmoothingMatrix                               smoothing_matrix;
      Smoother                                      smoother;
      mutable VectorType                            r, e, rc, ec;
    };
  } // namespace internal
} // namespace dealvem

#endif
