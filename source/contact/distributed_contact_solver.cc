// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dealvem/contact/distributed_contact_solver.h>
#include <dealvem/elasticity/elasticity_assembler.h>
#include <dealvem/solvers/contact_constraints.h>
#include <dealvem/solvers/parallel_solver.h>
#include <dealvem/vem/partitioning.h>

#include "../solvers/two_level_cycle.h"

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace dealvem
{
  DistributedContactSolver::DistributedContactSolver(const Settings                          &settings,
                                                     const VEMPartition<2>                   &partition,
                                                     const dealii::AffineConstraints<double> &displacement_constraints,
                                                     const MPI_Comm                           comm)
    : SaddlePointSolver(settings)
    , partition(partition)
    , displacement_constraints(displacement_constraints)
    , comm(comm)
  {
    AssertThrow(is_condensed(settings.type),
                dealii::ExcMessage("Solver/Type = " + type_name(settings.type) +
                                   " works on the whole saddle-point system, which is not distributed: with more "
                                   "than one MPI process, contact is solved with the constraints condensed. Use "
                                   "'CG-AMG' or 'direct constraints' (the condensed system factored by Amesos "
                                   "KLU), or 'automatic'."));
  }



  void
  DistributedContactSolver::set_assembler(const ElasticityAssembler<2> &a)
  {
    assembler = &a;
  }



  std::string
  DistributedContactSolver::description() const
  {
    const unsigned int np = dealii::Utilities::MPI::n_mpi_processes(comm);
    const std::string preconditioner = uses_p_multigrid() ? " + p-multigrid (Chebyshev on k = 2, ML AMG on the "
                                                            "k = 1 level with the contact constraints of the vertices)" :
                                                            " + ML AMG";
    return std::string(settings.type == Type::cg_amg_constraints ? (used_gmres ? "GMRES" : "CG") + preconditioner :
                                                                 "Amesos KLU (direct)") +
           " on the stiffness condensed by the active contact constraints, distributed over " +
           std::to_string(np) + " MPI process" + (np > 1 ? "es" : "") +
           " (one slave DoF per constraint, multipliers from the residual" +
           std::string(used_gmres ? "; slipping pairs: Petrov-Galerkin condensation, not symmetric" : "") +
           std::string(used_stick_preconditioner ? "; stick springs preconditioned by tying them" : "") + ")";
  }



  namespace
  {
    /**
     * The two-subspace preconditioner of the stick penalty (see
     * SaddlePointSolver::set_stick_directions()) on the distributed path:
     * M^{-1} r = Z AMG(Z^T K Z) Z^T r + sum_s e_s r_s / K_ss. The tie lines
     * Z are few (one per active pair at most) and known on every process;
     * Z^T and Z exchange the values of their slaves and masters by one
     * small reduction each. Z^T K Z is assembled from the cells with the
     * ties as further constraints (the springs vanish on tied functions).
     * Its inverse is approximated by the p-multigrid when a coarse space
     * @p P is given (the normal and tie lines carried to the coarse level,
     * as in the serial StickPreconditioner), else by ML AMG.
     */
    class DistributedStickPreconditioner
    {
    public:
      DistributedStickPreconditioner(const dealii::TrilinosWrappers::SparseMatrix &K,
                                     const ContactConstraints                     &ties,
                                     const dealii::AffineConstraints<double>      &tied,
                                     const dealii::TrilinosWrappers::SparseMatrix &K_tied,
                                     const std::vector<std::vector<double>>       &modes,
                                     const VEMPartition<2>                        &partition,
                                     const dealii::SparseMatrix<double>           *P,
                                     const std::vector<std::vector<double>>       &coarse_modes,
                                     const MPI_Comm                                comm)
        : K(K)
        , comm(comm)
      {
        const dealii::IndexSet &owned = partition.locally_owned_dofs();
        std::set<unsigned int>  master_set;
        for (const auto &line : ties.get_constraints().get_lines())
          {
            lines.emplace_back(line.index, line.entries);
            for (const auto &e : line.entries)
              master_set.insert(e.first);
          }
        masters.assign(master_set.begin(), master_set.end());
        for (unsigned int k = 0; k < masters.size(); ++k)
          master_index[masters[k]] = k;

        // the p-multigrid (or AMG) on Z^T K Z, assembled with K
        if (P != nullptr)
          cycle = internal::make_distributed_two_level(K_tied, *P, coarse_modes, &tied, LinearSolver::Settings(),
                                                       comm, P_trilinos);
        else
          {
            std::vector<std::vector<double>> local(modes.size());
            for (unsigned int k = 0; k < modes.size(); ++k)
              for (const auto i : owned)
                local[k].push_back(modes[k][i]);
            Teuchos::ParameterList list;
            internal::set_ml_parameters(&list, local, owned.n_elements(), null_space);
            amg.initialize(K_tied.trilinos_matrix(), list);
          }
        w.reinit(owned, comm);
        v.reinit(owned, comm);
      }

      void
      vmult(dealii::TrilinosWrappers::MPI::Vector &dst, const dealii::TrilinosWrappers::MPI::Vector &src) const
      {
        // (local arrays only: element access to Trilinos vectors would need
        // a compress() whose mode every process must agree on)
        const dealii::IndexSet &owned = src.locally_owned_elements();
        const auto local = [&](const unsigned int i) { return owned.index_within_set(i); };
        const double *s  = src.begin();
        // Z^T: the slaves' entries go to their masters
        std::vector<double> slave_values(lines.size(), 0.);
        for (unsigned int k = 0; k < lines.size(); ++k)
          if (owned.is_element(lines[k].first))
            slave_values[k] = s[local(lines[k].first)];
        dealii::Utilities::MPI::sum(slave_values, comm, slave_values);
        w        = src;
        double *wp = w.begin();
        for (unsigned int k = 0; k < lines.size(); ++k)
          {
            for (const auto &e : lines[k].second)
              if (owned.is_element(e.first))
                wp[local(e.first)] += e.second * slave_values[k];
            if (owned.is_element(lines[k].first))
              wp[local(lines[k].first)] = 0.;
          }
        if (cycle)
          cycle->vmult(v, w);
        else
          amg.vmult(v, w);
        // Z: the slaves from their masters, plus the diagonal correction
        const double       *vp = v.begin();
        std::vector<double> master_values(masters.size(), 0.);
        for (unsigned int k = 0; k < masters.size(); ++k)
          if (owned.is_element(masters[k]))
            master_values[k] = vp[local(masters[k])];
        dealii::Utilities::MPI::sum(master_values, comm, master_values);
        dst        = v;
        double *dp = dst.begin();
        for (const auto &line : lines)
          if (owned.is_element(line.first))
            {
              double value = 0;
              for (const auto &e : line.second)
                value += e.second * master_values[master_index.at(e.first)];
              dp[local(line.first)] = value + s[local(line.first)] / K.diag_element(line.first);
            }
      }

    private:
      const dealii::TrilinosWrappers::SparseMatrix                                  &K;
      MPI_Comm                                                                       comm;
      std::vector<std::pair<unsigned int, std::vector<std::pair<unsigned int, double>>>> lines;
      std::vector<unsigned int>                                                      masters;
      std::map<unsigned int, unsigned int>                                               master_index;
      std::vector<double>                                                            null_space;
      dealii::TrilinosWrappers::PreconditionAMG                                      amg;
      dealii::TrilinosWrappers::SparseMatrix                                         P_trilinos;
      std::unique_ptr<internal::TwoLevelCycle<dealii::TrilinosWrappers::MPI::Vector>> cycle;
      mutable dealii::TrilinosWrappers::MPI::Vector                                  w, v;
    };



    using DoFMap = std::map<dealii::types::global_dof_index, std::map<dealii::types::global_dof_index, double>>;
    using LineDifferences = std::vector<std::pair<unsigned int, std::vector<std::pair<unsigned int, double>>>>;

    // Step 1: the displacement constraints and the contact's slave lines in
    // one closed set of constraints.
    void
    merge_constraints(const dealii::AffineConstraints<double> &first,
                      const dealii::AffineConstraints<double> &second,
                      dealii::AffineConstraints<double>       &all)
    {
      for (const auto *c : {&first, &second})
        for (const auto &line : c->get_lines())
          {
            all.add_line(line.index);
            all.add_entries(line.index, line.entries);
            all.set_inhomogeneity(line.index, line.inhomogeneity);
          }
      all.close();
    }



    // The multiplier rows of A (rows n to n + m) whose displacement entries
    // belong to nodes of more than one process.
    unsigned int
    count_rows_across(const dealii::SparseMatrix<double> &A,
                      const unsigned int                  n,
                      const unsigned int                  m,
                      const VEMPartition<2>              &partition)
    {
      unsigned int n_across = 0;
      for (unsigned int r = 0; r < m; ++r)
        {
          unsigned int owner = dealii::numbers::invalid_unsigned_int;
          bool         cut   = false;
          for (auto it = A.begin(n + r), it_end = A.end(n + r); it != it_end; ++it)
            if (it->column() < n && it->value() != 0.)
              {
                const unsigned int o = partition.node_owner(it->column() / 2);
                cut                  = cut || (owner != dealii::numbers::invalid_unsigned_int && o != owner);
                owner                = o;
              }
          n_across += cut;
        }
      return n_across;
    }



    // Step 2, the spring rows: the rows of the contact blocks' displacement
    // part (springs, right-hand side with the forces of the known
    // multipliers) that this process adds, those of its owned DoFs that the
    // displacement constraints leave free; their DoFs (through the merged
    // constraints) join @p relevant.
    struct SpringRows
    {
      std::vector<std::vector<dealii::types::global_dof_index>> dofs;
      std::vector<std::vector<double>>                          values;
      std::vector<double>                                       rhs;
    };

    void
    collect_spring_rows(const dealii::SparseMatrix<double>      &A,
                        const dealii::Vector<double>            &b,
                        const unsigned int                       n,
                        const std::vector<double>               &known,
                        const dealii::IndexSet                  &owned,
                        const dealii::AffineConstraints<double> &displacement_constraints,
                        const dealii::AffineConstraints<double> &all,
                        dealii::IndexSet                        &relevant,
                        SpringRows                              &rows)
    {
      for (const auto i : owned)
        {
          if (displacement_constraints.is_constrained(i))
            continue;
          std::vector<dealii::types::global_dof_index> dofs{i};
          std::vector<double>                          values{0.};
          double                                       rhs = b[i];
          for (auto it = A.begin(i), it_end = A.end(i); it != it_end; ++it)
            {
              const auto j = it->column();
              if (it->value() == 0.)
                continue;
              if (j >= n)
                rhs -= it->value() * known[j - n];
              else if (j == i)
                values[0] = it->value();
              else
                {
                  dofs.push_back(j);
                  values.push_back(it->value());
                }
            }
          if (dofs.size() == 1 && values[0] == 0. && rhs == 0.)
            continue;
          for (const auto d : dofs)
            {
              relevant.add_index(d);
              if (all.is_constrained(d))
                for (const auto &e : *all.get_constraint_entries(d))
                  relevant.add_index(e.first);
            }
          rows.dofs.push_back(std::move(dofs));
          rows.values.push_back(std::move(values));
          rows.rhs.push_back(rhs);
        }
    }



    // Step 2, Petrov-Galerkin (slipping pairs): the slaves whose test line
    // differs from the trial line, the owned cells around them, and the
    // masters of the difference, which receive the slave's row of K C.
    struct PetrovGalerkinCorrection
    {
      DoFMap                                                    slave_rows;
      std::vector<unsigned int>                                 cells;
      std::vector<std::vector<dealii::types::global_dof_index>> columns;
    };

    void
    prepare_correction(const dealii::SparseMatrix<double>      &A,
                       const unsigned int                       n,
                       const LineDifferences                   &differences,
                       const dealii::IndexSet                  &owned,
                       const dealii::AffineConstraints<double> &all,
                       const VEMPartition<2>                   &partition,
                       const VEMDoFHandler<2>                  &dof_handler,
                       dealii::IndexSet                        &relevant,
                       PetrovGalerkinCorrection                &correction)
    {
      auto                                        &slave_rows = correction.slave_rows;
      std::vector<dealii::types::global_dof_index> dof_indices;
      correction.columns.resize(differences.size());
      for (const auto &d : differences)
        slave_rows[d.first];
      for (const unsigned int c : partition.locally_owned_cells())
        {
          dof_handler.get_dof_indices(c, dof_indices);
          for (const auto d : dof_indices)
            if (slave_rows.count(d) > 0)
              {
                correction.cells.push_back(c);
                break;
              }
        }
      // the columns of the slaves' rows: the DoFs of their cells and of
      // their spring rows, through the constraints
      std::map<dealii::types::global_dof_index, std::set<dealii::types::global_dof_index>> columns;
      for (const unsigned int c : correction.cells)
        {
          dof_handler.get_dof_indices(c, dof_indices);
          for (const auto s : dof_indices)
            if (slave_rows.count(s) > 0)
              columns[s].insert(dof_indices.begin(), dof_indices.end());
        }
      for (unsigned int k = 0; k < differences.size(); ++k)
        {
          const auto s = differences[k].first;
          if (owned.is_element(s))
            for (auto it = A.begin(s), it_end = A.end(s); it != it_end; ++it)
              if (it->column() < n)
                columns[s].insert(it->column());
          for (const auto j : columns[s])
            if (all.is_constrained(j))
              for (const auto &e : *all.get_constraint_entries(j))
                correction.columns[k].push_back(e.first);
            else
              correction.columns[k].push_back(j);
          for (const auto &e : differences[k].second)
            relevant.add_index(e.first);
          for (const auto j : correction.columns[k])
            relevant.add_index(j);
        }
    }



    // Step 2: the condensed stiffness and load of the owned cells, plus the
    // spring rows, in a matrix with the sparsity of both and of the
    // Petrov-Galerkin correction (not compressed). With @p tied (stick by
    // penalty), also the cells condensed by those constraints into
    // @p K_tied, on the same pattern (which then holds the entries of both
    // sets of constraints).
    void
    assemble_condensed(const SpringRows                        &rows,
                       const LineDifferences                   &differences,
                       const PetrovGalerkinCorrection          &correction,
                       const dealii::IndexSet                  &owned,
                       const dealii::IndexSet                  &relevant,
                       const dealii::AffineConstraints<double> &all,
                       const VEMPartition<2>                   &partition,
                       const ElasticityAssembler<2>            &assembler,
                       const MPI_Comm                           comm,
                       dealii::TrilinosWrappers::SparseMatrix  &K,
                       dealii::TrilinosWrappers::MPI::Vector   &f,
                       const dealii::AffineConstraints<double> *tied,
                       dealii::TrilinosWrappers::SparseMatrix  *K_tied)
    {
      dealii::DynamicSparsityPattern dsp(relevant);
      partition.make_sparsity_pattern(dsp, all);
      if (tied != nullptr)
        partition.make_sparsity_pattern(dsp, *tied);
      for (const auto &dofs : rows.dofs)
        all.add_entries_local_to_global(dofs, dsp, false);
      for (unsigned int k = 0; k < differences.size(); ++k)
        for (const auto &e : differences[k].second)
          dsp.add_entries(e.first, correction.columns[k].begin(), correction.columns[k].end());
      dealii::SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
      K.reinit(owned, owned, dsp, comm);
      if (tied != nullptr)
        {
          // the stiffness tied by the stick springs on K's pattern (a
          // copy of the graph, the values zero yet), from the same cell
          // matrices
          K_tied->reinit(K);
          assembler.assemble(all, partition.locally_owned_cells(), K, f, *tied, *K_tied);
        }
      else
        assembler.assemble(all, partition.locally_owned_cells(), K, f);
      for (unsigned int k = 0; k < rows.dofs.size(); ++k)
        {
          // one row of a "cell" whose other rows are zero: condensation is
          // linear in the local matrix, so row by row adds up to the whole
          const unsigned int         s = rows.dofs[k].size();
          dealii::FullMatrix<double> local(s, s);
          dealii::Vector<double>     local_rhs(s);
          for (unsigned int j = 0; j < s; ++j)
            local(0, j) = rows.values[k][j];
          local_rhs[0] = rows.rhs[k];
          all.distribute_local_to_global(local, local_rhs, rows.dofs[k], K, f);
        }
    }



    // Step 2: Z^T K C = C^T K C + (Z - C)^T K C: this process's part of each
    // slave's row of K C (its owned cells; the spring row on the owner) and
    // of f - K c, times the difference of the lines.
    void
    add_correction(const dealii::SparseMatrix<double>      &A,
                   const dealii::Vector<double>            &b,
                   const unsigned int                       n,
                   const std::vector<double>               &known,
                   const LineDifferences                   &differences,
                   PetrovGalerkinCorrection                &correction,
                   const dealii::IndexSet                  &owned,
                   const dealii::AffineConstraints<double> &all,
                   const ElasticityAssembler<2>            &assembler,
                   const MPI_Comm                           comm,
                   dealii::TrilinosWrappers::SparseMatrix  &K,
                   dealii::TrilinosWrappers::MPI::Vector   &f)
    {
      auto &slave_rows = correction.slave_rows;
      assembler.add_matrix_rows(correction.cells, slave_rows);
      dealii::Vector<double> c(n), r(n);
      all.distribute(c); // the inhomogeneities
      assembler.add_residual(correction.cells, c, dealii::Utilities::MPI::this_mpi_process(comm) == 0, r);
      for (const auto &d : differences)
        {
          const auto s   = d.first;
          auto      &row = slave_rows[s];
          double     rs  = r[s];
          if (owned.is_element(s))
            {
              rs += b[s];
              for (auto it = A.begin(s), it_end = A.end(s); it != it_end; ++it)
                {
                  const auto j = it->column();
                  if (j >= n)
                    rs -= it->value() * known[j - n];
                  else
                    {
                      row[j] += it->value();
                      rs -= it->value() * c[j];
                    }
                }
            }
          std::map<dealii::types::global_dof_index, double> condensed;
          for (const auto &e : row)
            if (all.is_constrained(e.first))
              {
                for (const auto &l : *all.get_constraint_entries(e.first))
                  condensed[l.first] += e.second * l.second;
              }
            else
              condensed[e.first] += e.second;
          std::vector<dealii::types::global_dof_index> cols;
          std::vector<double>                          values;
          for (const auto &e : condensed)
            if (e.second != 0.)
              {
                cols.push_back(e.first);
                values.push_back(e.second);
              }
          for (const auto &e : d.second)
            {
              std::vector<double> v(values);
              for (auto &x : v)
                x *= e.second;
              K.add(e.first, cols.size(), cols.data(), v.data());
              f.add(std::vector<dealii::types::global_dof_index>{e.first}, std::vector<double>{e.second * rs});
            }
        }
    }



    // Step 3 with stick by penalty: CG (GMRES when not symmetric) with the
    // two-subspace preconditioner; returns the iterations.
    unsigned int
    solve_with_stick_preconditioner(const dealii::TrilinosWrappers::SparseMatrix &K,
                                    const DistributedStickPreconditioner         &preconditioner,
                                    const unsigned int                            max_iterations,
                                    const double                                  relative_tolerance,
                                    const bool                                    gmres_solve,
                                    dealii::TrilinosWrappers::MPI::Vector        &u,
                                    const dealii::TrilinosWrappers::MPI::Vector  &f)
    {
      const double target = relative_tolerance * f.l2_norm();
      using Vector        = dealii::TrilinosWrappers::MPI::Vector;
      unsigned int iterations = 0;
      // The Krylov methods stop on their recurred residual, which on these
      // matrices (stiff springs) can drift from the true one by more than
      // the tolerance: solve again for the true residual, at most twice
      // (iterative refinement), until |f - K u| <= tol |f| or the true
      // residual is at the floor that rounding in K u leaves, a normwise
      // backward error |f - K u| / (|K| |u| + |f|) (max norms) of 1e-10:
      // the serial solver's acceptance (internal::check_residual), so that
      // both accept the same solutions. (Refining below that floor had cost
      // two more solves of 5 iterations each on a 2.3e5-DoF stick-penalty
      // patch test, 33 against the serial 24 iterations, for a residual
      // 2.5 times the target after the first solve.)
      const double K_norm = K.linfty_norm();
      Vector       r(f), d(f);
      for (unsigned int round = 0; round < 3; ++round)
        {
          const bool first = round == 0;
          if (!first)
            {
              K.vmult(r, u);
              r.sadd(-1., 1., f);
              if (r.l2_norm() <= target || r.linfty_norm() <= 1e-10 * (K_norm * u.linfty_norm() + f.linfty_norm()))
                break;
              d = 0;
            }
          dealii::SolverControl       control(max_iterations, target);
          dealii::SolverCG<Vector>    cg(control);
          dealii::SolverGMRES<Vector> gmres(control, dealii::SolverGMRES<Vector>::AdditionalData(200, true));
          try
            {
              Vector &x = first ? u : d;
              if (gmres_solve)
                gmres.solve(K, x, first ? f : r, preconditioner);
              else
                cg.solve(K, x, first ? f : r, preconditioner);
            }
          catch (const dealii::SolverControl::NoConvergence &e)
            {
              AssertThrow(false, dealii::ExcMessage("CG-AMG constraints (stick penalty) did not converge: residual " +
                                                    std::to_string(e.last_residual) + " after " +
                                                    std::to_string(e.last_step) + " iterations (target " +
                                                    std::to_string(control.tolerance()) + ")."));
            }
          iterations += control.last_step();
          if (!first)
            u += d;
        }
      return iterations;
    }



    // Step 4: the elastic forces on the slave DoFs, added to @p b. The
    // residual rows the multipliers need are the slaves and the DoFs whose
    // displacement constraint refers to a slave (their rows are condensed
    // into the slave's); only the owned cells around them contribute, summed
    // over the processes in rank order.
    void
    add_slave_residuals(const ContactConstraints                &contact,
                        const dealii::AffineConstraints<double> &displacement_constraints,
                        const unsigned int                       n,
                        const VEMPartition<2>                   &partition,
                        const ElasticityAssembler<2>            &assembler,
                        const MPI_Comm                           comm,
                        const dealii::Vector<double>            &full,
                        dealii::Vector<double>                  &b)
    {
      const auto       &dof_handler = assembler.get_dof_handler();
      std::vector<bool> is_slave(n, false);
      for (const auto &sl : contact.get_slaves())
        is_slave[sl.second] = true;
      std::vector<unsigned int>                                            targets;
      std::vector<int>                                                     target_of(n, -1);
      std::map<unsigned int, std::vector<std::pair<unsigned int, double>>> folded;
      for (const auto &sl : contact.get_slaves())
        {
          target_of[sl.second] = targets.size();
          targets.push_back(sl.second);
        }
      for (const auto &line : displacement_constraints.get_lines())
        for (const auto &e : line.entries)
          if (e.first < n && is_slave[e.first])
            {
              if (target_of[line.index] < 0)
                {
                  target_of[line.index] = targets.size();
                  targets.push_back(line.index);
                }
              folded[e.first].emplace_back(line.index, e.second);
            }
      std::vector<unsigned int>                    cells;
      std::vector<dealii::types::global_dof_index> dof_indices;
      for (const unsigned int c : partition.locally_owned_cells())
        {
          dof_handler.get_dof_indices(c, dof_indices);
          for (const auto d : dof_indices)
            if (target_of[d] >= 0)
              {
                cells.push_back(c);
                break;
              }
        }
      dealii::Vector<double> r(n);
      assembler.add_residual(cells, full, dealii::Utilities::MPI::this_mpi_process(comm) == 0, r);
      std::vector<double> local_r(targets.size());
      for (unsigned int k = 0; k < targets.size(); ++k)
        local_r[k] = r[targets[k]];
      const auto          parts = dealii::Utilities::MPI::all_gather(comm, local_r);
      std::vector<double> target_r(targets.size(), 0.);
      for (const auto &p : parts) // in rank order on every process: the same bits
        for (unsigned int k = 0; k < targets.size(); ++k)
          target_r[k] += p[k];

      for (const auto &sl : contact.get_slaves())
        {
          const unsigned int s  = sl.second;
          double             v  = target_r[target_of[s]];
          const auto         fo = folded.find(s);
          if (fo != folded.end())
            for (const auto &e : fo->second)
              v += e.second * target_r[target_of[e.first]];
          b[s] += v;
        }
    }
  } // namespace



  void
  DistributedContactSolver::solve(const dealii::SparseMatrix<double> &A,
                                  const unsigned int                  n,
                                  dealii::Vector<double>             &x,
                                  const dealii::Vector<double>       &b)
  {
    AssertThrow(assembler != nullptr,
                dealii::ExcMessage("DistributedContactSolver: set_assembler() was not called."));
    AssertDimension(A.m(), b.size());
    const unsigned int m = A.m() - n;
    x.reinit(b.size());

    // 1. the active constraints as slave lines, merged with the
    //    displacement constraints
    double length = 0;
    if (modes.size() == 3)
      for (const double v : modes[2])
        length = std::max(length, std::abs(v));
    ContactConstraints contact;
    contact.reinit(A, n, b, length, 1e-10, &displacement_constraints);
    n_dropped = contact.get_dependent_rows().size();
    dealii::AffineConstraints<double> all;
    merge_constraints(displacement_constraints, contact.get_constraints(), all);
    n_rows_across = count_rows_across(A, n, m, partition);

    // known multipliers (inactive, and the constant parts of tied ones):
    // their forces go to the right-hand side
    const std::vector<double> known = contact.known_multipliers();

    // the stick springs' ties (stick by penalty with CG-AMG): the
    // preconditioner's stiffness Z^T K Z is K's cells condensed by the
    // displacement, contact and tie lines together (the springs vanish on
    // tied functions), assembled with K in step 2 (a slave of a tie must
    // be free of all constraints so far)
    const bool                        with_stick = !stick_rows.empty() && settings.type == Type::cg_amg_constraints;
    ContactConstraints                ties;
    dealii::AffineConstraints<double> tied;
    dealii::TrilinosWrappers::SparseMatrix K_tied;
    if (with_stick)
      {
        ties = ContactConstraints::tie_lines(stick_rows, contact.get_constraints(), all, n, length);
        merge_constraints(all, ties.get_constraints(), tied);
      }

    // 2. the condensed stiffness: the owned cells, the spring rows of the
    //    owned DoFs and (slipping pairs) the Petrov-Galerkin correction
    const dealii::IndexSet &owned    = partition.locally_owned_dofs();
    dealii::IndexSet        relevant = partition.locally_relevant_dofs(all);
    if (with_stick)
      relevant.add_indices(partition.locally_relevant_dofs(tied));
    SpringRows              rows;
    collect_spring_rows(A, b, n, known, owned, displacement_constraints, all, relevant, rows);
    const auto              &differences = contact.get_line_differences();
    PetrovGalerkinCorrection correction;
    if (!differences.empty())
      prepare_correction(
        A, n, differences, owned, all, partition, assembler->get_dof_handler(), relevant, correction);
    relevant.compress();
    dealii::TrilinosWrappers::SparseMatrix K;
    dealii::TrilinosWrappers::MPI::Vector  f(owned, comm), u(owned, comm);
    assemble_condensed(rows, differences, correction, owned, relevant, all, partition, *assembler, comm, K, f,
                       with_stick ? &tied : nullptr, with_stick ? &K_tied : nullptr);
    if (!differences.empty())
      add_correction(A, b, n, known, differences, correction, owned, all, *assembler, comm, K, f);
    K.compress(dealii::VectorOperation::add);
    f.compress(dealii::VectorOperation::add);

    // 3. the condensed solve (GMRES instead of CG where slipping pairs make
    //    the condensed matrix non-symmetric; KLU factors either)
    LinearSolver::Settings linear;
    linear.type = (settings.type == Type::cg_amg_constraints ? LinearSolver::Type::cg_amg : LinearSolver::Type::klu);
    linear.relative_tolerance = settings.relative_tolerance;
    linear.max_iterations     = settings.max_iterations;
    linear.symmetric          = contact.is_symmetric();
    used_gmres                = !contact.is_symmetric();
    if (settings.warm_start && previous.size() == n && linear.type == LinearSolver::Type::cg_amg)
      {
        for (const auto i : owned)
          u(i) = previous[i];
        u.compress(dealii::VectorOperation::insert);
      }
    used_stick_preconditioner = false;
    if (with_stick)
      {
        // stick by penalty: CG with the two-subspace preconditioner
        const DistributedStickPreconditioner preconditioner(K, ties, tied, K_tied, modes, partition,
                                                            uses_p_multigrid() ? coarse_prolongation : nullptr,
                                                            coarse_modes, comm);
        iterations                = solve_with_stick_preconditioner(
          K, preconditioner, settings.max_iterations, settings.relative_tolerance, used_gmres, u, f);
        used_stick_preconditioner = true;
      }
    else
      {
        ParallelLinearSolver solver(linear);
        if (linear.type == LinearSolver::Type::cg_amg)
          {
            solver.set_near_null_space(modes, owned);
            // the p-multigrid, its coarse level tied by the contact
            // constraints between vertices as the condensed matrix is
            if (uses_p_multigrid())
              solver.set_coarse_space(*coarse_prolongation, coarse_modes, &all);
          }
        solver.solve(K, u, f);
        iterations = solver.last_iterations();
      }
    stick_rows.clear();

    // 4. the displacements on every process, then the multipliers
    dealii::Vector<double> mine(n), full(n);
    for (const auto i : owned)
      mine[i] = u[i];
    // one contribution per entry: the sum is exact
    dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(mine.data(), n), comm,
                                dealii::ArrayView<double>(full.data(), n));
    all.distribute(full);
    if (linear.type == LinearSolver::Type::cg_amg)
      previous = full;
    dealii::Vector<double> b_with_elasticity(b);
    add_slave_residuals(contact, displacement_constraints, n, partition, *assembler, comm, full, b_with_elasticity);
    for (unsigned int i = 0; i < n; ++i)
      x[i] = full[i];
    contact.distribute_and_recover_multipliers(A, b_with_elasticity, x);
    for (unsigned int i = 0; i < x.size(); ++i)
      AssertThrow(std::isfinite(x[i]),
                  dealii::ExcMessage("The distributed contact solve produced a non-finite value: the condensed "
                                     "system is singular (is every body supported?)."));
  }
} // namespace dealvem
