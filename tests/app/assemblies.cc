// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Assemblies of many bodies with the contact interfaces found by
// ContactDetection ('Pairs = auto'), checked against statics:
// a) examples/parameters/assembly-tower.prm (8 bodies, non-matching
//    Voronoi meshes, Coulomb friction, self-weight): the interface below
//    block i carries the weight of the blocks above, 0.5 (8 - i), with no
//    tangential force and its centre of pressure under their centroid,
//    x = 0.5 + 0.04 (i + 7), all to 1e-10 (relative to the weight);
// b) examples/parameters/assembly-wall.prm (one gmsh file, a body per
//    physical surface, conforming in the file): 6 bodies, 9 interfaces;
//    the base's bed joints carry the weight 4, each half block of row 2 its
//    weight 0.5 at x = 0.5 and 3.5, the head joints of row 2 open; with
//    Coulomb friction (mu = 0.1, 0.3, 0.6) the same statics and
//    |tau| <= mu p at every closed pair (three bodies meet where a head
//    joint ends on a bed joint);
// c) the interfaces named by hand (the ids the detection would replace,
//    in the detection's master / slave order) give the same displacements
//    and multipliers as 'auto' to 1e-12;
// d) 1000 blocks (a wall of 40 courses in running bond, each block meshed
//    on its own with 2 or 3 cells along, k = 1) added by add_parts() from
//    one mesh, on a base: set up, checked for support, detected and solved;
//    the base's bed joints carry the whole weight (1e-9), every bed joint
//    carries the weight above it in its course (1e-8), and the number of
//    interfaces is the number of joints of the bond; timings printed;
// f) friction by pairs of materials: the block of
//    examples/parameters/friction-drag.prm dragged until it slides on the
//    base (normal force 10, four steps of 0.2): the friction force is
//    mu * 10 to 1e-10 with mu
//    from 'Friction between materials' ('Material/Name' of each body), a
//    pair of names beating a '*', bodies beating materials; in the wall of
//    b) the names of 'Part materials' reach every interface (reported
//    coefficients); unknown and invalid names are errors;
// e) misuse: 'Part materials' without 'Parts as bodies', a part material
//    for an id the file lacks, 'Friction between bodies' naming a body that
//    does not exist or used without Coulomb friction, 'auto' with nothing
//    that faces, more 'Body b' sections than declared.
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/function.h>

#include <dealvem/app/contact_problem.h>
#include <dealvem/app/elasticity_problem.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/masonry_wall.h>

#include "../tests.h"

#include <chrono>
#include <map>

using namespace dealvem;
using testing::check;
using testing::check_near;
using testing::check_small;
using testing::check_throws;

namespace
{
  using P = dealii::Point<2>;

  // run a parameter file the way the program does (as many body sections
  // as it needs), without output files
  ContactProblem::Results
  run_file(const std::string &file, const std::string &extra = "")
  {
    dealii::ParameterHandler prm;
    ElasticityProblem::declare_parameters(prm);
    ContactProblem::declare_parameters(prm, ContactProblem::body_sections(file));
    prm.parse_input(file);
    if (!extra.empty())
      prm.parse_input_from_string(extra, "", true);
    ContactProblem problem(MPI_COMM_SELF);
    problem.parse_parameters(prm, testing::source_dir() + "/examples/parameters");
    auto &o      = problem.options();
    o.write_vtu  = o.write_json = o.write_pictures = o.write_csv = false;
    problem.run();
    return problem.get_results();
  }

  // the interface between bodies a and b (either side), or nullptr
  const ContactProblem::InterfaceResult *
  between(const ContactProblem::Results &r, const unsigned int a, const unsigned int b)
  {
    for (const auto &i : r.interface_results)
      if ((i.master_body == a && i.slave_body == b) || (i.master_body == b && i.slave_body == a))
        return &i;
    return nullptr;
  }

  void
  tower()
  {
    const auto r = run_file(testing::source_dir() + "/examples/parameters/assembly-tower.prm");
    check(r.interface_results.size() == 7, "a) 7 interfaces detected");
    for (unsigned int i = 1; i <= 7; ++i)
      {
        const auto *itf = between(r, i - 1, i);
        check(itf != nullptr, "a) interface below block " + std::to_string(i));
        if (itf == nullptr)
          continue;
        const std::string below = "a) below block " + std::to_string(i);
        check_near(itf->normal_force, 0.5 * (8 - i), 1e-10 * 3.5, below + ": normal force = weight above");
        check_small(itf->tangential_force, 1e-10 * 3.5, below + ": no tangential force");
        check_near(itf->centre_of_pressure[0], 0.5 + 0.04 * (i + 7), 1e-10, below + ": centre of pressure");
        check(itf->detected, below + ": found by the detection");
      }
  }

  void
  wall_from_gmsh()
  {
    const auto r = run_file(testing::source_dir() + "/examples/parameters/assembly-wall.prm");
    check(r.cells_per_body.size() == 6, "b) 6 bodies from the physical surfaces");
    check(r.interface_results.size() == 9, "b) 9 interfaces");
    const auto *b1 = between(r, 0, 1), *b2 = between(r, 0, 2);
    if (b1 && b2)
      check_near(b1->normal_force + b2->normal_force, 4., 4e-10, "b) the base carries the weight of the wall");
    for (const auto &[half, x] : std::vector<std::pair<unsigned int, double>>{{3, 0.5}, {5, 3.5}})
      {
        const unsigned int below = (half == 3 ? 1 : 2);
        const auto        *itf   = between(r, below, half);
        check(itf != nullptr, "b) bed joint of half block " + std::to_string(half));
        if (itf == nullptr)
          continue;
        check_near(itf->normal_force, 0.5, 1e-10, "b) half block " + std::to_string(half) + ": its weight");
        check_near(itf->centre_of_pressure[0], x, 1e-10, "b) half block " + std::to_string(half) + ": centre");
      }
    for (const auto &[a, b] : std::vector<std::pair<unsigned int, unsigned int>>{{3, 4}, {4, 5}})
      if (const auto *itf = between(r, a, b))
        check(itf->n_stick + itf->n_slip == 0 && itf->normal_force == 0,
              "b) head joint " + std::to_string(a) + "-" + std::to_string(b) + " of row 2 is open");

    // where three bodies meet (a head joint ending on a bed joint or on
    // the base: (1, 0.5), (3, 0.5), (2, 0), (2, 0.5)) the head joint's end
    // pair repeats the two bed-joint pairs there: it is marked and open
    {
      std::vector<P> expected = {P(1, 0.5), P(3, 0.5), P(2, 0), P(2, 0.5)};
      check(r.n_junction_pairs == 4, "b) 4 junction pairs, got " + std::to_string(r.n_junction_pairs));
      unsigned int found = 0;
      for (const auto &p : r.pairs)
        for (const auto &e : expected)
          if ((p.location - e).norm() < 1e-12 && std::abs(p.tangent[1]) > 0.99)
            {
              ++found;
              check(p.status == "open" && p.multiplier == 0,
                    "b) the head joint's pair at the junction is open and carries no force");
            }
      check(found == 4, "b) the 4 head-joint pairs at the junctions, found " + std::to_string(found));
    }

    // Coulomb friction: the same statics for any mu, and Coulomb's law at
    // every pair. Where a head joint ends on a bed joint, three bodies
    // meet and the head joint's end pair repeats what the two bed joints
    // impose; it stays open (NodeInsertion::mark_junctions()). Before, it
    // took a share of the force that made the friction iteration cycle
    // ("The friction active set cycles") for mu < 0.68.
    for (const double mu : {0.1, 0.3, 0.6})
      {
        const std::string name = "b) Coulomb, mu = " + std::to_string(mu) + ": ";
        const auto        rc   = run_file(testing::source_dir() + "/examples/parameters/assembly-wall.prm",
                                 "subsection Contact\n set Tangential = coulomb\n set Friction coefficient = " +
                                   std::to_string(mu) + "\nend\n");
        const auto *c1 = between(rc, 0, 1), *c2 = between(rc, 0, 2);
        check(c1 && c2, name + "bed joints on the base");
        if (c1 && c2)
          check_near(c1->normal_force + c2->normal_force, 4., 4e-10, name + "the base carries the weight");
        for (const auto &[half, x] : std::vector<std::pair<unsigned int, double>>{{3, 0.5}, {5, 3.5}})
          if (const auto *itf = between(rc, half == 3 ? 1 : 2, half))
            {
              check_near(itf->normal_force, 0.5, 1e-10, name + "half block " + std::to_string(half) + ": its weight");
              check_near(itf->centre_of_pressure[0], x, 1e-10, name + "half block " + std::to_string(half) + ": centre");
            }
        double worst = 0;
        for (const auto &p : rc.pairs)
          if (p.status != "open")
            worst = std::max(worst, std::abs(p.tangential_traction) - mu * p.lumped_pressure);
        check(worst <= 1e-10, name + "|tau| <= mu p at every closed pair (largest excess " + std::to_string(worst) + ")");
      }
  }

  PolygonalMesh<2>
  brick(const P &lo, const P &hi, const unsigned int nx, const unsigned int ny)
  {
    PolygonalMesh<2> m;
    PolygonalMeshGenerators::structured_quads(m, lo, hi, nx, ny);
    return m;
  }

  // three blocks stacked on a base; the pairs by 'auto' or by hand
  ContactProblem::Results
  small_stack(const bool automatic, const std::vector<ContactDetection::Interface> &detected = {})
  {
    ContactProblem problem(MPI_COMM_SELF);
    const ElasticMaterial steel(1000, 0.3);
    problem.add_body(brick(P(-1, -1), P(2, 0), 5, 2), steel, 0);              // ids 0..3
    problem.add_body(brick(P(0, 0), P(1, 0.5), 3, 2), steel, 10);             // 10..13
    problem.add_body(brick(P(0.1, 0.5), P(1.1, 1), 4, 2), steel, 20);         // 20..23
    problem.add_body(brick(P(0.2, 1), P(1.2, 1.5), 2, 1), steel, 30);         // 30..33
    problem.boundary_conditions().add_dirichlet(2, {{true, true}},
                                                std::make_shared<dealii::Functions::ZeroFunction<2>>(2));
    problem.boundary_conditions().set_body_force(
      std::make_shared<dealii::Functions::ConstantFunction<2>>(std::vector<double>{0., -1.}));
    auto &o              = problem.options();
    o.contact.tangential = ContactSettings::Tangential::multipliers;
    o.write_vtu = o.write_json = o.write_pictures = o.write_csv = false;
    if (automatic)
      problem.detect_contact_pairs();
    else
      {
        // the faces the detection finds, in its master / slave order: the
        // top of body b (3 + 10 b) and the bottom of body b + 1 (12 + 10 b)
        for (const auto &d : detected)
          {
            const unsigned int lower = std::min(d.master_body, d.slave_body);
            const unsigned int top = 3 + 10 * lower, bottom = 12 + 10 * lower;
            if (d.master_body == lower)
              problem.add_contact_pair(top, bottom);
            else
              problem.add_contact_pair(bottom, top);
          }
      }
    problem.run();
    return problem.get_results();
  }

  void
  auto_against_hand()
  {
    const auto a = small_stack(true);
    check(a.detection.interfaces.size() == 3, "c) 3 interfaces detected");
    const auto h = small_stack(false, a.detection.interfaces);
    check(a.solution.size() == h.solution.size() && a.pairs.size() == h.pairs.size(),
          "c) the same unknowns by hand and by detection");
    if (a.solution.size() != h.solution.size() || a.pairs.size() != h.pairs.size())
      return;
    double du = 0, umax = 0, dl = 0, lmax = 0;
    for (unsigned int i = 0; i < a.solution.size(); ++i)
      {
        du   = std::max(du, std::abs(a.solution[i] - h.solution[i]));
        umax = std::max(umax, std::abs(a.solution[i]));
      }
    for (unsigned int i = 0; i < a.pairs.size(); ++i)
      {
        dl   = std::max(dl, std::abs(a.pairs[i].multiplier - h.pairs[i].multiplier));
        lmax = std::max(lmax, std::abs(a.pairs[i].multiplier));
      }
    check_small(du / umax, 1e-12, "c) displacements: auto against hand-named pairs (relative)");
    check_small(dl / lmax, 1e-12, "c) multipliers: auto against hand-named pairs (relative)");
  }

  void
  thousand_blocks()
  {
    // courses of 25 blocks 1 x 0.5; odd courses shifted by half a block,
    // with half blocks at both ends (26 pieces): 40 courses, 1020 blocks,
    // 2 or 3 quads along each (half blocks too), one across; the base 27 x 2
    const unsigned int courses = 40, per_course = 25;
    PolygonalMeshGenerators::MasonryWall layout;
    layout.blocks_per_course = per_course;
    layout.n_blocks          = courses / 2 * (2 * per_course + 1);
    layout.quads_along       = 2;
    layout.quads_across      = 1;
    layout.scale_half_blocks = false;
    layout.base_quads_along  = 27;
    layout.base_quads_across = 2;
    PolygonalMesh<2> wall;
    PolygonalMeshGenerators::masonry_wall(wall, layout);
    // every course is complete: a weight of 0.5 per block length
    const std::vector<double> course_weight(courses, 0.5 * per_course);
    double                    weight = 0;
    for (const double w : course_weight)
      weight += w;
    const unsigned int n_blocks = wall.get_material_ids().size() - 1;

    const auto    start = std::chrono::steady_clock::now();
    ContactProblem problem(MPI_COMM_SELF);
    problem.add_parts(wall, ElasticMaterial(1000, 0.2));
    problem.boundary_conditions().add_dirichlet(2, {{true, true}},
                                                std::make_shared<dealii::Functions::ZeroFunction<2>>(2));
    problem.boundary_conditions().set_body_force(
      std::make_shared<dealii::Functions::ConstantFunction<2>>(std::vector<double>{0., -1.}));
    problem.detect_contact_pairs();
    auto &o              = problem.options();
    o.degree             = 1;
    o.contact.tangential = ContactSettings::Tangential::multipliers;
    o.write_vtu = o.write_json = o.write_pictures = o.write_csv = false;
    problem.run();
    const auto   &r       = problem.get_results();
    const double  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "d) " << n_blocks << " blocks + base: " << r.n_dofs << " DoFs, " << r.n_multipliers
              << " multipliers, " << r.interface_results.size() << " interfaces, " << seconds << " s (";
    for (const auto &t : r.timings)
      std::cout << t.first << " " << t.second << " s; ";
    std::cout << ")" << std::endl;
    check(n_blocks == 1020 && problem.n_bodies() == 1021, "d) 1020 blocks and the base are bodies");
    // joints: course 0 on the base (25), bed joints between courses (each
    // upper block on two lower ones, half blocks on one: 2 * 25 per pair of
    // courses, 50 * 39), head joints (24 in even courses, 25 in odd ones)
    const unsigned int expected = 25 + 50 * 39 + 20 * 24 + 20 * 25;
    check(r.interface_results.size() == expected,
          "d) " + std::to_string(expected) + " interfaces, got " + std::to_string(r.interface_results.size()));
    // the bed joints of each course carry the weight of the courses above
    std::map<unsigned int, double> carried; // course of the lower side -> normal force
    std::map<unsigned int, unsigned int> course_of;
    for (unsigned int b = 0; b <= n_blocks; ++b)
      course_of[b] = 0;
    {
      unsigned int b = 1;
      for (unsigned int c = 0; c < courses; ++c)
        for (unsigned int k = 0; k < (c % 2 == 0 ? per_course : per_course + 1); ++k)
          course_of[b++] = c + 1; // the base is course 0
    }
    for (const auto &i : r.interface_results)
      {
        const unsigned int cm = course_of[i.master_body], cs = course_of[i.slave_body];
        if (cm != cs)
          carried[std::min(cm, cs)] += i.normal_force;
      }
    double above = weight;
    for (unsigned int c = 0; c < courses; ++c)
      {
        check_near(carried[c], above, (c == 0 ? 1e-9 : 1e-8) * weight,
                   "d) bed joints on course " + std::to_string(c) + " carry the weight above");
        above -= course_weight[c];
      }
  }

  void
  friction_by_materials()
  {
    const std::string drag  = testing::source_dir() + "/examples/parameters/friction-drag.prm";
    const std::string names = "subsection Material\n set Name = steel\nend\n"
                              "subsection Body 1\n subsection Material\n  set Name = rubber\n end\nend\n"
                              "subsection Boundary conditions and loads\n set Function constants = p=10, d=0.2\nend\n";
    // the friction force of the last step (every closed pair slips) and
    // the coefficient the interface reports
    const auto slide = [&](const std::string &contact, const double mu, const std::string &what) {
      const auto r = run_file(drag, names + "subsection Contact\n" + contact + "\nend\n");
      const auto &last = r.steps.back();
      // N = 10 (the load); F = mu N only if every closed pair is at its
      // bound |T| <= mu N (the block slides, or tips onto one pair that
      // is about to)
      check_near(last.total_contact_force[1], 10, 1e-10 * 10, "f) " + what + ": N = p");
      check_near(std::abs(last.total_contact_force[0]), mu * 10, 1e-10 * 10, "f) " + what + ": F = mu N");
      check_near(r.interface_results.at(0).friction_coefficient, mu, 0, "f) " + what + ": reported coefficient");
    };
    slide(" set Friction between materials = steel : rubber : 0.5", 0.5, "a pair of materials");
    slide(" set Friction between materials = steel : rubber : 0.5; * : rubber : 0.4", 0.5, "names beat '*'");
    slide(" set Friction between materials = * : rubber : 0.4; steel : rubber : 0.5", 0.5, "names beat a later '*'");
    slide(" set Friction between materials = rubber : * : 0.4", 0.4, "a wildcard");
    slide(" set Friction between materials = steel : rubber : 0.4; steel : rubber : 0.45", 0.45, "the later entry");
    slide(" set Friction between materials = steel : rubber : 0.5\n set Friction between bodies = 1 : 0 : 0.2", 0.2,
          "bodies beat materials");
    slide(" set Friction between materials = steel : steel : 0.5", 0.3, "no match: the common coefficient");
    check_throws([&] { run_file(drag, names + "subsection Contact\n set Friction between materials = wood : "
                                              "rubber : 0.5\nend\n"); },
                 "no body has the material 'wood'", "f) an unknown material");
    check_throws([&] { run_file(drag, "subsection Material\n set Name = st eel\nend\n"); },
                 "Parameter 'Material/Name': the material name 'st eel' is not valid", "f) an invalid name");
    check_throws([&] { run_file(drag, names + "subsection Contact\n set Friction between materials = steel : "
                                              "rubber\nend\n"); },
                 "expected 'name a : name b : mu'", "f) an entry without a coefficient");
    check_throws([&] { run_file(drag, names + "subsection Contact\n set Tangential = multipliers\n set Friction "
                                              "between materials = steel : rubber : 0.5\n set Friction "
                                              "coefficient = 0\nend\n"); },
                 "'Contact/Friction between materials' gives friction coefficients, but 'Contact/Tangential' is",
                 "f) friction between materials without Coulomb friction");

    // the parts of one gmsh file: the base (id 1) 'stone' by 'Part
    // materials', the blocks 'brick' by 'Material/Name'
    const std::string wall = testing::source_dir() + "/examples/parameters/assembly-wall.prm";
    const auto        r    = run_file(wall, "subsection Material\n set Name = brick\n set Part materials = 1 : 5000 : "
                                            "0.25 : stone\nend\nsubsection Contact\n set Tangential = coulomb\n set "
                                            "Friction coefficient = 0.1\n set Friction between materials = stone : "
                                            "brick : 2; brick : brick : 3\nend\n");
    unsigned int n_stone = 0, n_brick = 0;
    for (const auto &i : r.interface_results)
      {
        const bool base = (i.master_body == 0 || i.slave_body == 0);
        check_near(i.friction_coefficient, base ? 2. : 3., 0, "f) wall: coefficient by the parts' materials");
        (base ? n_stone : n_brick) += 1;
      }
    check(n_stone > 0 && n_brick > 0, "f) wall: interfaces with the base and between blocks");
    check_throws([&] {
      run_file(wall, "subsection Material\n set Part materials = 1 : 5000 : 0.25 : stone\nend\nsubsection "
                     "Contact\n set Tangential = coulomb\n set Friction between materials = stone : mortar : "
                     "0.5\nend\n");
    },
                 "no body has the material 'mortar'", "f) a material no part has");
  }

  void
  misuse()
  {
    const std::string wall = testing::source_dir() + "/examples/parameters/assembly-wall.prm";
    check_throws([&] { run_file(wall, "subsection Mesh\n set Parts as bodies = false\nend\n"); },
                 "'Material/Part materials' is set, but 'Mesh/Parts as bodies' is false",
                 "e) part materials without parts");
    check_throws([&] { run_file(wall, "subsection Material\n set Part materials = 7 : 100 : 0.3\nend\n"); },
                 "gives material id 7, which no cell of the mesh file", "e) a part material for a missing id");
    check_throws([&] {
      run_file(wall, "subsection Contact\n set Friction between bodies = 0 : 9 : 0.5\nend\n");
    },
                 "there is no body 9", "e) friction for a body that does not exist");
    check_throws([&] {
      run_file(wall, "subsection Contact\n set Friction between bodies = 0 : * : 0.5\nend\n");
    },
                 "'Contact/Friction between bodies' gives friction coefficients, but 'Contact/Tangential' is",
                 "e) friction between bodies without Coulomb friction");
    {
      ContactProblem problem(MPI_COMM_SELF);
      problem.add_body(brick(P(0, 0), P(1, 1), 2, 2), ElasticMaterial(1000, 0.3), 0);
      problem.add_body(brick(P(3, 0), P(4, 1), 2, 2), ElasticMaterial(1000, 0.3), 10);
      problem.detect_contact_pairs();
      auto &o    = problem.options();
      o.write_vtu = o.write_json = o.write_pictures = o.write_csv = false;
      check_throws([&] { problem.run(); }, "no boundary parts of different bodies face each other",
                   "e) auto with bodies far apart");
    }
    {
      dealii::ParameterHandler prm;
      ElasticityProblem::declare_parameters(prm);
      ContactProblem::declare_parameters(prm, 3);
      prm.parse_input_from_string("set Number of bodies = 4\n");
      ContactProblem problem(MPI_COMM_SELF);
      check_throws([&] { problem.parse_parameters(prm); }, "but only 3 body sections are declared",
                   "e) more bodies than declared sections");
    }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  tower();
  wall_from_gmsh();
  auto_against_hand();
  thousand_blocks();
  friction_by_materials();
  misuse();
  return testing::finish();
}
