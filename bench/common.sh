# Shared by the bench scripts (sourced, not run).

# require_built SCRIPT BUILD_DIR TARGET...: exits 2 naming the build command when a target's
# binary is missing (kerf in BUILD_DIR, the Google Benchmark harnesses in BUILD_DIR/bench).
require_built() {
    local script=$1 build=$2
    shift 2
    local target exe
    for target in "$@"; do
        if [ "$target" = kerf ]; then exe="$build/kerf"; else exe="$build/bench/$target"; fi
        if [ ! -x "$exe" ]; then
            echo "$script: $exe is missing; build with: cmake -S . -B $build -DCMAKE_BUILD_TYPE=Release -DKERF_BENCH=ON && cmake --build $build --target $*" >&2
            exit 2
        fi
    done
}

# print_machine REPO FILE: the date, CPU, cores, the source commit and the input, for the log.
print_machine() {
    echo "== machine"
    echo "date:     $(date -u '+%Y-%m-%d %H:%M UTC')"
    command -v lscpu >/dev/null && echo "cpu:      $(lscpu | sed -n 's/^Model name: *//p' | head -1)"
    echo "cores:    $(nproc)"
    echo "source:   $(git -C "$1" rev-parse --short HEAD 2>/dev/null || echo '?')"
    echo "input:    $(stat -c %s "$2") bytes ($2)"
}

# time_runs NAME COMMAND...: RUNS (a variable of the caller) timed runs of COMMAND, pinned to one
# core when taskset is there, output to /dev/null, one line each (GNU time: wall, user, sys, peak
# RSS, the load), then the best and median wall time. Needs /usr/bin/time.
time_runs() {
    local name=$1
    shift
    local pin=() walls=() timing
    command -v taskset >/dev/null && pin=(taskset -c $(( $(nproc) > 1 ? 1 : 0 )))
    timing=$(mktemp)
    for ((i = 1; i <= runs; i++)); do
        "${pin[@]}" /usr/bin/time -o "$timing" -f '%e %U %S %M' "$@" >/dev/null 2>/dev/null || true
        read -r wall user sys rss < <(tail -1 "$timing")
        printf '%-10s run %d: %5.2f s wall, %5.2f s user, %5.2f s sys, peak %d MB, load %s\n' \
            "$name" "$i" "$wall" "$user" "$sys" $((rss / 1024)) "$(cut -d' ' -f1 /proc/loadavg)"
        walls+=("$wall")
    done
    rm -f "$timing"
    printf '%s\n' "${walls[@]}" | sort -n | awk -v n="$name" '{ w[NR] = $1 } END {
        printf "%-10s best %.2f s, median %.2f s wall\n", n, w[1], w[int((NR + 1) / 2)] }'
}
