#!/usr/bin/env bash
# `make run`: kerf's main jobs on the bundled examples (examples/): lint the folder, dry-run a
# program for its cycle time, draw a toolpath into an SVG file, check the formatting; then which
# dialect kerf reads and why. Each step says what its exit code means; the script fails only when
# kerf fails to run (exit 2 or a crash), not when it finds the defects examples/defects.nc holds
# on purpose.
set -u
kerf=${1:-build/kerf}
cd "$(dirname "$0")/.."
out_dir=$(cd "$(dirname "$kerf")" && pwd)
svg="$out_dir/lathe-shaft.svg"
status=0

step() {   # step "what the exit codes mean" kerf-arguments...
  local meaning=$1
  shift
  echo "=== kerf $*"
  "$kerf" "$@"
  local rc=$?
  echo "--- exit code $rc ($meaning)"
  if [ $rc -gt 1 ]; then status=$rc; fi
  echo
}

step "0 clean, 1 findings: examples/defects.nc holds the reference's seed defects on purpose" check examples
step "0: ended normally" run examples/lathe-shaft.nc
step "0: ended normally; the picture is $svg" plot examples/lathe-shaft.nc -o "$svg"
[ -s "$svg" ] && echo "wrote $svg ($(wc -c < "$svg") bytes): open it in a browser" && echo
step "0 formatted, 1 a file would change or cannot be formatted (defects.nc has syntax errors)" fmt --check examples
step "0 converted (and its dry run the same as the source's), 1 constructs left or a difference" convert examples/lathe-shaft.nc --to fanuc-lathe-b --verify
step "0 clean, 1 syntax errors" parse examples/lathe-shaft.nc --explain-dialect --stats
echo "=== kerf explain G71 --dialect fanuc-lathe-a --lang ru"
"$kerf" explain G71 --dialect fanuc-lathe-a --lang ru
echo
echo "=== kerf dialects"
"$kerf" dialects
exit $status
