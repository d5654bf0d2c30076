#!/usr/bin/env bash
# Runs the parse benchmark (bench/RESULTS.md): bench/run.sh BUILD_DIR [kerf_bench options...]
#
#   1. generates BUILD_DIR/bench-100mb.nc with bench/gen_mill.py if it is missing
#      (KERF_BENCH_MB=N for another size; the file name stays the same only for the default 100)
#   2. runs BUILD_DIR/bench/kerf_bench on it, pinned to one core (taskset), extra arguments passed on
#      (e.g. --benchmark_filter=ParseBind --benchmark_repetitions=3); JSON copy in BUILD_DIR/bench-results.json
#   3. measures the peak RSS of one `kerf parse FILE --dialect fanuc-mill --stats` with /usr/bin/time
#      and prints peak / input size (requirement: at most 4)
#
# Expects kerf_bench and kerf to be built (make bench does both, with -DKERF_BENCH=ON).
set -euo pipefail

build=${1:-build}
[ $# -gt 0 ] && shift
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$build" && pwd)

mb=${KERF_BENCH_MB:-100}
if [ "$mb" = 100 ]; then file="$build/bench-100mb.nc"; else file="$build/bench-${mb}mb.nc"; fi
bench="$build/bench/kerf_bench"
kerf="$build/kerf"
. "$here/common.sh"
require_built run.sh "$build" kerf_bench kerf

if [ ! -s "$file" ]; then
    echo "== generating $file ($mb MB)"
    python3 "$here/gen_mill.py" "$file.tmp" "$mb"
    mv "$file.tmp" "$file"
fi

# ---- machine ----
echo "== machine"
echo "date:     $(date -u '+%Y-%m-%d %H:%M UTC')"
if command -v lscpu >/dev/null; then
    echo "cpu:      $(lscpu | sed -n 's/^Model name: *//p' | head -1)"
fi
echo "cores:    $(nproc) (nproc)"
echo "memory:   $(awk '/MemTotal/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo)"
echo "kernel:   $(uname -r)"
cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt" | head -1)
[ -n "$cxx" ] && echo "compiler: $("$cxx" --version | head -1)"
if command -v git >/dev/null && git -C "$here/.." rev-parse --git-dir >/dev/null 2>&1; then
    dirty=$(git -C "$here/.." status --porcelain -- grammar ast dialects cli | wc -l)
    echo "source:   $(git -C "$here/.." rev-parse --short HEAD)$([ "$dirty" -gt 0 ] && echo " + $dirty uncommitted file(s) in grammar/ ast/ dialects/ cli/")"
fi
echo "build:    $(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt" | head -1)"
echo "load:     $(cut -d' ' -f1-3 /proc/loadavg) (1/5/15 min; other work on the machine skews real time)"
if [ -r /sys/kernel/mm/transparent_hugepage/enabled ]; then
    echo "THP:      $(cat /sys/kernel/mm/transparent_hugepage/enabled)"
fi

# ---- input ----
bytes=$(stat -c %s "$file")
lines=$(wc -l < "$file")
echo "== input"
echo "file:     $file"
echo "bytes:    $bytes ($(awk -v b="$bytes" 'BEGIN {printf "%.1f MB", b / 1e6}'))"
echo "lines:    $lines, average $(awk -v b="$bytes" -v l="$lines" 'BEGIN {printf "%.1f", b / l}') bytes per line (newline included)"
echo "sample:"
sed -n '1,3p;1000,1004p' "$file" | sed 's/^/    /'

# ---- throughput ----
pin=()
if command -v taskset >/dev/null; then
    core=1
    [ "$(nproc)" -lt 2 ] && core=0
    pin=(taskset -c "$core")
    echo "== kerf_bench (pinned: taskset -c $core)"
else
    echo "== kerf_bench (not pinned: taskset is missing)"
fi
KERF_BENCH_FILE="$file" "${pin[@]}" "$bench" \
    --benchmark_out="$build/bench-results.json" --benchmark_out_format=json "$@"

# ---- peak memory ----
if [ ! -x /usr/bin/time ]; then
    echo "== installing GNU time for /usr/bin/time"
    sudo=""
    [ "$(id -u)" = 0 ] || sudo=sudo
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq time
fi
echo "== peak memory: kerf parse $file --dialect fanuc-mill --stats"
rss_file=$(mktemp)
trap 'rm -f "$rss_file"' EXIT
status=0
"${pin[@]}" /usr/bin/time -o "$rss_file" -f '%M %e %U %S %R' "$kerf" parse "$file" --dialect fanuc-mill --stats || status=$?
[ "$status" = 0 ] || echo "(kerf exited with status $status)"
read -r peak_kb wall user sys minflt < <(tail -1 "$rss_file")
echo "process:  ${wall} s wall, ${user} s user, ${sys} s sys, ${minflt} minor page faults (whole run: read + parse + bind + exit)"
awk -v kb="$peak_kb" -v b="$bytes" 'BEGIN {
    peak = kb * 1024
    printf "peak RSS: %d KiB = %.1f MB; input %.1f MB; ratio %.2f (target <= 4)\n", kb, peak / 1e6, b / 1e6, peak / b
}'
