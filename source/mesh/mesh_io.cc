// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/mesh/mesh_io.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace dealvem
{
  namespace MeshIO
  {
    namespace
    {
      // A token reader that knows the line of every token.
      class Tokens
      {
      public:
        Tokens(std::istream &in, const std::string &name)
          : name(name)
        {
          std::string  line;
          unsigned int n = 0;
          while (std::getline(in, line))
            {
              ++n;
              lines.push_back(line);
              if (n <= 2)
                continue; // header and title are free text
              std::istringstream s(line);
              std::string        t;
              while (s >> t)
                tokens.emplace_back(t, n);
            }
        }

        bool
        done() const
        {
          return pos >= tokens.size();
        }

        unsigned int
        line() const
        {
          return pos < tokens.size() ? tokens[pos].second : lines.size();
        }

        std::string
        where() const
        {
          return name + ":" + std::to_string(line()) + ": ";
        }

        std::string
        next(const std::string &expected)
        {
          AssertThrow(!done(), ExcInvalidMesh(name + ":" + std::to_string(lines.size()) +
                                              ": unexpected end of file, expected " + expected + "."));
          return tokens[pos++].first;
        }

        void
        expect(const std::string &keyword)
        {
          const unsigned int l = line();
          const std::string  t = next(keyword);
          AssertThrow(t == keyword, ExcInvalidMesh(name + ":" + std::to_string(l) + ": expected " +
                                                   keyword + ", found '" + t + "'."));
        }

        long long
        integer(const std::string &what)
        {
          const unsigned int l = line();
          const std::string  t = next(what);
          std::size_t        p = 0;
          long long          v = 0;
          bool               ok = true;
          try
            {
              v = std::stoll(t, &p);
            }
          catch (...)
            {
              ok = false;
            }
          AssertThrow(ok && p == t.size(), ExcInvalidMesh(name + ":" + std::to_string(l) + ": expected " + what +
                                                          " (an integer), found '" + t + "'."));
          return v;
        }

        double
        real(const std::string &what)
        {
          const unsigned int l = line();
          const std::string  t = next(what);
          std::size_t        p = 0;
          double             v = 0;
          bool               ok = true;
          try
            {
              v = std::stod(t, &p);
            }
          catch (...)
            {
              ok = false;
            }
          AssertThrow(ok && p == t.size() && std::isfinite(v),
                      ExcInvalidMesh(name + ":" + std::to_string(l) + ": expected " + what +
                                     " (a finite number), found '" + t + "'."));
          return v;
        }

        std::string              name;
        std::vector<std::string> lines;

      private:
        std::vector<std::pair<std::string, unsigned int>> tokens;
        std::size_t                                        pos = 0;
      };
    } // namespace



    template <int dim>
    void
    read_vtk(PolygonalMesh<dim> &mesh, std::istream &in, const std::string &name)
    {
      Tokens t(in, name);
      AssertThrow(!t.lines.empty() && t.lines[0].find("# vtk DataFile") == 0,
                  ExcInvalidMesh(name + ":1: not a legacy VTK file (the first line must start with "
                                        "'# vtk DataFile')."));
      AssertThrow(t.lines.size() >= 3, ExcInvalidMesh(name + ": the file is truncated after its header."));
      {
        const unsigned int l = t.line();
        const std::string  fmt = t.next("ASCII");
        AssertThrow(fmt == "ASCII", ExcInvalidMesh(name + ":" + std::to_string(l) + ": only ASCII VTK files "
                                                   "are supported, found '" + fmt + "'."));
      }
      t.expect("DATASET");
      {
        const unsigned int l  = t.line();
        const std::string  ds = t.next("UNSTRUCTURED_GRID");
        AssertThrow(ds == "UNSTRUCTURED_GRID",
                    ExcInvalidMesh(name + ":" + std::to_string(l) +
                                   ": expected DATASET UNSTRUCTURED_GRID, found '" + ds + "'."));
      }
      t.expect("POINTS");
      const long long n_points = t.integer("the number of points");
      AssertThrow(n_points > 0, ExcInvalidMesh(t.where() + "the number of points must be positive."));
      t.next("the point data type");
      mesh.clear();
      mesh.name = name;
      for (long long i = 0; i < n_points; ++i)
        {
          const double x = t.real("x of point " + std::to_string(i));
          const double y = t.real("y of point " + std::to_string(i));
          const double z = t.real("z of point " + std::to_string(i));
          (void)z;
          mesh.add_vertex(dealii::Point<dim>(x, y));
        }
      t.expect("CELLS");
      const long long n_cells = t.integer("the number of cells");
      t.integer("the size of the cell list");
      std::vector<std::vector<unsigned int>> conn(n_cells);
      std::vector<unsigned int>              cell_line(n_cells);
      for (long long c = 0; c < n_cells; ++c)
        {
          cell_line[c]     = t.line();
          const long long n = t.integer("the vertex count of cell " + std::to_string(c));
          AssertThrow(n >= 1 && n < 100000,
                      ExcInvalidMesh(t.where() + "invalid vertex count " + std::to_string(n) + " of cell " +
                                     std::to_string(c) + "."));
          for (long long k = 0; k < n; ++k)
            {
              const long long v = t.integer("a vertex index of cell " + std::to_string(c));
              AssertThrow(v >= 0 && v < n_points,
                          ExcInvalidMesh(name + ":" + std::to_string(cell_line[c]) + ": cell " + std::to_string(c) +
                                         " refers to point " + std::to_string(v) + ", but there are " +
                                         std::to_string(n_points) + " points."));
              conn[c].push_back(v);
            }
        }
      t.expect("CELL_TYPES");
      const long long n_types = t.integer("the number of cell types");
      AssertThrow(n_types == n_cells, ExcInvalidMesh(t.where() + "CELL_TYPES gives " + std::to_string(n_types) +
                                                     " types for " + std::to_string(n_cells) + " cells."));
      std::vector<int> types(n_cells);
      for (long long c = 0; c < n_cells; ++c)
        {
          const unsigned int l = t.line();
          types[c]             = t.integer("the type of cell " + std::to_string(c));
          AssertThrow(types[c] == 3 || types[c] == 5 || types[c] == 7 || types[c] == 9,
                      ExcInvalidMesh(name + ":" + std::to_string(l) + ": cell " + std::to_string(c) +
                                     " has the unsupported VTK cell type " + std::to_string(types[c]) +
                                     " (supported: 3 line, 5 triangle, 7 polygon, 9 quad)."));
          AssertThrow(types[c] != 3 || conn[c].size() == 2,
                      ExcInvalidMesh(name + ":" + std::to_string(cell_line[c]) + ": line cell " +
                                     std::to_string(c) + " must have 2 points."));
        }
      std::vector<long long> material(n_cells, 0), boundary(n_cells, 0);
      while (!t.done())
        {
          const unsigned int l  = t.line();
          const std::string  kw = t.next("a data section");
          if (kw == "CELL_DATA")
            {
              const long long n = t.integer("the number of cell data values");
              AssertThrow(n == n_cells, ExcInvalidMesh(name + ":" + std::to_string(l) + ": CELL_DATA " +
                                                       std::to_string(n) + " does not match " +
                                                       std::to_string(n_cells) + " cells."));
            }
          else if (kw == "SCALARS")
            {
              const std::string field = t.next("a field name");
              t.next("a data type");
              // optional number of components, then LOOKUP_TABLE
              std::string w = t.next("LOOKUP_TABLE");
              if (w != "LOOKUP_TABLE")
                w = t.next("LOOKUP_TABLE");
              AssertThrow(w == "LOOKUP_TABLE",
                          ExcInvalidMesh(t.where() + "expected LOOKUP_TABLE, found '" + w + "'."));
              t.next("a lookup table name");
              for (long long c = 0; c < n_cells; ++c)
                {
                  const double v = t.real("value " + std::to_string(c) + " of field " + field);
                  if (field == "material_id")
                    material[c] = std::llround(v);
                  else if (field == "boundary_id")
                    boundary[c] = std::llround(v);
                }
            }
          else
            AssertThrow(false, ExcInvalidMesh(name + ":" + std::to_string(l) + ": unsupported section '" + kw +
                                              "' (supported after CELL_TYPES: CELL_DATA with SCALARS "
                                              "material_id and boundary_id)."));
        }
      for (long long c = 0; c < n_cells; ++c)
        if (types[c] != 3)
          {
            // reject clockwise polygons here, where the file line is known
            double             a = 0;
            const unsigned int n = conn[c].size();
            for (unsigned int i = 0; i < n; ++i)
              {
                const auto &p = mesh.vertex(conn[c][i]), &q = mesh.vertex(conn[c][(i + 1) % n]);
                a += p[0] * q[1] - q[0] * p[1];
              }
            AssertThrow(n < 3 || a > 0,
                        ExcInvalidMesh(name + ":" + std::to_string(cell_line[c]) + ": cell " + std::to_string(c) +
                                       (a < 0 ? " is clockwise" : " has zero area") +
                                       "; polygons must be counter-clockwise."));
            AssertThrow(material[c] >= 0 && material[c] < 255,
                        ExcInvalidMesh(name + ": cell " + std::to_string(c) + " has an invalid material_id."));
            mesh.add_cell(conn[c], dealii::types::material_id(material[c]));
          }
      for (long long c = 0; c < n_cells; ++c)
        if (types[c] == 3)
          {
            AssertThrow(boundary[c] >= 0 && boundary[c] < 255,
                        ExcInvalidMesh(name + ": line cell " + std::to_string(c) + " has an invalid boundary_id."));
            mesh.set_boundary_id(conn[c][0], conn[c][1], dealii::types::boundary_id(boundary[c]));
          }
      mesh.finalize();
    }



    template <int dim>
    void
    read_vtk(PolygonalMesh<dim> &mesh, const std::string &filename)
    {
      std::ifstream in(filename);
      AssertThrow(in, ExcInvalidMesh("cannot open the mesh file '" + filename + "'."));
      read_vtk(mesh, in, filename);
    }



    template <int dim>
    void
    write_vtk(const PolygonalMesh<dim> &mesh, std::ostream &out)
    {
      unsigned int n_lines = 0, size = 0;
      for (const auto &e : mesh.get_edges())
        if (e.at_boundary())
          ++n_lines;
      for (const auto &c : mesh.get_cells())
        size += c.vertices.size() + 1;
      size += 3 * n_lines;
      out << "# vtk DataFile Version 3.0\n" << mesh.name << " (dealvem polygonal mesh)\nASCII\n"
          << "DATASET UNSTRUCTURED_GRID\nPOINTS " << mesh.n_vertices() << " double\n"
          << std::setprecision(17);
      for (const auto &v : mesh.get_vertices())
        out << v[0] << " " << v[1] << " 0\n";
      out << "CELLS " << mesh.n_cells() + n_lines << " " << size << "\n";
      for (const auto &c : mesh.get_cells())
        {
          out << c.vertices.size();
          for (const auto v : c.vertices)
            out << " " << v;
          out << "\n";
        }
      for (const auto &e : mesh.get_edges())
        if (e.at_boundary())
          out << "2 " << e.vertices[0] << " " << e.vertices[1] << "\n";
      out << "CELL_TYPES " << mesh.n_cells() + n_lines << "\n";
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        out << "7\n";
      for (unsigned int l = 0; l < n_lines; ++l)
        out << "3\n";
      out << "CELL_DATA " << mesh.n_cells() + n_lines << "\nSCALARS material_id int 1\nLOOKUP_TABLE default\n";
      for (const auto &c : mesh.get_cells())
        out << int(c.material_id) << "\n";
      for (unsigned int l = 0; l < n_lines; ++l)
        out << "0\n";
      out << "SCALARS boundary_id int 1\nLOOKUP_TABLE default\n";
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        out << "0\n";
      for (const auto &e : mesh.get_edges())
        if (e.at_boundary())
          out << int(e.boundary_id) << "\n";
    }



    template <int dim>
    void
    write_vtk(const PolygonalMesh<dim> &mesh, const std::string &filename)
    {
      std::ofstream out(filename);
      AssertThrow(out, dealii::ExcMessage("Cannot write the mesh file '" + filename + "'."));
      write_vtk(mesh, out);
    }

    template void read_vtk(PolygonalMesh<2> &, const std::string &);
    template void read_vtk(PolygonalMesh<2> &, std::istream &, const std::string &);
    template void write_vtk(const PolygonalMesh<2> &, const std::string &);
    template void write_vtk(const PolygonalMesh<2> &, std::ostream &);
  } // namespace MeshIO
} // namespace dealvem
