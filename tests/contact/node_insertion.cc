// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Node insertion on contact interfaces (NodeInsertion::insert), with
// numbers fixed by the geometry.
//
// Counting for two straight sides that touch and overlap completely, with
// n_m + 1 master and n_s + 1 slave vertices of which c coincide (the
// corners and shared interior vertices; no other pair of vertices is
// closer than merge_fraction times the local edge length): the c
// coinciding vertices are merged, every other slave vertex is inserted
// into the master side and every other master vertex into the slave side:
//   n_merged = c, n_inserted_master = n_s + 1 - c,
//   n_inserted_slave = n_m + 1 - c,
//   n_master_edges = n_slave_edges = n_m + n_s + 1 - c,
// vertex pairs = edges + 1, midpoint pairs (k = 2) = edges. Every pair has
// g_0 = 0 (up to round-off), a discretisation gap, so every vertex pair is
// counted in n_closed_gaps.
//
// a) flat 3 / 4 (hand count), 3 / 7, 3 / Voronoi, inserting twice;
// b) ratios 1:3, 2:7, 1:2 (shared middle vertex);
// c) interface sloped at 30 degrees;
// d) partial overlap;
// e) two interfaces in one mesh (three stacked blocks);
// f) merging: slave vertices 1e-7 .. 0.08 edge lengths beside the master
//    vertices are merged (no sub-edge shorter than 0.05 h); at 0.15 they
//    are inserted;
// g) unpaired nodes: a half disc on a flat block, partly beyond the
//    search distance;
// h) real gaps and penetrations are kept: blocks 0.01 and 0.1 apart or
//    overlapping by 0.01, and slave vertices moved normally by 1e-7 .. 1e-2
//    edge lengths (computed in double precision, so kept for every size);
// i) errors, each naming the interface ids;
// j) the facing test's band for vertices paired before (keep_facing).
// For k = 1 and 2: weights and segment lengths sum to the interface
// length, pairs ordered along the slave side, locations where the entities
// are, the mesh valid.
#include <deal.II/base/mpi.h>

#include <dealvem/contact/node_insertion.h>
#include <dealvem/mesh/generators.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <sstream>

#include "../tests.h"

using namespace dealvem;
using Mesh = PolygonalMesh<2>;
using P    = dealii::Point<2>;
using T    = dealii::Tensor<1, 2>;

namespace
{
  /// Give all cells material @p material and add @p offset to all boundary
  /// ids.
  void
  relabel(Mesh &mesh, const unsigned int material, const unsigned int offset)
  {
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      mesh.set_material_id(c, material);
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      if (mesh.edge(e).at_boundary())
        mesh.set_edge_boundary_id(e, mesh.edge(e).boundary_id + offset);
  }

  /// A structured quad block [x0,x1]x[y0,y1] (generator), ids 0..3 + offset.
  Mesh
  block(const double x0, const double y0, const double x1, const double y1,
        const unsigned int nx, const unsigned int ny, const unsigned int material,
        const unsigned int offset)
  {
    Mesh mesh;
    PolygonalMeshGenerators::structured_quads(mesh, P(x0, y0), P(x1, y1), nx, ny);
    relabel(mesh, material, offset);
    return mesh;
  }

  /// A Voronoi block [x0,x1]x[y0,y1] with @p n cells, ids 0..3 + offset.
  Mesh
  voronoi_block(const double x0, const double y0, const double x1, const double y1,
                const unsigned int n, const unsigned int material, const unsigned int offset)
  {
    Mesh mesh;
    PolygonalMeshGenerators::voronoi(mesh, P(x0, y0), P(x1, y1), n, 20, 1);
    relabel(mesh, material, offset);
    return mesh;
  }

  /// nx by ny quads of the unit square mapped by @p map (arguments: the
  /// reference point and the vertex indices i, j), built by hand; boundary
  /// ids left/right/bottom/top = offset + 0/1/2/3.
  Mesh
  mapped_quads(const unsigned int nx, const unsigned int ny,
               const std::function<P(double, double, unsigned int, unsigned int)> &map,
               const unsigned int material, const unsigned int offset)
  {
    Mesh mesh;
    mesh.name = "mapped quads";
    for (unsigned int j = 0; j <= ny; ++j)
      for (unsigned int i = 0; i <= nx; ++i)
        mesh.add_vertex(map(double(i) / nx, double(j) / ny, i, j));
    const auto v = [&](const unsigned int i, const unsigned int j) { return j * (nx + 1) + i; };
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        mesh.add_cell({v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)}, material);
    for (unsigned int j = 0; j < ny; ++j)
      {
        mesh.set_boundary_id(v(0, j), v(0, j + 1), offset + 0);
        mesh.set_boundary_id(v(nx, j), v(nx, j + 1), offset + 1);
      }
    for (unsigned int i = 0; i < nx; ++i)
      {
        mesh.set_boundary_id(v(i, 0), v(i + 1, 0), offset + 2);
        mesh.set_boundary_id(v(i, ny), v(i + 1, ny), offset + 3);
      }
    mesh.finalize();
    return mesh;
  }

  Mesh
  join(Mesh lower, const Mesh &upper)
  {
    lower.append(upper);
    lower.name = "two bodies";
    return lower;
  }

  unsigned int
  n_edges_with_id(const Mesh &mesh, const unsigned int id)
  {
    unsigned int n = 0;
    for (const auto &e : mesh.get_edges())
      n += (e.at_boundary() && e.boundary_id == id);
    return n;
  }

  /// Shortest edge with boundary id @p id.
  double
  min_edge_length(const Mesh &mesh, const unsigned int id)
  {
    double m = 1e300;
    for (const auto &e : mesh.get_edges())
      if (e.at_boundary() && e.boundary_id == id)
        m = std::min(m, mesh.vertex(e.vertices[0]).distance(mesh.vertex(e.vertices[1])));
    return m;
  }

  std::string
  report_string(const NodeInsertion::Report &r)
  {
    std::ostringstream s;
    s << "inserted master " << r.n_inserted_master << ", inserted slave " << r.n_inserted_slave
      << ", merged " << r.n_merged << ", closed gaps " << r.n_closed_gaps << " (max "
      << r.max_closed_gap << "), master edges " << r.n_master_edges << ", slave edges "
      << r.n_slave_edges << ", unpaired " << r.unpaired.size();
    return s.str();
  }

  struct Expected
  {
    int inserted_master = -1, inserted_slave = -1, merged = -1, closed = -1, master_edges = -1,
        slave_edges = -1, pairs_k1 = -1, pairs_k2 = -1;
    /// Vertices on the master and slave sides before insertion (complete
    /// overlap: every vertex gets a partner), or -1.
    int    n_master_vertices = -1, n_slave_vertices = -1;
    /// Length of the overlap (sum of the weights and segment lengths).
    double length = 1;
    T      normal;
    /// The initial gap of every pair (the sides are parallel).
    double gap = 0;
    /// Tolerance for the gaps and the coinciding tangential positions.
    double tolerance = 1e-14;
    /// Lower bound for the interface edge lengths after insertion.
    double min_length = 0;
    /// Unpaired nodes expected.
    bool unpaired = false;
    /// Total area unchanged (no vertex moved along a side).
    bool same_area = true;
  };

  void
  check_count(const int expected, const unsigned int value, const std::string &what)
  {
    if (expected >= 0)
      testing::check(int(value) == expected,
                     what + " = " + std::to_string(value) + " (expected " + std::to_string(expected) + ")");
  }

  void
  check_report(const NodeInsertion::Report &r, const Expected &x, const std::string &name)
  {
    std::cout << "      " << name << ": " << report_string(r) << std::endl;
    check_count(x.inserted_master, r.n_inserted_master, name + ": n_inserted_master");
    check_count(x.inserted_slave, r.n_inserted_slave, name + ": n_inserted_slave");
    check_count(x.merged, r.n_merged, name + ": n_merged");
    check_count(x.closed, r.n_closed_gaps, name + ": n_closed_gaps");
    check_count(x.master_edges, r.n_master_edges, name + ": n_master_edges");
    check_count(x.slave_edges, r.n_slave_edges, name + ": n_slave_edges");
    if (x.n_slave_vertices >= 0)
      check_count(x.n_slave_vertices, r.n_merged + r.n_inserted_master,
                  name + ": every slave vertex has a partner: n_merged + n_inserted_master");
    if (x.n_master_vertices >= 0)
      check_count(x.n_master_vertices, r.n_merged + r.n_inserted_slave,
                  name + ": every master vertex has a partner: n_merged + n_inserted_slave");
    if (!x.unpaired)
      testing::check(r.unpaired.empty(), name + ": no unpaired node");
  }

  /// Checks of the pairs of one interface.
  void
  check_interface(const Mesh &mesh, const NodeInsertion::Interface &itf, const unsigned int index,
                  const Expected &x, const std::string &name)
  {
    const unsigned int k     = itf.degree;
    const std::string  label = name + ", k = " + std::to_string(k);
    double             weight = 0, length = 0, normal_err = 0, tangent_err = 0, gap_err = 0, shift = 0,
           location = 0;
    unsigned int n_mid = 0, wrong_interface = 0;
    T            t;
    t[0] = -x.normal[1];
    t[1] = x.normal[0];
    for (const auto &p : itf.pairs)
      {
        weight += p.weight;
        normal_err  = std::max(normal_err, (p.normal - x.normal).norm());
        tangent_err = std::max(tangent_err, (p.tangent - t).norm());
        gap_err     = std::max(gap_err, std::abs(p.initial_gap - x.gap));
        shift       = std::max(shift, std::abs((p.slave_location - p.master_location) * t));
        n_mid += p.on_edge();
        wrong_interface += (p.interface != index);
        // the entities are where the locations say
        if (p.on_edge())
          {
            const auto &em = mesh.edge(p.master_entity).vertices;
            const auto &es = mesh.edge(p.slave_entity).vertices;
            location       = std::max(
              {location,
               p.master_location.distance(0.5 * (mesh.vertex(em[0]) + mesh.vertex(em[1]))),
               p.slave_location.distance(0.5 * (mesh.vertex(es[0]) + mesh.vertex(es[1])))});
          }
        else
          location = std::max({location, p.master_location.distance(mesh.vertex(p.master_entity)),
                               p.slave_location.distance(mesh.vertex(p.slave_entity))});
      }
    for (const auto &s : itf.segments)
      length += s.length;
    std::cout << "      " << label << ": " << itf.pairs.size() << " pairs (" << n_mid
              << " midpoint pairs), " << itf.segments.size() << " segments" << std::endl;
    check_count(k == 1 ? x.pairs_k1 : x.pairs_k2, itf.pairs.size(), label + ": number of pairs");
    testing::check(itf.pairs.size() - n_mid == itf.segments.size() + 1 &&
                     n_mid == (k == 2 ? itf.segments.size() : 0u),
                   label + ": one chain: vertex pairs = segments + 1, midpoint pairs = " +
                     (k == 2 ? std::string("segments") : std::string("0")));
    testing::check_near(weight, x.length, 1e-14 * x.length, label + ": sum of the weights = interface length");
    testing::check_near(length, x.length, 1e-14 * x.length,
                        label + ": sum of the segment lengths = interface length");
    testing::check_small(normal_err, 1e-14, label + ": normals");
    testing::check_small(tangent_err, 1e-14, label + ": tangents");
    testing::check_small(gap_err, x.tolerance, label + ": initial gaps = " + std::to_string(x.gap));
    testing::check_small(shift, x.tolerance, label + ": master and slave node of each pair opposite");
    testing::check_small(location, 1e-15, label + ": pair locations = entity locations");
    testing::check(wrong_interface == 0, label + ": interface index " + std::to_string(index));
    // ordered along the slave side (which runs along -t, counter-clockwise
    // around the upper body)
    bool ordered = true;
    for (unsigned int i = 1; i < itf.pairs.size(); ++i)
      ordered = ordered && (itf.pairs[i].slave_location * t < itf.pairs[i - 1].slave_location * t);
    testing::check(ordered, label + ": pairs ordered along the slave side");
  }

  /// Insert for k = 1 and 2 (each on a copy of @p mesh), check the report,
  /// the mesh and the pairs; return the mesh after insertion (k = 1).
  Mesh
  run(const Mesh &original, const unsigned int master, const unsigned int slave, const Expected &x,
      const std::string &name, const NodeInsertion::Settings &settings = NodeInsertion::Settings())
  {
    std::cout << name << std::endl;
    const double area = original.total_area();
    Mesh         result;
    for (const unsigned int k : {1u, 2u})
      {
        Mesh       mesh = original;
        const auto itf  = NodeInsertion::insert(mesh, master, slave, k, settings);
        const std::string label = name + ", k = " + std::to_string(k);
        check_report(itf.report, x, label);
        bool valid = true;
        try
          {
            mesh.validate();
          }
        catch (const std::exception &e)
          {
            std::cout << e.what() << std::endl;
            valid = false;
          }
        testing::check(valid, label + ": mesh valid after insertion");
        if (x.same_area)
          testing::check_near(mesh.total_area(), area, 1e-14 * area, label + ": total area unchanged");
        const double h_min = std::min(min_edge_length(mesh, master), min_edge_length(mesh, slave));
        testing::check(h_min >= x.min_length, label + ": shortest interface edge " + std::to_string(h_min) +
                                                " >= " + std::to_string(x.min_length));
        check_interface(mesh, itf, 0, x, name);
        if (k == 1)
          result = mesh;
      }
    return result;
  }

  T
  up()
  {
    T n;
    n[1] = 1;
    return n;
  }

  /// Flat touching interface, complete overlap (see the top of the file).
  Expected
  flat(const int n_m, const int n_s, const int c)
  {
    Expected x;
    x.inserted_master   = n_s + 1 - c;
    x.inserted_slave    = n_m + 1 - c;
    x.merged            = c;
    x.master_edges      = n_m + n_s + 1 - c;
    x.slave_edges       = x.master_edges;
    x.closed            = x.master_edges + 1;
    x.pairs_k1          = x.master_edges + 1;
    x.pairs_k2          = 2 * x.master_edges + 1;
    x.n_master_vertices = n_m + 1;
    x.n_slave_vertices  = n_s + 1;
    x.normal            = up();
    // shortest sub-edge: 1 / (n_m n_s) times the gcd structure; a bound
    x.min_length = 1. / (n_m * n_s) - 1e-14;
    return x;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // lower block: ids 0..3 (top 3 = master); upper block: ids 4..7 (bottom 6 = slave)

  // a) 3 against 4 quads: master 0, 1/3, 2/3, 1 and slave 0, 1/4, .., 1;
  // the corners merge, the 3 interior slave vertices go into the master
  // side and the 2 interior master vertices into the slave side: 7
  // vertices, 6 sub-edges, 7 pairs (k = 1) and 13 (k = 2); the shortest
  // sub-edge is 1/3 - 1/4 = 1/12
  {
    Expected x = flat(3, 4, 2);
    testing::check(x.inserted_master == 3 && x.inserted_slave == 2 && x.merged == 2 && x.pairs_k1 == 7 &&
                     x.pairs_k2 == 13,
                   "a) hand count 3 / 4: 3 inserted master, 2 inserted slave, 2 merged, 7 and 13 pairs");
    x.min_length = 1. / 12 - 1e-14;
    Mesh mesh = run(join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0, 1, 1, 2, 4, 4, 1, 4)), 3, 6, x,
                    "a) flat 3x3 / 4x4");
    // inserting again changes nothing: all 7 vertex pairs merge
    const unsigned int n_vertices = mesh.n_vertices();
    const auto         again      = NodeInsertion::insert(mesh, 3, 6, 1, NodeInsertion::Settings());
    Expected           y;
    y.inserted_master = y.inserted_slave = 0;
    y.merged = y.closed = 7;
    y.master_edges = y.slave_edges = 6;
    check_report(again.report, y, "a) insert again");
    testing::check(mesh.n_vertices() == n_vertices && again.pairs.size() == 7u,
                   "a) insert again: no new vertex, the same 7 pairs");
  }
  run(join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0, 1, 1, 2, 7, 7, 1, 4)), 3, 6, flat(3, 7, 2),
      "a) flat 3x3 / 7x7");
  {
    // Voronoi upper block: only the partner counts are fixed (a Voronoi
    // vertex may fall within the merge distance of 1/3 or 2/3)
    const Mesh   upper = voronoi_block(0, 1, 1, 2, 49, 1, 4);
    const int    n_s   = n_edges_with_id(upper, 6);
    Expected     x;
    x.n_master_vertices = 4;
    x.n_slave_vertices  = n_s + 1;
    x.normal            = up();
    x.min_length        = 0.05 * min_edge_length(upper, 6);
    std::cout << "      Voronoi upper block: " << n_s << " interface edges" << std::endl;
    run(join(block(0, 0, 1, 1, 3, 3, 0, 0), upper), 3, 6, x, "a) flat 3x3 / Voronoi");
  }

  // b) ratios
  run(join(block(0, 0, 1, 1, 1, 1, 0, 0), block(0, 1, 1, 2, 3, 3, 1, 4)), 3, 6, flat(1, 3, 2),
      "b) ratio 1:3");
  run(join(block(0, 0, 1, 1, 2, 2, 0, 0), block(0, 1, 1, 2, 7, 7, 1, 4)), 3, 6, flat(2, 7, 2),
      "b) ratio 2:7");
  run(join(block(0, 0, 1, 1, 2, 2, 0, 0), block(0, 1, 1, 2, 4, 4, 1, 4)), 3, 6, flat(2, 4, 3),
      "b) ratio 1:2, shared middle vertex");

  // c) sloped at 30 degrees: lower top y = 1 + tan30 x, upper bottom the same line
  {
    const double t     = std::tan(M_PI / 6);
    const auto   lower = [t](const double xi, const double eta, unsigned int, unsigned int) {
      return P(xi, eta * (1 + t * xi));
    };
    const auto upper = [t](const double xi, const double eta, unsigned int, unsigned int) {
      return P(xi, 1 + t * xi + eta * (1 - t * xi));
    };
    Expected x  = flat(3, 5, 2);
    x.length    = 1 / std::cos(M_PI / 6);
    x.normal[0] = -std::sin(M_PI / 6);
    x.normal[1] = std::cos(M_PI / 6);
    x.tolerance = 1e-14;
    run(join(mapped_quads(3, 3, lower, 0, 0), mapped_quads(5, 4, upper, 1, 4)), 3, 6, x,
        "c) sloped 30 degrees, 3 / 5");
  }

  // d) partial overlap: upper block [0.5,1.5]x[1,2] with 4x4 cells; slave
  // vertices 0.5, 0.75 go into the master side, master vertex 2/3 into
  // the slave side, the vertices at x = 1 merge; 1/3, 1.25, 1.5 lie
  // outside the overlap [0.5, 1]
  {
    Expected x;
    x.inserted_master = 2;
    x.inserted_slave  = 1;
    x.merged          = 1;
    x.closed          = 4;
    x.master_edges    = 5;
    x.slave_edges     = 5;
    x.pairs_k1        = 4;
    x.pairs_k2        = 7;
    x.length          = 0.5;
    x.normal          = up();
    x.min_length      = 0.75 - 2. / 3 - 1e-14; // 1/12
    run(join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0.5, 1, 1.5, 2, 4, 4, 1, 4)), 3, 6, x,
        "d) partial overlap");
  }

  // e) three stacked blocks, two interfaces (ids 3 : 6 and 7 : 10)
  {
    std::cout << "e) two interfaces" << std::endl;
    Mesh mesh = join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0, 1, 1, 2, 5, 5, 1, 4));
    mesh.append(block(0, 2, 1, 3, 4, 4, 2, 8));
    const double            area = mesh.total_area();
    NodeInsertion::Settings settings;
    for (const unsigned int k : {1u, 2u})
      {
        Mesh       m    = mesh;
        const auto itf0 = NodeInsertion::insert(m, 3, 6, k, settings, 0);
        const auto itf1 = NodeInsertion::insert(m, 7, 10, k, settings, 1);
        const std::string label = "e) k = " + std::to_string(k);
        check_report(itf0.report, flat(3, 5, 2), label + ", interface 0 (3 : 6)");
        check_report(itf1.report, flat(5, 4, 2), label + ", interface 1 (7 : 10)");
        m.validate();
        testing::check_near(m.total_area(), area, 1e-14 * area, label + ": total area unchanged");
        check_interface(m, itf0, 0, flat(3, 5, 2), "e) interface 0");
        check_interface(m, itf1, 1, flat(5, 4, 2), "e) interface 1");
      }
  }

  // f) merging instead of short sub-edges: master vertices 0, 1/4, .., 1
  // (h = 1/4); the 3 interior slave vertices are moved along the interface
  // by delta h. With merge fraction f, a pair merges if delta h <= f times
  // the shortest edge at the two vertices, h (1 - delta) at the last one:
  // delta <= f (1 - delta). Then all 5 vertex pairs merge, nothing is
  // inserted, the slave vertices move onto the master vertices and every
  // sub-edge is h again. Otherwise the 3 interior vertices of each side go
  // into the other one (8 vertices, 7 sub-edges) and the shortest sub-edge
  // is delta h >= 0.05 h. Merge fractions 0.05 and 0.1, and 1e-9 (that of
  // FiniteSliding): a vertex closer than 1e-3 of an edge to a vertex of the
  // other side merges then too (delta < 1e-3 (1 - delta)), the shortest
  // sub-edge a split makes; before, both vertices were left unpaired.
  for (const double fraction : {0.05, 0.1, 1e-9})
    for (const double delta : {1e-7, 1e-5, 1e-3, 1e-2, 0.03, 0.08, 0.15})
      {
        // (delta = 1e-3 with the fraction 1e-9 lies on the threshold itself:
        // either answer is right)
        if (fraction < 1e-3 && delta == 1e-3)
          continue;
        NodeInsertion::Settings settings;
        settings.merge_fraction = fraction;
        const double h          = 0.25;
        const auto upper = [&](const double xi, const double eta, const unsigned int i, const unsigned int j) {
          return P(xi + (j == 0 && i > 0 && i < 4 ? delta * h : 0.), 1 + eta);
        };
        const bool merge = delta <= fraction * (1 - delta) || delta < 1e-3 * (1 - delta);
        Expected   x;
        x.inserted_master   = merge ? 0 : 3;
        x.inserted_slave    = merge ? 0 : 3;
        x.merged            = merge ? 5 : 2;
        x.closed            = merge ? 5 : 8;
        x.master_edges      = merge ? 4 : 7;
        x.slave_edges       = x.master_edges;
        x.pairs_k1          = x.master_edges + 1;
        x.pairs_k2          = 2 * x.master_edges + 1;
        x.n_master_vertices = 5;
        x.n_slave_vertices  = 5;
        x.normal            = up();
        x.min_length        = (merge ? h : delta * h) - 1e-15;
        x.same_area         = !merge; // a merge moves the slave vertex
        std::ostringstream name;
        name << "f) merge fraction " << fraction << ", slave vertices " << delta
             << " h beside the master vertices";
        run(join(block(0, 0, 1, 1, 4, 1, 0, 0), mapped_quads(4, 2, upper, 1, 4)), 3, 6, x, name.str(),
            settings);
      }

  // g) unpaired nodes: a half disc of radius 1 centred at (0, 1) (fan of
  // triangles, arc vertices every 7.5 degrees at (sin a, 1 - cos a)) on the
  // flat top y = 0 of the block [-1,1]x[-0.5,0] (4 edges). The interface
  // size is the diagonal of [-1,1]x[0,1], sqrt(5); with search distance
  // 0.02 nodes farther than 0.02 sqrt(5) = 0.0447 from the other side stay
  // unpaired: the arc vertices at a = 0, +-7.5, +-15 degrees (gaps 1 - cos a
  // up to 0.034) pair, those at +-22.5 degrees (gap 0.076) are reported,
  // as are the master vertices at x = +-0.5 (gap 1 - cos 30 = 0.134).
  // Pairs: the bottom vertices merge, the 4 other arc vertices go into the
  // master side; 5 vertex pairs, 4 segments (chords of 7.5 degrees), the
  // gaps 1 - cos a are real and kept.
  {
    std::cout << "g) half disc on a block, partly beyond the search distance" << std::endl;
    const double R = 1, dtheta = M_PI / 24;
    Mesh         upper;
    upper.name                = "half disc";
    const unsigned int centre = upper.add_vertex(P(0, R));
    std::vector<unsigned int> arc;
    for (int j = 0; j <= 24; ++j)
      {
        const double a = -M_PI / 2 + j * dtheta;
        arc.push_back(upper.add_vertex(P(R * std::sin(a), R - R * std::cos(a))));
      }
    for (unsigned int j = 0; j < 24; ++j)
      {
        upper.add_cell({centre, arc[j], arc[j + 1]}, 1);
        upper.set_boundary_id(arc[j], arc[j + 1], 6);
      }
    upper.set_boundary_id(centre, arc[0], 7);
    upper.set_boundary_id(arc[24], centre, 7);
    upper.finalize();
    const Mesh original = join(block(-1, -0.5, 1, 0, 4, 1, 0, 0), upper);

    NodeInsertion::Settings settings;
    settings.search_distance = 0.02;
    const double chord       = 2 * R * std::sin(dtheta / 2);
    for (const unsigned int k : {1u, 2u})
      {
        const std::string label = "g) half disc, k = " + std::to_string(k);
        Mesh              mesh  = original;
        const auto        itf   = NodeInsertion::insert(mesh, 3, 6, k, settings);
        const auto       &r     = itf.report;
        Expected          x;
        x.inserted_master = 4;
        x.inserted_slave  = 0;
        x.merged          = 1;
        x.closed          = 1; // the touching bottom vertex (g_0 = 0)
        x.master_edges    = 8;
        x.slave_edges     = 24;
        x.unpaired        = true;
        check_report(r, x, label);
        mesh.validate();
        // the reported nodes
        bool         slave_22 = false, master_05 = false, reasons = true;
        unsigned int n_listed_paired = 0;
        for (const auto &u : r.unpaired)
          {
            std::cout << "      unpaired " << (u.on_master ? "master" : "slave") << " vertex at ("
                      << u.location[0] << ", " << u.location[1] << "): " << u.reason << std::endl;
            reasons = reasons && u.reason.find("search distance") != std::string::npos;
            if (!u.on_master && std::abs(std::abs(u.location[0]) - std::sin(3 * dtheta)) < 1e-14)
              slave_22 = true;
            if (u.on_master && std::abs(std::abs(u.location[0]) - 0.5) < 1e-14 && std::abs(u.location[1]) < 1e-14)
              master_05 = true;
            n_listed_paired += (std::abs(u.location[0]) < 0.3);
          }
        testing::check(!r.unpaired.empty() && reasons,
                       label + ": unpaired nodes reported, each beyond the search distance");
        testing::check(slave_22 && master_05,
                       label + ": the arc vertices at +-22.5 degrees and the master vertices at x = +-0.5 "
                               "are reported");
        testing::check(n_listed_paired == 0, label + ": no paired node (|x| < 0.3) reported");
        double weight = 0, gap_err = 0, x_err = 0, max_x = 0;
        for (const auto &p : itf.pairs)
          {
            weight += p.weight;
            x_err = std::max(x_err, std::abs(p.master_location[0] - p.slave_location[0]));
            max_x = std::max(max_x, std::abs(p.slave_location[0]));
            // vertex: on the circle; midpoint: mean of the chord's ends
            double g0 = R - std::sqrt(R * R - p.slave_location[0] * p.slave_location[0]);
            if (p.on_edge())
              {
                const auto &e = mesh.edge(p.slave_entity).vertices;
                g0            = 0.5 * (mesh.vertex(e[0])[1] + mesh.vertex(e[1])[1]);
              }
            gap_err = std::max(gap_err, std::abs(p.initial_gap - g0));
          }
        check_count(k == 1 ? 5 : 9, itf.pairs.size(), label + ": number of pairs");
        check_count(4, itf.segments.size(), label + ": number of segments");
        testing::check(max_x < 0.3, label + ": only nodes with |x| < 0.3 pair");
        testing::check_small(gap_err, 1e-12, label + ": real gaps kept: g0 = R - sqrt(R^2 - x^2)");
        testing::check_small(x_err, 1e-14, label + ": master node below the slave node");
        testing::check_near(weight, 4 * chord, 1e-14, label + ": weights sum to the paired arc length");
      }
  }

  // h) real gaps and penetrations are kept. Two blocks g apart (upper
  // block independently meshed, structured and Voronoi): every pair has
  // g_0 = g (to 1e-12 relative), the nodes are opposite each other along
  // the normal, and no gap is closed (|g| is far above the coordinate
  // precision 1e-5 (|x| + |y|) <= 2e-5 and the sides are flat).
  for (const double g : {0.01, 0.1, -0.01})
    for (const bool voronoi : {false, true})
      {
        const Mesh upper = voronoi ? voronoi_block(0, 1 + g, 1, 2 + g, 30, 1, 4) :
                                     block(0, 1 + g, 1, 2 + g, 4, 4, 1, 4);
        Expected   x;
        x.closed            = 0;
        x.n_master_vertices = 4;
        x.n_slave_vertices  = n_edges_with_id(upper, 6) + 1;
        x.normal            = up();
        x.gap               = g;
        x.tolerance         = 1e-12 * std::abs(g);
        x.min_length        = voronoi ? 0.05 * min_edge_length(upper, 6) : 1. / 12 - 1e-14;
        std::ostringstream name;
        name << "h) " << (g > 0 ? "gap " : "penetration ") << std::abs(g) << ", 3x3 / "
             << (voronoi ? "Voronoi" : "4x4");
        run(join(block(0, 0, 1, 1, 3, 3, 0, 0), upper), 3, 6, x, name.str());
      }
  // ... and slave interior vertices moved normally (away from the lower
  // block) by delta h, h = 1/4: all 5 vertex pairs merge; the moved
  // coordinates are computed in double precision, so for every delta
  // (1e-7 .. 1e-2) the gap delta h is real and kept at the 3 interior
  // pairs (only the 2 corner pairs, at zero gap, closed).
  for (const double delta : {1e-7, 1e-5, 1e-3, 1e-2})
    for (const unsigned int k : {1u, 2u})
      {
        const double h     = 0.25;
        const auto   upper = [&](const double xi, const double eta, const unsigned int i, const unsigned int j) {
          return P(xi, 1 + eta + (j == 0 && i > 0 && i < 4 ? delta * h : 0.));
        };
        // computed in double precision: a real gap for every delta (the
        // data carry no decimal rounding; the old rule closed delta h < 1e-5)
        const bool closed = false;
        Mesh       mesh   = join(block(0, 0, 1, 1, 4, 1, 0, 0), mapped_quads(4, 2, upper, 1, 4));
        const auto itf    = NodeInsertion::insert(mesh, 3, 6, k, NodeInsertion::Settings());
        std::ostringstream name;
        name << "h) slave vertices " << delta << " h above the master vertices, k = " << k;
        Expected x;
        x.inserted_master = x.inserted_slave = 0;
        x.merged                             = 5;
        x.closed                             = closed ? 5 : 2;
        check_report(itf.report, x, name.str());
        double gap_err = 0, shift = 0;
        for (const auto &p : itf.pairs)
          {
            const double xs     = p.slave_location[0];
            const auto   vertex = [&](const double x) { return (x > 0.1 && x < 0.9) ? delta * h : 0.; };
            // a midpoint pair: the mean of the gaps at the ends of its edge
            const double expected =
              closed ? 0. : (p.on_edge() ? 0.5 * (vertex(xs - h / 2) + vertex(xs + h / 2)) : vertex(xs));
            gap_err               = std::max(gap_err, std::abs(p.initial_gap - expected));
            shift                 = std::max(shift, std::abs(p.slave_location[0] - p.master_location[0]));
          }
        check_count(k == 1 ? 5 : 9, itf.pairs.size(), name.str() + ": number of pairs");
        testing::check_small(gap_err, 1e-15, name.str() + (closed ? ": gaps closed (g0 = 0)" :
                                                                     ": gaps delta h kept at the interior pairs"));
        testing::check_small(shift, 1e-15, name.str() + ": nodes opposite each other");
      }

  // i) errors, each naming the interface
  {
    std::cout << "i) errors" << std::endl;
    const NodeInsertion::Settings settings;
    const Mesh two = join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0, 1, 1, 2, 4, 4, 1, 4));
    testing::check_throws([&] { Mesh m = two; NodeInsertion::insert(m, 3, 42, 1, settings); },
                          "(master id 3, slave id 42): boundary id 42 has no boundary edges",
                          "i) unknown boundary id");
    testing::check_throws([&] { Mesh m = two; NodeInsertion::insert(m, 3, 0, 1, settings); },
                          "(master id 3, slave id 0): both boundary ids 3 and 0 belong to the same body",
                          "i) both ids on the same body");
    testing::check_throws([&] { Mesh m = two; NodeInsertion::insert(m, 3, 6, 3, settings); },
                          "(master id 3, slave id 6): contact node pairs are implemented for at most one node "
                          "inside an edge (order k = 1 and 2), not k = 3",
                          "i) degree 3");
    // the upper block keeps the ids 0..3: id 3 is on both bodies
    const Mesh same_ids = join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0, 1, 1, 2, 4, 4, 1, 0));
    testing::check_throws([&] { Mesh m = same_ids; NodeInsertion::insert(m, 3, 2, 1, settings); },
                          "(master id 3, slave id 2): the boundary edges with id 3 belong to more than one body",
                          "i) one boundary id on two bodies");
    const Mesh far = join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0, 5, 1, 6, 4, 4, 1, 4));
    testing::check_throws([&] { Mesh m = far; NodeInsertion::insert(m, 3, 6, 1, settings); },
                          "(master id 3, slave id 6): the boundary parts do not face or overlap",
                          "i) parts far apart");
    // the top of the lower block against the left side of the upper block:
    // they touch at (0, 1), but the normals are at 90 degrees
    testing::check_throws([&] { Mesh m = two; NodeInsertion::insert(m, 3, 4, 1, settings); },
                          "(master id 3, slave id 4): the boundary parts do not face or overlap",
                          "i) parts not facing each other");
    NodeInsertion::Settings bad;
    bad.merge_fraction = 0.6;
    testing::check_throws([&] { Mesh m = two; NodeInsertion::insert(m, 3, 6, 1, bad); },
                          "(master id 3, slave id 6): the merge fraction must lie in (0, 0.5)",
                          "i) merge fraction out of range");
  }

  // j) the facing test with a band (Settings::keep_facing): a slave side
  // that lies flat on the master side for x in [0.25, 0.75] and then rises
  // at 70 degrees, so that the outward normals of its rising part and of
  // the master side are at 110 degrees. Its first vertex there,
  // (0.75 + 0.15 cos 70, 1 + 0.15 sin 70), 0.56 master edges above the
  // master side, fails the facing test (120 degrees) and is reported
  // unpaired; listed in keep_facing (a vertex paired in an earlier pass of
  // FiniteSliding) it keeps a partner: its closest point on the master
  // side. The last vertex, not listed, stays unpaired.
  {
    std::cout << "j) the facing test with a band (keep_facing)" << std::endl;
    const double c = std::cos(70 * M_PI / 180), s = std::sin(70 * M_PI / 180);
    const auto   bottom = [&](const double xi) {
      return xi <= 0.5 ? P(0.25 + xi, 1.) : P(0.75 + 0.6 * (xi - 0.5) * c, 1. + 0.6 * (xi - 0.5) * s);
    };
    const auto upper = [&](const double xi, const double eta, unsigned int, unsigned int) {
      return bottom(xi) + T({0., 0.5 * eta});
    };
    const Mesh         lower    = block(0, 0, 2, 1, 8, 2, 0, 0);
    const Mesh         both     = join(lower, mapped_quads(4, 1, upper, 1, 4));
    const unsigned int rising   = lower.n_vertices() + 3; // (i, j) = (3, 0)
    const unsigned int last     = lower.n_vertices() + 4;
    const auto         paired   = [](const NodeInsertion::Interface &itf, const unsigned int v) {
      for (const auto &p : itf.pairs)
        if (!p.on_edge() && p.slave_entity == v)
          return &p;
      return static_cast<const ContactNodePair *>(nullptr);
    };
    const auto unpaired = [](const NodeInsertion::Interface &itf, const unsigned int v) {
      for (const auto &u : itf.report.unpaired)
        if (!u.on_master && u.vertex == v)
          return u.reason;
      return std::string();
    };
    for (const unsigned int k : {1u, 2u})
      {
        const std::string name = "j) k = " + std::to_string(k) + ": ";
        Mesh              plain = both;
        const auto        itf   = NodeInsertion::insert(plain, 3, 6, k, NodeInsertion::Settings());
        testing::check(plain.vertex(rising).distance(bottom(0.75)) < 1e-15, name + "the rising vertex found");
        testing::check(paired(itf, rising) == nullptr, name + "without keep_facing the rising vertex has no partner");
        testing::check(unpaired(itf, rising).find("does not face") != std::string::npos,
                       name + "without keep_facing the rising vertex is reported as not facing");
        NodeInsertion::Settings band;
        band.keep_facing = {rising};
        Mesh       kept  = both;
        const auto itf2  = NodeInsertion::insert(kept, 3, 6, k, band);
        const auto *pair = paired(itf2, rising);
        testing::check(pair != nullptr, name + "with keep_facing the rising vertex has a partner");
        if (pair != nullptr)
          testing::check_small(pair->master_location.distance(P(bottom(0.75)[0], 1.)), 1e-14,
                               name + "its partner is its closest point on the master side");
        testing::check(paired(itf2, last) == nullptr && !unpaired(itf2, last).empty(),
                       name + "the last vertex, not listed, stays unpaired");
        testing::check(itf2.pairs.size() == itf.pairs.size() + (k == 1 ? 1 : 2),
                       name + "keep_facing adds the one pair and its edge's midpoint pair (k = 2), nothing else");
        kept.validate();
      }
  }

  return testing::finish();
}
