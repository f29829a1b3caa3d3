// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_design_design_output_h
#define dealvem_design_design_output_h

#include <string>
#include <vector>

namespace dealvem
{
  template <int dim>
  class PolygonalMesh;

  namespace Design
  {
    /**
     * The densities of a design as a picture: every cell of @p mesh filled
     * with the grey of its density (black = 1, white = 0), as PolyTop and
     * Sigmund's 99-line code show designs; @p title above it. Throws if the
     * file cannot be written or a density is not in [0, 1].
     */
    void
    write_density_svg(const std::string &filename, const PolygonalMesh<2> &mesh, const std::vector<double> &density,
                      const std::string &title);

    /**
     * The densities as a VTU file of polygons (VTK_POLYGON) with the cell
     * field "density" and, when @p extra is not empty, further cell fields
     * (name, one value per cell), for ParaView (an iteration series:
     * "design-0001.vtu", ...).
     */
    void
    write_density_vtu(const std::string &filename, const PolygonalMesh<2> &mesh, const std::vector<double> &density,
                      const std::vector<std::pair<std::string, std::vector<double>>> &extra = {});
  } // namespace Design
} // namespace dealvem

#endif
