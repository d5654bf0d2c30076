// Time of known moves with and without trapezoidal acceleration (motion/time.hpp, exact-stop
// model). tests/motion/test_time.cpp covers the trapezoid formula and a two-axis rapid; this file
// adds: the formula against the integrated velocity profile (an independent derivation), a
// diagonal G01 whose path acceleration comes from per-axis limits, a triangle profile, a three-axis
// rapid in both G00 modes, a rotary span with acceleration, and an arc's feed time. Every expected
// number is derived by hand next to it; times in seconds.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "motion/arc.hpp"
#include "motion/time.hpp"

using namespace kerf::motion;

namespace {

// The distance covered in time T by the fastest rest-to-rest profile allowed by v and a:
// v(t) = min(a·t, v, a·(T − t)) (accelerate, cruise, brake), integrated by the midpoint rule in n
// steps. If T is the true minimum time for a length L, this gives back L: an independent check of
// trapezoid_time's closed form (which never integrates).
double distance_in(double T, double v_max, double a, int n = 200000) {
    double s = 0;
    const double dt = T / n;
    for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) * dt;
        s += std::min({a * t, v_max, a * (T - t)}) * dt;
    }
    return s;
}

}  // namespace

// v = 100 mm/s, a = 500 mm/s²:
//   L = 100 reaches v (v²/a = 20 ≤ 100): 100/100 + 100/500 = 1.2 s
//   L = 10 does not (triangle): 2·√(10/500) = 0.2828427 s
// Integrating the profile v(t) = min(a·t, v, a·(T − t)) over each T must give back the length
// (and a slightly shorter T must fall short of it: T is the minimum).
TEST_CASE("trapezoid formula against the integrated velocity profile", "[time]") {
    CHECK(trapezoid_time(100, 100, 500) == Approx(1.2));
    CHECK(distance_in(1.2, 100, 500) == Approx(100).epsilon(1e-6));
    CHECK(distance_in(1.2 * 0.999, 100, 500) < 100);
    CHECK(trapezoid_time(10, 100, 500) == Approx(0.2828427));
    CHECK(distance_in(trapezoid_time(10, 100, 500), 100, 500) == Approx(10).epsilon(1e-6));
    CHECK(distance_in(0.2828427 * 0.999, 100, 500) < 10);
}

// G01 from (0, 0, 0) to (30, 40, 0): L = 50 mm, direction u = (0.6, 0.8, 0).
// F6000 mm/min = 100 mm/s. Axis accelerations X 1000, Y 500 mm/s²:
//   path acceleration = min(1000/0.6, 500/0.8) = min(1666.67, 625) = 625 mm/s² (Y limits)
//   without acceleration: 50/100 = 0.5 s
//   with it: v²/a = 10000/625 = 16 ≤ 50 → 50/100 + 100/625 = 0.5 + 0.16 = 0.66 s
// The same move at F30000 (500 mm/s): v²/a = 400 > 50 → triangle 2·√(50/625) = 0.5656854 s.
TEST_CASE("G01 diagonal: path acceleration from the axes, trapezoid and triangle", "[time]") {
    AxisLimits3 limits;
    limits.x = {10000, 1000};
    limits.y = {10000, 500};
    limits.z = {10000, 1000};
    const Vec3 delta{30, 40, 0};
    const double a = path_accel(delta, limits);
    CHECK(a == Approx(625));
    CHECK(feed_time(50, 6000) == Approx(0.5));
    CHECK(feed_time(50, 6000, a) == Approx(0.66));
    CHECK(feed_time(50, 30000, a) == Approx(0.5656854));
    // A move along Z only: the Z limit alone, 1000 mm/s²: 50/100 + 100/1000 = 0.6 s.
    CHECK(feed_time(50, 6000, path_accel(Vec3{0, 0, -50}, limits)) == Approx(0.6));
}

// Rapid (0,0,0) → (100, 50, 20); rates X 12000 (200 mm/s), Y 6000 (100 mm/s), Z 3000 (50 mm/s)
// mm/min; accelerations X 2000, Y 500, Z 1000 mm/s².
//   Without acceleration (both modes): max(100/200, 50/100, 20/50) = max(0.5, 0.5, 0.4) = 0.5 s.
//   Dog-leg, each axis alone:
//     X: v²/a = 20 ≤ 100 → 0.5 + 0.1 = 0.6 s
//     Y: v²/a = 20 ≤ 50  → 0.5 + 0.2 = 0.7 s
//     Z: v²/a = 2.5 ≤ 20 → 0.4 + 0.05 = 0.45 s          → 0.7 s
//   Straight: σ' ≤ min(200/100, 100/50, 50/20) = 2 /s, σ'' ≤ min(2000/100, 500/50, 1000/20) = 10 /s²;
//     σ'²/σ'' = 0.4 ≤ 1 → 1/2 + 2/10 = 0.7 s.
TEST_CASE("three-axis rapid with and without acceleration", "[time]") {
    AxisLimits3 no_accel;
    no_accel.x = {12000, 0};
    no_accel.y = {6000, 0};
    no_accel.z = {3000, 0};
    const Vec3 move{100, 50, 20};
    CHECK(rapid_time(move, no_accel, RapidMode::dog_leg) == Approx(0.5));
    CHECK(rapid_time(move, no_accel, RapidMode::straight) == Approx(0.5));
    AxisLimits3 accel;
    accel.x = {12000, 2000};
    accel.y = {6000, 500};
    accel.z = {3000, 1000};
    CHECK(rapid_time(move, accel, RapidMode::dog_leg) == Approx(0.7));
    CHECK(rapid_time(move, accel, RapidMode::straight) == Approx(0.7));
    // Negative travel takes the same time: (−100, −50, −20).
    CHECK(rapid_time(Vec3{-100, -50, -20}, accel, RapidMode::dog_leg) == Approx(0.7));
}

// Span form: X 100 mm at 6000 mm/min (100 mm/s), a 500 mm/s²; C 90° at 3600°/min (60°/s),
// a 100°/s².
//   Without acceleration: max(1.0, 1.5) = 1.5 s.
//   Dog-leg: X v²/a = 20 ≤ 100 → 1 + 0.2 = 1.2 s; C v²/a = 36 ≤ 90 → 1.5 + 0.6 = 2.1 s → 2.1 s.
//   Straight: σ' ≤ min(100/100, 60/90) = 0.666667, σ'' ≤ min(500/100, 100/90) = 1.111111;
//     σ'²/σ'' = 0.4 ≤ 1 → 1/0.666667 + 0.666667/1.111111 = 1.5 + 0.6 = 2.1 s.
TEST_CASE("rotary span with acceleration", "[time]") {
    const std::array<double, 2> travel{100, 90};
    const std::array<AxisLimits, 2> plain{AxisLimits{6000, 0}, AxisLimits{3600, 0}};
    CHECK(rapid_time(travel, plain, RapidMode::dog_leg) == Approx(1.5));
    const std::array<AxisLimits, 2> limits{AxisLimits{6000, 500}, AxisLimits{3600, 100}};
    CHECK(rapid_time(travel, limits, RapidMode::dog_leg) == Approx(2.1));
    CHECK(rapid_time(travel, limits, RapidMode::straight) == Approx(2.1));
}

// Arc: G17 G03 quarter of R10 from (10, 0) about the origin: 15.707963 mm. F600 = 10 mm/s:
//   no acceleration: 1.5707963 s; a = 100 mm/s²: v²/a = 1 ≤ 15.708 → 1.5707963 + 0.1 = 1.6707963 s.
// A helix (Z −5 on the same quarter) is timed on its planar length (F along the arc): the same.
TEST_CASE("arc feed time with and without acceleration", "[time]") {
    const ArcResult q = arc_from_center({10, 0, 0}, {0, 10, 0}, Plane::xy, ArcDirection::ccw, {-10, 0, 0});
    REQUIRE(q.ok());
    CHECK(feed_length(q.arc()) == Approx(15.7079633));
    CHECK(feed_time(feed_length(q.arc()), 600) == Approx(1.5707963));
    CHECK(feed_time(feed_length(q.arc()), 600, 100) == Approx(1.6707963));
    const ArcResult h = arc_from_center({10, 0, 0}, {0, 10, -5}, Plane::xy, ArcDirection::ccw, {-10, 0, 0});
    REQUIRE(h.ok());
    CHECK(feed_time(feed_length(h.arc()), 600, 100) == Approx(1.6707963));
}
