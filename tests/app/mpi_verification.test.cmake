# The verification and the per-piece support under mpirun -np 2 (the
# distributed paths), on the inputs of the bad-input corpus:
# - 41 (one body, a VTK mesh with a second, unheld square), 43 (a vertex
#   hinge), 44 (a floating piece in a contact body): refused with the piece
#   named, as on one process;
# - 45 (stiffness ratio 1e12 between two bodies): refused by the
#   verification (the balance check, or the residual check of the KLU
#   solve), never exit 0;
# - tests/app/mpi-contact.prm: the JSON of np = 2 records the verification
#   (largest relative imbalance and residual below 1e-9).
# Each refusal exits with a code != 0 (every process names the error and the
# job is aborted, as app/dealvem.cc does for every error under MPI).
execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE)
set(mpi_flags --oversubscribe)
if(uid STREQUAL "0")
  list(APPEND mpi_flags --allow-run-as-root)
endif()
set(bad ${SOURCE_DIR}/tests/bad_input)

function(refused name prm regex)
  set(dir ${WORK_DIR}/${name})
  file(REMOVE_RECURSE ${dir})
  file(MAKE_DIRECTORY ${dir})
  execute_process(COMMAND ${MPIEXEC} ${MPIEXEC_NUMPROC_FLAG} 2 ${mpi_flags} ${DEALVEM} ${prm}
    WORKING_DIRECTORY ${dir} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  set(all "${out}${err}")
  string(REGEX REPLACE "[ \t\r\n]+" " " flat "${all}")
  if(rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${name}: exit code 0 under mpirun -np 2\n${all}")
  endif()
  if(NOT flat MATCHES "${regex}")
    message(FATAL_ERROR "FAIL ${name}: exit code ${rc} but the output does not match '${regex}'\n${all}")
  endif()
  foreach(sig "Segmentation fault" "terminate called" "unknown exception")
    string(FIND "${all}" "${sig}" pos)
    if(NOT pos EQUAL -1)
      message(FATAL_ERROR "FAIL ${name}: crash output '${sig}'\n${all}")
    endif()
  endforeach()
  message(STATUS "PASS ${name}: refused under mpirun -np 2 (exit ${rc})")
endfunction()

refused(piece_vtk ${bad}/41-vtk-disconnected-piece.prm
  "piece 1 of body 0 \\(1 cell; cell 1, centroid \\(2.5, 0.5\\); bounding box \\[2, 3\\] x \\[0, 1\\]\\)")
refused(hinge ${bad}/43-vertex-hinge.prm "\\[rotation of piece 1\\]")
refused(floating_piece ${bad}/44-floating-piece-in-contact-body.prm "rotation of body 1, piece 1\\]")
refused(ratio_1e12 ${bad}/45-stiffness-ratio-1e12.prm "(Verification failed after the solve of|is inaccurate)")

# a correct run records its verification in the JSON summary
set(dir ${WORK_DIR}/contact)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
file(READ ${SOURCE_DIR}/tests/app/mpi-contact.prm text)
file(WRITE ${dir}/input.prm "${text}")
execute_process(COMMAND ${MPIEXEC} ${MPIEXEC_NUMPROC_FLAG} 2 ${mpi_flags} ${DEALVEM} input.prm
  WORKING_DIRECTORY ${dir} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "FAIL contact np2: exit code ${rc}\n${out}${err}")
endif()
file(READ ${dir}/output/contact.json json)
foreach(key max_relative_imbalance max_relative_residual)
  string(JSON v GET "${json}" verification ${key})
  # below 1e-9: a mantissa and an exponent of -10 or less
  if(NOT v MATCHES "e-([1-9][0-9]+)$" OR CMAKE_MATCH_1 LESS 10)
    if(NOT v STREQUAL "0")
      message(FATAL_ERROR "FAIL contact np2: verification ${key} = ${v} (expected below 1e-9)")
    endif()
  endif()
  message(STATUS "PASS contact np2: verification ${key} = ${v}")
endforeach()
