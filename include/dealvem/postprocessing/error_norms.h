// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_postprocessing_error_norms_h
#define dealvem_postprocessing_error_norms_h

#include <deal.II/base/convergence_table.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/material.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <map>
#include <string>
#include <vector>

namespace dealvem
{
  /**
   * Errors of a virtual element solution against an exact displacement
   * $u$, measured with the projection (the virtual functions themselves are
   * not known inside the cells):
   * - l2 $= (\sum_E \|u - \Pi u_h\|^2_{0,E})^{1/2}$,
   * - h1_seminorm $= (\sum_E |u - \Pi u_h|^2_{1,E})^{1/2}$,
   * - energy $= (\sum_E \int_E \varepsilon(u-\Pi u_h):C\varepsilon(u-\Pi u_h))^{1/2}$,
   *   with $C\varepsilon$ the stress of the cell's constitutive law
   *   (ConstitutiveLaw::stress(); the laws must be linear, so that this is a
   *   norm),
   * and the same norms of $u$ (for relative errors).
   */
  struct ErrorNorms
  {
    /// @var double l2
    /// $\|u - \Pi u_h\|_0$ over the measured cells (units of the
    /// displacement).
    /// @var double h1_seminorm
    /// $|u - \Pi u_h|_1$, the L2 norm of the gradient error.
    /// @var double energy
    /// The energy norm of $u - \Pi u_h$ (square root of twice the strain
    /// energy of the error).
    double l2 = 0, h1_seminorm = 0, energy = 0;
    /// @var double l2_exact
    /// $\|u\|_0$ over the measured cells, the scale of l2.
    /// @var double h1_exact
    /// $|u|_1$ over the measured cells, the scale of h1_seminorm.
    /// @var double energy_exact
    /// The energy norm of $u$ over the measured cells, the scale of energy.
    double l2_exact = 0, h1_exact = 0, energy_exact = 0;
  };

  /**
   * Compute the errors by a quadrature of degree 2k + 6 on every polygon.
   * @p exact has two components; its gradient() must be implemented (for
   * example dealii::AutoDerivativeFunction, or analytically). With
   * @p body set, only the cells of that material id (one body of a contact
   * problem) are measured. Throws if a measured cell's law is not linear.
   */
  template <int dim>
  ErrorNorms
  compute_errors(const VEMDoFHandler<dim>         &dof_handler,
                 const MaterialLibrary<dim>       &laws,
                 const dealii::Vector<double>     &solution,
                 const dealii::Function<dim>      &exact,
                 const dealii::types::material_id body = dealii::numbers::invalid_material_id);

  /// The same with one ElasticMaterial per material id.
  template <int dim>
  ErrorNorms
  compute_errors(const VEMDoFHandler<dim>                                    &dof_handler,
                 const std::map<dealii::types::material_id, ElasticMaterial> &materials,
                 const dealii::Vector<double>                                &solution,
                 const dealii::Function<dim>                                 &exact,
                 const dealii::types::material_id body = dealii::numbers::invalid_material_id);

  /**
   * The same over the cells @p cells only (for example the locally owned
   * cells of an MPI process; @p solution needs the entries of their DoFs).
   * The squares of the norms add over disjoint sets of cells:
   * sum_over_processes() combines the results of all processes into the
   * norms over the whole mesh.
   */
  template <int dim>
  ErrorNorms
  compute_errors(const VEMDoFHandler<dim>        &dof_handler,
                 const MaterialLibrary<dim>      &laws,
                 const dealii::Vector<double>    &solution,
                 const dealii::Function<dim>     &exact,
                 const std::vector<unsigned int> &cells);

  /// The same with one ElasticMaterial per material id.
  template <int dim>
  ErrorNorms
  compute_errors(const VEMDoFHandler<dim>                                    &dof_handler,
                 const std::map<dealii::types::material_id, ElasticMaterial> &materials,
                 const dealii::Vector<double>                                &solution,
                 const dealii::Function<dim>                                 &exact,
                 const std::vector<unsigned int>                             &cells);

  /**
   * Combine error norms computed on disjoint sets of cells by the
   * processes of @p comm (collective): each norm is the square root of the
   * sum of the squares. Every process gets the result.
   */
  ErrorNorms
  sum_over_processes(const ErrorNorms &local, const MPI_Comm comm);

  /**
   * Add the convergence rates of the column @p key of @p table, as
   * ConvergenceTable::evaluate_convergence_rates(key, "dofs",
   * reduction_rate_log2, 2) does (the column "<key>...red.rate.log2", "-" in the
   * first row, $2\log(e_{i-1}/e_i)/\log(N_i/N_{i-1})$ with two decimals),
   * from the errors @p errors and the numbers of DoFs @p n_dofs of the
   * rows, except where a rate is undefined: an error of zero or one that is
   * not finite, or no more DoFs than in the row before (two cycles that read
   * the same mesh). There the row reads "n/a" instead of inf or nan.
   */
  void
  add_convergence_rates(dealii::ConvergenceTable  &table,
                        const std::string         &key,
                        const std::vector<double> &errors,
                        const std::vector<double> &n_dofs);
} // namespace dealvem

#endif
