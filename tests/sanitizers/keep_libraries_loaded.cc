// Sanitizer runs only (scripts/sanitize.sh preloads it with LD_PRELOAD):
// dlclose() that keeps every library loaded.
//
// OpenMPI opens its components (mca_*.so) with dlopen() and closes them in
// MPI_Finalize(). What they allocated in MPI_Init() and never freed is
// reported by LeakSanitizer at exit, when the component is gone and its
// frames show as "<unknown module>": no suppression can name them except
// through a caller further up the stack, which only the slow unwinder
// (fast_unwind_on_malloc=0, about 3x the run time of the whole suite)
// reaches through OpenMPI's frames without frame pointers. With the
// components kept loaded, the first frame of every such allocation names
// its module, and tests/sanitizers/lsan.supp matches the module path.
// Nothing in dealvem, deal.II or Trilinos unloads libraries.
extern "C" int
dlclose(void *)
{
  return 0;
}
