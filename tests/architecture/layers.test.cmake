# The layers of dealvem (doc/architecture.md): a module may include its own
# headers and those of the modules below it, never one above. The rank of
# each module:
#   base 0 < mesh 1 < vem 2 < elasticity 3, solvers 3 < contact 4
#          < postprocessing 5 < design 6 < app 7
# solvers holds linear algebra only (it knows matrices, not meshes), so it
# sits beside elasticity; the contact algorithms drive it.
# Also checked: public headers include no Eigen, CGAL or boost (heavy
# includes stay in the .cc files), and every public header includes only
# dealvem headers that exist.
set(rank_base 0)
set(rank_mesh 1)
set(rank_vem 2)
set(rank_elasticity 3)
set(rank_solvers 3)
set(rank_contact 4)
set(rank_postprocessing 5)
set(rank_design 6)
set(rank_app 7)

set(violations "")
set(n_files 0)
set(n_includes 0)
foreach(module base mesh vem elasticity solvers contact postprocessing design app)
  file(GLOB files ${SOURCE_DIR}/include/dealvem/${module}/*.h ${SOURCE_DIR}/source/${module}/*.cc)
  if(NOT files)
    message(FATAL_ERROR "FAIL: module '${module}' has no files; update this test with the layout")
  endif()
  foreach(f ${files})
    math(EXPR n_files "${n_files} + 1")
    file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include")
    foreach(line ${lines})
      if(line MATCHES "<dealvem/([a-z_]+)/([a-z_]+\\.h)>")
        set(target ${CMAKE_MATCH_1})
        set(header ${CMAKE_MATCH_2})
        math(EXPR n_includes "${n_includes} + 1")
        if(NOT DEFINED rank_${target})
          list(APPEND violations "${f}: includes unknown module '${target}' (${line})")
        elseif(${rank_${target}} GREATER ${rank_${module}})
          list(APPEND violations "${f}: module '${module}' includes '${target}/${header}', a module above it")
        elseif(${rank_${target}} EQUAL ${rank_${module}} AND NOT target STREQUAL module)
          list(APPEND violations "${f}: module '${module}' includes '${target}/${header}' of the same rank")
        endif()
        if(NOT EXISTS ${SOURCE_DIR}/include/dealvem/${target}/${header})
          list(APPEND violations "${f}: includes '${target}/${header}', which does not exist")
        endif()
      endif()
      if(f MATCHES "\\.h$" AND line MATCHES "<(Eigen|CGAL|boost)/")
        list(APPEND violations "${f}: public header includes a heavy library (${line})")
      endif()
    endforeach()
  endforeach()
endforeach()

if(n_includes LESS 50)
  message(FATAL_ERROR "FAIL: only ${n_includes} dealvem includes found in ${n_files} files; the scan is broken")
endif()
if(violations)
  string(REPLACE ";" "\n  " text "${violations}")
  message(FATAL_ERROR "FAIL: layering violations:\n  ${text}")
endif()
message(STATUS "PASS: ${n_files} files, ${n_includes} dealvem includes, no module includes one above it")
