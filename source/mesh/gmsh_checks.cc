// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The checks half of the gmsh reader (gmsh_reader.h): what makes the cells
// and boundary lines that were read a mesh (no degenerate, clockwise or
// repeated cell, no edge of three cells, boundary ids on boundary edges
// only), and the names of elements in its messages.
#include "gmsh_reader.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace dealvem
{
  namespace MeshIO
  {
    namespace internal
    {
      // "quadrangle 7", with " (line 23)" if @p at_line
      std::string
      GmshReader::element_name(const Element &e, const bool at_line) const
      {
        const std::string kind = e.type == 1 ? "line element" :
                                 e.type == 2 ? "triangle" :
                                 e.type == 3 ? "quadrangle" :
                                               std::string(e.n == 2 ? "line element" :
                                                           e.n == 3 ? "triangle" :
                                                                      "quadrangle") +
                                                 " (type " + std::to_string(e.type) + ")";
        return kind + " " + std::to_string(e.number) +
               (at_line ? " (line " + std::to_string(e.line) + ")" : std::string());
      }



      dealii::ExcMessage
      GmshReader::element_error(const Element &e, const std::string &what) const
      {
        return dealii::ExcMessage("Invalid gmsh file " + name + ":" + std::to_string(e.line) + ": " + what);
      }



      std::string
      GmshReader::node_list(const Element &e) const
      {
        std::ostringstream s;
        s << std::setprecision(15);
        for (unsigned int k = 0; k < e.n; ++k)
          s << (k > 0 ? ", " : "") << node_tags[e.node[k]] << " (" << points[e.node[k]][0] << ", "
            << points[e.node[k]][1] << ")";
        return s.str();
      }



      // No cell without area or with a side of length zero, no bow-tie
      // quadrangle, no clockwise cell, no cell given twice, no edge of
      // more than two cells, no edge between two bodies (physical
      // surfaces) unless the parts become bodies of their own.
      void
      GmshReader::check_cells()
      {
        std::map<std::vector<unsigned int>, std::size_t> seen;
        for (std::size_t i = 0; i < cells.size(); ++i)
          {
            const Element     &c = cells[i];
            const unsigned int n = c.n;
            double             area = 0, length = 0;
            unsigned int       left = 0, right = 0;
            for (unsigned int k = 0; k < n; ++k)
              {
                const auto &a = points[c.node[k]], &b = points[c.node[(k + 1) % n]], &q = points[c.node[(k + 2) % n]];
                area += a[0] * b[1] - b[0] * a[1];
                length            = std::max(length, a.distance(b));
                const double turn = (b[0] - a[0]) * (q[1] - b[1]) - (b[1] - a[1]) * (q[0] - b[0]);
                left += (turn > 0);
                right += (turn < 0);
              }
            area /= 2;
            for (unsigned int k = 0; k < n && length > 0; ++k)
              AssertThrow(points[c.node[k]] != points[c.node[(k + 1) % n]],
                          element_error(c, element_name(c, false) + " has its nodes " +
                                             std::to_string(node_tags[c.node[k]]) + " and " +
                                             std::to_string(node_tags[c.node[(k + 1) % n]]) + " at the same point (" +
                                             node_list(c) +
                                             "): a side of length zero. Merge the two nodes or remove the cell."));
            AssertThrow(n == 3 || (left != 2 || right != 2) || length == 0,
                        element_error(c, element_name(c, false) + " crosses itself (its sides cross like a bow "
                                                                  "tie): nodes " +
                                           node_list(c) + ". List the nodes in their order around the cell."));
            AssertThrow(std::abs(area) > 1e-12 * length * length && length > 0,
                        element_error(c, element_name(c, false) + " has zero area: its nodes " + node_list(c) +
                                           (length == 0 ? " lie at one point." :
                                            n == 3      ? " lie on one line." :
                                                          " enclose no area.") +
                                           " Remove the cell or move its nodes apart."));
            AssertThrow(area > 0,
                        element_error(c, element_name(c, false) + " is clockwise (nodes " + node_list(c) +
                                           "); cells must be counter-clockwise, as gmsh writes them for a "
                                           "surface whose normal is +z. Reverse the surface in gmsh "
                                           "('Reverse Surface') or mesh it with its normal along +z."));
            std::vector<unsigned int> key(c.node.begin(), c.node.begin() + n);
            std::sort(key.begin(), key.end());
            const auto it = seen.emplace(key, i);
            AssertThrow(it.second, element_error(c, element_name(c, false) + " has the same nodes as " +
                                                      element_name(cells[it.first->second]) +
                                                      ": a cell is given twice. Remove one of them."));
          }
        for (std::size_t i = 0; i < cells.size(); ++i)
          for (unsigned int k = 0; k < cells[i].n; ++k)
            edge_cells[edge_key(cells[i].node[k], cells[i].node[(k + 1) % cells[i].n])].push_back(i);
        for (const auto &e : edge_cells)
          {
            const std::string from_to = "the edge from node " + std::to_string(node_tags[e.first.first]) +
                                        " to node " + std::to_string(node_tags[e.first.second]);
            if (e.second.size() > 2)
              {
                const Element &c = cells[e.second[2]];
                AssertThrow(false, element_error(c, from_to + " belongs to three cells: " +
                                                      element_name(cells[e.second[0]]) + ", " +
                                                      element_name(cells[e.second[1]]) + " and " + element_name(c) +
                                                      "; cells overlap there."));
              }
            if (e.second.size() == 2)
              {
                const Element &a = cells[e.second[0]], &b = cells[e.second[1]];
                AssertThrow(a.physical == b.physical || separate_parts,
                            element_error(b, element_name(a) + " (physical surface " + std::to_string(a.physical) +
                                               ") and " + element_name(b) + " (physical surface " +
                                               std::to_string(b.physical) + ") share " + from_to +
                                               ". Different physical surfaces are different bodies (material "
                                               "ids), and bodies interact through contact only: give each "
                                               "body its own nodes along the interface (separate curves in "
                                               "gmsh), put both in one physical surface, or read the parts as "
                                               "separate bodies ('Mesh/Parts as bodies = true')."));
              }
          }
      }



      // Lines with a physical tag give boundary ids: each must be an edge
      // of exactly one cell, and an edge gets one id.
      void
      GmshReader::check_lines()
      {
        std::map<std::pair<unsigned int, unsigned int>, std::size_t> seen;
        for (std::size_t i = 0; i < lines.size(); ++i)
          {
            const Element &l   = lines[i];
            const auto     key = edge_key(l.node[0], l.node[1]);
            const auto     it  = edge_cells.find(key);
            AssertThrow(it != edge_cells.end(),
                        element_error(l, element_name(l, false) + " (physical line " + std::to_string(l.physical) +
                                           ") joins the nodes " + node_list(l) +
                                           ", which are not the two ends of an edge of any cell; a boundary "
                                           "id can only go to a cell side. Is the curve meshed with other "
                                           "nodes than the surface (a missing 'Coherence', or a curve not "
                                           "part of the surface)?"));
            AssertThrow(it->second.size() == 1,
                        element_error(l, element_name(l, false) + " (physical line " + std::to_string(l.physical) +
                                           ") lies on the edge from node " + std::to_string(node_tags[key.first]) +
                                           " to node " + std::to_string(node_tags[key.second]) +
                                           " inside the mesh, between " + element_name(cells[it->second[0]]) +
                                           " and " + element_name(cells[it->second[1]]) +
                                           "; boundary ids go to boundary edges only. Remove the curve from "
                                           "the physical group (or the line from the file)."));
            const auto s = seen.emplace(key, i);
            AssertThrow(s.second || lines[s.first->second].physical == l.physical,
                        element_error(l, element_name(l, false) + " (physical line " + std::to_string(l.physical) +
                                           ") and " + element_name(lines[s.first->second]) + " (physical line " +
                                           std::to_string(lines[s.first->second].physical) +
                                           ") give the edge from node " + std::to_string(node_tags[key.first]) +
                                           " to node " + std::to_string(node_tags[key.second]) +
                                           " two boundary ids. Keep one of them."));
          }
      }
    } // namespace internal
  } // namespace MeshIO
} // namespace dealvem
