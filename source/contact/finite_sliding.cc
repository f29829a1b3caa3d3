// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// FiniteSliding: construction, the public interface (it forwards to the
// state, FiniteSliding::Impl), the evaluation of a converged step and its
// nodal forces.

#include "finite_sliding_impl.h"

#include <dealvem/vem/vem_element_data.h>

namespace dealvem
{
  using namespace internal::finite_sliding;

  NodeInsertion::Settings
  FiniteSliding::Parameters::default_insertion()
  {
    NodeInsertion::Settings s;
    s.merge_fraction            = 1e-9;
    s.close_discretisation_gaps = false;
    s.allow_no_pairs            = true;
    return s;
  }



  FiniteSliding::Impl::Discretization::~Discretization()
  {
    dof_handler.reset();
    mesh.reset();
  }



  FiniteSliding::Impl::Impl(const PolygonalMesh<2>           &mesh_in,
                            const MaterialLibrary<2>         &laws,
                            const std::vector<InterfaceData> &interfaces_in,
                            const Parameters                 &parameters_in)
    : original(mesh_in)
    , laws(laws)
    , interface_data(interfaces_in)
    , parameters(parameters_in)
  {
    AssertThrow(!interface_data.empty() || parameters.detection.enabled,
                dealii::ExcMessage("FiniteSliding: no contact interface given, and no detection."));
    // node insertion pairs at most one node inside an edge
    AssertThrow(parameters.degree >= 1 && VEMElementData(parameters.degree).nodes_per_edge() <= 1,
                dealii::ExcMessage("FiniteSliding: the degree must be 1 or 2 (at most one node inside an edge), "
                                   "not " +
                                   std::to_string(parameters.degree) + "."));
    AssertThrow(std::isfinite(parameters.complementarity_constant) && parameters.complementarity_constant >= 0,
                dealii::ExcMessage("FiniteSliding: the complementarity constant must be positive (or 0 for the "
                                   "default rule)."));
    AssertThrow(std::isfinite(parameters.pairing_tolerance) && parameters.pairing_tolerance > 0,
                dealii::ExcMessage("FiniteSliding: the pairing tolerance must be positive."));
    AssertThrow(parameters.max_pairing_passes >= 1,
                dealii::ExcMessage("FiniteSliding: max_pairing_passes must be at least 1."));
    std::set<dealii::types::boundary_id> ids;
    for (unsigned int i = 0; i < interface_data.size(); ++i)
      {
        const double mu = interface_data[i].friction_coefficient;
        AssertThrow(std::isfinite(mu) && mu >= 0,
                    dealii::ExcMessage("FiniteSliding: interface " + std::to_string(i) +
                                       " has the friction coefficient " + std::to_string(mu) +
                                       "; it must be finite and not negative."));
        AssertThrow(mu == 0 || parameters.normal == ContactSettings::Normal::unilateral,
                    dealii::ExcMessage("FiniteSliding: interface " + std::to_string(i) +
                                       " has friction, but the contact is tied."));
        ids.insert(interface_data[i].master_id);
        ids.insert(interface_data[i].slave_id);
        reported.push_back({false, interface_data[i].master_id, interface_data[i].slave_id, 0, 0});
      }
    if (parameters.detection.enabled)
      {
        const auto &d = parameters.detection;
        for (const auto id : d.candidate_ids)
          AssertThrow(ids.count(id) == 0,
                      dealii::ExcMessage("FiniteSliding: the boundary id " + std::to_string(int(id)) +
                                         " is a side of a given interface and a candidate of the detection."));
        // the bodies with candidate edges, and every pair of them
        std::set<unsigned int> bodies;
        for (unsigned int e = 0; e < original.n_edges(); ++e)
          if (original.edge(e).at_boundary() && d.candidate_ids.count(original.edge(e).boundary_id) > 0)
            bodies.insert(original.cell(original.edge(e).cells[0]).material_id);
        for (auto a = bodies.begin(), a_end = bodies.end(); a != a_end; ++a)
          for (auto b = std::next(a); b != bodies.end(); ++b)
            reported.push_back({true, 0, 0, *a, *b});
        AssertThrow(original.n_edges() == 0 || ContactDetection::first_free_id(original) < 65535,
                    dealii::ExcMessage("FiniteSliding: no boundary id is left for detected interfaces."));
        ids.insert(d.candidate_ids.begin(), d.candidate_ids.end());
      }
    for (unsigned int e = 0; e < original.n_edges(); ++e)
      {
        const auto &edge = original.edge(e);
        if (edge.at_boundary() && ids.count(edge.boundary_id) > 0)
          {
            interface_edges.push_back({{edge.vertices[0], edge.vertices[1], edge.cells[0]}});
            side_neighbours[edge.vertices[0]].push_back(edge.vertices[1]);
            side_neighbours[edge.vertices[1]].push_back(edge.vertices[0]);
            edge_ids[edge_key(edge.vertices[0], edge.vertices[1])] = edge.boundary_id;
          }
      }
    // the vertices of each side, and those on a straight run of one side
    std::map<dealii::types::boundary_id, std::vector<unsigned int>> by_id;
    for (const auto &[v, around] : side_neighbours)
      {
        std::set<dealii::types::boundary_id> own;
        for (const unsigned int w : around)
          own.insert(edge_ids.at(edge_key(v, w)));
        for (const auto id : own)
          by_id[id].push_back(v);
        if (around.size() != 2 || own.size() != 1)
          continue;
        const dealii::Tensor<1, 2> d0 = original.vertex(v) - original.vertex(around[0]);
        const dealii::Tensor<1, 2> d1 = original.vertex(around[1]) - original.vertex(v);
        if (d0 * d1 > 0 && std::abs(d0[0] * d1[1] - d0[1] * d1[0]) <= 1e-12 * d0.norm() * d1.norm())
          movable.insert(v);
      }
    for (const auto &i : interface_data)
      given_sides.push_back({by_id[i.master_id], by_id[i.slave_id]});
    // the arcs of the curved parts, as node insertion sees them in the
    // reference configuration
    for (const auto id : ids)
      for (const auto &[e, kappa] : NodeInsertion::edge_curvatures(original, id))
        arc_kappa[edge_key(original.edge(e).vertices[0], original.edge(e).vertices[1])] = kappa;
    if (parameters.complementarity_constant == 0)
      parameters.complementarity_constant =
        this->laws.min_characteristic_stiffness() / original.cell_diameter_range().first;
    parameters.newton.scale_prescribed_motion = false;
    parameters.newton.check_fixed_pairs       = !parameters.reinsert;
    if (parameters.normal == ContactSettings::Normal::tied)
      parameters.reinsert = false;
  }



  FiniteSliding::Impl::~Impl()
  {
    // the solver and the contact refer to the assembler and the DoF
    // handler, which refers to the mesh
    solver.reset();
    contact.reset();
    assembler.reset();
    current.reset();
    start.reset();
  }



  FiniteSliding::FiniteSliding(const PolygonalMesh<2>           &mesh,
                               const MaterialLibrary<2>         &laws,
                               const std::vector<InterfaceData> &interfaces,
                               const Parameters                 &parameters)
    : impl(std::make_unique<Impl>(mesh, laws, interfaces, parameters))
  {}



  FiniteSliding::~FiniteSliding() = default;



  void
  FiniteSliding::set_constraints_function(const ConstraintsFunction &f)
  {
    impl->set_constraints_function(f);
  }



  void
  FiniteSliding::set_loads(const LoadsFunction &f, const std::function<double(double)> &load_factor)
  {
    impl->set_loads(f, load_factor);
  }



  void
  FiniteSliding::solve_step(const unsigned int step, const double time)
  {
    impl->solve_step(step, time);
  }



  void
  FiniteSliding::run(const unsigned int n_steps, const double t0, const double t1)
  {
    impl->run(n_steps, t0, t1);
  }



  const PolygonalMesh<2> &
  FiniteSliding::get_mesh() const
  {
    return impl->get_mesh();
  }



  const PolygonalMesh<2> &
  FiniteSliding::get_original_mesh() const
  {
    return impl->original;
  }



  const VEMDoFHandler<2> &
  FiniteSliding::get_dof_handler() const
  {
    return impl->get_dof_handler();
  }



  const dealii::Vector<double> &
  FiniteSliding::get_solution() const
  {
    return impl->get_solution();
  }



  const dealii::Vector<double> &
  FiniteSliding::get_multipliers() const
  {
    return impl->get_multipliers();
  }



  const FiniteStrainContact &
  FiniteSliding::get_contact() const
  {
    return impl->get_contact();
  }



  const std::vector<NodeInsertion::Interface> &
  FiniteSliding::get_interfaces() const
  {
    return impl->interfaces;
  }



  const std::vector<FiniteSliding::ReportedInterface> &
  FiniteSliding::get_reported_interfaces() const
  {
    return impl->reported;
  }



  unsigned int
  FiniteSliding::reported_interface(const unsigned int pair_interface) const
  {
    return impl->pass_interfaces.at(pair_interface).reported;
  }



  double
  FiniteSliding::reported_sign(const unsigned int pair_interface) const
  {
    return impl->reported_sign(pair_interface);
  }



  double
  FiniteSliding::Impl::reported_sign(const unsigned int pair_interface) const
  {
    const auto &p = pass_interfaces.at(pair_interface);
    return reported.at(p.reported).detected && p.slave_body != reported.at(p.reported).body_b ? -1. : 1.;
  }



  const std::vector<FiniteSliding::StepRecord> &
  FiniteSliding::get_history() const
  {
    return impl->history;
  }



  double
  FiniteSliding::strain_energy() const
  {
    return impl->strain_energy();
  }



  FiniteSliding::NodalForces
  FiniteSliding::nodal_forces() const
  {
    return impl->nodal_forces();
  }



  const dealii::AffineConstraints<double> &
  FiniteSliding::get_constraints() const
  {
    return impl->get_constraints();
  }



  void
  FiniteSliding::Impl::set_constraints_function(const ConstraintsFunction &f)
  {
    constraints_function = f;
  }



  void
  FiniteSliding::Impl::set_loads(const LoadsFunction &f, const std::function<double(double)> &load_factor)
  {
    loads_function       = f;
    load_factor_function = load_factor;
  }



  const PolygonalMesh<2> &
  FiniteSliding::Impl::get_mesh() const
  {
    AssertThrow(current != nullptr, dealii::ExcMessage("FiniteSliding: no step has been solved yet."));
    return *current->mesh;
  }



  const VEMDoFHandler<2> &
  FiniteSliding::Impl::get_dof_handler() const
  {
    AssertThrow(current != nullptr, dealii::ExcMessage("FiniteSliding: no step has been solved yet."));
    return *current->dof_handler;
  }



  const dealii::Vector<double> &
  FiniteSliding::Impl::get_solution() const
  {
    return solution;
  }



  const dealii::Vector<double> &
  FiniteSliding::Impl::get_multipliers() const
  {
    return multipliers;
  }



  double
  FiniteSliding::Impl::strain_energy() const
  {
    AssertThrow(assembler != nullptr && !last_failed,
                dealii::ExcMessage("FiniteSliding::strain_energy(): no step has converged yet."));
    return assembler->strain_energy(solution);
  }



  const FiniteStrainContact &
  FiniteSliding::Impl::get_contact() const
  {
    AssertThrow(contact != nullptr, dealii::ExcMessage("FiniteSliding: no step has been solved yet."));
    return *contact;
  }



  const dealii::AffineConstraints<double> &
  FiniteSliding::Impl::get_constraints() const
  {
    return constraints;
  }



  void
  FiniteSliding::Impl::run(const unsigned int n_steps, const double t0, const double t1)
  {
    const unsigned int first = last_step + 1;
    for (unsigned int i = 1; i <= n_steps; ++i)
      solve_step(first + i - 1, t0 + (t1 - t0) * i / n_steps);
  }



  void
  FiniteSliding::Impl::evaluate(StepRecord &record) const
  {
    const auto np = contact->n_pairs();
    const auto n0 = original.n_vertices();
    record.normal_force.assign(reported.size(), dealii::Tensor<1, 2>());
    record.friction_force.assign(reported.size(), dealii::Tensor<1, 2>());
    record.n_detected  = pass_interfaces.size() - interface_data.size();
    record.n_uncovered = uncovered_edges();
    record.n_active = record.n_slipping = record.n_new_contacts = record.n_sticking_in_contact = 0;
    record.max_slip = record.pairing_offset = record.merged_offset = record.dissipation = 0;
    record.n_merged                         = 0;
    // at each pair, the shortest current slave sub-edge (for the slip) and
    // the length of the sub-edges it touches (the chord over which its
    // normal turns: the scale of the pairing offset)
    std::vector<double> h(np, std::numeric_limits<double>::max()), chord(np, 0.);
    unsigned int        offset = 0;
    for (const auto &interface : interfaces)
      {
        for (const auto &s : interface.segments)
          {
            const double L = contact->current_positions(offset + s.first, solution)[1].distance(
              contact->current_positions(offset + s.second, solution)[1]);
            for (const unsigned int p : {s.first, s.second, s.midpoint})
              if (p != dealii::numbers::invalid_unsigned_int)
                {
                  h[offset + p] = std::min(h[offset + p], L);
                  chord[offset + p] += L;
                }
          }
        offset += interface.pairs.size();
      }
    const bool two = (contact->n_constraints() == 2 * np);
    for (unsigned int i = 0; i < np; ++i)
      {
        if (contact->is_left_out(i))
          continue;
        const auto interface = pass_interfaces[contact->get_pairs()[i].interface].reported;
        const auto n         = reported_sign(contact->get_pairs()[i].interface) * contact->current_normal(i, solution);
        const auto t         = turn_left(n);
        const bool active    = multipliers[i] != 0;
        if (active && contact->is_new_contact(i))
          ++record.n_new_contacts;
        if (active)
          {
            record.normal_force[interface] -= multipliers[i] * n;
            ++record.n_active;
            // (midpoint pairs of k = 2 on a curved interface are apart by
            // the difference of the two sides' parametrizations, O(h^3))
            const auto   x   = contact->current_positions(i, solution);
            const double off = std::abs((x[1] - x[0]) * t);
            const auto &pair   = contact->get_pairs()[i];
            // (two vertices of the original mesh: a merge, Parameters::
            // insertion's merge_fraction)
            if (chord[i] > 0 && !pair.on_edge() && pair.master_entity < n0 && pair.slave_entity < n0)
              {
                ++record.n_merged;
                record.merged_offset = std::max(record.merged_offset, off / chord[i]);
              }
            else if (chord[i] > 0 && !pair.on_edge())
              {
                record.pairing_offset = std::max(record.pairing_offset, off / chord[i]);
              }
          }
        else if (chord[i] > 0 && !contact->get_pairs()[i].on_edge())
          {
            // An open pair: its partners need only be opposite each other
            // within its gap. One whose partners slid apart by more than the
            // gap may no longer see the other side where it is (a bore
            // turned by a large step, paired where a linear prediction put
            // it, came out with every pair open and the bodies overlapping):
            // it counts in the pairing offset, and the step makes its pairs
            // again. What counts is the sliding within the pass: the
            // tangential distance the partners had where the pairs were made
            // is taken off. (A vertex whose partner is a kink of a coarse
            // polygon is paired at a slant, and pairing again makes the same
            // pair: on a gear flank beyond its graded band, partners 0.0156
            // apart at 46 degrees to the normal held the offset at 0.0039 in
            // every pass, and the step failed at every cut-back.)
            const auto   x   = contact->current_positions(i, solution);
            const double off = std::abs((x[1] - x[0]) * t);
            const double gap = contact->value(i, solution);
            double       off_paired = 0;
            if (pairing_base.size() == solution.size())
              {
                const auto xb = contact->current_positions(i, pairing_base);
                const auto nb = reported_sign(contact->get_pairs()[i].interface) * contact->current_normal(i, pairing_base);
                off_paired    = std::abs((xb[1] - xb[0]) * turn_left(nb));
              }
            record.pairing_offset =
              std::max(record.pairing_offset, std::max(0., off - off_paired - std::max(gap, 0.)) / chord[i]);
          }
        if (two)
          {
            const double lt = multipliers[np + i];
            record.friction_force[interface] -= lt * t;
            if (contact->is_frictional() && active && lt != 0 &&
                std::abs(lt) >= contact->friction_coefficient(i) * std::abs(multipliers[i]) * (1 - 1e-9))
              ++record.n_slipping;
            else if (contact->is_frictional() && active && !contact->is_new_contact(i))
              ++record.n_sticking_in_contact;
            if (contact->is_frictional())
              record.dissipation += std::abs(lt * contact->value(np + i, solution));
            if (contact->is_frictional() && h[i] < std::numeric_limits<double>::max())
              record.max_slip = std::max(record.max_slip, std::abs(contact->value(np + i, solution)) / h[i]);
          }
      }
  }



  std::vector<std::pair<unsigned int, unsigned int>>
  FiniteSliding::Impl::loose_merges() const
  {
    std::vector<std::pair<unsigned int, unsigned int>> loose;
    const auto                                         np = contact->n_pairs();
    const auto                                         n0 = original.n_vertices();
    // the two sub-edges at each vertex pair, as evaluate() measures them
    std::vector<double> chord(np, 0.);
    unsigned int        offset = 0;
    for (const auto &interface : interfaces)
      {
        for (const auto &s : interface.segments)
          {
            const double L = contact->current_positions(offset + s.first, solution)[1].distance(
              contact->current_positions(offset + s.second, solution)[1]);
            for (const unsigned int p : {s.first, s.second})
              chord[offset + p] += L;
          }
        offset += interface.pairs.size();
      }
    for (unsigned int i = 0; i < np; ++i)
      {
        const auto &pair = contact->get_pairs()[i];
        if (pair.on_edge() || pair.master_entity >= n0 || pair.slave_entity >= n0 || chord[i] <= 0 ||
            contact->is_left_out(i))
          continue;
        const std::pair<unsigned int, unsigned int> merge(pair.master_entity, pair.slave_entity);
        if (step_merges.count(merge) == 0 || step_reheld.count(merge) > 0)
          continue;
        const auto x = contact->current_positions(i, solution);
        const auto t = turn_left(contact->current_normal(i, solution));
        if (std::abs((x[1] - x[0]) * t) > 1e-3 * chord[i])
          loose.push_back(merge);
      }
    return loose;
  }



  FiniteSliding::NodalForces
  FiniteSliding::Impl::nodal_forces() const
  {
    AssertThrow(assembler != nullptr && contact != nullptr && n_converged > 0 && !last_failed,
                dealii::ExcMessage("FiniteSliding::nodal_forces(): no step has converged yet."));
    const unsigned int n = current->dof_handler->n_dofs();
    NodalForces        forces;
    // the residual lambda f_ext - f_int(u) at the load factors 0 and the
    // step's gives both parts
    dealii::Vector<double> residual(n);
    assembler->assemble(solution, 0., residual, constraints, nullptr, nullptr);
    forces.internal = residual;
    forces.internal *= -1.;
    assembler->assemble(solution, last_load_factor, residual, constraints, nullptr, nullptr);
    forces.external = residual;
    forces.external += forces.internal;
    forces.contact.reinit(n);
    FiniteStrainConstraints::Linearization lin;
    for (unsigned int j = 0; j < contact->n_constraints(); ++j)
      if (!contact->is_left_out(j) && multipliers[j] != 0)
        {
          contact->linearize(j, solution, lin, false);
          for (unsigned int k = 0; k < lin.dofs.size(); ++k)
            if (lin.dofs[k] < n)
              forces.contact[lin.dofs[k]] -= multipliers[j] * lin.gradient[k];
        }
    return forces;
  }
} // namespace dealvem
