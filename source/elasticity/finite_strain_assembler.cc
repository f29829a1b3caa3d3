// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/memory_consumption.h>

#include <dealvem/elasticity/finite_strain_assembler.h>
#include <dealvem/elasticity/hyperelastic_material.h>
#include <dealvem/vem/vem_values.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

namespace dealvem
{
  std::string
  pressure_load_name(const PressureLoad kind)
  {
    return kind == PressureLoad::dead ? "dead" : "follower";
  }



  PressureLoad
  parse_pressure_load(const std::string &value, const std::string &parameter)
  {
    std::string v;
    for (const char c : value)
      v += char(std::tolower(static_cast<unsigned char>(c)));
    const auto first = v.find_first_not_of(" \t");
    const auto last  = v.find_last_not_of(" \t");
    v                = (first == std::string::npos ? std::string() : v.substr(first, last - first + 1));
    if (v == "dead")
      return PressureLoad::dead;
    if (v == "follower")
      return PressureLoad::follower;
    AssertThrow(false, dealii::ExcMessage("Parameter '" + parameter + "' = '" + value +
                                          "' is not a kind of pressure load: use 'follower' (the pressure acts "
                                          "on the deformed boundary, along its current normal) or 'dead' (the "
                                          "nominal traction -p N on the undeformed boundary)."));
    return PressureLoad::follower;
  }




  namespace finite_strain_assembler_kernels
  {
    // The consistency part of one cell from its cell data (see the class
    // documentation): with F_q = I + sum_m q_m(x_q) F_m, F_m = sum_i u_i g_im,
    //   r_i  = sum_m g_im : S_m,          S_m  = sum_q w_q q_m P(F_q),
    //   K_ik = sum_ml g_im : B_ml : g_kl, B_ml = sum_q w_q q_m q_l A(F_q).
    // g_im has only the row c = i % 2. N_M: the number of monomials (1 or
    // 3), a constant so that the loops unroll.
    template <int dim, unsigned int N_M>
    void
    cell_consistency(const ConstitutiveLaw<dim> &law,
                     const unsigned int          cell,
                     const unsigned int          n,
                     const double               *g,
                     const unsigned int          n_q,
                     const double               *w,
                     const double               *q_values,
                     const double               *local_u,
                     const bool                  with_tangent,
                     double                     *r,
                     dealii::FullMatrix<double> *K,
                     std::vector<double>        &scratch)
    {
      constexpr unsigned int n_pairs = N_M * (N_M + 1) / 2;
      constexpr unsigned int d2 = dim * dim, d4 = d2 * d2;
      // F_m
      double F_m[N_M][dim][dim] = {};
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int c  = i % dim;
          const double       ui = local_u[i];
          for (unsigned int j = 0; j < dim; ++j)
            for (unsigned int m = 0; m < N_M; ++m)
              F_m[m][c][j] += ui * g[(i * dim + j) * N_M + m];
        }
      // the moments of P and A
      double                 S[N_M][dim][dim] = {};
      double                 B[n_pairs][d4]   = {};
      dealii::Tensor<2, dim> F, P;
      dealii::Tensor<4, dim> A;
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const double *qv = q_values + q * N_M;
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              {
                double v = (a == b ? 1. : 0.);
                for (unsigned int m = 0; m < N_M; ++m)
                  v += qv[m] * F_m[m][a][b];
                F[a][b] = v;
              }
          const double J = dealii::determinant(F);
          AssertThrow(J > 0 && std::isfinite(J), ExcInvertedCell(cell, q, J));
          if (with_tangent)
            law.first_piola_kirchhoff_stress_and_tangent(F, P, A);
          else
            P = law.first_piola_kirchhoff_stress(F);
          for (unsigned int m = 0; m < N_M; ++m)
            {
              const double wm = w[q] * qv[m];
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  S[m][a][b] += wm * P[a][b];
            }
          if (!with_tangent)
            continue;
          double A_flat[d4];
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              for (unsigned int c = 0; c < dim; ++c)
                for (unsigned int d = 0; d < dim; ++d)
                  A_flat[((a * dim + b) * dim + c) * dim + d] = A[a][b][c][d];
          unsigned int p = 0;
          for (unsigned int m = 0; m < N_M; ++m)
            for (unsigned int l = 0; l <= m; ++l, ++p)
              {
                const double wml = w[q] * qv[m] * qv[l];
                for (unsigned int e = 0; e < d4; ++e)
                  B[p][e] += wml * A_flat[e];
              }
        }
      // r_i = sum_m g_im : S_m (row c = i % dim)
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int c = i % dim;
          double             v = 0;
          for (unsigned int j = 0; j < dim; ++j)
            for (unsigned int m = 0; m < N_M; ++m)
              v += g[(i * dim + j) * N_M + m] * S[m][c][j];
          r[i] = v;
        }
      if (!with_tangent)
        return;
      // H_i[l][d][L] = sum_m sum_j g_im[j] (B_ml)[c j d L], then
      // K_ik = sum_l sum_L H_i[l][c_k][L] g_kl[L]
      constexpr unsigned int h_size = N_M * d2;
      scratch.resize(std::size_t(n) * h_size);
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int c = i % dim;
          double            *H = &scratch[std::size_t(i) * h_size];
          std::fill(H, H + h_size, 0.);
          for (unsigned int m = 0; m < N_M; ++m)
            for (unsigned int l = 0; l < N_M; ++l)
              {
                const double *B_ml = B[m >= l ? m * (m + 1) / 2 + l : l * (l + 1) / 2 + m];
                for (unsigned int j = 0; j < dim; ++j)
                  {
                    const double  gij = g[(i * dim + j) * N_M + m];
                    const double *row = B_ml + (c * dim + j) * d2;
                    for (unsigned int e = 0; e < d2; ++e)
                      H[l * d2 + e] += gij * row[e];
                  }
              }
        }
      for (unsigned int i = 0; i < n; ++i)
        {
          const double *H = &scratch[std::size_t(i) * h_size];
          for (unsigned int k = 0; k <= i; ++k)
            {
              const unsigned int c_k = k % dim;
              double             v   = 0;
              for (unsigned int l = 0; l < N_M; ++l)
                for (unsigned int L = 0; L < dim; ++L)
                  v += H[l * d2 + c_k * dim + L] * g[(k * dim + L) * N_M + l];
              (*K)(i, k) = v;
            }
        }
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int k = 0; k < i; ++k)
          (*K)(k, i) = (*K)(i, k);
    }



    // The same for the number of monomials n_m at run time.
    template <int dim>
    void
    cell_consistency(const unsigned int          n_m,
                     const ConstitutiveLaw<dim> &law,
                     const unsigned int          cell,
                     const unsigned int          n,
                     const double               *g,
                     const unsigned int          n_q,
                     const double               *w,
                     const double               *q_values,
                     const double               *local_u,
                     const bool                  with_tangent,
                     double                     *r,
                     dealii::FullMatrix<double> *K,
                     std::vector<double>        &scratch)
    {
      if (n_m == 1)
        cell_consistency<dim, 1>(law, cell, n, g, n_q, w, q_values, local_u, with_tangent, r, K, scratch);
      else
        {
          AssertThrow(n_m == 3, dealii::ExcMessage("FiniteStrainAssembler: orders 1 and 2 only."));
          cell_consistency<dim, 3>(law, cell, n, g, n_q, w, q_values, local_u, with_tangent, r, K, scratch);
        }
    }



    // The deformation gradients of a cell at its points.
    template <int dim>
    void
    cell_deformation_gradients(const unsigned int                   n_m,
                               const unsigned int                   n,
                               const double                        *g,
                               const unsigned int                   n_q,
                               const double                        *q_values,
                               const double                        *local_u,
                               std::vector<dealii::Tensor<2, dim>> &F)
    {
      std::vector<dealii::Tensor<2, dim>> F_m(n_m);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int m = 0; m < n_m; ++m)
            F_m[m][i % dim][j] += local_u[i] * g[(i * dim + j) * n_m + m];
      F.resize(n_q);
      for (unsigned int q = 0; q < n_q; ++q)
        {
          dealii::Tensor<2, dim> Fq;
          for (unsigned int d = 0; d < dim; ++d)
            Fq[d][d] = 1.;
          for (unsigned int m = 0; m < n_m; ++m)
            Fq += q_values[q * n_m + m] * F_m[m];
          F[q] = Fq;
        }
    }
  } // namespace finite_strain_assembler_kernels



  template <int dim>
  FiniteStrainAssembler<dim>::FiniteStrainAssembler(const VEMDoFHandler<dim>   &dof_handler,
                                                    const MaterialLibrary<dim> &laws,
                                                    const double                gamma,
                                                    const Stabilization         stabilization,
                                                    const StabilizationScaling  scaling)
    : dof_handler(dof_handler)
    , laws(laws)
    , loads(dof_handler, laws, gamma, stabilization)
    , gamma(gamma)
    , stabilization(stabilization == Stabilization::automatic ? Stabilization::trace : stabilization)
    , scaling(scaling)
  {
    for (const auto &l : laws.get_laws())
      AssertThrow(l.second->has_finite_strain_response(),
                  dealii::ExcMessage("FiniteStrainAssembler: the constitutive law '" + l.second->get_name() +
                                     "' of material id " + std::to_string(l.first) +
                                     " has no finite-strain response (first Piola-Kirchhoff stress and "
                                     "tangent); use NeoHookeMaterial or SaintVenantKirchhoffMaterial."));
    for (const auto id : dof_handler.get_mesh().get_material_ids())
      AssertThrow(laws.has_law(id),
                  dealii::ExcMessage("FiniteStrainAssembler: the mesh has cells of material id " +
                                     std::to_string(id) + ", for which the library has no law."));
    freeze_stabilization(dealii::Vector<double>(dof_handler.n_dofs()));
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::set_body_force(const dealii::Function<dim> &f)
  {
    loads.set_body_force(f);
    body_force = &f;
    if (cell_data_current() && !cell_data.has_body_force_data)
      compute_body_force_data();
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::add_traction(const dealii::types::boundary_id id, const dealii::Function<dim> &g)
  {
    loads.add_traction(id, g);
    loaded_boundary_ids.push_back(id);
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::add_pressure(const dealii::types::boundary_id id,
                                           const dealii::Function<dim>     &p,
                                           const PressureLoad               kind)
  {
    AssertThrow(p.n_components == 1,
                dealii::ExcMessage("FiniteStrainAssembler::add_pressure(): a pressure must be a scalar function "
                                   "(boundary id " + std::to_string(int(id)) + ")."));
    if (kind == PressureLoad::dead)
      loads.add_pressure(id, p);
    else
      follower_pressures.emplace_back(id, &p);
    loaded_boundary_ids.push_back(id);
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::add_follower_loads(const VEMValues<dim>         &vem_values,
                                                 const dealii::Vector<double> &local_u,
                                                 const double                  factor,
                                                 dealii::Vector<double>       &F,
                                                 dealii::FullMatrix<double>   *K) const
  {
    if (follower_pressures.empty())
      return;
    dealii::Vector<double>     Fp;
    dealii::FullMatrix<double> Kp;
    for (unsigned int e = 0; e < vem_values.n_edges(); ++e)
      {
        const dealii::types::boundary_id id = vem_values.edge_boundary_id(e);
        if (id == dealii::numbers::internal_face_boundary_id)
          continue;
        for (const auto &p : follower_pressures)
          if (p.first == id)
            {
              Fp.reinit(F.size());
              if (K != nullptr)
                Kp.reinit(F.size(), F.size());
              vem_values.get_element().add_edge_follower_pressure(e, *p.second, local_u, Fp,
                                                                  K != nullptr ? &Kp : nullptr);
              F.add(factor, Fp);
              if (K != nullptr)
                K->add(-factor, Kp);
            }
      }
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::assemble_load_vector(dealii::Vector<double> &f_ext) const
  {
    loads.assemble_load_vector(f_ext);
    if (follower_pressures.empty())
      return;
    // the follower pressures in the reference configuration
    VEMValues<dim>         vem_values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values);
    dealii::Vector<double> local_u, F;
    for (unsigned int c = 0; c < dof_handler.get_mesh().n_cells(); ++c)
      {
        vem_values.reinit(c);
        const auto &indices = vem_values.get_dof_indices();
        local_u.reinit(indices.size());
        F.reinit(indices.size());
        add_follower_loads(vem_values, local_u, 1., F, nullptr);
        for (unsigned int i = 0; i < indices.size(); ++i)
          f_ext[indices[i]] += F[i];
      }
  }



  template <int dim>
  bool
  FiniteStrainAssembler<dim>::cell_data_current() const
  {
    return cell_data.valid && cell_data.revision == dof_handler.get_mesh().get_revision() &&
           cell_data.degree == dof_handler.get_degree() && cell_data.n_dofs == dof_handler.n_dofs();
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::compute_cell_data()
  {
    // VEMValues::reinit() checks that the numbering is that of the mesh
    const auto        &mesh    = dof_handler.get_mesh();
    const unsigned int n_cells = mesh.n_cells();
    CellData           data;
    data.revision = mesh.get_revision();
    data.degree   = dof_handler.get_degree();
    data.n_dofs   = dof_handler.n_dofs();
    data.dof_start.assign(1, 0);
    data.point_start.assign(1, 0);
    data.boundary_start.assign(1, 0);
    data.cell_laws.resize(n_cells);
    data.stabilization_bases.resize(n_cells);
    VEMValues<dim> vem_values(dof_handler, dealii::update_quadrature_points | dealii::update_JxW_values);
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        vem_values.reinit(c);
        const VirtualElement<dim> &element = vem_values.get_element();
        const unsigned int         n = element.n_dofs_per_cell(), n_m = element.n_gradient_monomials();
        AssertThrow(n_m == 1 || n_m == 3,
                    dealii::ExcMessage("FiniteStrainAssembler: orders 1 and 2 only (the order is " +
                                       std::to_string(dof_handler.get_degree()) + ")."));
        data.n_monomials = n_m;
        const auto &indices = vem_values.get_dof_indices();
        AssertDimension(indices.size(), n);
        data.dof_indices.insert(data.dof_indices.end(), indices.begin(), indices.end());
        data.dof_start.push_back(data.dof_indices.size());
        // g_im: the rows (2c + j) n_m + m of Pi^0 grad for the component
        // c = i % 2 of DoF i (the other component's rows are zero)
        const dealii::FullMatrix<double> &Pi_grad = element.get_gradient_projector();
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            for (unsigned int m = 0; m < n_m; ++m)
              data.gradient.push_back(Pi_grad((dim * (i % dim) + j) * n_m + m, i));
        // the points: for k = 1 the gradient is constant, one point with the
        // sum of the weights
        const unsigned int n_q = vem_values.n_quadrature_points();
        if (n_m == 1)
          {
            double area = 0;
            for (unsigned int q = 0; q < n_q; ++q)
              area += vem_values.JxW(q);
            data.weights.push_back(area);
            data.monomials.push_back(1.);
          }
        else
          for (unsigned int q = 0; q < n_q; ++q)
            {
              // the scaled monomials 1, xi, eta (VirtualElement::n_gradient_monomials())
              const dealii::Point<dim> x = element.get_geometry().scaled(vem_values.quadrature_point(q));
              data.weights.push_back(vem_values.JxW(q));
              data.monomials.push_back(1.);
              data.monomials.push_back(x[0]);
              data.monomials.push_back(x[1]);
            }
        data.point_start.push_back(data.weights.size());
        for (unsigned int e = 0; e < vem_values.n_edges(); ++e)
          if (vem_values.edge_boundary_id(e) != dealii::numbers::internal_face_boundary_id)
            data.boundary_ids.push_back(vem_values.edge_boundary_id(e));
        data.boundary_start.push_back(data.boundary_ids.size());
        data.cell_laws[c] = &loads.get_law(c);
        FiniteStrainOperator<dim>::stabilization_base(element, stabilization, data.stabilization_bases[c]);
      }
    data.valid = true;
    cell_data  = std::move(data);
    // the diagonal of K_c(0)
    cell_data.initial_diagonal.resize(cell_data.dof_indices.size());
    std::vector<double>        zero, r, scratch;
    dealii::FullMatrix<double> K;
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        const unsigned int start = cell_data.dof_start[c], n = cell_data.dof_start[c + 1] - start,
                           p0 = cell_data.point_start[c], n_m = cell_data.n_monomials;
        zero.assign(n, 0.);
        r.resize(n);
        K.reinit(n, n);
        finite_strain_assembler_kernels::cell_consistency<dim>(
          n_m, *cell_data.cell_laws[c], c, n, &cell_data.gradient[std::size_t(start) * dim * n_m],
          cell_data.point_start[c + 1] - p0, &cell_data.weights[p0], &cell_data.monomials[std::size_t(p0) * n_m],
          zero.data(), true, r.data(), &K, scratch);
        for (unsigned int i = 0; i < n; ++i)
          cell_data.initial_diagonal[start + i] = K(i, i);
      }
    if (body_force != nullptr)
      compute_body_force_data();
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::compute_body_force_data()
  {
    // the quadrature of VirtualElement::body_force_vector() (degree k + 3)
    // and its map from the moments of the load to the DoFs
    const unsigned int n_cells = dof_handler.get_mesh().n_cells();
    CellData          &data    = cell_data;
    data.body_point_start.assign(1, 0);
    data.body_points.clear();
    data.body_monomials.clear();
    data.body_maps.assign(12 * data.dof_indices.size(), 0.);
    VEMValues<dim>                  vem_values(dof_handler);
    std::vector<dealii::Point<dim>> points;
    std::vector<double>             weights;
    dealii::FullMatrix<double>      W;
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        vem_values.reinit(c);
        const VirtualElement<dim> &element = vem_values.get_element();
        element.get_geometry().quadrature(dof_handler.get_degree() + 3, points, weights);
        for (unsigned int q = 0; q < points.size(); ++q)
          {
            const dealii::Point<dim> x = element.get_geometry().scaled(points[q]);
            const double             w = weights[q];
            data.body_points.push_back(points[q]);
            for (const double m : {1., x[0], x[1], x[0] * x[0], x[0] * x[1], x[1] * x[1]})
              data.body_monomials.push_back(w * m);
          }
        data.body_point_start.push_back(data.body_points.size());
        element.body_force_moment_map(W);
        const unsigned int start = data.dof_start[c];
        for (unsigned int i = 0; i < W.m(); ++i)
          for (unsigned int j = 0; j < 12; ++j)
            data.body_maps[12 * (std::size_t(start) + i) + j] = W(i, j);
      }
    data.has_body_force_data = true;
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::check_frozen(const std::string &caller) const
  {
    dof_handler.check_mesh_unchanged();
    AssertThrow(cell_data_current(),
                dealii::ExcMessage("FiniteStrainAssembler::" + caller +
                                   "(): the mesh changed since the stabilization was frozen; call "
                                   "freeze_stabilization() again."));
  }



  template <int dim>
  bool
  FiniteStrainAssembler<dim>::cell_has_boundary_load(const unsigned int c) const
  {
    for (unsigned int b = cell_data.boundary_start[c]; b < cell_data.boundary_start[c + 1]; ++b)
      if (std::find(loaded_boundary_ids.begin(), loaded_boundary_ids.end(), cell_data.boundary_ids[b]) !=
          loaded_boundary_ids.end())
        return true;
    return false;
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::freeze_stabilization(const dealii::Vector<double> &u)
  {
    AssertThrow(u.size() == dof_handler.n_dofs(),
                dealii::ExcMessage("FiniteStrainAssembler::freeze_stabilization(): the displacement has " +
                                   std::to_string(u.size()) + " entries, not n_dofs() = " +
                                   std::to_string(dof_handler.n_dofs()) + "."));
    dof_handler.check_mesh_unchanged();
    if (!cell_data_current())
      compute_cell_data();
    const unsigned int n_cells = dof_handler.get_mesh().n_cells(), n_m = cell_data.n_monomials;
    const bool         diagonal_rule = (stabilization == Stabilization::diagonal);
    stabilization_factors.assign(n_cells, 0.);
    stabilization_matrices.clear();
    if (diagonal_rule)
      stabilization_matrices.resize(n_cells);
    std::vector<double>        local_u, r, scratch;
    dealii::Vector<double>     initial_diagonal, current_diagonal, d;
    dealii::FullMatrix<double> K;
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        const unsigned int start = cell_data.dof_start[c], n = cell_data.dof_start[c + 1] - start;
        initial_diagonal.reinit(n);
        current_diagonal.reinit(n);
        for (unsigned int i = 0; i < n; ++i)
          initial_diagonal[i] = cell_data.initial_diagonal[start + i];
        if (scaling == StabilizationScaling::current_tangent)
          {
            const unsigned int p0 = cell_data.point_start[c];
            local_u.resize(n);
            r.resize(n);
            for (unsigned int i = 0; i < n; ++i)
              local_u[i] = u[cell_data.dof_indices[start + i]];
            K.reinit(n, n);
            finite_strain_assembler_kernels::cell_consistency<dim>(
              n_m, *cell_data.cell_laws[c], c, n, &cell_data.gradient[std::size_t(start) * dim * n_m],
              cell_data.point_start[c + 1] - p0, &cell_data.weights[p0],
              &cell_data.monomials[std::size_t(p0) * n_m], local_u.data(), true, r.data(), &K, scratch);
            for (unsigned int i = 0; i < n; ++i)
              current_diagonal[i] = K(i, i);
          }
        FiniteStrainOperator<dim>::stabilization_scales(initial_diagonal, current_diagonal, scaling, d);
        stabilization_factors[c] = FiniteStrainOperator<dim>::scaled_stabilization(
          cell_data.stabilization_bases[c], d, gamma, stabilization,
          VirtualElement<dim>::stabilization_rules(dof_handler.get_degree()).diagonal_weight,
          diagonal_rule ? &stabilization_matrices[c] : nullptr);
      }
  }



  template <int dim>
  void
  FiniteStrainAssembler<dim>::assemble(const dealii::Vector<double>            &u,
                                       const double                             load_factor,
                                       dealii::Vector<double>                  &residual,
                                       const dealii::AffineConstraints<double> &constraints,
                                       dealii::SparseMatrix<double>            *tangent,
                                       dealii::Vector<double>                  *rhs) const
  {
    const auto n_dofs = dof_handler.n_dofs();
    AssertThrow(u.size() == n_dofs,
                dealii::ExcMessage("FiniteStrainAssembler::assemble(): the displacement has " +
                                   std::to_string(u.size()) + " entries, not n_dofs() = " + std::to_string(n_dofs) +
                                   "."));
    AssertThrow(std::isfinite(load_factor),
                dealii::ExcMessage("FiniteStrainAssembler::assemble(): the load factor is not finite."));
    check_frozen("assemble");
    residual.reinit(n_dofs);
    const bool with_tangent = (tangent != nullptr);
    if (with_tangent)
      {
        AssertThrow(rhs != nullptr && tangent->m() >= n_dofs && tangent->m() == tangent->n(),
                    dealii::ExcMessage("FiniteStrainAssembler::assemble(): the tangent needs a right-hand side "
                                       "vector and at least n_dofs() rows (square)."));
        *tangent = 0;
        rhs->reinit(tangent->m());
      }
    // the element only for the cells with a load
    VEMValues<dim>                               vem_values(dof_handler);
    dealii::Vector<double>                       local_u, F, load, f_value(2);
    std::vector<double>                          r_c, scratch;
    std::vector<dealii::types::global_dof_index> indices;
    dealii::FullMatrix<double>                   K;
    const unsigned int                           n_m = cell_data.n_monomials;
    for (unsigned int c = 0; c < dof_handler.get_mesh().n_cells(); ++c)
      {
        const unsigned int start = cell_data.dof_start[c], n = cell_data.dof_start[c + 1] - start,
                           p0 = cell_data.point_start[c];
        indices.assign(cell_data.dof_indices.begin() + start, cell_data.dof_indices.begin() + start + n);
        local_u.reinit(n, true);
        for (unsigned int i = 0; i < n; ++i)
          local_u[i] = u[indices[i]];
        r_c.resize(n);
        if (with_tangent)
          K.reinit(n, n, true);
        finite_strain_assembler_kernels::cell_consistency<dim>(
          n_m, *cell_data.cell_laws[c], c, n, &cell_data.gradient[std::size_t(start) * dim * n_m],
          cell_data.point_start[c + 1] - p0, &cell_data.weights[p0], &cell_data.monomials[std::size_t(p0) * n_m],
          local_u.begin(), with_tangent, r_c.data(), &K, scratch);
        // F <- load_factor F_load - (r_c + K_s u): the cell's residual, and
        // K <- K_c + K_s
        const bool                        diagonal_rule = !stabilization_matrices.empty();
        const dealii::FullMatrix<double> &K_s =
          diagonal_rule ? stabilization_matrices[c] : cell_data.stabilization_bases[c];
        const double factor = diagonal_rule ? 1. : stabilization_factors[c];
        F.reinit(n, true);
        for (unsigned int i = 0; i < n; ++i)
          {
            double Ksu = 0;
            for (unsigned int j = 0; j < n; ++j)
              Ksu += K_s(i, j) * local_u[j];
            F[i] = -r_c[i] - factor * Ksu;
          }
        if (with_tangent)
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              K(i, j) += factor * K_s(i, j);
        if (cell_has_boundary_load(c))
          {
            // the element for the edge loads (and the body force)
            vem_values.reinit(c);
            loads.local_load(vem_values, load);
            F.add(load_factor, load);
            // the follower pressures at the current edge positions, and
            // their derivative (K = K_c + K_s - load_factor dF_p/du)
            add_follower_loads(vem_values, local_u, load_factor, F, with_tangent ? &K : nullptr);
          }
        else if (body_force != nullptr)
          {
            // the moments of the body force against the monomials, then
            // VirtualElement::body_force_moment_map()
            double mu[12] = {};
            for (unsigned int q = cell_data.body_point_start[c]; q < cell_data.body_point_start[c + 1]; ++q)
              {
                body_force->vector_value(cell_data.body_points[q], f_value);
                const double *wm = &cell_data.body_monomials[6 * std::size_t(q)];
                for (unsigned int m = 0; m < 6; ++m)
                  {
                    mu[m] += f_value[0] * wm[m];
                    mu[6 + m] += f_value[1] * wm[m];
                  }
              }
            for (unsigned int i = 0; i < n; ++i)
              {
                const double *W = &cell_data.body_maps[12 * (std::size_t(start) + i)];
                double        v = 0;
                for (unsigned int j = 0; j < 12; ++j)
                  v += W[j] * mu[j];
                F[i] += load_factor * v;
              }
          }
        for (unsigned int i = 0; i < n; ++i)
          residual[indices[i]] += F[i];
        if (with_tangent)
          constraints.distribute_local_to_global(K, F, indices, *tangent, *rhs);
      }
  }



  template <int dim>
  double
  FiniteStrainAssembler<dim>::strain_energy(const dealii::Vector<double> &u) const
  {
    AssertThrow(u.size() == dof_handler.n_dofs(),
                dealii::ExcMessage("FiniteStrainAssembler::strain_energy(): the displacement has " +
                                   std::to_string(u.size()) + " entries, not n_dofs() = " +
                                   std::to_string(dof_handler.n_dofs()) + "."));
    check_frozen("strain_energy");
    const unsigned int                  n_m = cell_data.n_monomials;
    std::vector<double>                 local_u;
    std::vector<dealii::Tensor<2, dim>> F;
    double                              energy = 0;
    for (unsigned int c = 0; c < dof_handler.get_mesh().n_cells(); ++c)
      {
        const auto *hyperelastic = dynamic_cast<const HyperelasticMaterial *>(cell_data.cell_laws[c]);
        AssertThrow(hyperelastic != nullptr,
                    dealii::ExcMessage("FiniteStrainAssembler::strain_energy(): the law '" +
                                       cell_data.cell_laws[c]->get_name() + "' of cell " + std::to_string(c) +
                                       " is not a hyperelastic law with an energy."));
        const unsigned int start = cell_data.dof_start[c], n = cell_data.dof_start[c + 1] - start,
                           p0 = cell_data.point_start[c], n_q = cell_data.point_start[c + 1] - p0;
        local_u.resize(n);
        for (unsigned int i = 0; i < n; ++i)
          local_u[i] = u[cell_data.dof_indices[start + i]];
        finite_strain_assembler_kernels::cell_deformation_gradients<dim>(
          n_m, n, &cell_data.gradient[std::size_t(start) * dim * n_m], n_q,
          &cell_data.monomials[std::size_t(p0) * n_m], local_u.data(), F);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const double J = dealii::determinant(F[q]);
            AssertThrow(J > 0 && std::isfinite(J), ExcInvertedCell(c, q, J));
            energy += hyperelastic->strain_energy(F[q]) * cell_data.weights[p0 + q];
          }
        // the stabilization: 1/2 u^T K_s u
        const bool                        diagonal_rule = !stabilization_matrices.empty();
        const dealii::FullMatrix<double> &K_s =
          diagonal_rule ? stabilization_matrices[c] : cell_data.stabilization_bases[c];
        const double factor = diagonal_rule ? 1. : stabilization_factors[c];
        double       uKu    = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            double Ksu = 0;
            for (unsigned int j = 0; j < n; ++j)
              Ksu += K_s(i, j) * local_u[j];
            uKu += local_u[i] * factor * Ksu;
          }
        energy += 0.5 * uKu;
      }
    return energy;
  }



  template <int dim>
  std::size_t
  FiniteStrainAssembler<dim>::memory_consumption() const
  {
    std::size_t bytes = dealii::MemoryConsumption::memory_consumption(cell_data.dof_start) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.dof_indices) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.gradient) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.point_start) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.weights) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.monomials) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.cell_laws) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.boundary_start) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.boundary_ids) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.initial_diagonal) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.body_point_start) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.body_points) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.body_monomials) +
                        dealii::MemoryConsumption::memory_consumption(cell_data.body_maps) +
                        dealii::MemoryConsumption::memory_consumption(stabilization_factors);
    for (const auto &m : cell_data.stabilization_bases)
      bytes += m.memory_consumption();
    for (const auto &m : stabilization_matrices)
      bytes += m.memory_consumption();
    return bytes;
  }



  template class FiniteStrainAssembler<2>;
} // namespace dealvem
