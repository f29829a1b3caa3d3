// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_postprocessing_stress_recovery_h
#define dealvem_postprocessing_stress_recovery_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/material.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <map>
#include <vector>

namespace dealvem
{
  /**
   * Strain and stress from the projection: in each cell the strain of
   * $\Pi_* u_h$ averaged over the cell (exact for the polynomial part, which
   * is all a virtual element knows inside a cell), the stress
   * $\sigma(\varepsilon)$ and the out-of-plane stress of the cell's
   * constitutive law (ConstitutiveLaw::stress(), ConstitutiveLaw::stress_zz();
   * any law, linear or not), and the von Mises stress; for plots, nodal values at the mesh vertices: the average over
   * the cells around a vertex of each cell's projected stress evaluated at
   * the vertex.
   */
  template <int dim>
  class StressRecovery
  {
  public:
    /// Compute on all cells, with the laws of @p laws.
    StressRecovery(const VEMDoFHandler<dim>     &dof_handler,
                   const MaterialLibrary<dim>   &laws,
                   const dealii::Vector<double> &solution);

    /// The same with one ElasticMaterial per material id.
    StressRecovery(const VEMDoFHandler<dim>                                    &dof_handler,
                   const std::map<dealii::types::material_id, ElasticMaterial> &materials,
                   const dealii::Vector<double>                                &solution);

    /**
     * The same on the cells @p cells only (increasing; for example the
     * locally owned and ghost cells of an MPI process, VEMPartition): the
     * values of other cells stay zero, and the nodal averages are taken
     * over the given cells around each vertex, so they are complete at the
     * vertices whose cells are all given. @p solution needs the entries of
     * the DoFs of these cells only.
     */
    StressRecovery(const VEMDoFHandler<dim>        &dof_handler,
                   const MaterialLibrary<dim>      &laws,
                   const dealii::Vector<double>    &solution,
                   const std::vector<unsigned int> &cells);

    /// The same with one ElasticMaterial per material id.
    StressRecovery(const VEMDoFHandler<dim>                                    &dof_handler,
                   const std::map<dealii::types::material_id, ElasticMaterial> &materials,
                   const dealii::Vector<double>                                &solution,
                   const std::vector<unsigned int>                             &cells);

    /// In-plane strain $\varepsilon(\Pi u_h)$ of cell @p c, averaged over
    /// the cell (dimensionless); zero for a cell that was not computed.
    const dealii::SymmetricTensor<2, dim> &
    cell_strain(const unsigned int c) const
    {
      return strain[c];
    }

    /// In-plane stress of cell @p c: the cell's law applied to
    /// cell_strain() (units of the law's moduli, e.g. Pa).
    const dealii::SymmetricTensor<2, dim> &
    cell_stress(const unsigned int c) const
    {
      return stress[c];
    }

    /// Von Mises stress of cell @p c from cell_stress() and the law's
    /// out-of-plane stress $\sigma_{zz}$.
    double
    cell_von_mises(const unsigned int c) const
    {
      return von_mises[c];
    }

    /// In-plane stress at mesh vertex @p v: the mean over the computed cells
    /// around it of each cell's stress evaluated at the vertex; zero at a
    /// vertex with no computed cell.
    const dealii::SymmetricTensor<2, dim> &
    vertex_stress(const unsigned int v) const
    {
      return nodal_stress[v];
    }

    /// Von Mises stress of the averaged vertex_stress() and averaged
    /// $\sigma_{zz}$ at mesh vertex @p v.
    double
    vertex_von_mises(const unsigned int v) const
    {
      return nodal_von_mises[v];
    }

  private:
    void
    compute(const VEMDoFHandler<dim>        &dof_handler,
            const MaterialLibrary<dim>      &laws,
            const dealii::Vector<double>    &solution,
            const std::vector<unsigned int> *cells);

    std::vector<dealii::SymmetricTensor<2, dim>> strain, stress, nodal_stress;
    std::vector<double>                          von_mises, nodal_von_mises;
  };
} // namespace dealvem

#endif
