// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_finite_sliding_h
#define dealvem_contact_finite_sliding_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/contact_detection.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/elasticity/finite_strain_solver.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/mesh/polygonal_mesh.h>

#include <functional>
#include <memory>
#include <set>
#include <vector>

namespace dealvem
{
  class FiniteStrainContact;
  template <int dim>
  class VEMDoFHandler;
  template <int dim>
  class FiniteStrainAssembler;

  /**
   * Contact at finite strain with finite sliding: node insertion made
   * again in the current configuration at every load step.
   *
   * Node-to-node contact after node insertion is exact while the partners
   * stay opposite each other. When the bodies slide by more than a small
   * part of an edge, the pairs of the reference configuration tear apart.
   * This class keeps the <em>original</em> mesh $M_0$ (without inserted
   * nodes) and, before every load step $n$:
   *
   * 1. <b>Pairs in the current configuration.</b> The vertices of $M_0$ are
   *    moved to their current positions $x = X + u(X)$ (a copy $C$; in the
   *    first pass of a step, $u$ is the extrapolation in time of the last
   *    two steps, where the step is expected to end: per piece of the
   *    bodies its rigid motion continued as a turn about its fixed point,
   *    the rest linearly (extrapolate()); or the last step's state
   *    $u_{n-1}$ when there is no such extrapolation or
   *    Parameters::extrapolate is false),
   *    and NodeInsertion::insert() pairs the interface nodes of $C$ by
   *    projection, splitting the edges of $C$ where a partner lands. No
   *    gap is closed and no vertex moved (Parameters::insertion has
   *    Settings::close_discretisation_gaps = false and a merge fraction of
   *    $10^{-9}$): every gap the insertion sees is real, and a partner that
   *    lands closer than $10^{-9}$ edge lengths to a vertex, or closer than
   *    $10^{-3}$ of an edge (the shortest sub-edge the insertion makes), is
   *    paired with it. Before that, a vertex inside a straight run of one
   *    side (two collinear edges of $M_0$) that faces a vertex of the other
   *    side within 0.05 of the local edge length along the sides (0.25 once
   *    it did so in the step) is put, in $C$ only, on the normal of the
   *    other side through that vertex, so that the two are paired: no
   *    sub-edge shorter than 0.05 of an edge is made there (see step 2).
   * 2. <b>Back to the reference configuration.</b> A vertex inserted into
   *    the original edge $(a, b)$ of $C$ at the chord parameter
   *    $s = (x - x_a)\cdot(x_b - x_a)/|x_b - x_a|^2$ is a vertex of the new
   *    reference mesh $M_n$ at $X = X_a + s\,(X_b - X_a)$: the material
   *    point the partner faces now. The current edge, though, is the
   *    curve $x(s) = X(s) + u(s)$ with the trace $u$ of the last mesh
   *    (piecewise linear with kinks at its nodes for $k = 1$, piecewise
   *    quadratic for $k = 2$), not the chord: when the partner is closer
   *    to the curve than half the edge, $s$ is moved to the point of the
   *    curve closest to it (Gauss-Newton on each piece; the chord's $s$ is
   *    kept if the nodes of the edge would change their order). Without
   *    this, partners that coincide in the pairing configuration would
   *    start the next pass apart by the sag of the curve, and the pairing
   *    of a stretched or curved side would stall there. A pair of two
   *    vertices of $M_0$ (merged) is made exact the same way: the vertex on
   *    a straight run (the slave's if both are) moves along its side, in
   *    the reference configuration, to the point of its side's current
   *    curve closest to its partner (within 0.9 of the way to the next
   *    node on either side; StepRecord::n_moved). The side is straight, so
   *    the body keeps its shape and only its mesh changes. Without this a
   *    vertex that faces a corner of the other side flips from pass to pass
   *    between the two edges at the corner (the solution of each pairing
   *    pushes it past the corner), or the merged pair keeps the offset at
   *    which it was merged. $M_n$ is $M_0$ with these vertices, so the
   *    nodes inserted at earlier steps that no longer face a partner are
   *    gone.
   *    <b>Curved sides.</b> Where a side follows a smooth curve, node
   *    insertion puts a new vertex on the circle through the neighbouring
   *    vertices (NodeInsertion, rule 2), and its material point is the
   *    point of the same arc in the reference configuration
   *    (NodeInsertion::edge_curvatures() of $M_0$; reference_point()), not
   *    of the chord: both sides then lie on their curves at every pair, and
   *    the sag of the polygons (up to $L^2\kappa/8$, as large as a fit's
   *    interference on a ring of 40 edges) is never taken for a gap. The
   *    displacement of a node off the sub-edge it splits is the sub-edge's
   *    trace plus the node's offset turned with the sub-edge, which
   *    carries rigid motions exactly. (Measured on a ring turned on its
   *    shaft by 90 degrees, k = 2: every pair active, the pressure within
   *    0.7 % of Lame's at every step, the friction torque 0.998
   *    $\mu N R$; with the chords, 22 % of the pairs carried the load and
   *    the pressures ranged from 0.3 to 2.3 times Lame's.)
   * 3. <b>The state on the new mesh.</b> The displacement $u_{n-1}$ is
   *    carried over node by node: the vertices off the interfaces and the
   *    cell moments of $M_0$ keep their values; a node on an interface
   *    (a vertex, moved or not, an inserted vertex, a sub-edge midpoint for
   *    $k = 2$) takes the value of the trace of $u_{n-1}$ at its material
   *    point (the trace is
   *    a polynomial of degree $k$ on each sub-edge of $M_{n-1}$, so this is
   *    exact for the nodes it adds, and the trace of a removed node is
   *    replaced by its interpolant). The multipliers start from the
   *    pressure and friction traction of the nearest old pair, times the
   *    new tributary weight.
   * 4. <b>The step.</b> A FiniteStrainContact is built on the new pairs
   *    with the configuration where they were made as its base
   *    (FiniteStrainContact::Options::base: normals and turn angles) and
   *    the configuration where the step started as the origin of the slip
   *    (Options::slip_origin). FiniteStrainSolver solves the step with its
   *    semismooth Newton method (frictionless or Coulomb friction).
   * 5. <b>Pairs at the end of the step.</b> Within the step the pairs are
   *    fixed, so partners that slide apart by $\delta$ transmit their
   *    force between points $\delta$ apart: a couple of the order of
   *    $\lambda\delta$, which the turning normal of the consistent
   *    linearization spreads over the neighbouring nodes. The pairing is
   *    therefore made again at the converged state and the step solved
   *    again from it (steps 1--4 with the new state as the pairing
   *    configuration; the slip is still measured from the start of the
   *    step), until the partners of every active pair coincide at
   *    convergence: the largest tangential distance of partners over the
   *    length of the slave sub-edges at the pair (the chord over which its
   *    normal turns) is below Parameters::pairing_tolerance
   *    (StepRecord::pairing_offset, StepRecord::n_passes; an open pair
   *    counts with what that distance grew in the pass beyond its gap: a
   *    pairing that lost the contact, every pair open and the bodies
   *    overlapping where no pair looks, is made again; an interface whose
   *    parts no longer face each other, a body slid off its partner, has
   *    no pairs: it is open, and closes again where they meet). The state each
   *    pass starts from is the last pass's, so the later passes take one
   *    or two Newton updates. The passes are a fixed-point iteration on
   *    the positions of the interface vertices where the pairs are made;
   *    it is accelerated by Anderson's method (the last five passes):
   *    where sticking pairs drag their partners along, plain repetition
   *    gains only a factor 0.5-0.9 per pass, and where a vertex faces a
   *    corner of the other side it flips. (Measured on the ironing die of
   *    examples/step-11: 10.5 passes per step without friction, 6.8 with,
   *    against 12.7 and 7.8 with a secant factor per vertex.)
   *
   * <h3>Frictional history</h3>
   * Coulomb friction is enforced by Lagrange multipliers in its incremental
   * form: a pair sticks ($s = 0$ over the step) or slips with the force
   * $\mu\lambda_n$. The history of that law is the position where the step
   * starts, and the pairs are made at that position: the history of a
   * pair moves with its material point by construction. The only state
   * that has to move between the meshes is the multipliers, which serve
   * as Newton's first iterate.
   *
   * 6. <b>Cutbacks.</b> A step whose Newton solve or pairing passes fail
   *    is solved again from its start as two half steps, each cut again if
   *    it fails, down to $2^{-\text{max\_cutbacks}}$ of the step
   *    (Parameters::max_cutbacks, StepRecord::n_substeps). (examples/step-11
   *    slides the ironing die by 1, eight slab elements, in one step: the
   *    first Newton solve inverts cells, the halves of 0.25, 0.25 and 0.5
   *    converge, and the die ends with the force of 40 steps to 1e-4.)
   *
   * Every pair counts its slip from the start of the step, a contact that
   * begins within the step too (its slave point off the master side at the
   * start, FiniteStrainContact::is_new_contact(),
   * StepRecord::n_new_contacts): backward Euler, first order in the step.
   *
   * <h3>A converged step does not depend on its predictor</h3>
   * Where the passes of a step start (the extrapolation, or the start of
   * the step) changes how many passes it takes, not where it ends: every
   * decision the passes hold within a step is checked against the converged
   * state. A merge of two vertices held by the step's hysteresis is
   * released when the converged state has them farther apart than node
   * insertion merges, and the step goes on (a merge the insertion makes
   * again is then held to the end of the step); vertices keep their
   * partners from pass to pass only once the passes pair near the step's
   * end (the previous pass's offsets within $10^{-2}$ of the sub-edges); a
   * detected pair of bodies keeps the master side of its first converged
   * step. tests/contact/finite_sliding_detection turns a wheel along a race
   * with $\mu = 0.3$ with and without the predictor: forces and moments
   * agree to 4.4e-5 (the nodes of open pairs are placed only to within
   * their gaps); they were 1.7 % apart, and 11 % with a better predictor,
   * when a new contact counted its slip from the step's first pass and
   * held merges stayed to the end of the step.
   *
   * <h3>Interfaces found in the current configuration</h3>
   * With Parameters::detection ('Contact/Pairs = auto') the free boundary
   * of the bodies is a candidate everywhere: the first pass of each step
   * runs ContactDetection on $M_0$ at the pairing positions (without
   * splitting edges), each detected side grows to the corners of its face
   * (the side a user would name), and the later passes keep those
   * interfaces unless the converged state of a pass shows an edge facing
   * another body, within half the detection distance, that no interface of
   * the pass covered (StepRecord::n_uncovered): then the next pass detects
   * again. The detected interfaces of a pair of bodies are reported
   * together (get_reported_interfaces(), reported_sign()).
   *
   * <h3>Limits</h3>
   * - Pairs are made between Newton solves (step 5), not within one; the
   *   first pass of a step pairs where the step is expected to end (the
   *   extrapolation of the last two steps); a step that slides too far for
   *   that is cut back (step 6).
   * - The stabilization of each pass is frozen at the state the pass starts
   *   from (FiniteStrainSolver), the end of the last pass.
   * - For $k = 2$ the partners are found on the chords of the current
   *   edges, then moved onto the curves (step 2); the midpoints of two
   *   paired sub-edges that curve differently are apart by the difference
   *   of the two parametrizations, $O(h^3\kappa)$, which
   *   StepRecord::pairing_offset does not count (vertex pairs only).
   * - Tied contact (Normal::tied) makes its pairs once, in the reference
   *   configuration, and keeps them: it does not slide.
   * - The passes can still cycle where a discrete state changes from one
   *   pass to the next and the sides give no straight run to move a vertex
   *   along (two polygons facing each other near their corners); the
   *   smallest sub-step then throws with the offset of every pass.
   * - Coulomb friction in its incremental form is first-order accurate in
   *   the step. On the ironing die the friction force is the same within
   *   2.5 % from 10 to 80 steps per unit slide, and the energy balance
   *   closes to 3 % (examples/step-11); its remainder, the error of
   *   carrying the state from mesh to mesh, falls with the mesh, not with
   *   the step.
   * - Where several vertices are moved to face corners of the other side
   *   at once (the ironing of step-11 pressed to 0.3), steps converge only
   *   after cutbacks.
   */
  class FiniteSliding
  {
  public:
    /// One contact interface: the boundary ids of its two sides and its
    /// friction coefficient.
    struct InterfaceData
    {
      /// The boundary id of the master side.
      dealii::types::boundary_id master_id = 0;
      /// The boundary id of the slave side.
      dealii::types::boundary_id slave_id = 0;
      /// Coulomb friction coefficient (0: frictionless).
      double friction_coefficient = 0;
    };

    /// The settings.
    struct Parameters
    {
      /// The order k of the virtual elements (1 or 2).
      unsigned int degree = 1;
      /// Unilateral (frictionless or Coulomb) or tied.
      ContactSettings::Normal normal = ContactSettings::Normal::unilateral;
      /// The complementarity constant $c$ (FiniteStrainContact), a
      /// stiffness per length; 0: $E_{min}/h_{min}$, the smallest
      /// characteristic stiffness of the laws over the smallest cell
      /// diameter of the original mesh.
      double complementarity_constant = 0;
      /// The stabilization rule of the virtual elements. Node insertion
      /// splits edges wherever a partner lands, also within a small
      /// fraction of an edge of an existing vertex (a slave vertex passing a
      /// master vertex does so in every sliding step). The trace rule
      /// stabilizes the relative motion of the two nodes of such a short
      /// sub-edge like any other motion, so a contact force on one of them
      /// folds the trace there (measured: a ring pressed by a plate, a
      /// sub-edge of 6e-4 of its edge stretched to 2.5 times its length, and
      /// the pairing stalled at 3e-3). The boundary rule stiffens it by the
      /// ratio of the lengths, as the material would.
      Stabilization stabilization = Stabilization::boundary;
      /// Make the pairs again at every step (finite sliding); false keeps
      /// the pairs of the reference configuration (small sliding).
      bool reinsert = true;
      /// The rules of node insertion (see the class documentation for the
      /// defaults, which differ from NodeInsertion's).
      NodeInsertion::Settings insertion = default_insertion();
      /// Newton's controls; scale_prescribed_motion is set to false (the
      /// constraints function gives the motion at the time of the step).
      FiniteStrainSolver<2>::Parameters newton;
      /// The pairs of a step are made again at its converged state until
      /// the largest tangential distance of the partners of an active pair,
      /// over the length of the slave sub-edges at the pair, is below this.
      /// (Newton's own tolerances leave the nodes uncertain by about 1e-9
      /// of that length on the meshes of the benchmark, so much less is
      /// not reachable.)
      double pairing_tolerance = 1e-8;
      /// The first pass of a step pairs the nodes where the last two
      /// converged steps predict its end (each connected piece of the
      /// bodies continues its rigid motion, a turn about its fixed point,
      /// and the rest linearly in time); false: where the step starts. The
      /// converged answer does not depend on it, to the pairing tolerance
      /// (tests/contact/finite_sliding_detection and
      /// finite_sliding_indentation assert it with friction and new
      /// contacts); the number of passes does.
      bool extrapolate = true;
      /// At most this many passes (pairing and Newton solve) per step; a
      /// step that does not meet the tolerance then throws, naming the
      /// offset.
      unsigned int max_pairing_passes = 12;
      /// A step whose Newton solve or pairing passes fail is solved again
      /// from its start as two half steps (the constraints and the loads at
      /// the middle time), each of them cut again if it fails, down to
      /// $2^{-\text{max\_cutbacks}}$ of the step; then it throws, naming
      /// the sub-step and the failure. 0: throw at once.
      unsigned int max_cutbacks = 4;

      /// NodeInsertion::Settings without gap closing and without merges
      /// beyond $10^{-9}$ edge lengths.
      static NodeInsertion::Settings
      default_insertion();

      /// Interfaces found in the current configuration ('Contact/Pairs =
      /// auto'), besides those given to the constructor.
      struct Detection
      {
        /// Detect the interfaces at every pairing pass.
        bool enabled = false;
        /// The boundary ids of the edges that may come into contact (the
        /// free boundary of the bodies: no boundary condition, no given
        /// interface).
        std::set<dealii::types::boundary_id> candidate_ids;
        /// The rule of ContactDetection (its rule 2, the split of an edge
        /// that faces two bodies, is not applied: an edge faces the body it
        /// overlaps most).
        ContactDetection::Settings settings;
        /// The Coulomb coefficient between two bodies (material ids);
        /// empty: frictionless.
        std::function<double(unsigned int, unsigned int)> friction;
      };

      /// See Detection.
      Detection detection;
    };

    /// One interface as the results report it (StepRecord::normal_force,
    /// reported_interface()): an interface given to the constructor, or a
    /// pair of bodies whose detected interfaces are summed.
    struct ReportedInterface
    {
      /// A pair of bodies found by the detection (else a given interface).
      bool detected = false;
      /// The boundary id of the master side of a given interface.
      dealii::types::boundary_id master_id = 0;
      /// The boundary id of its slave side.
      dealii::types::boundary_id slave_id = 0;
      /// The body (material id) with the lower index of a detected one.
      unsigned int body_a = 0;
      /// The other body; the reported forces act on it.
      unsigned int body_b = 0;
    };

    /// The Dirichlet constraints at the time @p time on @p dof_handler
    /// (the values of that time, not scaled): fill @p constraints and close
    /// them. Called for every step, on the mesh of the step.
    using ConstraintsFunction = std::function<
      void(const VEMDoFHandler<2> &dof_handler, const double time, dealii::AffineConstraints<double> &constraints)>;

    /// Add the loads (body force, tractions) to a new assembler; the
    /// functions given to it must outlive this object.
    using LoadsFunction = std::function<void(FiniteStrainAssembler<2> &assembler)>;

    /// What a load step did.
    struct StepRecord
    {
      /// The step number.
      unsigned int step = 0;
      /// The time of the step.
      double time = 0;
      /// The load factor of the forces at that time.
      double load_factor = 0;
      /// Newton's record of each pass of the step.
      std::vector<FiniteStrainSolver<2>::StepRecord> newton;
      /// Number of passes (pairing and Newton solve) of the step.
      unsigned int n_passes = 0;
      /// After the last pass: the largest tangential distance of the
      /// partners of an active vertex pair over the length of the slave
      /// sub-edges at the pair; for an open pair, what that distance grew
      /// in the pass beyond its gap (partners that slid apart by more than
      /// their gap may no longer see the other side where it is).
      double pairing_offset = 0;
      /// Active pairs of two vertices of the original mesh in the last pass
      /// (merged by the insertion: closer than the merge fraction of
      /// Parameters::insertion), not counted in pairing_offset.
      unsigned int n_merged = 0;
      /// Their largest tangential offset over the slave sub-edges at the
      /// pair.
      double merged_offset = 0;
      /// The pairing offset after each pass (the fixed-point history).
      std::vector<double> pairing_offsets;
      /// Vertices inserted into $M_0$ for the last pass of the step.
      unsigned int n_inserted = 0;
      /// Vertices of $M_0$ on a straight side moved along it to face a
      /// vertex of the other side in the last pass (see the class
      /// documentation, step 2).
      unsigned int n_moved = 0;
      /// Node pairs of the last pass.
      unsigned int n_pairs = 0;
      /// DoFs of the step's mesh.
      unsigned int n_dofs = 0;
      /// Wall time of pairing, new mesh, DoFs, transfer and the setup of
      /// the solver (seconds, all passes).
      double setup_time = 0;
      /// Wall time of the Newton solves (seconds, all passes).
      double solve_time = 0;
      /// The normal part of the contact force on the slave side of each
      /// reported interface (on ReportedInterface::body_b for a detected
      /// pair of bodies; current configuration, per unit thickness).
      std::vector<dealii::Tensor<1, 2>> normal_force;
      /// The friction part of that force.
      std::vector<dealii::Tensor<1, 2>> friction_force;
      /// Number of active pairs at convergence.
      unsigned int n_active = 0;
      /// Number of slipping pairs at convergence.
      unsigned int n_slipping = 0;
      /// The largest |slip| of the step over the shortest slave sub-edge
      /// at its pair (current lengths).
      double max_slip = 0;
      /// The work of the friction forces over the step, $\sum_i
      /// |\lambda_{t,i}\, s_i|$ with the tangential multiplier (a force)
      /// and the slip $s_i$ of the step at each pair (0 without friction):
      /// the energy the step dissipates.
      double dissipation = 0;
      /// The sub-steps the step was solved in (Parameters::max_cutbacks):
      /// 1 unless it was cut back. The record holds the state of the last
      /// one, the dissipation summed over them, and the passes, Newton
      /// records, pairing offsets and times of every attempt (the failed
      /// ones too).
      unsigned int n_substeps = 1;
      /// Active pairs whose contact began within the step
      /// (FiniteStrainContact::is_new_contact(); their slip counts from the
      /// start of the step, as every pair's).
      unsigned int n_new_contacts = 0;
      /// Active pairs that were in contact at the start of the step and
      /// stick (Coulomb friction; 0 in steady sliding).
      unsigned int n_sticking_in_contact = 0;
      /// With Parameters::detection: interfaces detected in the last pass.
      unsigned int n_detected = 0;
      /// With Parameters::detection: candidate edges of $M_0$ that face
      /// another body at the converged state of the last pass (within half
      /// the detection distance) but lay on no interface of the pass. The
      /// pass is then made again (as for a pairing offset above the
      /// tolerance): a contact that begins within a pass is never left
      /// without pairs.
      unsigned int n_uncovered = 0;
    };

    /**
     * Constructor: the original mesh @p mesh (copied; every body, with the
     * boundary ids of the interfaces and no inserted nodes), the laws by
     * material id, the interfaces, and the settings. Throws if there is no
     * interface, the degree is not 1 or 2, a friction coefficient is
     * negative or given with tied contact, or a setting is out of range.
     */
    FiniteSliding(const PolygonalMesh<2>           &mesh,
                  const MaterialLibrary<2>         &laws,
                  const std::vector<InterfaceData> &interfaces,
                  const Parameters                 &parameters);

    ~FiniteSliding();

    /// The Dirichlet constraints (required before the first step).
    void
    set_constraints_function(const ConstraintsFunction &f);

    /// The loads and, optionally, the load factor of the forces as a
    /// function of time (default: the time itself).
    void
    set_loads(const LoadsFunction &f, const std::function<double(double)> &load_factor = {});

    /// Solve the step @p step at the time @p time from the last converged
    /// state. Where Newton or the pairing passes fail, the step is cut
    /// back into halves (Parameters::max_cutbacks; StepRecord::n_substeps);
    /// if the smallest sub-step fails too, throws (FiniteStrainSolver's
    /// message or the pairing offsets, with the step and the sub-step), and
    /// the state stays at the last converged (sub-)step, on its mesh.
    void
    solve_step(const unsigned int step, const double time);

    /// Steps 1..n at the times $t_0 + (t_1 - t_0)\,i/n$.
    void
    run(const unsigned int n_steps, const double t0 = 0, const double t1 = 1);

    /// The mesh of the last step (reference coordinates, with its inserted
    /// vertices).
    const PolygonalMesh<2> &
    get_mesh() const;

    /// The original mesh $M_0$.
    const PolygonalMesh<2> &
    get_original_mesh() const;

    /// The DoF handler of the last step's mesh.
    const VEMDoFHandler<2> &
    get_dof_handler() const;

    /// The displacement of the last converged step on get_dof_handler().
    const dealii::Vector<double> &
    get_solution() const;

    /// Its multipliers (FiniteStrainContact's constraints).
    const dealii::Vector<double> &
    get_multipliers() const;

    /// The contact constraints of the last step (its pairs, normals,
    /// weights).
    const FiniteStrainContact &
    get_contact() const;

    /// The interfaces of the last pairing (pairs in the current
    /// configuration of the start of the last step).
    const std::vector<NodeInsertion::Interface> &
    get_interfaces() const;

    /// The interfaces the results report (StepRecord::normal_force and
    /// friction_force have one entry each): those given to the
    /// constructor, then, with Parameters::detection, every pair of bodies
    /// that have candidate edges.
    const std::vector<ReportedInterface> &
    get_reported_interfaces() const;

    /// The reported interface of a pair of the last step
    /// (ContactNodePair::interface of get_contact()'s pairs indexes the
    /// interfaces of the last pass, get_interfaces()).
    unsigned int
    reported_interface(const unsigned int pair_interface) const;

    /// +1 where the slave side of the interface @p pair_interface of the
    /// last pass is the side the results report the force on (the slave of
    /// a given interface; the body with the higher material id of a
    /// detected one, ReportedInterface::body_b), else -1: the forces on a
    /// detected pair of bodies keep their sign when the detection makes
    /// the other side the master.
    double
    reported_sign(const unsigned int pair_interface) const;

    /// One record per converged step.
    const std::vector<StepRecord> &
    get_history() const;

    /// The energy stored in the bodies at the last converged step
    /// (FiniteStrainAssembler::strain_energy() on the step's mesh; the
    /// laws must be hyperelastic). With the work of the loads and the
    /// dissipation of the steps (StepRecord::dissipation) this gives the
    /// energy balance of a run.
    double
    strain_energy() const;

    /// The nodal forces of the last converged step, each with n_dofs()
    /// entries of get_dof_handler() (per unit thickness, unconstrained).
    struct NodalForces
    {
      /// The internal force $f_{int}(u)$ of the bodies.
      dealii::Vector<double> internal;
      /// The applied loads at the step's load factor $\lambda$:
      /// $\lambda(f_{ext} + f_p(u))$, with the follower pressures $f_p$ at
      /// the converged state.
      dealii::Vector<double> external;
      /// The contact forces $-\sum_j \lambda_j\,\partial g_j/\partial u$
      /// of the multipliers $\lambda_j$ (get_multipliers()): the force each
      /// node receives from its pairs, normal and friction, with the terms of
      /// the turning normals on the neighbours of a pair.
      dealii::Vector<double> contact;
    };

    /**
     * The nodal forces of the last converged step: at every free DoF
     * external + contact - internal vanishes to Newton's tolerance; at a
     * constrained DoF it is minus the reaction of the support there (see
     * SupportReactions). Throws if no step has converged (or the last one
     * failed). The loads are evaluated at the time their functions were
     * last given; set it to the time of the step before calling.
     */
    NodalForces
    nodal_forces() const;

    /// The displacement constraints of the last step on get_dof_handler()
    /// (those the constraints function gave at its time).
    const dealii::AffineConstraints<double> &
    get_constraints() const;

  private:
    /// The state of the runs and the steps of the algorithm
    /// (source/contact/finite_sliding_impl.h).
    class Impl;
    /// The state (one object per FiniteSliding).
    std::unique_ptr<Impl> impl;
  };
} // namespace dealvem

#endif
