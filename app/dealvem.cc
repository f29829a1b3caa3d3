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
//   mpirun -np N dealvem input.prm
//                                one body: the distributed path (METIS
//                                partition, Trilinos matrices, .pvtu);
//                                contact problems run on one process so far
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/app/elasticity_problem.h>
#include <dealvem/app/input_parsing.h>
#include <dealvem/base/run_files.h>

#include <muParserError.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <system_error>
#include <typeinfo>
#include <vector>

namespace
{
  namespace fs = std::filesystem;

  std::string
  trim(const std::string &s)
  {
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos)
      return "";
    const auto e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
  }

  /**
   * Follow the 'include' directives of the parameter file @p file the way
   * deal.II's ParameterHandler reads them (comments after '#' removed,
   * lines ending in '\' joined, "include name" or "INCLUDE name" at the
   * start of a line, the name taken relative to the working directory),
   * before ParameterHandler sees the file: a file that includes itself,
   * directly or through others, would recurse until the stack overflows.
   * @p stack holds the canonical paths of the files being read; throws
   * naming the cycle, or an include file that cannot be opened.
   */
  void
  check_includes(const std::string &file, std::vector<std::string> &stack)
  {
    std::error_code ec;
    const fs::path  canonical = fs::weakly_canonical(fs::absolute(file), ec);
    const std::string key     = ec ? file : canonical.string();
    for (unsigned int i = 0; i < stack.size(); ++i)
      if (stack[i] == key)
        {
          std::string cycle;
          for (unsigned int j = i; j < stack.size(); ++j)
            cycle += "'" + stack[j] + "' includes ";
          AssertThrow(false, dealii::ExcMessage("The parameter files include each other in a cycle: " +
                                                cycle + "'" + key +
                                                "' again. Remove one of these 'include' lines."));
        }
    AssertThrow(stack.size() < 100,
                dealii::ExcMessage("The 'include' directives of the parameter files nest more than 100 "
                                   "deep (at '" + key + "')."));
    std::ifstream in(file);
    AssertThrow(in, dealii::ExcMessage("Cannot open the parameter file '" + file + "'."));
    stack.push_back(key);
    std::string  line, joined;
    unsigned int line_number = 0, first_line = 1;
    while (std::getline(in, line))
      {
        ++line_number;
        if (joined.empty())
          first_line = line_number;
        // comments: '#' not escaped as '\#'
        for (std::size_t p = line.find('#'); p != std::string::npos; p = line.find('#', p + 1))
          if (p == 0 || line[p - 1] != '\\')
            {
              line.erase(p);
              break;
            }
        const std::string t = trim(line);
        if (!t.empty() && t.back() == '\\')
          {
            joined += t.substr(0, t.size() - 1);
            continue;
          }
        joined += t;
        const std::string statement = trim(joined);
        joined.clear();
        if (statement.compare(0, 8, "include ") == 0 || statement.compare(0, 8, "INCLUDE ") == 0)
          {
            const std::string name = trim(statement.substr(8));
            AssertThrow(!name.empty() && fs::is_regular_file(name, ec),
                        dealii::ExcMessage("Parameter file '" + file + "', line " +
                                           std::to_string(first_line) + ": cannot open the included file '" +
                                           name +
                                           "' (include file names are relative to the working directory)."));
            check_includes(name, stack);
          }
      }
    stack.pop_back();
  }

  void
  print_error(const std::string &text)
  {
    // with several MPI processes every process that fails reports, naming
    // itself (a failure on one process only would otherwise go unexplained)
    int initialized = 0, finalized = 0, rank = 0, size = 1;
    MPI_Initialized(&initialized);
    MPI_Finalized(&finalized);
    if (initialized && !finalized)
      {
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        MPI_Comm_size(MPI_COMM_WORLD, &size);
      }
    // one write, so that the reports of several processes do not interleave
    std::ostringstream message;
    message << std::endl
            << "----------------------------------------------------" << std::endl
            << "dealvem: error"
            << (size > 1 ? " (MPI process " + std::to_string(rank) + " of " + std::to_string(size) + ")" : "")
            << ":" << std::endl
            << text << std::endl
            << "----------------------------------------------------" << std::endl;
    // which output files the failed run wrote (process 0 keeps the list)
    if (!dealvem::RunFiles::last_failure_report().empty())
      message << dealvem::RunFiles::last_failure_report() << std::endl;
    std::cerr << message.str() << std::flush;
  }

  // The exit after an error. With several MPI processes the others may be
  // waiting in a collective call for the one that failed, so the whole job is
  // aborted (after the message was written) instead of hanging; with one
  // process the program returns 1.
  int
  failure_exit()
  {
    std::cout.flush();
    std::cerr.flush();
    if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
} // namespace

int
main(int argc, char **argv)
{
  // outside the try block, so that MPI is still up while an error is
  // reported (and finalised after it)
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const std::string arg = (argc > 1 ? argv[1] : "");
      // as many body sections as the file uses (a plain scan of its lines;
      // an unreadable file is reported below)
      std::error_code          ec0;
      const bool               readable = (argc == 2 && fs::is_regular_file(arg, ec0));
      dealii::ParameterHandler prm;
      dealvem::ElasticityProblem::declare_parameters(prm);
      dealvem::ContactProblem::declare_parameters(
        prm, readable ? dealvem::ContactProblem::body_sections(arg) : dealvem::ContactProblem::default_body_sections);

      if (argc != 2 || arg == "-h" || arg == "--help")
        {
          std::cerr << "Usage: dealvem input.prm\n"
                       "       dealvem --print-parameters\n";
          return argc == 2 ? 0 : 1;
        }
      if (arg == "--print-parameters")
        {
          prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
          std::cout.flush();
          AssertThrow(std::cout, dealii::ExcMessage("Cannot write the parameters to the standard output."));
          return 0;
        }
      std::error_code ec;
      if (!fs::exists(arg, ec))
        {
          std::cerr << "dealvem: cannot open parameter file '" << arg << "'." << std::endl;
          return 1;
        }
      if (fs::is_directory(arg, ec))
        {
          std::cerr << "dealvem: cannot open parameter file '" << arg << "': it is a directory."
                    << std::endl;
          return 1;
        }
      {
        std::vector<std::string> stack;
        check_includes(arg, stack);
      }
      prm.parse_input(arg);
      // values with '{' passed ParameterHandler unchecked
      dealvem::InputParsing::check_braced_values(prm);
      const std::string directory = fs::path(arg).parent_path().string();
      if (dealvem::ContactProblem::is_contact_problem(prm))
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
      std::cout.flush();
    }
  catch (const std::exception &exc)
    {
      // std::exception and dealii::ExceptionBase (derived from it)
      print_error(exc.what());
      return failure_exit();
    }
  catch (const mu::ParserError &exc)
    {
      print_error("error of the expression parser (muparser): " + exc.GetMsg() +
                  (exc.GetExpr().empty() ? std::string() : " in the expression '" + exc.GetExpr() + "'"));
      return failure_exit();
    }
  catch (const std::string &text)
    {
      print_error(text);
      return failure_exit();
    }
  catch (const char *text)
    {
      print_error(text != nullptr ? text : "(no message)");
      return failure_exit();
    }
  catch (...)
    {
      print_error("the program stopped on an exception of a type it does not know, so there is no "
                  "message; this is a bug of dealvem, please report it with the parameter file.");
      return failure_exit();
    }
  return 0;
}
