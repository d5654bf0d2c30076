#include "motion/time.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace kerf::motion {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

bool accel_modelled(double a) { return a > 0.0 && std::isfinite(a); }

std::array<double, 3> components(Vec3 v) { return {v.x, v.y, v.z}; }
std::array<AxisLimits, 3> components(const AxisLimits3& l) { return {l.x, l.y, l.z}; }

// Minutes of ∫ ds/(f·n) over a piece of length len on which the diameter goes linearly from
// da to db (both ≥ 0) and the regime (free or clamped) does not change.
double css_piece_minutes(double len, double da, double db, double vc, double f, const SpindleClamp& clamp) {
    const double d_mid = (da + db) / 2.0;
    if (vc > 0.0 && d_mid > 0.0) {
        const double n_free = 1000.0 * vc / (std::numbers::pi * d_mid);
        const double lo = std::max(clamp.min_rpm, 0.0);
        const double hi = std::max(clamp.max_rpm, lo);
        // Free piece: 1/(f·n) = π·D/(1000·Vc·f) is linear in s, the trapezoid rule is exact.
        if (n_free >= lo && n_free <= hi) return std::numbers::pi * len * d_mid / (1000.0 * vc * f);
    }
    // Clamped piece: constant rpm (+inf rpm, i.e. no clamp at D = 0, gives 0 min).
    const double n = css_rpm(vc, d_mid, clamp);
    if (!(n > 0.0)) return inf;
    return len / (f * n);
}

}  // namespace

double trapezoid_time(double length, double v_mm_s, double accel_mm_s2) {
    if (!(length > 0.0)) return 0.0;
    if (!(v_mm_s > 0.0)) return inf;
    if (!accel_modelled(accel_mm_s2) || !std::isfinite(v_mm_s)) return length / v_mm_s;
    // Reaches v after v/a s and v²/(2a) mm; accelerating and braking cover v²/a.
    if (length >= v_mm_s * v_mm_s / accel_mm_s2) return length / v_mm_s + v_mm_s / accel_mm_s2;
    // Triangle: accelerate over L/2 (t = sqrt(L/a)), brake over L/2.
    return 2.0 * std::sqrt(length / accel_mm_s2);
}

double rapid_time(std::span<const double> travel, std::span<const AxisLimits> limits, RapidMode mode) {
    const std::size_t n = std::min(travel.size(), limits.size());
    if (mode == RapidMode::dog_leg) {
        double t = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            t = std::max(t, trapezoid_time(std::fabs(travel[i]), limits[i].rapid_mm_min / 60.0,
                                           limits[i].accel_mm_s2));
        return t;
    }
    // Straight: normalised progress σ ∈ [0, 1]; axis i sits at d_i·σ.
    double v_sigma = inf;   // 1/s
    double a_sigma = inf;   // 1/s²
    bool moves = false;
    for (std::size_t i = 0; i < n; ++i) {
        const double d = std::fabs(travel[i]);
        if (!(d > 0.0)) continue;
        moves = true;
        const double v = limits[i].rapid_mm_min / 60.0;
        v_sigma = std::min(v_sigma, v > 0.0 ? v / d : 0.0);
        if (accel_modelled(limits[i].accel_mm_s2)) a_sigma = std::min(a_sigma, limits[i].accel_mm_s2 / d);
    }
    if (!moves) return 0.0;
    return trapezoid_time(1.0, v_sigma, a_sigma);
}

double rapid_time(Vec3 delta, const AxisLimits3& limits, RapidMode mode) {
    const auto d = components(delta);
    const auto l = components(limits);
    return rapid_time(std::span<const double>(d), std::span<const AxisLimits>(l), mode);
}

std::vector<Vec3> dog_leg_path(Vec3 start, Vec3 end, const AxisLimits3& limits) {
    const Vec3 delta = end - start;
    // Arrival time of each axis at constant speed.
    std::array<double, 3> arrive{};
    for (Axis a : {Axis::x, Axis::y, Axis::z}) {
        const double d = std::fabs(get(delta, a));
        const double v = limits[a].rapid_mm_min / 60.0;
        arrive[static_cast<int>(a)] = d > 0.0 ? (v > 0.0 ? d / v : inf) : 0.0;
    }
    std::array<double, 3> times = arrive;
    std::sort(times.begin(), times.end());
    std::vector<Vec3> path{start};
    for (double t : times) {
        if (!(t > 0.0)) continue;
        Vec3 p = start;
        for (Axis a : {Axis::x, Axis::y, Axis::z}) {
            const double total = arrive[static_cast<int>(a)];
            const double frac = total <= t ? 1.0 : t / total;
            set(p, a, frac >= 1.0 ? get(end, a) : get(start, a) + get(delta, a) * frac);
        }
        if (!(p == path.back())) path.push_back(p);
    }
    if (!(path.back() == end)) path.push_back(end);
    return path;
}

double path_accel(Vec3 delta, const AxisLimits3& limits) {
    const double l = norm(delta);
    if (!(l > 0.0)) return inf;
    double a = inf;
    for (Axis ax : {Axis::x, Axis::y, Axis::z}) {
        const double u = std::fabs(get(delta, ax)) / l;
        if (u > 0.0 && accel_modelled(limits[ax].accel_mm_s2)) a = std::min(a, limits[ax].accel_mm_s2 / u);
    }
    return a;
}

double feed_time(double length, double feed_mm_min, double accel_mm_s2) {
    return trapezoid_time(length, feed_mm_min / 60.0, accel_mm_s2);
}

double css_rpm(double surface_m_min, double diameter_mm, const SpindleClamp& clamp) {
    double n = 0.0;
    if (surface_m_min > 0.0) {
        const double d = std::fabs(diameter_mm);
        n = d > 0.0 ? 1000.0 * surface_m_min / (std::numbers::pi * d) : inf;
    }
    return std::clamp(n, std::max(clamp.min_rpm, 0.0), std::max(clamp.max_rpm, std::max(clamp.min_rpm, 0.0)));
}

double css_feed_time(double length, double d_start_mm, double d_end_mm, double surface_m_min,
                     double feed_mm_rev, const SpindleClamp& clamp) {
    if (!(length > 0.0)) return 0.0;
    if (!(feed_mm_rev > 0.0)) return inf;
    // Break points along s ∈ [0, L] where d(s) = d0 + (d1 − d0)·s/L reaches 0 or ±D_c for the
    // diameters D_c at which the rpm hits a clamp.
    std::vector<double> cuts{0.0, length};
    const double slope = (d_end_mm - d_start_mm) / length;
    auto add_crossing = [&](double d) {
        if (slope == 0.0) return;
        const double s = (d - d_start_mm) / slope;
        if (s > 0.0 && s < length) cuts.push_back(s);
    };
    add_crossing(0.0);
    if (surface_m_min > 0.0) {
        for (double n_limit : {clamp.max_rpm, clamp.min_rpm}) {
            if (!(n_limit > 0.0) || !std::isfinite(n_limit)) continue;
            const double dc = 1000.0 * surface_m_min / (std::numbers::pi * n_limit);
            add_crossing(dc);
            add_crossing(-dc);
        }
    }
    std::sort(cuts.begin(), cuts.end());
    double minutes = 0.0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double len = cuts[i + 1] - cuts[i];
        if (!(len > 0.0)) continue;
        const double da = std::fabs(d_start_mm + slope * cuts[i]);
        const double db = std::fabs(d_start_mm + slope * cuts[i + 1]);
        minutes += css_piece_minutes(len, da, db, surface_m_min, feed_mm_rev, clamp);
    }
    return minutes * 60.0;
}

double css_feed_time(const Line& line, double surface_m_min, double feed_mm_rev, const SpindleClamp& clamp,
                     Axis radial_axis) {
    return css_feed_time(length(line), 2.0 * get(line.start, radial_axis), 2.0 * get(line.end, radial_axis),
                         surface_m_min, feed_mm_rev, clamp);
}

double css_feed_time(const Arc& arc, double surface_m_min, double feed_mm_rev, const SpindleClamp& clamp,
                     Axis radial_axis) {
    const double total = length(arc);
    if (!(total > 0.0)) return 0.0;
    if (!(feed_mm_rev > 0.0)) return inf;
    const double span = std::fabs(arc.sweep);
    // 1. Cut at the quadrant points (the radial coordinate, an in-plane c + r·cos or r·sin, has
    //    its extremes there; along the normal it is linear) and at most every 30°.
    std::vector<double> cuts{0.0, 1.0};
    if (span > 0.0) {
        const double a0 = start_angle(arc);
        for (int k = 0; k < 4; ++k) {
            const double q = k * (std::numbers::pi / 2.0);
            double ahead = std::fmod(arc.sweep > 0.0 ? q - a0 : a0 - q, 2.0 * std::numbers::pi);
            if (ahead < 0.0) ahead += 2.0 * std::numbers::pi;
            if (ahead > 0.0 && ahead < span) cuts.push_back(ahead / span);
        }
        const int parts = static_cast<int>(std::ceil(span / (std::numbers::pi / 6.0)));
        for (int i = 1; i < parts; ++i) cuts.push_back(static_cast<double>(i) / parts);
    }
    std::sort(cuts.begin(), cuts.end());
    // 2. Between those cuts the radial coordinate is monotonic: each level where the regime can
    //    change (D = 0, D = diameter of the max or min clamp) is crossed at most once; find it by
    //    bisection.
    auto radial = [&](double t) { return get(point_at(arc, t), radial_axis); };
    std::vector<double> levels{0.0};
    if (surface_m_min > 0.0) {
        for (double n_limit : {clamp.max_rpm, clamp.min_rpm}) {
            if (!(n_limit > 0.0) || !std::isfinite(n_limit)) continue;
            const double rc = 500.0 * surface_m_min / (std::numbers::pi * n_limit);   // D_c / 2
            levels.push_back(rc);
            levels.push_back(-rc);
        }
    }
    std::vector<double> breaks = cuts;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        for (double level : levels) {
            double lo = cuts[i];
            double hi = cuts[i + 1];
            const double f_lo = radial(lo) - level;
            if (!(f_lo * (radial(hi) - level) < 0.0)) continue;
            for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
                const double mid = (lo + hi) / 2.0;
                if ((radial(mid) - level) * f_lo > 0.0) lo = mid; else hi = mid;
            }
            breaks.push_back((lo + hi) / 2.0);
        }
    }
    std::sort(breaks.begin(), breaks.end());
    // 3. On each piece the regime is fixed and the integrand π·D/(1000·Vc·f) (free) is a smooth
    //    sinusoid over at most 30°, or a constant (clamped): 8-point Gauss-Legendre is exact to
    //    rounding. ds = total·dt (t is proportional to the path length).
    static constexpr std::array<double, 4> node{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                                0.9602898564975363};
    static constexpr std::array<double, 4> weight{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                                  0.1012285362903763};
    auto minutes_per_mm = [&](double t) {
        const double n = css_rpm(surface_m_min, 2.0 * radial(t), clamp);
        return n > 0.0 ? 1.0 / (feed_mm_rev * n) : inf;
    };
    double minutes = 0.0;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        const double half = (breaks[i + 1] - breaks[i]) / 2.0;
        if (!(half > 0.0)) continue;
        const double mid = (breaks[i + 1] + breaks[i]) / 2.0;
        double sum = 0.0;
        for (std::size_t k = 0; k < node.size(); ++k)
            sum += weight[k] * (minutes_per_mm(mid - half * node[k]) + minutes_per_mm(mid + half * node[k]));
        minutes += sum * half * total;
    }
    return minutes * 60.0;
}

double dwell_time(double value, DwellUnit unit, double rpm) {
    if (!(value > 0.0)) return 0.0;
    switch (unit) {
    case DwellUnit::seconds: return value;
    case DwellUnit::milliseconds: return value / 1000.0;
    case DwellUnit::revolutions: return rpm > 0.0 ? value * 60.0 / rpm : inf;
    }
    return value;
}

std::optional<VariableLead> variable_lead(double length, double lead_start, double lead_change) {
    if (lead_start <= 0) return std::nullopt;
    if (std::fabs(lead_change) < 1e-12) return VariableLead{length / lead_start, lead_start};
    const double square = lead_start * lead_start + 2 * lead_change * length;
    if (square <= 0) return std::nullopt;
    const double end = std::sqrt(square);
    // (end − L0) / K loses digits when K·length is tiny beside L0²: 2·length / (L0 + end) is the same.
    return VariableLead{2 * length / (lead_start + end), end};
}

}  // namespace kerf::motion
