// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// ContactRows, the layout of the multiplier rows. A body [1/4, 3/4] x
// [0, 1/2] (3 x 2 quads) tied at k = 1 onto a block [0, 1] x [-1/2, 0]
// (4 x 2 quads, non-matching), E = 1000, nu = 0.3; block bottom held
// vertically, its corner horizontally; on the body's top a pressure p = 5
// and a shear traction s = 2.
// Checked, with tangential multipliers (Tangential = multipliers) and
// without (penalty):
// - the sizes: n_dofs() is the DoF handler's, n_pairs() the assembler's,
//   n_rows() the system size minus n_dofs(), n_unknowns() the system size;
// - the rows: normal_row(i) = n + i, tangential_row(i) = n + n_pairs + i,
//   row(j) = n + j, pair_of() and kind_of() invert them, every multiplier
//   row is the row of exactly one (pair, kind);
// - the pair data (gap0, weight, normal, tangent) are the pair's;
// - the assembled system agrees: row normal_row(i) holds (u_B - u_A).n_i
//   and row tangential_row(i) (u_B - u_A).t_i over the pair's DoFs;
// - the multipliers the solve wrote, read by normal_multiplier() and
//   tangential_multiplier(), are the contact forces: on the body,
//   sum_i lambda_n,i n_i + lambda_t,i t_i equals the applied load
//   (s w, -p w), w = 1/2 (with the penalty, the spring forces of
//   tangential_forces() stand for lambda_t);
// - FiniteStrainContact::rows() has the layout of its constraints (tied:
//   two per pair; unilateral frictionless: one).
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/contact_rows.h>
#include <dealvem/contact/finite_strain_contact.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/solvers/saddle_point_solver.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <cmath>
#include <map>

#include "../tests.h"

using namespace dealvem;

namespace
{
  const double p_load = 5, s_load = 2, width = 0.5;

  struct Problem
  {
    std::map<dealii::types::material_id, ElasticMaterial> materials{{0, ElasticMaterial(1000, 0.3)},
                                                                    {1, ElasticMaterial(1000, 0.3)}};
    PolygonalMesh<2>                                      mesh;
    VEMDoFHandler<2>                                      dof_handler;
    std::vector<NodeInsertion::Interface>                 interfaces;
    std::unique_ptr<ContactScales>                        scales;

    Problem()
    {
      PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, -0.5), dealii::Point<2>(1, 0), 4, 2);
      PolygonalMesh<2> body;
      PolygonalMeshGenerators::structured_quads(body, dealii::Point<2>(0.25, 0), dealii::Point<2>(0.75, 0.5), 3, 2);
      for (unsigned int c = 0; c < body.n_cells(); ++c)
        body.set_material_id(c, 1);
      for (unsigned int e = 0; e < body.n_edges(); ++e)
        if (body.edge(e).at_boundary())
          body.set_edge_boundary_id(e, body.edge(e).boundary_id + 10);
      mesh.append(body);
      interfaces = {NodeInsertion::insert(mesh, 3, 12, 1, NodeInsertion::Settings())};
      dof_handler.reinit(mesh);
      dof_handler.distribute_dofs(1);
      scales = std::make_unique<ContactScales>(std::vector<double>{1000, 1000}, interfaces);
    }
  };

  void
  check_assembler(const Problem &pb, const ContactSettings::Tangential tangential)
  {
    const bool        multipliers = (tangential == ContactSettings::Tangential::multipliers);
    const std::string name        = multipliers ? "multipliers" : "penalty";
    ContactSettings   settings;
    settings.normal     = ContactSettings::Normal::tied;
    settings.tangential = tangential;
    const ContactAssembler<2> contact(pb.dof_handler, pb.interfaces[0].pairs, settings, pb.scales->penalty(settings));
    const auto               &pairs = contact.get_pairs();

    dealii::AffineConstraints<double>  constraints;
    dealii::Functions::ZeroFunction<2> zero(2);
    BoundaryConditions::interpolate_boundary_values(pb.dof_handler, {2}, zero, {{false, true}}, constraints);
    BoundaryConditions::add_point_constraint(pb.dof_handler, dealii::Point<2>(0, -0.5), 0, 0., constraints);
    constraints.close();

    const unsigned int             n = pb.dof_handler.n_dofs();
    dealii::DynamicSparsityPattern dsp(n + contact.n_multipliers());
    pb.dof_handler.make_sparsity_pattern(dsp);
    contact.add_sparsity(dsp);
    constraints.condense(dsp);
    dealii::SparsityPattern sparsity;
    sparsity.copy_from(dsp);
    dealii::SparseMatrix<double> matrix(sparsity);
    dealii::Vector<double>       rhs(n + contact.n_multipliers());

    // the sizes
    const ContactRows  rows = contact.rows();
    const unsigned int m    = rows.n_pairs();
    std::cout << name << ": " << n << " DoFs, " << m << " pairs, " << rows.n_rows() << " rows" << std::endl;
    testing::check(rows.n_dofs() == n && m == contact.n_pairs() && m > 4 && rows.has_tangential_rows() == multipliers &&
                     rows.n_rows() == matrix.m() - n && rows.n_rows() == (multipliers ? 2 : 1) * m &&
                     rows.n_unknowns() == matrix.m() && &rows.pairs() == &pairs,
                   name + ": n_dofs, n_pairs, n_rows = system size - n_dofs, n_unknowns = system size");

    // the rows and their inverse
    bool                      layout = true;
    std::vector<unsigned int> hits(rows.n_rows(), 0);
    for (unsigned int i = 0; i < m; ++i)
      {
        const unsigned int r = rows.normal_row(i);
        layout               = layout && r == n + i && rows.is_multiplier_row(r) && rows.pair_of(r) == i &&
                 rows.kind_of(r) == ContactRows::Kind::normal;
        ++hits[r - n];
        if (multipliers)
          {
            const unsigned int t = rows.tangential_row(i);
            layout               = layout && t == n + m + i && rows.is_multiplier_row(t) && rows.pair_of(t) == i &&
                     rows.kind_of(t) == ContactRows::Kind::tangential;
            ++hits[t - n];
          }
      }
    for (unsigned int j = 0; j < rows.n_rows(); ++j)
      layout = layout && hits[j] == 1 && rows.row(j) == n + j;
    layout = layout && !rows.is_multiplier_row(n - 1) && !rows.is_multiplier_row(rows.n_unknowns());
    testing::check(layout, name + ": normal_row(i) = n + i, tangential_row(i) = n + n_pairs + i, row(j) = n + j; "
                                  "pair_of and kind_of invert them, one (pair, kind) per row");

    bool data = true;
    for (unsigned int i = 0; i < m; ++i)
      data = data && rows.gap0(i) == pairs[i].initial_gap && rows.weight(i) == pairs[i].weight &&
             rows.normal(i) == pairs[i].normal && rows.tangent(i) == pairs[i].tangent;
    testing::check(data, name + ": gap0, weight, normal, tangent are the pair's");

    // the system (the elasticity assembler zeroes it first), and in it the
    // contact blocks: the rows hold (u_B - u_A).n and .t
    ElasticityAssembler<2>                 assembler(pb.dof_handler, pb.materials);
    dealii::Functions::ConstantFunction<2> pressure(p_load);
    dealii::Functions::ConstantFunction<2> traction(std::vector<double>{s_load, 0.});
    assembler.add_pressure(13, pressure);
    assembler.add_traction(13, traction);
    assembler.assemble(constraints, matrix, rhs);
    contact.assemble(constraints, std::vector<bool>(m, true), matrix, rhs);
    unsigned int n_checked = 0;
    bool         rows_hold = true;
    for (unsigned int i = 0; i < m; ++i)
      {
        const auto d     = contact.pair_dofs(i);
        bool       fixed = false;
        for (const auto dof : d)
          fixed = fixed || constraints.is_constrained(dof);
        if (fixed)
          continue;
        ++n_checked;
        for (unsigned int k = 0; k < 4; ++k)
          {
            const double sign = (k < 2 ? -1. : 1.);
            rows_hold         = rows_hold && matrix.el(rows.normal_row(i), d[k]) == sign * rows.normal(i)[k % 2];
            if (multipliers)
              rows_hold = rows_hold && matrix.el(rows.tangential_row(i), d[k]) == sign * rows.tangent(i)[k % 2];
          }
      }
    testing::check(rows_hold && n_checked > 2,
                   name + ": the assembled rows normal_row(i), tangential_row(i) hold (u_B - u_A).n_i, .t_i (" +
                     std::to_string(n_checked) + " pairs)");

    // the solve: the multipliers are the forces that hold the body
    SaddlePointSolver      solver(SaddlePointSolver::Settings{});
    dealii::Vector<double> x;
    solver.solve(matrix, n, x, rhs);
    constraints.distribute(x);
    testing::check(x.size() == rows.n_unknowns(), name + ": the solution has n_unknowns() entries");
    const auto           ft = contact.tangential_forces(x);
    dealii::Tensor<1, 2> force;
    double               normal_sum = 0;
    for (unsigned int i = 0; i < m; ++i)
      {
        const double lt = multipliers ? rows.tangential_multiplier(x, i) : -ft[i];
        force += rows.normal_multiplier(x, i) * rows.normal(i) + lt * rows.tangent(i);
        normal_sum += rows.normal_multiplier(x, i);
      }
    std::cout << name << ": sum of lambda_n n + lambda_t t = (" << force[0] << ", " << force[1]
              << "), sum of lambda_n = " << normal_sum << std::endl;
    dealii::Tensor<1, 2> load;
    load[0] = s_load * width;
    load[1] = -p_load * width;
    testing::check_small((force - load).norm() / (p_load * width), 1e-10,
                         name + ": |sum lambda_n n + lambda_t t - (s w, -p w)| / (p w)");
    testing::check_small(std::abs(normal_sum + p_load * width) / (p_load * width), 1e-10,
                         name + ": |sum lambda_n + p w| / (p w) (flat interface)");
  }

  void
  check_finite_strain(const Problem &pb)
  {
    const double       c = pb.scales->complementarity_constant();
    const unsigned int n = pb.dof_handler.n_dofs();
    for (const auto normal : {ContactSettings::Normal::tied, ContactSettings::Normal::unilateral})
      {
        const std::string         name = "finite strain, " + ContactSettings::normal_name(normal);
        const FiniteStrainContact contact(pb.dof_handler, pb.interfaces, normal, c);
        const ContactRows         rows = contact.rows();
        bool                      ok   = rows.n_dofs() == n && rows.n_pairs() == contact.n_pairs() &&
                  rows.n_rows() == contact.n_constraints() &&
                  rows.has_tangential_rows() == (normal == ContactSettings::Normal::tied);
        for (unsigned int j = 0; j < contact.n_constraints(); ++j)
          {
            const unsigned int r = rows.row(j);
            ok                   = ok && r == n + j && rows.pair_of(r) == contact.pair_of(j) &&
                 (rows.kind_of(r) == ContactRows::Kind::tangential) == contact.is_tangential(j) &&
                 (contact.is_tangential(j) ? rows.tangential_row(contact.pair_of(j))
                                           : rows.normal_row(contact.pair_of(j))) == r;
          }
        std::cout << name << ": " << rows.n_rows() << " rows for " << rows.n_pairs() << " pairs" << std::endl;
        testing::check(ok, name + ": rows() has the layout of the constraints (row(j) = n + j, pair_of, kind_of)");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Problem                            pb;
  check_assembler(pb, ContactSettings::Tangential::multipliers);
  check_assembler(pb, ContactSettings::Tangential::penalty);
  check_finite_strain(pb);
  return testing::finish();
}
