// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The verification after every contact solve (ForceBalance in
// ContactProblem) on a soft and a stiff block: the upper block (Young's
// modulus E_top) pressed by p = 10 onto the lower one (E = 1, clamped at
// its bottom), non-matching meshes, stick by penalty. Run on one process
// (serial path) and under mpirun -np 2 (distributed path):
// - stiffness ratio 1: every solver type gives the contact force (0, 10)
//   to 1e-10 and a relative imbalance and residual below 1e-11 per body
//   (recorded per step in Results::steps[].balance);
// - ratios 1e9 and 1e12, the soft block on the stiff one and the stiff one
//   on the soft one: either the contact force is (0, 10) to 1e-6 relative,
//   or the run is refused by the verification ("Verification failed" or
//   "is inaccurate"), never a wrong answer (a stiff block on a soft one at
//   1e12 gave a force 1.2 % off with exit 0).
#include <deal.II/base/mpi.h>

#include <sstream>

#include "../contact_common.h"
#include "../tests.h"

namespace
{
  std::string
  stack_prm(const double e_bottom, const double e_top, const std::string &solver)
  {
    std::ostringstream prm;
    prm.precision(17);
    prm << "set Number of bodies = 2\n"
        << testing::block_mesh("structured quads", 0, 0, 1, 1, 4, 4, 0)
        << "subsection Material\n  set Young's modulus = " << e_bottom << "\n  set Poisson's ratio = 0.3\nend\n"
        << "subsection Body 1\n"
        << testing::block_mesh("structured quads", 0, 1, 1, 2, 5, 5, 10)
        << "subsection Material\n  set Young's modulus = " << e_top << "\n  set Poisson's ratio = 0.3\nend\nend\n"
        << "subsection Discretization\n  set Order = 2\nend\n"
        << "subsection Contact\n  set Pairs = 3 : 12\nend\n"
        << "subsection Solver\n  set Type = " << solver << "\nend\n"
        << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : xy : 0, 0\n"
        << "  set Pressure = 13 : 10\nend\n"
        << "subsection Output\n  set Write VTU = false\n  set Write JSON = false\n  set Write pictures = "
           "false\n  set Write CSV = false\nend\n";
    return prm.str();
  }

  // Run; returns false (and the message) when refused.
  bool
  run(const std::string &prm, dealvem::ContactProblem::Results &results, std::string &message)
  {
    try
      {
        results = testing::run_contact(prm, MPI_COMM_WORLD);
        return true;
      }
    catch (const std::exception &e)
      {
        message = testing::collapse_white_space(e.what());
        return false;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool parallel = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;
  const std::vector<std::string> solvers =
    parallel ? std::vector<std::string>{"direct constraints", "CG-AMG"} :
               std::vector<std::string>{"UMFPACK", "KLU", "GMRES-AMG", "CG-AMG", "direct constraints"};
  for (const auto &solver : solvers)
    {
      const std::string                tag = solver + (parallel ? " (np 2)" : "");
      dealvem::ContactProblem::Results r;
      std::string                      message;
      const bool                       ok = run(stack_prm(1., 1., solver), r, message);
      testing::check(ok, tag + ", ratio 1: runs" + (ok ? "" : ": " + message));
      if (!ok)
        continue;
      testing::check_small(r.total_contact_force[0], 1e-10, tag + ", ratio 1: contact force x");
      testing::check_near(r.total_contact_force[1], 10., 1e-9, tag + ", ratio 1: contact force y");
      testing::check(r.steps.size() == 1 && r.steps[0].balance.size() == 2, tag + ": balance of both bodies recorded");
      const bool   direct = (solver == "UMFPACK" || solver == "KLU" || solver == "direct constraints");
      const double bound  = direct ? 1e-11 : 1e-8;
      for (const auto &b : r.steps[0].balance)
        {
          testing::check_small(b.imbalance, bound, tag + ", body " + std::to_string(b.body) + ": relative imbalance");
          testing::check_small(b.residual, bound, tag + ", body " + std::to_string(b.body) + ": relative residual");
          std::ostringstream t;
          t << tag << ", body " << b.body << ": within the tolerance " << b.tolerance << " (condition "
            << b.condition << ")";
          testing::check(b.imbalance <= b.tolerance && b.residual <= b.tolerance, t.str());
        }
    }

  // large stiffness ratios: correct or refused, never a wrong answer
  for (const bool stiff_on_soft : {false, true})
  for (const double ratio : {1e9, 1e12})
    for (const std::string &solver : parallel ? std::vector<std::string>{"direct constraints"} :
                                               std::vector<std::string>{"UMFPACK", "KLU", "direct constraints"})
      {
        std::ostringstream tag;
        tag << solver << (parallel ? " (np 2)" : "") << ", ratio " << ratio
            << (stiff_on_soft ? ", stiff block on the soft one" : ", soft block on the stiff one");
        dealvem::ContactProblem::Results r;
        std::string                      message;
        const bool                       ok =
          run(stiff_on_soft ? stack_prm(1., ratio, solver) : stack_prm(ratio, 1., solver), r, message);
        const bool refused = !ok && (message.find("Verification failed") != std::string::npos ||
                                     message.find("is inaccurate") != std::string::npos);
        if (ok)
          {
            const double fx = r.total_contact_force[0], fy = r.total_contact_force[1];
            std::ostringstream s;
            s << tag.str() << ": computed, contact force (" << fx << ", " << fy << ") within 1e-6 of (0, 10)";
            testing::check(std::abs(fx) <= 1e-5 && std::abs(fy - 10) <= 1e-5, s.str());
          }
        else
          testing::check(refused, tag.str() + ": refused by the verification: " + message.substr(0, 300));
      }
  return testing::n_failures() == 0 ? 0 : 1;
}
