// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_postprocessing_finite_strain_output_h
#define dealvem_postprocessing_finite_strain_output_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/material_library.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace dealvem
{
  /**
   * The in-plane Cauchy stress $\sigma = J^{-1}PF^T$ of @p law at the
   * in-plane deformation gradient @p F, and in @p J the volume ratio: $J =
   * \det F$ in plane strain, $J = f\det F$ in plane stress with the
   * thickness stretch $f$ of the law (HyperelasticMaterial::
   * out_of_plane_stretch()), so that $\sigma$ is the in-plane block of the
   * 3D Cauchy stress in both models. Throws if @p law has no finite-strain
   * response or $\det F \le 0$.
   */
  dealii::Tensor<2, 2>
  finite_strain_cauchy_stress(const ConstitutiveLaw<2> &law, const dealii::Tensor<2, 2> &F, double &J);

  /**
   * Write a finite-strain state as a VTK XML unstructured grid (.vtu,
   * ASCII) for ParaView: the polygons (VTK_POLYGON cells) at their
   * reference positions with
   * - point data: "displacement" (3 components, z = 0; the vertex DoFs of
   *   @p solution), so that "Warp By Vector" with factor 1 shows the
   *   deformed body;
   * - cell data: "cauchy_stress" (xx, yy, xy of the in-plane Cauchy stress
   *   $\sigma = J^{-1}PF^T$, averaged over the cell's quadrature points with
   *   their reference weights; finite_strain_cauchy_stress()), "det_F"
   *   (the mean of $J$ over the cell: its area ratio in plane strain, its
   *   volume ratio $f\det F$ in plane stress), "body_id" (material id) and
   *   "cell_id".
   *
   * $F = I + \Pi^0_{k-1}\nabla u$ at the quadrature points of each cell
   * (VEMValues::get_function_gradient_projections()), and $P(F)$ from the
   * cell's law in @p laws (ConstitutiveLaw::first_piola_kirchhoff_stress()),
   * as FiniteStrainOperator computes them. This is the output for
   * FiniteStrainSolver: write_vtu_file() writes the stress of a law's
   * small-strain response, which is not the stress at finite strain.
   *
   * Throws an ExcMessage naming the cell if a law has no finite-strain
   * response, if $\det F \le 0$ at a quadrature point, or if a value
   * written would not be finite; the file is then not created (OutputFile).
   */
  template <int dim>
  void
  write_finite_strain_vtu_file(const std::string            &filename,
                               const VEMDoFHandler<dim>     &dof_handler,
                               const MaterialLibrary<dim>   &laws,
                               const dealii::Vector<double> &solution);

  /**
   * A ParaView collection file (.pvd) for a time series: one DataSet per
   * entry of @p times_and_files, (time, file name relative to the .pvd's
   * folder), in the given order; ParaView then shows the files as the time
   * steps of one data set (the load factor of a FiniteStrainSolver run,
   * say). Throws an ExcMessage if the list is empty, a time is not finite,
   * the times do not increase strictly, or a file name is empty or holds a
   * character that an XML attribute cannot take (quotes, '<', '>', '&').
   */
  void
  write_pvd_record(const std::string &filename, const std::vector<std::pair<double, std::string>> &times_and_files);
} // namespace dealvem

#endif
