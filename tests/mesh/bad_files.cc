// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Malformed mesh files: each one gives an error naming the file (and the
// line) instead of a crash, a hang, a huge allocation or silently wrong
// data. The bad files are small strings written to the working directory:
// - legacy VTK: absurd, negative and non-integer counts (rejected before
//   anything is allocated), a lost CELL_DATA section, indices out of range,
//   huge coordinates, ids out of range;
// - gmsh .msh (MeshIO::read_msh): a wrong version in the header, the
//   binary flag without an endianness marker, physical ids out of range, absurd node counts, truncated
//   sections, a node at 1e308, unknown node tags;
// - the bucket grid of the mesh validation with huge or flat extents;
// - the valid data files still read.
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/mesh_io.h>

#include <chrono>
#include <iostream>
#include <fstream>
#include <limits>

#include "../tests.h"

using namespace dealvem;
using P = dealii::Point<2>;

namespace
{
  void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  // run f, print the message of the exception it throws in full (from
  // deal.II's "Additional information" to the stack trace), rethrow
  template <typename F>
  void
  show_message(F &&f)
  {
    try
      {
        f();
      }
    catch (const std::exception &e)
      {
        const std::string m     = testing::collapse_white_space(e.what());
        const auto        begin = m.find("Additional information: ");
        const auto        from  = (begin == std::string::npos ? 0 : begin + 24);
        std::cout << "      message: " << m.substr(from, m.find(" Stacktrace:", from) - from) << std::endl;
        throw;
      }
  }

  void
  vtk_fails(const std::string &name, const std::string &text, const std::string &fragment, const std::string &what)
  {
    write(name, text);
    testing::check_throws([&] {
      show_message([&] {
        PolygonalMesh<2> m;
        MeshIO::read_vtk(m, name);
      });
    }, fragment, "VTK: " + what);
  }

  void
  gmsh_fails(const std::string &name, const std::string &text, const std::string &fragment, const std::string &what)
  {
    write(name, text);
    testing::check_throws([&] {
      show_message([&] {
        PolygonalMesh<2> m;
        PolygonalMeshGenerators::from_gridin_file(m, name);
      });
    }, fragment, "gmsh: " + what);
  }

  const std::string vtk_head = "# vtk DataFile Version 3.0\ntest\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  // a unit square and its four boundary edges (lines 5 to 19 after the head)
  const std::string vtk_points = "POINTS 4 double\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  const std::string vtk_cells  = "CELLS 5 17\n4 0 1 2 3\n2 0 1\n2 1 2\n2 2 3\n2 3 0\nCELL_TYPES 5\n7\n3\n3\n3\n3\n";
  const std::string vtk_data   = "CELL_DATA 5\nSCALARS material_id int 1\nLOOKUP_TABLE default\n2\n0\n0\n0\n0\n"
                               "SCALARS boundary_id int 1\nLOOKUP_TABLE default\n0\n1\n2\n3\n4\n";

  // two quadrangles on [0,2]x[0,1] in gmsh format 2.2 (as tests/mesh/data/rectangle.msh)
  const std::string msh_format   = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const std::string msh_nodes    = "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 2 0 0\n4 0 1 0\n5 1 1 0\n6 2 1 0\n$EndNodes\n";
  const std::string msh_elements = "$Elements\n3\n1 1 2 2 1 1 2\n2 3 2 7 1 1 2 5 4\n3 3 2 7 1 2 3 6 5\n$EndElements\n";
} // namespace

int
main()
{
  const auto start = std::chrono::steady_clock::now();

  // valid files still read
  {
    PolygonalMesh<2> m;
    MeshIO::read_vtk(m, testing::source_dir() + "/tests/mesh/data/two_cells.vtk");
    testing::check(m.n_cells() == 2 && m.get_boundary_ids() == std::vector<dealii::types::boundary_id>{0, 5, 6},
                   "two_cells.vtk still reads");
    PolygonalMeshGenerators::from_gridin_file(m, testing::source_dir() + "/tests/mesh/data/rectangle.msh");
    testing::check(m.n_cells() == 2 && m.get_material_ids() == std::vector<dealii::types::material_id>{7},
                   "rectangle.msh still reads");
    write("square.vtk", vtk_head + vtk_points + vtk_cells + vtk_data);
    MeshIO::read_vtk(m, "square.vtk");
    testing::check(m.get_boundary_ids() == std::vector<dealii::types::boundary_id>{1, 2, 3, 4} &&
                     m.get_material_ids() == std::vector<dealii::types::material_id>{2},
                   "square.vtk (the base of the bad VTK files) reads");
    write("good.msh", msh_format + msh_nodes + msh_elements);
    PolygonalMeshGenerators::from_gridin_file(m, "good.msh");
    testing::check(m.n_cells() == 2 && m.get_boundary_ids() == std::vector<dealii::types::boundary_id>{0, 2},
                   "good.msh (the base of the bad gmsh files) reads");
    // a round trip through the writer still reads
    MeshIO::write_vtk(m, "round_trip.vtk");
    PolygonalMesh<2> r;
    MeshIO::read_vtk(r, "round_trip.vtk");
    testing::check(r.get_vertices() == m.get_vertices(), "write_vtk/read_vtk round trip");
  }

  // VTK: counts from the header are checked against the file size before
  // anything is allocated
  const std::string cells_tail = "4 0 1 2 3\nCELL_TYPES 1\n7\n";
  vtk_fails("cells_2e8.vtk", vtk_head + vtk_points + "CELLS 200000000 800000000\n" + cells_tail,
            "cells_2e8.vtk:10: the number of cells is 200000000, but the file has only", "2e8 cells");
  vtk_fails("cells_1e9.vtk", vtk_head + vtk_points + "CELLS 1000000000 5\n" + cells_tail,
            "cells_1e9.vtk:10: the number of cells is 1000000000, but the file has only", "1e9 cells");
  vtk_fails("cells_1e9_text.vtk", vtk_head + vtk_points + "CELLS 1e9 5\n" + cells_tail,
            "cells_1e9_text.vtk:10: expected the number of cells (an integer), found '1e9'", "cells '1e9'");
  vtk_fails("cells_minus_1.vtk", vtk_head + vtk_points + "CELLS -1 5\n" + cells_tail,
            "cells_minus_1.vtk:10: the number of cells must be at least 1, found -1", "-1 cells");
  vtk_fails("cells_overflow.vtk", vtk_head + vtk_points + "CELLS 99999999999999999999 5\n" + cells_tail,
            "cells_overflow.vtk:10: expected the number of cells, found '99999999999999999999', which is out of the "
            "range",
            "a cell count beyond the integers");
  vtk_fails("points_huge.vtk", vtk_head + "POINTS 123456789012 double\n0 0 0\n",
            "points_huge.vtk:5: the number of points is 123456789012, but the file has only", "1.2e11 points");
  vtk_fails("list_size.vtk", vtk_head + vtk_points + "CELLS 1 7\n" + cells_tail,
            "list_size.vtk:10: the size of the cell list is given as 7, but the 1 cells hold 5 numbers",
            "a wrong size of the cell list");
  // the CELL_DATA section lost: line cells without boundary ids
  vtk_fails("no_cell_data.vtk", vtk_head + vtk_points + vtk_cells,
            "no_cell_data.vtk:21: the file has 4 line cells (boundary edges), but no CELL_DATA field boundary_id",
            "CELL_DATA missing");
  vtk_fails("cut_cell_data.vtk", vtk_head + vtk_points + vtk_cells + "CELL_DATA 5\n",
            "cut_cell_data.vtk:22: CELL_DATA is announced, but no SCALARS field follows", "CELL_DATA cut off");
  vtk_fails("cut_values.vtk", vtk_head + vtk_points + vtk_cells + vtk_data.substr(0, vtk_data.size() - 4),
            "cut_values.vtk:34: unexpected end of file, expected value 3 of field boundary_id",
            "CELL_DATA values cut off");
  vtk_fails("no_boundary_id.vtk",
            vtk_head + vtk_points + vtk_cells + "CELL_DATA 5\nSCALARS material_id int 1\nLOOKUP_TABLE default\n2\n0\n0\n0\n0\n",
            "no_boundary_id.vtk:29: the file has 4 line cells (boundary edges), but no CELL_DATA field boundary_id",
            "the boundary_id field missing");
  // indices, coordinates and ids out of range
  vtk_fails("index.vtk", vtk_head + vtk_points + "CELLS 1 5\n4 0 1 2 4\nCELL_TYPES 1\n7\n",
            "index.vtk:11: cell 0 refers to point 4, but the points are numbered 0 to 3", "index out of range");
  vtk_fails("negative_index.vtk", vtk_head + vtk_points + "CELLS 1 5\n4 0 1 -2 3\nCELL_TYPES 1\n7\n",
            "negative_index.vtk:11: cell 0 refers to point -2", "negative index");
  vtk_fails("nan.vtk", vtk_head + "POINTS 3 double\n0 0 0\n1 nan 0\n0 1 0\n",
            "nan.vtk:7: expected y of point 1 (a finite number), found 'nan'", "NaN coordinate");
  vtk_fails("huge.vtk", vtk_head + "POINTS 3 double\n0 0 0\n1e308 0 0\n0 1 0\n",
            "huge.vtk:7: x of point 1 is 1e+308; coordinates larger than 1e+100", "coordinate 1e308");
  vtk_fails("material.vtk", vtk_head + vtk_points + vtk_cells +
                              "CELL_DATA 5\nSCALARS material_id int 1\nLOOKUP_TABLE default\n4294967295\n0\n0\n0\n0\n",
            "material.vtk:25: material_id of cell 0 is '4294967295'; material ids must be integers from 0 to 65535", "material id out of range");
  vtk_fails("not_an_edge.vtk",
            vtk_head + vtk_points + "CELLS 2 8\n4 0 1 2 3\n2 0 2\nCELL_TYPES 2\n7\n3\n" +
              "CELL_DATA 2\nSCALARS boundary_id int 1\nLOOKUP_TABLE default\n0\n1\n",
            "not_an_edge.vtk:12: line cell 1 from point 0 to point 2 is not an edge of any polygon",
            "a line cell that is no edge");

  // gmsh: the native reader's checks
  gmsh_fails("version.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n" + msh_nodes + msh_elements,
             "version.msh:5: expected 'numEntityBlocks numNodes minNodeTag maxNodeTag' after $Nodes, as format 4.1 "
             "in $MeshFormat says (4 numbers on the line), found '6'",
             "header 4.1 on 2.2 content");
  gmsh_fails("version3.msh", "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n" + msh_nodes + msh_elements,
             "version3.msh:2: unsupported gmsh format version '3.0'", "version 3.0");
  // binary files are read (tests/mesh/gmsh_reader.cc); an ASCII body under
  // the binary flag has no endianness marker
  gmsh_fails("binary.msh", "$MeshFormat\n2.2 1 8\n$EndMeshFormat\n" + msh_nodes + msh_elements,
             "binary.msh:3: expected the endianness marker of a binary file (the integer 1 in 4 bytes)",
             "binary flag without a marker");
  gmsh_fails("physical.msh",
             msh_format + msh_nodes + "$Elements\n2\n1 3 2 4294967295 1 1 2 5 4\n2 3 2 7 1 2 3 6 5\n$EndElements\n",
             "physical.msh:15: the physical tag of element 1 of 2 is '4294967295', but it becomes a material id, "
             "which must be an integer from 0 to 65535",
             "physical id 4294967295");
  gmsh_fails("physical255.msh",
             msh_format + msh_nodes + "$Elements\n2\n1 1 2 255 1 1 2\n2 3 2 7 1 1 2 5 4\n$EndElements\n",
             "physical255.msh:15: the physical tag of element 1 of 2 is '255'", "physical id 255");
  gmsh_fails("nodes_minus_6.msh", msh_format + "$Nodes\n-6\n1 0 0 0\n$EndNodes\n" + msh_elements,
             "nodes_minus_6.msh:5: expected the number of nodes (a non-negative integer), found '-6'", "-6 nodes");
  gmsh_fails("nodes_1e11.msh", msh_format + "$Nodes\n100000000000\n1 0 0 0\n$EndNodes\n" + msh_elements,
             "nodes_1e11.msh:5: the number of nodes is 100000000000, but the file has only", "1e11 nodes");
  gmsh_fails("nodes_1e11_text.msh", msh_format + "$Nodes\n1e11\n1 0 0 0\n$EndNodes\n" + msh_elements,
             "nodes_1e11_text.msh:5: expected the number of nodes (a non-negative integer), found '1e11'",
             "nodes '1e11'");
  gmsh_fails("too_few_nodes.msh", msh_format + "$Nodes\n7\n1 0 0 0\n2 1 0 0\n3 2 0 0\n4 0 1 0\n5 1 1 0\n6 2 1 0\n"
                                  "$EndNodes\n" + msh_elements,
             "too_few_nodes.msh:12: expected node 7 of 7 ('tag x y z'), found '$EndNodes'", "node count too large");
  gmsh_fails("truncated.msh", msh_format + msh_nodes + "$Elements\n3\n1 1 2 2 1 1 2\n2 3 2 7 1 1 2 5 4\n",
             "truncated.msh:16: unexpected end of file, expected element 3 of 3; the file is truncated",
             "elements cut off");
  gmsh_fails("no_end.msh", msh_format + msh_nodes + msh_elements.substr(0, msh_elements.size() - 13),
             "no_end.msh:17: unexpected end of file, expected $EndElements; the file is truncated",
             "$EndElements missing");
  gmsh_fails("node_1e308.msh", msh_format + "$Nodes\n6\n1 0 0 0\n2 1e308 0 0\n3 2 0 0\n4 0 1 0\n5 1 1 0\n6 2 1 0\n"
                                 "$EndNodes\n" + msh_elements,
             "node_1e308.msh:7: x of node 2 of 6 is 1e308; coordinates larger than 1e100", "a node at 1e308");
  gmsh_fails("node_inf.msh", msh_format + "$Nodes\n6\n1 0 0 0\n2 inf 0 0\n3 2 0 0\n4 0 1 0\n5 1 1 0\n6 2 1 0\n"
                               "$EndNodes\n" + msh_elements,
             "node_inf.msh:7: expected x of node 2 of 6 (a finite number), found 'inf'", "a node at inf");
  gmsh_fails("unknown_node.msh",
             msh_format + msh_nodes + "$Elements\n1\n1 3 2 7 1 1 2 5 9\n$EndElements\n",
             "unknown_node.msh:15: element 1 of 1 refers to node '9', which is not in $Nodes", "unknown node tag");
  gmsh_fails("no_physical_end.msh", msh_format + "$PhysicalNames\n1\n2 7 \"body\"\n" + msh_nodes + msh_elements,
             "no_physical_end.msh:7: expected $EndPhysicalNames, found '$Nodes'", "$EndPhysicalNames missing");
  gmsh_fails("tetra.msh", msh_format + msh_nodes + "$Elements\n1\n1 4 2 7 1 1 2 5 4\n$EndElements\n",
             "tetra.msh:15: element type 4 of element 1 of 1 is not supported in 2d", "a tetrahedron");
  // a gmsh 4.1 file with a wrong node block count
  const std::string msh41 = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 1 0\n1 0 0 0 2 1 0 1 7 0\n"
                            "$EndEntities\n$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                            "$EndNodes\n$Elements\n1 1 1 1\n2 1 3 1\n1 1 2 3 4\n$EndElements\n";
  write("good41.msh", msh41);
  {
    PolygonalMesh<2> m;
    PolygonalMeshGenerators::from_gridin_file(m, "good41.msh");
    testing::check(m.n_cells() == 1 && m.get_material_ids() == std::vector<dealii::types::material_id>{7},
                   "a valid gmsh 4.1 file reads");
  }
  std::string bad41 = msh41;
  bad41.replace(bad41.find("$Nodes\n1 4 1 4"), 14, "$Nodes\n9999999999 4 1 4");
  gmsh_fails("blocks41.msh", bad41,
             "blocks41.msh:9: the number of node blocks is 9999999999, but the file has only", "4.1 block count");
  std::string cut41 = msh41.substr(0, msh41.find("0 1 0\n$EndNodes"));
  gmsh_fails("cut41.msh", cut41, "cut41.msh:17: unexpected end of file, expected the coordinates of node 4 of 4",
             "4.1 nodes cut off");

  // the bucket grid of the validation: huge, flat and tiny extents
  {
    auto build = [](const std::vector<P> &v, const std::vector<std::vector<unsigned int>> &cells) {
      PolygonalMesh<2> m;
      m.name = "grid";
      for (const auto &p : v)
        m.add_vertex(p);
      for (const auto &c : cells)
        m.add_cell(c);
      m.finalize();
      return m;
    };
    testing::check_throws([&] { build({P(0, 0), P(1e308, 0), P(0, 1)}, {{0, 1, 2}}); },
                          "vertex 1 at (1e+308, 0) has a coordinate larger than 1e100", "mesh: a vertex at 1e308");
    testing::check_throws([&] { build({P(0, 0), P(-1e308, 0), P(1e308, 1), P(0, 1)}, {{0, 2, 3}, {0, 3, 1}}); },
                          "larger than 1e100", "mesh: vertices at -1e308 and 1e308");
    testing::check_throws([&] { build({P(0, 0), P(std::numeric_limits<double>::infinity(), 0), P(0, 1)}, {{0, 1, 2}}); },
                          "non-finite", "mesh: a vertex at infinity");
    // large but allowed: two triangles spanning 1e99, and a long thin strip
    for (const double s : {1e99, 1e-99})
      {
        const PolygonalMesh<2> m = build({P(-s, -s), P(s, -s), P(s, s), P(-s, s), P(0, 0)},
                                         {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
        testing::check(m.n_cells() == 4 && std::abs(m.total_area() - 4 * s * s) <= 1e-12 * 4 * s * s,
                       std::string("mesh: four triangles of size ") + (s > 1 ? "1e99" : "1e-99") + " are valid");
      }
    // a strip 1e93 long and 1e88 high: the bucket grid gets 2049 x 1 buckets
    std::vector<P>                         strip;
    std::vector<std::vector<unsigned int>> quads;
    for (unsigned int i = 0; i <= 1000; ++i)
      {
        strip.emplace_back(1e90 * i, 0);
        strip.emplace_back(1e90 * i, 1e88);
      }
    for (unsigned int i = 0; i < 1000; ++i)
      quads.push_back({2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
    const PolygonalMesh<2> m = build(strip, quads);
    testing::check(m.n_cells() == 1000 && m.n_edges() == 3001, "mesh: a strip 1e93 long and 1e88 high is valid");
    // a triangle inside quadrangle 500 of the strip is still found
    strip.emplace_back(500.2e90, 0.2e88);
    strip.emplace_back(500.8e90, 0.2e88);
    strip.emplace_back(500.5e90, 0.8e88);
    quads.push_back({2002, 2003, 2004});
    testing::check_throws([&] { build(strip, quads); }, "lies inside cell 500",
                          "mesh: a cell inside another in the long strip");
  }

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  testing::check(seconds < 5, "all bad files rejected in " + std::to_string(seconds) + " s");
  return testing::finish();
}
