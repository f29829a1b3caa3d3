# needs: CGAL (the patch test and rigid-top.prm have Voronoi meshes)
# Runs the program `dealvem` as a user would:
# - --print-parameters lists the sections;
# - a good single-body file (tests/app/cantilever.prm: uniform tension, so
#   the errors must be at round-off) and the contact patch test of
#   examples/step-2 run and write their files; the patch test's interface
#   resultant, support reactions and moments (about two points) are those of
#   the load, and its node pairs' CSV has the pressure p at every pair;
#   a moment point that is not two finite numbers is refused;
# - a rigid top plate loaded by its resultant (tests/app/rigid-top.prm,
#   k = 2 and k = 1): uniform compression, errors at round-off;
# - bad input exits non-zero with a message naming the problem;
# - the JSON timings of the cantilever and the patch test cover the run:
#   their stages add up to its wall time (check_timings()).
include(${TEST_DIR}/program_checks.cmake)

file(REMOVE_RECURSE ${WORK_DIR}/output)
run_dealvem("print parameters" TRUE "subsection Contact" --print-parameters)
foreach(section "subsection Mesh" "subsection Material" "subsection Solver" "Young's modulus")
  string(FIND "${LAST_OUTPUT}" "${section}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "FAIL print parameters: no '${section}'")
  endif()
endforeach()

# a good single-body run: uniform tension is reproduced exactly
run_dealvem("cantilever" TRUE "Summary written to" ${TEST_DIR}/cantilever.prm)
foreach(f output/solution-cycle0.vtu output/solution-cycle1.vtu output/solution.json)
  if(NOT EXISTS ${WORK_DIR}/${f})
    message(FATAL_ERROR "FAIL cantilever: ${f} was not written")
  endif()
endforeach()
file(READ ${WORK_DIR}/output/solution.json json)
string(JSON dofs GET "${json}" cycles 1 dofs)
string(JSON l2 GET "${json}" cycles 1 errors L2)
if(dofs LESS 100 OR l2 GREATER 1e-12)
  message(FATAL_ERROR "FAIL cantilever: dofs ${dofs}, L2 error ${l2} (uniform tension must be exact)")
endif()
message(STATUS "PASS cantilever JSON: ${dofs} DoFs, L2 error ${l2}")
check_timings("cantilever timings" "${json}" mesh setup assembly solve errors postprocessing verification
              "output vtu" "output json")

# a rigid top plate under its resultant: uniform compression, exact for k = 2 and 1
file(READ ${TEST_DIR}/rigid-top.prm rigid_prm)
string(REPLACE "set Order = 2" "set Order = 1" rigid_prm_k1 "${rigid_prm}")
string(REPLACE "set Base name = rigid" "set Base name = rigid-k1" rigid_prm_k1 "${rigid_prm_k1}")
file(WRITE ${WORK_DIR}/rigid-top-k1.prm "${rigid_prm_k1}")
foreach(variant "${TEST_DIR}/rigid-top.prm;rigid" "${WORK_DIR}/rigid-top-k1.prm;rigid-k1")
  list(GET variant 0 prm_file)
  list(GET variant 1 base)
  run_dealvem("rigid top ${base}" TRUE "Summary written to" ${prm_file})
  file(READ ${WORK_DIR}/output/${base}.json json)
  string(JSON l2 GET "${json}" cycles 0 errors L2)
  if(l2 GREATER 1e-12)
    message(FATAL_ERROR "FAIL rigid top ${base}: L2 error ${l2} (uniform compression must be exact)")
  endif()
  message(STATUS "PASS rigid top ${base} JSON: L2 error ${l2}")
endforeach()

# the contact patch test as a parameter file
run_dealvem("contact patch test" TRUE "sigma_yy in [-10, -10]" ${SOURCE_DIR}/examples/step-2/patch-test.prm)
foreach(f output/patch-test-interface.csv output/patch-test-stress.svg output/patch-test-pressure.svg
          output/patch-test.json output/patch-test.vtu)
  if(NOT EXISTS ${WORK_DIR}/${f})
    message(FATAL_ERROR "FAIL contact patch test: ${f} was not written")
  endif()
endforeach()
file(READ ${WORK_DIR}/output/patch-test.json json)
string(JSON pmin GET "${json}" contact pressure_min)
string(JSON pmax GET "${json}" contact pressure_max)
# uniform pressure p = 10 at every pair (the patch test), to round-off
foreach(v ${pmin} ${pmax})
  if(v LESS 9.999999999 OR v GREATER 10.000000001)
    message(FATAL_ERROR "FAIL contact JSON: contact pressure ${v} is not 10 (range [${pmin}, ${pmax}])")
  endif()
endforeach()
message(STATUS "PASS contact JSON: contact pressure in [${pmin}, ${pmax}] = 10 to 1e-10")
check_timings("contact patch test timings" "${json}" mesh "node insertion" setup assembly solve postprocessing
              verification report "output csv" "output vtu" "output svg" "output json")

# a file that gives only the top-level 'Material' means it for every body:
# the patch test with body 1's section removed and another E and nu still
# has p = 10 at every pair (body 1 on the old default E = 1000, nu = 0.3
# gave 9.58 to 15.09); a bad nu of body 1 is refused by name
file(READ ${SOURCE_DIR}/examples/step-2/patch-test.prm patch_prm)
string(REGEX REPLACE "  subsection Material\n    set Young's modulus    = 7000\n    set Poisson's ratio    = 0.3\n  end\n"
       "" patch_one_material "${patch_prm}")
string(REPLACE "set Young's modulus     = 7000" "set Young's modulus     = 3000" patch_one_material "${patch_one_material}")
string(REPLACE "set Poisson's ratio     = 0.3" "set Poisson's ratio     = 0.2" patch_one_material "${patch_one_material}")
string(REPLACE "set Base name            = patch-test" "set Base name            = patch-one-material"
       patch_one_material "${patch_one_material}")
if(patch_one_material STREQUAL patch_prm OR NOT patch_one_material MATCHES "= 3000" OR
   patch_one_material MATCHES "modulus +=? 7000")
  message(FATAL_ERROR "FAIL one material: examples/step-2/patch-test.prm no longer has the expected Material sections")
endif()
file(WRITE ${WORK_DIR}/patch-one-material.prm "${patch_one_material}")
run_dealvem("one material for all bodies" TRUE "summary: output/patch-one-material.json" ${WORK_DIR}/patch-one-material.prm)
file(READ ${WORK_DIR}/output/patch-one-material.json json)
string(JSON pmin GET "${json}" contact pressure_min)
string(JSON pmax GET "${json}" contact pressure_max)
foreach(v ${pmin} ${pmax})
  if(v LESS 9.999999999 OR v GREATER 10.000000001)
    message(FATAL_ERROR "FAIL one material: contact pressure ${v} is not 10 (range [${pmin}, ${pmax}]): "
                        "body 1 did not take the top-level material")
  endif()
endforeach()
message(STATUS "PASS one material for all bodies: contact pressure in [${pmin}, ${pmax}]")
string(REPLACE "  set Boundary id offset = 10\n  end\n"
       "  set Boundary id offset = 10\n  end\n  subsection Material\n    set Poisson's ratio = 0.7\n  end\n"
       patch_bad_nu "${patch_one_material}")
file(WRITE ${WORK_DIR}/patch-bad-nu.prm "${patch_bad_nu}")
run_dealvem("bad nu of body 1" FALSE "Body 1/Material/Poisson's ratio" ${WORK_DIR}/patch-bad-nu.prm)

# what a user of a pressed part reads (the patch test: p = 10 on the top
# [0, 1] of the upper block, the slave side): the interface passes the load
# p * 1 = 10 to the lower block, the bottom (boundary 2) carries it and the
# point constraint nothing, at the line of action x = 0.5: about the default
# moment point (0, 0) both moments are 10 * 0.5 = 5 (to 1e-10), about
# (0.5, 7) on the line of symmetry zero (to 1e-10 of 10 * 7); every node
# pair has the pressure 10 (to 1e-10) and is closed
foreach(q "interfaces 0" "reactions boundary_2")
  separate_arguments(keys UNIX_COMMAND "${q}")
  string(JSON fy GET "${json}" ${keys} force_y)
  string(JSON m GET "${json}" ${keys} moment)
  check_value(${fy} 10 "contact patch test: ${q} force_y")
  check_value(${m} 5 "contact patch test: ${q} moment about (0, 0)")
  check_json_roundoff("${json}" "contact patch test" ${keys} force_x)
endforeach()
check_json_roundoff("${json}" "contact patch test" reactions point_0 force_x)
file(STRINGS ${WORK_DIR}/output/patch-test-interface.csv rows)
list(GET rows 0 header)
string(REPLACE "," ";" header "${header}")
list(FIND header "pressure" p_col)
list(FIND header "status" status_col)
list(FIND header "normal_y" ny_col)
list(REMOVE_AT rows 0)
list(LENGTH rows n_rows)
string(JSON n_pairs GET "${json}" contact node_pairs)
if(p_col EQUAL -1 OR status_col EQUAL -1 OR ny_col EQUAL -1 OR NOT n_rows EQUAL n_pairs)
  message(FATAL_ERROR "FAIL contact patch test CSV: ${n_rows} rows for ${n_pairs} pairs, header '${header}'")
endif()
foreach(row ${rows})
  string(REPLACE "," ";" f "${row}")
  list(GET f ${p_col} p)
  list(GET f ${status_col} status)
  list(GET f ${ny_col} ny)
  if(p LESS 9.999999999 OR p GREATER 10.000000001 OR NOT status STREQUAL "closed" OR NOT ny EQUAL 1)
    message(FATAL_ERROR "FAIL contact patch test CSV: a pair with pressure ${p}, status ${status}, normal_y ${ny}")
  endif()
endforeach()
message(STATUS "PASS contact patch test CSV: ${n_rows} pairs closed with the pressure 10 to 1e-10")
file(READ ${SOURCE_DIR}/examples/step-2/patch-test.prm contact_prm)
string(REGEX REPLACE "(set Base name[^\n]*)" "\\1-moment\n  set Moment point = 0.5, 7" moment_prm "${contact_prm}")
file(WRITE ${WORK_DIR}/patch-test-moment.prm "${moment_prm}")
run_dealvem("contact patch test, moments about (0.5, 7)" TRUE "reaction on boundary 2: force (0, 10)"
  ${WORK_DIR}/patch-test-moment.prm)
file(READ ${WORK_DIR}/output/patch-test-moment.json json)
# (round-off of the force 10 at the distance 7: within 1e-10 of 70)
string(JSON m_interface GET "${json}" interfaces 0 moment)
string(JSON m_bottom GET "${json}" reactions boundary_2 moment)
check_balance("contact patch test: the interface's moment about (0.5, 7)" 10 70 ${m_interface})
check_balance("contact patch test: the bottom's moment about (0.5, 7)" 10 70 ${m_bottom})
file(STRINGS ${WORK_DIR}/output/patch-test-moment-reactions.csv rows)
# (force_y is 10 to 1e-10, on either side: the round-off may land below 10)
if(NOT rows MATCHES "^step,time,support,boundary_id,force_x,force_y,moment;1,1,boundary_2,2,0,(10(\\.0000000000[0-9]*)?|9\\.9999999999[0-9]*),[-0-9.e]+;1,1,point_0,-1,")
  message(FATAL_ERROR "FAIL contact patch test: patch-test-moment-reactions.csv is\n${rows}")
endif()
# a moment point that is not two finite numbers is refused, naming the entry
foreach(bad "1, inf" "0.5")
  string(REGEX REPLACE "(set Base name[^\n]*)" "\\1-bad\n  set Moment point = ${bad}" bad_prm "${contact_prm}")
  file(WRITE ${WORK_DIR}/patch-test-bad-moment.prm "${bad_prm}")
  run_dealvem("bad input: moment point '${bad}'" FALSE "Parameter 'Output/Moment point'"
    ${WORK_DIR}/patch-test-bad-moment.prm)
endforeach()

# the contact patch test with nu = 0 and the top of the upper body a rigid
# plate under the resultant (0, -p) instead of the pressure p: the same
# uniform state (the rigid plate allows it when nu = 0), through the
# contact problem's support check and load distribution
file(READ ${SOURCE_DIR}/examples/step-2/patch-test.prm contact_prm)
string(REGEX REPLACE "Poisson's ratio( *)= 0.3" "Poisson's ratio\\1= 0" contact_prm "${contact_prm}")
string(REGEX REPLACE "set Pressure( *)= 13 : p" "set Rigid boundary = 13 : 0, -p" contact_prm "${contact_prm}")
string(REPLACE "patch-test" "rigid-contact" contact_prm "${contact_prm}")
file(WRITE ${WORK_DIR}/rigid-contact.prm "${contact_prm}")
run_dealvem("contact with a rigid top" TRUE "sigma_yy in [-10, -10]" ${WORK_DIR}/rigid-contact.prm)
string(FIND "${LAST_OUTPUT}" "contact pressure on active pairs: min 10, max 10" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "FAIL contact with a rigid top: the contact pressure is not 10\n${LAST_OUTPUT}")
endif()

# bad input: each case a small parameter file
function(bad_case name fragment text)
  file(WRITE ${WORK_DIR}/${name}.prm "${text}")
  run_dealvem("bad input: ${name}" FALSE "${fragment}" ${WORK_DIR}/${name}.prm)
endfunction()
set(ok_bc "subsection Boundary conditions and loads\n  set Dirichlet = 0 : xy : 0, 0\nend\n")
bad_case(unknown_parameter "Colour" "set Colour = blue\n")
bad_case(poisson "Poisson's ratio" "subsection Material\n  set Poisson's ratio = 0.7\nend\n${ok_bc}")
bad_case(order "Order" "subsection Discretization\n  set Order = 3\nend\n${ok_bc}")
bad_case(dirichlet "Dirichlet entry" "subsection Boundary conditions and loads\n  set Dirichlet = 0 : z : 1\nend\n")
bad_case(missing_mesh "no-such-mesh.vtk" "subsection Mesh\n  set Type = vtk file\n  set File name = no-such-mesh.vtk\nend\n${ok_bc}")
file(WRITE ${WORK_DIR}/cw.vtk "# vtk DataFile Version 3.0\ncw\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 double\n0 0 0\n1 0 0\n0 1 0\nCELLS 1 4\n3 0 2 1\nCELL_TYPES 1\n7\n")
bad_case(clockwise_file "cw.vtk:10" "subsection Mesh\n  set Type = vtk file\n  set File name = cw.vtk\nend\n${ok_bc}")
bad_case(unsupported "Unsupported body" "subsection Boundary conditions and loads\n  set Traction = 1 : 1, 0\nend\n")
bad_case(expression "cannot parse" "subsection Boundary conditions and loads\n  set Dirichlet = 0 : xy : 0, sin(\nend\n")
bad_case(missing_boundary_id "Boundary conditions and loads/Pressure entry '13 : p'': no boundary edge of mesh" "subsection Boundary conditions and loads\n  set Function constants = p=1\n  set Dirichlet = 0 : xy : 0, 0\n  set Pressure = 13 : p\nend\n")
bad_case(not_finite "the expression '1/(x-x)' evaluates to inf at the point" "subsection Boundary conditions and loads\n  set Dirichlet = 0 : xy : 0, 0\n  set Body force = 0, 1/(x-x)\nend\n")
bad_case(point_conflict "is already constrained by Boundary conditions and loads/Dirichlet entry '0 : xy : 0, 0' to the value 0, which conflicts with the value 1" "subsection Boundary conditions and loads\n  set Dirichlet = 0 : xy : 0, 0\n  set Point constraints = 0, 0 : x : 1\nend\n")
bad_case(rigid_conflict "Rigid boundary entry '3 : 0, -1'' on mesh" "subsection Boundary conditions and loads\n  set Dirichlet = 0 : xy : 0, 0\n  set Rigid boundary = 3 : 0, -1\nend\n")
run_dealvem("bad input: missing parameter file" FALSE "cannot open" ${WORK_DIR}/does-not-exist.prm)
