// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Output: a linear displacement field interpolated on a Voronoi mesh has
// the constant stress C eps in every cell (StressRecovery, 1e-12 relative);
// its VTU file is read back by VTK (Debian's /usr/bin/python3 with
// python3-vtk9; the reader ParaView uses)
// with the right numbers of points, polygon cells and arrays (and a further
// point field under its name and range; one of the wrong size refused); the JSON
// summary nests keys and escapes strings as expected.
#include <dealvem/postprocessing/json_summary.h>
#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/postprocessing/vtu_output.h>
#include <dealvem/vem/virtual_element.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "../elasticity_common.h"
#include "../tests.h"

using namespace dealvem;

class Linear : public dealii::Function<2>
{
public:
  Linear()
    : dealii::Function<2>(2)
  {}
  double
  value(const dealii::Point<2> &p, const unsigned int c) const override
  {
    return c == 0 ? 1e-3 * p[0] + 2e-3 * p[1] : -5e-4 * p[0] + 3e-3 * p[1];
  }
};

int
main()
{
  PolygonalMesh<2> mesh;
  PolygonalMeshGenerators::voronoi(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(2, 1), 30, 10, 2);
  const ElasticMaterial                                       material(2000, 0.25);
  const std::map<dealii::types::material_id, ElasticMaterial> materials = {{0, material}};
  const Linear                                                u;
  // exact stress of the linear field
  dealii::SymmetricTensor<2, 2> eps;
  eps[0][0] = 1e-3;
  eps[1][1] = 3e-3;
  eps[0][1] = 0.5 * (2e-3 - 5e-4);
  const auto sigma = material.stress(eps);
  for (const unsigned int k : {1u, 2u})
    {
      VEMDoFHandler<2> dof_handler(mesh);
      dof_handler.distribute_dofs(k);
      dealii::Vector<double>                       x(dof_handler.n_dofs()), local;
      VirtualElement<2>                            element(k);
      std::vector<dealii::types::global_dof_index> indices;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          element.reinit(mesh.cell_vertices(c));
          element.interpolate(u, local);
          dof_handler.get_dof_indices(c, indices);
          for (unsigned int i = 0; i < indices.size(); ++i)
            x[indices[i]] = local[i];
        }
      const StressRecovery<2> s(dof_handler, materials, x);
      double                  err = 0;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        err = std::max(err, (s.cell_stress(c) - sigma).norm() / sigma.norm());
      testing::check_small(err, 1e-12, "k=" + std::to_string(k) + ": cell stresses of a linear field");

      const std::string file = "linear-k" + std::to_string(k) + ".vtu";
      write_vtu_file(file, dof_handler, x, s);
      const std::string cmd = "/usr/bin/python3 " + testing::source_dir() + "/tests/postprocessing/read_vtu.py " + file +
                              " > " + file + ".txt 2>&1";
      const int rc = std::system(cmd.c_str());
      testing::check(rc == 0, file + ": read back by VTK's XML reader");
      std::ifstream in(file + ".txt");
      std::string   line, text;
      while (std::getline(in, line))
        text += line + "\n";
      std::cout << text;
      testing::check(text.find("points " + std::to_string(mesh.n_vertices()) + "\n") != std::string::npos &&
                       text.find("polygon cells " + std::to_string(mesh.n_cells()) + "\n") != std::string::npos,
                     file + ": numbers of points and polygon cells");

      // a further point field (the x coordinate of each vertex, range [0, 2])
      // is read back under its name; one of the wrong size is refused
      std::vector<double> vertex_x(mesh.n_vertices());
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        vertex_x[v] = mesh.vertex(v)[0];
      const std::string extra_file = "extra-k" + std::to_string(k) + ".vtu";
      write_vtu_file(extra_file, dof_handler, x, s, {{"vertex_x", vertex_x}});
      const std::string extra_cmd = "/usr/bin/python3 " + testing::source_dir() +
                                    "/tests/postprocessing/read_vtu.py " + extra_file + " > " + extra_file +
                                    ".txt 2>&1";
      testing::check(std::system(extra_cmd.c_str()) == 0, extra_file + ": read back by VTK's XML reader");
      std::ifstream extra_in(extra_file + ".txt");
      std::string   extra_text;
      while (std::getline(extra_in, line))
        extra_text += line + "\n";
      testing::check(extra_text.find("extra point array vertex_x 1 0.0 2.0\n") != std::string::npos,
                     extra_file + ": the point field vertex_x with the range [0, 2] (" + extra_text + ")");
      vertex_x.pop_back();
      testing::check_throws([&] { write_vtu_file("short.vtu", dof_handler, x, s, {{"vertex_x", vertex_x}}); },
                            "the point field 'vertex_x' has " + std::to_string(mesh.n_vertices() - 1) +
                              " values for " + std::to_string(mesh.n_vertices()) + " mesh vertices",
                            "k=" + std::to_string(k) + ": a point field of the wrong size is refused");

      // a displacement that overflowed: the file is refused, naming the
      // field and the vertex, and nothing is written
      dealii::Vector<double> bad = x;
      bad[2 * 3 + 1]             = std::numeric_limits<double>::infinity();
      const StressRecovery<2> bad_stresses(dof_handler, materials, bad);
      const std::string       bad_file = "overflow-k" + std::to_string(k) + ".vtu";
      testing::check_throws([&] { write_vtu_file(bad_file, dof_handler, bad, bad_stresses); },
                            "Cannot write the VTU file '" + bad_file + "': the field 'displacement' is inf at vertex 3",
                            "k=" + std::to_string(k) + ": a VTU file with an infinite displacement is refused");
      testing::check(!std::ifstream(bad_file), "... and not written");
    }

  JsonSummary json;
  json.set("a.b", 1.5);
  json.set("a.c", "say \"hi\"");
  json.set("d", 2.0);
  const std::string expected = "{\n  \"a\": {\n    \"b\": 1.5,\n    \"c\": \"say \\\"hi\\\"\"\n  },\n  \"d\": 2\n}\n";
  testing::check(json.to_string() == expected, "JSON summary text:\n" + json.to_string());
  testing::check_throws([&] { json.set("contact.dissipated_energy", std::numeric_limits<double>::infinity()); },
                        "JSON summary: the value of 'contact.dissipated_energy' is inf",
                        "an infinite number is refused by the JSON summary, naming its key");
  testing::check_throws([&] { json.set("steps.1.force_x", std::nan("")); },
                        "JSON summary: the value of 'steps.1.force_x' is NaN", "... and so is NaN");
  // a map of numbers under a prefix (a StageTimer's stages): an earlier key
  // keeps its place with the new value, new keys follow in the map's order
  JsonSummary timings;
  timings.set("timings.solve", 9.0);
  timings.set("timings.", std::map<std::string, double>{{"solve", 0.25}, {"assembly", 0.5}});
  testing::check(timings.to_string() == "{\n  \"timings\": {\n    \"solve\": 0.25,\n    \"assembly\": 0.5\n  }\n}\n",
                 "JSON summary: a map under a prefix:\n" + timings.to_string());
  return testing::finish();
}
