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
   * - Point constraints: `x, y : component : value; ...` (the mesh vertex
   *   at (x, y); component x or y)
   * - Body force: `fx, fy` (empty: none)
   * Every malformed entry gives an error naming the parameter and the entry.
   */
  class BoundaryConditionParameters
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Write all constraints (Dirichlet first, then rollers, then points).
    void
    apply_constraints(const VEMDoFHandler<2> &dof_handler,
                      dealii::AffineConstraints<double> &constraints) const;

    /// Hand the loads to an assembler (the functions live in this object).
    void
    add_loads(ElasticityAssembler<2> &assembler) const;

    const std::map<std::string, double> &
    get_constants() const
    {
      return constants;
    }

    /// The boundary ids used by any condition or load.
    std::set<dealii::types::boundary_id>
    used_boundary_ids() const;

  private:
    struct Dirichlet
    {
      dealii::types::boundary_id                   id;
      std::array<bool, 2>                          mask;
      std::unique_ptr<InputParsing::ParsedFunction> function;
    };
    struct Load
    {
      dealii::types::boundary_id                   id;
      std::unique_ptr<InputParsing::ParsedFunction> function;
    };
    struct PointConstraint
    {
      dealii::Point<2> point;
      unsigned int     component;
      double           value;
    };

    std::map<std::string, double>                  constants;
    std::vector<Dirichlet>                         dirichlet;
    std::vector<dealii::types::boundary_id>        rollers;
    std::vector<Load>                              tractions, pressures;
    std::vector<PointConstraint>                   points;
    std::unique_ptr<InputParsing::ParsedFunction>  body_force;
  };
} // namespace dealvem

#endif
