// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The edge loads of VirtualElement (tractions, pressures, follower
// pressures): integrals over one edge of the trace, whose basis is the
// edge's Lagrange basis of VEMElementData. Kept apart from the projector in
// virtual_element.cc; the class is instantiated there, these members here.
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>

#include <dealvem/vem/virtual_element.h>

#include <vector>

namespace dealvem
{
  template <int dim>
  void
  VirtualElement<dim>::add_edge_traction(const unsigned int           edge,
                                         const dealii::Function<dim> &g,
                                         dealii::Vector<double>      &F) const
  {
    AssertDimension(g.n_components, 2);
    AssertDimension(F.size(), n_dofs);
    const auto               nodes = edge_nodes(edge);
    const dealii::Point<dim> a     = geometry->vertex(edge);
    const dealii::Point<dim> b     = geometry->vertex((edge + 1) % n_vertices);
    const double             L     = geometry->edge_length(edge);
    const dealii::Quadrature<1> &q = internal::gauss_rule(5);
    dealii::Vector<double>   gv(2);
    for (unsigned int k = 0; k < q.size(); ++k)
      {
        const double             s = q.point(k)[0];
        const dealii::Point<dim> x = a + s * (b - a);
        g.vector_value(x, gv);
        // the Lagrange basis on the nodes of the edge
        std::vector<double> phi;
        data.edge_shape_values(s, phi);
        for (unsigned int j = 0; j < nodes.size(); ++j)
          for (unsigned int c = 0; c < 2; ++c)
            F[2 * nodes[j] + c] += q.weight(k) * L * phi[j] * gv[c];
      }
  }



  template <int dim>
  void
  VirtualElement<dim>::add_edge_pressure(const unsigned int           edge,
                                         const dealii::Function<dim> &pressure,
                                         dealii::Vector<double>      &F) const
  {
    // g = -p n: wrap the scalar pressure into a vector function.
    class Traction : public dealii::Function<dim>
    {
    public:
      Traction(const dealii::Function<dim> &p, const dealii::Tensor<1, dim> &n)
        : dealii::Function<dim>(2)
        , p(p)
        , n(n)
      {}
      double
      value(const dealii::Point<dim> &x, const unsigned int c) const override
      {
        return -p.value(x) * n[c];
      }
      void
      vector_value(const dealii::Point<dim> &x, dealii::Vector<double> &v) const override
      {
        const double pv = p.value(x);
        v[0]            = -pv * n[0];
        v[1]            = -pv * n[1];
      }

    private:
      const dealii::Function<dim> &p;
      const dealii::Tensor<1, dim> n;
    };
    const Traction t(pressure, geometry->edge_normal(edge));
    add_edge_traction(edge, t, F);
  }

  template <int dim>
  void
  VirtualElement<dim>::add_edge_follower_pressure(const unsigned int            edge,
                                                  const dealii::Function<dim>  &pressure,
                                                  const dealii::Vector<double> &local_u,
                                                  dealii::Vector<double>       &F,
                                                  dealii::FullMatrix<double>   *K) const
  {
    static_assert(dim == 2, "add_edge_follower_pressure is implemented in 2D");
    AssertDimension(pressure.n_components, 1);
    AssertDimension(F.size(), n_dofs);
    AssertDimension(local_u.size(), n_dofs);
    const auto               nodes = edge_nodes(edge);
    const dealii::Point<dim> a     = geometry->vertex(edge);
    const dealii::Point<dim> b     = geometry->vertex((edge + 1) % n_vertices);
    // Q (b - a) = (t_y, -t_x) |b - a|: the outward normal times the length
    // for counter-clockwise edges; the sign makes it so for either order
    const dealii::Tensor<1, dim> n0   = geometry->edge_normal(edge);
    const double                 sign = ((b - a)[1] * n0[0] - (b - a)[0] * n0[1]) >= 0 ? 1. : -1.;
    // the current node positions x_b, rotated: Q x_b = (x_b[1], -x_b[0])
    std::vector<dealii::Tensor<1, dim>> Qx(nodes.size());
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const dealii::Point<dim> X = node_location(nodes[j]);
        const double             x = X[0] + local_u[2 * nodes[j]], y = X[1] + local_u[2 * nodes[j] + 1];
        Qx[j][0]                   = y;
        Qx[j][1]                   = -x;
      }
    // M_ab = -sign int p N_a N_b' ds
    dealii::FullMatrix<double>   M(nodes.size(), nodes.size());
    const dealii::Quadrature<1> &q = internal::gauss_rule(5);
    for (unsigned int k = 0; k < q.size(); ++k)
      {
        const double             s = q.point(k)[0];
        const dealii::Point<dim> X = a + s * (b - a);
        const double             p = pressure.value(X);
        std::vector<double>      phi, dphi;
        data.edge_shape_values(s, phi);
        data.edge_shape_derivatives(s, dphi);
        for (unsigned int i = 0; i < nodes.size(); ++i)
          for (unsigned int j = 0; j < nodes.size(); ++j)
            M(i, j) -= sign * q.weight(k) * p * phi[i] * dphi[j];
      }
    for (unsigned int i = 0; i < nodes.size(); ++i)
      for (unsigned int j = 0; j < nodes.size(); ++j)
        {
          for (unsigned int c = 0; c < 2; ++c)
            F[2 * nodes[i] + c] += M(i, j) * Qx[j][c];
          if (K != nullptr)
            {
              // d(Q x_b)_c / d u_{b,d} = Q_cd, Q = [[0, 1], [-1, 0]]
              (*K)(2 * nodes[i], 2 * nodes[j] + 1) += M(i, j);
              (*K)(2 * nodes[i] + 1, 2 * nodes[j]) -= M(i, j);
            }
        }
  }



  template void
  VirtualElement<2>::add_edge_traction(const unsigned int, const dealii::Function<2> &, dealii::Vector<double> &) const;
  template void
  VirtualElement<2>::add_edge_pressure(const unsigned int, const dealii::Function<2> &, dealii::Vector<double> &) const;
  template void
  VirtualElement<2>::add_edge_follower_pressure(const unsigned int,
                                                const dealii::Function<2> &,
                                                const dealii::Vector<double> &,
                                                dealii::Vector<double> &,
                                                dealii::FullMatrix<double> *) const;
} // namespace dealvem
