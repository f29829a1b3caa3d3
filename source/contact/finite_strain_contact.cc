// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/contact/finite_strain_contact.h>

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <map>
#include <sstream>

namespace dealvem
{
  namespace
  {
    // J v: v turned by +90 degrees
    dealii::Tensor<1, 2>
    quarter_turn(const dealii::Tensor<1, 2> &v)
    {
      dealii::Tensor<1, 2> r;
      r[0] = -v[1];
      r[1] = v[0];
      return r;
    }

    // R(theta) v
    dealii::Tensor<1, 2>
    rotate(const dealii::Tensor<1, 2> &v, const double theta)
    {
      const double         c = std::cos(theta), s = std::sin(theta);
      dealii::Tensor<1, 2> r;
      r[0] = c * v[0] - s * v[1];
      r[1] = s * v[0] + c * v[1];
      return r;
    }

    // The closest point to p on the curve through x0, xm, x1 (the quadratic
    // with x(-1) = x0, x(0) = xm, x(1) = x1; a straight segment when xm is
    // its middle), and the curve's tangent there: the best of a few
    // samples, then Newton on the parameter.
    std::pair<dealii::Point<2>, dealii::Tensor<1, 2>>
    closest_on_piece(const dealii::Point<2> &p,
                     const dealii::Point<2> &x0,
                     const dealii::Point<2> &xm,
                     const dealii::Point<2> &x1)
    {
      const dealii::Tensor<1, 2> b = 0.5 * (x1 - x0), c = 0.5 * (x1 + x0) - xm; // x(s) = xm + s b + s^2 c
      const auto                 at = [&](const double s) { return xm + s * b + s * s * c; };
      double                     best = -1, best_d = std::numeric_limits<double>::max();
      for (int k = 0; k <= 8; ++k)
        {
          const double s = -1 + 0.25 * k, dist = at(s).distance_square(p);
          if (dist < best_d)
            {
              best_d = dist;
              best   = s;
            }
        }
      double s = best;
      for (unsigned int it = 0; it < 20; ++it)
        {
          const dealii::Tensor<1, 2> r = at(s) - p, dx = b + 2 * s * c;
          const double               g = r * dx, H = dx * dx + 2 * (r * c);
          if (!(H > 0))
            break;
          const double next = std::clamp(s - g / H, -1., 1.);
          if (std::abs(next - s) < 1e-14)
            break;
          s = next;
        }
      return {at(s), b + 2 * s * c};
    }
  } // namespace



  FiniteStrainContact::FiniteStrainContact(const VEMDoFHandler<2>                      &dof_handler,
                                           const std::vector<NodeInsertion::Interface> &interfaces,
                                           const ContactSettings::Normal                normal,
                                           const double                                 c)
    : FiniteStrainContact(dof_handler, interfaces, normal, c, Options())
  {}



  namespace
  {
    // A sub-edge of the master side at the slip origin: its end, its middle
    // (the edge node, or the chord's midpoint), its other end.
    using Piece = std::array<dealii::Point<2>, 3>;

    // The chord deviation of each piece of one interface where the master
    // side follows a smooth curve: a slave point that lay on the curve at
    // the origin is off the chord of a piece by up to l^2 kappa / 8 (l the
    // piece's length), more than the 1e-2 l of a touch once l kappa > 0.08
    // (a ring of 40 edges). kappa from the turns to the neighbouring pieces
    // (the angle between two chords over their mean length); turns above 30
    // degrees are corners, not curvature.
    std::vector<double>
    piece_curvatures(const std::vector<Piece> &list)
    {
      std::vector<double> curvatures(list.size(), 0.);
      for (unsigned int j = 0; j < list.size(); ++j)
        {
          const dealii::Tensor<1, 2> dj    = list[j][2] - list[j][0];
          const double               lj    = dj.norm();
          double                     kappa = 0;
          for (const int step : {-1, 1})
            {
              const int m = int(j) + step;
              if (m < 0 || m >= int(list.size()) || lj == 0)
                continue;
              // (neighbours along the side share an end)
              if (!(step < 0 ? list[m][2].distance(list[j][0]) <= 1e-12 * lj :
                               list[m][0].distance(list[j][2]) <= 1e-12 * lj))
                continue;
              const dealii::Tensor<1, 2> dm = list[m][2] - list[m][0];
              const double               lm = dm.norm();
              if (lm == 0)
                continue;
              const double sine = std::abs(dj[0] * dm[1] - dj[1] * dm[0]) / (lj * lm);
              if ((dj * dm) <= 0 || sine > 0.5)
                continue;
              kappa = std::max(kappa, 2 * std::asin(sine) / (lj + lm));
            }
          curvatures[j] = kappa;
        }
      return curvatures;
    }

    // The gap of the slave point @p x_slave to the master side's curve at
    // the origin (the pieces of its interface), on the side of the turned
    // normal @p n_origin, and the gap below which the point counts as
    // touching: within 1e-2 of the nearest piece's chord, plus 1.5 times
    // the chord deviations (the curvature of the chords is an estimate; an
    // edge node of k = 2 lies on its own sub-edge's chord, of length
    // @p l_own, off the curve by that chord's deviation too). (Beyond the
    // ends of the paired part of the master side, which is all the class
    // knows of it, the side is continued along its end tangent: the gap is
    // the normal part of the distance.)
    std::pair<double, double>
    gap_and_touch_at_origin(const dealii::Point<2>     &x_slave,
                            const dealii::Tensor<1, 2> &n_origin,
                            const std::vector<Piece>   &pieces,
                            const std::vector<double>  &curvatures,
                            const double                l_own)
    {
      double gap = std::numeric_limits<double>::max(), nearest = gap, touch = 0;
      for (unsigned int j = 0; j < pieces.size(); ++j)
        {
          const auto &piece = pieces[j];
          // (a piece x(s) = xm + s b + s^2 c lies within |b| + |c| of xm:
          // one farther than the nearest so far is skipped unsearched)
          const double reach =
            0.5 * (piece[2].distance(piece[0]) + ((piece[2] - piece[1]) + (piece[0] - piece[1])).norm());
          if (x_slave.distance(piece[1]) - reach >= nearest)
            continue;
          const auto [q, tangent] = closest_on_piece(x_slave, piece[0], piece[1], piece[2]);
          const double dist       = q.distance(x_slave);
          if (dist < nearest && tangent.norm() > 0)
            {
              nearest                     = dist;
              dealii::Tensor<1, 2> normal = quarter_turn(tangent / tangent.norm());
              if (normal * n_origin < 0)
                normal = -normal;
              gap            = (x_slave - q) * normal;
              const double l = piece[0].distance(piece[2]);
              touch          = 1e-2 * l + 1.5 * (l * l + l_own * l_own) * curvatures[j] / 8;
            }
        }
      return {gap, touch};
    }
  } // namespace



  /**
   * What the constructor's steps share about the pairs of all interfaces:
   * for each pair the pairs next to it along its interface (vertex pairs:
   * through the sub-edges; edge-node pairs: the two ends of their
   * sub-edge), the side its normal is taken from, and its interface.
   */
  struct FiniteStrainContact::Topology
  {
    std::vector<std::vector<unsigned int>>            neighbours;
    std::vector<NodeInsertion::Interface::NormalSide> side_of_pair;
    std::vector<unsigned int>                         interface_of_pair;
    unsigned int                                      n_interfaces = 0;
  };



  FiniteStrainContact::FiniteStrainContact(const VEMDoFHandler<2>                      &dof_handler,
                                           const std::vector<NodeInsertion::Interface> &interfaces,
                                           const ContactSettings::Normal                normal,
                                           const double                                 c,
                                           const Options                               &options)
    : dof_handler(dof_handler)
    , model(normal)
    , c(c)
  {
    AssertThrow(std::isfinite(c) && c > 0,
                dealii::ExcMessage("FiniteStrainContact: the complementarity constant must be positive."));
    AssertThrow(options.base == nullptr || options.base->size() == dof_handler.n_dofs(),
                dealii::ExcMessage("FiniteStrainContact: the base displacement has " +
                                   std::to_string(options.base == nullptr ? 0 : options.base->size()) +
                                   " entries, the DoF handler " + std::to_string(dof_handler.n_dofs()) + "."));
    Topology topology;
    collect_pairs(interfaces, options, topology);
    // (no pairs at all is a valid state: every interface is open, as where a
    // body slid off its partner in FiniteSliding)
    set_up_pair_data(topology, options.base);
    set_up_slip_origins(topology, options);
  }



  void
  FiniteStrainContact::collect_pairs(const std::vector<NodeInsertion::Interface> &interfaces,
                                     const Options                               &options,
                                     Topology                                    &topology)
  {
    const auto mu_of = [&](const unsigned int interface) {
      double m = options.friction_coefficient;
      if (interface < options.friction_coefficients.size() && options.friction_coefficients[interface] >= 0)
        m = options.friction_coefficients[interface];
      AssertThrow(std::isfinite(m) && m >= 0,
                  dealii::ExcMessage("FiniteStrainContact: the friction coefficient of interface " +
                                     std::to_string(interface) + " is " + std::to_string(m) +
                                     "; it must be finite and not negative."));
      AssertThrow(m == 0 || model == ContactSettings::Normal::unilateral,
                  dealii::ExcMessage("FiniteStrainContact: interface " + std::to_string(interface) +
                                     " has the friction coefficient " + std::to_string(m) +
                                     ", but tied contact has no friction (it sticks everywhere)."));
      return m;
    };
    auto &neighbours         = topology.neighbours;
    topology.n_interfaces    = interfaces.size();
    for (const auto &interface : interfaces)
      {
        const unsigned int offset       = pairs.size();
        const double       interface_mu = mu_of(&interface - interfaces.data());
        for (const auto &p : interface.pairs)
          {
            pairs.push_back(p);
            topology.side_of_pair.push_back(interface.normal_side);
            topology.interface_of_pair.push_back(&interface - interfaces.data());
            mu.push_back(interface_mu);
            frictional = frictional || interface_mu > 0;
          }
        neighbours.resize(pairs.size());
        for (auto s : interface.segments)
          {
            s.first += offset;
            s.second += offset;
            neighbours[s.first].push_back(s.second);
            neighbours[s.second].push_back(s.first);
            if (s.midpoint != dealii::numbers::invalid_unsigned_int)
              {
                s.midpoint += offset;
                neighbours[s.midpoint] = {s.first, s.second};
              }
            segments.push_back(s);
          }
      }
  }



  void
  FiniteStrainContact::set_up_pair_data(const Topology &topology, const dealii::Vector<double> *base)
  {
    const auto node_of = [&](const unsigned int i, const bool master) {
      const auto &p = pairs[i];
      AssertThrow(!p.on_edge() || dof_handler.get_element_data().nodes_per_edge() == 1,
                  dealii::ExcMessage("FiniteStrainContact: pair " + std::to_string(i) +
                                     " pairs edge nodes, but the DoF handler's layout " +
                                     dof_handler.get_element_data().get_name() + " has " +
                                     std::to_string(dof_handler.get_element_data().nodes_per_edge()) +
                                     " nodes per edge, not one."));
      return p.node(dof_handler, master);
    };

    // positions in the base configuration X + u_b
    const auto base_location = [&](const unsigned int node) {
      dealii::Point<2> x = dof_handler.node_location(node);
      if (base != nullptr)
        for (unsigned int comp = 0; comp < 2; ++comp)
          x[comp] += (*base)[VEMDoFHandler<2>::node_dof(node, comp)];
      return x;
    };

    // The typical sub-edge of each interface (the median length of its
    // segments on the master side in the base configuration): a chord
    // shorter than 1e-2 of it is lengthened along the chain (below).
    std::vector<std::vector<double>> lengths(topology.n_interfaces);
    for (const auto &s : segments)
      lengths[topology.interface_of_pair[s.first]].push_back(
        base_location(node_of(s.first, true)).distance(base_location(node_of(s.second, true))));
    std::vector<double> short_chord(topology.n_interfaces, 0.);
    for (unsigned int k = 0; k < topology.n_interfaces; ++k)
      if (!lengths[k].empty())
        {
          auto middle = lengths[k].begin() + lengths[k].size() / 2;
          std::nth_element(lengths[k].begin(), middle, lengths[k].end());
          short_chord[k] = 1e-2 * *middle;
        }
    // one pair further along the chain from @p node, away from @p from
    // (invalid at the end of the chain)
    const auto outward = [&](const unsigned int from, const unsigned int node) {
      for (const unsigned int q : topology.neighbours[node])
        if (q != from)
          return q;
      return dealii::numbers::invalid_unsigned_int;
    };

    data.resize(pairs.size());
    fixed.assign(pairs.size(), false);
    new_contact.assign(pairs.size(), false);
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        auto &d       = data[i];
        d.master_node = node_of(i, true);
        d.slave_node  = node_of(i, false);
        d.n0          = pairs[i].normal;
        d.t0          = quarter_turn(d.n0);
        const dealii::Tensor<1, 2> a0 = base_location(d.slave_node) - base_location(d.master_node);
        d.tied_normal     = a0 * d.n0;
        d.tied_tangential = a0 * d.t0;

        // the chord ends: the two neighbours, or the pair itself and its
        // one neighbour at the end of a chain
        const auto &nb = topology.neighbours[i];
        if (nb.empty())
          continue;
        const unsigned int minus = nb.size() >= 2 ? nb[0] : i;
        const unsigned int plus  = nb.size() >= 2 ? nb[1] : nb[0];
        // (whence each end was reached: a midpoint pair's ends go outward
        // from each other; the pair's own node at the end of a chain
        // cannot go further)
        const bool         midpoint   = pairs[i].on_edge();
        const unsigned int minus_from = (nb.size() >= 2 ? (midpoint ? plus : i) : plus);
        const unsigned int plus_from  = (nb.size() >= 2 ? (midpoint ? minus : i) : i);
        std::vector<std::pair<bool, double>> sides; // (master side?, weight)
        switch (topology.side_of_pair[i])
          {
            case NodeInsertion::Interface::NormalSide::master:
              sides = {{true, 1.}};
              break;
            case NodeInsertion::Interface::NormalSide::slave:
              sides = {{false, 1.}};
              break;
            case NodeInsertion::Interface::NormalSide::bisector:
              sides = {{true, 0.5}, {false, 0.5}};
              break;
          }
        for (const auto &[master, weight] : sides)
          {
            // A chord much shorter than the interface's sub-edges (node
            // insertion in FiniteSliding makes sub-edges down to 1e-9 of an
            // edge) turns the normal by the round-off of its two ends: the
            // derivative of theta is 1/|d|. Measured: a midpoint pair of a
            // sub-edge 7e-12 long had gap derivatives of 5e5 with respect to
            // its ends, and Newton cycled. Such a chord is lengthened by a
            // pair along the chain at each end, up to 8 times, until it
            // reaches 1e-2 of the interface's median sub-edge.
            unsigned int lo = minus, hi = plus, lo_from = minus_from, hi_from = plus_from;
            const auto   length = [&]() {
              return base_location(node_of(hi, master)).distance(base_location(node_of(lo, master)));
            };
            for (unsigned int extension = 0;
                 extension < 8 && length() < short_chord[topology.interface_of_pair[i]]; ++extension)
              {
                const unsigned int next_lo = outward(lo_from, lo), next_hi = outward(hi_from, hi);
                if (next_lo == dealii::numbers::invalid_unsigned_int &&
                    next_hi == dealii::numbers::invalid_unsigned_int)
                  break;
                if (next_lo != dealii::numbers::invalid_unsigned_int)
                  {
                    lo_from = lo;
                    lo      = next_lo;
                  }
                if (next_hi != dealii::numbers::invalid_unsigned_int)
                  {
                    hi_from = hi;
                    hi      = next_hi;
                  }
              }
            Chord chord;
            chord.minus     = node_of(lo, master);
            chord.plus      = node_of(hi, master);
            chord.reference = base_location(chord.plus) - base_location(chord.minus);
            chord.weight    = weight;
            if (chord.reference.norm() > 0)
              d.chords.push_back(chord);
          }
        // a bisector with one degenerate side: the other side turns it alone
        if (d.chords.size() == 1)
          d.chords[0].weight = 1.;
      }
  }



  void
  FiniteStrainContact::set_up_slip_origins(const Topology &topology, const Options &options)
  {
    // the slip origin: a.t in the configuration where the slip starts, t
    // turned there from the base by the pair's chords; the master side's
    // sub-edges there (end, middle, end), by interface, and their
    // curvatures
    std::vector<std::vector<Piece>> pieces_at_origin(topology.n_interfaces);
    if (options.slip_origin != nullptr && options.slip_origin->size() == dof_handler.n_dofs())
      for (const auto &s : segments)
        {
          const auto x0 = position(data[s.first].master_node, *options.slip_origin);
          const auto x1 = position(data[s.second].master_node, *options.slip_origin);
          const auto xm = s.midpoint != dealii::numbers::invalid_unsigned_int ?
                            position(data[s.midpoint].master_node, *options.slip_origin) :
                            dealii::Point<2>(0.5 * (x0 + x1));
          pieces_at_origin[topology.interface_of_pair[s.first]].push_back({{x0, xm, x1}});
        }
    std::vector<std::vector<double>> kappa_at_origin(topology.n_interfaces);
    for (unsigned int k = 0; k < pieces_at_origin.size(); ++k)
      kappa_at_origin[k] = piece_curvatures(pieces_at_origin[k]);

    const auto &neighbours = topology.neighbours;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        auto &d = data[i];
        if (options.slip_origin == nullptr)
          {
            d.slip_origin = d.tied_tangential;
            continue;
          }
        AssertThrow(options.slip_origin->size() == dof_handler.n_dofs(),
                    dealii::ExcMessage("FiniteStrainContact: the slip origin has " +
                                       std::to_string(options.slip_origin->size()) + " entries, the DoF handler " +
                                       std::to_string(dof_handler.n_dofs()) + "."));
        const dealii::Tensor<1, 2> a =
          position(d.slave_node, *options.slip_origin) - position(d.master_node, *options.slip_origin);
        const double               theta = turn(d, *options.slip_origin, nullptr);
        // Every pair's slip counts from the slip origin, a contact that
        // begins within the step too: its slip is the relative tangential
        // motion of its two material points over the whole step, as if it
        // had touched at the start (backward Euler; first order in the
        // step). Any later origin would be a configuration inside the step,
        // which only a predictor or an iterate can give: the converged
        // answer would then depend on them. (It did: where new pairs
        // counted their slip from the step's first pass, a better
        // predictor turned 3 of 6 slipping pairs of a race turned by 45
        // degrees into sticking ones, the moment 11 % off mu N R.) A pair
        // whose slave point was off the master side at the origin is
        // flagged (is_new_contact()), and with Options::contact_origin its
        // slip counts from there instead. The gap at the origin is the distance of the slave point to
        // the master side's curve at the origin, on the side of the turned
        // normal: not a.n, which on a curved interface reads the chord
        // between two material points that slid along each other as a gap
        // (of the slide squared over twice the radius). Within 1e-2 of the
        // piece's chord the point counts as touching (for k = 2 the two
        // sides' quadratics meet only at the nodes).
        double l_own = 0;
        if (pairs[i].on_edge() && neighbours[i].size() == 2)
          l_own = position(data[neighbours[i][0]].slave_node, *options.slip_origin)
                    .distance(position(data[neighbours[i][1]].slave_node, *options.slip_origin));
        const unsigned int interface = topology.interface_of_pair[i];
        const auto [gap_at_origin, touch] =
          gap_and_touch_at_origin(position(d.slave_node, *options.slip_origin),
                                  rotate(d.n0, theta),
                                  pieces_at_origin[interface],
                                  kappa_at_origin[interface],
                                  l_own);
        d.slip_origin = a * rotate(d.t0, theta);
        if (gap_at_origin > touch)
          {
            new_contact[i] = true;
            if (options.contact_origin != nullptr)
              {
                const auto &uc = *options.contact_origin;
                AssertThrow(uc.size() == dof_handler.n_dofs(),
                            dealii::ExcMessage("FiniteStrainContact: the contact origin has " +
                                               std::to_string(uc.size()) + " entries, the DoF handler " +
                                               std::to_string(dof_handler.n_dofs()) + "."));
                const dealii::Tensor<1, 2> ac = position(d.slave_node, uc) - position(d.master_node, uc);
                d.slip_origin                 = ac * rotate(d.t0, turn(d, uc, nullptr));
              }
          }
      }
  }



  void
  FiniteStrainContact::mark_fixed_pairs(const dealii::AffineConstraints<double> &constraints)
  {
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        bool all = true;
        for (const unsigned int node : {data[i].master_node, data[i].slave_node})
          for (unsigned int comp = 0; comp < 2; ++comp)
            all = all && constraints.is_constrained(VEMDoFHandler<2>::node_dof(node, comp));
        fixed[i] = all;
      }
  }



  dealii::Point<2>
  FiniteStrainContact::position(const unsigned int node, const dealii::Vector<double> &u) const
  {
    dealii::Point<2> x = dof_handler.node_location(node);
    x[0] += u[VEMDoFHandler<2>::node_dof(node, 0)];
    x[1] += u[VEMDoFHandler<2>::node_dof(node, 1)];
    return x;
  }



  double
  FiniteStrainContact::turn(const PairData                     &d,
                            const dealii::Vector<double>       &u,
                            std::vector<dealii::Tensor<1, 2>> *chords) const
  {
    double theta = 0;
    if (chords != nullptr)
      chords->clear();
    for (const auto &chord : d.chords)
      {
        const dealii::Tensor<1, 2> now   = position(chord.plus, u) - position(chord.minus, u);
        const dealii::Tensor<1, 2> &ref  = chord.reference;
        const double               cross = ref[0] * now[1] - ref[1] * now[0];
        theta += chord.weight * std::atan2(cross, ref * now);
        if (chords != nullptr)
          chords->push_back(now);
      }
    return theta;
  }



  std::array<dealii::Point<2>, 2>
  FiniteStrainContact::current_positions(const unsigned int i, const dealii::Vector<double> &u) const
  {
    return {{position(data[i].master_node, u), position(data[i].slave_node, u)}};
  }



  dealii::Tensor<1, 2>
  FiniteStrainContact::current_normal(const unsigned int i, const dealii::Vector<double> &u) const
  {
    return rotate(data[i].n0, turn(data[i], u, nullptr));
  }



  double
  FiniteStrainContact::value(const unsigned int j, const dealii::Vector<double> &u) const
  {
    const unsigned int   i     = pair_of(j);
    const PairData      &d     = data[i];
    const bool           tang  = is_tangential(j);
    const double         theta = turn(d, u, nullptr);
    const dealii::Tensor<1, 2> e = rotate(tang ? d.t0 : d.n0, theta);
    const dealii::Tensor<1, 2> a = position(d.slave_node, u) - position(d.master_node, u);
    return a * e - offset(d, tang);
  }



  void
  FiniteStrainContact::linearize(const unsigned int            j,
                                 const dealii::Vector<double> &u,
                                 Linearization                &result,
                                 const bool                    with_hessian) const
  {
    const unsigned int i    = pair_of(j);
    const PairData    &d    = data[i];
    const bool         tang = is_tangential(j);

    std::vector<dealii::Tensor<1, 2>> chords;
    const double                      theta = turn(d, u, &chords);
    const dealii::Tensor<1, 2>        e     = rotate(tang ? d.t0 : d.n0, theta);
    const dealii::Tensor<1, 2>        Je    = quarter_turn(e);
    const dealii::Tensor<1, 2>        a     = position(d.slave_node, u) - position(d.master_node, u);
    result.value                      = a * e - offset(d, tang);

    // The variables v = (a, d_1, ..., d_m), each a 2-vector, and how they
    // depend on the nodes: a = x_B - x_A, d_s = x_plus - x_minus.
    const unsigned int n_var = 1 + d.chords.size();
    std::vector<unsigned int> nodes;               // the distinct nodes
    std::vector<std::vector<std::pair<unsigned int, double>>> uses(n_var); // (local node, sign)
    const auto local = [&](const unsigned int node) {
      const auto it = std::find(nodes.begin(), nodes.end(), node);
      if (it != nodes.end())
        return static_cast<unsigned int>(it - nodes.begin());
      nodes.push_back(node);
      return static_cast<unsigned int>(nodes.size() - 1);
    };
    uses[0] = {{local(d.slave_node), 1.}, {local(d.master_node), -1.}};
    for (unsigned int s = 0; s < d.chords.size(); ++s)
      uses[1 + s] = {{local(d.chords[s].plus), 1.}, {local(d.chords[s].minus), -1.}};

    // gradient and Hessian in the variables
    std::vector<dealii::Tensor<1, 2>> w(d.chords.size());
    for (unsigned int s = 0; s < d.chords.size(); ++s)
      w[s] = quarter_turn(chords[s]) / chords[s].norm_square();
    const double aJe = a * Je, ae = a * e;
    std::vector<dealii::Tensor<1, 2>> gv(n_var);
    gv[0] = e;
    for (unsigned int s = 0; s < d.chords.size(); ++s)
      gv[1 + s] = d.chords[s].weight * aJe * w[s];

    // Hv[p][q]: the 2x2 block d^2 g / dv_p dv_q
    std::vector<std::vector<dealii::Tensor<2, 2>>> Hv;
    if (with_hessian)
      {
        Hv.assign(n_var, std::vector<dealii::Tensor<2, 2>>(n_var));
        for (unsigned int s = 0; s < d.chords.size(); ++s)
          {
            const double cs = d.chords[s].weight;
            Hv[0][1 + s]    = cs * dealii::outer_product(Je, w[s]);
            Hv[1 + s][0]    = dealii::transpose(Hv[0][1 + s]);
            for (unsigned int r = 0; r < d.chords.size(); ++r)
              Hv[1 + s][1 + r] = -cs * d.chords[r].weight * ae * dealii::outer_product(w[s], w[r]);
            dealii::Tensor<2, 2> J;
            J[0][1] = -1;
            J[1][0] = 1;
            const double dd = chords[s].norm_square();
            Hv[1 + s][1 + s] += cs * aJe * (J / dd - 2. / dd * dealii::outer_product(w[s], chords[s]));
          }
      }

    // to the DoFs of the nodes
    const unsigned int n_local = 2 * nodes.size();
    result.dofs.resize(n_local);
    for (unsigned int k = 0; k < nodes.size(); ++k)
      for (unsigned int comp = 0; comp < 2; ++comp)
        result.dofs[2 * k + comp] = VEMDoFHandler<2>::node_dof(nodes[k], comp);
    result.gradient.reinit(n_local);
    for (unsigned int p = 0; p < n_var; ++p)
      for (const auto &[node, sign] : uses[p])
        for (unsigned int comp = 0; comp < 2; ++comp)
          result.gradient[2 * node + comp] += sign * gv[p][comp];
    if (with_hessian)
      {
        result.hessian.reinit(n_local, n_local);
        for (unsigned int p = 0; p < n_var; ++p)
          for (unsigned int q = 0; q < n_var; ++q)
            for (const auto &[node_p, sign_p] : uses[p])
              for (const auto &[node_q, sign_q] : uses[q])
                for (unsigned int k = 0; k < 2; ++k)
                  for (unsigned int l = 0; l < 2; ++l)
                    result.hessian(2 * node_p + k, 2 * node_q + l) += sign_p * sign_q * Hv[p][q][k][l];
      }
  }



  ContactRows
  FiniteStrainContact::rows() const
  {
    return ContactRows(dof_handler.n_dofs(), pairs, n_constraints() > pairs.size());
  }



  void
  FiniteStrainContact::add_sparsity(dealii::DynamicSparsityPattern          &dsp,
                                    const dealii::AffineConstraints<double> &constraints) const
  {
    const ContactRows layout = rows();
    AssertThrow(dsp.n_rows() == layout.n_unknowns() && dsp.n_cols() == layout.n_unknowns(),
                dealii::ExcMessage("FiniteStrainContact::add_sparsity(): the pattern must have n_dofs() + "
                                   "n_constraints() rows and columns."));
    dealii::Vector<double> zero(layout.n_dofs());
    Linearization          lin;
    for (unsigned int j = 0; j < n_constraints(); ++j)
      {
        const unsigned int row = layout.row(j);
        dsp.add(row, row);
        if (is_left_out(j))
          continue;
        linearize(j, zero, lin, false);
        std::vector<dealii::types::global_dof_index> indices = lin.dofs;
        indices.push_back(row);
        constraints.add_entries_local_to_global(indices, dsp, true);
        // the slip equation lambda_t = mu |lambda_n| sign(.) couples the
        // tangential multiplier to the normal one
        if (frictional && is_tangential(j))
          dsp.add(row, layout.normal_row(pair_of(j)));
      }
  }



  std::string
  FiniteStrainContact::describe(const unsigned int j) const
  {
    const auto &p = pairs[pair_of(j)];
    std::ostringstream s;
    s << "the contact pair at (" << p.slave_location[0] << ", " << p.slave_location[1] << ") of interface "
      << p.interface;
    return s.str();
  }



  std::vector<double>
  FiniteStrainContact::current_weights(const dealii::Vector<double> &u) const
  {
    std::vector<double> w(pairs.size(), 0.);
    for (const auto &s : segments)
      {
        const double L = position(data[s.second].slave_node, u).distance(position(data[s.first].slave_node, u));
        if (s.midpoint == dealii::numbers::invalid_unsigned_int)
          {
            w[s.first] += L / 2;
            w[s.second] += L / 2;
          }
        else
          {
            w[s.first] += L / 6;
            w[s.second] += L / 6;
            w[s.midpoint] += 2 * L / 3;
          }
      }
    return w;
  }
} // namespace dealvem
