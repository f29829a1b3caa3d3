// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/base/output_file.h>
#include <dealvem/base/run_files.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <unistd.h>

namespace dealvem
{
  namespace
  {
    namespace fs = std::filesystem;

    std::string
    errno_text(const int e)
    {
      return e != 0 ? std::string(" (") + std::strerror(e) + ")" : std::string();
    }

    // a name for the temporary file, in the folder of the target
    std::string
    temporary_name(const std::string &target)
    {
      static std::atomic<unsigned long> counter{0};
      const fs::path                    p(target);
      const std::string                 name = "." + p.filename().string() + ".tmp" +
                               std::to_string(static_cast<long>(::getpid())) + "-" +
                               std::to_string(counter++);
      return (p.parent_path() / name).string();
    }
  } // namespace



  OutputFile::OutputFile(const std::string &filename)
    : target(filename)
  {
    AssertThrow(!filename.empty(), dealii::ExcMessage("Cannot write a file with an empty name."));
    std::error_code ec;
    const auto      status = fs::status(filename, ec);
    AssertThrow(!fs::is_directory(status),
                dealii::ExcMessage("Cannot write the file '" + filename + "': it is a directory."));
    // devices and pipes: write directly (a rename would replace them)
    direct    = fs::exists(status) && !fs::is_regular_file(status);
    temporary = direct ? filename : temporary_name(filename);
    errno     = 0;
    out.open(temporary, std::ios::out | std::ios::trunc | std::ios::binary);
    const int e = errno;
    if (!out)
      {
        finished = true;
        const std::string folder = fs::path(filename).parent_path().string();
        AssertThrow(false,
                    dealii::ExcMessage("Cannot write the file '" + filename + "': " +
                                       (direct ? std::string("cannot open it") :
                                                 "cannot create a file in the folder '" +
                                                   (folder.empty() ? std::string(".") : folder) + "'") +
                                       errno_text(e) + "."));
      }
  }



  OutputFile::~OutputFile()
  {
    if (!finished)
      discard();
  }



  std::ostream &
  OutputFile::stream()
  {
    return out;
  }



  void
  OutputFile::discard() noexcept
  {
    finished = true;
    if (out.is_open())
      out.close();
    if (!direct)
      {
        std::error_code ec;
        fs::remove(temporary, ec);
      }
  }



  void
  OutputFile::commit()
  {
    AssertThrow(!finished,
                dealii::ExcMessage("The file '" + target + "' was already committed or discarded."));
    errno = 0;
    bool ok = static_cast<bool>(out);
    if (ok)
      {
        out.flush();
        ok = static_cast<bool>(out);
      }
    int e = errno;
    out.close();
    if (ok && out.fail())
      {
        ok = false;
        e  = errno;
      }
    if (!ok)
      {
        discard();
        AssertThrow(false,
                    dealii::ExcMessage("Writing the file '" + target + "' failed" + errno_text(e) +
                                       (direct ? std::string(".") :
                                                 "; the earlier version of the file, if any, is unchanged.")));
      }
    if (!direct)
      {
        std::error_code ec;
        fs::rename(temporary, target, ec);
        if (ec)
          {
            discard();
            AssertThrow(false, dealii::ExcMessage("Cannot move the new file '" + target +
                                                  "' into place (" + ec.message() +
                                                  "); the earlier version of the file, if any, "
                                                  "is unchanged."));
          }
        // a run of the program keeps the list of its files
        RunFiles::record(target);
      }
    finished = true;
  }



  void
  check_output_names(const std::string &folder, const std::string &base_name)
  {
    AssertThrow(!folder.empty() && folder.find_first_not_of(" \t") != std::string::npos,
                dealii::ExcMessage("Parameter 'Output/Folder' is empty: name the folder for the "
                                   "output files ('.' for the working directory)."));
    AssertThrow(!base_name.empty() && base_name.find_first_not_of(" \t") != std::string::npos,
                dealii::ExcMessage("Parameter 'Output/Base name' is empty: name the output files."));
    AssertThrow(base_name.find('/') == std::string::npos,
                dealii::ExcMessage("Parameter 'Output/Base name' = '" + base_name +
                                   "' contains '/': it is a file name without folder; put the "
                                   "folder into 'Output/Folder'."));
    AssertThrow(base_name != "." && base_name != "..",
                dealii::ExcMessage("Parameter 'Output/Base name' = '" + base_name +
                                   "' is not a usable file name."));
  }



  void
  create_output_folder(const std::string &folder)
  {
    std::error_code ec;
    fs::create_directories(folder, ec);
    AssertThrow(!ec, dealii::ExcMessage("Parameter 'Output/Folder': cannot create the output folder '" +
                                        folder + "' (" + ec.message() + ")."));
    AssertThrow(fs::is_directory(folder, ec),
                dealii::ExcMessage("Parameter 'Output/Folder': '" + folder +
                                   "' exists but is not a folder."));
  }



  std::string
  output_prefix(const std::string &folder,
                const std::string &base_name,
                const unsigned int cycle,
                const unsigned int n_cycles)
  {
    return folder + "/" + base_name + (n_cycles > 1 ? "-cycle" + std::to_string(cycle) : std::string());
  }
} // namespace dealvem
