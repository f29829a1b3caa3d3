# Runs the program `dealvem` as a user would:
# - --print-parameters lists the sections;
# - a good single-body file (tests/app/cantilever.prm: uniform tension, so
#   the errors must be at round-off) and the contact patch test of
#   examples/step-2 run and write their files;
# - bad input exits non-zero with a message naming the problem.
function(run_dealvem name expect_success fragment)
  execute_process(COMMAND ${DEALVEM} ${ARGN} WORKING_DIRECTORY ${WORK_DIR}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(all "${out}${err}")
  if(expect_success AND NOT rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${name}: exit code ${rc}\n${all}")
  endif()
  if(NOT expect_success AND rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${name}: succeeded but should fail\n${all}")
  endif()
  string(FIND "${all}" "${fragment}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "FAIL ${name}: output lacks '${fragment}'\n${all}")
  endif()
  message(STATUS "PASS ${name}")
  set(LAST_OUTPUT "${all}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR}/output)
run_dealvem("print parameters" TRUE "subsection Contact" --print-parameters)
foreach(section "subsection Mesh" "subsection Material" "subsection Solver" "Young's modulus")
  string(FIND "${LAST_OUTPUT}" "${section}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "FAIL print parameters: no '${section}'")
  endif()
endforeach()

# a good single-body run: uniform tension is reproduced exactly
run_dealvem("cantilever" TRUE "Summary written to" ${TEST_DIR}/cantilever.prm)
foreach(f output/solution-0.vtu output/solution-1.vtu output/solution.json)
  if(NOT EXISTS ${WORK_DIR}/${f})
    message(FATAL_ERROR "FAIL cantilever: ${f} was not written")
  endif()
endforeach()
file(READ ${WORK_DIR}/output/solution.json json)
string(JSON dofs GET "${json}" cycles 1 dofs)
string(JSON l2 GET "${json}" cycles 1 errors L2)
if(dofs LESS 100 OR l2 GREATER 1e-12)
  message(FATAL_ERROR "FAIL cantilever: dofs ${dofs}, L2 error ${l2} (uniform tension must be exact)")
endif()
message(STATUS "PASS cantilever JSON: ${dofs} DoFs, L2 error ${l2}")

# the contact patch test as a parameter file
run_dealvem("contact patch test" TRUE "sigma_yy in [-10, -10]" ${SOURCE_DIR}/examples/step-2/patch-test.prm)
foreach(f output/patch-test-interface.csv output/patch-test-stress.svg output/patch-test-pressure.svg
          output/patch-test.json output/patch-test.vtu)
  if(NOT EXISTS ${WORK_DIR}/${f})
    message(FATAL_ERROR "FAIL contact patch test: ${f} was not written")
  endif()
endforeach()
file(READ ${WORK_DIR}/output/patch-test.json json)
string(JSON pmin GET "${json}" contact pressure_min)
string(JSON pmax GET "${json}" contact pressure_max)
message(STATUS "PASS contact JSON: contact pressure in [${pmin}, ${pmax}]")

# bad input: each case a small parameter file
function(bad_case name fragment text)
  file(WRITE ${WORK_DIR}/${name}.prm "${text}")
  run_dealvem("bad input: ${name}" FALSE "${fragment}" ${WORK_DIR}/${name}.prm)
endfunction()
set(ok_bc "subsection Boundary conditions and loads\n  set Dirichlet = 0 : xy : 0, 0\nend\n")
bad_case(unknown_parameter "Colour" "set Colour = blue\n")
bad_case(poisson "Poisson's ratio" "subsection Material\n  set Poisson's ratio = 0.7\nend\n${ok_bc}")
bad_case(order "Order" "subsection Discretization\n  set Order = 3\nend\n${ok_bc}")
bad_case(dirichlet "Dirichlet entry" "subsection Boundary conditions and loads\n  set Dirichlet = 0 : z : 1\nend\n")
bad_case(missing_mesh "no-such-mesh.vtk" "subsection Mesh\n  set Type = vtk file\n  set File name = no-such-mesh.vtk\nend\n${ok_bc}")
file(WRITE ${WORK_DIR}/cw.vtk "# vtk DataFile Version 3.0\ncw\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 double\n0 0 0\n1 0 0\n0 1 0\nCELLS 1 4\n3 0 2 1\nCELL_TYPES 1\n7\n")
bad_case(clockwise_file "cw.vtk:10" "subsection Mesh\n  set Type = vtk file\n  set File name = cw.vtk\nend\n${ok_bc}")
bad_case(unsupported "Unsupported body" "subsection Boundary conditions and loads\n  set Traction = 1 : 1, 0\nend\n")
bad_case(expression "cannot parse" "subsection Boundary conditions and loads\n  set Dirichlet = 0 : xy : 0, sin(\nend\n")
run_dealvem("bad input: missing parameter file" FALSE "cannot open" ${WORK_DIR}/does-not-exist.prm)
