// Arcs through the interpreter (reference/semantics.md §3): G02/G03 in G17, G18 and G19 with R
// (R < 0 = more than 180° [FANUC mills]) and with I/J/K (vector from the start to the centre,
// incremental), full circles, helices (the third axis moves; F is the feed along the arc in the
// plane), the radius tolerance (alarm 020 beyond it), and lathe arcs with X as a diameter (the
// centre reported as a diameter like the end point).
//
// Frames (motion/vec.hpp): G17 (first X, second Y), G18 (first Z, second X), G19 (first Y,
// second Z); in every frame G03 is counter-clockwise, i.e. a positive angle from first toward
// second, seen from the positive end of the normal axis. Each centre below is derived by hand:
// for an R arc from S to E the centre lies on the perpendicular bisector of SE at distance
// h = √(R² − (|SE|/2)²) from the midpoint; of the two candidates, the one that makes the sweep in
// the commanded direction ≤ 180° is taken for R > 0, the other for R < 0.
//
// Setups are built by hand (zero offsets); mills run under G94 (F in mm/min).
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf;
using namespace kerf::test;

namespace {

constexpr double pi = std::numbers::pi;

// Runs use bare_setup (tests/interpreter/interpreter_fixture.hpp), fanuc-mill unless named.

// The one arc of a program that starts with `prelude` (positioning) and ends with M30.
Event one_arc(const std::string& prelude, const std::string& arc_block, const char* id = "fanuc-mill") {
    const Run r = run_bare("O1\n" + prelude + "\n" + arc_block + "\nM30\n", id);
    INFO(arc_block);
    require_clean(r);
    const auto a = arcs(r);
    REQUIRE(a.size() == 1);
    REQUIRE(a[0].center.has_value());
    return a[0];
}

void check_center(const Event& e, double x, double y, double z) {
    REQUIRE(e.center.has_value());
    CHECK((*e.center)[X] == Approx(x).margin(1e-9));
    CHECK((*e.center)[Y] == Approx(y).margin(1e-9));
    CHECK((*e.center)[Z] == Approx(z).margin(1e-9));
}

}  // namespace

// --- G17 -------------------------------------------------------------------------------------------

// From (0, 0) to (10, 10), R10: |SE| = 14.142, h = √(100 − 50) = 7.071, midpoint (5, 5):
// candidates (10, 0) and (0, 10).
//   centre (10, 0): S at 180°, E at 90° → CW −90° (G02, R > 0) or CCW +270° (G03, R < 0)
//   centre (0, 10): S at −90°, E at 0°  → CCW +90° (G03, R > 0) or CW −270° (G02, R < 0)
// Quarter: π·10/2 = 15.70796 mm, at F100: 0.1570796 min = 9.424778 s; three quarters: 47.12389 mm.
TEST_CASE("G17 arcs with R: both directions, R > 0 and R < 0", "[arcs]") {
    const std::string start = "G17 G90 G0 X0. Y0. Z0.";
    const Event cw = one_arc(start, "G02 X10. Y10. R10. F100.");
    CHECK(cw.kind == EventKind::arc_cw);
    check_center(cw, 10, 0, 0);
    CHECK(cw.radius == Approx(10));
    CHECK(cw.length_mm == Approx(15.7079633));
    CHECK(cw.time_s == Approx(9.4247780));
    CHECK(cw.end[X] == Approx(10));
    CHECK(cw.end[Y] == Approx(10));

    const Event ccw = one_arc(start, "G03 X10. Y10. R10. F100.");
    CHECK(ccw.kind == EventKind::arc_ccw);
    check_center(ccw, 0, 10, 0);
    CHECK(ccw.length_mm == Approx(15.7079633));

    const Event cw_major = one_arc(start, "G02 X10. Y10. R-10. F100.");
    check_center(cw_major, 0, 10, 0);
    CHECK(cw_major.length_mm == Approx(47.1238898));

    const Event ccw_major = one_arc(start, "G03 X10. Y10. R-10. F100.");
    check_center(ccw_major, 10, 0, 0);
    CHECK(ccw_major.length_mm == Approx(47.1238898));
}

// I/J: from (10, 0), G03 to (0, 10) with I−10 J0 → centre (0, 0), S at 0°, E at 90°, a CCW
// quarter of 15.70796 mm. I/J are incremental even under G90 (semantics.md §3).
TEST_CASE("G17 arc with I/J", "[arcs]") {
    const Event e = one_arc("G17 G90 G0 X10. Y0. Z0.", "G03 X0. Y10. I-10. J0. F100.");
    CHECK(e.kind == EventKind::arc_ccw);
    check_center(e, 0, 0, 0);
    CHECK(e.radius == Approx(10));
    CHECK(e.length_mm == Approx(15.7079633));
}

// End = start with I/J: a full circle, 2π·10 = 62.83185 mm, ending where it started.
//   G02 from (10, 0) to (10, 0) with I−10 → centre (0, 0).
TEST_CASE("G17 full circle with I/J", "[arcs]") {
    const Event cw = one_arc("G17 G90 G0 X10. Y0. Z0.", "G02 X10. Y0. I-10. J0. F100.");
    check_center(cw, 0, 0, 0);
    CHECK(cw.length_mm == Approx(62.8318531));
    CHECK(cw.end[X] == Approx(10));
    CHECK(cw.end[Y] == Approx(0).margin(1e-9));
}

// [FANUC] The end point words may be omitted: "G03 J10." alone is a full circle from the current
// point (end = start). From (0, −10) with J10 → centre (0, 0), 62.83185 mm, back at (0, −10).
TEST_CASE("G17 full circle without end point words", "[arcs]") {
    const Event ccw = one_arc("G17 G90 G0 X0. Y-10. Z0.", "G03 J10. F100.");
    check_center(ccw, 0, 0, 0);
    CHECK(ccw.length_mm == Approx(62.8318531));
    CHECK(ccw.end[Y] == Approx(-10));
}

// --- G18 (frame Z, X; seen from +Y) ----------------------------------------------------------------

// R: from (X0, Z0) to (X10, Z10): in the frame (Z, X) S = (0, 0), E = (10, 10), the same numbers as
// the G17 case, so G02 R10 has its centre at frame (10, 0) = Z10 X0, G03 R10 at frame (0, 10) =
// Z0 X10. Check of G02: seen from +Y with Z right and X up, S is left of the centre (180°), E
// above it (90°): 180° → 90° is clockwise.
// I/K: from (X10, Z0) with I−10 K0 → centre (0, 0, 0); frame S = (0, 10) at 90°, E = (X0, Z10) =
// frame (10, 0) at 0°: 90° → 0° is clockwise, G02.
TEST_CASE("G18 arcs with R and I/K", "[arcs]") {
    const Event cw = one_arc("G18 G90 G0 X0. Y0. Z0.", "G02 X10. Z10. R10. F100.");
    check_center(cw, 0, 0, 10);
    CHECK(cw.length_mm == Approx(15.7079633));
    const Event ccw = one_arc("G18 G90 G0 X0. Y0. Z0.", "G03 X10. Z10. R10. F100.");
    check_center(ccw, 10, 0, 0);
    const Event major = one_arc("G18 G90 G0 X0. Y0. Z0.", "G02 X10. Z10. R-10. F100.");
    check_center(major, 10, 0, 0);
    CHECK(major.length_mm == Approx(47.1238898));
    const Event ik = one_arc("G18 G90 G0 X10. Y0. Z0.", "G02 X0. Z10. I-10. K0. F100.");
    CHECK(ik.kind == EventKind::arc_cw);
    check_center(ik, 0, 0, 0);
    CHECK(ik.length_mm == Approx(15.7079633));
}

// --- G19 (frame Y, Z; seen from +X) ----------------------------------------------------------------

// R: from (Y0, Z0) to (Y10, Z10): G02 R10 → frame (10, 0) = Y10 Z0; G03 R10 → frame (0, 10) = Y0 Z10.
// J/K: from (Y10, Z0) with J−10 K0 → centre (0, 0, 0); frame S = (10, 0) at 0°, E = (Y0, Z10) =
// frame (0, 10) at 90°: counter-clockwise, G03.
TEST_CASE("G19 arcs with R and J/K", "[arcs]") {
    const Event cw = one_arc("G19 G90 G0 X0. Y0. Z0.", "G02 Y10. Z10. R10. F100.");
    check_center(cw, 0, 10, 0);
    CHECK(cw.length_mm == Approx(15.7079633));
    const Event ccw = one_arc("G19 G90 G0 X0. Y0. Z0.", "G03 Y10. Z10. R10. F100.");
    check_center(ccw, 0, 0, 10);
    const Event jk = one_arc("G19 G90 G0 X0. Y10. Z0.", "G03 Y0. Z10. J-10. K0. F100.");
    CHECK(jk.kind == EventKind::arc_ccw);
    check_center(jk, 0, 0, 0);
    CHECK(jk.length_mm == Approx(15.7079633));
}

// --- helices -----------------------------------------------------------------------------------------

// G17 G03 from (10, 0, 0) to (0, 10, −5) with I−10: a quarter in the plane (15.70796 mm) while Z
// falls 5 mm: path √(15.70796² + 5²) = 16.48454 mm. F is the feed along the arc in the plane
// (semantics.md §3, [FANUC] "the feedrate along the arc"), so time = 15.70796/100 min = 9.424778 s.
// A full turn (end = start in the plane) with Z −3: √(62.83185² + 3²) = 62.90343 mm.
// G18 with Y as the third axis: quarter in Z-X plus 5 in Y: 16.48454 mm.
TEST_CASE("helical arcs: the third axis moves", "[arcs]") {
    const Event q = one_arc("G17 G90 G0 X10. Y0. Z0.", "G03 X0. Y10. Z-5. I-10. J0. F100.");
    CHECK(q.center.has_value());
    CHECK((*q.center)[X] == Approx(0).margin(1e-9));
    CHECK((*q.center)[Y] == Approx(0).margin(1e-9));
    CHECK(q.end[Z] == Approx(-5));
    CHECK(q.radius == Approx(10));
    CHECK(q.length_mm == Approx(16.4845415));
    CHECK(q.time_s == Approx(9.4247780));

    const Event turn = one_arc("G17 G90 G0 X10. Y0. Z0.", "G02 X10. Y0. Z-3. I-10. F100.");
    CHECK(turn.end[Z] == Approx(-3));
    CHECK(turn.length_mm == Approx(62.9034320));

    const Event g18 = one_arc("G18 G90 G0 X10. Y0. Z0.", "G02 X0. Y5. Z10. I-10. K0. F100.");
    CHECK(g18.end[Y] == Approx(5));
    CHECK(g18.length_mm == Approx(16.4845415));
}

// --- radius checks -------------------------------------------------------------------------------------

// I/J: from (0, 0) to (10, 0).
//   I5.004 → centre (5.004, 0): start radius 5.004, end radius 4.996, difference 0.008 ≤ 0.01 (the
//   tolerance, motion/arc.hpp): no alarm.
//   I5.01  → 5.01 vs 4.99, difference 0.02 > 0.01: FANUC alarm 020, the move is not made.
TEST_CASE("I/J radius mismatch: within the tolerance runs, beyond it is alarm 020", "[arcs]") {
    const Event ok = one_arc("G17 G90 G0 X0. Y0.", "G02 X10. Y0. I5.004 J0. F100.");
    CHECK(ok.end[X] == Approx(10));
    const Run bad = run_bare("O1\nG17 G90 G0 X0. Y0.\nG02 X10. Y0. I5.01 J0. F100.\nM30\n");
    INFO(alarm_list(bad));
    REQUIRE(bad.result.alarms.size() == 1);
    CHECK(bad.result.alarms[0].code == 20);
    CHECK(arcs(bad).empty());
    CHECK_FALSE(bad.result.completed);
}

// R: a chord of exactly 2R is a semicircle (centre the midpoint): (0, 0) → (20, 0) R10, centre
// (10, 0), π·10 = 31.41593 mm. A chord within the tolerance above 2R is accepted as a semicircle
// (semantics.md §3 "accept chord = 2R within tolerance"): X20.005 → half chord 10.0025 ≤ 10.01.
// A chord far above 2R (30 > 20) is an alarm ([FANUC], semantics.md §3) and no arc is made.
TEST_CASE("R arcs: semicircle, chord within tolerance, R too small", "[arcs]") {
    const Event semi = one_arc("G17 G90 G0 X0. Y0.", "G02 X20. Y0. R10. F100.");
    check_center(semi, 10, 0, 0);
    CHECK(semi.length_mm == Approx(31.4159265));
    const Event near = one_arc("G17 G90 G0 X0. Y0.", "G02 X20.005 Y0. R10. F100.");
    CHECK(near.end[X] == Approx(20.005));
    const Run bad = run_bare("O1\nG17 G90 G0 X0. Y0.\nG02 X30. Y0. R10. F100.\nM30\n");
    CHECK_FALSE(bad.result.alarms.empty());
    CHECK(arcs(bad).empty());
    CHECK_FALSE(bad.result.completed);
}

// --- lathe arcs (G18, X diameter, I/K radius values; dialects.md §3.3) -----------------------------------

// semantics.md §3's own example, O0004: N60 G1 Z-22 at Ø30, N70 G2 X40 Z-27 R5 "the concave R5
// fillet into the shoulder, centre at X40 (r 20) Z−22". In radius geometry S = (x15, z−22),
// E = (x20, z−27), centre (x20, z−22): S below the centre, E left of it (Z right, X up): clockwise.
// The centre is reported as a diameter like the end: X40 Z−22. Length π·5/2 = 7.85398 mm; under
// G98 F100 (mm/min): 7.85398/100 min = 4.712389 s.
TEST_CASE("lathe: the O0004 fillet, centre as a diameter", "[arcs]") {
    const Run r = run_bare("O0004\nG0 X30. Z0.\nG98 G1 Z-22. F100.\nG2 X40. Z-27. R5.\nM30\n", "fanuc-lathe-a");
    require_clean(r);
    const auto a = arcs(r);
    REQUIRE(a.size() == 1);
    CHECK(a[0].kind == EventKind::arc_cw);
    check_center(a[0], 40, 0, -22);
    CHECK(a[0].radius == Approx(5));
    CHECK(a[0].end[X] == Approx(40));
    CHECK(a[0].end[Z] == Approx(-27));
    CHECK(a[0].length_mm == Approx(7.8539816));
    CHECK(a[0].time_s == Approx(4.7123890));
}

// From X20 Z0 (radius x10) to X40 Z−10 (x20):
//   G02 with I10 K0: centre = start + (x 10, z 0) = (x20, z0) → reported X40 Z0; in the frame (Z, X)
//   S is at −90° and E at 180° about it: clockwise, a quarter of radius 10 (15.70796 mm). The R10
//   form G02 X40. Z-10. R10. has the same centre.
//   G03 with I0 K−10: centre (x10, z−10) → reported X20 Z−10; S at 0°, E at 90°: counter-clockwise.
TEST_CASE("lathe: I/K and R arcs with diameter X", "[arcs]") {
    const Event ik = one_arc("G0 X20. Z0.", "G98 G02 X40. Z-10. I10. K0. F100.", "fanuc-lathe-a");
    check_center(ik, 40, 0, 0);
    CHECK(ik.radius == Approx(10));
    CHECK(ik.length_mm == Approx(15.7079633));
    const Event r = one_arc("G0 X20. Z0.", "G98 G02 X40. Z-10. R10. F100.", "fanuc-lathe-a");
    check_center(r, 40, 0, 0);
    const Event ccw = one_arc("G0 X20. Z0.", "G98 G03 X40. Z-10. I0. K-10. F100.", "fanuc-lathe-a");
    CHECK(ccw.kind == EventKind::arc_ccw);
    check_center(ccw, 20, 0, -10);
    CHECK(ccw.length_mm == Approx(15.7079633));
}

// A lathe semicircle with chord = 2R along Z (semantics.md §3: SPINNER writes such arcs): X40 Z0 →
// X40 Z−30 with R15: centre the midpoint (x20, z−15) → reported X40 Z−15; π·15 = 47.12389 mm.
TEST_CASE("lathe: semicircle with chord 2R", "[arcs]") {
    const Event e = one_arc("G0 X40. Z0.", "G98 G03 X40. Z-30. R15. F100.", "fanuc-lathe-a");
    check_center(e, 40, 0, -15);
    CHECK(e.length_mm == Approx(47.1238898));
}
