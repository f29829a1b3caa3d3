# About 12 s in Release, more than 600 s under the sanitizers (-O0, 24 + 24
# + 2 x 12 + 12 finite-strain load steps, each with its pairing passes): the
# sanitizer run (scripts/sanitize.sh) leaves this test to the normal suite,
# to keep the CI run near an hour. Checked under the sanitizers by hand when
# it was added (no report).
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
