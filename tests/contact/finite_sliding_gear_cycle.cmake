# Six finite-sliding steps of a gear pair at 10k DoFs (2-3 pairing passes
# each) and six small-strain contact solves: 46 s in Release, so the
# sanitizer run leaves it to the normal suite, like contact/finite_sliding.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
# The longer arc: ten roll angles over three tenths of a base pitch, 12k
# DoFs, 1 min 45 s of CPU in Release (measured: torque within 0.038 %, peak
# pressure within 0.94 %).
add_test(NAME contact/finite_sliding_gear_cycle-study COMMAND ${_target} --study WORKING_DIRECTORY ${_workdir})
set_tests_properties(contact/finite_sliding_gear_cycle-study PROPERTIES LABELS "contact;long" TIMEOUT 900)
