// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The native gmsh reader MeshIO::read_msh():
// - one geometry (tests/mesh/data/mixed_block.geo: triangles on the left
//   half, recombined quadrangles on the right half, named physical groups)
//   written by gmsh as MSH 2.2 and 4.1, ASCII and binary, gives one and the
//   same PolygonalMesh: vertices, polygons, boundary and material ids;
// - the second-order mesh of the same geometry, reduced to its corners, is
//   the first-order mesh;
// - the physical names, native refinement (4 children a cell, the ids
//   handed on to both halves of a boundary edge), separate material ids;
// - binary files cut short, with a foreign byte order or a clockwise cell
//   are refused with the file and line.
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/mesh_io.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "../tests.h"

using namespace dealvem;

namespace
{
  std::string
  data(const std::string &name)
  {
    return testing::source_dir() + "/tests/mesh/data/" + name;
  }

  std::string
  read(const std::string &file)
  {
    std::ifstream      in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  void
  write(const std::string &file, const std::string &text)
  {
    std::ofstream(file, std::ios::binary) << text;
  }

  // the largest difference of vertex coordinates, or -1 if the topology or
  // an id differs
  double
  difference(const PolygonalMesh<2> &a, const PolygonalMesh<2> &b)
  {
    if (a.n_vertices() != b.n_vertices() || a.n_cells() != b.n_cells() || a.n_edges() != b.n_edges())
      return -1;
    for (unsigned int c = 0; c < a.n_cells(); ++c)
      if (a.cell(c).vertices != b.cell(c).vertices || a.cell(c).material_id != b.cell(c).material_id)
        return -1;
    for (unsigned int e = 0; e < a.n_edges(); ++e)
      if (a.edge(e).vertices != b.edge(e).vertices || a.edge(e).boundary_id != b.edge(e).boundary_id)
        return -1;
    double d = 0;
    for (unsigned int v = 0; v < a.n_vertices(); ++v)
      d = std::max(d, a.vertex(v).distance(b.vertex(v)));
    return d;
  }

  void
  fails(const std::string &file, const std::string &fragment, const std::string &what)
  {
    testing::check_throws([&] {
      PolygonalMesh<2> m;
      try
        {
          MeshIO::read_msh(m, file);
        }
      catch (const std::exception &e)
        {
          const std::string s = testing::collapse_white_space(e.what());
          const auto        b = s.find("Invalid gmsh file");
          std::cout << "      message: " << s.substr(b == std::string::npos ? 0 : b, 200) << std::endl;
          throw;
        }
    }, fragment, what);
  }
} // namespace

int
main()
{
  // the four encodings of one mesh
  PolygonalMesh<2>          ref;
  const MeshIO::PhysicalNames names = MeshIO::read_msh(ref, data("mixed_block_msh22.msh"));
  unsigned int              n_triangles = 0, n_quads = 0;
  for (const auto &c : ref.get_cells())
    (c.vertices.size() == 3 ? n_triangles : n_quads) += 1;
  std::cout << "MSH 2.2 ASCII: " << ref.n_vertices() << " vertices, " << n_triangles << " triangles, " << n_quads
            << " quadrangles, area " << ref.total_area() << std::endl;
  testing::check(n_triangles > 0 && n_quads > 0 && n_triangles + n_quads == ref.n_cells(),
                 "the mixed mesh has triangles and quadrangles");
  testing::check(std::abs(ref.total_area() - 2) < 1e-13, "the cells cover the block [0,2]x[0,1]");
  testing::check(ref.get_material_ids() == std::vector<dealii::types::material_id>{1},
                 "the physical surface 'block' (tag 1) is material id 1");
  testing::check(ref.get_boundary_ids() == std::vector<dealii::types::boundary_id>{0, 3, 5, 7},
                 "boundary ids 3 (clamped), 5 (loaded), 7 (bottom), 0 (top, no physical curve)");
  // the right side x = 2 carries id 5, the left side id 3
  {
    bool ok = true;
    for (const auto &e : ref.get_edges())
      if (e.at_boundary())
        {
          const double x0 = ref.vertex(e.vertices[0])[0], x1 = ref.vertex(e.vertices[1])[0];
          const double y0 = ref.vertex(e.vertices[0])[1], y1 = ref.vertex(e.vertices[1])[1];
          const int    want = (x0 == 2 && x1 == 2) ? 5 : (x0 == 0 && x1 == 0) ? 3 : (y0 == 0 && y1 == 0) ? 7 : 0;
          ok = ok && int(e.boundary_id) == want;
        }
    testing::check(ok, "every boundary edge has the id of its side");
  }
  testing::check(names.boundary_ids == std::map<std::string, dealii::types::boundary_id>{{"bottom", 7},
                                                                                        {"clamped", 3},
                                                                                        {"loaded", 5}} &&
                   names.material_ids == std::map<std::string, dealii::types::material_id>{{"block", 1}},
                 "the physical names: " + names.list());
  for (const std::string f : {"mixed_block_msh22_bin.msh", "mixed_block_msh41.msh", "mixed_block_msh41_bin.msh"})
    {
      PolygonalMesh<2> m;
      const auto       n = MeshIO::read_msh(m, data(f));
      const double     d = difference(ref, m);
      std::cout << f << ": largest vertex difference " << d << std::endl;
      // ASCII files hold 16 significant digits: up to one unit in the last
      // place of the binary value
      testing::check(d >= 0 && d <= 1e-15 && n.list() == names.list(),
                     f + " gives the same mesh and names as the MSH 2.2 ASCII file");
    }
  {
    PolygonalMesh<2> a, b;
    MeshIO::read_msh(a, data("mixed_block_msh22_bin.msh"));
    MeshIO::read_msh(b, data("mixed_block_msh41_bin.msh"));
    testing::check(difference(a, b) == 0, "the two binary files give bit-identical meshes");
  }
  // second order, reduced to the corners
  {
    PolygonalMesh<2> m;
    MeshIO::read_msh(m, data("mixed_block_order2.msh"));
    const double d = difference(ref, m);
    std::cout << "second order: largest vertex difference " << d << std::endl;
    testing::check(d >= 0 && d <= 1e-15, "the second-order mesh (types 9 and 10, lines 8) by its corners");
  }
  // the parameter program's way in
  {
    PolygonalMesh<2> m;
    PolygonalMeshGenerators::from_gridin_file(m, data("mixed_block_msh41_bin.msh"));
    testing::check(difference(ref, m) >= 0, "from_gridin_file reads .msh natively");
  }
  // native refinement: four children a cell, both halves of a boundary
  // edge keep its id
  {
    PolygonalMesh<2> m;
    MeshIO::read_msh(m, data("mixed_block_msh41.msh"), 2);
    unsigned int n_boundary = 0, n_boundary_ref = 0, n_on_right = 0, n_right_ref = 0;
    for (const auto &e : m.get_edges())
      if (e.at_boundary())
        {
          ++n_boundary;
          n_on_right += (e.boundary_id == 5);
        }
    for (const auto &e : ref.get_edges())
      if (e.at_boundary())
        {
          ++n_boundary_ref;
          n_right_ref += (e.boundary_id == 5);
        }
    std::cout << "refined twice: " << m.n_cells() << " cells, " << n_boundary << " boundary edges, "
              << n_on_right << " with id 5" << std::endl;
    testing::check(m.n_cells() == 16 * ref.n_cells() && n_boundary == 4 * n_boundary_ref &&
                     n_on_right == 4 * n_right_ref && std::abs(m.total_area() - 2) < 1e-13 &&
                     m.get_boundary_ids() == ref.get_boundary_ids(),
                   "refined twice: 16 times the cells, 4 times the boundary edges, the same ids");
    std::size_t n_triangles_fine = 0;
    for (const auto &c : m.get_cells())
      n_triangles_fine += (c.vertices.size() == 3);
    testing::check(n_triangles_fine == 16 * n_triangles, "triangles give triangles, quadrangles quadrangles");
  }
  // two physical surfaces sharing an edge: refused, or separate parts
  {
    const std::string two = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 2 0 0\n"
                            "4 0 1 0\n5 1 1 0\n6 2 1 0\n$EndNodes\n$Elements\n3\n1 1 2 4 1 1 2\n"
                            "2 2 2 7 1 1 2 4\n3 3 2 8 1 2 3 6 5\n$EndElements\n";
    write("parts.msh", two);
    // a triangle (1 2 4) and a quadrangle (2 3 6 5): no shared edge; add
    // a triangle (2 5 4) of a third surface that shares an edge with both
    std::string shared = two;
    shared.replace(shared.find("$Elements\n3"), 11, "$Elements\n4");
    shared.replace(shared.find("$EndElements"), 0, "4 2 2 9 1 2 5 4\n");
    write("shared.msh", shared);
    fails("shared.msh", "shared.msh:18: triangle 2 (line 16) (physical surface 7) and triangle 4 (line 18) "
                        "(physical surface 9) share the edge from node 2 to node 4",
          "two bodies sharing an edge");
    PolygonalMesh<2> m;
    MeshIO::read_msh(m, "shared.msh", 0, true);
    testing::check(m.n_cells() == 3 && m.n_vertices() == 6 + 4 && m.get_material_ids().size() == 3 &&
                     m.get_boundary_ids() == std::vector<dealii::types::boundary_id>{0, 4},
                   "separate material ids: the nodes 2, 4, 5 of the shared edges are copied per part");
  }
  // a clockwise cell
  write("clockwise.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n"
                         "$Elements\n1\n5 2 2 1 1 1 3 2\n$EndElements\n");
  fails("clockwise.msh", "clockwise.msh:12: triangle 5 is clockwise (nodes 1 (0, 0), 3 (0, 1), 2 (1, 0))",
        "a clockwise triangle");
  // binary files cut short, with another byte order, or a corrupt count
  const std::string bin41 = read(data("mixed_block_msh41_bin.msh"));
  const std::string bin22 = read(data("mixed_block_msh22_bin.msh"));
  for (const auto &[name, text] : {std::make_pair("cut41.msh", bin41), std::make_pair("cut22.msh", bin22)})
    {
      const std::size_t at = text.find("$Elements") + 60;
      write(name, text.substr(0, at));
      fails(name, std::string(name) + ":", std::string("a binary file cut in $Elements: ") + name);
      testing::check_throws([&] {
        PolygonalMesh<2> m;
        MeshIO::read_msh(m, name);
      }, "unexpected end of file in the binary data", std::string("the cut is named: ") + name);
    }
  {
    std::string swapped = bin22;
    const std::size_t at = swapped.find("2.2 1 8\n") + 8;
    swapped.replace(at, 4, std::string("\0\0\0\1", 4));
    write("swapped.msh", swapped);
    fails("swapped.msh", "swapped.msh:3: the binary file was written with the other byte order",
          "a big-endian marker");
    swapped.replace(at, 4, std::string("\7\0\0\0", 4));
    write("marker7.msh", swapped);
    fails("marker7.msh", "marker7.msh:3: expected the endianness marker of a binary file (the integer 1 in 4 "
                         "bytes), found 7",
          "a corrupt marker");
    // the node count of the binary 4.1 file made huge: refused before
    // anything is allocated
    std::string huge = bin41;
    const std::size_t nodes = huge.find("$Nodes\n") + 7;
    const std::uint64_t n   = 1ull << 40;
    huge.replace(nodes + 8, 8, std::string(reinterpret_cast<const char *>(&n), 8));
    write("huge41.msh", huge);
    fails("huge41.msh", "the number of nodes is 1099511627776, but the file has only", "a binary node count 2^40");
  }
  // every prefix of the binary files, and every byte of them set to 0xff:
  // read or refused with a deal.II exception, never a crash, a
  // std::bad_alloc or another exception
  {
    unsigned int n_read = 0, n_refused = 0, n_other = 0;
    for (const std::string f : {"mixed_block_msh22_bin.msh", "mixed_block_msh41_bin.msh"})
      {
        const std::string text = read(data(f));
        const auto        try_read = [&](const std::string &bytes) {
          write("mutated.msh", bytes);
          try
            {
              PolygonalMesh<2> m;
              MeshIO::read_msh(m, "mutated.msh");
              ++n_read;
            }
          catch (const dealii::ExceptionBase &)
            {
              ++n_refused;
            }
          catch (...)
            {
              ++n_other;
            }
        };
        for (std::size_t n = 0; n < text.size(); ++n)
          try_read(text.substr(0, n));
        for (std::size_t i = 0; i < text.size(); ++i)
          {
            std::string t = text;
            t[i]          = char(0xff);
            try_read(t);
          }
      }
    std::cout << "mutated files: " << n_read << " read, " << n_refused << " refused, " << n_other
              << " other exceptions" << std::endl;
    testing::check(n_other == 0 && n_refused > 0, "cut and corrupted files are refused cleanly");
  }

  // count_entities reads the counts of binary files
  for (const std::string f : {"mixed_block_msh22_bin.msh", "mixed_block_msh41_bin.msh", "mixed_block_msh41.msh"})
    {
      const auto c = MeshIO::count_entities(data(f), "msh");
      std::cout << f << ": count_entities " << c.n_vertices << " nodes, " << c.n_cells << " elements" << std::endl;
      testing::check(c.valid && c.n_vertices >= ref.n_vertices() && c.n_cells >= ref.n_cells(),
                     "count_entities of " + f);
    }
  return testing::finish();
}
