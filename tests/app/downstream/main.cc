// A downstream program: a Voronoi mesh, VEM k = 2 DoFs and one element
// stiffness, through the installed-style package dealvem::dealvem.
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/virtual_element.h>

#include <iostream>

int
main()
{
  dealvem::PolygonalMesh<2> mesh;
  dealvem::PolygonalMeshGenerators::voronoi(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 20, 5, 1);
  dealvem::VEMDoFHandler<2> dof_handler(mesh);
  dof_handler.distribute_dofs(2);
  dealvem::VirtualElement<2> element(2);
  element.reinit(mesh.cell_vertices(0), dealvem::ElasticMaterial(1000, 0.3));
  std::cout << "downstream: " << mesh.n_cells() << " cells, " << dof_handler.n_dofs() << " dofs, element matrix "
            << element.get_stiffness_matrix().m() << "x" << element.get_stiffness_matrix().n() << std::endl;
  return 0;
}
