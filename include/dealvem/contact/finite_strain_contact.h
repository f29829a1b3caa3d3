// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_finite_strain_contact_h
#define dealvem_contact_finite_strain_contact_h

#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/contact_rows.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/elasticity/finite_strain_constraints.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <array>
#include <vector>

namespace dealvem
{
  /**
   * Node-to-node contact at finite strain with small sliding: the pairs of
   * node insertion (NodeInsertion::insert(), made in the reference
   * configuration) are kept, and the gaps and normals are evaluated in the
   * current configuration $x = X + u$. FiniteStrainSolver enforces the
   * constraints with Lagrange multipliers (set_contact()).
   *
   * <h3>The constraints of a pair</h3>
   * With the pair's nodes A (master) and B (slave) and
   * $a = x_B - x_A$, the current normal is the reference normal $n_0$ of
   * the pair (ContactNodePair::normal) turned by the angle $\theta$ by
   * which the interface has turned at the pair:
   * @f[ n(u) = R(\theta)\,n_0,\qquad t(u) = R(\theta)\,t_0 = J n(u), @f]
   * with $R(\theta)$ the rotation by $\theta$ and $J = R(\pi/2)$. The angle
   * is measured on a chord of the side that gives the normal
   * (NodeInsertion::Interface::normal_side): with $d_0 = X_+ - X_-$ and
   * $d = x_+ - x_-$ the chord between the pair's neighbours $\pm$ along
   * the interface (the pair's own node at the end of a chain; for a
   * midpoint pair, the two ends of its sub-edge; a chord shorter than
   * 1e-2 of the interface's median sub-edge is lengthened by a pair along
   * the chain at each end until it is not, since the derivative of the
   * angle is $1/|d|$ and FiniteSliding's node insertion makes sub-edges
   * down to 1e-9 of an edge),
   * $\theta_s = \mathrm{atan2}(d_0\times d,\ d_0\cdot d)$; the bisector
   * normal turns by the mean of the two sides' angles. At $u = 0$ every
   * normal is the reference normal, so the small-strain limit is the
   * linear node-to-node contact of ContactAssembler.
   * - Unilateral (ContactSettings::Normal::unilateral): one constraint per
   *   pair, the gap $g = a\cdot n(u) \ge 0$, with the multiplier
   *   $\lambda \le 0$ and $g\lambda = 0$; frictionless.
   * - Tied: two constraints per pair, $a\cdot n(u) = g_0$ and
   *   $a\cdot t(u) = (X_B - X_A)\cdot t_0$: the relative position of the
   *   two nodes, seen in the frame that turns with the interface, does not
   *   change (for a closed gap, $u_B = u_A$).
   *
   * A multiplier is the contact force on the pair in the current
   * configuration (per unit thickness): the slave node receives
   * $-\lambda\,\partial g/\partial x_B$; the Cauchy pressure is
   * $p = -\lambda/w(u)$ with the current tributary weight $w(u)$
   * (current_weights()).
   *
   * <h3>Linearization</h3>
   * linearize() returns $g$, its gradient and its Hessian with respect to
   * the displacement DoFs of the nodes involved (A, B and the chord ends).
   * With $e = n$ or $t$, $w_s = J d_s/|d_s|^2 = \partial\theta_s/\partial d_s$
   * and the weight $c_s$ of side $s$ in $\theta$ (1, or 1/2 for the
   * bisector):
   * @f[ \frac{\partial g}{\partial a} = e,\quad
   *     \frac{\partial g}{\partial d_s} = c_s\,(a\cdot Je)\,w_s, @f]
   * @f[ \frac{\partial^2 g}{\partial a\,\partial d_s} = c_s\, Je\otimes w_s,\quad
   *     \frac{\partial^2 g}{\partial d_s\,\partial d_r} =
   *       -c_s c_r\,(a\cdot e)\, w_s\otimes w_r
   *       + \delta_{sr} c_s\,(a\cdot Je)\Big(\frac{J}{|d_s|^2}
   *       - \frac{2\,w_s\otimes d_s}{|d_s|^2}\Big), @f]
   * and $\partial^2 g/\partial a^2 = 0$. The Newton matrix of
   * FiniteStrainSolver gets $\sum_j \lambda_j\,\partial^2 g_j/\partial u^2$
   * in its displacement block (the geometric stiffness of the turning
   * normals) and the gradients as the constraint rows: the linearization is
   * exact, so Newton converges quadratically with contact too.
   *
   * <h3>Pairs left out</h3>
   * - Pairs that close a triangle where three bodies meet
   *   (ContactNodePair::junction; NodeInsertion::mark_junctions()): their
   *   constraints repeat those of the two other pairs.
   * - Pairs whose two nodes are fully fixed by the displacement constraints
   *   (mark_fixed_pairs()): their gap is prescribed, a multiplier would make
   *   the system singular. FiniteStrainSolver checks after every step that
   *   the prescribed motion does not make such a pair penetrate (unilateral)
   *   or move apart (tied), and throws naming the pair otherwise.
   *
   * The model is small sliding: the pairs do not change. It is exact while
   * the partners stay opposite each other (homogeneous deformations, a flat
   * interface of which one side stays flat) and an approximation of the
   * order of the relative tangential motion times the curvature otherwise.
   * For finite sliding, FiniteSliding makes the pairs again in the current
   * configuration at every load step and builds this class with that
   * configuration as its base (Options::base).
   *
   * <h3>Coulomb friction</h3>
   * With unilateral contact and Options::friction_coefficient $\mu > 0$,
   * every pair gets a second, tangential constraint (constraint
   * n_pairs() + i, as for tied contact) whose value is the slip since the
   * base configuration,
   * @f[ s(u) = a\cdot t(u) - a_o\cdot t(u_o), @f]
   * with $a_o$ the vector between the pair's nodes in the configuration
   * $u_o$ where the slip starts (Options::slip_origin, by default the base
   * configuration, where $t(u_b) = t_0$); a pair whose slave point was off
   * the master side at $u_o$ (its distance to the master side's curve
   * there, on the side of the normal, above $10^{-2}$ of the nearest
   * sub-edge plus 1.5 times its chord deviation where the master side
   * curves: a point on a curved side lies off the chords of the other
   * side's sub-edges by up to $l^2\kappa/8$) has no history there: its slip
   * is measured from Options::contact_origin, the configuration where the
   * contact is taken to begin, or is $a\cdot t(u)$ itself without one (it
   * sticks, once closed, with its nodes opposite each other). Its multiplier $\lambda_t$ is the friction force
   * (the slave node receives $-\lambda_t\,\partial s/\partial x_B$);
   * FiniteStrainSolver enforces the Coulomb law
   * $\lambda_t = \mathrm{proj}_{[-\mu\lambda_n^-,\ \mu\lambda_n^-]}
   * (\lambda_t + c\,w\,s)$, $\lambda_n^- = \max(0, -\lambda_n)$, by a
   * semismooth Newton method: stick ($s = 0$ over the step) or slip
   * ($\lambda_t = \mu\lambda_n^-\,\mathrm{sign}(\lambda_t + c\,w\,s)$).
   * The law is the incremental (backward Euler) Coulomb law of a load
   * step: its whole history is the base configuration, where the step
   * started.
   */
  class FiniteStrainContact : public FiniteStrainConstraints
  {
  public:
    /**
     * Constructor: the pairs of all @p interfaces (in order) on the DoFs of
     * @p dof_handler (distributed on the mesh after node insertion), the
     * normal model @p normal (tied or unilateral; unilateral contact is
     * frictionless), and the complementarity constant @p c
     * (ContactScales::complementarity_constant(), a stiffness per length):
     * a pair is active where $-\lambda/w - c\,g > 0$. Throws unless
     * $c > 0$, some pair exists, and every midpoint pair has a degree-2
     * DoF handler.
     */
    FiniteStrainContact(const VEMDoFHandler<2>                      &dof_handler,
                        const std::vector<NodeInsertion::Interface> &interfaces,
                        const ContactSettings::Normal                normal,
                        const double                                 c);

    /// What the constructor takes beyond the normal model.
    struct Options
    {
      /// Coulomb friction coefficient $\mu \ge 0$ of unilateral contact
      /// (0: frictionless), for every interface without its own entry.
      double friction_coefficient = 0;
      /// Friction coefficient per interface (in the order of the
      /// constructor's interfaces; negative or missing entries use
      /// friction_coefficient).
      std::vector<double> friction_coefficients;
      /// The base configuration $X + u_b$ in which the pairs were made and
      /// their normals given (ContactNodePair::normal): the reference of
      /// the turn angle, of the tied offsets and of the slip. Null: $u_b = 0$
      /// (the pairs of node insertion in the reference configuration). The
      /// vector is read by the constructor only.
      const dealii::Vector<double> *base = nullptr;
      /// The configuration $X + u_o$ from which the slip of Coulomb friction
      /// is measured (where the load step started; FiniteSliding pairs the
      /// nodes at the end of the step and measures the slip from its
      /// start). Null: the base. Read by the constructor only.
      const dealii::Vector<double> *slip_origin = nullptr;
      /// For the pairs that were open at the slip origin (new contacts):
      /// the configuration from which their slip is measured instead (the
      /// point where they are taken to have touched; FiniteSliding: where
      /// the first pass of the step made its pairs). Null: $a\cdot t$ itself
      /// (they stick with their nodes opposite each other).
      const dealii::Vector<double> *contact_origin = nullptr;
    };

    /**
     * Constructor as above with @p options: Coulomb friction and the base
     * configuration. Throws if a friction coefficient is negative or not
     * finite, or positive with tied contact, or if the base vector does not
     * have n_dofs() entries.
     */
    FiniteStrainContact(const VEMDoFHandler<2>                      &dof_handler,
                        const std::vector<NodeInsertion::Interface> &interfaces,
                        const ContactSettings::Normal                normal,
                        const double                                 c,
                        const Options                               &options);

    /// The normal model.
    ContactSettings::Normal
    get_model() const
    {
      return model;
    }

    /// Whether a constraint is an equation (tied) or an inequality.
    bool
    is_bilateral() const
    {
      return model == ContactSettings::Normal::tied;
    }

    /// The complementarity constant given to the constructor.
    double
    complementarity_constant() const override
    {
      return c;
    }

    /// The node pairs, of all interfaces in order.
    const std::vector<ContactNodePair> &
    get_pairs() const
    {
      return pairs;
    }

    /// Number of node pairs.
    unsigned int
    n_pairs() const
    {
      return pairs.size();
    }

    /// Whether unilateral contact has Coulomb friction (some interface
    /// with $\mu > 0$): then every pair has a tangential constraint.
    bool
    is_frictional() const
    {
      return frictional;
    }

    /// The friction coefficient of pair @p i (0 without friction).
    double
    friction_coefficient(const unsigned int i) const
    {
      return mu[i];
    }

    /// Number of constraints (multipliers): one per pair (frictionless
    /// unilateral), two per pair (tied, or Coulomb friction: constraint i
    /// is the normal one of pair i, constraint n_pairs() + i the tangential
    /// one).
    unsigned int
    n_constraints() const override
    {
      return (is_bilateral() || frictional ? 2 : 1) * pairs.size();
    }

    /**
     * The multiplier rows of the constraints in the system of
     * FiniteStrainSolver (n_dofs() + n_constraints() unknowns): constraint j
     * is unknown rows().row(j); the normal constraint of pair i is
     * ContactRows::normal_row(i), the tangential one (tied contact, Coulomb
     * friction) ContactRows::tangential_row(i). Valid while this object
     * lives.
     */
    ContactRows
    rows() const;

    /// The pair of constraint @p j.
    unsigned int
    pair_of(const unsigned int j) const
    {
      return j % pairs.size();
    }

    /// Whether constraint @p j is a tangential one (tied contact or
    /// Coulomb friction).
    bool
    is_tangential(const unsigned int j) const
    {
      return j >= pairs.size();
    }

    /**
     * Mark the pairs whose two nodes are fully fixed by @p constraints (all
     * four displacement DoFs constrained): their constraints are left out
     * (is_left_out()). Called by FiniteStrainSolver::set_contact().
     */
    void
    mark_fixed_pairs(const dealii::AffineConstraints<double> &constraints);

    /// Whether constraint @p j is left out: a junction pair or a pair fixed
    /// by the displacement constraints (see the class documentation).
    bool
    is_left_out(const unsigned int j) const override
    {
      const unsigned int i = pair_of(j);
      return pairs[i].junction || fixed[i];
    }

    /// Whether pair @p i is fully fixed by the displacement constraints
    /// (mark_fixed_pairs()).
    bool
    is_fixed(const unsigned int i) const
    {
      return fixed[i];
    }

    /// Whether pair @p i began its contact after the slip origin
    /// (Options::slip_origin): its slave point was off the master side
    /// there, so its slip counts from Options::contact_origin. False
    /// without a slip origin.
    bool
    is_new_contact(const unsigned int i) const
    {
      return new_contact[i];
    }

    /// Whether pair @p i is left out (a junction pair or fixed).
    bool
    is_pair_left_out(const unsigned int i) const
    {
      return pairs[i].junction || fixed[i];
    }

    /// @name The interface of FiniteStrainSolver (FiniteStrainConstraints)
    /// @{
    Kind
    kind(const unsigned int j) const override
    {
      if (is_bilateral())
        return Kind::equality;
      return is_tangential(j) ? Kind::friction : Kind::unilateral;
    }

    unsigned int
    normal_of(const unsigned int j) const override
    {
      return pair_of(j);
    }

    double
    friction_coefficient_of(const unsigned int j) const override
    {
      return mu[pair_of(j)];
    }

    /// The pair's tributary weight (ContactNodePair::weight).
    double
    weight(const unsigned int j) const override
    {
      return pairs[pair_of(j)].weight;
    }

    /// Calls mark_fixed_pairs().
    void
    mark_prescribed(const dealii::AffineConstraints<double> &constraints) override
    {
      mark_fixed_pairs(constraints);
    }

    /// Whether the pair of constraint @p j is fixed (and not a junction).
    bool
    is_prescribed(const unsigned int j) const override
    {
      return fixed[pair_of(j)] && !pairs[pair_of(j)].junction;
    }

    /// "the contact pair at (x, y) of interface i" (the slave location).
    std::string
    describe(const unsigned int j) const override;
    /// @}

    /// The value of constraint @p j at the displacement @p u (n_dofs()
    /// entries).
    double
    value(const unsigned int j, const dealii::Vector<double> &u) const override;

    /// Value, gradient and Hessian of constraint @p j at @p u; the Hessian
    /// only if @p with_hessian.
    void
    linearize(const unsigned int            j,
              const dealii::Vector<double> &u,
              Linearization                &result,
              const bool                    with_hessian = true) const override;

    /**
     * Add the couplings of the constraints to @p dsp, of size n_dofs() +
     * n_constraints() (constraint j is unknown n_dofs() + j), with the
     * displacement constraints @p constraints condensed as
     * VEMDoFHandler::make_sparsity_pattern() does: the constraint rows and
     * columns, the Hessian blocks among the DoFs of a constraint, and the
     * diagonal of every multiplier; with friction also the coupling of
     * each tangential multiplier to its pair's normal one (the slip
     * equation).
     */
    void
    add_sparsity(dealii::DynamicSparsityPattern          &dsp,
                 const dealii::AffineConstraints<double> &constraints) const override;

    /// The tributary weight of every pair in the current configuration: the
    /// weights of ContactNodePair::weight with the slave sub-edge lengths
    /// measured between the current positions of its nodes.
    std::vector<double>
    current_weights(const dealii::Vector<double> &u) const;

    /// The current position $x = X + u$ of the master and the slave node of
    /// pair @p i.
    std::array<dealii::Point<2>, 2>
    current_positions(const unsigned int i, const dealii::Vector<double> &u) const;

    /// The current normal $n(u)$ of pair @p i.
    dealii::Tensor<1, 2>
    current_normal(const unsigned int i, const dealii::Vector<double> &u) const;

  private:
    /// The chord that measures the turn of one side at a pair.
    struct Chord
    {
      unsigned int         minus = 0, plus = 0; ///< node indices of its ends
      dealii::Tensor<1, 2> reference;           ///< X_+ - X_-
      double               weight = 0;          ///< c_s
    };
    /// What a pair needs: its two nodes, its chords, its reference frame.
    struct PairData
    {
      unsigned int         master_node = 0, slave_node = 0;
      std::vector<Chord>   chords;
      dealii::Tensor<1, 2> n0, t0;
      double               tied_normal = 0, tied_tangential = 0; ///< (x_B - x_A).n0, .t0 at the base
      double               slip_origin = 0; ///< a.t at the origin of the slip (Coulomb)
    };

    /// What the constructor's steps share about the pairs (defined in the
    /// .cc file).
    struct Topology;

    /// Constructor step 1: the pairs, segments and friction coefficients of
    /// all @p interfaces, and the pairs' neighbours, normal sides and
    /// interfaces in @p topology.
    void
    collect_pairs(const std::vector<NodeInsertion::Interface> &interfaces,
                  const Options                               &options,
                  Topology                                    &topology);

    /// Constructor step 2: the nodes, the frame and the chords of each pair,
    /// with the base displacement @p base (none if null).
    void
    set_up_pair_data(const Topology &topology, const dealii::Vector<double> *base);

    /// Constructor step 3: the slip origin of each pair, and which pairs
    /// begin their contact within the step (is_new_contact()).
    void
    set_up_slip_origins(const Topology &topology, const Options &options);

    /// The angle theta of pair @p i at @p u (and, if not null, the values
    /// d and theta_s of each chord).
    double
    turn(const PairData &data, const dealii::Vector<double> &u, std::vector<dealii::Tensor<1, 2>> *d) const;

    dealii::Point<2>
    position(const unsigned int node, const dealii::Vector<double> &u) const;

    /// What the value of a constraint subtracts from $a\cdot e$: the base
    /// offsets of tied contact and of the slip, 0 for the unilateral gap.
    double
    offset(const PairData &d, const bool tangential) const
    {
      if (tangential)
        return is_bilateral() ? d.tied_tangential : d.slip_origin;
      return is_bilateral() ? d.tied_normal : 0.;
    }

    const VEMDoFHandler<2>      &dof_handler;
    ContactSettings::Normal      model;
    double                       c;
    std::vector<ContactNodePair> pairs;
    std::vector<ContactSegment>  segments; ///< of all interfaces, pair indices global
    std::vector<PairData>        data;
    std::vector<bool>            fixed;
    std::vector<bool>            new_contact; ///< see is_new_contact()
    bool                         frictional = false;
    std::vector<double>          mu; ///< friction coefficient of each pair
  };
} // namespace dealvem

#endif
