// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// FiniteSliding: the interfaces of a pass (the given ones and those the
// detection finds), the sides and their reference curves, the vertices
// snapped onto their partners, and the transfer of states between meshes.

#include "finite_sliding_impl.h"

namespace dealvem
{
  using namespace internal::finite_sliding;

  ContactDetection::Result
  FiniteSliding::Impl::detect_candidates(PolygonalMesh<2> &there, const double distance_factor) const
  {
    const auto                          &d = parameters.detection;
    std::set<dealii::types::boundary_id> excluded;
    for (const auto id : original.get_boundary_ids())
      if (d.candidate_ids.count(id) == 0)
        excluded.insert(id);
    ContactDetection::Settings settings = d.settings;
    settings.split_edges                = false;
    settings.distance *= distance_factor;
    return ContactDetection::detect(there, excluded, ContactDetection::first_free_id(original), settings);
  }



  std::vector<FiniteSliding::Impl::PassInterface>
  FiniteSliding::Impl::pass_interfaces_at(
    const std::vector<dealii::Point<2>>                                            &x,
    std::vector<dealii::types::boundary_id>                                        &edge_ids_there,
    std::vector<bool>                                                              &detected_there,
    std::vector<std::pair<std::vector<unsigned int>, std::vector<unsigned int>>> &sides) const
  {
    std::vector<PassInterface> pass;
    for (unsigned int i = 0; i < interface_data.size(); ++i)
      pass.push_back({interface_data[i].master_id, interface_data[i].slave_id,
                      interface_data[i].friction_coefficient, i});
    sides = given_sides;
    edge_ids_there.resize(original.n_edges());
    detected_there.assign(original.n_edges(), false);
    for (unsigned int e = 0; e < original.n_edges(); ++e)
      edge_ids_there[e] = original.edge(e).boundary_id;
    const auto &d = parameters.detection;
    if (!d.enabled)
      return pass;
    // the detection on a copy of M_0 at x: its edges keep their numbers
    // (no split), so their new ids apply to every copy of M_0
    PolygonalMesh<2> there(original);
    for (unsigned int v = 0; v < original.n_vertices(); ++v)
      there.move_vertex(v, x[v]);
    auto found = detect_candidates(there, 1.);
    // a pair of bodies keeps the master body of its first converged step
    // (the two sides swap their ids, which the edges carry by body)
    for (auto &itf : found.interfaces)
      {
        const auto key = std::minmax(itf.master_body, itf.slave_body);
        const auto it  = detected_master.find({key.first, key.second});
        if (it != detected_master.end() && it->second != itf.master_body)
          {
            std::swap(itf.master_body, itf.slave_body);
            std::swap(itf.master_id, itf.slave_id);
            std::swap(itf.n_master_edges, itf.n_slave_edges);
            std::swap(itf.master_h, itf.slave_h);
          }
      }
    for (unsigned int e = 0; e < there.n_edges(); ++e)
      if (there.edge(e).at_boundary() && there.edge(e).boundary_id != original.edge(e).boundary_id)
        {
          edge_ids_there[e] = there.edge(e).boundary_id;
          detected_there[e] = true;
        }
    // Each detected side grows along the candidate boundary of its body
    // to the next corner (a turn above the detection's corner angle), as a
    // side named by hand ends at the corners of a face: node insertion then
    // sees the same side whether the facing part is large or small, and the
    // vertex where a contact zone ends has both its edges on the side (its
    // normal and curvature from both). Two sides growing into each other
    // stop where they meet (an edge reached by both stays unlabelled).
    {
      std::map<unsigned int, std::vector<unsigned int>> at_vertex; // candidate boundary edges at a vertex
      for (unsigned int e = 0; e < there.n_edges(); ++e)
        if (there.edge(e).at_boundary() && d.candidate_ids.count(original.edge(e).boundary_id) > 0)
          for (const unsigned int v : there.edge(e).vertices)
            at_vertex[v].push_back(e);
      const auto normal = [&](const unsigned int e) {
        const auto          &ev = there.edge(e).vertices;
        dealii::Tensor<1, 2> t  = x[ev[1]] - x[ev[0]];
        dealii::Tensor<1, 2> n;
        n[0]           = t[1];
        n[1]           = -t[0];
        const double l = n.norm();
        return l > 0 ? n / l : n;
      };
      const double           cos_corner = std::cos(d.settings.corner_angle * M_PI / 180.);
      const auto             labelled   = [&](const unsigned int e) {
        return edge_ids_there[e] != original.edge(e).boundary_id;
      };
      std::vector<bool> blocked(original.n_edges(), false);
      std::vector<unsigned int> front;
      for (unsigned int e = 0; e < original.n_edges(); ++e)
        if (original.edge(e).at_boundary() && labelled(e))
          front.push_back(e);
      while (!front.empty())
        {
          std::map<unsigned int, std::set<dealii::types::boundary_id>> offered;
          for (const unsigned int e : front)
            for (const unsigned int v : there.edge(e).vertices)
              {
                const auto it = at_vertex.find(v);
                if (it == at_vertex.end() || it->second.size() != 2)
                  continue;
                const unsigned int f = it->second[0] == e ? it->second[1] : it->second[0];
                if (!labelled(f) && !blocked[f] && normal(e) * normal(f) >= cos_corner)
                  offered[f].insert(edge_ids_there[e]);
              }
          front.clear();
          for (const auto &[f, ids] : offered)
            if (ids.size() == 1)
              {
                edge_ids_there[f] = *ids.begin();
                front.push_back(f);
              }
            else
              blocked[f] = true;
        }
    }
    std::map<dealii::types::boundary_id, std::set<unsigned int>> side_vertices;
    for (unsigned int e = 0; e < original.n_edges(); ++e)
      if (original.edge(e).at_boundary() && edge_ids_there[e] != original.edge(e).boundary_id)
        for (const unsigned int v : original.edge(e).vertices)
          side_vertices[edge_ids_there[e]].insert(v);
    const unsigned int n_given = interface_data.size();
    for (const auto &itf : found.interfaces)
      {
        const unsigned int a = std::min(itf.master_body, itf.slave_body), b = std::max(itf.master_body, itf.slave_body);
        unsigned int       k = n_given;
        while (k < reported.size() && !(reported[k].body_a == a && reported[k].body_b == b))
          ++k;
        Assert(k < reported.size(), dealii::ExcInternalError());
        const double mu = d.friction ? d.friction(a, b) : 0.;
        AssertThrow(std::isfinite(mu) && mu >= 0 && (mu == 0 || parameters.normal == ContactSettings::Normal::unilateral),
                    dealii::ExcMessage("FiniteSliding: the friction coefficient between the bodies " +
                                       std::to_string(a) + " and " + std::to_string(b) + " is " +
                                       internal::number_string(mu) +
                                       "; it must be finite, not negative, and 0 with tied contact."));
        pass.push_back({itf.master_id, itf.slave_id, mu, k, itf.master_body, itf.slave_body});
        const auto &m = side_vertices[itf.master_id], &sl = side_vertices[itf.slave_id];
        sides.push_back({std::vector<unsigned int>(m.begin(), m.end()), std::vector<unsigned int>(sl.begin(), sl.end())});
      }
    return pass;
  }



  unsigned int
  FiniteSliding::Impl::uncovered_edges() const
  {
    const auto &d = parameters.detection;
    if (!d.enabled || current == nullptr || pass_partner.size() != original.n_edges())
      return 0;
    // the original vertices at the converged state (a vertex moved along
    // its straight side in the step's mesh stays on that side)
    const unsigned int n0 = original.n_vertices();
    PolygonalMesh<2>   there(original);
    for (unsigned int v = 0; v < n0; ++v)
      {
        dealii::Point<2> x = current->mesh->vertex(v);
        for (unsigned int comp = 0; comp < 2; ++comp)
          x[comp] += solution[VEMDoFHandler<2>::node_dof(current->dof_handler->vertex_node(v), comp)];
        there.move_vertex(v, x);
      }
    // (half the distance of the pairing passes: a band, so that a part at
    // the threshold is not taken in and left out by turns)
    const auto found = detect_candidates(there, 0.5);
    std::map<dealii::types::boundary_id, unsigned int> partner_of_id;
    for (const auto &itf : found.interfaces)
      {
        partner_of_id[itf.master_id] = itf.slave_body;
        partner_of_id[itf.slave_id]  = itf.master_body;
      }
    unsigned int n = 0;
    for (unsigned int e = 0; e < there.n_edges(); ++e)
      if (there.edge(e).at_boundary())
        {
          // (an edge the detection of the pass gave to another body faced
          // both: it faces the one it overlaps most, and the two
          // detections may weigh that differently; an edge a side grew
          // over faces the body of that side, or a new one)
          const auto it = partner_of_id.find(there.edge(e).boundary_id);
          if (it != partner_of_id.end() && pass_partner[e] != it->second &&
              (pass_partner[e] == dealii::numbers::invalid_unsigned_int || !pass_detected[e]))
            ++n;
        }
    return n;
  }



  dealii::Point<2>
  FiniteSliding::Impl::reference_point(const unsigned int a, const unsigned int b, const double s) const
  {
    const dealii::Point<2>    &Xa = original.vertex(a), &Xb = original.vertex(b);
    const dealii::Tensor<1, 2> d  = Xb - Xa;
    const dealii::Point<2>     chord = Xa + s * d;
    const auto                 it    = arc_kappa.find(edge_key(a, b));
    if (it == arc_kappa.end() || it->second == 0)
      return chord;
    // the circle of curvature kappa through Xa and Xb, on the outward side
    // of the chord for a convex part ((a, b) in the order of the edge's
    // vertices, which runs along the loop of its cell: the body lies to the
    // left of a -> b)
    const double L = d.norm(), R = 1. / std::abs(it->second);
    const double xi = (s - 0.5) * L;
    if (!(2 * R > L) || !(R > std::abs(xi)))
      return chord;
    const double         sag = std::sqrt(R * R - xi * xi) - std::sqrt(R * R - 0.25 * L * L);
    dealii::Tensor<1, 2> outward;
    outward[0] = d[1] / L;
    outward[1] = -d[0] / L;
    return chord + (it->second > 0 ? sag : -sag) * outward;
  }



  std::map<unsigned int, std::vector<unsigned int>>
  FiniteSliding::Impl::neighbours_along_sides() const
  {
    if (!parameters.detection.enabled)
      return side_neighbours;
    std::map<unsigned int, std::vector<unsigned int>> result;
    for (const auto &entry : side_neighbours)
      result.emplace(entry.first, neighbours_on_sides(entry.first));
    return result;
  }



  std::vector<unsigned int>
  FiniteSliding::Impl::neighbours_on_sides(const unsigned int v) const
  {
    const auto &all = side_neighbours.at(v);
    if (!parameters.detection.enabled || all.size() < 2)
      return all;
    // (with detection the whole free boundary is a candidate: a corner of a
    // body has the neighbour of the face on a side of the pass only, as on
    // a named side)
    std::vector<unsigned int> kept;
    for (const unsigned int w : all)
      for (const auto &sides : interface_sides)
        if (std::binary_search(sides.first.begin(), sides.first.end(), w) ||
            std::binary_search(sides.second.begin(), sides.second.end(), w))
          {
            kept.push_back(w);
            break;
          }
    return kept.empty() ? all : kept;
  }



  void
  FiniteSliding::Impl::snap_close_vertices(std::vector<dealii::Point<2>> &x)
  {
    const auto unit = [](const dealii::Tensor<1, 2> &t) { return t / t.norm(); };
    const auto around_of = [&](const unsigned int v) { return neighbours_on_sides(v); };
    // the unit tangent of a side at a vertex, and the shortest edge there
    const auto tangent = [&](const unsigned int v) {
      const auto around = around_of(v);
      return unit(around.size() == 2 ? x[around[1]] - x[around[0]] : x[around[0]] - x[v]);
    };
    const auto local_h = [&](const unsigned int v) {
      double h = std::numeric_limits<double>::max();
      for (const unsigned int w : around_of(v))
        h = std::min(h, x[v].distance(x[w]));
      return h;
    };
    struct Candidate
    {
      double       distance;
      unsigned int v, w;
    };
    std::vector<Candidate> candidates;
    for (const auto &sides : interface_sides)
      for (const bool slave_moves : {true, false})
        {
          const auto &own   = slave_moves ? sides.second : sides.first;
          const auto &other = slave_moves ? sides.first : sides.second;
          for (const unsigned int v : own)
            {
              if (movable.count(v) == 0)
                continue;
              const dealii::Tensor<1, 2> t = tangent(v);
              // a pair snapped in an earlier pass of the step stays so
              // while its vertices remain within half an edge of each other:
              // the decisions of a step only grow, so they settle after
              // finitely many passes (a threshold that could also drop a
              // pair flips near it from pass to pass: the moved material
              // point faces the vertex, the original one does not)
              unsigned int kept = dealii::numbers::invalid_unsigned_int;
              for (const unsigned int w : other)
                if (step_snaps.count({v, w}) > 0)
                  kept = w;
              double       best   = std::numeric_limits<double>::max();
              unsigned int best_w = 0;
              if (kept != dealii::numbers::invalid_unsigned_int)
                {
                  best   = x[v].distance(x[kept]);
                  best_w = kept;
                }
              else
                for (const unsigned int w : other)
                  if (const double d = x[v].distance(x[w]); d < best)
                    {
                      best   = d;
                      best_w = w;
                    }
              if (best == std::numeric_limits<double>::max())
                continue;
              // (a master vertex moves only where its slave partner cannot)
              if (!slave_moves && movable.count(best_w) > 0)
                continue;
              const double h     = std::min(local_h(v), local_h(best_w));
              const double along = std::abs((x[best_w] - x[v]) * t);
              const double apart = std::abs(turn_left(t) * (x[best_w] - x[v]));
              const bool   again = kept != dealii::numbers::invalid_unsigned_int;
              if (along <= (again ? 0.5 : 0.05) * h && apart <= 0.5 * h)
                candidates.push_back({again ? -1. : along, v, best_w});
            }
        }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate &a, const Candidate &b) {
      return a.distance < b.distance || (a.distance == b.distance && a.v < b.v);
    });
    std::set<unsigned int> used;
    for (const auto &c : candidates)
      {
        if (used.count(c.v) > 0 || used.count(c.w) > 0)
          continue;
        used.insert(c.v);
        used.insert(c.w);
        step_snaps.insert({c.v, c.w});
        // onto the normal of the other side through w: the insertion finds
        // w as the closest point of v's new position
        const dealii::Tensor<1, 2> n = turn_left(tangent(c.w));
        x[c.v]                       = x[c.w] + ((x[c.v] - x[c.w]) * n) * n;
      }
  }



  dealii::Vector<double>
  FiniteSliding::Impl::transfer(const Discretization &from, const dealii::Vector<double> &u_old,
                          const Discretization &to) const
  {
    if (&from == &to)
      return u_old;
    const auto &old_mesh = *from.mesh;
    const auto &old_dofs = *from.dof_handler;
    const auto &new_mesh = *to.mesh;
    const auto &new_dofs = *to.dof_handler;
    const auto  n0       = original.n_vertices();
    dealii::Vector<double> u_new(new_dofs.n_dofs());
    const auto copy = [&](const unsigned int new_node, const unsigned int old_node) {
      for (unsigned int comp = 0; comp < 2; ++comp)
        u_new[VEMDoFHandler<2>::node_dof(new_node, comp)] = u_old[VEMDoFHandler<2>::node_dof(old_node, comp)];
    };
    // the vertices and the cell moments of M_0, and the edges of M_0 that
    // are not interface edges, keep their values
    for (unsigned int v = 0; v < n0; ++v)
      copy(new_dofs.vertex_node(v), old_dofs.vertex_node(v));
    const VEMElementData &layout = new_dofs.get_element_data();
    for (unsigned int cell = 0; cell < new_mesh.n_cells() && layout.nodes_per_cell() > 0; ++cell)
      for (unsigned int j = 0; j < layout.nodes_per_cell(); ++j)
        copy(new_dofs.cell_node(cell, j), old_dofs.cell_node(cell, j));
    if (layout.nodes_per_edge() > 0)
      {
        std::map<std::uint64_t, unsigned int> old_edges;
        for (unsigned int e = 0; e < old_mesh.n_edges(); ++e)
          {
            const auto &ev = old_mesh.edge(e).vertices;
            if (ev[0] < n0 && ev[1] < n0)
              old_edges[edge_key(ev[0], ev[1])] = e;
          }
        for (unsigned int e = 0; e < new_mesh.n_edges(); ++e)
          {
            const auto &ev = new_mesh.edge(e).vertices;
            if (ev[0] < n0 && ev[1] < n0)
              {
                const auto it = old_edges.find(edge_key(ev[0], ev[1]));
                if (it == old_edges.end())
                  continue;
                // (the edge nodes count from an edge's first vertex: the
                // old edge may run the other way)
                const bool same_way = old_mesh.edge(it->second).vertices[0] == ev[0];
                for (unsigned int j = 0; j < layout.nodes_per_edge(); ++j)
                  copy(new_dofs.edge_node(e, j),
                       old_dofs.edge_node(it->second, same_way ? j : layout.nodes_per_edge() - 1 - j));
              }
          }
      }
    // the nodes on the interface edges: the old trace at their material
    // points (the vertices of M_0 too: one moved along a straight side in
    // either mesh has a new material point)
    const auto         neighbours = neighbours_along_sides();
    const TraceOnSides old_trace(original, interface_edges, neighbours, old_mesh, old_dofs, u_old);
    for (const auto &[a, b, cell] : interface_edges)
      {
        const Chain new_chain = make_chain(new_mesh, a, b, cell, new_mesh.get_vertices());
        const auto  set       = [&](const unsigned int node, const dealii::Point<2> &X) {
          const auto value = old_trace.value(X, a, b);
          for (unsigned int comp = 0; comp < 2; ++comp)
            u_new[VEMDoFHandler<2>::node_dof(node, comp)] = value[comp];
        };
        for (unsigned int k = 0; k < new_chain.vertices.size(); ++k)
          set(new_dofs.vertex_node(new_chain.vertices[k]), new_mesh.vertex(new_chain.vertices[k]));
        // the edge nodes at their places along the chain's edges
        const auto &positions = layout.edge_node_positions();
        for (unsigned int k = 0; k + 1 < new_chain.vertices.size(); ++k)
          {
            const unsigned int e        = new_chain.edges[k];
            const bool         same_way = new_mesh.edge(e).vertices[0] == new_chain.vertices[k];
            for (unsigned int j = 0; j < positions.size(); ++j)
              {
                const double t = same_way ? positions[j] : 1. - positions[j];
                set(new_dofs.edge_node(e, j),
                    dealii::Point<2>((1. - t) * new_mesh.vertex(new_chain.vertices[k]) +
                                     t * new_mesh.vertex(new_chain.vertices[k + 1])));
              }
          }
      }
    return u_new;
  }
} // namespace dealvem
