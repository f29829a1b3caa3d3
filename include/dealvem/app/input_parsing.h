// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_app_input_parsing_h
#define dealvem_app_input_parsing_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>

#include <dealvem/elasticity/elasticity_operator.h>

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
    /// The largest boundary id the input accepts (ids 0..254, as in the
    /// parameter files' patterns and gmsh's physical tags the program
    /// reads).
    constexpr unsigned int max_boundary_id = 254;

    /// Split @p s at the character @p sep where it is not inside
    /// parentheses; trims white space; drops empty pieces if
    /// @p keep_empty is false.
    std::vector<std::string>
    split(const std::string &s, const char sep, const bool keep_empty = false);

    /// Trim white space at both ends.
    std::string
    trim(const std::string &s);

    /// The stabilization rule 'Discretization/Stabilization' names: "trace",
    /// "diagonal", "boundary", or else (the entry's pattern leaves only
    /// "automatic") Stabilization::automatic. Both programs read the entry
    /// with it.
    Stabilization
    parse_stabilization(const std::string &name);

    /// The largest number of load steps ('Load steps/Number of steps').
    constexpr unsigned int max_load_steps = 100000;

    /// Throw unless 1 <= @p steps <= max_load_steps, naming 'Load
    /// steps/Number of steps' (the check of both programs).
    void
    check_number_of_load_steps(const long steps);

    /// Parse "a=1, b=2.5" into a map; throws naming @p parameter on errors.
    std::map<std::string, double>
    parse_constants(const std::string &s, const std::string &parameter);

    /// Parse a non-negative integer; throws naming @p parameter otherwise.
    unsigned int
    parse_unsigned(const std::string &s, const std::string &parameter);

    /**
     * Parse an id given as a number or as a physical name of the mesh file
     * (gmsh \$PhysicalNames, see MeshIO::PhysicalNames): @p names maps the
     * names to ids, @p what says which kind of id ("boundary id",
     * "material id") and @p known lists every name of the file for the
     * message. A name that is not in @p names is an error listing them;
     * numbers are returned as they are (the caller checks their range).
     */
    template <typename Id>
    unsigned int
    parse_id_or_name(const std::string               &s,
                     const std::string               &parameter,
                     const std::map<std::string, Id> &names,
                     const std::string               &what,
                     const std::string               &known)
    {
      const std::string t = trim(s);
      if (!t.empty() && t.find_first_not_of("0123456789") == std::string::npos)
        return parse_unsigned(t, parameter);
      const auto it = names.find(t);
      AssertThrow(it != names.end(),
                  dealii::ExcMessage("Parameter '" + parameter + "': '" + t + "' is neither a " + what +
                                     " (a non-negative integer) nor a physical name of the mesh file(s) for a " +
                                     what + ". The physical names are: " + known + "."));
      return it->second;
    }

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

    /**
     * Whether the muparser expression @p expression uses the variable
     * @p variable (as a name of its own: "t" in "5*t", not in "tan(x)" or
     * "1e5").
     */
    bool
    uses_variable(const std::string &expression, const std::string &variable);

    /// Size estimate of a run, see estimate_run_size().
    struct RunSizeEstimate
    {
      /// Cells of the largest (last) refinement cycle, all bodies.
      double cells = 0;
      /// DoFs of the largest (last) refinement cycle, all bodies.
      double dofs = 0;
      /// Voronoi cells of the largest cycle (summed over the bodies).
      double voronoi_cells = 0;
      /// The largest number of Lloyd iterations of a Voronoi body.
      double lloyd_iterations = 0;
      /// Sum over cycles and bodies of (Lloyd iterations + 1) * cells.
      double lloyd_work = 0;
      /// false when the size of a mesh file could not be found from its
      /// header (it does not enter the numbers above); files whose header
      /// gives their counts enter them (see MeshIO::count_entities()).
      bool complete = true;
      /// The mesh files that entered the estimate, with their header
      /// counts, for messages ("'a.msh' (header: 1000000 nodes, ...)").
      std::string files;
    };

    /// The linear solvers as the size check sees them.
    enum class SolverKind
    {
      /// a sparse direct factorization (UMFPACK, KLU)
      direct,
      /// CG or GMRES with AMG or the p-multigrid
      iterative,
      /// the one-body program's 'automatic': direct up to
      /// direct_solver_max_dofs DoFs when it fits, else iterative
      automatic
    };

    /**
     * The automatic choice of the one-body program: a direct
     * factorization up to this many DoFs, CG with the p-multigrid or AMG
     * above. Measured on 2 cores (doc/benchmarks.md, "Solver choice"):
     * UMFPACK and CG-AMG take the same time at 3e3 to 6e3 DoFs (quads and
     * Voronoi cells, k = 1 and 2), and UMFPACK grows faster above (2.5x
     * CG's time at 2.4e4 DoFs, 4.5x at 2e5); up to 1e4 DoFs the direct
     * solve costs at most 0.1 s more and needs no tolerance.
     */
    constexpr double direct_solver_max_dofs = 1e4;
    /// Contact problems, 'Solver/Type = automatic': up to this many
    /// displacement DoFs the condensed stiffness is factored (direct
    /// constraints), above it CG-AMG iterates on it (measured crossover,
    /// doc/benchmarks.md).
    constexpr double contact_direct_solver_max_dofs = 1.2e5;

    /// The constants of estimated_memory() (bytes): fits to the peak
    /// memory measured on quads and Voronoi cells, k = 1 and 2, up to
    /// 2e5 DoFs and to the 1e6-DoF runs of doc/benchmarks.md, rounded up.
    constexpr double base_bytes_per_dof_k2    = 1500;
    constexpr double base_bytes_per_dof_k1    = 1500;  ///< per DoF for k = 1 (mesh, DoFs, matrix, vectors, output)
    constexpr double iterative_bytes_per_dof  = 1000;  ///< per DoF added by CG and its preconditioner
    constexpr double direct_bytes_per_dof_log = 300;   ///< times log2(DoFs), per DoF, added by the factors
    constexpr double fixed_bytes              = 200e6; ///< added to every estimate, whatever the size

    /**
     * Estimated peak memory (bytes) of a run with @p n_dofs DoFs of order
     * @p degree solved by a direct factorization (@p direct) or by CG with
     * AMG or the p-multigrid: mesh, DoFs, matrix, vectors, postprocessing,
     * and the factors or the multigrid hierarchy. The constants are fits to
     * the peak memory measured on structured quads and Voronoi meshes
     * (doc/benchmarks.md, "Solver choice"), rounded up.
     */
    double
    estimated_memory(const double n_dofs, const unsigned int degree, const bool direct);

    /**
     * The memory a run may use (bytes): @p limit_GB if positive (the
     * parameter 'Memory limit'), else 80 % of the smallest of the physical
     * memory, the process limits (ulimit -v, -d) and the control group's
     * limit. @p source gets a description for messages.
     */
    double
    memory_limit(const double limit_GB, std::string &source);

    /**
     * Whether 'Solver/Type = automatic' takes a direct solver for a
     * one-body problem with @p n_dofs DoFs: up to direct_solver_max_dofs,
     * and only when its estimated memory stays within @p limit_bytes.
     * @p reason gets the explanation the program prints.
     */
    bool
    automatic_solver_is_direct(const double n_dofs, const unsigned int degree, const double limit_bytes,
                               std::string &reason);

    /// The limits checked by check_run_size().
    constexpr double max_dofs             = 2e7;
    constexpr double max_voronoi_cells    = 1e7; ///< Voronoi cells of the largest cycle
    constexpr double max_lloyd_iterations = 1e5; ///< Lloyd iterations of one body
    constexpr double max_lloyd_work       = 1e8; ///< Voronoi cells times Lloyd iterations
    /// Cell counts beyond this cannot be represented by the mesh classes,
    /// whatever 'Allow large runs' says.
    constexpr double max_representable_cells = 1e9;

    /**
     * Estimate the size of a run from the mesh generators' parameters of
     * the bodies @p meshes, the number of refinement cycles (subdivisions
     * times 2^cycle, Voronoi cells times 4^cycle) and the order @p degree
     * (DoFs: 2 per vertex, plus 2 per edge and 2 per cell for k = 2;
     * Voronoi meshes: about 2 vertices and 3 edges per cell). Mesh files
     * (relative to @p base_directory) enter with the counts of their
     * header (MeshIO::count_entities(); V vertices and C cells give
     * V + C edges; a 'gridin file' refined in the cycles has 4^cycle times
     * the vertices and cells; a name with '{cycle}' is read per cycle),
     * before their body is read.
     */
    RunSizeEstimate
    estimate_run_size(const std::vector<const MeshParameters *> &meshes,
                      const unsigned int                        n_cycles,
                      const unsigned int                        degree,
                      const std::string                        &base_directory = "");

    /**
     * Refuse a run whose estimate exceeds max_dofs, max_voronoi_cells,
     * max_lloyd_iterations or max_lloyd_work, or whose estimated memory
     * with the solver @p solver (estimated_memory()) exceeds
     * memory_limit(@p memory_limit_GB), unless @p allow_large_runs (the
     * parameter 'Allow large runs'); the message gives the estimate, the
     * mesh files and their header counts, the limit, and names the
     * parameters that change it. Runs beyond max_representable_cells are
     * refused in any case. Returns the estimate.
     */
    RunSizeEstimate
    check_run_size(const std::vector<const MeshParameters *> &meshes,
                   const unsigned int                        n_cycles,
                   const unsigned int                        degree,
                   const bool                                allow_large_runs,
                   const std::string                        &base_directory = "",
                   const SolverKind                          solver         = SolverKind::automatic,
                   const double                              memory_limit_GB = 0);

    /// One entry of a ParameterHandler: its path ("Body 1/Mesh/Type"), its
    /// current and default values and the description of its pattern.
    struct Entry
    {
      std::string path;          ///< "Body 1/Mesh/Type"
      std::string value;         ///< the current value
      std::string default_value; ///< the declared default
      std::string pattern;       ///< the description of the pattern
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
      /// One component per expression, in x, y and t, with the @p constants;
      /// @p parameter names the parameter in the messages.
      ParsedFunction(const std::vector<std::string>       &expressions,
                     const std::map<std::string, double> &constants,
                     const std::string                    &parameter);

      /// The value of component @p component at @p p (and the current time),
      /// checked to be finite.
      double
      value(const dealii::Point<2> &p, const unsigned int component = 0) const override;

      /// All components at @p p, checked to be finite.
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
