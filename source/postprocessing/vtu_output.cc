// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/base/output_file.h>
#include <dealvem/postprocessing/vtu_output.h>

#include <iomanip>

namespace dealvem
{
  template <int dim>
  void
  write_vtu_file(const std::string            &filename,
                 const VEMDoFHandler<dim>     &dof_handler,
                 const dealii::Vector<double> &u,
                 const StressRecovery<dim>    &s)
  {
    const auto   &mesh = dof_handler.get_mesh();
    OutputFile    file(filename);
    std::ostream &out = file.stream();
    out << std::setprecision(14);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << mesh.n_vertices() << "\" NumberOfCells=\""
        << mesh.n_cells() << "\">\n";
    out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto &v : mesh.get_vertices())
      out << v[0] << " " << v[1] << " 0\n";
    out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto &c : mesh.get_cells())
      {
        for (const auto v : c.vertices)
          out << v << " ";
        out << "\n";
      }
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    std::size_t offset = 0;
    for (const auto &c : mesh.get_cells())
      {
        offset += c.vertices.size();
        out << offset << "\n";
      }
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      out << "7\n";
    out << "</DataArray>\n</Cells>\n";

    out << "<PointData Vectors=\"displacement\">\n"
        << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      out << u[2 * v] << " " << u[2 * v + 1] << " 0\n";
    out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      {
        const auto &t = s.vertex_stress(v);
        out << t[0][0] << " " << t[1][1] << " " << t[0][1] << "\n";
      }
    out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"von_mises\" format=\"ascii\">\n";
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      out << s.vertex_von_mises(v) << "\n";
    out << "</DataArray>\n</PointData>\n";

    out << "<CellData>\n<DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const auto &t = s.cell_stress(c);
        out << t[0][0] << " " << t[1][1] << " " << t[0][1] << "\n";
      }
    out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"von_mises\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      out << s.cell_von_mises(c) << "\n";
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"body_id\" format=\"ascii\">\n";
    for (const auto &c : mesh.get_cells())
      out << int(c.material_id) << "\n";
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"cell_id\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      out << c << "\n";
    out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    file.commit();
  }

  template void
  write_vtu_file(const std::string &, const VEMDoFHandler<2> &, const dealii::Vector<double> &,
                 const StressRecovery<2> &);
} // namespace dealvem
