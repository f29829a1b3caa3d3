// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/base/number_string.h>
#include <dealvem/design/material_interpolation.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace dealvem
{
  namespace Design
  {
    void
    MaterialInterpolation::check() const
    {
      using internal::number_string;
      AssertThrow(std::isfinite(minimum) && minimum > 0 && minimum < 1,
                  dealii::ExcMessage("Design/Minimum stiffness: the stiffness factor of a void cell must lie in "
                                     "(0, 1), got " + number_string(minimum) + "."));
      if (type == Type::simp)
        {
          AssertThrow(std::isfinite(penalty) && penalty >= 1,
                      dealii::ExcMessage("Design/Penalization: the SIMP exponent must be at least 1, got " +
                                         number_string(penalty) + "."));
        }
      else
        {
          AssertThrow(std::isfinite(penalty) && penalty >= 0,
                      dealii::ExcMessage("Design/Penalization: the RAMP parameter q must be non-negative, got " +
                                         number_string(penalty) + "."));
        }
    }



    double
    MaterialInterpolation::factor(const double rho) const
    {
      if (type == Type::simp)
        return minimum + std::pow(rho, penalty) * (1 - minimum);
      return minimum + rho / (1 + penalty * (1 - rho)) * (1 - minimum);
    }



    double
    MaterialInterpolation::derivative(const double rho) const
    {
      if (type == Type::simp)
        return rho > 0 || penalty == 1 ? penalty * std::pow(rho, penalty - 1) * (1 - minimum) : 0.;
      const double d = 1 + penalty * (1 - rho);
      return (1 + penalty) / (d * d) * (1 - minimum);
    }



    MaterialInterpolation::Type
    MaterialInterpolation::parse(const std::string &name)
    {
      std::string n = name;
      std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::tolower(c); });
      if (n == "simp")
        return Type::simp;
      if (n == "ramp")
        return Type::ramp;
      AssertThrow(false, dealii::ExcMessage("Design/Interpolation: '" + name + "' is not SIMP or RAMP."));
      return Type::simp;
    }



    std::string
    MaterialInterpolation::name(const Type t)
    {
      return t == Type::simp ? "SIMP" : "RAMP";
    }



    void
    HeavisideProjection::check() const
    {
      using internal::number_string;
      AssertThrow(std::isfinite(beta) && beta > 0,
                  dealii::ExcMessage("Design/Projection sharpness: beta must be positive, got " +
                                     number_string(beta) + "."));
      AssertThrow(std::isfinite(eta) && eta > 0 && eta < 1,
                  dealii::ExcMessage("Design/Projection threshold: eta must lie in (0, 1), got " +
                                     number_string(eta) + "."));
    }



    double
    HeavisideProjection::value(const double x) const
    {
      const double a = std::tanh(beta * eta);
      return (a + std::tanh(beta * (x - eta))) / (a + std::tanh(beta * (1 - eta)));
    }



    double
    HeavisideProjection::derivative(const double x) const
    {
      const double t = std::tanh(beta * (x - eta));
      return beta * (1 - t * t) / (std::tanh(beta * eta) + std::tanh(beta * (1 - eta)));
    }
  } // namespace Design
} // namespace dealvem
