## ---------------------------------------------------------------------
## dealvem: virtual elements for 2D contact of elastic bodies, on deal.II
## SPDX-License-Identifier: LGPL-2.1-or-later
## ---------------------------------------------------------------------
## The ctest doc/doxygen: build the Doxygen reference through the 'doc'
## target of the build directory BINARY_DIR and fail when Doxygen wrote
## anything to its warnings log (WARN_LOGFILE of doc/Doxyfile.in: an
## undocumented member, a bad @param name, a broken reference or @cite, ...),
## printing the log. Registered by CMakeLists.txt when Doxygen is found;
## by hand:
##   cmake -DBINARY_DIR=build -P doc/check_doxygen.cmake
if(NOT BINARY_DIR)
  message(FATAL_ERROR "check_doxygen.cmake: pass -DBINARY_DIR=<build directory>")
endif()
set(_log ${BINARY_DIR}/doc/doxygen-warnings.log)
# a log left from an earlier run must not stand in for this one
file(REMOVE ${_log})
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY_DIR} --target doc
  RESULT_VARIABLE _result
  OUTPUT_VARIABLE _output
  ERROR_VARIABLE _output)
if(NOT _result EQUAL 0)
  message("${_output}")
  message(FATAL_ERROR "doc/doxygen: the 'doc' target failed (exit status ${_result}).")
endif()
if(NOT EXISTS ${_log})
  message(FATAL_ERROR "doc/doxygen: Doxygen wrote no warnings log ${_log}; "
    "WARN_LOGFILE in doc/Doxyfile.in must name it.")
endif()
file(READ ${_log} _warnings)
string(STRIP "${_warnings}" _warnings)
if(NOT _warnings STREQUAL "")
  string(REGEX MATCHALL "\n" _lines "${_warnings}\n")
  list(LENGTH _lines _n_lines)
  message("${_warnings}")
  message(FATAL_ERROR "doc/doxygen: Doxygen wrote ${_n_lines} line(s) to ${_log} (above). "
    "Document every public member (/** ... */ or ///< in the header) and fix the "
    "@param names and references it names; the reference must build without warnings.")
endif()
message(STATUS "doc/doxygen: the reference in ${BINARY_DIR}/doc/html built without warnings")
