// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_base_number_string_h
#define dealvem_base_number_string_h

#include <deal.II/base/point.h>

#include <sstream>
#include <string>

namespace dealvem
{
  /**
   * Text of numbers and points for error messages. std::to_string(double)
   * prints six fixed decimals ("0.000000" for 1e-9); these print as a
   * stream does by default (six significant digits, exponent when needed).
   */
  namespace internal
  {
    /// @p x as `std::ostream << x` writes it, e.g. "1e-09" or "0.25".
    inline std::string
    number_string(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    /// @p p as "(x, y)" (first two coordinates), numbers as number_string().
    template <int dim>
    std::string
    point_string(const dealii::Point<dim> &p)
    {
      static_assert(dim >= 2, "point_string() prints two coordinates");
      std::ostringstream s;
      s << "(" << p[0] << ", " << p[1] << ")";
      return s.str();
    }
  } // namespace internal
} // namespace dealvem

#endif
