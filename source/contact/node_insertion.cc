// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/numerics/rtree.h>

#include <dealvem/base/number_string.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/vem/vem_element_data.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <utility>
#include "node_insertion_side.h"

namespace dealvem
{
  using namespace internal::node_insertion;

  NodeInsertion::BoundaryEdges
  NodeInsertion::boundary_edges(const PolygonalMesh<2> &mesh)
  {
    BoundaryEdges edges;
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      if (mesh.edge(e).at_boundary())
        edges[mesh.edge(e).boundary_id].push_back(e);
    return edges;
  }



  std::map<unsigned int, double>
  NodeInsertion::edge_curvatures(const PolygonalMesh<2> &mesh, const dealii::types::boundary_id id)
  {
    const Side                     side = collect_side(mesh, id);
    std::map<unsigned int, double> result;
    for (unsigned int i = 0; i < side.edges.size(); ++i)
      result[side.edge_indices[i]] = side.edge_kappa[i];
    return result;
  }



  NodeInsertion::Interface
  NodeInsertion::insert(PolygonalMesh<2>                &mesh,
                        const dealii::types::boundary_id master_id,
                        const dealii::types::boundary_id slave_id,
                        const unsigned int               degree,
                        const Settings                  &settings,
                        const unsigned int               index,
                        BoundaryEdges                   *edges)
  {
    const std::string name = interface_name(master_id, slave_id);
    // the pairing of rule 5 matches one node inside each edge of the two
    // sides; more would need them matched in order along the edge
    AssertThrow(degree >= 1 && VEMElementData(degree).nodes_per_edge() <= 1,
                dealii::ExcMessage(name + "contact node pairs are implemented for at most one node inside an "
                                          "edge (order k = 1 and 2), not k = " +
                                   std::to_string(degree) + "."));
    Interface result;
    result.master_id = master_id;
    result.slave_id  = slave_id;
    result.degree    = degree;
    result.index     = index;
    Report &report   = result.report;

    const unsigned int n_edges_before = mesh.n_edges();
    const auto         known          = [&](const dealii::types::boundary_id id) -> const std::vector<unsigned int> * {
      if (edges == nullptr)
        return nullptr;
      const auto it = edges->find(id);
      static const std::vector<unsigned int> none;
      return it == edges->end() ? &none : &it->second;
    };
    const Side master = collect_side(mesh, master_id, known(master_id), n_edges_before);
    const Side slave  = collect_side(mesh, slave_id, known(slave_id), n_edges_before);
    check_interface(mesh, master_id, slave_id, master, slave, settings);

    // size of the interface: diagonal of the bounding box of both sides
    Point lo(1e300, 1e300), hi(-1e300, -1e300);
    for (const Side *side : {&master, &slave})
      for (const auto &e : side->edges)
        for (const unsigned int v : e)
          for (unsigned int d = 0; d < 2; ++d)
            {
              lo[d] = std::min(lo[d], mesh.vertex(v)[d]);
              hi[d] = std::max(hi[d], mesh.vertex(v)[d]);
            }
    const double search = settings.search_distance * lo.distance(hi);
    const double f      = settings.merge_fraction;
    // the precision of the coordinates (rule 3, zero gaps): the decimal
    // grid of each side's data, or the one set, relative to the interface
    const std::array<double, 2> grid =
      (settings.coordinate_precision == Settings::detect_precision ?
         std::array<double, 2>{{decimal_grid(mesh, master), decimal_grid(mesh, slave)}} :
         std::array<double, 2>{{settings.coordinate_precision * lo.distance(hi),
                                settings.coordinate_precision * lo.distance(hi)}});

    // 1. partners: project every vertex onto the other side
    std::map<unsigned int, Candidate> on_master, on_slave; // slave vertices onto master, and back
    propose_partners(mesh, slave, master, false, settings, search, lo.distance(hi), report, on_master);
    propose_partners(mesh, master, slave, true, settings, search, lo.distance(hi), report, on_slave);

    // 2. merges: a vertex whose closest point lies within f h of a vertex
    // of the other side is paired with it; closest candidates first
    std::map<unsigned int, unsigned int> master_partner, slave_partner; // vertex -> partner vertex
    merge_close_vertices(mesh, master, slave, f, on_master, on_slave, report, master_partner, slave_partner);
    std::set<unsigned int> merged_master, merged_slave;
    for (const auto &p : master_partner)
      merged_master.insert(p.first);
    for (const auto &p : slave_partner)
      merged_slave.insert(p.first);

    // 3. splits: the other accepted vertices split the edge they project on
    std::vector<Inserted> inserted;
    split_edges(mesh, master, slave, on_master, master_partner, slave_partner, true, report, inserted);
    split_edges(mesh, slave, master, on_slave, slave_partner, master_partner, false, report, inserted);

    // 4. gaps: judge every pair, put merged original vertices opposite each
    // other, then close the gaps or keep them, one decision per interface
    // (the three passes are described before judge_gaps())
    InsertedByVertex by_vertex;
    for (const auto &ins : inserted)
      by_vertex[ins.vertex] = &ins;
    const std::vector<JudgedPair> judged =
      judge_gaps(mesh, master, slave, master_partner, by_vertex, grid, settings);
    face_merged_vertices(mesh, master, slave, master_partner, by_vertex, report);
    close_or_keep_gaps(mesh, master, slave, judged, by_vertex, settings, report);

    // the moves of rules 3 and 4 must leave every cell valid (a caller of
    // many interfaces validates once, after the last)
    try
      {
        if (settings.validate_mesh)
          mesh.validate();
      }
    catch (const std::exception &e)
      {
        AssertThrow(false, dealii::ExcMessage(name + "moving the interface vertices onto their partners "
                                                     "made a cell invalid (the meshes of the two sides are too "
                                                     "far apart for their cells, or too coarse for the curvature): " +
                                              std::string(e.what())));
      }

    // (an interface without pairs is open only where no vertex lies in the
    // overlap of the two parts behind the other side: one that does, but
    // failed the distance or facing test, is a penetration the pairs would
    // miss)
    if (master_partner.empty() && settings.allow_no_pairs &&
        std::none_of(report.unpaired.begin(), report.unpaired.end(),
                     [](const UnpairedNode &u) { return u.behind; }))
      {
        result.master_edges = master.edge_indices;
        result.slave_edges  = slave.edge_indices;
        return result;
      }
    AssertThrow(!master_partner.empty(),
                dealii::ExcMessage(name + "the boundary parts do not face or overlap each other within the "
                                          "search distance (" +
                                   number_string(settings.search_distance) + " times the interface size " +
                                   number_string(lo.distance(hi)) + ") in mesh '" + mesh.name + "'."));

    // 5. pairs in the order of the slave side, and the paired sub-edges
    const Side master_after = collect_side(mesh, master);
    const Side slave_after  = collect_side(mesh, slave);
    result.master_edges     = master_after.edge_indices;
    result.slave_edges      = slave_after.edge_indices;
    // the edges this interface added, under their ids
    if (edges != nullptr)
      for (unsigned int e = n_edges_before; e < mesh.n_edges(); ++e)
        if (mesh.edge(e).at_boundary())
          (*edges)[mesh.edge(e).boundary_id].push_back(e);
    report.n_master_edges   = master_after.edges.size();
    report.n_slave_edges    = slave_after.edges.size();
    pair_slave_chains(mesh, master_after, slave_after, slave_partner, degree, index, result);
    update_geometry(mesh, result);
    return result;
  }



  void
  NodeInsertion::update_geometry(const PolygonalMesh<2> &mesh, Interface &interface)
  {
    // The contact direction of the interface does not depend on which side
    // is called master: it is the normal of the flatter side (the smaller
    // mean curvature over the paired vertices, by more than 10 %), turned to
    // point out of the master, or, where the two sides curve alike, the
    // bisector of their outward normals, n = (n_A - n_B)/|n_A - n_B| (A =
    // master, B = slave), which is either normal where the sides coincide.
    // Two straight sides (polygonal, without a smooth curvature) keep the
    // master's normal: which face carries the normal is the user's choice
    // there, as in node-to-segment codes.
    // A cylinder on a block gets the block's normal whichever is master (the
    // half-space direction of Hertz's theory); with the master's normal
    // alone the two choices were 1.1 % of p0 apart in the Hertz pressure.
    // (the edges insert() recorded, if they are still those of the ids: no
    // search of the whole mesh)
    const auto still = [&](const std::vector<unsigned int> &list, const dealii::types::boundary_id id) {
      for (const unsigned int e : list)
        if (e >= mesh.n_edges() || !mesh.edge(e).at_boundary() || mesh.edge(e).boundary_id != id)
          return false;
      return !list.empty();
    };
    const bool recorded =
      still(interface.master_edges, interface.master_id) && still(interface.slave_edges, interface.slave_id);
    const Side master   = recorded ? collect_side(mesh, interface.master_id, &interface.master_edges, mesh.n_edges()) :
                                     collect_side(mesh, interface.master_id);
    const Side slave    = recorded ? collect_side(mesh, interface.slave_id, &interface.slave_edges, mesh.n_edges()) :
                                     collect_side(mesh, interface.slave_id);
    {
      double       km = 0, ks = 0;
      unsigned int n  = 0;
      for (const auto &p : interface.pairs)
        if (!p.on_edge())
          {
            const auto a = master.kappa.find(p.master_entity), b = slave.kappa.find(p.slave_entity);
            km += (a != master.kappa.end() ? std::abs(a->second) : 0.);
            ks += (b != slave.kappa.end() ? std::abs(b->second) : 0.);
            ++n;
          }
      // "straight": a mean curvature below 1e-6 over the size of the slave
      // side (the box of its edges)
      const double size = slave.lo.distance(slave.hi);
      const bool straight = n == 0 || std::max(km, ks) / n * size <= 1e-6;
      interface.normal_side = (straight || km < 0.9 * ks ? Interface::NormalSide::master :
                               ks < 0.9 * km         ? Interface::NormalSide::slave :
                                                       Interface::NormalSide::bisector);
    }
    for (auto &p : interface.pairs)
      {
        Vector n_master, n_slave;
        if (p.on_edge())
          {
            // the single edge node (k = 2) is the midpoint
            const auto &me = mesh.edge(p.master_entity).vertices, &se = mesh.edge(p.slave_entity).vertices;
            p.master_location = 0.5 * (mesh.vertex(me[0]) + mesh.vertex(me[1]));
            p.slave_location  = 0.5 * (mesh.vertex(se[0]) + mesh.vertex(se[1]));
            // the edges' own outward normals (their vertices in the order of
            // the side, i.e. of the owning cell)
            const auto mi = master.edge_by_pair.find(key(me[0], me[1]));
            const auto si = slave.edge_by_pair.find(key(se[0], se[1]));
            AssertThrow(mi != master.edge_by_pair.end() && si != slave.edge_by_pair.end(),
                        dealii::ExcInternalError("node insertion: a paired edge is not on its side."));
            n_master = edge_normal(mesh.vertex(master.edges[mi->second][0]), mesh.vertex(master.edges[mi->second][1]));
            n_slave  = edge_normal(mesh.vertex(slave.edges[si->second][0]), mesh.vertex(slave.edges[si->second][1]));
          }
        else
          {
            p.master_location = mesh.vertex(p.master_entity);
            p.slave_location  = mesh.vertex(p.slave_entity);
            const auto n = master.normal.find(p.master_entity), m = slave.normal.find(p.slave_entity);
            AssertThrow(n != master.normal.end() && m != slave.normal.end(),
                        dealii::ExcInternalError("node insertion: a paired vertex " +
                                                 std::to_string(p.master_entity) + " / " +
                                                 std::to_string(p.slave_entity) + " is not on its side."));
            n_master = n->second;
            n_slave  = m->second;
          }
        const Vector bisector = n_master - n_slave;
        switch (interface.normal_side)
          {
            case Interface::NormalSide::master:
              p.normal = n_master;
              break;
            case Interface::NormalSide::slave:
              p.normal = -n_slave;
              break;
            default:
              p.normal = (bisector.norm() > 1e-12 ? bisector / bisector.norm() : n_master);
          }
        p.tangent     = tangent_of(p.normal);
        p.initial_gap = (p.slave_location - p.master_location) * p.normal;
        p.weight      = 0;
      }
    const VEMElementData       layout(interface.degree);
    const std::vector<double> &edge_weights = layout.edge_quadrature_weights();
    for (auto &s : interface.segments)
      {
        s.length = interface.pairs[s.first].slave_location.distance(interface.pairs[s.second].slave_location);
        // the Gauss-Lobatto rule on the sub-edge's nodes: its end weights
        // at the vertex pairs, its interior weight at the edge node pair
        const double end_weight = edge_weights.front() * s.length;
        interface.pairs[s.first].weight += end_weight;
        interface.pairs[s.second].weight += end_weight;
        if (s.midpoint != invalid)
          interface.pairs[s.midpoint].weight += edge_weights[1] * s.length;
      }
  }


  unsigned int
  NodeInsertion::mark_junctions(std::vector<ContactNodePair> &pairs, const PolygonalMesh<2> &mesh)
  {
    // per vertex: the vertex pairs it is in (pair, partner)
    std::map<unsigned int, std::vector<std::pair<unsigned int, unsigned int>>> at;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      if (!pairs[i].on_edge())
        {
          at[pairs[i].master_entity].emplace_back(i, pairs[i].slave_entity);
          at[pairs[i].slave_entity].emplace_back(i, pairs[i].master_entity);
        }
    // the neighbours of the paired vertices along the boundary
    std::map<unsigned int, std::vector<unsigned int>> boundary_neighbours;
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      if (mesh.edge(e).at_boundary())
        for (unsigned int k = 0; k < 2; ++k)
          {
            const unsigned int v = mesh.edge(e).vertices[k];
            if (at.count(v) != 0)
              boundary_neighbours[v].push_back(mesh.edge(e).vertices[1 - k]);
          }
    // whether the boundary runs straight through v
    const auto straight = [&](const unsigned int v) {
      const auto &nb = boundary_neighbours[v];
      if (nb.size() != 2)
        return false;
      const dealii::Tensor<1, 2> d0 = mesh.vertex(nb[0]) - mesh.vertex(v), d1 = mesh.vertex(nb[1]) - mesh.vertex(v);
      return std::abs(d0[0] * d1[1] - d0[1] * d1[0]) <= 1e-9 * d0.norm() * d1.norm();
    };
    unsigned int n_marked = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        pairs[p].junction = false;
        if (pairs[p].on_edge())
          continue;
        const unsigned int a = pairs[p].master_entity, b = pairs[p].slave_entity;
        for (const auto &[q, c] : at[a])
          {
            if (pairs[p].junction || q == p || pairs[q].interface == pairs[p].interface)
              continue;
            for (const auto &[r, c2] : at[b])
              if (c2 == c && r != p && r != q && pairs[r].interface != pairs[p].interface)
                {
                  const bool sc = straight(c);
                  const unsigned int n_straight = straight(a) + straight(b) + sc;
                  pairs[p].junction = (n_straight == 1) ? sc :
                                                          (pairs[p].interface > pairs[q].interface &&
                                                           pairs[p].interface > pairs[r].interface);
                  break;
                }
          }
        n_marked += pairs[p].junction;
      }
    return n_marked;
  }
} // namespace dealvem
