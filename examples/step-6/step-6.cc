// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// step-6: the active-set loop in the open.
//
// A curved body pressed onto a block, with the contact iteration written
// out as deal.II's step-41 writes the one of its obstacle problem.
//
// Build (from a dealvem build directory):   make step-6
// Run:                                      ./examples/step-6 [k]
// What it does: a body whose bottom is the parabola y = x^2 / (2 R)
// (R = 1, width 1, height 1/2) is pressed by a uniform pressure p = 50 on
// its top onto a block [-1, 1] x [-1, 0] (E = 1000, nu = 0.3 for both,
// plane strain); the two meshes do not match. Node insertion pairs the
// nodes of the two surfaces; normal contact is unilateral, and a
// tangential multiplier ties each active pair (stick), which holds the body
// tangentially. The program writes the primal-dual active
// set loop itself: per iteration it adds the contact blocks of the current
// active set to a copy of the elasticity system, solves it, and asks
// ActiveSetUpdate for the next set, printing the size of the set, the
// pairs that closed and opened and the complementarity residual, and
// writing "step-6-k<k>-<iteration>.vtu" with the point fields
// "active_set" and "contact_pressure" (and "step-6-k<k>-pressure.svg", the
// pressure along the interface per iteration). It then checks (and exits with an
// error otherwise): the complementarity residual of the converged solution
// is zero; the resultant of the contact forces on the body balances the
// applied load to round-off; ActiveSetSolver::solve() on the same system
// takes the same number of iterations through the same sets and gives the
// same u and lambda to 1e-10. k = 1 and 2, or the one given.

// @sect3{Include files}
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <dealvem/app/input_parsing.h>
#include <dealvem/contact/active_set_solver.h>
#include <dealvem/contact/active_set_update.h>
#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/contact/rigid_body_support.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/postprocessing/svg_plots.h>
#include <dealvem/postprocessing/vtu_output.h>
#include <dealvem/solvers/saddle_point_solver.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace Step6
{
  using namespace dealvem;

  // @sect3{The PressedBody class}
  //
  // The structure of step-41's ObstacleProblem: the elasticity system is
  // set up and assembled once; run() then iterates
  // assemble the contact blocks of the active set -> solve -> update the
  // active set -> output, until the set does not change.
  class PressedBody
  {
  public:
    explicit PressedBody(const unsigned int degree);
    void
    run();

  private:
    void
    make_meshes();
    void
    insert_nodes();
    void
    setup_system();
    void
    assemble_system();
    void
    solve_for_active_set();
    void
    output_results(const unsigned int iteration);
    void
    check_results() const;

    const unsigned int degree;
    const double       p = 50., R = 1., E = 1000., nu = 0.3;

    std::map<dealii::types::material_id, ElasticMaterial> materials;
    PolygonalMesh<2>                                      mesh;
    VEMDoFHandler<2>                                      dof_handler;
    std::vector<NodeInsertion::Interface>                 interfaces;
    std::unique_ptr<ContactScales>                        scales;
    std::unique_ptr<ContactAssembler<2>>                  contact;
    std::unique_ptr<RigidBodySupport>                     support;
    ContactSettings                                       settings;
    dealii::AffineConstraints<double>                     constraints;
    dealii::SparsityPattern                               sparsity_pattern;
    dealii::SparseMatrix<double>                          system_matrix, contact_matrix;
    dealii::Vector<double>                                system_rhs, contact_rhs, solution;
    unsigned int                                          n_dofs = 0;

    // The state of the iteration: the current active set, the iteration
    // count, the sets visited (for cycle detection). It is ours; the
    // update rule only advances it.
    std::unique_ptr<ActiveSetUpdate<2>>  update;
    ActiveSetUpdate<2>::State            state;
    std::vector<std::vector<bool>>       sets_solved_with;
    // The contact pressure along the interface per iteration, for a picture.
    std::vector<SVGPlots::Series>        pressure_history;
  };

  PressedBody::PressedBody(const unsigned int degree)
    : degree(degree)
    , materials({{0, ElasticMaterial(E, nu)}, {1, ElasticMaterial(E, nu)}})
  {}

  // @sect4{PressedBody::make_meshes}
  //
  // Both bodies are deal.II triangulations converted to polygons. The
  // block has 12 x 6 cells; the body 16 x 4, with its bottom bent onto the
  // parabola $y = x^2/(2R)$ by GridTools::transform (the top $y = 1/2$
  // stays straight). The body gets material id 1 and boundary ids 10..13
  // (left, right, bottom, top), then the two meshes become one
  // PolygonalMesh whose bodies share no vertex.
  void
  PressedBody::make_meshes()
  {
    dealii::Triangulation<2> block, body;
    dealii::GridGenerator::subdivided_hyper_rectangle(block, {12, 6}, dealii::Point<2>(-1, -1),
                                                      dealii::Point<2>(1, 0), true);
    dealii::GridGenerator::subdivided_hyper_rectangle(body, {16, 4}, dealii::Point<2>(-0.5, 0),
                                                      dealii::Point<2>(0.5, 0.5), true);
    const double radius = R;
    dealii::GridTools::transform(
      [radius](const dealii::Point<2> &q) {
        return dealii::Point<2>(q[0], q[1] + (1 - 2 * q[1]) * q[0] * q[0] / (2 * radius));
      },
      body);
    // (colorize = true also numbers the cells' material ids by quadrant:
    // one id per body instead)
    for (const auto &cell : block.active_cell_iterators())
      cell->set_material_id(0);
    for (const auto &cell : body.active_cell_iterators())
      {
        cell->set_material_id(1);
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            face->set_boundary_id(face->boundary_id() + 10);
      }
    // from_triangulation() copies material and boundary ids
    PolygonalMeshGenerators::from_triangulation(mesh, block);
    PolygonalMesh<2> upper;
    PolygonalMeshGenerators::from_triangulation(upper, body);
    mesh.append(upper);
  }

  // @sect4{PressedBody::insert_nodes}
  //
  // The block's top (id 3) is the master side, which gives the normal; the
  // body's bottom (id 12) the slave side. Node insertion makes both sides
  // carry the same nodes in the overlap, so each node pair is one
  // constraint $g_i = (u_B - u_A)\cdot n_i + g_{0,i} \ge 0$ between two
  // DoF sets. The gaps between the parabola's chords and the flat block are
  // real gaps (not two discretisations of one curve), so none of them is
  // closed as a discretisation gap.
  void
  PressedBody::insert_nodes()
  {
    NodeInsertion::Settings insertion;
    insertion.close_discretisation_gaps = false;
    interfaces = {NodeInsertion::insert(mesh, 3, 12, degree, insertion)};
    dof_handler.reinit(mesh);
    dof_handler.distribute_dofs(degree);
    std::cout << "   " << interfaces[0].pairs.size() << " node pairs, " << dof_handler.n_dofs() << " DoFs"
              << std::endl;
  }

  // @sect4{PressedBody::setup_system}
  //
  // The unknowns are the displacements followed by one normal multiplier
  // per node pair and one tangential multiplier per pair (the tangential
  // constraint $(u_B - u_A)\cdot t_i = 0$, enforced on the active pairs
  // only). The block's bottom is held vertically and its corner $(-1,-1)$
  // horizontally; the body is held only by contact: vertically by the
  // active pairs, tangentially by their tangential multipliers. The
  // constant of the active-set rule is the library's $c = E_{min}/h_{min}$
  // (ContactScales).
  void
  PressedBody::setup_system()
  {
    settings.normal     = ContactSettings::Normal::unilateral;
    settings.tangential = ContactSettings::Tangential::multipliers;
    scales = std::make_unique<ContactScales>(std::vector<double>{E, E}, interfaces);
    contact = std::make_unique<ContactAssembler<2>>(dof_handler, interfaces[0].pairs, settings,
                                                    scales->penalty(settings));

    constraints.clear();
    dealii::Functions::ZeroFunction<2> zero(2);
    BoundaryConditions::interpolate_boundary_values(dof_handler, {2}, zero, {{false, true}}, constraints);
    BoundaryConditions::add_point_constraint(dof_handler, dealii::Point<2>(-1, -1), 0, 0., constraints);
    constraints.close();

    n_dofs                 = dof_handler.n_dofs();
    const unsigned int n_m = contact->n_multipliers();
    dealii::DynamicSparsityPattern dsp(n_dofs + n_m);
    dof_handler.make_sparsity_pattern(dsp);
    contact->add_sparsity(dsp);
    constraints.condense(dsp);
    sparsity_pattern.copy_from(dsp);
    system_matrix.reinit(sparsity_pattern);
    contact_matrix.reinit(sparsity_pattern);
    system_rhs.reinit(n_dofs + n_m);

    // Which rigid-body motions a set of closed pairs holds: the first set
    // must hold the body, or the first system is singular.
    support = std::make_unique<RigidBodySupport>(dof_handler, constraints, *contact, true);
  }

  // @sect4{PressedBody::assemble_system}
  //
  // The elastic part and the pressure on the body's top, once: the active
  // set only changes the contact blocks.
  void
  PressedBody::assemble_system()
  {
    ElasticityAssembler<2>                 assembler(dof_handler, materials);
    dealii::Functions::ConstantFunction<2> pressure(p);
    assembler.add_pressure(13, pressure);
    assembler.assemble(constraints, system_matrix, system_rhs);
  }

  // @sect4{PressedBody::solve_for_active_set}
  //
  // The loop of step-41. ActiveSetUpdate holds the rule; the loop, the
  // matrices and the solver are ours. initial_state() closes the pairs with
  // zero initial gap and, since one pair cannot hold the body against
  // rotation, the next smallest gaps until RigidBodySupport says the body
  // is held. Each update() takes the solution, proposes
  // $\{i : -\lambda_i/w_i - c\,g_i > 0\}$ (with ActiveSetSolver's
  // acceleration, see its documentation), and returns true when the set
  // repeats.
  void
  PressedBody::solve_for_active_set()
  {
    update = std::make_unique<ActiveSetUpdate<2>>(contact->get_pairs(), settings,
                                                  scales->complementarity_constant());
    update->set_support(support.get());
    update->set_pair_neighbours(ActiveSetSolver<2>::pair_neighbours(interfaces));
    state = update->initial_state();
    std::cout << "   first active set: " << std::count(state.active.begin(), state.active.end(), true)
              << " pairs (" << state.n_closed_for_support << " closed to hold the body)" << std::endl;

    SaddlePointSolver solver(SaddlePointSolver::Settings{});
    for (unsigned int iteration = 1;; ++iteration)
      {
        // 1. The system of this active set: the elasticity part plus the
        // contact blocks, $g_i = 0$ for active pairs, $\lambda_i = 0$ for
        // the others.
        contact_matrix.copy_from(system_matrix);
        contact_rhs = system_rhs;
        contact->assemble(constraints, state.active, contact_matrix, contact_rhs);
        // 2. One linear solve (UMFPACK on the saddle-point system).
        solver.solve(contact_matrix, n_dofs, solution, contact_rhs);
        constraints.distribute(solution);
        sets_solved_with.push_back(state.active);
        // 3. The update of the active set.
        const unsigned int n_active      = std::count(state.active.begin(), state.active.end(), true);
        const unsigned int n_accelerated = state.n_accelerated;
        const bool         converged     = update->update(state, *contact, solution);
        std::cout << "   iteration " << iteration << ": " << std::setw(2) << n_active << " active pairs, "
                  << "complementarity residual " << std::scientific << std::setprecision(2) << state.residual
                  << std::defaultfloat;
        if (converged)
          std::cout << ", the set repeats: converged" << std::endl;
        else
          std::cout << "; next set: " << state.n_closed << " closed, " << state.n_opened << " opened"
                    << (state.n_accelerated > n_accelerated ? " (corrected by the acceleration)" : "")
                    << std::endl;
        // 4. The active set and the pressure of this iteration, for ParaView.
        output_results(iteration);
        if (converged)
          break;
      }
  }

  // @sect4{PressedBody::output_results}
  //
  // step-41 writes the active set as a field per iteration. Ours lives on
  // node pairs: the point field "active_set" is 1 at both vertices of an
  // active pair (its master and slave vertex), "contact_pressure" is
  // $-\lambda_i/w_i$ there; k = 2 midpoint pairs have no vertex and are
  // not shown. The set written is the one this iteration solved with. The
  // pressure at every pair also goes into a line plot, one curve per
  // iteration from the second on (written by run() as
  // step-6-k<k>-pressure.svg).
  void
  PressedBody::output_results(const unsigned int iteration)
  {
    const auto         &pairs = contact->get_pairs();
    const ContactRows   rows  = contact->rows();
    const auto         &set   = sets_solved_with.back();
    std::vector<double> active(mesh.n_vertices(), 0.), pressure(mesh.n_vertices(), 0.);
    for (unsigned int i = 0; i < pairs.size(); ++i)
      if (!pairs[i].on_edge())
        for (const unsigned int v : {pairs[i].master_entity, pairs[i].slave_entity})
          {
            active[v]   = set[i] ? 1. : 0.;
            pressure[v] = -rows.normal_multiplier(solution, i) / pairs[i].weight;
          }
    dealii::Vector<double> u(n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      u[i] = solution[i];
    const StressRecovery<2> stresses(dof_handler, materials, u);
    write_vtu_file("step-6-k" + std::to_string(degree) + "-" + std::to_string(iteration) + ".vtu", dof_handler, u,
                   stresses, {{"active_set", active}, {"contact_pressure", pressure}});

    // the pressure at every pair (midpoints included), sorted along x; not
    // for the first iteration, whose few closed pairs carry the whole load
    // at pressures that would flatten the other curves
    if (iteration == 1)
      return;
    SVGPlots::Series series;
    series.name = "iteration " + std::to_string(iteration);
    for (unsigned int i = 0; i < pairs.size(); ++i)
      series.points.emplace_back(pairs[i].slave_location[0], -rows.normal_multiplier(solution, i) / pairs[i].weight);
    std::sort(series.points.begin(), series.points.end());
    series.marker_radius = 2;
    pressure_history.push_back(series);
  }

  // @sect4{PressedBody::check_results}
  //
  // Three checks, each on numbers the mathematics fixes:
  // - the converged solution satisfies the contact conditions: the
  //   complementarity residual $\max_i |p_i - \max(0, p_i - c g_i)|$ is
  //   zero (to $10^{-10} p$);
  // - the body is held only by contact, and the VEM stiffness annihilates
  //   translations exactly, so the resultant of the contact forces on the
  //   body's nodes, $\sum_i (-\lambda_i n_i + f_{t,i} t_i)$ with
  //   $f_{t,i}$ the tangential force on the slave node (minus its
  //   tangential multiplier, ContactAssembler::tangential_forces()),
  //   balances the applied load $(0, -p \cdot 1)$ to round-off;
  // - ActiveSetSolver, the library's driver of the same rule, run on the
  //   same system, goes through the same sets in the same number of
  //   iterations and returns the same $u$ and $\lambda$ (to $10^{-10}$ of
  //   their size: the same operations in the same order).
  void
  PressedBody::check_results() const
  {
    const auto &pairs = contact->get_pairs();

    // the multiplier of pair i: the solution's entry in the pair's normal
    // row (ContactRows, unknown n_dofs + i)
    const ContactRows   rows = contact->rows();
    std::vector<double> gaps = contact->gaps(solution), lambda(pairs.size());
    for (unsigned int i = 0; i < pairs.size(); ++i)
      lambda[i] = rows.normal_multiplier(solution, i);
    const double residual = update->residual(gaps, lambda);

    const auto           ft = contact->tangential_forces(solution);
    dealii::Tensor<1, 2> force;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      force += -lambda[i] * pairs[i].normal + ft[i] * pairs[i].tangent;
    const dealii::Tensor<1, 2> load({0., -p * 1.});
    const double               balance = (force + load).norm() / load.norm();

    SaddlePointSolver  solver(SaddlePointSolver::Settings{});
    ActiveSetSolver<2> active_set(*contact, constraints, solver, settings, scales->complementarity_constant());
    active_set.set_support(support.get());
    active_set.set_pair_neighbours(ActiveSetSolver<2>::pair_neighbours(interfaces));
    dealii::SparseMatrix<double> work(sparsity_pattern);
    dealii::Vector<double>       x;
    const auto                   result = active_set.solve(system_matrix, system_rhs, work, x);
    double                       du = 0, u_max = 0, dl = 0, l_max = 0;
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        du    = std::max(du, std::abs(x[i] - solution[i]));
        u_max = std::max(u_max, std::abs(solution[i]));
      }
    for (unsigned int i = n_dofs; i < x.size(); ++i)
      {
        dl    = std::max(dl, std::abs(x[i] - solution[i]));
        l_max = std::max(l_max, std::abs(solution[i]));
      }
    bool same_sets = (result.n_active_history.size() == sets_solved_with.size());
    for (unsigned int it = 0; same_sets && it < sets_solved_with.size(); ++it)
      same_sets = (result.n_active_history[it] ==
                   static_cast<unsigned int>(
                     std::count(sets_solved_with[it].begin(), sets_solved_with[it].end(), true)));

    std::cout << std::scientific << std::setprecision(2) << "   complementarity residual / p = " << residual / p
              << ", |contact force + load| / |load| = " << balance << std::endl
              << "   ActiveSetSolver: " << result.n_iterations << " iterations (this loop: " << state.n_iterations
              << "), max |u - u_loop| / max |u| = " << du / u_max
              << ", max |lambda - lambda_loop| / max |lambda| = " << dl / l_max << std::defaultfloat << std::endl;
    AssertThrow(residual <= 1e-10 * p,
                dealii::ExcMessage("The converged active set does not satisfy the contact conditions."));
    AssertThrow(balance <= 1e-10, dealii::ExcMessage("The contact forces do not balance the applied load."));
    AssertThrow(result.n_iterations == state.n_iterations && result.active == state.active && same_sets &&
                  du <= 1e-10 * u_max && dl <= 1e-10 * l_max,
                dealii::ExcMessage("The loop of this program and ActiveSetSolver::solve() differ."));
  }

  void
  PressedBody::run()
  {
    std::cout << "k = " << degree << std::endl;
    make_meshes();
    insert_nodes();
    setup_system();
    assemble_system();
    solve_for_active_set();
    SVGPlots::write_line_plot("step-6-k" + std::to_string(degree) + "-pressure.svg", pressure_history, "x",
                              "contact pressure -lambda_i / w_i",
                              "step-6, k = " + std::to_string(degree) + ": pressure per active-set iteration");
    check_results();
  }
} // namespace Step6


// @sect3{The main function}
//
// As in step-2: an optional order k (1 or 2); anything else stops with the
// usage and exit code 2.
int
main(int argc, char **argv)
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      std::vector<unsigned int>                degrees = {1, 2};
      unsigned int                             k       = 0;
      if (argc > 2 || (argc == 2 && !dealvem::InputParsing::parse_count(argv[1], 1, 2, k)))
        {
          std::cerr << "step-6: " << (argc > 2 ? "too many arguments" : "the order k must be 1 or 2, not '" +
                                                                             std::string(argv[1]) + "'")
                    << ".\nusage: step-6 [k]   (k = 1 or 2, the order of the virtual elements; both if omitted)"
                    << std::endl;
          return 2;
        }
      if (argc == 2)
        degrees = {k};
      for (const unsigned int k : degrees)
        {
          Step6::PressedBody problem(k);
          problem.run();
        }
    }
  catch (std::exception &exc)
    {
      std::cerr << std::endl
                << "----------------------------------------------------" << std::endl
                << "Exception on processing: " << std::endl
                << exc.what() << std::endl
                << "Aborting!" << std::endl
                << "----------------------------------------------------" << std::endl;
      return 1;
    }
  return 0;
}
