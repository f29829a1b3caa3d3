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

#include <cstdint>
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
   *
   * <h3>Cell data</h3>
   * Everything but the displacement is a function of the reference mesh,
   * so the element of each cell is computed once per mesh (by
   * freeze_stabilization(), which the constructor calls) and what the
   * assembly needs is kept: the DoF indices, the coefficients $g_{im}$ of
   * $\Pi^0\nabla\varphi_i = \sum_m g_{im}\,q_m$ in the scaled monomials
   * $q_m$ of degree $\le k-1$ ($2n_m$ numbers per DoF: the other
   * component's row is zero), the quadrature weights $w_q$ and the values
   * $q_m(x_q)$ (for $k = 1$ one point with the cell's area: $F$ is
   * constant), the law, the boundary ids of the cell's edges, the diagonal of
   * $K_c(0)$, and the state-independent part of the stabilization
   * (FiniteStrainOperator::stabilization_base(); for the trace and
   * boundary rules $K_s = \gamma\tau$ times it, so freeze_stabilization()
   * only computes the diagonal of $K_c(u^*)$ and keeps one factor per
   * cell). With $G_i(x) = \sum_m g_{im}q_m(x)$ the sums over the points
   * fold into moments:
   * @f[
   *   (r_c)_i = \sum_m g_{im} : \sum_q w_q\,q_m(x_q)\,P(F_q),\qquad
   *   (K_c)_{ik} = \sum_{m,l} g_{im} : \Bigl(\sum_q w_q\,q_m(x_q)\,q_l(x_q)\,A(F_q)\Bigr) : g_{kl},
   * @f]
   * the law once per point (ConstitutiveLaw::first_piola_kirchhoff_stress_and_tangent()),
   * then work that does not grow with the number of points. The values
   * are FiniteStrainOperator's to round-off. With a body force the cell
   * data also hold its quadrature (VirtualElement::body_force_vector()'s)
   * with the weighted monomials and VirtualElement::body_force_moment_map(),
   * so that an assembly evaluates only the load function; the cells with
   * an edge of a loaded boundary id (tractions, pressures) compute their
   * element again at every assembly.
   *
   * The data belong to the mesh's revision (PolygonalMesh::get_revision()),
   * the order and the number of DoFs, as VEMDoFHandler's numbering: after
   * the mesh changes (and VEMDoFHandler::distribute_dofs() numbers it
   * again), assemble() and strain_energy() throw until
   * freeze_stabilization() has been called, which computes them for the
   * new mesh.
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
     * StabilizationScaling::initial_tangent). Computes the cell data (see
     * the class documentation) first if the mesh is not the one they were
     * computed for. Throws ExcInvertedCell if @p u inverts a cell.
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

    /// The memory of the cell data and the stabilization (bytes).
    std::size_t
    memory_consumption() const;

  private:
    const VEMDoFHandler<dim>               &dof_handler;
    MaterialLibrary<dim>                    laws;
    /// The loads (and the law of a cell), shared with linear elasticity.
    ElasticityAssembler<dim>                loads;
    double                                  gamma;
    Stabilization                           stabilization;
    StabilizationScaling                    scaling;
    /// The follower pressures: boundary id and function.
    std::vector<std::pair<dealii::types::boundary_id, const dealii::Function<dim> *>> follower_pressures;
    /// The body force (set_body_force()), or nullptr.
    const dealii::Function<dim> *body_force = nullptr;
    /// The boundary ids with a traction or a pressure (dead or follower).
    std::vector<dealii::types::boundary_id> loaded_boundary_ids;

    /// The cell data (see the class documentation), for the mesh of
    /// revision @p revision, the order @p degree and @p n_dofs DoFs.
    struct CellData
    {
      /// Whether the data were computed.
      bool valid = false;
      /// The key: the mesh's revision, the order and the number of DoFs.
      std::uint64_t                   revision = 0;
      unsigned int                    degree   = 0;
      dealii::types::global_dof_index n_dofs   = 0;
      /// $n_m$, the number of scaled monomials of degree $\le k-1$.
      unsigned int n_monomials = 0;
      /// The DoFs of cell c: dof_indices[dof_start[c] ... dof_start[c + 1]).
      std::vector<unsigned int>                    dof_start;
      std::vector<dealii::types::global_dof_index> dof_indices;
      /// For the local DoF i of cell c (global position p = dof_start[c] + i)
      /// the coefficients g_im of Pi^0 grad phi_i, row i % 2, at
      /// gradient[(p * dim + j) * n_m + m] (column j).
      std::vector<double> gradient;
      /// The points of cell c: point_start[c] ... point_start[c + 1]; their
      /// weights and monomial values (monomials[q * n_m + m]).
      std::vector<unsigned int> point_start;
      std::vector<double>       weights;
      std::vector<double>       monomials;
      /// The law of each cell.
      std::vector<const ConstitutiveLaw<dim> *> cell_laws;
      /// The boundary ids of the boundary edges of cell c:
      /// boundary_ids[boundary_start[c] ... boundary_start[c + 1]).
      std::vector<unsigned int>               boundary_start;
      std::vector<dealii::types::boundary_id> boundary_ids;
      /// The diagonal of K_c(0), at dof_start[c] + i.
      std::vector<double> initial_diagonal;
      /// FiniteStrainOperator::stabilization_base() of each cell.
      std::vector<dealii::FullMatrix<double>> stabilization_bases;
      /// With a body force: the points of its quadrature in cell c,
      /// body_points[body_point_start[c] ... body_point_start[c + 1]), the
      /// weights times the six scaled monomials of degree <= 2 at each
      /// (body_monomials[6 q + m]), and VirtualElement::body_force_moment_map()
      /// of the local DoF i at body_maps[12 (dof_start[c] + i) ...].
      bool                            has_body_force_data = false;
      std::vector<unsigned int>       body_point_start;
      std::vector<dealii::Point<dim>> body_points;
      std::vector<double>             body_monomials;
      std::vector<double>             body_maps;
    };
    CellData cell_data;

    /// The stabilization frozen by freeze_stabilization(): gamma tau per
    /// cell (trace and boundary rules: K_s = factor times the base), or
    /// the matrices (diagonal rule).
    std::vector<double>                     stabilization_factors;
    std::vector<dealii::FullMatrix<double>> stabilization_matrices;

    /// Whether cell_data belong to the present mesh, order and numbering.
    bool
    cell_data_current() const;

    /// Compute cell_data for the present mesh.
    void
    compute_cell_data();

    /// Throw (naming @p caller) unless the stabilization was frozen on
    /// the present mesh.
    void
    check_frozen(const std::string &caller) const;

    /// Compute the body-force part of cell_data.
    void
    compute_body_force_data();

    /// Whether cell @p c has an edge with a loaded boundary id.
    bool
    cell_has_boundary_load(const unsigned int c) const;

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
