// The programmed-point stage (transforms.hpp): rotation, scaling, mirror as one map.
#include "interpreter/transforms.hpp"

#include <algorithm>
#include <cmath>

namespace kerf::interpreter {

namespace {

Position rotate(const Position& p, const Rotation& r, double angle) {
    const auto [i, j] = plane_indices(r.plane);
    const double u = p[i] - r.center_first;
    const double v = p[j] - r.center_second;
    Position out = p;
    out[i] = r.center_first + u * std::cos(angle) - v * std::sin(angle);
    out[j] = r.center_second + u * std::sin(angle) + v * std::cos(angle);
    return out;
}

// Scaling about the centre by the factors (inverse: by their reciprocals; a zero factor is
// refused when G51 is read, executor_transforms.cpp).
Position scale(const Position& p, const Scaling& s, bool inverse) {
    Position out = p;
    for (std::size_t a = 0; a < 3; ++a) {
        const double k = inverse ? 1.0 / s.factor[a] : s.factor[a];
        out[a] = s.center[a] + (p[a] - s.center[a]) * k;
    }
    return out;
}

// A mirror is its own inverse: x → 2m − x on each mirrored axis.
Position reflect(const Position& p, const Mirror& m) {
    Position out = p;
    for (std::size_t a = 0; a < kAxisCount; ++a)
        if (m[a]) out[a] = 2 * *m[a] - p[a];
    return out;
}

double sign(bool negative) { return negative ? -1.0 : 1.0; }

}  // namespace

std::pair<std::size_t, std::size_t> plane_indices(motion::Plane plane) {
    const motion::PlaneAxes axes = motion::plane_axes(plane);
    return {static_cast<std::size_t>(axes.first), static_cast<std::size_t>(axes.second)};
}

bool ProgramFrame::identity() const {
    return !scaling && !rotation && std::none_of(mirror.begin(), mirror.end(), [](const auto& m) { return m.has_value(); });
}

Position ProgramFrame::to_work(const Position& program) const {
    Position p = rotation ? rotate(program, *rotation, rotation->angle) : program;
    if (scaling) p = scale(p, *scaling, false);
    return reflect(p, mirror);
}

Position ProgramFrame::to_program(const Position& work) const {
    Position p = reflect(work, mirror);
    if (scaling) p = scale(p, *scaling, true);
    return rotation ? rotate(p, *rotation, -rotation->angle) : p;
}

motion::Vec3 ProgramFrame::vector_to_work(motion::Vec3 v) const {
    if (rotation) {
        const motion::PlaneAxes axes = motion::plane_axes(rotation->plane);
        const double u = motion::get(v, axes.first), w = motion::get(v, axes.second);
        motion::set(v, axes.first, u * std::cos(rotation->angle) - w * std::sin(rotation->angle));
        motion::set(v, axes.second, u * std::sin(rotation->angle) + w * std::cos(rotation->angle));
    }
    for (const motion::Axis a : {motion::Axis::x, motion::Axis::y, motion::Axis::z}) {
        const std::size_t i = static_cast<std::size_t>(a);
        const double k = (scaling ? scaling->factor[i] : 1.0) * sign(mirror[i].has_value());
        motion::set(v, a, motion::get(v, a) * k);
    }
    return v;
}

bool ProgramFrame::reverses(motion::Plane plane) const {
    const auto [i, j] = plane_indices(plane);
    bool odd = mirror[i].has_value() != mirror[j].has_value();
    if (scaling) odd = odd != ((scaling->factor[i] < 0) != (scaling->factor[j] < 0));
    return odd;
}

double ProgramFrame::radius_factor(motion::Plane plane) const {
    if (!scaling) return 1.0;
    const auto [i, j] = plane_indices(plane);
    return std::max(std::fabs(scaling->factor[i]), std::fabs(scaling->factor[j]));
}

}  // namespace kerf::interpreter
