#!/usr/bin/env bash
# The program index on a folder of 10,000 program files (issue 12: under 1 s). Usage:
#   bench/index.sh BUILD_DIR
#   1. makes BUILD_DIR/bench-library with bench/gen_library.py if it is missing
#   2. runs BUILD_DIR/bench/kerf_bench_index (index the folder; the scan alone; lookups)
#   3. end to end: `kerf run main.nc` in that folder (its M98 P calls the last program, so the run
#      indexes the whole folder), against the same main.nc alone in an empty folder
# The files are read from the page cache (each is read once before the timed runs); a cold disk adds
# its own read time. Figures go to bench/RESULTS.md by hand.
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
require_built index.sh "$build" kerf_bench_index kerf
library="$build/bench-library"
[ -d "$library" ] || python3 "$here/gen_library.py" "$library" 10000
echo "== machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "== folder: $(ls "$library" | wc -l) files, $(du -sh "$library" | cut -f1)"
cat "$library"/* > /dev/null   # into the page cache
KERF_BENCH_LIBRARY="$library" "$build/bench/kerf_bench_index"
alone=$(mktemp -d)
cp "$library/main.nc" "$alone/"
for i in 1 2 3; do
  /usr/bin/time -f "kerf run main.nc in the 10,000-file folder: %e s wall, %U s user, %M KB peak" "$build/kerf" run "$library/main.nc" > /dev/null
  /usr/bin/time -f "kerf run main.nc alone (no call resolved): %e s wall" "$build/kerf" run "$alone/main.nc" > /dev/null || true
done
rm -rf "$alone"
