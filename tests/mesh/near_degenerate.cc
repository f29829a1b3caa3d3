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
// the bottom edge and the edge into the fourth vertex). Last, split_edge()
// on a short edge far from the origin (its tolerance follows the rounding
// of the coordinates, not only the edge's length).
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
  {
    // split_edge() far from the origin: a point computed on the chord of a
    // short, slanted edge carries the rounding eps |x| of its coordinates,
    // so it lies off the chord by about eps |x| L, far above 1e-9 L^2 when
    // |x| / L is 1e9; the split is accepted (the tolerance follows the
    // coordinates' rounding), and a point off the chord by 1e-4 L is not
    PolygonalMesh<2> m;
    m.name = "far";
    const P      o(1.3e6, -0.7e6);
    const double L = 1.3e-3;
    for (const P &p : {o, o + dealii::Tensor<1, 2>({L, 0.37 * L}), o + dealii::Tensor<1, 2>({0.2 * L, L})})
      m.add_vertex(p);
    m.add_cell({0, 1, 2});
    m.finalize();
    unsigned int e = 0;
    for (; e < m.n_edges(); ++e)
      if ((m.edge(e).vertices[0] == 0 && m.edge(e).vertices[1] == 1) ||
          (m.edge(e).vertices[0] == 1 && m.edge(e).vertices[1] == 0))
        break;
    const P      a = m.vertex(m.edge(e).vertices[0]), b = m.vertex(m.edge(e).vertices[1]);
    unsigned int n_split = 0;
    for (const double t : {0.1234567, 0.5, 0.7654321})
      {
        PolygonalMesh<2> c = m;
        c.split_edge(e, a + t * (b - a));
        c.validate();
        ++n_split;
      }
    testing::check(n_split == 3, "split_edge() 1e9 edge lengths from the origin accepts points on the chord");
    const dealii::Tensor<1, 2> normal({-(b - a)[1], (b - a)[0]});
    testing::check_throws(
      [&] {
        PolygonalMesh<2> c = m;
        c.split_edge(e, a + 0.5 * (b - a) + 1e-4 * normal);
      },
      "does not lie strictly inside edge",
      "split_edge() refuses a point 1e-4 L off the chord (500 units in the last place of its coordinates)");
  }
  return testing::finish();
}
