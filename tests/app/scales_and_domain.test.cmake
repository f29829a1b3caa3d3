# Issue 37: the finite-strain paths at other scales, Newton iterates outside
# the domain of the law, and bodies on which no force acts.
# - Class 4: Saint Venant-Kirchhoff in plane stress, a strip on rollers
#   pulled by the traction t = 1.29 E (and 3 E) in one load step. The first
#   Newton iterate (the linear response, F_xx = 2.29) has no plane-stress
#   state and used to end the run; the line search steps back from it. The
#   state is homogeneous uniaxial stress, S_xx = E E_xx, so
#   lambda (lambda^2 - 1) / 2 = t / E, lambda_y^2 = 1 - nu (lambda^2 - 1)
#   and sigma_xx = t lambda / (lambda lambda_y^2): 2480.8218489797 E / 1000
#   and, for t = 3 E (lambda = 2 exactly), 30 E; to 1e-10, at E = 1000, and
#   (t = 1.29 E) scaled by 1e-6 and 1e9: class 2 on the one-body path, every
#   stress scales with E.
# - Class 2: the finite-sliding block (k = 1, four steps) scaled by 1e-6 and
#   1e9 (moduli and loads): the contact forces scale with the factor, to
#   1e-6 relative (the pairing tolerance is 1e-8).
# - Class 5: a block moved rigidly onto its base by its Dirichlet data
#   (tied, E = 300 on 1000) and a Voronoi body (k = 2) translated by its
#   Dirichlet data: no force acts, the verification passes (it used to
#   report forces that "cannot be resolved in double precision"), and the
#   contact force is round-off.
include(${TEST_DIR}/program_checks.cmake)
file(REMOVE_RECURSE ${WORK_DIR}/output)

# x * 10^k for a decimal mantissa text and an integer k, as text
function(scaled text k out)
  if(text MATCHES "^(-?[0-9.]+)e([-+]?[0-9]+)$")
    set(m "${CMAKE_MATCH_1}")
    math(EXPR e "${CMAKE_MATCH_2} + ${k}")
  else()
    set(m "${text}")
    set(e ${k})
  endif()
  set(${out} "${m}e${e}" PARENT_SCOPE)
endfunction()

# --- class 4: Saint Venant-Kirchhoff in plane stress, one load step
foreach(case "1.29;2.4808218489797;0 -6 9" "3;30;0")
  list(GET case 0 ratio)
  list(GET case 1 sigma)
  list(GET case 2 scales)
  string(REPLACE " " ";" scales "${scales}")
  foreach(k ${scales})
    scaled(1000 ${k} E)
    scaled("${ratio}e3" ${k} t)
    math(EXPR k3 "${k} + 3")
    scaled(${sigma} ${k3} expected)
    set(name "svk-${ratio}-${k}")
    file(WRITE ${WORK_DIR}/${name}.prm "subsection Mesh
  set Type               = structured quads
  set Subdivisions       = 4, 2
  set Upper right corner = 2, 1
end
subsection Material
  set Law             = saint venant-kirchhoff
  set Model           = plane stress
  set Young's modulus = ${E}
  set Poisson's ratio = 0.3
end
subsection Boundary conditions and loads
  set Dirichlet = 0 : x : 0; 2 : y : 0
  set Traction  = 1 : ${t}, 0
end
subsection Finite strain
  set Enabled = true
end
subsection Output
  set Write VTU = false
  set Base name = ${name}
end
")
    run_dealvem("${name}" TRUE "load step 1 of 1" ${WORK_DIR}/${name}.prm)
    file(READ ${WORK_DIR}/output/${name}.json json)
    string(JSON s GET "${json}" cycles 0 finite_strain steps 1 max_cauchy_norm)
    check_value(${s} ${expected} "${name}: sigma_xx of uniaxial stress")
  endforeach()
endforeach()

# --- class 2: the finite-sliding block at three scales
foreach(k 0 -6 9)
  scaled(1000 ${k} E0)
  scaled(300 ${k} E1)
  file(WRITE ${WORK_DIR}/sliding-${k}.prm "set Number of bodies = 2
subsection Mesh
  set Type               = structured quads
  set Lower left corner  = 0, 0
  set Upper right corner = 3, 1
  set Subdivisions       = 6, 2
end
subsection Material
  set Law             = neo-hooke
  set Young's modulus = ${E0}
  set Poisson's ratio = 0.3
end
subsection Body 1
  subsection Mesh
    set Type               = structured quads
    set Lower left corner  = 0.25, 1
    set Upper right corner = 1.25, 2
    set Subdivisions       = 3, 3
    set Boundary id offset = 10
  end
  subsection Material
    set Young's modulus = ${E1}
    set Poisson's ratio = 0.25
  end
end
subsection Finite strain
  set Enabled = true
end
subsection Contact
  set Pairs                = 3 : 12
  set Tangential           = coulomb
  set Friction coefficient = 0.3
end
subsection Boundary conditions and loads
  set Dirichlet = 2 : xy : 0, 0; 13 : xy : 0.5*max(t-0.1,0), -0.02*min(t,0.1)/0.1
end
subsection Load steps
  set Number of steps = 4
  set Final time      = 0.7
end
subsection Output
  set Write VTU      = false
  set Write CSV      = false
  set Write pictures = false
  set Base name      = sliding-${k}
end
")
  run_dealvem("finite sliding scaled by 1e${k}" TRUE "step 4 (t = 0.7)" ${WORK_DIR}/sliding-${k}.prm)
  file(READ ${WORK_DIR}/output/sliding-${k}.json json)
  string(JSON n${k} GET "${json}" steps 4 interfaces 0 normal_force_y)
  string(JSON f${k} GET "${json}" steps 4 interfaces 0 friction_force_x)
endforeach()
foreach(k -6 9)
  scaled(${n0} ${k} n)
  check_relative(${n} ${n${k}} 6 "finite sliding scaled by 1e${k}: normal force / 1e${k}")
  scaled(${f0} ${k} f)
  check_relative(${f} ${f${k}} 6 "finite sliding scaled by 1e${k}: friction force / 1e${k}")
endforeach()

# --- class 5: no force acts
run_dealvem("block moved rigidly onto its base (tied)" TRUE "verification: every body in equilibrium"
  ${TEST_DIR}/rigid-move-tied.prm)
file(READ ${WORK_DIR}/output/rigid-move-tied.json json)
check_json_roundoff("${json}" "rigid move, tied: total contact force" contact total_force_y)
# the same with unilateral frictionless contact: every pair touches without
# force, and the active set must not follow the round-off until it cycles
file(READ ${TEST_DIR}/rigid-move-tied.prm _tied)
string(REPLACE "set Normal = tied" "set Normal = unilateral\n  set Tangential = frictionless" _unilateral "${_tied}")
string(REPLACE "rigid-move-tied" "rigid-move-unilateral" _unilateral "${_unilateral}")
file(WRITE ${WORK_DIR}/rigid-move-unilateral.prm "${_unilateral}")
run_dealvem("block moved rigidly onto its base (unilateral)" TRUE "verification: every body in equilibrium"
  ${WORK_DIR}/rigid-move-unilateral.prm)
file(READ ${WORK_DIR}/output/rigid-move-unilateral.json json)
check_json_roundoff("${json}" "rigid move, unilateral: total contact force" contact total_force_y)
file(WRITE ${WORK_DIR}/translated.prm "subsection Mesh
  set Type            = voronoi
  set Number of cells = 20
end
subsection Discretization
  set Order = 2
end
subsection Boundary conditions and loads
  set Dirichlet = 0 : xy : 0.3, -0.7; 1 : xy : 0.3, -0.7
end
subsection Output
  set Write VTU = false
  set Base name = translated
end
")
run_dealvem("a body translated by its Dirichlet data" TRUE "verification: in equilibrium"
  ${WORK_DIR}/translated.prm)
