#!/bin/sh
# kerf check on the generated 100 MB mill program (all rules) and on a folder of 10,000 small
# programs. Usage: bench/check.sh BUILD_DIR. Figures go to bench/RESULTS.md by hand.
set -e
BUILD=${1:-build}
BIG=$BUILD/bench-100mb.nc
[ -f "$BIG" ] || python3 "$(dirname "$0")/gen_mill.py" "$BIG" 100
SMALL=$BUILD/bench-check-small
if [ ! -d "$SMALL" ]; then
  mkdir -p "$SMALL"
  head -c 4000 "$BIG" | sed '$d' > "$SMALL/seed.nc"; echo M30 >> "$SMALL/seed.nc"
  i=0; while [ $i -lt 10000 ]; do cp "$SMALL/seed.nc" "$SMALL/p$i.nc"; i=$((i+1)); done
  rm "$SMALL/seed.nc"
fi
nproc; uname -r
/usr/bin/time -f "100 MB: %e s wall, %U s user, %M KB peak" "$BUILD/kerf" check --dialect fanuc-mill --format json "$BIG" > /dev/null || true
/usr/bin/time -f "10,000 files: %e s wall, %U s user, %M KB peak" "$BUILD/kerf" check --dialect fanuc-mill --format json "$SMALL" > /dev/null || true
