// G41/G42 inside G112 polar interpolation (reference/cycles.md §18 "Tool-radius compensation is
// computed in the Cartesian plane"; semantics.md §5 "In G112 mode the compensation works in the
// Cartesian plane with the cutter radius", the seed's "R → 4, T → 9"): interpreter/
// polar_compensation.cpp. fanuc-lathe-a, bare setup, calculator-type decimal input (X40 = 40 mm),
// G98. Tool 1: nose radius 2 mm, tip 9 (the cutter's centre is the controlled point).
//
// The plane (cycles.md §18): x = X/2, y = C in mm; a machine point (X_dia, C°) is the plane point
// (X/2·cos C, X/2·sin C). Every piece of a block ends on the block's offset path (pieces are
// straight in X/C, their ends lie on the Cartesian path), so each piece's plane point is checked.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "tests/interpreter/polar_plane.hpp"

using namespace kerf;
using namespace kerf::test;

namespace {

Run run_polar(const std::string& text, double radius) {
    return run_bare(text, "fanuc-lathe-a", [&](Setup& s) {
        s.calculator_decimal = true;
        s.tools[1].nose_radius = radius;
        s.tools[1].tip = 9;
    });
}

// The last piece of a block ends on the plane point (x, y).
void check_plane_end(const std::vector<Event>& m, double x, double y) {
    REQUIRE(!m.empty());
    CHECK(plane_x(m.back()) == Approx(x).margin(0.001));
    CHECK(plane_y(m.back()) == Approx(y).margin(0.001));
}

bool has_alarm(const Run& r, int number) {
    for (const Event& e : r.events)
        if (e.kind == EventKind::alarm && e.code == number) return true;
    return false;
}

bool has_text(const Run& r, const std::string& part) {
    for (const Event& e : r.events)
        if (e.text.find(part) != std::string::npos) return true;
    return false;
}

// A 20 × 20 square about the centre, programmed counter-clockwise from (10, −30) up the side x = 10
// (C before G112 is degrees of the real axis; inside the mode it is the virtual axis in mm).
// Under G42 (tool right of the path) the tool is outside: each side's offset line lies 2 mm out.
//   line 5 start-up along +y (10,−30)→(10,−10), the next side goes on straight: ends (12, −10)
//   line 6 (10,−10)→(10,10), x = 12; outside corner of 90° with the next side: the offset lines
//          meet at (12, 12) (compensation C: intersection, semantics.md §6)
//   line 7 (10,10)→(−10,10), y = 12, to (−12, 12)
//   line 8 (−10,10)→(−10,−10), x = −12, to (−12, −12)
//   line 9 (−10,−10)→(10,−10), y = −12, to (12, −12)
//   line 10 (10,−10)→(10,0), x = 12; the next block cancels along +x, an inside corner for the
//          tool on the right: the element ends perpendicular, at (12, 0) (a cancel at an inside
//          corner, like the start-up, has no offset of its own to meet: radius_compensation.cpp)
//   line 11 G40 to (20, 0): the tool ends on the programmed point.
const char* kSquareG42 =
    "O1\n"                   // 1
    "T0101 G98 G0 X20 C0\n"  // 2  C0 before G112: the plane's start point is (10, 0)
    "G112\n"                 // 3
    "G0 C-30\n"              // 4  (10, −30)
    "G1 G42 C-10 F100\n"     // 5
    "C10\n"                  // 6
    "X-20\n"                 // 7
    "C-10\n"                 // 8
    "X20\n"                  // 9
    "C0\n"                   // 10
    "G40 X40\n"              // 11
    "G113\n"                 // 12
    "M30\n";

}  // namespace

TEST_CASE("G112 with G42: the square's tool path is offset outside by the cutter radius", "[polar][compensation]") {
    const Run r = run_polar(kSquareG42, 2);
    require_clean(r);
    CHECK_FALSE(has_text(r, "not applied"));
    const struct {
        std::uint32_t line;
        double end_x, end_y;
        char fixed;      // the offset line the pieces lie on: 'x' = end_x, 'y' = end_y
        double value;
    } sides[] = {
        {5, 12, -10, 'x', 12},  {6, 12, 12, 'x', 12},   {7, -12, 12, 'y', 12},
        {8, -12, -12, 'x', -12}, {9, 12, -12, 'y', -12}, {10, 12, 0, 'x', 12},
    };
    for (const auto& side : sides) {
        INFO("line " << side.line);
        const auto m = moves_on_line(r, side.line);
        REQUIRE(!m.empty());
        // The start-up (line 5) first reaches the offset line; the other sides run on it.
        for (std::size_t i = side.line == 5 ? m.size() - 1 : 0; i < m.size(); ++i) {
            INFO("piece " << i);
            CHECK((side.fixed == 'x' ? plane_x(m[i]) : plane_y(m[i])) == Approx(side.value).margin(0.001));
        }
        check_plane_end(m, side.end_x, side.end_y);
    }
    // The cancel ends on the programmed point X40 C0: (20, 0).
    const auto cancel = moves_on_line(r, 11);
    REQUIRE(!cancel.empty());
    CHECK(cancel.back().end[X] == Approx(40).margin(0.001));
    CHECK(std::remainder(cancel.back().end[C], 360.0) == Approx(0).margin(0.001));
    // G113 then runs the ordinary modes again from the real X/C.
    CHECK(moves_on_line(r, 12).empty());
}

TEST_CASE("G112 with G42 and a zero radius runs the programmed square", "[polar][compensation]") {
    const Run r = run_polar(kSquareG42, 0);
    require_clean(r);
    const double corners[][3] = {{5, 10, -10}, {6, 10, 10}, {7, -10, 10}, {8, -10, -10}, {9, 10, -10}, {10, 10, 0}};
    for (const auto& [line, x, y] : corners) {
        INFO("line " << line);
        check_plane_end(moves_on_line(r, static_cast<std::uint32_t>(line)), x, y);
    }
}

// An arc under G41 (tool left): counter-clockwise about the centre the left side is the inside.
//   line 5 start-up along +y (20,−20)→(20,0), left of +y is −x: the tool ends at (18, 0), where the
//          arc's offset begins (the arc leaves tangent to the line)
//   line 6 G3 (20,0)→(−20,0) R20 about (0,0): the tool's arc has radius 20 − 2 = 18, to (−18, 0);
//          C turns from 0° to 180°
//   line 7 G1 down (−20,0)→(−20,−20), tangent; left of −y is +x: every piece on x = −18
//   line 8 G40 X-60: the cancel ends on the programmed point (−30, −20).
TEST_CASE("G112 with G41 on an arc: the tool's arc is the programmed one less the radius", "[polar][compensation]") {
    const Run r = run_polar("O1\nT0101 G98 G0 X40 C0\nG112\nG0 C-20\nG1 G41 C0 F100\nG3 X-40 C0 R20\nG1 C-20\n"
                            "G40 X-60\nG113\nM30\n",
                            2);
    require_clean(r);
    check_plane_end(moves_on_line(r, 5), 18, 0);
    const auto arc = moves_on_line(r, 6);
    REQUIRE(arc.size() >= 4);   // no polar piece turns more than 45° (motion/polar.hpp)
    for (const Event& e : arc) CHECK(std::hypot(plane_x(e), plane_y(e)) == Approx(18).margin(0.001));
    check_plane_end(arc, -18, 0);
    CHECK(arc.back().end[C] == Approx(180).margin(0.001));
    const auto down = moves_on_line(r, 7);
    REQUIRE(!down.empty());
    for (const Event& e : down) CHECK(plane_x(e) == Approx(-18).margin(0.001));
    check_plane_end(moves_on_line(r, 8), -30, -20);
}

TEST_CASE("G112 or G113 while the compensation holds an offset is alarm 145", "[polar][compensation]") {
    // G113 without G40 first (every seed program cancels before G113, cycles.md §18).
    const Run off = run_polar("O1\nT0101 G98 G0 X20 C0\nG112\nG0 C-30\nG1 G42 C-10 F100\nC10\nG113\nM30\n", 2);
    CHECK(has_alarm(off, 145));
    // G112 while a compensated contour is on in the ordinary plane (a lathe's G18).
    const Run on = run_polar("O1\nT0101 G98 G0 X40 Z5\nG1 G42 Z0 F100\nX60\nG112\nG1 X80 C10\nM30\n", 2);
    CHECK(has_alarm(on, 145));
}

TEST_CASE("G112 with G42: a block with only Z keeps the offset", "[polar][compensation]") {
    // Line 6 plunges Z only: the tool stays at (12, −10) of the start-up and the next side goes on.
    const Run r = run_polar("O1\nT0101 G98 G0 X20 C0 Z5\nG112\nG0 C-30\nG1 G42 C-10 F100\nZ-2\nC10\nX-20\n"
                            "G40 X-20 C40\nG113\nM30\n",
                            2);
    require_clean(r);
    const auto plunge = moves_on_line(r, 6);
    REQUIRE(plunge.size() == 1);
    CHECK(plunge[0].end[Z] == Approx(-2));
    check_plane_end(plunge, 12, -10);
    check_plane_end(moves_on_line(r, 7), 12, 12);
}
