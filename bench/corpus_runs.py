#!/usr/bin/env python3
"""How kerf's dry run ends on every program of ../shared/corpus, whole-process (issue 12, point 3).

    python3 bench/corpus_runs.py KERF [CORPUS] [--timeout S]

Runs `KERF run --lenient FILE` on every file of the corpus (MANIFEST.md aside) under GNU time with a
wall-clock timeout, and prints one line per file (ending, wall time, peak RSS) and a summary: endings
ended normally, bar-feed repeats, alarms by number, timeouts. Older builds without --lenient are run
without it. The endings are read from the command's own last lines (`ended normally`, `alarm N`),
so the script works on builds before and after the issue.
"""
import collections
import pathlib
import re
import subprocess
import sys
import tempfile


def run(kerf, path, timeout, lenient):
    with tempfile.NamedTemporaryFile("r") as t:
        cmd = ["/usr/bin/time", "-f", "%e %M", "-o", t.name, kerf, "run"] + (["--lenient"] if lenient else []) + [str(path)]
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, errors="replace", timeout=timeout)
        except subprocess.TimeoutExpired:
            return "timeout", timeout, None, ""
        fields = (t.read().strip().splitlines() or ["0 0"])[-1].split()
        wall, rss_kb = float(fields[0]), int(fields[1])
    out = p.stdout + p.stderr
    return classify(out), wall, rss_kb, out


def classify(out):
    m = re.search(r"alarm (\d+)", out)
    if "repeats" in out and "ended normally" in out:
        return "repeats"
    if m:
        return f"alarm {int(m.group(1))}"
    if "ended normally" in out:
        return "normal"
    if re.search(r"step limit|move limit", out, re.I):
        return "step limit"
    last = [l for l in out.splitlines() if l.strip()]
    return "other: " + (last[-1][:80] if last else "(no output)")


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    timeout = 120.0
    if "--timeout" in sys.argv:
        timeout = float(sys.argv[sys.argv.index("--timeout") + 1])
        args = [a for a in args if a != sys.argv[sys.argv.index("--timeout") + 1]]
    kerf = args[0]
    corpus = pathlib.Path(args[1] if len(args) > 1 else pathlib.Path(__file__).resolve().parents[1] / ".." / "shared" / "corpus")
    probe = subprocess.run([kerf, "run", "--help"], capture_output=True, text=True)
    lenient = "--lenient" in probe.stdout + probe.stderr
    files = sorted(p for p in corpus.rglob("*") if p.is_file() and p.name != "MANIFEST.md")
    endings = collections.Counter()
    total_wall = 0.0
    for f in files:
        ending, wall, rss, _ = run(kerf, f, timeout, lenient)
        total_wall += wall
        endings[ending.split(":")[0] if ending.startswith("other") else ending] += 1
        rss_txt = f"{rss / 1024:.0f} MB" if rss else "-"
        print(f"{f.relative_to(corpus)}\t{ending}\t{wall:.2f} s\t{rss_txt}", flush=True)
    print(f"\n{len(files)} files, --lenient {'on' if lenient else 'not available'}, timeout {timeout:.0f} s, "
          f"total wall {total_wall:.0f} s")
    for ending, n in sorted(endings.items(), key=lambda kv: (-kv[1], kv[0])):
        print(f"{n:4d}  {ending}")


if __name__ == "__main__":
    main()
