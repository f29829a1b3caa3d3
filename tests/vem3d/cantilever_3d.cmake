# Three hexahedral meshes up to 2e4 DoFs with UMFPACK: a few seconds in
# Release, minutes at -O0 under the sanitizers. The sanitizer run leaves it
# to the normal suite (the element runs there in vem3d/patch_test_3d).
set_tests_properties(${_test} PROPERTIES LABELS "vem3d;sanitize_slow")
