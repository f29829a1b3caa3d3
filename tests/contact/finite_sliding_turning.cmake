# Five turns of the ring on its shaft and two blocks dragged off their base
# (33 s in Release): left to the normal suite by the sanitizer run, like
# contact/finite_sliding_ring.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
