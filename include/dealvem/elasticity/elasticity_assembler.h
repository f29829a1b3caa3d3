// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_elasticity_elasticity_assembler_h
#define dealvem_elasticity_elasticity_assembler_h

#include <deal.II/base/function.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <map>
#include <vector>

namespace dealii
{
  namespace TrilinosWrappers
  {
    class SparseMatrix;
    namespace MPI
    {
      class Vector;
    }
  } // namespace TrilinosWrappers
} // namespace dealii

namespace dealvem
{
  template <int dim>
  class VEMValues;

  /**
   * Assembles the global stiffness matrix and load vector of 2D linear
   * elasticity with the virtual element of VEMDoFHandler::get_degree().
   *
   * Takes: a VEMDoFHandler with distributed DoFs, one linear constitutive
   * law per material id (a MaterialLibrary, or a map of ElasticMaterial),
   * the stabilization factor $\gamma$, loads (body force,
   * tractions and pressures on boundary ids) and an AffineConstraints object
   * holding the Dirichlet data. Gives: the condensed matrix and right-hand
   * side, assembled cell by cell with
   * AffineConstraints::distribute_local_to_global (as in deal.II's step-8).
   *
   * The loads are those of VirtualElement: body force through the
   * projection, tractions and pressures by a 5-point Gauss rule on each
   * loaded boundary edge.
   */
  template <int dim>
  class ElasticityAssembler
  {
  public:
    /**
     * Constructor: the laws of @p laws (copied; the library shares its
     * laws). Throws unless $\gamma > 0$ and every law is linear
     * (ElasticityOperator assembles linear laws only).
     */
    ElasticityAssembler(const VEMDoFHandler<dim>   &dof_handler,
                        const MaterialLibrary<dim> &laws,
                        const double                gamma         = 1.0,
                        const Stabilization         stabilization = Stabilization::automatic);

    /// The same with one ElasticMaterial per material id.
    ElasticityAssembler(const VEMDoFHandler<dim>                                   &dof_handler,
                        const std::map<dealii::types::material_id, ElasticMaterial> &materials,
                        const double                                                gamma = 1.0,
                        const Stabilization stabilization = Stabilization::automatic);

    /// Body force (2 components). The function must outlive the assembler.
    void
    set_body_force(const dealii::Function<dim> &f);

    /// Traction (2 components) on the boundary edges with id @p id.
    void
    add_traction(const dealii::types::boundary_id id, const dealii::Function<dim> &g);

    /// Normal pressure (scalar, positive = pushing into the body) on the
    /// boundary edges with id @p id.
    void
    add_pressure(const dealii::types::boundary_id id, const dealii::Function<dim> &p);

    /**
     * A concentrated load @p value on the DoF @p dof, added to the
     * unconstrained load vector (so assemble() distributes it with the
     * constraints like the other loads). Used for the resultant of a rigid
     * boundary part (BoundaryConditions::rigid_boundary_load()).
     */
    void
    add_nodal_load(const dealii::types::global_dof_index dof, const double value);

    /// The DoF handler given to the constructor (held by reference: it
    /// must outlive the assembler).
    const VEMDoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /// The constitutive law of cell @p c (throws naming the cell if its
    /// material id has no law).
    const ConstitutiveLaw<dim> &
    get_law(const unsigned int c) const;

    /// The laws by material id.
    const MaterialLibrary<dim> &
    get_material_library() const
    {
      return laws;
    }

    /// The material of cell @p c as an ElasticMaterial (throws naming the
    /// cell if its material id has no law, or if its law is not an
    /// ElasticMaterial; get_law() takes any law).
    const ElasticMaterial &
    get_material(const unsigned int c) const;

    /// The laws of the library that are ElasticMaterial objects, by
    /// material id (all of them when the assembler was given a map of
    /// ElasticMaterial).
    const std::map<dealii::types::material_id, ElasticMaterial> &
    get_materials() const
    {
      return materials;
    }

    /// The stabilization factor $\gamma > 0$ given to the constructor
    /// (dimensionless; it scales the stabilization of every cell).
    double
    get_gamma() const
    {
      return gamma;
    }

    /// The stabilization rule of the element matrices (ElasticityOperator).
    Stabilization
    get_stabilization() const
    {
      return stabilization;
    }

    /// Reuse the element matrices of translated cells (default: on); see
    /// VirtualElement::reinit().
    /// The matrices are those of ElasticityOperator.
    void
    set_cell_similarity(const bool enable)
    {
      cell_similarity = enable;
    }

    /// Assemble the matrix and the right-hand side. @p matrix must have a
    /// sparsity pattern from VEMDoFHandler::make_sparsity_pattern (with the
    /// constraints' entries added, as for deal.II). Both are zeroed first;
    /// they may be larger than n_dofs() (a saddle-point system whose first
    /// n_dofs() unknowns are the displacements, as ContactProblem's), and
    /// @p rhs is resized to n_dofs() when it is smaller.
    void
    assemble(const dealii::AffineConstraints<double> &constraints,
             dealii::SparseMatrix<double>            &matrix,
             dealii::Vector<double>                  &rhs) const;

    /**
     * The same for a matrix and vector distributed over MPI processes
     * (step-40's assembly): only the cells @p cells (the locally owned ones,
     * VEMPartition::locally_owned_cells()) are assembled, entries of rows
     * owned by other processes are sent to them by
     * compress(VectorOperation::add) at the end (collective). The matrix
     * needs the distributed sparsity pattern of those cells with the
     * constraints' entries; @p constraints must hold the lines of the DoFs
     * of the cells. The nodal loads are added on process 0 only. The loop
     * body is the serial one.
     */
    void
    assemble(const dealii::AffineConstraints<double>   &constraints,
             const std::vector<unsigned int>           &cells,
             dealii::TrilinosWrappers::SparseMatrix    &matrix,
             dealii::TrilinosWrappers::MPI::Vector     &rhs) const;

    /**
     * The same, and each cell's stiffness matrix also added to
     * @p second_matrix under the constraints @p second_constraints (the
     * matrix only, zeroed first, compressed at the end): two condensations
     * of the same stiffness from one computation of the cell matrices. The
     * distributed contact solve assembles its condensed stiffness and the
     * stiffness tied by the stick springs (the preconditioner's) this way;
     * @p second_matrix may have the sparsity pattern of @p matrix when that
     * holds the entries of both sets of constraints.
     */
    void
    assemble(const dealii::AffineConstraints<double> &constraints,
             const std::vector<unsigned int>         &cells,
             dealii::TrilinosWrappers::SparseMatrix  &matrix,
             dealii::TrilinosWrappers::MPI::Vector   &rhs,
             const dealii::AffineConstraints<double> &second_constraints,
             dealii::TrilinosWrappers::SparseMatrix  &second_matrix) const;

    /**
     * Add the unconstrained residual f_c - K_c u_c of the cells @p cells
     * (and the nodal loads if @p with_nodal_loads) to @p r (size n_dofs()).
     * Where no constraint line touches a DoF and @p u satisfies the
     * constraints, this is the residual of the condensed system; the
     * distributed contact solve uses it to recover the multipliers from the
     * cells around the slave DoFs only.
     */
    void
    add_residual(const std::vector<unsigned int> &cells,
                 const dealii::Vector<double>    &u,
                 const bool                       with_nodal_loads,
                 dealii::Vector<double>          &r) const;

    /**
     * Add the rows of the unconstrained cell stiffness matrices of the cells
     * @p cells to @p rows: for every key d of @p rows (a DoF) and every cell
     * with the DoF d, rows[d][j] += K_c(d, j). The distributed contact solve
     * uses it for the Petrov-Galerkin correction of slipping pairs (the row
     * of the stiffness at a slave DoF, ContactConstraints).
     */
    void
    add_matrix_rows(
      const std::vector<unsigned int>                                                              &cells,
      std::map<dealii::types::global_dof_index, std::map<dealii::types::global_dof_index, double>> &rows) const;

    /// Assemble only the (unconstrained) load vector: body force and
    /// boundary loads.
    void
    assemble_load_vector(dealii::Vector<double> &rhs) const;

    /**
     * The local load vector of the cell @p vem_values was reinit()ed on:
     * body force and the tractions and pressures on its boundary edges.
     * Used by assemble() and by loops that assemble their own matrices
     * (ContactProblem) so that loads are computed in one place.
     */
    void
    local_load(const VEMValues<dim> &vem_values, dealii::Vector<double> &F) const;

  private:
    /// The one assembly loop: the cells @p cells (all if nullptr), the
    /// nodal loads if @p with_nodal_loads; each cell matrix also into
    /// @p second_matrix under @p second_constraints when both are given.
    template <typename MatrixType, typename VectorType>
    void
    assemble_cells(const dealii::AffineConstraints<double> &constraints,
                   const std::vector<unsigned int>         *cells,
                   const bool                               with_nodal_loads,
                   MatrixType                              &matrix,
                   VectorType                              &rhs,
                   const dealii::AffineConstraints<double> *second_constraints = nullptr,
                   MatrixType                              *second_matrix      = nullptr) const;

    const VEMDoFHandler<dim>                               &dof_handler;
    MaterialLibrary<dim>                                    laws;
    std::map<dealii::types::material_id, ElasticMaterial>   materials;
    double                                                  gamma;
    Stabilization                                           stabilization;
    bool                                                    cell_similarity = true;
    const dealii::Function<dim>                            *body_force = nullptr;
    std::vector<std::pair<dealii::types::boundary_id, const dealii::Function<dim> *>> tractions;
    std::vector<std::pair<dealii::types::boundary_id, const dealii::Function<dim> *>> pressures;
    std::vector<std::pair<dealii::types::global_dof_index, double>>                 nodal_loads;
  };
} // namespace dealvem

#endif
