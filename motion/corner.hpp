// Plane geometry of corners: line-line intersection, chamfers and fillets between two lines
// (direct drawing, semantics.md §10) and the offset geometry of cutter / nose radius compensation
// (semantics.md §5, §6). Everything is in a plane frame (first, second axis of motion/vec.hpp:
// G18 = (Z, X) with X as a radius), in geometric mm; a positive turn is counter-clockwise (G03).
#pragma once

#include <cmath>
#include <optional>

namespace kerf::motion {

struct P2 {
    double a = 0;   // first axis of the plane
    double b = 0;   // second axis
    friend constexpr P2 operator+(P2 p, P2 q) { return {p.a + q.a, p.b + q.b}; }
    friend constexpr P2 operator-(P2 p, P2 q) { return {p.a - q.a, p.b - q.b}; }
    friend constexpr P2 operator*(P2 p, double k) { return {p.a * k, p.b * k}; }
    friend constexpr P2 operator*(double k, P2 p) { return p * k; }
};

constexpr double dot(P2 p, P2 q) { return p.a * q.a + p.b * q.b; }
constexpr double cross(P2 p, P2 q) { return p.a * q.b - p.b * q.a; }
inline double norm(P2 p) { return std::hypot(p.a, p.b); }
// The unit vector of p; p itself when it has no length.
inline P2 unit(P2 p) {
    const double n = norm(p);
    return n > 0 ? P2{p.a / n, p.b / n} : p;
}
// p turned by +90° (to the left of a path along p).
constexpr P2 left_normal(P2 p) { return {-p.b, p.a}; }
// The unit direction at `degrees` from the plane's first axis, counter-clockwise positive
// (the ,A angle of semantics.md §10.1).
P2 direction_at(double degrees);
// The signed angle (radians, −π..π) that turns direction `from` into `to` (> 0 counter-clockwise).
double turn_angle(P2 from, P2 to);

// The crossing of the lines p + s·dp and q + t·dq; nullopt when they are parallel.
std::optional<P2> intersect(P2 p, P2 dp, P2 q, P2 dq);
// The point of the line p + s·d whose coordinate (`second` false: first axis) equals `value`;
// nullopt when the line runs parallel to that coordinate's level.
std::optional<P2> point_with_coordinate(P2 p, P2 d, bool second, double value);

// A corner between an incoming and an outgoing line meeting at `corner`: the incoming line stops
// `setback` before the corner (at `in_end`), the outgoing line starts `setback` after it (at
// `out_start`); a fillet joins them by an arc about `center` through `sweep` radians (> 0
// counter-clockwise), a chamfer by a straight line.
struct CornerPiece {
    P2 in_end;
    P2 out_start;
    double setback = 0;
    bool arc = false;
    P2 center;
    double radius = 0;
    double sweep = 0;
};
// The chamfer whose ends lie `c` from the corner along both lines (semantics.md §10.1).
CornerPiece chamfer(P2 corner, P2 dir_in, P2 dir_out, double c);
// The fillet of radius r tangent to both lines: setback r·tan(|turn|/2). nullopt when the path
// reverses (turn of 180°: no tangent circle). A straight continuation gives a zero corner.
std::optional<CornerPiece> fillet(P2 corner, P2 dir_in, P2 dir_out, double r);

}  // namespace kerf::motion
