#!/usr/bin/env python3
# Writes the rule fixtures from the hand-written table below (kept for review; run once, the
# files are committed). Each entry: dialect, bad program, good program, expected findings as
# (line, the text the finding starts at, severity). The column is where that text starts on the
# line: the position is what I (the author) say the defect is, not what kerf prints.
import os, sys
L, M, ISO = "fanuc-lathe-a", "fanuc-mill", "iso-legacy-mill"
E, W, I, H = "error", "warning", "info", "hint"
def prog(*lines): return "O0001\n" + "\n".join(lines) + "\nM30\n"
F = {
 "K1001-address-without-value": (L, prog("G01 X-11.Z F0.2"), prog("G01 X-11. Z-5. F0.2"), [(2, "Z F", E)]),
 "K1002-malformed-number": (L, prog("G01 X-12.8. Z-3. F0.2"), prog("G01 X-12.8 Z-3. F0.2"), [(2, "X-12.8.", E)]),
 "K1003-letter-o-for-zero": (M, prog("T2 MO6"), prog("T2 M06"), [(2, "MO6", E)]),
 "K1004-placeholder-value": (L, prog("G00 X? Z1."), prog("G00 X1. Z1."), [(2, "X?", E)]),
 "K1005-decimal-comma": (L, prog("G01 Z-1,3 F0.25"), prog("G01 Z-1.3 F0.25"), [(2, "-1,3", W)]),
 "K1006-unknown-word": (L, prog("UNLOAD"), prog("(UNLOAD)"), [(2, "UNLOAD", E)]),
 "K1007-value-without-address": (L, prog("N10 21 G40"), prog("N10 G21 G40"), [(2, "21", E)]),
 "K1008-misplaced-block-delete": (L, prog("G00 / X10."), prog("/ G00 X10."), [(2, "/", E)]),
 "K1009-stray-text": (L, prog("G01 X10. F0.2 @"), prog("G01 X10. F0.2 (@)"), [(2, "@", E)]),
 "K1010-unknown-comma-word": (L, prog("G01 X10. ,Q5"), prog("G01 X10. ,C1."), [(2, ",Q5", E)]),
 "K1011-slash-comment": (L, prog("G00 X0. // HOME"), prog("G00 X0. (HOME)"), [(2, "//", E)]),
 "K1012-zero-for-letter-o": (L, "00018\nG00 X0.\nM30\n", "O0018\nG00 X0.\nM30\n", [(1, "00018", W)]),
 "K1013-listing-ellipsis": (L, prog("G00 X0.", "...", "G00 X1."), prog("G00 X0.", "G00 X1."), [(3, "...", E)]),
 "K1014-unclosed-comment": (L, prog("G00 X0. (HOME"), prog("G00 X0. (HOME)"), [(2, "(HOME", E)]),
 "K1015-nested-comment": (L, prog("(ROUGH (OD) PASS)"), prog("(ROUGH - OD - PASS)"), [(2, "(OD", W)]),
 "K1016-unmatched-close-paren": (L, prog("G01 X1. F0.2)"), prog("G01 X1. F0.2"), [(2, ")", E)]),
 "K1017-packed-p-with-l": (L, prog("M98 P41001 L2") + "O1001\nM99\n", prog("M98 P41001") + "O1001\nM99\n", [(2, "P41001", E)]),
 "K1018-second-sequence-number": (L, prog("N50 G01 X1. N30"), prog("N50 G01 X1."), [(2, "N30", E)]),
 "K1019-parser-limit": (L, prog("#1=" + "[" * 70 + "1" + "]" * 70), prog("#1=[[1]]"), [(2, "#1=", E)]),
 "K1020-missing-decimal-point": (M, prog("G01 X10 Y10. F100."), prog("G01 X10. Y10. F100."), [(2, "X10", W)]),
 "K1021-duplicate-address": (L, prog("G01 X10. F0.010 F.010"), prog("G01 X10. F0.010"), [(2, "F.010", W)]),
 "K1022-point-on-integer-address": (L, prog("M08."), prog("M08"), [(2, "M08.", W)]),
 "K1023-byte-order-mark": (L, "\ufeff" + prog("G00 X0."), prog("G00 X0."), [(1, "\ufeff", I)]),
 "K1024-empty-comment": (L, prog("G00 X0. ()"), prog("G00 X0."), [(2, "()", H)]),
 "K1025-non-ascii-comment": (L, prog("(ТОКАРНЫЙ)"), prog("(TOKARNYJ)"), [(2, "(", I)]),
 # One finding per file (issue 15: the p2g generator writes 64 of them), at the first lower-case letter.
 "K1026-lower-case-address": (L, prog("g01 z-18.5 F0.2", "x10."), prog("G01 Z-18.5 F0.2"), [(2, "g", I)]),
 "K2001-unknown-code": (L, prog("G384 X10."), prog("G00 X10."), [(2, "G384", E)]),
 "K2002-code-not-fitted": (M, prog("G12.1"), prog("G00 X0."), [(2, "G12.1", W)]),
 "K2003-word-not-allowed": (L, prog("G04 Q5"), prog("G04 P500"), [(2, "Q5", W)]),
 "K2004-required-word-missing": (L, prog("G00 X0. Z0.", "G02 X20. Z-5. F0.2"), prog("G00 X0. Z0.", "G02 X20. Z-5. R5. F0.2"), [(3, "G02", E)]),
 "K2005-modal-group-conflict": (L, prog("G00 G01 X10. F0.2"), prog("G01 X10. F0.2"), [(2, "G01", W)]),
 "K2007-css-and-clamp-in-one-block": (L, prog("G50 G96 S200"), prog("G50 S2000", "G96 S200"), [(2, "G50", E)]),
 "K2008-meaning-differs-between-dialects": (L, prog("G90 X20. Z-10. F0.2"), prog("G01 X20. Z-10. F0.2"), [(2, "G90", I)]),
 # M codes the table lacks: one note per file at the first (a machine builder's codes; no alarm 010).
 "K2010-unlisted-m-code": (M, prog("M25 G49", "M165 P9810 Z-.5", "M25"), prog("M08"), [(2, "M25", I)]),
 "K3001-label-not-found": (L, prog("G71 U1. R0.5", "G71 P100 Q200 U0.5 W0.1 F0.3", "N100 G00 X20.", "N210 G01 Z-10."),
                           prog("G71 U1. R0.5", "G71 P100 Q200 U0.5 W0.1 F0.3", "N100 G00 X20.", "N200 G01 Z-10."), [(3, "Q200", E)]),
 "K3002-ambiguous-label": (L, prog("#1=1", "IF [#1 EQ 1] GOTO 10", "N10 G00 X1.", "N10 G00 X2."), prog("#1=1", "IF [#1 EQ 1] GOTO 10", "N10 G00 X1.", "N20 G00 X2."), [(3, "IF", W)]),
 # Once per program and file: the second call to O1234 says nothing new (issue 15).
 "K3003-program-not-found": (L, prog("M98 P1234", "M98 P1234"), prog("M98 P1000") + "O1000\nM99\n", [(2, "P1234", E)]),
 "K3004-loop-mismatch": (L, prog("#1=0", "WHILE [#1 LT 3] DO 1", "#1=#1+1", "END 2"), prog("#1=0", "WHILE [#1 LT 3] DO 1", "#1=#1+1", "END 1"),
                         [(3, "WHILE", E), (5, "END 2", E)]),
 "K3005-loop-nesting-too-deep": (L, prog("#1=0", "WHILE [#1 LT 1] DO 1", "WHILE [#1 LT 1] DO 2", "WHILE [#1 LT 1] DO 3", "WHILE [#1 LT 1] DO 1", "#1=1", "END 1", "END 3", "END 2", "END 1"),
                                 prog("#1=0", "WHILE [#1 LT 1] DO 1", "WHILE [#1 LT 1] DO 2", "WHILE [#1 LT 1] DO 3", "#1=1", "END 3", "END 2", "END 1"), [(6, "WHILE", E)]),
 "K3006-missing-program-end": (L, "O0001\nG00 X0.\n", "O0001\nG00 X0.\nM30\n", [(1, "O0001", W)]),
 "K3007-unreachable-block": (L, prog("G00 X0.", "M30", "G00 X100."), prog("G00 X100."), [(4, "G00 X100.", W)]),
 "K3008-duplicate-program-number": (L, "O0100\nM30\nO0100\nM99\n", "O0100\nM30\nO0101\nM99\n", [(3, "O0100", E)]),
 "K3009-protected-program-number": (L, "O9001\nG00 X0.\nM99\n", "O1001\nG00 X0.\nM99\n", [(1, "O9001", I)]),
 # N10 twice and not a jump target (MANIFEST: O0001 N130-N150, O0005 N30/N70): one finding at the second.
 "K3011-duplicate-sequence-number": (M, prog("N10 G00 X0. Y0.", "N20 Z1.", "N10 G01 Z-1. F100."), prog("N10 G00 X0. Y0.", "N20 Z1.", "N30 G01 Z-1. F100."),
                                     [(4, "N10 G01", W)]),
 "K4001-vacant-local-in-arithmetic": (L, prog("#2=#1+10."), prog("#1=5.", "#2=#1+10."), [(2, "#1", W)]),
 "K4002-division-by-zero": (L, prog("#1=10/0"), prog("#1=10/2"), [(2, "10/0", E)]),
 "K4003-write-read-only-variable": (L, prog("#0=1"), prog("#100=1"), [(2, "#0", E)]),
 "K4004-endless-loop": (L, prog("N1 GOTO 1"), prog("#1=0", "WHILE [#1 LT 3] DO 1", "#1=#1+1", "END 1"), [(2, "N1 GOTO 1", E)]),
 "K4005-macro-evaluation-error": (L, prog("#1=SQRT[-1]"), prog("#1=SQRT[1]"), [(2, "#1=SQRT[-1]", E)]),
 "K4006-user-alarm": (L, prog("#3000=1(NO TOOL)"), prog("IF [#20 NE #0] THEN #3000=1(NO TOOL)"), [(2, "#3000", W)]),
 "K4007-call-nesting-too-deep": (L, "O0001\nM98 P0002\nM30\nO0002\nM98 P0002\nM99\n", "O0001\nM98 P0002\nM30\nO0002\nM99\n", [(5, "M98", E)]),
 "K4008-call-without-program": (L, prog("G65 A1. B2."), prog("G65 P1000 A1. B2.") + "O1000\nM99\n", [(2, "G65", E)]),
 "K4009-call-target-not-found": (L, "O0001\nM98 P0002\nM30\nO0002\nM99 P50\n", "O0001\nM98 P0002\nN50 M30\nO0002\nM99 P50\n", [(5, "M99", E)]),
 "K4010-data-input-out-of-range": (L, prog("G10 L2 P9 X0."), prog("G10 L2 P1 X0."), [(2, "G10", E)]),
 "K4011-reference-point-number": (L, prog("G30 P5 U0."), prog("G30 P3 U0."), [(2, "G30", E)]),
 "K4099-interpreter-alarm": (L, prog("#1=#[-5]"), prog("#1=#5"), [(2, "#1", E)]),
 "K5001-feed-move-without-feed": (L, prog("T0101", "G01 X10. Z-1."), prog("T0101", "G01 X10. Z-1. F0.2"), [(3, "G01", E)]),
 "K5002-feed-with-spindle-stopped": (L, prog("T0101", "G99 G01 X10. Z-1. F0.2"), prog("T0101", "G97 S800 M03", "G99 G01 X10. Z-1. F0.2"), [(3, "G99", W)]),
 "K5003-thread-lead-too-fast": (L, prog("T0101", "G97 S3000 M03", "G00 X20. Z2.", "G32 Z-20. F20."), prog("T0101", "G97 S300 M03", "G00 X20. Z2.", "G32 Z-20. F20."), [(5, "G32", E)]),
 "K5005-feed-per-rev-too-high": (L, prog("T0101", "G97 S800 M03", "G99 G01 Z-5. F100."), prog("T0101", "G97 S800 M03", "G98 G01 Z-5. F100."), [(4, "G99", W)]),
 "K5006-feed-per-min-too-low": (L, prog("T0101", "G97 S800 M03", "G98 G01 Z-5. F0.2"), prog("T0101", "G97 S800 M03", "G99 G01 Z-5. F0.2"), [(4, "G98", W)]),
 "K5007-rapid-at-cut-depth": (M, prog("T1 M06", "G00 X0. Y0. Z5.", "G01 Z-5. F100.", "G01 X50. Y50.", "G00 X25. Y20."),
                              prog("T1 M06", "G00 X0. Y0. Z5.", "G01 Z-5. F100.", "G01 X50. Y50.", "G00 Z5.", "G00 X25. Y20."), [(6, "G00", W)]),
 "K5008-cut-without-tool": (L, prog("G01 X10. Z-1. F0.2"), prog("T0101", "G01 X10. Z-1. F0.2"), [(2, "G01", W)]),
 "K5009-not-checked-by-dry-run": (ISO, prog("G00 X0. Y0.", "G43 D1", "G01 X10. Y5. F100."), prog("G00 X0. Y0.", "G01 X10. Y5. F100."), [(3, "G43", I)]),
 "K5010-spindle-without-speed": (L, prog("M03"), prog("G97 S800 M03"), [(2, "M03", W)]),
 "K5011-css-without-clamp": (L, prog("G96 S200 M03"), prog("G50 S2000", "G96 S200 M03"), [(2, "G96", W)]),
 "K5012-thread-in-css": (L, prog("G50 S2000", "G96 S150 M03", "G00 X20. Z2.", "G32 Z-20. F1.5"), prog("G50 S2000", "G97 S800 M03", "G00 X20. Z2.", "G32 Z-20. F1.5"), [(5, "G32", W)]),
 "K5013-compensation-start-on-arc": (L, prog("G00 X0. Z0.", "G02 G41 X20. Z-5. R15. F0.2"), prog("G00 X0. Z0.", "G01 G41 X20. Z-1. F0.2", "G02 X20. Z-5. R15."), [(3, "G41", E)]),
 "K5014-arc-radius-mismatch": (L, prog("T0101", "G00 X0. Z0.", "G02 X20. Z-10. R2. F0.2"), prog("T0101", "G00 X0. Z0.", "G02 X20. Z-10. R10. F0.2"), [(4, "G02", E)]),
 "K5016-compensation-cancel-on-arc": (L, prog("G00 X0. Z0.", "G03 G40 X30. Z-10. R15. F0.2"), prog("G00 X0. Z0.", "G03 X30. Z-10. R15. F0.2", "G00 G40 X40."), [(3, "G40", E)]),
 "K5017-compensation-active-at-end": (L, "O0001\nG42 G01 X20. F0.2\nM30\n", "O0001\nG42 G01 X20. F0.2\nG00 G40 X100.\nM30\n", [(3, "M30", W)]),
 "K5018-tool-without-offset": (L, prog("T0100"), prog("T0101"), [(2, "T0100", W)]),
 # T9 M06 loads T9; T1 alone pre-selects the next tool: H1 is not the spindle's (issue 15).
 "K5019-length-offset-mismatch": (M, prog("T9 M06", "T1", "G43 H1 Z50."), prog("T9 M06", "T1", "G43 H9 Z50."), [(4, "H1", W)]),
 "K5020-g28-absolute-intermediate": (L, prog("G28 X0. Z0."), prog("G28 U0. W0."), [(2, "X0.", W)]),
 "K5022-cycle-parameter-out-of-range": (L, prog("G04 X-1."), prog("G04 X1."), [(2, "X-1.", E)]),
 # An 8 x 8 pocket with a 10 mm cutter (G10 L12 R5.): the offset of Y18. runs from (13,15) to (13,13), against the
 # programmed direction, so the control stops at that block (alarm 041); a 30 x 30 pocket fits.
 # Inch resolution (0.0001) without G20 on a machine that starts in mm (corpus CGIP09902.NC).
 "K5024-units-not-set": (M, "O0001\nG90 G54 G00 X1.5234 Y2.1250\nG01 Z-0.1250 F10.\nX2.5000 Y3.0625\nX0.5000\nM30\n",
                         "O0001\nG20 G90 G54 G00 X1.5234 Y2.1250\nG01 Z-0.1250 F10.\nX2.5000 Y3.0625\nX0.5000\nM30\n", [(2, "G90", W)]),
 "K5023-compensation-overcut": (M, prog("G10 L12 P1 R5.", "G90 G00 X0. Y0.", "G41 D1 G01 X10. Y10. F100.", "X18.", "Y18.", "X10.", "Y10.", "G40 G00 X0. Y0."),
                                prog("G10 L12 P1 R5.", "G90 G00 X0. Y0.", "G41 D1 G01 X10. Y10. F100.", "X40.", "Y40.", "X10.", "Y10.", "G40 G00 X0. Y0."),
                                [(6, "Y18.", E)]),
}
# K2009 needs detection: "# foreign" runs it on bad.nc and good.nc as the project layer does.
FOREIGN = {"K2009-foreign-control": (M, "%@MACRO\n// UNLOAD ALL TOOLS\n#100:=0;\nIF (#100 = 0) THEN\nEND_IF;\n", prog("#100=0"),
                                     [(1, "%@MACRO", W)], "# foreign")}
# The rules that compare a program with its machine need a machine file ("# machine-file M..": the
# machine was given, with these M codes); the built-in machines' limits are guesses (issue 15).
MACHINE = {
 "K2006-too-many-m-codes": (L, prog("S800 M03 M08"), prog("S800 M03", "M08"), [(2, "M08", E)], "# machine-file"),
 "K2011-m-code-not-on-machine": (M, prog("M25 G49", "M77"), prog("M25 G49", "M08"), [(3, "M77", W)], "# machine-file M25"),
 "K5021-spindle-over-limit": (L, prog("G97 S9000 M03"), prog("G97 S3000 M03"), [(2, "S9000", W)], "# machine-file"),
}
# K5015 needs soft limits: the harness sets them from "# soft-limit AXIS MIN MAX".
SOFT = {"K5015-soft-limit": (L, prog("G00 X900."), prog("G00 X200."), [(2, "G00", E)], "# soft-limit X -500 10")}   # machine X: home 0, the spindle axis at -300
# K3010 needs other files: the harness answers the program index's question from
# "# program-files N FILE..." (the real index is tested in tests/project/test_workspace.cpp).
INDEX = {"K3010-program-in-several-files": (M, prog("M98 P1000"), prog("M98 P1001"), [(2, "P1000", W)],
                                            "# program-files 1000 a.nc old/a.nc")}
here = os.path.dirname(os.path.abspath(__file__))
def write(name, d, bad, good, exp, extra=None):
    os.makedirs(os.path.join(here, name), exist_ok=True)
    open(os.path.join(here, name, "bad.nc"), "w", encoding="utf-8").write(bad)
    open(os.path.join(here, name, "good.nc"), "w", encoding="utf-8").write(good)
    lines = bad.split("\n")
    out = [f"# dialect {d}"] + ([extra] if extra else [])
    for (ln, needle, sev) in exp:
        text = lines[ln - 1]
        assert needle in text, (name, needle, text)
        col = len(text[: text.index(needle)].encode("utf-8")) + 1   # byte column
        out.append(f"{ln}:{col} {sev} {name.split('-')[0]}")
    open(os.path.join(here, name, "expected.txt"), "w").write("\n".join(out) + "\n")
for k, v in F.items(): write(k, *v)
for k, v in SOFT.items(): write(k, v[0], v[1], v[2], v[3], v[4])
for k, v in FOREIGN.items(): write(k, v[0], v[1], v[2], v[3], v[4])
for k, v in MACHINE.items(): write(k, v[0], v[1], v[2], v[3], v[4])
for k, v in INDEX.items(): write(k, v[0], v[1], v[2], v[3], v[4])
