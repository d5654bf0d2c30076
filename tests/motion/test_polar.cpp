// motion/polar.hpp: the polar and cylindrical maps of cycles.md §18–§19, by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "motion/polar.hpp"

using namespace kerf::motion;

namespace {
const PlaneMap kPolar{PlaneMap::Kind::polar, 0};
P2 line(P2 a, P2 b, double t) { return a + (b - a) * t; }
}  // namespace

TEST_CASE("polar map: corner points of a square and the unwrapped angle") {
    // cycles.md §18: radius = √(x² + y²), angle = atan2(y, x) in degrees.
    // (10, 10): √200 = 14.1421, 45°; (−10, 10): 135°; (−10, −10): −135°, taken near 135° → 225°.
    P2 m = to_machine(kPolar, {10, 10}, 0);
    CHECK(m.a == Approx(std::sqrt(200.0)));
    CHECK(m.b == Approx(45));
    m = to_machine(kPolar, {-10, 10}, 45);
    CHECK(m.b == Approx(135));
    m = to_machine(kPolar, {-10, -10}, 135);
    CHECK(m.b == Approx(225));   // continuous across ±180°, not −135
    m = to_machine(kPolar, {-10, -10}, -100);
    CHECK(m.b == Approx(-135));
    // Hexagon P2 of seed 001 §10.5: X30 (radius 15) C25.98: √(225 + 674.9604) = 29.99934;
    // 25.98/15 = 1.732 = tan 60° − 0.0000508, so atan2 = 60° − 0.0000508·cos²60°·(180/π) = 59.99927°.
    m = to_machine(kPolar, {15, 25.98}, 0);
    CHECK(m.a == Approx(29.99934).epsilon(1e-6));
    CHECK(m.b == Approx(59.99927).epsilon(1e-6));
    // The centre keeps the angle it is given.
    CHECK(to_machine(kPolar, {0, 0}, 33).b == 33);
    // And back: (√200, 45°) → (10, 10).
    const P2 c = to_cartesian(kPolar, {std::sqrt(200.0), 45});
    CHECK(c.a == Approx(10));
    CHECK(c.b == Approx(10));
}

TEST_CASE("polar map: a line is cut into pieces within the tolerance") {
    // The line y = 10 from x = 10 to x = −10 (a side of the square): the machine turns from 45°
    // to 135°; its radius goes 14.14 → 10 → 14.14. A single piece in (r, θ) would pass through
    // (14.14, 90°) = (0, 14.14): 4.14 mm off the line, so it must be cut.
    const P2 a{10, 10}, b{-10, 10};
    const auto points = map_path(kPolar, [&](double t) { return line(a, b, t); }, 45, 0.01);
    REQUIRE(points.size() > 2);
    CHECK(points.back().t == 1.0);
    CHECK(points.back().machine.b == Approx(135));
    CHECK(points.back().machine.a == Approx(std::sqrt(200.0)));
    // Every piece: no piece turns more than 45°, its middle (machine axes linear) is within
    // 0.01 mm of the line y = 10, and its ends lie on the line.
    P2 prev = to_machine(kPolar, a, 45);
    for (const MappedPoint& p : points) {
        CHECK(p.cartesian.b == Approx(10));
        CHECK(std::fabs(p.machine.b - prev.b) <= 45.0);
        const P2 middle = to_cartesian(kPolar, (prev + p.machine) * 0.5);
        CHECK(std::fabs(middle.b - 10) <= 0.0101);
        prev = p.machine;
    }
    // The angles climb monotonically from 45° to 135°.
    for (std::size_t i = 1; i < points.size(); ++i) CHECK(points[i].machine.b > points[i - 1].machine.b);
}

TEST_CASE("polar map: a circle about the centre is one radius, the angle runs on past 180°") {
    // A full turn about the centre at radius 5 (CCW from (5, 0)): the radius stays 5 and the
    // machine angle ends at 360°, not 0 (unwrapped); no piece turns more than 45° → at least 8.
    const auto points = map_path(kPolar, [](double t) { return P2{5 * std::cos(2 * M_PI * t), 5 * std::sin(2 * M_PI * t)}; },
                                 0, 0.01);
    REQUIRE(points.size() >= 8);
    CHECK(points.back().machine.b == Approx(360));
    for (const MappedPoint& p : points) CHECK(p.machine.a == Approx(5));
}

TEST_CASE("polar map: the nearest approach to the centre") {
    // The line x = 3 from y = −4 to y = 4 passes 3 mm from the centre; the start is 5 mm away.
    const P2 a{3, -4}, b{3, 4};
    const auto points = map_path(kPolar, [&](double t) { return line(a, b, t); }, -53.13, 0.01);
    CHECK(min_radius(points, a) == Approx(3).margin(1e-9));
}

TEST_CASE("cylindrical map: arc length to degrees, lines in one piece, arcs by chords") {
    // cycles.md §19: C in mm of arc on a cylinder of radius r: r = 50, 50·π/2 = 78.54 mm is 90°.
    const PlaneMap cyl{PlaneMap::Kind::cylindrical, 50};
    CHECK(to_machine(cyl, {-10, 50 * M_PI / 2}, 0).b == Approx(90));
    CHECK(to_machine(cyl, {-10, 50 * M_PI / 2}, 0).a == -10);
    CHECK(to_cartesian(cyl, {-10, 90}).b == Approx(50 * M_PI / 2));
    // A line of the unrolled plane is a line of (Z, C): one piece.
    const P2 a{0, 0}, b{-20, 30};
    CHECK(map_path(cyl, [&](double t) { return line(a, b, t); }, 0, 0.01).size() == 1);
    // A half circle of radius 10 in the plane, tolerance 0.01: the chord of a piece of angle φ
    // sags 10·(1 − cos(φ/2)) ≤ 0.01 → φ ≤ 2·acos(0.999) = 5.125°; halving from 180° the pieces
    // are 180/64 = 2.8125° (the next larger, 5.625°, sags 0.0120): 64 pieces.
    const auto arc = map_path(cyl, [](double t) { return P2{10 * std::cos(M_PI * t), 10 * std::sin(M_PI * t)}; }, 0, 0.01);
    CHECK(arc.size() == 64);
}
