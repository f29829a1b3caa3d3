// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The constitutive-law seam (ConstitutiveLaw, MaterialLibrary) with laws
// written here, through the interface only:
// - a general anisotropic linear law (full 3x3 Voigt matrix, not isotropic)
//   passes the displacement patch test for k = 1 (linear field) and k = 2
//   (quadratic field, constant body force -div(C eps(u))) on a Voronoi and a
//   non-convex mesh: every DoF exact to 1e-11 relative; its element
//   consistency matrix equals the quadrature of eps(Pi phi_i) : C :
//   eps(Pi phi_j) over VEMValues, and of sym(Pi0 grad phi_i) : C :
//   sym(Pi0 grad phi_j) (the form a finite-strain operator will use), to
//   1e-12 relative; StressRecovery gives C eps(u) in every cell and at every
//   vertex, and its von Mises stress with the law's sigma_zz, to 1e-10
//   relative; compute_errors() gives the energy norm of u (and of a linear
//   error field) equal to the exact integral of eps : C : eps by a Gauss
//   rule on the unit square, to 1e-12 relative, and a zero energy error;
// - an isotropic law written here as a Voigt matrix, in the material frame
//   and rotated by 0.7 rad (its components then carry round-off, so the
//   operator takes its general path), gives ElasticMaterial's stiffness
//   matrix to 1e-12 relative, plane strain and plane stress, k = 1, 2;
// - a non-linear law is refused by ElasticityOperator, ElasticityAssembler
//   and compute_errors() with messages naming it; ElasticMaterial has no
//   finite-strain response yet and says so; a tangent without the major
//   symmetry and one that is not positive definite are refused; the
//   MaterialLibrary refuses unknown ids, duplicates and null laws;
//   ContactScales takes E_min from the laws' characteristic stiffness.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/constitutive_law.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/elasticity/material_library.h>
#include <dealvem/postprocessing/error_norms.h>
#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/vem/vem_values.h>
#include <dealvem/vem/virtual_element.h>

#include <cmath>

#include "../elasticity_common.h"
#include "../tests.h"

using namespace dealvem;
using P        = dealii::Point<2>;
using Voigt    = std::array<std::array<double, 3>, 3>;
using Strain   = dealii::SymmetricTensor<2, 2>;
using Tangent  = dealii::SymmetricTensor<4, 2>;

// Voigt index -> tensor indices (xx, yy, xy)
constexpr unsigned int voigt_index[3][2] = {{0, 0}, {1, 1}, {0, 1}};

/**
 * A linear law given by its Voigt matrix (engineering shear strain:
 * (s_xx, s_yy, s_xy) = C (e_xx, e_yy, 2 e_xy)), expressed in a frame rotated
 * by @p angle: the tangent is the rotated fourth-order tensor, computed
 * component by component (with round-off in every entry when angle != 0).
 * sigma_zz = z . (e_xx, e_yy, 2 e_xy) in the material frame.
 */
class VoigtLaw : public ConstitutiveLaw<2>
{
public:
  VoigtLaw(const Voigt &C, const std::array<double, 3> &z, const double stiffness, const double angle = 0)
    : Cv(C)
    , z(z)
    , stiffness(stiffness)
    , angle(angle)
  {
    // the tensor in the material frame
    dealii::Tensor<4, 2> C0;
    for (unsigned int I = 0; I < 3; ++I)
      for (unsigned int J = 0; J < 3; ++J)
        {
          const unsigned int i = voigt_index[I][0], j = voigt_index[I][1], k = voigt_index[J][0],
                             l = voigt_index[J][1];
          for (const auto &ij : {std::make_pair(i, j), std::make_pair(j, i)})
            for (const auto &kl : {std::make_pair(k, l), std::make_pair(l, k)})
              C0[ij.first][ij.second][kl.first][kl.second] = C[I][J];
        }
    // rotated: C_ijkl = R_ia R_jb R_kc R_ld C0_abcd
    const double         c = std::cos(angle), s = std::sin(angle);
    dealii::Tensor<2, 2> R;
    R[0][0] = c;
    R[0][1] = -s;
    R[1][0] = s;
    R[1][1] = c;
    dealii::Tensor<4, 2> Cr;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int l = 0; l < 2; ++l)
            for (unsigned int a = 0; a < 2; ++a)
              for (unsigned int b = 0; b < 2; ++b)
                for (unsigned int cc = 0; cc < 2; ++cc)
                  for (unsigned int d = 0; d < 2; ++d)
                    Cr[i][j][k][l] += R[i][a] * R[j][b] * R[k][cc] * R[l][d] * C0[a][b][cc][d];
    for (unsigned int I = 0; I < 3; ++I)
      for (unsigned int J = 0; J < 3; ++J)
        C_tensor[voigt_index[I][0]][voigt_index[I][1]][voigt_index[J][0]][voigt_index[J][1]] =
          Cr[voigt_index[I][0]][voigt_index[I][1]][voigt_index[J][0]][voigt_index[J][1]];
    Rt = dealii::transpose(R);
  }
  std::string
  get_name() const override
  {
    return "test Voigt law";
  }
  std::unique_ptr<ConstitutiveLaw<2>>
  clone() const override
  {
    return std::make_unique<VoigtLaw>(*this);
  }
  bool
  is_linear() const override
  {
    return true;
  }
  double
  characteristic_stiffness() const override
  {
    return stiffness;
  }
  Strain
  stress(const Strain &eps) const override
  {
    return C_tensor * eps;
  }
  Tangent
  tangent(const Strain &) const override
  {
    return C_tensor;
  }
  double
  stress_zz(const Strain &eps) const override
  {
    // the strain in the material frame
    const dealii::Tensor<2, 2> e = Rt * dealii::Tensor<2, 2>(eps) * dealii::transpose(Rt);
    return z[0] * e[0][0] + z[1] * e[1][1] + z[2] * 2 * e[0][1];
  }
  // sigma = C eps by the Voigt matrix (material frame, angle = 0 only):
  // the test's independent evaluation
  Strain
  voigt_stress(const Strain &eps) const
  {
    const double ev[3] = {eps[0][0], eps[1][1], 2 * eps[0][1]};
    Strain       s;
    for (unsigned int I = 0; I < 3; ++I)
      {
        double v = 0;
        for (unsigned int J = 0; J < 3; ++J)
          v += Cv[I][J] * ev[J];
        s[voigt_index[I][0]][voigt_index[I][1]] = v;
      }
    return s;
  }

  Voigt                Cv;
  std::array<double, 3> z;
  double               stiffness, angle;
  Tangent              C_tensor;
  dealii::Tensor<2, 2> Rt;
};

// sigma = C eps (1 + |eps|^2): not linear
class SofteningLaw : public VoigtLaw
{
public:
  using VoigtLaw::VoigtLaw;
  std::string
  get_name() const override
  {
    return "test non-linear law";
  }
  bool
  is_linear() const override
  {
    return false;
  }
  std::unique_ptr<ConstitutiveLaw<2>>
  clone() const override
  {
    return std::make_unique<SofteningLaw>(*this);
  }
  Strain
  stress(const Strain &eps) const override
  {
    return (1 + eps.norm() * eps.norm()) * (C_tensor * eps);
  }
};

// a general anisotropic Voigt matrix (positive definite, shear coupling)
const Voigt anisotropic = {{{{200, 60, 30}}, {{60, 120, -20}}, {{30, -20, 50}}}};

// u = (1e-3 + 2e-3 x - 1e-3 y + q(3x^2 - xy + 2y^2),
//      -2e-3 + 1.5e-3 x + 0.5e-3 y + q(x^2 + 4xy - y^2)) (+ the linear field delta)
class Field : public dealii::Function<2>
{
public:
  Field(const double q, const double delta = 0)
    : dealii::Function<2>(2)
    , q(q)
    , d(delta)
  {}
  double
  value(const P &p, const unsigned int c) const override
  {
    const double x = p[0], y = p[1];
    if (c == 0)
      return 1e-3 + 2e-3 * x - 1e-3 * y + q * (3 * x * x - x * y + 2 * y * y) + d * (x + 2 * y);
    return -2e-3 + 1.5e-3 * x + 0.5e-3 * y + q * (x * x + 4 * x * y - y * y) + d * (-3 * x + y);
  }
  dealii::Tensor<1, 2>
  gradient(const P &p, const unsigned int c) const override
  {
    return grad(p)[c];
  }
  dealii::Tensor<2, 2>
  grad(const P &p) const
  {
    const double         x = p[0], y = p[1];
    dealii::Tensor<2, 2> g;
    g[0][0] = 2e-3 + q * (6 * x - y) + d;
    g[0][1] = -1e-3 + q * (-x + 4 * y) + 2 * d;
    g[1][0] = 1.5e-3 + q * (2 * x + 4 * y) - 3 * d;
    g[1][1] = 0.5e-3 + q * (4 * x - 2 * y) + d;
    return g;
  }
  Strain
  strain(const P &p) const
  {
    return dealii::symmetrize(grad(p));
  }
  // d eps / d x_j (constant)
  Strain
  strain_derivative(const unsigned int j) const
  {
    // Hessians H_0 = q [[6, -1], [-1, 4]], H_1 = q [[2, 4], [4, -2]];
    // (d_j grad u)_{cl} = (H_c)_{lj}
    const double         H[2][2][2] = {{{6, -1}, {-1, 4}}, {{2, 4}, {4, -2}}};
    dealii::Tensor<2, 2> T;
    for (unsigned int c = 0; c < 2; ++c)
      for (unsigned int l = 0; l < 2; ++l)
        T[c][l] = q * H[c][l][j];
    return dealii::symmetrize(T);
  }
  double q, d;
};

// f = -div(C eps(u)), constant for the quadratic field
class BodyForce : public dealii::Function<2>
{
public:
  BodyForce(const Field &u, const VoigtLaw &law)
    : dealii::Function<2>(2)
  {
    for (unsigned int j = 0; j < 2; ++j)
      {
        const Strain s = law.voigt_stress(u.strain_derivative(j));
        for (unsigned int i = 0; i < 2; ++i)
          f[i] -= s[i][j];
      }
  }
  double
  value(const P &, const unsigned int c) const override
  {
    return f[c];
  }
  double f[2] = {0, 0};
};

double
relative_difference(const dealii::FullMatrix<double> &A, const dealii::FullMatrix<double> &B)
{
  double d = 0, m = 0;
  for (unsigned int i = 0; i < A.m(); ++i)
    for (unsigned int j = 0; j < A.n(); ++j)
      {
        d = std::max(d, std::abs(A(i, j) - B(i, j)));
        m = std::max(m, std::abs(B(i, j)));
      }
  return d / m;
}

// the patch test, stresses, energy norms and element matrices of the
// anisotropic law on one mesh
void
check_anisotropic_law(const std::string &family)
{
  const VoigtLaw law(anisotropic, {{0.1, 0.2, 0.05}}, 100.);
  for (const unsigned int k : {1u, 2u})
    {
      PolygonalMesh<2> mesh;
      testing::make_mesh(mesh, family, 1);
      const std::string tag = family + " (" + std::to_string(mesh.n_cells()) + " cells) k=" + std::to_string(k) + ": ";
      VEMDoFHandler<2>  dof_handler(mesh);
      dof_handler.distribute_dofs(k);
      MaterialLibrary<2> laws;
      for (const auto id : mesh.get_material_ids())
        laws.add(id, law);
      const Field     u(k == 2 ? 1e-3 : 0.);
      const BodyForce f(u, law);

      // the patch test: Dirichlet data on the whole boundary
      dealii::AffineConstraints<double> constraints;
      BoundaryConditions::interpolate_boundary_values(dof_handler, {0, 1, 2, 3}, u, {{true, true}}, constraints);
      constraints.close();
      dealii::DynamicSparsityPattern dsp(dof_handler.n_dofs());
      dof_handler.make_sparsity_pattern(dsp, constraints);
      dealii::SparsityPattern sp;
      sp.copy_from(dsp);
      dealii::SparseMatrix<double> A(sp);
      dealii::Vector<double>       b, x(dof_handler.n_dofs());
      ElasticityAssembler<2>       assembler(dof_handler, laws);
      assembler.set_body_force(f);
      assembler.assemble(constraints, A, b);
      dealii::SparseDirectUMFPACK solver;
      solver.initialize(A);
      solver.vmult(x, b);
      constraints.distribute(x);

      double                                       err = 0, umax = 0;
      VirtualElement<2>                            element(k);
      std::vector<dealii::types::global_dof_index> indices;
      dealii::Vector<double>                       exact;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          element.reinit(mesh.cell_vertices(c));
          element.interpolate(u, exact);
          dof_handler.get_dof_indices(c, indices);
          for (unsigned int i = 0; i < indices.size(); ++i)
            {
              err  = std::max(err, std::abs(x[indices[i]] - exact[i]));
              umax = std::max(umax, std::abs(exact[i]));
            }
        }
      testing::check_small(err / umax, 1e-11, tag + "anisotropic law, patch test: max DoF error / max |u|");

      // stresses: C eps(u) at the centroids and at the vertices
      const StressRecovery<2> stresses(dof_handler, laws, x);
      double                  err_cell = 0, err_vertex = 0, err_mises = 0, smax = 0;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          const P      centroid = PolygonGeometry<2>(mesh.cell_vertices(c)).centroid();
          const Strain eps      = u.strain(centroid);
          const Strain sigma    = law.voigt_stress(eps);
          const double szz      = 0.1 * eps[0][0] + 0.2 * eps[1][1] + 0.05 * 2 * eps[0][1];
          smax                  = std::max(smax, sigma.norm());
          err_cell              = std::max(err_cell, (stresses.cell_stress(c) - sigma).norm());
          err_mises = std::max(err_mises, std::abs(stresses.cell_von_mises(c) - von_mises_stress(sigma, szz)));
        }
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        err_vertex =
          std::max(err_vertex, (stresses.vertex_stress(v) - law.voigt_stress(u.strain(mesh.vertex(v)))).norm());
      testing::check_small(err_cell / smax, 1e-10, tag + "StressRecovery: cell stress = C eps(u)(centroid)");
      testing::check_small(err_vertex / smax, 1e-10, tag + "StressRecovery: vertex stress = C eps(u)(vertex)");
      testing::check_small(err_mises / smax, 1e-10, tag + "StressRecovery: von Mises with the law's sigma_zz");

      // energy norms against the exact integral (Gauss 4 x 4 on the unit
      // square, exact for the quadratic integrand)
      const dealii::QGauss<2> gauss(4);
      double                  energy2 = 0, delta_energy2 = 0;
      const Field             delta(0., 1e-4);
      const Strain            eps_delta = delta.strain(P()) - Field(0.).strain(P());
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const Strain eps = u.strain(gauss.point(q));
          energy2 += gauss.weight(q) * (law.voigt_stress(eps) * eps);
        }
      delta_energy2 = law.voigt_stress(eps_delta) * eps_delta;
      const ErrorNorms e = compute_errors(dof_handler, laws, x, u);
      testing::check_near(e.energy_exact, std::sqrt(energy2), 1e-12 * std::sqrt(energy2),
                          tag + "compute_errors: energy norm of u = (int eps : C : eps)^(1/2)");
      testing::check_small(e.energy / e.energy_exact, 1e-10, tag + "compute_errors: energy error of u_h");
      const Field      u_plus_delta(k == 2 ? 1e-3 : 0., 1e-4);
      const ErrorNorms ed = compute_errors(dof_handler, laws, x, u_plus_delta);
      testing::check_near(ed.energy, std::sqrt(delta_energy2), 1e-10 * std::sqrt(delta_energy2),
                          tag + "compute_errors: energy norm of a linear error field");

      // the element consistency matrices against quadrature over VEMValues,
      // with the strain of the projection and with the symmetric part of
      // the full-gradient projection
      VEMValues<2> vem_values(dof_handler, dealii::update_gradients | dealii::update_JxW_values);
      ElasticityOperator<2>       elasticity;
      dealii::FullMatrix<double>  K1, K2;
      double                      err_k1 = 0, err_k2 = 0, err_rigid = 0;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          vem_values.reinit(c);
          const unsigned int n = vem_values.dofs_per_cell();
          K1.reinit(n, n);
          K2.reinit(n, n);
          for (unsigned int q = 0; q < vem_values.n_quadrature_points(); ++q)
            for (unsigned int i = 0; i < n; ++i)
              {
                const Strain s1 = law.voigt_stress(vem_values.shape_symmetric_gradient(i, q));
                const Strain s2 = law.voigt_stress(dealii::symmetrize(vem_values.shape_gradient_projection(i, q)));
                for (unsigned int j = 0; j < n; ++j)
                  {
                    K1(i, j) += s1 * vem_values.shape_symmetric_gradient(j, q) * vem_values.JxW(q);
                    K2(i, j) +=
                      s2 * dealii::symmetrize(vem_values.shape_gradient_projection(j, q)) * vem_values.JxW(q);
                  }
              }
          elasticity.reinit(vem_values.get_element(), law);
          err_k1 = std::max(err_k1, relative_difference(K1, elasticity.get_consistency_matrix()));
          err_k2 = std::max(err_k2, relative_difference(K2, elasticity.get_consistency_matrix()));
          // the rigid-body modes are in the kernel of K
          const auto &K = elasticity.get_stiffness_matrix();
          const auto &D = vem_values.get_element().get_D();
          double      kmax = 0, r = 0;
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              kmax = std::max(kmax, std::abs(K(i, j)));
          for (unsigned int alpha = 0; alpha < 3; ++alpha)
            for (unsigned int i = 0; i < n; ++i)
              {
                double v = 0;
                for (unsigned int j = 0; j < n; ++j)
                  v += K(i, j) * D(j, alpha);
                r = std::max(r, std::abs(v));
              }
          err_rigid = std::max(err_rigid, r / kmax);
        }
      testing::check_small(err_k1, 1e-12, tag + "K_c = quadrature of eps(Pi phi_i) : C : eps(Pi phi_j)");
      testing::check_small(err_k2, 1e-12, tag + "K_c = quadrature of sym(Pi0 grad phi_i) : C : sym(Pi0 grad phi_j)");
      testing::check_small(err_rigid, 1e-12, tag + "K D_rigid = 0 (rigid-body modes in the kernel)");
    }
}

// the isotropic law through the interface gives ElasticMaterial's stiffness
void
check_isotropic_law(const std::string &name, const std::vector<P> &vertices)
{
  for (const auto model : {ElasticMaterial::Model::plane_strain, ElasticMaterial::Model::plane_stress})
    {
      const ElasticMaterial material(210e3, 0.3, model);
      // lambda and mu computed here, not read from ElasticMaterial
      const double E = 210e3, nu = 0.3, mu = E / (2 * (1 + nu));
      const double lambda = model == ElasticMaterial::Model::plane_strain ? E * nu / ((1 + nu) * (1 - 2 * nu)) :
                                                                            E * nu / (1 - nu * nu);
      const Voigt  C      = {{{{lambda + 2 * mu, lambda, 0}}, {{lambda, lambda + 2 * mu, 0}}, {{0, 0, mu}}}};
      for (const double angle : {0., 0.7})
        {
          const VoigtLaw law(C, {{0, 0, 0}}, E, angle);
          for (const unsigned int k : {1u, 2u})
            {
              VirtualElement<2> element(k);
              element.reinit(vertices);
              ElasticityOperator<2> reference, seam;
              reference.reinit(element, material);
              seam.reinit(element, law);
              testing::check_small(relative_difference(seam.get_stiffness_matrix(), reference.get_stiffness_matrix()),
                                   1e-12,
                                   name + " k=" + std::to_string(k) + " " + ElasticMaterial::model_name(model) +
                                     ", isotropic law rotated by " + std::to_string(angle) +
                                     ": K = ElasticMaterial's K");
            }
        }
    }
}

int
main()
{
  check_anisotropic_law("voronoi");
  check_anisotropic_law("nonconvex");

  {
    std::vector<P> hexagon;
    for (unsigned int i = 0; i < 6; ++i)
      hexagon.emplace_back(3 + std::cos(M_PI * i / 3 + 0.3), -2 + std::sin(M_PI * i / 3 + 0.3));
    check_isotropic_law("hexagon", hexagon);
    check_isotropic_law("non-convex pentagon", {P(0, 0), P(2, 0), P(2, 2), P(1, 0.8), P(0, 2)});
    check_isotropic_law("square with a hanging vertex", {P(0, 0), P(0.5, 0), P(1, 0), P(1, 1), P(0, 1)});
  }

  // the ElasticMaterial as a ConstitutiveLaw
  {
    const ElasticMaterial m(7000, 0.3, ElasticMaterial::Model::plane_strain);
    const ConstitutiveLaw<2> &law = m;
    Strain                    eps;
    eps[0][0] = 1e-3;
    eps[1][1] = -2e-4;
    eps[0][1] = 3e-4;
    testing::check_small((law.tangent(eps) * eps - m.stress(eps)).norm() / m.stress(eps).norm(), 1e-14,
                         "ElasticMaterial: tangent : eps = stress(eps)");
    testing::check(law.is_linear() && law.characteristic_stiffness() == 7000 && !law.has_finite_strain_response(),
                   "ElasticMaterial: linear, characteristic stiffness E, no finite-strain response");
    testing::check(law.get_name() == "linear isotropic (E = 7000, nu = 0.3, plane strain)",
                   "ElasticMaterial: name '" + law.get_name() + "'");
    testing::check_throws([&] { law.first_piola_kirchhoff_stress(dealii::unit_symmetric_tensor<2>()); },
                          "has no finite-strain response: the first Piola-Kirchhoff stress P(F) is not implemented",
                          "ElasticMaterial: P(F) throws 'not implemented for this law'");
    testing::check_throws([&] { law.first_piola_kirchhoff_tangent(dealii::unit_symmetric_tensor<2>()); },
                          "the tangent dP/dF is not implemented for this law",
                          "ElasticMaterial: dP/dF throws 'not implemented for this law'");
  }

  // bad laws and bad libraries
  {
    PolygonalMesh<2> mesh;
    testing::make_mesh(mesh, "structured quads", 0);
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(2);
    VirtualElement<2> element(2);
    element.reinit(mesh.cell_vertices(0));
    ElasticityOperator<2> elasticity;

    const SofteningLaw soft(anisotropic, {{0, 0, 0}}, 100.);
    testing::check_throws([&] { elasticity.reinit(element, soft); },
                          "ElasticityOperator: the constitutive law 'test non-linear law' is not linear",
                          "a non-linear law is refused by ElasticityOperator");
    MaterialLibrary<2> soft_laws;
    soft_laws.add(0, soft);
    testing::check_throws([&] { ElasticityAssembler<2> a(dof_handler, soft_laws); },
                          "the constitutive law 'test non-linear law' of material id 0 is not linear",
                          "a non-linear law is refused by ElasticityAssembler");
    const dealii::Vector<double> zero(dof_handler.n_dofs());
    testing::check_throws([&] { compute_errors(dof_handler, soft_laws, zero, Field(0.)); },
                          "compute_errors(): the constitutive law 'test non-linear law' of material id 0 is not linear",
                          "a non-linear law is refused by compute_errors()");

    Voigt asymmetric = anisotropic;
    asymmetric[0][2] = 35;
    testing::check_throws([&] { elasticity.reinit(element, VoigtLaw(asymmetric, {{0, 0, 0}}, 1.)); },
                          "lacks the major symmetry C_ijkl = C_klij",
                          "a tangent without the major symmetry is refused");
    Voigt indefinite = anisotropic;
    indefinite[2][2] = 1;
    testing::check_throws([&] { elasticity.reinit(element, VoigtLaw(indefinite, {{0, 0, 0}}, 1.)); },
                          "is not positive definite", "a tangent that is not positive definite is refused");
    // after a refused law, a good one still works
    elasticity.reinit(element, VoigtLaw(anisotropic, {{0, 0, 0}}, 1.));
    testing::check(elasticity.get_stiffness_matrix().m() == element.n_dofs_per_cell(),
                   "the operator works again after a refused law");

    MaterialLibrary<2> laws;
    laws.add(0, VoigtLaw(anisotropic, {{0, 0, 0}}, 1000.));
    testing::check_throws([&] { laws.get_law(7); }, "No constitutive law is defined for material id 7",
                          "MaterialLibrary: an unknown material id is refused, naming it");
    testing::check_throws([&] { laws.add(0, ElasticMaterial()); }, "material id 0 has a law already",
                          "MaterialLibrary: a second law for one id is refused");
    testing::check_throws([&] { laws.add(1, std::shared_ptr<const ConstitutiveLaw<2>>()); }, "is null",
                          "MaterialLibrary: a null law is refused");
    const ElasticityAssembler<2> assembler(dof_handler, laws);
    testing::check_throws([&] { assembler.get_material(0); }, "is not an ElasticMaterial; use get_law()",
                          "ElasticityAssembler::get_material() refuses a law that is no ElasticMaterial");
    testing::check(assembler.get_law(0).get_name() == "test Voigt law", "ElasticityAssembler::get_law()");

    // ContactScales: E_min from the characteristic stiffness
    laws.add(1, ElasticMaterial(4000, 0.3));
    NodeInsertion::Interface itf;
    itf.segments.push_back(ContactSegment{0, 1, dealii::numbers::invalid_unsigned_int, 0.1});
    const ContactScales scales(laws, {itf});
    testing::check(scales.E_min == 1000 && scales.h_min == 0.1,
                   "ContactScales: E_min = the smallest characteristic stiffness of the laws");
  }
  return testing::finish();
}
