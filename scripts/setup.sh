#!/usr/bin/env bash
# Install the Debian 12 packages dealvem needs (idempotent: does nothing when
# they are all present). Run as root, or with sudo available.
set -euo pipefail
# The library and the program: deal.II (with Trilinos, UMFPACK, MPI), CHOLMOD,
# Eigen, CGAL, NLopt (MMA of the topology optimizer), the compiler, and LLVM's
# linker lld (a third of gold's time on deal.II's long list of libraries).
PACKAGES="libdeal.ii-dev libsuitesparse-dev libeigen3-dev libcgal-dev libnlopt-dev cmake g++ make lld"
# With --tests, also what the test suite uses: numdiff, python3 with VTK (the
# VTU files read back), gmsh (meshes written by gmsh itself), doxygen and
# texlive-binaries (bibtex, for @cite: the reference, 'doc' target, and its
# ctest doc/doxygen; no graphviz: doc/Doxyfile.in has HAVE_DOT = NO).
if [ "${1:-}" = "--tests" ]; then
  PACKAGES="$PACKAGES numdiff python3 python3-vtk9 gmsh doxygen texlive-binaries"
fi
missing=""
for p in $PACKAGES; do
  dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
done
if [ -z "$missing" ]; then
  echo "setup: all packages present"
  exit 0
fi
SUDO=""
if [ "$(id -u)" != "0" ]; then SUDO="sudo"; fi
echo "setup: installing$missing"
dpkg_options=()
if [ "${CI:-}" = "true" ]; then
  # a throw-away CI machine: no fsync after every file dpkg unpacks, no
  # documentation, manual pages or translations (about 600 packages; 287 s
  # against 327 s for download and install in a fresh Debian 12 chroot)
  dpkg_options=(-o Dpkg::Options::=--force-unsafe-io)
  printf 'path-exclude /usr/share/doc/*\npath-exclude /usr/share/man/*\npath-exclude /usr/share/locale/*\n' \
    | $SUDO tee /etc/dpkg/dpkg.cfg.d/01-dealvem-ci-nodoc > /dev/null
fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${dpkg_options[@]}" $missing
