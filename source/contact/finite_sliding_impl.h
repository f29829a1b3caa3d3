// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_source_contact_finite_sliding_impl_h
#define dealvem_source_contact_finite_sliding_impl_h

// The state of FiniteSliding and the steps of its algorithm, shared by the
// files source/contact/finite_sliding*.cc (not installed).

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
#include <array>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace dealvem
{
  namespace internal
  {
    namespace finite_sliding
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
    inline Chain
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

    inline TracePoint
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
      // the trace on the edge: the Lagrange basis on its nodes (first
      // vertex, the edge's node when k = 2, second vertex; FiniteSliding
      // takes at most one node inside an edge, which sits at its middle, so
      // the direction of the mesh's edge does not matter)
      const VEMElementData &layout = dofs.get_element_data();
      std::vector<double>   phi, dphi;
      layout.edge_shape_values(t, phi);
      layout.edge_shape_derivatives(t, dphi);
      for (unsigned int comp = 0; comp < 2; ++comp)
        {
          const double u0 = u[VEMDoFHandler<2>::node_dof(dofs.vertex_node(chain.vertices[i]), comp)];
          const double u1 = u[VEMDoFHandler<2>::node_dof(dofs.vertex_node(chain.vertices[i + 1]), comp)];
          p.value[comp]      = phi.front() * u0 + phi.back() * u1;
          p.derivative[comp] = dphi.front() * u0 + dphi.back() * u1;
          if (layout.nodes_per_edge() == 1)
            {
              const double um = u[VEMDoFHandler<2>::node_dof(dofs.edge_node(chain.edges[i], 0), comp)];
              p.value[comp] += phi[1] * um;
              p.derivative[comp] += dphi[1] * um;
            }
        }
      return p;
    }

    inline std::uint64_t
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

    inline dealii::Tensor<1, 2>
    turn_left(const dealii::Tensor<1, 2> &v)
    {
      dealii::Tensor<1, 2> r;
      r[0] = -v[1];
      r[1] = v[0];
      return r;
    }
    } // namespace finite_sliding
  } // namespace internal



  class FiniteSliding::Impl
  {
  public:
    // The arguments of FiniteSliding's constructor (see there).
    Impl(const PolygonalMesh<2>           &mesh,
         const MaterialLibrary<2>         &laws,
         const std::vector<InterfaceData> &interfaces,
         const Parameters                 &parameters);

    ~Impl();

    // The operations of the public interface (documented in
    // finite_sliding.h).
    void
    set_constraints_function(const ConstraintsFunction &f);
    void
    set_loads(const LoadsFunction &f, const std::function<double(double)> &load_factor);
    void
    solve_step(const unsigned int step, const double time);
    void
    run(const unsigned int n_steps, const double t0, const double t1);
    const PolygonalMesh<2> &
    get_mesh() const;
    const VEMDoFHandler<2> &
    get_dof_handler() const;
    const dealii::Vector<double> &
    get_solution() const;
    const dealii::Vector<double> &
    get_multipliers() const;
    const FiniteStrainContact &
    get_contact() const;
    double
    strain_energy() const;
    NodalForces
    nodal_forces() const;
    const dealii::AffineConstraints<double> &
    get_constraints() const;
    double
    reported_sign(const unsigned int pair_interface) const;

    /// A mesh with its DoF handler (the handler refers to the mesh).
    struct Discretization
    {
      std::unique_ptr<PolygonalMesh<2>> mesh;
      std::unique_ptr<VEMDoFHandler<2>> dof_handler;
      ~Discretization();
    };

    /// Pair in the configuration @p u_pair (on the current mesh), make the
    /// new mesh and DoF handler, transfer the states, build the contact
    /// and the solver. @p first_pass: the step starts from the last
    /// converged state (else from @p u_pair at the step's own load factor).
    void
    prepare_pass(const double time, const double load_factor, const unsigned int step, const bool first_pass,
                 StepRecord &record);

    /// The state expected at the step's end from the last two converged
    /// states @p u1 and @p u0 (on @p disc) and the ratio @p s of the new
    /// step's length to the last one's: per piece of the mesh, its rigid
    /// motion (rotation about its centroid and translation) continued as a
    /// rigid motion, the rest linearly.
    dealii::Vector<double>
    extrapolate(const Discretization &disc, const dealii::Vector<double> &u1, const dealii::Vector<double> &u0,
                const double s) const;

    /// Before the first Newton solve of a step: throw, naming the motion,
    /// where a rigid-body motion of a piece of the bodies is held neither
    /// by the displacement constraints nor by a contact pair closed where
    /// the step starts (a multiplier from the last step, or no gap), as
    /// RigidBodySupport checks at small strain. Cutting the step back does
    /// not help, so the error ends solve_step() at once.
    void
    check_support(const unsigned int step, const double time) const;

    /// The values of the states @p u (on @p from) at the nodes of @p to.
    dealii::Vector<double>
    transfer(const Discretization &from, const dealii::Vector<double> &u, const Discretization &to) const;

    /// The tangential offsets and the slip of the pairs at the solution
    /// (StepRecord::pairing_offset, max_slip) and the forces.
    void
    evaluate(StepRecord &record) const;

    PolygonalMesh<2>           original;
    MaterialLibrary<2>         laws;
    std::vector<InterfaceData> interface_data;
    std::vector<ReportedInterface> reported;

    /// An interface of a pass: its ids, its friction and its reported
    /// interface.
    struct PassInterface
    {
      dealii::types::boundary_id master_id = 0, slave_id = 0;
      double                     friction_coefficient = 0;
      unsigned int               reported             = 0;
      /// The body (material id) of the master side of a detected one.
      unsigned int master_body = 0;
      /// The body of its slave side.
      unsigned int slave_body = 0;
    };
    /// The interfaces of the current pass (those of `interfaces`).
    std::vector<PassInterface> pass_interfaces;
    /// The master body of each pair of bodies (lower, higher material id)
    /// the detection has found in a converged step: the pair keeps it in
    /// every later pass and step. (ContactDetection takes the coarser of
    /// the two facing parts, which on sides of about the same edge length
    /// changes with the configuration: a wheel in a race of the same edge
    /// length swapped its sides from step to step, and the first pass of a
    /// step, paired where the step was predicted to end, decided the
    /// discretization the step converged on: two answers 1.7 % apart.)
    std::map<std::pair<unsigned int, unsigned int>, unsigned int> detected_master;
    /// With Parameters::detection: the body each edge of $M_0$ faced on an
    /// interface of the current pass (numbers::invalid_unsigned_int: none).
    std::vector<unsigned int> pass_partner;
    /// Whether the detection itself put each edge of $M_0$ on its
    /// interface in the current pass (else a side grew over it).
    std::vector<bool> pass_detected;
    /// With Parameters::detection: the interfaces of the first pass of the
    /// current step, the ids they give to the edges of $M_0$ and their
    /// sides, which the later passes keep (the decisions of a step only
    /// change where a pass leaves an edge uncovered: StepRecord::
    /// n_uncovered; then the next pass detects again, redetect).
    std::vector<PassInterface>              step_pass;
    std::vector<dealii::types::boundary_id> step_labels;
    std::vector<bool>                       step_detected;
    std::vector<std::pair<std::vector<unsigned int>, std::vector<unsigned int>>> step_sides;
    bool                                    redetect = false;
    /// The sides of the given interfaces (original vertices).
    std::vector<std::pair<std::vector<unsigned int>, std::vector<unsigned int>>> given_sides;
    /// The interfaces of a pass with the original vertices at @p x: the
    /// given ones, then those ContactDetection finds among the candidate
    /// edges (Parameters::detection); @p edge_ids receives the boundary id
    /// of each edge of $M_0$ there, @p sides the vertices of each side.
    std::vector<PassInterface>
    pass_interfaces_at(const std::vector<dealii::Point<2>> &x,
                       std::vector<dealii::types::boundary_id> &edge_ids_there,
                       std::vector<bool>                       &detected_there,
                       std::vector<std::pair<std::vector<unsigned int>, std::vector<unsigned int>>> &sides) const;
    /// ContactDetection on @p there (a copy of $M_0$ with moved vertices)
    /// among the candidate edges, without splits, at @p distance_factor
    /// times the detection distance.
    ContactDetection::Result
    detect_candidates(PolygonalMesh<2> &there, const double distance_factor) const;
    /// With Parameters::detection: the candidate edges of $M_0$ that face
    /// another body at the converged state of the pass (within half the
    /// detection distance) but lay on no interface of the pass.
    unsigned int
    uncovered_edges() const;
    Parameters                 parameters;
    ConstraintsFunction        constraints_function;
    LoadsFunction              loads_function;
    std::function<double(double)> load_factor_function;

    /// The original edges of the interfaces: (a, b, cell) of $M_0$.
    std::vector<std::array<unsigned int, 3>> interface_edges;
    /// The neighbours of each vertex of an interface along its side (one
    /// or two vertices of $M_0$).
    std::map<unsigned int, std::vector<unsigned int>> side_neighbours;
    /// The boundary id of each original interface edge (by its vertices).
    std::map<std::uint64_t, dealii::types::boundary_id> edge_ids;
    /// The signed curvature (convex > 0) of the arc each original interface
    /// edge is taken to follow in the reference configuration
    /// (NodeInsertion::edge_curvatures(): 0 on straight parts and at
    /// corners), by its vertices.
    std::map<std::uint64_t, double> arc_kappa;

    /// The point of the reference curve of the original interface edge
    /// (@p a, @p b) (its arc, or its chord where it is straight) whose foot
    /// on the chord has the chord parameter @p s; (a, b) in the order of
    /// the edge's vertices (interface_edges).
    dealii::Point<2>
    reference_point(const unsigned int a, const unsigned int b, const double s) const;
    /// The vertices of $M_0$ inside a straight run of one interface side
    /// (two collinear edges of one boundary id): their material points may
    /// move along the side (see prepare_pass()).
    std::set<unsigned int> movable;
    /// The original vertices of the master and the slave side of each
    /// interface of the pass being made.
    std::vector<std::pair<std::vector<unsigned int>, std::vector<unsigned int>>> interface_sides;

    /// The neighbours of the vertex @p v along its side (with detection,
    /// those on a side of the pass, where there are any).
    std::vector<unsigned int>
    neighbours_on_sides(const unsigned int v) const;
    /// neighbours_on_sides() of every vertex of side_neighbours.
    std::map<unsigned int, std::vector<unsigned int>>
    neighbours_along_sides() const;
    /// Move each vertex of a straight side that faces a vertex of the other
    /// side within 0.05 of the local edge length along the sides onto the
    /// normal of the other side through that vertex, in the positions @p x
    /// where the pairs are made.
    void
    snap_close_vertices(std::vector<dealii::Point<2>> &x);
    /// The pairs (vertex, vertex of the other side) snap_close_vertices()
    /// made in a pass of the current step.
    std::set<std::pair<unsigned int, unsigned int>> step_snaps;

    /// The pairs of two original vertices (master, slave) merged in a pass
    /// of the current step (they stay merged, see prepare_pass()).
    std::set<std::pair<unsigned int, unsigned int>> step_merges;
    /// Merges of the step that a converged pass found held beyond the
    /// distance at which node insertion merges (loose_merges()): the later
    /// passes no longer hold them. One that node insertion merges again
    /// goes to step_reheld and is held to the end of the step.
    std::set<std::pair<unsigned int, unsigned int>> step_released, step_reheld;

    /// The held merges (step_merges, not in step_reheld) whose vertices are
    /// apart along the interface at the solution by more than 1e-3 of the
    /// two sub-edges at the pair (about twice the distance at which node
    /// insertion merges two vertices): held only by the step's hysteresis,
    /// not by the rule that made them.
    std::vector<std::pair<unsigned int, unsigned int>>
    loose_merges() const;

    /// The original vertices that had a partner in a pass of the current
    /// step (NodeInsertion::Settings::keep_facing of the later passes).
    std::set<unsigned int> step_paired;

    /// Whether the residual of the pairing passes grew in the current step
    /// (the vertices moved along their sides then take half updates, see
    /// relaxed_pairing_state()).
    bool step_damped = false;

    /// The discretization of the current pass and that of the start of the
    /// step (the last converged step's; null before the first step).
    std::unique_ptr<Discretization>           current, start;
    std::unique_ptr<FiniteStrainAssembler<2>> assembler;
    std::unique_ptr<FiniteStrainContact>      contact;
    std::unique_ptr<FiniteStrainSolver<2>>    solver;
    std::vector<NodeInsertion::Interface>     interfaces;
    dealii::AffineConstraints<double>         constraints;

    /// On the current discretization: the state of the last pass (the last
    /// converged step after a step).
    dealii::Vector<double> solution, multipliers;
    /// On the start discretization: the last two converged steps (the
    /// second for the extrapolation; empty before two steps).
    dealii::Vector<double> start_solution, start_previous_solution, start_multipliers;
    /// Whether the last solve_step() failed (the start of the step stays).
    bool last_failed = false;
    /// The configuration where the pairs of the current pass were made (on
    /// the current discretization).
    dealii::Vector<double> pairing_base;
    /// The acceleration of the pairing passes of a step (Anderson): the
    /// displacements of the interface vertices where the last passes made
    /// their pairs, and their changes to the converged states.
    std::vector<std::vector<double>> anderson_x, anderson_r;
    /// The vertices moved along their sides in the pass of that history.
    std::set<unsigned int> anderson_moved;
    /// With detection: the vertices on the sides of the interfaces of that
    /// history (the history starts again when they change).
    std::set<unsigned int> anderson_on_side;

    /// The configuration where the next pass of a step makes its pairs: the
    /// Anderson extrapolation of the last passes' pairing positions and
    /// converged states at the interface vertices (see the implementation).
    dealii::Vector<double>
    relaxed_pairing_state();
    /// relaxed_pairing_state(), the fit: the next pairing positions
    /// x_{k+1} of the interface vertices from their pairing positions @p x
    /// and residuals @p r of this pass (two entries per vertex of
    /// side_neighbours), with the Anderson history updated (and started
    /// again where the residual grew). @p length is the size of the
    /// problem, the scale of a negligible fit.
    std::vector<double>
    anderson_next(const std::vector<double> &x, const std::vector<double> &r, const double length);
    /// relaxed_pairing_state(), the result: the solution with the vertices
    /// at @p next, the other nodes of an interface edge moved by the
    /// correction of its end vertices interpolated along the edge; the
    /// vertices off @p on_side (with detection) take the plain update, those
    /// in @p moved the plain update (halved once the step was damped).
    dealii::Vector<double>
    corrected_pairing_state(const std::vector<double>    &x,
                            const std::vector<double>    &r,
                            const std::vector<double>    &next,
                            const std::set<unsigned int> &on_side,
                            const std::set<unsigned int> &moved) const;
    /// One attempt at the step from t_start to time, cut in halves where
    /// it fails (Parameters::max_cutbacks); adds its sub-steps to total.
    void
    solve_with_cutbacks(const unsigned int step,
                        const double       t_start,
                        const double       time,
                        const unsigned int depth,
                        StepRecord        &total);
    /// One increment to @p time from the last converged state (pairing
    /// passes and Newton solves); throws where it fails.
    void
    solve_increment(const unsigned int step, const double time, StepRecord &record);
    double                 last_time = 0, previous_time = 0;
    double                 last_load_factor = 0, previous_load_factor = 0;
    unsigned int           last_step = 0, previous_step = 0, n_converged = 0;
    std::vector<StepRecord> history;

    // The working state of one pass of prepare_pass(), handed from step to
    // step.
    struct Pass
    {
      // the arguments of prepare_pass()
      double       time        = 0;
      double       load_factor = 0;
      unsigned int step        = 0;
      bool         first_pass  = false;
      // step 0: the discretization and the state where the pairs are made,
      // and whether that is where the step is expected to end
      const Discretization  *pair_disc = nullptr;
      dealii::Vector<double> u_pair;
      bool                   predicted = false;
      // step 1: the pairing positions of the original vertices (after and
      // before the snaps and merges), the pairing mesh and the interfaces
      std::vector<dealii::Point<2>>         x_pair, x_true;
      std::unique_ptr<Discretization>       next;
      std::vector<NodeInsertion::Interface> new_interfaces;
      std::vector<PassInterface>            new_pass;
      std::vector<unsigned int>             new_partner;
      std::vector<bool>                     new_detected;
      // step 2: the vertices in the pairing and the reference configuration,
      // the trace where the pairs are made, and the nodes of each original
      // interface edge
      std::vector<dealii::Point<2>>                                    x_now, reference;
      std::vector<bool>                                                placed;
      std::map<unsigned int, std::vector<unsigned int>>                trace_neighbours;
      std::unique_ptr<internal::finite_sliding::TraceOnSides>          pair_trace;
      std::vector<std::tuple<unsigned int, unsigned int, internal::finite_sliding::Chain>> chains;
      // step 3: the states on the new mesh
      dealii::Vector<double> u_base, u_newton, u_origin, u_previous;
      bool                   with_previous = false;
      // step 4: the new contact and its multipliers
      std::unique_ptr<FiniteStrainContact> new_contact;
      dealii::Vector<double>               lambda;
    };
    // The steps of prepare_pass() (see there, finite_sliding_pass.cc).
    void
    choose_pairing_state(Pass &pass);
    void
    pair_in_configuration(Pass &pass, const dealii::Vector<double> &u);
    void
    pairing_positions(Pass &pass, const dealii::Vector<double> &u);
    void
    interfaces_of_pass(Pass &pass, std::vector<dealii::types::boundary_id> &ids_there);
    void
    hold_step_merges(std::vector<dealii::Point<2>> &x_pair);
    void
    make_pairing_mesh(Pass &pass, const std::vector<dealii::types::boundary_id> &ids_there);
    void
    insert_nodes(Pass &pass);
    void
    keep_step_decisions(Pass &pass, bool settled);
    void
    place_inserted_vertices(Pass &pass);
    void
    move_paired_vertices(Pass &pass);
    void
    make_pass_mesh(Pass &pass, StepRecord &record);
    void
    transfer_states(Pass &pass);
    void
    make_pass_contact(Pass &pass);
    void
    install_pass(Pass &pass, StepRecord &record);
  };
} // namespace dealvem

#endif
