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

echo "== machine"
echo "date:     $(date -u '+%Y-%m-%d %H:%M UTC')"
command -v lscpu >/dev/null && echo "cpu:      $(lscpu | sed -n 's/^Model name: *//p' | head -1)"
echo "cores:    $(nproc)"
echo "source:   $(git -C "$here/.." rev-parse --short HEAD 2>/dev/null || echo '?')"
echo "input:    $(stat -c %s "$file") bytes ($file)"

pin=()
command -v taskset >/dev/null && pin=(taskset -c $(( $(nproc) > 1 ? 1 : 0 )))

timing=$(mktemp)
trap 'rm -f "$timing"' EXIT

# time_runs NAME COMMAND...: RUNS timed runs; one line each, then best and median wall.
time_runs() {
    local name=$1
    shift
    local walls=()
    for ((i = 1; i <= runs; i++)); do
        "${pin[@]}" /usr/bin/time -o "$timing" -f '%e %U %S %M' "$@" >/dev/null 2>/dev/null || true
        read -r wall user sys rss < <(tail -1 "$timing")
        printf '%-10s run %d: %5.2f s wall, %5.2f s user, %5.2f s sys, peak %d MB, load %s\n' \
            "$name" "$i" "$wall" "$user" "$sys" $((rss / 1024)) "$(cut -d' ' -f1 /proc/loadavg)"
        walls+=("$wall")
    done
    printf '%s\n' "${walls[@]}" | sort -n | awk -v n="$name" '{ w[NR] = $1 } END {
        printf "%-10s best %.2f s, median %.2f s wall\n", n, w[1], w[int((NR + 1) / 2)] }'
}

echo "== runs ($runs each, pinned: ${pin[*]:-no})"
time_runs parse "$kerf" parse "$file" --dialect fanuc-mill --stats
time_runs fmt "$kerf" fmt "$file" --dialect fanuc-mill
time_runs fmt-style "$kerf" fmt "$file" --dialect fanuc-mill --word-order canonical --code-digits two --comment-inside padded
time_runs fmt-runnable "$kerf" fmt "$runnable" --dialect fanuc-mill --code-digits minimal
time_runs verify "$kerf" fmt "$runnable" --dialect fanuc-mill --code-digits minimal --verify
