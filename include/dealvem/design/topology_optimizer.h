// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_design_topology_optimizer_h
#define dealvem_design_topology_optimizer_h

#include <deal.II/base/types.h>

#include <dealvem/design/density_filter.h>
#include <dealvem/design/design_problem.h>
#include <dealvem/design/material_interpolation.h>

#include <functional>
#include <set>
#include <string>
#include <vector>

namespace dealvem
{
  namespace Design
  {
    /**
     * Density topology optimization on a polygonal mesh, in the manner of
     * PolyTop: a design variable $z_i \in [0, 1]$ per design cell, the
     * filtered densities $\tilde\rho = P z$ (DensityFilter), optionally
     * projected $\bar\rho = H_\beta(\tilde\rho)$ (HeavisideProjection, with
     * $\beta$ doubled every Settings::projection_interval iterations up to
     * Settings::max_beta), the stiffness factors
     * $s_c = s(\bar\rho_c)$ (MaterialInterpolation) handed to a
     * DesignProblem, and the volume constraint
     * $\sum_i |E_i| \bar\rho_i \le V^* \sum_i |E_i|$ over the design cells.
     *
     * Cells whose material id is in Settings::solid_ids keep density 1,
     * those in Settings::void_ids density 0 (passive cells); every other
     * cell is designed.
     *
     * The optimizers:
     * - Optimizer::mma: the method of moving asymptotes of NLopt
     *   (NLOPT_LD_MMA, Svanberg's globally convergent CCSA variant), with
     *   the objective scaled by its value on the initial design. NLopt's MMA
     *   may evaluate several trial designs per outer iteration; every
     *   evaluation is counted and reported.
     *   The DesignProblem's own constraints $g_j \le 0$
     *   (DesignProblem::n_constraints(): a bound on an interface's force or
     *   pressure, ElasticDesignProblem::add_constraint()) are MMA
     *   constraints beside the volume, scaled like it.
     * - Optimizer::oc: the optimality-criteria update of Sigmund's 99-line
     *   code and PolyTop (move limit Settings::move, damping 1/2, the
     *   multiplier of the volume constraint by bisection), for compliance
     *   (a gradient of one sign) under the volume constraint only; run()
     *   refuses a problem with constraints of its own.
     *
     * Convergence: the largest change of a design variable between two
     * iterations below Settings::tolerance, or Settings::max_iterations.
     */
    class TopologyOptimizer
    {
    public:
      /// The optimizer.
      enum class Optimizer
      {
        mma, ///< NLopt's MMA
        oc   ///< optimality criteria
      };

      /// The parameters.
      struct Settings
      {
        /// The volume fraction $V^*$ of the design cells, in (0, 1].
        double                   volume_fraction = 0.5;
        /// The filter radius R (length; > 0).
        double                   filter_radius = 0.1;
        /// The stiffness interpolation.
        MaterialInterpolation    interpolation;
        /// The optimizer.
        Optimizer                optimizer = Optimizer::mma;
        /// At most this many iterations (OC updates, or MMA evaluations).
        unsigned int             max_iterations = 200;
        /// Stop when no design variable changes by more than this.
        double                   tolerance = 1e-2;
        /// OC: the move limit.
        double                   move = 0.2;
        /// Heaviside projection with continuation (off: $\bar\rho = \tilde\rho$).
        bool                     projection = false;
        /// The projection's threshold and first sharpness.
        HeavisideProjection      heaviside;
        /// Double the sharpness every this many iterations ...
        unsigned int             projection_interval = 40;
        /// ... up to this value.
        double                   max_beta = 32;
        /// The starting density of the design cells (default: the volume
        /// fraction, a feasible uniform design).
        double                   initial_density = -1;
        /// Material ids of solid passive cells (density 1).
        std::set<dealii::types::material_id> solid_ids;
        /// Material ids of void passive cells (density 0).
        std::set<dealii::types::material_id> void_ids;

        /// Throw, naming the parameter, unless every value is in range.
        void
        check() const;
      };

      /// One iteration of the history.
      struct Iteration
      {
        /// The objective (unscaled).
        double       objective = 0;
        /// The volume fraction of the design cells.
        double       volume = 0;
        /// The largest change of a design variable since the last one.
        double       change = 0;
        /// The projection's sharpness.
        double       beta = 0;
        /// The share of design cells with $\bar\rho$ in (0.1, 0.9): a
        /// measure of grey.
        double       grey = 0;
        /// The problem's constraints $g_j$ (DesignProblem::constraints();
        /// feasible where $\le 0$), empty without.
        std::vector<double> constraints;
      };

      /// What run() returns.
      struct Result
      {
        /// The iterations (evaluations of the problem, in order); the last
        /// one is the returned design (evaluated once more when the
        /// optimizer's last evaluation was at another point).
        std::vector<Iteration> history;
        /// The physical densities $\bar\rho$ of every cell of the mesh
        /// (passive cells 0 or 1).
        std::vector<double>    densities;
        /// The final objective.
        double                 objective = 0;
        /// The final volume fraction.
        double                 volume = 0;
        /// The problem's constraints $g_j$ at the final design (feasible
        /// where $\le 0$).
        std::vector<double>    constraints;
        /// Whether the change tolerance was reached.
        bool                   converged = false;
        /// Whether the final design meets the volume and the problem's
        /// constraints to $10^{-3}$ (scaled values; when not, stop_reason
        /// names the worst constraint and converged is false).
        bool                   feasible = true;
        /// NLopt's return code (MMA), as text.
        std::string            stop_reason;
        /// Wall time of run() (s).
        double                 time = 0;
        /// The part of it spent in DesignProblem::evaluate() (s).
        double                 analysis_time = 0;
      };

      /// An optimizer with @p settings (checked).
      explicit TopologyOptimizer(const Settings &settings);

      /// Call @p callback after every iteration, with the iteration's
      /// number, its record and the physical densities of every cell (for
      /// output per iteration).
      void
      set_callback(const std::function<void(unsigned int, const Iteration &, const std::vector<double> &)> &callback)
      {
        this->callback = callback;
      }

      /// Optimize @p problem (whose mesh defines the cells), from the
      /// uniform design Settings::initial_density.
      Result
      run(DesignProblem &problem);

      /**
       * Optimize @p problem from the densities @p initial (one per cell of
       * its mesh, in [0, 1]; the passive cells' entries are ignored): the
       * design variables start there. With transfer_densities(), the design
       * of a coarser mesh becomes the start of a finer one (a multilevel
       * design: most iterations on the coarse mesh, a few on the fine).
       */
      Result
      run(DesignProblem &problem, const std::vector<double> &initial);

      /**
       * The densities and the chain rule of one design: the physical
       * densities of every cell, the stiffness factors, and, given
       * $\partial J/\partial s_c$, $\partial J/\partial z_i$. Public so that
       * tests check the chain against finite differences.
       */
      struct Chain
      {
        std::vector<unsigned int> design_cells; ///< the designed cells
        std::vector<double>       areas;        ///< their areas
        DensityFilter             filter;       ///< over their centroids
        std::vector<double>       base;         ///< densities of every cell (passive values)
        std::vector<double>       filtered;     ///< P z (design cells)
        std::vector<double>       physical;     ///< the densities of every cell

        /// Fill physical (every cell) from the variables @p z and return
        /// the stiffness factors.
        std::vector<double>
        factors(const std::vector<double> &z, const MaterialInterpolation &m, const HeavisideProjection *h);

        /// $\partial J/\partial z$ from $\partial J/\partial s$ (after factors()).
        std::vector<double>
        variable_gradient(const std::vector<double> &ds, const MaterialInterpolation &m,
                          const HeavisideProjection *h) const;

        /// The volume fraction of the design cells and its gradient.
        double
        volume(std::vector<double> *gradient, const HeavisideProjection *h) const;
      };

      /// The chain of @p mesh for @p settings (design cells, filter).
      static Chain
      make_chain(const PolygonalMesh<2> &mesh, const Settings &settings);

    private:
      Settings settings;
      std::function<void(unsigned int, const Iteration &, const std::vector<double> &)> callback;
    };

    /// "MMA" or "OC" (case-insensitive); throws otherwise.
    TopologyOptimizer::Optimizer
    parse_optimizer(const std::string &name);
  } // namespace Design
} // namespace dealvem

#endif
