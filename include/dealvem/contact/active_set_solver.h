// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_active_set_solver_h
#define dealvem_contact_active_set_solver_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <dealvem/contact/active_set_update.h>
#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/contact_solver.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/contact/primal_active_set.h>
#include <dealvem/contact/rigid_body_support.h>
#include <dealvem/solvers/saddle_point_solver.h>

#include <memory>
#include <string>
#include <vector>

namespace dealvem
{
  /**
   * Solves the contact problem: for tied normal contact one saddle-point
   * solve; for unilateral contact the primal-dual active set strategy of
   * Hüeber and Wohlmuth (2005) @cite HueeberWohlmuth2005, a semismooth
   * Newton method on the complementarity function of the normal contact
   * conditions (in the spirit of @cite AlartCurnier1991).
   *
   * With the compressive nodal force $\mu_i = -\lambda_i \ge 0$, the
   * conditions $g_i\ge 0$, $\mu_i\ge 0$, $g_i\mu_i = 0$ are equivalent to
   * $\mu_i = \max(0, \mu_i - c\,w_i\,g_i)$ for any $c > 0$. Starting from the
   * pairs whose initial gap is closed ($g_{0,i}\le 0$), each iteration solves
   * with $g_i = 0$ on the active set and $\lambda_i = 0$ elsewhere, then
   * takes the new active set $\{i : \mu_i/w_i - c\,g_i > 0\}$, until it does
   * not change. A set seen before (other than the last one) means the
   * iteration cycles: this and exceeding the iteration limit throw an
   * exception with the iteration history.
   *
   * With a RigidBodySupport (set_support()), bodies that start apart or
   * touch at a single point get a first active set that holds them: the
   * pairs of smallest initial gap are closed until every body is held (the
   * contact a rigid approach makes first), so the first system is not
   * singular, whatever the solver. An active set that would leave a body
   * free (every pair that held it pulled open) means there is no static
   * equilibrium: solve() then stops with a message naming the free motions.
   *
   * <h3>Acceleration</h3>
   * The plain update crawls in two places, both seen on Hertz-type
   * problems (examples/step-3): the first solve holds the bodies at the
   * few pairs of smallest gap, so the bodies approach far too much and
   * nearly every pair comes out penetrating; from that too large set the
   * iteration then releases, per step, only the band at each edge of the
   * contact zone where the bonded solution is in tension, which is about
   * half of the excess (the excess halves per step). With
   * set_pair_neighbours() (the pairs' order along their interfaces) and
   * ContactSettings::accelerate_active_set, two corrections of the
   * proposed set shorten both phases:
   * - a step that would more than double the active set adds only the
   *   pairs penetrating by more than half the largest penetration (the
   *   rest follow in the next step if they still penetrate);
   * - a step that releases pairs also releases, from each run of released
   *   pairs along the interface, the kept active pairs next to it over the
   *   run's length (the excess halves per step, so twice the band reaches
   *   about the true edge).
   * A correction is dropped when the corrected set would leave a body
   * free, and the release extrapolation is switched off for the rest of
   * the solve as soon as a pair it released penetrates again (the edge is
   * then found); from there on the plain update runs. Convergence is
   * judged on the plain update of the last exact solution, so the result
   * is the same complementarity solution: only the path is shorter
   * (Hertz, step-3's meshes: k = 1 from 8/10/10 to 4/4/5 iterations, k = 2
   * from 8/9/11 to 5/5/6). Cycle detection applies to plain steps.
   *
   * <h3>Global convergence</h3>
   * The update above is a semismooth Newton method: fast near the
   * solution, but with no guarantee from far away. Near a limit load (an
   * arch just thicker than its least thickness, a wall just inside its
   * friction limit) its first steps open so many pairs at once that the
   * set holds no equilibrium, or the sets cycle. With
   * ContactSettings::globalize (the default) such a failure is not the
   * answer: the solve starts again with PrimalActiveSetSolver, a primal
   * active-set method whose energy never rises, which converges whenever
   * the problem has a solution and otherwise returns a collapse mechanism,
   * the proof that it has none. solve() then throws "No static
   * equilibrium" with the mechanism (last_mechanism()).
   * With tangential stick the globalized solve ties open pairs
   * tangentially too (the convex model); the update above then polishes
   * its solution, starting from its set, to the model of the fast path
   * (open pairs free), which takes one or two solves where that model has
   * a solution near the convex one. That model is not convex: the polish
   * gives up when a working set comes back or after 30 solves, then tries
   * the fast path's update from the convex set (at most 10 iterations). If
   * neither converges, the convex solution is returned and
   * Result::convex_stick_model says so (the report's "convex stick model
   * kept"; the pairs' status "open-tied").
   *
   * <h3>Cycles of the stick model</h3>
   * With stick (Tangential penalty or multipliers) the fast path's model,
   * stick at closed pairs only, is not convex, and its plain update can
   * cycle for a reason, not by round-off: on a tall running-bond wall (15
   * courses and more, tests/contact/tall_wall.cc) head-joint pairs near the
   * wall's ends close, come out in tension because the stick holds them,
   * open, are free tangentially and penetrate again. When a plain step
   * would return to a visited set, the pairs it switches are held
   * tangentially from then on, open or closed (the convex model on those
   * pairs only, ActiveSetUpdate::State::tied_open; at most three such
   * rounds, decided on completed solves), and the iteration goes on; a
   * further cycle is a failure and the globalized solve takes over as
   * above. On a large wall many such pairs flip with the same period but
   * in different phases, and the whole set does not repeat for tens of
   * iterations: a pair that the plain updates switch three times in a row
   * and that would switch a fourth time is held the same way on its own
   * (ActiveSetUpdate::State::alternations). Result::tied_open lists the
   * pairs; those that end open have the status "open-tied" and transmit
   * their tangential force, and the report says how many were held.
   * Measured on the 150-block wall: 10 iterations and 9 pairs held (6 end
   * open; 12, 11 and 8 with cycles alone) instead of the globalized
   * solve, its polish and the convex model for all 442 open pairs; on the
   * 201-body wall of benchmark_assembly 200 5, 13 iterations instead of
   * 33. The fast path's answers are not touched where no pair cycles or
   * alternates.
   *
   * <h3>Inexact solves</h3>
   * Unilateral contact (not tied): the solution of a set that is not the
   * last one only serves to choose the next set. With a solver that can
   * stop early (SaddlePointSolver::set_inexact(): CG-AMG on the symmetric
   * condensed stiffness), every solve stops first at 1e-3 relative
   * (SaddlePointSolver::Settings::inexact_start_tolerance) and the rule is
   * applied to a copy of the state; the solve is continued by a decade
   * (SaddlePointSolver::refine_last_solve()) and the rule applied again,
   * and the next set is taken once two such solves propose the same one
   * (the pairs' decisions did not move with the solve's error), or at once
   * when the first proposal opens or closes at least 32 pairs (a set far
   * from the last one: the few pairs within the solve's error can change
   * the path, not the set accepted; on the 100-block wall of
   * benchmarks/assembly 39 CG iterations instead of 46, on the 200-block
   * wall 69 instead of 81, the same sets in every iteration); else the
   * solve goes on by decades down to its inexact tolerance
   * (Settings::inexact_tolerance, 1e-6 relative), where, as before, if
   * the rule proposes a next set, that set is taken; if it would stop
   * (converge, or fail: a
   * cycle, the iteration limit, a set that holds no equilibrium), the solve
   * is continued to the full tolerance from where it stopped
   * (SaddlePointSolver::complete_last_solve(), the same condensed matrix
   * and preconditioner) and the rule decides on that solution. So the
   * solution returned, every convergence decision and every failure are
   * those of full-accuracy solves; the intermediate sets may differ only
   * where a pair's decision lies within the inexact solve's error, which
   * can change the path but not the set the iteration accepts (it is
   * checked at full accuracy). CG iterations in all, decades against a
   * single inexact tolerance of 1e-6 (measured 2026-11-30): the walls of
   * benchmarks/assembly with 50, 100, 150 and 200 blocks, 6 quads per
   * block: 109/136, 103/134, 176/220, 275/369 (same active-set iterations);
   * 100 blocks, 12 quads (73k DoFs): 340/432 and 8 active-set iterations
   * instead of 10, solve 9.7 s instead of 10.6 s; the Hertz-like pair of
   * tests/contact/inexact_active_set with its meshes refined 1, 3/2, 4/2,
   * 8/4 times: 116/146, 145/151, 237/309, 244/291. (A single tolerance of
   * 1e-3 took 580 CG iterations instead of 225 on the 3/2 refinement: its
   * loose solutions sent the iteration another way.)
   *
   * <h3>Driver and rule</h3>
   * solve() only owns the loop: per iteration it adds the contact blocks
   * of the current set (ContactAssembler::assemble()), solves with the
   * SaddlePointSolver and hands the solution to ActiveSetUpdate::update(),
   * which holds every rule above (first set, update, acceleration,
   * convergence, cycles, iteration limit, equilibrium). A program that
   * wants the loop in its own hands (examples/step-6, a Newton method)
   * calls ActiveSetUpdate directly and gets the same iterates.
   */
  template <int dim>
  class ActiveSetSolver : public ContactSolver<dim>
  {
  public:
    /// What solve() returns besides the solution (the fields of
    /// ContactSolveResult's first two groups).
    using Result = ContactSolveResult;

    /// @p c is the constant of the active-set update, units of E/h.
    ActiveSetSolver(const ContactAssembler<dim>             &contact,
                    const dealii::AffineConstraints<double> &constraints,
                    SaddlePointSolver                       &solver,
                    const ContactSettings                   &settings,
                    const double                             c);

    /// Neighbours along the interfaces of the concatenated pair lists of
    /// @p interfaces (in the order given).
    static std::vector<std::vector<unsigned int>>
    pair_neighbours(const std::vector<NodeInsertion::Interface> &interfaces);

    /**
     * @p system_matrix and @p system_rhs hold the elasticity part (size
     * n_dofs + n_multipliers, assembled with the constraints). @p matrix
     * (same sparsity) is used as work space; it may be @p system_matrix
     * itself (solves_in_place()): the contact blocks are then assembled
     * into the system matrix, whose rows they write
     * (ContactAssembler::rows_written()) are restored before each
     * assembly and before solve() returns or throws. On return @p x holds
     * the displacements followed by the multipliers.
     */
    Result
    solve(const dealii::SparseMatrix<double> &system_matrix,
          const dealii::Vector<double>       &system_rhs,
          dealii::SparseMatrix<double>       &matrix,
          dealii::Vector<double>             &x);

    /// Solve one load step: solve(), with the result kept (last_result())
    /// and its state filled.
    const Result &
    solve_step(const dealii::SparseMatrix<double> &system_matrix,
               const dealii::Vector<double>       &system_rhs,
               dealii::SparseMatrix<double>       &matrix,
               dealii::Vector<double>             &x) override;

    /// True: solve_step() may be given the system matrix as its work
    /// matrix (see solve()).
    bool
    solves_in_place() const override;

    /// "active set" (or "tied" for tied normal contact).
    std::string
    name() const override;

  private:
    using ContactSolver<dim>::contact;
    using ContactSolver<dim>::constraints;
    using ContactSolver<dim>::solver;
    using ContactSolver<dim>::settings;
    using ContactSolver<dim>::c;
    using ContactSolver<dim>::support;
    using ContactSolver<dim>::neighbours;
    using ContactSolver<dim>::mechanism;
  };
} // namespace dealvem

#endif
