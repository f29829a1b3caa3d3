// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_postprocessing_vtu_output_h
#define dealvem_postprocessing_vtu_output_h

#include <deal.II/lac/vector.h>

#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace dealvem
{
  /**
   * Write the solution as a VTK XML unstructured grid (.vtu, ASCII) that
   * ParaView opens: the polygons (VTK_POLYGON cells) with
   * - point data: "displacement" (3 components, z = 0; the vertex DoFs),
   *   "stress" (xx, yy, xy; nodal averages) and "von_mises";
   * - cell data: "stress" (xx, yy, xy; cell values of the projection),
   *   "von_mises", "body_id" (material id) and "cell_id".
   * Use ParaView's "Warp By Vector" on "displacement" for the deformed
   * shape.
   */
  template <int dim>
  void
  write_vtu_file(const std::string            &filename,
                 const VEMDoFHandler<dim>     &dof_handler,
                 const dealii::Vector<double> &solution,
                 const StressRecovery<dim>    &stresses);

  /**
   * The same, with further scalar point data: each entry of
   * @p point_data is a field name and one value per mesh vertex (for
   * example the active set of a contact iteration, 1 at the vertices of
   * active pairs, as examples/step-6 writes it). Throws if a name is empty,
   * repeats, clashes with the fields above or holds a character XML
   * attributes cannot take, if a field has the wrong size, or if a value
   * is not finite.
   */
  template <int dim>
  void
  write_vtu_file(const std::string                                             &filename,
                 const VEMDoFHandler<dim>                                      &dof_handler,
                 const dealii::Vector<double>                                  &solution,
                 const StressRecovery<dim>                                     &stresses,
                 const std::vector<std::pair<std::string, std::vector<double>>> &point_data);

  /**
   * One piece of a parallel output: the cells @p cells (the locally owned
   * cells of MPI process @p subdomain), the vertices they use (renumbered
   * locally, in increasing global order) and the same fields as
   * write_vtu_file(), plus the cell data "subdomain". @p solution and
   * @p stresses need the values on these cells and their vertices only.
   * write_pvtu_record() writes the file that joins the pieces.
   */
  template <int dim>
  void
  write_vtu_piece(const std::string               &filename,
                  const VEMDoFHandler<dim>        &dof_handler,
                  const dealii::Vector<double>    &solution,
                  const StressRecovery<dim>       &stresses,
                  const std::vector<unsigned int> &cells,
                  const unsigned int               subdomain);

  /**
   * The .pvtu file that ParaView opens for the pieces @p pieces (file
   * names relative to the .pvtu's folder) written by write_vtu_piece().
   */
  void
  write_pvtu_record(const std::string &filename, const std::vector<std::string> &pieces);

  /**
   * The beginning of a VTU file of every polygon of @p mesh (VTK_POLYGON
   * cells on the mesh's vertices): the XML header, the piece, the points
   * and the cells, up to and including "</Cells>". The caller writes its
   * PointData and CellData (one value per vertex, per cell) and ends the
   * file with "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n". Used by the
   * writers of finite-strain states and of design densities.
   */
  void
  write_vtu_polygons(std::ostream &out, const PolygonalMesh<2> &mesh);
} // namespace dealvem

#endif
