// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_contact_solver_h
#define dealvem_contact_contact_solver_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/primal_active_set.h>
#include <dealvem/contact/rigid_body_support.h>
#include <dealvem/solvers/saddle_point_solver.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace dealvem
{
  /**
   * What a contact solve of one load step reports besides the solution, for
   * every contact solver (ContactSolver). The first group is filled by every
   * solver; the others by the solver they are named after and stay at
   * their defaults (zero, empty, false) otherwise, so that a program reads
   * one type whatever solver ran.
   */
  struct ContactSolveResult
  {
    /// @name Every solver (ContactSolver::solve_step() fills both state and
    /// active)
    /// @{

    /// The converged state of each pair (row i of the contact constraints
    /// belongs to pair i): open, stick, or slip along +t or -t. The
    /// unilateral and tied solvers report a closed pair as stick.
    std::vector<PairState> state;
    /// Per pair, whether the normal constraint is enforced (the pair is
    /// closed: state != open).
    std::vector<bool> active;
    /// Iterations of the nonlinear solve (active-set or semismooth Newton
    /// steps), i.e. saddle-point solves.
    unsigned int n_iterations = 0;
    /// Per iteration, the number of closed pairs of the set solved with.
    std::vector<unsigned int> n_active_history;
    /// Iterations of the linear solver summed over all saddle-point
    /// solves (SaddlePointSolver::last_iterations(): 1 per direct solve),
    /// the completions of inexact solves included.
    unsigned int linear_iterations = 0;
    /// Saddle-point solves of the globally convergent solve that took over
    /// when the fast path failed (0: not needed).
    unsigned int n_globalized_solves = 0;
    /// @}

    /// @name The unilateral and tied solver (ActiveSetSolver)
    /// @{

    /// Inexact solves continued to the full tolerance because the rule
    /// would stop on them (ActiveSetSolver, "Inexact solves").
    unsigned int n_completed_solves = 0;
    /// Pairs with an open initial gap closed for the first iteration so
    /// that every body is held.
    unsigned int n_closed_for_support = 0;
    /// Steps whose proposed set the acceleration corrected.
    unsigned int n_accelerated = 0;
    /// Why the fast path (the active-set iteration) gave up, when the
    /// globalized solve took over; empty otherwise.
    std::string fast_path_failure;
    /// Rigid steps of the globalized solve.
    unsigned int n_globalized_rigid_steps = 0;
    /// Iterations of the polish after the globalized solve (stick models).
    unsigned int n_polish_iterations = 0;
    /// Whether the result is the convex stick model of the globalized
    /// solve (open pairs tied tangentially) because the polish to the
    /// model of the fast path did not converge.
    bool convex_stick_model = false;
    /// Per pair (empty: none), whether the fast path held the pair
    /// tangentially although it is open: with stick, the pairs whose
    /// switching made the active set cycle or alternate
    /// (ActiveSetUpdate::State::tied_open).
    std::vector<bool> tied_open;

    /// Whether pair @p i transmits a tangential force: closed, or held
    /// tangentially while open (the convex stick model, or tied_open).
    bool
    tied_tangentially(const unsigned int i) const
    {
      return active[i] || convex_stick_model || (i < tied_open.size() && tied_open[i]);
    }
    /// @}

    /// @name Coulomb friction (FrictionSolver)
    /// @{

    /// Per iteration, the numbers of open, sticking and slipping pairs of
    /// the states it solved with.
    std::vector<std::array<unsigned int, 3>> history;
    /// @var std::vector<double> slip
    /// Per pair, the relative tangential displacement
    /// $s_i = (u_B-u_A)\cdot t_i$ at the end of the step (length units).
    /// @var std::vector<double> slip_increment
    /// Per pair, the slip of this step against the reference of the last
    /// one: $s_i$ minus the reference with multipliers, the increment of
    /// the plastic slip with the penalty variant; zero for open pairs.
    /// @var std::vector<double> tangential_multiplier
    /// Per pair, the friction nodal force $\lambda_{t,i}$ (the slave node
    /// receives $-\lambda_{t,i} t_i$).
    /// @var std::vector<double> reference
    /// Per pair, the reference for the next step: the relative tangential
    /// displacement, or the plastic slip with the penalty variant.
    std::vector<double> slip, slip_increment, tangential_multiplier, reference;
    /// Energy dissipated by friction in this step,
    /// $\sum_{\text{slip}} \lambda_{t,i}\,\Delta s_i$ (with the penalty, the
    /// plastic slip increment).
    double dissipated_energy = 0;
    /// The factors of the friction coefficients at which the continuation
    /// converged, in order, ending with 1; empty when the plain iteration
    /// converged.
    std::vector<double> continuation_factors;
    /// Semismooth Newton iterations that did not converge (the plain one
    /// and those of the continuation); their saddle-point solves are
    /// counted in n_iterations.
    unsigned int n_failed_attempts = 0;
    /// Whether the step was solved by the globalized path after the plain
    /// iteration failed: the Tresca fixed point (or Newton from its
    /// settled states), without continuation.
    bool globalized_start = false;
    /// Tresca problems solved in the fixed point (0: not needed).
    unsigned int n_fixed_point_iterations = 0;
    /// @}
  };

  /**
   * The one seam of the contact solvers: the nonlinear solve of a load step
   * of bodies in contact, given the elasticity part of the saddle-point
   * system, the contact rows (ContactAssembler, whose rows() gives their
   * layout as a ContactRows) and a linear SaddlePointSolver.
   *
   * A program holds a ContactSolver made by create() from the contact
   * settings and calls solve_step() once per load step; a solver carries
   * what a step hands to the next (the friction states and reference
   * slips) itself. The solvers are
   * - ActiveSetSolver: tied contact (one solve) and unilateral
   *   frictionless or stick contact (an accelerated primal-dual active set
   *   with the globally convergent PrimalActiveSetSolver behind it);
   * - FrictionSolver: Coulomb friction (a semismooth Newton method on
   *   open / stick / slip states, globalized by a Tresca fixed point).
   *
   * A new solver (a different globalization, an interior-point method, a
   * mortar formulation's solve) derives from this class, implements
   * solve_step() and name(), fills the first group of ContactSolveResult,
   * and joins create(): the programs do not change. The linear solves are
   * another seam, SaddlePointSolver (serial, or DistributedContactSolver
   * on several MPI processes), so every contact solver runs on every
   * linear solver.
   *
   * When a solve proves that there is no static equilibrium it throws, and
   * last_mechanism() gives the collapse mechanism found.
   */
  template <int dim>
  class ContactSolver
  {
  public:
    /// What solve_step() reports.
    using Result = ContactSolveResult;

    /**
     * The solver the contact settings ask for: FrictionSolver for Coulomb
     * friction (ContactSettings::is_coulomb()), ActiveSetSolver otherwise.
     * The arguments are those of the constructors: the contact rows, the
     * constraints of the displacements, the linear solver, the settings and
     * the constant @p c of the complementarity function (units of E/h).
     * The references must outlive the solver.
     */
    static std::unique_ptr<ContactSolver<dim>>
    create(const ContactAssembler<dim>             &contact,
           const dealii::AffineConstraints<double> &constraints,
           SaddlePointSolver                       &solver,
           const ContactSettings                   &settings,
           const double                             c);

    /// Frees the solver.
    virtual ~ContactSolver();

    /// The solver's name for reports ("active set", "Coulomb friction").
    virtual std::string
    name() const = 0;

    /**
     * Solve one load step. @p system_matrix and @p system_rhs hold the
     * elasticity part (size n_dofs + n_multipliers, assembled with the
     * constraints); @p matrix has the same sparsity and is overwritten with
     * the system of each iteration (it may be @p system_matrix itself if
     * solves_in_place(): the solver then restores it before it returns or
     * throws; a solver that cannot refuses that); @p x receives the displacements and the
     * multipliers. The step starts from the state the last call ended in
     * (the first from the initial gaps). Throws, with the iteration history
     * or the collapse mechanism (last_mechanism()), if the step has no
     * solution or the iteration fails.
     */
    virtual const Result &
    solve_step(const dealii::SparseMatrix<double> &system_matrix,
               const dealii::Vector<double>       &system_rhs,
               dealii::SparseMatrix<double>       &matrix,
               dealii::Vector<double>             &x) = 0;

    /// Whether solve_step() may be given the system matrix itself as its
    /// work matrix, saving a copy of the size of the system (false unless
    /// a solver says otherwise).
    virtual bool
    solves_in_place() const;

    /// The result of the last solve_step() (empty before the first).
    const Result &
    last_result() const
    {
      return result;
    }

    /// Check every set of closed pairs against the rigid-body motions of
    /// the bodies (RigidBodySupport): a set that would leave a body free
    /// is corrected or, if none holds it, proves there is no equilibrium.
    void
    set_support(const RigidBodySupport *support)
    {
      this->support = support;
    }

    /// The neighbours of each pair along its interface, for solvers that
    /// use them (ActiveSetSolver's acceleration; others ignore them).
    void
    set_pair_neighbours(const std::vector<std::vector<unsigned int>> &neighbours)
    {
      this->neighbours = neighbours;
    }

    /// The collapse mechanism of the last solve that proved there is no
    /// static equilibrium (nullptr otherwise).
    const CollapseMechanism *
    last_mechanism() const
    {
      return mechanism.get();
    }

  protected:
    /// Store the references (see create()).
    ContactSolver(const ContactAssembler<dim>             &contact,
                  const dealii::AffineConstraints<double> &constraints,
                  SaddlePointSolver                       &solver,
                  const ContactSettings                   &settings,
                  const double                             c);

    /// Fill the common fields of @p r that the concrete solve left empty:
    /// state from active or active from state, and n_active_history from
    /// the friction history.
    static void
    complete_common_fields(Result &r);

    /// The contact rows and the blocks they add.
    const ContactAssembler<dim> &contact;
    /// The constraints of the displacements.
    const dealii::AffineConstraints<double> &constraints;
    /// The linear saddle-point solver.
    SaddlePointSolver &solver;
    /// The contact settings (a copy).
    ContactSettings settings;
    /// The constant of the complementarity function.
    double c;
    /// The rigid-body check, or nullptr.
    const RigidBodySupport *support = nullptr;
    /// The pairs' neighbours along their interfaces (may be empty).
    std::vector<std::vector<unsigned int>> neighbours;
    /// The collapse mechanism of the last failed solve, or nullptr.
    std::shared_ptr<CollapseMechanism> mechanism;
    /// The result of the last solve_step().
    Result result;
  };
} // namespace dealvem

#endif
