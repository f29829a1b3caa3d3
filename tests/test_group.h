// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The entry point of a test group (tests/CMakeLists.txt, option
// DEALVEM_TEST_GROUPS): several test programs of one module compiled as one
// translation unit, each inside a namespace of its own, and one main() that
// runs the test named by its first argument with the remaining arguments:
//
//   test_contact_2 tall_wall [arguments of tall_wall ...]
//
// A test sees argv[0] (the group program) followed by its own arguments, as
// if it were a program of its own. The deal.II, dealvem and standard
// headers the tests include are parsed and their templates instantiated
// once per group instead of once per test: the compile time of the suite
// falls by a factor of about four.
#ifndef dealvem_test_group_h
#define dealvem_test_group_h

#include <cstring>
#include <iostream>

namespace testing
{
  namespace group
  {
    /// A test's main(), whichever of the two standard signatures it has.
    class Entry
    {
    public:
      Entry(const char *name, int (*main_without_arguments)())
        : name(name)
        , without_arguments(main_without_arguments)
      {}

      Entry(const char *name, int (*main_with_arguments)(int, char **))
        : name(name)
        , with_arguments(main_with_arguments)
      {}

      int
      run(int argc, char **argv) const
      {
        return with_arguments != nullptr ? with_arguments(argc, argv) : without_arguments();
      }

      const char *name;

    private:
      int (*without_arguments)()             = nullptr;
      int (*with_arguments)(int, char **) = nullptr;
    };

    /// Run the test named by argv[1] of the group @p tests (n of them).
    inline int
    run(int argc, char **argv, const Entry *tests, const unsigned int n)
    {
      for (unsigned int i = 0; argc >= 2 && i < n; ++i)
        if (std::strcmp(argv[1], tests[i].name) == 0)
          {
            // the test sees the program's name and its own arguments
            argv[1] = argv[0];
            return tests[i].run(argc - 1, argv + 1);
          }
      std::cerr << "usage: " << argv[0] << " <test> [arguments]\n"
                << (argc >= 2 ? "unknown test '" + std::string(argv[1]) + "'; " : std::string())
                << "the tests of this group:";
      for (unsigned int i = 0; i < n; ++i)
        std::cerr << ' ' << tests[i].name;
      std::cerr << std::endl;
      return 2;
    }
  } // namespace group
} // namespace testing

#endif
