// Sanitizer runs only (scripts/sanitizer-env.sh preloads it with
// LD_PRELOAD): two changes to how OpenMPI's own allocations meet
// LeakSanitizer, so that the leak check at exit neither reports them nor
// costs a second and a half per process.
//
// 1. MPI_Init(), MPI_Init_thread() and MPI_Finalize() run with the leak
//    check disabled on the calling thread (__lsan_disable()): what OpenMPI
//    allocates there and never frees (its component registry, op tables,
//    ORTE state, about 3400 blocks in a singleton process) is ignored by
//    LeakSanitizer. Before, those blocks were reported and then matched
//    against tests/sanitizers/lsan.supp, and matching a suppression
//    symbolizes a stack: GCC's in-process symbolizer first reads the symbol
//    tables of every loaded library (deal.II's debug library alone is
//    576 MB), 1.0-1.6 s at the exit of every process. With a few hundred
//    program runs in the sanitizer suite (the bad-input corpus, the
//    parameter-file tests) that was several minutes of CI. A leak of any
//    other code is still reported (checked with a program that leaks an
//    array after MPI_Init_thread: one report, its own line named).
// 2. dlclose() unloads nothing. OpenMPI opens its components (mca_*.so)
//    with dlopen() and closes them in MPI_Finalize(); a block one of them
//    allocated outside the calls above (another thread, a later MPI call)
//    would otherwise be reported with "<unknown module>" frames that no
//    suppression can name except through a caller further up, which only
//    the slow unwinder (about 3x the run time of the whole suite) reaches.
//    Kept loaded, the first frame names the component, and lsan.supp
//    matches its path. Nothing in dealvem, deal.II or Trilinos unloads
//    libraries.
//
// The real MPI functions are found with dlsym(RTLD_NEXT); __lsan_* are
// declared weak so that a process without the sanitizer runtime still runs.
#include <dlfcn.h>

extern "C"
{
  void
  __lsan_disable() __attribute__((weak));
  void
  __lsan_enable() __attribute__((weak));
}

namespace
{
  // Calls f with LeakSanitizer's check disabled on this thread.
  template <typename F>
  int
  without_leak_check(F f)
  {
    if (__lsan_disable)
      __lsan_disable();
    const int result = f();
    if (__lsan_enable)
      __lsan_enable();
    return result;
  }

  template <typename Function>
  Function
  next_definition(const char *name)
  {
    return reinterpret_cast<Function>(dlsym(RTLD_NEXT, name));
  }
} // namespace

extern "C" int
MPI_Init(int *argc, char ***argv)
{
  using Function = int (*)(int *, char ***);
  static const Function real = next_definition<Function>("MPI_Init");
  return without_leak_check([&] { return real(argc, argv); });
}

extern "C" int
MPI_Init_thread(int *argc, char ***argv, int required, int *provided)
{
  using Function = int (*)(int *, char ***, int, int *);
  static const Function real = next_definition<Function>("MPI_Init_thread");
  return without_leak_check([&] { return real(argc, argv, required, provided); });
}

extern "C" int
MPI_Finalize()
{
  using Function = int (*)();
  static const Function real = next_definition<Function>("MPI_Finalize");
  return without_leak_check([&] { return real(); });
}

extern "C" int
dlclose(void *)
{
  return 0;
}
