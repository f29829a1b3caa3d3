// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <dealvem/solvers/linear_solver.h>

#include <Teuchos_ParameterList.hpp>
#include <ml_MultiLevelPreconditioner.h>

#include <algorithm>
#include <cctype>

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
      Teuchos::ParameterList &list = *static_cast<Teuchos::ParameterList *>(list_ptr);
      ML_Epetra::SetDefaults("SA", list);
      list.set("ML output", 0);
      list.set("smoother: type", "Chebyshev");
      list.set("smoother: sweeps", 2);
      list.set("aggregation: threshold", 1e-4);
      list.set("coarse: type", "Amesos-KLU");
      list.set("coarse: max size", 2000);
      if (modes.size() == 3)
        {
          storage.resize(3 * n);
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int i = 0; i < n; ++i)
              storage[k * n + i] = modes[k][i];
          list.set("null space: type", "pre-computed");
          list.set("null space: dimension", 3);
          list.set("null space: vectors", storage.data());
        }
      else
        list.set("PDE equations", 2);
    }


    void
    solve_direct(const dealii::SparseMatrix<double> &A,
                 dealii::Vector<double>             &x,
                 const dealii::Vector<double>       &b,
                 const bool                          use_klu)
    {
      if (!use_klu)
        {
          dealii::SparseDirectUMFPACK direct;
          direct.initialize(A);
          direct.vmult(x, b);
          return;
        }
      dealii::TrilinosWrappers::SparseMatrix At;
      At.reinit(A);
      dealii::SolverControl                                  control(1, 0);
      dealii::TrilinosWrappers::SolverDirect::AdditionalData data(false, "Amesos_Klu");
      dealii::TrilinosWrappers::SolverDirect                 direct(control, data);
      direct.solve(At, x, b);
    }



    std::string
    upper_case(const std::string &name)
    {
      std::string n = name;
      std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::toupper(c); });
      return n;
    }
  } // namespace internal



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



  LinearSolver::LinearSolver(const Settings &settings)
    : settings(settings)
  {}



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
          return "CG + ML AMG (" + std::to_string(modes.size() == 3 ? 3 : 2) + " near-null-space vectors)";
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
      }
    else
      {
        dealii::TrilinosWrappers::SparseMatrix At;
        At.reinit(A);
        Teuchos::ParameterList list;
        std::vector<double>    storage;
        internal::set_ml_parameters(&list, modes, A.m(), storage);
        dealii::TrilinosWrappers::PreconditionAMG amg;
        amg.initialize(At.trilinos_matrix(), list);
        dealii::SolverControl control(settings.max_iterations, settings.relative_tolerance * b.l2_norm());
        dealii::SolverCG<dealii::Vector<double>> cg(control);
        try
          {
            cg.solve(At, x, b, amg);
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
    for (unsigned int i = 0; i < x.size(); ++i)
      AssertThrow(std::isfinite(x[i]), dealii::ExcMessage("The linear solver produced a non-finite value: "
                                                          "the system is singular (is the body supported?)."));
  }
} // namespace dealvem
