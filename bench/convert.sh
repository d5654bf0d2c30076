#!/usr/bin/env bash
# Times `kerf convert` on a generated 100 MB lathe program (bench/RESULTS.md, "kerf convert"):
#   bench/convert.sh BUILD_DIR [RUNS]
#
#   1. generates BUILD_DIR/conv100.nc with ../shared/tools/gen_program.py --kind lathe --size 100M
#      (system A: G50/G96/G99, U/W words, G71/G70 with profiles, G75, G76, arcs) if missing
#   2. prints the machine and the load
#   3. runs each command RUNS times (default 3) pinned to one core, output to /dev/null, and prints
#      every run and the best and median wall time (GNU time: wall, user, sys, peak RSS):
#        parse   kerf parse FILE --dialect fanuc-lathe-a --stats     (the parse + bind inside convert)
#        A->B    kerf convert FILE --from fanuc-lathe-a --to fanuc-lathe-b   (U/W → G91 X/Z, G50 → G92, ...)
#        A->C    kerf convert FILE --from fanuc-lathe-a --to fanuc-lathe-c
#   The target (issue 16) is 100 MB converted in under 2 s.
# Expects kerf to be built: cmake --build BUILD_DIR --target kerf
set -euo pipefail

build=${1:-build}
runs=${2:-3}
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$build" && pwd)
kerf="$build/kerf"
[ -x "$kerf" ] || { echo "convert.sh: $kerf is missing; cmake --build $build --target kerf" >&2; exit 2; }
gen="$here/../../shared/tools/gen_program.py"
file="$build/conv100.nc"
[ -s "$file" ] || { python3 "$gen" --kind lathe --size 100M --out "$file.tmp" && mv "$file.tmp" "$file"; }
command -v /usr/bin/time >/dev/null || { echo "convert.sh: GNU time (/usr/bin/time) is missing: apt-get install time" >&2; exit 2; }
. "$here/common.sh"

print_machine "$here/.." "$file"
echo "== runs ($runs each, pinned to one core when taskset is there)"
time_runs parse "$kerf" parse "$file" --dialect fanuc-lathe-a --stats
time_runs 'A->B' "$kerf" convert "$file" --from fanuc-lathe-a --to fanuc-lathe-b
time_runs 'A->C' "$kerf" convert "$file" --from fanuc-lathe-a --to fanuc-lathe-c
