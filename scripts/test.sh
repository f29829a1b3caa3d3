#!/usr/bin/env bash
# Build everything and run the default ctest suite (all tests except those
# labelled "long"; run those with: ctest --test-dir build -L long).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$ROOT/scripts/setup.sh" --tests
bash "$ROOT/scripts/build.sh"
cd "${BUILD_DIR:-$ROOT/build}"
ctest -LE long --output-on-failure -j "${JOBS:-$(nproc)}" --timeout 900
