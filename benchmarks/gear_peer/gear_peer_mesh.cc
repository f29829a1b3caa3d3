// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// A helper of benchmarks/gear_peer/run.sh: builds the polygon mesh of one
// body from a parameter file that holds a single section 'Mesh' (the same
// entries as a body's 'Mesh' section of the program dealvem, e.g. Type =
// spur gear with its subsection 'Gear') through the program's own
// MeshParameters::create_mesh(), and writes it as legacy VTK with its
// boundary ids (MeshIO::write_vtk, 17 digits). The contact run of dealvem and
// the GetFEM script then both read this file, so that the two codes see the
// same vertices, cells and boundary edges.
//
//   benchmark_gear_peer_mesh body.prm body.vtk

#include <dealvem/app/mesh_parameters.h>
#include <dealvem/mesh/mesh_io.h>
#include <dealvem/mesh/polygonal_mesh.h>

#include <deal.II/base/parameter_handler.h>

#include <exception>
#include <iostream>
#include <string>

int
main(int argc, char **argv)
{
  if (argc != 3)
    {
      std::cerr << "usage: " << argv[0] << " mesh.prm out.vtk" << std::endl;
      return 2;
    }
  try
    {
      const std::string input = argv[1];
      const auto        slash = input.find_last_of('/');
      const std::string dir   = (slash == std::string::npos ? std::string() : input.substr(0, slash));

      dealii::ParameterHandler prm;
      prm.enter_subsection("Mesh");
      dealvem::MeshParameters::declare_parameters(prm);
      prm.leave_subsection();
      prm.parse_input(input);

      dealvem::MeshParameters parameters;
      prm.enter_subsection("Mesh");
      parameters.parse_parameters(prm, "Mesh");
      prm.leave_subsection();

      dealvem::PolygonalMesh<2> mesh;
      parameters.create_mesh(mesh, 0, dir);
      dealvem::MeshIO::write_vtk(mesh, argv[2]);

      unsigned int n_boundary = 0;
      for (const auto &e : mesh.get_edges())
        if (e.at_boundary())
          ++n_boundary;
      std::cout << argv[2] << ": " << mesh.n_cells() << " cells, " << mesh.n_vertices() << " vertices, "
                << n_boundary << " boundary edges (" << parameters.description() << ")" << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cerr << "gear_peer_mesh: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
