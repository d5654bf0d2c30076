// motion/corner.hpp: intersections, chamfers and fillets in a plane frame, by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "motion/corner.hpp"

using namespace kerf::motion;

TEST_CASE("corner geometry: directions, turns and intersections") {
    const P2 d = direction_at(150);   // (cos150, sin150) = (−0.8660, 0.5)
    CHECK(d.a == Approx(-std::sqrt(3.0) / 2));
    CHECK(d.b == Approx(0.5));
    CHECK(turn_angle({1, 0}, {0, 1}) == Approx(M_PI / 2));    // left turn: counter-clockwise
    CHECK(turn_angle({0, 1}, {1, 0}) == Approx(-M_PI / 2));
    // y = x and y = 4 − x meet at (2, 2).
    const auto p = intersect({0, 0}, {1, 1}, {0, 4}, {1, -1});
    REQUIRE(p);
    CHECK(p->a == Approx(2));
    CHECK(p->b == Approx(2));
    CHECK_FALSE(intersect({0, 0}, {1, 1}, {0, 4}, {2, 2}));   // parallel
    // The line from (0, 0) at 45° reaches b = 3 at a = 3; a line along a never reaches b = 3.
    const auto q = point_with_coordinate({0, 0}, {1, 1}, true, 3);
    REQUIRE(q);
    CHECK(q->a == Approx(3));
    CHECK_FALSE(point_with_coordinate({0, 0}, {1, 0}, true, 3));
}

TEST_CASE("corner geometry: chamfer and fillet of a right-angle corner") {
    // Travel +a into the corner (10, 0), then +b: a left turn of 90°.
    const CornerPiece c = chamfer({10, 0}, {1, 0}, {0, 1}, 2);
    CHECK(c.in_end.a == Approx(8));
    CHECK(c.out_start.b == Approx(2));
    CHECK_FALSE(c.arc);
    const auto f = fillet({10, 0}, {1, 0}, {0, 1}, 3);
    REQUIRE(f);
    // Setback 3·tan45° = 3; centre 3 to the left of +a travel at the in point: (7, 3).
    CHECK(f->setback == Approx(3));
    CHECK(f->in_end.a == Approx(7));
    CHECK(f->out_start.a == Approx(10));
    CHECK(f->out_start.b == Approx(3));
    CHECK(f->center.a == Approx(7));
    CHECK(f->center.b == Approx(3));
    CHECK(f->sweep == Approx(M_PI / 2));
    // A right turn puts the centre on the right and sweeps clockwise.
    const auto g = fillet({10, 0}, {1, 0}, {0, -1}, 3);
    REQUIRE(g);
    CHECK(g->center.b == Approx(-3));
    CHECK(g->sweep == Approx(-M_PI / 2));
    // Reversal: no tangent circle.
    CHECK_FALSE(fillet({10, 0}, {1, 0}, {-1, 0}, 3));
}
