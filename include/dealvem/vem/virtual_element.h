// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_vem_virtual_element_h
#define dealvem_vem_virtual_element_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <dealvem/vem/polygon_geometry.h>
#include <dealvem/vem/vem_element_data.h>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dealvem
{
  /**
   * The conforming virtual element space of order $k\in\{1,2\}$ for
   * vector fields (2 components) on one polygon $E$ with $N$ vertices. It
   * plays the part of deal.II's FiniteElement and knows nothing of the
   * equation solved with it: the bilinear forms live in the operators above
   * it (ElasticityOperator for linear elasticity).
   *
   * <h3>Degrees of freedom</h3>
   * Per displacement component $c\in\{x,y\}$: the values at the $N$
   * vertices; for $k=2$ also the values at the $N$ edge midpoints and the
   * cell moment $\frac{1}{|E|}\int_E u_c$. The local numbering interleaves
   * the components: local DoF $2j+c$ is component $c$ of node $j$, where
   * nodes $0..N-1$ are the vertices, $N..2N-1$ the edge midpoints (node
   * $N+i$ on edge $i=[v_i,v_{i+1}]$) and $2N$ the cell moment. Hence
   * $n_{dofs} = 2N$ for $k=1$ and $2(2N+1)$ for $k=2$
   * (system_to_component_index() gives the pair (component, node)).
   *
   * <h3>Polynomial basis</h3>
   * With the scaled coordinates $\xi=(x-\bar x)/h$, $\eta=(y-\bar y)/h$ the
   * basis $\{p_\alpha\}$ of $[P_k]^2$ has $n_p = 6$ ($k=1$) or $12$ ($k=2$)
   * members, rigid-body modes first:
   * $p_0=(1,0)$, $p_1=(0,1)$, $p_2=(-\eta,\xi)$, $p_3=(\xi,0)$, $p_4=(0,\eta)$,
   * $p_5=(\eta,\xi)$, and for $k=2$ $p_{6,7,8} = (\xi^2,0),(\xi\eta,0),(\eta^2,0)$,
   * $p_{9,10,11} = (0,\xi^2),(0,\xi\eta),(0,\eta^2)$.
   *
   * <h3>The projector</h3>
   * $\Pi^\nabla$ maps the space onto $[P_k]^2$ by
   * $\int_E\varepsilon(\Pi^\nabla v):\varepsilon(p) = \int_E\varepsilon(v):\varepsilon(p)$
   * for all $p\in[P_k]^2$, plus three conditions on the rigid-body modes.
   * It is the elliptic projector of every linear elasticity form
   * $a(u,v)=\int\varepsilon(u):\mathbb{C}:\varepsilon(v)$ with a constant,
   * positive definite $\mathbb{C}$ (isotropic,
   * $\int\lambda\,\mathrm{div}\,u\,\mathrm{div}\,v+2\mu\,\varepsilon(u):\varepsilon(v)$,
   * or anisotropic): $\varepsilon([P_k]^2)$ is the space of all symmetric
   * tensor fields of degree $k-1$, which such a law maps onto itself, so the
   * orthogonality in $a$ and in the strain product are the same condition.
   * This is why the space needs no material.
   * - $D\in\mathbb{R}^{n_{dofs}\times n_p}$, $D_{i\alpha} = \mathrm{dof}_i(p_\alpha)$.
   * - $B\in\mathbb{R}^{n_p\times n_{dofs}}$: for the strain modes $\alpha\ge 3$,
   *   $B_{\alpha i} = \int_E\varepsilon(p_\alpha):\varepsilon(\varphi_i)
   *   = \int_{\partial E}(\varepsilon(p_\alpha)n)\cdot\varphi_i
   *   - \int_E \mathrm{div}\,\varepsilon(p_\alpha)\cdot\varphi_i$, where the edge
   *   integrals use the Gauss-Lobatto rule on the edge's nodes (trapezoidal
   *   for $k=1$, Simpson for $k=2$; exact because the integrand has degree
   *   $2k-1$) and the volume term, present for $k=2$ only, is $|E|$ times the
   *   constant $\mathrm{div}\,\varepsilon(p_\alpha)$ times the cell-moment DoF.
   *   The rigid-mode rows fix the projection on the kernel: rows 0
   *   and 1 are the cell moments ($k=2$) or the vertex means ($k=1$) of the
   *   two components; row 2 is the mean rotation
   *   $\frac{h}{2|E|}\int_{\partial E}\varphi_i\cdot t$ (the factor makes $G_{22}=1$).
   * - $G = BD$; the projector in the polynomial basis is
   *   $\Pi_* = G^{-1}B$ and in the DoF basis $\Pi = D\Pi_*$.
   * - The Gram matrices of the basis, zero on the rigid modes:
   *   $E_{\alpha\beta}=\int_E\varepsilon(p_\alpha):\varepsilon(p_\beta)$ (the
   *   symmetrized strain block of $G$) and
   *   $T_{\alpha\beta}=\int_E\mathrm{div}\,p_\alpha\,\mathrm{div}\,p_\beta$
   *   (exact monomial integrals). An operator's consistency matrix is
   *   $\Pi_*^T(\ldots)\Pi_*$ of a combination of them.
   * - The stabilization form $S = (I-\Pi)^T(I-\Pi)$ (the "dofi-dofi"
   *   stabilization with unit scaling); an operator scales it.
   *
   * The rows of $G$ and $B$ are scaled to unit size before $G$ is factored
   * (row scaling does not change $\Pi_*$), so cells of any size and aspect
   * ratio are handled to round-off.
   *
   * <h3>The L2 projector</h3>
   * The space is the "enhanced" one: the moments of $v$ against $[P_k]^2$
   * are by definition those of $\Pi^\nabla v$ (for $k=2$ the constant
   * moment is a degree of freedom and equals that of $\Pi^\nabla v$ through
   * rows 0 and 1 of $B$). Hence the L2 projector onto $[P_k]^2$ is
   * computable and equal to $\Pi^\nabla$: get_l2_projector() returns the
   * same matrix, and the loads below use it.
   *
   * <h3>The full-gradient projector</h3>
   * $\Pi^0\nabla$ maps $v$ to the L2 projection of its whole gradient
   * $\nabla v$ (not only the strain) onto $[P_{k-1}]^{2\times 2}$, computable
   * from the degrees of freedom: for $q$ in $P_{k-1}$,
   * $\int_E \partial_j v_c\,q = \int_{\partial E} v_c\,n_j\,q
   * - \int_E v_c\,\partial_j q$. For $k=1$, $q=1$ and the result is the
   * constant $\frac{1}{|E|}\int_{\partial E} v\otimes n$, with the
   * trapezoidal rule on each edge (exact: $v$ is linear there). For $k=2$,
   * $q\in\{1,\xi,\eta\}$: the edge integrand $v_c q$ is cubic and
   * Simpson's rule on vertex, midpoint, vertex (the edge's DoFs) is exact;
   * $\partial_j q$ is a constant, so the cell term is $|E|$ times that
   * constant times the cell-moment DoF. Solving with the Gram matrix
   * $M_{mn} = \int_E q_m q_n$ of the scaled monomials of degree $\le k-1$
   * (get_monomial_gram()) gives the coefficients
   * (get_gradient_projector()). The symmetric part of $\Pi^0\nabla v$ is
   * $\varepsilon(\Pi^\nabla v)$, because $\varepsilon([P_k]^2)$ is all of
   * the symmetric $[P_{k-1}]^{2\times 2}$; the antisymmetric part is
   * the projected rotation, which $\Pi^\nabla$ only fixes by its mean. A
   * finite-strain operator builds $F = I + \Pi^0\nabla u$ from it
   * (ConstitutiveLaw).
   *
   * <h3>Loads</h3>
   * $F_i = \int_E f\cdot\Pi^0\varphi_i = \sum_\alpha (\Pi_*)_{\alpha i}\int_E f\cdot p_\alpha$.
   * It is exact for constant $f$ and keeps the $O(h^{k+1})$ L2 rate.
   *
   * See Beirão da Veiga, Brezzi, Marini, Russo, M3AS 24 (2014) ("The
   * hitchhiker's guide to the virtual element method"), Ahmad, Alsaedi,
   * Brezzi, Marini, Russo, CAMWA 66 (2013) for the enhanced space and
   * Beirão da Veiga, Brezzi, Marini, SINUM 51 (2013) for elasticity; the
   * tutorial step-1 builds the same matrices.
   *
   * References: @cite BeiraoBrezziMariniRusso2014,
   * @cite BeiraoBrezziMarini2013, @cite ArtioliBeiraoLovadinaSacco2017.
   */
  template <int dim>
  class VirtualElement
  {
  public:
    /// Order k, from 1 to max_degree() (AssertThrow otherwise).
    explicit VirtualElement(const unsigned int degree);

    /**
     * The highest order this class implements (2). The programs read the
     * range of 'Discretization/Order' from here, and VEMDoFHandler numbers
     * any order (it reads VEMElementData); so a new order changes this
     * number and the order-dependent parts of the projector in
     * virtual_element.cc (see doc/architecture.md, "Seams").
     */
    static constexpr unsigned int
    max_degree()
    {
      return 2;
    }

    /**
     * The order-dependent constants of the stabilizations that
     * ElasticityOperator and FiniteStrainOperator apply (Stabilization):
     * they belong to the element, as the projector does, so that those
     * operators hold no branch on the order.
     */
    struct StabilizationRules
    {
      /// Whether Stabilization::automatic means the trace form (k = 1) or
      /// the diagonal (dofi-dofi) form (k = 2) for a linear law.
      bool automatic_is_trace;
      /// The factor $c_k$ of the diagonal form, $c_k \max(K_{aa}, 10^{-3}	au)$:
      /// 1 for k = 1, 1/5 for k = 2 (doc/architecture.md, "The stabilization
      /// is the root of the raw error at k = 2").
      double diagonal_weight;
      /// The divisor of an edge's d/ds stiffness (VEMElementData::edge_stiffness())
      /// in the boundary form: 2 for k = 1, 5 for k = 2.
      double boundary_edge_divisor;
    };

    /// The rules of order @p degree (AssertThrow outside 1 to max_degree()).
    static const StabilizationRules &
    stabilization_rules(const unsigned int degree);

    /// The rules of this element's order.
    const StabilizationRules &
    get_stabilization_rules() const
    {
      return stabilization_rules(degree);
    }

    ~VirtualElement();

    /// The order k (1 or 2) given to the constructor.
    unsigned int
    get_degree() const
    {
      return degree;
    }

    /// "VEM<2>(k)", in the style of FiniteElement::get_name().
    std::string
    get_name() const;

    /// Number of vector components (2).
    static constexpr unsigned int
    n_components()
    {
      return 2;
    }

    /// Number of vector polynomials $n_p = (k+1)(k+2)$ (6 or 12).
    unsigned int
    n_polynomials() const
    {
      return (degree + 1) * (degree + 2);
    }

    /// The layout of the DoFs (nodes per vertex, edge and cell, the edge
    /// nodes' positions, the local order), as deal.II's FiniteElementData;
    /// VEMDoFHandler::distribute_dofs(element) reads it.
    const VEMElementData &
    get_element_data() const
    {
      return data;
    }

    /// Number of local DoFs of a polygon with @p n_vertices vertices.
    unsigned int
    n_dofs_per_cell(const unsigned int n_vertices) const
    {
      return data.n_dofs_per_cell(n_vertices);
    }

    /// Number of local DoFs of the polygon of the last reinit().
    unsigned int
    n_dofs_per_cell() const
    {
      return n_dofs;
    }

    /// Number of nodes (vertices, edge midpoints, cell moment) of a polygon.
    unsigned int
    n_nodes(const unsigned int n_vertices) const
    {
      return data.n_nodes(n_vertices);
    }

    /// (component, node) of local DoF @p i, as
    /// FiniteElement::system_to_component_index() gives (component, index).
    static std::pair<unsigned int, unsigned int>
    system_to_component_index(const unsigned int i)
    {
      return {i % 2, i / 2};
    }

    /**
     * Compute the space on the polygon with the given counter-clockwise
     * vertices.
     *
     * All matrices depend only on the vertices relative to each other. When
     * the polygon is a translate of the one of the previous call (vertex
     * differences equal to $10^{-14}h + 8\epsilon\max|x_i|$, the rounding
     * of the coordinates included), only the geometry is moved and the
     * matrices are kept, as deal.II's FEValues does for translated cells
     * (CellSimilarity). On structured meshes this makes assembly much
     * cheaper; see set_cell_similarity() to switch it off.
     */
    void
    reinit(const std::vector<dealii::Point<dim>> &vertices);

    /// Enable (default) or disable the reuse of the matrices for translated
    /// polygons described at reinit().
    void
    set_cell_similarity(const bool enable);

    /// Whether the last reinit() reused the matrices of the previous call.
    bool
    last_reinit_reused() const
    {
      return reused;
    }

    /// A number that changes whenever reinit() computes the matrices anew
    /// (not when it reuses them), unique over all VirtualElement objects:
    /// operators built on this space key their own caches on it.
    std::uint64_t
    matrices_revision() const
    {
      return revision;
    }

    /// Geometry of the polygon of the last reinit(): vertices, area,
    /// centroid, diameter h, edges and the cell quadrature. Empty before the
    /// first reinit().
    const PolygonGeometry<dim> &
    get_geometry() const
    {
      return *geometry;
    }

    /// $D$ (n_dofs x n_p).
    const dealii::FullMatrix<double> &
    get_D() const
    {
      return D;
    }

    /// $B$ (n_p x n_dofs), rows unscaled.
    const dealii::FullMatrix<double> &
    get_B() const
    {
      return B;
    }

    /// $G = BD$ (n_p x n_p).
    const dealii::FullMatrix<double> &
    get_G() const
    {
      return G;
    }

    /// $\Pi_* = G^{-1}B$ (n_p x n_dofs): coefficients of $\Pi^\nabla$.
    const dealii::FullMatrix<double> &
    get_projector() const
    {
      return Pi_star;
    }

    /// The coefficients of the L2 projector $\Pi^0$ onto $[P_k]^2$: the
    /// same matrix as get_projector() in this (enhanced) space; see the
    /// class documentation.
    const dealii::FullMatrix<double> &
    get_l2_projector() const
    {
      return Pi_star;
    }

    /// $\Pi = D\Pi_*$ (n_dofs x n_dofs).
    dealii::FullMatrix<double>
    get_projector_dof_basis() const;

    /// Strain Gram matrix $E_{\alpha\beta}=\int_E\varepsilon(p_\alpha):\varepsilon(p_\beta)$
    /// (n_p x n_p, zero in the rows and columns of the rigid modes).
    const dealii::FullMatrix<double> &
    get_strain_gram() const
    {
      return E_gram;
    }

    /// Divergence Gram matrix $T_{\alpha\beta}=\int_E\mathrm{div}\,p_\alpha\,\mathrm{div}\,p_\beta$
    /// (n_p x n_p, zero in the rows and columns of the rigid modes).
    const dealii::FullMatrix<double> &
    get_divergence_gram() const
    {
      return T_gram;
    }

    /// The stabilization form $S = (I-\Pi)^T(I-\Pi)$ (n_dofs x n_dofs,
    /// symmetric, zero on $[P_k]^2$); operators scale it.
    const dealii::FullMatrix<double> &
    get_stabilization_form() const
    {
      return S;
    }

    /**
     * Adds @p factor times $\int_E \Delta p_\alpha\cdot\varphi_j$ to
     * row @p alpha of @p B, for every local DoF j: the cell term of a
     * projector defined by the full gradient,
     * $\int_E \nabla p_\alpha : \nabla\varphi_j = \int_{\partial E}
     * (\nabla p_\alpha n)\cdot\varphi_j - \int_E \Delta p_\alpha\cdot\varphi_j$.
     * $\Delta p_\alpha$ has degree k - 2, so the integral is a combination
     * of the cell moments (nothing for k = 1; the cell mean times the
     * constant Laplacian times |E| for k = 2). FiniteStrainOperator's
     * componentwise projector calls it.
     */
    void
    add_cell_laplacian_term(const unsigned int alpha, const double factor, dealii::FullMatrix<double> &B) const;

    /// Number $n_m$ of the scaled monomials of degree $\le k-1$, the basis
    /// of the gradient projection: 1 ($k=1$: the constant) or 3 ($k=2$:
    /// $1,\xi,\eta$).
    unsigned int
    n_gradient_monomials() const
    {
      return degree * (degree + 1) / 2;
    }

    /// The Gram matrix $M_{mn} = \int_E q_m q_n$ of the scaled monomials
    /// $q_m$ of degree $\le k-1$ ($n_m\times n_m$, exact).
    const dealii::FullMatrix<double> &
    get_monomial_gram() const
    {
      return M_gram;
    }

    /**
     * The full-gradient projector $\Pi^0\nabla$ (see the class
     * documentation), a $4n_m\times n_{dofs}$ matrix: row
     * $(2c+j)\,n_m + m$ holds the coefficient of the scaled monomial $q_m$
     * in the component $(\Pi^0\nabla v)_{cj}$ (derivative of displacement
     * component $c$ along $x_j$), so that
     * $(\Pi^0\nabla v)_{cj}(x) = \sum_m (\Pi^0\nabla\,v)_{(2c+j)n_m+m}\,q_m(x)$
     * for the local DoF vector $v$.
     */
    const dealii::FullMatrix<double> &
    get_gradient_projector() const
    {
      return Pi_grad;
    }

    /// The coefficients ($4n_m$, layout of get_gradient_projector()) of
    /// $\Pi^0\nabla u$ for the local DoF values @p local_dofs.
    void
    project_gradient(const dealii::Vector<double> &local_dofs,
                     dealii::Vector<double>       &coefficients) const;

    /// $\Pi^0\nabla u$ at a physical point, from the coefficients of
    /// project_gradient().
    dealii::Tensor<2, dim>
    gradient_projection_value(const dealii::Vector<double> &coefficients,
                              const dealii::Point<dim>     &p) const;

    /// $\Pi^0\nabla\varphi_i$ at a physical point (row = component).
    dealii::Tensor<2, dim>
    shape_gradient_projection(const unsigned int i, const dealii::Point<dim> &p) const;

    /// The gradient of the basis polynomial $p_\alpha$ in the scaled
    /// monomials of degree $\le k-1$: $\nabla p_\alpha = \sum_m G_m q_m$,
    /// returned as @p G ($n_m$ tensors, physical units). Operators combine
    /// it with get_monomial_gram() into exact integrals of products of
    /// gradients.
    void
    polynomial_gradient_coefficients(const unsigned int                   alpha,
                                     std::vector<dealii::Tensor<2, dim>> &G) const;

    /// Value of the basis polynomial $p_\alpha$ at a physical point.
    dealii::Tensor<1, dim>
    polynomial_value(const unsigned int alpha, const dealii::Point<dim> &p) const;

    /// Gradient $\nabla p_\alpha$ (row = component) at a physical point.
    dealii::Tensor<2, dim>
    polynomial_gradient(const unsigned int alpha, const dealii::Point<dim> &p) const;

    /// $\Pi\varphi_i$ at a physical point: the projected shape function,
    /// what FiniteElement::shape_value() is for a finite element.
    dealii::Tensor<1, dim>
    projected_shape_value(const unsigned int i, const dealii::Point<dim> &p) const;

    /// $\nabla\Pi\varphi_i$ at a physical point (row = component).
    dealii::Tensor<2, dim>
    projected_shape_grad(const unsigned int i, const dealii::Point<dim> &p) const;

    /// Value of the local DoFs of a vector function (2 components):
    /// point values at vertices and midpoints, the cell moment by quadrature.
    void
    interpolate(const dealii::Function<dim> &f, dealii::Vector<double> &local_dofs) const;

    /// Coefficients $\Pi_* u$ of the projection of local DoF values.
    void
    project(const dealii::Vector<double> &local_dofs,
            dealii::Vector<double>       &coefficients) const;

    /// The projection $\Pi u$ evaluated at a point, from its coefficients.
    dealii::Tensor<1, dim>
    projection_value(const dealii::Vector<double> &coefficients,
                     const dealii::Point<dim>     &p) const;

    /// Gradient of the projection at a point.
    dealii::Tensor<2, dim>
    projection_gradient(const dealii::Vector<double> &coefficients,
                        const dealii::Point<dim>     &p) const;

    /// Strain of the projection at a point.
    dealii::SymmetricTensor<2, dim>
    projection_strain(const dealii::Vector<double> &coefficients,
                      const dealii::Point<dim>     &p) const;

    /**
     * Body-force load vector $F_i = \int_E f\cdot\Pi^0\varphi_i$, with a
     * quadrature of degree k + @p extra_degree on the polygon.
     */
    void
    body_force_vector(const dealii::Function<dim> &f,
                      dealii::Vector<double>      &F,
                      const unsigned int           extra_degree = 3) const;

    /**
     * What body_force_vector() does after the quadrature, as a matrix:
     * with the moments $\mu_{cm} = \int_E f_c\,q_m$ of the load against
     * the six scaled monomials $q_m$ of degree $\le 2$ ($1, \xi, \eta,
     * \xi^2, \xi\eta, \eta^2$), $F_i = \sum_{c,m} W_{i,6c+m}\,\mu_{cm}$.
     * @p W gets $n_{dofs}\times 12$ entries. For a loop that keeps $W$ and
     * the quadrature of a cell and evaluates only the load again
     * (FiniteStrainAssembler).
     */
    void
    body_force_moment_map(dealii::FullMatrix<double> &W) const;

    /**
     * Load vector of a traction $g$ (2 components) on local edge @p edge:
     * $F_i = \int_{e}g\cdot\varphi_i\,ds$, where the trace of $\varphi_i$ on
     * the edge is the 1D Lagrange polynomial of degree k on the edge's nodes.
     * A 5-point Gauss rule is used (exact to degree 9), so the integral is
     * exact for tractions that are polynomials of degree up to 9 - k on the
     * edge and accurate to quadrature error otherwise.
     * Only entries of the edge's nodes are added to @p F.
     */
    void
    add_edge_traction(const unsigned int           edge,
                      const dealii::Function<dim> &g,
                      dealii::Vector<double>      &F) const;

    /**
     * Same, for a normal pressure $p$ (scalar function): $g = -p\,n$.
     */
    void
    add_edge_pressure(const unsigned int           edge,
                      const dealii::Function<dim> &pressure,
                      dealii::Vector<double>      &F) const;

    /**
     * The load of a pressure $p$ (scalar function of the reference
     * position, positive pushing into the body) that follows the deformed
     * edge @p edge: $F_i = -\int_{e_t} p\,n\cdot\varphi_i\,da$ on the
     * current edge $e_t$, with @p local_u the displacement DoFs of the cell,
     * and its derivative $K_{ij} = \partial F_i/\partial u_j$ in @p K
     * (n_dofs x n_dofs; only the rows and columns of the edge's nodes are
     * touched, by addition).
     *
     * The current edge is the trace $x(s) = \sum_b N_b(s)\,x_b$, $s \in
     * [0, 1]$, of the 1D Lagrange polynomials $N_b$ of degree k on the
     * edge's nodes (edge_nodes(): both vertices, and for k = 2 the
     * midpoint) at their current positions $x_b = X_b + u_b$. The current
     * outward normal times the length element is the tangent rotated by
     * 90 degrees, $n\,da = \pm Q\,x'(s)\,ds$ with $Q = \begin{pmatrix} 0 & 1
     * \\ -1 & 0\end{pmatrix}$ (the sign that makes it the outward normal
     * edge_normal() for $u = 0$), so
     * @f[
     *   F_{2a+c} = \mp\sum_b \Big(\int_0^1 p(X(s))\,N_a(s)\,N_b'(s)\,ds\Big)
     *              (Q\,x_b)_c,
     *   \qquad
     *   K_{2a+c,\,2b+d} = \mp\int_0^1 p(X(s))\,N_a(s)\,N_b'(s)\,ds\;Q_{cd}:
     * @f]
     * the load is linear in the current node positions and its tangent is a
     * constant matrix per edge (for a pressure given at reference points).
     * $N_aN_b'$ has degree $2k-1$; the 5-point Gauss rule used (exact to
     * degree 9) integrates it exactly for a pressure polynomial of degree
     * up to $10-2k$ along the edge. This is $-p\,J F^{-T}N\,dA$ of the
     * reference edge for the trace of the displacement, the Nanson
     * formula on the edge itself.
     */
    void
    add_edge_follower_pressure(const unsigned int            edge,
                               const dealii::Function<dim>  &pressure,
                               const dealii::Vector<double> &local_u,
                               dealii::Vector<double>       &F,
                               dealii::FullMatrix<double>   *K) const;

    /// Local node indices (into the interleaved numbering, node j has DoFs
    /// 2j, 2j+1) lying on local edge @p edge: 2 for k = 1, 3 for k = 2
    /// (start vertex, midpoint, end vertex).
    std::vector<unsigned int>
    edge_nodes(const unsigned int edge) const;

    /// Location of local node j (vertex, midpoint, or the centroid for the
    /// cell moment).
    dealii::Point<dim>
    node_location(const unsigned int j) const;

  private:
    /// Whether @p vertices are a translate of the polygon of the last full
    /// computation (cell similarity); if not, record them as that polygon.
    bool
    is_translate_of_last(const std::vector<dealii::Point<dim>> &vertices);

    /// The exact integrals of the scaled monomials of degree <= 2 (k = 2;
    /// for k = 1 only the area is needed and set).
    void
    compute_monomial_integrals();

    /// $D_{i\alpha} = \mathrm{dof}_i(p_\alpha)$.
    void
    compute_D();

    /// Rows 0, 1, 2 of $B$: the translations (cell moments or vertex
    /// means) and the mean rotation, which fix $\Pi^\nabla$ on the rigid
    /// modes. Resizes $B$.
    void
    compute_B_rigid_rows();

    /// Rows $\alpha\ge 3$ of $B$:
    /// $\int_{\partial E}(\varepsilon(p_\alpha)n)\cdot\varphi_i$ by
    /// Gauss-Lobatto on the edge nodes, minus the cell term
    /// $\int_E\mathrm{div}\,\varepsilon(p_\alpha)\cdot\varphi_i$ for k = 2.
    void
    compute_B_strain_rows();

    /// $G = BD$ and $\Pi_* = G^{-1}B$, with $G$ equilibrated by rows and
    /// columns before its LU factorization.
    void
    compute_projector();

    /// The strain Gram matrix $E$ (from $G$), the divergence Gram matrix
    /// $T$ and the monomial Gram matrix $M$ (exact monomial integrals).
    void
    compute_gram_matrices();

    /// The stabilization form $S = (I-\Pi)^T(I-\Pi)$.
    void
    compute_stabilization_form();

    /// The full-gradient projector $\Pi^0\nabla$ (needs $M$).
    void
    compute_gradient_projector();

    /// The local nodes of edge @p e in the order of its Gauss-Lobatto
    /// points: start vertex, then (k = 2) the midpoint, then the end
    /// vertex; the first degree + 1 entries are used.
    std::array<unsigned int, 3>
    edge_node_triple(const unsigned int e) const
    {
      const unsigned int next = (e + 1) % n_vertices;
      return {{e, data.nodes_per_edge() == 0 ? next : data.edge_node(n_vertices, e, 0), next}};
    }

    unsigned int                                degree;
    /// The DoF layout of order degree.
    VEMElementData                              data;
    unsigned int                                n_vertices;
    unsigned int                                n_dofs;
    std::unique_ptr<PolygonGeometry<dim>>       geometry;
    dealii::FullMatrix<double>                  D, B, G, Pi_star, E_gram, T_gram, S;
    /// Monomial Gram matrix and full-gradient projector.
    dealii::FullMatrix<double>                  M_gram, Pi_grad;
    /// Integrals of the scaled monomials $1,\xi,\eta,\xi^2,\xi\eta,\eta^2$.
    std::array<double, 6>                       monomial_integrals{};
    bool                                        use_similarity = true;
    bool                                        reused         = false;
    std::uint64_t                               revision       = 0;

    /// Polynomial coefficients: coef[alpha][component][monomial], monomials
    /// 1, xi, eta, xi^2, xi eta, eta^2.
    std::vector<std::array<std::array<double, 6>, 2>> coef;

    /// Scratch storage of reinit() and body_force_vector() (defined in the
    /// .cc file, so that this header does not include Eigen): reused from
    /// cell to cell, so that assembly loops do not allocate.
    struct Workspace;
    std::unique_ptr<Workspace> workspace;
  };
} // namespace dealvem

#endif
