# Spur gear pairs through the parameter file, on coarse meshes (about 2 s a
# run): the placement of a pair and the torque balance along the line of
# action.
# - examples/parameters/gear-pair.prm made coarse (no global refinement,
#   flanks at 0.1), once as it is and once moved and turned as a whole: the
#   pinion centred at (-3000, 7000), the pair turned by -143 degrees (both
#   'Rotation' entries less 143, the gear's centre at c1 + 102 (cos, sin)
#   (-143 deg), the bearing and the moment point with them). A rigid motion
#   of the model changes nothing: the normal force, the gear's reaction
#   moment about its centre, the peak pressure and the pinion's angle agree
#   to 1e-6 relative (measured 1e-9; node insertion makes a pair more or
#   less on the moved model, 363 and 362, with the same forces). Also the
#   sectors 'Teeth = 19, 3' and '30, 3' run past the last tooth.
# - tests/app/gear-pair-13-40.prm (z 13/40, profile shifts +0.3/-0.3): the
#   gear's reaction moment is T1 z2 / z1 = 28923.08 within 0.5 % (measured
#   -0.21 %, the same on meshes five times finer), and the contact closes
#   only at the pitch point (26, 0): the centre of pressure within 0.1 mm,
#   every closed pair within 0.5 mm.
include(${TEST_DIR}/program_checks.cmake)
file(REMOVE_RECURSE ${WORK_DIR}/output)

function(check_between value low high what)
  if(NOT (value GREATER low AND value LESS high))
    message(FATAL_ERROR "FAIL ${what}: ${value} not in (${low}, ${high})")
  endif()
  message(STATUS "PASS ${what}: ${value} in (${low}, ${high})")
endfunction()

# the results compared between the two placements
function(gear_results base out)
  file(READ ${WORK_DIR}/output/${base}.json json)
  string(JSON fn GET "${json}" interfaces 0 normal_force)
  string(JSON m2 GET "${json}" reactions boundary_10 moment)
  string(JSON pmax GET "${json}" contact pressure_max)
  string(JSON angle GET "${json}" rotations rotation_0 angle)
  set(${out} ${fn} ${m2} ${pmax} ${angle} PARENT_SCOPE)
endfunction()

# replaces in the text of variable prm each "from|to" pair of the arguments;
# a line this test edits that the example no longer has stops it
function(edit_prm)
  foreach(pair ${ARGN})
    string(REPLACE "|" ";" pair "${pair}")
    list(GET pair 0 from)
    list(GET pair 1 to)
    string(FIND "${prm}" "${from}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "gear-pair.prm has no line '${from}' (this test edits it)")
    endif()
    string(REPLACE "${from}" "${to}" prm "${prm}")
  endforeach()
  set(prm "${prm}" PARENT_SCOPE)
endfunction()

file(READ ${SOURCE_DIR}/examples/parameters/gear-pair.prm prm)
edit_prm("set Global refinements  = 1|set Global refinements  = 0"
         "set Flank cell size     = 0.02|set Flank cell size     = 0.1"
         "set Base name      = gear-pair|set Base name      = gear-coarse\n  set Write VTU      = false")
file(WRITE ${WORK_DIR}/gear-coarse.prm "${prm}")
run_dealvem("gear pair, coarse" TRUE "rotation of boundary 0 about (0, 0): torque 9400 (applied)"
  ${WORK_DIR}/gear-coarse.prm)
gear_results(gear-coarse here)

edit_prm("set Centre              = 0, 0|set Centre              = -3000, 7000"
         "set Rotation            = -4.428380275608647|set Rotation            = -147.42838027560865"
         "set Centre              = 102, 0|set Centre              = -3081.4608220248238, 6938.614867638491"
         "set Rotation            = 177.14298046734925|set Rotation            = 34.14298046734925"
         "set Rotation about centre = 0 : 0, 0 :|set Rotation about centre = 0 : -3000, 7000 :"
         "set Moment point   = 102, 0|set Moment point   = -3081.4608220248238, 6938.614867638491"
         "set Base name      = gear-coarse|set Base name      = gear-moved")
file(WRITE ${WORK_DIR}/gear-moved.prm "${prm}")
run_dealvem("gear pair, moved and turned" TRUE
  "rotation of boundary 0 about (-3000, 7000): torque 9400 (applied)" ${WORK_DIR}/gear-moved.prm)
gear_results(gear-moved moved)
set(names "normal force" "gear reaction moment" "peak pressure" "pinion angle")
foreach(i 0 1 2 3)
  list(GET here ${i} a)
  list(GET moved ${i} b)
  list(GET names ${i} what)
  check_relative(${a} ${b} 6 "gear pair moved by a rigid motion: ${what}")
endforeach()
list(GET here 1 m2)
check_between(${m2} 14526.3 14613.7 "gear pair, coarse: gear reaction moment = T1 z2 / z1 = 14570 (0.3 %)")

# profile-shifted 13/40
run_dealvem("gear pair 13/40" TRUE "rotation of boundary 0 about (0, 0): torque 9400 (applied)"
  ${TEST_DIR}/gear-pair-13-40.prm)
file(READ ${WORK_DIR}/output/gear-13-40.json json)
string(JSON m2 GET "${json}" reactions boundary_10 moment)
check_between(${m2} 28778.5 29067.7 "gear pair 13/40: gear reaction moment = T1 z2 / z1 = 28923.08 (0.5 %)")
string(JSON cx GET "${json}" interfaces 0 centre_x)
string(JSON cy GET "${json}" interfaces 0 centre_y)
check_between(${cx} 25.9 26.1 "gear pair 13/40: centre of pressure, x")
check_between(${cy} -0.1 0.1 "gear pair 13/40: centre of pressure, y")
file(STRINGS ${WORK_DIR}/output/gear-13-40-interface.csv rows)
set(n_active 0)
foreach(row ${rows})
  if(row MATCHES "^0,[0-9]+,([-0-9.e+]+),([-0-9.e+]+),[^,]*,[^,]*,[01],1,")
    if(NOT (CMAKE_MATCH_1 GREATER 25.5 AND CMAKE_MATCH_1 LESS 26.5 AND CMAKE_MATCH_2 GREATER -0.5 AND
            CMAKE_MATCH_2 LESS 0.5))
      message(FATAL_ERROR "FAIL gear pair 13/40: a closed pair at (${CMAKE_MATCH_1}, ${CMAKE_MATCH_2})")
    endif()
    math(EXPR n_active "${n_active} + 1")
  endif()
endforeach()
if(n_active LESS 3)
  message(FATAL_ERROR "FAIL gear pair 13/40: ${n_active} closed pairs")
endif()
message(STATUS "PASS gear pair 13/40: all ${n_active} closed pairs within 0.5 mm of the pitch point")

# a pinion on a rack (tests/app/rack-pinion.prm, Type = gear rack): the
# normal force is T / r_b = 9400 / (40 cos 20 deg) = 250.08 and the rack's
# support takes the tangential force T / r = 235 along the pitch line, both
# within 0.05 % (measured -2.4e-5 and -4.2e-5: the discrete flank normals
# and the centre of pressure's offset turn and move the force a little);
# the contact closes only at the pitch point (0, 0): the centre of pressure
# within 0.1 mm
run_dealvem("rack and pinion" TRUE "rotation of boundary 0 about (0, 40): torque 9400 (applied)"
  ${TEST_DIR}/rack-pinion.prm)
file(READ ${WORK_DIR}/output/rack-pinion.json json)
string(JSON fn GET "${json}" interfaces 0 normal_force)
check_between(${fn} 249.95 250.21 "rack and pinion: normal force = T / r_b = 250.08 (0.05 %)")
string(JSON rx GET "${json}" reactions boundary_10 force_x)
check_between(${rx} -235.12 -234.88 "rack and pinion: the rack's support reaction along the pitch line = -T / r = -235 (0.05 %)")
string(JSON cx GET "${json}" interfaces 0 centre_x)
string(JSON cy GET "${json}" interfaces 0 centre_y)
check_between(${cx} -0.1 0.1 "rack and pinion: centre of pressure, x")
check_between(${cy} -0.1 0.1 "rack and pinion: centre of pressure, y")
