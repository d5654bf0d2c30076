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
