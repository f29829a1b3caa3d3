// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_app_problem_setup_h
#define dealvem_app_problem_setup_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>

#include <dealvem/app/input_parsing.h>
#include <dealvem/elasticity/elasticity_assembler.h>
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
   * - Pressure: `id : p; ...` (positive pressure pushes into the body)
   * - Point constraints: `x, y : component : value; ...` or
   *   `x, y : component : value : body` (the mesh vertex at (x, y), of the
   *   cells with material id `body` if given; component x or y; the value
   *   is an expression evaluated at (x, y))
   * - Rigid boundary: `id : Fx, Fy; ...` or `id : Fx, Fy : M; ...` (the
   *   nodes on the boundary part move as one rigid body, loaded by the
   *   force (Fx, Fy) at the part's centroid and the moment M about it;
   *   the expressions are evaluated at the centroid)
   * - Body force: `fx, fy` (empty: none)
   *
   * Expressions are muparser expressions in x, y and t with the function
   * constants; t = 1 unless set_time() says otherwise (contact problems with
   * load steps, section "Load steps").
   * Every malformed entry gives an error naming the parameter and the entry;
   * so does an entry on a boundary id the mesh does not have
   * (check_boundary_ids()), an expression that is not finite where it is
   * evaluated, and a constraint that conflicts with an earlier one.
   */
  class BoundaryConditionParameters
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

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
    /// entry.
    void
    apply_constraints(const VEMDoFHandler<2> &dof_handler,
                      dealii::AffineConstraints<double> &constraints) const;

    /// Hand the loads to an assembler (the functions live in this object);
    /// the resultants of rigid boundaries become nodal loads.
    void
    add_loads(ElasticityAssembler<2> &assembler) const;

    /**
     * Set the time t of every expression of this section (Dirichlet data,
     * loads, point constraints, rigid boundaries, body force). Load steps
     * call this before apply_constraints() and add_loads().
     */
    void
    set_time(const double t);

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
    struct Dirichlet
    {
      std::string                                   name;
      dealii::types::boundary_id                   id;
      std::array<bool, 2>                          mask;
      std::unique_ptr<InputParsing::ParsedFunction> function;
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
      std::unique_ptr<InputParsing::ParsedFunction> function;
    };
    struct PointConstraint
    {
      std::string                                   name;
      dealii::Point<2>                              point;
      unsigned int                                  component;
      std::unique_ptr<InputParsing::ParsedFunction> value;
      dealii::types::material_id                    body;
    };
    struct RigidBoundary
    {
      std::string                                   name;
      dealii::types::boundary_id                   id;
      std::unique_ptr<InputParsing::ParsedFunction> force;
      std::unique_ptr<InputParsing::ParsedFunction> moment;
    };

    std::map<std::string, double>                  constants;
    std::vector<Dirichlet>                         dirichlet;
    std::vector<Roller>                            rollers;
    std::vector<Load>                              tractions, pressures;
    std::vector<PointConstraint>                   points;
    std::vector<RigidBoundary>                     rigid_boundaries;
    std::unique_ptr<InputParsing::ParsedFunction>  body_force;
  };
} // namespace dealvem

#endif
