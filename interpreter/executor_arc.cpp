// Arcs (G02/G03) through the motion kernel (reference/semantics.md §3): plane from the modal
// state, centre from I/J/K (incremental from the start, radius values) or R (negative R = more
// than 180°), lathe X converted from diameter to radius for the geometry and back for the trace.
#include <fmt/format.h>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"
#include "motion/arc.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

namespace {

motion::Vec3 geometric(const Position& p, bool diameter_x) {
    return {diameter_x ? p[0] / 2 : p[0], p[1], p[2]};
}

}  // namespace

motion::Plane Executor::plane() const {
    for (const auto& [group, code] : modal_) {
        if (!code) continue;
        if (code->function == fn::plane_xy) return motion::Plane::xy;
        if (code->function == fn::plane_zx) return motion::Plane::zx;
        if (code->function == fn::plane_yz) return motion::Plane::yz;
    }
    return dialect_.machine == dialects::MachineKind::lathe ? motion::Plane::zx : motion::Plane::xy;
}

void Executor::arc_move(bool cw, const Position& to, const BlockWords& words, const ast::BlockView& view) {
    const Frame& f = *frame_;
    const motion::Vec3 start = geometric(position_, setup_.diameter_x);
    const motion::Vec3 end = geometric(to, setup_.diameter_x);
    const motion::ArcDirection dir = cw ? motion::ArcDirection::cw : motion::ArcDirection::ccw;
    const auto* r = words.get('R');
    motion::ArcResult arc = [&] {
        if (r) return motion::arc_from_radius(start, end, plane(), dir, axis_value(*r, 'R'));
        motion::Vec3 offset{};
        if (const auto* i = words.get('I')) offset.x = axis_value(*i, 'I');
        if (const auto* j = words.get('J')) offset.y = axis_value(*j, 'J');
        if (const auto* k = words.get('K')) offset.z = axis_value(*k, 'K');
        return motion::arc_from_center(start, end, plane(), dir, offset);
    }();
    if (!arc) {
        const motion::ArcError& e = arc.error();
        alarm(f, view, e.fanuc_alarm,
              fmt::format("arc: {} (found {:.4f}, allowed {:.4f})", motion::describe(e.code), e.found, e.allowed));
        return;
    }
    Event e;
    e.kind = cw ? EventKind::arc_cw : EventKind::arc_ccw;
    e.source = source(f, view);
    e.start = position_;
    e.end = to;
    const motion::Vec3 c = arc.arc().center;
    Position center = to;
    center[0] = setup_.diameter_x ? c.x * 2 : c.x;
    center[1] = c.y;
    center[2] = c.z;
    e.center = center;
    e.radius = arc.arc().radius;
    e.length_mm = motion::length(arc.arc());
    // F is the speed along the arc in its plane; a helix's third axis follows (semantics.md §3).
    const double timed_length = motion::feed_length(arc.arc());
    e.feed = feed_;
    const bool per_rev = modal_function("05") == fn::feed_per_revolution;
    e.feed_per_rev = per_rev;
    e.spindle_rpm = current_rpm(to[0]);
    const double mm_per_min = per_rev ? feed_ * e.spindle_rpm : feed_;
    e.time_s = mm_per_min > 0 ? timed_length / mm_per_min * 60.0 : 0;
    result_.feed_distance_mm += e.length_mm;
    position_ = to;
    emit(std::move(e));
}

}  // namespace kerf::interpreter
