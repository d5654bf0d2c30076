#include "motion/polar.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kerf::motion {

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
constexpr double kMaxTurnDeg = 45.0;   // a piece turns at most this much (keeps the unwrapping sound)

// The angle deg + 360·k nearest near_deg.
double nearest_branch(double deg, double near_deg) {
    return deg + 360.0 * std::round((near_deg - deg) / 360.0);
}

// Distance from the origin to the segment p–q.
double segment_distance_to_origin(P2 p, P2 q) {
    const P2 d = q - p;
    const double len2 = dot(d, d);
    const double t = len2 > 0 ? std::clamp(-dot(p, d) / len2, 0.0, 1.0) : 0.0;
    return norm(p + d * t);
}

}  // namespace

P2 to_machine(const PlaneMap& map, P2 c, double near_deg) {
    if (map.kind == PlaneMap::Kind::cylindrical) return {c.a, c.b / map.cylinder_radius * kDegPerRad};
    const double r = std::hypot(c.a, c.b);
    if (r == 0) return {0, near_deg};
    return {r, nearest_branch(std::atan2(c.b, c.a) * kDegPerRad, near_deg)};
}

P2 to_cartesian(const PlaneMap& map, P2 m) {
    if (map.kind == PlaneMap::Kind::cylindrical) return {m.a, m.b / kDegPerRad * map.cylinder_radius};
    return {m.a * std::cos(m.b / kDegPerRad), m.a * std::sin(m.b / kDegPerRad)};
}

std::vector<MappedPoint> map_path(const PlaneMap& map, const std::function<P2(double)>& path, double start_deg,
                                  double tolerance, std::size_t max_points) {
    std::vector<MappedPoint> out;
    const double tol = std::max(tolerance, 1e-9);
    constexpr double kMinStep = 1.0 / (1 << 20);
    MappedPoint from{0, path(0), {}};
    from.machine = to_machine(map, from.cartesian, start_deg);
    double step = 1.0;
    while (from.t < 1.0) {
        const double t = std::min(1.0, from.t + step);
        MappedPoint to{t, path(t), {}};
        to.machine = to_machine(map, to.cartesian, from.machine.b);
        // The machine moves its axes linearly: at the middle of the piece it is at the mean of
        // the two machine points; the programmed path is at the middle parameter.
        const P2 tool = to_cartesian(map, (from.machine + to.machine) * 0.5);
        const double error = norm(tool - path((from.t + t) / 2));
        const bool turns = map.kind == PlaneMap::Kind::polar && std::fabs(to.machine.b - from.machine.b) > kMaxTurnDeg;
        const bool small = error <= tol && !turns;
        if (!small && step > kMinStep && out.size() + 1 < max_points) {
            step /= 2;
            continue;
        }
        if (t == 1.0) to.cartesian = path(1.0);
        out.push_back(to);
        from = to;
        step = std::min(1.0, step * 2);
        if (out.size() + 1 >= max_points && from.t < 1.0) {   // the budget is spent: straight to the end
            MappedPoint end{1.0, path(1.0), {}};
            end.machine = to_machine(map, end.cartesian, from.machine.b);
            out.push_back(end);
            break;
        }
    }
    return out;
}

double min_radius(const std::vector<MappedPoint>& points, P2 start) {
    double best = norm(start);
    P2 prev = start;
    for (const MappedPoint& p : points) {
        best = std::min(best, segment_distance_to_origin(prev, p.cartesian));
        prev = p.cartesian;
    }
    return best;
}

}  // namespace kerf::motion
