#!/usr/bin/env bash
# Whole-process figures on short-line CAM output, side by side with LinuxCNC's rs274 (issue 18;
# bench/RESULTS.md "Whole process on CAM output"):
#   bench/cam.sh BUILD_DIR
#
#   1. generates in KERF_BENCH_DATA (default /tmp/kerf-bench-data; never the repository), if missing:
#        K/K-100M.nc (K = mill, lathe, macro)  ../shared/tools/gen_program.py --kind K --size 100M (seed 1)
#        ngc/K-100M.ngc                         gen_program.py --linuxcnc: the same program for rs274 (O line dropped)
#        small/                                 10,000 programs of 2-8 KB (bench/gen_small_programs.py: mill, lathe, macro)
#      (KERF_BENCH_SIZE changes the size, e.g. 10M for a quick look). Each big file has a folder of
#      its own: a call the macro program cannot resolve in its file makes kerf index the folder.
#   2. runs KERF_BENCH_RUNS rounds (default 5); each round runs every case once, so a disturbance of
#      the shared machine spreads over the cases instead of hitting one; every process is timed by
#      GNU time (wall, user, sys, peak RSS, minor faults), output to /dev/null:
#        parse   kerf parse F --dialect D --stats
#        run     kerf run F --dialect D --json --time-limit 0
#        check   kerf check F --dialect D --format json --time-limit 0
#      (--time-limit 0: the dry run's default wall-clock limit of 10 s would cut a run short on a
#      loaded machine, and the figure would then be of less work)
#        fmt     kerf fmt F --dialect D
#        rs274   rs274 -g -t ../shared/tools/linuxcnc-tool.tbl F.ngc /dev/null
#      for the mill, lathe and macro programs (D = fanuc-mill, fanuc-lathe-a, fanuc-mill); then
#        check-folder   kerf check small --format json      (each file's dialect detected)
#        corpus-run     kerf run FILE --json                 on the corpus's 4 largest files
#      Not pinned: kerf uses the second core where it has one (kerf run reads ahead, check runs the
#      dry run beside the static rules, a folder check runs files on every core). KERF_BENCH_PIN=1 pins
#      every process to one core (taskset) to see the one-core figure.
#   3. prints, and writes to BUILD_DIR/cam-results.md, the table: median wall (and the spread), user and
#      sys of the median run, CPU / wall (> 1: two cores busy), the median CPU time, peak RSS and its ratio to the input,
#      MB/s, and rs274's median / kerf's median on the same program, in wall and in CPU time. rs274 runs the mill
#      program to its end; it stops at the first line it cannot read in the lathe program (U/W words)
#      and the macro program (WHILE), which the table says (no ratio there).
#   KERF_BENCH_KERF=path runs another kerf binary (a build of the commit before a change) with the
#   same script; KERF_BENCH_TIMEOUT (seconds, default 600) ends a case that runs longer (exit 124 in
#   the table: the figure is then a lower bound).
#   KERF_BENCH_RAW=file prints the table again from the raw figures of an earlier run.
#   The raw figures stay in BUILD_DIR/cam-raw.txt (case round wall user sys peak_kb minflt exit load).
#
# Needs kerf built (cmake --build BUILD_DIR --target kerf), rs274 (Debian linuxcnc-uspace) and GNU
# time (`make bench` installs both).
set -euo pipefail

build=${1:-build}
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$build" && pwd)
shared=$(cd "$here/../../shared" 2>/dev/null && pwd || true)
[ -n "$shared" ] || shared=/work/shared
gen="$shared/tools/gen_program.py"
tools="$shared/tools/linuxcnc-tool.tbl"
corpus="$shared/corpus"
data=${KERF_BENCH_DATA:-/tmp/kerf-bench-data}
size=${KERF_BENCH_SIZE:-100M}
runs=${KERF_BENCH_RUNS:-5}
kerf=${KERF_BENCH_KERF:-$build/kerf}
limit=${KERF_BENCH_TIMEOUT:-600}
. "$here/common.sh"
[ -n "${KERF_BENCH_KERF:-}" ] || require_built cam.sh "$build" kerf
rs274=$(command -v rs274 || true)
for need in "$gen" "$tools" /usr/bin/time; do
    [ -e "$need" ] || { echo "cam.sh: $need is missing" >&2; exit 2; }
done
[ -n "$rs274" ] || { echo "cam.sh: rs274 is missing (Debian linuxcnc-uspace; make bench installs it)" >&2; exit 2; }

# ---- inputs ----
mkdir -p "$data/ngc" "$data/mill" "$data/lathe" "$data/macro"
kinds=(mill lathe macro)
declare -A dialect=([mill]=fanuc-mill [lathe]=fanuc-lathe-a [macro]=fanuc-mill)
for k in "${kinds[@]}"; do
    f="$data/$k/$k-$size.nc"
    if [ ! -s "$f" ]; then
        echo "== generating $f"
        python3 "$gen" --kind "$k" --size "$size" --out "$f.tmp" && mv "$f.tmp" "$f"
    fi
    [ -s "$data/ngc/$k-$size.ngc" ] || python3 "$gen" --linuxcnc "$f" "$data/ngc/$k-$size.ngc"
done
small="$data/small"
if [ ! -d "$small" ]; then
    echo "== generating $small"
    python3 "$here/gen_small_programs.py" "$gen" "$small.tmp" 10000 && mv "$small.tmp" "$small"
fi
mapfile -t largest < <(find "$corpus" -type f ! -name MANIFEST.md -printf '%s %p\n' | sort -rn | head -4 | cut -d' ' -f2-)

# ---- machine ----
echo "== machine"
echo "date:     $(date -u '+%Y-%m-%d %H:%M UTC')"
command -v lscpu >/dev/null && echo "cpu:      $(lscpu | sed -n 's/^Model name: *//p' | head -1)"
echo "cores:    $(nproc)"
echo "memory:   $(awk '/MemTotal/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo)"
echo "kernel:   $(uname -r)"
echo "build:    $(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt" | head -1)"
echo "kerf:     $kerf"
echo "source:   $(git -C "$here/.." rev-parse --short HEAD 2>/dev/null || echo '?')$( [ -n "$(git -C "$here/.." status --porcelain -uno 2>/dev/null)" ] && echo ' + uncommitted changes')"
echo "rs274:    $rs274, $(dpkg-query -W -f='${Package} ${Version}' linuxcnc-uspace 2>/dev/null || echo 'version unknown')"
for k in "${kinds[@]}"; do
    f="$data/$k/$k-$size.nc"
    echo "input:    $f: $(stat -c %s "$f") bytes, $(wc -l < "$f") lines"
done
echo "folder:   $small: $(find "$small" -type f | wc -l) files, $(du -sb "$small" | cut -f1) bytes"

pin=()
if [ "${KERF_BENCH_PIN:-0}" = 1 ]; then
    pin=(taskset -c $(( $(nproc) > 1 ? 1 : 0 )))
    echo "pinning:  ${pin[*]}"
fi

# ---- measurements ----
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
raw="$build/cam-raw.txt"

measure() {   # measure CASE ROUND command...
    local case=$1 round=$2 status=0
    shift 2
    local guard=()
    [ "$1" = "$kerf" ] && guard=(timeout "$limit")   # rs274 always runs to its end
    "${pin[@]}" /usr/bin/time -o "$tmp/time" -f '%e %U %S %M %R' "${guard[@]}" "$@" > /dev/null 2> "$tmp/stderr" < /dev/null || status=$?
    local t
    t=$(tail -1 "$tmp/time")
    echo "$case $round $t $status $(cut -d' ' -f1 /proc/loadavg)" >> "$raw"
    printf '  %-24s %s  exit %d  load %s\n' "$case" "$t" "$status" "$(cut -d' ' -f1 /proc/loadavg)"
}

if [ -n "${KERF_BENCH_RAW:-}" ]; then   # only the table, from the raw figures of an earlier run
    [ "$KERF_BENCH_RAW" -ef "$raw" ] || cp "$KERF_BENCH_RAW" "$raw"
else
: > "$raw"
echo "== runs ($runs rounds; wall user sys peak_kb minor_faults)"
for round in $(seq 1 "$runs"); do
    echo "-- round $round (load $(cut -d' ' -f1-3 /proc/loadavg))"
    for k in "${kinds[@]}"; do
        f="$data/$k/$k-$size.nc"
        d=${dialect[$k]}
        measure "$k/parse" "$round" "$kerf" parse "$f" --dialect "$d" --stats
        measure "$k/run" "$round" "$kerf" run "$f" --dialect "$d" --json --time-limit 0
        measure "$k/check" "$round" "$kerf" check "$f" --dialect "$d" --format json --time-limit 0
        measure "$k/fmt" "$round" "$kerf" fmt "$f" --dialect "$d"
        if [ "$k" = mill ] || [ "$round" = 1 ]; then
            measure "$k/rs274" "$round" "$rs274" -g -t "$tools" "$data/ngc/$k-$size.ngc" /dev/null
            [ "$k" = mill ] || echo "$k: $(grep -v '^executing' "$tmp/stderr" | head -2 | tr '\n' ' ')" > "$tmp/rs274-$k"
        fi
    done
    measure "folder/check" "$round" "$kerf" check "$small" --format json
    for f in "${largest[@]}"; do
        measure "corpus-run/$(basename "$f")" "$round" "$kerf" run "$f" --json
    done
done

# What each run did (from one run each, outside the timing): kerf run's summary, rs274's end.
echo "== what the runs did"
for k in "${kinds[@]}"; do
    f="$data/$k/$k-$size.nc"
    echo "$k: kerf run: $("$kerf" run "$f" --dialect "${dialect[$k]}" --json 2>/dev/null | grep -o -E '"(blocks|completed)":[a-z0-9]+' | tr '\n' ' ')"
    [ -f "$tmp/rs274-$k" ] && echo "$k: rs274 stops: $(cat "$tmp/rs274-$k")"
done
for f in "${largest[@]}"; do
    echo "$(basename "$f"): $(stat -c %s "$f") bytes; kerf run: $("$kerf" run "$f" --json 2>/dev/null | grep -o -E '"(blocks|completed)":[a-z0-9]+' | tr '\n' ' ')"
done
fi

# ---- table ----
out="$build/cam-results.md"
bytes_list=""
for k in "${kinds[@]}"; do bytes_list="$bytes_list $k=$(stat -c %s "$data/$k/$k-$size.nc")"; done
bytes_list="$bytes_list folder=$(du -sb "$small" | cut -f1)"
for f in "${largest[@]}"; do bytes_list="$bytes_list corpus-run/$(basename "$f")=$(stat -c %s "$f")"; done
awk -v sizes="$bytes_list" '
function median_index(c,   i, j, n, idx, w, t) {   # the round whose wall time is the median
    n = cnt[c]
    for (i = 1; i <= n; i++) { idx[i] = i; w[i] = wall[c, i] }
    for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (w[idx[j]] < w[idx[i]]) { t = idx[i]; idx[i] = idx[j]; idx[j] = t }
    lo = w[idx[1]]; hi = w[idx[n]]
    return idx[int((n + 1) / 2)]
}
function median_cpu(c,   i, j, n, v, t) {   # the median of user + sys over the rounds
    n = cnt[c]
    for (i = 1; i <= n; i++) v[i] = user[c, i] + sys[c, i]
    for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (v[j] < v[i]) { t = v[i]; v[i] = v[j]; v[j] = t }
    return v[int((n + 1) / 2)]
}
BEGIN { n = split(sizes, s, " "); for (i = 1; i <= n; i++) { split(s[i], kv, "="); bytes[kv[1]] = kv[2] } }
{
    c = $1; i = ++cnt[c]
    wall[c, i] = $3; user[c, i] = $4; sys[c, i] = $5; rss[c, i] = $6; flt[c, i] = $7; st[c, i] = $8
    if (!(c in seen)) { order[++m] = c; seen[c] = 1 }
}
END {
    print "| case | median wall s (min-max) | user s | sys s | CPU/wall | median CPU s | peak RSS MB | RSS / input | minor faults | MB/s | rs274 / kerf wall | rs274 / kerf CPU |"
    print "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    for (o = 1; o <= m; o++) {
        c = order[o]; mi = median_index(c)
        split(c, part, "/"); key = part[1] == "corpus-run" ? c : part[1]
        b = bytes[key]; mw = wall[c, mi]
        peak = 0; for (r = 1; r <= cnt[c]; r++) if (rss[c, r] > peak) peak = rss[c, r]
        ratio = "-"; cratio = "-"; mc = median_cpu(c)
        if (part[1] == "mill" && part[2] != "rs274" && ("mill/rs274" in seen)) {
            rmi = median_index("mill/rs274"); ratio = sprintf("%.1fx", wall["mill/rs274", rmi] / mw)
            if (mc > 0) cratio = sprintf("%.1fx", median_cpu("mill/rs274") / mc)
            mi = median_index(c)   # median_index sets lo/hi for the row
        }
        if (part[2] == "rs274" && part[1] != "mill") ratio = cratio = "stops early"
        bad = ""; for (r = 1; r <= cnt[c]; r++) if (st[c, r] != 0 && st[c, r] != 1) bad = " (exit " st[c, r] ")"
        printf "| %s%s | %.2f (%.2f-%.2f) | %.2f | %.2f | %.2f | %.2f | %.0f | %s | %d | %s | %s | %s |\n", c, bad, mw, lo, hi,
            user[c, mi], sys[c, mi], (mw > 0) ? (user[c, mi] + sys[c, mi]) / mw : 0, mc, peak * 1024 / 1e6,
            (b > 0) ? sprintf("%.2f", peak * 1024 / b) : "-", flt[c, mi], (b > 0 && mw > 0) ? sprintf("%.1f", b / 1e6 / mw) : "-", ratio, cratio
    }
    print ""
    print "Median of the rounds by wall time; user, sys and minor faults of that run; peak RSS the largest of all rounds;"
    print "CPU/wall > 1 where kerf kept both cores busy; rs274 / kerf = rs274 median / kerf median on the same mill program, in wall"
    print "time and in CPU time (user + sys: what a loaded machine disturbs least). exit 124: ended by the time limit (a lower bound)."
}' "$raw" | tee "$out"
echo "(table: $out; raw figures: $raw)"
