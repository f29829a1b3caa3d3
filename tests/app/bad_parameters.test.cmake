# Bad parameter files: each must stop with a non-zero exit code and a
# message that names the cause (the parameter and its value, the file, the
# folder), never crash, hang or give a silent wrong answer. Each case is a
# small parameter file written here and a
# fragment the message must contain. Also: a multi-cycle run writes
# <base>-cycle<c>.* files, a single cycle <base>.*.
# run_dealvem() of program_checks.cmake, each run stopped after 120 s: it
# also fails on a crash, a sanitizer report or an uncaught exception
set(RUN_TIMEOUT 120)
include(${TEST_DIR}/program_checks.cmake)

function(bad_case name fragment text)
  file(WRITE ${WORK_DIR}/${name}.prm "${text}")
  run_dealvem("bad input: ${name}" FALSE "${fragment}" ${WORK_DIR}/${name}.prm)
  set(LAST_OUTPUT "${LAST_OUTPUT}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR}/output ${WORK_DIR}/somefile)
set(ok_bc "subsection Boundary conditions and loads\n  set Dirichlet = 0 : xy : 0, 0\nend\n")
set(small_mesh "subsection Mesh\n  set Type = structured quads\n  set Subdivisions = 2, 2\nend\n")

# ---- output names and folders
bad_case(empty_base_name "Parameter 'Output/Base name' is empty"
  "${small_mesh}${ok_bc}subsection Output\n  set Base name =\nend\n")
bad_case(slash_base_name "Parameter 'Output/Base name' = 'a/b' contains '/'"
  "${small_mesh}${ok_bc}subsection Output\n  set Base name = a/b\nend\n")
bad_case(empty_folder "Parameter 'Output/Folder' is empty"
  "${small_mesh}${ok_bc}subsection Output\n  set Folder =\nend\n")
file(WRITE ${WORK_DIR}/somefile "a regular file, not a folder\n")
bad_case(folder_below_file "cannot create the output folder 'somefile/out'"
  "${small_mesh}${ok_bc}subsection Output\n  set Folder = somefile/out\nend\n")
# the target of the JSON summary is a folder: the writer names the file
file(MAKE_DIRECTORY ${WORK_DIR}/output/blocked.json)
bad_case(json_target_is_folder "Cannot write the file 'output/blocked.json': it is a directory"
  "${small_mesh}${ok_bc}subsection Output\n  set Base name = blocked\n  set Write VTU = false\nend\n")

# ---- parameter ranges
bad_case(tiny_E "Parameter 'Material/Young's modulus' = 1e-300 is out of range: it must lie in [1e-200, 1e+200]"
  "${small_mesh}${ok_bc}subsection Material\n  set Young's modulus = 1e-300\nend\n")
bad_case(huge_E "Parameter 'Material/Young's modulus' = 1e+308 is out of range"
  "${small_mesh}${ok_bc}subsection Material\n  set Young's modulus = 1e308\nend\n")
bad_case(zero_E "Parameter 'Material/Young's modulus' = 0 is out of range"
  "${small_mesh}${ok_bc}subsection Material\n  set Young's modulus = 0\nend\n")
bad_case(small_gamma "Parameter 'Discretization/Stabilization factor' = 1e-07 is out of range: it must lie in [1e-06, 1e+06]"
  "${small_mesh}${ok_bc}subsection Discretization\n  set Stabilization factor = 1e-7\nend\n")
bad_case(large_gamma "Parameter 'Discretization/Stabilization factor' = 1e+07 is out of range"
  "${small_mesh}${ok_bc}subsection Discretization\n  set Stabilization factor = 1e7\nend\n")
bad_case(tolerance_one "Parameter 'Solver/Relative tolerance' = 1 is out of range: it must lie in (0, 1)"
  "${small_mesh}${ok_bc}subsection Solver\n  set Relative tolerance = 1\nend\n")
file(READ ${SOURCE_DIR}/examples/step-2/patch-test.prm contact_prm)
string(REPLACE "subsection Contact\n" "subsection Contact\n  set Penalty = 1e308\n" prm "${contact_prm}")
bad_case(contact_penalty "Parameter 'Contact/Penalty' = 1e+308 is out of range for this problem: the stick penalty must lie in [" "${prm}")
string(REPLACE "subsection Contact\n" "subsection Contact\n  set Penalty factor = 1e13\n" prm "${contact_prm}")
bad_case(contact_penalty_factor "Parameter 'Contact/Penalty factor' = 1e+13 is out of range" "${prm}")
string(REGEX REPLACE "(subsection Body 1.*Young's modulus *)= 7000" "\\1= 1e-300" prm "${contact_prm}")
bad_case(contact_body_E "Parameter 'Body 1/Material/Young's modulus' = 1e-300 is out of range" "${prm}")

# ---- material law and finite strain (section 'Finite strain', 'Material/Law')
set(fs_on "subsection Finite strain\n  set Enabled = true\nend\n")
bad_case(unknown_law "Parameter 'Material/Law' = 'mooney-rivlin' is not a law of the program: use 'linear', 'neo-hooke' or 'saint venant-kirchhoff'"
  "${small_mesh}${ok_bc}subsection Material\n  set Law = mooney-rivlin\nend\n")
bad_case(finite_strain_linear "Parameter 'Finite strain/Enabled' is true, but 'Material/Law' is 'linear': the linear law has no finite-strain response"
  "${small_mesh}${ok_bc}${fs_on}")
set(neo "subsection Material\n  set Law = neo-hooke\nend\n")
bad_case(finite_strain_zero_steps "Parameter 'Load steps/Number of steps' is 0: it must be at least 1"
  "${small_mesh}${ok_bc}${fs_on}${neo}subsection Load steps\n  set Number of steps = 0\nend\n")
bad_case(finite_strain_final_time "Parameter 'Load steps/Final time' = 0 is out of range"
  "${small_mesh}${ok_bc}${fs_on}${neo}subsection Load steps\n  set Final time = 0\nend\n")
# (one body at small strain reads 'Load steps' too: t at the final time)
bad_case(load_steps_small_strain_zero "Parameter 'Load steps/Number of steps' is 0: it must be at least 1"
  "${small_mesh}${ok_bc}${neo}subsection Load steps\n  set Number of steps = 0\nend\n")
bad_case(finite_strain_pressure_load "Parameter 'Finite strain/Pressure load' = 'sideways' is not a kind of pressure load: use 'follower'"
  "${small_mesh}${neo}subsection Finite strain\n  set Enabled = true\n  set Pressure load = sideways\nend\nsubsection Boundary conditions and loads\n  set Dirichlet = 0 : xy : 0, 0\n  set Pressure = 3 : 1\nend\n")
bad_case(finite_strain_rigid "a rigid boundary part is a small-displacement condition"
  "${small_mesh}${fs_on}${neo}subsection Boundary conditions and loads\n  set Dirichlet = 2 : xy : 0, 0\n  set Rigid boundary = 3 : 0, -1\nend\n")
bad_case(finite_strain_residual_tolerance "Parameter 'Finite strain/Residual tolerance' = 0 is out of range"
  "${small_mesh}${ok_bc}${neo}subsection Finite strain\n  set Enabled = true\n  set Residual tolerance = 0\nend\n")
bad_case(finite_strain_monitor "Parameter 'Finite strain/Monitor point' = (0.3 0.3) is not a vertex of the mesh"
  "${small_mesh}${ok_bc}${neo}subsection Finite strain\n  set Enabled = true\n  set Monitor point = 0.3, 0.3\nend\n")
bad_case(finite_strain_monitor_text "Parameter 'Finite strain/Monitor point' = '1': expected two coordinates 'x, y'"
  "${small_mesh}${ok_bc}${neo}subsection Finite strain\n  set Enabled = true\n  set Monitor point = 1\nend\n")
# (finite strain with contact is finite sliding: its bad input is checked in
# app/finite_sliding_program)

# ---- the size of a run
bad_case(huge_subdivisions "This run is very large: more than 2e+07 DoFs"
  "subsection Mesh\n  set Type = structured quads\n  set Subdivisions = 10000, 10000\nend\n${ok_bc}")
string(REGEX REPLACE "[ \t\r\n]+" " " flat "${LAST_OUTPUT}")
string(FIND "${flat}" "set 'Allow large runs = true'" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "FAIL huge_subdivisions: the message does not name 'Allow large runs'")
endif()
bad_case(huge_voronoi "more than 1e+07 Voronoi cells"
  "subsection Mesh\n  set Type = voronoi\n  set Number of cells = 20000000\n  set Lloyd iterations = 0\nend\n${ok_bc}")
bad_case(many_cycles "more than 2e+07 DoFs"
  "subsection Mesh\n  set Type = voronoi\n  set Number of cells = 1000\nend\nsubsection Convergence study\n  set Refinement cycles = 8\nend\n${ok_bc}")
bad_case(lloyd "more than 1e+05 Lloyd iterations"
  "subsection Mesh\n  set Type = voronoi\n  set Lloyd iterations = 1000000\nend\n${ok_bc}")
bad_case(unrepresentable "more cells than the program can represent"
  "set Allow large runs = true\nsubsection Mesh\n  set Type = structured quads\n  set Subdivisions = 999999999, 999999999\nend\n${ok_bc}")

# ---- expressions and function constants
set(bc_head "subsection Boundary conditions and loads\n  set Dirichlet = 0 : xy : 0, 0\n")
bad_case(constant_x "Parameter 'Boundary conditions and loads/Function constants': the name 'x' is reserved"
  "${small_mesh}${bc_head}  set Function constants = x=1\nend\n")
bad_case(constant_1a "Parameter 'Boundary conditions and loads/Function constants': '1a' is not a valid constant name"
  "${small_mesh}${bc_head}  set Function constants = 1a=2\nend\n")
bad_case(constant_a_b "Parameter 'Boundary conditions and loads/Function constants (a)': 'b' is not a finite real number"
  "${small_mesh}${bc_head}  set Function constants = a=b\nend\n")
bad_case(unknown_function "Parameter 'Boundary conditions and loads/Body force': cannot parse the expression(s) 'foo(x), 0'"
  "${small_mesh}${bc_head}  set Body force = foo(x), 0\nend\n")

# ---- parameter files
# include names are relative to the working directory (as in deal.II)
file(WRITE ${WORK_DIR}/include-self.prm "# includes itself\ninclude include-self.prm\n")
run_dealvem("bad input: file includes itself" FALSE "include each other in a cycle" ${WORK_DIR}/include-self.prm)
file(WRITE ${WORK_DIR}/include-a.prm "include include-b.prm\n")
file(WRITE ${WORK_DIR}/include-b.prm "# b includes a\ninclude include-a.prm\n")
run_dealvem("bad input: two files include each other" FALSE "include-b.prm' includes" ${WORK_DIR}/include-a.prm)
file(WRITE ${WORK_DIR}/include-missing.prm "include no-such-file.prm\n")
run_dealvem("bad input: missing include file" FALSE "cannot open the included file 'no-such-file.prm'"
  ${WORK_DIR}/include-missing.prm)
file(MAKE_DIRECTORY ${WORK_DIR}/a-folder.prm)
run_dealvem("bad input: parameter file is a folder" FALSE "it is a directory" ${WORK_DIR}/a-folder.prm)

# ---- good runs: an include that is not a cycle; cycle file names
file(WRITE ${WORK_DIR}/common.prm "${small_mesh}${ok_bc}")
file(WRITE ${WORK_DIR}/with-include.prm
  "include common.prm\nsubsection Convergence study\n  set Refinement cycles = 2\nend\nsubsection Output\n  set Base name = multi\nend\n")
run_dealvem("include and two cycles" TRUE "Summary written to" ${WORK_DIR}/with-include.prm)
foreach(f output/multi-cycle0.vtu output/multi-cycle1.vtu output/multi.json)
  if(NOT EXISTS ${WORK_DIR}/${f})
    message(FATAL_ERROR "FAIL include and two cycles: ${f} was not written")
  endif()
endforeach()
file(WRITE ${WORK_DIR}/single.prm "${small_mesh}${ok_bc}subsection Output\n  set Base name = single\nend\n")
run_dealvem("one cycle" TRUE "Summary written to" ${WORK_DIR}/single.prm)
if(NOT EXISTS ${WORK_DIR}/output/single.vtu)
  message(FATAL_ERROR "FAIL one cycle: output/single.vtu was not written")
endif()
file(GLOB leftovers ${WORK_DIR}/output/.*tmp*)
if(leftovers)
  message(FATAL_ERROR "FAIL: temporary files left behind: ${leftovers}")
endif()
message(STATUS "PASS no temporary files left")

# ---- a convergence study whose two cycles read the same mesh: the rates
# are undefined; the table says "n/a" (never nan or inf) and a warning
# names the cycles
configure_file(${SOURCE_DIR}/tests/mesh/data/two_cells.vtk ${WORK_DIR}/same-0.vtk COPYONLY)
configure_file(${SOURCE_DIR}/tests/mesh/data/two_cells.vtk ${WORK_DIR}/same-1.vtk COPYONLY)
set(linear "1e-3*x + 2e-3*y, -1e-3*x + 3e-3*y")
file(WRITE ${WORK_DIR}/same-mesh.prm "subsection Mesh
  set Type        = vtk file
  set File name   = same-{cycle}.vtk
  set Material id = 4
end
subsection Convergence study
  set Refinement cycles = 2
end
subsection Boundary conditions and loads
  set Dirichlet = 0 : xy : ${linear}; 5 : xy : ${linear}; 6 : xy : ${linear}
end
subsection Exact solution
  set Displacement = ${linear}
end
subsection Output
  set Base name = same-mesh
end
")
run_dealvem("two cycles on the same mesh" TRUE "DoFs, no more than cycle 0" ${WORK_DIR}/same-mesh.prm)
string(REGEX MATCH "n/a" na "${LAST_OUTPUT}")
string(REGEX MATCH "[^a-z](-?nan|-?inf)[^a-z]" nonfinite "${LAST_OUTPUT}")
if(NOT na OR nonfinite)
  message(FATAL_ERROR "FAIL two cycles on the same mesh: the rates must read n/a, not '${nonfinite}'\n${LAST_OUTPUT}")
endif()
message(STATUS "PASS two cycles on the same mesh: rates n/a")
