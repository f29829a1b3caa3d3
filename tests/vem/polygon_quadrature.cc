// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// PolygonGeometry::quadrature(d) (a fan of deal.II QGaussSimplex /
// QWitherdenVincentSimplex rules) integrates every scaled monomial
// xi^a eta^b with a + b <= d exactly, for d = 0..13, on convex (Voronoi),
// non-convex and very flat polygons: compared with the divergence-theorem
// integrals of integrate_scaled_monomial() to 1e-13 relative to the
// integral of |xi^a eta^b| (estimated by the rule of degree 13); 1e-11 for the
// flat cell at x = 1000, whose quadrature points carry an absolute round-off
// of 1e-13 in xi and eta (a rule one degree short misses by far more).
// Degree 14 is refused with a message.
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/polygon_geometry.h>

#include <cmath>

#include "../tests.h"

using namespace dealvem;

int
main()
{
  std::vector<std::pair<std::string, std::vector<dealii::Point<2>>>> polygons;
  std::vector<double>                                                tolerances = {1e-13, 1e-13, 1e-13, 1e-11};
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::voronoi(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 9, 10, 3);
    polygons.emplace_back("voronoi cell", mesh.cell_vertices(4));
  }
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::nonconvex(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(1, 1), 3, 3, 0.4);
    polygons.emplace_back("non-convex cell", mesh.cell_vertices(4));
  }
  polygons.emplace_back("L-shape", std::vector<dealii::Point<2>>{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  polygons.emplace_back("flat quad 1:100 far away",
                        std::vector<dealii::Point<2>>{{1000, 7}, {1001, 7}, {1001, 7.01}, {1000, 7.01}});

  for (unsigned int p = 0; p < polygons.size(); ++p)
    {
      const auto &[name, vertices] = polygons[p];
      const PolygonGeometry<2> g(vertices);
      double                   worst = 0;
      for (unsigned int d = 0; d <= 13; ++d)
        {
          const dealii::Quadrature<2> q     = g.quadrature(d);
          const dealii::Quadrature<2> q_abs = g.quadrature(13);
          for (unsigned int a = 0; a <= d; ++a)
            {
              const unsigned int b = d - a; // only the top degree; lower ones are tested at lower d
              for (const unsigned int bb : {b, 0u})
                {
                  if (a + bb > d)
                    continue;
                  double sum = 0, scale = 0;
                  for (unsigned int i = 0; i < q.size(); ++i)
                    {
                      const dealii::Point<2> s = g.scaled(q.point(i));
                      sum += q.weight(i) * std::pow(s[0], a) * std::pow(s[1], bb);
                    }
                  for (unsigned int i = 0; i < q_abs.size(); ++i)
                    {
                      const dealii::Point<2> s = g.scaled(q_abs.point(i));
                      scale += std::abs(q_abs.weight(i) * std::pow(s[0], a) * std::pow(s[1], bb));
                    }
                  worst = std::max(worst, std::abs(sum - g.integrate_scaled_monomial(a, bb)) / scale);
                }
            }
        }
      testing::check_small(worst, tolerances[p], name + ": monomials of degree <= d exact for d = 0..13 (relative)");
    }
  testing::check_throws([&] { PolygonGeometry<2>(polygons[0].second).quadrature(14); },
                        "degree 14 is above the largest available (13)", "degree 14 is refused");
  return testing::finish();
}
