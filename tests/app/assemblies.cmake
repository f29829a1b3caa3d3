# The 1020-block wall (20,872 DoFs, 2,955 interfaces, 16,118 multipliers)
# takes 1.4 s in Release and many minutes at -O0 under the sanitizers; the
# detection, insertion and support code it runs is exercised under the
# sanitizers by contact/contact_detection and examples/step-8 (19 voussoirs
# read from one gmsh file). The normal suite runs it.
set_tests_properties(${_test} PROPERTIES LABELS "app;sanitize_slow")
