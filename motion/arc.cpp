#include "motion/arc.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kerf::motion {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

// Angle reduced to [0, 2π).
double wrap(double a) {
    double r = std::fmod(a, two_pi);
    if (r < 0.0) r += two_pi;
    if (r >= two_pi) r = 0.0;
    return r;
}

// Signed sweep from angle a0 to angle a1 in the given direction; full = 2π (signed).
double sweep_between(double a0, double a1, bool cw, bool full) {
    if (full) return cw ? -two_pi : two_pi;
    return cw ? -wrap(a0 - a1) : wrap(a1 - a0);
}

ArcError error(ArcErrorCode code, int alarm = 0, double found = 0.0, double allowed = 0.0) {
    return ArcError{code, alarm, found, allowed};
}

// Common tail of both forms: the centre is known (in-plane coordinates c1, c2).
ArcResult finish(Vec3 start, Vec3 end, Plane plane, bool cw, double c1, double c2,
                 const ArcOptions& options) {
    const PlanePoint s = to_plane(start, plane);
    const PlanePoint e = to_plane(end, plane);
    const double r0 = std::hypot(s.first - c1, s.second - c2);
    const double r1 = std::hypot(e.first - c1, e.second - c2);
    const double mismatch = std::fabs(r1 - r0);
    const double eps = options.same_point_eps;
    if (std::min(r0, r1) <= eps) {
        if (mismatch > options.radius_tolerance)
            return error(ArcErrorCode::radius_mismatch, 20, mismatch, options.radius_tolerance);
        return error(ArcErrorCode::zero_radius);
    }
    // semantics.md §3: "[FANUC] if the end point is not on the circle within tolerance → alarm".
    if (mismatch > options.radius_tolerance)
        return error(ArcErrorCode::radius_mismatch, 20, mismatch, options.radius_tolerance);
    const bool full = std::hypot(e.first - s.first, e.second - s.second) <= eps;
    const double a0 = std::atan2(s.second - c2, s.first - c1);
    const double a1 = std::atan2(e.second - c2, e.first - c1);
    Arc arc{};
    arc.start = start;
    arc.end = end;
    arc.center = from_plane({c1, c2, s.normal}, plane);
    arc.radius = r0;
    arc.end_radius = r1;
    arc.sweep = sweep_between(a0, a1, cw, full);
    arc.plane = plane;
    arc.cw = cw;
    arc.helix_length = e.normal - s.normal;
    return arc;
}

}  // namespace

const char* describe(ArcErrorCode code) {
    switch (code) {
    case ArcErrorCode::invalid_input: return "arc word or coordinate is not a finite number";
    case ArcErrorCode::zero_radius: return "arc radius is zero";
    case ArcErrorCode::radius_mismatch: return "end point is not on the arc (start and end radii differ)";
    case ArcErrorCode::r_too_small: return "arc radius R is too small for the distance to the end point";
    case ArcErrorCode::r_zero_chord: return "R form with the end point equal to the start point (no motion)";
    case ArcErrorCode::negative_r_unsupported: return "negative R (arc over 180 degrees) is not supported";
    }
    return "arc error";
}

ArcResult arc_from_center(Vec3 start, Vec3 end, Plane plane, ArcDirection dir, Vec3 center_offset,
                          const ArcOptions& options) {
    if (!is_finite(start) || !is_finite(end) || !is_finite(center_offset))
        return error(ArcErrorCode::invalid_input);
    const PlanePoint s = to_plane(start, plane);
    const PlanePoint o = to_plane(center_offset, plane);
    return finish(start, end, plane, dir == ArcDirection::cw, s.first + o.first, s.second + o.second,
                  options);
}

ArcResult arc_from_radius(Vec3 start, Vec3 end, Plane plane, ArcDirection dir, double r,
                          const ArcOptions& options) {
    if (!is_finite(start) || !is_finite(end) || !std::isfinite(r)) return error(ArcErrorCode::invalid_input);
    if (std::fabs(r) <= options.same_point_eps) return error(ArcErrorCode::zero_radius);
    if (r < 0.0 && !options.allow_negative_r) return error(ArcErrorCode::negative_r_unsupported);
    const bool cw = dir == ArcDirection::cw;
    const PlanePoint s = to_plane(start, plane);
    const PlanePoint e = to_plane(end, plane);
    const double d1 = e.first - s.first;
    const double d2 = e.second - s.second;
    const double chord = std::hypot(d1, d2);
    if (chord <= options.same_point_eps) return error(ArcErrorCode::r_zero_chord);
    const double half = chord / 2.0;
    double rr = std::fabs(r);
    if (half > rr + options.radius_tolerance) {
        if (!options.enlarge_small_r)
            return error(ArcErrorCode::r_too_small, 20, half, rr + options.radius_tolerance);
        rr = half;
    }
    // Distance from the chord midpoint to the centre; 0 for a semicircle (chord = 2R within tol).
    const double h = half >= rr ? 0.0 : std::sqrt((rr - half) * (rr + half));
    // Left normal of the chord direction in the plane frame. The centre of a CCW arc of at most
    // 180° lies to the left of the chord (travelling start → end), of a CW one to the right; the
    // arc of more than 180° (R < 0) takes the other centre.
    const double u1 = d1 / chord;
    const double u2 = d2 / chord;
    const double left1 = -u2;
    const double left2 = u1;
    const double side = (cw ? -1.0 : 1.0) * (r > 0.0 ? 1.0 : -1.0);
    const double c1 = s.first + d1 / 2.0 + side * h * left1;
    const double c2 = s.second + d2 / 2.0 + side * h * left2;
    ArcResult result = finish(start, end, plane, cw, c1, c2, options);
    if (result.ok() && h == 0.0) {
        // Semicircle: both centres coincide; the direction alone picks the side. Make the sweep
        // exactly ±π (atan2 of the two ends may land on either side of the cut).
        Arc arc = result.arc();
        arc.sweep = cw ? -std::numbers::pi : std::numbers::pi;
        return arc;
    }
    return result;
}

double start_angle(const Arc& arc) {
    const PlanePoint s = to_plane(arc.start, arc.plane);
    const PlanePoint c = to_plane(arc.center, arc.plane);
    return std::atan2(s.second - c.second, s.first - c.first);
}

double planar_length(const Arc& arc) { return std::fabs(arc.sweep) * (arc.radius + arc.end_radius) / 2.0; }

double length(const Arc& arc) { return std::hypot(planar_length(arc), arc.helix_length); }

Vec3 point_at(const Arc& arc, double t) {
    if (!(t > 0.0)) return arc.start;
    if (t >= 1.0) return arc.end;
    const PlanePoint s = to_plane(arc.start, arc.plane);
    const PlanePoint c = to_plane(arc.center, arc.plane);
    const double a = start_angle(arc) + t * arc.sweep;
    const double r = arc.radius + t * (arc.end_radius - arc.radius);
    return from_plane({c.first + r * std::cos(a), c.second + r * std::sin(a), s.normal + t * arc.helix_length},
                      arc.plane);
}

Vec3 tangent_at(const Arc& arc, double t) {
    t = std::clamp(t, 0.0, 1.0);
    const double a = start_angle(arc) + t * arc.sweep;
    const double r = arc.radius + t * (arc.end_radius - arc.radius);
    const double dr = arc.end_radius - arc.radius;
    // d/dt of (c + r(t)·(cos a, sin a), n0 + t·h).
    const PlanePoint d{dr * std::cos(a) - r * arc.sweep * std::sin(a),
                       dr * std::sin(a) + r * arc.sweep * std::cos(a), arc.helix_length};
    const Vec3 v = from_plane(d, arc.plane);
    const double n = norm(v);
    return n > 0.0 ? v / n : Vec3{};
}

Box bounds(const Arc& arc) {
    Box box = box_of(arc.start, arc.end);
    const double a0 = start_angle(arc);
    const double span = std::fabs(arc.sweep);
    if (!(span > 0.0)) return box;
    for (int k = 0; k < 4; ++k) {
        const double q = k * (std::numbers::pi / 2.0);
        // How far (radians, in the direction of travel) the quadrant angle q lies from the start.
        const double ahead = arc.sweep > 0.0 ? wrap(q - a0) : wrap(a0 - q);
        if (ahead <= span) box.extend(point_at(arc, ahead / span));
    }
    return box;
}

}  // namespace kerf::motion
