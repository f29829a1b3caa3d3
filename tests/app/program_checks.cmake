# Checks shared by the script tests of tests/app that run the program
# `dealvem` (included, not a test itself: its name does not end in
# .test.cmake).

# run_dealvem(name expect_success fragment args...): run ${DEALVEM} with
# args in WORK_DIR; fail unless it succeeds (or fails, as expected) cleanly
# and its output contains fragment (white space collapsed); the output is
# left in LAST_OUTPUT. A script that sets RUN_TIMEOUT (seconds) before the
# include stops each run after that time (a failure).
function(run_dealvem name expect_success fragment)
  set(timeout "")
  if(DEFINED RUN_TIMEOUT)
    set(timeout TIMEOUT ${RUN_TIMEOUT})
  endif()
  execute_process(COMMAND ${DEALVEM} ${ARGN} WORKING_DIRECTORY ${WORK_DIR}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err ${timeout})
  set(all "${out}${err}")
  # deal.II breaks the text of an error message into lines: compare with the
  # white space collapsed
  string(REGEX REPLACE "[ \t\r\n]+" " " all_flat "${all}")
  string(REGEX REPLACE "[ \t\r\n]+" " " fragment "${fragment}")
  if(expect_success AND NOT rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${name}: exit code ${rc}\n${all}")
  endif()
  if(NOT expect_success AND rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${name}: succeeded but should fail\n${all}")
  endif()
  # a rejection must be a clean one: no crash, no sanitizer report, no
  # uncaught exception (an exit code alone does not tell)
  if(NOT rc MATCHES "^[0-9]+$")
    message(FATAL_ERROR "FAIL ${name}: ended by '${rc}'\n${all}")
  endif()
  foreach(crash "Segmentation fault" "AddressSanitizer" "LeakSanitizer" "runtime error:"
                "terminate called" "unknown exception")
    string(FIND "${all}" "${crash}" crash_pos)
    if(NOT crash_pos EQUAL -1)
      message(FATAL_ERROR "FAIL ${name}: the output shows '${crash}'\n${all}")
    endif()
  endforeach()
  string(FIND "${all_flat}" "${fragment}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "FAIL ${name}: output lacks '${fragment}'\n${all}")
  endif()
  message(STATUS "PASS ${name}")
  set(LAST_OUTPUT "${all}" PARENT_SCOPE)
endfunction()

# is_roundoff(value result): result TRUE if the decimal number value is
# zero or below 1e-10 in magnitude (written with an exponent e-10 ... e-99,
# as the JSON summaries write such numbers)
function(is_roundoff value result)
  string(REGEX MATCH "^-?[0-9.]+e-(1[0-9]|[2-9][0-9])$" small "${value}")
  if(small OR value EQUAL 0)
    set(${result} TRUE PARENT_SCOPE)
  else()
    set(${result} FALSE PARENT_SCOPE)
  endif()
endfunction()

# CMake has integer arithmetic only: a decimal number "d.ddde-XX" (or
# "0.000ddd") becomes 16 significant digits as an integer and a decimal
# exponent, and |a - b| <= tol |a| is checked on the integers of equal
# exponent (tol = 10^-digits).
function(parse_decimal text out_mantissa out_exponent)
  string(TOLOWER "${text}" t)
  set(exp10 0)
  if(t MATCHES "^-?([0-9.]+)e([-+]?[0-9]+)$")
    set(t "${CMAKE_MATCH_1}")
    set(exp10 "${CMAKE_MATCH_2}")
    string(REGEX REPLACE "^\\+" "" exp10 "${exp10}")
  endif()
  string(REGEX REPLACE "^-" "" t "${t}")
  string(FIND "${t}" "." dot)
  if(dot EQUAL -1)
    string(LENGTH "${t}" dot)
  endif()
  string(REPLACE "." "" digits "${t}")
  # exponent of the first digit of `digits`: value = 0.digits * 10^(dot + exp10)
  math(EXPR e "${dot} + ${exp10}")
  while(digits MATCHES "^0[0-9]")
    string(SUBSTRING "${digits}" 1 -1 digits)
    math(EXPR e "${e} - 1")
  endwhile()
  string(APPEND digits "0000000000000000")
  string(SUBSTRING "${digits}" 0 16 digits)
  string(REGEX REPLACE "^0+" "" m "${digits}")
  if(m STREQUAL "")
    set(m 0)
  endif()
  set(${out_mantissa} ${m} PARENT_SCOPE)
  set(${out_exponent} ${e} PARENT_SCOPE)
endfunction()

function(check_relative a b digits what)
  parse_decimal(${a} ma ea)
  parse_decimal(${b} mb eb)
  if(ea GREATER eb)
    math(EXPR mb "${mb} / 10")
  elseif(eb GREATER ea)
    math(EXPR ma "${ma} / 10")
  endif()
  math(EXPR diff "${ma} - ${mb}")
  if(diff LESS 0)
    math(EXPR diff "-${diff}")
  endif()
  set(scale 1)
  foreach(i RANGE 1 ${digits})
    math(EXPR scale "${scale} * 10")
  endforeach()
  math(EXPR bound "${ma} / ${scale}")
  if(diff GREATER bound)
    message(FATAL_ERROR "FAIL ${what}: ${a} and ${b} differ by more than 1e-${digits} relative")
  endif()
  message(STATUS "PASS ${what}: ${a} and ${b} agree to 1e-${digits} relative")
endfunction()

# check_json_roundoff(json what key...): the JSON value at the keys is
# round-off (is_roundoff: below 1e-10)
function(check_json_roundoff json what)
  string(JSON value GET "${json}" ${ARGN})
  is_roundoff("${value}" small)
  if(NOT small)
    message(FATAL_ERROR "FAIL ${what}: ${ARGN} = ${value}, expected below 1e-10")
  endif()
  message(STATUS "PASS ${what}: ${ARGN} = ${value}")
endfunction()

# check_value(value expected what): |value - expected| <= 1e-10 |expected|,
# the signs compared too
function(check_value value expected what)
  string(REGEX MATCH "^-" sv "${value}")
  string(REGEX MATCH "^-" se "${expected}")
  if(NOT "${sv}" STREQUAL "${se}")
    message(FATAL_ERROR "FAIL ${what}: ${value}, expected ${expected}")
  endif()
  string(REGEX REPLACE "^-" "" v "${value}")
  string(REGEX REPLACE "^-" "" e "${expected}")
  check_relative(${e} ${v} 10 "${what}")
endfunction()
