// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The outline of an involute spur gear cut by a rack. The geometry is
// evaluated in the frame of a tooth: its axis along +x, the centre at the
// origin, the "upper" flank at positive polar angles; the lower half is the
// mirror image. The rack's generation of the fillet is written in a fixed
// frame where the rack rolls on the line y = r (the pitch point at (0, r)).
#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <dealvem/base/number_string.h>
#include <dealvem/mesh/spur_gear.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dealvem
{
  using internal::number_string;

  namespace
  {

    double
    involute_function(const double angle)
    {
      return std::tan(angle) - angle;
    }

    dealii::Point<2>
    rotated(const dealii::Point<2> &p, const double angle)
    {
      const double c = std::cos(angle), s = std::sin(angle);
      return dealii::Point<2>(c * p[0] - s * p[1], s * p[0] + c * p[1]);
    }

    /// Samples per piece: the nearest sample starts the projection, the
    /// piecewise linear arc length of the samples is the outline coordinate.
    constexpr unsigned int n_samples = 512;
  } // namespace


  /// One piece of the outline of a tooth: a curve of the upper half (kind)
  /// evaluated at parameter q, mirrored for the lower half, with its samples
  /// in the direction of the outline coordinate.
  struct OutlinePiece
  {
    SpurGear::Piece               kind;
    bool                          mirrored = false;
    std::vector<double>           q;      // parameter of each sample (monotone)
    std::vector<double>           length; // arc length from the piece's start
    std::vector<dealii::Point<2>> points;
  };


  struct SpurGear::Impl
  {
    Parameters prm;
    double     r = 0, rb = 0, ra = 0, rf = 0, rho_f = 0, alpha = 0, tau = 0;
    double     psi_b    = 0; // half angle of the tooth at the base circle
    double     d        = 0; // depth of the rack corner's centre below the rolling line
    double     c_x      = 0; // its horizontal position at zero roll
    double     beta_max = 0; // contact-normal angle where the corner meets the rack's straight flank
    double     t_form   = 0; // roll parameter of the involute at the form radius
    double     t_end    = 0; // roll parameter where the (relieved) flank reaches the tip circle
    double     rho_form = 0; // form radius
    double     phi_root = 0; // polar angle where the fillet meets the root circle
    double     phi_tip  = 0; // polar angle of the tip corner
    double     relief_t = 0; // roll parameter where the tip relief starts
    // internal gears: the flank's polar angle is psi_b + inv(alpha_rho) (the
    // tooth widens outward); the root fillet is a circle of radius rho_f
    // about fillet_c, from the root circle (angle fillet_a0 about the centre
    // fillet_c) to the flank (angle fillet_a1)
    bool             internal = false;
    dealii::Point<2> fillet_c;
    double           fillet_a0 = 0, fillet_a1 = 0;

    std::array<OutlinePiece, 7> pieces;
    std::array<double, 8>       starts{};

    /// The data of an internal gear (Parameters::internal), after the
    /// checks common to both kinds: radii, the flank's angle, the root
    /// fillet circle, the tip corner, the rim and the pieces; @p ok throws
    /// with its message if its condition fails.
    template <typename Check>
    void
    make_internal(const Check &ok);

    /// Roll of the gear while the rack corner touches at contact-normal angle beta.
    double
    roll(const double beta) const
    {
      return (d * std::tan(beta) - c_x) / r;
    }

    /// The fillet point at contact-normal angle beta (0 <= beta <= pi/2 -
    /// alpha: the normal's angle from the downward vertical), upper half.
    dealii::Point<2>
    fillet(const double beta) const
    {
      // fixed frame: pitch point (0, r), rack corner centre (d tan(beta), r - d)
      const dealii::Point<2> e(d * std::tan(beta) + rho_f * std::sin(beta), r - d - rho_f * std::cos(beta));
      // tooth frame: the fixed frame's +y is the tooth frame's +x at zero
      // roll, and the gear has turned clockwise by the roll
      return rotated(e, roll(beta) - dealii::numbers::PI / 2);
    }

    /// The unrelieved involute of the upper flank at roll parameter t.
    dealii::Point<2>
    involute(const double t) const
    {
      if (internal)
        {
          // the string unwinds the other way: polar angle psi_b + t - atan(t)
          const double g = psi_b + t;
          return dealii::Point<2>(rb * (std::cos(g) + t * std::sin(g)), rb * (std::sin(g) - t * std::cos(g)));
        }
      const double g = psi_b - t;
      // the base circle's point at angle g plus the unwound string t rb
      return dealii::Point<2>(rb * (std::cos(g) - t * std::sin(g)), rb * (std::sin(g) + t * std::cos(g)));
    }

    /// The outward unit normal of the upper flank at roll parameter t.
    dealii::Tensor<1, 2>
    involute_normal(const double t) const
    {
      const double         g = internal ? psi_b + t : psi_b - t;
      dealii::Tensor<1, 2> n;
      // the string's direction, away from the tooth on the upper flank
      n[0] = -std::sin(g);
      n[1] = std::cos(g);
      return n;
    }

    double
    relief(const double t) const
    {
      if (prm.tip_relief <= 0)
        return 0.;
      // the roll length fraction from the relief's start to the tip corner;
      // an internal gear's tip lies at the small roll parameters
      const double xi = (t - relief_t) / (t_end - relief_t);
      if (xi <= 0)
        return 0.;
      return prm.tip_relief * (prm.relief_shape == ReliefShape::linear ? xi : xi * xi);
    }

    dealii::Point<2>
    flank(const double t) const
    {
      return involute(t) - relief(t) * involute_normal(t);
    }

    /// Point of an upper-half curve.
    dealii::Point<2>
    curve(const Piece kind, const double q) const
    {
      switch (kind)
        {
          case Piece::root_arc:
            return dealii::Point<2>(rf * std::cos(q), rf * std::sin(q));
          case Piece::tip_arc:
            return dealii::Point<2>(ra * std::cos(q), ra * std::sin(q));
          case Piece::fillet:
            if (internal)
              {
                // q in [0, 1]: the angle about the fillet's centre, linear in q
                const double a = fillet_a0 + q * (fillet_a1 - fillet_a0);
                return fillet_c + rho_f * dealii::Tensor<1, 2>({std::cos(a), std::sin(a)});
              }
            // q = tan(beta): the roll is linear in q
            return fillet(std::atan(q));
          case Piece::involute:
            // q = t^2: the involute's arc length r_b t^2 / 2 is linear in q
            return flank(std::sqrt(q));
        }
      return {};
    }

    dealii::Point<2>
    piece_point(const OutlinePiece &piece, const double q) const
    {
      const dealii::Point<2> p = curve(piece.kind, q);
      return piece.mirrored ? dealii::Point<2>(p[0], -p[1]) : p;
    }

    void
    tabulate(OutlinePiece &piece, const Piece kind, const bool mirrored, const double q0, const double q1) const
    {
      piece.kind     = kind;
      piece.mirrored = mirrored;
      piece.q.resize(n_samples + 1);
      piece.length.resize(n_samples + 1);
      piece.points.resize(n_samples + 1);
      // finer near q0 and q1 would not matter: the samples only
      // reparameterize, every point is evaluated on the exact curve
      for (unsigned int i = 0; i <= n_samples; ++i)
        {
          piece.q[i]      = q0 + (q1 - q0) * i / n_samples;
          piece.points[i] = piece_point(piece, piece.q[i]);
          piece.length[i] = (i == 0 ? 0. : piece.length[i - 1] + piece.points[i].distance(piece.points[i - 1]));
        }
    }

    /// Parameter q of the piece at arc length l (piecewise linear in the samples).
    static double
    parameter_at(const OutlinePiece &piece, const double l)
    {
      const auto  &L  = piece.length;
      const double lc = std::min(std::max(l, 0.), L.back());
      unsigned int i  = std::upper_bound(L.begin(), L.end(), lc) - L.begin();
      i               = std::min<unsigned int>(std::max(i, 1u), n_samples);
      const double w  = (lc - L[i - 1]) / (L[i] - L[i - 1]);
      return piece.q[i - 1] + w * (piece.q[i] - piece.q[i - 1]);
    }

    /// Arc length of the piece at parameter q (the inverse of parameter_at).
    static double
    length_at(const OutlinePiece &piece, const double q)
    {
      const auto &Q = piece.q;
      // the samples are equidistant in q
      const double       f = (q - Q.front()) / (Q.back() - Q.front()) * n_samples;
      const unsigned int i = std::min<unsigned int>(std::max<double>(std::floor(f), 0.), n_samples - 1) + 1;
      const double       w = (q - Q[i - 1]) / (Q[i] - Q[i - 1]);
      return piece.length[i - 1] + w * (piece.length[i] - piece.length[i - 1]);
    }

    /// The parameter of the point of the piece nearest to p, and the distance.
    std::pair<double, double>
    project(const OutlinePiece &piece, const dealii::Point<2> &p) const
    {
      unsigned int best = 0;
      double       dmin = std::numeric_limits<double>::max();
      for (unsigned int i = 0; i <= n_samples; ++i)
        {
          const double dist = piece.points[i].distance_square(p);
          if (dist < dmin)
            dmin = dist, best = i;
        }
      double lo = piece.q[best == 0 ? 0 : best - 1], hi = piece.q[std::min(best + 1, n_samples)];
      if (lo > hi)
        std::swap(lo, hi);
      // f(q) = (c(q) - p) . c'(q) vanishes at the nearest point: safeguarded Newton
      const double h  = 1e-4 * (hi - lo);
      auto         fd = [&](const double q, double &f, double &df) {
        const dealii::Point<2>     c  = piece_point(piece, q);
        const dealii::Tensor<1, 2> c1 = (piece_point(piece, q + h) - piece_point(piece, q - h)) / (2 * h);
        const dealii::Tensor<1, 2> c2 = (piece_point(piece, q + h) - 2 * c + piece_point(piece, q - h)) / (h * h);
        f                             = (c - p) * c1;
        df                            = c1 * c1 + (c - p) * c2;
      };
      const double tol = 1e-13 * (hi - lo);
      double       q   = piece.q[best], f, df;
      double       flo, fhi, dummy;
      fd(lo, flo, dummy);
      fd(hi, fhi, dummy);
      if (flo > 0 && fhi > 0)
        q = lo; // nearest at the lower end
      else if (flo < 0 && fhi < 0)
        q = hi;
      else
        for (unsigned int it = 0; it < 60; ++it)
          {
            fd(q, f, df);
            if (f == 0)
              break;
            if ((f < 0) == (flo < 0))
              lo = q, flo = f;
            else
              hi = q;
            double next = q - f / df;
            if (!(df > 0) || !(next > lo && next < hi))
              next = 0.5 * (lo + hi);
            if (std::abs(next - q) <= tol || hi - lo <= tol)
              {
                q = next;
                break;
              }
            q = next;
          }
      return {q, piece_point(piece, q).distance(p)};
    }
  };


  template <typename Check>
  void
  SpurGear::Impl::make_internal(const Check &ok)
  {
    {
      Impl        &g = *this;
      auto        &p = g.prm;
      const double m = p.module;
      ok(p.bore_radius == 0, "an internal gear has no bore: its body reaches from the teeth out to the rim radius "
                             "(set 'rim radius', leave 'bore radius' 0).");
      // the profile shift x as ISO 21771 signs it for internal gears (with
      // z < 0 in its formulas): a positive x moves the tooth profile toward
      // the centre, which thickens the teeth on the reference circle and
      // moves the tip and root circles inward
      const double x = p.profile_shift;
      g.internal     = true;
      g.ra           = g.r - m * (p.addendum + x); // the tip circle, inside
      g.rf           = g.r + m * (p.dedendum - x); // the root circle, outside
      g.rho_f        = p.rack_tip_radius * m;
      const double s = m * (dealii::numbers::PI / 2 + 2 * x * std::tan(g.alpha)) - p.backlash; // the tooth on the reference circle
      ok(s > 0, "the backlash allowance " + number_string(p.backlash) + " leaves no tooth.");
      // the flank's polar angle psi_b + inv(alpha_rho): s / (2 r) on the reference circle
      g.psi_b = s / (2 * g.r) - involute_function(g.alpha);
      ok(g.ra > g.rb * (1 + 1e-9), "the tip circle of an internal gear (radius " + number_string(g.ra) +
                                     ") must lie outside the base circle (radius " + number_string(g.rb) +
                                     "): lower the addendum coefficient or raise the number of teeth.");
      // the fillet circle touches the root circle from inside (centre at
      // radius r_f - rho_f) and the flank from the space: its centre is the
      // flank point P(t) moved by rho_f along the normal into the space,
      // |P + rho_f n|^2 = (r_b t - rho_f)^2 + r_b^2
      const double rc = g.rf - g.rho_f;
      ok(rc > g.rb, "the root fillet radius " + number_string(g.rho_f) + " is too large for the root circle.");
      g.t_form   = (g.rho_f + std::sqrt(rc * rc - g.rb * g.rb)) / g.rb;
      g.rho_form = g.rb * std::sqrt(1 + g.t_form * g.t_form);
      ok(g.rho_form > g.ra, "the root fillet reaches the tip circle: no flank is left (lower 'rack tip radius' " +
                              number_string(p.rack_tip_radius) + " or raise the dedendum).");
      const double           a_n      = g.psi_b + g.t_form;
      const dealii::Point<2> P        = g.involute(g.t_form);
      g.fillet_c                      = P + g.rho_f * dealii::Tensor<1, 2>({-std::sin(a_n), std::cos(a_n)});
      g.fillet_a0                     = std::atan2(g.fillet_c[1], g.fillet_c[0]);
      const dealii::Tensor<1, 2> back = P - g.fillet_c;
      g.fillet_a1                     = std::atan2(back[1], back[0]);
      g.fillet_a1 -= 2 * dealii::numbers::PI * std::round((g.fillet_a1 - g.fillet_a0) / (2 * dealii::numbers::PI));
      g.phi_root = g.fillet_a0;
      ok(g.phi_root < g.tau, "the root fillets of neighbouring teeth would cross (lower 'rack tip radius' " +
                               number_string(p.rack_tip_radius) + " or the backlash).");
      // tip relief: from the relief radius inward to the tip circle. In the
      // frame of the string's base point the involute point is r_b (1, -t)
      // and the normal (0, 1), so the relieved flank reaches the tip circle
      // where r_b^2 + (r_b t + C_a)^2 = r_a^2, at t = t_a - C_a / r_b
      const double t_a = std::sqrt(g.ra * g.ra / (g.rb * g.rb) - 1.);
      if (p.tip_relief > 0)
        {
          if (p.tip_relief_radius == 0)
            p.tip_relief_radius = 0.5 * (g.r + g.ra);
          ok(p.tip_relief_radius > g.ra && p.tip_relief_radius < g.rho_form,
             "the tip relief radius " + number_string(p.tip_relief_radius) + " of an internal gear must lie between "
             "the tip radius " + number_string(g.ra) + " and the form radius " + number_string(g.rho_form) + ".");
          g.relief_t = std::sqrt(p.tip_relief_radius * p.tip_relief_radius / (g.rb * g.rb) - 1.);
          ok(p.tip_relief < 0.5 * g.rb * t_a && p.tip_relief < 0.5 * g.ra * (involute_function(std::atan(t_a)) + g.psi_b),
             "the tip relief " + number_string(p.tip_relief) + " removes the tooth's tip land.");
        }
      g.t_end                    = t_a - p.tip_relief / g.rb;
      const dealii::Point<2> tip = g.flank(g.t_end);
      g.phi_tip                  = std::atan2(tip[1], tip[0]);
      ok(g.phi_tip > 1e-3 * g.tau, "the teeth are pointed: no tip land is left (lower the addendum or the shift).");
      if (p.rim_radius == 0)
        p.rim_radius = g.rf + 3 * m;
      ok(std::isfinite(p.rim_radius) && p.rim_radius > g.rf + m, "the rim radius " + number_string(p.rim_radius) +
                                                                   " must exceed the root radius plus a module (" +
                                                                   number_string(g.rf + m) + ").");

      // the seven pieces of a pitch, counter-clockwise: root arc (outside),
      // fillet, flank down to the tip, tip arc (inside), flank, fillet, root arc
      g.tabulate(g.pieces[0], Piece::root_arc, false, -g.tau, -g.phi_root);
      g.tabulate(g.pieces[1], Piece::fillet, true, 0., 1.);
      g.tabulate(g.pieces[2], Piece::involute, true, g.t_form * g.t_form, g.t_end * g.t_end);
      g.tabulate(g.pieces[3], Piece::tip_arc, false, -g.phi_tip, g.phi_tip);
      g.tabulate(g.pieces[4], Piece::involute, false, g.t_end * g.t_end, g.t_form * g.t_form);
      g.tabulate(g.pieces[5], Piece::fillet, false, 1., 0.);
      g.tabulate(g.pieces[6], Piece::root_arc, false, g.phi_root, g.tau);
      // the outline must be a simple curve: radius rising along flank and fillet
      for (const unsigned int i : {4u, 5u})
        for (unsigned int k = 1; k <= n_samples; ++k)
          ok(g.pieces[i].points[k].norm() > g.pieces[i].points[k - 1].norm() - 1e-14 * g.rf,
             "the flank or fillet of the internal gear is not monotone in radius.");
    }
  }


  SpurGear::SpurGear(const Parameters &parameters)
    : impl(std::make_unique<Impl>())
  {
    Impl &g  = *impl;
    g.prm    = parameters;
    auto &p  = g.prm;
    auto  ok = [](const bool condition, const std::string &message) {
      AssertThrow(condition, dealii::ExcMessage("SpurGear: " + message));
    };
    ok(std::isfinite(p.module) && p.module > 0, "the module must be positive, not " + number_string(p.module) + ".");
    ok(p.n_teeth >= 5, "a gear needs at least 5 teeth, not " + std::to_string(p.n_teeth) + ".");
    ok(std::isfinite(p.pressure_angle) && p.pressure_angle > 0 && p.pressure_angle < 35 * dealii::numbers::PI / 180,
       "the pressure angle must lie in (0, 35) degrees, not " + number_string(p.pressure_angle * 180 / dealii::numbers::PI) +
         " degrees.");
    ok(std::isfinite(p.profile_shift) && std::abs(p.profile_shift) < 2,
       "the profile shift coefficient must lie in (-2, 2), not " + number_string(p.profile_shift) + ".");
    ok(std::isfinite(p.addendum) && p.addendum > 0, "the addendum coefficient must be positive.");
    ok(std::isfinite(p.dedendum) && p.dedendum > 0, "the dedendum coefficient must be positive.");
    ok(std::isfinite(p.rack_tip_radius) && p.rack_tip_radius >= 0,
       "the rack tip radius coefficient must not be negative.");
    ok(std::isfinite(p.backlash) && p.backlash >= 0, "the backlash allowance must not be negative.");
    ok(std::isfinite(p.tip_relief) && p.tip_relief >= 0, "the tip relief must not be negative.");
    ok(std::isfinite(p.center[0]) && std::isfinite(p.center[1]) && std::isfinite(p.rotation),
       "the centre and the rotation must be finite.");

    const double m = p.module;
    g.alpha        = p.pressure_angle;
    g.tau          = dealii::numbers::PI / p.n_teeth;
    g.r            = m * p.n_teeth / 2;
    g.rb           = g.r * std::cos(g.alpha);
    ok(p.internal || p.rim_radius == 0, "the rim radius is for internal gears (set 'internal'); an external gear "
                                        "reaches from its bore to the teeth.");
    if (p.internal)
      {
        g.make_internal(ok);
        g.starts[0] = 0;
        for (unsigned int i = 0; i < 7; ++i)
          g.starts[i + 1] = g.starts[i] + g.pieces[i].length.back();
        return;
      }
    g.ra           = g.r + m * (p.addendum + p.profile_shift);
    g.rf           = g.r - m * (p.dedendum - p.profile_shift);
    g.rho_f        = p.rack_tip_radius * m;
    g.d            = m * (p.dedendum - p.profile_shift) - g.rho_f;
    const double s = m * (dealii::numbers::PI / 2 + 2 * p.profile_shift * std::tan(g.alpha)) - p.backlash;
    ok(s > 0, "the backlash allowance " + number_string(p.backlash) + " leaves no tooth.");
    g.psi_b = s / (2 * g.r) + involute_function(g.alpha);
    ok(g.rf > 0, "the root radius " + number_string(g.rf) + " is not positive (dedendum too large).");
    ok(g.d > 0, "the rack's corner centre lies above the rolling line (dedendum - profile shift must exceed the "
                "rack tip radius coefficient).");

    // the form radius: where the rack corner's circle leaves its straight
    // flank, whose normal makes the angle alpha with the rolling line
    g.beta_max = dealii::numbers::PI / 2 - g.alpha;
    const dealii::Point<2> e_alpha(g.d * std::tan(g.beta_max) + g.rho_f * std::sin(g.beta_max),
                                   g.r - g.d - g.rho_f * std::cos(g.beta_max));
    g.rho_form = e_alpha.norm();
    // that point lies on the line of action at the distance d / sin(alpha)
    // + rho_f from the pitch point; beyond the line's tangent point on the
    // base circle (r sin(alpha) from the pitch point) the rack cuts into
    // the involute it has made: undercut
    const double along = g.d / std::sin(g.alpha) + g.rho_f, limit = g.r * std::sin(g.alpha);
    ok(along < limit * (1 - 1e-9), "the teeth are undercut: the rack's straight flank reaches " + number_string(along) +
                                     " along the line of action, beyond its tangent point on the base circle at " +
                                     number_string(limit) +
                                     " (in modules: dedendum - profile shift - rack tip radius (1 - sin alpha) must "
                                     "stay below z sin^2(alpha) / 2); "
                                     "raise the profile shift coefficient (now " +
                                     number_string(p.profile_shift) + ") or the number of teeth.");
    g.t_form = std::sqrt(g.rho_form * g.rho_form / (g.rb * g.rb) - 1.);
    ok(g.ra > g.rho_form, "the tip radius lies below the form radius: no flank is left.");
    // place the rack so that its straight flank cuts this flank: the corner
    // leaves the straight flank (beta = beta_max) at the flank's point at the form radius
    const double psi_form = g.psi_b - involute_function(std::atan(g.t_form));
    g.c_x      = g.d * std::tan(g.beta_max) - g.r * (psi_form - (std::atan2(e_alpha[1], e_alpha[0]) - dealii::numbers::PI / 2));
    g.phi_root = g.roll(0.);
    ok(g.phi_root < g.tau,
       "the rack tip is too round for the tooth space: the fillets of neighbouring teeth would cross (lower "
       "'rack tip radius' " +
         number_string(p.rack_tip_radius) + " or the dedendum).");

    // tip: the tooth must keep a land, and the relief must end inside the tooth
    const double t_a = std::sqrt(g.ra * g.ra / (g.rb * g.rb) - 1.);
    if (p.tip_relief > 0)
      {
        if (p.tip_relief_radius == 0)
          p.tip_relief_radius = 0.5 * (g.r + g.ra);
        ok(p.tip_relief_radius > g.rho_form && p.tip_relief_radius < g.ra,
           "the tip relief radius " + number_string(p.tip_relief_radius) + " must lie between the form radius " +
             number_string(g.rho_form) + " and the tip radius " + number_string(g.ra) + ".");
        g.relief_t = std::sqrt(p.tip_relief_radius * p.tip_relief_radius / (g.rb * g.rb) - 1.);
        ok(p.tip_relief < 0.5 * g.ra * (g.psi_b - involute_function(std::atan(t_a))),
           "the tip relief " + number_string(p.tip_relief) + " removes the tooth's tip land.");
      }
    // the relieved flank ends where it reaches the tip circle, with the
    // full relief there: in the frame of the string's base point the
    // involute point is r_b (1, t) and the normal (0, 1), so
    // r_b^2 + (r_b t - C_a)^2 = r_a^2 at t = t_a + C_a / r_b
    g.t_end                       = t_a + p.tip_relief / g.rb;
    const dealii::Point<2> corner = g.flank(g.t_end);
    g.phi_tip                     = std::atan2(corner[1], corner[0]);
    ok(g.phi_tip > 1e-3 * g.tau, "the teeth are pointed: no tip land is left (lower the addendum or the shift).");

    if (p.bore_radius == 0)
      p.bore_radius = 0.5 * g.rf;
    ok(std::isfinite(p.bore_radius) && p.bore_radius > 0 && p.bore_radius < 0.9 * g.rf,
       "the bore radius " + number_string(p.bore_radius) +
         " must lie in (0, 0.9 root radius = " + number_string(0.9 * g.rf) + ").");

    // the seven pieces of a pitch, counter-clockwise
    g.tabulate(g.pieces[0], Piece::root_arc, false, -g.tau, -g.phi_root);
    g.tabulate(g.pieces[1], Piece::fillet, true, 0., std::tan(g.beta_max));
    g.tabulate(g.pieces[2], Piece::involute, true, g.t_form * g.t_form, g.t_end * g.t_end);
    g.tabulate(g.pieces[3], Piece::tip_arc, false, -g.phi_tip, g.phi_tip);
    g.tabulate(g.pieces[4], Piece::involute, false, g.t_end * g.t_end, g.t_form * g.t_form);
    g.tabulate(g.pieces[5], Piece::fillet, false, std::tan(g.beta_max), 0.);
    g.tabulate(g.pieces[6], Piece::root_arc, false, g.phi_root, g.tau);
    g.starts[0] = 0;
    for (unsigned int i = 0; i < 7; ++i)
      g.starts[i + 1] = g.starts[i] + g.pieces[i].length.back();

    // the outline must be a simple curve: radius rising along fillet and flank
    for (const unsigned int i : {4u, 5u})
      for (unsigned int k = 1; k <= n_samples; ++k)
        ok(g.pieces[i].points[k].norm() < g.pieces[i].points[k - 1].norm(),
           "the flank or fillet is not monotone in radius (an undercut or an excessive tip relief).");
  }


  SpurGear::~SpurGear() = default;

  SpurGear::SpurGear(const SpurGear &other)
    : impl(std::make_unique<Impl>(*other.impl))
  {}

  SpurGear &
  SpurGear::operator=(const SpurGear &other)
  {
    *impl = *other.impl;
    return *this;
  }

  const SpurGear::Parameters &
  SpurGear::parameters() const
  {
    return impl->prm;
  }

  double
  SpurGear::reference_radius() const
  {
    return impl->r;
  }

  double
  SpurGear::base_radius() const
  {
    return impl->rb;
  }

  double
  SpurGear::tip_radius() const
  {
    return impl->ra;
  }

  double
  SpurGear::root_radius() const
  {
    return impl->rf;
  }

  double
  SpurGear::form_radius() const
  {
    return impl->rho_form;
  }

  double
  SpurGear::base_pitch() const
  {
    return dealii::numbers::PI * impl->prm.module * std::cos(impl->alpha);
  }

  double
  SpurGear::angular_pitch() const
  {
    return 2 * impl->tau;
  }

  double
  SpurGear::base_half_angle() const
  {
    return impl->psi_b;
  }

  double
  SpurGear::flank_half_angle(const double radius) const
  {
    AssertThrow(radius >= impl->rb, dealii::ExcMessage("SpurGear::flank_half_angle: radius below the base circle."));
    const double inv = involute_function(std::acos(impl->rb / radius));
    return impl->internal ? impl->psi_b + inv : impl->psi_b - inv;
  }

  double
  SpurGear::tip_relief_at(const double radius) const
  {
    if (radius <= impl->rb)
      return 0.;
    return impl->relief(std::sqrt(radius * radius / (impl->rb * impl->rb) - 1.));
  }

  double
  SpurGear::outline_pitch_length() const
  {
    return impl->starts[7];
  }

  const std::array<double, 8> &
  SpurGear::piece_starts() const
  {
    return impl->starts;
  }

  unsigned int
  SpurGear::n_teeth() const
  {
    return impl->prm.n_teeth;
  }

  bool
  SpurGear::is_internal() const
  {
    return impl->internal;
  }

  double
  SpurGear::body_radius() const
  {
    return impl->internal ? impl->prm.rim_radius : impl->prm.bore_radius;
  }

  dealii::Point<2>
  SpurGear::outline_point(const double s) const
  {
    const Impl  &g     = *impl;
    const double L     = g.starts[7];
    const double k     = std::floor(s / L);
    double       local = s - k * L;
    local              = std::min(std::max(local, 0.), L);
    unsigned int j     = std::upper_bound(g.starts.begin() + 1, g.starts.end() - 1, local) - g.starts.begin() - 1;
    const double q     = Impl::parameter_at(g.pieces[j], local - g.starts[j]);
    const double axis  = g.prm.rotation + 2 * g.tau * k;
    return g.prm.center + rotated(g.piece_point(g.pieces[j], q), axis);
  }

  dealii::Tensor<1, 2>
  SpurGear::outline_tangent(const double s) const
  {
    const double h = 1e-7 * impl->starts[7];
    return (outline_point(s + h) - outline_point(s - h)) / (2 * h);
  }

  double
  SpurGear::outline_coordinate(const dealii::Point<2> &p, const double reference_s) const
  {
    const Impl                &g     = *impl;
    const dealii::Tensor<1, 2> rel   = p - g.prm.center;
    const double               phi   = std::atan2(rel[1], rel[0]) - g.prm.rotation;
    const double               k     = std::round(phi / (2 * g.tau));
    const dealii::Point<2>     local = rotated(dealii::Point<2>(rel), -(g.prm.rotation + 2 * g.tau * k));
    double                     best = std::numeric_limits<double>::max(), s = 0;
    for (unsigned int j = 0; j < 7; ++j)
      {
        // a point of the upper half lies on pieces 3 to 6, of the lower on 0 to 3
        if ((local[1] > 0 && j < 3) || (local[1] < 0 && j > 3))
          continue;
        const auto [q, dist] = g.project(g.pieces[j], local);
        if (dist < best)
          best = dist, s = g.starts[j] + Impl::length_at(g.pieces[j], q);
      }
    // tooth k's pitch starts half a pitch before its axis
    const double L     = g.starts[7];
    double       value = k * L + s;
    const double P     = L * g.prm.n_teeth;
    value += P * std::round((reference_s - value) / P);
    return value;
  }

  double
  SpurGear::distance_to_outline(const dealii::Point<2> &p) const
  {
    return outline_point(outline_coordinate(p)).distance(p);
  }

  SpurGear::Piece
  SpurGear::piece(const double s) const
  {
    const double L     = impl->starts[7];
    const double local = s - std::floor(s / L) * L;
    unsigned int j =
      std::upper_bound(impl->starts.begin() + 1, impl->starts.end() - 1, local) - impl->starts.begin() - 1;
    return impl->pieces[j].kind;
  }

  std::vector<dealii::Point<2>>
  SpurGear::outline(const unsigned int first, const unsigned int n, const double spacing) const
  {
    AssertThrow(spacing > 0, dealii::ExcMessage("SpurGear::outline: the spacing must be positive."));
    std::vector<dealii::Point<2>> points;
    const double                  L = impl->starts[7];
    for (unsigned int k = first; k < first + n; ++k)
      for (unsigned int j = 0; j < 7; ++j)
        {
          const double a = impl->starts[j], b = impl->starts[j + 1];
          if (b - a <= 0)
            continue;
          const unsigned int m = std::max<unsigned int>(1, std::ceil((b - a) / spacing));
          for (unsigned int i = (points.empty() ? 0 : 1); i <= m; ++i)
            points.push_back(outline_point(k * L + a + (b - a) * i / m));
        }
    return points;
  }

  double
  SpurGear::area(const unsigned int first, const unsigned int n) const
  {
    // Green: area = 1/2 closed integral of (x dy - y dx), about the centre;
    // the radial sides of a sector add nothing, the bore arc is subtracted
    const Impl  &g = *impl;
    const double L = g.starts[7];
    // 8-point Gauss rule per piece subinterval
    static const double xg[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
    static const double wg[4] = {0.3626837833783620, 0.3137066533153911, 0.2223810344533745, 0.1012285362903763};
    // the integral over [q0, q1] of one piece
    const auto integral = [&](const OutlinePiece &piece, const double q0, const double q1) {
      double part = 0;
      for (unsigned int gq = 0; gq < 8; ++gq)
        {
          const double xi = (gq < 4 ? -xg[gq] : xg[gq - 4]), w = wg[gq % 4];
          const double q  = 0.5 * (q0 + q1) + 0.5 * (q1 - q0) * xi;
          const double h  = 1e-5 * std::abs(q1 - q0);
          const auto   c  = g.piece_point(piece, q);
          const auto   dc = (g.piece_point(piece, q + h) - g.piece_point(piece, q - h)) / (2 * h);
          part += 0.5 * w * 0.5 * (q1 - q0) * (c[0] * dc[1] - c[1] * dc[0]);
        }
      return part;
    };
    // the flank's kink where the tip relief starts (q = t^2 on an involute
    // piece): the Gauss rule is split there, so that it integrates smooth
    // pieces only (a kink inside a rule costs 4e-6 of a ring's area)
    const double kink  = (g.prm.tip_relief > 0 ? g.relief_t * g.relief_t : -1.);
    double       sum   = 0;
    for (unsigned int k = first; k < first + n; ++k)
      for (unsigned int j = 0; j < 7; ++j)
        for (unsigned int i = 0; i < n_samples; ++i)
          {
            // integrate in the piece's parameter q over one sample interval
            const auto  &piece = g.pieces[j];
            const double q0 = piece.q[i], q1 = piece.q[i + 1];
            if (piece.kind == Piece::involute && kink > std::min(q0, q1) && kink < std::max(q0, q1))
              sum += integral(piece, q0, kink) + integral(piece, kink, q1);
            else
              sum += integral(piece, q0, q1);
          }
    (void)L;
    if (g.internal)
      {
        // the ring between the outline and the rim
        const double R = g.prm.rim_radius;
        return 0.5 * R * R * 2 * g.tau * n - sum;
      }
    const double rb = g.prm.bore_radius;
    return sum - 0.5 * rb * rb * 2 * g.tau * n;
  }
} // namespace dealvem
