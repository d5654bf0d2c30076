#!/usr/bin/env python3
"""A folder of small programs for `kerf check FOLDER` (bench/cam.sh, issue 18).

    gen_small_programs.py GEN_PROGRAM.py OUT_DIR [COUNT]

Writes COUNT (default 10,000) programs with ../shared/tools/gen_program.py's generators, each
with its own seed: 70 % mill, 20 % lathe, 10 % macro, 2-8 KB each (about 100-450 lines of the
short CAM lines the issue is about). One Python process for all of them (10,000 runs of the
generator's command line would take minutes). Deterministic for a given COUNT.
"""
import importlib.util
import os
import random
import sys


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    spec = importlib.util.spec_from_file_location("gen_program", sys.argv[1])
    gen = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(gen)
    out_dir = sys.argv[2]
    count = int(sys.argv[3]) if len(sys.argv) == 4 else 10000
    os.makedirs(out_dir, exist_ok=True)
    pick = random.Random(18)
    for i in range(count):
        roll = pick.random()
        kind = "mill" if roll < 0.7 else "lathe" if roll < 0.9 else "macro"
        size = pick.randrange(2000, 8000)
        rnd = random.Random("%s-%d-%d" % (kind, size, i))
        with open(os.path.join(out_dir, "%s_%05d.nc" % (kind, i)), "w") as f:
            o = gen.Out(f, size)
            if kind == "lathe":
                gen.gen_lathe(o, rnd)
            else:
                gen.gen_mill(o, rnd, macro=(kind == "macro"))
            o.flush()


if __name__ == "__main__":
    main()
