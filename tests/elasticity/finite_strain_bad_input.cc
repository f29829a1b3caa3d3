// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Bad input to the finite-strain solver gives a clear error, never NaN or a
// hang:
// - a prescribed displacement that inverts the body: u = lambda (F - I) X
//   on the whole boundary with F = diag(1, -0.2), in 10 load steps; the
//   boundary itself turns inside out beyond lambda = 1/1.2, so load step 9
//   (lambda = 0.9) must fail with an exception naming the step, the load
//   factor and an inverted cell; the 8 converged steps are kept (history
//   of 9 steps, the last one not converged) and the solution is the exact
//   state of step 8, 0.8 (F - I) X, to 1e-10; (k = 1 and 2, Neo-Hooke and
//   Saint Venant-Kirchhoff, Voronoi mesh)
// - a step that does not converge within max_iterations (1 here) stops
//   with the step number and its residual history in the message;
// - a law without finite-strain response (ElasticMaterial), zero load
//   steps, and constraints that are not closed are refused with messages
//   naming them.
#include <iostream>

#include "../elasticity_common.h"
#include "../finite_strain_common.h"
#include "../tests.h"

using namespace dealvem;

int
main()
{
  const double         E = 7000., nu = 0.3;
  dealii::Tensor<2, 2> F;
  F[0][0] = 1.;
  F[1][1] = -0.2;
  const testing::HomogeneousDeformation inverting(F);
  PolygonalMesh<2>                      mesh;
  testing::make_mesh(mesh, "voronoi", 0);

  const NeoHookeMaterial             neo_hooke(E, nu);
  const SaintVenantKirchhoffMaterial svk(E, nu);
  for (const unsigned int k : {1u, 2u})
    for (const HyperelasticMaterial *law :
         {static_cast<const HyperelasticMaterial *>(&neo_hooke), static_cast<const HyperelasticMaterial *>(&svk)})
      {
        const std::string name =
          "k = " + std::to_string(k) + ", " + law->get_name().substr(0, law->get_name().find(" ("));
        VEMDoFHandler<2> dof_handler(mesh);
        dof_handler.distribute_dofs(k);
        FiniteStrainAssembler<2>          assembler(dof_handler, testing::one_law_library(dof_handler, *law));
        dealii::AffineConstraints<double> constraints;
        testing::dirichlet_constraints(dof_handler, {0, 1, 2, 3}, inverting, constraints);
        FiniteStrainSolver<2>::Parameters parameters;
        parameters.n_load_steps = 10;
        FiniteStrainSolver<2> solver(assembler, constraints, parameters);
        std::string           message;
        try
          {
            solver.run();
          }
        catch (const std::exception &e)
          {
            message = testing::collapse_white_space(e.what());
          }
        std::cout << "--- " << name << ": " << message.substr(message.find("FiniteStrainSolver"), 300) << std::endl;
        testing::check(message.find("load step 9 (load factor 0.9) did not converge") != std::string::npos,
                       name + ": the error names load step 9 and its load factor");
        testing::check(message.find("inverted") != std::string::npos && message.find("cell") != std::string::npos,
                       name + ": the error says that a cell is inverted");
        const auto &history = solver.get_history();
        bool        kept    = history.size() == 9 && !history.back().converged;
        for (unsigned int s = 0; s + 1 < history.size(); ++s)
          kept = kept && history[s].converged;
        testing::check(kept, name + ": 8 converged steps kept, the failed one recorded");
        testing::check_near(solver.get_load_factor(), 0.8, 1e-15, name + ": load factor of the kept solution");
        std::vector<dealii::Point<2>> support;
        dof_handler.map_dofs_to_support_points(support);
        double err = 0;
        for (unsigned int i = 0; i < support.size(); ++i)
          err = std::max(err, std::abs(solver.get_solution()[i] - 0.8 * inverting.value(support[i], i % 2)));
        testing::check_small(err, 1e-10, name + ": kept solution = the exact state of step 8");
      }

  // a step that cannot converge in the iterations allowed
  {
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(1);
    FiniteStrainAssembler<2> assembler(dof_handler, testing::one_law_library(dof_handler, neo_hooke));
    dealii::Tensor<2, 2>     G;
    G[0][0] = 1.2;
    G[1][1] = 0.9;
    G[0][1] = 0.2;
    const testing::HomogeneousDeformation stretch(G);
    dealii::AffineConstraints<double>     constraints;
    testing::dirichlet_constraints(dof_handler, {0, 1}, stretch, constraints);
    FiniteStrainSolver<2>::Parameters parameters;
    parameters.n_load_steps   = 2;
    parameters.max_iterations = 1;
    FiniteStrainSolver<2> solver(assembler, constraints, parameters);
    testing::check_throws([&]() { solver.run(); }, "load step 1 (load factor 0.5) did not converge: no convergence in 1 Newton iterations",
                          "max_iterations = 1: the error names the step");
    testing::check_throws([&]() { solver.run(); }, "Newton history of the step: step 1, load factor 0.5: NOT converged after 1 Newton updates",
                          "  and prints the residual history of the step");
  }

  // laws and parameters refused
  {
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(1);
    const ElasticMaterial linear(E, nu);
    testing::check_throws([&]() { FiniteStrainAssembler<2>(dof_handler, testing::one_law_library(dof_handler, linear)); },
                          "has no finite-strain response", "a linear law is refused by FiniteStrainAssembler");
    FiniteStrainAssembler<2>          assembler(dof_handler, testing::one_law_library(dof_handler, svk));
    dealii::AffineConstraints<double> open_constraints;
    open_constraints.add_line(0);
    FiniteStrainSolver<2>::Parameters parameters;
    testing::check_throws([&]() { FiniteStrainSolver<2>(assembler, open_constraints, parameters); },
                          "the constraints must be closed", "constraints that are not closed are refused");
    dealii::AffineConstraints<double> constraints;
    constraints.close();
    parameters.n_load_steps = 0;
    testing::check_throws([&]() { FiniteStrainSolver<2>(assembler, constraints, parameters); },
                          "the number of load steps (n_load_steps) must be at least 1", "zero load steps are refused");
  }
  return testing::finish();
}
