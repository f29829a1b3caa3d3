// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The distributed path of ElasticityProblem against the serial one, on
// tests/app/mpi-voronoi.prm (Voronoi, k = 2, body force of a smooth exact
// solution; the second cycle has 9606 DoFs). Run directly (one process: the
// distributed path on one process) and by ctest under mpirun -np 2
// (app/mpi_elasticity-np2). Checks:
// - VEMPartition: the owned DoFs of the processes are disjoint and cover
//   all DoFs, every owned DoF lies on an owned cell, the relevant DoFs
//   contain the owned ones and the DoFs of the owned cells;
// - the distributed solve with the direct solver (Amesos KLU) gives the
//   serial UMFPACK displacements at all DoFs (gathered) to 1e-10 relative
//   (max norm of the difference over the max norm of the solution), and the
//   L2, H1 and energy errors (summed over the processes) to 1e-10 relative;
// - the distributed CG solve (k = 2: the p-multigrid of ParallelLinearSolver,
//   as on the serial path; relative residual 1e-12) gives them to
//   1e-10 as well (measured: 5e-14 for the displacements);
// - the .pvtu record and one .vtu piece per process are written, and the
//   pieces hold all cells once.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <dealvem/app/elasticity_problem.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/partitioning.h>

#include "../tests.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>

using namespace dealvem;
using testing::check;
using testing::check_small;

namespace
{
  struct Result
  {
    dealii::Vector<double> solution;
    std::vector<double>    errors;
  };

  Result
  run(const MPI_Comm comm, const ElasticityProblem::Parallelism parallelism, const std::string &solver,
      const std::string &folder, const bool write_vtu)
  {
    const char       *dir  = std::getenv("DEALVEM_SOURCE_DIR");
    const std::string file = std::string(dir ? dir : "../../..") + "/tests/app/mpi-voronoi.prm";
    dealii::ParameterHandler prm;
    ElasticityProblem::declare_parameters(prm);
    prm.parse_input(file);
    prm.enter_subsection("Solver");
    prm.set("Type", solver);
    prm.set("Relative tolerance", "1e-12");
    prm.leave_subsection();
    prm.enter_subsection("Output");
    prm.set("Folder", folder);
    prm.set("Write VTU", write_vtu);
    prm.set("Write JSON", false);
    prm.leave_subsection();
    ElasticityProblem problem(comm, parallelism);
    problem.parse_parameters(prm, std::filesystem::path(file).parent_path().string());
    problem.gather_solution = true;
    problem.run();
    check(problem.is_distributed() == (parallelism == ElasticityProblem::Parallelism::distributed),
          "the problem takes the path asked for");
    check(problem.peak_memory_per_process.size() ==
              (problem.is_distributed() ? dealii::Utilities::MPI::n_mpi_processes(comm) : 1u) &&
            problem.peak_memory_per_process[0] > 0,
          "peak memory reported for every process");
    return {problem.last_solution, problem.last_errors};
  }

  void
  compare(const Result &a, const Result &ref, const double tolerance, const std::string &what)
  {
    check(a.solution.size() == ref.solution.size(), what + ": same number of DoFs");
    if (a.solution.size() != ref.solution.size())
      return;
    dealii::Vector<double> d = a.solution;
    d -= ref.solution;
    check_small(d.linfty_norm() / ref.solution.linfty_norm(), tolerance,
                what + ": max |u - u_serial| / max |u_serial| over all " + std::to_string(d.size()) + " DoFs");
    const char *names[] = {"L2", "H1", "energy"};
    for (unsigned int i = 0; i < 3; ++i)
      check_small(std::abs(a.errors[i] - ref.errors[i]) / ref.errors[i], tolerance,
                  what + ": relative difference of the " + names[i] + " error");
  }

  // the partition's index sets on a Voronoi mesh, k = 2
  void
  check_partition(const MPI_Comm comm)
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::voronoi(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(2, 1), 150, 5, 3);
    VEMDoFHandler<2> dofs(mesh);
    dofs.distribute_dofs(2);
    VEMPartition<2> partition;
    partition.reinit(dofs, comm);
    const dealii::AffineConstraints<double> none;
    const dealii::IndexSet &owned    = partition.locally_owned_dofs();
    const dealii::IndexSet  relevant = partition.locally_relevant_dofs(none);
    const dealii::IndexSet  on_cells = partition.dofs_of_cells(partition.locally_owned_cells());
    const auto all = dealii::Utilities::MPI::all_gather(comm, owned);
    dealii::IndexSet union_set(dofs.n_dofs());
    std::size_t      n_total = 0;
    for (const auto &s : all)
      {
        union_set.add_indices(s);
        n_total += s.n_elements();
      }
    check(n_total == dofs.n_dofs() && union_set.n_elements() == dofs.n_dofs(),
          "owned DoFs: disjoint over the processes and covering all " + std::to_string(dofs.n_dofs()) + " DoFs");
    bool on_own_cell = true;
    for (const auto i : owned)
      on_own_cell = on_own_cell && on_cells.is_element(i);
    check(on_own_cell, "every owned DoF lies on an owned cell");
    dealii::IndexSet covered = relevant;
    covered.add_indices(owned);
    covered.add_indices(on_cells);
    check(covered == relevant, "relevant DoFs contain the owned DoFs and the DoFs of the owned cells");
    const auto per_part = partition.cells_per_part();
    std::size_t n_cells = 0;
    for (const auto n : per_part)
      n_cells += n;
    check(n_cells == mesh.n_cells() && partition.locally_owned_cells().size() == per_part[partition.this_part()],
          "cells per part add up to the mesh");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm     comm = MPI_COMM_WORLD;
  const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
  const unsigned int size = dealii::Utilities::MPI::n_mpi_processes(comm);
  if (rank > 0)
    std::cout.setstate(std::ios::failbit); // one report (failures are summed below)
  std::cout << "MPI processes: " << size << std::endl;

  check_partition(comm);

  // the serial reference on process 0, sent to the others
  Result serial;
  if (rank == 0)
    serial = run(MPI_COMM_SELF, ElasticityProblem::Parallelism::serial, "UMFPACK", "serial", false);
  unsigned int n = serial.solution.size();
  MPI_Bcast(&n, 1, MPI_UNSIGNED, 0, comm);
  serial.solution.reinit(n, rank == 0);
  serial.errors.resize(3);
  MPI_Bcast(serial.solution.data(), n, MPI_DOUBLE, 0, comm);
  MPI_Bcast(serial.errors.data(), 3, MPI_DOUBLE, 0, comm);

  const std::string folder = "np" + std::to_string(size);
  if (rank == 0)
    std::filesystem::remove_all(folder);
  MPI_Barrier(comm);
  // (a run removes the files of the earlier run with the same prefix: the
  // run whose pieces are checked below goes last)
  const Result direct = run(comm, ElasticityProblem::Parallelism::distributed, "KLU", folder, false);
  compare(direct, serial, 1e-10, "distributed KLU on " + std::to_string(size) + " process(es)");
  const Result amg = run(comm, ElasticityProblem::Parallelism::distributed, "CG-AMG", folder, true);
  compare(amg, serial, 1e-10, "distributed CG-AMG on " + std::to_string(size) + " process(es)");

  // the output of the last cycle: the record names every piece, the pieces
  // hold every cell once
  MPI_Barrier(comm);
  if (rank == 0)
    {
      std::ifstream     in(folder + "/solution-cycle1.pvtu");
      const std::string pvtu((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      unsigned int      cells = 0;
      for (unsigned int p = 0; p < size; ++p)
        {
          const std::string piece = "solution-cycle1." + std::to_string(p) + ".vtu";
          check(pvtu.find("<Piece Source=\"" + piece + "\"/>") != std::string::npos, "the .pvtu names " + piece);
          std::ifstream     pin(folder + "/" + piece);
          const std::string text((std::istreambuf_iterator<char>(pin)), std::istreambuf_iterator<char>());
          std::smatch       m;
          const bool        found = std::regex_search(text, m, std::regex("NumberOfCells=\"([0-9]+)\""));
          check(found, piece + " written");
          if (found)
            cells += std::stoul(m[1]);
        }
      check(cells == 800, "the pieces hold the 800 cells of the mesh once (" + std::to_string(cells) + ")");
    }

  const int failures = dealii::Utilities::MPI::sum(testing::n_failures(), comm);
  return failures;
}
