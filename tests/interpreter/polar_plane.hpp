// The Cartesian plane of G112 polar interpolation seen from a trace event (reference/cycles.md
// §18): a machine point (X diameter, C degrees) is the plane point (X/2·cos C, X/2·sin C).
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>

#include "tests/interpreter/interpreter_fixture.hpp"

namespace kerf::test {

inline constexpr std::size_t C = 5;
inline constexpr double kDeg = 180.0 / std::numbers::pi;

inline double plane_x(const Event& e) { return e.end[X] / 2 * std::cos(e.end[C] / kDeg); }
inline double plane_y(const Event& e) { return e.end[X] / 2 * std::sin(e.end[C] / kDeg); }

}  // namespace kerf::test
