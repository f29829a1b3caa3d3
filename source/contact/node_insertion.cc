// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/numerics/rtree.h>

#include <dealvem/base/number_string.h>
#include <dealvem/contact/node_insertion.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <utility>

namespace dealvem
{
  namespace
  {
    using Mesh       = PolygonalMesh<2>;
    using Point      = dealii::Point<2>;
    using Vector     = dealii::Tensor<1, 2>;
    using VertexPair = std::pair<unsigned int, unsigned int>;

    constexpr unsigned int invalid = dealii::numbers::invalid_unsigned_int;

    VertexPair
    key(const unsigned int a, const unsigned int b)
    {
      return a < b ? VertexPair(a, b) : VertexPair(b, a);
    }

    double
    cross(const Vector &a, const Vector &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    std::string
    interface_name(const dealii::types::boundary_id master_id,
                   const dealii::types::boundary_id slave_id)
    {
      return "contact interface (master id " + std::to_string(master_id) + ", slave id " +
             std::to_string(slave_id) + "): ";
    }

    using internal::number_string;
    using internal::point_string;

    /// Outward unit normal of a boundary edge a -> b (counter-clockwise
    /// order of its cell: the body lies on the left).
    Vector
    edge_normal(const Point &a, const Point &b)
    {
      Vector t = b - a;
      t /= t.norm();
      Vector n;
      n[0] = t[1];
      n[1] = -t[0];
      return n;
    }

    Vector
    tangent_of(const Vector &n)
    {
      Vector t;
      t[0] = -n[1];
      t[1] = n[0];
      return t;
    }

    /**
     * One side of an interface: its boundary edges (vertex pairs in the
     * counter-clockwise order of the owning cell), the chains they form,
     * and per vertex the local edge length, outward normal and curvature.
     */
    struct Side
    {
      dealii::types::boundary_id               id = 0;
      std::vector<std::array<unsigned int, 2>> edges;
      std::vector<unsigned int>                edge_indices; ///< mesh edge of edges[i], ascending
      /// The number of mesh edges when the side was collected (the edges
      /// added since are the only new candidates of a later collection).
      unsigned int                             n_mesh_edges = 0;
      std::set<dealii::types::material_id>     materials;
      std::map<VertexPair, unsigned int>       edge_by_pair; ///< -> index into edges
      std::map<unsigned int, unsigned int>     outgoing, incoming; ///< vertex -> index into edges
      /// Vertices in chain order; a closed chain does not repeat its first vertex.
      std::vector<std::vector<unsigned int>>   chains;
      std::vector<bool>                        closed;
      std::map<unsigned int, double>           h;      ///< shortest side edge at the vertex
      std::map<unsigned int, Vector>           normal; ///< averaged outward normal
      std::map<unsigned int, double>           kappa;  ///< smooth signed curvature, 0 at kinks
      std::vector<double>                      edge_kappa;     ///< smooth, for placing new vertices
      /// Circle through the vertex and its neighbours for the gap rule:
      /// interior vertices turning by less than 60 degrees (a coarse
      /// sampling of a curve turns that much); absent at chain ends and
      /// sharper corners.
      std::map<unsigned int, double>           kappa_gap;
      /// The edges' bounding boxes grown by half the edge length on every
      /// side (a hit of cast() lies at most merge_fraction < 1/2 edge lengths
      /// beyond an end), with the index into edges: the candidate search of
      /// project() and cast().
      dealii::RTree<std::pair<dealii::BoundingBox<2>, unsigned int>> edge_tree;
      Point lo, hi; ///< corners of the union of those boxes

      bool
      is_end(const unsigned int v) const
      {
        return outgoing.count(v) == 0 || incoming.count(v) == 0;
      }
    };

    /// Signed curvature (convex > 0) of the circle through a, b, c, or 0 if
    /// the side turns at b by more than the angle whose sine is
    /// @p corner_sine (default 30 degrees: a corner, not a curve).
    double
    menger_curvature(const Point &a, const Point &b, const Point &c, const double corner_sine = 0.5)
    {
      const Vector d1 = b - a, d2 = c - b;
      const double l1 = d1.norm(), l2 = d2.norm(), l3 = (c - a).norm();
      if (l1 == 0 || l2 == 0 || l3 == 0)
        return 0;
      const double sine = cross(d1, d2) / (l1 * l2);
      // a turn of round-off size is a straight side, not a circle of
      // enormous radius: the arc through points 1e16 away from its centre
      // would place a new vertex wrongly by the size of the coordinates
      if ((d1 * d2) <= 0 || std::abs(sine) > corner_sine || std::abs(sine) < 1e-9)
        return 0;
      return 2 * cross(d1, d2) / (l1 * l2 * l3);
    }

    /**
     * The circle through the ends a, b of a chord with signed curvature
     * @p kappa (convex > 0 for the side whose outward chord normal is
     * edge_normal(a, b)): the curve a side is taken to follow between two
     * vertices where it approximates a smooth curve.
     */
    struct Arc
    {
      bool   valid = false;
      Point  centre;
      double radius = 0;
    };

    Arc
    arc_of(const Point &a, const Point &b, const double kappa)
    {
      Arc          arc;
      const double L = a.distance(b);
      // (|kappa| L below 1e-9: straight to round-off, see menger_curvature())
      if (kappa == 0 || !std::isfinite(kappa) || std::abs(kappa) * L >= 2 || std::abs(kappa) * L < 1e-9)
        return arc;
      arc.radius     = 1. / std::abs(kappa);
      const double s = std::sqrt(arc.radius * arc.radius - 0.25 * L * L);
      arc.centre     = 0.5 * (a + b) - (kappa > 0 ? s : -s) * edge_normal(a, b);
      arc.valid      = true;
      return arc;
    }

    /// Chord parameter of the foot of @p x on the chord a -> b.
    double
    chord_parameter(const Point &a, const Point &b, const Point &x)
    {
      return ((x - a) * (b - a)) / a.distance_square(b);
    }

    /**
     * The point of the arc of the chord a -> b (curvature @p kappa) nearest
     * to @p p: the foot of p along the arc's normal. Returns false (and
     * leaves @p x) if there is no arc or the foot falls off the chord's
     * span.
     */
    bool
    closest_on_arc(const Point &a, const Point &b, const double kappa, const Point &p, Point &x)
    {
      const Arc arc = arc_of(a, b, kappa);
      if (!arc.valid || p.distance(arc.centre) == 0)
        return false;
      const Point  y = arc.centre + (arc.radius / p.distance(arc.centre)) * (p - arc.centre);
      const double t = chord_parameter(a, b, y);
      if (!(t > 0 && t < 1))
        return false;
      x = y;
      return true;
    }

    /**
     * The point where the line through @p p along @p direction meets the
     * arc of the chord a -> b (curvature @p kappa), the one nearer to p.
     * Returns false if there is no arc, the line misses it, or the hit falls
     * off the chord's span.
     */
    bool
    cast_on_arc(const Point &a, const Point &b, const double kappa, const Point &p, const Vector &direction,
                Point &x)
    {
      const Arc arc = arc_of(a, b, kappa);
      if (!arc.valid)
        return false;
      const Vector d    = direction / direction.norm();
      const Vector pc   = p - arc.centre;
      const double half = d * pc;
      const double disc = half * half - (pc * pc - arc.radius * arc.radius);
      if (disc < 0)
        return false;
      const double root = std::sqrt(disc);
      const double tau1 = -half - root, tau2 = -half + root;
      const Point  y    = p + (std::abs(tau1) < std::abs(tau2) ? tau1 : tau2) * d;
      const double t    = chord_parameter(a, b, y);
      if (!(t > 0 && t < 1))
        return false;
      x = y;
      return true;
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

    /// The closest point of a vertex on the other side.
    struct Projection
    {
      unsigned int edge = invalid; ///< index into Side::edges
      double       t    = 0;       ///< clamped parameter along the edge
      double       length = 0;
      double       distance = 0;
      Point        point;
      bool         inside = false; ///< not beyond an end of the side
      bool         facing = false; ///< outward normals opposed
      double       normal_cosine = 1; ///< cosine of the angle between them
    };

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

    /// What happens to one vertex of a side.
    struct Candidate
    {
      Projection projection;
      bool       accepted = false;
    };



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



    /// A vertex inserted by rule 3 (splits), for the gap rule 4.
    struct Inserted
    {
      unsigned int vertex;  ///< the new vertex
      unsigned int partner; ///< its partner on the other side
      bool         on_master;
      unsigned int edge;    ///< the split edge of the receiving side (before insertion)
      Point        chord;   ///< the point of the chord at the split
      Vector       normal;  ///< outward normal of the chord
      double       q;       ///< t(1 - t) L^2 / 2: chord deviation per unit curvature
    };



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
                }
              partner_onto[nv] = v;
              partner_from[v]  = nv;
              inserted.push_back({nv, v, onto_master, entry.first, xa + t * (xb - xa), edge_normal(xa, xb),
                                  0.5 * t * (1 - t) * L * L});
              previous = t;
              ++(onto_master ? report.n_inserted_master : report.n_inserted_slave);
            }
          for (const auto &m : moves)
            mesh.move_vertex(m.first, m.second);
        }
    }



    // Rule 4 (gaps) in three passes, one function each, called in this order
    // after the splits (the rule itself is item 3 of the class documentation
    // of NodeInsertion, "Discretisation gaps are closed, real gaps are kept"):
    //  (a) judge_gaps(): every pair is classified on the geometry the splits
    //      left, before any merged vertex moves: its gap is zero (round-off
    //      of the coordinates), a discretisation gap (the partner's offset
    //      from the receiving chord is what a curvature both sides show
    //      around the pair would give), unresolved (next to an inflection,
    //      within twice the chord deviation) or real;
    //  (b) face_merged_vertices(): two merged original vertices are placed
    //      opposite each other along the master normal, the slave vertex
    //      sliding along its own curve (the master vertex instead when the
    //      slave vertex ends its side), so a merge never carries a node
    //      across a gap;
    //  (c) close_or_keep_gaps(): one decision for the whole interface. With
    //      no real gap the two sides sample one curve and every gap is
    //      closed (the partners coincide; unless the settings switch the
    //      closing off, which keeps every gap); with a real gap anywhere only
    //      the zero gaps are closed, the others are kept as measured and the
    //      ones that could have been discretisation gaps are reported with
    //      their chord deviation. A smooth interface thus never has closed
    //      and kept gaps above round-off side by side.
    // The passes share the vertices rule 3 inserted, looked up by vertex.
    using InsertedByVertex = std::map<unsigned int, const Inserted *>;

    /// The class pass (a) of rule 4 puts the gap of a pair in.
    enum class GapVerdict
    {
      zero,           ///< within the coordinate precision
      discretisation, ///< inside the curvature band of the two sides
      unresolved,     ///< outside the band, but next to an inflection and within twice the deviation
      real            ///< anything else
    };

    /// One pair as pass (a) of rule 4 judged it.
    struct JudgedPair
    {
      unsigned int m, s;      ///< master and slave vertex
      GapVerdict   verdict;
      double       deviation; ///< chord deviation at the pair: q times the largest |kappa| (0 if not compared)
    };

    /**
     * The range of the gap-rule curvatures (Side::kappa_gap, convex > 0 for
     * @p side) of the vertices @p vs and of their neighbours on @p side,
     * multiplied by @p sign (-1: seen from the other side). If the range
     * holds both signs (an inflection nearby, whose extremes may fall
     * between the samples) it is made symmetric, [-max, max]. Without any
     * known curvature (straight side, corners) it is [0, 0].
     */
    std::pair<double, double>
    curvature_range(const Side &side, const std::vector<unsigned int> &vs, const double sign)
    {
      std::vector<unsigned int> around;
      for (const unsigned int v : vs)
        {
          around.push_back(v);
          if (const auto in = side.incoming.find(v); in != side.incoming.end())
            around.push_back(side.edges[in->second][0]);
          if (const auto out = side.outgoing.find(v); out != side.outgoing.end())
            around.push_back(side.edges[out->second][1]);
        }
      double lo = 0, hi = 0;
      bool   first = true;
      for (const unsigned int v : around)
        if (const auto k = side.kappa_gap.find(v); k != side.kappa_gap.end())
          {
            lo    = first ? sign * k->second : std::min(lo, sign * k->second);
            hi    = first ? sign * k->second : std::max(hi, sign * k->second);
            first = false;
          }
      if (lo < 0 && hi > 0)
        {
          const double k = std::max(-lo, hi);
          lo = -k, hi = k;
        }
      return std::make_pair(lo, hi);
    }

    /**
     * The union of the curvature ranges @p r and @p p, widened by
     * @p curvature_factor. A union that contains 0 is scaled about 0, so
     * the two signs stay apart (a flat block under a cylinder never
     * qualifies); any other union is widened about its centre but never
     * across 0, so two circles of different radii remain distinguishable
     * however close the radii are.
     */
    std::pair<double, double>
    widened_band(const std::pair<double, double> &r, const std::pair<double, double> &p,
                 const double curvature_factor)
    {
      const double lo = std::min(r.first, p.first), hi = std::max(r.second, p.second);
      const double f  = curvature_factor;
      if (lo <= 0 && hi >= 0)
        return std::make_pair(f * lo, f * hi);
      const double c = 0.5 * (lo + hi), w = 0.5 * f * (hi - lo);
      return lo > 0 ? std::make_pair(std::max(c - w, 0.), c + w) : std::make_pair(c - w, std::min(c + w, 0.));
    }

    /**
     * Judge a gap against a chord of the receiving side @p onto: the chord
     * is edge @p edge of @p onto (indices of the side before insertion),
     * @p chord the point of the chord facing the partner, @p normal the
     * chord's outward normal and @p q = t(1 - t) L^2 / 2 its deviation per
     * unit curvature (negative beyond the chord's ends, where the circle
     * lies on the other side). The partner is vertex @p partner of
     * @p from. If both sides sample one curve, the partner lies off the
     * chord by q kappa for some kappa in the widened band of the two sides'
     * curvatures; @p tol is the coordinate tolerance of the pair. Sets
     * @p deviation to |q| times the largest |kappa| of the band. Returns
     * discretisation, unresolved or real (never zero).
     */
    GapVerdict
    judge_against_chord(const Mesh                    &mesh,
                        const Side                    &onto,
                        const unsigned int             edge,
                        const Point                   &chord,
                        const Vector                  &normal,
                        const double                   q,
                        const Side                    &from,
                        const unsigned int             partner,
                        const double                   tol,
                        const double                   curvature_factor,
                        double                        &deviation)
    {
      const auto   band  = widened_band(curvature_range(onto, {onto.edges[edge][0], onto.edges[edge][1]}, 1.),
                                        curvature_range(from, {partner}, -1.), curvature_factor);
      const double k     = std::max(-band.first, band.second);
      const double delta = (mesh.vertex(partner) - chord) * normal;
      deviation          = std::abs(q) * k;
      if (delta >= std::min(q * band.first, q * band.second) - tol &&
          delta <= std::max(q * band.first, q * band.second) + tol)
        return GapVerdict::discretisation;
      // next to an inflection a curve sampled too coarsely can still
      // produce a gap of up to twice the largest chord deviation
      if (band.first < 0 && band.second > 0 && std::abs(delta) <= 2 * std::abs(q) * k)
        return GapVerdict::unresolved;
      return GapVerdict::real;
    }

    /// Distance from |@p c| to the next larger double: the spacing of
    /// the doubles at @p c.
    double
    ulp(const double c)
    {
      return std::nextafter(std::abs(c), std::numeric_limits<double>::infinity()) - std::abs(c);
    }

    /**
     * The decimal grid the coordinates of @p side were written on, for the
     * zero gaps of rule 3 ('Coordinate precision = auto'): the coarsest
     * power of ten $10^e$ of which every nonzero coordinate of the side's
     * vertices is an integer multiple to within two units in the last
     * place of a double, searched over at most 12 significant digits.
     * Returns 0 (no rounding beyond double's own) if some coordinate needs
     * more digits (coordinates computed in double precision: generators,
     * transformations, rotations) or if every coordinate is a binary
     * fraction of at most 32 significant bits (integers, halves, the
     * vertices of a generator's dyadic steps such as 0.125: exact values,
     * not rounded ones, although their decimals are short too). It is 0
     * as well if the grid exceeds 1/100 of the side's shortest edge: data
     * rounded that coarsely would not be a usable mesh, so vertices on such
     * a lattice were placed on it (a generator's steps of 0.1 or 0.05 over
     * the unit square) and are exact; taking 0.1 as their rounding would
     * close real gaps of up to half an element. The grid depends on the
     * data only, not on where the model lies: a shift by a multiple of the
     * grid keeps it, a scaling by a power of ten scales it and the edges
     * alike.
     */
    double
    decimal_grid(const Mesh &mesh, const Side &side)
    {
      std::set<unsigned int> vertices;
      for (const auto &e : side.edges)
        vertices.insert(e.begin(), e.end());
      double grid = std::numeric_limits<double>::infinity();
      double shortest = std::numeric_limits<double>::infinity();
      for (const auto &e : side.edges)
        shortest = std::min(shortest, mesh.vertex(e[0]).distance(mesh.vertex(e[1])));
      bool   all_binary = true;
      for (const unsigned int v : vertices)
        for (unsigned int d = 0; d < 2; ++d)
          {
            const double c = mesh.vertex(v)[d];
            if (c == 0)
              continue;
            int exponent = 0;
            std::frexp(c, &exponent);
            const double bits = std::ldexp(c, 32 - exponent); // 32 significant bits
            all_binary        = all_binary && bits == std::round(bits);
            // the first (coarsest) 10^e, e = top + 1 - digits, with c an
            // integer multiple of it: c / 10^e (or c 10^-e) is formed with
            // at most one rounding, so an exact multiple lies within two
            // units in the last place of the quotient
            const int top   = static_cast<int>(std::floor(std::log10(std::abs(c))));
            bool      found = false;
            for (int digits = 1; digits <= 12 && !found; ++digits)
              {
                const int    e     = top + 1 - digits;
                const double power = std::pow(10., std::abs(e)); // exact up to 1e22
                const double q     = (e >= 0 ? c / power : c * power);
                if (std::abs(q - std::round(q)) <= 2 * ulp(q))
                  {
                    grid  = std::min(grid, e >= 0 ? power : 1 / power);
                    found = true;
                  }
              }
            if (!found)
              return 0;
          }
      return (all_binary || !std::isfinite(grid) || grid > 1e-2 * shortest) ? 0 : grid;
    }

    /**
     * Rule 4, pass (a): judge the gap of every pair of @p master_partner
     * (master vertex -> slave vertex) on the current mesh, i.e. after the
     * splits and before any merged vertex moves. @p master and @p slave are
     * the sides as collected before insertion (their edges are the chords
     * of rule 3), @p by_vertex the vertices rule 3 inserted, @p grid the
     * decimal grids of the master and the slave side (decimal_grid(); with
     * 'Coordinate precision' set, that value times @p size, the interface
     * size, on both). A gap within half the sum of the two grids, plus four
     * units in the last place of the pair's largest coordinate and
     * $10^{-12}$ of the local edge length (double round-off), is zero; otherwise a pair with an inserted
     * vertex is judged against the chord it split, and two merged original
     * vertices against the edge at the master vertex that the slave vertex
     * lies least beyond (along the edge). Returns the pairs in the order of @p master_partner.
     */
    std::vector<JudgedPair>
    judge_gaps(const Mesh                                 &mesh,
               const Side                                 &master,
               const Side                                 &slave,
               const std::map<unsigned int, unsigned int> &master_partner,
               const InsertedByVertex                     &by_vertex,
               const std::array<double, 2>                &grid,
               const NodeInsertion::Settings              &settings)
    {
      std::vector<JudgedPair> judged;
      const Side              master_now = collect_side(mesh, master);
      for (const auto &mp : master_partner)
        {
          const unsigned int m = mp.first, s = mp.second;
          const auto         im = by_vertex.find(m), is = by_vertex.find(s);
          const Inserted *ins = (im != by_vertex.end() ? im->second : (is != by_vertex.end() ? is->second : nullptr));
          const Point     xm = mesh.vertex(m), xs = mesh.vertex(s);
          const double    g0 = (xs - xm) * master_now.normal.at(m);
          const double    largest = std::max({std::abs(xm[0]), std::abs(xm[1]), std::abs(xs[0]), std::abs(xs[1])});
          const double    tol = 0.5 * (grid[0] + grid[1]) + 4 * ulp(largest) +
                             1e-12 * std::min(master_now.h.at(m), slave.h.count(s) ? slave.h.at(s) : master_now.h.at(m));
          JudgedPair j{m, s, std::abs(g0) <= tol ? GapVerdict::zero : GapVerdict::real, 0};
          const double cf = settings.curvature_factor;
          if (j.verdict == GapVerdict::real && ins)
            j.verdict = ins->on_master ?
                          judge_against_chord(mesh, master, ins->edge, ins->chord, ins->normal, ins->q, slave, s,
                                              tol, cf, j.deviation) :
                          judge_against_chord(mesh, slave, ins->edge, ins->chord, ins->normal, ins->q, master, m,
                                              tol, cf, j.deviation);
          else if (j.verdict == GapVerdict::real)
            {
              // two merged original vertices: the chord is the master edge
              // at m closest to the slave vertex along the side (at a convex
              // vertex the slave vertex may lie beyond both edges)
              unsigned int best = invalid;
              double       best_t = 0, best_out = std::numeric_limits<double>::max();
              for (const auto *edges : {&master.incoming, &master.outgoing})
                if (const auto it = edges->find(m); it != edges->end())
                  {
                    const Point &a = mesh.vertex(master.edges[it->second][0]),
                                &b = mesh.vertex(master.edges[it->second][1]);
                    const double t   = chord_parameter(a, b, xs);
                    const double out = std::max({-t, t - 1, 0.});
                    if (out < best_out)
                      best = it->second, best_t = t, best_out = out;
                  }
              if (best != invalid)
                {
                  const Point &a = mesh.vertex(master.edges[best][0]), &b = mesh.vertex(master.edges[best][1]);
                  j.verdict = judge_against_chord(mesh, master, best, a + best_t * (b - a), edge_normal(a, b),
                                                  0.5 * best_t * (1 - best_t) * a.distance_square(b), slave, s,
                                                  tol, cf, j.deviation);
                }
            }
          judged.push_back(j);
        }
      return judged;
    }

    /// The indices into Side::edges of the (one or two) edges of @p side at
    /// vertex @p v: the incoming one first.
    std::vector<unsigned int>
    side_edges_at(const Side &side, const unsigned int v)
    {
      std::vector<unsigned int> e;
      for (const auto *map : {&side.incoming, &side.outgoing})
        if (const auto it = map->find(v); it != map->end())
          e.push_back(it->second);
      return e;
    }

    /**
     * Rule 4, pass (b): place every pair of two merged original vertices
     * (pairs without a vertex of @p by_vertex) opposite each other. The
     * slave vertex moves along its side (on the arc of either of its edges,
     * or the edge itself if straight) to where the line through the master
     * vertex along the master normal meets it; if the slave vertex ends its
     * side, the master vertex moves instead, to the point of its side
     * closest to the slave vertex. Nothing moves if both vertices end their
     * sides, or if no target lies within half an edge length of the moving
     * vertex (a corner). @p master and @p slave are the sides collected before
     * insertion. Updates Report::max_merge_shift.
     */
    void
    face_merged_vertices(PolygonalMesh<2>                           &mesh,
                         const Side                                 &master,
                         const Side                                 &slave,
                         const std::map<unsigned int, unsigned int> &master_partner,
                         const InsertedByVertex                     &by_vertex,
                         NodeInsertion::Report                      &report)
    {
      for (const auto &mp : master_partner)
        {
          const unsigned int m = mp.first, s = mp.second;
          if (by_vertex.count(m) || by_vertex.count(s))
            continue; // rule 3 already put the inserted vertex where it faces its partner
          const bool move_slave = !slave.is_end(s), move_master = !move_slave && !master.is_end(m);
          const Side &side = move_slave ? slave : master;
          const unsigned int v = move_slave ? s : m;
          if (!move_slave && !move_master)
            continue;
          Point  target = mesh.vertex(v);
          double best   = std::numeric_limits<double>::max();
          for (const unsigned int e : side_edges_at(side, v))
            {
              const Point &a = mesh.vertex(side.edges[e][0]), &b = mesh.vertex(side.edges[e][1]);
              Point        x;
              bool         hit = false;
              if (move_slave)
                {
                  hit = cast_on_arc(a, b, side.edge_kappa[e], mesh.vertex(m), master.normal.at(m), x);
                  if (!hit)
                    {
                      // a straight edge: intersect the chord
                      const Vector d = b - a, dir = master.normal.at(m);
                      const double denom = cross(d, dir);
                      if (std::abs(denom) > 1e-12 * d.norm())
                        {
                          const double t = cross(mesh.vertex(m) - a, dir) / denom;
                          hit            = (t > 0 && t < 1) && side.edge_kappa[e] == 0;
                          x              = a + t * d;
                        }
                    }
                }
              else
                {
                  hit = closest_on_arc(a, b, side.edge_kappa[e], mesh.vertex(s), x);
                  if (!hit && side.edge_kappa[e] == 0)
                    {
                      const double t = chord_parameter(a, b, mesh.vertex(s));
                      hit            = (t > 0 && t < 1);
                      x              = a + t * (b - a);
                    }
                }
              if (hit && x.distance(mesh.vertex(v)) < best)
                best = x.distance(mesh.vertex(v)), target = x;
            }
          if (best > 0.5 * side.h.at(v))
            continue; // no hit close to the vertex (a corner): it stays
          report.max_merge_shift = std::max(report.max_merge_shift, best);
          mesh.move_vertex(v, target);
        }
    }

    /**
     * Rule 4, pass (c): one decision for the interface on the pairs
     * @p judged by pass (a), with the gaps measured on the current mesh
     * (after pass (b)) along the master normals. The interface is one curve
     * if Settings::close_discretisation_gaps is set and no pair is real;
     * then every pair is closed (unresolved ones are also listed in
     * Report::closed_unresolved_gaps). Otherwise only the zero gaps are
     * closed (none if close_discretisation_gaps is false), and, with
     * close_discretisation_gaps set, the kept discretisation and
     * unresolved gaps are listed in Report::unresolved_gaps. Closing moves the inserted vertex
     * (@p by_vertex) onto its partner; for two original vertices the slave
     * one onto the master one, unless only the slave vertex ends its side.
     * @p master and @p slave are the sides collected before insertion.
     * Updates the gap and merge-shift counters of @p report.
     */
    void
    close_or_keep_gaps(PolygonalMesh<2>               &mesh,
                       const Side                     &master,
                       const Side                     &slave,
                       const std::vector<JudgedPair>  &judged,
                       const InsertedByVertex         &by_vertex,
                       const NodeInsertion::Settings  &settings,
                       NodeInsertion::Report          &report)
    {
      const Side   master_now = collect_side(mesh, master);
      unsigned int n_real = 0;
      for (const auto &j : judged)
        n_real += (j.verdict == GapVerdict::real);
      const bool one_curve = settings.close_discretisation_gaps && n_real == 0;
      for (const auto &j : judged)
        {
          const Point  xm = mesh.vertex(j.m), xs = mesh.vertex(j.s);
          const double g0 = (xs - xm) * master_now.normal.at(j.m);
          const bool   close =
            settings.close_discretisation_gaps && (j.verdict == GapVerdict::zero || (one_curve && j.verdict != GapVerdict::real));
          if (!close)
            {
              if (settings.close_discretisation_gaps && j.verdict != GapVerdict::real && j.verdict != GapVerdict::zero)
                report.unresolved_gaps.push_back({0.5 * (xm + xs), g0, j.deviation});
              if (j.verdict != GapVerdict::zero)
                {
                  ++report.n_kept_gaps;
                  report.max_kept_gap = std::max(report.max_kept_gap, std::abs(g0));
                }
              continue;
            }
          if (one_curve && j.verdict == GapVerdict::unresolved)
            report.closed_unresolved_gaps.push_back({0.5 * (xm + xs), g0, j.deviation});
          // the inserted vertex moves onto the original one; of two original
          // vertices the slave one moves, unless only the slave one ends its side
          const bool is_new_master = by_vertex.count(j.m) > 0, is_new_slave = by_vertex.count(j.s) > 0;
          bool       move_master   = is_new_master;
          if (!is_new_master && !is_new_slave)
            move_master = slave.is_end(j.s) && !master.is_end(j.m);
          if (move_master)
            mesh.move_vertex(j.m, xs);
          else
            mesh.move_vertex(j.s, xm);
          if (!is_new_master && !is_new_slave)
            report.max_merge_shift = std::max(report.max_merge_shift, xm.distance(xs));
          ++report.n_closed_gaps;
          report.max_closed_gap = std::max(report.max_closed_gap, std::abs(g0));
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
              if (degree == 2)
                {
                  ContactNodePair p;
                  p.master_entity =
                    master_after.edge_indices[master_after.edge_by_pair.at(key(pa->second, pb->second))];
                  p.slave_entity = slave_after.edge_indices[slave_after.edge_by_pair.at(key(sa, sb))];
                  p.is_midpoint  = true;
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
  } // namespace



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
    AssertThrow(degree == 1 || degree == 2,
                dealii::ExcMessage(name + "contact node pairs are implemented for order k = 1 and 2, not k = " +
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
        if (!p.is_midpoint)
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
        if (p.is_midpoint)
          {
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
    for (auto &s : interface.segments)
      {
        s.length = interface.pairs[s.first].slave_location.distance(interface.pairs[s.second].slave_location);
        const double end_weight = (interface.degree == 1 ? 0.5 : 1. / 6.) * s.length;
        interface.pairs[s.first].weight += end_weight;
        interface.pairs[s.second].weight += end_weight;
        if (s.midpoint != invalid)
          interface.pairs[s.midpoint].weight += 2. / 3. * s.length;
      }
  }


  unsigned int
  NodeInsertion::mark_junctions(std::vector<ContactNodePair> &pairs, const PolygonalMesh<2> &mesh)
  {
    // per vertex: the vertex pairs it is in (pair, partner)
    std::map<unsigned int, std::vector<std::pair<unsigned int, unsigned int>>> at;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      if (!pairs[i].is_midpoint)
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
        if (pairs[p].is_midpoint)
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
