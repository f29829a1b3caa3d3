# needs: CGAL (main.cc makes a Voronoi mesh)
# find_package(dealvem) from a separate CMake project (tests/app/downstream),
# as a user does:
#  - against the build tree (dealvem_DIR = the build directory), with the
#    build's own type;
#  - against an install tree made here holding both variants, the Release
#    libdealvem.so (cmake --install of this build) and the Debug
#    libdealvem.g.so (a library-only Debug build, see below), with the
#    consumer in Release and in Debug. The Debug consumer is configured
#    without CMAKE_BUILD_TYPE: deal_ii_initialize_cached_variables() makes it
#    Debug, as for any deal.II user project.
# Each consumer must link exactly one deal.II and one dealvem library, of
# its build type (ldd), and run to exit code 0; the Debug one also checks
# that a misuse caught by an Assert() of dealvem throws. The installed
# targets must carry no compile flags or definitions (INTERFACE_ properties
# other than the include directory and link libraries).
#
# The Debug library: DEBUG_LIBRARY_DIR (a configured Debug build directory
# of dealvem, e.g. the one scripts/install.sh makes) if given, else a
# library-only Debug build made in ${WORK_DIR}/debug-library (kept between
# runs; ccache makes rebuilds cheap). JOBS (default 1) compile jobs.
#
# In a Debug build tree (the sanitizer build, scripts/sanitize.sh) the build
# tree is itself the Debug variant: it is installed alone and the Release
# consumer is skipped (there is no Release library in such a build; the
# normal Release suite covers it). Under SANITIZE the install-tree consumers
# get the sanitizer flags, which only the build tree's targets carry.
cmake_policy(VERSION 3.13)   # lists keep empty elements (CMP0007)
set(_sanitize_args "")
if(SANITIZE)
  # the sanitizer flags travel with the build tree's targets only
  set(_flags "-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer")
  set(_sanitize_args "-DCMAKE_CXX_FLAGS=${_flags}" "-DCMAKE_EXE_LINKER_FLAGS=${_flags}")
endif()
if(NOT JOBS)
  set(JOBS 1)
endif()

function(run_or_fail _what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${_what}:\n${_out}${_err}")
  endif()
endfunction()

# ------------------------------------------------------------ the install tree
file(REMOVE_RECURSE ${WORK_DIR}/prefix)
run_or_fail("install" ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${WORK_DIR}/prefix)
if(CMAKE_BUILD_TYPE STREQUAL "Release")
  if(DEBUG_LIBRARY_DIR)
    set(_debug_dir ${DEBUG_LIBRARY_DIR})
    if(NOT EXISTS ${_debug_dir}/CMakeCache.txt)
      message(FATAL_ERROR "FAIL: DEBUG_LIBRARY_DIR ${_debug_dir} is not a configured build directory")
    endif()
    file(STRINGS ${_debug_dir}/CMakeCache.txt _type REGEX "^CMAKE_BUILD_TYPE:")
    if(NOT _type MATCHES "=Debug$")
      message(FATAL_ERROR "FAIL: DEBUG_LIBRARY_DIR ${_debug_dir} is not a Debug build (${_type})")
    endif()
  else()
    set(_debug_dir ${WORK_DIR}/debug-library)
    # the CGAL choice of this build: both variants share dealvem/config.h
    file(STRINGS ${BINARY_DIR}/CMakeCache.txt _cgal REGEX "^DEALVEM_WITH_CGAL:")
    string(REGEX REPLACE "^[^=]*=" "" _cgal "${_cgal}")
    run_or_fail("configure the Debug library" ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${_debug_dir}
      -DCMAKE_BUILD_TYPE=Debug -DDEALVEM_WITH_CGAL=${_cgal} -DDEALVEM_ENABLE_PROGRAM=OFF
      -DDEALVEM_ENABLE_TESTS=OFF -DDEALVEM_ENABLE_EXAMPLES=OFF -DDEALVEM_ENABLE_BENCHMARKS=OFF
      -DDEALVEM_ENABLE_DOC=OFF)
  endif()
  string(TIMESTAMP _start "%s")
  run_or_fail("build the Debug library in ${_debug_dir}" ${CMAKE_COMMAND} --build ${_debug_dir} -j ${JOBS})
  string(TIMESTAMP _end "%s")
  math(EXPR _seconds "${_end} - ${_start}")
  message(STATUS "Debug library (${_debug_dir}) up to date in ${_seconds} s")
  run_or_fail("install the Debug library" ${CMAKE_COMMAND} --install ${_debug_dir} --prefix ${WORK_DIR}/prefix)
  set(_installed_variants debug release)
else()
  set(_installed_variants debug)
endif()

file(GLOB_RECURSE _config ${WORK_DIR}/prefix/*/dealvemConfig.cmake)
if(NOT _config)
  message(FATAL_ERROR "FAIL install: no dealvemConfig.cmake under ${WORK_DIR}/prefix")
endif()
get_filename_component(_install_dir ${_config} DIRECTORY)
if(NOT EXISTS ${WORK_DIR}/prefix/include/dealvem/postprocessing/fe_transfer.h)
  message(FATAL_ERROR "FAIL install: headers missing under ${WORK_DIR}/prefix/include")
endif()
foreach(_variant ${_installed_variants})
  if(NOT EXISTS ${_install_dir}/dealvemTargets-${_variant}.cmake)
    message(FATAL_ERROR "FAIL install: no dealvemTargets-${_variant}.cmake in ${_install_dir}")
  endif()
endforeach()
# what the installed targets pass on to their users: the include directory
# and (dealvem::dealvem) the variant's library; no flags, no definitions
file(GLOB _export_files ${_install_dir}/*.cmake)
foreach(_file ${_export_files})
  file(STRINGS ${_file} _lines REGEX "INTERFACE_[A-Z_]+")
  foreach(_line ${_lines})
    if(NOT _line MATCHES "INTERFACE_(INCLUDE_DIRECTORIES|LINK_LIBRARIES)"
        OR _line MATCHES "NDEBUG|DEBUG|frounding|CGAL|deal[._]ii|deal_II|Eigen|cholmod")
      message(FATAL_ERROR "FAIL: ${_file} exports more than include directories and dealvem's "
        "library:\n${_line}")
    endif()
  endforeach()
endforeach()

# ------------------------------------------------------------ the consumers
# name, dealvem_DIR, CMAKE_BUILD_TYPE given (empty: none), build type expected
set(_consumers "build-tree|${BINARY_DIR}|${CMAKE_BUILD_TYPE}|${CMAKE_BUILD_TYPE}")
list(APPEND _consumers "install-debug|${_install_dir}||Debug")
list(FIND _installed_variants release _has_release)
if(_has_release GREATER -1)
  list(APPEND _consumers "install-release|${_install_dir}|Release|Release")
else()
  message(STATUS "SKIP the Release consumer: ${CMAKE_BUILD_TYPE} build tree, no Release library")
endif()

foreach(_consumer ${_consumers})
  string(REPLACE "|" ";" _fields "${_consumer}")
  list(GET _fields 0 _name)
  list(GET _fields 1 _dir)
  list(GET _fields 2 _type)
  list(GET _fields 3 _expected)
  set(_args -Ddealvem_DIR=${_dir})
  if(_type)
    list(APPEND _args -DCMAKE_BUILD_TYPE=${_type})
  endif()
  if(NOT _name STREQUAL "build-tree")
    list(APPEND _args ${_sanitize_args})
  endif()
  set(_build ${WORK_DIR}/build-${_name})
  file(REMOVE_RECURSE ${_build})
  run_or_fail("configure ${_name}" ${CMAKE_COMMAND} -S ${TEST_DIR}/downstream -B ${_build} ${_args})
  # the package found must be the one asked for, the build type the one expected
  file(STRINGS ${_build}/CMakeCache.txt _found REGEX "^dealvem_DIR:")
  if(NOT _found MATCHES "${_dir}")
    message(FATAL_ERROR "FAIL: ${_name} found ${_found}, not ${_dir}")
  endif()
  file(STRINGS ${_build}/CMakeCache.txt _found_type REGEX "^CMAKE_BUILD_TYPE:")
  if(NOT _found_type MATCHES "=${_expected}$")
    message(FATAL_ERROR "FAIL: ${_name} has ${_found_type}, not ${_expected}")
  endif()
  run_or_fail("build ${_name}" ${CMAKE_COMMAND} --build ${_build})

  # one deal.II and one dealvem, both of the build type
  find_program(_ldd ldd)
  if(_ldd)
    execute_process(COMMAND ${_ldd} ${_build}/downstream OUTPUT_VARIABLE _libs ERROR_VARIABLE _libs)
    if(_expected STREQUAL "Debug")
      set(_want "libdeal\\.ii\\.g\\.so" "libdealvem\\.g\\.so")
      set(_unwanted "libdeal\\.ii\\.so" "libdealvem\\.so")
    else()
      set(_want "libdeal\\.ii\\.so" "libdealvem\\.so")
      set(_unwanted "libdeal\\.ii\\.g\\.so" "libdealvem\\.g\\.so")
    endif()
    foreach(_lib ${_want})
      if(NOT _libs MATCHES "${_lib}")
        message(FATAL_ERROR "FAIL: ${_name} (${_expected}) does not link ${_lib}:\n${_libs}")
      endif()
    endforeach()
    foreach(_lib ${_unwanted})
      if(_libs MATCHES "${_lib}")
        message(FATAL_ERROR "FAIL: ${_name} (${_expected}) links ${_lib}:\n${_libs}")
      endif()
    endforeach()
  endif()

  execute_process(COMMAND ${_build}/downstream RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(_expect "build type: ${_expected}" "downstream: 20 cells"
    "transfer: 16 cells, 128 FE_DGQ(1) DoFs, max |u - u_h| at the DoFs 0")
  if(_expected STREQUAL "Debug")
    list(APPEND _expect "debug: VEMValues::n_edges() before reinit() throws ExceptionBase")
  endif()
  set(_missing "")
  foreach(_line ${_expect})
    string(FIND "${out}" "${_line}" pos)
    if(pos EQUAL -1)
      string(APPEND _missing "\n  missing: ${_line}")
    endif()
  endforeach()
  if(NOT rc EQUAL 0 OR _missing)
    message(FATAL_ERROR "FAIL run ${_name}: exit ${rc}${_missing}\n${out}${err}")
  endif()
  message(STATUS "PASS (${_name}, ${_expected})\n${out}")
endforeach()
