# Convergence rates on four mesh families up to 1e5 DoFs: over 3 minutes at
# -O0 under the sanitizers. The sanitizer run leaves it to the normal suite
# (the element code runs there in elasticity/patch_tests and
# vem/vem_values).
set_tests_properties(${_test} PROPERTIES LABELS "elasticity;sanitize_slow")
