// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/postprocessing/json_summary.h>
#include <dealvem/base/output_file.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace dealvem
{
  JsonSummary::Node &
  JsonSummary::find(const std::string &path)
  {
    Node       *n = &root;
    std::size_t start = 0;
    while (true)
      {
        const std::size_t dot  = path.find('.', start);
        const std::string name = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
        Node             *next = nullptr;
        for (auto &c : n->children)
          if (c.first == name)
            next = c.second.get();
        if (next == nullptr)
          {
            n->children.emplace_back(name, std::make_unique<Node>());
            next = n->children.back().second.get();
          }
        n = next;
        if (dot == std::string::npos)
          return *n;
        start = dot + 1;
      }
  }



  void
  JsonSummary::set(const std::string &path, const double value)
  {
    // JSON has no inf or NaN, and a null in place of a number that
    // overflowed would hide the failure from whoever reads the summary
    AssertThrow(std::isfinite(value),
                dealii::ExcMessage("JSON summary: the value of '" + path + "' is " +
                                   (std::isnan(value) ? std::string("NaN") : value > 0 ? "inf" : "-inf") +
                                   "; a summary with a non-finite number is not written. The quantity "
                                   "overflowed (check the input for values far from 1 in the units of "
                                   "the problem)."));
    Node &n   = find(path);
    n.is_leaf = true;
    std::ostringstream s;
    s << std::setprecision(17) << value;
    n.value = s.str();
  }



  void
  JsonSummary::set(const std::string &prefix, const std::map<std::string, double> &values)
  {
    for (const auto &v : values)
      set(prefix + v.first, v.second);
  }



  void
  JsonSummary::set(const std::string &path, const std::string &value)
  {
    Node &n   = find(path);
    n.is_leaf = true;
    std::string e = "\"";
    for (const char c : value)
      {
        if (c == '"' || c == '\\')
          e += '\\', e += c;
        else if (c == '\n')
          e += "\\n";
        else if (static_cast<unsigned char>(c) < 0x20)
          e += ' ';
        else
          e += c;
      }
    n.value = e + "\"";
  }



  void
  JsonSummary::print(const Node &n, std::string &out, const unsigned int indent)
  {
    if (n.is_leaf)
      {
        out += n.value;
        return;
      }
    out += "{\n";
    for (unsigned int i = 0; i < n.children.size(); ++i)
      {
        out += std::string(indent + 2, ' ') + "\"" + n.children[i].first + "\": ";
        print(*n.children[i].second, out, indent + 2);
        out += (i + 1 < n.children.size() ? ",\n" : "\n");
      }
    out += std::string(indent, ' ') + "}";
  }



  std::string
  JsonSummary::to_string() const
  {
    std::string out;
    print(root, out, 0);
    return out + "\n";
  }



  void
  JsonSummary::write(const std::string &filename) const
  {
    OutputFile file(filename);
    file.stream() << to_string();
    file.commit();
  }
} // namespace dealvem
