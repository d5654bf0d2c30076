// What real shop programs need of the dry run (issue 12, "Numbers and units", "Programs that loop",
// "Dry-run fidelity"): the smallest program that shows each rule, with the expected numbers worked
// out by hand in the comments.
#include <cmath>

#include "dialects/alarms.hpp"
#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf;
using namespace kerf::test;


namespace {

std::vector<Event> alarms_of(const Run& r) { return of_kind(r, EventKind::alarm); }

// A fanuc-mill bare setup with IS-B integer input (calculator-type input off).
// A control of dialect `id` reading integers as least input increments (IS-B, calculator input off).
Setup is_b(const char* id) {
    Setup s = bare_setup(dialect(id));
    s.calculator_decimal = false;
    return s;
}

Setup mill_is_b() { return is_b("fanuc-mill"); }

}  // namespace

TEST_CASE("G20: an integer word counts 0.0001 inch on IS-B, 0.00001 on IS-C, not 0.001", "[units]") {
    const auto& d = dialect("fanuc-mill");
    // [FANUC] least input increment, IS-B: 0.001 mm, 0.0001 in. X15 → 0.0015 in = 0.0381 mm.
    Run r = run_with("O1\nG20 G90 G0 X15 Y-15\nM30\n", d, mill_is_b());
    REQUIRE(moves(r).size() == 1);
    CHECK(moves(r)[0].end[X] == Approx(0.0015));
    CHECK(moves(r)[0].end[Y] == Approx(-0.0015));
    CHECK(moves(r)[0].machine_end[X] == Approx(0.0381));
    CHECK(moves(r)[0].inch);
    Setup c = mill_is_b();
    c.increment_mm = 0.0001;   // IS-C: 0.00001 in
    r = run_with("O1\nG20 G90 G0 X15\nM30\n", d, c);
    CHECK(moves(r)[0].end[X] == Approx(0.00015));
    // G21: 0.001 mm as before.
    r = run_with("O1\nG21 G90 G0 X15\nM30\n", d, mill_is_b());
    CHECK(moves(r)[0].end[X] == Approx(0.015));
    CHECK_FALSE(moves(r)[0].inch);
}

TEST_CASE("G76 P/Q in G20 count 0.0001 inch (Doosan O0201)", "[units]") {
    // O0201: G76 P040000 Q30 R30 / G76 X1.911 Z-.5 P645 Q180 F.1 from X2.04 Z.05.
    // Height k = 0.0645 in (radius), first depth Δd = 0.0180 in: the thread crest X = 1.911 + 2k
    // = 2.040, the first pass at 2.040 − 2·0.018 = 2.004 (cycles.md §7; 10x the unit gave 2.841).
    const auto& d = dialect("fanuc-lathe-a");
    const Setup s = is_b("fanuc-lathe-a");
    const Run r = run_with("O1\nG20 G99\nT0101\nG97 S600 M03\nG0 X2.04 Z.05\nG76 P040000 Q30 R30\n"
                           "G76 X1.911 Z-.5 P645 Q180 F.1\nM30\n",
                           d, s);
    CHECK(alarms_of(r).empty());
    const std::vector<Event> threads = of_kind(r, EventKind::thread);
    REQUIRE_FALSE(threads.empty());
    CHECK(threads.front().end[X] == Approx(2.004).margin(1e-6));
    CHECK(threads.back().end[X] == Approx(1.911).margin(1e-6));
}

TEST_CASE("a rotary axis counts degrees: C360000 is 360°, also under G20", "[units]") {
    const auto& d = dialect("fanuc-lathe-a");
    const Setup s = is_b("fanuc-lathe-a");
    for (const char* units : {"G21", "G20"}) {
        INFO(units);
        const Run r = run_with(std::string("O1\n") + units + " G98\nG0 C360000\nM30\n", d, s);
        REQUIRE(moves(r).size() == 1);
        CHECK(moves(r)[0].end[5] == Approx(360.0));
        CHECK(moves(r)[0].machine_end[5] == Approx(360.0));   // degrees are not scaled by 25.4
    }
}

TEST_CASE("a macro value in an address is rounded to the address's increment", "[units][macro]") {
    // [FANUC] custom macro: #1 = 1.2345 then X-#1 moves 1.235 (IS-B mm), X[1/3] is X0.333.
    Run r = run_bare("O1\n#1=1.2345\nG91 G0 X-#1\nG90 G0 Y[1/3]\nM30\n");
    REQUIRE(moves(r).size() == 2);
    CHECK(moves(r)[0].end[X] == Approx(-1.235).margin(1e-12));
    CHECK(moves(r)[1].end[Y] == Approx(0.333).margin(1e-12));
    // Inches: 0.0001 in (1.23456 → 1.2346).
    r = run_bare("O1\nG20\n#1=1.23456\nG90 G0 X#1\nM30\n");
    CHECK(moves(r)[0].end[X] == Approx(1.2346).margin(1e-12));
}

TEST_CASE("G52 and G50/G92 under G20 shift in inches", "[units]") {
    // semantics.md §2.4: the vector is in the program's unit. G52 X1. Y2. in G20 → 25.4, 50.8 mm.
    Run r = run_bare("O1\nG20\nG52 X1. Y2.\nG90 G0 X0 Y0\nM30\n");
    REQUIRE(moves(r).size() == 1);
    CHECK(moves(r)[0].machine_end[X] == Approx(25.4));
    CHECK(moves(r)[0].machine_end[Y] == Approx(50.8));
    // G92 X1.: the current point (machine 0) becomes X1 in: G0 X0 goes 1 in = 25.4 mm to the minus side.
    r = run_bare("O1\nG20\nG92 X1. Y0\nG90 G0 X0\nM30\n");
    CHECK(moves(r)[0].machine_end[X] == Approx(-25.4));
}

TEST_CASE("G10 and #5221 under G20 write and read inches; the register keeps mm", "[units]") {
    const Run r = run_bare("O1\nG20\nG10 L2 P1 X1. Y0 Z0\nG54 G90 G0 X0 Y0\n#100=#5221\nG0 X#100\nM30\n");
    REQUIRE(moves(r).size() == 2);
    CHECK(moves(r)[0].machine_end[X] == Approx(25.4));   // G54 X zero at machine 25.4 mm
    CHECK(moves(r)[1].end[X] == Approx(1.0));            // #5221 reads 1 (inch), X1. from there
    CHECK(moves(r)[1].machine_end[X] == Approx(50.8));
}

TEST_CASE("drilling switches are mm whatever the program's unit", "[units][cycles]") {
    // machine/SCHEMA.md: peck_clearance (G83 re-approach) 0.5 mm and high_speed_retract (G73) 0.1 mm.
    // In G20 they are 0.5/25.4 = 0.019685 in and 0.1/25.4 = 0.003937 in (differential A1).
    Setup s = bare_setup(dialect("fanuc-mill"));
    s.cycles.peck_clearance = 0.5;
    s.cycles.high_speed_retract = 0.1;
    const Run g83 = run_with("O1\nG20 G90 G0 X0 Y0 Z1.\nG99 G83 Z-0.5 R0.1 Q0.2 F10.\nG80\nM30\n", dialect("fanuc-mill"), s);
    // Pecks: feed 0.1 → −0.1, rapid up to R, rapid down to −0.1 + 0.019685, feed to −0.3 ...
    bool reapproach = false;
    for (const Event& e : moves(g83))
        if (e.kind == EventKind::rapid && std::fabs(e.end[Z] - (-0.1 + 0.5 / 25.4)) < 1e-9) reapproach = true;
    CHECK(reapproach);
    const Run g73 = run_with("O1\nG20 G90 G0 X0 Y0 Z1.\nG99 G73 Z-0.5 R0.1 Q0.2 F10.\nG80\nM30\n", dialect("fanuc-mill"), s);
    bool retract = false;
    for (const Event& e : moves(g73))
        if (e.kind == EventKind::rapid && std::fabs(e.end[Z] - (-0.1 + 0.1 / 25.4)) < 1e-9) retract = true;
    CHECK(retract);
}

TEST_CASE("G81 P does not dwell: FANUC's G81 has no dwell word", "[cycles]") {
    const Run r = run_bare("O1\nG90 G0 X0 Y0 Z5.\nG99 G81 Z-1. R1. P500 F100.\nX10.\nG80\nM30\n");
    CHECK(count(r, EventKind::dwell) == 0);
    const Run g82 = run_bare("O1\nG90 G0 X0 Y0 Z5.\nG99 G82 Z-1. R1. P500 F100.\nX10.\nG80\nM30\n");
    CHECK(count(g82, EventKind::dwell) == 2);   // one per hole
}

TEST_CASE("M99 at the end of a main program: one pass, then a note", "[loops]") {
    const std::string text = "O1\nG90 G0 X10. Y0\nG0 X20.\nM99\n";
    Run r = run_bare(text);
    CHECK(r.result.completed);
    CHECK(r.result.repeats);
    CHECK(r.result.passes == 1);
    CHECK(moves(r).size() == 2);
    CHECK(alarms_of(r).empty());
    bool noted = false;
    for (const Event& e : of_kind(r, EventKind::message))
        noted |= e.code == interpreter::kerf_warning::program_repeats && e.source.line == 4;
    CHECK(noted);
    interpreter::RunOptions three;
    three.passes = 3;
    r = run_with(text, dialect("fanuc-mill"), bare_setup(dialect("fanuc-mill")), three);
    CHECK(r.result.passes == 3);
    CHECK(moves(r).size() == 6);   // X10 and X20 in each of the three passes
    // M99 P: the pass goes on at N20.
    r = run_with("O1\nN10 G90 G0 X10. Y0\nN20 G0 X20.\nG0 X30.\nM99 P20\n", dialect("fanuc-mill"),
                 bare_setup(dialect("fanuc-mill")), three);
    CHECK(moves(r).size() == 3 + 2 + 2);
}

TEST_CASE("preset variables are set before the first block", "[loops][macro]") {
    interpreter::RunOptions options;
    options.preset = {{100, 5.0}, {500, -2.5}};
    const Run r = run_with("O1\nG90 G0 X#100 Y#500\nM30\n", dialect("fanuc-mill"), bare_setup(dialect("fanuc-mill")), options);
    REQUIRE(moves(r).size() == 1);
    CHECK(moves(r)[0].end[X] == Approx(5.0));
    CHECK(moves(r)[0].end[Y] == Approx(-2.5));
}

TEST_CASE("a feed move without F raises alarm 011 in the dry run", "[alarms]") {
    const Run r = run_bare("O1\nG90 G0 X0 Y0\nG01 X10.\nM30\n");
    REQUIRE(alarms_of(r).size() == 1);
    CHECK(alarms_of(r)[0].code == alarms::feed_zero);
    CHECK(alarms_of(r)[0].source.line == 3);
    CHECK_FALSE(r.result.completed);
    // F0 is no feed either; G00 needs none; an arc does.
    CHECK(alarms_of(run_bare("O1\nG01 X10. F0\nM30\n")).size() == 1);
    CHECK(alarms_of(run_bare("O1\nG00 X10.\nM30\n")).empty());
    CHECK(alarms_of(run_bare("O1\nG02 X10. Y0 R5.\nM30\n")).size() == 1);
}

TEST_CASE("a profile block that breaks monotony is where alarm 064 stands", "[alarms][cycles]") {
    // N25's `Z-8` without a point is 0.008 mm: the profile runs back up in Z (−20 → −0.008),
    // so the type I profile is not monotonic; the alarm is at N25 (line 8), not at the G71 line.
    const auto& d = dialect("fanuc-lathe-a");
    const Setup s = is_b("fanuc-lathe-a");
    const Run r = run_with("O1\nG99 T0101 S500 M03\nG0 X50. Z2.\nG71 U1. R0.5\nG71 P10 Q30 U0.2 W0.1 F0.2\n"
                           "N10 G0 X20.\nN20 G1 Z-20. F0.1\nN25 Z-8\nN30 X50.\nM30\n",
                           d, s);
    REQUIRE(alarms_of(r).size() == 1);
    CHECK(alarms_of(r)[0].code == alarms::profile_not_monotonic);
    CHECK(alarms_of(r)[0].source.line == 8);
}

TEST_CASE("G54.1 P and G10 L20: the additional work offsets", "[coordinates]") {
    const Run r = run_bare("O1\nG10 L20 P2 X100. Y50. Z0\nG54.1 P2 G90 G0 X0 Y0\n#100=#7021\n#101=#14022\nG0 X#100 Y#101\nG54 G0 X0 Y0\nM30\n");
    REQUIRE(moves(r).size() == 3);
    CHECK(moves(r)[0].machine_end[X] == Approx(100.0));
    CHECK(moves(r)[0].machine_end[Y] == Approx(50.0));
    CHECK(moves(r)[1].end[X] == Approx(100.0));   // #7021: P2 X; #14022: P2 Y
    CHECK(moves(r)[1].end[Y] == Approx(50.0));
    CHECK(moves(r)[2].machine_end[X] == Approx(0.0));   // back on G54 (zero in the bare setup)
    // P outside the machine's 48: alarm 030 at that block.
    const Run bad = run_bare("O1\nG54.1 P49\nM30\n");
    REQUIRE(alarms_of(bad).size() == 1);
    CHECK(alarms_of(bad)[0].code == alarms::offset_number);
    // A tool offset number past the machine's count is an alarm where it is written.
    const Run g10 = run_bare("O1\nG10 L10 P299 R5.\nM30\n", "fanuc-mill", [](Setup& s) { s.tool_offset_count = 64; });
    REQUIRE(alarms_of(g10).size() == 1);
    CHECK(alarms_of(g10)[0].code == alarms::offset_number);
    CHECK(alarms_of(g10)[0].source.line == 2);
}

TEST_CASE("G45–G48 act only in their block: a G91 block after them moves from the tool", "[offsets]") {
    // semantics.md §9.3: G46 with D = 10 shortens X90 Y55 to X80 Y45 (the tool), programmed (90, 55).
    // The next G91 X10. moves the tool by +10 in X only: (90, 45), not to the programmed (100, 55).
    const Run r = run_bare("O1\nG90 G46 G0 X90. Y55. D08\nG91 G0 X10.\nM30\n", "iso-legacy-mill",
                           [](Setup& s) { s.tools[8].radius = 10; });
    REQUIRE(moves(r).size() == 2);
    CHECK(moves(r)[0].end[X] == Approx(80.0));
    CHECK(moves(r)[0].end[Y] == Approx(45.0));
    CHECK(moves(r)[1].end[X] == Approx(90.0));
    CHECK(moves(r)[1].end[Y] == Approx(45.0));
}

TEST_CASE("the machine's power-on switches decide the start modes", "[power-on]") {
    // A6: an inch machine without G20 in the program reads X1. as 1 inch.
    Setup s = bare_setup(dialect("fanuc-mill"));
    s.power_on = {dialects::functions::inch_input, dialects::functions::incremental_programming};
    const Run r = run_with("O1\nG0 X1.\nX1.\nM30\n", dialect("fanuc-mill"), s);
    REQUIRE(moves(r).size() == 2);
    CHECK(moves(r)[1].end[X] == Approx(2.0));   // G91 at power-on: 1 + 1
    CHECK(moves(r)[1].machine_end[X] == Approx(50.8));
}

TEST_CASE("a move takes up a length offset: its length is the machine's travel", "[length]") {
    // A7: G43 Z15. H1 at Z15 with H1 = 50.8: the work Z stays, machine Z moves 50.8 mm.
    const Run r = run_bare("O1\nG90 G0 Z15.\nG43 Z15. H1\nM30\n", "fanuc-mill", [](Setup& s) {
        s.tools[1].length = 50.8;
        s.rapid_mm_min = {10000, 10000, 10000, 0, 0, 0};
    });
    REQUIRE(moves(r).size() == 2);
    CHECK(moves(r)[1].length_mm == Approx(50.8));
    CHECK(moves(r)[1].time_s > 0);
    // With the axis-movement reading, `G43 H1` alone moves Z at once.
    const Run at_once = run_bare("O1\nG90 G0 Z15.\nG43 H1\nM30\n", "fanuc-mill", [](Setup& s) {
        s.tools[1].length = 50.8;
        s.length_offset_at_once = true;
    });
    REQUIRE(moves(at_once).size() == 2);
    CHECK(moves(at_once)[1].machine_end[Z] == Approx(15.0 + 50.8));
    CHECK(moves(at_once)[1].length_mm == Approx(50.8));
    const Run later = run_bare("O1\nG90 G0 Z15.\nG43 H1\nM30\n", "fanuc-mill", [](Setup& s) { s.tools[1].length = 50.8; });
    CHECK(moves(later).size() == 1);
}

TEST_CASE("M codes act in the order of semantics.md §1.2: M03 before the block's cut, M05 after", "[order]") {
    const Run r = run("O1\nT0101\nG0 X20. Z2.\nG99 G01 Z-5. F0.2 S800 M03\nG01 Z-10. M05\nM30\n", "fanuc-lathe-a");
    const std::vector<Event>& e = r.events;
    std::size_t start = e.size(), cut = e.size(), stop = e.size(), second = e.size();
    for (std::size_t i = 0; i < e.size(); ++i) {
        if (e[i].kind == EventKind::spindle && e[i].spindle_running && start == e.size()) start = i;
        if (e[i].kind == EventKind::linear && e[i].source.line == 4) cut = i;
        if (e[i].kind == EventKind::linear && e[i].source.line == 5) second = i;
        if (e[i].kind == EventKind::spindle && !e[i].spindle_running) stop = i;
    }
    REQUIRE(cut < e.size());
    CHECK(start < cut);
    CHECK(e[cut].spindle_running);
    CHECK(e[second].spindle_running);   // M05 acts after the block's move
    CHECK(second < stop);
}

TEST_CASE("work_shift_sign and g68_positive are the machine's", "[switches]") {
    // semantics.md §2.6: machine = program + offset − shift (FANUC) or + shift.
    const auto& d = dialect("fanuc-lathe-a");
    Setup s = bare_setup(d);
    s.work_shift = {0, 0, 10, 0, 0, 0};
    Run r = run_with("O1\nG0 X0 Z0\nM30\n", d, s);
    CHECK(moves(r)[0].machine_end[Z] == Approx(-10.0));
    s.work_shift_sign = 1;
    r = run_with("O1\nG0 X0 Z0\nM30\n", d, s);
    CHECK(moves(r)[0].machine_end[Z] == Approx(10.0));
    // ADV400's table says + is clockwise; a machine that says ccw wins (semantics.md §12.4).
    const auto& adv = dialect("adv400-mill");
    Setup a = plain_setup(adv);
    a.g68_positive_cw = false;
    r = run_with("O1\nG90 G0 X0 Y0\nG68 X0 Y0 R90.\nG0 X10. Y0\nM30\n", adv, a);
    CHECK(moves(r).back().end[X] == Approx(0.0).margin(1e-9));
    CHECK(moves(r).back().end[Y] == Approx(10.0));   // counter-clockwise by 90°
}
