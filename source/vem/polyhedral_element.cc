// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <dealvem/mesh/polyhedral_mesh.h>
#include <dealvem/vem/polyhedral_element.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace dealvem
{
  double
  IsotropicMaterial3D::lambda() const
  {
    return youngs_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
  }



  double
  IsotropicMaterial3D::mu() const
  {
    return youngs_modulus / (2 * (1 + poisson_ratio));
  }



  void
  IsotropicMaterial3D::check() const
  {
    AssertThrow(std::isfinite(youngs_modulus) && youngs_modulus > 0,
                dealii::ExcMessage("Young's modulus must be positive, not " + std::to_string(youngs_modulus) + "."));
    AssertThrow(std::isfinite(poisson_ratio) && poisson_ratio > -1 && poisson_ratio < 0.5,
                dealii::ExcMessage("Poisson's ratio must lie in (-1, 0.5), not " + std::to_string(poisson_ratio) +
                                   "."));
  }



  PolyhedralElement::PolyhedralElement(const double stabilization)
    : tau(stabilization)
  {
    AssertThrow(std::isfinite(stabilization) && stabilization > 0,
                dealii::ExcMessage("The stabilization factor of the polyhedral element must be positive, not " +
                                   std::to_string(stabilization) + "."));
  }



  namespace polyhedral_element_internal
  {
    // The face weights from a face geometry the caller already has
    // (compute() needs the geometry itself too: computed once per face).
    std::vector<double>
    face_weights(const PolyhedralMesh &mesh, const unsigned int f, const PolyhedralMesh::FaceGeometry &g)
    {
      const auto      &loop = mesh.face(f).vertices;
      const auto       n    = loop.size();
      dealii::Point<3> average;
      for (const unsigned int v : loop)
        average += mesh.vertex(v) / double(n);
      const dealii::Tensor<1, 3> shift = g.centroid - average;
      std::vector<double>        w(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const dealii::Tensor<1, 3> chord = mesh.vertex(loop[(i + 1) % n]) - mesh.vertex(loop[(i + n - 1) % n]);
          w[i]                             = g.area / n + 0.5 * (dealii::cross_product_3d(chord, g.normal) * shift);
        }
      return w;
    }
  } // namespace polyhedral_element_internal



  std::vector<double>
  PolyhedralElement::face_weights(const PolyhedralMesh &mesh, const unsigned int f)
  {
    return polyhedral_element_internal::face_weights(mesh, f, mesh.face_geometry(f));
  }



  void
  PolyhedralElement::compute(const PolyhedralMesh      &mesh,
                             const unsigned int         c,
                             const IsotropicMaterial3D *material,
                             CellData                  &data) const
  {
    const auto &cell = mesh.cell(c);
    data.vertices    = mesh.cell_vertex_indices(c);
    const auto nv    = data.vertices.size();
    const auto local = [&](const unsigned int v) {
      return std::lower_bound(data.vertices.begin(), data.vertices.end(), v) - data.vertices.begin();
    };

    // volume and centroid from the signed tetrahedra (x0, x_F, v_i, v_i+1)
    const dealii::Point<3> x0     = mesh.vertex(data.vertices[0]);
    double                 volume = 0;
    dealii::Tensor<1, 3>   moment;
    // the boundary integrals of the basis functions times the outward
    // normal: sum over faces of (int_F phi_i) n_F
    std::vector<dealii::Tensor<1, 3>> normal_integral(nv);
    for (const unsigned int f : cell.faces)
      {
        const auto   g    = mesh.face_geometry(f);
        const double sign = mesh.face_points_out_of(f, c) ? 1. : -1.;
        const auto  &loop = mesh.face(f).vertices;
        const auto   w    = polyhedral_element_internal::face_weights(mesh, f, g);
        for (unsigned int i = 0; i < loop.size(); ++i)
          {
            normal_integral[local(loop[i])] += sign * w[i] * g.normal;
            const dealii::Tensor<1, 3> a = g.centroid - x0, b = mesh.vertex(loop[i]) - x0,
                                       d = mesh.vertex(loop[(i + 1) % loop.size()]) - x0;
            const double t               = sign * (a * dealii::cross_product_3d(b, d)) / 6.;
            volume += t;
            moment += t * (a + b + d) / 4.;
          }
      }
    AssertThrow(volume > 0, dealii::ExcMessage("Polyhedral cell " + std::to_string(c) + " has the volume " +
                                               std::to_string(volume) + " (finalize() validates the mesh)."));
    data.volume   = volume;
    data.centroid = x0 + moment / volume;
    data.diameter = 0;
    dealii::Point<3> average;
    for (unsigned int i = 0; i < nv; ++i)
      {
        average += mesh.vertex(data.vertices[i]) / double(nv);
        for (unsigned int j = i + 1; j < nv; ++j)
          data.diameter =
            std::max(data.diameter, mesh.vertex(data.vertices[i]).distance(mesh.vertex(data.vertices[j])));
      }

    // Pi v = a + G (x - x_E): G_dk = (1/|E|) sum_i v_i,d (int phi_i n_k);
    // a = mean of the vertex values - G (x_avg - x_E)
    const unsigned int n_dofs = 3 * nv;
    data.projector.reinit(12, n_dofs);
    const dealii::Tensor<1, 3> offset = average - data.centroid;
    for (unsigned int i = 0; i < nv; ++i)
      for (unsigned int d = 0; d < 3; ++d)
        {
          const unsigned int j = 3 * i + d;
          for (unsigned int k = 0; k < 3; ++k)
            data.projector(3 + 3 * d + k, j) = normal_integral[i][k] / volume;
          data.projector(d, j) = 1. / nv;
          for (unsigned int k = 0; k < 3; ++k)
            data.projector(d, j) -= data.projector(3 + 3 * d + k, j) * offset[k];
        }
    if (material == nullptr)
      return;

    // consistency: |E| B^T D B with the Voigt strain (xx, yy, zz, yz, xz, xy;
    // engineering shears) of G
    const double               lambda = material->lambda(), mu = material->mu();
    dealii::FullMatrix<double> B(6, n_dofs);
    for (unsigned int j = 0; j < n_dofs; ++j)
      {
        const auto G = [&](const unsigned int d, const unsigned int k) { return data.projector(3 + 3 * d + k, j); };
        B(0, j)      = G(0, 0);
        B(1, j)      = G(1, 1);
        B(2, j)      = G(2, 2);
        B(3, j)      = G(1, 2) + G(2, 1);
        B(4, j)      = G(0, 2) + G(2, 0);
        B(5, j)      = G(0, 1) + G(1, 0);
      }
    dealii::FullMatrix<double> D(6, 6);
    for (unsigned int a = 0; a < 3; ++a)
      {
        for (unsigned int b = 0; b < 3; ++b)
          D(a, b) = lambda;
        D(a, a) += 2 * mu;
        D(3 + a, 3 + a) = mu;
      }
    dealii::FullMatrix<double> DB(6, n_dofs);
    D.mmult(DB, B);
    data.stiffness.reinit(n_dofs, n_dofs);
    B.Tmmult(data.stiffness, DB);
    data.stiffness *= volume;

    // stabilization: (I - P)^T Sigma (I - P), P the vertex values of Pi
    double trace = 0;
    for (unsigned int j = 0; j < n_dofs; ++j)
      trace += data.stiffness(j, j);
    std::vector<double> sigma(n_dofs);
    for (unsigned int j = 0; j < n_dofs; ++j)
      sigma[j] = tau * std::max(data.stiffness(j, j), 1e-3 * trace / n_dofs);
    // With P = V Pi (V: the values of the 12 polynomial modes at the
    // vertices, four non-zeros per row), the product is
    //   Sigma - Sigma P - P^T Sigma + Pi^T (V^T Sigma V) Pi,
    // 12 n^2 operations for the last term instead of the n^3 of forming
    // (I - P)^T Sigma (I - P) directly (n = 3 nv, up to 100 on Voronoi
    // cells).
    std::vector<dealii::Tensor<1, 3>> x(nv);
    for (unsigned int i = 0; i < nv; ++i)
      x[i] = mesh.vertex(data.vertices[i]) - data.centroid;
    // M = V^T Sigma V (12 x 12, symmetric): row 3 i + d of V has 1 in
    // column d and x_i[k] in column 3 + 3 d + k
    double M[12][12] = {};
    for (unsigned int i = 0; i < nv; ++i)
      for (unsigned int d = 0; d < 3; ++d)
        {
          const double       s          = sigma[3 * i + d];
          const unsigned int columns[4] = {d, 3 + 3 * d, 4 + 3 * d, 5 + 3 * d};
          const double       values[4]  = {1., x[i][0], x[i][1], x[i][2]};
          for (unsigned int p = 0; p < 4; ++p)
            for (unsigned int q = 0; q < 4; ++q)
              M[columns[p]][columns[q]] += s * values[p] * values[q];
        }
    // W = M Pi, stored transposed (n x 12) beside Pi^T, so that the n^2
    // entries of Pi^T W are inner products of contiguous rows of 12
    std::vector<double> PiT(12 * n_dofs), WT(12 * n_dofs, 0.);
    for (unsigned int j = 0; j < n_dofs; ++j)
      for (unsigned int m = 0; m < 12; ++m)
        PiT[12 * j + m] = data.projector(m, j);
    for (unsigned int j = 0; j < n_dofs; ++j)
      for (unsigned int m = 0; m < 12; ++m)
        {
          double w = 0;
          for (unsigned int l = 0; l < 12; ++l)
            w += M[m][l] * PiT[12 * j + l];
          WT[12 * j + m] = w;
        }
    // P (n x n): the vertex values of Pi
    dealii::FullMatrix<double> P(n_dofs, n_dofs);
    for (unsigned int i = 0; i < nv; ++i)
      for (unsigned int d = 0; d < 3; ++d)
        for (unsigned int j = 0; j < n_dofs; ++j)
          P(3 * i + d, j) = PiT[12 * j + d] + PiT[12 * j + 3 + 3 * d] * x[i][0] + PiT[12 * j + 4 + 3 * d] * x[i][1] +
                            PiT[12 * j + 5 + 3 * d] * x[i][2];
    for (unsigned int a = 0; a < n_dofs; ++a)
      {
        data.stiffness(a, a) += sigma[a];
        const double *pa = &PiT[12 * a];
        for (unsigned int b = 0; b < n_dofs; ++b)
          {
            const double *wb = &WT[12 * b];
            double        s  = -sigma[a] * P(a, b) - sigma[b] * P(b, a);
            for (unsigned int m = 0; m < 12; ++m)
              s += pa[m] * wb[m];
            data.stiffness(a, b) += s;
          }
      }
    // exact symmetry (the products above are symmetric up to round-off)
    for (unsigned int a = 0; a < n_dofs; ++a)
      for (unsigned int b = a + 1; b < n_dofs; ++b)
        {
          const double m       = 0.5 * (data.stiffness(a, b) + data.stiffness(b, a));
          data.stiffness(a, b) = data.stiffness(b, a) = m;
        }
  }



  void
  PolyhedralElement::cell_quadrature(const PolyhedralMesh          &mesh,
                                     const unsigned int             c,
                                     std::vector<dealii::Point<3>> &points,
                                     std::vector<double>           &weights)
  {
    static const dealii::QGaussSimplex<3> reference(3);
    points.clear();
    weights.clear();
    const auto &cell = mesh.cell(c);
    // the apex: the vertex average (any point works with signed volumes)
    const auto       vertices = mesh.cell_vertex_indices(c);
    dealii::Point<3> apex;
    for (const unsigned int v : vertices)
      apex += mesh.vertex(v) / double(vertices.size());
    for (const unsigned int f : cell.faces)
      {
        const auto   g    = mesh.face_geometry(f);
        const double sign = mesh.face_points_out_of(f, c) ? 1. : -1.;
        const auto  &loop = mesh.face(f).vertices;
        for (unsigned int i = 0; i < loop.size(); ++i)
          {
            // tetrahedron (apex, x_F, v_i, v_i+1), its volume signed by the
            // orientation of the triangle seen from the apex
            const dealii::Tensor<1, 3> e0 = g.centroid - apex, e1 = mesh.vertex(loop[i]) - apex,
                                       e2 = mesh.vertex(loop[(i + 1) % loop.size()]) - apex;
            const double det              = e0 * dealii::cross_product_3d(e1, e2);
            for (unsigned int q = 0; q < reference.size(); ++q)
              {
                const auto &xi = reference.point(q);
                points.push_back(apex + xi[0] * e0 + xi[1] * e1 + xi[2] * e2);
                weights.push_back(sign * reference.weight(q) * det);
              }
          }
      }
  }
} // namespace dealvem
