// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/base/output_file.h>
#include <dealvem/base/run_files.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <system_error>

namespace dealvem
{
  namespace
  {
    namespace fs = std::filesystem;

    // the run that records committed files (one at a time; a nested one
    // hides the outer one until it ends)
    RunFiles *active_run = nullptr;

    // the report of the last failed run
    std::string failure_report;

    // what follows the base name in the names of the program's files
    const std::regex &
    suffix_pattern()
    {
      static const std::regex pattern(
        "(-cycle[0-9]+)?(-step-[0-9]+)?"
        "(\\.vtu|\\.pvtu|\\.[0-9]+\\.vtu|\\.pvd|\\.json|-interface\\.csv|-resultants\\.csv|-reactions\\.csv|"
        "-history\\.csv|-stress\\.svg|"
        "-pressure\\.svg|-assembly\\.svg)");
      return pattern;
    }
  } // namespace



  RunFiles::RunFiles(const std::string &folder,
                     const std::string &base_name,
                     const bool         writer,
                     const bool         writes_files)
    : folder(folder)
    , base_name(base_name)
    , writer(writer)
    , writes_files(writes_files)
  {}



  RunFiles::~RunFiles()
  {
    if (active && !finished)
      {
        try
          {
            failed();
          }
        catch (...)
          {}
      }
    if (active_run == this)
      active_run = nullptr;
  }



  bool
  RunFiles::matches(const std::string &base_name, const std::string &name)
  {
    if (base_name.empty())
      return false;
    // OutputFile's temporary files: ".<name>.tmp<pid>-<n>"
    static const std::regex temporary("\\.(.*)\\.tmp[0-9]+-[0-9]+");
    std::smatch             m;
    if (std::regex_match(name, m, temporary))
      return matches(base_name, m[1].str());
    if (name.size() <= base_name.size() || name.compare(0, base_name.size(), base_name) != 0)
      return false;
    const std::string rest = name.substr(base_name.size());
    return rest == ".files" || std::regex_match(rest, suffix_pattern());
  }



  std::string
  RunFiles::manifest_name() const
  {
    return (fs::path(folder) / (base_name + ".files")).string();
  }



  std::vector<std::string>
  RunFiles::start()
  {
    std::vector<std::string> removed;
    files.clear();
    finished = false;
    // a run without output files cannot mix its files with others
    if (!writes_files)
      return removed;
    if (writer)
      {
        std::error_code ec;
        std::vector<fs::path> old;
        for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
          {
            std::error_code ec2;
            if (!it->is_directory(ec2) && matches(base_name, it->path().filename().string()))
              old.push_back(it->path());
          }
        AssertThrow(!ec, dealii::ExcMessage("Cannot list the output folder '" + folder + "' (" + ec.message() +
                                            ") to remove the files of an earlier run."));
        std::sort(old.begin(), old.end());
        for (const auto &p : old)
          {
            std::error_code ec2;
            fs::remove(p, ec2);
            AssertThrow(!ec2,
                        dealii::ExcMessage("Cannot remove the file '" + p.string() + "' of an earlier run with the "
                                           "output prefix '" + folder + "/" + base_name + "' (" + ec2.message() +
                                           "); remove it, or choose another 'Output/Base name'."));
            if (p.filename().string() != base_name + ".files")
              removed.push_back(p.string());
          }
        std::ofstream out(manifest_name(), std::ios::trunc);
        out << "# dealvem: the files written by one run with the output prefix '" << folder << "/" << base_name
            << "'; the last 'status:' line says whether the run completed\n"
            << "status: running\n";
        AssertThrow(static_cast<bool>(out),
                    dealii::ExcMessage("Cannot write the file '" + manifest_name() + "' (the list of the run's "
                                       "files): is the output folder writable?"));
      }
    active     = true;
    active_run = this;
    return removed;
  }



  std::string
  RunFiles::removal_note(const std::vector<std::string> &removed) const
  {
    if (removed.empty())
      return "";
    std::string text = "Output: removed the " + std::to_string(removed.size()) +
                       " file(s) of an earlier run with the output prefix '" + folder + "/" + base_name + "' (";
    for (unsigned int i = 0; i < removed.size() && i < 3; ++i)
      text += (i > 0 ? ", " : "") + fs::path(removed[i]).filename().string();
    text += removed.size() > 3 ? ", ...)\n" : ")\n";
    return text;
  }



  void
  RunFiles::append_line(const std::string &line) const
  {
    if (!writer)
      return;
    std::ofstream out(manifest_name(), std::ios::app);
    out << line << '\n';
    AssertThrow(static_cast<bool>(out), dealii::ExcMessage("Cannot append to the file '" + manifest_name() + "'."));
  }



  void
  RunFiles::add(const std::string &filename)
  {
    if (!active || !writer || std::find(files.begin(), files.end(), filename) != files.end())
      return;
    files.push_back(filename);
    append_line("file: " + filename);
  }



  void
  RunFiles::complete()
  {
    if (!active || finished)
      return;
    finished = true;
    append_line("status: complete");
  }



  std::string
  RunFiles::failed()
  {
    if (!active)
      return "";
    if (!finished)
      {
        finished = true;
        append_line("status: failed");
      }
    std::string text = "The run did not complete: ";
    if (files.empty())
      text += "it wrote no output files";
    else
      {
        text += "the " + std::to_string(files.size()) + " file(s) it wrote are incomplete as a set:";
        for (const auto &f : files)
          text += "\n  " + f;
      }
    text += "\nNo file of an earlier run is left under the output prefix '" + folder + "/" + base_name +
            "' (removed at the start); the list is in '" + manifest_name() + "' (status: failed).";
    if (writer)
      failure_report = text;
    return text;
  }



  const std::string &
  RunFiles::last_failure_report()
  {
    return failure_report;
  }



  void
  RunFiles::record(const std::string &filename)
  {
    if (active_run != nullptr)
      active_run->add(filename);
  }


  void
  run_with_files(const RunOutput                                &output,
                 const std::function<void(const std::string &)> &print,
                 const std::function<void()>                    &body,
                 const std::function<void()>                    &on_failure,
                 const std::function<void()>                    &synchronize)
  {
    check_output_names(output.folder, output.base_name);
    if (output.writer)
      create_output_folder(output.folder);
    RunFiles run_files(output.folder, output.base_name, output.writer, output.writes_files);
    const std::string note = run_files.removal_note(run_files.start());
    if (print)
      print(note);
    if (synchronize)
      synchronize();
    try
      {
        body();
      }
    catch (...)
      {
        if (on_failure)
          try
            {
              on_failure();
            }
          catch (...)
            {}
        run_files.failed();
        throw;
      }
    run_files.complete();
  }
} // namespace dealvem
