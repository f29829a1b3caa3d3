# 120 s under the sanitizers (-O0; two load kinds on three meshes): left to
# the normal suite by the sanitizer run; the finite-strain pressure loads run
# under the sanitizers in app/finite_strain_pressure_program and
# elasticity/finite_strain_bad_input.
set_tests_properties(${_test} PROPERTIES LABELS "elasticity;sanitize_slow")
