// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/mesh/connected_pieces.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

namespace dealvem
{
  ConnectedPieces::ConnectedPieces(const PolygonalMesh<2> &mesh)
  {
    const unsigned int        n_cells = mesh.n_cells();
    std::vector<unsigned int> parent(n_cells);
    std::iota(parent.begin(), parent.end(), 0u);
    const auto find = [&parent](unsigned int c) {
      while (parent[c] != c)
        {
          parent[c] = parent[parent[c]];
          c         = parent[c];
        }
      return c;
    };
    // an interior edge joins its two cells; a shared vertex joins nothing
    for (const auto &e : mesh.get_edges())
      if (!e.at_boundary())
        {
          const unsigned int a = find(e.cells[0]), b = find(e.cells[1]);
          if (a != b)
            parent[std::max(a, b)] = std::min(a, b);
        }
    // pieces numbered in the order of their lowest cell
    cell_piece.assign(n_cells, dealii::numbers::invalid_unsigned_int);
    std::vector<unsigned int> root_piece(n_cells, dealii::numbers::invalid_unsigned_int);
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        const unsigned int r = find(c);
        if (root_piece[r] == dealii::numbers::invalid_unsigned_int)
          {
            root_piece[r] = cells_in_piece.size();
            cells_in_piece.push_back(0);
            piece_first_cell.push_back(c);
            piece_body.push_back(mesh.cell(c).material_id);
          }
        cell_piece[c] = root_piece[r];
        ++cells_in_piece[cell_piece[c]];
      }
    const unsigned int n = cells_in_piece.size();
    piece_index_in_body.resize(n);
    {
      std::map<dealii::types::material_id, unsigned int> count;
      for (unsigned int p = 0; p < n; ++p)
        piece_index_in_body[p] = count[piece_body[p]]++;
    }
    // the first cell's index among the cells of its body (the cell number
    // in the body's own mesh file)
    piece_first_cell_in_body.assign(n, 0);
    {
      std::map<dealii::types::material_id, unsigned int> count;
      unsigned int                                       p = 0;
      for (unsigned int c = 0; c < n_cells && p < n; ++c)
        {
          const auto id = mesh.cell(c).material_id;
          while (p < n && piece_first_cell[p] < c)
            ++p;
          if (p < n && piece_first_cell[p] == c)
            piece_first_cell_in_body[p] = count[id];
          ++count[id];
        }
    }

    // area centroid (shoelace formula per cell), bounding box, size
    std::vector<double> area(n, 0.);
    piece_centroid.assign(n, dealii::Point<2>());
    piece_box.assign(n, {dealii::Point<2>(1e300, 1e300), dealii::Point<2>(-1e300, -1e300)});
    std::vector<dealii::Point<2>> mean(n);
    std::vector<double>           n_vertices(n, 0.);
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        const unsigned int p  = cell_piece[c];
        const auto        &vs = mesh.cell(c).vertices;
        for (unsigned int i = 0; i < vs.size(); ++i)
          {
            const auto  &x0 = mesh.vertex(vs[i]);
            const auto  &x1 = mesh.vertex(vs[(i + 1) % vs.size()]);
            const double cross = x0[0] * x1[1] - x1[0] * x0[1];
            area[p] += 0.5 * cross;
            piece_centroid[p][0] += (x0[0] + x1[0]) * cross / 6.;
            piece_centroid[p][1] += (x0[1] + x1[1]) * cross / 6.;
            for (unsigned int d = 0; d < 2; ++d)
              {
                piece_box[p].first[d]  = std::min(piece_box[p].first[d], x0[d]);
                piece_box[p].second[d] = std::max(piece_box[p].second[d], x0[d]);
              }
            mean[p] += x0;
            n_vertices[p] += 1;
          }
      }
    for (unsigned int p = 0; p < n; ++p)
      {
        // a piece of (numerically) zero area keeps its vertex mean
        if (std::abs(area[p]) > 0)
          piece_centroid[p] /= area[p];
        else
          piece_centroid[p] = mean[p] / std::max(n_vertices[p], 1.);
      }
    piece_size.assign(n, 0.);
    for (unsigned int c = 0; c < n_cells; ++c)
      for (const auto v : mesh.cell(c).vertices)
        piece_size[cell_piece[c]] =
          std::max(piece_size[cell_piece[c]], mesh.vertex(v).distance(piece_centroid[cell_piece[c]]));
    for (auto &s : piece_size)
      s = std::max(s, 1e-300);
  }



  unsigned int
  ConnectedPieces::n_pieces_of_body(const dealii::types::material_id b) const
  {
    return std::count(piece_body.begin(), piece_body.end(), b);
  }



  std::string
  ConnectedPieces::describe(const unsigned int p) const
  {
    std::ostringstream s;
    s.precision(6);
    s << "piece " << piece_index_in_body[p] << " of body " << int(piece_body[p]) << " (" << cells_in_piece[p]
      << (cells_in_piece[p] == 1 ? " cell" : " cells") << "; cell " << piece_first_cell_in_body[p] << ", centroid ("
      << piece_centroid[p][0] << ", " << piece_centroid[p][1] << "); bounding box [" << piece_box[p].first[0]
      << ", " << piece_box[p].second[0] << "] x [" << piece_box[p].first[1] << ", " << piece_box[p].second[1]
      << "])";
    return s.str();
  }
} // namespace dealvem
