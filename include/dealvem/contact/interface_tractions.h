// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_contact_interface_tractions_h
#define dealvem_contact_interface_tractions_h

#include <dealvem/contact/node_insertion.h>

#include <vector>

namespace dealvem
{
  /**
   * The recovered normal pressure and tangential traction of every node
   * pair of all interfaces of a contact problem, from the nodal contact
   * forces of a solve.
   *
   * The node pairs are numbered interface after interface, in the order of
   * the interfaces and of their pairs (the numbering of the contact
   * assembler). Each interface is handed to ContactPressure::recover() with
   * a patch of three sub-edges on each side and a fit of the interface's
   * own degree k: linear for k = 1, where it removes the node-by-node kink
   * pattern of the raw forces; quadratic for k = 2, whose raw forces have
   * no such pattern and where a linear fit would miss the curvature of the
   * pressure (Hertz, level 0: 1.20 % against 0.47 % of $p_0$). The
   * recovery is a patch fit, not the consistent solve
   * $M_\Gamma p = -\lambda$ of ContactPressure::consistent(), which
   * amplifies the node-by-node patterns.
   */
  namespace InterfaceTractions
  {
    /// The recovered tractions of all node pairs (one entry per pair).
    struct Recovered
    {
      /// Normal pressure, compression > 0 (zero at open pairs).
      std::vector<double> pressure;
      /// Tangential traction along each pair's tangent (zero at open
      /// pairs).
      std::vector<double> shear;
    };

    /**
     * Recover the tractions of all pairs of @p interfaces from the normal
     * nodal forces @p normal_force ($-\lambda_i$, compression > 0) and the
     * tangential nodal forces @p tangential_force; only the pairs with
     * @p closed set enter the fits. The three vectors have one entry per
     * node pair, numbered interface after interface.
     */
    Recovered
    recover(const std::vector<NodeInsertion::Interface> &interfaces,
            const std::vector<double>                   &normal_force,
            const std::vector<double>                   &tangential_force,
            const std::vector<bool>                     &closed);
  } // namespace InterfaceTractions
} // namespace dealvem

#endif
