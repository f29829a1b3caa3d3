# Five gear-pair solves of 35k DoFs (the model as given, shifted, scaled
# twice and turned): half a minute in Release, many minutes at -O0 under the
# sanitizers, so the sanitizer run (scripts/sanitize.sh) leaves this test to
# the normal suite.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
