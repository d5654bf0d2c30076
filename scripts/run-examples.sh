#!/usr/bin/env bash
# `make run`: kerf on the bundled examples: which dialect it reads, the typed tree, the findings.
set -u
kerf=${1:-build/kerf}
cd "$(dirname "$0")/.."
status=0
for f in examples/*.nc; do
  echo "=== kerf parse $f"
  "$kerf" parse "$f" --explain-dialect
  rc=$?
  echo "--- exit code $rc ($( [ $rc = 0 ] && echo clean || echo 'findings: see the diagnostics above' ))"
  [ $rc -gt 1 ] && status=$rc
  echo
done
echo "=== kerf explain G71 --dialect fanuc-lathe-a --lang ru"
"$kerf" explain G71 --dialect fanuc-lathe-a --lang ru
echo
echo "=== kerf dialects"
"$kerf" dialects
exit $status
