# Distributed elasticity on meshes of 1e4-1e5 DoFs, run once serially and
# once under mpirun -np 2: about 4 minutes each at -O0 under the sanitizers.
# The sanitizer run leaves both to the normal suite; the distributed paths
# run there in contact/verification-np2 and app/mpi_verification.
set_tests_properties(${_test} PROPERTIES LABELS "app;sanitize_slow")
