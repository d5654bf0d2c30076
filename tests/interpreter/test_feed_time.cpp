// Spindle speed, feed and time of moves through the interpreter (reference/semantics.md §4, §4.1;
// gcode-tables.md §5): G96 rpm from X (n = 1000·Vc/(π·D)), its clamp by G50 S (system A) / G92 S
// (systems B/C) and by the machine's maximum, G97 fixed rpm, feed per minute and per revolution,
// and rapid time from the Setup's rapid rates (no acceleration: the Setup leaves it out).
//
// Units: rapid rates in the Setup are geometric mm/min per axis (motion/time.hpp: lathe X moves
// at its radius), F in mm/min (G94/G98) or mm/rev (G95/G99), times in seconds. Every expected
// number is derived by hand in the comment next to it (π = 3.14159265).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf;
using namespace kerf::test;

// Runs use bare_setup (tests/interpreter/interpreter_fixture.hpp): no rapid rates unless set.

// --- G96 (semantics.md §4.1) -------------------------------------------------------------------------

// Lathe A, G50 S3000, G96 S200 (Vc = 200 m/min), G99 F0.2 (mm/rev, the power-on mode):
//   G1 Z0. at X100: n = 1000·200/(π·100) = 636.6198 rpm; feed 0.2·636.6198 = 127.3240 mm/min;
//                   5 mm → 5/127.3240 min = 2.356194 s
//   G1 Z-5. at X50: n = 1000·200/(π·50) = 1273.2395 rpm
//   G1 Z-10. at X10: n = 6366.198 rpm > S3000 → 3000 rpm; 5 mm at 0.2·3000 = 600 mm/min = 0.5 s
// The M3 in the G96 block runs at X0 (the power-on position), where n is clamped: 3000 rpm.
TEST_CASE("G96: rpm from the diameter, clamped by G50 S", "[feed]") {
    const Run r = run_bare("O1\nG50 S3000\nG96 S200 M3\nG0 X100. Z5.\nG1 Z0. F0.2\nG0 X50.\nG1 Z-5.\nG0 X10.\nG1 Z-10.\nM30\n",
                           "fanuc-lathe-a");
    require_clean(r);
    std::vector<Event> cuts;
    for (const Event& e : r.events)
        if (e.kind == EventKind::linear) cuts.push_back(e);
    REQUIRE(cuts.size() == 3);
    CHECK(cuts[0].feed_per_rev);
    CHECK(cuts[0].spindle_rpm == Approx(636.6198));
    CHECK(cuts[0].time_s == Approx(2.356194));
    CHECK(cuts[1].spindle_rpm == Approx(1273.2395));
    CHECK(cuts[2].spindle_rpm == Approx(3000));
    CHECK(cuts[2].time_s == Approx(0.5));
    std::vector<double> spindle;
    for (const Event& e : r.events)
        if (e.kind == EventKind::spindle) spindle.push_back(e.spindle_rpm);
    REQUIRE(spindle.size() == 1);
    CHECK(spindle[0] == Approx(3000));
}

// The machine maximum clamps too: Setup::max_rpm 2500 with G50 S3000 → at X10 (6366 rpm free)
// min(3000, 2500) = 2500; with G50 S2000 → 2000; without any G50 S → 2500.
TEST_CASE("G96: the machine's maximum rpm", "[feed]") {
    auto max2500 = [](Setup& s) { s.max_rpm = 2500; };
    const Run a = run_bare("O1\nG50 S3000\nG96 S200 M3\nG0 X10. Z5.\nG1 Z0. F0.2\nM30\n", "fanuc-lathe-a", max2500);
    require_clean(a);
    REQUIRE(moves(a).size() == 2);
    CHECK(moves(a)[1].spindle_rpm == Approx(2500));
    const Run b = run_bare("O1\nG50 S2000\nG96 S200 M3\nG0 X10. Z5.\nG1 Z0. F0.2\nM30\n", "fanuc-lathe-a", max2500);
    require_clean(b);
    CHECK(moves(b)[1].spindle_rpm == Approx(2000));
    const Run c = run_bare("O1\nG96 S200 M3\nG0 X10. Z5.\nG1 Z0. F0.2\nM30\n", "fanuc-lathe-a", max2500);
    require_clean(c);
    CHECK(moves(c)[1].spindle_rpm == Approx(2500));
}

// Systems B/C: the clamp is G92 S (dialects.md §4), G96 S150, G95 F0.1:
//   at X50: n = 1000·150/(π·50) = 954.9297 rpm; at X20: 2387.324 > S1500 → 1500 rpm.
TEST_CASE("G96 in systems B/C: G92 S clamps", "[feed]") {
    for (const char* id : {"fanuc-lathe-b", "fanuc-lathe-c"}) {
        INFO(id);
        const Run r = run_bare("O1\nG92 S1500\nG96 S150 M3\nG90 G0 X50. Z5.\nG95 G1 Z0. F0.1\nG0 X20.\nG1 Z-5.\nM30\n", id);
        require_clean(r);
        std::vector<Event> cuts;
        for (const Event& e : r.events)
            if (e.kind == EventKind::linear) cuts.push_back(e);
        REQUIRE(cuts.size() == 2);
        CHECK(cuts[0].spindle_rpm == Approx(954.9297));
        CHECK(cuts[1].spindle_rpm == Approx(1500));
        // The G92 S block is a clamp, not a coordinate setting: the tool still reads X50 Z5 etc.
        CHECK(cuts[0].end[X] == Approx(50));
    }
}

// G97 S800: a fixed rpm whatever X is; G99 F0.2 → 160 mm/min; 10 mm → 10/160 min = 3.75 s.
TEST_CASE("G97: fixed rpm", "[feed]") {
    const Run r = run_bare("O1\nG97 S800 M3\nG0 X100. Z0.\nG1 Z-10. F0.2\nG0 X10.\nG1 Z-20.\nM30\n", "fanuc-lathe-a");
    require_clean(r);
    std::vector<Event> cuts;
    for (const Event& e : r.events)
        if (e.kind == EventKind::linear) cuts.push_back(e);
    REQUIRE(cuts.size() == 2);
    CHECK(cuts[0].spindle_rpm == Approx(800));
    CHECK(cuts[0].time_s == Approx(3.75));
    CHECK(cuts[1].spindle_rpm == Approx(800));
    CHECK(cuts[1].time_s == Approx(3.75));
}

// [FANUC] (semantics.md §4.1) the rpm of a cutting move is computed continuously, so a facing cut
// under G96 speeds up as X falls. G50 S3000, G96 S200, G99 F0.2, X100 → X20 at Z0 (radius 50 → 10):
//   the clamp starts at D = 1000·200/(π·3000) = 21.22066 mm (radius xc = 10.61033);
//   free part: ∫ π·2x dx/(1000·Vc·f) = π·(50² − 10.61033²)/40000 min = 11.250456 s;
//   clamped part: (10.61033 − 10) mm at 0.2·3000 = 600 mm/min = 0.061033 s; total 11.311489 s.
// (The end-point rpm alone would give 40 mm at 600 mm/min = 4 s.)
TEST_CASE("G96: time of a facing cut with the rpm following X", "[feed]") {
    const Run r = run_bare("O1\nG50 S3000\nG96 S200 M3\nG0 X100. Z0.\nG1 X20. F0.2\nM30\n", "fanuc-lathe-a");
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 2);
    CHECK(m[1].length_mm == Approx(40));
    CHECK(m[1].time_s == Approx(11.311489));
}

// --- feed per minute / per revolution (semantics.md §4) ----------------------------------------------

// Mill G94 F200: (0, 0) → (30, 40) is 50 mm → 50/200 min = 15 s.
// Lathe A G98 F100: Z0 → Z−50 is 50 mm → 30 s.
// Lathe B G94 F100 (feed per minute in B): the same 30 s.
TEST_CASE("feed per minute: time of a known move", "[feed]") {
    const Run mill = run_bare("O1\nG90 G94 G1 X30. Y40. F200.\nM30\n", "fanuc-mill");
    require_clean(mill);
    REQUIRE(moves(mill).size() == 1);
    CHECK_FALSE(moves(mill)[0].feed_per_rev);
    CHECK(moves(mill)[0].length_mm == Approx(50));
    CHECK(moves(mill)[0].time_s == Approx(15));
    CHECK(mill.result.total_time_s == Approx(15));
    CHECK(mill.result.feed_distance_mm == Approx(50));

    const Run a = run_bare("O1\nG98 G1 Z-50. F100.\nM30\n", "fanuc-lathe-a");
    require_clean(a);
    REQUIRE(moves(a).size() == 1);
    CHECK(moves(a)[0].time_s == Approx(30));

    const Run b = run_bare("O1\nG94 G1 Z-50. F100.\nM30\n", "fanuc-lathe-b");
    require_clean(b);
    REQUIRE(moves(b).size() == 1);
    CHECK(moves(b)[0].time_s == Approx(30));
}

// Feed per revolution: F × rpm mm/min (semantics.md §4 [seed 003]).
//   Lathe A G99 F0.2 at S500: 100 mm/min; 10 mm → 6 s.
//   Mill G95 F0.1 at S1000: 100 mm/min; 10 mm → 6 s.
// F is modal: the second lathe cut (Z−10 → Z−25, 15 mm) keeps F0.2 → 9 s; total 6 + 9 = 15 s
// (rapids have no rapid rate in this Setup: 0 s).
TEST_CASE("feed per revolution: time of a known move", "[feed]") {
    const Run a = run_bare("O1\nG97 S500 M3\nG0 X40. Z0.\nG99 G1 Z-10. F0.2\nZ-25.\nM30\n", "fanuc-lathe-a");
    require_clean(a);
    std::vector<Event> cuts;
    for (const Event& e : a.events)
        if (e.kind == EventKind::linear) cuts.push_back(e);
    REQUIRE(cuts.size() == 2);
    CHECK(cuts[0].feed_per_rev);
    CHECK(cuts[0].feed == Approx(0.2));
    CHECK(cuts[0].time_s == Approx(6));
    CHECK(cuts[1].time_s == Approx(9));
    CHECK(a.result.total_time_s == Approx(15));

    const Run mill = run_bare("O1\nS1000 M3\nG90 G95 G1 X10. F0.1\nM30\n", "fanuc-mill");
    require_clean(mill);
    REQUIRE(moves(mill).size() == 1);
    CHECK(moves(mill)[0].feed_per_rev);
    CHECK(moves(mill)[0].time_s == Approx(6));
}

// --- rapid (gcode-tables.md §5) ----------------------------------------------------------------------

// Mill rapid rates X 6000, Y 3000, Z 1200 mm/min. G0 (0,0,0) → (100, 30, −12):
//   X 100/6000 min = 1.0 s, Y 30/3000 min = 0.6 s, Z 12/1200 min = 0.6 s → the slowest axis: 1.0 s
//   (dog-leg and straight agree without acceleration).
// G0 → (100, 0, −12): only Y moves, 30 mm → 0.6 s. F does not matter for G00.
// Totals: 1.6 s, rapid distance √(100² + 30² + 12²) + 30 = √11044 + 30 = 105.0904 + 30 = 135.0904 mm.
TEST_CASE("rapid time from the Setup's rapid rates (mill)", "[feed]") {
    const Run r = run_bare("O1\nG90 G0 X100. Y30. Z-12. F1.\nG0 Y0.\nM30\n", "fanuc-mill",
                           [](Setup& s) { s.rapid_mm_min = {6000, 3000, 1200, 0, 0, 0}; });
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 2);
    CHECK(m[0].time_s == Approx(1.0));
    CHECK(m[1].time_s == Approx(0.6));
    CHECK(r.result.total_time_s == Approx(1.6));
    CHECK(r.result.rapid_distance_mm == Approx(135.0904));
}

// Lathe: X is a diameter, the axis moves its radius. Rates X 6000, Z 12000 mm/min.
// G0 (X0, Z0) → (X100, Z−30): X radius 50 mm → 0.5 s; Z 30 mm → 0.15 s → 0.5 s.
TEST_CASE("rapid time on a lathe uses the radius travel of X", "[feed]") {
    const Run r = run_bare("O1\nG0 X100. Z-30.\nM30\n", "fanuc-lathe-a",
                           [](Setup& s) { s.rapid_mm_min = {6000, 0, 12000, 0, 0, 0}; });
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 1);
    CHECK(m[0].time_s == Approx(0.5));
    CHECK(m[0].length_mm == Approx(std::sqrt(50.0 * 50.0 + 30.0 * 30.0)));
}

// Time per tool: a lathe T0101 cut of 6 s, then T0202 cuts of 9 s (G98 F100: 10 mm and 15 mm).
TEST_CASE("time is booked to the active tool", "[feed]") {
    const Run r = run_bare("O1\nT0101\nG98 G1 Z-10. F100.\nT0202\nG1 Z-25.\nM30\n", "fanuc-lathe-a");
    require_clean(r);
    CHECK(r.result.time_per_tool_s.at(1) == Approx(6));
    CHECK(r.result.time_per_tool_s.at(2) == Approx(9));
    CHECK(r.result.total_time_s == Approx(15));
    REQUIRE(r.result.tools.size() == 2);
    CHECK(r.result.tools[0] == 1);
    CHECK(r.result.tools[1] == 2);
}

// --- dwell (semantics.md §8.2) -------------------------------------------------------------------------

// G04 X_ is a time in seconds: X is a data word of G04 (the dialect's parameter_words), not a move.
//   Mill:     G90 G0 X10. → G4 X2.: one dwell of 2 s, the tool stays at X10 (one move in all).
//   Lathe A:  G0 X50. Z0. → G4 X1.5 (1.5 s) → G4 U2. (2 s): the tool stays at X50 Z0.
TEST_CASE("G04 X is a dwell time, not a move", "[feed]") {
    const Run mill = run_bare("O1\nG90 G0 X10. Y0.\nG4 X2.\nM30\n", "fanuc-mill");
    require_clean(mill);
    CHECK(moves(mill).size() == 1);
    CHECK(mill.result.final_position[X] == Approx(10));
    std::vector<double> dwells;
    for (const Event& e : mill.events)
        if (e.kind == EventKind::dwell) dwells.push_back(e.time_s);
    REQUIRE(dwells.size() == 1);
    CHECK(dwells[0] == Approx(2));

    const Run lathe = run_bare("O1\nG0 X50. Z0.\nG4 X1.5\nG4 U2.\nM30\n", "fanuc-lathe-a");
    require_clean(lathe);
    CHECK(moves(lathe).size() == 1);
    CHECK(lathe.result.final_position[X] == Approx(50));
    CHECK(lathe.result.final_position[Z] == Approx(0));
    CHECK(lathe.result.total_time_s == Approx(3.5));   // no rapid rates in this Setup: 1.5 + 2 s of dwell
}
