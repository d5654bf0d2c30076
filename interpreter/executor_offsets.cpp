// G45–G48 one-block position offsets (reference semantics.md §9.3), the executor's side: the D
// register is modal for these codes ("the data of D08 given in N6 apply to N6–N8"); the tool's
// move is the programmed move (from the programmed point, G90 or G91) changed by the rule of
// interpreter/compensation/position_offset.hpp, started from where the tool stands. The
// programmed point is kept apart (state_.programmed), so the next block measures from it.
#include <fmt/format.h>

#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/compensation/position_offset.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

std::optional<int> Executor::position_offset_factor(const BlockContext& ctx) const {
    // The factor is a trait of the code's function (dialects/functions.hpp): no string compare per block.
    if (!(ctx.scan.classes & kPositionOffsetCode)) return std::nullopt;
    for (const ast::CodeRef& c : ctx.scan.g)
        if (c.info && c.info->position_offset() != 0) return c.info->position_offset();
    return std::nullopt;
}

double Executor::d_register() const {
    const auto& d = state_.last_words[static_cast<std::size_t>('D' - 'A')];
    if (!d) return 0;
    const auto it = memory_.tools.find(static_cast<int>(std::lround(*d)));
    return it == memory_.tools.end() ? 0 : (it->second.radius + it->second.radius_wear) / state_.unit_scale();
}

Outcome Executor::position_offset_move(const BlockContext& ctx, int factor, const Position& start,
                                    const Position& to) {
    const BlockWords& words = ctx.words;
    const double d = d_register();
    const dialects::FunctionId motion = state_.flags.motion;
    // An arc needs its centre words: seed 004 N11 `G45 Y0.` and N12 follow the G02 of N10 and
    // still move straight, "10 mm in Y" (semantics.md §9.3 table) [inference: the seed's intent].
    const bool centre = words.get('I') || words.get('J') || words.get('K') || words.get('R');
    if ((motion == fn::circular_cw || motion == fn::circular_ccw) && centre) {
        if (const Outcome o = position_offset_arc(ctx, motion == fn::circular_cw, factor * d, start, to); o != Outcome::moved)
            return o;
    } else {
        Position end = state_.position;
        const auto offset_axis = [&](char letter) {
            const auto axis = axis_of_letter(letter);
            if (!axis) return;
            const std::size_t a = static_cast<std::size_t>(*axis);
            end[a] = state_.position[a] + compensation::offset_move(to[a] - start[a], factor, d);
        };
        for (const auto& [letter, w] : words.words)
            if (!w.data && dialect_.lexical.is_axis(letter)) offset_axis(letter);
        for (const auto& [letter, w] : words.incremental) offset_axis(letter);
        move(motion == fn::rapid ? EventKind::rapid : EventKind::linear, end, ctx);
    }
    state_.programmed = state_.position == to ? std::nullopt : std::optional<Position>(to);
    state_.programmed_by_offset = state_.programmed.has_value();
    return unless_stopped(Outcome::moved);
}

// An arc under G45–G48: the radius grows by `change` (R40 → R50 for G45 D10), the centre and the
// end point scaled about the tool's start by the same ratio (semantics.md §9.3, N7 and N10).
Outcome Executor::position_offset_arc(const BlockContext& ctx, bool cw, double change,
                                   const Position& start, const Position& to) {
    const BlockWords& words = ctx.words;
    const motion::ArcResult arc = arc_geometry(state_, cw, start, to, words);
    if (!arc) {
        alarm(ctx, arc.error().fanuc_alarm, fmt::format("arc: {}", motion::describe(arc.error().code)));
        return Outcome::stopped;
    }
    const double scale = state_.unit_scale();
    const double k = arc.arc().radius > 0 ? (arc.arc().radius + change * scale) / arc.arc().radius : 1.0;
    const motion::Vec3 tool = geometric_mm(state_.position, setup_.diameter_x, scale);
    const motion::Vec3 from = arc.arc().start;
    const motion::Vec3 normal = motion::plane_normal(state_.plane());
    const auto scaled = [&](motion::Vec3 p) {
        const motion::Vec3 v = p - from;
        const motion::Vec3 along_normal = normal * motion::dot(v, normal);
        return tool + (v - along_normal) * k + along_normal;
    };
    const Position end = from_geometric(scaled(arc.arc().end), to, setup_.diameter_x, scale);
    const Position center = from_geometric(scaled(arc.arc().center), to, setup_.diameter_x, scale);
    cycle_arc(cw, end, center, ctx);
    return unless_stopped(Outcome::moved);
}

}  // namespace kerf::interpreter
