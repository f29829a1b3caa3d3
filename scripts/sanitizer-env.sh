# Sourced by scripts/sanitize.sh (and read by scripts/fuzz.py): the runtime
# options of the sanitizers, with the checked-in suppression files of
# tests/sanitizers/ (third-party frames only). Reports go to stderr and end
# the process with a non-zero exit code.
_SAN_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/../tests/sanitizers" && pwd)"
# The library tests/sanitizers/sanitizer_preload.cc, preloaded here when the
# sanitizer build has made it, runs OpenMPI's MPI_Init and MPI_Finalize
# without the leak check (their blocks are OpenMPI's; matching them against
# the suppressions symbolized a stack at the exit of every process, 1-1.6 s
# each) and keeps OpenMPI's components loaded until the leak check, so that
# a block they allocate elsewhere is reported with its module's name, which
# lsan.supp matches (verify_asan_link_order=0: it comes before the ASan
# runtime; it intercepts nothing ASan does)
_SAN_PRELOAD="${BUILD_DIR:-$_SAN_DIR/../../build-sanitize}/lib/libsanitizer_preload.so"
if [ -f "$_SAN_PRELOAD" ]; then
  export LD_PRELOAD="$(cd "$(dirname "$_SAN_PRELOAD")" && pwd)/$(basename "$_SAN_PRELOAD")${LD_PRELOAD:+:$LD_PRELOAD}"
fi
export ASAN_OPTIONS="detect_leaks=1:verify_asan_link_order=0:halt_on_error=1:abort_on_error=0:check_initialization_order=1:suppressions=$_SAN_DIR/asan.supp"
export LSAN_OPTIONS="suppressions=$_SAN_DIR/lsan.supp:print_suppressions=0:report_objects=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$_SAN_DIR/ubsan.supp"
# OpenMPI: no shared-memory/CMA probing noise on containers, one process
export OMPI_MCA_btl_vader_single_copy_mechanism=none
# a program started without mpirun initializes MPI as a singleton; by default
# Open MPI 4.1 then starts a helper daemon (orted) for it: 0.24 s of the 1.5 s
# a sanitized program takes to start, and the suite starts about 600 of them
export OMPI_MCA_ess_singleton_isolated=1
unset _SAN_DIR _SAN_PRELOAD
