// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/base/output_file.h>
#include <dealvem/postprocessing/svg_plots.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

namespace dealvem
{
  namespace SVGPlots
  {
    namespace
    {
      // blue (0) - white (0.5) - red (1)
      std::string
      colour(double t)
      {
        t = std::min(1., std::max(0., t));
        double r, g, b;
        if (t < 0.5)
          {
            const double s = t / 0.5;
            r              = 0.23 + s * (0.97 - 0.23);
            g              = 0.30 + s * (0.97 - 0.30);
            b              = 0.75 + s * (0.97 - 0.75);
          }
        else
          {
            const double s = (t - 0.5) / 0.5;
            r              = 0.97 + s * (0.71 - 0.97);
            g              = 0.97 + s * (0.02 - 0.97);
            b              = 0.97 + s * (0.15 - 0.97);
          }
        std::ostringstream o;
        o << "rgb(" << int(255 * r) << "," << int(255 * g) << "," << int(255 * b) << ")";
        return o.str();
      }

      std::string
      number(const double v)
      {
        std::ostringstream o;
        o << std::setprecision(4) << v;
        return o.str();
      }

      std::string
      escape(const std::string &s)
      {
        std::string r;
        for (const char c : s)
          {
            if (c == '<')
              r += "&lt;";
            else if (c == '>')
              r += "&gt;";
            else if (c == '&')
              r += "&amp;";
            else
              r += c;
          }
        return r;
      }
    } // namespace



    void
    write_mesh(const std::string                       &filename,
               const PolygonalMesh<2>                  &mesh,
               const std::vector<dealii::Tensor<1, 2>> &displacement,
               const double                             scale,
               const std::vector<double>               &cell_values,
               const std::string                       &value_name,
               const std::vector<bool>                 &marked,
               const std::string                       &title)
    {
      AssertThrow(displacement.size() == mesh.n_vertices() && cell_values.size() == mesh.n_cells(),
                  dealii::ExcMessage("SVGPlots::write_mesh: data sizes do not match the mesh."));
      std::vector<dealii::Point<2>> x(mesh.n_vertices());
      double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        {
          x[v] = mesh.vertex(v) + scale * displacement[v];
          xmin = std::min(xmin, x[v][0]);
          xmax = std::max(xmax, x[v][0]);
          ymin = std::min(ymin, x[v][1]);
          ymax = std::max(ymax, x[v][1]);
        }
      const double width = 640, margin = 40, bar = 90;
      const double s      = (width - 2 * margin) / std::max(xmax - xmin, 1e-300);
      const double height = std::min(2000., (ymax - ymin) * s + 2 * margin + 30);
      const double sy     = std::min(s, (height - 2 * margin - 30) / std::max(ymax - ymin, 1e-300));
      auto px = [&](const dealii::Point<2> &p) { return margin + (p[0] - xmin) * sy; };
      auto py = [&](const dealii::Point<2> &p) { return height - margin - (p[1] - ymin) * sy; };

      double vmin = 1e300, vmax = -1e300;
      for (const double v : cell_values)
        {
          vmin = std::min(vmin, v);
          vmax = std::max(vmax, v);
        }
      // symmetric colour range around the mean when the field is uniform
      if (vmax - vmin <= 1e-9 * std::max(std::abs(vmax), std::abs(vmin)))
        {
          const double c = 0.5 * (vmax + vmin), d = std::max(std::abs(c) * 0.01, 1e-300);
          vmin = c - d;
          vmax = c + d;
        }

      OutputFile    file(filename);
      std::ostream &out = file.stream();
      out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width + bar << "\" height=\""
          << height << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
      out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
      out << "<text x=\"" << margin << "\" y=\"20\">" << escape(title) << "</text>\n";
      out << std::setprecision(6);
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          out << "<polygon points=\"";
          for (const auto v : mesh.cell(c).vertices)
            out << px(x[v]) << "," << py(x[v]) << " ";
          out << "\" fill=\"" << colour((cell_values[c] - vmin) / (vmax - vmin))
              << "\" stroke=\"black\" stroke-width=\"0.5\"/>\n";
        }
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        if (v < marked.size() && marked[v])
          out << "<circle cx=\"" << px(x[v]) << "\" cy=\"" << py(x[v])
              << "\" r=\"2.5\" fill=\"black\"/>\n";
      // colour bar
      const double bx = width + 10, by0 = margin + 20, bh = height - 2 * margin - 40;
      for (unsigned int i = 0; i < 50; ++i)
        out << "<rect x=\"" << bx << "\" y=\"" << by0 + bh * (1 - (i + 1) / 50.) << "\" width=\"16\" height=\""
            << bh / 50. + 0.5 << "\" fill=\"" << colour((i + 0.5) / 50.) << "\"/>\n";
      out << "<text x=\"" << bx << "\" y=\"" << by0 - 8 << "\">" << escape(value_name) << "</text>\n";
      out << "<text x=\"" << bx + 20 << "\" y=\"" << by0 + 10 << "\">" << number(vmax) << "</text>\n";
      out << "<text x=\"" << bx + 20 << "\" y=\"" << by0 + bh << "\">" << number(vmin) << "</text>\n";
      out << "</svg>\n";
      file.commit();
    }



    void
    write_assembly(const std::string        &filename,
                   const PolygonalMesh<2>   &mesh,
                   const std::vector<Arrow> &arrows,
                   const std::string        &title)
    {
      AssertThrow(mesh.n_vertices() > 0, dealii::ExcMessage("SVGPlots::write_assembly: the mesh is empty."));
      double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        {
          xmin = std::min(xmin, mesh.vertex(v)[0]);
          xmax = std::max(xmax, mesh.vertex(v)[0]);
          ymin = std::min(ymin, mesh.vertex(v)[1]);
          ymax = std::max(ymax, mesh.vertex(v)[1]);
        }
      const double width = 800, margin = 40;
      const double extent = std::max(xmax - xmin, 1e-300);
      const double s      = (width - 2 * margin) / extent;
      const double height = std::min(2400., (ymax - ymin) * s + 2 * margin + 30);
      const double sy     = std::min(s, (height - 2 * margin - 30) / std::max(ymax - ymin, 1e-300));
      auto px = [&](const dealii::Point<2> &p) { return margin + (p[0] - xmin) * sy; };
      auto py = [&](const dealii::Point<2> &p) { return height - margin - (p[1] - ymin) * sy; };
      // eight light colours; consecutive ids (neighbours in most
      // assemblies) differ
      const char *palette[] = {"#aec7e8", "#ffbb78", "#98df8a", "#ff9896",
                               "#c5b0d5", "#c49c94", "#f7b6d2", "#dbdb8d"};
      double fmax = 0;
      for (const auto &a : arrows)
        fmax = std::max(fmax, a.force.norm());
      const double arrow_scale = (fmax > 0 ? 0.1 * (xmax - xmin) / fmax : 0.);

      OutputFile    file(filename);
      std::ostream &out = file.stream();
      out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
          << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
      out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
      out << "<text x=\"" << margin << "\" y=\"20\">" << escape(title) << "</text>\n";
      out << std::setprecision(6);
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          out << "<polygon points=\"";
          for (const auto v : mesh.cell(c).vertices)
            out << px(mesh.vertex(v)) << "," << py(mesh.vertex(v)) << " ";
          out << "\" fill=\"" << palette[mesh.cell(c).material_id % 8]
              << "\" stroke=\"#888\" stroke-width=\"0.3\"/>\n";
        }
      // body outlines: the boundary edges
      for (unsigned int e = 0; e < mesh.n_edges(); ++e)
        if (mesh.edge(e).at_boundary())
          {
            const auto &a = mesh.vertex(mesh.edge(e).vertices[0]), &b = mesh.vertex(mesh.edge(e).vertices[1]);
            out << "<line x1=\"" << px(a) << "\" y1=\"" << py(a) << "\" x2=\"" << px(b) << "\" y2=\"" << py(b)
                << "\" stroke=\"black\" stroke-width=\"0.8\"/>\n";
          }
      for (const auto &a : arrows)
        {
          const double L = a.force.norm() * arrow_scale * sy;
          if (!(L > 0.5))
            continue;
          const double x0 = px(a.point), y0 = py(a.point);
          // screen direction (y down)
          const double dx = a.force[0] / a.force.norm(), dy = -a.force[1] / a.force.norm();
          const double x1 = x0 + L * dx, y1 = y0 + L * dy, head = std::min(8., 0.4 * L);
          out << "<line x1=\"" << x0 << "\" y1=\"" << y0 << "\" x2=\"" << x1 << "\" y2=\"" << y1
              << "\" stroke=\"#d62728\" stroke-width=\"1.8\"/>\n";
          out << "<polygon points=\"" << x1 << "," << y1 << " " << x1 - head * dx - 0.5 * head * dy << ","
              << y1 - head * dy + 0.5 * head * dx << " " << x1 - head * dx + 0.5 * head * dy << ","
              << y1 - head * dy - 0.5 * head * dx << "\" fill=\"#d62728\"/>\n";
          out << "<circle cx=\"" << x0 << "\" cy=\"" << y0 << "\" r=\"2\" fill=\"#d62728\"/>\n";
        }
      out << "</svg>\n";
      file.commit();
    }



    void
    write_line_plot(const std::string         &filename,
                    const std::vector<Series> &series,
                    const std::string         &x_label,
                    const std::string         &y_label,
                    const std::string         &title)
    {
      double xmin = 1e300, xmax = -1e300, ymin = 0, ymax = -1e300;
      for (const auto &s : series)
        for (const auto &p : s.points)
          {
            xmin = std::min(xmin, p.first);
            xmax = std::max(xmax, p.first);
            ymin = std::min(ymin, p.second);
            ymax = std::max(ymax, p.second);
          }
      if (xmax <= xmin)
        {
          xmin -= 1;
          xmax += 1;
        }
      if (ymax <= ymin)
        ymax = ymin + 1;
      ymax += 0.1 * (ymax - ymin);
      const double W = 640, H = 400, L = 70, R = 20, T = 40, B = 50;
      auto px = [&](double x) { return L + (x - xmin) / (xmax - xmin) * (W - L - R); };
      auto py = [&](double y) { return H - B - (y - ymin) / (ymax - ymin) * (H - T - B); };
      const char *colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};

      OutputFile    file(filename);
      std::ostream &out = file.stream();
      out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
          << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
      out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
      out << "<text x=\"" << L << "\" y=\"20\">" << escape(title) << "</text>\n";
      out << "<rect x=\"" << L << "\" y=\"" << T << "\" width=\"" << W - L - R << "\" height=\""
          << H - T - B << "\" fill=\"none\" stroke=\"black\"/>\n";
      // tick values: round-off next to zero prints as 0
      const auto tick = [](const double v, const double range) { return std::abs(v) < 1e-9 * range ? 0. : v; };
      for (unsigned int i = 0; i <= 4; ++i)
        {
          const double xv = tick(xmin + i * (xmax - xmin) / 4, xmax - xmin),
                       yv = tick(ymin + i * (ymax - ymin) / 4, ymax - ymin);
          out << "<text x=\"" << px(xv) - 10 << "\" y=\"" << H - B + 16 << "\">" << number(xv)
              << "</text>\n";
          out << "<text x=\"" << 5 << "\" y=\"" << py(yv) + 4 << "\">" << number(yv) << "</text>\n";
          out << "<line x1=\"" << L << "\" x2=\"" << W - R << "\" y1=\"" << py(yv) << "\" y2=\""
              << py(yv) << "\" stroke=\"#ddd\"/>\n";
        }
      out << "<text x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 10 << "\" text-anchor=\"middle\">" << escape(x_label)
          << "</text>\n";
      out << "<text x=\"15\" y=\"" << T - 8 << "\">" << escape(y_label) << "</text>\n";
      for (unsigned int k = 0; k < series.size(); ++k)
        {
          const auto &s = series[k];
          const char *c = colours[k % 4];
          if (s.line)
            {
              out << "<polyline fill=\"none\" stroke=\"" << c << "\" stroke-width=\"1.5\" points=\"";
              for (const auto &p : s.points)
                out << px(p.first) << "," << py(p.second) << " ";
              out << "\"/>\n";
            }
          if (s.marker_radius > 0)
            for (const auto &p : s.points)
              out << "<circle cx=\"" << px(p.first) << "\" cy=\"" << py(p.second) << "\" r=\""
                  << s.marker_radius << "\" fill=\"" << c << "\"/>\n";
        }
      // legend: a white box in the corner of the plot area that hides the
      // fewest data points (upper left first, then upper right, lower
      // left, lower right)
      if (!series.empty())
        {
          std::size_t longest = 0;
          for (const auto &s : series)
            longest = std::max(longest, s.name.size());
          const double lw = 36 + 6.5 * longest, lh = 8 + 16 * series.size();
          double       lx = L + 8, ly = T + 8;
          unsigned int fewest = std::numeric_limits<unsigned int>::max();
          for (const auto &[cx, cy] :
               {std::pair<double, double>(L + 8, T + 8), std::pair<double, double>(W - R - 8 - lw, T + 8),
                std::pair<double, double>(L + 8, H - B - 8 - lh),
                std::pair<double, double>(W - R - 8 - lw, H - B - 8 - lh)})
            {
              unsigned int hidden = 0;
              for (const auto &s : series)
                for (const auto &p : s.points)
                  {
                    const double x = px(p.first), y = py(p.second), m = s.marker_radius + 2;
                    hidden += (x > cx - m && x < cx + lw + m && y > cy - m && y < cy + lh + m);
                  }
              if (hidden < fewest)
                fewest = hidden, lx = cx, ly = cy;
            }
          out << "<rect x=\"" << lx << "\" y=\"" << ly << "\" width=\"" << lw << "\" height=\"" << lh
              << "\" fill=\"white\" fill-opacity=\"0.9\" stroke=\"#999\"/>\n";
          for (unsigned int k = 0; k < series.size(); ++k)
            {
              const auto  &s = series[k];
              const char  *c = colours[k % 4];
              const double y = ly + 14 + 16 * k;
              if (s.line)
                out << "<line x1=\"" << lx + 6 << "\" x2=\"" << lx + 26 << "\" y1=\"" << y - 4 << "\" y2=\""
                    << y - 4 << "\" stroke=\"" << c << "\" stroke-width=\"1.5\"/>\n";
              if (s.marker_radius > 0)
                out << "<circle cx=\"" << lx + 16 << "\" cy=\"" << y - 4 << "\" r=\"" << s.marker_radius
                    << "\" fill=\"" << c << "\"/>\n";
              out << "<text x=\"" << lx + 32 << "\" y=\"" << y << "\" fill=\"black\">" << escape(s.name)
                  << "</text>\n";
            }
        }
      out << "</svg>\n";
      file.commit();
    }
  } // namespace SVGPlots
} // namespace dealvem
