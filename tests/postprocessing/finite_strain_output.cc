// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The finite-strain output (postprocessing/finite_strain_output.h):
// - a homogeneous deformation u = (F - I) X, F = [[1.2, 0.3], [-0.1, 0.9]],
//   interpolated on 3 x 2 quads of [0,2] x [0,1] (k = 1 and 2) and written by
//   write_finite_strain_vtu_file(): read back from the file, as cell data and
//   as point data, "cauchy_stress" equals the Neo-Hooke sigma = J^-1 P F^T
//   (E = 100, nu = 0.3, plane strain) to 1e-12 relative,
//   "cauchy_stress_zz" the Neo-Hooke lambda ln J / J (written out here from
//   the law's formula), "cauchy_von_mises" the von Mises stress of the four
//   components (written out) and "principal_stretches" the square roots of
//   the eigenvalues of F^T F (by deal.II's eigenvalues()) and 1, all to
//   1e-12 relative; "det_F" equals det F to 1e-13 and the point
//   "displacement" equals (F - I) X at every vertex to 1e-13; the file has
//   no small-strain "stress" or "von_mises" array;
// - the same in plane stress (k = 1): sigma_zz = 0, the third stretch is
//   the law's thickness stretch f and det_F = f det F (1e-12);
// - the files are read by VTK's XML reader (read_vtu.py, finite-strain
//   mode) when python3 has the vtk module: every field present as point and
//   cell data, no small-strain stress (skipped, and said so, without it);
// - a state with det F < 0 is refused, naming the cell, and a law without
//   a finite-strain response too;
// - write_pvd_record() writes one DataSet per entry, in order, with the
//   times and file names given; an empty list, times that do not increase
//   and a file name with a quote are refused with a message saying so.
#include <deal.II/base/function.h>
#include <deal.II/base/symmetric_tensor.h>

#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/postprocessing/finite_strain_output.h>
#include <dealvem/vem/virtual_element.h>

#include <array>
#include <cmath>
#include <cstdlib>
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

  // the numbers of the DataArray named @p name in the section @p section
  // ("PointData" or "CellData")
  std::vector<double>
  data_array(const std::string &text, const std::string &name, const std::string &section = "CellData")
  {
    const auto open  = text.find("<" + section);
    const auto close = text.find("</" + section + ">");
    if (open == std::string::npos || close == std::string::npos)
      return {};
    const auto from = text.find("Name=\"" + name + "\"", open);
    if (from > close)
      return {};
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
  // the further fields, from their definitions
  const double sigma_zz  = law.lambda() * std::log(J) / J;
  const double von_mises = std::sqrt(0.5 * (std::pow(sigma[0][0] - sigma[1][1], 2) + std::pow(sigma[1][1] - sigma_zz, 2) +
                                            std::pow(sigma_zz - sigma[0][0], 2)) +
                                     3 * sigma[0][1] * sigma[0][1]);
  const auto   C_eig     = dealii::eigenvalues(dealii::SymmetricTensor<2, 2>(dealii::transpose(F) * F));
  const std::array<double, 3> stretches = {{std::sqrt(C_eig[0]), std::sqrt(C_eig[1]), 1.}};
  const bool has_vtk = std::system("/usr/bin/python3 -c 'import vtk' > /dev/null 2>&1") == 0;
  if (!has_vtk)
    std::cout << "note: python3 has no vtk module (python3-vtk9): the files are not read by VTK's reader" << std::endl;

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
                                d = data_array(text, "displacement", "PointData");
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

      // every field as cell and point data
      for (const std::string section : {"CellData", "PointData"})
        {
          const unsigned int  n   = section == "CellData" ? mesh.n_cells() : mesh.n_vertices();
          const auto          st  = data_array(text, "cauchy_stress", section);
          const auto          zz  = data_array(text, "cauchy_stress_zz", section);
          const auto          vm  = data_array(text, "cauchy_von_mises", section);
          const auto          dj  = data_array(text, "det_F", section);
          const auto          lam = data_array(text, "principal_stretches", section);
          const std::string   what = name + ", " + section;
          const bool sizes = st.size() == 3 * n && zz.size() == n && vm.size() == n && dj.size() == n && lam.size() == 3 * n;
          testing::check(sizes, what + ": cauchy_stress, cauchy_stress_zz, cauchy_von_mises, det_F and "
                                       "principal_stretches have one entry per " + (n == mesh.n_cells() ? "cell" : "vertex"));
          double e_s = 0, e_zz = 0, e_vm = 0, e_J = 0, e_l = 0;
          for (unsigned int i = 0; sizes && i < n; ++i)
            {
              e_s  = std::max({e_s, std::abs(st[3 * i] - sigma[0][0]), std::abs(st[3 * i + 1] - sigma[1][1]),
                              std::abs(st[3 * i + 2] - sigma[0][1])});
              e_zz = std::max(e_zz, std::abs(zz[i] - sigma_zz));
              e_vm = std::max(e_vm, std::abs(vm[i] - von_mises));
              e_J  = std::max(e_J, std::abs(dj[i] - J));
              for (unsigned int c = 0; c < 3; ++c)
                e_l = std::max(e_l, std::abs(lam[3 * i + c] - stretches[c]));
            }
          testing::check_small(e_s / sigma.norm(), 1e-12, what + ": Cauchy stress");
          testing::check_small(e_zz / std::abs(sigma_zz), 1e-12, what + ": sigma_zz = lambda ln J / J");
          testing::check_small(e_vm / von_mises, 1e-12, what + ": von Mises stress");
          testing::check_small(e_J, 1e-13, what + ": det F");
          testing::check_small(e_l, 1e-12, what + ": principal stretches");
        }
      testing::check(text.find("Name=\"stress\"") == std::string::npos &&
                       text.find("Name=\"von_mises\"") == std::string::npos,
                     name + ": no small-strain stress or von_mises in the file");
      if (has_vtk)
        {
          const std::string cmd = "/usr/bin/python3 " + testing::source_dir() + "/tests/postprocessing/read_vtu.py " +
                                  file + " finite-strain > " + file + ".txt 2>&1";
          const int rc = std::system(cmd.c_str());
          std::cout << read(file + ".txt");
          testing::check(rc == 0, file + ": read by VTK's XML reader with every finite-strain field, no small-strain "
                                         "stress");
        }

      // an inverted state: F = [[-0.5, 0], [0, 1]]
      dealii::Tensor<2, 2> G;
      G[0][0] = -0.5;
      G[1][1] = 1.;
      const dealii::Vector<double> y = interpolate(dof_handler, Homogeneous(G));
      testing::check_throws([&]() { write_finite_strain_vtu_file("inverted.vtu", dof_handler, laws, y); },
                            "of cell 0 (an inverted or collapsed cell)", name + ": an inverted state is refused");
    }

  // plane stress: sigma_zz = 0, the thickness stretch f, J = f det F
  {
    const NeoHookeMaterial plane_stress(100., 0.3, ElasticMaterial::Model::plane_stress);
    MaterialLibrary<2>     ps_laws;
    ps_laws.add(0, plane_stress);
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(1);
    const dealii::Vector<double> x = interpolate(dof_handler, u);
    write_finite_strain_vtu_file("plane-stress.vtu", dof_handler, ps_laws, x);
    const std::string text = read("plane-stress.vtu");
    const double      f    = plane_stress.out_of_plane_stretch(F);
    const auto        zz = data_array(text, "cauchy_stress_zz"), lam = data_array(text, "principal_stretches"),
               dj = data_array(text, "det_F");
    double e_zz = 0, e_f = 0, e_J = 0;
    for (unsigned int c = 0; c < mesh.n_cells() && zz.size() == mesh.n_cells() && lam.size() == 3 * mesh.n_cells() &&
                             dj.size() == mesh.n_cells();
         ++c)
      {
        e_zz = std::max(e_zz, std::abs(zz[c]));
        e_f  = std::max(e_f, std::abs(lam[3 * c + 2] - f));
        e_J  = std::max(e_J, std::abs(dj[c] - f * J));
      }
    testing::check(zz.size() == mesh.n_cells(), "plane stress: cauchy_stress_zz per cell");
    testing::check_small(e_zz, 1e-12, "plane stress: sigma_zz = 0");
    testing::check_small(e_f, 1e-12, "plane stress: third principal stretch = f = " + std::to_string(f));
    testing::check_small(e_J, 1e-12, "plane stress: det_F = f det F");
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
