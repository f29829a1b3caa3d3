// A downstream program: a Voronoi mesh, VEM k = 2 DoFs and one element
// stiffness, and a deal.II triangulation solved nowhere but transferred
// (a linear field, reproduced exactly), through the package dealvem::dealvem.
// Built by tests/app/downstream.test.cmake in Debug and in Release: it
// checks that the build type's deal.II definitions arrived alone (DEBUG or
// NDEBUG, not both) and, in Debug, that the debug library libdealvem.g.so
// is linked: a misuse its Assert()s catch throws instead of crashing.
#include <deal.II/base/exceptions.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/triangulation_map.h>
#include <dealvem/postprocessing/fe_transfer.h>
#include <dealvem/vem/vem_dof_handler.h>
#include <dealvem/vem/vem_values.h>
#include <dealvem/vem/virtual_element.h>

#include <cmath>
#include <iostream>

int
main()
{
#if defined(DEBUG) && defined(NDEBUG)
  std::cout << "build type: both DEBUG and NDEBUG defined (mixed Debug and Release flags)" << std::endl;
  return 1;
#elif defined(DEBUG)
  std::cout << "build type: Debug" << std::endl;
#else
  std::cout << "build type: Release" << std::endl;
#endif

  dealvem::PolygonalMesh<2> mesh;
  dealvem::PolygonalMeshGenerators::voronoi(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 20, 5, 1);
  dealvem::VEMDoFHandler<2> dof_handler(mesh);
  dof_handler.distribute_dofs(2);
  dealvem::VirtualElement<2> element(2);
  element.reinit(mesh.cell_vertices(0));
  dealvem::ElasticityOperator<2> elasticity;
  elasticity.reinit(element, dealvem::ElasticMaterial(1000, 0.3));
  std::cout << "downstream: " << mesh.n_cells() << " cells, " << dof_handler.n_dofs() << " dofs, element matrix "
            << elasticity.get_stiffness_matrix().m() << "x" << elasticity.get_stiffness_matrix().n() << std::endl;

#ifdef DEBUG
  // VEMValues asked for a cell's edges before reinit(): the debug library's
  // Assert must catch it. deal.II aborts on a failed Assert in Debug mode
  // unless told to throw instead.
  dealii::deal_II_exceptions::disable_abort_on_exception();
  {
    dealvem::VEMValues<2> vem_values(dof_handler);
    try
      {
        const unsigned int n = vem_values.n_edges();
        std::cout << "debug: VEMValues::n_edges() before reinit() returned " << n << " without an exception"
                  << std::endl;
        return 1;
      }
    catch (const dealii::ExceptionBase &)
      {
        std::cout << "debug: VEMValues::n_edges() before reinit() throws ExceptionBase" << std::endl;
      }
  }
#endif

  // u = (x + 2y, 3x - y) at the VEM nodes, transferred to FE_DGQ(1)^2
  dealii::Triangulation<2> tria;
  dealii::GridGenerator::hyper_cube(tria);
  tria.refine_global(2);
  dealvem::PolygonalMesh<2>    tria_mesh;
  dealvem::TriangulationMap<2> map;
  dealvem::PolygonalMeshGenerators::from_triangulation(tria_mesh, tria, map);
  dealvem::VEMDoFHandler<2> vem_dofs(tria_mesh);
  vem_dofs.distribute_dofs(1);
  dealii::Vector<double> u_h(vem_dofs.n_dofs());
  for (unsigned int node = 0; node < vem_dofs.n_nodes(); ++node)
    {
      const dealii::Point<2> x = vem_dofs.node_location(node);
      u_h[2 * node]            = x[0] + 2 * x[1];
      u_h[2 * node + 1]        = 3 * x[0] - x[1];
    }
  const dealii::FESystem<2> fe(dealii::FE_DGQ<2>(1), 2);
  dealii::DoFHandler<2>     fe_dofs(tria);
  fe_dofs.distribute_dofs(fe);
  dealii::Vector<double> field;
  dealvem::FETransfer::interpolate_to_discontinuous(map, vem_dofs, u_h, fe_dofs, field);
  std::vector<dealii::Point<2>> support(fe.n_dofs_per_cell());
  std::vector<dealii::types::global_dof_index> indices(fe.n_dofs_per_cell());
  double error = 0;
  for (const auto &cell : fe_dofs.active_cell_iterators())
    {
      cell->get_dof_indices(indices);
      for (unsigned int i = 0; i < indices.size(); ++i)
        {
          // FE_DGQ(1) support points are the vertices, in deal.II's order
          const dealii::Point<2> x = cell->vertex(fe.system_to_base_index(i).second);
          const double exact = fe.system_to_component_index(i).first == 0 ? x[0] + 2 * x[1] : 3 * x[0] - x[1];
          error = std::max(error, std::abs(field[indices[i]] - exact));
        }
    }
  std::cout << "transfer: " << tria.n_active_cells() << " cells, " << fe_dofs.n_dofs()
            << " FE_DGQ(1) DoFs, max |u - u_h| at the DoFs " << (error < 1e-14 ? 0. : error) << std::endl;
  return 0;
}
