# The program on a gmsh file: a binary MSH 4.1 mesh of triangles and
# quadrangles whose boundaries and material the parameter file names by
# their physical names (tests/app/gmsh/mixed-block.prm). Uniform tension
# must be exact on the file mesh and its native refinements; a name the
# file does not have and a material id it does not have are refused with
# the names and ids of the file. A contact patch test names its pair by a
# physical name (tests/app/gmsh/stacked.prm).
include(${TEST_DIR}/program_checks.cmake)

file(REMOVE_RECURSE ${WORK_DIR}/output)
run_dealvem("mixed gmsh patch test" TRUE "Summary written to" ${TEST_DIR}/gmsh/mixed-block.prm)
file(READ ${WORK_DIR}/output/mixed-block.json json)
string(JSON n_cycles LENGTH "${json}" cycles)
if(NOT n_cycles EQUAL 3)
  message(FATAL_ERROR "FAIL mixed gmsh patch test: ${n_cycles} cycles in the JSON, expected 3")
endif()
math(EXPR last "${n_cycles} - 1")
foreach(c RANGE ${last})
  string(JSON dofs GET "${json}" cycles ${c} dofs)
  string(JSON l2 GET "${json}" cycles ${c} errors L2)
  string(JSON h1 GET "${json}" cycles ${c} errors H1_seminorm)
  string(JSON vm GET "${json}" cycles ${c} max_von_mises)
  is_roundoff("${l2}" l2_ok)
  is_roundoff("${h1}" h1_ok)
  if(NOT l2_ok OR NOT h1_ok)
    message(FATAL_ERROR "FAIL mixed gmsh patch test: cycle ${c}: L2 error ${l2}, H1 error ${h1} (uniform tension must be exact)")
  endif()
  # the stress is the uniform tension sigma_xx = 10: the largest von Mises
  # stress is 10 to 1e-10
  if(NOT vm MATCHES "^(10(\\.0000000000[0-9]*)?|9\\.9999999999[0-9]*)$")
    message(FATAL_ERROR "FAIL mixed gmsh patch test: cycle ${c}: largest von Mises stress ${vm}, expected 10 to 1e-10")
  endif()
  message(STATUS "cycle ${c}: ${dofs} DoFs, L2 error ${l2}, H1 error ${h1}, largest von Mises stress ${vm}")
endforeach()
string(JSON dofs0 GET "${json}" cycles 0 dofs)
string(JSON dofs2 GET "${json}" cycles 2 dofs)
if(NOT dofs2 GREATER dofs0)
  message(FATAL_ERROR "FAIL mixed gmsh patch test: the refined cycles have ${dofs2} DoFs, the file mesh ${dofs0}")
endif()
message(STATUS "PASS mixed gmsh patch test")

# by number, the same file works as well
file(READ ${TEST_DIR}/gmsh/mixed-block.prm prm)
string(REPLACE "clamped : xy" "3 : xy" prm_numbers "${prm}")
string(REPLACE "loaded : 10, 0; bottom" "5 : 10, 0; 7" prm_numbers "${prm_numbers}")
string(REPLACE "Material id = block" "Material id = 1" prm_numbers "${prm_numbers}")
string(REPLACE "Refinement cycles = 3" "Refinement cycles = 1" prm_numbers "${prm_numbers}")
string(REPLACE "mixed-block.msh" "${TEST_DIR}/gmsh/mixed-block.msh" prm_numbers "${prm_numbers}")
file(WRITE ${WORK_DIR}/numbers.prm "${prm_numbers}")
run_dealvem("ids by number" TRUE "Summary written to" ${WORK_DIR}/numbers.prm)
file(READ ${WORK_DIR}/output/mixed-block.json json)
string(JSON l2 GET "${json}" cycles 0 errors L2)
is_roundoff("${l2}" l2_ok)
if(NOT l2_ok)
  message(FATAL_ERROR "FAIL ids by number: L2 error ${l2}")
endif()
message(STATUS "PASS ids by number: L2 error ${l2}")

# a name the file does not have: the names of the file are listed
string(REPLACE "clamped : xy" "fixed : xy" prm_bad "${prm}")
string(REPLACE "mixed-block.msh" "${TEST_DIR}/gmsh/mixed-block.msh" prm_bad "${prm_bad}")
file(WRITE ${WORK_DIR}/bad_name.prm "${prm_bad}")
run_dealvem("unknown name" FALSE
  "'fixed' is neither a boundary id (a non-negative integer) nor a physical name of the mesh file(s) for a boundary id. The physical names are: boundaries (dimension 1): 'bottom' = 7, 'clamped' = 3, 'loaded' = 5; surfaces (dimension 2): 'block' = 1"
  ${WORK_DIR}/bad_name.prm)
message(STATUS "PASS unknown name")

# the material id the file does not have: its ids and names are listed
string(REPLACE "Material id = 1" "Material id = 0" prm_bad "${prm_numbers}")
file(WRITE ${WORK_DIR}/bad_id.prm "${prm_bad}")
run_dealvem("material id mismatch" FALSE
  "has material id 1 ('block'), but the parameter file defines a material for id 0 only ('Mesh/Material id'). The material ids of the mesh are 1 ('block')."
  ${WORK_DIR}/bad_id.prm)
message(STATUS "PASS material id mismatch")

# contact: the gmsh body's 'bottom' curve named in 'Contact/Pairs' (its id
# 7 + the offset 10); uniform pressure gives sigma_yy = -10 in both bodies
run_dealvem("contact pair by name" TRUE "sigma_yy in [-10, -10]" ${TEST_DIR}/gmsh/stacked.prm)
string(REGEX MATCH "sigma_xy in \\[([^,]*), ([^]]*)\\]" xy "${LAST_OUTPUT}")
foreach(v "${CMAKE_MATCH_1}" "${CMAKE_MATCH_2}")
  is_roundoff("${v}" ok)
  if(NOT ok)
    message(FATAL_ERROR "FAIL contact pair by name: sigma_xy ${v}, expected 0 (uniform compression)")
  endif()
endforeach()

# two bodies from one file with an offset: the names mean two ids and
# cannot be used (numbers can); the message says why
file(READ ${TEST_DIR}/gmsh/stacked.prm prm)
string(REPLACE "structured quads" "gridin file\n  set File name = ${TEST_DIR}/gmsh/mixed-block.msh" prm2 "${prm}")
string(REPLACE "File name          = mixed-block.msh" "File name = ${TEST_DIR}/gmsh/mixed-block.msh" prm2 "${prm2}")
file(WRITE ${WORK_DIR}/same_file.prm "${prm2}")
run_dealvem("ambiguous name" FALSE
  "'bottom' cannot be used: it is boundary id 7 in '${TEST_DIR}/gmsh/mixed-block.msh' and 17 in"
  ${WORK_DIR}/same_file.prm)

# a boundary id no edge carries: the ids of the mesh with their names
string(REPLACE "5 : 10, 0; 7" "9 : 10, 0; 7" prm_bad "${prm_numbers}")
file(WRITE ${WORK_DIR}/bad_boundary.prm "${prm_bad}")
run_dealvem("boundary id mismatch" FALSE
  "has boundary id 9; the boundary ids of the mesh are 0, 3 ('clamped'), 5 ('loaded'), 7 ('bottom'). Name one of these ids (or its physical name)"
  ${WORK_DIR}/bad_boundary.prm)
