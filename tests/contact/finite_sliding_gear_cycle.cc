// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// A spur gear pair turned through its mesh cycle in one finite-sliding
// run, against the quasi-static series of examples/step-12 (issue 41,
// item 4).
//
// The pair of tests/contact/gear_pair: pinion z1 = 20, gear z2 = 31,
// module 1, 20 degrees, standard centre distance, backlash allowance 0.05
// on each gear, and here a parabolic tip relief of 0.015 on both (twice
// the loaded deflection along the line of action, so that a tooth pair
// takes up and gives off its load on the relief rather than on the tip
// corner); steel (E = 210000, nu = 0.3, plane strain), k = 2, frictionless
// unilateral contact between the whole tooth outlines of three-tooth
// sectors. Pinion tooth k (-1, 0, 1) meshes with gear tooth -k, its contact
// point at s + k p_b on the line of action (s: tooth 0's, from the pitch
// point; p_b = 2.952 the base pitch; the path of contact runs from s_A =
// -2.451 to s_E = 2.298, single contact in [-0.654, 0.501]). The driving
// flanks of every tooth pair whose point comes within 0.3 of the path
// during the run are graded to 0.005 over the band of radii that point
// crosses (and 0.03 beyond).
//
// Finite sliding (FiniteSliding, Neo-Hooke with the same E and nu): the
// meshes are made once, at the first roll angle phi_0 (phi = s / r_b1),
// where the driving flanks touch unloaded on the line of action. Step 1
// turns the pinion's bore by the loaded rotation theta = 8e-4 about its
// centre (the gear's bore held): about 700 N mm/mm, a peak pressure of
// 1100 MPa in single contact. Each later step turns both bores rigidly
// about their centres (exact rotations), the pinion's by phi_i - phi_0 +
// theta, the gear's by -(phi_i - phi_0) z1 / z2; the pairs are made again
// in the current configuration at every step, so a tooth pair whose flanks
// come within the search distance is paired within the run, and one that
// opens lets its pairs go. (FiniteSliding cannot load a bore by a torque
// with its angle an unknown, so the transmitted torque is the result here,
// the loaded rotation the datum.)
//
// Quasi-static series (step-12's approach; ContactProblem, small strain,
// linear elastic with the same E and nu and finite sliding's boundary
// stabilization): at every roll angle phi_i the gears are meshed anew at
// that position with the same settings (the same meshes turned rigidly),
// the pinion's bore turned by theta, the gear's bore clamped, one contact
// solve with node insertion in the reference configuration.
//
// Compared at every roll angle: the torque on the pinion (the moment of
// the contact forces about its centre), and per tooth pair its share of
// that torque and the peak of the recovered contact pressure. Asserted:
// every step converges; the torque within 1 % (issue 41's figure); each
// pair's share within 0.01 (of the whole torque); the peak pressure within
// 1 % (issue 41's figure) on each zone that is resolved (a / h >= 8, a
// Hertz's half-width with
// the involutes' local radii for the pair's force, h the edge length of
// its closed zone, in both models) and clear of the ends of the path
// (where a tooth pair takes up or gives off its load, its zone is small
// and on the relief: those are listed, not compared); a resolved zone at
// every roll angle; no closed pair off the three tooth pairs; and the
// number of loaded tooth pairs changes in the run in both models.
//
// Default: s from -1.16 to -0.96, 3 roll angles: tooth pair 1 gives off
// its last tenth of the load on the pinion's relief and leaves contact
// (23k DoFs, 3 pairing passes and 19-27 Newton updates a step, 37 s of CPU
// in Release). Measured: the torque within 0.024 %, pair 1's share 0.0860
// against 0.0863 at s = -1.16 and nothing at -1.06 in either model; the
// peak pressure on pair 0 -0.63 %, +0.055 %, -0.48 % (a/h 18.7-21.4).
// With the flanks graded to 0.01 (15k DoFs, --h 0.01) the peaks differed
// by -0.87 %, +1.5 %, +0.91 % (a/h 9.5-10.9): the two insertions (current
// against reference configuration) place the nodes at the peak
// differently, by an amount that halves with the flank cells.
// With --pitch (ctest label "long"): one base pitch, s from -1.553 to
// 1.399 (the zone of single contact in the middle, tooth pair 1 leaving at
// the start and pair -1 entering at the end), 16 roll angles (0.197 mm, 4.7
// contact half-widths, a step; 54k DoFs, 3 pairing passes and 16-24
// Newton updates a step, one cut-back; 13.6 min of CPU in Release).
// Measured with the flanks graded to 0.01 (--pitch --h 0.01, 54k DoFs):
// pair 1 leaves between s = -1.16 and -0.96, pair -1 enters
// between 0.81 and 1.01 (both models); the torque within 0.047 %, the
// shares within 3.2e-4, the peak pressures of the 16 resolved zones within
// -1.0 to +1.3 % (the 1 % asserted now is for the default 0.005, which has
// not been run over the whole pitch: about twice the CPU).
// --angles N, --from S, --to S, --s-max S (from -S to S), --h H,
// --margin M, --relief C, --tolerance T and --theta T change the settings
// for other studies.
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/contact/contact_pressure.h>
#include <dealvem/contact/finite_sliding.h>
#include <dealvem/contact/finite_strain_contact.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/mesh/spur_gear.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "../finite_sliding_common.h"
#include "../tests.h"

using namespace dealvem;

namespace
{
  const double       pi = std::acos(-1.);
  const double       m = 1, E = 210e3, nu = 0.3, j = 0.05, alpha = 20 * pi / 180;
  const unsigned int z1 = 20, z2 = 31;
  const double       r1 = m * z1 / 2, r2 = m * z2 / 2, a = r1 + r2;
  const double       rb1 = r1 * std::cos(alpha), rb2 = r2 * std::cos(alpha);
  // the base pitch, and the ends of the path of contact on the line of
  // action from the pitch point: the gear's tip (A) and the pinion's (E)
  const double p_b = pi * m * std::cos(alpha);
  const double s_A = -(std::sqrt((r2 + m) * (r2 + m) - rb2 * rb2) - r2 * std::sin(alpha));
  const double s_E = std::sqrt((r1 + m) * (r1 + m) - rb1 * rb1) - r1 * std::sin(alpha);
  // how far (along the line of action) the loaded contact may reach past
  // the ends of the path: the flanks graded that far
  const double extension = 0.3 * m;

  // Pairs are made within 0.01 of the interface's size (about 0.1 mm, 2.5
  // contact half-widths): the flanks of the teeth that do not touch stay
  // unpaired. (With the default 0.25,
  // 2.6 mm here, the pairing passes of finite sliding's first step stalled
  // at an offset of 0.0387 of a sub-edge, the same in every pass and at
  // every cut-back; the pair that held it was not traced.)
  const double search_distance = 0.01;

  struct Settings
  {
    double       theta    = 8e-4; // the loaded rotation of the pinion's bore
    double       relief   = 0.015; // parabolic tip relief of both gears
    double       s_first  = -1.16; // the contact point of pinion tooth 0 runs from s_first ...
    double       s_last   = -0.96; // ... to s_last
    unsigned int n_angles = 3;     // roll angles (the steps after the first)
    double       flank_h  = 0.005; // cell size on the graded flanks
    double       margin   = 0.03; // the graded band reaches this far (radius) beyond the contact path
    // FiniteSliding's pairing tolerance: partners of the active pairs within
    // 1e-4 of the sub-edges at the pair, 4e-7 mm where the contact
    // half-width is 10 sub-edges (the figures compared are those of 1e-6 to
    // 2e-6, relative; it saves a pass a step)
    double       tolerance = 1e-4;
  };

  /// The tooth pairs: pinion tooth k (-1, 0, 1) meshes with gear tooth -k,
  /// its contact point at s + k p_b when tooth 0's is at s.
  const std::array<int, 3> teeth{{-1, 0, 1}};

  /// The gears at the pinion's roll angle phi: at phi = 0 the
  /// counter-clockwise flanks of pinion tooth 0 and gear tooth 0 touch at the
  /// pitch point (r1, 0).
  std::pair<SpurGear::Parameters, SpurGear::Parameters>
  gears(const Settings &st, const double phi)
  {
    SpurGear::Parameters p1, p2;
    p1.module = p2.module = m;
    p1.n_teeth            = z1;
    p2.n_teeth            = z2;
    p1.backlash = p2.backlash = j;
    p1.tip_relief = p2.tip_relief = st.relief;
    p1.relief_shape = p2.relief_shape = SpurGear::ReliefShape::parabolic;
    const double s            = m * pi / 2 - j;
    p1.rotation               = -s / (2 * r1) + phi;
    p2.center                 = dealii::Point<2>(a, 0);
    p2.rotation               = pi - s / (2 * r2) - phi * z1 / z2;
    p1.bore_radius            = 0.5 * r1;
    p2.bore_radius            = 0.6 * r2;
    return {p1, p2};
  }

  /// The two sectors at roll angle phi, each with boundary ids 0 (bore),
  /// 1 (teeth), 2 and 3 (sides) and material id 0. Every tooth pair whose
  /// contact point comes within the extension of the path of contact
  /// during the run is graded on its driving flanks over the band of radii
  /// that point crosses, and a margin.
  void
  make_meshes(const Settings &st, const double phi, PolygonalMesh<2> &pinion, PolygonalMesh<2> &gear)
  {
    const auto [p1, p2] = gears(st, phi);
    const SpurGear g1(p1), g2(p2);
    const auto radius = [](const double rb, const double along) { return std::hypot(rb, along); };
    using Zone  = PolygonalMeshGenerators::GearMeshSettings::FlankZone;
    using Flank = PolygonalMeshGenerators::GearMeshSettings::Flank;
    PolygonalMeshGenerators::GearMeshSettings m1;
    m1.first_tooth          = z1 - 1;
    m1.n_teeth              = 3;
    m1.n_global_refinements = 0;
    m1.flank_cell_size      = st.flank_h;
    auto m2                 = m1;
    m2.first_tooth          = z2 - 1;
    for (const int k : teeth)
      {
        const double first = std::max(st.s_first + k * p_b, s_A - extension),
                     last  = std::min(st.s_last + k * p_b, s_E + extension);
        if (first >= last)
          continue;
        const double from1 = radius(rb1, r1 * std::sin(alpha) + first) - st.margin * m,
                     to1   = radius(rb1, r1 * std::sin(alpha) + last) + st.margin * m;
        const double from2 = radius(rb2, r2 * std::sin(alpha) - last) - st.margin * m,
                     to2   = radius(rb2, r2 * std::sin(alpha) - first) + st.margin * m;
        // (a band that lies beyond a tip, where the contact point runs past
        // the end of the path, is not graded on that gear)
        if (std::max(from1, g1.form_radius()) < std::min(to1, g1.tip_radius()))
          m1.zones.push_back(Zone{k, std::max(from1, g1.form_radius()), std::min(to1, g1.tip_radius()),
                                  Flank::counter_clockwise});
        if (std::max(from2, g2.form_radius()) < std::min(to2, g2.tip_radius()))
          m2.zones.push_back(Zone{-k, std::max(from2, g2.form_radius()), std::min(to2, g2.tip_radius()),
                                  Flank::counter_clockwise});
      }
    PolygonalMeshGenerators::spur_gear(pinion, g1, m1);
    PolygonalMeshGenerators::spur_gear(gear, g2, m2);
  }

  /// What a model gives on one tooth pair at one roll angle.
  struct PairOutcome
  {
    double                        torque = 0, p_max = 0, normal_force = 0;
    std::vector<dealii::Point<2>> closed; // the closed pairs' positions
  };

  /// What a model gives at one roll angle, by tooth pair (teeth[]).
  struct Outcome
  {
    double                     phi = 0, torque = 0;
    unsigned int               n_dofs = 0;
    std::array<PairOutcome, 3> pair;
    // closed pairs on no tooth pair of teeth[]
    unsigned int n_elsewhere = 0;

    /// Adds a closed pair at x (current position) on pinion tooth k, with
    /// the normal force f, its moment about the pinion's centre and the
    /// recovered pressure p.
    void
    add(const int k, const dealii::Point<2> &x, const double f, const double moment, const double p)
    {
      torque += moment;
      if (std::abs(k) > 1)
        {
          ++n_elsewhere;
          return;
        }
      auto &q = pair[k + 1];
      q.torque += moment;
      q.normal_force += f;
      q.p_max = std::max(q.p_max, p);
      q.closed.push_back(x);
    }
  };

  /// The pinion tooth nearest to a point of its outline in the reference
  /// configuration at roll angle phi.
  int
  pinion_tooth(const dealii::Point<2> &x, const double phi)
  {
    const double angle = std::atan2(x[1], x[0]) - (-(m * pi / 2 - j) / (2 * r1) + phi);
    int          k     = static_cast<int>(std::lround(angle / (2 * pi / z1)));
    return ((k % int(z1)) + int(z1) + int(z1) / 2) % int(z1) - int(z1) / 2;
  }

  /// The edge length of a closed zone from its pairs' positions (k = 2:
  /// vertices and midpoints, two nodes per edge).
  double
  zone_edge(const std::vector<dealii::Point<2>> &x)
  {
    double extent = 0;
    for (const auto &p : x)
      for (const auto &q : x)
        extent = std::max(extent, p.distance(q));
    return x.size() > 1 ? 2 * extent / (x.size() - 1) : 0.;
  }

  /// The quasi-static solve at roll angle phi (small strain, step-12's
  /// approach).
  Outcome
  quasi_static(const Settings &st, const double phi)
  {
    PolygonalMesh<2> pinion, gear;
    make_meshes(st, phi, pinion, gear);
    ContactProblem problem(MPI_COMM_SELF);
    problem.add_body(pinion, ElasticMaterial(E, nu, ElasticMaterial::Model::plane_strain));
    problem.add_body(gear, ElasticMaterial(E, nu, ElasticMaterial::Model::plane_strain), 10);
    problem.add_contact_pair(1, 11);
    auto &bc = problem.boundary_conditions();
    bc.add_rotation_about_centre(0, dealii::Point<2>(0, 0),
                                 std::make_shared<dealii::Functions::ConstantFunction<2>>(st.theta), false,
                                 "pinion bore");
    bc.add_dirichlet(10, {{true, true}}, std::make_shared<dealii::Functions::ZeroFunction<2>>(2));
    auto &o              = problem.options();
    o.contact.normal     = ContactSettings::Normal::unilateral;
    o.contact.tangential = ContactSettings::Tangential::frictionless;
    o.insertion.search_distance = search_distance;
    // finite sliding's rule (FiniteSliding::Parameters::stabilization)
    o.stabilization = Stabilization::boundary;
    o.write_vtu = o.write_json = o.write_pictures = o.write_csv = false;
    o.base_name                                                 = "finite_sliding_gear_cycle";
    problem.run();
    const auto &r = problem.get_results();
    Outcome     out;
    out.phi    = phi;
    out.n_dofs = r.n_dofs;
    for (const auto &pr : r.pairs)
      if (pr.active)
        // the force on the pinion (the master side) is +lambda n
        out.add(pinion_tooth(pr.location, phi), pr.location, -pr.multiplier,
                SupportReactions::moment(pr.location, pr.multiplier * pr.normal, dealii::Point<2>(0, 0)),
                pr.pressure);
    return out;
  }

  /// The rigid rotation of X about c by the angle t, as a displacement.
  dealii::Tensor<1, 2>
  turned(const dealii::Point<2> &X, const dealii::Point<2> &c, const double t)
  {
    const double         x = X[0] - c[0], y = X[1] - c[1];
    dealii::Tensor<1, 2> u;
    u[0] = std::cos(t) * x - std::sin(t) * y - x;
    u[1] = std::sin(t) * x + std::cos(t) * y - y;
    return u;
  }

  /// The finite-sliding run: step 1 loads at phi_0, step i + 1 is at phi_i.
  std::vector<Outcome>
  finite_sliding(const Settings &st, const std::vector<double> &phi, bool &converged)
  {
    PolygonalMesh<2> mesh, gear;
    make_meshes(st, phi[0], mesh, gear);
    for (unsigned int c = 0; c < gear.n_cells(); ++c)
      gear.set_material_id(c, 1);
    for (unsigned int e = 0; e < gear.n_edges(); ++e)
      if (gear.edge(e).at_boundary())
        gear.set_edge_boundary_id(e, gear.edge(e).boundary_id + 10);
    mesh.append(gear);
    const NeoHookeMaterial law(E, nu);
    MaterialLibrary<2>     laws;
    laws.add(0, law);
    laws.add(1, law);
    FiniteSliding::Parameters parameters;
    parameters.degree            = 2;
    parameters.pairing_tolerance = st.tolerance;
    parameters.insertion.search_distance = search_distance;
    FiniteSliding sliding(mesh, laws, {FiniteSliding::InterfaceData{1, 11, 0.}}, parameters);
    // the time t: from 0 to 1 the pinion's bore turns by theta t (the
    // load; a step cut back halves it), then by the roll angle
    // phi(t) - phi_0, phi(1 + i) = phi_i, besides
    const double theta = st.theta, dphi = phi.size() > 1 ? phi[1] - phi[0] : 0.;
    sliding.set_constraints_function(testing::prescribe(
      {0, 10}, [theta, dphi](const dealii::types::boundary_id id, const dealii::Point<2> &X, const double t) {
        const double roll = std::max(t - 1, 0.) * dphi;
        return id == 0 ? turned(X, dealii::Point<2>(0, 0), roll + theta * std::min(t, 1.)) :
                         turned(X, dealii::Point<2>(a, 0), -roll * double(z1) / z2);
      }));

    std::vector<Outcome> results;
    converged = true;
    for (unsigned int i = 0; i < phi.size(); ++i)
      {
        const auto start = std::chrono::steady_clock::now();
        try
          {
            sliding.solve_step(i + 1, 1. + i);
          }
        catch (const std::exception &e)
          {
            std::cout << "finite sliding: step " << i + 1 << " failed: " << e.what() << std::endl;
            converged = false;
            break;
          }
        const auto   &record  = sliding.get_history().back();
        const auto   &u       = sliding.get_solution();
        const auto   &lambda  = sliding.get_multipliers();
        const auto   &contact = sliding.get_contact();
        const auto    np      = contact.n_pairs();
        Outcome       out;
        out.phi    = phi[i];
        out.n_dofs = record.n_dofs;
        // the recovery of the small-strain program (InterfaceTractions):
        // a fit of the interface's degree to the closed pairs' forces
        std::vector<double> force(np);
        std::vector<bool>   closed_pair(np);
        for (unsigned int k = 0; k < np; ++k)
          {
            force[k]       = contact.is_left_out(k) ? 0. : -lambda[k];
            closed_pair[k] = !contact.is_left_out(k) && lambda[k] != 0;
          }
        const auto &itf       = sliding.get_interfaces()[0];
        const auto  recovered = ContactPressure::recover(itf, force, closed_pair, 3, itf.degree);
        for (unsigned int k = 0; k < np; ++k)
          {
            if (contact.is_left_out(k) || lambda[k] == 0)
              continue;
            const auto x   = contact.current_positions(k, u)[1];
            const auto nrm = contact.current_normal(k, u);
            // the pair's place in the reference configuration at phi_i:
            // the current position turned back by the rigid part of the
            // pinion's motion
            const auto X = dealii::Point<2>() + turned(x, dealii::Point<2>(0, 0), -(phi[i] - phi[0]) - theta) +
                           dealii::Tensor<1, 2>(x);
            // the force on the pinion (the master side) is +lambda n
            out.add(pinion_tooth(X, phi[0]), x, -lambda[k],
                    SupportReactions::moment(x, lambda[k] * nrm, dealii::Point<2>(0, 0)), recovered[k]);
          }
        results.push_back(out);
        unsigned int updates = 0;
        for (const auto &pass : record.newton)
          updates += pass.iterations.empty() ? 0 : pass.iterations.size() - 1;
        std::cout << "  finite sliding, step " << i + 1 << " (roll " << std::setprecision(5) << phi[i] * 180 / pi
                  << " deg): " << record.n_dofs << " DoFs, " << record.n_pairs << " pairs, " << record.n_active
                  << " active, " << record.n_passes << " passes, " << record.n_substeps << " sub-steps, "
                  << updates << " Newton updates, offset " << std::setprecision(3) << record.pairing_offset
                  << ", torque " << std::setprecision(8) << out.torque << " (pairs -1, 0, 1: " << out.pair[0].torque
                  << ", " << out.pair[1].torque << ", " << out.pair[2].torque << "), "
                  << std::setprecision(3)
                  << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s"
                  << std::endl;
        std::cout << "    Newton updates (pairing offset) by pass:";
        for (unsigned int q = 0; q < record.newton.size(); ++q)
          std::cout << " " << (record.newton[q].iterations.empty() ? 0 : record.newton[q].iterations.size() - 1)
                    << " (" << std::setprecision(2)
                    << (q < record.pairing_offsets.size() ? record.pairing_offsets[q] : -1.) << ")";
        std::cout << std::setprecision(6) << std::endl;
      }
    return results;
  }

  /// Compares the two series per roll angle and per tooth pair, prints the
  /// table, and asserts the figures of the header.
  void
  compare(const std::vector<double> &phi, const std::vector<Outcome> &fs, const std::vector<Outcome> &qs)
  {
    const double Es = E / (2 * (1 - nu * nu));
    std::cout << "| roll (deg) | s (mm) | pair | s_k (mm) | torque FS | torque QS | diff | share FS | share QS | "
                 "p_max FS | p_max QS | diff | a/h FS, QS |"
              << std::endl;
    // (nothing compared counts as a failure)
    double       torque_diff = fs.empty() ? 1 : 0, share_diff = torque_diff, pressure_diff = torque_diff;
    unsigned int n_compared = 0, n_changes_fs = 0, n_changes_qs = 0, loaded_fs = 0, loaded_qs = 0;
    bool         every_angle_compared = true;
    for (unsigned int i = 0; i < fs.size(); ++i)
      {
        const auto  &f = fs[i], &q = qs[i];
        const double dT = f.torque / q.torque - 1;
        torque_diff     = std::max(torque_diff, std::abs(dT));
        testing::check(f.n_elsewhere == 0 && q.n_elsewhere == 0,
                       "only the tooth pairs of the sectors' middle carry load at roll " +
                         std::to_string(phi[i] * 180 / pi));
        unsigned int n_fs = 0, n_qs = 0, compared_here = 0;
        for (const int k : teeth)
          {
            const auto &pf = f.pair[k + 1], &pq = q.pair[k + 1];
            n_fs += !pf.closed.empty();
            n_qs += !pq.closed.empty();
            if (pf.closed.empty() && pq.closed.empty())
              continue;
            const double s  = rb1 * phi[i] + k * p_b;
            const double R1 = r1 * std::sin(alpha) + s, R2 = r2 * std::sin(alpha) - s;
            // Hertz's half-width with the local radii (the flanks' where the
            // point is on the path of contact; at a tip corner it has no
            // meaning, and the zone is not compared)
            const double half = R1 > 0 && R2 > 0 ? std::sqrt(4 * pq.normal_force * R1 * R2 / (R1 + R2) / (pi * Es)) : 0;
            const double ah_fs = pf.closed.size() > 1 ? half / zone_edge(pf.closed) : 0,
                         ah_qs = pq.closed.size() > 1 ? half / zone_edge(pq.closed) : 0;
            const bool   on_path  = s - half > s_A && s + half < s_E;
            const bool   resolved = on_path && std::min(ah_fs, ah_qs) >= 8;
            const double share_fs = pf.torque / f.torque, share_qs = pq.torque / q.torque;
            const double dp       = pq.p_max > 0 ? pf.p_max / pq.p_max - 1 : 0;
            share_diff            = std::max(share_diff, std::abs(share_fs - share_qs));
            if (resolved)
              {
                pressure_diff = std::max(pressure_diff, std::abs(dp));
                ++n_compared;
                ++compared_here;
              }
            std::cout << "| " << std::setprecision(4) << phi[i] * 180 / pi << " | " << std::setprecision(3)
                      << rb1 * phi[i] << " | " << k << " | " << s << " | " << std::setprecision(7) << pf.torque
                      << " | " << pq.torque << " | " << std::setprecision(2) << 100 * (pf.torque / pq.torque - 1)
                      << " % | " << std::setprecision(4) << share_fs << " | " << share_qs << " | "
                      << std::setprecision(6) << pf.p_max << " | " << pq.p_max << " | " << std::setprecision(2)
                      << 100 * dp << " %" << (resolved ? "" : on_path ? " (a/h < 8)" : " (tip corner)") << " | "
                      << std::setprecision(3) << ah_fs << ", " << ah_qs << " |" << std::endl;
          }
        std::cout << "| " << std::setprecision(4) << phi[i] * 180 / pi << " | " << std::setprecision(3)
                  << rb1 * phi[i] << " | all | | " << std::setprecision(7) << f.torque << " | " << q.torque << " | "
                  << std::setprecision(2) << 100 * dT << " % | | | | | | |" << std::endl;
        every_angle_compared = every_angle_compared && compared_here > 0;
        if (i > 0)
          {
            n_changes_fs += n_fs != loaded_fs;
            n_changes_qs += n_qs != loaded_qs;
          }
        loaded_fs = n_fs;
        loaded_qs = n_qs;
      }
    std::cout << "loaded tooth pairs changed " << n_changes_fs << " times (finite sliding), " << n_changes_qs
              << " times (quasi-static); peak pressures compared on " << n_compared << " zones" << std::endl;
    testing::check(n_changes_fs > 0 && n_changes_qs > 0, "a second tooth pair enters or leaves contact in the run");
    testing::check(every_angle_compared, "at every roll angle a zone is resolved (a / h >= 8) clear of the tips");
    testing::check_small(torque_diff, 0.01, "torque on the pinion, finite sliding against quasi-static (relative)");
    testing::check_small(share_diff, 0.01, "share of the torque per tooth pair, finite sliding against quasi-static");
    // issue 41's 1 %: with the flanks graded to 0.005 (a / h about 20)
    // the peaks of the two insertions (in the current and in the reference
    // configuration) differ by 0.63 % at most; graded to 0.01 (a / h about
    // 10) by up to 1.5 % (see the header)
    testing::check_small(pressure_diff, 0.01,
                         "peak pressure per resolved zone, finite sliding against quasi-static (relative)");
  }
} // namespace

int
main(int argc, char **argv)
{
  // (the quasi-static series above 1.2e5 DoFs, --pitch --h 0.0025, solves
  // by CG-AMG: Trilinos needs MPI)
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Settings st;
  for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--pitch")
        {
          // one base pitch, the zone of single contact in its middle
          st.s_first  = (s_A + s_E) / 2 - p_b / 2;
          st.s_last   = st.s_first + p_b;
          st.n_angles = 16;
        }
      else if (arg == "--angles" && i + 1 < argc)
        st.n_angles = std::stoul(argv[++i]);
      else if (arg == "--h" && i + 1 < argc)
        st.flank_h = std::stod(argv[++i]);
      else if (arg == "--s-max" && i + 1 < argc)
        {
          st.s_last  = std::stod(argv[++i]);
          st.s_first = -st.s_last;
        }
      else if (arg == "--from" && i + 1 < argc)
        st.s_first = std::stod(argv[++i]);
      else if (arg == "--to" && i + 1 < argc)
        st.s_last = std::stod(argv[++i]);
      else if (arg == "--margin" && i + 1 < argc)
        st.margin = std::stod(argv[++i]);
      else if (arg == "--tolerance" && i + 1 < argc)
        st.tolerance = std::stod(argv[++i]);
      else if (arg == "--relief" && i + 1 < argc)
        st.relief = std::stod(argv[++i]);
      else if (arg == "--theta" && i + 1 < argc)
        st.theta = std::stod(argv[++i]);
    }
  // the roll angles: the contact point of tooth 0 at s_first ... s_last
  std::vector<double> phi;
  for (unsigned int i = 0; i < st.n_angles; ++i)
    phi.push_back((st.s_first + (st.s_last - st.s_first) * i / (st.n_angles - 1)) / rb1);

  const auto t0        = std::chrono::steady_clock::now();
  bool       converged = false;
  const auto fs        = finite_sliding(st, phi, converged);
  const auto t1        = std::chrono::steady_clock::now();
  std::vector<Outcome> qs;
  for (const double p : phi)
    qs.push_back(quasi_static(st, p));
  const auto t2 = std::chrono::steady_clock::now();
  std::cout << "finite sliding " << std::chrono::duration<double>(t1 - t0).count() << " s, quasi-static series "
            << std::chrono::duration<double>(t2 - t1).count() << " s" << std::endl;

  testing::check(converged && fs.size() == phi.size(), "finite sliding: every step converges");
  compare(phi, fs, qs);
  return testing::finish();
}
