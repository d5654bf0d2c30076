#!/usr/bin/env bash
# The top functions of one kerf command by share of CPU samples (the "flame graph summary" of
# bench/RESULTS.md), and the share of each thread:
#   bench/profile.sh KERF_BINARY N -- kerf-arguments...
# e.g. bench/profile.sh build/kerf 15 -- check /tmp/kerf-bench-data/mill/mill-100M.nc --dialect fanuc-mill --format json --time-limit 0
# Samples at 2 kHz on every thread (`perf record -F 2000`, Debian linux-perf), output to /dev/null.
# Symbols are self time (no call graph: the build has no frame pointers); the anonymous namespace
# is shortened to `anon` and argument lists dropped.
set -euo pipefail
kerf=$1; top=$2; shift 3
data=$(mktemp /tmp/kerf-profile.XXXXXX)
trap 'rm -f "$data"' EXIT
perf record -q -F 2000 -o "$data" "$kerf" "$@" >/dev/null 2>&1 || true
echo "threads (share of samples):"
perf report -i "$data" --no-children --sort pid --stdio 2>/dev/null | awk '/%/ && !/^#/ {printf "  %s %s\n", $1, $2}'
echo "top $top functions (self):"
perf report -i "$data" --no-children --sort symbol --stdio 2>/dev/null |
    awk '/%/ && !/^#/ {pct=$1; $1=""; $2=""; sub(/^ +/, ""); print pct, $0}' |
    sed -e 's/(anonymous namespace)/anon/g' -e 's/(.*$//' | head -n "$top" | sed 's/^/  /'
