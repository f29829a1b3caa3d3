// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// ContactDetection::detect() on assemblies whose interfaces are known:
// a) two stacked blocks (3 x 3 and 4 x 4 quads): one interface, the
//    coarser block is the master, ids 1000 : 1001, 3 / 4 edges, length 1,
//    every other edge keeps its id;
// b) running bond (a block of one cell on two blocks of 2 x 2): the top
//    block's bottom edge is split once at the joint; three interfaces
//    (the two bed joints of length 0.5, the head joint of length 1), equal
//    mean edges so the lower body is the master;
// c) blocks that touch at a corner only: no interface;
// d) a gap of 0.1 (edges 1/3: within 0.5 h) is detected, one of 0.2 is
//    not; an overlap of 0.05 is detected;
// e) a tenon in a U-shaped mortise: three interfaces (top, bottom, end;
//    the corners end the chains) of lengths 2, 2, 1;
// f) excluded ids (a boundary condition on the top of the lower block):
//    no interface; the first free id is at least 1000 and above every id;
// g) the detected interfaces, made matching by NodeInsertion, give pairs
//    on every node of the shorter side.
#include <dealvem/contact/contact_detection.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/mesh/generators.h>

#include "../tests.h"

#include <algorithm>

using namespace dealvem;
using testing::check;
using testing::check_near;

namespace
{
  using P = dealii::Point<2>;

  // a rectangle of nx x ny quads as body (material id) b, boundary ids
  // raised by 10 b
  PolygonalMesh<2>
  block(const P &lo, const P &hi, const unsigned int nx, const unsigned int ny, const unsigned int b)
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::structured_quads(mesh, lo, hi, nx, ny);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      mesh.set_material_id(c, b);
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      if (mesh.edge(e).at_boundary())
        mesh.set_edge_boundary_id(e, mesh.edge(e).boundary_id + 10 * b);
    return mesh;
  }

  PolygonalMesh<2>
  assembly(const std::vector<PolygonalMesh<2>> &parts)
  {
    PolygonalMesh<2>                     mesh = parts[0];
    std::vector<const PolygonalMesh<2> *> rest;
    for (unsigned int i = 1; i < parts.size(); ++i)
      rest.push_back(&parts[i]);
    if (!rest.empty())
      mesh.append(rest);
    return mesh;
  }

  // total length of the edges with boundary id @p id
  double
  length_of(const PolygonalMesh<2> &mesh, const unsigned int id)
  {
    double L = 0;
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      if (mesh.edge(e).at_boundary() && mesh.edge(e).boundary_id == id)
        L += mesh.vertex(mesh.edge(e).vertices[0]).distance(mesh.vertex(mesh.edge(e).vertices[1]));
    return L;
  }

  void
  stacked_blocks()
  {
    auto mesh = assembly({block(P(0, 0), P(1, 1), 3, 3, 0), block(P(0, 1), P(1, 2), 4, 4, 1)});
    const unsigned int n_edges = mesh.n_edges();
    const auto r = ContactDetection::detect(mesh, {}, ContactDetection::first_free_id(mesh));
    check(r.interfaces.size() == 1, "a) one interface");
    if (r.interfaces.size() != 1)
      return;
    const auto &i = r.interfaces[0];
    check(i.master_body == 0 && i.slave_body == 1, "a) the coarser block (body 0) is the master");
    check(i.master_id == 1000 && i.slave_id == 1001, "a) ids 1000 : 1001");
    check(i.n_master_edges == 3 && i.n_slave_edges == 4, "a) 3 master and 4 slave edges");
    check_near(i.length, 1., 1e-14, "a) interface length");
    check(r.n_split_edges == 0 && mesh.n_edges() == n_edges, "a) no edge split");
    check_near(length_of(mesh, 1000), 1, 1e-14, "a) master edges cover the top of body 0");
    check_near(length_of(mesh, 1001), 1, 1e-14, "a) slave edges cover the bottom of body 1");
    // the other sides keep their ids: left of body 0 (0), top of body 1 (13)
    check_near(length_of(mesh, 0), 1, 1e-14, "a) left side of body 0 kept");
    check_near(length_of(mesh, 13), 1, 1e-14, "a) top of body 1 kept");
    check(length_of(mesh, 3) == 0 && length_of(mesh, 12) == 0, "a) the interface ids replaced");

    // g) node insertion on the detected interface pairs every node
    const auto itf = NodeInsertion::insert(mesh, i.master_id, i.slave_id, 2, NodeInsertion::Settings());
    // vertices at x = 0, 1/4, 1/3, 1/2, 2/3, 3/4, 1 (7) and a midpoint on each of the 6 sub-edges
    check(itf.pairs.size() == 13, "g) 13 node pairs (k = 2) on the detected interface, got " +
                                    std::to_string(itf.pairs.size()));
  }

  void
  running_bond()
  {
    auto mesh = assembly({block(P(0, 0), P(1, 1), 2, 2, 0), block(P(1, 0), P(2, 1), 2, 2, 1),
                          block(P(0.5, 1), P(1.5, 2), 1, 1, 2)});
    const auto r = ContactDetection::detect(mesh, {}, ContactDetection::first_free_id(mesh));
    check(r.n_split_edges == 1, "b) the top block's bottom edge is split once, got " + std::to_string(r.n_split_edges));
    check(r.interfaces.size() == 3, "b) three interfaces, got " + std::to_string(r.interfaces.size()));
    if (r.interfaces.size() != 3)
      return;
    // ordered by (lower body, higher body)
    const auto &h = r.interfaces[0], &b0 = r.interfaces[1], &b1 = r.interfaces[2];
    check(h.master_body == 0 && h.slave_body == 1, "b) head joint between bodies 0 and 1");
    check_near(h.length, 1, 1e-14, "b) head joint length");
    check(b0.master_body == 0 && b0.slave_body == 2, "b) bed joint of body 2 on body 0 (equal h: lower master)");
    check(b1.master_body == 1 && b1.slave_body == 2, "b) bed joint of body 2 on body 1");
    check_near(b0.length, 0.5, 1e-14, "b) bed joint 0-2 length");
    check_near(b1.length, 0.5, 1e-14, "b) bed joint 1-2 length");
    check(b0.n_master_edges == 1 && b0.n_slave_edges == 1, "b) one edge a side on bed joint 0-2");
  }

  void
  corner_and_gaps()
  {
    {
      auto       mesh = assembly({block(P(0, 0), P(1, 1), 3, 3, 0), block(P(1, 1), P(2, 2), 3, 3, 1)});
      const auto r    = ContactDetection::detect(mesh, {}, 1000);
      check(r.interfaces.empty(), "c) a corner contact is no interface");
    }
    for (const double g : {0.1, 0.2, -0.05})
      {
        auto       mesh = assembly({block(P(0, 0), P(1, 1), 3, 3, 0), block(P(0, 1 + g), P(1, 2 + g), 3, 3, 1)});
        const auto r    = ContactDetection::detect(mesh, {}, 1000);
        const bool expected = (g < 0.5 / 3);
        check(r.interfaces.size() == (expected ? 1u : 0u),
              "d) gap " + std::to_string(g) + (expected ? " detected" : " not detected"));
      }
  }

  void
  mortise_and_tenon()
  {
    // the mortise: [0,3]^2 without [1,3] x [1,2], unit quads (body 0)
    PolygonalMesh<2> mortise;
    for (unsigned int j = 0; j <= 3; ++j)
      for (unsigned int i = 0; i <= 3; ++i)
        mortise.add_vertex(P(i, j));
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int i = 0; i < 3; ++i)
        if (!(j == 1 && i >= 1))
          mortise.add_cell({4 * j + i, 4 * j + i + 1, 4 * (j + 1) + i + 1, 4 * (j + 1) + i}, 0);
    mortise.finalize();
    // the tenon: [1, 3.5] x [1, 2] in 5 x 2 quads (body 1)
    auto       mesh = assembly({mortise, block(P(1, 1), P(3.5, 2), 5, 2, 1)});
    const auto r    = ContactDetection::detect(mesh, {}, 1000);
    check(r.interfaces.size() == 3, "e) three interfaces of the tenon, got " + std::to_string(r.interfaces.size()));
    std::vector<double> lengths;
    for (const auto &i : r.interfaces)
      {
        lengths.push_back(i.length);
        check(i.master_body == 0, "e) the mortise (coarser) is the master");
      }
    std::sort(lengths.begin(), lengths.end());
    if (lengths.size() == 3)
      {
        check_near(lengths[0], 1, 1e-14, "e) end face length");
        check_near(lengths[1], 2, 1e-14, "e) face length");
        check_near(lengths[2], 2, 1e-14, "e) face length");
      }
  }

  void
  excluded()
  {
    auto mesh = assembly({block(P(0, 0), P(1, 1), 3, 3, 0), block(P(0, 1), P(1, 2), 4, 4, 1)});
    const auto r = ContactDetection::detect(mesh, {3}, 1000);
    check(r.interfaces.empty(), "f) an excluded id is never an interface");
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      if (mesh.edge(e).at_boundary())
        {
          mesh.set_edge_boundary_id(e, 1500);
          break;
        }
    check(ContactDetection::first_free_id(mesh) == 1501, "f) first free id above the largest id");
    testing::check_throws([&] { ContactDetection::detect(mesh, {}, 1000); }, "is in use",
                          "f) detect() refuses a first id below an id in use");
  }
} // namespace

int
main()
{
  stacked_blocks();
  running_bond();
  corner_and_gaps();
  mortise_and_tenon();
  excluded();
  return testing::finish();
}
