// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
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

#include <Teuchos_ParameterList.hpp>
#include <ml_MultiLevelPreconditioner.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
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
  {}



  void
  SaddlePointSolver::set_near_null_space(const std::vector<std::vector<double>> &m)
  {
    modes = m;
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
             " + ML AMG on the stiffness condensed by the active contact constraints (one slave DoF per "
             "constraint, multipliers from the residual" +
             std::string(used_gmres ? "; slipping pairs: Petrov-Galerkin condensation, not symmetric" : "") +
             std::string(used_stick_preconditioner ? "; stick springs preconditioned by tying them" : "") +
             (n_amg_setups > 0 ? "; AMG set up " + std::to_string(n_amg_setups) + " time(s) in " +
                                   seconds(amg_setup_seconds) + ", reused " +
                                   std::to_string(n_amg_reuses) + " time(s) for an unchanged matrix" :
                                 "") +
             ")";
    if (settings.type == Type::direct_constraints)
      return std::string(used_gmres       ? "UMFPACK LU (slipping pairs: the condensed matrix is not symmetric)" :
                         used_lu_fallback ? "UMFPACK LU (the condensed matrix is not positive definite)" :
                                            "CHOLMOD Cholesky") +
             " of the stiffness condensed by the active contact constraints (one slave DoF per constraint, "
             "multipliers from the residual)";
    return type_name(settings.type) + " (direct, whole saddle-point matrix)";
  }



  namespace
  {
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
        for (auto it = A.begin(i); it != A.end(i); ++it)
          dsp.add(i, it->column());
      pattern.copy_from(dsp);
      blocks.reinit(pattern);
      for (unsigned int i = 0; i < A.m(); ++i)
        for (auto it = A.begin(i); it != A.end(i); ++it)
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
          for (auto it = M->begin(i); it != M->end(i); ++it)
            dsp.add(i, it->column());
      for (unsigned int i = 0; i < first.m(); ++i)
        dsp.add(i, i);
      pattern.copy_from(dsp);
      C.reinit(pattern);
      for (unsigned int i = 0; i < first.m(); ++i)
        {
          for (auto it = first.begin(i); it != first.end(i); ++it)
            C.add(i, it->column(), it->value());
          for (auto it = second.begin(i); it != second.end(i); ++it)
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
        K_trilinos.reinit(K_rho);
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

    /**
     * The two-subspace preconditioner of the condensed stick-penalty system
     * (see SaddlePointSolver::set_stick_directions()):
     * M^{-1} r = Z AMG(Z^T K Z) Z^T r + sum_s e_s r_s / K_ss.
     */
    class StickPreconditioner
    {
    public:
      StickPreconditioner(const dealii::SparseMatrix<double>                                  &K,
                          const dealii::AffineConstraints<double>                           &normal_lines,
                          const std::vector<std::vector<std::pair<unsigned int, double>>> &stick_rows,
                          const std::vector<std::vector<double>>                            &modes,
                          const double                                                      length)
        : K(K)
      {
        const unsigned int n = K.m();
        const ContactConstraints ties = ContactConstraints::tie_lines(stick_rows, normal_lines, normal_lines, n, length);
        Z.copy_from(ties.get_constraints());
        for (const auto &sl : ties.get_slaves())
          slaves.push_back(sl.second);

        // Z^T K Z: the springs vanish on tied functions
        dealii::DynamicSparsityPattern dsp(n, n);
        for (unsigned int i = 0; i < n; ++i)
          for (auto it = K.get_sparsity_pattern().begin(i); it != K.get_sparsity_pattern().end(i); ++it)
            dsp.add(i, it->column());
        Z.condense(dsp);
        tied_pattern.copy_from(dsp);
        dealii::SparseMatrix<double> tied(tied_pattern);
        for (unsigned int i = 0; i < n; ++i)
          for (auto it = K.begin(i); it != K.end(i); ++it)
            tied.add(i, it->column(), it->value());
        Z.condense(tied);
        tied_trilinos.reinit(tied);
        Teuchos::ParameterList list;
        internal::set_ml_parameters(&list, modes, n, null_space);
        amg.initialize(tied_trilinos.trilinos_matrix(), list);
        w.reinit(n);
        v.reinit(n);
      }

      void
      vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const
      {
        w = src;
        Z.condense(w);
        amg.vmult(v, w);
        Z.distribute(v);
        dst = v;
        for (const auto s : slaves)
          dst[s] += src[s] / K.diag_element(s);
      }

      unsigned int
      n_ties() const
      {
        return slaves.size();
      }

    private:
      const dealii::SparseMatrix<double>       &K;
      dealii::AffineConstraints<double>         Z;
      std::vector<unsigned int>                 slaves;
      dealii::SparsityPattern                   tied_pattern;
      dealii::TrilinosWrappers::SparseMatrix    tied_trilinos;
      std::vector<double>                       null_space;
      dealii::TrilinosWrappers::PreconditionAMG amg;
      mutable dealii::Vector<double>            w, v;
    };
  } // namespace



  namespace internal
  {
    /**
     * An ML AMG hierarchy with a copy of the matrix it was built on, so that
     * a later solve with the same matrix (pattern and values, bit for bit)
     * reuses it: the preconditioner, and so every iterate, is then exactly
     * the one a fresh set-up would give.
     */
    class AMGCache
    {
    public:
      /// Whether @p K is the matrix of the hierarchy; if not, build it.
      bool
      prepare(const dealii::SparseMatrix<double> &K, const std::vector<std::vector<double>> &modes)
      {
        const auto &sp   = K.get_sparsity_pattern();
        bool        same = valid && sp.n_rows() == columns.size() && K.n_nonzero_elements() == values.size();
        std::size_t k    = 0;
        for (unsigned int i = 0; same && i < sp.n_rows(); ++i)
          {
            same = (columns[i] == sp.row_length(i));
            for (auto it = K.begin(i); same && it != K.end(i); ++it, ++k)
              same = (it->column() == indices[k] && it->value() == values[k]);
          }
        if (same)
          return true;
        columns.assign(sp.n_rows(), 0);
        indices.clear();
        values.clear();
        for (unsigned int i = 0; i < sp.n_rows(); ++i)
          {
            columns[i] = sp.row_length(i);
            for (auto it = K.begin(i); it != K.end(i); ++it)
              {
                indices.push_back(it->column());
                values.push_back(it->value());
              }
          }
        valid = false;
        matrix.reinit(K);
        list = Teuchos::ParameterList();
        set_ml_parameters(&list, modes, K.m(), null_space);
        amg.initialize(matrix.trilinos_matrix(), list);
        valid = true;
        return false;
      }

      const dealii::TrilinosWrappers::PreconditionAMG &
      preconditioner() const
      {
        return amg;
      }

    private:
      bool                                      valid = false;
      std::vector<unsigned int>                 columns;
      std::vector<unsigned int>                 indices;
      std::vector<double>                       values;
      dealii::TrilinosWrappers::SparseMatrix    matrix;
      Teuchos::ParameterList                    list;
      std::vector<double>                       null_space;
      dealii::TrilinosWrappers::PreconditionAMG amg;
    };
  } // namespace internal



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
    if (is_condensed(settings.type))
      {
        // a length scale for the consistency test of redundant constraints:
        // the coordinates in the rotation mode
        double length = 0;
        if (modes.size() == 3)
          for (const double v : modes[2])
            length = std::max(length, std::abs(v));
        ContactConstraints contact;
        contact.reinit(A, n_displacements, b, length);
        n_dropped = contact.get_dependent_rows().size();
        dealii::SparsityPattern      sparsity;
        dealii::SparseMatrix<double> K;
        dealii::Vector<double>       f;
        contact.condense(A, b, sparsity, K, f);
        used_gmres = !contact.is_symmetric();
        dealii::Vector<double> u(n_displacements);
        if (settings.type == Type::direct_constraints)
          {
            // Cholesky of the symmetric condensed stiffness; LU where it is
            // not positive definite, or not symmetric (slipping pairs)
            if (!cholesky)
              cholesky = std::make_shared<internal::SparseCholesky>();
            used_lu_fallback = used_gmres || !cholesky->factorize(K);
            if (used_lu_fallback)
              internal::solve_direct(K, u, f, false);
            else
              cholesky->solve(u, f);
            iterations = 1;
          }
        else
          {
            // CG (GMRES when slipping pairs make the condensed matrix
            // non-symmetric) with ML AMG, or with the two-subspace
            // preconditioner of the stick springs
            if (settings.warm_start && previous.size() == n_displacements)
              u = previous;
            std::unique_ptr<StickPreconditioner> stick;
            if (!stick_rows.empty())
              stick = std::make_unique<StickPreconditioner>(K, contact.get_constraints(), stick_rows, modes, length);
            else
              {
                // AMG on the symmetric part C^T K C: GMRES on Z^T K C needs
                // fewer iterations with it than with AMG on Z^T K C itself
                // (measured: 96-108 against 100-144 per Newton iteration on a
                // 56k-DoF sliding patch test)
                dealii::SparsityPattern      sp_sym;
                dealii::SparseMatrix<double> K_sym;
                dealii::Vector<double>       f_sym;
                if (used_gmres)
                  contact.condense(A, b, sp_sym, K_sym, f_sym, true);
                if (!amg_cache)
                  amg_cache = std::make_shared<internal::AMGCache>();
                dealii::Timer setup;
                if (amg_cache->prepare(used_gmres ? K_sym : K, modes))
                  ++n_amg_reuses;
                else
                  {
                    ++n_amg_setups;
                    amg_setup_seconds += setup.wall_time();
                  }
              }
            used_stick_preconditioner = (stick != nullptr);
            dealii::SolverControl control(settings.max_iterations, settings.relative_tolerance * f.l2_norm());
            try
              {
                if (used_gmres)
                  {
                    dealii::SolverGMRES<dealii::Vector<double>>::AdditionalData data(200, true);
                    dealii::SolverGMRES<dealii::Vector<double>> gmres(control, data);
                    if (stick)
                      gmres.solve(K, u, f, *stick);
                    else
                      gmres.solve(K, u, f, amg_cache->preconditioner());
                  }
                else
                  {
                    dealii::SolverCG<dealii::Vector<double>> cg(control);
                    if (stick)
                      cg.solve(K, u, f, *stick);
                    else
                      cg.solve(K, u, f, amg_cache->preconditioner());
                  }
              }
            catch (const dealii::SolverControl::NoConvergence &e)
              {
                AssertThrow(false,
                            dealii::ExcMessage(std::string(used_gmres ? "GMRES" : "CG") +
                                               "-AMG on the condensed contact problem" +
                                               (stick ? " (stick penalty)" : "") + " did not converge: residual " +
                                               std::to_string(e.last_residual) + " after " +
                                               std::to_string(e.last_step) + " iterations (target " +
                                               std::to_string(control.tolerance()) + ")."));
              }
            iterations = control.last_step();
            previous   = u;
            internal::check_residual(K, u, f, settings.relative_tolerance,
                                     description() + (context.empty() ? "" : ", " + context));
          }
        stick_rows.clear();
        for (unsigned int i = 0; i < n_displacements; ++i)
          x[i] = u[i];
        contact.distribute_and_recover_multipliers(A, b, x);
      }
    else if (settings.type != Type::gmres_amg)
      {
        internal::solve_direct(A, x, b, settings.type == Type::klu);
        iterations = 1;
      }
    else
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
    for (unsigned int i = 0; i < x.size(); ++i)
      AssertThrow(std::isfinite(x[i]),
                  dealii::ExcMessage("The saddle-point solver produced a non-finite value: the "
                                     "system is singular (is every body supported?)."));
    // the residual of the system that was solved (the condensed solve
    // checks its CG and recovers the multipliers from the residual)
    if (settings.type != Type::cg_amg_constraints)
      internal::check_residual(A, x, b, settings.type == Type::gmres_amg ? settings.relative_tolerance : 0.,
                               type_name(settings.type) + (context.empty() ? "" : ", " + context));
  }
} // namespace dealvem
