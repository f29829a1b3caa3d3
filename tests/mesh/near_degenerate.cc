// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Near-degenerate cells and what validation decides about them, with the
// reason the decisions use a tolerance rather than exact predicates.
//
// The pentagon (0,0), (2,0), (2,2), (1,d), (0,2) has its fourth vertex at
// height d above the bottom edge, which is not one of its own edges:
// - d = 0: the loop touches itself (exact predicates say the same);
// - d = -1e-15: the vertex lies below the bottom edge, the loop crosses
//   itself (so do exact predicates);
// - d = 1e-15 and 1e-13: exactly, the loop is simple -- two halves joined
//   by a neck 1e-15 wide. Validation rejects it as self-intersecting: a vertex
//   within 1e-12 times the edge lengths of a non-adjacent edge is touching.
//   A virtual element on such a cell has a projector and a stabilization
//   scaled by the cell diameter while the cell is two cells, and a mesh file
//   that means "touching" carries round-off of this size, so exact
//   orientation tests (CGAL's or Shewchuk's) would accept what must be
//   refused; the tolerance decision is the intended one and is kept;
// - d = 1e-6 and 0.25: a thin but genuine neck, accepted, area 2 + d to
//   1e-14.
// Each rejection names the cell and the two edges of its loop (0 and 2:
// the bottom edge and the edge into the fourth vertex).
#include <dealvem/mesh/polygonal_mesh.h>

#include "../tests.h"

#include <sstream>

using namespace dealvem;
using P = dealii::Point<2>;

namespace
{
  PolygonalMesh<2>
  pentagon(const double d)
  {
    PolygonalMesh<2> m;
    m.name = "pentagon";
    for (const P &p : {P(0, 0), P(2, 0), P(2, 2), P(1, d), P(0, 2)})
      m.add_vertex(p);
    m.add_cell({0, 1, 2, 3, 4});
    m.finalize();
    return m;
  }
} // namespace

int
main()
{
  for (const double d : {0., -1e-15, 1e-15, 1e-13})
    {
      std::ostringstream s;
      s << "pentagon with its fourth vertex " << d << " above a non-adjacent edge";
      testing::check_throws([d] { pentagon(d); }, "mesh 'pentagon': cell 0 is self-intersecting (edges 0 and 2",
                            s.str() + " is rejected");
    }
  for (const double d : {1e-6, 0.25})
    {
      const PolygonalMesh<2> m = pentagon(d);
      testing::check_near(m.total_area(), 2 + d, 1e-14, "pentagon with a neck of width " + std::to_string(d) +
                                                            " is valid, area 2 + d");
    }
  return testing::finish();
}
