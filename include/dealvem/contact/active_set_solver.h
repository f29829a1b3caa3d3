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
   * (open pairs free), which takes one or two solves. If the polish does
   * not converge, the convex solution is returned and
   * Result::convex_stick_model says so. The fast path's answers are not
   * touched where it converges.
   *
   * <h3>Inexact solves</h3>
   * Unilateral contact (not tied): the solution of a set that is not the
   * last one only serves to choose the next set. With a solver that can
   * stop early (SaddlePointSolver::set_inexact(): CG-AMG on the symmetric
   * condensed stiffness), every solve stops at its inexact tolerance
   * (SaddlePointSolver::Settings::inexact_tolerance, 1e-6 relative), and
   * the rule is first applied to a copy of the state: if it proposes a
   * next set, that set is taken; if it would stop (converge, or fail: a
   * cycle, the iteration limit, a set that holds no equilibrium), the solve
   * is continued to the full tolerance from where it stopped
   * (SaddlePointSolver::complete_last_solve(), the same condensed matrix
   * and preconditioner) and the rule decides on that solution. So the
   * solution returned, every convergence decision and every failure are
   * those of full-accuracy solves; the intermediate sets may differ only
   * where a pair's decision lies within the inexact solve's error, which
   * can change the path but not the set the iteration accepts (it is
   * checked at full accuracy). On the 100-block wall of
   * benchmarks/assembly this takes 5 iterations as before, with 21 to 33 CG
   * iterations per solve instead of 49 to 59, and 25 for the completion.
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
  class ActiveSetSolver
  {
  public:
    /// What solve() returns besides the solution.
    struct Result
    {
      /// The converged active set, per pair (true: normal constraint
      /// enforced, the pair is closed).
      std::vector<bool>         active;
      /// Active-set iterations, i.e. saddle-point solves.
      unsigned int              n_iterations = 0;
      /// Per iteration, the number of active pairs of the set solved with.
      std::vector<unsigned int> n_active_history;
      /// Iterations of the linear solver summed over all saddle-point
      /// solves (SaddlePointSolver::last_iterations(): 1 per direct solve),
      /// the completions of inexact solves included.
      unsigned int              linear_iterations = 0;
      /// Inexact solves continued to the full tolerance because the rule
      /// would stop on them (see "Inexact solves" in the class
      /// documentation).
      unsigned int              n_completed_solves = 0;
      /// Pairs with an open initial gap closed for the first iteration so
      /// that every body is held.
      unsigned int              n_closed_for_support = 0;
      /// Steps whose proposed set the acceleration corrected.
      unsigned int              n_accelerated = 0;
      /// Why the fast path (the active-set iteration above) gave up, when
      /// the globalized solve took over; empty otherwise.
      std::string               fast_path_failure;
      /// Saddle-point solves of the globalized solve (0: not needed).
      unsigned int              n_globalized_solves = 0;
      /// Rigid steps of the globalized solve.
      unsigned int              n_globalized_rigid_steps = 0;
      /// Iterations of the polish after the globalized solve (stick models).
      unsigned int              n_polish_iterations = 0;
      /// Whether the result is the convex stick model of the globalized
      /// solve (open pairs tied tangentially) because the polish to the
      /// model of the fast path did not converge.
      bool                      convex_stick_model = false;
    };

    /// @p c is the constant of the active-set update, units of E/h.
    ActiveSetSolver(const ContactAssembler<dim>             &contact,
                    const dealii::AffineConstraints<double> &constraints,
                    SaddlePointSolver                       &solver,
                    const ContactSettings                   &settings,
                    const double                             c);

    /// Check every active set against the rigid-body motions (see above).
    void
    set_support(const RigidBodySupport *support)
    {
      this->support = support;
    }

    /**
     * The neighbours of each pair along its interface (pairs of one
     * sub-edge, vertex - midpoint - vertex for k = 2), for the acceleration
     * above. pair_neighbours() builds them from node insertion's segments.
     */
    void
    set_pair_neighbours(const std::vector<std::vector<unsigned int>> &neighbours)
    {
      this->neighbours = neighbours;
    }

    /// Neighbours along the interfaces of the concatenated pair lists of
    /// @p interfaces (in the order given).
    static std::vector<std::vector<unsigned int>>
    pair_neighbours(const std::vector<NodeInsertion::Interface> &interfaces);

    /**
     * @p system_matrix and @p system_rhs hold the elasticity part (size
     * n_dofs + n_multipliers, assembled with the constraints). @p matrix
     * (same sparsity) is used as work space. On return @p x holds the
     * displacements followed by the multipliers.
     */
    Result
    solve(const dealii::SparseMatrix<double> &system_matrix,
          const dealii::Vector<double>       &system_rhs,
          dealii::SparseMatrix<double>       &matrix,
          dealii::Vector<double>             &x);

    /**
     * The collapse mechanism of the last solve() that found no equilibrium
     * (the globalized solve's proof), or nullptr. solve() throws "No static
     * equilibrium" with its description; a program catches the exception
     * and writes the mechanism (ContactProblem: a VTU field and an SVG
     * picture).
     */
    const CollapseMechanism *
    last_mechanism() const
    {
      return mechanism.get();
    }

  private:
    const ContactAssembler<dim>             &contact;
    const dealii::AffineConstraints<double> &constraints;
    SaddlePointSolver                       &solver;
    ContactSettings                          settings;
    double                                   c;
    const RigidBodySupport                  *support = nullptr;
    std::vector<std::vector<unsigned int>>   neighbours;
    std::unique_ptr<CollapseMechanism>       mechanism;
  };
} // namespace dealvem

#endif
