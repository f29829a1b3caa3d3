# Runs the program `dealvem` on parameter files that name malformed mesh
# files: each run must exit non-zero, quickly, with a message naming the
# file and line (no crash, hang or huge allocation).
function(bad_mesh name type file fragment text)
  file(WRITE ${WORK_DIR}/${file} "${text}")
  file(WRITE ${WORK_DIR}/${name}.prm "subsection Mesh\n  set Type = ${type}\n  set File name = ${file}\nend\n"
             "subsection Boundary conditions and loads\n  set Dirichlet = 0 : xy : 0, 0\nend\n")
  execute_process(COMMAND ${DEALVEM} ${WORK_DIR}/${name}.prm WORKING_DIRECTORY ${WORK_DIR}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  set(all "${out}${err}")
  # deal.II breaks the text of an error message into lines
  string(REGEX REPLACE "[ \t\r\n]+" " " all_flat "${all}")
  string(REGEX REPLACE "[ \t\r\n]+" " " fragment "${fragment}")
  if(rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${name}: succeeded but should fail\n${all}")
  endif()
  if(NOT rc MATCHES "^[0-9]+$")
    message(FATAL_ERROR "FAIL ${name}: the program did not exit normally (${rc})\n${all}")
  endif()
  string(FIND "${all_flat}" "${fragment}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "FAIL ${name}: output lacks '${fragment}'\n${all}")
  endif()
  message(STATUS "PASS ${name}")
endfunction()

set(vtk_head "# vtk DataFile Version 3.0\ntest\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n")
bad_mesh(vtk_2e8_cells "vtk file" cells.vtk "cells.vtk:10: the number of cells is 200000000, but the file has only"
         "${vtk_head}CELLS 200000000 800000000\n4 0 1 2 3\nCELL_TYPES 1\n7\n")
bad_mesh(vtk_no_cell_data "vtk file" no_data.vtk "no_data.vtk:15: the file has 1 line cells (boundary edges), but no CELL_DATA field boundary_id"
         "${vtk_head}CELLS 2 8\n4 0 1 2 3\n2 0 1\nCELL_TYPES 2\n7\n3\n")

set(msh_nodes "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 2 0 0\n4 0 1 0\n5 1 1 0\n6 2 1 0\n$EndNodes\n")
set(msh_elements "$Elements\n2\n1 3 2 7 1 1 2 5 4\n2 3 2 7 1 2 3 6 5\n$EndElements\n")
bad_mesh(gmsh_version "gridin file" version.msh "version.msh:5: expected 'numEntityBlocks numNodes minNodeTag maxNodeTag' after $Nodes"
         "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n${msh_nodes}${msh_elements}")
bad_mesh(gmsh_binary "gridin file" binary.msh "binary.msh:3: expected the endianness marker of a binary file"
         "$MeshFormat\n2.2 1 8\n$EndMeshFormat\n${msh_nodes}${msh_elements}")
bad_mesh(gmsh_nodes "gridin file" nodes.msh "nodes.msh:5: the number of nodes is 100000000000, but the file has only"
         "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n100000000000\n1 0 0 0\n$EndNodes\n${msh_elements}")
bad_mesh(gmsh_physical "gridin file" physical.msh "physical.msh:15: the physical tag of element 1 of 2 is '4294967295'"
         "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n${msh_nodes}$Elements\n2\n1 3 2 4294967295 1 1 2 5 4\n2 3 2 7 1 2 3 6 5\n$EndElements\n")
