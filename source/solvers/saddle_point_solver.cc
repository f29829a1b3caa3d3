// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/block_linear_operator.h>
#include <deal.II/lac/block_sparse_matrix.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/block_vector.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/linear_operator.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <dealvem/solvers/contact_constraints.h>
#include <dealvem/solvers/linear_solver.h>
#include <dealvem/solvers/saddle_point_solver.h>

#include "sparse_cholesky.h"
#include "two_level_cycle.h"

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <Teuchos_ParameterList.hpp>
#include <ml_MultiLevelPreconditioner.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>

namespace dealvem
{
  SaddlePointSolver::Type
  SaddlePointSolver::parse_type(const std::string &name)
  {
    const std::string n = internal::upper_case(name);
    if (n == "UMFPACK")
      return Type::umfpack;
    if (n == "KLU")
      return Type::klu;
    if (n == "GMRES-AMG")
      return Type::gmres_amg;
    if (n == "CG-AMG CONSTRAINTS" || n == "CG-AMG")
      return Type::cg_amg_constraints;
    if (n == "DIRECT CONSTRAINTS")
      return Type::direct_constraints;
    AssertThrow(false, dealii::ExcMessage("Unknown contact solver '" + name +
                                          "': expected UMFPACK, KLU, GMRES-AMG, CG-AMG or direct constraints."));
    return Type::umfpack;
  }



  std::string
  SaddlePointSolver::type_name(const Type t)
  {
    switch (t)
      {
        case Type::umfpack:
          return "UMFPACK";
        case Type::klu:
          return "KLU";
        case Type::cg_amg_constraints:
          return "CG-AMG";
        case Type::direct_constraints:
          return "direct constraints";
        default:
          return "GMRES-AMG";
      }
  }



  SaddlePointSolver::SaddlePointSolver(const Settings &settings)
    : settings(settings)
  {
    AssertThrow(settings.amg_reuse_fraction >= 0 && settings.amg_reuse_fraction <= 1,
                dealii::ExcMessage("SaddlePointSolver: the AMG reuse fraction must lie in [0, 1], not " +
                                   std::to_string(settings.amg_reuse_fraction) + "."));
    AssertThrow(settings.inexact_tolerance >= 0 && settings.inexact_tolerance < 1,
                dealii::ExcMessage("SaddlePointSolver: the inexact tolerance must lie in [0, 1), not " +
                                   std::to_string(settings.inexact_tolerance) + "."));
    AssertThrow(settings.inexact_start_tolerance >= 0 && settings.inexact_start_tolerance < 1,
                dealii::ExcMessage("SaddlePointSolver: the inexact start tolerance must lie in [0, 1), not " +
                                   std::to_string(settings.inexact_start_tolerance) + "."));
    // (Trilinos calls MPI: without MPI_Init the process aborts inside
    // Epetra with MPI's own message, far from the cause)
    const bool trilinos = settings.type == Type::gmres_amg || settings.type == Type::cg_amg_constraints ||
                          settings.type == Type::klu;
    AssertThrow(!trilinos || dealii::Utilities::MPI::job_supports_mpi(),
                dealii::ExcMessage("SaddlePointSolver: Solver/Type = " + type_name(settings.type) +
                                   " uses Trilinos (Epetra, ML, Amesos), which needs MPI to be initialized: create a "
                                   "dealii::Utilities::MPI::MPI_InitFinalize object at the start of main() "
                                   "(as every dealvem program and tutorial does), or choose a direct solver."));
  }



  void
  SaddlePointSolver::set_near_null_space(const std::vector<std::vector<double>> &m)
  {
    modes = m;
  }



  void
  SaddlePointSolver::set_coarse_space(const dealii::SparseMatrix<double>     &P,
                                      const std::vector<std::vector<double>> &m)
  {
    internal::check_coarse_space(P, m);
    coarse_prolongation = &P;
    coarse_modes        = m;
  }



  void
  SaddlePointSolver::set_stick_directions(const std::vector<std::vector<std::pair<unsigned int, double>>> &rows)
  {
    stick_rows = rows;
  }



  std::string
  SaddlePointSolver::description() const
  {
    const auto seconds = [](const double s) {
      std::ostringstream o;
      o.precision(3);
      o << s << " s";
      return o.str();
    };
    if (settings.type == Type::gmres_amg)
      return "GMRES + block preconditioner (ML AMG on K + rho B^T B, exact approximate Schur complement)";
    if (settings.type == Type::cg_amg_constraints)
      return std::string(used_gmres ? "GMRES" : "CG") +
             (uses_p_multigrid() ? std::string(" + p-multigrid (Chebyshev on k = 2, ML AMG on the k = 1 level with the "
                                               "contact constraints of the vertices)") :
                                   std::string(" + ML AMG")) +
             " on the stiffness condensed by the active contact constraints (one slave DoF per "
             "constraint, multipliers from the residual" +
             std::string(used_gmres ? "; slipping pairs: Petrov-Galerkin condensation, not symmetric" : "") +
             std::string(used_stick_preconditioner ? "; stick springs preconditioned by tying them" : "") +
             (n_amg_setups > 0 ? "; AMG set up " + std::to_string(n_amg_setups) + " time(s) in " +
                                   seconds(amg_setup_seconds) + ", reused " +
                                   std::to_string(n_amg_reuses) + " time(s) for an unchanged matrix, " +
                                   std::to_string(n_amg_corrections) +
                                   " time(s) corrected on the rows that changed" +
                                   (n_amg_slow_corrections > 0 ? " (" + std::to_string(n_amg_slow_corrections) +
                                                                   " of them set up again, too slow)" :
                                                                 "") :
                                 "") +
             ")";
    if (settings.type == Type::direct_constraints)
      return std::string(used_gmres       ? "UMFPACK LU (slipping pairs: the condensed matrix is not symmetric)" :
                         used_lu_fallback ? "UMFPACK LU (the condensed matrix is not positive definite)" :
                                            "CHOLMOD Cholesky") +
             " of the stiffness condensed by the active contact constraints (one slave DoF per constraint, "
             "multipliers from the residual" +
             (n_factorization_reuses > 0 ? "; " + std::to_string(n_factorizations) + " factorization(s), " +
                                             std::to_string(n_factorization_reuses) +
                                             " solve(s) with the factorization of an unchanged matrix" :
                                           "") +
             (cholesky && cholesky->n_reused_analyses > 0 ?
                "; " + std::to_string(cholesky->n_reused_analyses) +
                  " factorization(s) with the ordering of the last pattern" :
                "") +
             ")";
    return type_name(settings.type) + " (direct, whole saddle-point matrix)";
  }



  namespace
  {
    // Throw if @p u holds a non-finite value (after every solve and every
    // continuation; the only check of an inexact solution, whose residual
    // is not checked).
    void
    check_finite(const dealii::Vector<double> &u)
    {
      for (const double v : u)
        AssertThrow(std::isfinite(v), dealii::ExcMessage("The saddle-point solver produced a non-finite value: the "
                                                         "system is singular (is every body supported?)."));
    }



    // The saddle-point matrix [K B^T; B D] as deal.II's 2 x 2 block matrix,
    // the first block the displacements, the second the multipliers.
    void
    split_into_blocks(const dealii::SparseMatrix<double> &A,
                      const unsigned int                  n,
                      dealii::BlockSparsityPattern       &pattern,
                      dealii::BlockSparseMatrix<double>  &blocks)
    {
      const unsigned int                  m = A.m() - n;
      dealii::BlockDynamicSparsityPattern dsp(std::vector<dealii::types::global_dof_index>{n, m},
                                              std::vector<dealii::types::global_dof_index>{n, m});
      for (unsigned int i = 0; i < A.m(); ++i)
        for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it)
          dsp.add(i, it->column());
      pattern.copy_from(dsp);
      blocks.reinit(pattern);
      for (unsigned int i = 0; i < A.m(); ++i)
        for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it)
          blocks.set(i, it->column(), it->value());
    }



    // C = first + factor * second, on the union of the two patterns.
    void
    add_matrices(const dealii::SparseMatrix<double> &first,
                 const dealii::SparseMatrix<double> &second,
                 const double                        factor,
                 dealii::SparsityPattern            &pattern,
                 dealii::SparseMatrix<double>       &C)
    {
      dealii::DynamicSparsityPattern dsp(first.m(), first.n());
      for (const auto *M : {&first, &second})
        for (unsigned int i = 0; i < M->m(); ++i)
          for (auto it = M->begin(i), it_end = M->end(i); it != it_end; ++it)
            dsp.add(i, it->column());
      for (unsigned int i = 0; i < first.m(); ++i)
        dsp.add(i, i);
      pattern.copy_from(dsp);
      C.reinit(pattern);
      for (unsigned int i = 0; i < first.m(); ++i)
        {
          for (auto it = first.begin(i), it_end = first.end(i); it != it_end; ++it)
            C.add(i, it->column(), it->value());
          for (auto it = second.begin(i), it_end = second.end(i); it != it_end; ++it)
            C.add(i, it->column(), factor * it->value());
        }
    }



    // Block lower-triangular preconditioner of the saddle-point matrix,
    //   P^{-1} = [K_rho, 0; B, S]^{-1},
    // with K_rho = K + rho B^T B approximated by one ML AMG cycle and
    // S = D - B diag(K_rho)^{-1} B^T factorised by UMFPACK. The blocks come
    // from the BlockSparseMatrix, the products from SparseMatrix::mmult, and
    // the forward substitution is deal.II's block_forward_substitution.
    class BlockPreconditioner
    {
    public:
      BlockPreconditioner(const dealii::BlockSparseMatrix<double> &A,
                          const std::vector<std::vector<double>>  &modes)
      {
        const auto &K  = A.block(0, 0);
        const auto &Bt = A.block(0, 1);
        const auto &B  = A.block(1, 0);
        const auto &D  = A.block(1, 1);

        // rho: the mean absolute diagonal of K, so that both terms of K_rho
        // have the same scale
        double rho = 0;
        for (unsigned int i = 0; i < K.m(); ++i)
          rho += std::abs(K.diag_element(i));
        rho = (K.m() > 0 && rho > 0 ? rho / K.m() : 1.);

        dealii::SparsityPattern      sp_btb, sp_bdb;
        dealii::SparseMatrix<double> BtB, BDB;
        // mmult rebuilds the pattern the product matrix is attached to
        BtB.reinit(sp_btb);
        BDB.reinit(sp_bdb);
        Bt.mmult(BtB, B, dealii::Vector<double>(), true);
        add_matrices(K, BtB, rho, sp_k, K_rho);

        dealii::Vector<double> inverse_diagonal(K_rho.m());
        for (unsigned int i = 0; i < K_rho.m(); ++i)
          inverse_diagonal[i] = 1. / K_rho.diag_element(i);
        B.mmult(BDB, Bt, inverse_diagonal, true);
        add_matrices(D, BDB, -1., sp_s, S);
        S_inverse.initialize(S);

        // AMG on K_rho with the rigid-body modes
        internal::copy_to_trilinos(K_rho, K_trilinos);
        Teuchos::ParameterList list;
        internal::set_ml_parameters(&list, modes, K_rho.m(), null_space);
        amg.initialize(K_trilinos.trilinos_matrix(), list);
      }

      // The preconditioner as a LinearOperator on block vectors.
      dealii::LinearOperator<dealii::BlockVector<double>>
      linear_operator(const dealii::BlockSparseMatrix<double> &A) const
      {
        using Op                = dealii::LinearOperator<dealii::Vector<double>>;
        const Op         K_inv = dealii::linear_operator<dealii::Vector<double>>(K_rho, amg);
        const Op         S_inv = dealii::linear_operator<dealii::Vector<double>>(S, S_inverse);
        const auto       diagonal =
          dealii::block_diagonal_operator<2, dealii::BlockVector<double>>(std::array<Op, 2>{{K_inv, S_inv}});
        return dealii::block_forward_substitution(dealii::block_operator(A), diagonal);
      }

    private:
      dealii::SparsityPattern                   sp_k, sp_s;
      dealii::SparseMatrix<double>              K_rho, S;
      dealii::SparseDirectUMFPACK               S_inverse;
      dealii::TrilinosWrappers::SparseMatrix    K_trilinos;
      dealii::TrilinosWrappers::PreconditionAMG amg;
      std::vector<double>                       null_space;
    };

  } // namespace



  namespace internal
  {
    /**
     * A condensed contact stiffness on one process as the iterative solvers
     * read it: a deal.II matrix (condensed for the stick-spring, slip and
     * direct paths) or a Trilinos one (ContactConstraints::condense() into
     * Trilinos, for CG on a symmetric problem: the p-multigrid or ML then
     * works on that matrix itself, and no deal.II copy exists). Rows are
     * visited in ascending column order in both, so that the fingerprints
     * of the AMG cache agree between them. A Trilinos matrix is shared:
     * the cache keeps the one its hierarchy was built on alive.
     */
    class CondensedMatrix
    {
    public:
      /// None (id() is null).
      CondensedMatrix() = default;

      explicit CondensedMatrix(const dealii::SparseMatrix<double> &K)
        : deal_ii(&K)
      {}

      explicit CondensedMatrix(std::shared_ptr<const dealii::TrilinosWrappers::SparseMatrix> K)
        : trilinos(std::move(K))
        , epetra(&trilinos->trilinos_matrix())
      {}

      explicit CondensedMatrix(std::shared_ptr<const CondensedRows> K)
        : rows(std::move(K))
      {}

      /// The matrix it refers to (for identity comparisons).
      const void *
      id() const
      {
        if (rows != nullptr)
          return rows.get();
        return (deal_ii != nullptr ? static_cast<const void *>(deal_ii) : static_cast<const void *>(trilinos.get()));
      }

      unsigned int
      m() const
      {
        if (rows != nullptr)
          return rows->m();
        return (deal_ii != nullptr ? deal_ii->m() : trilinos->m());
      }

      unsigned int
      row_length(const unsigned int i) const
      {
        if (rows != nullptr)
          return rows->row_length(i);
        return (deal_ii != nullptr ? deal_ii->get_sparsity_pattern().row_length(i)
                                   : static_cast<unsigned int>(epetra->NumMyEntries(static_cast<int>(i))));
      }

      /// f(column, value) for the entries of row @p i, columns ascending.
      template <typename F>
      void
      for_row(const unsigned int i, F &&f) const
      {
        if (rows != nullptr)
          {
            rows->for_row(i, f);
            return;
          }
        if (deal_ii == nullptr)
          {
            int     n       = 0;
            double *values  = nullptr;
            int    *columns = nullptr;
            epetra->ExtractMyRowView(static_cast<int>(i), n, values, columns);
            for (int k = 0; k < n; ++k)
              f(static_cast<unsigned int>(columns[k]), values[k]);
            return;
          }
        // deal.II lists the diagonal of a square matrix first
        const auto &sp    = deal_ii->get_sparsity_pattern();
        auto        value = deal_ii->begin(i);
        auto        it = sp.begin(i), end = sp.end(i);
        if (it == end)
          return;
        const double diagonal     = value->value();
        bool         diagonal_out = false;
        for (++it, ++value; it != end; ++it, ++value)
          {
            const unsigned int j = it->column();
            if (!diagonal_out && j > i)
              {
                f(i, diagonal);
                diagonal_out = true;
              }
            f(j, value->value());
          }
        if (!diagonal_out)
          f(i, diagonal);
      }

      double
      diag_element(const unsigned int i) const
      {
        if (rows != nullptr)
          return rows->diag_element(i);
        return (deal_ii != nullptr ? deal_ii->diag_element(i) : trilinos->diag_element(i));
      }

      void
      vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const
      {
        if (deal_ii != nullptr)
          deal_ii->vmult(dst, src);
        else if (rows != nullptr)
          rows->vmult(dst, src);
        else
          trilinos->vmult(dst, src);
      }

      /// @p r = @p b - K @p x; returns its l2 norm.
      double
      residual(dealii::Vector<double> &r, const dealii::Vector<double> &x, const dealii::Vector<double> &b) const
      {
        if (deal_ii != nullptr)
          return deal_ii->residual(r, x, b);
        vmult(r, x);
        r.sadd(-1., 1., b);
        return r.l2_norm();
      }

      /// The deal.II matrix (null: another kind).
      const dealii::SparseMatrix<double> *deal_ii = nullptr;
      /// The rows that refer to the saddle-point matrix (null: another kind).
      std::shared_ptr<const CondensedRows> rows;
      /// The Trilinos matrix (null: a deal.II one), and its Epetra matrix.
      std::shared_ptr<const dealii::TrilinosWrappers::SparseMatrix> trilinos;
      const Epetra_CrsMatrix                                       *epetra = nullptr;
    };



    /// check_residual() of K u = f for either kind of condensed matrix.
    double
    check_condensed_residual(const CondensedMatrix        &K,
                             const dealii::Vector<double> &u,
                             const dealii::Vector<double> &f,
                             const double                  relative_tolerance,
                             const std::string            &solver)
    {
      if (K.deal_ii != nullptr)
        return check_residual(*K.deal_ii, u, f, relative_tolerance, solver);
      dealii::Vector<double> r(f.size());
      K.residual(r, u, f);
      return check_residual(r, u, f, relative_tolerance, solver, [&K]() {
        double norm = 0;
        for (unsigned int i = 0; i < K.m(); ++i)
          {
            double row = 0;
            K.for_row(i, [&row](unsigned int, const double v) { row += std::abs(v); });
            norm = std::max(norm, row);
          }
        return norm;
      });
    }



    /**
     * The coarse space of the p-multigrid on a condensed contact matrix
     * (SaddlePointSolver::set_coarse_space()): the prolongation, the coarse
     * rigid-body modes and the constraint lines the matrix was condensed
     * with (carried to the coarse level). Null P: none.
     */
    struct CondensedCoarseSpace
    {
      const dealii::SparseMatrix<double>      *P     = nullptr;
      const std::vector<std::vector<double>>  *modes = nullptr;
      const dealii::AffineConstraints<double> *lines = nullptr;
    };

    /**
     * The p-multigrid of LinearSolver on a condensed matrix @p A (its
     * Trilinos copy @p At, which must outlive the result): the prolongation
     * restricted to the decoupled rows of @p A with the constraints of
     * @p coarse carried to the coarse level, its Trilinos copy in @p Pt,
     * and the shared two-level cycle with LinearSolver's default settings
     * (Chebyshev degree 3, one ML V-cycle on the coarse level).
     */
    std::unique_ptr<TwoLevelCycle<dealii::Vector<double>>>
    make_condensed_two_level(const dealii::SparseMatrix<double>           &A,
                             const dealii::TrilinosWrappers::SparseMatrix &At,
                             const CondensedCoarseSpace                   &coarse,
                             dealii::TrilinosWrappers::SparseMatrix       &Pt)
    {
      return make_serial_two_level(A, At, *coarse.P, *coarse.modes, coarse.lines, LinearSolver::Settings(), Pt);
    }
  } // namespace internal



  namespace
  {
    /**
     * Z^T K Z for the closed homogeneous lines @p Z, written straight into
     * an Epetra matrix on one process (the fast path of epetra_copy(): rows
     * in ascending column order, entries of magnitude at most
     * @p drop_tolerance kept as zeros), as AffineConstraints::condense()
     * would leave it: a slave's row and column are zero but for the
     * diagonal, which gets the mean magnitude of K's diagonal; a slave's
     * couplings go to its masters with the line's weights. Only the rows of
     * slaves, of their masters and of the DoFs coupled to a slave differ
     * from K's; the others are copied as they are, so that no condensed
     * deal.II matrix of the full size is made on the way (at 1e6 DoFs its
     * fresh memory alone cost about as much as the p-multigrid's set-up).
     * @p decoupled flags the rows without an off-diagonal nonzero.
     */
    std::unique_ptr<Epetra_CrsMatrix>
    epetra_tied_copy(const internal::CondensedMatrix         &K,
                     const dealii::AffineConstraints<double> &Z,
                     const double                             drop_tolerance,
                     std::vector<bool>                       &decoupled)
    {
      const unsigned int             n     = K.m();
      constexpr unsigned int         none  = dealii::numbers::invalid_unsigned_int;
      const auto                    &lines = Z.get_lines();
      std::vector<unsigned int>      line_of(n, none);
      for (unsigned int l = 0; l < lines.size(); ++l)
        line_of[lines[l].index] = l;
      // the slaves of each master, with the weights
      std::map<unsigned int, std::vector<std::pair<unsigned int, double>>> slaves_of;
      for (const auto &line : lines)
        for (const auto &e : line.entries)
          {
            AssertThrow(line_of[e.first] == none,
                        dealii::ExcMessage("StickPreconditioner: the tie lines are not closed (DoF " +
                                           std::to_string(e.first) + " is a master and a slave)."));
            slaves_of[e.first].emplace_back(line.index, e.second);
          }
      double mean_diagonal = 0;
      for (unsigned int i = 0; i < n; ++i)
        mean_diagonal += std::abs(K.diag_element(i));
      mean_diagonal /= std::max(n, 1u);

      // the rows that change: computed once, kept until they are inserted
      std::map<unsigned int, std::vector<std::pair<int, double>>> changed;
      std::vector<std::pair<int, double>>                         entries;
      std::vector<int>                                            lengths(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          lengths[i] = static_cast<int>(K.row_length(i));
          if (line_of[i] != none)
            continue;
          const auto master    = slaves_of.find(i);
          bool       has_slave = master != slaves_of.end();
          if (!has_slave)
            K.for_row(i, [&](const unsigned int j, double) { has_slave = has_slave || line_of[j] != none; });
          if (!has_slave)
            continue;
          entries.clear();
          const auto add_row = [&](const unsigned int r, const double weight) {
            K.for_row(r, [&](const unsigned int j, const double value) {
              if (line_of[j] == none)
                entries.emplace_back(static_cast<int>(j), weight * value);
              else
                {
                  entries.emplace_back(static_cast<int>(j), 0.);
                  for (const auto &e : lines[line_of[j]].entries)
                    entries.emplace_back(static_cast<int>(e.first), weight * value * e.second);
                }
            });
          };
          add_row(i, 1.);
          if (master != slaves_of.end())
            for (const auto &s : master->second)
              add_row(s.first, s.second);
          std::sort(entries.begin(), entries.end(), [](const auto &x, const auto &y) { return x.first < y.first; });
          auto &row = changed[i];
          for (const auto &e : entries)
            if (!row.empty() && row.back().first == e.first)
              row.back().second += e.second;
            else
              row.push_back(e);
          lengths[i] = static_cast<int>(row.size());
        }

      decoupled.assign(n, true);
      auto next_changed = changed.begin();
      return internal::epetra_from_rows(n, n, lengths, [&](const unsigned int i, int *columns, double *values) {
        int k = 0;
        if (next_changed != changed.end() && next_changed->first == i)
          {
            for (const auto &e : next_changed->second)
              {
                columns[k] = e.first;
                values[k]  = e.second;
                ++k;
              }
            ++next_changed;
          }
        else
          {
            const bool slave = line_of[i] != none;
            K.for_row(i, [&](const unsigned int j, const double value) {
              columns[k] = static_cast<int>(j);
              values[k]  = (!slave ? value : (j == i ? mean_diagonal : 0.));
              ++k;
            });
          }
        for (int e = 0; e < k; ++e)
          {
            if (values[e] != 0. && columns[e] != static_cast<int>(i))
              decoupled[i] = false;
            if (std::abs(values[e]) <= drop_tolerance)
              values[e] = 0.;
          }
      });
    }



    /**
     * The two-subspace preconditioner of the condensed stick-penalty system
     * (see SaddlePointSolver::set_stick_directions()):
     * M^{-1} r = Z AMG(Z^T K Z) Z^T r + sum_s e_s r_s / K_ss.
     */
    class StickPreconditioner
    {
    public:
      StickPreconditioner(const internal::CondensedMatrix                                 &K,
                          const dealii::AffineConstraints<double>                         &normal_lines,
                          const std::vector<std::vector<std::pair<unsigned int, double>>> &stick_rows,
                          const std::vector<std::vector<double>>                          &modes,
                          const double                                                     length,
                          internal::CondensedCoarseSpace                                   coarse)
      {
        const unsigned int n = K.m();
        const ContactConstraints ties = ContactConstraints::tie_lines(stick_rows, normal_lines, normal_lines, n, length);
        Z.copy_from(ties.get_constraints());
        for (const auto &sl : ties.get_slaves())
          {
            slaves.push_back(sl.second);
            inverse_diagonal.push_back(1. / K.diag_element(sl.second));
          }

        // Z^T K Z: the springs vanish on tied functions
        std::vector<bool> decoupled;
        tied_trilinos.reinit(*epetra_tied_copy(K, Z, 1e-13, decoupled));
        if (coarse.P != nullptr)
          {
            // the p-multigrid on Z^T K Z, its coarse level tied as K's
            // normal lines and Z's ties together tie the fine one (a normal
            // line may refer to a DoF that a tie line constrains: close()
            // resolves the chain)
            for (const dealii::AffineConstraints<double> *c : {&normal_lines, static_cast<const dealii::AffineConstraints<double> *>(&Z)})
              for (const auto &line : c->get_lines())
                if (!all_lines.is_constrained(line.index))
                  {
                    all_lines.add_line(line.index);
                    all_lines.add_entries(line.index, line.entries);
                  }
            all_lines.close();
            coarse.lines = &all_lines;
            cycle = internal::make_serial_two_level(decoupled, tied_trilinos, *coarse.P, *coarse.modes, &all_lines,
                                                    LinearSolver::Settings(), P_trilinos);
          }
        else
          {
            Teuchos::ParameterList list;
            internal::set_ml_parameters(&list, modes, n, null_space);
            amg.initialize(tied_trilinos.trilinos_matrix(), list);
          }
        w.reinit(n);
        v.reinit(n);
      }

      void
      vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const
      {
        w = src;
        Z.condense(w);
        if (cycle)
          cycle->vmult(v, w);
        else
          amg.vmult(v, w);
        Z.distribute(v);
        dst = v;
        for (std::size_t k = 0; k < slaves.size(); ++k)
          dst[slaves[k]] += src[slaves[k]] * inverse_diagonal[k];
      }

      unsigned int
      n_ties() const
      {
        return slaves.size();
      }

    private:
      dealii::AffineConstraints<double>         Z, all_lines;
      /// The tied DoFs and the inverses of their diagonal entries in K.
      std::vector<unsigned int>                                        slaves;
      std::vector<double>                                              inverse_diagonal;
      dealii::TrilinosWrappers::SparseMatrix    tied_trilinos, P_trilinos;
      std::vector<double>                       null_space;
      dealii::TrilinosWrappers::PreconditionAMG amg;
      std::unique_ptr<internal::TwoLevelCycle<dealii::Vector<double>>> cycle;
      mutable dealii::Vector<double>            w, v;
    };

    // CG (GMRES with @p gmres, when slipping pairs make the condensed
    // matrix non-symmetric) on K u = f with the preconditioner of the stick
    // springs, from u, down to the residual @p target; returns the
    // iterations. @p where completes the message of a solve that does not
    // converge.
    unsigned int
    solve_with_stick(const internal::CondensedMatrix &K,
                     dealii::Vector<double>          &u,
                     const dealii::Vector<double>    &f,
                     const StickPreconditioner       &stick,
                     const double                     target,
                     const unsigned int               max_iterations,
                     const bool                       gmres,
                     const std::string               &where)
    {
      dealii::SolverControl control(max_iterations, target);
      try
        {
          if (gmres)
            {
              dealii::SolverGMRES<dealii::Vector<double>>::AdditionalData data(200, true);
              dealii::SolverGMRES<dealii::Vector<double>>                 solver(control, data);
              solver.solve(K, u, f, stick);
            }
          else
            {
              dealii::SolverCG<dealii::Vector<double>> solver(control);
              solver.solve(K, u, f, stick);
            }
        }
      catch (const dealii::SolverControl::NoConvergence &e)
        {
          AssertThrow(false,
                      dealii::ExcMessage(std::string(gmres ? "GMRES" : "CG") +
                                         "-AMG on the condensed contact problem (stick penalty) did not converge" +
                                         where + ": residual " + std::to_string(e.last_residual) + " after " +
                                         std::to_string(e.last_step) + " iterations (target " +
                                         std::to_string(control.tolerance()) + ")."));
        }
      return control.last_step();
    }
  } // namespace



  namespace internal
  {
    /**
     * The ML AMG hierarchy of the condensed CG-AMG solves, kept from one
     * solve to the next with a fingerprint of each row of the matrix $K_0$
     * it was built on (64 bits of its columns and value bits: 8 bytes a row
     * where a copy of the matrix took 12 bytes an entry, 360 MB at 1e6 DoFs).
     * prepare() compares the matrix $K$ of a solve with $K_0$ row by row:
     * - no row differs (by its fingerprint; a changed row that kept its
     *   fingerprint, with probability 2^-64, would only keep an older
     *   preconditioner, which is still symmetric positive definite, so CG's
     *   answer is the same): the hierarchy is
     *   used as it is, so the preconditioner, and every iterate, is the one
     *   a fresh set-up would give (load steps and Newton iterations that
     *   keep the closed pairs);
     * - some rows differ, at most a given fraction of them (an active-set
     *   step that opens or closes a few pairs changes the rows of their
     *   slave DoFs and of the DoFs coupled to those): the hierarchy is kept
     *   and combined with the exact solve $Q = R_S^T K_{SS}^{-1} R_S$ on the
     *   set $S$ of those rows and the rows coupled to them (sparse Cholesky
     *   of the rows and columns $S$ of $K$) as a symmetric multiplicative
     *   Schwarz method: an exact solve on $S$,
     *   one AMG cycle $M$ on the remaining residual, the exact solve on $S$
     *   again. Its error propagation $(I - QK)(I - MK)(I - QK)$ is
     *   self-adjoint in the energy product with eigenvalues below 1
     *   ($I - QK$ is an energy-orthogonal projection, $M$ is symmetric
     *   positive definite), so the preconditioner is symmetric positive
     *   definite for CG whatever the changes. The old cycle alone is not
     *   enough: the modes an opened pair frees are missing from its coarse
     *   spaces, and CG took 4 to 15 times the iterations of a fresh
     *   hierarchy on the 100-block wall of benchmarks/assembly; corrected,
     *   0.9 to 1.2 times where at most 2 % of the rows changed;
     * - more rows differ: the hierarchy is built again.
     *
     * A $K$ condensed into Trilinos (CondensedMatrix) is the matrix ML or
     * the p-multigrid works on, shared: the cache keeps the one its
     * hierarchy was built on. A deal.II $K$ is copied by epetra_copy():
     * the matrix deal.II's reinit() makes, without its global-index
     * look-ups and sorting.
     */
    class AMGCache
    {
    public:
      /// How prepare() provides the preconditioner.
      enum class Use
      {
        built,    ///< a new hierarchy for the matrix
        reused,   ///< the hierarchy of the same matrix
        corrected ///< the hierarchy of an earlier matrix, corrected on the changed rows
      };

      /**
       * Make vmult() a preconditioner for @p K (kept by reference until
       * the next call): see the class documentation. At most
       * @p max_changed_fraction of the rows may differ from the matrix of
       * the hierarchy for a correction; 0 allows only the exact reuse.
       */
      Use
      prepare(const CondensedMatrix                  &K,
              const std::vector<std::vector<double>> &modes,
              const double                            max_changed_fraction,
              const CondensedCoarseSpace             &coarse_space = CondensedCoarseSpace())
      {
        coarse = coarse_space;
        // (the continuation of the last solve: the same matrix, prepared)
        if (continuing && matrix.id() == K.id())
          {
            continuing = false;
            return Use::reused;
          }
        continuing     = false;
        matrix         = K;
        pending_matrix = nullptr;
        changed.clear();
        const unsigned int n = K.m();
        if (has_hierarchy && fingerprints.size() == n)
          {
            const std::size_t max_changed = static_cast<std::size_t>(max_changed_fraction * n);
            bool              too_many    = false;
            // (all rows are fingerprinted, for build() if it follows)
            pending.resize(n);
            for (unsigned int i = 0; i < n; ++i)
              {
                pending[i] = fingerprint(K, i);
                if (!too_many && pending[i] != fingerprints[i])
                  {
                    changed.push_back(i);
                    too_many = (changed.size() > max_changed);
                  }
              }
            pending_matrix = K.id();
            if (changed.empty())
              return Use::reused;
            if (!too_many)
              {
                // the changed rows and the rows coupled to them: the
                // correction then reaches one layer further (on the wall of
                // benchmarks/assembly, 10-20 % fewer CG iterations than
                // with the changed rows alone)
                std::vector<bool> in(n, false);
                for (const auto i : changed)
                  in[i] = true;
                const std::size_t n_changed = changed.size();
                for (std::size_t k = 0; k < n_changed; ++k)
                  K.for_row(changed[k], [&](const unsigned int j, double) {
                    if (!in[j])
                      {
                        in[j] = true;
                        changed.push_back(j);
                      }
                  });
                std::sort(changed.begin(), changed.end());
                if (factorize_changed_rows())
                  return Use::corrected;
              }
            changed.clear();
          }
        build(modes);
        return Use::built;
      }

      /// Set before a solve that continues the last one on the same
      /// matrix: the next prepare() keeps the preconditioner as it is (a
      /// corrected hierarchy with its factorization of the changed rows)
      /// instead of comparing the matrix again and factorizing the changed
      /// rows again (measured: the continuations of the inexact solves of
      /// the 100-block wall took 0.25 s, most of it there).
      bool continuing = false;

      /**
       * Build the hierarchy for the matrix of the last prepare() (e.g. when
       * a corrected one converges too slowly).
       */
      void
      build(const std::vector<std::vector<double>> &modes)
      {
        Assert(matrix.id() != nullptr, dealii::ExcMessage("AMGCache: prepare() first."));
        const CondensedMatrix &K = matrix;
        const unsigned int     n = K.m();
        changed.clear();
        // the fingerprints of the rows, for the comparison (those prepare()
        // computed for this matrix, if it did)
        if (pending_matrix == K.id() && pending.size() == n)
          fingerprints.swap(pending);
        else
          {
            fingerprints.resize(n);
            for (unsigned int i = 0; i < n; ++i)
              fingerprints[i] = fingerprint(K, i);
          }
        pending_matrix = nullptr;
        has_hierarchy  = true;
        if (coarse.P != nullptr)
          {
            // the p-multigrid: its cycle works on a Trilinos matrix (as
            // LinearSolver's for one body): K itself, or a copy of a deal.II K
            cycle.reset();
            amg_matrix.reset();
            if (K.trilinos != nullptr)
              {
                std::vector<bool> decoupled(n, true);
                for (unsigned int i = 0; i < n; ++i)
                  K.for_row(i, [&](const unsigned int j, const double v) {
                    if (j != i && v != 0.)
                      decoupled[i] = false;
                  });
                cycle_owner = K.trilinos;
                cycle       = make_serial_two_level(decoupled, *K.trilinos, *coarse.P, *coarse.modes, coarse.lines,
                                                    LinearSolver::Settings(), P_trilinos);
              }
            else
              {
                cycle_owner.reset();
                auto copy = std::make_shared<dealii::TrilinosWrappers::SparseMatrix>();
                copy_to_trilinos(*K.deal_ii, *copy);
                cycle       = make_condensed_two_level(*K.deal_ii, *copy, coarse, P_trilinos);
                cycle_owner = std::move(copy);
              }
            return;
          }

        // ML's Epetra matrix: K's own, or a copy of a deal.II K
        std::unique_ptr<Epetra_CrsMatrix> fresh = (K.deal_ii != nullptr ? epetra_copy(*K.deal_ii, 1e-13) : nullptr);
        cycle.reset();
        list = Teuchos::ParameterList();
        set_ml_parameters(&list, modes, n, null_space);
        // (the old hierarchy refers to the old matrix until it is replaced)
        amg.initialize(fresh != nullptr ? *fresh : *K.epetra, list);
        amg_matrix = std::move(fresh);
        amg_owner  = K.trilinos;
      }

      /// Whether the preconditioner is the p-multigrid.
      bool
      is_two_level() const
      {
        return cycle != nullptr;
      }

      /// The rows corrected by the exact solve (empty unless prepare()
      /// returned Use::corrected).
      std::size_t
      n_changed_rows() const
      {
        return changed.size();
      }

      /// Apply the preconditioner of the last prepare() to @p src.
      void
      vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const
      {
        if (changed.empty())
          {
            apply_cycle(dst, src);
            return;
          }
        const CondensedMatrix &K = matrix;
        const std::size_t      m = changed.size();
        // the exact solve on S; the residual src - K x1 of its result x1,
        // which lives on S (the column of a symmetric K is its row)
        restricted.reinit(m);
        for (std::size_t k = 0; k < m; ++k)
          restricted[k] = src[changed[k]];
        cholesky.solve(correction, restricted);
        residual = src;
        for (std::size_t k = 0; k < m; ++k)
          {
            const double c = correction[k];
            K.for_row(changed[k], [&](const unsigned int j, const double v) { residual[j] -= v * c; });
          }
        // one AMG cycle on it
        apply_cycle(dst, residual);
        for (std::size_t k = 0; k < m; ++k)
          dst[changed[k]] += correction[k];
        // the exact solve on S again, for the residual on S
        for (std::size_t k = 0; k < m; ++k)
          {
            double r = src[changed[k]];
            K.for_row(changed[k], [&](const unsigned int j, const double v) { r -= v * dst[j]; });
            restricted[k] = r;
          }
        cholesky.solve(correction, restricted);
        for (std::size_t k = 0; k < m; ++k)
          dst[changed[k]] += correction[k];
      }

    private:
      // one cycle of the hierarchy: ML's V-cycle or the p-multigrid
      void
      apply_cycle(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const
      {
        if (cycle)
          cycle->vmult(dst, src);
        else
          amg.vmult(dst, src);
      }

      // K restricted to the changed rows and columns, factorized; false if
      // it is not positive definite (then the hierarchy is built again)
      bool
      factorize_changed_rows()
      {
        const CondensedMatrix &K = matrix;
        const std::size_t      m = changed.size();
        local.assign(K.m(), -1);
        for (std::size_t k = 0; k < m; ++k)
          local[changed[k]] = static_cast<int>(k);
        std::vector<unsigned int> lengths(m, 0);
        for (std::size_t k = 0; k < m; ++k)
          K.for_row(changed[k], [&](const unsigned int j, double) { lengths[k] += (local[j] >= 0); });
        changed_pattern.reinit(m, m, lengths);
        for (std::size_t k = 0; k < m; ++k)
          K.for_row(changed[k], [&](const unsigned int j, double) {
            if (local[j] >= 0)
              changed_pattern.add(k, local[j]);
          });
        changed_pattern.compress();
        changed_matrix.reinit(changed_pattern);
        for (std::size_t k = 0; k < m; ++k)
          K.for_row(changed[k], [&](const unsigned int j, const double v) {
            if (local[j] >= 0)
              changed_matrix.set(k, local[j], v);
          });
        return cholesky.factorize(changed_matrix);
      }

      /// The matrix of the last prepare().
      CondensedMatrix matrix;
      /// Whether a hierarchy was built.
      bool has_hierarchy = false;
      /// A 64-bit fingerprint of each row (length, columns and the bits of
      /// the values) of the matrix the hierarchy was built on.
      std::vector<std::uint64_t> fingerprints;
      /// The fingerprints of the matrix of the last prepare() that
      /// compared them (@p pending_matrix), kept for a build() on it.
      std::vector<std::uint64_t> pending;
      const void                *pending_matrix = nullptr;

      /// The fingerprint of row @p i of @p K: its length, columns and
      /// value bits. Each entry (its value's bits plus an odd multiple of
      /// its column) is mixed into one of two lanes, alternately, by an
      /// xor, a multiplication and a rotation (the rotation carries the
      /// high bits into the next product, so that changes of sign or
      /// exponent cannot cancel); the lanes are combined by splitmix64's
      /// finalizer. Two independent lanes of three operations an entry
      /// take a fifth of the time of a finalizer per column and per value
      /// (0.36 s for a 1e6-DoF condensed matrix, 48 entries a row); a
      /// collision would only keep an older, still symmetric positive
      /// definite, preconditioner (see the class documentation).
      static std::uint64_t
      fingerprint(const CondensedMatrix &K, const unsigned int i)
      {
        const auto rotate   = [](const std::uint64_t x, const int r) { return (x << r) | (x >> (64 - r)); };
        const auto finalize = [](std::uint64_t x) {
          x ^= x >> 30;
          x *= 0xbf58476d1ce4e5b9ULL;
          x ^= x >> 27;
          x *= 0x94d049bb133111ebULL;
          return x ^ (x >> 31);
        };
        constexpr std::uint64_t prime_a = 0x9e3779b97f4a7c15ULL, prime_b = 0xc2b2ae3d27d4eb4fULL,
                                column_factor = 0x165667b19e3779f9ULL;
        std::uint64_t a = prime_a ^ K.row_length(i), b = prime_b;
        bool          lane_a = true;
        K.for_row(i, [&](const unsigned int j, const double v) {
          std::uint64_t bits;
          std::memcpy(&bits, &v, sizeof bits);
          const std::uint64_t entry = bits + column_factor * (std::uint64_t(j) + 1);
          if (lane_a)
            a = rotate((a ^ entry) * prime_b, 29);
          else
            b = rotate((b ^ entry) * prime_a, 31);
          lane_a = !lane_a;
        });
        return finalize(a ^ rotate(finalize(b), 17));
      }
      /// ML's copy of a deal.II matrix, or the Trilinos matrix ML works on.
      std::unique_ptr<Epetra_CrsMatrix>                             amg_matrix;
      std::shared_ptr<const dealii::TrilinosWrappers::SparseMatrix> amg_owner;
      Teuchos::ParameterList                    list;
      std::vector<double>                       null_space;
      dealii::TrilinosWrappers::PreconditionAMG amg;
      /// The coarse space of the p-multigrid (none: ML AMG), the Trilinos
      /// copies of the matrix and the restricted prolongation it works on,
      /// and its cycle.
      CondensedCoarseSpace                                          coarse;
      std::shared_ptr<const dealii::TrilinosWrappers::SparseMatrix> cycle_owner;
      dealii::TrilinosWrappers::SparseMatrix                        P_trilinos;
      std::unique_ptr<TwoLevelCycle<dealii::Vector<double>>>        cycle;
      /// The rows that differ, their index among them, and the factorized
      /// restriction of the matrix to them.
      std::vector<unsigned int>              changed;
      std::vector<int>                       local;
      dealii::SparsityPattern                changed_pattern;
      dealii::SparseMatrix<double>           changed_matrix;
      SparseCholesky                         cholesky;
      mutable dealii::Vector<double>         restricted, correction, residual;
    };



    /**
     * A condensed contact system and its solution, kept after a solve that
     * stopped at the inexact tolerance for
     * SaddlePointSolver::complete_last_solve().
     */
    struct CondensedSystem
    {
      ContactConstraints           contact;
      CompressedRowPattern         sparsity;
      /// The condensed stiffness: K, or Kt when it was condensed into
      /// Trilinos (CG on a symmetric problem without stick springs).
      dealii::SparseMatrix<double>                            K;
      std::shared_ptr<dealii::TrilinosWrappers::SparseMatrix> Kt;
      /// Or kept as rows of the saddle-point matrix (CG with the stick
      /// springs, whose preconditioner makes its own matrix).
      std::shared_ptr<CondensedRows> rows;
      dealii::Vector<double>       f;
      dealii::Vector<double>       u;
      /// The size of the saddle-point system it was condensed from.
      unsigned int                 size = 0;

      /// K or Kt, as the iterative solvers read it.
      CondensedMatrix
      matrix() const
      {
        if (rows != nullptr)
          return CondensedMatrix(std::shared_ptr<const CondensedRows>(rows));
        return (Kt != nullptr ? CondensedMatrix(Kt) : CondensedMatrix(K));
      }
    };
  } // namespace internal



  std::pair<unsigned int, unsigned int>
  SaddlePointSolver::analysis_counts() const
  {
    if (!cholesky)
      return {0, 0};
    return {cholesky->n_analyses, cholesky->n_reused_analyses};
  }



  void
  SaddlePointSolver::set_inexact(const bool inexact)
  {
    inexact_solves = inexact;
  }



  unsigned int
  SaddlePointSolver::solve_with_amg(const internal::CondensedMatrix         &K,
                                    const internal::CondensedMatrix         &K_amg,
                                    dealii::Vector<double>                  &u,
                                    const dealii::Vector<double>            &f,
                                    const double                             relative_tolerance,
                                    const bool                               symmetric,
                                    const dealii::AffineConstraints<double> &lines)
  {
    internal::CondensedCoarseSpace coarse;
    if (uses_p_multigrid())
      {
        AssertThrow(coarse_prolongation->m() == K.m(),
                    dealii::ExcMessage("SaddlePointSolver: the coarse space (set_coarse_space()) has " +
                                       std::to_string(coarse_prolongation->m()) + " fine rows, the condensed "
                                       "stiffness " + std::to_string(K.m()) + ": set it for the DoF handler of "
                                       "this system."));
        coarse.P     = coarse_prolongation;
        coarse.modes = &coarse_modes;
        coarse.lines = &lines;
      }
    if (!amg_cache)
      amg_cache = std::make_shared<internal::AMGCache>();
    dealii::Timer setup;
    const auto    use = amg_cache->prepare(K_amg, modes, settings.amg_reuse_fraction, coarse);
    if (use == internal::AMGCache::Use::built)
      {
        ++n_amg_setups;
        amg_setup_seconds += setup.wall_time();
      }
    else if (use == internal::AMGCache::Use::reused)
      ++n_amg_reuses;
    else
      ++n_amg_corrections;

    const double target = relative_tolerance * f.l2_norm();
    const auto   krylov = [&](dealii::SolverControl &control) {
      if (symmetric)
        {
          dealii::SolverCG<dealii::Vector<double>> cg(control);
          cg.solve(K, u, f, *amg_cache);
        }
      else
        {
          dealii::SolverGMRES<dealii::Vector<double>>::AdditionalData data(200, true);
          dealii::SolverGMRES<dealii::Vector<double>> gmres(control, data);
          gmres.solve(K, u, f, *amg_cache);
        }
    };
    const auto fail = [&](const dealii::SolverControl::NoConvergence &e, const double tolerance) {
      AssertThrow(false, dealii::ExcMessage(std::string(symmetric ? "CG" : "GMRES") +
                                            "-AMG on the condensed contact problem did not converge: residual " +
                                            std::to_string(e.last_residual) + " after " +
                                            std::to_string(e.last_step) + " iterations (target " +
                                            std::to_string(tolerance) + ")."));
    };

    // a corrected hierarchy may take at most twice the iterations per
    // decade of residual reduction that the last freshly built one took
    // (and 10 more); beyond, it is built again for this matrix and the
    // iteration goes on from where it stopped
    unsigned int budget = settings.max_iterations;
    if (use == internal::AMGCache::Use::corrected && amg_iterations_per_decade > 0)
      {
        dealii::Vector<double> r(f.size());
        const double           start   = K.residual(r, u, f);
        const double decades = (start > target && target > 0 ? std::log10(start / target) : 0.);
        budget = static_cast<unsigned int>(
          std::min<double>(settings.max_iterations, 10 + std::ceil(2 * amg_iterations_per_decade * decades)));
      }
    dealii::SolverControl control(budget, target);
    try
      {
        krylov(control);
      }
    catch (const dealii::SolverControl::NoConvergence &e)
      {
        if (budget >= settings.max_iterations)
          fail(e, target);
        dealii::Timer rebuild;
        amg_cache->build(modes);
        ++n_amg_setups;
        ++n_amg_slow_corrections;
        amg_setup_seconds += rebuild.wall_time();
        dealii::SolverControl rest(settings.max_iterations - control.last_step(), target);
        try
          {
            krylov(rest);
          }
        catch (const dealii::SolverControl::NoConvergence &e2)
          {
            fail(e2, target);
          }
        return control.last_step() + rest.last_step();
      }
    // the rate of a fresh hierarchy: the yardstick of the corrected ones
    if (use == internal::AMGCache::Use::built && control.last_value() > 0 &&
        control.initial_value() > 10 * control.last_value())
      amg_iterations_per_decade = control.last_step() / std::log10(control.initial_value() / control.last_value());
    return control.last_step();
  }



  namespace
  {
    // Whether two condensed matrices have the same pattern and values.
    bool
    same_condensed_matrix(const dealii::SparseMatrix<double> &A, const dealii::SparseMatrix<double> &B)
    {
      if (A.m() != B.m() || A.n_nonzero_elements() != B.n_nonzero_elements())
        return false;
      const auto &pa = A.get_sparsity_pattern();
      const auto &pb = B.get_sparsity_pattern();
      for (unsigned int i = 0; i < A.m(); ++i)
        {
          if (pa.row_length(i) != pb.row_length(i))
            return false;
          auto a = A.begin(i), b = B.begin(i);
          for (const auto a_end = A.end(i); a != a_end; ++a, ++b)
            if (a->column() != b->column() || a->value() != b->value())
              return false;
        }
      return true;
    }
  } // namespace



  void
  SaddlePointSolver::solve_condensed(const dealii::SparseMatrix<double> &A,
                                     const unsigned int                  n_displacements,
                                     dealii::Vector<double>             &x,
                                     const dealii::Vector<double>       &b)
  {
    // a length scale for the consistency test of redundant constraints:
    // the coordinates in the rotation mode
    double length = 0;
    if (modes.size() == 3)
      for (const double v : modes[2])
        length = std::max(length, std::abs(v));
    auto  system  = std::make_shared<internal::CondensedSystem>();
    auto &contact = system->contact;
    auto &K       = system->K;
    auto &f       = system->f;
    auto &u       = system->u;
    system->size  = A.m();
    contact.reinit(A, n_displacements, b, length);
    n_dropped  = contact.get_dependent_rows().size();
    used_gmres = !contact.is_symmetric();
    // CG on a symmetric problem without stick springs works on a Trilinos
    // matrix (the p-multigrid's or ML's own): condensed straight into it
    // (with stick springs, whose preconditioner makes a matrix of its own,
    // CG reads the condensed rows from A)
    if (settings.type == Type::cg_amg_constraints && !used_gmres && stick_rows.empty())
      {
        system->Kt = std::make_shared<dealii::TrilinosWrappers::SparseMatrix>();
        contact.condense(A, b, *system->Kt, f);
      }
    else if (settings.type == Type::cg_amg_constraints && !used_gmres)
      {
        system->rows = std::make_shared<CondensedRows>();
        contact.condense(A, b, *system->rows, f);
      }
    else
      contact.condense(A, b, system->sparsity, K, f);
    u.reinit(n_displacements);
    if (settings.type == Type::direct_constraints)
      {
        // Cholesky of the symmetric condensed stiffness; LU where it is
        // not positive definite, or not symmetric (slipping pairs)
        // the factorization of the last solve is kept while its condensed
        // matrix comes back unchanged (an adjoint solve, a load step)
        const bool same = factored_system && !used_gmres && same_condensed_matrix(factored_system->K, K);
        if (same)
          {
            used_lu_fallback = false;
            ++n_factorization_reuses;
          }
        else
          {
            factored_system.reset();
            if (!cholesky)
              cholesky = std::make_shared<internal::SparseCholesky>();
            used_lu_fallback = used_gmres || !cholesky->factorize(K);
            if (!used_lu_fallback)
              {
                ++n_factorizations;
                factored_system = system;
              }
          }
        if (used_lu_fallback)
          internal::solve_direct(K, u, f, false);
        else
          cholesky->solve(u, f);
        iterations = 1;
      }
    else
      solve_condensed_iteratively(*system, A, b, length);
    stick_rows.clear();
    for (unsigned int i = 0; i < n_displacements; ++i)
      x[i] = u[i];
    contact.distribute_and_recover_multipliers(A, b, x);
    if (settings.type == Type::cg_amg_constraints)
      {
        previous.reinit(n_displacements);
        for (unsigned int i = 0; i < n_displacements; ++i)
          previous[i] = x[i];
      }
    if (last_inexact)
      inexact_system = system;
  }



  void
  SaddlePointSolver::solve_condensed_iteratively(internal::CondensedSystem          &system,
                                                 const dealii::SparseMatrix<double> &A,
                                                 const dealii::Vector<double>       &b,
                                                 const double                        length)
  {
    const unsigned int            n_displacements = system.u.size();
    auto                           &contact         = system.contact;
    const internal::CondensedMatrix matrix          = system.matrix();
    const dealii::Vector<double> &f               = system.f;
    dealii::Vector<double>       &u               = system.u;
    // the start: the displacements of the previous solve, with the
    // slave DoFs of this one at their condensed value (their rows
    // are decoupled: f_s / K_ss, zero); zero instead where that is
    // closer (after a large change of the set, e.g. from a first
    // set that only holds the bodies, the old displacements
    // penetrate far across the newly closed pairs)
    if (settings.warm_start && previous.size() == n_displacements)
      {
        u = previous;
        for (const auto &sl : contact.get_slaves())
          {
            const double d = matrix.diag_element(sl.second);
            u[sl.second]   = (d != 0 ? f[sl.second] / d : 0.);
          }
        dealii::Vector<double> r(n_displacements);
        if (matrix.residual(r, u, f) >= f.l2_norm())
          u = 0.;
      }
    // an inexact solve stops early (CG on the symmetric condensed
    // stiffness, with or without stick springs: complete_last_solve()
    // goes on from there, with the same preconditioner)
    last_inexact = inexact_solves && !used_gmres && settings.inexact_tolerance > settings.relative_tolerance;
    const double tolerance =
      (last_inexact ? std::max(settings.inexact_tolerance, settings.inexact_start_tolerance) :
                      settings.relative_tolerance);
    last_inexact_tolerance = tolerance;
    if (!stick_rows.empty())
      {
        // CG (GMRES when slipping pairs make the condensed matrix
        // non-symmetric) with the two-subspace preconditioner of the
        // stick springs
        internal::CondensedCoarseSpace coarse;
        if (uses_p_multigrid())
          {
            coarse.P     = coarse_prolongation;
            coarse.modes = &coarse_modes;
          }
        const auto stick_ptr = std::make_shared<const StickPreconditioner>(matrix, contact.get_constraints(),
                                                                           stick_rows, modes, length, coarse);
        const StickPreconditioner &stick = *stick_ptr;
        if (last_inexact)
          inexact_stick = stick_ptr;
        used_stick_preconditioner = true;
        iterations =
          solve_with_stick(matrix, u, f, stick, tolerance * f.l2_norm(), settings.max_iterations, used_gmres, "");
      }
    else if (used_gmres)
      {
        // GMRES with AMG on the symmetric part C^T K C: it needs
        // fewer iterations with it than with AMG on Z^T K C itself
        // (measured: 96-108 against 100-144 per Newton iteration on
        // a 56k-DoF sliding patch test)
        CompressedRowPattern         sp_sym;
        dealii::SparseMatrix<double> K_sym;
        dealii::Vector<double>       f_sym;
        contact.condense(A, b, sp_sym, K_sym, f_sym, true);
        iterations =
          solve_with_amg(matrix, internal::CondensedMatrix(K_sym), u, f, tolerance, false, contact.get_constraints());
      }
    else
      iterations = solve_with_amg(matrix, matrix, u, f, tolerance, true, contact.get_constraints());
    // (an inexact solution only proposes the next set: its residual is
    // checked when the accepted set's solve is completed; solve() checks
    // every solution for finite values)
    if (!last_inexact)
      internal::check_condensed_residual(matrix, u, f, tolerance,
                                         description() + (context.empty() ? "" : ", " + context));
  }



  void
  SaddlePointSolver::solve_block_gmres(const dealii::SparseMatrix<double> &A,
                                       const unsigned int                  n_displacements,
                                       dealii::Vector<double>             &x,
                                       const dealii::Vector<double>       &b)
  {
    dealii::BlockSparsityPattern      pattern;
    dealii::BlockSparseMatrix<double> blocks;
    split_into_blocks(A, n_displacements, pattern, blocks);
    const BlockPreconditioner preconditioner(blocks, modes);
    const std::vector<dealii::types::global_dof_index> sizes{n_displacements,
                                                             A.m() - n_displacements};
    dealii::BlockVector<double>                        xb(sizes), bb(sizes);
    for (unsigned int i = 0; i < b.size(); ++i)
      bb[i] = b[i];
    dealii::SolverControl control(settings.max_iterations,
                                  settings.relative_tolerance * b.l2_norm());
    dealii::SolverGMRES<dealii::BlockVector<double>>::AdditionalData data(200, true);
    dealii::SolverGMRES<dealii::BlockVector<double>> gmres(control, data);
    try
      {
        gmres.solve(blocks, xb, bb, preconditioner.linear_operator(blocks));
      }
    catch (const dealii::SolverControl::NoConvergence &e)
      {
        AssertThrow(false,
                    dealii::ExcMessage("GMRES-AMG did not converge: residual " +
                                       std::to_string(e.last_residual) + " after " +
                                       std::to_string(e.last_step) + " iterations (target " +
                                       std::to_string(control.tolerance()) + ")."));
      }
    iterations = control.last_step();
    for (unsigned int i = 0; i < x.size(); ++i)
      x[i] = xb[i];
  }



  void
  SaddlePointSolver::solve(const dealii::SparseMatrix<double> &A,
                           const unsigned int                  n_displacements,
                           dealii::Vector<double>             &x,
                           const dealii::Vector<double>       &b)
  {
    AssertDimension(A.m(), b.size());
    x.reinit(b.size());
    n_dropped                 = 0;
    used_stick_preconditioner = false;
    last_inexact              = false;
    inexact_system.reset();
    inexact_stick.reset();
    if (is_condensed(settings.type))
      solve_condensed(A, n_displacements, x, b);
    else if (settings.type != Type::gmres_amg)
      {
        internal::solve_direct(A, x, b, settings.type == Type::klu);
        iterations = 1;
      }
    else
      solve_block_gmres(A, n_displacements, x, b);
    check_finite(x);
    // the residual of the system that was solved (the condensed solve
    // checks its CG and recovers the multipliers from the residual)
    if (settings.type != Type::cg_amg_constraints)
      internal::check_residual(A, x, b, settings.type == Type::gmres_amg ? settings.relative_tolerance : 0.,
                               type_name(settings.type) + (context.empty() ? "" : ", " + context));
  }



  void
  SaddlePointSolver::complete_last_solve(const dealii::SparseMatrix<double> &A,
                                         dealii::Vector<double>             &x,
                                         const dealii::Vector<double>       &b)
  {
    continue_last_solve(A, x, b, settings.relative_tolerance, "complete_last_solve");
    last_inexact = false;
    inexact_system.reset();
    inexact_stick.reset();
  }



  bool
  SaddlePointSolver::refine_last_solve(const dealii::SparseMatrix<double> &A,
                                       dealii::Vector<double>             &x,
                                       const dealii::Vector<double>       &b)
  {
    AssertThrow(last_inexact && inexact_system != nullptr,
                dealii::ExcMessage("SaddlePointSolver::refine_last_solve(): the last solve was not an inexact "
                                   "one (see set_inexact())."));
    // (0.1 times 1e-5 is 1.0000000000000002e-6 in floating point: without
    // the slack a tolerance of 1e-6 got one more continuation, of no CG
    // iteration, with its residual check, multiplier recovery and rule)
    if (last_inexact_tolerance <= settings.inexact_tolerance * (1 + 1e-12))
      return false;
    last_inexact_tolerance = std::max(settings.inexact_tolerance, 0.1 * last_inexact_tolerance);
    continue_last_solve(A, x, b, last_inexact_tolerance, "refine_last_solve");
    return true;
  }



  void
  SaddlePointSolver::continue_last_solve(const dealii::SparseMatrix<double> &A,
                                         dealii::Vector<double>             &x,
                                         const dealii::Vector<double>       &b,
                                         const double                        tolerance,
                                         const std::string                  &what)
  {
    AssertThrow(last_inexact && inexact_system != nullptr,
                dealii::ExcMessage("SaddlePointSolver::" + what +
                                   "(): the last solve was not an inexact one (see set_inexact())."));
    auto              &system = *inexact_system;
    const unsigned int n      = system.u.size();
    AssertThrow(A.m() == system.size && b.size() == system.size && x.size() == system.size,
                dealii::ExcMessage("SaddlePointSolver::" + what +
                                   "(): the system is not the one of the last solve."));
    // (condensed rows read the saddle-point matrix: the one given now)
    if (system.rows != nullptr)
      system.rows->rebind(A);
    if (amg_cache && inexact_stick == nullptr)
      amg_cache->continuing = true;
    // (a continuation is not a reuse of the hierarchy for another matrix:
    // the report does not count it)
    const unsigned int reuses = n_amg_reuses;
    if (inexact_stick != nullptr)
      {
        // (CG on the matrix with the stick springs, preconditioned as the
        // inexact solve was)
        const auto &stick = *std::static_pointer_cast<const StickPreconditioner>(inexact_stick);
        iterations        = solve_with_stick(system.matrix(), system.u, system.f, stick, tolerance * system.f.l2_norm(),
                                             settings.max_iterations, false, " in " + what + "()");
      }
    else
      iterations = solve_with_amg(system.matrix(), system.matrix(), system.u, system.f, tolerance, true,
                                  system.contact.get_constraints());
    n_amg_reuses = reuses;
    // (a refined solution is only checked for finite values, below)
    if (tolerance <= settings.relative_tolerance)
      internal::check_condensed_residual(system.matrix(), system.u, system.f, tolerance,
                                         description() + (context.empty() ? "" : ", " + context) + ", completed");
    for (unsigned int i = 0; i < n; ++i)
      x[i] = system.u[i];
    system.contact.distribute_and_recover_multipliers(A, b, x);
    for (unsigned int i = 0; i < n; ++i)
      previous[i] = x[i];
    check_finite(x);
  }
} // namespace dealvem
