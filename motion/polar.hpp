// Polar coordinate interpolation (G12.1/G112, cycles.md §18) and cylindrical interpolation
// (G07.1/G107, cycles.md §19): a path programmed in a Cartesian plane, turned into the real axes
// (a linear axis and a rotary axis in degrees) as short pieces along which the real axes move
// linearly. Pure geometry, mm and degrees; the interpreter converts diameters and inches.
//
// * Polar: the plane is (x = the linear axis as a radius, y = the virtual axis in mm); the
//   machine point is (radius = √(x² + y²), angle = atan2(y, x) in degrees), the angle unwrapped
//   continuously from the previous point (cycles.md §18 "Expansion [FANUC]"). The angle is
//   measured from the rotary axis position at the start of the mode (the caller adds it).
// * Cylindrical: the plane is (a = the axis along the cylinder, b = the arc length in mm on a
//   cylinder of radius r); the machine point is (a, b / r in degrees) (cycles.md §19). The map is
//   linear: a line needs one piece, an arc its chords.
#pragma once

#include <functional>
#include <vector>

#include "motion/corner.hpp"

namespace kerf::motion {

struct PlaneMap {
    enum class Kind { polar, cylindrical } kind = Kind::polar;
    double cylinder_radius = 0;   // cylindrical: r in mm (> 0)
};

// A programmed point (a, b) of the Cartesian plane into the machine's (linear, degrees); for the
// polar map the angle is the branch of atan2 nearest `near_deg` (continuous across ±180°). At the
// centre (0, 0) the angle is undefined: `near_deg` is kept.
P2 to_machine(const PlaneMap& map, P2 cartesian, double near_deg);
// And back.
P2 to_cartesian(const PlaneMap& map, P2 machine);

struct MappedPoint {
    double t = 0;       // path parameter in [0, 1]
    P2 cartesian;       // the programmed-plane point on the path
    P2 machine;         // (linear, degrees)
};

// The pieces of a Cartesian path (`path(t)`, t in [0, 1], proportional to its length) for the
// machine: points after the start up to the end (the end is last, t = 1), such that between two
// of them, the real axes moving linearly, the tool stays within `tolerance` mm of the path (tested
// at the middle of each piece; no polar piece turns more than 45°). `start_deg`: the machine angle at
// t = 0. At most `max_points` points (the last one is the end whatever the tolerance).
std::vector<MappedPoint> map_path(const PlaneMap& map, const std::function<P2(double)>& path, double start_deg,
                                  double tolerance, std::size_t max_points = 20000);

// The nearest distance of the path's pieces to the centre of the polar plane (through the path's
// points): where it is small the rotary axis turns fast (cycles.md §18 "Near the centre").
double min_radius(const std::vector<MappedPoint>& points, P2 start);

}  // namespace kerf::motion
