# Four Hertz solves of about 1e4 DoFs each (k = 1, 2, both master choices)
# and one more: minutes at -O0 under the sanitizers, so the sanitizer run
# (scripts/sanitize.sh) leaves this test to the normal suite.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
