// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dealvem/app/polyhedral_elasticity.h>
#include <dealvem/mesh/polyhedral_mesh.h>
#include <dealvem/solvers/parallel_solver.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace dealvem
{
  PolyhedralElasticity::PolyhedralElasticity(const PolyhedralMesh &mesh, const Settings &settings, MPI_Comm comm)
    : mesh(&mesh)
    , settings(settings)
    , comm(comm)
    , n_vertices(mesh.n_vertices())
  {
    settings.material.check();
    AssertThrow(mesh.n_cells() > 0, dealii::ExcMessage("PolyhedralElasticity: the mesh has no cells."));
  }



  unsigned int
  PolyhedralElasticity::n_processes() const
  {
    // a program that never initialized MPI (no MPI_InitFinalize) runs on
    // one process
    return dealii::Utilities::MPI::job_supports_mpi() ? dealii::Utilities::MPI::n_mpi_processes(comm) : 1;
  }



  void
  PolyhedralElasticity::set_body_force(const VectorFunction &f)
  {
    body_force = f;
  }



  void
  PolyhedralElasticity::add_dirichlet(const dealii::types::boundary_id id,
                                      const VectorFunction            &g,
                                      const std::array<bool, 3>       &components)
  {
    dirichlet.push_back({id, g, components});
  }



  void
  PolyhedralElasticity::add_traction(const dealii::types::boundary_id id, const TractionFunction &t)
  {
    tractions.emplace_back(id, t);
  }



  std::vector<std::vector<double>>
  PolyhedralElasticity::rigid_body_modes() const
  {
    // rotations about the centre of the bounding box, scaled by its size so
    // that all six modes have entries of order one
    dealii::Point<3> lo = mesh->vertex(0), hi = mesh->vertex(0);
    for (const auto &p : mesh->get_vertices())
      for (unsigned int d = 0; d < 3; ++d)
        {
          lo[d] = std::min(lo[d], p[d]);
          hi[d] = std::max(hi[d], p[d]);
        }
    const dealii::Point<3>           centre = 0.5 * (lo + hi);
    const double                     size   = std::max(lo.distance(hi), 1e-300);
    std::vector<std::vector<double>> modes(6, std::vector<double>(n_dofs()));
    for (unsigned int v = 0; v < n_vertices; ++v)
      {
        const dealii::Tensor<1, 3> x = (mesh->vertex(v) - centre) / size;
        for (unsigned int d = 0; d < 3; ++d)
          modes[d][3 * v + d] = 1;
        // rotation about axis a: e_a x x
        for (unsigned int a = 0; a < 3; ++a)
          {
            dealii::Tensor<1, 3> axis;
            axis[a]                      = 1;
            const dealii::Tensor<1, 3> r = dealii::cross_product_3d(axis, x);
            for (unsigned int d = 0; d < 3; ++d)
              modes[3 + a][3 * v + d] = r[d];
          }
      }
    return modes;
  }



  void
  PolyhedralElasticity::make_constraints(dealii::AffineConstraints<double> &constraints) const
  {
    const PolyhedralMesh &m   = *mesh;
    const auto            ids = m.get_boundary_ids();
    for (const auto &bc : dirichlet)
      {
        AssertThrow(std::find(ids.begin(), ids.end(), bc.id) != ids.end(),
                    dealii::ExcMessage("PolyhedralElasticity: no boundary face of " + m.name + " has the boundary id " +
                                       std::to_string(bc.id) + " of a prescribed displacement."));
        std::set<unsigned int> nodes;
        for (unsigned int f = 0; f < m.n_faces(); ++f)
          if (m.face(f).at_boundary() && m.face(f).boundary_id == bc.id)
            nodes.insert(m.face(f).vertices.begin(), m.face(f).vertices.end());
        for (const unsigned int v : nodes)
          {
            const dealii::Tensor<1, 3> g = bc.g(m.vertex(v));
            for (unsigned int d = 0; d < 3; ++d)
              if (bc.components[d] && !constraints.is_constrained(3 * v + d))
                {
                  constraints.add_line(3 * v + d);
                  constraints.set_inhomogeneity(3 * v + d, g[d]);
                }
          }
      }
    for (const auto &t : tractions)
      AssertThrow(std::find(ids.begin(), ids.end(), t.first) != ids.end(),
                  dealii::ExcMessage("PolyhedralElasticity: no boundary face of " + m.name + " has the boundary id " +
                                     std::to_string(t.first) + " of a traction."));
    constraints.close();
    {
      // The supports must hold every connected piece of the mesh against its
      // six rigid motions: per piece, the rigid modes restricted to the
      // constrained DoFs must be linearly independent. (Checked per piece: a
      // second body that no support reaches would otherwise pass a check of
      // the whole mesh and make the system singular.)
      std::vector<unsigned int> parent(n_vertices);
      for (unsigned int v = 0; v < n_vertices; ++v)
        parent[v] = v;
      const auto root = [&parent](unsigned int v) {
        while (parent[v] != v)
          v = parent[v] = parent[parent[v]];
        return v;
      };
      std::vector<unsigned int> first_cell(n_vertices, dealii::numbers::invalid_unsigned_int);
      for (unsigned int c = 0; c < m.n_cells(); ++c)
        {
          const auto vertices = m.cell_vertex_indices(c);
          for (const unsigned int v : vertices)
            {
              parent[root(v)] = root(vertices[0]);
              if (first_cell[v] == dealii::numbers::invalid_unsigned_int)
                first_cell[v] = c;
            }
        }
      std::map<unsigned int, std::vector<unsigned int>> pieces; // root -> vertices
      for (unsigned int v = 0; v < n_vertices; ++v)
        pieces[root(v)].push_back(v);
      for (const auto &[piece_root, vertices] : pieces)
        {
          dealii::Point<3> lo = m.vertex(vertices[0]), hi = lo;
          for (const unsigned int v : vertices)
            for (unsigned int d = 0; d < 3; ++d)
              {
                lo[d] = std::min(lo[d], m.vertex(v)[d]);
                hi[d] = std::max(hi[d], m.vertex(v)[d]);
              }
          const dealii::Point<3>           centre = 0.5 * (lo + hi);
          const double                     size   = std::max(lo.distance(hi), 1e-300);
          dealii::LAPACKFullMatrix<double> gram(6, 6);
          for (const unsigned int v : vertices)
            {
              const dealii::Tensor<1, 3> x          = (m.vertex(v) - centre) / size;
              double                     mode[6][3] = {};
              for (unsigned int d = 0; d < 3; ++d)
                mode[d][d] = 1;
              for (unsigned int a = 0; a < 3; ++a)
                {
                  dealii::Tensor<1, 3> axis;
                  axis[a]                      = 1;
                  const dealii::Tensor<1, 3> r = dealii::cross_product_3d(axis, x);
                  for (unsigned int d = 0; d < 3; ++d)
                    mode[3 + a][d] = r[d];
                }
              for (unsigned int d = 0; d < 3; ++d)
                if (constraints.is_constrained(3 * v + d))
                  for (unsigned int a = 0; a < 6; ++a)
                    for (unsigned int b = 0; b < 6; ++b)
                      gram(a, b) += mode[a][d] * mode[b][d];
            }
          gram.compute_eigenvalues();
          double smallest = 1e300, largest = 0;
          for (unsigned int a = 0; a < 6; ++a)
            {
              smallest = std::min(smallest, gram.eigenvalue(a).real());
              largest  = std::max(largest, gram.eigenvalue(a).real());
            }
          AssertThrow(largest > 0 && smallest > 1e-10 * largest,
                      dealii::ExcMessage(
                        "PolyhedralElasticity: the prescribed displacements on " + m.name + " do not hold " +
                        (pieces.size() == 1 ? std::string("the body")
                                            : "the piece of cell " + std::to_string(first_cell[vertices[0]]) + " (" +
                                                std::to_string(vertices.size()) + " vertices; the mesh has " +
                                                std::to_string(pieces.size()) + " pieces)") +
                        " against all six rigid motions (translations and rotations); prescribe displacements on "
                        "more faces or components."));
        }
    }
  }



  void
  PolyhedralElasticity::partition_cells()
  {
    const PolyhedralMesh &m       = *mesh;
    const unsigned int    n_cells = m.n_cells();
    const unsigned int    n_parts = n_processes();
    const unsigned int    me      = n_parts > 1 ? dealii::Utilities::MPI::this_mpi_process(comm) : 0;
    AssertThrow(n_cells >= n_parts,
                dealii::ExcMessage("PolyhedralElasticity: " + m.name + " has " + std::to_string(n_cells) +
                                   " cells, fewer than the " + std::to_string(n_parts) +
                                   " MPI processes; run with fewer processes."));
    cell_owner.assign(n_cells, 0);
    if (n_parts > 1)
      {
        // METIS on the graph of cells sharing a face, on process 0 only:
        // the others receive its answer, so that no two processes can
        // disagree on the partition
        if (me == 0)
          {
            dealii::DynamicSparsityPattern graph(n_cells, n_cells);
            for (unsigned int f = 0; f < m.n_faces(); ++f)
              if (!m.face(f).at_boundary())
                {
                  graph.add(m.face(f).cells[0], m.face(f).cells[1]);
                  graph.add(m.face(f).cells[1], m.face(f).cells[0]);
                }
            dealii::SparsityPattern pattern;
            pattern.copy_from(graph);
            dealii::SparsityTools::partition(pattern, n_parts, cell_owner, dealii::SparsityTools::Partitioner::metis);
          }
        const int ierr = MPI_Bcast(cell_owner.data(), n_cells, MPI_UNSIGNED, 0, comm);
        AssertThrowMPI(ierr);
      }
    owned_cells.clear();
    for (unsigned int c = 0; c < n_cells; ++c)
      if (cell_owner[c] == me)
        owned_cells.push_back(c);
    const unsigned int fewest =
      n_parts > 1 ? dealii::Utilities::MPI::min(static_cast<unsigned int>(owned_cells.size()), comm) : n_cells;
    AssertThrow(fewest > 0, dealii::ExcMessage("PolyhedralElasticity: METIS left an MPI process without cells (" +
                                               std::to_string(n_cells) + " cells over " + std::to_string(n_parts) +
                                               " processes); run with fewer processes."));
  }



  void
  PolyhedralElasticity::solve()
  {
    dealii::Timer         timer;
    const PolyhedralMesh &m = *mesh;
    AssertThrow(m.n_vertices() == n_vertices,
                dealii::ExcMessage("PolyhedralElasticity: the mesh changed since the problem was set up."));
    dealii::AffineConstraints<double> constraints;
    make_constraints(constraints);
    partition_cells();
    const bool         distributed = n_processes() > 1;
    const unsigned int me          = distributed ? dealii::Utilities::MPI::this_mpi_process(comm) : 0;

    // a vertex belongs to the lowest process among those of its cells
    std::vector<std::vector<unsigned int>> cell_vertices(m.n_cells());
    std::vector<unsigned int>              vertex_owner(n_vertices, dealii::numbers::invalid_unsigned_int);
    for (unsigned int c = 0; c < m.n_cells(); ++c)
      {
        cell_vertices[c] = m.cell_vertex_indices(c);
        for (const unsigned int v : cell_vertices[c])
          vertex_owner[v] = std::min(vertex_owner[v], cell_owner[c]);
      }
    // the number of each vertex in the system: its own index on one
    // process; distributed, the vertices of process 0 first, then those of
    // process 1, ... (each in the order of the mesh), so that every process
    // owns a contiguous range of rows: Epetra's maps of contiguous ranges
    // find a row by an offset where a list of rows needs a hash table
    // (doc/benchmarks.md: the assembly on two processes at 3e5 DoFs, 5.1 s
    // with the mesh's numbering, 3.7 s with this one)
    std::vector<unsigned int> number(n_vertices);
    {
      std::vector<unsigned int> first(n_processes() + 1, 0);
      if (distributed)
        for (unsigned int v = 0; v < n_vertices; ++v)
          ++first[vertex_owner[v] + 1];
      for (unsigned int p = 0; p < n_processes(); ++p)
        first[p + 1] += first[p];
      for (unsigned int v = 0; v < n_vertices; ++v)
        number[v] = distributed ? first[vertex_owner[v]]++ : v;
    }
    if (distributed)
      {
        // the supports in that numbering (lines without entries)
        dealii::AffineConstraints<double> renumbered;
        for (const auto &line : constraints.get_lines())
          {
            const unsigned int i = 3 * number[line.index / 3] + line.index % 3;
            renumbered.add_line(i);
            renumbered.set_inhomogeneity(i, line.inhomogeneity);
          }
        renumbered.close();
        constraints.copy_from(renumbered);
      }
    std::vector<dealii::types::global_dof_index> dofs;
    const auto                                   cell_dofs = [&cell_vertices, &dofs, &number](const unsigned int c) {
      dofs.clear();
      for (const unsigned int v : cell_vertices[c])
        for (unsigned int d = 0; d < 3; ++d)
          dofs.push_back(3 * number[v] + d);
    };

    // the cell's stiffness and load; DoFs in the element's vertex order
    const PolyhedralElement     element(settings.stabilization);
    PolyhedralElement::CellData data;
    dealii::Vector<double>      f_local;
    const auto                  local_system = [&](const unsigned int c) {
      element.compute(m, c, &settings.material, data);
      const unsigned int n = 3 * data.vertices.size();
      dofs.resize(n);
      for (unsigned int i = 0; i < data.vertices.size(); ++i)
        for (unsigned int d = 0; d < 3; ++d)
          dofs[3 * i + d] = 3 * number[data.vertices[i]] + d;
      f_local.reinit(n);
      if (body_force)
        {
          // int_E f . phi_j with f at the centroid and the integral of the
          // projection: |E| times the value of Pi phi_j at the centroid
          const dealii::Tensor<1, 3> f = body_force(data.centroid);
          for (unsigned int j = 0; j < n; ++j)
            for (unsigned int d = 0; d < 3; ++d)
              f_local[j] += data.volume * f[d] * data.projector(d, j);
        }
    };
    // tractions: constant on each face (its value at the centroid) times
    // the face integrals of the basis functions; each face by the process
    // of its cell
    const auto add_tractions = [&](auto &F) {
      for (const auto &[id, t] : tractions)
        for (unsigned int f = 0; f < m.n_faces(); ++f)
          if (m.face(f).at_boundary() && m.face(f).boundary_id == id && cell_owner[m.face(f).cells[0]] == me)
            {
              const auto g = m.face_geometry(f);
              // the stored loop points out of the face's only cell
              const dealii::Tensor<1, 3> value = t(g.centroid, g.normal);
              const auto                 w     = PolyhedralElement::face_weights(m, f);
              const auto                &loop  = m.face(f).vertices;
              dealii::Vector<double>     fl(3 * loop.size());
              dofs.resize(3 * loop.size());
              for (unsigned int i = 0; i < loop.size(); ++i)
                for (unsigned int d = 0; d < 3; ++d)
                  {
                    fl[3 * i + d]   = w[i] * value[d];
                    dofs[3 * i + d] = 3 * number[loop[i]] + d;
                  }
              constraints.distribute_local_to_global(fl, dofs, F);
            }
    };

    if (!distributed)
      {
        // the pattern: all DoFs of a cell couple
        dealii::DynamicSparsityPattern dsp(n_dofs(), n_dofs());
        for (unsigned int c = 0; c < m.n_cells(); ++c)
          {
            cell_dofs(c);
            constraints.add_entries_local_to_global(dofs, dsp, false);
          }
        dealii::SparsityPattern pattern;
        pattern.copy_from(dsp);
        dealii::SparseMatrix<double> K(pattern);
        matrix_entries = pattern.n_nonzero_elements();
        dealii::Vector<double> F(n_dofs());
        for (unsigned int c = 0; c < m.n_cells(); ++c)
          {
            local_system(c);
            constraints.distribute_local_to_global(data.stiffness, f_local, dofs, K, F);
          }
        add_tractions(F);
        assembly_time = timer.wall_time();

        timer.restart();
        LinearSolver solver(settings.solver);
        if (settings.solver.type == LinearSolver::Type::cg_amg)
          solver.set_near_null_space(rigid_body_modes());
        solver.solve(K, u, F);
        constraints.distribute(u);
        iterations = solver.last_iterations();
        solve_time = timer.wall_time();
        return;
      }

    // distributed: the rows of this process's vertices; the pattern of its
    // cells, rows of other processes sent to them
    std::vector<dealii::types::global_dof_index> relevant_list;
    unsigned int                                 n_owned = 0, first_owned = n_vertices;
    for (unsigned int v = 0; v < n_vertices; ++v)
      if (vertex_owner[v] == me)
        {
          ++n_owned;
          first_owned = std::min(first_owned, number[v]);
        }
    for (const unsigned int c : owned_cells)
      {
        cell_dofs(c);
        relevant_list.insert(relevant_list.end(), dofs.begin(), dofs.end());
      }
    std::sort(relevant_list.begin(), relevant_list.end());
    relevant_list.erase(std::unique(relevant_list.begin(), relevant_list.end()), relevant_list.end());
    dealii::IndexSet owned(n_dofs()), relevant(n_dofs());
    if (n_owned > 0)
      owned.add_range(3 * first_owned, 3 * (first_owned + n_owned));
    owned.compress();
    relevant.add_indices(relevant_list.begin(), relevant_list.end());
    relevant.add_indices(owned);
    relevant.compress();
    dealii::DynamicSparsityPattern dsp(relevant);
    for (const unsigned int c : owned_cells)
      {
        cell_dofs(c);
        constraints.add_entries_local_to_global(dofs, dsp, false);
      }
    dealii::SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
    dealii::TrilinosWrappers::SparseMatrix K;
    K.reinit(owned, owned, dsp, comm);
    dealii::TrilinosWrappers::MPI::Vector F(owned, comm), x(owned, comm);
    for (const unsigned int c : owned_cells)
      {
        local_system(c);
        constraints.distribute_local_to_global(data.stiffness, f_local, dofs, K, F);
      }
    add_tractions(F);
    K.compress(dealii::VectorOperation::add);
    F.compress(dealii::VectorOperation::add);
    matrix_entries = K.n_nonzero_elements();
    assembly_time  = timer.wall_time();

    timer.restart();
    ParallelLinearSolver solver(settings.solver);
    if (settings.solver.type == LinearSolver::Type::cg_amg)
      {
        auto modes = rigid_body_modes();
        for (auto &mode : modes)
          {
            std::vector<double> renumbered(mode.size());
            for (unsigned int v = 0; v < n_vertices; ++v)
              for (unsigned int d = 0; d < 3; ++d)
                renumbered[3 * number[v] + d] = mode[3 * v + d];
            mode.swap(renumbered);
          }
        solver.set_near_null_space(modes, owned);
      }
    solver.solve(K, x, F);
    iterations = solver.last_iterations();
    // every process gets the whole solution (the mesh is replicated): the
    // owned entries, summed over the processes
    dealii::Vector<double> all(n_dofs());
    for (const auto i : owned)
      all[i] = x(i);
    const int ierr = MPI_Allreduce(MPI_IN_PLACE, all.data(), all.size(), MPI_DOUBLE, MPI_SUM, comm);
    AssertThrowMPI(ierr);
    constraints.distribute(all);
    u.reinit(n_dofs());
    for (unsigned int v = 0; v < n_vertices; ++v)
      for (unsigned int d = 0; d < 3; ++d)
        u[3 * v + d] = all[3 * number[v] + d];
    solve_time = timer.wall_time();
  }



  PolyhedralElasticity::Errors
  PolyhedralElasticity::errors(const VectorFunction                                                &exact,
                               const std::function<dealii::Tensor<2, 3>(const dealii::Point<3> &)> &grad_exact) const
  {
    AssertThrow(u.size() == n_dofs(), dealii::ExcMessage("PolyhedralElasticity::errors() before solve()."));
    const PolyhedralElement       element(settings.stabilization);
    PolyhedralElement::CellData   data;
    std::vector<dealii::Point<3>> points;
    std::vector<double>           weights;
    Errors                        e;
    // each process its own cells, then the sums over the processes
    for (const unsigned int c : owned_cells)
      {
        element.compute(*mesh, c, nullptr, data);
        // the coefficients of Pi u_h
        double coefficients[12] = {};
        for (unsigned int r = 0; r < 12; ++r)
          for (unsigned int i = 0; i < data.vertices.size(); ++i)
            for (unsigned int d = 0; d < 3; ++d)
              coefficients[r] += data.projector(r, 3 * i + d) * u[3 * data.vertices[i] + d];
        dealii::Tensor<2, 3> G;
        for (unsigned int d = 0; d < 3; ++d)
          for (unsigned int k = 0; k < 3; ++k)
            G[d][k] = coefficients[3 + 3 * d + k];
        PolyhedralElement::cell_quadrature(*mesh, c, points, weights);
        for (unsigned int q = 0; q < points.size(); ++q)
          {
            dealii::Tensor<1, 3> value;
            for (unsigned int d = 0; d < 3; ++d)
              value[d] = coefficients[d];
            value += G * (points[q] - data.centroid);
            const dealii::Tensor<1, 3> ue = exact(points[q]);
            const dealii::Tensor<2, 3> ge = grad_exact(points[q]);
            e.l2 += weights[q] * (ue - value).norm_square();
            e.h1_semi += weights[q] * (ge - G).norm_square();
            e.l2_exact += weights[q] * ue.norm_square();
            e.h1_semi_exact += weights[q] * ge.norm_square();
          }
      }
    if (n_processes() > 1)
      {
        double    sums[4] = {e.l2, e.h1_semi, e.l2_exact, e.h1_semi_exact};
        const int ierr    = MPI_Allreduce(MPI_IN_PLACE, sums, 4, MPI_DOUBLE, MPI_SUM, comm);
        AssertThrowMPI(ierr);
        e.l2            = sums[0];
        e.h1_semi       = sums[1];
        e.l2_exact      = sums[2];
        e.h1_semi_exact = sums[3];
      }
    // a signed quadrature can leave a tiny negative sum for an error at
    // round-off level
    e.l2            = std::sqrt(std::max(e.l2, 0.));
    e.h1_semi       = std::sqrt(std::max(e.h1_semi, 0.));
    e.l2_exact      = std::sqrt(std::max(e.l2_exact, 0.));
    e.h1_semi_exact = std::sqrt(std::max(e.h1_semi_exact, 0.));
    return e;
  }



  std::vector<double>
  PolyhedralElasticity::cell_stresses() const
  {
    AssertThrow(u.size() == n_dofs(), dealii::ExcMessage("PolyhedralElasticity::cell_stresses() before solve()."));
    const PolyhedralElement     element(settings.stabilization);
    PolyhedralElement::CellData data;
    const double                lambda = settings.material.lambda(), mu = settings.material.mu();
    std::vector<double>         stress(6 * mesh->n_cells());
    // each process its own cells; the others' by a sum over the processes
    for (const unsigned int c : owned_cells)
      {
        element.compute(*mesh, c, nullptr, data);
        dealii::Tensor<2, 3> G;
        for (unsigned int d = 0; d < 3; ++d)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int i = 0; i < data.vertices.size(); ++i)
              for (unsigned int e = 0; e < 3; ++e)
                G[d][k] += data.projector(3 + 3 * d + k, 3 * i + e) * u[3 * data.vertices[i] + e];
        const double trace = G[0][0] + G[1][1] + G[2][2];
        for (unsigned int d = 0; d < 3; ++d)
          stress[6 * c + d] = lambda * trace + 2 * mu * G[d][d];
        stress[6 * c + 3] = mu * (G[1][2] + G[2][1]);
        stress[6 * c + 4] = mu * (G[0][2] + G[2][0]);
        stress[6 * c + 5] = mu * (G[0][1] + G[1][0]);
      }
    if (n_processes() > 1)
      {
        const int ierr = MPI_Allreduce(MPI_IN_PLACE, stress.data(), stress.size(), MPI_DOUBLE, MPI_SUM, comm);
        AssertThrowMPI(ierr);
      }
    return stress;
  }



  void
  PolyhedralElasticity::write_vtu(const std::string &file_name) const
  {
    const auto         s        = cell_stresses();
    const unsigned int n        = mesh->n_cells();
    static const char *names[6] = {"stress_xx", "stress_yy", "stress_zz", "stress_yz", "stress_xz", "stress_xy"};
    std::vector<std::pair<std::string, std::vector<double>>> cell_fields;
    for (unsigned int k = 0; k < 6; ++k)
      {
        std::vector<double> values(n);
        for (unsigned int c = 0; c < n; ++c)
          values[c] = s[6 * c + k];
        cell_fields.emplace_back(names[k], std::move(values));
      }
    std::vector<double> von_mises(n);
    for (unsigned int c = 0; c < n; ++c)
      {
        const double *t = &s[6 * c];
        von_mises[c]    = std::sqrt(
             0.5 * ((t[0] - t[1]) * (t[0] - t[1]) + (t[1] - t[2]) * (t[1] - t[2]) + (t[2] - t[0]) * (t[2] - t[0])) +
             3 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]));
      }
    cell_fields.emplace_back("von_mises", std::move(von_mises));
    if (n_processes() > 1)
      cell_fields.emplace_back("process", std::vector<double>(cell_owner.begin(), cell_owner.end()));
    if (n_processes() == 1 || dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      mesh->write_vtu(file_name, {{"displacement", std::vector<double>(u.begin(), u.end())}}, cell_fields);
  }
} // namespace dealvem
