// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/tensor.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <dealvem/solvers/p_multigrid.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/vem_element_data.h>
#include <dealvem/vem/virtual_element.h>

#include <algorithm>
#include <cmath>

namespace dealvem
{
  namespace
  {
    /**
     * The two rows (one per component, over the 2N local k = 1 DoFs) that
     * give the mean over the polygon of the k = 1 projection Pi u1. This is
     * the only place where the prolongation looks at the virtual element
     * (the material-free space).
     */
    void
    moment_rows(const std::vector<dealii::Point<2>> &vertices,
                VirtualElement<2>                   &element_k1,
                dealii::FullMatrix<double>          &rows)
    {
      const unsigned int N = vertices.size();
      element_k1.reinit(vertices);
      const dealii::FullMatrix<double> &Pi_star  = element_k1.get_projector(); // 6 x 2N
      const dealii::FullMatrix<double> &D        = element_k1.get_D();         // 2N x 6
      const dealii::Point<2>            centroid = element_k1.get_geometry().centroid();
      AssertThrow(Pi_star.n() == 2 * N && D.m() == 2 * N,
                  dealii::ExcMessage("p-multigrid: unexpected size of the k = 1 projector."));

      // affine weights of the centroid in terms of the vertices
      dealii::Point<2> xbar;
      for (const auto &v : vertices)
        xbar += v / double(N);
      dealii::Tensor<2, 2> M;
      for (const auto &v : vertices)
        M += dealii::outer_product(v - xbar, v - xbar);
      const dealii::Tensor<1, 2> y = dealii::invert(M) * (centroid - xbar);
      std::vector<double>        w(N);
      for (unsigned int i = 0; i < N; ++i)
        w[i] = 1. / N + (vertices[i] - xbar) * y;

      // Pi u1 at the vertices is D Pi_star u1; average it with the weights
      rows.reinit(2, 2 * N);
      for (unsigned int c = 0; c < 2; ++c)
        for (unsigned int i = 0; i < N; ++i)
          for (unsigned int a = 0; a < Pi_star.m(); ++a)
            {
              const double f = w[i] * D(2 * i + c, a);
              if (f != 0.)
                for (unsigned int j = 0; j < 2 * N; ++j)
                  rows(c, j) += f * Pi_star(a, j);
            }
      // The c-component of Pi u1 depends on the c-component of u1 only (its
      // gradient is the mean gradient of u1, its mean the vertex mean), so
      // the other component's entries are round-off: drop them.
      for (unsigned int c = 0; c < 2; ++c)
        for (unsigned int j = 0; j < 2 * N; ++j)
          if (j % 2 != c)
            {
              AssertThrow(std::abs(rows(c, j)) < 1e-10,
                          dealii::ExcMessage("p-multigrid: the k = 1 projection couples the components."));
              rows(c, j) = 0;
            }
    }
  } // namespace



  bool
  PMultigrid::applies_to(const VEMElementData &layout)
  {
    return layout.nodes_per_edge() >= 1 && layout.nodes_per_cell() <= 1;
  }



  void
  PMultigrid::make_prolongation(const VEMDoFHandler<2>           &dof_handler,
                                dealii::SparsityPattern          &sparsity,
                                dealii::SparseMatrix<double>     &P,
                                std::vector<std::vector<double>> &coarse_modes)
  {
    const VEMElementData &layout = dof_handler.get_element_data();
    AssertThrow(applies_to(layout),
                dealii::ExcMessage("p-multigrid: the fine space " + layout.get_name() +
                                   " needs edge nodes and at most one moment per cell (k = 2); it has " +
                                   std::to_string(layout.nodes_per_edge()) + " node(s) per edge and " +
                                   std::to_string(layout.nodes_per_cell()) + " moment(s) per cell."));
    const unsigned int          n_e      = layout.nodes_per_edge();
    const bool                  has_mean = layout.nodes_per_cell() == 1;
    const std::vector<double>  &t        = layout.edge_node_positions();
    dof_handler.check_mesh_unchanged();
    const PolygonalMesh<2> &mesh = dof_handler.get_mesh();
    VEMDoFHandler<2>        coarse(mesh);
    coarse.distribute_dofs(VEMElementData(1));
    coarse_modes = coarse.rigid_body_modes();

    std::vector<dealii::types::global_dof_index> fine_dofs, coarse_dofs;
    dealii::DynamicSparsityPattern               dsp(dof_handler.n_dofs(), coarse.n_dofs());
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        dof_handler.get_dof_indices(c, fine_dofs);
        coarse.get_dof_indices(c, coarse_dofs);
        const unsigned int N = coarse_dofs.size() / 2;
        for (unsigned int i = 0; i < N; ++i)
          for (unsigned int d = 0; d < 2; ++d)
            {
              dsp.add(fine_dofs[2 * i + d], coarse_dofs[2 * i + d]);
              for (unsigned int j = 0; j < n_e; ++j)
                {
                  const unsigned int node = layout.edge_node(N, i, j);
                  dsp.add(fine_dofs[2 * node + d], coarse_dofs[2 * i + d]);
                  dsp.add(fine_dofs[2 * node + d], coarse_dofs[2 * ((i + 1) % N) + d]);
                }
              if (has_mean)
                for (unsigned int j = 0; j < N; ++j)
                  dsp.add(fine_dofs[2 * layout.cell_node(N, 0) + d], coarse_dofs[2 * j + d]);
            }
      }
    sparsity.copy_from(dsp);
    P.reinit(sparsity);

    VirtualElement<2>               element_k1(1);
    dealii::FullMatrix<double>      rows;
    std::vector<dealii::Point<2>>   vertices;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        dof_handler.get_dof_indices(c, fine_dofs);
        coarse.get_dof_indices(c, coarse_dofs);
        const unsigned int N = coarse_dofs.size() / 2;
        AssertThrow(fine_dofs.size() == layout.n_dofs_per_cell(N),
                    dealii::ExcMessage("p-multigrid: cell " + std::to_string(c) + " has inconsistent k = 1 and " +
                                       layout.get_name() + " DoF counts."));
        for (unsigned int i = 0; i < N; ++i)
          for (unsigned int d = 0; d < 2; ++d)
            {
              P.set(fine_dofs[2 * i + d], coarse_dofs[2 * i + d], 1.);
              for (unsigned int j = 0; j < n_e; ++j)
                {
                  const unsigned int node = layout.edge_node(N, i, j);
                  P.set(fine_dofs[2 * node + d], coarse_dofs[2 * i + d], 1. - t[j]);
                  P.set(fine_dofs[2 * node + d], coarse_dofs[2 * ((i + 1) % N) + d], t[j]);
                }
            }
        if (!has_mean)
          continue;
        mesh.cell_vertices(c, vertices);
        moment_rows(vertices, element_k1, rows);
        for (unsigned int d = 0; d < 2; ++d)
          for (unsigned int j = 0; j < N; ++j)
            P.set(fine_dofs[2 * layout.cell_node(N, 0) + d], coarse_dofs[2 * j + d], rows(d, 2 * j + d));
      }
  }
} // namespace dealvem
