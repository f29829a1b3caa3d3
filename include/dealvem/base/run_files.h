// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_base_run_files_h
#define dealvem_base_run_files_h

#include <functional>
#include <string>
#include <vector>

namespace dealvem
{
  /**
   * The output files of one run of the program, so that the files under
   * one output prefix always belong to one run.
   *
   * A run writes its files as "<folder>/<base name>" followed by one of the
   * program's own suffixes (matches()): `.vtu`, `.pvtu`, `.<process>.vtu`,
   * `.pvd`, `.json`, `-interface.csv`, `-resultants.csv`, `-reactions.csv`,
   * `-history.csv`, `-stress.svg`,
   * `-pressure.svg`, `-assembly.svg`,
   * optionally after `-cycle<c>` and `-step-<n>`. A rerun with fewer load
   * steps, cycles or output options would leave some files of the earlier
   * run beside its own. So start() first removes every file of the folder
   * whose name matches these patterns for this base name (nothing else:
   * not other base names, not other suffixes), and then keeps the list of
   * the files this run writes in the manifest "<folder>/<base name>.files":
   * @code
   *   # dealvem: the files written by one run with the output prefix 'output/solution'
   *   status: running
   *   file: output/solution-step-001.vtu
   *   ...
   *   status: complete
   * @endcode
   * The last "status:" line is "complete" after complete(), "failed" after
   * failed(), and stays "running" if the process was killed. Every
   * OutputFile that is committed while a RunFiles object is active (between
   * start() and its destruction) is added through record().
   *
   * With several MPI processes only one process (@p writer true) removes
   * and records; the caller puts a barrier after start() before the other
   * processes write.
   */
  class RunFiles
  {
  public:
    /// The run writing under "<folder>/<base_name>"; only a @p writer
    /// touches files. A run that writes no files at all (@p writes_files
    /// false: every output switched off) leaves the folder as it is.
    RunFiles(const std::string &folder,
             const std::string &base_name,
             const bool         writer       = true,
             const bool         writes_files = true);

    /// Stops recording; a run that ended neither by complete() nor by
    /// failed() (an exception went through) is marked failed.
    ~RunFiles();

    RunFiles(const RunFiles &) = delete;
    RunFiles &
    operator=(const RunFiles &) = delete;

    /// Remove the files of earlier runs with this prefix, start the
    /// manifest, and record the files committed from now on. Returns the
    /// names of the removed files.
    std::vector<std::string>
    start();

    /// A line for the user about the files start() removed (@p removed);
    /// empty if there were none.
    std::string
    removal_note(const std::vector<std::string> &removed) const;

    /// Add @p filename to the list of this run (once).
    void
    add(const std::string &filename);

    /// Mark the run complete in the manifest.
    void
    complete();

    /// Mark the run failed in the manifest and return a text for the user:
    /// which files this run wrote (all of them incomplete as a set) and
    /// that no file of an earlier run is left under the prefix.
    std::string
    failed();

    /// The files this run has written so far.
    const std::vector<std::string> &
    get_files() const
    {
      return files;
    }

    /// The manifest's name, "<folder>/<base name>.files".
    std::string
    manifest_name() const;

    /// The text failed() returned last in this process (empty if no run
    /// failed), for the program's error message.
    static const std::string &
    last_failure_report();

    /// Record @p filename with the active run, if any (OutputFile::commit()
    /// calls this).
    static void
    record(const std::string &filename);

    /// Whether the file name @p name (without folder) is one the program
    /// writes for @p base_name (including OutputFile's temporary names and
    /// the manifest).
    static bool
    matches(const std::string &base_name, const std::string &name);

  private:
    void
    append_line(const std::string &line) const;

    std::string              folder;
    std::string              base_name;
    bool                     writer;
    bool                     writes_files;
    bool                     active   = false;
    bool                     finished = false;
    std::vector<std::string> files;
  };


  /**
   * Where and how a program's run writes its files, for run_with_files().
   */
  struct RunOutput
  {
    /// 'Output/Folder' (not empty), created by the writer if needed.
    std::string folder;
    /// 'Output/Base name' (not empty, no '/').
    std::string base_name;
    /// Whether this process writes (process 0 of an MPI run, or the only
    /// one): it creates the folder, removes the files of earlier runs and
    /// keeps the manifest.
    bool writer = true;
    /// Whether the run writes any file at all (false: every output is
    /// switched off and the folder is left as it is).
    bool writes_files = true;
  };

  /**
   * The frame the programs (ElasticityProblem::run() and
   * ContactProblem::run()) run in, in one place:
   * 1. the output names are checked (check_output_names()) and the writer
   *    creates the folder;
   * 2. RunFiles removes the files of an earlier run under the same prefix
   *    and starts the manifest; the note about removed files (empty if none)
   *    goes to @p print;
   * 3. @p synchronize is called if given (an MPI barrier, so that no
   *    process writes before the earlier files are gone);
   * 4. @p body runs; if it returns, the manifest says "complete";
   * 5. if it throws, @p on_failure is called if given (for example to mark
   *    a JSON summary failed; anything it throws is dropped so that the
   *    original error is the one reported), the manifest says "failed" and
   *    the exception goes on to the caller (the program prints the list of
   *    files the run wrote after its error message:
   *    RunFiles::last_failure_report()).
   */
  void
  run_with_files(const RunOutput                                &output,
                 const std::function<void(const std::string &)> &print,
                 const std::function<void()>                    &body,
                 const std::function<void()>                    &on_failure  = {},
                 const std::function<void()>                    &synchronize = {});
} // namespace dealvem

#endif
