// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <dealvem/vem/partitioning.h>

#include <algorithm>
#include <string>

namespace dealvem
{
  template <int dim>
  void
  VEMPartition<dim>::reinit(const VEMDoFHandler<dim> &dofs, const MPI_Comm comm)
  {
    dof_handler = &dofs;
    dofs.check_mesh_unchanged();
    const auto        &mesh    = dofs.get_mesh();
    const unsigned int n_cells = mesh.n_cells();
    n_parts_                   = dealii::Utilities::MPI::n_mpi_processes(comm);
    this_part_                 = dealii::Utilities::MPI::this_mpi_process(comm);
    AssertThrow(n_cells >= n_parts_,
                dealii::ExcMessage("The mesh has " + std::to_string(n_cells) + " cells, fewer than the " +
                                   std::to_string(n_parts_) + " MPI processes; run with fewer processes."));

    // the cell graph: one entry per pair of cells sharing an edge; METIS
    // runs on process 0 only, and the others receive its answer, so that
    // no process can disagree on the partition
    cell_owner_.assign(n_cells, 0);
    if (n_parts_ > 1)
      {
        if (this_part_ == 0)
          {
            dealii::DynamicSparsityPattern graph(n_cells, n_cells);
            for (unsigned int e = 0; e < mesh.n_edges(); ++e)
              {
                const auto &edge = mesh.edge(e);
                if (edge.at_boundary())
                  continue;
                graph.add(edge.cells[0], edge.cells[1]);
                graph.add(edge.cells[1], edge.cells[0]);
              }
            dealii::SparsityPattern pattern;
            pattern.copy_from(graph);
            dealii::SparsityTools::partition(pattern, n_parts_, cell_owner_,
                                             dealii::SparsityTools::Partitioner::metis);
          }
        const int ierr = MPI_Bcast(cell_owner_.data(), n_cells, MPI_UNSIGNED, 0, comm);
        AssertThrowMPI(ierr);
      }

    const std::vector<unsigned int> per_part = cells_per_part();
    for (unsigned int p = 0; p < n_parts_; ++p)
      AssertThrow(per_part[p] > 0,
                  dealii::ExcMessage("METIS left MPI process " + std::to_string(p) + " without cells (" +
                                     std::to_string(n_cells) + " cells over " + std::to_string(n_parts_) +
                                     " processes); run with fewer processes."));
    owned_cells.clear();
    for (unsigned int c = 0; c < n_cells; ++c)
      if (cell_owner_[c] == this_part_)
        owned_cells.push_back(c);
    n_cut_edges_ = 0;
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      {
        const auto &edge = mesh.edge(e);
        if (!edge.at_boundary() && cell_owner_[edge.cells[0]] != cell_owner_[edge.cells[1]])
          ++n_cut_edges_;
      }

    // node owner: the lowest part among the cells around the node
    node_owner_.assign(dofs.n_nodes(), dealii::numbers::invalid_unsigned_int);
    std::vector<unsigned int> nodes;
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        dofs.get_node_indices(c, nodes);
        for (const unsigned int n : nodes)
          node_owner_[n] = std::min(node_owner_[n], cell_owner_[c]);
      }
    std::vector<dealii::types::global_dof_index> owned;
    for (unsigned int n = 0; n < node_owner_.size(); ++n)
      {
        AssertThrow(node_owner_[n] != dealii::numbers::invalid_unsigned_int,
                    dealii::ExcMessage("VEMPartition: node " + std::to_string(n) + " belongs to no cell."));
        if (node_owner_[n] == this_part_)
          {
            owned.push_back(VEMDoFHandler<dim>::node_dof(n, 0));
            owned.push_back(VEMDoFHandler<dim>::node_dof(n, 1));
          }
      }
    owned_dofs = dealii::IndexSet(dofs.n_dofs());
    owned_dofs.add_indices(owned.begin(), owned.end());
    owned_dofs.compress();

    // ghost layer: cells of other parts touching a vertex of an owned cell
    std::vector<bool> touched(mesh.n_vertices(), false);
    for (const unsigned int c : owned_cells)
      for (const unsigned int v : mesh.cell(c).vertices)
        touched[v] = true;
    ghost_cells_.clear();
    for (unsigned int c = 0; c < n_cells; ++c)
      if (cell_owner_[c] != this_part_)
        for (const unsigned int v : mesh.cell(c).vertices)
          if (touched[v])
            {
              ghost_cells_.push_back(c);
              break;
            }
  }



  template <int dim>
  dealii::IndexSet
  VEMPartition<dim>::dofs_of_cells(const std::vector<unsigned int> &cells) const
  {
    Assert(dof_handler != nullptr, dealii::ExcMessage("VEMPartition: call reinit() first."));
    dof_handler->check_mesh_unchanged();
    std::vector<dealii::types::global_dof_index> all, indices;
    for (const unsigned int c : cells)
      {
        dof_handler->get_dof_indices(c, indices);
        all.insert(all.end(), indices.begin(), indices.end());
      }
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    dealii::IndexSet set(dof_handler->n_dofs());
    set.add_indices(all.begin(), all.end());
    set.compress();
    return set;
  }



  template <int dim>
  dealii::IndexSet
  VEMPartition<dim>::locally_relevant_dofs(const dealii::AffineConstraints<double> &constraints) const
  {
    dealii::IndexSet relevant = dofs_of_cells(owned_cells);
    std::vector<dealii::types::global_dof_index> masters;
    for (const auto i : relevant)
      if (const auto *entries = constraints.get_constraint_entries(i))
        for (const auto &entry : *entries)
          masters.push_back(entry.first);
    std::sort(masters.begin(), masters.end());
    masters.erase(std::unique(masters.begin(), masters.end()), masters.end());
    relevant.add_indices(masters.begin(), masters.end());
    relevant.compress();
    return relevant;
  }



  template <int dim>
  void
  VEMPartition<dim>::make_sparsity_pattern(dealii::DynamicSparsityPattern          &dsp,
                                           const dealii::AffineConstraints<double> &constraints) const
  {
    Assert(dof_handler != nullptr, dealii::ExcMessage("VEMPartition: call reinit() first."));
    dof_handler->check_mesh_unchanged();
    std::vector<dealii::types::global_dof_index> indices;
    for (const unsigned int c : owned_cells)
      {
        dof_handler->get_dof_indices(c, indices);
        constraints.add_entries_local_to_global(indices, dsp, true);
      }
  }



  template <int dim>
  std::vector<unsigned int>
  VEMPartition<dim>::cells_per_part() const
  {
    std::vector<unsigned int> count(n_parts_, 0);
    for (const unsigned int p : cell_owner_)
      ++count[p];
    return count;
  }



  template class VEMPartition<2>;
} // namespace dealvem
