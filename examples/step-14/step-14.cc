// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// step-14: 3D elasticity on polyhedra (issue 43).
//
// Build (from a dealvem build directory):   make step-14
// Run:                                      ./examples/step-14 [--fine]
// What it does:
// 1. A spherical cavity of radius a = 1 in an elastic body under remote
//    uniaxial tension S = 1 along z (E = 1, nu = 0.3): one octant of a
//    thick shell a <= r <= R = 10 (deal.II's quarter_hyper_shell, refined
//    towards the cavity), symmetry on the planes x = 0, y = 0, z = 0 and
//    the remote traction S e_z (e_z . n) on the outer sphere. The
//    hexahedra of the curved shell have warped faces: each is split into
//    two triangles (PolyhedralMesh::from_triangulation(..., true)), so the
//    cells are polyhedra with up to twelve faces. First-order virtual
//    elements, CG with ML AMG (six rigid modes). Compared with Goodier's
//    solution (1933): on the equatorial plane
//      sigma_zz(r) = S [1 + (4 - 5 nu)/(2 (7 - 5 nu)) (a/r)^3
//                         + 9/(2 (7 - 5 nu)) (a/r)^5],
//    whose value at r = a is the stress concentration factor
//    K_t = (27 - 15 nu)/(2 (7 - 5 nu)) = 2.0455. The cells along the
//    equator give sigma_zz at their centroids; a least-squares fit of
//    Goodier's form S [1 + A (a/r)^3 + B (a/r)^5] to them gives the
//    computed K_t = 1 + A + B. Writes step-14-cavity.vtu (ParaView:
//    displacement, the six stresses and von Mises per cell) and
//    step-14-cavity.csv (r, the computed and Goodier's sigma_zz).
// 2. Centroidal Voronoi polyhedra of the unit cube (CGAL, Lloyd's
//    iteration): the displacement patch test to round-off, then a smooth
//    manufactured solution on 64, 512 and 4096 cells (125, 1000 and 8000
//    with --fine): the errors of the projected solution fall as h^2 in L2
//    and h in H1. Writes step-14-voronoi.vtu (the coarsest mesh).
// The program stops with an error unless: K_t is within 1 % of Goodier's
// (0.5 % with --fine); the equatorial stresses are within 3 % (1.5 %) of
// Goodier's at every cell centroid with r <= 3a; the Voronoi patch test holds to
// 1e-10; the Voronoi rates between the two finest meshes are at least 1.8
// (L2) and 0.85 (H1).

// @sect3{Include files}
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <dealvem/app/polyhedral_elasticity.h>
#include <dealvem/mesh/polyhedral_generators.h>
#include <dealvem/mesh/polyhedral_mesh.h>
#include <dealvem/postprocessing/svg_plots.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace Step14
{
  using namespace dealvem;
  using P = dealii::Point<3>;
  using T = dealii::Tensor<1, 3>;

  // @sect3{Goodier's solution on the equatorial plane}
  double
  goodier_sigma_zz(const double r, const double a, const double nu)
  {
    const double q = a / r;
    return 1 + (4 - 5 * nu) / (2 * (7 - 5 * nu)) * q * q * q + 9 / (2 * (7 - 5 * nu)) * std::pow(q, 5);
  }

  // @sect3{The cavity}
  //
  // The octant of the shell a <= r <= R, refined @p refinements times, then
  // its radii graded towards the cavity: a vertex at radius r moves to
  // a + (R - a) t^2 with t = (r - a)/(R - a), which keeps spheres spheres
  // and puts the small cells where the stress varies fastest.
  void
  cavity(const unsigned int refinements, const double kt_tolerance, const double profile_tolerance)
  {
    const double a = 1, R = 10, nu = 0.3;
    dealii::Timer timer;
    dealii::Triangulation<3> tria;
    dealii::GridGenerator::quarter_hyper_shell(tria, P(), a, R, 0, true);
    tria.refine_global(refinements);
    dealii::GridTools::transform(
      [a, R](const P &x) {
        const double r = x.norm();
        const double t = (r - a) / (R - a);
        return P(x * ((a + (R - a) * t * t) / r));
      },
      tria);
    PolyhedralMesh mesh = PolyhedralMesh::from_triangulation(tria, 1e-8, true);
    std::cout << "Spherical cavity: " << mesh.n_cells() << " polyhedra (" << tria.n_active_cells()
              << " hexahedra with their warped faces split), " << mesh.n_faces() << " faces, " << 3 * mesh.n_vertices()
              << " DoFs" << std::endl;

    PolyhedralElasticity::Settings settings;
    settings.material                  = {1., nu};
    settings.solver.type               = LinearSolver::Type::cg_amg;
    settings.solver.relative_tolerance = 1e-10;
    PolyhedralElasticity problem(mesh, settings);
    const auto zero = [](const P &) { return T(); };
    problem.add_dirichlet(2, zero, {{true, false, false}}); // x = 0
    problem.add_dirichlet(3, zero, {{false, true, false}}); // y = 0
    problem.add_dirichlet(4, zero, {{false, false, true}}); // z = 0
    problem.add_traction(1, [](const P &, const T &n) { return T({0, 0, n[2]}); });
    problem.solve();
    std::cout << "  assembly " << problem.last_times().first << " s, CG-AMG " << problem.last_iterations()
              << " iterations, " << problem.last_times().second << " s" << std::endl;

    // the cells whose centroid lies within half a cell of the plane z = 0
    const auto stress = problem.cell_stresses();
    PolyhedralElement                    element;
    PolyhedralElement::CellData          data;
    std::vector<std::pair<double, double>> equator; // (r, sigma_zz)
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        element.compute(mesh, c, nullptr, data);
        const double r = data.centroid.norm();
        if (std::abs(data.centroid[2]) < 0.25 * data.diameter)
          equator.emplace_back(r, stress[6 * c + 2]);
      }
    std::sort(equator.begin(), equator.end());
    AssertThrow(equator.size() >= 4, dealii::ExcMessage("step-14: too few cells along the equator."));
    // least squares: sigma - 1 = A q^3 + B q^5, q = a / r
    dealii::LAPACKFullMatrix<double> normal(2, 2);
    dealii::Vector<double>           rhs(2);
    double                           worst = 0;
    std::ofstream                    csv("step-14-cavity.csv");
    csv << "r,sigma_zz,goodier\n";
    for (const auto &[r, s] : equator)
      {
        const double q = a / r, f[2] = {q * q * q, std::pow(q, 5)};
        for (unsigned int i = 0; i < 2; ++i)
          {
            rhs[i] += f[i] * (s - 1);
            for (unsigned int j = 0; j < 2; ++j)
              normal(i, j) += f[i] * f[j];
          }
        const double exact = goodier_sigma_zz(r, a, nu);
        csv << r << ',' << s << ',' << exact << '\n';
        if (r <= 3 * a)
          worst = std::max(worst, std::abs(s - exact) / exact);
      }
    {
      SVGPlots::Series computed{"cell stress sigma_zz at the centroid (dealvem, k = 1)", {}, false, 2.5},
        exact{"Goodier (1933)", {}, true, 0};
      for (const auto &[r, s] : equator)
        if (r <= 4 * a)
          computed.points.emplace_back(r, s);
      for (unsigned int i = 0; i <= 60; ++i)
        {
          const double r = a + 3 * a * i / 60.;
          exact.points.emplace_back(r, goodier_sigma_zz(r, a, nu));
        }
      SVGPlots::write_line_plot("step-14-cavity.svg", {exact, computed}, "r / a (plane z = 0)", "sigma_zz / S",
                                "Spherical cavity under remote tension: stress on the equatorial plane");
    }
    normal.compute_lu_factorization();
    normal.solve(rhs);
    const double kt = 1 + rhs[0] + rhs[1], kt_exact = goodier_sigma_zz(a, a, nu);
    std::cout << "  equator: " << equator.size() << " cells; the cell nearest the cavity (r = " << equator[0].first
              << "): sigma_zz " << equator[0].second << ", Goodier there " << goodier_sigma_zz(equator[0].first, a, nu)
              << std::endl
              << "  fitted K_t = " << kt << " against Goodier's " << kt_exact << " (" << std::showpos
              << 100 * (kt / kt_exact - 1) << std::noshowpos << " %); largest deviation at r <= 3a: " << 100 * worst
              << " %" << std::endl;
    problem.write_vtu("step-14-cavity.vtu");
    std::cout << "  wrote step-14-cavity.vtu, step-14-cavity.csv and step-14-cavity.svg (" << timer.wall_time() << " s)" << std::endl;
    AssertThrow(std::abs(kt / kt_exact - 1) <= kt_tolerance,
                dealii::ExcMessage("step-14: the fitted stress concentration factor " + std::to_string(kt) +
                                   " is not within " + std::to_string(100 * kt_tolerance) + " % of Goodier's " +
                                   std::to_string(kt_exact) + "."));
    AssertThrow(worst <= profile_tolerance,
                dealii::ExcMessage("step-14: an equatorial cell stress at r <= 3a deviates by " +
                                   std::to_string(100 * worst) + " % from Goodier's, more than " +
                                   std::to_string(100 * profile_tolerance) + " %."));
  }

  // @sect3{Voronoi polyhedra}
  //
  // A smooth displacement, u_d = sin(pi x) sin(pi y) sin(pi z) + a linear
  // field, with the body force that makes it a solution, and its values
  // on the whole boundary.
  T
  smooth(const P &x)
  {
    const double s = std::sin(M_PI * x[0]) * std::sin(M_PI * x[1]) * std::sin(M_PI * x[2]);
    return T({s + 0.1 * x[1], s - 0.2 * x[2], s + 0.3 * x[0]});
  }

  dealii::Tensor<2, 3>
  smooth_gradient(const P &x)
  {
    const double sx = std::sin(M_PI * x[0]), sy = std::sin(M_PI * x[1]), sz = std::sin(M_PI * x[2]);
    const double cx = std::cos(M_PI * x[0]), cy = std::cos(M_PI * x[1]), cz = std::cos(M_PI * x[2]);
    dealii::Tensor<2, 3> g;
    for (unsigned int d = 0; d < 3; ++d)
      g[d] = T({M_PI * cx * sy * sz, M_PI * sx * cy * sz, M_PI * sx * sy * cz});
    g[0][1] += 0.1;
    g[1][2] -= 0.2;
    g[2][0] += 0.3;
    return g;
  }

  // -div sigma = -(lambda + mu) grad div u - mu Laplace u
  T
  smooth_force(const P &x, const double lambda, const double mu)
  {
    const double sx = std::sin(M_PI * x[0]), sy = std::sin(M_PI * x[1]), sz = std::sin(M_PI * x[2]);
    const double cx = std::cos(M_PI * x[0]), cy = std::cos(M_PI * x[1]), cz = std::cos(M_PI * x[2]);
    const double s = sx * sy * sz, p2 = M_PI * M_PI;
    const T grad_div({p2 * (-s + cx * cy * sz + cx * sy * cz), p2 * (cx * cy * sz - s + sx * cy * cz),
                      p2 * (cx * sy * cz + sx * cy * cz - s)});
    return -(lambda + mu) * grad_div + 3 * p2 * mu * T({s, s, s});
  }

  // A picture of a box mesh seen from the corner (1, 1, 1): the boundary
  // faces turned towards the viewer, projected isometrically, each filled
  // with a colour of its cell. (The faces of a box seen from outside do not
  // hide one another.)
  void
  write_box_picture(const PolyhedralMesh &mesh, const std::string &file_name)
  {
    const T view = T({1, 1, 1}) / std::sqrt(3.);
    const T e1   = T({1, -1, 0}) / std::sqrt(2.), e2 = dealii::cross_product_3d(view, e1);
    const double scale = 300, x0 = 260, y0 = 270;
    std::ofstream out(file_name);
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"520\" height=\"540\" viewBox=\"0 0 520 540\">\n"
        << "<rect width=\"520\" height=\"540\" fill=\"white\"/>\n";
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      {
        if (!mesh.face(f).at_boundary() || mesh.face_geometry(f).normal * view <= 1e-12)
          continue;
        const unsigned int c   = mesh.face(f).cells[0];
        const double       hue = std::fmod(c * 137.508, 360.);
        out << "<polygon fill=\"hsl(" << hue << ",55%,72%)\" stroke=\"black\" stroke-width=\"0.8\" points=\"";
        for (const unsigned int v : mesh.face(f).vertices)
          {
            const T x = mesh.vertex(v) - P(0.5, 0.5, 0.5);
            out << x0 + scale * (x * e1) << ',' << y0 - scale * (x * e2) << ' ';
          }
        out << "\"/>\n";
      }
    out << "<text x=\"260\" y=\"525\" font-family=\"sans-serif\" font-size=\"15\" text-anchor=\"middle\">"
        << mesh.n_cells() << " centroidal Voronoi polyhedra of the unit cube (CGAL, Lloyd)</text>\n</svg>\n";
  }

  void
  voronoi(const std::vector<unsigned int> &sizes)
  {
    std::cout << "Centroidal Voronoi polyhedra of the unit cube:" << std::endl;
    const double nu = 0.3;
    PolyhedralElasticity::Settings settings;
    settings.material                  = {1., nu};
    settings.solver.type               = LinearSolver::Type::cg_amg;
    settings.solver.relative_tolerance = 1e-12;
    const double lambda = settings.material.lambda(), mu = settings.material.mu();
    std::vector<double> h, l2, h1;
    for (const unsigned int n : sizes)
      {
        dealii::Timer  timer;
        PolyhedralMesh mesh;
        PolyhedralMeshGenerators::voronoi_box(mesh, P(0, 0, 0), P(1, 1, 1), n, 20, 1);
        const double mesh_time = timer.wall_time();
        unsigned int most_faces = 0;
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          most_faces = std::max<unsigned int>(most_faces, mesh.cell(c).faces.size());
        if (n == sizes[0])
          {
            // the displacement patch test: a linear field on the boundary
            const auto linear = [](const P &x) {
              return T({1e-3 + 2e-3 * x[0] - 1e-3 * x[1] + 4e-3 * x[2], -2e-3 + 1e-3 * x[0] + 3e-3 * x[1],
                        5e-4 - 3e-3 * x[1] + 1e-3 * x[2]});
            };
            PolyhedralElasticity patch(mesh, settings);
            for (const auto id : mesh.get_boundary_ids())
              patch.add_dirichlet(id, linear);
            patch.solve();
            double error = 0;
            for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
              for (unsigned int d = 0; d < 3; ++d)
                error = std::max(error, std::abs(patch.solution()[3 * v + d] - linear(mesh.vertex(v))[d]));
            std::cout << "  patch test on " << mesh.n_cells() << " cells: largest nodal error " << error
                      << " (displacements up to 8e-3)" << std::endl;
            AssertThrow(error <= 1e-10 * 8e-3,
                        dealii::ExcMessage("step-14: the Voronoi patch test fails: nodal error " +
                                           std::to_string(error) + "."));
            mesh.write_vtu("step-14-voronoi.vtu");
            write_box_picture(mesh, "step-14-voronoi.svg");
          }
        PolyhedralElasticity problem(mesh, settings);
        for (const auto id : mesh.get_boundary_ids())
          problem.add_dirichlet(id, smooth);
        problem.set_body_force([=](const P &x) { return smooth_force(x, lambda, mu); });
        problem.solve();
        const auto e = problem.errors(smooth, smooth_gradient);
        h.push_back(std::cbrt(1. / n));
        l2.push_back(e.l2 / e.l2_exact);
        h1.push_back(e.h1_semi / e.h1_semi_exact);
        std::cout << "  " << std::setw(5) << mesh.n_cells() << " cells (up to " << most_faces << " faces), "
                  << std::setw(6) << problem.n_dofs() << " DoFs: relative L2 error " << std::setprecision(4)
                  << l2.back() << ", H1 " << h1.back() << std::setprecision(6) << "; mesh " << mesh_time
                  << " s, CG-AMG " << problem.last_iterations() << " iterations" << std::endl;
      }
    const unsigned int n       = h.size();
    const double       rate_l2 = std::log(l2[n - 2] / l2[n - 1]) / std::log(h[n - 2] / h[n - 1]);
    const double       rate_h1 = std::log(h1[n - 2] / h1[n - 1]) / std::log(h[n - 2] / h[n - 1]);
    std::cout << "  rates (h = cells^(-1/3)): L2 " << rate_l2 << ", H1 " << rate_h1 << "; wrote step-14-voronoi.vtu and .svg"
              << std::endl;
    AssertThrow(rate_l2 >= 1.8 && rate_h1 >= 0.85,
                dealii::ExcMessage("step-14: the Voronoi rates " + std::to_string(rate_l2) + " (L2) and " +
                                   std::to_string(rate_h1) + " (H1) are below 1.8 and 0.85."));
  }
} // namespace Step14



int
main(int argc, char **argv)
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const bool fine = (argc == 2 && std::strcmp(argv[1], "--fine") == 0);
      if (argc > 2 || (argc == 2 && !fine))
        {
          std::cerr << "step-14: "
                    << (argc > 2 ? std::string("too many arguments") :
                                   "unknown argument '" + std::string(argv[1]) + "'")
                    << ".\nusage: step-14 [--fine]   (--fine: the cavity refined once more, 3.1e5 DoFs; Voronoi meshes up to 8000 cells)" << std::endl;
          return 2;
        }
      Step14::cavity(fine ? 5 : 4, fine ? 0.005 : 0.01, fine ? 0.015 : 0.03);
      Step14::voronoi(fine ? std::vector<unsigned int>{125, 1000, 8000} : std::vector<unsigned int>{64, 512, 4096});
    }
  catch (std::exception &exc)
    {
      std::cerr << std::endl
                << "----------------------------------------------------" << std::endl
                << "Exception on processing: " << std::endl
                << exc.what() << std::endl
                << "Aborting!" << std::endl
                << "----------------------------------------------------" << std::endl;
      return 1;
    }
  return 0;
}
