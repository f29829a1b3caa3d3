// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <dealvem/app/input_parsing.h>
#include <dealvem/mesh/mesh_io.h>
#include <dealvem/app/mesh_parameters.h>
#include <dealvem/solvers/p_multigrid.h>
#include <dealvem/vem/vem_element_data.h>

#include <muParserError.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <filesystem>
#include <cmath>
#include <cstdlib>

#include <sys/resource.h>
#include <unistd.h>
#include <exception>
#include <iomanip>
#include <sstream>

namespace dealvem
{
  namespace InputParsing
  {
    Stabilization
    parse_stabilization(const std::string &name)
    {
      return (name == "trace"    ? Stabilization::trace :
              name == "diagonal" ? Stabilization::diagonal :
              name == "boundary" ? Stabilization::boundary :
                                   Stabilization::automatic);
    }



    void
    check_number_of_load_steps(const long steps)
    {
      AssertThrow(steps >= 1 && steps <= long(max_load_steps),
                  dealii::ExcMessage("Parameter 'Load steps/Number of steps' is " + std::to_string(steps) +
                                     ": it must be at least 1 (and at most 100000)."));
    }



    std::string
    trim(const std::string &s)
    {
      const auto b = s.find_first_not_of(" \t\r\n");
      if (b == std::string::npos)
        return "";
      const auto e = s.find_last_not_of(" \t\r\n");
      return s.substr(b, e - b + 1);
    }



    std::vector<std::string>
    split(const std::string &s, const char sep, const bool keep_empty)
    {
      std::vector<std::string> out;
      int                      depth = 0;
      std::string              current;
      for (const char ch : s)
        {
          if (ch == '(')
            ++depth;
          else if (ch == ')')
            --depth;
          if (ch == sep && depth == 0)
            {
              const std::string t = trim(current);
              if (keep_empty || !t.empty())
                out.push_back(t);
              current.clear();
            }
          else
            current += ch;
        }
      const std::string t = trim(current);
      if (keep_empty || !t.empty())
        out.push_back(t);
      return out;
    }



    double
    parse_double(const std::string &s, const std::string &parameter)
    {
      const std::string t = trim(s);
      std::size_t       pos = 0;
      double            v   = 0;
      bool              ok  = !t.empty();
      try
        {
          v = std::stod(t, &pos);
        }
      catch (...)
        {
          ok = false;
        }
      AssertThrow(ok && pos == t.size() && std::isfinite(v),
                  dealii::ExcMessage("Parameter '" + parameter + "': '" + t +
                                     "' is not a finite real number."));
      return v;
    }



    unsigned int
    parse_unsigned(const std::string &s, const std::string &parameter)
    {
      const std::string t = trim(s);
      bool              ok = !t.empty() && t.find_first_not_of("0123456789") == std::string::npos &&
              t.size() < 10;
      AssertThrow(ok,
                  dealii::ExcMessage("Parameter '" + parameter + "': '" + t +
                                     "' is not a non-negative integer."));
      return std::stoul(t);
    }



    void
    check_range(const double       value,
                const double       lower,
                const double       upper,
                const std::string &parameter,
                const bool         lower_open,
                const bool         upper_open,
                const std::string &reason)
    {
      const bool ok = std::isfinite(value) && (lower_open ? value > lower : value >= lower) &&
                      (upper_open ? value < upper : value <= upper);
      if (ok)
        return;
      std::ostringstream msg;
      msg << "Parameter '" << parameter << "' = " << value << " is out of range: it must lie in "
          << (lower_open ? "(" : "[") << lower << ", " << upper << (upper_open ? ")" : "]") << ".";
      if (!reason.empty())
        msg << " " << reason;
      AssertThrow(false, dealii::ExcMessage(msg.str()));
    }



    void
    check_constant_names(const std::map<std::string, double> &constants, const std::string &parameter)
    {
      // the variables, and the functions and constants of muparser and of
      // deal.II's FunctionParser
      static const std::vector<std::string> reserved = {
        "x",     "y",     "t",     "sin",  "cos",  "tan",   "asin",  "acos",  "atan", "sinh",
        "cosh",  "tanh",  "asinh", "acosh", "atanh", "log2", "log10", "log",   "ln",   "exp",
        "sqrt",  "sign",  "rint",  "abs",  "min",  "max",   "sum",   "avg",   "ceil", "cot",
        "csc",   "floor", "sec",   "pow",  "erfc", "rand",  "rand_seed", "atan2", "fmod", "int",
        "_pi",   "_e",    "pi",    "Pi"};
      for (const auto &c : constants)
        {
          const std::string &name = c.first;
          const bool valid = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                             std::all_of(name.begin(), name.end(), [](const char ch) {
                               return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
                             });
          AssertThrow(valid,
                      dealii::ExcMessage("Parameter '" + parameter + "': '" + name +
                                         "' is not a valid constant name (a letter or '_' followed by "
                                         "letters, digits or '_')."));
          AssertThrow(std::find(reserved.begin(), reserved.end(), name) == reserved.end(),
                      dealii::ExcMessage("Parameter '" + parameter + "': the name '" + name +
                                         "' is reserved (" +
                                         (name == "x" || name == "y" || name == "t" ?
                                            std::string("a variable of the expressions") :
                                            std::string("a function or constant of the expression parser")) +
                                         "); choose another name for this constant."));
        }
      // whatever else the parser does not accept
      std::string error;
      try
        {
          dealii::FunctionParser<2> parser(1);
          parser.initialize("x,y,t", "0", constants, true);
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
      catch (const mu::ParserError &e)
        {
          error = e.GetMsg();
        }
      catch (...)
        {
          error = "the expression parser rejected them";
        }
      AssertThrow(error.empty(), dealii::ExcMessage("Parameter '" + parameter +
                                                    "': the constants are not accepted: " + error));
    }



    std::map<std::string, double>
    parse_constants(const std::string &s, const std::string &parameter)
    {
      std::map<std::string, double> c;
      for (const auto &entry : split(s, ','))
        {
          const auto kv = split(entry, '=', true);
          AssertThrow(kv.size() == 2 && !kv[0].empty(),
                      dealii::ExcMessage("Parameter '" + parameter + "': expected name=value, got '" +
                                         entry + "'."));
          AssertThrow(c.count(kv[0]) == 0,
                      dealii::ExcMessage("Parameter '" + parameter + "': the constant '" + kv[0] +
                                         "' is defined twice."));
          c[kv[0]] = parse_double(kv[1], parameter + " (" + kv[0] + ")");
        }
      check_constant_names(c, parameter);
      return c;
    }



    bool
    uses_variable(const std::string &expression, const std::string &variable)
    {
      const auto is_start = [](const char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
      const auto is_name  = [](const char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
      const auto is_digit = [](const char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
      std::size_t i = 0;
      while (i < expression.size())
        {
          const char c = expression[i];
          if (is_digit(c) || (c == '.' && i + 1 < expression.size() && is_digit(expression[i + 1])))
            {
              // a number, with its exponent
              while (i < expression.size() && (is_digit(expression[i]) || expression[i] == '.'))
                ++i;
              if (i < expression.size() && (expression[i] == 'e' || expression[i] == 'E'))
                {
                  std::size_t j = i + 1;
                  if (j < expression.size() && (expression[j] == '+' || expression[j] == '-'))
                    ++j;
                  if (j < expression.size() && is_digit(expression[j]))
                    {
                      i = j;
                      while (i < expression.size() && is_digit(expression[i]))
                        ++i;
                    }
                }
            }
          else if (is_start(c))
            {
              const std::size_t b = i;
              while (i < expression.size() && is_name(expression[i]))
                ++i;
              if (expression.compare(b, i - b, variable) == 0 && i - b == variable.size())
                return true;
            }
          else
            ++i;
        }
      return false;
    }



    RunSizeEstimate
    estimate_run_size(const std::vector<const MeshParameters *> &meshes,
                      const unsigned int                        n_cycles,
                      const unsigned int                        degree,
                      const std::string                        &base_directory)
    {
      RunSizeEstimate e;
      for (const MeshParameters *m : meshes)
        for (unsigned int cycle = 0; cycle < std::max(n_cycles, 1u); ++cycle)
          {
            const bool   last = (cycle + 1 == std::max(n_cycles, 1u));
            const double f    = std::ldexp(1., int(cycle));
            const double nx = double(m->nx) * f, ny = double(m->ny) * f;
            double       cells = 0, vertices = 0, edges = 0;
            if (m->type == "structured quads" || m->type == "perturbed quads")
              {
                cells    = nx * ny;
                vertices = (nx + 1) * (ny + 1);
                edges    = 2 * nx * ny + nx + ny;
              }
            else if (m->type == "structured triangles")
              {
                cells    = 2 * nx * ny;
                vertices = (nx + 1) * (ny + 1);
                edges    = 3 * nx * ny + nx + ny;
              }
            else if (m->type == "nonconvex")
              {
                // a polygon per subdivision, with an extra (reflex) vertex
                cells    = nx * ny;
                vertices = 2 * (nx + 1) * (ny + 1);
                edges    = 3 * nx * ny + 2 * (nx + ny);
              }
            else if (m->type == "voronoi")
              {
                // a centroidal Voronoi mesh has about 2 vertices and 3 edges per cell
                cells    = double(m->n_cells) * f * f;
                vertices = 2 * cells + 4;
                edges    = 3 * cells + 4;
                e.lloyd_work += (double(m->lloyd_iterations) + 1) * cells;
                e.lloyd_iterations = std::max(e.lloyd_iterations, double(m->lloyd_iterations));
                if (last)
                  e.voronoi_cells += cells;
              }
            else
              {
                // a mesh file: the counts of its header (per cycle with
                // '{cycle}' in the name, else refined 'cycle' times)
                std::string path     = m->file_name;
                const auto  at       = path.find("{cycle}");
                const bool  per_file = (at != std::string::npos);
                if (per_file)
                  path.replace(at, 7, std::to_string(cycle));
                else if (cycle > 0 && m->type == "vtk file")
                  break; // refused by the reader (a VTK mesh is not refined)
                if (!path.empty() && path[0] != '/' && !base_directory.empty())
                  path = base_directory + "/" + path;
                const std::string ext    = std::filesystem::path(path).extension().string();
                const std::string format = m->type == "vtk file" ? "vtk" : (ext.empty() || ext == ".msh") ? "msh" : "";
                std::error_code   ec;
                MeshIO::FileCounts counts;
                if (!format.empty() && std::filesystem::is_regular_file(path, ec))
                  counts = MeshIO::count_entities(path, format);
                if (!counts.valid)
                  {
                    e.complete = false;
                    continue;
                  }
                const double r = per_file ? 1. : std::ldexp(1., 2 * int(cycle));
                vertices       = double(counts.n_vertices) * r;
                // without a cell count, one cell per vertex (quadrangles)
                cells = (counts.n_cells > 0 ? double(counts.n_cells) : double(counts.n_vertices)) * r;
                edges = vertices + cells;
                if (last)
                  {
                    std::ostringstream f;
                    f << (e.files.empty() ? "" : ", ") << "'" << path << "' (line " << counts.line << ": "
                      << counts.n_vertices << (format == "vtk" ? " points" : " nodes");
                    if (counts.n_cells > 0)
                      f << ", " << counts.n_cells << (format == "vtk" ? " cells" : " elements");
                    if (!per_file && cycle > 0)
                      f << "; refined " << cycle << " times";
                    f << ")";
                    e.files += f.str();
                  }
              }
            if (last)
              {
                e.cells += cells;
                // two DoFs per node, the nodes as the element's layout
                // places them on the vertices, edges and cells
                const VEMElementData layout(degree);
                e.dofs += 2 * vertices * layout.nodes_per_vertex() +
                          (2 * edges * layout.nodes_per_edge() + 2 * cells * layout.nodes_per_cell());
              }
          }
      return e;
    }



    double
    estimated_memory(const double n_dofs, const unsigned int degree, const bool direct)
    {
      // bytes per DoF of everything but the solver (mesh, DoF handler,
      // matrix, vectors, stresses, output): k = 1 rows hold fewer entries
      const double base = (degree >= 2 ? base_bytes_per_dof_k2 : base_bytes_per_dof_k1);
      if (!direct)
        return (base + iterative_bytes_per_dof) * n_dofs + fixed_bytes;
      // the factors of a 2D problem grow like n log n
      return base * n_dofs + direct_bytes_per_dof_log * n_dofs * std::log2(std::max(n_dofs, 2.)) + fixed_bytes;
    }



    double
    memory_limit(const double limit_GB, std::string &source)
    {
      if (limit_GB > 0)
        {
          source = "the parameter 'Memory limit'";
          return limit_GB * 1e9;
        }
      double      bytes = 0;
      std::string what;
      const long  pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
      if (pages > 0 && page > 0)
        {
          bytes = double(pages) * double(page);
          what  = "the physical memory of this machine";
        }
      for (const int resource : {RLIMIT_AS, RLIMIT_DATA})
        {
          struct rlimit l;
          if (::getrlimit(resource, &l) == 0 && l.rlim_cur != RLIM_INFINITY &&
              (bytes == 0 || double(l.rlim_cur) < bytes))
            {
              bytes = double(l.rlim_cur);
              what  = resource == RLIMIT_AS ? "the process limit 'ulimit -v'" : "the process limit 'ulimit -d'";
            }
        }
      for (const char *cgroup : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"})
        {
          std::ifstream in(cgroup);
          double        v = 0;
          if (in >> v && v > 0 && (bytes == 0 || v < bytes))
            {
              bytes = v;
              what  = "the memory limit of the control group (container)";
            }
        }
      if (bytes == 0)
        {
          source = "a default of 8 GB (the memory of this machine is not known)";
          return 8e9;
        }
      source = "80 % of " + what;
      return 0.8 * bytes;
    }



    bool
    automatic_solver_is_direct(const double n_dofs, const unsigned int degree, const double limit_bytes,
                               std::string &reason)
    {
      std::ostringstream r;
      r << std::setprecision(3);
      if (n_dofs > direct_solver_max_dofs)
        {
          r << n_dofs << " DoFs > " << direct_solver_max_dofs
            << ": above this size CG with "
            << (PMultigrid::applies_to(VEMElementData(degree)) ? "the p-multigrid" : "AMG")
            << " is faster than a direct factorization (measured crossover, doc/benchmarks.md)";
          reason = r.str();
          return false;
        }
      const double direct = estimated_memory(n_dofs, degree, true);
      if (direct > limit_bytes)
        {
          r << "the direct factorization would need about " << direct / 1e9 << " GB, more than the limit of "
            << limit_bytes / 1e9 << " GB";
          reason = r.str();
          return false;
        }
      r << n_dofs << " DoFs <= " << direct_solver_max_dofs
        << ": a direct factorization is as fast as CG or faster at this size (measured crossover, "
           "doc/benchmarks.md)";
      reason = r.str();
      return true;
    }



    RunSizeEstimate
    check_run_size(const std::vector<const MeshParameters *> &meshes,
                   const unsigned int                        n_cycles,
                   const unsigned int                        degree,
                   const bool                                allow_large_runs,
                   const std::string                        &base_directory,
                   const SolverKind                          solver,
                   const double                              memory_limit_GB)
    {
      const RunSizeEstimate e = estimate_run_size(meshes, n_cycles, degree, base_directory);
      std::ostringstream    estimate;
      estimate << std::setprecision(3);
      if (!e.files.empty())
        estimate << "mesh file(s) " << e.files << "; ";
      estimate << "the estimate for the last of the " << n_cycles
               << " refinement cycle(s) is " << e.cells << " cells and " << e.dofs << " DoFs";
      if (e.voronoi_cells > 0)
        estimate << ", " << e.voronoi_cells << " Voronoi cells, " << e.lloyd_iterations
                 << " Lloyd iterations (Lloyd iterations x cells summed over the cycles: "
                 << e.lloyd_work << ")";
      AssertThrow(e.cells <= max_representable_cells,
                  dealii::ExcMessage("The mesh parameters ('Mesh/Subdivisions', 'Mesh/Number of cells', "
                                     "'Convergence study/Refinement cycles') ask for more cells than the "
                                     "program can represent: " +
                                     estimate.str() + "."));
      if (allow_large_runs)
        return e;
      std::string what;
      std::ostringstream limit;
      limit << std::setprecision(3);
      if (e.dofs > max_dofs)
        limit << " more than " << max_dofs << " DoFs;";
      if (e.voronoi_cells > max_voronoi_cells)
        limit << " more than " << max_voronoi_cells << " Voronoi cells;";
      if (e.lloyd_iterations > max_lloyd_iterations)
        limit << " more than " << max_lloyd_iterations << " Lloyd iterations;";
      if (e.lloyd_work > max_lloyd_work)
        limit << " Lloyd iterations x cells above " << max_lloyd_work << ";";
      // the memory with the solver the run will use
      std::string  limit_source;
      const double limit_bytes = memory_limit(memory_limit_GB, limit_source);
      std::string  reason;
      const bool   direct = solver == SolverKind::direct ||
                          (solver == SolverKind::automatic && automatic_solver_is_direct(e.dofs, degree, limit_bytes, reason));
      const double memory = estimated_memory(e.dofs, degree, direct);
      std::string  solver_hint;
      if (memory > limit_bytes)
        {
          limit << " about " << memory / 1e9 << " GB of memory with "
                << (direct ? "a direct factorization ('Solver/Type' = UMFPACK or KLU)" :
                             "CG and AMG or the p-multigrid")
                << ", more than the limit of " << limit_bytes / 1e9 << " GB (" << limit_source << ");";
          const double iterative = estimated_memory(e.dofs, degree, false);
          if (direct && iterative <= limit_bytes)
            {
              std::ostringstream h;
              h << std::setprecision(3) << " An iterative solver would need about " << iterative / 1e9
                << " GB: set 'Solver/Type = automatic' or 'CG-AMG'.";
              solver_hint = h.str();
            }
        }
      what = limit.str();
      AssertThrow(what.empty(),
                  dealii::ExcMessage("This run is very large:" + what + " " + estimate.str() +
                                     ". It would take very long or run out of memory." + solver_hint +
                                     " Reduce 'Mesh/Subdivisions', 'Mesh/Number of cells', 'Mesh/Lloyd "
                                     "iterations', the mesh file or 'Convergence study/Refinement cycles', "
                                     "set 'Memory limit' (in GB) if the run may use more memory, or set "
                                     "'Allow large runs = true' (top level of the parameter file) to go "
                                     "ahead anyway."));
      return e;
    }



    namespace
    {
      // the number of components, refusing an empty list before the base
      // class sees it (a Function needs at least one component)
      unsigned int
      n_expressions(const std::vector<std::string> &expressions, const std::string &parameter)
      {
        AssertThrow(!expressions.empty(),
                    dealii::ExcMessage("Parameter '" + parameter + "': no expression given."));
        return expressions.size();
      }

      // the message of whatever the parser threw
      std::string
      parser_error(const std::exception_ptr &e)
      {
        try
          {
            std::rethrow_exception(e);
          }
        catch (const std::exception &x)
          {
            return x.what();
          }
        catch (const mu::ParserError &x)
          {
            return x.GetMsg();
          }
        catch (...)
          {
          }
        return "the expression parser failed";
      }
    } // namespace



    ParsedFunction::ParsedFunction(const std::vector<std::string>      &expressions,
                                   const std::map<std::string, double> &constants,
                                   const std::string                   &parameter)
      : dealii::Functions::ParsedFunction<2>(n_expressions(expressions, parameter), 1e-5)
      , expressions(expressions)
      , parameter(parameter)
    {
      set_formula(FourthOrder);
      std::string joined, constant_list;
      for (const auto &x : expressions)
        joined += (joined.empty() ? "" : ", ") + x;
      // the values as the parser reads them back: 17 significant digits
      // give every double exactly
      std::ostringstream c;
      c << std::setprecision(17);
      for (const auto &[name, v] : constants)
        c << (c.tellp() > 0 ? ", " : "") << name << '=' << v;
      std::exception_ptr error;
      try
        {
          // the section Functions::ParsedFunction reads; its variable names
          // default to "x,y,t", which makes t the time of the parser
          dealii::ParameterHandler prm;
          declare_parameters(prm, expressions.size());
          std::string expression_list;
          for (const auto &x : expressions)
            expression_list += (expression_list.empty() ? "" : "; ") + x;
          prm.set("Function expression", expression_list);
          prm.set("Function constants", c.str());
          parse_parameters(prm);
          set_time(1.0);
          // evaluate once (the value itself is not checked) so that unknown
          // names are reported here rather than in the middle of assembly
          dealii::Vector<double> v(expressions.size());
          dealii::Functions::ParsedFunction<2>::vector_value(dealii::Point<2>(0.123, 0.456), v);
        }
      catch (...)
        {
          error = std::current_exception();
        }
      AssertThrow(!error, dealii::ExcMessage("Parameter '" + parameter + "': cannot parse the expression(s) '" +
                                             joined + "': " + (error ? parser_error(error) : std::string())));
    }



    void
    ParsedFunction::report(const dealii::Point<2> &p,
                           const unsigned int      component,
                           const std::string      &what) const
    {
      std::ostringstream msg;
      msg << "Parameter '" << parameter << "': the expression '"
          << (component < expressions.size() ? expressions[component] : std::string("?")) << "' "
          << what << " at the point (" << p[0] << ", " << p[1] << "), t = " << get_time() << ".";
      AssertThrow(false, dealii::ExcMessage(msg.str()));
      std::abort(); // not reached
    }



    double
    ParsedFunction::value(const dealii::Point<2> &p, const unsigned int component) const
    {
      double v = 0;
      try
        {
          v = dealii::Functions::ParsedFunction<2>::value(p, component);
        }
      catch (...)
        {
          report(p, component, "cannot be evaluated (" + parser_error(std::current_exception()) + ")");
        }
      if (!std::isfinite(v))
        report(p, component,
               std::string("evaluates to ") + (std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf")));
      return v;
    }



    void
    ParsedFunction::vector_value(const dealii::Point<2> &p, dealii::Vector<double> &values) const
    {
      AssertThrow(values.size() == n_components,
                  dealii::ExcMessage("Parameter '" + parameter + "': " + std::to_string(n_components) +
                                     " expressions, but " + std::to_string(values.size()) +
                                     " values requested."));
      for (unsigned int c = 0; c < n_components; ++c)
        values[c] = value(p, c);
    }



    namespace
    {
      // ParameterHandler writes every character of a section or entry name
      // other than a letter or digit as '_' and two hexadecimal digits
      std::string
      demangle(const std::string &s)
      {
        std::string out;
        for (std::size_t i = 0; i < s.size(); ++i)
          if (s[i] == '_' && i + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
              std::isxdigit(static_cast<unsigned char>(s[i + 2])))
            {
              out += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
              i += 2;
            }
          else
            out += s[i];
        return out;
      }

      void
      collect_entries(const boost::property_tree::ptree &tree, const std::string &prefix, std::vector<Entry> &out)
      {
        for (const auto &child : tree)
          {
            const std::string name = demangle(child.first);
            const auto        value = child.second.get_optional<std::string>("value");
            if (value)
              out.push_back(Entry{prefix + name, *value, child.second.get<std::string>("default_value", ""),
                                  trim(child.second.get<std::string>("pattern_description", ""))});
            else if (!child.second.empty())
              collect_entries(child.second, prefix + name + "/", out);
          }
      }
    } // namespace



    std::vector<Entry>
    list_entries(const dealii::ParameterHandler &prm)
    {
      std::stringstream xml;
      prm.print_parameters(xml, dealii::ParameterHandler::XML);
      boost::property_tree::ptree tree;
      boost::property_tree::read_xml(xml, tree);
      std::vector<Entry> out;
      const auto         root = tree.get_child_optional("ParameterHandler");
      AssertThrow(root, dealii::ExcMessage("InputParsing::list_entries: the XML description of the "
                                           "parameters has no element 'ParameterHandler'."));
      collect_entries(*root, "", out);
      return out;
    }



    void
    check_braced_values(const dealii::ParameterHandler &prm)
    {
      for (const auto &e : list_entries(prm))
        {
          if (e.value.find('{') == std::string::npos)
            continue;
          const auto pattern = dealii::Patterns::pattern_factory(e.pattern);
          // a pattern that cannot be rebuilt from its description is left
          // alone (dealvem declares none)
          if (pattern == nullptr || pattern->match(e.value))
            continue;
          AssertThrow(false,
                      dealii::ExcMessage("Parameter '" + e.path + "' = '" + e.value + "' does not match its pattern " +
                                         e.pattern +
                                         ". (The parameter reader leaves values that contain '{' unchecked; "
                                         "dealvem takes them literally, so write the value without braces.)"));
        }
    }



    std::vector<std::string>
    changed_entries(const dealii::ParameterHandler &prm, const std::string &section)
    {
      std::vector<std::string> out;
      const std::string        prefix = section.empty() ? std::string() : section + "/";
      for (const auto &e : list_entries(prm))
        if (e.path.compare(0, prefix.size(), prefix) == 0 && trim(e.value) != trim(e.default_value))
          out.push_back(e.path);
      return out;
    }



    void
    check_section_unused(const dealii::ParameterHandler &prm,
                         const std::string              &section,
                         const std::string              &reason)
    {
      const auto changed = changed_entries(prm, section);
      if (changed.empty())
        return;
      std::ostringstream msg;
      msg << "The parameter file sets '" << changed[0] << "'";
      if (changed.size() > 1)
        msg << " (and " << changed.size() - 1 << " more entr" << (changed.size() > 2 ? "ies" : "y")
            << " of section '" << section << "')";
      msg << ", but this problem does not read section '" << section << "', so the setting would be ignored. "
          << reason;
      AssertThrow(false, dealii::ExcMessage(msg.str()));
    }

    bool
    parse_count(const std::string &text, const unsigned int min, const unsigned int max, unsigned int &value)
    {
      if (text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos)
        return false;
      const unsigned int v = static_cast<unsigned int>(std::stoul(text));
      if (v < min || v > max)
        return false;
      value = v;
      return true;
    }

  } // namespace InputParsing
} // namespace dealvem
