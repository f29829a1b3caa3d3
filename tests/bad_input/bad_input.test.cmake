# The bad-input corpus: every tests/bad_input/NN-<class>.prm is one input
# the program must reject. Its header names what the output must contain,
#   # expect: <fragment>
# (white space is collapsed before comparing, as deal.II wraps its messages).
# For each file `dealvem` runs in its own folder; the case passes when
#   - the exit code is a number other than 0 (not a signal),
#   - the output contains the fragment,
#   - no crash signature appears (segfault, sanitizer report, uncaught
#     exception).
# A case the program does not reject yet carries a line
#   # xfail: <why>
# and is reported as XFAIL while it still fails the first two checks (a crash
# is an error even then); when it starts to pass, the test fails (XPASS) so
# that the mark gets removed. Mesh files next to a case are found relative to
# the parameter file.
set(crash_signatures "Segmentation fault" "AddressSanitizer" "LeakSanitizer"
  "runtime error:" "terminate called" "unknown exception")
if(NOT DEFINED CASE_TIMEOUT)
  set(CASE_TIMEOUT 300)
endif()

if(NOT EXISTS "${DEALVEM}")
  message(FATAL_ERROR "the program '${DEALVEM}' does not exist (build it first)")
endif()
file(GLOB cases ${TEST_DIR}/*.prm)
list(SORT cases)
list(LENGTH cases n_cases)
if(n_cases EQUAL 0)
  message(FATAL_ERROR "no cases in ${TEST_DIR}")
endif()

set(failures "")
set(xfails "")
foreach(prm ${cases})
  get_filename_component(name ${prm} NAME_WE)
  file(STRINGS ${prm} expect_lines REGEX "^# expect: ")
  file(STRINGS ${prm} xfail_lines REGEX "^# xfail: ")
  if(NOT expect_lines)
    list(APPEND failures "${name}: no '# expect: ' line")
    continue()
  endif()
  list(GET expect_lines 0 fragment)
  string(REGEX REPLACE "^# expect: " "" fragment "${fragment}")
  string(STRIP "${fragment}" fragment)
  string(REGEX REPLACE "[ \t\r\n]+" " " fragment "${fragment}")

  set(dir ${WORK_DIR}/${name})
  file(REMOVE_RECURSE ${dir})
  file(MAKE_DIRECTORY ${dir})
  execute_process(COMMAND ${DEALVEM} ${prm} WORKING_DIRECTORY ${dir}
    TIMEOUT ${CASE_TIMEOUT}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(all "${out}${err}")
  file(WRITE ${dir}/output.txt "exit: ${rc}\n${all}")
  string(REGEX REPLACE "[ \t\r\n]+" " " all_flat "${all}")

  # a crash is an error whatever the case's mark
  set(crash "")
  if(NOT rc MATCHES "^[0-9]+$")
    set(crash "ended by '${rc}'")
  endif()
  foreach(sig ${crash_signatures})
    string(FIND "${all}" "${sig}" pos)
    if(NOT pos EQUAL -1)
      set(crash "${crash} output contains '${sig}'")
    endif()
  endforeach()
  if(crash)
    list(APPEND failures "${name}: CRASH (${crash}) (output: ${dir}/output.txt)")
    message(STATUS "CRASH ${name}:${crash}\n${all}")
    continue()
  endif()

  set(problem "")
  if(rc EQUAL 0)
    set(problem "exit code 0 (accepted)")
  else()
    string(FIND "${all_flat}" "${fragment}" pos)
    if(pos EQUAL -1)
      set(problem "exit code ${rc} but the output lacks '${fragment}'")
    endif()
  endif()

  if(xfail_lines)
    if(problem)
      message(STATUS "XFAIL ${name}: ${problem}")
      list(APPEND xfails ${name})
    else()
      list(APPEND failures "${name}: XPASS (rejected as expected now: remove its '# xfail:' line)")
    endif()
  elseif(problem)
    list(APPEND failures "${name}: ${problem} (output: ${dir}/output.txt)")
    message(STATUS "FAIL ${name}: ${problem}\n${all}")
  else()
    message(STATUS "PASS ${name} (exit ${rc})")
  endif()
endforeach()

list(LENGTH failures n_failures)
list(LENGTH xfails n_xfails)
message(STATUS "${n_cases} cases, ${n_failures} failed, ${n_xfails} expected failures ${xfails}")
if(n_failures GREATER 0)
  string(REPLACE ";" "\n  " failures "${failures}")
  message(FATAL_ERROR "bad-input corpus:\n  ${failures}")
endif()
