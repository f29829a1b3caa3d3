// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_postprocessing_svg_plots_h
#define dealvem_postprocessing_svg_plots_h

#include <deal.II/base/tensor.h>

#include <dealvem/mesh/polygonal_mesh.h>

#include <string>
#include <utility>
#include <vector>

namespace dealvem
{
  /**
   * Pictures without ParaView: self-contained SVG files that any browser
   * (and GitHub's README view) shows.
   */
  namespace SVGPlots
  {
    /**
     * The polygons of @p mesh on their deformed positions
     * $x + s\,u(x)$ (@p displacement per vertex, @p scale s), filled by the
     * per-cell @p cell_values with a blue-white-red colour map and a colour
     * bar labelled @p value_name; vertices with @p marked[v] get a dot.
     */
    void
    write_mesh(const std::string                       &filename,
               const PolygonalMesh<2>                  &mesh,
               const std::vector<dealii::Tensor<1, 2>> &displacement,
               const double                             scale,
               const std::vector<double>               &cell_values,
               const std::string                       &value_name,
               const std::vector<bool>                 &marked,
               const std::string                       &title);

    /// A force drawn as an arrow: its point of application and its vector.
    struct Arrow
    {
      /// Where the force acts (the tail of the arrow).
      dealii::Point<2>     point;
      /// The force.
      dealii::Tensor<1, 2> force;
    };

    /**
     * An assembly: the polygons of @p mesh filled with one colour per body
     * (material id; neighbouring ids get different colours), the cells'
     * edges thin and grey, and @p arrows scaled so that the largest is a
     * tenth of the picture's width (a contact force at the centre of
     * pressure of each interface, say).
     */
    void
    write_assembly(const std::string        &filename,
                   const PolygonalMesh<2>   &mesh,
                   const std::vector<Arrow> &arrows,
                   const std::string        &title);

    /// One curve of a line plot.
    struct Series
    {
      /// The legend entry.
      std::string                             name;
      /// The points (x, y), in the order to join them.
      std::vector<std::pair<double, double>> points;
      /// Join the points by a line.
      bool                                    line = true;
      /// Radius of the point markers (0: none).
      double                                  marker_radius = 3;
    };

    /// A line plot with markers, axes with ticks, and a legend in the
    /// upper left corner; series are drawn in order (the last on top).
    void
    write_line_plot(const std::string         &filename,
                    const std::vector<Series> &series,
                    const std::string         &x_label,
                    const std::string         &y_label,
                    const std::string         &title);
  } // namespace SVGPlots
} // namespace dealvem

#endif
