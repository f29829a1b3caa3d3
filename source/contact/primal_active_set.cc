// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/primal_active_set.h>
#include <dealvem/elasticity/piece_support.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace dealvem
{
  namespace
  {
    using ModeRow = std::vector<std::pair<unsigned int, double>>;

    // the value of a row over the modes on a mode vector
    double
    row_value(const ModeRow &row, const std::vector<double> &modes)
    {
      double v = 0;
      for (const auto &[j, c] : row)
        v += c * modes[j];
      return v;
    }
  } // namespace



  std::string
  CollapseMechanism::describe(const std::vector<ContactNodePair> &pairs) const
  {
    std::ostringstream out;
    out << "collapse mechanism (a rigid motion that every contact and support allows and on which the loads do "
           "positive work: the proof that no equilibrium exists): "
        << moving.size() << " piece(s) move";
    out.precision(4);
    for (const auto &m : moving)
      {
        out << "\n    body " << m.body;
        if (m.rotates)
          out << " rotates by " << m.rotation << " about (" << m.centre << ")";
        else
          out << " translates by (" << m.translation << ")";
      }
    if (!closed_pairs.empty())
      {
        out << "\n    it stays in contact (hinges, or points it slides on) at";
        const unsigned int shown = std::min<unsigned int>(closed_pairs.size(), 12);
        for (unsigned int j = 0; j < shown; ++j)
          out << (j > 0 ? "," : "") << " (" << pairs[closed_pairs[j]].slave_location << ")";
        if (closed_pairs.size() > shown)
          out << " and " << closed_pairs.size() - shown << " more";
      }
    out << "\n    failing condition: " << failing_condition << " (" << opening_pairs.size()
        << " pair(s) open, " << sliding_pairs.size() << " slide); work of the loads " << work
        << " for a largest displacement 1 (cosine with the loads " << relative_work
        << "); largest violation of the contact conditions " << largest_violation;
    if (!friction_pairs.empty())
      out << "\n    " << friction_pairs.size() << " pair(s) slide against their friction bound, which can absorb "
          << friction_dissipation << " of that work at most";
    return out.str();
  }



  template <int dim>
  PrimalActiveSetSolver<dim>::PrimalActiveSetSolver(const ContactAssembler<dim>             &contact,
                                                    const dealii::AffineConstraints<double> &constraints,
                                                    SaddlePointSolver                       &solver,
                                                    const ContactSettings                   &settings)
    : contact(contact)
    , constraints(constraints)
    , solver(solver)
    , settings(settings)
    , stick(settings.tangential == ContactSettings::Tangential::penalty ||
            settings.tangential == ContactSettings::Tangential::multipliers)
    , pieces(std::make_unique<PieceSupport>(contact.get_dof_handler()))
  {
    AssertThrow(settings.normal == ContactSettings::Normal::unilateral && !settings.is_coulomb(),
                dealii::ExcMessage("PrimalActiveSetSolver solves unilateral contact, frictionless or with "
                                   "stick (Tangential = frictionless, penalty or multipliers)."));
    const auto        &dh     = contact.get_dof_handler();
    const unsigned int n_dofs = dh.n_dofs();
    dof_piece.assign(n_dofs, dealii::numbers::invalid_unsigned_int);
    for (unsigned int dof = 0; dof < n_dofs; ++dof)
      if (const auto &ps = pieces->pieces_of_node(dof / 2); !ps.empty())
        dof_piece[dof] = ps.front();

    // a linear form over DoFs as a row over the modes (first piece of
    // each node), and in PieceSupport's convention
    const auto to_modes = [&](const PieceSupport::Form &form) {
      std::map<unsigned int, double> row;
      for (const auto &[dof, c] : form)
        if (const unsigned int p = dof_piece[dof]; p != dealii::numbers::invalid_unsigned_int)
          for (unsigned int k = 0; k < 3; ++k)
            row[3 * p + k] += c * pieces->mode(p, k, dof);
      ModeRow r;
      for (const auto &e : row)
        if (e.second != 0.)
          r.push_back(e);
      return r;
    };
    PieceSupport::Form form;
    for (const auto &line : constraints.get_lines())
      {
        if (line.index >= n_dofs)
          continue;
        form.assign(1, {line.index, 1.});
        for (const auto &e : line.entries)
          form.emplace_back(e.first, -e.second);
        constraint_rows.push_back(to_modes(form));
        pieces->add_rows(form, support_constraint_rows);
      }
    const auto &pairs = contact.get_pairs();
    normal_rows.resize(pairs.size());
    tangential_rows.resize(pairs.size());
    support_normal_rows.resize(pairs.size());
    support_tangential_rows.resize(pairs.size());
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto d = contact.pair_dofs(i);
        for (unsigned int dir = 0; dir < 2; ++dir)
          {
            const auto &v = (dir == 0 ? pairs[i].normal : pairs[i].tangent);
            form          = {{d[0], -v[0]}, {d[1], -v[1]}, {d[2], v[0]}, {d[3], v[1]}};
            (dir == 0 ? normal_rows : tangential_rows)[i] = to_modes(form);
            pieces->add_rows(form, (dir == 0 ? support_normal_rows : support_tangential_rows)[i]);
          }
      }
  }



  template <int dim>
  PrimalActiveSetSolver<dim>::~PrimalActiveSetSolver() = default;



  template <int dim>
  std::vector<std::vector<double>>
  PrimalActiveSetSolver<dim>::free_motions(const std::vector<bool> &closed,
                                           const std::vector<bool> &tangential) const
  {
    const auto &pairs = contact.get_pairs();
    std::vector<const PieceSupport::Row *> rows;
    for (const auto &r : support_constraint_rows)
      rows.push_back(&r);
    for (unsigned int i = 0; i < pairs.size(); ++i)
      if (!pairs[i].junction)
        {
          if (closed[i])
            for (const auto &r : support_normal_rows[i])
              rows.push_back(&r);
          if (tangential[i])
            for (const auto &r : support_tangential_rows[i])
              rows.push_back(&r);
        }
    const auto motions = pieces->free_motions(rows);
    if (motions.empty())
      return {};
    // every mode of the pieces that a free motion moves, and the null space
    // of all rows restricted to them (the other pieces are held)
    std::vector<unsigned int> column(pieces->n_modes(), dealii::numbers::invalid_unsigned_int), modes;
    for (const auto &m : motions)
      for (const auto j : m)
        if (column[3 * (j / 3)] == dealii::numbers::invalid_unsigned_int)
          for (unsigned int k = 0; k < 3; ++k)
            {
              column[3 * (j / 3) + k] = modes.size();
              modes.push_back(3 * (j / 3) + k);
            }
    std::vector<const ModeRow *> all;
    for (const auto &r : constraint_rows)
      all.push_back(&r);
    for (unsigned int i = 0; i < pairs.size(); ++i)
      if (!pairs[i].junction)
        {
          if (closed[i])
            all.push_back(&normal_rows[i]);
          if (tangential[i])
            all.push_back(&tangential_rows[i]);
        }
    std::vector<const ModeRow *> touching;
    for (const auto *r : all)
      for (const auto &e : *r)
        if (column[e.first] != dealii::numbers::invalid_unsigned_int)
          {
            touching.push_back(r);
            break;
          }
    const unsigned int N = modes.size();
    Eigen::MatrixXd    A = Eigen::MatrixXd::Zero(std::max<std::size_t>(touching.size(), 1), N);
    for (unsigned int r = 0; r < touching.size(); ++r)
      for (const auto &e : *touching[r])
        if (column[e.first] != dealii::numbers::invalid_unsigned_int)
          A(r, column[e.first]) += e.second;
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
    const auto                             &sigma = svd.singularValues();
    const double                            smax  = sigma.size() > 0 ? sigma.maxCoeff() : 0.;
    std::vector<std::vector<double>>        basis;
    for (unsigned int k = 0; k < N; ++k)
      {
        const double s = (k < sigma.size() ? sigma(k) : 0.);
        if (smax == 0 || s <= 1e-6 * smax)
          {
            std::vector<double> z(pieces->n_modes(), 0.);
            for (unsigned int j = 0; j < N; ++j)
              z[modes[j]] = svd.matrixV()(j, k);
            basis.push_back(std::move(z));
          }
      }
    return basis;
  }



  template <int dim>
  dealii::Vector<double>
  PrimalActiveSetSolver<dim>::motion_field(const std::vector<double> &modes) const
  {
    dealii::Vector<double> d(dof_piece.size());
    for (unsigned int dof = 0; dof < dof_piece.size(); ++dof)
      if (const unsigned int p = dof_piece[dof]; p != dealii::numbers::invalid_unsigned_int)
        for (unsigned int k = 0; k < 3; ++k)
          if (modes[3 * p + k] != 0.)
            d[dof] += modes[3 * p + k] * pieces->mode(p, k, dof);
    return d;
  }



  template <int dim>
  CollapseMechanism
  PrimalActiveSetSolver<dim>::make_mechanism(const std::vector<double> &modes_in,
                                             const std::vector<bool>   &tangential,
                                             const std::vector<double> &bound) const
  {
    const auto        &pairs = contact.get_pairs();
    const auto        &cp    = pieces->get_pieces();
    CollapseMechanism  m;
    std::vector<double> modes = modes_in;
    m.displacement            = motion_field(modes);
    // scale: largest nodal displacement 1
    double dmax = 0;
    for (unsigned int node = 0; 2 * node + 1 < m.displacement.size(); ++node)
      dmax = std::max(dmax, std::hypot(m.displacement[2 * node], m.displacement[2 * node + 1]));
    AssertThrow(dmax > 0, dealii::ExcInternalError());
    for (auto &v : modes)
      v /= dmax;
    m.displacement /= dmax;
    double wnorm = 0, anorm = 0;
    for (unsigned int j = 0; j < modes.size(); ++j)
      {
        m.work += mode_work[j] * modes[j];
        wnorm += mode_work[j] * mode_work[j];
        anorm += modes[j] * modes[j];
      }
    m.relative_work = m.work / std::sqrt(std::max(wnorm * anorm, 1e-300));
    // the conditions, relative to the largest displacement (1)
    for (const auto &r : constraint_rows)
      m.largest_violation = std::max(m.largest_violation, std::abs(row_value(r, modes)));
    // per piece: its motion
    std::vector<bool> moves(cp.n_pieces(), false);
    for (unsigned int p = 0; p < cp.n_pieces(); ++p)
      {
        const double t0 = modes[3 * p], t1 = modes[3 * p + 1], r = modes[3 * p + 2];
        if (std::abs(t0) + std::abs(t1) + std::abs(r) <= 1e-9)
          continue;
        moves[p] = true;
        CollapseMechanism::PieceMotion pm;
        pm.piece          = p;
        pm.body           = cp.body(p);
        pm.centroid       = cp.centroid(p);
        pm.translation[0] = t0;
        pm.translation[1] = t1;
        pm.rotation       = r / cp.size(p);
        pm.rotates        = std::abs(r) > 1e-9 * std::hypot(t0, t1);
        if (pm.rotates)
          pm.centre = pm.centroid + dealii::Tensor<1, 2>({-t1 / pm.rotation, t0 / pm.rotation});
        m.moving.push_back(pm);
      }
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        if (pairs[i].junction)
          continue;
        const double gn = row_value(normal_rows[i], modes), gt = row_value(tangential_rows[i], modes);
        m.largest_violation = std::max(m.largest_violation, -gn);
        const auto   d      = contact.pair_dofs(i);
        const unsigned int pa = dof_piece[d[0]], pb = dof_piece[d[2]];
        const bool   involved = (pa != dealii::numbers::invalid_unsigned_int && moves[pa]) ||
                              (pb != dealii::numbers::invalid_unsigned_int && moves[pb]);
        if (tangential[i])
          m.largest_violation = std::max(m.largest_violation, std::abs(gt));
        // Tresca bounds: the friction force b_i opposes the slide
        if (!bound.empty() && !tangential[i])
          m.friction_dissipation += bound[i] * std::abs(gt);
        if (!involved)
          continue;
        if (gn > 1e-8)
          m.opening_pairs.push_back(i);
        else
          {
            // closed: a hinge or a contact it slides on, unless both sides
            // move together
            const bool same = (pa == pb) || (pa != dealii::numbers::invalid_unsigned_int &&
                                             pb != dealii::numbers::invalid_unsigned_int && moves[pa] &&
                                             moves[pb] &&
                                             std::abs(modes[3 * pa + 2] / cp.size(pa) -
                                                      modes[3 * pb + 2] / cp.size(pb)) <= 1e-8 &&
                                             std::abs(gt) <= 1e-8);
            if (!same)
              {
                m.closed_pairs.push_back(i);
                m.closed_pair_bodies.emplace_back(
                  pa != dealii::numbers::invalid_unsigned_int ? cp.body(pa) : 0u,
                  pb != dealii::numbers::invalid_unsigned_int ? cp.body(pb) : 0u);
                m.closed_pair_locations.push_back(pairs[i].slave_location);
              }
            if (!tangential[i] && std::abs(gt) > 1e-8)
              {
                m.sliding_pairs.push_back(i);
                if (!bound.empty() && bound[i] > 0)
                  m.friction_pairs.push_back(i);
              }
          }
      }
    if (!m.friction_pairs.empty())
      m.failing_condition = std::string("friction (closed pairs slide against their friction bound") +
                            (m.opening_pairs.empty() ? std::string(")") :
                                                       std::string("; and no-tension joints: pairs open)"));
    else if (!m.opening_pairs.empty() && !m.sliding_pairs.empty())
      m.failing_condition = "no-tension joints and frictionless sliding (pairs open, and closed pairs slide)";
    else if (!m.sliding_pairs.empty())
      m.failing_condition = "frictionless sliding (closed pairs slide, none opens)";
    else if (!m.opening_pairs.empty())
      m.failing_condition = std::string("no-tension joints (pairs open") +
                            (stick ? "; nothing slides: the joints stick)" : ")");
    else
      m.failing_condition = "no support (the moving bodies touch nothing in the direction they move)";
    return m;
  }



  template <int dim>
  typename PrimalActiveSetSolver<dim>::Result
  PrimalActiveSetSolver<dim>::solve(const dealii::SparseMatrix<double> &system_matrix,
                                    const dealii::Vector<double>       &system_rhs,
                                    dealii::SparseMatrix<double>       &matrix,
                                    dealii::Vector<double>             &x)
  {
    on_closed_only = false;
    return iterate(system_matrix, system_rhs, matrix, x, nullptr);
  }



  template <int dim>
  typename PrimalActiveSetSolver<dim>::Result
  PrimalActiveSetSolver<dim>::solve_stick_on_closed(const dealii::SparseMatrix<double> &system_matrix,
                                                    const dealii::Vector<double>       &system_rhs,
                                                    dealii::SparseMatrix<double>       &matrix,
                                                    dealii::Vector<double>             &x,
                                                    const std::vector<bool>            &active)
  {
    on_closed_only = stick;
    auto r         = iterate(system_matrix, system_rhs, matrix, x, &active);
    on_closed_only = false;
    return r;
  }



  template <int dim>
  typename PrimalActiveSetSolver<dim>::Result
  PrimalActiveSetSolver<dim>::solve_tresca(const dealii::SparseMatrix<double> &system_matrix,
                                           const dealii::Vector<double>       &system_rhs,
                                           dealii::SparseMatrix<double>       &matrix,
                                           dealii::Vector<double>             &x,
                                           const std::vector<double>          &bound,
                                           const std::vector<bool>            &active,
                                           const std::vector<PairState>       &state)
  {
    const unsigned int n_pairs = contact.n_pairs();
    AssertThrow(stick, dealii::ExcMessage("PrimalActiveSetSolver::solve_tresca() needs a stick model "
                                          "(Tangential = penalty or multipliers) in its settings."));
    AssertThrow(bound.size() == n_pairs && active.size() == n_pairs && state.size() == n_pairs,
                dealii::ExcMessage("PrimalActiveSetSolver::solve_tresca(): " + std::to_string(bound.size()) +
                                   " bounds, " + std::to_string(active.size()) + " closed flags and " +
                                   std::to_string(state.size()) + " states for " + std::to_string(n_pairs) +
                                   " pairs."));
    for (unsigned int i = 0; i < n_pairs; ++i)
      AssertThrow(std::isfinite(bound[i]) && bound[i] >= 0,
                  dealii::ExcMessage("PrimalActiveSetSolver::solve_tresca(): the friction bound of pair " +
                                     std::to_string(i) + " is " + std::to_string(bound[i]) +
                                     "; it must be finite and >= 0."));
    on_closed_only = false;
    tresca_bound   = bound;
    tresca_start   = state;
    Result r;
    try
      {
        r = iterate(system_matrix, system_rhs, matrix, x, &active);
      }
    catch (...)
      {
        tresca_bound.clear();
        throw;
      }
    tresca_bound.clear();
    return r;
  }



  // iterate() and its Iteration: primal_active_set_iteration.cc

  template class PrimalActiveSetSolver<2>;
} // namespace dealvem
