// Moves to and from fixed machine points (semantics.md §2.2, §2.8): G53 one-shot machine
// coordinates, G28 reference return, G30 P2..P4 2nd–4th reference point, G29 return from the
// reference point through the intermediate point remembered per axis, G27 the return check.
#include <fmt/format.h>

#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

namespace {

bool programmed(const BlockWords& words, std::size_t axis) {
    const char letter = kAxisLetters[axis];
    return words.words.count(letter) || words.incremental.count(letter);
}

}  // namespace

// not_mine: the block has none of these codes; otherwise moved, done (no axis words) or stopped.
Outcome Executor::apply_reference_motion(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    if (!(ctx.scan.classes & kOneShotCode)) return Outcome::not_mine;   // the common block: no group-00 code
    const bool g53 = has_function(ctx, fn::machine_coordinate_select) || has_function(ctx, fn::machine_coordinate_select_g0_g1);
    const bool g28 = has_function(ctx, fn::reference_return);
    const bool g30 = has_function(ctx, fn::reference_return_nth);
    const bool g29 = has_function(ctx, fn::return_from_reference);
    const bool g27 = has_function(ctx, fn::reference_return_check);
    if (!g53 && !g28 && !g30 && !g29 && !g27) return Outcome::not_mine;
    bool moves = false;
    const Position to = target_position(state_, state_.position, words, moves);
    if (!moves) return Outcome::done;
    if (g27) {
        // [FANUC] G27 reference position return check: a rapid positioning to the programmed point
        // (which should be the reference point; the check lamp is the machine's, not the trace's).
        move(EventKind::rapid, to, ctx);
        return unless_stopped(Outcome::moved);
    }
    if (g53) {
        // The programmed values are machine coordinates, for this block only (§2.2).
        const Position offset = machine_offset(state_);
        Position target = state_.position;
        for (const auto& [letter, w] : words.words)
            if (const auto axis = axis_of_letter(letter); axis && dialect_.lexical.is_axis(letter)) {
                const std::size_t a = static_cast<std::size_t>(*axis);
                target[a] = (axis_value(state_, w, letter) * state_.axis_scale(a) - offset[a]) / state_.axis_scale(a);
            }
        // pcnc-mill G53 follows the active G00/G01 and its feed (§2.2); FANUC G53 is a rapid.
        const bool feed = has_function(ctx, fn::machine_coordinate_select_g0_g1) && state_.flags.motion == fn::linear;
        move(feed ? EventKind::linear : EventKind::rapid, target, ctx);
        return unless_stopped(Outcome::moved);
    }
    if (g29) {
        // To the remembered intermediate point, then to the programmed point; incremental words
        // count from the intermediate point ([FANUC] G29).
        Position mid = state_.position;
        for (std::size_t a = 0; a < kAxisCount; ++a)
            if (programmed(words, a) && state_.intermediate[a]) mid[a] = *state_.intermediate[a];
        move(EventKind::rapid, mid, ctx);
        if (stopped_) return Outcome::stopped;
        bool unused = false;
        move(EventKind::rapid, target_position(state_, state_.position, words, unused), ctx);
        return unless_stopped(Outcome::moved);
    }
    int point = 1;
    if (g30) {
        const auto* p = words.get('P');
        point = p ? static_cast<int>(std::lround(p->value)) : setup_.g30_default_p;
        // P1 is the G28 point (pcnc-mill, dialects.md §8); P2..P4 the others.
        if (point < 1 || point > 4) {
            alarm(ctx, 46, fmt::format("G30 P{}: P must be 1 to 4 (alarm 046)", point));
            return Outcome::stopped;
        }
    }
    // Through the intermediate point (remembered per axis for G29), then to the reference point,
    // programmed axes only (§2.8).
    Position via = to;
    if (setup_.g28_point_in_machine) {
        const Position offset = machine_offset(state_);
        for (std::size_t a = 0; a < kAxisCount; ++a)
            if (const auto* w = words.get(kAxisLetters[a]); w && programmed(words, a)) via[a] = (axis_value(state_, *w, kAxisLetters[a]) * state_.axis_scale(a) - offset[a]) / state_.axis_scale(a);
    }
    for (std::size_t a = 0; a < kAxisCount; ++a)
        if (programmed(words, a)) state_.intermediate[a] = via[a];
    move(EventKind::rapid, via, ctx);
    if (stopped_) return Outcome::stopped;
    const Position offset = machine_offset(state_);
    Position home = state_.position;
    for (std::size_t a = 0; a < kAxisCount; ++a)
        if (programmed(words, a))
            home[a] = (setup_.reference_points[static_cast<std::size_t>(point - 1)][a] - offset[a]) / state_.axis_scale(a);
    move(EventKind::rapid, home, ctx);
    return unless_stopped(Outcome::moved);
}

}  // namespace kerf::interpreter
