// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// FiniteSliding: a load step (its cutbacks, its increments with the
// pairing passes and their Anderson acceleration, the extrapolation of the
// state where a step is expected to end, and the check of the supports).

#include "finite_sliding_impl.h"

namespace dealvem
{
  using namespace internal::finite_sliding;

  void
  FiniteSliding::Impl::solve_step(const unsigned int step, const double time)
  {
    AssertThrow(constraints_function,
                dealii::ExcMessage("FiniteSliding: set_constraints_function() must be called before the first step."));
    AssertThrow(std::isfinite(time),
                dealii::ExcMessage("FiniteSliding: the time of step " + std::to_string(step) + " is not finite."));
    StepRecord total;
    total.n_substeps = 0;
    solve_with_cutbacks(step, last_time, time, 0, total);
    history.push_back(total);
  }



  void
  FiniteSliding::Impl::solve_with_cutbacks(const unsigned int step,
                                     const double       t_start,
                                     const double       time,
                                     const unsigned int depth,
                                     StepRecord        &total)
  {
    StepRecord record;
    try
      {
        solve_increment(step, time, record);
      }
    catch (const ExcStepInput &)
      {
        throw;
      }
    catch (const dealii::ExceptionBase &e)
      {
        // the state is still that of t_start: the step is solved again as
        // two halves (the constraints and loads at the middle time), down
        // to 2^-max_cutbacks of it
        if (depth >= parameters.max_cutbacks)
          {
            if (parameters.max_cutbacks == 0)
              throw;
            std::ostringstream info;
            e.print_info(info);
            AssertThrow(false, dealii::ExcMessage("FiniteSliding: step " + std::to_string(step) +
                                                  ": its sub-step from the time " + std::to_string(t_start) + " to " +
                                                  std::to_string(time) + " (1/" + std::to_string(1u << depth) +
                                                  " of the step, after " + std::to_string(depth) +
                                                  " cutbacks, Parameters::max_cutbacks) failed: " + info.str()));
          }
        // (the work of the failed attempt counts in the step's record)
        total.n_passes += record.n_passes;
        total.setup_time += record.setup_time;
        total.solve_time += record.solve_time;
        total.newton.insert(total.newton.end(), record.newton.begin(), record.newton.end());
        total.pairing_offsets.insert(total.pairing_offsets.end(), record.pairing_offsets.begin(),
                                     record.pairing_offsets.end());
        const double middle = 0.5 * (t_start + time);
        solve_with_cutbacks(step, t_start, middle, depth + 1, total);
        solve_with_cutbacks(step, middle, time, depth + 1, total);
        return;
      }
    // the record of the step: the state of its last sub-step, the work
    // (passes, Newton, times) of all attempts, the dissipation of the
    // converged sub-steps
    const auto passes = total.n_passes, substeps = total.n_substeps;
    const double setup = total.setup_time, solve = total.solve_time, dissipation = total.dissipation;
    auto newton  = std::move(total.newton);
    auto offsets = std::move(total.pairing_offsets);
    newton.insert(newton.end(), record.newton.begin(), record.newton.end());
    offsets.insert(offsets.end(), record.pairing_offsets.begin(), record.pairing_offsets.end());
    total                 = record;
    total.n_passes        = passes + record.n_passes;
    total.n_substeps      = substeps + 1;
    total.setup_time      = setup + record.setup_time;
    total.solve_time      = solve + record.solve_time;
    total.dissipation     = dissipation + record.dissipation;
    total.newton          = std::move(newton);
    total.pairing_offsets = std::move(offsets);
  }



  void
  FiniteSliding::Impl::solve_increment(const unsigned int step, const double time, StepRecord &record)
  {
    record.step        = step;
    record.time        = time;
    record.load_factor = load_factor_function ? load_factor_function(time) : time;
    AssertThrow(std::isfinite(record.load_factor),
                dealii::ExcMessage("FiniteSliding: the load factor at the time " + std::to_string(time) +
                                   " is not finite."));

    // the converged state of the last step is where this one starts
    if (!last_failed && current != nullptr && parameters.reinsert)
      {
        if (start != nullptr && n_converged >= 2)
          start_previous_solution = transfer(*start, start_solution, *current);
        else
          start_previous_solution.reinit(0);
        // the objects of the last pass refer to it and stay alive with it
        start             = std::move(current);
        start_solution    = solution;
        start_multipliers = multipliers;
      }
    last_failed = true;

    // (the passes since the last release of merges, below: each release
    // gets the full budget of passes)
    unsigned int budget_start = 0;
    for (unsigned int pass = 1;; ++pass)
      {
        prepare_pass(time, record.load_factor, step, pass == 1, record);
        if (pass == 1)
          check_support(step, time);
        const auto clock = std::chrono::steady_clock::now();
        try
          {
            solver->solve_step(step, record.load_factor);
          }
        catch (const dealii::ExceptionBase &e)
          {
            // the state stays at the last converged step, on this mesh
            if (!parameters.reinsert)
              {
                solution    = solver->get_solution();
                multipliers = solver->get_multipliers();
              }
            else
              {
                solution = start != nullptr ? transfer(*start, start_solution, *current) :
                                              dealii::Vector<double>(current->dof_handler->n_dofs());
                multipliers.reinit(contact->n_constraints());
              }
            std::ostringstream info;
            e.print_info(info);
            AssertThrow(false, dealii::ExcMessage("FiniteSliding: step " + std::to_string(step) + " (time " +
                                                  std::to_string(time) + "), pass " + std::to_string(pass) +
                                                  " of the pairing: " + info.str()));
          }
        record.solve_time += std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
        record.newton.push_back(solver->get_history().back());
        record.n_passes = pass;
        solution        = solver->get_solution();
        multipliers     = solver->get_multipliers();
        evaluate(record);
        record.pairing_offsets.push_back(record.pairing_offset);

        if (!parameters.reinsert || (record.pairing_offset <= parameters.pairing_tolerance && record.n_uncovered == 0))
          {
            // A merge made in an earlier pass of the step and held by the
            // step's hysteresis (hold_step_merges()) is released when the
            // converged state has its two vertices farther apart than node
            // insertion merges: the step goes on without holding it. So the
            // step ends where the rules themselves put it, not where the
            // passes happened to pass by: a wheel carried along a race of
            // the same vertex spacing merged its vertex with the race's in
            // a pass whose pairs were still far off, held it at 4.5 % of
            // the sub-edges, and converged 1.7 % away (moment) from the
            // same step started from a prediction. A merge that node
            // insertion makes again after the release is held to the end of
            // the step.
            const auto loose = parameters.reinsert ? loose_merges() : decltype(loose_merges())();
            if (loose.empty())
              break;
            step_released.insert(loose.begin(), loose.end());
            budget_start = pass;
            continue;
          }
        redetect = record.n_uncovered > 0;
        AssertThrow(pass - budget_start < parameters.max_pairing_passes || record.n_uncovered == 0,
                    dealii::ExcMessage("FiniteSliding: step " + std::to_string(step) + " (time " +
                                       std::to_string(time) + "): after " + std::to_string(pass) +
                                       " passes of pairing at the converged state, " +
                                       std::to_string(record.n_uncovered) +
                                       " boundary edges still face another body on no interface of the pass "
                                       "(contact detection, 'Contact/Pairs = auto'); take smaller steps or raise "
                                       "Parameters::max_pairing_passes."));
        AssertThrow(pass - budget_start < parameters.max_pairing_passes,
                    dealii::ExcMessage("FiniteSliding: step " + std::to_string(step) + " (time " +
                                       std::to_string(time) + "): after " + std::to_string(pass) +
                                       " passes of pairing at the converged state, partners of active pairs are "
                                       "still " +
                                       internal::number_string(record.pairing_offset) +
                                       " of the sub-edges at the pair apart (tolerance " +
                                       internal::number_string(parameters.pairing_tolerance) + "; by pass: " +
                                       [&] {
                                         std::string list;
                                         for (const double o : record.pairing_offsets)
                                           list += (list.empty() ? "" : ", ") + internal::number_string(o);
                                         return list;
                                       }() +
                                       "); take smaller steps or raise Parameters::max_pairing_passes."));
      }

    // the pairs whose two nodes the constraints fix: the prescribed motion
    // must not make them penetrate (the solver leaves this check to the
    // last pass, where the partners are opposite each other)
    if (parameters.reinsert)
      {
        const double length = original.extent();
        for (unsigned int i = 0; i < contact->n_pairs(); ++i)
          if (contact->is_fixed(i) && !contact->get_pairs()[i].junction)
            {
              const double g = contact->value(i, solution);
              AssertThrow(g >= -1e-10 * length,
                          dealii::ExcMessage("FiniteSliding: step " + std::to_string(step) + " (time " +
                                             std::to_string(time) +
                                             "): the displacement constraints fix both nodes of the contact pair "
                                             "at (" +
                                             std::to_string(contact->get_pairs()[i].slave_location[0]) + ", " +
                                             std::to_string(contact->get_pairs()[i].slave_location[1]) +
                                             ") of interface " + std::to_string(contact->get_pairs()[i].interface) +
                                             " and make it penetrate (gap " + std::to_string(g) +
                                             "): the prescribed motions of the two bodies contradict the contact."));
            }
      }

    for (const auto &itf : pass_interfaces)
      if (itf.reported < reported.size() && reported[itf.reported].detected)
        detected_master.emplace(std::minmax(itf.master_body, itf.slave_body), itf.master_body);
    last_failed          = false;
    previous_time        = last_time;
    last_time            = time;
    previous_load_factor = last_load_factor;
    previous_step        = last_step;
    last_load_factor     = record.load_factor;
    last_step            = step;
    ++n_converged;
  }



  void
  FiniteSliding::Impl::check_support(const unsigned int step, const double time) const
  {
    // the rows by which the displacement constraints and the pairs closed
    // at the start of the step restrict the rigid-body modes of the pieces
    // (as RigidBodySupport does at small strain)
    const PieceSupport             pieces(*current->dof_handler);
    std::vector<PieceSupport::Row> rows;
    PieceSupport::Form             form;
    for (const auto &line : constraints.get_lines())
      {
        if (line.index >= current->dof_handler->n_dofs())
          continue;
        form.assign(1, {line.index, 1.});
        for (const auto &e : line.entries)
          form.emplace_back(e.first, -e.second);
        pieces.add_rows(form, rows);
      }
    const unsigned int np     = contact->n_pairs();
    const double       length = original.extent();
    // (tied contact and Coulomb friction, which sticks unless the load
    // overcomes it, hold the tangential direction too)
    const bool tangential = contact->n_constraints() == 2 * np;
    FiniteStrainConstraints::Linearization linearization;
    for (unsigned int i = 0; i < np; ++i)
      {
        if (contact->is_left_out(i))
          continue;
        const bool closed = contact->is_bilateral() || (i < multipliers.size() && multipliers[i] != 0) ||
                            contact->value(i, solution) <= 1e-9 * length;
        if (!closed)
          continue;
        for (const unsigned int j : {i, np + i})
          {
            if (j >= np && !tangential)
              continue;
            contact->linearize(j, solution, linearization, false);
            form.clear();
            for (unsigned int k = 0; k < linearization.dofs.size(); ++k)
              form.emplace_back(linearization.dofs[k], linearization.gradient[k]);
            pieces.add_rows(form, rows);
          }
      }
    std::vector<const PieceSupport::Row *> pointers;
    for (const auto &row : rows)
      pointers.push_back(&row);
    const auto motions = pieces.free_motions(pointers);
    if (motions.empty())
      return;
    AssertThrow(false,
                ExcStepInput("FiniteSliding: step " + std::to_string(step) + " (time " + std::to_string(time) +
                             "): the rigid-body motion " + pieces.describe(motions, true) +
                             " is held neither by the displacement constraints nor by a contact pair that is "
                             "closed where the step starts" +
                             (tangential ? std::string() :
                                           std::string(" (frictionless contact holds no tangential motion)")) +
                             ": Newton's matrix would be singular. A body held by contact alone must touch its "
                             "partner where the step starts; hold it by displacement constraints otherwise."));
  }



  dealii::Vector<double>
  FiniteSliding::Impl::relaxed_pairing_state()
  {
    // The passes of a step are a fixed-point iteration x_{k+1} = F(x_k):
    // x_k the positions of the interface vertices where pass k makes its
    // pairs, F(x_k) their positions at the converged state of that pass.
    // Plain repetition converges slowly where sticking pairs drag their
    // partners along (a factor up to 0.9 per pass), and flips between
    // mirror-image pairings where a vertex faces a kink of the other side
    // (factor -1 or worse: a 2-cycle, or growing); per-node secant factors
    // handle either alone but not their coupling (measured on the ironing
    // die: 12.7 passes per step against 10.5 here, frictionless, and
    // 7.8 against 6.8 with friction). Anderson acceleration (depth 5) fits
    // the residual r_k = F(x_k) - x_k by the differences of the last
    // passes' residuals and steps: g = argmin |r_k - dR g|, and the next
    // pairs are made at x_k + r_k - (dX + dR) g. The other nodes of an
    // interface edge take the plain update plus the correction of its two
    // end vertices interpolated along the edge.
    const auto  &dofs   = *current->dof_handler;
    const auto  &mesh   = *current->mesh;
    const double length = original.extent();
    // the interface vertices, their pairing positions x_k and the
    // residuals r_k of this pass
    const unsigned int  n = side_neighbours.size();
    std::vector<double> x(2 * n), r(2 * n);
    // (with detection, the vertices on the sides of the pass's interfaces
    // only: the rest of the free boundary takes the plain update, as off
    // a named side, and stays out of the fit)
    std::set<unsigned int> on_side;
    if (parameters.detection.enabled)
      for (const auto &sides : interface_sides)
        {
          on_side.insert(sides.first.begin(), sides.first.end());
          on_side.insert(sides.second.begin(), sides.second.end());
        }
    const auto fitted = [&](const unsigned int v) {
      return !parameters.detection.enabled || on_side.count(v) > 0;
    };
    {
      unsigned int i = 0;
      for (const auto &entry : side_neighbours)
        {
          // (a vertex moved along its side faces its partner by the move,
          // step 2 of prepare_pass(): it takes the plain update, and stays
          // out of the secants)
          if (fitted(entry.first) && mesh.vertex(entry.first) == original.vertex(entry.first))
            for (unsigned int comp = 0; comp < 2; ++comp)
              {
                const auto dof   = VEMDoFHandler<2>::node_dof(dofs.vertex_node(entry.first), comp);
                x[2 * i + comp] = mesh.vertex(entry.first)[comp] + pairing_base[dof];
                r[2 * i + comp] = solution[dof] - pairing_base[dof];
              }
          ++i;
        }
    }
    // (when the vertices moved along their sides change, the history
    // starts again: their coordinates are not comparable across that)
    std::set<unsigned int> moved;
    for (const auto &entry : side_neighbours)
      if (mesh.vertex(entry.first) != original.vertex(entry.first))
        moved.insert(entry.first);
    if (moved != anderson_moved || on_side != anderson_on_side)
      {
        anderson_x.clear();
        anderson_r.clear();
      }
    anderson_moved   = moved;
    anderson_on_side = on_side;
    const std::vector<double> next = anderson_next(x, r, length);
    return corrected_pairing_state(x, r, next, on_side, moved);
  }



  std::vector<double>
  FiniteSliding::Impl::anderson_next(const std::vector<double> &x, const std::vector<double> &r, const double length)
  {
    const unsigned int n = x.size() / 2;
    // Safeguard: where the residual grew since the last pass, the history
    // no longer describes the map (a pass changed which side of a kink a
    // partner lies on, or the fit was poor): it starts again from this
    // pass, whose plain update is halved; the vertices moved along their
    // sides, which the fit leaves out, take half updates for the rest of
    // the step. Ironing pressed to 0.25 instead of 0.2 stalled at offsets
    // of 1e-3 in sub-steps of 1/16 without this and converges with it.
    bool restart = false;
    if (!anderson_r.empty())
      {
        double now = 0, before = 0;
        for (unsigned int j = 0; j < 2 * n; ++j)
          {
            now += r[j] * r[j];
            before += anderson_r.back()[j] * anderson_r.back()[j];
          }
        if (now > before)
          {
            anderson_x.clear();
            anderson_r.clear();
            restart     = true;
            step_damped = true;
          }
      }
    anderson_x.push_back(x);
    anderson_r.push_back(r);
    const unsigned int depth = 5;
    if (anderson_x.size() > depth + 1)
      {
        anderson_x.erase(anderson_x.begin());
        anderson_r.erase(anderson_r.begin());
      }
    // Anderson: min |r_k - dR g| over the differences of the last passes,
    // x_{k+1} = x_k + r_k - (dX + dR) g
    std::vector<double> next(2 * n);
    const double omega = restart ? 0.5 : 1.0;
    for (unsigned int j = 0; j < 2 * n; ++j)
      next[j] = x[j] + omega * r[j];
    const unsigned int m = anderson_x.size() - 1;
    if (m > 0)
      {
        std::vector<std::vector<double>> dR(m, std::vector<double>(2 * n)), dX(m, std::vector<double>(2 * n));
        for (unsigned int c = 0; c < m; ++c)
          for (unsigned int j = 0; j < 2 * n; ++j)
            {
              dR[c][j] = anderson_r[c + 1][j] - anderson_r[c][j];
              dX[c][j] = anderson_x[c + 1][j] - anderson_x[c][j];
            }
        dealii::FullMatrix<double> A(m, m);
        dealii::Vector<double>     b(m), g(m);
        double                     scale = 0;
        for (unsigned int c = 0; c < m; ++c)
          {
            for (unsigned int d = 0; d < m; ++d)
              for (unsigned int j = 0; j < 2 * n; ++j)
                A(c, d) += dR[c][j] * dR[d][j];
            for (unsigned int j = 0; j < 2 * n; ++j)
              b[c] += dR[c][j] * r[j];
            scale = std::max(scale, A(c, c));
          }
        if (scale > std::pow(1e-12 * length, 2))
          {
            for (unsigned int c = 0; c < m; ++c)
              A(c, c) += 1e-10 * scale;
            dealii::FullMatrix<double> inverse(m, m);
            inverse.invert(A);
            inverse.vmult(g, b);
            // (differences that are dependent to round-off make the small
            // system singular: the fit is then dropped, and the pass takes
            // the plain update)
            bool finite = true;
            for (unsigned int c = 0; c < m; ++c)
              finite = finite && std::isfinite(g[c]);
            if (finite)
              for (unsigned int c = 0; c < m; ++c)
                for (unsigned int j = 0; j < 2 * n; ++j)
                  next[j] -= (dX[c][j] + dR[c][j]) * g[c];
            else
              {
                anderson_x.clear();
                anderson_r.clear();
              }
          }
      }
    return next;
  }



  dealii::Vector<double>
  FiniteSliding::Impl::corrected_pairing_state(const std::vector<double>    &x,
                                               const std::vector<double>    &r,
                                               const std::vector<double>    &next,
                                               const std::set<unsigned int> &on_side,
                                               const std::set<unsigned int> &moved) const
  {
    const auto &dofs   = *current->dof_handler;
    const auto &mesh   = *current->mesh;
    const auto  fitted = [&](const unsigned int v) {
      return !parameters.detection.enabled || on_side.count(v) > 0;
    };
    // the vertices go to x_{k+1}; the other nodes of an interface edge take
    // the plain update plus the correction of the vertices interpolated
    // along the edge
    std::map<unsigned int, dealii::Tensor<1, 2>> correction;
    {
      unsigned int i = 0;
      for (const auto &entry : side_neighbours)
        {
          if (!fitted(entry.first))
            ;
          else if (moved.count(entry.first) == 0)
            for (unsigned int comp = 0; comp < 2; ++comp)
              correction[entry.first][comp] = next[2 * i + comp] - x[2 * i + comp] - r[2 * i + comp];
          else if (step_damped)
            for (unsigned int comp = 0; comp < 2; ++comp)
              {
                const auto dof = VEMDoFHandler<2>::node_dof(dofs.vertex_node(entry.first), comp);
                correction[entry.first][comp] = -0.5 * (solution[dof] - pairing_base[dof]);
              }
          ++i;
        }
    }
    dealii::Vector<double> u = solution;
    const auto add = [&](const unsigned int node, const dealii::Tensor<1, 2> &c) {
      for (unsigned int comp = 0; comp < 2; ++comp)
        u[VEMDoFHandler<2>::node_dof(node, comp)] += c[comp];
    };
    for (const auto &[a, b, cell] : interface_edges)
      {
        const Chain chain = make_chain(mesh, a, b, cell, mesh.get_vertices());
        const auto &ca = correction[a], &cb = correction[b];
        for (unsigned int k = 1; k + 1 < chain.vertices.size(); ++k)
          add(dofs.vertex_node(chain.vertices[k]), (1 - chain.s[k]) * ca + chain.s[k] * cb);
        // the edge nodes at their places along the chain's edges (counted
        // from an edge's first vertex)
        const auto &positions = dofs.get_element_data().edge_node_positions();
        for (unsigned int k = 0; k + 1 < chain.vertices.size(); ++k)
          {
            const bool same_way = mesh.edge(chain.edges[k]).vertices[0] == chain.vertices[k];
            for (unsigned int j = 0; j < positions.size(); ++j)
              {
                const double t  = same_way ? positions[j] : 1. - positions[j];
                const double sm = (1 - t) * chain.s[k] + t * chain.s[k + 1];
                add(dofs.edge_node(chain.edges[k], j), (1 - sm) * ca + sm * cb);
              }
          }
      }
    for (const auto &[v, c] : correction)
      add(dofs.vertex_node(v), c);
    return u;
  }



  dealii::Vector<double>
  FiniteSliding::Impl::extrapolate(const Discretization &disc, const dealii::Vector<double> &u1,
                             const dealii::Vector<double> &u0, const double s) const
  {
    // Each edge-connected piece moves from x0 = X + u0 to x1 = X + u1 by a
    // rigid motion (the least-squares fit over its nodes: the rotation
    // theta about the centroid, and the move of the centroid from c0 to c1)
    // and a remainder r. A planar rigid motion that turns is a rotation by
    // theta about one fixed point q, (I - R(theta)) q = c1 - R(theta) c0:
    // for a gear, its centre, wherever the piece's centroid lies. The
    // prediction continues that motion, a turn by s theta about q, and adds
    // s r. Exact for rigid rotations about a fixed point (a bore turned
    // about its centre at a steady rate) and for translations (q at
    // infinity; the formula below has the limit), and the linear
    // extrapolation without rotation. Written without q:
    //   x2 = x1 + M [(x1 - c1) - R(theta) (x1 - c0)] + s r,
    //   M  = (R(s theta) - I)(I - R(theta))^-1
    //      = -sin(s theta / 2) / sin(theta / 2) R((s - 1) theta / 2),
    // which tends to -s I as theta -> 0. (A rotation extrapolated
    // linearly is off along the arc by about (s theta)^2 R / 2: a bore
    // turned by 30 degrees a step put its nodes 0.27 radii off the circle;
    // turned about the piece's centroid instead of the fixed point, off by
    // about theta^2 |c - q| when the piece is a gear's sector.)
    const auto             &dofs = *disc.dof_handler;
    const auto             &mesh = *disc.mesh;
    const ConnectedPieces   pieces(mesh);
    const unsigned int      n_nodes = dofs.n_nodes();
    std::vector<unsigned int> piece_of_node(n_nodes, 0);
    std::vector<unsigned int> nodes;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        dofs.get_node_indices(c, nodes);
        for (const unsigned int node : nodes)
          piece_of_node[node] = pieces.piece_of_cell(c);
      }
    const auto position = [&](const dealii::Vector<double> &u, const unsigned int node) {
      dealii::Point<2> x = dofs.node_location(node);
      for (unsigned int comp = 0; comp < 2; ++comp)
        x[comp] += u[VEMDoFHandler<2>::node_dof(node, comp)];
      return x;
    };
    const unsigned int            np = pieces.n_pieces();
    std::vector<dealii::Point<2>> c0(np), c1(np);
    std::vector<unsigned int>     count(np, 0);
    for (unsigned int node = 0; node < n_nodes; ++node)
      {
        const unsigned int p = piece_of_node[node];
        c0[p] += position(u0, node);
        c1[p] += position(u1, node);
        ++count[p];
      }
    std::vector<double> dot(np, 0.), cross(np, 0.);
    for (unsigned int p = 0; p < np; ++p)
      if (count[p] > 0)
        {
          c0[p] /= count[p];
          c1[p] /= count[p];
        }
    for (unsigned int node = 0; node < n_nodes; ++node)
      {
        const unsigned int         p = piece_of_node[node];
        const dealii::Tensor<1, 2> a = position(u0, node) - c0[p], b = position(u1, node) - c1[p];
        dot[p] += a * b;
        cross[p] += a[0] * b[1] - a[1] * b[0];
      }
    const auto rotate = [](const double angle, const dealii::Tensor<1, 2> &v) {
      dealii::Tensor<1, 2> r;
      r[0] = std::cos(angle) * v[0] - std::sin(angle) * v[1];
      r[1] = std::sin(angle) * v[0] + std::cos(angle) * v[1];
      return r;
    };
    std::vector<double> theta(np, 0.), m_scale(np, s), m_angle(np, 0.);
    for (unsigned int p = 0; p < np; ++p)
      {
        theta[p] = (dot[p] != 0 || cross[p] != 0) ? std::atan2(cross[p], dot[p]) : 0.;
        // sin(s theta / 2) / sin(theta / 2) -> s as theta -> 0 (and to
        // round-off already below 1e-8)
        if (std::abs(theta[p]) > 1e-8)
          m_scale[p] = std::sin(s * theta[p] / 2) / std::sin(theta[p] / 2);
        m_angle[p] = (s - 1) * theta[p] / 2;
      }
    dealii::Vector<double> u(u1.size());
    for (unsigned int node = 0; node < n_nodes; ++node)
      {
        const unsigned int         p  = piece_of_node[node];
        const dealii::Point<2>     x0 = position(u0, node), x1 = position(u1, node);
        const dealii::Tensor<1, 2> remainder = (x1 - c1[p]) - rotate(theta[p], x0 - c0[p]);
        const dealii::Tensor<1, 2> w         = (x1 - c1[p]) - rotate(theta[p], x1 - c0[p]);
        const dealii::Point<2>     x2        = x1 - m_scale[p] * rotate(m_angle[p], w) + s * remainder;
        for (unsigned int comp = 0; comp < 2; ++comp)
          u[VEMDoFHandler<2>::node_dof(node, comp)] = x2[comp] - dofs.node_location(node)[comp];
      }
    return u;
  }
} // namespace dealvem
