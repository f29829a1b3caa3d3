// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>

#include <dealvem/base/number_string.h>
#include <dealvem/contact/finite_sliding.h>
#include <dealvem/contact/finite_strain_contact.h>
#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/piece_support.h>
#include <dealvem/mesh/connected_pieces.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace dealvem
{
  namespace
  {
    // An error of the input found before a step is solved (a body without
    // support): cutting the step back cannot help, so it ends the run at
    // once.
    class ExcStepInput : public dealii::ExcMessage
    {
    public:
      using dealii::ExcMessage::ExcMessage;
    };

    // The nodes of an original interface edge (a, b) of M_0 in a mesh made
    // from M_0 by splitting edges: the vertices from a to b along the loop
    // of the edge's cell, their parameters s on the chord (in that mesh's
    // coordinates, or in the coordinates of the given points), and the
    // sub-edges between them.
    struct Chain
    {
      std::vector<unsigned int> vertices;
      std::vector<double>       s;
      std::vector<unsigned int> edges;
    };

    // (@p pa and @p pb: the ends of the chord the parameters refer to, by
    // default the positions of a and b in @p x; with the original positions
    // of a and b, the parameters of a moved vertex of a straight side (see
    // FiniteSliding::prepare_pass()) include its ends)
    Chain
    make_chain(const PolygonalMesh<2> &mesh, const unsigned int a, const unsigned int b, const unsigned int cell,
               const std::vector<dealii::Point<2>> &x, const dealii::Point<2> *pa = nullptr,
               const dealii::Point<2> *pb = nullptr)
    {
      Chain       chain;
      const auto &loop = mesh.cell(cell).vertices;
      const auto  n    = loop.size();
      const auto  it   = std::find(loop.begin(), loop.end(), a);
      AssertThrow(it != loop.end(), dealii::ExcInternalError());
      unsigned int i = it - loop.begin();
      const dealii::Point<2>     xa = pa != nullptr ? *pa : x[a], xb = pb != nullptr ? *pb : x[b];
      const dealii::Tensor<1, 2> d  = xb - xa;
      const double               dd = d.norm_square();
      const bool                 given = pa != nullptr;
      for (unsigned int k = 0; k <= n; ++k, i = (i + 1) % n)
        {
          const unsigned int v = loop[i];
          chain.vertices.push_back(v);
          chain.s.push_back(!given && v == a ? 0. : (!given && v == b ? 1. : (x[v] - xa) * d / dd));
          if (v == b)
            break;
          chain.edges.push_back(mesh.cell(cell).edges[i]);
        }
      AssertThrow(chain.vertices.back() == b,
                  dealii::ExcMessage("FiniteSliding: the interface edge (" + std::to_string(a) + ", " +
                                     std::to_string(b) + ") is not a run of the loop of cell " +
                                     std::to_string(cell) + "."));
      return chain;
    }

    // The trace of the field @p u (DoF handler @p dofs) on the chain at the
    // chain parameter s: its value, its derivative with respect to the
    // local coordinate of the piece, the piece and that coordinate t.
    struct TracePoint
    {
      dealii::Tensor<1, 2> value, derivative;
      unsigned int         piece = 0;
      double               t     = 0;
    };

    TracePoint
    trace_at(const Chain &chain, const VEMDoFHandler<2> &dofs, const dealii::Vector<double> &u, const double s)
    {
      TracePoint   p;
      unsigned int i = 0;
      while (i + 2 < chain.vertices.size() && s > chain.s[i + 1])
        ++i;
      const double len = chain.s[i + 1] - chain.s[i];
      const double t   = len > 0 ? (s - chain.s[i]) / len : 0.;
      p.piece          = i;
      p.t              = t;
      for (unsigned int comp = 0; comp < 2; ++comp)
        {
          const double u0 = u[VEMDoFHandler<2>::node_dof(dofs.vertex_node(chain.vertices[i]), comp)];
          const double u1 = u[VEMDoFHandler<2>::node_dof(dofs.vertex_node(chain.vertices[i + 1]), comp)];
          if (dofs.get_degree() == 1)
            {
              p.value[comp]      = (1 - t) * u0 + t * u1;
              p.derivative[comp] = u1 - u0;
              continue;
            }
          const double um = u[VEMDoFHandler<2>::node_dof(dofs.edge_node(chain.edges[i]), comp)];
          // quadratic through (0, u0), (1/2, um), (1, u1)
          p.value[comp]      = u0 * (1 - t) * (1 - 2 * t) + um * 4 * t * (1 - t) + u1 * t * (2 * t - 1);
          p.derivative[comp] = u0 * (4 * t - 3) + um * (4 - 8 * t) + u1 * (4 * t - 1);
        }
      return p;
    }

    std::uint64_t
    edge_key(const unsigned int a, const unsigned int b)
    {
      return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
    }

    // The trace of a state on the interface sides of a mesh made from M_0,
    // at a point X of the reference configuration on an original interface
    // edge: the chains of the original edges with parameters on the edges
    // of M_0 (a vertex moved along a straight side lies beyond the end of
    // one edge's chain and within the next one's).
    class TraceOnSides
    {
    public:
      TraceOnSides(const PolygonalMesh<2> &original, const std::vector<std::array<unsigned int, 3>> &edges,
                   const std::map<unsigned int, std::vector<unsigned int>> &neighbours,
                   const PolygonalMesh<2> &mesh, const VEMDoFHandler<2> &dofs, const dealii::Vector<double> &u)
        : original(original)
        , neighbours(neighbours)
        , mesh(mesh)
        , dofs(dofs)
        , u(u)
      {
        for (const auto &[a, b, cell] : edges)
          chains[edge_key(a, b)] = {{{a, b}},
                                    make_chain(mesh, a, b, cell, mesh.get_vertices(), &original.vertex(a),
                                               &original.vertex(b))};
      }

      // the value at X, which lies on the original edge (a, b) or next to it
      dealii::Tensor<1, 2>
      value(const dealii::Point<2> &X, const unsigned int a, const unsigned int b) const
      {
        const auto evaluate = [&](const std::pair<std::array<unsigned int, 2>, Chain> &entry,
                                  const bool                                          strict) {
          const auto                &[ends, chain] = entry;
          const dealii::Point<2>     xa = original.vertex(ends[0]);
          const dealii::Tensor<1, 2> d  = original.vertex(ends[1]) - xa;
          const double               s  = (X - xa) * d / d.norm_square();
          const double               tolerance = 1e-12;
          if (strict && (s < chain.s.front() - tolerance || s > chain.s.back() + tolerance))
            return false;
          const TracePoint p = trace_at(chain, dofs, u, s);
          result             = p.value;
          // X off the sub-edge of this mesh that it projects onto (a node
          // of a curved side placed on the side's arc, see
          // FiniteSliding::reference_point()): the offset d from the
          // sub-edge turns with the sub-edge, so that the node's current
          // position is the sub-edge's current point plus R d. Rigid
          // motions are then carried exactly (the trace of a linear field
          // is exact on the straight sub-edge); otherwise the error is the
          // strain times |d|, a fraction of the sag of the sub-edge.
          const dealii::Point<2>     &Pa = mesh.vertex(chain.vertices[p.piece]);
          const dealii::Point<2>     &Pb = mesh.vertex(chain.vertices[p.piece + 1]);
          const dealii::Tensor<1, 2>  T0 = Pb - Pa;
          const dealii::Tensor<1, 2>  offset = X - (Pa + p.t * T0);
          if (offset.norm() > 1e-14 * T0.norm())
            {
              const dealii::Tensor<1, 2> T     = T0 + p.derivative;
              const double               theta = std::atan2(T0[0] * T[1] - T0[1] * T[0], T0 * T);
              const double               c = std::cos(theta), sn = std::sin(theta);
              result[0] += (c - 1) * offset[0] - sn * offset[1];
              result[1] += sn * offset[0] + (c - 1) * offset[1];
            }
          return true;
        };
        const auto own = chains.find(edge_key(a, b));
        AssertThrow(own != chains.end(), dealii::ExcInternalError());
        if (evaluate(own->second, true))
          return result;
        for (const unsigned int end : {a, b})
          if (const auto it = neighbours.find(end); it != neighbours.end())
            for (const unsigned int w : it->second)
              if (const auto next = chains.find(edge_key(end, w)); next != chains.end() && next != own &&
                                                                   evaluate(next->second, true))
                return result;
        evaluate(own->second, false);
        return result;
      }

    private:
      const PolygonalMesh<2>                                                      &original;
      const std::map<unsigned int, std::vector<unsigned int>>                     &neighbours;
      const PolygonalMesh<2>                                                      &mesh;
      const VEMDoFHandler<2>                                                      &dofs;
      const dealii::Vector<double>                                                &u;
      std::map<std::uint64_t, std::pair<std::array<unsigned int, 2>, Chain>>     chains;
      mutable dealii::Tensor<1, 2>                                                result;
    };

    // The parameter in [s0, s1] of the point of @p curve closest to
    // @p target: Gauss-Newton on |x(s) - target|^2 (the tangent by central
    // differences over @p width times the interval), started at the closest
    // of @p start and n_samples + 1 equidistant samples (a curve that folds
    // back on itself has local minima at the ends of the interval), stopped
    // when an update is below @p stop.
    template <typename Curve>
    double
    closest_on_curve(const Curve &curve, const double s0, const double s1, const double start,
                     const dealii::Point<2> &target, const unsigned int n_samples, const double width,
                     const double stop)
    {
      double s = start, d_start = curve(s).distance(target);
      for (unsigned int j = 0; j <= n_samples; ++j)
        if (const double sj = s0 + (s1 - s0) * j / n_samples, dj = curve(sj).distance(target); dj < d_start)
          {
            s       = sj;
            d_start = dj;
          }
      for (unsigned int iteration = 0; iteration < 30; ++iteration)
        {
          const double               e  = width * (s1 - s0);
          const double               sm = std::max(s0, s - e), sp = std::min(s1, s + e);
          const dealii::Tensor<1, 2> dx = (curve(sp) - curve(sm)) / (sp - sm);
          const double next_s = std::clamp(s - ((curve(s) - target) * dx) / dx.norm_square(), s0, s1);
          const bool   done   = std::abs(next_s - s) < stop;
          s                   = next_s;
          if (done)
            break;
        }
      return s;
    }

    dealii::Tensor<1, 2>
    turn_left(const dealii::Tensor<1, 2> &v)
    {
      dealii::Tensor<1, 2> r;
      r[0] = -v[1];
      r[1] = v[0];
      return r;
    }
  } // namespace



  NodeInsertion::Settings
  FiniteSliding::Parameters::default_insertion()
  {
    NodeInsertion::Settings s;
    s.merge_fraction            = 1e-9;
    s.close_discretisation_gaps = false;
    s.allow_no_pairs            = true;
    return s;
  }



  FiniteSliding::Discretization::~Discretization()
  {
    dof_handler.reset();
    mesh.reset();
  }



  FiniteSliding::FiniteSliding(const PolygonalMesh<2>           &mesh_in,
                               const MaterialLibrary<2>         &laws,
                               const std::vector<InterfaceData> &interfaces_in,
                               const Parameters                 &parameters_in)
    : original(mesh_in)
    , laws(laws)
    , interface_data(interfaces_in)
    , parameters(parameters_in)
  {
    AssertThrow(!interface_data.empty() || parameters.detection.enabled,
                dealii::ExcMessage("FiniteSliding: no contact interface given, and no detection."));
    AssertThrow(parameters.degree == 1 || parameters.degree == 2,
                dealii::ExcMessage("FiniteSliding: the degree must be 1 or 2, not " +
                                   std::to_string(parameters.degree) + "."));
    AssertThrow(std::isfinite(parameters.complementarity_constant) && parameters.complementarity_constant >= 0,
                dealii::ExcMessage("FiniteSliding: the complementarity constant must be positive (or 0 for the "
                                   "default rule)."));
    AssertThrow(std::isfinite(parameters.pairing_tolerance) && parameters.pairing_tolerance > 0,
                dealii::ExcMessage("FiniteSliding: the pairing tolerance must be positive."));
    AssertThrow(parameters.max_pairing_passes >= 1,
                dealii::ExcMessage("FiniteSliding: max_pairing_passes must be at least 1."));
    std::set<dealii::types::boundary_id> ids;
    for (unsigned int i = 0; i < interface_data.size(); ++i)
      {
        const double mu = interface_data[i].friction_coefficient;
        AssertThrow(std::isfinite(mu) && mu >= 0,
                    dealii::ExcMessage("FiniteSliding: interface " + std::to_string(i) +
                                       " has the friction coefficient " + std::to_string(mu) +
                                       "; it must be finite and not negative."));
        AssertThrow(mu == 0 || parameters.normal == ContactSettings::Normal::unilateral,
                    dealii::ExcMessage("FiniteSliding: interface " + std::to_string(i) +
                                       " has friction, but the contact is tied."));
        ids.insert(interface_data[i].master_id);
        ids.insert(interface_data[i].slave_id);
        reported.push_back({false, interface_data[i].master_id, interface_data[i].slave_id, 0, 0});
      }
    if (parameters.detection.enabled)
      {
        const auto &d = parameters.detection;
        for (const auto id : d.candidate_ids)
          AssertThrow(ids.count(id) == 0,
                      dealii::ExcMessage("FiniteSliding: the boundary id " + std::to_string(int(id)) +
                                         " is a side of a given interface and a candidate of the detection."));
        // the bodies with candidate edges, and every pair of them
        std::set<unsigned int> bodies;
        for (unsigned int e = 0; e < original.n_edges(); ++e)
          if (original.edge(e).at_boundary() && d.candidate_ids.count(original.edge(e).boundary_id) > 0)
            bodies.insert(original.cell(original.edge(e).cells[0]).material_id);
        for (auto a = bodies.begin(); a != bodies.end(); ++a)
          for (auto b = std::next(a); b != bodies.end(); ++b)
            reported.push_back({true, 0, 0, *a, *b});
        AssertThrow(original.n_edges() == 0 || ContactDetection::first_free_id(original) < 65535,
                    dealii::ExcMessage("FiniteSliding: no boundary id is left for detected interfaces."));
        ids.insert(d.candidate_ids.begin(), d.candidate_ids.end());
      }
    for (unsigned int e = 0; e < original.n_edges(); ++e)
      {
        const auto &edge = original.edge(e);
        if (edge.at_boundary() && ids.count(edge.boundary_id) > 0)
          {
            interface_edges.push_back({{edge.vertices[0], edge.vertices[1], edge.cells[0]}});
            side_neighbours[edge.vertices[0]].push_back(edge.vertices[1]);
            side_neighbours[edge.vertices[1]].push_back(edge.vertices[0]);
            edge_ids[edge_key(edge.vertices[0], edge.vertices[1])] = edge.boundary_id;
          }
      }
    // the vertices of each side, and those on a straight run of one side
    std::map<dealii::types::boundary_id, std::vector<unsigned int>> by_id;
    for (const auto &[v, around] : side_neighbours)
      {
        std::set<dealii::types::boundary_id> own;
        for (const unsigned int w : around)
          own.insert(edge_ids.at(edge_key(v, w)));
        for (const auto id : own)
          by_id[id].push_back(v);
        if (around.size() != 2 || own.size() != 1)
          continue;
        const dealii::Tensor<1, 2> d0 = original.vertex(v) - original.vertex(around[0]);
        const dealii::Tensor<1, 2> d1 = original.vertex(around[1]) - original.vertex(v);
        if (d0 * d1 > 0 && std::abs(d0[0] * d1[1] - d0[1] * d1[0]) <= 1e-12 * d0.norm() * d1.norm())
          movable.insert(v);
      }
    for (const auto &i : interface_data)
      given_sides.push_back({by_id[i.master_id], by_id[i.slave_id]});
    // the arcs of the curved parts, as node insertion sees them in the
    // reference configuration
    for (const auto id : ids)
      for (const auto &[e, kappa] : NodeInsertion::edge_curvatures(original, id))
        arc_kappa[edge_key(original.edge(e).vertices[0], original.edge(e).vertices[1])] = kappa;
    if (parameters.complementarity_constant == 0)
      parameters.complementarity_constant =
        this->laws.min_characteristic_stiffness() / original.cell_diameter_range().first;
    parameters.newton.scale_prescribed_motion = false;
    parameters.newton.check_fixed_pairs       = !parameters.reinsert;
    if (parameters.normal == ContactSettings::Normal::tied)
      parameters.reinsert = false;
  }



  ContactDetection::Result
  FiniteSliding::detect_candidates(PolygonalMesh<2> &there, const double distance_factor) const
  {
    const auto                          &d = parameters.detection;
    std::set<dealii::types::boundary_id> excluded;
    for (const auto id : original.get_boundary_ids())
      if (d.candidate_ids.count(id) == 0)
        excluded.insert(id);
    ContactDetection::Settings settings = d.settings;
    settings.split_edges                = false;
    settings.distance *= distance_factor;
    return ContactDetection::detect(there, excluded, ContactDetection::first_free_id(original), settings);
  }



  std::vector<FiniteSliding::PassInterface>
  FiniteSliding::pass_interfaces_at(
    const std::vector<dealii::Point<2>>                                            &x,
    std::vector<dealii::types::boundary_id>                                        &edge_ids_there,
    std::vector<bool>                                                              &detected_there,
    std::vector<std::pair<std::vector<unsigned int>, std::vector<unsigned int>>> &sides) const
  {
    std::vector<PassInterface> pass;
    for (unsigned int i = 0; i < interface_data.size(); ++i)
      pass.push_back({interface_data[i].master_id, interface_data[i].slave_id,
                      interface_data[i].friction_coefficient, i});
    sides = given_sides;
    edge_ids_there.resize(original.n_edges());
    detected_there.assign(original.n_edges(), false);
    for (unsigned int e = 0; e < original.n_edges(); ++e)
      edge_ids_there[e] = original.edge(e).boundary_id;
    const auto &d = parameters.detection;
    if (!d.enabled)
      return pass;
    // the detection on a copy of M_0 at x: its edges keep their numbers
    // (no split), so their new ids apply to every copy of M_0
    PolygonalMesh<2> there(original);
    for (unsigned int v = 0; v < original.n_vertices(); ++v)
      there.move_vertex(v, x[v]);
    const auto found = detect_candidates(there, 1.);
    for (unsigned int e = 0; e < there.n_edges(); ++e)
      if (there.edge(e).at_boundary() && there.edge(e).boundary_id != original.edge(e).boundary_id)
        {
          edge_ids_there[e] = there.edge(e).boundary_id;
          detected_there[e] = true;
        }
    // Each detected side grows along the candidate boundary of its body
    // to the next corner (a turn above the detection's corner angle), as a
    // side named by hand ends at the corners of a face: node insertion then
    // sees the same side whether the facing part is large or small, and the
    // vertex where a contact zone ends has both its edges on the side (its
    // normal and curvature from both). Two sides growing into each other
    // stop where they meet (an edge reached by both stays unlabelled).
    {
      std::map<unsigned int, std::vector<unsigned int>> at_vertex; // candidate boundary edges at a vertex
      for (unsigned int e = 0; e < there.n_edges(); ++e)
        if (there.edge(e).at_boundary() && d.candidate_ids.count(original.edge(e).boundary_id) > 0)
          for (const unsigned int v : there.edge(e).vertices)
            at_vertex[v].push_back(e);
      const auto normal = [&](const unsigned int e) {
        const auto          &ev = there.edge(e).vertices;
        dealii::Tensor<1, 2> t  = x[ev[1]] - x[ev[0]];
        dealii::Tensor<1, 2> n;
        n[0]           = t[1];
        n[1]           = -t[0];
        const double l = n.norm();
        return l > 0 ? n / l : n;
      };
      const double           cos_corner = std::cos(d.settings.corner_angle * M_PI / 180.);
      const auto             labelled   = [&](const unsigned int e) {
        return edge_ids_there[e] != original.edge(e).boundary_id;
      };
      std::vector<bool> blocked(original.n_edges(), false);
      std::vector<unsigned int> front;
      for (unsigned int e = 0; e < original.n_edges(); ++e)
        if (original.edge(e).at_boundary() && labelled(e))
          front.push_back(e);
      while (!front.empty())
        {
          std::map<unsigned int, std::set<dealii::types::boundary_id>> offered;
          for (const unsigned int e : front)
            for (const unsigned int v : there.edge(e).vertices)
              {
                const auto it = at_vertex.find(v);
                if (it == at_vertex.end() || it->second.size() != 2)
                  continue;
                const unsigned int f = it->second[0] == e ? it->second[1] : it->second[0];
                if (!labelled(f) && !blocked[f] && normal(e) * normal(f) >= cos_corner)
                  offered[f].insert(edge_ids_there[e]);
              }
          front.clear();
          for (const auto &[f, ids] : offered)
            if (ids.size() == 1)
              {
                edge_ids_there[f] = *ids.begin();
                front.push_back(f);
              }
            else
              blocked[f] = true;
        }
    }
    std::map<dealii::types::boundary_id, std::set<unsigned int>> side_vertices;
    for (unsigned int e = 0; e < original.n_edges(); ++e)
      if (original.edge(e).at_boundary() && edge_ids_there[e] != original.edge(e).boundary_id)
        for (const unsigned int v : original.edge(e).vertices)
          side_vertices[edge_ids_there[e]].insert(v);
    const unsigned int n_given = interface_data.size();
    for (const auto &itf : found.interfaces)
      {
        const unsigned int a = std::min(itf.master_body, itf.slave_body), b = std::max(itf.master_body, itf.slave_body);
        unsigned int       k = n_given;
        while (k < reported.size() && !(reported[k].body_a == a && reported[k].body_b == b))
          ++k;
        Assert(k < reported.size(), dealii::ExcInternalError());
        const double mu = d.friction ? d.friction(a, b) : 0.;
        AssertThrow(std::isfinite(mu) && mu >= 0 && (mu == 0 || parameters.normal == ContactSettings::Normal::unilateral),
                    dealii::ExcMessage("FiniteSliding: the friction coefficient between the bodies " +
                                       std::to_string(a) + " and " + std::to_string(b) + " is " +
                                       internal::number_string(mu) +
                                       "; it must be finite, not negative, and 0 with tied contact."));
        pass.push_back({itf.master_id, itf.slave_id, mu, k, itf.master_body, itf.slave_body});
        const auto &m = side_vertices[itf.master_id], &sl = side_vertices[itf.slave_id];
        sides.push_back({std::vector<unsigned int>(m.begin(), m.end()), std::vector<unsigned int>(sl.begin(), sl.end())});
      }
    return pass;
  }



  unsigned int
  FiniteSliding::uncovered_edges() const
  {
    const auto &d = parameters.detection;
    if (!d.enabled || current == nullptr || pass_partner.size() != original.n_edges())
      return 0;
    // the original vertices at the converged state (a vertex moved along
    // its straight side in the step's mesh stays on that side)
    const unsigned int n0 = original.n_vertices();
    PolygonalMesh<2>   there(original);
    for (unsigned int v = 0; v < n0; ++v)
      {
        dealii::Point<2> x = current->mesh->vertex(v);
        for (unsigned int comp = 0; comp < 2; ++comp)
          x[comp] += solution[VEMDoFHandler<2>::node_dof(current->dof_handler->vertex_node(v), comp)];
        there.move_vertex(v, x);
      }
    // (half the distance of the pairing passes: a band, so that a part at
    // the threshold is not taken in and left out by turns)
    const auto found = detect_candidates(there, 0.5);
    std::map<dealii::types::boundary_id, unsigned int> partner_of_id;
    for (const auto &itf : found.interfaces)
      {
        partner_of_id[itf.master_id] = itf.slave_body;
        partner_of_id[itf.slave_id]  = itf.master_body;
      }
    unsigned int n = 0;
    for (unsigned int e = 0; e < there.n_edges(); ++e)
      if (there.edge(e).at_boundary())
        {
          // (an edge the detection of the pass gave to another body faced
          // both: it faces the one it overlaps most, and the two
          // detections may weigh that differently; an edge a side grew
          // over faces the body of that side, or a new one)
          const auto it = partner_of_id.find(there.edge(e).boundary_id);
          if (it != partner_of_id.end() && pass_partner[e] != it->second &&
              (pass_partner[e] == dealii::numbers::invalid_unsigned_int || !pass_detected[e]))
            ++n;
        }
    return n;
  }



  dealii::Point<2>
  FiniteSliding::reference_point(const unsigned int a, const unsigned int b, const double s) const
  {
    const dealii::Point<2>    &Xa = original.vertex(a), &Xb = original.vertex(b);
    const dealii::Tensor<1, 2> d  = Xb - Xa;
    const dealii::Point<2>     chord = Xa + s * d;
    const auto                 it    = arc_kappa.find(edge_key(a, b));
    if (it == arc_kappa.end() || it->second == 0)
      return chord;
    // the circle of curvature kappa through Xa and Xb, on the outward side
    // of the chord for a convex part ((a, b) in the order of the edge's
    // vertices, which runs along the loop of its cell: the body lies to the
    // left of a -> b)
    const double L = d.norm(), R = 1. / std::abs(it->second);
    const double xi = (s - 0.5) * L;
    if (!(2 * R > L) || !(R > std::abs(xi)))
      return chord;
    const double         sag = std::sqrt(R * R - xi * xi) - std::sqrt(R * R - 0.25 * L * L);
    dealii::Tensor<1, 2> outward;
    outward[0] = d[1] / L;
    outward[1] = -d[0] / L;
    return chord + (it->second > 0 ? sag : -sag) * outward;
  }



  FiniteSliding::~FiniteSliding()
  {
    // the solver and the contact refer to the assembler and the DoF
    // handler, which refers to the mesh
    solver.reset();
    contact.reset();
    assembler.reset();
    current.reset();
    start.reset();
    first_pass_disc.reset();
  }



  void
  FiniteSliding::set_constraints_function(const ConstraintsFunction &f)
  {
    constraints_function = f;
  }



  void
  FiniteSliding::set_loads(const LoadsFunction &f, const std::function<double(double)> &load_factor)
  {
    loads_function       = f;
    load_factor_function = load_factor;
  }



  const PolygonalMesh<2> &
  FiniteSliding::get_mesh() const
  {
    AssertThrow(current != nullptr, dealii::ExcMessage("FiniteSliding: no step has been solved yet."));
    return *current->mesh;
  }



  const VEMDoFHandler<2> &
  FiniteSliding::get_dof_handler() const
  {
    AssertThrow(current != nullptr, dealii::ExcMessage("FiniteSliding: no step has been solved yet."));
    return *current->dof_handler;
  }



  const dealii::Vector<double> &
  FiniteSliding::get_solution() const
  {
    return solution;
  }



  const dealii::Vector<double> &
  FiniteSliding::get_multipliers() const
  {
    return multipliers;
  }



  double
  FiniteSliding::strain_energy() const
  {
    AssertThrow(assembler != nullptr && !last_failed,
                dealii::ExcMessage("FiniteSliding::strain_energy(): no step has converged yet."));
    return assembler->strain_energy(solution);
  }



  const FiniteStrainContact &
  FiniteSliding::get_contact() const
  {
    AssertThrow(contact != nullptr, dealii::ExcMessage("FiniteSliding: no step has been solved yet."));
    return *contact;
  }



  dealii::Vector<double>
  FiniteSliding::transfer(const Discretization &from, const dealii::Vector<double> &u_old,
                          const Discretization &to) const
  {
    if (&from == &to)
      return u_old;
    const auto &old_mesh = *from.mesh;
    const auto &old_dofs = *from.dof_handler;
    const auto &new_mesh = *to.mesh;
    const auto &new_dofs = *to.dof_handler;
    const auto  n0       = original.n_vertices();
    dealii::Vector<double> u_new(new_dofs.n_dofs());
    const auto copy = [&](const unsigned int new_node, const unsigned int old_node) {
      for (unsigned int comp = 0; comp < 2; ++comp)
        u_new[VEMDoFHandler<2>::node_dof(new_node, comp)] = u_old[VEMDoFHandler<2>::node_dof(old_node, comp)];
    };
    // the vertices and the cell moments of M_0, and the edges of M_0 that
    // are not interface edges, keep their values
    for (unsigned int v = 0; v < n0; ++v)
      copy(new_dofs.vertex_node(v), old_dofs.vertex_node(v));
    if (parameters.degree == 2)
      {
        for (unsigned int cell = 0; cell < new_mesh.n_cells(); ++cell)
          copy(new_dofs.cell_node(cell), old_dofs.cell_node(cell));
        std::map<std::uint64_t, unsigned int> old_edges;
        for (unsigned int e = 0; e < old_mesh.n_edges(); ++e)
          {
            const auto &ev = old_mesh.edge(e).vertices;
            if (ev[0] < n0 && ev[1] < n0)
              old_edges[edge_key(ev[0], ev[1])] = e;
          }
        for (unsigned int e = 0; e < new_mesh.n_edges(); ++e)
          {
            const auto &ev = new_mesh.edge(e).vertices;
            if (ev[0] < n0 && ev[1] < n0)
              {
                const auto it = old_edges.find(edge_key(ev[0], ev[1]));
                if (it != old_edges.end())
                  copy(new_dofs.edge_node(e), old_dofs.edge_node(it->second));
              }
          }
      }
    // the nodes on the interface edges: the old trace at their material
    // points (the vertices of M_0 too: one moved along a straight side in
    // either mesh has a new material point)
    const auto         neighbours = neighbours_along_sides();
    const TraceOnSides old_trace(original, interface_edges, neighbours, old_mesh, old_dofs, u_old);
    for (const auto &[a, b, cell] : interface_edges)
      {
        const Chain new_chain = make_chain(new_mesh, a, b, cell, new_mesh.get_vertices());
        const auto  set       = [&](const unsigned int node, const dealii::Point<2> &X) {
          const auto value = old_trace.value(X, a, b);
          for (unsigned int comp = 0; comp < 2; ++comp)
            u_new[VEMDoFHandler<2>::node_dof(node, comp)] = value[comp];
        };
        for (unsigned int k = 0; k < new_chain.vertices.size(); ++k)
          set(new_dofs.vertex_node(new_chain.vertices[k]), new_mesh.vertex(new_chain.vertices[k]));
        if (parameters.degree == 2)
          for (unsigned int k = 0; k + 1 < new_chain.vertices.size(); ++k)
            set(new_dofs.edge_node(new_chain.edges[k]),
                dealii::Point<2>(0.5 * (new_mesh.vertex(new_chain.vertices[k]) +
                                        new_mesh.vertex(new_chain.vertices[k + 1]))));
      }
    return u_new;
  }



  std::map<unsigned int, std::vector<unsigned int>>
  FiniteSliding::neighbours_along_sides() const
  {
    if (!parameters.detection.enabled)
      return side_neighbours;
    std::map<unsigned int, std::vector<unsigned int>> result;
    for (const auto &entry : side_neighbours)
      result.emplace(entry.first, neighbours_on_sides(entry.first));
    return result;
  }



  std::vector<unsigned int>
  FiniteSliding::neighbours_on_sides(const unsigned int v) const
  {
    const auto &all = side_neighbours.at(v);
    if (!parameters.detection.enabled || all.size() < 2)
      return all;
    // (with detection the whole free boundary is a candidate: a corner of a
    // body has the neighbour of the face on a side of the pass only, as on
    // a named side)
    std::vector<unsigned int> kept;
    for (const unsigned int w : all)
      for (const auto &sides : interface_sides)
        if (std::binary_search(sides.first.begin(), sides.first.end(), w) ||
            std::binary_search(sides.second.begin(), sides.second.end(), w))
          {
            kept.push_back(w);
            break;
          }
    return kept.empty() ? all : kept;
  }



  void
  FiniteSliding::snap_close_vertices(std::vector<dealii::Point<2>> &x)
  {
    const auto unit = [](const dealii::Tensor<1, 2> &t) { return t / t.norm(); };
    const auto around_of = [&](const unsigned int v) { return neighbours_on_sides(v); };
    // the unit tangent of a side at a vertex, and the shortest edge there
    const auto tangent = [&](const unsigned int v) {
      const auto around = around_of(v);
      return unit(around.size() == 2 ? x[around[1]] - x[around[0]] : x[around[0]] - x[v]);
    };
    const auto local_h = [&](const unsigned int v) {
      double h = std::numeric_limits<double>::max();
      for (const unsigned int w : around_of(v))
        h = std::min(h, x[v].distance(x[w]));
      return h;
    };
    struct Candidate
    {
      double       distance;
      unsigned int v, w;
    };
    std::vector<Candidate> candidates;
    for (const auto &sides : interface_sides)
      for (const bool slave_moves : {true, false})
        {
          const auto &own   = slave_moves ? sides.second : sides.first;
          const auto &other = slave_moves ? sides.first : sides.second;
          for (const unsigned int v : own)
            {
              if (movable.count(v) == 0)
                continue;
              const dealii::Tensor<1, 2> t = tangent(v);
              // a pair snapped in an earlier pass of the step stays so
              // while its vertices remain within half an edge of each other:
              // the decisions of a step only grow, so they settle after
              // finitely many passes (a threshold that could also drop a
              // pair flips near it from pass to pass: the moved material
              // point faces the vertex, the original one does not)
              unsigned int kept = dealii::numbers::invalid_unsigned_int;
              for (const unsigned int w : other)
                if (step_snaps.count({v, w}) > 0)
                  kept = w;
              double       best   = std::numeric_limits<double>::max();
              unsigned int best_w = 0;
              if (kept != dealii::numbers::invalid_unsigned_int)
                {
                  best   = x[v].distance(x[kept]);
                  best_w = kept;
                }
              else
                for (const unsigned int w : other)
                  if (const double d = x[v].distance(x[w]); d < best)
                    {
                      best   = d;
                      best_w = w;
                    }
              if (best == std::numeric_limits<double>::max())
                continue;
              // (a master vertex moves only where its slave partner cannot)
              if (!slave_moves && movable.count(best_w) > 0)
                continue;
              const double h     = std::min(local_h(v), local_h(best_w));
              const double along = std::abs((x[best_w] - x[v]) * t);
              const double apart = std::abs(turn_left(t) * (x[best_w] - x[v]));
              const bool   again = kept != dealii::numbers::invalid_unsigned_int;
              if (along <= (again ? 0.5 : 0.05) * h && apart <= 0.5 * h)
                candidates.push_back({again ? -1. : along, v, best_w});
            }
        }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate &a, const Candidate &b) {
      return a.distance < b.distance || (a.distance == b.distance && a.v < b.v);
    });
    std::set<unsigned int> used;
    for (const auto &c : candidates)
      {
        if (used.count(c.v) > 0 || used.count(c.w) > 0)
          continue;
        used.insert(c.v);
        used.insert(c.w);
        step_snaps.insert({c.v, c.w});
        // onto the normal of the other side through w: the insertion finds
        // w as the closest point of v's new position
        const dealii::Tensor<1, 2> n = turn_left(tangent(c.w));
        x[c.v]                       = x[c.w] + ((x[c.v] - x[c.w]) * n) * n;
      }
  }



  dealii::Vector<double>
  FiniteSliding::relaxed_pairing_state()
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
        if (parameters.degree == 2)
          for (unsigned int k = 0; k + 1 < chain.vertices.size(); ++k)
            {
              const double sm = 0.5 * (chain.s[k] + chain.s[k + 1]);
              add(dofs.edge_node(chain.edges[k]), (1 - sm) * ca + sm * cb);
            }
      }
    for (const auto &[v, c] : correction)
      add(dofs.vertex_node(v), c);
    return u;
  }



  dealii::Vector<double>
  FiniteSliding::extrapolate(const Discretization &disc, const dealii::Vector<double> &u1,
                             const dealii::Vector<double> &u0, const double s) const
  {
    // Each edge-connected piece moves from x0 = X + u0 to x1 = X + u1 by a
    // rigid motion (the least-squares fit over its nodes: the rotation
    // theta about the centroid c, and the move of the centroid) and a
    // remainder r. The prediction turns the piece on by s theta about its
    // centroid, moves the centroid on by s times its move, and adds s r:
    // exact for rigid motions, translations and, without rotation, the
    // linear extrapolation. (A rotation extrapolated linearly is off along
    // the arc by about (s theta)^2 R / 2: a bore turned by 30 degrees a
    // step put its nodes 0.27 radii off the circle.)
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
    dealii::Vector<double> u(u1.size());
    for (unsigned int node = 0; node < n_nodes; ++node)
      {
        const unsigned int p     = piece_of_node[node];
        const double       theta = (dot[p] != 0 || cross[p] != 0) ? std::atan2(cross[p], dot[p]) : 0.;
        const dealii::Point<2>     x0 = position(u0, node), x1 = position(u1, node);
        const dealii::Tensor<1, 2> remainder = (x1 - c1[p]) - rotate(theta, x0 - c0[p]);
        const dealii::Point<2>     x2 =
          c1[p] + s * (c1[p] - c0[p]) + rotate(s * theta, x1 - c1[p]) + s * remainder;
        for (unsigned int comp = 0; comp < 2; ++comp)
          u[VEMDoFHandler<2>::node_dof(node, comp)] = x2[comp] - dofs.node_location(node)[comp];
      }
    return u;
  }



  void
  FiniteSliding::prepare_pass(const double time, const double load_factor, const unsigned int step,
                              const bool first_pass, StepRecord &record)
  {
    const auto   clock  = std::chrono::steady_clock::now();
    const auto   degree = parameters.degree;
    const auto   n0     = original.n_vertices();
    const double c      = parameters.complementarity_constant;

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

    // where the pairs are made: a later pass at the end of the last pass;
    // the first pass of a step where the step is expected to end, the
    // linear extrapolation of the last two steps in time (else where it
    // starts)
    const Discretization  *pair_disc = first_pass ? start.get() : current.get();
    dealii::Vector<double> u_pair    = first_pass ? start_solution : solution;
    if (first_pass)
      {
        step_snaps.clear();
        step_paired.clear();
        step_damped = false;
        anderson_x.clear();
        anderson_r.clear();
      }
    else if (pairing_base.size() == solution.size())
      u_pair = relaxed_pairing_state();
    const bool with_extrapolation = first_pass && n_converged >= 2 && start_previous_solution.size() == u_pair.size() &&
                             last_time != previous_time;
    // whether the pairs are made where the step is expected to end (an
    // extrapolation or the end of a pass), not where it starts
    bool predicted = !first_pass;
    if (with_extrapolation)
      {
        const double s = (time - last_time) / (last_time - previous_time);
        if (std::isfinite(s) && s > 0 && s <= 4)
          {
            u_pair    = extrapolate(*start, start_solution, start_previous_solution, s);
            predicted = true;
          }
      }

    // 1. the original vertices at their positions there, paired by node
    // insertion
    std::vector<dealii::Point<2>>         x_pair(n0), x_true(n0);
    std::unique_ptr<Discretization>       next;
    std::vector<NodeInsertion::Interface> new_interfaces;
    std::vector<PassInterface>            new_pass;
    std::vector<unsigned int>             new_partner;
    std::vector<bool>                     new_detected;
    const auto pair_at = [&](const dealii::Vector<double> &u) {
      for (unsigned int v = 0; v < n0; ++v)
        {
          x_pair[v] = original.vertex(v);
          if (pair_disc != nullptr)
            for (unsigned int comp = 0; comp < 2; ++comp)
              x_pair[v][comp] += u[VEMDoFHandler<2>::node_dof(pair_disc->dof_handler->vertex_node(v), comp)];
        }
      // (a vertex of a straight side moved in that mesh (step 2): where its
      // original material point is, from the trace)
      // (the trace only where the last mesh moved a vertex: most steps none)
      if (pair_disc != nullptr &&
          std::any_of(movable.begin(), movable.end(),
                      [&](const unsigned int v) { return pair_disc->mesh->vertex(v) != original.vertex(v); }))
        {
          const auto         neighbours = neighbours_along_sides();
          const TraceOnSides trace(original, interface_edges, neighbours, *pair_disc->mesh,
                                   *pair_disc->dof_handler, u);
          for (const unsigned int v : movable)
            if (pair_disc->mesh->vertex(v) != original.vertex(v))
              x_pair[v] = original.vertex(v) + trace.value(original.vertex(v), v, side_neighbours.at(v)[0]);
        }
      x_true = x_pair;
      // the interfaces there: the given ones, and those the detection finds
      // (Parameters::detection) with the ids of their edges
      std::vector<dealii::types::boundary_id> ids_there;
      if (first_pass || redetect || step_labels.size() != original.n_edges())
        {
          new_pass      = pass_interfaces_at(x_pair, ids_there, new_detected, interface_sides);
          step_pass     = new_pass;
          step_labels   = ids_there;
          step_detected = new_detected;
          step_sides    = interface_sides;
          redetect      = false;
        }
      else
        {
          new_detected    = step_detected;
          // (later passes keep the interfaces of the step: a part at the
          // detection distance would otherwise be taken in and left out by
          // turns, and the passes would not settle)
          new_pass        = step_pass;
          ids_there       = step_labels;
          interface_sides = step_sides;
        }
      // A vertex of a straight side that faces a vertex of the other side
      // within 0.05 of the local edge length along the sides is paired with
      // it: the insertion sees it on the normal through that vertex (here
      // only), and its material point is then moved along its straight
      // side to the point that faces the other vertex (step 2). No sub-edge
      // that short is made, and the pair is exact.
      snap_close_vertices(x_pair);
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
          if (movable.count(m) > 0 || movable.count(sv) > 0)
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
      next       = std::make_unique<Discretization>();
      next->mesh = std::make_unique<PolygonalMesh<2>>(original);
      for (unsigned int v = 0; v < n0; ++v)
        next->mesh->move_vertex(v, x_pair[v]);
      new_partner.assign(original.n_edges(), dealii::numbers::invalid_unsigned_int);
      if (parameters.detection.enabled)
        {
          std::map<dealii::types::boundary_id, unsigned int> partner_of_id;
          for (const auto &i : new_pass)
            {
              partner_of_id[i.master_id] = i.slave_body;
              partner_of_id[i.slave_id]  = i.master_body;
            }
          for (unsigned int e = 0; e < original.n_edges(); ++e)
            if (original.edge(e).at_boundary() && ids_there[e] != original.edge(e).boundary_id)
              {
                next->mesh->set_edge_boundary_id(e, ids_there[e]);
                new_partner[e] = partner_of_id.at(ids_there[e]);
              }
        }
      new_interfaces.clear();
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
          for (unsigned int i = 0; i < new_pass.size(); ++i)
            new_interfaces.push_back(
              NodeInsertion::insert(*next->mesh, new_pass[i].master_id, new_pass[i].slave_id, degree, settings, i));
        }
      catch (const dealii::ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          const std::string message = "FiniteSliding: pairing the interfaces in the current configuration of step " +
                                      std::to_string(step) + " failed: " + info.str();
          // (where the step starts, the pairing is the same for every
          // sub-step: cutting the step back cannot help)
          if (first_pass && !predicted)
            AssertThrow(false, ExcStepInput(message));
          AssertThrow(false, dealii::ExcMessage(message));
        }
    };
    try
      {
        pair_at(u_pair);
      }
    catch (const dealii::ExceptionBase &)
      {
        // an extrapolated configuration may not be a valid one: pair where
        // the step starts
        if (!(first_pass && predicted))
          throw;
        u_pair    = start_solution;
        predicted = false;
        pair_at(u_pair);
      }

    if (first_pass)
      step_merges.clear();
    for (const auto &interface : new_interfaces)
      for (const auto &pair : interface.pairs)
        if (!pair.is_midpoint)
          {
            if (pair.master_entity < n0 && pair.slave_entity < n0)
              step_merges.insert({pair.master_entity, pair.slave_entity});
            for (const unsigned int v : {pair.master_entity, pair.slave_entity})
              if (v < n0)
                step_paired.insert(v);
          }
    // 2. the inserted vertices back to the reference configuration, by
    // their parameter on the original edge
    std::vector<dealii::Point<2>> x_now = next->mesh->get_vertices();
    for (unsigned int v = 0; v < n0; ++v)
      x_now[v] = x_pair[v];
    std::vector<dealii::Point<2>> reference(next->mesh->n_vertices());
    std::vector<bool>             placed(next->mesh->n_vertices(), false);
    for (unsigned int v = 0; v < n0; ++v)
      {
        reference[v] = original.vertex(v);
        placed[v]    = true;
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
    for (const auto &interface : new_interfaces)
        for (const auto &pair : interface.pairs)
          if (!pair.is_midpoint)
            {
              if (pair.master_entity >= n0)
                partner[pair.master_entity] = pair.slave_entity;
              if (pair.slave_entity >= n0)
                partner[pair.slave_entity] = pair.master_entity;
            }
    std::unique_ptr<TraceOnSides> pair_trace;
    const auto                    trace_neighbours = neighbours_along_sides();
    if (pair_disc != nullptr)
      pair_trace = std::make_unique<TraceOnSides>(original, interface_edges, trace_neighbours, *pair_disc->mesh,
                                                  *pair_disc->dof_handler, u_pair);
    std::vector<std::tuple<unsigned int, unsigned int, Chain>> chains;
    for (const auto &[a, b, cell] : interface_edges)
      {
        Chain chain = make_chain(*next->mesh, a, b, cell, x_now);
        if (pair_disc != nullptr && !partner.empty() && chain.vertices.size() > 2)
          {
            const Chain old_chain = make_chain(*pair_disc->mesh, a, b, cell, pair_disc->mesh->get_vertices(),
                                               &original.vertex(a), &original.vertex(b));
            const auto curve = [&, a = a, b = b](const double s) {
              const dealii::Point<2> X = reference_point(a, b, s);
              return dealii::Point<2>(X + pair_trace->value(X, a, b));
            };
            std::vector<double> corrected(chain.vertices.size(), -1.);
            for (unsigned int k = 1; k + 1 < chain.vertices.size(); ++k)
              {
                const auto it = partner.find(chain.vertices[k]);
                if (it == partner.end())
                  continue;
                const dealii::Point<2> target = x_true[it->second];
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
                if (best_d < 0.5 * x_now[a].distance(x_now[b]))
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
        chains.push_back({a, b, std::move(chain)});
      }

    for (auto &[a, b, chain] : chains)
      for (unsigned int k = 1; k + 1 < chain.vertices.size(); ++k)
        {
          const unsigned int v = chain.vertices[k];
          reference[v]         = reference_point(a, b, chain.s[k]);
          placed[v]            = true;
        }

    // Pairs of two original vertices (merged by the insertion, or paired
    // by snap_close_vertices()): the vertex on a straight side (the
    // slave's if both are) moves along its side to the material point
    // that faces its partner, the closest point of its side's current
    // curve (the trace where the pairs are made) to the partner, within
    // 0.9 of the way to the next node on either side. The mesh keeps its
    // cells (the side is straight, so the body does not change), and the
    // state follows the material points (transfer()). Without this the two
    // partners stay apart by where the insertion found them.
    for (const auto &interface : new_interfaces)
      for (const auto &pair : interface.pairs)
        {
          if (pair.is_midpoint || pair.master_entity >= n0 || pair.slave_entity >= n0)
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
              h = std::min(h, x_true[q].distance(x_true[w]));
          if (x_true[v].distance(x_true[p]) > 0.5 * h)
            continue;
          const dealii::Point<2>     X = original.vertex(v);
          const dealii::Tensor<1, 2> T = (original.vertex(around[1]) - original.vertex(around[0])) /
                                         original.vertex(around[1]).distance(original.vertex(around[0]));
          // the nearest nodes along the side (the line coordinate sigma
          // from the original position of v)
          double lo = (original.vertex(around[0]) - X) * T, hi = (original.vertex(around[1]) - X) * T;
          for (const auto &[a, b, chain] : chains)
            if (a == v || b == v)
              for (const unsigned int w : chain.vertices)
                if (w != v)
                  {
                    const double sigma = (reference[w] - X) * T;
                    if (sigma < 0)
                      lo = std::max(lo, sigma);
                    else
                      hi = std::min(hi, sigma);
                  }
          lo *= 0.9;
          hi *= 0.9;
          const auto curve = [&](const double sigma) {
            const dealii::Point<2> Y = X + sigma * T;
            if (pair_trace == nullptr)
              return Y;
            return dealii::Point<2>(Y + pair_trace->value(Y, v, sigma < 0 ? around[0] : around[1]));
          };
          const dealii::Point<2> target = x_true[p];
          const double best = closest_on_curve(curve, lo, hi, 0., target, 16, 1e-7, 1e-15 * (hi - lo));
          reference[v]      = X + best * T;
        }
    record.n_moved = 0;
    for (unsigned int v = 0; v < n0; ++v)
      if (reference[v] != original.vertex(v))
        ++record.n_moved;
    for (unsigned int v = 0; v < next->mesh->n_vertices(); ++v)
      {
        AssertThrow(placed[v], dealii::ExcMessage("FiniteSliding: an inserted vertex lies on no interface edge of "
                                                  "the original mesh."));
        next->mesh->move_vertex(v, reference[v]);
      }
    next->mesh->validate();
    next->dof_handler = std::make_unique<VEMDoFHandler<2>>(*next->mesh);
    next->dof_handler->distribute_dofs(degree);
    record.n_inserted = 0;
    for (const auto &i : new_interfaces)
      record.n_inserted += i.report.n_inserted_master + i.report.n_inserted_slave;

    // 3. the states on the new mesh: where the pairs were made, where the
    // step started, and the step before (for the extrapolation)
    const auto n_new  = next->dof_handler->n_dofs();
    const auto states = [&](const Discretization *from, const dealii::Vector<double> &u) {
      return from == nullptr ? dealii::Vector<double>(n_new) : transfer(*from, u, *next);
    };
    const dealii::Vector<double> u_base   = states(pair_disc, u_pair);
    // a later pass starts Newton from the last pass's solution (the
    // pairing state above is relaxed at the interface only)
    const dealii::Vector<double> u_newton = first_pass ? dealii::Vector<double>() : states(pair_disc, solution);
    const dealii::Vector<double> u_origin = states(start.get(), start_solution);
    // where the contacts that begin within the step begin: the first
    // pairing configuration of the step that predicts its end (until there
    // is one, this pass's)
    if (first_pass)
      first_pass_disc.reset();
    const dealii::Vector<double> u_contact =
      first_pass_disc == nullptr ? u_base : states(first_pass_disc.get(), first_pass_pairing);
    dealii::Vector<double>       u_previous;
    const bool with_previous = first_pass && n_converged >= 2 && start_previous_solution.size() > 0;
    if (with_previous)
      u_previous = states(start.get(), start_previous_solution);

    // 4. the contact of the new pairs
    FiniteStrainContact::Options options;
    options.base        = &u_base;
    options.slip_origin    = &u_origin;
    options.contact_origin = &u_contact;
    for (const auto &i : new_pass)
      options.friction_coefficients.push_back(i.friction_coefficient);
    auto new_contact = std::make_unique<FiniteStrainContact>(*next->dof_handler, new_interfaces, parameters.normal, c,
                                                             options);

    // the multipliers: the traction of the nearest pair of the same
    // interface where the pairs were made, times the new weight
    dealii::Vector<double> lambda(new_contact->n_constraints());
    const dealii::Vector<double> &lambda_old = first_pass ? start_multipliers : multipliers;
    if (contact != nullptr && pair_disc != nullptr && lambda_old.size() == contact->n_constraints())
      {
        const auto old_weights = contact->current_weights(u_pair);
        const auto new_weights = new_contact->current_weights(u_base);
        const auto np_old = contact->n_pairs(), np_new = new_contact->n_pairs();
        const bool both_tangential =
          new_contact->n_constraints() == 2 * np_new && contact->n_constraints() == 2 * np_old;
        for (unsigned int i = 0; i < np_new; ++i)
          {
            const auto   x       = new_contact->current_positions(i, u_base)[1];
            // (the same reported interface: with detection, the interfaces
            // of two passes may be numbered differently)
            const auto   id      = new_pass[new_contact->get_pairs()[i].interface].reported;
            double       best    = std::numeric_limits<double>::max();
            unsigned int nearest = np_old;
            for (unsigned int o = 0; o < np_old; ++o)
              if (pass_interfaces[contact->get_pairs()[o].interface].reported == id)
                {
                  const double d = contact->current_positions(o, u_pair)[1].distance_square(x);
                  if (d < best)
                    {
                      best    = d;
                      nearest = o;
                    }
                }
            if (nearest == np_old || old_weights[nearest] <= 0)
              continue;
            lambda[i] = lambda_old[nearest] / old_weights[nearest] * new_weights[i];
            if (both_tangential)
              lambda[np_new + i] = lambda_old[np_old + nearest] / old_weights[nearest] * new_weights[i];
          }
      }

    // the new objects replace the old ones (in the order of their
    // references; the start of the step stays)
    solver.reset();
    contact.reset();
    assembler.reset();
    if (predicted && first_pass_disc == nullptr && parameters.reinsert)
      {
        // a copy of this pass's mesh and DoFs with its pairing state
        first_pass_disc              = std::make_unique<Discretization>();
        first_pass_disc->mesh        = std::make_unique<PolygonalMesh<2>>(*next->mesh);
        first_pass_disc->dof_handler = std::make_unique<VEMDoFHandler<2>>(*first_pass_disc->mesh);
        first_pass_disc->dof_handler->distribute_dofs(degree);
        first_pass_pairing = u_base;
      }
    current    = std::move(next);
    contact         = std::move(new_contact);
    interfaces      = std::move(new_interfaces);
    pass_interfaces = std::move(new_pass);
    pass_partner    = std::move(new_partner);
    pass_detected   = std::move(new_detected);

    assembler = std::make_unique<FiniteStrainAssembler<2>>(*current->dof_handler, laws, 1.0, parameters.stabilization);
    if (loads_function)
      loads_function(*assembler);
    constraints.clear();
    constraints_function(*current->dof_handler, time, constraints);
    AssertThrow(constraints.is_closed(),
                dealii::ExcMessage("FiniteSliding: the constraints function must close the constraints."));
    solver = std::make_unique<FiniteStrainSolver<2>>(*assembler, constraints, parameters.newton);
    solver->set_contact(*contact);
    if (first_pass)
      {
        solver->set_state(u_origin, lambda, last_load_factor, last_step, with_previous ? &u_previous : nullptr,
                          previous_load_factor, previous_step);
        solution = u_origin;
      }
    else
      {
        solver->set_state(u_newton, lambda, load_factor, step);
        solution = u_newton;
      }
    pairing_base = u_base;
    multipliers = lambda;
    record.n_pairs = contact->n_pairs();
    record.n_dofs  = current->dof_handler->n_dofs();
    record.setup_time += std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
  }



  void
  FiniteSliding::evaluate(StepRecord &record) const
  {
    const auto np = contact->n_pairs();
    const auto n0 = original.n_vertices();
    record.normal_force.assign(reported.size(), dealii::Tensor<1, 2>());
    record.friction_force.assign(reported.size(), dealii::Tensor<1, 2>());
    record.n_detected  = pass_interfaces.size() - interface_data.size();
    record.n_uncovered = uncovered_edges();
    record.n_active = record.n_slipping = record.n_new_contacts = record.n_sticking_in_contact = 0;
    record.max_slip = record.pairing_offset = record.merged_offset = record.dissipation = 0;
    record.n_merged                         = 0;
    // at each pair, the shortest current slave sub-edge (for the slip) and
    // the length of the sub-edges it touches (the chord over which its
    // normal turns: the scale of the pairing offset)
    std::vector<double> h(np, std::numeric_limits<double>::max()), chord(np, 0.);
    unsigned int        offset = 0;
    for (const auto &interface : interfaces)
      {
        for (const auto &s : interface.segments)
          {
            const double L = contact->current_positions(offset + s.first, solution)[1].distance(
              contact->current_positions(offset + s.second, solution)[1]);
            for (const unsigned int p : {s.first, s.second, s.midpoint})
              if (p != dealii::numbers::invalid_unsigned_int)
                {
                  h[offset + p] = std::min(h[offset + p], L);
                  chord[offset + p] += L;
                }
          }
        offset += interface.pairs.size();
      }
    const bool two = (contact->n_constraints() == 2 * np);
    for (unsigned int i = 0; i < np; ++i)
      {
        if (contact->is_left_out(i))
          continue;
        const auto interface = pass_interfaces[contact->get_pairs()[i].interface].reported;
        const auto n         = reported_sign(contact->get_pairs()[i].interface) * contact->current_normal(i, solution);
        const auto t         = turn_left(n);
        const bool active    = multipliers[i] != 0;
        if (active && contact->is_new_contact(i))
          ++record.n_new_contacts;
        if (active)
          {
            record.normal_force[interface] -= multipliers[i] * n;
            ++record.n_active;
            // (midpoint pairs of k = 2 on a curved interface are apart by
            // the difference of the two sides' parametrizations, O(h^3))
            const auto   x   = contact->current_positions(i, solution);
            const double off = std::abs((x[1] - x[0]) * t);
            const auto &pair   = contact->get_pairs()[i];
            // (two vertices of the original mesh: a merge, Parameters::
            // insertion's merge_fraction)
            if (chord[i] > 0 && !pair.is_midpoint && pair.master_entity < n0 && pair.slave_entity < n0)
              {
                ++record.n_merged;
                record.merged_offset = std::max(record.merged_offset, off / chord[i]);
              }
            else if (chord[i] > 0 && !pair.is_midpoint)
              {
                record.pairing_offset = std::max(record.pairing_offset, off / chord[i]);
              }
          }
        else if (chord[i] > 0 && !contact->get_pairs()[i].is_midpoint)
          {
            // An open pair: its partners need only be opposite each other
            // within its gap. One whose partners slid apart by more than the
            // gap may no longer see the other side where it is (a bore
            // turned by a large step, paired where a linear prediction put
            // it, came out with every pair open and the bodies overlapping):
            // it counts in the pairing offset, and the step makes its pairs
            // again.
            const auto   x   = contact->current_positions(i, solution);
            const double off = std::abs((x[1] - x[0]) * t);
            const double gap = contact->value(i, solution);
            record.pairing_offset = std::max(record.pairing_offset, std::max(0., off - std::max(gap, 0.)) / chord[i]);
          }
        if (two)
          {
            const double lt = multipliers[np + i];
            record.friction_force[interface] -= lt * t;
            if (contact->is_frictional() && active && lt != 0 &&
                std::abs(lt) >= contact->friction_coefficient(i) * std::abs(multipliers[i]) * (1 - 1e-9))
              ++record.n_slipping;
            else if (contact->is_frictional() && active && !contact->is_new_contact(i))
              ++record.n_sticking_in_contact;
            if (contact->is_frictional())
              record.dissipation += std::abs(lt * contact->value(np + i, solution));
            if (contact->is_frictional() && h[i] < std::numeric_limits<double>::max())
              record.max_slip = std::max(record.max_slip, std::abs(contact->value(np + i, solution)) / h[i]);
          }
      }
  }



  void
  FiniteSliding::solve_step(const unsigned int step, const double time)
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
  FiniteSliding::solve_with_cutbacks(const unsigned int step,
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
  FiniteSliding::solve_increment(const unsigned int step, const double time, StepRecord &record)
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
          break;
        redetect = record.n_uncovered > 0;
        AssertThrow(pass < parameters.max_pairing_passes || record.n_uncovered == 0,
                    dealii::ExcMessage("FiniteSliding: step " + std::to_string(step) + " (time " +
                                       std::to_string(time) + "): after " + std::to_string(pass) +
                                       " passes of pairing at the converged state, " +
                                       std::to_string(record.n_uncovered) +
                                       " boundary edges still face another body on no interface of the pass "
                                       "(contact detection, 'Contact/Pairs = auto'); take smaller steps or raise "
                                       "Parameters::max_pairing_passes."));
        AssertThrow(pass < parameters.max_pairing_passes,
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
  FiniteSliding::check_support(const unsigned int step, const double time) const
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



  void
  FiniteSliding::run(const unsigned int n_steps, const double t0, const double t1)
  {
    const unsigned int first = last_step + 1;
    for (unsigned int i = 1; i <= n_steps; ++i)
      solve_step(first + i - 1, t0 + (t1 - t0) * i / n_steps);
  }



  FiniteSliding::NodalForces
  FiniteSliding::nodal_forces() const
  {
    AssertThrow(assembler != nullptr && contact != nullptr && n_converged > 0 && !last_failed,
                dealii::ExcMessage("FiniteSliding::nodal_forces(): no step has converged yet."));
    const unsigned int n = current->dof_handler->n_dofs();
    NodalForces        forces;
    // the residual lambda f_ext - f_int(u) at the load factors 0 and the
    // step's gives both parts
    dealii::Vector<double> residual(n);
    assembler->assemble(solution, 0., residual, constraints, nullptr, nullptr);
    forces.internal = residual;
    forces.internal *= -1.;
    assembler->assemble(solution, last_load_factor, residual, constraints, nullptr, nullptr);
    forces.external = residual;
    forces.external += forces.internal;
    forces.contact.reinit(n);
    FiniteStrainConstraints::Linearization lin;
    for (unsigned int j = 0; j < contact->n_constraints(); ++j)
      if (!contact->is_left_out(j) && multipliers[j] != 0)
        {
          contact->linearize(j, solution, lin, false);
          for (unsigned int k = 0; k < lin.dofs.size(); ++k)
            if (lin.dofs[k] < n)
              forces.contact[lin.dofs[k]] -= multipliers[j] * lin.gradient[k];
        }
    return forces;
  }



  const dealii::AffineConstraints<double> &
  FiniteSliding::get_constraints() const
  {
    return constraints;
  }
} // namespace dealvem
