// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <dealvem/base/number_string.h>
#include <dealvem/contact/active_set_solver.h>
#include <dealvem/contact/contact_rows.h>
#include <dealvem/contact/contact_solver.h>
#include <dealvem/contact/node_insertion.h>
#include <dealvem/contact/rigid_body_support.h>
#include <dealvem/design/design_problem.h>
#include <dealvem/elasticity/boundary_conditions.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/elasticity/elasticity_operator.h>
#include <dealvem/vem/vem_values.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace dealvem
{
  namespace Design
  {
    // Everything setup() builds.
    struct ElasticDesignProblem::Data
    {
      std::vector<NodeInsertion::Interface> interfaces;
      std::vector<ContactNodePair>          pairs;
      std::unique_ptr<ContactAssembler<2>>  contact;
      std::unique_ptr<RigidBodySupport>     support;
      std::unique_ptr<SaddlePointSolver>    solver;
      std::unique_ptr<ContactSolver<2>>     contact_solver;
      dealii::AffineConstraints<double>     constraints;
      dealii::SparsityPattern               sparsity;
      dealii::SparseMatrix<double>          system_matrix, work_matrix;
      dealii::Vector<double>                load;       // unconstrained f (size n)
      dealii::Vector<double>                system_rhs; // f condensed, size n + m
      dealii::Vector<double>                x;
      unsigned int                          n = 0, m = 0;
      double                                h_min = 0; // shortest paired sub-edge
      double                                complementarity = 1;
      // the unit-factor cell matrices, kept when they fit in the budget
      std::vector<double>      cell_matrices;
      std::vector<std::size_t> cell_offset;
      bool                     cached = false;
      std::vector<std::vector<dealii::types::global_dof_index>> cell_dofs;
    };



    ElasticDesignProblem::ElasticDesignProblem(const PolygonalMesh<2>   &mesh,
                                               const MaterialLibrary<2> &laws,
                                               const unsigned int        degree)
      : mesh(mesh)
      , laws(laws)
      , degree(degree)
    {
      AssertThrow(degree == 1 || degree == 2,
                  dealii::ExcMessage("ElasticDesignProblem: the order k must be 1 or 2, got " +
                                     std::to_string(degree) + "."));
      for (const auto &l : laws.get_laws())
        AssertThrow(l.second->is_linear(),
                    dealii::ExcMessage("ElasticDesignProblem: the law '" + l.second->get_name() + "' of material id " +
                                       std::to_string(l.first) + " is not linear; the design problem needs linear "
                                       "laws (a stiffness factor per cell scales the cell matrix)."));
      settings.normal     = ContactSettings::Normal::unilateral;
      settings.tangential = ContactSettings::Tangential::multipliers;
      solver_settings_.type = SaddlePointSolver::Type::direct_constraints;
    }



    ElasticDesignProblem::~ElasticDesignProblem() = default;



    void
    ElasticDesignProblem::add_support(const dealii::types::boundary_id id, const std::array<bool, 2> &fixed)
    {
      supports.emplace_back(id, fixed);
    }



    void
    ElasticDesignProblem::add_point_support(const dealii::Point<2> &p, const unsigned int component)
    {
      AssertThrow(component < 2, dealii::ExcMessage("add_point_support(): the component must be 0 or 1."));
      point_supports.emplace_back(p, component);
    }



    void
    ElasticDesignProblem::add_traction(const dealii::types::boundary_id id, const dealii::Tensor<1, 2> &t)
    {
      AssertThrow(std::isfinite(t[0]) && std::isfinite(t[1]),
                  dealii::ExcMessage("add_traction(): the traction on boundary id " + std::to_string(id) +
                                     " is not finite."));
      tractions.emplace_back(id, t);
    }



    void
    ElasticDesignProblem::add_point_load(const dealii::Point<2> &p, const dealii::Tensor<1, 2> &f)
    {
      AssertThrow(std::isfinite(f[0]) && std::isfinite(f[1]),
                  dealii::ExcMessage("add_point_load(): the force at " + internal::point_string(p) +
                                     " is not finite."));
      point_loads.emplace_back(p, f);
    }



    void
    ElasticDesignProblem::add_boundary_conditions(const ConstraintFunction &constraints, const LoadFunction &loads)
    {
      if (constraints)
        constraint_functions.push_back(constraints);
      if (loads)
        load_functions.push_back(loads);
    }



    void
    ElasticDesignProblem::add_contact_interface(const dealii::types::boundary_id master,
                                                const dealii::types::boundary_id slave)
    {
      AssertThrow(master != slave, dealii::ExcMessage("add_contact_interface(): the master and slave ids are "
                                                      "the same (" + std::to_string(master) + ")."));
      interface_ids.emplace_back(master, slave);
    }



    void
    ElasticDesignProblem::set_objective(const Objective objective, const unsigned int interface)
    {
      this->objective     = objective;
      objective_interface = interface;
    }



    void
    ElasticDesignProblem::set_pressure_norm_exponent(const double P)
    {
      AssertThrow(std::isfinite(P) && P >= 1,
                  dealii::ExcMessage("ElasticDesignProblem: the exponent of the pressure norm must be at least 1, "
                                     "got " + internal::number_string(P) + "."));
      pressure_exponent = P;
    }



    unsigned int
    ElasticDesignProblem::n_pairs() const
    {
      return data ? data->pairs.size() : 0;
    }



    const std::vector<ContactNodePair> &
    ElasticDesignProblem::get_pairs() const
    {
      AssertThrow(data != nullptr, dealii::ExcMessage("ElasticDesignProblem: call setup() first."));
      return data->pairs;
    }



    std::string
    DesignProblem::constraint_name(const unsigned int j) const
    {
      return "constraint " + std::to_string(j);
    }



    void
    DesignProblem::constraints(std::vector<double> &values, std::vector<std::vector<double>> &gradients) const
    {
      AssertThrow(n_constraints() == 0,
                  dealii::ExcMessage("DesignProblem: a problem with constraints must implement constraints()."));
      values.clear();
      gradients.clear();
    }



    std::string
    ElasticDesignProblem::response_name(const Response response, const unsigned int interface) const
    {
      if (response == Response::compliance)
        return "compliance";
      if (response == Response::interface_force)
        return "normal force of interface " + std::to_string(interface);
      return "largest pressure of interface " + std::to_string(interface) + " (" +
             internal::number_string(pressure_exponent) + "-norm)";
    }



    std::string
    ElasticDesignProblem::objective_name() const
    {
      return response_name(objective, objective_interface);
    }



    void
    ElasticDesignProblem::add_constraint(const Response     response,
                                         const double       bound,
                                         const Bound        sense,
                                         const unsigned int interface)
    {
      AssertThrow(std::isfinite(bound) && bound > 0,
                  dealii::ExcMessage("ElasticDesignProblem::add_constraint(): the bound of the " +
                                     response_name(response, interface) + " must be positive, got " +
                                     internal::number_string(bound) + "."));
      AssertThrow(data == nullptr,
                  dealii::ExcMessage("ElasticDesignProblem::add_constraint(): call it before setup()."));
      constraint_list.push_back(Constraint{response, interface, bound, sense});
    }



    std::string
    ElasticDesignProblem::constraint_name(const unsigned int j) const
    {
      AssertThrow(j < constraint_list.size(),
                  dealii::ExcMessage("ElasticDesignProblem: constraint " + std::to_string(j) + " of " +
                                     std::to_string(constraint_list.size()) + "."));
      const Constraint &c = constraint_list[j];
      return response_name(c.response, c.interface) + (c.sense == Bound::at_most ? " <= " : " >= ") +
             internal::number_string(c.bound);
    }



    void
    ElasticDesignProblem::constraints(std::vector<double> &values, std::vector<std::vector<double>> &gradients) const
    {
      AssertThrow(constraint_values.size() == constraint_list.size(),
                  dealii::ExcMessage("ElasticDesignProblem::constraints(): call evaluate() first."));
      values    = constraint_values;
      gradients = constraint_gradients;
    }



    namespace
    {
      // The vertex of @p mesh at @p p, within 1e-8 of the mesh's extent.
      unsigned int
      design_vertex_at(const PolygonalMesh<2> &mesh, const dealii::Point<2> &p, const std::string &what)
      {
        dealii::Point<2> lo = mesh.vertex(0), hi = mesh.vertex(0);
        unsigned int     best = 0;
        double           d    = p.distance(mesh.vertex(0));
        for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
          {
            for (unsigned int k = 0; k < 2; ++k)
              {
                lo[k] = std::min(lo[k], mesh.vertex(v)[k]);
                hi[k] = std::max(hi[k], mesh.vertex(v)[k]);
              }
            if (p.distance(mesh.vertex(v)) < d)
              {
                d    = p.distance(mesh.vertex(v));
                best = v;
              }
          }
        AssertThrow(d <= 1e-8 * lo.distance(hi),
                    dealii::ExcMessage(what + ": no vertex of the mesh at " + internal::point_string(p) +
                                       " (the nearest is " + internal::point_string(mesh.vertex(best)) +
                                       "); put a vertex there."));
        return best;
      }
    } // namespace



    void
    ElasticDesignProblem::setup()
    {
      AssertThrow(mesh.n_cells() > 0, dealii::ExcMessage("ElasticDesignProblem: the mesh has no cells."));
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        AssertThrow(laws.has_law(mesh.cell(c).material_id),
                    dealii::ExcMessage("ElasticDesignProblem: cell " + std::to_string(c) + " has material id " +
                                       std::to_string(mesh.cell(c).material_id) + ", which has no law."));
      AssertThrow(!settings.is_coulomb(),
                  dealii::ExcMessage("ElasticDesignProblem: Coulomb friction is path-dependent and its system is "
                                     "not symmetric; design with tied, stick or frictionless contact."));
      AssertThrow(objective == Objective::compliance || objective_interface < interface_ids.size(),
                  dealii::ExcMessage("ElasticDesignProblem: the objective belongs to interface " +
                                     std::to_string(objective_interface) + ", but there are " +
                                     std::to_string(interface_ids.size()) + " contact interfaces."));
      for (unsigned int j = 0; j < constraint_list.size(); ++j)
        AssertThrow(constraint_list[j].response == Response::compliance ||
                      constraint_list[j].interface < interface_ids.size(),
                    dealii::ExcMessage("ElasticDesignProblem: constraint " + std::to_string(j) + " (" +
                                       constraint_name(j) + ") belongs to interface " +
                                       std::to_string(constraint_list[j].interface) + ", but there are " +
                                       std::to_string(interface_ids.size()) + " contact interfaces."));
      data = std::make_unique<Data>();
      Data &d = *data;

      // 1. node insertion: the interfaces become matching
      if (!interface_ids.empty())
        {
          NodeInsertion::Settings s = insertion;
          s.validate_mesh           = false;
          auto edges                = NodeInsertion::boundary_edges(mesh);
          for (unsigned int i = 0; i < interface_ids.size(); ++i)
            d.interfaces.push_back(NodeInsertion::insert(mesh, interface_ids[i].first, interface_ids[i].second,
                                                         degree, s, i, &edges));
          mesh.validate();
          for (auto &itf : d.interfaces)
            NodeInsertion::update_geometry(mesh, itf);
          for (const auto &itf : d.interfaces)
            {
              AssertThrow(!itf.pairs.empty(),
                          dealii::ExcMessage("ElasticDesignProblem: node insertion found no pair between boundary "
                                             "ids " + std::to_string(itf.master_id) + " and " +
                                             std::to_string(itf.slave_id) + "."));
              d.pairs.insert(d.pairs.end(), itf.pairs.begin(), itf.pairs.end());
            }
          NodeInsertion::mark_junctions(d.pairs, mesh);
        }

      // 2. DoFs, constraints (homogeneous), loads
      dof_handler.reinit(mesh);
      dof_handler.distribute_dofs(degree);
      d.n = dof_handler.n_dofs();
      {
        const dealii::Functions::ZeroFunction<2> zero(2);
        for (const auto &s : supports)
          BoundaryConditions::interpolate_boundary_values(dof_handler, {s.first}, zero, s.second, d.constraints);
        for (const auto &s : point_supports)
          {
            const unsigned int v = design_vertex_at(mesh, s.first, "add_point_support()");
            const auto         dof = VEMDoFHandler<2>::node_dof(dof_handler.vertex_node(v), s.second);
            if (!d.constraints.is_constrained(dof))
              d.constraints.add_line(dof);
          }
        for (const auto &f : constraint_functions)
          f(dof_handler, d.constraints);
        d.constraints.close();
        for (const auto &line : d.constraints.get_lines())
          AssertThrow(line.inhomogeneity == 0,
                      dealii::ExcMessage("ElasticDesignProblem: the boundary conditions prescribe the displacement " +
                                         internal::number_string(line.inhomogeneity) + " at DoF " +
                                         std::to_string(line.index) + " (node at " +
                                         internal::point_string(dof_handler.node_location(line.index / 2)) +
                                         "); a design needs zero Dirichlet data (the compliance of a prescribed "
                                         "displacement is not the work of the loads)."));
      }
      std::vector<dealii::Functions::ConstantFunction<2>> traction_functions;
      traction_functions.reserve(tractions.size());
      ElasticityAssembler<2> loads(dof_handler, laws);
      for (const auto &t : tractions)
        {
          traction_functions.emplace_back(std::vector<double>{t.second[0], t.second[1]});
          loads.add_traction(t.first, traction_functions.back());
        }
      for (const auto &f : point_loads)
        {
          const unsigned int v = design_vertex_at(mesh, f.first, "add_point_load()");
          for (unsigned int k = 0; k < 2; ++k)
            if (f.second[k] != 0)
              loads.add_nodal_load(VEMDoFHandler<2>::node_dof(dof_handler.vertex_node(v), k), f.second[k]);
        }
      for (const auto &f : load_functions)
        f(loads);
      loads.assemble_load_vector(d.load);

      // 3. the contact rows, the support check and the solvers
      // (without contact: no scales, an assembler without rows for the
      // support check)
      std::unique_ptr<ContactScales> scales;
      if (!d.pairs.empty())
        {
          scales  = std::make_unique<ContactScales>(laws, d.interfaces);
          d.h_min = scales->h_min;
        }
      d.contact = std::make_unique<ContactAssembler<2>>(dof_handler, d.pairs, settings,
                                                        scales ? scales->penalty(settings) : 1.);
      d.m = d.contact->n_multipliers();
      d.support = std::make_unique<RigidBodySupport>(dof_handler, d.constraints, *d.contact,
                                                     settings.tangential != ContactSettings::Tangential::frictionless);
      {
        const std::string free = d.support->free_motions(std::vector<bool>(d.pairs.size(), true));
        AssertThrow(free.empty(),
                    dealii::ExcMessage("ElasticDesignProblem: the supports and contact interfaces leave these "
                                       "rigid-body motions free: " + free + "."));
      }
      dealii::DynamicSparsityPattern dsp(d.n + d.m);
      dof_handler.make_sparsity_pattern(dsp);
      d.contact->add_sparsity(dsp);
      d.constraints.condense(dsp);
      d.sparsity.copy_from(dsp);
      d.system_matrix.reinit(d.sparsity);
      d.work_matrix.reinit(d.sparsity);
      d.system_rhs.reinit(d.n + d.m);
      for (unsigned int i = 0; i < d.n; ++i)
        d.system_rhs[i] = d.load[i];
      d.constraints.condense(d.system_rhs);

      d.complementarity = scales ? scales->complementarity_constant() : 1.;

      // 4. the unit-factor cell matrices, kept if they take at most 2^28
      // bytes (256 MiB): they do not depend on the design
      std::size_t total = 0;
      d.cell_offset.assign(mesh.n_cells() + 1, 0);
      d.cell_dofs.resize(mesh.n_cells());
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          const std::size_t k = dof_handler.n_dofs_per_cell(c);
          d.cell_offset[c + 1] = d.cell_offset[c] + k * k;
          total += k * k;
        }
      d.cached = total * sizeof(double) <= (std::size_t(1) << 28);
      VEMValues<2> values(dof_handler);
      values.set_cell_similarity(true);
      ElasticityOperator<2> op;
      if (d.cached)
        d.cell_matrices.resize(total);
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          values.reinit(c);
          d.cell_dofs[c] = values.get_dof_indices();
          if (d.cached)
            {
              op.reinit(values.get_element(), laws.get_law(mesh.cell(c).material_id), 1.0, Stabilization::automatic);
              const auto &K = op.get_stiffness_matrix();
              std::copy(&K(0, 0), &K(0, 0) + K.m() * K.n(), d.cell_matrices.begin() + d.cell_offset[c]);
            }
        }
    }



    void
    ElasticDesignProblem::assemble(const std::vector<double> &factors)
    {
      Data &d = *data;
      d.system_matrix = 0;
      dealii::FullMatrix<double> K;
      VEMValues<2>               values(dof_handler);
      values.set_cell_similarity(true);
      ElasticityOperator<2> op;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          const unsigned int k = d.cell_dofs[c].size();
          K.reinit(k, k);
          if (d.cached)
            std::copy(d.cell_matrices.begin() + d.cell_offset[c], d.cell_matrices.begin() + d.cell_offset[c + 1],
                      &K(0, 0));
          else
            {
              values.reinit(c);
              op.reinit(values.get_element(), laws.get_law(mesh.cell(c).material_id), 1.0, Stabilization::automatic);
              K = op.get_stiffness_matrix();
            }
          K *= factors[c];
          d.constraints.distribute_local_to_global(K, d.cell_dofs[c], d.system_matrix);
        }
    }



    std::vector<double>
    ElasticDesignProblem::cell_bilinear_forms(const dealii::Vector<double> &v, const dealii::Vector<double> &w) const
    {
      AssertThrow(data != nullptr, dealii::ExcMessage("ElasticDesignProblem: call setup() first."));
      const Data                &d = *data;
      std::vector<double>        result(mesh.n_cells());
      dealii::FullMatrix<double> K;
      dealii::Vector<double>     vc, wc, Kv;
      VEMValues<2>               values(dof_handler);
      values.set_cell_similarity(true);
      ElasticityOperator<2> op;
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          const auto        &dofs = d.cell_dofs[c];
          const unsigned int k    = dofs.size();
          vc.reinit(k);
          wc.reinit(k);
          Kv.reinit(k);
          for (unsigned int i = 0; i < k; ++i)
            {
              vc[i] = v[dofs[i]];
              wc[i] = w[dofs[i]];
            }
          if (d.cached)
            {
              const double *Kc = d.cell_matrices.data() + d.cell_offset[c];
              double        s  = 0;
              for (unsigned int i = 0; i < k; ++i)
                {
                  double r = 0;
                  for (unsigned int j = 0; j < k; ++j)
                    r += Kc[i * k + j] * vc[j];
                  s += wc[i] * r;
                }
              result[c] = s;
            }
          else
            {
              values.reinit(c);
              op.reinit(values.get_element(), laws.get_law(mesh.cell(c).material_id), 1.0, Stabilization::automatic);
              op.get_stiffness_matrix().vmult(Kv, vc);
              result[c] = wc * Kv;
            }
        }
      return result;
    }



    double
    ElasticDesignProblem::response_and_state_derivative(const Response         response,
                                                        const unsigned int     interface,
                                                        const bool             for_objective,
                                                        dealii::Vector<double> &a) const
    {
      const Data        &d = *data;
      const unsigned int p = d.pairs.size();
      a                    = 0;
      if (response == Response::compliance)
        {
          for (unsigned int i = 0; i < d.n; ++i)
            a[i] = d.load[i];
          return d.load * state.displacement;
        }
      if (p == 0)
        {
          AssertThrow(!for_objective || response != Response::max_pressure,
                      dealii::ExcMessage("ElasticDesignProblem: the objective is the largest pressure of interface " +
                                         std::to_string(interface) + ", which has no contact pairs."));
          return 0;
        }
      const ContactRows rows = d.contact->rows();
      if (response == Response::interface_force)
        {
          // J = -sum of the interface's normal multipliers
          for (unsigned int i = 0; i < p; ++i)
            if (d.pairs[i].interface == interface)
              a[rows.normal_row(i)] = -1;
          return a * d.x;
        }
      // J = (sum max(0, p_i)^P)^(1/P), scaled by the largest pressure
      // against overflow; a = dJ/dx (the adjoint of a non-linear J)
      const double        P = pressure_exponent;
      std::vector<double> pressure(p, 0.);
      double              p_max = 0;
      for (unsigned int i = 0; i < p; ++i)
        if (d.pairs[i].interface == interface && !d.pairs[i].junction)
          {
            pressure[i] = std::max(0., -state.normal_multipliers[i] / d.pairs[i].weight);
            p_max       = std::max(p_max, pressure[i]);
          }
      // an interface that opens entirely has no pressure: as a constraint
      // that is a value 0 with a zero gradient; as the objective there is
      // nothing to minimize
      AssertThrow(p_max > 0 || !for_objective,
                  dealii::ExcMessage("ElasticDesignProblem: the objective is the largest pressure of interface " +
                                     std::to_string(interface) + ", which carries no pressure."));
      if (p_max == 0)
        return 0;
      double sum = 0;
      for (unsigned int i = 0; i < p; ++i)
        sum += std::pow(pressure[i] / p_max, P);
      const double J = p_max * std::pow(sum, 1 / P);
      for (unsigned int i = 0; i < p; ++i)
        if (pressure[i] > 0)
          a[rows.normal_row(i)] = -std::pow(pressure[i] / J, P - 1) / d.pairs[i].weight;
      return J;
    }



    double
    ElasticDesignProblem::evaluate(const std::vector<double> &factors, std::vector<double> &gradient)
    {
      AssertThrow(data != nullptr, dealii::ExcMessage("ElasticDesignProblem: call setup() before evaluate()."));
      AssertThrow(factors.size() == mesh.n_cells(),
                  dealii::ExcMessage("ElasticDesignProblem::evaluate(): " + std::to_string(factors.size()) +
                                     " stiffness factors for " + std::to_string(mesh.n_cells()) + " cells."));
      for (unsigned int c = 0; c < factors.size(); ++c)
        AssertThrow(std::isfinite(factors[c]) && factors[c] > 0,
                    dealii::ExcMessage("ElasticDesignProblem::evaluate(): the stiffness factor of cell " +
                                       std::to_string(c) + " is " + internal::number_string(factors[c]) +
                                       "; it must be positive (MaterialInterpolation::minimum)."));
      Data &d = *data;
      // the solvers, at the first evaluation (the solver settings may be
      // chosen after setup(), by the size it gave)
      if (!d.solver)
        {
          d.solver = std::make_unique<SaddlePointSolver>(solver_settings_);
          if (SaddlePointSolver::is_iterative(solver_settings_.type))
            d.solver->set_near_null_space(dof_handler.rigid_body_modes());
          if (!d.pairs.empty())
            {
              d.contact_solver =
                ContactSolver<2>::create(*d.contact, d.constraints, *d.solver, settings, d.complementarity);
              d.contact_solver->set_support(d.support.get());
              d.contact_solver->set_pair_neighbours(ActiveSetSolver<2>::pair_neighbours(d.interfaces));
            }
        }
      using Clock        = std::chrono::steady_clock;
      const auto seconds = [](const Clock::time_point t) {
        return std::chrono::duration<double>(Clock::now() - t).count();
      };
      const unsigned int factorizations_before = d.solver->factorization_counts().first;
      const unsigned int analyses_before       = d.solver->analysis_counts().first;
      auto               start                 = Clock::now();
      assemble(factors);
      state               = State();
      state.time_assembly = seconds(start);
      start               = Clock::now();
      const unsigned p = d.pairs.size();

      // the state
      if (p == 0)
        {
          d.x.reinit(d.n);
          d.solver->solve(d.system_matrix, d.n, d.x, d.system_rhs);
          d.constraints.distribute(d.x);
          state.n_solves          = 1;
          state.linear_iterations = d.solver->last_iterations();
        }
      else
        {
          const auto &r              = d.contact_solver->solve_step(d.system_matrix, d.system_rhs, d.work_matrix, d.x);
          state.active               = r.active;
          state.n_contact_iterations = r.n_iterations;
          state.n_solves             = r.n_iterations;
          state.linear_iterations    = r.linear_iterations;
        }
      state.time_state = seconds(start);
      state.displacement.reinit(d.n);
      for (unsigned int i = 0; i < d.n; ++i)
        state.displacement[i] = d.x[i];
      state.compliance = d.load * state.displacement;

      // the multipliers, the forces of the interfaces, degenerate pairs
      if (p > 0)
        {
          const ContactRows         rows = d.contact->rows();
          const std::vector<double> gaps = d.contact->gaps(d.x);
          state.normal_multipliers.resize(p);
          state.interface_forces.assign(interface_ids.size(), 0.);
          double l_max = 0;
          for (unsigned int i = 0; i < p; ++i)
            {
              state.normal_multipliers[i] = rows.normal_multiplier(d.x, i);
              state.interface_forces[d.pairs[i].interface] -= state.normal_multipliers[i];
              l_max = std::max(l_max, std::abs(state.normal_multipliers[i]));
            }
          if (settings.normal == ContactSettings::Normal::unilateral)
            for (unsigned int i = 0; i < p; ++i)
              if (!d.pairs[i].junction &&
                  ((state.active[i] && std::abs(state.normal_multipliers[i]) <= 1e-8 * l_max) ||
                   (!state.active[i] && gaps[i] <= 1e-8 * d.h_min)))
                ++state.n_degenerate_pairs;
        }

      // every response R = a^T x (or R(x) with a = dR/dx) and its gradient
      // -y_c^T K_c u_c by the adjoint A y = a of the converged set; the
      // compliance is self-adjoint (y = x) when the enforced rows have no
      // right-hand side (an enforced normal row's is -g0 of its pair; the
      // tangential rows have none)
      start = Clock::now();
      bool compliance_self_adjoint = true;
      if (p > 0)
        {
          const ContactRows rows = d.contact->rows();
          for (unsigned int i = 0; i < p && compliance_self_adjoint; ++i)
            compliance_self_adjoint = !state.active[i] || std::abs(rows.gap0(i)) <= 1e-12 * d.h_min;
        }
      bool adjoint_matrix_ready = false;
      // the adjoints solved so far, by response and interface (a
      // constraint on the objective's response needs none of its own)
      std::vector<std::pair<std::pair<Response, unsigned int>, dealii::Vector<double>>> solved;
      const auto adjoint = [&](const Response response, const unsigned int interface, const dealii::Vector<double> &a) {
        if (response == Response::compliance && compliance_self_adjoint)
          return dealii::Vector<double>(d.x);
        const auto key = std::make_pair(response, response == Response::compliance ? 0u : interface);
        for (const auto &done : solved)
          if (done.first == key)
            return done.second;
        if (p > 0 && !adjoint_matrix_ready)
          {
            // the matrix of the converged set, as the solver's last result
            // has it (open pairs tied tangentially where it kept them so);
            // the direct solver finds the factorization of the state's
            // last solve unchanged and reuses it
            const auto       &r = d.contact_solver->last_result();
            std::vector<bool> tangential(p);
            for (unsigned int i = 0; i < p; ++i)
              tangential[i] = r.tied_tangentially(i);
            dealii::Vector<double> unused_rhs(d.n + d.m);
            d.work_matrix.copy_from(d.system_matrix);
            d.contact->assemble(d.constraints, state.active, tangential, d.work_matrix, unused_rhs);
            adjoint_matrix_ready = true;
          }
        dealii::Vector<double> b = a;
        d.constraints.condense(b);
        dealii::Vector<double> y(d.n + d.m);
        d.solver->solve(p > 0 ? d.work_matrix : d.system_matrix, d.n, y, b);
        d.constraints.distribute(y);
        ++state.n_solves;
        state.adjoint_solved = true;
        solved.emplace_back(key, y);
        return y;
      };
      const auto gradient_of = [&](const dealii::Vector<double> &y) {
        dealii::Vector<double> yu(d.n);
        for (unsigned int i = 0; i < d.n; ++i)
          yu[i] = y[i];
        std::vector<double> g = cell_bilinear_forms(state.displacement, yu);
        for (double &v : g)
          v = -v;
        return g;
      };

      dealii::Vector<double> a(d.n + d.m);
      const double           J = response_and_state_derivative(objective, objective_interface, true, a);
      const auto             y = adjoint(objective, objective_interface, a);
      double adjoint_time      = seconds(start);
      start                    = Clock::now();
      gradient                 = gradient_of(y);
      double sensitivity_time  = seconds(start);

      const unsigned int n_c = constraint_list.size();
      constraint_values.assign(n_c, 0.);
      constraint_gradients.assign(n_c, std::vector<double>());
      state.constraint_responses.assign(n_c, 0.);
      for (unsigned int j = 0; j < n_c; ++j)
        {
          const Constraint &c = constraint_list[j];
          start               = Clock::now();
          a                   = 0;
          const double R      = response_and_state_derivative(c.response, c.interface, false, a);
          const auto   yj     = adjoint(c.response, c.interface, a);
          adjoint_time += seconds(start);
          start                      = Clock::now();
          const double sign          = (c.sense == Bound::at_most ? 1. : -1.) / c.bound;
          state.constraint_responses[j] = R;
          constraint_values[j]       = sign * (R - c.bound);
          constraint_gradients[j]    = gradient_of(yj);
          for (double &v : constraint_gradients[j])
            v *= sign;
          sensitivity_time += seconds(start);
        }
      state.n_factorizations   = d.solver->factorization_counts().first - factorizations_before;
      state.n_analyses         = d.solver->analysis_counts().first - analyses_before;
      state.time_adjoint       = adjoint_time;
      state.time_sensitivities = sensitivity_time;
      return J;
    }
  } // namespace Design
} // namespace dealvem
