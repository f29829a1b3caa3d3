// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The finite-strain output (postprocessing/finite_strain_output.h):
// - a homogeneous deformation u = (F - I) X, F = [[1.2, 0.3], [-0.1, 0.9]],
//   interpolated on 3 x 2 quads of [0,2] x [0,1] (k = 1 and 2) and written by
//   write_finite_strain_vtu_file(): read back from the file, every cell's
//   "cauchy_stress" equals the Neo-Hooke sigma = J^-1 P F^T (E = 100,
//   nu = 0.3) to 1e-12 relative, "det_F" equals det F to 1e-13 and the
//   point "displacement" equals (F - I) X at every vertex to 1e-13;
// - a state with det F < 0 is refused, naming the cell, and a law without
//   a finite-strain response too;
// - write_pvd_record() writes one DataSet per entry, in order, with the
//   times and file names given; an empty list, times that do not increase
//   and a file name with a quote are refused with a message saying so.
#include <deal.II/base/function.h>

#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/postprocessing/finite_strain_output.h>
#include <dealvem/vem/virtual_element.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

#include "../tests.h"

using namespace dealvem;

namespace
{
  class Homogeneous : public dealii::Function<2>
  {
  public:
    explicit Homogeneous(const dealii::Tensor<2, 2> &F)
      : dealii::Function<2>(2)
      , F(F)
    {}
    double
    value(const dealii::Point<2> &p, const unsigned int c) const override
    {
      return F[c][0] * p[0] + F[c][1] * p[1] - p[c];
    }
    dealii::Tensor<2, 2> F;
  };

  std::string
  read(const std::string &file)
  {
    std::ifstream      in(file);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  // the numbers of the DataArray named @p name
  std::vector<double>
  data_array(const std::string &text, const std::string &name)
  {
    const auto from = text.find("Name=\"" + name + "\"");
    if (from == std::string::npos)
      return {};
    const auto         begin = text.find('>', from) + 1;
    const auto         end   = text.find("</DataArray>", begin);
    std::istringstream in(text.substr(begin, end - begin));
    std::vector<double> values;
    double              x;
    while (in >> x)
      values.push_back(x);
    return values;
  }

  dealii::Vector<double>
  interpolate(const VEMDoFHandler<2> &dof_handler, const dealii::Function<2> &u)
  {
    dealii::Vector<double>                       x(dof_handler.n_dofs()), local;
    VirtualElement<2>                            element(dof_handler.get_degree());
    std::vector<dealii::types::global_dof_index> indices;
    const auto                                  &mesh = dof_handler.get_mesh();
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        element.reinit(mesh.cell_vertices(c));
        element.interpolate(u, local);
        dof_handler.get_dof_indices(c, indices);
        for (unsigned int i = 0; i < indices.size(); ++i)
          x[indices[i]] = local[i];
      }
    return x;
  }
} // namespace

int
main()
{
  PolygonalMesh<2> mesh;
  PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, 0), dealii::Point<2>(2, 1), 3, 2);
  const NeoHookeMaterial law(100., 0.3);
  MaterialLibrary<2>     laws;
  laws.add(0, law);

  dealii::Tensor<2, 2> F;
  F[0][0] = 1.2;
  F[0][1] = 0.3;
  F[1][0] = -0.1;
  F[1][1] = 0.9;
  const double               J     = dealii::determinant(F);
  const dealii::Tensor<2, 2> sigma = law.cauchy_stress(F);
  const Homogeneous          u(F);

  for (const unsigned int k : {1u, 2u})
    {
      const std::string name = "k = " + std::to_string(k);
      VEMDoFHandler<2>  dof_handler(mesh);
      dof_handler.distribute_dofs(k);
      const dealii::Vector<double> x    = interpolate(dof_handler, u);
      const std::string            file = "homogeneous-k" + std::to_string(k) + ".vtu";
      write_finite_strain_vtu_file(file, dof_handler, laws, x);
      const std::string text = read(file);

      const std::vector<double> s = data_array(text, "cauchy_stress"), det = data_array(text, "det_F"),
                                d = data_array(text, "displacement");
      testing::check(s.size() == 3 * mesh.n_cells() && det.size() == mesh.n_cells() &&
                       d.size() == 3 * mesh.n_vertices(),
                     name + ": the arrays cauchy_stress, det_F and displacement have one entry per cell / vertex");
      double err_s = 0, err_J = 0, err_u = 0;
      for (unsigned int c = 0; c < mesh.n_cells() && s.size() == 3 * mesh.n_cells() && det.size() == mesh.n_cells();
           ++c)
        {
          err_s = std::max({err_s, std::abs(s[3 * c] - sigma[0][0]), std::abs(s[3 * c + 1] - sigma[1][1]),
                            std::abs(s[3 * c + 2] - sigma[0][1])});
          err_J = std::max(err_J, std::abs(det[c] - J));
        }
      for (unsigned int v = 0; v < mesh.n_vertices() && d.size() == 3 * mesh.n_vertices(); ++v)
        err_u = std::max({err_u, std::abs(d[3 * v] - u.value(mesh.vertex(v), 0)),
                          std::abs(d[3 * v + 1] - u.value(mesh.vertex(v), 1)), std::abs(d[3 * v + 2])});
      testing::check_small(err_s / sigma.norm(), 1e-12, name + ": cell Cauchy stress of the homogeneous state");
      testing::check_small(err_J, 1e-13, name + ": cell det F");
      testing::check_small(err_u, 1e-13, name + ": vertex displacement");

      // an inverted state: F = [[-0.5, 0], [0, 1]]
      dealii::Tensor<2, 2> G;
      G[0][0] = -0.5;
      G[1][1] = 1.;
      const dealii::Vector<double> y = interpolate(dof_handler, Homogeneous(G));
      testing::check_throws([&]() { write_finite_strain_vtu_file("inverted.vtu", dof_handler, laws, y); },
                            "of cell 0 (an inverted or collapsed cell)", name + ": an inverted state is refused");
    }

  // a law without a finite-strain response
  {
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(1);
    MaterialLibrary<2> linear;
    linear.add(0, ElasticMaterial(100., 0.3, ElasticMaterial::Model::plane_strain));
    testing::check_throws(
      [&]() { write_finite_strain_vtu_file("linear.vtu", dof_handler, linear, dealii::Vector<double>(dof_handler.n_dofs())); },
      "has no finite-strain response", "a linear law is refused");
  }

  // the .pvd collection
  write_pvd_record("series.pvd", {{0., "a-00.vtu"}, {0.5, "a-01.vtu"}, {1., "a-02.vtu"}});
  const std::string pvd = read("series.pvd");
  const auto        p0 = pvd.find("timestep=\"0\" group=\"\" part=\"0\" file=\"a-00.vtu\"");
  const auto        p1 = pvd.find("timestep=\"0.5\" group=\"\" part=\"0\" file=\"a-01.vtu\"");
  const auto        p2 = pvd.find("timestep=\"1\" group=\"\" part=\"0\" file=\"a-02.vtu\"");
  testing::check(pvd.find("<VTKFile type=\"Collection\"") != std::string::npos && p0 != std::string::npos &&
                   p1 != std::string::npos && p2 != std::string::npos && p0 < p1 && p1 < p2,
                 "the .pvd lists the three data sets in order with their times");
  testing::check_throws([]() { write_pvd_record("bad.pvd", {}); }, "the list of time steps is empty",
                        "an empty series is refused");
  testing::check_throws([]() { write_pvd_record("bad.pvd", {{0., "a.vtu"}, {0., "b.vtu"}}); },
                        "the times do not increase at entry 1", "equal times are refused");
  testing::check_throws([]() { write_pvd_record("bad.pvd", {{0., "a\".vtu"}}); }, "holds a quote",
                        "a file name with a quote is refused");
  return testing::finish();
}
