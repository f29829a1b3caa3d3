# The same test under mpirun (the distributed contact solves then have pairs cut by the partition) with two processes (oversubscribed: CI has two
# cores shared with other jobs; as root, Open MPI needs --allow-run-as-root).
execute_process(COMMAND id -u OUTPUT_VARIABLE _uid OUTPUT_STRIP_TRAILING_WHITESPACE)
set(_mpi_flags --oversubscribe)
if(_uid STREQUAL "0")
  list(APPEND _mpi_flags --allow-run-as-root)
endif()
add_test(NAME ${_test}-np2
  COMMAND ${DEAL_II_MPIEXEC} ${DEAL_II_MPIEXEC_NUMPROC_FLAG} 2 ${_mpi_flags} $<TARGET_FILE:${_target}>
  WORKING_DIRECTORY ${_workdir})
set_tests_properties(${_test}-np2 PROPERTIES LABELS "${_module};mpi" TIMEOUT 300
  ENVIRONMENT "DEALVEM_SOURCE_DIR=${CMAKE_SOURCE_DIR};DEALVEM_BINARY_DIR=${CMAKE_BINARY_DIR};OMP_NUM_THREADS=1")
