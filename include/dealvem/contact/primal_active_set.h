// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_primal_active_set_h
#define dealvem_contact_primal_active_set_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/solvers/saddle_point_solver.h>

#include <memory>
#include <string>
#include <vector>

namespace dealvem
{
  class PieceSupport;

  /**
   * A collapse mechanism: a rigid motion $d$ of the bodies that every
   * contact pair and every displacement constraint allows and on which the
   * loads do positive work. It is the proof that a contact problem has no
   * static equilibrium: for any contact forces in equilibrium with the
   * loads, the principle of virtual work on $d$ gives
   * $f\cdot d = \sum_i \lambda_{n,i}\,(C_{n,i}\,d) + \lambda_{t,i}\,(C_{t,i}\,d)$,
   * which is $\le 0$ for compressive normal forces on separating or
   * closed pairs and tangential forces where $d$ does not slide, against
   * $f\cdot d > 0$ (Farkas' lemma for the equilibrium conditions).
   *
   * The motion is scaled so that the largest nodal displacement is 1.
   */
  struct CollapseMechanism
  {
    /// The rigid motion of one moving piece (an edge-connected part of a
    /// body; a body is usually one piece).
    struct PieceMotion
    {
      /// The piece (ConnectedPieces numbering) and its body (material id).
      unsigned int piece = 0;
      /// The body (material id) of the piece.
      unsigned int body = 0;
      /// The displacement of the piece's area centroid.
      dealii::Tensor<1, 2> translation;
      /// The rotation angle (counter-clockwise positive).
      double rotation = 0;
      /// The area centroid of the piece.
      dealii::Point<2> centroid;
      /// Whether the motion is a rotation (else a translation): the
      /// rotation moves the farthest vertex by more than 1e-9 of the
      /// translation.
      bool rotates = false;
      /// The instantaneous centre of the rotation (where the piece does
      /// not move), when rotates.
      dealii::Point<2> centre;
    };
    /// The pieces that move, in the order of the pieces.
    std::vector<PieceMotion> moving;
    /// The motion per DoF (constrained DoFs included).
    dealii::Vector<double> displacement;
    /// The work $f\cdot d$ of the loads on the motion (> 0).
    double work = 0;
    /// The work relative to the largest work of the loads on a unit rigid
    /// motion of one piece (a measure of how clearly the loads win).
    double relative_work = 0;
    /// The largest violation of the conditions the motion must satisfy,
    /// relative to the largest nodal displacement (1): penetration
    /// $\max_i(-C_{n,i}d)$, tangential motion $|C_{t,i}d|$ at pairs that
    /// stick (stick models) and constraint residuals. Round-off sized for a
    /// proof.
    double largest_violation = 0;
    /// Pairs between moving bodies (or a moving and a fixed one) that stay
    /// closed ($C_{n,i}d = 0$): the hinges and the contacts the bodies
    /// slide or rotate on.
    std::vector<unsigned int> closed_pairs;
    /// The bodies (material ids) on the two sides of each of closed_pairs
    /// (master side first).
    std::vector<std::pair<unsigned int, unsigned int>> closed_pair_bodies;
    /// The slave location of each of closed_pairs.
    std::vector<dealii::Point<2>> closed_pair_locations;
    /// Pairs that open ($C_{n,i}d > 0$).
    std::vector<unsigned int> opening_pairs;
    /// Closed pairs that slide ($C_{t,i}d \ne 0$; frictionless contact only).
    std::vector<unsigned int> sliding_pairs;
    /// Closed pairs among sliding_pairs that slide against a friction
    /// bound (PrimalActiveSetSolver::solve_tresca()).
    std::vector<unsigned int> friction_pairs;
    /// The largest work that the friction bounds $b_i$ can absorb on the
    /// motion, $D = \sum_i b_i |C_{t,i}d|$ (0 without bounds); work
    /// $> D$ proves that the bounds cannot hold the bodies.
    double friction_dissipation = 0;
    /// The condition that fails, named from the motion: "no-tension joints"
    /// (pairs open, nothing slides), "frictionless sliding" (closed pairs
    /// slide, none opens), "friction" (closed pairs slide against their
    /// friction bound) or two of them.
    std::string failing_condition;

    /// A few lines: which bodies move and how (translation, or rotation and
    /// its centre), where the hinges are, which condition fails, the work.
    std::string
    describe(const std::vector<ContactNodePair> &pairs) const;
  };

  /**
   * A globally convergent solver of frictionless and stick contact: the
   * primal active-set method for the convex quadratic program
   * @f[
   *   \min_u\ \tfrac12 u^TKu - f^Tu \quad\text{s.t.}\quad
   *   C_{n,i}u + g_{0,i} \ge 0,\qquad C_{t,i}u = 0\ \text{(stick)},
   * @f]
   * (the displacement constraints condensed into $K$ and $f$), as in
   * Nocedal and Wright, Numerical Optimization, algorithm 16.3, with the
   * steps a contact problem needs when $K$ is singular (bodies held by
   * contact alone).
   *
   * <h3>The method</h3>
   * It keeps a feasible displacement $u$ (no pair penetrates) and a
   * working set $W$ of closed pairs, and never lets the energy rise:
   * 1. <b>Start.</b> $W$ = the pairs with a closed initial gap (and the
   *    pairs of smallest gap until every body is held); the solution with
   *    $g = 0$ on $W$; pairs that penetrate join $W$ until none does.
   * 2. <b>At the minimiser over $W$.</b> If no pair of $W$ is in tension,
   *    $u$ solves the problem (KKT conditions). Otherwise the pairs in
   *    tension leave $W$ (all of them; only the one of largest tension if
   *    that leaves a motion free on which the loads do no work, or if a
   *    pair dropped with others would penetrate at once: the classical
   *    single drop, which always gives a descent direction).
   * 3. <b>Step.</b> If $W$ holds every body, solve with $g = 0$ on $W$
   *    and go from $u$ towards that solution as far as no open pair
   *    penetrates (ratio test); a pair that blocks the step joins $W$. If
   *    $W$ leaves rigid motions free, the energy falls linearly along the
   *    free motion $z$ with the largest work $f\cdot z$ (the projection
   *    of the loads on the free motions): move the bodies along $z$ until a
   *    pair blocks, and add it; if no pair ever blocks, $z$ is a collapse
   *    mechanism (CollapseMechanism) and there is no equilibrium. If the
   *    loads do no work on the free motions, the step is regularised by a
   *    proximal term on the free bodies (their free motion stays put).
   * The energy falls strictly at every step that moves (K symmetric
   * positive semi-definite, the dropped multipliers strictly in tension),
   * so no working set repeats at a minimiser: the method ends after finitely
   * many steps, either at the solution or with the mechanism. Each step
   * costs one saddle-point solve (a rigid step none); a limit of
   * $\max(200, 6 n_{pairs})$ solves guards degenerate ties and throws.
   *
   * With tangential stick (ContactSettings::Tangential::penalty and
   * ContactSettings::Tangential::multipliers) the
   * convex model ties the tangential direction of every pair, open or
   * closed, as Coulomb friction with an infinite coefficient and the
   * associated flow rule does; the non-associated model of
   * ActiveSetSolver's fast path releases open pairs tangentially.
   * ActiveSetSolver therefore polishes the convex solution with its own
   * update (see there). The mechanisms of the two models differ only by
   * sliding at open pairs; a mechanism of the convex model is one of the
   * non-associated model too, so its proof holds for both.
   *
   * <h3>Limits</h3>
   * Rigid motions are those of the edge-connected pieces of the bodies
   * (PieceSupport); a node shared by two pieces (a hinge vertex) moves
   * with the first of them in a rigid step. Junction pairs (three bodies
   * at a point) stay open, as in the active-set update.
   */
  template <int dim>
  class PrimalActiveSetSolver
  {
  public:
    /// What solve() returns besides the solution.
    struct Result
    {
      /// Whether a solution was found (else: no static equilibrium, and
      /// mechanism holds the proof).
      bool converged = false;
      /// The closed pairs of the solution (the working set).
      std::vector<bool> active;
      /// Saddle-point solves.
      unsigned int n_solves = 0;
      /// Rigid steps (no solve).
      unsigned int n_rigid_steps = 0;
      /// Working-set changes (pairs added or dropped).
      unsigned int n_changes = 0;
      /// Iterations of the linear solver over all solves.
      unsigned int linear_iterations = 0;
      /// The energy $\tfrac12u^TKu - f^Tu$ after each step that moved.
      std::vector<double> energy;
      /// The collapse mechanism when !converged.
      CollapseMechanism mechanism;
      /// solve_tresca() only: the state of each pair at the solution
      /// (open: not in the working set, whatever its tangential force; a
      /// closed pair without friction bound slips with zero force).
      std::vector<PairState> state;
      /// solve_tresca() only: the tangential nodal force $\lambda_{t,i}$ of
      /// each pair (ContactAssembler's sign), $\pm b_i$ where it slips.
      std::vector<double> tangential_force;
    };

    /// The contact @p contact (unilateral normal contact; frictionless,
    /// penalty or multiplier stick), the displacement @p constraints and
    /// the linear @p solver, as for ActiveSetSolver.
    PrimalActiveSetSolver(const ContactAssembler<dim>             &contact,
                          const dealii::AffineConstraints<double> &constraints,
                          SaddlePointSolver                       &solver,
                          const ContactSettings                   &settings);

    ~PrimalActiveSetSolver();

    /**
     * Solve; the arguments are those of ActiveSetSolver::solve(). On
     * success @p x holds the displacements and the multipliers of the
     * convex model (with stick: tangential multipliers at every pair).
     * Throws only on a degenerate tie that does not resolve (see above).
     */
    Result
    solve(const dealii::SparseMatrix<double> &system_matrix,
          const dealii::Vector<double>       &system_rhs,
          dealii::SparseMatrix<double>       &matrix,
          dealii::Vector<double>             &x);

    /**
     * The same iteration for the model of ActiveSetSolver's fast path, in
     * which an open pair is free tangentially (stick only where closed),
     * started from the solution @p x (a feasible displacement, e.g. that of
     * the convex model) and the closed pairs @p active. This model is not
     * convex: a pair that closes again must return to its tangential
     * position, so the energy need not fall at every step, and a free
     * motion found here proves nothing. Result::converged says whether it
     * found a solution; a mechanism is not reported.
     */
    Result
    solve_stick_on_closed(const dealii::SparseMatrix<double> &system_matrix,
                          const dealii::Vector<double>       &system_rhs,
                          dealii::SparseMatrix<double>       &matrix,
                          dealii::Vector<double>             &x,
                          const std::vector<bool>            &active);

    /**
     * Tresca friction: the same iteration for the convex problem
     * @f[
     *   \min_u\ \tfrac12 u^TKu - f^Tu + \sum_i \psi_i(C_{t,i}u - r_i)
     *   \quad\text{s.t.}\quad C_{n,i}u + g_{0,i} \ge 0,
     * @f]
     * where the friction bound $b_i \ge 0$ of pair i (@p bound, a nodal
     * force) limits its tangential force: with tangential multipliers
     * $\psi_i(s) = b_i|s|$ (exact stick below the bound), with the stick
     * penalty $k_i = \varepsilon_t w_i$ the Huber function
     * $\psi_i(s) = \tfrac12 k_i s^2$ for $|s| \le b_i/k_i$ and
     * $b_i|s| - b_i^2/(2k_i)$ beyond. Besides its working set of closed
     * pairs the iteration keeps, per pair with $b_i > 0$, whether it sticks
     * (the stick row or spring) or slips in the direction $\sigma_i$ (the
     * force $\sigma_ib_i$ as a load): a sticking pair whose multiplier
     * exceeds $b_i$ at a minimiser starts to slip (as a pair in tension
     * leaves the working set), and a step that would carry a pair across the
     * end of its piece of $\psi_i$ stops there and switches it (as a pair
     * that would penetrate joins the set). The energy falls at every step
     * that moves, so the iteration ends at the minimiser or with a rigid
     * motion, allowed by the normal contacts, on which the loads do more
     * work than the bounds can absorb (CollapseMechanism, failing condition
     * "friction" when pairs slide against a bound). Pairs with $b_i = 0$
     * are free tangentially. Every pair keeps its bound whether it is open
     * or closed (convexity); FrictionSolver's fixed point sets $b_i$ from
     * the normal forces, 0 at open pairs.
     *
     * @p x is the start (no pair penetrates) and returns the solution;
     * @p active the closed pairs at the start; @p state the tangential
     * state of each pair at the start (stick or a slip direction; used where
     * it agrees with @p x). The settings of the constructor must be a stick
     * model (penalty or multipliers); the reference of
     * set_tangential_reference() is $r$.
     */
    Result
    solve_tresca(const dealii::SparseMatrix<double> &system_matrix,
                 const dealii::Vector<double>       &system_rhs,
                 dealii::SparseMatrix<double>       &matrix,
                 dealii::Vector<double>             &x,
                 const std::vector<double>          &bound,
                 const std::vector<bool>            &active,
                 const std::vector<PairState>       &state);

    /**
     * Stick at the relative tangential displacements @p reference (one per
     * pair) instead of 0: the stick of a quasi-static load step that starts
     * from earlier slips (Coulomb friction's reference, FrictionSolver).
     * Empty: 0.
     */
    void
    set_tangential_reference(const std::vector<double> &reference)
    {
      initial_reference = reference;
    }

  private:
    /// The state and the steps of one run of iterate() (defined in
    /// source/contact/primal_active_set_iteration.cc).
    class Iteration;

    /// The iteration of solve() and solve_stick_on_closed() (@p start:
    /// the closed pairs to start from with the displacement in @p x).
    Result
    iterate(const dealii::SparseMatrix<double> &system_matrix,
            const dealii::Vector<double>       &system_rhs,
            dealii::SparseMatrix<double>       &matrix,
            dealii::Vector<double>             &x,
            const std::vector<bool>            *start);

    /// The free rigid motions with working set @p closed: an orthonormal
    /// basis over the modes (3 p + k), empty when every body is held.
    std::vector<std::vector<double>>
    free_motions(const std::vector<bool> &closed, const std::vector<bool> &tangential) const;

    /// The displacement (per DoF) of the motion @p modes.
    dealii::Vector<double>
    motion_field(const std::vector<double> &modes) const;

    /// The mechanism of the motion @p modes (verified, scaled, described)
    /// with the pairs @p tangential held tangentially and the friction
    /// bounds @p bound (empty: none).
    CollapseMechanism
    make_mechanism(const std::vector<double> &modes,
                   const std::vector<bool>   &tangential,
                   const std::vector<double> &bound) const;

    const ContactAssembler<dim>             &contact;
    const dealii::AffineConstraints<double> &constraints;
    SaddlePointSolver                       &solver;
    ContactSettings                          settings;
    bool                                     stick;
    /// Stick only at closed pairs (solve_stick_on_closed()).
    bool                                     on_closed_only = false;
    /// See set_tangential_reference().
    std::vector<double>                      initial_reference;
    /// solve_tresca(): the friction bounds (empty otherwise) and the
    /// tangential states to start from.
    std::vector<double>                      tresca_bound;
    std::vector<PairState>                   tresca_start;
    std::unique_ptr<PieceSupport>            pieces;
    /// Per DoF, the piece that moves it (the first piece of its node;
    /// invalid for nodes of no cell).
    std::vector<unsigned int> dof_piece;
    /// Per mode, the work of the loads on it (set by solve()).
    std::vector<double> mode_work;
    /// Rows over the modes (first-piece convention): constraint lines, and
    /// per pair its normal and tangential row.
    std::vector<std::vector<std::pair<unsigned int, double>>> constraint_rows, normal_rows, tangential_rows;
    /// The same rows in PieceSupport's convention, for its rank test.
    std::vector<std::vector<std::pair<unsigned int, double>>> support_constraint_rows;
    std::vector<std::vector<std::vector<std::pair<unsigned int, double>>>> support_normal_rows,
      support_tangential_rows;
  };
} // namespace dealvem

#endif
