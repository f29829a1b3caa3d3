// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_contact_rows_h
#define dealvem_contact_contact_rows_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace dealvem
{
  struct ContactNodePair;

  /**
   * The Lagrange-multiplier rows of a node-to-node contact system: which
   * unknown of the saddle-point system belongs to which pair, and what the
   * pair is. The system has n_dofs() + n_rows() unknowns, the displacement
   * DoFs first, then
   * - the normal row of every pair: normal_row(i) = n_dofs() + i;
   * - with tangential multipliers (has_tangential_rows()), the tangential
   *   row of every pair: tangential_row(i) = n_dofs() + n_pairs() + i.
   *
   * ContactAssembler::rows() makes it (tangential rows with
   * ContactSettings::Tangential::multipliers and coulomb; the stick penalty
   * has none), and FiniteStrainContact::rows() for the constraints of
   * finite-strain contact (tangential rows for tied contact and Coulomb
   * friction), which follow the same layout. The object refers to the pairs
   * of the one that made it, so it is valid as long as that one lives; it is
   * cheap to copy.
   */
  class ContactRows
  {
  public:
    /// What a multiplier row enforces.
    enum class Kind
    {
      normal,    ///< the normal constraint of a pair (the gap)
      tangential ///< the tangential constraint of a pair (stick or friction)
    };

    /// The rows of @p pairs after @p n_dofs displacement DoFs, with a
    /// tangential row per pair if @p tangential_rows.
    ContactRows(const unsigned int n_dofs, const std::vector<ContactNodePair> &pairs, const bool tangential_rows);

    /// Number of displacement DoFs: the first multiplier row.
    unsigned int
    n_dofs() const
    {
      return n_displacement_dofs;
    }

    /// Number of node pairs.
    unsigned int
    n_pairs() const
    {
      return n_node_pairs;
    }

    /// Whether every pair has a tangential row.
    bool
    has_tangential_rows() const
    {
      return tangential;
    }

    /// Number of multiplier rows: n_pairs(), or 2 n_pairs() with
    /// tangential rows.
    unsigned int
    n_rows() const
    {
      return (tangential ? 2 : 1) * n_node_pairs;
    }

    /// Size of the saddle-point system, n_dofs() + n_rows().
    unsigned int
    n_unknowns() const
    {
      return n_displacement_dofs + n_rows();
    }

    /// The row of multiplier @p j (0 <= j < n_rows()), n_dofs() + j: the
    /// multipliers in the order of the rows.
    unsigned int
    row(const unsigned int j) const
    {
      AssertIndexRange(j, n_rows());
      return n_displacement_dofs + j;
    }

    /// The row of the normal constraint of pair @p pair.
    unsigned int
    normal_row(const unsigned int pair) const
    {
      AssertIndexRange(pair, n_node_pairs);
      return n_displacement_dofs + pair;
    }

    /// The row of the tangential constraint of pair @p pair (only with
    /// has_tangential_rows()).
    unsigned int
    tangential_row(const unsigned int pair) const
    {
      Assert(tangential, dealii::ExcMessage("ContactRows: these contact rows have no tangential rows."));
      AssertIndexRange(pair, n_node_pairs);
      return n_displacement_dofs + n_node_pairs + pair;
    }

    /// Whether @p row is a multiplier row (n_dofs() <= row < n_unknowns()).
    bool
    is_multiplier_row(const unsigned int row) const
    {
      return row >= n_displacement_dofs && row < n_unknowns();
    }

    /// The pair of multiplier row @p row.
    unsigned int
    pair_of(const unsigned int row) const
    {
      Assert(is_multiplier_row(row), dealii::ExcIndexRange(row, n_displacement_dofs, n_unknowns()));
      return (row - n_displacement_dofs) % n_node_pairs;
    }

    /// Whether multiplier row @p row is a normal or a tangential one.
    Kind
    kind_of(const unsigned int row) const
    {
      Assert(is_multiplier_row(row), dealii::ExcIndexRange(row, n_displacement_dofs, n_unknowns()));
      return (row - n_displacement_dofs < n_node_pairs) ? Kind::normal : Kind::tangential;
    }

    /// The initial gap $g_0$ of pair @p pair (ContactNodePair::initial_gap).
    double
    gap0(const unsigned int pair) const;

    /// The tributary weight of pair @p pair (ContactNodePair::weight).
    double
    weight(const unsigned int pair) const;

    /// The contact normal of pair @p pair (ContactNodePair::normal).
    const dealii::Tensor<1, 2> &
    normal(const unsigned int pair) const;

    /// The tangent of pair @p pair (ContactNodePair::tangent).
    const dealii::Tensor<1, 2> &
    tangent(const unsigned int pair) const;

    /// The pairs, in the order of the rows.
    const std::vector<ContactNodePair> &
    pairs() const
    {
      return *pair_list;
    }

    /// The normal multiplier $\lambda_n$ of pair @p pair in the solution
    /// @p x of the system (a nodal force, negative in compression).
    template <typename VectorType>
    double
    normal_multiplier(const VectorType &x, const unsigned int pair) const
    {
      return x[normal_row(pair)];
    }

    /// The tangential multiplier $\lambda_t$ of pair @p pair in the solution
    /// @p x (only with has_tangential_rows()).
    template <typename VectorType>
    double
    tangential_multiplier(const VectorType &x, const unsigned int pair) const
    {
      return x[tangential_row(pair)];
    }

  private:
    unsigned int                        n_displacement_dofs;
    unsigned int                        n_node_pairs;
    bool                                tangential;
    const std::vector<ContactNodePair> *pair_list;
  };
} // namespace dealvem

#endif
