// Arcs (G02/G03) through the motion kernel (reference/semantics.md §3): plane from the modal
// state, centre from I/J/K (incremental from the start, radius values) or R (negative R = more
// than 180°), lathe X converted from diameter to radius for the geometry and back for the trace.
#include <fmt/format.h>

#include <cmath>

#include "interpreter/executor.hpp"
#include "motion/arc.hpp"
#include "motion/time.hpp"

namespace kerf::interpreter {

motion::ArcResult Executor::arc_geometry(const MachineState& s, bool cw, const Position& from, const Position& to,
                                         const BlockWords& words) const {
    const double scale = s.unit_scale();
    const motion::Vec3 start = geometric_mm(from, setup_.diameter_x, scale);
    const motion::Vec3 end = geometric_mm(to, setup_.diameter_x, scale);
    // [transforms] G68/G51/G51.1 (transforms.hpp): under a mirror of one plane axis the arc runs
    // the other way round ([FANUC] G02 ↔ G03); R is scaled, I/J/K turned, scaled and mirrored.
    const ProgramFrame frame = s.program_frame();
    const bool turned = cw != frame.reverses(s.plane());
    const motion::ArcDirection dir = turned ? motion::ArcDirection::cw : motion::ArcDirection::ccw;
    motion::ArcOptions options;
    options.radius_tolerance = setup_.arc_tolerance;
    options.allow_negative_r = setup_.arc_negative_r;
    options.enlarge_small_r = setup_.arc_enlarge_small_r;
    if (const auto* r = words.get('R')) {
        const double radius = axis_value(s, *r, 'R') * scale * frame.radius_factor(s.plane());
        return motion::arc_from_radius(start, end, s.plane(), dir, radius, options);
    }
    motion::Vec3 offset{};
    if (const auto* i = words.get('I')) offset.x = axis_value(s, *i, 'I') * scale;
    if (const auto* j = words.get('J')) offset.y = axis_value(s, *j, 'J') * scale;
    if (const auto* k = words.get('K')) offset.z = axis_value(s, *k, 'K') * scale;
    return motion::arc_from_center(start, end, s.plane(), dir, frame.vector_to_work(offset), options);
}

void Executor::arc_move(bool cw, const Position& to, const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    const motion::ArcResult arc = arc_geometry(state_, cw, state_.position, to, words);
    if (!arc) {
        const motion::ArcError& e = arc.error();
        if (e.code == motion::ArcErrorCode::r_zero_chord) {
            // FANUC runs an R arc whose end is its start as a 0° arc: no motion (semantics.md §3).
            Event m = event_at(EventKind::message, ctx);
            m.text = "arc with R whose end point is its start point: no motion (a 0° arc)";
            emit(m);
            return;
        }
        alarm(ctx, e.fanuc_alarm,
              fmt::format("arc: {} (found {:.4f}, allowed {:.4f})", motion::describe(e.code), e.found, e.allowed));
        return;
    }
    emit_arc(arc.arc(), to, ctx);
}

void Executor::emit_arc(const motion::Arc& arc, const Position& to, const BlockContext& ctx) {
    const FeedRate feed = modal_feed();
    if (!feed_commanded(motion::length(arc) > 0, ctx, feed.value)) return;
    const double scale = state_.unit_scale();
    const motion::Box box = motion::bounds(arc);
    if (!within_soft_limits(from_geometric(box.min, to, setup_.diameter_x, scale),
                            from_geometric(box.max, to, setup_.diameter_x, scale), ctx))
        return;
    Event e;
    e.kind = arc.cw ? EventKind::arc_cw : EventKind::arc_ccw;
    e.source = ctx.source();
    e.start = state_.position;
    e.end = to;
    e.center = from_geometric(arc.center, to, setup_.diameter_x, scale);
    e.radius = arc.radius;
    e.length_mm = motion::length(arc);
    // F is the speed along the arc in its plane; a helix's third axis follows (semantics.md §3).
    const motion::PlaneAxes axes = motion::plane_axes(arc.plane);
    double accel = 0;
    for (const motion::Axis a : {axes.first, axes.second}) {
        const double axis_accel = setup_.accel_mm_s2[static_cast<std::size_t>(a)];
        if (axis_accel > 0) accel = accel > 0 ? std::min(accel, axis_accel) : axis_accel;
    }
    time_feed_move(e, motion::feed_length(arc), accel, &arc, feed);
    result_.feed_distance_mm += e.length_mm;
    state_.position = to;
    emit(std::move(e));
}

}  // namespace kerf::interpreter
