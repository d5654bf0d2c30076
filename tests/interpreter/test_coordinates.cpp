// Coordinate systems through the interpreter (reference/semantics.md §2): G54–G59 with offsets
// from the Setup, machine positions of events, G10 P0 work shift (§2.6 with its worked example),
// G50/G92 setting and its cancel (§2.5), G52 in its FANUC and current-point readings and G152
// (§2.4), G53 (§2.2), G28 (§2.8), incremental words per G-code system (dialects.md §3.2, §4) and
// lathe diameter X lengths (§3.3).
//
// Every Setup here is built by hand (no machine file): work offsets, external offset and reference
// points are zero unless the test sets them, so machine = program value + the offsets the test
// names. Every expected number is derived by hand in the comment next to it; lathe X values are
// diameters everywhere (machine X too, semantics.md §2.7 "X values in diameter throughout").
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf;
using namespace kerf::test;

// Every Setup is plain_setup (tests/interpreter/interpreter_fixture.hpp) plus what the test names.
// The moves read back here have always included thread cuts (moves_with_threads).

// --- G54–G59 ------------------------------------------------------------------------------------

// Offsets (machine coordinates of each zero), G5(4+i): X = 100·(i+1), Y = 10·(i+1), Z = −(i+1).
// Every block moves to work (1, 2, 3), so machine = (1 + 100(i+1), 2 + 10(i+1), 3 − (i+1)):
//   G54 (101, 12, 2)  G55 (201, 22, 1)  G56 (301, 32, 0)
//   G57 (401, 42, −1) G58 (501, 52, −2) G59 (601, 62, −3)
// Selecting G55 while the tool stands at machine (101, 12, 2) does not move it: it then reads
// machine − G55 = (101 − 200, 12 − 20, 2 − (−2)) = (−99, −8, 4) (the start of the G55 move).
TEST_CASE("G54-G59 select the work offsets of the Setup; events carry machine positions", "[coordinates]") {
    const Run r = run("O1\nG54 G90 G0 X1. Y2. Z3.\nG55 X1. Y2. Z3.\nG56 X1. Y2. Z3.\nG57 X1. Y2. Z3.\n"
                      "G58 X1. Y2. Z3.\nG59 X1. Y2. Z3.\nM30\n",
                      "fanuc-mill", [](Setup& s) {
                          for (std::size_t i = 0; i < 6; ++i)
                              s.work_offsets[i] = {100.0 * (i + 1), 10.0 * (i + 1), -1.0 * (i + 1), 0, 0, 0};
                      });
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 6);
    for (std::size_t i = 0; i < 6; ++i) {
        INFO("G5" << 4 + i);
        CHECK(m[i].end[X] == Approx(1));
        CHECK(m[i].end[Y] == Approx(2));
        CHECK(m[i].end[Z] == Approx(3));
        CHECK(m[i].machine_end[X] == Approx(1 + 100.0 * (i + 1)));
        CHECK(m[i].machine_end[Y] == Approx(2 + 10.0 * (i + 1)));
        CHECK(m[i].machine_end[Z] == Approx(3 - 1.0 * (i + 1)));
    }
    CHECK(m[1].start[X] == Approx(-99));
    CHECK(m[1].start[Y] == Approx(-8));
    CHECK(m[1].start[Z] == Approx(4));
}

// G54 is active at power-on (semantics.md §2.3): G0 X0 Y0 Z0 without a G5x code goes to the G54
// zero, machine (100, 10, −1). The external offset (parameter 1220) adds to all six systems:
// G56 (300, 30, −3) + external (0.5, −0.5, 1) = machine (300.5, 29.5, −2) for work (0, 0, 0).
TEST_CASE("G54 at power-on; the external offset adds to every system", "[coordinates]") {
    auto offsets = [](Setup& s) {
        for (std::size_t i = 0; i < 6; ++i)
            s.work_offsets[i] = {100.0 * (i + 1), 10.0 * (i + 1), -1.0 * (i + 1), 0, 0, 0};
    };
    const Run r = run("O1\nG90 G0 X0. Y0. Z0.\nM30\n", "fanuc-mill", offsets);
    require_clean(r);
    REQUIRE(moves_with_threads(r).size() == 1);
    CHECK(moves_with_threads(r)[0].machine_end[X] == Approx(100));
    CHECK(moves_with_threads(r)[0].machine_end[Y] == Approx(10));
    CHECK(moves_with_threads(r)[0].machine_end[Z] == Approx(-1));

    const Run e = run("O1\nG56 G90 G0 X0. Y0. Z0.\nM30\n", "fanuc-mill", [&](Setup& s) {
        offsets(s);
        s.external_offset = {0.5, -0.5, 1, 0, 0, 0};
    });
    require_clean(e);
    REQUIRE(moves_with_threads(e).size() == 1);
    CHECK(moves_with_threads(e)[0].machine_end[X] == Approx(300.5));
    CHECK(moves_with_threads(e)[0].machine_end[Y] == Approx(29.5));
    CHECK(moves_with_threads(e)[0].machine_end[Z] == Approx(-2));
}

// Lathe, X diameter: G55 zero at machine X−40 (diameter) Z250. G55 G0 X50. Z10. → machine
// X = 50 + (−40) = 10, Z = 10 + 250 = 260; the event's work end stays X50 Z10.
TEST_CASE("lathe G55: offsets and positions in diameter", "[coordinates]") {
    const Run r = run("O1\nG55 G0 X50. Z10.\nM30\n", "fanuc-lathe-a",
                      [](Setup& s) { s.work_offsets[1] = {-40, 0, 250, 0, 0, 0}; });
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 1);
    CHECK(m[0].end[X] == Approx(50));
    CHECK(m[0].end[Z] == Approx(10));
    CHECK(m[0].machine_end[X] == Approx(10));
    CHECK(m[0].machine_end[Z] == Approx(260));
}

// --- G10 P0 work shift (semantics.md §2.6) ------------------------------------------------------

// machine = program − shift (offsets zero), so a G10 changes what the tool reads, not where it is:
//   G0 X100. Z100.       machine (100, 100), shift (0, 0)
//   G10 P0 X-2. Z-100.   X/Z replace: shift (−2, −100); reads (100 − 2, 100 − 100) = (98, 0)
//   G10 P0 U1. W10.      U/W add: shift (−1, −90); reads (99, 10)
//   G0 X10. Z0.          machine (10 + 1, 0 + 90) = (11, 90)
//   G10 P0 X4.           X replaced: shift (4, −90); the tool at machine X11 reads 11 + 4 = 15
//   G0 X10.              machine X = 10 − 4 = 6, Z stays 90
// Three moves: the G10 blocks do not move; each writes one coordinate_change event.
TEST_CASE("G10 P0: X/Z replace the shift, U/W add to it, at once and without motion", "[coordinates]") {
    const Run r = run("O1\nG0 X100. Z100.\nG10 P0 X-2. Z-100.\nG10 P0 U1. W10.\nG0 X10. Z0.\nG10 P0 X4.\nG0 X10.\nM30\n",
                      "fanuc-lathe-a");
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 3);
    CHECK(count(r, EventKind::coordinate_change) == 3);
    CHECK(m[0].machine_end[X] == Approx(100));
    CHECK(m[0].machine_end[Z] == Approx(100));
    CHECK(m[1].start[X] == Approx(99));
    CHECK(m[1].start[Z] == Approx(10));
    CHECK(m[1].machine_end[X] == Approx(11));
    CHECK(m[1].machine_end[Z] == Approx(90));
    CHECK(m[2].start[X] == Approx(15));
    CHECK(m[2].machine_end[X] == Approx(6));
    CHECK(m[2].machine_end[Z] == Approx(90));
    CHECK(r.result.final_position[X] == Approx(10));
    CHECK(r.result.final_position[Z] == Approx(0));
}

// The worked example of semantics.md §2.6 (seed 001 §7.8, O0001/O0002, written inline here):
// G10 P0 Z-130, then O0002 three times, each facing at program Z−10 and then adding W10.
// machine Z = −10 − shift with shift −130, −120, −110 → 120, 110, 100 mm in front of the chuck
// face; the register ends at −100, so the final G0 X150 Z150 is at machine Z 150 + 100 = 250.
// The facing cut G1 X-2 ends at machine X −2 (no X shift). SPINNER reads X30 as 30 mm.
TEST_CASE("G10 P0: the worked example of semantics.md §2.6", "[coordinates]") {
    const Run r = run("O0001\nN10 G10 P0 Z-130\nN20 M98 P30002\nN30 G0 X150 Z150\nN40 M30\n"
                      "O0002\nN50 G0 X30 Z-10\nN60 G98 G1 X-2 F100\nN70 G10 P0 W10\nN80 M99\n",
                      "spinner-lathe-a");
    require_clean(r);
    std::vector<Event> cuts;
    for (const Event& e : r.events)
        if (e.kind == EventKind::linear) cuts.push_back(e);
    REQUIRE(cuts.size() == 3);
    CHECK(cuts[0].machine_end[Z] == Approx(120));
    CHECK(cuts[1].machine_end[Z] == Approx(110));
    CHECK(cuts[2].machine_end[Z] == Approx(100));
    for (const Event& c : cuts) {
        CHECK(c.end[Z] == Approx(-10));   // the program always says Z−10
        CHECK(c.machine_end[X] == Approx(-2));
    }
    const auto m = moves_with_threads(r);
    REQUIRE_FALSE(m.empty());
    CHECK(m.back().end[X] == Approx(150));
    CHECK(m.back().end[Z] == Approx(150));
    CHECK(m.back().machine_end[Z] == Approx(250));
}

// --- G50 / G92 coordinate system setting (semantics.md §2.5) ------------------------------------

// Lathe A: G50 X Z gives the current point the programmed values, no motion:
//   G0 X100. Z50.     machine (100, 50)
//   G50 X0. Z0.       reads (0, 0): setting correction (100, 50)
//   G0 X20. Z-5.      machine (20 + 100, −5 + 50) = (120, 45)
//   G50.3 X0. Z0.     FANUC T (system A) workpiece coordinate system preset: the setting is undone
//                     on X and Z; the tool stays at machine (120, 45) and reads (120, 45); no motion
//   G0 X10.           machine X 10, Z 45
TEST_CASE("G50 X Z (lathe A) sets the current point; G50.3 cancels it", "[coordinates]") {
    const Run r = run("O1\nG0 X100. Z50.\nG50 X0. Z0.\nG0 X20. Z-5.\nG50.3 X0. Z0.\nG0 X10.\nM30\n", "fanuc-lathe-a");
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 3);   // G50 and G50.3 do not move
    CHECK(m[1].start[X] == Approx(0));
    CHECK(m[1].start[Z] == Approx(0));
    CHECK(m[1].machine_end[X] == Approx(120));
    CHECK(m[1].machine_end[Z] == Approx(45));
    CHECK(m[2].start[X] == Approx(120));
    CHECK(m[2].start[Z] == Approx(45));
    CHECK(m[2].machine_end[X] == Approx(10));
    CHECK(m[2].machine_end[Z] == Approx(45));
}

// The same with G92 / G92.1 in systems B and C (dialects.md §4 table) and on the FANUC mill
// (G92 X Y Z, G92.1); numbers as in the lathe A case (Y: machine 30 → G92 Y0 → G0 Y5. is machine
// 35; after G92.1 it reads 35).
TEST_CASE("G92 X Z (lathe B/C, mill) sets the current point; G92.1 cancels it", "[coordinates]") {
    for (const char* id : {"fanuc-lathe-b", "fanuc-lathe-c"}) {
        INFO(id);
        const Run r = run("O1\nG90 G0 X100. Z50.\nG92 X0. Z0.\nG0 X20. Z-5.\nG92.1 X0. Z0.\nG0 X10.\nM30\n", id);
        require_clean(r);
        const auto m = moves_with_threads(r);
        REQUIRE(m.size() == 3);
        CHECK(m[1].start[X] == Approx(0));
        CHECK(m[1].machine_end[X] == Approx(120));
        CHECK(m[1].machine_end[Z] == Approx(45));
        CHECK(m[2].start[X] == Approx(120));
        CHECK(m[2].start[Z] == Approx(45));
        CHECK(m[2].machine_end[X] == Approx(10));
    }
    const Run mill = run("O1\nG90 G0 X100. Y30. Z50.\nG92 X0. Y0. Z0.\nG0 X20. Y5. Z-5.\nG92.1 X0. Y0. Z0.\nG0 X10.\nM30\n",
                         "fanuc-mill");
    require_clean(mill);
    const auto m = moves_with_threads(mill);
    REQUIRE(m.size() == 3);
    CHECK(m[1].machine_end[X] == Approx(120));
    CHECK(m[1].machine_end[Y] == Approx(35));
    CHECK(m[1].machine_end[Z] == Approx(45));
    CHECK(m[2].start[X] == Approx(120));
    CHECK(m[2].start[Y] == Approx(35));
    CHECK(m[2].start[Z] == Approx(45));
    CHECK(m[2].machine_end[X] == Approx(10));
}

// [FANUC] G92.1 IP0 presets only the axes it names ("axes that are not specified are not subject
// to the preset"): after G92 X0 Y0 at machine (100, 30), G92.1 X0 restores X only:
//   the tool at machine (100, 30) reads X100 but still Y0.
TEST_CASE("G92.1 X0 presets only the named axis", "[coordinates]") {
    const Run r = run("O1\nG90 G0 X100. Y30.\nG92 X0. Y0.\nG92.1 X0.\nG0 Z1.\nM30\n", "fanuc-mill");
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 2);
    CHECK(m[1].start[X] == Approx(100));
    CHECK(m[1].start[Y] == Approx(0));
}

// ADV400 (semantics.md §2.5): mill G92 / G92.1 (bare), lathe G50 / G50.1 (bare).
//   mill:  G0 X100. Y30. → G92 X0. Y0. → G0 X20. is machine 120 → G92.1 → reads (120, 30)
//   lathe: G0 X100. Z50. → G50 X0. Z0. → G0 X20. is machine X120 → G50.1 → reads (120, 50)
TEST_CASE("ADV400: G92/G92.1 (mill) and G50/G50.1 (lathe)", "[coordinates]") {
    const Run mill = run("G90 G0 X100 Y30\nG92 X0 Y0\nG0 X20\nG92.1\nG0 Z1\nM30\n", "adv400-mill");
    require_clean(mill);
    const auto mm = moves_with_threads(mill);
    REQUIRE(mm.size() == 3);
    CHECK(mm[1].machine_end[X] == Approx(120));
    CHECK(mm[2].start[X] == Approx(120));
    CHECK(mm[2].start[Y] == Approx(30));
    const Run lathe = run("G90 G0 X100 Z50\nG50 X0 Z0\nG0 X20\nG50.1\nG0 Z1\nM30\n", "adv400-lathe");
    require_clean(lathe);
    const auto lm = moves_with_threads(lathe);
    REQUIRE(lm.size() == 3);
    CHECK(lm[1].machine_end[X] == Approx(120));
    CHECK(lm[2].start[X] == Approx(120));
    CHECK(lm[2].start[Z] == Approx(50));
}

// semantics.md §2.4 (FANUC row): G52 is "also cancelled by G50/G92".
//   G0 X0. Y0.     machine (0, 0)
//   G52 X10. Y5.   local origin at work (10, 5): the tool reads (−10, −5)
//   G92 X0. Y0.    the tool reads (0, 0); the local system is cancelled
//   G52 X0. Y0.    nothing left to cancel: still (0, 0)
//   G0 X1.         machine X 1 (program 0 = machine 0 since the G92)
TEST_CASE("FANUC G92 cancels the G52 local system", "[coordinates]") {
    const Run r = run("O1\nG90 G0 X0. Y0.\nG52 X10. Y5.\nG92 X0. Y0.\nG52 X0. Y0.\nG0 X1.\nM30\n", "fanuc-mill");
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 2);
    CHECK(m[1].start[X] == Approx(0));
    CHECK(m[1].start[Y] == Approx(0));
    CHECK(m[1].machine_end[X] == Approx(1));
    CHECK(m[1].machine_end[Y] == Approx(0));
}

// --- G52 (semantics.md §2.4) --------------------------------------------------------------------

// FANUC vector reading on a lathe (X diameter), G52 applies to every work system, X0 Z0 cancels;
// G55 zero at machine X−40 Z250 (diameter):
//   G0 X100. Z100.   machine (100, 100)
//   G52 X20. Z-10.   local origin = work origin + (20, −10): reads (100 − 20, 100 + 10) = (80, 110)
//   G0 X0. Z0.       machine (20, −10)
//   G55              reads machine − G55 − local = (20 + 40 − 20, −10 − 250 + 10) = (40, −250)
//   G0 X0. Z0.       machine = G55 + local = (−40 + 20, 250 − 10) = (−20, 240)
//   G52 X0. Z0.      cancel: reads machine − G55 = (−20 + 40, 240 − 250) = (20, −10)
//   G0 X0. Z0.       machine (−40, 250)
TEST_CASE("G52 FANUC: vector shift of every work system, no motion, X0 Z0 cancels", "[coordinates]") {
    const Run r = run("O1\nG0 X100. Z100.\nG52 X20. Z-10.\nG0 X0. Z0.\nG55\nG0 X0. Z0.\nG52 X0. Z0.\nG0 X0. Z0.\nM30\n",
                      "fanuc-lathe-a", [](Setup& s) { s.work_offsets[1] = {-40, 0, 250, 0, 0, 0}; });
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 4);   // G52 and G55 alone do not move
    CHECK(m[1].start[X] == Approx(80));
    CHECK(m[1].start[Z] == Approx(110));
    CHECK(m[1].machine_end[X] == Approx(20));
    CHECK(m[1].machine_end[Z] == Approx(-10));
    CHECK(m[2].start[X] == Approx(40));
    CHECK(m[2].start[Z] == Approx(-250));
    CHECK(m[2].machine_end[X] == Approx(-20));
    CHECK(m[2].machine_end[Z] == Approx(240));
    CHECK(m[3].start[X] == Approx(20));
    CHECK(m[3].start[Z] == Approx(-10));
    CHECK(m[3].machine_end[X] == Approx(-40));
    CHECK(m[3].machine_end[Z] == Approx(250));
}

// pcnc-mill, the reference's example 2: "X20Y20Z20 then G52 X5 Y5 → tool reads X5 Y5 Z20"
// (omitted axes are not shifted); selecting G54–G59 cancels G52 (G55 = G54 = zero here):
//   G0 X20 Y20 Z20   machine (20, 20, 20)
//   G52 X5 Y5        L = (15, 15, 0): reads (5, 5, 20)
//   G0 Z30           machine (20, 20, 30)
//   G55              G52 cancelled: reads (20, 20, 30)
//   G0 X0            machine X 0
TEST_CASE("G52 pcnc-mill: current point takes the values, omitted axes keep theirs, G55 cancels", "[coordinates]") {
    const Run r = run("G90 G0 X20 Y20 Z20\nG52 X5 Y5 ; local system\nG0 Z30\nG55\nG0 X0\nM2\n", "pcnc-mill");
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].start[X] == Approx(5));
    CHECK(m[1].start[Y] == Approx(5));
    CHECK(m[1].start[Z] == Approx(20));
    CHECK(m[1].machine_end[X] == Approx(20));
    CHECK(m[1].machine_end[Y] == Approx(20));
    CHECK(m[1].machine_end[Z] == Approx(30));
    CHECK(m[2].start[X] == Approx(20));
    CHECK(m[2].start[Y] == Approx(20));
    CHECK(m[2].start[Z] == Approx(30));
    CHECK(m[2].machine_end[X] == Approx(0));
}

// pcnc-mill: "a new G52 redefines the local system relative to the work system"; only G152 (or
// G54–G59) cancels, so G52 X0 Y0 is an ordinary redefinition: the tool at work (20, 20) reads (0, 0)
// (L = (20, 20)). G152 then restores the work system: the tool reads (20, 20) again.
TEST_CASE("G52 pcnc-mill: G52 X0 Y0 makes the tool read zero; G152 cancels", "[coordinates]") {
    const Run r = run("G90 G0 X20 Y20\nG52 X5 Y5\nG52 X0 Y0\nG0 Z1\nG152\nG0 Z2\nM2\n", "pcnc-mill");
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].start[X] == Approx(0));
    CHECK(m[1].start[Y] == Approx(0));
    CHECK(m[2].start[X] == Approx(20));
    CHECK(m[2].start[Y] == Approx(20));
}

// ADV400 (semantics.md §2.4): the pcnc reading, cancelled by G52 with zero values:
//   G0 X200 Y160     machine (200, 160)
//   G52 X100 Y100    A = (100, 60): reads (100, 100)
//   G0 X20           machine X 120
//   G52 X0 Y0        cancel: reads (120, 160)
//   G0 Y0            machine Y 0
TEST_CASE("G52 ADV400: current point takes the values; zeros cancel", "[coordinates]") {
    const Run r = run("G90 G0 X200 Y160\nG52 X100 Y100\nG0 X20\nG52 X0 Y0\nG0 Y0\nM30\n", "adv400-mill");
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].start[X] == Approx(100));
    CHECK(m[1].start[Y] == Approx(100));
    CHECK(m[1].machine_end[X] == Approx(120));
    CHECK(m[2].start[X] == Approx(120));
    CHECK(m[2].start[Y] == Approx(160));
    CHECK(m[2].machine_end[Y] == Approx(0));
}

// --- G53 (semantics.md §2.2) ---------------------------------------------------------------------

// FANUC mill, G54 zero at machine (−500, −300, −500):
//   G0 X10. Y10. Z10.   machine (−490, −290, −490)
//   G53 X-100. Y-50.    rapid to machine X−100 Y−50, Z unchanged (−490): work (400, 250, 10)
//   X0.                 G53 was one-shot and G00 is still modal: machine X −500, work start X400
TEST_CASE("G53: one-shot rapid in machine coordinates", "[coordinates]") {
    const Run r = run("O1\nG90 G0 X10. Y10. Z10.\nG53 X-100. Y-50.\nX0.\nM30\n", "fanuc-mill",
                      [](Setup& s) { s.work_offsets[0] = {-500, -300, -500, 0, 0, 0}; });
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].kind == EventKind::rapid);
    CHECK(m[1].machine_end[X] == Approx(-100));
    CHECK(m[1].machine_end[Y] == Approx(-50));
    CHECK(m[1].machine_end[Z] == Approx(-490));
    CHECK(m[1].end[X] == Approx(400));
    CHECK(m[1].end[Y] == Approx(250));
    CHECK(m[1].end[Z] == Approx(10));
    CHECK(m[2].start[X] == Approx(400));
    CHECK(m[2].machine_end[X] == Approx(-500));
}

// [FANUC] G53 ignores the local system too and is a rapid even under G01, which stays modal:
// G54 zero (−500, 0, 0), G52 X5.: G53 X-100. goes to machine X−100 (work = −100 + 500 − 5 = 395);
// the next block X0. is a G01 move to machine −500 + 5 = −495.
TEST_CASE("G53 ignores G52 and is a rapid under G01", "[coordinates]") {
    const Run r = run("O1\nG90 G1 X0. F1000.\nG52 X5.\nG53 X-100.\nX0.\nM30\n", "fanuc-mill",
                      [](Setup& s) { s.work_offsets[0] = {-500, 0, 0, 0, 0, 0}; });
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].kind == EventKind::rapid);
    CHECK(m[1].machine_end[X] == Approx(-100));
    CHECK(m[1].end[X] == Approx(395));
    CHECK(m[2].kind == EventKind::linear);
    CHECK(m[2].machine_end[X] == Approx(-495));
}

// Lathe G53 X Z in diameter: G54 zero at machine X10 Z20; G53 X200. Z300. → machine (200, 300),
// work (190, 280).
TEST_CASE("lathe G53 with diameter X", "[coordinates]") {
    const Run r = run("O1\nG53 X200. Z300.\nM30\n", "fanuc-lathe-a",
                      [](Setup& s) { s.work_offsets[0] = {10, 0, 20, 0, 0, 0}; });
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 1);
    CHECK(m[0].machine_end[X] == Approx(200));
    CHECK(m[0].machine_end[Z] == Approx(300));
    CHECK(m[0].end[X] == Approx(190));
    CHECK(m[0].end[Z] == Approx(280));
}

// pcnc-mill (semantics.md §2.2): "only G00 or G01 may be used; the speed follows the active G0/G1,
// and with G1 a feed may be given in the block". G54 zero at machine (100, 50):
//   G54 G1 X0 Y0 F600     machine (100, 50)
//   G53 X60               a G01 move to machine X60: 40 mm at 600 mm/min = 4 s; work X −40
//   X20                   back in G54: machine X 120
TEST_CASE("G53 pcnc-mill follows the active G01 and its feed", "[coordinates]") {
    const Run r = run("G54 G90 G1 X0 Y0 F600\nG53 X60\nX20\nM2\n", "pcnc-mill",
                      [](Setup& s) { s.work_offsets[0] = {100, 50, 0, 0, 0, 0}; });
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].kind == EventKind::linear);
    CHECK(m[1].machine_end[X] == Approx(60));
    CHECK(m[1].end[X] == Approx(-40));
    CHECK(m[1].time_s == Approx(4.0));
    CHECK(m[2].machine_end[X] == Approx(120));
}

// --- G28 (semantics.md §2.8) ---------------------------------------------------------------------

// FANUC mill, G54 zero at machine (−500, −300, −500), reference point 1 at machine (0, 0, 0):
//   G0 X10. Y20. Z30.   machine (−490, −280, −470)
//   G28 X50. Y60.       rapid to the intermediate point, work (50, 60, 30) = machine (−450, −240, −470),
//                       then rapid to reference point 1 on X and Y only: machine (0, 0, −470) =
//                       work (500, 300, 30); Z is not programmed and stays
//   G91 G28 Z0.         intermediate point = the current point; Z to machine 0 = work Z 500
TEST_CASE("G28: via the intermediate point to reference point 1, programmed axes only", "[coordinates]") {
    const Run r = run("O1\nG90 G0 X10. Y20. Z30.\nG28 X50. Y60.\nG91 G28 Z0.\nM30\n", "fanuc-mill",
                      [](Setup& s) { s.work_offsets[0] = {-500, -300, -500, 0, 0, 0}; });
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() >= 4);   // each G28: intermediate leg, then reference leg (the G91 Z0 one is empty)
    for (const Event& e : m) CHECK(e.kind == EventKind::rapid);
    CHECK(m[1].end[X] == Approx(50));
    CHECK(m[1].end[Y] == Approx(60));
    CHECK(m[1].end[Z] == Approx(30));
    CHECK(m[1].machine_end[X] == Approx(-450));
    CHECK(m[1].machine_end[Y] == Approx(-240));
    CHECK(m[2].machine_end[X] == Approx(0));
    CHECK(m[2].machine_end[Y] == Approx(0));
    CHECK(m[2].machine_end[Z] == Approx(-470));
    CHECK(m[2].end[X] == Approx(500));
    CHECK(m[2].end[Y] == Approx(300));
    CHECK(m.back().machine_end[X] == Approx(0));
    CHECK(m.back().machine_end[Y] == Approx(0));
    CHECK(m.back().machine_end[Z] == Approx(0));
    CHECK(r.result.final_position[X] == Approx(500));
    CHECK(r.result.final_position[Y] == Approx(300));
    CHECK(r.result.final_position[Z] == Approx(500));
}

// Lathe idioms (dialects.md §3.2): G28 U0 / G28 W0 = straight to the reference point on that axis.
// Reference point 1 at machine X300 (diameter) Z550; offsets zero:
//   G0 X50. Z20.  →  G28 U0.: X to 300, Z stays 20  →  G28 W0.: Z to 550, X stays 300
TEST_CASE("lathe G28 U0 and G28 W0 move one axis each", "[coordinates]") {
    const Run r = run("O1\nG0 X50. Z20.\nG28 U0.\nG28 W0.\nM30\n", "fanuc-lathe-a",
                      [](Setup& s) { s.reference_points[0] = {300, 0, 550, 0, 0, 0}; });
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE_FALSE(m.empty());
    bool x_home_with_z20 = false;
    for (const Event& e : m)
        if (std::fabs(e.machine_end[X] - 300) < 1e-9 && std::fabs(e.machine_end[Z] - 20) < 1e-9) x_home_with_z20 = true;
    CHECK(x_home_with_z20);   // after G28 U0: X at the reference point, Z untouched
    CHECK(m.back().machine_end[X] == Approx(300));
    CHECK(m.back().machine_end[Z] == Approx(550));
}

// --- incremental words (dialects.md §3.2, §4) ------------------------------------------------------

// System A: X/Z absolute, U/W incremental; with X and U in one block the later one is used [FANUC]:
//   G0 X50. Z0.   →  G0 X20. U10.: U is later → 50 + 10 = 60  →  G0 U10. X20.: X is later → 20
TEST_CASE("system A: X and U in one block, the later word wins", "[coordinates]") {
    const Run r = run("O1\nG0 X50. Z0.\nG0 X20. U10.\nG0 U10. X20.\nM30\n", "fanuc-lathe-a");
    CHECK(r.result.alarms.empty());
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].end[X] == Approx(60));
    CHECK(m[2].end[X] == Approx(20));
}

// Systems B and C: G90/G91 (group 03) decide, X stays a diameter under G91; U/W keep their
// incremental meaning (the dialect lists them as incremental letters, dialects.md §4 [FANUC]):
//   G90 G0 X50. Z0.   →  G91 G0 X10. Z-5.: (60, −5)  →  G90 G0 X20.: 20  →  G0 U10. W-5.: (30, −10)
TEST_CASE("systems B/C: G91 and U/W", "[coordinates]") {
    for (const char* id : {"fanuc-lathe-b", "fanuc-lathe-c"}) {
        INFO(id);
        const Run r = run("O1\nG90 G0 X50. Z0.\nG91 G0 X10. Z-5.\nG90 G0 X20.\nG0 U10. W-5.\nM30\n", id);
        require_clean(r);
        const auto m = moves_with_threads(r);
        REQUIRE(m.size() == 4);
        CHECK(m[1].end[X] == Approx(60));
        CHECK(m[1].end[Z] == Approx(-5));
        CHECK(m[2].end[X] == Approx(20));
        CHECK(m[2].end[Z] == Approx(-5));
        CHECK(m[3].end[X] == Approx(30));
        CHECK(m[3].end[Z] == Approx(-10));
        // Incremental diameter: X10 under G91 moves the tool 5 mm radially.
        CHECK(m[1].length_mm == Approx(std::sqrt(5.0 * 5.0 + 5.0 * 5.0)));
    }
}

// Mills: G91 in pcnc-mill and adv400-mill as in fanuc-mill: G90 X10 Y10 → G91 X5 Y-5 → (15, 5);
// G90 X0 → 0.
TEST_CASE("mills: G91 incremental in pcnc-mill and adv400-mill", "[coordinates]") {
    for (const char* id : {"pcnc-mill", "adv400-mill"}) {
        INFO(id);
        const Run r = run("G90 G0 X10 Y10\nG91 G0 X5 Y-5\nG90 G0 X0\nM30\n", id);
        CHECK(r.result.alarms.empty());
        const auto m = moves_with_threads(r);
        REQUIRE(m.size() == 3);
        CHECK(m[1].end[X] == Approx(15));
        CHECK(m[1].end[Y] == Approx(5));
        CHECK(m[2].end[X] == Approx(0));
        CHECK(m[2].end[Y] == Approx(5));
    }
}

// --- lathe diameter lengths (dialects.md §3.3) ------------------------------------------------------

// X is a diameter; the path runs at the radius:
//   G0 X20. Z0.        from (0, 0): 10 mm (radius) rapid
//   G98 G1 X40. F100.  10 mm radially; 10/100 min = 6 s
//   G1 Z-30.           30 mm; 18 s
//   G1 X20. Z-40.      radius −10, Z −10: √200 = 14.1421 mm; 8.4853 s
// rapid distance 10, feed distance 10 + 30 + 14.1421 = 54.1421 mm.
TEST_CASE("lathe: lengths and times use the radius of diameter X", "[coordinates]") {
    const Run r = run("O1\nG0 X20. Z0.\nG98 G1 X40. F100.\nG1 Z-30.\nG1 X20. Z-40.\nM30\n", "fanuc-lathe-a");
    require_clean(r);
    const auto m = moves_with_threads(r);
    REQUIRE(m.size() == 4);
    CHECK(m[0].length_mm == Approx(10));
    CHECK(m[1].length_mm == Approx(10));
    CHECK(m[1].time_s == Approx(6));
    CHECK(m[2].length_mm == Approx(30));
    CHECK(m[2].time_s == Approx(18));
    CHECK(m[3].length_mm == Approx(14.1421356));
    CHECK(m[3].time_s == Approx(8.4852814));
    CHECK(r.result.rapid_distance_mm == Approx(10));
    CHECK(r.result.feed_distance_mm == Approx(54.1421356));
}
