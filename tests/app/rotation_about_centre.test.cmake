# 'Rotation about centre' (a gear's bore turned about its centre) through the
# program `dealvem`:
# - one body at small strain: the top of the unit square turned about
#   (0.5, 1) by the torque 0.5 (the angle an unknown; bottom clamped); the
#   JSON summary reports the mode, the torque and the moment about the
#   centre; the angle found, prescribed ('angle a'), needs the reaction
#   moment 0.5 sin(a)/a (the mesh is mirror-symmetric about x = 0.5, so the
#   radial part of the exact rotation has no moment): within [0.49999, 0.5];
# - one body at finite strain (neo-Hooke): the bottom turned by pi/2 in four
#   load steps without t in the data, no other support: every step is the
#   exact rotation by n/4 pi/2 (reported per step), stress free (max Cauchy
#   stress below 1e-10 E);
# - a torque at finite strain is refused, naming the entry;
# - two bodies in contact (tests/app/gear-torque-contact.prm): the upper
#   block's top is a bearing under the torque 0.5 t; per step the rotation
#   is printed, written to -rotations.csv and the JSON summary, and the
#   clamped bottom's reaction moment about the centre is -0.5 t.
include(${TEST_DIR}/program_checks.cmake)
file(REMOVE_RECURSE ${WORK_DIR}/output)

function(check_between name value low high)
  if(NOT (value GREATER low AND value LESS high))
    message(FATAL_ERROR "FAIL ${name}: ${value} not in (${low}, ${high})")
  endif()
  message(STATUS "PASS ${name}: ${value} in (${low}, ${high})")
endfunction()

set(block "subsection Mesh\n  set Type = structured quads\n  set Subdivisions = 8, 8\nend\n\
subsection Material\n  set Young's modulus = 1000\n  set Poisson's ratio = 0.3\nend\n\
subsection Output\n  set Folder = output\n  set Base name = BASE\n  set Write VTU = false\nend\n")

# one body, torque
string(REPLACE "BASE" "torque" prm "${block}")
file(WRITE ${WORK_DIR}/torque.prm "${prm}subsection Boundary conditions and loads\n\
  set Dirichlet = 2 : xy : 0, 0\n  set Rotation about centre = 3 : 0.5, 1 : torque 0.5\nend\n")
run_dealvem("torque on the top" TRUE "rotation of boundary 3 about (0.5, 1): torque 0.5 (applied), angle"
  ${WORK_DIR}/torque.prm)
file(READ ${WORK_DIR}/output/torque.json json)
string(JSON mode GET "${json}" cycles 0 rotations rotation_3 mode)
string(JSON angle GET "${json}" cycles 0 rotations rotation_3 angle)
string(JSON moment GET "${json}" cycles 0 rotations rotation_3 moment_about_centre)
if(NOT mode STREQUAL "torque")
  message(FATAL_ERROR "FAIL torque: mode '${mode}'")
endif()
check_between("torque: moment about the centre" ${moment} 0.4999999999 0.5000000001)
check_between("torque: the angle solved for" ${angle} 0.001 0.01)

# one body, the angle found prescribed
string(REPLACE "BASE" "angle" prm "${block}")
file(WRITE ${WORK_DIR}/angle.prm "${prm}subsection Boundary conditions and loads\n\
  set Dirichlet = 2 : xy : 0, 0\n  set Rotation about centre = 3 : 0.5, 1 : angle ${angle}\nend\n")
run_dealvem("angle on the top" TRUE "(prescribed), moment about centre" ${WORK_DIR}/angle.prm)
file(READ ${WORK_DIR}/output/angle.json json)
string(JSON reaction GET "${json}" cycles 0 rotations rotation_3 reaction_moment_about_centre)
check_between("angle: the reaction moment about the centre is the torque 0.5 sin(a)/a" ${reaction} 0.49999 0.5000000001)

# finite strain: an exact rotation by pi/2 in 4 steps, stress free
file(WRITE ${WORK_DIR}/finite.prm "subsection Mesh\n  set Type = structured quads\n  set Subdivisions = 4, 4\nend\n\
subsection Material\n  set Young's modulus = 1000\n  set Poisson's ratio = 0.3\n  set Law = neo-hooke\nend\n\
subsection Boundary conditions and loads\n  set Rotation about centre = 2 : 0.3, 0.2 : angle pi/2\nend\n\
subsection Finite strain\n  set Enabled = true\nend\nsubsection Load steps\n  set Number of steps = 4\nend\n\
subsection Output\n  set Folder = output\n  set Base name = finite\n  set Write VTU = false\nend\n")
run_dealvem("finite strain rotation" TRUE "rotation of boundary 2 about (0.3, 0.2): angle 0.785398 (prescribed)"
  ${WORK_DIR}/finite.prm)
file(READ ${WORK_DIR}/output/finite.json json)
foreach(step 1 2 3 4)
  string(JSON a GET "${json}" cycles 0 finite_strain steps ${step} rotations rotation_2 angle)
  string(JSON s GET "${json}" cycles 0 finite_strain steps ${step} max_cauchy_norm)
  check_between("finite strain step ${step}: max Cauchy stress (below 1e-10 E)" ${s} -1 1e-7)
  string(JSON m GET "${json}" cycles 0 finite_strain steps ${step} rotations rotation_2 reaction_moment_about_centre)
  check_between("finite strain step ${step}: reaction moment" ${m} -1e-7 1e-7)
endforeach()
check_between("finite strain: the angle of the last step" ${a} 1.5707963267 1.5707963268)

# a torque at finite strain is refused
file(READ ${WORK_DIR}/finite.prm prm)
string(REPLACE "angle pi/2" "torque 1\n  set Dirichlet = 3 : xy : 0, 0" prm "${prm}")
file(WRITE ${WORK_DIR}/finite-torque.prm "${prm}")
run_dealvem("finite strain torque" FALSE
  "Rotation about centre entry '2 : 0.3, 0.2 : torque 1'': a torque about a centre (the angle an unknown) is a small-strain condition"
  ${WORK_DIR}/finite-torque.prm)

# contact: a bearing under a torque, the moment balance about the centre
run_dealvem("contact with a torque" TRUE "rotation of boundary 13 about (0.5, 2): torque 0.5 (applied)"
  ${TEST_DIR}/gear-torque-contact.prm)
file(READ ${WORK_DIR}/output/gear-contact.json json)
foreach(step 1 2)
  string(JSON torque GET "${json}" steps ${step} rotations rotation_13 torque)
  string(JSON m GET "${json}" steps ${step} reactions boundary_2 moment)
  string(JSON mc GET "${json}" steps ${step} rotations rotation_13 moment_about_centre)
  message(STATUS "step ${step}: torque ${torque}, moment about the centre ${mc}, bottom reaction moment ${m}")
endforeach()
string(JSON m1 GET "${json}" steps 1 reactions boundary_2 moment)
string(JSON m2 GET "${json}" steps 2 reactions boundary_2 moment)
check_between("contact step 1: bottom reaction moment about the centre = -0.25" ${m1} -0.2500000001 -0.2499999999)
check_between("contact step 2: bottom reaction moment about the centre = -0.5" ${m2} -0.5000000001 -0.4999999999)
file(STRINGS ${WORK_DIR}/output/gear-contact-rotations.csv lines)
list(LENGTH lines n_lines)
list(GET lines 0 header)
if(NOT n_lines EQUAL 3 OR NOT header MATCHES "^step,time,rotation,boundary_id,centre_x,centre_y,mode,angle,torque,")
  message(FATAL_ERROR "FAIL contact: gear-contact-rotations.csv has ${n_lines} lines, header '${header}'")
endif()
message(STATUS "PASS contact: gear-contact-rotations.csv, ${n_lines} lines")
