// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The distributed path of PolyhedralElasticity against its serial path. Run
// directly (one process) and by ctest under mpirun -np 2 (vem3d/mpi_3d-np2).
// The mesh: the non-convex L cells of l_shaped_cells(8) (256 cells) and
// the hexahedra of a randomly perturbed deal.II mesh with its warped faces
// split, both mapped to a bar 4 x 1 x 1; clamped at x = 0, a body force and
// a traction on x = 4. Checks:
// - the cells of the processes are disjoint and cover the mesh, every
//   process has some;
// - the distributed solve with the direct solver (Amesos KLU) gives the
//   serial UMFPACK displacements at every DoF to 1e-10 relative (max norm
//   of the difference over the max norm of the solution); the distributed
//   CG-AMG solve (six rigid modes, relative residual 1e-12) to 1e-9;
// - errors() (summed over the processes) and cell_stresses() (gathered)
//   equal the serial ones to 1e-9 relative;
// - the displacement patch test on the distributed path: a linear field
//   prescribed on the whole boundary is reproduced at every vertex to 1e-10
//   of its size (KLU and CG-AMG);
// - write_vtu() writes one file, from process 0, with the process of each
//   cell on more than one process;
// - on more than one process, a mesh with fewer cells than processes is
//   refused with a message that says so.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <dealvem/app/polyhedral_elasticity.h>
#include <dealvem/mesh/polyhedral_generators.h>
#include <dealvem/mesh/polyhedral_mesh.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../tests.h"

using namespace dealvem;
using testing::check;
using testing::check_small;
using P = dealii::Point<3>;
using T = dealii::Tensor<1, 3>;

namespace
{
  struct Outcome
  {
    dealii::Vector<double>       u;
    PolyhedralElasticity::Errors errors;
    std::vector<double>          stresses;
    unsigned int                 iterations = 0;
    std::vector<unsigned int>    owned_cells;
  };

  // a smooth field for the error norms (not the solution: the norms only
  // have to agree between the paths)
  T
  field(const P &x)
  {
    return T({std::sin(x[0]) * x[1], 0.1 * x[2] * x[2], std::cos(x[1] + x[2])});
  }
  dealii::Tensor<2, 3>
  field_gradient(const P &x)
  {
    dealii::Tensor<2, 3> g;
    g[0][0] = std::cos(x[0]) * x[1];
    g[0][1] = std::sin(x[0]);
    g[1][2] = 0.2 * x[2];
    g[2][1] = g[2][2] = -std::sin(x[1] + x[2]);
    return g;
  }

  Outcome
  bar(const PolyhedralMesh &mesh, const MPI_Comm comm, const LinearSolver::Type type)
  {
    PolyhedralElasticity::Settings settings;
    settings.material                  = {200., 0.3};
    settings.solver.type               = type;
    settings.solver.relative_tolerance = 1e-12;
    PolyhedralElasticity problem(mesh, settings, comm);
    problem.add_dirichlet(0, [](const P &) { return T(); });
    problem.set_body_force([](const P &x) { return T({0.1 * x[1], 0, -1}); });
    problem.add_traction(1, [](const P &x, const T &) { return T({1 + x[2], 0.5, -0.2 * x[1]}); });
    problem.solve();
    return {problem.solution(), problem.errors(field, field_gradient), problem.cell_stresses(),
            problem.last_iterations(), problem.locally_owned_cells()};
  }

  double
  relative_difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    double diff = 0, size = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        diff = std::max(diff, std::abs(a[i] - b[i]));
        size = std::max(size, std::abs(b[i]));
      }
    return a.size() == b.size() ? diff / size : 1e300;
  }

  void
  compare(const Outcome &o, const Outcome &serial, const double tolerance, const std::string &what)
  {
    check_small(relative_difference(std::vector<double>(o.u.begin(), o.u.end()),
                                    std::vector<double>(serial.u.begin(), serial.u.end())),
                tolerance, what + ": displacements against the serial UMFPACK solve");
    check_small(relative_difference(o.stresses, serial.stresses), tolerance,
                what + ": cell stresses against the serial ones");
    check_small(std::abs(o.errors.l2 - serial.errors.l2) / serial.errors.l2 +
                  std::abs(o.errors.h1_semi - serial.errors.h1_semi) / serial.errors.h1_semi +
                  std::abs(o.errors.l2_exact - serial.errors.l2_exact) / serial.errors.l2_exact,
                1e-9, what + ": errors() against the serial ones");
  }

  void
  patch_test(const PolyhedralMesh &mesh, const MPI_Comm comm, const LinearSolver::Type type, const std::string &what)
  {
    // u = b + A x, prescribed on the whole boundary (ids 0 to 5)
    const auto exact = [](const P &x) {
      return T({0.01 + 0.002 * x[0] - 0.001 * x[1] + 0.003 * x[2], -0.02 + 0.001 * x[0] + 0.004 * x[1],
                0.005 - 0.002 * x[1] + 0.001 * x[2]});
    };
    PolyhedralElasticity::Settings settings;
    settings.material                  = {1., 0.25};
    settings.solver.type               = type;
    settings.solver.relative_tolerance = 1e-13;
    PolyhedralElasticity problem(mesh, settings, comm);
    for (unsigned int id = 0; id < 6; ++id)
      problem.add_dirichlet(id, exact);
    problem.solve();
    double error = 0, size = 0;
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      {
        const T e = exact(mesh.vertex(v));
        for (unsigned int d = 0; d < 3; ++d)
          {
            error = std::max(error, std::abs(problem.solution()[3 * v + d] - e[d]));
            size  = std::max(size, std::abs(e[d]));
          }
      }
    check_small(error / size, 1e-10, what + ": the displacement patch test at every vertex");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const unsigned int                       rank = dealii::Utilities::MPI::this_mpi_process(comm);
  const unsigned int                       size = dealii::Utilities::MPI::n_mpi_processes(comm);
  if (rank > 0)
    std::cout.setstate(std::ios::failbit); // one report (failures are summed below)
  std::cout << "MPI processes: " << size << std::endl;

  // the two meshes, the same on every process
  std::vector<std::pair<std::string, PolyhedralMesh>> meshes;
  {
    PolyhedralMesh l_mesh;
    PolyhedralMeshGenerators::l_shaped_cells(l_mesh, 8);
    l_mesh.transform([](const P &x) { return P(4 * x[0], x[1] + 0.1 * x[0], x[2]); });
    l_mesh.name = "L cells";
    meshes.emplace_back("L cells", std::move(l_mesh));

    dealii::Triangulation<3> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {24, 6, 6}, P(0, 0, 0), P(4, 1, 1), true);
    // a fixed seed: the same perturbation on every process
    dealii::GridTools::distort_random(0.25, tria, false, 7);
    PolyhedralMesh hex = PolyhedralMesh::from_triangulation(tria, 1e-8, true, "perturbed hexahedra");
    meshes.emplace_back("perturbed hexahedra", std::move(hex));
  }

  for (const auto &[name, mesh] : meshes)
    {
      // the serial reference on process 0, sent to the others
      Outcome serial;
      if (rank == 0)
        serial = bar(mesh, MPI_COMM_SELF, LinearSolver::Type::umfpack);
      unsigned int n[2] = {serial.u.size(), static_cast<unsigned int>(serial.stresses.size())};
      MPI_Bcast(n, 2, MPI_UNSIGNED, 0, comm);
      serial.u.reinit(n[0], rank == 0);
      serial.stresses.resize(n[1]);
      double errors[3] = {serial.errors.l2, serial.errors.h1_semi, serial.errors.l2_exact};
      MPI_Bcast(serial.u.data(), n[0], MPI_DOUBLE, 0, comm);
      MPI_Bcast(serial.stresses.data(), n[1], MPI_DOUBLE, 0, comm);
      MPI_Bcast(errors, 3, MPI_DOUBLE, 0, comm);
      serial.errors.l2       = errors[0];
      serial.errors.h1_semi  = errors[1];
      serial.errors.l2_exact = errors[2];

      const Outcome      direct = bar(mesh, comm, LinearSolver::Type::klu);
      const unsigned int owned  = direct.owned_cells.size();
      check(dealii::Utilities::MPI::sum(owned, comm) == mesh.n_cells() && dealii::Utilities::MPI::min(owned, comm) > 0,
            name + ": the processes' cells cover the " + std::to_string(mesh.n_cells()) +
              " cells, every process has some");
      // disjoint: each cell marked by exactly one process
      std::vector<unsigned int> marks(mesh.n_cells(), 0);
      for (const unsigned int c : direct.owned_cells)
        marks[c] = 1;
      MPI_Allreduce(MPI_IN_PLACE, marks.data(), marks.size(), MPI_UNSIGNED, MPI_SUM, comm);
      check(*std::max_element(marks.begin(), marks.end()) == 1 && *std::min_element(marks.begin(), marks.end()) == 1,
            name + ": each cell belongs to exactly one process");
      compare(direct, serial, 1e-10, name + ", distributed KLU on " + std::to_string(size) + " process(es)");
      const Outcome amg = bar(mesh, comm, LinearSolver::Type::cg_amg);
      std::cout << "  " << name << ": CG-AMG " << amg.iterations << " iterations" << std::endl;
      compare(amg, serial, 1e-9, name + ", distributed CG-AMG on " + std::to_string(size) + " process(es)");
      patch_test(mesh, comm, LinearSolver::Type::klu, name + ", KLU on " + std::to_string(size) + " process(es)");
      patch_test(mesh, comm, LinearSolver::Type::cg_amg, name + ", CG-AMG on " + std::to_string(size) + " process(es)");
    }

  // the VTU file: one, written by process 0
  {
    const std::string file = "bar-np" + std::to_string(size) + ".vtu";
    if (rank == 0)
      std::filesystem::remove(file);
    MPI_Barrier(comm);
    PolyhedralElasticity::Settings settings;
    settings.material    = {1., 0.3};
    settings.solver.type = LinearSolver::Type::klu;
    PolyhedralElasticity problem(meshes[0].second, settings, comm);
    problem.add_dirichlet(0, [](const P &) { return T(); });
    problem.set_body_force([](const P &) { return T({0, 0, -1}); });
    problem.solve();
    problem.write_vtu(file);
    MPI_Barrier(comm);
    if (rank == 0)
      {
        std::ifstream     in(file);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        check(text.find("NumberOfCells=\"" + std::to_string(meshes[0].second.n_cells()) + "\"") != std::string::npos,
              file + " holds every cell");
        check((text.find("Name=\"process\"") != std::string::npos) == (size > 1),
              file + " has the process field exactly when distributed");
      }
  }

  if (size > 1)
    {
      PolyhedralMesh one;
      PolyhedralMeshGenerators::hyper_rectangle(one, P(0, 0, 0), P(1, 1, 1), {{1, 1, 1}});
      PolyhedralElasticity::Settings settings;
      settings.material    = {1., 0.3};
      settings.solver.type = LinearSolver::Type::klu;
      PolyhedralElasticity problem(one, settings, comm);
      problem.add_dirichlet(0, [](const P &) { return T(); });
      testing::check_throws([&problem]() { problem.solve(); },
                            "fewer than the " + std::to_string(size) + " MPI processes",
                            "one cell on " + std::to_string(size) + " processes is refused");
    }

  const int failures = dealii::Utilities::MPI::sum(testing::n_failures(), comm);
  std::cout << (failures == 0 ? "OK" : "FAILED") << ": " << failures << " failed check(s)" << std::endl;
  return failures;
}
