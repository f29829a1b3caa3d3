# One bad command line of a tutorial program: run PROGRAM with the arguments
# ARGS (separated by '+') and require the exit code 2 (the usage exit),
# the fragment EXPECT in the output and the usage line, within 20 s (a wrapped
# cycle count used to make step-5 run for ever). Called by
# tests/CMakeLists.txt with -DPROGRAM=... -DARGS=... -DEXPECT=... -P.
string(REPLACE "+" ";" ARGS "${ARGS}")
execute_process(COMMAND ${PROGRAM} ${ARGS} TIMEOUT 20
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(NOT rc STREQUAL "2")
  message(FATAL_ERROR "FAIL: '${PROGRAM} ${ARGS}' ended with '${rc}', expected the usage exit code 2\n${all}")
endif()
foreach(fragment "${EXPECT}" "usage: ")
  string(FIND "${all}" "${fragment}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "FAIL: the output of '${PROGRAM} ${ARGS}' lacks '${fragment}'\n${all}")
  endif()
endforeach()
message(STATUS "PASS: '${ARGS}' refused with: ${err}")
