// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_design_design_problem_h
#define dealvem_design_design_problem_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/mesh/polygonal_mesh.h>
#include <dealvem/solvers/saddle_point_solver.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dealvem
{
  template <int dim>
  class ElasticityAssembler;

  namespace Design
  {
    /**
     * The seam between an optimizer and the analysis it designs: for a
     * stiffness factor per cell of the mesh (the interpolated densities,
     * MaterialInterpolation), solve the state and return the objective
     * $J$ and its gradient $\partial J/\partial s_c$ with respect to every
     * cell's factor. TopologyOptimizer calls only this.
     */
    class DesignProblem
    {
    public:
      virtual ~DesignProblem() = default;

      /// The mesh whose cells the factors belong to.
      virtual const PolygonalMesh<2> &
      get_mesh() const = 0;

      /// A name of the objective for reports ("compliance", ...).
      virtual std::string
      objective_name() const = 0;

      /**
       * Solve the state with the stiffness factors @p factors (one per cell
       * of get_mesh(), each > 0: the law of cell c is multiplied by
       * factors[c]) and return the objective; @p gradient receives
       * $\partial J/\partial s_c$ for every cell.
       */
      virtual double
      evaluate(const std::vector<double> &factors, std::vector<double> &gradient) = 0;

      /// The number of constraints $g_j(s) \le 0$ of the design besides
      /// the volume (default: none).
      virtual unsigned int
      n_constraints() const
      {
        return 0;
      }

      /// A name of constraint @p j for reports.
      virtual std::string
      constraint_name(const unsigned int j) const;

      /**
       * The constraints at the design of the last evaluate(): @p values
       * receives $g_j$ (feasible where $\le 0$, of order one: normalized by
       * their bound) and @p gradients the $\partial g_j/\partial s_c$ of
       * every cell, one vector per constraint. Throws unless evaluate() was
       * called.
       */
      virtual void
      constraints(std::vector<double> &values, std::vector<std::vector<double>> &gradients) const;
    };



    /**
     * Elastic bodies on one polygonal mesh (material id = body), optionally
     * in node-to-node contact across non-matching interfaces, as a design
     * problem: homogeneous supports, loads independent of the design, and
     * a stiffness factor per cell.
     *
     * <h3>The state</h3>
     * setup() inserts the nodes of every contact interface
     * (NodeInsertion), distributes the DoFs of order k, builds the
     * constraints of the supports, the contact rows (ContactAssembler) and
     * the load vector $f$. evaluate() assembles $K(s) = \sum_c s_c K_c$
     * ($K_c$ the VEM matrix of cell c with its body's law, ElasticityOperator)
     * and solves: without contact the elasticity system, with contact the
     * contact problem of the given ContactSettings (tied, unilateral with
     * stick by multipliers or by a penalty, or frictionless) by the
     * library's ContactSolver (ActiveSetSolver), each design from the
     * initial gaps.
     *
     * <h3>Objectives and their sensitivities</h3>
     * With the converged active set fixed, the state
     * $x = (u, \lambda)$ solves the symmetric system $A(s) x = b$ of that set
     * (ContactAssembler's rows, the inactive multipliers zero). An objective
     * linear in the state, $J = a^T x$, then has
     * @f[ \frac{\partial J}{\partial s_c} = -\,y_c^T K_c\, u_c, \qquad
     *     A y = a, @f]
     * (the adjoint $y$; only the stiffness block of $A$ depends on $s$):
     * - Objective::compliance: $J = f^T u$, $a = (f, 0)$. When every
     *   enforced row has a zero right-hand side (no initial gap or
     *   interference on the active pairs) $y = x$ and no adjoint solve is
     *   needed: $\partial J/\partial s_c = -u_c^T K_c u_c$. Otherwise one
     *   more solve of the same matrix.
     * - Objective::interface_force: the compressive normal force of one
     *   interface, $J = -\sum_{i \in I} \lambda_i$ (the multipliers are
     *   non-positive in compression), $a$ the indicator of its normal rows.
     * - Objective::max_pressure: the largest contact pressure of one
     *   interface, smoothly: the $P$-norm
     *   $J = \bigl(\sum_{i \in I} \max(0, p_i)^P\bigr)^{1/P}$ of the pair
     *   pressures $p_i = -\lambda_i / w_i$ ($w_i$ the tributary length;
     *   $P$ = set_pressure_norm_exponent(), default 8), which lies between
     *   $\max_i p_i$ and $n^{1/P}\max_i p_i$. It is not linear in $x$: the
     *   adjoint takes $a = \partial J/\partial x$ at the state,
     *   $a_{\lambda_i} = -\max(0,p_i)^{P-1} J^{1-P} / w_i$.
     *
     * The derivative is that of the converged set: it assumes strict
     * complementarity. last_state() reports the degenerate pairs (closed
     * with a multiplier below $10^{-8}$ of the largest, or open with a gap
     * below $10^{-8}$ of the mesh size) at which it is only one-sided.
     */
    class ElasticDesignProblem : public DesignProblem
    {
    public:
      /// A response of the state: the objective, or a constrained quantity.
      enum class Response
      {
        compliance,      ///< $f^T u$
        interface_force, ///< the compressive normal force of one interface
        max_pressure     ///< the P-norm of the pair pressures of one interface
      };
      /// What evaluate() returns.
      using Objective = Response;

      /// The side of a constraint's bound.
      enum class Bound
      {
        at_most, ///< response $\le$ bound
        at_least ///< response $\ge$ bound
      };

      /// The state of the last evaluate().
      struct State
      {
        /// The displacements (size n_dofs()).
        dealii::Vector<double> displacement;
        /// The normal multiplier of every pair (empty without contact).
        std::vector<double> normal_multipliers;
        /// Whether each pair was closed.
        std::vector<bool> active;
        /// The compliance $f^T u$.
        double compliance = 0;
        /// The compressive normal force of each interface, $-\sum \lambda_i$.
        std::vector<double> interface_forces;
        /// The response of each constraint (add_constraint()), unscaled.
        std::vector<double> constraint_responses;
        /// Pairs at which the derivative is one-sided (see the class
        /// documentation).
        unsigned int n_degenerate_pairs = 0;
        /// Active-set iterations of the contact solve (0 without contact).
        unsigned int n_contact_iterations = 0;
        /// Linear solves, the adjoint included.
        unsigned int n_solves = 0;
        /// Krylov iterations of the state's solves (iterative solvers; 1
        /// per solve for the direct ones).
        unsigned int linear_iterations = 0;
        /// Whether an adjoint solve was needed.
        bool adjoint_solved = false;
        /// The direct constraint solver: Cholesky factorizations computed
        /// in this evaluation (the adjoint solves reuse the state's).
        unsigned int n_factorizations = 0;
        /// Of these, the factorizations that computed a fill-reducing
        /// ordering for a new pattern (the others kept the ordering of the
        /// last one: a design on a fixed mesh and active set analyses its
        /// pattern once).
        unsigned int n_analyses = 0;
        /// Wall time (s) of the assembly of $\sum_c s_c K_c$.
        double time_assembly = 0;
        /// Wall time (s) of the state: the solve, or the contact solve with
        /// all its active-set iterations.
        double time_state = 0;
        /// Wall time (s) of the adjoint solve (about 0 when not needed).
        double time_adjoint = 0;
        /// Wall time (s) of the cell-wise sensitivities.
        double time_sensitivities = 0;
      };

      /**
       * The bodies of @p mesh (copied; node insertion changes the copy) with
       * the laws @p laws (linear laws, by material id), virtual elements of
       * order @p degree (1 or 2).
       */
      ElasticDesignProblem(const PolygonalMesh<2> &mesh, const MaterialLibrary<2> &laws, const unsigned int degree);

      ~ElasticDesignProblem() override;

      /// Hold the components @p fixed of the boundary edges with id @p id
      /// at zero.
      void
      add_support(const dealii::types::boundary_id id, const std::array<bool, 2> &fixed = {{true, true}});

      /// Hold component @p component of the vertex at @p p (a vertex of the
      /// mesh within $10^{-8}$ of its extent; throws otherwise).
      void
      add_point_support(const dealii::Point<2> &p, const unsigned int component);

      /// A constant traction @p t on the boundary edges with id @p id.
      void
      add_traction(const dealii::types::boundary_id id, const dealii::Tensor<1, 2> &t);

      /// A point force @p f at the vertex at @p p (as add_point_support()).
      void
      add_point_load(const dealii::Point<2> &p, const dealii::Tensor<1, 2> &f);

      /// Writes constraints of the displacements (after those of
      /// add_support() and add_point_support()).
      using ConstraintFunction =
        std::function<void(const VEMDoFHandler<2> &, dealii::AffineConstraints<double> &)>;
      /// Hands loads to an assembler (its add_traction(), add_pressure(),
      /// set_body_force(), add_nodal_load()).
      using LoadFunction = std::function<void(ElasticityAssembler<2> &)>;

      /**
       * Supports and loads of a caller that has its own description of them
       * (the parameter programs: BoundaryConditionParameters::
       * apply_constraints() and add_loads()). setup() calls both; the
       * constraints must prescribe zero displacements (setup() throws
       * naming the DoF and its value otherwise), and the functions and
       * whatever they refer to must outlive setup().
       */
      void
      add_boundary_conditions(const ConstraintFunction &constraints, const LoadFunction &loads);

      /// A contact interface: the boundary parts with ids @p master and
      /// @p slave (node insertion makes them matching in setup()).
      void
      add_contact_interface(const dealii::types::boundary_id master, const dealii::types::boundary_id slave);

      /// The contact model (default: unilateral, stick by multipliers).
      ContactSettings &
      contact_settings()
      {
        return settings;
      }

      /// The node insertion of setup() (NodeInsertion::Settings; its
      /// validate_mesh is ignored: the mesh is validated once after every
      /// interface).
      NodeInsertion::Settings &
      insertion_settings()
      {
        return insertion;
      }

      /// The linear solver (default: the Cholesky factorization of the
      /// condensed stiffness, SaddlePointSolver::Type::direct_constraints),
      /// read at the first evaluate().
      SaddlePointSolver::Settings &
      solver_settings()
      {
        return solver_settings_;
      }

      /// The objective; for Objective::interface_force and max_pressure,
      /// the interface (in the order of add_contact_interface()).
      void
      set_objective(const Objective objective, const unsigned int interface = 0);

      /// The exponent P of Objective::max_pressure (>= 1; default 8; the
      /// constraints on the largest pressure too).
      void
      set_pressure_norm_exponent(const double P);

      /**
       * Constrain the response @p response (of interface @p interface for
       * the force and the pressure) to @p bound from the side @p sense:
       * $g = (R - R^*)/|R^*| \le 0$ (Bound::at_most) or
       * $g = (R^* - R)/|R^*| \le 0$ (Bound::at_least). Its gradient is that
       * of the response, by the adjoint of the converged set (one more
       * solve with the factorization or preconditioner of the state; none
       * for a self-adjoint compliance). The bound must be positive: the
       * three responses are non-negative.
       */
      void
      add_constraint(const Response     response,
                     const double       bound,
                     const Bound        sense     = Bound::at_most,
                     const unsigned int interface = 0);

      unsigned int
      n_constraints() const override
      {
        return constraint_list.size();
      }

      std::string
      constraint_name(const unsigned int j) const override;

      void
      constraints(std::vector<double> &values, std::vector<std::vector<double>> &gradients) const override;

      /// Build everything that does not depend on the design (see the class
      /// documentation). Throws if a body is not held.
      void
      setup();

      /// The mesh after node insertion (the cells keep their indices).
      const PolygonalMesh<2> &
      get_mesh() const override
      {
        return mesh;
      }

      /// The DoF handler (after setup()).
      const VEMDoFHandler<2> &
      get_dof_handler() const
      {
        return dof_handler;
      }

      /// The laws by material id.
      const MaterialLibrary<2> &
      get_laws() const
      {
        return laws;
      }

      /// The number of contact pairs (after setup()).
      unsigned int
      n_pairs() const;

      /// The contact pairs of every interface, in order (after setup(); the
      /// index of a pair is its index in State::normal_multipliers).
      const std::vector<ContactNodePair> &
      get_pairs() const;

      std::string
      objective_name() const override;

      double
      evaluate(const std::vector<double> &factors, std::vector<double> &gradient) override;

      /// The state of the last evaluate().
      const State &
      last_state() const
      {
        return state;
      }

      /**
       * $\sum_c$ factors[c] $\cdot w_c^T K_c v_c$ cell by cell: the vector
       * whose entry c is $w_c^T K_c v_c$ (the unit-factor matrices), for
       * displacements @p v and @p w of size n_dofs().
       */
      std::vector<double>
      cell_bilinear_forms(const dealii::Vector<double> &v, const dealii::Vector<double> &w) const;

    private:
      struct Data;

      /// One constraint of add_constraint().
      struct Constraint
      {
        Response     response;
        unsigned int interface;
        double       bound;
        Bound        sense;
      };

      void
      assemble(const std::vector<double> &factors);

      /// The value of @p response of interface @p interface at the state
      /// and its derivative @p a with respect to the state (size n + m).
      double
      response_and_state_derivative(const Response response, const unsigned int interface, const bool for_objective,
                                    dealii::Vector<double> &a) const;

      /// The name of @p response of interface @p interface.
      std::string
      response_name(const Response response, const unsigned int interface) const;

      PolygonalMesh<2>                                   mesh;
      MaterialLibrary<2>                                 laws;
      unsigned int                                       degree;
      VEMDoFHandler<2>                                   dof_handler;
      ContactSettings                                    settings;
      NodeInsertion::Settings                            insertion;
      SaddlePointSolver::Settings                        solver_settings_;
      Objective                                          objective = Objective::compliance;
      unsigned int                                       objective_interface = 0;
      double                                             pressure_exponent   = 8;
      std::vector<std::pair<dealii::types::boundary_id, std::array<bool, 2>>> supports;
      std::vector<std::pair<dealii::Point<2>, unsigned int>>                  point_supports;
      std::vector<std::pair<dealii::types::boundary_id, dealii::Tensor<1, 2>>> tractions;
      std::vector<std::pair<dealii::Point<2>, dealii::Tensor<1, 2>>>          point_loads;
      std::vector<std::pair<dealii::types::boundary_id, dealii::types::boundary_id>> interface_ids;
      std::vector<ConstraintFunction>                                         constraint_functions;
      std::vector<LoadFunction>                                               load_functions;
      std::vector<Constraint>                                                 constraint_list;
      std::unique_ptr<Data>                                                   data;
      State                                                                   state;
      /// The constraint values and gradients of the last evaluate().
      std::vector<double>                                                     constraint_values;
      std::vector<std::vector<double>>                                        constraint_gradients;
    };
  } // namespace Design
} // namespace dealvem

#endif
