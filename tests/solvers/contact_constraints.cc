// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// SaddlePointSolver 'CG-AMG constraints' on small hand-made saddle-point
// systems [[K, B^T], [B, D]] (K the 20x20 matrix tridiag(-1, 2.5, -1), DoF 5
// decoupled as a Dirichlet DoF condensed by AffineConstraints leaves it):
//   rows 0: u0 - u10 = 0.1, 1: u3 + 0.5 u12 = -0.2, 2: inactive (D = 1),
//   3: u0 + u1 - u11 = 0.05 (shares u0 with row 0: Gauss-Jordan),
//   4: 2 u0 - 2 u10 = 0.2 (twice row 0: redundant, consistent).
// a) without row 4 the solver agrees with UMFPACK on the saddle point to
//    1e-10 (u and lambda); the constraints hold to 1e-12;
// b) with row 4, u is the same (1e-10), the row is reported as dropped, and
//    the row it depends on carries the force: lambda_0 = mu_0, lambda_4 = 0
//    (1e-10), the others as in a);
// c) row 4 with right-hand side 0.3: "Inconsistent redundant contact
//    constraints" naming rows 4 and 0;
// d) a force column that differs from its constraint row (1.5 times row 1)
//    and a tied multiplier row (lambda_2 = -0.3 lambda_0, force along
//    (u0, u10) = (0.7, -0.7), as a slipping pair's friction force): the
//    Petrov-Galerkin condensation (CG-AMG, i.e. GMRES, and direct
//    constraints, i.e. UMFPACK LU) against UMFPACK on the saddle point to
//    1e-10 in u and lambda; a constraint row with an off-diagonal D entry is
//    refused, naming the row; an unknown solver name lists the types.
// e) ContactConstraints::condense() against deal.II's own condensation of
//    K by the same lines, entry by entry to 1e-14 (see below), and into a
//    CompressedRowPattern and (symmetric problems) into a Trilinos matrix
//    and into CondensedRows: the same pattern and values, bit for bit
//    (refused when not symmetric), the rows' product to 1e-15;
// f) CompressedRowPattern::assign() refuses a row whose diagonal is not
//    first, or whose columns do not ascend, naming the row.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <dealvem/solvers/contact_constraints.h>
#include <dealvem/solvers/saddle_point_solver.h>

#include <cmath>
#include <map>

#include "../tests.h"

using namespace dealvem;

namespace
{
  const unsigned int n = 20;

  struct System
  {
    dealii::SparsityPattern      sp;
    dealii::SparseMatrix<double> A;
    dealii::Vector<double>       b;
  };

  /// rows: (coefficients, rhs); empty coefficients = inactive row.
  /// @p bt_change / @p d_coupling spoil the structure for d).
  void
  build(System &s, const std::vector<std::pair<std::map<unsigned int, double>, double>> &rows,
        const bool bt_change = false, const bool d_coupling = false, const bool tied = false)
  {
    const unsigned int             m = rows.size();
    dealii::DynamicSparsityPattern dsp(n + m);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j < std::min(n, i + 2); ++j)
        dsp.add(i, j);
    for (unsigned int r = 0; r < m; ++r)
      {
        dsp.add(n + r, n + r);
        for (const auto &e : rows[r].first)
          {
            dsp.add(n + r, e.first);
            dsp.add(e.first, n + r);
          }
      }
    dsp.add(n, n + 1);
    // the tied row 2: lambda_2 + 0.3 lambda_0 = 0, its force along
    // (u0, u10) = (0.7, -0.7) (a friction force following a normal force)
    dsp.add(n + 2, n);
    dsp.add(0, n + 2);
    dsp.add(10, n + 2);
    s.sp.copy_from(dsp);
    s.A.reinit(s.sp);
    s.b.reinit(n + m);
    for (unsigned int i = 0; i < n; ++i)
      {
        if (i == 5)
          {
            s.A.set(i, i, 2.5); // a condensed Dirichlet DoF: decoupled
            continue;
          }
        s.A.set(i, i, 2.5);
        if (i > 0 && i - 1 != 5)
          s.A.set(i, i - 1, -1.);
        if (i + 1 < n && i + 1 != 5)
          s.A.set(i, i + 1, -1.);
        s.b[i] = std::sin(1. + i);
      }
    for (unsigned int r = 0; r < m; ++r)
      {
        if (rows[r].first.empty())
          s.A.set(n + r, n + r, 1.);
        for (const auto &e : rows[r].first)
          {
            s.A.set(n + r, e.first, e.second);
            s.A.set(e.first, n + r, e.second * (bt_change && r == 1 ? 1.5 : 1.));
          }
        s.b[n + r] = rows[r].second;
      }
    if (d_coupling)
      s.A.set(n, n + 1, 0.3);
    if (tied)
      {
        s.A.set(n + 2, n, 0.3);
        s.A.set(0, n + 2, 0.7);
        s.A.set(10, n + 2, -0.7);
      }
  }

  dealii::Vector<double>
  solve(const System &s, const SaddlePointSolver::Type type)
  {
    SaddlePointSolver::Settings settings;
    settings.type               = type;
    settings.relative_tolerance = 1e-13;
    SaddlePointSolver      solver(settings);
    dealii::Vector<double> x;
    solver.solve(s.A, n, x, s.b);
    std::cout << "      " << SaddlePointSolver::type_name(type) << ": " << solver.last_iterations()
              << " iteration(s), " << solver.last_dropped_constraints() << " dropped" << std::endl;
    return x;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using Rows = std::vector<std::pair<std::map<unsigned int, double>, double>>;
  const Rows base = {{{{0, 1.}, {10, -1.}}, 0.1},
                     {{{3, 1.}, {12, 0.5}}, -0.2},
                     {{}, 0.},
                     {{{0, 1.}, {1, 1.}, {11, -1.}}, 0.05}};
  Rows with_redundant = base;
  with_redundant.push_back({{{0, 2.}, {10, -2.}}, 0.2});

  // a)
  System s;
  build(s, base);
  const auto ref = solve(s, SaddlePointSolver::Type::umfpack);
  const auto x   = solve(s, SaddlePointSolver::Type::cg_amg_constraints);
  double     du = 0, u = 0, dl = 0, l = 0;
  for (unsigned int i = 0; i < n; ++i)
    if (i != 5)
      {
        du = std::max(du, std::abs(x[i] - ref[i]));
        u  = std::max(u, std::abs(ref[i]));
      }
  for (unsigned int r = 0; r < base.size(); ++r)
    {
      dl = std::max(dl, std::abs(x[n + r] - ref[n + r]));
      l  = std::max(l, std::abs(ref[n + r]));
    }
  testing::check_small(du / u, 1e-10, "a) u against UMFPACK (max norm, relative)");
  testing::check_small(dl / l, 1e-10, "a) lambda against UMFPACK (max norm, relative)");
  testing::check_small(x[n + 2], 0, "a) inactive row: lambda = 0");
  double violation = 0;
  for (const auto &row : base)
    {
      double v = -row.second;
      for (const auto &e : row.first)
        v += e.second * x[e.first];
      violation = std::max(violation, std::abs(v));
    }
  testing::check_small(violation, 1e-12, "a) constraints B u = g");

  // b)
  System s2;
  build(s2, with_redundant);
  SaddlePointSolver::Settings settings;
  settings.type               = SaddlePointSolver::Type::cg_amg_constraints;
  settings.relative_tolerance = 1e-13;
  SaddlePointSolver      solver(settings);
  dealii::Vector<double> x2;
  solver.solve(s2.A, n, x2, s2.b);
  testing::check(solver.last_dropped_constraints() == 1, "b) one redundant constraint dropped");
  du = 0;
  for (unsigned int i = 0; i < n; ++i)
    if (i != 5)
      du = std::max(du, std::abs(x2[i] - ref[i]));
  testing::check_small(du / u, 1e-10, "b) u with the redundant row, against a)");
  testing::check_small(std::abs(x2[n + 0] - ref[n]) / l, 1e-10, "b) lambda_0 = mu_0");
  testing::check_small(std::abs(x2[n + 4]) / l, 1e-10, "b) lambda_4 = 0 (the dependent row carries no force)");
  testing::check_small((std::abs(x2[n + 1] - ref[n + 1]) + std::abs(x2[n + 3] - ref[n + 3])) / l, 1e-10,
                       "b) lambda_1, lambda_3 as in a)");

  // c)
  Rows inconsistent = with_redundant;
  inconsistent[4].second = 0.3;
  System s3;
  build(s3, inconsistent);
  testing::check_throws([&] { solve(s3, SaddlePointSolver::Type::cg_amg_constraints); },
                        "Inconsistent redundant contact constraints: multiplier row 4 is a linear combination of "
                        "the constraint rows {0}",
                        "c) inconsistent redundant constraints");

  // d) Petrov-Galerkin: a force column that differs from its row, and a
  //    tied multiplier row: both condensed solvers against UMFPACK
  System s4, s5, s6;
  build(s4, base, true, false);
  build(s5, base, false, true);
  build(s6, base, false, false, true);
  for (const auto *sys : {&s4, &s6})
    {
      const std::string what = (sys == &s4 ? "d) force column 1.5 times its row" : "d) tied multiplier row");
      const auto        r    = solve(*sys, SaddlePointSolver::Type::umfpack);
      double            ru = 0, rl = 0;
      for (unsigned int i = 0; i < n; ++i)
        ru = std::max(ru, std::abs(r[i]));
      for (unsigned int i = n; i < r.size(); ++i)
        rl = std::max(rl, std::abs(r[i]));
      testing::check(rl > 0.1 * ru && (sys == &s4 || std::abs(r[n + 2] + 0.3 * r[n]) < 1e-12 * rl),
                     what + ": the reference has non-trivial multipliers (and lambda_2 = -0.3 lambda_0)");
      for (const auto type : {SaddlePointSolver::Type::cg_amg_constraints, SaddlePointSolver::Type::direct_constraints})
        {
          const auto y = solve(*sys, type);
          double     eu = 0, el = 0;
          for (unsigned int i = 0; i < n; ++i)
            eu = std::max(eu, std::abs(y[i] - r[i]));
          for (unsigned int i = n; i < r.size(); ++i)
            el = std::max(el, std::abs(y[i] - r[i]));
          testing::check_small(eu / ru, 1e-10, what + ", " + SaddlePointSolver::type_name(type) + ": u against UMFPACK");
          testing::check_small(el / rl, 1e-10,
                               what + ", " + SaddlePointSolver::type_name(type) + ": lambda against UMFPACK");
        }
    }
  testing::check_throws([&] { solve(s5, SaddlePointSolver::Type::cg_amg_constraints); },
                        "multiplier row 0 (unknown 20) has both displacement entries and entries of the multiplier "
                        "block",
                        "d) a constraint row with multiplier couplings refused");
  testing::check_throws([] { SaddlePointSolver::parse_type("foo"); },
                        "expected UMFPACK, KLU, GMRES-AMG, CG-AMG or direct constraints", "d) unknown solver name");
  testing::check(SaddlePointSolver::parse_type("cg-amg CONSTRAINTS") ==
                   SaddlePointSolver::Type::cg_amg_constraints,
                 "d) 'CG-AMG constraints' parsed case-insensitively");

  // e) ContactConstraints::condense() (row by row) against deal.II's
  //    condensation of K by the same lines (pattern from the condensed
  //    DynamicSparsityPattern, AffineConstraints::condense()), entry by
  //    entry to 1e-14 of the largest: the system of a) (rows sharing u0,
  //    an inactive row), b) (a dependent row) and of the tied row's
  //    symmetric part (the lines of its constraint rows)
  for (const auto *sys : {&s, &s2, &s6})
    {
      const std::string  what = (sys == &s ? "e) a)" : sys == &s2 ? "e) b)" : "e) tied row, symmetric part");
      ContactConstraints cc;
      cc.reinit(sys->A, n, sys->b, 1.);
      dealii::SparsityPattern      sp;
      dealii::SparseMatrix<double> K;
      dealii::Vector<double>       f;
      cc.condense(sys->A, sys->b, sp, K, f, true);

      const auto                    &lines = cc.get_constraints();
      dealii::DynamicSparsityPattern dsp(n);
      for (unsigned int i = 0; i < n; ++i)
        for (auto it = sys->A.begin(i); it != sys->A.end(i); ++it)
          if (it->column() < n)
            dsp.add(i, it->column());
      lines.condense(dsp);
      dealii::SparsityPattern sp_ref;
      sp_ref.copy_from(dsp);
      dealii::SparseMatrix<double> K_ref(sp_ref);
      dealii::Vector<double>       f_ref(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          f_ref[i] = sys->b[i];
          for (auto it = sys->A.begin(i); it != sys->A.end(i); ++it)
            if (it->column() < n)
              K_ref.set(i, it->column(), it->value());
        }
      lines.condense(K_ref, f_ref);
      double dk = 0, k = 0, df = 0, fm = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          for (unsigned int j = 0; j < n; ++j)
            {
              dk = std::max(dk, std::abs(K.el(i, j) - K_ref.el(i, j)));
              k  = std::max(k, std::abs(K_ref.el(i, j)));
            }
          df = std::max(df, std::abs(f[i] - f_ref[i]));
          fm = std::max(fm, std::abs(f_ref[i]));
        }
      // the same condensation into a CompressedRowPattern (filled in one
      // pass): the same pattern, row by row in the same order, and the
      // same values bit for bit
      CompressedRowPattern         sp_direct;
      dealii::SparseMatrix<double> K_direct;
      dealii::Vector<double>       f_direct;
      cc.condense(sys->A, sys->b, sp_direct, K_direct, f_direct, true);
      bool same = sp_direct.n_nonzero_elements() == sp.n_nonzero_elements() && sp_direct.n_rows() == n &&
                  sp_direct.is_compressed() && sp_direct.max_entries_per_row() == sp.max_entries_per_row();
      for (unsigned int i = 0; same && i < n; ++i)
        {
          same   = sp_direct.row_length(i) == sp.row_length(i);
          auto a = K_direct.begin(i);
          for (auto b = K.begin(i); same && b != K.end(i); ++a, ++b)
            same = a->column() == b->column() && a->value() == b->value();
          same = same && f_direct[i] == f[i];
        }
      testing::check(same, what + ": the CompressedRowPattern path gives the same pattern and values");
      // and into a Trilinos matrix (symmetric problems): the same rows,
      // ascending, the same values bit for bit; refused otherwise
      if (cc.is_symmetric())
        {
          dealii::TrilinosWrappers::SparseMatrix Kt;
          dealii::Vector<double>                 f_trilinos;
          cc.condense(sys->A, sys->b, Kt, f_trilinos);
          bool same_t = Kt.m() == n && Kt.n() == n && Kt.n_nonzero_elements() == sp.n_nonzero_elements();
          for (unsigned int i = 0; same_t && i < n; ++i)
            {
              same_t = Kt.row_length(i) == sp.row_length(i) && f_trilinos[i] == f[i];
              for (auto b = K.begin(i); same_t && b != K.end(i); ++b)
                same_t = Kt.el(i, b->column()) == b->value();
            }
          testing::check(same_t, what + ": the Trilinos path gives the same pattern and values");

          // and into rows that refer to A: the same entries, ascending; the
          // product of K to round-off; rebind() refuses another matrix
          CondensedRows          rows;
          dealii::Vector<double> f_rows;
          cc.condense(sys->A, sys->b, rows, f_rows);
          bool same_r = rows.m() == n;
          for (unsigned int i = 0; same_r && i < n; ++i)
            {
              std::vector<std::pair<unsigned int, double>> entries;
              rows.for_row(i, [&](const unsigned int j, const double v) { entries.emplace_back(j, v); });
              same_r = entries.size() == sp.row_length(i) && rows.row_length(i) == sp.row_length(i) &&
                       f_rows[i] == f[i] && rows.diag_element(i) == K.diag_element(i);
              for (std::size_t e = 0; same_r && e < entries.size(); ++e)
                same_r =
                  (e == 0 || entries[e].first > entries[e - 1].first) && K.el(i, entries[e].first) == entries[e].second;
            }
          testing::check(same_r, what + ": the rows give the same pattern and values, ascending");
          dealii::Vector<double> x(n), y(n), y_ref(n);
          for (unsigned int i = 0; i < n; ++i)
            x[i] = std::sin(1. + 3. * i);
          rows.vmult(y, x);
          K.vmult(y_ref, x);
          y -= y_ref;
          testing::check_small(y.linfty_norm() / y_ref.linfty_norm(), 1e-15,
                               what + ": the rows' product against K's (max norm, relative)");
          dealii::SparseMatrix<double> other(sp);
          testing::check_throws([&] { rows.rebind(other); }, "not the saddle-point matrix",
                                what + ": rebind() to another matrix refused");
        }
      else
        testing::check_throws(
          [&] {
            dealii::TrilinosWrappers::SparseMatrix Kt;
            dealii::Vector<double>                 f_trilinos;
            cc.condense(sys->A, sys->b, Kt, f_trilinos);
          },
          "the constraints are not symmetric", what + ": condense() into Trilinos refused");
      testing::check(lines.n_constraints() >= 2, what + ": at least two slave lines");
      testing::check_small(dk / k, 1e-14, what + ": condensed K against deal.II's condensation");
      testing::check_small(df / fm, 1e-14, what + ": condensed f against deal.II's condensation");
    }
  // f) CompressedRowPattern::assign() refuses rows that are not in
  //    deal.II's order (diagonal first, then ascending), naming the row
  {
    const auto attempt = [](const std::vector<std::size_t> &starts, const std::vector<unsigned int> &columns) {
      std::unique_ptr<std::size_t[]> s(new std::size_t[starts.size()]);
      std::copy(starts.begin(), starts.end(), s.get());
      std::unique_ptr<dealii::SparsityPattern::size_type[]> c(new dealii::SparsityPattern::size_type[columns.size()]);
      std::copy(columns.begin(), columns.end(), c.get());
      CompressedRowPattern p;
      p.assign(starts.size() - 1, std::move(s), std::move(c));
      return p.n_nonzero_elements();
    };
    testing::check(attempt({0, 2, 3, 5}, {0, 2, 1, 2, 0}) == 5, "f) a valid 3x3 pattern is taken");
    {
      // a pattern reused: larger by reinit(), then assigned smaller rows,
      // then larger again (its arrays must be reallocated, not overrun:
      // the sanitizer build checks), and used by a matrix each time
      CompressedRowPattern p;
      p.reinit(50, 50, 3);
      p.compress();
      std::unique_ptr<std::size_t[]>                        s(new std::size_t[3]{0, 1, 3});
      std::unique_ptr<dealii::SparsityPattern::size_type[]> c(new dealii::SparsityPattern::size_type[3]{0, 1, 0});
      p.assign(2, std::move(s), std::move(c));
      dealii::SparseMatrix<double> M(p);
      M.set(1, 0, 2.);
      const bool small = p.n_rows() == 2 && p.n_nonzero_elements() == 3 && M.el(1, 0) == 2. && M.el(0, 1) == 0.;
      M.clear();
      p.reinit(40, 40, 4);
      for (unsigned int i = 0; i + 1 < 40; ++i)
        p.add(i, i + 1);
      p.compress();
      M.reinit(p);
      testing::check(small && p.n_rows() == 40 && p.n_nonzero_elements() == 79 && M.m() == 40,
                     "f) a CompressedRowPattern reused: reinit() larger, assign() smaller, reinit() larger");
    }
    testing::check_throws(
      [&] {
        attempt({0, 2, 3, 5}, {2, 0, 1, 2, 0});
      },
      "row 0 does not start with its diagonal", "f) a row without its diagonal first");
    testing::check_throws(
      [&] {
        attempt({0, 3, 4, 5}, {0, 2, 1, 1, 2});
      },
      "the columns of row 0 are not ascending", "f) columns out of order");
  }
  return testing::finish();
}
