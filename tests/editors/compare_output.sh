#!/bin/sh
# Runs a real-client test and compares what it printed with its reviewed expected file.
#   compare_output.sh EXPECTED COMMAND [ARGS...]
# On a difference: the unified diff and exit 1 (the new output is left next to the build for review).
expected="$1"; shift
actual="$(mktemp)"
trap 'rm -f "$actual"' EXIT
if ! "$@" > "$actual"; then
    echo "compare_output.sh: the client failed: $*" >&2
    cat "$actual" >&2
    exit 1
fi
if ! diff -u "$expected" "$actual"; then
    echo "compare_output.sh: the output differs from $expected (review it, then update the file)" >&2
    exit 1
fi
