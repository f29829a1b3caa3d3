// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// NodeInsertion: the sides of an interface (collected from the boundary
// ids, with their normals and arcs), the checks of an interface, and the
// projections and casts of points onto a side.

#include "node_insertion_side.h"

namespace dealvem
{
  namespace internal
  {
    namespace node_insertion
    {
    // The boundary edges with id @p id among the candidates (see collect_side()),
    // with their cells' materials.
    void
    add_side_edges(const Mesh &mesh, const dealii::types::boundary_id id, const std::vector<unsigned int> *known,
                   const unsigned int first_new, Side &side)
    {
      std::vector<unsigned int> candidates;
      if (known != nullptr)
        candidates = *known;
      for (unsigned int e = (known != nullptr ? first_new : 0); e < mesh.n_edges(); ++e)
        candidates.push_back(e);
      for (const unsigned int e : candidates)
        {
          if (e >= mesh.n_edges())
            continue;
          const auto &edge = mesh.edge(e);
          if (!edge.at_boundary() || edge.boundary_id != id)
            continue;
          const unsigned int i = side.edges.size();
          side.edges.push_back(edge.vertices);
          side.edge_indices.push_back(e);
          side.edge_by_pair[key(edge.vertices[0], edge.vertices[1])] = i;
          side.materials.insert(mesh.cell(edge.cells[0]).material_id);
          AssertThrow(side.outgoing.count(edge.vertices[0]) == 0 && side.incoming.count(edge.vertices[1]) == 0,
                      dealii::ExcMessage("contact interface: the boundary part with id " + std::to_string(id) +
                                         " of mesh '" + mesh.name + "' touches itself at vertex " +
                                         std::to_string(edge.vertices[side.outgoing.count(edge.vertices[0]) ? 0 : 1]) +
                                         " " + point_string(mesh.vertex(edge.vertices[side.outgoing.count(edge.vertices[0]) ? 0 : 1])) +
                                         "; split it into parts that are simple curves."));
          side.outgoing[edge.vertices[0]] = i;
          side.incoming[edge.vertices[1]] = i;
        }
    }



    // The chains of the side's edges.
    void
    make_side_chains(Side &side)
    {
      // chains: open ones from the vertices without an incoming edge, then loops
      std::vector<bool> visited(side.edges.size(), false);
      const auto        walk = [&](const unsigned int start, const bool loop) {
        std::vector<unsigned int> chain{start};
        unsigned int              v = start;
        while (true)
          {
            const auto it = side.outgoing.find(v);
            if (it == side.outgoing.end() || visited[it->second])
              break;
            visited[it->second] = true;
            v                   = side.edges[it->second][1];
            if (loop && v == start)
              break;
            chain.push_back(v);
          }
        side.chains.push_back(chain);
        side.closed.push_back(loop);
      };
      for (const auto &o : side.outgoing)
        if (side.incoming.count(o.first) == 0)
          walk(o.first, false);
      for (unsigned int i = 0; i < side.edges.size(); ++i)
        if (!visited[i])
          walk(side.edges[i][0], true);
    }



    // The shortest edge and the average chord normal at each vertex.
    void
    set_side_lengths_and_normals(const Mesh &mesh, Side &side)
    {
      // per vertex: local edge length and normal
      for (unsigned int i = 0; i < side.edges.size(); ++i)
        {
          const Point &a = mesh.vertex(side.edges[i][0]), &b = mesh.vertex(side.edges[i][1]);
          const double L = a.distance(b);
          const Vector n = edge_normal(a, b);
          for (const unsigned int v : side.edges[i])
            {
              const auto it = side.h.find(v);
              side.h[v]     = (it == side.h.end() ? L : std::min(it->second, L));
              side.normal[v] += n;
            }
        }
      for (auto &n : side.normal)
        n.second /= n.second.norm();
    }



    // The curvatures of the vertices (Side::kappa, Side::kappa_gap).
    void
    set_side_curvatures(const Mesh &mesh, Side &side)
    {
      // curvature: the circle through a vertex and its neighbours, kept only
      // where the neighbours agree (a smooth curve, not a single kink)
      std::map<unsigned int, double> raw;
      for (unsigned int c = 0; c < side.chains.size(); ++c)
        {
          const auto        &chain = side.chains[c];
          const unsigned int n     = chain.size();
          for (unsigned int i = 0; i < n; ++i)
            {
              const bool interior = side.closed[c] || (i > 0 && i + 1 < n);
              raw[chain[i]]       = interior ? menger_curvature(mesh.vertex(chain[(i + n - 1) % n]),
                                                                mesh.vertex(chain[i]),
                                                                mesh.vertex(chain[(i + 1) % n])) :
                                               std::numeric_limits<double>::quiet_NaN();
            }
          const auto agree = [](const double k1, const double k2) {
            return std::isnan(k2) || (k1 * k2 > 0 && std::abs(k2) <= 3 * std::abs(k1) && std::abs(k1) <= 3 * std::abs(k2));
          };
          for (unsigned int i = 0; i < n; ++i)
            {
              const double k = raw[chain[i]];
              double       smooth = 0;
              if (!std::isnan(k) && k != 0)
                {
                  const bool has_prev = side.closed[c] || i > 0, has_next = side.closed[c] || i + 1 < n;
                  const double kp = has_prev ? raw[chain[(i + n - 1) % n]] : std::numeric_limits<double>::quiet_NaN();
                  const double kn = has_next ? raw[chain[(i + 1) % n]] : std::numeric_limits<double>::quiet_NaN();
                  if (agree(k, kp) && agree(k, kn) && !(std::isnan(kp) && std::isnan(kn)))
                    smooth = k;
                }
              side.kappa[chain[i]] = smooth;
            }
          for (unsigned int i = 0; i < n; ++i)
            if (side.closed[c] || (i > 0 && i + 1 < n))
              {
                const Point &a = mesh.vertex(chain[(i + n - 1) % n]), &b = mesh.vertex(chain[i]),
                            &d = mesh.vertex(chain[(i + 1) % n]);
                const Vector d1 = b - a, d2 = d - b;
                // a turn above 60 degrees is a corner (sin 60 = 0.866)
                if ((d1 * d2) > 0 && std::abs(cross(d1, d2)) <= 0.866 * d1.norm() * d2.norm())
                  side.kappa_gap[chain[i]] = menger_curvature(a, b, d, 1.);
              }
          // chain ends take the curvature of their neighbour
          if (!side.closed[c] && n >= 3)
            {
              side.kappa[chain[0]]     = side.kappa[chain[1]];
              side.kappa[chain[n - 1]] = side.kappa[chain[n - 2]];
            }
        }
    }



    // The grown bounding boxes of the edges and their R-tree.
    void
    make_side_edge_tree(const Mesh &mesh, Side &side)
    {
      std::vector<std::pair<dealii::BoundingBox<2>, unsigned int>> boxes;
      side.lo = Point(std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
      side.hi = -side.lo;
      for (unsigned int i = 0; i < side.edges.size(); ++i)
        {
          const Point &a = mesh.vertex(side.edges[i][0]), &b = mesh.vertex(side.edges[i][1]);
          const double r = 0.5 * a.distance(b);
          Point        lo, hi;
          for (unsigned int d = 0; d < 2; ++d)
            {
              lo[d]      = std::min(a[d], b[d]) - r;
              hi[d]      = std::max(a[d], b[d]) + r;
              side.lo[d] = std::min(side.lo[d], lo[d]);
              side.hi[d] = std::max(side.hi[d], hi[d]);
            }
          boxes.emplace_back(dealii::BoundingBox<2>(std::make_pair(lo, hi)), i);
        }
      side.edge_tree = dealii::pack_rtree(boxes);
    }



    // The curvature of each edge, and the vertex normals of the curve the
    // side follows.
    void
    set_side_curve_normals(const Mesh &mesh, Side &side)
    {
      side.edge_kappa.resize(side.edges.size());
      for (unsigned int i = 0; i < side.edges.size(); ++i)
        {
          const double ka = side.kappa[side.edges[i][0]], kb = side.kappa[side.edges[i][1]];
          side.edge_kappa[i] = (ka * kb > 0 ? (std::abs(ka) < std::abs(kb) ? ka : kb) : 0.);
        }

      // where a side follows a smooth curve, the vertex normal is the normal
      // of that curve (the circles of the edges at the vertex, averaged),
      // not the average of the chord normals: at an end of the side, or
      // between chords of different lengths, the two differ by up to half
      // the chord's turning angle
      for (auto &n : side.normal)
        n.second = Vector();
      for (unsigned int i = 0; i < side.edges.size(); ++i)
        {
          const Point &a = mesh.vertex(side.edges[i][0]), &b = mesh.vertex(side.edges[i][1]);
          const Vector n = edge_normal(a, b);
          const double x = 0.5 * a.distance(b) * side.edge_kappa[i];
          const double turn = (std::abs(x) < 1 ? std::asin(x) : 0.);
          for (unsigned int end = 0; end < 2; ++end) // at a: turned back, at b: on
            {
              const double phi = (end == 0 ? -turn : turn);
              Vector       r;
              r[0] = n[0] * std::cos(phi) - n[1] * std::sin(phi);
              r[1] = n[0] * std::sin(phi) + n[1] * std::cos(phi);
              side.normal[side.edges[i][end]] += r;
            }
        }
      for (auto &n : side.normal)
        n.second /= n.second.norm();
    }



    // The edges with boundary id @p id: those of @p known (ascending mesh
    // edge indices) that still carry it, and the edges from @p first_new on;
    // without @p known every edge of the mesh is looked at.
    Side
    collect_side(const Mesh                      &mesh,
                 const dealii::types::boundary_id id,
                 const std::vector<unsigned int> *known,
                 const unsigned int               first_new)
    {
      Side side;
      side.id           = id;
      side.n_mesh_edges = mesh.n_edges();
      add_side_edges(mesh, id, known, first_new, side);
      make_side_chains(side);
      set_side_lengths_and_normals(mesh, side);
      set_side_curvatures(mesh, side);
      make_side_edge_tree(mesh, side);
      set_side_curve_normals(mesh, side);
      return side;
    }



    // every edge of the mesh looked at
    Side
    collect_side(const Mesh &mesh, const dealii::types::boundary_id id)
    {
      return collect_side(mesh, id, nullptr, 0);
    }



    // the side again after the mesh changed: its edges (split edges keep
    // their index) and the edges added since
    Side
    collect_side(const Mesh &mesh, const Side &previous)
    {
      return collect_side(mesh, previous.id, &previous.edge_indices, previous.n_mesh_edges);
    }



    std::string
    materials_string(const std::set<dealii::types::material_id> &m)
    {
      std::string s;
      for (const auto id : m)
        s += (s.empty() ? "" : ", ") + std::to_string(id);
      return s;
    }



    void
    check_interface(const Mesh                      &mesh,
                    const dealii::types::boundary_id master_id,
                    const dealii::types::boundary_id slave_id,
                    const Side                      &master,
                    const Side                      &slave,
                    const NodeInsertion::Settings   &settings)
    {
      const std::string name = interface_name(master_id, slave_id);
      AssertThrow(settings.merge_fraction > 0 && settings.merge_fraction < 0.5,
                  dealii::ExcMessage(name + "the merge fraction must lie in (0, 0.5), but it is " +
                                     number_string(settings.merge_fraction) + "."));
      AssertThrow(settings.search_distance > 0 && std::isfinite(settings.search_distance),
                  dealii::ExcMessage(name + "the search distance must be positive and finite, but it is " +
                                     number_string(settings.search_distance) + "."));
      AssertThrow(settings.coordinate_precision == NodeInsertion::Settings::detect_precision ||
                    (settings.coordinate_precision >= 0 && settings.coordinate_precision < 1e-2),
                  dealii::ExcMessage(name + "the coordinate precision must be 'auto' (detected) or lie in "
                                            "[0, 0.01), but it is " +
                                     number_string(settings.coordinate_precision) + "."));
      AssertThrow(settings.curvature_factor >= 0 && settings.curvature_factor <= 10,
                  dealii::ExcMessage(name + "the curvature factor must lie in [0, 10], but it is " +
                                     number_string(settings.curvature_factor) + "."));
      for (const auto &s : {std::make_pair(master_id, &master), std::make_pair(slave_id, &slave)})
        AssertThrow(!s.second->edges.empty(),
                    dealii::ExcMessage(name + "boundary id " + std::to_string(s.first) +
                                       " has no boundary edges in mesh '" + mesh.name + "'."));
      for (const auto &s : {std::make_pair(master_id, &master), std::make_pair(slave_id, &slave)})
        AssertThrow(s.second->materials.size() == 1,
                    dealii::ExcMessage(name + "the boundary edges with id " + std::to_string(s.first) +
                                       " belong to more than one body (material ids " +
                                       materials_string(s.second->materials) +
                                       "); each side of a contact interface must lie on one body."));
      AssertThrow(*master.materials.begin() != *slave.materials.begin(),
                  dealii::ExcMessage(name + "both boundary ids " + std::to_string(master_id) + " and " +
                                     std::to_string(slave_id) + " belong to the same body (material id " +
                                     std::to_string(*master.materials.begin()) +
                                     "); a contact interface joins two different bodies."));
    }



    /**
     * Complete a projection found on edge best.edge at the unclamped edge
     * parameter @p unclamped: beyond an end of the side it is accepted only
     * within the merge distance of the end vertex; the outward normal of the
     * side there (the vertex normal at an end of the edge) must be opposed
     * to @p own_normal.
     */
    void
    classify(const Mesh &mesh, const Side &side, const double unclamped, const Vector &own_normal,
             const double merge_fraction, Projection &best)
    {
      const unsigned int end_vertex = side.edges[best.edge][unclamped < 0.5 ? 0 : 1];
      const double       beyond     = (unclamped < 0 ? -unclamped : unclamped - 1) * best.length;
      best.inside = (beyond <= 0) || !side.is_end(end_vertex) ||
                    beyond <= merge_fraction * side.h.at(end_vertex);
      const Vector other_normal =
        (best.t == 0 || best.t == 1) ? side.normal.at(side.edges[best.edge][best.t == 0 ? 0 : 1]) :
                                       edge_normal(mesh.vertex(side.edges[best.edge][0]),
                                                   mesh.vertex(side.edges[best.edge][1]));
      best.normal_cosine = other_normal * own_normal;
      best.facing        = best.normal_cosine <= -0.5;
    }



    Projection
    project(const Mesh &mesh, const Side &side, const Point &p, const Vector &own_normal,
            const double merge_fraction)
    {
      // distance from p to edge i, as the search below computes it
      const auto distance_to = [&](const unsigned int i) {
        const Point &a = mesh.vertex(side.edges[i][0]), &b = mesh.vertex(side.edges[i][1]);
        const Vector d = b - a;
        return p.distance(a + std::min(1., std::max(0., ((p - a) * d) / (d * d))) * d);
      };
      // Candidates: the edge of the box nearest to p is at some distance D;
      // every edge at most D from p has its box within D of p, so the query
      // of the square of half-width D (a little more, against round-off)
      // returns every edge that can be the closest. In index order, the
      // loop below then finds the same edge as a loop over all edges.
      std::vector<std::pair<dealii::BoundingBox<2>, unsigned int>> hits;
      side.edge_tree.query(boost::geometry::index::nearest(p, 1), std::back_inserter(hits));
      std::vector<unsigned int> candidates;
      if (!hits.empty())
        {
          const double r = distance_to(hits[0].second) * (1 + 1e-9) + 1e-12 * side.lo.distance(side.hi);
          const dealii::BoundingBox<2> square(
            std::make_pair(Point(p[0] - r, p[1] - r), Point(p[0] + r, p[1] + r)));
          hits.clear();
          side.edge_tree.query(boost::geometry::index::intersects(square), std::back_inserter(hits));
          for (const auto &h : hits)
            candidates.push_back(h.second);
          std::sort(candidates.begin(), candidates.end());
        }

      Projection best;
      double     best_distance = std::numeric_limits<double>::max();
      double     unclamped     = 0;
      for (const unsigned int i : candidates)
        {
          const Point &a = mesh.vertex(side.edges[i][0]), &b = mesh.vertex(side.edges[i][1]);
          const Vector d  = b - a;
          const double L2 = d * d;
          const double s  = ((p - a) * d) / L2;
          const double t  = std::min(1., std::max(0., s));
          const Point  x  = a + t * d;
          const double dist = p.distance(x);
          if (dist < best_distance)
            {
              best_distance = dist;
              unclamped     = s;
              best.edge     = i;
              best.t        = t;
              best.length   = std::sqrt(L2);
              best.point    = x;
            }
        }
      best.distance = best_distance;
      // (no edge found: p is not a finite point, or the side's search
      // structure holds nothing)
      AssertThrow(best.edge != invalid,
                  dealii::ExcMessage("NodeInsertion: the point (" + std::to_string(p[0]) + ", " +
                                     std::to_string(p[1]) + ") has no closest point on the side with boundary id " +
                                     std::to_string(int(side.id)) + " (" + std::to_string(side.edges.size()) +
                                     " edges): a coordinate is not finite, or the side is empty."));
      classify(mesh, side, unclamped, own_normal, merge_fraction, best);
      return best;
    }



    /**
     * The point of @p side hit by the line through @p p along @p direction
     * (the master normal at a master vertex), nearest to @p p. Master
     * vertices are carried over to the slave side this way, and slave
     * vertices onto the master side by their closest point, which is the
     * same map (along the master normals) read backwards: the two cannot
     * cross.
     */
    Projection
    cast(const Mesh &mesh, const Side &side, const Point &p, const Vector &direction,
         const double merge_fraction)
    {
      // Candidates: a hit lies on the line through p along direction, at
      // most half an edge length beyond its edge, hence inside the edge's
      // grown box, and within R of p; the boxes crossed by that piece of
      // the line are all edges that can be hit. In index order, the loop
      // below then finds the same edge as a loop over all edges.
      std::vector<unsigned int> candidates;
      {
        double R = 0;
        for (const double x : {side.lo[0], side.hi[0]})
          for (const double y : {side.lo[1], side.hi[1]})
            R = std::max(R, p.distance(Point(x, y)));
        R = 2 * R + 1e-12 * side.lo.distance(side.hi);
        const dealii::Segment<2> line(p - R * direction, p + R * direction);
        std::vector<std::pair<dealii::BoundingBox<2>, unsigned int>> hits;
        side.edge_tree.query(boost::geometry::index::intersects(line), std::back_inserter(hits));
        for (const auto &h : hits)
          candidates.push_back(h.second);
        std::sort(candidates.begin(), candidates.end());
      }

      Projection   best;
      double       best_distance = std::numeric_limits<double>::max();
      double       unclamped     = 0;
      for (const unsigned int i : candidates)
        {
          const Point &a = mesh.vertex(side.edges[i][0]), &b = mesh.vertex(side.edges[i][1]);
          const Vector d     = b - a;
          const double L     = d.norm();
          const double denom = cross(d, direction);
          if (std::abs(denom) <= 1e-12 * L)
            continue; // the line runs along the edge
          const double t   = cross(p - a, direction) / denom;
          const double tau = cross(p - a, d) / denom;
          // accept hits slightly beyond the ends of the edge (decided below)
          const double slack = merge_fraction * side.h.at(side.edges[i][t < 0.5 ? 0 : 1]) / L;
          if (t < -slack || t > 1 + slack)
            continue;
          if (std::abs(tau) < best_distance)
            {
              best_distance = std::abs(tau);
              unclamped     = t;
              best.edge     = i;
              best.t        = std::min(1., std::max(0., t));
              best.length   = L;
              best.point    = a + best.t * d;
            }
        }
      if (best.edge == invalid)
        return best; // inside = false
      best.distance = p.distance(best.point);
      // (a hit inside the edge is inside the side; classify() decides the rest)
      classify(mesh, side, unclamped, direction, merge_fraction, best);
      return best;
    }
    } // namespace node_insertion
  } // namespace internal
} // namespace dealvem
