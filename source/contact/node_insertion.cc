// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/contact/node_insertion.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <utility>

namespace dealvem
{
  namespace
  {
    using Mesh = PolygonalMesh<2>;
    using VertexPair = std::pair<unsigned int, unsigned int>;

    constexpr unsigned int invalid = dealii::numbers::invalid_unsigned_int;

    VertexPair
    key(const unsigned int a, const unsigned int b)
    {
      return a < b ? VertexPair(a, b) : VertexPair(b, a);
    }

    std::string
    interface_name(const dealii::types::boundary_id master_id,
                   const dealii::types::boundary_id slave_id)
    {
      return "contact interface (master id " + std::to_string(master_id) + ", slave id " +
             std::to_string(slave_id) + "):\n";
    }

    std::string
    number_string(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    std::string
    point_string(const dealii::Point<2> &p)
    {
      std::ostringstream s;
      s << "(" << p[0] << ", " << p[1] << ")";
      return s.str();
    }

    /// One side of an interface: its boundary edges (as vertex pairs in the
    /// counter-clockwise order of the owning cell) and their vertices.
    struct Side
    {
      /// (a, b) in the CCW order of the cell, and the current edge index.
      std::vector<std::array<unsigned int, 2>> edges;
      std::vector<unsigned int>                edge_indices;
      /// Sorted vertex indices.
      std::vector<unsigned int>                vertices;
      /// Number of side edges at each vertex.
      std::map<unsigned int, unsigned int>     degree;
      /// Edge index by vertex pair.
      std::map<VertexPair, unsigned int>       edge_by_pair;
      /// Material ids of the cells owning the edges.
      std::set<dealii::types::material_id>     materials;
    };

    Side
    collect_side(const Mesh &mesh, const dealii::types::boundary_id id)
    {
      Side side;
      std::set<unsigned int> vertices;
      for (unsigned int e = 0; e < mesh.n_edges(); ++e)
        {
          const auto &edge = mesh.edge(e);
          if (!edge.at_boundary() || edge.boundary_id != id)
            continue;
          side.edges.push_back(edge.vertices);
          side.edge_indices.push_back(e);
          side.edge_by_pair[key(edge.vertices[0], edge.vertices[1])] = e;
          side.materials.insert(mesh.cell(edge.cells[0]).material_id);
          for (const unsigned int v : edge.vertices)
            {
              vertices.insert(v);
              ++side.degree[v];
            }
        }
      side.vertices.assign(vertices.begin(), vertices.end());
      return side;
    }

    std::string
    materials_string(const std::set<dealii::types::material_id> &m)
    {
      std::string s;
      for (const auto id : m)
        s += (s.empty() ? "" : ", ") + std::to_string(id);
      return s;
    }

    /// Checks common to insert() and make_pairs().
    void
    check_interface(const Mesh                      &mesh,
                    const dealii::types::boundary_id master_id,
                    const dealii::types::boundary_id slave_id,
                    const Side                      &master,
                    const Side                      &slave,
                    const NodeInsertion::Settings   &settings)
    {
      AssertThrow(settings.snap_tolerance > 0 && settings.snap_tolerance < 0.5,
                  dealii::ExcMessage(interface_name(master_id, slave_id) +
                                     "the snap tolerance must lie in (0, 0.5), but it is " +
                                     number_string(settings.snap_tolerance) + "."));
      AssertThrow(settings.search_distance > 0,
                  dealii::ExcMessage(interface_name(master_id, slave_id) +
                                     "the search distance must be positive, but it is " +
                                     number_string(settings.search_distance) + "."));
      for (const auto &s : {std::make_pair(master_id, &master), std::make_pair(slave_id, &slave)})
        AssertThrow(!s.second->edges.empty(),
                    dealii::ExcMessage("contact interface: boundary id " + std::to_string(s.first) +
                                       " has no boundary edges in mesh '" + mesh.name + "'."));
      AssertThrow(master.materials.size() == 1,
                  dealii::ExcMessage(interface_name(master_id, slave_id) + "the boundary edges with id " +
                                     std::to_string(master_id) + " belong to more than one body (material ids " +
                                     materials_string(master.materials) +
                                     "); each side of a contact interface must lie on one body."));
      AssertThrow(slave.materials.size() == 1,
                  dealii::ExcMessage(interface_name(master_id, slave_id) + "the boundary edges with id " +
                                     std::to_string(slave_id) + " belong to more than one body (material ids " +
                                     materials_string(slave.materials) +
                                     "); each side of a contact interface must lie on one body."));
      AssertThrow(*master.materials.begin() != *slave.materials.begin(),
                  dealii::ExcMessage(interface_name(master_id, slave_id) + "both boundary ids " +
                                     std::to_string(master_id) + " and " + std::to_string(slave_id) +
                                     " belong to the same body (material id " +
                                     std::to_string(*master.materials.begin()) +
                                     "); a contact interface joins two different bodies."));
    }

    /// The projection of a point onto the edges of one side.
    struct Projection
    {
      bool             found = false;
      unsigned int     edge  = invalid; ///< index into Side::edges
      double           s     = 0;       ///< clamped parameter from edges[edge][0]
      double           length = 0;      ///< length of that edge
      dealii::Point<2> point;           ///< closest point
    };

    /**
     * Closest point of @p p on the edges of @p side (nearest edge). Accepted
     * if the distance is at most search_distance times the length of that
     * edge and the point does not lie beyond an end of the side: the
     * unclamped parameter must lie in [-snap, 1 + snap] unless the
     * closest point is a vertex joining two edges of the side (a corner of
     * a polygonal side, where both parameters lie outside [0, 1]).
     *
     * @p reference_lengths (one per edge of the side), if given, replace the
     * edge lengths in the distance criterion.
     */
    Projection
    project(const Mesh &mesh, const Side &side, const dealii::Point<2> &p,
            const NodeInsertion::Settings &settings,
            const std::vector<double>     *reference_lengths = nullptr)
    {
      Projection best;
      double     best_distance = std::numeric_limits<double>::max();
      double     best_unclamped = 0;
      for (unsigned int i = 0; i < side.edges.size(); ++i)
        {
          const dealii::Point<2>     &a = mesh.vertex(side.edges[i][0]);
          const dealii::Point<2>     &b = mesh.vertex(side.edges[i][1]);
          const dealii::Tensor<1, 2>  d = b - a;
          const double                L2 = d * d;
          if (L2 == 0)
            continue;
          const double           s_unclamped = ((p - a) * d) / L2;
          const double           s           = std::min(1., std::max(0., s_unclamped));
          const dealii::Point<2> x           = a + s * d;
          const double           distance    = p.distance(x);
          if (distance < best_distance)
            {
              best_distance  = distance;
              best_unclamped = s_unclamped;
              best.edge      = i;
              best.s         = s;
              best.length    = std::sqrt(L2);
              best.point     = x;
            }
        }
      if (best.edge == invalid)
        return best;
      const double reference = (reference_lengths ? (*reference_lengths)[best.edge] : best.length);
      if (best_distance > settings.search_distance * reference)
        return best;
      const double snap = settings.snap_tolerance;
      if (best_unclamped < -snap || best_unclamped > 1 + snap)
        {
          // beyond an end of the edge: accept only at a corner inside the side
          const unsigned int v = side.edges[best.edge][best_unclamped < 0 ? 0 : 1];
          const auto         it = side.degree.find(v);
          if (it == side.degree.end() || it->second < 2)
            return best;
        }
      best.found = true;
      return best;
    }

    /**
     * For each edge of @p side the length of the straight run of side edges
     * it belongs to (consecutive collinear edges joined at a vertex of the
     * side). Inserting vertices splits an edge into collinear pieces, so the
     * run containing a piece is at least as long as the edge that was split:
     * make_pairs() measures the search distance against it and so accepts
     * every projection that insert() accepted.
     */
    std::vector<double>
    run_lengths(const Mesh &mesh, const Side &side)
    {
      const unsigned int        n = side.edges.size();
      std::vector<unsigned int> parent(n);
      for (unsigned int i = 0; i < n; ++i)
        parent[i] = i;
      const std::function<unsigned int(unsigned int)> root = [&](unsigned int i) {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      };
      std::map<unsigned int, unsigned int> incoming, outgoing;
      for (unsigned int i = 0; i < n; ++i)
        {
          incoming[side.edges[i][1]] = i;
          outgoing[side.edges[i][0]] = i;
        }
      const auto unit_tangent = [&](const unsigned int i) {
        dealii::Tensor<1, 2> t = mesh.vertex(side.edges[i][1]) - mesh.vertex(side.edges[i][0]);
        return t / t.norm();
      };
      for (const auto &in : incoming)
        {
          const auto out = outgoing.find(in.first);
          if (out == outgoing.end() || side.degree.at(in.first) != 2)
            continue;
          const dealii::Tensor<1, 2> t1 = unit_tangent(in.second), t2 = unit_tangent(out->second);
          if (t1 * t2 > 0 && std::abs(t1[0] * t2[1] - t1[1] * t2[0]) <= 1e-10)
            parent[root(in.second)] = root(out->second);
        }
      std::vector<double> sum(n, 0.), lengths(n);
      for (unsigned int i = 0; i < n; ++i)
        sum[root(i)] += mesh.vertex(side.edges[i][0]).distance(mesh.vertex(side.edges[i][1]));
      for (unsigned int i = 0; i < n; ++i)
        lengths[i] = sum[root(i)];
      return lengths;
    }



    /**
     * One pass: project the vertices of @p from onto the edges of @p onto,
     * snap or split. Vertices in @p matched (vertex of @p from -> vertex of
     * @p onto) already have a partner and count as snapped. New matches are
     * added to @p matched_back (vertex of @p onto -> vertex of @p from).
     * Returns the number of accepted projections.
     */
    unsigned int
    insertion_pass(Mesh                                     &mesh,
                   const dealii::types::boundary_id          from_id,
                   const dealii::types::boundary_id          onto_id,
                   const std::map<unsigned int, unsigned int> &matched,
                   std::map<unsigned int, unsigned int>     &matched_back,
                   const NodeInsertion::Settings            &settings,
                   unsigned int                             &n_inserted,
                   unsigned int                             &n_snapped)
    {
      const Side   from = collect_side(mesh, from_id);
      const Side   onto = collect_side(mesh, onto_id);
      const double snap = settings.snap_tolerance;

      struct Insertion
      {
        double           s;
        dealii::Point<2> point;
        unsigned int     source;
      };
      std::map<unsigned int, std::vector<Insertion>> insertions; // by index into onto.edges
      unsigned int                                   n_accepted = 0;

      for (const unsigned int v : from.vertices)
        {
          const auto m = matched.find(v);
          if (m != matched.end())
            {
              ++n_snapped;
              ++n_accepted;
              continue;
            }
          const Projection pr = project(mesh, onto, mesh.vertex(v), settings);
          if (!pr.found)
            continue;
          ++n_accepted;
          if (pr.s <= snap || pr.s >= 1 - snap)
            {
              ++n_snapped;
              const unsigned int w = onto.edges[pr.edge][pr.s <= snap ? 0 : 1];
              if (matched_back.count(w) == 0)
                matched_back[w] = v;
            }
          else
            insertions[pr.edge].push_back({pr.s, pr.point, v});
        }

      for (auto &entry : insertions)
        {
          auto &list = entry.second;
          std::sort(list.begin(), list.end(),
                    [](const Insertion &x, const Insertion &y) { return x.s < y.s; });
          const unsigned int a = onto.edges[entry.first][0];
          const unsigned int b = onto.edges[entry.first][1];
          const double       L = mesh.vertex(a).distance(mesh.vertex(b));
          unsigned int       previous   = a;
          double             previous_s = 0;
          unsigned int       current    = invalid; // the mesh edge (previous, b)
          for (const auto &ins : list)
            {
              if (ins.s - previous_s <= snap || ins.s >= 1 - snap)
                {
                  // closer than the snap tolerance to the previous point:
                  // it shares that vertex
                  ++n_snapped;
                  if (previous != a && matched_back.count(previous) == 0)
                    matched_back[previous] = ins.source;
                  continue;
                }
              // the sub-edge (previous, b) contains the point
              unsigned int e = current;
              if (e == invalid)
                for (unsigned int i = 0; i < mesh.n_edges(); ++i)
                  if (key(mesh.edge(i).vertices[0], mesh.edge(i).vertices[1]) == key(previous, b))
                    {
                      e = i;
                      break;
                    }
              AssertThrow(e != invalid,
                          dealii::ExcInternalError("node insertion: the sub-edge from vertex " +
                                                   std::to_string(previous) + " to vertex " +
                                                   std::to_string(b) + " was not found."));
              AssertThrow((ins.s - previous_s) * L > 0 && (1 - ins.s) * L > 0,
                          dealii::ExcInternalError("node insertion would create a zero-length edge at " +
                                                   point_string(ins.point) + "."));
              const unsigned int v = mesh.split_edge(e, ins.point);
              // split_edge keeps e for the piece at the edge's first vertex
              // and appends the other piece: find the one ending at b
              current = (key(mesh.edge(e).vertices[0], mesh.edge(e).vertices[1]) == key(v, b)) ?
                          e :
                          mesh.n_edges() - 1;
              ++n_inserted;
              matched_back[v] = ins.source;
              previous        = v;
              previous_s      = ins.s;
            }
        }
      return n_accepted;
    }

    /// Outward unit normal of a boundary edge (a, b) in its cell's CCW order.
    dealii::Tensor<1, 2>
    edge_normal(const Mesh &mesh, const std::array<unsigned int, 2> &edge)
    {
      dealii::Tensor<1, 2> t = mesh.vertex(edge[1]) - mesh.vertex(edge[0]);
      t /= t.norm();
      dealii::Tensor<1, 2> n;
      n[0] = t[1];
      n[1] = -t[0];
      return n;
    }

    dealii::Tensor<1, 2>
    tangent_of(const dealii::Tensor<1, 2> &n)
    {
      dealii::Tensor<1, 2> t;
      t[0] = -n[1];
      t[1] = n[0];
      return t;
    }
  } // namespace



  NodeInsertion::Report
  NodeInsertion::insert(PolygonalMesh<2>                &mesh,
                        const dealii::types::boundary_id master_id,
                        const dealii::types::boundary_id slave_id,
                        const Settings                  &settings)
  {
    {
      const Side master = collect_side(mesh, master_id);
      const Side slave  = collect_side(mesh, slave_id);
      check_interface(mesh, master_id, slave_id, master, slave, settings);
    }

    Report report;
    // master vertex -> slave vertex it came from or snapped to (pass 1)
    std::map<unsigned int, unsigned int> master_to_slave;
    // slave vertex -> master vertex (pass 2); unused afterwards
    std::map<unsigned int, unsigned int> slave_to_master;
    const std::map<unsigned int, unsigned int> none;

    // pass 1: slave vertices onto master edges
    const unsigned int n1 = insertion_pass(mesh, slave_id, master_id, none, master_to_slave, settings,
                                           report.n_inserted_master, report.n_snapped);
    // pass 2: master vertices onto slave edges; vertices that came from (or
    // snapped to) a slave vertex in pass 1 already have their partner and
    // count as snapped
    const unsigned int n2 = insertion_pass(mesh, master_id, slave_id, master_to_slave, slave_to_master,
                                           settings, report.n_inserted_slave, report.n_snapped);

    AssertThrow(n1 + n2 > 0,
                dealii::ExcMessage(interface_name(master_id, slave_id) +
                                   "the boundary parts do not face or overlap each other within the "
                                   "search distance (" +
                                   number_string(settings.search_distance) +
                                   " times the edge length) in mesh '" + mesh.name + "'."));

    report.n_master_edges = collect_side(mesh, master_id).edges.size();
    report.n_slave_edges  = collect_side(mesh, slave_id).edges.size();
    return report;
  }



  std::vector<ContactNodePair>
  NodeInsertion::make_pairs(const PolygonalMesh<2>          &mesh,
                            const dealii::types::boundary_id master_id,
                            const dealii::types::boundary_id slave_id,
                            const unsigned int               degree,
                            const Settings                  &settings,
                            const unsigned int               interface)
  {
    AssertThrow(degree == 1 || degree == 2,
                dealii::ExcMessage(interface_name(master_id, slave_id) +
                                   "contact node pairs are implemented for order k = 1 and 2, not k = " +
                                   std::to_string(degree) + "."));
    const Side master = collect_side(mesh, master_id);
    const Side slave  = collect_side(mesh, slave_id);
    check_interface(mesh, master_id, slave_id, master, slave, settings);
    const double snap = settings.snap_tolerance;
    // the search distance is measured against the straight runs of edges,
    // i.e. against the edges before insertion (see run_lengths())
    const std::vector<double> master_runs = run_lengths(mesh, master);
    const std::vector<double> slave_runs  = run_lengths(mesh, slave);

    // candidate partners: (slave vertex, master vertex, distance)
    std::map<unsigned int, std::pair<unsigned int, double>> partner; // slave -> (master, distance)
    const auto offer = [&](const unsigned int s, const unsigned int m) {
      const double d  = mesh.vertex(s).distance(mesh.vertex(m));
      const auto   it = partner.find(s);
      if (it == partner.end() || d < it->second.second)
        partner[s] = {m, d};
    };
    // the slave vertex projects onto (the snap tolerance of) a master vertex
    for (const unsigned int s : slave.vertices)
      {
        const Projection pr = project(mesh, master, mesh.vertex(s), settings, &master_runs);
        if (!pr.found)
          continue;
        if (pr.s <= snap)
          offer(s, master.edges[pr.edge][0]);
        else if (pr.s >= 1 - snap)
          offer(s, master.edges[pr.edge][1]);
      }
    // the master vertex projects onto a slave vertex (curved master sides,
    // where the projection of the slave vertex is not the master vertex)
    for (const unsigned int m : master.vertices)
      {
        const Projection pr = project(mesh, slave, mesh.vertex(m), settings, &slave_runs);
        if (!pr.found)
          continue;
        unsigned int s = invalid;
        if (pr.s <= snap)
          s = slave.edges[pr.edge][0];
        else if (pr.s >= 1 - snap)
          s = slave.edges[pr.edge][1];
        if (s != invalid && partner.count(s) == 0)
          offer(s, m);
      }
    // each master vertex has at most one partner: the closest slave vertex
    {
      std::map<unsigned int, std::pair<unsigned int, double>> best; // master -> (slave, distance)
      for (const auto &p : partner)
        {
          const auto it = best.find(p.second.first);
          if (it == best.end() || p.second.second < it->second.second)
            best[p.second.first] = {p.first, p.second.second};
        }
      std::map<unsigned int, std::pair<unsigned int, double>> unique;
      for (const auto &b : best)
        unique[b.second.first] = {b.first, b.second.second};
      partner = unique;
    }

    // master normal at a vertex: average of the adjacent master edge normals
    std::map<unsigned int, dealii::Tensor<1, 2>> master_normal;
    for (const auto &e : master.edges)
      {
        const dealii::Tensor<1, 2> n = edge_normal(mesh, e);
        master_normal[e[0]] += n;
        master_normal[e[1]] += n;
      }
    for (auto &n : master_normal)
      n.second /= n.second.norm();

    // order along the slave side: follow the chains of slave edges (each
    // edge runs from vertex [0] to vertex [1] in its cell's CCW order)
    std::map<unsigned int, std::vector<unsigned int>> outgoing; // vertex -> indices into slave.edges
    std::map<unsigned int, unsigned int>              n_incoming;
    for (unsigned int i = 0; i < slave.edges.size(); ++i)
      {
        outgoing[slave.edges[i][0]].push_back(i);
        ++n_incoming[slave.edges[i][1]];
      }
    std::map<unsigned int, unsigned int> vertex_order, edge_order;
    {
      std::vector<bool> visited(slave.edges.size(), false);
      unsigned int      counter = 0;
      const auto        walk    = [&](unsigned int v) {
        if (vertex_order.count(v) == 0)
          vertex_order[v] = counter++;
        while (true)
          {
            unsigned int next = invalid;
            const auto   it   = outgoing.find(v);
            if (it != outgoing.end())
              for (const unsigned int i : it->second)
                if (!visited[i])
                  {
                    next = i;
                    break;
                  }
            if (next == invalid)
              break;
            visited[next]    = true;
            edge_order[next] = counter++;
            v                = slave.edges[next][1];
            if (vertex_order.count(v) == 0)
              vertex_order[v] = counter++;
          }
      };
      // open chains first (from the vertices without incoming edge), then
      // closed loops
      for (const unsigned int v : slave.vertices)
        if (n_incoming.count(v) == 0)
          walk(v);
      for (unsigned int i = 0; i < slave.edges.size(); ++i)
        if (!visited[i])
          walk(slave.edges[i][0]);
    }

    std::vector<std::pair<unsigned int, ContactNodePair>> ordered;

    // vertex pairs
    std::map<unsigned int, double> weight;
    for (const auto &e : slave.edges)
      if (partner.count(e[0]) && partner.count(e[1]))
        {
          const double L = mesh.vertex(e[0]).distance(mesh.vertex(e[1]));
          const double w = (degree == 1 ? L / 2 : L / 6);
          weight[e[0]] += w;
          weight[e[1]] += w;
        }
    for (const auto &p : partner)
      {
        const auto w = weight.find(p.first);
        if (w == weight.end() || !(w->second > 0))
          continue; // isolated node: no paired sub-edge
        ContactNodePair pair;
        pair.master_entity   = p.second.first;
        pair.slave_entity    = p.first;
        pair.is_midpoint     = false;
        pair.master_location = mesh.vertex(pair.master_entity);
        pair.slave_location  = mesh.vertex(pair.slave_entity);
        pair.normal          = master_normal.at(pair.master_entity);
        pair.tangent         = tangent_of(pair.normal);
        pair.initial_gap     = (pair.slave_location - pair.master_location) * pair.normal;
        pair.weight          = w->second;
        pair.interface       = interface;
        ordered.emplace_back(vertex_order.at(p.first), pair);
      }

    // midpoint pairs
    if (degree == 2)
      for (unsigned int i = 0; i < slave.edges.size(); ++i)
        {
          const auto &e  = slave.edges[i];
          const auto  pa = partner.find(e[0]), pb = partner.find(e[1]);
          if (pa == partner.end() || pb == partner.end())
            continue;
          const auto me = master.edge_by_pair.find(key(pa->second.first, pb->second.first));
          if (me == master.edge_by_pair.end())
            continue;
          const auto &medge = mesh.edge(me->second).vertices;
          ContactNodePair pair;
          pair.master_entity   = me->second;
          pair.slave_entity    = slave.edge_indices[i];
          pair.is_midpoint     = true;
          pair.master_location = 0.5 * (mesh.vertex(medge[0]) + mesh.vertex(medge[1]));
          pair.slave_location  = 0.5 * (mesh.vertex(e[0]) + mesh.vertex(e[1]));
          pair.normal          = edge_normal(mesh, medge);
          pair.tangent         = tangent_of(pair.normal);
          pair.initial_gap     = (pair.slave_location - pair.master_location) * pair.normal;
          pair.weight          = 2. / 3. * mesh.vertex(e[0]).distance(mesh.vertex(e[1]));
          pair.interface       = interface;
          ordered.emplace_back(edge_order.at(i), pair);
        }

    std::sort(ordered.begin(), ordered.end(),
              [](const auto &x, const auto &y) { return x.first < y.first; });
    std::vector<ContactNodePair> pairs;
    pairs.reserve(ordered.size());
    for (const auto &o : ordered)
      pairs.push_back(o.second);
    return pairs;
  }
} // namespace dealvem
