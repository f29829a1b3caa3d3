// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_distributed_contact_solver_h
#define dealvem_contact_distributed_contact_solver_h

#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>

#include <dealvem/solvers/saddle_point_solver.h>

#include <string>

namespace dealvem
{
  template <int dim>
  class VEMPartition;
  template <int dim>
  class ElasticityAssembler;

  /**
   * The contact system solved over MPI processes as constraints (the
   * `CG-AMG constraints` method of SaddlePointSolver, distributed as in
   * deal.II's step-40 and step-42).
   *
   * Every process holds the whole mesh, the node pairs and the contact
   * blocks (they are small: one row per multiplier); the stiffness matrix is
   * never assembled whole. solve() is handed the saddle-point matrix of the
   * <b>contact part only</b> ($B$, $B^T$, $D$ and the stick-penalty springs
   * in the displacement block, all with the displacement constraints
   * condensed, as ContactAssembler writes them) and, per active-set
   * iteration:
   * 1. builds the slave lines of the active constraints (ContactConstraints;
   *    a DoF may be a slave if the displacement constraints leave it free)
   *    and merges them with the displacement constraints;
   * 2. assembles the condensed stiffness of the locally owned cells
   *    (ElasticityAssembler's distributed overload, with the merged
   *    constraints) into a dealii::TrilinosWrappers::SparseMatrix, plus the
   *    spring rows of the owned DoFs; entries of rows owned elsewhere (a
   *    pair whose two nodes live on different processes couples them) are
   *    sent by compress();
   * 3. solves by ParallelLinearSolver (CG + ML AMG for `CG-AMG constraints`;
   *    Amesos KLU for `UMFPACK` and `KLU`, the direct reference);
   * 4. gathers the displacements on every process (the replicated mesh
   *    needs them there), sets the constrained DoFs, and recovers the
   *    multipliers from the residual on the slave DoFs, which only the cells
   *    around the slaves contribute (ElasticityAssembler::add_residual(),
   *    summed over the processes in rank order so that every process gets
   *    the same bits and takes the same active-set decisions).
   *
   * Slipping pairs of Coulomb friction make the condensed matrix
   * non-symmetric (ContactConstraints, Petrov-Galerkin condensation): each
   * process adds its cells' part of the correction
   * $(Z - C)^T K C$ (ElasticityAssembler::add_matrix_rows(), add_residual()),
   * and the solve is GMRES + ML AMG or Amesos KLU. GMRES-AMG (a
   * saddle-point iteration) is refused with a message.
   */
  class DistributedContactSolver : public SaddlePointSolver
  {
  public:
    /// @p displacement_constraints (Dirichlet, rollers, points; closed) and
    /// @p partition must outlive the solver.
    DistributedContactSolver(const Settings                          &settings,
                             const VEMPartition<2>                   &partition,
                             const dealii::AffineConstraints<double> &displacement_constraints,
                             const MPI_Comm                           comm);

    /// The elasticity part (materials, loads) of the current load step.
    void
    set_assembler(const ElasticityAssembler<2> &assembler);

    void
    solve(const dealii::SparseMatrix<double> &A,
          const unsigned int                  n_displacements,
          dealii::Vector<double>             &x,
          const dealii::Vector<double>       &b) override;

    std::string
    description() const override;

    /// Constraint rows of the last solve whose DoFs are owned by more than
    /// one process (pairs cut by the partition).
    unsigned int
    last_rows_across_processes() const
    {
      return n_rows_across;
    }

  private:
    const VEMPartition<2>                   &partition;
    const dealii::AffineConstraints<double> &displacement_constraints;
    MPI_Comm                                 comm;
    const ElasticityAssembler<2>            *assembler     = nullptr;
    unsigned int                             n_rows_across = 0;
  };
} // namespace dealvem

#endif
