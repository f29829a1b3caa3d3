// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Contact tests run ContactProblem from parameter strings.
#ifndef dealvem_tests_contact_common_h
#define dealvem_tests_contact_common_h

#include <deal.II/base/parameter_handler.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/app/elasticity_problem.h>

#include <string>

namespace testing
{
  /// Parse @p prm_text (after the declarations of the program) and run.
  /// By default the serial path on each process (MPI_COMM_SELF), so that
  /// a test run under mpirun computes its reference on every process.
  inline dealvem::ContactProblem::Results
  run_contact(const std::string                          &prm_text,
              const MPI_Comm                              comm        = MPI_COMM_SELF,
              const dealvem::ElasticityProblem::Parallelism parallelism =
                dealvem::ElasticityProblem::Parallelism::automatic)
  {
    dealii::ParameterHandler prm;
    dealvem::ElasticityProblem::declare_parameters(prm);
    dealvem::ContactProblem::declare_parameters(prm);
    prm.parse_input_from_string(prm_text);
    dealvem::ContactProblem problem(comm, parallelism);
    problem.parse_parameters(prm);
    problem.run();
    return problem.get_results();
  }

  /// A mesh section for a block [x0,x1] x [y0,y1].
  inline std::string
  block_mesh(const std::string &type, const double x0, const double y0, const double x1,
             const double y1, const unsigned int nx, const unsigned int ny,
             const unsigned int offset, const unsigned int seed = 1, const double tilt = 0)
  {
    std::ostringstream s;
    s << "subsection Mesh\n  set Type = " << type << "\n  set Lower left corner = " << x0 << ", "
      << y0 << "\n  set Upper right corner = " << x1 << ", " << y1 << "\n  set Subdivisions = " << nx
      << ", " << ny << "\n  set Number of cells = " << nx * ny << "\n  set Seed = " << seed
      << "\n  set Boundary id offset = " << offset;
    if (tilt != 0) // raise the block linearly in x: its bottom slopes by tilt
      s << "\n  set Transformation = x, y + " << tilt << "*x";
    s << "\nend\n";
    return s.str();
  }
} // namespace testing

#endif
