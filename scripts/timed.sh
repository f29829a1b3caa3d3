#!/usr/bin/env bash
# A compiler and linker launcher for scripts/build-profile.sh: runs the
# command and appends "user-CPU-s system-CPU-s wall-s output-file" to
# $DEALVEM_TIMED_LOG (one line per command; short lines, so concurrent
# appends do not interleave).
out=""
prev=""
for a in "$@"; do
  if [ "$prev" = "-o" ]; then out="$a"; fi
  prev="$a"
done
exec /usr/bin/time -f "%U %S %e $out" -a -o "${DEALVEM_TIMED_LOG:-/dev/null}" "$@"
