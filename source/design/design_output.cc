// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/design/design_output.h>
#include <dealvem/mesh/polygonal_mesh.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>

namespace dealvem
{
  namespace Design
  {
    namespace
    {
      void
      check_density_field(const PolygonalMesh<2> &mesh, const std::vector<double> &density, const std::string &file)
      {
        AssertThrow(density.size() == mesh.n_cells(),
                    dealii::ExcMessage(file + ": " + std::to_string(density.size()) + " densities for " +
                                       std::to_string(mesh.n_cells()) + " cells."));
        for (unsigned int c = 0; c < density.size(); ++c)
          AssertThrow(std::isfinite(density[c]) && density[c] >= -1e-12 && density[c] <= 1 + 1e-12,
                      dealii::ExcMessage(file + ": the density of cell " + std::to_string(c) +
                                         " is not in [0, 1]."));
      }
    } // namespace



    void
    write_density_svg(const std::string &filename, const PolygonalMesh<2> &mesh, const std::vector<double> &density,
                      const std::string &title)
    {
      check_density_field(mesh, density, filename);
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        {
          x0 = std::min(x0, mesh.vertex(v)[0]);
          x1 = std::max(x1, mesh.vertex(v)[0]);
          y0 = std::min(y0, mesh.vertex(v)[1]);
          y1 = std::max(y1, mesh.vertex(v)[1]);
        }
      // 800 pixels wide (or 500 high), 10 px margins, 30 px for the title
      const double scale  = std::min(800 / std::max(x1 - x0, 1e-300), 500 / std::max(y1 - y0, 1e-300));
      const double width  = (x1 - x0) * scale + 20;
      const double height = (y1 - y0) * scale + 50;
      std::ofstream out(filename);
      AssertThrow(out, dealii::ExcMessage("Cannot open '" + filename + "' for writing."));
      out << std::fixed << std::setprecision(2);
      out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
          << "\" viewBox=\"0 0 " << width << " " << height << "\">\n"
          << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
          << "<text x=\"10\" y=\"20\" font-family=\"sans-serif\" font-size=\"14\">" << title << "</text>\n";
      std::vector<dealii::Point<2>> p;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          const int grey = static_cast<int>(std::lround(255 * (1 - std::clamp(density[c], 0., 1.))));
          if (grey >= 255)
            continue; // void: the white background
          mesh.cell_vertices(c, p);
          out << "<polygon points=\"";
          for (const auto &q : p)
            out << 10 + (q[0] - x0) * scale << "," << 40 + (y1 - q[1]) * scale << " ";
          // a stroke of the same grey closes the hairline gaps between cells
          out << "\" fill=\"rgb(" << grey << "," << grey << "," << grey << ")\" stroke=\"rgb(" << grey << ","
              << grey << "," << grey << ")\" stroke-width=\"0.5\"/>\n";
        }
      out << "</svg>\n";
      AssertThrow(out, dealii::ExcMessage("Writing '" + filename + "' failed."));
    }



    void
    write_density_vtu(const std::string &filename, const PolygonalMesh<2> &mesh, const std::vector<double> &density,
                      const std::vector<std::pair<std::string, std::vector<double>>> &extra)
    {
      check_density_field(mesh, density, filename);
      for (const auto &f : extra)
        AssertThrow(f.second.size() == mesh.n_cells() && !f.first.empty() &&
                      f.first.find_first_of("\"<>&") == std::string::npos,
                    dealii::ExcMessage(filename + ": the cell field '" + f.first +
                                       "' needs a plain name and one value per cell."));
      std::ofstream out(filename);
      AssertThrow(out, dealii::ExcMessage("Cannot open '" + filename + "' for writing."));
      out << std::setprecision(12);
      out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
          << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << mesh.n_vertices() << "\" NumberOfCells=\""
          << mesh.n_cells() << "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        out << mesh.vertex(v)[0] << " " << mesh.vertex(v)[1] << " 0\n";
      out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          for (const unsigned int v : mesh.cell(c).vertices)
            out << v << " ";
          out << "\n";
        }
      out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
      std::size_t offset = 0;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          offset += mesh.cell(c).vertices.size();
          out << offset << "\n";
        }
      out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        out << "7\n"; // VTK_POLYGON
      out << "</DataArray>\n</Cells>\n<CellData Scalars=\"density\">\n"
          << "<DataArray type=\"Float64\" Name=\"density\" format=\"ascii\">\n";
      for (const double d : density)
        out << d << "\n";
      out << "</DataArray>\n";
      for (const auto &f : extra)
        {
          out << "<DataArray type=\"Float64\" Name=\"" << f.first << "\" format=\"ascii\">\n";
          for (const double d : f.second)
            out << d << "\n";
          out << "</DataArray>\n";
        }
      out << "<DataArray type=\"Int32\" Name=\"material_id\" format=\"ascii\">\n";
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        out << int(mesh.cell(c).material_id) << "\n";
      out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
      AssertThrow(out, dealii::ExcMessage("Writing '" + filename + "' failed."));
    }
  } // namespace Design
} // namespace dealvem
