// Feed and time model (semantics.md §4, §4.1, §8; gcode-tables.md §5 seed 003 G00). Every
// expected number is derived by hand in the comment above it. Times in seconds.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "motion/time.hpp"

using namespace kerf::motion;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double inf = std::numeric_limits<double>::infinity();

}  // namespace

// v = 100 mm/s, a = 500 mm/s²: v reached after v²/(2a) = 10 mm; a rest-to-rest move that reaches
// v needs L ≥ v²/a = 20 mm.
//   L = 100: 100/100 + 100/500 = 1.2 s
//   L = 10 : triangle, 2·√(10/500) = 0.2828427 s
//   L = 20 : both formulas give 0.4 s (continuous at the switch)
TEST_CASE("trapezoid: reaches the feed, triangle, boundary, no acceleration") {
    CHECK(trapezoid_time(100, 100, 500) == Approx(1.2));
    CHECK(trapezoid_time(10, 100, 500) == Approx(0.2828427));
    CHECK(trapezoid_time(20, 100, 500) == Approx(0.4));
    CHECK(trapezoid_time(20 - 1e-9, 100, 500) == Approx(0.4));
    CHECK(trapezoid_time(100, 100, 0) == Approx(1.0));     // 0 = not modelled
    CHECK(trapezoid_time(100, 100, inf) == Approx(1.0));
    CHECK(trapezoid_time(0, 100, 500) == 0.0);
    CHECK(trapezoid_time(10, 0, 500) == inf);
}

// F6000 mm/min = 100 mm/s over 100 mm: 1.0 s; with a = 500 mm/s²: 1.2 s (as above).
// F0.2 mm/rev at 1000 rpm = 200 mm/min (semantics.md §4: feed/min = feed/rev × rpm);
// 50 mm at 200 mm/min = 0.25 min = 15 s.
TEST_CASE("feed time: per minute, per revolution, with and without acceleration") {
    CHECK(feed_time(100, 6000) == Approx(1.0));
    CHECK(feed_time(100, 6000, 500) == Approx(1.2));
    CHECK(feed_time(10, 6000, 500) == Approx(0.2828427));
    CHECK(feed_per_minute(0.2, 1000) == Approx(200.0));
    CHECK(feed_time(50, feed_per_minute(0.2, 1000)) == Approx(15.0));
    CHECK(feed_time(50, 0) == inf);   // no feed: the control would not move
    CHECK(feed_time(0, 0) == 0.0);
}

// Known move: X100 Z100 (Y still). X: 10000 mm/min = 166.667 mm/s, a 1000 mm/s²;
// Z: 20000 mm/min = 333.333 mm/s, a 500 mm/s².
TEST_CASE("rapid time: straight vs dog-leg on a known move") {
    const Vec3 move{100, 0, 100};
    AxisLimits3 no_accel;
    no_accel.x = {10000, 0};
    no_accel.z = {20000, 0};
    // Without acceleration both modes take the slowest axis at its own rate:
    // max(100/166.667, 100/333.333) = max(0.6, 0.3) = 0.6 s.
    CHECK(rapid_time(move, no_accel, RapidMode::straight) == Approx(0.6));
    CHECK(rapid_time(move, no_accel, RapidMode::dog_leg) == Approx(0.6));

    AxisLimits3 limits;
    limits.x = {10000, 1000};
    limits.y = {10000, 1000};
    limits.z = {20000, 500};
    // Dog-leg, each axis on its own:
    //   X: v²/a = 166.667²/1000 = 27.8 ≤ 100 → 100/166.667 + 166.667/1000 = 0.6 + 0.1666667
    //      = 0.7666667 s
    //   Z: v²/a = 333.333²/500 = 222.2 > 100 → triangle 2·√(100/500) = 0.8944272 s
    //   → 0.8944272 s (Z, limited by its acceleration)
    CHECK(rapid_time(move, limits, RapidMode::dog_leg) == Approx(0.8944272));
    // Straight: progress σ with σ' ≤ min(166.667/100, 333.333/100) = 1.666667 /s (X limits the
    // speed) and σ'' ≤ min(1000/100, 500/100) = 5 /s² (Z limits the acceleration);
    // σ'²/σ'' = 0.5556 ≤ 1 → 1/1.666667 + 1.666667/5 = 0.6 + 0.3333333 = 0.9333333 s.
    // Straight is slower: no axis may exceed its rate *or* its acceleration on the line.
    CHECK(rapid_time(move, limits, RapidMode::straight) == Approx(0.9333333));
    // Path acceleration along the diagonal: u = (0.7071, 0, 0.7071); X 1000/0.7071 = 1414.2,
    // Z 500/0.7071 = 707.1068 → 707.1068 mm/s².
    CHECK(path_accel(move, limits) == Approx(707.1068));
    CHECK(rapid_time(Vec3{}, limits, RapidMode::straight) == 0.0);
    CHECK(rapid_time(Vec3{}, limits, RapidMode::dog_leg) == 0.0);
}

// Equal rates 6000 mm/min = 100 mm/s on X and Z, move X100 Z10 from the origin: Z arrives after
// 0.1 s at X10, X after 1 s. Dog-leg path: (0,0,0) → (10,0,10) → (100,0,10).
TEST_CASE("rapid: the dog-leg path") {
    AxisLimits3 limits;
    limits.x = {6000, 0};
    limits.y = {6000, 0};
    limits.z = {6000, 0};
    const auto path = dog_leg_path({0, 0, 0}, {100, 0, 10}, limits);
    REQUIRE(path.size() == 3);
    CHECK(path[0] == Vec3{0, 0, 0});
    CHECK(path[1].x == Approx(10.0));
    CHECK(path[1].z == Approx(10.0));
    CHECK(path[2] == Vec3{100, 0, 10});
    // A single-axis move has no knee.
    CHECK(dog_leg_path({0, 0, 0}, {0, 0, -50}, limits).size() == 2);
    // A diagonal at equal rates has none either: both arrive together.
    CHECK(dog_leg_path({0, 0, 0}, {20, 0, 20}, limits).size() == 2);
}

// Span form with a rotary axis: X 100 mm at 6000 mm/min (1 s), C 180° at 5400°/min = 90°/s (2 s)
// → 2 s in both modes (no acceleration).
TEST_CASE("rapid time: span form with a rotary axis") {
    const std::array<double, 2> travel{100, -180};
    const std::array<AxisLimits, 2> limits{AxisLimits{6000, 0}, AxisLimits{5400, 0}};
    CHECK(rapid_time(travel, limits, RapidMode::dog_leg) == Approx(2.0));
    CHECK(rapid_time(travel, limits, RapidMode::straight) == Approx(2.0));
}

// semantics.md §4.1: n = 1000·Vc/(π·D), clamped by G50 S.
//   Vc 200, D 100 → 200000/(π·100) = 636.6198 rpm
//   D 10 → 6366.198 > S2000 → 2000; D 0 → 2000; no clamp at D 0 → +inf
//   D 1000 → 63.662 < minimum 100 → 100; D −100 (X negative) → |D| → 636.6198
TEST_CASE("G96 rpm and clamp") {
    const SpindleClamp g50{2000, 0};
    CHECK(css_rpm(200, 100, g50) == Approx(636.6198));
    CHECK(css_rpm(200, 10, g50) == Approx(2000));
    CHECK(css_rpm(200, 10, SpindleClamp{}) == Approx(6366.198));
    CHECK(css_rpm(200, 0, g50) == Approx(2000));
    CHECK(css_rpm(200, 0, SpindleClamp{}) == inf);
    CHECK(css_rpm(200, 1000, SpindleClamp{2000, 100}) == Approx(100));
    CHECK(css_rpm(200, -100, g50) == Approx(636.6198));
    CHECK(css_rpm(0, 100, g50) == 0.0);
}

// Facing cut under G96 S200 (Vc = 200 m/min), G99 F0.2 (f = 0.2 mm/rev), G50 S2000, from X100
// (diameter; radius x0 = 50) to X0 along X (radius travel 50 mm).
// Closed form with x the radius (D = 2x, ds = dx):
//   free while n < 2000, i.e. x > xc = 500·Vc/(π·2000) = 15.9154943 mm:
//     t_free = ∫ π·2x dx / (1000·Vc·f) from xc to 50 = π·(50² − xc²)/(1000·200·0.2)
//            = π·(2500 − 253.30)/40000 min = 0.1764552 min = 10.5873104 s
//   clamped for x < xc at 2000 rpm, i.e. 0.2·2000 = 400 mm/min:
//     t_clamp = 15.9154943/400 min = 2.3873241 s
//   total 12.9746345 s
TEST_CASE("CSS time: facing move against the closed form") {
    const SpindleClamp g50{2000, 0};
    CHECK(css_feed_time(50, 100, 0, 200, 0.2, g50) == Approx(12.9746345));
    // Same through a geometric line (x is the radius).
    CHECK(css_feed_time(Line{{50, 0, 5}, {0, 0, 5}}, 200, 0.2, g50) == Approx(12.9746345));
    // Direction does not matter (facing outward).
    CHECK(css_feed_time(50, 0, 100, 200, 0.2, g50) == Approx(12.9746345));
    // Without a clamp: π·50²/40000 min = 0.1963495 min = 11.7809725 s.
    CHECK(css_feed_time(50, 100, 0, 200, 0.2, SpindleClamp{}) == Approx(11.7809725));
    // Past the centre to X−2 (semantics.md §2.6 `G1 X-2`): one more mm of radius at 400 mm/min =
    // 0.15 s → 13.1246345 s.
    CHECK(css_feed_time(51, 100, -2, 200, 0.2, g50) == Approx(13.1246345));
}

// Turning along Z at constant Ø50: n = 200000/(π·50) = 1273.2395 rpm, feed 254.6479 mm/min;
// 100 mm → π·50·100/40000 min = 0.3926991 min = 23.5619449 s.
// At Ø1000 → Ø800 with a minimum of 100 rpm: the free rpm (63.7 to 79.6) is below 100 all the way
// → 100 rpm, 20 mm/min; 100 mm of path → 5 min = 300 s.
TEST_CASE("CSS time: constant diameter and the minimum clamp") {
    CHECK(css_feed_time(100, 50, 50, 200, 0.2, SpindleClamp{2000, 0}) == Approx(23.5619449));
    CHECK(css_feed_time(100, 1000, 800, 200, 0.2, SpindleClamp{2000, 100}) == Approx(300.0));
    CHECK(css_feed_time(0, 100, 0, 200, 0.2, SpindleClamp{}) == 0.0);
    CHECK(css_feed_time(10, 100, 0, 200, 0.0, SpindleClamp{}) == inf);
}

// Cross-check the analytic method against brute-force Simpson integration of ds/(f·n(D(s))) on
// a taper that crosses the max clamp: L 80 mm, Ø120 → Ø10, Vc 250, f 0.15, clamp 3000 rpm.
TEST_CASE("CSS time: analytic equals numeric integration on a taper through the clamp") {
    const SpindleClamp clamp{3000, 50};
    const double L = 80, d0 = 120, d1 = 10, vc = 250, f = 0.15;
    const int n = 20000;   // even
    auto minutes_per_mm = [&](double s) { return 1.0 / (f * css_rpm(vc, d0 + (d1 - d0) * s / L, clamp)); };
    double sum = minutes_per_mm(0) + minutes_per_mm(L);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * minutes_per_mm(L * i / n);
    const double numeric_s = sum * (L / n) / 3.0 * 60.0;
    CHECK(css_feed_time(L, d0, d1, vc, f, clamp) == Approx(numeric_s).epsilon(1e-6));
}

// Arc under G96, G18 quarter circle r 20 about the spindle axis: from (x20, z0) to (x0, z20),
// G02 I−20 (centre at the origin; frame (Z, X): start at 90°, end at 0°, CW −π/2). With φ the angle from the X axis, x = 20·cos φ, ds = 20 dφ.
//   Unclamped: ∫ D ds = ∫ 2·20 cos φ·20 dφ over [0, π/2] = 2·20² = 800;
//     t = π·800/(1000·200·0.2) min = 0.0628319 min = 3.7699112 s
//   Clamp at xc = 10 (n_max = 500·200/(π·10) = 3183.0989 rpm): free for φ < acos(10/20) = π/3:
//     t_free = π·2·20²·sin(π/3)/40000 min = π·692.8203/40000 min = 3.2648389 s
//     t_clamp = arc (π/2 − π/3)·20 = 10.4719755 mm at 0.2·3183.0989 = 636.6198 mm/min
//             = 0.9869604 s (= π²/10 s)
//     total 4.2517993 s
TEST_CASE("CSS time: quarter arc against the closed form") {
    const ArcResult q = arc_from_center({20, 0, 0}, {0, 0, 20}, Plane::zx, ArcDirection::cw, {-20, 0, 0});
    REQUIRE(q.ok());
    REQUIRE(q.arc().sweep == Approx(-pi / 2));
    // Closed forms to full precision: 60·π·800/40000 and 60·(π·2·400·sin(π/3)/40000 + π²/600).
    const double unclamped = 60.0 * pi * 800.0 / 40000.0;                                   // 3.7699112
    const double clamped = 60.0 * (pi * 800.0 * std::sin(pi / 3) / 40000.0 + pi * pi / 600.0);   // 4.2517993
    CHECK(unclamped == Approx(3.7699112));
    CHECK(clamped == Approx(4.2517993));
    CHECK(css_feed_time(q.arc(), 200, 0.2, SpindleClamp{}) == Approx(unclamped).epsilon(1e-9));
    const double n_max = 500.0 * 200.0 / (pi * 10.0);   // 3183.0989 rpm: clamp at x = 10
    CHECK(css_feed_time(q.arc(), 200, 0.2, SpindleClamp{n_max, 0}) == Approx(clamped).epsilon(1e-9));
    // The same arc driven the other way round (G03 from x0 z20 to x20 z0) takes the same time.
    const ArcResult back = arc_from_center({0, 0, 20}, {20, 0, 0}, Plane::zx, ArcDirection::ccw, {0, 0, -20});
    REQUIRE(back.ok());
    CHECK(css_feed_time(back.arc(), 200, 0.2, SpindleClamp{n_max, 0}) == Approx(clamped).epsilon(1e-9));
}

// An arc through the spindle axis: G18 G02 from (x10, z0) to (x−10, z0) about the origin (I−10)
// passes x = 0 at z = +10: in the frame (Z, X) it starts at 90° and runs CW through 0° (z10, x0)
// to −90°.
// With x = 10·cos φ, φ ∈ [0, π]: ∫ D ds = ∫ 2·10·|cos φ|·10 dφ = 200·2 = 400;
// t = π·400/40000 min = 0.0314159 min = 1.8849556 s (no clamp). With a clamp the numeric
// brute force (Simpson on 200000 intervals of ds/(f·n)) must agree.
TEST_CASE("CSS time: arc through the spindle axis, closed form and brute force") {
    const ArcResult r = arc_from_center({10, 0, 0}, {-10, 0, 0}, Plane::zx, ArcDirection::cw, {-10, 0, 0});
    REQUIRE(r.ok());
    const Arc& arc = r.arc();
    REQUIRE(arc.sweep == Approx(-pi));
    CHECK(point_at(arc, 0.5).z == Approx(10.0));
    const double closed = 60.0 * pi * 400.0 / 40000.0;   // 1.8849556
    CHECK(closed == Approx(1.8849556));
    CHECK(css_feed_time(arc, 200, 0.2, SpindleClamp{}) == Approx(closed).epsilon(1e-9));
    const SpindleClamp clamp{5000, 0};   // clamps for x < 500·200/(π·5000) = 6.366 mm
    const int n = 200000;
    auto per_t = [&](double t) {
        return length(arc) / (0.2 * css_rpm(200, 2.0 * point_at(arc, t).x, clamp));
    };
    double sum = per_t(0) + per_t(1);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * per_t(static_cast<double>(i) / n);
    const double numeric_s = sum / n / 3.0 * 60.0;
    CHECK(css_feed_time(arc, 200, 0.2, clamp) == Approx(numeric_s).epsilon(1e-7));
    CHECK(css_feed_time(arc, 200, 0.2, clamp) > 1.8849556);   // clamping only slows
}

// G04: X1.5 → 1.5 s; P1000 (FANUC ms) → 1 s; 10 revolutions at 600 rpm → 10/600 min = 1 s.
TEST_CASE("dwell time") {
    CHECK(dwell_time(1.5, DwellUnit::seconds) == Approx(1.5));
    CHECK(dwell_time(1000, DwellUnit::milliseconds) == Approx(1.0));
    CHECK(dwell_time(10, DwellUnit::revolutions, 600) == Approx(1.0));
    CHECK(dwell_time(10, DwellUnit::revolutions, 0) == inf);
    CHECK(dwell_time(-3, DwellUnit::seconds) == 0.0);
    CHECK(dwell_time(0, DwellUnit::seconds) == 0.0);
}
