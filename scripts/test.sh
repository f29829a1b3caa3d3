#!/usr/bin/env bash
# Build everything and run the default ctest suite (all tests except those
# labelled "long"; run those with: ctest --test-dir build -L long).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$ROOT/scripts/setup.sh" --tests
bash "$ROOT/scripts/build.sh"
cd "${BUILD_DIR:-$ROOT/build}"
# programs started without mpirun: MPI as a singleton without Open MPI's
# helper daemon (orted): 0.2 s less to start each of the about 500 programs
# the suite starts (scripts/sanitizer-env.sh does the same for the sanitizer run)
export OMPI_MCA_ess_singleton_isolated=1
ctest -LE long --output-on-failure -j "${JOBS:-$(nproc)}" --timeout 900
