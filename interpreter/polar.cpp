// G12.1/G112 … G13.1/G113 polar coordinate interpolation (cycles.md §18) and G07.1/G107
// cylindrical interpolation (cycles.md §19): the executor's mode. In the mode the program is
// written in a Cartesian plane (polar: X as a diameter and the virtual axis C in mm; cylindrical:
// the axis along the cylinder and C as mm of arc); lines and arcs of that plane become pieces of
// linear motion of the real axes (X and C in degrees), within the machine's transform_tolerance
// (motion/polar.hpp). The trace's `end` is the real X/C; the programmed Cartesian point is kept
// here (PlaneTransform::programmed), not in the trace (docs/trace.md). F is the tangential feed
// along the Cartesian path ([FANUC], cycles.md §18), so a piece takes its Cartesian length / F.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"
#include "motion/arc.hpp"
#include "motion/polar.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

namespace {

constexpr std::size_t kX = 0, kC = 5;
constexpr double kDegPerRad = 180.0 / std::numbers::pi;

// [FANUC] alarms of the modes (the reference lists none): PS0146 "improper G code" in polar
// coordinate interpolation, PS0176 "improper G code in G07.1 mode", PS0175 "illegal G07.1 axis".
constexpr int kImproperInPolar = 146, kImproperInCylindrical = 176, kIllegalCylinderAxis = 175;


// The rotary axis letters and the linear axis each turns about (A about X, B about Y, C about Z).
std::optional<std::pair<std::size_t, std::size_t>> cylinder_axes(char rotary) {
    if (rotary < 'A' || rotary > 'C') return std::nullopt;
    const auto r = static_cast<std::size_t>(rotary - 'A');
    return std::pair{3 + r, r};
}

}  // namespace

// A coordinate of a programmed point in the plane, geometric mm (lathe X as a radius).
double Executor::plane_mm(const MachineState& s, std::size_t axis, double value) const {
    return (axis == kX && setup_.diameter_x ? value / 2 : value) * s.unit_scale();
}
double Executor::program_value(const MachineState& s, std::size_t axis, double mm) const {
    return (axis == kX && setup_.diameter_x ? mm * 2 : mm) / s.unit_scale();
}

motion::P2 Executor::transform_point(const MachineState& s, const Position& p) const {
    const PlaneTransform& t = *s.transform;
    return {plane_mm(s, t.linear, p[t.linear]), p[t.rotary] * s.unit_scale()};   // the virtual axis: mm, never a diameter
}

Outcome Executor::apply_plane_transform(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    if (state_.transform) {
        if (const auto improper = improper_in_transform(ctx)) {
            alarm(ctx, state_.transform->map.kind == motion::PlaneMap::Kind::polar ? kImproperInPolar : kImproperInCylindrical,
                  fmt::format("{} is not allowed in {} mode ([FANUC] alarm {})", *improper, state_.transform->code,
                              state_.transform->map.kind == motion::PlaneMap::Kind::polar ? kImproperInPolar : kImproperInCylindrical));
            return Outcome::stopped;
        }
    }
    for (const ast::CodeRef& c : ctx.scan.g) {
        if (!c.info) continue;
        const dialects::FunctionId f = c.info->function;
        if (f == fn::polar_interpolation_off && state_.transform && state_.transform->map.kind == motion::PlaneMap::Kind::polar) {
            if (!transform_switch_allowed(ctx, c.info->spelling)) return Outcome::stopped;
            state_.transform.reset();   // G113: the ordinary modes resume at the real X/C (cycles.md §18)
        } else if (f == fn::polar_interpolation_on && !state_.transform) {
            if (!transform_switch_allowed(ctx, c.info->spelling)) return Outcome::stopped;
            if (words.get('C')) return start_polar_with_c(ctx, c.info->spelling);
            start_polar(c.info->spelling);
        } else if (f == fn::cylindrical_interpolation) {
            if (cylindrical_code(ctx, c.info->spelling) == Outcome::stopped) return Outcome::stopped;
            if (!state_.transform) return Outcome::not_mine;   // G07.1 C0: the block's other words run as usual
        }
    }
    if (!state_.transform) return Outcome::not_mine;
    return transform_move(ctx);
}

std::optional<std::string> Executor::improper_in_transform(const BlockContext& ctx) const {
    for (const std::vector<ast::CodeRef>* codes : {&ctx.scan.g, &ctx.scan.m})
        for (const ast::CodeRef& c : *codes) {
            if (!c.info) continue;
            // [FANUC] the modes allow motion G00–G03, dwell, compensation, feed modes and macro
            // calls; a cycle, a reference return or a new coordinate system would move the plane
            // under the program (traits::not_in_plane_transform).
            const bool improper = c.info->has(dialects::traits::cycle | dialects::traits::not_in_plane_transform) ||
                                  (c.info->function == fn::polar_interpolation_on &&
                                   state_.transform->map.kind == motion::PlaneMap::Kind::cylindrical) ||
                                  (c.info->function == fn::cylindrical_interpolation &&
                                   state_.transform->map.kind == motion::PlaneMap::Kind::polar);
            if (improper) return fmt::format("{} ({})", c.info->spelling, c.info->function);
        }
    if (state_.flags.motion == fn::thread_cutting) return std::string("thread cutting");
    return std::nullopt;
}

// G112: the plane's origin is the centre of rotation; the tool's X is the plane's x and the
// virtual axis starts at 0; the C position at G112 is the plane's angle 0 (cycles.md §18
// "C_start"; every seed program turns C to 0 first).
void Executor::start_polar(const std::string& spelling) {
    PlaneTransform t;
    t.map = {motion::PlaneMap::Kind::polar, 0};
    t.linear = kX;
    t.rotary = kC;
    t.origin_deg = state_.position[kC];
    t.programmed = state_.position;
    t.programmed[kC] = 0;
    t.code = spelling;
    state_.transform = t;
}

// Seed 001 §10.11 writes `G112 C45`: the meaning of C is unknown (cycles.md §18): said, not moved.
Outcome Executor::start_polar_with_c(const BlockContext& ctx, const std::string& spelling) {
    const BlockWords& words = ctx.words;
    Event e = event_at(EventKind::message, ctx);
    e.text = fmt::format("{} C{}: a C word in the {} block has no known meaning (cycles.md §18): ignored", spelling,
                         words.get('C')->value, spelling);
    emit(e);
    start_polar(spelling);
    BlockWords rest;
    for (const auto& [letter, word] : words.words)
        if (letter != 'C') rest.words.set(letter, word);
    for (const auto& [letter, word] : words.incremental)
        if (letter != 'C') rest.incremental.set(letter, word);
    return transform_move(ctx.with(rest));
}

// G07.1 C r starts cylindrical interpolation on a cylinder of radius r (mm), G07.1 C0 ends it
// (cycles.md §19). The rotary word names the axis: C turns about Z (lathes), A about X, B about
// Y. C is then programmed in mm of arc: the tool's angle at the start is that many mm of arc.
Outcome Executor::cylindrical_code(const BlockContext& ctx, const std::string& spelling) {
    const BlockWords& words = ctx.words;
    char letter = 0;
    for (const char l : {'C', 'A', 'B'})
        if (const auto* w = words.get(l); w && !letter) letter = l;
    const auto axes = letter ? cylinder_axes(letter) : std::nullopt;
    if (!axes) {
        alarm(ctx, kIllegalCylinderAxis,
              fmt::format("{} without the rotary axis and radius (G07.1 C<r>) ([FANUC] alarm {})", spelling,
                          kIllegalCylinderAxis));
        return Outcome::stopped;
    }
    const double radius = axis_value(state_, *words.get(letter), letter) * state_.unit_scale();
    if (radius == 0) {
        state_.transform.reset();
        return Outcome::done;
    }
    PlaneTransform t;
    t.map = {motion::PlaneMap::Kind::cylindrical, std::fabs(radius)};
    t.rotary = axes->first;
    t.linear = axes->second;
    t.programmed = state_.position;
    t.programmed[t.rotary] = state_.position[t.rotary] / kDegPerRad * t.map.cylinder_radius / state_.unit_scale();
    t.code = spelling;
    state_.transform = t;
    return Outcome::done;
}

// A block in the mode: its end point in the Cartesian plane, the line or arc there, its pieces.
// Under G41/G42 the tool centre's path is offset in the Cartesian plane first (polar_compensation.cpp).
Outcome Executor::transform_move(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    PlaneTransform& t = *state_.transform;
    bool moves = false;
    const Position real = state_.position;
    const Position to = target_position(state_, t.programmed, words, moves);   // measured from the programmed point
    note_drawing_outside_g01(ctx);
    if (compensating() || (ctx.scan.classes & kRadiusCompCode)) return transform_compensated(ctx, to, moves);
    const dialects::FunctionId motion = state_.flags.motion;
    const bool arc = motion == fn::circular_cw || motion == fn::circular_ccw;
    if (!moves) return Outcome::done;
    if (motion != fn::rapid && motion != fn::linear && !arc) return Outcome::done;   // no motion code: nothing moves
    const motion::P2 a = transform_point(state_, t.programmed), b = transform_point(state_, to);
    std::function<motion::P2(double)> path = [a, b](double u) { return a + (b - a) * u; };
    if (arc) {
        const auto geometry = transform_arc(state_, motion == fn::circular_cw, a, b, words);
        if (!geometry) {
            raise(transform_arc_alarm(state_, ctx, geometry));
            return Outcome::stopped;
        }
        path = [g = geometry.arc()](double u) { return arc_point(g, u); };
    }
    run_plane_path(motion == fn::rapid ? EventKind::rapid : EventKind::linear, path, {real, to, 0, 1}, ctx);
    if (!stopped_) t.programmed = to;
    return unless_stopped(Outcome::moved);
}

Alarm Executor::transform_arc_alarm(const MachineState& s, const BlockContext& ctx, const motion::ArcResult& geometry) const {
    return {ctx.source(), s.position, geometry.error().fanuc_alarm,
            fmt::format("arc in {} mode: {} (found {:.4f}, allowed {:.4f})", s.transform->code,
                        motion::describe(geometry.error().code), geometry.error().found, geometry.error().allowed)};
}

motion::P2 Executor::arc_point(const motion::Arc& arc, double u) {
    const motion::Vec3 p = motion::point_at(arc, u);
    return {p.x, p.y};
}

// A path of the Cartesian plane from the tool's point (path(0)) run as pieces of the real axes;
// the axes outside the plane go from span.from toward span.to over the part [u0, u1] of the block.
void Executor::run_plane_path(EventKind kind, const std::function<motion::P2(double)>& path, const PathSpan& span,
                              const BlockContext& ctx) {
    const PlaneTransform& t = *state_.transform;
    const double start_deg = state_.position[t.rotary] - t.origin_deg;
    const std::vector<motion::MappedPoint> pieces = motion::map_path(t.map, path, start_deg, setup_.transform_tolerance);
    const motion::P2 a = path(0);
    if (kind != EventKind::rapid && t.map.kind == motion::PlaneMap::Kind::polar) warn_rotary_speed(ctx, pieces, a);
    motion::P2 previous = a;
    for (const motion::MappedPoint& p : pieces) {
        const double u = span.u0 + (span.u1 - span.u0) * p.t;
        Position end = span.to;   // the axes outside the plane move linearly along the block
        for (std::size_t axis = 0; axis < kAxisCount; ++axis)
            end[axis] = span.from[axis] + (span.to[axis] - span.from[axis]) * u;
        end[t.linear] = program_value(state_, t.linear, p.machine.a);
        end[t.rotary] = t.origin_deg + p.machine.b;
        double other_mm2 = 0;   // travel of the linear axes outside the plane
        for (std::size_t axis = 0; axis < 3; ++axis)
            if (axis != t.linear && !setup_.rotary[axis]) {
                const double d = plane_mm(state_, axis, end[axis]) - plane_mm(state_, axis, state_.position[axis]);
                other_mm2 += d * d;
            }
        transform_piece(kind, end, std::sqrt(motion::dot(p.cartesian - previous, p.cartesian - previous) + other_mm2), ctx);
        if (stopped_) return;
        previous = p.cartesian;
    }
}

// G02/G03 in the Cartesian plane (counter-clockwise from its first axis toward the second): R,
// or I (first axis, a radius value) and J (second axis) from the start point (cycles.md §18
// `G2 X-100 C-30 R30`).
motion::ArcResult Executor::transform_arc(const MachineState& s, bool cw, motion::P2 a, motion::P2 b, const BlockWords& words) const {
    const motion::Vec3 start{a.a, a.b, 0}, end{b.a, b.b, 0};
    const motion::ArcDirection dir = cw ? motion::ArcDirection::cw : motion::ArcDirection::ccw;
    motion::ArcOptions options;
    options.radius_tolerance = setup_.arc_tolerance;
    options.allow_negative_r = setup_.arc_negative_r;
    options.enlarge_small_r = setup_.arc_enlarge_small_r;
    if (const auto* r = words.get('R')) return motion::arc_from_radius(start, end, motion::Plane::xy, dir, axis_value(s, *r, 'R') * s.unit_scale(), options);
    motion::Vec3 offset{};
    if (const auto* i = words.get('I')) offset.x = axis_value(s, *i, 'I') * s.unit_scale();
    if (const auto* j = words.get('J')) offset.y = axis_value(s, *j, 'J') * s.unit_scale();
    return motion::arc_from_center(start, end, motion::Plane::xy, dir, offset, options);
}

// Near the centre of the polar plane the rotary axis must turn fast: at F mm/min and radius r it
// turns F/r·(180/π) °/min; past the axis' rapid rate the control clamps it ([FANUC]) and the block
// takes longer than the trace says (cycles.md §18 "a dry run should warn").
void Executor::warn_rotary_speed(const BlockContext& ctx, const std::vector<motion::MappedPoint>& pieces, motion::P2 start) {
    const double limit = setup_.rapid_mm_min[state_.transform->rotary];
    const double feed = state_.feed * state_.unit_scale();
    if (limit <= 0 || feed <= 0 || state_.flags.per_revolution) return;
    const double r = motion::min_radius(pieces, start);
    const double needed = r > 0 ? feed / r * kDegPerRad : INFINITY;
    if (needed <= limit) return;
    Event e = event_at(EventKind::message, ctx);
    e.text = fmt::format("{}: the path passes {:.3f} mm from the centre: C would turn {} °/min at F{}, over its rate "
                         "{} °/min: the control slows down and this block takes longer (cycles.md §18)",
                         state_.transform->code, r, std::isfinite(needed) ? fmt::format("{:.0f}", needed) : std::string("without limit"),
                         state_.feed, limit);
    emit(e);
}

// One piece: a rapid at the axes' own rates (executor_motion.cpp move), a feed piece timed along
// its Cartesian length at F.
void Executor::transform_piece(EventKind kind, const Position& to, double length_mm, const BlockContext& ctx) {
    if (kind == EventKind::rapid) {
        move(kind, to, ctx);
        return;
    }
    if (!within_soft_limits(to, to, ctx)) return;
    Event e;
    e.kind = kind;
    e.source = ctx.source();
    e.start = state_.position;
    e.end = to;
    e.length_mm = length_mm;
    time_feed_move(e, length_mm, 0.0, nullptr, modal_feed());   // pieces blend: no exact stop between them
    result_.feed_distance_mm += length_mm;
    state_.position = to;
    emit(std::move(e));
}

}  // namespace kerf::interpreter
