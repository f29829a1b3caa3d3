// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_postprocessing_json_summary_h
#define dealvem_postprocessing_json_summary_h

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dealvem
{
  /**
   * A small JSON writer for run summaries. Keys are paths with dots,
   * "cycles.0.dofs", which become nested objects; insertion order is kept;
   * numbers are written with 17 significant digits (a non-finite number
   * is refused: set() throws naming its key), strings escaped.
   */
  class JsonSummary
  {
  public:
    /// Set the number at the dotted @p path (replacing an earlier value).
    void
    set(const std::string &path, const double value);

    /// Set the string at the dotted @p path (replacing an earlier value).
    void
    set(const std::string &path, const std::string &value);

    /// The same for a C string (not to be taken for a bool).
    void
    set(const std::string &path, const char *value)
    {
      set(path, std::string(value));
    }

    /// Set every number of @p values at @p prefix followed by its key
    /// ("timings." and a StageTimer's stages: "timings.solve", ...).
    void
    set(const std::string &prefix, const std::map<std::string, double> &values);

    /// The JSON text.
    std::string
    to_string() const;

    /// Write to a file through OutputFile: the file is replaced only when
    /// it was written completely; throws naming the file on failure.
    void
    write(const std::string &filename) const;

  private:
    struct Node
    {
      std::vector<std::pair<std::string, std::unique_ptr<Node>>> children;
      bool                                                       is_leaf = false;
      std::string                                                value; // JSON text
    };
    Node root;

    Node &
    find(const std::string &path);

    static void
    print(const Node &n, std::string &out, const unsigned int indent);
  };
} // namespace dealvem

#endif
