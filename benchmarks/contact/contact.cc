// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The contact patch test scaled up: two stacked blocks [0,1]x[0,1] and
// [0,1]x[1,2] with non-matching structured quads (n and n + n/3 + 1
// subdivisions), k = 2, pressure on top, unilateral normal contact and stick
// by penalty -- against the same geometry meshed as ONE body [0,1]x[0,2]
// (matching mesh, n' x 2n' quads with n' chosen for about the same number
// of DoFs) with the same load and supports and the same solver.
//
//   benchmark_contact --n N --solver UMFPACK|KLU|GMRES-AMG|"CG-AMG constraints"
//                     [--tangential penalty|multipliers] [--penalty-factor F]
//                     [--preconditioner AMG|automatic] [--run both|contact|onebody]
//                     [--distributed]
//
// prints "RESULT contact n dofs multipliers t_mesh t_insertion t_assembly
// t_solve", "TOTAL contact n t_total cg_iterations active_set_iterations"
// (the whole contact run, mesh to output), "RESULT onebody n dofs -
// t_mesh 0 t_assembly t_solve" and "TOTAL onebody n t_total cg_iterations"
// and "STAGES contact|onebody | stage seconds | ..." (every stage of the
// run's timings) (wall seconds; the one-body run maps GMRES-AMG and CG-AMG constraints to
// CG-AMG). Both runs use 'Solver/Preconditioner' = the --preconditioner
// given (AMG by default: ML AMG on the whole matrix; automatic: the
// p-multigrid for k = 2 on one body and on the condensed contact system).
// Under mpirun both runs take the distributed path; --distributed makes
// the contact run take it also in one process (to tell what the
// distributed formulation costs from what the partition costs). --run contact or
// onebody runs one of the two: a run that follows the other in the same
// process finds the heap already faulted in (on a VM with expensive page
// faults the second run was up to 2x faster than in a process of its own),
// so benchmarks/contact/run.sh and benchmarks/run_benchmarks.sh run each in
// its own process.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/app/elasticity_problem.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace
{
  // "STAGES which name=seconds; ...": every stage of the run's timings
  template <typename Map>
  void
  print_stages(const std::string &which, const Map &timings)
  {
    std::cout << "STAGES " << which;
    for (const auto &t : timings)
      std::cout << " | " << t.first << " " << t.second;
    std::cout << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      unsigned int                             n      = 30;
      std::string                              solver = "UMFPACK";
      std::string                              tangential = "penalty";
      std::string                              penalty_factor = "1000";
      std::string                              preconditioner = "AMG";
      std::string                              which          = "both";
      bool                                     distributed    = false;
      for (int i = 1; i < argc; i += 2)
        {
          const std::string a = argv[i];
          if (a == "--distributed")
            {
              distributed = true;
              --i;
              continue;
            }
          if (i + 1 == argc)
            throw std::invalid_argument(a + ": a value is missing");
          if (a == "--n")
            n = std::stoul(argv[i + 1]);
          else if (a == "--solver")
            solver = argv[i + 1];
          else if (a == "--tangential")
            tangential = argv[i + 1];
          else if (a == "--penalty-factor")
            penalty_factor = argv[i + 1];
          else if (a == "--preconditioner")
            preconditioner = argv[i + 1];
          else if (a == "--run")
            which = argv[i + 1];
          else
            throw std::invalid_argument("unknown option " + a);
        }
      if (which != "both" && which != "contact" && which != "onebody")
        throw std::invalid_argument("--run " + which + ": expected both, contact or onebody");
      const std::string common =
        "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\n"
        "subsection Discretization\n  set Order = 2\nend\n"
        "subsection Solver\n  set Type = " + solver + "\n  set Relative tolerance = 1e-10\n"
        "  set Preconditioner = " + preconditioner + "\nend\n"
        "subsection Output\n  set Folder = benchmark-output\n  set Write VTU = false\n  set Write JSON = false\n"
        "  set Write pictures = false\n  set Write CSV = false\nend\n";
      const unsigned int m = n + n / 3 + 1;
      if (which != "onebody")
      {
        std::ostringstream prm;
        prm << "set Number of bodies = 2\n"
            << "subsection Mesh\n  set Type = structured quads\n  set Subdivisions = " << n << ", " << n << "\nend\n"
            << "subsection Body 1\n  subsection Mesh\n    set Type = structured quads\n"
            << "    set Lower left corner = 0, 1\n    set Upper right corner = 1, 2\n    set Subdivisions = " << m
            << ", " << m << "\n    set Boundary id offset = 10\n  end\n"
            << "  subsection Material\n    set Young's modulus = 7000\n  end\nend\n"
            << "subsection Contact\n  set Pairs = 3 : 12\n  set Tangential = " << tangential
            << "\n  set Penalty factor = " << penalty_factor << "\nend\n"
            << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : y : 0\n"
            << "  set Point constraints = 0, 0 : x : 0\n  set Pressure = 13 : 10\nend\n"
            << common;
        dealii::ParameterHandler ph;
        dealvem::ElasticityProblem::declare_parameters(ph);
        dealvem::ContactProblem::declare_parameters(ph);
        ph.parse_input_from_string(prm.str());
        const auto              start = std::chrono::steady_clock::now();
        dealvem::ContactProblem problem(MPI_COMM_WORLD, distributed
                                                          ? dealvem::ElasticityProblem::Parallelism::distributed
                                                          : dealvem::ElasticityProblem::Parallelism::automatic);
        problem.parse_parameters(ph);
        problem.run();
        const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const auto &r = problem.get_results();
        auto        t = r.timings;
        if (root)
          std::cout << "RESULT contact " << n << " " << r.n_dofs << " " << r.n_multipliers << " " << t["mesh"] << " "
                  << t["node insertion"] << " " << t["assembly"] << " " << t["solve"] << std::endl;
        if (root)
          std::cout << "TOTAL contact " << n << " " << total << " " << r.linear_iterations << " "
                  << r.active_set_iterations << std::endl;
        if (root)
          print_stages("contact", t);
      }
      if (which != "contact")
      {
        const unsigned int n1 = std::max(1u, unsigned(std::lround(std::sqrt((n * n + m * m) / 2.))));
        std::ostringstream prm;
        prm << "subsection Mesh\n  set Type = structured quads\n  set Upper right corner = 1, 2\n"
            << "  set Subdivisions = " << n1 << ", " << 2 * n1 << "\nend\n"
            << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : y : 0\n"
            << "  set Point constraints = 0, 0 : x : 0\n  set Pressure = 3 : 10\nend\n"
            << common;
        dealii::ParameterHandler ph;
        dealvem::ElasticityProblem::declare_parameters(ph);
        dealvem::ContactProblem::declare_parameters(ph);
        ph.parse_input_from_string(prm.str());
        const auto                 start = std::chrono::steady_clock::now();
        dealvem::ElasticityProblem problem;
        problem.parse_parameters(ph);
        problem.run();
        const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        auto         t     = problem.last_timings;
        if (root)
          {
            std::cout << "RESULT onebody " << n << " " << problem.last_n_dofs << " 0 " << t["mesh"] << " 0 "
                      << t["setup"] + t["assembly"] << " " << t["solve"] << std::endl;
            std::cout << "TOTAL onebody " << n << " " << total << " " << problem.last_iterations << std::endl;
            print_stages("onebody", t);
          }
      }
    }
  catch (std::exception &e)
    {
      std::cerr << "benchmark_contact: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
