# Curved contact interfaces under refinement (k = 1 and 2): over 3 minutes
# at -O0 under the sanitizers. The sanitizer run leaves it to the normal
# suite (the same contact code runs there in contact/bodies_apart and
# contact/sloped_interface).
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
