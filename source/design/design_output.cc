// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/design/design_output.h>
#include <dealvem/base/output_file.h>
#include <dealvem/mesh/polygonal_mesh.h>
#include <dealvem/postprocessing/vtu_output.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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
      // at most 900 x 500 pixels of picture, 10 px margins, 28 px for the
      // title; coordinates as integers in tenths of a pixel
      const double scale  = std::min(900 / std::max(x1 - x0, 1e-300), 500 / std::max(y1 - y0, 1e-300));
      const double width  = (x1 - x0) * scale, height = (y1 - y0) * scale;
      // one path per grey level (64 levels), each cell a closed subpath:
      // a picture of thousands of cells stays small. Cells below 2 % are
      // left to the white background.
      constexpr unsigned int   n_levels = 64;
      std::vector<std::string> paths(n_levels + 1);
      std::vector<dealii::Point<2>> p;
      char                          number[48];
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          const double rho = std::clamp(density[c], 0., 1.);
          if (rho < 0.02)
            continue;
          std::string &path = paths[std::lround(rho * n_levels)];
          mesh.cell_vertices(c, p);
          for (unsigned int i = 0; i < p.size(); ++i)
            {
              std::snprintf(number, sizeof(number), "%s%ld %ld", i == 0 ? "M" : " ",
                            std::lround(10 * (p[i][0] - x0) * scale), std::lround(10 * (y1 - p[i][1]) * scale));
              path += number;
            }
          path += 'Z';
        }
      std::ofstream out(filename);
      AssertThrow(out, dealii::ExcMessage("Cannot open '" + filename + "' for writing."));
      out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << std::lround(width + 20) << "\" height=\""
          << std::lround(height + 38) << "\" viewBox=\"0 0 " << std::lround(width + 20) << " "
          << std::lround(height + 38) << "\">\n"
          << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
          << "<text x=\"10\" y=\"18\" font-family=\"sans-serif\" font-size=\"14\">" << title << "</text>\n"
          << "<rect x=\"10\" y=\"28\" width=\"" << std::lround(width) << "\" height=\"" << std::lround(height)
          << "\" fill=\"none\" stroke=\"#888\" stroke-width=\"0.5\"/>\n"
          // each cell stroked in its own grey hides the seams between cells
          << "<g transform=\"translate(10,28) scale(0.1)\" stroke-width=\"4\" stroke-linejoin=\"round\">\n";
      for (unsigned int l = 0; l <= n_levels; ++l)
        if (!paths[l].empty())
          {
            const int grey = static_cast<int>(std::lround(255 * (1 - double(l) / n_levels)));
            std::snprintf(number, sizeof(number), "#%02x%02x%02x", grey, grey, grey);
            out << "<path fill=\"" << number << "\" stroke=\"" << number << "\" d=\"" << paths[l] << "\"/>\n";
          }
      out << "</g>\n</svg>\n";
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
      OutputFile    file(filename);
      std::ostream &out = file.stream();
      out << std::setprecision(12);
      write_vtu_polygons(out, mesh);
      out << "<CellData Scalars=\"density\">\n"
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
      file.commit();
    }
  } // namespace Design
} // namespace dealvem
