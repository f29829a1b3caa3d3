# Size estimates for file meshes (issue 19, classes 9 and 14): files with
# 1e6 cells (legacy VTK, gmsh 2.2 and 4.1), generated here, are refused from
# the counts in their header, before their body is read (the points and
# cells written below are not even a valid mesh), with the estimate, the
# file, its counts, the limit and the parameters that change it; quickly
# (they used to end in std::bad_alloc after 12-17 s). A header that declares
# 1e6 cells on a truncated file is refused as truncated. 'Memory limit'
# fixes the limit so that the test does not depend on the machine.
set(n 1000000)
function(write_repeated file head line count tail)
  string(REPEAT "${line}" ${count} body)
  file(WRITE ${file} "${head}${body}${tail}")
endfunction()
write_repeated(${WORK_DIR}/big.vtk
  "# vtk DataFile Version 3.0\nbig\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS ${n} double\n" "0 0 0\n" ${n} "")
string(REPEAT "4 0 1 2 3\n" ${n} cells)
file(APPEND ${WORK_DIR}/big.vtk "CELLS ${n} 5000000\n${cells}")
write_repeated(${WORK_DIR}/big22.msh "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n${n}\n" "1 0 0 0\n" ${n} "$EndNodes\n")
string(REPEAT "1 3 2 7 1 1 2 3 4\n" ${n} elements)
file(APPEND ${WORK_DIR}/big22.msh "$Elements\n${n}\n${elements}$EndElements\n")
write_repeated(${WORK_DIR}/big41.msh
  "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 7 0\n$EndEntities\n$Nodes\n1 ${n} 1 ${n}\n2 1 0 ${n}\n"
  "1\n" ${n} "")
string(REPEAT "0 0 0\n" ${n} coordinates)
string(REPEAT "1 1 2 3 4\n" ${n} elements)
file(APPEND ${WORK_DIR}/big41.msh "${coordinates}$EndNodes\n$Elements\n1 ${n} 1 ${n}\n2 1 3 ${n}\n${elements}$EndElements\n")
# a header of 1e6 points with 3 of them: truncated
file(WRITE ${WORK_DIR}/truncated.vtk
  "# vtk DataFile Version 3.0\nbig\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS ${n} double\n0 0 0\n1 0 0\n0 1 0\n")

function(refuse name type file solver fragments)
  file(WRITE ${WORK_DIR}/${name}.prm "set Memory limit = 4
subsection Mesh
  set Type      = ${type}
  set File name = ${file}
end
subsection Solver
  set Type = ${solver}
end
subsection Boundary conditions and loads
  set Dirichlet = 0 : xy : 0, 0
end
")
  string(TIMESTAMP t0 "%s")
  execute_process(COMMAND ${DEALVEM} ${WORK_DIR}/${name}.prm WORKING_DIRECTORY ${WORK_DIR}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
  string(TIMESTAMP t1 "%s")
  math(EXPR seconds "${t1} - ${t0}")
  set(all "${out}${err}")
  string(REGEX REPLACE "[ \t\r\n]+" " " flat "${all}")
  if(rc EQUAL 0 OR NOT rc MATCHES "^[0-9]+$")
    message(FATAL_ERROR "FAIL ${name}: exit code ${rc}\n${all}")
  endif()
  foreach(f ${fragments})
    string(FIND "${flat}" "${f}" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "FAIL ${name}: the message lacks '${f}'\n${all}")
    endif()
  endforeach()
  foreach(sig "bad_alloc" "terminate called" "Segmentation fault")
    string(FIND "${all}" "${sig}" pos)
    if(NOT pos EQUAL -1)
      message(FATAL_ERROR "FAIL ${name}: '${sig}'\n${all}")
    endif()
  endforeach()
  if(seconds GREATER 20)
    message(FATAL_ERROR "FAIL ${name}: the refusal took ${seconds} s")
  endif()
  message(STATUS "PASS ${name} (${seconds} s)")
endfunction()

set(limit "more than the limit of 4 GB (the parameter 'Memory limit')" "set 'Allow large runs = true'")
refuse(vtk_automatic "vtk file" big.vtk automatic
  "This run is very large: about;big.vtk' (line 5: 1000000 points, 1000000 cells);8e+06 DoFs;CG and AMG or the p-multigrid;${limit}")
refuse(vtk_umfpack "vtk file" big.vtk UMFPACK
  "big.vtk' (line 5: 1000000 points, 1000000 cells);a direct factorization ('Solver/Type' = UMFPACK or KLU);${limit}")
refuse(gmsh22 "gridin file" big22.msh automatic
  "big22.msh' (line 5: 1000000 nodes, 1000000 elements);${limit}")
refuse(gmsh41 "gridin file" big41.msh automatic
  "big41.msh' (line 9: 1000000 nodes, 1000000 elements);${limit}")
refuse(truncated "vtk file" truncated.vtk automatic
  "truncated.vtk:5: the number of points is 1000000, but the file has only")
