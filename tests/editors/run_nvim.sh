#!/bin/sh
# Runs the Neovim real-client test and compares its output with the reviewed expected file.
#   run_nvim.sh KERF_BINARY SOURCE_DIR
set -e
kerf="$1"; src="$2"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT
KERF_BINARY="$kerf" KERF_WORKSPACE="$src/tests/editors/workspace" KERF_OUT="$out" \
    timeout 120 nvim --headless -u NONE -i NONE --cmd "set rtp+=$src/editors/nvim" \
    -c "luafile $src/tests/editors/nvim_client.lua" > /dev/null 2>&1 || { echo "nvim failed:"; cat "$out"; exit 1; }
if ! diff -u "$src/tests/editors/nvim_client.expected" "$out"; then
    echo "run_nvim.sh: the output differs from tests/editors/nvim_client.expected (review it, then update the file)" >&2
    exit 1
fi
