# Three mesh families up to 1.5e4 DoFs in 3D with UMFPACK: 9 s in Release,
# minutes at -O0 under the sanitizers. The sanitizer run leaves it to the
# normal suite (the element and the problem run there in
# vem3d/patch_test_3d).
set_tests_properties(${_test} PROPERTIES LABELS "vem3d;sanitize_slow")
