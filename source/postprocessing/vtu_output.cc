// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/base/output_file.h>
#include <dealvem/postprocessing/vtu_output.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace dealvem
{
  namespace
  {
    // write_cells(), step 1: the vertices of the cells @p cells in the order
    // of the mesh (all of them if @p whole_mesh) and the local number of
    // each vertex of the mesh in this list.
    template <int dim>
    void
    select_vertices(const PolygonalMesh<dim> &mesh, const std::vector<unsigned int> &cells, const bool whole_mesh,
                    std::vector<unsigned int> &local, std::vector<unsigned int> &vertices)
    {
      local.assign(mesh.n_vertices(), dealii::numbers::invalid_unsigned_int);
      if (!whole_mesh)
        {
          for (const unsigned int c : cells)
            for (const unsigned int v : mesh.cell(c).vertices)
              local[v] = 0;
          for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
            if (local[v] == 0)
              {
                local[v] = vertices.size();
                vertices.push_back(v);
              }
        }
      else
        for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
          {
            local[v] = v;
            vertices.push_back(v);
          }
    }



    // write_cells(), step 2: nothing non-finite goes into the file: a value
    // that overflowed stops the output, naming the field and where it is.
    template <int dim>
    void
    check_finite(const std::string &filename, const PolygonalMesh<dim> &mesh, const dealii::Vector<double> &u,
                 const StressRecovery<dim> &s, const std::vector<unsigned int> &cells,
                 const std::vector<unsigned int> &vertices)
    {
      const auto refuse = [&](const std::string &field, const double value, const std::string &where) {
        std::ostringstream msg;
        msg << "Cannot write the VTU file '" << filename << "': the field '" << field << "' is " << value
            << " at " << where
            << ". The solution or the stresses recovered from it overflow (or the solve failed); "
               "check the loads and the material for values far from 1 in the units of the problem.";
        AssertThrow(false, dealii::ExcMessage(msg.str()));
      };
      const auto vertex_name = [&](const unsigned int v) {
        std::ostringstream w;
        w << "vertex " << v << " (" << mesh.get_vertices()[v][0] << ", " << mesh.get_vertices()[v][1] << ")";
        return w.str();
      };
      // the displacements first: stresses derive from them
      for (const unsigned int v : vertices)
        for (unsigned int d = 0; d < 2; ++d)
          {
            if (!std::isfinite(mesh.get_vertices()[v][d]))
              refuse("coordinates", mesh.get_vertices()[v][d], "vertex " + std::to_string(v));
            if (!std::isfinite(u[2 * v + d]))
              refuse("displacement", u[2 * v + d], vertex_name(v));
          }
      for (const unsigned int v : vertices)
        {
          for (unsigned int d = 0; d < 2; ++d)
            for (unsigned int e = 0; e < 2; ++e)
              if (!std::isfinite(s.vertex_stress(v)[d][e]))
                refuse("stress", s.vertex_stress(v)[d][e], vertex_name(v));
          if (!std::isfinite(s.vertex_von_mises(v)))
            refuse("von_mises", s.vertex_von_mises(v), vertex_name(v));
        }
      for (const unsigned int c : cells)
        {
          for (unsigned int d = 0; d < 2; ++d)
            for (unsigned int e = 0; e < 2; ++e)
              if (!std::isfinite(s.cell_stress(c)[d][e]))
                refuse("stress", s.cell_stress(c)[d][e], "cell " + std::to_string(c));
          if (!std::isfinite(s.cell_von_mises(c)))
            refuse("von_mises", s.cell_von_mises(c), "cell " + std::to_string(c));
        }
    }



    // write_cells(), step 3: further point fields: one finite value per
    // mesh vertex, a name that is new and fits an XML attribute.
    template <int dim>
    void
    check_extra_fields(const std::string &filename, const PolygonalMesh<dim> &mesh,
                       const std::vector<unsigned int>                                &vertices,
                       const std::vector<std::pair<std::string, std::vector<double>>> &extra)
    {
      for (unsigned int f = 0; f < extra.size(); ++f)
        {
          const std::string &name = extra[f].first;
          const std::string  what = "Cannot write the VTU file '" + filename + "': the point field '" + name + "'";
          AssertThrow(!name.empty() && name.find_first_of("\"<>&'") == std::string::npos,
                      dealii::ExcMessage(what + " needs a non-empty name without quotes, '<', '>' or '&'."));
          for (unsigned int g = 0; g < f; ++g)
            AssertThrow(extra[g].first != name, dealii::ExcMessage(what + " is given twice."));
          AssertThrow(name != "displacement" && name != "stress" && name != "von_mises",
                      dealii::ExcMessage(what + " has the name of a field that is always written."));
          AssertThrow(extra[f].second.size() == mesh.n_vertices(),
                      dealii::ExcMessage(what + " has " + std::to_string(extra[f].second.size()) +
                                         " values for " + std::to_string(mesh.n_vertices()) + " mesh vertices."));
          for (const unsigned int v : vertices)
            AssertThrow(std::isfinite(extra[f].second[v]),
                        dealii::ExcMessage(what + " is not finite at vertex " + std::to_string(v) + "."));
        }
    }



    // write_cells(), step 4: the points and the cells (connectivity,
    // offsets, types) of the piece.
    template <int dim>
    void
    write_geometry(std::ostream &out, const PolygonalMesh<dim> &mesh, const std::vector<unsigned int> &cells,
                   const std::vector<unsigned int> &vertices, const std::vector<unsigned int> &local)
    {
      out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const unsigned int v : vertices)
        out << mesh.get_vertices()[v][0] << " " << mesh.get_vertices()[v][1] << " 0\n";
      out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
      for (const unsigned int c : cells)
        {
          for (const auto v : mesh.cell(c).vertices)
            out << local[v] << " ";
          out << "\n";
        }
      out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
      std::size_t offset = 0;
      for (const unsigned int c : cells)
        {
          offset += mesh.cell(c).vertices.size();
          out << offset << "\n";
        }
      out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
      for (unsigned int i = 0; i < cells.size(); ++i)
        out << "7\n";
      out << "</DataArray>\n</Cells>\n";
    }



    // write_cells(), step 5: the point data: displacement, stress,
    // von_mises and the further fields.
    template <int dim>
    void
    write_point_data(std::ostream &out, const dealii::Vector<double> &u, const StressRecovery<dim> &s,
                     const std::vector<unsigned int>                                &vertices,
                     const std::vector<std::pair<std::string, std::vector<double>>> &extra)
    {
      out << "<PointData Vectors=\"displacement\">\n"
          << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const unsigned int v : vertices)
        out << u[2 * v] << " " << u[2 * v + 1] << " 0\n";
      out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const unsigned int v : vertices)
        {
          const auto &t = s.vertex_stress(v);
          out << t[0][0] << " " << t[1][1] << " " << t[0][1] << "\n";
        }
      out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"von_mises\" format=\"ascii\">\n";
      for (const unsigned int v : vertices)
        out << s.vertex_von_mises(v) << "\n";
      for (const auto &field : extra)
        {
          out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"" << field.first << "\" format=\"ascii\">\n";
          for (const unsigned int v : vertices)
            out << field.second[v] << "\n";
        }
      out << "</DataArray>\n</PointData>\n";
    }



    // write_cells(), step 6: the cell data: stress, von_mises, body_id,
    // cell_id and, unless @p subdomain is invalid_unsigned_int, subdomain;
    // then the end of the file.
    template <int dim>
    void
    write_cell_data(std::ostream &out, const PolygonalMesh<dim> &mesh, const StressRecovery<dim> &s,
                    const std::vector<unsigned int> &cells, const unsigned int subdomain)
    {
      out << "<CellData>\n<DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const unsigned int c : cells)
        {
          const auto &t = s.cell_stress(c);
          out << t[0][0] << " " << t[1][1] << " " << t[0][1] << "\n";
        }
      out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"von_mises\" format=\"ascii\">\n";
      for (const unsigned int c : cells)
        out << s.cell_von_mises(c) << "\n";
      out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"body_id\" format=\"ascii\">\n";
      for (const unsigned int c : cells)
        out << int(mesh.cell(c).material_id) << "\n";
      out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"cell_id\" format=\"ascii\">\n";
      for (const unsigned int c : cells)
        out << c << "\n";
      if (subdomain != dealii::numbers::invalid_unsigned_int)
        {
          out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"subdomain\" format=\"ascii\">\n";
          for (unsigned int i = 0; i < cells.size(); ++i)
            out << subdomain << "\n";
        }
      out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    }



    // The writer of write_vtu_file() and write_vtu_piece(): the cells
    // @p cells (all if nullptr) with the vertices they use; the cell data
    // "subdomain" if @p subdomain is not invalid_unsigned_int.
    template <int dim>
    void
    write_cells(const std::string               &filename,
                const VEMDoFHandler<dim>        &dof_handler,
                const dealii::Vector<double>    &u,
                const StressRecovery<dim>       &s,
                const std::vector<unsigned int> *cell_list,
                const unsigned int               subdomain,
                const std::vector<std::pair<std::string, std::vector<double>>> &extra = {})
    {
      const auto &mesh = dof_handler.get_mesh();
      std::vector<unsigned int> cells;
      if (cell_list)
        cells = *cell_list;
      else
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          cells.push_back(c);
      std::vector<unsigned int> local, vertices;
      select_vertices(mesh, cells, cell_list == nullptr, local, vertices);
      check_finite(filename, mesh, u, s, cells, vertices);
      check_extra_fields(filename, mesh, vertices, extra);

      OutputFile    file(filename);
      std::ostream &out = file.stream();
      out << std::setprecision(14);
      out << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
          << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << vertices.size() << "\" NumberOfCells=\""
          << cells.size() << "\">\n";
      write_geometry(out, mesh, cells, vertices, local);
      write_point_data(out, u, s, vertices, extra);
      write_cell_data(out, mesh, s, cells, subdomain);
      file.commit();
    }
  } // namespace



  template <int dim>
  void
  write_vtu_file(const std::string            &filename,
                 const VEMDoFHandler<dim>     &dof_handler,
                 const dealii::Vector<double> &u,
                 const StressRecovery<dim>    &s)
  {
    write_cells(filename, dof_handler, u, s, nullptr, dealii::numbers::invalid_unsigned_int);
  }



  template <int dim>
  void
  write_vtu_file(const std::string                                             &filename,
                 const VEMDoFHandler<dim>                                      &dof_handler,
                 const dealii::Vector<double>                                  &u,
                 const StressRecovery<dim>                                     &s,
                 const std::vector<std::pair<std::string, std::vector<double>>> &point_data)
  {
    write_cells(filename, dof_handler, u, s, nullptr, dealii::numbers::invalid_unsigned_int, point_data);
  }



  template <int dim>
  void
  write_vtu_piece(const std::string               &filename,
                  const VEMDoFHandler<dim>        &dof_handler,
                  const dealii::Vector<double>    &u,
                  const StressRecovery<dim>       &s,
                  const std::vector<unsigned int> &cells,
                  const unsigned int               subdomain)
  {
    write_cells(filename, dof_handler, u, s, &cells, subdomain);
  }



  void
  write_pvtu_record(const std::string &filename, const std::vector<std::string> &pieces)
  {
    OutputFile    file(filename);
    std::ostream &out = file.stream();
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "<PUnstructuredGrid GhostLevel=\"0\">\n"
        << "<PPointData Vectors=\"displacement\">\n"
        << "<PDataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\"/>\n"
        << "<PDataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"3\"/>\n"
        << "<PDataArray type=\"Float64\" Name=\"von_mises\"/>\n"
        << "</PPointData>\n<PCellData>\n"
        << "<PDataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"3\"/>\n"
        << "<PDataArray type=\"Float64\" Name=\"von_mises\"/>\n"
        << "<PDataArray type=\"Int32\" Name=\"body_id\"/>\n"
        << "<PDataArray type=\"Int32\" Name=\"cell_id\"/>\n"
        << "<PDataArray type=\"Int32\" Name=\"subdomain\"/>\n"
        << "</PCellData>\n<PPoints>\n<PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n</PPoints>\n";
    for (const auto &p : pieces)
      out << "<Piece Source=\"" << p << "\"/>\n";
    out << "</PUnstructuredGrid>\n</VTKFile>\n";
    file.commit();
  }



  template void
  write_vtu_file(const std::string &, const VEMDoFHandler<2> &, const dealii::Vector<double> &,
                 const StressRecovery<2> &);
  template void
  write_vtu_file(const std::string &, const VEMDoFHandler<2> &, const dealii::Vector<double> &,
                 const StressRecovery<2> &, const std::vector<std::pair<std::string, std::vector<double>>> &);
  template void
  write_vtu_piece(const std::string &, const VEMDoFHandler<2> &, const dealii::Vector<double> &,
                  const StressRecovery<2> &, const std::vector<unsigned int> &, const unsigned int);
  void
  write_vtu_polygons(std::ostream &out, const PolygonalMesh<2> &mesh)
  {
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
  }
} // namespace dealvem
