#include "motion/corner.hpp"

namespace kerf::motion {

namespace {
constexpr double kParallel = 1e-12;   // |sin| of the angle between unit directions
constexpr double kPi = 3.14159265358979323846;
}  // namespace

P2 direction_at(double degrees) {
    const double r = degrees * kPi / 180.0;
    return {std::cos(r), std::sin(r)};
}

double turn_angle(P2 from, P2 to) { return std::atan2(cross(from, to), dot(from, to)); }

std::optional<P2> intersect(P2 p, P2 dp, P2 q, P2 dq) {
    const double d = cross(dp, dq);
    if (std::fabs(d) <= kParallel * norm(dp) * norm(dq)) return std::nullopt;
    // p + s·dp = q + t·dq  →  s = ((q − p) × dq) / (dp × dq)
    const double s = cross(q - p, dq) / d;
    return p + dp * s;
}

std::optional<P2> point_with_coordinate(P2 p, P2 d, bool second, double value) {
    const double along = second ? d.b : d.a;
    if (std::fabs(along) <= kParallel * norm(d)) return std::nullopt;
    const double s = (value - (second ? p.b : p.a)) / along;
    P2 out = p + d * s;
    (second ? out.b : out.a) = value;   // exact on the named coordinate
    return out;
}

CornerPiece chamfer(P2 corner, P2 dir_in, P2 dir_out, double c) {
    CornerPiece piece;
    piece.setback = c;
    piece.in_end = corner - unit(dir_in) * c;
    piece.out_start = corner + unit(dir_out) * c;
    return piece;
}

std::optional<CornerPiece> fillet(P2 corner, P2 dir_in, P2 dir_out, double r) {
    const P2 in = unit(dir_in), out = unit(dir_out);
    const double turn = turn_angle(in, out);
    if (std::fabs(std::fabs(turn) - kPi) < 1e-9) return std::nullopt;
    CornerPiece piece;
    piece.setback = r * std::tan(std::fabs(turn) / 2);
    piece.in_end = corner - in * piece.setback;
    piece.out_start = corner + out * piece.setback;
    if (std::fabs(turn) < 1e-12) return piece;   // straight on: nothing to round
    piece.arc = true;
    piece.radius = r;
    piece.sweep = turn;
    // The centre lies r from the incoming line on the side the path turns to.
    piece.center = piece.in_end + left_normal(in) * (turn > 0 ? r : -r);
    return piece;
}

}  // namespace kerf::motion
