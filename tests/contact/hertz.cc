// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Hertz contact (NAFEMS): a half cylinder R = 50, E = 70000, on a block
// [-100,100]x[-100,0], E = 210000, nu = 0.3, plane strain, frictionless
// unilateral contact; the flat cut of the cylinder is a rigid boundary part
// loaded by (0, -P), P = 35000. Both meshes are deal.II quadrilaterals
// refined toward the contact zone (block edge 0.125, cylinder arc edge
// 0.153 there), converted to polygons and read back through 'vtk file', so
// the curved and the flat side do not match and node insertion keeps the
// real gaps between them. For k = 1 and k = 2:
// - recovered peak pressure within 1 % of p0 = 2P/(pi a);
// - half-width within one local edge of a = sqrt(4PR/(pi E*));
// - recovered nodal pressure within 1.5 % (k = 1) and 1 % (k = 2) of p0 at
//   every pair with |x| < 0.8a, the raw multipliers per length within
//   2.5 % (k = 1) and 0.7 % (k = 2), the recovered no worse than the raw
//   ones for k = 2;
// - no open pair inside |x| < a - h; no open-end warning;
// - total contact force = P to 1e-10 relative;
// - for both choices of the master body (the flat block, the cylinder):
//   the recovered pressures at |x| < 0.8a agree within 0.5 % of p0 and the
//   stresses of the cells there within 2 % of p0 (no master bias beyond
//   the discretisation error: the contact direction is the flat block's
//   normal whichever side is master).
// And the warning for a contact part that is too short: with the block's
// contact part cut to |x| <= 4 < a, the pairs at both ends of the paired
// part are active where both boundaries go on smoothly, so the run reports
// two open-end warnings (k = 1).
// The mesh code is a copy of the one in examples/step-3 (kept small).
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/mesh_io.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>

#include "../contact_common.h"
#include "../graded_meshes.h"
#include "../tests.h"

namespace
{
  constexpr double R = 50., E_cyl = 70000., E_block = 210000., nu = 0.3, P = 35000.;
  constexpr double h_target = 0.125, x_strip = 8.;

  // block: ids 0 left, 1 right, 2 bottom, 3 top
  void
  write_block(const std::string &file)
  {
    testing::write_graded_block(file, h_target, x_strip);
  }


  // lower half disk about (0, R): ids 0 arc, 1 flat cut
  void
  write_cylinder(const std::string &file)
  {
    const dealii::Point<2>   centre(0, R);
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::half_hyper_ball(tria, dealii::Point<2>(), R);
    dealii::GridTools::rotate(-M_PI / 2, tria);
    dealii::GridTools::shift(centre - dealii::Point<2>(), tria);
    tria.set_manifold(0, dealii::SphericalManifold<2>(centre));
    tria.refine_global(3);
    testing::refine_toward(tria, h_target, [&](const dealii::Point<2> &p) {
      const auto   q = p - centre;
      const double r = q.norm();
      if (r > 1e-12 * R)
        {
          const auto on_arc = centre + (R / r) * q;
          if (std::abs(on_arc[0]) <= x_strip && on_arc[1] < R)
            return std::abs(r - R);
        }
      const double ye = R - std::sqrt(R * R - x_strip * x_strip);
      return std::min(p.distance(dealii::Point<2>(-x_strip, ye)), p.distance(dealii::Point<2>(x_strip, ye)));
    });
    dealvem::PolygonalMesh<2> mesh;
    dealvem::PolygonalMeshGenerators::from_triangulation(mesh, tria);
    dealvem::MeshIO::write_vtk(mesh, file);
  }

  // longest edge with boundary id @p id of the mesh in @p file over |x| <= s
  double
  local_edge(const std::string &file, const unsigned int id, const double s)
  {
    dealvem::PolygonalMesh<2> mesh;
    dealvem::MeshIO::read_vtk(mesh, file);
    double h = 0;
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      {
        const auto &edge = mesh.edge(e);
        if (!edge.at_boundary() || edge.boundary_id != id)
          continue;
        const auto &a = mesh.vertex(edge.vertices[0]), &b = mesh.vertex(edge.vertices[1]);
        if (std::abs(0.5 * (a[0] + b[0])) <= s)
          h = std::max(h, a.distance(b));
      }
    return h;
  }

  std::string
  hertz_prm(const unsigned int k, const std::string &block_file = "block.vtk", const bool block_master = true)
  {
    std::ostringstream p;
    p << "set Number of bodies = 2\n"
      << "subsection Mesh\n  set Type = vtk file\n  set File name = " << block_file << "\nend\n"
      << "subsection Material\n  set Model = plane strain\n  set Young's modulus = " << E_block
      << "\n  set Poisson's ratio = " << nu << "\nend\n"
      << "subsection Body 1\n  subsection Mesh\n    set Type = vtk file\n    set File name = cylinder.vtk\n"
      << "    set Boundary id offset = 10\n  end\n  subsection Material\n    set Young's modulus = " << E_cyl
      << "\n    set Poisson's ratio = " << nu << "\n  end\nend\n"
      << "subsection Discretization\n  set Order = " << k << "\nend\n"
      << "subsection Contact\n  set Pairs = " << (block_master ? "3 : 10" : "10 : 3") << "\n  set Normal = unilateral\n"
      << "  set Tangential = frictionless\nend\n"
      << "subsection Boundary conditions and loads\n  set Dirichlet = 2 : xy : 0, 0\n"
      << "  set Rigid boundary = 11 : 0, " << -P << "\n  set Point constraints = 0, 50 : x : 0 : 1"
      // with the cylinder as master the pair normals are radial, so
      // frictionless contact leaves the rotation about the cylinder's
      // centre free: hold its lowest point horizontally (u_x = 0 there by
      // symmetry), for both choices alike
      << "; 0, 0 : x : 0 : 1\nend\n"
      << "subsection Output\n  set Write VTU = false\n  set Write JSON = false\n"
      << "  set Write pictures = false\n  set Write CSV = false\nend\n";
    return p.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double E_star = 1. / ((1. - nu * nu) / E_cyl + (1. - nu * nu) / E_block);
  const double a      = std::sqrt(4. * P * R / (M_PI * E_star));
  const double p0     = 2. * P / (M_PI * a);
  auto         exact  = [&](const double x) { return std::abs(x) < a ? p0 * std::sqrt(1. - x * x / (a * a)) : 0.; };
  std::cout << "a = " << a << ", p0 = " << p0 << std::endl;

  write_block("block.vtk");
  write_cylinder("cylinder.vtk");
  const double h = std::max(local_edge("block.vtk", 3, a + 1), local_edge("cylinder.vtk", 0, a + 1));
  std::cout << "local edge length h = " << h << std::endl;

  // the recovered pressure of a run at x (linear between its closed pairs)
  const auto pressure_at = [](const dealvem::ContactProblem::Results &r, const double x) {
    std::vector<std::pair<double, double>> px;
    for (const auto &pair : r.pairs)
      px.emplace_back(pair.location[0], pair.pressure);
    std::sort(px.begin(), px.end());
    const auto it = std::lower_bound(px.begin(), px.end(), std::make_pair(x, -1e300));
    if (it == px.begin() || it == px.end())
      return it == px.end() ? px.back().second : px.front().second;
    const auto &l = *(it - 1), &u = *it;
    return u.first == l.first ? u.second : l.second + (x - l.first) / (u.first - l.first) * (u.second - l.second);
  };

  for (const unsigned int k : {1u, 2u})
    {
      dealvem::ContactProblem::Results by_master[2];
      for (const bool block_master : {true, false})
        {
          const std::string tag = "k=" + std::to_string(k) + ", master " + (block_master ? "block" : "cylinder");
          const auto        r   = testing::run_contact(hertz_prm(k, "block.vtk", block_master));
          double            p_max = 0, error = 0, raw_error = 0, x_min = 0, x_max = 0;
          unsigned int      open_inside = 0;
          for (const auto &pair : r.pairs)
            if (pair.active)
              {
                x_min = std::min(x_min, pair.location[0]);
                x_max = std::max(x_max, pair.location[0]);
              }
          double open_left = -1e10, open_right = 1e10;
          for (const auto &pair : r.pairs)
            {
              const double x = pair.location[0];
              p_max          = std::max(p_max, pair.pressure);
              if (std::abs(x) < 0.8 * a)
                {
                  error     = std::max(error, std::abs(pair.pressure - exact(x)));
                  raw_error = std::max(raw_error, std::abs(pair.lumped_pressure - exact(x)));
                }
              if (!pair.active)
                {
                  if (std::abs(x) < a - h)
                    ++open_inside;
                  if (x > x_max)
                    open_right = std::min(open_right, x);
                  if (x < x_min)
                    open_left = std::max(open_left, x);
                }
            }
          // edge of the contact zone: middle between the last closed and the
          // first open pair, on both sides
          const double a_h = 0.25 * (x_max + open_right - x_min - open_left);
          std::cout << tag << ": peak " << p_max / p0 - 1 << ", (a_h - a)/h " << (a_h - a) / h
                    << ", max nodal error inside 0.8a / p0: recovered " << error / p0 << ", raw " << raw_error / p0
                    << ", active-set iterations " << r.active_set_iterations << std::endl;
          testing::check_small(p_max / p0 - 1., 0.01, tag + ": peak pressure / p0 - 1");
          testing::check_small((a_h - a) / h, 1., tag + ": (half-width - a) / h");
          testing::check_small(error / p0, k == 2 ? 0.01 : 0.015, tag + ": max recovered nodal pressure error inside 0.8a / p0");
          // the multipliers themselves (issue 17: k = 2 raw within 0.7 % of
          // p0 on a mesh like step-3's level 1; measured 0.56 %)
          testing::check_small(raw_error / p0, k == 2 ? 0.007 : 0.025, tag + ": max raw nodal pressure error inside 0.8a / p0");
          if (k == 2)
            testing::check(error <= raw_error, tag + ": the recovered pressure is no worse than the raw one");
          testing::check(open_inside == 0, tag + ": no open pair inside |x| < a - h (" + std::to_string(open_inside) + ")");
          testing::check(r.n_open_end_warnings == 0, tag + ": no open-end warnings");
          // (on the slave body: the cylinder, or the block when it is the slave)
          const double sign = block_master ? 1. : -1.;
          testing::check_small(sign * r.total_contact_force[1] / P - 1., 1e-10, tag + ": total contact force / P - 1");
          testing::check_small(r.total_contact_force[0] / P, 1e-10, tag + ": horizontal contact force / P");
          by_master[block_master] = r;
        }
      // no master bias: the recovered pressures of the two choices at the
      // pairs inside 0.8a, and the stresses of every cell
      double d_pressure = 0, d_stress = 0;
      for (const auto &pair : by_master[0].pairs)
        if (std::abs(pair.location[0]) < 0.8 * a)
          d_pressure = std::max(d_pressure, std::abs(pair.pressure - pressure_at(by_master[1], pair.location[0])));
      const auto &s0 = by_master[0].cell_stress, &s1 = by_master[1].cell_stress;
      testing::check(s0.size() == s1.size(), "k=" + std::to_string(k) + ": the same cells for both masters");
      // (cells with their centroid at |x| < 0.8a: the edge of the contact
      // zone, where the last closed pair may differ, is left out as for the
      // pressures)
      std::vector<dealii::Point<2>> vertices;
      for (unsigned int c = 0; c < std::min(s0.size(), s1.size()); ++c)
        {
          by_master[0].mesh.cell_vertices(c, vertices);
          double x = 0;
          for (const auto &v : vertices)
            x += v[0] / vertices.size();
          if (std::abs(x) < 0.8 * a)
            for (unsigned int i = 0; i < 3; ++i)
              d_stress = std::max(d_stress, std::abs(s0[c][i] - s1[c][i]));
        }
      std::cout << "k=" << k << ", master block against master cylinder: recovered pressure inside 0.8a differs by "
                << d_pressure / p0 << " p0, cell stresses by " << d_stress / p0 << " p0" << std::endl;
      testing::check_small(d_pressure / p0, 0.005, "k=" + std::to_string(k) + ": master choice, recovered pressure / p0");
      testing::check_small(d_stress / p0, 0.02, "k=" + std::to_string(k) + ": master choice, cell stresses / p0");
    }
  {
    dealvem::PolygonalMesh<2> block;
    dealvem::MeshIO::read_vtk(block, "block.vtk");
    for (unsigned int e = 0; e < block.n_edges(); ++e)
      {
        const auto &edge = block.edge(e);
        if (edge.at_boundary() && edge.boundary_id == 3 &&
            std::abs(0.5 * (block.vertex(edge.vertices[0])[0] + block.vertex(edge.vertices[1])[0])) > 4.)
          block.set_edge_boundary_id(e, 4);
      }
    dealvem::MeshIO::write_vtk(block, "block-cut.vtk");
    const auto r = testing::run_contact(hertz_prm(1, "block-cut.vtk"));
    testing::check(r.n_open_end_warnings == 2,
                   "contact part |x| <= 4 < a: two open-end warnings (" + std::to_string(r.n_open_end_warnings) + ")");
  }
  return testing::finish();
}
