# One pinion-in-ring solve of 34k DoFs: 4 s in Release, a minute or more at
# -O0 under the sanitizers; the internal gear's geometry and mesher run there
# in mesh/spur_gear, so the sanitizer run leaves this test to the normal suite.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
