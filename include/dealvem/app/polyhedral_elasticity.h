// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_app_polyhedral_elasticity_h
#define dealvem_app_polyhedral_elasticity_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/smartpointer.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>

#include <dealvem/solvers/linear_solver.h>
#include <dealvem/vem/polyhedral_element.h>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  template <typename number>
  class AffineConstraints;
}

namespace dealvem
{
  class PolyhedralMesh;

  /**
   * Linear elasticity in 3D with first-order virtual elements on a
   * PolyhedralMesh: the step-8 of polyhedra (issue 43).
   *
   * DoFs: three per vertex, DoF 3 v + d is component d at vertex v. Loads: a
   * body force (per cell by its value at the centroid times the integrals of
   * the basis functions' projections) and tractions on boundary faces (per
   * face by its value at the face centroid times the face integrals of the
   * basis functions: exact for a constant traction, so a uniform stress
   * state is reproduced exactly). Supports: prescribed displacements on the
   * vertices of boundary faces with a given boundary id, all components or
   * some. Solvers: UMFPACK, or CG with ML AMG whose near-null space is the
   * six rigid-body modes (LinearSolver).
   *
   * Errors against an exact solution use the cellwise projection:
   * $\|u - \Pi u_h\|_{L^2}$ and $\|\nabla u - \nabla \Pi u_h\|_{L^2}$ by a
   * quadrature of degree 3 on each cell (PolyhedralElement::cell_quadrature()).
   */
  class PolyhedralElasticity
  {
  public:
    /// A vector field of the position (displacement, body force).
    using VectorFunction = std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &)>;
    /// A traction of the position and the outward unit normal.
    using TractionFunction =
      std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &, const dealii::Tensor<1, 3> &normal)>;

    /// The material, the element and the solver.
    struct Settings
    {
      /// Young's modulus and Poisson's ratio.
      IsotropicMaterial3D material;
      /// Factor of the element's stabilization.
      double stabilization = 1.;
      /// UMFPACK (default) or CG-AMG.
      LinearSolver::Settings solver;
    };

    /**
     * A problem on @p mesh (kept by reference: it must outlive the problem).
     *
     * With a communicator of more than one process, every process holds
     * the whole mesh (as deal.II's parallel::shared::Triangulation does) and
     * the problem is distributed: METIS partitions the cells over the
     * processes (on the graph of shared faces, computed on process 0 and
     * broadcast); a vertex belongs to the lowest process among those of its
     * cells; each process assembles its cells into the rows of a
     * dealii::TrilinosWrappers::SparseMatrix, and ParallelLinearSolver solves
     * (CG with ML AMG on the six rigid modes, or Amesos KLU for the direct
     * types). After solve() every process holds the whole solution, so that
     * errors(), cell_stresses() and the other queries work as in serial;
     * write_vtu() writes on process 0 only. All calls are collective.
     */
    PolyhedralElasticity(const PolyhedralMesh &mesh, const Settings &settings, MPI_Comm comm = MPI_COMM_SELF);

    /// The body force per volume.
    void
    set_body_force(const VectorFunction &f);

    /// Prescribe the displacement @p g on the boundary faces with id @p id,
    /// in the components where @p components is true.
    void
    add_dirichlet(const dealii::types::boundary_id id,
                  const VectorFunction            &g,
                  const std::array<bool, 3>       &components = {{true, true, true}});

    /// A traction t(x, n) (force per area) on the boundary faces with id @p id.
    void
    add_traction(const dealii::types::boundary_id id, const TractionFunction &t);

    /// Assemble and solve. Throws (naming the cause) for a boundary id that
    /// no face has, or a body not held against rigid motion.
    void
    solve();

    /// Three per vertex.
    unsigned int
    n_dofs() const
    {
      return 3 * n_vertices;
    }

    /// The nodal displacements (after solve()).
    const dealii::Vector<double> &
    solution() const
    {
      return u;
    }

    /// The iterations of the last solve (1 for a direct solver).
    unsigned int
    last_iterations() const
    {
      return iterations;
    }

    /// The number of stored entries of the last system matrix.
    std::size_t
    n_matrix_entries() const
    {
      return matrix_entries;
    }

    /// The number of MPI processes of the communicator given to the
    /// constructor.
    unsigned int
    n_processes() const;

    /// The cells this process assembled in the last solve() (all cells on
    /// one process), increasing.
    const std::vector<unsigned int> &
    locally_owned_cells() const
    {
      return owned_cells;
    }

    /// The wall time in seconds of assembly and of the linear solve.
    std::pair<double, double>
    last_times() const
    {
      return {assembly_time, solve_time};
    }

    /// Error norms of errors().
    struct Errors
    {
      /// The L2 norm of u - Pi u_h.
      double l2 = 0;
      /// The L2 norm of grad u - grad Pi u_h.
      double h1_semi = 0;
      /// The norms of the exact solution, for relative errors.
      double l2_exact = 0;
      /// The L2 norm of grad u.
      double h1_semi_exact = 0;
    };

    /// Errors of the projected solution against @p u and its gradient
    /// @p grad_u (grad_u(x)[d][k] = du_d/dx_k).
    Errors
    errors(const VectorFunction &u, const std::function<dealii::Tensor<2, 3>(const dealii::Point<3> &)> &grad_u) const;

    /// The stress of the projected solution per cell (Voigt order xx, yy,
    /// zz, yz, xz, xy), 6 values per cell.
    std::vector<double>
    cell_stresses() const;

    /// A VTU file: displacement at the vertices; stress components and von
    /// Mises stress per cell (and, on more than one process, the process
    /// that assembled each cell). Written by process 0 only.
    void
    write_vtu(const std::string &file_name) const;

    /// The six rigid-body modes of the DoF vector (translations, then
    /// rotations about the centre of the bounding box).
    std::vector<std::vector<double>>
    rigid_body_modes() const;

  private:
    /// The supports as constraints, after checking that they hold every
    /// connected piece of the mesh.
    void
    make_constraints(dealii::AffineConstraints<double> &constraints) const;

    /// The METIS partition of the cells over the processes (all cells
    /// owned by process 0 on one process).
    void
    partition_cells();

    dealii::SmartPointer<const PolyhedralMesh> mesh;
    Settings                                   settings;
    MPI_Comm                                   comm;
    std::vector<unsigned int>                  cell_owner, owned_cells;
    unsigned int                               n_vertices;
    VectorFunction                             body_force;
    struct Dirichlet
    {
      dealii::types::boundary_id id;
      VectorFunction             g;
      std::array<bool, 3>        components;
    };
    std::vector<Dirichlet>                                               dirichlet;
    std::vector<std::pair<dealii::types::boundary_id, TractionFunction>> tractions;
    dealii::Vector<double>                                               u;
    unsigned int                                                         iterations     = 0;
    std::size_t                                                          matrix_entries = 0;
    double                                                               assembly_time = 0, solve_time = 0;
  };
} // namespace dealvem

#endif
