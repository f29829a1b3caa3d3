// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/vem/vem_values.h>

#include <cctype>
#include <cmath>
#include <string>

namespace dealvem
{
  std::string
  pressure_load_name(const PressureLoad kind)
  {
    return kind == PressureLoad::dead ? "dead" : "follower";
  }



  PressureLoad
  parse_pressure_load(const std::string &value, const std::string &parameter)
  {
    std::string v;
    for (const char c : value)
      v += char(std::tolower(static_cast<unsigned char>(c)));
    const auto first = v.find_first_not_of(" \t");
    const auto last  = v.find_last_not_of(" \t");
    v                = (first == std::string::npos ? std::string() : v.substr(first, last - first + 1));
    if (v == "dead")
      return PressureLoad::dead;
    if (v == "follower")
      return PressureLoad::follower;
    AssertThrow(false, dealii::ExcMessage("Parameter '" + parameter + "' = '" + value +
                                          "' is not a kind of pressure load: use 'follower' (the pressure acts "
                                          "on the deformed boundary, along its current normal) or 'dead' (the "
                                          "nominal traction -p N on the undeformed boundary)."));
    return PressureLoad::follower;
  }



  template <int dim>
  FiniteStrainAssembler<dim>::FiniteStrainAssembler(const VEMDoFHandler<dim>   &dof_handler,
                                                    const MaterialLibrary<dim> &laws,
                                                    const double                gamma,
                                                    const Stabilization         stabilization,
                                                    const StabilizationScaling  scaling)
    : dof_handler(dof_handler)
    , laws(laws)
    , loads(dof_handler, laws, gamma, stabilization)
    , gamma(gamma)
    , stabilization(stabilization == Stabilization::automatic ? Stabilization::trace : stabilization)
    , scaling(scaling)
  {
    for (const auto &l : laws.get_laws())
      AssertThrow(l.second->has_finite_strain_response(),
                  dealii::ExcMessage("FiniteStrainAssembler: the constitutive law '" + l.second->get_name() +
                                     "' of material id " + std::to_string(l.first) +
                                     " has no finite-strain response (first Piola-Kirchhoff stress and "
                                     "tangent); use NeoHookeMaterial or SaintVenantKirchhoffMaterial."));
    for (const auto id : dof_handler.get_mesh().get_material_ids())
      AssertThrow(laws.has_law(id),
                  dealii::ExcMessage("FiniteStrainAssembler: the mesh has cells of material id " +
                                     std::to_string(id) + ", for which the library has no law."));
    freeze_stabilization(dealii::Vector<double>(dof_handler.n_dofs()));
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::set_body_force(const dealii::Function<dim> &f)
  {
    loads.set_body_force(f);
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::add_traction(const dealii::types::boundary_id id, const dealii::Function<dim> &g)
  {
    loads.add_traction(id, g);
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::add_pressure(const dealii::types::boundary_id id,
                                           const dealii::Function<dim>     &p,
                                           const PressureLoad               kind)
  {
    AssertThrow(p.n_components == 1,
                dealii::ExcMessage("FiniteStrainAssembler::add_pressure(): a pressure must be a scalar function "
                                   "(boundary id " + std::to_string(int(id)) + ")."));
    if (kind == PressureLoad::dead)
      loads.add_pressure(id, p);
    else
      follower_pressures.emplace_back(id, &p);
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::add_follower_loads(const VEMValues<dim>         &vem_values,
                                                 const dealii::Vector<double> &local_u,
                                                 const double                  factor,
                                                 dealii::Vector<double>       &F,
                                                 dealii::FullMatrix<double>   *K) const
  {
    if (follower_pressures.empty())
      return;
    dealii::Vector<double>     Fp;
    dealii::FullMatrix<double> Kp;
    for (unsigned int e = 0; e < vem_values.n_edges(); ++e)
      {
        const dealii::types::boundary_id id = vem_values.edge_boundary_id(e);
        if (id == dealii::numbers::internal_face_boundary_id)
          continue;
        for (const auto &p : follower_pressures)
          if (p.first == id)
            {
              Fp.reinit(F.size());
              if (K != nullptr)
                Kp.reinit(F.size(), F.size());
              vem_values.get_element().add_edge_follower_pressure(e, *p.second, local_u, Fp,
                                                                  K != nullptr ? &Kp : nullptr);
              F.add(factor, Fp);
              if (K != nullptr)
                K->add(-factor, Kp);
            }
      }
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::assemble_load_vector(dealii::Vector<double> &f_ext) const
  {
    loads.assemble_load_vector(f_ext);
    if (follower_pressures.empty())
      return;
    // the follower pressures in the reference configuration
    VEMValues<dim>         vem_values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values);
    dealii::Vector<double> local_u, F;
    for (unsigned int c = 0; c < dof_handler.get_mesh().n_cells(); ++c)
      {
        vem_values.reinit(c);
        const auto &indices = vem_values.get_dof_indices();
        local_u.reinit(indices.size());
        F.reinit(indices.size());
        add_follower_loads(vem_values, local_u, 1., F, nullptr);
        for (unsigned int i = 0; i < indices.size(); ++i)
          f_ext[indices[i]] += F[i];
      }
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::freeze_stabilization(const dealii::Vector<double> &u)
  {
    AssertThrow(u.size() == dof_handler.n_dofs(),
                dealii::ExcMessage("FiniteStrainAssembler::freeze_stabilization(): the displacement has " +
                                   std::to_string(u.size()) + " entries, not n_dofs() = " +
                                   std::to_string(dof_handler.n_dofs()) + "."));
    const unsigned int n_cells = dof_handler.get_mesh().n_cells();
    stabilization_matrices.resize(n_cells);
    VEMValues<dim>            vem_values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values);
    FiniteStrainOperator<dim> op;
    dealii::Vector<double>    local_u;
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        vem_values.reinit(c);
        op.reinit(vem_values);
        dof_handler.get_dof_values(c, u, local_u);
        op.compute_stabilization(vem_values.get_element(), loads.get_law(c), local_u, gamma, stabilization,
                                 scaling, stabilization_matrices[c]);
      }
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::assemble(const dealii::Vector<double>            &u,
                                       const double                             load_factor,
                                       dealii::Vector<double>                  &residual,
                                       const dealii::AffineConstraints<double> &constraints,
                                       dealii::SparseMatrix<double>            *tangent,
                                       dealii::Vector<double>                  *rhs) const
  {
    const auto n = dof_handler.n_dofs();
    AssertThrow(u.size() == n,
                dealii::ExcMessage("FiniteStrainAssembler::assemble(): the displacement has " +
                                   std::to_string(u.size()) + " entries, not n_dofs() = " + std::to_string(n) +
                                   "."));
    AssertThrow(std::isfinite(load_factor),
                dealii::ExcMessage("FiniteStrainAssembler::assemble(): the load factor is not finite."));
    AssertThrow(stabilization_matrices.size() == dof_handler.get_mesh().n_cells(),
                dealii::ExcMessage("FiniteStrainAssembler::assemble(): the mesh changed since the "
                                   "stabilization was frozen; call freeze_stabilization() again."));
    residual.reinit(n);
    if (tangent != nullptr)
      {
        AssertThrow(rhs != nullptr && tangent->m() >= n && tangent->m() == tangent->n(),
                    dealii::ExcMessage("FiniteStrainAssembler::assemble(): the tangent needs a right-hand side "
                                       "vector and at least n_dofs() rows (square)."));
        *tangent = 0;
        rhs->reinit(tangent->m());
      }
    VEMValues<dim>            vem_values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values);
    FiniteStrainOperator<dim> op;
    dealii::Vector<double>    local_u, r_c, F, Ksu;
    dealii::FullMatrix<double> K;
    for (unsigned int c = 0; c < dof_handler.get_mesh().n_cells(); ++c)
      {
        vem_values.reinit(c);
        op.reinit(vem_values);
        dof_handler.get_dof_values(c, u, local_u);
        op.compute_consistency(loads.get_law(c), local_u, tangent != nullptr, r_c, K);
        const dealii::FullMatrix<double> &K_s = stabilization_matrices[c];
        AssertThrow(K_s.m() == local_u.size(),
                    dealii::ExcMessage("FiniteStrainAssembler::assemble(): the stabilization of cell " +
                                       std::to_string(c) + " does not match its DoFs; call "
                                       "freeze_stabilization() again after changing the mesh."));
        Ksu.reinit(local_u.size());
        K_s.vmult(Ksu, local_u);
        loads.local_load(vem_values, F);
        // F <- load_factor F - (r_c + K_s u): the cell's residual
        F *= load_factor;
        F -= r_c;
        F -= Ksu;
        // the follower pressures at the current edge positions, and their
        // derivative (K = K_c - load_factor dF_p/du)
        add_follower_loads(vem_values, local_u, load_factor, F, tangent != nullptr ? &K : nullptr);
        const auto &indices = vem_values.get_dof_indices();
        for (unsigned int i = 0; i < indices.size(); ++i)
          residual[indices[i]] += F[i];
        if (tangent != nullptr)
          {
            K.add(1., K_s);
            constraints.distribute_local_to_global(K, F, indices, *tangent, *rhs);
          }
      }
  }



  template <int dim>
  double
  FiniteStrainAssembler<dim>::strain_energy(const dealii::Vector<double> &u) const
  {
    AssertThrow(u.size() == dof_handler.n_dofs(),
                dealii::ExcMessage("FiniteStrainAssembler::strain_energy(): the displacement has " +
                                   std::to_string(u.size()) + " entries, not n_dofs() = " +
                                   std::to_string(dof_handler.n_dofs()) + "."));
    AssertThrow(stabilization_matrices.size() == dof_handler.get_mesh().n_cells(),
                dealii::ExcMessage("FiniteStrainAssembler::strain_energy(): the stabilization is not frozen for "
                                   "this mesh; call freeze_stabilization() first."));
    VEMValues<dim>            vem_values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values);
    FiniteStrainOperator<dim> op;
    dealii::Vector<double>    local_u, Ksu;
    double                    energy = 0;
    for (unsigned int c = 0; c < dof_handler.get_mesh().n_cells(); ++c)
      {
        vem_values.reinit(c);
        op.reinit(vem_values);
        dof_handler.get_dof_values(c, u, local_u);
        energy += op.strain_energy(loads.get_law(c), local_u);
        Ksu.reinit(local_u.size());
        stabilization_matrices[c].vmult(Ksu, local_u);
        energy += 0.5 * (local_u * Ksu);
      }
    return energy;
  }



  template class FiniteStrainAssembler<2>;
} // namespace dealvem
