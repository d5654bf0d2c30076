// motion/offset.hpp: offset elements, crossings and corner classes, derived by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "motion/offset.hpp"

using namespace kerf::motion;

TEST_CASE("offset: a line moves along its left normal, an arc changes its radius") {
    // Line (0,0)→(10,0): left is +b. Offset 2 left → b = 2; offset 2 right → b = −2.
    const Element line{{0, 0}, {10, 0}, false, {}, true};
    const auto left = offset_element(line, 2);
    REQUIRE(left);
    CHECK(left->start.b == Approx(2));
    CHECK(left->end.a == Approx(10));
    CHECK(offset_element(line, -2)->end.b == Approx(-2));
    // CCW arc R10 about the origin from (10,0) to (0,10): the centre is on its left, so a left
    // offset of 3 gives R7 (ends (7,0), (0,7)); a right offset R13.
    const Element arc{{10, 0}, {0, 10}, true, {0, 0}, true};
    const auto in = offset_element(arc, 3);
    REQUIRE(in);
    CHECK(in->start.a == Approx(7));
    CHECK(in->end.b == Approx(7));
    CHECK(arc_radius(*offset_element(arc, -3)) == Approx(13));
    // CW arc: the centre is on the right; a left offset grows the radius.
    const Element cw{{0, 10}, {10, 0}, true, {0, 0}, false};
    CHECK(arc_radius(*offset_element(cw, 3)) == Approx(13));
    // A tool of radius 10 or more does not fit inside R10: over-cut (nullopt).
    CHECK_FALSE(offset_element(arc, 10));
    CHECK_FALSE(offset_element(arc, 12));
}

TEST_CASE("offset: tangents of lines and arcs") {
    const Element arc{{10, 0}, {0, 10}, true, {0, 0}, true};
    // CCW at angle 0 travels +b; at 90° travels −a.
    CHECK(start_tangent(arc).b == Approx(1));
    CHECK(end_tangent(arc).a == Approx(-1));
    const Element cw{{0, 10}, {10, 0}, true, {0, 0}, false};
    CHECK(start_tangent(cw).a == Approx(1));   // CW at 90° travels +a
    CHECK(end_tangent(cw).b == Approx(-1));
}

TEST_CASE("offset: crossings of lines and circles") {
    // b = 50 meets the circle R20 about (90,40) at a = 90 ± √(400 − 100) = 90 ± 17.3205.
    const auto pts = line_circle({0, 50}, {1, 0}, {90, 40}, 20);
    REQUIRE(pts.size() == 2);
    CHECK(pts[0].a == Approx(90 - std::sqrt(300.0)));
    CHECK(pts[1].a == Approx(90 + std::sqrt(300.0)));
    CHECK(line_circle({0, 70}, {1, 0}, {90, 40}, 20).empty());
    // Circles R5 about (0,0) and (8,0): a = 4, b = ±3.
    const auto cc = circle_circle({0, 0}, 5, {8, 0}, 5);
    REQUIRE(cc.size() == 2);
    CHECK(cc[0].a == Approx(4));
    CHECK(std::fabs(cc[0].b) == Approx(3));
    CHECK(circle_circle({0, 0}, 1, {8, 0}, 1).empty());
    // meet: the crossing nearest the corner. Line b = 50 and the circle: near (100,40) → 107.32.
    const Element line{{140, 50}, {100, 50}, false, {}, true};
    const Element arc{{110, 40}, {90, 60}, true, {90, 40}, true};
    const auto m = meet(line, arc, {100, 40});
    REQUIRE(m);
    CHECK(m->a == Approx(90 + std::sqrt(300.0)));
    CHECK(m->b == Approx(50));
}

TEST_CASE("offset: corner classes for a tool on the left and on the right") {
    // +a then +b is a left turn of 90°: inside for G41 (side +1), outside (exactly 90°, not
    // acute) for G42.
    CHECK(classify_corner({1, 0}, {0, 1}, +1) == CornerClass::inside);
    CHECK(classify_corner({1, 0}, {0, 1}, -1) == CornerClass::outside);
    // A turn of 135° to the right: outside for G41, interior angle 45° → acute.
    CHECK(classify_corner({1, 0}, {-1 / std::sqrt(2.0), -1 / std::sqrt(2.0)}, +1) == CornerClass::outside_acute);
    CHECK(classify_corner({1, 0}, {1, 0}, +1) == CornerClass::straight);
}

TEST_CASE("offset: a join behind the tool is an over-cut") {
    const Element line{{0, 0}, {10, 0}, false, {}, true};
    CHECK(ahead_on(line, {0, 0}, {5, 0}));
    CHECK_FALSE(ahead_on(line, {4, 0}, {3, 0}));
    // CCW quarter arc about the origin from (10,0) to (0,10): 45° lies ahead, −45° does not.
    const Element arc{{10, 0}, {0, 10}, true, {0, 0}, true};
    const double h = 10 / std::sqrt(2.0);
    CHECK(ahead_on(arc, {10, 0}, {h, h}));
    CHECK_FALSE(ahead_on(arc, {10, 0}, {h, -h}));
}
