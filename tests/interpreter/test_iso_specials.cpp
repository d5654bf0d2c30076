// iso-legacy-mill special functions (seed 004; semantics.md §9.4, §9.5) through the interpreter:
// G28 K F corner slow-down and G29 cancel (function ids corner-slowdown / -cancel, not reference
// returns), G43 as an approach that stops D short. Expected values derived by hand below.
#include <cmath>

#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf::test;

namespace {

// The example-6 numbers of §9.5 on a path without compensation (bare setup: no acceleration, so
// a feed move takes length / F exactly).
const char* kSlowdown =
    "O1\nG90 G17\nG0 X180. Y140.\nG1 F210\nG28 K15. F30\nX30.\nY60.\nG3 X55. Y35. I25.\n"
    "G28 K5 F50\nG1 X75. F1000\nX78.\nG29\nX100.\nM30\n";

std::vector<Event> on_line(const Run& r, std::uint32_t line) { return moves_on_line(r, line); }

// Both runs clean, and their moves the same kind to the same X Y, move for move.
void same_moves(const Run& a_run, const Run& b_run, double margin) {
    require_clean(a_run);
    require_clean(b_run);
    const auto a = moves(a_run), b = moves(b_run);
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        INFO("move " << i);
        CHECK(a[i].kind == b[i].kind);
        CHECK(a[i].end[X] == Approx(b[i].end[X]).margin(margin));
        CHECK(a[i].end[Y] == Approx(b[i].end[Y]).margin(margin));
    }
}

}  // namespace

// Step (machine switch corner_slowdown = "step"): the feed drops to F·(1 − p) for the last K mm.
//   line 6  X30 from X180 Y140: 150 mm → 135 mm at F210 (38.571 s) to X45, 15 mm at 147 (6.122 s)
//   line 7  Y60: 80 mm → 65 mm at 210 to Y75, 15 mm at 147
//   line 8  G3: an arc, no slow-down (§9.5 "G28 is valid only in G1 blocks"): one event at 210
//   line 10 X75 F1000 from X55: 20 mm → 15 mm at 1000 (0.9 s) to X70, 5 mm at 500 (0.6 s)
//   line 11 X78: 3 mm < K: one piece at 500 (0.36 s)
//   line 13 after G29: X100 one move at 1000
TEST_CASE("seed 004 G28 K F: the last K mm of each G01 move at the reduced feed (step)") {
    const Run r = run_bare(kSlowdown, "iso-legacy-mill", [](Setup& s) { s.corner_slowdown_step = true; });
    require_clean(r);
    const auto l6 = on_line(r, 6);
    REQUIRE(l6.size() == 2);
    CHECK(l6[0].end[X] == Approx(45));
    CHECK(l6[0].feed == Approx(210));
    CHECK(l6[0].time_s == Approx(135.0 / 210 * 60));
    CHECK(l6[1].end[X] == Approx(30));
    CHECK(l6[1].feed == Approx(147));
    CHECK(l6[1].time_s == Approx(15.0 / 147 * 60));
    const auto l7 = on_line(r, 7);
    REQUIRE(l7.size() == 2);
    CHECK(l7[0].end[Y] == Approx(75));
    CHECK(l7[1].feed == Approx(147));
    const auto l8 = on_line(r, 8);
    REQUIRE(l8.size() == 1);
    CHECK(l8[0].kind == EventKind::arc_ccw);
    CHECK(l8[0].feed == Approx(210));
    const auto l10 = on_line(r, 10);
    REQUIRE(l10.size() == 2);
    CHECK(l10[0].end[X] == Approx(70));
    CHECK(l10[0].time_s == Approx(0.9));
    CHECK(l10[1].feed == Approx(500));
    CHECK(l10[1].time_s == Approx(0.6));
    const auto l11 = on_line(r, 11);
    REQUIRE(l11.size() == 1);
    CHECK(l11[0].feed == Approx(500));
    CHECK(l11[0].time_s == Approx(0.36));
    const auto l13 = on_line(r, 13);
    REQUIRE(l13.size() == 1);
    CHECK(l13[0].feed == Approx(1000));
    // The G28 blocks have no motion and do not return to the reference point.
    CHECK(on_line(r, 5).empty());
    CHECK(on_line(r, 9).empty());
}

// Ramp (the default): f(s) = F(1 − p) + F·p·s/K at s mm before the end; the time of the last d mm
// is K/(F·p) · ln(f(d) / (F(1 − p))) minutes. The event's feed is the end feed.
//   line 6: 15/63 · ln(210/147) · 60 = 5.0954 s
//   line 10: 5/500 · ln(1000/500) · 60 = 0.41589 s
//   line 11 (3 mm of the 5): f(3) = 500 + 500·3/5 = 800 → 5/500 · ln(800/500) · 60 = 0.28200 s
TEST_CASE("seed 004 G28 K F: the default ramp times the reduced piece by the mean of 1/feed") {
    const Run r = run_bare(kSlowdown, "iso-legacy-mill");
    require_clean(r);
    const auto l6 = on_line(r, 6);
    REQUIRE(l6.size() == 2);
    CHECK(l6[0].time_s == Approx(135.0 / 210 * 60));
    CHECK(l6[1].feed == Approx(147));
    CHECK(l6[1].time_s == Approx(15.0 / 63 * std::log(210.0 / 147) * 60));
    CHECK(l6[1].time_s == Approx(5.0954).margin(0.0001));
    const auto l10 = on_line(r, 10);
    REQUIRE(l10.size() == 2);
    CHECK(l10[1].time_s == Approx(0.41589).margin(0.0001));
    const auto l11 = on_line(r, 11);
    REQUIRE(l11.size() == 1);
    CHECK(l11[0].time_s == Approx(0.28200).margin(0.0001));
}

// §9.4: `G0 G43 X140. Y35. D08` from X75 Y35 with D08 = 10 stops at X130 Y35; the next block is
// measured from the programmed point: G91 G1 X10. ends at X150.
TEST_CASE("seed 004 G43 in a move: the approach stops D short of the programmed point") {
    const Run r = run_bare("O1\nG90 G17 G0 X75. Y35.\nG0 G43 X140. Y35. D08\nG91 G1 X10. F100\nM30\n", "iso-legacy-mill",
                           [](Setup& s) { s.tools[8].radius = 10; });
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].kind == EventKind::rapid);
    CHECK(m[1].end[X] == Approx(130));
    CHECK(m[1].end[Y] == Approx(35));
    CHECK(m[2].end[X] == Approx(150));
    CHECK(count(r, EventKind::message) == 1);   // the inference is flagged
}

// Under G42 (example 6 N50–N65): the approach leaves the tool at the start-up point of the next
// element: `G2 G41 X180. Y75. I40.` (centre X180 Y35, R40, tool outside: R50) runs from X130 Y35
// to X180 Y85 without a start-up alarm.
TEST_CASE("seed 004 G43 approach under compensation, then a G41 arc from the offset point") {
    const Run r = run_bare("O1\nG90 G17 G0 X75. Y60.\nG1 G42 D08 Y35. F100\nG0 G43 X140. Y35. D08\n"
                           "G2 G41 X180. Y75. I40. D08\nM30\n",
                           "iso-legacy-mill", [](Setup& s) { s.tools[8].radius = 10; });
    require_clean(r);
    const auto l4 = on_line(r, 4);
    REQUIRE(!l4.empty());
    CHECK(l4.back().end[X] == Approx(130));
    CHECK(l4.back().end[Y] == Approx(35));
    const auto l5 = on_line(r, 5);
    REQUIRE(l5.size() == 1);
    CHECK(l5[0].kind == EventKind::arc_cw);
    CHECK(l5[0].end[X] == Approx(180));
    CHECK(l5[0].end[Y] == Approx(85));
    CHECK(l5[0].radius == Approx(50));
}

// §9.6: G12/G13 as quarter arcs from the programmed point, CCW under G41/G40 and CW under G42.
//   from X135 Y50 `G12 X95. Y90.`: chord (−40, 40), half (−20, 20); CCW: the centre is the middle
//   (115, 70) plus the half chord turned +90° (−20, −20) = (95, 50), R40 (= the explicit `G3 X95.
//   Y90. I-40. J0.` of example 4); under G42 turned −90° (20, 20): centre (135, 90), CW.
TEST_CASE("seed 004 G12/G13: a quarter arc, its direction from the compensation side") {
    const Run ccw = run_bare("O1\nG90 G17 G0 X135. Y50.\nG12 X95. Y90. F200\nG13 X55. Y50.\nM30\n", "iso-legacy-mill");
    require_clean(ccw);
    const auto a = arcs(ccw);
    REQUIRE(a.size() == 2);
    CHECK(a[0].kind == EventKind::arc_ccw);
    REQUIRE(a[0].center);
    CHECK((*a[0].center)[X] == Approx(95));
    CHECK((*a[0].center)[Y] == Approx(50));
    CHECK(a[0].radius == Approx(40));
    // G13 from X95 Y90 to X55 Y50: half (−20, −20), turned +90° (20, −20): centre (95, 50) again.
    CHECK(a[1].kind == EventKind::arc_ccw);
    CHECK((*a[1].center)[X] == Approx(95));
    CHECK((*a[1].center)[Y] == Approx(50));
    CHECK(a[1].end[X] == Approx(55));
    // G42 with a zero radius (D03 = 0) started on a line (an arc start is alarm 034): the tool
    // follows the programmed path.
    const Run cw = run_bare("O1\nG90 G17 G0 X135. Y40.\nG42 D03 G1 Y50. F100\nG12 X95. Y90. F200\nG40 G1 Y100.\nM30\n",
                            "iso-legacy-mill", [](Setup& s) { s.tools[3].radius = 0; });
    require_clean(cw);
    const auto b = arcs(cw);
    REQUIRE(b.size() == 1);
    CHECK(b[0].kind == EventKind::arc_cw);
    CHECK((*b[0].center)[X] == Approx(135));
    CHECK((*b[0].center)[Y] == Approx(90));
}

// Example 4 with its bracketed alternatives (the G12 end point taken as Y90, the explicit arc's;
// Ambiguities §12.10): under G41 D03 = 12 the compensated path equals that of the explicit G3
// blocks move for move.
TEST_CASE("seed 004 example 4: G12/G13 under G41 give the path of the explicit arcs") {
    const std::string head = "O1\nG0 X135. Y50. Z-30.\nG41 D03\n";
    const std::string body = "G1 X45. F40\nG3 Y10. I0. J-40.\nG1 X180.\nG3 Y90. I0. J40.\nG1 X95.\n";
    const auto with_regs = [](Setup& s) {
        s.tools[3].radius = 12;
        s.comp_shift_without_motion = true;
    };
    const Run explicit_arcs = run_bare(head + "G3 X95. Y90. I-40. J0. F200\n" + body + "G3 X55. Y50. I0. J-40. F200\nG0 G40 X95. M02\n",
                                       "iso-legacy-mill", with_regs);
    const Run g12 = run_bare(head + "G12 X95. Y90. F200\n" + body + "G13 X55. Y50. F200\nG0 G40 X95. M02\n", "iso-legacy-mill",
                             with_regs);
    same_moves(g12, explicit_arcs, 1e-6);
    // The explicit run: the entry arc R28 about X95 Y50 (the golden trace of example 4).
    CHECK(moves(explicit_arcs)[2].radius == Approx(28));
}

// G43/G44 with H (semantics.md §7: "G43 and G44 define the directions of the axial offset", the
// offsets in registers addressed by H): the axial length offset on Z, + for G43, − for G44, as
// executor_length.cpp applies FANUC's. H3 = 40 (length) − 1 (wear) = 39; bare setup: machine =
// work + offset.
//   line 2 G0 Z100            machine Z 100
//   line 3 G43 H3 Z50.        machine 50 + 39 = 89; no approach shortening (H given): X Y not moved
//   line 4 G44 H3 Z20.        machine 20 − 39 = −19
//   line 5 G43 H0 Z0.         H0: no offset, machine 0
TEST_CASE("seed 004 G43/G44 with H: the axial length offset on Z") {
    const Run r = run_bare("O1\nG90 G17 G0 X10. Y10. Z100.\nG0 G43 H3 Z50.\nG0 G44 H3 Z20.\nG0 G43 H0 Z0.\nM30\n",
                           "iso-legacy-mill", [](Setup& s) {
                               s.tools[3].length = 40;
                               s.tools[3].length_wear = -1;
                               s.tools[3].radius = 5;
                           });
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 4);
    CHECK(m[1].end[Z] == Approx(50));
    CHECK(m[1].machine_end[Z] == Approx(89));
    CHECK(m[1].end[X] == Approx(10));
    CHECK(m[2].machine_end[Z] == Approx(-19));
    CHECK(m[3].machine_end[Z] == Approx(0));
    const auto changes = of_kind(r, EventKind::coordinate_change);
    REQUIRE(changes.size() == 3);
    CHECK(changes[0].code == 3);
    CHECK(count(r, EventKind::message) == 0);
}

// Machine switch iso_g43 = "length-offset" (semantics.md §12.9, machine/SCHEMA.md): G43 is the
// axial offset even without H, so example 6's approach `G0 G43 X140. Y35. D08` is not shortened
// (X140, not X130) and the modal H (H3 = 39 from line 2) shifts machine Z from the next Z move.
TEST_CASE("seed 004 G43 with the length-offset switch: no approach shortening, the modal H on Z") {
    const Run r = run_bare("O1\nG90 G17 G0 X75. Y35. Z10. H3\nG0 G43 X140. Y35. D08\nZ10.\nM30\n", "iso-legacy-mill",
                           [](Setup& s) {
                               s.tools[3].length = 39;
                               s.tools[8].radius = 10;
                               s.iso_g43_approach = false;
                           });
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].end[X] == Approx(140));
    CHECK(m[1].machine_end[Z] == Approx(10));   // no Z in the G43 block: not taken up yet
    CHECK(m[2].machine_end[Z] == Approx(49));   // Z10. takes H3 = 39 up
    CHECK(count(r, EventKind::message) == 0);
}

// G44 without H: the seed gives only "the opposite direction of G43" (its chapter 8 is missing):
// nothing is offset, the move runs as programmed and a message says why.
TEST_CASE("seed 004 G44 without H: the move as programmed, the gap said") {
    const Run r = run_bare("O1\nG90 G17 G0 X75. Y35.\nG0 G44 X140. Y35. D08\nM30\n", "iso-legacy-mill",
                           [](Setup& s) { s.tools[8].radius = 10; });
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 2);
    CHECK(m[1].end[X] == Approx(140));
    REQUIRE(count(r, EventKind::message) == 1);
    CHECK(of_kind(r, EventKind::message)[0].text.find("opposite direction of G43") != std::string::npos);
}

// A G12/G13 quarter arc is no mode: read ahead from it (compensation's look-ahead), the block after
// it without a motion code is the modal G01, as when it is written. Before, the look-ahead took the
// quarter arc's motion for it and the corner at the arc's end was built for an arc.
TEST_CASE("seed 004 G12 under G41: the block after it runs and is read ahead with the modal G01") {
    const auto with_regs = [](Setup& s) {
        s.tools[1].radius = 2;
        s.comp_shift_without_motion = true;
    };
    const std::string head = "O1\nG90 G17 G0 X0. Y0.\nG41 D1 G1 X10. Y0. F200\nG12 X20. Y10.\n";
    const Run modal = run_bare(head + "X30. Y10.\nG40 G1 Y20.\nM02\n", "iso-legacy-mill", with_regs);
    const Run written = run_bare(head + "G01 X30. Y10.\nG40 G1 Y20.\nM02\n", "iso-legacy-mill", with_regs);
    same_moves(modal, written, 1e-9);
}
