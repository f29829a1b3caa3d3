// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/vem/virtual_element.h>

#include <cmath>
#include <string>

namespace dealvem
{
  template <int dim>
  ElasticityAssembler<dim>::ElasticityAssembler(
    const VEMDoFHandler<dim>                                    &dof_handler,
    const std::map<dealii::types::material_id, ElasticMaterial> &materials,
    const double                                                 gamma)
    : dof_handler(dof_handler)
    , materials(materials)
    , gamma(gamma)
  {
    AssertThrow(gamma > 0 && std::isfinite(gamma),
                dealii::ExcMessage("The stabilization factor gamma must be positive, got " +
                                   std::to_string(gamma) + "."));
  }



  template <int dim>
  void
  ElasticityAssembler<dim>::set_body_force(const dealii::Function<dim> &f)
  {
    AssertThrow(f.n_components == 2,
                dealii::ExcMessage("The body force must have 2 components."));
    body_force = &f;
  }



  template <int dim>
  void
  ElasticityAssembler<dim>::add_traction(const dealii::types::boundary_id id,
                                         const dealii::Function<dim>     &g)
  {
    AssertThrow(g.n_components == 2,
                dealii::ExcMessage("A traction must have 2 components (boundary id " +
                                   std::to_string(id) + ")."));
    tractions.emplace_back(id, &g);
  }



  template <int dim>
  void
  ElasticityAssembler<dim>::add_pressure(const dealii::types::boundary_id id,
                                         const dealii::Function<dim>     &p)
  {
    AssertThrow(p.n_components == 1,
                dealii::ExcMessage("A pressure must be a scalar function (boundary id " +
                                   std::to_string(id) + ")."));
    pressures.emplace_back(id, &p);
  }



  template <int dim>
  void
  ElasticityAssembler<dim>::add_nodal_load(const dealii::types::global_dof_index dof,
                                           const double                          value)
  {
    AssertThrow(dof < dof_handler.n_dofs(),
                dealii::ExcMessage("Nodal load on DoF " + std::to_string(dof) + ", but there are only " +
                                   std::to_string(dof_handler.n_dofs()) + " DoFs."));
    AssertThrow(std::isfinite(value),
                dealii::ExcMessage("Nodal load on DoF " + std::to_string(dof) + " is not finite."));
    nodal_loads.emplace_back(dof, value);
  }



  template <int dim>
  const ElasticMaterial &
  ElasticityAssembler<dim>::get_material(const unsigned int c) const
  {
    const auto id = dof_handler.get_mesh().cell(c).material_id;
    const auto it = materials.find(id);
    AssertThrow(it != materials.end(),
                dealii::ExcMessage("Cell " + std::to_string(c) + " of mesh '" +
                                   dof_handler.get_mesh().name + "' has material id " +
                                   std::to_string(id) + ", for which no material is defined."));
    return it->second;
  }



  template <int dim>
  void
  ElasticityAssembler<dim>::local_load(const unsigned int      c,
                                       const void             *element_ptr,
                                       dealii::Vector<double> &F) const
  {
    const auto &element = *static_cast<const VirtualElement<dim> *>(element_ptr);
    const auto &mesh    = dof_handler.get_mesh();
    const auto &cell    = mesh.cell(c);
    F.reinit(element.n_dofs_per_cell(cell.vertices.size()));
    if (body_force != nullptr)
      element.body_force_vector(*body_force, F);
    if (tractions.empty() && pressures.empty())
      return;
    for (unsigned int i = 0; i < cell.edges.size(); ++i)
      {
        const auto &edge = mesh.edge(cell.edges[i]);
        if (!edge.at_boundary())
          continue;
        for (const auto &t : tractions)
          if (t.first == edge.boundary_id)
            element.add_edge_traction(i, *t.second, F);
        for (const auto &p : pressures)
          if (p.first == edge.boundary_id)
            element.add_edge_pressure(i, *p.second, F);
      }
  }



  template <int dim>
  void
  ElasticityAssembler<dim>::assemble(const dealii::AffineConstraints<double> &constraints,
                                     dealii::SparseMatrix<double>            &matrix,
                                     dealii::Vector<double>                  &rhs) const
  {
    const auto &mesh = dof_handler.get_mesh();
    matrix           = 0;
    rhs.reinit(dof_handler.n_dofs());
    VirtualElement<dim>                          element(dof_handler.get_degree());
    element.set_cell_similarity(cell_similarity);
    std::vector<dealii::types::global_dof_index> indices;
    std::vector<dealii::Point<dim>>              vertices;
    dealii::Vector<double>                       F;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        mesh.cell_vertices(c, vertices);
        element.reinit(vertices, get_material(c), gamma);
        local_load(c, &element, F);
        dof_handler.get_dof_indices(c, indices);
        constraints.distribute_local_to_global(
          element.get_stiffness_matrix(), F, indices, matrix, rhs);
      }
    // nodal loads: a "cell" of their DoFs without matrix, so that loads on
    // constrained DoFs go to the DoFs they depend on
    if (!nodal_loads.empty())
      {
        indices.clear();
        F.reinit(nodal_loads.size());
        for (unsigned int i = 0; i < nodal_loads.size(); ++i)
          {
            indices.push_back(nodal_loads[i].first);
            F[i] = nodal_loads[i].second;
          }
        constraints.distribute_local_to_global(F, indices, rhs);
      }
  }



  template <int dim>
  void
  ElasticityAssembler<dim>::assemble_load_vector(dealii::Vector<double> &rhs) const
  {
    const auto &mesh = dof_handler.get_mesh();
    rhs.reinit(dof_handler.n_dofs());
    VirtualElement<dim>                          element(dof_handler.get_degree());
    element.set_cell_similarity(cell_similarity);
    std::vector<dealii::types::global_dof_index> indices;
    std::vector<dealii::Point<dim>>              vertices;
    dealii::Vector<double>                       F;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        mesh.cell_vertices(c, vertices);
        element.reinit(vertices, get_material(c), gamma);
        local_load(c, &element, F);
        dof_handler.get_dof_indices(c, indices);
        for (unsigned int i = 0; i < indices.size(); ++i)
          rhs[indices[i]] += F[i];
      }
    for (const auto &l : nodal_loads)
      rhs[l.first] += l.second;
  }

  template class ElasticityAssembler<2>;
} // namespace dealvem
