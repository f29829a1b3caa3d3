# Two runs of finite sliding with 3-12 pairing passes per step: left to the
# normal suite by the sanitizer run, like contact/finite_sliding.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
