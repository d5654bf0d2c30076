// Special functions of iso-legacy-mill (reference seed 004; semantics.md §9.4, §9.5), reached by
// function id: G28 K F / G29 are the corner slow-down and its cancel there, not reference returns
// (gcode-tables.md §6), and G43 in a move is an approach that stops D short of the point.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

// §9.5: `G28 K15. F30` – over the last K mm before each G01 end point the feed is reduced by F
// percent; a new G28 replaces the values, G29 cancels. The block has no motion.
void Executor::apply_corner_slowdown(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    for (const ast::CodeRef& c : ctx.scan.g) {
        if (!c.info || !(code_class_of(*c.info) & kCornerSlowdownCode)) continue;
        if (c.info->function == fn::corner_slowdown_cancel) {
            state_.slowdown.reset();
            continue;
        }
        const auto* k = words.get('K');
        const auto* p = words.get('F');
        // K in mm as written: the seed's `K5` is "5 mm before point 7" (§9.5), not 5 increments.
        if (!k || !p || k->value <= 0 || p->value <= 0 || p->value >= 100) {
            Event e = event_at(EventKind::message, ctx);
            e.text = fmt::format("{} needs K > 0 (mm) and F in 1..99 (percent): no corner slow-down (semantics.md §9.5)",
                                 c.info->spelling);
            emit(e);
            state_.slowdown.reset();
            continue;
        }
        state_.slowdown = Slowdown{k->value * state_.unit_scale(), p->value / 100.0};
    }
}

// The move from the tool to `to` at F up to K mm before the end, then at F·(1 − p) (the event's
// feed). The machine switch corner_slowdown: a step (the seed's "147 mm/min over the last 15 mm")
// or, by default, a linear ramp from F to F·(1 − p) ("at point 7 the feed is 500"), whose time
// over the last d ≤ K mm is ∫ ds / f(s) with f(s) = F·(1 − p) + F·p·s/K:
// K/(F·p) · ln(f(d) / (F·(1 − p))).
Outcome Executor::slowed_move(const Position& to, const BlockContext& ctx, const FeedRate& feed) {
    const double length = motion::distance(geometric_mm(state_.position, setup_.diameter_x, state_.unit_scale()),
                                           geometric_mm(to, setup_.diameter_x, state_.unit_scale()));
    if (length <= 1e-9 || feed.value <= 0) return Outcome::not_mine;
    const double k = state_.slowdown->k_mm;
    const double d = std::min(k, length);
    if (d < length) {
        Position mid = state_.position;
        const double t = 1 - d / length;
        for (std::size_t a = 0; a < kAxisCount; ++a) mid[a] = state_.position[a] + (to[a] - state_.position[a]) * t;
        run_move(EventKind::linear, mid, ctx, feed);   // the pieces of a split move are not split again
    }
    if (!stopped_) {
        const double full = feed.value;
        FeedRate reduced{full * (1 - state_.slowdown->fraction), feed.per_revolution, 1.0};
        if (!setup_.corner_slowdown_step) {
            const double at_d = reduced.value + (full - reduced.value) * d / k;
            reduced.time_factor = (k / (full - reduced.value) * std::log(at_d / reduced.value)) / (d / reduced.value);
        }
        run_move(EventKind::linear, to, ctx, reduced);
    }
    return unless_stopped(Outcome::moved);
}

// G43/G44 of seed 004 without H (with H they are the axial length offset, executor_length.cpp).
// G43 in a G00/G01 move is the approach of §9.4; G44 is only "the opposite direction of G43"
// (semantics.md §7, the seed's chapter 8 is missing): it moves nothing else and says so, as does
// a G43 without a move.
Outcome Executor::axial_offset_motion(const BlockContext& ctx, const Position& to,
                                                  bool moves) {
    const BlockWords& words = ctx.words;
    const dialects::CodeInfo* code = nullptr;
    for (const ast::CodeRef& c : ctx.scan.g)
        if (c.info && (code_class_of(*c.info) & kApproachOffsetCode)) code = c.info;
    if (!code || axial_offset_is_length(*code, words)) return Outcome::not_mine;
    const bool straight = state_.flags.motion == fn::rapid || state_.flags.motion == fn::linear;
    if (code->function == fn::axial_offset_plus && moves && straight) return approach_offset_move(ctx, to);
    Event m = event_at(EventKind::message, ctx);
    m.code = kerf_warning::not_modelled;
    m.text = code->function == fn::axial_offset_plus
                 ? fmt::format("{} without H and without a G00/G01 move: no approach to shorten (semantics.md §9.4); "
                               "give H for an axial offset",
                               code->spelling)
                 : fmt::format("{} without H: seed 004 defines it only as the opposite direction of G43 (semantics.md §7, "
                               "its chapter 8 is missing): no offset applied; give H for an axial offset",
                               code->spelling);
    emit(m);
    return Outcome::not_mine;   // said; the block runs as usual
}

// §9.4 (example 6 `N60 G0 G43 X140. Y35. D08`): the tool stops D short of the programmed point
// along the approach from the programmed start [inference, flagged in a message; machine switch
// iso_g43]. Under G41/G42 the tool then stands at an offset point of the programmed end (the
// centre of the next element's start-up), so the compensation goes on from there.
Outcome Executor::approach_offset_move(const BlockContext& ctx, const Position& to) {
    const Position from = state_.comp_path ? *state_.comp_path : state_.programmed.value_or(state_.position);
    const motion::P2 a = plane_point(state_, from), b = plane_point(state_, to);
    const double length = motion::norm(b - a);
    const double d = d_register() * state_.unit_scale();
    const motion::P2 end = length > 1e-9 ? b - (b - a) * (d / length) : b;
    Event m = event_at(EventKind::message, ctx);
    m.text = fmt::format("G43 approach: the tool stops D = {:.3f} mm short of the programmed point (semantics.md §9.4, "
                         "an inference of seed 004 example 6)", d);
    emit(m);
    move(state_.flags.motion == fn::rapid ? EventKind::rapid : EventKind::linear, plane_position(state_, end, to), ctx);
    if (stopped_) return Outcome::stopped;
    if (state_.comp_side != 0) {
        state_.radius_comp.stand_at(end);
        state_.comp_path = to;
    }
    state_.programmed = to;
    return Outcome::moved;
}

// §9.6 (example 4: `G12 X95. Y30. F200` may replace `G3 X95. Y90. I-40. J0. F200`, `G13 X55. Y50.
// F200` the exit `G3 X55. Y50. I0. J-40.`): the seed gives neither radius nor direction; in the
// example both are quarter circles, counter-clockwise under G41 [inference]: a quarter arc from
// the programmed point to X Y, CCW under G41 (and G40), CW under G42, its centre on the side the
// arc turns to at |chord|/2 from the chord's middle. The block then runs as that G02/G03 with
// centre words (compensation included).
BlockWords Executor::arc_approach_words(const MachineState& s, const BlockContext& ctx, const Position& from,
                                        const Position& to, bool& ccw) const {
    const motion::P2 a = plane_point(s, from), b = plane_point(s, to);
    ccw = comp_side_of_block(s, ctx, s.comp_side) >= 0;
    const motion::P2 half = (b - a) * 0.5;
    const motion::P2 towards = ccw ? motion::P2{-half.b, half.a} : motion::P2{half.b, -half.a};   // the half chord turned ±90°
    const motion::P2 offset = (half + towards) * (1.0 / s.unit_scale());   // centre − start, program units
    static constexpr char kLetters[3][2] = {{'I', 'J'}, {'K', 'I'}, {'J', 'K'}};   // G17, G18, G19 plane frames
    const auto& letters = kLetters[s.plane() == motion::Plane::xy ? 0 : s.plane() == motion::Plane::zx ? 1 : 2];
    BlockWords arc = ctx.words;
    for (const auto& [letter, value] : {std::pair{letters[0], offset.a}, std::pair{letters[1], offset.b}}) {
        Word w;
        w.value = value;
        w.has_point = true;
        arc.words.set(letter, w);
    }
    return arc;
}

Outcome Executor::arc_approach_move(const BlockContext& ctx, const Position& to) {
    bool ccw = true;
    const BlockWords arc = arc_approach_words(state_, ctx, state_.comp_path ? *state_.comp_path : state_.programmed.value_or(state_.position), to, ccw);
    const BlockContext as_arc = ctx.running_as(arc, ccw ? fn::circular_ccw : fn::circular_cw);
    Outcome moved = Outcome::moved;
    if ((ctx.scan.classes & kRadiusCompCode) || compensating()) moved = compensate_motion(as_arc, to, true);
    else arc_move(!ccw, to, as_arc);
    if (!compensating()) state_.programmed.reset();
    return unless_stopped(moved);
}

}  // namespace kerf::interpreter
