// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// NodeInsertion: rule 4 (discretisation gaps closed, real gaps kept) in
// its three passes.

#include "node_insertion_side.h"

namespace dealvem
{
  namespace internal
  {
    namespace node_insertion
    {
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
     * The cells around the boundary vertex @p v, in the order met when
     * walking from its boundary edge @p first (a mesh edge) across the
     * interior edges at @p v, up to the boundary edge that ends the walk.
     * The walk is local (no scan of the mesh).
     */
    std::vector<unsigned int>
    cells_around(const Mesh &mesh, const unsigned int v, const unsigned int first)
    {
      std::vector<unsigned int> cells;
      unsigned int              e = first, c = mesh.edge(first).cells[0];
      while (c != invalid && std::find(cells.begin(), cells.end(), c) == cells.end())
        {
          cells.push_back(c);
          unsigned int next = invalid;
          for (const unsigned int f : mesh.cell(c).edges)
            if (f != e && (mesh.edge(f).vertices[0] == v || mesh.edge(f).vertices[1] == v))
              next = f;
          if (next == invalid)
            break;
          e                = next;
          const auto &edge = mesh.edge(e);
          c                = (edge.cells[0] == c ? edge.cells[1] : edge.cells[0]);
        }
      return cells;
    }



    /// Whether segments [a, b] and [c, d] cross, or one has an end on (or
    /// within 1e-9 of the longer length of) the other: stricter than the
    /// mesh's own validation, so a move it lets through leaves no cell
    /// that validate() refuses.
    bool
    segments_meet(const Point &a, const Point &b, const Point &c, const Point &d)
    {
      const double L   = std::max(a.distance(b), c.distance(d));
      const double eps = 1e-9 * L * L;
      const auto   sgn = [eps](const Point &p, const Point &q, const Point &r) {
        const double x = cross(q - p, r - p);
        return x > eps ? 1 : (x < -eps ? -1 : 0);
      };
      const int d1 = sgn(c, d, a), d2 = sgn(c, d, b), d3 = sgn(a, b, c), d4 = sgn(a, b, d);
      if (d1 * d2 < 0 && d3 * d4 < 0)
        return true;
      // r (on the line p q to within eps) between p and q
      const auto on = [](const Point &p, const Point &q, const Point &r) {
        const double t = (r - p) * (q - p) / (q - p).norm_square();
        return t >= -1e-9 && t <= 1 + 1e-9;
      };
      return (d1 == 0 && on(c, d, a)) || (d2 == 0 && on(c, d, b)) || (d3 == 0 && on(a, b, c)) ||
             (d4 == 0 && on(a, b, d));
    }



    /**
     * Whether the cells around the boundary vertex @p v (boundary edge
     * @p first at it) are valid after @p v moved: each is a simple
     * counter-clockwise polygon (its two edges at @p v cross no other edge
     * of it), and their angles at @p v add up to less than a full turn (a
     * cell folded over its neighbour adds a turn).
     */
    bool
    valid_around(const Mesh &mesh, const unsigned int v, const unsigned int first)
    {
      double angle = 0;
      for (const unsigned int c : cells_around(mesh, v, first))
        {
          const auto        &loop = mesh.cell(c).vertices;
          const unsigned int n    = loop.size();
          const unsigned int i    = std::find(loop.begin(), loop.end(), v) - loop.begin();
          if (i == n)
            return false;
          double area = 0;
          for (unsigned int j = 0; j < n; ++j)
            area += cross(mesh.vertex(loop[j]) - mesh.vertex(v), mesh.vertex(loop[(j + 1) % n]) - mesh.vertex(v));
          if (!(area > 0))
            return false;
          const Point &x = mesh.vertex(v), &p = mesh.vertex(loop[(i + n - 1) % n]), &q = mesh.vertex(loop[(i + 1) % n]);
          // the edges at v against the edges not adjacent to them
          for (unsigned int j = 0; j < n; ++j)
            {
              const unsigned int j1 = (j + 1) % n;
              const Point       &a = mesh.vertex(loop[j]), &b = mesh.vertex(loop[j1]);
              if (j != i && j1 != i && j1 != (i + n - 1) % n && segments_meet(x, p, a, b))
                return false;
              if (j != i && j != (i + 1) % n && j1 != i && segments_meet(x, q, a, b))
                return false;
            }
          double a = std::atan2(cross(q - x, p - x), (q - x) * (p - x));
          angle += (a <= 0 ? a + 2 * dealii::numbers::PI : a);
        }
      return angle < 2 * dealii::numbers::PI * (1 - 1e-12);
    }



    /**
     * Move the boundary vertex @p v of @p side (the side as on the current
     * mesh) to @p x if the cells around it stay valid (valid_around());
     * otherwise it stays where it is. Returns whether it moved.
     */
    bool
    move_if_valid(PolygonalMesh<2> &mesh, const Side &side, const unsigned int v, const Point &x)
    {
      const auto e = side_edges_at(side, v);
      if (e.empty())
        return false;
      const Point old = mesh.vertex(v);
      mesh.move_vertex(v, x);
      if (valid_around(mesh, v, side.edge_indices[e[0]]))
        return true;
      mesh.move_vertex(v, old);
      return false;
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
      const Side master_now = collect_side(mesh, master), slave_now = collect_side(mesh, slave);
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
          // (a move past a vertex that rule 3 inserted next to it would fold
          // its cell: the vertex then stays, and its gap is judged as it is)
          if (move_if_valid(mesh, move_slave ? slave_now : master_now, v, target))
            report.max_merge_shift = std::max(report.max_merge_shift, best);
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
      const Side   master_now = collect_side(mesh, master), slave_now = collect_side(mesh, slave);
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
          // a move that would fold a cell is not made: the gap is kept
          if (!(move_master ? move_if_valid(mesh, master_now, j.m, xs) : move_if_valid(mesh, slave_now, j.s, xm)))
            {
              report.unresolved_gaps.push_back({0.5 * (xm + xs), g0, j.deviation});
              ++report.n_kept_gaps;
              report.max_kept_gap = std::max(report.max_kept_gap, std::abs(g0));
              continue;
            }
          if (!is_new_master && !is_new_slave)
            report.max_merge_shift = std::max(report.max_merge_shift, xm.distance(xs));
          ++report.n_closed_gaps;
          report.max_closed_gap = std::max(report.max_closed_gap, std::abs(g0));
        }
    }
    } // namespace node_insertion
  } // namespace internal
} // namespace dealvem
