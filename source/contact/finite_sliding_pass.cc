// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// FiniteSliding: one pairing pass (FiniteSliding::Impl::prepare_pass() and
// its steps): the pairs made by node insertion in the current
// configuration, the new mesh in the reference configuration, the states
// transferred to it, and the contact and the solver of the pass.

#include "finite_sliding_impl.h"

namespace dealvem
{
  using namespace internal::finite_sliding;

  void
  FiniteSliding::Impl::prepare_pass(const double time, const double load_factor, const unsigned int step,
                                    const bool first_pass, StepRecord &record)
  {
    const auto clock = std::chrono::steady_clock::now();

    if (current != nullptr && !parameters.reinsert)
      {
        // small sliding: the pairs of the reference configuration stay
        constraints.clear();
        constraints_function(*current->dof_handler, time, constraints);
        solver->set_constraints(constraints);
        record.n_pairs = contact->n_pairs();
        record.n_dofs  = current->dof_handler->n_dofs();
        return;
      }

    Pass pass;
    pass.time        = time;
    pass.load_factor = load_factor;
    pass.step        = step;
    pass.first_pass  = first_pass;
    // (where the pairs are made)
    choose_pairing_state(pass);

    // 1. the original vertices at their positions there, paired by node
    // insertion
    pass.x_pair.resize(original.n_vertices());
    pass.x_true.resize(original.n_vertices());
    try
      {
        pair_in_configuration(pass, pass.u_pair);
      }
    catch (const dealii::ExceptionBase &)
      {
        // an extrapolated configuration may not be a valid one: pair where
        // the step starts
        if (!(pass.first_pass && pass.predicted))
          throw;
        pass.u_pair    = start_solution;
        pass.predicted = false;
        pair_in_configuration(pass, pass.u_pair);
      }
    // (the decisions the later passes keep are taken from passes that pair
    // near the step's end: the previous pass's partners within 1e-2 of
    // their sub-edges)
    keep_step_decisions(pass, !pass.first_pass && !record.pairing_offsets.empty() &&
                                record.pairing_offsets.back() <= 1e-2);

    // 2. the inserted vertices back to the reference configuration, by
    // their parameter on the original edge; the original vertices paired
    // on a straight side moved along it; the new mesh there
    place_inserted_vertices(pass);
    move_paired_vertices(pass);
    make_pass_mesh(pass, record);

    // 3. the states on the new mesh: where the pairs were made, where the
    // step started, and the step before (for the extrapolation)
    transfer_states(pass);

    // 4. the contact of the new pairs, and the objects of the pass
    make_pass_contact(pass);
    install_pass(pass, record);
    record.setup_time += std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
  }




  // Step 0 of prepare_pass(): the configuration where the pairs are made.
  void
  FiniteSliding::Impl::choose_pairing_state(Pass &pass)
  {
    // where the pairs are made: a later pass at the end of the last pass;
    // the first pass of a step where the step is expected to end, the
    // linear extrapolation of the last two steps in time (else where it
    // starts)
    pass.pair_disc = pass.first_pass ? start.get() : current.get();
    pass.u_pair    = pass.first_pass ? start_solution : solution;
    if (pass.first_pass)
      {
        step_snaps.clear();
        step_paired.clear();
        step_damped = false;
        anderson_x.clear();
        anderson_r.clear();
      }
    else if (pairing_base.size() == solution.size())
      pass.u_pair = relaxed_pairing_state();
    const bool with_extrapolation = pass.first_pass && parameters.extrapolate && n_converged >= 2 &&
                                    start_previous_solution.size() == pass.u_pair.size() &&
                                    last_time != previous_time;
    // whether the pairs are made where the step is expected to end (an
    // extrapolation or the end of a pass), not where it starts
    pass.predicted = !pass.first_pass;
    if (with_extrapolation)
      {
        const double s = (pass.time - last_time) / (last_time - previous_time);
        if (std::isfinite(s) && s > 0 && s <= 4)
          {
            pass.u_pair    = extrapolate(*start, start_solution, start_previous_solution, s);
            pass.predicted = true;
          }
      }
  }




  // Step 1 of prepare_pass() in the configuration @p u: the interfaces
  // there, the positions of the original vertices (snapped and merged as
  // the step decided) and the pairs node insertion makes.
  void
  FiniteSliding::Impl::pair_in_configuration(Pass &pass, const dealii::Vector<double> &u)
  {
    pairing_positions(pass, u);
    // the interfaces there: the given ones, and those the detection finds
    // (Parameters::detection) with the ids of their edges
    std::vector<dealii::types::boundary_id> ids_there;
    interfaces_of_pass(pass, ids_there);
    // A vertex of a straight side that faces a vertex of the other side
    // within 0.05 of the local edge length along the sides is paired with
    // it: the insertion sees it on the normal through that vertex (here
    // only), and its material point is then moved along its straight
    // side to the point that faces the other vertex (step 2). No sub-edge
    // that short is made, and the pair is exact.
    snap_close_vertices(pass.x_pair);
    hold_step_merges(pass.x_pair);
    make_pairing_mesh(pass, ids_there);
    insert_nodes(pass);
  }




  // Step 1a: the original vertices at their positions in @p u.
  void
  FiniteSliding::Impl::pairing_positions(Pass &pass, const dealii::Vector<double> &u)
  {
    const auto n0 = original.n_vertices();
    for (unsigned int v = 0; v < n0; ++v)
      {
        pass.x_pair[v] = original.vertex(v);
        if (pass.pair_disc != nullptr)
          for (unsigned int comp = 0; comp < 2; ++comp)
            pass.x_pair[v][comp] += u[VEMDoFHandler<2>::node_dof(pass.pair_disc->dof_handler->vertex_node(v), comp)];
      }
    // (a vertex of a straight side moved in that mesh (step 2): where its
    // original material point is, from the trace)
    // (the trace only where the last mesh moved a vertex: most steps none)
    if (pass.pair_disc != nullptr &&
        std::any_of(movable.begin(), movable.end(),
                    [&](const unsigned int v) { return pass.pair_disc->mesh->vertex(v) != original.vertex(v); }))
      {
        const auto         neighbours = neighbours_along_sides();
        const TraceOnSides trace(original, interface_edges, neighbours, *pass.pair_disc->mesh,
                                 *pass.pair_disc->dof_handler, u);
        for (const unsigned int v : movable)
          if (pass.pair_disc->mesh->vertex(v) != original.vertex(v))
            pass.x_pair[v] = original.vertex(v) + trace.value(original.vertex(v), v, side_neighbours.at(v)[0]);
      }
    pass.x_true = pass.x_pair;
  }




  // Step 1b: the interfaces of the pass (detected in the first pass of a
  // step, or when the step asks for it; else those of the step).
  void
  FiniteSliding::Impl::interfaces_of_pass(Pass &pass, std::vector<dealii::types::boundary_id> &ids_there)
  {
    if (pass.first_pass || redetect || step_labels.size() != original.n_edges())
      {
        pass.new_pass = pass_interfaces_at(pass.x_pair, ids_there, pass.new_detected, interface_sides);
        step_pass     = pass.new_pass;
        step_labels   = ids_there;
        step_detected = pass.new_detected;
        step_sides    = interface_sides;
        redetect      = false;
      }
    else
      {
        pass.new_detected = step_detected;
        // (later passes keep the interfaces of the step: a part at the
        // detection distance would otherwise be taken in and left out by
        // turns, and the passes would not settle)
        pass.new_pass   = step_pass;
        ids_there       = step_labels;
        interface_sides = step_sides;
      }
  }




  // Step 1c: the merges of earlier passes of the step, held in the pairing
  // positions @p x_pair.
  void
  FiniteSliding::Impl::hold_step_merges(std::vector<dealii::Point<2>> &x_pair)
  {
    // Merges hold within a step: two original vertices merged in an
    // earlier pass of the step (closer than about 1e-3 of an edge length,
    // the shortest sub-edge node insertion makes), neither of them on a
    // straight side, stay merged while
    // they are within 0.05 of the shorter adjacent edge along the master
    // side. The slave vertex is moved onto the master vertex along the
    // master side in the pairing configuration only (its material point
    // stays). Without this, a vertex that faces a kink or a vertex of
    // the other side flips between the merged pair and two split pairs
    // that push it to the far side of the kink: the passes cycle.
    for (const auto &[m, sv] : step_merges)
      {
        if (movable.count(m) > 0 || movable.count(sv) > 0 ||
            (step_released.count({m, sv}) > 0 && step_reheld.count({m, sv}) == 0))
          continue;
        const auto nm = side_neighbours.find(m), ns = side_neighbours.find(sv);
        if (nm == side_neighbours.end() || ns == side_neighbours.end() || nm->second.empty() ||
            ns->second.empty())
          continue;
        const auto           around = neighbours_on_sides(m);
        dealii::Tensor<1, 2> t      = x_pair[around.back()] - x_pair[around.front()];
        if (around.size() == 1)
          t = x_pair[around.front()] - x_pair[m];
        if (t.norm() == 0)
          continue;
        t /= t.norm();
        double h = std::numeric_limits<double>::max();
        for (const unsigned int v : {m, sv})
          for (const unsigned int w : neighbours_on_sides(v))
            h = std::min(h, x_pair[v].distance(x_pair[w]));
        const double along = (x_pair[sv] - x_pair[m]) * t;
        if (std::abs(along) <= 0.25 * h)
          x_pair[sv] -= along * t;
      }
  }




  // Step 1d: a copy of M_0 at the pairing positions, with the boundary ids
  // of the pass.
  void
  FiniteSliding::Impl::make_pairing_mesh(Pass &pass, const std::vector<dealii::types::boundary_id> &ids_there)
  {
    const auto n0 = original.n_vertices();
    pass.next       = std::make_unique<Discretization>();
    pass.next->mesh = std::make_unique<PolygonalMesh<2>>(original);
    for (unsigned int v = 0; v < n0; ++v)
      pass.next->mesh->move_vertex(v, pass.x_pair[v]);
    pass.new_partner.assign(original.n_edges(), dealii::numbers::invalid_unsigned_int);
    if (parameters.detection.enabled)
      {
        std::map<dealii::types::boundary_id, unsigned int> partner_of_id;
        for (const auto &i : pass.new_pass)
          {
            partner_of_id[i.master_id] = i.slave_body;
            partner_of_id[i.slave_id]  = i.master_body;
          }
        for (unsigned int e = 0; e < original.n_edges(); ++e)
          if (original.edge(e).at_boundary() && ids_there[e] != original.edge(e).boundary_id)
            {
              pass.next->mesh->set_edge_boundary_id(e, ids_there[e]);
              pass.new_partner[e] = partner_of_id.at(ids_there[e]);
            }
      }
  }




  // Step 1e: node insertion on each interface of the pass.
  void
  FiniteSliding::Impl::insert_nodes(Pass &pass)
  {
    const auto degree = parameters.degree;
    pass.new_interfaces.clear();
    // A vertex paired in an earlier pass of the step keeps its partner
    // while the two sides' normals there are at more than 90 degrees
    // (new pairs need 120): the decisions of a step only grow, as the
    // snaps and merges do. Without the band, a die vertex whose normal
    // and the bulging slab's sat at 120 degrees gained and lost its
    // partner from pass to pass (an open pair far from the contact,
    // but its node changes the slab's discrete space), and the passes
    // stalled at offsets of 5e-5 (ironing pressed to 0.3, mu = 0.3).
    NodeInsertion::Settings settings = parameters.insertion;
    settings.keep_facing.insert(step_paired.begin(), step_paired.end());
    try
      {
        for (unsigned int i = 0; i < pass.new_pass.size(); ++i)
          pass.new_interfaces.push_back(NodeInsertion::insert(
            *pass.next->mesh, pass.new_pass[i].master_id, pass.new_pass[i].slave_id, degree, settings, i));
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        const std::string message = "FiniteSliding: pairing the interfaces in the current configuration of step " +
                                    std::to_string(pass.step) + " failed: " + info.str();
        // (where the step starts, the pairing is the same for every
        // sub-step: cutting the step back cannot help)
        if (pass.first_pass && !pass.predicted)
          AssertThrow(false, ExcStepInput(message));
        AssertThrow(false, dealii::ExcMessage(message));
      }
  }




  // After step 1: the merges and the paired vertices the later passes of
  // the step keep.
  void
  FiniteSliding::Impl::keep_step_decisions(Pass &pass, const bool settled)
  {
    const auto n0 = original.n_vertices();
    if (pass.first_pass)
      {
        step_merges.clear();
        step_released.clear();
        step_reheld.clear();
      }
    for (const auto &interface : pass.new_interfaces)
      for (const auto &pair : interface.pairs)
        if (!pair.on_edge())
          {
            if (pair.master_entity < n0 && pair.slave_entity < n0)
              {
                step_merges.insert({pair.master_entity, pair.slave_entity});
                // (released, and merged again by the insertion's own rule:
                // held from now on; the passes would otherwise alternate)
                if (step_released.count({pair.master_entity, pair.slave_entity}) > 0)
                  step_reheld.insert({pair.master_entity, pair.slave_entity});
              }
            // (only where the passes have settled near the step's end: a
            // pass that pairs where the step started, or where a pass with
            // pairs far from their place left it, pairs vertices the end
            // does not; kept, their partners on open sides changed the
            // discrete space, and a step came out 4e-5 apart from the same
            // step started from a prediction)
            if (settled)
              for (const unsigned int v : {pair.master_entity, pair.slave_entity})
                if (v < n0)
                  step_paired.insert(v);
          }
  }




  // Step 2a: the inserted vertices at their material points on the
  // original edges (the reference curve of each edge).
  void
  FiniteSliding::Impl::place_inserted_vertices(Pass &pass)
  {
    const auto n0 = original.n_vertices();
    pass.x_now = pass.next->mesh->get_vertices();
    for (unsigned int v = 0; v < n0; ++v)
      pass.x_now[v] = pass.x_pair[v];
    pass.reference = std::vector<dealii::Point<2>>(pass.next->mesh->n_vertices());
    pass.placed.assign(pass.next->mesh->n_vertices(), false);
    for (unsigned int v = 0; v < n0; ++v)
      {
        pass.reference[v] = original.vertex(v);
        pass.placed[v]    = true;
      }
    // The current edge is the curve x(s) = X(s) + u(s), u the trace on
    // the sub-edges of the mesh where the pairs are made (linear or
    // quadratic on each), not the chord of the original edge through its
    // moved end points that the insertion sees: the two differ by the kinks
    // (k = 1) and the curvature (k = 2) of the trace. The inserted vertex
    // goes to the point of that curve closest to its partner; with the
    // chord's parameter, partners that coincide in the pairing
    // configuration would start apart and the pairing of a curved or
    // stretched side would never reach a fixed point.
    std::map<unsigned int, unsigned int> partner; // inserted vertex -> its partner vertex
    for (const auto &interface : pass.new_interfaces)
        for (const auto &pair : interface.pairs)
          if (!pair.on_edge())
            {
              if (pair.master_entity >= n0)
                partner[pair.master_entity] = pair.slave_entity;
              if (pair.slave_entity >= n0)
                partner[pair.slave_entity] = pair.master_entity;
            }
    pass.trace_neighbours = neighbours_along_sides();
    if (pass.pair_disc != nullptr)
      pass.pair_trace = std::make_unique<TraceOnSides>(original, interface_edges, pass.trace_neighbours,
                                                       *pass.pair_disc->mesh, *pass.pair_disc->dof_handler, pass.u_pair);
    for (const auto &[a, b, cell] : interface_edges)
      {
        Chain chain = make_chain(*pass.next->mesh, a, b, cell, pass.x_now);
        if (pass.pair_disc != nullptr && !partner.empty() && chain.vertices.size() > 2)
          {
            const Chain old_chain = make_chain(*pass.pair_disc->mesh, a, b, cell,
                                               pass.pair_disc->mesh->get_vertices(), &original.vertex(a),
                                               &original.vertex(b));
            const auto curve = [&, a = a, b = b](const double s) {
              const dealii::Point<2> X = reference_point(a, b, s);
              return dealii::Point<2>(X + pass.pair_trace->value(X, a, b));
            };
            std::vector<double> corrected(chain.vertices.size(), -1.);
            for (unsigned int k = 1; k + 1 < chain.vertices.size(); ++k)
              {
                const auto it = partner.find(chain.vertices[k]);
                if (it == partner.end())
                  continue;
                const dealii::Point<2> target = pass.x_true[it->second];
                // (the whole edge: the neighbours' parameters are still
                // chord parameters of the current configuration, or already
                // reference ones; the order is checked below)
                const double           lo = 0, hi = 1;
                const double           margin = 1e-9;
                double                 best_s = chain.s[k], best_d = curve(best_s).distance(target);
                // on each sub-edge of the old mesh within (lo, hi) the
                // curve is a polynomial: Gauss-Newton on |x(s) - target|^2
                // there (exact in one update for k = 1), the tangent by
                // central differences; the closest of these points wins
                for (unsigned int piece = 0; piece + 1 < old_chain.s.size(); ++piece)
                  {
                    const double s0 = std::max(lo + margin, old_chain.s[piece]);
                    const double s1 = std::min(hi - margin, old_chain.s[piece + 1]);
                    if (!(s1 > s0))
                      continue;
                    // (the trace of a short sub-edge may fold back on
                    // itself at a far-off pairing: Gauss-Newton starts at
                    // the closest of a few samples, not in the local
                    // minimum at an end of the piece)
                    const double s =
                      closest_on_curve(curve, s0, s1, std::clamp(chain.s[k], s0, s1), target, 8, 1e-6, 1e-15);
                    const double d = curve(s).distance(target);
                    if (d < best_d)
                      {
                        best_d = d;
                        best_s = s;
                      }
                  }
                // a partner far from the curve (an open pair: its gap is
                // larger than the edge) need not face its node exactly:
                // it keeps the chord's parameter
                if (best_d < 0.5 * pass.x_now[a].distance(pass.x_now[b]))
                  corrected[k] = best_s;
              }
            // the material points must keep their order along the edge;
            // where they do not (two partners far apart whose closest
            // points cross), all nodes of the edge keep the chord's
            // parameters
            std::vector<double> s_new = chain.s;
            for (unsigned int k = 1; k + 1 < chain.vertices.size(); ++k)
              if (corrected[k] >= 0)
                s_new[k] = corrected[k];
            bool monotone = true;
            for (unsigned int k = 0; k + 1 < s_new.size(); ++k)
              monotone = monotone && s_new[k + 1] > s_new[k];
            if (monotone)
              chain.s = s_new;
          }
        pass.chains.push_back({a, b, std::move(chain)});
      }

    for (auto &[a, b, chain] : pass.chains)
      for (unsigned int k = 1; k + 1 < chain.vertices.size(); ++k)
        {
          const unsigned int v = chain.vertices[k];
          pass.reference[v] = reference_point(a, b, chain.s[k]);
          pass.placed[v]    = true;
        }
  }




  // Step 2b: a paired original vertex on a straight side moved along it.
  void
  FiniteSliding::Impl::move_paired_vertices(Pass &pass)
  {
    const auto n0 = original.n_vertices();
    // Pairs of two original vertices (merged by the insertion, or paired
    // by snap_close_vertices()): the vertex on a straight side (the
    // slave's if both are) moves along its side to the material point
    // that faces its partner, the closest point of its side's current
    // curve (the trace where the pairs are made) to the partner, within
    // 0.9 of the way to the next node on either side. The mesh keeps its
    // cells (the side is straight, so the body does not change), and the
    // state follows the material points (transfer()). Without this the two
    // partners stay apart by where the insertion found them.
    for (const auto &interface : pass.new_interfaces)
      for (const auto &pair : interface.pairs)
        {
          if (pair.on_edge() || pair.master_entity >= n0 || pair.slave_entity >= n0)
            continue;
          const bool         slave_moves = movable.count(pair.slave_entity) > 0;
          if (!slave_moves && movable.count(pair.master_entity) == 0)
            continue;
          const unsigned int v = slave_moves ? pair.slave_entity : pair.master_entity;
          const unsigned int p = slave_moves ? pair.master_entity : pair.slave_entity;
          const auto        &around = side_neighbours.at(v);
          // (only partners that touch or nearly: a pair across a gap wider
          // than half an edge is open, and where it faces does not matter)
          double h = std::numeric_limits<double>::max();
          for (const unsigned int q : {v, p})
            for (const unsigned int w : side_neighbours.at(q))
              h = std::min(h, pass.x_true[q].distance(pass.x_true[w]));
          if (pass.x_true[v].distance(pass.x_true[p]) > 0.5 * h)
            continue;
          const dealii::Point<2>     X = original.vertex(v);
          const dealii::Tensor<1, 2> T = (original.vertex(around[1]) - original.vertex(around[0])) /
                                         original.vertex(around[1]).distance(original.vertex(around[0]));
          // the nearest nodes along the side (the line coordinate sigma
          // from the original position of v)
          double lo = (original.vertex(around[0]) - X) * T, hi = (original.vertex(around[1]) - X) * T;
          for (const auto &[a, b, chain] : pass.chains)
            if (a == v || b == v)
              for (const unsigned int w : chain.vertices)
                if (w != v)
                  {
                    const double sigma = (pass.reference[w] - X) * T;
                    if (sigma < 0)
                      lo = std::max(lo, sigma);
                    else
                      hi = std::min(hi, sigma);
                  }
          lo *= 0.9;
          hi *= 0.9;
          const auto curve = [&](const double sigma) {
            const dealii::Point<2> Y = X + sigma * T;
            if (pass.pair_trace == nullptr)
              return Y;
            return dealii::Point<2>(Y + pass.pair_trace->value(Y, v, sigma < 0 ? around[0] : around[1]));
          };
          const dealii::Point<2> target = pass.x_true[p];
          const double best = closest_on_curve(curve, lo, hi, 0., target, 16, 1e-7, 1e-15 * (hi - lo));
          pass.reference[v] = X + best * T;
        }
  }




  // Step 2c: the new mesh in the reference configuration and its DoFs.
  void
  FiniteSliding::Impl::make_pass_mesh(Pass &pass, StepRecord &record)
  {
    const auto n0 = original.n_vertices();
    const auto degree = parameters.degree;
    record.n_moved = 0;
    for (unsigned int v = 0; v < n0; ++v)
      if (pass.reference[v] != original.vertex(v))
        ++record.n_moved;
    for (unsigned int v = 0; v < pass.next->mesh->n_vertices(); ++v)
      {
        AssertThrow(pass.placed[v],
                    dealii::ExcMessage("FiniteSliding: an inserted vertex lies on no interface edge of "
                                       "the original mesh."));
        pass.next->mesh->move_vertex(v, pass.reference[v]);
      }
    pass.next->mesh->validate();
    pass.next->dof_handler = std::make_unique<VEMDoFHandler<2>>(*pass.next->mesh);
    pass.next->dof_handler->distribute_dofs(VEMElementData(degree));
    record.n_inserted = 0;
    for (const auto &i : pass.new_interfaces)
      record.n_inserted += i.report.n_inserted_master + i.report.n_inserted_slave;
  }




  // Step 3: the states transferred to the new mesh.
  void
  FiniteSliding::Impl::transfer_states(Pass &pass)
  {
    const auto n_new  = pass.next->dof_handler->n_dofs();
    const auto states = [&](const Discretization *from, const dealii::Vector<double> &u) {
      return from == nullptr ? dealii::Vector<double>(n_new) : transfer(*from, u, *pass.next);
    };
    pass.u_base = states(pass.pair_disc, pass.u_pair);
    // a later pass starts Newton from the last pass's solution (the
    // pairing state above is relaxed at the interface only)
    pass.u_newton = pass.first_pass ? dealii::Vector<double>() : states(pass.pair_disc, solution);
    // (every pair's slip counts from the start of the step:
    // FiniteStrainContact::set_up_slip_origins)
    pass.u_origin = states(start.get(), start_solution);
    pass.with_previous = pass.first_pass && n_converged >= 2 && start_previous_solution.size() > 0;
    if (pass.with_previous)
      pass.u_previous = states(start.get(), start_previous_solution);
  }




  // Step 4a: the contact of the new pairs and its first multipliers.
  void
  FiniteSliding::Impl::make_pass_contact(Pass &pass)
  {
    const double c = parameters.complementarity_constant;
    FiniteStrainContact::Options options;
    options.base           = &pass.u_base;
    options.slip_origin    = &pass.u_origin;
    for (const auto &i : pass.new_pass)
      options.friction_coefficients.push_back(i.friction_coefficient);
    pass.new_contact = std::make_unique<FiniteStrainContact>(*pass.next->dof_handler, pass.new_interfaces,
                                                             parameters.normal, c, options);

    // the multipliers: the traction of the nearest pair of the same
    // interface where the pairs were made, times the new weight
    pass.lambda.reinit(pass.new_contact->n_constraints());
    const dealii::Vector<double> &lambda_old = pass.first_pass ? start_multipliers : multipliers;
    if (contact != nullptr && pass.pair_disc != nullptr && lambda_old.size() == contact->n_constraints())
      {
        const auto old_weights = contact->current_weights(pass.u_pair);
        const auto new_weights = pass.new_contact->current_weights(pass.u_base);
        const auto np_old = contact->n_pairs(), np_new = pass.new_contact->n_pairs();
        const bool both_tangential =
          pass.new_contact->n_constraints() == 2 * np_new && contact->n_constraints() == 2 * np_old;
        for (unsigned int i = 0; i < np_new; ++i)
          {
            const auto   x       = pass.new_contact->current_positions(i, pass.u_base)[1];
            // (the same reported interface: with detection, the interfaces
            // of two passes may be numbered differently)
            const auto   id      = pass.new_pass[pass.new_contact->get_pairs()[i].interface].reported;
            double       best    = std::numeric_limits<double>::max();
            unsigned int nearest = np_old;
            for (unsigned int o = 0; o < np_old; ++o)
              if (pass_interfaces[contact->get_pairs()[o].interface].reported == id)
                {
                  const double d = contact->current_positions(o, pass.u_pair)[1].distance_square(x);
                  if (d < best)
                    {
                      best    = d;
                      nearest = o;
                    }
                }
            if (nearest == np_old || old_weights[nearest] <= 0)
              continue;
            pass.lambda[i] = lambda_old[nearest] / old_weights[nearest] * new_weights[i];
            if (both_tangential)
              pass.lambda[np_new + i] = lambda_old[np_old + nearest] / old_weights[nearest] * new_weights[i];
          }
      }
  }




  // Step 4b: the objects of the pass replace the old ones; the solver
  // starts from the pass's state.
  void
  FiniteSliding::Impl::install_pass(Pass &pass, StepRecord &record)
  {
    // the new objects replace the old ones (in the order of their
    // references; the start of the step stays)
    solver.reset();
    contact.reset();
    assembler.reset();
    current         = std::move(pass.next);
    contact         = std::move(pass.new_contact);
    interfaces      = std::move(pass.new_interfaces);
    pass_interfaces = std::move(pass.new_pass);
    pass_partner    = std::move(pass.new_partner);
    pass_detected   = std::move(pass.new_detected);

    assembler = std::make_unique<FiniteStrainAssembler<2>>(*current->dof_handler, laws, 1.0, parameters.stabilization);
    if (loads_function)
      loads_function(*assembler);
    constraints.clear();
    constraints_function(*current->dof_handler, pass.time, constraints);
    AssertThrow(constraints.is_closed(),
                dealii::ExcMessage("FiniteSliding: the constraints function must close the constraints."));
    solver = std::make_unique<FiniteStrainSolver<2>>(*assembler, constraints, parameters.newton);
    solver->set_contact(*contact);
    if (pass.first_pass)
      {
        solver->set_state(pass.u_origin, pass.lambda, last_load_factor, last_step,
                          pass.with_previous ? &pass.u_previous : nullptr, previous_load_factor, previous_step);
        solution = pass.u_origin;
      }
    else
      {
        solver->set_state(pass.u_newton, pass.lambda, pass.load_factor, pass.step);
        solution = pass.u_newton;
      }
    pairing_base = pass.u_base;
    multipliers  = pass.lambda;
    record.n_pairs = contact->n_pairs();
    record.n_dofs  = current->dof_handler->n_dofs();
  }
} // namespace dealvem
