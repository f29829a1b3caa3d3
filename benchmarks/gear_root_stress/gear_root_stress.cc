// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Tooth root stress of the pinion of examples/step-12: dealvem's virtual
// elements (k = 2) against deal.II's FE_Q(2) on the same meshes, and
// ISO 6336-3 method B.
//
// The problem. The pinion of step-12 (m = 4, z = 20, 20 degrees, backlash
// allowance 0.1, linear tip relief 0.01, bore radius 16, steel E = 210000,
// nu = 0.3, plane strain per mm of face width) as a sector of five teeth
// (from the middle of the space before tooth 0 to the middle of the space
// after tooth 4; PolygonalMeshGenerators::spur_gear()), clamped on the bore
// and on both sector sides. Tooth 2, in the middle, is placed as step-12's
// pinion tooth 0 at the roll angle phi (default -1.447 degrees, step-12's
// position 6 of 8, where a single tooth pair carries the load; --hpstc: the
// highest point of single tooth contact). Its counter-clockwise (driving)
// flank carries the contact force of a single pair, F_n = 250 N/mm along
// the line of action, as a Hertz traction p0 sqrt(1 - (d/a)^2) over the
// half-width a from Hertz with the flanks' radii of curvature at the contact
// point (the pinion's and the gear's, z2 = 31), directed along the flank's
// normal there (the line of action).
//
// The quantity: the largest tensile (maximum in-plane principal) stress on
// the root fillet of the loaded flank's side (the tension side), the
// trochoid piece of SpurGear's outline of tooth 2 between the form circle
// and the root circle.
//
// 1. FE_Q(2): deal.II FESystem(FE_Q(2), 2) with MappingQ(2) on
//    the triangulation of spur_gear(tria, ...) (global refinement 1, the
//    contact zone graded to 0.02 as in step-12), refined further toward the
//    fillet with refine_toward() to the fillet cell sizes h = 0.4, 0.2, 0.1,
//    0.05, 0.025, 0.0125 (level 0: no fillet refinement, step-12's mesh),
//    hanging-node constraints, UMFPACK; the stress evaluated at 9 points on
//    each boundary face of the fillet. The fillet sequence converges;
//    the far field is checked by the finest fillet level on the block mesh
//    refined 2 and 3 times instead of once (FE_Q(2) and VEM). The
//    reference is FE_Q(2) at the finest fillet level with 3 global
//    refinements, its error estimated by the change from 2. Two more
//    columns help to read VEM's figure: FE_Q(2)'s largest stress at the
//    faces' end points only (the mesh vertices, where VEM's recovered
//    stress lives), and FE_Q(2) with MappingQ(1), on the straight-edged
//    cells VEM sees.
// 2. VEM k = 2 (ElasticityAssembler, UMFPACK) on the same triangulations
//    converted to polygons (from_triangulation(): what
//    spur_gear(PolygonalMesh, ...) does; a hanging vertex becomes a vertex
//    of the coarse neighbour, whose halves of the edge get a midpoint node
//    each: three free nodes where FE_Q(2) has the coarse face's midpoint
//    and three constrained ones, so VEM has 1 to 3 % fewer DoFs, FE_Q(2)'s
//    count including the constrained ones); the fillet stress is the
//    largest principal stress of
//    StressRecovery::vertex_stress() at the fillet's mesh vertices.
// 3. ISO 6336-3 method B at the highest point of single tooth contact:
//    s_Fn, rho_F from the 30 degree tangent on the exact outline, h_Fe and
//    alpha_Fen from the normal at the load point, Y_F, Y_S and
//    sigma_F0 = F_t / (b m) Y_F Y_S (Y_beta = Y_B = Y_DT = 1), with ISO's
//    closed forms for s_Fn and rho_F printed as a check of the outline.
// 4. Saint-Venant: the finest FE level again with the Hertz half-width
//    halved and doubled (same force).
//
// Output: Markdown tables on stdout. Options:
//   --hpstc         the load at the highest point of single tooth contact
//   --levels n      fillet refinement levels 0 .. n (default 6)
//   --vem-levels n  VEM at levels 0 .. n (default: as --levels)
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/elasticity/material.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/spur_gear.h>
#include <dealvem/postprocessing/stress_recovery.h>
#include <dealvem/solvers/linear_solver.h>
#include <dealvem/vem/vem_dof_handler.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;

namespace RootStress
{
  using namespace dealvem;

  const double pi = std::acos(-1.);

  // the pair of step-12 (its pinion is meshed, the gear gives the Hertz radii)
  const double       m = 4, alpha = 20 * pi / 180, backlash = 0.1, relief = 0.01;
  const unsigned int z1 = 20, z2 = 31;
  const double       E = 210000, nu = 0.3, F_n = 250;
  const double       r1 = m * z1 / 2., r2 = m * z2 / 2.;
  const double       rb1 = r1 * std::cos(alpha), rb2 = r2 * std::cos(alpha);
  const unsigned int loaded_tooth = 2, n_sector_teeth = 5;

  // the load: where, which direction, how spread
  struct Load
  {
    double       s   = 0;       // contact coordinate on the line of action from the pitch point
    double       rho = 0;       // radius of the contact point on the pinion
    Point<2>     x;             // contact point on the exact outline
    Tensor<1, 2> t, n;          // unit tangent (counter-clockwise outline) and outward normal there
    double       a = 0, p0 = 0; // Hertz half-width and peak pressure
  };

  SpurGear::Parameters
  pinion_parameters(const double phi)
  {
    SpurGear::Parameters p;
    p.module      = m;
    p.n_teeth     = z1;
    p.backlash    = backlash;
    p.tip_relief  = relief;
    p.bore_radius = 0.4 * r1;
    // tooth 2 where step-12 has tooth 0 at the roll angle phi
    p.rotation = -(m * pi / 2 - backlash) / (2 * r1) + phi - 2 * pi * loaded_tooth / z1;
    return p;
  }

  // the outline coordinate range [begin, end) of a piece of the loaded tooth
  std::pair<double, double>
  piece_range(const SpurGear &gear, const unsigned int piece)
  {
    const double shift = loaded_tooth * gear.outline_pitch_length();
    return {shift + gear.piece_starts()[piece], shift + gear.piece_starts()[piece + 1]};
  }

  // the point of the loaded tooth's counter-clockwise flank (piece 4) at the
  // radius rho (bisection: the radius falls along the piece)
  double
  flank_coordinate(const SpurGear &gear, const double rho)
  {
    auto [lo, hi] = piece_range(gear, 4);
    for (unsigned int i = 0; i < 100; ++i)
      {
        const double mid = (lo + hi) / 2;
        if (gear.outline_point(mid).norm() > rho)
          lo = mid;
        else
          hi = mid;
      }
    return (lo + hi) / 2;
  }

  Load
  make_load(const SpurGear &gear, const double s, const double a_factor)
  {
    Load l;
    l.s            = s;
    l.rho          = std::hypot(rb1, r1 * std::sin(alpha) + s);
    const double c = flank_coordinate(gear, l.rho);
    l.x            = gear.outline_point(c);
    l.t            = gear.outline_tangent(c);
    l.t /= l.t.norm();
    l.n = Tensor<1, 2>({l.t[1], -l.t[0]});
    // Hertz, plane strain, both flanks steel
    const double rho1 = r1 * std::sin(alpha) + s, rho2 = r2 * std::sin(alpha) - s;
    const double R = rho1 * rho2 / (rho1 + rho2), Es = E / (2 * (1 - nu * nu));
    l.a  = a_factor * std::sqrt(4 * F_n * R / (pi * Es));
    l.p0 = 2 * F_n / (pi * l.a);
    return l;
  }

  // the traction on the pinion: -p n on the flank within a of the contact point
  class HertzTraction : public Function<2>
  {
  public:
    explicit HertzTraction(const Load &load)
      : Function<2>(2)
      , load(load)
    {}

    double
    value(const Point<2> &x, const unsigned int c) const override
    {
      const Tensor<1, 2> d  = x - load.x;
      const double       xi = d * load.t;
      if (d.norm() > 2 * load.a || std::abs(xi) >= load.a)
        return 0.;
      return -load.p0 * std::sqrt(1 - xi * xi / (load.a * load.a)) * load.n[c];
    }

    void
    vector_value(const Point<2> &x, Vector<double> &v) const override
    {
      for (unsigned int c = 0; c < 2; ++c)
        v[c] = value(x, c);
    }

  private:
    Load load;
  };

  double
  max_principal(const SymmetricTensor<2, 2> &s)
  {
    return 0.5 * (s[0][0] + s[1][1]) + std::sqrt(0.25 * (s[0][0] - s[1][1]) * (s[0][0] - s[1][1]) + s[0][1] * s[0][1]);
  }

  // is x on the tension-side fillet of the loaded tooth (piece 5)?
  bool
  on_fillet(const SpurGear &gear, const Point<2> &x)
  {
    if (gear.distance_to_outline(x) > 1e-3)
      return false;
    const auto [lo, hi] = piece_range(gear, 5);
    const double c      = gear.outline_coordinate(x, (lo + hi) / 2);
    return c >= lo - 1e-9 && c <= hi + 1e-9;
  }

  // the mesh of a level: step-12's settings on the pinion sector, then the
  // fillet graded to h (level 0: not)
  void
  make_mesh(Triangulation<2>  &tria,
            const SpurGear    &gear,
            const Load        &load,
            const unsigned int level,
            const unsigned int n_global = 1)
  {
    PolygonalMeshGenerators::GearMeshSettings settings;
    settings.first_tooth          = 0;
    settings.n_teeth              = n_sector_teeth;
    settings.n_global_refinements = n_global;
    settings.flank_cell_size      = 0.02;
    const double band             = 0.1 * m;
    settings.zones.push_back({int(loaded_tooth), std::max(load.rho - band, gear.form_radius()),
                              std::min(load.rho + band, gear.tip_radius()),
                              PolygonalMeshGenerators::GearMeshSettings::Flank::counter_clockwise});
    PolygonalMeshGenerators::spur_gear(tria, gear, settings);
    if (level == 0)
      return;
    const auto [lo, hi] = piece_range(gear, 5);
    std::vector<Point<2>> fillet;
    for (unsigned int i = 0; i <= 400; ++i)
      fillet.push_back(gear.outline_point(lo + (hi - lo) * i / 400.));
    const auto distance = [&](const Point<2> &x) {
      double d = 1e300;
      for (const auto &p : fillet)
        d = std::min(d, x.distance(p));
      return d;
    };
    PolygonalMeshGenerators::refine_toward(tria, distance, 0.8 / std::pow(2., level), 3.);
  }

  struct Result
  {
    unsigned int dofs  = 0;
    double       sigma = 0, where = 0, seconds = 0, force = 0;
    double       sigma_vertices = 0; // FE_Q(2): the largest over the faces' end points only
  };

  // ------------------------------------------------------------ FE_Q(2)
  Result
  solve_fe(const SpurGear    &gear,
           const Load        &load,
           const unsigned int level,
           const unsigned int n_global       = 1,
           const unsigned int mapping_degree = 2)
  {
    Timer            timer;
    Triangulation<2> tria;
    make_mesh(tria, gear, load, level, n_global);
    const FESystem<2> fe(FE_Q<2>(2), 2);
    const MappingQ<2> mapping(mapping_degree);
    DoFHandler<2>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    AffineConstraints<double> constraints;
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    for (const types::boundary_id id : {0, 2, 3})
      VectorTools::interpolate_boundary_values(mapping, dof_handler, id, Functions::ZeroFunction<2>(2), constraints);
    constraints.close();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityPattern sp;
    sp.copy_from(dsp);
    SparseMatrix<double> A(sp);
    Vector<double>       b(dof_handler.n_dofs()), x(dof_handler.n_dofs());

    const ElasticMaterial material(E, nu, ElasticMaterial::Model::plane_strain);
    const double          lambda = material.lambda(), mu = material.mu();
    const QGauss<2>       quadrature(3);
    const QGauss<1>       face_quadrature(5);
    FEValues<2>           fe_values(mapping, fe, quadrature, update_gradients | update_JxW_values);
    FEFaceValues<2> fe_face(mapping, fe, face_quadrature, update_values | update_quadrature_points | update_JxW_values);
    const HertzTraction                  traction(load);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    const FEValuesExtractors::Vector     u(0);
    Tensor<1, 2>                         force;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell_matrix = 0;
        cell_rhs    = 0;
        fe_values.reinit(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          for (const unsigned int i : fe_values.dof_indices())
            {
              const SymmetricTensor<2, 2> ei = fe_values[u].symmetric_gradient(i, q);
              const double                ti = trace(ei);
              for (const unsigned int j : fe_values.dof_indices())
                {
                  const SymmetricTensor<2, 2> ej = fe_values[u].symmetric_gradient(j, q);
                  cell_matrix(i, j) += (lambda * ti * trace(ej) + 2 * mu * (ei * ej)) * fe_values.JxW(q);
                }
            }
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 1 &&
              cell->face(f)->center().distance(load.x) < 4 * load.a + 2 * cell->face(f)->diameter())
            {
              fe_face.reinit(cell, f);
              for (const unsigned int q : fe_face.quadrature_point_indices())
                {
                  Tensor<1, 2> g;
                  for (unsigned int c = 0; c < 2; ++c)
                    g[c] = traction.value(fe_face.quadrature_point(q), c);
                  force += g * fe_face.JxW(q);
                  for (const unsigned int i : fe_face.dof_indices())
                    cell_rhs(i) += fe_face[u].value(i, q) * g * fe_face.JxW(q);
                }
            }
        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, A, b);
      }
    SparseDirectUMFPACK solver;
    solver.initialize(A);
    solver.vmult(x, b);
    constraints.distribute(x);

    // the stress at 9 points of each fillet face
    Result                             r;
    const QIterated<1>                 points(QTrapezoid<1>(), 8);
    FEFaceValues<2>                    fe_points(mapping, fe, points, update_gradients | update_quadrature_points);
    std::vector<SymmetricTensor<2, 2>> eps(points.size());
    r.sigma = r.sigma_vertices = -1e300;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 1 &&
            on_fillet(gear, cell->face(f)->center(true)))
          {
            fe_points.reinit(cell, f);
            fe_points[u].get_function_symmetric_gradients(x, eps);
            for (unsigned int q = 0; q < points.size(); ++q)
              {
                const double s = max_principal(lambda * trace(eps[q]) * unit_symmetric_tensor<2>() + 2 * mu * eps[q]);
                if (s > r.sigma)
                  {
                    r.sigma = s;
                    r.where = fe_points.quadrature_point(q).norm();
                  }
                if (q == 0 || q + 1 == points.size())
                  r.sigma_vertices = std::max(r.sigma_vertices, s);
              }
          }
    r.dofs    = dof_handler.n_dofs();
    r.force   = force.norm();
    r.seconds = timer.wall_time();
    return r;
  }

  // ------------------------------------------------------------ VEM k = 2
  Result
  solve_vem(const SpurGear &gear, const Load &load, const unsigned int level, const unsigned int n_global = 1)
  {
    Timer            timer;
    Triangulation<2> tria;
    make_mesh(tria, gear, load, level, n_global);
    PolygonalMesh<2> mesh;
    PolygonalMeshGenerators::from_triangulation(mesh, tria);
    tria.clear();
    VEMDoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(2);
    AffineConstraints<double> constraints;
    BoundaryConditions::interpolate_boundary_values(dof_handler, {0, 2, 3}, Functions::ZeroFunction<2>(2),
                                                    {{true, true}}, constraints);
    constraints.close();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    dof_handler.make_sparsity_pattern(dsp, constraints);
    SparsityPattern sp;
    sp.copy_from(dsp);
    SparseMatrix<double>                                A(sp);
    Vector<double>                                      b, x;
    const std::map<types::material_id, ElasticMaterial> materials = {
      {0, ElasticMaterial(E, nu, ElasticMaterial::Model::plane_strain)}};
    ElasticityAssembler<2> assembler(dof_handler, materials);
    const HertzTraction    traction(load);
    assembler.add_traction(1, traction);
    assembler.assemble(constraints, A, b);
    Vector<double> load_vector(dof_handler.n_dofs());
    assembler.assemble_load_vector(load_vector);
    Tensor<1, 2> force;
    for (unsigned int i = 0; i < load_vector.size(); ++i)
      force[i % 2] += load_vector[i];
    LinearSolver::Settings settings;
    settings.type = LinearSolver::Type::umfpack;
    LinearSolver solver(settings);
    solver.solve(A, x, b);
    constraints.distribute(x);

    const StressRecovery<2> recovery(dof_handler, materials, x);
    Result                  r;
    r.sigma = -1e300;
    std::vector<bool> seen(mesh.n_vertices(), false);
    for (const auto &e : mesh.get_edges())
      if (e.at_boundary() && e.boundary_id == 1)
        for (const unsigned int v : e.vertices)
          if (!seen[v] && on_fillet(gear, mesh.vertex(v)))
            {
              seen[v]        = true;
              const double s = max_principal(recovery.vertex_stress(v));
              if (s > r.sigma)
                {
                  r.sigma = s;
                  r.where = mesh.vertex(v).norm();
                }
            }
    r.dofs    = dof_handler.n_dofs();
    r.force   = force.norm();
    r.seconds = timer.wall_time();
    return r;
  }

  // ------------------------------------------------------------ ISO 6336-3 method B
  // The tooth's frame: x along the axis of the loaded tooth, y toward its
  // counter-clockwise flank.
  struct ISOResult
  {
    double s_Fn = 0, rho_F = 0, h_Fe = 0, alpha_Fen = 0, Y_F = 0, Y_S = 0, sigma_F0 = 0, F_t = 0;
    // from ISO's closed forms, as a check of the outline: unthinned, thinned by a rack shift
    double iso_s_Fn[2] = {0, 0}, iso_rho_F[2] = {0, 0};
  };

  ISOResult
  iso_root_stress(const SpurGear &gear, const Load &load)
  {
    const double axis  = gear.parameters().rotation + 2 * pi * loaded_tooth / z1;
    const auto   local = [&](const Tensor<1, 2> &v) {
      return Tensor<1, 2>(
        {std::cos(axis) * v[0] + std::sin(axis) * v[1], -std::sin(axis) * v[0] + std::cos(axis) * v[1]});
    };
    // the 30 degree tangent: the angle between the fillet's tangent and the
    // axis falls from about 90 degrees at the root to the flank's at the form circle
    const auto angle = [&](const double c) {
      const Tensor<1, 2> t = local(gear.outline_tangent(c));
      return std::acos(std::abs(t[0]) / t.norm());
    };
    auto [lo, hi] = piece_range(gear, 5); // from the form circle down to the root
    AssertThrow(angle(lo) < pi / 6 && angle(hi) > pi / 6, ExcMessage("no 30 degree tangent on the fillet"));
    for (unsigned int i = 0; i < 100; ++i)
      {
        const double mid                = (lo + hi) / 2;
        (angle(mid) < pi / 6 ? lo : hi) = mid;
      }
    const double       c30 = (lo + hi) / 2;
    const Tensor<1, 2> p30 = local(gear.outline_point(c30));
    ISOResult          r;
    r.s_Fn = 2 * std::abs(p30[1]);
    // the radius of curvature there: the circle through the outline points
    // 0.05 mm before and after it
    const Point<2> pa = gear.outline_point(c30 - 0.05), pb = gear.outline_point(c30),
                   pc    = gear.outline_point(c30 + 0.05);
    const Tensor<1, 2> u = pb - pa, v = pc - pb;
    r.rho_F = pa.distance(pb) * pb.distance(pc) * pa.distance(pc) / (2 * std::abs(u[0] * v[1] - u[1] * v[0]));
    // the load line through the load point along the force, to the axis
    const Tensor<1, 2> P = local(load.x), d = local(-load.n);
    const double       x_axis = P[0] - P[1] / d[1] * d[0];
    r.h_Fe                    = x_axis - p30[0];
    r.alpha_Fen               = std::atan(std::abs(d[0] / d[1]));
    r.Y_F                     = 6 * r.h_Fe / m * std::cos(r.alpha_Fen) / (std::pow(r.s_Fn / m, 2) * std::cos(alpha));
    const double L = r.s_Fn / r.h_Fe, q_s = r.s_Fn / (2 * r.rho_F);
    r.Y_S = (1.2 + 0.13 * L) * std::pow(q_s, 1 / (1.21 + 2.3 / L));
    r.F_t = F_n * std::cos(alpha); // the torque over the reference radius
    // ISO 6336-3's closed forms for the same fillet (basic rack h_fP = 1.25 m,
    // rho_fP = 0.38 m, no protuberance): for the unthinned tooth, and with
    // the backlash allowance taken as the profile shift -j / (2 m tan alpha)
    // of the generating rack
    for (const unsigned int thinned : {0, 1})
      {
        const double x_E = thinned ? -backlash / (2 * m * std::tan(alpha)) : 0., h_fP = 1.25, rho_fP = 0.38;
        const double G     = rho_fP - h_fP + x_E;
        const double E_m   = pi / 4 - h_fP * std::tan(alpha) - (1 - std::sin(alpha)) * rho_fP / std::cos(alpha);
        const double H     = 2. / z1 * (pi / 2 - E_m) - pi / 3;
        double       theta = pi / 6;
        for (unsigned int i = 0; i < 100; ++i)
          theta = 2 * G / z1 * std::tan(theta) - H;
        r.iso_s_Fn[thinned] = m * (z1 * std::sin(pi / 3 - theta) + std::sqrt(3.) * (G / std::cos(theta) - rho_fP));
        r.iso_rho_F[thinned] =
          m * (rho_fP + 2 * G * G / (std::cos(theta) * (z1 * std::cos(theta) * std::cos(theta) - 2 * G)));
      }
    r.sigma_F0 = r.F_t / (1. * m) * r.Y_F * r.Y_S;
    return r;
  }
} // namespace RootStress

int
main(int argc, char **argv)
{
  using namespace RootStress;
  try
    {
      bool         hpstc  = false;
      unsigned int levels = 6, vem_levels = 6;
      bool         vem_given = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string a = argv[i];
          if (a == "--hpstc")
            hpstc = true;
          else if (a == "--levels" && i + 1 < argc)
            levels = std::stoul(argv[++i]);
          else if (a == "--vem-levels" && i + 1 < argc)
            vem_levels = std::stoul(argv[++i]), vem_given = true;
          else
            {
              std::cerr << "usage: benchmark_gear_root_stress [--hpstc] [--levels n] [--vem-levels n]" << std::endl;
              return 2;
            }
        }
      if (!vem_given)
        vem_levels = levels;

      // the path of contact of step-12's pair and the load position on it
      const double ra1 = r1 + m, ra2 = r2 + m;
      const double recess   = std::sqrt(ra1 * ra1 - rb1 * rb1) - r1 * std::sin(alpha);
      const double approach = std::sqrt(ra2 * ra2 - rb2 * rb2) - r2 * std::sin(alpha);
      const double p_b      = pi * m * std::cos(alpha);
      const double phi      = hpstc ? (p_b - approach) / rb1 : -1.447 * pi / 180;
      const double s        = rb1 * phi;

      const SpurGear gear(pinion_parameters(phi));
      const Load     load = make_load(gear, s, 1.);
      std::cout << "# Tooth root stress of step-12's pinion, "
                << (hpstc ? "load at the HPSTC" : "load at step-12's roll angle") << "\n\n"
                << "- roll angle " << std::setprecision(5) << phi * 180 / pi << " degrees, contact " << s
                << " mm from the pitch point along the line of action (a single pair in contact for s in ["
                << recess - p_b << ", " << p_b - approach << "]), radius " << load.rho << " mm (form radius "
                << gear.form_radius() << ", relief from " << gear.parameters().tip_relief_radius << ")\n"
                << "- F_n = " << F_n << " N/mm, Hertz half-width a = " << load.a << " mm, p0 = " << load.p0
                << " MPa; the flank normal against the line of action: |cos| = "
                << std::max(std::abs(load.n * Tensor<1, 2>({std::sin(alpha), std::cos(alpha)})),
                            std::abs(load.n * Tensor<1, 2>({std::sin(alpha), -std::cos(alpha)})))
                << "\n\n";

      // the fillet sequence on the block mesh refined once (step-12's)
      std::vector<Result> fe(levels + 1), fe_flat(levels + 1), vem(vem_levels + 1);
      for (unsigned int l = 0; l <= levels; ++l)
        {
          fe[l]      = solve_fe(gear, load, l);
          fe_flat[l] = solve_fe(gear, load, l, 1, 1);
        }
      for (unsigned int l = 0; l <= vem_levels; ++l)
        vem[l] = solve_vem(gear, load, l);
      // the far field: the finest fillet level on the block mesh refined
      // 2 and 3 times; the reference is the last, its error the change from
      // the one before
      std::vector<Result> fe_far(4), vem_far(4);
      fe_far[1]  = fe[levels];
      vem_far[1] = vem[std::min(levels, vem_levels)];
      for (unsigned int g = 2; g <= 3; ++g)
        {
          fe_far[g]  = solve_fe(gear, load, levels, g);
          vem_far[g] = solve_vem(gear, load, std::min(levels, vem_levels), g);
        }
      const double reference = fe_far[3].sigma, err = std::abs(fe_far[3].sigma - fe_far[2].sigma);

      std::cout << "| level | fillet h (mm) | DoFs FE_Q(2) | sigma_root FE_Q(2) (MPa) | change | at vertices | "
                   "straight edges | at radius | resultant (N/mm) | time (s) | DoFs VEM | sigma_root VEM (MPa) | "
                   "VEM / reference - 1 | at radius | resultant | time (s) |\n"
                << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
      for (unsigned int l = 0; l <= std::max(levels, vem_levels); ++l)
        {
          std::cout << "| " << l << " | " << (l == 0 ? std::string("(step-12)") : std::to_string(0.8 / std::pow(2., l)))
                    << " | ";
          if (l <= levels)
            std::cout << fe[l].dofs << " | " << std::setprecision(6) << fe[l].sigma << " | "
                      << (l > 0 ? std::to_string(fe[l].sigma / fe[l - 1].sigma - 1) : std::string("")) << " | "
                      << fe[l].sigma_vertices << " | " << fe_flat[l].sigma << " | " << std::setprecision(5)
                      << fe[l].where << " | " << fe[l].force << " | " << std::setprecision(3) << fe[l].seconds << " | ";
          else
            std::cout << " | | | | | | | | ";
          if (l <= vem_levels)
            std::cout << vem[l].dofs << " | " << std::setprecision(6) << vem[l].sigma << " | " << std::setprecision(3)
                      << vem[l].sigma / reference - 1 << " | " << std::setprecision(5) << vem[l].where << " | "
                      << vem[l].force << " | " << std::setprecision(3) << vem[l].seconds << " |\n";
          else
            std::cout << " | | | | | |\n";
        }

      std::cout << "\nThe far field (fillet level " << std::min(levels, vem_levels) << ", VEM; " << levels
                << ", FE_Q(2)):\n\n"
                << "| global refinements | DoFs FE_Q(2) | sigma_root FE_Q(2) (MPa) | time (s) | DoFs VEM | "
                   "sigma_root VEM (MPa) | VEM / FE_Q(2) - 1 | time (s) |\n"
                << "|---:|---:|---:|---:|---:|---:|---:|---:|\n";
      for (unsigned int g = 1; g <= 3; ++g)
        std::cout << "| " << g << " | " << fe_far[g].dofs << " | " << std::setprecision(6) << fe_far[g].sigma << " | "
                  << std::setprecision(3) << fe_far[g].seconds << " | " << vem_far[g].dofs << " | "
                  << std::setprecision(6) << vem_far[g].sigma << " | " << std::setprecision(3)
                  << vem_far[g].sigma / fe_far[g].sigma - 1 << " | " << vem_far[g].seconds << " |\n";

      std::cout << "\nReference (FE_Q(2), fillet level " << levels
                << ", 3 global refinements): " << std::setprecision(6) << reference << " MPa, estimated error "
                << std::setprecision(3) << err << " MPa (" << 100 * err / reference
                << " %, the change from 2 global refinements; the fillet "
                << "levels " << levels - 1 << " to " << levels << " changed it by " << std::setprecision(2)
                << 100 * std::abs(fe[levels].sigma / fe[levels - 1].sigma - 1) << " %)\n\n"
                << "**VEM k = 2 at step-12's mesh (level 0, " << vem[0].dofs << " DoFs): " << std::setprecision(6)
                << vem[0].sigma << " MPa, " << std::setprecision(3) << 100 * (vem[0].sigma / reference - 1)
                << " % from the reference; FE_Q(2) on that mesh " << std::setprecision(6) << fe[0].sigma << " MPa, "
                << std::setprecision(3) << 100 * (fe[0].sigma / reference - 1) << " %**\n\n";

      // Saint-Venant: the half-width halved and doubled
      std::cout << "Saint-Venant: the Hertz half-width changed at the same force (FE_Q(2), fillet level " << levels
                << ", 1 global refinement)\n\n"
                << "| Hertz half-width | a (mm) | sigma_root (MPa) | change |\n"
                << "|---|---:|---:|---:|\n";
      for (const double f : {0.5, 1., 2.})
        {
          const Load   l     = make_load(gear, s, f);
          const double sigma = (f == 1. ? fe[levels].sigma : solve_fe(gear, l, levels).sigma);
          std::cout << "| " << f << " a | " << std::setprecision(4) << l.a << " | " << std::setprecision(6) << sigma
                    << " | " << std::setprecision(3) << sigma / fe[levels].sigma - 1 << " |\n";
        }

      if (hpstc)
        {
          const ISOResult iso = iso_root_stress(gear, load);
          std::cout << "\nISO 6336-3 method B (load at the HPSTC, b = 1 mm, F_t = " << std::setprecision(5) << iso.F_t
                    << " N/mm): s_Fn = " << iso.s_Fn << " mm, rho_F = " << iso.rho_F << " mm, h_Fe = " << iso.h_Fe
                    << " mm, alpha_Fen = " << iso.alpha_Fen * 180 / pi << " degrees, Y_F = " << iso.Y_F
                    << ", Y_S = " << iso.Y_S << ", sigma_F0 = " << iso.sigma_F0
                    << " MPa; FE_Q(2) reference / sigma_F0 = " << std::setprecision(3) << reference / iso.sigma_F0
                    << "\n"
                    << "(ISO's closed forms for the rack-generated fillet: s_Fn = " << std::setprecision(5)
                    << iso.iso_s_Fn[0] << " mm, rho_F = " << iso.iso_rho_F[0] << " mm unthinned; " << iso.iso_s_Fn[1]
                    << " mm, " << iso.iso_rho_F[1] << " mm with the backlash allowance as a profile shift)\n";
        }
    }
  catch (const std::exception &e)
    {
      std::cerr << "benchmark_gear_root_stress: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
