// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// NodeInsertion: rule 1 (partners), rule 2 (merges), rule 3 (splits) and
// rule 5 (the pairs of the slave chains).

#include "node_insertion_side.h"

namespace dealvem
{
  namespace internal
  {
    namespace node_insertion
    {
    // Rule 1 (partners): project every vertex of @p from that has a normal
    // onto the side @p onto (master vertices cast along their normal, slave
    // vertices projected) and keep, per vertex, the candidate partner point;
    // a vertex outside the overlap is skipped, one beyond the search distance
    // or on a part that does not face the other side is reported unpaired.
    void
    propose_partners(const PolygonalMesh<2>             &mesh,
                     const Side                         &from,
                     const Side                         &onto,
                     const bool                          from_master,
                     const NodeInsertion::Settings      &settings,
                     const double                        search,
                     const double                        interface_size,
                     NodeInsertion::Report              &report,
                     std::map<unsigned int, Candidate>  &out)
    {
      const double f = settings.merge_fraction;
      for (const auto &vn : from.normal)
        {
          const unsigned int v = vn.first;
          Candidate          c;
          c.projection = from_master ? cast(mesh, onto, mesh.vertex(v), vn.second, f) :
                                       project(mesh, onto, mesh.vertex(v), vn.second, f);
          if (!c.projection.inside)
            continue; // outside the overlap of the two parts
          // (behind the other side: inside its body, locally)
          const bool behind =
            c.projection.edge != invalid &&
            (mesh.vertex(v) - c.projection.point) *
                edge_normal(mesh.vertex(onto.edges[c.projection.edge][0]), mesh.vertex(onto.edges[c.projection.edge][1])) <
              0;
          if (c.projection.distance > search)
            report.unpaired.push_back({from_master, v, mesh.vertex(v),
                                       "its distance " + number_string(c.projection.distance) +
                                         " to the other side exceeds the search distance " +
                                         number_string(search) + " (Search distance " +
                                         number_string(settings.search_distance) +
                                         " times the interface size " + number_string(interface_size) + ")",
                                       behind});
          else if (!c.projection.facing &&
                   !(settings.keep_facing.count(v) > 0 && c.projection.normal_cosine <= 0))
            {
              // far from the other side, a part that turns away (the flank
              // of a cylinder above a block) is simply outside the overlap;
              // within two edge lengths it is worth a word
              if (c.projection.distance <= 2 * from.h.at(v))
                report.unpaired.push_back({from_master, v, mesh.vertex(v),
                                           "the other side does not face it there (outward normals at less "
                                           "than 120 degrees)",
                                           behind});
              continue;
            }
          else
            c.accepted = true;
          out[v] = c;
        }
    }



    // Rule 2 (merges): a vertex whose candidate point lies within the merge
    // fraction times the local edge length of a vertex of the other side is
    // paired with that vertex instead of splitting an edge; the closest
    // candidates are merged first, each vertex at most once. Fills the
    // partner maps (vertex -> partner vertex) of both sides.
    void
    merge_close_vertices(const PolygonalMesh<2>                  &mesh,
                         const Side                              &master,
                         const Side                              &slave,
                         const double                             f,
                         const std::map<unsigned int, Candidate> &on_master,
                         const std::map<unsigned int, Candidate> &on_slave,
                         NodeInsertion::Report                   &report,
                         std::map<unsigned int, unsigned int>    &master_partner,
                         std::map<unsigned int, unsigned int>    &slave_partner)
    {
      struct Merge
      {
        double       distance;
        unsigned int m, s;
      };
      std::vector<Merge> merges;
      const auto         offer = [&](const Side &onto, const Side &from, const unsigned int v,
                             const Candidate &c, const bool v_is_slave) {
        if (!c.accepted)
          return;
        const unsigned int w  = onto.edges[c.projection.edge][c.projection.t <= 0.5 ? 0 : 1];
        const double       d  = c.projection.point.distance(mesh.vertex(w));
        const double       hl = std::min(from.h.at(v), onto.h.at(w));
        // (rule 3 refuses a split that would leave a sub-edge shorter than
        // 1e-3 of the edge length: a vertex that close to a vertex of the
        // other side is merged with it also when the merge fraction is
        // smaller, rather than left without a partner)
        const auto  &ends = onto.edges[c.projection.edge];
        const double L    = mesh.vertex(ends[0]).distance(mesh.vertex(ends[1]));
        if (d <= f * hl || d < 1e-3 * std::min(from.h.at(v), L))
          merges.push_back({d, v_is_slave ? w : v, v_is_slave ? v : w});
      };
      for (const auto &c : on_master)
        offer(master, slave, c.first, c.second, true);
      for (const auto &c : on_slave)
        offer(slave, master, c.first, c.second, false);
      std::sort(merges.begin(), merges.end(), [](const Merge &a, const Merge &b) {
        return a.distance < b.distance || (a.distance == b.distance && VertexPair(a.m, a.s) < VertexPair(b.m, b.s));
      });
      for (const auto &m : merges)
        if (master_partner.count(m.m) == 0 && slave_partner.count(m.s) == 0)
          {
            master_partner[m.m] = m.s;
            slave_partner[m.s]  = m.m;
            ++report.n_merged;
          }
    }



    // Rule 3 (splits): every accepted candidate of @p cands (vertices of
    // @p from) without a partner yet splits the edge of @p onto it projects
    // on; on a curved side the new vertex is moved onto the circle of the
    // side's curvature. A candidate that falls on a vertex of @p onto that
    // is paired already, or that would make a sub-edge shorter than 1e-3 of
    // an edge length, is reported unpaired. The new pairs go into the
    // partner maps, the new vertices into @p inserted.
    void
    split_edges(PolygonalMesh<2>                        &mesh,
                const Side                              &onto,
                const Side                              &from,
                const std::map<unsigned int, Candidate> &cands,
                std::map<unsigned int, unsigned int>    &partner_onto,
                std::map<unsigned int, unsigned int>    &partner_from,
                const bool                               onto_master,
                NodeInsertion::Report                   &report,
                std::vector<Inserted>                   &inserted)
    {
      std::map<unsigned int, std::vector<std::pair<double, unsigned int>>> by_edge; // edge -> (t, vertex)
      for (const auto &c : cands)
        if (c.second.accepted && partner_from.count(c.first) == 0)
          {
            const auto &pr = c.second.projection;
            if (pr.t <= 0 || pr.t >= 1)
              {
                const unsigned int w = onto.edges[pr.edge][pr.t <= 0 ? 0 : 1];
                report.unpaired.push_back({!onto_master, c.first, mesh.vertex(c.first),
                                           "its closest point on the other side is vertex " + std::to_string(w) +
                                             " " + point_string(mesh.vertex(w)) +
                                             ", which is already paired with a closer node"});
                continue;
              }
            by_edge[pr.edge].emplace_back(pr.t, c.first);
          }
      for (auto &entry : by_edge)
        {
          auto &list = entry.second;
          std::sort(list.begin(), list.end());
          const unsigned int a = onto.edges[entry.first][0], b = onto.edges[entry.first][1];
          const Point        xa = mesh.vertex(a), xb = mesh.vertex(b);
          const double       L  = xa.distance(xb);
          const double       kappa = onto.edge_kappa[entry.first];
          unsigned int       e        = onto.edge_indices[entry.first]; // the piece (previous, b)
          double             previous = 0;
          std::vector<std::pair<unsigned int, Point>> moves; // after all splits of this edge
          std::vector<double>                         moved_t;
          for (unsigned int i = 0; i < list.size(); ++i)
            {
              const double       t    = list[i].first;
              const unsigned int v    = list[i].second;
              const double       hl   = std::min(from.h.at(v), L);
              if ((t - previous) * L < 1e-3 * hl || (1 - t) * L < 1e-3 * hl)
                {
                  report.unpaired.push_back({!onto_master, v, mesh.vertex(v),
                                             "it lies within 1e-3 of an edge length of another node on the "
                                             "other side (a sub-edge that short would be created)"});
                  continue;
                }
              const unsigned int nv = mesh.split_edge(e, xa + t * (xb - xa));
              // split_edge keeps e for (previous, nv) and appends (nv, b)
              e = mesh.n_edges() - 1;
              // on a smooth curve, the new vertex goes onto the circle of the
              // side's curvature instead of the chord, at the point the
              // partner faces along the master normals: the closest point of
              // the circle to a slave vertex, the hit of the master vertex's
              // normal line. So the pair's gap is the normal distance of the
              // two curves, whether they coincide, overlap or stand apart.
              if (kappa != 0)
                {
                  Point      target;
                  const bool on_arc = onto_master ?
                                        closest_on_arc(xa, xb, kappa, mesh.vertex(v), target) :
                                        cast_on_arc(xa, xb, kappa, mesh.vertex(v), from.normal.at(v), target);
                  if (!on_arc) // (a degenerate arc: the chord's own offset rule)
                    target = mesh.vertex(nv) + 0.5 * t * (1 - t) * L * L * kappa * edge_normal(xa, xb);
                  moves.emplace_back(nv, target);
                  moved_t.push_back(t);
                }
              partner_onto[nv] = v;
              partner_from[v]  = nv;
              inserted.push_back({nv, v, onto_master, entry.first, xa + t * (xb - xa), edge_normal(xa, xb),
                                  0.5 * t * (1 - t) * L * L});
              previous = t;
              ++(onto_master ? report.n_inserted_master : report.n_inserted_slave);
            }
          // the partners' normals may cross where the other side turns
          // sharply (a gear's tip corner facing a flank): targets out of
          // order along the edge would fold it. Then every new vertex of the
          // edge takes the chord's own offset rule, which keeps the order.
          bool ordered = true;
          for (unsigned int i = 0; i < moves.size() && ordered; ++i)
            {
              const double tau = (moves[i].second - xa) * (xb - xa) / (L * L);
              const double before = (i == 0 ? 0. : (moves[i - 1].second - xa) * (xb - xa) / (L * L));
              ordered            = tau > before && tau < 1;
            }
          if (!ordered)
            for (unsigned int i = 0; i < moves.size(); ++i)
              moves[i].second = xa + moved_t[i] * (xb - xa) +
                                0.5 * moved_t[i] * (1 - moved_t[i]) * L * L * kappa * edge_normal(xa, xb);
          for (const auto &m : moves)
            mesh.move_vertex(m.first, m.second);
        }
    }



    // Rule 5 (pairs): walk the chains of the slave side after insertion;
    // every slave edge whose two end vertices are paired with the two ends
    // of one master edge becomes a paired sub-edge (ContactSegment; for
    // k = 2 with the pair of the two edge midpoints), and the vertex pairs
    // are made in the order of the slave chains. The first and the last
    // pair of a run of paired sub-edges are marked at_open_end where both
    // boundaries go on smoothly beyond them. A paired slave vertex on no
    // paired sub-edge is reported unpaired.
    void
    pair_slave_chains(const PolygonalMesh<2>                     &mesh,
                      const Side                                 &master_after,
                      const Side                                 &slave_after,
                      const std::map<unsigned int, unsigned int> &slave_partner,
                      const unsigned int                          degree,
                      const unsigned int                          index,
                      NodeInsertion::Interface                   &result)
    {
      NodeInsertion::Report &report = result.report;
      // the layout's edge nodes are paired with the sub-edges (at most one
      // per edge: NodeInsertion::insert() admits k = 1 and 2 only)
      const bool pair_edge_nodes = VEMElementData(degree).nodes_per_edge() > 0;
      // does the boundary of the body go on smoothly beyond the end vertex v
      // of a side (the part was cut out of a smooth boundary)? The other
      // boundary edge at v is found by walking around v from the side's
      // own edge, cell by cell through the interior edges at v (no search
      // of the whole mesh).
      const auto other_boundary_edge = [&](const unsigned int own_edge, const unsigned int v) {
        unsigned int edge = own_edge, cell = mesh.edge(own_edge).cells[0];
        for (unsigned int step = 0; step < 64; ++step)
          {
            const auto  &c    = mesh.cell(cell);
            unsigned int next = dealii::numbers::invalid_unsigned_int;
            for (unsigned int i = 0; i < c.edges.size(); ++i)
              if (c.edges[i] != edge && (mesh.edge(c.edges[i]).vertices[0] == v || mesh.edge(c.edges[i]).vertices[1] == v))
                next = c.edges[i];
            if (next == dealii::numbers::invalid_unsigned_int)
              return next;
            if (mesh.edge(next).at_boundary())
              return next;
            edge = next;
            cell = (mesh.edge(next).cells[0] == cell ? mesh.edge(next).cells[1] : mesh.edge(next).cells[0]);
          }
        return dealii::numbers::invalid_unsigned_int;
      };
      const auto continues_smoothly = [&](const Side &side, const unsigned int v) {
        if (!side.is_end(v))
          return true;
        const auto         own = side.outgoing.count(v) ? side.outgoing.at(v) : side.incoming.at(v);
        const unsigned int own_mesh_edge = side.edge_indices[own];
        const unsigned int other         = other_boundary_edge(own_mesh_edge, v);
        for (const unsigned int e : std::vector<unsigned int>{other})
          if (e != dealii::numbers::invalid_unsigned_int && e != own_mesh_edge && mesh.edge(e).boundary_id != side.id)
            {
              const auto  &ev = mesh.edge(e).vertices;
              const auto  &ov = side.edges[own];
              const Vector d_own   = mesh.vertex(ov[1]) - mesh.vertex(ov[0]);
              const Vector d_other = mesh.vertex(ev[1]) - mesh.vertex(ev[0]);
              const double c = (d_own * d_other) / (d_own.norm() * d_other.norm());
              if (c >= std::cos(30. * M_PI / 180.))
                return true;
            }
        return false;
      };

      for (unsigned int c = 0; c < slave_after.chains.size(); ++c)
        {
          const auto        &chain = slave_after.chains[c];
          const unsigned int n     = chain.size();
          const unsigned int n_edges_in_chain = slave_after.closed[c] ? n : n - 1;
          // vertex pair index of each chain vertex (created lazily)
          std::vector<unsigned int> pair_of(n, invalid);
          unsigned int              run_start = invalid, last = invalid;
          const auto                close_run = [&]() {
            if (run_start == invalid)
              return;
            if (run_start == last && slave_after.closed[c])
              {
                run_start = invalid; // a whole closed loop: no ends
                return;
              }
            for (const unsigned int p : {run_start, last})
              {
                auto &pair = result.pairs[p];
                if (continues_smoothly(slave_after, pair.slave_entity) &&
                    continues_smoothly(master_after, pair.master_entity))
                  pair.at_open_end = true;
              }
            run_start = invalid;
          };
          const auto vertex_pair = [&](const unsigned int i) {
            if (pair_of[i] == invalid)
              {
                ContactNodePair p;
                p.master_entity = slave_partner.at(chain[i]);
                p.slave_entity  = chain[i];
                p.interface     = index;
                pair_of[i]      = result.pairs.size();
                result.pairs.push_back(p);
              }
            return pair_of[i];
          };
          for (unsigned int i = 0; i < n_edges_in_chain; ++i)
            {
              const unsigned int sa = chain[i], sb = chain[(i + 1) % n];
              const auto         pa = slave_partner.find(sa), pb = slave_partner.find(sb);
              const bool         paired = pa != slave_partner.end() && pb != slave_partner.end() &&
                                  master_after.edge_by_pair.count(key(pa->second, pb->second));
              if (!paired)
                {
                  close_run();
                  continue;
                }
              ContactSegment seg;
              seg.first = vertex_pair(i);
              if (run_start == invalid)
                run_start = seg.first;
              if (pair_edge_nodes)
                {
                  ContactNodePair p;
                  p.master_entity =
                    master_after.edge_indices[master_after.edge_by_pair.at(key(pa->second, pb->second))];
                  p.slave_entity = slave_after.edge_indices[slave_after.edge_by_pair.at(key(sa, sb))];
                  p.kind         = VEMElementData::NodeKind::edge;
                  p.interface    = index;
                  seg.midpoint   = result.pairs.size();
                  result.pairs.push_back(p);
                }
              seg.second = vertex_pair((i + 1) % n);
              last       = seg.second;
              result.segments.push_back(seg);
            }
          close_run();
          for (unsigned int i = 0; i < n; ++i)
            if (slave_partner.count(chain[i]) && pair_of[i] == invalid)
              report.unpaired.push_back({false, chain[i], mesh.vertex(chain[i]),
                                         "none of its slave edges has both ends paired (the overlap there is "
                                         "shorter than one edge)"});
        }
    }
    } // namespace node_insertion
  } // namespace internal
} // namespace dealvem
