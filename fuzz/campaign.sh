#!/bin/sh
# A fuzzing campaign: each target given for SECONDS, one after the other, each on its own
# working corpus (kept between campaigns under WORK, so the time adds up), then one markdown row
# per target for the table of fuzz/README.md "Campaigns".
#
#   fuzz/campaign.sh SECONDS [TARGET ...]      (default: every target of build-fuzz/)
#   WORK=/tmp/kerf-fuzz (default)   ARGS='-max_len=16384' (default)
#
# A finding stops that target's run and leaves its input under WORK/artifacts/TARGET/; fix it and
# copy the input to fuzz/regressions/<target>/ (README "Run").
set -eu
seconds=${1:?usage: fuzz/campaign.sh SECONDS [TARGET ...]}
shift
work=${WORK:-/tmp/kerf-fuzz}
args=${ARGS:--max_len=16384}
cd "$(dirname "$0")/.."
[ -d build-fuzz/seeds ] || { echo "make fuzz first" >&2; exit 2; }
targets=${*:-$(cd build-fuzz && ls fuzz_* | sed 's/^fuzz_//')}
rev=$(git rev-parse --short HEAD)
rows=""
for t in $targets; do
    mkdir -p "$work/corpus/$t" "$work/artifacts/$t"
    log="$work/$t-$(date -u +%Y%m%dT%H%M%S).log"
    start=$(date -u +%H:%M)
    set +e
    /usr/bin/time -f '%M %U %S' -o "$log.rss" "./build-fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
        $args -print_final_stats=1 -artifact_prefix="$work/artifacts/$t/" "$work/corpus/$t" "build-fuzz/seeds/$t" >"$log" 2>&1
    rc=$?
    set -e
    end=$(date -u +%H:%M)
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    secs=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
    cov=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -1)
    units=$(ls "$work/corpus/$t" | wc -l)
    # peak RSS and the CPU seconds the fuzzer had (user + system): on a shared machine the
    # wall-clock budget says little about how much fuzzing a run was.
    set -- $(tail -1 "$log.rss")
    rss=$(($1 / 1024))
    cpu=$(echo "$2 $3" | awk '{printf "%d", $1 + $2}')
    if [ "$rc" -eq 0 ]; then result="no crash, leak or timeout"; else result="FINDING (exit $rc): $(grep -m1 -E 'ERROR|invariant|SUMMARY' "$log" || echo see $log)"; fi
    row="| fuzz_$t | $rev | $(date -u +%F) $start–$end, ${seconds} s, ${cpu} CPU s | ${runs:-?} | ${secs:-?} | ${cov:-?} | $units | ${rss} MB | $result |"
    echo "$row"
    rows="$rows$row
"
done
printf '\n%s' "$rows"
