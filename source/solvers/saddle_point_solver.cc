// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <dealvem/solvers/contact_constraints.h>
#include <dealvem/solvers/linear_solver.h>
#include <dealvem/solvers/saddle_point_solver.h>

#include <Teuchos_ParameterList.hpp>
#include <ml_MultiLevelPreconditioner.h>

#include <algorithm>
#include <cctype>
#include <cmath>

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
    if (n == "CG-AMG CONSTRAINTS")
      return Type::cg_amg_constraints;
    AssertThrow(false, dealii::ExcMessage("Unknown saddle-point solver '" + name +
                                          "': expected UMFPACK, KLU, GMRES-AMG or CG-AMG constraints."));
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
          return "CG-AMG constraints";
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



  std::string
  SaddlePointSolver::description() const
  {
    if (settings.type == Type::gmres_amg)
      return "GMRES + block preconditioner (ML AMG on K + rho B^T B, exact approximate Schur complement)";
    if (settings.type == Type::cg_amg_constraints)
      return "CG + ML AMG on the stiffness condensed by the active contact constraints (one slave DoF per "
             "constraint, multipliers from the residual)";
    return type_name(settings.type) + " (direct, whole saddle-point matrix)";
  }



  namespace
  {
    // Block lower-triangular preconditioner of the saddle-point matrix.
    class BlockPreconditioner
    {
    public:
      BlockPreconditioner(const dealii::SparseMatrix<double>     &A,
                          const unsigned int                      n,
                          const std::vector<std::vector<double>> &modes)
        : n(n)
        , m(A.m() - n)
      {
        // split A into K (n x n), B (m x n) and D (m x m)
        dealii::DynamicSparsityPattern dsp_k(n, n), dsp_b(m, n), dsp_s(m, m);
        for (unsigned int i = 0; i < A.m(); ++i)
          for (auto it = A.begin(i); it != A.end(i); ++it)
            {
              const unsigned int j = it->column();
              if (i < n && j < n)
                dsp_k.add(i, j);
              else if (i >= n && j < n)
                dsp_b.add(i - n, j);
            }
        // K_rho = K + rho B^T B: add the pattern of B^T B
        std::vector<std::vector<unsigned int>> b_rows(m);
        for (unsigned int i = n; i < A.m(); ++i)
          for (auto it = A.begin(i); it != A.end(i); ++it)
            if (it->column() < n && it->value() != 0.)
              b_rows[i - n].push_back(it->column());
        for (const auto &r : b_rows)
          for (const auto a : r)
            for (const auto b : r)
              dsp_k.add(a, b);
        sp_k.copy_from(dsp_k);
        sp_b.copy_from(dsp_b);
        K.reinit(sp_k);
        Bm.reinit(sp_b);
        double       diag_sum = 0;
        unsigned int n_diag   = 0;
        for (unsigned int i = 0; i < A.m(); ++i)
          for (auto it = A.begin(i); it != A.end(i); ++it)
            {
              const unsigned int j = it->column();
              if (i < n && j < n)
                {
                  K.set(i, j, it->value());
                  if (i == j)
                    {
                      diag_sum += std::abs(it->value());
                      ++n_diag;
                    }
                }
              else if (i >= n && j < n)
                Bm.set(i - n, j, it->value());
            }
        const double rho = (n_diag > 0 ? diag_sum / n_diag : 1.);
        for (unsigned int r = 0; r < m; ++r)
          for (auto it1 = Bm.begin(r); it1 != Bm.end(r); ++it1)
            for (auto it2 = Bm.begin(r); it2 != Bm.end(r); ++it2)
              K.add(it1->column(), it2->column(), rho * it1->value() * it2->value());

        // S = D - B diag(K_rho)^{-1} B^T
        for (unsigned int r = 0; r < m; ++r)
          dsp_s.add(r, r);
        // column lists of B for S's pattern
        std::vector<std::vector<std::pair<unsigned int, double>>> cols(n);
        for (unsigned int r = 0; r < m; ++r)
          for (auto it = Bm.begin(r); it != Bm.end(r); ++it)
            if (it->value() != 0.)
              cols[it->column()].emplace_back(r, it->value());
        for (const auto &c : cols)
          for (const auto &a : c)
            for (const auto &b : c)
              dsp_s.add(a.first, b.first);
        sp_s.copy_from(dsp_s);
        S.reinit(sp_s);
        for (unsigned int i = n; i < A.m(); ++i)
          for (auto it = A.begin(i); it != A.end(i); ++it)
            if (it->column() >= n)
              S.add(i - n, it->column() - n, it->value());
        for (unsigned int j = 0; j < n; ++j)
          {
            const double d = K.diag_element(j);
            for (const auto &a : cols[j])
              for (const auto &b : cols[j])
                S.add(a.first, b.first, -a.second * b.second / d);
          }
        S_inverse.initialize(S);

        // AMG on K_rho with the rigid-body modes
        K_trilinos.reinit(K);
        Teuchos::ParameterList list;
        internal::set_ml_parameters(&list, modes, n, null_space);
        amg.initialize(K_trilinos.trilinos_matrix(), list);
      }

      void
      vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const
      {
        dealii::Vector<double> ru(n), zu(n), rl(m), zl(m), bz(m);
        for (unsigned int i = 0; i < n; ++i)
          ru[i] = src[i];
        for (unsigned int i = 0; i < m; ++i)
          rl[i] = src[n + i];
        amg.vmult(zu, ru);
        Bm.vmult(bz, zu);
        rl -= bz;
        S_inverse.vmult(zl, rl);
        for (unsigned int i = 0; i < n; ++i)
          dst[i] = zu[i];
        for (unsigned int i = 0; i < m; ++i)
          dst[n + i] = zl[i];
      }

    private:
      const unsigned int                       n, m;
      dealii::SparsityPattern                  sp_k, sp_b, sp_s;
      dealii::SparseMatrix<double>             K, Bm, S;
      dealii::SparseDirectUMFPACK              S_inverse;
      dealii::TrilinosWrappers::SparseMatrix   K_trilinos;
      dealii::TrilinosWrappers::PreconditionAMG amg;
      std::vector<double>                      null_space;
    };
  } // namespace



  void
  SaddlePointSolver::solve(const dealii::SparseMatrix<double> &A,
                           const unsigned int                  n_displacements,
                           dealii::Vector<double>             &x,
                           const dealii::Vector<double>       &b)
  {
    AssertDimension(A.m(), b.size());
    x.reinit(b.size());
    n_dropped = 0;
    if (settings.type == Type::cg_amg_constraints)
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
        dealii::Vector<double>       f, u;
        contact.condense(A, b, sparsity, K, f);
        LinearSolver::Settings linear;
        linear.type               = LinearSolver::Type::cg_amg;
        linear.relative_tolerance = settings.relative_tolerance;
        linear.max_iterations     = settings.max_iterations;
        LinearSolver cg(linear);
        cg.set_near_null_space(modes);
        cg.solve(K, u, f);
        iterations = cg.last_iterations();
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
        BlockPreconditioner preconditioner(A, n_displacements, modes);
        dealii::SolverControl control(settings.max_iterations,
                                      settings.relative_tolerance * b.l2_norm());
        dealii::SolverGMRES<dealii::Vector<double>>::AdditionalData data(200, true);
        dealii::SolverGMRES<dealii::Vector<double>> gmres(control, data);
        try
          {
            gmres.solve(A, x, b, preconditioner);
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
      }
    for (unsigned int i = 0; i < x.size(); ++i)
      AssertThrow(std::isfinite(x[i]),
                  dealii::ExcMessage("The saddle-point solver produced a non-finite value: the "
                                     "system is singular (is every body supported?)."));
  }
} // namespace dealvem
