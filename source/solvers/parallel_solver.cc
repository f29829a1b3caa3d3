// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dealvem/solvers/parallel_solver.h>

#include <Teuchos_ParameterList.hpp>

#include <cmath>

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



  std::string
  ParallelLinearSolver::description() const
  {
    const std::string where = " on " + std::to_string(n_processes) + " MPI process" + (n_processes > 1 ? "es" : "");
    if (settings.type != LinearSolver::Type::cg_amg)
      return "KLU (Trilinos Amesos, direct, factored on one process)" + where;
    return "CG + ML AMG (" + std::to_string(local_modes.size() == 3 ? 3 : 2) + " near-null-space vectors)" + where;
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
        direct.solve(A, x, b);
        iterations = 1;
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
        // ML's settings: those of the serial CG-AMG (linear_solver.cc)
        Teuchos::ParameterList list;
        std::vector<double>    storage;
        internal::set_ml_parameters(&list, local_modes, n_local, storage);
        dealii::TrilinosWrappers::PreconditionAMG amg;
        amg.initialize(A.trilinos_matrix(), list);
        dealii::SolverControl control(settings.max_iterations, settings.relative_tolerance * b.l2_norm());
        dealii::SolverCG<dealii::TrilinosWrappers::MPI::Vector> cg(control);
        try
          {
            cg.solve(A, x, b, amg);
          }
        catch (const dealii::SolverControl::NoConvergence &e)
          {
            AssertThrow(false, dealii::ExcMessage("CG-AMG did not converge: residual " +
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
  }
} // namespace dealvem
