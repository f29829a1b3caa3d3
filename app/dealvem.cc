// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The parameter-file program:
//   dealvem input.prm            solve the problem described in input.prm:
//                                one body (elasticity, optional convergence
//                                study) or several bodies in contact
//   dealvem --print-parameters   print every parameter with its default
//                                value and documentation
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/app/elasticity_problem.h>

#include <filesystem>
#include <iostream>

int
main(int argc, char **argv)
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      dealii::ParameterHandler                 prm;
      dealvem::ElasticityProblem::declare_parameters(prm);
      dealvem::ContactProblem::declare_parameters(prm);

      const std::string arg = (argc > 1 ? argv[1] : "");
      if (argc != 2 || arg == "-h" || arg == "--help")
        {
          std::cerr << "Usage: dealvem input.prm\n"
                       "       dealvem --print-parameters\n";
          return argc == 2 ? 0 : 1;
        }
      if (arg == "--print-parameters")
        {
          prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
          return 0;
        }
      if (!std::filesystem::exists(arg))
        {
          std::cerr << "dealvem: cannot open parameter file '" << arg << "'." << std::endl;
          return 1;
        }
      prm.parse_input(arg);
      const std::string directory = std::filesystem::path(arg).parent_path().string();
      if (dealvem::ContactProblem::n_bodies(prm) > 1)
        {
          dealvem::ContactProblem problem;
          problem.parse_parameters(prm, directory);
          problem.run();
        }
      else
        {
          dealvem::ElasticityProblem problem;
          problem.parse_parameters(prm, directory);
          problem.run();
        }
    }
  catch (std::exception &exc)
    {
      std::cerr << std::endl
                << "----------------------------------------------------" << std::endl
                << "dealvem: error:" << std::endl
                << exc.what() << std::endl
                << "----------------------------------------------------" << std::endl;
      return 1;
    }
  catch (...)
    {
      std::cerr << "dealvem: unknown exception." << std::endl;
      return 1;
    }
  return 0;
}
