// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_contact_pressure_h
#define dealvem_contact_contact_pressure_h

#include <dealvem/contact/node_insertion.h>

#include <vector>

namespace dealvem
{
  /**
   * Contact pressure from the nodal contact forces of one matched
   * interface.
   *
   * A multiplier $\lambda_i$ is a nodal force. In the exact (patch test)
   * case it is the integral of the pressure against the trace basis
   * function $\varphi_i$ of node $i$ (a P1 hat for k = 1, a P2 Lagrange
   * function for k = 2, on the paired sub-edges).
   *
   * <h3>Why the raw nodal values oscillate</h3>
   * After node insertion every pair joins an original vertex of one body
   * to a vertex inserted into an edge of the other. In its own body an
   * inserted vertex is held against the "kink" of the edge it split only
   * by the VEM stabilization (the consistency part sees the cell's
   * polynomial projection only), while an original vertex is held by the
   * cells around it. A smooth displacement that is not a polynomial of the
   * cell has a kink of size $O(h^{k+1})$ at the inserted vertex; the
   * stabilization answers with a self-equilibrated force pattern (the kink
   * force at the inserted node balanced by its two neighbours) of size
   * $O(\gamma E h^{k})$ per unit length. These patterns alternate between
   * the two bodies along the interface, so the nodal forces, and
   * $-\lambda_i/w_i$, oscillate node by node around the true pressure.
   * Measured on the Hertz problem (step-3), trace stabilization: about 3 % of $p_0$ for k = 1 and
   * 5 % for k = 2 at $h/a \approx 0.02$, growing with the stabilization
   * factor $\gamma$ and falling with $h$; at k = 2 the diagonal
   * stabilization (ElasticityOperator) removes most of it (Hertz, level 1:
   * 0.53 % of $p_0$). Dividing by the consistent
   * interface mass matrix instead of the lumped one (consistent()) is exact
   * for pressures of degree k but amplifies these patterns (they are of
   * high frequency), to about twice the lumped error.
   *
   * <h3>Recovery</h3>
   * recover() fits, at each closed pair, a polynomial $q$ of degree
   * @p fit_degree in the arc length such that the nodal forces it would
   * produce, $\int_\Gamma q\,\varphi_j\,ds$, match the nodal forces of the
   * closed pairs on the sub-edges that contain the pair and within
   * @p patch_segments further sub-edges on each side, in the least-squares
   * sense; the pressure is $q$ at the pair. The patch reaches equally far
   * to both sides, so mirror-symmetric data give a mirror-symmetric
   * recovery. The nodal forces of a pressure of degree at most
   * @p fit_degree are matched exactly, so the recovery keeps the patch test
   * exact; with a linear fit the kink patterns, which sum to zero against
   * every linear function over their three nodes, are filtered out. The
   * program fits degree k: Hertz inside $0.8a$, level 1: 0.54 % (k = 1) and
   * 0.44 % (k = 2) of $p_0$. Open pairs carry no pressure (zero), and only
   * closed pairs enter a fit, so the recovery keeps $g_i p_i = 0$.
   *
   * The exactness it keeps is that of the contact patch test
   * @cite TaylorPapadopoulos1991; the accuracy figures are against Hertz's
   * solution @cite Hertz1882, @cite Johnson1985.
   */
  namespace ContactPressure
  {
    /**
     * Recovered pressure of the pairs of @p interface from their
     * compressive nodal forces @p force (= -lambda, one per pair of the
     * interface, in its order). @p active (empty: all closed) marks the
     * closed pairs; open pairs get zero.
     */
    std::vector<double>
    recover(const NodeInsertion::Interface &interface,
            const std::vector<double>      &force,
            const std::vector<bool>        &active         = {},
            const unsigned int              patch_segments = 3,
            const unsigned int              fit_degree     = 1);

    /**
     * The solution of $M_\Gamma p = f$ with the interface mass matrix of
     * the closed pairs (open pairs: zero). Exact for pressures of degree k;
     * see the class documentation for why it is not the default.
     */
    std::vector<double>
    consistent(const NodeInsertion::Interface &interface,
               const std::vector<double>      &force,
               const std::vector<bool>        &active = {});

    /// The lumped values force / weight: the raw multipliers per length.
    std::vector<double>
    lumped(const NodeInsertion::Interface &interface, const std::vector<double> &force);
  } // namespace ContactPressure
} // namespace dealvem

#endif
