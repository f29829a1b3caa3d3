// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Convergence of the 3D first-order virtual element (PolyhedralElasticity)
// on a manufactured solution in the unit cube: u_d = s + l_d with
// s = sin(pi x) sin(pi y) sin(pi z) in each component and a linear l, so the
// boundary data are not zero; E = 1, nu = 0.3; the body force
// f = -(lambda + mu) grad div u - mu Laplace u.
// Meshes (each refined three times by halving h): hexahedra; the L-shaped
// non-convex cells of three cubes beside single cubes; a hexahedral mesh
// refined locally (polyhedra with the finer faces), refined globally.
// The theory (Beirao da Veiga, Dassi and Russo 2017) gives
// |u - Pi u_h|_1 = O(h) and ||u - Pi u_h||_0 = O(h^2); asserted: the rates
// between the two finest meshes in [1.85, 2.3] (L2) and [0.9, 1.15] (H1),
// and the finest errors below stated bounds (the measured values, rounded
// up by about 30 %).
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <dealvem/app/polyhedral_elasticity.h>
#include <dealvem/mesh/polyhedral_generators.h>
#include <dealvem/mesh/polyhedral_mesh.h>

#include <cmath>

#include "../tests.h"

using namespace dealvem;
using P  = dealii::Point<3>;
using T  = dealii::Tensor<1, 3>;
using T2 = dealii::Tensor<2, 3>;

namespace
{
  const double pi = M_PI;

  T
  exact(const P &x)
  {
    const double s = std::sin(pi * x[0]) * std::sin(pi * x[1]) * std::sin(pi * x[2]);
    return T({s + 0.1 * x[1], s - 0.2 * x[2], s + 0.3 * x[0]});
  }

  T2
  exact_gradient(const P &x)
  {
    const double sx = std::sin(pi * x[0]), sy = std::sin(pi * x[1]), sz = std::sin(pi * x[2]);
    const double cx = std::cos(pi * x[0]), cy = std::cos(pi * x[1]), cz = std::cos(pi * x[2]);
    const T      ds({pi * cx * sy * sz, pi * sx * cy * sz, pi * sx * sy * cz});
    T2           g;
    for (unsigned int d = 0; d < 3; ++d)
      g[d] = ds;
    g[0][1] += 0.1;
    g[1][2] -= 0.2;
    g[2][0] += 0.3;
    return g;
  }

  T
  body_force(const P &x, const double lambda, const double mu)
  {
    const double sx = std::sin(pi * x[0]), sy = std::sin(pi * x[1]), sz = std::sin(pi * x[2]);
    const double cx = std::cos(pi * x[0]), cy = std::cos(pi * x[1]), cz = std::cos(pi * x[2]);
    const double s  = sx * sy * sz;
    // grad div u, div u = s_x + s_y + s_z
    const T grad_div({-pi * pi * s + pi * pi * cx * cy * sz + pi * pi * cx * sy * cz,
                      pi * pi * cx * cy * sz - pi * pi * s + pi * pi * sx * cy * cz,
                      pi * pi * cx * sy * cz + pi * pi * sx * cy * cz - pi * pi * s});
    const T laplace({-3 * pi * pi * s, -3 * pi * pi * s, -3 * pi * pi * s});
    return -(lambda + mu) * grad_div - mu * laplace;
  }

  PolyhedralMesh
  hexahedra(const unsigned int n)
  {
    dealii::Triangulation<3> tria;
    dealii::GridGenerator::subdivided_hyper_cube(tria, n, 0, 1);
    return PolyhedralMesh::from_triangulation(tria);
  }

  PolyhedralMesh
  locally_refined(const unsigned int global)
  {
    dealii::Triangulation<3> tria;
    dealii::GridGenerator::hyper_cube(tria, 0, 1);
    tria.refine_global(1);
    tria.begin_active()->set_refine_flag();
    tria.execute_coarsening_and_refinement();
    tria.refine_global(global);
    return PolyhedralMesh::from_triangulation(tria);
  }
  PolyhedralMesh
  l_cells(const unsigned int n)
  {
    PolyhedralMesh mesh;
    PolyhedralMeshGenerators::l_shaped_cells(mesh, n);
    return mesh;
  }

  void
  study(const std::string &label, const std::function<PolyhedralMesh(unsigned int)> &make,
        const std::vector<unsigned int> &levels, const double l2_bound, const double h1_bound)
  {
    std::cout << "--- " << label << std::endl;
    std::vector<double> h, l2, h1;
    for (const unsigned int level : levels)
      {
        PolyhedralMesh mesh = make(level);
        mesh.set_boundary_ids([](const P &, const T &) { return true; }, 0);
        PolyhedralElasticity::Settings settings;
        settings.material = {1., 0.3};
        const double         lambda = settings.material.lambda(), mu = settings.material.mu();
        PolyhedralElasticity problem(mesh, settings);
        problem.add_dirichlet(0, exact);
        problem.set_body_force([=](const P &x) { return body_force(x, lambda, mu); });
        problem.solve();
        const auto e = problem.errors(exact, exact_gradient);
        h.push_back(mesh.cell_diameter_range().second);
        l2.push_back(e.l2 / e.l2_exact);
        h1.push_back(e.h1_semi / e.h1_semi_exact);
        std::cout << "    " << mesh.n_cells() << " cells, " << problem.n_dofs() << " DoFs, h " << h.back()
                  << ": relative L2 error " << l2.back() << ", H1 " << h1.back() << std::endl;
      }
    const unsigned int n       = h.size();
    const double       rate_l2 = std::log(l2[n - 2] / l2[n - 1]) / std::log(h[n - 2] / h[n - 1]);
    const double       rate_h1 = std::log(h1[n - 2] / h1[n - 1]) / std::log(h[n - 2] / h[n - 1]);
    testing::check(rate_l2 >= 1.85 && rate_l2 <= 2.3, label + ": L2 rate " + std::to_string(rate_l2) + " in [1.85, 2.3]");
    testing::check(rate_h1 >= 0.9 && rate_h1 <= 1.15, label + ": H1 rate " + std::to_string(rate_h1) + " in [0.9, 1.15]");
    testing::check(l2.back() <= l2_bound, label + ": finest relative L2 error " + std::to_string(l2.back()) +
                                            " below " + std::to_string(l2_bound));
    testing::check(h1.back() <= h1_bound, label + ": finest relative H1 error " + std::to_string(h1.back()) +
                                            " below " + std::to_string(h1_bound));
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // measured (2026-12-01): finest relative L2 / H1 errors 0.00733 / 0.0974,
  // 0.0166 / 0.168 and 0.0260 / 0.186; rates 1.99 / 0.99, 1.93 / 0.94 and
  // 1.94 / 0.99
  study("hexahedra", hexahedra, {4, 8, 16}, 0.0095, 0.127);
  study("L-shaped cells and cubes", l_cells, {4, 8, 16}, 0.0216, 0.218);
  study("locally refined hexahedra, refined globally", locally_refined, {0, 1, 2}, 0.034, 0.242);
  return testing::finish();
}
