// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dealvem/solvers/parallel_solver.h>

#include "two_level_cycle.h"

#include <Epetra_CrsMatrix.h>
#include <Teuchos_ParameterList.hpp>

#include <cmath>
#include <limits>
#include <sstream>

namespace dealvem
{
  ParallelLinearSolver::ParallelLinearSolver(const LinearSolver::Settings &settings)
    : settings(settings)
  {}



  void
  ParallelLinearSolver::set_near_null_space(const std::vector<std::vector<double>> &modes,
                                            const dealii::IndexSet                 &owned)
  {
    local_modes.assign(modes.size(), std::vector<double>());
    for (unsigned int k = 0; k < modes.size(); ++k)
      {
        AssertThrow(modes[k].size() == owned.size(),
                    dealii::ExcMessage("ParallelLinearSolver: a near-null-space vector has " +
                                       std::to_string(modes[k].size()) + " entries, the system " +
                                       std::to_string(owned.size()) + "."));
        local_modes[k].reserve(owned.n_elements());
        // an IndexSet iterates in increasing order, the order of the
        // Epetra row map that IndexSet::make_trilinos_map() builds
        for (const auto i : owned)
          local_modes[k].push_back(modes[k][i]);
      }
  }



  void
  ParallelLinearSolver::set_coarse_space(const dealii::SparseMatrix<double>      &P,
                                         const std::vector<std::vector<double>>  &m,
                                         const dealii::AffineConstraints<double> *lines)
  {
    internal::check_coarse_space(P, m);
    prolongation     = &P;
    coarse_modes     = m;
    coarse_lines     = lines;
  }



  namespace internal
  {
    std::unique_ptr<TwoLevelCycle<dealii::TrilinosWrappers::MPI::Vector>>
    make_distributed_two_level(const dealii::TrilinosWrappers::SparseMatrix &A,
                               const dealii::SparseMatrix<double>           &P,
                               const std::vector<std::vector<double>>       &coarse_modes,
                               const dealii::AffineConstraints<double>      *lines,
                               const LinearSolver::Settings                 &settings,
                               const MPI_Comm                                comm,
                               dealii::TrilinosWrappers::SparseMatrix       &Pt)
    {
      AssertThrow(P.m() == A.m(), dealii::ExcMessage("p-multigrid: the prolongation has " + std::to_string(P.m()) +
                                                     " rows but the matrix " + std::to_string(A.m()) + "."));
      const dealii::IndexSet owned = A.locally_owned_range_indices();
      // decoupled rows (constrained DoFs), known to every process
      std::vector<unsigned int> flags(A.m(), 0);
      // (Epetra's row views: deal.II's row iterators step into the next
      // row, which need not be owned with a non-contiguous partition)
      const Epetra_CrsMatrix &M = A.trilinos_matrix();
      for (int local = 0; local < M.NumMyRows(); ++local)
        {
          int     n_entries = 0;
          double *values    = nullptr;
          int    *columns   = nullptr;
          M.ExtractMyRowView(local, n_entries, values, columns);
          const auto i = static_cast<unsigned int>(M.GRID(local));
          flags[i]     = 1;
          for (int k = 0; k < n_entries; ++k)
            if (static_cast<unsigned int>(M.GCID(columns[k])) != i && values[k] != 0.)
              {
                flags[i] = 0;
                break;
              }
        }
      dealii::Utilities::MPI::max(flags, comm, flags);
      const std::vector<bool>      decoupled(flags.begin(), flags.end());
      dealii::SparsityPattern      sparsity;
      dealii::SparseMatrix<double> Pc;
      restrict_prolongation(P, decoupled, lines, sparsity, Pc);

      // the coarse DoFs of this process: copies of its owned vertex DoFs
      dealii::IndexSet owned_coarse(P.n());
      for (const auto i : owned)
        {
          unsigned int n_entries = 0, column = 0;
          double       value     = 0;
          for (auto it = P.begin(i), it_end = P.end(i); it != it_end; ++it)
            if (it->value() != 0.)
              {
                ++n_entries;
                column = it->column();
                value  = it->value();
              }
          if (n_entries == 1 && value == 1.)
            owned_coarse.add_index(column);
        }
      owned_coarse.compress();
      AssertThrow(dealii::Utilities::MPI::sum(owned_coarse.n_elements(), comm) == P.n(),
                  dealii::ExcMessage("p-multigrid: the coarse DoFs are not owned once each (is P a "
                                     "prolongation from PMultigrid::make_prolongation()?)."));

      dealii::DynamicSparsityPattern dsp(P.m(), P.n(), owned);
      for (const auto i : owned)
        for (auto it = Pc.begin(i), it_end = Pc.end(i); it != it_end; ++it)
          dsp.add(i, it->column());
      Pt.reinit(owned, owned_coarse, dsp, comm);
      for (const auto i : owned)
        for (auto it = Pc.begin(i), it_end = Pc.end(i); it != it_end; ++it)
          Pt.set(i, it->column(), it->value());
      Pt.compress(dealii::VectorOperation::insert);

      std::vector<std::vector<double>> local(coarse_modes.size());
      for (unsigned int k = 0; k < coarse_modes.size(); ++k)
        for (const auto j : owned_coarse)
          local[k].push_back(coarse_modes[k][j]);
      return std::make_unique<TwoLevelCycle<dealii::TrilinosWrappers::MPI::Vector>>(A, Pt, local, settings, comm);
    }
  } // namespace internal



  namespace
  {
    /// The p-multigrid of ParallelLinearSolver: the shared distributed
    /// two-level cycle (internal::make_distributed_two_level()).
    class DistributedTwoLevel
    {
    public:
      DistributedTwoLevel(const dealii::TrilinosWrappers::SparseMatrix &A,
                          const dealii::SparseMatrix<double>           &P,
                          const std::vector<std::vector<double>>       &coarse_modes,
                          const dealii::AffineConstraints<double>      *lines,
                          const LinearSolver::Settings                 &settings,
                          const MPI_Comm                                comm)
      {
        cycle = internal::make_distributed_two_level(A, P, coarse_modes, lines, settings, comm, Pt);
      }

      void
      vmult(dealii::TrilinosWrappers::MPI::Vector &x, const dealii::TrilinosWrappers::MPI::Vector &b) const
      {
        cycle->vmult(x, b);
      }

    private:
      dealii::TrilinosWrappers::SparseMatrix                                          Pt;
      std::unique_ptr<internal::TwoLevelCycle<dealii::TrilinosWrappers::MPI::Vector>> cycle;
    };
  } // namespace



  std::string
  ParallelLinearSolver::description() const
  {
    const std::string where = " on " + std::to_string(n_processes) + " MPI process" + (n_processes > 1 ? "es" : "");
    if (settings.type != LinearSolver::Type::cg_amg)
      return "KLU (Trilinos Amesos, direct, factored on one process)" + where;
    const std::string krylov = settings.symmetric ? "CG" : "GMRES";
    if (used_p_multigrid)
      return krylov + " + two-level p-multigrid (Chebyshev(" + std::to_string(settings.smoother_degree) +
             ") on k = 2, ML AMG on the Galerkin k = 1 level)" + where;
    return krylov + " + ML AMG (" + std::to_string(local_modes.size() == 3 ? 3 : 2) + " near-null-space vectors)" + where;
  }



  void
  ParallelLinearSolver::solve(const dealii::TrilinosWrappers::SparseMatrix &A,
                              dealii::TrilinosWrappers::MPI::Vector        &x,
                              const dealii::TrilinosWrappers::MPI::Vector  &b)
  {
    n_processes = dealii::Utilities::MPI::n_mpi_processes(b.get_mpi_communicator());
    if (settings.type != LinearSolver::Type::cg_amg)
      {
        dealii::SolverControl                                  control(1, 0);
        dealii::TrilinosWrappers::SolverDirect::AdditionalData data(false, "Amesos_Klu");
        dealii::TrilinosWrappers::SolverDirect                 direct(control, data);
        direct.initialize(A);
        direct.solve(x, b);
        // iterative refinement with the same factors, on the componentwise
        // backward error omega = max_i |b - Ax|_i / (|A||x| + |b|)_i (as
        // internal::solve_direct() does serially): while omega > 4 eps,
        // at most three steps, each kept only if it halves omega
        Epetra_CrsMatrix abs_matrix(A.trilinos_matrix());
        for (int i = 0; i < abs_matrix.NumMyRows(); ++i)
          {
            int     n_entries = 0;
            double *values    = nullptr;
            abs_matrix.ExtractMyRowView(i, n_entries, values);
            for (int k = 0; k < n_entries; ++k)
              values[k] = std::abs(values[k]);
          }
        const auto omega_of = [&](const dealii::TrilinosWrappers::MPI::Vector &y,
                                  dealii::TrilinosWrappers::MPI::Vector       &r) {
          A.residual(r, y, b);
          dealii::TrilinosWrappers::MPI::Vector y_abs(y), size(b);
          for (const auto i : y_abs.locally_owned_elements())
            y_abs(i) = std::abs(y(i));
          y_abs.compress(dealii::VectorOperation::insert);
          abs_matrix.Multiply(false, y_abs.trilinos_vector(), size.trilinos_vector());
          double omega = 0;
          for (const auto i : r.locally_owned_elements())
            if (r(i) != 0)
              {
                const double d = size(i) + std::abs(b(i));
                omega = std::max(omega, d > 0 ? std::abs(r(i)) / d : std::numeric_limits<double>::infinity());
              }
          return dealii::Utilities::MPI::max(omega, b.get_mpi_communicator());
        };
        dealii::TrilinosWrappers::MPI::Vector r(b), d(x), x_new(x), r_new(b);
        double omega = omega_of(x, r);
        for (unsigned int step = 0; step < 3 && omega > 4 * std::numeric_limits<double>::epsilon() &&
                                    std::isfinite(omega);
             ++step)
          {
            direct.solve(d, r);
            x_new = x;
            x_new += d;
            const double omega_new = omega_of(x_new, r_new);
            if (!(omega_new <= 0.5 * omega))
              break;
            x.swap(x_new);
            r.swap(r_new);
            omega = omega_new;
          }
        iterations = 1;
        setup_time = 0;
      }
    else
      {
        const unsigned int n_local = b.locally_owned_size();
        AssertThrow(n_local == static_cast<unsigned int>(A.trilinos_matrix().RowMap().NumMyElements()),
                    dealii::ExcMessage("ParallelLinearSolver: the vector and the matrix have different row maps."));
        AssertThrow(local_modes.empty() || local_modes[0].size() == n_local,
                    dealii::ExcMessage("ParallelLinearSolver: the near-null space has " +
                                       std::to_string(local_modes[0].size()) + " local entries, the matrix " +
                                       std::to_string(n_local) + " local rows."));
        dealii::Timer timer;
        used_p_multigrid = prolongation != nullptr && settings.preconditioner != LinearSolver::Preconditioner::amg;
        AssertThrow(settings.preconditioner != LinearSolver::Preconditioner::p_multigrid || prolongation != nullptr,
                    dealii::ExcMessage("The p-multigrid preconditioner needs the coarse space: call "
                                       "ParallelLinearSolver::set_coarse_space()."));
        // ML's settings: those of the serial CG-AMG (linear_solver.cc)
        Teuchos::ParameterList                    list;
        std::vector<double>                       storage;
        dealii::TrilinosWrappers::PreconditionAMG amg;
        std::unique_ptr<DistributedTwoLevel>      two_level;
        if (used_p_multigrid)
          two_level = std::make_unique<DistributedTwoLevel>(A, *prolongation, coarse_modes, coarse_lines, settings,
                                                            b.get_mpi_communicator());
        else
          {
            internal::set_ml_parameters(&list, local_modes, n_local, storage, settings.amg);
            amg.initialize(A.trilinos_matrix(), list);
          }
        setup_time = timer.wall_time();
        dealii::SolverControl control(settings.max_iterations, settings.relative_tolerance * b.l2_norm());
        using Vector = dealii::TrilinosWrappers::MPI::Vector;
        dealii::SolverCG<Vector>    cg(control);
        dealii::SolverGMRES<Vector> gmres(control, dealii::SolverGMRES<Vector>::AdditionalData(200, true));
        const std::string           krylov = settings.symmetric ? "CG" : "GMRES";
        try
          {
            if (used_p_multigrid)
              settings.symmetric ? cg.solve(A, x, b, *two_level) : gmres.solve(A, x, b, *two_level);
            else
              settings.symmetric ? cg.solve(A, x, b, amg) : gmres.solve(A, x, b, amg);
          }
        catch (const dealii::SolverControl::NoConvergence &e)
          {
            AssertThrow(false, dealii::ExcMessage(krylov + std::string(used_p_multigrid ? " with p-multigrid" : "-AMG") +
                                                  " did not converge: residual " +
                                                  std::to_string(e.last_residual) + " after " +
                                                  std::to_string(e.last_step) + " iterations (target " +
                                                  std::to_string(control.tolerance()) + ")."));
          }
        iterations = control.last_step();
      }
    bool finite = true;
    for (const auto i : x.locally_owned_elements())
      finite = finite && std::isfinite(x(i));
    finite = dealii::Utilities::MPI::min(finite ? 1 : 0, b.get_mpi_communicator()) == 1;
    AssertThrow(finite, dealii::ExcMessage("The linear solver produced a non-finite value: "
                                           "the system is singular (is the body supported?)."));
    // the residual of the system that was solved (as internal::check_residual)
    {
      dealii::TrilinosWrappers::MPI::Vector r(b);
      A.residual(r, x, b);
      const double r_norm = r.l2_norm(), b_norm = b.l2_norm();
      std::ostringstream msg;
      msg.precision(4);
      const double eta = r.linfty_norm() / (A.linfty_norm() * x.linfty_norm() + b.linfty_norm());
      if (r.linfty_norm() == 0 || eta <= 1e-10)
        return;
      if (settings.type != LinearSolver::Type::cg_amg)
        msg << "The direct solve (KLU, " << n_processes << " MPI processes) is inaccurate: the normwise backward "
            << "error of its solution, |b - Ax| / (|A| |x| + |b|) in the max norm, is " << eta
            << " (tolerance 1e-10): the matrix is numerically singular or too ill-conditioned for double "
               "precision.";
      else
        {
          const double relative = (b_norm > 0 ? r_norm / b_norm : r_norm);
          if (relative <= 10 * settings.relative_tolerance && std::isfinite(relative))
            return;
          msg << "The iterative solve (" << (settings.symmetric ? "CG" : "GMRES") << ", " << n_processes << " MPI processes) is inaccurate: its residual |b - Ax| / |b| is "
              << relative << ", more than 10 times its relative tolerance " << settings.relative_tolerance
              << ", and its normwise backward error " << eta << " exceeds 1e-10.";
        }
      AssertThrow(false, dealii::ExcMessage(msg.str()));
    }
  }
} // namespace dealvem
