// Rule behaviour beyond the one bad/good pair of each fixture: the cases the reference examples
// showed (fragments, cycle parameters that look like other words, dialect-dependent numbers).
#include <catch2/catch.hpp>

#include "analyzer/rule.hpp"
#include "tests/analyzer/check_fixture.hpp"

using namespace kerf;
using Findings = std::vector<std::string>;

// K3006: reference/README.md "Example files" — the seeds print excerpts; a fragment is no program.
TEST_CASE("K3006 missing-program-end: programs yes, listing fragments no") {
    const std::string dialect = "fanuc-lathe-a";
    // A program: its O number (dialects.md §3.4) or a '%' tape file makes it one.
    CHECK(test::summary(test::check("O0001\nG00 X0.\n", dialect), "K3006") == Findings{"1:1 warning K3006"});
    CHECK(test::summary(test::check("%\nG00 X0.\nG01 Z-1. F0.2\n%\n", dialect), "K3006") == Findings{"2:1 warning K3006"});
    // A listing with '...' for left-out blocks (001_O001_M316.nc) is a fragment, O number or not.
    CHECK(test::summary(test::check("O0001\nG00 X0.\n...\nG01 Z-1. F0.2\n", dialect), "K3006").empty());
    CHECK(test::summary(test::check("O0001\nN10 G00 X0.\nN110.....\n", dialect), "K3006").empty());
    // No O number and no '%': an excerpt (001_11-5_slow_variant.nc, "fragment without O number").
    CHECK(test::summary(test::check("T0101\nG97 S3500 M4 F0.2\nG0 X0. Z2.\n", dialect), "K3006").empty());
}

// K1022: H D M T are whole-number addresses, unless a code of the block takes them as data.
TEST_CASE("K1022 point-on-integer-address: not on the data words of a cycle") {
    // 001_O0001_G384_G380_tapping.nc: G384 H20.0 (depth) D300. (return speed) M20. (brake).
    CHECK(test::summary(test::check("O0001\nG384 H20.0 F2.0 S300 D300. M20. T2\nG380\nM30\n", "spinner-lathe-a"), "K1022").empty());
    // The same letters outside a cycle still take whole numbers.
    CHECK(test::summary(test::check("O0001\nT0101\nM08.\nM30\n", "spinner-lathe-a"), "K1022") == Findings{"3:1 warning K1022"});
}

// K5008: the machine's axes with carries_tool = false (fanuc-lathe.toml B: tailstock / sub-spindle
// carriage) move no cutting tool, so a feed of B alone is no cut (cycles.md §12 G38, §16 G138).
TEST_CASE("K5008 cut-without-tool: not on feeds of the tailstock or transfer axis B") {
    // 001_O0001_G138_tailstock.nc, 001_O0001_G38_transfer.nc: cycles before any T word.
    CHECK(test::summary(test::check("O0001\nG138 B-425.8 Q1 S700 T300 J10 E1\nM30\n", "spinner-lathe-a"), "K5008").empty());
    CHECK(test::summary(test::check("O0001\nG38 B-410. F500 Q1.\nM30\n", "spinner-lathe-a"), "K5008").empty());
    CHECK(test::summary(test::check("O0001\nG01 B-100. F500\nM30\n", "spinner-lathe-a"), "K5008").empty());
    // A feed that moves X or Z (the turret) still cuts without a tool, with or without B.
    CHECK(test::summary(test::check("O0001\nG01 Z-10. F0.2\nM30\n", "spinner-lathe-a"), "K5008") == Findings{"2:1 warning K5008"});
    CHECK(test::summary(test::check("O0001\nG01 B-100. Z-10. F500\nM30\n", "spinner-lathe-a"), "K5008") == Findings{"2:1 warning K5008"});
}

// K4004 is the step limit only (kerf_alarm::step_limit): another alarm is not an endless loop.
TEST_CASE("K4004 endless-loop: only the step limit, not other alarms") {
    CHECK(test::summary(test::check("O0001\nN1 GOTO 1\nM30\n", "fanuc-lathe-a"), "K4004") == Findings{"2:1 error K4004"});
    const auto other = test::check("O0001\n#1=#[-5]\nM30\n", "fanuc-lathe-a");
    CHECK(test::summary(other, "K4004").empty());
    CHECK(test::summary(other, "K4099") == Findings{"2:1 error K4099"});
}

TEST_CASE("K5018 tool-without-offset: not on the T word of G138 (thrust limit)") {
    // 001_O0001_G138_tailstock.nc: G138 B-425.8 Q1 S700 T300 J10 E1.
    CHECK(test::summary(test::check("O0001\nG138 B-425.8 Q1 S700 T300 J10 E1\nM30\n", "spinner-lathe-a"), "K5018").empty());
    CHECK(test::summary(test::check("O0001\nT300\nM30\n", "spinner-lathe-a"), "K5018") == Findings{"2:1 warning K5018"});
}

// K1020 reads the dialect's decimal mode (dialects.md §2 Numbers, §11.9).
TEST_CASE("K1020 missing-decimal-point: by the dialect's decimal mode, and K of G28 K F is no arc word") {
    const char* text = "O0001\nG01 X10 Z-5 F100.\nM30\n";
    CHECK(test::summary(test::check(text, "fanuc-lathe-a"), "K1020") == Findings{"2:5 warning K1020", "2:9 warning K1020"});
    // SPINNER and ADV400 read integers as millimetres (calculator-type input).
    CHECK(test::summary(test::check(text, "spinner-lathe-a"), "K1020").empty());
    CHECK(test::summary(test::check(text, "adv400-lathe"), "K1020").empty());
    // 004_ex6_G28_corner_slowdown.nc: G28 K5 F50 under a modal G02 — K is the slow-down distance.
    const char* corner = "G17 G90 G02 X10. Y0. R5. F100.\nG28 K5 F50\nG29\nM02\n";
    CHECK(test::summary(test::check(corner, "iso-legacy-mill"), "K1020").empty());
    CHECK(test::summary(test::check("G17 G90 G02 X10. Y0. R5 F100.\nM02\n", "iso-legacy-mill"), "K1020") == Findings{"1:22 warning K1020"});
}

// corpus MechatronicsCherepanovMA__CNCLearn__1002.NC:37 (MANIFEST: "T0000 (no offset)").
TEST_CASE("K5018 tool-without-offset: T0000 in the mmnn form, not the short T0 cancel") {
    CHECK(test::summary(test::check("O0001\nT0000(THREAD)\nG32 Z-10. F1.\nM30\n", "fanuc-lathe-a"), "K5018") == Findings{"2:1 warning K5018"});
    CHECK(test::summary(test::check("O0001\nT0101\nG01 Z-10. F0.2\nG28 U0. W0. T0\nM30\n", "fanuc-lathe-a"), "K5018").empty());
}

// The label table behind K3001/K3002 (analyzer/rule.hpp): counts by integer label, the blocks of a
// label exactly (N10.5 is not label 10), in block order even when the numbers are not ascending, and
// kept true across an edit that replaces and moves blocks (the server's incremental check).
TEST_CASE("label table: count, blocks in block order, splice after an edit") {
    using E = analyzer::LabelTable::Entry;
    analyzer::LabelTable t({E{20.0, 1}, E{10.0, 2}, E{10.5, 3}, E{30.0, 4}, E{10.0, 7}, E{20.0, 9}});
    CHECK(t.count(10) == 3);   // N10.5 counts as label 10, as before
    CHECK(t.blocks(10) == std::vector<std::uint32_t>{2, 7});
    CHECK(t.blocks(20) == std::vector<std::uint32_t>{1, 9});
    CHECK(t.count(40) == 0);
    CHECK(t.blocks(40).empty());
    // Blocks 3 and 4 replaced by three new ones: the later blocks move by one.
    t.splice(3, 5, 1);
    CHECK(t.count(10) == 2);
    CHECK(t.count(30) == 0);
    CHECK(t.blocks(10) == std::vector<std::uint32_t>{2, 8});
    CHECK(t.blocks(20) == std::vector<std::uint32_t>{1, 10});
    // Two blocks inserted before block 2, none removed.
    t.splice(2, 2, 2);
    CHECK(t.blocks(10) == std::vector<std::uint32_t>{4, 10});
    CHECK(t.blocks(20) == std::vector<std::uint32_t>{1, 12});
}

// Issue 15: the corpus' false positives, fixed at the root.
TEST_CASE("K2001 unknown-code is for G codes; an unlisted M code is K2010 once per file") {
    const auto c = test::check("O0001\nM25 G49\nM25\nM165 P9810\nG384 X10.\nM30\n", "fanuc-mill");
    CHECK(test::summary(c, "K2001") == Findings{"5:1 error K2001"});
    CHECK(test::summary(c, "K2010") == Findings{"2:1 info K2010"});
    REQUIRE(c.report.findings.size() > 0);
    for (const analyzer::Finding& f : c.findings)
        if (f.rule == "K2010") CHECK(f.message == "M25, M165 are not in the table of fanuc-mill: the machine builder's M codes?");
}

TEST_CASE("K2004 required-word-missing: M98 Q alone is a local call (FANUC), not a missing P") {
    const std::string text = "O0001\nM98 Q100\nM30\nN100 G00 X0. Y0.\nM99\n";
    CHECK(test::summary(test::check(text, "fanuc-mill"), "K2004").empty());
    CHECK(test::summary(test::check("O0001\nM98 L2\nM30\n", "fanuc-mill"), "K2004") == Findings{"2:1 error K2004"});
}

TEST_CASE("K1022 point-on-integer-address: not on the arguments of a macro call by M code or G65") {
    // Doosan O1000: M165 calls the probe macro O9814 (a builder's M code); D1.415 is its argument.
    CHECK(test::summary(test::check("O0001\nM165 P9814 D1.415 S1.\nM30\n", "fanuc-mill"), "K1022").empty());
    CHECK(test::summary(test::check("O0001\nG65 P9814 D1.415 T2.\nM30\n", "fanuc-mill"), "K1022").empty());
    // A listed M code's block keeps the rule: M08. is still a point on M.
    CHECK(test::summary(test::check("O0001\nM08.\nM30\n", "fanuc-mill"), "K1022") == Findings{"2:1 warning K1022"});
}

TEST_CASE("K4001 vacant-local-in-arithmetic: not on documented or passed G65 arguments") {
    // O09994: "( G65 P9994 A B C )" in the header names #1 #2 #3 its arguments.
    const std::string documented = "O9994 (MACRO)\n( G65 P9994 A B C )\nG01 X[#2*2] F100.\nM30\n";
    CHECK(test::summary(test::check(documented, "fanuc-mill"), "K4001").empty());
    // Without the documentation #2 is a vacant read.
    CHECK(test::summary(test::check("O9994 (MACRO)\nG01 X[#2*2] F100.\nM30\n", "fanuc-mill"), "K4001") == Findings{"2:7 warning K4001"});
    // A caller in the same file passes B: #2 is an argument.
    const std::string called = "O0001\nG65 P9994 B2.\nM30\nO9994\nG01 X[#2*2] F100.\nM30\n";
    CHECK(test::summary(test::check(called, "fanuc-mill"), "K4001").empty());
}

TEST_CASE("K4006 user-alarm: a macro's guard for a missing argument, with no caller, is not a finding") {
    // 9250-DynamicOffsetRotation: IF [#1 EQ #0] THEN #3000=1 (NEED ROTATION AXIS) run without a caller.
    const std::string guard = "O9250\nIF [#1 EQ #0] THEN #3000=1(NEED ROTATION AXIS)\nG01 X#1 F100.\nM99\n";
    CHECK(test::summary(test::check(guard, "fanuc-mill"), "K4006").empty());
    // The same alarm in a program that reads no argument is the program's own: reported.
    CHECK(test::summary(test::check("O0001\n#100=1\nIF [#100 EQ 1] THEN #3000=1(STOP)\nM30\n", "fanuc-mill"), "K4006") ==
          Findings{"3:1 warning K4006"});
    // With a caller in the file the guard speaks about a real call.
    const std::string called = "O0001\nG65 P9250 B1.\nM30\nO9250\nIF [#1 EQ #0] THEN #3000=1(NEED ROTATION AXIS)\nM99\n";
    CHECK(test::summary(test::check(called, "fanuc-mill"), "K4006") == Findings{"5:1 warning K4006"});
}

TEST_CASE("K5007 rapid-at-cut-depth: a boring bar's back-off and moves before the tool goes down are no cut") {
    // O0051: feed into the bore, then 'G00 Y-.025 (BACK OFF SIDE OF BORE)' (0.635 mm sideways).
    const std::string bore = "O0001\nG20\nT2 M06\nG00 X0. Y0. Z.5\nG01 Z-2.05 F5.\nG00 Y-.025\nG00 Z.625\nM30\n";
    CHECK(test::summary(test::check(bore, "fanuc-mill"), "K5007").empty());
    // 1006.nc N5895: G1 X4.3 Y2.5 at the tool-change height before the tool went down cuts nothing.
    const std::string above = "O0001\nT7 M06\nG01 X4.3 Y2.5 F650.\nG00 Z0.6\nG00 X1. Y1.\nM30\n";
    CHECK(test::summary(test::check(above, "fanuc-mill"), "K5007").empty());
}

TEST_CASE("K2006 and K5021 compare with the machine only when a machine file gives it") {
    const std::string text = "O0001\nG97 S9000 M03 M08\nM30\n";
    CHECK(test::summary(test::check(text, "fanuc-lathe-a"), "K2006").empty());
    CHECK(test::summary(test::check(text, "fanuc-lathe-a"), "K5021").empty());
    test::SoftLimit machine;
    machine.machine_given = true;
    const auto given = test::check(text, "fanuc-lathe-a", test::all_rules_on(), machine);
    CHECK(test::summary(given, "K2006") == Findings{"2:15 error K2006"});
    CHECK(test::summary(given, "K5021") == Findings{"2:5 warning K5021"});
}

TEST_CASE("K3002 ambiguous-label and K3011 duplicate-sequence-number in a dialect that searches forward (Haas)") {
    // O09985: GOTO4 jumps to the N4 after it on a Haas; both N4 are labels, neither rule fires.
    const std::string text = "O0001\n#1=1\nIF [#1 EQ 1] GOTO4\nN4 #2=1\nIF [#2 EQ 1] GOTO4\nN4 #3=1\nM30\n";
    CHECK(test::summary(test::check(text, "haas-mill"), "K3002").empty());
    CHECK(test::summary(test::check(text, "haas-mill"), "K3011").empty());
    // FANUC searches from the top (dialects.md §2): the second GOTO4 lands on the first N4.
    CHECK(test::summary(test::check(text, "fanuc-mill"), "K3002") == Findings{"3:1 warning K3002", "5:1 warning K3002"});
}

TEST_CASE("K3003 program-not-found: not for the programs the machine keeps resident") {
    analyzer::CheckOptions options = test::all_rules_on();
    options.resident = [](std::int64_t n) { return n >= 9000 && n <= 9999; };
    CHECK(test::summary(test::check("O0001\nG65 P9810 Z1.\nM98 P1234\nM30\n", "fanuc-mill", options), "K3003") ==
          Findings{"3:5 error K3003"});
    // The dry run skips the resident call with a message instead of alarm 078 (K4009).
    CHECK(test::summary(test::check("O0001\nG65 P9810 Z1.\nM30\n", "fanuc-mill", options), "K4009").empty());
}
