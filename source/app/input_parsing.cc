// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <dealvem/app/input_parsing.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace dealvem
{
  namespace InputParsing
  {
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
          c[kv[0]] = parse_double(kv[1], parameter + " (" + kv[0] + ")");
        }
      return c;
    }



    ParsedFunction::ParsedFunction(const std::vector<std::string>      &expressions,
                                   const std::map<std::string, double> &constants,
                                   const std::string                   &parameter)
      : dealii::AutoDerivativeFunction<2>(1e-5, expressions.size(), 1.0)
      , expressions(expressions)
      , parameter(parameter)
      , parser(expressions.size(), 1.0)
    {
      AssertThrow(!expressions.empty(),
                  dealii::ExcMessage("Parameter '" + parameter + "': no expression given."));
      set_formula(FourthOrder);
      std::string joined;
      for (const auto &x : expressions)
        joined += (joined.empty() ? "" : ", ") + x;
      std::string error;
      try
        {
          // t is the time variable of FunctionParser: get_time() of the parser
          parser.initialize("x,y,t", expressions, constants, true);
          // evaluate once (the value itself is not checked) so that unknown
          // names are reported here rather than in the middle of assembly
          dealii::Vector<double> v(expressions.size());
          parser.vector_value(dealii::Point<2>(0.123, 0.456), v);
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
      catch (...)
        {
          error = "the expression parser failed";
        }
      AssertThrow(error.empty(),
                  dealii::ExcMessage("Parameter '" + parameter + "': cannot parse the expression(s) '" +
                                     joined + "': " + error));
    }



    void
    ParsedFunction::report(const dealii::Point<2> &p,
                           const unsigned int      component,
                           const std::string      &what) const
    {
      std::ostringstream msg;
      msg << "Parameter '" << parameter << "': the expression '"
          << (component < expressions.size() ? expressions[component] : std::string("?")) << "' "
          << what << " at the point (" << p[0] << ", " << p[1] << "), t = " << parser.get_time()
          << ".";
      AssertThrow(false, dealii::ExcMessage(msg.str()));
      std::abort(); // not reached
    }



    double
    ParsedFunction::value(const dealii::Point<2> &p, const unsigned int component) const
    {
      double      v = 0;
      std::string error;
      try
        {
          v = parser.value(p, component);
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
      catch (...)
        {
          error = "unknown parser error";
        }
      if (!error.empty())
        report(p, component, "cannot be evaluated (" + error + ")");
      if (!std::isfinite(v))
        {
          report(p, component,
                 std::string("evaluates to ") + (std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf")));
        }
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



    void
    ParsedFunction::set_time(const double new_time)
    {
      dealii::AutoDerivativeFunction<2>::set_time(new_time);
      parser.set_time(new_time);
    }
  } // namespace InputParsing
} // namespace dealvem
