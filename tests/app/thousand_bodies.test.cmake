# 1021 bodies from a parameter file (issue 21): examples/parameters/
# assembly-wall-1000.geo is meshed by gmsh, as a user would, and
# assembly-wall-1000.prm run by the program: a wall of 1020 blocks in
# running bond on a base, a body per physical surface ('Parts as bodies'),
# the joints found by 'Pairs = auto', the blocks held only by contact.
# thousand_bodies_check.py then checks the resultants CSV against statics:
# 2955 interfaces (25 on the base, 50 x 39 bed joints between courses,
# 20 x 24 + 20 x 25 head joints), the base carrying the weight 500 and the
# bed joints on every course the weight of the courses above (1e-9 of the
# weight), and no net horizontal force on any course's bed joints. Then the
# same wall with Coulomb friction (mu = 0.6): the same statics, and
# |tau| <= mu p at every closed pair (1e-10); about 1950 pairs where a head
# joint ends on a bed joint repeat two others and stay open
# (NodeInsertion::mark_junctions(); before, the friction iteration cycled).
find_program(GMSH gmsh)
if(NOT GMSH)
  message(FATAL_ERROR "FAIL: this test needs gmsh (apt-get install gmsh; scripts/setup.sh installs it)")
endif()
find_program(PYTHON3 python3)
if(NOT PYTHON3)
  message(FATAL_ERROR "FAIL: this test needs python3 (scripts/setup.sh installs it)")
endif()
set(EXAMPLES ${SOURCE_DIR}/examples/parameters)
file(REMOVE_RECURSE ${WORK_DIR}/output)
file(COPY ${EXAMPLES}/assembly-wall-1000.prm DESTINATION ${WORK_DIR})
execute_process(COMMAND ${GMSH} -2 -format msh2 ${EXAMPLES}/assembly-wall-1000.geo -o ${WORK_DIR}/assembly-wall-1000.msh
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR err MATCHES "Error")
  message(FATAL_ERROR "FAIL: gmsh could not mesh assembly-wall-1000.geo (exit ${rc}):\n${out}\n${err}")
endif()
string(TIMESTAMP start "%s")
execute_process(COMMAND ${DEALVEM} assembly-wall-1000.prm WORKING_DIRECTORY ${WORK_DIR}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(TIMESTAMP stop "%s")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "FAIL: dealvem assembly-wall-1000.prm exited with ${rc}:\n${out}\n${err}")
endif()
foreach(expected "1021 parts of 'assembly-wall-1000.msh' are bodies 0 to 1020" "2955 contact interface\\(s\\) detected"
    "every body in equilibrium")
  if(NOT out MATCHES "${expected}")
    message(FATAL_ERROR "FAIL: the output lacks '${expected}':\n${out}")
  endif()
endforeach()
math(EXPR seconds "${stop} - ${start}")
message(STATUS "dealvem assembly-wall-1000.prm: 1021 bodies in about ${seconds} s")
execute_process(COMMAND ${PYTHON3} ${TEST_DIR}/thousand_bodies_check.py ${WORK_DIR}/output/assembly-wall-1000-resultants.csv
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "FAIL: the statics of the wall")
endif()

# Coulomb friction
file(READ ${WORK_DIR}/assembly-wall-1000.prm prm)
string(REPLACE "set Tangential = multipliers" "set Tangential = coulomb\n  set Friction coefficient = 0.6" prm "${prm}")
string(REPLACE "set Base name      = assembly-wall-1000" "set Base name      = coulomb" prm "${prm}")
file(WRITE ${WORK_DIR}/coulomb.prm "${prm}")
execute_process(COMMAND ${DEALVEM} coulomb.prm WORKING_DIRECTORY ${WORK_DIR}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "FAIL: dealvem coulomb.prm (the wall with mu = 0.6) exited with ${rc}:\n${out}\n${err}")
endif()
string(REGEX MATCH "load step 1 of 1[^\n]*" step "${out}")
string(REGEX MATCH "\\(([0-9]+) where three bodies meet" junctions "${out}")
message(STATUS "Coulomb, mu = 0.6: ${step}; junction pairs: ${CMAKE_MATCH_1}")
if(NOT CMAKE_MATCH_1 GREATER 1000)
  message(FATAL_ERROR "FAIL: the wall's head joints end on bed joints about 1950 times; reported: '${junctions}'")
endif()
execute_process(COMMAND ${PYTHON3} ${TEST_DIR}/thousand_bodies_check.py ${WORK_DIR}/output/coulomb-resultants.csv
  ${WORK_DIR}/output/coulomb-interface.csv 0.6
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "FAIL: the statics of the wall with Coulomb friction")
endif()
