// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <deal.II/base/parallel.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <dealvem/base/number_string.h>
#include <dealvem/solvers/contact_constraints.h>

#include "two_level_cycle.h"

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cmath>
#include <functional>
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



    using SparseRow = std::vector<std::pair<unsigned int, double>>;

    // The multiplier rows of a saddle-point matrix, by kind (see
    // classify_multiplier_rows()).
    struct MultiplierRows
    {
      std::vector<SparseRow> bt;        // the columns of B^T, from the displacement rows
      std::vector<SparseRow> rows;      // the displacement entries of each multiplier row
      std::vector<SparseRow> couplings; // the entries of each row to other multipliers
      std::vector<double>    diagonal;  // the diagonal entry of each row
      std::vector<double>    bmax;      // the largest displacement entry of each row
    };



    // reinit(), step 1: the columns of B^T, and the multiplier rows
    // classified: constraint rows (displacement entries, no D entries),
    // known rows (diagonal only) and tied rows (diagonal and couplings to
    // other multipliers).
    MultiplierRows
    classify_multiplier_rows(const dealii::SparseMatrix<double> &A, const unsigned int n, const unsigned int m)
    {
      MultiplierRows mr;
      auto          &bt = mr.bt, &rows = mr.rows, &couplings = mr.couplings;
      auto          &diagonal = mr.diagonal, &bmax = mr.bmax;
      // the columns of B^T, from the displacement rows
      bt.resize(m);
      for (unsigned int i = 0; i < n; ++i)
        for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it)
          if (it->column() >= n && it->value() != 0.)
            bt[it->column() - n].emplace_back(i, it->value());

      rows.resize(m);
      couplings.resize(m);
      diagonal.assign(m, 0.);
      bmax.assign(m, 0.);
      for (unsigned int r = 0; r < m; ++r)
        {
          const unsigned int i = n + r;
          for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it)
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
          // (the row's name is only made for a message)
          const auto which = [&]() {
            return "multiplier row " + std::to_string(r) + " (unknown " + std::to_string(i) + ")";
          };
          if (rows[r].empty())
            {
              AssertThrow(diagonal[r] != 0.,
                          dealii::ExcMessage("Condensed contact constraints: " + which() +
                                             (couplings[r].empty() ? " is zero" : " has no diagonal entry") +
                                             ": the saddle-point matrix is singular."));
            }
          else
            {
              AssertThrow(diagonal[r] == 0. && couplings[r].empty(),
                          dealii::ExcMessage("Condensed contact constraints: " + which() +
                                             " has both displacement entries and entries of the multiplier block: "
                                             "not a constraint row."));
            }
        }
      return mr;
    }



    // reinit(), step 2: the known rows (their value into @p inactive), the
    // tied rows (into @p tied) and the test columns: B^T's own, plus the
    // columns of the tied multipliers that depend on it (a slipping pair's
    // friction force -mu sigma lambda_n acts along the tangent).
    std::vector<std::map<unsigned int, double>>
    known_and_tied_rows(const MultiplierRows &mr, const dealii::Vector<double> &b, const unsigned int n,
                        std::vector<std::pair<unsigned int, double>> &inactive,
                        std::vector<ContactConstraints::Tied>        &tied)
    {
      const auto        &rows = mr.rows, &couplings = mr.couplings, &bt = mr.bt;
      const auto        &diagonal = mr.diagonal;
      const unsigned int m        = rows.size();
      std::vector<double> known(m, 0.);
      std::vector<bool>   is_known(m, false);
      for (unsigned int r = 0; r < m; ++r)
        if (rows[r].empty() && couplings[r].empty())
          {
            known[r]    = b[n + r] / diagonal[r];
            is_known[r] = true;
            inactive.emplace_back(r, known[r]);
          }
      std::vector<std::map<unsigned int, double>> test(m);
      for (unsigned int r = 0; r < m; ++r)
        if (!rows[r].empty())
          for (const auto &e : bt[r])
            test[r][e.first] += e.second;
      for (unsigned int r = 0; r < m; ++r)
        if (rows[r].empty() && !couplings[r].empty())
          {
            ContactConstraints::Tied t;
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
      return test;
    }



    // reinit(), step 4, a row that depends on the rows before it (its
    // reduced entries vanish): its right-hand side must vanish too (to the
    // rounding of the values of size @p scale that entered it), and it must
    // carry no friction force.
    void
    check_dependent_row(const unsigned int r, const std::set<unsigned int> &origin, const double rhs,
                        const double scale, const double abs_floor, const bool row_symmetric)
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
      AssertThrow(row_symmetric,
                  dealii::ExcMessage("Condensed contact constraints: multiplier row " + std::to_string(r) +
                                     " is a linear combination of the constraint rows {" + on +
                                     "} and carries a friction force (a slipping pair): the condensed "
                                     "solvers cannot split its force among the dependent rows. Use "
                                     "Solver/Type = UMFPACK or KLU for this model."));
    }



    // reinit(), step 5: the lines of the eliminations as the constraints
    // (and, for non-symmetric rows, the test constraints and the lines
    // where they differ from the trial ones).
    void
    lines_to_constraints(
      const Elimination &trial, const Elimination &test_elimination, const bool symmetric,
      dealii::AffineConstraints<double> &constraints, dealii::AffineConstraints<double> &test_constraints,
      std::vector<std::pair<unsigned int, std::vector<std::pair<unsigned int, double>>>> &test_lines)
    {
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



    using MasterLine = std::vector<std::pair<dealii::types::global_dof_index, double>>;
    using TestLines  = std::vector<std::pair<unsigned int, std::vector<std::pair<unsigned int, double>>>>;

    // condense() with test lines (Petrov-Galerkin), step 1: the fill-in of
    // each displacement row: a row coupled to a slave couples to its
    // masters; a master row gets the couplings of its slaves' rows (@p line:
    // the master line of each slave, nullptr for the other DoFs); the test
    // masters of a slave get its row too.
    std::vector<std::vector<unsigned int>>
    fill_in(const dealii::SparseMatrix<double>                       &A,
            const unsigned int                                        n,
            const std::vector<std::pair<unsigned int, unsigned int>> &slaves,
            const std::vector<const MasterLine *>                    &line,
            const TestLines                                          &test_lines)
    {
      std::vector<std::vector<unsigned int>> extra(n);
      const auto add_row_of = [&](const unsigned int target, const unsigned int s) {
        auto &x = extra[target];
        for (auto it = A.begin(s), it_end = A.end(s); it != it_end; ++it)
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
          for (auto it = A.begin(s.second), it_end = A.end(s.second); it != it_end; ++it)
            {
              const auto i = it->column();
              if (i < n && line[i] == nullptr)
                for (const auto &e : *line[s.second])
                  extra[i].push_back(e.first);
            }
          for (const auto &e : *line[s.second])
            add_row_of(e.first, s.second);
        }
      // the test masters of a slave get its row too
      for (const auto &t : test_lines)
        for (const auto &e : t.second)
          add_row_of(e.first, t.first);
      return extra;
    }



    // condense(), step 2: the pattern of the condensed matrix: the rows of
    // K with their fill-in @p extra, each sorted and without repetitions,
    // so that the pattern takes them as they are.
    void
    condensed_pattern(const dealii::SparseMatrix<double> &A, const unsigned int n,
                      std::vector<std::vector<unsigned int>> &extra, dealii::SparsityPattern &sparsity)
    {
      const dealii::SparsityPattern &sp = A.get_sparsity_pattern();
      std::vector<unsigned int>      row_length(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          auto &x = extra[i];
          if (!x.empty())
            {
              for (auto it = sp.begin(i), it_end = sp.end(i); it != it_end; ++it)
                if (it->column() < n)
                  x.push_back(it->column());
              std::sort(x.begin(), x.end());
              x.erase(std::unique(x.begin(), x.end()), x.end());
              row_length[i] = x.size();
            }
          else
            for (auto it = sp.begin(i), it_end = sp.end(i); it != it_end; ++it)
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
              for (auto it = sp.begin(i), it_end = sp.end(i); it != it_end; ++it)
                if (it->column() < n)
                  cols.push_back(it->column());
              std::sort(cols.begin(), cols.end());
            }
          sparsity.add_entries(i, cols.begin(), cols.end(), true);
        }
      sparsity.compress();
    }



    // condense(), step 3: K and f = b - B^T lambda (the forces of the
    // @p known multipliers @p lambda) before the condensation; both rows
    // list the diagonal first and then ascending columns, and the new row
    // contains the old one.
    void
    copy_stiffness(const dealii::SparseMatrix<double> &A, const dealii::Vector<double> &b, const unsigned int n,
                   const std::vector<bool> &known, const std::vector<double> &lambda,
                   const dealii::SparsityPattern &sparsity, dealii::SparseMatrix<double> &K,
                   dealii::Vector<double> &f)
    {
      K.reinit(sparsity);
      f.reinit(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          f[i]    = b[i];
          auto kt = K.begin(i);
          for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it)
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
    }



    // condense(), step 5: Z^T K C = C^T K C + (Z - C)^T K C: the test lines
    // that differ from the trial lines (slipping pairs) add their
    // difference times the slave's row of K C (and of f - K c) to the
    // masters.
    void
    add_test_line_differences(const dealii::SparseMatrix<double> &A, const dealii::Vector<double> &b,
                              const unsigned int n, const std::vector<bool> &known,
                              const std::vector<double> &lambda, const std::vector<const MasterLine *> &line,
                              const dealii::AffineConstraints<double> &constraints, const TestLines &test_lines,
                              dealii::SparseMatrix<double> &K, dealii::Vector<double> &f)
    {
      for (const auto &t : test_lines)
        {
          const unsigned int             s = t.first;
          std::map<unsigned int, double> row;
          double                         rs = b[s];
          for (auto it = A.begin(s), it_end = A.end(s); it != it_end; ++it)
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


    // takes the rows of condense_by_rows() for a CondensedRows: the matrix,
    // n, the average diagonal, the kind of each row (0 decoupled, 1 plain,
    // 2 gathered), the row lengths, and the gathered rows compressed
    using RowsSetter = std::function<void(const dealii::SparseMatrix<double> &,
                                          unsigned int,
                                          double,
                                          std::vector<unsigned char> &&,
                                          std::vector<unsigned int> &&,
                                          std::vector<std::size_t> &&,
                                          std::vector<unsigned int> &&,
                                          std::vector<double> &&)>;

    // condense() without test lines (symmetric problems, and the symmetric
    // part C^T K C otherwise), row by row: row i of the condensed matrix
    // gathers, from its sources (row i itself with weight 1 and each slave
    // s whose line holds i, with its coefficient), their rows of K with
    // every slave column replaced by its line. The result is that of
    // copy_stiffness() and AffineConstraints::condense() (same pattern,
    // same values up to the order of the sums; slave rows decoupled with
    // the average of |K_ii| on the diagonal), without the binary search of
    // SparseMatrix::add() for every product and the fill-in lists
    // (measured on the 100-block wall of benchmarks/assembly, 24k DoFs,
    // both in the same process: 15 ms a condensation instead of 22 ms).
    void
    condense_by_rows(const dealii::SparseMatrix<double>                       &A,
                     const dealii::Vector<double>                             &b,
                     const unsigned int                                        n,
                     const std::vector<bool>                                  &known,
                     const std::vector<double>                                &lambda,
                     const std::vector<std::pair<unsigned int, unsigned int>> &slaves,
                     const std::vector<const MasterLine *>                    &line,
                     const dealii::AffineConstraints<double>                  &constraints,
                     dealii::SparsityPattern                                  &sparsity,
                     dealii::SparseMatrix<double>                             &K,
                     dealii::Vector<double>                                   &f,
                     dealii::TrilinosWrappers::SparseMatrix                   *trilinos = nullptr,
                     const RowsSetter                                         &rows     = {})
    {
      // the slaves of each master with their coefficients (compressed rows)
      std::vector<unsigned int> first(n + 1, 0);
      for (const auto &s : slaves)
        for (const auto &e : *line[s.second])
          ++first[e.first + 1];
      for (unsigned int i = 0; i < n; ++i)
        first[i + 1] += first[i];
      std::vector<std::pair<unsigned int, double>> of_master(first[n]);
      {
        std::vector<unsigned int> next(first.begin(), first.end() - 1);
        for (const auto &s : slaves)
          for (const auto &e : *line[s.second])
            of_master[next[e.first]++] = {s.second, e.second};
      }
      double average_diagonal = 0;
      for (unsigned int i = 0; i < n; ++i)
        average_diagonal += std::abs(A.diag_element(i));
      average_diagonal /= std::max(n, 1u);

      // The rows by kind: a slave row is decoupled (its pattern that of K,
      // the average diagonal); a row that no slave line holds and without
      // slave columns is K's row; only the others (gathered) are kept in
      // compressed rows until K's pattern is known (on the 100-block wall
      // of benchmarks/assembly, 70 % of the entries with unilateral or
      // tied contact, 8 % for its one-body comparison).
      enum Kind : unsigned char
      {
        slave_row,
        plain_row,
        gathered_row
      };
      const dealii::SparsityPattern &pattern = A.get_sparsity_pattern();
      std::vector<Kind>              kind(n, gathered_row);
      std::vector<unsigned int>      row_length(n, 0);
      for (unsigned int i = 0; i < n; ++i)
        {
          if (line[i] != nullptr)
            kind[i] = slave_row;
          else if (first[i] == first[i + 1])
            {
              kind[i] = plain_row;
              for (auto it = pattern.begin(i), end = pattern.end(i); it != end; ++it)
                if (it->column() < n && line[it->column()] != nullptr)
                  {
                    kind[i] = gathered_row;
                    break;
                  }
            }
          if (kind[i] != gathered_row)
            for (auto it = pattern.begin(i), end = pattern.end(i); it != end; ++it)
              row_length[i] += (it->column() < n);
        }

      std::vector<unsigned int> row_start(n + 1, 0), columns, diagonal_at(n, 0);
      std::vector<double>       values;
      {
        // (room for the gathered rows: their rows of K and half more for
        // the fill of the slave rows, so that they are seldom moved: on the
        // 100-block wall of benchmarks/assembly the fill is 41 %)
        std::size_t estimate = 0;
        for (unsigned int i = 0; i < n; ++i)
          if (kind[i] == gathered_row)
            estimate += pattern.row_length(i);
        estimate += estimate / 2;
        columns.reserve(estimate);
        values.reserve(estimate);
      }
      std::vector<double>       sum(n, 0.);
      std::vector<bool>         touched(n, false);
      std::vector<unsigned int> row;
      f.reinit(n);
      const auto put = [&](const unsigned int j, const double v) {
        if (!touched[j])
          {
            touched[j] = true;
            row.push_back(j);
          }
        sum[j] += v;
      };
      // add w times row p of K (slave columns by their lines) to the row
      // being gathered, and w times p's right-hand side to @p fi
      const auto gather = [&](const unsigned int p, const double w, const bool own, double &fi) {
        double fp = b[p];
        // (the pattern's iterator reads the columns inline; the matrix's
        // calls out of line for each)
        auto value = A.begin(p);
        for (auto it = pattern.begin(p), end = pattern.end(p); it != end; ++it, ++value)
          {
            const auto   j = it->column();
            const double a = value->value();
            if (j >= n)
              {
                if (known[j - n])
                  fp -= a * lambda[j - n];
                continue;
              }
            if (line[j] == nullptr)
              put(j, w * a);
            else
              {
                // (a slave column of the row's own K row stays in the
                // pattern, as a zero)
                if (own)
                  put(j, 0.);
                for (const auto &e : *line[j])
                  put(e.first, w * a * e.second);
                fp -= a * constraints.get_inhomogeneity(j);
              }
          }
        fi += w * fp;
      };
      for (unsigned int i = 0; i < n; ++i)
        {
          if (kind[i] == gathered_row)
            {
              double fi = 0;
              gather(i, 1., true, fi);
              for (unsigned int k = first[i]; k < first[i + 1]; ++k)
                gather(of_master[k].first, of_master[k].second, false, fi);
              f[i] = fi;
              std::sort(row.begin(), row.end());
              for (const auto j : row)
                {
                  if (j == i)
                    diagonal_at[i] = columns.size();
                  columns.push_back(j);
                  values.push_back(sum[j]);
                  sum[j]     = 0.;
                  touched[j] = false;
                }
              row_length[i] = row.size();
              row.clear();
            }
          else if (kind[i] == plain_row)
            {
              double fi    = b[i];
              auto   value = A.begin(i);
              for (auto it = pattern.begin(i), end = pattern.end(i); it != end; ++it, ++value)
                if (it->column() >= n && known[it->column() - n])
                  fi -= value->value() * lambda[it->column() - n];
              f[i] = fi;
            }
          row_start[i + 1] = columns.size();
        }

      if (rows)
        {
          // the rows kept as they are: the gathered ones compressed
          std::vector<std::size_t> starts(n + 1, 0);
          for (unsigned int i = 0; i < n; ++i)
            starts[i + 1] = row_start[i + 1];
          std::vector<unsigned char> kinds(n);
          for (unsigned int i = 0; i < n; ++i)
            kinds[i] = static_cast<unsigned char>(kind[i] == slave_row ? 0 : kind[i] == plain_row ? 1 : 2);
          rows(A, n, average_diagonal, std::move(kinds), std::move(row_length), std::move(starts), std::move(columns),
               std::move(values));
          return;
        }
      if (trilinos != nullptr)
        {
          // the rows ascending, written once into Epetra's storage: a slave
          // row and a plain one are A's row below n (whose diagonal comes
          // first in deal.II's order), a gathered row is kept ascending
          std::vector<int> lengths(row_length.begin(), row_length.end());
          const auto       fill = [&](const unsigned int i, int *cols, double *vals) {
            int k = 0;
            if (kind[i] == gathered_row)
              for (unsigned int e = row_start[i]; e < row_start[i + 1]; ++e, ++k)
                {
                  cols[k] = static_cast<int>(columns[e]);
                  vals[k] = values[e];
                }
            else
              {
                const bool slave = (kind[i] == slave_row);
                auto       value = A.begin(i);
                for (auto it = pattern.begin(i), end = pattern.end(i); it != end; ++it, ++value)
                  if (it->column() < n)
                    {
                      cols[k] = static_cast<int>(it->column());
                      vals[k] = (!slave ? value->value() : (it->column() == i ? average_diagonal : 0.));
                      ++k;
                    }
                for (int d = 0; d + 1 < k && cols[d + 1] < cols[d]; ++d)
                  {
                    std::swap(cols[d], cols[d + 1]);
                    std::swap(vals[d], vals[d + 1]);
                  }
              }
          };
          trilinos->reinit(*internal::epetra_from_rows(n, n, lengths, fill));
          return;
        }

      // the pattern: K's rows (diagonal first, then ascending, as A's rows
      // list the columns below n) and the gathered rows (ascending: their
      // diagonal goes first); written whole into a CompressedRowPattern
      auto *const direct = (n > 0 ? dynamic_cast<CompressedRowPattern *>(&sparsity) : nullptr);
      if (direct != nullptr)
        {
          std::unique_ptr<std::size_t[]> starts(new std::size_t[n + 1]);
          starts[0] = 0;
          for (unsigned int i = 0; i < n; ++i)
            starts[i + 1] = starts[i] + row_length[i];
          std::unique_ptr<dealii::SparsityPattern::size_type[]> entries(
            new dealii::SparsityPattern::size_type[starts[n]]);
          for (unsigned int i = 0; i < n; ++i)
            {
              auto *out = entries.get() + starts[i];
              if (kind[i] == gathered_row)
                {
                  *out++ = i;
                  for (unsigned int k = row_start[i]; k < row_start[i + 1]; ++k)
                    if (k != diagonal_at[i])
                      *out++ = columns[k];
                }
              else
                for (auto it = pattern.begin(i), end = pattern.end(i); it != end; ++it)
                  if (it->column() < n)
                    *out++ = it->column();
            }
          columns = std::vector<unsigned int>();
          direct->assign(n, std::move(starts), std::move(entries));
        }
      else
        {
          sparsity.reinit(n, n, row_length);
          for (unsigned int i = 0; i < n; ++i)
            if (kind[i] == gathered_row)
              sparsity.add_entries(i, columns.begin() + row_start[i], columns.begin() + row_start[i + 1], true);
            else
              {
                row.clear();
                for (auto it = pattern.begin(i), end = pattern.end(i); it != end; ++it)
                  if (it->column() < n)
                    row.push_back(it->column());
                std::size_t d = 0;
                while (d + 1 < row.size() && row[d + 1] < row[d])
                  {
                    std::swap(row[d], row[d + 1]);
                    ++d;
                  }
                sparsity.add_entries(i, row.begin(), row.end(), true);
              }
          sparsity.compress();
          columns = std::vector<unsigned int>();
        }
      K.reinit(sparsity);
      // the values; K's rows list the diagonal first, then the other
      // columns ascending, as A's rows (whose multiplier columns follow)
      for (unsigned int i = 0; i < n; ++i)
        if (kind[i] == slave_row)
          K.begin(i)->value() = average_diagonal;
        else if (kind[i] == plain_row)
          {
            auto kt = K.begin(i);
            for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it)
              if (it->column() < n)
                (kt++)->value() = it->value();
          }
        else
          {
            // the gathered row ascending: its diagonal goes first
            K.begin(i)->value() = values[diagonal_at[i]];
            auto kt             = K.begin(i);
            ++kt;
            for (unsigned int k = row_start[i]; k < row_start[i + 1]; ++k)
              if (k != diagonal_at[i])
                (kt++)->value() = values[k];
          }
    }
  } // namespace



  void
  CompressedRowPattern::assign(const size_type                n,
                               std::unique_ptr<std::size_t[]> row_start,
                               std::unique_ptr<size_type[]>   columns)
  {
    AssertThrow(n > 0 && row_start != nullptr && row_start[0] == 0 && (row_start[n] == 0 || columns != nullptr),
                dealii::ExcMessage("CompressedRowPattern::assign(): empty or inconsistent rows."));
    unsigned int longest = 0;
    for (size_type i = 0; i < n; ++i)
      {
        const std::size_t begin = row_start[i], end = row_start[i + 1];
        AssertThrow(end > begin && columns[begin] == i,
                    dealii::ExcMessage("CompressedRowPattern::assign(): row " + std::to_string(i) +
                                       " does not start with its diagonal."));
        for (std::size_t k = begin + 1; k < end; ++k)
          AssertThrow(columns[k] < n && columns[k] != i && (k == begin + 1 || columns[k] > columns[k - 1]),
                      dealii::ExcMessage("CompressedRowPattern::assign(): the columns of row " + std::to_string(i) +
                                         " are not ascending after the diagonal, or out of range."));
        longest = std::max<unsigned int>(longest, end - begin);
      }
    // a square pattern of size n (diagonal first in every row: deal.II's
    // flag for it is set by reinit()), its arrays then replaced
    reinit(n, n, 1);
    max_dim        = n; // (the length of rowstart less one: a later reinit() reallocates above it)
    rowstart       = std::move(row_start);
    colnums        = std::move(columns);
    max_vec_len    = rowstart[n];
    max_row_length = longest;
    compressed     = true;
  }



  struct ContactConstraints::Recovery
  {
    /// B_{I,S}^T by rows: row k's entries are entries[start[k]] to
    /// entries[start[k + 1]] (flat: no allocation per row, and compared
    /// with the next call's as two arrays)
    std::vector<unsigned int>                                 start;
    std::vector<std::pair<unsigned int, double>>              entries;
    dealii::SparsityPattern                                   sparsity;
    dealii::SparseMatrix<double>                              G;
    dealii::SparseDirectUMFPACK                               direct;
  };



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
    recovery.reset();
    constraints.clear();
    test_constraints.clear();
    test_lines.clear();
    constraint_rows.clear();
    dependent_rows.clear();
    slaves.clear();
    inactive.clear();
    tied.clear();
    symmetric = true;

    // step 1: the multiplier rows by kind
    const MultiplierRows mr   = classify_multiplier_rows(A, n, m);
    const auto          &rows = mr.rows;
    const auto          &bmax = mr.bmax;
    // step 2: the known and tied rows, and the test columns
    const std::vector<std::map<unsigned int, double>> test = known_and_tied_rows(mr, b, n, inactive, tied);
    // step 3: which constraint rows equal their test columns
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

    // a DoF can be a slave if its row of K couples to other DoFs (DoFs
    // condensed by the displacement constraints have decoupled rows)
    const auto eligible = [&](const unsigned int j) {
      if (displacement_constraints != nullptr)
        return !displacement_constraints->is_constrained(j);
      for (auto it = A.begin(j), it_end = A.end(j); it != it_end; ++it)
        if (it->column() < n && it->column() != j && it->value() != 0.)
          return true;
      return false;
    };

    // step 4: Gauss-Jordan elimination with partial pivoting per row; with
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
            check_dependent_row(r, origin, rhs, scale, abs_floor, row_symmetric[r]);
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

    // step 5: the constraints from the lines of the eliminations
    lines_to_constraints(trial, test_elimination, symmetric, constraints, test_constraints, test_lines);
  }



  void
  ContactConstraints::known_multipliers(std::vector<double> &lambda, std::vector<bool> &known) const
  {
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
    known_multipliers(lambda, known);

    // the master DoFs of each slave
    std::vector<const std::vector<std::pair<dealii::types::global_dof_index, double>> *> line(n, nullptr);
    for (const auto &s : slaves)
      line[s.second] = constraints.get_constraint_entries(s.second);

    // C^T K C: row by row
    if (symmetric || symmetric_part)
      {
        condense_by_rows(A, b, n, known, lambda, slaves, line, constraints, sparsity, K, f);
        return;
      }
    // Z^T K C (Petrov-Galerkin): step 1, the fill-in
    std::vector<std::vector<unsigned int>> extra = fill_in(A, n, slaves, line, test_lines);
    // step 2: the pattern of the condensed matrix
    condensed_pattern(A, n, extra, sparsity);
    // step 3: copy K; step 4: condense it
    copy_stiffness(A, b, n, known, lambda, sparsity, K, f);
    constraints.condense(K, f);
    // step 5: the Petrov-Galerkin difference of the test lines
    add_test_line_differences(A, b, n, known, lambda, line, constraints, test_lines, K, f);
  }



  void
  ContactConstraints::condense(const dealii::SparseMatrix<double>     &A,
                               const dealii::Vector<double>           &b,
                               dealii::TrilinosWrappers::SparseMatrix &K,
                               dealii::Vector<double>                 &f) const
  {
    condense_symmetric(A, b, f, &K, nullptr);
  }



  void
  ContactConstraints::condense(const dealii::SparseMatrix<double> &A,
                               const dealii::Vector<double>       &b,
                               CondensedRows                      &K,
                               dealii::Vector<double>             &f) const
  {
    condense_symmetric(A, b, f, nullptr, &K);
  }



  void
  ContactConstraints::condense_symmetric(const dealii::SparseMatrix<double>     &A,
                                         const dealii::Vector<double>           &b,
                                         dealii::Vector<double>                 &f,
                                         dealii::TrilinosWrappers::SparseMatrix *trilinos,
                                         CondensedRows                          *rows) const
  {
    AssertDimension(A.m(), n + m);
    AssertThrow(symmetric, dealii::ExcMessage(std::string("ContactConstraints::condense() into ") +
                                              (rows != nullptr ? "rows" : "a Trilinos matrix") +
                                              ": the constraints are not symmetric (slipping pairs); condense "
                                              "into a deal.II matrix instead."));
    std::vector<double> lambda(m, 0.);
    std::vector<bool>   known(m, false);
    known_multipliers(lambda, known);
    std::vector<const std::vector<std::pair<dealii::types::global_dof_index, double>> *> line(n, nullptr);
    for (const auto &s : slaves)
      line[s.second] = constraints.get_constraint_entries(s.second);
    dealii::SparsityPattern      unused_pattern;
    dealii::SparseMatrix<double> unused_matrix;
    RowsSetter                   take_rows;
    if (rows != nullptr)
      take_rows = [rows](const dealii::SparseMatrix<double> &A_, const unsigned int n_, const double average,
                         std::vector<unsigned char> &&kinds, std::vector<unsigned int> &&lengths,
                         std::vector<std::size_t> &&starts, std::vector<unsigned int> &&columns,
                         std::vector<double> &&values) {
        rows->A                = &A_;
        rows->n                = n_;
        rows->average_diagonal = average;
        rows->kind.resize(n_);
        for (unsigned int i = 0; i < n_; ++i)
          rows->kind[i] = static_cast<CondensedRows::Kind>(kinds[i]);
        rows->lengths   = std::move(lengths);
        rows->row_start = std::move(starts);
        rows->columns   = std::move(columns);
        rows->values    = std::move(values);
      };
    condense_by_rows(A, b, n, known, lambda, slaves, line, constraints, unused_pattern, unused_matrix, f, trilinos,
                     take_rows);
  }



  double
  CondensedRows::diag_element(const unsigned int i) const
  {
    if (kind[i] == decoupled)
      return average_diagonal;
    if (kind[i] == plain)
      return A->diag_element(i);
    for (std::size_t k = row_start[i]; k < row_start[i + 1]; ++k)
      if (columns[k] == i)
        return values[k];
    return 0.;
  }



  void
  CondensedRows::vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const
  {
    AssertDimension(dst.size(), n);
    AssertDimension(src.size(), n);
    const double *x = src.begin();
    double       *y = dst.begin();
    dealii::parallel::apply_to_subranges(
      0U, n,
      [&](const unsigned int begin, const unsigned int end) {
        const auto &sp = A->get_sparsity_pattern();
        for (unsigned int i = begin; i < end; ++i)
          {
            double sum = 0;
            if (kind[i] == decoupled)
              sum = average_diagonal * x[i];
            else if (kind[i] == gathered)
              for (std::size_t k = row_start[i]; k < row_start[i + 1]; ++k)
                sum += values[k] * x[columns[k]];
            else
              {
                auto value = A->begin(i);
                for (auto it = sp.begin(i), e = sp.end(i); it != e; ++it, ++value)
                  {
                    const unsigned int j = it->column();
                    if (j >= n)
                      break;
                    sum += value->value() * x[j];
                  }
              }
            y[i] = sum;
          }
      },
      4096);
  }



  void
  CondensedRows::rebind(const dealii::SparseMatrix<double> &A_again)
  {
    AssertThrow(A != nullptr && A_again.m() == A->m() && A_again.n_nonzero_elements() == A->n_nonzero_elements(),
                dealii::ExcMessage("CondensedRows::rebind(): not the saddle-point matrix the rows were condensed "
                                   "from."));
    A = &A_again;
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
    dealii::Vector<double>                       r(n_s);
    std::vector<unsigned int>                    start(n_s + 1, 0);
    std::vector<std::pair<unsigned int, double>> entries;
    if (recovery != nullptr)
      entries.reserve(recovery->entries.size());
    for (unsigned int k = 0; k < n_s; ++k)
      {
        const unsigned int s = slaves[k].second;
        double             v = b[s];
        for (auto it = A.begin(s), it_end = A.end(s); it != it_end; ++it)
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
                    entries.emplace_back(column[e.first], e.second * it->value());
              }
            else if (column[j - n] >= 0 && it->value() != 0.)
              entries.emplace_back(column[j - n], it->value());
          }
        r[k]         = v;
        start[k + 1] = entries.size();
      }

    // B_{I,S}^T lambda_I = r_S; its LU is kept while the matrix comes back
    // entry for entry (the continuations of an inexact solve: on the
    // 100-block wall of benchmarks/assembly, 8 of the 12 recoveries of the
    // unilateral run)
    if (recovery == nullptr || recovery->start != start || recovery->entries != entries)
      {
        auto                           fresh = std::make_shared<Recovery>();
        dealii::DynamicSparsityPattern dsp(n_s, n_s);
        for (unsigned int k = 0; k < n_s; ++k)
          for (unsigned int e = start[k]; e < start[k + 1]; ++e)
            dsp.add(k, entries[e].first);
        fresh->sparsity.copy_from(dsp);
        fresh->G.reinit(fresh->sparsity);
        for (unsigned int k = 0; k < n_s; ++k)
          for (unsigned int e = start[k]; e < start[k + 1]; ++e)
            fresh->G.add(k, entries[e].first, entries[e].second);
        fresh->direct.initialize(fresh->G);
        fresh->start   = std::move(start);
        fresh->entries = std::move(entries);
        recovery       = std::move(fresh);
      }
    dealii::Vector<double> y(n_s);
    recovery->direct.vmult(y, r);
    for (unsigned int k = 0; k < n_s; ++k)
      x[n + independent[k]] = y[k];
    for (const auto &t : tied)
      for (const auto &e : t.entries)
        x[n + t.row] += e.second * x[n + e.first];
  }
} // namespace dealvem
