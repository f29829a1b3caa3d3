# The time t in one-body runs (issue 38): one-body problems read 'Load
# steps' as contact problems do, step k of N at t_k = k * Final time / N.
# - Small strain (linear, static): a block on rollers under the traction
#   -5 t on its top, 'Final time = 2' and 3 steps, is solved once at t = 2
#   (a note says so): the largest von Mises stress equals that of the same
#   run with the traction -10 and no 'Load steps' section to 1e-10
#   relative, and the exact uniaxial solution written with t (compared at
#   t = 2) has round-off errors in both runs (at t = 1 the errors would be
#   1).
# - Finite strain (Neo-Hooke, k = 2): the whole boundary prescribed to the
#   homogeneous deformation u = (0.1 t^2 x, -0.05 t y), 4 steps to t = 2:
#   step k must reach the values of t_k = k/2 at the monitored corner
#   (1, 1), i.e. (0.1 t_k^2, -0.05 t_k) to 1e-10 relative (proportional load
#   factors k/4 of the data at t = 2 would give (0.1 k, -0.025 k), 0.2
#   instead of 0.1 at step 2); the program says that it steps "at the times
#   t of the expressions", and the errors against the exact solution at
#   t = 2 are round-off.
include(${TEST_DIR}/program_checks.cmake)
file(REMOVE_RECURSE ${WORK_DIR}/output)

# --- small strain: traction -5 t at t = 2 against the traction -10
set(linear "subsection Mesh
  set Type         = structured quads
  set Subdivisions = 3, 3
end
subsection Material
  set Young's modulus = 7000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions and loads
  set Dirichlet         = 2 : y : 0
  set Point constraints = 0, 0 : x : 0
  set Traction          = 3 : 0, @LOAD@
end
subsection Exact solution
  set Displacement = 0.3*1.3*@SIGMA@/7000*x, -0.91*@SIGMA@/7000*y
end
@STEPS@
subsection Output
  set Folder    = output
  set Base name = @BASE@
  set Write VTU = false
end
")
set(LOAD "-5*t")
set(SIGMA "5*t")
set(STEPS "subsection Load steps\n  set Number of steps = 3\n  set Final time      = 2\nend")
set(BASE "timed")
string(CONFIGURE "${linear}" text @ONLY)
file(WRITE ${WORK_DIR}/timed.prm "${text}")
run_dealvem("one body, small strain, traction -5 t at Final time 2" TRUE
  "the program solves it once, with every expression at t = 2" ${WORK_DIR}/timed.prm)
set(LOAD "-10")
set(SIGMA "10")
set(STEPS "")
set(BASE "fixed")
string(CONFIGURE "${linear}" text @ONLY)
file(WRITE ${WORK_DIR}/fixed.prm "${text}")
run_dealvem("one body, small strain, traction -10" TRUE "" ${WORK_DIR}/fixed.prm)
file(READ ${WORK_DIR}/output/timed.json timed)
file(READ ${WORK_DIR}/output/fixed.json fixed)
foreach(e L2 H1_seminorm)
  check_json_roundoff("${timed}" "traction -5 t, t = 2" cycles 0 errors ${e})
  check_json_roundoff("${fixed}" "traction -10" cycles 0 errors ${e})
endforeach()
string(JSON vm_timed GET "${timed}" cycles 0 max_von_mises)
string(JSON vm_fixed GET "${fixed}" cycles 0 max_von_mises)
check_relative(${vm_fixed} ${vm_timed} 10 "max von Mises of the traction -5 t at t = 2 and of -10")

# --- finite strain: the Dirichlet data of t_k at step k
file(WRITE ${WORK_DIR}/finite.prm "subsection Mesh
  set Type         = structured quads
  set Subdivisions = 3, 3
end
subsection Material
  set Young's modulus = 10
  set Poisson's ratio = 0.3
  set Law             = neo-hooke
end
subsection Boundary conditions and loads
  set Dirichlet = 0 : xy : 0.1*t*t*x, -0.05*t*y; 1 : xy : 0.1*t*t*x, -0.05*t*y; 2 : xy : 0.1*t*t*x, -0.05*t*y; 3 : xy : 0.1*t*t*x, -0.05*t*y
end
subsection Exact solution
  set Displacement = 0.1*t*t*x, -0.05*t*y
end
subsection Finite strain
  set Enabled       = true
  set Monitor point = 1, 1
end
subsection Load steps
  set Number of steps = 4
  set Final time      = 2
end
subsection Output
  set Folder    = output
  set Base name = finite
  set Write VTU = false
end
")
run_dealvem("one body, finite strain, Dirichlet data in t" TRUE "load steps at the times t of the expressions"
  ${WORK_DIR}/finite.prm)
file(READ ${WORK_DIR}/output/finite.json json)
foreach(step 1 2 3 4)
  math(EXPR t2 "${step} * ${step}") # (2 t_k)^2 = k^2: u_x = 0.1 t_k^2 = 0.025 k^2
  string(JSON ux GET "${json}" cycles 0 finite_strain steps ${step} monitor_ux)
  string(JSON uy GET "${json}" cycles 0 finite_strain steps ${step} monitor_uy)
  string(JSON t GET "${json}" cycles 0 finite_strain steps ${step} time)
  # expected values as decimals
  math(EXPR ux_e "25 * ${t2}")      # in units of 1e-3
  math(EXPR uy_e "25 * ${step}")    # -0.05 t_k = -0.025 k, units of 1e-3
  set(ux_expected "0.0${ux_e}")
  if(ux_e GREATER_EQUAL 100)
    set(ux_expected "0.${ux_e}")
  endif()
  set(uy_expected "-0.0${uy_e}")
  if(uy_e GREATER_EQUAL 100)
    set(uy_expected "-0.${uy_e}")
  endif()
  check_value(${ux} ${ux_expected} "finite strain step ${step} (t = ${t}): u_x(1, 1)")
  check_value(${uy} ${uy_expected} "finite strain step ${step} (t = ${t}): u_y(1, 1)")
endforeach()
foreach(e L2 H1_seminorm)
  check_json_roundoff("${json}" "finite strain at t = 2" cycles 0 errors ${e})
endforeach()
