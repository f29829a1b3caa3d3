// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <dealvem/base/number_string.h>
#include <dealvem/design/topology_optimizer.h>

#include <nlopt.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <numeric>

namespace dealvem
{
  namespace Design
  {
    void
    TopologyOptimizer::Settings::check() const
    {
      using internal::number_string;
      AssertThrow(std::isfinite(volume_fraction) && volume_fraction > 0 && volume_fraction <= 1,
                  dealii::ExcMessage("Design/Volume fraction must lie in (0, 1], got " +
                                     number_string(volume_fraction) + "."));
      AssertThrow(std::isfinite(filter_radius) && filter_radius > 0,
                  dealii::ExcMessage("Design/Filter radius must be positive, got " + number_string(filter_radius) +
                                     "."));
      interpolation.check();
      AssertThrow(max_iterations >= 1, dealii::ExcMessage("Design/Iterations must be at least 1."));
      AssertThrow(std::isfinite(tolerance) && tolerance > 0 && tolerance < 1,
                  dealii::ExcMessage("Design/Tolerance must lie in (0, 1), got " + number_string(tolerance) + "."));
      AssertThrow(std::isfinite(move) && move > 0 && move <= 1,
                  dealii::ExcMessage("Design/Move limit must lie in (0, 1], got " + number_string(move) + "."));
      if (projection)
        {
          heaviside.check();
          AssertThrow(projection_interval >= 1,
                      dealii::ExcMessage("Design/Projection interval must be at least 1."));
          AssertThrow(std::isfinite(max_beta) && max_beta >= heaviside.beta,
                      dealii::ExcMessage("Design/Maximum sharpness must be at least the first sharpness, got " +
                                         number_string(max_beta) + "."));
        }
      AssertThrow(initial_density < 0 || (initial_density <= 1 && std::isfinite(initial_density)),
                  dealii::ExcMessage("Design/Initial density must lie in [0, 1], got " +
                                     number_string(initial_density) + "."));
      for (const auto id : solid_ids)
        AssertThrow(void_ids.count(id) == 0,
                    dealii::ExcMessage("Design: material id " + std::to_string(id) +
                                       " is listed both as solid and as void."));
    }



    TopologyOptimizer::Optimizer
    parse_optimizer(const std::string &name)
    {
      std::string n = name;
      std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::tolower(c); });
      if (n == "mma")
        return TopologyOptimizer::Optimizer::mma;
      if (n == "oc")
        return TopologyOptimizer::Optimizer::oc;
      AssertThrow(false, dealii::ExcMessage("Design/Optimizer: '" + name + "' is not MMA or OC."));
      return TopologyOptimizer::Optimizer::mma;
    }



    TopologyOptimizer::TopologyOptimizer(const Settings &settings)
      : settings(settings)
    {
      settings.check();
    }



    TopologyOptimizer::Chain
    TopologyOptimizer::make_chain(const PolygonalMesh<2> &mesh, const Settings &settings)
    {
      Chain chain;
      chain.base.assign(mesh.n_cells(), 0.);
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        {
          const auto id = mesh.cell(c).material_id;
          if (settings.solid_ids.count(id))
            chain.base[c] = 1;
          else if (!settings.void_ids.count(id))
            chain.design_cells.push_back(c);
        }
      AssertThrow(!chain.design_cells.empty(),
                  dealii::ExcMessage("Design: every cell is passive (solid or void material ids); nothing to "
                                     "design."));
      chain.areas = cell_areas(mesh, chain.design_cells);
      chain.filter.reinit(cell_centroids(mesh, chain.design_cells), settings.filter_radius);
      chain.physical = chain.base;
      return chain;
    }



    std::vector<double>
    TopologyOptimizer::Chain::factors(const std::vector<double> &z, const MaterialInterpolation &m,
                                      const HeavisideProjection *h)
    {
      filter.apply(z, filtered);
      physical = base;
      for (unsigned int i = 0; i < design_cells.size(); ++i)
        physical[design_cells[i]] = h ? h->value(filtered[i]) : filtered[i];
      std::vector<double> s(physical.size());
      for (unsigned int c = 0; c < s.size(); ++c)
        s[c] = m.factor(physical[c]);
      return s;
    }



    std::vector<double>
    TopologyOptimizer::Chain::variable_gradient(const std::vector<double> &ds, const MaterialInterpolation &m,
                                                const HeavisideProjection *h) const
    {
      std::vector<double> g(design_cells.size()), gz;
      for (unsigned int i = 0; i < design_cells.size(); ++i)
        {
          const unsigned int c = design_cells[i];
          g[i] = ds[c] * m.derivative(physical[c]) * (h ? h->derivative(filtered[i]) : 1.);
        }
      filter.apply_transpose(g, gz);
      return gz;
    }



    double
    TopologyOptimizer::Chain::volume(std::vector<double> *gradient, const HeavisideProjection *h) const
    {
      const double total = std::accumulate(areas.begin(), areas.end(), 0.);
      double       v     = 0;
      std::vector<double> g(design_cells.size());
      for (unsigned int i = 0; i < design_cells.size(); ++i)
        {
          v += areas[i] * physical[design_cells[i]];
          g[i] = areas[i] / total * (h ? h->derivative(filtered[i]) : 1.);
        }
      if (gradient)
        filter.apply_transpose(g, *gradient);
      return v / total;
    }



    namespace
    {
      // What the NLopt callbacks see.
      struct DesignMMAContext
      {
        TopologyOptimizer::Chain                   *chain;
        DesignProblem                               *problem;
        const TopologyOptimizer::Settings          *settings;
        HeavisideProjection                         *projection; // nullptr: none
        double                                       scale = 1;  // 1 / J(initial design)
        double                                       analysis_time = 0;
        std::vector<TopologyOptimizer::Iteration>   *history;
        std::vector<double>                          last_z;
        std::function<void(unsigned int, const TopologyOptimizer::Iteration &, const std::vector<double> &)>
          *callback;
      };

      double
      design_grey(const TopologyOptimizer::Chain &chain)
      {
        unsigned int n = 0;
        for (const unsigned int c : chain.design_cells)
          n += (chain.physical[c] > 0.1 && chain.physical[c] < 0.9);
        return double(n) / chain.design_cells.size();
      }

      // J(z) / J0 and its gradient; records the iteration
      double
      design_objective(unsigned n, const double *x, double *grad, void *data)
      {
        auto                     &ctx = *static_cast<DesignMMAContext *>(data);
        const std::vector<double> z(x, x + n);
        const auto s = ctx.chain->factors(z, ctx.settings->interpolation, ctx.projection);
        std::vector<double> ds;
        const auto          start = std::chrono::steady_clock::now();
        const double        J     = ctx.problem->evaluate(s, ds);
        ctx.analysis_time += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        // NLopt's CCSA starts with conservative quadratic terms of unit
        // weight: scaled by n / J0 the gradient entries are of order one
        // (about -p / rho for SIMP compliance), so the first steps are not
        // vanishingly small
        if (ctx.history->empty())
          ctx.scale = n / std::max(std::abs(J), 1e-300);
        if (grad)
          {
            const auto g = ctx.chain->variable_gradient(ds, ctx.settings->interpolation, ctx.projection);
            for (unsigned i = 0; i < n; ++i)
              grad[i] = g[i] * ctx.scale;
          }
        TopologyOptimizer::Iteration it;
        it.objective = J;
        it.volume    = ctx.chain->volume(nullptr, ctx.projection);
        it.beta      = ctx.projection ? ctx.projection->beta : 0;
        it.grey      = design_grey(*ctx.chain);
        it.change    = 0;
        if (ctx.problem->n_constraints() > 0)
          {
            std::vector<std::vector<double>> unused;
            ctx.problem->constraints(it.constraints, unused);
          }
        if (!ctx.last_z.empty())
          for (unsigned i = 0; i < n; ++i)
            it.change = std::max(it.change, std::abs(z[i] - ctx.last_z[i]));
        ctx.last_z = z;
        ctx.history->push_back(it);
        if (*ctx.callback)
          (*ctx.callback)(ctx.history->size(), it, ctx.chain->physical);
        return J * ctx.scale;
      }

      double
      design_volume_constraint(unsigned n, const double *x, double *grad, void *data)
      {
        auto                     &ctx = *static_cast<DesignMMAContext *>(data);
        const std::vector<double> z(x, x + n);
        ctx.chain->factors(z, ctx.settings->interpolation, ctx.projection);
        std::vector<double> g;
        const double        v = ctx.chain->volume(&g, ctx.projection);
        // scaled by n like the objective (entries of order one)
        if (grad)
          for (unsigned i = 0; i < n; ++i)
            grad[i] = n * g[i];
        return n * (v - ctx.settings->volume_fraction);
      }

      // the problem's own constraints g_j(z) <= 0, at the design of the
      // objective's last evaluation (NLopt evaluates the objective first at
      // every point), scaled by n like the volume
      void
      design_problem_constraints(unsigned m, double *result, unsigned n, const double *x, double *grad, void *data)
      {
        auto &ctx = *static_cast<DesignMMAContext *>(data);
        if (ctx.last_z.size() != n || !std::equal(ctx.last_z.begin(), ctx.last_z.end(), x))
          {
            // not the last point evaluated: evaluate it (recorded as an
            // iteration like any other evaluation)
            std::vector<double> unused(n);
            design_objective(n, x, unused.data(), &ctx);
          }
        std::vector<double>              g;
        std::vector<std::vector<double>> dg;
        ctx.problem->constraints(g, dg);
        AssertThrow(g.size() == m && dg.size() == m,
                    dealii::ExcMessage("Design: the problem returned " + std::to_string(g.size()) +
                                       " constraints, but declares " + std::to_string(m) + "."));
        if (grad)
          ctx.chain->factors(std::vector<double>(x, x + n), ctx.settings->interpolation, ctx.projection);
        for (unsigned j = 0; j < m; ++j)
          {
            result[j] = n * g[j];
            if (grad)
              {
                const auto gz = ctx.chain->variable_gradient(dg[j], ctx.settings->interpolation, ctx.projection);
                for (unsigned i = 0; i < n; ++i)
                  grad[j * n + i] = n * gz[i];
              }
          }
      }

      std::string
      design_nlopt_result(const nlopt_result r)
      {
        switch (r)
          {
            case NLOPT_SUCCESS:
              return "success";
            case NLOPT_STOPVAL_REACHED:
              return "objective value reached";
            case NLOPT_FTOL_REACHED:
              return "objective tolerance reached";
            case NLOPT_XTOL_REACHED:
              return "design change below the tolerance";
            case NLOPT_MAXEVAL_REACHED:
              return "iteration limit";
            case NLOPT_MAXTIME_REACHED:
              return "time limit";
            case NLOPT_FAILURE:
              return "NLopt failure";
            case NLOPT_INVALID_ARGS:
              return "NLopt: invalid arguments";
            case NLOPT_OUT_OF_MEMORY:
              return "NLopt: out of memory";
            case NLOPT_ROUNDOFF_LIMITED:
              return "NLopt: round-off limited";
            case NLOPT_FORCED_STOP:
              return "stopped";
            default:
              return "NLopt code " + std::to_string(int(r));
          }
      }
    } // namespace



    TopologyOptimizer::Result
    TopologyOptimizer::run(DesignProblem &problem)
    {
      const double z0 = settings.initial_density >= 0 ? settings.initial_density : settings.volume_fraction;
      return run(problem, std::vector<double>(problem.get_mesh().n_cells(), z0));
    }



    TopologyOptimizer::Result
    TopologyOptimizer::run(DesignProblem &problem, const std::vector<double> &initial)
    {
      const auto start = std::chrono::steady_clock::now();
      AssertThrow(initial.size() == problem.get_mesh().n_cells(),
                  dealii::ExcMessage("TopologyOptimizer::run(): " + std::to_string(initial.size()) +
                                     " initial densities for " + std::to_string(problem.get_mesh().n_cells()) +
                                     " cells."));
      Chain              chain = make_chain(problem.get_mesh(), settings);
      const unsigned int n     = chain.design_cells.size();
      std::vector<double> z(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const double v = initial[chain.design_cells[i]];
          // (filtered densities may exceed 1 or fall below 0 by rounding)
          AssertThrow(std::isfinite(v) && v >= -1e-12 && v <= 1 + 1e-12,
                      dealii::ExcMessage("TopologyOptimizer::run(): the initial density of cell " +
                                         std::to_string(chain.design_cells[i]) + " is " +
                                         internal::number_string(v) + "; it must lie in [0, 1]."));
          z[i] = std::clamp(v, 0., 1.);
        }
      HeavisideProjection projection = settings.heaviside;
      HeavisideProjection *h = settings.projection ? &projection : nullptr;

      const unsigned int n_constraints = problem.n_constraints();
      AssertThrow(n_constraints == 0 || settings.optimizer == Optimizer::mma,
                  dealii::ExcMessage("Design/Optimizer: OC handles the volume constraint only, and the problem has " +
                                     std::to_string(n_constraints) + " constraint(s) of its own (" +
                                     problem.constraint_name(0) + "); choose MMA."));

      Result           result;
      DesignMMAContext ctx;
      ctx.chain      = &chain;
      ctx.problem    = &problem;
      ctx.settings   = &settings;
      ctx.projection = h;
      ctx.history    = &result.history;
      ctx.callback   = &callback;

      if (settings.optimizer == Optimizer::mma)
        {
          // MMA in rounds: with projection, one round per sharpness, each
          // of at most projection_interval evaluations; the last round (the
          // largest sharpness, or the only one) runs to the tolerance
          const std::vector<double> lower(n, 0.), upper(n, 1.);
          while (result.history.size() < settings.max_iterations)
            {
              const bool last_round = (h == nullptr || projection.beta >= settings.max_beta);
              nlopt_opt  opt        = nlopt_create(NLOPT_LD_MMA, n);
              nlopt_set_lower_bounds(opt, lower.data());
              nlopt_set_upper_bounds(opt, upper.data());
              nlopt_set_min_objective(opt, design_objective, &ctx);
              nlopt_add_inequality_constraint(opt, design_volume_constraint, &ctx, 1e-8 * n);
              if (n_constraints > 0)
                {
                  const std::vector<double> tolerances(n_constraints, 1e-8 * n);
                  nlopt_add_inequality_mconstraint(opt, n_constraints, design_problem_constraints, &ctx,
                                                   tolerances.data());
                }
              const unsigned int left = settings.max_iterations - result.history.size();
              nlopt_set_maxeval(opt, last_round ? left : std::min(left, settings.projection_interval));
              // the first moves (the asymptotes' first distance) as OC's
              // move limit; NLopt stops when no variable moves by more than
              // the tolerance between two outer iterations (the inner ones,
              // which re-evaluate near the same point when a step was not
              // conservative, do not count)
              nlopt_set_initial_step1(opt, settings.move);
              if (last_round)
                nlopt_set_xtol_abs1(opt, settings.tolerance);
              double             f = 0;
              const nlopt_result r = nlopt_optimize(opt, z.data(), &f);
              nlopt_destroy(opt);
              result.stop_reason = design_nlopt_result(r);
              result.converged   = (r == NLOPT_XTOL_REACHED);
              AssertThrow(r > 0 || r == NLOPT_ROUNDOFF_LIMITED,
                          dealii::ExcMessage("Design: NLopt's MMA stopped with '" + result.stop_reason + "'."));
              if (last_round)
                break;
              projection.beta = std::min(2 * projection.beta, settings.max_beta);
            }
        }
      else
        {
          // optimality criteria: z_new = clamp(z * sqrt(-dJ/dz / (l dV/dz)))
          // within the move limit, damping 1/2, l by bisection
          unsigned int since_beta = 0;
          for (unsigned int it = 0; it < settings.max_iterations; ++it)
            {
              std::vector<double> grad(n), gv;
              design_objective(n, z.data(), grad.data(), &ctx);
              chain.volume(&gv, h);
              std::vector<double> z_new(n);
              double              l1 = 0, l2 = 1e9;
              const double        move = settings.move;
              while ((l2 - l1) / (l1 + l2) > 1e-4 && l2 > 1e-40)
                {
                  const double lm = 0.5 * (l1 + l2);
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const double B = std::max(0., -grad[i]) / (lm * std::max(gv[i], 1e-30));
                      z_new[i] = std::clamp(z[i] * std::sqrt(B), std::max(0., z[i] - move), std::min(1., z[i] + move));
                    }
                  chain.factors(z_new, settings.interpolation, h);
                  if (chain.volume(nullptr, h) > settings.volume_fraction)
                    l1 = lm;
                  else
                    l2 = lm;
                }
              double change = 0;
              for (unsigned int i = 0; i < n; ++i)
                change = std::max(change, std::abs(z_new[i] - z[i]));
              z = z_new;
              ++since_beta;
              if (change < settings.tolerance)
                {
                  if (h == nullptr || projection.beta >= settings.max_beta)
                    {
                      result.converged = true;
                      break;
                    }
                }
              if (h && since_beta >= settings.projection_interval && projection.beta < settings.max_beta)
                {
                  projection.beta = std::min(2 * projection.beta, settings.max_beta);
                  since_beta      = 0;
                }
            }
          result.stop_reason = result.converged ? "design change below the tolerance" : "iteration limit";
        }

      // the final design (NLopt's best point, OC's last update) is the
      // history's last entry: evaluated once more, and recorded, when the
      // optimizer's last evaluation was at another point (a trial point
      // MMA rejected, or the design before OC's last update)
      if (ctx.last_z != z)
        design_objective(n, z.data(), nullptr, &ctx);
      chain.factors(z, settings.interpolation, h);
      result.densities = chain.physical;
      result.volume    = chain.volume(nullptr, h);
      result.objective = result.history.back().objective;
      if (n_constraints > 0 && !result.history.empty())
        {
          std::vector<std::vector<double>> unused;
          problem.constraints(result.constraints, unused);
        }
      // a design that stopped outside the feasible set is not converged,
      // whatever the change (a constraint whose gradient vanishes, e.g. the
      // force of an interface that is open everywhere, stops MMA at once)
      double       worst = (result.volume - settings.volume_fraction) / settings.volume_fraction;
      std::string  worst_name = "volume fraction <= " + internal::number_string(settings.volume_fraction);
      for (unsigned int j = 0; j < result.constraints.size(); ++j)
        if (result.constraints[j] > worst)
          {
            worst      = result.constraints[j];
            worst_name = problem.constraint_name(j);
          }
      if (worst > 1e-3)
        {
          result.feasible  = false;
          result.converged = false;
          result.stop_reason += "; the design violates '" + worst_name + "' (scaled by " +
                                internal::number_string(worst) + ")";
        }
      result.analysis_time = ctx.analysis_time;
      result.time          = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return result;
    }
  } // namespace Design
} // namespace dealvem
