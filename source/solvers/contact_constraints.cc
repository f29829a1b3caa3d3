// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/solvers/contact_constraints.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

namespace dealvem
{
  namespace
  {
    std::string
    to_string(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    /// One slave line during the elimination: u_slave = sum a_j u_j + c,
    /// and the constraint rows it was combined from.
    struct Line
    {
      unsigned int                    slave;
      std::map<unsigned int, double>  entries;
      double                          inhomogeneity = 0;
      double                          scale         = 0; ///< sum of |values| that entered c
      std::set<unsigned int>          rows;
    };
  } // namespace



  ContactConstraints
  ContactConstraints::tie_lines(const std::vector<std::vector<std::pair<unsigned int, double>>> &stick_rows,
                            const dealii::AffineConstraints<double>                           &normal_lines,
                            const dealii::AffineConstraints<double>                           &excluded,
                            const unsigned int                                                n,
                            const double                                                      length)
  {
    // the spring directions in terms of DoFs that are not normal slaves
    std::vector<std::vector<std::pair<unsigned int, double>>> rows;
    for (const auto &r : stick_rows)
      {
        std::map<unsigned int, double> row;
        for (const auto &e : r)
          if (normal_lines.is_constrained(e.first))
            {
              for (const auto &l : *normal_lines.get_constraint_entries(e.first))
                row[l.first] += e.second * l.second;
            }
          else
            row[e.first] += e.second;
        std::vector<std::pair<unsigned int, double>> reduced;
        for (const auto &x : row)
          if (x.second != 0.)
            reduced.emplace_back(x.first, x.second);
        if (!reduced.empty())
          rows.push_back(std::move(reduced));
      }
    // the tie lines: ContactConstraints on a saddle matrix that holds
    // only the tie rows (zero right-hand side: Z is homogeneous)
    const unsigned int        m = rows.size();
    std::vector<unsigned int> row_length(n + m, 1);
    for (const auto &r : rows)
      for (const auto &e : r)
        ++row_length[e.first];
    for (unsigned int k = 0; k < m; ++k)
      row_length[n + k] += rows[k].size();
    dealii::SparsityPattern ties_pattern(n + m, n + m, row_length);
    for (unsigned int k = 0; k < m; ++k)
      for (const auto &e : rows[k])
        {
          ties_pattern.add(n + k, e.first);
          ties_pattern.add(e.first, n + k);
        }
    ties_pattern.compress();
    dealii::SparseMatrix<double> T(ties_pattern);
    for (unsigned int k = 0; k < m; ++k)
      for (const auto &e : rows[k])
        {
          T.set(n + k, e.first, e.second);
          T.set(e.first, n + k, e.second);
        }
    ContactConstraints ties;
    ties.reinit(T, n, dealii::Vector<double>(n + m), length, 1e-10, &excluded);
    return ties;
  }



  void
  ContactConstraints::reinit(const dealii::SparseMatrix<double> &A,
                             const unsigned int                  n_displacements,
                             const dealii::Vector<double>       &b,
                             const double                        length_scale,
                             const double                        dependency_tolerance,
                             const dealii::AffineConstraints<double> *displacement_constraints)
  {
    AssertThrow(A.m() == A.n() && A.m() == b.size() && n_displacements <= A.m(),
                dealii::ExcMessage("ContactConstraints: the saddle-point matrix must be square, of the size of "
                                   "the right-hand side, with at most that many displacements."));
    n = n_displacements;
    m = A.m() - n;
    constraints.clear();
    constraint_rows.clear();
    dependent_rows.clear();
    slaves.clear();
    inactive.clear();

    // the columns of B^T, from the displacement rows
    std::vector<std::vector<std::pair<unsigned int, double>>> bt(m);
    for (unsigned int i = 0; i < n; ++i)
      for (auto it = A.begin(i); it != A.end(i); ++it)
        if (it->column() >= n && it->value() != 0.)
          bt[it->column() - n].emplace_back(i, it->value());

    // classify the multiplier rows
    std::vector<std::vector<std::pair<unsigned int, double>>> rows(m);
    for (unsigned int r = 0; r < m; ++r)
      {
        const unsigned int i        = n + r;
        double             diagonal = 0, off_diagonal = 0, bmax = 0;
        for (auto it = A.begin(i); it != A.end(i); ++it)
          {
            const auto j = it->column();
            if (it->value() == 0.)
              continue;
            if (j < n)
              {
                rows[r].emplace_back(j, it->value());
                bmax = std::max(bmax, std::abs(it->value()));
              }
            else if (j == i)
              diagonal = it->value();
            else
              off_diagonal = std::max(off_diagonal, std::abs(it->value()));
          }
        std::sort(rows[r].begin(), rows[r].end());
        const std::string which = "multiplier row " + std::to_string(r) + " (unknown " + std::to_string(i) + ")";
        AssertThrow(off_diagonal == 0.,
                    dealii::ExcMessage("Condensed contact constraints: " + which +
                                       " couples multipliers with each other (as the slip rows of Coulomb friction "
                                       "do): the system is not a set of linear constraints on a symmetric problem. "
                                       "Use the UMFPACK, KLU or GMRES-AMG contact solver."));
        if (rows[r].empty())
          {
            AssertThrow(diagonal != 0.,
                        dealii::ExcMessage("Condensed contact constraints: " + which +
                                           " is zero: the saddle-point matrix is singular."));
            inactive.emplace_back(r, b[i] / diagonal);
            continue;
          }
        AssertThrow(diagonal == 0.,
                    dealii::ExcMessage("Condensed contact constraints: " + which +
                                       " has both displacement entries and a diagonal entry: not a constraint row."));
        bool symmetric = (bt[r].size() == rows[r].size());
        for (unsigned int k = 0; symmetric && k < rows[r].size(); ++k)
          symmetric = (bt[r][k].first == rows[r][k].first &&
                       std::abs(bt[r][k].second - rows[r][k].second) <= 1e-12 * bmax);
        AssertThrow(symmetric,
                    dealii::ExcMessage("Condensed contact constraints: the force column of " + which +
                                       " is not the constraint row (a non-symmetric coupling, as the slip rows of "
                                       "Coulomb friction give). Use the UMFPACK, KLU or GMRES-AMG contact solver."));
        constraint_rows.push_back(r);
      }
    bt.clear();

    // a DoF can be a slave if its row of K couples to other DoFs (DoFs
    // condensed by the displacement constraints have decoupled rows)
    const auto eligible = [&](const unsigned int j) {
      if (displacement_constraints != nullptr)
        return !displacement_constraints->is_constrained(j);
      for (auto it = A.begin(j); it != A.end(j); ++it)
        if (it->column() < n && it->column() != j && it->value() != 0.)
          return true;
      return false;
    };

    // Gauss-Jordan elimination with partial pivoting per row
    std::vector<Line>                                          lines;
    std::unordered_map<unsigned int, unsigned int>             line_of; // slave DoF -> line
    std::unordered_map<unsigned int, std::vector<unsigned int>> users;  // DoF -> lines containing it
    const double                                               abs_floor = 1e-12 * length_scale;
    for (const unsigned int r : constraint_rows)
      {
        std::map<unsigned int, double> row;
        double                         rhs = b[n + r], scale = std::abs(b[n + r]), norm = 0;
        std::set<unsigned int>         origin;
        for (const auto &e : rows[r])
          {
            norm          = std::max(norm, std::abs(e.second));
            const auto li = line_of.find(e.first);
            if (li == line_of.end())
              row[e.first] += e.second;
            else
              {
                const Line &l = lines[li->second];
                for (const auto &le : l.entries)
                  row[le.first] += e.second * le.second;
                rhs -= e.second * l.inhomogeneity;
                scale += std::abs(e.second) * (std::abs(l.inhomogeneity) + l.scale);
                origin.insert(l.rows.begin(), l.rows.end());
              }
          }
        unsigned int pivot = dealii::numbers::invalid_unsigned_int;
        double       best  = 0;
        for (const auto &e : row)
          if (std::abs(e.second) > best && eligible(e.first))
            {
              best  = std::abs(e.second);
              pivot = e.first;
            }
        if (best <= dependency_tolerance * norm)
          {
            std::string on;
            for (const auto o : origin)
              on += (on.empty() ? "" : ", ") + std::to_string(o);
            AssertThrow(std::abs(rhs) <= 1e-10 * scale + abs_floor,
                        dealii::ExcMessage(
                          "Inconsistent redundant contact constraints: multiplier row " + std::to_string(r) +
                          " is a linear combination of the constraint rows {" + on +
                          "} (ContactAssembler numbers the normal constraint of pair i as row i and the "
                          "tangential one, if any, as row n_pairs + i; the rows include the Dirichlet/roller constraints condensed into them), but its "
                          "right-hand side differs from theirs by " + to_string(rhs) + " (values of size " +
                          to_string(scale) + " entered it): the contact gaps and the prescribed displacements "
                          "cannot all hold. Check the Dirichlet, roller and point constraints on the nodes of "
                          "these contact pairs."));
            dependent_rows.push_back(r);
            continue;
          }
        // the new line u_p = (rhs - sum_{j != p} row_j u_j) / row_p
        Line l;
        l.slave             = pivot;
        const double a      = row[pivot];
        l.inhomogeneity     = rhs / a;
        l.scale             = scale / std::abs(a);
        l.rows              = origin;
        l.rows.insert(r);
        for (const auto &e : row)
          if (e.first != pivot && e.second != 0.)
            l.entries[e.first] = -e.second / a;
        // substitute it into the lines that use the pivot
        const auto us = users.find(pivot);
        if (us != users.end())
          {
            // (the loop adds to users: take the list out first)
            const std::vector<unsigned int> targets = std::move(us->second);
            users.erase(us);
            for (const auto t : targets)
              {
                Line      &lt = lines[t];
                const auto pe = lt.entries.find(pivot);
                if (pe == lt.entries.end())
                  continue;
                const double c = pe->second;
                lt.entries.erase(pe);
                for (const auto &e : l.entries)
                  {
                    double &v = lt.entries[e.first];
                    v += c * e.second;
                    users[e.first].push_back(t);
                  }
                lt.inhomogeneity += c * l.inhomogeneity;
                lt.scale += std::abs(c) * (std::abs(l.inhomogeneity) + l.scale);
                lt.rows.insert(l.rows.begin(), l.rows.end());
                for (auto it = lt.entries.begin(); it != lt.entries.end();)
                  it = (it->second == 0. ? lt.entries.erase(it) : std::next(it));
              }
          }
        const unsigned int index = lines.size();
        for (const auto &e : l.entries)
          users[e.first].push_back(index);
        line_of[pivot] = index;
        lines.push_back(std::move(l));
        slaves.emplace_back(r, pivot);
      }

    for (const auto &l : lines)
      {
        constraints.add_line(l.slave);
        for (const auto &e : l.entries)
          constraints.add_entry(l.slave, e.first, e.second);
        constraints.set_inhomogeneity(l.slave, l.inhomogeneity);
      }
    constraints.close();
  }



  void
  ContactConstraints::condense(const dealii::SparseMatrix<double> &A,
                               const dealii::Vector<double>       &b,
                               dealii::SparsityPattern            &sparsity,
                               dealii::SparseMatrix<double>       &K,
                               dealii::Vector<double>             &f) const
  {
    AssertDimension(A.m(), n + m);
    // multiplier values of the inactive rows (their forces go to the rhs)
    std::vector<double> lambda(m, 0.);
    std::vector<bool>   known(m, false);
    for (const auto &in : inactive)
      {
        lambda[in.first] = in.second;
        known[in.first]  = true;
      }

    // the master DoFs of each slave, and the slaves of each master
    std::vector<const std::vector<std::pair<dealii::types::global_dof_index, double>> *> line(n, nullptr);
    std::unordered_map<unsigned int, std::vector<unsigned int>>                          slaves_of;
    for (const auto &s : slaves)
      {
        line[s.second] = constraints.get_constraint_entries(s.second);
        for (const auto &e : *line[s.second])
          slaves_of[e.first].push_back(s.second);
      }

    // fill-in: a row coupled to a slave couples to its masters; a master
    // row gets the couplings of its slaves' rows
    std::unordered_map<unsigned int, std::vector<unsigned int>> extra;
    const auto add_row_of = [&](const unsigned int target, const unsigned int s) {
      auto &x = extra[target];
      for (auto it = A.begin(s); it != A.end(s); ++it)
        {
          const auto j = it->column();
          if (j >= n)
            continue;
          if (line[j] == nullptr)
            x.push_back(j);
          else
            for (const auto &e : *line[j])
              x.push_back(e.first);
        }
    };
    for (const auto &s : slaves)
      {
        for (auto it = A.begin(s.second); it != A.end(s.second); ++it)
          {
            const auto i = it->column();
            if (i < n && line[i] == nullptr)
              for (const auto &e : *line[s.second])
                extra[i].push_back(e.first);
          }
        for (const auto &e : *line[s.second])
          add_row_of(e.first, s.second);
      }
    for (auto &x : extra)
      {
        std::sort(x.second.begin(), x.second.end());
        x.second.erase(std::unique(x.second.begin(), x.second.end()), x.second.end());
      }

    const dealii::SparsityPattern &sp = A.get_sparsity_pattern();
    std::vector<unsigned int>      row_length(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        unsigned int c = 0;
        for (auto it = sp.begin(i); it != sp.end(i); ++it)
          c += (it->column() < n);
        const auto x  = extra.find(i);
        row_length[i] = c + (x == extra.end() ? 0 : x->second.size());
      }
    sparsity.reinit(n, n, row_length);
    std::vector<dealii::types::global_dof_index> cols;
    for (unsigned int i = 0; i < n; ++i)
      {
        cols.clear();
        for (auto it = sp.begin(i); it != sp.end(i); ++it)
          if (it->column() < n)
            cols.push_back(it->column());
        const auto x = extra.find(i);
        if (x != extra.end())
          cols.insert(cols.end(), x->second.begin(), x->second.end());
        sparsity.add_entries(i, cols.begin(), cols.end(), x == extra.end());
      }
    sparsity.compress();

    // copy K: both rows list the diagonal first and then ascending columns,
    // and the new row contains the old one
    K.reinit(sparsity);
    f.reinit(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        f[i]    = b[i];
        auto kt = K.begin(i);
        for (auto it = A.begin(i); it != A.end(i); ++it)
          {
            const auto j = it->column();
            if (j >= n)
              {
                if (known[j - n])
                  f[i] -= it->value() * lambda[j - n];
                continue;
              }
            while (kt->column() != j)
              ++kt;
            kt->value() = it->value();
          }
      }
    constraints.condense(K, f);
  }



  void
  ContactConstraints::distribute_and_recover_multipliers(const dealii::SparseMatrix<double> &A,
                                                         const dealii::Vector<double>       &b,
                                                         dealii::Vector<double>             &x) const
  {
    AssertDimension(x.size(), n + m);
    dealii::Vector<double> u(n);
    for (unsigned int i = 0; i < n; ++i)
      u[i] = x[i];
    constraints.distribute(u);
    for (unsigned int i = 0; i < n; ++i)
      x[i] = u[i];
    std::vector<bool> known(m, false);
    for (unsigned int r = 0; r < m; ++r)
      x[n + r] = 0;
    for (const auto &in : inactive)
      {
        x[n + in.first] = in.second;
        known[in.first] = true;
      }
    if (constraint_rows.empty())
      return;

    // residual on the slave rows, and the matrix B_{.S}^T (slave rows x
    // enforced multipliers)
    const unsigned int  n_s = slaves.size(), n_c = constraint_rows.size();
    std::vector<int>    column(m, -1);
    for (unsigned int k = 0; k < n_c; ++k)
      column[constraint_rows[k]] = k;
    dealii::Vector<double>                                    r(n_s);
    std::vector<std::vector<std::pair<unsigned int, double>>> M(n_s);
    for (unsigned int k = 0; k < n_s; ++k)
      {
        const unsigned int s = slaves[k].second;
        double             v = b[s];
        for (auto it = A.begin(s); it != A.end(s); ++it)
          {
            const auto j = it->column();
            if (j < n)
              v -= it->value() * u[j];
            else if (known[j - n])
              v -= it->value() * x[j];
            else if (column[j - n] >= 0 && it->value() != 0.)
              M[k].emplace_back(column[j - n], it->value());
          }
        r[k] = v;
      }

    dealii::DynamicSparsityPattern dsp(n_s, n_s);
    dealii::SparsityPattern        sp;
    dealii::SparseMatrix<double>   G;
    dealii::Vector<double>         y(n_s);
    if (n_s == n_c)
      {
        // square: B_{.S}^T lambda = r_S
        for (unsigned int k = 0; k < n_s; ++k)
          for (const auto &e : M[k])
            dsp.add(k, e.first);
        sp.copy_from(dsp);
        G.reinit(sp);
        for (unsigned int k = 0; k < n_s; ++k)
          for (const auto &e : M[k])
            G.add(k, e.first, e.second);
      }
    else
      {
        // minimum norm: lambda = M^T (M M^T)^{-1} r_S
        std::vector<std::vector<std::pair<unsigned int, double>>> by_column(n_c);
        for (unsigned int k = 0; k < n_s; ++k)
          for (const auto &e : M[k])
            by_column[e.first].emplace_back(k, e.second);
        for (const auto &c : by_column)
          for (const auto &p : c)
            for (const auto &q : c)
              dsp.add(p.first, q.first);
        sp.copy_from(dsp);
        G.reinit(sp);
        for (const auto &c : by_column)
          for (const auto &p : c)
            for (const auto &q : c)
              G.add(p.first, q.first, p.second * q.second);
      }
    dealii::SparseDirectUMFPACK direct;
    direct.initialize(G);
    direct.vmult(y, r);
    if (n_s == n_c)
      for (unsigned int k = 0; k < n_c; ++k)
        x[n + constraint_rows[k]] = y[k];
    else
      for (unsigned int k = 0; k < n_s; ++k)
        for (const auto &e : M[k])
          x[n + constraint_rows[e.first]] += e.second * y[k];
  }
} // namespace dealvem
