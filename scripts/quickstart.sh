#!/usr/bin/env bash
# Quick start on a fresh Debian 12 machine: install the packages, build
# dealvem, and run the main example -- the contact patch test of
# examples/step-2/patch-test.prm -- printing a short result and where the
# output files are.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$ROOT/scripts/setup.sh"
bash "$ROOT/scripts/build.sh"
mkdir -p "$ROOT/build/run"
cd "$ROOT/build/run"
"$ROOT/build/bin/dealvem" "$ROOT/examples/step-2/patch-test.prm"
echo
echo "Output files are in $ROOT/build/run/output/:"
ls -1 "$ROOT/build/run/output/" | sed 's/^/  /'
