// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_vem_partitioning_h
#define dealvem_vem_partitioning_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>

#include <dealvem/vem/vem_dof_handler.h>

#include <vector>

namespace dealvem
{
  /**
   * The distribution of a (replicated) polygon mesh and its DoFs over the
   * processes of an MPI communicator: what deal.II's
   * parallel::shared::Triangulation with a METIS partitioner and the
   * DoFHandler's index sets are for a finite element mesh.
   *
   * Every process holds the whole PolygonalMesh and VEMDoFHandler (the DoF
   * numbering is the serial one). reinit() partitions the cells with METIS
   * on the cell graph (two cells are neighbours when they share an edge),
   * through dealii::SparsityTools::partition; the partition is computed on
   * process 0 and broadcast, so that all processes agree on it. Then:
   * - a cell is locally owned by the process of its part;
   * - a node (two DoFs) belongs to the lowest-numbered process among the
   *   owners of the cells around it, so locally_owned_dofs() are disjoint
   *   over the processes and cover all DoFs; the sets are not contiguous
   *   (the serial numbering is kept), which Epetra maps allow;
   * - locally_relevant_dofs() are the DoFs of the locally owned cells plus
   *   the DoFs their constraints refer to (rows the assembly writes to);
   * - ghost_cells() are the cells of other processes sharing a vertex with
   *   a locally owned cell, the layer needed for complete nodal averages
   *   (stresses at vertices) on the owned cells.
   *
   * With one process the partition is trivial (everything owned).
   */
  template <int dim>
  class VEMPartition
  {
  public:
    /// Partition the cells of @p dof_handler's mesh (its DoFs distributed)
    /// over the processes of @p comm. Collective.
    void
    reinit(const VEMDoFHandler<dim> &dof_handler, const MPI_Comm comm);

    /// Number of parts, the number of processes of the communicator given
    /// to reinit() (1 before it).
    unsigned int
    n_parts() const
    {
      return n_parts_;
    }

    /// The part of this process: its rank in the communicator given to
    /// reinit() (0 before it).
    unsigned int
    this_part() const
    {
      return this_part_;
    }

    /// Owner (part) of cell @p c.
    unsigned int
    cell_owner(const unsigned int c) const
    {
      return cell_owner_[c];
    }

    /// Owner (part) of node @p node (DoFs 2 node and 2 node + 1).
    unsigned int
    node_owner(const unsigned int node) const
    {
      return node_owner_[node];
    }

    /// The cells of this process, increasing.
    const std::vector<unsigned int> &
    locally_owned_cells() const
    {
      return owned_cells;
    }

    /// Cells of other processes with a vertex on a locally owned cell,
    /// increasing.
    const std::vector<unsigned int> &
    ghost_cells() const
    {
      return ghost_cells_;
    }

    /// The DoFs of the nodes this process owns (see node_owner()); over
    /// all processes the sets are disjoint and cover all DoFs.
    const dealii::IndexSet &
    locally_owned_dofs() const
    {
      return owned_dofs;
    }

    /// The DoFs of the locally owned cells and the DoFs that the
    /// constraints of these DoFs refer to.
    dealii::IndexSet
    locally_relevant_dofs(const dealii::AffineConstraints<double> &constraints) const;

    /// The DoFs of the given cells (for example owned and ghost cells).
    dealii::IndexSet
    dofs_of_cells(const std::vector<unsigned int> &cells) const;

    /// Add the couplings of the locally owned cells, with the entries the
    /// constraints add (as VEMDoFHandler::make_sparsity_pattern() does for
    /// all cells); then dealii::SparsityTools::distribute_sparsity_pattern()
    /// sends the rows of other processes to them.
    void
    make_sparsity_pattern(dealii::DynamicSparsityPattern          &dsp,
                          const dealii::AffineConstraints<double> &constraints) const;

    /// Number of interior edges whose two cells lie in different parts.
    unsigned int
    n_cut_edges() const
    {
      return n_cut_edges_;
    }

    /// Number of cells of each part.
    std::vector<unsigned int>
    cells_per_part() const;

  private:
    const VEMDoFHandler<dim>                                         *dof_handler = nullptr;
    unsigned int                                                      n_parts_   = 1;
    unsigned int                                                      this_part_ = 0;
    std::vector<unsigned int>                                         cell_owner_, node_owner_;
    std::vector<unsigned int>                                         owned_cells, ghost_cells_;
    dealii::IndexSet                                                  owned_dofs;
    unsigned int                                                      n_cut_edges_ = 0;
  };
} // namespace dealvem

#endif
