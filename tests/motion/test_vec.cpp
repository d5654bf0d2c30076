// Vec3 arithmetic and the G17/G18/G19 plane frames (semantics.md §3).
#include <catch2/catch.hpp>

#include <numbers>

#include "motion/arc.hpp"
#include "motion/vec.hpp"

using namespace kerf::motion;

namespace {
constexpr double pi = std::numbers::pi;
}

TEST_CASE("vec3: arithmetic, dot, cross, norm") {
    const Vec3 a{1, 2, 3};
    const Vec3 b{4, -5, 6};
    CHECK(a + b == Vec3{5, -3, 9});
    CHECK(b - a == Vec3{3, -7, 3});
    CHECK(-a == Vec3{-1, -2, -3});
    CHECK(a * 2.0 == Vec3{2, 4, 6});
    CHECK(2.0 * a == Vec3{2, 4, 6});
    CHECK(b / 2.0 == Vec3{2, -2.5, 3});
    // 1·4 + 2·(−5) + 3·6 = 4 − 10 + 18 = 12
    CHECK(dot(a, b) == 12.0);
    // (2·6 − 3·(−5), 3·4 − 1·6, 1·(−5) − 2·4) = (27, 6, −13)
    CHECK(cross(a, b) == Vec3{27, 6, -13});
    CHECK(cross(Vec3{1, 0, 0}, Vec3{0, 1, 0}) == Vec3{0, 0, 1});
    // 3-4-12 triangle: sqrt(9 + 16 + 144) = 13
    CHECK(norm(Vec3{3, 4, 12}) == Approx(13.0));
    CHECK(distance(Vec3{1, 1, 1}, Vec3{4, 5, 1}) == Approx(5.0));
    CHECK(lerp(a, b, 0.5) == Vec3{2.5, -1.5, 4.5});
    CHECK(lerp(a, b, 1.0) == b);
    CHECK(abs_components(Vec3{-1, 2, -3}) == Vec3{1, 2, 3});
    Vec3 c = a;
    c += b;
    c -= a;
    c *= 0.5;
    CHECK(c == Vec3{2, -2.5, 3});
    set(c, Axis::y, 7.0);
    CHECK(get(c, Axis::y) == 7.0);
    CHECK(axis_letter(Axis::z) == 'Z');
}

TEST_CASE("plane frames: G17 (X,Y|Z), G18 (Z,X|Y), G19 (Y,Z|X)") {
    const Vec3 p{1, 2, 3};
    CHECK(to_plane(p, Plane::xy) == PlanePoint{1, 2, 3});
    CHECK(to_plane(p, Plane::zx) == PlanePoint{3, 1, 2});   // first Z, second X, normal Y
    CHECK(to_plane(p, Plane::yz) == PlanePoint{2, 3, 1});   // first Y, second Z, normal X
    for (Plane pl : {Plane::xy, Plane::zx, Plane::yz}) CHECK(from_plane(to_plane(p, pl), pl) == p);
    CHECK(g_code(Plane::xy) == 17);
    CHECK(g_code(Plane::zx) == 18);
    CHECK(g_code(Plane::yz) == 19);
    CHECK(plane_normal(Plane::xy) == Vec3{0, 0, 1});
    CHECK(plane_normal(Plane::zx) == Vec3{0, 1, 0});
    CHECK(plane_normal(Plane::yz) == Vec3{1, 0, 0});
    // Every frame is right-handed: first × second = +normal.
    for (Plane pl : {Plane::xy, Plane::zx, Plane::yz}) {
        const Vec3 first = from_plane({1, 0, 0}, pl);
        const Vec3 second = from_plane({0, 1, 0}, pl);
        CHECK(cross(first, second) == plane_normal(pl));
    }
}

// The direction convention, checked in world coordinates without the plane helpers: the angular
// velocity ω = r × v of the tool about the centre (r = start − centre, v = the direction of
// motion) points toward the viewer for a counter-clockwise motion. semantics.md §3: G03 is CCW
// seen from +Z (G17), +Y (G18), +X (G19); G02 clockwise. So ω·(+normal) > 0 for G03, < 0 for G02.
TEST_CASE("arc direction: G02 clockwise, G03 counter-clockwise seen from +normal in every plane") {
    struct Case {
        Plane plane;
        Vec3 start;
        Vec3 end;
        Vec3 offset;       // I, J, K
        Vec3 view_from;    // world unit vector toward the viewer
    };
    // Quarter circles of radius 10 about the origin from the plane's first axis to its second.
    const Case cases[] = {
        {Plane::xy, {10, 0, 0}, {0, 10, 0}, {-10, 0, 0}, {0, 0, 1}},    // I−10
        {Plane::zx, {0, 0, 10}, {10, 0, 0}, {0, 0, -10}, {0, 1, 0}},    // K−10
        {Plane::yz, {0, 10, 0}, {0, 0, 10}, {0, -10, 0}, {1, 0, 0}},    // J−10
    };
    for (const Case& c : cases) {
        for (ArcDirection dir : {ArcDirection::cw, ArcDirection::ccw}) {
            const ArcResult r = arc_from_center(c.start, c.end, c.plane, dir, c.offset);
            REQUIRE(r.ok());
            const Arc& arc = r.arc();
            const Vec3 radius_vector = arc.start - arc.center;
            const Vec3 omega = cross(radius_vector, tangent_at(arc, 0.0));
            if (dir == ArcDirection::ccw)
                CHECK(dot(omega, c.view_from) > 0.0);
            else
                CHECK(dot(omega, c.view_from) < 0.0);
            // Also by a finite step: the point a little after the start.
            const Vec3 step = point_at(arc, 1e-3) - arc.start;
            CHECK(dot(cross(radius_vector, step), c.view_from) * (dir == ArcDirection::ccw ? 1 : -1) > 0.0);
        }
    }
}

// G18 pictured: looking from +Y toward −Y with X up, Z must point to the right (Z × X = +Y toward
// the viewer), the view of the SPINNER lathe figures (semantics.md §3). On that picture clockwise
// from the top point (X10 Z0) goes right, to (X0 Z10), a quarter circle through (X7.071 Z7.071).
TEST_CASE("G18: G02 from X10 Z0 to X0 Z10 about the origin is the 90 degree arc through X+ Z+") {
    const ArcResult r = arc_from_center({10, 0, 0}, {0, 0, 10}, Plane::zx, ArcDirection::cw, {-10, 0, 0});
    REQUIRE(r.ok());
    const Arc& arc = r.arc();
    // Plane frame (first Z, second X): start (0, 10) at 90°, end (10, 0) at 0°; CW 90° → −π/2.
    CHECK(arc.sweep == Approx(-pi / 2));
    const Vec3 mid = point_at(arc, 0.5);
    // 10·cos 45° = 7.0710678
    CHECK(mid.x == Approx(7.0710678));
    CHECK(mid.z == Approx(7.0710678));
    CHECK(mid.y == Approx(0.0).margin(1e-12));
    // The same words with G03 go the long way round: CCW in the frame from 90° to 360°, passing
    // 180° (Z−10) and 270° (X−10); 270° of sweep.
    const ArcResult l = arc_from_center({10, 0, 0}, {0, 0, 10}, Plane::zx, ArcDirection::ccw, {-10, 0, 0});
    REQUIRE(l.ok());
    CHECK(l.arc().sweep == Approx(3 * pi / 2));
    const Vec3 lmid = point_at(l.arc(), 0.5);   // 90° + 135° = 225°: Z = 10·cos 225°, X = 10·sin 225°
    CHECK(lmid.z == Approx(-7.0710678));
    CHECK(lmid.x == Approx(-7.0710678));
}
