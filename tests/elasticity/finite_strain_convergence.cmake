# Eight finite-strain Newton solves up to 12k DoFs (about 13 s in Release):
# minutes at -O0 under the sanitizers, so the sanitizer run
# (scripts/sanitize.sh) leaves this test to the normal suite.
set_tests_properties(${_test} PROPERTIES LABELS "elasticity;sanitize_slow")
