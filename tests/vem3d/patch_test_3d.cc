// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The 3D first-order virtual element (PolyhedralElement) and its problem
// (PolyhedralElasticity) on seven kinds of polyhedral meshes, each mapped by
// a random affine map (faces stay planar):
// - hexahedra of a deal.II Triangulation<3>;
// - tetrahedra of a deal.II Triangulation<3>, interior vertices moved at
//   random;
// - flat hexahedra, 1 x 1 x 0.01;
// - hexahedra with every vertex moved at random, their warped faces split
//   into two triangles each (from_triangulation(..., split_warped_faces));
// - a locally refined hexahedral mesh: the coarse cells next to refined
//   ones become polyhedra with the finer faces and the edge midpoints as
//   their own (no hanging-node constraints);
// - non-convex cells: L-shaped unions of three cubes, beside single cubes,
//   with coplanar faces side by side;
// - the same L cells, far from the origin (shifted by 1e4 of their size)
//   and scaled by 1e-3.
// Checked, with the tolerances relative to the data:
// - the projector reproduces linear displacements, Pi p = p (1e-12 on
//   every cell; 1e-10 for the mesh far from the origin, whose nodal values
//   carry four digits of position: 1.4e-11 measured, 4.7e-15 near it);
// - the element stiffness is symmetric, kills the six rigid-body modes
//   (1e-12 of |K| |mode|, 1e-10 far away) and has exactly six eigenvalues
//   below 1e-10 of its largest (checked on up to 20 cells of each mesh);
// - the displacement patch test: a linear field prescribed on the whole
//   boundary is reproduced at every vertex to 1e-10 of its size, and every
//   cell's stress equals the exact one to 1e-9 of its size, with UMFPACK and
//   with CG-AMG (six rigid modes, tolerance 1e-13);
// - the traction patch test: the same field with displacements prescribed
//   on one side only and the exact tractions on the others: the same
//   tolerances.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <dealvem/app/polyhedral_elasticity.h>
#include <dealvem/mesh/polyhedral_generators.h>
#include <dealvem/mesh/polyhedral_mesh.h>
#include <dealvem/vem/polyhedral_element.h>

#include <cmath>
#include <random>

#include "../tests.h"

using namespace dealvem;
using P = dealii::Point<3>;
using T = dealii::Tensor<1, 3>;

namespace
{
  std::mt19937 rng(20261201);

  double
  uniform(const double a, const double b)
  {
    return std::uniform_real_distribution<double>(a, b)(rng);
  }

  // a random affine map close to a rotation and stretch (well conditioned)
  std::function<P(const P &)>
  random_affine(const double scale, const P &shift)
  {
    dealii::Tensor<2, 3> A;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        A[i][j] = (i == j ? 1. : 0.) + uniform(-0.3, 0.3);
    return [A, scale, shift](const P &x) { return shift + scale * (A * x); };
  }
  PolyhedralMesh
  l_cells(const unsigned int n)
  {
    PolyhedralMesh mesh;
    PolyhedralMeshGenerators::l_shaped_cells(mesh, n);
    return mesh;
  }

  // the linear field u = a + B x and its stress
  struct Linear
  {
    T                    a;
    dealii::Tensor<2, 3> B;

    T
    operator()(const P &x) const
    {
      return a + B * x;
    }
  };

  // @p far: the mesh lies 1e4 of its size from the origin, so nodal values
  // of a linear field carry four digits of position: the element's
  // tolerances are 100 times wider there
  void
  check_mesh(const std::string &label, PolyhedralMesh &mesh, const bool far = false)
  {
    const double element_tolerance = far ? 1e-10 : 1e-12;
    std::cout << "--- " << label << ": " << mesh.n_cells() << " cells, " << mesh.n_faces() << " faces, "
              << mesh.n_vertices() << " vertices" << std::endl;
    const double size = mesh.extent();
    Linear       field;
    for (unsigned int d = 0; d < 3; ++d)
      {
        field.a[d] = uniform(-1, 1) * 1e-3 * size;
        for (unsigned int k = 0; k < 3; ++k)
          field.B[d][k] = uniform(-1, 1) * 1e-3;
      }
    IsotropicMaterial3D material{2.1e5, 0.3};
    const double        lambda = material.lambda(), mu = material.mu();
    const dealii::Tensor<2, 3> strain = 0.5 * (field.B + dealii::transpose(field.B));
    const dealii::Tensor<2, 3> sigma =
      lambda * dealii::trace(strain) * dealii::unit_symmetric_tensor<3>() + 2 * mu * strain;

    // the element
    {
      const PolyhedralElement     element;
      PolyhedralElement::CellData data;
      double                      projection_error = 0, symmetry = 0, kernel = 0;
      unsigned int                wrong_kernels = 0, checked = 0;
      const unsigned int          step = std::max(1u, mesh.n_cells() / 20);
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          element.compute(mesh, c, &material, data);
          const unsigned int     n = 3 * data.vertices.size();
          dealii::Vector<double> nodal(n);
          for (unsigned int i = 0; i < data.vertices.size(); ++i)
            for (unsigned int d = 0; d < 3; ++d)
              nodal[3 * i + d] = field(mesh.vertex(data.vertices[i]))[d];
          dealii::Vector<double> coefficients(12);
          data.projector.vmult(coefficients, nodal);
          const T at_centroid = field(data.centroid);
          for (unsigned int d = 0; d < 3; ++d)
            {
              projection_error = std::max(projection_error, std::abs(coefficients[d] - at_centroid[d]) / (1e-3 * size));
              for (unsigned int k = 0; k < 3; ++k)
                projection_error =
                  std::max(projection_error, std::abs(coefficients[3 + 3 * d + k] - field.B[d][k]) / 1e-3);
            }
          if (c % step != 0)
            continue;
          ++checked;
          const double norm = data.stiffness.frobenius_norm();
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              symmetry = std::max(symmetry, std::abs(data.stiffness(i, j) - data.stiffness(j, i)) / norm);
          // rigid modes: translations and rotations about the centroid
          for (unsigned int m = 0; m < 6; ++m)
            {
              dealii::Vector<double> mode(n), Km(n);
              for (unsigned int i = 0; i < data.vertices.size(); ++i)
                {
                  const T x = mesh.vertex(data.vertices[i]) - data.centroid;
                  T       r;
                  if (m < 3)
                    r[m] = 1;
                  else
                    {
                      T axis;
                      axis[m - 3] = 1;
                      r           = dealii::cross_product_3d(axis, x) / data.diameter;
                    }
                  for (unsigned int d = 0; d < 3; ++d)
                    mode[3 * i + d] = r[d];
                }
              data.stiffness.vmult(Km, mode);
              kernel = std::max(kernel, Km.l2_norm() / (norm * mode.l2_norm()));
            }
          dealii::LAPACKFullMatrix<double> K(n, n);
          K = data.stiffness;
          K.compute_eigenvalues();
          double largest = 0;
          for (unsigned int i = 0; i < n; ++i)
            largest = std::max(largest, std::abs(K.eigenvalue(i)));
          unsigned int zeros = 0;
          for (unsigned int i = 0; i < n; ++i)
            {
              zeros += std::abs(K.eigenvalue(i)) < 1e-10 * largest;
              if (K.eigenvalue(i).real() < -1e-10 * largest)
                ++wrong_kernels;
            }
          if (zeros != 6)
            ++wrong_kernels;
        }
      testing::check_small(projection_error, element_tolerance, label + ": Pi p = p for a linear p, every cell (relative)");
      testing::check_small(symmetry, 1e-14, label + ": element stiffness symmetric");
      testing::check_small(kernel, element_tolerance, label + ": K times each rigid mode, relative to |K| |mode|");
      testing::check(wrong_kernels == 0, label + ": exactly six zero eigenvalues and none negative, on " +
                                           std::to_string(checked) + " cells");
    }

    const auto compare = [&](const PolyhedralElasticity &problem, const std::string &what) {
      double error = 0, stress_error = 0, scale = 0;
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        {
          const T exact = field(mesh.vertex(v));
          scale         = std::max(scale, exact.norm());
          for (unsigned int d = 0; d < 3; ++d)
            error = std::max(error, std::abs(problem.solution()[3 * v + d] - exact[d]));
        }
      const auto         s        = problem.cell_stresses();
      const unsigned int voigt[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        for (unsigned int k = 0; k < 6; ++k)
          stress_error = std::max(stress_error, std::abs(s[6 * c + k] - sigma[voigt[k][0]][voigt[k][1]]));
      testing::check_small(error / scale, 1e-10, label + ", " + what + ": largest nodal error / largest displacement");
      testing::check_small(stress_error / sigma.norm(), 1e-9, label + ", " + what + ": largest cell stress error / |sigma|");
    };

    // displacement patch test: the field on the whole boundary
    for (const auto type : {LinearSolver::Type::umfpack, LinearSolver::Type::cg_amg})
      {
        mesh.set_boundary_ids([](const P &, const T &) { return true; }, 0);
        PolyhedralElasticity::Settings settings;
        settings.material                  = material;
        settings.solver.type               = type;
        settings.solver.relative_tolerance = 1e-13;
        PolyhedralElasticity problem(mesh, settings);
        problem.add_dirichlet(0, field);
        problem.solve();
        compare(problem, std::string("displacements on the boundary, ") +
                           (type == LinearSolver::Type::umfpack ? "UMFPACK" : "CG-AMG (" +
                                                                                std::to_string(problem.last_iterations()) +
                                                                                " iterations)"));
      }
    // traction patch test: displacements on the faces whose normal is
    // closest to -x, the exact tractions sigma n elsewhere
    {
      double lowest = 0;
      for (unsigned int f = 0; f < mesh.n_faces(); ++f)
        if (mesh.face(f).at_boundary())
          lowest = std::min(lowest, mesh.face_geometry(f).normal[0]);
      mesh.set_boundary_ids([](const P &, const T &) { return true; }, 1);
      const unsigned int held =
        mesh.set_boundary_ids([lowest](const P &, const T &n) { return n[0] < lowest + 1e-6; }, 0);
      testing::check(held > 0, label + ": some faces held");
      PolyhedralElasticity::Settings settings;
      settings.material = material;
      PolyhedralElasticity problem(mesh, settings);
      problem.add_dirichlet(0, field);
      problem.add_traction(1, [sigma](const P &, const T &n) { return sigma * n; });
      problem.solve();
      compare(problem, "tractions on all but one side");
    }
  }
} // namespace

int
main(int argc, char **argv)
{
  // CG-AMG (Trilinos ML) needs MPI
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  {
    dealii::Triangulation<3> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {3, 2, 4}, P(0, 0, 0), P(1.5, 1, 2));
    dealii::GridTools::transform(random_affine(1., P(0.3, -0.2, 0.1)), tria);
    PolyhedralMesh mesh = PolyhedralMesh::from_triangulation(tria);
    check_mesh("hexahedra 3x2x4, affine", mesh);
  }
  {
    dealii::Triangulation<3> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle_with_simplices(tria, {3, 3, 3}, P(0, 0, 0), P(1, 1, 1));
    PolyhedralMesh mesh = PolyhedralMesh::from_triangulation(tria);
    // move the interior vertices (faces of tetrahedra stay planar)
    std::vector<bool> on_boundary(mesh.n_vertices(), false);
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      if (mesh.face(f).at_boundary())
        for (const unsigned int v : mesh.face(f).vertices)
          on_boundary[v] = true;
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      if (!on_boundary[v])
        mesh.move_vertex(v, mesh.vertex(v) + T({uniform(-0.08, 0.08), uniform(-0.08, 0.08), uniform(-0.08, 0.08)}));
    mesh.transform(random_affine(2., P(-1, 0, 3)));
    mesh.validate();
    check_mesh("tetrahedra, interior vertices moved, affine", mesh);
  }
  {
    // flat cells: 1 x 1 x 0.01 plates, and thin Voronoi-like slivers are the
    // case the D-recipe stabilization is chosen for
    dealii::Triangulation<3> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {2, 3, 2}, P(0, 0, 0), P(2, 3, 0.02));
    dealii::GridTools::transform(random_affine(1., P(0, 0, 0)), tria);
    PolyhedralMesh mesh = PolyhedralMesh::from_triangulation(tria);
    check_mesh("flat hexahedra (1 : 1 : 0.01), affine", mesh);
  }
  {
    // every vertex moved at random: warped faces, split into triangles
    dealii::Triangulation<3> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {3, 3, 2}, P(0, 0, 0), P(1, 1, 1));
    dealii::GridTools::distort_random(0.25, tria, false, 11);
    PolyhedralMesh mesh = PolyhedralMesh::from_triangulation(tria, 1e-8, true);
    unsigned int   n_triangles = 0;
    for (unsigned int f = 0; f < mesh.n_faces(); ++f)
      n_triangles += mesh.face(f).vertices.size() == 3;
    testing::check(n_triangles > mesh.n_faces() / 2, "distorted hexahedra: warped faces split into triangles (" +
                                                       std::to_string(n_triangles) + " of " +
                                                       std::to_string(mesh.n_faces()) + " faces)");
    check_mesh("hexahedra with every vertex moved, warped faces split", mesh);
  }
  {
    dealii::Triangulation<3> tria;
    dealii::GridGenerator::hyper_cube(tria, 0, 1);
    tria.refine_global(2);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->center()[0] < 0.5 && cell->center()[1] < 0.5 && cell->center()[2] < 0.75)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->center()[0] < 0.2 && cell->center()[1] < 0.3 && cell->center()[2] < 0.3)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();
    dealii::GridTools::transform(random_affine(1., P(0, 0, 0)), tria);
    PolyhedralMesh mesh = PolyhedralMesh::from_triangulation(tria);
    unsigned int   n_polyhedra = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      n_polyhedra += mesh.cell(c).faces.size() > 6 || mesh.cell_vertex_indices(c).size() > 8;
    std::cout << "    cells with more than six faces or eight vertices: " << n_polyhedra << std::endl;
    testing::check(n_polyhedra > 10, "locally refined: coarse cells beside refined ones became polyhedra");
    testing::check(tria.n_active_cells() == mesh.n_cells(), "locally refined: one polyhedron per active cell");
    check_mesh("hexahedra refined locally twice, affine", mesh);
  }
  {
    PolyhedralMesh mesh = l_cells(4);
    mesh.transform(random_affine(1., P(0, 0, 0)));
    mesh.validate();
    check_mesh("L-shaped (non-convex) cells and cubes, affine", mesh);
  }
  {
    PolyhedralMesh mesh = l_cells(4);
    mesh.transform(random_affine(1e-3, P(10, -10, 10)));
    mesh.validate();
    check_mesh("the same, size 1e-3 at 1e4 of its size from the origin", mesh, true);
  }
  return testing::finish();
}
