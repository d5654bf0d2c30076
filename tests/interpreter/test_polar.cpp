// G12.1/G112 … G13.1/G113 polar coordinate interpolation (reference/cycles.md §18) and G07.1/G107
// cylindrical interpolation (§19) through the interpreter (interpreter/polar.cpp), fanuc-lathe-a
// with the bare setup (zero offsets, no rapid rates, X as a diameter), calculator-type input (X40
// = 40 mm, to keep the texts short), G98 (F in mm/min).
//
// Polar, by hand (cycles.md §18 "Expansion"): a programmed point (X, C) of the plane is
// (x = X/2, y = C) in mm; the machine goes to X_dia = 2·√(x² + y²), C = C_start + atan2(y, x) in
// degrees, continuous across ±180°. C_start = the C at G112 (0 here). Each block becomes pieces
// whose end points lie on the programmed line or arc (the last one at the programmed end); F is
// the speed along the Cartesian path, so a block of length L takes L/F.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "tests/interpreter/polar_plane.hpp"

using namespace kerf;
using namespace kerf::test;

namespace {

double time_of(const std::vector<Event>& events) {
    double t = 0;
    for (const Event& e : events) t += e.time_s;
    return t;
}

// fanuc-lathe-a, bare setup, calculator-type decimal input, then `change`.
Run run_lathe(const std::string& text, const SetupChange& change = {}) {
    return run_bare(text, "fanuc-lathe-a", [&](Setup& s) {
        s.calculator_decimal = true;
        if (change) change(s);
    });
}

bool has_message(const Run& r, const std::string& part) {
    for (const Event& e : r.events)
        if ((e.kind == EventKind::message || e.kind == EventKind::alarm) && e.text.find(part) != std::string::npos) return true;
    return false;
}

const char* kSquare =
    "O1\n"             // 1
    "G98 G0 X40 C0\n"  // 2  x = 20, y = 0
    "G112\n"           // 3
    "G1 X20 C10 F100\n"// 4  (10, 10)
    "X-20\n"           // 5  (−10, 10)
    "C-10\n"           // 6  (−10, −10)
    "X20\n"            // 7  (10, −10)
    "C10\n"            // 8  (10, 10) again, one turn later
    "G113\n"           // 9
    "G0 X50\n"         // 10 ordinary again
    "M30\n";

}  // namespace

TEST_CASE("G112: the corners of a square in the X–C plane become X diameter and C degrees", "[polar]") {
    const Run r = run_lathe(kSquare);
    require_clean(r);
    // Corner (10, 10): X = 2·√200 = 28.2843, C = atan2(10, 10) = 45°; (−10, 10): 135°;
    // (−10, −10): 225° (not −135: continuous); (10, −10): 315°; (10, 10) again: 405°.
    const double corner_x = 2 * std::sqrt(200.0);
    const struct {
        std::uint32_t line;
        double c;
    } corners[] = {{4, 45}, {5, 135}, {6, 225}, {7, 315}, {8, 405}};
    for (const auto& corner : corners) {
        INFO("line " << corner.line);
        const auto m = moves_on_line(r, corner.line);
        REQUIRE(!m.empty());
        CHECK(m.back().end[X] == Approx(corner_x));
        CHECK(m.back().end[C] == Approx(corner.c));
        CHECK(m.back().kind == EventKind::linear);
    }
    // After G113 an X move is an ordinary X move: C stays at 405°.
    const auto after = moves_on_line(r, 10);
    REQUIRE(after.size() == 1);
    CHECK(after[0].kind == EventKind::rapid);
    CHECK(after[0].end[X] == Approx(50));
    CHECK(after[0].end[C] == Approx(405));
    CHECK(r.result.final_position[C] == Approx(405));
}

TEST_CASE("G112: every piece ends on the programmed line, and the pieces are short", "[polar]") {
    const Run r = run_lathe(kSquare);
    require_clean(r);
    // Line 5 runs along y = 10 from x = 10 to x = −10: C from 45° to 135°. One piece would pass
    // through (√200, 90°) = (0, 14.14), 4.1 mm off; with the 0.01 mm tolerance there are many.
    const auto side = moves_on_line(r, 5);
    REQUIRE(side.size() > 4);
    double previous_c = 45;
    for (const Event& e : side) {
        CHECK(plane_y(e) == Approx(10).margin(1e-9));
        CHECK(e.end[C] > previous_c);          // the angle climbs monotonically
        CHECK(e.end[C] - previous_c <= 45.0);  // no piece turns more than 45° (motion/polar.hpp)
        previous_c = e.end[C];
    }
    // Line 6 along x = −10: every piece end has x = −10.
    for (const Event& e : moves_on_line(r, 6)) CHECK(plane_x(e) == Approx(-10).margin(1e-9));
}

TEST_CASE("G112: F is the feed along the Cartesian path", "[polar]") {
    const Run r = run_lathe(kSquare);
    require_clean(r);
    // Line 4: (20, 0) → (10, 10): √(100 + 100) = 14.1421 mm at 100 mm/min = 8.4853 s; the
    // pieces' lengths (chords on the line) add up to it.
    const auto first = moves_on_line(r, 4);
    double length = 0;
    for (const Event& e : first) length += e.length_mm;
    CHECK(length == Approx(std::sqrt(200.0)));
    CHECK(time_of(first) == Approx(std::sqrt(200.0) / 100 * 60));
    // Each side of the square: 20 mm at 100 mm/min = 12 s.
    for (std::uint32_t line = 5; line <= 8; ++line) CHECK(time_of(moves_on_line(r, line)) == Approx(12.0));
    // The summary's feed distance: 14.1421 + 4·20 = 94.1421 mm.
    CHECK(r.result.feed_distance_mm == Approx(std::sqrt(200.0) + 80));
}

TEST_CASE("G112: arcs with R and with I/J in the plane", "[polar]") {
    // Seed 001 §10.6 (O0033): P4 X-100 C30, `G2 X-100 C-30 R30`: the semicircle about (−50, 0),
    // clockwise from (−50, 30) through (−20, 0) to (−50, −30). C from atan2(30, −50) = 149.036°
    // through 180° to 210.964°; the nearest point to the centre is (−20, 0): X = 40.
    const Run r = run_lathe("O1\nG98 G0 X120 C0\nG112\nG1 X-100 C30 F100\nG2 X-100 C-30 R30\nG113\nM30\n");
    require_clean(r);
    const auto arc = moves_on_line(r, 5);
    REQUIRE(arc.size() > 4);
    double min_x = 1e9;
    for (const Event& e : arc) {
        CHECK(e.kind == EventKind::linear);   // arcs of the plane are pieces of linear X/C motion
        const double dx = plane_x(e) + 50, dy = plane_y(e);
        CHECK(std::hypot(dx, dy) == Approx(30).margin(1e-6));   // on the programmed circle
        min_x = std::min(min_x, e.end[X]);
    }
    CHECK(arc.back().end[C] == Approx(180 + std::atan2(30.0, 50.0) * kDeg));   // 210.964°
    CHECK(min_x == Approx(40).margin(0.01));
    // Half of a circle of radius 30: 30π = 94.2478 mm at F100: 56.549 s.
    CHECK(time_of(arc) == Approx(30 * std::numbers::pi / 100 * 60).epsilon(1e-4));

    // I/J: from (20, 0) about the centre (I−20 J0 → (0, 0)) to (0, 20), counter-clockwise: X stays
    // 40, C goes 0 → 90°; the radius is constant, so only the 45° limit cuts it: 2 pieces.
    const Run ij = run_lathe("O1\nG98 G0 X40 C0\nG112\nG3 X0 C20 I-20 J0 F100\nG113\nM30\n");
    require_clean(ij);
    const auto quarter = moves_on_line(ij, 4);
    REQUIRE(quarter.size() == 2);
    CHECK(quarter[0].end[X] == Approx(40));
    CHECK(quarter[0].end[C] == Approx(45));
    CHECK(quarter[1].end[X] == Approx(40));
    CHECK(quarter[1].end[C] == Approx(90));
}

TEST_CASE("G112: C_start is the C position at G112; Z moves with the path", "[polar]") {
    // C at 30° when G112 starts: the plane's angle 0 is there. (20, 10) → 30 + atan2(10, 20) =
    // 30 + 26.565 = 56.565°; Z runs linearly from 0 to −5 over the pieces.
    const Run r = run_lathe("O1\nG98 G0 X40 Z0 C30\nG112\nG1 X40 C10 Z-5 F100\nG113\nM30\n");
    require_clean(r);
    const auto m = moves_on_line(r, 4);
    REQUIRE(!m.empty());
    CHECK(m.back().end[C] == Approx(30 + std::atan2(10.0, 20.0) * kDeg));
    CHECK(m.back().end[X] == Approx(2 * std::sqrt(500.0)));
    CHECK(m.back().end[Z] == Approx(-5));
    // The length counts Z: √(10² + 5²) = 11.1803 mm.
    double length = 0;
    for (const Event& e : m) length += e.length_mm;
    CHECK(length == Approx(std::sqrt(125.0)));
}

TEST_CASE("G112 C45 (seed 001 §10.11): the C word is said and ignored", "[polar]") {
    const Run r = run_lathe("O1\nG98 G0 X40 C0\nG112 C45\nG1 X20 F100\nG113\nM30\n");
    require_clean(r);
    CHECK(has_message(r, "no known meaning"));
    CHECK(moves_on_line(r, 3).empty());
    // The mode is on: X20 is (10, 0) of the plane: X20 C0.
    const auto m = moves_on_line(r, 4);
    REQUIRE(!m.empty());
    CHECK(m.back().end[X] == Approx(20));
    CHECK(m.back().end[C] == Approx(0));
}

TEST_CASE("G112: improper codes in the mode are alarm 146 [FANUC]", "[polar]") {
    const Run g28 = run_lathe("O1\nG98 G0 X40 C0\nG112\nG28 U0\nG113\nM30\n");
    REQUIRE(g28.result.alarms.size() == 1);
    CHECK(g28.result.alarms[0].code == 146);
    CHECK(g28.result.alarms[0].source.line == 4);
    const Run cycle = run_lathe("O1\nG98 G0 X40 Z2 C0\nG112\nG83 Z-5 Q1000 F50\nG113\nM30\n");
    REQUIRE(cycle.result.alarms.size() == 1);
    CHECK(cycle.result.alarms[0].code == 146);
}

TEST_CASE("G112: near the centre the C axis would turn faster than its rate: said", "[polar]") {
    // The line x = 1 (X2) from y = −10 to y = 10 passes 1 mm from the centre: at F100 C would turn
    // 100/1·(180/π) = 5730 °/min, over a C rate of 3600 °/min. The line x = 10 (X20) passes 10 mm
    // away: 573 °/min, no message.
    const auto with_rate = [](Setup& s) { s.rapid_mm_min[C] = 3600; };
    const Run near = run_lathe("O1\nG98 G0 X20 C0\nG112\nG1 X2 C-10 F100\nC10\nG113\nM30\n", with_rate);
    require_clean(near);
    CHECK(has_message(near, "1.000 mm from the centre"));
    const Run far = run_lathe("O1\nG98 G0 X40 C0\nG112\nG1 X20 C-10 F100\nC10\nG113\nM30\n", with_rate);
    require_clean(far);
    CHECK_FALSE(has_message(far, "from the centre"));
}

TEST_CASE("G112: the chord tolerance is the machine's transform_tolerance", "[polar]") {
    const auto pieces = [](double tolerance) {
        const Run r = run_lathe(kSquare, [&](Setup& s) { s.transform_tolerance = tolerance; });
        return moves_on_line(r, 5).size();
    };
    CHECK(pieces(0.001) > pieces(0.01));
    CHECK(pieces(0.01) > pieces(0.1));
}

TEST_CASE("G107: cylindrical interpolation, C in mm of arc on the cylinder", "[polar]") {
    // cycles.md §19: G07.1 C30 = a cylinder of radius 30; C is then mm of arc: 47.1239 mm =
    // 47.1239/30 rad = 90°. A line of the unrolled plane is a line of Z/C: one piece.
    const double quarter = 30 * std::numbers::pi / 2;   // 47.1239
    const std::string text = "O1\nG98 G0 X60 Z0 C0\nG107 C30\nG1 Z-10 C47.1239 F100\nG2 Z-30 C47.1239 R10\nG107 C0\nG0 C0\nM30\n";
    const Run r = run_lathe(text);
    require_clean(r);
    CHECK(moves_on_line(r, 3).empty());   // G107 C30: C is the radius, not a move
    const auto line = moves_on_line(r, 4);
    REQUIRE(line.size() == 1);
    CHECK(line[0].end[Z] == Approx(-10));
    CHECK(line[0].end[C] == Approx(47.1239 / 30 * kDeg));
    CHECK(line[0].end[X] == Approx(60));
    // F along the unrolled path: √(10² + 47.1239²) = 48.1733 mm at 100 mm/min = 28.904 s.
    CHECK(line[0].time_s == Approx(std::hypot(10.0, 47.1239) / 100 * 60));
    // The semicircle of radius 10 about (Z−20, 47.1239 mm): every piece end on it; ends at Z−30
    // and the same C.
    const auto arc = moves_on_line(r, 5);
    REQUIRE(arc.size() > 4);
    for (const Event& e : arc) {
        const double s = e.end[C] / kDeg * 30;   // back to mm of arc
        CHECK(std::hypot(e.end[Z] + 20, s - quarter) == Approx(10).margin(1e-3));
    }
    CHECK(arc.back().end[Z] == Approx(-30));
    CHECK(arc.back().end[C] == Approx(90).margin(1e-3));
    // G107 C0 ends it: G0 C0 turns C back to 0° as an ordinary rapid.
    const auto back = moves_on_line(r, 7);
    REQUIRE(back.size() == 1);
    CHECK(back[0].end[C] == Approx(0));
    CHECK(back[0].start[C] == Approx(90).margin(1e-3));
}
