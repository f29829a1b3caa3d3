// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_vem_vem_dof_handler_h
#define dealvem_vem_vem_dof_handler_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/smartpointer.h>
#include <deal.II/base/types.h>

#include <dealvem/mesh/polygonal_mesh.h>
#include <dealvem/vem/vem_element_data.h>

#include <set>
#include <vector>

namespace dealii
{
  class DynamicSparsityPattern;
  template <typename Number>
  class Vector;
  template <typename Number>
  class AffineConstraints;
}

namespace dealvem
{
  template <int dim>
  class VirtualElement;

  /**
   * Enumerates the degrees of freedom of the order-k virtual element space
   * for 2D vector problems (two displacement components) on a
   * PolygonalMesh.
   *
   * The DoFs live on the mesh entities: two per vertex; for k = 2 also two
   * per edge (midpoint values) and two per cell (cell moments). Entities
   * shared by several cells carry one set of DoFs, which makes the space
   * conforming. The global numbering is entity by entity: first all
   * vertices (DoF 2v + c of vertex v, component c), then all edges, then
   * all cells.
   *
   * get_dof_indices() returns the global indices of a cell in the local
   * order of VirtualElement (interleaved components; vertices, then edge
   * midpoints, then the cell moment), so local matrices from VirtualElement
   * go straight into AffineConstraints::distribute_local_to_global.
   *
   * A node is an entity carrying two DoFs (one per component); nodes are
   * numbered like the DoFs: node j owns DoFs 2j and 2j + 1.
   *
   * <h3>Lifetime and mesh changes</h3>
   * The mesh is held through a dealii::SmartPointer, as deal.II's DoFHandler
   * holds its Triangulation: destroying the mesh while a DoF handler still
   * points to it is reported (in Debug builds). distribute_dofs() records the
   * mesh's revision (PolygonalMesh::get_revision()). If the mesh is changed
   * afterwards -- node insertion splits edges and moves vertices, shift(),
   * finalize(), assignment of another mesh -- the numbering no longer
   * matches the mesh, and every function below that reads the mesh throws
   * ExcMeshChangedAfterDistributeDofs (also in Release builds), naming the
   * change. Calling distribute_dofs() again renumbers the DoFs for the
   * changed mesh.
   */
  template <int dim>
  class VEMDoFHandler
  {
  public:
    VEMDoFHandler() = default;

    /// A handler attached to @p mesh, as reinit(); no DoFs until
    /// distribute_dofs().
    explicit VEMDoFHandler(const PolygonalMesh<dim> &mesh);

    /// Attach a (finalized) mesh.
    void
    reinit(const PolygonalMesh<dim> &mesh);

    /// Enumerate the DoFs for order @p degree (1 or 2): the layout
    /// VEMElementData(degree).
    void
    distribute_dofs(const unsigned int degree);

    /// Enumerate the DoFs of the space of @p element (its
    /// get_element_data()), as deal.II's DoFHandler::distribute_dofs(fe).
    void
    distribute_dofs(const VirtualElement<dim> &element);

    /**
     * Enumerate the DoFs of the layout @p data: nodes on the vertices, then
     * VEMElementData::nodes_per_edge() on every edge (edge by edge, from the
     * edge's first vertex), then VEMElementData::nodes_per_cell() in every
     * cell. The other members read the layout from here.
     */
    void
    distribute_dofs(const VEMElementData &data);

    /// The layout of the last distribute_dofs() (that of order 1 before
    /// it; see get_degree()).
    const VEMElementData &
    get_element_data() const
    {
      return data;
    }

    /// The attached mesh (asserted in debug mode that there is one).
    const PolygonalMesh<dim> &
    get_mesh() const
    {
      Assert(mesh != nullptr, dealii::ExcMessage("VEMDoFHandler: no mesh attached."));
      return *mesh;
    }

    /**
     * Throw ExcMeshChangedAfterDistributeDofs unless distribute_dofs() has
     * been called for the present revision of the mesh. The member functions
     * that read the mesh call this; user code that combines the DoF handler
     * with its own look at the mesh can call it too.
     */
    void
    check_mesh_unchanged() const;

    /// The order k of the last distribute_dofs(); 0 before it, and after
    /// reinit().
    unsigned int
    get_degree() const
    {
      return degree;
    }

    /// Total number of DoFs (two per node); 0 before distribute_dofs().
    dealii::types::global_dof_index
    n_dofs() const
    {
      return n_dofs_;
    }

    /// Number of nodes (= n_dofs() / 2).
    unsigned int
    n_nodes() const
    {
      return n_dofs_ / 2;
    }

    /// Number of DoFs of cell @p c.
    unsigned int
    n_dofs_per_cell(const unsigned int c) const;

    /// Global DoF indices of cell @p c in VirtualElement's local order.
    void
    get_dof_indices(const unsigned int                            c,
                    std::vector<dealii::types::global_dof_index> &indices) const;

    /// The values of a global vector at the DoFs of cell @p c, in
    /// VirtualElement's local order (deal.II's cell->get_dof_values()).
    void
    get_dof_values(const unsigned int c, const dealii::Vector<double> &global,
                   dealii::Vector<double> &local) const;

    /// Global node indices of cell @p c in local node order.
    void
    get_node_indices(const unsigned int c, std::vector<unsigned int> &nodes) const;

    /// Node of vertex @p v of the mesh (the vertices are numbered first, so
    /// this is @p v itself).
    unsigned int
    vertex_node(const unsigned int v) const
    {
      return v;
    }

    /// Node of the midpoint of edge @p e of the mesh (k = 2 only; asserted
    /// in debug mode).
    unsigned int
    edge_node(const unsigned int e) const;

    /// Node @p j of the nodes inside edge @p e of the mesh, counted from
    /// the edge's first vertex (asserted in debug mode that it exists).
    unsigned int
    edge_node(const unsigned int e, const unsigned int j) const;

    /// Node of the cell moment of cell @p c (k = 2 only; asserted in debug
    /// mode).
    unsigned int
    cell_node(const unsigned int c) const;

    /// Node of moment @p j of cell @p c (asserted in debug mode that it
    /// exists).
    unsigned int
    cell_node(const unsigned int c, const unsigned int j) const;

    /// DoF of component @p comp at node @p node.
    static dealii::types::global_dof_index
    node_dof(const unsigned int node, const unsigned int comp)
    {
      return 2 * dealii::types::global_dof_index(node) + comp;
    }

    /// Location of a node: vertex, edge midpoint or cell centroid.
    dealii::Point<dim>
    node_location(const unsigned int node) const;

    /// True for cell-moment nodes (not point values).
    bool
    is_moment_node(const unsigned int node) const;

    /// Locations of all DoFs (the node location of each), like
    /// DoFTools::map_dofs_to_support_points.
    void
    map_dofs_to_support_points(std::vector<dealii::Point<dim>> &points) const;

    /// Nodes lying on boundary edges whose boundary id is in @p ids
    /// (vertices and, for k = 2, midpoints), sorted.
    std::vector<unsigned int>
    boundary_nodes(const std::set<dealii::types::boundary_id> &ids) const;

    /// Sparsity pattern: all DoFs of a cell couple with each other.
    void
    make_sparsity_pattern(dealii::DynamicSparsityPattern &dsp) const;

    /// The same with the entries that @p constraints add, as
    /// DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints,
    /// keep_constrained_dofs) does for a deal.II DoFHandler.
    void
    make_sparsity_pattern(dealii::DynamicSparsityPattern          &dsp,
                          const dealii::AffineConstraints<double> &constraints,
                          const bool keep_constrained_dofs = true) const;

    /// The three rigid-body modes (two translations and the rotation about
    /// the origin) as DoF vectors, for example for AMG near-null spaces.
    /// Cell-moment DoFs get the cell average of the mode.
    std::vector<std::vector<double>>
    rigid_body_modes() const;

  private:
    /// Call f(j, node) for the local nodes j of cell @p c in
    /// VirtualElement's order (vertices, edge midpoints, cell moment): the
    /// one definition of that order, used without temporary storage.
    template <typename F>
    void
    for_each_node(const unsigned int c, const F &f) const;

    dealii::SmartPointer<const PolygonalMesh<dim>, VEMDoFHandler<dim>> mesh;
    /// Revision of the mesh at the last distribute_dofs().
    std::uint64_t                                  mesh_revision = 0;
    unsigned int                                   degree = 0;
    /// The layout of the last distribute_dofs().
    VEMElementData                                 data{1};
    dealii::types::global_dof_index                n_dofs_ = 0;
    unsigned int                                   n_vertex_nodes = 0;
    unsigned int                                   n_edge_nodes   = 0;
    std::vector<dealii::Point<dim>>                cell_centroids;
  };



  /**
   * The mesh of a VEMDoFHandler was changed after distribute_dofs():
   * arguments are the mesh's name and the operation that changed it.
   */
  DeclException2(ExcMeshChangedAfterDistributeDofs,
                 std::string,
                 std::string,
                 << "VEMDoFHandler: the mesh '" << arg1 << "' was changed after distribute_dofs() (last change: "
                 << arg2 << "), so the DoF numbering no longer matches it; call distribute_dofs() again.");

  /// A VEMDoFHandler was used before distribute_dofs() was called.
  DeclExceptionMsg(ExcNoDoFsDistributed,
                   "VEMDoFHandler: no DoFs; call reinit(mesh) and distribute_dofs(degree) first.");
} // namespace dealvem

#endif
