// The programmed-point stage of FANUC mills: G68 coordinate rotation, G51 scaling and G51.1
// programmable mirror image between the program's frame and work coordinates. Pure geometry:
// the executor keeps the modes (executor_transforms.cpp, executor_rotation.cpp) and asks this
// stage for every programmed point, arc centre vector and arc direction.
#pragma once

#include <array>
#include <optional>

#include "interpreter/events.hpp"
#include "motion/vec.hpp"

namespace kerf::interpreter {

// G68 coordinate rotation (semantics.md §2.9): programmed points are turned about `center` by
// `angle` (radians, counter-clockwise positive in the plane frame) in `plane`.
struct Rotation {
    motion::Plane plane = motion::Plane::xy;
    double center_first = 0, center_second = 0;
    double angle = 0;
};

// G51 scaling [FANUC]: per linear axis (X Y Z) a centre and a magnification; a negative
// magnification (G51 I J K) mirrors that axis about the centre.
struct Scaling {
    std::array<double, 3> center{};
    std::array<double, 3> factor{1, 1, 1};
};

// G51.1 programmable mirror image [FANUC]: per axis the position of the mirror line, program units
// (nullopt: that axis is not mirrored).
using Mirror = std::array<std::optional<double>, kAxisCount>;

// The plane's (first, second) axes as Position indices (motion::Axis x, y, z are 0, 1, 2 there too).
std::pair<std::size_t, std::size_t> plane_indices(motion::Plane plane);

// The three modes as one map from the program's frame to work coordinates. [FANUC] they nest as
// G51.1 ⊃ G51 ⊃ G68 (mirror commanded first and cancelled last, then scaling, then rotation; the
// FANUC manuals: "scaling is applied first and then the coordinates are rotated", the rotation
// centre of a G68 given in G51 mode "will also be scaled"; programmable mirror image is processed
// before scaling and rotation, whose directions it reverses). Read from the inside out, a
// programmed point p is rotated, then scaled, then mirrored: work = M(S(R(p))); a mode commanded
// inside another has its centre in that other's frame, which is the same thing. A view over the
// executor's modes, valid while they are.
struct ProgramFrame {
    const Mirror& mirror;
    const std::optional<Scaling>& scaling;
    const std::optional<Rotation>& rotation;

    bool identity() const;
    Position to_work(const Position& program) const;
    Position to_program(const Position& work) const;
    // A vector of the program's frame (I/J/K of an arc, mm): the linear part of to_work.
    motion::Vec3 vector_to_work(motion::Vec3 v) const;
    // An odd number of mirrored axes in the plane (G51.1 or a negative G51 magnification): the
    // path runs the other way round, so G02 ↔ G03 and G41 ↔ G42 swap [FANUC].
    bool reverses(motion::Plane plane) const;
    // The factor an arc's R is scaled by: the larger magnification of the plane's two axes (with
    // unequal ones FANUC does not cut an ellipse; the larger one keeps every scaled chord within 2R).
    double radius_factor(motion::Plane plane) const;
};

}  // namespace kerf::interpreter
