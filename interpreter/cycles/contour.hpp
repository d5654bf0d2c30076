// Plane geometry of a lathe finishing profile for the roughing cycles (cycles.md §2–§4): lines
// and arcs in the Z–X plane with X as a radius, in program units. Arcs are kept as centre,
// radius, start angle and signed sweep in the G18 frame (first axis Z, second X: angle =
// atan2(x − cx, z − cz), > 0 counter-clockwise), the frame the motion kernel uses for G18.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "interpreter/cycles/context.hpp"

namespace kerf::interpreter::cycles {

struct Pt {
    double x = 0;   // radius
    double z = 0;
};

enum class Coord { x, z };
inline double get(Pt p, Coord c) { return c == Coord::x ? p.x : p.z; }
inline Pt make(Coord c, double value, double other) { return c == Coord::x ? Pt{value, other} : Pt{other, value}; }
inline Coord other(Coord c) { return c == Coord::x ? Coord::z : Coord::x; }

struct Seg {
    Pt a, b;
    EventKind kind = EventKind::linear;   // rapid, linear, arc_cw, arc_ccw
    Pt c;                                 // arcs: centre
    double r = 0, a0 = 0, sweep = 0;      // arcs: radius, start angle, signed sweep
    std::size_t move = 0;                 // index of the ProfileMove it came from
    bool is_arc() const { return kind == EventKind::arc_cw || kind == EventKind::arc_ccw; }
};
using Contour = std::vector<Seg>;

Pt to_pt(const Position& p, bool diameter_x);
Position to_position(Pt p, const Position& like, bool diameter_x);

// The profile's moves from index `first` on, starting where move first−1 ends (A for 0).
Contour contour_of(const Profile& profile, std::size_t first, bool diameter_x);
Contour shifted(const Contour& contour, double dx, double dz);
Pt point_at(const Seg& s, double t);

struct Crossing {
    std::size_t seg = 0;
    double t = 0;
    Pt p;
};
// The first point, walking the contour, where coordinate `c` equals `value`.
std::optional<Crossing> first_crossing(const Contour& contour, Coord c, double value);
// The part of the contour after a crossing.
Contour after(const Contour& contour, const Crossing& at);
// The first segment along which coordinate `c` reverses (arcs included); nullopt when it never does.
std::optional<std::size_t> first_reversal(const Contour& contour, Coord c);
// The contour with every segment cut where coordinate `c` passes `value` (arcs up to twice), so
// each piece lies wholly on one side of the line c = value (G71/G72 type II levels).
Contour split_at(const Contour& contour, Coord c, double value);
// The part of the contour before a crossing.
Contour until(const Contour& contour, const Crossing& at);
// The largest value of `direction` · coordinate `c` on the contour (arcs' extremes included),
// returned as the coordinate: direction +1 the maximum, −1 the minimum.
double extreme(const Contour& contour, Coord c, double direction);

}  // namespace kerf::interpreter::cycles
