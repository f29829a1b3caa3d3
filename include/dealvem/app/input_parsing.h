// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_app_input_parsing_h
#define dealvem_app_input_parsing_h

#include <deal.II/base/auto_derivative_function.h>
#include <deal.II/base/function_parser.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dealvem
{
  /**
   * Helpers that turn the compact strings of the parameter file into
   * objects. Syntax (used by the "Boundary conditions" section of
   * `dealvem input.prm`):
   * - a list of entries separated by ';',
   * - the fields of an entry separated by ':',
   * - the components of a field separated by ',' (commas inside
   *   parentheses, as in pow(x,2), do not split).
   * Expressions are muparser expressions in x, y and t with the
   * constants of the "Function constants" parameter. The programs solve
   * static problems, so t is always 1 there (a load written as 10*t is the
   * load 10); t is there so that one parameter file can later serve a load
   * history.
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
     * A function of (x, y) and the time t given by muparser expressions, one
     * per component, with derivatives by fourth-order difference quotients.
     * The time starts at t = 1 (the value used by the static problems);
     * set_time() changes it.
     *
     * The expressions are checked on construction; errors name @p parameter
     * and the expression. Every evaluation checks the result: a value that is
     * not finite (division by zero, sqrt(-1), ...) stops with an exception
     * naming @p parameter, the expression, the point and the time, and so
     * does an error of the parser during evaluation.
     */
    class ParsedFunction : public dealii::AutoDerivativeFunction<2>
    {
    public:
      ParsedFunction(const std::vector<std::string>       &expressions,
                     const std::map<std::string, double> &constants,
                     const std::string                    &parameter);

      double
      value(const dealii::Point<2> &p, const unsigned int component = 0) const override;

      void
      vector_value(const dealii::Point<2> &p, dealii::Vector<double> &values) const override;

      /// Set the time t of the expressions (of this object and its parser).
      void
      set_time(const double new_time) override;

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

      std::vector<std::string>           expressions;
      std::string                        parameter;
      dealii::FunctionParser<2>          parser;
    };
  } // namespace InputParsing
} // namespace dealvem

#endif
