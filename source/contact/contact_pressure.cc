// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/contact/contact_pressure.h>

#include <cmath>
#include <map>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace dealvem
{
  namespace ContactPressure
  {
    std::vector<double>
    lumped(const NodeInsertion::Interface &interface, const std::vector<double> &force)
    {
      AssertDimension(force.size(), interface.pairs.size());
      std::vector<double> p(force.size(), 0.);
      for (unsigned int i = 0; i < force.size(); ++i)
        if (interface.pairs[i].weight > 0)
          p[i] = force[i] / interface.pairs[i].weight;
      return p;
    }



    std::vector<double>
    consistent(const NodeInsertion::Interface &interface,
               const std::vector<double>      &force,
               const std::vector<bool>        &active)
    {
      const unsigned int n = interface.pairs.size();
      AssertDimension(force.size(), n);
      Assert(active.empty() || active.size() == n, dealii::ExcDimensionMismatch(active.size(), n));
      // an open pair carries no pressure: its row and column become p_i = 0
      const auto open = [&](const unsigned int i) { return !active.empty() && !active[i]; };
      std::vector<Eigen::Triplet<double>> entries;
      std::vector<bool>                   on_segment(n, false);
      for (const auto &s : interface.segments)
        {
          const double L = s.length;
          if (s.midpoint == dealii::numbers::invalid_unsigned_int)
            {
              // P1: L/6 [2 1; 1 2]
              const unsigned int idx[2] = {s.first, s.second};
              for (unsigned int a = 0; a < 2; ++a)
                for (unsigned int b = 0; b < 2; ++b)
                  if (!open(idx[a]) && !open(idx[b]))
                    entries.emplace_back(idx[a], idx[b], L / 6. * (a == b ? 2. : 1.));
            }
          else
            {
              // P2 with nodes (end, end, midpoint): L/30 [4 -1 2; -1 4 2; 2 2 16]
              const unsigned int idx[3]     = {s.first, s.second, s.midpoint};
              const double       M[3][3]    = {{4, -1, 2}, {-1, 4, 2}, {2, 2, 16}};
              for (unsigned int a = 0; a < 3; ++a)
                for (unsigned int b = 0; b < 3; ++b)
                  if (!open(idx[a]) && !open(idx[b]))
                    entries.emplace_back(idx[a], idx[b], L / 30. * M[a][b]);
            }
          on_segment[s.first] = on_segment[s.second] = true;
          if (s.midpoint != dealii::numbers::invalid_unsigned_int)
            on_segment[s.midpoint] = true;
        }
      // pairs on no segment keep the lumped value (unit row)
      for (unsigned int i = 0; i < n; ++i)
        if (open(i))
          entries.emplace_back(i, i, 1.);
        else if (!on_segment[i])
          entries.emplace_back(i, i, interface.pairs[i].weight > 0 ? interface.pairs[i].weight : 1.);
      Eigen::SparseMatrix<double> M(n, n);
      M.setFromTriplets(entries.begin(), entries.end());
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(M);
      AssertThrow(solver.info() == Eigen::Success,
                  dealii::ExcInternalError("contact pressure: the interface mass matrix of interface " +
                                           std::to_string(interface.index) + " could not be factorized."));
      Eigen::VectorXd f(n);
      for (unsigned int i = 0; i < n; ++i)
        f(i) = open(i) ? 0. : force[i];
      const Eigen::VectorXd p = solver.solve(f);
      return std::vector<double>(p.data(), p.data() + n);
    }



    std::vector<double>
    recover(const NodeInsertion::Interface &interface,
            const std::vector<double>      &force,
            const std::vector<bool>        &active,
            const unsigned int              patch_segments,
            const unsigned int              fit_degree)
    {
      const unsigned int n = interface.pairs.size();
      AssertDimension(force.size(), n);
      const auto open = [&](const unsigned int i) { return !active.empty() && !active[i]; };
      constexpr unsigned int invalid = dealii::numbers::invalid_unsigned_int;

      // segments at each vertex pair, and the arc length of every pair
      // along its chain of segments (chains follow the slave side)
      std::vector<std::vector<unsigned int>> at(n);
      for (unsigned int s = 0; s < interface.segments.size(); ++s)
        {
          at[interface.segments[s].first].push_back(s);
          at[interface.segments[s].second].push_back(s);
          if (interface.segments[s].midpoint != invalid)
            at[interface.segments[s].midpoint].push_back(s);
        }
      std::vector<double> p = lumped(interface, force);
      for (unsigned int i = 0; i < n; ++i)
        if (open(i))
          p[i] = 0;

      // Gauss points on [0, 1] (exact for degree 5)
      const double gx[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
      const double gw[3] = {5. / 18, 8. / 18, 5. / 18};

      for (unsigned int i = 0; i < n; ++i)
        {
          if (open(i) || at[i].empty())
            continue;
          // the patch: the segments that contain node i, and those reached
          // from them in at most patch_segments steps through closed vertex
          // pairs, with the arc length of their start relative to node i.
          // It grows from all segments at i at once, so that it reaches
          // equally far to both sides (a mirror-symmetric problem gives a
          // mirror-symmetric recovery).
          std::map<unsigned int, double> seg_start; // segment -> s at its 'first' end
          {
            std::vector<unsigned int> frontier;
            for (const unsigned int s : at[i])
              {
                const auto &seg = interface.segments[s];
                // position of node i inside this segment
                const double s_i  = (i == seg.second ? seg.length : (i == seg.midpoint ? 0.5 * seg.length : 0.));
                seg_start[s]      = -s_i;
                frontier.push_back(s);
              }
            for (unsigned int step = 0; step < patch_segments; ++step)
              {
                std::vector<unsigned int> next;
                for (const unsigned int s : frontier)
                  {
                    const auto &seg = interface.segments[s];
                    for (const unsigned int end : {seg.first, seg.second})
                      {
                        if (open(end))
                          continue;
                        const double s_end = seg_start[s] + (end == seg.second ? seg.length : 0.);
                        for (const unsigned int t : at[end])
                          if (seg_start.count(t) == 0 && (interface.segments[t].first == end ||
                                                          interface.segments[t].second == end))
                            {
                              const auto &tseg = interface.segments[t];
                              seg_start[t] = (tseg.first == end ? s_end : s_end - tseg.length);
                              next.push_back(t);
                            }
                      }
                  }
                frontier = next;
              }
          }
          // rows: closed nodes of the patch segments; b_j(alpha) = int s^alpha phi_j
          std::map<unsigned int, std::vector<double>> rows;
          const unsigned int degree = std::min(fit_degree, 4u);
          for (const auto &ss : seg_start)
            {
              const auto        &seg   = interface.segments[ss.first];
              const bool         quad  = (seg.midpoint != invalid);
              const unsigned int nodes[3] = {seg.first, seg.second, seg.midpoint};
              for (unsigned int q = 0; q < 3; ++q)
                {
                  const double t = gx[q], s = ss.second + t * seg.length, w = gw[q] * seg.length;
                  double       phi[3];
                  if (quad)
                    {
                      phi[0] = (1 - t) * (1 - 2 * t);
                      phi[1] = t * (2 * t - 1);
                      phi[2] = 4 * t * (1 - t);
                    }
                  else
                    {
                      phi[0] = 1 - t;
                      phi[1] = t;
                      phi[2] = 0;
                    }
                  for (unsigned int a = 0; a < (quad ? 3u : 2u); ++a)
                    {
                      auto &row = rows[nodes[a]];
                      row.resize(degree + 1, 0.);
                      double sp = 1;
                      for (unsigned int d = 0; d <= degree; ++d, sp *= s)
                        row[d] += w * phi[a] * sp;
                    }
                }
            }
          // a node is a full row only if all its segments are in the patch
          std::vector<unsigned int> use;
          for (const auto &r : rows)
            {
              bool complete = !open(r.first);
              for (const unsigned int t : at[r.first])
                complete = complete && seg_start.count(t);
              if (complete)
                use.push_back(r.first);
            }
          unsigned int fit = std::min<unsigned int>(degree, use.size() > 0 ? use.size() - 1 : 0);
          Eigen::MatrixXd A(use.size(), fit + 1);
          Eigen::VectorXd b(use.size());
          // scale the monomials by the patch size for conditioning
          double size = 0;
          for (const auto &ss : seg_start)
            size = std::max({size, std::abs(ss.second), std::abs(ss.second + interface.segments[ss.first].length)});
          for (unsigned int r = 0; r < use.size(); ++r)
            {
              for (unsigned int d = 0; d <= fit; ++d)
                A(r, d) = rows[use[r]][d] / std::pow(size, d);
              b(r) = force[use[r]];
            }
          if (use.size() == 0)
            continue;
          const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
          p[i] = c(0);
        }
      return p;
    }
  } // namespace ContactPressure
} // namespace dealvem
