// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>

#include <dealvem/elasticity/finite_strain_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

namespace dealvem
{
  namespace
  {
    std::string
    number(const double x)
    {
      std::ostringstream s;
      s << std::setprecision(6) << x;
      return s.str();
    }

    // the additional information of a deal.II exception, on one line
    std::string
    exception_text(const dealii::ExceptionBase &e)
    {
      std::ostringstream s;
      e.print_info(s);
      std::string text = s.str();
      for (char &c : text)
        if (c == '\n')
          c = ' ';
      while (!text.empty() && text.back() == ' ')
        text.pop_back();
      return text;
    }
  } // namespace



  template <int dim>
  FiniteStrainSolver<dim>::FiniteStrainSolver(FiniteStrainAssembler<dim>              &assembler,
                                              const dealii::AffineConstraints<double> &constraints_in,
                                              const Parameters                        &parameters)
    : assembler(assembler)
    , parameters(parameters)
  {
    AssertThrow(constraints_in.is_closed(),
                dealii::ExcMessage("FiniteStrainSolver: the constraints must be closed (AffineConstraints::close())."));
    AssertThrow(parameters.n_load_steps >= 1,
                dealii::ExcMessage("FiniteStrainSolver: the number of load steps (n_load_steps) must be at least 1."));
    AssertThrow(parameters.max_iterations >= 1,
                dealii::ExcMessage("FiniteStrainSolver: max_iterations must be at least 1."));
    AssertThrow(std::isfinite(parameters.residual_tolerance) && parameters.residual_tolerance > 0,
                dealii::ExcMessage("FiniteStrainSolver: residual_tolerance must be positive, got " +
                                   number(parameters.residual_tolerance) + "."));
    AssertThrow(std::isfinite(parameters.update_tolerance) && parameters.update_tolerance > 0,
                dealii::ExcMessage("FiniteStrainSolver: update_tolerance must be positive, got " +
                                   number(parameters.update_tolerance) + "."));
    AssertThrow(std::isfinite(parameters.absolute_residual_tolerance),
                dealii::ExcMessage("FiniteStrainSolver: absolute_residual_tolerance must be finite."));

    constraints.copy_from(constraints_in);
    homogeneous_constraints.copy_from(constraints_in);
    std::vector<dealii::types::global_dof_index> lines;
    for (const auto &line : constraints.get_lines())
      lines.push_back(line.index);
    for (const auto i : lines)
      homogeneous_constraints.set_inhomogeneity(i, 0.);

    const auto &dof_handler = assembler.get_dof_handler();
    const auto  n           = dof_handler.n_dofs();
    dealii::DynamicSparsityPattern dsp(n);
    dof_handler.make_sparsity_pattern(dsp, constraints);
    sparsity.copy_from(dsp);
    tangent.reinit(sparsity);
    solution.reinit(n);
    assembler.assemble_load_vector(f_ext);

    absolute_tolerance = parameters.absolute_residual_tolerance;
    if (absolute_tolerance < 0)
      {
        const auto &vertices = dof_handler.get_mesh().get_vertices();
        dealii::Point<dim> lo = vertices.front(), hi = vertices.front();
        for (const auto &v : vertices)
          for (unsigned int d = 0; d < dim; ++d)
            {
              lo[d] = std::min(lo[d], v[d]);
              hi[d] = std::max(hi[d], v[d]);
            }
        absolute_tolerance =
          1e-12 * assembler.get_material_library().min_characteristic_stiffness() * lo.distance(hi);
      }
  }



  template <int dim>
  void
  FiniteStrainSolver<dim>::run()
  {
    for (unsigned int n = 1; n <= parameters.n_load_steps; ++n)
      solve_step(n, static_cast<double>(n) / parameters.n_load_steps);
  }



  template <int dim>
  void
  FiniteStrainSolver<dim>::solve_step(const unsigned int step, const double load_factor)
  {
    AssertThrow(std::isfinite(load_factor),
                dealii::ExcMessage("FiniteStrainSolver: the load factor of step " + std::to_string(step) +
                                   " is not finite."));
    StepRecord record;
    record.step        = step;
    record.load_factor = load_factor;

    const auto fail = [&](const std::string &reason) {
      record.converged = false;
      history.push_back(record);
      AssertThrow(false,
                  dealii::ExcMessage("FiniteStrainSolver: load step " + std::to_string(step) + " (load factor " +
                                     number(load_factor) + ") did not converge: " + reason +
                                     "\nNewton history of the step:\n" + step_history_text(record) +
                                     "The solution is kept at the last converged step (load factor " +
                                     number(current_load_factor) + ")."));
    };

    // the stabilization scaled at the last converged state (FiniteStrainOperator)
    assembler.freeze_stabilization(solution);

    dealii::Vector<double>            u = solution, r, rhs, du, u_trial, r_trial, tmp;
    dealii::AffineConstraints<double> update_constraints;
    update_constraints.copy_from(constraints);
    // the largest prescribed value, for the test that the constraints hold
    double prescribed = 0;
    for (const auto &line : constraints.get_lines())
      prescribed = std::max(prescribed, std::abs(load_factor * line.inhomogeneity));

    const auto free_norm = [&](const dealii::Vector<double> &residual) {
      tmp = residual;
      homogeneous_constraints.condense(tmp);
      return tmp.l2_norm();
    };

    const double f_ext_norm  = f_ext.l2_norm();
    double       last_update = std::numeric_limits<double>::infinity();
    std::string  inversion; // the last inverted cell met in the step
    for (unsigned int it = 0;; ++it)
      {
        // the update's constraints: what the iterate misses of
        // u_i = sum_j a_ij u_j + lambda b_i
        double mismatch = 0;
        for (const auto &line : constraints.get_lines())
          {
            double target = load_factor * line.inhomogeneity;
            for (const auto &entry : line.entries)
              target += entry.second * u[entry.first];
            const double miss = target - u[line.index];
            update_constraints.set_inhomogeneity(line.index, miss);
            mismatch = std::max(mismatch, std::abs(miss));
          }
        const bool moves_prescribed = mismatch > 1e-13 * std::max(prescribed, u.linfty_norm());

        try
          {
            assembler.assemble(u, load_factor, r, update_constraints, &tangent, &rhs);
          }
        catch (const ExcInvertedCell &e)
          {
            fail("the iterate inverts a cell: " + exception_text(e));
          }
        const double r_norm = free_norm(r);
        // the force scale at this iterate: the load or the internal forces
        // (reactions included), whichever is larger
        tmp = f_ext;
        tmp *= load_factor;
        tmp -= r;
        const double F_ref = std::max(std::abs(load_factor) * f_ext_norm, tmp.l2_norm());

        IterationRecord iteration;
        iteration.residual_norm     = r_norm;
        iteration.relative_residual = F_ref > 0 ? r_norm / F_ref : 0.;
        iteration.update_norm       = 0;
        iteration.step_length       = 0;
        if (!moves_prescribed && r_norm <= std::max(parameters.residual_tolerance * F_ref, absolute_tolerance) &&
            last_update <= parameters.update_tolerance * u.l2_norm())
          {
            record.iterations.push_back(iteration);
            record.converged = true;
            break;
          }
        if (it == parameters.max_iterations)
          {
            record.iterations.push_back(iteration);
            fail("no convergence in " + std::to_string(parameters.max_iterations) + " Newton iterations" +
                 (inversion.empty() ? std::string() :
                                      " (the line search met inverted cells, the last: " + inversion + ")"));
          }

        // the Newton direction
        dealii::SparseDirectUMFPACK direct;
        direct.initialize(tangent);
        du.reinit(u.size());
        direct.vmult(du, rhs);
        update_constraints.distribute(du);

        // backtracking: halve alpha while the trial inverts a cell or (for
        // an update that keeps the prescribed DoFs) does not decrease the
        // free residual enough
        double      alpha       = 1;
        bool        accepted    = false;
        std::string last_failure;
        for (unsigned int h = 0; h <= parameters.max_line_search_halvings; ++h, alpha *= 0.5)
          {
            u_trial = u;
            u_trial.add(alpha, du);
            try
              {
                assembler.assemble(u_trial, load_factor, r_trial, update_constraints, nullptr, nullptr);
              }
            catch (const ExcInvertedCell &e)
              {
                last_failure = exception_text(e);
                inversion    = last_failure;
                continue;
              }
            if (!parameters.line_search || moves_prescribed ||
                free_norm(r_trial) <= (1. - 1e-4 * alpha) * r_norm)
              {
                accepted = true;
                break;
              }
            last_failure = "no sufficient decrease of the residual";
          }
        if (!accepted)
          {
            // no decrease found (e.g. a residual at round-off): take the full
            // step if it inverts nothing
            alpha   = 1;
            u_trial = u;
            u_trial.add(1., du);
            try
              {
                assembler.assemble(u_trial, load_factor, r_trial, update_constraints, nullptr, nullptr);
                accepted = true;
              }
            catch (const ExcInvertedCell &e)
              {
                last_failure = exception_text(e);
                inversion    = last_failure;
              }
          }
        if (!accepted)
          {
            iteration.update_norm = du.l2_norm();
            record.iterations.push_back(iteration);
            fail("every step length of the line search, down to 2^-" +
                 std::to_string(parameters.max_line_search_halvings) + ", inverts a cell: " + last_failure);
          }
        last_update           = alpha * du.l2_norm();
        iteration.update_norm = last_update;
        iteration.step_length = alpha;
        record.iterations.push_back(iteration);
        u = u_trial;
      }
    solution            = u;
    current_load_factor = load_factor;
    history.push_back(record);
  }



  template <int dim>
  std::string
  FiniteStrainSolver<dim>::step_history_text(const StepRecord &record)
  {
    std::ostringstream s;
    unsigned int n_updates = 0;
    for (const auto &it : record.iterations)
      n_updates += (it.step_length > 0 ? 1 : 0);
    s << "  step " << record.step << ", load factor " << std::setprecision(6) << record.load_factor << ": "
      << (record.converged ? "converged" : "NOT converged") << " after " << n_updates << " Newton updates\n";
    s << "    it   |r|          |r|/F_ref    |alpha du|   alpha\n";
    for (unsigned int i = 0; i < record.iterations.size(); ++i)
      {
        const auto &it = record.iterations[i];
        s << "    " << std::setw(3) << i << "  " << std::scientific << std::setprecision(3) << it.residual_norm
          << "    " << it.relative_residual << "    " << it.update_norm << "    " << std::defaultfloat
          << std::setprecision(4) << it.step_length << "\n";
      }
    return s.str();
  }



  template <int dim>
  void
  FiniteStrainSolver<dim>::print_history(std::ostream &out) const
  {
    for (const auto &record : history)
      out << step_history_text(record);
  }



  template class FiniteStrainSolver<2>;
} // namespace dealvem
