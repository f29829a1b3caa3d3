# find_package(dealvem) from a separate CMake project against the build tree.
file(REMOVE_RECURSE ${WORK_DIR}/build)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${TEST_DIR}/downstream -B ${WORK_DIR}/build
    -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE} -Ddealvem_DIR=${BINARY_DIR}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "FAIL configure:\n${out}${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "FAIL build:\n${out}${err}")
endif()
execute_process(COMMAND ${WORK_DIR}/build/downstream RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${out}" "downstream: 20 cells" pos)
if(NOT rc EQUAL 0 OR pos EQUAL -1)
  message(FATAL_ERROR "FAIL run: ${rc}\n${out}${err}")
endif()
message(STATUS "PASS ${out}")
