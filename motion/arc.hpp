// Circular and helical moves (G02/G03), semantics.md §3.
//
// Conventions
// * Coordinates are geometric (lathe X already converted from diameter to radius by the caller).
// * Direction: G02 = ArcDirection::cw, G03 = ArcDirection::ccw, seen from the positive end of the
//   plane's normal axis (vec.hpp: G17 from +Z, G18 from +Y, G19 from +X). In every plane frame
//   (first, second) a CCW arc has a positive sweep, a CW arc a negative one.
// * Centre form: the offset is the I/J/K vector from the start point to the centre, incremental
//   regardless of G90/G91 (semantics.md §3), passed as {I, J, K} in X/Y/Z; only the two in-plane
//   components are used (G17: I, J; G18: K, I; G19: J, K). End = start gives a full circle.
// * Radius form: R > 0 the arc of at most 180°, R < 0 the arc of more than 180° [FANUC mills];
//   R cannot describe a full circle. A chord of 2|R| within the radius tolerance is a semicircle
//   (SPINNER `G2 X106 Z-37,5 R15`, semantics.md §3).
// * Helix: the motion along the normal axis (end.normal − start.normal) is spread linearly over
//   the sweep; `helix_length` is that signed displacement.
// * Radius tolerance: an I/J/K arc whose end radius differs from its start radius by more than
//   the tolerance is FANUC alarm 020 (the FANUC limit is parameter 3410, set by the builder; the
//   reference gives no number). Default 0.01 mm, between the usual control defaults (Beckhoff
//   5 µm, Okuma 20 µm). Within the tolerance the control moves on a spiral from the start radius
//   to the end radius; the kernel models that spiral (radius linear in the angle).
#pragma once

#include <cmath>
#include <numbers>
#include <variant>

#include "motion/bounds.hpp"
#include "motion/vec.hpp"

namespace kerf::motion {

enum class ArcDirection { cw, ccw };   // G02, G03

struct Arc {
    Vec3 start;
    Vec3 end;
    Vec3 center;                // in-plane centre; its normal component equals start's
    double radius = 0.0;        // in-plane distance start–centre
    double sweep = 0.0;         // signed radians: > 0 CCW (G03), < 0 CW (G02); ±2π full circle
    Plane plane = Plane::xy;
    bool cw = false;            // G02
    double helix_length = 0.0;  // signed travel along the plane normal (end − start)
    double end_radius = 0.0;    // in-plane distance end–centre (== radius up to the tolerance)
};

enum class ArcErrorCode {
    invalid_input,           // a coordinate, offset or R is not finite
    zero_radius,             // centre on the start or end point (I=J=K=0, R0)
    radius_mismatch,         // |end radius − start radius| > tolerance      (FANUC alarm 020)
    r_too_small,             // R form: chord > 2|R| + tolerance             (FANUC alarm 020 [inference])
    r_zero_chord,            // R form with end = start in the plane: FANUC runs a 0° arc, no motion
    negative_r_unsupported,  // R < 0 with ArcOptions::allow_negative_r off (many lathes, §3)
};

struct ArcError {
    ArcErrorCode code;
    int fanuc_alarm;   // FANUC alarm number this corresponds to, 0 when none
    double found;      // radius_mismatch: |r_end − r_start|; r_too_small: chord/2; otherwise 0
    double allowed;    // radius_mismatch: tolerance; r_too_small: |R| + tolerance; otherwise 0
};

// Short English text for a code (the analyzer owns the user-facing messages).
const char* describe(ArcErrorCode code);

struct ArcOptions {
    double radius_tolerance = 0.01;  // mm; FANUC parameter 3410 analogue
    bool allow_negative_r = true;    // mills: R < 0 is the >180° arc; lathes: often unsupported
    bool enlarge_small_r = false;    // some models enlarge a too small R to chord/2 (§3)
    double same_point_eps = 1e-6;    // in-plane chord below this = same point (full circle)
};

// Either an Arc or an ArcError.
class ArcResult {
public:
    ArcResult(const Arc& arc) : value_(arc) {}
    ArcResult(const ArcError& error) : value_(error) {}
    bool ok() const { return std::holds_alternative<Arc>(value_); }
    explicit operator bool() const { return ok(); }
    const Arc& arc() const { return std::get<Arc>(value_); }         // precondition: ok()
    const ArcError& error() const { return std::get<ArcError>(value_); }  // precondition: !ok()

private:
    std::variant<Arc, ArcError> value_;
};

// Centre form: G02/G03 with I/J/K (center_offset = {I, J, K}, incremental from start).
ArcResult arc_from_center(Vec3 start, Vec3 end, Plane plane, ArcDirection dir, Vec3 center_offset,
                          const ArcOptions& options = {});

// Radius form: G02/G03 with R (signed, see above).
ArcResult arc_from_radius(Vec3 start, Vec3 end, Plane plane, ArcDirection dir, double r,
                          const ArcOptions& options = {});

inline bool is_full_circle(const Arc& arc) { return std::fabs(arc.sweep) >= 2.0 * std::numbers::pi; }

// Angle of the start point about the centre in the plane frame: atan2(second, first), radians.
double start_angle(const Arc& arc);

// In-plane path length |sweep|·(r_start + r_end)/2 (exact for a circle; for the tolerance spiral
// the neglected term is of order (Δr)²/r).
double planar_length(const Arc& arc);

// Path length including the helix: sqrt(planar² + helix²) (a helix is a line on the unrolled
// cylinder).
double length(const Arc& arc);

// The length the programmed F applies to: for a helix the feed is tangential along the arc in
// the plane and the normal axis follows at F × (helix / planar length) (semantics.md §3, ADV400
// "axis feed F × (axis length / arc length)"; [FANUC] the same), so feed time = planar_length / F,
// not length / F. Equal to length() when there is no helix.
inline double feed_length(const Arc& arc) { return planar_length(arc); }

// Point at parameter t in [0, 1] (clamped): angle start + t·sweep, radius and normal coordinate
// linear in t; t = 0 is start and t = 1 is end exactly. t is proportional to the path length.
Vec3 point_at(const Arc& arc, double t);

// Unit tangent (direction of motion) at parameter t.
Vec3 tangent_at(const Arc& arc, double t);

// Exact axis-aligned box: the end points plus every quadrant point (angle 0, 90°, 180°, 270° in
// the plane frame) that the sweep passes; the normal axis is linear, so its extremes are the end
// points.
Box bounds(const Arc& arc);

}  // namespace kerf::motion
