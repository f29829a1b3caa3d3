# The files under one output prefix belong to one run (issue 19, class 8).
# 1. A 4-step Coulomb friction run writes steps 1-4, the .pvd, the final VTU
#    and CSV, the pictures and the JSON; its manifest output/run.files says
#    'status: complete' and lists them.
# 2. A rerun with the same prefix whose tangential load exceeds mu times the
#    normal load at step 3 must fail (exit != 0), print the files it wrote
#    (steps 1-2, .pvd, JSON) as the incomplete files of this run, mark its
#    manifest 'failed' and its JSON "status": "failed", and leave no file of
#    run 1 behind: no step 3 or 4, no final VTU/CSV/SVG.
# 3. A one-body run with the same prefix removes the contact files (no
#    interface CSV, no step files) and completes.
# A file of another prefix in the folder is never touched.
function(run_dealvem name expect_ok prm)
  file(WRITE ${WORK_DIR}/${name}.prm "${prm}")
  execute_process(COMMAND ${DEALVEM} ${WORK_DIR}/${name}.prm WORKING_DIRECTORY ${WORK_DIR}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  set(all "${out}${err}")
  if(expect_ok AND NOT rc EQUAL 0)
    message(FATAL_ERROR "FAIL ${name}: exit code ${rc}\n${all}")
  endif()
  if(NOT expect_ok AND (rc EQUAL 0 OR NOT rc MATCHES "^[0-9]+$"))
    message(FATAL_ERROR "FAIL ${name}: exit code ${rc}, expected a failure\n${all}")
  endif()
  set(output "${all}" PARENT_SCOPE)
endfunction()

function(expect_files present)
  foreach(f ${ARGN})
    if(present AND NOT EXISTS ${WORK_DIR}/output/${f})
      message(FATAL_ERROR "FAIL: output/${f} is missing")
    elseif(NOT present AND EXISTS ${WORK_DIR}/output/${f})
      message(FATAL_ERROR "FAIL: output/${f} of an earlier run is still there")
    endif()
  endforeach()
endfunction()

function(expect_text text fragment what)
  string(REGEX REPLACE "[ \t\r\n]+" " " flat "${text}")
  string(FIND "${flat}" "${fragment}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "FAIL ${what}: lacks '${fragment}'\n${text}")
  endif()
endfunction()

set(friction "set Number of bodies = 2
subsection Mesh
  set Type         = structured quads
  set Subdivisions = 2, 2
end
subsection Body 1
  subsection Mesh
    set Type               = structured quads
    set Subdivisions       = 3, 3
    set Lower left corner  = 0, 1
    set Upper right corner = 1, 2
    set Boundary id offset = 10
  end
end
subsection Discretization
  set Order = 1
end
subsection Output
  set Base name = run
end
subsection Contact
  set Pairs                = 3 : 12
  set Tangential           = coulomb
  set Friction coefficient = 0.3
end
subsection Load steps
  set Number of steps = 4
  set Final time      = 4
end
subsection Boundary conditions and loads
  set Dirichlet = 2 : xy : 0, 0
  set Traction  = 13 : @SHEAR@*t, -10
end
")
file(REMOVE_RECURSE ${WORK_DIR}/output)
file(MAKE_DIRECTORY ${WORK_DIR}/output)
file(WRITE ${WORK_DIR}/output/other.json "{}\n")
file(WRITE ${WORK_DIR}/output/run-notes.txt "not a file of the program\n")

# 1. the good run: shear 0.5 t, at most 2 < mu * 10 = 3
set(SHEAR 0.5)
string(CONFIGURE "${friction}" prm @ONLY)
run_dealvem(good TRUE "${prm}")
set(all_files run.vtu run-interface.csv run-resultants.csv run-reactions.csv run-stress.svg run-pressure.svg
  run-assembly.svg run.json run.pvd)
foreach(s 001 002 003 004)
  list(APPEND all_files run-step-${s}.vtu run-step-${s}-interface.csv run-step-${s}-resultants.csv)
endforeach()
expect_files(TRUE ${all_files} run.files)
file(READ ${WORK_DIR}/output/run.files manifest)
expect_text("${manifest}" "status: complete" "the manifest of the good run")
foreach(f ${all_files})
  expect_text("${manifest}" "file: output/${f}" "the manifest of the good run")
endforeach()
message(STATUS "PASS good run: ${all_files}")

# 2. the failing rerun: shear 1.2 t, 3.6 > 3 at step 3
set(SHEAR 1.2)
string(CONFIGURE "${friction}" prm @ONLY)
run_dealvem(failing FALSE "${prm}")
expect_text("${output}" "Output: removed the 21 file(s) of an earlier run with the output prefix 'output/run'"
            "the output of the failing rerun")
# (9 files of the two converged steps and the collapse mechanism of step 3,
# friction failing: run-mechanism.vtu and .svg)
expect_text("${output}" "The run did not complete: the 11 file(s) it wrote are incomplete as a set"
            "the output of the failing rerun")
foreach(f run-step-001.vtu run-step-002-interface.csv run.pvd run.json)
  expect_text("${output}" "output/${f}" "the list of the failing rerun's files")
endforeach()
expect_files(TRUE run-step-001.vtu run-step-001-interface.csv run-step-002.vtu run-step-002-interface.csv
             run-step-001-resultants.csv run-step-002-resultants.csv run-reactions.csv run.pvd run.json run.files
             run-mechanism.vtu run-mechanism.svg other.json run-notes.txt)
expect_files(FALSE run-step-003.vtu run-step-003-interface.csv run-step-004.vtu run-step-004-interface.csv
             run.vtu run-interface.csv run-resultants.csv run-stress.svg run-pressure.svg run-assembly.svg)
file(READ ${WORK_DIR}/output/run.files manifest)
expect_text("${manifest}" "status: failed" "the manifest of the failing rerun")
file(READ ${WORK_DIR}/output/run.json json)
string(JSON status GET "${json}" status)
if(NOT status STREQUAL "failed")
  message(FATAL_ERROR "FAIL: the JSON of the failing rerun says status '${status}'")
endif()
file(READ ${WORK_DIR}/output/run.pvd pvd)
string(FIND "${pvd}" "run-step-003.vtu" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "FAIL: the .pvd of the failing rerun names step 3")
endif()
message(STATUS "PASS failing rerun: only its own files, listed, manifest and JSON 'failed'")

# 3. a one-body run with the same prefix
run_dealvem(one_body TRUE "subsection Mesh
  set Type         = structured quads
  set Subdivisions = 2, 2
end
subsection Boundary conditions and loads
  set Dirichlet = 2 : xy : 0, 0
  set Traction  = 3 : 0, -1
end
subsection Output
  set Base name = run
end
")
expect_files(TRUE run.vtu run.json other.json run-notes.txt)
expect_files(FALSE run-step-001.vtu run-step-002-interface.csv run-reactions.csv run.pvd)
file(READ ${WORK_DIR}/output/run.json json)
string(JSON status GET "${json}" status)
if(NOT status STREQUAL "complete")
  message(FATAL_ERROR "FAIL: the JSON of the one-body run says status '${status}'")
endif()
message(STATUS "PASS one-body rerun: the contact files are gone, other files kept")
