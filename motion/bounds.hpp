// Axis-aligned bounding boxes and the soft-limit (stored stroke limit) check.
#pragma once

#include <limits>
#include <vector>

#include "motion/vec.hpp"

namespace kerf::motion {

// An axis-aligned box; default-constructed it is empty (min = +inf, max = −inf), so the first
// extend() makes it the point itself. Boxes of lines and arcs are exact (line.hpp, arc.hpp).
struct Box {
    static constexpr double inf = std::numeric_limits<double>::infinity();
    Vec3 min{inf, inf, inf};
    Vec3 max{-inf, -inf, -inf};

    constexpr bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void extend(Vec3 p);
    void merge(const Box& other);   // extend by another box (an empty one changes nothing)
    // True when p lies inside the box grown by tol on every side (false for an empty box).
    bool contains(Vec3 p, double tol = 0.0) const;
    // max − min per axis; zero vector for an empty box.
    Vec3 size() const;
};

// The smallest box holding both points.
Box box_of(Vec3 a, Vec3 b);

// Stored stroke limits (FANUC "stored stroke check 1", parameters 1320/1321; overtravel alarms
// OT500/OT501 [FANUC]). Values are machine coordinates of the control point; an axis without a
// limit keeps ±infinity. The reference only lists "soft limits" as machine configuration
// (design.md); the check is kept geometric so the interpreter decides what to report.
struct SoftLimits {
    static constexpr double inf = std::numeric_limits<double>::infinity();
    Vec3 min{-inf, -inf, -inf};
    Vec3 max{inf, inf, inf};
};

enum class LimitSide { below_min, above_max };

struct LimitViolation {
    Axis axis;
    LimitSide side;
    double excess;   // how far past the limit, > 0 (same unit as the coordinates)
    double limit;    // the limit that was passed
    double value;    // the extreme coordinate that passed it
};

// Every limit the point passes (none, one per axis). A value exactly on the limit is allowed.
std::vector<LimitViolation> check_soft_limits(Vec3 point, const SoftLimits& limits);
// Every limit the box passes: a move is inside the limits when its exact box is (a box can pass
// both limits of one axis, so up to six entries). Empty box: no violations.
std::vector<LimitViolation> check_soft_limits(const Box& box, const SoftLimits& limits);

}  // namespace kerf::motion
