// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <dealvem/base/output_file.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/postprocessing/finite_strain_output.h>
#include <dealvem/postprocessing/vtu_output.h>
#include <dealvem/vem/vem_values.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <string>

namespace dealvem
{
  namespace
  {
    double
    von_mises_of(const FiniteStrainPointState &s)
    {
      dealii::SymmetricTensor<2, 2> sigma;
      sigma[0][0] = s.cauchy_stress[0];
      sigma[1][1] = s.cauchy_stress[1];
      sigma[0][1] = s.cauchy_stress[2];
      return von_mises_stress(sigma, s.cauchy_stress_zz);
    }

    // a += w b, member by member (von Mises excluded: it is made from the
    // sums)
    void
    add_scaled(FiniteStrainPointState &a, const double w, const FiniteStrainPointState &b)
    {
      for (unsigned int i = 0; i < 3; ++i)
        {
          a.cauchy_stress[i] += w * b.cauchy_stress[i];
          a.principal_stretches[i] += w * b.principal_stretches[i];
        }
      a.cauchy_stress_zz += w * b.cauchy_stress_zz;
      a.det_F += w * b.det_F;
    }

    FiniteStrainPointState
    zero_state()
    {
      FiniteStrainPointState z;
      z.det_F               = 0;
      z.principal_stretches = {{0., 0., 0.}};
      return z;
    }

    void
    divide(FiniteStrainPointState &a, const double w)
    {
      FiniteStrainPointState b = a;
      a                        = zero_state();
      add_scaled(a, 1. / w, b);
      a.von_mises = von_mises_of(a);
    }

    bool
    is_finite(const FiniteStrainPointState &s)
    {
      bool ok = std::isfinite(s.cauchy_stress_zz) && std::isfinite(s.det_F) && std::isfinite(s.von_mises);
      for (unsigned int i = 0; i < 3; ++i)
        ok = ok && std::isfinite(s.cauchy_stress[i]) && std::isfinite(s.principal_stretches[i]);
      return ok;
    }
  } // namespace



  dealii::Tensor<2, 2>
  finite_strain_cauchy_stress(const ConstitutiveLaw<2> &law, const dealii::Tensor<2, 2> &F, double &J)
  {
    AssertThrow(law.has_finite_strain_response(),
                dealii::ExcMessage("The law " + law.get_name() + " has no finite-strain response."));
    const double det_F = dealii::determinant(F);
    AssertThrow(std::isfinite(det_F) && det_F > 0,
                dealii::ExcMessage("det F = " + std::to_string(det_F) + ": an inverted or collapsed state."));
    // in plane stress the law knows its thickness stretch f: J = f det F
    if (const auto *hyperelastic = dynamic_cast<const HyperelasticMaterial *>(&law))
      {
        J = hyperelastic->out_of_plane_stretch(F) * det_F;
        return hyperelastic->cauchy_stress(F);
      }
    J = det_F;
    return law.first_piola_kirchhoff_stress(F) * dealii::transpose(F) / det_F;
  }



  FiniteStrainPointState
  finite_strain_point_state(const ConstitutiveLaw<2> &law, const dealii::Tensor<2, 2> &F)
  {
    FiniteStrainPointState s;
    double                 J     = 0;
    const auto             sigma = finite_strain_cauchy_stress(law, F, J);
    s.cauchy_stress              = {{sigma[0][0], sigma[1][1], 0.5 * (sigma[0][1] + sigma[1][0])}};
    s.det_F                      = J;
    s.principal_stretches[2]     = 1.;
    if (const auto *hyperelastic = dynamic_cast<const HyperelasticMaterial *>(&law))
      {
        s.cauchy_stress_zz       = hyperelastic->cauchy_stress_zz(F);
        s.principal_stretches[2] = hyperelastic->out_of_plane_stretch(F);
      }
    // the eigenvalues of C = F^T F, the squares of the in-plane stretches
    const dealii::Tensor<2, 2> C    = dealii::transpose(F) * F;
    const double               mean = 0.5 * (C[0][0] + C[1][1]);
    const double               root = std::hypot(0.5 * (C[0][0] - C[1][1]), C[0][1]);
    s.principal_stretches[0]        = std::sqrt(mean + root);
    // (det C = (det F)^2 > 0: the smaller eigenvalue from the product, free
    // of the cancellation in mean - root)
    s.principal_stretches[1] = std::abs(dealii::determinant(F)) / s.principal_stretches[0];
    s.von_mises              = von_mises_of(s);
    return s;
  }






  template <int dim>
  FiniteStrainFields
  compute_finite_strain_fields(const VEMDoFHandler<dim>     &dof_handler,
                               const MaterialLibrary<dim>   &laws,
                               const dealii::Vector<double> &u)
  {
    static_assert(dim == 2, "compute_finite_strain_fields is implemented for 2D meshes");
    const auto &mesh = dof_handler.get_mesh();
    AssertThrow(u.size() == dof_handler.n_dofs(),
                dealii::ExcMessage("compute_finite_strain_fields(): the solution has " + std::to_string(u.size()) +
                                   " entries for " + std::to_string(dof_handler.n_dofs()) + " DoFs."));
    FiniteStrainFields out;
    out.cells.assign(mesh.n_cells(), zero_state());
    out.vertices.assign(mesh.n_vertices(), zero_state());
    std::vector<double> cell_area(mesh.n_cells(), 0.), vertex_area(mesh.n_vertices(), 0.);
    VEMValues<dim> values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values);
    std::vector<dealii::Tensor<2, dim>> grads;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const ConstitutiveLaw<dim> &law = laws.get_law(mesh.cell(c).material_id);
        AssertThrow(law.has_finite_strain_response(),
                    dealii::ExcMessage("The law of cell " + std::to_string(c) + ", " + law.get_name() +
                                       ", has no finite-strain response."));
        values.reinit(c);
        values.get_function_gradient_projections(u, grads);
        for (unsigned int q = 0; q < grads.size(); ++q)
          {
            dealii::Tensor<2, dim> F = grads[q];
            for (unsigned int d = 0; d < dim; ++d)
              F[d][d] += 1.;
            const double det_F = dealii::determinant(F);
            AssertThrow(std::isfinite(det_F) && det_F > 0,
                        dealii::ExcMessage("det F = " + std::to_string(det_F) + " at quadrature point " +
                                           std::to_string(q) + " of cell " + std::to_string(c) +
                                           " (an inverted or collapsed cell)."));
            add_scaled(out.cells[c], values.JxW(q), finite_strain_point_state(law, F));
            cell_area[c] += values.JxW(q);
          }
        divide(out.cells[c], cell_area[c]);
        AssertThrow(is_finite(out.cells[c]),
                    dealii::ExcMessage("The finite-strain output of cell " + std::to_string(c) +
                                       " (Cauchy stress, det F or stretches) is not finite."));
        const auto &s = out.cells[c].cauchy_stress;
        out.max_cell_cauchy_norm =
          std::max(out.max_cell_cauchy_norm, std::sqrt(s[0] * s[0] + s[1] * s[1] + 2 * s[2] * s[2]));
        for (const unsigned int v : mesh.cell(c).vertices)
          {
            add_scaled(out.vertices[v], cell_area[c], out.cells[c]);
            vertex_area[v] += cell_area[c];
          }
      }
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      if (vertex_area[v] > 0)
        divide(out.vertices[v], vertex_area[v]);
      else
        out.vertices[v] = FiniteStrainPointState(); // a vertex of no cell: the unstressed state
    return out;
  }



  template <int dim>
  void
  write_finite_strain_vtu_file(const std::string            &filename,
                               const VEMDoFHandler<dim>     &dof_handler,
                               const MaterialLibrary<dim>   &laws,
                               const dealii::Vector<double> &u)
  {
    static_assert(dim == 2, "write_finite_strain_vtu_file is implemented for 2D meshes");
    const auto        &mesh = dof_handler.get_mesh();
    const std::string  what = "Cannot write the VTU file '" + filename + "': ";
    AssertThrow(u.size() == dof_handler.n_dofs(),
                dealii::ExcMessage(what + "the solution has " + std::to_string(u.size()) + " entries for " +
                                   std::to_string(dof_handler.n_dofs()) + " DoFs."));

    // the values first, so that nothing is written if one fails
    // (the messages name the cell and say what is wrong with it)
    const FiniteStrainFields fields = compute_finite_strain_fields(dof_handler, laws, u);
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      for (unsigned int d = 0; d < 2; ++d)
        AssertThrow(std::isfinite(u[VEMDoFHandler<dim>::node_dof(dof_handler.vertex_node(v), d)]),
                    dealii::ExcMessage(what + "the displacement of vertex " + std::to_string(v) + " is not finite."));

    OutputFile    file(filename);
    std::ostream &out = file.stream();
    out << std::setprecision(14);
    write_vtu_polygons(out, mesh);

    // the fields of one state per entity, under the same names as point
    // and cell data
    const auto write_fields = [&out](const std::vector<FiniteStrainPointState> &states) {
      out << "<DataArray type=\"Float64\" Name=\"cauchy_stress\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const auto &s : states)
        out << s.cauchy_stress[0] << " " << s.cauchy_stress[1] << " " << s.cauchy_stress[2] << "\n";
      out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"cauchy_stress_zz\" format=\"ascii\">\n";
      for (const auto &s : states)
        out << s.cauchy_stress_zz << "\n";
      out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"cauchy_von_mises\" format=\"ascii\">\n";
      for (const auto &s : states)
        out << s.von_mises << "\n";
      out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"det_F\" format=\"ascii\">\n";
      for (const auto &s : states)
        out << s.det_F << "\n";
      out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"principal_stretches\" NumberOfComponents=\"3\" "
             "format=\"ascii\">\n";
      for (const auto &s : states)
        out << s.principal_stretches[0] << " " << s.principal_stretches[1] << " " << s.principal_stretches[2]
            << "\n";
      out << "</DataArray>\n";
    };

    out << "<PointData Vectors=\"displacement\">\n"
        << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      {
        const unsigned int node = dof_handler.vertex_node(v);
        out << u[VEMDoFHandler<dim>::node_dof(node, 0)] << " " << u[VEMDoFHandler<dim>::node_dof(node, 1)] << " 0\n";
      }
    out << "</DataArray>\n";
    write_fields(fields.vertices);
    out << "</PointData>\n<CellData>\n";
    write_fields(fields.cells);
    out << "<DataArray type=\"Int32\" Name=\"body_id\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      out << int(mesh.cell(c).material_id) << "\n";
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"cell_id\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      out << c << "\n";
    out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    file.commit();
  }



  void
  write_pvd_record(const std::string &filename, const std::vector<std::pair<double, std::string>> &times_and_files)
  {
    const std::string what = "Cannot write the PVD file '" + filename + "': ";
    AssertThrow(!times_and_files.empty(), dealii::ExcMessage(what + "the list of time steps is empty."));
    for (unsigned int i = 0; i < times_and_files.size(); ++i)
      {
        const double       t    = times_and_files[i].first;
        const std::string &name = times_and_files[i].second;
        AssertThrow(std::isfinite(t),
                    dealii::ExcMessage(what + "the time of entry " + std::to_string(i) + " is not finite."));
        AssertThrow(i == 0 || t > times_and_files[i - 1].first,
                    dealii::ExcMessage(what + "the times do not increase at entry " + std::to_string(i) + " (" +
                                       std::to_string(times_and_files[i - 1].first) + " then " +
                                       std::to_string(t) + ")."));
        AssertThrow(!name.empty() && name.find_first_of("\"<>&'") == std::string::npos,
                    dealii::ExcMessage(what + "the file name of entry " + std::to_string(i) + ", '" + name +
                                       "', is empty or holds a quote, '<', '>' or '&'."));
      }
    OutputFile    file(filename);
    std::ostream &out = file.stream();
    out << std::setprecision(14);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n";
    for (const auto &[t, name] : times_and_files)
      out << "<DataSet timestep=\"" << t << "\" group=\"\" part=\"0\" file=\"" << name << "\"/>\n";
    out << "</Collection>\n</VTKFile>\n";
    file.commit();
  }



  template FiniteStrainFields
  compute_finite_strain_fields(const VEMDoFHandler<2> &, const MaterialLibrary<2> &, const dealii::Vector<double> &);
  template void
  write_finite_strain_vtu_file(const std::string &, const VEMDoFHandler<2> &, const MaterialLibrary<2> &,
                               const dealii::Vector<double> &);
} // namespace dealvem
