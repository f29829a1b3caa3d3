// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The rubber ring of ring_reference.cc solved with dealvem: finite-strain
// virtual elements and finite sliding (FiniteSliding) against a rigid plate.
// Quarter ring of radii 0.6 and 1 (GridGenerator::quarter_hyper_shell,
// refined r times; its vertices on the circles), Neo-Hooke E = 1,
// nu = 0.3, plane strain, u_x = 0 on x = 0, u_y = 0 on y = 0; the plate
// [0, 1.2] x [1, 1.1] of m x 3 quads, every node of it moved down by d
// (rigid), frictionless, d = 0.05 ... 0.45 in nine steps (the reference
// ends its smooth branch at a limit point near d = 0.46).
//
// Usage: benchmark_ring_vem [k r m [swap]]   (default: 2 3 60)
//   k     the order of the virtual elements (1 or 2)
//   r     the global refinements of the ring
//   m     the plate cells along x
//   swap  1: the ring is the master side (default: the plate)
// Prints per step: d, DoFs, active pairs, merged pairs, pairing passes,
// Newton updates, the plate force (quarter model, per unit thickness),
// set-up and solve times; then a machine-readable block
//   # vem: d F
// (benchmarks/ring_compression/run.sh compares it with the reference).
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <dealvem/contact/finite_sliding.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace dealvem;

int
main(int argc, char **argv)
{
  const auto number = [&](const int i, const unsigned int fallback) {
    return argc > i ? static_cast<unsigned int>(std::stoul(argv[i])) : fallback;
  };
  const unsigned int k = number(1, 2), r = number(2, 3), m = number(3, 60), swap = number(4, 0);
  if (argc > 5 || (k != 1 && k != 2) || r > 6 || m < 2)
    {
      std::cerr << "usage: benchmark_ring_vem [k (1 or 2) r (0..6) m (>= 2) [swap (0 or 1)]]" << std::endl;
      return 2;
    }
  dealii::Triangulation<2> tria;
  dealii::GridGenerator::quarter_hyper_shell(tria, dealii::Point<2>(), 0.6, 1.0, 0, true);
  tria.refine_global(r);
  PolygonalMesh<2> mesh, plate;
  PolygonalMeshGenerators::from_triangulation(mesh, tria);
  // ring ids: 0 inner circle, 1 outer circle, 2 on x = 0, 3 on y = 0
  for (unsigned int e = 0; e < mesh.n_edges(); ++e)
    {
      const auto &edge = mesh.edge(e);
      if (edge.at_boundary() && edge.boundary_id >= 2)
        {
          const auto c = 0.5 * (mesh.vertex(edge.vertices[0]) + mesh.vertex(edge.vertices[1]));
          mesh.set_edge_boundary_id(e, std::abs(c[0]) < 1e-12 ? 2 : 3);
        }
    }
  // the plate: ids 10 left, 11 right, 12 bottom, 13 top
  PolygonalMeshGenerators::structured_quads(plate, dealii::Point<2>(0, 1.0), dealii::Point<2>(1.2, 1.1), m, 3);
  for (unsigned int c = 0; c < plate.n_cells(); ++c)
    plate.set_material_id(c, 1);
  for (unsigned int e = 0; e < plate.n_edges(); ++e)
    if (plate.edge(e).at_boundary())
      plate.set_edge_boundary_id(e, plate.edge(e).boundary_id + 10);
  mesh.append(plate);

  const NeoHookeMaterial law(1.0, 0.3);
  MaterialLibrary<2>     laws;
  laws.add(0, law);
  laws.add(1, law);
  FiniteSliding::Parameters parameters;
  parameters.degree             = k;
  parameters.pairing_tolerance  = 1e-6;
  parameters.max_pairing_passes = 20;
  const FiniteSliding::InterfaceData interface =
    swap ? FiniteSliding::InterfaceData{1, 12, 0.} : FiniteSliding::InterfaceData{12, 1, 0.};
  FiniteSliding sliding(mesh, laws, {interface}, parameters);
  sliding.set_constraints_function(
    [&](const VEMDoFHandler<2> &dofs, const double t, dealii::AffineConstraints<double> &constraints) {
      const auto &mm  = dofs.get_mesh();
      const auto  fix = [&](const unsigned int node, const unsigned int comp, const double value) {
        const auto dof = VEMDoFHandler<2>::node_dof(node, comp);
        if (!constraints.is_constrained(dof))
          {
            constraints.add_line(dof);
            constraints.set_inhomogeneity(dof, value);
          }
      };
      for (unsigned int e = 0; e < mm.n_edges(); ++e)
        {
          const auto &edge = mm.edge(e);
          if (!edge.at_boundary() || (edge.boundary_id != 2 && edge.boundary_id != 3))
            continue;
          std::vector<unsigned int> nodes = {dofs.vertex_node(edge.vertices[0]), dofs.vertex_node(edge.vertices[1])};
          if (k == 2)
            nodes.push_back(dofs.edge_node(e));
          for (const auto node : nodes)
            fix(node, edge.boundary_id == 2 ? 0 : 1, 0.);
        }
      std::vector<unsigned int> nodes;
      for (unsigned int c = 0; c < mm.n_cells(); ++c)
        if (mm.cell(c).material_id == 1)
          {
            dofs.get_node_indices(c, nodes);
            for (const auto node : nodes)
              {
                fix(node, 0, 0.);
                fix(node, 1, -0.45 * t);
              }
          }
      constraints.close();
    });

  std::cout << "VEM k = " << k << ", ring refined " << r << " times, plate " << m << " x 3, "
            << (swap ? "ring" : "plate") << " as master" << std::endl;
  std::cout << "   d     DoFs  active merged passes Newton  force         set-up(s) solve(s)" << std::endl;
  std::vector<double> forces;
  for (unsigned int n = 1; n <= 9; ++n)
    {
      try
        {
          sliding.solve_step(n, n / 9.);
        }
      catch (const std::exception &e)
        {
          std::cout << "step " << n << " failed: " << e.what() << std::endl;
          return 1;
        }
      const auto  &record = sliding.get_history().back();
      unsigned int newton = 0;
      for (const auto &pass : record.newton)
        newton += pass.iterations.size();
      forces.push_back(std::abs(record.normal_force[0][1]));
      std::cout << std::fixed << std::setprecision(2) << std::setw(5) << 0.05 * n << std::setw(8) << record.n_dofs
                << std::setw(7) << record.n_active << std::setw(7) << record.n_merged << std::setw(7)
                << record.n_passes << std::setw(7) << newton << "  " << std::scientific << std::setprecision(6)
                << forces.back() << "  " << std::fixed << std::setprecision(3) << std::setw(8) << record.setup_time
                << std::setw(9) << record.solve_time << std::endl;
    }
  std::cout << "# vem: d F" << std::endl;
  for (unsigned int n = 0; n < forces.size(); ++n)
    std::cout << std::fixed << std::setprecision(2) << 0.05 * (n + 1) << " " << std::scientific
              << std::setprecision(9) << forces[n] << std::endl;
  return 0;
}
