// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// Reference force-displacement curve of a rubber ring squeezed between two
// rigid, frictionless, flat plates, computed with plain deal.II (FE_Q(2),
// finite strain). It is the independent peer of dealvem's virtual element
// solution of the same problem and uses nothing of dealvem.
//
// The problem (plane strain, per unit thickness). A ring centred at the
// origin, inner radius 0.6, outer radius 1.0; by symmetry only the quarter
// x >= 0, y >= 0 is modelled, with u_x = 0 on the edge x = 0 and u_y = 0 on
// the edge y = 0. Compressible Neo-Hooke with E = 1, nu = 0.3 and the 3D
// Lame constants lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)):
//   psi = mu/2 (tr(F^T F) + 1 - 3) - mu ln J + lambda/2 (ln J)^2,
//   P   = mu F + (lambda ln J - mu) F^{-T}.
// The upper plate is the line y = 1 - d; it touches the outer surface
// without friction, so the only condition is y + u_y <= 1 - d there. The
// plate is lowered to d = 0.05, 0.10, ..., 0.50 (the ring squeezed to half
// its outer diameter). Reported per d: the plate force F(d) on the quarter
// model (the integral of the contact pressure over the outer surface),
// which is half the force between the two plates of the full ring.
//
// The method.
//  - Mesh: GridGenerator::quarter_hyper_shell with 4 cells along the arc
//    and 1 through the thickness, refined globally r times (4 2^r x 2^r
//    cells). The boundary ids are set here from the geometry (inner arc 0,
//    outer arc 1, x = 0: 2, y = 0: 3). deal.II 9.4 gives every cell and
//    face manifold id 0 with a SphericalManifold about the origin (set
//    again here explicitly): refinement is then exact in polar coordinates,
//    the arcs stay circles and the straight edges (rays) stay straight; this
//    is checked for every refined boundary vertex.
//  - Displacements FE_Q(2)^2, QGauss(3) in the cells, total Lagrangian, with
//    MappingQ(2) (isoparametric; evaluated once through MappingQCache). The
//    isoparametric mapping matters for the contact: with it, a face pressed
//    flat against the plate can be exactly flat; with MappingQ(3) its
//    deformed shape is cubic, the contact conditions of a fully pressed
//    face cannot all hold, and the Uzawa iterations stall (measured).
//  - Contact: at the contact points of each face of the outer arc
//    (reference positions X, weights w) the gap violation
//    g = X_y + u_y - (1 - d) (> 0 means penetration) and the augmented
//    pressure p = max(0, lambda_q + eps g), with a multiplier lambda_q per
//    point and the penalty eps = c E / h_face (c = --penalty, h_face the
//    length of the face). With lambda_q fixed, the discrete problem minimises
//      Pi(u) = int psi dV + sum_q w_q max(0, lambda_q + eps g_q)^2 / (2 eps),
//    whose gradient adds sum_q w_q p_q phi_{i,y} to the internal forces and
//    whose Hessian adds eps w_q phi_{i,y} phi_{j,y} where lambda_q + eps g_q
//    > 0 (the consistent tangent). The contact points are the three
//    Gauss-Lobatto points (the nodes) of each face by default, or two Gauss
//    points (--contact-points gauss2): both give as many conditions along
//    the arc as there are u_y DoFs on it. More points per face (QGauss(3),
//    QGauss(4)) over-constrain the arc (4 conditions on the 2 new DoFs of a
//    face): the multipliers are not unique, and where the active set is
//    slightly inconsistent at the contact edge the Uzawa iterations drift
//    for hundreds of iterations at a penetration of 1e-8 (measured), so the
//    tolerances below are not reached.
//  - Newton's method: UMFPACK for each update; a backtracking line search
//    that rejects states with J <= 0 and accepts a step that decreases Pi
//    (Armijo) or else the residual norm. In the Uzawa iterations the
//    factorisation of the previous tangent is reused while the residual
//    falls by at least 10 per iteration (a chord method; the converged state
//    is the same). Converged when |r| <= 1e-10 max(F, 1e-3) on the free DoFs.
//  - Loading: the plate moves in sub-steps (default 0.025, halved when a
//    step fails), each starting from a linear extrapolation of the last two
//    states; after every sub-step the multipliers take the pressures
//    (lambda_q <- p_q). At each reported d, Uzawa iterations follow (solve,
//    lambda_q <- p_q) until the largest penetration is below 1e-9 and the
//    force changes by less than 1e-10 relative; the multipliers are then the
//    contact pressures and the contact condition holds to 1e-9 at the
//    contact points. (The material is elastic and the plate frictionless,
//    so the result does not depend on the path, only on d.)
//  - The smooth branch and its end. Towards d = 0.5 the inner surface at
//    the side of the ring (the hinge at (0.6, 0)) is compressed to a
//    tangential stretch of about 0.54 at d = 0.45 and below 0.5 beyond
//    (Biot's surface instability of a half-space of this material in plane
//    strain sets in at a stretch of 0.509). On fine meshes the smooth,
//    symmetric solution ends there at a limit point (the tangent stays
//    positive definite up to it; measured up to r = 5): beyond it no
//    sub-step converges, or Newton jumps to a folded state in which the
//    inner surface next to the symmetry line y = 0 passes through that line
//    (in the full ring: through its mirror image, i.e. a crease with
//    self-contact, which this model does not have) and the force drops by
//    20-40 %. Measured (defaults): the smooth branch ends at d = 0.498
//    (r = 3), 0.480 (r = 4), 0.469 (r = 5), 0.463 (r = 6), moving down with
//    refinement (towards about 0.455 if the trend continues), so there is no
//    reference value at d = 0.5, and d = 0.45 lies close to the end of the
//    smooth branch. The path of a mesh ends when no sub-step down to 1/16 of
//    the nominal one converges, when a boundary point has crossed a
//    symmetry line, or when the force has decreased; the reported positions
//    beyond are marked "not reached", and there is no reference value (nan)
//    where the finest mesh has none.
//  - Checks printed per d: the force as the integral of the pressure,
//    F = sum_q w_q p_q, and as the vertical reaction on the symmetry edge
//    y = 0 (the sum of the internal-force residual over the constrained u_y
//    DoFs; by the partition of unity the two agree up to the Newton
//    tolerance); the contact half-width (the largest deformed x of a contact
//    point with p > 0: only as fine as the contact points); the smallest J
//    at the cell quadrature points; the deformed inner surface: the height
//    of its top point, its smallest deformed y on the upper half and x on
//    the lower half (distances to the symmetry lines, i.e. half the gap to
//    the mirror image), the number of boundary points across a symmetry
//    line, its smallest tangential stretch; and the number of negative
//    eigenvalues of the tangent (0: a stable equilibrium), from an LDL^T
//    factorisation in profile storage (Sylvester's law of inertia; DoFs in
//    Cuthill-McKee order), on meshes up to --inertia-max-refinement.
//  - Accuracy: F(d) per mesh, the relative differences of successive
//    meshes and the observed orders. Where the convergence is monotone at a
//    stable rate (the orders of the last two triples of meshes both in
//    [1, 6] and within 1 of each other), the Richardson extrapolation from
//    the three finest meshes, with the error estimate max(|F_extrapolated -
//    F_finest|, |F_extrapolated - extrapolation from the previous triple|).
//    Otherwise (the usual case: the contact edge crosses element boundaries
//    as the mesh is refined, so the differences change sign) the finest
//    value with the error estimate max(|F_r - F_{r-1}|, |F_{r-1} -
//    F_{r-2}| / 2, |F_{r-2} - F_{r-3}| / 4) for the finest mesh r (as far as
//    there are meshes): if every refinement at least halves the error, each
//    term bounds the error of F_r; the largest is taken because a single
//    difference can be small by chance (seen on the coarse meshes).
//  - Measured (defaults; Debian 12, deal.II 9.4.1, Release, one core of a
//    VM shared with other work): r = 2..5 in about 2.5 minutes (r = 5 about
//    2 minutes of CPU), r = 6 about 15 minutes. F and the reaction agree to
//    1e-10 relative. For d <= 0.45 the forces of r = 6 differ from those of
//    r = 5 by at most 4e-5 relative, and with --contact-points gauss2 the
//    r = 5 forces lie within 3e-5 of the default ones.
//
// Options (all optional):
//   --min-refinements N       coarsest mesh (default 2: 16 x 4 cells)
//   --max-refinements M       finest mesh (default 5: 128 x 32 cells)
//   --contact-points rule     lobatto3 (default) or gauss2 (or gaussN,
//                             lobattoN, see above)
//   --penalty c               penalty factor, eps = c E / h_face (default 1000)
//   --substeps n              sub-steps per 0.05 of plate travel (default 2)
//   --mapping-degree k        MappingQ degree (default 2, see above)
//   --inertia-max-refinement R  count the negative eigenvalues of the
//                             tangent at each reported d on meshes up to R
//                             (default 5)
//   --verbose 1               Newton, Uzawa and sub-step history on stderr
// Three meshes or more give the error estimates.
//
// Output (stdout): per mesh a table of F, the reaction, their relative
// difference, the Uzawa and Newton iterations, the largest penetration, the
// contact half-width and the checks, and the run time; then the table of F
// per mesh, the differences and orders, the reference values; last the
// machine-readable block
//   # reference: d F_extrapolated error_estimate
//   0.05 <F> <err>
//   ...
//   0.50 <F> <err>
// (nan nan where the finest mesh has no smooth solution).
//
// Building: the top-level CMakeLists.txt globs benchmarks/*/*.cc, so dealvem's
// build has the target benchmark_ring_reference (it links dealvem, which this
// file does not use). On its own: a CMakeLists.txt with
//   find_package(deal.II 9.4 REQUIRED)
//   deal_ii_initialize_cached_variables()
//   project(ring_reference CXX)
//   add_executable(ring_reference <path>/ring_reference.cc)
//   deal_ii_setup_target(ring_reference)
// configured with -DCMAKE_BUILD_TYPE=Release.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace RingReference
{
  using namespace dealii;

  // ------------------------------------------------------------ the data
  const double r_inner  = 0.6;
  const double r_outer  = 1.0;
  const double young    = 1.0;
  const double poisson  = 0.3;
  const double lambda_L = young * poisson / ((1. + poisson) * (1. - 2. * poisson));
  const double mu_L     = young / (2. * (1. + poisson));

  // the plate travels reported
  const unsigned int n_reports   = 10;
  const double       report_step = 0.05;

  // stopping rules of the Uzawa loop
  const double max_penetration_tolerance = 1e-9;
  const double force_change_tolerance    = 1e-10;

  // boundary indicators (assigned by geometry below)
  const types::boundary_id id_inner = 0, id_outer = 1, id_x0 = 2, id_y0 = 3;

  struct Options
  {
    unsigned int min_refinements = 2;
    unsigned int max_refinements = 5;
    unsigned int mapping_degree  = 2;
    unsigned int substeps        = 2;
    unsigned int inertia_max     = 5; // the inertia of the tangent up to this refinement
    std::string  contact_rule    = "lobatto3";
    double       penalty_factor  = 1e3;
    bool         verbose         = false;
  };

  // The contact points of a face of the outer arc: gaussN (N Gauss points)
  // or lobattoN (N Gauss-Lobatto points, for N = 3 the nodes of the face).
  Quadrature<1>
  contact_rule(const std::string &name)
  {
    if (name.rfind("gauss", 0) == 0)
      return QGauss<1>(std::stoul(name.substr(5)));
    if (name.rfind("lobatto", 0) == 0)
      return QGaussLobatto<1>(std::stoul(name.substr(7)));
    AssertThrow(false, ExcMessage("--contact-points: gaussN or lobattoN, not " + name));
    return QGauss<1>(1);
  }

  // ------------------------------------------------ Neo-Hooke at one point
  // The state at one quadrature point from the displacement gradient.
  class NeoHookePoint
  {
  public:
    explicit NeoHookePoint(const Tensor<2, 2> &grad_u)
    {
      F = grad_u;
      F[0][0] += 1.;
      F[1][1] += 1.;
      J = determinant(F);
      if (J > 0)
        {
          log_J   = std::log(J);
          F_inv_T = transpose(invert(F));
          coeff   = lambda_L * log_J - mu_L;
        }
    }

    bool
    admissible() const
    {
      return J > 0;
    }

    // psi with the out-of-plane stretch 1
    double
    energy() const
    {
      return 0.5 * mu_L * (scalar_product(F, F) - 2.) - mu_L * log_J + 0.5 * lambda_L * log_J * log_J;
    }

    Tensor<2, 2>
    stress() const
    {
      return mu_L * F + coeff * F_inv_T;
    }

    // dP/dF applied to a direction H:
    //   mu H + lambda (F^{-T} : H) F^{-T} - (lambda ln J - mu) F^{-T} H^T F^{-T}
    Tensor<2, 2>
    tangent(const Tensor<2, 2> &H) const
    {
      Tensor<2, 2> result = mu_L * H;
      result += (lambda_L * scalar_product(F_inv_T, H)) * F_inv_T;
      result -= coeff * (F_inv_T * transpose(H) * F_inv_T);
      return result;
    }

    double J = 0;

  private:
    Tensor<2, 2> F, F_inv_T;
    double       log_J = 0, coeff = 0;
  };

  // ------------------------------------------------------------ results
  struct LoadRecord
  {
    double       d                 = 0;
    double       force             = 0; // sum_q w_q p_q
    double       reaction          = 0; // residual summed over the u_y DoFs on y = 0
    double       max_penetration   = 0;
    double       half_width        = 0;
    double       min_J             = 0;
    double       inner_top_y       = 0;    // deformed y of the inner top point
    double       inner_min_y       = 0;    // smallest deformed y, upper half of the inner arc
    double       inner_min_x       = 0;    // smallest deformed x, lower half of the inner arc
    unsigned int n_crossing        = 0;    // boundary points across a symmetry line
    double       inner_min_stretch = 0;    // smallest tangential stretch of the inner surface
    int          n_negative        = -1;   // negative eigenvalues of the tangent (-1: not computed)
    bool         valid             = true; // on the smooth branch
    unsigned int uzawa_iterations  = 0;
    unsigned int newton_total      = 0; // Newton iterations spent in the Uzawa loop
  };

  struct NewtonFailure : public std::runtime_error
  {
    explicit NewtonFailure(const std::string &what)
      : std::runtime_error(what)
    {
    }
  };

  // The contact data of one face of the outer arc: the multipliers and the
  // penalty of its contact points.
  struct ContactFace
  {
    DoFHandler<2>::active_cell_iterator cell;
    unsigned int                        face_no = 0;
    double                              penalty = 0;
    std::vector<double>                 multiplier;
  };

  // g = y + u_y - (1 - d) at a contact point: > 0 is a penetration
  double
  plate_gap(const Point<2> &X, const Tensor<1, 2> &u, const double d)
  {
    return X[1] + u[1] - (r_outer - d);
  }

  struct ContactSummary
  {
    double force           = 0; // the plate force, sum_q w_q p_q
    double max_penetration = 0; // the largest g over all contact points
    double half_width      = 0; // the largest deformed x of a plate point with p > 0
  };

  // ------------------------------------------------------------ the solver
  class RingProblem
  {
  public:
    RingProblem(const unsigned int refinements, const Options &options);

    std::vector<LoadRecord>
    run();

    unsigned int
    n_cells() const
    {
      return tria.n_active_cells();
    }
    types::global_dof_index
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }
    unsigned int
    newton_iterations() const
    {
      return total_newton;
    }
    unsigned int
    n_substeps() const
    {
      return total_substeps;
    }
    // the last plate position of the smooth branch if it was lost before
    // d = 0.5, otherwise -1
    double
    end_of_branch() const
    {
      return branch_end;
    }

  private:
    void
    make_mesh(const unsigned int refinements);
    void
    setup();
    double
    assemble(const Vector<double> &u, const double d, const bool with_tangent);
    double
    energy(const Vector<double> &u, const double d, bool &admissible) const;
    unsigned int
    newton(const double d, const bool chord = false);
    unsigned int
    crossings() const;
    // the pressures at the current solution, optionally stored as the
    // multipliers
    ContactSummary
    contact_state(const double d, const bool update_multipliers);
    void
    geometry_checks(LoadRecord &record) const;
    unsigned int
    negative_eigenvalues() const;
    void
    log(const std::string &text) const
    {
      if (options.verbose)
        std::cerr << text << std::endl;
    }

    const Options                        options;
    const unsigned int                   refinements;
    Triangulation<2>                     tria;
    const FESystem<2>                    fe;
    MappingQCache<2>                     mapping; // MappingQ(k), its support points computed once
    DoFHandler<2>                        dof_handler;
    const QGauss<2>                      cell_quadrature;
    const Quadrature<1>                  face_quadrature;  // the contact points of a face
    const QGauss<1>                      check_quadrature; // the state checks on the boundary
    AffineConstraints<double>            constraints;
    std::vector<types::global_dof_index> support_y_dofs; // u_y on y = 0
    SparsityPattern                      sparsity;
    SparseMatrix<double>                 tangent;
    Vector<double>                       solution, residual;
    std::vector<ContactFace>             contact_faces;
    SparseDirectUMFPACK                  direct; // the factorised tangent of the last Newton iteration
    bool                                 factorization_valid = false;
    unsigned int                         total_newton = 0, total_substeps = 0;
    double                               branch_end = -1; // the last d of the smooth branch when it was lost
  };

  RingProblem::RingProblem(const unsigned int refinements, const Options &options)
    : options(options)
    , refinements(refinements)
    , fe(FE_Q<2>(2), 2)
    , mapping(options.mapping_degree)
    , dof_handler(tria)
    , cell_quadrature(3)
    , face_quadrature(contact_rule(options.contact_rule))
    , check_quadrature(4)
  {
    make_mesh(refinements);
    mapping.initialize(MappingQ<2>(options.mapping_degree), tria);
    setup();
  }

  void
  RingProblem::make_mesh(const unsigned int refinements)
  {
    GridGenerator::quarter_hyper_shell(tria, Point<2>(), r_inner, r_outer, 4);
    // deal.II 9.4 sets manifold id 0 on all cells and faces with a
    // SphericalManifold about the origin; set it again explicitly so that
    // this program does not depend on that detail.
    tria.set_all_manifold_ids(0);
    tria.set_manifold(0, SphericalManifold<2>(Point<2>()));
    // boundary ids by geometry: inner arc, outer arc, x = 0, y = 0
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const Point<2>     a = cell->face(f)->vertex(0), b = cell->face(f)->vertex(1);
            types::boundary_id id;
            if (std::abs(a[0]) < 1e-12 && std::abs(b[0]) < 1e-12)
              id = id_x0;
            else if (std::abs(a[1]) < 1e-12 && std::abs(b[1]) < 1e-12)
              id = id_y0;
            else if (std::abs(a.norm() - r_outer) < 1e-12 && std::abs(b.norm() - r_outer) < 1e-12)
              id = id_outer;
            else if (std::abs(a.norm() - r_inner) < 1e-12 && std::abs(b.norm() - r_inner) < 1e-12)
              id = id_inner;
            else
              AssertThrow(false, ExcMessage("a boundary face of the quarter ring that is none of its four sides"));
            cell->face(f)->set_boundary_id(id);
          }
    tria.refine_global(refinements);
    // the refined boundary vertices must lie on their sides
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          for (unsigned int v = 0; v < 2; ++v)
            {
              const Point<2> p   = cell->face(f)->vertex(v);
              const auto     id  = cell->face(f)->boundary_id();
              const double   err = (id == id_x0      ? std::abs(p[0])
                                    : id == id_y0    ? std::abs(p[1])
                                    : id == id_outer ? std::abs(p.norm() - r_outer)
                                                     : std::abs(p.norm() - r_inner));
              AssertThrow(err < 1e-12, ExcMessage("a refined boundary vertex is off its side"));
            }
  }

  void
  RingProblem::setup()
  {
    dof_handler.distribute_dofs(fe);
    // a small profile for the LDL^T factorisation of negative_eigenvalues()
    DoFRenumbering::Cuthill_McKee(dof_handler);
    constraints.clear();
    const FEValuesExtractors::Scalar ux(0), uy(1);
    VectorTools::interpolate_boundary_values(mapping, dof_handler, id_x0, Functions::ZeroFunction<2>(2), constraints,
                                             fe.component_mask(ux));
    VectorTools::interpolate_boundary_values(mapping, dof_handler, id_y0, Functions::ZeroFunction<2>(2), constraints,
                                             fe.component_mask(uy));
    constraints.close();
    const IndexSet support = DoFTools::extract_boundary_dofs(dof_handler, fe.component_mask(uy), {id_y0});
    for (const auto i : support)
      support_y_dofs.push_back(i);

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    sparsity.copy_from(dsp);
    tangent.reinit(sparsity);
    solution.reinit(dof_handler.n_dofs());
    residual.reinit(dof_handler.n_dofs());

    // the contact points on each face of the outer arc
    FEFaceValues<2> face_values(mapping, fe, face_quadrature, update_JxW_values);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == id_outer)
          {
            face_values.reinit(cell, f);
            double length = 0;
            for (unsigned int q = 0; q < face_quadrature.size(); ++q)
              length += face_values.JxW(q);
            ContactFace c;
            c.cell    = cell;
            c.face_no = f;
            c.penalty = options.penalty_factor * young / length;
            c.multiplier.assign(face_quadrature.size(), 0.);
            contact_faces.push_back(c);
          }
  }

  // The gradient of Pi (the internal plus contact forces) at u into
  // `residual` (all DoFs, the constrained ones included: they hold the
  // reactions) and, optionally, its Hessian into `tangent` (condensed).
  // Returns the contact force sum_q w_q p_q.
  double
  RingProblem::assemble(const Vector<double> &u, const double d, const bool with_tangent)
  {
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n_i = fe.n_dofs_per_cell();
    FEValues<2>                          values(mapping, fe, cell_quadrature, update_gradients | update_JxW_values);
    FEFaceValues<2>                      face_values(mapping, fe, face_quadrature,
                                                     update_values | update_quadrature_points | update_JxW_values);
    std::vector<Tensor<2, 2>>            grad_u(cell_quadrature.size());
    std::vector<Tensor<1, 2>>            u_face(face_quadrature.size());
    std::vector<Tensor<2, 2>>            grad_phi(n_i);
    std::vector<double>                  phi_y(n_i);
    FullMatrix<double>                   K_local(n_i, n_i);
    Vector<double>                       r_local(n_i);
    std::vector<types::global_dof_index> dofs(n_i);

    residual = 0;
    if (with_tangent)
      tangent = 0;

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        values.reinit(cell);
        values[displacement].get_function_gradients(u, grad_u);
        K_local = 0;
        r_local = 0;
        for (unsigned int q = 0; q < cell_quadrature.size(); ++q)
          {
            const NeoHookePoint point(grad_u[q]);
            AssertThrow(point.admissible(), ExcMessage("assembly at a state with J <= 0"));
            const Tensor<2, 2> P  = point.stress();
            const double       dV = values.JxW(q);
            for (unsigned int i = 0; i < n_i; ++i)
              {
                grad_phi[i] = values[displacement].gradient(i, q);
                r_local(i) += scalar_product(P, grad_phi[i]) * dV;
              }
            if (with_tangent)
              for (unsigned int j = 0; j < n_i; ++j)
                {
                  const Tensor<2, 2> A_j = point.tangent(grad_phi[j]);
                  for (unsigned int i = j; i < n_i; ++i)
                    K_local(i, j) += scalar_product(grad_phi[i], A_j) * dV;
                }
          }
        if (with_tangent)
          for (unsigned int j = 0; j < n_i; ++j)
            for (unsigned int i = j + 1; i < n_i; ++i)
              K_local(j, i) = K_local(i, j);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n_i; ++i)
          residual(dofs[i]) += r_local(i);
        if (with_tangent)
          constraints.distribute_local_to_global(K_local, dofs, tangent);
      }

    double force = 0;
    for (const auto &c : contact_faces)
      {
        face_values.reinit(c.cell, c.face_no);
        face_values[displacement].get_function_values(u, u_face);
        K_local         = 0;
        r_local         = 0;
        bool any_active = false;
        for (unsigned int q = 0; q < face_quadrature.size(); ++q)
          {
            const double gap   = plate_gap(face_values.quadrature_point(q), u_face[q], d);
            const double trial = c.multiplier[q] + c.penalty * gap;
            if (trial <= 0)
              continue;
            any_active     = true;
            const double w = face_values.JxW(q);
            force += w * trial;
            for (unsigned int i = 0; i < n_i; ++i)
              phi_y[i] = face_values[displacement].value(i, q)[1];
            for (unsigned int i = 0; i < n_i; ++i)
              {
                r_local(i) += trial * phi_y[i] * w;
                if (with_tangent)
                  for (unsigned int j = 0; j < n_i; ++j)
                    K_local(i, j) += c.penalty * phi_y[i] * phi_y[j] * w;
              }
          }
        if (!any_active)
          continue;
        c.cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n_i; ++i)
          residual(dofs[i]) += r_local(i);
        if (with_tangent)
          constraints.distribute_local_to_global(K_local, dofs, tangent);
      }
    return force;
  }

  // Pi(u); admissible = false (and the value meaningless) if J <= 0 somewhere.
  double
  RingProblem::energy(const Vector<double> &u, const double d, bool &admissible) const
  {
    const FEValuesExtractors::Vector displacement(0);
    FEValues<2>                      values(mapping, fe, cell_quadrature, update_gradients | update_JxW_values);
    FEFaceValues<2>                  face_values(mapping, fe, face_quadrature,
                                                 update_values | update_quadrature_points | update_JxW_values);
    std::vector<Tensor<2, 2>>        grad_u(cell_quadrature.size());
    std::vector<Tensor<1, 2>>        u_face(face_quadrature.size());
    double                           pi = 0;
    admissible                          = true;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        values.reinit(cell);
        values[displacement].get_function_gradients(u, grad_u);
        for (unsigned int q = 0; q < cell_quadrature.size(); ++q)
          {
            const NeoHookePoint point(grad_u[q]);
            if (!point.admissible())
              {
                admissible = false;
                return 0;
              }
            pi += point.energy() * values.JxW(q);
          }
      }
    for (const auto &c : contact_faces)
      {
        face_values.reinit(c.cell, c.face_no);
        face_values[displacement].get_function_values(u, u_face);
        for (unsigned int q = 0; q < face_quadrature.size(); ++q)
          {
            const double gap   = plate_gap(face_values.quadrature_point(q), u_face[q], d);
            const double trial = std::max(0., c.multiplier[q] + c.penalty * gap);
            pi += trial * trial / (2. * c.penalty) * face_values.JxW(q);
          }
      }
    return pi;
  }

  // Newton's method for grad Pi = 0 at plate position d, the multipliers
  // fixed, from the current solution. Throws NewtonFailure.
  unsigned int
  RingProblem::newton(const double d, const bool chord)
  {
    // With chord = true the iterations start with the factorisation of the
    // last tangent (the Uzawa iterations change the state little) and switch
    // to the current tangent as soon as the residual falls by less than a
    // factor 10 per iteration or a step has to be shortened.
    bool           use_old       = chord && factorization_valid;
    double         last_norm     = std::numeric_limits<double>::max();
    unsigned int   n_short_steps = 0;
    Vector<double> update(dof_handler.n_dofs()), trial(dof_handler.n_dofs()), free_residual;
    bool           admissible = true;
    double         pi         = energy(solution, d, admissible);
    if (!admissible)
      throw NewtonFailure("the initial state is inverted");
    double last_update = std::numeric_limits<double>::max();
    for (unsigned int it = 0;; ++it)
      {
        const double force = assemble(solution, d, !use_old);
        free_residual      = residual;
        constraints.set_zero(free_residual);
        const double norm = free_residual.l2_norm();
        if (use_old && norm > 0.1 * last_norm)
          {
            use_old = false;
            assemble(solution, d, true);
          }
        last_norm              = norm;
        const double tolerance = 1e-10 * std::max(force, 1e-3);
        {
          std::ostringstream s;
          s << "    Newton " << it << (use_old ? " (chord)" : "") << ": |r| = " << std::scientific
            << std::setprecision(3) << norm << " (tol " << tolerance << "), force " << std::setprecision(12) << force;
          log(s.str());
        }
        // converged, or the last update was round-off and the residual small
        if (norm <= tolerance || (norm <= 1e3 * tolerance && last_update <= 1e-14))
          {
            total_newton += it;
            return it;
          }
        if (it >= 15)
          throw NewtonFailure("Newton did not converge in 15 iterations");
        if (n_short_steps >= 4)
          throw NewtonFailure("four steps in a row shortened to 1/16 or less");

        free_residual *= -1.;
        if (!use_old)
          {
            direct.initialize(tangent);
            factorization_valid = true;
          }
        direct.vmult(update, free_residual);
        constraints.distribute(update);
        // The slope of Pi along the update (negative for a descent direction).
        // A step is taken if it keeps J > 0 and decreases Pi (Armijo) or, where
        // that fails, if it decreases the residual norm (the Newton update is
        // a descent direction of |r|^2).
        const double slope       = -(free_residual * update);
        double       alpha       = 1;
        bool         by_residual = false, found = false;
        for (unsigned int h = 0; h < 30; ++h, alpha *= 0.5)
          {
            trial = solution;
            trial.add(alpha, update);
            const double pi_trial = energy(trial, d, admissible);
            if (!admissible)
              continue;
            if (slope < 0 && pi_trial <= pi + 1e-4 * alpha * slope + 1e-13 * std::abs(pi))
              {
                pi    = pi_trial;
                found = true;
                break;
              }
            assemble(trial, d, false);
            constraints.set_zero(residual);
            if (residual.l2_norm() <= (1. - 1e-4 * alpha) * norm)
              {
                pi          = pi_trial;
                by_residual = found = true;
                break;
              }
          }
        if (!found)
          throw NewtonFailure("the line search failed");
        if (alpha < 1)
          use_old = false;
        n_short_steps = (alpha <= 1. / 16 ? n_short_steps + 1 : 0);
        if (alpha < 1 || by_residual)
          {
            std::ostringstream s;
            s << "    line search: alpha = " << alpha << (by_residual ? " (residual decrease)" : "") << ", slope "
              << slope << ", |r| |du| " << norm * update.l2_norm();
            log(s.str());
          }
        last_update = alpha * update.linfty_norm();
        solution    = trial;
      }
  }

  ContactSummary
  RingProblem::contact_state(const double d, const bool update_multipliers)
  {
    const FEValuesExtractors::Vector displacement(0);
    FEFaceValues<2>                  face_values(mapping, fe, face_quadrature,
                                                 update_values | update_quadrature_points | update_JxW_values);
    std::vector<Tensor<1, 2>>        u_face(face_quadrature.size());
    ContactSummary                   sum;
    for (auto &c : contact_faces)
      {
        face_values.reinit(c.cell, c.face_no);
        face_values[displacement].get_function_values(solution, u_face);
        for (unsigned int q = 0; q < face_quadrature.size(); ++q)
          {
            const Point<2> &X   = face_values.quadrature_point(q);
            const double    gap = plate_gap(X, u_face[q], d);
            const double    p   = std::max(0., c.multiplier[q] + c.penalty * gap);
            sum.max_penetration = std::max(sum.max_penetration, gap);
            sum.force += p * face_values.JxW(q);
            if (p > 0)
              sum.half_width = std::max(sum.half_width, X[0] + u_face[q][0]);
            if (update_multipliers)
              c.multiplier[q] = p;
          }
      }
    return sum;
  }

  // The state checks at a converged load: the smallest J at the cell
  // quadrature points; the deformed inner surface: the height of its top
  // point (reference (0, 0.6)) above the symmetry line y = 0, the smallest
  // deformed y on its upper half (reference angle >= 45 degrees) and the
  // smallest deformed x on its lower half (where a self-contact of the full
  // ring would show: the inner surface reaching its mirror image), its
  // smallest tangential stretch; and the number of boundary points that
  // crossed a symmetry line.
  void
  RingProblem::geometry_checks(LoadRecord &record) const
  {
    const FEValuesExtractors::Vector displacement(0);
    FEValues<2>                      values(mapping, fe, cell_quadrature, update_gradients);
    FEFaceValues<2>                  face_values(mapping, fe, check_quadrature,
                                                 update_values | update_gradients | update_quadrature_points | update_normal_vectors);
    std::vector<Tensor<2, 2>>        grad_u(cell_quadrature.size()), grad_u_face(check_quadrature.size());
    std::vector<Tensor<1, 2>>        u_face(check_quadrature.size());
    record.min_J             = std::numeric_limits<double>::max();
    record.inner_min_stretch = std::numeric_limits<double>::max();
    record.inner_min_x = record.inner_min_y = std::numeric_limits<double>::max();
    record.n_crossing                       = crossings();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        values.reinit(cell);
        values[displacement].get_function_gradients(solution, grad_u);
        for (const auto &g : grad_u)
          record.min_J = std::min(record.min_J, NeoHookePoint(g).J);
        for (const auto v : cell->vertex_indices())
          if (cell->vertex(v).distance(Point<2>(0, r_inner)) < 1e-12)
            record.inner_top_y = r_inner + solution(cell->vertex_dof_index(v, 1));
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == id_inner)
            {
              face_values.reinit(cell, f);
              face_values[displacement].get_function_values(solution, u_face);
              face_values[displacement].get_function_gradients(solution, grad_u_face);
              for (unsigned int q = 0; q < check_quadrature.size(); ++q)
                {
                  const Point<2>    &X = face_values.quadrature_point(q);
                  const Tensor<1, 2> N = face_values.normal_vector(q);
                  const Tensor<1, 2> T({-N[1], N[0]});
                  record.inner_min_stretch = std::min(record.inner_min_stretch, (T + grad_u_face[q] * T).norm());
                  const double x = X[0] + u_face[q][0], y = X[1] + u_face[q][1];
                  if (X[1] >= X[0])
                    record.inner_min_y = std::min(record.inner_min_y, y);
                  else
                    record.inner_min_x = std::min(record.inner_min_x, x);
                }
            }
      }
  }

  // The number of negative eigenvalues of the (condensed, symmetric) tangent,
  // by Sylvester's law of inertia from its LDL^T factorisation without
  // pivoting in profile (skyline) storage: 0 means the equilibrium is a
  // strict local minimum of Pi (stable), > 0 that it is a saddle point (the
  // principal branch past a bifurcation). Without pivoting the factorisation
  // is not backward stable for indefinite matrices, but the count is reliable
  // unless a pivot comes out near zero (then the state is at a bifurcation
  // anyway).
  unsigned int
  RingProblem::negative_eigenvalues() const
  {
    const unsigned int        n = tangent.m();
    std::vector<unsigned int> first(n);
    std::vector<std::size_t>  start(n + 1, 0);
    for (unsigned int i = 0; i < n; ++i)
      {
        first[i] = i;
        for (auto e = sparsity.begin(i); e != sparsity.end(i); ++e)
          first[i] = std::min<unsigned int>(first[i], e->column());
        start[i + 1] = start[i] + (i - first[i] + 1);
      }
    std::vector<double> L(start[n], 0.);
    for (unsigned int i = 0; i < n; ++i)
      for (auto e = tangent.begin(i); e != tangent.end(i); ++e)
        if (e->column() <= i)
          L[start[i] + e->column() - first[i]] = e->value();
    std::vector<double> D(n);
    unsigned int        negative = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        double *const      row = &L[start[i]];
        const unsigned int fi  = first[i];
        // row[k - fi] becomes L_ik D_k for k < i, column by column
        for (unsigned int j = fi; j < i; ++j)
          {
            const double *const row_j = &L[start[j]];
            const unsigned int  fj    = first[j];
            double              s     = row[j - fi];
            for (unsigned int k = std::max(fi, fj); k < j; ++k)
              s -= row[k - fi] * row_j[k - fj];
            row[j - fi] = s;
          }
        double d = row[i - fi];
        for (unsigned int k = fi; k < i; ++k)
          {
            const double l = row[k - fi] / D[k];
            d -= l * row[k - fi];
            row[k - fi] = l;
          }
        D[i] = d;
        AssertThrow(d != 0, ExcMessage("a zero pivot in the inertia count"));
        if (d < 0)
          ++negative;
      }
    return negative;
  }

  // The number of boundary points (QGauss(4) on every boundary face) whose
  // deformed position lies across one of the symmetry lines x = 0, y = 0: in
  // the full ring the surface would penetrate its mirror image there.
  unsigned int
  RingProblem::crossings() const
  {
    const FEValuesExtractors::Vector displacement(0);
    FEFaceValues<2>           face_values(mapping, fe, check_quadrature, update_values | update_quadrature_points);
    std::vector<Tensor<1, 2>> u_face(check_quadrature.size());
    unsigned int              n         = 0;
    const double              tolerance = 1e-12;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            face_values.reinit(cell, f);
            face_values[displacement].get_function_values(solution, u_face);
            for (unsigned int q = 0; q < check_quadrature.size(); ++q)
              {
                const Point<2> &X = face_values.quadrature_point(q);
                if (X[0] + u_face[q][0] < -tolerance || X[1] + u_face[q][1] < -tolerance)
                  ++n;
              }
          }
    return n;
  }

  // The load path. Returns one record per reported d; the records from the
  // point where the smooth (symmetric, unfolded) branch is lost on are marked
  // invalid: either no sub-step, however small, converges any more (a limit
  // point), or the converged state has folded (a boundary point crossed a
  // symmetry line) or carries less force than the previous one (it snapped
  // past a limit point).
  std::vector<LoadRecord>
  RingProblem::run()
  {
    std::vector<LoadRecord>          records;
    Vector<double>                   previous(dof_handler.n_dofs()), saved(dof_handler.n_dofs());
    std::vector<std::vector<double>> saved_multipliers(contact_faces.size());
    double                           d = 0, last_increment = 0, last_force = 0;
    const double                     nominal = report_step / options.substeps;
    bool                             lost    = false;

    const auto restore = [&]() {
      solution = saved;
      for (unsigned int f = 0; f < contact_faces.size(); ++f)
        contact_faces[f].multiplier = saved_multipliers[f];
    };

    for (unsigned int k = 1; k <= n_reports && !lost; ++k)
      {
        const double target = k * report_step;
        double       h      = nominal;
        // sub-steps up to the reported plate position
        while (d < target - 1e-14)
          {
            const double d_new = std::min(d + h, target);
            saved              = solution;
            for (unsigned int f = 0; f < contact_faces.size(); ++f)
              saved_multipliers[f] = contact_faces[f].multiplier;
            // predictor: linear extrapolation of the last two states
            if (last_increment > 0)
              {
                Vector<double> predicted = solution;
                predicted.add((d_new - d) / last_increment, solution);
                predicted.add(-(d_new - d) / last_increment, previous);
                bool ok = true;
                energy(predicted, d_new, ok);
                if (ok)
                  solution = predicted;
              }
            bool converged = true;
            try
              {
                log("  d = " + std::to_string(d_new));
                newton(d_new);
              }
            catch (const NewtonFailure &failure)
              {
                log(std::string("  sub-step failed (") + failure.what() + ")");
                converged = false;
              }
            double force = 0;
            if (converged)
              {
                force                      = contact_state(d_new, false).force;
                const unsigned int crossed = crossings();
                if (options.verbose)
                  {
                    std::ostringstream s;
                    s << "  sub-step d = " << d_new << ": F = " << std::setprecision(10) << force
                      << ", crossing points " << crossed;
                    if (refinements <= options.inertia_max)
                      {
                        assemble(solution, d_new, true);
                        s << ", negative eigenvalues " << negative_eigenvalues();
                      }
                    log(s.str());
                  }
                if (crossed > 0 || force < last_force)
                  {
                    log("  the state has folded or snapped: the smooth branch is lost");
                    restore();
                    lost = true;
                    break;
                  }
              }
            else
              {
                restore();
                h /= 2;
                if (h < nominal / 16)
                  {
                    log("  no sub-step converges: the smooth branch ends");
                    lost = true;
                    break;
                  }
                continue;
              }
            ++total_substeps;
            previous       = saved;
            last_increment = d_new - d;
            d              = d_new;
            last_force     = force;
            if (d < target - 1e-14)
              // not a reported position: the pressures become the multipliers
              contact_state(d, true);
          }
        if (lost)
          break;
        d = target;

        // Uzawa iterations at the reported position
        LoadRecord record;
        record.d                         = target;
        double             uzawa_force   = -1;
        const unsigned int newton_before = total_newton;
        try
          {
            for (unsigned int it = 1;; ++it)
              {
                AssertThrow(it <= 500, ExcMessage("the Uzawa iterations did not converge"));
                const ContactSummary state       = contact_state(d, false);
                const double         force       = state.force;
                const double         penetration = state.max_penetration;
                {
                  std::ostringstream s;
                  s << "  Uzawa " << it << ": force " << std::setprecision(14) << force << ", penetration "
                    << std::scientific << std::setprecision(3) << penetration;
                  log(s.str());
                }
                if (penetration < max_penetration_tolerance &&
                    std::abs(force - uzawa_force) <= force_change_tolerance * std::abs(force))
                  {
                    record.force            = force;
                    record.max_penetration  = penetration;
                    record.half_width       = state.half_width;
                    record.uzawa_iterations = it;
                    break;
                  }
                uzawa_force = force;
                contact_state(d, true);
                newton(d, true);
              }
          }
        catch (const NewtonFailure &failure)
          {
            log(std::string("  Uzawa: Newton failed (") + failure.what() + "): the smooth branch is lost");
            lost = true;
            break;
          }
        record.newton_total = total_newton - newton_before;
        // the reaction on y = 0 from the converged state (no multiplier change)
        const double force_again = assemble(solution, d, false);
        AssertThrow(std::abs(force_again - record.force) <= 1e-12 * std::abs(record.force),
                    ExcMessage("the force changed on reassembly"));
        record.reaction = 0;
        for (const auto i : support_y_dofs)
          record.reaction += residual(i);
        geometry_checks(record);
        if (refinements <= options.inertia_max)
          {
            assemble(solution, d, true);
            record.n_negative = negative_eigenvalues();
          }
        record.valid = (record.n_crossing == 0);
        records.push_back(record);
        last_force = record.force;
        // the pressures are the multipliers of the next steps
        contact_state(d, true);
      }
    if (lost)
      branch_end = d;
    // the positions not reached
    while (records.size() < n_reports)
      {
        LoadRecord record;
        record.d     = (records.size() + 1) * report_step;
        record.valid = false;
        records.push_back(record);
      }
    return records;
  }

  // ------------------------------------------------------- the mesh study
  struct Extrapolation
  {
    double value      = std::numeric_limits<double>::quiet_NaN();
    double error      = std::numeric_limits<double>::quiet_NaN();
    bool   richardson = false;
  };

  // log2 of the ratio of successive differences ending at F[m] (NaN where
  // the differences change sign)
  double
  observed_order(const std::vector<double> &F, const unsigned int m)
  {
    const double ratio = (F[m - 1] - F[m - 2]) / (F[m] - F[m - 1]);
    return ratio > 0 ? std::log(ratio) / std::log(2.) : std::numeric_limits<double>::quiet_NaN();
  }

  // The reference value from F on successive meshes (coarse to fine, at least
  // two). With delta_m = F_m - F_{m-1}:
  //  - Richardson where the convergence is monotone at a stable rate: the
  //    observed orders of the last two triples (four meshes needed) both
  //    between 1 and 6 and within 1 of each other. Value F_m + delta_m /
  //    (2^p - 1) with the last order p; error: the larger of the correction
  //    and the change against the extrapolation from the previous triple.
  //  - Otherwise the finest value, with the error max(|delta_m|,
  //    |delta_{m-1}| / 2, |delta_{m-2}| / 4) (as far as there are meshes). If
  //    each refinement at least halves the error, each term bounds the error
  //    of F_m; taking the largest is a margin against a difference that is
  //    small by chance in the irregular (non-monotone) convergence caused by
  //    the contact edge crossing element boundaries.
  Extrapolation
  extrapolate(const std::vector<double> &F)
  {
    Extrapolation      e;
    const unsigned int m = F.size() - 1;
    e.value              = F[m];
    if (F.size() < 2)
      return e; // no estimate
    // max_j |F_{m-j} - F_{m-j-1}| / 2^j over the last three differences
    e.error = 0;
    for (unsigned int j = 0; j < 3 && j + 1 <= m; ++j)
      e.error = std::max(e.error, std::abs(F[m - j] - F[m - j - 1]) / std::pow(2., j));
    if (m >= 3)
      {
        const double p = observed_order(F, m), p_before = observed_order(F, m - 1);
        if (p >= 1 && p <= 6 && p_before >= 1 && p_before <= 6 && std::abs(p - p_before) <= 1)
          {
            const double value  = F[m] + (F[m] - F[m - 1]) / (std::pow(2., p) - 1.);
            const double before = F[m - 1] + (F[m - 1] - F[m - 2]) / (std::pow(2., p_before) - 1.);
            e.richardson        = true;
            e.value             = value;
            e.error             = std::max(std::abs(value - F[m]), std::abs(value - before));
          }
      }
    return e;
  }

  Options
  parse(int argc, char **argv)
  {
    Options o;
    for (int a = 1; a < argc; a += 2)
      {
        const std::string opt = argv[a];
        AssertThrow(a + 1 < argc, ExcMessage("option " + opt + " needs a value"));
        const std::string val = argv[a + 1];
        if (opt == "--min-refinements")
          o.min_refinements = std::stoul(val);
        else if (opt == "--max-refinements")
          o.max_refinements = std::stoul(val);
        else if (opt == "--mapping-degree")
          o.mapping_degree = std::stoul(val);
        else if (opt == "--penalty")
          o.penalty_factor = std::stod(val);
        else if (opt == "--substeps")
          o.substeps = std::stoul(val);
        else if (opt == "--contact-points")
          o.contact_rule = val;
        else if (opt == "--inertia-max-refinement")
          o.inertia_max = std::stoul(val);
        else if (opt == "--verbose")
          o.verbose = (std::stoul(val) != 0);
        else
          AssertThrow(false, ExcMessage("unknown option " + opt));
      }
    AssertThrow(o.min_refinements <= o.max_refinements, ExcMessage("--min-refinements > --max-refinements"));
    AssertThrow(o.mapping_degree >= 1 && o.substeps >= 1 && o.penalty_factor > 0, ExcMessage("bad option value"));
    return o;
  }
} // namespace RingReference

int
main(int argc, char **argv)
{
  using namespace RingReference;
  try
    {
      const Options options = parse(argc, argv);
      std::cout << "Rubber ring between rigid frictionless plates: deal.II FE_Q(2) reference\n"
                << "ring 0.6 < r < 1.0, quarter model; plane strain Neo-Hooke E = " << young << ", nu = " << poisson
                << " (lambda = " << std::setprecision(10) << lambda_L << ", mu = " << mu_L << ")\n"
                << "MappingQ(" << options.mapping_degree << "), QGauss(3) cells, contact points "
                << options.contact_rule << " per face, penalty " << options.penalty_factor << " E/h_face with Uzawa, "
                << options.substeps << " sub-steps per 0.05 of plate travel\n\n";

      std::vector<unsigned int>            levels;
      std::vector<std::vector<LoadRecord>> results;
      std::vector<double>                  seconds, branch_end;
      std::vector<unsigned int>            cells;
      std::vector<types::global_dof_index> dofs;
      for (unsigned int r = options.min_refinements; r <= options.max_refinements; ++r)
        {
          dealii::Timer timer;
          RingProblem   problem(r, options);
          std::cout << "## refinement " << r << ": " << problem.n_cells() << " cells (" << 4 * (1u << r) << " x "
                    << (1u << r) << "), " << problem.n_dofs() << " DoFs" << std::endl;
          const auto records = problem.run();
          timer.stop();
          std::cout << "|    d | F = int p dS       | reaction on y = 0  | rel. diff | Uzawa | Newton | max penetr. "
                       "| half-width | min J  | inner top y | inner min y | inner min x | crossed | inner min "
                       "stretch | neg. eig. |\n";
          for (const auto &rec : records)
            {
              std::cout << "| " << std::fixed << std::setprecision(2) << rec.d << " | ";
              if (rec.force == 0)
                {
                  std::cout << "(not reached: the smooth branch was lost before)\n";
                  continue;
                }
              std::cout << std::setprecision(15) << rec.force << " | " << rec.reaction << " | " << std::scientific
                        << std::setprecision(2) << std::abs(rec.reaction - rec.force) / rec.force << "  | "
                        << std::setw(5) << rec.uzawa_iterations << " | " << std::setw(6) << rec.newton_total << " | "
                        << std::setw(11) << rec.max_penetration << " | " << std::fixed << std::setprecision(6)
                        << rec.half_width << "   | " << std::setprecision(4) << rec.min_J << " | "
                        << std::setprecision(6) << rec.inner_top_y << "    | " << rec.inner_min_y << "    | "
                        << rec.inner_min_x << "    | " << std::setw(7) << rec.n_crossing << " | "
                        << std::setprecision(4) << rec.inner_min_stretch << "            | " << std::setw(9)
                        << (rec.n_negative < 0 ? std::string("-") : std::to_string(rec.n_negative)) << " |\n";
            }
          std::cout << std::defaultfloat << "run time " << std::setprecision(4) << timer.wall_time() << " s wall, "
                    << timer.cpu_time() << " s CPU; " << problem.n_substeps() << " sub-steps, "
                    << problem.newton_iterations() << " Newton iterations in all\n";
          if (problem.end_of_branch() >= 0)
            std::cout << "the smooth branch is lost beyond d = " << std::setprecision(6) << problem.end_of_branch()
                      << " (no smaller sub-step converges, or the next state folds through a symmetry line or "
                         "carries less force)\n";
          std::cout << std::endl;
          levels.push_back(r);
          results.push_back(records);
          seconds.push_back(timer.wall_time());
          branch_end.push_back(problem.end_of_branch());
          cells.push_back(problem.n_cells());
          dofs.push_back(problem.n_dofs());
        }

      // the mesh study
      const unsigned int n_meshes = levels.size();
      std::cout << "## F(d) per mesh\n";
      for (unsigned int m = 0; m < n_meshes; ++m)
        {
          std::cout << "#   r = " << levels[m] << ": " << cells[m] << " cells, " << dofs[m] << " DoFs, "
                    << std::setprecision(4) << seconds[m] << " s wall";
          if (branch_end[m] >= 0)
            std::cout << ", smooth branch lost beyond d = " << std::setprecision(6) << branch_end[m];
          std::cout << "\n";
        }
      std::cout << "|    d |";
      for (unsigned int m = 0; m < n_meshes; ++m)
        std::cout << "  r = " << levels[m] << "            |";
      std::cout << "\n";
      for (unsigned int k = 0; k < n_reports; ++k)
        {
          std::cout << "| " << std::fixed << std::setprecision(2) << (k + 1) * report_step << " |";
          for (unsigned int m = 0; m < n_meshes; ++m)
            if (results[m][k].valid)
              std::cout << " " << std::setprecision(15) << results[m][k].force << " |";
            else
              std::cout << "        -          |";
          std::cout << "\n";
        }
      std::cout << std::defaultfloat << "\n## relative differences of successive meshes (F_r - F_{r-1}) / F_r, "
                << "and observed orders log2(diff_{r-1} / diff_r)\n|    d |";
      for (unsigned int m = 1; m < n_meshes; ++m)
        std::cout << " r = " << levels[m] << " vs " << levels[m - 1] << " |";
      for (unsigned int m = 2; m < n_meshes; ++m)
        std::cout << " order at r = " << levels[m] << " |";
      std::cout << "\n";
      std::vector<Extrapolation> reference(n_reports);
      for (unsigned int k = 0; k < n_reports; ++k)
        {
          std::vector<double> F;
          for (unsigned int m = 0; m < n_meshes; ++m)
            F.push_back(results[m][k].valid ? results[m][k].force : std::numeric_limits<double>::quiet_NaN());
          std::cout << "| " << std::fixed << std::setprecision(2) << (k + 1) * report_step << " |" << std::scientific;
          for (unsigned int m = 1; m < n_meshes; ++m)
            std::cout << " " << std::setw(14) << std::setprecision(3) << (F[m] - F[m - 1]) / F[m] << " |";
          for (unsigned int m = 2; m < n_meshes; ++m)
            std::cout << " " << std::fixed << std::setw(16) << std::setprecision(2) << observed_order(F, m) << " |";
          std::cout << "\n";
          // the reference from the meshes on the smooth branch, if the
          // finest one is
          std::vector<double> valid_F;
          for (unsigned int m = 0; m < n_meshes; ++m)
            if (results[m][k].valid)
              valid_F.push_back(F[m]);
            else
              valid_F.clear();
          if (results[n_meshes - 1][k].valid && valid_F.size() >= 2)
            reference[k] = extrapolate(valid_F);
        }

      std::cout << std::defaultfloat << "\n## reference values (see the header of ring_reference.cc for the "
                << "error estimate; nan: no smooth solution on the finest mesh)\n"
                << "|    d | F finest mesh    | F reference      | error estimate | relative | method |\n";
      double worst = 0;
      for (unsigned int k = 0; k < n_reports; ++k)
        {
          const auto &e = reference[k];
          std::cout << "| " << std::fixed << std::setprecision(2) << (k + 1) * report_step << " | "
                    << std::setprecision(14);
          if (results[n_meshes - 1][k].valid)
            std::cout << results[n_meshes - 1][k].force;
          else
            std::cout << "      -         ";
          std::cout << " | " << e.value << " | " << std::scientific << std::setprecision(2) << e.error << "       | "
                    << e.error / std::abs(e.value) << " | "
                    << (e.richardson ? "Richardson" : (std::isnan(e.value) ? "none" : "finest")) << std::defaultfloat
                    << " |\n";
          if (!std::isnan(e.error))
            worst = std::max(worst, e.error / std::abs(e.value));
        }
      double worst_check = 0;
      for (const auto &rs : results)
        for (const auto &rec : rs)
          if (rec.force > 0)
            worst_check = std::max(worst_check, std::abs(rec.reaction - rec.force) / rec.force);
      std::cout << "\nlargest relative error estimate (where there is a reference): " << std::scientific
                << std::setprecision(2) << worst
                << "; largest |reaction - F| / F over all meshes and d: " << worst_check << std::defaultfloat << "\n\n";

      std::cout << "# reference: d F_extrapolated error_estimate\n";
      for (unsigned int k = 0; k < n_reports; ++k)
        std::cout << std::fixed << std::setprecision(2) << (k + 1) * report_step << " " << std::scientific
                  << std::setprecision(12) << reference[k].value << " " << std::setprecision(3) << reference[k].error
                  << "\n";
      std::cout << std::defaultfloat << std::flush;
    }
  catch (std::exception &exc)
    {
      std::cerr << "\n----------------------------------------------------\n"
                << "Exception: " << exc.what() << "\n----------------------------------------------------" << std::endl;
      return 1;
    }
  return 0;
}
