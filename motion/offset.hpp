// Offset geometry of cutter and tool nose radius compensation (reference semantics.md §5, §6):
// path elements (lines and arcs) in a plane frame (motion/corner.hpp: first, second axis, a
// positive turn counter-clockwise = G03), their offsets to the left or right, the points where
// two offset elements meet, and the class of a corner. Pure functions; geometric mm.
#pragma once

#include <optional>
#include <vector>

#include "motion/corner.hpp"

namespace kerf::motion {

// A programmed or offset path element: a line start → end, or an arc about `center`.
struct Element {
    P2 start;
    P2 end;
    bool arc = false;
    P2 center;
    bool ccw = true;   // arcs: G03 (counter-clockwise in the plane frame)
};

double arc_radius(const Element& e);       // at its start
double arc_end_radius(const Element& e);   // at its end: an arc's end may miss its circle by the arc tolerance (semantics.md §3)
// Unit direction of travel at the element's start and end.
P2 start_tangent(const Element& e);
P2 end_tangent(const Element& e);
// The element moved `offset` to its left (negative: to its right). An arc keeps its centre and
// its radius changes by ∓offset, at each end from that end's own radius (an end off the circle
// within the tolerance keeps the tool r from the programmed end, as FANUC does; differential A3);
// nullopt when that radius reaches zero or below: the tool does not fit an inside arc (the
// over-cut of FANUC alarm 041).
std::optional<Element> offset_element(const Element& e, double offset);

// Crossings of the line p + s·d (any s) with the circle (c, r), and of two circles.
std::vector<P2> line_circle(P2 p, P2 d, P2 c, double r);
std::vector<P2> circle_circle(P2 c1, double r1, P2 c2, double r2);
// Where the (unbounded) supports of two elements cross, the crossing nearest `near`; nullopt
// when they do not cross (parallel lines, circles apart). `a` ends where `b` starts: an arc's
// circle is taken at that end (a's end radius, b's start radius).
std::optional<P2> meet(const Element& a, const Element& b, P2 near);

// The corner between an element ending along `in` and the next starting along `out`, for a tool
// on side `side` (+1 left G41, −1 right G42), as FANUC compensation C tells them apart
// (semantics.md §6): a straight (tangent) continuation, an inside corner, an outside corner of
// 90° or more, an acute outside corner (less than 90°, the path turns by more than 90°).
enum class CornerClass { straight, inside, outside, outside_acute };
CornerClass classify_corner(P2 in, P2 out, int side);

// True when `p` lies on the element ahead of (or at) `from`, going the element's way, or on its
// extension past the end: the part from `from` to `p` does not run backwards. A join behind the
// tool means the element is too short for the radius (over-cut).
bool ahead_on(const Element& e, P2 from, P2 p);

}  // namespace kerf::motion
