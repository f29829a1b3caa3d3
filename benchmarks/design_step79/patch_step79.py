#!/usr/bin/env python3
# Patch a copy of deal.II's step-79.cc (the Debian file
# /usr/share/doc/libdeal.ii-doc/examples/step-79/step-79.cc, deal.II 9.4) for
# benchmarks/design_step79/run.sh: at the end of SANDTopOpt::run() print one
# line "DEALVEM_STEP79 key value ..." with the final compliance f^T u (f the
# traction load vector that step-79's right-hand side assembles, u the
# displacement block of its state; the boundary integral of t . u as a
# check), the volume fraction of the filtered and unfiltered densities, the
# grey fraction, the Newton steps (iteration_number: one KKT solve each), the
# outer barrier steps and the wall time of run(); and write the filtered
# densities (cell centre, density) to step79_densities.txt. The VTU file per
# iteration is written only with STEP79_VTU set. Nothing else changes.
#
# Usage: patch_step79.py step-79.cc patched.cc   (fails if an anchor is not
# found exactly once: a step-79.cc of another deal.II version)
import sys

src = open(sys.argv[1]).read()


def sub(old, new):
    global src
    n = src.count(old)
    if n != 1:
        sys.exit("patch of step-79.cc: expected one occurrence of %r, found %d" % (old, n))
    src = src.replace(old, new)


sub("#include <algorithm>\n",
    "#include <algorithm>\n#include <chrono>   // dealvem benchmark\n#include <cstdlib>  // dealvem benchmark\n"
    "#include <iomanip>  // dealvem benchmark\n")
sub('    std::cout << "filter r is: " << filter_r << std::endl;\n',
    "    // dealvem benchmark: wall time and outer (barrier) steps\n"
    "    const auto   dealvem_start         = std::chrono::steady_clock::now();\n"
    "    unsigned int dealvem_barrier_steps = 0;\n"
    '    std::cout << "filter r is: " << filter_r << std::endl;\n')
sub('        std::cout << "Starting outer step in iteration "',
    '        ++dealvem_barrier_steps; // dealvem benchmark\n'
    '        std::cout << "Starting outer step in iteration "')
sub("            output_results(iteration_number);\n",
    "            // dealvem benchmark: no VTU file per iteration unless asked\n"
    '            if (std::getenv("STEP79_VTU") != nullptr)\n'
    "              output_results(iteration_number);\n")
sub("    write_as_stl();\n  }\n} // namespace SAND\n",
    r'''    // dealvem benchmark: the final design. The compliance f^T u with
    // f_i = int_{down_force} t . phi_i (the traction step-79's rhs
    // assembles) and, as a check, int_{down_force} t . u; the volume
    // fraction of the filtered ("density") and unfiltered densities;
    // the share of cells with density in (0.1, 0.9).
    {
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - dealvem_start).count();
      const QGauss<dim - 1>       face_quadrature(fe.degree + 1);
      FEFaceValues<dim>           fe_face_values(fe, face_quadrature, update_values | update_JxW_values);
      std::vector<Tensor<1, dim>> u_q(face_quadrature.size());
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      Vector<double> load(dof_handler.n_dofs());
      double         integral = 0, force = 0, loaded_length = 0;
      Tensor<1, dim> traction;
      traction[1] = -1.;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == BoundaryIds::down_force)
            {
              fe_face_values.reinit(cell, face);
              cell->get_dof_indices(dofs);
              fe_face_values[ValueExtractors::displacements<dim>].get_function_values(nonlinear_solution, u_q);
              for (const auto q : fe_face_values.quadrature_point_indices())
                {
                  integral += traction * u_q[q] * fe_face_values.JxW(q);
                  force += traction[1] * fe_face_values.JxW(q);
                  loaded_length += fe_face_values.JxW(q);
                  for (const auto i : fe_face_values.dof_indices())
                    load(dofs[i]) += traction * fe_face_values[ValueExtractors::displacements<dim>].value(i, q) *
                                     fe_face_values.JxW(q);
                }
            }
      double compliance = 0;
      for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
        compliance += load(i) * nonlinear_solution(i);
      double       volume = 0, unfiltered_volume = 0, area = 0, min_density = 1e300, max_density = -1e300;
      unsigned int n_grey = 0;
      std::ofstream densities("step79_densities.txt");
      densities << std::setprecision(17);
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          const double rho = nonlinear_solution.block(SolutionBlocks::density)[cell->active_cell_index()];
          const double z = nonlinear_solution.block(SolutionBlocks::unfiltered_density)[cell->active_cell_index()];
          volume += rho * cell->measure();
          unfiltered_volume += z * cell->measure();
          area += cell->measure();
          min_density = std::min(min_density, rho);
          max_density = std::max(max_density, rho);
          n_grey += (rho > 0.1 && rho < 0.9);
          densities << cell->center()[0] << ' ' << cell->center()[1] << ' ' << rho << '\n';
        }
      std::cout << std::setprecision(10) << "DEALVEM_STEP79 cells " << triangulation.n_active_cells()
                << " displacement_dofs " << nonlinear_solution.block(SolutionBlocks::displacement).size()
                << " total_dofs " << dof_handler.n_dofs() << " compliance " << compliance << " compliance_integral "
                << integral << " force " << force << " loaded_length " << loaded_length << " volume "
                << volume / area << " unfiltered_volume " << unfiltered_volume / area << " grey "
                << double(n_grey) / triangulation.n_active_cells() << " min_density " << min_density
                << " max_density " << max_density << " newton_steps " << iteration_number << " barrier_steps "
                << dealvem_barrier_steps << " final_barrier " << barrier_size << " time " << seconds << std::endl;
    }
    write_as_stl();
  }
} // namespace SAND
''')
open(sys.argv[2], "w").write(src)
