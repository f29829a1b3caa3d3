// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/timer.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <dealvem/solvers/linear_solver.h>

#include "two_level_cycle.h"

#include <Epetra_CrsMatrix.h>
#include <Epetra_IntSerialDenseVector.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <Teuchos_ParameterList.hpp>
#include <ml_MultiLevelPreconditioner.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>

namespace dealvem
{
  namespace internal
  {
    void
    set_ml_parameters(void                                   *list_ptr,
                      const std::vector<std::vector<double>> &modes,
                      const unsigned int                      n,
                      std::vector<double>                    &storage)
    {
      set_ml_parameters(list_ptr, modes, n, storage, LinearSolver::AMGSettings());
    }



    void
    set_ml_parameters(void                                   *list_ptr,
                      const std::vector<std::vector<double>> &modes,
                      const unsigned int                      n,
                      std::vector<double>                    &storage,
                      const LinearSolver::AMGSettings        &amg)
    {
      AssertThrow(amg.smoother_sweeps >= 1, dealii::ExcMessage("AMG: at least one smoother sweep is needed."));
      AssertThrow(amg.aggregation_threshold >= 0 && amg.aggregation_threshold < 1,
                  dealii::ExcMessage("AMG: the aggregation threshold must lie in [0, 1)."));
      Teuchos::ParameterList &list = *static_cast<Teuchos::ParameterList *>(list_ptr);
      ML_Epetra::SetDefaults(amg.elliptic ? "SA" : "NSSA", list);
      list.set("ML output", 0);
      list.set("smoother: type", amg.smoother_type);
      list.set("smoother: sweeps", int(amg.smoother_sweeps));
      list.set("aggregation: threshold", amg.aggregation_threshold);
      if (amg.uncoupled_aggregation)
        list.set("aggregation: type", "Uncoupled");
      list.set("coarse: type", "Amesos-KLU");
      list.set("coarse: max size", 2000);
      if (modes.size() == 3 && !amg.use_rotation)
        {
          // the two translations, as ML's own constant modes for 2 PDEs
          list.set("PDE equations", 2);
          storage.clear();
        }
      else if (modes.size() == 3)
        {
          storage.resize(3 * n);
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int i = 0; i < n; ++i)
              storage[k * n + i] = modes[k][i];
          list.set("null space: type", "pre-computed");
          list.set("null space: dimension", 3);
          list.set("null space: vectors", storage.data());
        }
      else if (modes.size() == 6 && !amg.use_rotation)
        {
          // 3D: the three translations as ML's constant modes
          list.set("PDE equations", 3);
          storage.clear();
        }
      else if (modes.size() == 6)
        {
          // 3D: three translations and three rotations
          storage.resize(6 * n);
          for (unsigned int k = 0; k < 6; ++k)
            for (unsigned int i = 0; i < n; ++i)
              storage[k * n + i] = modes[k][i];
          list.set("PDE equations", 3);
          list.set("null space: type", "pre-computed");
          list.set("null space: dimension", 6);
          list.set("null space: vectors", storage.data());
        }
      else
        list.set("PDE equations", 2);
    }


    namespace
    {
      // r = b - A x and the componentwise backward error of x
      double
      backward_error(const dealii::SparseMatrix<double> &A,
                     const dealii::Vector<double>       &x,
                     const dealii::Vector<double>       &b,
                     dealii::Vector<double>             &r)
      {
        r.reinit(b.size());
        double omega = 0;
        for (unsigned int i = 0; i < A.m(); ++i)
          {
            double s = b[i], size = std::abs(b[i]);
            for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it)
              {
                const double t = it->value() * x[it->column()];
                s -= t;
                size += std::abs(t);
              }
            r[i] = s;
            if (s != 0)
              omega = std::max(omega, size > 0 ? std::abs(s) / size : std::numeric_limits<double>::infinity());
          }
        return omega;
      }
    } // namespace



    double
    solve_direct(const dealii::SparseMatrix<double> &A,
                 dealii::Vector<double>             &x,
                 const dealii::Vector<double>       &b,
                 const bool                          use_klu)
    {
      // the factors, kept for the refinement (Trilinos objects only for
      // KLU: they need MPI, which a program using UMFPACK need not start)
      dealii::SparseDirectUMFPACK                             umfpack;
      std::unique_ptr<dealii::TrilinosWrappers::SparseMatrix> At;
      dealii::SolverControl                                   control(1, 0);
      const dealii::TrilinosWrappers::SolverDirect::AdditionalData data(false, "Amesos_Klu");
      std::unique_ptr<dealii::TrilinosWrappers::SolverDirect>      klu;
      dealii::LinearAlgebra::distributed::Vector<double>           kx, kb;
      if (!use_klu)
        umfpack.initialize(A);
      else
        {
          At = std::make_unique<dealii::TrilinosWrappers::SparseMatrix>();
          copy_to_trilinos(A, *At);
          klu = std::make_unique<dealii::TrilinosWrappers::SolverDirect>(control, data);
          klu->initialize(*At);
          kx.reinit(b.size());
          kb.reinit(b.size());
        }
      const auto apply = [&](dealii::Vector<double> &y, const dealii::Vector<double> &rhs) {
        y.reinit(rhs.size());
        if (!use_klu)
          umfpack.vmult(y, rhs);
        else
          {
            for (unsigned int i = 0; i < rhs.size(); ++i)
              kb[i] = rhs[i];
            klu->solve(kx, kb);
            for (unsigned int i = 0; i < rhs.size(); ++i)
              y[i] = kx[i];
          }
      };
      apply(x, b);
      dealii::Vector<double> r, d, x_new, r_new;
      double                 omega = backward_error(A, x, b, r);
      const double           eps   = std::numeric_limits<double>::epsilon();
      for (unsigned int step = 0; step < 3 && omega > 4 * eps && std::isfinite(omega); ++step)
        {
          apply(d, r);
          x_new = x;
          x_new += d;
          const double omega_new = backward_error(A, x_new, b, r_new);
          if (!(omega_new <= 0.5 * omega))
            break;
          x.swap(x_new);
          r.swap(r_new);
          omega = omega_new;
        }
      return omega;
    }



    double
    check_residual(const dealii::SparseMatrix<double> &A,
                   const dealii::Vector<double>       &x,
                   const dealii::Vector<double>       &b,
                   const double                        relative_tolerance,
                   const std::string                  &solver)
    {
      dealii::Vector<double> r(b.size());
      A.residual(r, x, b);
      return check_residual(r, x, b, relative_tolerance, solver, [&A]() {
        double a_norm = 0;
        for (unsigned int i = 0; i < A.m(); ++i)
          {
            double row = 0;
            for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it)
              row += std::abs(it->value());
            a_norm = std::max(a_norm, row);
          }
        return a_norm;
      });
    }



    double
    check_residual(const dealii::Vector<double>  &r,
                   const dealii::Vector<double>  &x,
                   const dealii::Vector<double>  &b,
                   const double                   relative_tolerance,
                   const std::string             &solver,
                   const std::function<double()> &matrix_norm)
    {
      const double r_norm = r.l2_norm(), b_norm = b.l2_norm();
      const double relative = (b_norm > 0 ? r_norm / b_norm : r_norm);
      // an iterative solve within its tolerance passes without the norm of
      // A below (a pass over the matrix: on the 100-block wall of
      // benchmarks/assembly, eight checks of a unilateral solve)
      if (relative_tolerance > 0 && relative <= 10 * relative_tolerance && std::isfinite(relative))
        return relative;
      std::ostringstream msg;
      msg.precision(4);
      // the normwise backward error: about eps for a stable direct solve,
      // and the floor of the true residual of an iterative one (whose
      // recursively updated residual may fall below it)
      const double a_norm = matrix_norm();
      const double eta = r.linfty_norm() / (a_norm * x.linfty_norm() + b.linfty_norm());
      if (r.linfty_norm() == 0 || eta <= 1e-10)
        return relative;
      if (relative_tolerance == 0)
        msg << "The direct solve (" << solver << ") is inaccurate: the normwise backward error of its "
            << "solution, |b - Ax| / (|A| |x| + |b|) in the max norm, is " << eta
            << " (tolerance 1e-10; |b - Ax| = " << r.linfty_norm() << ", |A| = " << a_norm
            << ", |x| = " << x.linfty_norm() << ", |b| = " << b.linfty_norm()
            << "): the matrix is numerically singular or too ill-conditioned for double precision.";
      else
        {
          msg << "The iterative solve (" << solver << ") is inaccurate: its residual |b - Ax| / |b| is "
              << relative << ", more than 10 times its relative tolerance " << relative_tolerance
              << ", and its normwise backward error " << eta << " exceeds 1e-10.";
        }
      AssertThrow(false, dealii::ExcMessage(msg.str()));
      return relative;
    }



    std::string
    upper_case(const std::string &name)
    {
      std::string n = name;
      std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::toupper(c); });
      return n;
    }
  } // namespace internal



  namespace internal
  {
    void
    restrict_prolongation(const dealii::SparseMatrix<double>      &P,
                          const std::vector<bool>                 &decoupled,
                          const dealii::AffineConstraints<double> *lines,
                          dealii::SparsityPattern                 &sparsity,
                          dealii::SparseMatrix<double>            &Pc)
    {
      const unsigned int m = P.m(), n_coarse = P.n();
      const auto         none = dealii::numbers::invalid_unsigned_int;
      // the coarse DoF each fine row copies (a vertex value), if any
      std::vector<unsigned int> copy_of(m, none);
      for (unsigned int i = 0; i < m; ++i)
        {
          unsigned int n_nonzero = 0, column = 0;
          double       value     = 0;
          for (auto it = P.begin(i), it_end = P.end(i); it != it_end; ++it)
            if (it->value() != 0.)
              {
                ++n_nonzero;
                column = it->column();
                value  = it->value();
              }
          if (n_nonzero == 1 && value == 1.)
            copy_of[i] = column;
        }
      // coarse DoFs copied from decoupled fine DoFs: decoupled themselves,
      // and where the fine DoF's constraint line has vertex values only,
      // replaced by that line on the coarse level
      enum : unsigned char
      {
        free_dof,
        decoupled_dof,
        replaced_dof
      };
      std::vector<unsigned char>                                 state(n_coarse, free_dof);
      std::vector<std::vector<std::pair<unsigned int, double>>> coarse_line(n_coarse);
      for (unsigned int i = 0; i < m; ++i)
        if (decoupled[i] && copy_of[i] != none)
          {
            const unsigned int c = copy_of[i];
            state[c]             = decoupled_dof;
            if (lines == nullptr || !lines->is_constrained(i))
              continue;
            const auto *entries = lines->get_constraint_entries(i);
            if (entries == nullptr)
              continue;
            bool                                         vertices_only = true;
            std::vector<std::pair<unsigned int, double>> line;
            for (const auto &e : *entries)
              {
                if (e.first >= m || e.second == 0.)
                  continue;
                if (decoupled[e.first])
                  continue; // a fixed DoF: no motion to follow
                if (copy_of[e.first] == none)
                  {
                    vertices_only = false;
                    break;
                  }
                line.emplace_back(copy_of[e.first], e.second);
              }
            if (vertices_only && !line.empty())
              {
                state[c]       = replaced_dof;
                coarse_line[c] = std::move(line);
              }
          }

      const auto for_each_entry = [&](const unsigned int i, const auto &action) {
        if (decoupled[i])
          {
            if (copy_of[i] != none)
              action(copy_of[i], 1.);
            return;
          }
        for (auto it = P.begin(i), it_end = P.end(i); it != it_end; ++it)
          {
            const unsigned int c = it->column();
            if (it->value() == 0. || state[c] == decoupled_dof)
              continue;
            if (state[c] == free_dof)
              action(c, it->value());
            else
              for (const auto &e : coarse_line[c])
                action(e.first, it->value() * e.second);
          }
      };
      dealii::DynamicSparsityPattern dsp(m, n_coarse);
      for (unsigned int i = 0; i < m; ++i)
        for_each_entry(i, [&](const unsigned int c, const double) { dsp.add(i, c); });
      sparsity.copy_from(dsp);
      Pc.reinit(sparsity);
      for (unsigned int i = 0; i < m; ++i)
        for_each_entry(i, [&](const unsigned int c, const double v) { Pc.add(i, c, v); });
    }



    std::unique_ptr<Epetra_CrsMatrix>
    epetra_from_rows(const unsigned int                                        m,
                     const unsigned int                                        n,
                     const std::vector<int>                                   &lengths,
                     const std::function<void(unsigned int, int *, double *)> &fill)
    {
      AssertThrow(lengths.size() == m, dealii::ExcMessage("epetra_from_rows: one length per row."));
      // one process; local indices are the global ones
      const Epetra_MpiComm comm(MPI_COMM_SELF);
      const Epetra_Map     rows(static_cast<int>(m), 0, comm), columns(static_cast<int>(n), 0, comm);
      auto                 copy = std::make_unique<Epetra_CrsMatrix>(Copy, rows, columns, 0, false);
      // the compressed rows written in place (Epetra's expert interface,
      // which EpetraExt's products use): no insertion per row, no sorting
      // and no copy into optimized storage by FillComplete() (at 24k DoFs
      // 6 of the 9 ms of a copy; the fresh memory is touched once)
      Epetra_IntSerialDenseVector &offsets = copy->ExpertExtractIndexOffset();
      Epetra_IntSerialDenseVector &indices = copy->ExpertExtractIndices();
      double                     *&values  = copy->ExpertExtractValues();
      AssertThrow(offsets.Resize(static_cast<int>(m) + 1) == 0, dealii::ExcMessage("epetra_from_rows: no memory."));
      std::size_t nnz = 0;
      for (unsigned int i = 0; i < m; ++i)
        {
          offsets[i] = static_cast<int>(nnz);
          nnz += static_cast<std::size_t>(lengths[i]);
          AssertThrow(nnz <= static_cast<std::size_t>(std::numeric_limits<int>::max()),
                      dealii::ExcMessage("epetra_from_rows: more entries than Epetra's int indices hold."));
        }
      offsets[m] = static_cast<int>(nnz);
      AssertThrow(indices.Resize(static_cast<int>(nnz)) == 0, dealii::ExcMessage("epetra_from_rows: no memory."));
      delete[] values;
      values                 = new double[std::max<std::size_t>(nnz, 1)];
      int *const column_data = indices.Values();
      for (unsigned int i = 0; i < m; ++i)
        fill(i, column_data + offsets[i], values + offsets[i]);
      AssertThrow(copy->ExpertStaticFillComplete(columns, rows) == 0,
                  dealii::ExcMessage("epetra_from_rows: ExpertStaticFillComplete() failed."));
      return copy;
    }



    std::unique_ptr<Epetra_CrsMatrix>
    epetra_copy(const dealii::SparseMatrix<double> &A, const double drop_tolerance)
    {
      const auto        &sp = A.get_sparsity_pattern();
      const unsigned int m = A.m(), n = A.n();
      std::vector<int>   lengths(m);
      for (unsigned int i = 0; i < m; ++i)
        lengths[i] = static_cast<int>(sp.row_length(i));
      const bool square = (m == n);
      return epetra_from_rows(m, n, lengths, [&](const unsigned int i, int *columns, double *values) {
        int k = 0;
        for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it, ++k)
          {
            columns[k] = static_cast<int>(it->column());
            values[k]  = (std::abs(it->value()) > drop_tolerance ? it->value() : 0.);
          }
        // deal.II lists a square matrix's diagonal first, then the other
        // columns ascending: Epetra's rows are ascending throughout
        if (square)
          for (int d = 0; d + 1 < k && columns[d + 1] < columns[d]; ++d)
            {
              std::swap(columns[d], columns[d + 1]);
              std::swap(values[d], values[d + 1]);
            }
      });
    }



    bool
    single_precision_values(const dealii::TrilinosWrappers::SparseMatrix &A,
                            const int                                   *&offsets,
                            const int                                   *&indices,
                            std::unique_ptr<float[]>                     &values)
    {
      values.reset();
      const Epetra_CrsMatrix &E    = A.trilinos_matrix();
      const Epetra_Map       &rows = E.RowMap(), &columns = E.ColMap();
      const auto              identity = [](const Epetra_Map &map, const long long n) {
        return map.LinearMap() && map.NumMyElements() == n && map.NumGlobalElements() == n && map.MinMyGID() == 0;
      };
      if (!identity(rows, A.m()) || !identity(columns, A.n()) || !E.StorageOptimized())
        return false;
      int    *offset_data = nullptr, *index_data = nullptr;
      double *value_data = nullptr;
      if (E.ExtractCrsDataPointers(offset_data, index_data, value_data) != 0)
        return false;
      offsets               = offset_data;
      indices               = index_data;
      const std::size_t nnz = offset_data[A.m()];
      values.reset(new float[nnz]); // (not zeroed: every value is written)
      for (std::size_t k = 0; k < nnz; ++k)
        values[k] = static_cast<float>(value_data[k]);
      return true;
    }



    void
    copy_to_trilinos(const dealii::SparseMatrix<double>     &A,
                     dealii::TrilinosWrappers::SparseMatrix &At,
                     const double                            drop_tolerance)
    {
      // (reinit() from an Epetra matrix copies its graph and its values as
      // one block each)
      At.reinit(*epetra_copy(A, drop_tolerance));
    }



    std::unique_ptr<TwoLevelCycle<dealii::Vector<double>>>
    make_serial_two_level(const dealii::SparseMatrix<double>           &A,
                          const dealii::TrilinosWrappers::SparseMatrix &At,
                          const dealii::SparseMatrix<double>           &P,
                          const std::vector<std::vector<double>>       &coarse_modes,
                          const dealii::AffineConstraints<double>      *lines,
                          const LinearSolver::Settings                 &settings,
                          dealii::TrilinosWrappers::SparseMatrix       &Pt)
    {
      // DoFs whose rows carry no coupling: constrained and condensed.
      std::vector<bool> decoupled(A.m(), true);
      for (unsigned int i = 0; i < A.m(); ++i)
        for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it)
          if (it->column() != i && it->value() != 0.)
            {
              decoupled[i] = false;
              break;
            }
      return make_serial_two_level(decoupled, At, P, coarse_modes, lines, settings, Pt);
    }



    std::unique_ptr<TwoLevelCycle<dealii::Vector<double>>>
    make_serial_two_level(const std::vector<bool>                      &decoupled,
                          const dealii::TrilinosWrappers::SparseMatrix &At,
                          const dealii::SparseMatrix<double>           &P,
                          const std::vector<std::vector<double>>       &coarse_modes,
                          const dealii::AffineConstraints<double>      *lines,
                          const LinearSolver::Settings                 &settings,
                          dealii::TrilinosWrappers::SparseMatrix       &Pt)
    {
      AssertThrow(P.m() == decoupled.size(),
                  dealii::ExcMessage("p-multigrid: the prolongation has " + std::to_string(P.m()) +
                                     " rows but the matrix " + std::to_string(decoupled.size()) + "."));
      dealii::SparsityPattern      sparsity;
      dealii::SparseMatrix<double> Pc;
      restrict_prolongation(P, decoupled, lines, sparsity, Pc);
      copy_to_trilinos(Pc, Pt, 0.);
      return std::make_unique<TwoLevelCycle<dealii::Vector<double>>>(At, Pt, coarse_modes, settings, MPI_COMM_SELF);
    }
  } // namespace internal



  namespace
  {
    /// LinearSolver's p-multigrid: the shared two-level cycle on the
    /// serial matrix.
    class TwoLevelPreconditioner
    {
    public:
      TwoLevelPreconditioner(const dealii::SparseMatrix<double>           &A,
                             const dealii::TrilinosWrappers::SparseMatrix &At,
                             const dealii::SparseMatrix<double>           &P,
                             const std::vector<std::vector<double>>       &coarse_modes,
                             const LinearSolver::Settings                 &settings)
      {
        cycle = internal::make_serial_two_level(A, At, P, coarse_modes, nullptr, settings, Pt);
      }

      void
      vmult(dealii::Vector<double> &x, const dealii::Vector<double> &b) const
      {
        cycle->vmult(x, b);
      }

    private:
      dealii::TrilinosWrappers::SparseMatrix                            Pt;
      std::unique_ptr<internal::TwoLevelCycle<dealii::Vector<double>>> cycle;
    };
  } // namespace



  LinearSolver::Type
  LinearSolver::parse_type(const std::string &name)
  {
    const std::string n = internal::upper_case(name);
    if (n == "UMFPACK")
      return Type::umfpack;
    if (n == "KLU")
      return Type::klu;
    if (n == "CG-AMG")
      return Type::cg_amg;
    AssertThrow(false, dealii::ExcMessage("Unknown linear solver '" + name +
                                          "': expected UMFPACK, KLU or CG-AMG."));
    return Type::umfpack;
  }



  std::string
  LinearSolver::type_name(const Type t)
  {
    return t == Type::umfpack ? "UMFPACK" : (t == Type::klu ? "KLU" : "CG-AMG");
  }



  LinearSolver::Preconditioner
  LinearSolver::parse_preconditioner(const std::string &name)
  {
    const std::string n = internal::upper_case(name);
    if (n == "AUTOMATIC")
      return Preconditioner::automatic;
    if (n == "AMG")
      return Preconditioner::amg;
    if (n == "P-MULTIGRID")
      return Preconditioner::p_multigrid;
    AssertThrow(false, dealii::ExcMessage("Unknown preconditioner '" + name +
                                          "': expected automatic, AMG or p-multigrid."));
    return Preconditioner::automatic;
  }



  std::string
  LinearSolver::preconditioner_name(const Preconditioner p)
  {
    return p == Preconditioner::automatic ? "automatic" : (p == Preconditioner::amg ? "AMG" : "p-multigrid");
  }



  LinearSolver::LinearSolver(const Settings &settings)
    : settings(settings)
  {}



  void
  LinearSolver::set_coarse_space(const dealii::SparseMatrix<double>     &P,
                                 const std::vector<std::vector<double>> &m)
  {
    internal::check_coarse_space(P, m);
    prolongation = &P;
    coarse_modes = m;
  }



  LinearSolver::Preconditioner
  LinearSolver::effective_preconditioner() const
  {
    if (settings.preconditioner == Preconditioner::automatic)
      return prolongation ? Preconditioner::p_multigrid : Preconditioner::amg;
    AssertThrow(settings.preconditioner != Preconditioner::p_multigrid || prolongation,
                dealii::ExcMessage("The p-multigrid preconditioner needs the coarse space: call "
                                   "LinearSolver::set_coarse_space() (e.g. with PMultigrid::make_prolongation())."));
    return settings.preconditioner;
  }



  void
  LinearSolver::set_near_null_space(const std::vector<std::vector<double>> &m)
  {
    modes = m;
  }



  std::string
  LinearSolver::description() const
  {
    switch (settings.type)
      {
        case Type::umfpack:
          return "UMFPACK (SuiteSparse, direct)";
        case Type::klu:
          return "KLU (Trilinos Amesos, direct)";
        default:
          if (effective_preconditioner() == Preconditioner::p_multigrid)
            return "CG + two-level p-multigrid (Chebyshev(" + std::to_string(settings.smoother_degree) +
                   ") on k = 2, ML AMG on the Galerkin k = 1 level)";
          return "CG + ML AMG (" +
                 std::to_string(modes.size() == 6 ? (settings.amg.use_rotation ? 6 : 3) :
                                                    (modes.size() == 3 && settings.amg.use_rotation ? 3 : 2)) +
                 " near-null-space vectors)";
      }
  }



  void
  LinearSolver::solve(const dealii::SparseMatrix<double> &A,
                      dealii::Vector<double>             &x,
                      const dealii::Vector<double>       &b)
  {
    x.reinit(b.size());
    if (settings.type != Type::cg_amg)
      {
        internal::solve_direct(A, x, b, settings.type == Type::klu);
        iterations = 1;
        setup_time = 0;
      }
    else
      {
        dealii::Timer timer;
        // everything the iteration needs, built before it (setup_time)
        dealii::TrilinosWrappers::SparseMatrix At;
        internal::copy_to_trilinos(A, At);
        // the near-null space in storage is read by ML: it must outlive amg
        Teuchos::ParameterList                    list;
        std::vector<double>                       storage;
        dealii::TrilinosWrappers::PreconditionAMG amg;
        std::unique_ptr<TwoLevelPreconditioner>   two_level;
        const bool pmg = effective_preconditioner() == Preconditioner::p_multigrid;
        if (pmg)
          two_level = std::make_unique<TwoLevelPreconditioner>(A, At, *prolongation, coarse_modes, settings);
        else
          {
            internal::set_ml_parameters(&list, modes, A.m(), storage, settings.amg);
            amg.initialize(At.trilinos_matrix(), list);
          }
        setup_time = timer.wall_time();

        dealii::SolverControl control(settings.max_iterations, settings.relative_tolerance * b.l2_norm());
        dealii::SolverCG<dealii::Vector<double>> cg(control);
        try
          {
            if (pmg)
              cg.solve(At, x, b, *two_level);
            else
              cg.solve(At, x, b, amg);
          }
        catch (const dealii::SolverControl::NoConvergence &e)
          {
            AssertThrow(false, dealii::ExcMessage(std::string(pmg ? "CG with p-multigrid" : "CG-AMG") +
                                                  " did not converge: residual " +
                                                  std::to_string(e.last_residual) + " after " +
                                                  std::to_string(e.last_step) + " iterations (target " +
                                                  std::to_string(control.tolerance()) + ")."));
          }
        iterations = control.last_step();
      }
    for (unsigned int i = 0; i < x.size(); ++i)
      if (!std::isfinite(x[i]))
        {
          // the rigid-body support is checked before a solve, so the usual
          // cause is a solution beyond double precision: give its scale
          std::ostringstream msg;
          msg << "The linear solver produced a non-finite value (unknown " << i << ", right-hand side up to "
              << b.linfty_norm()
              << "): the solution overflows double precision, because the loads are far too large for the "
                 "stiffness, or the system is singular (is the body supported?).";
          AssertThrow(false, dealii::ExcMessage(msg.str()));
        }
    // the residual of the system that was solved
    internal::check_residual(A, x, b, settings.type == Type::cg_amg ? settings.relative_tolerance : 0.,
                             description());
  }
} // namespace dealvem
