// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------

#include <dealvem/postprocessing/error_norms.h>
#include <dealvem/vem/virtual_element.h>

#include <cmath>

namespace dealvem
{
  namespace
  {
    // the error integrals over the cells of @p cells (all if nullptr) of
    // material id @p body (any if invalid_material_id)
    template <int dim>
    ErrorNorms
    errors_on_cells(const VEMDoFHandler<dim>        &dof_handler,
                    const MaterialLibrary<dim>      &laws,
                    const dealii::Vector<double>    &solution,
                    const dealii::Function<dim>     &exact,
                    const dealii::types::material_id body,
                    const std::vector<unsigned int> *cells)
  {
    AssertThrow(exact.n_components == 2, dealii::ExcMessage("The exact displacement needs 2 components."));
    const auto        &mesh = dof_handler.get_mesh();
    const unsigned int k    = dof_handler.get_degree();
    VirtualElement<dim>                          element(k);
    dealii::Vector<double>                       local, coef, u(2);
    std::vector<dealii::Tensor<1, dim>>          grad(2);
    double l2 = 0, h1 = 0, en = 0, l2e = 0, h1e = 0, ene = 0;
    const unsigned int n_cells = cells ? cells->size() : mesh.n_cells();
    for (unsigned int cell = 0; cell < n_cells; ++cell)
      {
        const unsigned int c = cells ? (*cells)[cell] : cell;
        if (body != dealii::numbers::invalid_material_id && mesh.cell(c).material_id != body)
          continue;
        const ConstitutiveLaw<dim> &material = laws.get_law(mesh.cell(c).material_id);
        AssertThrow(material.is_linear(),
                    dealii::ExcMessage("compute_errors(): the constitutive law '" + material.get_name() +
                                       "' of material id " + std::to_string(mesh.cell(c).material_id) +
                                       " is not linear, so the energy norm of an error is undefined."));
        element.reinit(mesh.cell_vertices(c));
        dof_handler.get_dof_values(c, solution, local);
        element.project(local, coef);
        const dealii::Quadrature<dim> q = element.get_geometry().quadrature(2 * k + 6);
        for (unsigned int i = 0; i < q.size(); ++i)
          {
            const auto &x = q.point(i);
            exact.vector_value(x, u);
            exact.vector_gradient(x, grad);
            const dealii::Tensor<1, dim> uh = element.projection_value(coef, x);
            const dealii::Tensor<2, dim> gh = element.projection_gradient(coef, x);
            dealii::Tensor<2, dim>       g;
            for (unsigned int a = 0; a < 2; ++a)
              g[a] = grad[a];
            dealii::Tensor<1, dim> e;
            e[0]                                   = u[0] - uh[0];
            e[1]                                   = u[1] - uh[1];
            const dealii::Tensor<2, dim>      ge   = g - gh;
            const dealii::SymmetricTensor<2, dim> eps  = dealii::symmetrize(ge);
            const dealii::SymmetricTensor<2, dim> epsx = dealii::symmetrize(g);
            const double                      w    = q.weight(i);
            l2 += w * (e * e);
            h1 += w * dealii::scalar_product(ge, ge);
            en += w * (material.stress(eps) * eps);
            l2e += w * (u[0] * u[0] + u[1] * u[1]);
            h1e += w * dealii::scalar_product(g, g);
            ene += w * (material.stress(epsx) * epsx);
          }
      }
    ErrorNorms r;
    r.l2           = std::sqrt(std::max(l2, 0.));
    r.h1_seminorm  = std::sqrt(std::max(h1, 0.));
    r.energy       = std::sqrt(std::max(en, 0.));
    r.l2_exact     = std::sqrt(std::max(l2e, 0.));
    r.h1_exact     = std::sqrt(std::max(h1e, 0.));
    r.energy_exact = std::sqrt(std::max(ene, 0.));
    return r;
  }
  } // namespace



  template <int dim>
  ErrorNorms
  compute_errors(const VEMDoFHandler<dim>         &dof_handler,
                 const MaterialLibrary<dim>       &laws,
                 const dealii::Vector<double>     &solution,
                 const dealii::Function<dim>      &exact,
                 const dealii::types::material_id body)
  {
    return errors_on_cells(dof_handler, laws, solution, exact, body, nullptr);
  }



  template <int dim>
  ErrorNorms
  compute_errors(const VEMDoFHandler<dim>        &dof_handler,
                 const MaterialLibrary<dim>      &laws,
                 const dealii::Vector<double>    &solution,
                 const dealii::Function<dim>     &exact,
                 const std::vector<unsigned int> &cells)
  {
    return errors_on_cells(dof_handler, laws, solution, exact, dealii::numbers::invalid_material_id, &cells);
  }



  template <int dim>
  ErrorNorms
  compute_errors(const VEMDoFHandler<dim>                                    &dof_handler,
                 const std::map<dealii::types::material_id, ElasticMaterial> &materials,
                 const dealii::Vector<double>                                &solution,
                 const dealii::Function<dim>                                 &exact,
                 const dealii::types::material_id                             body)
  {
    return errors_on_cells(dof_handler, MaterialLibrary<dim>(materials), solution, exact, body, nullptr);
  }



  template <int dim>
  ErrorNorms
  compute_errors(const VEMDoFHandler<dim>                                    &dof_handler,
                 const std::map<dealii::types::material_id, ElasticMaterial> &materials,
                 const dealii::Vector<double>                                &solution,
                 const dealii::Function<dim>                                 &exact,
                 const std::vector<unsigned int>                             &cells)
  {
    return errors_on_cells(dof_handler, MaterialLibrary<dim>(materials), solution, exact,
                           dealii::numbers::invalid_material_id, &cells);
  }



  ErrorNorms
  sum_over_processes(const ErrorNorms &local, const MPI_Comm comm)
  {
    const std::vector<double> squares = {local.l2 * local.l2,         local.h1_seminorm * local.h1_seminorm,
                                         local.energy * local.energy, local.l2_exact * local.l2_exact,
                                         local.h1_exact * local.h1_exact, local.energy_exact * local.energy_exact};
    std::vector<double>       sums(squares.size());
    const int ierr = MPI_Allreduce(squares.data(), sums.data(), squares.size(), MPI_DOUBLE, MPI_SUM, comm);
    AssertThrowMPI(ierr);
    ErrorNorms r;
    r.l2           = std::sqrt(sums[0]);
    r.h1_seminorm  = std::sqrt(sums[1]);
    r.energy       = std::sqrt(sums[2]);
    r.l2_exact     = std::sqrt(sums[3]);
    r.h1_exact     = std::sqrt(sums[4]);
    r.energy_exact = std::sqrt(sums[5]);
    return r;
  }

  void
  add_convergence_rates(dealii::ConvergenceTable  &table,
                        const std::string         &key,
                        const std::vector<double> &errors,
                        const std::vector<double> &n_dofs)
  {
    AssertThrow(errors.size() == n_dofs.size(),
                dealii::ExcMessage("add_convergence_rates: " + std::to_string(errors.size()) + " errors but " +
                                   std::to_string(n_dofs.size()) + " DoF counts for the column '" + key + "'."));
    // ConvergenceTable computes only the rows that its rate column lacks;
    // with every row filled here, evaluate_convergence_rates() adds nothing
    // but the column's format (two decimals, grouped under key) as for its own
    const std::string rate_key = key + "...red.rate.log2";
    for (unsigned int i = 0; i < errors.size(); ++i)
      {
        if (i == 0)
          {
            table.add_value(rate_key, std::string("-"));
            continue;
          }
        const bool defined = errors[i - 1] > 0 && errors[i] > 0 && std::isfinite(errors[i - 1]) &&
                             std::isfinite(errors[i]) && n_dofs[i] > n_dofs[i - 1];
        if (defined)
          table.add_value(rate_key, 2 * std::log(errors[i - 1] / errors[i]) / std::log(n_dofs[i] / n_dofs[i - 1]));
        else
          table.add_value(rate_key, std::string("n/a"));
      }
    table.evaluate_convergence_rates(key, "dofs", dealii::ConvergenceTable::reduction_rate_log2, 2);
  }



  template ErrorNorms
  compute_errors(const VEMDoFHandler<2> &, const MaterialLibrary<2> &, const dealii::Vector<double> &,
                 const dealii::Function<2> &, const dealii::types::material_id);
  template ErrorNorms
  compute_errors(const VEMDoFHandler<2> &, const MaterialLibrary<2> &, const dealii::Vector<double> &,
                 const dealii::Function<2> &, const std::vector<unsigned int> &);
  template ErrorNorms
  compute_errors(const VEMDoFHandler<2> &, const std::map<dealii::types::material_id, ElasticMaterial> &,
                 const dealii::Vector<double> &, const dealii::Function<2> &,
                 const dealii::types::material_id);
  template ErrorNorms
  compute_errors(const VEMDoFHandler<2> &, const std::map<dealii::types::material_id, ElasticMaterial> &,
                 const dealii::Vector<double> &, const dealii::Function<2> &, const std::vector<unsigned int> &);
} // namespace dealvem
