// Lines, bounding boxes and the soft-limit check.
#include <catch2/catch.hpp>

#include "motion/arc.hpp"
#include "motion/bounds.hpp"
#include "motion/line.hpp"

using namespace kerf::motion;

TEST_CASE("line: length, point at t, direction, exact bounds") {
    const Line line{{1, 2, 3}, {4, 6, -9}};
    // Δ = (3, 4, −12): length √(9 + 16 + 144) = 13.
    CHECK(length(line) == Approx(13.0));
    CHECK(point_at(line, 0.0) == Vec3{1, 2, 3});
    CHECK(point_at(line, 1.0) == Vec3{4, 6, -9});
    CHECK(point_at(line, -0.5) == Vec3{1, 2, 3});
    CHECK(point_at(line, 0.5) == Vec3{2.5, 4, -3});
    const Vec3 u = direction(line);
    CHECK(u.x == Approx(3.0 / 13));
    CHECK(u.z == Approx(-12.0 / 13));
    const Box b = bounds(line);
    CHECK(b.min == Vec3{1, 2, -9});
    CHECK(b.max == Vec3{4, 6, 3});
    CHECK(b.size() == Vec3{3, 4, 12});
    const Line still{{5, 5, 5}, {5, 5, 5}};
    CHECK(length(still) == 0.0);
    CHECK(direction(still) == Vec3{});
    CHECK(bounds(still).size() == Vec3{});
}

TEST_CASE("box: empty, extend, contains, merge") {
    Box box;
    CHECK(box.empty());
    CHECK(box.size() == Vec3{});
    CHECK_FALSE(box.contains({0, 0, 0}));
    box.extend({1, 1, 1});
    CHECK_FALSE(box.empty());
    CHECK(box.min == Vec3{1, 1, 1});
    CHECK(box.max == Vec3{1, 1, 1});
    box.extend({-1, 3, 0});
    CHECK(box.min == Vec3{-1, 1, 0});
    CHECK(box.max == Vec3{1, 3, 1});
    CHECK(box.contains({0, 2, 0.5}));
    CHECK_FALSE(box.contains({0, 3.1, 0.5}));
    CHECK(box.contains({0, 3.1, 0.5}, 0.2));
    Box other;
    box.merge(other);   // merging an empty box changes nothing
    CHECK(box.min == Vec3{-1, 1, 0});
    other.extend({10, -10, 0});
    box.merge(other);
    CHECK(box.min == Vec3{-1, -10, 0});
    CHECK(box.max == Vec3{10, 3, 1});
}

// Limits X [−500, 0], Y [−200, 200], Z [−400, 10].
TEST_CASE("soft limits: which axis and by how much") {
    SoftLimits limits;
    limits.min = {-500, -200, -400};
    limits.max = {0, 200, 10};
    CHECK(check_soft_limits(Vec3{-10, 0, 0}, limits).empty());
    CHECK(check_soft_limits(Vec3{0, 200, -400}, limits).empty());   // on the limit is allowed
    // (5, 0, −401): X 5 over its maximum 0, Z 1 under its minimum −400.
    const auto v = check_soft_limits(Vec3{5, 0, -401}, limits);
    REQUIRE(v.size() == 2);
    CHECK(v[0].axis == Axis::x);
    CHECK(v[0].side == LimitSide::above_max);
    CHECK(v[0].excess == Approx(5.0));
    CHECK(v[0].limit == 0.0);
    CHECK(v[0].value == 5.0);
    CHECK(v[1].axis == Axis::z);
    CHECK(v[1].side == LimitSide::below_min);
    CHECK(v[1].excess == Approx(1.0));

    // Both end points of an arc inside, the arc outside: G17 G02 from (−60, 195) to (−40, 195)
    // with R10: centre (−50, 195), CW from 180° to 0° over the top, y max 205 → Y 5 over 200.
    const ArcResult arc = arc_from_radius({-60, 195, 0}, {-40, 195, 0}, Plane::xy, ArcDirection::cw, 10.0);
    REQUIRE(arc.ok());
    CHECK(check_soft_limits(arc.arc().start, limits).empty());
    CHECK(check_soft_limits(arc.arc().end, limits).empty());
    const auto over = check_soft_limits(bounds(arc.arc()), limits);
    REQUIRE(over.size() == 1);
    CHECK(over[0].axis == Axis::y);
    CHECK(over[0].side == LimitSide::above_max);
    CHECK(over[0].excess == Approx(5.0));

    // A box can pass both limits of one axis: Y from −250 to 260 → 50 under, 60 over.
    const auto both = check_soft_limits(bounds(Line{{-10, -250, 0}, {-10, 260, 0}}), limits);
    REQUIRE(both.size() == 2);
    CHECK(both[0].side == LimitSide::below_min);
    CHECK(both[0].excess == Approx(50.0));
    CHECK(both[1].side == LimitSide::above_max);
    CHECK(both[1].excess == Approx(60.0));

    // Default limits are infinite; an empty box passes nothing.
    CHECK(check_soft_limits(Vec3{1e9, -1e9, 1e9}, SoftLimits{}).empty());
    CHECK(check_soft_limits(Box{}, limits).empty());
}
