// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// VEMDoFHandler holds its mesh through a SmartPointer and refuses to work
// on a mesh changed after distribute_dofs(): node insertion (split_edge,
// move_vertex), shift() and assigning another mesh are detected and named
// in the message; distribute_dofs() again gives a valid numbering of the
// changed mesh (every DoF used, counts as the entities say).
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <dealvem/contact/node_insertion.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>

#include "../tests.h"

using namespace dealvem;

namespace
{
  // two blocks, 3x3 quads below (ids 0..3), 4x4 quads above (ids 10..13,
  // material 1): the top side 3 of the lower block and the bottom side 12
  // of the upper one do not match
  void
  make_two_blocks(PolygonalMesh<2> &mesh)
  {
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 3, 3);
    PolygonalMesh<2> upper;
    PolygonalMeshGenerators::structured_quads(upper, dealii::Point<2>(0, 1), dealii::Point<2>(1, 2), 4, 4);
    for (unsigned int c = 0; c < upper.n_cells(); ++c)
      upper.set_material_id(c, 1);
    for (unsigned int e = 0; e < upper.n_edges(); ++e)
      if (upper.edge(e).at_boundary())
        upper.set_edge_boundary_id(e, upper.edge(e).boundary_id + 10);
    mesh.append(upper);
    mesh.name = "two blocks";
  }

  // every cell's DoF indices are in range, every DoF belongs to a cell, and
  // the count is 2 (vertices + edges + cells) for k = 2
  void
  check_numbering(const VEMDoFHandler<2> &dof_handler, const std::string &what)
  {
    const auto &mesh = dof_handler.get_mesh();
    testing::check(dof_handler.n_dofs() == 2 * (mesh.n_vertices() + mesh.n_edges() + mesh.n_cells()),
                   what + ": n_dofs = 2 (vertices + edges + cells) = " + std::to_string(dof_handler.n_dofs()));
    std::vector<bool>                            used(dof_handler.n_dofs(), false);
    std::vector<dealii::types::global_dof_index> indices;
    bool                                         in_range = true;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        dof_handler.get_dof_indices(c, indices);
        in_range = in_range && indices.size() == 2 * (2 * mesh.cell(c).vertices.size() + 1);
        for (const auto i : indices)
          if (i < used.size())
            used[i] = true;
          else
            in_range = false;
      }
    testing::check(in_range && std::find(used.begin(), used.end(), false) == used.end(),
                   what + ": every cell has 2(2N+1) DoFs in range and every DoF belongs to a cell");
  }
} // namespace

int
main()
{
  const std::string again = "was changed after distribute_dofs()";
  const std::string call  = "call distribute_dofs() again";

  // (1) node insertion after distribute_dofs()
  {
    PolygonalMesh<2> mesh;
    make_two_blocks(mesh);
    VEMDoFHandler<2> dof_handler(mesh);
    testing::check(mesh.n_subscriptions() == 1, "the DoF handler subscribes to the mesh (SmartPointer)");
    dof_handler.distribute_dofs(2);
    check_numbering(dof_handler, "before node insertion");
    const auto n_dofs_before = dof_handler.n_dofs();
    const auto revision      = mesh.get_revision();

    const auto interface = NodeInsertion::insert(mesh, 3, 12, 2, NodeInsertion::Settings());
    testing::check(mesh.get_revision() != revision && interface.pairs.size() > 0,
                   "node insertion changed the mesh's revision (last change: " + mesh.get_last_change() + ")");
    std::vector<dealii::types::global_dof_index> indices;
    testing::check_throws([&] { dof_handler.get_dof_indices(0, indices); }, again,
                          "get_dof_indices after node insertion throws");
    testing::check_throws([&] { dof_handler.get_dof_indices(0, indices); }, call,
                          "... and tells what to do");
    testing::check_throws([&] { dof_handler.get_dof_indices(0, indices); },
                          "(last change: " + mesh.get_last_change() + ")", "... and names the change");
    testing::check(mesh.get_last_change() == "split_edge()" || mesh.get_last_change() == "move_vertex()",
                   "the last change of node insertion is split_edge() or move_vertex()");
    dealii::DynamicSparsityPattern dsp(n_dofs_before);
    testing::check_throws([&] { dof_handler.make_sparsity_pattern(dsp); }, again,
                          "make_sparsity_pattern after node insertion throws");
    testing::check_throws([&] { dof_handler.boundary_nodes({3}); }, again,
                          "boundary_nodes after node insertion throws");
    testing::check_throws([&] { dof_handler.rigid_body_modes(); }, again,
                          "rigid_body_modes after node insertion throws");

    // (2) distribute again: a valid numbering of the changed mesh
    dof_handler.distribute_dofs(2);
    check_numbering(dof_handler, "after node insertion and distribute_dofs()");
    testing::check(dof_handler.n_dofs() > n_dofs_before,
                   "the inserted nodes have DoFs: " + std::to_string(n_dofs_before) + " -> " +
                     std::to_string(dof_handler.n_dofs()));
  }

  // (3) other changes: move_vertex, shift, assignment; material ids do not count
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 2, 2);
    mesh.name = "unit square";
    VEMDoFHandler<2> dof_handler(mesh);
    std::vector<dealii::types::global_dof_index> indices;
    testing::check_throws([&] { dof_handler.get_dof_indices(0, indices); }, "no DoFs; call reinit(mesh) and distribute_dofs(degree) first",
                          "use before distribute_dofs throws");
    dof_handler.distribute_dofs(1);
    mesh.set_material_id(0, 3);
    dof_handler.get_dof_indices(0, indices);
    testing::check(indices.size() == 8, "a material id change keeps the numbering valid");

    mesh.move_vertex(4, dealii::Point<2>(0.55, 0.5));
    testing::check_throws([&] { dof_handler.get_dof_indices(0, indices); },
                          "the mesh 'unit square' was changed after distribute_dofs() (last change: move_vertex())",
                          "move_vertex is named");
    dof_handler.distribute_dofs(1);
    testing::check(dof_handler.node_location(4).distance(dealii::Point<2>(0.55, 0.5)) == 0.,
                   "after distribute_dofs() the node is at the moved vertex");

    mesh.shift(dealii::Tensor<1, 2>({1., 0.}));
    testing::check_throws([&] { dof_handler.node_location(4); }, "(last change: shift())", "shift is named");
    dof_handler.distribute_dofs(1);

    PolygonalMesh<2> other;
    PolygonalMeshGenerators::structured_quads(other, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 3, 3);
    testing::check(other.get_revision() != mesh.get_revision(), "two meshes never share a revision");
    mesh = other;
    testing::check_throws([&] { dof_handler.get_dof_indices(0, indices); }, again,
                          "assigning another mesh is detected");
    dof_handler.distribute_dofs(1);
    testing::check(dof_handler.n_dofs() == 32, "after distribute_dofs() the 3x3 mesh has 32 DoFs");
  }
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 2, 2);
    {
      VEMDoFHandler<2> dof_handler(mesh);
      VEMDoFHandler<2> copy(dof_handler);
      testing::check(mesh.n_subscriptions() == 2, "a copy of a DoF handler subscribes too");
    }
    testing::check(mesh.n_subscriptions() == 0, "destroyed DoF handlers unsubscribe");
  }
  return testing::finish();
}
