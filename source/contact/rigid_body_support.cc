// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/rigid_body_support.h>

#include <Eigen/Dense>

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
  {
    const auto               &mesh = dof_handler.get_mesh();
    std::vector<unsigned int> node_body(dof_handler.n_nodes(), 0), nodes;
    n_body = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        n_body = std::max<unsigned int>(n_body, mesh.cell(c).material_id + 1);
        dof_handler.get_node_indices(c, nodes);
        for (const auto n : nodes)
          node_body[n] = mesh.cell(c).material_id;
      }
    // centre and size of each body, from its vertices
    std::vector<dealii::Point<2>> centre(n_body);
    std::vector<double>           size(n_body, 1e-300), count(n_body, 0);
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      {
        centre[node_body[v]] += mesh.vertex(v);
        count[node_body[v]] += 1;
      }
    for (unsigned int b = 0; b < n_body; ++b)
      centre[b] /= std::max(count[b], 1.);
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      size[node_body[v]] = std::max(size[node_body[v]], mesh.vertex(v).distance(centre[node_body[v]]));

    const unsigned int N = 3 * n_body;
    // the value of the rigid-body modes at a DoF, times factor, added to row
    const auto add_modes = [&](const dealii::types::global_dof_index dof, const double factor,
                               std::vector<double> &row) {
      const unsigned int node = dof / 2, comp = dof % 2, b = node_body[node];
      const auto         x    = dof_handler.node_location(node) - centre[b];
      row[3 * b + comp] += factor;
      row[3 * b + 2] += factor * (comp == 0 ? -x[1] : x[0]) / size[b];
    };
    gram_constraints.assign(N * N, 0.);
    for (const auto &line : constraints.get_lines())
      {
        if (line.index >= dof_handler.n_dofs())
          continue;
        std::vector<double> row(N, 0.);
        add_modes(line.index, 1., row);
        for (const auto &e : line.entries)
          add_modes(e.first, -e.second, row);
        for (unsigned int i = 0; i < N; ++i)
          for (unsigned int j = 0; j < N; ++j)
            gram_constraints[i * N + j] += row[i] * row[j];
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
            const auto         &v = (dir == 0 ? p.normal : p.tangent);
            std::vector<double> row(N, 0.);
            add_modes(d[0], -v[0], row);
            add_modes(d[1], -v[1], row);
            add_modes(d[2], v[0], row);
            add_modes(d[3], v[1], row);
            pair_rows[i].push_back(row);
          }
      }
  }



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
    const unsigned int N = 3 * n_body;
    Eigen::MatrixXd    gram(N, N);
    for (unsigned int i = 0; i < N; ++i)
      for (unsigned int j = 0; j < N; ++j)
        gram(i, j) = gram_constraints[i * N + j];
    for (unsigned int p = 0; p < pair_rows.size(); ++p)
      if (closed[p])
        for (unsigned int r = 0; r < pair_rows[p].size(); ++r)
          if (const auto &row = pair_rows[p][r]; r == 0 || tangential_held[p])
            for (unsigned int i = 0; i < N; ++i)
              if (row[i] != 0)
                for (unsigned int j = 0; j < N; ++j)
                  gram(i, j) += row[i] * row[j];
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram);
    const double       vmax = std::max(eig.eigenvalues().maxCoeff(), 1e-300);
    std::ostringstream msg;
    const char        *names[3] = {"x-translation", "y-translation", "rotation"};
    for (unsigned int k = 0; k < N; ++k)
      if (eig.eigenvalues()(k) <= 1e-10 * vmax)
        {
          msg << (msg.tellp() > 0 ? " " : "") << "[";
          bool first = true;
          for (unsigned int j = 0; j < N; ++j)
            if (std::abs(eig.eigenvectors()(j, k)) > 1e-3)
              {
                msg << (first ? "" : " + ") << names[j % 3] << " of body " << j / 3;
                first = false;
              }
          msg << "]";
        }
    return msg.str();
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
