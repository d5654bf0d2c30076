#!/usr/bin/env python3
"""Writes a deterministic FANUC mill program of about SIZE megabytes (default 100) to OUT.

Lines look like real CAM output: `N1234 G01 X12.345 Y-3.2 Z-0.75 F1200.`, with arcs (R and I/J),
comments, tool changes (T M06 G43 H), spindle and coolant words. Used by bench/run.sh.
"""
import random
import sys


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "bench-100mb.nc"
    size = int(float(sys.argv[2] if len(sys.argv) > 2 else "100") * 1_000_000)
    rnd = random.Random(20261121)
    n = 10
    written = 0
    tool = 1
    with open(out, "w", newline="\n") as f:
        def emit(line):
            nonlocal written
            f.write(line + "\n")
            written += len(line) + 1

        emit("%")
        emit("O1000 (BENCH PROGRAM - GENERATED)")
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
            elif r < 0.02:
                emit(f"(PASS {n} - CONTOUR AT Z-{rnd.random() * 5:.3f})")
            elif r < 0.12:
                x2 = round(x + rnd.uniform(-20, 20), 3)
                y2 = round(y + rnd.uniform(-20, 20), 3)
                if rnd.random() < 0.5:
                    emit(f"N{n} G02 X{x2:.3f} Y{y2:.3f} R{rnd.uniform(15, 40):.3f} F{rnd.randint(200, 2400)}.")
                else:
                    emit(f"N{n} G03 X{x2:.3f} Y{y2:.3f} I{rnd.uniform(-10, 10):.3f} J{rnd.uniform(-10, 10):.3f}")
                x, y = x2, y2
            elif r < 0.15:
                emit(f"N{n} G00 Z{rnd.uniform(2, 25):.1f}")
            else:
                x = round(x + rnd.uniform(-5, 5), 3)
                y = round(y + rnd.uniform(-5, 5), 3)
                emit(f"N{n} G01 X{x:.3f} Y{y:.1f} Z-{rnd.uniform(0, 3):.2f} F{rnd.randint(200, 2400)}.")
        emit("M30")
        emit("%")


if __name__ == "__main__":
    main()
