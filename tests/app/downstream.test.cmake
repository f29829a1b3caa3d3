# needs: CGAL (main.cc makes a Voronoi mesh)
# find_package(dealvem) from a separate CMake project (tests/app/downstream),
# as a user does:
#  - against the build tree (dealvem_DIR = the build directory), with the
#    build's own type;
#  - against an install tree made here: this build's variant (cmake --install
#    of this build) and, when the build directory of the other variant is
#    given, that one beside it in the same prefix; each installed variant
#    gets a consumer of its build type (Release: -DCMAKE_BUILD_TYPE=Release;
#    Debug: no CMAKE_BUILD_TYPE, which deal_ii_initialize_cached_variables()
#    makes Debug, as for any deal.II user project). A consumer of a variant
#    the prefix lacks must stop at find_package() with the message that
#    names scripts/install.sh.
# Each consumer must link exactly one deal.II and one dealvem library, of
# its build type (ldd), and run to exit code 0; the Debug one also checks
# that a misuse caught by an Assert() of dealvem throws. The installed
# targets must carry no compile flags or definitions (INTERFACE_ properties
# other than the include directory and link libraries).
#
# The other variant: DEBUG_LIBRARY_DIR in a Release tree (a built Debug
# build directory of dealvem, e.g. the one scripts/install.sh makes),
# RELEASE_LIBRARY_DIR in a Debug tree (scripts/sanitize.sh passes the
# Release build of scripts/test.sh when there is one, so CI checks both
# variants side by side). The test builds no library itself: in the default
# suite it takes seconds, not the 21 minutes a second, Debug library took on
# one core.
#
# Under SANITIZE the install-tree consumers get the sanitizer flags, which
# only the build tree's targets carry.
cmake_policy(VERSION 3.13)   # lists keep empty elements (CMP0007)
set(_sanitize_args "")
if(SANITIZE)
  # the sanitizer flags travel with the build tree's targets only
  set(_flags "-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer")
  set(_sanitize_args "-DCMAKE_CXX_FLAGS=${_flags}" "-DCMAKE_EXE_LINKER_FLAGS=${_flags}")
endif()
function(run_or_fail _what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${_what}:\n${_out}${_err}")
  endif()
endfunction()

# ------------------------------------------------------------ the install tree
# The prefix gets this build tree's variant and, when a build directory of
# the other variant is given (DEBUG_LIBRARY_DIR in a Release tree,
# RELEASE_LIBRARY_DIR in a Debug tree), that one too. Nothing is compiled
# here but the consumers: the default suite (Release) checks the build tree
# and the Release install, and that a Debug consumer of a prefix without the
# Debug library stops at find_package() with the message that says how to
# install it; CI's sanitizer stage (a Debug tree, given the Release build of
# the test stage by scripts/sanitize.sh) checks both variants side by side.
function(check_build_dir _dir _type)
  if(NOT EXISTS ${_dir}/CMakeCache.txt)
    message(FATAL_ERROR "FAIL: ${_dir} is not a configured build directory")
  endif()
  file(STRINGS ${_dir}/CMakeCache.txt _found REGEX "^CMAKE_BUILD_TYPE:")
  if(NOT _found MATCHES "=${_type}$")
    message(FATAL_ERROR "FAIL: ${_dir} is not a ${_type} build (${_found})")
  endif()
  file(GLOB _libs ${_dir}/libdealvem*.so*)
  if(NOT _libs)
    message(FATAL_ERROR "FAIL: ${_dir} holds no dealvem library; build it first")
  endif()
endfunction()
file(REMOVE_RECURSE ${WORK_DIR}/prefix)
run_or_fail("install" ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${WORK_DIR}/prefix)
if(CMAKE_BUILD_TYPE STREQUAL "Release")
  set(_installed_variants release)
  if(DEBUG_LIBRARY_DIR)
    check_build_dir(${DEBUG_LIBRARY_DIR} Debug)
    run_or_fail("install the Debug library" ${CMAKE_COMMAND} --install ${DEBUG_LIBRARY_DIR}
      --prefix ${WORK_DIR}/prefix)
    list(APPEND _installed_variants debug)
  endif()
else()
  set(_installed_variants debug)
  if(RELEASE_LIBRARY_DIR)
    check_build_dir(${RELEASE_LIBRARY_DIR} Release)
    run_or_fail("install the Release library" ${CMAKE_COMMAND} --install ${RELEASE_LIBRARY_DIR}
      --prefix ${WORK_DIR}/prefix)
    list(APPEND _installed_variants release)
  endif()
endif()
message(STATUS "installed variants: ${_installed_variants}")

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
foreach(_variant debug release)
  list(FIND _installed_variants ${_variant} _has)
  if(_variant STREQUAL "debug")
    # no CMAKE_BUILD_TYPE: deal_ii_initialize_cached_variables() makes it Debug
    set(_entry "install-debug|${_install_dir}||Debug")
  else()
    set(_entry "install-release|${_install_dir}|Release|Release")
  endif()
  if(_has GREATER -1)
    list(APPEND _consumers "${_entry}")
  else()
    # a consumer of the missing variant must stop at find_package() and say
    # how to install it
    string(REPLACE "|" ";" _fields "${_entry}")
    list(GET _fields 0 _name)
    list(GET _fields 2 _type)
    set(_args -Ddealvem_DIR=${_install_dir})
    if(_type)
      list(APPEND _args -DCMAKE_BUILD_TYPE=${_type})
    endif()
    set(_build ${WORK_DIR}/build-${_name})
    file(REMOVE_RECURSE ${_build})
    execute_process(COMMAND ${CMAKE_COMMAND} -S ${TEST_DIR}/downstream -B ${_build} ${_args}
      RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
    string(REGEX REPLACE "[ \n]+" " " _flat "${_out}${_err}")
    if(_rc EQUAL 0 OR NOT _flat MATCHES "has no ${_variant} library .*scripts/install.sh")
      message(FATAL_ERROR "FAIL ${_name}: configuring against a prefix without the ${_variant} "
        "library must stop and name scripts/install.sh (exit ${_rc}):\n${_out}${_err}")
    endif()
    message(STATUS "PASS (${_name}: no ${_variant} library installed; find_package stops and says so)")
  endif()
endforeach()

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
