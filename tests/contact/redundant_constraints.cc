// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Contact constraints that the displacement constraints fix already.
//
// Two stacked blocks [0,1]x[0,1] (3x3 quads, master side id 3) and
// [0,1]x[1,2] (4x4 quads, slave side id 12, left side id 10), both held by
// rollers u_x = 0 on their left sides x = 0 (ids 0 and 10), tangential
// multipliers. The interface pair at (0, 1) joins two nodes with u_x = 0:
// its tangential constraint (u_B - u_A).t = 0 (t = (-1, 0)) only involves
// constrained DoFs and is a zero row after condensation. ContactAssembler
// drops it (lambda_t = 0) because the rollers give the slip 0 that stick
// requires, and lists it in get_dropped_constraints().
//
// a) ContactAssembler directly, k = 1, 2, tied and unilateral: exactly one
//    dropped constraint, the tangential one of pair 0 at (0, 1), imposed
//    value 0; its multiplier row is the identity row.
// b) The contact patch test with these rollers (pressure p = 10 on top,
//    bottom held vertically, no other support) through ContactProblem:
//    it runs (the zero row used to make the saddle-point matrix singular)
//    and the stress is uniform, sigma_yy = -p, sigma_xx = sigma_xy = 0 to
//    1e-10 p (the exact solution has u_x = 0 on x = 0), contact force =
//    load to 1e-10.
// c) Conflicts: u_x = 0.001 on the upper left side against u_x = 0 on the
//    lower one forces a tangential slip (u_B - u_A).t = -0.001 at (0, 1),
//    stick requires 0: an error naming the pair and both values (directly
//    and through ContactProblem, tied). Prescribed u_y = 0.002 on the upper
//    and 0 on the lower left side force a gap of 0.002 at (0, 1): an error
//    for tied contact; for unilateral contact an open gap is admissible,
//    the normal constraint is dropped instead.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/contact/contact_assembler.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <sstream>

#include "../contact_common.h"
#include "../tests.h"

using namespace dealvem;
using Mesh = PolygonalMesh<2>;
using P    = dealii::Point<2>;

namespace
{
  Mesh
  block(const double y0, const unsigned int n, const unsigned int material, const unsigned int offset)
  {
    Mesh mesh;
    PolygonalMeshGenerators::structured_quads(mesh, P(0, y0), P(1, y0 + 1), n, n);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      mesh.set_material_id(c, material);
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      if (mesh.edge(e).at_boundary())
        mesh.set_edge_boundary_id(e, mesh.edge(e).boundary_id + offset);
    return mesh;
  }

  /// Prescribed displacement of component @p comp on the left sides:
  /// @p lower on id 0, @p upper on id 10.
  struct Left
  {
    unsigned int comp;
    double       lower, upper;
  };

  /// Assemble the contact blocks (all pairs active) with the constraints
  /// @p left; return the assembler's dropped list and whether the
  /// multiplier rows of the dropped constraints are identity rows.
  std::vector<ContactAssembler<2>::DroppedConstraint>
  assemble(const unsigned int k, const ContactSettings::Normal normal, const Left &left, bool &identity_rows)
  {
    Mesh mesh = block(0, 3, 0, 0);
    mesh.append(block(1, 4, 1, 10));
    const auto       itf = NodeInsertion::insert(mesh, 3, 12, k, NodeInsertion::Settings());
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(k);
    ContactSettings settings;
    settings.normal     = normal;
    settings.tangential = ContactSettings::Tangential::multipliers;
    ContactAssembler<2> contact(dof_handler, itf.pairs, settings, 1.);

    dealii::AffineConstraints<double> constraints;
    for (const auto &side : {std::make_pair(0u, left.lower), std::make_pair(10u, left.upper)})
      for (const auto node : dof_handler.boundary_nodes({dealii::types::boundary_id(side.first)}))
        {
          const auto dof = VEMDoFHandler<2>::node_dof(node, left.comp);
          constraints.add_line(dof);
          constraints.set_inhomogeneity(dof, side.second);
        }
    constraints.close();

    const unsigned int             n = dof_handler.n_dofs(), m = contact.n_multipliers();
    dealii::DynamicSparsityPattern dsp(n + m);
    dof_handler.make_sparsity_pattern(dsp);
    contact.add_sparsity(dsp);
    constraints.condense(dsp);
    dealii::SparsityPattern sparsity;
    sparsity.copy_from(dsp);
    dealii::SparseMatrix<double> matrix(sparsity);
    dealii::Vector<double>       rhs(n + m);
    contact.assemble(constraints, std::vector<bool>(contact.n_pairs(), true), matrix, rhs);

    identity_rows = true;
    for (const auto &d : contact.get_dropped_constraints())
      {
        const unsigned int row = n + (d.tangential ? contact.n_pairs() : 0) + d.pair;
        for (auto it = matrix.begin(row); it != matrix.end(row); ++it)
          identity_rows = identity_rows && (it->value() == (it->column() == row ? 1. : 0.));
        identity_rows = identity_rows && rhs[row] == 0;
      }
    return contact.get_dropped_constraints();
  }

  std::string
  prm(const unsigned int k, const std::string &normal, const std::string &supports)
  {
    std::ostringstream s;
    s << "set Number of bodies = 2\n"
      << testing::block_mesh("structured quads", 0, 0, 1, 1, 3, 3, 0)
      << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\n"
      << "subsection Body 1\n"
      << testing::block_mesh("structured quads", 0, 1, 1, 2, 4, 4, 10)
      << "subsection Material\n  set Young's modulus = 7000\n  set Poisson's ratio = 0.3\nend\nend\n"
      << "subsection Discretization\n  set Order = " << k << "\nend\n"
      << "subsection Contact\n  set Pairs = 3 : 12\n  set Normal = " << normal
      << "\n  set Tangential = multipliers\nend\n"
      << "subsection Boundary conditions and loads\n" << supports << "  set Pressure = 13 : 10\nend\n"
      << "subsection Output\n  set Write VTU = false\n  set Write JSON = false\n"
      << "  set Write pictures = false\n  set Write CSV = false\nend\n";
    return s.str();
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double p = 10;
  using Normal   = ContactSettings::Normal;

  for (const unsigned int k : {1u, 2u})
    for (const Normal normal : {Normal::tied, Normal::unilateral})
      {
        const std::string tag =
          "k = " + std::to_string(k) + (normal == Normal::tied ? ", tied" : ", unilateral");
        // a) rollers on both left sides
        bool       identity = false;
        const auto dropped  = assemble(k, normal, {0, 0., 0.}, identity);
        for (const auto &d : dropped)
          std::cout << "      dropped: pair " << d.pair << " at (" << d.location[0] << ", " << d.location[1]
                    << "), " << (d.tangential ? "tangential" : "normal") << ", imposed " << d.imposed_value
                    << std::endl;
        testing::check(dropped.size() == 1 && dropped[0].pair == 0 && dropped[0].tangential &&
                         dropped[0].location.distance(P(0, 1)) < 1e-15 && dropped[0].imposed_value == 0,
                       "a) " + tag + ": one dropped constraint, the tangential one of pair 0 at (0, 1)");
        testing::check(identity, "a) " + tag + ": its multiplier row is lambda = 0");

        // b) the patch test with the rollers
        const auto r = testing::run_contact(
          prm(k, normal == Normal::tied ? "tied" : "unilateral",
              "  set Dirichlet = 2 : y : 0\n  set Roller = 0, 10\n"));
        double stress_err = 0;
        for (const auto &s : r.cell_stress)
          stress_err = std::max({stress_err, std::abs(s[0]), std::abs(s[1] + p), std::abs(s[2])});
        unsigned int n_active = 0;
        for (const auto &pr : r.pairs)
          n_active += pr.active;
        const double load = r.applied_load_per_body[1].norm();
        testing::check(n_active == r.pairs.size(), "b) " + tag + ": all " + std::to_string(r.pairs.size()) +
                                                     " pairs active");
        testing::check_small(stress_err / p, 1e-10, "b) " + tag + ": rollers on both left sides: max stress error / p");
        testing::check_small((r.total_contact_force + r.applied_load_per_body[1]).norm() / load, 1e-10,
                             "b) " + tag + ": |contact force + load| / |load|");

        // c) conflicts
        testing::check_throws([&] { bool id; assemble(k, normal, {0, 0., 0.001}, id); },
                              "the Dirichlet/roller data force a tangential slip of -0.001 at pair (0, 1) "
                              "but contact requires 0 (stick)",
                              "c) " + tag + ": u_x = 0 and 0.001 on the left sides: named conflict");
        if (normal == Normal::tied)
          testing::check_throws([&] { bool id; assemble(k, normal, {1, 0., 0.002}, id); },
                                "the Dirichlet/roller data force a gap of 0.002 at pair (0, 1) but contact "
                                "requires 0 (tied)",
                                "c) " + tag + ": u_y = 0 and 0.002 on the left sides: named conflict");
        else
          {
            const auto d = assemble(k, normal, {1, 0., 0.002}, identity);
            testing::check(d.size() == 1 && d[0].pair == 0 && !d[0].tangential &&
                             std::abs(d[0].imposed_value - 0.002) < 1e-15 && identity,
                           "c) " + tag + ": u_y = 0 and 0.002 on the left sides: an open gap, the normal "
                                         "constraint of pair 0 dropped");
          }
      }
  testing::check_throws(
    [&] {
      testing::run_contact(prm(1, "tied", "  set Dirichlet = 2 : y : 0; 0 : x : 0; 10 : x : 0.001\n"));
    },
    "force a tangential slip of -0.001 at pair (0, 1) but contact requires 0",
    "c) ContactProblem, tied, k = 1: u_x = 0 and 0.001 on the left sides: named conflict");
  return testing::finish();
}
