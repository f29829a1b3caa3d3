// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Node insertion on contact interfaces (NodeInsertion::insert and
// make_pairs), with numbers fixed by the geometry.
//
// Counting for two straight sides that overlap completely, with n_m + 1
// master and n_s + 1 slave vertices of which c coincide (the corners and
// shared interior vertices): pass 1 snaps c slave vertices and inserts
// n_s + 1 - c into the master side; pass 2 finds the n_s + 1 master
// vertices matched in pass 1 (counted as snapped) and inserts the other
// n_m + 1 - c into the slave side. So
//   n_inserted_master = n_s + 1 - c, n_inserted_slave = n_m + 1 - c,
//   n_snapped = c + (n_s + 1) = 2c + n_inserted_master,
//   n_master_edges = n_slave_edges = n_m + n_s + 2 - c - 1.
//
// a) flat interface, 3x3 lower block, 7x7 (and Voronoi) upper block;
// b) ratios 1:3, 2:7, 1:2 (shared middle vertex), a vertex shifted by 1e-9
//    (snaps, no tiny edge);
// c) interface sloped at 30 degrees;
// d) partial overlap;
// e) curved slave side (polygonal arc) with initial gaps;
// f) two interfaces in one mesh (three stacked blocks);
// g) errors.
// For k = 1 and 2: weights sum to the interface length, normals, gaps,
// coinciding locations, midpoint pairs for k = 2, the mesh stays valid and
// its area unchanged.
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

  /// nx by ny quads of the unit square mapped by @p map, built by hand;
  /// boundary ids left/right/bottom/top = offset + 0/1/2/3.
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

  std::string
  report_string(const NodeInsertion::Report &r)
  {
    std::ostringstream s;
    s << "inserted master " << r.n_inserted_master << ", inserted slave " << r.n_inserted_slave
      << ", snapped " << r.n_snapped << ", master edges " << r.n_master_edges << ", slave edges "
      << r.n_slave_edges;
    return s.str();
  }

  /// Vertices (sorted along @p t) and edge lengths of the boundary part @p id.
  std::vector<P>
  side_vertices(const Mesh &mesh, const unsigned int id, const T &t)
  {
    std::vector<unsigned int> v;
    for (const auto &e : mesh.get_edges())
      if (e.at_boundary() && e.boundary_id == id)
        v.insert(v.end(), e.vertices.begin(), e.vertices.end());
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    std::vector<P> p;
    for (const auto i : v)
      p.push_back(mesh.vertex(i));
    std::sort(p.begin(), p.end(), [&](const P &a, const P &b) { return a * t < b * t; });
    return p;
  }

  double
  min_edge_length(const Mesh &mesh, const unsigned int id)
  {
    double m = 1e300;
    for (const auto &e : mesh.get_edges())
      if (e.at_boundary() && e.boundary_id == id)
        m = std::min(m, mesh.vertex(e.vertices[0]).distance(mesh.vertex(e.vertices[1])));
    return m;
  }

  struct Expected
  {
    int    inserted_master = -1, inserted_slave = -1, snapped = -1, master_edges = -1,
        slave_edges = -1;
    /// Length of the overlap (sum of the weights).
    double length = 1;
    T      normal;
    /// The sides carry the same vertices (complete overlap, flat).
    bool   same_vertices = true;
    /// Tolerance for coinciding locations and zero gaps.
    double tolerance = 1e-14;
    /// Lower bound for the interface edge lengths after insertion.
    double min_length = 1e-3;
  };

  void
  check_report(const NodeInsertion::Report &r, const Expected &x, const std::string &name)
  {
    std::cout << "      " << name << ": " << report_string(r) << std::endl;
    const auto c = [&](const int expected, const unsigned int value, const std::string &what) {
      if (expected >= 0)
        testing::check(int(value) == expected, name + ": " + what + " = " + std::to_string(value) +
                                                 " (expected " + std::to_string(expected) + ")");
    };
    c(x.inserted_master, r.n_inserted_master, "n_inserted_master");
    c(x.inserted_slave, r.n_inserted_slave, "n_inserted_slave");
    c(x.snapped, r.n_snapped, "n_snapped");
    c(x.master_edges, r.n_master_edges, "n_master_edges");
    c(x.slave_edges, r.n_slave_edges, "n_slave_edges");
  }

  /// Checks of the pairs of one interface for one degree.
  void
  check_pairs(const Mesh &mesh, const std::vector<ContactNodePair> &pairs, const unsigned int k,
              const unsigned int interface, const unsigned int n_slave_edges, const Expected &x,
              const std::string &name)
  {
    const std::string label = name + ", k = " + std::to_string(k);
    double            weight = 0, normal_err = 0, tangent_err = 0, gap = 0, location = 0;
    unsigned int      n_mid = 0, wrong_interface = 0;
    for (const auto &p : pairs)
      {
        weight += p.weight;
        normal_err  = std::max(normal_err, (p.normal - x.normal).norm());
        T t;
        t[0]        = -x.normal[1];
        t[1]        = x.normal[0];
        tangent_err = std::max(tangent_err, (p.tangent - t).norm());
        gap         = std::max(gap, std::abs(p.initial_gap));
        location    = std::max(location, p.master_location.distance(p.slave_location));
        n_mid += p.is_midpoint;
        wrong_interface += (p.interface != interface);
        // the entities are where the locations say
        if (p.is_midpoint)
          {
            const auto &em = mesh.edge(p.master_entity).vertices;
            const auto &es = mesh.edge(p.slave_entity).vertices;
            location = std::max(location, p.master_location.distance(
                                            0.5 * (mesh.vertex(em[0]) + mesh.vertex(em[1]))));
            location = std::max(location, p.slave_location.distance(
                                            0.5 * (mesh.vertex(es[0]) + mesh.vertex(es[1]))));
          }
        else
          {
            location = std::max(location, p.master_location.distance(mesh.vertex(p.master_entity)));
            location = std::max(location, p.slave_location.distance(mesh.vertex(p.slave_entity)));
          }
      }
    std::cout << "      " << label << ": " << pairs.size() << " pairs (" << n_mid << " midpoint pairs)"
              << std::endl;
    testing::check_near(weight, x.length, 1e-14, label + ": sum of the weights = interface length");
    testing::check_small(normal_err, 1e-14, label + ": normals");
    testing::check_small(tangent_err, 1e-14, label + ": tangents");
    testing::check_small(gap, x.tolerance, label + ": initial gaps zero");
    testing::check_small(location, x.tolerance, label + ": the locations of each pair coincide");
    testing::check(wrong_interface == 0, label + ": interface index " + std::to_string(interface));
    if (x.same_vertices)
      {
        testing::check(pairs.size() - n_mid == n_slave_edges + 1,
                       label + ": one vertex pair per interface vertex (" +
                         std::to_string(pairs.size() - n_mid) + ")");
        testing::check(n_mid == (k == 2 ? n_slave_edges : 0),
                       label + ": midpoint pairs = interface sub-edges (" + std::to_string(n_mid) + ")");
      }
    // ordered along the interface
    bool monotone = true;
    T    t;
    t[0] = -x.normal[1];
    t[1] = x.normal[0];
    for (unsigned int i = 1; i < pairs.size(); ++i)
      monotone = monotone && (pairs[i].slave_location * t < pairs[i - 1].slave_location * t);
    testing::check(monotone, label + ": pairs ordered along the interface");
  }

  /// Insert, check the report, the mesh and the pairs for k = 1, 2.
  Mesh
  run(Mesh mesh, const unsigned int master, const unsigned int slave, const Expected &x,
      const std::string &name, const NodeInsertion::Settings &settings = NodeInsertion::Settings())
  {
    std::cout << name << std::endl;
    const double area = mesh.total_area();
    const auto   r    = NodeInsertion::insert(mesh, master, slave, settings);
    check_report(r, x, name);
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
    testing::check(valid, name + ": mesh valid after insertion");
    testing::check_near(mesh.total_area(), area, 1e-14 * area, name + ": total area unchanged");
    T t;
    t[0] = -x.normal[1];
    t[1] = x.normal[0];
    if (x.same_vertices)
      {
        const auto   pm = side_vertices(mesh, master, t), ps = side_vertices(mesh, slave, t);
        double       d  = (pm.size() == ps.size() ? 0 : 1e300);
        for (unsigned int i = 0; i < std::min(pm.size(), ps.size()); ++i)
          d = std::max(d, pm[i].distance(ps[i]));
        testing::check_small(d, x.tolerance, name + ": master and slave interface vertices coincide (" +
                                               std::to_string(pm.size()) + " and " +
                                               std::to_string(ps.size()) + ")");
      }
    testing::check(min_edge_length(mesh, master) > x.min_length && min_edge_length(mesh, slave) > x.min_length,
                   name + ": no tiny interface edge");
    for (const unsigned int k : {1u, 2u})
      check_pairs(mesh, NodeInsertion::make_pairs(mesh, master, slave, k, settings), k, 0,
                  r.n_slave_edges, x, name);
    return mesh;
  }

  T
  up()
  {
    T n;
    n[1] = 1;
    return n;
  }

  Expected
  flat(const int n_m, const int n_s, const int c)
  {
    Expected x;
    x.inserted_master = n_s + 1 - c;
    x.inserted_slave  = n_m + 1 - c;
    x.snapped         = 2 * c + x.inserted_master;
    x.master_edges = x.slave_edges = n_m + n_s + 1 - c;
    x.normal                       = up();
    return x;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // lower block: ids 0..3 (top 3 = master); upper block: ids 4..7 (bottom 6 = slave)

  // a) flat, non-matching: 3 vs 7 subdivisions; only the corners coincide
  {
    const Expected x = flat(3, 7, 2);
    testing::check(x.inserted_master == 6 && x.inserted_slave == 2 && x.snapped == 10,
                   "a) hand count: 6 inserted master, 2 inserted slave, 10 snapped");
    Mesh mesh = run(join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0, 1, 1, 2, 7, 7, 1, 4)), 3, 6, x,
                    "a) flat 3x3 / 7x7");
    // inserting again changes nothing: every vertex snaps
    const unsigned int n_vertices = mesh.n_vertices();
    Expected           again      = x;
    again.inserted_master = again.inserted_slave = 0;
    again.snapped                                 = 20;
    check_report(NodeInsertion::insert(mesh, 3, 6, NodeInsertion::Settings()), again, "a) insert again");
    testing::check(mesh.n_vertices() == n_vertices, "a) insert again: no new vertex");
  }
  // a') Voronoi upper block: count its interface vertices
  {
    Mesh upper;
    PolygonalMeshGenerators::voronoi(upper, P(0, 1), P(1, 2), 49, 20, 1);
    relabel(upper, 1, 4);
    unsigned int n_s = 0;
    for (const auto &e : upper.get_edges())
      n_s += (e.at_boundary() && e.boundary_id == 6);
    std::cout << "      Voronoi upper block: " << n_s << " interface edges" << std::endl;
    run(join(block(0, 0, 1, 1, 3, 3, 0, 0), upper), 3, 6, flat(3, n_s, 2), "a') flat 3x3 / Voronoi");
  }

  // b) ratios
  run(join(block(0, 0, 1, 1, 1, 1, 0, 0), block(0, 1, 1, 2, 3, 3, 1, 4)), 3, 6, flat(1, 3, 2),
      "b) ratio 1:3");
  run(join(block(0, 0, 1, 1, 2, 2, 0, 0), block(0, 1, 1, 2, 7, 7, 1, 4)), 3, 6, flat(2, 7, 2),
      "b) ratio 2:7");
  run(join(block(0, 0, 1, 1, 2, 2, 0, 0), block(0, 1, 1, 2, 4, 4, 1, 4)), 3, 6, flat(2, 4, 3),
      "b) ratio 1:2, shared middle vertex");
  {
    // the shared middle vertex of the upper block moved by 1e-9: it snaps
    const auto shifted = [](const double xi, const double eta, const unsigned int i,
                            const unsigned int j) {
      return P(xi + (i == 2 && j == 0 ? 1e-9 : 0.), 1 + eta);
    };
    Expected x  = flat(2, 4, 3);
    x.tolerance = 2e-9;
    const Mesh mesh = run(join(block(0, 0, 1, 1, 2, 2, 0, 0), mapped_quads(4, 4, shifted, 1, 4)), 3, 6, x,
                          "b) vertex 1e-9 off the shared middle vertex");
    testing::check(mesh.n_vertices() == 9 + 25 + 2, "b) shifted: only the two new master vertices added");
  }

  // c) sloped at 30 degrees: lower top y = 1 + tan30 x, upper bottom the same line
  {
    const double t     = std::tan(M_PI / 6);
    const auto   lower = [t](const double xi, const double eta, unsigned int, unsigned int) {
      return P(xi, eta * (1 + t * xi));
    };
    const auto upper = [t](const double xi, const double eta, unsigned int, unsigned int) {
      return P(xi, 1 + t * xi + eta * (1 - t * xi));
    };
    Expected x = flat(3, 5, 2);
    x.length   = 1 / std::cos(M_PI / 6);
    x.normal[0] = -std::sin(M_PI / 6);
    x.normal[1] = std::cos(M_PI / 6);
    run(join(mapped_quads(3, 3, lower, 0, 0), mapped_quads(5, 4, upper, 1, 4)), 3, 6, x,
        "c) sloped 30 degrees, 3 / 5");
  }

  // d) partial overlap: upper block [0.5,1.5]x[1,2] with 4x4 cells
  {
    Expected x;
    x.inserted_master = 2; // x = 0.5, 0.75
    x.inserted_slave  = 1; // x = 2/3
    x.snapped         = 4; // x = 1 in pass 1; 0.5, 0.75, 1 in pass 2
    x.master_edges    = 5;
    x.slave_edges     = 5;
    x.length          = 0.5;
    x.normal          = up();
    x.same_vertices   = false;
    const Mesh mesh =
      run(join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0.5, 1, 1.5, 2, 4, 4, 1, 4)), 3, 6, x, "d) partial overlap");
    for (const unsigned int k : {1u, 2u})
      {
        const auto pairs = NodeInsertion::make_pairs(mesh, 3, 6, k, NodeInsertion::Settings());
        bool       inside = true;
        for (const auto &p : pairs)
          inside = inside && p.slave_location[0] >= 0.5 - 1e-14 && p.slave_location[0] <= 1 + 1e-14;
        testing::check(inside && pairs.size() == (k == 1 ? 4u : 7u),
                       "d) k = " + std::to_string(k) + ": " + std::to_string(pairs.size()) +
                         " pairs, all on x in [0.5, 1]");
      }
  }

  // e) curved slave side: a half disc of radius R = 1 centred at (0, 1),
  // fan of triangles, arc vertices every 7.5 degrees; it touches the flat
  // master side y = 0 (x in [-1, 1], 4 edges of length 0.5) at x = 0. With
  // search distance 0.1 (0.05 absolute on the master side) the arc vertices
  // at 0, +-7.5, +-15 degrees (|x| < 0.3, gaps up to 0.034) pair, the next
  // ones (gap 0.076) do not.
  {
    std::cout << "e) curved slave side" << std::endl;
    const double R = 1, dtheta = M_PI / 24;
    Mesh         upper;
    upper.name = "half disc";
    const unsigned int centre = upper.add_vertex(P(0, R));
    std::vector<unsigned int> arc;
    for (int j = 0; j <= 24; ++j)
      {
        const double theta = -M_PI / 2 + j * dtheta;
        arc.push_back(upper.add_vertex(P(R * std::sin(theta), R - R * std::cos(theta))));
      }
    for (unsigned int j = 0; j < 24; ++j)
      {
        upper.add_cell({centre, arc[j], arc[j + 1]}, 1);
        upper.set_boundary_id(arc[j], arc[j + 1], 6);
      }
    upper.set_boundary_id(centre, arc[0], 7);
    upper.set_boundary_id(arc[24], centre, 7);
    upper.finalize();
    Mesh mesh = join(block(-1, -0.5, 1, 0, 4, 1, 0, 0), upper);

    NodeInsertion::Settings settings;
    settings.search_distance = 0.1;
    const double area = mesh.total_area();
    const auto   r    = NodeInsertion::insert(mesh, 3, 6, settings);
    Expected     x;
    x.inserted_master = 4;
    x.inserted_slave  = 0;
    x.snapped         = 6; // the bottom vertex in pass 1; it and the 4 new vertices in pass 2
    x.master_edges    = 8;
    x.slave_edges     = 24;
    check_report(r, x, "e) curved");
    testing::check_near(mesh.total_area(), area, 1e-14 * area, "e) total area unchanged");
    mesh.validate();
    const double chord = 2 * R * std::sin(dtheta / 2);
    for (const unsigned int k : {1u, 2u})
      {
        const std::string label = "e) curved, k = " + std::to_string(k);
        const auto        pairs = NodeInsertion::make_pairs(mesh, 3, 6, k, settings);
        double            weight = 0, gap_err = 0, normal_err = 0, x_err = 0, max_x = 0;
        unsigned int      n_mid  = 0;
        for (const auto &p : pairs)
          {
            weight += p.weight;
            n_mid += p.is_midpoint;
            normal_err = std::max(normal_err, (p.normal - up()).norm());
            x_err      = std::max(x_err, std::abs(p.master_location[0] - p.slave_location[0]));
            max_x      = std::max(max_x, std::abs(p.slave_location[0]));
            const double xs = p.slave_location[0];
            // vertex: on the circle; midpoint: mean of the chord's ends
            double g0 = R - std::sqrt(R * R - xs * xs);
            if (p.is_midpoint)
              {
                const auto &e = mesh.edge(p.slave_entity).vertices;
                g0            = 0.5 * (mesh.vertex(e[0])[1] + mesh.vertex(e[1])[1]);
              }
            gap_err = std::max(gap_err, std::abs(p.initial_gap - g0));
          }
        std::cout << "      " << label << ": " << pairs.size() << " pairs (" << n_mid << " midpoint pairs)"
                  << std::endl;
        testing::check(pairs.size() == (k == 1 ? 5u : 9u) && n_mid == (k == 1 ? 0u : 4u),
                       label + ": 5 vertex pairs (|x| < 0.3)" + (k == 2 ? " and 4 midpoint pairs" : ""));
        testing::check(max_x < 0.3, label + ": only nodes with |x| < 0.3 pair");
        testing::check_small(gap_err, 1e-12, label + ": gaps g0 = R - sqrt(R^2 - x^2)");
        testing::check_small(normal_err, 1e-14, label + ": normals (0, 1)");
        testing::check_small(x_err, 1e-14, label + ": master node below the slave node");
        testing::check_near(weight, 4 * chord, 1e-14, label + ": weights sum to the paired arc length");
      }
  }

  // f) three stacked blocks, two interfaces
  {
    std::cout << "f) two interfaces" << std::endl;
    Mesh mesh = join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0, 1, 1, 2, 5, 5, 1, 4));
    mesh.append(block(0, 2, 1, 3, 4, 4, 2, 8));
    const double area = mesh.total_area();
    NodeInsertion::Settings settings;
    check_report(NodeInsertion::insert(mesh, 3, 6, settings), flat(3, 5, 2), "f) interface 0 (3 : 6)");
    check_report(NodeInsertion::insert(mesh, 7, 10, settings), flat(5, 4, 2), "f) interface 1 (7 : 10)");
    mesh.validate();
    testing::check_near(mesh.total_area(), area, 1e-14 * area, "f) total area unchanged");
    for (const unsigned int k : {1u, 2u})
      {
        const Expected x0 = flat(3, 5, 2), x1 = flat(5, 4, 2);
        check_pairs(mesh, NodeInsertion::make_pairs(mesh, 3, 6, k, settings, 0), k, 0, x0.slave_edges, x0,
                    "f) interface 0");
        check_pairs(mesh, NodeInsertion::make_pairs(mesh, 7, 10, k, settings, 1), k, 1, x1.slave_edges, x1,
                    "f) interface 1");
      }
  }

  // g) errors
  {
    std::cout << "g) errors" << std::endl;
    const NodeInsertion::Settings settings;
    const Mesh two = join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0, 1, 1, 2, 4, 4, 1, 4));
    testing::check_throws([&] { Mesh m = two; NodeInsertion::insert(m, 3, 42, settings); },
                          "boundary id 42 has no boundary edges", "g) unknown boundary id");
    testing::check_throws([&] { Mesh m = two; NodeInsertion::insert(m, 3, 0, settings); },
                          "belong to the same body", "g) both ids on the same body");
    testing::check_throws([&] { NodeInsertion::make_pairs(two, 3, 0, 1, settings); },
                          "belong to the same body", "g) make_pairs: both ids on the same body");
    // the upper block keeps the ids 0..3: id 3 is on both bodies
    const Mesh same_ids = join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0, 1, 1, 2, 4, 4, 1, 0));
    testing::check_throws([&] { Mesh m = same_ids; NodeInsertion::insert(m, 3, 2, settings); },
                          "belong to more than one body", "g) one boundary id on two bodies");
    const Mesh far = join(block(0, 0, 1, 1, 3, 3, 0, 0), block(0, 5, 1, 6, 4, 4, 1, 4));
    testing::check_throws([&] { Mesh m = far; NodeInsertion::insert(m, 3, 6, settings); },
                          "do not face or overlap", "g) parts far apart");
    testing::check_throws([&] { NodeInsertion::make_pairs(two, 3, 6, 3, settings); }, "k = 3",
                          "g) make_pairs: degree 3");
  }

  return testing::finish();
}
