// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/base/number_string.h>
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



  namespace
  {
    /// The lines of a Gauss-Jordan elimination: every line in terms of DoFs
    /// that are not slaves.
    struct Elimination
    {
      std::vector<Line>                                           lines;
      std::unordered_map<unsigned int, unsigned int>              line_of; // slave DoF -> line
      std::unordered_map<unsigned int, std::vector<unsigned int>> users;   // DoF -> lines containing it

      /// @p row with the slaves so far substituted; the value subtracted
      /// from the right-hand side, its scale and the rows it came from.
      void
      reduce(const std::vector<std::pair<unsigned int, double>> &row,
             std::map<unsigned int, double>                     &reduced,
             double                                             &rhs,
             double                                             &scale,
             std::set<unsigned int>                             &origin) const
      {
        for (const auto &e : row)
          {
            const auto li = line_of.find(e.first);
            if (li == line_of.end())
              reduced[e.first] += e.second;
            else
              {
                const Line &l = lines[li->second];
                for (const auto &le : l.entries)
                  reduced[le.first] += e.second * le.second;
                rhs -= e.second * l.inhomogeneity;
                scale += std::abs(e.second) * (std::abs(l.inhomogeneity) + l.scale);
                origin.insert(l.rows.begin(), l.rows.end());
              }
          }
      }

      /// Add the line u_p = (rhs - sum_{j != p} row_j u_j) / row_p and
      /// substitute it into the lines that use the pivot p.
      void
      add(const std::map<unsigned int, double> &row,
          const unsigned int                    pivot,
          const double                          rhs,
          const double                          scale,
          std::set<unsigned int>                origin)
      {
        Line         l;
        l.slave         = pivot;
        const double a  = row.at(pivot);
        l.inhomogeneity = rhs / a;
        l.scale         = scale / std::abs(a);
        l.rows          = std::move(origin);
        for (const auto &e : row)
          if (e.first != pivot && e.second != 0.)
            l.entries[e.first] = -e.second / a;
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
                    lt.entries[e.first] += c * e.second;
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
      }
    };
  } // namespace



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
    test_constraints.clear();
    test_lines.clear();
    constraint_rows.clear();
    dependent_rows.clear();
    slaves.clear();
    inactive.clear();
    tied.clear();
    symmetric = true;

    // the columns of B^T, from the displacement rows
    std::vector<std::vector<std::pair<unsigned int, double>>> bt(m);
    for (unsigned int i = 0; i < n; ++i)
      for (auto it = A.begin(i); it != A.end(i); ++it)
        if (it->column() >= n && it->value() != 0.)
          bt[it->column() - n].emplace_back(i, it->value());

    // classify the multiplier rows: constraint rows (displacement entries,
    // no D entries), known rows (diagonal only) and tied rows (diagonal and
    // couplings to other multipliers)
    std::vector<std::vector<std::pair<unsigned int, double>>> rows(m), couplings(m);
    std::vector<double>                                       diagonal(m, 0.), bmax(m, 0.);
    for (unsigned int r = 0; r < m; ++r)
      {
        const unsigned int i = n + r;
        for (auto it = A.begin(i); it != A.end(i); ++it)
          {
            const auto j = it->column();
            if (it->value() == 0.)
              continue;
            if (j < n)
              {
                rows[r].emplace_back(j, it->value());
                bmax[r] = std::max(bmax[r], std::abs(it->value()));
              }
            else if (j == i)
              diagonal[r] = it->value();
            else
              couplings[r].emplace_back(j - n, it->value());
          }
        std::sort(rows[r].begin(), rows[r].end());
        const std::string which = "multiplier row " + std::to_string(r) + " (unknown " + std::to_string(i) + ")";
        if (rows[r].empty())
          {
            AssertThrow(diagonal[r] != 0.,
                        dealii::ExcMessage("Condensed contact constraints: " + which +
                                           (couplings[r].empty() ? " is zero" : " has no diagonal entry") +
                                           ": the saddle-point matrix is singular."));
          }
        else
          {
            AssertThrow(diagonal[r] == 0. && couplings[r].empty(),
                        dealii::ExcMessage("Condensed contact constraints: " + which +
                                           " has both displacement entries and entries of the multiplier block: "
                                           "not a constraint row."));
          }
      }
    std::vector<double> known(m, 0.);
    std::vector<bool>   is_known(m, false);
    for (unsigned int r = 0; r < m; ++r)
      if (rows[r].empty() && couplings[r].empty())
        {
          known[r]    = b[n + r] / diagonal[r];
          is_known[r] = true;
          inactive.emplace_back(r, known[r]);
        }
    // the test columns: B^T's own, plus the columns of the tied multipliers
    // that depend on it (a slipping pair's friction force -mu sigma lambda_n
    // acts along the tangent)
    std::vector<std::map<unsigned int, double>> test(m);
    for (unsigned int r = 0; r < m; ++r)
      if (!rows[r].empty())
        for (const auto &e : bt[r])
          test[r][e.first] += e.second;
    for (unsigned int r = 0; r < m; ++r)
      if (rows[r].empty() && !couplings[r].empty())
        {
          Tied t;
          t.row   = r;
          t.value = b[n + r] / diagonal[r];
          for (const auto &c : couplings[r])
            {
              const double factor = -c.second / diagonal[r];
              if (is_known[c.first])
                t.value += factor * known[c.first];
              else
                {
                  AssertThrow(!rows[c.first].empty(),
                              dealii::ExcMessage("Condensed contact constraints: multiplier row " +
                                                 std::to_string(r) + " couples to the multiplier of row " +
                                                 std::to_string(c.first) +
                                                 ", which is itself coupled to further multipliers: only one "
                                                 "level of multiplier couplings (a friction force proportional "
                                                 "to a normal force) can be condensed."));
                  t.entries.emplace_back(c.first, factor);
                  for (const auto &e : bt[r])
                    test[c.first][e.first] += factor * e.second;
                }
            }
          tied.push_back(std::move(t));
        }
    std::vector<bool> row_symmetric(m, true);
    for (unsigned int r = 0; r < m; ++r)
      if (!rows[r].empty())
        {
          bool same = (test[r].size() == rows[r].size());
          auto te   = test[r].begin();
          for (unsigned int k = 0; same && k < rows[r].size(); ++k, ++te)
            same = (te->first == rows[r][k].first && std::abs(te->second - rows[r][k].second) <= 1e-12 * bmax[r]);
          row_symmetric[r] = same;
          symmetric        = symmetric && same;
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

    // Gauss-Jordan elimination with partial pivoting per row; with
    // non-symmetric rows the test rows are eliminated alongside with the
    // same slaves (Petrov-Galerkin condensation)
    Elimination  trial, test_elimination;
    const double abs_floor = 1e-12 * length_scale;
    for (const unsigned int r : constraint_rows)
      {
        std::map<unsigned int, double> row, test_row;
        double                         rhs = b[n + r], scale = std::abs(b[n + r]);
        std::set<unsigned int>         origin;
        trial.reduce(rows[r], row, rhs, scale, origin);
        if (!symmetric)
          {
            double                 unused_rhs = 0, unused_scale = 0;
            std::set<unsigned int> unused_origin;
            const std::vector<std::pair<unsigned int, double>> t(test[r].begin(), test[r].end());
            test_elimination.reduce(t, test_row, unused_rhs, unused_scale, unused_origin);
          }
        double test_norm = 0;
        for (const auto &e : test[r])
          test_norm = std::max(test_norm, std::abs(e.second));
        unsigned int pivot = dealii::numbers::invalid_unsigned_int;
        double       best = 0, best_score = 0;
        for (const auto &e : row)
          if (eligible(e.first))
            {
              best = std::max(best, std::abs(e.second));
              // symmetric: the largest entry; otherwise the largest product
              // of the trial and the test entry
              double score = std::abs(e.second);
              if (!symmetric)
                {
                  const auto te = test_row.find(e.first);
                  score *= (te == test_row.end() ? 0. : std::abs(te->second));
                }
              if (score > best_score)
                {
                  best_score = score;
                  pivot      = e.first;
                }
            }
        if (best <= dependency_tolerance * bmax[r])
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
                          "right-hand side differs from theirs by " + internal::number_string(rhs) + " (values of size " +
                          internal::number_string(scale) + " entered it): the contact gaps and the prescribed displacements "
                          "cannot all hold. Check the Dirichlet, roller and point constraints on the nodes of "
                          "these contact pairs."));
            AssertThrow(row_symmetric[r],
                        dealii::ExcMessage("Condensed contact constraints: multiplier row " + std::to_string(r) +
                                           " is a linear combination of the constraint rows {" + on +
                                           "} and carries a friction force (a slipping pair): the condensed "
                                           "solvers cannot split its force among the dependent rows. Use "
                                           "Solver/Type = UMFPACK or KLU for this model."));
            dependent_rows.push_back(r);
            continue;
          }
        AssertThrow(symmetric || best_score > dependency_tolerance * best * test_norm,
                    dealii::ExcMessage("Condensed contact constraints: multiplier row " + std::to_string(r) +
                                       " (a slipping pair) has no DoF where both its constraint and its "
                                       "friction-force direction are non-zero after the rows before it were "
                                       "eliminated. Use Solver/Type = UMFPACK or KLU for this model."));
        if (!symmetric)
          test_elimination.add(test_row, pivot, 0., 0., {});
        origin.insert(r);
        trial.add(row, pivot, rhs, scale, origin);
        slaves.emplace_back(r, pivot);
      }

    for (const auto &l : trial.lines)
      {
        constraints.add_line(l.slave);
        for (const auto &e : l.entries)
          constraints.add_entry(l.slave, e.first, e.second);
        constraints.set_inhomogeneity(l.slave, l.inhomogeneity);
      }
    constraints.close();
    if (!symmetric)
      {
        for (const auto &l : test_elimination.lines)
          {
            test_constraints.add_line(l.slave);
            for (const auto &e : l.entries)
              test_constraints.add_entry(l.slave, e.first, e.second);
            // the difference to the trial line: where the Petrov-Galerkin
            // condensation departs from the symmetric one
            std::map<unsigned int, double> difference(l.entries.begin(), l.entries.end());
            for (const auto &e : trial.lines[trial.line_of.at(l.slave)].entries)
              difference[e.first] -= e.second;
            std::vector<std::pair<unsigned int, double>> d;
            for (const auto &e : difference)
              if (e.second != 0.)
                d.emplace_back(e.first, e.second);
            if (!d.empty())
              test_lines.emplace_back(l.slave, std::move(d));
          }
        test_constraints.close();
      }
  }



  void
  ContactConstraints::condense(const dealii::SparseMatrix<double> &A,
                               const dealii::Vector<double>       &b,
                               dealii::SparsityPattern            &sparsity,
                               dealii::SparseMatrix<double>       &K,
                               dealii::Vector<double>             &f,
                               const bool                          symmetric_part) const
  {
    AssertDimension(A.m(), n + m);
    // multiplier values of the inactive rows and the constant parts of the
    // tied ones (their forces go to the rhs)
    std::vector<double> lambda(m, 0.);
    std::vector<bool>   known(m, false);
    for (const auto &in : inactive)
      {
        lambda[in.first] = in.second;
        known[in.first]  = true;
      }
    for (const auto &t : tied)
      {
        lambda[t.row] = t.value;
        known[t.row]  = true;
      }

    // the master DoFs of each slave
    std::vector<const std::vector<std::pair<dealii::types::global_dof_index, double>> *> line(n, nullptr);
    for (const auto &s : slaves)
      line[s.second] = constraints.get_constraint_entries(s.second);

    // fill-in: a row coupled to a slave couples to its masters; a master
    // row gets the couplings of its slaves' rows
    std::vector<std::vector<unsigned int>> extra(n);
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
    // Petrov-Galerkin: the test masters of a slave get its row too
    if (!symmetric_part)
      for (const auto &t : test_lines)
        for (const auto &e : t.second)
          add_row_of(e.first, t.first);

    // the rows: those of K with their fill-in, each sorted and without
    // repetitions, so that the pattern takes them as they are
    const dealii::SparsityPattern &sp = A.get_sparsity_pattern();
    std::vector<unsigned int>      row_length(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        auto &x = extra[i];
        if (!x.empty())
          {
            for (auto it = sp.begin(i); it != sp.end(i); ++it)
              if (it->column() < n)
                x.push_back(it->column());
            std::sort(x.begin(), x.end());
            x.erase(std::unique(x.begin(), x.end()), x.end());
            row_length[i] = x.size();
          }
        else
          for (auto it = sp.begin(i); it != sp.end(i); ++it)
            row_length[i] += (it->column() < n);
      }
    sparsity.reinit(n, n, row_length);
    std::vector<dealii::types::global_dof_index> cols;
    for (unsigned int i = 0; i < n; ++i)
      {
        cols.clear();
        if (!extra[i].empty())
          cols.assign(extra[i].begin(), extra[i].end());
        else
          {
            for (auto it = sp.begin(i); it != sp.end(i); ++it)
              if (it->column() < n)
                cols.push_back(it->column());
            std::sort(cols.begin(), cols.end());
          }
        sparsity.add_entries(i, cols.begin(), cols.end(), true);
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

    // Z^T K C = C^T K C + (Z - C)^T K C: the test lines that differ from
    // the trial lines (slipping pairs) add their difference times the
    // slave's row of K C (and of f - K c) to the masters
    if (symmetric_part)
      return;
    for (const auto &t : test_lines)
      {
        const unsigned int             s = t.first;
        std::map<unsigned int, double> row;
        double                         rs = b[s];
        for (auto it = A.begin(s); it != A.end(s); ++it)
          {
            const auto j = it->column();
            if (j >= n)
              {
                if (known[j - n])
                  rs -= it->value() * lambda[j - n];
                continue;
              }
            if (line[j] == nullptr)
              row[j] += it->value();
            else
              {
                for (const auto &e : *line[j])
                  row[e.first] += it->value() * e.second;
                rs -= it->value() * constraints.get_inhomogeneity(j);
              }
          }
        for (const auto &d : t.second)
          {
            for (const auto &e : row)
              K.add(d.first, e.first, d.second * e.second);
            f[d.first] += d.second * rs;
          }
      }
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
    std::vector<int>  tied_of(m, -1);
    for (unsigned int r = 0; r < m; ++r)
      x[n + r] = 0;
    for (const auto &in : inactive)
      {
        x[n + in.first] = in.second;
        known[in.first] = true;
      }
    for (unsigned int k = 0; k < tied.size(); ++k)
      {
        x[n + tied[k].row] = tied[k].value;
        tied_of[tied[k].row] = k;
      }
    if (constraint_rows.empty())
      return;

    // residual on the slave rows, and the matrix B_{I,S}^T (slave rows x
    // the independent enforced multipliers I). A dependent row carries no
    // force: the rows before it, on which it depends, carry all of it (see
    // the class documentation); so B_{I,S}^T is square, and triangular up
    // to permutation with the pivots of reinit().
    const unsigned int  n_s = slaves.size(), n_c = constraint_rows.size();
    std::vector<bool>   dependent(m, false);
    for (const auto r : dependent_rows)
      dependent[r] = true;
    std::vector<int>          column(m, -1);
    std::vector<unsigned int> independent;
    for (unsigned int k = 0; k < n_c; ++k)
      if (!dependent[constraint_rows[k]])
        {
          column[constraint_rows[k]] = independent.size();
          independent.push_back(constraint_rows[k]);
        }
    AssertThrow(independent.size() == n_s,
                dealii::ExcMessage("ContactConstraints: " + std::to_string(independent.size()) +
                                   " independent constraint rows for " + std::to_string(n_s) + " slave DoFs."));
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
            else if (tied_of[j - n] >= 0)
              {
                // a tied multiplier: its constant part is known, the rest
                // acts through the multipliers it follows
                v -= it->value() * x[j];
                for (const auto &e : tied[tied_of[j - n]].entries)
                  if (column[e.first] >= 0)
                    M[k].emplace_back(column[e.first], e.second * it->value());
              }
            else if (column[j - n] >= 0 && it->value() != 0.)
              M[k].emplace_back(column[j - n], it->value());
          }
        r[k] = v;
      }

    // B_{I,S}^T lambda_I = r_S
    dealii::DynamicSparsityPattern dsp(n_s, n_s);
    for (unsigned int k = 0; k < n_s; ++k)
      for (const auto &e : M[k])
        dsp.add(k, e.first);
    dealii::SparsityPattern sp;
    sp.copy_from(dsp);
    dealii::SparseMatrix<double> G(sp);
    for (unsigned int k = 0; k < n_s; ++k)
      for (const auto &e : M[k])
        G.add(k, e.first, e.second);
    dealii::Vector<double>      y(n_s);
    dealii::SparseDirectUMFPACK direct;
    direct.initialize(G);
    direct.vmult(y, r);
    for (unsigned int k = 0; k < n_s; ++k)
      x[n + independent[k]] = y[k];
    for (const auto &t : tied)
      for (const auto &e : t.entries)
        x[n + t.row] += e.second * x[n + e.first];
  }
} // namespace dealvem
