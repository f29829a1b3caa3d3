# Condensed CG-AMG and direct solves up to a few 1e4 DoFs, serially and
# (contact/condensed_solver-np2) on two processes: the longest tests under
# the sanitizers (about 5 and 4 minutes of CI time at -O0 with ASan), whose
# distributed code paths contact/verification-np2 and app/mpi_program also
# run there. The sanitizer run (scripts/sanitize.sh) leaves both to the
# normal suite; the np2 variant inherits the label (tests/CMakeLists.txt).
set_tests_properties(${_test} PROPERTIES LABELS "contact;sanitize_slow")
