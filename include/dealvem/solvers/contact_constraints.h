// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_solvers_contact_constraints_h
#define dealvem_solvers_contact_constraints_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  namespace TrilinosWrappers
  {
    class SparseMatrix;
  }
} // namespace dealii

namespace dealvem
{
  /**
   * A square sparsity pattern that is given its compressed rows whole,
   * for ContactConstraints::condense(): deal.II's way to build a pattern
   * (reinit() with the row lengths, the entries added, compress()) holds
   * the column indices twice and copies them once more, which is 0.3 s
   * and 195 MB of fresh memory for a condensed stiffness of 1e6 DoFs
   * (48 entries a row). A plain dealii::SparsityPattern passed to
   * condense() is built that way; this class is filled in one pass.
   */
  class CompressedRowPattern : public dealii::SparsityPattern
  {
  public:
    /**
     * Make this the pattern of an @p n x @p n matrix whose row i has the
     * columns @p columns[@p row_start[i]] to
     * @p columns[@p row_start[i + 1] - 1], the diagonal first and then
     * the others in ascending order (deal.II's order for square
     * patterns). Both arrays are taken over; the order is checked.
     */
    void
    assign(size_type n, std::unique_ptr<std::size_t[]> row_start, std::unique_ptr<size_type[]> columns);
  };



  /**
   * The condensed stiffness of ContactConstraints::condense() kept as rows
   * that refer to the saddle-point matrix they come from instead of as a
   * matrix of its own: a slave row is decoupled (the average magnitude of
   * K's diagonal), a row that no slave line holds and without slave
   * columns is K's row of the saddle-point matrix, and only the other
   * rows (gathered from the rows of K by the lines) are stored. Its
   * product is the condensed matrix's without the memory of one (at 1e6
   * DoFs, 380 MB of fresh memory for a two-body patch test). The
   * saddle-point matrix must outlive it, or be given again by rebind().
   */
  class CondensedRows
  {
  public:
    /// The number of rows (displacement DoFs).
    unsigned int
    m() const
    {
      return n;
    }

    /// The entries of row @p i.
    unsigned int
    row_length(const unsigned int i) const
    {
      return lengths[i];
    }

    /// f(column, value) for the entries of row @p i, columns ascending
    /// (the pattern of the condensed matrix, zeros included).
    template <typename F>
    void
    for_row(const unsigned int i, F &&f) const
    {
      if (kind[i] == gathered)
        {
          for (std::size_t k = row_start[i]; k < row_start[i + 1]; ++k)
            f(columns[k], values[k]);
          return;
        }
      // K's row of A, whose diagonal comes first in deal.II's order
      const bool   slave = (kind[i] == decoupled);
      const auto  &sp    = A->get_sparsity_pattern();
      auto         value = A->begin(i);
      auto         it = sp.begin(i), end = sp.end(i);
      const double diagonal     = (slave ? average_diagonal : value->value());
      bool         diagonal_out = false;
      for (++it, ++value; it != end; ++it, ++value)
        {
          const unsigned int j = it->column();
          if (j >= n)
            break;
          if (!diagonal_out && j > i)
            {
              f(i, diagonal);
              diagonal_out = true;
            }
          f(j, slave ? 0. : value->value());
        }
      if (!diagonal_out)
        f(i, diagonal);
    }

    /// The diagonal entry of row @p i.
    double
    diag_element(const unsigned int i) const;

    /// @p dst = K_condensed @p src (rows in parallel).
    void
    vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const;

    /// Refer to @p A_again from now on: the same saddle-point matrix (the
    /// same pattern and values), e.g. passed again to complete a solve.
    void
    rebind(const dealii::SparseMatrix<double> &A_again);

  private:
    friend class ContactConstraints;
    enum Kind : unsigned char
    {
      decoupled,
      plain,
      gathered
    };
    const dealii::SparseMatrix<double> *A                = nullptr;
    unsigned int                        n                = 0;
    double                              average_diagonal = 0;
    std::vector<Kind>                   kind;
    std::vector<unsigned int>           lengths;
    /// The gathered rows (ascending), compressed.
    std::vector<std::size_t>  row_start;
    std::vector<unsigned int> columns;
    std::vector<double>       values;
  };



  /**
   * The active contact constraints of a saddle-point system
   * @f[ \begin{pmatrix} K & B^T \\ B & D \end{pmatrix}
   *     \begin{pmatrix} u \\ \lambda \end{pmatrix} =
   *     \begin{pmatrix} f \\ g \end{pmatrix} @f]
   * (the layout of SaddlePointSolver) written as affine constraints on
   * displacement DoFs, so that the contact problem becomes a symmetric
   * positive definite problem in the remaining DoFs, as deal.II's step-41
   * and step-42 impose their active sets.
   *
   * The multiplier rows are classified from the matrix:
   * - <b>constraint rows</b>: a non-zero row of $B$ and a zero row of $D$;
   *   the equation $B_r u = g_r$ is enforced;
   * - <b>inactive rows</b>: a zero row of $B$ and only a diagonal entry in
   *   $D$: $\lambda_r = g_r / D_{rr}$ (zero for the contact assembler's
   *   $\lambda = 0$ rows);
   * - <b>tied rows</b>: a zero row of $B$, a diagonal entry and couplings
   *   to constraint rows $q$ in $D$: $\lambda_r = (g_r - \sum_q D_{rq}
   *   \lambda_q)/D_{rr}$, the friction force of a slipping pair,
   *   $\lambda_t = -\mu\sigma\lambda_n$ (ContactAssembler::assemble_friction());
   * - anything else (a row with both $B$ and $D$ entries, a tied row that
   *   follows another tied row) throws, naming the row.
   *
   * <b>Test and trial spaces.</b> The force of constraint row $q$ acts on
   * the displacements along its <em>test column</em>: its column of $B^T$
   * plus $-D_{rq}/D_{rr}$ times the columns of the tied rows $r$ that
   * follow it. Where every test column is the row of $B$ (frictionless
   * contact, sticking pairs) the problem is symmetric and the condensed
   * matrix is $C^T K C$ for the slave lines $u = C\tilde u + c$. A slipping
   * pair's test column $B_n^T - \mu\sigma B_t^T$ differs from its row
   * $B_n$: then the test functions are condensed by their own lines
   * $v = Z\tilde v$ (the kernel of the test columns, same slave DoFs, found
   * by the same elimination on the test rows) and the condensed matrix is
   * the Petrov-Galerkin product $Z^T K C$, no longer symmetric
   * (is_symmetric() is false), computed as
   * $C^T K C + (Z - C)^T K C$: only the slaves whose two lines differ add a
   * correction, their row of $K C$ times the difference of the lines.
   *
   * <b>Choice of the slave DoFs.</b> The constraint rows are taken in order
   * and reduced by the constraints found so far (Gauss-Jordan: every line
   * is kept in terms of DoFs that are not slaves). In the reduced row the
   * eligible entry of largest magnitude (partial pivoting) gives the slave
   * DoF (with non-symmetric rows: the largest product of the reduced trial
   * and test entries, so that both pivots are non-zero); eligible are DoFs that are not yet slaves and whose row of $K$ has
   * an off-diagonal entry (a DoF condensed by a Dirichlet or roller
   * constraint has a zero column in $B$ and a decoupled row in $K$). So the
   * slaves are distinct, not fixed by the displacement constraints, and the
   * slave block of $B$ is triangular up to permutation with pivots that are
   * the largest of their reduced rows.
   *
   * <b>Redundant constraints.</b> A reduced row whose largest entry is at
   * most @p dependency_tolerance times the largest entry of the original
   * row is linearly dependent on the rows before it (e.g. two contact pairs
   * on one node whose partners are both fixed). If its reduced right-hand
   * side vanishes (relative to the values that entered it, and to
   * 1e-12 times the length scale) the row is dropped from the constraints
   * and listed by get_dependent_rows(), and its multiplier is zero: the
   * rows before it, on which it depends, carry the force. (Where three
   * bodies meet, e.g. a head joint ending on a bed joint, the pair of the
   * later interface repeats what the two earlier ones impose. Any split of
   * the force among dependent rows is an equilibrium; a split that gives
   * the repeated pair a share, like the minimum-norm one used before, made
   * the friction and active-set tests judge a pressure and a friction force
   * that no physics fixes, and the Coulomb iteration cycled on them. With
   * zero, the pair is closed and free of force, which is consistent with
   * every contact model: unilateral sees a zero pressure at a zero gap,
   * Coulomb a zero friction force.) Otherwise the constraints contradict
   * each other and reinit() throws, naming the row, the rows it depends on
   * and the two values.
   *
   * <b>Multipliers.</b> After the condensed solve, the residual
   * $r = f - K u$ lies in the range of $B^T$, and its restriction to the
   * slave DoFs determines $\lambda$: recover_multipliers() solves
   * $B_{I,S}^T \lambda_I = r_S$ for the independent rows $I$ (square, one
   * row per slave, UMFPACK) and sets the dependent ones to zero.
   */
  class ContactConstraints
  {
  public:
    /**
     * Read the multiplier rows of @p A (first @p n_displacements unknowns
     * are displacements) and @p b and build the constraints. @p length_scale
     * (a typical coordinate of the model, 0 if unknown) sets the absolute
     * floor of the consistency test of redundant constraints.
     *
     * Without @p displacement_constraints a DoF may be a slave if its row
     * of $K$ in @p A couples to other DoFs. With them, @p A need not hold
     * $K$ at all (the distributed contact solve passes only the contact
     * blocks and assembles $K$ on the processes' cells): a DoF may be a
     * slave if those constraints do not constrain it.
     */
    void
    reinit(const dealii::SparseMatrix<double>      &A,
           const unsigned int                       n_displacements,
           const dealii::Vector<double>            &b,
           const double                             length_scale,
           const double                             dependency_tolerance    = 1e-10,
           const dealii::AffineConstraints<double> *displacement_constraints = nullptr);

    /// The slave lines (closed; every line in terms of non-slave DoFs).
    const dealii::AffineConstraints<double> &
    get_constraints() const
    {
      return constraints;
    }

    /**
     * Condense the displacement block $K$ of @p A and the displacement part
     * of @p b (with the forces of the inactive multipliers moved to the
     * right-hand side) into @p K_condensed (pattern in @p sparsity) and
     * @p f_condensed. The slave rows become decoupled diagonal rows. A
     * CompressedRowPattern as @p sparsity is filled without deal.II's
     * compress() (symmetric problems and @p symmetric_part).
     */
    void
    condense(const dealii::SparseMatrix<double> &A,
             const dealii::Vector<double>       &b,
             dealii::SparsityPattern            &sparsity,
             dealii::SparseMatrix<double>       &K_condensed,
             dealii::Vector<double>             &f_condensed,
             const bool                          symmetric_part = false) const;

    /**
     * condense() of a symmetric problem (is_symmetric()) written straight
     * into a Trilinos matrix on one process (MPI_COMM_SELF, rows ascending,
     * every entry of the condensed pattern kept, zeros included), for
     * solvers that work on Trilinos matrices: no deal.II copy of the
     * condensed stiffness is made on the way, so that a contact solve holds
     * the saddle-point matrix where a one-body solve holds its stiffness
     * (at 1e6 DoFs the copy was 380 MB of fresh memory). Throws if the
     * problem is not symmetric.
     */
    void
    condense(const dealii::SparseMatrix<double>     &A,
             const dealii::Vector<double>           &b,
             dealii::TrilinosWrappers::SparseMatrix &K_condensed,
             dealii::Vector<double>                 &f_condensed) const;

    /// condense() of a symmetric problem into rows that refer to @p A
    /// (see CondensedRows; @p A must outlive them). Throws if the problem
    /// is not symmetric.
    void
    condense(const dealii::SparseMatrix<double> &A,
             const dealii::Vector<double>       &b,
             CondensedRows                      &K_condensed,
             dealii::Vector<double>             &f_condensed) const;

    /**
     * Complete @p x (size of @p b): on entry its first n_displacements
     * entries hold the displacements of the condensed solve (slave values
     * are overwritten from the constraints); on return the multipliers
     * follow.
     */
    void
    distribute_and_recover_multipliers(const dealii::SparseMatrix<double> &A,
                                       const dealii::Vector<double>       &b,
                                       dealii::Vector<double>             &x) const;

    /// The number of multiplier rows with displacement entries (the
    /// constraints that condensation eliminates).
    unsigned int
    n_constraint_rows() const
    {
      return constraint_rows.size();
    }

    /// Multiplier rows (0-based) dropped as linearly dependent.
    const std::vector<unsigned int> &
    get_dependent_rows() const
    {
      return dependent_rows;
    }

    /// The slave DoF of each enforced (not dropped) constraint row.
    const std::vector<std::pair<unsigned int, unsigned int>> &
    get_slaves() const
    {
      return slaves;
    }

    /**
     * The homogeneous lines that tie the two ends of every stick spring
     * (rows over displacement DoFs, ContactAssembler::stick_penalty_rows()):
     * the rows are first written without the slaves of @p normal_lines
     * (the active normal constraints, closed), then turned into slave lines
     * as reinit() does, a DoF being eligible as a slave when @p excluded
     * does not constrain it. Used by the stick-penalty preconditioners of
     * the condensed contact solvers (serial and distributed).
     */
    static ContactConstraints
    tie_lines(const std::vector<std::vector<std::pair<unsigned int, double>>> &stick_rows,
              const dealii::AffineConstraints<double>                           &normal_lines,
              const dealii::AffineConstraints<double>                           &excluded,
              const unsigned int                                                n_displacements,
              const double                                                      length_scale);

    /// The multiplier rows without displacement entries and their values
    /// (g_r / D_rr; zero for the contact assembler's inactive pairs).
    const std::vector<std::pair<unsigned int, double>> &
    get_inactive_rows() const
    {
      return inactive;
    }

    /// A multiplier that follows constraint multipliers:
    /// $\lambda_r = $ value $+ \sum$ entries$_q \lambda_q$.
    struct Tied
    {
      /// The multiplier row r.
      unsigned int                                 row = 0;
      /// The constant part of lambda_r.
      double                                       value = 0;
      /// The rows q and their coefficients.
      std::vector<std::pair<unsigned int, double>> entries;
    };

    /// The multipliers that follow others (see Tied).
    const std::vector<Tied> &
    get_tied_rows() const
    {
      return tied;
    }

    /// The multipliers known before the solve: the inactive ones and the
    /// constant parts of the tied ones (zero elsewhere), m entries. Their
    /// forces belong to the right-hand side of the condensed problem.
    std::vector<double>
    known_multipliers() const
    {
      std::vector<double> lambda(m, 0.);
      for (const auto &in : inactive)
        lambda[in.first] = in.second;
      for (const auto &t : tied)
        lambda[t.row] = t.value;
      return lambda;
    }

    /// Whether every test column is its constraint row (no slipping pair):
    /// then the condensed matrix is symmetric.
    bool
    is_symmetric() const
    {
      return symmetric;
    }

    /// The test lines (homogeneous, the same slaves as get_constraints());
    /// empty when is_symmetric().
    const dealii::AffineConstraints<double> &
    get_test_constraints() const
    {
      return test_constraints;
    }

    /// Per slave whose test line differs from its trial line: the slave and
    /// the difference of the lines (test minus trial coefficients).
    const std::vector<std::pair<unsigned int, std::vector<std::pair<unsigned int, double>>>> &
    get_line_differences() const
    {
      return test_lines;
    }

  private:
    /// The factorized B_{I,S}^T of distribute_and_recover_multipliers(),
    /// kept while its entries come back (the continuations of an inexact
    /// solve recover the multipliers of the same constraints again).
    struct Recovery;
    mutable std::shared_ptr<Recovery> recovery;

    /// The multiplier values known before the solve (inactive rows, the
    /// constant parts of tied ones) into @p lambda, flagged in @p known
    /// (both of size m): their forces go to the right-hand side.
    void
    known_multipliers(std::vector<double> &lambda, std::vector<bool> &known) const;

    /// condense() of a symmetric problem into @p trilinos or @p rows (one
    /// of them non-null).
    void
    condense_symmetric(const dealii::SparseMatrix<double>     &A,
                       const dealii::Vector<double>           &b,
                       dealii::Vector<double>                 &f,
                       dealii::TrilinosWrappers::SparseMatrix *trilinos,
                       CondensedRows                          *rows) const;

    unsigned int                                     n = 0;
    unsigned int                                     m = 0;
    dealii::AffineConstraints<double>                constraints;
    std::vector<unsigned int>                        constraint_rows;
    std::vector<unsigned int>                        dependent_rows;
    /// (multiplier row, slave DoF)
    std::vector<std::pair<unsigned int, unsigned int>> slaves;
    /// Inactive rows and their multiplier values.
    std::vector<std::pair<unsigned int, double>>      inactive;
    std::vector<Tied>                                 tied;
    bool                                              symmetric = true;
    dealii::AffineConstraints<double>                 test_constraints;
    std::vector<std::pair<unsigned int, std::vector<std::pair<unsigned int, double>>>> test_lines;
  };
} // namespace dealvem

#endif
