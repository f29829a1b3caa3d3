# Interference fits on curved interfaces, both master choices, k = 1 and 2,
# several meshes: over 3 minutes at -O0 under the sanitizers. The sanitizer
# run leaves it to the normal suite (the same contact code runs there in
# contact/bodies_apart and contact/patch_test).
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
