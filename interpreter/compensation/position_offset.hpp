// G45–G48 one-block position offsets (reference semantics.md §9.3): each axis move written in the
// block is lengthened or shortened by the value of the D register (G45 +D, G46 −D, G47 +2D,
// G48 −2D); a written move of zero becomes a move of that amount in the + direction; an arc's
// radius changes the same way, with its end point and centre offset scaled about the start.
// Pure rules; the executor applies them (executor_offsets.cpp). How many D a code moves by is a
// trait of its function (dialects/functions.hpp FunctionDef::position_offset).
#pragma once

#include <optional>
#include <string_view>

namespace kerf::interpreter::compensation {

// The tool's move along one axis for a programmed move `delta` (semantics.md §9.3 table: "+75 →
// +95" with 2·D = 20; "0 → −10" with G46 D = 10).
inline double offset_move(double delta, int factor, double d) {
    const double sign = delta < 0 ? -1.0 : 1.0;
    return delta + sign * factor * d;
}

// The scale of an arc whose programmed radius is `radius` (R40 → R50 under G45 D10: 1.25).
inline double arc_scale(double radius, int factor, double d) {
    return radius > 0 ? (radius + factor * d) / radius : 1.0;
}

}  // namespace kerf::interpreter::compensation
