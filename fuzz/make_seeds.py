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

fuzz_lsp gets scripts of messages (fuzz/check_lsp.cpp): a session through every request of the
server on a lathe program, edits with ranges inside and outside the text, cancellations, settings
from the client, broken framing, a request before initialize, and a sample of the programs opened,
edited and asked about.

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


# fuzz_lsp: scripts of messages (fuzz/check_lsp.cpp Writer::step; one byte picks the kind, the bytes
# after it fill it in, in the order step() reads them).
def lsp_initialize(flags=0, dialect=4):        # dialect: index into kDialects (4 = fanuc-lathe-a)
    return bytes([1, flags, dialect])


def lsp_open(uri, version, program=None, text=None):
    if text is not None:                          # choice % 4 == 0: the text from the script
        text = text[:255 * 4]
        n = (len(text) + 3) // 4
        return bytes([3, uri, version, 0, n]) + text.ljust(n * 4, b"\n")
    choice = next(c for c in range(1, 256) if c % 4 and c % 5 == program)   # kPrograms[program]
    return bytes([3, uri, version, choice])


def lsp_change(uri, piece, line, char, end_line, end_char):   # one ranged change, kPieces[piece]
    return bytes([4, 0, piece, line, char, end_line, end_char, uri])


def lsp_request(method, uri, line, char, b=1):   # method: index into kRequests; b % 3 != 0: newName digits
    body = bytes([6, method, uri, line, char, line, 0, line + 1, 0, b])
    body += bytes(b % 4)                          # query
    body += bytes([line, char, line, char + 1])   # positions
    body += bytes([uri, line, 0, line, 5, line, 0, line, 5, uri])   # item, data
    return body


LSP_SHUTDOWN_EXIT = bytes([8, 9])


def lsp_seeds(programs_for_lsp):
    every_request = b"".join(lsp_request(m, 0, 6, 9) for m in range(24))
    yield lsp_initialize() + bytes([2]) + lsp_open(0, 1, program=0) + every_request + LSP_SHUTDOWN_EXIT
    yield (lsp_initialize(3, 3) + bytes([2]) + lsp_open(0, 1, program=1) + lsp_change(0, 2, 2, 5, 2, 5) +
           lsp_change(0, 4, 40, 0, 3, 1) + bytes([7, 0]) + lsp_request(0, 0, 2, 5) + bytes([14]) + LSP_SHUTDOWN_EXIT)
    yield (lsp_initialize(1, 5) + bytes([15, 1, 3, 2]) + lsp_open(1, 1, program=2) + lsp_open(2, 1, program=3) +
           bytes([11, 4, 1]) + lsp_request(2, 1, 7, 6) + bytes([10, 1, 16, 1, 1]) + lsp_request(19, 0, 0, 1) + bytes([14]))
    yield bytes([0, 12]) + b"Content-Len" + lsp_initialize() + bytes([12, 5]) + b"{bad}" + bytes([13, 2, 18, 3, 17, 5]) + LSP_SHUTDOWN_EXIT
    yield lsp_request(0, 0, 0, 0) + lsp_initialize() + bytes([5, 0, 1]) + bytes([9])
    for text in programs_for_lsp:
        yield (lsp_initialize(0, 0) + bytes([2]) + lsp_open(0, 1, text=text) + lsp_change(0, 1, 3, 2, 3, 4) +
               lsp_request(0, 0, 3, 2) + lsp_request(7, 0, 0, 0) + lsp_request(15, 0, 0, 0) + LSP_SHUTDOWN_EXIT)


def main():
    count = 0
    for_lsp = []
    for seed in programs():
        for target in ("grammar", "interpreter", "analyzer", "formatter"):
            write(target, seed)
        for variant in converter_seeds(seed):
            write("converter", variant)
        count += 1
        if count % 5 == 0:   # a sample of programs as documents of the language server
            for_lsp.append(seed[1:1021])
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
    for script in lsp_seeds(for_lsp):
        write("lsp", script)
    print(f"{count} program seeds, the TOML seeds and {len(for_lsp) + 5} message scripts in {OUT}")


main()
