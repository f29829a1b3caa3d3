# Sourced by scripts/sanitize.sh (and read by scripts/fuzz.py): the runtime
# options of the sanitizers, with the checked-in suppression files of
# tests/sanitizers/ (third-party frames only). Reports go to stderr and end
# the process with a non-zero exit code.
_SAN_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/../tests/sanitizers" && pwd)"
# fast_unwind_on_malloc=0: leak stacks must reach through OpenMPI frames
# without frame pointers to the MPI entry points named in lsan.supp (costs
# about 3x run time; malloc_context_size bounds it)
export ASAN_OPTIONS="detect_leaks=1:fast_unwind_on_malloc=0:malloc_context_size=16:halt_on_error=1:abort_on_error=0:check_initialization_order=1:suppressions=$_SAN_DIR/asan.supp"
export LSAN_OPTIONS="suppressions=$_SAN_DIR/lsan.supp:print_suppressions=0:report_objects=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$_SAN_DIR/ubsan.supp"
# OpenMPI: no shared-memory/CMA probing noise on containers, one process
export OMPI_MCA_btl_vader_single_copy_mechanism=none
unset _SAN_DIR
