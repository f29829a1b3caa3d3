// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The outline of a gear rack. The geometry is evaluated in the frame of a
// tooth: its axis along x = 0, the pitch line along y = 0, the teeth
// pointing toward +y. The first half of a pitch (the middle of the space
// before the tooth up to the middle of its tip land) is written out; the
// second half is its mirror image about the tooth's axis.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>

#include <dealvem/base/number_string.h>
#include <dealvem/mesh/gear_rack.h>

#include <algorithm>
#include <cmath>

namespace dealvem
{
  using internal::number_string;

  namespace
  {

    bool
    finite_non_negative(const double x)
    {
      return std::isfinite(x) && x >= 0;
    }
  } // namespace


  GearRack::GearRack(const Parameters &parameters)
    : prm(parameters)
  {
    const auto fail = [](const std::string &text) { return dealii::ExcMessage("GearRack: " + text); };
    AssertThrow(std::isfinite(prm.module) && prm.module > 0,
                fail("the module must be positive and finite, not " + number_string(prm.module) + "."));
    AssertThrow(prm.n_teeth >= 1, fail("the number of teeth must be at least 1."));
    AssertThrow(std::isfinite(prm.pressure_angle) && prm.pressure_angle > 0 && prm.pressure_angle < dealii::numbers::PI / 4,
                fail("the pressure angle must lie between 0 and 45 degrees, not " +
                     number_string(prm.pressure_angle * 180 / dealii::numbers::PI) + " degrees."));
    AssertThrow(finite_non_negative(prm.addendum),
                fail("the addendum coefficient must not be negative, not " + number_string(prm.addendum) + "."));
    AssertThrow(std::isfinite(prm.dedendum) && prm.dedendum > 0,
                fail("the dedendum coefficient must be positive, not " + number_string(prm.dedendum) + "."));
    AssertThrow(finite_non_negative(prm.root_fillet_radius),
                fail("the root fillet radius coefficient must not be negative, not " +
                     number_string(prm.root_fillet_radius) + "."));
    AssertThrow(finite_non_negative(prm.body_depth),
                fail("the body depth must not be negative, not " + number_string(prm.body_depth) + "."));
    AssertThrow(std::isfinite(prm.profile_shift) && std::isfinite(prm.backlash) &&
                  std::isfinite(prm.pitch_line_height) && std::isfinite(prm.position),
                fail("the profile shift, backlash, pitch line height and position must be finite."));
    if (prm.body_depth == 0)
      prm.body_depth = 3 * prm.module;

    const double m = prm.module, a = prm.pressure_angle, tan_a = std::tan(a), p = pitch();
    // the thickness at the pitch line and the straight flank's half width at height y
    const double s_p        = m * (dealii::numbers::PI / 2 + 2 * prm.profile_shift * tan_a) - prm.backlash;
    const auto   half_width = [&](const double y) { return s_p / 2 - y * tan_a; };
    AssertThrow(s_p > 0, fail("the backlash " + number_string(prm.backlash) +
                              " thins the teeth to nothing (their thickness at the pitch line would be " +
                              number_string(s_p) + ")."));
    y_tip  = (prm.addendum + prm.profile_shift) * m;
    y_root = -(prm.dedendum - prm.profile_shift) * m;
    AssertThrow(2 * half_width(y_root) < p,
                fail("the teeth overlap at the root line: their thickness there, " +
                     number_string(2 * half_width(y_root)) + ", reaches the pitch " + number_string(p) + " (backlash " +
                     number_string(prm.backlash) + ", dedendum " + number_string(prm.dedendum) + ", profile shift " +
                     number_string(prm.profile_shift) + ")."));
    half_tip = half_width(y_tip);
    AssertThrow(half_tip > 0,
                fail("the teeth are pointed: the tip land would be " + number_string(2 * half_tip) +
                     " wide (addendum " + number_string(prm.addendum) + ", profile shift " +
                     number_string(prm.profile_shift) + ", backlash " + number_string(prm.backlash) + ")."));
    // the fillet: centre rho above the root line and rho from the flank along its normal
    const double rho = prm.root_fillet_radius * m;
    fillet_y         = y_root + rho;
    fillet_x         = half_width(fillet_y) + rho / std::cos(a);
    y_form           = fillet_y - rho * std::sin(a);
    form_x           = fillet_x - rho * std::cos(a);
    AssertThrow(fillet_x <= p / 2 * (1 + 1e-14),
                fail("the root fillet radius " + number_string(rho) +
                     " does not fit in the tooth space: the fillets of a space would cross (the largest radius "
                     "that fits is " +
                     number_string(rho * (p / 2 - half_width(y_root)) / (fillet_x - half_width(y_root))) + ")."));
    AssertThrow(y_form < y_tip, fail("the root fillet radius " + number_string(rho) +
                                     " does not fit on the flank: the fillet would reach the tip line."));

    root_length   = std::max(0., p / 2 - fillet_x);
    fillet_length = rho * (dealii::numbers::PI / 2 - a);
    flank_length  = (y_tip - y_form) / std::cos(a);
    starts[0]     = 0;
    starts[1]     = root_length;
    starts[2]     = starts[1] + fillet_length;
    starts[3]     = starts[2] + flank_length;
    starts[4]     = starts[3] + 2 * half_tip;
    starts[5]     = starts[4] + flank_length;
    starts[6]     = starts[5] + fillet_length;
    starts[7]     = starts[6] + root_length;
  }


  const GearRack::Parameters &
  GearRack::parameters() const
  {
    return prm;
  }


  unsigned int
  GearRack::n_teeth() const
  {
    return prm.n_teeth;
  }


  double
  GearRack::pitch() const
  {
    return dealii::numbers::PI * prm.module;
  }


  double
  GearRack::base_pitch() const
  {
    return pitch() * std::cos(prm.pressure_angle);
  }


  double
  GearRack::tip_height() const
  {
    return prm.pitch_line_height + y_tip;
  }


  double
  GearRack::root_height() const
  {
    return prm.pitch_line_height + y_root;
  }


  double
  GearRack::form_height() const
  {
    return prm.pitch_line_height + y_form;
  }


  double
  GearRack::bottom_height() const
  {
    return root_height() - prm.body_depth;
  }


  double
  GearRack::tooth_axis(const unsigned int k) const
  {
    return prm.position + k * pitch();
  }


  double
  GearRack::tooth_thickness(const double y) const
  {
    return 2 * half_tip + 2 * (tip_height() - y) * std::tan(prm.pressure_angle);
  }


  dealii::Point<2>
  GearRack::fillet_center(const unsigned int k) const
  {
    return dealii::Point<2>(tooth_axis(k) + fillet_x, prm.pitch_line_height + fillet_y);
  }


  std::array<double, 2>
  GearRack::extent() const
  {
    return {{tooth_axis(0) - pitch() / 2, tooth_axis(prm.n_teeth - 1) + pitch() / 2}};
  }


  double
  GearRack::outline_pitch_length() const
  {
    return starts[7];
  }


  const std::array<double, 8> &
  GearRack::piece_starts() const
  {
    return starts;
  }


  std::pair<dealii::Point<2>, dealii::Tensor<1, 2>>
  GearRack::half_pitch_point(const double u) const
  {
    const double a = prm.pressure_angle;
    if (u <= starts[1])
      return {dealii::Point<2>(-pitch() / 2 + u, y_root), dealii::Tensor<1, 2>({1., 0.})};
    if (u <= starts[2])
      {
        // from straight below the centre (-pi/2) counter-clockwise to -alpha
        const double rho = prm.root_fillet_radius * prm.module, phi = -dealii::numbers::PI / 2 + (u - starts[1]) / rho;
        return {dealii::Point<2>(-fillet_x + rho * std::cos(phi), fillet_y + rho * std::sin(phi)),
                dealii::Tensor<1, 2>({-std::sin(phi), std::cos(phi)})};
      }
    if (u <= starts[3])
      {
        const double v = u - starts[2];
        return {dealii::Point<2>(-form_x + v * std::sin(a), y_form + v * std::cos(a)),
                dealii::Tensor<1, 2>({std::sin(a), std::cos(a)})};
      }
    return {dealii::Point<2>(-half_tip + (u - starts[3]), y_tip), dealii::Tensor<1, 2>({1., 0.})};
  }


  dealii::Point<2>
  GearRack::outline_point(const double s) const
  {
    const double L = starts[7];
    const int    k = std::clamp(static_cast<int>(std::floor(s / L)), 0, static_cast<int>(prm.n_teeth) - 1);
    const double u = s - k * L;
    auto         q = half_pitch_point(u <= L / 2 ? u : L - u).first;
    if (u > L / 2)
      q[0] = -q[0];
    return dealii::Point<2>(tooth_axis(k) + q[0], prm.pitch_line_height + q[1]);
  }


  dealii::Tensor<1, 2>
  GearRack::outline_tangent(const double s) const
  {
    const double L = starts[7];
    const int    k = std::clamp(static_cast<int>(std::floor(s / L)), 0, static_cast<int>(prm.n_teeth) - 1);
    const double u = s - k * L;
    auto         t = half_pitch_point(u <= L / 2 ? u : L - u).second;
    // the mirror image, run backwards: (x, y) -> (x, -y)
    if (u > L / 2)
      t[1] = -t[1];
    return t;
  }


  double
  GearRack::half_pitch_coordinate(const dealii::Point<2> &q) const
  {
    const double          a = prm.pressure_angle, rho = prm.root_fillet_radius * prm.module;
    std::array<double, 4> u;
    // root line (continued beyond the middle of the space: the rack's ends)
    u[0] = std::min(q[0] + pitch() / 2, starts[1]);
    // fillet: the angle of q about the centre, clamped to the arc
    const double phi = std::atan2(q[1] - fillet_y, q[0] + fillet_x);
    u[1]             = starts[1] + rho * (std::clamp(phi, -dealii::numbers::PI / 2, -a) + dealii::numbers::PI / 2);
    // flank: the projection on the line, clamped to its ends
    const double v = (q[0] + form_x) * std::sin(a) + (q[1] - y_form) * std::cos(a);
    u[2]           = starts[2] + std::clamp(v, 0., flank_length);
    // tip line up to the tooth's axis
    u[3]        = starts[3] + std::clamp(q[0] + half_tip, 0., half_tip);
    double best = u[0], d_best = q.distance(half_pitch_point(u[0]).first);
    for (unsigned int i = 1; i < 4; ++i)
      {
        const double d = q.distance(half_pitch_point(u[i]).first);
        if (d < d_best)
          {
            d_best = d;
            best   = u[i];
          }
      }
    return best;
  }


  double
  GearRack::outline_coordinate(const dealii::Point<2> &p) const
  {
    const double L  = starts[7];
    const double x0 = p[0] - prm.position;
    const int    k  = std::clamp(static_cast<int>(std::lround(x0 / pitch())), 0, static_cast<int>(prm.n_teeth) - 1);
    const double x  = x0 - k * pitch();
    const bool   mirrored = x > 0;
    const double u        = half_pitch_coordinate(dealii::Point<2>(mirrored ? -x : x, p[1] - prm.pitch_line_height));
    return k * L + (mirrored ? L - u : u);
  }


  double
  GearRack::distance_to_outline(const dealii::Point<2> &p) const
  {
    return p.distance(outline_point(outline_coordinate(p)));
  }


  GearRack::Piece
  GearRack::piece(const double s) const
  {
    const double L = starts[7];
    double       u = s - L * std::floor(s / L);
    if (u > L / 2)
      u = L - u;
    if (u < starts[1])
      return Piece::root_line;
    if (u < starts[2])
      return Piece::fillet;
    if (u < starts[3])
      return Piece::flank;
    return Piece::tip_line;
  }


  std::vector<dealii::Point<2>>
  GearRack::outline(const double spacing) const
  {
    AssertThrow(std::isfinite(spacing) && spacing > 0,
                dealii::ExcMessage("GearRack::outline(): the spacing must be positive, not " + number_string(spacing) +
                                   "."));
    std::vector<dealii::Point<2>> points{outline_point(0.)};
    for (unsigned int k = 0; k < prm.n_teeth; ++k)
      for (unsigned int j = 0; j < 7; ++j)
        {
          const double len = starts[j + 1] - starts[j];
          if (len <= 0)
            continue;
          const unsigned int n = std::max(1, static_cast<int>(std::ceil(len / spacing)));
          for (unsigned int i = 1; i <= n; ++i)
            points.push_back(outline_point(k * starts[7] + starts[j] + len * i / n));
        }
    return points;
  }


  double
  GearRack::area() const
  {
    // the area under the outline down to the back line: the integral of
    // (y - y_bottom) dx along the outline, piece by piece (Gauss points on
    // the arcs; exact on the straight pieces)
    const dealii::QGauss<1> gauss(12);
    const double            y_b = bottom_height();
    double                  sum = 0;
    for (unsigned int k = 0; k < prm.n_teeth; ++k)
      for (unsigned int j = 0; j < 7; ++j)
        {
          const double len = starts[j + 1] - starts[j];
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const double s = k * starts[7] + starts[j] + len * gauss.point(q)[0];
              sum += gauss.weight(q) * len * (outline_point(s)[1] - y_b) * outline_tangent(s)[0];
            }
        }
    return sum;
  }
} // namespace dealvem
