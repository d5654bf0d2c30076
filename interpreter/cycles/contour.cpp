#include "interpreter/cycles/contour.hpp"

#include <cmath>
#include <algorithm>
#include <numbers>

namespace kerf::interpreter::cycles {

namespace {

constexpr double kEps = 1e-9;
constexpr double kTwoPi = 2 * std::numbers::pi;

// Parameter t in [0, 1] of angle `theta` on the arc, or nullopt when the sweep does not reach it.
std::optional<double> arc_parameter(const Seg& s, double theta) {
    double delta = s.sweep > 0 ? theta - s.a0 : s.a0 - theta;
    delta = std::fmod(delta, kTwoPi);
    if (delta < 0) delta += kTwoPi;
    if (delta > kTwoPi - 1e-12) delta = 0;
    const double t = delta / std::fabs(s.sweep);
    if (t > 1 + kEps) return std::nullopt;
    return std::min(t, 1.0);
}

// Angles where coordinate `c` of the circle equals `value` (x = cx + r sin θ, z = cz + r cos θ).
std::vector<double> circle_angles(const Seg& s, Coord c, double value) {
    const double q = (value - get(s.c, c)) / s.r;
    if (std::fabs(q) > 1 + kEps) return {};
    const double k = std::max(-1.0, std::min(1.0, q));
    if (c == Coord::x) return {std::asin(k), std::numbers::pi - std::asin(k)};
    return {std::acos(k), -std::acos(k)};
}

std::optional<double> crossing_t(const Seg& s, Coord c, double value) {
    if (!s.is_arc()) {
        const double a = get(s.a, c), b = get(s.b, c);
        if (std::fabs(b - a) < kEps) return std::fabs(a - value) < kEps ? std::optional<double>(0.0) : std::nullopt;
        const double t = (value - a) / (b - a);
        if (t < -kEps || t > 1 + kEps) return std::nullopt;
        return std::max(0.0, std::min(1.0, t));
    }
    std::optional<double> best;
    for (const double theta : circle_angles(s, c, value))
        if (const auto t = arc_parameter(s, theta); t && (!best || *t < *best)) best = t;
    return best;
}

// The part of segment s from t0 to t1.
Seg part(const Seg& s, double t0, double t1) {
    Seg p = s;
    p.a = point_at(s, t0);
    p.b = point_at(s, t1);
    if (s.is_arc()) {
        p.a0 = s.a0 + t0 * s.sweep;
        p.sweep = (t1 - t0) * s.sweep;
    }
    return p;
}

// Parameters t strictly inside (0, 1) where coordinate `c` of s equals `value`, ascending.
std::vector<double> inner_crossings(const Seg& s, Coord c, double value) {
    std::vector<double> ts;
    if (!s.is_arc()) {
        const double a = get(s.a, c), b = get(s.b, c);
        if (std::fabs(b - a) < kEps) return ts;
        const double t = (value - a) / (b - a);
        if (t > kEps && t < 1 - kEps) ts.push_back(t);
        return ts;
    }
    for (const double theta : circle_angles(s, c, value))
        if (const auto t = arc_parameter(s, theta); t && *t > kEps && *t < 1 - kEps) ts.push_back(*t);
    std::sort(ts.begin(), ts.end());
    if (ts.size() == 2 && ts[1] - ts[0] < kEps) ts.pop_back();   // tangent: one touch
    return ts;
}

}  // namespace

Pt to_pt(const Position& p, bool diameter_x) { return {diameter_x ? p[0] / 2 : p[0], p[2]}; }

Position to_position(Pt p, const Position& like, bool diameter_x) {
    Position out = like;
    out[0] = diameter_x ? p.x * 2 : p.x;
    out[2] = p.z;
    return out;
}

Contour contour_of(const Profile& profile, std::size_t first, bool diameter_x) {
    Contour out;
    Pt from = to_pt(first == 0 ? profile.start : profile.moves[first - 1].end, diameter_x);
    for (std::size_t i = first; i < profile.moves.size(); ++i) {
        const ProfileMove& m = profile.moves[i];
        Seg s;
        s.a = from;
        s.b = to_pt(m.end, diameter_x);
        s.kind = m.kind;
        s.move = i;
        if (s.is_arc()) {
            s.c = to_pt(m.center, diameter_x);
            s.r = std::hypot(s.a.x - s.c.x, s.a.z - s.c.z);
            s.a0 = std::atan2(s.a.x - s.c.x, s.a.z - s.c.z);
            s.sweep = m.sweep;
        }
        out.push_back(s);
        from = s.b;
    }
    return out;
}

Contour shifted(const Contour& contour, double dx, double dz) {
    Contour out = contour;
    for (Seg& s : out) {
        for (Pt* p : {&s.a, &s.b, &s.c}) {
            p->x += dx;
            p->z += dz;
        }
    }
    return out;
}

Pt point_at(const Seg& s, double t) {
    if (t <= 0) return s.a;
    if (t >= 1) return s.b;
    if (!s.is_arc()) return {s.a.x + (s.b.x - s.a.x) * t, s.a.z + (s.b.z - s.a.z) * t};
    const double theta = s.a0 + t * s.sweep;
    return {s.c.x + s.r * std::sin(theta), s.c.z + s.r * std::cos(theta)};
}

std::optional<Crossing> first_crossing(const Contour& contour, Coord c, double value) {
    for (std::size_t i = 0; i < contour.size(); ++i)
        if (const auto t = crossing_t(contour[i], c, value)) {
            Pt p = point_at(contour[i], *t);
            if (c == Coord::x) p.x = value;   // exact on the level
            else p.z = value;
            return Crossing{i, *t, p};
        }
    return std::nullopt;
}

Contour after(const Contour& contour, const Crossing& at) {
    Contour out;
    if (at.seg >= contour.size()) return out;
    Seg first = part(contour[at.seg], at.t, 1.0);
    first.a = at.p;
    if (std::hypot(first.b.x - first.a.x, first.b.z - first.a.z) > kEps) out.push_back(first);
    out.insert(out.end(), contour.begin() + static_cast<std::ptrdiff_t>(at.seg) + 1, contour.end());
    return out;
}

Contour split_at(const Contour& contour, Coord c, double value) {
    Contour out;
    for (const Seg& s : contour) {
        double from = 0;
        for (const double t : inner_crossings(s, c, value)) {
            Seg p = part(s, from, t);
            if (c == Coord::x) p.b.x = value;   // exact on the line
            else p.b.z = value;
            out.push_back(p);
            from = t;
        }
        Seg last = part(s, from, 1.0);
        if (from > 0) (c == Coord::x ? last.a.x : last.a.z) = value;
        out.push_back(last);
    }
    return out;
}

Contour until(const Contour& contour, const Crossing& at) {
    Contour out(contour.begin(), contour.begin() + static_cast<std::ptrdiff_t>(std::min(at.seg, contour.size())));
    if (at.seg >= contour.size()) return out;
    Seg last = part(contour[at.seg], 0.0, at.t);
    last.b = at.p;
    if (std::hypot(last.b.x - last.a.x, last.b.z - last.a.z) > kEps) out.push_back(last);
    return out;
}

double extreme(const Contour& contour, Coord c, double direction) {
    double best = -1e300;   // in direction · value
    const auto see = [&](Pt p) { best = std::max(best, direction * get(p, c)); };
    for (const Seg& s : contour) {
        see(s.a);
        see(s.b);
        if (!s.is_arc()) continue;
        // x = cx + r sin θ is extreme at θ = ±π/2, z = cz + r cos θ at θ = 0, π.
        const double h = std::numbers::pi / 2;
        for (const double theta : c == Coord::x ? std::vector<double>{h, -h} : std::vector<double>{0.0, std::numbers::pi})
            if (const auto t = arc_parameter(s, theta)) see(point_at(s, *t));
    }
    return direction * best;
}

std::optional<std::size_t> first_reversal(const Contour& contour, Coord c) {
    int direction = 0;   // +1 / −1 once known
    const auto step = [&](double from, double to) {
        const double d = to - from;
        if (std::fabs(d) < 1e-7) return true;
        const int sign = d > 0 ? 1 : -1;
        if (direction == 0) direction = sign;
        return sign == direction;
    };
    for (std::size_t i = 0; i < contour.size(); ++i) {
        const Seg& s = contour[i];
        if (!s.is_arc()) {
            if (!step(get(s.a, c), get(s.b, c))) return i;
            continue;
        }
        // An arc reverses the coordinate where it passes an extreme of the circle inside its sweep.
        double last = get(s.a, c);
        for (int k = 1; k <= 16; ++k) {
            const double now = get(point_at(s, k / 16.0), c);
            if (!step(last, now)) return i;
            last = now;
        }
    }
    return std::nullopt;
}

}  // namespace kerf::interpreter::cycles
