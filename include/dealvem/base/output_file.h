// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_base_output_file_h
#define dealvem_base_output_file_h

#include <fstream>
#include <ostream>
#include <string>

namespace dealvem
{
  /**
   * An output file that is never left half-written.
   *
   * The text goes to a temporary file next to the target (same folder, so
   * that the final rename is atomic); commit() flushes and closes it,
   * checks that every write succeeded, and only then renames it over the
   * target. If anything fails (the folder does not exist or is not
   * writable, the disk is full, the stream was put into a failed state, an
   * exception leaves the scope before commit()), the temporary file is
   * removed, an existing file of the same name is left as it was, and
   * commit() (or the constructor) throws an ExcMessage naming the target.
   *
   * A target that exists but is not a regular file (a device such as
   * /dev/null or /dev/full, a pipe) is written directly, without a
   * temporary file; errors are detected and reported all the same. A
   * target that is a directory is an error.
   *
   * @code
   *   OutputFile file("output/solution.json");
   *   file.stream() << text;
   *   file.commit();
   * @endcode
   */
  class OutputFile
  {
  public:
    /// Open the temporary file for @p filename (throws naming
    /// @p filename if it cannot be created).
    explicit OutputFile(const std::string &filename);

    /// Remove the temporary file unless commit() succeeded.
    ~OutputFile();

    OutputFile(const OutputFile &) = delete;
    OutputFile &
    operator=(const OutputFile &) = delete;

    /// The stream to write to.
    std::ostream &
    stream();

    /// Flush, close, check, and move the file into place. Throws naming
    /// the target (and the reason) on failure, after removing the
    /// temporary file. May be called once.
    void
    commit();

    /// The target file name.
    const std::string &
    filename() const
    {
      return target;
    }

    /// The temporary file written before commit() (equal to filename()
    /// for targets that are written directly).
    const std::string &
    temporary_filename() const
    {
      return temporary;
    }

  private:
    /// Close and remove the temporary file (if it is not the target).
    void
    discard() noexcept;

    std::string   target;
    std::string   temporary;
    std::ofstream out;
    bool          direct    = false;
    bool          finished  = false;
  };


  /**
   * Check the parameters 'Output/Folder' (not empty) and 'Output/Base name'
   * (not empty, no '/'), naming the parameter in the error message.
   */
  void
  check_output_names(const std::string &folder, const std::string &base_name);

  /**
   * Create the output folder @p folder (and its parents) if needed; throws
   * naming the folder and the reason if that fails or if @p folder exists
   * but is not a folder.
   */
  void
  create_output_folder(const std::string &folder);

  /**
   * The common beginning of the names of the files of refinement cycle
   * @p cycle: "<folder>/<base>" for a single cycle, "<folder>/<base>-cycle<c>"
   * when @p n_cycles > 1.
   */
  std::string
  output_prefix(const std::string &folder,
                const std::string &base_name,
                const unsigned int cycle,
                const unsigned int n_cycles);
} // namespace dealvem

#endif
