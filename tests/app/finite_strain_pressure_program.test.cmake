# A pressure at finite strain through the program (issue 38): the unit
# square (structured quads, k = 2, Neo-Hooke, E = 10, nu = 0.3, plane
# strain) on rollers along x = 0 and y = 0, free on the right, the pressure
# p = 1 on the top side, 3 load steps. The state is homogeneous (uniaxial
# stress), which the virtual elements contain, so the Cauchy stress of the
# output files is that of the load to round-off:
# - 'Finite strain/Pressure load = follower' (the default, also run without
#   the entry): p per unit current length, sigma_yy = -p and sigma_xx =
#   sigma_xy = 0 in every cell (1e-9 p);
# - 'dead': p per unit reference length, the nominal P_yy = -p, so
#   sigma_yy = -p / lambda_x with lambda_x = 1 + u_x(1, 1) (1e-9 relative);
# - the two runs' u_y(1, 1) differ by more than 1 %;
# - the last step's VTU file has cauchy_stress, cauchy_stress_zz,
#   cauchy_von_mises, det_F and principal_stretches as point and cell data
#   (read by VTK's reader, read_vtu.py in its finite-strain mode, where
#   python3 has vtk; else by text) and no small-strain 'stress' or
#   'von_mises'; cauchy_von_mises there equals the von Mises stress of
#   (0, sigma_yy, sigma_zz, 0) and principal_stretches (lambda_x, lambda_y,
#   1) with lambda_y = 1 + u_y(1, 1).
include(${TEST_DIR}/program_checks.cmake)
file(REMOVE_RECURSE ${WORK_DIR}/output)
set(python /usr/bin/python3)

foreach(kind follower dead default)
  if(kind STREQUAL "default")
    set(entry "")
  else()
    set(entry "  set Pressure load = ${kind}\n")
  endif()
  file(WRITE ${WORK_DIR}/${kind}.prm "subsection Mesh
  set Type         = structured quads
  set Subdivisions = 3, 3
end
subsection Material
  set Young's modulus = 10
  set Poisson's ratio = 0.3
  set Law             = neo-hooke
end
subsection Boundary conditions and loads
  set Roller   = 0, 2
  set Pressure = 3 : 1
end
subsection Finite strain
  set Enabled       = true
  set Monitor point = 1, 1
${entry}end
subsection Load steps
  set Number of steps = 3
end
subsection Output
  set Folder    = output
  set Base name = ${kind}
end
")
  run_dealvem("pressure at finite strain, ${kind}" TRUE "Newton history" ${WORK_DIR}/${kind}.prm)
  file(READ ${WORK_DIR}/output/${kind}.json json)
  string(JSON ux_${kind} GET "${json}" cycles 0 finite_strain monitor_point ux)
  string(JSON uy_${kind} GET "${json}" cycles 0 finite_strain monitor_point uy)
endforeach()

# the checks that need floating point, in python (the VTU text parsed here;
# VTK's reader below)
set(check [=[
import re, sys, math
kind, ux, uy, path = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
text = open(path).read()
def section(name):
    return text[text.index("<" + name):text.index("</" + name + ">")]
def array(sec, name):
    m = re.search(r'Name="' + name + r'"[^>]*>([^<]*)<', section(sec))
    if m is None:
        sys.exit("FAIL %s: no %s array %s" % (kind, sec, name))
    return [float(x) for x in m.group(1).split()]
fails = []
for sec in ("PointData", "CellData"):
    for bad in ("stress", "von_mises"):
        if re.search(r'Name="' + bad + '"', section(sec)):
            fails.append("%s has the small-strain array %s" % (sec, bad))
p, lx, ly = 1.0, 1 + ux, 1 + uy
syy = -p if kind != "dead" else -p / lx
for sec in ("PointData", "CellData"):
    s, zz, vm, J, lam = (array(sec, n) for n in
                         ("cauchy_stress", "cauchy_stress_zz", "cauchy_von_mises", "det_F", "principal_stretches"))
    for i in range(len(zz)):
        e = max(abs(s[3*i]), abs(s[3*i+1] - syy), abs(s[3*i+2]))
        v = math.sqrt(0.5 * ((0 - s[3*i+1])**2 + (s[3*i+1] - zz[i])**2 + (zz[i] - 0)**2))
        if e > 1e-9 * p or abs(vm[i] - v) > 1e-9 * p or abs(J[i] - lx * ly) > 1e-9 \
           or abs(lam[3*i] - max(lx, ly)) > 1e-9 or abs(lam[3*i+1] - min(lx, ly)) > 1e-9 or abs(lam[3*i+2] - 1) > 1e-12:
            fails.append("%s %d: sigma (%g, %g, %g) zz %g vm %g J %g stretches %s; expected sigma_yy %g, "
                         "stretches %g, %g" % (sec, i, s[3*i], s[3*i+1], s[3*i+2], zz[i], vm[i], J[i],
                                              lam[3*i:3*i+3], syy, lx, ly))
            break
if fails:
    sys.exit("FAIL " + kind + ": " + "; ".join(fails))
print("PASS %s: sigma_yy = %.12g (expected %.12g), von Mises, det F, stretches (%g, %g) as point and cell data; "
      "no small-strain fields" % (kind, s[1], syy, lx, ly))
]=])
file(WRITE ${WORK_DIR}/check.py "${check}")
foreach(kind follower dead default)
  execute_process(COMMAND ${python} ${WORK_DIR}/check.py ${kind} ${ux_${kind}} ${uy_${kind}}
    ${WORK_DIR}/output/${kind}-step-003.vtu RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${out}${err}")
  endif()
  message(STATUS "${out}")
endforeach()
if(NOT "${uy_follower}" STREQUAL "${uy_default}")
  message(FATAL_ERROR "FAIL the default pressure load is not the follower one: u_y(1, 1) = ${uy_default}, "
                      "follower ${uy_follower}")
endif()
message(STATUS "PASS the default pressure load is the follower one")
# |u_y| of the two kinds differ by more than 1 % (compared as text numbers
# through python)
execute_process(COMMAND ${python} -c
  "import sys; f, d = float(sys.argv[1]), float(sys.argv[2]); sys.exit(0 if abs(f - d) > 0.01 * abs(d) else 1)"
  ${uy_follower} ${uy_dead} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "FAIL follower and dead loads give u_y(1, 1) = ${uy_follower} and ${uy_dead}")
endif()
message(STATUS "PASS follower and dead loads differ: u_y(1, 1) = ${uy_follower} and ${uy_dead}")
# VTK's own reader, as ParaView reads the files
execute_process(COMMAND ${python} -c "import vtk" RESULT_VARIABLE has_vtk OUTPUT_QUIET ERROR_QUIET)
if(has_vtk EQUAL 0)
  execute_process(COMMAND ${python} ${SOURCE_DIR}/tests/postprocessing/read_vtu.py
    ${WORK_DIR}/output/follower-step-003.vtu finite-strain RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "FAIL read_vtu.py (finite-strain mode):\n${out}${err}")
  endif()
  message(STATUS "PASS VTK reads follower-step-003.vtu with every finite-strain field:\n${out}")
else()
  message(STATUS "note: python3 has no vtk module; VTK's reader not run")
endif()
