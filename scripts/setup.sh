#!/usr/bin/env bash
# Install the Debian 12 packages dealvem needs (idempotent: does nothing when
# they are all present). Run as root, or with sudo available.
set -euo pipefail
# doxygen and texlive-binaries (bibtex, for @cite): the reference ('doc'
# target) and its ctest doc/doxygen; no graphviz (doc/Doxyfile.in: HAVE_DOT = NO)
PACKAGES="libdeal.ii-dev libsuitesparse-dev libeigen3-dev libcgal-dev cmake g++ make ccache numdiff python3 python3-vtk9 gmsh doxygen texlive-binaries"
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
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing
