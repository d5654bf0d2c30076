#include "motion/bounds.hpp"

#include <algorithm>

namespace kerf::motion {

void Box::extend(Vec3 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
}

void Box::merge(const Box& other) {
    if (other.empty()) return;
    extend(other.min);
    extend(other.max);
}

bool Box::contains(Vec3 p, double tol) const {
    if (empty()) return false;
    return p.x >= min.x - tol && p.x <= max.x + tol && p.y >= min.y - tol && p.y <= max.y + tol &&
           p.z >= min.z - tol && p.z <= max.z + tol;
}

Vec3 Box::size() const {
    if (empty()) return {};
    return max - min;
}

Box box_of(Vec3 a, Vec3 b) {
    Box box;
    box.extend(a);
    box.extend(b);
    return box;
}

namespace {

void check_axis(Axis axis, double lo, double hi, const SoftLimits& limits,
                std::vector<LimitViolation>& out) {
    const double min_limit = get(limits.min, axis);
    const double max_limit = get(limits.max, axis);
    if (lo < min_limit) out.push_back({axis, LimitSide::below_min, min_limit - lo, min_limit, lo});
    if (hi > max_limit) out.push_back({axis, LimitSide::above_max, hi - max_limit, max_limit, hi});
}

}  // namespace

std::vector<LimitViolation> check_soft_limits(Vec3 point, const SoftLimits& limits) {
    std::vector<LimitViolation> out;
    for (Axis a : {Axis::x, Axis::y, Axis::z}) check_axis(a, get(point, a), get(point, a), limits, out);
    return out;
}

std::vector<LimitViolation> check_soft_limits(const Box& box, const SoftLimits& limits) {
    std::vector<LimitViolation> out;
    if (box.empty()) return out;
    for (Axis a : {Axis::x, Axis::y, Axis::z}) check_axis(a, get(box.min, a), get(box.max, a), limits, out);
    return out;
}

}  // namespace kerf::motion
