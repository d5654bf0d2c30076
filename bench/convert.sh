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

time_runs() {
    local name=$1
    shift
    local walls=()
    for ((i = 1; i <= runs; i++)); do
        "${pin[@]}" /usr/bin/time -o "$timing" -f '%e %U %S %M' "$@" >/dev/null 2>/dev/null || true
        read -r wall user sys rss < <(tail -1 "$timing")
        printf '%-7s run %d: %5.2f s wall, %5.2f s user, %5.2f s sys, peak %d MB, load %s\n' \
            "$name" "$i" "$wall" "$user" "$sys" $((rss / 1024)) "$(cut -d' ' -f1 /proc/loadavg)"
        walls+=("$wall")
    done
    printf '%s\n' "${walls[@]}" | sort -n | awk -v n="$name" '{ w[NR] = $1 } END {
        printf "%-7s best %.2f s, median %.2f s wall\n", n, w[1], w[int((NR + 1) / 2)] }'
}

echo "== runs ($runs each, pinned: ${pin[*]:-no})"
time_runs parse "$kerf" parse "$file" --dialect fanuc-lathe-a --stats
time_runs 'A->B' "$kerf" convert "$file" --from fanuc-lathe-a --to fanuc-lathe-b
time_runs 'A->C' "$kerf" convert "$file" --from fanuc-lathe-a --to fanuc-lathe-c
