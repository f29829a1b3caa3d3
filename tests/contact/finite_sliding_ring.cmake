# Two runs of finite sliding at 4k DoFs with 3-4 pairing passes per step
# (30 s in Release): left to the normal suite by the sanitizer run, like
# contact/finite_sliding; tests/vem/element_properties runs the boundary
# stabilization under the sanitizers.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
