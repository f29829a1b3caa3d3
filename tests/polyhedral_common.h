// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Geometry of polyhedral cells computed independently of the library (for
// the tests of the Voronoi generators): volumes, centroids and the CVT
// energy from signed tetrahedra.
#ifndef dealvem_tests_polyhedral_common_h
#define dealvem_tests_polyhedral_common_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dealvem/mesh/polyhedral_mesh.h>

#include <algorithm>
#include <array>
#include <vector>

namespace testing
{
  using dealvem::PolyhedralMesh;
  using P3 = dealii::Point<3>;
  using T3 = dealii::Tensor<1, 3>;

  // The loop of face f oriented out of cell c.
  inline std::vector<unsigned int>
  outward_loop(const PolyhedralMesh &mesh, const unsigned int f, const unsigned int c)
  {
    std::vector<unsigned int> loop = mesh.face(f).vertices;
    if (!mesh.face_points_out_of(f, c))
      std::reverse(loop.begin(), loop.end());
    return loop;
  }

  // Volume, centroid, int_c |x - g|^2 dx (g the centroid), the sum of the
  // outward area vectors and the area of cell c: the tetrahedra from its
  // first vertex to the triangle fans of its faces.
  struct CellMoments
  {
    double volume = 0;
    P3     centroid;
    double second_moment = 0;
    T3     area_vector;
    double area = 0;
  };

  inline CellMoments
  cell_moments(const PolyhedralMesh &mesh, const unsigned int c)
  {
    CellMoments                    m;
    const P3                       o = mesh.vertex(mesh.cell_vertex_indices(c)[0]);
    std::vector<std::array<T3, 4>> tets; // relative to o
    std::vector<double>            tet_volume;
    for (const unsigned int f : mesh.cell(c).faces)
      {
        const auto loop = outward_loop(mesh, f, c);
        const T3   a    = mesh.vertex(loop[0]) - o;
        for (unsigned int k = 1; k + 1 < loop.size(); ++k)
          {
            const T3     b = mesh.vertex(loop[k]) - o, d = mesh.vertex(loop[k + 1]) - o;
            const double v = a * dealii::cross_product_3d(b, d) / 6;
            const T3     n = dealii::cross_product_3d(b - a, d - a) / 2;
            m.area_vector += n;
            m.area += n.norm();
            m.volume += v;
            m.centroid += v * (a + b + d) / 4;
            tets.push_back({{T3(), a, b, d}});
            tet_volume.push_back(v);
          }
      }
    const T3 g = T3(m.centroid) / m.volume;
    // int_T |x - g|^2 = |T| / 20 (sum_i |w_i|^2 + |sum_i w_i|^2), w_i = p_i - g
    for (unsigned int t = 0; t < tets.size(); ++t)
      {
        double s2 = 0;
        T3     s;
        for (const T3 &p : tets[t])
          {
            s2 += (p - g).norm_square();
            s += p - g;
          }
        m.second_moment += tet_volume[t] / 20 * (s2 + s.norm_square());
      }
    m.centroid = o + g;
    return m;
  }

  inline double
  cvt_energy(const PolyhedralMesh &mesh)
  {
    double e = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      e += cell_moments(mesh, c).second_moment;
    return e;
  }
} // namespace testing

#endif
