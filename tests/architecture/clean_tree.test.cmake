# The source tree holds sources, not the products of a run: no compiled
# Python (__pycache__, .pyc), no object files or libraries, no run logs or
# result files at the top level (a program run from the source directory
# leaves its .txt, .csv, .json, .vtu there; .gitignore keeps them out), and
# the files git tracks at the top level are the ones listed here. Checked on
# the files git tracks (skipped when the source tree is not a git checkout,
# e.g. an unpacked release archive).
cmake_policy(VERSION 3.13)   # IN_LIST (CMP0057)
find_program(GIT git)
if(NOT GIT OR NOT EXISTS ${SOURCE_DIR}/.git)
  message(STATUS "SKIP: ${SOURCE_DIR} is not a git checkout")
  return()
endif()
execute_process(COMMAND ${GIT} -C ${SOURCE_DIR} ls-files
  RESULT_VARIABLE rc OUTPUT_VARIABLE files ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "FAIL: git ls-files in ${SOURCE_DIR}: ${err}")
endif()
string(REPLACE "\n" ";" files "${files}")
set(top_level_allowed .ci .clang-format .gitignore CMakeLists.txt LICENSE README.md app benchmarks cmake doc examples
  include scripts source tests)
set(bad "")
set(n 0)
foreach(f ${files})
  if(f STREQUAL "")
    continue()
  endif()
  math(EXPR n "${n} + 1")
  if(f MATCHES "(^|/)__pycache__/|\\.(pyc|pyo|o|so|a|log)$|(^|/)(core|a\\.out)$")
    string(APPEND bad "\n  ${f}: a build or run product")
  endif()
  string(REGEX REPLACE "/.*" "" top "${f}")
  if(NOT top IN_LIST top_level_allowed)
    string(APPEND bad "\n  ${f}: not a file the top level holds (add it to this test if it belongs)")
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "FAIL: tracked files that do not belong in the source tree:${bad}")
endif()
message(STATUS "PASS: ${n} tracked files, none a build or run product")
