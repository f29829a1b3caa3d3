// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// For k = 1 and 2, plane strain and plane stress, on many polygon shapes:
// - the projector reproduces polynomials: Pi p = p for every p in [P_k]^2
//   (checked as Pi_* D = I and Pi D = D), relative 1e-10;
// - the element stiffness is symmetric and positive semidefinite with
//   exactly three zero eigenvalues (|lambda| <= 1e-10 lambda_max), and the
//   kernel contains the rigid-body modes; with the default rules and with
//   Stabilization::boundary;
// - the consistency part reproduces the energy of polynomials:
//   D^T K D = a(p_alpha, p_beta), the elasticity form integrated by
//   quadrature from the polynomials' gradients (K_E exact on [P_k]^2);
// - cell similarity: the space reuses its matrices for translated polygons,
//   the elasticity operator also when the material and gamma are the same.
#include <deal.II/base/point.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <dealvem/mesh/generators.h>
#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/vem/virtual_element.h>

#include <cmath>
#include <limits>
#include <random>

#include "../tests.h"

using namespace dealvem;
using P = dealii::Point<2>;

std::vector<P>
regular_polygon(const unsigned int n, const double r, const P c = P())
{
  std::vector<P> v;
  for (unsigned int i = 0; i < n; ++i)
    v.emplace_back(c[0] + r * std::cos(2 * M_PI * i / n + 0.3), c[1] + r * std::sin(2 * M_PI * i / n + 0.3));
  return v;
}

std::vector<P>
random_convex_polygon(const unsigned int n, std::mt19937 &rng)
{
  // sorted random angles on an ellipse, then a random shift
  std::uniform_real_distribution<double> u(0, 2 * M_PI);
  std::vector<double>                    angles(n);
  for (auto &a : angles)
    a = u(rng);
  std::sort(angles.begin(), angles.end());
  std::vector<P> v;
  for (const double a : angles)
    v.emplace_back(3.0 + 1.3 * std::cos(a), -2.0 + 0.7 * std::sin(a));
  return v;
}

std::vector<P>
scaled(const std::vector<P> &v, const double s, const P shift = P())
{
  std::vector<P> r;
  for (const auto &p : v)
    r.emplace_back(shift[0] + s * p[0], shift[1] + s * p[1]);
  return r;
}

void
check_polygon(const std::string &name, const std::vector<P> &vertices)
{
  for (const unsigned int k : {1u, 2u})
    for (const auto model : {ElasticMaterial::Model::plane_strain, ElasticMaterial::Model::plane_stress})
      for (const auto rule : {Stabilization::automatic, Stabilization::boundary})
      {
        const ElasticMaterial material(210e3, 0.3, model);
        VirtualElement<2>     element(k);
        element.reinit(vertices);
        ElasticityOperator<2> elasticity;
        elasticity.reinit(element, material, 1.0, rule);
        const auto        &D  = element.get_D();
        const auto        &Ps = element.get_projector();
        const auto        &K  = elasticity.get_stiffness_matrix();
        const unsigned int n  = K.m(), np = element.n_polynomials();

        // Pi_* D = I
        dealii::FullMatrix<double> PD(np, np);
        Ps.mmult(PD, D);
        double err_proj = 0;
        for (unsigned int a = 0; a < np; ++a)
          for (unsigned int b = 0; b < np; ++b)
            err_proj = std::max(err_proj, std::abs(PD(a, b) - (a == b ? 1. : 0.)));

        // symmetry
        double kmax = 0, asym = 0;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              kmax = std::max(kmax, std::abs(K(i, j)));
              asym = std::max(asym, std::abs(K(i, j) - K(j, i)));
            }

        // eigenvalues
        dealii::Vector<double>     eig;
        dealii::FullMatrix<double> vec;
        dealii::LAPACKFullMatrix<double> LK2(n, n);
        LK2 = K;
        LK2.compute_eigenvalues_symmetric(-1e300, 1e300, 0., eig, vec);
        const double lmax   = eig[eig.size() - 1];
        unsigned int n_zero = 0;
        double       lmin   = 1e300;
        for (unsigned int i = 0; i < eig.size(); ++i)
          {
            // (the boundary rule stiffens the short edges of a 1:100 sliver
            // 20 times more than the trace rule, and so its largest
            // eigenvalue; the sliver's softest mode, 0.74 in both, is then
            // 6e-11 of it: the zero threshold is 1e-11 there)
            if (std::abs(eig[i]) <= (rule == Stabilization::boundary ? 1e-11 : 1e-10) * lmax)
              ++n_zero;
            lmin = std::min(lmin, eig[i]);
          }

        // D^T K D equals a(p_alpha, p_beta) (zero on the rigid modes),
        // integrated here from the gradients of the polynomials
        dealii::FullMatrix<double> a_pp(np, np);
        {
          const dealii::Quadrature<2> q = element.get_geometry().quadrature(2 * k);
          for (unsigned int i = 0; i < q.size(); ++i)
            for (unsigned int a = 0; a < np; ++a)
              for (unsigned int b = 0; b < np; ++b)
                {
                  const auto ea = dealii::symmetrize(element.polynomial_gradient(a, q.point(i)));
                  const auto eb = dealii::symmetrize(element.polynomial_gradient(b, q.point(i)));
                  a_pp(a, b) += q.weight(i) * (material.stress(ea) * eb);
                }
        }
        dealii::FullMatrix<double> KD(n, np), DKD(np, np);
        K.mmult(KD, D);
        D.Tmmult(DKD, KD);
        double err_energy = 0, gmax = 0;
        for (unsigned int a = 0; a < np; ++a)
          for (unsigned int b = 0; b < np; ++b)
            {
              const double g = a_pp(a, b);
              gmax           = std::max(gmax, std::abs(g));
              err_energy     = std::max(err_energy, std::abs(DKD(a, b) - g));
            }

        const std::string tag = name + " k=" + std::to_string(k) + " " + ElasticMaterial::model_name(model) +
                                (rule == Stabilization::boundary ? " boundary rule" : "");
        testing::check_small(err_proj, 1e-10, tag + ": |Pi_* D - I|");
        testing::check_small(asym / kmax, 1e-13, tag + ": asymmetry of K");
        testing::check(lmin >= -1e-10 * lmax, tag + ": K positive semidefinite");
        testing::check(n_zero == 3, tag + ": exactly 3 zero eigenvalues (found " + std::to_string(n_zero) + ")");
        // amplified by cond(G) on elongated cells: 1e-9 relative
        testing::check_small(err_energy / gmax, 1e-9, tag + ": D^T K D = a(p,p)");
      }
}

// Cell similarity: a translated polygon reuses the matrices, which then
// equal a fresh computation to round-off; any other change recomputes them.
double
max_difference(const dealii::FullMatrix<double> &A, const dealii::FullMatrix<double> &B)
{
  if (A.m() != B.m() || A.n() != B.n())
    return 1e300;
  double d = 0, a = 0;
  for (unsigned int i = 0; i < A.m(); ++i)
    for (unsigned int j = 0; j < A.n(); ++j)
      {
        d = std::max(d, std::abs(A(i, j) - B(i, j)));
        a = std::max(a, std::abs(B(i, j)));
      }
  return d / a;
}

void
check_cell_similarity()
{
  const ElasticMaterial material(210e3, 0.3), other(100e3, 0.3);
  const std::vector<P>  hexagon = regular_polygon(6, 0.7, P(0.2, 0.1));
  for (const unsigned int k : {1u, 2u})
    {
      const std::string tag = "cell similarity k=" + std::to_string(k) + ": ";
      VirtualElement<2> element(k), fresh(k);
      ElasticityOperator<2> op, fresh_op;
      fresh.set_cell_similarity(false);
      element.reinit(hexagon);
      op.reinit(element, material);
      testing::check(!element.last_reinit_reused() && !op.last_reinit_reused(), tag + "first polygon computed");
      const std::vector<P> moved = scaled(hexagon, 1.0, P(12.5, -3.25));
      element.reinit(moved);
      op.reinit(element, material);
      fresh.reinit(moved);
      fresh_op.reinit(fresh, material);
      testing::check(element.last_reinit_reused(), tag + "translated polygon reuses the space's matrices");
      testing::check(op.last_reinit_reused(), tag + "... and the operator its matrices");
      testing::check(!fresh.last_reinit_reused(), tag + "disabled reuse computes");
      testing::check_small(max_difference(op.get_stiffness_matrix(), fresh_op.get_stiffness_matrix()), 1e-13,
                           tag + "reused K equals a fresh K");
      testing::check_small(max_difference(element.get_projector(), fresh.get_projector()), 1e-13,
                           tag + "reused Pi_* equals a fresh Pi_*");
      testing::check_small(element.get_geometry().centroid().distance(fresh.get_geometry().centroid()), 1e-14,
                           tag + "geometry moved with the polygon");
      // anything else is recomputed: scaled, one vertex moved, other number
      // of vertices
      const std::vector<std::pair<std::string, std::vector<P>>> changed = {
        {"scaled polygon", scaled(moved, 1.0 + 1e-9, P())},
        {"one vertex moved", [&] {
           auto v = moved;
           v[3][0] += 1e-9;
           return v;
         }()},
        {"other vertex count", regular_polygon(7, 0.7)}};
      for (const auto &c : changed)
        {
          element.reinit(moved);
          op.reinit(element, material);
          element.reinit(c.second);
          op.reinit(element, material);
          fresh.reinit(c.second);
          fresh_op.reinit(fresh, material);
          testing::check(!element.last_reinit_reused() && !op.last_reinit_reused(),
                         tag + c.first + " is recomputed");
          testing::check_small(max_difference(op.get_stiffness_matrix(), fresh_op.get_stiffness_matrix()), 1e-14,
                               tag + c.first + ": K equals a fresh K");
        }
      // the space does not depend on the material: only the operator
      // recomputes for another material or gamma
      element.reinit(moved);
      op.reinit(element, material);
      const auto Pi = element.get_projector();
      element.reinit(moved);
      testing::check(element.last_reinit_reused(), tag + "same polygon again reuses the space");
      op.reinit(element, other);
      testing::check(!op.last_reinit_reused(), tag + "other material recomputes the operator");
      op.reinit(element, other, 2.0);
      testing::check(!op.last_reinit_reused(), tag + "other gamma recomputes the operator");
      testing::check_small(std::abs(op.get_stabilization_scaling() /
                                      ElasticityOperator<2>::stabilization_scaling(op.get_consistency_matrix(), 1.0) -
                                    2.0),
                           1e-14, tag + "gamma scales the stabilization");
      // a second space at another polygon must not be mistaken for the first
      VirtualElement<2> second(k);
      second.reinit(regular_polygon(5, 0.3));
      op.reinit(second, other, 2.0);
      testing::check(!op.last_reinit_reused(), tag + "another space is not mistaken for the first");
      testing::check_small(max_difference(element.get_projector(), Pi), 0., tag + "space unchanged");
    }
}

// Cell similarity on a structured grid away from the origin: its vertices
// x0 + (x1 - x0) i / n are rounded to the last place of |x|, so congruent
// cells differ in their shapes by that rounding (up to 4.4e-16 on [1, 2]
// with n = 281, where 1e-14 h is 5e-17). Every cell after the first reuses
// the matrices (the rounding is part of the test), wherever the grid sits
// (at 1, at 1e3), and a reused K equals a fresh one to the rounding of
// the coordinates (eps |x| / h, relative).
void
check_similarity_on_grids()
{
  const ElasticMaterial material(1.0, 0.3);
  for (const unsigned int k : {1u, 2u})
    for (const double offset : {0., 1., 1e3})
      {
        const unsigned int    n = 281;
        VirtualElement<2>     element(k), fresh(k);
        ElasticityOperator<2> op, fresh_op;
        fresh.set_cell_similarity(false);
        unsigned int computed = 0;
        double       worst    = 0;
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int i = 0; i < n; ++i)
            {
              const auto x = [&](const unsigned int a) { return offset + (offset + 1 - offset) * a / n; };
              const auto y = [&](const unsigned int b) { return offset + 1 + (offset + 2 - (offset + 1)) * b / n; };
              const std::vector<P> cell = {P(x(i), y(j)), P(x(i + 1), y(j)), P(x(i + 1), y(j + 1)), P(x(i), y(j + 1))};
              element.reinit(cell);
              op.reinit(element, material);
              computed += element.last_reinit_reused() ? 0 : 1;
              if (i % 40 == 7)
                {
                  fresh.reinit(cell);
                  fresh_op.reinit(fresh, material);
                  worst = std::max(worst, max_difference(op.get_stiffness_matrix(), fresh_op.get_stiffness_matrix()));
                }
            }
        const std::string tag =
          "grid of 3 x 281 cells at offset " + std::to_string(offset) + ", k=" + std::to_string(k) + ": ";
        std::cout << "  " << tag << computed << " cells computed, reused K against fresh " << worst << std::endl;
        testing::check(computed == 1, tag + "only the first cell is computed");
        // a fresh K is itself computed from coordinates rounded to
        // eps |x|, which is eps |x| / h relative to the cell
        testing::check_small(worst, 50 * std::numeric_limits<double>::epsilon() * (1 + (offset + 2) * n),
                             tag + "reused K equals a fresh K to the rounding of the coordinates");
      }
}

// A short edge: the unit square with its bottom edge split at delta. The
// motion of the split vertex alone, along the edge, stretches an edge of
// length delta; the boundary rule stiffens it like 1/delta (the trace
// rule, whose scale is one number for the cell, does not): its energy grows
// by about 100 from delta = 1e-1 to 1e-3 (here at least 30), the trace
// rule's by less than 2.
void
check_short_edge()
{
  const ElasticMaterial material(1.0, 0.3);
  for (const unsigned int k : {1u, 2u})
    {
      double energy[2][2];
      for (unsigned int r = 0; r < 2; ++r)
        for (unsigned int i = 0; i < 2; ++i)
          {
            const double      delta = (i == 0 ? 1e-1 : 1e-3);
            VirtualElement<2> element(k);
            element.reinit({P(0, 0), P(delta, 0), P(1, 0), P(1, 1), P(0, 1)});
            ElasticityOperator<2> op;
            op.reinit(element, material, 1.0, r == 0 ? Stabilization::trace : Stabilization::boundary);
            const auto &K = op.get_stiffness_matrix();
            // local DoF 2 * 1 + 0: x-component of vertex 1
            energy[r][i] = K(2, 2);
          }
      const std::string tag = "short edge, k=" + std::to_string(k) + ": ";
      std::cout << "  " << tag << "energy of the split vertex's motion at delta = 1e-1, 1e-3: trace rule "
                << energy[0][0] << ", " << energy[0][1] << "; boundary rule " << energy[1][0] << ", "
                << energy[1][1] << std::endl;
      testing::check(energy[1][1] > 30 * energy[1][0], tag + "the boundary rule stiffens the short edge");
      testing::check(energy[0][1] < 2 * energy[0][0], tag + "the trace rule does not");
    }
}

int
main()
{
  check_cell_similarity();
  check_similarity_on_grids();
  check_short_edge();
  std::mt19937 rng(42);
  check_polygon("triangle", {P(0, 0), P(1, 0), P(0.2, 0.9)});
  check_polygon("unit square", {P(0, 0), P(1, 0), P(1, 1), P(0, 1)});
  check_polygon("skew quad", {P(0.1, -0.2), P(1.3, 0.1), P(1.1, 0.8), P(-0.2, 1.2)});
  check_polygon("regular hexagon", regular_polygon(6, 1.0));
  check_polygon("regular 11-gon", regular_polygon(11, 0.5, P(5, 7)));
  for (unsigned int i = 0; i < 4; ++i)
    check_polygon("random convex " + std::to_string(i), random_convex_polygon(5 + 2 * i, rng));
  // a Voronoi-like cell: irregular convex heptagon with a very short edge
  check_polygon("voronoi-like heptagon", {P(0, 0), P(1, -0.1), P(1.6, 0.5), P(1.6001, 0.5003), P(1.2, 1.3), P(0.3, 1.4), P(-0.4, 0.7)});
  // cells of a centroidal Voronoi mesh (the generator's own output)
  {
    dealvem::PolygonalMesh<2> mesh;
    dealvem::PolygonalMeshGenerators::voronoi(mesh, P(0, 0), P(1, 1), 30, 10, 5);
    for (unsigned int c = 0; c < mesh.n_cells(); c += 10)
      check_polygon("Voronoi cell " + std::to_string(c) + " (" + std::to_string(mesh.cell(c).vertices.size()) +
                      " vertices)",
                    mesh.cell_vertices(c));
  }
  // non-convex: L shape, arrow, star
  check_polygon("L shape", {P(0, 0), P(2, 0), P(2, 1), P(1, 1), P(1, 2), P(0, 2)});
  check_polygon("arrow", {P(0, 0), P(1, 0.5), P(2, 0), P(1, 2)});
  {
    std::vector<P> star;
    for (unsigned int i = 0; i < 10; ++i)
      {
        const double r = (i % 2 == 0) ? 1.0 : 0.4;
        star.emplace_back(r * std::cos(2 * M_PI * i / 10), r * std::sin(2 * M_PI * i / 10));
      }
    check_polygon("star (non-convex, not star-shaped w.r.t. vertices)", star);
  }
  // collinear (hanging) vertices: a square with extra vertices on two edges
  check_polygon("square with 3 collinear vertices", {P(0, 0), P(0.5, 0), P(1, 0), P(1, 0.3), P(1, 1), P(0, 1), P(0, 0.5)});
  check_polygon("quad with hanging node (triangle-like)", {P(0, 0), P(1, 0), P(2, 0), P(1, 1)});
  // aspect ratio 1:100
  check_polygon("quad 1:100", {P(0, 0), P(1, 0), P(1, 0.01), P(0, 0.01)});
  // (A 1:100 cell with an extra collinear vertex has a physical fourth
  // eigenvalue of about 1e-11 lambda_max for k = 2 -- a thin-plate bending
  // mode -- so it cannot be told apart from zero at 1e-10 and is not used.)
  check_polygon("hexagon 1:100", {P(0, 0), P(0.5, -0.002), P(1, 0), P(1, 0.01), P(0.5, 0.012), P(0, 0.01)});
  {
    // the same quad rotated by 30 degrees and moved away from the origin
    std::vector<P> q;
    for (const P &p : {P(0, 0), P(1, 0), P(1, 0.01), P(0, 0.01)})
      q.emplace_back(10 + std::cos(M_PI / 6) * p[0] - std::sin(M_PI / 6) * p[1], -5 + std::sin(M_PI / 6) * p[0] + std::cos(M_PI / 6) * p[1]);
    check_polygon("quad 1:100 rotated by 30 degrees", q);
  }
  // tiny and huge cells
  check_polygon("pentagon of size 1e-6", scaled(regular_polygon(5, 1.0), 1e-6, P(1, 1)));
  check_polygon("pentagon of size 1e6", scaled(regular_polygon(5, 1.0), 1e6, P(-3e6, 2e6)));
  check_polygon("L shape of size 1e-6", scaled({P(0, 0), P(2, 0), P(2, 1), P(1, 1), P(1, 2), P(0, 2)}, 1e-6));
  check_polygon("L shape of size 1e6", scaled({P(0, 0), P(2, 0), P(2, 1), P(1, 1), P(1, 2), P(0, 2)}, 1e6));
  return testing::finish();
}
