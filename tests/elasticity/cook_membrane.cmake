# Four finite-strain Newton solves of Cook's membrane up to 2178 DoFs (about
# 6 s in Release): minutes at -O0 under the sanitizers, so the sanitizer run
# (scripts/sanitize.sh) leaves this test to the normal suite.
set_tests_properties(${_test} PROPERTIES LABELS "elasticity;sanitize_slow")
