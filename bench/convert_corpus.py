#!/usr/bin/env python3
"""`kerf convert --verify` over the whole corpus and the reference examples, one target at a time
(bench/RESULTS.md "kerf convert"): files converted, reported, verified per target, as a markdown table.

usage: bench/convert_corpus.py KERF [SHARED_DIR]

Each target converts the files whose source dialect is for the same kind of machine (lathe targets
the lathe programs, mill targets the mill programs; the source dialect is what `kerf convert`
resolves: the (DIALECT: ...) header or detection). The results go to a temporary --output-dir.
Columns: files of that kind; converted cleanly (exit 0 for the file: nothing left as it was, no
syntax error); files whose only reports are syntax errors (converted around them); files with
constructs left as they were, and how many constructs; --verify agreeing; --verify differing (of
these, how many converted with nothing left as it was: a difference there would be a converter
bug); wall time of the whole command.
"""
import json
import os
import subprocess
import sys
import tempfile
import time

LATHE = ["fanuc-lathe-a", "fanuc-lathe-b", "fanuc-lathe-c", "spinner-lathe-a", "spinner-lathe-b", "spinner-lathe-c",
         "adv400-lathe"]
MILL = ["fanuc-mill", "adv400-mill", "pcnc-mill", "iso-legacy-mill"]
TARGETS = ["fanuc-lathe-a", "fanuc-lathe-b", "fanuc-lathe-c", "spinner-lathe-b", "spinner-lathe-c", "adv400-lathe",
           "fanuc-mill", "adv400-mill",
           "pcnc-mill", "iso-legacy-mill"]


def kind(dialect):
    return "lathe" if dialect in LATHE else "mill" if dialect in MILL else "?"


def main():
    kerf = sys.argv[1]
    shared = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "..", "shared")
    sources = [os.path.join(shared, "corpus"), os.path.join(shared, "reference", "examples")]
    print("| target | source kind | files | clean | syntax errors only | with constructs left (constructs) | verified | differ (of them nothing left) | wall |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for target in TARGETS:
        with tempfile.TemporaryDirectory() as out:
            start = time.time()
            run = subprocess.run([kerf, "convert", "--to", target, "--verify", "--format", "json", "--output-dir", out]
                                 + sources, capture_output=True, text=True)
            wall = time.time() - start
        doc = json.loads(run.stdout)
        files = [f for f in doc["files"] if kind(f.get("from", "")) == kind(target) and f.get("from") != target]
        def left(f):
            return sum(1 for r in f["reports"] if r["kind"] == "not converted")
        clean = sum(1 for f in files if f["clean"])
        syntax_only = sum(1 for f in files if not f["clean"] and left(f) == 0)
        with_left = sum(1 for f in files if left(f) > 0)
        constructs = sum(left(f) for f in files)
        verified = sum(1 for f in files if f.get("verified") is True)
        differ = sum(1 for f in files if f.get("verified") is False)
        differ_nothing_left = sum(1 for f in files if f.get("verified") is False and left(f) == 0)
        print(f"| {target} | {kind(target)} | {len(files)} | {clean} | {syntax_only} | {with_left} ({constructs}) | {verified} | "
              f"{differ} ({differ_nothing_left}) | {wall:.1f} s |")


if __name__ == "__main__":
    main()
