// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The gmsh .msh reader of MeshIO (read_msh(), read_msh_physical_names())
// and its writer of triangulations (write_msh(), format 2.2 ASCII). The reader:
// formats 2.2 and 4.1, ASCII and binary, any mix of two-dimensional
// elements read as polygons. The file is parsed and checked by
// internal::GmshReader (gmsh_reader.h, gmsh_reader.cc, gmsh_checks.cc);
// here its cells become a PolygonalMesh.
#include <deal.II/grid/tria.h>

#include <dealvem/mesh/mesh_io.h>

#include "gmsh_reader.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace dealvem
{
  namespace MeshIO
  {
    namespace
    {
      using internal::edge_key;

      // The cells and boundary edges of the file as plain lists, refined
      // by midpoints.
      struct PlainMesh
      {
        std::vector<dealii::Point<2>>                          points;
        std::vector<std::vector<unsigned int>>                 cells;
        std::vector<dealii::types::material_id>                material;
        std::map<std::pair<unsigned int, unsigned int>, dealii::types::boundary_id> boundary;

        // each triangle into four by its edge midpoints, each quadrangle
        // into four by its edge midpoints and its centre; a boundary edge
        // passes its id to both halves
        void
        refine()
        {
          std::map<std::pair<unsigned int, unsigned int>, unsigned int> midpoint;
          const auto mid = [&](const unsigned int a, const unsigned int b) {
            const auto it = midpoint.try_emplace(edge_key(a, b), points.size());
            if (it.second)
              points.push_back(0.5 * (points[a] + points[b]));
            return it.first->second;
          };
          std::vector<std::vector<unsigned int>> fine;
          std::vector<dealii::types::material_id> fine_material;
          fine.reserve(4 * cells.size());
          for (std::size_t c = 0; c < cells.size(); ++c)
            {
              const auto &v = cells[c];
              if (v.size() == 3)
                {
                  const unsigned int m01 = mid(v[0], v[1]), m12 = mid(v[1], v[2]), m20 = mid(v[2], v[0]);
                  fine.push_back({v[0], m01, m20});
                  fine.push_back({m01, v[1], m12});
                  fine.push_back({m20, m12, v[2]});
                  fine.push_back({m01, m12, m20});
                }
              else
                {
                  const unsigned int m[4] = {mid(v[0], v[1]), mid(v[1], v[2]), mid(v[2], v[3]), mid(v[3], v[0])};
                  const unsigned int centre = points.size();
                  points.push_back(0.25 * (points[v[0]] + points[v[1]] + points[v[2]] + points[v[3]]));
                  for (unsigned int k = 0; k < 4; ++k)
                    fine.push_back({v[k], m[k], centre, m[(k + 3) % 4]});
                }
              fine_material.insert(fine_material.end(), 4, material[c]);
            }
          std::map<std::pair<unsigned int, unsigned int>, dealii::types::boundary_id> fine_boundary;
          for (const auto &[edge, id] : boundary)
            {
              const unsigned int m = midpoint.at(edge);
              fine_boundary[edge_key(edge.first, m)]  = id;
              fine_boundary[edge_key(m, edge.second)] = id;
            }
          cells.swap(fine);
          material.swap(fine_material);
          boundary.swap(fine_boundary);
        }
      };

      std::string
      read_file(const std::string &filename)
      {
        AssertThrow(!std::filesystem::is_directory(filename),
                    dealii::ExcMessage("Mesh file '" + filename + "' is a directory."));
        std::ifstream in(filename, std::ios::binary);
        AssertThrow(in, dealii::ExcMessage("Cannot open the mesh file '" + filename + "'."));
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
      }
    } // namespace



    std::string
    PhysicalNames::list() const
    {
      std::string s;
      for (const auto &[what, map] : {std::make_pair("boundaries (dimension 1): ", &boundary_ids),
                                      std::make_pair("surfaces (dimension 2): ", &material_ids)})
        {
          if (map->empty())
            continue;
          s += (s.empty() ? "" : "; ") + std::string(what);
          bool first = true;
          for (const auto &[n, id] : *map)
            {
              s += (first ? "'" : ", '") + n + "' = " + std::to_string(id);
              first = false;
            }
        }
      for (const auto &[n, why] : unusable)
        s += (s.empty() ? "" : "; ") + std::string("'") + n + "' cannot be used: " + why;
      return s.empty() ? std::string("(the file has no physical names)") : s;
    }



    template <int dim>
    PhysicalNames
    read_msh(PolygonalMesh<dim> &mesh,
             const std::string  &filename,
             const unsigned int  n_refinements,
             const bool          separate_material_ids)
    {
      internal::GmshReader reader(filename, read_file(filename), separate_material_ids);
      reader.run();

      // the corners of the cells, numbered in the order of $Nodes (the
      // other nodes of higher-order elements are dropped)
      PlainMesh                 plain;
      std::vector<unsigned int> vertex(reader.points.size(), dealii::numbers::invalid_unsigned_int);
      for (const auto &c : reader.cells)
        for (unsigned int k = 0; k < c.n; ++k)
          vertex[c.node[k]] = 0;
      for (unsigned int i = 0; i < vertex.size(); ++i)
        if (vertex[i] == 0)
          {
            vertex[i] = plain.points.size();
            plain.points.push_back(reader.points[i]);
          }
      for (const auto &c : reader.cells)
        {
          plain.cells.emplace_back();
          for (unsigned int k = 0; k < c.n; ++k)
            plain.cells.back().push_back(vertex[c.node[k]]);
          plain.material.push_back(dealii::types::material_id(c.physical));
        }
      for (const auto &l : reader.lines)
        plain.boundary[edge_key(vertex[l.node[0]], vertex[l.node[1]])] = dealii::types::boundary_id(l.physical);
      for (unsigned int r = 0; r < n_refinements; ++r)
        plain.refine();

      mesh.clear();
      for (const auto &p : plain.points)
        mesh.add_vertex(p);
      // separate_material_ids: the material id that uses a vertex first
      // keeps it, the others get copies
      std::vector<dealii::types::material_id>                                      owner;
      std::map<std::pair<unsigned int, dealii::types::material_id>, unsigned int> copies;
      std::map<std::pair<unsigned int, unsigned int>, dealii::types::material_id> edge_material;
      if (separate_material_ids)
        owner.assign(plain.points.size(), dealii::numbers::invalid_material_id);
      for (std::size_t c = 0; c < plain.cells.size(); ++c)
        {
          std::vector<unsigned int> loop = plain.cells[c];
          const auto                id   = plain.material[c];
          if (separate_material_ids)
            {
              for (unsigned int k = 0; k < loop.size(); ++k)
                edge_material[edge_key(loop[k], loop[(k + 1) % loop.size()])] = id;
              for (auto &v : loop)
                {
                  if (owner[v] == dealii::numbers::invalid_material_id)
                    owner[v] = id;
                  if (owner[v] != id)
                    {
                      const auto copy = copies.try_emplace({v, id}, mesh.n_vertices());
                      if (copy.second)
                        mesh.add_vertex(mesh.vertex(v));
                      v = copy.first->second;
                    }
                }
            }
          mesh.add_cell(loop, id);
        }
      for (const auto &[edge, id] : plain.boundary)
        {
          unsigned int a = edge.first, b = edge.second;
          if (separate_material_ids)
            {
              const auto m   = edge_material.at(edge);
              const auto own = [&](const unsigned int v) {
                return owner[v] == m ? v : copies.at({v, m});
              };
              a = own(a);
              b = own(b);
            }
          mesh.set_boundary_id(a, b, id);
        }
      mesh.name = filename;
      mesh.finalize();
      return reader.names;
    }



    PhysicalNames
    read_msh_physical_names(const std::string &filename)
    {
      // the names come before the nodes: read the head of the file only
      std::ifstream in(filename, std::ios::binary);
      AssertThrow(in, dealii::ExcMessage("Cannot open the mesh file '" + filename + "'."));
      std::string head, text;
      bool        in_names = false;
      while (std::getline(in, text))
        {
          head += text + "\n";
          std::istringstream s(text);
          std::string        w;
          s >> w;
          if (w == "$PhysicalNames")
            in_names = true;
          if (w == "$EndPhysicalNames" || (!in_names && (w == "$Nodes" || w == "$Entities" || w == "$Elements")))
            break;
        }
      if (!in_names)
        return {};
      // the format and the names, checked as read_msh() checks them
      internal::GmshReader reader(filename, head, false);
      reader.run(true);
      return reader.names;
    }



    template PhysicalNames read_msh(PolygonalMesh<2> &, const std::string &, const unsigned int, const bool);
    void
    write_msh(const dealii::Triangulation<2, 2> &tria, const std::string &filename)
    {
      std::ofstream out(filename);
      AssertThrow(out, dealii::ExcMessage("MeshIO::write_msh: cannot open '" + filename + "' for writing."));
      const std::vector<bool>  &used = tria.get_used_vertices();
      std::vector<unsigned int> number(used.size(), 0);
      unsigned int              n_nodes = 0;
      for (unsigned int v = 0; v < used.size(); ++v)
        if (used[v])
          number[v] = ++n_nodes;
      out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << n_nodes << '\n' << std::setprecision(17);
      for (unsigned int v = 0; v < used.size(); ++v)
        if (used[v])
          out << number[v] << ' ' << tria.get_vertices()[v][0] << ' ' << tria.get_vertices()[v][1] << " 0\n";
      out << "$EndNodes\n";
      std::ostringstream elements;
      unsigned int       n_elements = 0;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() != 0)
            elements << ++n_elements << " 1 2 " << int(cell->face(f)->boundary_id()) << ' '
                     << int(cell->face(f)->boundary_id()) << ' ' << number[cell->face(f)->vertex_index(0)] << ' '
                     << number[cell->face(f)->vertex_index(1)] << '\n';
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int id = cell->material_id();
          if (cell->n_vertices() == 4)
            // gmsh orders a quadrangle's vertices around it, deal.II lexicographically
            elements << ++n_elements << " 3 2 " << id << ' ' << id << ' ' << number[cell->vertex_index(0)] << ' '
                     << number[cell->vertex_index(1)] << ' ' << number[cell->vertex_index(3)] << ' '
                     << number[cell->vertex_index(2)] << '\n';
          else
            elements << ++n_elements << " 2 2 " << id << ' ' << id << ' ' << number[cell->vertex_index(0)] << ' '
                     << number[cell->vertex_index(1)] << ' ' << number[cell->vertex_index(2)] << '\n';
        }
      out << "$Elements\n" << n_elements << '\n' << elements.str() << "$EndElements\n";
      out.close();
      AssertThrow(out, dealii::ExcMessage("MeshIO::write_msh: writing '" + filename + "' failed."));
    }
  } // namespace MeshIO
} // namespace dealvem
