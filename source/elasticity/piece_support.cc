// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/elasticity/piece_support.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace dealvem
{
  namespace
  {
    using Row = PieceSupport::Row;

    // whether a 3x3 Gram matrix of the rows of a piece has rank 3 (the
    // rows hold all three rigid motions of the piece)
    bool
    full_rank(const Eigen::Matrix3d &g)
    {
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(g);
      return eig.eigenvalues()(2) > 0 && eig.eigenvalues()(0) > 1e-10 * eig.eigenvalues()(2);
    }



    // The rows of the free_motions() check sorted by the pieces they
    // touch (a column 3 p + k of a row is motion k of piece p), and which
    // pieces the rows hold.
    struct PieceRows
    {
      PieceRows(const std::vector<const Row *> &rows, const unsigned int n_pieces);

      // the Gram matrix of piece @p p's own rows plus its part of the rows
      // that touch it and otherwise only held pieces
      Eigen::Matrix3d
      restricted_gram(const unsigned int p) const;

      // step 1b: pieces held through held pieces (see free_motions())
      void
      hold_through_held_pieces();

      const std::vector<const Row *>        &rows;
      std::vector<Eigen::Matrix3d>           own;     // the Gram matrix of the rows of each piece alone
      std::vector<bool>                      single;  // whether a row touches one piece only
      std::vector<bool>                      held;    // whether a piece is held
      std::vector<std::vector<unsigned int>> rows_of; // the rows that touch a piece and another one
    };



    // step 1: the pieces held by the rows that touch them alone
    PieceRows::PieceRows(const std::vector<const Row *> &rows, const unsigned int n_pieces)
      : rows(rows)
      , own(n_pieces, Eigen::Matrix3d::Zero())
      , single(rows.size(), true)
      , held(n_pieces, false)
      , rows_of(n_pieces)
    {
      for (unsigned int r = 0; r < rows.size(); ++r)
        {
          const auto &row = *rows[r];
          for (const auto &e : row)
            single[r] = single[r] && (e.first / 3 == row.front().first / 3);
          if (single[r] && !row.empty())
            {
              const unsigned int p = row.front().first / 3;
              Eigen::Vector3d    v = Eigen::Vector3d::Zero();
              for (const auto &e : row)
                v(e.first % 3) += e.second;
              own[p] += v * v.transpose();
            }
        }
      for (unsigned int p = 0; p < n_pieces; ++p)
        held[p] = full_rank(own[p]);
      for (unsigned int r = 0; r < rows.size(); ++r)
        if (!single[r])
          for (const auto &e : *rows[r])
            if (rows_of[e.first / 3].empty() || rows_of[e.first / 3].back() != r)
              rows_of[e.first / 3].push_back(r);
    }



    Eigen::Matrix3d
    PieceRows::restricted_gram(const unsigned int p) const
    {
      Eigen::Matrix3d g = own[p];
      for (const unsigned int r : rows_of[p])
        {
          Eigen::Vector3d v      = Eigen::Vector3d::Zero();
          bool            others = false;
          for (const auto &e : *rows[r])
            if (e.first / 3 == p)
              v(e.first % 3) += e.second;
            else
              others = others || !held[e.first / 3];
          if (!others)
            g += v * v.transpose();
        }
      return g;
    }



    void
    PieceRows::hold_through_held_pieces()
    {
      const unsigned int        n_pieces = held.size();
      std::vector<unsigned int> work;
      std::vector<bool>         queued(n_pieces, false);
      const auto                queue_neighbours = [&](const unsigned int p) {
        for (const unsigned int r : rows_of[p])
          for (const auto &e : *rows[r])
            if (const unsigned int q = e.first / 3; !held[q] && !queued[q])
              {
                queued[q] = true;
                work.push_back(q);
              }
      };
      for (unsigned int p = 0; p < n_pieces; ++p)
        if (held[p])
          queue_neighbours(p);
      while (!work.empty())
        {
          const unsigned int p = work.back();
          work.pop_back();
          queued[p] = false;
          if (held[p])
            continue;
          if (full_rank(restricted_gram(p)))
            {
              held[p] = true;
              queue_neighbours(p);
            }
        }
    }



    // step 3: the free motions of the unheld pieces @p rest that rows
    // couple to one another (@p column: the index of each piece in
    // @p rest), from the null space of the dense Gram matrix of the rows
    // with the columns of the other pieces dropped; appended to @p motions.
    void
    add_coupled_motions(const std::vector<const Row *> &rows, const std::vector<unsigned int> &rest,
                        const std::vector<unsigned int> &column, std::vector<std::vector<unsigned int>> &motions)
    {
      const unsigned int N    = 3 * rest.size();
      Eigen::MatrixXd    gram = Eigen::MatrixXd::Zero(N, N);
      std::vector<std::pair<unsigned int, double>> reduced;
      for (unsigned int r = 0; r < rows.size(); ++r)
        {
          reduced.clear();
          for (const auto &e : *rows[r])
            if (const unsigned int p = e.first / 3; column[p] != dealii::numbers::invalid_unsigned_int)
              reduced.emplace_back(3 * column[p] + e.first % 3, e.second);
          for (const auto &a : reduced)
            for (const auto &b : reduced)
              gram(a.first, b.first) += a.second * b.second;
        }
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram);
      const double vmax = std::max(eig.eigenvalues().maxCoeff(), 0.);
      for (unsigned int k = 0; k < N; ++k)
        if (vmax == 0 || eig.eigenvalues()(k) <= 1e-10 * vmax)
          {
            std::vector<unsigned int> m;
            for (unsigned int j = 0; j < N; ++j)
              if (std::abs(eig.eigenvectors()(j, k)) > 1e-3)
                m.push_back(3 * rest[j / 3] + j % 3);
            motions.push_back(m);
          }
    }
  } // namespace



  PieceSupport::PieceSupport(const VEMDoFHandler<2> &dof_handler)
    : pieces(dof_handler.get_mesh())
    , dof_handler(dof_handler)
    , node_pieces(dof_handler.n_nodes())
  {
    const auto               &mesh = dof_handler.get_mesh();
    std::vector<unsigned int> nodes;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const unsigned int p = pieces.piece_of_cell(c);
        dof_handler.get_node_indices(c, nodes);
        for (const auto n : nodes)
          if (std::find(node_pieces[n].begin(), node_pieces[n].end(), p) == node_pieces[n].end())
            node_pieces[n].push_back(p);
      }
  }



  double
  PieceSupport::mode(const unsigned int p, const unsigned int k, const dealii::types::global_dof_index dof) const
  {
    const unsigned int node = dof / 2, comp = dof % 2;
    if (k < 2)
      return (k == comp ? 1. : 0.);
    const auto x = dof_handler.node_location(node) - pieces.centroid(p);
    return (comp == 0 ? -x[1] : x[0]) / pieces.size(p);
  }



  void
  PieceSupport::add_rows(const Form &form, std::vector<Row> &rows) const
  {
    // the pieces at hinge nodes of the form: one row for each
    std::vector<unsigned int> choices;
    double                    magnitude = 0;
    for (const auto &[dof, c] : form)
      {
        magnitude += std::abs(c);
        const auto &ps = node_pieces[dof / 2];
        if (ps.size() > 1)
          for (const auto p : ps)
            if (std::find(choices.begin(), choices.end(), p) == choices.end())
              choices.push_back(p);
      }
    if (choices.empty())
      choices.push_back(dealii::numbers::invalid_unsigned_int);
    for (const auto choice : choices)
      {
        std::map<unsigned int, double> row;
        for (const auto &[dof, c] : form)
          {
            const auto &ps = node_pieces[dof / 2];
            if (ps.empty())
              continue;
            const unsigned int p =
              (std::find(ps.begin(), ps.end(), choice) != ps.end() ? choice : ps.front());
            for (unsigned int k = 0; k < 3; ++k)
              if (const double v = mode(p, k, dof); v != 0)
                row[3 * p + k] += c * v;
          }
        // a form that the rigid motions satisfy (a rigid boundary) holds
        // nothing: its row is round-off
        double norm = 0;
        for (const auto &e : row)
          norm += e.second * e.second;
        if (std::sqrt(norm) <= 1e-10 * std::max(magnitude, 1.))
          continue;
        rows.emplace_back(row.begin(), row.end());
      }
  }



  std::vector<std::vector<unsigned int>>
  PieceSupport::free_motions(const std::vector<const Row *> &rows) const
  {
    const unsigned int n_pieces = pieces.n_pieces();
    // 1. pieces held by the rows that touch them alone
    PieceRows piece_rows(rows, n_pieces);
    // 1b. held through held pieces: a piece whose part of the rows that
    // touch it and otherwise only held pieces has rank 3 is held too (any
    // free motion vanishes on the held pieces, so these rows restrict the
    // piece alone); repeated from the pieces just held, so that a stack or
    // a row of many bodies resting on one another costs time linear in the
    // rows, and the dense test of step 3 only sees pieces held through one
    // another in a loop
    piece_rows.hold_through_held_pieces();
    const std::vector<bool> &held   = piece_rows.held;
    const std::vector<bool> &single = piece_rows.single;
    // 2. an unheld piece that no row couples to another: its own null space
    std::vector<bool> coupled(n_pieces, false);
    for (unsigned int r = 0; r < rows.size(); ++r)
      if (!single[r])
        {
          std::vector<unsigned int> touched;
          for (const auto &e : *rows[r])
            if (!held[e.first / 3])
              touched.push_back(e.first / 3);
          std::sort(touched.begin(), touched.end());
          if (!touched.empty() && touched.front() != touched.back())
            for (const auto p : touched)
              coupled[p] = true;
        }
    std::vector<std::vector<unsigned int>> motions;
    std::vector<unsigned int>              rest, column(n_pieces, dealii::numbers::invalid_unsigned_int);
    for (unsigned int p = 0; p < n_pieces; ++p)
      if (!held[p] && !coupled[p])
        {
          // (the rows of held partners fix nothing of this piece beyond its
          // own rows: add its part of the rows that touch held pieces too)
          const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(piece_rows.restricted_gram(p));
          const double vmax = std::max(eig.eigenvalues()(2), 0.);
          for (unsigned int k = 0; k < 3; ++k)
            if (vmax == 0 || eig.eigenvalues()(k) <= 1e-10 * vmax)
              {
                std::vector<unsigned int> m;
                for (unsigned int j = 0; j < 3; ++j)
                  if (std::abs(eig.eigenvectors()(j, k)) > 1e-3)
                    m.push_back(3 * p + j);
                motions.push_back(m);
              }
        }
      else if (!held[p])
        {
          column[p] = rest.size();
          rest.push_back(p);
        }
    // 3. the coupled unheld pieces together, the held pieces' columns dropped
    if (rest.empty())
      return motions;
    AssertThrow(rest.size() <= 400,
                dealii::ExcMessage("Unsupported pieces: " + std::to_string(rest.size()) +
                                   " edge-connected pieces of the meshes are held only through one another "
                                   "(the first: " + pieces.describe(rest.front()) +
                                   "), more than the 400 whose free motions the dense check of such pieces can "
                                   "find. Either a mesh file has that many cells that share no edge with the "
                                   "rest of their body (check the files), or an assembly of that many bodies "
                                   "is held only by contacts that this iteration left open or slipping: hold "
                                   "more of them by Dirichlet, roller or point constraints, or by contacts that "
                                   "stick."));
    add_coupled_motions(rows, rest, column, motions);
    return motions;
  }



  std::string
  PieceSupport::describe(const std::vector<std::vector<unsigned int>> &motions, const bool with_body) const
  {
    const char        *names[3] = {"x-translation", "y-translation", "rotation"};
    std::ostringstream msg;
    for (const auto &m : motions)
      {
        msg << (msg.tellp() > 0 ? " " : "") << "[";
        for (unsigned int j = 0; j < m.size(); ++j)
          {
            const unsigned int p = m[j] / 3;
            msg << (j == 0 ? "" : " + ") << names[m[j] % 3];
            if (with_body)
              msg << " of body " << int(pieces.body(p));
            if (pieces.n_pieces_of_body(pieces.body(p)) > 1)
              msg << (with_body ? ", " : " of ") << "piece " << pieces.index_in_body(p);
          }
        msg << "]";
      }
    return msg.str();
  }



  std::string
  PieceSupport::describe_pieces(const std::vector<std::vector<unsigned int>> &motions) const
  {
    std::set<unsigned int> named;
    for (const auto &m : motions)
      for (const auto j : m)
        if (pieces.n_pieces_of_body(pieces.body(j / 3)) > 1)
          named.insert(j / 3);
    std::ostringstream msg;
    for (const auto p : named)
      msg << (msg.tellp() > 0 ? "; " : "") << pieces.describe(p);
    return msg.str();
  }



  std::string
  PieceSupport::describe_hinges(const std::vector<std::vector<unsigned int>> &motions) const
  {
    std::set<unsigned int> moving;
    for (const auto &m : motions)
      for (const auto j : m)
        moving.insert(j / 3);
    std::ostringstream msg;
    std::set<std::pair<unsigned int, unsigned int>> named;
    const auto &mesh = dof_handler.get_mesh();
    for (unsigned int v = 0; v < mesh.n_vertices() && v < node_pieces.size(); ++v)
      if (node_pieces[v].size() > 1)
        for (const auto p : node_pieces[v])
          if (moving.count(p) > 0)
            for (const auto q : node_pieces[v])
              if (q != p && named.insert({p, q}).second)
                msg << " Piece " << pieces.index_in_body(p) << " of body " << int(pieces.body(p))
                    << " touches piece " << pieces.index_in_body(q) << " at the vertex (" << mesh.vertex(v)[0]
                    << ", " << mesh.vertex(v)[1] << ") only: a hinge, not a connection.";
    return msg.str();
  }
} // namespace dealvem
