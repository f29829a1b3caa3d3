// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// PolyhedralMeshGenerators: the structured hexahedra of a box, and a
// centroidal Voronoi mesh of a convex domain (a box being one) by Lloyd's
// iteration. The domain is an intersection of half-spaces; CGAL's exact
// linear programming bounds it (or finds it empty, unbounded or flat), and
// its polytope is its bounding box cut by the half-spaces. The neighbours of
// a generator come from CGAL's 3D Delaunay triangulation; its Voronoi cell
// is the domain's polytope cut by the bisector planes, computed here on a
// list of face polygons. The only file of the 3D mesh layer that includes
// CGAL.
#include <deal.II/base/tensor.h>

#include <dealvem/config.h>
#include <dealvem/mesh/polyhedral_generators.h>

#ifdef DEALVEM_WITH_CGAL
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace dealvem
{
  // file-local (the library is a unity build: a name of its own)
  namespace polyhedral_generators_internal
  {
    namespace
    {
      using Pt  = dealii::Point<3>;
      using Vec = dealii::Tensor<1, 3>;

      // Throws unless @p upper lies above @p lower in every coordinate.
      void
      check_box(const Pt &lower, const Pt &upper, const std::string &what)
      {
        for (unsigned int d = 0; d < 3; ++d)
          AssertThrow(std::isfinite(lower[d]) && std::isfinite(upper[d]) && upper[d] > lower[d],
                      dealii::ExcMessage(what + ": the upper corner of the box must lie above the lower corner "
                                                "in every coordinate."));
      }

      // Finalizes @p mesh and gives every boundary face the boundary id of the
      // side of the box [lower, upper] its vertices lie on (0: x = lower[0],
      // 1: x = upper[0], 2, 3 for y and 4, 5 for z), as deal.II's colorize.
      void
      finish_box(PolyhedralMesh &mesh, const Pt &lower, const Pt &upper)
      {
        mesh.finalize();
        const double tol = 1e-10 * lower.distance(upper);
        for (unsigned int f = 0; f < mesh.n_faces(); ++f)
          if (mesh.face(f).at_boundary())
            {
              int side = -1;
              for (unsigned int s = 0; s < 6 && side < 0; ++s)
                {
                  const unsigned int d     = s / 2;
                  const double       plane = (s % 2 == 0 ? lower[d] : upper[d]);
                  bool               on    = true;
                  for (const unsigned int v : mesh.face(f).vertices)
                    on = on && std::abs(mesh.vertex(v)[d] - plane) <= tol;
                  if (on)
                    side = s;
                }
              AssertThrow(side >= 0, dealii::ExcMessage("PolyhedralMeshGenerators: boundary face " + std::to_string(f) +
                                                        " lies on no side of the box; internal error."));
              mesh.set_face_boundary_id(f, side);
            }
      }

      // A half-space {x : n.x <= b} of a convex domain, with |n| = 1.
      struct Plane
      {
        Vec    n;
        double b;
      };

      // The half-spaces @p half_spaces (normals of any length) with unit
      // normals, checked: finite numbers, non-zero normals, at most 255 of
      // them (the boundary ids 0..254). Each normal is divided by its largest
      // component before its length (no underflow or overflow of the squares):
      // a normal along an axis stays exactly +-1 there, and its offset exact.
      std::vector<Plane>
      normalised_half_spaces(const std::vector<std::pair<Vec, double>> &half_spaces, const std::string &who)
      {
        AssertThrow(!half_spaces.empty(),
                    dealii::ExcMessage(who + ": the list of half-spaces is empty (the domain would be all of space)."));
        AssertThrow(half_spaces.size() <= 255,
                    dealii::ExcMessage(who + ": " + std::to_string(half_spaces.size()) +
                                       " half-spaces; at most 255 are accepted (half-space i gives the boundary id i, "
                                       "and dealvem's programs read the boundary ids 0..254)."));
        std::vector<Plane> planes;
        for (unsigned int i = 0; i < half_spaces.size(); ++i)
          {
            const Vec   &n    = half_spaces[i].first;
            const double b    = half_spaces[i].second;
            const auto   name = who + ": half-space " + std::to_string(i);
            AssertThrow(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]) && std::isfinite(b),
                        dealii::ExcMessage(name + " has a normal or an offset that is not a finite number (NaN or "
                                                  "infinite)."));
            const double largest = std::max({std::abs(n[0]), std::abs(n[1]), std::abs(n[2])});
            AssertThrow(largest > 0, dealii::ExcMessage(name + " has a zero normal."));
            const Vec    scaled = n / largest;
            const double length = scaled.norm();
            const Plane  plane{scaled / length, b / largest / length};
            AssertThrow(std::isfinite(plane.b),
                        dealii::ExcMessage(name + ": its offset divided by the length of its normal is not a finite "
                                                  "number (a normal too small for its offset)."));
            planes.push_back(plane);
          }
        return planes;
      }

#ifdef DEALVEM_WITH_CGAL
      // The six half-spaces of the box [lower, upper] in the order of the
      // boundary ids of deal.II's colorize: x = lower[0], x = upper[0], then
      // y and z.
      std::vector<std::pair<Vec, double>>
      box_half_spaces(const Pt &lower, const Pt &upper)
      {
        std::vector<std::pair<Vec, double>> half_spaces;
        for (unsigned int d = 0; d < 3; ++d)
          {
            Vec n;
            n[d] = -1;
            half_spaces.emplace_back(n, -lower[d]);
            n[d] = 1;
            half_spaces.emplace_back(n, upper[d]);
          }
        return half_spaces;
      }

      // The planes a cell is cut by are named by labels: label >= 0 is the
      // bisector between the cell's generator and generator `label`,
      // label = -1 - i the half-space i of the domain, and -1 - n - s (n
      // half-spaces) the side s of the domain's bounding box where no
      // half-space lies on it (a label that only names the vertices of the
      // domain's polytope, never one of its faces).
      //
      // A vertex of a cell while it is being cut: its position and the labels
      // of the three planes it is the intersection of, sorted. The cell's
      // generator and these three name the vertex in every cell it belongs
      // to (the point equidistant from four generators, or from three on a
      // side of the box, ...): add_cells() identifies the copies of a vertex
      // computed in different cells by this name, not by their positions,
      // which may differ by much more than round-off where the planes meet
      // at small angles (a nearly degenerate diagram). planes[0] = no_plane:
      // a vertex where more than three planes meet, whose two edges give no
      // name; only its position identifies it.
      constexpr int no_plane = std::numeric_limits<int>::min();
      struct ClipVertex
      {
        Pt                 x;
        std::array<int, 3> planes;
      };

      // A face of a convex polyhedron while it is being cut: the vertex loop,
      // oriented by the right-hand rule with the normal pointing out, and the
      // label of its plane. A vertex common to several faces is stored in
      // each of them with the same bits (the cuts compute it the same way
      // from the same points), so that comparing points exactly recognises
      // it.
      struct ClipFace
      {
        int                     label;
        std::vector<ClipVertex> points;
      };
      using ClipPolyhedron = std::vector<ClipFace>;

      // The box [a, b] as six outward-oriented quadrilaterals, the side s
      // (x-, x+, y-, y+, z-, z+) labelled label[s].
      ClipPolyhedron
      box_polyhedron(const Pt &a, const Pt &b, const std::array<int, 6> &label)
      {
        auto c = [&](const int i, const int j, const int k) {
          ClipVertex v{Pt(i == 0 ? a[0] : b[0], j == 0 ? a[1] : b[1], k == 0 ? a[2] : b[2]),
                       {{label[4 + k], label[2 + j], label[i]}}};
          std::sort(v.planes.begin(), v.planes.end());
          return v;
        };
        return {{label[0], {c(0, 0, 0), c(0, 0, 1), c(0, 1, 1), c(0, 1, 0)}},  // x-: z then y, normal -x
                {label[1], {c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)}},  // x+
                {label[2], {c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)}},  // y-: x then z, normal -y
                {label[3], {c(0, 1, 0), c(0, 1, 1), c(1, 1, 1), c(1, 1, 0)}},  // y+
                {label[4], {c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)}},  // z-: y then x, normal -z
                {label[5], {c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)}}}; // z+
      }

      bool
      lexicographically_less(const Pt &a, const Pt &b)
      {
        return std::lexicographical_compare(a.begin_raw(), a.end_raw(), b.begin_raw(), b.end_raw());
      }

      bool
      lexicographically_less_vertex(const ClipVertex &a, const ClipVertex &b)
      {
        return lexicographically_less(a.x, b.x);
      }

      // The point where the edge [a, b] crosses the plane @p label, from the
      // signed distances @p da, @p db of its ends (of opposite signs), and
      // its planes: the two the ends have in common (those of the edge) and
      // the new one. Computed from the lexicographically smaller end, so
      // that the two faces sharing the edge (which run along it in opposite
      // directions) get the same bits.
      ClipVertex
      crossing(const ClipVertex &a, const double da, const ClipVertex &b, const double db, const int label)
      {
        if (lexicographically_less(b.x, a.x))
          return crossing(b, db, a, da, label);
        const double t = da / (da - db);
        ClipVertex   v{a.x + t * (b.x - a.x), {{no_plane, no_plane, no_plane}}};
        if (a.planes[0] != no_plane && b.planes[0] != no_plane)
          {
            std::array<int, 3> common;
            const auto         end =
              std::set_intersection(a.planes.begin(), a.planes.end(), b.planes.begin(), b.planes.end(), common.begin());
            if (end - common.begin() == 2)
              {
                v.planes = {{common[0], common[1], label}};
                std::sort(v.planes.begin(), v.planes.end());
              }
          }
        return v;
      }

      // Buffers of clip(), kept from one call to the next.
      struct ClipScratch
      {
        std::vector<double>                          d;
        std::vector<ClipVertex>                      kept;
        std::vector<ClipVertex>                      cap;
        std::vector<std::pair<double, unsigned int>> by_angle;
      };

      // Cut @p poly by the plane n.x = c (n: unit normal) and keep the part
      // n.x <= c; the new face lies in the plane and gets @p label. A vertex
      // within @p eps of the plane counts as on it: it is kept and becomes a
      // vertex of the new face, and no edge is cut next to it (otherwise it
      // would come back as a second vertex a round-off away). The new face is
      // made of the kept on-plane vertices and the edge crossings, each once,
      // ordered counterclockwise about n (its outward normal). Returns false
      // if the plane cuts nothing off.
      bool
      clip(ClipPolyhedron &poly, const Vec &n, const double c, const int label, const double eps, ClipScratch &scratch)
      {
        auto distance = [&](const ClipVertex &p) { return n * p.x - c; };
        bool any_out  = false;
        for (const auto &face : poly)
          {
            for (const auto &p : face.points)
              if (distance(p) > eps)
                {
                  any_out = true;
                  break;
                }
            if (any_out)
              break;
          }
        if (!any_out)
          return false;

        std::vector<double>     &d    = scratch.d;
        std::vector<ClipVertex> &kept = scratch.kept;
        std::vector<ClipVertex> &cap  = scratch.cap;
        cap.clear();
        unsigned int n_faces = 0;
        for (unsigned int f = 0; f < poly.size(); ++f)
          {
            ClipFace          &face = poly[f];
            const unsigned int m    = face.points.size();
            d.resize(m);
            bool strictly_inside = false, outside = false;
            for (unsigned int k = 0; k < m; ++k)
              {
                d[k] = distance(face.points[k]);
                strictly_inside |= (d[k] < -eps);
                outside |= (d[k] > eps);
              }
            // a face with no vertex strictly inside lies in the cutting plane
            // (it is part of the new face) or beyond it: dropped
            if (!strictly_inside)
              {
                for (unsigned int k = 0; k < m; ++k)
                  if (d[k] >= -eps && d[k] <= eps)
                    cap.push_back(face.points[k]);
                continue;
              }
            if (!outside)
              {
                for (unsigned int k = 0; k < m; ++k)
                  if (d[k] >= -eps)
                    cap.push_back(face.points[k]);
              }
            else
              {
                kept.clear();
                for (unsigned int k = 0; k < m; ++k)
                  {
                    const unsigned int l = (k + 1) % m;
                    if (d[k] <= eps)
                      {
                        kept.push_back(face.points[k]);
                        if (d[k] >= -eps)
                          cap.push_back(face.points[k]);
                      }
                    if ((d[k] < -eps && d[l] > eps) || (d[k] > eps && d[l] < -eps))
                      {
                        const ClipVertex x = crossing(face.points[k], d[k], face.points[l], d[l], label);
                        kept.push_back(x);
                        cap.push_back(x);
                      }
                  }
                // (the face's old buffer becomes the next face's scratch)
                face.points.swap(kept);
              }
            if (face.points.size() >= 3)
              {
                if (n_faces != f)
                  std::swap(poly[n_faces], face);
                ++n_faces;
              }
          }
        poly.resize(n_faces);

        std::sort(cap.begin(), cap.end(), lexicographically_less_vertex);
        cap.erase(std::unique(cap.begin(), cap.end(),
                              [](const ClipVertex &a, const ClipVertex &b) { return a.x == b.x; }),
                  cap.end());
        if (cap.size() >= 3)
          {
            Pt centre;
            for (const auto &p : cap)
              centre += p.x;
            centre /= cap.size();
            // an in-plane basis u, v with u x v = n: increasing angle is
            // counterclockwise about n
            unsigned int far = 0;
            for (unsigned int k = 1; k < cap.size(); ++k)
              if (cap[k].x.distance_square(centre) > cap[far].x.distance_square(centre))
                far = k;
            Vec u = cap[far].x - centre;
            u -= (u * n) * n;
            u /= u.norm();
            const Vec v        = dealii::cross_product_3d(n, u);
            auto     &by_angle = scratch.by_angle;
            by_angle.resize(cap.size());
            for (unsigned int k = 0; k < cap.size(); ++k)
              {
                const Vec r = cap[k].x - centre;
                by_angle[k] = {std::atan2(r * v, r * u), k};
              }
            std::sort(by_angle.begin(), by_angle.end());
            ClipFace new_face{label, {}};
            new_face.points.reserve(cap.size());
            for (const auto &a : by_angle)
              new_face.points.push_back(cap[a.second]);
            poly.push_back(std::move(new_face));
          }
        return true;
      }

      // Volume and centroid of a closed outward-oriented polyhedron: the
      // tetrahedra from the point @p o to the triangles of a fan of each face.
      std::pair<double, Pt>
      volume_and_centroid(const ClipPolyhedron &poly, const Pt &o)
      {
        double volume = 0;
        Vec    moment;
        for (const auto &face : poly)
          {
            const auto &q = face.points;
            for (unsigned int k = 1; k + 1 < q.size(); ++k)
              {
                const Vec    a = q[0].x - o, b = q[k].x - o, c = q[k + 1].x - o;
                const double v = a * dealii::cross_product_3d(b, c) / 6;
                volume += v;
                moment += v * (a + b + c) / 4;
              }
          }
        return {volume, volume > 0 ? o + moment / volume : o};
      }

      // A convex domain as the generator uses it: the computation runs in
      // coordinates relative to the lower corner of its bounding box
      // (`origin`), where the half-space i is n_i.x <= offset[i].
      struct ConvexDomain
      {
        std::vector<Plane>  planes;
        Pt                  origin;
        Pt                  extent;          // the bounding box, relative: [0, extent]
        double              diagonal;        // |extent|
        double              coordinate_size; // max(diagonal, largest |coordinate| of the bounding box)
        std::vector<double> offset;
        // a half-space whose normal is +-e_d exactly: axis[i] = d (else -1)
        // and the coordinate x_d of its plane, relative and absolute (a
        // vertex put on the plane gets the absolute coordinate exactly)
        std::vector<int>    axis;
        std::vector<double> axis_relative, axis_absolute;
        // the polytope (relative), its faces labelled -1 - i, and its volume;
        // whether half-space i has a face on it (a redundant one has none)
        ClipPolyhedron    polytope;
        double            volume = 0;
        std::vector<bool> has_face;

        bool
        contains(const Pt &p) const
        {
          for (unsigned int i = 0; i < planes.size(); ++i)
            if (planes[i].n * p > offset[i])
              return false;
          return true;
        }
      };

      // Lower and upper bounds of the domain along the axes and the radius of
      // its largest inscribed ball, by CGAL's linear programming in exact
      // arithmetic on the doubles of @p planes: an empty or unbounded domain
      // is told exactly, whatever its size. Throws (naming @p who) for an
      // empty or unbounded domain.
      void
      bound_domain(const std::vector<Plane> &planes, const std::string &who, Pt &lower, Pt &upper, double &inradius)
      {
        using Program  = CGAL::Quadratic_program<double>;
        using Solution = CGAL::Quadratic_program_solution<CGAL::Gmpzf>;
        // variables x, y, z free; r >= 0 (the radius, used last)
        Program lp(CGAL::SMALLER, false, 0, false, 0);
        for (unsigned int i = 0; i < planes.size(); ++i)
          {
            for (unsigned int d = 0; d < 3; ++d)
              lp.set_a(d, i, planes[i].n[d]);
            lp.set_b(i, planes[i].b);
          }
        const char *axis_name[3] = {"x", "y", "z"};
        for (unsigned int d = 0; d < 3; ++d)
          for (const int sign : {1, -1})
            {
              for (unsigned int e = 0; e < 3; ++e)
                lp.set_c(e, e == d ? sign : 0);
              const Solution solution = CGAL::solve_linear_program(lp, CGAL::Gmpzf());
              AssertThrow(!solution.is_infeasible(),
                          dealii::ExcMessage(who + ": the domain is empty: no point satisfies all " +
                                             std::to_string(planes.size()) + " half-spaces."));
              AssertThrow(!solution.is_unbounded(),
                          dealii::ExcMessage(who + ": the domain is unbounded: it extends without end towards " +
                                             (sign > 0 ? "-" : "+") + axis_name[d] +
                                             " (the half-spaces must bound a polytope)."));
              const double value = CGAL::to_double(solution.objective_value());
              if (sign > 0)
                lower[d] = value;
              else
                upper[d] = -value;
            }
        // the largest ball: max r with n_i.x + r <= b_i (|n_i| = 1)
        for (unsigned int i = 0; i < planes.size(); ++i)
          lp.set_a(3, i, 1);
        lp.set_l(3, true, 0);
        lp.set_u(3, false);
        for (unsigned int e = 0; e < 3; ++e)
          lp.set_c(e, 0);
        lp.set_c(3, -1);
        const Solution solution = CGAL::solve_linear_program(lp, CGAL::Gmpzf());
        AssertThrow(solution.is_optimal(),
                    dealii::ExcMessage(who + ": the largest ball inside the domain was not found; internal error."));
        inradius = 0. - CGAL::to_double(solution.objective_value()); // (0 - 0 = +0)
      }

      // The domain of the half-spaces @p planes: its bounding box, its
      // polytope, checked (not empty, bounded, of a volume). A side of the
      // bounding box on which a half-space's plane normal to the axis lies
      // is put exactly on that plane (for a box: the box itself, every
      // coordinate exact); the other sides lie a quarter of the diagonal
      // beyond the domain, so that the half-spaces cut them off entirely.
      ConvexDomain
      make_domain(const std::vector<Plane> &planes, const std::string &who)
      {
        ConvexDomain domain;
        domain.planes        = planes;
        const unsigned int n = planes.size();
        domain.axis.assign(n, -1);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int d = 0; d < 3; ++d)
            if (planes[i].n[(d + 1) % 3] == 0 && planes[i].n[(d + 2) % 3] == 0)
              domain.axis[i] = d;

        Pt     lower, upper;
        double inradius = 0;
        bound_domain(planes, who, lower, upper, inradius);
        const double lp_diagonal = lower.distance(upper);
        if (!(inradius > 0 && inradius >= 1e-6 * lp_diagonal))
          {
            std::ostringstream message;
            message << who << ": the domain has no interior or is too thin: its largest inscribed ball has the radius "
                    << inradius << ", less than 1e-6 of the diagonal " << lp_diagonal << " of its bounding box.";
            AssertThrow(false, dealii::ExcMessage(message.str()));
          }

        // the sides of the bounding box that lie on a plane normal to an axis
        std::array<int, 6> side_plane;
        side_plane.fill(-1);
        for (unsigned int s = 0; s < 6; ++s)
          {
            const unsigned int d     = s / 2;
            const double       sign  = (s % 2 == 0 ? -1. : 1.);
            double            &bound = (s % 2 == 0 ? lower[d] : upper[d]);
            // x_d <= b (sign +1) or x_d >= -b (sign -1): the tightest such
            // plane (least b), the first of equal ones
            for (unsigned int i = 0; i < n; ++i)
              if (domain.axis[i] == int(d) && planes[i].n[d] == sign &&
                  (side_plane[s] < 0 || planes[i].b < planes[side_plane[s]].b))
                side_plane[s] = i;
            if (side_plane[s] >= 0)
              {
                const double x = sign * planes[side_plane[s]].b;
                if (std::abs(x - bound) <= 1e-9 * lp_diagonal)
                  bound = x;
                else
                  side_plane[s] = -1;
              }
          }

        domain.origin = lower;
        for (unsigned int d = 0; d < 3; ++d)
          domain.extent[d] = upper[d] - lower[d];
        domain.diagonal        = domain.extent.norm();
        domain.coordinate_size = domain.diagonal;
        for (unsigned int d = 0; d < 3; ++d)
          domain.coordinate_size = std::max({domain.coordinate_size, std::abs(lower[d]), std::abs(upper[d])});
        domain.offset.resize(n);
        domain.axis_relative.assign(n, 0);
        domain.axis_absolute.assign(n, 0);
        for (unsigned int i = 0; i < n; ++i)
          {
            domain.offset[i] = planes[i].b - planes[i].n * Vec(domain.origin);
            if (domain.axis[i] >= 0)
              {
                const double sign       = planes[i].n[domain.axis[i]];
                const double relative   = sign * domain.offset[i];
                domain.axis_relative[i] = (relative == 0 ? 0. : relative); // (no -0)
                domain.axis_absolute[i] = sign * planes[i].b;
              }
          }

        const double       margin = 0.25 * domain.diagonal;
        Pt                 a, b;
        std::array<int, 6> label;
        for (unsigned int d = 0; d < 3; ++d)
          {
            a[d] = (side_plane[2 * d] >= 0 ? 0. : -margin);
            b[d] = (side_plane[2 * d + 1] >= 0 ? domain.extent[d] : domain.extent[d] + margin);
          }
        for (unsigned int s = 0; s < 6; ++s)
          label[s] = (side_plane[s] >= 0 ? -1 - side_plane[s] : -1 - int(n) - int(s));
        domain.polytope = box_polyhedron(a, b, label);
        ClipScratch scratch;
        for (unsigned int i = 0; i < n; ++i)
          clip(domain.polytope, planes[i].n, domain.offset[i], -1 - int(i), 1e-13 * domain.diagonal, scratch);
        for (const auto &face : domain.polytope)
          AssertThrow(face.label >= -int(n),
                      dealii::ExcMessage(who +
                                         ": a side of the domain's bounding box is left on its polytope (a corner "
                                         "of the domain sharper than the tolerances resolve); internal error."));
        domain.has_face.assign(n, false);
        for (const auto &face : domain.polytope)
          domain.has_face[-1 - face.label] = true;
        domain.volume = volume_and_centroid(domain.polytope, Pt()).first;
        AssertThrow(domain.volume > 0,
                    dealii::ExcMessage(who + ": the domain's polytope has no volume; internal error."));
        return domain;
      }

      // The Voronoi cells of @p sites in the domain, each cut from the
      // domain's polytope by the bisector planes with its neighbours in the
      // Delaunay triangulation, nearest first (of equally near ones, the
      // lower index first).
      std::vector<ClipPolyhedron>
      voronoi_cells(const std::vector<Pt> &sites,
                    const ConvexDomain    &domain,
                    const unsigned int     seed,
                    const std::string     &who)
      {
        using K   = CGAL::Exact_predicates_inexact_constructions_kernel;
        using Vb  = CGAL::Triangulation_vertex_base_with_info_3<unsigned int, K>;
        using Tds = CGAL::Triangulation_data_structure_3<Vb>;
        using DT  = CGAL::Delaunay_triangulation_3<K, Tds>;
        using CP  = K::Point_3;

        const unsigned int n   = sites.size();
        const double       eps = 1e-13 * domain.diagonal;

        std::vector<std::pair<CP, unsigned int>> points;
        points.reserve(n);
        for (unsigned int i = 0; i < n; ++i)
          points.emplace_back(CP(sites[i][0], sites[i][1], sites[i][2]), i);
        DT dt(points.begin(), points.end());
        AssertThrow(dt.number_of_vertices() == n,
                    dealii::ExcMessage(who + ": two generators coincide (seed " + std::to_string(seed) + ")."));

        std::vector<std::vector<unsigned int>> neighbours(n);
        if (dt.dimension() == 3)
          for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
            {
              const unsigned int a = e->first->vertex(e->second)->info(), b = e->first->vertex(e->third)->info();
              neighbours[a].push_back(b);
              neighbours[b].push_back(a);
            }
        else
          // the generators lie in a plane or on a line (three or fewer, or a
          // degenerate set): every other generator is a candidate
          for (unsigned int a = 0; a < n; ++a)
            for (unsigned int b = 0; b < n; ++b)
              if (a != b)
                neighbours[a].push_back(b);

        const ClipPolyhedron       &box = domain.polytope;
        std::vector<ClipPolyhedron> cells(n);
        ClipScratch                 scratch;
        for (unsigned int i = 0; i < n; ++i)
          {
            const Pt &z   = sites[i];
            auto     &nbs = neighbours[i];
            // (equal distances, as Lloyd's iteration near a symmetric
            // configuration makes them, by index: CGAL lists the edges in an
            // order that is not a function of the generators alone, it
            // changed with the calls made before in the same program, and
            // the order of the cuts changes the round-off)
            std::sort(nbs.begin(), nbs.end(), [&](const unsigned int a, const unsigned int b) {
              const double da = z.distance_square(sites[a]), db = z.distance_square(sites[b]);
              return da < db || (da == db && a < b);
            });
            ClipPolyhedron cell = box;
            // the cell lies in the ball about z through its farthest vertex:
            // a bisector beyond it (and every later one, farther still) cuts
            // nothing
            double radius = 0;
            for (const auto &face : cell)
              for (const auto &p : face.points)
                radius = std::max(radius, z.distance(p.x));
            for (const unsigned int j : nbs)
              {
                const double half = z.distance(sites[j]) / 2;
                if (half > radius + eps)
                  break;
                const Vec n_ij = (sites[j] - z) / (2 * half);
                const Pt  mid  = z + 0.5 * (sites[j] - z);
                if (clip(cell, n_ij, n_ij * mid, int(j), eps, scratch))
                  {
                    radius = 0;
                    for (const auto &face : cell)
                      for (const auto &p : face.points)
                        radius = std::max(radius, z.distance(p.x));
                  }
              }
            cells[i] = std::move(cell);
          }
        return cells;
      }

      // A spatial hash of points: a point within @p tol of one inserted
      // before is given that point's index.
      class PointMerger
      {
      public:
        explicit PointMerger(const double tol)
          : tol(tol)
        {}

        unsigned int
        find_or_add(const Pt &p)
        {
          const std::array<std::int64_t, 3> b = bucket(p);
          for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
              for (std::int64_t dz = -1; dz <= 1; ++dz)
                {
                  const auto it = buckets.find(key({{b[0] + dx, b[1] + dy, b[2] + dz}}));
                  if (it != buckets.end())
                    for (const unsigned int v : it->second)
                      if (points[v].distance(p) <= tol)
                        return v;
                }
          points.push_back(p);
          buckets[key(b)].push_back(points.size() - 1);
          return points.size() - 1;
        }

        const Pt &
        point(const unsigned int v) const
        {
          return points[v];
        }

      private:
        std::array<std::int64_t, 3>
        bucket(const Pt &p) const
        {
          return {{std::int64_t(std::floor(p[0] / tol)), std::int64_t(std::floor(p[1] / tol)),
                   std::int64_t(std::floor(p[2] / tol))}};
        }

        static std::uint64_t
        key(const std::array<std::int64_t, 3> &b)
        {
          // (a hash of the three bucket numbers: two buckets of the same
          // hash share a list, whose points are compared by their distance)
          std::uint64_t h = 1469598103934665603ull;
          for (const std::int64_t c : b)
            h = (h ^ std::uint64_t(c)) * 1099511628211ull;
          return h;
        }

        double                                                   tol;
        std::vector<Pt>                                          points;
        std::unordered_map<std::uint64_t, std::vector<unsigned>> buckets;
      };

      // @p loop itself if its points @p p lie in a plane to round-off
      // (@p round_off) and to a quarter of the planarity tolerance of
      // PolyhedralMesh::finalize() (1e-8 times the diameter), otherwise a fan
      // of triangles. A Voronoi face is planar to round-off, but where the
      // diagram is nearly degenerate (Lloyd's iteration near a symmetric
      // configuration: more than four generators nearly cospherical) the
      // vertices of a face are merged ones or computed at planes meeting at
      // small angles, and a face can be warped by 1e-9 of the box. The fan
      // starts at the vertex whose smallest triangle is largest (no sliver
      // from three nearly collinear vertices where another apex avoids it).
      std::vector<std::vector<unsigned int>>
      planar_pieces(const std::vector<unsigned int> &loop, const std::vector<Pt> &p, const double round_off)
      {
        const unsigned int m = loop.size();
        if (m == 3)
          return {loop};
        Vec    area;
        Pt     average;
        double diameter = 0;
        for (unsigned int k = 0; k < m; ++k)
          {
            if (k >= 1 && k + 1 < m)
              area += dealii::cross_product_3d(p[k] - p[0], p[k + 1] - p[0]);
            average += (p[k] - Pt()) / m;
            for (unsigned int l = k + 1; l < m; ++l)
              diameter = std::max(diameter, p[k].distance(p[l]));
          }
        double warp = 0;
        if (area.norm() > 0)
          for (unsigned int k = 0; k < m; ++k)
            warp = std::max(warp, std::abs(area * (p[k] - average)) / area.norm());
        if (area.norm() > 0 && warp <= std::min(round_off, 0.25e-8 * diameter))
          return {loop};

        unsigned int apex = 0;
        double       best = -1;
        for (unsigned int a = 0; a < m; ++a)
          {
            double smallest = std::numeric_limits<double>::max();
            for (unsigned int k = 1; k + 1 < m; ++k)
              smallest =
                std::min(smallest, dealii::cross_product_3d(p[(a + k) % m] - p[a], p[(a + k + 1) % m] - p[a]).norm());
            if (smallest > best)
              {
                best = smallest;
                apex = a;
              }
          }
        std::vector<std::vector<unsigned int>> triangles;
        for (unsigned int k = 1; k + 1 < m; ++k)
          triangles.push_back({loop[apex], loop[(apex + k) % m], loop[(apex + k + 1) % m]});
        return triangles;
      }

      // Puts @p p (relative coordinates) on the planes of the domain it lies
      // within @p tol of (those with a face of the domain: not onto a
      // redundant half-space's plane near the domain); @p near is scratch.
      // Planes normal to an axis set the coordinate exactly (the first such
      // plane of an axis, by index). Where an oblique plane is near, @p p is
      // projected onto the intersection of the near planes (at most three
      // whose normals are independent, nearest first); if that moves it by
      // more than 10 tol (planes at a small angle, far from their common
      // edge), onto the nearest plane only.
      Pt
      snap_to_domain(Pt p, const ConvexDomain &domain, const double tol, std::vector<unsigned int> &near)
      {
        near.clear();
        bool oblique = false;
        for (unsigned int i = 0; i < domain.planes.size(); ++i)
          if (domain.has_face[i] && std::abs(domain.planes[i].n * p - domain.offset[i]) <= tol)
            {
              near.push_back(i);
              oblique |= (domain.axis[i] < 0);
            }
        if (near.empty())
          return p;
        if (oblique)
          {
            auto distance = [&](const unsigned int i) { return std::abs(domain.planes[i].n * p - domain.offset[i]); };
            std::stable_sort(near.begin(), near.end(),
                             [&](const unsigned int a, const unsigned int b) { return distance(a) < distance(b); });
            // an orthonormal basis of the chosen normals (Gram-Schmidt) and
            // the residuals in it: the least move onto their planes
            std::vector<unsigned int> chosen;
            std::array<Vec, 3>        basis;
            std::array<double, 3>     residual{};
            for (const unsigned int i : near)
              {
                if (chosen.size() == 3)
                  break;
                Vec    u = domain.planes[i].n;
                double r = domain.planes[i].n * p - domain.offset[i];
                for (unsigned int k = 0; k < chosen.size(); ++k)
                  {
                    const double c = u * basis[k];
                    u -= c * basis[k];
                    r -= c * residual[k];
                  }
                const double length = u.norm();
                if (length < 1e-3)
                  continue;
                basis[chosen.size()]    = u / length;
                residual[chosen.size()] = r / length;
                chosen.push_back(i);
              }
            Pt q = p;
            for (unsigned int k = 0; k < chosen.size(); ++k)
              q -= residual[k] * basis[k];
            if (q.distance(p) > 10 * tol)
              {
                chosen.assign(1, near[0]);
                q = p - (domain.planes[near[0]].n * p - domain.offset[near[0]]) * domain.planes[near[0]].n;
              }
            p    = q;
            near = chosen;
            std::sort(near.begin(), near.end());
          }
        std::array<bool, 3> done{};
        for (const unsigned int i : near)
          if (domain.axis[i] >= 0 && !done[domain.axis[i]])
            {
              p[domain.axis[i]]    = domain.axis_relative[i];
              done[domain.axis[i]] = true;
            }
        return p;
      }

      // The cells of the last iteration into @p mesh (not finalized): the
      // vertices merged within @p tol and put on the planes of the domain
      // within @p tol (snap_to_domain()), then moved back by the domain's
      // origin (a coordinate on a plane normal to an axis becomes the
      // plane's own exactly). Each interior face is taken from the cell of
      // smaller index and reversed for the other one; a face that is not
      // planar to @p round_off is split into triangles (planar_pieces()).
      // Returns the labels of the face loops of each cell, in the order
      // given to the mesh (a piece of a face has the face's label).
      std::vector<std::vector<int>>
      add_cells(PolyhedralMesh                    &mesh,
                const std::vector<ClipPolyhedron> &cells,
                const ConvexDomain                &domain,
                const double                       tol,
                const double                       round_off,
                const std::string                 &who)
      {
        const unsigned int n = cells.size();
        PointMerger        merger(tol);
        // a vertex named by its four planes (ClipVertex) is placed where it
        // was computed first, and every copy of it is given that point
        struct NameHash
        {
          std::size_t
          operator()(const std::array<int, 4> &a) const
          {
            std::size_t h = 0;
            for (const int x : a)
              h = h * 1000003u + std::size_t(std::uint32_t(x));
            return h;
          }
        };
        std::unordered_map<std::array<int, 4>, unsigned int, NameHash> point_of_name;
        std::vector<unsigned int>                                      near;
        auto find_or_add = [&](const Pt &p) { return merger.find_or_add(snap_to_domain(p, domain, tol, near)); };

        // the face loops of every cell, as merged point indices, with labels
        std::vector<std::vector<std::pair<int, std::vector<unsigned int>>>> loops(n);
        for (unsigned int i = 0; i < n; ++i)
          for (const auto &face : cells[i])
            {
              std::vector<unsigned int> loop;
              for (const ClipVertex &cv : face.points)
                {
                  unsigned int v;
                  if (cv.planes[0] == no_plane)
                    v = find_or_add(cv.x);
                  else
                    {
                      std::array<int, 4> name{{int(i), cv.planes[0], cv.planes[1], cv.planes[2]}};
                      std::sort(name.begin(), name.end());
                      const auto found = point_of_name.find(name);
                      if (found != point_of_name.end())
                        v = found->second;
                      else
                        {
                          v = find_or_add(cv.x);
                          point_of_name.emplace(name, v);
                        }
                    }
                  if (loop.empty() || loop.back() != v)
                    loop.push_back(v);
                }
              while (loop.size() > 1 && loop.front() == loop.back())
                loop.pop_back();
              if (loop.size() >= 3)
                loops[i].emplace_back(face.label, std::move(loop));
            }

        // the mesh's vertices: in the order of first use
        std::vector<unsigned int> mesh_index;
        std::vector<Pt>           mesh_point;
        auto                      vertex = [&](const unsigned int v) {
          if (v >= mesh_index.size())
            mesh_index.resize(v + 1, dealii::numbers::invalid_unsigned_int);
          if (mesh_index[v] == dealii::numbers::invalid_unsigned_int)
            {
              const Pt &p = merger.point(v);
              Pt        q;
              for (unsigned int d = 0; d < 3; ++d)
                q[d] = domain.origin[d] + p[d];
              std::array<bool, 3> done{};
              for (unsigned int i = 0; i < domain.planes.size(); ++i)
                if (domain.axis[i] >= 0 && domain.has_face[i] && !done[domain.axis[i]] &&
                    p[domain.axis[i]] == domain.axis_relative[i])
                  {
                    q[domain.axis[i]]    = domain.axis_absolute[i];
                    done[domain.axis[i]] = true;
                  }
              mesh_index[v] = mesh.add_vertex(q);
              mesh_point.push_back(q);
            }
          return mesh_index[v];
        };
        // a loop of merged points as planar loops of mesh vertices
        std::vector<Pt> p;
        auto            pieces = [&](const std::vector<unsigned int> &merged_loop) {
          std::vector<unsigned int> loop;
          p.clear();
          for (const unsigned int v : merged_loop)
            {
              loop.push_back(vertex(v));
              p.push_back(mesh_point[loop.back()]);
            }
          return planar_pieces(loop, p, round_off);
        };

        // interior faces: the loop of the cell of smaller index, its
        // vertex set for the check of the other side, its planar pieces
        struct SharedFace
        {
          std::vector<unsigned int>              sorted;
          std::vector<std::vector<unsigned int>> pieces;
          bool                                   matched = false;
        };
        std::map<std::pair<unsigned int, unsigned int>, SharedFace> shared;

        std::vector<std::vector<int>> labels(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            std::vector<std::vector<unsigned int>> face_loops;
            for (const auto &lf : loops[i])
              {
                if (lf.first >= 0 && unsigned(lf.first) < i)
                  {
                    const unsigned int j   = lf.first;
                    const auto         it  = shared.find({j, i});
                    auto               own = lf.second;
                    std::sort(own.begin(), own.end());
                    AssertThrow(it != shared.end() && it->second.sorted == own,
                                dealii::ExcMessage(who + ": the common face of cells " + std::to_string(j) + " and " +
                                                   std::to_string(i) +
                                                   " has different vertices in the two cells after merging "
                                                   "(a nearly degenerate Voronoi diagram); internal error."));
                    it->second.matched = true;
                    for (const auto &piece : it->second.pieces)
                      face_loops.emplace_back(piece.rbegin(), piece.rend());
                    labels[i].resize(face_loops.size(), lf.first);
                  }
                else
                  {
                    auto face_pieces = pieces(lf.second);
                    face_loops.insert(face_loops.end(), face_pieces.begin(), face_pieces.end());
                    labels[i].resize(face_loops.size(), lf.first);
                    if (lf.first >= 0)
                      {
                        SharedFace &sf = shared[{i, unsigned(lf.first)}];
                        sf.sorted      = lf.second;
                        std::sort(sf.sorted.begin(), sf.sorted.end());
                        sf.pieces = std::move(face_pieces);
                      }
                  }
              }
            mesh.add_cell(face_loops);
          }
        for (const auto &[pair, sf] : shared)
          AssertThrow(sf.matched, dealii::ExcMessage(
                                    who + ": the common face of cells " + std::to_string(pair.first) + " and " +
                                    std::to_string(pair.second) + " is missing in cell " + std::to_string(pair.second) +
                                    " after merging the vertices (a nearly degenerate Voronoi diagram); "
                                    "internal error."));
        return labels;
      }

      // The centroidal Voronoi mesh of the domain of @p planes: the common
      // work of voronoi_box() and voronoi_convex(), their errors naming
      // @p who. The vertices are merged within 1e-7 of the domain's diagonal
      // or, with @p merge_by_coordinates (voronoi_box(), as it always did),
      // of the larger of the diagonal and the largest coordinate.
      void
      voronoi_mesh(PolyhedralMesh           &mesh,
                   const std::vector<Plane> &planes,
                   const unsigned int        n_cells,
                   const unsigned int        lloyd_iterations,
                   const unsigned int        seed,
                   const std::string        &who,
                   const bool                merge_by_coordinates)
      {
        const ConvexDomain domain = make_domain(planes, who);
        const Pt          &L      = domain.extent;
        AssertThrow(domain.volume >= 1e-6 * L[0] * L[1] * L[2],
                    dealii::ExcMessage(who + ": the domain fills less than 1e-6 of its bounding box (the generators "
                                             "are drawn in the box and kept inside the domain): turn it to the axes."));

        // generators uniform in the domain: drawn in its bounding box, those
        // outside it drawn again
        std::mt19937                           rng(seed);
        std::uniform_real_distribution<double> ux(0, L[0]), uy(0, L[1]), uz(0, L[2]);
        std::vector<Pt>                        sites(n_cells);
        for (auto &s : sites)
          while (true)
            {
              // (one draw per statement: the order of evaluation of the
              // arguments of a call is unspecified)
              const double x = ux(rng), y = uy(rng), z = uz(rng);
              s = Pt(x, y, z);
              if (domain.contains(s))
                break;
            }

        std::vector<ClipPolyhedron> cells;
        for (unsigned int iteration = 0; iteration <= lloyd_iterations; ++iteration)
          {
            cells = voronoi_cells(sites, domain, seed, who);
            if (iteration == lloyd_iterations)
              break;
            for (unsigned int i = 0; i < n_cells; ++i)
              {
                const auto vc = volume_and_centroid(cells[i], sites[i]);
                if (vc.first > 0)
                  sites[i] = vc.second;
              }
          }

        mesh.clear();
        mesh.name = who + " " + std::to_string(n_cells) + " cells, seed " + std::to_string(seed);
        // Vertices closer than 1e-7 of the domain's size are merged: the
        // nearly degenerate diagrams of Lloyd's iteration near a symmetric
        // configuration have edges of any small length, and a face that
        // small would be refused by finalize() (1e-8 of its diameter, the
        // planarity tolerance, would be below the round-off of the
        // coordinates). A face warped by more than 1e-13 of the size of the
        // coordinates (their round-off) is split into triangles.
        const double tol    = 1e-7 * (merge_by_coordinates ? domain.coordinate_size : domain.diagonal);
        const auto   labels = add_cells(mesh, cells, domain, tol, 1e-13 * domain.coordinate_size, who);
        mesh.finalize();
        // the boundary ids: the index of the half-space a face lies on (its
        // label), the cell's faces in the order of their loops
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          {
            AssertThrow(mesh.cell(c).faces.size() == labels[c].size(),
                        dealii::ExcMessage(who + ": cell " + std::to_string(c) +
                                           " has other faces than were given to the mesh; internal error."));
            for (unsigned int k = 0; k < labels[c].size(); ++k)
              {
                const unsigned int f = mesh.cell(c).faces[k];
                if (!mesh.face(f).at_boundary())
                  continue;
                const int label = labels[c][k];
                AssertThrow(label < 0 && label >= -int(planes.size()),
                            dealii::ExcMessage(who + ": boundary face " + std::to_string(f) +
                                               " lies on none of the half-spaces' planes; internal error."));
                mesh.set_face_boundary_id(f, dealii::types::boundary_id(-1 - label));
              }
          }
        AssertThrow(std::abs(mesh.total_volume() - domain.volume) <= 1e-10 * domain.volume,
                    dealii::ExcMessage(who + ": the cells do not fill the domain; internal error."));
      }

      // The half-spaces of the facets of the convex hull of @p points: the
      // hull triangles of CGAL's Delaunay triangulation (the finite facets
      // of its infinite cells), those in one plane (an exact test) joined
      // into one facet. The normal of a facet is the sum of its triangles'
      // outward area vectors, normalised; its offset the largest n.p of its
      // vertices.
      std::vector<std::pair<Vec, double>>
      hull_half_spaces(const std::vector<Pt> &points)
      {
        using K  = CGAL::Exact_predicates_inexact_constructions_kernel;
        using DT = CGAL::Delaunay_triangulation_3<K>;
        using CP = K::Point_3;
        std::vector<CP> cgal_points;
        Vec             mean;
        for (const Pt &p : points)
          {
            AssertThrow(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]),
                        dealii::ExcMessage("convex_hull_half_spaces: a point has a coordinate that is not a finite "
                                           "number."));
            cgal_points.emplace_back(p[0], p[1], p[2]);
            mean += p / double(points.size());
          }
        const DT dt(cgal_points.begin(), cgal_points.end());
        AssertThrow(dt.dimension() == 3,
                    dealii::ExcMessage("convex_hull_half_spaces: the points lie in a plane (or on a line): their hull "
                                       "has no volume."));
        auto to_pt = [](const CP &p) { return Pt(p.x(), p.y(), p.z()); };

        struct Facet
        {
          std::array<CP, 3> triangle; // one of its triangles
          Vec               area;     // the sum of its outward area vectors
          std::vector<Pt>   vertices;
        };
        std::vector<Facet>           facets;
        std::vector<DT::Cell_handle> outer;
        dt.incident_cells(dt.infinite_vertex(), std::back_inserter(outer));
        for (const auto &cell : outer)
          {
            const int k    = cell->index(dt.infinite_vertex());
            CP        a    = cell->vertex((k + 1) % 4)->point();
            CP        b    = cell->vertex((k + 2) % 4)->point();
            CP        c    = cell->vertex((k + 3) % 4)->point();
            Vec       area = 0.5 * dealii::cross_product_3d(to_pt(b) - to_pt(a), to_pt(c) - to_pt(a));
            if (area * (Pt(mean) - to_pt(a)) > 0)
              {
                std::swap(b, c);
                area = -area;
              }
            Facet *facet = nullptr;
            for (auto &f : facets)
              if (f.area * area > 0 && CGAL::coplanar(f.triangle[0], f.triangle[1], f.triangle[2], a) &&
                  CGAL::coplanar(f.triangle[0], f.triangle[1], f.triangle[2], b) &&
                  CGAL::coplanar(f.triangle[0], f.triangle[1], f.triangle[2], c))
                {
                  facet = &f;
                  break;
                }
            if (facet == nullptr)
              {
                facets.push_back(Facet{{{a, b, c}}, Vec(), {}});
                facet = &facets.back();
              }
            facet->area += area;
            for (const CP &p : {a, b, c})
              facet->vertices.push_back(to_pt(p));
          }
        std::vector<std::pair<Vec, double>> half_spaces;
        for (const auto &f : facets)
          {
            const Vec n = f.area / f.area.norm();
            double    b = -std::numeric_limits<double>::max();
            for (const Pt &p : f.vertices)
              b = std::max(b, n * p);
            half_spaces.emplace_back(n, b);
          }
        return half_spaces;
      }
#endif
    } // namespace
  }   // namespace polyhedral_generators_internal



  namespace PolyhedralMeshGenerators
  {
    void
    hyper_rectangle(PolyhedralMesh                   &mesh,
                    const dealii::Point<3>           &lower,
                    const dealii::Point<3>           &upper,
                    const std::array<unsigned int, 3> subdivisions)
    {
      using namespace polyhedral_generators_internal;
      check_box(lower, upper, "hyper_rectangle");
      const unsigned int nx = subdivisions[0], ny = subdivisions[1], nz = subdivisions[2];
      AssertThrow(nx >= 1 && ny >= 1 && nz >= 1,
                  dealii::ExcMessage("hyper_rectangle: the numbers of subdivisions must be at least 1."));
      mesh.clear();
      mesh.name = "hyper_rectangle " + std::to_string(nx) + "x" + std::to_string(ny) + "x" + std::to_string(nz);
      // (the last vertex of a row is the upper corner's coordinate exactly)
      auto coordinate = [&](const unsigned int d, const unsigned int i) {
        return i == subdivisions[d] ? upper[d] : lower[d] + (upper[d] - lower[d]) * i / subdivisions[d];
      };
      for (unsigned int k = 0; k <= nz; ++k)
        for (unsigned int j = 0; j <= ny; ++j)
          for (unsigned int i = 0; i <= nx; ++i)
            mesh.add_vertex(Pt(coordinate(0, i), coordinate(1, j), coordinate(2, k)));
      auto v = [&](const unsigned int i, const unsigned int j, const unsigned int k) {
        return (k * (ny + 1) + j) * (nx + 1) + i;
      };
      for (unsigned int k = 0; k < nz; ++k)
        for (unsigned int j = 0; j < ny; ++j)
          for (unsigned int i = 0; i < nx; ++i)
            mesh.add_cell({{v(i, j, k), v(i, j, k + 1), v(i, j + 1, k + 1), v(i, j + 1, k)},                   // x-
                           {v(i + 1, j, k), v(i + 1, j + 1, k), v(i + 1, j + 1, k + 1), v(i + 1, j, k + 1)},   // x+
                           {v(i, j, k), v(i + 1, j, k), v(i + 1, j, k + 1), v(i, j, k + 1)},                   // y-
                           {v(i, j + 1, k), v(i, j + 1, k + 1), v(i + 1, j + 1, k + 1), v(i + 1, j + 1, k)},   // y+
                           {v(i, j, k), v(i, j + 1, k), v(i + 1, j + 1, k), v(i + 1, j, k)},                   // z-
                           {v(i, j, k + 1), v(i + 1, j, k + 1), v(i + 1, j + 1, k + 1), v(i, j + 1, k + 1)}}); // z+
      finish_box(mesh, lower, upper);
    }



    void
    voronoi_box(PolyhedralMesh         &mesh,
                const dealii::Point<3> &lower,
                const dealii::Point<3> &upper,
                const unsigned int      n_cells,
                const unsigned int      lloyd_iterations,
                const unsigned int      seed)
    {
      using namespace polyhedral_generators_internal;
      check_box(lower, upper, "voronoi_box");
      AssertThrow(n_cells >= 1, dealii::ExcMessage("voronoi_box: at least one cell is needed."));
#ifndef DEALVEM_WITH_CGAL
      (void)mesh;
      (void)lloyd_iterations;
      (void)seed;
      AssertThrow(false, dealii::ExcMessage("voronoi_box: dealvem was configured without CGAL; the Voronoi mesh "
                                            "generator needs it (install CGAL, e.g. apt-get install libcgal-dev, and "
                                            "configure dealvem again with -DDEALVEM_WITH_CGAL=ON), or use "
                                            "hyper_rectangle()."));
#else
      voronoi_mesh(mesh, normalised_half_spaces(box_half_spaces(lower, upper), "voronoi_box"), n_cells,
                   lloyd_iterations, seed, "voronoi_box", true);
#endif
    }



    void
    voronoi_convex(PolyhedralMesh                                             &mesh,
                   const std::vector<std::pair<dealii::Tensor<1, 3>, double>> &half_spaces,
                   const unsigned int                                          n_cells,
                   const unsigned int                                          lloyd_iterations,
                   const unsigned int                                          seed)
    {
      using namespace polyhedral_generators_internal;
      AssertThrow(n_cells >= 1, dealii::ExcMessage("voronoi_convex: at least one cell is needed."));
      const std::vector<Plane> planes = normalised_half_spaces(half_spaces, "voronoi_convex");
#ifndef DEALVEM_WITH_CGAL
      (void)mesh;
      (void)planes;
      (void)lloyd_iterations;
      (void)seed;
      AssertThrow(false, dealii::ExcMessage("voronoi_convex: dealvem was configured without CGAL; the Voronoi mesh "
                                            "generator needs it (install CGAL, e.g. apt-get install libcgal-dev, and "
                                            "configure dealvem again with -DDEALVEM_WITH_CGAL=ON)."));
#else
      voronoi_mesh(mesh, planes, n_cells, lloyd_iterations, seed, "voronoi_convex", false);
#endif
    }



    std::vector<std::pair<dealii::Tensor<1, 3>, double>>
    convex_hull_half_spaces(const std::vector<dealii::Point<3>> &points)
    {
      using namespace polyhedral_generators_internal;
      AssertThrow(points.size() >= 4, dealii::ExcMessage("convex_hull_half_spaces: " + std::to_string(points.size()) +
                                                         " points; a hull with a volume needs at least four."));
#ifndef DEALVEM_WITH_CGAL
      AssertThrow(false, dealii::ExcMessage("convex_hull_half_spaces: dealvem was configured without CGAL, which "
                                            "computes the hull (configure dealvem again with "
                                            "-DDEALVEM_WITH_CGAL=ON)."));
      return {};
#else
      return hull_half_spaces(points);
#endif
    }
  } // namespace PolyhedralMeshGenerators
} // namespace dealvem
