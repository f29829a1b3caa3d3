// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// The one source of the object library dealvem_pch, whose only job is to
// compile tests/precompiled.h once for the test programs and tutorials
// (CMakeLists.txt, DEALVEM_PRECOMPILED_HEADERS). The header comes in through
// the precompiled header CMake adds; nothing else is compiled here.
