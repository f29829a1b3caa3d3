# Three finite-sliding steps of a gear pair where a tooth pair leaves
# contact, at 15k DoFs, and three small-strain contact solves: 40 s of CPU
# in Release, so the sanitizer run leaves it to the normal suite, like
# contact/finite_sliding.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
# One base pitch in 16 roll angles (both double-contact zones, a pair
# leaving and one entering), 54k DoFs: 13.6 min of CPU in Release (measured:
# torque within 0.047 %, shares within 3.2e-4, peak pressure within 1.3 %).
add_test(NAME contact/finite_sliding_gear_cycle-pitch COMMAND ${_test_command} --pitch WORKING_DIRECTORY ${_workdir})
set_tests_properties(contact/finite_sliding_gear_cycle-pitch PROPERTIES LABELS "contact;long" TIMEOUT 7200)
