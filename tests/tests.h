// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// A small test harness: deal.II's own tests/tests.h is not installed.
// Each test program prints what it checks and calls check(); the program's
// exit code is the number of failed checks (0 = pass), so ctest sees it.
#ifndef dealvem_tests_h
#define dealvem_tests_h

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iomanip>
#include <sstream>
#include <iostream>
#include <string>

namespace testing
{
  inline int &
  n_failures()
  {
    static int n = 0;
    return n;
  }

  /// Check a condition; print PASS/FAIL with a description.
  inline void
  check(const bool condition, const std::string &what)
  {
    std::cout << (condition ? "PASS  " : "FAIL  ") << what << std::endl;
    if (!condition)
      ++n_failures();
  }

  /// Check |value| <= tolerance, printing the value.
  inline void
  check_small(const double value, const double tolerance, const std::string &what)
  {
    std::ostringstream s;
    s << what << ": " << std::scientific << std::setprecision(3) << value
      << " (tolerance " << tolerance << ")";
    check(std::isfinite(value) && std::abs(value) <= tolerance, s.str());
  }

  /// Check |value - expected| <= tolerance.
  inline void
  check_near(const double value,
             const double expected,
             const double tolerance,
             const std::string &what)
  {
    std::ostringstream s;
    s << what << ": " << std::setprecision(10) << value << " expected "
      << expected << " (tolerance " << std::scientific << std::setprecision(1)
      << tolerance << ")";
    check(std::isfinite(value) && std::abs(value - expected) <= tolerance,
          s.str());
  }

  /// @p s with every run of white space (spaces, line breaks) replaced by
  /// one space: deal.II breaks the text of an ExcMessage into lines.
  inline std::string
  collapse_white_space(const std::string &s)
  {
    std::string out;
    bool        space = false;
    for (const char c : s)
      if (c == ' ' || c == '\n' || c == '\t' || c == '\r')
        space = true;
      else
        {
          if (space && !out.empty())
            out += ' ';
          space = false;
          out += c;
        }
    return out;
  }

  /// Run @p f and check that it throws an exception whose what() contains
  /// @p fragment (white space compared as collapse_white_space() does).
  template <typename F>
  void
  check_throws(F &&f, const std::string &fragment_text, const std::string &what)
  {
    const std::string fragment = collapse_white_space(fragment_text);
    try
      {
        f();
      }
    catch (const std::exception &e)
      {
        const std::string msg = collapse_white_space(e.what());
        const bool        ok  = msg.find(fragment) != std::string::npos;
        check(ok, what + (ok ? "" : " (message was: " + msg + ")"));
        if (ok)
          {
            // Show the first line of the message that matched.
            const auto p = msg.find(fragment);
            std::cout << "      ... " << msg.substr(p, std::getenv("DEALVEM_FULL_MESSAGES") ? std::string::npos : 100) << std::endl;
          }
        return;
      }
    check(false, what + " (no exception)");
  }

  /// The source directory (for data files), from the environment.
  inline std::string
  source_dir()
  {
    const char *s = std::getenv("DEALVEM_SOURCE_DIR");
    return s ? std::string(s) : std::string(".");
  }

  /// Print the summary and return the exit code.
  inline int
  finish()
  {
    std::cout << (n_failures() == 0 ? "OK" : "FAILED") << ": " << n_failures()
              << " failed check(s)" << std::endl;
    return n_failures() == 0 ? 0 : 1;
  }
} // namespace testing


#endif
