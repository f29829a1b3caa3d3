// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/contact/contact_pressure.h>
#include <dealvem/contact/interface_tractions.h>

namespace dealvem
{
  namespace InterfaceTractions
  {
    Recovered
    recover(const std::vector<NodeInsertion::Interface> &interfaces,
            const std::vector<double>                   &normal_force,
            const std::vector<double>                   &tangential_force,
            const std::vector<bool>                     &closed)
    {
      Recovered    out;
      unsigned int offset = 0;
      for (const auto &itf : interfaces)
        {
          // this interface's slice of the global pair numbering
          const unsigned int  n_pairs = itf.pairs.size();
          std::vector<double> force(n_pairs), force_t(n_pairs);
          std::vector<bool>   active(n_pairs);
          for (unsigned int j = 0; j < n_pairs; ++j)
            {
              force[j]   = normal_force[offset + j];
              force_t[j] = tangential_force[offset + j];
              active[j]  = closed[offset + j];
            }
          // the fit has the degree of the interface (see the class comment)
          const unsigned int fit = itf.degree;
          const auto         p   = ContactPressure::recover(itf, force, active, 3, fit);
          out.pressure.insert(out.pressure.end(), p.begin(), p.end());
          const auto q = ContactPressure::recover(itf, force_t, active, 3, fit);
          out.shear.insert(out.shear.end(), q.begin(), q.end());
          offset += n_pairs;
        }
      return out;
    }
  } // namespace InterfaceTractions
} // namespace dealvem
