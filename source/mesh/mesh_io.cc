// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/base/number_string.h>
#include <dealvem/base/output_file.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/mesh_io.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

namespace dealvem
{
  namespace MeshIO
  {
    namespace
    {
      // Coordinates beyond this magnitude are refused: the geometric checks
      // multiply differences of coordinates, which would overflow (the same
      // limit is enforced by PolygonalMesh::finalize()).
      constexpr double max_coordinate = 1e100;

      // The smallest number of bytes of text one entry of a list can take:
      // one character and one separator per number.
      constexpr std::uintmax_t bytes_per_number = 2;

      // Number of bytes from the current position of @p in to its end, or
      // the largest value when the stream cannot tell (a pipe).
      std::uintmax_t
      remaining_bytes(std::istream &in)
      {
        const auto unknown = std::numeric_limits<std::uintmax_t>::max();
        if (!in)
          return unknown;
        const std::streampos here = in.tellg();
        if (here == std::streampos(-1))
          {
            in.clear();
            return unknown;
          }
        in.seekg(0, std::ios::end);
        const std::streampos end = in.tellg();
        in.clear();
        in.seekg(here);
        if (end == std::streampos(-1) || end < here || !in)
          {
            in.clear();
            return unknown;
          }
        return static_cast<std::uintmax_t>(end - here);
      }

      // Reads the stream token by token, one line at a time, and knows the
      // line of every token. Nothing is stored beyond the current line, so
      // memory does not depend on the size of the file or on counts written
      // in it.
      class Tokens
      {
      public:
        Tokens(std::istream &in, const std::string &name, const std::uintmax_t size)
          : name(name)
          , size(size)
          , in(in)
        {
          // the first two lines (header and title) are free text
          if (std::getline(in, header))
            ++n_lines;
          std::string title;
          if (std::getline(in, title))
            ++n_lines;
          pos = current.size();
        }

        // true when only white space is left
        bool
        done()
        {
          return !fill();
        }

        // the line of the next token (the last line at the end of the file)
        std::size_t
        line()
        {
          fill();
          return n_lines;
        }

        // "file:line: " for the next token
        std::string
        where()
        {
          return at(line());
        }

        std::string
        at(const std::size_t l) const
        {
          return name + ":" + std::to_string(l) + ": ";
        }

        std::string
        next(const std::string &expected)
        {
          AssertThrow(fill(), ExcInvalidMesh(at(n_lines) + "unexpected end of file, expected " + expected + "."));
          const std::size_t begin = pos;
          while (pos < current.size() && !is_space(current[pos]))
            ++pos;
          last = current.substr(begin, pos - begin);
          return last;
        }

        void
        expect(const std::string &keyword)
        {
          const std::size_t l = line();
          const std::string t = next(keyword);
          AssertThrow(t == keyword,
                      ExcInvalidMesh(at(l) + "expected " + keyword + ", found '" + t + "'."));
        }

        // an integer that fits into a long long
        long long
        integer(const std::string &what)
        {
          const std::size_t l = line();
          const std::string t = next(what);
          long long         v = 0;
          const auto        r = std::from_chars(t.data(), t.data() + t.size(), v);
          AssertThrow(r.ec != std::errc::result_out_of_range,
                      ExcInvalidMesh(at(l) + "expected " + what + ", found '" + t +
                                     "', which is out of the range of integers."));
          AssertThrow(r.ec == std::errc() && r.ptr == t.data() + t.size(),
                      ExcInvalidMesh(at(l) + "expected " + what + " (an integer), found '" + t + "'."));
          return v;
        }

        // A count of entries that follow in the file, each taking at least
        // @p min_bytes bytes of text: it must be an integer of at least
        // @p min and the file must be large enough to hold that many entries.
        // Checked before anything is allocated for the entries.
        long long
        count(const std::string &what, const std::uintmax_t min_bytes, const long long min = 0)
        {
          const std::size_t l = line();
          const long long   n = integer(what);
          AssertThrow(n >= min, ExcInvalidMesh(at(l) + what + " must be " +
                                               (min == 0 ? std::string("non-negative") :
                                                           "at least " + std::to_string(min)) +
                                               ", found " + std::to_string(n) + "."));
          if (size != std::numeric_limits<std::uintmax_t>::max())
            {
              const std::uintmax_t capacity = size / min_bytes;
              AssertThrow(static_cast<std::uintmax_t>(n) <= capacity,
                          ExcInvalidMesh(at(l) + what + " is " + std::to_string(n) + ", but the file has only " +
                                         std::to_string(size) + " bytes, room for at most " +
                                         std::to_string(capacity) +
                                         "; the count is wrong or the file is truncated."));
            }
          return n;
        }

        double
        real(const std::string &what)
        {
          const std::size_t l = line();
          const std::string t = next(what);
          char             *end = nullptr;
          const double      v = std::strtod(t.c_str(), &end);
          const bool number   = !t.empty() && end == t.c_str() + t.size();
          AssertThrow(number && std::isfinite(v),
                      ExcInvalidMesh(at(l) + "expected " + what + " (a finite number), found '" + t + "'."));
          return v;
        }

        // a real number of magnitude up to max_coordinate
        double
        coordinate(const std::string &what)
        {
          const std::size_t l = line();
          const double      v = real(what);
          AssertThrow(std::abs(v) <= max_coordinate,
                      ExcInvalidMesh(at(l) + what + " is " + dealvem::internal::number_string(v) + "; coordinates larger than " +
                                     dealvem::internal::number_string(max_coordinate) + " in magnitude are not supported."));
          return v;
        }

        std::string    name;
        std::string    header;
        std::string    last; // the token last read
        std::uintmax_t size;
        std::size_t    n_lines = 0;

      private:
        static bool
        is_space(const char c)
        {
          return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
        }

        // move to the next token; false at the end of the file
        bool
        fill()
        {
          while (true)
            {
              while (pos < current.size() && is_space(current[pos]))
                ++pos;
              if (pos < current.size())
                return true;
              if (!std::getline(in, current))
                {
                  current.clear();
                  pos = 0;
                  return false;
                }
              ++n_lines;
              pos = 0;
            }
        }

        std::istream &in;
        std::string   current;
        std::size_t   pos = 0;
      };



      // read_vtk(), step 1: the header line, ASCII and DATASET
      // UNSTRUCTURED_GRID.
      void
      read_vtk_header(Tokens &t, const std::string &name)
      {
        AssertThrow(t.n_lines >= 1 && t.header.find("# vtk DataFile") == 0,
                    ExcInvalidMesh(name + ":1: not a legacy VTK file (the first line must start with "
                                          "'# vtk DataFile')."));
        AssertThrow(t.n_lines >= 2 && !t.done(), ExcInvalidMesh(name + ": the file is truncated after its header."));
        {
          const std::size_t l   = t.line();
          const std::string fmt = t.next("ASCII");
          AssertThrow(fmt == "ASCII", ExcInvalidMesh(t.at(l) + "only ASCII VTK files are supported, found '" +
                                                     fmt + "'."));
        }
        t.expect("DATASET");
        {
          const std::size_t l  = t.line();
          const std::string ds = t.next("UNSTRUCTURED_GRID");
          AssertThrow(ds == "UNSTRUCTURED_GRID",
                      ExcInvalidMesh(t.at(l) + "expected DATASET UNSTRUCTURED_GRID, found '" + ds + "'."));
        }
      }



      // read_vtk(), step 2: the POINTS (three numbers each) as the vertices
      // of @p mesh, which is cleared first; returns their number.
      template <int dim>
      long long
      read_vtk_points(Tokens &t, PolygonalMesh<dim> &mesh, const std::string &name)
      {
        t.expect("POINTS");
        const std::size_t points_line = t.line();
        const long long n_points = t.count("the number of points", 3 * bytes_per_number, 1);
        t.next("the point data type");
        mesh.clear();
        mesh.name = name;
        for (long long i = 0; i < n_points; ++i)
          {
            const double x = t.coordinate("x of point " + std::to_string(i));
            const double y = t.coordinate("y of point " + std::to_string(i));
            t.coordinate("z of point " + std::to_string(i));
            mesh.add_vertex(dealii::Point<dim>(x, y));
          }
        // a mesh far below the scale of double precision: the areas below
        // (products of coordinates) underflow and every cell would look
        // degenerate; say what is wrong instead
        if (n_points > 0)
          {
            dealii::Point<dim> lo = mesh.vertex(0), hi = mesh.vertex(0);
            for (const auto &p : mesh.get_vertices())
              for (unsigned int d = 0; d < 2; ++d)
                {
                  lo[d] = std::min(lo[d], p[d]);
                  hi[d] = std::max(hi[d], p[d]);
                }
            const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
            if (extent > 0 && extent < 1e-100)
              {
                std::ostringstream msg;
                msg << t.at(points_line) << "the points span only " << extent
                    << "; meshes smaller than 1e-100 are not supported, because areas and geometric "
                       "tolerances (products of coordinate differences) underflow. Give the coordinates in "
                       "a length unit nearer to the size of the mesh.";
                AssertThrow(false, ExcInvalidMesh(msg.str()));
              }
          }
        return n_points;
      }



      // The cells of a VTK file as read: points, type and ids of each, and
      // the lines of the file for the messages.
      struct VtkCells
      {
        long long                              n_cells    = 0;
        std::size_t                            cells_line = 0; // the line of CELLS
        std::vector<std::vector<unsigned int>> conn;           // the point indices of each cell
        std::vector<std::size_t>               cell_line;      // the line of each cell
        std::vector<int>                       types;          // the VTK type of each cell
        long long                              n_line_cells = 0;
        std::vector<int>                       material, boundary; // ids from CELL_DATA
      };



      // read_vtk(), step 3: CELLS, a count and at least one point index
      // each.
      void
      read_vtk_cells(Tokens &t, const long long n_points, const bool size_known, VtkCells &cells)
      {
        t.expect("CELLS");
        cells.cells_line          = t.line();
        const std::size_t cells_line = cells.cells_line;
        const long long   n_cells    = t.count("the number of cells", 2 * bytes_per_number, 1);
        const long long   list_size  = t.count("the size of the cell list", bytes_per_number, 2 * n_cells);
        cells.n_cells                = n_cells;
        // the counts are bounded by the size of the file: reserving is safe
        std::vector<std::vector<unsigned int>> &conn      = cells.conn;
        std::vector<std::size_t>               &cell_line = cells.cell_line;
        if (size_known)
          {
            conn.reserve(n_cells);
            cell_line.reserve(n_cells);
          }
        long long n_numbers = 0;
        for (long long c = 0; c < n_cells; ++c)
          {
            cell_line.push_back(t.line());
            conn.emplace_back();
            const std::size_t l = t.line();
            const long long   n = t.integer("the point count of cell " + std::to_string(c));
            AssertThrow(n >= 1 && n < 100000,
                        ExcInvalidMesh(t.at(l) + "invalid point count " + std::to_string(n) + " of cell " +
                                       std::to_string(c) + " (expected 1 to 99999)."));
            n_numbers += n + 1;
            AssertThrow(n_numbers <= list_size,
                        ExcInvalidMesh(t.at(l) + "cell " + std::to_string(c) + " goes beyond the size " +
                                       std::to_string(list_size) + " of the cell list given on line " +
                                       std::to_string(cells_line) + "."));
            for (long long k = 0; k < n; ++k)
              {
                const std::size_t lv = t.line();
                const long long   v  = t.integer("a point index of cell " + std::to_string(c));
                AssertThrow(v >= 0 && v < n_points,
                            ExcInvalidMesh(t.at(lv) + "cell " + std::to_string(c) + " refers to point " +
                                           std::to_string(v) + ", but the points are numbered 0 to " +
                                           std::to_string(n_points - 1) + "."));
                conn[c].push_back(v);
              }
          }
        AssertThrow(n_numbers == list_size,
                    ExcInvalidMesh(t.at(cells_line) + "the size of the cell list is given as " +
                                   std::to_string(list_size) + ", but the " + std::to_string(n_cells) +
                                   " cells hold " + std::to_string(n_numbers) + " numbers."));
      }



      // read_vtk(), step 4: CELL_TYPES, one of line, triangle, polygon or
      // quad for each cell, with as many points as the type has.
      void
      read_vtk_cell_types(Tokens &t, VtkCells &cells)
      {
        const long long n_cells = cells.n_cells;
        t.expect("CELL_TYPES");
        {
          const std::size_t l       = t.line();
          const long long   n_types = t.count("the number of cell types", bytes_per_number);
          AssertThrow(n_types == n_cells, ExcInvalidMesh(t.at(l) + "CELL_TYPES gives " + std::to_string(n_types) +
                                                         " types for " + std::to_string(n_cells) + " cells."));
        }
        cells.types.assign(n_cells, 0);
        for (long long c = 0; c < n_cells; ++c)
          {
            const std::size_t l    = t.line();
            const long long   type = t.integer("the type of cell " + std::to_string(c));
            AssertThrow(type == 3 || type == 5 || type == 7 || type == 9,
                        ExcInvalidMesh(t.at(l) + "cell " + std::to_string(c) + " has the unsupported VTK cell type " +
                                       std::to_string(type) + " (supported: 3 line, 5 triangle, 7 polygon, 9 quad)."));
            cells.types[c]          = type;
            const std::size_t n     = cells.conn[c].size();
            const std::size_t n_req = (type == 3 ? 2 : type == 5 ? 3 : type == 9 ? 4 : 0);
            AssertThrow(n_req == 0 || n == n_req,
                        ExcInvalidMesh(t.at(cells.cell_line[c]) + "cell " + std::to_string(c) + " of VTK type " +
                                       std::to_string(type) + " must have " + std::to_string(n_req) +
                                       " points, found " + std::to_string(n) + "."));
            AssertThrow(type != 7 || n >= 3,
                        ExcInvalidMesh(t.at(cells.cell_line[c]) + "polygon cell " + std::to_string(c) + " has " +
                                       std::to_string(n) + " points; a polygon needs at least 3."));
            cells.n_line_cells += (type == 3);
          }
        AssertThrow(cells.n_line_cells < n_cells,
                    ExcInvalidMesh(t.at(cells.cells_line) + "the file has no polygon cells, only lines."));
      }



      // read_vtk(), step 5b: one SCALARS field of CELL_DATA (the keyword
      // SCALARS read on line @p l); material_id goes to the polygons,
      // boundary_id to the lines, other fields are read and dropped.
      void
      read_vtk_scalars(Tokens &t, const std::size_t l, std::set<std::string> &fields, VtkCells &cells)
      {
        const long long   n_cells = cells.n_cells;
        const std::string field   = t.next("a field name");
        AssertThrow(fields.insert(field).second,
                    ExcInvalidMesh(t.at(l) + "the field '" + field + "' is given twice."));
        t.next("a data type");
        // an optional number of components (must be 1), then LOOKUP_TABLE
        {
          const std::size_t lw = t.line();
          std::string       w  = t.next("LOOKUP_TABLE");
          if (w != "LOOKUP_TABLE")
            {
              AssertThrow(w == "1", ExcInvalidMesh(t.at(lw) + "the field '" + field +
                                                   "' must have 1 component, found '" + w + "'."));
              w = t.next("LOOKUP_TABLE");
            }
          AssertThrow(w == "LOOKUP_TABLE", ExcInvalidMesh(t.at(lw) + "expected LOOKUP_TABLE, found '" + w + "'."));
        }
        t.next("a lookup table name");
        const bool is_material = (field == "material_id"), is_boundary = (field == "boundary_id");
        for (long long c = 0; c < n_cells; ++c)
          {
            const std::size_t lv = t.line();
            const double      v  = t.real("value " + std::to_string(c) + " of field " + field + " (" +
                                          std::to_string(n_cells) + " values, one per cell)");
            // ids count where they are used: material ids on polygons,
            // boundary ids on lines
            const bool used = (is_material && cells.types[c] != 3) || (is_boundary && cells.types[c] == 3);
            if (used)
              {
                const double max = is_material ? PolygonalMeshGenerators::max_material_id : 254;
                AssertThrow(v == std::floor(v) && v >= 0 && v <= max,
                            ExcInvalidMesh(t.at(lv) + field + " of cell " + std::to_string(c) + " is '" + t.last +
                                           "'; " + (is_material ? "material" : "boundary") +
                                           " ids must be integers from 0 to " + std::to_string(int(max)) + "."));
                (is_material ? cells.material : cells.boundary)[c] = int(v);
              }
          }
      }



      // read_vtk(), step 5: the rest of the file, CELL_DATA with SCALARS
      // material_id (polygons) and boundary_id (lines).
      void
      read_vtk_cell_data(Tokens &t, VtkCells &cells)
      {
        const long long n_cells = cells.n_cells;
        cells.material.assign(n_cells, 0);
        cells.boundary.assign(n_cells, 0);
        std::set<std::string> fields;
        std::size_t           cell_data_line = 0;
        while (!t.done())
          {
            const std::size_t l  = t.line();
            const std::string kw = t.next("a data section");
            if (kw == "CELL_DATA")
              {
                AssertThrow(cell_data_line == 0,
                            ExcInvalidMesh(t.at(l) + "a second CELL_DATA section (the first is on line " +
                                           std::to_string(cell_data_line) + ")."));
                cell_data_line    = l;
                const long long n = t.count("the number of cell data values", bytes_per_number);
                AssertThrow(n == n_cells, ExcInvalidMesh(t.at(l) + "CELL_DATA " + std::to_string(n) +
                                                         " does not match the " + std::to_string(n_cells) +
                                                         " cells."));
              }
            else if (kw == "SCALARS")
              {
                AssertThrow(cell_data_line > 0,
                            ExcInvalidMesh(t.at(l) + "SCALARS before CELL_DATA (point data is not supported)."));
                read_vtk_scalars(t, l, fields, cells);
              }
            else
              AssertThrow(false, ExcInvalidMesh(t.at(l) + "unsupported section '" + kw +
                                                "' (supported after CELL_TYPES: CELL_DATA with SCALARS "
                                                "material_id and boundary_id)."));
          }
        AssertThrow(cell_data_line == 0 || !fields.empty(),
                    ExcInvalidMesh(t.at(cell_data_line) + "CELL_DATA is announced, but no SCALARS field "
                                   "follows; the file is truncated."));
        // Line cells exist only to carry boundary ids (write_vtk always writes
        // them with CELL_DATA material_id and boundary_id): without the ids
        // the file has lost its end.
        AssertThrow(cells.n_line_cells == 0 || fields.count("boundary_id") == 1,
                    ExcInvalidMesh(t.at(t.n_lines) + "the file has " + std::to_string(cells.n_line_cells) +
                                   " line cells (boundary edges), but no CELL_DATA field boundary_id for them; the "
                                   "file is truncated or incomplete."));
      }



      // read_vtk(), step 6: every line cell must be an edge of a polygon;
      // then the polygons (counter-clockwise, checked here where the line
      // of the file is known) and the boundary ids of the lines go into
      // @p mesh.
      template <int dim>
      void
      add_vtk_cells(Tokens &t, const VtkCells &cells, PolygonalMesh<dim> &mesh)
      {
        const long long n_cells = cells.n_cells;
        const auto     &conn    = cells.conn;
        const auto     &types   = cells.types;
        std::set<std::pair<unsigned int, unsigned int>> polygon_edges;
        for (long long c = 0; c < n_cells; ++c)
          if (types[c] != 3)
            for (std::size_t i = 0; i < conn[c].size(); ++i)
              {
                const unsigned int a = conn[c][i], b = conn[c][(i + 1) % conn[c].size()];
                polygon_edges.insert({std::min(a, b), std::max(a, b)});
              }
        for (long long c = 0; c < n_cells; ++c)
          if (types[c] == 3)
            AssertThrow(polygon_edges.count({std::min(conn[c][0], conn[c][1]), std::max(conn[c][0], conn[c][1])}) ==
                          1,
                        ExcInvalidMesh(t.at(cells.cell_line[c]) + "line cell " + std::to_string(c) + " from point " +
                                       std::to_string(conn[c][0]) + " to point " + std::to_string(conn[c][1]) +
                                       " is not an edge of any polygon."));

        for (long long c = 0; c < n_cells; ++c)
          if (types[c] != 3)
            {
              // reject clockwise polygons here, where the file line is known
              double            a = 0;
              const std::size_t n = conn[c].size();
              for (std::size_t i = 0; i < n; ++i)
                {
                  const auto &p = mesh.vertex(conn[c][i]), &q = mesh.vertex(conn[c][(i + 1) % n]);
                  a += p[0] * q[1] - q[0] * p[1];
                }
              AssertThrow(a > 0, ExcInvalidMesh(t.at(cells.cell_line[c]) + "cell " + std::to_string(c) +
                                                (a < 0 ? " is clockwise" : " has zero area") +
                                                "; polygons must be counter-clockwise."));
              mesh.add_cell(conn[c], dealii::types::material_id(cells.material[c]));
            }
        for (long long c = 0; c < n_cells; ++c)
          if (types[c] == 3)
            mesh.set_boundary_id(conn[c][0], conn[c][1], dealii::types::boundary_id(cells.boundary[c]));
      }
    } // namespace



    template <int dim>
    void
    read_vtk(PolygonalMesh<dim> &mesh, std::istream &in, const std::string &name)
    {
      const std::uintmax_t size = remaining_bytes(in);
      Tokens               t(in, name, size);
      const bool           size_known = size != std::numeric_limits<std::uintmax_t>::max();
      read_vtk_header(t, name);
      const long long n_points = read_vtk_points(t, mesh, name);
      VtkCells        cells;
      read_vtk_cells(t, n_points, size_known, cells);
      read_vtk_cell_types(t, cells);
      read_vtk_cell_data(t, cells);
      add_vtk_cells(t, cells, mesh);
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
      // written to a temporary file and renamed: never half-written
      OutputFile file(filename);
      write_vtk(mesh, file.stream());
      file.commit();
    }

    FileCounts
    count_entities(const std::string &filename, const std::string &format)
    {
      std::ifstream in(filename);
      AssertThrow(in, ExcInvalidMesh("Cannot open the mesh file '" + filename + "'."));
      std::error_code      ec;
      const std::uintmax_t size = std::filesystem::file_size(filename, ec);
      FileCounts           counts;
      const bool           vtk = (format == "vtk");
      // the keyword before a count, and the smallest number of bytes a
      // vertex takes in the file
      const std::string vertex_key = vtk ? "POINTS" : "$Nodes", cell_key = vtk ? "CELLS" : "$Elements";
      const std::uintmax_t min_vertex_bytes = vtk ? 3 * bytes_per_number : 8;
      int               version = 22;
      bool              binary  = false;
      std::string       text;
      std::size_t       line = 0;
      // the count that follows @p key on its line (VTK) or on the next
      // line (gmsh; format 4: the second number)
      const auto read_count = [&](const std::string &rest, unsigned long long &n) {
        std::string numbers = rest;
        if (!vtk && binary && version >= 40)
          {
            // binary 4.1: four 8-byte counts, the second the one wanted
            std::uint64_t v[4];
            if (!in.read(reinterpret_cast<char *>(v), sizeof(v)))
              return false;
            n = v[1];
            return true;
          }
        if (!vtk)
          {
            if (!std::getline(in, numbers))
              return false;
            ++line;
          }
        std::istringstream s(numbers);
        std::string        word;
        if (!vtk && version >= 40)
          s >> word;
        if (!(s >> word))
          return false;
        const auto r = std::from_chars(word.data(), word.data() + word.size(), n);
        return r.ec == std::errc() && r.ptr == word.data() + word.size();
      };
      bool after_format = false;
      while (std::getline(in, text))
        {
          ++line;
          // most lines are numbers: look at the first word only where it
          // can be a keyword
          const std::size_t b = text.find_first_not_of(" \t");
          if (b == std::string::npos || !(text[b] == '$' || text[b] == 'P' || text[b] == 'C' || after_format))
            continue;
          std::istringstream s(text);
          std::string        key;
          s >> key;
          if (!vtk && key == "$MeshFormat")
            after_format = true;
          else if (after_format)
            {
              version      = (key.compare(0, 1, "4") == 0) ? 40 : 22;
              after_format = false;
              std::string file_type;
              s >> file_type;
              if (file_type == "1")
                {
                  // binary: the endianness marker, the integer 1, and a
                  // newline; another marker: the reader will say why
                  std::int32_t marker = 0;
                  if (!in.read(reinterpret_cast<char *>(&marker), sizeof(marker)) || marker != 1)
                    return counts;
                  binary = true;
                }
            }
          else if (key == vertex_key && counts.line == 0)
            {
              counts.line = line;
              std::string rest;
              std::getline(s, rest);
              unsigned long long n = 0;
              const bool found = read_count(rest, n);
              counts.line      = line; // gmsh: the line after $Nodes
              if (!found || (size > 0 && !ec && n > size / min_vertex_bytes))
                return counts;
              counts.n_vertices = n;
              counts.valid      = true;
            }
          else if (key == cell_key && counts.valid)
            {
              std::string rest;
              std::getline(s, rest);
              unsigned long long n = 0;
              if (read_count(rest, n) && (ec || n <= size / 4))
                counts.n_cells = n;
              return counts;
            }
        }
      return counts;
    }



    template void read_vtk(PolygonalMesh<2> &, const std::string &);
    template void read_vtk(PolygonalMesh<2> &, std::istream &, const std::string &);
    template void write_vtk(const PolygonalMesh<2> &, const std::string &);
    template void write_vtk(const PolygonalMesh<2> &, std::ostream &);
  } // namespace MeshIO
} // namespace dealvem
