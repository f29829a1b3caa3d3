# 'Solver/Type = automatic' (the default) for one body prints its choice and
# the reason (issue 19, class 14): UMFPACK on a small mesh, CG-AMG (with the
# p-multigrid at k = 2) above the threshold of 1e4 DoFs (the measured
# crossover, doc/benchmarks.md). The refinement cycles of one run cross it:
# 20 x 20 quads (3362 DoFs) and 40 x 40 (13122 DoFs). An explicit type is
# used as given, silently.
function(run name prm)
  file(WRITE ${WORK_DIR}/${name}.prm "${prm}")
  execute_process(COMMAND ${DEALVEM} ${WORK_DIR}/${name}.prm WORKING_DIRECTORY ${WORK_DIR}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${name}: exit code ${rc}\n${out}${err}")
  endif()
  string(REGEX REPLACE "[ \t\r\n]+" " " flat "${out}${err}")
  set(output "${flat}" PARENT_SCOPE)
endfunction()
function(expect name text fragment)
  string(FIND "${text}" "${fragment}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "FAIL ${name}: the output lacks '${fragment}'\n${text}")
  endif()
endfunction()

set(base "subsection Mesh
  set Type         = structured quads
  set Subdivisions = 20, 20
end
subsection Boundary conditions and loads
  set Dirichlet = 0 : xy : 0, 0
  set Traction  = 1 : 0, -1
end
subsection Output
  set Write VTU = false
end
")
run(automatic "${base}subsection Convergence study\n  set Refinement cycles = 2\nend\n")
expect(automatic "${output}" "solver (Solver/Type = automatic): UMFPACK, 3.36e+03 DoFs <= 1e+04: a direct factorization")
expect(automatic "${output}" "Cycle 0: 400 cells, 3362 DoFs, h = 0.0707107, solver UMFPACK")
expect(automatic "${output}" "solver (Solver/Type = automatic): CG-AMG, 1.31e+04 DoFs > 1e+04: above this size CG with the p-multigrid is faster")
expect(automatic "${output}" "Cycle 1: 1600 cells, 13122 DoFs")
message(STATUS "PASS automatic: UMFPACK below, CG-AMG above the crossover, printed with the reason")

run(explicit "${base}subsection Solver\n  set Type = UMFPACK\nend\n")
string(FIND "${output}" "Solver/Type = automatic" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "FAIL explicit: an automatic choice is printed for Solver/Type = UMFPACK\n${output}")
endif()
message(STATUS "PASS explicit: no automatic choice")
