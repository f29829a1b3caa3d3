# needs: CGAL (Voronoi meshes)
# The finite-strain path of the program `dealvem` (one body,
# 'Finite strain/Enabled = true'), run from parameter files as a user would:
# - a homogeneous deformation F = [[1.1, 0.3], [0.05, 0.7]] prescribed on
#   the whole boundary of a Voronoi mesh (k = 2, Neo-Hooke) and of a
#   non-convex mesh (k = 1, Saint Venant-Kirchhoff), and in plane stress
#   on perturbed quads (k = 1, Neo-Hooke), 4 load steps: the
#   virtual elements contain it, so the errors against the exact
#   displacement (JSON) are at round-off (below 1e-10) and the monitored
#   corner (1, 1) moves by (F - I)(1, 1) = (0.4, -0.25) to 1e-10 relative,
#   the Cauchy stress of the output has the norm of the law's at F (1e-10);
#   every step converged, wrote its VTU file and appears in the .pvd;
# - examples/parameters/finite-strain-cook.prm (Cook's membrane, k = 2,
#   2178 DoFs): the tip u_y within 0.5 % of the reference 8.69919 (the
#   bound of tests/elasticity/cook_membrane), and its JSON timings cover
#   the run (check_timings());
# - examples/parameters/finite-strain-rotation.prm (90 degree rotation on
#   the boundary, 6 steps): the largest cell Cauchy stress is below 1e-10
#   (E = 1000: the small-strain answer would be 2.72 E) and the errors
#   against the rotation are at round-off;
# - a hyperelastic law at small strain (the default): the program solves
#   linear elasticity with the law's linearization, says so, and a uniform
#   tension under a traction matches the plane-strain linear solution of
#   the same E, nu to round-off;
# - the contact patch test of examples/step-2 with 'Material/Law =
#   neo-hooke': solved at small strain with the linearization (a note says
#   so), the pressure is p = 10 at every pair to 1e-10;
# - a Newton step that cannot converge (the prescribed F_yy = -0.2 inverts
#   the cells at load factor 0.9): non-zero exit with the solver's message
#   naming step 9 and its load factor; the files of steps 1-8 are kept and
#   the JSON summary says "failed" with 8 converged steps.
include(${TEST_DIR}/program_checks.cmake)
set(RUN_TIMEOUT 600)
set(EXAMPLES ${SOURCE_DIR}/examples/parameters)
file(REMOVE_RECURSE ${WORK_DIR}/output)

# every step converged, with its file in the series
function(check_steps json base n what)
  string(JSON converged GET "${json}" cycles 0 finite_strain converged_steps)
  if(NOT converged EQUAL n)
    message(FATAL_ERROR "FAIL ${what}: ${converged} of ${n} load steps converged")
  endif()
  file(READ ${WORK_DIR}/output/${base}.pvd pvd)
  foreach(s RANGE 1 ${n})
    string(JSON c GET "${json}" cycles 0 finite_strain steps ${s} converged)
    string(JSON it GET "${json}" cycles 0 finite_strain steps ${s} newton_iterations)
    if(NOT c STREQUAL "true" OR it LESS 1)
      message(FATAL_ERROR "FAIL ${what}: step ${s}: converged ${c}, ${it} Newton iterations")
    endif()
    string(LENGTH "00${s}" len)
    math(EXPR cut "${len} - 3")
    string(SUBSTRING "00${s}" ${cut} 3 nnn)
    if(NOT EXISTS ${WORK_DIR}/output/${base}-step-${nnn}.vtu)
      message(FATAL_ERROR "FAIL ${what}: output/${base}-step-${nnn}.vtu was not written")
    endif()
    string(FIND "${pvd}" "file=\"${base}-step-${nnn}.vtu\"" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "FAIL ${what}: ${base}.pvd lacks step ${s}\n${pvd}")
    endif()
  endforeach()
  string(JSON status GET "${json}" status)
  if(NOT status STREQUAL "complete")
    message(FATAL_ERROR "FAIL ${what}: status ${status}")
  endif()
  message(STATUS "PASS ${what}: ${n} load steps converged, each with its VTU file in ${base}.pvd")
endfunction()

# --- homogeneous finite deformation, exact on polygons
set(exact "0.1*x + 0.3*y, 0.05*x - 0.3*y")
# (the last field: |sigma| of the law at F, E = 10, nu = 0.3, computed
# independently: sigma = (mu F F^T + (lambda ln J - mu) I) / J for Neo-Hooke,
# F S F^T / J with S = lambda tr(E) I + 2 mu E for Saint Venant-Kirchhoff)
# In plane stress (Neo-Hooke, k = 1) the thickness stretch f solves
# mu (f^2 - 1) + lambda ln(f det F) = 0 (f = 1.11920738772318) and sigma is
# the in-plane block at J = f det F.
foreach(variant "voronoi;2;neo-hooke;5.14082506187988;plane strain"
                "nonconvex;1;saint venant-kirchhoff;2.21590388540504;plane strain"
                "perturbed quads;1;neo-hooke;3.86350519847767;plane stress")
  list(GET variant 0 type)
  list(GET variant 1 k)
  list(GET variant 2 law)
  list(GET variant 3 sigma_norm)
  list(GET variant 4 model)
  string(REPLACE " " "_" tag "${type}-${law}")
  string(REPLACE " " "_" type_tag "${type}")
  file(WRITE ${WORK_DIR}/homogeneous-${type_tag}.prm "subsection Mesh
  set Type            = ${type}
  set Number of cells = 40
  set Subdivisions    = 5, 4
end
subsection Material
  set Young's modulus = 10
  set Poisson's ratio = 0.3
  set Law             = ${law}
  set Model           = ${model}
end
subsection Discretization
  set Order = ${k}
end
subsection Boundary conditions and loads
  set Dirichlet = 0 : xy : ${exact}; 1 : xy : ${exact}; 2 : xy : ${exact}; 3 : xy : ${exact}
end
subsection Exact solution
  set Displacement = ${exact}
end
subsection Finite strain
  set Enabled       = true
  set Monitor point = 1, 1
end
subsection Load steps
  set Number of steps = 4
end
subsection Output
  set Base name = homogeneous-${type_tag}
end
")
  run_dealvem("homogeneous F, ${type}, k = ${k}, ${law}, ${model}" TRUE "Newton history"
    ${WORK_DIR}/homogeneous-${type_tag}.prm)
  file(READ ${WORK_DIR}/output/homogeneous-${type_tag}.json json)
  foreach(e L2 H1_seminorm)
    check_json_roundoff("${json}" "homogeneous ${type}" cycles 0 errors ${e})
  endforeach()
  string(JSON ux GET "${json}" cycles 0 finite_strain monitor_point ux)
  string(JSON uy GET "${json}" cycles 0 finite_strain monitor_point uy)
  check_value(${ux} 0.4 "homogeneous ${type}: u_x(1, 1)")
  check_value(${uy} -0.25 "homogeneous ${type}: u_y(1, 1)")
  # the Cauchy stress of the output is the law's at F in every cell
  string(JSON s GET "${json}" cycles 0 max_cauchy_norm)
  check_relative(${sigma_norm} ${s} 10 "homogeneous ${type}: |Cauchy stress|")
  string(JSON l GET "${json}" material law)
  if(NOT l STREQUAL "${law}")
    message(FATAL_ERROR "FAIL homogeneous ${type}: material.law = '${l}'")
  endif()
  check_steps("${json}" homogeneous-${type_tag} 4 "homogeneous ${type}")
endforeach()

# --- Cook's membrane: the tip displacement within 0.5 % of the reference
run_dealvem("finite-strain-cook.prm" TRUE "Newton history" ${EXAMPLES}/finite-strain-cook.prm)
file(READ ${WORK_DIR}/output/cook.json json)
check_steps("${json}" cook 10 "Cook's membrane")
string(JSON dofs GET "${json}" cycles 0 dofs)
string(JSON uy GET "${json}" cycles 0 finite_strain monitor_point uy)
# 0.995 * 8.69919 = 8.655694, 1.005 * 8.69919 = 8.742686: compared in units
# of 1e-6 (CMake has integer arithmetic only)
if(NOT uy MATCHES "^([0-9]+)\\.([0-9][0-9][0-9][0-9][0-9][0-9])")
  message(FATAL_ERROR "FAIL Cook's membrane: tip u_y = '${uy}' is not a positive decimal number")
endif()
math(EXPR micro "${CMAKE_MATCH_1} * 1000000 + 1${CMAKE_MATCH_2} - 1000000")
if(micro LESS 8655694 OR micro GREATER 8742686)
  message(FATAL_ERROR "FAIL Cook's membrane: tip u_y = ${uy} is not within 0.5 % of 8.69919")
endif()
message(STATUS "PASS Cook's membrane (${dofs} DoFs): tip u_y = ${uy}, within 0.5 % of 8.69919")
check_timings("Cook's membrane timings" "${json}" mesh setup "finite strain solve" postprocessing verification
              "output vtu" "output json")

# --- a rotation by 90 degrees: stress-free
run_dealvem("finite-strain-rotation.prm" TRUE "Newton history" ${EXAMPLES}/finite-strain-rotation.prm)
file(READ ${WORK_DIR}/output/rotation.json json)
check_steps("${json}" rotation 6 "90 degree rotation")
check_json_roundoff("${json}" "90 degree rotation" cycles 0 max_cauchy_norm)
foreach(e L2 H1_seminorm)
  check_json_roundoff("${json}" "90 degree rotation" cycles 0 errors ${e})
endforeach()

# --- a hyperelastic law at small strain: its linearization, the linear law
# sigma_xx = p = 1, plane strain, E = 1000, nu = 0.3:
# eps_xx = (1 - nu^2) p / E = 9.1e-4, eps_yy = -nu (1 + nu) p / E = -3.9e-4
file(WRITE ${WORK_DIR}/small-strain-svk.prm "subsection Mesh
  set Type         = structured quads
  set Subdivisions = 4, 4
end
subsection Material
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
  set Law             = saint venant-kirchhoff
end
subsection Boundary conditions and loads
  set Roller   = 0, 2
  set Traction = 1 : 1, 0
end
subsection Exact solution
  set Displacement = 9.1e-4*x, -3.9e-4*y
end
subsection Output
  set Base name = small-strain-svk
end
")
run_dealvem("saint venant-kirchhoff at small strain" TRUE
  "the program solves linear elasticity with the law's linearization at F = I" ${WORK_DIR}/small-strain-svk.prm)
file(READ ${WORK_DIR}/output/small-strain-svk.json json)
foreach(e L2 H1_seminorm)
  check_json_roundoff("${json}" "saint venant-kirchhoff at small strain" cycles 0 errors ${e})
endforeach()

# --- a contact problem with a hyperelastic law: small strain, linearization
file(READ ${SOURCE_DIR}/examples/step-2/patch-test.prm contact_prm)
file(WRITE ${WORK_DIR}/patch-test-neo-hooke.prm "${contact_prm}
subsection Material
  set Law = neo-hooke
end
subsection Output
  set Base name = patch-test-neo-hooke
end
")
run_dealvem("contact patch test, neo-hooke" TRUE
  "contact problems are solved at small strain, with the law's linearization at F = I"
  ${WORK_DIR}/patch-test-neo-hooke.prm)
file(READ ${WORK_DIR}/output/patch-test-neo-hooke.json json)
foreach(key pressure_min pressure_max)
  string(JSON p GET "${json}" contact ${key})
  check_relative(10 ${p} 10 "contact patch test, neo-hooke: ${key}")
endforeach()

# --- a load step that inverts the cells: a clean failure, earlier steps kept
file(WRITE ${WORK_DIR}/inverting.prm "subsection Mesh
  set Type         = structured quads
  set Subdivisions = 3, 3
end
subsection Material
  set Law = neo-hooke
end
subsection Discretization
  set Order = 1
end
subsection Boundary conditions and loads
  set Dirichlet = 0 : xy : 0, -1.2*y; 1 : xy : 0, -1.2*y; 2 : xy : 0, -1.2*y; 3 : xy : 0, -1.2*y
end
subsection Finite strain
  set Enabled = true
end
subsection Load steps
  set Number of steps = 10
end
subsection Output
  set Base name = inverting
end
")
run_dealvem("inverting boundary values" FALSE "load step 9 (load factor 0.9) did not converge"
  ${WORK_DIR}/inverting.prm)
file(READ ${WORK_DIR}/output/inverting.json json)
string(JSON status GET "${json}" status)
string(JSON converged GET "${json}" cycles 0 finite_strain converged_steps)
string(JSON step9_converged GET "${json}" cycles 0 finite_strain steps 9 converged)
if(NOT status STREQUAL "failed" OR NOT converged EQUAL 8 OR NOT step9_converged STREQUAL "false")
  message(FATAL_ERROR "FAIL inverting: status ${status}, ${converged} converged steps, step 9 converged: ${step9_converged}")
endif()
foreach(f inverting-step-008.vtu inverting.pvd)
  if(NOT EXISTS ${WORK_DIR}/output/${f})
    message(FATAL_ERROR "FAIL inverting: output/${f} of the converged steps is missing")
  endif()
endforeach()
if(EXISTS ${WORK_DIR}/output/inverting-step-009.vtu)
  message(FATAL_ERROR "FAIL inverting: the failed step 9 wrote a VTU file")
endif()
message(STATUS "PASS inverting: step 9 fails cleanly, steps 1-8 kept, JSON status 'failed'")
