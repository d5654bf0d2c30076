// Straight moves (G00 interpolated, G01): length, point at a parameter, exact bounds.
#pragma once

#include "motion/bounds.hpp"
#include "motion/vec.hpp"

namespace kerf::motion {

struct Line {
    Vec3 start;
    Vec3 end;
};

inline double length(const Line& line) { return distance(line.start, line.end); }

// Point at parameter t in [0, 1] (clamped); t is proportional to the distance travelled.
inline Vec3 point_at(const Line& line, double t) {
    if (!(t > 0.0)) return line.start;
    if (t >= 1.0) return line.end;
    return lerp(line.start, line.end, t);
}

// Unit direction; the zero vector for a move of zero length.
inline Vec3 direction(const Line& line) {
    const double l = length(line);
    return l > 0.0 ? (line.end - line.start) / l : Vec3{};
}

// Exact: the box of the two end points.
inline Box bounds(const Line& line) { return box_of(line.start, line.end); }

}  // namespace kerf::motion
