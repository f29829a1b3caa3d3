// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The precompiled header of the test programs and tutorials (CMake target
// dealvem_pch, option DEALVEM_PRECOMPILED_HEADERS): the deal.II and standard
// headers that nearly every one of them includes, directly or through
// dealvem's headers, parsed once per build instead of once per program.
// Only third-party headers belong here: a program must still compile without
// it (each includes what it uses), and dealvem's own headers change too
// often to be precompiled for everyone.
#ifndef dealvem_tests_precompiled_h
#define dealvem_tests_precompiled_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#endif
