// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// ContactProblem set up in code (add_body, add_contact_pair,
// boundary_conditions(), options()) rather than from a parameter file.
// Two blocks, [0,1]^2 in 3 x 3 quads and [0,1] x [1,2] in 4 x 4 quads (ids
// + 10), frictionless unilateral contact, k = 2, pressure p = 10 on top, the
// lower block on a roller at its bottom, each block held sideways at one
// corner. The exact solution is the uniform stress sigma_yy = -p.
// a) the code set-up gives the contact patch test: every pair active, the
//    recovered and lumped pressures equal p to 1e-10, total force p;
// b) the same problem from a parameter file gives the same displacements
//    and multipliers to the last bit (the parameter file is one client of
//    the interface);
// c) the upper block as a deal.II Triangulation (add_body(tria)): the same
//    pressures; an unknown boundary id in a condition is refused; a law of
//    the user's own (a ConstitutiveLaw that is not an ElasticMaterial, with
//    the same values) gives the displacements of a) to round-off (1e-13);
// d) a pressure given as a dealii::Function of time over 3 load steps:
//    the total contact force at step k is p k / 3 (to 1e-10), and a body
//    force of code returning NaN stops with a message naming it;
// e) misuse stops with a message naming the setting: no body, two bodies
//    and no pair, one boundary id in two pairs, the same id twice, a
//    function with the wrong number of components, a model mixed across
//    bodies, a friction coefficient without Coulomb friction, order 3, a
//    boundary id offset past 254, and the refinement cycles of a mesh given
//    in code.
#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/app/elasticity_problem.h>
#include <dealvem/mesh/generators.h>

#include "../tests.h"

#include <limits>

using namespace dealvem;
using testing::check;
using testing::check_near;
using testing::check_small;
using testing::check_throws;

namespace
{
  constexpr double p = 10.;

  PolygonalMesh<2>
  block(const double y0, const unsigned int n)
  {
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::structured_quads(mesh, dealii::Point<2>(0, y0), dealii::Point<2>(1, y0 + 1), n, n);
    return mesh;
  }

  ElasticMaterial
  material()
  {
    return ElasticMaterial(7000, 0.3, ElasticMaterial::Model::plane_strain);
  }

  std::shared_ptr<dealii::Function<2>>
  zero(const unsigned int n_components)
  {
    return std::make_shared<dealii::Functions::ZeroFunction<2>>(n_components);
  }

  std::shared_ptr<dealii::Function<2>>
  constant(const double value)
  {
    return std::make_shared<dealii::Functions::ConstantFunction<2>>(value);
  }

  // Everything but the bodies and the load on top.
  void
  common_setup(ContactProblem &problem, const std::string &name)
  {
    problem.add_contact_pair(3, 12);
    auto &bc = problem.boundary_conditions();
    bc.add_dirichlet(2, {{false, true}}, zero(2));
    bc.add_point_constraint(dealii::Point<2>(0, 0), 0, zero(1), 0);
    bc.add_point_constraint(dealii::Point<2>(0, 2), 0, zero(1), 1);
    auto &o              = problem.options();
    o.degree             = 2;
    o.contact.normal     = ContactSettings::Normal::unilateral;
    o.contact.tangential = ContactSettings::Tangential::frictionless;
    o.base_name          = name;
    o.write_vtu = o.write_pictures = o.write_json = o.write_csv = false;
  }

  // The contact patch test of a result: every pair active, pressures p.
  void
  check_patch(const ContactProblem::Results &r, const std::string &what)
  {
    unsigned int n_active = 0;
    double       err_recovered = 0, err_lumped = 0;
    for (const auto &pr : r.pairs)
      {
        n_active += pr.active;
        err_recovered = std::max(err_recovered, std::abs(pr.pressure - p));
        err_lumped    = std::max(err_lumped, std::abs(pr.lumped_pressure - p));
      }
    check(!r.pairs.empty() && n_active == r.pairs.size(),
          what + ": every one of the " + std::to_string(r.pairs.size()) + " pairs is active");
    check_small(err_recovered / p, 1e-10, what + ": recovered pressure - p, relative");
    check_small(err_lumped / p, 1e-10, what + ": raw pressure -lambda/w - p, relative");
    check_small((std::abs(r.total_contact_force[1]) - p) / p, 1e-10, what + ": |total contact force| - p, relative");
    check_small(r.total_contact_force[0] / p, 1e-10, what + ": tangential total force / p");
  }

  const char *parameter_file = R"(
set Number of bodies = 2
subsection Mesh
  set Type                = structured quads
  set Lower left corner   = 0, 0
  set Upper right corner  = 1, 1
  set Subdivisions        = 3, 3
end
subsection Material
  set Young's modulus     = 7000
  set Poisson's ratio     = 0.3
  set Model               = plane strain
end
subsection Body 1
  subsection Mesh
    set Type               = structured quads
    set Lower left corner  = 0, 1
    set Upper right corner = 1, 2
    set Subdivisions       = 4, 4
    set Boundary id offset = 10
  end
  subsection Material
    set Young's modulus    = 7000
    set Poisson's ratio    = 0.3
  end
end
subsection Discretization
  set Order = 2
end
subsection Contact
  set Pairs      = 3 : 12
  set Normal     = unilateral
  set Tangential = frictionless
end
subsection Boundary conditions and loads
  set Dirichlet         = 2 : y : 0
  set Point constraints = 0, 0 : x : 0 : 0; 0, 2 : x : 0 : 1
  set Pressure          = 13 : 10
end
subsection Output
  set Base name      = from_file
  set Write VTU      = false
  set Write JSON     = false
  set Write pictures = false
  set Write CSV      = false
end
)";

  // A pressure p t / T over load steps (its time is set by ContactProblem).
  class RisingPressure : public dealii::Function<2>
  {
  public:
    RisingPressure()
      : dealii::Function<2>(1)
    {}
    double
    value(const dealii::Point<2> &, const unsigned int) const override
    {
      return p * get_time() / 3.;
    }
  };

  // A linear law written by a user: the isotropic law of material() behind
  // the ConstitutiveLaw interface, without being an ElasticMaterial.
  class UserLaw : public ConstitutiveLaw<2>
  {
  public:
    std::string
    get_name() const override
    {
      return "the test's own law";
    }
    std::unique_ptr<ConstitutiveLaw<2>>
    clone() const override
    {
      return std::make_unique<UserLaw>(*this);
    }
    bool
    is_linear() const override
    {
      return true;
    }
    double
    characteristic_stiffness() const override
    {
      return law.characteristic_stiffness();
    }
    dealii::SymmetricTensor<2, 2>
    stress(const dealii::SymmetricTensor<2, 2> &strain) const override
    {
      return law.stress(strain);
    }
    dealii::SymmetricTensor<4, 2>
    tangent(const dealii::SymmetricTensor<2, 2> &strain) const override
    {
      return law.tangent(strain);
    }
    double
    stress_zz(const dealii::SymmetricTensor<2, 2> &strain) const override
    {
      return law.stress_zz(strain);
    }

  private:
    ElasticMaterial law = material();
  };

  class NotANumber : public dealii::Function<2>
  {
  public:
    NotANumber()
      : dealii::Function<2>(2)
    {}
    double
    value(const dealii::Point<2> &, const unsigned int) const override
    {
      return std::numeric_limits<double>::quiet_NaN();
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // a) in code
  ContactProblem in_code;
  check(in_code.add_body(block(0, 3), material()) == 0, "a) the first body gets index 0");
  check(in_code.add_body(block(1, 4), material(), 10) == 1, "a) the second body gets index 1");
  common_setup(in_code, "in_code");
  in_code.boundary_conditions().add_pressure(13, constant(p));
  in_code.run();
  const auto &a = in_code.get_results();
  check_patch(a, "a) set up in code");

  // b) from a parameter file
  {
    dealii::ParameterHandler prm;
    ElasticityProblem::declare_parameters(prm);
    ContactProblem::declare_parameters(prm);
    prm.parse_input_from_string(parameter_file);
    ContactProblem from_file;
    from_file.parse_parameters(prm);
    from_file.run();
    const auto &b = from_file.get_results();
    check(a.solution.size() == b.solution.size(), "b) the same number of unknowns from the parameter file");
    double du = 0, dl = 0;
    for (unsigned int i = 0; i < std::min(a.solution.size(), b.solution.size()); ++i)
      du = std::max(du, std::abs(a.solution[i] - b.solution[i]));
    for (unsigned int i = 0; i < std::min(a.pairs.size(), b.pairs.size()); ++i)
      dl = std::max(dl, std::abs(a.pairs[i].multiplier - b.pairs[i].multiplier));
    check(a.pairs.size() == b.pairs.size(), "b) the same pairs");
    check(du == 0, "b) the displacements of the parameter file equal those set in code, bit for bit");
    check(dl == 0, "b) and so do the multipliers");
  }

  // c) the upper block as a deal.II triangulation
  {
    dealii::Triangulation<2> tria;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, {5u, 5u}, dealii::Point<2>(0, 1),
                                                      dealii::Point<2>(1, 2), true);
    ContactProblem problem;
    problem.add_body(block(0, 3), material());
    problem.add_body(tria, material(), 10);
    common_setup(problem, "tria");
    problem.boundary_conditions().add_pressure(13, constant(p));
    problem.run();
    check_patch(problem.get_results(), "c) upper block from a Triangulation (5 x 5)");

    ContactProblem own_law;
    own_law.add_body(block(0, 3), UserLaw());
    own_law.add_body(block(1, 4), UserLaw(), 10);
    common_setup(own_law, "own_law");
    own_law.boundary_conditions().add_pressure(13, constant(p));
    own_law.run();
    const auto &r = own_law.get_results();
    double      du = 0, umax = 0;
    for (unsigned int i = 0; i < std::min(a.solution.size(), r.solution.size()); ++i)
      {
        du   = std::max(du, std::abs(a.solution[i] - r.solution[i]));
        umax = std::max(umax, std::abs(a.solution[i]));
      }
    check(a.solution.size() == r.solution.size(), "c) a law of the user's own: the same unknowns");
    check_small(du / umax, 1e-13, "c) a law of the user's own: max |u - u_a| / max |u_a|");
    check_patch(r, "c) a law of the user's own");

    ContactProblem wrong_id;
    wrong_id.add_body(block(0, 3), material());
    wrong_id.add_body(tria, material(), 10);
    common_setup(wrong_id, "wrong_id");
    wrong_id.boundary_conditions().add_pressure(23, constant(p));
    check_throws([&] { wrong_id.run(); }, "'Pressure on boundary id 23': no boundary edge",
                 "c) a pressure on a boundary id no body has is refused, naming it");
  }

  // d) loads as functions of time over load steps
  {
    ContactProblem problem;
    problem.add_body(block(0, 3), material());
    problem.add_body(block(1, 4), material(), 10);
    common_setup(problem, "steps");
    problem.boundary_conditions().add_pressure(13, std::make_shared<RisingPressure>());
    problem.options().n_load_steps = 3;
    problem.options().final_time   = 3;
    problem.run();
    const auto &r = problem.get_results();
    check(r.steps.size() == 3, "d) three load steps");
    for (unsigned int k = 0; k < r.steps.size(); ++k)
      check_near(std::abs(r.steps[k].total_contact_force[1]), p * (k + 1) / 3., 1e-10 * p,
                 "d) step " + std::to_string(k + 1) + ": total contact force p t / 3");

    ContactProblem nan;
    nan.add_body(block(0, 3), material());
    nan.add_body(block(1, 4), material(), 10);
    common_setup(nan, "nan");
    nan.boundary_conditions().add_pressure(13, constant(p));
    nan.boundary_conditions().set_body_force(std::make_shared<NotANumber>(), "gravity of the test");
    check_throws([&] { nan.run(); }, "gravity of the test: the function returns nan",
                 "d) a body force that returns NaN is refused, naming it");
  }

  // e) misuse
  {
    ContactProblem empty;
    check_throws([&] { empty.run(); }, "no body", "e) run() without a body");

    ContactProblem no_pair;
    no_pair.add_body(block(0, 3), material());
    no_pair.add_body(block(1, 4), material(), 10);
    check_throws([&] { no_pair.run(); }, "'Contact/Pairs' is empty but there are 2 bodies",
                 "e) two bodies and no contact pair");

    ContactProblem pairs;
    pairs.add_contact_pair(3, 12);
    check_throws([&] { pairs.add_contact_pair(12, 20); },
                 "boundary id 12 is already part of the contact pair 3 : 12",
                 "e) one boundary id in two pairs");
    check_throws([&] { pairs.add_contact_pair(5, 5); }, "two different boundary ids",
                 "e) the same boundary id on both sides");

    BoundaryConditionParameters bc;
    check_throws([&] { bc.add_traction(3, zero(1)); }, "Traction on boundary id 3: the function has 1 component(s), 2 expected",
                 "e) a traction with one component");
    check_throws([&] { bc.add_pressure(3, nullptr); }, "Pressure on boundary id 3: the function is a null pointer",
                 "e) a null pressure function");

    ContactProblem models;
    models.add_body(block(0, 3), material());
    check_throws([&] { models.add_body(block(1, 4), ElasticMaterial(7000, 0.3, ElasticMaterial::Model::plane_stress), 10); },
                 "body 1 is in plane stress, body 0 in plane strain", "e) plane stress mixed with plane strain");
    check_throws([&] { models.add_body(block(1, 4), material(), 252); }, "id 255 is out of range",
                 "e) a boundary id offset that lifts an id past 254");

    ContactProblem friction;
    friction.add_body(block(0, 3), material());
    friction.add_body(block(1, 4), material(), 10);
    common_setup(friction, "friction");
    friction.options().contact.friction_coefficient = 0.3;
    check_throws([&] { friction.run(); }, "'Contact/Friction coefficient' is 0.3",
                 "e) a friction coefficient with frictionless contact");

    ContactProblem order;
    order.add_body(block(0, 3), material());
    order.options().degree = 3;
    check_throws([&] { order.run(); }, "'Discretization/Order' is 3", "e) order 3");
  }
  return testing::finish();
}
