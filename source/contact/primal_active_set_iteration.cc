// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The primal active-set iteration of PrimalActiveSetSolver (iterate()): one
// class, Iteration, with a member per step of the method (the class
// documentation in primal_active_set.h). The mechanisms, the free motions
// and the entry points are in primal_active_set.cc.
#include <dealvem/contact/primal_active_set.h>
#include <dealvem/elasticity/piece_support.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace dealvem
{
  /**
   * One run of iterate(): the state of the primal active-set iteration (the
   * feasible point, the working set, the Tresca slip states, the drops of
   * the last minimiser) and one member per step of the method as the class
   * documentation numbers them: the set-up, the start (step 1), the test at
   * a minimiser (step 2), and the step (step 3: its direction, the ratio
   * test, the retraction of drops that would come back at once, the move).
   */
  template <int dim>
  class PrimalActiveSetSolver<dim>::Iteration
  {
  public:
    Iteration(PrimalActiveSetSolver<dim>         &owner,
              const dealii::SparseMatrix<double> &system_matrix,
              const dealii::Vector<double>       &system_rhs,
              dealii::SparseMatrix<double>       &matrix,
              dealii::Vector<double>             &x);

    /// Steps 1 to 3 until the solution or the mechanism.
    Result
    run(const std::vector<bool> *start);

  private:
    /// The pairs held tangentially with the closed pairs @p closed.
    std::vector<bool>
    tangential_of(const std::vector<bool> &closed) const;

    /// The length of the stick piece of the Huber function (penalty).
    double
    stick_range(const unsigned int i) const
    {
      return bound[i] / (penalty * pairs[i].weight);
    }

    /// The energy 1/2 u.K u - f.u (condensed) with the stick springs and
    /// the friction terms.
    double
    energy(const dealii::Vector<double> &y) const;

    /// One solve with g = 0 on @p closed (and the slip forces as loads),
    /// optionally with the proximal term eps (u - anchor) on the DoFs
    /// @p prox.
    void
    solve_equality_problem(const std::vector<bool>         &closed,
                           const std::vector<unsigned int> &prox,
                           const double                     eps,
                           const dealii::Vector<double>    &anchor,
                           dealii::Vector<double>          &y);

    /// Throws when the solves and rigid steps exceed their limit.
    void
    check_limit() const;

    /// The tolerance of a gap at the displacement @p y.
    double
    gap_tolerance(const dealii::Vector<double> &y) const;

    /// Step 1 from the closed pairs @p start and the displacement x: the
    /// tangential states (Tresca) where they agree with x.
    void
    start_from(const std::vector<bool> &start);

    /// Step 1 from nothing: the closed initial gaps, the smallest gaps until
    /// every body is held, then the pairs that penetrate until none does.
    void
    start_from_gaps();

    /// The work of the loads and of the slip forces on each mode.
    void
    update_load_work();

    /// The projection @p proj of the loads on the free motions @p Z (an
    /// orthonormal basis over the modes); returns the work on it, |proj|^2.
    double
    project_loads(const std::vector<std::vector<double>> &Z, std::vector<double> &proj);

    /// The result's Tresca states and tangential forces at xc.
    void
    finish_tresca();

    /// Undo the drops and releases, and drop (or release) the largest
    /// violation alone.
    void
    restore_single();

    /// Step 2 at the minimiser over W: returns true when no pair of W is in
    /// tension (the result is then complete); otherwise drops the pairs in
    /// tension (or the largest violation alone).
    bool
    test_minimiser();

    /// Step 3, the direction: a rigid motion along the projection of the
    /// loads on the free motions, or the solve over W (free motions without
    /// work pinned); sets rigid, slope and tslope.
    void
    compute_direction();

    /// The DoFs (one per motion) that pin the free motions @p Z without
    /// work, and the stiffness @p eps of their springs.
    std::vector<unsigned int>
    pin_free_motions(const std::vector<std::vector<double>> &Z, double &eps) const;

    /// Step 3, the ratio test: pairs that would penetrate, and (Tresca)
    /// pairs that would leave their piece of the friction term; sets alpha,
    /// blocking and tblocking.
    void
    ratio_test();

    /// Drops that would come back at once (a dropped pair still closed, or
    /// a released one at its stick point, moving back) stay in the set, or
    /// the largest violation alone is dropped; returns true when the step
    /// must be taken again.
    bool
    retract_drops();

    /// Step 3, the move by alpha and the blocking pairs joining the set.
    void
    take_step();

    PrimalActiveSetSolver<dim>         &owner;
    const ContactAssembler<dim>        &contact;
    const dealii::SparseMatrix<double> &system_matrix;
    const dealii::Vector<double>       &system_rhs;
    dealii::SparseMatrix<double>       &matrix;
    dealii::Vector<double>             &x;

    const std::vector<ContactNodePair> &pairs;
    const unsigned int                  n_pairs;
    const unsigned int                  n;
    /// The multiplier rows of the system (contact.rows()).
    const ContactRows                   rows;
    const bool                          tresca;
    const bool                          springs;
    const double                        penalty;
    const unsigned int                  max_solves;
    /// The solves and rigid steps a polish (solve_stick_on_closed()) may
    /// take before it gives up.
    static constexpr unsigned int polish_solve_limit = 30;
    Result                              result;
    double                              work_scale = 0;
    double                              max_weight = 0;
    std::vector<bool>                   usable, tangential;
    /// (stick at closed pairs only: a pair sticks where it closes)
    std::vector<double> reference;
    /// Tresca: per pair its bound, whether it is free (no bound) and its
    /// slip direction (0: sticks).
    std::vector<double> bound;
    std::vector<bool>   free_t;
    std::vector<int>    slip_dir;

    dealii::Vector<double> rhs, trial, local;
    /// The working set and the feasible point.
    std::vector<bool>      W;
    dealii::Vector<double> xc;
    bool                   at_minimiser = true;

    std::vector<double> load_work;
    /// The projection of the loads on the free motions.
    std::vector<double> a;
    /// The free motions of W, when the drop test has computed them already.
    std::vector<std::vector<double>> Z_of_W;
    bool                             Z_up_to_date = false;

    bool                      single = false;
    std::vector<unsigned int> dropped, released;
    /// The pair of the largest violation at the minimiser, and whether it is
    /// a tangential one (a stick multiplier above its bound).
    unsigned int largest            = 0;
    bool         largest_tangential = false;

    /// The step: gaps and slips at xc, whether it is rigid, the change of
    /// the gaps and slips along the direction, the step length and the
    /// pairs that block it.
    std::vector<double>       g, sc;
    double                    gtol = 0;
    bool                      rigid = false;
    std::vector<double>       slope, tslope;
    double                    tslope_max = 0;
    double                    alpha      = 0;
    std::vector<unsigned int> blocking, tblocking;
  };



  template <int dim>
  PrimalActiveSetSolver<dim>::Iteration::Iteration(PrimalActiveSetSolver<dim>         &owner,
                                                   const dealii::SparseMatrix<double> &system_matrix,
                                                   const dealii::Vector<double>       &system_rhs,
                                                   dealii::SparseMatrix<double>       &matrix,
                                                   dealii::Vector<double>             &x)
    : owner(owner)
    , contact(owner.contact)
    , system_matrix(system_matrix)
    , system_rhs(system_rhs)
    , matrix(matrix)
    , x(x)
    , pairs(contact.get_pairs())
    , n_pairs(pairs.size())
    , n(system_matrix.m() - contact.n_multipliers())
    , rows(contact.rows())
    , tresca(!owner.tresca_bound.empty())
    , springs(owner.settings.tangential == ContactSettings::Tangential::penalty)
    , penalty(contact.get_penalty())
    , max_solves(std::max(200u, (tresca ? 12 : 6) * n_pairs))
    , usable(n_pairs)
    , tangential(n_pairs)
    , reference(n_pairs, 0.)
    , bound(n_pairs, 0.)
    , free_t(n_pairs, true)
    , slip_dir(n_pairs, 0)
    , trial(system_matrix.m())
    , local(4)
    , W(n_pairs)
  {}



  template <int dim>
  std::vector<bool>
  PrimalActiveSetSolver<dim>::Iteration::tangential_of(const std::vector<bool> &closed) const
  {
    std::vector<bool> t(n_pairs);
    for (unsigned int i = 0; i < n_pairs; ++i)
      t[i] = usable[i] &&
             (tresca ? (!free_t[i] && slip_dir[i] == 0) : (owner.on_closed_only ? bool(closed[i]) : owner.stick));
    return t;
  }



  template <int dim>
  double
  PrimalActiveSetSolver<dim>::Iteration::energy(const dealii::Vector<double> &y) const
  {
    const auto &constraints = owner.constraints;
    double      e           = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        if (constraints.is_constrained(i))
          continue;
        double ku = 0;
        for (auto it = system_matrix.begin(i), it_end = system_matrix.end(i); it != it_end; ++it)
          if (it->column() < n && !constraints.is_constrained(it->column()))
            ku += it->value() * y[it->column()];
        e += 0.5 * y[i] * ku - system_rhs[i] * y[i];
      }
    if (springs || tresca)
      {
        const auto s = contact.slips(y);
        for (unsigned int i = 0; i < n_pairs; ++i)
          {
            const double d = s[i] - reference[i];
            if (tangential[i] && springs)
              e += 0.5 * penalty * pairs[i].weight * d * d;
            else if (tresca && !free_t[i] && !tangential[i])
              e += bound[i] * std::abs(d) - (springs ? 0.5 * bound[i] * stick_range(i) : 0.);
          }
      }
    return e;
  }



  template <int dim>
  void
  PrimalActiveSetSolver<dim>::Iteration::solve_equality_problem(const std::vector<bool>         &closed,
                                                                const std::vector<unsigned int> &prox,
                                                                const double                     eps,
                                                                const dealii::Vector<double>    &anchor,
                                                                dealii::Vector<double>          &y)
  {
    const auto &constraints = owner.constraints;
    auto       &solver      = owner.solver;
    matrix.copy_from(system_matrix);
    rhs        = system_rhs;
    tangential = tangential_of(closed);
    contact.assemble(constraints, closed, tangential, matrix, rhs, &reference);
    if (tresca)
      for (unsigned int i = 0; i < n_pairs; ++i)
        if (!free_t[i] && slip_dir[i] != 0)
          {
            // the friction force sigma b along C_t, moved to the loads
            const auto   d = contact.pair_dofs(i);
            const auto  &t = pairs[i].tangent;
            const double f = slip_dir[i] * bound[i];
            local[0]       = f * t[0];
            local[1]       = f * t[1];
            local[2]       = -f * t[0];
            local[3]       = -f * t[1];
            const std::vector<dealii::types::global_dof_index> dofs(d.begin(), d.end());
            constraints.distribute_local_to_global(local, dofs, rhs);
          }
    for (const auto dof : prox)
      {
        matrix.add(dof, dof, eps);
        rhs[dof] += eps * anchor[dof];
      }
    if (solver.get_type() == SaddlePointSolver::Type::cg_amg_constraints)
      solver.set_stick_directions(contact.stick_penalty_rows(constraints, tangential));
    solver.set_context(std::string(tresca ? "Tresca friction" : "globalized active set") + ", solve " +
                       std::to_string(result.n_solves + 1));
    y.reinit(system_matrix.m());
    solver.solve(matrix, n, y, rhs);
    constraints.distribute(y);
    ++result.n_solves;
    result.linear_iterations += solver.last_iterations();
  }



  template <int dim>
  void
  PrimalActiveSetSolver<dim>::Iteration::check_limit() const
  {
    AssertThrow(result.n_solves + result.n_rigid_steps <= max_solves,
                dealii::ExcMessage("The globalized contact solver made " + std::to_string(result.n_solves) +
                                   " solves and " + std::to_string(result.n_rigid_steps) +
                                   " rigid steps without settling: degenerate ties between pairs that close "
                                   "and open at once. Perturb the geometry or the loads slightly."));
  }



  template <int dim>
  double
  PrimalActiveSetSolver<dim>::Iteration::gap_tolerance(const dealii::Vector<double> &y) const
  {
    double umax = 0;
    for (unsigned int i = 0; i < n; ++i)
      umax = std::max(umax, std::abs(y[i]));
    return 1e-12 * max_weight + 1e-11 * umax;
  }



  template <int dim>
  void
  PrimalActiveSetSolver<dim>::Iteration::start_from(const std::vector<bool> &start)
  {
    AssertDimension(start.size(), n_pairs);
    for (unsigned int i = 0; i < n_pairs; ++i)
      W[i] = start[i] && usable[i];
    xc           = x;
    at_minimiser = false;
    if (tresca)
      {
        // the tangential states, where they agree with the start
        const auto   s    = contact.slips(xc);
        const double stol = gap_tolerance(xc);
        for (unsigned int i = 0; i < n_pairs; ++i)
          {
            if (free_t[i])
              continue;
            const double d = s[i] - reference[i];
            if (springs)
              slip_dir[i] = (std::abs(d) <= stick_range(i) ? 0 : (d > 0 ? 1 : -1));
            else if (std::abs(d) > stol)
              slip_dir[i] = (d > 0 ? 1 : -1);
            else
              slip_dir[i] = (owner.tresca_start[i] == PairState::slip_positive ? 1 :
                             owner.tresca_start[i] == PairState::slip_negative ? -1 :
                                                                                 0);
          }
      }
  }



  template <int dim>
  void
  PrimalActiveSetSolver<dim>::Iteration::start_from_gaps()
  {
    for (unsigned int i = 0; i < n_pairs; ++i)
      W[i] = usable[i] && pairs[i].initial_gap <= 1e-12 * max_weight;
    while (!owner.free_motions(W, tangential_of(W)).empty())
      {
        double g = std::numeric_limits<double>::max();
        for (unsigned int i = 0; i < n_pairs; ++i)
          if (usable[i] && !W[i])
            g = std::min(g, pairs[i].initial_gap);
        AssertThrow(g < std::numeric_limits<double>::max(),
                    dealii::ExcMessage("Contact: even with every contact pair closed, some rigid-body motions "
                                       "are free. Add Dirichlet, roller or point constraints."));
        for (unsigned int i = 0; i < n_pairs; ++i)
          if (usable[i] && !W[i] && pairs[i].initial_gap <= g + 1e-9 * max_weight)
            W[i] = true;
      }
    for (;;)
      {
        check_limit();
        solve_equality_problem(W, {}, 0., xc, xc);
        const auto   g     = contact.gaps(xc);
        const double gtol  = gap_tolerance(xc);
        bool         added = false;
        for (unsigned int i = 0; i < n_pairs; ++i)
          if (usable[i] && !W[i] && g[i] < -gtol)
            {
              W[i]  = true;
              added = true;
              ++result.n_changes;
            }
        if (!added)
          break;
      }
  }



  template <int dim>
  void
  PrimalActiveSetSolver<dim>::Iteration::update_load_work()
  {
    load_work = owner.mode_work;
    if (tresca)
      for (unsigned int i = 0; i < n_pairs; ++i)
        if (!free_t[i] && slip_dir[i] != 0)
          for (const auto &[j, c] : owner.tangential_rows[i])
            load_work[j] -= slip_dir[i] * bound[i] * c;
  }



  template <int dim>
  double
  PrimalActiveSetSolver<dim>::Iteration::project_loads(const std::vector<std::vector<double>> &Z,
                                                       std::vector<double>                    &proj)
  {
    update_load_work();
    proj.assign(owner.pieces->n_modes(), 0.);
    double w = 0;
    for (const auto &z : Z)
      {
        double wz = 0;
        for (unsigned int j = 0; j < z.size(); ++j)
          wz += load_work[j] * z[j];
        for (unsigned int j = 0; j < z.size(); ++j)
          proj[j] += wz * z[j];
        w += wz * wz;
      }
    return w;
  }



  template <int dim>
  void
  PrimalActiveSetSolver<dim>::Iteration::finish_tresca()
  {
    if (!tresca)
      return;
    const auto s = contact.slips(xc);
    result.state.assign(n_pairs, PairState::open);
    result.tangential_force.assign(n_pairs, 0.);
    for (unsigned int i = 0; i < n_pairs; ++i)
      {
        const double d = s[i] - reference[i];
        if (!free_t[i] && slip_dir[i] == 0)
          result.tangential_force[i] = springs ? penalty * pairs[i].weight * d : rows.tangential_multiplier(xc, i);
        else if (!free_t[i])
          result.tangential_force[i] = slip_dir[i] * bound[i];
        if (!W[i])
          continue;
        if (free_t[i])
          result.state[i] = (d >= 0 ? PairState::slip_positive : PairState::slip_negative);
        else
          result.state[i] = (slip_dir[i] == 0 ? PairState::stick :
                             slip_dir[i] > 0  ? PairState::slip_positive :
                                                PairState::slip_negative);
      }
  }



  template <int dim>
  void
  PrimalActiveSetSolver<dim>::Iteration::restore_single()
  {
    for (const auto i : dropped)
      W[i] = true;
    for (const auto i : released)
      slip_dir[i] = 0;
    dropped.clear();
    released.clear();
    if (largest_tangential)
      {
        slip_dir[largest] = (rows.tangential_multiplier(xc, largest) > 0 ? 1 : -1);
        released          = {largest};
      }
    else
      {
        W[largest] = false;
        dropped    = {largest};
      }
    single = true;
  }



  template <int dim>
  bool
  PrimalActiveSetSolver<dim>::Iteration::test_minimiser()
  {
    double scale = 0;
    for (unsigned int i = 0; i < n_pairs; ++i)
      {
        if (W[i])
          scale = std::max(scale, std::abs(rows.normal_multiplier(xc, i)) / pairs[i].weight);
        if (tresca && !springs && tangential[i])
          scale = std::max(scale, std::abs(rows.tangential_multiplier(xc, i)) / pairs[i].weight);
      }
    const double threshold = 1e-11 * scale;
    dropped.clear();
    released.clear();
    double most = 0;
    for (unsigned int i = 0; i < n_pairs; ++i)
      if (W[i] && rows.normal_multiplier(xc, i) / pairs[i].weight > threshold)
        {
          dropped.push_back(i);
          if (rows.normal_multiplier(xc, i) / pairs[i].weight > most)
            {
              most               = rows.normal_multiplier(xc, i) / pairs[i].weight;
              largest            = i;
              largest_tangential = false;
            }
        }
    // Tresca, exact stick: a multiplier above its bound slips
    if (tresca && !springs)
      for (unsigned int i = 0; i < n_pairs; ++i)
        if (tangential[i])
          {
            const double lt     = rows.tangential_multiplier(xc, i);
            const double excess = (std::abs(lt) - bound[i]) / pairs[i].weight;
            if (excess > threshold)
              {
                released.push_back(i);
                if (excess > most)
                  {
                    most               = excess;
                    largest            = i;
                    largest_tangential = true;
                  }
              }
          }
    if (dropped.empty() && released.empty())
      {
        result.converged = true;
        result.active    = W;
        x                = xc;
        finish_tresca();
        return true;
      }
    for (const auto i : dropped)
      W[i] = false;
    for (const auto i : released)
      slip_dir[i] = (rows.tangential_multiplier(xc, i) > 0 ? 1 : -1);
    single = (dropped.size() + released.size() == 1);
    if (!single)
      {
        // several drops that leave a motion free without work: drop the
        // largest violation alone
        Z_of_W       = owner.free_motions(W, tangential_of(W));
        Z_up_to_date = true;
        if (!Z_of_W.empty() && std::sqrt(project_loads(Z_of_W, a)) <= 1e-10 * work_scale)
          {
            Z_up_to_date = false;
            restore_single();
          }
      }
    result.n_changes += dropped.size() + released.size();
    at_minimiser = false;
    return false;
  }



  template <int dim>
  std::vector<unsigned int>
  PrimalActiveSetSolver<dim>::Iteration::pin_free_motions(const std::vector<std::vector<double>> &Z,
                                                          double                                 &eps) const
  {
    // free motions without work: the energy is constant along them, so
    // pinning one DoF per motion (a spring to its present value at DoFs
    // where the motions are independent) selects one of the minimisers and
    // the springs carry no force (to round-off)
    const auto                         &constraints = owner.constraints;
    std::vector<unsigned int>           prox;
    std::vector<dealii::Vector<double>> fields;
    for (const auto &z : Z)
      fields.push_back(owner.motion_field(z));
    std::vector<bool> used(fields.size(), false);
    for (unsigned int k = 0; k < fields.size(); ++k)
      {
        double       best = 0;
        unsigned int bdof = 0, bcol = 0;
        for (unsigned int c = 0; c < fields.size(); ++c)
          if (!used[c])
            for (unsigned int dof = 0; dof < n; ++dof)
              if (!constraints.is_constrained(dof) && std::abs(fields[c][dof]) > best)
                {
                  best = std::abs(fields[c][dof]);
                  bdof = dof;
                  bcol = c;
                }
        if (best == 0)
          break;
        used[bcol] = true;
        prox.push_back(bdof);
        for (unsigned int c = 0; c < fields.size(); ++c)
          if (!used[c])
            fields[c].add(-fields[c][bdof] / fields[bcol][bdof], fields[bcol]);
      }
    for (unsigned int dof = 0; dof < n; ++dof)
      eps = std::max(eps, std::abs(system_matrix.diag_element(dof)));
    return prox;
  }



  template <int dim>
  void
  PrimalActiveSetSolver<dim>::Iteration::compute_direction()
  {
    g    = contact.gaps(xc);
    sc   = tresca ? contact.slips(xc) : std::vector<double>();
    gtol = gap_tolerance(xc);
    if (!Z_up_to_date)
      Z_of_W = owner.free_motions(W, tangential_of(W));
    Z_up_to_date      = false;
    const auto  &Z    = Z_of_W;
    const double work = project_loads(Z, a);
    rigid             = !Z.empty() && std::sqrt(work) > 1e-10 * work_scale;
    slope.assign(n_pairs, 0.);
    tslope.assign(n_pairs, 0.);
    if (rigid)
      {
        tangential               = tangential_of(W);
        dealii::Vector<double> d = owner.motion_field(a);
        trial.reinit(system_matrix.m());
        for (unsigned int i = 0; i < n; ++i)
          trial[i] = d[i];
        const auto s = contact.gaps(trial);
        for (unsigned int i = 0; i < n_pairs; ++i)
          slope[i] = s[i] - pairs[i].initial_gap;
        if (tresca)
          tslope = contact.slips(trial);
      }
    else
      {
        std::vector<unsigned int> prox;
        double                    eps = 0;
        if (!Z.empty())
          prox = pin_free_motions(Z, eps);
        solve_equality_problem(W, prox, eps, xc, trial);
        const auto gt = contact.gaps(trial);
        for (unsigned int i = 0; i < n_pairs; ++i)
          slope[i] = gt[i] - g[i];
        if (tresca)
          {
            const auto st = contact.slips(trial);
            for (unsigned int i = 0; i < n_pairs; ++i)
              tslope[i] = st[i] - sc[i];
          }
      }
  }



  template <int dim>
  void
  PrimalActiveSetSolver<dim>::Iteration::ratio_test()
  {
    alpha = rigid ? std::numeric_limits<double>::infinity() : 1.;
    std::vector<double> ratio(n_pairs, std::numeric_limits<double>::infinity()),
      tratio(n_pairs, std::numeric_limits<double>::infinity());
    for (unsigned int i = 0; i < n_pairs; ++i)
      if (usable[i] && !W[i] && slope[i] < 0)
        {
          ratio[i] = std::max(0., g[i] + gtol) / -slope[i];
          alpha    = std::min(alpha, ratio[i]);
        }
    tslope_max = 0;
    for (const double v : tslope)
      tslope_max = std::max(tslope_max, std::abs(v));
    if (tresca)
      for (unsigned int i = 0; i < n_pairs; ++i)
        {
          // (a held pair moves by round-off only)
          if (free_t[i] || std::abs(tslope[i]) <= 1e-12 * tslope_max)
            continue;
          const double d = sc[i] - reference[i];
          if (slip_dir[i] != 0)
            {
              // slipping: back to the stick piece (0, or |d| = b/k)
              const double ds = slip_dir[i] * tslope[i];
              if (ds < 0)
                tratio[i] = std::max(0., slip_dir[i] * d - (springs ? stick_range(i) : 0.) + gtol) / -ds;
            }
          else if (springs)
            // a spring reaching its bound: |d| = b/k
            tratio[i] = (tslope[i] > 0 ? std::max(0., stick_range(i) - d + gtol) / tslope[i] :
                                         std::max(0., d + stick_range(i) + gtol) / -tslope[i]);
          alpha = std::min(alpha, tratio[i]);
        }
    blocking.clear();
    tblocking.clear();
    if (alpha < (rigid ? std::numeric_limits<double>::infinity() : 1.))
      for (unsigned int i = 0; i < n_pairs; ++i)
        {
          if (ratio[i] <= alpha * (1 + 1e-9) + 1e-300)
            blocking.push_back(i);
          if (tratio[i] <= alpha * (1 + 1e-9) + 1e-300)
            tblocking.push_back(i);
        }
  }



  template <int dim>
  bool
  PrimalActiveSetSolver<dim>::Iteration::retract_drops()
  {
    // pairs dropped together with others that would penetrate (or slip
    // back) at once: they stay in the set and the step is taken again
    // without them (no move, so the energy is unchanged, and the set of
    // drops shrinks each time); if all of them would, the largest violation
    // alone is dropped (the classical single drop, whose step keeps that
    // pair free)
    std::vector<unsigned int> back_n, back_t;
    for (const auto i : dropped)
      if (slope[i] < 0 && g[i] <= gtol)
        back_n.push_back(i);
    for (const auto i : released)
      if (slip_dir[i] * tslope[i] < 0 && std::abs(tslope[i]) > 1e-12 * tslope_max &&
          slip_dir[i] * (sc[i] - reference[i]) - (springs ? stick_range(i) : 0.) <= gtol)
        back_t.push_back(i);
    if (back_n.empty() && back_t.empty())
      return false;
    if (back_n.size() + back_t.size() < dropped.size() + released.size())
      {
        for (const auto i : back_n)
          {
            W[i] = true;
            dropped.erase(std::find(dropped.begin(), dropped.end(), i));
          }
        for (const auto i : back_t)
          {
            slip_dir[i] = 0;
            released.erase(std::find(released.begin(), released.end(), i));
          }
        single = (dropped.size() + released.size() == 1);
        // the largest violation among those left
        if ((largest_tangential && std::find(back_t.begin(), back_t.end(), largest) != back_t.end()) ||
            (!largest_tangential && std::find(back_n.begin(), back_n.end(), largest) != back_n.end()))
          {
            largest_tangential = dropped.empty();
            largest            = dropped.empty() ? released.front() : dropped.front();
          }
      }
    else
      restore_single();
    return true;
  }



  template <int dim>
  void
  PrimalActiveSetSolver<dim>::Iteration::take_step()
  {
    if (rigid)
      {
        const dealii::Vector<double> d = owner.motion_field(a);
        for (unsigned int i = 0; i < n; ++i)
          xc[i] += alpha * d[i];
        ++result.n_rigid_steps;
      }
    else if (blocking.empty() && tblocking.empty())
      {
        // the full step: the minimiser over W (with pinned free motions:
        // one of the minimisers)
        xc           = trial;
        at_minimiser = true;
      }
    else
      for (unsigned int i = 0; i < n; ++i)
        xc[i] += alpha * (trial[i] - xc[i]);
    const auto slips_now = owner.on_closed_only ? contact.slips(xc) : std::vector<double>();
    for (const auto i : blocking)
      {
        W[i] = true;
        if (owner.on_closed_only)
          reference[i] = slips_now[i];
        ++result.n_changes;
      }
    for (const auto i : tblocking)
      {
        // a slipping pair sticks; a spring at its bound slips on
        slip_dir[i] = (slip_dir[i] != 0 ? 0 : (tslope[i] > 0 ? 1 : -1));
        ++result.n_changes;
      }
    tangential = tangential_of(W);
    single     = true; // after the first step every drop is settled
    result.energy.push_back(energy(xc));
  }



  template <int dim>
  typename PrimalActiveSetSolver<dim>::Result
  PrimalActiveSetSolver<dim>::Iteration::run(const std::vector<bool> *start)
  {
    // set-up: the work of the loads on each mode (the condensed load
    // vector), the usable pairs, the stick reference and the Tresca bounds
    auto &mode_work = owner.mode_work;
    mode_work.assign(owner.pieces->n_modes(), 0.);
    for (unsigned int dof = 0; dof < n; ++dof)
      if (const unsigned int p = owner.dof_piece[dof];
          p != dealii::numbers::invalid_unsigned_int && !owner.constraints.is_constrained(dof))
        for (unsigned int k = 0; k < 3; ++k)
          mode_work[3 * p + k] += system_rhs[dof] * owner.pieces->mode(p, k, dof);
    for (const double w : mode_work)
      work_scale += w * w;
    work_scale = std::sqrt(work_scale);
    for (unsigned int i = 0; i < n_pairs; ++i)
      {
        usable[i]  = !pairs[i].junction;
        max_weight = std::max(max_weight, pairs[i].weight);
      }
    if (owner.initial_reference.size() == n_pairs)
      reference = owner.initial_reference;
    if (tresca)
      {
        bound = owner.tresca_bound;
        for (unsigned int i = 0; i < n_pairs; ++i)
          free_t[i] = !usable[i] || !(bound[i] > 0);
      }

    // 1. start: a feasible point and its working set
    if (start != nullptr)
      start_from(*start);
    else
      start_from_gaps();
    tangential = tangential_of(W);
    result.energy.push_back(energy(xc));

    // 2. and 3.: the primal active-set iteration from the minimiser over W
    single = start != nullptr;
    // the model with stick at closed pairs only (solve_stick_on_closed()) is
    // not convex: its energy may rise, and its working sets may come back.
    // A polish that meets a working set again at a minimiser, or that has
    // not settled after polish_solve_limit solves, gives up (converged =
    // false; the caller keeps the convex solution), so that it costs a
    // bounded number of solves instead of the limit of the convex method
    std::set<std::vector<bool>> minimiser_sets;
    for (;;)
      {
        if (owner.on_closed_only &&
            (result.n_solves + result.n_rigid_steps >= polish_solve_limit ||
             (at_minimiser && !minimiser_sets.insert(W).second)))
          {
            result.converged = false;
            return result;
          }
        check_limit();
        if (at_minimiser && test_minimiser())
          return result;
        // a step with working set W from xc
        compute_direction();
        ratio_test();
        if (rigid && alpha == std::numeric_limits<double>::infinity())
          {
            result.converged = false;
            // a free motion of the non-convex model proves nothing
            if (owner.on_closed_only)
              return result;
            // nothing ever blocks the free motion: no equilibrium
            result.active    = W;
            result.mechanism = owner.make_mechanism(a, tangential_of(W), tresca ? bound : std::vector<double>());
            x                = xc;
            finish_tresca();
            return result;
          }
        if (!single && retract_drops())
          continue;
        take_step();
      }
  }



  template <int dim>
  typename PrimalActiveSetSolver<dim>::Result
  PrimalActiveSetSolver<dim>::iterate(const dealii::SparseMatrix<double> &system_matrix,
                                      const dealii::Vector<double>       &system_rhs,
                                      dealii::SparseMatrix<double>       &matrix,
                                      dealii::Vector<double>             &x,
                                      const std::vector<bool>            *start)
  {
    Iteration iteration(*this, system_matrix, system_rhs, matrix, x);
    return iteration.run(start);
  }



  template typename PrimalActiveSetSolver<2>::Result
  PrimalActiveSetSolver<2>::iterate(const dealii::SparseMatrix<double> &,
                                    const dealii::Vector<double> &,
                                    dealii::SparseMatrix<double> &,
                                    dealii::Vector<double> &,
                                    const std::vector<bool> *);
} // namespace dealvem
