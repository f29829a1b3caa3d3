# 54-69 s under the sanitizers (-O0, one core; about a second in Release):
# the sanitizer run (scripts/sanitize.sh) leaves this test to the normal
# suite, to keep the CI run near an hour. Checked clean under the
# sanitizers when it was added.
set_tests_properties(${_test} PROPERTIES LABELS "elasticity;sanitize_slow")
