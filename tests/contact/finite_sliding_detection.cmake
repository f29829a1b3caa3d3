# Three pairs of finite-sliding runs, detected against named interfaces
# (about 10 s in Release): left to the normal suite by the sanitizer run.
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
