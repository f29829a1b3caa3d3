# Two curved contacts, each solved eight times (shifted, scaled, rotated):
# 150 s at -O0 under the sanitizers, the largest share of the sanitizer run.
# The sanitizer run leaves it to the normal suite (the same node insertion
# and contact code runs there in contact/imprecise_coordinates and
# contact/sloped_interface).
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
