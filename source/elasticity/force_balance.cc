// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/elasticity/force_balance.h>
#include <dealvem/vem/vem_values.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace dealvem
{
  namespace
  {
    // The sums over the cells that ForceBalance::compute() needs: the load
    // vector f, K u and the sum of the magnitudes |K_ij u_j| of its terms,
    // and the range of the characteristic stiffnesses of the laws.
    struct CellSums
    {
      dealii::Vector<double> f, Ku, Ku_abs;
      double                 stiffness_min = std::numeric_limits<double>::infinity();
      double                 stiffness_max = 0;
    };



    // compute(), step 1: f, K u and |K||u| of the cells @p cells (all cells
    // if nullptr) of this process, the nodal loads once (by the first
    // process), then summed over the processes of @p comm if @p parallel.
    CellSums
    sum_over_cells(const ElasticityAssembler<2> &assembler, const dealii::Vector<double> &u,
                   const std::vector<unsigned int> *cells, const MPI_Comm comm, const bool parallel, const bool first)
    {
      const auto        &dof_handler = assembler.get_dof_handler();
      const auto        &mesh        = dof_handler.get_mesh();
      const unsigned int n           = dof_handler.n_dofs();
      CellSums           sums;
      dealii::Vector<double> &f = sums.f, &Ku = sums.Ku, &Ku_abs = sums.Ku_abs;
      f.reinit(n);
      Ku.reinit(n);
      Ku_abs.reinit(n);
      double &stiffness_min = sums.stiffness_min, &stiffness_max = sums.stiffness_max;

      VEMValues<2>           vem_values(dof_handler);
      ElasticityOperator<2>  elasticity;
      dealii::Vector<double> F;
      const auto             add_cell = [&](const unsigned int c) {
        vem_values.reinit(c);
        const double stiffness = assembler.get_law(c).characteristic_stiffness();
        stiffness_min          = std::min(stiffness_min, stiffness);
        stiffness_max          = std::max(stiffness_max, stiffness);
        elasticity.reinit(vem_values.get_element(), assembler.get_law(c), assembler.get_gamma(),
                          assembler.get_stabilization());
        assembler.local_load(vem_values, F);
        const auto &indices = vem_values.get_dof_indices();
        const auto &K       = elasticity.get_stiffness_matrix();
        for (unsigned int i = 0; i < indices.size(); ++i)
          {
            double s = 0, a = 0;
            for (unsigned int j = 0; j < indices.size(); ++j)
              {
                const double t = K(i, j) * u[indices[j]];
                s += t;
                a += std::abs(t);
              }
            f[indices[i]] += F[i];
            Ku[indices[i]] += s;
            Ku_abs[indices[i]] += a;
          }
      };
      if (cells != nullptr)
        for (const auto c : *cells)
          add_cell(c);
      else
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          add_cell(c);
      // the nodal loads (rigid boundary resultants) once
      if (first)
        assembler.add_residual({}, u, true, f);
      if (parallel)
        {
          for (auto *v : {&f, &Ku, &Ku_abs})
            dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(v->begin(), n), comm,
                                        dealii::ArrayView<double>(v->begin(), n));
          stiffness_min = dealii::Utilities::MPI::min(stiffness_min, comm);
          stiffness_max = dealii::Utilities::MPI::max(stiffness_max, comm);
        }
      return sums;
    }



    // compute(), step 3: one Body for each material id, in the order of
    // the cells, with its area centroid and size (the largest distance of
    // a vertex from the centroid); @p node_body gets the index of the body
    // of each node.
    std::vector<ForceBalance::Body>
    find_bodies(const VEMDoFHandler<2> &dof_handler, std::vector<unsigned int> &node_body)
    {
      const auto                                        &mesh = dof_handler.get_mesh();
      std::map<dealii::types::material_id, unsigned int> index;
      std::vector<ForceBalance::Body>                    bodies;
      std::vector<double>                                area;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          const auto id = mesh.cell(c).material_id;
          if (index.count(id) == 0)
            {
              index[id] = bodies.size();
              bodies.emplace_back();
              bodies.back().body = id;
              area.push_back(0);
            }
          auto       &b  = bodies[index[id]];
          const auto &vs = mesh.cell(c).vertices;
          for (unsigned int i = 0; i < vs.size(); ++i)
            {
              const auto  &x0    = mesh.vertex(vs[i]);
              const auto  &x1    = mesh.vertex(vs[(i + 1) % vs.size()]);
              const double cross = x0[0] * x1[1] - x1[0] * x0[1];
              area[index[id]] += 0.5 * cross;
              b.centroid[0] += (x0[0] + x1[0]) * cross / 6.;
              b.centroid[1] += (x0[1] + x1[1]) * cross / 6.;
            }
        }
      for (unsigned int k = 0; k < bodies.size(); ++k)
        if (area[k] != 0)
          bodies[k].centroid /= area[k];
      std::vector<unsigned int> nodes;
      node_body.assign(dof_handler.n_nodes(), 0);
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          dof_handler.get_node_indices(c, nodes);
          for (const auto nd : nodes)
            node_body[nd] = index[mesh.cell(c).material_id];
        }
      for (unsigned int v = 0; v < mesh.n_vertices() && v < node_body.size(); ++v)
        bodies[node_body[v]].size =
          std::max(bodies[node_body[v]].size, mesh.vertex(v).distance(bodies[node_body[v]].centroid));
      return bodies;
    }



    // compute(), step 5: the relative imbalance, residual, condition and
    // tolerance of body @p b from the sums over its nodes: the @p loads
    // |f|, the @p magnitude of the terms of its equations and the
    // @p residual |rho + P|.
    void
    judge_body(ForceBalance::Body &b, const double loads, const double magnitude, const double residual,
               const bool moderate_stiffness_ratio, const double solver_tolerance, const unsigned int n,
               const double external_norm)
    {
      const double eps = std::numeric_limits<double>::epsilon();
      const auto   F   = b.applied + b.reaction + b.contact;
      const double M   = b.applied_moment + b.reaction_moment + b.contact_moment;
      // zero forces: no applied load, and the reactions and contact
      // forces no larger than the rounding of the body's magnitudes (the
      // exact forces are zero; the computed ones are the rounding of K u
      // for a rigid u, and of the partner's)
      b.zero_forces      = loads == 0 && moderate_stiffness_ratio && magnitude > 0 &&
                      b.forces <= ForceBalance::zero_force_factor * eps * magnitude;
      const double scale = b.zero_forces ? ForceBalance::zero_force_factor * eps * magnitude :
                                           std::max(b.forces, std::numeric_limits<double>::min());
      b.imbalance        = (std::abs(F[0]) + std::abs(F[1]) + std::abs(M) / std::max(b.size, 1e-300)) / scale;
      b.residual         = residual / scale;
      b.condition        = b.zero_forces ? 0. : magnitude / scale;
      b.tolerance        = (ForceBalance::rounding_factor * eps * magnitude +
                     ForceBalance::iterative_factor * solver_tolerance * std::sqrt(double(n)) * external_norm) /
                    scale;
      // zero forces within the rounding: the balance holds as exactly as
      // the arithmetic allows, and there is no force to relate it to
      if (b.zero_forces && b.imbalance <= b.tolerance && b.residual <= b.tolerance)
        b.imbalance = b.residual = 0;
      // a body on which nothing acts: nothing to balance
      if (b.forces == 0)
        {
          b.imbalance = b.residual = 0;
          if (magnitude == 0)
            b.condition = 0;
        }
    }
  } // namespace



  std::vector<ForceBalance::Body>
  ForceBalance::compute(const ElasticityAssembler<2>            &assembler,
                        const dealii::AffineConstraints<double> &constraints,
                        const dealii::Vector<double>            &u,
                        const dealii::Vector<double>            &contact_forces,
                        const double                             solver_tolerance,
                        const std::vector<unsigned int>         *cells,
                        const MPI_Comm                           comm,
                        const std::vector<std::pair<dealii::types::global_dof_index,
                                                    dealii::types::global_dof_index>> &couplings,
                        dealii::Vector<double>                                           *unbalanced)
  {
    const auto        &dof_handler = assembler.get_dof_handler();
    const unsigned int n           = dof_handler.n_dofs();
    AssertThrow(u.size() == n && (contact_forces.size() == 0 || contact_forces.size() == n),
                dealii::ExcMessage("ForceBalance::compute(): the vectors must have n_dofs() entries."));
    const bool parallel = dealii::Utilities::MPI::job_supports_mpi() &&
                          dealii::Utilities::MPI::n_mpi_processes(comm) > 1;
    const bool first    = !parallel || dealii::Utilities::MPI::this_mpi_process(comm) == 0;

    // step 1: f, K u and |K||u| of the cells of this process, then summed;
    // the range of the stiffnesses of the laws
    const CellSums                sums   = sum_over_cells(assembler, u, cells, comm, parallel, first);
    const dealii::Vector<double> &f      = sums.f;
    const dealii::Vector<double> &Ku     = sums.Ku;
    const dealii::Vector<double> &Ku_abs = sums.Ku_abs;
    const bool moderate_stiffness_ratio = sums.stiffness_max <= max_stiffness_ratio * sums.stiffness_min;
    dealii::Vector<double> e(n);
    if (contact_forces.size() == n)
      e = contact_forces;

    // step 2: rho = f + e - K u; the reactions P of the constraint lines;
    // the residual r = rho + P of the condensed equations
    dealii::Vector<double> rho(n), P(n);
    for (unsigned int i = 0; i < n; ++i)
      rho[i] = f[i] + e[i] - Ku[i];
    if (unbalanced != nullptr)
      *unbalanced = rho;
    for (const auto &line : constraints.get_lines())
      if (line.index < n)
        {
          P[line.index] -= rho[line.index];
          for (const auto &entry : line.entries)
            if (entry.first < n)
              P[entry.first] += entry.second * rho[line.index];
        }

    // step 3: bodies, their area centroid and size
    std::vector<unsigned int> node_body;
    std::vector<Body>         bodies = find_bodies(dof_handler, node_body);

    double external_norm = 0;
    for (unsigned int i = 0; i < n; ++i)
      external_norm += (f[i] + e[i] + P[i]) * (f[i] + e[i] + P[i]);
    external_norm = std::sqrt(external_norm);

    // step 4: the forces and moments on each body, and the sums behind its
    // scale
    std::vector<double> residual(bodies.size(), 0.), magnitude(bodies.size(), 0.), loads(bodies.size(), 0.);
    for (unsigned int i = 0; i < n; ++i)
      {
        auto              &b    = bodies[node_body[i / 2]];
        const unsigned int comp = i % 2;
        const auto         x    = dof_handler.node_location(i / 2) - b.centroid;
        // the moment arm of a force along this component about the centroid
        const double arm = (comp == 0 ? -x[1] : x[0]);
        b.applied[comp] += f[i];
        b.reaction[comp] += P[i];
        b.contact[comp] += e[i];
        b.applied_moment += arm * f[i];
        b.reaction_moment += arm * P[i];
        b.contact_moment += arm * e[i];
        b.forces += std::abs(f[i]) + std::abs(e[i]) + std::abs(P[i]);
        loads[node_body[i / 2]] += std::abs(f[i]);
        magnitude[node_body[i / 2]] += Ku_abs[i] + std::abs(f[i]) + std::abs(e[i]) + std::abs(P[i]);
        residual[node_body[i / 2]] += std::abs(rho[i] + P[i]);
      }
    // a contact force carries the rounding of the partner body's equations
    for (const auto &[i, j] : couplings)
      if (i < n && j < n && node_body[i / 2] != node_body[j / 2])
        {
          magnitude[node_body[i / 2]] += Ku_abs[j];
          magnitude[node_body[j / 2]] += Ku_abs[i];
        }

    // step 5: the balance of each body relative to its forces
    for (unsigned int k = 0; k < bodies.size(); ++k)
      judge_body(bodies[k], loads[k], magnitude[k], residual[k], moderate_stiffness_ratio, solver_tolerance, n,
                 external_norm);
    return bodies;
  }



  double
  ForceBalance::Body::attainable() const
  {
    return std::numeric_limits<double>::epsilon() * condition;
  }



  std::pair<double, double>
  ForceBalance::worst(const std::vector<Body> &bodies)
  {
    double imbalance = 0, residual = 0;
    for (const auto &b : bodies)
      {
        imbalance = std::max(imbalance, b.imbalance);
        residual  = std::max(residual, b.residual);
      }
    return {imbalance, residual};
  }



  void
  ForceBalance::check(const std::vector<Body> &bodies, const std::string &where)
  {
    for (const auto &b : bodies)
      if (!b.ok() || !std::isfinite(b.imbalance) || !std::isfinite(b.residual))
        {
          const auto         F = b.applied + b.reaction + b.contact;
          std::ostringstream msg;
          msg.precision(4);
          if (b.attainable() > max_attainable)
            {
              msg << "Verification failed after the solve of " << where << ": the forces of body " << int(b.body)
                  << " cannot be resolved in double precision. The condition of its balance (the magnitudes "
                     "summed into it, |K||u| + |f| + |reactions| + |contact|, over the sum of the magnitudes "
                     "of the forces acting on it, "
                  << b.forces << ") is " << b.condition << ", so its loads, support reactions and contact forces "
                  << "are computed only to " << b.attainable() << " relative (limit " << max_attainable
                  << "); this solve gives an imbalance of " << b.imbalance << " and a residual of " << b.residual
                  << ". Net force (" << F[0] << ", " << F[1] << ") = applied (" << b.applied[0] << ", "
                  << b.applied[1] << ") + reactions (" << b.reaction[0] << ", " << b.reaction[1]
                  << ") + contact (" << b.contact[0] << ", " << b.contact[1]
                  << "). Its strain drowns in a rigid displacement far larger than it. Typical causes: (1) a "
                     "load too small for the gap it first closes: a gear turned by a small torque through its "
                     "backlash, or a part pushed by a small force across an open gap, before the contact "
                     "holds it. Place the bodies in contact (turn the gear until its flank touches) or raise "
                     "the load. (2) A body many orders of magnitude stiffer than the body that supports it (the "
                     "contact forces between them carry the error to both). Bring the Young's moduli of the "
                     "bodies closer together (a stiffness ratio up to about 1e6 is resolved), or model the stiff "
                     "body as a rigid boundary part.";
              AssertThrow(false, dealii::ExcMessage(msg.str()));
            }
          msg << "Verification failed after the solve of " << where << ": body " << int(b.body)
              << " is not in equilibrium. Relative to the forces acting on it (sum of their magnitudes "
              << b.forces << "), the residual of its equations is " << b.residual
              << " and the imbalance of its loads, support reactions and contact forces is " << b.imbalance
              << "; the tolerance is " << b.tolerance << " (= 1e4 eps times the condition " << b.condition
              << " of the balance"
              << (b.tolerance > rounding_factor * std::numeric_limits<double>::epsilon() * b.condition * 1.0001 ?
                    ", plus the iterative solver's tolerance" :
                    "")
              << "). Net force (" << F[0] << ", " << F[1] << ") = applied (" << b.applied[0] << ", "
              << b.applied[1] << ") + reactions (" << b.reaction[0] << ", " << b.reaction[1] << ") + contact ("
              << b.contact[0] << ", " << b.contact[1] << "); net moment about the centroid (" << b.centroid[0]
              << ", " << b.centroid[1] << "): " << b.applied_moment + b.reaction_moment + b.contact_moment
              << ". The linear solve lost too many digits: the system is too ill-conditioned for double "
                 "precision (Young's moduli of very different size between bodies, a body held only by a "
                 "soft penalty, extreme mesh grading) or the iterative solver stopped early. Bring the "
                 "Young's moduli of the bodies closer together or use a tighter 'Solver/Relative tolerance'.";
          AssertThrow(false, dealii::ExcMessage(msg.str()));
        }
  }
} // namespace dealvem
