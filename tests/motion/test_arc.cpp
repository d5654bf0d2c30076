// Arcs and helices (semantics.md §3): R and I/J/K forms in G17/G18/G19, CW and CCW, full circles,
// helix length, radius tolerance, errors, exact bounds. Every expected number is derived in a
// comment; s = 10/√2 = 7.0710678 and 10 − s = 2.9289322 recur.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <limits>
#include <numbers>

#include "motion/arc.hpp"

using namespace kerf::motion;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double s = 7.0710678118654755;   // 10·cos 45°

Arc need(const ArcResult& r) {
    REQUIRE(r.ok());
    return r.arc();
}

void check_point(Vec3 p, Vec3 expected) {
    CHECK(p.x == Approx(expected.x).margin(1e-9));
    CHECK(p.y == Approx(expected.y).margin(1e-9));
    CHECK(p.z == Approx(expected.z).margin(1e-9));
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// R form

// G17, from (0,0) to (10,10), |R| = 10: chord √200 = 14.142, half 7.071, h = √(100 − 50) = 7.071;
// the two candidate centres are (10,0) and (0,10).
//   G02 R10 : CW ≤ 180°, centre right of the chord → (10,0); start at 180°, end at 90° → −π/2
//   G02 R−10: the other centre (0,10); start at −90°, end at 0°, CW → −3π/2
//   G03 R10 : centre left of the chord → (0,10); CCW from −90° to 0° → +π/2
//   G03 R−10: centre (10,0); CCW from 180° to 90° → +3π/2
TEST_CASE("arc R form, G17: the four combinations of sign and direction") {
    const Vec3 a{0, 0, 0};
    const Vec3 b{10, 10, 0};
    const Arc cw_minor = need(arc_from_radius(a, b, Plane::xy, ArcDirection::cw, 10.0));
    check_point(cw_minor.center, {10, 0, 0});
    CHECK(cw_minor.sweep == Approx(-pi / 2));
    CHECK(cw_minor.cw);
    CHECK(cw_minor.radius == Approx(10.0));
    // Midpoint at 180° − 45° = 135° about (10,0): (10 − s, s).
    check_point(point_at(cw_minor, 0.5), {10 - s, s, 0});
    // Length 10·π/2 = 15.7079633
    CHECK(length(cw_minor) == Approx(15.7079633));

    const Arc cw_major = need(arc_from_radius(a, b, Plane::xy, ArcDirection::cw, -10.0));
    check_point(cw_major.center, {0, 10, 0});
    CHECK(cw_major.sweep == Approx(-3 * pi / 2));
    // Length 10·3π/2 = 47.1238898
    CHECK(length(cw_major) == Approx(47.1238898));

    const Arc ccw_minor = need(arc_from_radius(a, b, Plane::xy, ArcDirection::ccw, 10.0));
    check_point(ccw_minor.center, {0, 10, 0});
    CHECK(ccw_minor.sweep == Approx(pi / 2));
    CHECK_FALSE(ccw_minor.cw);
    // Midpoint at −90° + 45° = −45° about (0,10): (s, 10 − s).
    check_point(point_at(ccw_minor, 0.5), {s, 10 - s, 0});

    const Arc ccw_major = need(arc_from_radius(a, b, Plane::xy, ArcDirection::ccw, -10.0));
    check_point(ccw_major.center, {10, 0, 0});
    CHECK(ccw_major.sweep == Approx(3 * pi / 2));
    // Midpoint at 180° + 135° = 315° about (10,0): (10 + s, −s).
    check_point(point_at(ccw_major, 0.5), {10 + s, -s, 0});
}

// semantics.md §3: SPINNER O0004 `N60 G1 Z-22` (Ø30) / `N70 G2 X40 Z-27 R5` is the concave R5
// fillet with its centre at X40 (r 20) Z−22. In radius coordinates: start (x15, z−22), end
// (x20, z−27). Frame (Z, X): start (−22, 15), end (−27, 20), centre (−22, 20): start at −90°,
// end at 180°; CW from −90° to −180° = −π/2.
TEST_CASE("arc R form, G18: the SPINNER R5 fillet into the shoulder (O0004 N70)") {
    const Arc fillet = need(arc_from_radius({15, 0, -22}, {20, 0, -27}, Plane::zx, ArcDirection::cw, 5.0));
    check_point(fillet.center, {20, 0, -22});
    CHECK(fillet.sweep == Approx(-pi / 2));
    // Midpoint at −135° about the centre: z = −22 + 5·cos(−135°) = −25.5355339,
    // x = 20 + 5·sin(−135°) = 16.4644661 (inside the corner: concave fillet).
    check_point(point_at(fillet, 0.5), {16.4644661, 0, -25.5355339});
    // Negative R takes the other centre, the mirror of (−22, 20) in the chord midpoint
    // (−24.5, 17.5): (−27, 15) in the frame, i.e. x15 z−27. Start rel centre (5, 0) → 0°, end rel
    // (0, 5) → 90°; CW from 0° to 90° the long way → −270°.
    const Arc major = need(arc_from_radius({15, 0, -22}, {20, 0, -27}, Plane::zx, ArcDirection::cw, -5.0));
    check_point(major.center, {15, 0, -27});
    CHECK(major.sweep == Approx(-3 * pi / 2));
}

// G19 frame (Y, Z): from (y0, z0) to (y10, z10) is the same frame picture as the G17 case above.
//   G03 R10 → centre (0,10) in the frame = world (x0, y0, z10), +π/2
//   G02 R−10 → the same centre, −3π/2
TEST_CASE("arc R form, G19") {
    const Arc ccw = need(arc_from_radius({0, 0, 0}, {0, 10, 10}, Plane::yz, ArcDirection::ccw, 10.0));
    check_point(ccw.center, {0, 0, 10});
    CHECK(ccw.sweep == Approx(pi / 2));
    // Midpoint at −45° in the frame about (0,10): y = s, z = 10 − s.
    check_point(point_at(ccw, 0.5), {0, s, 10 - s});
    const Arc cw = need(arc_from_radius({0, 0, 0}, {0, 10, 10}, Plane::yz, ArcDirection::cw, -10.0));
    check_point(cw.center, {0, 0, 10});
    CHECK(cw.sweep == Approx(-3 * pi / 2));
}

// Chord = 2R exactly: (0,0) → (20,0) R10 is a semicircle about (10,0). CCW from 180° by +180°:
// the midpoint is at 270°, (10, −10); CW: at 90°, (10, 10).
TEST_CASE("arc R form: semicircle, exact and within the tolerance") {
    const Arc ccw = need(arc_from_radius({0, 0, 0}, {20, 0, 0}, Plane::xy, ArcDirection::ccw, 10.0));
    check_point(ccw.center, {10, 0, 0});
    CHECK(ccw.sweep == Approx(pi));
    check_point(point_at(ccw, 0.5), {10, -10, 0});
    const Arc cw = need(arc_from_radius({0, 0, 0}, {20, 0, 0}, Plane::xy, ArcDirection::cw, 10.0));
    CHECK(cw.sweep == Approx(-pi));
    check_point(point_at(cw, 0.5), {10, 10, 0});
    // semantics.md §3 "accept chord = 2R within tolerance": (0,0) → (20.01,0) R10: half chord
    // 10.005 ≤ 10 + 0.01. Centre at the chord midpoint (10.005, 0), radius 10.005, sweep −π,
    // midpoint (10.005, 10.005).
    const Arc near = need(arc_from_radius({0, 0, 0}, {20.01, 0, 0}, Plane::xy, ArcDirection::cw, 10.0));
    check_point(near.center, {10.005, 0, 0});
    CHECK(near.radius == Approx(10.005));
    CHECK(near.sweep == Approx(-pi));
    check_point(point_at(near, 0.5), {10.005, 10.005, 0});
}

// (0,0) → (30,0) with R10: half chord 15 > 10 + 0.01 → error (found 15, allowed 10.01).
// With enlarge_small_r (some models, §3): R becomes 15, a semicircle about (15, 0).
TEST_CASE("arc R form: R too small for the chord") {
    const ArcResult r = arc_from_radius({0, 0, 0}, {30, 0, 0}, Plane::xy, ArcDirection::cw, 10.0);
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().code == ArcErrorCode::r_too_small);
    CHECK(r.error().fanuc_alarm == 20);
    CHECK(r.error().found == Approx(15.0));
    CHECK(r.error().allowed == Approx(10.01));
    ArcOptions enlarge;
    enlarge.enlarge_small_r = true;
    const Arc big = need(arc_from_radius({0, 0, 0}, {30, 0, 0}, Plane::xy, ArcDirection::cw, 10.0, enlarge));
    check_point(big.center, {15, 0, 0});
    CHECK(big.radius == Approx(15.0));
    CHECK(big.sweep == Approx(-pi));
}

TEST_CASE("arc R form: zero R, zero chord, negative R switched off, non-finite input") {
    const ArcResult zero = arc_from_radius({0, 0, 0}, {10, 0, 0}, Plane::xy, ArcDirection::cw, 0.0);
    REQUIRE_FALSE(zero.ok());
    CHECK(zero.error().code == ArcErrorCode::zero_radius);
    // R cannot describe a full circle (§3); FANUC runs a 0° arc.
    const ArcResult chord = arc_from_radius({5, 5, 0}, {5, 5, 0}, Plane::xy, ArcDirection::cw, 10.0);
    REQUIRE_FALSE(chord.ok());
    CHECK(chord.error().code == ArcErrorCode::r_zero_chord);
    ArcOptions lathe;
    lathe.allow_negative_r = false;
    const ArcResult neg = arc_from_radius({0, 0, 0}, {10, 10, 0}, Plane::xy, ArcDirection::cw, -10.0, lathe);
    REQUIRE_FALSE(neg.ok());
    CHECK(neg.error().code == ArcErrorCode::negative_r_unsupported);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const ArcResult bad = arc_from_radius({0, 0, 0}, {10, nan, 0}, Plane::xy, ArcDirection::cw, 10.0);
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error().code == ArcErrorCode::invalid_input);
    CHECK(std::string(describe(ArcErrorCode::radius_mismatch)).size() > 0);
}

// ---------------------------------------------------------------------------------------------
// I/J/K form

// G17: (0,0) → (20,0) with I10 J0: centre (10,0), semicircle. G03: 180° → 360°(0°) CCW = +π,
// through (10, −10); G02: −π through (10, 10).
TEST_CASE("arc I/J/K form, G17, CW and CCW") {
    const Arc ccw = need(arc_from_center({0, 0, 0}, {20, 0, 0}, Plane::xy, ArcDirection::ccw, {10, 0, 0}));
    check_point(ccw.center, {10, 0, 0});
    CHECK(ccw.sweep == Approx(pi));
    check_point(point_at(ccw, 0.5), {10, -10, 0});
    const Arc cw = need(arc_from_center({0, 0, 0}, {20, 0, 0}, Plane::xy, ArcDirection::cw, {10, 0, 0}));
    CHECK(cw.sweep == Approx(-pi));
    check_point(point_at(cw, 0.5), {10, 10, 0});
    // A K word in G17 is not a centre word: it does not move the centre.
    const Arc with_k = need(arc_from_center({0, 0, 0}, {20, 0, 0}, Plane::xy, ArcDirection::cw, {10, 0, 99}));
    check_point(with_k.center, {10, 0, 0});
}

// Reference example 000_lathe_G03_IK (adv400-lathe): G18, from X0 Z.1, `G03 I1 K1 X2`: centre
// x 0+1 = 1, z 0.1+1 = 1.1; r_start = √(1² + 1²) = 1.4142136, r_end = √((2−1)² + (0.1−1.1)²) =
// 1.4142136 (consistent). Frame (Z, X): start rel (−1, −1) at −135°, end rel (−1, +1) at +135°;
// CCW from −135° to +135° = +270° = 3π/2. Length 1.4142136·3π/2 = 6.6643244.
TEST_CASE("arc I/J/K form, G18: reference example 000_lathe_G03_IK") {
    const Arc arc = need(arc_from_center({0, 0, 0.1}, {2, 0, 0.1}, Plane::zx, ArcDirection::ccw, {1, 0, 1}));
    check_point(arc.center, {1, 0, 1.1});
    CHECK(arc.radius == Approx(1.4142136));
    CHECK(arc.sweep == Approx(3 * pi / 2));
    CHECK(length(arc) == Approx(6.6643244));
    // G02 with the same words: CW from −135° to −225° = −π/2, the short way through z = 1.1 − 1.414.
    const Arc cw = need(arc_from_center({0, 0, 0.1}, {2, 0, 0.1}, Plane::zx, ArcDirection::cw, {1, 0, 1}));
    CHECK(cw.sweep == Approx(-pi / 2));
    check_point(point_at(cw, 0.5), {1, 0, 1.1 - 1.4142136});
}

// G19: (y10, z0) → (y0, z10) with J−10 K0: centre at the origin. Frame (Y, Z): start at 0°, end
// at 90°: G03 +π/2 through (y s, z s); G02 −3π/2 through 0° − 135° = −135°: (y −s, z −s).
TEST_CASE("arc I/J/K form, G19, CW and CCW") {
    const Arc ccw = need(arc_from_center({0, 10, 0}, {0, 0, 10}, Plane::yz, ArcDirection::ccw, {0, -10, 0}));
    check_point(ccw.center, {0, 0, 0});
    CHECK(ccw.sweep == Approx(pi / 2));
    check_point(point_at(ccw, 0.5), {0, s, s});
    const Arc cw = need(arc_from_center({0, 10, 0}, {0, 0, 10}, Plane::yz, ArcDirection::cw, {0, -10, 0}));
    CHECK(cw.sweep == Approx(-3 * pi / 2));
    check_point(point_at(cw, 0.5), {0, -s, -s});
}

// G17 G02 I10 from (0,0) back to (0,0): full circle about (10,0), sweep −2π, length 20π =
// 62.8318531, box x [0, 20], y [−10, 10]. A quarter of the way (t = 0.25) CW from 180° is 90°:
// (10, 10).
TEST_CASE("arc: full circle with I/J/K") {
    const Arc full = need(arc_from_center({0, 0, 0}, {0, 0, 0}, Plane::xy, ArcDirection::cw, {10, 0, 0}));
    CHECK(is_full_circle(full));
    CHECK(full.sweep == Approx(-2 * pi));
    CHECK(length(full) == Approx(62.8318531));
    check_point(point_at(full, 0.25), {10, 10, 0});
    check_point(point_at(full, 1.0), {0, 0, 0});
    const Box box = bounds(full);
    check_point(box.min, {0, -10, 0});
    check_point(box.max, {20, 10, 0});
    const Arc ccw = need(arc_from_center({0, 0, 0}, {0, 0, 0}, Plane::xy, ArcDirection::ccw, {10, 0, 0}));
    CHECK(ccw.sweep == Approx(2 * pi));
    check_point(point_at(ccw, 0.25), {10, -10, 0});
}

// Helix: G17 G03 from (10,0,0) with I−10 to (10,0,−5): a full turn down 5 mm. Planar length
// 2π·10 = 62.8318531; length √(62.8318531² + 5²) = √(3947.8418 + 25) = 63.0304828. Halfway: angle
// 180° → (−10, 0), z −2.5.
TEST_CASE("arc: helix, full turn and quarter turn") {
    const Arc helix = need(arc_from_center({10, 0, 0}, {10, 0, -5}, Plane::xy, ArcDirection::ccw, {-10, 0, 0}));
    CHECK(helix.helix_length == Approx(-5.0));
    CHECK(planar_length(helix) == Approx(62.8318531));
    CHECK(length(helix) == Approx(63.0304828));
    // F is along the arc in the plane (§3): the feed length is the planar 62.8318531.
    CHECK(feed_length(helix) == Approx(62.8318531));
    check_point(point_at(helix, 0.5), {-10, 0, -2.5});
    CHECK(bounds(helix).min.z == Approx(-5.0));
    CHECK(bounds(helix).max.z == Approx(0.0));
    // The unit tangent rises at the helix angle: its z component is −5/63.0304828 = −0.0793267.
    CHECK(tangent_at(helix, 0.3).z == Approx(-0.0793267));
    // G18 quarter (the G02 X0 Z10 of test_vec) with 4 mm along Y: planar 10·π/2 = 15.7079633,
    // length √(15.7079633² + 4²) = 16.2092600.
    const Arc quarter = need(arc_from_center({10, 0, 0}, {0, 4, 10}, Plane::zx, ArcDirection::cw, {-10, 0, 0}));
    CHECK(quarter.helix_length == Approx(4.0));
    CHECK(length(quarter) == Approx(16.2092600));
    check_point(point_at(quarter, 0.5), {s, 2, s});
}

// ---------------------------------------------------------------------------------------------
// Radius tolerance (FANUC alarm 020)

// G17 G02 from (0,0) with I10 J0 (centre (10,0), r_start 10):
//   end (20.02, 0): r_end 10.02, |Δr| = 0.02 > 0.01 → radius_mismatch
//   end (19.995, 0.1): r_end = √(9.995² + 0.1²) = √99.910025 = 9.9955002, |Δr| = 0.0044998 < 0.01
//   → accepted; the arc is a spiral from r 10 to r 9.9955 ending exactly at the end point;
//   sweep: CW from 180° to atan2(0.1, 9.995) = 0.0100047 rad → −(π − 0.0100047) = −3.1315880.
TEST_CASE("arc: radius mismatch detected beyond the tolerance, tolerated below it") {
    const ArcResult bad = arc_from_center({0, 0, 0}, {20.02, 0, 0}, Plane::xy, ArcDirection::cw, {10, 0, 0});
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error().code == ArcErrorCode::radius_mismatch);
    CHECK(bad.error().fanuc_alarm == 20);
    CHECK(bad.error().found == Approx(0.02));
    CHECK(bad.error().allowed == Approx(0.01));

    const Arc ok = need(arc_from_center({0, 0, 0}, {19.995, 0.1, 0}, Plane::xy, ArcDirection::cw, {10, 0, 0}));
    CHECK(ok.radius == Approx(10.0));
    CHECK(ok.end_radius == Approx(9.9955002));
    CHECK(ok.sweep == Approx(-3.1315880));
    check_point(point_at(ok, 1.0), {19.995, 0.1, 0});
    check_point(point_at(ok, 1.0 - 1e-12), {19.995, 0.1, 0});
    // Length: 3.1315880·(10 + 9.9955002)/2 = 31.3088344
    CHECK(length(ok) == Approx(31.3088344));

    // A tighter tolerance (parameter) rejects the same arc.
    ArcOptions strict;
    strict.radius_tolerance = 0.001;
    const ArcResult rejected =
        arc_from_center({0, 0, 0}, {19.995, 0.1, 0}, Plane::xy, ArcDirection::cw, {10, 0, 0}, strict);
    REQUIRE_FALSE(rejected.ok());
    CHECK(rejected.error().code == ArcErrorCode::radius_mismatch);
    CHECK(rejected.error().found == Approx(0.0044998));
}

// Reference example 000_mill_G03_IJ_invalid_arc: from X0 Y1.0156 `G03 I1 J1 Y0 X2`: centre
// (1, 2.0156); r_start = √2 = 1.4142136, r_end = √(1² + 2.0156²) = 2.2500319; |Δr| = 0.8358183.
TEST_CASE("arc: reference example 000_mill_G03_IJ_invalid_arc raises the end-point error") {
    const ArcResult r = arc_from_center({0, 1.0156, 0.1}, {2, 0, 0.1}, Plane::xy, ArcDirection::ccw, {1, 1, 0});
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().code == ArcErrorCode::radius_mismatch);
    CHECK(r.error().found == Approx(0.8358183));
}

// I0 J0: start = end → zero radius; start ≠ end → the end is 10 from the centre, 0 at the start:
// a mismatch of 10.
TEST_CASE("arc: zero radius with I/J/K") {
    const ArcResult same = arc_from_center({5, 5, 0}, {5, 5, 0}, Plane::xy, ArcDirection::cw, {0, 0, 0});
    REQUIRE_FALSE(same.ok());
    CHECK(same.error().code == ArcErrorCode::zero_radius);
    const ArcResult apart = arc_from_center({5, 5, 0}, {15, 5, 0}, Plane::xy, ArcDirection::cw, {0, 0, 0});
    REQUIRE_FALSE(apart.ok());
    CHECK(apart.error().code == ArcErrorCode::radius_mismatch);
    CHECK(apart.error().found == Approx(10.0));
}

// ---------------------------------------------------------------------------------------------
// Exact bounds: the end points plus the quadrant points the sweep passes. Circle r 10 about
// (100, 50); points at 45° (100+s, 50+s), 135° (100−s, 50+s), 315° (100+s, 50−s).
TEST_CASE("arc bounds through quadrants") {
    const Vec3 c{100, 50, 0};
    const Vec3 p45 = c + Vec3{s, s, 0};
    const Vec3 p135 = c + Vec3{-s, s, 0};
    const Vec3 p315 = c + Vec3{s, -s, 0};
    auto box = [&](Vec3 a, Vec3 b, ArcDirection dir) {
        return bounds(need(arc_from_center(a, b, Plane::xy, dir, c - a)));
    };
    // CCW 45° → 135° passes 90°: x [100−s, 100+s], y [50+s, 60].
    Box b = box(p45, p135, ArcDirection::ccw);
    check_point(b.min, {100 - s, 50 + s, 0});
    check_point(b.max, {100 + s, 60, 0});
    // CW 45° → 135° (270°) passes 0°, 270°, 180°: x [90, 110], y [40, 50+s].
    b = box(p45, p135, ArcDirection::cw);
    check_point(b.min, {90, 40, 0});
    check_point(b.max, {110, 50 + s, 0});
    // CCW 45° → 315° (270°) passes 90°, 180°, 270°: x [90, 100+s], y [40, 60].
    b = box(p45, p315, ArcDirection::ccw);
    check_point(b.min, {90, 40, 0});
    check_point(b.max, {100 + s, 60, 0});
    // CW 45° → 315° (90°) passes 0°: x [100+s, 110], y [50−s, 50+s].
    b = box(p45, p315, ArcDirection::cw);
    check_point(b.min, {100 + s, 50 - s, 0});
    check_point(b.max, {110, 50 + s, 0});
    // Starting and ending on quadrant points: CCW 0° → 90° is the quarter x [100,110], y [50,60];
    // CW 0° → 90° (270°) also passes 270° and 180°: x [90,110], y [40,60].
    b = box(c + Vec3{10, 0, 0}, c + Vec3{0, 10, 0}, ArcDirection::ccw);
    check_point(b.min, {100, 50, 0});
    check_point(b.max, {110, 60, 0});
    b = box(c + Vec3{10, 0, 0}, c + Vec3{0, 10, 0}, ArcDirection::cw);
    check_point(b.min, {90, 40, 0});
    check_point(b.max, {110, 60, 0});
}

// G18: G02 from X0 Z10 to X0 Z−10 about the origin (K−10). Frame (Z, X): start at 0°, end at
// 180°; CW goes through −90°, i.e. X−10 (seen from +Y with Z right and X up: clockwise from the
// right-hand point goes down). Box z [−10, 10], x [−10, 0].
TEST_CASE("arc bounds in G18 and G19") {
    const Arc g18 = need(arc_from_center({0, 0, 10}, {0, 0, -10}, Plane::zx, ArcDirection::cw, {0, 0, -10}));
    Box b = bounds(g18);
    check_point(b.min, {-10, 0, -10});
    check_point(b.max, {0, 0, 10});
    // G19 G03 from Y10 Z0 to Y−10 Z0 (J−10): frame (Y, Z) 0° → 180° CCW passes 90°, Z+10.
    // Box y [−10, 10], z [0, 10].
    const Arc g19 = need(arc_from_center({0, 10, 0}, {0, -10, 0}, Plane::yz, ArcDirection::ccw, {0, -10, 0}));
    b = bounds(g19);
    check_point(b.min, {0, -10, 0});
    check_point(b.max, {0, 10, 10});
}

TEST_CASE("arc: start angle, end points exact, tangent of a plain arc") {
    const Arc arc = need(arc_from_center({0, 0, 0}, {10, 10, 0}, Plane::xy, ArcDirection::cw, {10, 0, 0}));
    // Centre (10,0): start rel (−10, 0) at 180°.
    CHECK(start_angle(arc) == Approx(pi));
    CHECK(point_at(arc, 0.0) == Vec3{0, 0, 0});
    CHECK(point_at(arc, -1.0) == Vec3{0, 0, 0});
    CHECK(point_at(arc, 1.0) == Vec3{10, 10, 0});
    CHECK(point_at(arc, 2.0) == Vec3{10, 10, 0});
    // CW from the leftmost point the tool moves in +Y.
    check_point(tangent_at(arc, 0.0), {0, 1, 0});
    // At the end (90° about (10,0)) CW motion is +X.
    check_point(tangent_at(arc, 1.0), {1, 0, 0});
}
