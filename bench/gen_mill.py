#!/usr/bin/env python3
"""Writes a deterministic FANUC mill program of about SIZE megabytes (default 100) to OUT.

    gen_mill.py OUT [SIZE] [--runnable] [--spelling fanuc|linuxcnc]

Lines look like real CAM output: `N1234 G01 X12.345 Y-3.2 Z-0.75 F1200.`, with arcs (R and I/J),
comments, tool changes (T M06 G43 H), spindle and coolant words. Used by bench/run.sh.

Without options the output is the parse benchmark's file (bench/RESULTS.md): its arcs take random
R and I/J values, so many of them are geometrically impossible (radius too small, end radius not the
start radius). A parser does not care; an interpreter stops at the first one (FANUC alarm 020).

--runnable   the same kind of program whose every arc is valid, for the dry-run benchmark
             (bench/dryrun_vs_rs274.sh): R at least half the chord plus 0.5 mm, the I/J centre on
             the chord's perpendicular bisector (start and end radius equal up to the 3-decimal
             rounding, < 0.001 mm). Same line mix and sizes as the default file; a different
             random sequence, so not the same bytes.
--spelling linuxcnc   with --runnable: the same toolpath, block for block, written for LinuxCNC's
             rs274 (bench/dryrun_vs_rs274.sh). The one difference is the program number line:
             `O1000 (BENCH ...)` becomes the comment `(O1000 BENCH ...)`, because an O word is a
             LinuxCNC o-code (sub, call, if ...) and one without a keyword, with a comment on its
             line, is undefined behaviour there (LinuxCNC's own rs274 happens to accept it). The `%`
             lines stay (LinuxCNC reads a file between `%` lines). Every other line is byte-identical,
             so the two files have the same blocks, words and motion.
"""
import argparse
import math
import random


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", nargs="?", default="bench-100mb.nc")
    ap.add_argument("size", nargs="?", default="100", help="megabytes (decimal), default 100")
    ap.add_argument("--runnable", action="store_true", help="valid arcs (for the dry run)")
    ap.add_argument("--spelling", choices=("fanuc", "linuxcnc"), default="fanuc")
    args = ap.parse_args()
    if args.spelling == "linuxcnc" and not args.runnable:
        ap.error("--spelling linuxcnc needs --runnable (rs274 stops at the default file's invalid arcs)")
    size = int(float(args.size) * 1_000_000)
    linuxcnc = args.spelling == "linuxcnc"
    # The default file keeps its historical seed and random sequence (same bytes as before).
    rnd = random.Random(20261121 if not args.runnable else 20261122)
    n = 10
    written = 0
    tool = 1
    with open(args.out, "w", newline="\n") as f:
        def emit(line):
            nonlocal written
            f.write(line + "\n")
            written += len(line) + 1

        emit("%")
        emit("(O1000 BENCH PROGRAM - GENERATED)" if linuxcnc else "O1000 (BENCH PROGRAM - GENERATED)")
        emit("G21 G17 G40 G49 G80 G90")
        x = y = 0.0
        while written < size:
            r = rnd.random()
            n += 1 if n < 99999 else -99990
            if r < 0.002:
                tool = tool % 24 + 1
                emit(f"N{n} T{tool:02d} M06 (TOOL {tool} - FLAT END MILL D{tool * 2}.)")
                emit(f"N{n} G54 G00 X0. Y0. S{rnd.randint(800, 12000)} M03")
                emit(f"N{n} G43 H{tool:02d} Z25. M08")
                if args.runnable:
                    x = y = 0.0
            elif r < 0.02:
                emit(f"(PASS {n} - CONTOUR AT Z-{rnd.random() * 5:.3f})")
            elif r < 0.12:
                x2 = round(x + rnd.uniform(-20, 20), 3)
                y2 = round(y + rnd.uniform(-20, 20), 3)
                if args.runnable and math.hypot(x2 - x, y2 - y) < 0.5:
                    x2 = round(x2 + 1.0, 3)   # keep chords away from zero (no accidental full circles)
                if rnd.random() < 0.5:
                    rad = rnd.uniform(15, 40)
                    if args.runnable:
                        rad = max(rad, math.hypot(x2 - x, y2 - y) / 2 + 0.5)
                    emit(f"N{n} G02 X{x2:.3f} Y{y2:.3f} R{rad:.3f} F{rnd.randint(200, 2400)}.")
                else:
                    i = rnd.uniform(-10, 10)
                    j = rnd.uniform(-10, 10)
                    if args.runnable:
                        # centre = chord midpoint + t * unit normal, t from the random I
                        dx, dy = x2 - x, y2 - y
                        chord = math.hypot(dx, dy)
                        cx = (x + x2) / 2 - dy / chord * i
                        cy = (y + y2) / 2 + dx / chord * i
                        i, j = round(cx - x, 3), round(cy - y, 3)
                    emit(f"N{n} G03 X{x2:.3f} Y{y2:.3f} I{i:.3f} J{j:.3f}")
                x, y = x2, y2
            elif r < 0.15:
                emit(f"N{n} G00 Z{rnd.uniform(2, 25):.1f}")
            else:
                x = round(x + rnd.uniform(-5, 5), 3)
                # the line writes Y with one decimal; the runnable file keeps the position it writes
                y = round(y + rnd.uniform(-5, 5), 1 if args.runnable else 3)
                emit(f"N{n} G01 X{x:.3f} Y{y:.1f} Z-{rnd.uniform(0, 3):.2f} F{rnd.randint(200, 2400)}.")
        emit("M30")
        emit("%")


if __name__ == "__main__":
    main()
