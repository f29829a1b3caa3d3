// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/rigid_body_support.h>
#include <dealvem/elasticity/piece_support.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace dealvem
{
  RigidBodySupport::RigidBodySupport(const VEMDoFHandler<2>                  &dof_handler,
                                     const dealii::AffineConstraints<double> &constraints,
                                     const ContactAssembler<2>               &contact,
                                     const bool                               tangential_stick)
    : pieces(std::make_unique<PieceSupport>(dof_handler))
  {
    const auto &mesh = dof_handler.get_mesh();
    n_body           = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      n_body = std::max<unsigned int>(n_body, mesh.cell(c).material_id + 1);
    PieceSupport::Form form;
    for (const auto &line : constraints.get_lines())
      {
        if (line.index >= dof_handler.n_dofs())
          continue;
        form.assign(1, {line.index, 1.});
        for (const auto &e : line.entries)
          form.emplace_back(e.first, -e.second);
        pieces->add_rows(form, constraint_rows);
      }
    pair_rows.resize(contact.n_pairs());
    initial_gaps.resize(contact.n_pairs());
    for (unsigned int i = 0; i < contact.n_pairs(); ++i)
      {
        const auto  d = contact.pair_dofs(i);
        const auto &p = contact.get_pairs()[i];
        initial_gaps[i] = p.initial_gap;
        for (unsigned int dir = 0; dir < (tangential_stick ? 2u : 1u); ++dir)
          {
            const auto &v = (dir == 0 ? p.normal : p.tangent);
            form      = {{d[0], -v[0]}, {d[1], -v[1]}, {d[2], v[0]}, {d[3], v[1]}};
            std::vector<PieceSupport::Row> rows;
            pieces->add_rows(form, rows);
            pair_rows[i].push_back(rows);
          }
      }
  }



  RigidBodySupport::~RigidBodySupport() = default;



  std::string
  RigidBodySupport::free_motions(const std::vector<bool> &closed) const
  {
    return free_motions(closed, closed);
  }



  std::string
  RigidBodySupport::free_motions(const std::vector<bool> &closed,
                                 const std::vector<bool> &tangential_held) const
  {
    AssertDimension(closed.size(), pair_rows.size());
    AssertDimension(tangential_held.size(), pair_rows.size());
    std::vector<const PieceSupport::Row *> rows;
    for (const auto &r : constraint_rows)
      rows.push_back(&r);
    for (unsigned int p = 0; p < pair_rows.size(); ++p)
      if (closed[p])
        for (unsigned int r = 0; r < pair_rows[p].size(); ++r)
          if (r == 0 || tangential_held[p])
            for (const auto &row : pair_rows[p][r])
              rows.push_back(&row);
    const auto motions = pieces->free_motions(rows);
    if (motions.empty())
      return "";
    std::string text = pieces->describe(motions, true);
    const std::string named = pieces->describe_pieces(motions);
    if (!named.empty())
      text += " (pieces that share no edge with the rest of their body, each to be held by its own constraints "
              "or contact; a vertex alone, a hinge, connects nothing: " + named + ")";
    // "; piece 1 of body 0 touches piece 0 at the vertex (1, 1) only: ..."
    // without its final period (the caller goes on with ". ")
    const std::string hinges = pieces->describe_hinges(motions);
    if (hinges.size() > 2)
      text += "; " + hinges.substr(1, hinges.size() - 2);
    return text;
  }



  unsigned int
  RigidBodySupport::close_smallest_gaps(std::vector<bool> &closed) const
  {
    AssertDimension(closed.size(), pair_rows.size());
    std::vector<unsigned int> order;
    double                    largest = 0;
    for (unsigned int p = 0; p < closed.size(); ++p)
      if (!closed[p])
        {
          order.push_back(p);
          largest = std::max(largest, std::abs(initial_gaps[p]));
        }
    std::stable_sort(order.begin(), order.end(),
                     [&](const unsigned int a, const unsigned int b) { return initial_gaps[a] < initial_gaps[b]; });
    unsigned int n_closed = 0;
    for (unsigned int k = 0; k < order.size() && !holds(closed);)
      {
        // close the next group of (nearly) equal gaps together
        const double g = initial_gaps[order[k]];
        while (k < order.size() && initial_gaps[order[k]] <= g + 1e-9 * largest)
          {
            closed[order[k]] = true;
            ++n_closed;
            ++k;
          }
      }
    return n_closed;
  }
} // namespace dealvem
