# The time t in load expressions through the program: the contact patch
# test on structured quads (3x3 below, 4x4 above, so no CGAL needed) with the
# pressure written as 5*t and two load steps to the final time 2. Step 1
# (t = 1) must carry the uniform contact pressure 5 at every pair, step 2
# (t = 2) the pressure 10, both to 1e-10 relative: the patch test is exact,
# so any other value means t did not reach the expression. The same file
# with 'Pressure = 13 : p' and p = 10 (no t, one step) gives 10 as well.
# The exact displacement, written with t as the load, is compared at the
# final time: the relative errors of the two-step run must be round-off
# (at t = 1 they would be 1).
function(run_case name)
  execute_process(COMMAND ${DEALVEM} ${ARGN} WORKING_DIRECTORY ${WORK_DIR}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${name}: exit code ${rc}\n${out}${err}")
  endif()
endfunction()

# every value of column 'pressure' of an interface CSV file within 1e-10 of
# the expected one (relative)
function(check_csv_pressure file expected)
  file(STRINGS ${file} lines)
  list(GET lines 0 header)
  string(REPLACE "," ";" header "${header}")
  list(FIND header "pressure" col)
  if(col EQUAL -1)
    message(FATAL_ERROR "FAIL ${file}: no column 'pressure' in '${header}'")
  endif()
  list(REMOVE_AT lines 0)
  list(LENGTH lines n)
  if(n LESS 5)
    message(FATAL_ERROR "FAIL ${file}: only ${n} pairs")
  endif()
  foreach(line ${lines})
    string(REPLACE "," ";" fields "${line}")
    list(GET fields ${col} p)
    # |p - expected| <= 1e-10 expected, in CMake's floating point
    if(p LESS_EQUAL 0)
      message(FATAL_ERROR "FAIL ${file}: pressure ${p}, expected ${expected}")
    endif()
    string(REGEX MATCH "^-?[0-9.]+(e[-+]?[0-9]+)?$" ok "${p}")
    if(NOT ok)
      message(FATAL_ERROR "FAIL ${file}: pressure '${p}' is not a number")
    endif()
    if(p LESS ${LOW_${expected}} OR p GREATER ${HIGH_${expected}})
      message(FATAL_ERROR "FAIL ${file}: pressure ${p} is not ${expected} to 1e-10")
    endif()
  endforeach()
  message(STATUS "PASS ${file}: ${n} pairs, pressure ${expected} to 1e-10")
endfunction()
set(LOW_5 4.9999999995)
set(HIGH_5 5.0000000005)
set(LOW_10 9.999999999)
set(HIGH_10 10.000000001)

set(prm "set Number of bodies = 2
subsection Mesh
  set Type = structured quads
  set Subdivisions = 3, 3
end
subsection Material
  set Young's modulus = 7000
  set Poisson's ratio = 0.3
end
subsection Body 1
  subsection Mesh
    set Type = structured quads
    set Lower left corner = 0, 1
    set Upper right corner = 1, 2
    set Subdivisions = 4, 4
    set Boundary id offset = 10
  end
  subsection Material
    set Young's modulus = 7000
    set Poisson's ratio = 0.3
  end
end
subsection Discretization
  set Order = 2
end
subsection Contact
  set Pairs = 3 : 12
  set Normal = unilateral
end
subsection Boundary conditions and loads
  set Function constants = p=10
  set Dirichlet = 2 : y : 0
  set Point constraints = 0, 0 : x : 0
  @PRESSURE@
end
@STEPS@
subsection Exact solution
  set Displacement = 0.3*1.3*5*t/7000*x, -0.91*5*t/7000*y
end
subsection Output
  set Folder = output
  set Base name = @BASE@
  set Write VTU = false
  set Write pictures = false
end
")
file(REMOVE_RECURSE ${WORK_DIR}/output)

# pressure 5*t, two steps to t = 2
set(PRESSURE "set Pressure = 13 : 5*t")
set(STEPS "subsection Load steps\n  set Number of steps = 2\n  set Final time = 2\nend")
set(BASE "steps")
string(CONFIGURE "${prm}" text @ONLY)
file(WRITE ${WORK_DIR}/steps.prm "${text}")
run_case("pressure 5*t in two load steps" ${WORK_DIR}/steps.prm)
check_csv_pressure(${WORK_DIR}/output/steps-step-001-interface.csv 5)
check_csv_pressure(${WORK_DIR}/output/steps-step-002-interface.csv 10)
file(READ ${WORK_DIR}/output/steps.json json)
string(JSON t2 GET "${json}" steps 2 time)
if(NOT t2 EQUAL 2)
  message(FATAL_ERROR "FAIL steps JSON: step 2 at t = ${t2}, not 2")
endif()
# the errors against the exact solution at t = 2
foreach(body body0 body1)
  foreach(norm L2 H1 energy)
    string(JSON err GET "${json}" errors ${body} ${norm})
    string(REGEX MATCH "^[0-9.]+e-(1[0-9]|[2-9][0-9])$" small "${err}")
    if(NOT small AND NOT err EQUAL 0)
      message(FATAL_ERROR "FAIL steps JSON: relative ${norm} error of ${body} = ${err} against the exact "
        "solution at the final time t = 2, expected round-off")
    endif()
  endforeach()
endforeach()
message(STATUS "PASS steps: the exact solution is evaluated at the final time")

# the spelling without t: p = 10, one step at t = 1
set(PRESSURE "set Pressure = 13 : p")
set(STEPS "")
set(BASE "static")
string(CONFIGURE "${prm}" text @ONLY)
file(WRITE ${WORK_DIR}/static.prm "${text}")
run_case("pressure p without t" ${WORK_DIR}/static.prm)
check_csv_pressure(${WORK_DIR}/output/static-interface.csv 10)

# the fuzz seeds of the friction, load-step and rigid-boundary inputs run
# as they are: every load step converges, and the JSON lists them all
foreach(seed friction-rigid-steps coulomb-penalty-steps)
  file(REMOVE_RECURSE ${WORK_DIR}/${seed})
  file(MAKE_DIRECTORY ${WORK_DIR}/${seed})
  execute_process(COMMAND ${DEALVEM} ${TEST_DIR}/${seed}.prm WORKING_DIRECTORY ${WORK_DIR}/${seed}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${seed}.prm: exit code ${rc}\n${out}${err}")
  endif()
  file(GLOB json ${WORK_DIR}/${seed}/output/*.json)
  file(READ ${json} text)
  string(JSON requested GET "${text}" load_steps requested)
  string(JSON converged GET "${text}" load_steps converged)
  if(NOT requested EQUAL converged OR requested LESS 2)
    message(FATAL_ERROR "FAIL ${seed}.prm: ${converged} of ${requested} load steps converged")
  endif()
  message(STATUS "PASS ${seed}.prm: ${converged} load steps")
endforeach()
