# Runs `dealvem` under mpirun as a user would (tests/app/mpi-voronoi.prm:
# Voronoi, k = 2, smooth exact solution, two cycles):
# - np = 1 (the serial path) and np = 2 (the distributed path) both succeed;
#   the L2, H1 and energy errors of both cycles in the two JSON summaries
#   agree to 1e-10 relative, and so do the DoF counts;
# - np = 2 writes <base>-cycle<c>.pvtu naming the pieces .0.vtu and .1.vtu,
#   both written, and the console output once (one "Summary written" line);
# - a contact problem (tests/app/mpi-contact.prm) with np = 1 (serial) and
#   np = 2 (distributed, contact pairs cut by the partition): the same
#   active sets, and pressures and contact force to 1e-10 relative.
# - a block moved rigidly onto its base (no force acts) passes the
#   verification with np = 2.
execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE)
set(mpi_flags --oversubscribe)
if(uid STREQUAL "0")
  list(APPEND mpi_flags --allow-run-as-root)
endif()

include(${TEST_DIR}/program_checks.cmake)

# the line @p text must appear once in @p output (process 0 alone prints)
function(check_printed_once text output what)
  string(REGEX MATCHALL "${text}" lines "${output}")
  list(LENGTH lines n_lines)
  if(NOT n_lines EQUAL 1)
    message(FATAL_ERROR "FAIL ${what}: '${text}' printed ${n_lines} times (process 0 alone prints)\n${output}")
  endif()
endfunction()

function(run_case name np expect_success folder prm)
  file(READ ${prm} text)
  string(REPLACE "set Folder = output" "set Folder = ${folder}" text "${text}")
  file(WRITE ${WORK_DIR}/${name}.prm "${text}")
  execute_process(COMMAND ${MPIEXEC} ${MPIEXEC_NUMPROC_FLAG} ${np} ${mpi_flags} ${DEALVEM} ${WORK_DIR}/${name}.prm
    WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(expect_success AND NOT rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${name}: exit code ${rc}\n${out}${err}")
  endif()
  if(NOT expect_success AND rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${name}: succeeded but should fail\n${out}${err}")
  endif()
  set(LAST_OUTPUT "${out}${err}" PARENT_SCOPE)
  message(STATUS "PASS ${name} runs (exit code ${rc})")
endfunction()

file(REMOVE_RECURSE ${WORK_DIR}/np1 ${WORK_DIR}/np2)
# the parameter file names no mesh file, so it may be copied to WORK_DIR
run_case(np1 1 TRUE np1 ${TEST_DIR}/mpi-voronoi.prm)
run_case(np2 2 TRUE np2 ${TEST_DIR}/mpi-voronoi.prm)
check_printed_once("Summary written to" "${LAST_OUTPUT}" np2)

file(READ ${WORK_DIR}/np1/solution.json json1)
file(READ ${WORK_DIR}/np2/solution.json json2)
foreach(cycle 0 1)
  string(JSON d1 GET "${json1}" cycles ${cycle} dofs)
  string(JSON d2 GET "${json2}" cycles ${cycle} dofs)
  string(JSON p2 GET "${json2}" cycles ${cycle} mpi_processes)
  if(NOT d1 EQUAL d2 OR NOT p2 EQUAL 2)
    message(FATAL_ERROR "FAIL cycle ${cycle}: ${d1} DoFs on np = 1, ${d2} on np = 2 (processes ${p2})")
  endif()
  foreach(norm L2 H1_seminorm energy)
    string(JSON e1 GET "${json1}" cycles ${cycle} errors ${norm})
    string(JSON e2 GET "${json2}" cycles ${cycle} errors ${norm})
    check_relative(${e1} ${e2} 10 "cycle ${cycle} ${norm} error, np = 1 against np = 2")
  endforeach()
  foreach(f np2/solution-cycle${cycle}.pvtu np2/solution-cycle${cycle}.0.vtu np2/solution-cycle${cycle}.1.vtu)
    if(NOT EXISTS ${WORK_DIR}/${f})
      message(FATAL_ERROR "FAIL np2: ${f} was not written")
    endif()
  endforeach()
  file(READ ${WORK_DIR}/np2/solution-cycle${cycle}.pvtu pvtu)
  foreach(p 0 1)
    string(FIND "${pvtu}" "<Piece Source=\"solution-cycle${cycle}.${p}.vtu\"/>" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "FAIL np2: the .pvtu of cycle ${cycle} does not name piece ${p}\n${pvtu}")
    endif()
  endforeach()
endforeach()
message(STATUS "PASS np = 1 and np = 2 agree; .pvtu and pieces written")

# contact: tests/app/mpi-contact.prm (parabola on a flat block, the active
# set changes over several iterations) with 'Solver/Type = direct
# constraints': np = 1 (serial, CHOLMOD on the condensed stiffness) and
# np = 2 (distributed: the condensed system factored by Amesos KLU); the
# partition must cut contact constraints
file(REMOVE_RECURSE ${WORK_DIR}/contact1 ${WORK_DIR}/contact2)
run_case(contact_np1 1 TRUE contact1 ${TEST_DIR}/mpi-contact.prm)
run_case(contact_np2 2 TRUE contact2 ${TEST_DIR}/mpi-contact.prm)
check_printed_once("summary: " "${LAST_OUTPUT}" "contact np2")
file(READ ${WORK_DIR}/contact1/contact.json json1)
file(READ ${WORK_DIR}/contact2/contact.json json2)
string(JSON p2 GET "${json2}" mpi processes)
string(JSON cut GET "${json2}" contact rows_across_processes)
if(NOT p2 EQUAL 2 OR NOT cut GREATER 0)
  message(FATAL_ERROR "FAIL contact np2: ${p2} processes, ${cut} contact rows cut by the partition")
endif()
message(STATUS "PASS contact np2: ${cut} contact constraint rows couple DoFs of the two processes")
foreach(key active_set_iterations active_pairs node_pairs)
  string(JSON a GET "${json1}" contact ${key})
  string(JSON b GET "${json2}" contact ${key})
  if(NOT a EQUAL b)
    message(FATAL_ERROR "FAIL contact ${key}: ${a} on np = 1, ${b} on np = 2")
  endif()
endforeach()
foreach(key pressure_min pressure_max total_force_y)
  string(JSON a GET "${json1}" contact ${key})
  string(JSON b GET "${json2}" contact ${key})
  check_relative(${a} ${b} 10 "contact ${key}, np = 1 against np = 2")
endforeach()
message(STATUS "PASS contact with np = 1 and np = 2 agree")

# a block moved rigidly onto its base (tests/app/rigid-move-tied.prm, issue
# 37 class 5): no force acts, and the distributed verification (its sums
# over the processes) must find the bodies in equilibrium, as the serial one
# does (tests/app/scales_and_domain)
run_case(rigid_np2 2 TRUE output-rigid ${TEST_DIR}/rigid-move-tied.prm)
string(FIND "${LAST_OUTPUT}" "verification: every body in equilibrium" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "FAIL rigid move np2: no verification line\n${LAST_OUTPUT}")
endif()
message(STATUS "PASS rigid move np2: verified")
