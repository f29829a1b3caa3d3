# needs: CGAL (main.cc makes a Voronoi mesh)
# find_package(dealvem) from a separate CMake project, twice: against the
# build tree (dealvem_DIR = the build directory) and against an install
# tree made here with cmake --install (dealvem_DIR = <prefix>/lib/cmake/dealvem),
# so the exported targets, the package configuration and the installed
# headers are all checked.
set(_sanitize_args "")
if(SANITIZE)
  # the sanitizer flags travel with the build tree's targets only
  set(_flags "-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer")
  set(_sanitize_args "-DCMAKE_CXX_FLAGS=${_flags}" "-DCMAKE_EXE_LINKER_FLAGS=${_flags}")
endif()

file(REMOVE_RECURSE ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${WORK_DIR}/prefix
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "FAIL install:\n${out}${err}")
endif()
file(GLOB_RECURSE _config ${WORK_DIR}/prefix/*/dealvemConfig.cmake)
if(NOT _config)
  message(FATAL_ERROR "FAIL install: no dealvemConfig.cmake under ${WORK_DIR}/prefix")
endif()
get_filename_component(_install_dir ${_config} DIRECTORY)
if(NOT EXISTS ${WORK_DIR}/prefix/include/dealvem/postprocessing/fe_transfer.h)
  message(FATAL_ERROR "FAIL install: headers missing under ${WORK_DIR}/prefix/include")
endif()

foreach(_tree build install)
  if(_tree STREQUAL "build")
    set(_dir ${BINARY_DIR})
    set(_extra "")
  else()
    set(_dir ${_install_dir})
    set(_extra ${_sanitize_args})
  endif()
  set(_build ${WORK_DIR}/build-${_tree})
  file(REMOVE_RECURSE ${_build})
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${TEST_DIR}/downstream -B ${_build}
      -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE} -Ddealvem_DIR=${_dir} ${_extra}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "FAIL configure against the ${_tree} tree:\n${out}${err}")
  endif()
  # the package found must be the one asked for
  file(STRINGS ${_build}/CMakeCache.txt _found REGEX "^dealvem_DIR:")
  if(NOT _found MATCHES "${_dir}")
    message(FATAL_ERROR "FAIL: the ${_tree} tree configure found ${_found}, not ${_dir}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${_build}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "FAIL build against the ${_tree} tree:\n${out}${err}")
  endif()
  execute_process(COMMAND ${_build}/downstream RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${out}" "downstream: 20 cells" pos)
  string(FIND "${out}" "transfer: 16 cells, 128 FE_DGQ(1) DoFs, max |u - u_h| at the DoFs 0" pos2)
  if(NOT rc EQUAL 0 OR pos EQUAL -1 OR pos2 EQUAL -1)
    message(FATAL_ERROR "FAIL run against the ${_tree} tree: ${rc}\n${out}${err}")
  endif()
  message(STATUS "PASS (${_tree} tree) ${out}")
endforeach()
