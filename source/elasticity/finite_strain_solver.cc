// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>

#include <dealvem/elasticity/finite_strain_constraints.h>
#include <dealvem/elasticity/finite_strain_solver.h>
#include <dealvem/elasticity/hyperelastic_material.h>

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

    // Evaluate a state; if it lies outside the domain of the element or
    // the law (a cell inverted, det F <= 0 at a material point, no
    // plane-stress state of the law), return the reason instead of
    // throwing. Other failures go on.
    template <typename Evaluation>
    bool
    evaluate_in_domain(const Evaluation &evaluation, std::string &reason)
    {
      try
        {
          evaluation();
          return true;
        }
      catch (const ExcInvertedCell &e)
        {
          reason = exception_text(e);
        }
      catch (const ExcNonPositiveJacobian &e)
        {
          reason = exception_text(e);
        }
      catch (const ExcNoPlaneStressState &e)
        {
          reason = exception_text(e);
        }
      return false;
    }

    // the state of every contact constraint at a Newton iterate: out of
    // the system (multiplier zero), a constraint row (active normal
    // contact, tied, stick), or slip in the positive or negative tangential
    // direction
    enum NewtonConstraintState : int
    {
      inactive   = 0,
      constraint = 1,
      slip_plus  = 2,
      slip_minus = 3
    };

    bool
    all_finite(const dealii::Vector<double> &v)
    {
      for (const double x : v)
        if (!std::isfinite(x))
          return false;
      return true;
    }

    // The update test's measure at an iterate whose merit (free residual,
    // with contact also phi) is @p merit: the size of the update that one
    // more Newton iteration would take. Testing only the last update taken
    // (@p last_update) costs, at the end of every step, one more
    // factorization and solve whose update is round-off: the residual
    // after Newton's last update is already at its floor, but that update
    // itself was of the size of the error before it. Once the iteration
    // contracts fast, the next update is estimated instead as the last one
    // times the contraction seen over the last iteration, the larger of
    // the residual's ratio (merit now / merit where the last update
    // started) and the updates' ratio (last / the one before): a linear
    // bound on what is quadratic convergence, so the estimate errs on the
    // large side. It is used only after a full (alpha = 1) update that
    // kept the prescribed values (whose residual ratio measures Newton's
    // rate), from the third iterate of a step on, and while the contraction
    // is below 1/2; otherwise the measure is the last update, as before.
    template <typename Record>
    double
    remaining_update(const Record &record, const double last_update, const bool last_moved_prescribed,
                     const double merit)
    {
      const auto        &its = record.iterations;
      const std::size_t n   = its.size();
      if (n < 2 || last_moved_prescribed || its[n - 1].step_length != 1.)
        return last_update;
      const double last_merit = std::hypot(its[n - 1].residual_norm, its[n - 1].contact_residual);
      const double before     = its[n - 2].update_norm;
      if (!(last_merit > 0) || !(before > 0))
        return last_update;
      const double contraction = std::max(merit / last_merit, last_update / before);
      return contraction < 0.5 ? contraction * last_update : last_update;
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

    const auto &vertices = dof_handler.get_mesh().get_vertices();
    dealii::Point<dim> lo = vertices.front(), hi = vertices.front();
    for (const auto &v : vertices)
      for (unsigned int d = 0; d < dim; ++d)
        {
          lo[d] = std::min(lo[d], v[d]);
          hi[d] = std::max(hi[d], v[d]);
        }
    length_scale       = lo.distance(hi);
    absolute_tolerance = parameters.absolute_residual_tolerance;
    if (absolute_tolerance < 0)
      absolute_tolerance =
        1e-12 * assembler.get_material_library().min_characteristic_stiffness() * length_scale;
  }



  template <int dim>
  void
  FiniteStrainSolver<dim>::set_contact(FiniteStrainConstraints &contact_in)
  {
    if constexpr (dim != 2)
      {
        AssertThrow(false, dealii::ExcMessage("FiniteStrainSolver::set_contact(): contact is two-dimensional."));
      }
    else
      {
        const auto &dof_handler = assembler.get_dof_handler();
        contact                 = &contact_in;
        contact->mark_prescribed(constraints);
        const auto n = dof_handler.n_dofs();
        const auto m = contact->n_constraints();
        dealii::DynamicSparsityPattern dsp(n + m);
        dof_handler.make_sparsity_pattern(dsp, constraints);
        contact->add_sparsity(dsp, constraints);
        tangent.clear();
        sparsity.copy_from(dsp);
        tangent.reinit(sparsity);
        multipliers.reinit(m);
      }
  }



  template <int dim>
  void
  FiniteStrainSolver<dim>::set_constraints(const dealii::AffineConstraints<double> &new_constraints)
  {
    AssertThrow(new_constraints.is_closed(),
                dealii::ExcMessage("FiniteStrainSolver::set_constraints(): the constraints must be closed."));
    const auto &old_lines = constraints.get_lines();
    const auto &new_lines = new_constraints.get_lines();
    AssertThrow(old_lines.size() == new_lines.size(),
                dealii::ExcMessage("FiniteStrainSolver::set_constraints(): the new constraints have " +
                                   std::to_string(new_lines.size()) + " lines, the old ones " +
                                   std::to_string(old_lines.size()) +
                                   "; they must constrain the same DoFs."));
    for (unsigned int l = 0; l < old_lines.size(); ++l)
      {
        bool same = old_lines[l].index == new_lines[l].index &&
                    old_lines[l].entries.size() == new_lines[l].entries.size();
        for (unsigned int e = 0; same && e < old_lines[l].entries.size(); ++e)
          same = old_lines[l].entries[e].first == new_lines[l].entries[e].first;
        AssertThrow(same,
                    dealii::ExcMessage("FiniteStrainSolver::set_constraints(): the constraint of DoF " +
                                       std::to_string(new_lines[l].index) +
                                       " differs in the DoFs it constrains or depends on from the old "
                                       "constraints; only values and coefficients may change."));
      }
    constraints.copy_from(new_constraints);
    homogeneous_constraints.copy_from(new_constraints);
    for (const auto &line : new_lines)
      homogeneous_constraints.set_inhomogeneity(line.index, 0.);
  }



  template <int dim>
  void
  FiniteStrainSolver<dim>::set_state(const dealii::Vector<double> &u,
                                     const dealii::Vector<double> &lambda,
                                     const double                  load_factor,
                                     const unsigned int            step,
                                     const dealii::Vector<double> *previous_u,
                                     const double                  previous_load_factor_in,
                                     const unsigned int            previous_step_in)
  {
    const auto n = assembler.get_dof_handler().n_dofs();
    const auto m = contact != nullptr ? contact->n_constraints() : 0u;
    AssertThrow(u.size() == n && (previous_u == nullptr || previous_u->size() == n),
                dealii::ExcMessage("FiniteStrainSolver::set_state(): a displacement has " +
                                   std::to_string(previous_u != nullptr && previous_u->size() != n ?
                                                    previous_u->size() :
                                                    u.size()) +
                                   " entries, the DoF handler " + std::to_string(n) + "."));
    AssertThrow(lambda.size() == m,
                dealii::ExcMessage("FiniteStrainSolver::set_state(): " + std::to_string(lambda.size()) +
                                   " multipliers given, the contact has " + std::to_string(m) +
                                   " constraints (set_contact() first)."));
    AssertThrow(std::isfinite(u.l2_norm()) && (lambda.size() == 0 || std::isfinite(lambda.l2_norm())) &&
                  std::isfinite(load_factor),
                dealii::ExcMessage("FiniteStrainSolver::set_state(): the state is not finite."));
    solution            = u;
    multipliers         = lambda;
    current_load_factor = load_factor;
    current_step        = step;
    n_converged         = 1;
    if (previous_u != nullptr)
      {
        previous_solution    = *previous_u;
        previous_multipliers = lambda; // the multipliers are not extrapolated
        previous_load_factor = previous_load_factor_in;
        previous_step        = previous_step_in;
        n_converged          = 2;
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
    // the loads at the current time of their functions (a caller with
    // time-dependent data sets it before the step): the reference force of
    // the convergence test
    assembler.assemble_load_vector(f_ext);
    if (parameters.extrapolate && n_converged >= 2)
      {
        const auto n_records = history.size();
        try
          {
            attempt_step(step, load_factor, true);
            return;
          }
        catch (const dealii::ExceptionBase &)
          {
            // the failed attempt's record goes; the step starts again from
            // the last converged state
            history.resize(n_records);
          }
        attempt_step(step, load_factor, false);
        // (a second failure has thrown above with its own record)
        history.back().restarted = true;
        return;
      }
    attempt_step(step, load_factor, false);
  }



  // The state of one attempt at a load step (attempt_step()), handed from
  // one of its stages to the next: the step, the iterate (u, lambda), the
  // trial state of the line search, the Newton system's work vectors, and
  // the contact data of the step.
  template <int dim>
  struct FiniteStrainSolver<dim>::NewtonStep
  {
    unsigned int step        = 0;
    double       load_factor = 0;
    // the factor of the prescribed values: the load factor, or 1 when the
    // constraints hold the motion of the step itself
    double     motion_factor = 0;
    StepRecord record;
    // the numbers of DoFs and of contact constraints
    dealii::types::global_dof_index n = 0;
    unsigned int                    m = 0;

    dealii::Vector<double>            u, r, rhs, du, u_trial, r_trial, tmp, x;
    dealii::Vector<double>            lambda, lambda_new, lambda_trial;
    dealii::AffineConstraints<double> update_constraints;
    // the largest prescribed value, for the test that the constraints hold
    double prescribed = 0;

    // contact: the pair weights (the scale of the complementarity
    // function) and the complementarity constant
    std::vector<double>                    weight;
    double                                 c = 0;
    FiniteStrainConstraints::Linearization lin;

    double      f_ext_norm  = 0;
    double      last_update = std::numeric_limits<double>::infinity();
    // whether the last update carried prescribed motion (its residual
    // ratio then says nothing about Newton's rate)
    bool last_moved_prescribed = true;
    std::string inversion; // the last inverted cell met in the step

    // the state of every constraint at the iterate (NewtonConstraintState)
    std::vector<int> active, previous_active;
  };



  // (see the header)
  template <int dim>
  void
  FiniteStrainSolver<dim>::attempt_step(const unsigned int step, const double load_factor, const bool extrapolate)
  {
    AssertThrow(std::isfinite(load_factor),
                dealii::ExcMessage("FiniteStrainSolver: the load factor of step " + std::to_string(step) +
                                   " is not finite."));
    NewtonStep ns;
    ns.step               = step;
    ns.load_factor        = load_factor;
    ns.record.step        = step;
    ns.record.load_factor = load_factor;
    ns.motion_factor      = parameters.scale_prescribed_motion ? load_factor : 1.;

    // the stabilization scaled at the last converged state (FiniteStrainOperator)
    assembler.freeze_stabilization(solution);
    start_attempt(ns);
    check_data_scale(ns);
    if (extrapolate && n_converged >= 2)
      extrapolate_first_iterate(ns);
    ns.active.assign(ns.m, inactive);
    for (unsigned int it = 0;; ++it)
      if (newton_iteration(ns, it))
        break;
    check_fixed_pairs(ns);
    accept_step(ns);
  }



  // The step fails: its record (not converged) goes to the history, and the
  // error names the reason.
  template <int dim>
  void
  FiniteStrainSolver<dim>::fail_step(NewtonStep &ns, const std::string &reason)
  {
    ns.record.converged = false;
    history.push_back(ns.record);
    AssertThrow(false,
                dealii::ExcMessage("FiniteStrainSolver: load step " + std::to_string(ns.step) + " (load factor " +
                                   number(ns.load_factor) + ") did not converge: " + reason +
                                   "\nNewton history of the step:\n" + step_history_text(ns.record) +
                                   "The solution is kept at the last converged step (load factor " +
                                   number(current_load_factor) + ")."));
  }



  // The start of an attempt: the sizes, the iterate at the last converged
  // state, the update's constraints and the contact weights.
  template <int dim>
  void
  FiniteStrainSolver<dim>::start_attempt(NewtonStep &ns)
  {
    const auto n = assembler.get_dof_handler().n_dofs();
    const auto m = contact != nullptr ? contact->n_constraints() : 0u;
    ns.n                   = n;
    ns.m                   = m;
    ns.record.with_contact = (contact != nullptr);

    ns.u      = solution;
    ns.lambda = multipliers;
    ns.update_constraints.copy_from(constraints);
    for (const auto &line : constraints.get_lines())
      ns.prescribed = std::max(ns.prescribed, std::abs(ns.motion_factor * line.inhomogeneity));

    ns.weight.assign(m, 0.);
    if (contact != nullptr)
      {
        ns.c = contact->complementarity_constant();
        for (unsigned int j = 0; j < m; ++j)
          ns.weight[j] = contact->weight(j);
      }
    ns.f_ext_norm = f_ext.l2_norm();
  }



  // The norm of the free part of @p residual.
  template <int dim>
  double
  FiniteStrainSolver<dim>::free_norm(NewtonStep &ns, const dealii::Vector<double> &residual) const
  {
    ns.tmp = residual;
    homogeneous_constraints.condense(ns.tmp);
    return ns.tmp.l2_norm();
  }



  // Contact: r <- r - sum_j lambda_j dg_j/du; returns the norm of the
  // complementarity residual phi.
  template <int dim>
  double
  FiniteStrainSolver<dim>::contact_residual(NewtonStep &ns, const dealii::Vector<double> &u_at, const dealii::Vector<double> &lambda_at,
                                            dealii::Vector<double> &residual) const
  {
    double phi2 = 0;
    for (unsigned int j = 0; j < ns.m; ++j)
      {
        if (contact->is_left_out(j))
          {
            phi2 += lambda_at[j] * lambda_at[j];
            continue;
          }
        contact->linearize(j, u_at, ns.lin, false);
        if (lambda_at[j] != 0)
          for (unsigned int k = 0; k < ns.lin.dofs.size(); ++k)
            residual[ns.lin.dofs[k]] -= lambda_at[j] * ns.lin.gradient[k];
        const double k_j = ns.c * ns.weight[j];
        double       phi = 0;
        const auto kind = contact->kind(j);
        if (kind == FiniteStrainConstraints::Kind::equality)
          phi = k_j * ns.lin.value;
        else if (kind == FiniteStrainConstraints::Kind::unilateral)
          phi = lambda_at[j] - std::min(0., lambda_at[j] + k_j * ns.lin.value);
        else
          {
            // Coulomb: lambda_t = proj_[-b, b](lambda_t + c w s)
            const unsigned int i     = contact->normal_of(j);
            const double       bound = contact->friction_coefficient_of(j) * std::max(0., -lambda_at[i]);
            phi = lambda_at[j] - std::clamp(lambda_at[j] + k_j * ns.lin.value, -bound, bound);
          }
        phi2 += phi * phi;
      }
    return std::sqrt(phi2);
  }



  // Step 1 of an attempt: the data must lie above Newton's round-off floor.
  template <int dim>
  void
  FiniteStrainSolver<dim>::check_data_scale(NewtonStep &ns) const
  {
    // Data below Newton's round-off floor: loads and prescribed motions that
    // the default floor (1e-12 E_min L) cannot tell from none, on a state
    // that is itself that small, would end the step at its first iterate
    // with the bodies where they were (exit 0, a wrong answer). They are
    // named instead.
    if (parameters.absolute_residual_tolerance < 0 && length_scale > 0)
      {
        const double stiffness = assembler.get_material_library().min_characteristic_stiffness() * length_scale;
        const double load      = std::abs(ns.load_factor) * ns.f_ext_norm / stiffness;
        const double motion    = ns.prescribed / length_scale;
        const double state     = solution.linfty_norm() / length_scale;
        const double data      = std::max(load, motion);
        AssertThrow(!(data > 0 && std::max(data, state) < 1e-10),
                    dealii::ExcMessage(
                      "FiniteStrainSolver: load step " + std::to_string(ns.step) + " (load factor " +
                      number(ns.load_factor) + "): its loads (" + number(load) +
                      " of the smallest Young's modulus times the size of the mesh) and prescribed displacements (" +
                      number(motion) +
                      " of the size) are all below 1e-10, and so is the state it starts from: Newton's residual "
                      "floor (1e-12 times that modulus times the size) cannot tell them from none, and the step "
                      "would end where it started. Choose units in which the displacements and the loads are "
                      "nearer to the size of the mesh and to its modulus times its size, or solve at small strain, "
                      "where the response is linear in the data."));
      }
  }



  // Step 2: the first iterate, the extrapolation of the last two converged
  // steps (where it lies in the domain).
  template <int dim>
  void
  FiniteStrainSolver<dim>::extrapolate_first_iterate(NewtonStep &ns)
  {
    double s = 0;
    if (current_load_factor != previous_load_factor)
      s = (ns.load_factor - current_load_factor) / (current_load_factor - previous_load_factor);
    else if (current_step != previous_step)
      s = static_cast<double>(static_cast<int>(ns.step) - static_cast<int>(current_step)) /
          (static_cast<int>(current_step) - static_cast<int>(previous_step));
    if (std::isfinite(s) && s > 0 && s <= 4)
      {
        ns.u_trial = solution;
        ns.u_trial.sadd(1. + s, -s, previous_solution);
        // (outside the domain, or not finite: start from the last
        // converged state)
        std::string reason;
        if (all_finite(ns.u_trial) &&
            evaluate_in_domain(
              [&] {
                assembler.assemble(ns.u_trial, ns.load_factor, ns.r_trial, ns.update_constraints, nullptr, nullptr);
              },
              reason) &&
            all_finite(ns.r_trial))
          {
            ns.u = ns.u_trial;
            if (ns.m > 0 && previous_multipliers.size() == ns.m)
              ns.lambda.sadd(1. + s, -s, previous_multipliers);
            ns.record.extrapolated = true;
          }
      }
  }



  // Step 3: Newton iteration @p it; true when the iterate has converged.
  template <int dim>
  bool
  FiniteStrainSolver<dim>::newton_iteration(NewtonStep &ns, const unsigned int it)
  {
    // the update's constraints: what the iterate misses of
    // u_i = sum_j a_ij u_j + lambda b_i
    double mismatch = 0;
    for (const auto &line : constraints.get_lines())
      {
        double target = ns.motion_factor * line.inhomogeneity;
        for (const auto &entry : line.entries)
          target += entry.second * ns.u[entry.first];
        const double miss = target - ns.u[line.index];
        ns.update_constraints.set_inhomogeneity(line.index, miss);
        mismatch = std::max(mismatch, std::abs(miss));
      }
    const bool moves_prescribed = mismatch > 1e-13 * std::max(ns.prescribed, ns.u.linfty_norm());

    assemble_iterate(ns, it);
    // the force scale at this iterate: the load or the internal forces
    // (reactions included), whichever is larger
    ns.tmp = f_ext;
    ns.tmp *= ns.load_factor;
    ns.tmp -= ns.r;
    const double F_ref = std::max(std::abs(ns.load_factor) * ns.f_ext_norm, ns.tmp.l2_norm());

    // contact: the active set of the iterate, the constraint rows and
    // the geometric stiffness
    double       phi_norm = 0;
    unsigned int n_active = 0, n_slip = 0;
    if (contact != nullptr)
      phi_norm = contact_rows(ns, n_active, n_slip);
    const double r_norm = free_norm(ns, ns.r);
    const double merit  = std::sqrt(r_norm * r_norm + phi_norm * phi_norm);

    IterationRecord iteration;
    iteration.residual_norm     = r_norm;
    iteration.relative_residual = F_ref > 0 ? r_norm / F_ref : 0.;
    iteration.update_norm       = 0;
    iteration.step_length       = 0;
    iteration.n_active          = n_active;
    iteration.n_slip            = n_slip;
    iteration.contact_residual  = phi_norm;
    const double tolerance      = std::max(parameters.residual_tolerance * F_ref, absolute_tolerance);
    // where the stiffest body is 1e3 times the softest, the residual of
    // the exact discrete solution evaluated in floating point can lie
    // just above the tolerance: an iterate whose last update changed u
    // only at round-off (1e-13 of |u|) is accepted with a residual up
    // to 100 times the tolerance
    const bool at_roundoff = it > 1 && ns.last_update <= 1e-13 * ns.u.l2_norm() && r_norm <= 100 * tolerance;
    if (!moves_prescribed && (r_norm <= tolerance || at_roundoff) && phi_norm <= tolerance &&
        (contact == nullptr || (it > 0 && ns.active == ns.previous_active)) &&
        remaining_update(ns.record, ns.last_update, ns.last_moved_prescribed, merit) <=
          parameters.update_tolerance * ns.u.l2_norm())
      {
        ns.record.iterations.push_back(iteration);
        ns.record.converged = true;
        return true;
      }
    if (it == parameters.max_iterations)
      {
        ns.record.iterations.push_back(iteration);
        fail_step(ns, "no convergence in " + std::to_string(parameters.max_iterations) + " Newton iterations" +
             (ns.inversion.empty() ? std::string() :
                                  " (the line search met states outside the domain of the law, the "
                                  "last: " + ns.inversion + ")"));
      }

    newton_direction(ns, iteration, it);
    const double alpha = line_search(ns, iteration, merit, moves_prescribed);
    ns.last_update           = alpha * ns.du.l2_norm();
    ns.last_moved_prescribed = moves_prescribed;
    iteration.update_norm = ns.last_update;
    iteration.step_length = alpha;
    ns.record.iterations.push_back(iteration);
    ns.u      = ns.u_trial;
    ns.lambda = ns.lambda_trial;
    return false;
  }



  // Step 3a: the residual and the tangent at the iterate.
  template <int dim>
  void
  FiniteStrainSolver<dim>::assemble_iterate(NewtonStep &ns, const unsigned int it)
  {
    {
      // (the iterate is the last converged state or an accepted trial,
      // both evaluated before; the tangent may still fail)
      std::string reason;
      if (!evaluate_in_domain(
            [&] { assembler.assemble(ns.u, ns.load_factor, ns.r, ns.update_constraints, &tangent, &ns.rhs); }, reason))
        fail_step(ns, "the iterate of Newton iteration " + std::to_string(it) + " lies outside the domain of the law: " +
             reason);
      if (!all_finite(ns.r) || !all_finite(ns.rhs))
        fail_step(ns, "the internal forces of Newton iteration " + std::to_string(it) +
             " are not finite (|r| = " + number(ns.r.l2_norm()) +
             "): the stresses overflow double precision. The loads, prescribed displacements or Young's "
             "moduli are out of scale with each other or with the size of the mesh.");
    }
  }



  // Step 3b: the active set of the iterate, the constraint rows and the
  // geometric stiffness of the contact; returns the norm of phi.
  template <int dim>
  double
  FiniteStrainSolver<dim>::contact_rows(NewtonStep &ns, unsigned int &n_active, unsigned int &n_slip)
  {
    ns.previous_active = ns.active;
    double scale    = 0;
    std::vector<double> g(ns.m, 0.);
    for (unsigned int j = 0; j < ns.m; ++j)
      if (!contact->is_left_out(j))
        {
          g[j]  = contact->value(j, ns.u);
          scale = std::max({scale, std::abs(ns.lambda[j]) / ns.weight[j], ns.c * std::abs(g[j])});
        }
    // gaps below 1e-12 of the mesh size are closed: a body that only
    // contact holds, touching with a gap of coordinate round-off
    // and no force yet, starts supported
    const double gap_floor = ns.c * 1e-12 * length_scale;
    for (unsigned int j = 0; j < ns.m; ++j)
      {
        ns.active[j] = inactive;
        if (contact->is_left_out(j))
          continue;
        if (contact->kind(j) == FiniteStrainConstraints::Kind::equality)
          ns.active[j] = constraint;
        else if (contact->kind(j) == FiniteStrainConstraints::Kind::unilateral)
          ns.active[j] = (-ns.lambda[j] / ns.weight[j] - ns.c * g[j] > -1e-12 * scale - gap_floor) ? constraint : inactive;
      }
    // Coulomb (after the normal states): stick where the trial force
    // lambda_t + c w s lies within the bound mu |lambda_n|, else slip
    for (unsigned int j = 0; j < ns.m; ++j)
      if (contact->kind(j) == FiniteStrainConstraints::Kind::friction && !contact->is_left_out(j))
        {
          const unsigned int i = contact->normal_of(j);
          if (ns.active[i] == inactive)
            continue;
          const double bound = contact->friction_coefficient_of(j) * std::max(0., -ns.lambda[i]);
          const double trial = ns.lambda[j] + ns.c * ns.weight[j] * g[j];
          if (std::abs(trial) <= bound + 1e-12 * scale * ns.weight[j])
            ns.active[j] = constraint;
          else
            ns.active[j] = trial > 0 ? slip_plus : slip_minus;
        }
    for (unsigned int j = 0; j < ns.m; ++j)
      {
        if (ns.active[j] == inactive)
          {
            tangent.add(ns.n + j, ns.n + j, ns.c * ns.weight[j]);
            continue;
          }
        if (contact->kind(j) != FiniteStrainConstraints::Kind::friction)
          ++n_active;
        else if (ns.active[j] != constraint)
          ++n_slip;
        contact->linearize(j, ns.u, ns.lin, true);
        const unsigned int                           nd = ns.lin.dofs.size();
        dealii::FullMatrix<double>                   M(nd + 1, nd + 1);
        dealii::Vector<double>                       b(nd + 1);
        std::vector<dealii::types::global_dof_index> indices = ns.lin.dofs;
        indices.push_back(ns.n + j);
        const bool slip = (ns.active[j] != constraint);
        for (unsigned int k = 0; k < nd; ++k)
          {
            for (unsigned int l = 0; l < nd; ++l)
              M(k, l) = ns.lambda[j] * ns.lin.hessian(k, l);
            M(k, nd) = ns.lin.gradient[k];
            M(nd, k) = slip ? 0. : ns.lin.gradient[k];
          }
        b[nd] = slip ? 0. : -ns.lin.value;
        // slip: c w (lambda_t + mu sigma lambda_n) = 0 (scaled as
        // the rows of the inactive constraints)
        if (slip)
          M(nd, nd) = ns.c * ns.weight[j];
        ns.update_constraints.distribute_local_to_global(M, b, indices, tangent, ns.rhs);
        if (slip)
          {
            const unsigned int i     = contact->normal_of(j);
            const double       sigma = (ns.active[j] == slip_plus) ? 1. : -1.;
            tangent.add(ns.n + j, ns.n + i, ns.c * ns.weight[j] * contact->friction_coefficient_of(j) * sigma);
          }
      }
    return contact_residual(ns, ns.u, ns.lambda, ns.r);
  }



  // Step 3c: the Newton direction and the new multipliers.
  template <int dim>
  void
  FiniteStrainSolver<dim>::newton_direction(NewtonStep &ns, IterationRecord &iteration, const unsigned int it)
  {
    // the Newton direction (and the new multipliers)
    dealii::SparseDirectUMFPACK direct;
    direct.initialize(tangent);
    ns.x.reinit(ns.n + ns.m);
    direct.vmult(ns.x, ns.rhs);
    ns.update_constraints.distribute(ns.x);
    if (!all_finite(ns.x))
      {
        ns.record.iterations.push_back(iteration);
        fail_step(ns, "the Newton update of iteration " + std::to_string(it) +
             " is not finite (the linear solve of the tangent gave |du| = " + number(ns.x.l2_norm()) +
             "): the tangent is singular or its entries are out of the range of double precision "
             "(Young's moduli, loads and mesh size far apart in scale).");
      }
    ns.du.reinit(ns.n);
    for (unsigned int i = 0; i < ns.n; ++i)
      ns.du[i] = ns.x[i];
    ns.lambda_new.reinit(ns.m);
    for (unsigned int j = 0; j < ns.m; ++j)
      ns.lambda_new[j] = (ns.active[j] != inactive) ? ns.x[ns.n + j] : 0.;
  }



  // Step 3d: the line search along the Newton direction; returns the step
  // length of the accepted trial state (ns.u_trial, ns.lambda_trial).
  template <int dim>
  double
  FiniteStrainSolver<dim>::line_search(NewtonStep &ns, IterationRecord &iteration, const double merit, const bool moves_prescribed)
  {
    // backtracking: halve alpha while the trial leaves the domain of the
    // element or the law (an inverted cell, det F <= 0, no plane-stress
    // state), gives a non-finite residual, or (for an update that keeps
    // the prescribed DoFs) does not decrease the merit (the free
    // residual, with contact also phi) enough
    double      alpha       = 1;
    bool        accepted    = false;
    std::string last_failure;
    const auto  try_step = [&](const double a) {
      ns.u_trial = ns.u;
      ns.u_trial.add(a, ns.du);
      ns.lambda_trial = ns.lambda;
      if (ns.m > 0) // (deal.II's debug mode refuses sadd() on empty vectors)
        ns.lambda_trial.sadd(1. - a, a, ns.lambda_new);
      assembler.assemble(ns.u_trial, ns.load_factor, ns.r_trial, ns.update_constraints, nullptr, nullptr);
      const double phi = (contact != nullptr) ? contact_residual(ns, ns.u_trial, ns.lambda_trial, ns.r_trial) : 0.;
      const double rn  = free_norm(ns, ns.r_trial);
      return std::sqrt(rn * rn + phi * phi);
    };
    for (unsigned int h = 0; h <= parameters.max_line_search_halvings; ++h, alpha *= 0.5)
      {
        double trial_merit = 0;
        if (!evaluate_in_domain([&] { trial_merit = try_step(alpha); }, last_failure))
          {
            ns.inversion = last_failure;
            continue;
          }
        if (!std::isfinite(trial_merit))
          {
            last_failure = "the residual of the trial state is not finite";
            continue;
          }
        if (!parameters.line_search || moves_prescribed || trial_merit <= (1. - 1e-4 * alpha) * merit)
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
        alpha = 1;
        double trial_merit = 0;
        if (!evaluate_in_domain([&] { trial_merit = try_step(1.); }, last_failure))
          ns.inversion = last_failure;
        else if (std::isfinite(trial_merit))
          accepted = true;
      }
    if (!accepted)
      {
        iteration.update_norm = ns.du.l2_norm();
        ns.record.iterations.push_back(iteration);
        fail_step(ns, "every step length of the line search, down to 2^-" +
             std::to_string(parameters.max_line_search_halvings) +
             ", leaves the domain of the element or the law or gives a non-finite residual; the last: " +
             last_failure);
      }
    return alpha;
  }



  // Step 4: the pairs whose gap the displacement constraints fix.
  template <int dim>
  void
  FiniteStrainSolver<dim>::check_fixed_pairs(NewtonStep &ns)
  {
    // pairs whose gap the displacement constraints fix: the prescribed
    // motion must not make them penetrate (or, tied, move apart)
    if (contact != nullptr && parameters.check_fixed_pairs)
      for (unsigned int j = 0; j < ns.m; ++j)
        {
          const auto kind = contact->kind(j);
          // (the slip of Coulomb friction may be anything)
          if (!contact->is_prescribed(j) || kind == FiniteStrainConstraints::Kind::friction)
            continue;
          const double g = contact->value(j, ns.u);
          if ((kind == FiniteStrainConstraints::Kind::equality && std::abs(g) > 1e-10 * length_scale) ||
              (kind == FiniteStrainConstraints::Kind::unilateral && g < -1e-10 * length_scale))
            fail_step(ns, "the displacement constraints fix both nodes of " + contact->describe(j) + ", and they make its " +
                 "constraint " + std::to_string(j) + " " +
                 (kind == FiniteStrainConstraints::Kind::equality ? "fail (value " : "penetrate (gap ") + number(g) +
                 "): the prescribed motions of the two bodies contradict the contact.");
        }
  }



  // Step 5: the converged state becomes the last one.
  template <int dim>
  void
  FiniteStrainSolver<dim>::accept_step(NewtonStep &ns)
  {
    previous_solution    = solution;
    previous_multipliers = multipliers;
    previous_load_factor = current_load_factor;
    previous_step        = current_step;
    solution             = ns.u;
    multipliers          = ns.lambda;
    current_load_factor  = ns.load_factor;
    current_step         = ns.step;
    ++n_converged;
    history.push_back(ns.record);
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
      << (record.converged ? "converged" : "NOT converged") << " after " << n_updates << " Newton updates"
      << (record.extrapolated ? " (from the extrapolated state)" : "")
      << (record.restarted ? " (restarted from the last converged state: the extrapolated start failed)" : "")
      << "\n";
    bool with_slip = false;
    for (const auto &it : record.iterations)
      with_slip = with_slip || it.n_slip > 0;
    s << "    it   |r|          |r|/F_ref    |alpha du|   alpha"
      << (record.with_contact ? "    active   |phi|" : "") << (with_slip ? "        slip" : "") << "\n";
    for (unsigned int i = 0; i < record.iterations.size(); ++i)
      {
        const auto &it = record.iterations[i];
        s << "    " << std::setw(3) << i << "  " << std::scientific << std::setprecision(3) << it.residual_norm
          << "    " << it.relative_residual << "    " << it.update_norm << "    " << std::defaultfloat
          << std::setprecision(4) << std::setw(6) << std::left << it.step_length << std::right;
        if (record.with_contact)
          s << "   " << std::setw(6) << it.n_active << "   " << std::scientific << std::setprecision(3)
            << it.contact_residual << std::defaultfloat;
        if (with_slip)
          s << "   " << std::setw(5) << it.n_slip;
        s << "\n";
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
