// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/bounding_box.h>
#include <deal.II/numerics/rtree.h>

#include <dealvem/base/number_string.h>
#include <dealvem/contact/contact_detection.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <numeric>
#include <sstream>

namespace dealvem
{
  namespace ContactDetection
  {
    namespace
    {
      using Point = dealii::Point<2>;
      namespace bgi = boost::geometry::index;

      // A boundary edge as the search sees it: ends in the order of its
      // cell's counter-clockwise loop, so the outward normal is the
      // direction turned clockwise.
      struct EdgeGeometry
      {
        Point                a, b;
        dealii::Tensor<1, 2> t, n; // unit tangent a -> b, outward normal
        double               length = 0;
        unsigned int         body   = 0;
      };

      EdgeGeometry
      edge_geometry(const PolygonalMesh<2> &mesh, const unsigned int e)
      {
        const auto  &edge = mesh.edge(e);
        const auto  &loop = mesh.cell(edge.cells[0]).vertices;
        unsigned int v0 = edge.vertices[0], v1 = edge.vertices[1];
        const auto   it = std::find(loop.begin(), loop.end(), v0);
        if (loop[(it - loop.begin() + 1) % loop.size()] != v1)
          std::swap(v0, v1);
        EdgeGeometry g;
        g.a      = mesh.vertex(v0);
        g.b      = mesh.vertex(v1);
        g.length = g.a.distance(g.b);
        g.t      = (g.b - g.a) / g.length;
        g.n[0]   = g.t[1];
        g.n[1]   = -g.t[0];
        g.body   = mesh.cell(edge.cells[0]).material_id;
        return g;
      }

      double
      point_segment_distance(const Point &p, const EdgeGeometry &s)
      {
        const double u = std::clamp((p - s.a) * s.t, 0., s.length);
        return p.distance(s.a + u * s.t);
      }

      double
      cross(const dealii::Tensor<1, 2> &u, const dealii::Tensor<1, 2> &v)
      {
        return u[0] * v[1] - u[1] * v[0];
      }

      double
      segment_distance(const EdgeGeometry &e, const EdgeGeometry &f)
      {
        // crossing segments are at distance zero
        const double c1 = cross(e.b - e.a, f.a - e.a), c2 = cross(e.b - e.a, f.b - e.a);
        const double c3 = cross(f.b - f.a, e.a - f.a), c4 = cross(f.b - f.a, e.b - f.a);
        if (((c1 < 0 && c2 > 0) || (c1 > 0 && c2 < 0)) && ((c3 < 0 && c4 > 0) || (c3 > 0 && c4 < 0)))
          return 0;
        return std::min({point_segment_distance(e.a, f), point_segment_distance(e.b, f),
                         point_segment_distance(f.a, e), point_segment_distance(f.b, e)});
      }

      // Where edge f faces edge e: the range [s0, s1] of e (arc length from
      // e.a) covered by the projection of f; empty (s1 <= s0) otherwise.
      std::pair<double, double>
      facing_range(const EdgeGeometry &e, const EdgeGeometry &f, const Settings &settings)
      {
        const std::pair<double, double> none(0., 0.);
        if (e.body == f.body || e.n * f.n > -std::cos(settings.max_angle * M_PI / 180.))
          return none;
        if (segment_distance(e, f) > settings.distance * std::max(e.length, f.length))
          return none;
        const double sa = (f.a - e.a) * e.t, sb = (f.b - e.a) * e.t;
        const double s0 = std::max(0., std::min(sa, sb)), s1 = std::min(e.length, std::max(sa, sb));
        if (s1 - s0 <= settings.min_overlap * std::min(e.length, f.length))
          return none;
        return {s0, s1};
      }

      // For every candidate edge, the facing ranges per facing body.
      struct Facing
      {
        std::vector<unsigned int>                               candidates;
        std::vector<EdgeGeometry>                               geometry; // by mesh edge index
        std::vector<std::map<unsigned int, std::pair<double, double>>> ranges;   // by mesh edge index
        std::vector<std::map<unsigned int, double>>             overlap;  // by mesh edge index
        std::vector<std::vector<unsigned int>>                  partners; // facing edges
      };

      Facing
      find_facing(const PolygonalMesh<2>                     &mesh,
                  const std::set<dealii::types::boundary_id> &excluded_ids,
                  const Settings                             &settings)
      {
        Facing f;
        f.geometry.resize(mesh.n_edges());
        f.ranges.resize(mesh.n_edges());
        f.overlap.resize(mesh.n_edges());
        f.partners.resize(mesh.n_edges());
        std::vector<std::pair<dealii::BoundingBox<2>, unsigned int>> boxes;
        for (unsigned int e = 0; e < mesh.n_edges(); ++e)
          {
            const auto &edge = mesh.edge(e);
            if (!edge.at_boundary() || excluded_ids.count(edge.boundary_id) > 0)
              continue;
            f.candidates.push_back(e);
            const EdgeGeometry g = edge_geometry(mesh, e);
            f.geometry[e]        = g;
            const double r       = settings.distance * g.length;
            Point        lo, hi;
            for (unsigned int d = 0; d < 2; ++d)
              {
                lo[d] = std::min(g.a[d], g.b[d]) - r;
                hi[d] = std::max(g.a[d], g.b[d]) + r;
              }
            boxes.emplace_back(dealii::BoundingBox<2>(std::make_pair(lo, hi)), e);
          }
        const auto tree = dealii::pack_rtree(boxes);
        std::vector<std::pair<dealii::BoundingBox<2>, unsigned int>> hits;
        for (const auto &box : boxes)
          {
            const unsigned int e = box.second;
            hits.clear();
            tree.query(bgi::intersects(box.first), std::back_inserter(hits));
            // the query's order is the tree's: sort for a result that does
            // not depend on it
            std::sort(hits.begin(), hits.end(),
                      [](const auto &x, const auto &y) { return x.second < y.second; });
            for (const auto &hit : hits)
              {
                const unsigned int other = hit.second;
                const auto r = facing_range(f.geometry[e], f.geometry[other], settings);
                if (r.second <= r.first)
                  continue;
                const unsigned int B = f.geometry[other].body;
                auto               it = f.ranges[e].find(B);
                if (it == f.ranges[e].end())
                  f.ranges[e][B] = r;
                else
                  it->second = {std::min(it->second.first, r.first), std::max(it->second.second, r.second)};
                f.overlap[e][B] += r.second - r.first;
                f.partners[e].push_back(other);
              }
          }
        return f;
      }

      struct UnionFind
      {
        std::vector<unsigned int> parent;
        explicit UnionFind(const unsigned int n)
          : parent(n)
        {
          std::iota(parent.begin(), parent.end(), 0u);
        }
        unsigned int
        find(unsigned int i)
        {
          while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
          return i;
        }
        void
        join(const unsigned int i, const unsigned int j)
        {
          const unsigned int a = find(i), b = find(j);
          if (a != b)
            parent[std::max(a, b)] = std::min(a, b);
        }
      };


      // Rule 2: an edge facing several bodies is split where their ranges
      // meet.
      void
      split_facing_edges(PolygonalMesh<2>                           &mesh,
                         const std::set<dealii::types::boundary_id> &excluded_ids,
                         const Settings                             &settings,
                         Result                                     &result)
      {
        const Facing facing = find_facing(mesh, excluded_ids, settings);
        for (const unsigned int e : facing.candidates)
          {
            if (facing.ranges[e].size() < 2)
              continue;
            std::vector<std::pair<double, double>> ranges;
            for (const auto &r : facing.ranges[e])
              ranges.push_back(r.second);
            std::sort(ranges.begin(), ranges.end(), [](const auto &x, const auto &y) {
              return x.first + x.second < y.first + y.second;
            });
            const EdgeGeometry &g = facing.geometry[e];
            std::vector<double> cuts;
            for (unsigned int i = 1; i < ranges.size(); ++i)
              {
                const double s = 0.5 * (ranges[i - 1].second + ranges[i].first);
                if (s > settings.merge_fraction * g.length && s < (1 - settings.merge_fraction) * g.length &&
                    (cuts.empty() || s > cuts.back() + settings.merge_fraction * g.length))
                  cuts.push_back(s);
              }
            // split_edge() keeps the first piece under the index of the
            // edge and appends the second: cut the last piece each time
            unsigned int piece = e;
            for (const double s : cuts)
              {
                // the piece runs along g in the direction of the loop, or
                // against it; split_edge() takes the point either way
                mesh.split_edge(piece, g.a + s * g.t);
                ++result.n_split_edges;
                // the piece beyond the cut (towards g.b) is the one to cut next
                const unsigned int appended           = mesh.n_edges() - 1;
                const auto        &ev                 = mesh.edge(appended).vertices;
                const bool         appended_is_beyond = (mesh.vertex(ev[0]).distance(g.b) < 1e-12 * g.length ||
                                                 mesh.vertex(ev[1]).distance(g.b) < 1e-12 * g.length);
                piece                                 = appended_is_beyond ? appended : piece;
              }
          }
      }



      // Rule 1: per candidate edge the body it overlaps most (invalid for
      // the other edges).
      std::vector<unsigned int>
      facing_bodies(const PolygonalMesh<2> &mesh, const Facing &facing)
      {
        std::vector<unsigned int> facing_body(mesh.n_edges(), dealii::numbers::invalid_unsigned_int);
        for (const unsigned int e : facing.candidates)
          {
            double best = 0;
            for (const auto &o : facing.overlap[e])
              if (o.second > best)
                {
                  best           = o.second;
                  facing_body[e] = o.first;
                }
          }
        return facing_body;
      }



      // Rule 3: chains of one body facing another (edges meeting at a
      // vertex at an angle below the corner angle), joined across the
      // interface.
      void
      join_chains(const PolygonalMesh<2>          &mesh,
                  const Facing                    &facing,
                  const std::vector<unsigned int> &facing_body,
                  const Settings                  &settings,
                  UnionFind                       &groups)
      {
        const unsigned int                                none = dealii::numbers::invalid_unsigned_int;
        std::map<unsigned int, std::vector<unsigned int>> at_vertex;
        for (const unsigned int e : facing.candidates)
          if (facing_body[e] != none)
            for (const unsigned int v : mesh.edge(e).vertices)
              at_vertex[v].push_back(e);
        const double cos_corner = std::cos(settings.corner_angle * M_PI / 180.);
        for (const auto &v : at_vertex)
          for (unsigned int i = 0; i < v.second.size(); ++i)
            for (unsigned int j = i + 1; j < v.second.size(); ++j)
              {
                const unsigned int e = v.second[i], f = v.second[j];
                if (facing.geometry[e].body == facing.geometry[f].body && facing_body[e] == facing_body[f] &&
                    facing.geometry[e].n * facing.geometry[f].n >= cos_corner)
                  groups.join(e, f);
              }
        for (const unsigned int e : facing.candidates)
          for (const unsigned int f : facing.partners[e])
            if (facing_body[e] == facing.geometry[f].body && facing_body[f] == facing.geometry[e].body)
              groups.join(e, f);
      }



      // A chain of joined edges: its two bodies (lower first), its first
      // edge and its edges.
      struct Group
      {
        unsigned int              low, high, first;
        std::vector<unsigned int> edges;
      };

      // Rule 4: the chains with edges on both sides, in the order of their
      // bodies and first edges.
      std::vector<Group>
      sorted_groups(const Facing &facing, const std::vector<unsigned int> &facing_body, UnionFind &groups)
      {
        std::map<unsigned int, std::vector<unsigned int>> members;
        for (const unsigned int e : facing.candidates)
          if (facing_body[e] != dealii::numbers::invalid_unsigned_int)
            members[groups.find(e)].push_back(e);
        std::vector<Group> list;
        for (auto &m : members)
          {
            Group g;
            g.low   = std::min(facing.geometry[m.second[0]].body, facing_body[m.second[0]]);
            g.high  = std::max(facing.geometry[m.second[0]].body, facing_body[m.second[0]]);
            g.first = *std::min_element(m.second.begin(), m.second.end());
            g.edges = std::move(m.second);
            // a chain whose partner chain is missing (every facing partner
            // assigned elsewhere) is no interface
            bool both = false;
            for (const unsigned int e : g.edges)
              both = both || facing.geometry[e].body != facing.geometry[g.edges[0]].body;
            if (both)
              list.push_back(std::move(g));
          }
        std::sort(list.begin(), list.end(), [](const Group &x, const Group &y) {
          return std::tie(x.low, x.high, x.first) < std::tie(y.low, y.high, y.first);
        });
        return list;
      }



      // Rule 5: the interface of chain @p k, its master (the coarser side)
      // and its ids, set on the edges.
      Interface
      make_interface(PolygonalMesh<2>                &mesh,
                     const Facing                    &facing,
                     const Group                     &g,
                     const unsigned int               k,
                     const dealii::types::boundary_id first_id)
      {
        double       length[2] = {0, 0};
        unsigned int count[2]  = {0, 0};
        for (const unsigned int e : g.edges)
          {
            const unsigned int side = (facing.geometry[e].body == g.low ? 0 : 1);
            length[side] += facing.geometry[e].length;
            ++count[side];
          }
        const double h[2] = {length[0] / count[0], length[1] / count[1]};
        // the coarser side is the master; the lower body on a tie
        const unsigned int master = (h[1] > h[0] * (1 + 1e-9)) ? 1 : 0;
        Interface          itf;
        itf.master_body    = (master == 0 ? g.low : g.high);
        itf.slave_body     = (master == 0 ? g.high : g.low);
        itf.master_id      = first_id + 2 * k;
        itf.slave_id       = first_id + 2 * k + 1;
        itf.n_master_edges = count[master];
        itf.n_slave_edges  = count[1 - master];
        itf.master_h       = h[master];
        itf.slave_h        = h[1 - master];
        itf.length         = std::min(length[0], length[1]);
        for (const unsigned int e : g.edges)
          mesh.set_edge_boundary_id(e, facing.geometry[e].body == itf.master_body ? itf.master_id : itf.slave_id);
        return itf;
      }
    } // namespace



    dealii::types::boundary_id
    first_free_id(const PolygonalMesh<2> &mesh)
    {
      dealii::types::boundary_id id = 1000;
      for (unsigned int e = 0; e < mesh.n_edges(); ++e)
        if (mesh.edge(e).at_boundary())
          id = std::max<dealii::types::boundary_id>(id, mesh.edge(e).boundary_id + 1);
      return id;
    }



    Result
    detect(PolygonalMesh<2>                           &mesh,
           const std::set<dealii::types::boundary_id> &excluded_ids,
           const dealii::types::boundary_id            first_id,
           const Settings                             &settings)
    {
      AssertThrow(settings.distance >= 0 && settings.max_angle > 0 && settings.max_angle < 90 &&
                    settings.min_overlap >= 0 && settings.min_overlap < 1 && settings.corner_angle > 0 &&
                    settings.corner_angle < 180 && settings.merge_fraction >= 0 && settings.merge_fraction < 0.5,
                  dealii::ExcMessage("ContactDetection::detect(): a setting is out of range (distance >= 0, "
                                     "0 < max angle < 90, 0 <= overlap < 1, 0 < corner angle < 180, "
                                     "0 <= merge fraction < 0.5)."));
      for (unsigned int e = 0; e < mesh.n_edges(); ++e)
        AssertThrow(!mesh.edge(e).at_boundary() || mesh.edge(e).boundary_id < first_id,
                    dealii::ExcMessage("ContactDetection::detect(): boundary id " +
                                       std::to_string(mesh.edge(e).boundary_id) + " is in use, but the ids of "
                                       "detected interfaces start at " + std::to_string(first_id) + "."));
      Result result;

      // rule 2: an edge facing several bodies is split where their ranges meet
      if (settings.split_edges)
        split_facing_edges(mesh, excluded_ids, settings, result);

      // rule 1 again on the split mesh: each edge faces the body it
      // overlaps most
      const Facing facing      = find_facing(mesh, excluded_ids, settings);
      result.n_candidate_edges = facing.candidates.size();
      const auto facing_body   = facing_bodies(mesh, facing);

      // rule 3: chains of one body facing another, joined across the
      // interface
      UnionFind groups(mesh.n_edges());
      join_chains(mesh, facing, facing_body, settings, groups);

      // rules 4 and 5: master, order, ids
      const std::vector<Group> list = sorted_groups(facing, facing_body, groups);
      for (unsigned int k = 0; k < list.size(); ++k)
        result.interfaces.push_back(make_interface(mesh, facing, list[k], k, first_id));
      return result;
    }



    std::string
    describe(const Result &result)
    {
      std::ostringstream out;
      out << "  " << result.interfaces.size() << " contact interface(s) detected (Pairs = auto; "
          << result.n_candidate_edges << " candidate boundary edges";
      if (result.n_split_edges > 0)
        out << ", " << result.n_split_edges << " edge(s) split where they face two bodies";
      out << "):\n";
      out << "    interface  master body : slave body   boundary ids    edges (master/slave)   length\n";
      for (unsigned int k = 0; k < result.interfaces.size(); ++k)
        {
          const auto &i = result.interfaces[k];
          out << "    " << std::setw(9) << k << "  " << std::setw(11) << i.master_body << " : " << std::setw(10)
              << std::left << i.slave_body << std::right << "   " << std::setw(6) << i.master_id << " : "
              << std::setw(6) << std::left << i.slave_id << std::right << "   " << std::setw(8)
              << i.n_master_edges << " / " << std::setw(6) << std::left << i.n_slave_edges << std::right
              << "   " << internal::number_string(i.length) << "\n";
        }
      return out.str();
    }
  } // namespace ContactDetection
} // namespace dealvem
