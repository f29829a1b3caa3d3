// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Output files are never half-written (OutputFile): a committed file has
// the new text; a failed write (stream put into a failed state, an
// exception before commit(), a folder that cannot hold the file, a full
// device) leaves the earlier file as it was, leaves no temporary file
// behind, and the error message names the file. The checks of the output
// parameters (folder, base name) and the cycle file names.
#include <dealvem/postprocessing/json_summary.h>
#include <dealvem/base/output_file.h>
#include <dealvem/postprocessing/svg_plots.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "../tests.h"

using namespace dealvem;
namespace fs = std::filesystem;

namespace
{
  std::string
  read(const std::string &name)
  {
    std::ifstream      in(name);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  // the files in @p folder whose names contain ".tmp"
  unsigned int
  n_temporaries(const std::string &folder)
  {
    unsigned int n = 0;
    for (const auto &e : fs::directory_iterator(folder))
      n += e.path().filename().string().find(".tmp") != std::string::npos;
    return n;
  }
} // namespace

int
main()
{
  fs::remove_all("out");
  fs::create_directories("out");

  // a good file, then a good rewrite
  {
    OutputFile f("out/a.txt");
    f.stream() << "first\n";
    testing::check(!fs::exists("out/a.txt"), "nothing at the target before commit()");
    f.commit();
  }
  testing::check(read("out/a.txt") == "first\n", "commit() writes the file");
  {
    OutputFile f("out/a.txt");
    f.stream() << "second\n";
    f.commit();
  }
  testing::check(read("out/a.txt") == "second\n", "a second commit() replaces the file");
  testing::check(n_temporaries("out") == 0, "no temporary file is left after commits");

  // a stream that fails: the earlier file stays, the message names the file
  testing::check_throws(
    [] {
      OutputFile f("out/a.txt");
      f.stream() << "half a file";
      f.stream().setstate(std::ios::badbit);
      f.commit();
    },
    "Writing the file 'out/a.txt' failed",
    "a failed stream is reported at commit(), naming the file");
  testing::check(read("out/a.txt") == "second\n", "... and the earlier file is unchanged");
  testing::check(n_temporaries("out") == 0, "... and the temporary file is removed");

  // an exception before commit(): the earlier file stays
  try
    {
      OutputFile f("out/a.txt");
      f.stream() << "never committed";
      throw std::runtime_error("stop");
    }
  catch (const std::runtime_error &)
    {}
  testing::check(read("out/a.txt") == "second\n" && n_temporaries("out") == 0,
                 "an exception before commit() keeps the earlier file, no temporary left");

  // a folder that cannot exist: a path below a regular file
  std::ofstream("out/somefile") << "a file, not a folder\n";
  testing::check_throws([] { OutputFile f("out/somefile/out.json"); },
                        "Cannot write the file 'out/somefile/out.json'",
                        "a file below a regular file: the message names it");
  testing::check_throws([] { OutputFile f("out/no-such-folder/out.json"); },
                        "Cannot write the file 'out/no-such-folder/out.json'",
                        "a file in a missing folder: the message names it");
  testing::check_throws([] { OutputFile f("out"); }, "'out': it is a directory",
                        "a target that is a directory: the message names it");

  // the writers use OutputFile: JSON and SVG
  {
    JsonSummary json;
    json.set("value", 1.);
    json.write("out/summary.json");
    const std::string good = read("out/summary.json");
    testing::check_throws([&] { json.write("out/somefile/summary.json"); },
                          "out/somefile/summary.json", "JsonSummary::write names the file that failed");
    testing::check(read("out/summary.json") == good, "... and the earlier JSON file is unchanged");
    SVGPlots::Series s;
    s.points = {{0., 1.}, {1., 2.}};
    testing::check_throws([&] { SVGPlots::write_line_plot("out/somefile/p.svg", {s}, "x", "y", "t"); },
                          "out/somefile/p.svg", "SVGPlots::write_line_plot names the file that failed");
    SVGPlots::write_line_plot("out/p.svg", {s}, "x", "y", "t");
    testing::check(read("out/p.svg").find("</svg>") != std::string::npos, "a good SVG file is complete");
  }

  // a full device: the failure must be reported, not ignored
  if (fs::exists("/dev/full"))
    testing::check_throws(
      [] {
        OutputFile f("/dev/full");
        for (unsigned int i = 0; i < 100000; ++i)
          f.stream() << "0123456789";
        f.commit();
      },
      "Writing the file '/dev/full' failed", "writing to /dev/full is reported as a failure");
  else
    std::cout << "(no /dev/full: skipped)" << std::endl;

  // the output parameters
  testing::check_throws([] { check_output_names("", "solution"); }, "Parameter 'Output/Folder' is empty",
                        "an empty folder is an error naming the parameter");
  testing::check_throws([] { check_output_names("output", ""); }, "Parameter 'Output/Base name' is empty",
                        "an empty base name is an error naming the parameter");
  testing::check_throws([] { check_output_names("output", "a/b"); },
                        "Parameter 'Output/Base name' = 'a/b' contains '/'",
                        "a base name with '/' is an error naming the parameter");
  testing::check_throws([] { create_output_folder("out/somefile/sub"); },
                        "cannot create the output folder 'out/somefile/sub'",
                        "a folder that cannot be created: the message names it");
  create_output_folder("out/new/folder");
  testing::check(fs::is_directory("out/new/folder"), "create_output_folder creates nested folders");
  testing::check(output_prefix("o", "b", 0, 1) == "o/b" && output_prefix("o", "b", 2, 3) == "o/b-cycle2",
                 "output_prefix: '<base>' for one cycle, '<base>-cycle<c>' for several");

  return testing::finish();
}
