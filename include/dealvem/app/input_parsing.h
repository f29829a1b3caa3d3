// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_app_input_parsing_h
#define dealvem_app_input_parsing_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dealvem
{
  struct MeshParameters;

  /**
   * Helpers that turn the compact strings of the parameter file into
   * objects. Syntax (used by the "Boundary conditions" section of
   * `dealvem input.prm`):
   * - a list of entries separated by ';',
   * - the fields of an entry separated by ':',
   * - the components of a field separated by ',' (commas inside
   *   parentheses, as in pow(x,2), do not split).
   * Expressions are muparser expressions in x, y and t with the
   * constants of the "Function constants" parameter. A static problem
   * evaluates them at t = 1 (a load written as 10*t is the load 10); a
   * contact problem with load steps (section "Load steps") evaluates them at
   * the time of each step, which makes a load history.
   */
  namespace InputParsing
  {
    /// Split @p s at the character @p sep where it is not inside
    /// parentheses; trims white space; drops empty pieces if
    /// @p keep_empty is false.
    std::vector<std::string>
    split(const std::string &s, const char sep, const bool keep_empty = false);

    /// Trim white space at both ends.
    std::string
    trim(const std::string &s);

    /// Parse "a=1, b=2.5" into a map; throws naming @p parameter on errors.
    std::map<std::string, double>
    parse_constants(const std::string &s, const std::string &parameter);

    /// Parse a non-negative integer; throws naming @p parameter otherwise.
    unsigned int
    parse_unsigned(const std::string &s, const std::string &parameter);

    /// Parse a real number; throws naming @p parameter otherwise.
    double
    parse_double(const std::string &s, const std::string &parameter);

    /**
     * Parse a command-line count: true and @p value set if @p text is a
     * whole number (digits only: no sign, at most 9 digits, so nothing
     * wraps or overflows) in [@p min, @p max]; false otherwise. The
     * tutorials' argument parsing.
     */
    bool
    parse_count(const std::string &text, const unsigned int min, const unsigned int max, unsigned int &value);

    /**
     * Check that @p value lies in the interval from @p lower to @p upper
     * (each end included unless @p lower_open or @p upper_open); throws an
     * ExcMessage naming @p parameter, the value and the interval, followed
     * by @p reason (may be empty) otherwise. Non-finite values are always
     * rejected.
     */
    void
    check_range(const double       value,
                const double       lower,
                const double       upper,
                const std::string &parameter,
                const bool         lower_open = false,
                const bool         upper_open = false,
                const std::string &reason     = "");

    /**
     * Check the names of the function constants: each must be a valid
     * muparser name (a letter or '_' followed by letters, digits or '_'),
     * and must not be one of the variables x, y, t or a function or
     * constant the parser already knows (sin, _pi, and pi and Pi, which
     * Functions::ParsedFunction defines, ...). Throws naming
     * @p parameter and the offending name.
     */
    void
    check_constant_names(const std::map<std::string, double> &constants, const std::string &parameter);

    /// Size estimate of a run, see estimate_run_size().
    struct RunSizeEstimate
    {
      /// Cells and DoFs of the largest (last) refinement cycle, all bodies.
      double cells = 0, dofs = 0;
      /// Voronoi cells of the largest cycle (summed over the bodies).
      double voronoi_cells = 0;
      /// The largest number of Lloyd iterations of a Voronoi body.
      double lloyd_iterations = 0;
      /// Sum over cycles and bodies of (Lloyd iterations + 1) * cells.
      double lloyd_work = 0;
      /// false when a mesh is read from a file (its size is not known
      /// before it is read; it does not enter the numbers above).
      bool complete = true;
    };

    /// The limits checked by check_run_size().
    constexpr double max_dofs             = 2e7;
    constexpr double max_voronoi_cells    = 1e7;
    constexpr double max_lloyd_iterations = 1e5;
    constexpr double max_lloyd_work       = 1e8;
    /// Cell counts beyond this cannot be represented by the mesh classes,
    /// whatever 'Allow large runs' says.
    constexpr double max_representable_cells = 1e9;

    /**
     * Estimate the size of a run from the mesh generators' parameters of
     * the bodies @p meshes, the number of refinement cycles (subdivisions
     * times 2^cycle, Voronoi cells times 4^cycle) and the order @p degree
     * (DoFs: 2 per vertex, plus 2 per edge and 2 per cell for k = 2;
     * Voronoi meshes: about 2 vertices and 3 edges per cell).
     */
    RunSizeEstimate
    estimate_run_size(const std::vector<const MeshParameters *> &meshes,
                      const unsigned int                        n_cycles,
                      const unsigned int                        degree);

    /**
     * Refuse a run whose estimate exceeds max_dofs, max_voronoi_cells,
     * max_lloyd_iterations or max_lloyd_work unless @p allow_large_runs
     * (the parameter 'Allow large runs'); the message gives the estimate
     * and names that parameter. Runs beyond max_representable_cells are
     * refused in any case.
     */
    void
    check_run_size(const std::vector<const MeshParameters *> &meshes,
                   const unsigned int                        n_cycles,
                   const unsigned int                        degree,
                   const bool                                allow_large_runs);

    /// One entry of a ParameterHandler: its path ("Body 1/Mesh/Type"), its
    /// current and default values and the description of its pattern.
    struct Entry
    {
      std::string path, value, default_value, pattern;
    };

    /**
     * Every entry of @p prm (from its XML description, so that the patterns
     * are known too), in the order ParameterHandler prints them.
     */
    std::vector<Entry>
    list_entries(const dealii::ParameterHandler &prm);

    /**
     * deal.II's ParameterHandler does not check a value that contains '{'
     * against the pattern of its entry (it keeps such values for its
     * parameter loops, which dealvem does not run), so that
     * `set Type = {voronoi}` would reach the program as the literal text.
     * Check every such value against its pattern and throw, naming the
     * entry, the value and the pattern, if it does not match. Values that
     * match (the expressions and file names of 'Anything' entries, such as
     * a file name with '{cycle}') pass.
     */
    void
    check_braced_values(const dealii::ParameterHandler &prm);

    /**
     * The paths of the entries of @p prm below the section @p section (a
     * path such as "Body 1" or "Contact", without a trailing '/') whose value
     * differs from their default: the entries a parameter file set to
     * something else. (ParameterHandler does not record which entries a
     * file sets; an entry set to its default value is not listed.)
     */
    std::vector<std::string>
    changed_entries(const dealii::ParameterHandler &prm, const std::string &section);

    /**
     * Throw if the parameter file set an entry of the section @p section
     * (see changed_entries()) that the problem it describes does not read:
     * the message names the first such entry, how many more there are, and
     * ends with @p reason (what the section needs, e.g. "set 'Number of
     * bodies = 2'").
     */
    void
    check_section_unused(const dealii::ParameterHandler &prm,
                         const std::string              &section,
                         const std::string              &reason);

    /**
     * A function of (x, y) and the time t given by muparser expressions, one
     * per component: deal.II's Functions::ParsedFunction (variables "x,y,t",
     * so every expression may use t; derivatives by fourth-order difference
     * quotients with step 1e-5), set up from the expressions and constants
     * directly instead of from a ParameterHandler section, with checks on
     * top. The time starts at t = 1 (the value used by the static problems);
     * set_time() (inherited) changes it for the parser and the difference
     * quotients alike.
     *
     * The constants known to the expressions are @p constants, muparser's
     * _pi and _e, and pi and Pi, which Functions::ParsedFunction defines
     * (check_constant_names() therefore refuses them as user constants).
     *
     * The expressions are checked on construction; errors name @p parameter
     * and the expression. Every evaluation checks the result: a value that is
     * not finite (division by zero, sqrt(-1), ...) stops with an exception
     * naming @p parameter, the expression, the point and the time, and so
     * does an error of the parser during evaluation.
     */
    class ParsedFunction : public dealii::Functions::ParsedFunction<2>
    {
    public:
      ParsedFunction(const std::vector<std::string>       &expressions,
                     const std::map<std::string, double> &constants,
                     const std::string                    &parameter);

      double
      value(const dealii::Point<2> &p, const unsigned int component = 0) const override;

      void
      vector_value(const dealii::Point<2> &p, dealii::Vector<double> &values) const override;

      /// The parameter name used in error messages.
      const std::string &
      get_parameter() const
      {
        return parameter;
      }

      /// The expressions, for output.
      const std::vector<std::string> &
      get_expressions() const
      {
        return expressions;
      }

    private:
      /// Throw an error naming the parameter, expression @p component, the
      /// point and the time, with the explanation @p what.
      [[noreturn]] void
      report(const dealii::Point<2> &p, const unsigned int component, const std::string &what) const;

      std::vector<std::string> expressions;
      std::string              parameter;
    };
  } // namespace InputParsing
} // namespace dealvem

#endif
