#include "motion/offset.hpp"

#include <cmath>

namespace kerf::motion {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kStraight = 1e-7;   // radians: a turn smaller than this is a tangent continuation
constexpr double kLength = 1e-9;     // mm

// The counter-clockwise angle 0..2π from direction u to direction v about a centre.
double ccw_angle(P2 u, P2 v) {
    const double a = std::atan2(cross(u, v), dot(u, v));
    return a < 0 ? a + 2 * kPi : a;
}
}  // namespace

double arc_radius(const Element& e) { return norm(e.start - e.center); }
double arc_end_radius(const Element& e) { return norm(e.end - e.center); }

P2 start_tangent(const Element& e) {
    if (!e.arc) return unit(e.end - e.start);
    const P2 n = left_normal(unit(e.start - e.center));   // counter-clockwise travel
    return e.ccw ? n : n * -1.0;
}

P2 end_tangent(const Element& e) {
    if (!e.arc) return unit(e.end - e.start);
    const P2 n = left_normal(unit(e.end - e.center));
    return e.ccw ? n : n * -1.0;
}

std::optional<Element> offset_element(const Element& e, double offset) {
    Element o = e;
    if (!e.arc) {
        const P2 shift = left_normal(unit(e.end - e.start)) * offset;
        o.start = e.start + shift;
        o.end = e.end + shift;
        return o;
    }
    // Left of a counter-clockwise arc is towards its centre: the radius shrinks.
    const double change = e.ccw ? -offset : offset;
    const double start_radius = arc_radius(e) + change, end_radius = arc_end_radius(e) + change;
    if (start_radius <= kLength || end_radius <= kLength) return std::nullopt;
    o.start = e.center + unit(e.start - e.center) * start_radius;
    o.end = e.center + unit(e.end - e.center) * end_radius;
    return o;
}

std::vector<P2> line_circle(P2 p, P2 d, P2 c, double r) {
    const P2 u = unit(d);
    const P2 foot = p + u * dot(c - p, u);   // the point of the line nearest the centre
    const double h2 = r * r - dot(foot - c, foot - c);
    if (h2 < -1e-9 * r * r) return {};
    const double h = std::sqrt(std::max(0.0, h2));
    if (h <= kLength) return {foot};
    return {foot - u * h, foot + u * h};
}

std::vector<P2> circle_circle(P2 c1, double r1, P2 c2, double r2) {
    const double d = norm(c2 - c1);
    if (d <= kLength || d > r1 + r2 + 1e-9 || d < std::fabs(r1 - r2) - 1e-9) return {};
    const double a = (r1 * r1 - r2 * r2 + d * d) / (2 * d);
    const double h = std::sqrt(std::max(0.0, r1 * r1 - a * a));
    const P2 u = unit(c2 - c1);
    const P2 m = c1 + u * a;
    if (h <= kLength) return {m};
    return {m + left_normal(u) * h, m - left_normal(u) * h};
}

std::optional<P2> meet(const Element& a, const Element& b, P2 near) {
    std::vector<P2> points;
    if (!a.arc && !b.arc) {
        if (const auto p = intersect(a.start, a.end - a.start, b.start, b.end - b.start)) points.push_back(*p);
    } else if (!a.arc || !b.arc) {
        const Element& line = a.arc ? b : a;
        const Element& arc = a.arc ? a : b;
        points = line_circle(line.start, line.end - line.start, arc.center, a.arc ? arc_end_radius(a) : arc_radius(b));
    } else {
        points = circle_circle(a.center, arc_end_radius(a), b.center, arc_radius(b));
    }
    std::optional<P2> best;
    for (const P2& p : points)
        if (!best || norm(p - near) < norm(*best - near)) best = p;
    return best;
}

CornerClass classify_corner(P2 in, P2 out, int side) {
    const double turn = turn_angle(in, out);
    if (std::fabs(turn) < kStraight) return CornerClass::straight;
    // A left tool (G41) is inside a left (counter-clockwise) turn; the interior angle of an
    // outside corner is 180° − |turn|, acute when the path turns by more than 90°.
    if (turn * side > 0) return CornerClass::inside;
    return std::fabs(turn) > kPi / 2 + kStraight ? CornerClass::outside_acute : CornerClass::outside;
}

bool ahead_on(const Element& e, P2 from, P2 p) {
    if (!e.arc) return dot(p - from, unit(e.end - e.start)) >= -1e-6;
    // Angles travelled from `from`, in the arc's direction (clockwise arcs mirrored).
    const auto travelled = [&](P2 q) {
        const double a = ccw_angle(from - e.center, q - e.center);
        const double t = e.ccw ? a : (a > 0 ? 2 * kPi - a : 0.0);
        return t > 2 * kPi - 1e-9 ? 0.0 : t;
    };
    const double to_p = travelled(p);
    double to_end = travelled(e.end);
    if (to_end < 1e-9) to_end = 2 * kPi;   // a full circle back to its start
    // Past the end is ahead too (an outside corner's join lies on the arc's extension, as a line's
    // lies past its end); behind `from` is an angle near a whole turn: the rest of the circle is
    // split between the two.
    return to_p <= to_end + (2 * kPi - to_end) / 2 || norm(p - from) < 1e-6;
}

}  // namespace kerf::motion
