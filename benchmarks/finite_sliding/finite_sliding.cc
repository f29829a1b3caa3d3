// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The cost of finite sliding (FiniteSliding): node insertion made again in
// the current configuration, the new mesh, DoFs, the transfer of the state
// and the new solver structures, against the Newton solve of the step.
//
// A block [0.5, 1.5] x [1, 1.5] (n x n/2 quads, Neo-Hooke E = 100,
// nu = 0.3) on a base [0, 3] x [0, 1] (Voronoi, 3 n^2 cells, Neo-Hooke
// E = 1000), Coulomb friction mu = 0.3, k = 2. The base's bottom is held;
// the block is pressed by the nominal traction (0, -2) on its top in the
// first step, then its top is moved to the right by a quarter of its
// element length per step while the traction stays (the top's vertical
// displacement is free). Pairs made at every step and at the converged
// state (FiniteSliding's passes).
//
//   benchmark_finite_sliding [--n N] [--steps S] [--mu MU]
//
// prints a line per step: DoFs, pairs, inserted vertices, passes, Newton
// updates, pairing offset, the setup time (pairing, mesh, DoFs, transfer,
// contact, sparsity pattern and solver; all passes), the Newton time and
// their ratio, then "RESULT n dofs setup_per_step solve_per_step ratio"
// (wall seconds, mean over the steps after the first two).
#include <deal.II/base/function.h>

#include <dealvem/contact/finite_sliding.h>
#include <dealvem/contact/finite_strain_contact.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <iomanip>
#include <iostream>
#include <string>

using namespace dealvem;

int
main(int argc, char **argv)
{
  try
    {
      unsigned int n = 48, steps = 6;
      double       mu = 0.3;
      for (int i = 1; i + 1 < argc; i += 2)
        {
          const std::string a = argv[i];
          if (a == "--n")
            n = std::stoul(argv[i + 1]);
          else if (a == "--steps")
            steps = std::stoul(argv[i + 1]);
          else if (a == "--mu")
            mu = std::stod(argv[i + 1]);
          else
            {
              std::cerr << "unknown option " << a << "\n";
              return 2;
            }
        }
      PolygonalMesh<2> mesh, block;
      PolygonalMeshGenerators::voronoi(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(3, 1), 3 * n * n, 10, 3);
      PolygonalMeshGenerators::structured_quads(block, dealii::Point<2>(0.5, 1), dealii::Point<2>(1.5, 1.5), n, n / 2);
      for (unsigned int c = 0; c < block.n_cells(); ++c)
        block.set_material_id(c, 1);
      for (unsigned int e = 0; e < block.n_edges(); ++e)
        if (block.edge(e).at_boundary())
          block.set_edge_boundary_id(e, block.edge(e).boundary_id + 10);
      mesh.append(block);
      MaterialLibrary<2> laws;
      laws.add(0, NeoHookeMaterial(1000, 0.3));
      laws.add(1, NeoHookeMaterial(100, 0.3));

      FiniteSliding::Parameters parameters;
      parameters.degree = 2;
      FiniteSliding sliding(mesh, laws, {{3, 12, mu}}, parameters);
      const double  dt   = 1. / steps;
      const double  push = 0.25 / n; // per step after the first
      sliding.set_constraints_function(
        [&](const VEMDoFHandler<2> &dofs, const double t, dealii::AffineConstraints<double> &constraints) {
          BoundaryConditions::interpolate_boundary_values(dofs, {2}, dealii::Functions::ZeroFunction<2>(2),
                                                          {{true, true}}, constraints);
          const double d = std::max(0., t / dt - 1) * push;
          BoundaryConditions::interpolate_boundary_values(dofs, {13}, dealii::Functions::ConstantFunction<2>(d, 2),
                                                          {{true, false}}, constraints);
          constraints.close();
        });
      const dealii::Functions::ConstantFunction<2> traction(std::vector<double>{0., -2.});
      sliding.set_loads([&](FiniteStrainAssembler<2> &assembler) { assembler.add_traction(13, traction); },
                        [&](const double t) { return std::min(1., t / dt); });

      double setup_sum = 0, solve_sum = 0;
      unsigned int counted = 0, dofs = 0;
      std::cout << "step  DoFs  pairs  inserted  passes  Newton  offset  setup[s]  solve[s]  setup/solve\n";
      for (unsigned int s = 1; s <= steps; ++s)
        {
          sliding.solve_step(s, s * dt);
          const auto &r       = sliding.get_history().back();
          unsigned int updates = 0;
          for (const auto &pass : r.newton)
            for (const auto &it : pass.iterations)
              updates += it.step_length > 0 ? 1 : 0;
          std::cout << std::setw(4) << s << "  " << r.n_dofs << "  " << r.n_pairs << "  " << r.n_inserted << "  "
                    << r.n_passes << "  " << updates << "  " << std::setprecision(2) << r.pairing_offset << "  "
                    << std::setprecision(3) << r.setup_time << "  " << r.solve_time << "  "
                    << r.setup_time / r.solve_time << "  (N = " << r.normal_force[0]
                    << ", T = " << r.friction_force[0] << ", slipping " << r.n_slipping << " of " << r.n_active
                    << ")" << std::endl;
          dofs = r.n_dofs;
          if (s > 2)
            {
              setup_sum += r.setup_time;
              solve_sum += r.solve_time;
              ++counted;
            }
        }
      if (counted > 0)
        std::cout << "RESULT " << n << " " << dofs << " " << setup_sum / counted << " " << solve_sum / counted << " "
                  << setup_sum / solve_sum << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << std::endl;
      return 1;
    }
  return 0;
}
