// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Shared pieces of the finite-strain tests: a homogeneous deformation
// u = (F - I) X + c as a Function, its nominal traction P N on a side of
// the unit square, a one-material library, and a finite-strain solve
// with Dirichlet data on boundary ids.
#ifndef dealvem_tests_finite_strain_common_h
#define dealvem_tests_finite_strain_common_h

#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/finite_strain_solver.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <map>
#include <memory>
#include <set>

namespace testing
{
  /// u(X) = (F - I) X + c.
  class HomogeneousDeformation : public dealii::Function<2>
  {
  public:
    HomogeneousDeformation(const dealii::Tensor<2, 2> &F, const dealii::Tensor<1, 2> &c = {})
      : dealii::Function<2>(2)
      , F(F)
      , c(c)
    {}
    double
    value(const dealii::Point<2> &p, const unsigned int comp) const override
    {
      return F[comp][0] * p[0] + F[comp][1] * p[1] - p[comp] + c[comp];
    }
    dealii::Tensor<2, 2> F;
    dealii::Tensor<1, 2> c;
  };

  /// The constant nominal traction P N (2 components).
  class ConstantTraction : public dealii::Function<2>
  {
  public:
    explicit ConstantTraction(const dealii::Tensor<1, 2> &t)
      : dealii::Function<2>(2)
      , t(t)
    {}
    double
    value(const dealii::Point<2> &, const unsigned int comp) const override
    {
      return t[comp];
    }
    dealii::Tensor<1, 2> t;
  };

  /// One law for every material id of the mesh of @p dof_handler.
  inline dealvem::MaterialLibrary<2>
  one_law_library(const dealvem::VEMDoFHandler<2> &dof_handler, const dealvem::ConstitutiveLaw<2> &law)
  {
    dealvem::MaterialLibrary<2> laws;
    std::shared_ptr<const dealvem::ConstitutiveLaw<2>> shared(law.clone().release());
    for (const auto id : dof_handler.get_mesh().get_material_ids())
      laws.add(id, shared);
    return laws;
  }

  /// The closed constraints of Dirichlet data @p g (full load) on the
  /// boundary ids @p ids.
  inline void
  dirichlet_constraints(const dealvem::VEMDoFHandler<2>          &dof_handler,
                        const std::set<dealii::types::boundary_id> &ids,
                        const dealii::Function<2>                  &g,
                        dealii::AffineConstraints<double>          &constraints)
  {
    constraints.clear();
    dealvem::BoundaryConditions::interpolate_boundary_values(dof_handler, ids, g, {{true, true}}, constraints);
    constraints.close();
  }
} // namespace testing

#endif
