// G41/G42 inside G112/G107 (reference/cycles.md §18 "Tool-radius compensation is computed in the
// Cartesian plane"; semantics.md §5 "In G112 mode the compensation works in the Cartesian plane
// with the cutter radius (§10.5 'R → 4, T → 9')"). The block's programmed line or arc of the
// Cartesian plane and the next block read ahead go through the same state machine as any other
// compensated block (compensation::RadiusCompensation); each tool-centre move it returns, a line
// or an arc of the Cartesian plane, is then cut into pieces of the real axes (polar.cpp
// run_plane_path). The controlled point is the cutter's centre: a live tool is tip 0 or 9
// (semantics.md §5), so no imaginary-tip shift applies in the plane.
#include <fmt/format.h>

#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;
using compensation::Programmed;

namespace {

// [FANUC] PS0145 "illegal conditions in polar coordinate interpolation": G12.1/G13.1 while the
// compensation holds an offset (the plane would change under the offset vector).
constexpr int kIllegalConditions = 145;

}  // namespace

// The block's element in the Cartesian plane from the programmed point `start` (read ahead too:
// comp_pieces comes here while a mode is on).
OrAlarm<motion::Element> Executor::transform_element(const MachineState& s, const BlockContext& ctx, const Position& start,
                                                      const Position& to) const {
    const BlockWords& words = ctx.words;
    const motion::P2 a = transform_point(s, start), b = transform_point(s, to);
    const dialects::FunctionId motion = ctx.motion_in(s);
    if (motion == fn::circular_cw || motion == fn::circular_ccw) {
        const motion::ArcResult geometry = transform_arc(s, motion == fn::circular_cw, a, b, words);
        if (!geometry) return {{}, transform_arc_alarm(s, ctx, geometry)};
        const motion::Vec3 c = geometry.arc().center;
        return {motion::Element{a, b, true, {c.x, c.y}, !geometry.arc().cw}, std::nullopt};
    }
    return {motion::Element{a, b, false, {}, true}, std::nullopt};
}

Outcome Executor::transform_compensated(const BlockContext& ctx, const Position& to, bool moves) {
    PlaneTransform& t = *state_.transform;
    const int side = comp_side_of_block(state_, ctx, state_.comp_side);
    const dialects::FunctionId motion = ctx.motion_in(state_);
    const bool runs = motion == fn::rapid || motion == fn::linear || motion == fn::circular_cw || motion == fn::circular_ccw;
    if (!moves || !runs) {
        state_.comp_side = side;   // G41/G42/G40 without motion: in force from the next move
        return Outcome::done;
    }
    const bool arc = motion == fn::circular_cw || motion == fn::circular_ccw;
    const EventKind kind = motion == fn::rapid ? EventKind::rapid : EventKind::linear;
    if (!arc && motion::norm(transform_point(state_, to) - transform_point(state_, t.programmed)) <= 1e-9) {
        // A move off the plane only (a Z plunge): the offset stays, the compensation goes on with
        // the next move in the plane (as executor_compensation.cpp, semantics.md §5).
        state_.comp_side = side;
        const motion::P2 at = t.tool.value_or(transform_point(state_, t.programmed));
        run_plane_path(kind, [at](double) { return at; }, {state_.position, to, 0, 1}, ctx);
        if (!stopped_) t.programmed = to;
        return unless_stopped(Outcome::moved);
    }
    CompPieces read = comp_pieces(state_, ctx, t.programmed, to, false);
    state_.comp_side = side;
    if (!block_pieces_run(read, ctx)) return unless_stopped(Outcome::done);
    const Programmed& current = read.pieces.front().programmed;
    OrAlarm<std::optional<Programmed>> next = comp_look_ahead(ctx, to);
    if (!next.ok()) {
        raise(std::move(*next.alarm));   // the block read ahead cannot be read
        return Outcome::stopped;
    }
    const auto step = comp_step(current, next.value, ctx);
    if (!step) return Outcome::stopped;
    run_transform_moves(*step, kind, to, ctx);
    if (stopped_) return Outcome::stopped;
    t.programmed = to;
    if (!state_.radius_comp.engaged()) t.tool.reset();   // cancelled: on the programmed point again
    return Outcome::moved;
}

// The tool-centre moves of one step, each cut into pieces; the axes outside the plane share the
// block's travel in proportion to the moves' lengths.
void Executor::run_transform_moves(const compensation::Step& step, EventKind kind, const Position& to,
                                   const BlockContext& ctx) {
    PlaneTransform& t = *state_.transform;
    const Position from = state_.position;
    std::vector<std::function<motion::P2(double)>> paths;
    std::vector<double> lengths;
    motion::P2 tool = t.tool.value_or(transform_point(state_, t.programmed));
    for (const compensation::ToolMove& m : step.moves) {
        std::function<motion::P2(double)> path = [a = tool, b = m.end](double u) { return a + (b - a) * u; };
        double length = motion::norm(m.end - tool);
        if (m.arc) {
            const motion::ArcResult arc =
                motion::arc_from_center({tool.a, tool.b, 0}, {m.end.a, m.end.b, 0}, motion::Plane::xy,
                                        m.ccw ? motion::ArcDirection::ccw : motion::ArcDirection::cw,
                                        {m.center.a - tool.a, m.center.b - tool.b, 0}, computed_arc_options());
            if (arc) {   // a degenerate arc piece runs as its chord
                path = [g = arc.arc()](double u) { return arc_point(g, u); };
                length = motion::length(arc.arc());
            }
        }
        paths.push_back(path);
        lengths.push_back(length);
        tool = m.end;
    }
    double total = 0;
    for (const double l : lengths) total += l;
    double done = 0;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const double u0 = total > 0 ? done / total : 0;
        done += lengths[i];
        const double u1 = total > 0 ? done / total : 1;
        run_plane_path(kind, paths[i], {from, to, u0, u1}, ctx);
        if (stopped_) return;
        t.tool = paths[i](1);
    }
}

// G12.1/G13.1 may only be given with the compensation cancelled ([FANUC] PS0145; every seed
// program gives G40 before G113, cycles.md §18).
bool Executor::transform_switch_allowed(const BlockContext& ctx, const std::string& spelling) {
    if (!state_.radius_comp.engaged()) return true;
    alarm(ctx, kIllegalConditions,
          fmt::format("{} while tool radius compensation is on: cancel it with G40 and a move first ([FANUC] alarm {})",
                      spelling, kIllegalConditions));
    return false;
}

}  // namespace kerf::interpreter
