# About 3 s in Release, more than 9 minutes under the sanitizers (-O0, with
# the machine shared): the sanitizer run (scripts/sanitize.sh) leaves this
# test to the normal suite, to keep the CI run near an hour. Run under the
# sanitizers by hand when the solver's debug-mode failure was fixed (no
# report in its first 33 checks).
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
