// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/tensor.h>

#include <dealvem/base/output_file.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/postprocessing/finite_strain_output.h>
#include <dealvem/vem/vem_values.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <string>

namespace dealvem
{
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

    // the cell values first, so that nothing is written if one fails
    std::vector<std::array<double, 3>> cauchy(mesh.n_cells());
    std::vector<double>                det_F(mesh.n_cells());
    VEMValues<dim> values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values);
    std::vector<dealii::Tensor<2, dim>> grads;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const ConstitutiveLaw<dim> &law = laws.get_law(mesh.cell(c).material_id);
        AssertThrow(law.has_finite_strain_response(),
                    dealii::ExcMessage(what + "the law of cell " + std::to_string(c) + ", " + law.get_name() +
                                       ", has no finite-strain response."));
        values.reinit(c);
        values.get_function_gradient_projections(u, grads);
        dealii::Tensor<2, dim> sigma_sum;
        double                 J_sum = 0, area = 0;
        for (unsigned int q = 0; q < grads.size(); ++q)
          {
            dealii::Tensor<2, dim> F = grads[q];
            for (unsigned int d = 0; d < dim; ++d)
              F[d][d] += 1.;
            const double det_F = dealii::determinant(F);
            AssertThrow(std::isfinite(det_F) && det_F > 0,
                        dealii::ExcMessage(what + "det F = " + std::to_string(det_F) + " at quadrature point " +
                                           std::to_string(q) + " of cell " + std::to_string(c) +
                                           " (an inverted or collapsed cell)."));
            double J = det_F;
            sigma_sum += finite_strain_cauchy_stress(law, F, J) * values.JxW(q);
            J_sum += J * values.JxW(q);
            area += values.JxW(q);
          }
        cauchy[c] = {{sigma_sum[0][0] / area, sigma_sum[1][1] / area, sigma_sum[0][1] / area}};
        det_F[c]  = J_sum / area;
        for (const double x : cauchy[c])
          AssertThrow(std::isfinite(x),
                      dealii::ExcMessage(what + "the Cauchy stress of cell " + std::to_string(c) + " is not finite."));
      }
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      for (unsigned int d = 0; d < 2; ++d)
        AssertThrow(std::isfinite(u[VEMDoFHandler<dim>::node_dof(dof_handler.vertex_node(v), d)]),
                    dealii::ExcMessage(what + "the displacement of vertex " + std::to_string(v) + " is not finite."));

    OutputFile    file(filename);
    std::ostream &out = file.stream();
    out << std::setprecision(14);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << mesh.n_vertices() << "\" NumberOfCells=\""
        << mesh.n_cells() << "\">\n"
        << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      out << mesh.vertex(v)[0] << " " << mesh.vertex(v)[1] << " 0\n";
    out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        for (const unsigned int v : mesh.cell(c).vertices)
          out << v << " ";
        out << "\n";
      }
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    std::size_t offset = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        offset += mesh.cell(c).vertices.size();
        out << offset << "\n";
      }
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      out << "7\n"; // VTK_POLYGON
    out << "</DataArray>\n</Cells>\n";

    out << "<PointData Vectors=\"displacement\">\n"
        << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      {
        const unsigned int node = dof_handler.vertex_node(v);
        out << u[VEMDoFHandler<dim>::node_dof(node, 0)] << " " << u[VEMDoFHandler<dim>::node_dof(node, 1)] << " 0\n";
      }
    out << "</DataArray>\n</PointData>\n";

    out << "<CellData>\n"
        << "<DataArray type=\"Float64\" Name=\"cauchy_stress\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      out << cauchy[c][0] << " " << cauchy[c][1] << " " << cauchy[c][2] << "\n";
    out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"det_F\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      out << det_F[c] << "\n";
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"body_id\" format=\"ascii\">\n";
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



  template void
  write_finite_strain_vtu_file(const std::string &, const VEMDoFHandler<2> &, const MaterialLibrary<2> &,
                               const dealii::Vector<double> &);
} // namespace dealvem
