// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_finite_strain_assembler_h
#define dealvem_elasticity_finite_strain_assembler_h

#include <deal.II/base/function.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/elasticity/finite_strain_operator.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/vem_values.h>

#include <string>
#include <utility>
#include <vector>

namespace dealvem
{
  /**
   * How a pressure acts at finite strain (FiniteStrainAssembler::add_pressure()).
   */
  enum class PressureLoad
  {
    /// A dead load: $p$ per unit reference length along the reference
    /// normal (the nominal traction $-p\,N$); it does not follow the
    /// deformation.
    dead,
    /// A follower load: $p$ per unit current length along the current
    /// normal ($-p\,n\,da$), as a gas or liquid pressure acts; it turns and
    /// stretches with the boundary.
    follower
  };

  /// "dead" or "follower".
  std::string
  pressure_load_name(const PressureLoad kind);

  /**
   * The PressureLoad named @p value ("dead" or "follower", case and blanks
   * around ignored); throws an ExcMessage naming @p parameter and the
   * values it takes otherwise.
   */
  PressureLoad
  parse_pressure_load(const std::string &value, const std::string &parameter);



  /**
   * Assembles the internal force vector and the consistent tangent matrix
   * of hyperelasticity at finite strain (total Lagrangian) with the
   * virtual element of VEMDoFHandler::get_degree(), cell by cell with
   * FiniteStrainOperator: what ElasticityAssembler is for linear
   * elasticity, for a Newton driver (FiniteStrainSolver).
   *
   * With the internal force $f_{int}(u) = \sum_E (r_c + K_s u)$ and the
   * external load $f_{ext}$ (body force and nominal tractions, dead loads
   * in the reference configuration), the residual at the load factor
   * $\lambda$ is $r(u) = \lambda f_{ext} - f_{int}(u)$ and the tangent
   * $K(u) = \partial f_{int}/\partial u = \sum_E (K_c + K_s)$.
   *
   * The loads are ElasticityAssembler's (held inside and built on the same
   * laws; ElasticityAssembler::local_load()): the body force
   * $\int_E f_0\cdot\Pi^0\varphi_i$ per unit reference area and the nominal
   * (first Piola-Kirchhoff) traction $T = PN$ per unit reference length
   * on boundary ids.
   *
   * <h3>Pressures</h3>
   * A pressure $p$ (positive pushing into the body) on a boundary id is
   * one of two loads (add_pressure(), PressureLoad):
   * - PressureLoad::dead: the nominal traction $T = -p\,N$ per unit
   *   reference length along the reference normal $N$, a part of
   *   $f_{ext}$ like the tractions;
   * - PressureLoad::follower: $t = -p\,n$ per unit current length along
   *   the current normal $n$, i.e. $T = -p\,JF^{-T}N$ per unit reference
   *   length (Nanson's formula). Its load vector $f_p(u)$ depends on the
   *   current edge positions (VirtualElement::add_edge_follower_pressure():
   *   linear in them, since $n\,da$ is the rotated current tangent $Q\,x'(s)\,ds$),
   *   so the residual is $r(u) = \lambda(f_{ext} + f_p(u)) - f_{int}(u)$
   *   and the tangent $K(u) = \partial f_{int}/\partial u -
   *   \lambda\,\partial f_p/\partial u$, where $\partial f_p/\partial u$
   *   is a constant matrix per boundary edge (not symmetric in general:
   *   the direct solver of FiniteStrainSolver takes it as it is). A
   *   follower pressure has no potential in general; strain_energy() leaves
   *   it out.
   * The pressure function is evaluated at reference points (a function of
   * $X$ and the time, set by the caller).
   *
   * Every law of the library must have a finite-strain response
   * (ConstitutiveLaw::has_finite_strain_response()) and a linear
   * small-strain response (its linearization at $F = I$, as
   * HyperelasticMaterial's), which ElasticityAssembler requires.
   *
   * The stabilization matrices $K_s$ are computed per cell by
   * freeze_stabilization() from a given state and kept until the next call
   * (see FiniteStrainOperator for the scaling and why it is frozen).
   */
  template <int dim>
  class FiniteStrainAssembler
  {
  public:
    /**
     * Constructor: the laws of @p laws (shared), the stabilization factor
     * @p gamma and rule @p stabilization of ElasticityOperator (default:
     * the trace rule for both orders, see FiniteStrainOperator for why;
     * Stabilization::automatic means the trace rule here too), and the
     * @p scaling of the stabilization (FiniteStrainOperator). Throws unless $\gamma > 0$, every
     * law has a finite-strain response, and every material id of the mesh
     * has a law. The stabilization is frozen at $u = 0$.
     */
    FiniteStrainAssembler(const VEMDoFHandler<dim>   &dof_handler,
                          const MaterialLibrary<dim> &laws,
                          const double                gamma         = 1.0,
                          const Stabilization         stabilization = Stabilization::trace,
                          const StabilizationScaling  scaling       = StabilizationScaling::current_tangent);

    /// Body force per unit reference area (2 components). The function
    /// must outlive the assembler.
    void
    set_body_force(const dealii::Function<dim> &f);

    /// Nominal traction $T = PN$ per unit reference length (2 components)
    /// on the boundary edges with id @p id. The function must outlive the
    /// assembler.
    void
    add_traction(const dealii::types::boundary_id id, const dealii::Function<dim> &g);

    /// A pressure $p$ (scalar function of the reference position, positive
    /// pushing into the body) on the boundary edges with id @p id, acting
    /// as @p kind says (PressureLoad; see the class documentation). The
    /// function must outlive the assembler.
    void
    add_pressure(const dealii::types::boundary_id id,
                 const dealii::Function<dim>     &p,
                 const PressureLoad               kind);

    /// Whether a follower pressure was added (the load then depends on the
    /// displacement).
    bool
    has_follower_loads() const
    {
      return !follower_pressures.empty();
    }

    /// The DoF handler given to the constructor.
    const VEMDoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /// The laws by material id.
    const MaterialLibrary<dim> &
    get_material_library() const
    {
      return laws;
    }

    /// The scaling of the stabilization given to the constructor.
    StabilizationScaling
    get_stabilization_scaling() const
    {
      return scaling;
    }

    /// The external load vector $f_{ext}$ at load factor 1 (unconstrained,
    /// n_dofs() entries), evaluated at the current time of the load
    /// functions; a follower pressure enters with its value in the
    /// reference configuration ($u = 0$), where it equals the dead one.
    void
    assemble_load_vector(dealii::Vector<double> &f_ext) const;

    /**
     * Compute and keep the stabilization matrix of every cell, scaled at the
     * state @p u (global displacement; ignored for
     * StabilizationScaling::initial_tangent). Throws ExcInvertedCell if
     * @p u inverts a cell.
     */
    void
    freeze_stabilization(const dealii::Vector<double> &u);

    /**
     * The residual $r(u) = \lambda f_{ext} - f_{int}(u)$ at the
     * displacement @p u and the load factor @p load_factor, unconstrained
     * (@p residual gets n_dofs() entries: at constrained DoFs it holds the
     * reactions with the opposite sign). If @p tangent is not null, also
     * the tangent matrix and its right-hand side @p rhs (the cell residuals)
     * condensed with @p constraints by
     * AffineConstraints::distribute_local_to_global, for the Newton update
     * $K\,\delta u = r$ (the constraints of the update: see
     * FiniteStrainSolver); @p tangent must have a sparsity pattern from
     * VEMDoFHandler::make_sparsity_pattern with these constraints. The
     * tangent may have more rows than n_dofs() (an augmented system, as
     * FiniteStrainSolver's with contact): the rows and columns beyond
     * n_dofs() are zeroed and left to the caller, and @p rhs gets the
     * tangent's size.
     * Throws ExcInvertedCell (naming the cell) if @p u inverts a cell.
     */
    void
    assemble(const dealii::Vector<double>            &u,
             const double                             load_factor,
             dealii::Vector<double>                  &residual,
             const dealii::AffineConstraints<double> &constraints,
             dealii::SparseMatrix<double>            *tangent,
             dealii::Vector<double>                  *rhs) const;

    /**
     * The stored energy at the displacement @p u: the strain energy of
     * every cell's consistency part (FiniteStrainOperator::strain_energy())
     * plus $\frac12 u_K^T K_s u_K$ of its frozen stabilization, the
     * potential of the internal force assemble() uses. Requires
     * freeze_stabilization() and hyperelastic laws (HyperelasticMaterial);
     * throws otherwise, or if @p u inverts a cell.
     */
    double
    strain_energy(const dealii::Vector<double> &u) const;

  private:
    const VEMDoFHandler<dim>               &dof_handler;
    MaterialLibrary<dim>                    laws;
    /// The loads (and the law of a cell), shared with linear elasticity.
    ElasticityAssembler<dim>                loads;
    double                                  gamma;
    Stabilization                           stabilization;
    StabilizationScaling                    scaling;
    std::vector<dealii::FullMatrix<double>> stabilization_matrices;
    /// The follower pressures: boundary id and function.
    std::vector<std::pair<dealii::types::boundary_id, const dealii::Function<dim> *>> follower_pressures;

    /// Add the follower pressures of the cell of @p vem_values at its
    /// displacement @p local_u to @p F (times @p factor), and $-$@p factor
    /// times their derivative to @p K if not null.
    void
    add_follower_loads(const VEMValues<dim>         &vem_values,
                       const dealii::Vector<double> &local_u,
                       const double                  factor,
                       dealii::Vector<double>       &F,
                       dealii::FullMatrix<double>   *K) const;
  };
} // namespace dealvem

#endif
