#!/usr/bin/env bash
# Times `kerf fmt` on the generated 100 MB mill program (bench/RESULTS.md, "kerf fmt"):
#   bench/fmt.sh BUILD_DIR [RUNS]
#
#   1. generates BUILD_DIR/bench-100mb.nc (bench/gen_mill.py, the parse benchmark's file) and
#      BUILD_DIR/bench-100mb-runnable.nc (--runnable: valid arcs, so a dry run goes to the end) if missing
#   2. prints the machine and the load
#   3. runs each command RUNS times (default 5) pinned to one core, output to /dev/null, and prints
#      every run and the best and median wall time (GNU time: wall, user, sys, peak RSS):
#        parse      kerf parse FILE --dialect fanuc-mill --stats      (the parse + bind inside fmt)
#        fmt        kerf fmt FILE --dialect fanuc-mill                (default style: this file is already in it)
#        fmt-style  kerf fmt FILE --dialect fanuc-mill --word-order canonical --code-digits two --comment-inside padded
#                   (every block is rewritten and the output differs from the input)
#        verify     kerf fmt RUNNABLE --dialect fanuc-mill --code-digits minimal --verify   (two dry runs compared)
#   The target (issue 6) is fmt under 1.5 s wall.
# Expects kerf to be built: cmake --build BUILD_DIR --target kerf
set -euo pipefail

build=${1:-build}
runs=${2:-5}
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$build" && pwd)
kerf="$build/kerf"
[ -x "$kerf" ] || { echo "fmt.sh: $kerf is missing; cmake --build $build --target kerf" >&2; exit 2; }

file="$build/bench-100mb.nc"
runnable="$build/bench-100mb-runnable.nc"
[ -s "$file" ] || { python3 "$here/gen_mill.py" "$file.tmp" 100 && mv "$file.tmp" "$file"; }
[ -s "$runnable" ] || { python3 "$here/gen_mill.py" "$runnable.tmp" 100 --runnable && mv "$runnable.tmp" "$runnable"; }
command -v /usr/bin/time >/dev/null || { echo "fmt.sh: GNU time (/usr/bin/time) is missing: apt-get install time" >&2; exit 2; }
. "$here/common.sh"

print_machine "$here/.." "$file"

echo "== runs ($runs each, pinned to one core when taskset is there)"
time_runs parse "$kerf" parse "$file" --dialect fanuc-mill --stats
time_runs fmt "$kerf" fmt "$file" --dialect fanuc-mill
time_runs fmt-style "$kerf" fmt "$file" --dialect fanuc-mill --word-order canonical --code-digits two --comment-inside padded
time_runs fmt-runnable "$kerf" fmt "$runnable" --dialect fanuc-mill --code-digits minimal
time_runs verify "$kerf" fmt "$runnable" --dialect fanuc-mill --code-digits minimal --verify
