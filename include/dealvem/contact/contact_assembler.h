// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_contact_assembler_h
#define dealvem_contact_contact_assembler_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <dealvem/contact/contact_rows.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <string>
#include <vector>

namespace dealvem
{
  template <int dim>
  class MaterialLibrary;
} // namespace dealvem

namespace dealvem
{
  /**
   * Options of node-to-node contact.
   */
  struct ContactSettings
  {
    /// Normal contact: tied (bilateral, $g = 0$ at every pair) or
    /// unilateral ($g\ge 0$, $\lambda\le 0$, $g\lambda = 0$ by an active set).
    enum class Normal
    {
      tied,
      unilateral
    };
    /// Tangential behaviour: frictionless, stick by a penalty, or stick by
    /// Lagrange multipliers (exactly tied); Coulomb friction with exact
    /// stick by multipliers (coulomb) or regularised by the penalty
    /// (coulomb_penalty), solved by FrictionSolver.
    enum class Tangential
    {
      frictionless,
      penalty,
      multipliers,
      coulomb,
      coulomb_penalty
    };
    /// The normal contact model ('Contact/Normal').
    Normal     normal     = Normal::unilateral;
    /// The tangential model ('Contact/Tangential').
    Tangential tangential = Tangential::penalty;
    /**
     * Tangential penalty $\varepsilon_t$ (stiffness per unit interface
     * length and per unit slip, units of $E/h$). Zero selects the default
     * rule $\varepsilon_t = 10^3\,E_{min}/h$, with $E_{min}$ the smallest
     * Young's modulus of the two bodies and $h$ the smallest interface
     * sub-edge length: a thousand times the stiffness of one layer of
     * elements, so the slip is about $10^{-3}$ of the elastic shear
     * deformation of the adjacent cells, while the condition number grows
     * by only that factor.
     */
    double penalty = 0;
    /// Factor of the default penalty rule.
    double penalty_factor = 1e3;
    /// Active set: maximum number of iterations.
    unsigned int max_active_set_iterations = 50;
    /// Active set: correct the plain update where it crawls (see
    /// ActiveSetSolver); false gives the plain primal-dual active set.
    bool accelerate_active_set = true;
    /// Unilateral contact without Coulomb friction: when the active-set
    /// iteration gives up (a cycle, the iteration limit, a set that holds
    /// no equilibrium), solve again with the globally convergent
    /// PrimalActiveSetSolver, which either converges or proves that there
    /// is no equilibrium (ActiveSetSolver). False: the iteration's failure
    /// is the answer.
    bool globalize = true;
    /// Coulomb friction coefficient of every interface without its own.
    double friction_coefficient = 0;
    /// Friction coefficient per interface (index ContactNodePair::interface);
    /// entries beyond its size, and negative entries, use
    /// friction_coefficient.
    std::vector<double> friction_coefficients;

    /// Whether the tangential model is Coulomb friction.
    bool
    is_coulomb() const
    {
      return tangential == Tangential::coulomb || tangential == Tangential::coulomb_penalty;
    }

    /// The friction coefficient of interface @p interface.
    double
    friction_coefficient_of(const unsigned int interface) const
    {
      return (interface < friction_coefficients.size() && friction_coefficients[interface] >= 0) ?
               friction_coefficients[interface] :
               friction_coefficient;
    }

    /// The model named @p s ("tied", "unilateral"); throws otherwise.
    static Normal
    parse_normal(const std::string &s);
    /// The model named @p s ("frictionless", "penalty", "multipliers",
    /// "coulomb", "coulomb penalty"); throws otherwise.
    static Tangential
    parse_tangential(const std::string &s);

    /// The parameter names of the models (inverse of the parse functions).
    static std::string
    normal_name(const Normal n);
    /// The parameter name of @p t (inverse of parse_tangential()).
    static std::string
    tangential_name(const Tangential t);
  };



  /**
   * The two constants a contact problem derives from its bodies and its
   * interfaces, by one rule that ContactProblem and the tutorials share:
   * the scale $E_{min}/h_{min}$, with $E_{min}$ the smallest Young's
   * modulus of the bodies in contact (the smallest
   * ConstitutiveLaw::characteristic_stiffness() of their laws, which is
   * $E$ for ElasticMaterial) and $h_{min}$ the shortest paired
   * sub-edge of the interfaces after node insertion (the stiffness of the
   * stiffest single connection, up to a constant).
   * - complementarity_constant(): $c = E_{min}/h_{min}$ in the
   *   complementarity functions of the active-set and semismooth Newton
   *   methods, $\lambda - \max(0,\lambda - c\,g)$: it puts gaps and
   *   multipliers (nodal forces) on one scale.
   * - penalty(): the stick penalty per unit length, ContactSettings::penalty
   *   when it is set (> 0), otherwise
   *   ContactSettings::penalty_factor $\cdot E_{min}/h_{min}$.
   */
  struct ContactScales
  {
    /// Throws unless @p youngs_moduli is non-empty and positive and some
    /// interface has a paired sub-edge.
    ContactScales(const std::vector<double>                   &youngs_moduli,
                  const std::vector<NodeInsertion::Interface> &interfaces);

    /// The same with $E_{min}$ the smallest characteristic stiffness of
    /// the laws of @p laws (MaterialLibrary::min_characteristic_stiffness()).
    ContactScales(const MaterialLibrary<2>                    &laws,
                  const std::vector<NodeInsertion::Interface> &interfaces);

    /// The smallest Young's modulus (characteristic stiffness) of the bodies.
    double E_min = 0;
    /// The shortest paired sub-edge of the interfaces.
    double h_min = 0;

    /// $E_{min}/h_{min}$, the scale of the constant $c$ of the active-set
    /// update (units of a stiffness per length).
    double
    complementarity_constant() const
    {
      return E_min / h_min;
    }

    /// The stick penalty: ContactSettings::penalty if positive, else
    /// ContactSettings::penalty_factor $E_{min}/h_{min}$.
    double
    penalty(const ContactSettings &settings) const
    {
      return settings.penalty > 0 ? settings.penalty : settings.penalty_factor * E_min / h_min;
    }

    /**
     * The range of a stick penalty, relative to $E_{min}/h_{min}$. Below
     * min_penalty_factor the springs hardly hold the stick direction: where
     * they are the only tangential support, a body moves by about
     * 1/min_penalty_factor times its elastic deformation, and the rigid
     * motion that the springs barely hold turns the system into a nearly
     * singular one (the solvers lose about 3 digits per factor 1000 of
     * stiffness contrast). Above max_penalty_factor the condition number,
     * which grows with the factor, leaves too few digits for the pressures.
     */
    static constexpr double min_penalty_factor = 1e-6;
    static constexpr double max_penalty_factor = 1e8; ///< see min_penalty_factor

    /**
     * Throw unless the stick penalty that penalty() gives for @p settings
     * lies in [min_penalty_factor, max_penalty_factor] $\cdot E_{min}/h_{min}$.
     * The message names @p penalty_parameter (when the penalty is given
     * explicitly, ContactSettings::penalty > 0) or @p factor_parameter
     * (when the default rule applies), the value, the bounds and the two
     * scales. Only meaningful for the penalty models of the tangential
     * behaviour (penalty, coulomb_penalty).
     */
    void
    check_penalty(const ContactSettings &settings,
                  const std::string     &penalty_parameter,
                  const std::string     &factor_parameter) const;
  };



  /**
   * State of a contact node pair under Coulomb friction: open (no contact
   * force), sticking (no incremental slip), or slipping in the direction
   * $+t$ or $-t$ of the slave node relative to the master node (the
   * friction force on the slave node then points the other way).
   */
  enum class PairState : unsigned char
  {
    open,
    stick,
    slip_positive,
    slip_negative
  };



  /**
   * Builds the contact blocks of the saddle-point system
   * @f[ \begin{pmatrix} K + K_t & C^T \\ C & 0 \end{pmatrix}
   *     \begin{pmatrix} u \\ \lambda \end{pmatrix} =
   *     \begin{pmatrix} f \\ -g_0 \end{pmatrix} @f]
   * from node pairs: one multiplier (row of $C$) per normal constraint,
   * $C_i u = (u_B - u_A)\cdot n_i$, and, with tangential multipliers, one
   * per tangential constraint $(u_B - u_A)\cdot t_i$. The tangential penalty
   * adds $K_t = \sum_i \varepsilon_t w_i\, c_i c_i^T$ with
   * $c_i u = (u_B - u_A)\cdot t_i$ and $w_i$ the tributary weight.
   *
   * The system has n_dofs() + n_multipliers() unknowns: multiplier j is
   * unknown n_dofs() + j (rows() gives the layout, a ContactRows).
   * Multipliers of inactive normal pairs get the equation $\lambda_j = 0$
   * (unit diagonal), so the sparsity pattern does not change during the
   * active-set iteration.
   *
   * A multiplier is a nodal force: $\lambda_i < 0$ is compression, and the
   * contact pressure at the node is $p_i = -\lambda_i / w_i$.
   *
   * <b>Redundant constraints.</b> A contact constraint whose displacement
   * DoFs are all fixed by the displacement constraints (Dirichlet, roller,
   * point constraints), e.g. the tangential constraint of a pair whose two
   * nodes both sit on a roller $u_x = 0$, becomes a zero row of $C$ after
   * condensation and would make the system singular. assemble() treats
   * such a row as AffineConstraints treats a constraint on a constrained
   * DoF: if the value that the displacement constraints impose on
   * $C_i u$ agrees with the value contact requires ($-g_0$ for a tied or
   * active normal constraint, 0 for a tangential one; for unilateral
   * contact any value that does not force a penetration), the multiplier
   * gets the equation $\lambda = 0$ and the constraint is listed in
   * get_dropped_constraints(); otherwise assemble() throws an error naming
   * the pair and the two values.
   */
  template <int dim>
  class ContactAssembler
  {
  public:
    /// A contact constraint that the displacement constraints already fix.
    struct DroppedConstraint
    {
      unsigned int     pair;       ///< index into get_pairs()
      dealii::Point<2> location;   ///< slave location of the pair
      bool             tangential; ///< false: the normal constraint
      /// Value of $(u_B - u_A)\cdot n$ (or $\cdot t$) imposed by the
      /// displacement constraints.
      double           imposed_value;
    };

    /// The contact rows of @p pairs on the DoFs of @p dof_handler, with
    /// the models of @p settings and the stick penalty @p penalty (used by
    /// the penalty models only).
    ContactAssembler(const VEMDoFHandler<dim>            &dof_handler,
                     const std::vector<ContactNodePair> &pairs,
                     const ContactSettings              &settings,
                     const double                        penalty);

    /// Number of multipliers (rows of C).
    unsigned int
    n_multipliers() const
    {
      return n_normal + n_tangential;
    }

    /// Number of node pairs. Multiplier of the normal constraint of pair i
    /// is n_dofs + i; with tangential multipliers, that of the tangential
    /// constraint of pair i is n_dofs + n_pairs + i (rows()).
    unsigned int
    n_pairs() const
    {
      return pairs.size();
    }

    /// The multiplier rows of the system: their layout, the pair and kind of
    /// each row, and the data of the pairs (valid while this assembler
    /// lives). Tangential rows with `Tangential = multipliers` and `coulomb`.
    ContactRows
    rows() const
    {
      return ContactRows(dof_handler.n_dofs(), pairs, n_tangential > 0);
    }

    /// The four displacement DoFs (u_A x, u_A y, u_B x, u_B y) of pair i.
    std::array<dealii::types::global_dof_index, 4>
    pair_dofs(const unsigned int i) const;

    /**
     * The rows of the system matrix that assemble() and assemble_friction()
     * may write with these @p constraints, ascending: the displacement rows
     * of the pairs' DoFs, of the DoFs their constraints refer to, and every
     * multiplier row. The other rows keep the values of the elasticity
     * part, which lets a solver assemble the contact blocks into the system
     * matrix itself and restore it afterwards (ActiveSetSolver).
     */
    std::vector<unsigned int>
    rows_written(const dealii::AffineConstraints<double> &constraints) const;

    /// Add the couplings of the contact blocks to a pattern of size
    /// n_dofs + n_multipliers.
    void
    add_sparsity(dealii::DynamicSparsityPattern &dsp) const;

    /**
     * With `Tangential = penalty` (and `coulomb penalty`, where @p active
     * marks the sticking pairs): the directions of the stick springs that
     * assemble() (assemble_friction()) adds for those pairs, the rows c_t = (u_B - u_A).t of
     * the pairs over their four DoFs with the displacement constraints
     * condensed in (homogeneous part; a row that the constraints fix
     * entirely is left out). Empty for the other tangential models. The
     * condensed contact solver uses them to build a preconditioner that does
     * not degrade with the penalty (SaddlePointSolver::set_stick_directions()).
     */
    std::vector<std::vector<std::pair<unsigned int, double>>>
    stick_penalty_rows(const dealii::AffineConstraints<double> &constraints,
                       const std::vector<bool>                 &active) const;

    /**
     * Add the contact blocks to the system: @p active[i] says whether the
     * normal constraint of pair i is enforced. The displacement constraints
     * (Dirichlet data) are applied through @p constraints.
     */
    void
    assemble(const dealii::AffineConstraints<double> &constraints,
             const std::vector<bool>                 &active,
             dealii::SparseMatrix<double>            &matrix,
             dealii::Vector<double>                  &rhs) const;

    /**
     * The same with the tangential stick (multipliers or penalty springs)
     * of pair i enforced where @p tangential_active[i] holds, whether or
     * not its normal constraint is: the convex model of stick contact that
     * PrimalActiveSetSolver solves (the associated limit of Coulomb
     * friction for an infinite coefficient: no relative tangential motion
     * at any pair). With @p tangential_active equal to @p active this is
     * assemble(). With @p reference, pair i sticks at the relative
     * tangential displacement (*reference)[i] instead of 0 (where it
     * closed: PrimalActiveSetSolver::solve_stick_on_closed()).
     */
    void
    assemble(const dealii::AffineConstraints<double> &constraints,
             const std::vector<bool>                 &active,
             const std::vector<bool>                 &tangential_active,
             dealii::SparseMatrix<double>            &matrix,
             dealii::Vector<double>                  &rhs,
             const std::vector<double>               *reference = nullptr) const;

    /// The DoF handler of the constructor.
    const VEMDoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /**
     * Add the contact blocks of Coulomb friction (ContactSettings::coulomb
     * or coulomb_penalty) for the pair states @p state. With the normal
     * multiplier $\lambda_{n,i}$ and the tangential nodal force
     * $\lambda_{t,i}$ (the slave node receives $-\lambda_{t,i} t_i$):
     * - open: $\lambda_{n,i} = 0$, $\lambda_{t,i} = 0$;
     * - stick: $g_i = 0$ and, with multipliers,
     *   $(u_B - u_A)\cdot t_i = r_i$ (the relative tangential displacement
     *   $r_i$ of the last converged load step: no incremental slip), or with
     *   the penalty $\lambda_{t,i} = \varepsilon_t w_i ((u_B - u_A)\cdot t_i - r_i)$
     *   ($r_i$ the plastic slip);
     * - slip in the direction $\sigma_i = \pm 1$: $g_i = 0$ and
     *   $\lambda_{t,i} + \mu\sigma_i\lambda_{n,i} = 0$, i.e. the friction
     *   force $\mu|\lambda_{n,i}|$ against the slip. With multipliers this
     *   is the row of $\lambda_{t,i}$; with the penalty, $\lambda_{t,i}$ is
     *   replaced by $-\mu\sigma_i\lambda_{n,i}$ in the displacement rows
     *   (the matrix is no longer symmetric in both cases).
     * @p reference holds the $r_i$. Every friction coefficient $\mu$ is
     * multiplied by @p friction_factor (1 for the model as set; the
     * continuation of FrictionSolver solves with larger factors on its way
     * to 1).
     */
    void
    assemble_friction(const dealii::AffineConstraints<double> &constraints,
                      const std::vector<PairState>            &state,
                      const std::vector<double>               &reference,
                      dealii::SparseMatrix<double>            &matrix,
                      dealii::Vector<double>                  &rhs,
                      const double                             friction_factor = 1.) const;

    /// The friction coefficient of pair i.
    double
    friction_coefficient(const unsigned int i) const
    {
      return settings.friction_coefficient_of(pairs[i].interface);
    }

    /// Gap $g_i = (u_B - u_A)\cdot n_i + g_{0,i}$ of each pair.
    std::vector<double>
    gaps(const dealii::Vector<double> &solution) const;

    /// Tangential slip $(u_B - u_A)\cdot t_i$ of each pair.
    std::vector<double>
    slips(const dealii::Vector<double> &solution) const;

    /// Tangential nodal force of each pair (penalty force or tangential
    /// multiplier), positive along $t_i$ on the slave side.
    std::vector<double>
    tangential_forces(const dealii::Vector<double> &solution) const;

    /// The stick penalty of the constructor.
    double
    get_penalty() const
    {
      return penalty;
    }

    /// The pairs of the constructor.
    const std::vector<ContactNodePair> &
    get_pairs() const
    {
      return pairs;
    }

    /**
     * The enforced contact constraints of the last call of assemble() that
     * were redundant with the displacement constraints and replaced by
     * $\lambda = 0$ (see the class documentation), in the order of the
     * pairs, normal before tangential.
     */
    const std::vector<DroppedConstraint> &
    get_dropped_constraints() const
    {
      return dropped;
    }

  private:
    /**
     * If the row @p c (coefficients of the four DoFs of pair @p i) only
     * involves DoFs that @p constraints fix, return true and the value the
     * constraints impose on it in @p value.
     */
    bool
    is_fixed_by_constraints(const dealii::AffineConstraints<double> &constraints,
                            const unsigned int                       i,
                            const double                             c[4],
                            double                                  &value) const;

    /**
     * The rule for redundant constraints (see the class documentation),
     * used by assemble() and assemble_friction(): if the constraint row
     * @p c of pair @p i (the normal one, or the tangential stick one when
     * @p tangential) involves only DoFs that @p constraints fix, check
     * that the value they impose agrees with @p required (with
     * @p unilateral, a normal value may also exceed it: an open gap), list
     * the constraint in `dropped` and return true; throw an error naming
     * the pair, the constraint and both values if they disagree. Return
     * false if the row is not fixed. Tolerance: 1e-12 relative to the
     * values compared, at least 1e-12 times the tributary length of the
     * pair (the round-off of the initial gap).
     */
    bool
    drop_if_fixed(const dealii::AffineConstraints<double> &constraints,
                  const unsigned int                       i,
                  const double                             c[4],
                  const bool                               tangential,
                  const double                             required,
                  const bool                               unilateral) const;

    const VEMDoFHandler<dim>     &dof_handler;
    std::vector<ContactNodePair>  pairs;
    ContactSettings               settings;
    double                        penalty;
    unsigned int                  n_normal, n_tangential;
    /// Filled by assemble() (which is otherwise const).
    mutable std::vector<DroppedConstraint> dropped;
  };
} // namespace dealvem

#endif
