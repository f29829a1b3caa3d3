// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The gmsh .msh reader behind MeshIO::read_msh() and
// MeshIO::read_msh_physical_names(), private to the library: the parsing of
// the sections is in gmsh_reader.cc, the checks of the cells and boundary
// lines that were read in gmsh_checks.cc, the conversion into a
// PolygonalMesh in gmsh_io.cc.
#ifndef dealvem_mesh_gmsh_reader_h
#define dealvem_mesh_gmsh_reader_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>

#include <dealvem/mesh/mesh_io.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace dealvem
{
  namespace MeshIO
  {
    namespace internal
    {
      // The gmsh element types of dimension 0 to 2 (the numbers of gmsh's
      // element type table): the number of nodes, of which the corners come
      // first in every type.
      struct ElementKind
      {
        unsigned int dim       = 0;
        unsigned int n_nodes   = 0;
        unsigned int n_corners = 0;
      };

      // An element the mesh keeps: a line with a physical tag (a boundary
      // An element the mesh keeps: a line with a physical tag (a boundary
      // id) or a triangle or quadrangle (a cell), by its corners.
      struct Element
      {
        long long                   number   = 0; // element number (2.2) or tag (4.1)
        std::size_t                 line     = 0; // line of the file
        long long                   physical = 0; // physical tag, 0 if none
        long long                   type     = 0; // gmsh element type
        unsigned int                n        = 0; // number of corners
        std::array<unsigned int, 4> node     = {{0, 0, 0, 0}}; // indices into the nodes
      };

      // the key of the edge between the nodes @p a and @p b, in either order
      inline std::pair<unsigned int, unsigned int>
      edge_key(const unsigned int a, const unsigned int b)
      {
        return {std::min(a, b), std::max(a, b)};
      }

      // Parses a gmsh file held in memory. A count is checked against the
      // size of the file before anything is allocated for it; memory is
      // proportional to the size of the file.
      class GmshReader
      {
      public:
        GmshReader(const std::string &name, std::string data, const bool separate_parts)
          : name(name)
          , data(std::move(data))
          , separate_parts(separate_parts)
        {}

        // what the file holds, after run()
        std::vector<dealii::Point<2>>                          points;    // by node index
        std::vector<long long>                                 node_tags; // by node index
        std::vector<Element>                                   cells, lines;
        PhysicalNames                                          names;

        // Read the file; with @p names_only up to the first section after
        // $PhysicalNames (the format and the names only).
        void
        run(const bool names_only = false);

        // Elements in messages (defined in gmsh_checks.cc): "quadrangle 7",
        // with " (line 23)" if @p at_line
        std::string
        element_name(const Element &e, const bool at_line = true) const;

        dealii::ExcMessage
        element_error(const Element &e, const std::string &what) const;

        std::string
        node_list(const Element &e) const;

        // the cells at each edge (by node indices), after run()
        std::map<std::pair<unsigned int, unsigned int>, std::vector<std::size_t>> edge_cells;

      private:
        const std::string name;
        const std::string data;
        const bool        separate_parts;
        std::size_t       pos = 0;
        // lines up to pos (counted on demand)
        std::size_t              line = 0, counted = 0, newlines = 0;
        std::string              text;
        std::vector<std::string> words;
        int                      version = 22; // 22 or 41
        bool                     binary  = false;
        std::unordered_map<long long, unsigned int> node_index;
        // physical tag of each entity (dimension, tag) of a 4.1 file
        std::map<std::pair<int, int>, long long> entity_physical;
        std::set<std::pair<int, int>>            entities;
        bool                                     have_entities = false;

        // The parsing (defined in gmsh_reader.cc): the message of an error
        // at the current line, then the lines, words and numbers of the file,
        // then its sections.
        dealii::ExcMessage
        error(const std::string &what) const;

        // the line of the file at pos (1 + the newlines before it)
        std::size_t
        line_at_pos();

        // The next line that is not blank, split into words; false at the
        // end of the file.
        bool
        next_line();

        void
        read_line(const std::string &expected);

        void
        expect_marker(const std::string &marker);

        void
        end_section(const std::string &marker);

        void
        expect_words(const std::size_t n, const std::string &what);

        long long
        integer(const std::string &word, const std::string &what, const long long min, const long long max) const;

        // A count of records that follow, each of at least @p min_bytes
        // bytes: bounded by the size of the file.
        long long
        count(const long long n, const std::string &word, const std::string &what,
              const std::uintmax_t min_bytes) const;

        long long
        count(const std::string &word, const std::string &what, const std::uintmax_t min_bytes) const;

        double
        coordinate(const double v, const std::string &word, const std::string &what) const;

        double
        coordinate(const std::string &word, const std::string &what) const;

        // a physical tag that becomes a material id (cells) or a boundary id
        long long
        physical_id(const long long v, const std::string &word, const std::string &what, const bool material) const;

        long long
        physical_id(const std::string &word, const std::string &what, const bool material) const;

        // binary values, in the byte order of this machine (checked with
        // the marker of the header)
        template <typename T>
        T
        get(const std::string &what);

        // where binary data is read: the line and the byte offset
        void
        at_binary();

        std::string
        byte() const;

        void
        read_format();

        void
        read_physical_names();

        // $Entities of a 4.1 file: the physical tag of each point, curve
        // and surface
        void
        read_entities();

        // skip a section this reader does not use (gmsh's rule for readers)
        void
        skip_section(const std::string &section);

        unsigned int
        add_node(const long long tag, const std::string &word, const std::string &what);

        void
        set_node_text(const unsigned int i, const std::string &x, const std::string &y, const std::string &z,
                      const std::string &what);

        void
        set_node_binary(const unsigned int i, const std::string &what);

        void
        read_nodes_2();

        // the four counts of $Nodes or $Elements in a 4.1 file
        std::array<long long, 2>
        block_counts(const std::string &kind, const std::uintmax_t min_entry_bytes);

        // the header of a block of a 4.1 file: dimension, tag, type or
        // parametric flag, count
        std::array<long long, 4>
        block_header(const std::string &block, const std::string &third, const std::uintmax_t min_bytes);

        void
        read_nodes_4();

        ElementKind
        kind_of(const long long type, const std::string &word, const std::string &what) const;

        // Keeps an element with the node tags @p tags (words or binary
        // values already read): all must be in $Nodes and distinct.
        void
        keep_element(const long long number, const long long physical, const long long type, const ElementKind &kind,
                     const std::vector<long long> &tags, const std::string &what);

        void
        read_elements_2();

        void
        read_elements_4();

        // The checks of what was read (defined in gmsh_checks.cc).
        //
        // No cell without area or with a side of length zero, no bow-tie
        // quadrangle, no clockwise cell, no cell given twice, no edge of
        // more than two cells, no edge between two bodies (physical
        // surfaces) unless the parts become bodies of their own.
        void
        check_cells();

        // Lines with a physical tag give boundary ids: each must be an edge
        // of exactly one cell, and an edge gets one id.
        void
        check_lines();
      };
    } // namespace internal
  } // namespace MeshIO
} // namespace dealvem

#endif
