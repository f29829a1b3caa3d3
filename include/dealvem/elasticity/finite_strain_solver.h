// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_finite_strain_solver_h
#define dealvem_elasticity_finite_strain_solver_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/finite_strain_assembler.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace dealvem
{
  class FiniteStrainConstraints;

  /**
   * Newton's method with load steps for the finite-strain problem of a
   * FiniteStrainAssembler: find $u$ with $r(u) = \lambda f_{ext} - f_{int}(u) = 0$
   * at the load factors $\lambda_n = n/N$, $n = 1..N$, and the Dirichlet
   * conditions scaled by the same factor.
   *
   * <h3>Dirichlet conditions</h3>
   * The constraints given to the constructor are those of the full load:
   * lines $u_i = \sum_j a_{ij}u_j + b_i$ as interpolate_boundary_values()
   * or add_roller() make them (closed). At the load factor $\lambda$ the
   * solver imposes $u_i = \sum_j a_{ij}u_j + \lambda b_i$. Each Newton
   * update $\delta u$ is constrained by the same lines with the
   * inhomogeneity $\lambda b_i + \sum_j a_{ij}u_j - u_i$ (what the current
   * iterate misses), so the first update of a step carries the increment of
   * the prescribed displacement into the whole body through the tangent of
   * the last converged state (as deal.II's step-44 does), and the later ones
   * are homogeneous.
   *
   * <h3>One Newton iteration</h3>
   * Assemble $K(u)$ and $r(u)$ (FiniteStrainAssembler::assemble()), solve
   * $K\,\delta u = r$ with the update constraints (SparseDirectUMFPACK),
   * and set $u \leftarrow u + \alpha\,\delta u$ with a backtracking line
   * search on the norm of the free residual (the residual condensed with
   * the homogeneous constraints, i.e. without the reactions):
   * $\alpha = 1, 1/2, 1/4, \ldots$ (at most Parameters::max_line_search_halvings
   * halvings) until $\|r(u+\alpha\delta u)\| \le (1 - 10^{-4}\alpha)\|r(u)\|$
   * and the trial state lies in the domain of the element and the law: no
   * cell inverted (ExcInvertedCell), $\det F > 0$ at every material point
   * (ExcNonPositiveJacobian), a plane-stress state of the law
   * (ExcNoPlaneStressState), a finite residual. Such a trial is only an
   * iterate, not the answer: it is halved like one without decrease, and
   * only a step that no step length brings back into the domain fails,
   * naming the step and the last reason. A Newton update or an internal
   * force that is not finite stops the step with its own message (the
   * iteration and the quantity), not as an inverted cell. An update that
   * moves prescribed DoFs (the first of a step) is taken in full unless it
   * leaves the domain: its
   * residual norm need not decrease, since the free residual at the old
   * state does not see the new boundary values; when it is shortened, the
   * next update carries the rest of the prescribed motion.
   *
   * <h3>Convergence</h3>
   * A step has converged when, at an iterate that satisfies the constraints
   * (to $10^{-14}$ of the largest prescribed value), both
   * - the free residual $\|r\|_2 \le \max(\varepsilon_r F_{ref}, \varepsilon_a)$,
   *   with $F_{ref}$ the larger of $\|\lambda f_{ext}\|_2$ and the norm of
   *   the internal forces (reactions included) at the iterate, and
   *   $\varepsilon_a$ = Parameters::absolute_residual_tolerance;
   * - the update test: the size $\eta$ of the update that one more
   *   iteration would take is $\le \varepsilon_u \|u\|_2$. $\eta$ is the
   *   last update $\|\alpha\,\delta u\|_2$, except once the iteration
   *   contracts fast: after a full step ($\alpha = 1$) that kept the
   *   prescribed values, from the third iterate of a step on,
   *   $\eta = \theta\,\|\delta u\|_2$ with the contraction
   *   $\theta = \max(m_k/m_{k-1}, \|\delta u_{k-1}\|/\|\delta u_{k-2}\|)$
   *   of the last iteration ($m$ the free residual, with contact and
   *   $\phi$ together), used while $\theta < 1/2$. Newton converges
   *   quadratically there, so this linear estimate of the next update errs
   *   on the large side; it spares the solve that would only confirm a
   *   residual already at round-off (without it, every step ended with one
   *   more factorization whose update was $10^{-14}\|u\|$: 4-5 solves per
   *   step on Cook's membrane instead of 3-4, doc/benchmarks.md). The
   *   answer changes by at most that skipped update.
   *
   * An iterate whose last update changed $u$ only at round-off
   * ($\le 10^{-13}\|u\|_2$) counts as converged with a residual up to 100
   * times that bound: where the bodies' stiffnesses differ by $10^3$ the
   * floating-point residual of the discrete solution itself can lie just
   * above it (a stiff die on a soft slab: $1.3\cdot 10^{-10} F_{ref}$).
   *
   * If a step does not converge within Parameters::max_iterations
   * iterations, or meets an inverted cell that the line search cannot
   * avoid, the solution is reset to the last converged step (the earlier
   * steps and their history are kept: get_solution(), get_history()), and
   * an ExcMessage names the step, its load factor, the reason and the
   * residual history of the step.
   *
   * <h3>The first iterate of a step</h3>
   * With Parameters::extrapolate (the default) and two converged steps
   * before it, a step starts from $u_n + s\,(u_n - u_{n-1})$ (and the
   * multipliers alike), $s$ the ratio of the new increment of the load
   * factor to the last one (of the step numbers when the load factor stays,
   * as with set_constraints() and solve_step(n, 1.)), unless that state
   * lies outside the domain of the law; then from $u_n$. Along a smooth load path the
   * extrapolated state is off by $O(\Delta\lambda^2)$ instead of
   * $O(\Delta\lambda)$: Newton needs fewer iterations, and the active set of
   * contact, judged at the first iterate, flips less. If the step does not
   * converge from the extrapolated state, it is solved again from $u_n$
   * (StepRecord::restarted); only that second failure stops the run.
   *
   * <h3>Stabilization</h3>
   * At the start of every load step the stabilization is frozen at the last
   * converged state (FiniteStrainAssembler::freeze_stabilization()), so
   * the tangent is exact within the step (FiniteStrainOperator).
   *
   * <h3>Contact</h3>
   * With set_contact(), the node pairs of a FiniteStrainContact are
   * enforced by Lagrange multipliers $\lambda_j$ (nodal forces in the
   * current configuration): the residual becomes
   * $r(u) - \sum_j \lambda_j\,\partial g_j/\partial u$ and each Newton
   * iteration solves, by a semismooth Newton (primal-dual active set)
   * step,
   * @f[ \begin{pmatrix} K(u) + \sum_j \lambda_j \nabla^2 g_j & G_{\mathcal A}^T \\
   *                     G_{\mathcal A} & 0 \end{pmatrix}
   *     \begin{pmatrix} \delta u \\ \lambda^{new}_{\mathcal A} \end{pmatrix} =
   *     \begin{pmatrix} \lambda_{load} f_{ext} - f_{int}(u) \\ -g_{\mathcal A}(u) \end{pmatrix},
   *     \qquad \lambda^{new}_j = 0 \ (j \notin \mathcal A), @f]
   * with $G$ the rows $\partial g_j/\partial u$ and the active set
   * $\mathcal A = \{j : -\lambda_j/w_j - c\,g_j(u) > 0\}$ of the iterate
   * (gaps below $10^{-12}$ of the mesh's size count as closed, so that a
   * body held only by contact, touching with a gap of coordinate
   * round-off, starts supported)
   * (every constraint for tied contact), $w_j$ the pair's weight and $c$
   * FiniteStrainContact::complementarity_constant(). The line search then
   * acts on $(u, \lambda)$ together, on the norm of the free residual and
   * the complementarity residual
   * $\phi_j = \lambda_j - \min(0, \lambda_j + c\,w_j g_j)$ (for tied
   * contact $c\,w_j g_j$). A step has converged when, in addition to the
   * tests above, the active set did not change in the last iteration and
   * $\|\phi\|_2 \le \max(\varepsilon_r F_{ref}, \varepsilon_a)$.
   * The iteration records get the number of active constraints and
   * $\|\phi\|_2$.
   *
   * With Coulomb friction (FiniteStrainContact::is_frictional()), each
   * tangential constraint of an active pair is a row of the system too:
   * where the trial force $\lambda_t + c\,w\,s$ lies within
   * $\mu\max(0, -\lambda_n)$ the stick row $\partial s/\partial u\,\delta u
   * = -s$, else the slip row
   * $\lambda_t^{new} + \mu\sigma\lambda_n^{new} = 0$ with $\sigma$ the sign
   * of the trial force (a row of multipliers only; the system is then not
   * symmetric, which the direct solver does not mind). $\phi$ gets
   * $\lambda_t - \mathrm{proj}_{[-b, b]}(\lambda_t + c\,w\,s)$, and the
   * step has converged only when no pair changed between stick, slip and
   * open in the last iteration.
   */
  template <int dim>
  class FiniteStrainSolver
  {
  public:
    /// The controls of the iteration.
    struct Parameters
    {
      /// Number $N$ of equal load steps of run().
      unsigned int n_load_steps = 10;
      /// Largest number of Newton iterations (linear solves) per step.
      unsigned int max_iterations = 30;
      /// $\varepsilon_r$: the residual test, relative to $F_{ref}$.
      double residual_tolerance = 1e-10;
      /// $\varepsilon_u$: the update test (the estimated next update),
      /// relative to $\|u\|$; see the class documentation.
      double update_tolerance = 1e-10;
      /// $\varepsilon_a$: the absolute residual floor, for problems whose
      /// forces are all zero (a rigid motion); a negative value means
      /// $10^{-12} E_{min} L$ with the smallest
      /// ConstitutiveLaw::characteristic_stiffness() $E_{min}$ and the
      /// diameter $L$ of the mesh's bounding box.
      double absolute_residual_tolerance = -1;
      /// Whether to search along the Newton direction (else $\alpha = 1$
      /// always, except on inversion).
      bool line_search = true;
      /// Largest number of halvings of $\alpha$.
      unsigned int max_line_search_halvings = 10;
      /// Start each step from the linear extrapolation of the last two
      /// converged steps (displacements and contact multipliers), as
      /// commercial codes do by default, instead of the last converged
      /// state; see the class documentation.
      bool extrapolate = true;
      /// Whether the prescribed values of the constraints scale with the
      /// load factor (the default: the constraints hold the full load).
      /// false: the constraints hold the values of the step being solved
      /// (set_constraints() before each step, as FiniteSliding does for
      /// prescribed motions that do not follow the forces).
      bool scale_prescribed_motion = true;
      /// Whether a converged step checks the contact pairs whose nodes the
      /// displacement constraints fix (FiniteStrainConstraints::is_prescribed()):
      /// the prescribed motion must not make them penetrate (tied: move
      /// apart). FiniteSliding checks them itself after the last pass of
      /// the pairing, where the partners are opposite each other.
      bool check_fixed_pairs = true;
    };

    /// One Newton iteration: the state it starts from and its update.
    struct IterationRecord
    {
      /// Free residual norm $\|r(u)\|_2$ at the iterate.
      double residual_norm = 0;
      /// $\|r\|_2 / F_{ref}$ (0 if $F_{ref} = 0$).
      double relative_residual = 0;
      /// Norm $\|\alpha\,\delta u\|_2$ of the update taken from the iterate
      /// (0 on the last record of a converged step: no update).
      double update_norm = 0;
      /// The line-search step $\alpha$ (1: full Newton step).
      double step_length = 1;
      /// With contact: the number of active constraints at the iterate.
      unsigned int n_active = 0;
      /// With contact: the complementarity residual $\|\phi\|_2$ (force).
      double contact_residual = 0;
      /// With Coulomb friction: the number of slipping pairs at the iterate.
      unsigned int n_slip = 0;
    };

    /// One load step.
    struct StepRecord
    {
      /// The step number (1-based).
      unsigned int step = 0;
      /// Its load factor $\lambda$.
      double load_factor = 0;
      /// Whether it converged.
      bool converged = false;
      /// The iterations, one record per assembled iterate.
      std::vector<IterationRecord> iterations;
      /// Whether the step was solved with contact (set_contact()).
      bool with_contact = false;
      /// Whether the step started from the extrapolated state
      /// (Parameters::extrapolate).
      bool extrapolated = false;
      /// Whether an attempt from the extrapolated state failed first and
      /// the step was solved again from the last converged state (the
      /// iterations are those of the second attempt).
      bool restarted = false;
    };

    /**
     * Constructor: the assembler (held by reference, it must outlive the
     * solver; not const, since the solver freezes its stabilization), the
     * constraints of the full load (copied; closed, as for deal.II), and
     * the parameters. The solution starts at zero. Throws if the
     * constraints are not closed or the parameters are invalid (naming the
     * parameter).
     */
    FiniteStrainSolver(FiniteStrainAssembler<dim>              &assembler,
                       const dealii::AffineConstraints<double> &constraints,
                       const Parameters                        &parameters);

    /**
     * Enforce the constraints of @p contact (a FiniteStrainContact, or any
     * FiniteStrainConstraints; held by reference; it
     * must outlive the solver and be built on the assembler's DoF handler)
     * in the following steps; see the class documentation. Marks the pairs
     * that the displacement constraints fix
     * (FiniteStrainConstraints::mark_prescribed()) and rebuilds the matrix
     * for n_dofs() + FiniteStrainConstraints::n_constraints() unknowns. The
     * multipliers start at zero.
     */
    void
    set_contact(FiniteStrainConstraints &contact);

    /**
     * Replace the constraints by @p new_constraints (closed) from the next
     * solve_step() on, keeping the solution: for prescribed motions that do
     * not scale with the load factor (a rotation imposed step by step:
     * set the constraints of step $n$ and call solve_step(n, 1.)). The new
     * constraints must constrain the same DoFs through the same DoFs as
     * the old ones (only the inhomogeneities and the coefficients may
     * change), so that the matrix structure stays valid; throws naming the
     * first DoF that differs otherwise.
     */
    void
    set_constraints(const dealii::AffineConstraints<double> &new_constraints);

    /**
     * Start the next step from the state @p u (displacement) and
     * @p lambda (contact multipliers, n_constraints() of the contact set by
     * set_contact(); empty without contact), taken as converged at
     * @p load_factor and step number @p step; with @p previous_u, the
     * displacement of the step before (at @p previous_load_factor,
     * @p previous_step), the next step may start from the extrapolation
     * (Parameters::extrapolate; the multipliers are not extrapolated). For
     * a solver built on a new mesh (FiniteSliding: the state transferred
     * from the last mesh). The history is kept. Throws if a size does not
     * match or a value is not finite.
     */
    void
    set_state(const dealii::Vector<double> &u,
              const dealii::Vector<double> &lambda,
              const double                  load_factor,
              const unsigned int            step,
              const dealii::Vector<double> *previous_u           = nullptr,
              const double                  previous_load_factor = 0,
              const unsigned int            previous_step        = 0);

    /// Solve the load steps $\lambda = n/N$, $n = 1..N$
    /// (Parameters::n_load_steps) from the current solution. Throws as
    /// described in the class documentation when a step fails.
    void
    run();

    /// Solve one load step to the load factor @p load_factor from the
    /// current solution, recorded as step number @p step. The external
    /// load $f_{ext}$ of the convergence test is assembled again at the
    /// start of the step, so that loads whose functions the caller set to
    /// the time of the step (Function::set_time()) count at that time.
    /// Throws as run().
    void
    solve_step(const unsigned int step, const double load_factor);

    /// The displacement of the last converged step (zero before the first).
    const dealii::Vector<double> &
    get_solution() const
    {
      return solution;
    }

    /// The contact multipliers of the last converged step (one per
    /// FiniteStrainContact constraint; empty without contact).
    const dealii::Vector<double> &
    get_multipliers() const
    {
      return multipliers;
    }

    /// The load factor of the last converged step.
    double
    get_load_factor() const
    {
      return current_load_factor;
    }

    /// Every step attempted, the failed one last.
    const std::vector<StepRecord> &
    get_history() const
    {
      return history;
    }

    /// Print the history: one line per Newton iteration with the residual
    /// norm, the relative residual, the update norm and $\alpha$.
    void
    print_history(std::ostream &out) const;

    /// The history of one step as text (print_history()'s lines for it).
    static std::string
    step_history_text(const StepRecord &record);

  private:
    /// One attempt at a step: from the extrapolated state if @p extrapolate
    /// (and two steps have converged), else from the last converged one.
    void
    attempt_step(const unsigned int step, const double load_factor, const bool extrapolate);

    /// The state of one attempt at a step, handed between its stages
    /// (defined in the source file).
    struct NewtonStep;
    /// The stages of attempt_step(), in their order (see the source file).
    void
    start_attempt(NewtonStep &ns);
    void
    check_data_scale(NewtonStep &ns) const;
    void
    extrapolate_first_iterate(NewtonStep &ns);
    bool
    newton_iteration(NewtonStep &ns, const unsigned int it);
    void
    assemble_iterate(NewtonStep &ns, const unsigned int it);
    double
    contact_rows(NewtonStep &ns, unsigned int &n_active, unsigned int &n_slip);
    void
    newton_direction(NewtonStep &ns, IterationRecord &iteration, const unsigned int it);
    double
    line_search(NewtonStep &ns, IterationRecord &iteration, const double merit, const bool moves_prescribed);
    void
    check_fixed_pairs(NewtonStep &ns);
    void
    accept_step(NewtonStep &ns);
    /// The norm of the free part of a residual, and the contact part of the
    /// residual (returns the norm of the complementarity residual).
    double
    free_norm(NewtonStep &ns, const dealii::Vector<double> &residual) const;
    double
    contact_residual(NewtonStep &ns, const dealii::Vector<double> &u_at, const dealii::Vector<double> &lambda_at,
                     dealii::Vector<double> &residual) const;
    /// A failed step: its record goes to the history, and it throws.
    void
    fail_step(NewtonStep &ns, const std::string &reason);

    FiniteStrainAssembler<dim>       &assembler;
    dealii::AffineConstraints<double> constraints;
    /// The constraints with zero inhomogeneities: for the free residual.
    dealii::AffineConstraints<double> homogeneous_constraints;
    Parameters                        parameters;
    dealii::SparsityPattern           sparsity;
    dealii::SparseMatrix<double>      tangent;
    dealii::Vector<double>            solution;
    dealii::Vector<double>            f_ext;
    /// The contact constraints (set_contact()), or null.
    FiniteStrainConstraints          *contact = nullptr;
    dealii::Vector<double>            multipliers;
    /// The diameter of the mesh's bounding box.
    double                            length_scale = 0;
    double                            current_load_factor = 0;
    /// The converged step before the last one (for the extrapolation).
    dealii::Vector<double>            previous_solution, previous_multipliers;
    double                            previous_load_factor = 0;
    unsigned int                      current_step = 0, previous_step = 0;
    unsigned int                      n_converged  = 0;
    double                            absolute_tolerance  = 0;
    std::vector<StepRecord>           history;
  };
} // namespace dealvem

#endif
