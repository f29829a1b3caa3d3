// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The parsing half of the gmsh reader (gmsh_reader.h): the sections
// $MeshFormat, $PhysicalNames, $Entities, $Nodes and $Elements of formats
// 2.2 and 4.1, ASCII and binary, and the words and numbers they are made of.
#include <dealvem/mesh/generators.h>

#include "gmsh_reader.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <tuple>

namespace dealvem
{
  namespace MeshIO
  {
    namespace internal
    {
      namespace
      {
        // Coordinates beyond this magnitude are refused (PolygonalMesh uses
        // the same limit): products of coordinate differences would overflow.
        constexpr double max_coordinate = 1e100;

        bool
        element_kind(const long long type, ElementKind &kind)
        {
          // lines: 2, 3, 4, 5, 6 nodes (types 1, 8, 26, 27, 28), 7 to 11
          // nodes (62 to 66)
          static const std::map<long long, unsigned int> lines = {
            {1, 2}, {8, 3}, {26, 4}, {27, 5}, {28, 6}, {62, 7}, {63, 8}, {64, 9}, {65, 10}, {66, 11}};
          // triangles: complete and incomplete (serendipity) types of order
          // 1 to 10
          static const std::map<long long, unsigned int> triangles = {
            {2, 3},   {9, 6},   {20, 9},  {21, 10}, {22, 12}, {23, 15}, {24, 15}, {25, 21}, {42, 28},
            {43, 36}, {44, 45}, {45, 55}, {46, 66}, {52, 18}, {53, 21}, {54, 24}, {55, 27}, {56, 30}};
          static const std::map<long long, unsigned int> quadrangles = {
            {3, 4},   {10, 9},  {16, 8},   {36, 16},  {37, 25}, {38, 36}, {39, 12}, {40, 16}, {41, 20},
            {47, 49}, {48, 64}, {49, 81}, {50, 100}, {51, 121}, {57, 24}, {58, 28}, {59, 32}, {60, 36},
            {61, 40}};
          if (type == 15)
            {
              kind = {0, 1, 1};
              return true;
            }
          for (const auto &[table, dim, corners] :
               {std::make_tuple(&lines, 1u, 2u), std::make_tuple(&triangles, 2u, 3u),
                std::make_tuple(&quadrangles, 2u, 4u)})
            {
              const auto it = table->find(type);
              if (it != table->end())
                {
                  kind = {dim, it->second, corners};
                  return true;
                }
            }
          return false;
        }
      } // namespace



      // Read the file; with @p names_only up to the first section after
      // $PhysicalNames (the format and the names only).
      void
      GmshReader::run(const bool names_only)
      {
        read_format();
        bool have_nodes = false, have_elements = false;
        while (true)
          {
            if (!next_line())
              break;
            const std::string section = words[0];
            AssertThrow(section[0] == '$',
                        error("expected a section ($Nodes, $Elements, ...), found '" + text + "'."));
            if (names_only && (section == "$Entities" || section == "$Nodes" || section == "$Elements"))
              return;
            if (section == "$PhysicalNames")
              read_physical_names();
            else if (section == "$Entities")
              read_entities();
            else if (section == "$Nodes")
              {
                AssertThrow(!have_nodes, error("a second $Nodes section."));
                version == 22 ? read_nodes_2() : read_nodes_4();
                have_nodes = true;
                end_section("$EndNodes");
              }
            else if (section == "$Elements")
              {
                AssertThrow(have_nodes, error("$Elements before $Nodes."));
                AssertThrow(!have_elements, error("a second $Elements section."));
                version == 22 ? read_elements_2() : read_elements_4();
                have_elements = true;
                end_section("$EndElements");
              }
            else
              skip_section(section);
          }
        if (names_only)
          return;
        AssertThrow(have_nodes && have_elements,
                    error("unexpected end of file, expected " + std::string(have_nodes ? "$Elements" : "$Nodes") +
                          "; the file is truncated."));
        AssertThrow(!cells.empty(),
                    error("the file has no triangles or quadrangles (two-dimensional elements): no cells."));
        check_cells();
        check_lines();
      }



      dealii::ExcMessage
      GmshReader::error(const std::string &what) const
      {
        return dealii::ExcMessage("Invalid gmsh file " + name + ":" + std::to_string(line) + ": " + what);
      }



      // the line of the file at pos (1 + the newlines before it)
      std::size_t
      GmshReader::line_at_pos()
      {
        newlines += std::count(data.begin() + counted, data.begin() + pos, '\n');
        counted = pos;
        return newlines + 1;
      }



      // The next line that is not blank, split into words; false at the
      // end of the file.
      bool
      GmshReader::next_line()
      {
        while (pos < data.size())
          {
            line             = line_at_pos();
            std::size_t end  = data.find('\n', pos);
            if (end == std::string::npos)
              end = data.size();
            text = data.substr(pos, end - pos);
            pos  = std::min(end + 1, data.size());
            if (!text.empty() && text.back() == '\r')
              text.pop_back();
            words.clear();
            std::istringstream s(text);
            std::string        w;
            while (s >> w)
              words.push_back(w);
            if (!words.empty())
              return true;
          }
        return false;
      }



      void
      GmshReader::read_line(const std::string &expected)
      {
        AssertThrow(next_line(), error("unexpected end of file, expected " + expected + "; the file is truncated."));
      }



      void
      GmshReader::expect_marker(const std::string &marker)
      {
        AssertThrow(words.size() == 1 && words[0] == marker, error("expected " + marker + ", found '" + text + "'."));
      }



      void
      GmshReader::end_section(const std::string &marker)
      {
        read_line(marker);
        expect_marker(marker);
      }



      void
      GmshReader::expect_words(const std::size_t n, const std::string &what)
      {
        AssertThrow(words.size() == n, error("expected " + what + " (" + std::to_string(n) +
                                             (n == 1 ? " number" : " numbers") + " on the line), found '" + text +
                                             "'."));
      }



      long long
      GmshReader::integer(const std::string &word, const std::string &what, const long long min,
                          const long long max) const
      {
        long long  v = 0;
        const auto r = std::from_chars(word.data(), word.data() + word.size(), v);
        AssertThrow(r.ec == std::errc() && r.ptr == word.data() + word.size() && v >= min && v <= max,
                    error("expected " + what + " (an integer from " + std::to_string(min) + " to " +
                          std::to_string(max) + "), found '" + word + "'."));
        return v;
      }



      // A count of records that follow, each of at least @p min_bytes
      // bytes: bounded by the size of the file.
      long long
      GmshReader::count(const long long n, const std::string &word, const std::string &what,
                        const std::uintmax_t min_bytes) const
      {
        const std::uintmax_t capacity = data.size() / min_bytes;
        AssertThrow(n >= 0 && static_cast<std::uintmax_t>(n) <= capacity,
                    error(what + " is " + word + ", but the file has only " + std::to_string(data.size()) +
                          " bytes, room for at most " + std::to_string(capacity) +
                          "; the count is wrong or the file is truncated."));
        return n;
      }



      long long
      GmshReader::count(const std::string &word, const std::string &what, const std::uintmax_t min_bytes) const
      {
        long long  n = 0;
        const auto r = std::from_chars(word.data(), word.data() + word.size(), n);
        AssertThrow(r.ec == std::errc() && r.ptr == word.data() + word.size() && n >= 0,
                    error("expected " + what + " (a non-negative integer), found '" + word + "'."));
        return count(n, word, what, min_bytes);
      }



      double
      GmshReader::coordinate(const double v, const std::string &word, const std::string &what) const
      {
        AssertThrow(std::isfinite(v), error("expected " + what + " (a finite number), found '" + word + "'."));
        AssertThrow(std::abs(v) <= max_coordinate,
                    error(what + " is " + word + "; coordinates larger than 1e100 in magnitude are not "
                                                 "supported."));
        return v;
      }



      double
      GmshReader::coordinate(const std::string &word, const std::string &what) const
      {
        char        *end = nullptr;
        const double v   = std::strtod(word.c_str(), &end);
        AssertThrow(end == word.c_str() + word.size() && !word.empty(),
                    error("expected " + what + " (a finite number), found '" + word + "'."));
        return coordinate(v, word, what);
      }



      // a physical tag that becomes a material id (cells) or a boundary id
      long long
      GmshReader::physical_id(const long long v, const std::string &word, const std::string &what,
                              const bool material) const
      {
        const long long max = material ? PolygonalMeshGenerators::max_material_id : 254;
        AssertThrow(v >= 0 && v <= max,
                    error(what + " is '" + word + "', but it becomes " +
                          (material ? std::string("a material id, which must be an integer from 0 to ") +
                                        std::to_string(max) :
                                      std::string("a boundary id, which must be an integer from 0 to 254")) +
                          "."));
        return v;
      }



      long long
      GmshReader::physical_id(const std::string &word, const std::string &what, const bool material) const
      {
        long long  v = -1;
        const auto r = std::from_chars(word.data(), word.data() + word.size(), v);
        if (r.ec != std::errc() || r.ptr != word.data() + word.size())
          v = -1;
        return physical_id(v, word, what, material);
      }



      // binary values, in the byte order of this machine (checked with
      // the marker of the header)
      template <typename T>
      T
      GmshReader::get(const std::string &what)
      {
        if (pos + sizeof(T) > data.size())
          {
            pos  = data.size();
            line = line_at_pos();
            AssertThrow(false, error("unexpected end of file in the binary data, expected " + what +
                                     "; the file is truncated."));
          }
        T v;
        std::memcpy(&v, data.data() + pos, sizeof(T));
        pos += sizeof(T);
        return v;
      }



      // where binary data is read: the line and the byte offset
      void
      GmshReader::at_binary()
      {
        line = line_at_pos();
      }



      std::string
      GmshReader::byte() const
      {
        return " (byte " + std::to_string(pos) + ")";
      }



      void
      GmshReader::read_format()
      {
        read_line("$MeshFormat");
        AssertThrow(words.size() == 1 && words[0] == "$MeshFormat",
                    error(words.size() == 1 && words[0] == "$NOD" ?
                            "gmsh format 1 ($NOD) is not supported; save the mesh in format 2.2 or 4.1." :
                            "expected $MeshFormat (a gmsh .msh file), found '" + text + "'."));
        read_line("the version line");
        expect_words(3, "'version file-type data-size'");
        if (words[0] == "2.2" || words[0] == "2.1" || words[0] == "2" || words[0] == "2.0")
          version = 22;
        else if (words[0] == "4.1")
          version = 41;
        else
          AssertThrow(false, error("unsupported gmsh format version '" + words[0] +
                                   "' (supported: 2.2 and 4.1; gmsh saves 4.1 with '-format msh41')."));
        AssertThrow(words[1] == "0" || words[1] == "1",
                    error("expected the file-type 0 (ASCII) or 1 (binary), found '" + words[1] + "'."));
        binary = (words[1] == "1");
        AssertThrow(words[2] == "8", error("expected the data size 8, found '" + words[2] + "'."));
        if (binary)
          {
            // the integer 1 written in binary, then a newline
            const std::size_t l = line + 1;
            const auto marker   = get<std::int32_t>("the endianness marker (the binary integer 1)");
            line                = l;
            AssertThrow(marker == 1,
                        error(marker == 0x01000000 ?
                                "the binary file was written with the other byte order (the endianness marker "
                                "reads 16777216 instead of 1); save the mesh on this kind of machine or as ASCII." :
                                "expected the endianness marker of a binary file (the integer 1 in 4 bytes), "
                                "found " + std::to_string(marker) + "; the file is corrupt."));
          }
        end_section("$EndMeshFormat");
      }



      void
      GmshReader::read_physical_names()
      {
        read_line("the number of physical names");
        expect_words(1, "the number of physical names");
        const long long n = count(words[0], "the number of physical names", 6);
        for (long long i = 0; i < n; ++i)
          {
            const std::string what = "physical name " + std::to_string(i + 1) + " of " + std::to_string(n);
            read_line(what);
            const std::size_t open = text.find('"'), close = text.rfind('"');
            AssertThrow(words.size() >= 3 && words[0][0] != '$' && open != std::string::npos && close > open,
                        error("expected " + what + " ('dimension tag \"name\"'), found '" + text + "'."));
            const long long   dim  = integer(words[0], "the dimension of " + what, 0, 3);
            const long long   tag  = integer(words[1], "the tag of " + what, 0, std::numeric_limits<int>::max());
            const std::string word = text.substr(open + 1, close - open - 1);
            AssertThrow(!word.empty(), error(what + " is empty."));
            if (dim == 1 || dim == 2)
              {
                physical_id(tag, words[1], "the tag of " + what + " '" + word + "'", dim == 2);
                auto &map = (dim == 1 ? names.boundary_ids : names.material_ids);
                AssertThrow(map.emplace(word, tag).second,
                            error("the physical name '" + word + "' of dimension " + words[0] +
                                  " is given twice; physical names must be unique."));
              }
          }
        end_section("$EndPhysicalNames");
      }



      // $Entities of a 4.1 file: the physical tag of each point, curve
      // and surface
      void
      GmshReader::read_entities()
      {
        AssertThrow(version == 41, error("an $Entities section in a gmsh 2.2 file; is the version in $MeshFormat "
                                         "right?"));
        AssertThrow(!have_entities, error("a second $Entities section."));
        have_entities = true;
        long long n[4];
        if (binary)
          {
            at_binary();
            for (unsigned int d = 0; d < 4; ++d)
              {
                const auto v = get<std::uint64_t>("the number of entities of dimension " + std::to_string(d));
                n[d]         = count(v > std::uint64_t(std::numeric_limits<long long>::max()) ? -1 : (long long)v,
                             std::to_string(v), "the number of entities of dimension " + std::to_string(d) + byte(),
                             16);
              }
          }
        else
          {
            read_line("the numbers of points, curves, surfaces and volumes");
            expect_words(4, "the numbers of points, curves, surfaces and volumes");
            for (unsigned int d = 0; d < 4; ++d)
              n[d] = count(words[d], "the number of entities of dimension " + std::to_string(d), 8);
          }
        for (unsigned int d = 0; d < 4; ++d)
          for (long long i = 0; i < n[d]; ++i)
            {
              const std::string what = "entity " + std::to_string(i + 1) + " of " + std::to_string(n[d]) +
                                       " of dimension " + std::to_string(d);
              const std::size_t n_box = (d == 0 ? 3 : 6);
              int               tag   = 0;
              std::vector<long long> physicals;
              if (binary)
                {
                  tag = get<std::int32_t>("the tag of " + what);
                  for (std::size_t k = 0; k < n_box; ++k)
                    {
                      const double v = get<double>("a bounding box coordinate of " + what);
                      coordinate(v, std::to_string(v), "a bounding box coordinate of " + what + byte());
                    }
                  const auto np = get<std::uint64_t>("the number of physical tags of " + what);
                  count(np > 1000000 ? -1 : (long long)np, std::to_string(np),
                        "the number of physical tags of " + what + byte(), 4);
                  for (std::uint64_t k = 0; k < np; ++k)
                    physicals.push_back(get<std::int32_t>("a physical tag of " + what));
                  if (d > 0)
                    {
                      const auto nb = get<std::uint64_t>("the number of bounding entities of " + what);
                      count(nb > std::uint64_t(1) << 40 ? -1 : (long long)nb, std::to_string(nb),
                            "the number of bounding entities of " + what + byte(), 4);
                      for (std::uint64_t k = 0; k < nb; ++k)
                        get<std::int32_t>("a bounding entity of " + what);
                    }
                }
              else
                {
                  read_line(what);
                  AssertThrow(words.size() >= 2 + n_box && words[0][0] != '$',
                              error("expected " + what + ", found '" + text + "'."));
                  tag = int(integer(words[0], "the tag of " + what, std::numeric_limits<int>::min(),
                                    std::numeric_limits<int>::max()));
                  for (std::size_t k = 1; k <= n_box; ++k)
                    coordinate(words[k], "a bounding box coordinate of " + what);
                  const long long np =
                    integer(words[1 + n_box], "the number of physical tags of " + what, 0, 1000000);
                  std::size_t w = 2 + n_box;
                  AssertThrow(words.size() >= w + np, error("expected " + what + ", found '" + text + "'."));
                  for (long long k = 0; k < np; ++k)
                    physicals.push_back(integer(words[w++], "a physical tag of " + what,
                                                std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
                  if (d > 0)
                    {
                      AssertThrow(words.size() > w, error("expected the number of bounding entities of " + what +
                                                          ", found '" + text + "'."));
                      const long long nb = integer(words[w++], "the number of bounding entities of " + what, 0,
                                                   std::numeric_limits<int>::max());
                      AssertThrow(words.size() == w + nb, error("expected " + std::to_string(nb) +
                                                                " bounding entities of " + what + ", found '" +
                                                                text + "'."));
                      for (; w < words.size(); ++w)
                        integer(words[w], "a bounding entity of " + what, std::numeric_limits<int>::min(),
                                std::numeric_limits<int>::max());
                    }
                  else
                    AssertThrow(words.size() == w, error("expected " + what + ", found '" + text + "'."));
                }
              AssertThrow(entities.insert({int(d), tag}).second,
                          error(what + " has the tag " + std::to_string(tag) + ", which an entity of dimension " +
                                std::to_string(d) + " has already."));
              if (d == 1 || d == 2)
                {
                  AssertThrow(physicals.size() <= 1,
                              error(what + " (tag " + std::to_string(tag) + ") belongs to " +
                                    std::to_string(physicals.size()) + " physical groups; its elements would get " +
                                    std::to_string(physicals.size()) + (d == 2 ? " material" : " boundary") +
                                    " ids. Put each " + (d == 2 ? "surface" : "curve") +
                                    " into one physical group only."));
                  if (physicals.size() == 1)
                    entity_physical[{int(d), tag}] =
                      physical_id(physicals[0], std::to_string(physicals[0]), "the physical tag of " + what, d == 2);
                }
            }
        if (binary)
          at_binary();
        end_section("$EndEntities");
      }



      // skip a section this reader does not use (gmsh's rule for readers)
      void
      GmshReader::skip_section(const std::string &section)
      {
        const std::string end = "$End" + section.substr(1);
        const std::size_t at  = data.find("\n" + end, pos - 1);
        AssertThrow(at != std::string::npos,
                    error("the section " + section + " has no " + end + "; the file is truncated."));
        pos = at + 1;
        end_section(end);
      }



      unsigned int
      GmshReader::add_node(const long long tag, const std::string &word, const std::string &what)
      {
        AssertThrow(tag >= 1 && tag <= std::numeric_limits<int>::max(),
                    error("expected the tag of " + what + " (an integer from 1 to " +
                          std::to_string(std::numeric_limits<int>::max()) + "), found '" + word + "'."));
        const unsigned int index = points.size();
        AssertThrow(node_index.emplace(tag, index).second, error("node tag " + word + " is used twice."));
        points.emplace_back();
        node_tags.push_back(tag);
        return index;
      }



      void
      GmshReader::set_node_text(const unsigned int i, const std::string &x, const std::string &y, const std::string &z,
                                const std::string &what)
      {
        points[i] = dealii::Point<2>(coordinate(x, "x of " + what), coordinate(y, "y of " + what));
        coordinate(z, "z of " + what);
      }



      void
      GmshReader::set_node_binary(const unsigned int i, const std::string &what)
      {
        double xyz[3];
        for (unsigned int d = 0; d < 3; ++d)
          {
            xyz[d] = get<double>(std::string(1, "xyz"[d]) + " of " + what);
            if (!std::isfinite(xyz[d]) || std::abs(xyz[d]) > max_coordinate)
              {
                at_binary();
                std::ostringstream s;
                s << xyz[d];
                coordinate(xyz[d], s.str(), std::string(1, "xyz"[d]) + " of " + what + byte());
              }
          }
        points[i] = dealii::Point<2>(xyz[0], xyz[1]);
      }



      void
      GmshReader::read_nodes_2()
      {
        read_line("the number of nodes");
        expect_words(1, "the number of nodes after $Nodes");
        // ASCII "tag x y z": at least 8 bytes; binary: 4 + 3 * 8 bytes
        const long long n = count(words[0], "the number of nodes", binary ? 28 : 8);
        points.reserve(n);
        for (long long i = 0; i < n; ++i)
          {
            const std::string what = "node " + std::to_string(i + 1) + " of " + std::to_string(n);
            if (binary)
              {
                at_binary();
                const std::int32_t tag = get<std::int32_t>("the tag of " + what);
                set_node_binary(add_node(tag, std::to_string(tag), what), what);
                continue;
              }
            read_line(what);
            AssertThrow(words.size() == 4 && words[0][0] != '$',
                        error("expected " + what + " ('tag x y z'), found '" + text + "'."));
            long long  tag = -1;
            const auto r   = std::from_chars(words[0].data(), words[0].data() + words[0].size(), tag);
            if (r.ec != std::errc() || r.ptr != words[0].data() + words[0].size())
              tag = -1;
            set_node_text(add_node(tag, words[0], what), words[1], words[2], words[3], what);
          }
        if (binary)
          at_binary();
      }



      // the four counts of $Nodes or $Elements in a 4.1 file
      std::array<long long, 2>
      GmshReader::block_counts(const std::string &kind, const std::uintmax_t min_entry_bytes)
      {
        if (binary)
          {
            at_binary();
            std::uint64_t v[4];
            for (unsigned int k = 0; k < 4; ++k)
              v[k] = get<std::uint64_t>("the " + kind + " counts");
            const auto as_count = [&](const std::uint64_t x, const std::string &what, const std::uintmax_t b) {
              return count(x > std::uint64_t(std::numeric_limits<long long>::max()) ? -1 : (long long)x,
                           std::to_string(x), what, b);
            };
            return {{as_count(v[0], "the number of " + kind + " blocks", 20),
                     as_count(v[1], "the number of " + kind + "s", min_entry_bytes)}};
          }
        read_line("the " + kind + " counts");
        expect_words(4, kind == "node" ? "'numEntityBlocks numNodes minNodeTag maxNodeTag' after $Nodes, as "
                                         "format 4.1 in $MeshFormat says" :
                                         "'numEntityBlocks numElements minElementTag maxElementTag' after "
                                         "$Elements in format 4.1");
        return {{count(words[0], "the number of " + kind + " blocks", 8),
                 count(words[1], "the number of " + kind + "s", min_entry_bytes)}};
      }



      // the header of a block of a 4.1 file: dimension, tag, type or
      // parametric flag, count
      std::array<long long, 4>
      GmshReader::block_header(const std::string &block, const std::string &third, const std::uintmax_t min_bytes)
      {
        if (binary)
          {
            at_binary();
            const long long d = get<std::int32_t>("the entity dimension of " + block);
            const long long t = get<std::int32_t>("the entity tag of " + block);
            const long long x = get<std::int32_t>("the " + third + " of " + block);
            const auto      m = get<std::uint64_t>("the size of " + block);
            AssertThrow(d >= 0 && d <= 3, error("the entity dimension of " + block + " is " + std::to_string(d) +
                                                byte() + "; the file is corrupt."));
            return {{d, t, x,
                     count(m > std::uint64_t(std::numeric_limits<long long>::max()) ? -1 : (long long)m,
                           std::to_string(m), "the number of entries in " + block + byte(), min_bytes)}};
          }
        read_line(block);
        expect_words(4, "the header of " + block);
        return {{integer(words[0], "the entity dimension of " + block, 0, 3),
                 integer(words[1], "the entity tag of " + block, std::numeric_limits<int>::min(),
                         std::numeric_limits<int>::max()),
                 integer(words[2], "the " + third + " of " + block, std::numeric_limits<int>::min(),
                         std::numeric_limits<int>::max()),
                 count(words[3], "the number of entries in " + block, min_bytes)}};
      }



      void
      GmshReader::read_nodes_4()
      {
        const auto      counts   = block_counts("node", binary ? 32 : 8);
        const long long n_blocks = counts[0], n = counts[1];
        points.reserve(n);
        long long n_read = 0;
        for (long long b = 0; b < n_blocks; ++b)
          {
            const std::string block = "node block " + std::to_string(b + 1) + " of " + std::to_string(n_blocks);
            const auto        h     = block_header(block, "parametric flag", binary ? 32 : 8);
            AssertThrow(h[2] == 0, error("parametric nodes are not supported; save the mesh without parametric "
                                         "coordinates."));
            const long long m = h[3];
            AssertThrow(n_read + m <= n,
                        error(block + " goes beyond the " + std::to_string(n) + " nodes announced after $Nodes."));
            std::vector<unsigned int> index(m);
            for (long long i = 0; i < m; ++i)
              {
                const std::string what = "node " + std::to_string(n_read + i + 1) + " of " + std::to_string(n);
                if (binary)
                  {
                    at_binary();
                    const auto tag = get<std::uint64_t>("the tag of " + what);
                    index[i]       = add_node(tag > std::uint64_t(std::numeric_limits<int>::max()) ? -1 : (long long)tag,
                                        std::to_string(tag), what + byte());
                    continue;
                  }
                read_line("the tag of " + what);
                expect_words(1, "the tag of " + what);
                long long  tag = -1;
                const auto r   = std::from_chars(words[0].data(), words[0].data() + words[0].size(), tag);
                if (r.ec != std::errc() || r.ptr != words[0].data() + words[0].size())
                  tag = -1;
                index[i] = add_node(tag, words[0], what);
              }
            for (long long i = 0; i < m; ++i)
              {
                const std::string what = "node " + std::to_string(n_read + i + 1) + " of " + std::to_string(n);
                if (binary)
                  {
                    at_binary();
                    set_node_binary(index[i], what);
                    continue;
                  }
                read_line("the coordinates of " + what);
                expect_words(3, "the coordinates 'x y z' of " + what);
                set_node_text(index[i], words[0], words[1], words[2], what);
              }
            n_read += m;
          }
        if (binary)
          at_binary();
        AssertThrow(n_read == n, error("the node blocks hold " + std::to_string(n_read) + " nodes, but " +
                                       std::to_string(n) + " are announced after $Nodes."));
      }



      ElementKind
      GmshReader::kind_of(const long long type, const std::string &word, const std::string &what) const
      {
        ElementKind kind;
        AssertThrow(element_kind(type, kind),
                    error("element type " + word + " of " + what +
                          " is not supported in 2d (supported: points (15), lines (1, 8, 26-28, 62-66), "
                          "triangles (2, 9, 20-25, 42-46, 52-56) and quadrangles (3, 10, 16, 36-41, 47-51, "
                          "57-61) of any order, read by their corners)."));
        return kind;
      }



      // Keeps an element with the node tags @p tags (words or binary
      // values already read): all must be in $Nodes and distinct.
      void
      GmshReader::keep_element(const long long number, const long long physical, const long long type,
                               const ElementKind &kind, const std::vector<long long> &tags, const std::string &what)
      {
        for (std::size_t k = 0; k < tags.size(); ++k)
          {
            AssertThrow(node_index.count(tags[k]) == 1,
                        error(what + " refers to node '" + std::to_string(tags[k]) + "', which is not in $Nodes."));
            for (std::size_t j = 0; j < k; ++j)
              AssertThrow(tags[j] != tags[k], error(what + " uses node " + std::to_string(tags[k]) + " twice."));
          }
        if (kind.dim == 0 || (kind.dim == 1 && physical == 0))
          return; // points, and lines that carry no boundary id
        Element e;
        e.number   = number;
        e.line     = line;
        e.physical = physical;
        e.type     = type;
        e.n        = kind.n_corners;
        for (unsigned int k = 0; k < kind.n_corners; ++k)
          e.node[k] = node_index.at(tags[k]);
        (kind.dim == 1 ? lines : cells).push_back(e);
      }



      void
      GmshReader::read_elements_2()
      {
        read_line("the number of elements");
        expect_words(1, "the number of elements after $Elements");
        // ASCII: at least 8 bytes an element; binary: number, one node
        const long long        n = count(words[0], "the number of elements", 8);
        std::vector<long long> tags;
        long long              i = 0;
        while (i < n)
          {
            if (binary)
              {
                // a block: type, number of elements, number of tags
                at_binary();
                const std::string block = "the element block after element " + std::to_string(i);
                const long long   type  = get<std::int32_t>("the element type of " + block);
                const long long   m     = get<std::int32_t>("the number of elements of " + block);
                const long long   nt    = get<std::int32_t>("the number of tags of " + block);
                const ElementKind kind  = kind_of(type, std::to_string(type), block + byte());
                AssertThrow(m >= 1 && m <= n - i,
                            error(block + " announces " + std::to_string(m) + " elements" + byte() + ", but " +
                                  std::to_string(n - i) + " are left of the " + std::to_string(n) +
                                  " announced after $Elements."));
                AssertThrow(nt >= 0 && nt <= 1000,
                            error("the number of tags of " + block + " is " + std::to_string(nt) + byte() + "."));
                count(m, std::to_string(m), "the number of elements of " + block,
                      4 * (1 + nt + kind.n_nodes));
                for (long long j = 0; j < m; ++j, ++i)
                  {
                    const std::string what = "element " + std::to_string(i + 1) + " of " + std::to_string(n);
                    at_binary();
                    const long long number = get<std::int32_t>("the number of " + what);
                    long long       physical = 0;
                    for (long long k = 0; k < nt; ++k)
                      {
                        const long long t = get<std::int32_t>("a tag of " + what);
                        if (k == 0 && kind.dim > 0)
                          physical = physical_id(t, std::to_string(t), "the physical tag of " + what, kind.dim == 2);
                      }
                    tags.resize(kind.n_nodes);
                    for (auto &t : tags)
                      t = get<std::int32_t>("a node of " + what);
                    keep_element(number, physical, type, kind, tags, what);
                  }
                continue;
              }
            const std::string what = "element " + std::to_string(i + 1) + " of " + std::to_string(n);
            read_line(what);
            AssertThrow(words.size() >= 3 && words[0][0] != '$',
                        error("expected " + what + " ('number type n-tags tags... nodes...'), found '" + text +
                              "'."));
            const long long   number = integer(words[0], "the number of " + what, 0, std::numeric_limits<int>::max());
            const long long   type   = integer(words[1], "the element type of " + what, 0,
                                               std::numeric_limits<int>::max());
            const ElementKind kind   = kind_of(type, words[1], what);
            const long long   n_tags = integer(words[2], "the number of tags of " + what, 0, 1000);
            AssertThrow(words.size() == std::size_t(3 + n_tags + kind.n_nodes),
                        error("expected " + std::to_string(n_tags) + " tags and " + std::to_string(kind.n_nodes) +
                              " nodes for " + what + ", found '" + text + "'."));
            // the first tag (the physical group) becomes the id
            long long physical = 0;
            if (n_tags > 0 && kind.dim > 0)
              physical = physical_id(words[3], "the physical tag of " + what, kind.dim == 2);
            for (long long k = 1; k < n_tags; ++k)
              integer(words[3 + k], "a tag of " + what, std::numeric_limits<int>::min(),
                      std::numeric_limits<int>::max());
            tags.resize(kind.n_nodes);
            for (unsigned int k = 0; k < kind.n_nodes; ++k)
              {
                const std::string &w = words[3 + n_tags + k];
                const auto         r = std::from_chars(w.data(), w.data() + w.size(), tags[k]);
                AssertThrow(r.ec == std::errc() && r.ptr == w.data() + w.size(),
                            error(what + " refers to node '" + w + "', which is not in $Nodes."));
              }
            keep_element(number, physical, type, kind, tags, what);
            ++i;
          }
        if (binary)
          at_binary();
      }



      void
      GmshReader::read_elements_4()
      {
        const auto      counts   = block_counts("element", binary ? 16 : 4);
        const long long n_blocks = counts[0], n = counts[1];
        long long       n_read = 0;
        std::vector<long long> tags;
        for (long long b = 0; b < n_blocks; ++b)
          {
            const std::string block = "element block " + std::to_string(b + 1) + " of " + std::to_string(n_blocks);
            const auto        h     = block_header(block, "element type", binary ? 16 : 4);
            const int         dim = int(h[0]), tag = int(h[1]);
            AssertThrow(!have_entities || entities.count({dim, tag}) == 1,
                        error(block + " refers to the entity of dimension " + std::to_string(dim) + " and tag " +
                              std::to_string(tag) + ", which is not in $Entities."));
            const ElementKind kind = kind_of(h[2], std::to_string(h[2]), block);
            AssertThrow(kind.dim == unsigned(dim),
                        error(block + " has elements of type " + std::to_string(h[2]) + " (dimension " +
                              std::to_string(kind.dim) + ") on an entity of dimension " + std::to_string(dim) +
                              "."));
            const long long m = h[3];
            AssertThrow(n_read + m <= n, error(block + " goes beyond the " + std::to_string(n) +
                                               " elements announced after $Elements."));
            if (binary)
              count(m, std::to_string(m), "the number of elements in " + block, 8 * (1 + kind.n_nodes));
            const auto      p        = entity_physical.find({dim, tag});
            const long long physical = (p == entity_physical.end() ? 0 : p->second);
            tags.resize(kind.n_nodes);
            for (long long i = 0; i < m; ++i)
              {
                const std::string what = "element " + std::to_string(n_read + i + 1) + " of " + std::to_string(n);
                long long         number = 0;
                if (binary)
                  {
                    at_binary();
                    const auto t = get<std::uint64_t>("the tag of " + what);
                    number       = t > std::uint64_t(std::numeric_limits<int>::max()) ? -1 : (long long)t;
                    for (auto &x : tags)
                      {
                        const auto v = get<std::uint64_t>("a node of " + what);
                        x            = v > std::uint64_t(std::numeric_limits<int>::max()) ? -1 : (long long)v;
                      }
                  }
                else
                  {
                    read_line(what);
                    AssertThrow(words.size() == 1 + kind.n_nodes,
                                error("expected " + what + " ('tag' and " + std::to_string(kind.n_nodes) +
                                      " nodes), found '" + text + "'."));
                    number = integer(words[0], "the tag of " + what, 1, std::numeric_limits<int>::max());
                    for (unsigned int k = 0; k < kind.n_nodes; ++k)
                      {
                        const std::string &w = words[1 + k];
                        const auto         r = std::from_chars(w.data(), w.data() + w.size(), tags[k]);
                        AssertThrow(r.ec == std::errc() && r.ptr == w.data() + w.size(),
                                    error(what + " refers to node '" + w + "', which is not in $Nodes."));
                      }
                  }
                keep_element(number, physical, h[2], kind, tags, what);
              }
            n_read += m;
          }
        if (binary)
          at_binary();
        AssertThrow(n_read == n, error("the element blocks hold " + std::to_string(n_read) + " elements, but " +
                                       std::to_string(n) + " are announced after $Elements."));
      }
    } // namespace internal
  } // namespace MeshIO
} // namespace dealvem
