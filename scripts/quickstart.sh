#!/usr/bin/env bash
# Quick start on a fresh Debian 12 machine: install the packages, build
# the library and the program dealvem only (the tests, tutorials and
# benchmarks are built by scripts/test.sh or `cmake --build build`), and run
# the main example -- the contact patch test of
# examples/step-2/patch-test.prm -- printing a short result and where the
# output files are. Each stage prints its time.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
start=$SECONDS
bash "$ROOT/scripts/setup.sh"
echo "quickstart: packages ready in $((SECONDS - start)) s"
start=$SECONDS
bash "$ROOT/scripts/build.sh" --target dealvem_app
echo "quickstart: library and program built in $((SECONDS - start)) s"
mkdir -p "$ROOT/build/run"
cd "$ROOT/build/run"
"$ROOT/build/bin/dealvem" "$ROOT/examples/step-2/patch-test.prm"
echo
echo "Output files are in $ROOT/build/run/output/:"
ls -1 "$ROOT/build/run/output/" | sed 's/^/  /'
