// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_vem_polyhedral_element_h
#define dealvem_vem_polyhedral_element_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace dealvem
{
  class PolyhedralMesh;

  /// An isotropic linear elastic material in 3D (Young's modulus and
  /// Poisson's ratio; refused outside E > 0, -1 < nu < 1/2).
  struct IsotropicMaterial3D
  {
    /// Young's modulus E.
    double youngs_modulus = 1;
    /// Poisson's ratio nu.
    double poisson_ratio  = 0.3;

    /// Lamé's first parameter.
    double
    lambda() const;

    /// The shear modulus.
    double
    mu() const;

    /// Throws naming the parameter when it is out of range.
    void
    check() const;
  };

  /**
   * The first-order conforming virtual element for 3D linear elasticity on
   * a polyhedron with planar polygonal faces (Gain, Talischi and Paulino
   * 2014; in the enhanced form of Beirão da Veiga, Dassi and Russo 2017).
   *
   * The degrees of freedom are the three displacement components at each
   * vertex of the cell. The local space contains the linear displacements;
   * on each face its functions are the 2D first-order virtual element
   * functions of that polygon (enhanced, so that their face integrals are
   * those of their face projections).
   *
   * <h3>The projector</h3>
   * The projection $\Pi v = a + G (x - x_E)$ onto linear displacements
   * takes
   * - $G = \frac{1}{|E|}\int_{\partial E} v \otimes n\, dS$, the mean of the
   *   displacement gradient (divergence theorem), so that its symmetric part
   *   is the mean strain and the energy projection follows;
   * - $a$ such that $\Pi v$ at the vertex average equals the average of the
   *   vertex values.
   * The face integrals $\int_F \varphi_i\, dS$ are those of the face's own
   * first-order projection: with $x_F$ the face's centroid, $\bar x_F$ its
   * vertex average and $n_F$ its normal,
   * $\int_F \varphi_i = |F|/n_F + \tfrac12 \big((x_{i+1} - x_{i-1}) \times
   * n_F\big)\cdot(x_F - \bar x_F)$, exact for linear functions. Hence
   * $\Pi p = p$ for every linear $p$, and the patch test holds to round-off
   * on any mesh of such cells, convex or not.
   *
   * <h3>Stiffness</h3>
   * $K_E = |E|\, B^T D B + (I - P)^T \Sigma (I - P)$, where $B$ gives the
   * Voigt strain of $\Pi v$, $D$ the isotropic elasticity matrix, $P$ the
   * values of $\Pi v$ at the vertices and $\Sigma$ the "D-recipe"
   * stabilization of Beirão da Veiga, Dassi and Russo: $\Sigma_{jj} =
   * \tau \max(K^c_{jj}, 10^{-3}\,\mathrm{tr}(K^c)/(3 n_v))$ with the
   * diagonal of the consistency matrix $K^c$. It scales with the
   * material and the size of each DoF's own contribution, which keeps it
   * robust on thin and flat cells, where a single scalar multiple of the
   * identity over-stiffens the short directions. The stiffness is
   * symmetric, positive semidefinite, with exactly the six rigid-body modes
   * as its kernel.
   */
  class PolyhedralElement
  {
  public:
    /// What compute() produces for one cell.
    struct CellData
    {
      /// The cell's vertices, sorted: local DoF 3 i + d is component d of
      /// vertex vertices[i].
      std::vector<unsigned int> vertices;
      /// Volume of the cell.
      double           volume = 0;
      /// Centroid (centre of volume) of the cell.
      dealii::Point<3> centroid;
      /// Largest distance between two vertices of the cell.
      double           diameter = 0;
      /// The projector: rows 0-2 the constant a (value of Pi v at the
      /// centroid), rows 3 + 3 d + k the entry G_dk of the gradient; columns
      /// the local DoFs.
      dealii::FullMatrix<double> projector;
      /// The element stiffness matrix (3 n_v x 3 n_v).
      dealii::FullMatrix<double> stiffness;
    };

    /// @p stabilization: the factor tau of the stabilization (> 0).
    explicit PolyhedralElement(const double stabilization = 1.);

    /**
     * The projector and, if @p material is given, the stiffness of cell
     * @p c of @p mesh.
     */
    void
    compute(const PolyhedralMesh &mesh, const unsigned int c, const IsotropicMaterial3D *material,
            CellData &data) const;

    /**
     * The integrals over face @p f of the face's vertex basis functions,
     * in the order of the face's loop (exact for linear functions).
     */
    static std::vector<double>
    face_weights(const PolyhedralMesh &mesh, const unsigned int f);

    /**
     * Points and weights of a quadrature on cell @p c exact for polynomials
     * of degree 3, from a signed decomposition into tetrahedra (the cell
     * centroid, each face's centroid and an edge of the face): valid for
     * non-convex cells too, where some weights are negative. Used for
     * error norms.
     */
    static void
    cell_quadrature(const PolyhedralMesh &mesh, const unsigned int c, std::vector<dealii::Point<3>> &points,
                    std::vector<double> &weights);

  private:
    double tau;
  };
} // namespace dealvem

#endif
