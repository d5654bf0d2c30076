// Feed and time model: rapid moves, feed moves (per minute, per revolution, constant surface
// speed), acceleration, dwell. semantics.md §4 (feed and speed), §4.1 (G96/G97/G50 S), §8
// (exact stop, dwell); gcode-tables.md §5 (seed 003 G00: "non-linear" dog-leg or "linear").
//
// Units (explicit in every name): time in seconds; lengths in mm (geometric: lathe X as a radius);
// feed per minute in mm/min; feed per revolution in mm/rev; spindle speed in rev/min; surface
// speed in m/min; rapid rates in mm/min and accelerations in mm/s² per axis (a rotary axis uses
// its own unit, deg/min and deg/s², in the span-based functions).
//
// Acceleration model: EXACT STOP. Every move starts and ends at rest and follows a trapezoidal
// (or triangular) velocity profile: a move of length L at speed v with acceleration a takes
// L/v + v/a when it reaches v (L ≥ v²/a), otherwise 2·sqrt(L/a). This is what G09/G61 do, and
// what G64 still does for G00 and before a block without motion (semantics.md §8.1). Blending of
// consecutive G64 cutting blocks (no stop at the corner) is NOT modelled yet, so times of
// continuous contours are upper bounds. Jerk limits, arc centripetal limits, spindle run-up and
// feed override are not modelled. An acceleration of 0 (or +inf) means "not modelled": the move
// runs at full speed from the first instant.
//
// Degenerate input: a length of 0 takes 0 s; a positive length with a speed or feed ≤ 0 takes
// +infinity (FANUC would not move: "no feed" alarm, or G99 with the spindle stopped, §4 – the
// interpreter reports it; the kernel only keeps the arithmetic total).
#pragma once

#include <optional>

#include <limits>
#include <span>
#include <vector>

#include "motion/arc.hpp"
#include "motion/line.hpp"
#include "motion/vec.hpp"

namespace kerf::motion {

struct AxisLimits {
    double rapid_mm_min = 0.0;  // G00 rate of this axis
    double accel_mm_s2 = 0.0;   // 0 = acceleration not modelled
};

struct AxisLimits3 {
    AxisLimits x;
    AxisLimits y;
    AxisLimits z;
    constexpr const AxisLimits& operator[](Axis a) const { return a == Axis::x ? x : a == Axis::y ? y : z; }
};

// G00 interpolation, FANUC parameter LRP (gcode-tables.md §5, seed 003 G00 row):
//   straight – "linear": the tool moves on the straight line; the path speed is the highest at
//              which no axis exceeds its own rapid rate (and, with acceleration, its own
//              acceleration), so the axis that needs the longest time runs at its own rate and
//              the others are scaled down;
//   dog_leg  – "non-linear": every axis runs at its own rate independently; the axes arrive one
//              after another and the block ends when the slowest one arrives.
// Without acceleration both take max_i(d_i / v_i); they differ when the axis limiting the speed
// is not the one limiting the acceleration (then straight is slower), and in the path they trace.
enum class RapidMode { straight, dog_leg };

// Time (s) of a rest-to-rest move of `length` at top speed v (mm/s) with acceleration a (mm/s²).
double trapezoid_time(double length, double v_mm_s, double accel_mm_s2);

// Time (s) of a G00 move; travel[i] is the signed or unsigned travel of axis i, limits[i] its
// limits (only the first min(size) axes are used).
//   dog_leg : max_i trapezoid_time(|d_i|, v_i, a_i)
//   straight: every axis follows d_i·σ(t) with σ from 0 to 1; σ' ≤ min_i v_i/|d_i| and
//             σ'' ≤ min_i a_i/|d_i| over the moving axes; time = trapezoid_time(1, those two).
double rapid_time(std::span<const double> travel, std::span<const AxisLimits> limits, RapidMode mode);
double rapid_time(Vec3 delta, const AxisLimits3& limits, RapidMode mode);

// The corners of a dog-leg rapid from start to end at constant axis speeds (acceleration
// ignored): start, the point where each axis in turn arrives, end (repeated points dropped).
// For plots and collision warnings; the straight mode path is the Line itself.
std::vector<Vec3> dog_leg_path(Vec3 start, Vec3 end, const AxisLimits3& limits);

// Path acceleration (mm/s²) of a straight move along `delta` such that no axis exceeds its own
// acceleration: min_i a_i/|u_i| (u the unit direction); +inf when no moving axis has one.
double path_accel(Vec3 delta, const AxisLimits3& limits);

// semantics.md §4 [seed 003]: feed per minute = feed per revolution × rpm.
constexpr double feed_per_minute(double feed_mm_rev, double rpm) { return feed_mm_rev * rpm; }

// G34 variable-lead threading (cycles.md §9, [FANUC] `G34 X Z F(L0) K(ΔL per revolution)`): the
// lead after n revolutions is L0 + K·n, so the distance after n revolutions is the integral
// ∫0^n (L0 + K·m) dm = L0·n + K·n²/2. A thread of `length` takes the n that solves
// K/2·n² + L0·n − length = 0: n = (√(L0² + 2·K·length) − L0) / K (n = length / L0 for K = 0), and
// ends with the lead L0 + K·n = √(L0² + 2·K·length). nullopt when the lead reaches zero first
// (L0² + 2·K·length ≤ 0 or L0 ≤ 0: [FANUC] alarm 313, lead level error).
struct VariableLead {
    double revolutions;
    double lead_end;
};
std::optional<VariableLead> variable_lead(double length, double lead_start, double lead_change);

// Time (s) of a cutting move of `length` (mm; line or arc length, tangential feed §3) at
// feed_mm_min; with accel_mm_s2 > 0 the exact-stop trapezoid is added.
double feed_time(double length, double feed_mm_min, double accel_mm_s2 = 0.0);

// Spindle speed limits that apply under G96: max_rpm = min(G50/G92 S clamp, machine maximum),
// min_rpm = the spindle's lowest speed (or 0).
struct SpindleClamp {
    double max_rpm = std::numeric_limits<double>::infinity();
    double min_rpm = 0.0;
};

// semantics.md §4.1: n = 1000·Vc/(π·D), D = |diameter|, clamped to [min_rpm, max_rpm]; D = 0
// gives max_rpm (+inf without a clamp). Vc ≤ 0 gives min_rpm.
double css_rpm(double surface_m_min, double diameter_mm, const SpindleClamp& clamp);

// Time (s) of a feed-per-revolution move under G96 whose diameter varies LINEARLY along the path
// from d_start to d_end (signed diameters; D = |d|, so a facing cut may pass the axis):
//   time = ∫ ds / (f · n(D(s)))
// Method: exact, analytic. The path is cut where D crosses 0 and where n(D) reaches max_rpm or
// min_rpm; on a clamped piece n is constant (time = len / (f·n_clamp)); on a free piece
// 1/(f·n) = π·D/(1000·Vc·f) is linear in s, so time = π·len·(D_a + D_b)/2 / (1000·Vc·f) min.
// (FANUC computes the rpm continuously for cutting moves; for G00 from the end point, §4.1.)
double css_feed_time(double length, double d_start_mm, double d_end_mm, double surface_m_min,
                     double feed_mm_rev, const SpindleClamp& clamp);

// The same for geometric moves with the spindle axis at radial_axis = 0: D = 2·|radial coordinate|
// (lathe X as a radius). A Line is exact (the function above). An Arc is cut at its quadrant points
// (where an in-plane radial coordinate has its extremes), at most every 30°, and where D crosses 0
// or a clamp diameter (bisection; the coordinate is monotonic between the quadrant points); each
// piece has one regime and a smooth integrand (a sinusoid or a constant) and is integrated by
// 8-point Gauss-Legendre: exact to rounding for a circle (tests/motion/test_time.cpp compares a
// quarter circle with its closed form to 1e-9). On the tolerance spiral (arc.hpp) the radius is
// taken linear in t as everywhere else.
double css_feed_time(const Line& line, double surface_m_min, double feed_mm_rev, const SpindleClamp& clamp,
                     Axis radial_axis = Axis::x);
double css_feed_time(const Arc& arc, double surface_m_min, double feed_mm_rev, const SpindleClamp& clamp,
                     Axis radial_axis = Axis::x);

// G04 (semantics.md §8.2). The interpreter decodes the words (X/U seconds, P milliseconds on
// FANUC, P seconds on ADV400, decimal-point rules); revolutions is the FANUC option of dwelling a
// number of spindle turns under G95/G99 (needs rpm > 0). Negative values count as 0 s.
enum class DwellUnit { seconds, milliseconds, revolutions };
double dwell_time(double value, DwellUnit unit, double rpm = 0.0);

}  // namespace kerf::motion
