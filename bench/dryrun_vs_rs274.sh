#!/usr/bin/env bash
# Dry-run benchmark against LinuxCNC's rs274 (bench/RESULTS.md, "Dry run"):
#   bench/dryrun_vs_rs274.sh BUILD_DIR
#
#   1. generates, if missing, in BUILD_DIR (bench/gen_mill.py --runnable: every arc valid, so both
#      interpreters run to M30):
#        bench-dryrun-100mb.nc   the FANUC program (kerf)
#        bench-dryrun-100mb.ngc  the same toolpath in LinuxCNC spelling (rs274): only the O line differs
#        bench-dryrun-10mb.nc / .ngc   the same at 10 MB, for memory growth
#      (KERF_DRYRUN_MB / KERF_DRYRUN_SMALL_MB change the sizes; the cases are named big and small)
#      and rs274-tools.tbl (tools 1-24, zero length: kerf's default machine has no offsets either)
#   2. checks that both really run the whole file: kerf's summary (blocks executed, ended normally)
#      and its trace event counts by kind against rs274's canonical calls (STRAIGHT_TRAVERSE /
#      STRAIGHT_FEED / ARC_FEED, PROGRAM_END), from the timed runs that write to a real file
#   3. runs, KERF_DRYRUN_RUNS times (default 3), in one go and pinned to one core (taskset; not
#      with KERF_DRYRUN_PIN=0, where kerf's read-ahead thread gets the second core):
#        kerf run F.nc                       no trace: the tree and the interpreter
#        kerf run F.nc --trace /dev/null     the JSON-lines trace produced and thrown away
#        kerf run F.nc --trace out.jsonl     the trace written to a file in BUILD_DIR
#        rs274 -g -t tools.tbl F.ngc /dev/null      canonical calls thrown away
#        rs274 -g -t tools.tbl F.ngc out.txt        canonical calls written to a file
#      on the 100 MB files, and kerf (all three) and rs274 (/dev/null) on the 10 MB files, each
#      under /usr/bin/time -v (wall, user, sys, peak RSS)
#   4. prints the table: best wall time and the spread over the runs, MB/s of each tool on its own
#      file, blocks/s on the same block count, peak RSS, rs274 time / kerf time
#   5. runs BUILD_DIR/bench/kerf_bench_dryrun (Google Benchmark) on the 100 MB file, unless
#      KERF_DRYRUN_GBENCH=0; extra arguments go to it
#
# Needs kerf and kerf_bench_dryrun built with -DKERF_BENCH=ON, rs274 (Debian linuxcnc-uspace) and
# GNU time (`make bench` installs both).
set -euo pipefail

build=${1:-build}
[ $# -gt 0 ] && shift
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$build" && pwd)
runs=${KERF_DRYRUN_RUNS:-3}

kerf="$build/kerf"
gbench="$build/bench/kerf_bench_dryrun"
. "$here/common.sh"
require_built dryrun_vs_rs274.sh "$build" kerf kerf_bench_dryrun
rs274=$(command -v rs274 || true)
if [ -z "$rs274" ]; then
    echo "dryrun_vs_rs274.sh: rs274 is missing (Debian package linuxcnc-uspace; make bench installs it)" >&2
    exit 2
fi
if [ ! -x /usr/bin/time ]; then
    echo "dryrun_vs_rs274.sh: /usr/bin/time is missing (Debian package time; make bench installs it)" >&2
    exit 2
fi

# ---- inputs ----
gen() {   # gen FILE MB [options]
    local file=$1 mb=$2
    shift 2
    if [ ! -s "$file" ]; then
        echo "== generating $file ($mb MB $*)"
        python3 "$here/gen_mill.py" "$file.tmp" "$mb" "$@"
        mv "$file.tmp" "$file"
    fi
}
big_mb=${KERF_DRYRUN_MB:-100}
small_mb=${KERF_DRYRUN_SMALL_MB:-10}
for mb in "$big_mb" "$small_mb"; do
    gen "$build/bench-dryrun-${mb}mb.nc" "$mb" --runnable
    gen "$build/bench-dryrun-${mb}mb.ngc" "$mb" --runnable --spelling linuxcnc
done
tools="$build/rs274-tools.tbl"
if [ ! -s "$tools" ]; then
    for t in $(seq 1 24); do echo "T$t P$t Z0 D$(awk -v t="$t" 'BEGIN {printf "%.4f", t * 2 / 25.4}') ;flat end mill D$((t * 2)) mm"; done > "$tools"
fi

# ---- machine ----
echo "== machine"
echo "date:     $(date -u '+%Y-%m-%d %H:%M UTC')"
command -v lscpu >/dev/null && echo "cpu:      $(lscpu | sed -n 's/^Model name: *//p' | head -1)"
echo "cores:    $(nproc) (nproc)"
echo "memory:   $(awk '/MemTotal/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo)"
echo "kernel:   $(uname -r)"
cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt" | head -1)
[ -n "$cxx" ] && echo "compiler: $("$cxx" --version | head -1)"
echo "build:    $(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt" | head -1)"
if command -v git >/dev/null && git -C "$here/.." rev-parse --git-dir >/dev/null 2>&1; then
    dirty=$(git -C "$here/.." status --porcelain -- grammar ast dialects interpreter motion machine cli | wc -l)
    echo "source:   $(git -C "$here/.." rev-parse --short HEAD)$([ "$dirty" -gt 0 ] && echo " + $dirty uncommitted file(s) in the libraries and cli/")"
fi
echo "rs274:    $rs274, $(dpkg-query -W -f='${Package} ${Version}' linuxcnc-uspace 2>/dev/null || echo 'version unknown')"
echo "load:     $(cut -d' ' -f1-3 /proc/loadavg) (1/5/15 min)"

# KERF_DRYRUN_PIN=0: not pinned. kerf then reads ahead on the second core (the grammar parses the
# next pieces while the interpreter runs); rs274 is single-threaded either way.
pin=()
if [ "${KERF_DRYRUN_PIN:-1}" != 0 ] && command -v taskset >/dev/null; then
    core=1
    [ "$(nproc)" -lt 2 ] && core=0
    pin=(taskset -c "$core")
    echo "pinning:  taskset -c $core (every measured process)"
fi

big_nc="$build/bench-dryrun-${big_mb}mb.nc"
big_ngc="$build/bench-dryrun-${big_mb}mb.ngc"
small_nc="$build/bench-dryrun-${small_mb}mb.nc"
small_ngc="$build/bench-dryrun-${small_mb}mb.ngc"
echo "== input"
for f in "$big_nc" "$big_ngc" "$small_nc" "$small_ngc"; do
    echo "$(basename "$f"): $(stat -c %s "$f") bytes, $(wc -l < "$f") lines"
done
echo "difference between the ${big_mb} MB files (diff):"
diff "$big_nc" "$big_ngc" | sed 's/^/    /' || true

# ---- measurements ----
tmp=$(mktemp -d)
kerf_trace="$build/dryrun-trace.jsonl"
rs_out="$build/dryrun-rs274.txt"
trap 'rm -rf "$tmp" "$kerf_trace" "$rs_out"' EXIT
results="$tmp/results"   # case run wall user sys rss_kb status
: > "$results"

measure() {   # measure CASE RUN command...
    local case=$1 run=$2
    shift 2
    local tv="$tmp/time" status=0
    "${pin[@]}" /usr/bin/time -v -o "$tv" "$@" > "$tmp/stdout" 2> "$tmp/stderr" < /dev/null || status=$?
    local wall user sys rss
    wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + p[i]; print s}' "$tv")
    user=$(awk -F': ' '/User time/ {print $2}' "$tv")
    sys=$(awk -F': ' '/System time/ {print $2}' "$tv")
    rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$tv")
    echo "$case $run $wall $user $sys $rss $status" >> "$results"
    printf '  %-22s run %d: %7.2f s wall, %6.2f user, %5.2f sys, peak RSS %7.1f MB, exit %d\n' \
        "$case" "$run" "$wall" "$user" "$sys" "$(awk -v k="$rss" 'BEGIN {print k * 1024 / 1e6}')" "$status"
}

check_kerf() {   # after kerf run --json --trace FILE: the summary and the trace's kinds
    echo "  kerf summary: $(grep -o -E '"(blocks|completed)":[a-z0-9]+|"alarms":\[[^]]*\]' "$tmp/stdout" | tr '\n' ' ')"
    echo "  kerf trace: $(wc -l < "$kerf_trace") lines, $(stat -c %s "$kerf_trace") bytes; events by kind:"
    cut -d'"' -f4 "$kerf_trace" | sort | uniq -c | sort -rn | tee "$tmp/kerf-kinds" | awk '{printf "    %-18s %d\n", $2, $1}'
}
check_rs274() {
    echo "  rs274 output: $(wc -l < "$rs_out") lines, $(stat -c %s "$rs_out") bytes; exit $1; stderr: $(tr '\n' ' ' < "$tmp/stderr" | cut -c1-200)"
    echo "  canonical calls by name (top 12):"
    awk '{c = $3; sub(/\(.*/, "", c); n[c]++} END {for (k in n) printf "%d %s\n", n[k], k}' "$rs_out" | sort -rn > "$tmp/rs-calls"
    head -12 "$tmp/rs-calls" | awk '{printf "    %-28s %d\n", $2, $1}'
    echo "  last lines:"
    tail -3 "$rs_out" | sed 's/^/    /'
    # the same moves? kerf rapid / linear / arc_cw + arc_ccw / tool_change against rs274's calls
    awk 'FNR == NR {k[$2] = $1; next} {r[$2] = $1}
         END {
             kr = k["rapid"] + 0; kl = k["linear"] + 0; ka = k["arc_cw"] + k["arc_ccw"]; kt = k["tool_change"] + 0
             rr = r["STRAIGHT_TRAVERSE"] + 0; rl = r["STRAIGHT_FEED"] + 0; ra = r["ARC_FEED"] + 0; rt = r["CHANGE_TOOL"] + 0
             same = kr == rr && kl == rl && ka == ra && kt == rt && ("PROGRAM_END" in r)
             printf "  same work: kerf rapid %d / linear %d / arc %d / tool change %d; rs274 STRAIGHT_TRAVERSE %d / STRAIGHT_FEED %d / ARC_FEED %d / CHANGE_TOOL %d, PROGRAM_END %s: %s\n",
                 kr, kl, ka, kt, rr, rl, ra, rt, ("PROGRAM_END" in r) ? "yes" : "no", same ? "EQUAL" : "DIFFERENT"
         }' "$tmp/kerf-kinds" "$tmp/rs-calls"
}

echo "== runs ($runs rounds; each round runs every case once, in this order)"
for run in $(seq 1 "$runs"); do
    echo "-- round $run (load $(cut -d' ' -f1-3 /proc/loadavg))"
    measure kerf-big-notrace "$run" "$kerf" run "$big_nc" --dialect fanuc-mill --json
    measure kerf-big-devnull "$run" "$kerf" run "$big_nc" --dialect fanuc-mill --json --trace /dev/null
    measure kerf-big-file "$run" "$kerf" run "$big_nc" --dialect fanuc-mill --json --trace "$kerf_trace"
    if [ "$run" = 1 ]; then check_kerf; fi
    rm -f "$kerf_trace"
    measure rs274-big-devnull "$run" "$rs274" -g -t "$tools" "$big_ngc" /dev/null
    measure rs274-big-file "$run" "$rs274" -g -t "$tools" "$big_ngc" "$rs_out"
    if [ "$run" = 1 ]; then check_rs274 "$(awk '$1 == "rs274-big-file" {s = $7} END {print s}' "$results")"; fi
    rm -f "$rs_out"
    measure kerf-small-notrace "$run" "$kerf" run "$small_nc" --dialect fanuc-mill --json
    measure kerf-small-devnull "$run" "$kerf" run "$small_nc" --dialect fanuc-mill --json --trace /dev/null
    measure kerf-small-file "$run" "$kerf" run "$small_nc" --dialect fanuc-mill --json --trace "$kerf_trace"
    rm -f "$kerf_trace"
    measure rs274-small-devnull "$run" "$rs274" -g -t "$tools" "$small_ngc" /dev/null
done

# ---- table ----
echo "== results over $runs rounds (MB = 10^6 bytes)"
bytes_of() { stat -c %s "$1"; }
lines_of() { wc -l < "$1"; }
b100nc=$(bytes_of "$big_nc") b100ngc=$(bytes_of "$big_ngc")
b10nc=$(bytes_of "$small_nc") b10ngc=$(bytes_of "$small_ngc")
l100=$(lines_of "$big_nc") l10=$(lines_of "$small_nc")
awk -v b100nc="$b100nc" -v b100ngc="$b100ngc" -v b10nc="$b10nc" -v b10ngc="$b10ngc" -v l100="$l100" -v l10="$l10" '
{
    c = $1; cpu = $4 + $5
    if (!(c in best) || $3 < best[c]) best[c] = $3
    if (!(c in worst) || $3 > worst[c]) worst[c] = $3
    if (!(c in bcpu) || cpu < bcpu[c]) bcpu[c] = cpu
    if (!(c in rss) || $6 > rss[c]) rss[c] = $6
    if (!(c in rmin) || $6 < rmin[c]) rmin[c] = $6
    if ($7 != 0) bad[c] = bad[c] " " $7
    if (!(c in seen)) { order[++n] = c; seen[c] = 1 }
}
function ratio(c, ref, v) { return (c !~ /^rs274/ && ref in v && v[c] > 0) ? sprintf("%.1fx", v[ref] / v[c]) : "-" }
END {
    printf "%-19s %8s %7s %7s %8s %10s %7s %8s %13s %8s %8s\n", "case", "input MB", "wall s", "spread", "MB/s", "blocks/s", "CPU s", "CPU MB/s", "peak RSS MB", "x wall", "x CPU"
    for (i = 1; i <= n; i++) {
        c = order[i]
        big = c ~ /-big-/
        bytes = c ~ /^rs274/ ? (big ? b100ngc : b10ngc) : (big ? b100nc : b10nc)
        lines = big ? l100 : l10
        ref = c ~ /-file$/ ? (big ? "rs274-big-file" : "") : (big ? "rs274-big-devnull" : "rs274-small-devnull")
        lo = sprintf("%.1f", rmin[c] * 1024 / 1e6); hi = sprintf("%.1f", rss[c] * 1024 / 1e6); rssr = lo == hi ? hi : lo "-" hi
        printf "%-19s %8.1f %7.2f %6.1f%% %8.1f %10.0f %7.2f %8.1f %13s %8s %8s%s\n", c, bytes / 1e6, best[c], (worst[c] / best[c] - 1) * 100,
               bytes / 1e6 / best[c], lines / best[c], bcpu[c], bytes / 1e6 / bcpu[c], rssr, ratio(c, ref, best), ratio(c, ref, bcpu),
               (c in bad) ? "  EXIT" bad[c] : ""
    }
    print ""
    print "big = " b100nc " bytes (.nc) / " b100ngc " (.ngc), small = " b10nc " / " b10ngc "; blocks (lines): " l100 " big, " l10 " small, the same in both spellings"
    print "wall s: best wall time; spread: slowest / best - 1; MB/s and blocks/s: on the best wall time, each tool on its own file;"
    print "CPU s: best user + sys; x wall / x CPU: rs274 time / kerf time (kerf without trace and with --trace /dev/null against rs274 to"
    print "/dev/null, which still formats every canonical call; kerf --trace to a file against rs274 writing its calls to a file)"
}' "$results"

echo "== memory: tree vs trace (peak RSS, MB)"
awk -v b100="$b100nc" -v b10="$b10nc" '
{ if (!($1 in r) || $6 > r[$1]) r[$1] = $6 }
END {
    for (s = 0; s < 2; s++) {
        sz = s ? "small" : "big"; b = s ? b10 : b100
        nt = r["kerf-" sz "-notrace"] * 1024 / 1e6; dn = r["kerf-" sz "-devnull"] * 1024 / 1e6; fl = r["kerf-" sz "-file"] * 1024 / 1e6
        printf "kerf, %5.1f MB file: no trace %.1f, --trace /dev/null %.1f, --trace file %.1f (the trace adds %+.1f / %+.1f); no trace / input %.2f\n", b / 1e6, nt, dn, fl, dn - nt, fl - nt, nt * 1e6 / b
    }
    printf "rs274: %.1f MB file %.1f, %.1f MB file %.1f\n", b10 / 1e6, r["rs274-small-devnull"] * 1024 / 1e6, b100 / 1e6, r["rs274-big-devnull"] * 1024 / 1e6
}' "$results"
cp "$results" "$build/dryrun-results.txt"
echo "(raw figures: $build/dryrun-results.txt: case round wall user sys peak_kb exit)"

# ---- Google Benchmark ----
if [ "${KERF_DRYRUN_GBENCH:-1}" != 0 ]; then
    echo "== kerf_bench_dryrun (${pin[*]:-not pinned})"
    KERF_DRYRUN_FILE="$big_nc" "${pin[@]}" "$gbench" \
        --benchmark_out="$build/bench-dryrun-results.json" --benchmark_out_format=json "$@"
fi
