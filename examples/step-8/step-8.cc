// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// step-8: a masonry arch.
//
// Build (from a dealvem build directory):   make step-8
// Run:                                      ./examples/step-8 [--study] [--write-doc-picture]
// What it does: a semicircular arch of N = 19 voussoirs (mean radius
// R = 10 m, thickness t, radial joints) stands on two abutment blocks whose
// bottoms are fixed, under its self-weight (rho g = 20 kN/m^3; E = 20 GPa,
// so that E / (rho g R) = 1e5). The program writes the whole assembly as
// one gmsh file (a physical surface per block, every block with nodes of
// its own, neighbouring voussoirs with 2 and 3 cells along their common
// joint: the joints do not match; a physical line on the abutments'
// bottoms), reads it back with PolygonalMeshGenerators::from_gridin_file(),
// makes every block a body (ContactProblem::add_parts()) and lets
// ContactDetection find the joints. Normal contact is unilateral (active
// set), the joints stick (tangential multipliers): Heyman's masonry, no
// tension and no sliding. For each thickness it prints the thrust line
// (normal and shear force and the eccentricity of the centre of pressure at
// every joint), checks it against the statics of the blocks and against a
// rigid-block limit analysis of the same geometry, whose least thickness
// is the reference: below it the contact solver must stop with "No static
// equilibrium" (reported as a collapse) and a collapse mechanism that proves
// it (just below the limit: four or more hinges where the limit analysis
// has them), above it the arch must stand and pass every check, 1.01 and
// 1.02 times the least thickness included. It exits with an error if any
// of this fails.
// --study scans t/R = 0.100 to 0.120 also for N = 9 to 25 and k = 1;
// --write-doc-picture writes the picture of the thrust line into doc/.

// @sect3{Include files}
#include <deal.II/base/exceptions.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/base/number_string.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/polygonal_mesh.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace Step8
{
  using namespace dealvem;
  using Point  = dealii::Point<2>;
  using Vector = dealii::Tensor<1, 2>;

  // @sect3{The data}
  //
  // kN and m. The stiffness only sets the size of the displacements: in
  // the small-displacement theory whether a no-tension assembly can stand
  // does not depend on E at all (see the introduction). E / (rho g R) = 1e5
  // keeps the displacements (rho g R^2 / E = 0.1 mm) far below the
  // thickness, so that the geometry is, as the theory assumes, the
  // undeformed one.
  constexpr double R        = 10.;   // mean radius
  constexpr double rho_g    = 20.;   // specific weight, kN/m^3
  constexpr double E        = 2e7;   // Young's modulus, kN/m^2
  constexpr double nu       = 0.2;   // Poisson's ratio
  constexpr double pi       = M_PI;

  // The boundary id (gmsh physical line) of the fixed bottoms of the
  // abutments.
  constexpr unsigned int fixed_id = 1;

  // @sect3{The geometry of the arch}
  //
  // Blocks are numbered from left to right: 0 the left abutment, 1 to N the
  // voussoirs, N + 1 the right abutment; block b is gmsh physical surface
  // b + 1, and since add_parts() numbers the bodies in increasing order of
  // the material ids, also body b. Joint j (0 to N) lies between blocks j
  // and j + 1, on the ray at the angle theta_j = pi (1 - j / N) from the
  // centre of the arch (joint 0 and N are the springers, on y = 0).
  // Voussoir i spans the angles theta_{i-1} to theta_i; its intrados and
  // extrados are polygons through n_arc + 1 points on the circles of radii
  // R - t/2 and R + t/2 (the cells have straight edges), and it is cut into
  // n_arc x m_i cells, m_i = 2 or 3 layers across the thickness
  // alternately: the two sides of a joint have 2 and 3 edges. The abutments
  // are squares t x t under the springers, 4 x 2 cells.
  struct Arch
  {
    unsigned int N;
    double       t;
    unsigned int n_arc = 2;

    double
    theta(const unsigned int j) const
    {
      return pi * (1. - double(j) / N);
    }
    Vector
    ray(const unsigned int j) const
    {
      return Vector({std::cos(theta(j)), std::sin(theta(j))});
    }
    unsigned int
    layers(const unsigned int voussoir) const
    {
      return (voussoir % 2 == 1) ? 2 : 3;
    }
    // The point at radius r on the ray of the angle a.
    static Point
    polar(const double r, const double a)
    {
      return Point(r * std::cos(a), r * std::sin(a));
    }
    // The outline of block b, counter-clockwise.
    std::vector<Point>
    outline(const unsigned int b) const
    {
      std::vector<Point> p;
      if (b == 0 || b == N + 1)
        {
          const double xc = (b == 0 ? -R : R);
          p = {Point(xc - t / 2, -t), Point(xc + t / 2, -t), Point(xc + t / 2, 0), Point(xc - t / 2, 0)};
          return p;
        }
      const double a0 = theta(b - 1), a1 = theta(b);
      for (unsigned int l = 0; l <= n_arc; ++l)
        p.push_back(polar(R - t / 2, a0 + (a1 - a0) * l / n_arc));
      for (unsigned int l = 0; l <= n_arc; ++l)
        p.push_back(polar(R + t / 2, a1 + (a0 - a1) * l / n_arc));
      return p;
    }
  };

  // Area and centroid of a polygon (the shoelace formulas).
  std::pair<double, Point>
  area_and_centroid(const std::vector<Point> &p)
  {
    double a = 0, cx = 0, cy = 0;
    for (unsigned int k = 0; k < p.size(); ++k)
      {
        const Point &q = p[k], &r = p[(k + 1) % p.size()];
        const double c = q[0] * r[1] - r[0] * q[1];
        a += c;
        cx += (q[0] + r[0]) * c;
        cy += (q[1] + r[1]) * c;
      }
    return {a / 2, Point(cx / (3 * a), cy / (3 * a))};
  }

  // @sect3{The gmsh file}
  //
  // The whole assembly in gmsh's ASCII format 2.2: every block numbers its
  // own nodes (nothing is shared across a joint), the cells are
  // quadrilaterals (element type 3) tagged with the physical surface b + 1
  // of their block, and the bottom edges of the abutments are lines
  // (element type 1) of physical line fixed_id. The format lists the nodes
  // of a quadrilateral counter-clockwise.
  void
  write_gmsh(const Arch &arch, const std::string &filename)
  {
    std::vector<Point>                                        nodes;
    std::vector<std::pair<unsigned int, std::array<unsigned int, 4>>> quads; // physical id, nodes
    std::vector<std::array<unsigned int, 2>>                  fixed_lines;
    // a grid of (n0 + 1) x (n1 + 1) nodes of one block, place(i0, i1) its
    // positions; returns the index of node (0, 0), the others follow
    // lexicographically
    auto add_grid = [&](const unsigned int block, const unsigned int n0, const unsigned int n1, auto place) {
      const unsigned int first = nodes.size();
      for (unsigned int i1 = 0; i1 <= n1; ++i1)
        for (unsigned int i0 = 0; i0 <= n0; ++i0)
          nodes.push_back(place(i0, i1));
      auto id = [&](const unsigned int i0, const unsigned int i1) { return first + i1 * (n0 + 1) + i0; };
      for (unsigned int i1 = 0; i1 < n1; ++i1)
        for (unsigned int i0 = 0; i0 < n0; ++i0)
          quads.push_back({block + 1, {{id(i0, i1), id(i0 + 1, i1), id(i0 + 1, i1 + 1), id(i0, i1 + 1)}}});
      return first;
    };
    const double t = arch.t;
    for (const unsigned int b : {0u, arch.N + 1})
      {
        const double       x0    = (b == 0 ? -R : R) - t / 2;
        const unsigned int first = add_grid(b, 4, 2, [&](const unsigned int i, const unsigned int k) {
          return Point(x0 + t * i / 4., -t + t * k / 2.);
        });
        for (unsigned int i = 0; i < 4; ++i)
          fixed_lines.push_back({{first + i, first + i + 1}});
      }
    // a voussoir: i0 along the arc from theta_{b-1} to theta_b (clockwise
    // about the centre, so left to right), i1 outward from the intrados:
    // counter-clockwise cells
    for (unsigned int b = 1; b <= arch.N; ++b)
      {
        const unsigned int m  = arch.layers(b);
        const double       a0 = arch.theta(b - 1), a1 = arch.theta(b);
        add_grid(b, arch.n_arc, m, [&](const unsigned int i, const unsigned int k) {
          return Arch::polar(R - t / 2 + t * k / m, a0 + (a1 - a0) * i / arch.n_arc);
        });
      }

    std::ofstream out(filename);
    AssertThrow(out, dealii::ExcMessage("step-8: cannot write " + filename));
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << nodes.size() << "\n" << std::setprecision(17);
    for (unsigned int n = 0; n < nodes.size(); ++n)
      out << n + 1 << " " << nodes[n][0] << " " << nodes[n][1] << " 0\n";
    out << "$EndNodes\n$Elements\n" << fixed_lines.size() + quads.size() << "\n";
    unsigned int element = 0;
    // element: number, type, 2 tags (physical, elementary), nodes (from 1)
    for (const auto &l : fixed_lines)
      out << ++element << " 1 2 " << fixed_id << " " << fixed_id << " " << l[0] + 1 << " " << l[1] + 1 << "\n";
    for (const auto &[physical, q] : quads)
      out << ++element << " 3 2 " << physical << " " << physical << " " << q[0] + 1 << " " << q[1] + 1 << " "
          << q[2] + 1 << " " << q[3] + 1 << "\n";
    out << "$EndElements\n";
    AssertThrow(out, dealii::ExcMessage("step-8: writing " + filename + " failed"));
  }

  // @sect3{Rigid-block limit analysis}
  //
  // The reference for the contact solution: Heyman's safe theorem for the
  // same blocks. Cut the arch at joint j; the force $F_j$ that the blocks
  // left of the cut transmit to those right of it is, by the equilibrium of
  // the left part, the reaction $F_0 = (H, V)$ of the left abutment minus
  // the weights $w_b$ of the voussoirs 1 to j, and its moment about the
  // centre of the arch is $M_j = M_0 - \sum_{b \le j} x_b w_b$ ($x_b$ the
  // abscissa of the centroid of voussoir b). The joint is the ray
  // $\rho\,u_j$, $R - t/2 \le \rho \le R + t/2$, and the line of action of
  // $F_j$ crosses it at $\rho_j = M_j / (u_j \times F_j)$. The arch can
  // stand (with no tension and no sliding) if and only if some $(H, V,
  // M_0)$ puts every $\rho_j$ inside its joint with a compressive $F_j$
  // ($u_j\times F_j < 0$ with the blocks numbered clockwise), i.e.
  // @f[
  //   (R + t/2)\,k_j - C_j \;\le\; M_0 \;\le\; (R - t/2)\,k_j - C_j ,
  //   \qquad k_j = u_j\times F_j,\quad C_j = -\sum_{b\le j} x_b w_b ,
  // @f]
  // for j = 0, ..., N. The blocks are symmetric about x = 0, so a
  // symmetric solution exists if any does (the mean of a solution and its
  // mirror image); it has V = W/2, W the weight of the arch. For a given H
  // the conditions are an interval of $M_0$; the width of the intersection,
  // $g(H) = \min_j(\text{upper}_j) - \max_j(\text{lower}_j)$, is a concave
  // function of H (a minimum of linear functions minus a maximum of linear
  // functions). The arch stands if $\max_H g(H) \ge 0$, and the thrusts H
  // with $g(H) \ge 0$ are the statically admissible ones, an interval
  // $[H_{\min}, H_{\max}]$ that closes to one value at the least
  // thickness.
  struct LimitAnalysis
  {
    Arch                arch;
    std::vector<double> w;  // weights of the voussoirs 1..N (index b)
    std::vector<double> xg; // abscissae of their centroids
    double              W = 0;

    explicit LimitAnalysis(const Arch &a)
      : arch(a)
      , w(a.N + 1, 0.)
      , xg(a.N + 1, 0.)
    {
      for (unsigned int b = 1; b <= a.N; ++b)
        {
          const auto [area, centroid] = area_and_centroid(a.outline(b));
          w[b]                        = rho_g * area;
          xg[b]                       = centroid[0];
          W += w[b];
        }
    }

    double
    g(const double H) const
    {
      double       lower = -1e300, upper = 1e300, Fy = W / 2, C = 0;
      const double ri = R - arch.t / 2, ro = R + arch.t / 2;
      for (unsigned int j = 0; j <= arch.N; ++j)
        {
          if (j > 0)
            {
              Fy -= w[j];
              C -= xg[j] * w[j];
            }
          const Vector u = arch.ray(j);
          const double k = u[0] * Fy - u[1] * H;
          lower          = std::max(lower, ro * k - C);
          upper          = std::min(upper, ri * k - C);
        }
      return upper - lower;
    }

    // The eccentricities e_j / (t/2) of the thrust line with the thrust H
    // and M_0 in the middle of its admissible interval.
    std::vector<double>
    eccentricities(const double H) const
    {
      double       lower = -1e300, upper = 1e300, Fy = W / 2, C = 0;
      const double ri = R - arch.t / 2, ro = R + arch.t / 2;
      std::vector<double> k(arch.N + 1), c(arch.N + 1), e(arch.N + 1);
      for (unsigned int j = 0; j <= arch.N; ++j)
        {
          if (j > 0)
            {
              Fy -= w[j];
              C -= xg[j] * w[j];
            }
          const Vector u = arch.ray(j);
          k[j]           = u[0] * Fy - u[1] * H;
          c[j]           = C;
          lower          = std::max(lower, ro * k[j] - C);
          upper          = std::min(upper, ri * k[j] - C);
        }
      const double M0 = (lower + upper) / 2;
      for (unsigned int j = 0; j <= arch.N; ++j)
        e[j] = ((M0 + c[j]) / k[j] - R) / (arch.t / 2);
      return e;
    }

    // The maximum of g over H in (0, W] by golden-section search (g is
    // concave): the H of the maximum, and g there.
    std::pair<double, double>
    best_thrust() const
    {
      const double phi = (std::sqrt(5.) - 1) / 2;
      double       a = 1e-6 * W, b = W;
      double       x1 = b - phi * (b - a), x2 = a + phi * (b - a), g1 = g(x1), g2 = g(x2);
      for (unsigned int it = 0; it < 200 && b - a > 1e-14 * W; ++it)
        if (g1 < g2)
          {
            a  = x1;
            x1 = x2;
            g1 = g2;
            x2 = a + phi * (b - a);
            g2 = g(x2);
          }
        else
          {
            b  = x2;
            x2 = x1;
            g2 = g1;
            x1 = b - phi * (b - a);
            g1 = g(x1);
          }
      const double H = (a + b) / 2;
      return {H, g(H)};
    }

    // The admissible thrusts [H_min, H_max] (bisection on both sides of the
    // maximum); empty (H_min > H_max) when the arch cannot stand.
    std::pair<double, double>
    admissible_thrusts() const
    {
      const auto [H_best, g_best] = best_thrust();
      if (g_best < 0)
        return {1, 0};
      auto edge = [&](double inside, double outside) {
        if (g(outside) >= 0)
          return outside;
        for (unsigned int it = 0; it < 200; ++it)
          {
            const double mid = (inside + outside) / 2;
            (g(mid) >= 0 ? inside : outside) = mid;
          }
        return inside;
      };
      return {edge(H_best, 1e-6 * W), edge(H_best, W)};
    }
  };

  // The least thickness t/R at which N voussoirs stand: bisection on the
  // sign of max_H g(H) between t/R = 0.05 and 0.2.
  double
  least_thickness(const unsigned int N)
  {
    double lo = 0.05, hi = 0.2;
    AssertThrow(LimitAnalysis(Arch{N, hi * R}).best_thrust().second >= 0 &&
                  LimitAnalysis(Arch{N, lo * R}).best_thrust().second < 0,
                dealii::ExcMessage("step-8: the least thickness is not between 0.05 R and 0.2 R"));
    for (unsigned int it = 0; it < 50; ++it)
      {
        const double mid = (lo + hi) / 2;
        (LimitAnalysis(Arch{N, mid * R}).best_thrust().second >= 0 ? hi : lo) = mid;
      }
    return hi;
  }

  // @sect3{The contact solve}
  //
  // One thickness: write the gmsh file, read it back as a user would, make
  // each physical surface a body, let the joints be found, fix the
  // abutments' bottoms, load by the self-weight, solve.
  //
  // ContactProblem prints its report (the detected interfaces, node
  // insertion, the active-set history, the verification) to std::cout, in
  // the stream's current format; unless @p report, the output of run()
  // goes to a string stream. The guard gives std::cout its default format
  // for the report and restores the stream, also when run() throws.
  struct SilentCout
  {
    explicit SilentCout(const bool active)
      : old(active ? std::cout.rdbuf(sink.rdbuf()) : nullptr)
      , flags(std::cout.flags())
      , precision(std::cout.precision())
    {
      std::cout.flags(std::ios_base::fmtflags());
      std::cout.precision(6);
    }
    ~SilentCout()
    {
      if (old != nullptr)
        std::cout.rdbuf(old);
      std::cout.flags(flags);
      std::cout.precision(precision);
    }
    std::ostringstream      sink;
    std::streambuf         *old;
    std::ios_base::fmtflags flags;
    std::streamsize         precision;
  };

  // The collapse mechanism of the last solve that found no equilibrium.
  std::unique_ptr<CollapseMechanism> last_mechanism;

  // The joints: 0 sticks (tangential multipliers, Heyman's no sliding);
  // a positive value is Coulomb friction with that coefficient.
  double joint_friction = 0;

  ContactProblem::Results
  solve(const Arch &arch, const unsigned int degree, const std::string &msh_file, const bool report)
  {
    write_gmsh(arch, msh_file);
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::from_gridin_file(mesh, msh_file, 0, /*separate_material_ids=*/true);

    ContactProblem problem(MPI_COMM_SELF);
    const auto     bodies = problem.add_parts(mesh, ElasticMaterial(E, nu, ElasticMaterial::Model::plane_strain));
    AssertThrow(bodies.size() == arch.N + 2,
                dealii::ExcMessage("step-8: " + std::to_string(bodies.size()) + " bodies read from " + msh_file +
                                   ", expected " + std::to_string(arch.N + 2)));
    problem.detect_contact_pairs();
    auto &bc = problem.boundary_conditions();
    bc.add_dirichlet(fixed_id, {{true, true}}, std::make_shared<dealii::Functions::ZeroFunction<2>>(2),
                     "fixed bottoms of the abutments");
    bc.set_body_force(std::make_shared<dealii::Functions::ConstantFunction<2>>(std::vector<double>{0., -rho_g}),
                      "self-weight");
    auto &o              = problem.options();
    o.degree             = degree;
    o.contact.normal     = ContactSettings::Normal::unilateral;
    o.contact.tangential = joint_friction > 0 ? ContactSettings::Tangential::coulomb :
                                                ContactSettings::Tangential::multipliers;
    o.contact.friction_coefficient = joint_friction;
    o.write_vtu = o.write_json = o.write_pictures = o.write_csv = false;
    const SilentCout silent(!report);
    last_mechanism.reset();
    try
      {
        problem.run();
      }
    catch (...)
      {
        // the proof of a collapse, kept for the checks below
        if (problem.collapse_mechanism() != nullptr)
          last_mechanism = std::make_unique<CollapseMechanism>(*problem.collapse_mechanism());
        throw;
      }
    return problem.get_results();
  }

  // @sect3{The thrust line}
  //
  // Per joint j: the force $F_j$ that block j + 1 receives from block j
  // (InterfaceResult::force is the force on the slave body, whichever side
  // that is), its normal part $N_j = F_j\cdot n_j$ ($n_j$ the normal of the
  // joint from block j to j + 1: compression > 0) and its part along the
  // joint $T_j$, the centre of pressure $c_j$ and its eccentricity
  // $e_j = (c_j - R\,u_j)\cdot u_j$ from the middle of the joint (positive
  // toward the extrados).
  struct Joint
  {
    Vector       force;
    double       normal = 0, shear = 0, e = 0;
    Point        centre;
    unsigned int n_open = 0, n_closed = 0;
  };

  struct Report
  {
    bool               stands = false;
    std::string        message; // the exception of a collapse
    std::vector<Joint> joints;
    double             H_left = 0, H_right = 0, V_left = 0, V_right = 0, W = 0;
    double             H_min = 0, H_max = 0; // admissible thrusts of the limit analysis
    double             u_max = 0;            // largest displacement
    unsigned int       iterations = 0, dofs = 0, pairs = 0;
    // some pairs end open but tied tangentially (status open-tied): the
    // solve fell back to the convex stick model, or the fast path held the
    // pairs of a cycle; see the results
    bool               convex = false;
    // a collapse: the hinges of the mechanism (joint, +1 extrados or -1
    // intrados), its work and its largest violation of the conditions
    std::vector<std::pair<unsigned int, int>> hinges;
    double             mechanism_work = 0, mechanism_violation = 0;
    std::string        failing_condition;
  };

  // The checks: every one appends to @p failures when it does not hold.
  void
  check(const bool ok, const std::string &what, std::vector<std::string> &failures)
  {
    if (!ok)
      failures.push_back(what);
  }

  Report
  evaluate(const Arch &arch, const ContactProblem::Results &r, std::vector<std::string> &failures)
  {
    Report             rep;
    const std::string  name = "t/R = " + std::to_string(arch.t / R) + ": ";
    const unsigned int N    = arch.N;
    rep.joints.resize(N + 1);
    std::vector<bool> found(N + 1, false);
    check(r.interface_results.size() == N + 1,
          name + std::to_string(r.interface_results.size()) + " interfaces detected, expected N + 1 = " +
            std::to_string(N + 1),
          failures);
    for (const auto &itf : r.interface_results)
      {
        const unsigned int j = std::min(itf.master_body, itf.slave_body);
        check(std::max(itf.master_body, itf.slave_body) == j + 1 && j <= N,
              name + "an interface between blocks " + std::to_string(itf.master_body) + " and " +
                std::to_string(itf.slave_body) + ", which are not neighbours",
              failures);
        if (j > N || found[j])
          continue;
        found[j]        = true;
        Joint &J        = rep.joints[j];
        J.force         = (itf.slave_body == j + 1 ? itf.force : -itf.force);
        const Vector u  = arch.ray(j);
        const Vector n({u[1], -u[0]});
        J.normal = J.force * n;
        J.shear  = J.force * u;
        J.centre = itf.centre_of_pressure;
        J.e      = (J.centre - Point(R * u[0], R * u[1])) * u;
        J.n_open = itf.n_open;
        J.n_closed = itf.n_stick + itf.n_slip;
        check(std::abs(J.normal - itf.normal_force) <= 1e-10 * std::abs(itf.normal_force) + 1e-12,
              name + "joint " + std::to_string(j) + ": the normal part of the force is not the normal force",
              failures);
        check(std::abs(itf.length - arch.t) <= 1e-10 * arch.t,
              name + "joint " + std::to_string(j) + " has the length " + std::to_string(itf.length), failures);
      }
    for (unsigned int j = 0; j <= N; ++j)
      check(found[j], name + "joint " + std::to_string(j) + " was not detected", failures);

    // The weights: the assembled load of each voussoir against rho g times
    // the area of its outline.
    const LimitAnalysis la(arch);
    rep.W = la.W;
    for (unsigned int b = 1; b <= N; ++b)
      check(std::abs(r.applied_load_per_body[b][1] + la.w[b]) <= 1e-12 * la.W &&
              std::abs(r.applied_load_per_body[b][0]) <= 1e-12 * la.W,
            name + "the load of voussoir " + std::to_string(b) + " is not its weight", failures);

    // Global equilibrium of the arch: the abutments' reactions carry the
    // weight, and the two thrusts are equal (the loads are vertical).
    rep.H_left  = rep.joints[0].force[0];
    rep.V_left  = rep.joints[0].force[1];
    rep.H_right = rep.joints[N].force[0];
    rep.V_right = -rep.joints[N].force[1];
    check(std::abs(rep.V_left + rep.V_right - la.W) <= 1e-10 * la.W,
          name + "the vertical reactions do not add up to the weight", failures);
    check(std::abs(rep.H_left - rep.H_right) <= 1e-10 * la.W, name + "the thrusts at the springers differ",
          failures);

    // The statics of the blocks: from the reaction of the left abutment,
    // the weights alone give the force and the centre of pressure at every
    // other joint (the recursion of the limit analysis, here with the
    // computed reaction); compare with the contact resultants.
    {
      Vector F = rep.joints[0].force;
      double M = rep.joints[0].centre[0] * F[1] - rep.joints[0].centre[1] * F[0];
      for (unsigned int j = 1; j <= N; ++j)
        {
          F[1] -= la.w[j];
          M -= la.xg[j] * la.w[j];
          const Vector u   = arch.ray(j);
          const double rho = M / (u[0] * F[1] - u[1] * F[0]);
          const Joint &J   = rep.joints[j];
          const double rho_computed = (J.centre - Point()) * u;
          check((J.force - F).norm() <= 1e-10 * la.W,
                name + "joint " + std::to_string(j) + ": the force differs from the statics of the blocks", failures);
          check(std::abs(rho - rho_computed) <= 1e-9 * R,
                name + "joint " + std::to_string(j) + ": the centre of pressure differs from the statics (by " +
                  std::to_string(rho - rho_computed) + " m)",
                failures);
        }
    }

    // The centre of pressure lies inside the joint (no tension), and the
    // thrust is statically admissible: within the range of the limit
    // analysis for this thickness.
    for (const auto &p : r.pairs)
      rep.convex = rep.convex || p.status == "open-tied";
    // (an open-tied pair carries shear although open, which moves the
    // line of action of a joint's force: the centre-of-pressure test is
    // Heyman's and applies to the model with free open pairs only). The
    // tolerance 1e-10: where a hinge sits at a corner of the joint, the
    // whole force is at one pair and its neighbours carry the round-off of
    // the multipliers (measured up to 3e-11 of t/2 just above the limit).
    for (unsigned int j = 0; j <= N; ++j)
      check(rep.convex ||
              (std::abs(rep.joints[j].e) <= arch.t / 2 * (1 + 1e-10) && rep.joints[j].normal > 0),
            name + "joint " + std::to_string(j) + ": the thrust line leaves the joint (e/(t/2) = " +
              dealvem::internal::number_string(std::abs(rep.joints[j].e) / (arch.t / 2) - 1) + " + 1, N = " + std::to_string(rep.joints[j].normal) +
              ")",
            failures);
    std::tie(rep.H_min, rep.H_max) = la.admissible_thrusts();
    check(rep.H_left >= rep.H_min * (1 - 1e-9) && rep.H_left <= rep.H_max * (1 + 1e-9),
          name + "the thrust " + std::to_string(rep.H_left) + " kN/m lies outside the admissible range [" +
            std::to_string(rep.H_min) + ", " + std::to_string(rep.H_max) + "]",
          failures);

    // The verification of every body by the library (ForceBalance).
    for (const auto &step : r.steps)
      for (const auto &b : step.balance)
        check(b.imbalance <= b.tolerance && b.residual <= b.tolerance,
              name + "the force balance of body " + std::to_string(b.body) + " fails", failures);

    for (unsigned int i = 0; i < r.solution.size(); ++i)
      rep.u_max = std::max(rep.u_max, std::abs(r.solution[i]));
    rep.iterations = r.active_set_iterations;
    rep.dofs       = r.n_dofs;
    rep.pairs      = r.pairs.size();
    rep.stands     = true;
    return rep;
  }

  // @sect3{Output}
  //
  // The table of the joints.
  void
  print_joints(const Arch &arch, const Report &rep)
  {
    std::cout << " joint | angle from crown | N [kN/m] | T [kN/m] |   T/N  | e/(t/2) | pairs closed/open\n";
    for (unsigned int j = 0; j <= arch.N; ++j)
      {
        const Joint &J = rep.joints[j];
        std::cout << std::setw(6) << j << " | " << std::fixed << std::setprecision(2) << std::setw(16)
                  << (arch.theta(j) - pi / 2) * 180 / pi << " | " << std::setw(8) << J.normal << " | "
                  << std::setw(8) << J.shear << " | " << std::setprecision(3) << std::setw(6) << J.shear / J.normal
                  << " | " << std::setw(7) << J.e / (arch.t / 2) << " | " << std::setw(6) << J.n_closed << "/"
                  << J.n_open << (std::abs(J.e) <= arch.t / 6 ? "" : "   outside the middle third")
                  << std::endl;
      }
  }

  // A picture: the blocks, the middle third of the arch (dashed) and the
  // thrust line through the centres of pressure.
  void
  write_svg(const Arch &arch, const Report &rep, const std::string &filename)
  {
    const double scale = 600. / (2 * R + 2 * arch.t), x0 = -R - arch.t, y0 = R + arch.t;
    auto         X = [&](const Point &p) { return 20 + scale * (p[0] - x0); };
    auto         Y = [&](const Point &p) { return 20 + scale * (y0 - p[1]); };
    std::ofstream out(filename);
    AssertThrow(out, dealii::ExcMessage("step-8: cannot write " + filename));
    out << std::fixed << std::setprecision(2) << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\""
        << 40 + scale * (2 * R + 2 * arch.t) << "\" height=\"" << 75 + scale * (R + 2 * arch.t) << "\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    for (unsigned int b = 0; b <= arch.N + 1; ++b)
      {
        out << "<polygon fill=\"" << (b == 0 || b == arch.N + 1 ? "#bbbbbb" : "#e8d8b0")
            << "\" stroke=\"black\" stroke-width=\"0.8\" points=\"";
        for (const Point &p : arch.outline(b))
          out << X(p) << "," << Y(p) << " ";
        out << "\"/>\n";
      }
    for (const double r : {R - arch.t / 6, R + arch.t / 6})
      {
        out << "<polyline fill=\"none\" stroke=\"#777777\" stroke-width=\"0.6\" stroke-dasharray=\"4,3\" points=\"";
        for (unsigned int k = 0; k <= 180; ++k)
          {
            const Point p = Arch::polar(r, pi * k / 180.);
            out << X(p) << "," << Y(p) << " ";
          }
        out << "\"/>\n";
      }
    out << "<polyline fill=\"none\" stroke=\"#c00000\" stroke-width=\"2\" points=\"";
    for (const Joint &J : rep.joints)
      out << X(J.centre) << "," << Y(J.centre) << " ";
    out << "\"/>\n";
    for (const Joint &J : rep.joints)
      out << "<circle cx=\"" << X(J.centre) << "\" cy=\"" << Y(J.centre) << "\" r=\""
          << (std::abs(J.e) > 0.95 * arch.t / 2 ? 5 : 2.5) << "\" fill=\"#c00000\"/>\n";
    out << "<text x=\"20\" y=\"" << 45 + scale * (R + 2 * arch.t)
        << "\" font-family=\"sans-serif\" font-size=\"13\">" << arch.N << " voussoirs, t/R = " << std::setprecision(3)
        << arch.t / R << ": the thrust line through the centres of pressure of the joints</text>\n"
        << std::setprecision(2) << "<text x=\"20\" y=\"" << 62 + scale * (R + 2 * arch.t)
        << "\" font-family=\"sans-serif\" font-size=\"13\">(large dots: |e| &gt; 0.95 t/2; dashed: the middle "
        << "third)</text>\n</svg>\n";
  }

  // @sect3{One thickness}
  //
  // Solve, and either evaluate the standing arch or record why the contact
  // solver stopped. Two of its exceptions are outcomes here: "No static
  // equilibrium" (an active set that leaves blocks free) is what the solver
  // says when the arch collapses; "The contact active set cycles" or "did
  // not settle" mean that the iteration found no solution either way. Any
  // other exception is an error of the program and is passed on.
  enum class Outcome
  {
    stands,
    no_equilibrium,
    no_convergence
  };

  std::string
  outcome_name(const Outcome o)
  {
    return o == Outcome::stands ? "stands" : o == Outcome::no_equilibrium ? "no static equilibrium" : "no convergence";
  }

  Outcome
  outcome(const Report &rep)
  {
    if (rep.stands)
      return Outcome::stands;
    return rep.message.find("No static equilibrium") == 0 ? Outcome::no_equilibrium : Outcome::no_convergence;
  }

  Report
  run_thickness(const Arch                 &arch,
                const unsigned int          degree,
                std::vector<std::string>   &failures,
                const bool                  verbose,
                const bool                  report = false)
  {
    std::filesystem::create_directories("output");
    std::ostringstream msh;
    msh << "output/arch-N" << arch.N << "-t" << std::fixed << std::setprecision(4) << arch.t / R << ".msh";
    Report rep;
    try
      {
        const auto r = solve(arch, degree, msh.str(), report);
        rep          = evaluate(arch, r, failures);
      }
    catch (const std::exception &exc)
      {
        const std::string what = exc.what();
        std::size_t       from = std::string::npos;
        for (const char *key : {"No static equilibrium", "The contact active set cycles",
                                "The contact active set did not settle"})
          from = std::min(from, what.find(key));
        if (from == std::string::npos)
          throw;
        rep.stands = false;
        // the message without deal.II's frame (file, line, condition, stack
        // trace), on one line
        std::string message;
        for (const char c : what.substr(from, what.find("Stacktrace") - from))
          if (!std::isspace(static_cast<unsigned char>(c)))
            message += c;
          else if (!message.empty() && message.back() != ' ')
            message += ' ';
        // the free motions of a large assembly make a long list: keep its
        // beginning and the active-set history
        const auto history = message.find("(active pairs per iteration");
        if (message.size() > 300 && history != std::string::npos && history > 160)
          message = message.substr(0, 160) + " ... " + message.substr(history, message.find(')', history) + 1 - history);
        rep.message = message;
        if (last_mechanism != nullptr)
          {
            // a hinge: a closed pair between blocks that move differently,
            // on joint min(a, b), at the intrados or the extrados
            for (unsigned int i = 0; i < last_mechanism->closed_pairs.size(); ++i)
              {
                const auto [a, b] = last_mechanism->closed_pair_bodies[i];
                const auto &x     = last_mechanism->closed_pair_locations[i];
                const std::pair<unsigned int, int> h(std::min(a, b), x.norm() > R ? 1 : -1);
                if (std::find(rep.hinges.begin(), rep.hinges.end(), h) == rep.hinges.end())
                  rep.hinges.push_back(h);
              }
            std::sort(rep.hinges.begin(), rep.hinges.end());
            rep.mechanism_work      = last_mechanism->relative_work;
            rep.mechanism_violation = last_mechanism->largest_violation;
            rep.failing_condition   = last_mechanism->failing_condition;
          }
      }
    if (verbose)
      {
        std::cout << "\nN = " << arch.N << ", k = " << degree << ", t/R = " << std::setprecision(4) << std::fixed
                  << arch.t / R << ": ";
        if (rep.stands)
          {
            std::cout << "stands (" << rep.dofs << " DoFs, " << rep.pairs << " node pairs, " << rep.iterations
                      << " active-set iterations)\n";
            print_joints(arch, rep);
            std::cout << std::scientific << std::setprecision(6) << " weight W = " << rep.W
                      << " kN/m; V_left + V_right - W = " << std::setprecision(1)
                      << rep.V_left + rep.V_right - rep.W << std::setprecision(6) << "\n thrust H_left = " << rep.H_left
                      << ", H_right = " << rep.H_right << " kN/m (difference " << std::setprecision(1)
                      << rep.H_left - rep.H_right << "), H/W = " << std::fixed << std::setprecision(4)
                      << rep.H_left / rep.W << "\n admissible thrusts of the limit analysis: H/W in ["
                      << rep.H_min / rep.W << ", " << rep.H_max / rep.W << "]\n largest displacement "
                      << std::scientific << std::setprecision(2) << rep.u_max << " m = " << std::fixed
                      << std::setprecision(2) << rep.u_max / (rho_g * R * R / E) << " rho g R^2 / E" << std::endl;
          }
        else
          std::cout << outcome_name(outcome(rep)) << ":\n  " << rep.message << std::endl;
      }
    return rep;
  }

  // @sect3{The collapse mechanism against the limit analysis}
  //
  // The joints where the thrust line of the limit analysis touches the
  // arch at its least thickness (+1 extrados, -1 intrados): the hinges of
  // its collapse mechanism.
  std::vector<std::pair<unsigned int, int>>
  limit_hinges(const unsigned int N)
  {
    const double        t = least_thickness(N);
    const LimitAnalysis la(Arch{N, t * R});
    const auto          e = la.eccentricities(la.best_thrust().first);
    std::vector<std::pair<unsigned int, int>> h;
    for (unsigned int j = 0; j <= N; ++j)
      if (std::abs(e[j]) > 1 - 1e-3)
        h.emplace_back(j, e[j] > 0 ? 1 : -1);
    return h;
  }

  std::string
  hinge_list(const std::vector<std::pair<unsigned int, int>> &h)
  {
    std::string s;
    for (const auto &[j, side] : h)
      s += " " + std::to_string(j) + (side > 0 ? " (extrados)" : " (intrados)");
    return s;
  }

  // The proof of a collapse just below the least thickness: a motion with
  // positive work that violates no condition (to 1e-8 of its size), with at
  // least four hinges, each where the thrust line of the limit analysis
  // touches the arch, on the same face.
  void
  check_mechanism(const Arch &arch, const unsigned int degree, const Report &rep,
                  const std::vector<std::pair<unsigned int, int>> &expected, std::vector<std::string> &failures)
  {
    const std::string name = "N = " + std::to_string(arch.N) + ", k = " + std::to_string(degree) +
                             ", t/R = " + std::to_string(arch.t / R) + ": the collapse mechanism ";
    if (rep.hinges.empty() && rep.mechanism_work == 0)
      {
        failures.push_back(name + "was not reported");
        return;
      }
    check(rep.mechanism_work > 0 && rep.mechanism_violation <= 1e-8,
          name + "is no proof (work " + std::to_string(rep.mechanism_work) + ", violation " +
            std::to_string(rep.mechanism_violation) + ")",
          failures);
    check(rep.hinges.size() >= 4, name + "has fewer than four hinges:" + hinge_list(rep.hinges), failures);
    for (const auto &h : rep.hinges)
      check(std::find(expected.begin(), expected.end(), h) != expected.end(),
            name + "has a hinge at joint" + hinge_list({h}) + ", where the limit analysis has none (its hinges:" +
              hinge_list(expected) + ")",
            failures);
  }

  // @sect3{Just below and just above the limit}
  //
  // For N voussoirs and both joint models: 0.99, 1.01 and 1.02 times the
  // least thickness of the limit analysis. Below it there must be no static
  // equilibrium (and, with sticking joints, a mechanism whose hinges are
  // the limit analysis'), above it the arch must stand. One line per N.
  void
  near_limit(const unsigned int N, const unsigned int degree, std::vector<std::string> &failures)
  {
    const double t_la   = least_thickness(N);
    const auto   hinges = limit_hinges(N);
    std::cout << std::setw(3) << N << " | " << degree << " | " << std::fixed << std::setprecision(5) << t_la;
    for (const double mu : {0., 0.8})
      {
        joint_friction = mu;
        std::cout << " |";
        for (const double ratio : {0.99, 1.01, 1.02})
          {
            const auto rep = run_thickness(Arch{N, ratio * t_la * R}, degree, failures, false);
            const auto o   = outcome(rep);
            std::cout << " " << (o == Outcome::stands ? "S" : o == Outcome::no_equilibrium ? "E" : "C");
            const std::string name = "N = " + std::to_string(N) + ", k = " + std::to_string(degree) +
                                     (mu > 0 ? ", Coulomb" : ", stick") + ", " +
                                     std::to_string(ratio).substr(0, 4) + " t_crit: ";
            if (ratio < 1)
              {
                check(o == Outcome::no_equilibrium, name + "does not end in 'No static equilibrium'", failures);
                if (o == Outcome::no_equilibrium && mu == 0)
                  check_mechanism(Arch{N, ratio * t_la * R}, degree, rep, hinges, failures);
              }
            else
              check(o == Outcome::stands, name + "does not stand: " + rep.message, failures);
          }
      }
    joint_friction = 0;
    std::cout << std::endl;
  }

  // @sect3{A scan of thicknesses}
  //
  // The contact solve at t/R = 0.100, 0.101, ..., 0.120 for N voussoirs,
  // one line: "S" stands, "E" no static equilibrium, "C" no convergence,
  // with the limit analysis' least thickness marked by '|'. The checks:
  // below the least thickness nothing stands (the solver must not return a
  // solution that cannot exist), and a thickness that stands passes every
  // check of evaluate(). Returns the smallest thickness from which on every
  // thickness of the scan stands (0.121 if 0.120 does not).
  double
  scan(const unsigned int N, const unsigned int degree, std::vector<std::string> &failures)
  {
    const double t_la = least_thickness(N);
    const auto   hinges = limit_hinges(N);
    std::string  line;
    double       t_all_stand = 0.121; // none
    bool         all_above   = true;
    unsigned int n_convex    = 0;
    for (int i = 20; i >= 0; --i)
      {
        const double tr  = 0.100 + 0.001 * i;
        const auto   rep = run_thickness(Arch{N, tr * R}, degree, failures, false);
        const auto   o   = outcome(rep);
        if (tr < t_la && i < 20 && 0.100 + 0.001 * (i + 1) >= t_la)
          line = "|" + line;
        line = std::string(o == Outcome::stands ? "S" : o == Outcome::no_equilibrium ? "E" : "C") + line;
        all_above = all_above && o == Outcome::stands;
        if (all_above)
          t_all_stand = tr;
        if (tr < t_la && o == Outcome::stands)
          failures.push_back("N = " + std::to_string(N) + ", k = " + std::to_string(degree) + ": t/R = " +
                             std::to_string(tr) + " stands below the least thickness " + std::to_string(t_la));
        if (tr >= t_la && o != Outcome::stands)
          failures.push_back("N = " + std::to_string(N) + ", k = " + std::to_string(degree) + ": t/R = " +
                             std::to_string(tr) + " does not stand above the least thickness " +
                             std::to_string(t_la) + ": " + rep.message);
        if (tr < t_la && tr > 0.98 * t_la && o == Outcome::no_equilibrium && joint_friction == 0)
          check_mechanism(Arch{N, tr * R}, degree, rep, hinges, failures);
        n_convex += rep.convex;
      }
    std::cout << std::setw(3) << N << " | " << degree << (joint_friction > 0 ? "*" : " ") << "| " << std::fixed << std::setprecision(5) << t_la << " | "
              << line << " | " << (t_all_stand > 0.1205 ? std::string("none") : std::to_string(t_all_stand).substr(0, 5))
              << (n_convex > 0 ? " (" + std::to_string(n_convex) + " with open-tied pairs)" : std::string())
              << std::endl;
    return t_all_stand;
  }
} // namespace Step8

// @sect3{The main function}
int
main(int argc, char **argv)
{
  using namespace Step8;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      bool study = false, doc_picture = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--study")
            study = true;
          else if (arg == "--write-doc-picture")
            doc_picture = true;
          else
            {
              std::cerr << "usage: step-8 [--study] [--write-doc-picture]" << std::endl;
              return 2;
            }
        }
      std::vector<std::string> failures;

      // The default run: N = 19 voussoirs, k = 2. First the least thickness
      // of the limit analysis of the same blocks.
      const unsigned int N      = 19;
      const double       t_crit = least_thickness(N);
      std::cout << "Rigid-block limit analysis, " << N << " voussoirs: least thickness t/R = " << std::fixed
                << std::setprecision(5) << t_crit << " (continuous arch: 0.1075)" << std::endl;
      {
        // the thrust line at the least thickness: where it touches the
        // intrados (-1) or the extrados (+1), the hinges of the mechanism
        const LimitAnalysis la(Arch{N, t_crit * R});
        const double       H = la.best_thrust().first;
        const auto         e = la.eccentricities(H);
        std::cout << "  at the least thickness H/W = " << std::setprecision(4) << H / la.W
                  << "; the thrust line touches the arch at joints";
        for (unsigned int j = 0; j <= N; ++j)
          if (std::abs(e[j]) > 1 - 1e-3)
            std::cout << " " << j << (e[j] > 0 ? " (extrados," : " (intrados,") << " " << std::setprecision(2)
                      << (Arch{N, t_crit * R}.theta(j) - pi / 2) * 180 / pi << " deg)";
        std::cout << std::endl;
      }
      AssertThrow(std::abs(t_crit - 0.10622) < 1e-5,
                  dealii::ExcMessage("step-8: the limit analysis gives " + std::to_string(t_crit) +
                                     " for 19 voussoirs, not 0.10622"));

      // Then the contact solves in detail at a few thicknesses. Above the
      // least thickness the arch must stand and pass every check. Below it
      // no equilibrium exists: these must end in "No static equilibrium",
      // and just below it (0.99 t_crit) the collapse mechanism must be the
      // limit analysis' one.
      const std::vector<double> thicknesses = {0.150,          0.120,          0.112, 0.110, 0.108,
                                               1.02 * t_crit, 1.01 * t_crit, 0.99 * t_crit,
                                               0.104,          0.100,          0.090};
      const auto                hinges      = limit_hinges(N);
      double                    t_stand = 1e300, t_collapse = 0;
      for (const double tr : thicknesses)
        {
          const Arch   arch{N, tr * R};
          const Report rep = run_thickness(arch, 2, failures, true, tr == thicknesses.front());
          const auto   o   = outcome(rep);
          if (o == Outcome::stands)
            t_stand = std::min(t_stand, tr);
          else if (tr < t_crit && o == Outcome::no_equilibrium)
            t_collapse = std::max(t_collapse, tr);
          if (tr >= t_crit && o != Outcome::stands)
            failures.push_back("t/R = " + std::to_string(tr) + " does not stand above the least thickness: " +
                               rep.message);
          if (o == Outcome::no_equilibrium && !rep.hinges.empty())
            std::cout << "  the proof: hinges at joints" << hinge_list(rep.hinges) << "; "
                      << rep.failing_condition << "; work of the weights on it " << std::scientific
                      << std::setprecision(3) << rep.mechanism_work << " (cosine with the loads), largest violation "
                      << rep.mechanism_violation << std::fixed << std::endl;
          if (tr < t_crit && tr > 0.98 * t_crit)
            check_mechanism(arch, 2, rep, hinges, failures);
          if (tr < t_crit && o != Outcome::no_equilibrium)
            failures.push_back("t/R = " + std::to_string(tr) + " is below the least thickness " +
                               std::to_string(t_crit) + ", but the solver says: " + outcome_name(o));
          if (tr >= t_crit && o != Outcome::stands)
            {
              // the limit analysis has thrust lines inside the arch here
              LimitAnalysis la(arch);
              const auto [H_min, H_max] = la.admissible_thrusts();
              std::cout << "  but the limit analysis admits the thrusts H/W in [" << std::setprecision(4)
                        << H_min / la.W << ", " << H_max / la.W << "]: the arch can stand" << std::endl;
              if (!(H_min <= H_max))
                failures.push_back("t/R = " + std::to_string(tr) + ": no admissible thrust above the least thickness");
            }
          if (o == Outcome::stands && tr == 0.120)
            {
              const std::string picture =
                doc_picture ? (std::filesystem::path(__FILE__).parent_path() / "doc" / "arch.svg").string() :
                              std::string("arch.svg");
              write_svg(arch, rep, picture);
              std::cout << "picture: " << picture << std::endl;
            }
        }
      std::cout << "\nBracket of the least thickness: collapses (no static equilibrium, below the limit) at t/R = "
                << std::setprecision(3) << t_collapse << ", stands at t/R = " << t_stand
                << "; limit analysis: " << std::setprecision(5) << t_crit << std::endl;
      if (!(t_collapse < t_crit && t_crit <= t_stand && t_stand - t_collapse <= 0.01))
        failures.push_back("the bracket [" + std::to_string(t_collapse) + ", " + std::to_string(t_stand) +
                           "] does not hold the least thickness of the limit analysis, or is wider than 0.01");

      // The scan: N = 19, k = 2 (and with --study more N and k = 1).
      std::cout << "\nContact solves at t/R = 0.100, 0.101, ..., 0.120 (S stands, E no static equilibrium, C no "
                   "convergence; | the least thickness of the limit analysis):\n"
                << "  N | k | limit   | 0.100 .. 0.120         | all stand from\n";
      const double t_all = scan(N, 2, failures);
      if (t_all > t_crit + 0.001)
        failures.push_back("N = 19, k = 2: not every thickness above the least thickness stands");
      if (study)
        for (const unsigned int k : {1u, 2u})
          for (const unsigned int n : {9u, 13u, 17u, 19u, 21u, 25u})
            if (k != 2 || n != N)
              scan(n, k, failures);

      // The other joint model: Coulomb friction with mu = 0.8 (stone on
      // stone), far above the T/N the joints need (0.39 at most): friction
      // does not limit these arches, so the least thickness is the same.
      // Nothing may stand below it, everything must stand above it: where
      // the semismooth Newton iteration of friction gives up, FrictionSolver
      // solves the stick problem and then Coulomb as a fixed point of
      // Tresca problems, each by the globally convergent active set.
      joint_friction = 0.8;
      std::cout << "\nThe same with Coulomb friction, mu = 0.8 (* in the k column):\n";
      scan(N, 2, failures);
      if (study)
        for (const unsigned int k : {1u, 2u})
          for (const unsigned int n : {9u, 13u, 25u})
            scan(n, k, failures);
      joint_friction = 0;

      // Other voussoir counts just below and just above their limits
      // (0.99, 1.01 and 1.02 times the least thickness), both joint models.
      std::cout << "\nOther voussoir counts at 0.99, 1.01 and 1.02 times their least thickness (stick | "
                   "Coulomb, mu = 0.8):\n"
                << "  N | k | limit   | stick  | Coulomb\n";
      for (const unsigned int n : {9u, 13u, 25u})
        near_limit(n, 1, failures);

      for (const auto &m : failures)
        std::cerr << "step-8 check failed: " << m << std::endl;
      return failures.empty() ? 0 : 1;
    }
  catch (std::exception &exc)
    {
      std::cerr << std::endl << "Exception: " << exc.what() << std::endl;
      return 1;
    }
}
