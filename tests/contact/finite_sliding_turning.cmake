# Five turns of the ring on its shaft and two blocks dragged off their base
# (33 s in Release): left to the normal suite by the sanitizer run, like
# contact/finite_sliding_ring.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
# The ring-on-shaft study (steps of 5, 15 and 30 degrees; doc/architecture.md,
# "Curved finite sliding"), about a minute: label "long".
add_test(NAME contact/finite_sliding_turning-study COMMAND ${_test_command} --study WORKING_DIRECTORY ${_workdir})
set_tests_properties(contact/finite_sliding_turning-study PROPERTIES LABELS "contact;long")
