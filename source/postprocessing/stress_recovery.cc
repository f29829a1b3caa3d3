// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/vem/virtual_element.h>

namespace dealvem
{
  template <int dim>
  StressRecovery<dim>::StressRecovery(const VEMDoFHandler<dim>     &dof_handler,
                                      const MaterialLibrary<dim>   &laws,
                                      const dealii::Vector<double> &solution)
  {
    compute(dof_handler, laws, solution, nullptr);
  }



  template <int dim>
  StressRecovery<dim>::StressRecovery(const VEMDoFHandler<dim>        &dof_handler,
                                      const MaterialLibrary<dim>      &laws,
                                      const dealii::Vector<double>    &solution,
                                      const std::vector<unsigned int> &cells)
  {
    compute(dof_handler, laws, solution, &cells);
  }



  template <int dim>
  StressRecovery<dim>::StressRecovery(
    const VEMDoFHandler<dim>                                    &dof_handler,
    const std::map<dealii::types::material_id, ElasticMaterial> &materials,
    const dealii::Vector<double>                                &solution)
  {
    compute(dof_handler, MaterialLibrary<dim>(materials), solution, nullptr);
  }



  template <int dim>
  StressRecovery<dim>::StressRecovery(
    const VEMDoFHandler<dim>                                    &dof_handler,
    const std::map<dealii::types::material_id, ElasticMaterial> &materials,
    const dealii::Vector<double>                                &solution,
    const std::vector<unsigned int>                             &cells)
  {
    compute(dof_handler, MaterialLibrary<dim>(materials), solution, &cells);
  }



  template <int dim>
  void
  StressRecovery<dim>::compute(const VEMDoFHandler<dim>        &dof_handler,
                               const MaterialLibrary<dim>      &laws,
                               const dealii::Vector<double>    &solution,
                               const std::vector<unsigned int> *cells)
  {
    const auto        &mesh = dof_handler.get_mesh();
    const unsigned int k    = dof_handler.get_degree();
    strain.resize(mesh.n_cells());
    stress.resize(mesh.n_cells());
    von_mises.resize(mesh.n_cells());
    nodal_stress.assign(mesh.n_vertices(), dealii::SymmetricTensor<2, dim>());
    nodal_von_mises.assign(mesh.n_vertices(), 0.);
    std::vector<double>                          nodal_zz(mesh.n_vertices(), 0.);
    std::vector<unsigned int>                    count(mesh.n_vertices(), 0);
    VirtualElement<dim>                          element(k);
    dealii::Vector<double>                       local, coef;
    const unsigned int n_cells = cells ? cells->size() : mesh.n_cells();
    for (unsigned int i = 0; i < n_cells; ++i)
      {
        const unsigned int c  = cells ? (*cells)[i] : i;
        AssertThrow(laws.has_law(mesh.cell(c).material_id),
                    dealii::ExcMessage("StressRecovery: no material for material id " +
                                       std::to_string(mesh.cell(c).material_id) + " of cell " +
                                       std::to_string(c) + "."));
        const ConstitutiveLaw<dim> &material = laws.get_law(mesh.cell(c).material_id);
        element.reinit(mesh.cell_vertices(c));
        dof_handler.get_dof_values(c, solution, local);
        element.project(local, coef);
        // the strain of Pi u is linear for k = 2: its mean is the value at
        // the centroid
        const auto &geo = element.get_geometry();
        strain[c]       = element.projection_strain(coef, geo.centroid());
        stress[c]       = material.stress(strain[c]);
        von_mises[c]    = von_mises_stress(stress[c], material.stress_zz(strain[c]));
        const auto &loop = mesh.cell(c).vertices;
        for (unsigned int i = 0; i < loop.size(); ++i)
          {
            const auto eps = element.projection_strain(coef, geo.vertex(i));
            nodal_stress[loop[i]] += material.stress(eps);
            nodal_zz[loop[i]] += material.stress_zz(eps);
            ++count[loop[i]];
          }
      }
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      if (count[v] > 0)
        {
          nodal_stress[v] /= count[v];
          nodal_von_mises[v] = von_mises_stress(nodal_stress[v], nodal_zz[v] / count[v]);
        }
  }

  template class StressRecovery<2>;
} // namespace dealvem
