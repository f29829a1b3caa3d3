// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_postprocessing_vtu_output_h
#define dealvem_postprocessing_vtu_output_h

#include <deal.II/lac/vector.h>

#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <string>

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
} // namespace dealvem

#endif
