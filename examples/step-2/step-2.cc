// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// step-2: the contact patch test on non-matching meshes -- node insertion
// and node-to-node Lagrange multipliers.
//
// Build (from a dealvem build directory):   make step-2
// Run:                                      ./examples/step-2 [k]
// What it does: two stacked blocks with non-matching meshes (3x3 quads below,
// 7x7 quads or Voronoi cells above) are pressed together by a uniform
// pressure p = 10 MPa (E = 7000 MPa, nu = 0.3, plane strain). Node insertion
// makes the interface matching, one multiplier per node pair enforces the
// normal contact (unilateral, by an active set), a penalty the tangential
// stick. The program prints the largest deviation of the stresses from the
// exact uniform state and of the contact pressures from p, and exits with
// an error if they are not at round-off. The same problem is described by
// the parameter file patch-test.prm for the `dealvem` program.

// @sect3{Include files}
#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <dealvem/app/input_parsing.h>
#include <dealvem/contact/active_set_solver.h>
#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/postprocessing/vtu_output.h>
#include <dealvem/solvers/saddle_point_solver.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/vem_values.h>

#include <iomanip>
#include <iostream>
#include <string>

namespace Step2
{
  using namespace dealvem;

  // @sect3{The ContactPatchTest class}
  class ContactPatchTest
  {
  public:
    ContactPatchTest(const unsigned int degree, const bool voronoi_upper);
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
    solve();
    void
    check_results() const;

    const unsigned int degree;
    const bool         voronoi_upper;
    const double       p = 10.;

    std::map<dealii::types::material_id, ElasticMaterial> materials;
    PolygonalMesh<2>                                      mesh;
    VEMDoFHandler<2>                                      dof_handler;
    std::vector<NodeInsertion::Interface>                 interfaces;
    std::vector<ContactNodePair>                          pairs;
    std::unique_ptr<ContactScales>                        scales;
    std::unique_ptr<ContactAssembler<2>>                  contact;
    ContactSettings                                       settings;
    dealii::AffineConstraints<double>                     constraints;
    dealii::SparsityPattern                               sparsity_pattern;
    dealii::SparseMatrix<double>                          system_matrix, work_matrix;
    dealii::Vector<double>                                system_rhs, solution;
    unsigned int                                          n_dofs = 0;
  };

  ContactPatchTest::ContactPatchTest(const unsigned int degree, const bool voronoi_upper)
    : degree(degree)
    , voronoi_upper(voronoi_upper)
    , materials({{0, ElasticMaterial(7000, 0.3)}, {1, ElasticMaterial(7000, 0.3)}})
  {}

  // @sect4{ContactPatchTest::make_meshes}
  //
  // Each body is meshed on its own; the upper body gets material id 1 and
  // boundary ids 10..13 (left, right, bottom, top), then both meshes are
  // put into one PolygonalMesh. Cells of different material ids never share
  // vertices: the bodies only interact through contact.
  void
  ContactPatchTest::make_meshes()
  {
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 3, 3);
    PolygonalMesh<2> upper;
    if (voronoi_upper)
      PolygonalMeshGenerators::voronoi(upper, dealii::Point<2>(0, 1), dealii::Point<2>(1, 2), 12, 30, 3);
    else
      PolygonalMeshGenerators::structured_quads(upper, dealii::Point<2>(0, 1), dealii::Point<2>(1, 2), 7, 7);
    for (unsigned int c = 0; c < upper.n_cells(); ++c)
      upper.set_material_id(c, 1);
    for (unsigned int e = 0; e < upper.n_edges(); ++e)
      if (upper.edge(e).at_boundary())
        upper.set_edge_boundary_id(e, upper.edge(e).boundary_id + 10);
    mesh.append(upper);
  }

  // @sect4{ContactPatchTest::insert_nodes}
  //
  // The interface is the top of the lower block (id 3, master: it gives
  // the normal) and the bottom of the upper block (id 12, slave). Node
  // insertion carries the vertices of each side over to the other side and
  // splits the edges there (nodes closer than 5 % of the local edge
  // length are merged instead), so that both sides carry the same vertices
  // -- and for k = 2 the same sub-edge midpoints. The polygons that own
  // split edges simply gain a vertex. insert() returns the node pairs it
  // made: normal n, tangent t, initial gap g_0 and the tributary weight w
  // (L/2 per end for k = 1; Simpson's L/6, 2L/3, L/6 for k = 2).
  void
  ContactPatchTest::insert_nodes()
  {
    interfaces           = {NodeInsertion::insert(mesh, 3, 12, degree, NodeInsertion::Settings())};
    const auto &report   = interfaces[0].report;
    std::cout << "   node insertion: " << report.n_inserted_master << " nodes inserted on the master side, "
              << report.n_inserted_slave << " on the slave side, " << report.n_merged << " merged" << std::endl;
    dof_handler.reinit(mesh);
    dof_handler.distribute_dofs(degree);
    pairs = interfaces[0].pairs;
    std::cout << "   " << pairs.size() << " node pairs, " << dof_handler.n_dofs() << " DoFs" << std::endl;
  }

  // @sect4{ContactPatchTest::setup_system}
  //
  // The unknowns are the displacements followed by one multiplier per
  // normal constraint: $[K\ C^T; C\ 0][u;\lambda] = [f; -g_0]$. The bottom
  // is held vertically and the corner (0,0) horizontally; the upper block is
  // held tangentially by the stick penalty and vertically by contact.
  void
  ContactPatchTest::setup_system()
  {
    settings.normal     = ContactSettings::Normal::unilateral;
    settings.tangential = ContactSettings::Tangential::penalty;
    // the library's one rule for the constants: E_min / h_min with E_min the
    // smallest characteristic stiffness of the laws (Young's modulus for
    // ElasticMaterial) and h_min the shortest paired sub-edge; the penalty
    // is settings.penalty_factor (1000) times it, the active-set constant c
    // is it
    scales  = std::make_unique<ContactScales>(MaterialLibrary<2>(materials), interfaces);
    contact = std::make_unique<ContactAssembler<2>>(dof_handler, pairs, settings, scales->penalty(settings));

    constraints.clear();
    dealii::Functions::ZeroFunction<2> zero(2);
    BoundaryConditions::interpolate_boundary_values(dof_handler, {2}, zero, {{false, true}}, constraints);
    BoundaryConditions::add_point_constraint(dof_handler, dealii::Point<2>(0, 0), 0, 0., constraints);
    constraints.close();

    n_dofs                 = dof_handler.n_dofs();
    const unsigned int n_m = contact->n_multipliers();
    dealii::DynamicSparsityPattern dsp(n_dofs + n_m);
    dof_handler.make_sparsity_pattern(dsp);
    contact->add_sparsity(dsp);
    constraints.condense(dsp);
    sparsity_pattern.copy_from(dsp);
    system_matrix.reinit(sparsity_pattern);
    work_matrix.reinit(sparsity_pattern);
    system_rhs.reinit(n_dofs + n_m);
  }

  // @sect4{ContactPatchTest::assemble_system}
  //
  // The elastic part, cell by cell, into the upper left block of the big
  // matrix; the pressure on the top of the upper block (id 13) is the load.
  // The contact blocks are added by the active-set solver in each of its
  // iterations.
  void
  ContactPatchTest::assemble_system()
  {
    VEMValues<2>                           vem_values(dof_handler);
    ElasticityOperator<2>                  elasticity;
    dealii::Functions::ConstantFunction<2> pressure(p);
    dealii::Vector<double>                 cell_rhs;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        vem_values.reinit(c);
        elasticity.reinit(vem_values.get_element(), materials.at(vem_values.material_id()));
        cell_rhs.reinit(vem_values.dofs_per_cell());
        for (unsigned int e = 0; e < vem_values.n_edges(); ++e)
          if (vem_values.edge_boundary_id(e) == 13)
            vem_values.add_edge_pressure(e, pressure, cell_rhs);
        constraints.distribute_local_to_global(elasticity.get_stiffness_matrix(), cell_rhs,
                                               vem_values.get_dof_indices(), system_matrix, system_rhs);
      }
  }

  // @sect4{ContactPatchTest::solve}
  //
  // The primal-dual active set starts from the pairs with closed gaps (here
  // all), solves the saddle-point system with UMFPACK, and updates the set
  // until it does not change.
  void
  ContactPatchTest::solve()
  {
    SaddlePointSolver       solver(SaddlePointSolver::Settings{});
    ActiveSetSolver<2>      active_set(*contact, constraints, solver, settings, scales->complementarity_constant());
    const auto              result = active_set.solve(system_matrix, system_rhs, work_matrix, solution);
    std::cout << "   active set: " << result.n_iterations << " iteration(s)" << std::endl;
  }

  // @sect4{ContactPatchTest::check_results}
  //
  // The patch test: $\sigma_{yy} = -p$, $\sigma_{xx} = \sigma_{xy} = 0$ in
  // every cell and the contact pressure $-\lambda_i / w_i = p$ at every node.
  void
  ContactPatchTest::check_results() const
  {
    dealii::Vector<double> u(n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      u[i] = solution[i];
    const StressRecovery<2> stresses(dof_handler, materials, u);
    double                  stress_error = 0, pressure_error = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const auto &s = stresses.cell_stress(c);
        stress_error  = std::max({stress_error, std::abs(s[0][0]), std::abs(s[1][1] + p), std::abs(s[0][1])});
      }
    // the multiplier of pair i is the solution's entry in the pair's normal
    // row (ContactRows, unknown n_dofs + i)
    const ContactRows rows = contact->rows();
    for (unsigned int i = 0; i < pairs.size(); ++i)
      pressure_error = std::max(pressure_error, std::abs(-rows.normal_multiplier(solution, i) / rows.weight(i) - p));
    std::cout << std::scientific << std::setprecision(2) << "   max |sigma - sigma_exact| / p = " << stress_error / p
              << ", max |pressure - p| / p = " << pressure_error / p << std::defaultfloat << std::endl;
    write_vtu_file("step-2-k" + std::to_string(degree) + (voronoi_upper ? "-voronoi" : "-quads") + ".vtu",
                   dof_handler, u, stresses);
    AssertThrow(stress_error <= 1e-10 * p && pressure_error <= 1e-10 * p,
                dealii::ExcMessage("The contact patch test is not passed to round-off."));
  }

  void
  ContactPatchTest::run()
  {
    std::cout << "k = " << degree << ", upper block: " << (voronoi_upper ? "Voronoi cells" : "7x7 quads")
              << std::endl;
    make_meshes();
    insert_nodes();
    setup_system();
    assemble_system();
    solve();
    check_results();
  }
} // namespace Step2


// @sect3{The command line}
//
// An argument is a whole number in a given range; anything else (a sign, a
// letter, a number too large for the type) stops the program with the usage
// instead of a wrapped or misread value (InputParsing::parse_count()).

// @sect3{The main function}
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
          std::cerr << "step-2: " << (argc > 2 ? "too many arguments" : "the order k must be 1 or 2, not '" +
                                                                             std::string(argv[1]) + "'")
                    << ".\nusage: step-2 [k]   (k = 1 or 2, the order of the virtual elements; both if omitted)"
                    << std::endl;
          return 2;
        }
      if (argc == 2)
        degrees = {k};
      for (const unsigned int k : degrees)
        for (const bool voronoi : {false, true})
          {
            Step2::ContactPatchTest test(k, voronoi);
            test.run();
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
