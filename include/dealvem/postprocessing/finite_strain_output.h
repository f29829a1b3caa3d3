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

#include <array>
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
   * What the finite-strain output shows at one material point (or averaged
   * over a cell or around a vertex, see FiniteStrainFields): the state of a
   * law at an in-plane deformation gradient $F$.
   */
  struct FiniteStrainPointState
  {
    /// The in-plane Cauchy stress $\sigma_{xx}, \sigma_{yy}, \sigma_{xy}$
    /// (finite_strain_cauchy_stress()).
    std::array<double, 3> cauchy_stress = {{0., 0., 0.}};
    /// The out-of-plane Cauchy stress $\sigma_{zz}$: the law's in plane
    /// strain (HyperelasticMaterial::cauchy_stress_zz(); for Neo-Hooke
    /// $\lambda\ln J/J$), zero in plane stress and for a law that is not a
    /// HyperelasticMaterial.
    double cauchy_stress_zz = 0;
    /// The von Mises stress of $(\sigma_{xx}, \sigma_{yy}, \sigma_{zz},
    /// \sigma_{xy})$ (von_mises_stress(): $\sqrt{\frac12((\sigma_{xx}-
    /// \sigma_{yy})^2 + (\sigma_{yy}-\sigma_{zz})^2 + (\sigma_{zz}-
    /// \sigma_{xx})^2) + 3\sigma_{xy}^2}$).
    double von_mises = 0;
    /// The volume ratio $J$: $\det F$ in plane strain, $f\det F$ in plane
    /// stress.
    double det_F = 1;
    /// The principal stretches: the two eigenvalues $\lambda_1 \ge
    /// \lambda_2$ of the in-plane $U = \sqrt{F^TF}$, and the thickness
    /// stretch $\lambda_3 = f$ (1 in plane strain).
    std::array<double, 3> principal_stretches = {{1., 1., 1.}};
  };

  /**
   * The state of @p law at the in-plane deformation gradient @p F: Cauchy
   * stress (in-plane and $\sigma_{zz}$), its von Mises value, $J$ and the
   * principal stretches (FiniteStrainPointState). The stretches of $U$ are
   * $\lambda_{1,2}^2 = \frac12\mathrm{tr}\,C \pm
   * \sqrt{\frac14(C_{11}-C_{22})^2 + C_{12}^2}$ with $C = F^TF$.
   * Throws like finite_strain_cauchy_stress().
   */
  FiniteStrainPointState
  finite_strain_point_state(const ConstitutiveLaw<2> &law, const dealii::Tensor<2, 2> &F);

  /**
   * The finite-strain output fields of a state, per cell and per vertex of
   * the mesh (what write_finite_strain_vtu_file() writes):
   * - a cell's value of $\sigma$, $\sigma_{zz}$, $J$ and the principal
   *   stretches is the mean of the point values (finite_strain_point_state())
   *   over the cell's quadrature points, weighted by their reference
   *   weights ($F = I + \Pi^0_{k-1}\nabla u$ there, as
   *   FiniteStrainOperator takes it); its von Mises stress is that of the
   *   cell's mean stress;
   * - a vertex's value of $\sigma$, $\sigma_{zz}$, $J$ and the stretches is
   *   the mean of the values of the cells around it, weighted by their
   *   reference areas (a vertex belongs to one body: the bodies of a mesh
   *   do not share vertices); its von Mises stress is that of the vertex's
   *   mean stress.
   *
   * For $k = 1$, $F$ is constant on a cell and the cell values are the
   * point values. The vertex values are a smoothing for plots: at a
   * boundary they lag the boundary value by about half a cell's change.
   */
  struct FiniteStrainFields
  {
    /// Per cell.
    std::vector<FiniteStrainPointState> cells;
    /// Per mesh vertex.
    std::vector<FiniteStrainPointState> vertices;
    /// The largest Frobenius norm of a cell's in-plane Cauchy stress.
    double max_cell_cauchy_norm = 0;
  };

  /**
   * Compute the FiniteStrainFields of the displacement @p u (global vector
   * of @p dof_handler), with the law of each cell from @p laws (by
   * material id). Throws an ExcMessage naming the cell if a law has no
   * finite-strain response, if $\det F \le 0$ at a quadrature point, or if
   * a value is not finite.
   */
  template <int dim>
  FiniteStrainFields
  compute_finite_strain_fields(const VEMDoFHandler<dim>     &dof_handler,
                               const MaterialLibrary<dim>   &laws,
                               const dealii::Vector<double> &u);

  /**
   * Write a finite-strain state as a VTK XML unstructured grid (.vtu,
   * ASCII) for ParaView: the polygons (VTK_POLYGON cells) at their
   * reference positions with the fields of compute_finite_strain_fields(),
   * under the same names as point data (averaged to the vertices) and as
   * cell data:
   * - "cauchy_stress" (3 components: xx, yy, xy of the in-plane Cauchy
   *   stress $\sigma = J^{-1}PF^T$), "cauchy_stress_zz" (the out-of-plane
   *   $\sigma_{zz}$: the law's in plane strain, 0 in plane stress),
   *   "cauchy_von_mises" (the von Mises stress of these four components),
   *   "det_F" (the volume ratio $J$: $\det F$ in plane strain, $f\det F$
   *   in plane stress) and "principal_stretches" (3 components: the
   *   in-plane stretches $\lambda_1 \ge \lambda_2$ and the thickness
   *   stretch $f$, 1 in plane strain);
   * - point data also "displacement" (3 components, z = 0; the vertex
   *   DoFs of @p solution), so that "Warp By Vector" with factor 1 shows
   *   the deformed body;
   * - cell data also "body_id" (material id) and "cell_id".
   *
   * The file has no small-strain "stress" or "von_mises" fields: the
   * stress of a law's small-strain response (write_vtu_file()) is not the
   * stress at finite strain. $P(F)$ comes from the cell's law in @p laws
   * (ConstitutiveLaw::first_piola_kirchhoff_stress()).
   *
   * Throws as compute_finite_strain_fields(), or if a displacement is not
   * finite; the file is then not created (OutputFile).
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
