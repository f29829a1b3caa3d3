// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_app_problem_setup_h
#define dealvem_app_problem_setup_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>

#include <dealvem/app/input_parsing.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/constitutive_law.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/finite_strain_solver.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/elasticity/support_reactions.h>
#include <dealvem/mesh/mesh_io.h>
#include <dealvem/postprocessing/json_summary.h>
#include <dealvem/mesh/polygonal_mesh.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dealvem
{
  /**
   * Boundary conditions and loads of the parameter file, section
   * "Boundary conditions and loads". Syntax (see InputParsing):
   * - Function constants: `E=7000, p=10`
   * - Dirichlet: `id : components : expressions; ...`, components one of
   *   x, y, xy, e.g. `0 : xy : 0, 0; 3 : y : -0.01*x`
   * - Roller: `id, id, ...` (straight boundary parts, u.n = 0)
   * - Traction: `id : gx, gy; ...`
   * - Pressure: `id : p; ...` (positive pressure pushes into the body; at
   *   finite strain a follower or a dead load, add_finite_strain_loads())
   * - Point constraints: `x, y : component : value; ...` or
   *   `x, y : component : value : body` (the mesh vertex at (x, y), of the
   *   cells with material id `body` if given; component x or y; the value
   *   is an expression evaluated at (x, y))
   * - Rigid boundary: `id : Fx, Fy; ...` or `id : Fx, Fy : M; ...` (the
   *   nodes on the boundary part move as one rigid body, loaded by the
   *   force (Fx, Fy) at the part's centroid and the moment M about it;
   *   the expressions are evaluated at the centroid)
   * - Rotation about centre: `id : cx, cy : angle a; ...` (the boundary
   *   part turned rigidly about (cx, cy) by the angle a, counter-clockwise,
   *   radians: Dirichlet data of the exact rotation) or
   *   `id : cx, cy : torque M; ...` (the part turns rigidly about (cx, cy)
   *   by an unknown angle, loaded by the torque M, counter-clockwise; small
   *   strain only); the expressions are evaluated at the centre
   * - Body force: `fx, fy` (empty: none)
   *
   * Expressions are muparser expressions in x, y and t with the function
   * constants; t = 1 unless set_time() says otherwise: the problems set
   * the time of their load steps (section "Load steps", step n of N at
   * t = n * Final time / N; a one-body problem at small strain is solved at
   * t = Final time).
   * Every malformed entry gives an error naming the parameter and the entry;
   * so does an entry on a boundary id the mesh does not have
   * (check_boundary_ids()), an expression that is not finite where it is
   * evaluated, and a constraint that conflicts with an earlier one.
   *
   * <h3>In code</h3>
   * The same lists can be filled without a parameter file, with any
   * dealii::Function<2> (add_dirichlet(), add_roller(), add_traction(),
   * add_pressure(), add_point_constraint(), add_rigid_boundary(),
   * set_body_force()); parse_parameters() is one client of these. Each
   * condition gets a name for the messages (by default "Dirichlet condition
   * on boundary id 3" and so on); a function that returns a non-finite value
   * is refused with that name, the point and the time. Functions are shared,
   * not copied: set_time() of the load steps calls their set_time().
   */
  class BoundaryConditionParameters
  {
  public:
    /// Declare the entries of the section 'Boundary conditions and loads'
    /// (with their help strings) in the current subsection of @p prm.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Read the section (replacing everything set before). Boundary ids
    /// may be given by the physical names of set_physical_names().
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The physical names of the mesh file(s) (MeshIO::read_msh_physical_names()),
    /// by which the entries may name boundary ids ('Dirichlet = clamped :
    /// xy : 0, 0') and bodies (the body of a point constraint); call before
    /// parse_parameters(). check_boundary_ids() shows them in its messages.
    void
    set_physical_names(const MeshIO::PhysicalNames &names)
    {
      physical_names = names;
    }

    /// Remove every condition and load (and the function constants).
    void
    clear();

    /**
     * Prescribe the displacement components selected by @p mask (two
     * components, x and y) on the boundary edges with id @p id to the
     * values of @p displacement (a function with two components; the
     * unselected one is not used).
     */
    void
    add_dirichlet(const dealii::types::boundary_id         id,
                  const std::array<bool, 2>                 &mask,
                  const std::shared_ptr<dealii::Function<2>> &displacement,
                  const std::string                         &name = "");

    /// Zero normal displacement on the straight boundary part @p id.
    void
    add_roller(const dealii::types::boundary_id id, const std::string &name = "");

    /// A traction (force per length; a function with two components) on
    /// the boundary edges with id @p id.
    void
    add_traction(const dealii::types::boundary_id         id,
                 const std::shared_ptr<dealii::Function<2>> &traction,
                 const std::string                         &name = "");

    /// A normal pressure (one component; positive pushes into the body).
    void
    add_pressure(const dealii::types::boundary_id         id,
                 const std::shared_ptr<dealii::Function<2>> &pressure,
                 const std::string                         &name = "");

    /**
     * Constrain component @p component (0: x, 1: y) of the mesh vertex at
     * @p point to the value of @p value (one component) there; where
     * vertices of several bodies lie at @p point, @p body (a material id)
     * selects one.
     */
    void
    add_point_constraint(const dealii::Point<2>                    &point,
                         const unsigned int                         component,
                         const std::shared_ptr<dealii::Function<2>> &value,
                         const dealii::types::material_id           body = dealii::numbers::invalid_material_id,
                         const std::string                         &name = "");

    /**
     * Make the boundary part @p id one rigid body loaded by @p force (two
     * components) at its arc-length centroid and the moment @p moment (one
     * component; null: none) about it, both evaluated at the centroid.
     */
    void
    add_rigid_boundary(const dealii::types::boundary_id         id,
                       const std::shared_ptr<dealii::Function<2>> &force,
                       const std::shared_ptr<dealii::Function<2>> &moment = nullptr,
                       const std::string                         &name   = "");

    /**
     * Turn the boundary part @p id rigidly about @p centre: with
     * @p torque_driven false by the angle @p value (one component,
     * counter-clockwise, radians; BoundaryConditions::add_prescribed_rotation()),
     * with @p torque_driven true by an unknown angle under the torque
     * @p value (counter-clockwise; BoundaryConditions::add_torque_rotation(),
     * small strain only). @p value is evaluated at the centre.
     */
    void
    add_rotation_about_centre(const dealii::types::boundary_id            id,
                              const dealii::Point<2>                     &centre,
                              const std::shared_ptr<dealii::Function<2>> &value,
                              const bool                                  torque_driven,
                              const std::string                          &name = "");

    /**
     * The factor of the prescribed angles of 'Rotation about centre' (1 by
     * default): a finite-strain load step without t in the data sets its
     * load factor here, so that apply_constraints() writes the exact
     * rotation by the factor times the angle (the other prescribed values
     * it scales itself).
     */
    void
    set_load_factor(const double factor)
    {
      angle_factor = factor;
    }

    /// Whether a 'Rotation about centre' entry is set.
    bool
    has_rotations() const
    {
      return !rotations.empty();
    }

    /**
     * The Rotation of every 'Rotation about centre' entry after a solve, in
     * the order of the entries: @p parts as apply_constraints() returned
     * them, @p constraints, @p u (the displacement), @p unbalanced and
     * @p positions as for SupportReactions::compute(). The torque is that
     * of the current time (set_time()).
     */
    std::vector<SupportReactions::Rotation>
    rotation_results(const std::vector<BoundaryConditions::RotationAboutCentre<2>> &parts,
                     const dealii::AffineConstraints<double>                       &constraints,
                     const dealii::Vector<double>                                  &u,
                     const dealii::Vector<double>                                  &unbalanced,
                     const std::vector<dealii::Point<2>>                           &positions) const;

    /// The body force (force per area; two components); null: none.
    void
    set_body_force(const std::shared_ptr<dealii::Function<2>> &force, const std::string &name = "");

    /// The bound of displacements, prescribed (apply_constraints()) or
    /// computed (checked by the problems after each solve), relative to the
    /// diagonal of the bounding box of the mesh: beyond it the
    /// small-displacement model means nothing and stresses and error
    /// integrals head for overflow.
    static constexpr double max_displacement_ratio = 1e6;

    /**
     * Stop with an error naming the parameter entry, the missing boundary id
     * and the ids the mesh has if an entry (Dirichlet, roller, traction,
     * pressure, rigid boundary) uses a boundary id that no boundary edge of
     * @p mesh carries.
     */
    void
    check_boundary_ids(const PolygonalMesh<2> &mesh) const;

    /// Write all constraints: Dirichlet first, then rollers, point
    /// constraints and rigid boundaries. A point constraint or rigid
    /// boundary that collides with an earlier constraint stops with a
    /// message naming both entries; so does a prescribed displacement larger
    /// than max_displacement_ratio times the size of the mesh, naming its
    /// entry. If @p supports is not null, it gets the supports whose
    /// reactions SupportReactions computes: one per boundary id with
    /// Dirichlet data or a roller ("boundary 3", the lines of all entries on
    /// that id), then one per point constraint ("point 0 (0, 0)"), each
    /// with the lines it wrote first; a support that wrote no line (its
    /// DoFs were constrained by an earlier entry) is listed without lines.
    /// The lines of rigid boundaries pass the load on within the body and
    /// are no support. Rotations about a centre come last: a prescribed
    /// angle is a support ("boundary 3") like Dirichlet data; a
    /// torque-driven part is none. If @p rotations is not null, it gets the
    /// parts of the 'Rotation about centre' entries, in their order
    /// (rotation_results() reads them).
    void
    apply_constraints(const VEMDoFHandler<2>                                  &dof_handler,
                      dealii::AffineConstraints<double>                       &constraints,
                      std::vector<SupportReactions::Support>                  *supports  = nullptr,
                      std::vector<BoundaryConditions::RotationAboutCentre<2>> *rotations = nullptr) const;

    /// Hand the loads to an assembler (the functions live in this object);
    /// the resultants of rigid boundaries become nodal loads.
    void
    add_loads(ElasticityAssembler<2> &assembler) const;

    /**
     * Hand the loads to a finite-strain assembler: the body force (per unit
     * reference area), the tractions (nominal, per unit reference length;
     * dead loads) and the pressures as @p pressure_load says (PressureLoad:
     * a follower load on the deformed boundary, or the dead nominal
     * traction $-p\,N$; FiniteStrainAssembler::add_pressure()). A rigid
     * boundary part carries a resultant that turns with it and is refused
     * with a message naming its entry and @p switch_name (the parameter
     * that asked for finite strain).
     */
    void
    add_finite_strain_loads(FiniteStrainAssembler<2> &assembler,
                            const std::string        &switch_name,
                            const PressureLoad        pressure_load) const;

    /// Whether a pressure load is set.
    bool
    has_pressure() const
    {
      return !pressures.empty();
    }

    /// Whether an expression of the section uses the time t
    /// (time_dependent_entries() is not empty).
    bool
    uses_time() const;

    /**
     * Set the time t of every expression of this section (Dirichlet data,
     * loads, point constraints, rigid boundaries, body force). Load steps
     * call this before apply_constraints() and add_loads().
     */
    void
    set_time(const double t);

    /// The 'Function constants' (name and value) of the expressions.
    const std::map<std::string, double> &
    get_constants() const
    {
      return constants;
    }

    /// The entries (parameter names) whose expressions use the time t.
    std::vector<std::string>
    time_dependent_entries() const;

    /// The boundary ids used by any condition or load.
    std::set<dealii::types::boundary_id>
    used_boundary_ids() const;

  private:
    /// Physical names of the mesh files (set_physical_names()).
    MeshIO::PhysicalNames physical_names;

    struct Dirichlet
    {
      std::string                                   name;
      dealii::types::boundary_id                   id;
      std::array<bool, 2>                          mask;
      std::shared_ptr<dealii::Function<2>>          function;
    };
    struct Roller
    {
      std::string                name;
      dealii::types::boundary_id id;
    };
    struct Load
    {
      std::string                                   name;
      dealii::types::boundary_id                   id;
      std::shared_ptr<dealii::Function<2>>          function;
    };
    struct PointConstraint
    {
      std::string                                   name;
      dealii::Point<2>                              point;
      unsigned int                                  component;
      std::shared_ptr<dealii::Function<2>>          value;
      dealii::types::material_id                    body;
    };
    struct RigidBoundary
    {
      std::string                                   name;
      dealii::types::boundary_id                   id;
      std::shared_ptr<dealii::Function<2>>          force;
      std::shared_ptr<dealii::Function<2>>          moment;
    };

    struct Rotation
    {
      std::string                          name;
      dealii::types::boundary_id           id;
      dealii::Point<2>                     centre;
      std::shared_ptr<dealii::Function<2>> value;
      bool                                 torque_driven;
    };

    /// Declare the entry 'Rotation about centre' (declare_parameters()).
    static void
    declare_rotation_entry(dealii::ParameterHandler &prm);

    /// Add the parts of the entry 'Rotation about centre' with the value
    /// @p value (parse_parameters()).
    void
    parse_rotation_entries(const std::string &value);

    std::vector<Rotation>                          rotations;
    double                                         angle_factor = 1;
    std::map<std::string, double>                  constants;
    std::vector<Dirichlet>                         dirichlet;
    std::vector<Roller>                            rollers;
    std::vector<Load>                              tractions, pressures;
    std::vector<PointConstraint>                   points;
    std::vector<RigidBoundary>                     rigid_boundaries;
    std::shared_ptr<dealii::Function<2>>           body_force;
    std::string                                    body_force_name;
  };


  /**
   * The report of the 'Rotation about centre' entries (SupportReactions::Rotation)
   * after a solve or a load step, shared by the programs: one line per part
   * on the terminal, the JSON entries and the CSV lines.
   */
  namespace RotationOutput
  {
    /**
     * One line per part: "rotation of boundary 3 about (0, 0): angle 0.01
     * (prescribed), moment about centre -12.5 (reaction), force (..)" or
     * "...: torque 5 (applied), angle 0.0012 (solved for), bearing force (..)".
     */
    void
    print(const dealii::ConditionalOStream              &out,
          const std::vector<SupportReactions::Rotation> &rotations,
          const std::string                             &indent);

    /**
     * The entries @p key + "rotation_<id>." + boundary_id, centre_x,
     * centre_y, mode ("angle" or "torque"), angle, torque,
     * reaction_moment_about_centre, moment_about_centre, force_x, force_y.
     */
    void
    json(JsonSummary &summary, const std::string &key, const std::vector<SupportReactions::Rotation> &rotations);

    /// The header of the CSV file of the rotations (one line per part and
    /// load step).
    std::string
    csv_header();

    /// The CSV line of @p r in load step @p step at time @p time (full
    /// precision), with a line break.
    std::string
    csv_line(const unsigned int step, const double time, const SupportReactions::Rotation &r);
  } // namespace RotationOutput



  /**
   * The constitutive law of the parameter file, entry 'Material/Law':
   * `linear` (ElasticMaterial, the default), `neo-hooke` (NeoHookeMaterial)
   * or `saint venant-kirchhoff` (SaintVenantKirchhoffMaterial), each from
   * the section's Young's modulus and Poisson's ratio. (The entry
   * 'Material/Model' was taken before: it is the 2D model, plane strain or
   * plane stress, and stays so.) Shared by ElasticityProblem and
   * ContactProblem.
   */
  namespace MaterialLaws
  {
    /// A law of the program: its name in LawFactory ("linear",
    /// "neo-hooke", ...); a new law is registered there, not here.
    using Law = std::string;

    /// The documentation string of the entry 'Law' (it lists the laws of
    /// LawFactory).
    std::string
    law_documentation();

    /**
     * The law named @p value (white space around it and case ignored;
     * aliases such as 'neo-hookean' give their law's name). Throws for any
     * other name, naming @p parameter, the value and the valid names.
     */
    Law
    parse(const std::string &value, const std::string &parameter);

    /// The name as the parameter file writes it ("neo-hooke", ...).
    inline std::string
    name(const Law &law)
    {
      return law;
    }

    /// Whether @p law is a hyperelastic law (has a finite-strain response).
    bool
    is_hyperelastic(const Law &law);

    /**
     * The law @p law with Young's modulus @p E, Poisson's ratio @p nu and
     * the 2D @p model (plane strain or plane stress, for every law).
     */
    std::shared_ptr<const ConstitutiveLaw<2>>
    make_law(const Law &law, const double E, const double nu, const ElasticMaterial::Model model);
  } // namespace MaterialLaws



  /**
   * The finite-strain switch of the parameter file, section 'Finite
   * strain': 'Enabled' (false: small strain, the default) and the Newton
   * controls of FiniteStrainSolver::Parameters ('Maximum Newton
   * iterations', 'Residual tolerance', 'Update tolerance', 'Line search'),
   * plus an optional 'Monitor point' whose displacement is reported per
   * load step. The number of load steps comes from the section 'Load
   * steps' ('Number of steps'), which the elasticity problem reads when
   * finite strain is enabled.
   */
  class FiniteStrainParameters
  {
  public:
    /// Declare the section 'Finite strain' (at the top level of @p prm).
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Read the section (at the top level of @p prm); throws naming the
    /// parameter for a malformed monitor point.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * For a problem that the program solves at small strain only: throw if
     * 'Finite strain/Enabled' is true, with a message that names the
     * parameter and ends with @p reason (which problem, and why).
     */
    static void
    refuse(dealii::ParameterHandler &prm, const std::string &reason);

    /// 'Finite strain/Enabled'.
    bool enabled = false;

    /// The Newton controls (n_load_steps is set by the problem from 'Load
    /// steps/Number of steps').
    FiniteStrainSolver<2>::Parameters solver;

    /// 'Finite strain/Pressure load': how the pressures act at finite
    /// strain (default PressureLoad::follower).
    PressureLoad pressure_load = PressureLoad::follower;

    /// Whether 'Monitor point' was given.
    bool has_monitor_point = false;

    /// The monitor point (a vertex of the mesh).
    dealii::Point<2> monitor_point;
  };


  /**
   * The scales of a problem checked before its solve: the loads against the
   * stiffness of the bodies (all paths), and at finite strain also the range
   * of the moduli.
   */
  namespace ScaleCheck
  {
    /// A body, as the checks name it.
    struct Body
    {
      /// The material id of its cells.
      dealii::types::material_id material_id = 0;
      /// Its name in messages ("body 1", "the body").
      std::string name;
      /// The parameter that gives its Young's modulus.
      std::string modulus_parameter;
      /// Its Young's modulus.
      double youngs_modulus = 1;
    };

    /// The range of $E$ and of $E$ times the size of a body that the
    /// finite-strain paths accept: Newton's residual norms and the Cauchy
    /// stress norms square forces and stresses of these orders, and the
    /// squares must stay within double precision with room for sums.
    constexpr double min_force_scale = 1e-100;
    /// See min_force_scale.
    constexpr double max_force_scale = 1e100;
    /// At finite strain, nonzero loads on a body below this times its
    /// Young's modulus times its size are refused: Newton's residual floor
    /// (1e-12 E times the size) would take them for none.
    constexpr double min_load_ratio = 1e-10;

    /**
     * Throw, naming the body, its modulus parameter and 'Boundary conditions
     * and loads', if the load vector @p f (unconstrained, on the DoFs of
     * @p dof_handler; @p when says at which time, "at t = 1") is not finite
     * on a body's DoFs, or if the sum of the magnitudes of its entries on a
     * body exceeds BoundaryConditionParameters::max_displacement_ratio
     * times the body's Young's modulus times its size (the diagonal of the
     * bounding box of its cells): the body would move by more than that
     * many times its size, beyond any model, and the solve would overflow
     * or fail for reasons that name neither. With @p finite_strain, first
     * throw if a body's modulus, or its modulus times its size, lies
     * outside [min_force_scale, max_force_scale], and throw if its nonzero
     * loads lie below min_load_ratio times its modulus times its size. A problem scaled as a
     * whole (the moduli and the loads by one factor) keeps its strains and
     * passes or fails alike.
     */
    void
    check(const VEMDoFHandler<2>       &dof_handler,
          const dealii::Vector<double> &f,
          const std::vector<Body>      &bodies,
          const std::string            &when,
          const bool                    finite_strain);
  } // namespace ScaleCheck

} // namespace dealvem

#endif
