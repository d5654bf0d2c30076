#!/usr/bin/env python3
"""Seed corpora for the fuzz targets, generated at run time (fuzz/README.md): nothing here is
committed, the seeds are written under OUT (default build-fuzz/seeds/<target>/).

Program targets (grammar, interpreter, analyzer, formatter, converter): byte 0 picks the dialect, so each
program becomes one seed per dialect it may be: the dialect of its `(DIALECT: id)` header (the
reference examples carry one), else the guess of its corpus folder (lathe -> fanuc-lathe-a, the
others -> fanuc-mill). Programs are cut to SEED_BYTES at a line end: a dry run of a whole CAM
program would make every execution slow, and libFuzzer mutates the start of a seed most.
Sources: fuzz/corpus (already in the target format), ../shared/reference/examples, ../shared/corpus.
The converter's byte 0 also picks the target (fuzz/checks.hpp check_converter): each program becomes
one seed per other dialect of its machine kind, and one with --expand.
TOML targets: machine/data/*.toml and dialects/data/*.toml, the examples of the schemas; for
kerf_toml, the .kerf.toml files of docs/config.md and tests/. The input target (the decoder) gets
the program seeds in UTF-8 and transcoded to UTF-16LE/BE (BOM or not) and UTF-32LE, behind its two
option bytes (line limit 0 = none, split step).

usage: fuzz/make_seeds.py [OUT]
"""
import hashlib
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SHARED = os.path.join(ROOT, "..", "shared")
OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build-fuzz", "seeds")
SEED_BYTES = 16 * 1024
# byte 0 -> dialect: (byte + 6) % 9 (fuzz/checks.cpp, fuzz/fuzz_grammar.cpp): '0'..'8' in this order.
DIALECTS = ["fanuc-lathe-a", "fanuc-lathe-b", "fanuc-lathe-c", "spinner-lathe-a", "fanuc-mill",
            "adv400-mill", "adv400-lathe", "pcnc-mill", "iso-legacy-mill"]


def write(target, data):
    d = os.path.join(OUT, target)
    os.makedirs(d, exist_ok=True)
    name = hashlib.sha1(data).hexdigest()[:16]
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def cut(data):
    if len(data) <= SEED_BYTES:
        return data
    end = data.rfind(b"\n", 0, SEED_BYTES)
    return data[: end + 1 if end > 0 else SEED_BYTES]


def dialect_byte(path, data):
    m = re.search(rb"\(DIALECT:\s*([a-z0-9-]+)", data[:4096])
    if m and m.group(1).decode() in DIALECTS:
        return str(DIALECTS.index(m.group(1).decode())).encode()
    return b"0" if os.sep + "lathe" + os.sep in path else b"4"


LATHES = {0, 1, 2, 3, 6}


def option_byte(source, target, style_expand=0):
    """byte 0 of a converter seed: (b + 6) % 9 is the source, (b // 9) % 9 the target, b // 81 the
    U/W style (1: letters) and --expand (2, 3) (fuzz/checks.cpp check_converter)."""
    for b in range(256):
        if (b + 6) % 9 == source and (b // 9) % 9 == target and b // 81 == style_expand:
            return bytes([b])
    raise ValueError((source, target, style_expand))


def converter_seeds(seed):
    source = (seed[0] + 6) % 9
    kind = LATHES if source in LATHES else set(range(9)) - LATHES
    for target in sorted(kind - {source}):
        yield option_byte(source, target) + seed[1:]
    yield option_byte(source, min(kind - {source}), 2) + seed[1:]


def programs():
    corpus = os.path.join(HERE, "corpus")
    for name in sorted(os.listdir(corpus)):
        with open(os.path.join(corpus, name), "rb") as f:
            yield f.read()
    for top in (os.path.join(SHARED, "reference", "examples"), os.path.join(SHARED, "corpus")):
        for dirpath, _, files in os.walk(top):
            for name in sorted(files):
                if name.endswith(".md"):
                    continue
                path = os.path.join(dirpath, name)
                with open(path, "rb") as f:
                    data = cut(f.read())
                yield dialect_byte(path, data) + data


def main():
    count = 0
    for seed in programs():
        for target in ("grammar", "interpreter", "analyzer", "formatter"):
            write(target, seed)
        for variant in converter_seeds(seed):
            write("converter", variant)
        count += 1
        if count % 7 == 0:   # a sample: the decoder does not need every program
            text = seed[1:4097]
            write("input", b"\0\x07" + text)
            try:
                u = text.decode("utf-8")
                for enc, bom in (("utf-16-le", b"\xff\xfe"), ("utf-16-be", b""), ("utf-32-le", b"")):
                    write("input", b"\0\x05" + bom + u.encode(enc))
            except UnicodeDecodeError:
                pass
    for example in (
        b"dialect = \"fanuc-mill\"\n[check]\ninclude = [\"**/*.nc\"]\n[check.rules]\nK1020 = \"off\"\n",
        b"[run]\ncall = \"G65 P9010 A1.\"\nset = [\"#100=5\"]\npasses = 2\n[programs]\nlibrary = [\"../lib\"]\n"
        b"resident = [\"O9000-O9999\"]\n[limits]\nmax_file_bytes = 1000\ntime_limit = 2.5\n",
        b"[format]\nletter_case = \"upper\"\nspacing = \"none\"\n",
    ):
        write("kerf_toml", example)
    for target, folder in (("machine_toml", "machine/data"), ("dialect_toml", "dialects/data")):
        d = os.path.join(ROOT, folder)
        for name in sorted(os.listdir(d)):
            if name.endswith(".toml"):
                with open(os.path.join(d, name), "rb") as f:
                    write(target, f.read())
    print(f"{count} program seeds and the TOML seeds in {OUT}")


main()
