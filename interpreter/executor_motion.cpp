// Steps 7-9 of a block: motion, dwell, M codes (with calls and returns).
#include <fmt/format.h>

#include <bit>

#include <algorithm>
#include <cmath>

#include "dialects/alarms.hpp"
#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"
#include "motion/line.hpp"
#include "motion/time.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

namespace {

// Path length of the linear axes (lathe X is a diameter: the path runs at the radius; a linear B
// slide counts) and the travel of the rotary axes in degrees, between two machine positions (mm).
struct Travel {
    double linear = 0;
    double rotary = 0;
};

Travel travel_of(const Position& a, const Position& b, const Setup& setup) {
    double linear = 0, rotary = 0;
    for (std::size_t i = 0; i < kAxisCount; ++i) {
        const double d = (b[i] - a[i]) * (i == 0 && setup.diameter_x ? 0.5 : 1.0);
        (setup.rotary[i] ? rotary : linear) += d * d;
    }
    return {std::sqrt(linear), std::sqrt(rotary)};
}

}  // namespace

motion::Vec3 geometric_mm(const Position& p, bool diameter_x, double scale) {
    return {(diameter_x ? p[0] / 2 : p[0]) * scale, p[1] * scale, p[2] * scale};
}

Position from_geometric(motion::Vec3 g, const Position& like, bool diameter_x, double scale) {
    Position p = like;
    p[0] = (diameter_x ? g.x * 2 : g.x) / scale;
    p[1] = g.y / scale;
    p[2] = g.z / scale;
    return p;
}

Position Executor::target_position(const MachineState& s, const Position& from, const BlockWords& words, bool& moves) const {
    // Built in the program's frame (G68, G51, G51.1 undone), then taken back into work coordinates.
    const Position start = to_program(s, from);
    Position to = start;
    moves = false;
    // Only the letters that are axes of the dialect (a table built once: this runs every block).
    for (std::uint32_t mask = words.words.mask() & axis_letters_; mask != 0; mask &= mask - 1) {
        const int i = std::countr_zero(mask);
        const char letter = static_cast<char>('A' + i);
        const Word& w = words.words.at(letter);
        if (w.data) continue;
        const std::size_t a = static_cast<std::size_t>(axis_of_[static_cast<std::size_t>(i)]);
        const double v = axis_value(s, w, letter);
        to[a] = s.flags.incremental ? to[a] + v : v;
        moves = true;
    }
    // U W H: incremental in system A; "the later-specified word is used" with X/U together (§3.2).
    for (std::uint32_t mask = words.incremental.mask(); mask != 0; mask &= mask - 1) {
        const int i = std::countr_zero(mask);
        const char axis_letter = static_cast<char>('A' + i);
        const Word& w = words.incremental.at(axis_letter);
        if (axis_of_[static_cast<std::size_t>(i)] < 0) continue;
        const std::size_t a = static_cast<std::size_t>(axis_of_[static_cast<std::size_t>(i)]);
        const Word* absolute = words.get(axis_letter);
        if (!absolute || absolute->token < w.token) to[a] = start[a] + axis_value(s, w, axis_letter);
        moves = true;
    }
    if (s.polar_command && moves) polar_target(s, words, start, to);   // [transforms] G16 (executor_transforms.cpp)
    // Without G68/G51/G51.1 (nearly every block) `to` is the result as it stands, built in the
    // caller's place: copied out just after its per-axis stores, it stalled store forwarding.
    if (!s.program_frame().identity()) to = from_program(s, to);
    return to;
}

// Stored stroke check 1 (alarms OT500/OT501 [FANUC]): checked before the move, which does not
// start when its end (or an arc's extreme) lies past a limit.
bool Executor::within_soft_limits(const Position& low, const Position& high, const BlockContext& ctx) {
    if (!state_.soft_limits_on || !any_soft_limit_) return true;
    const Position offset = machine_offset(state_);
    for (std::size_t a = 0; a < kAxisCount; ++a) {
        const SoftLimit& limit = setup_.soft_limits[a];
        const double scale = state_.axis_scale(a);
        const double machine_low = low[a] * scale + offset[a], machine_high = high[a] * scale + offset[a];
        const bool over = limit.max && machine_high > *limit.max + 1e-9;
        const bool under = limit.min && machine_low < *limit.min - 1e-9;
        if (!over && !under) continue;
        const int number = over ? 500 : 501;
        alarm(ctx, number,
              fmt::format("OT{}: {} overtravel on {}: machine {:.3f} past the soft limit {:.3f} (stored stroke check)",
                          number, over ? "+" : "-", kAxisLetters[a], over ? machine_high : machine_low,
                          over ? *limit.max : *limit.min));
        return false;
    }
    return true;
}

void Executor::time_feed_move(Event& e, double timed_length_mm, double accel_mm_s2, const motion::Arc* arc,
                              const FeedRate& feed) const {
    // F under G99/G95 and every thread lead are per revolution (semantics.md §4, cycles.md §9).
    const bool per_rev = feed.per_revolution || e.kind == EventKind::thread;
    e.feed = e.kind == EventKind::thread ? state_.thread_lead : feed.value;
    e.feed_per_rev = per_rev;
    e.spindle_rpm = current_rpm(state_, e.end[0]);
    e.spindle_running = state_.spindle_on;
    const double feed_mm = e.feed * state_.unit_scale();
    double seconds = 0;
    if (per_rev && state_.flags.css && e.kind != EventKind::thread) {
        // G96: the rpm follows the diameter along the move (motion/time.hpp css_feed_time).
        motion::SpindleClamp clamp;
        if (state_.max_rpm > 0) clamp.max_rpm = state_.max_rpm;
        if (setup_.max_rpm > 0) clamp.max_rpm = std::min(clamp.max_rpm, setup_.max_rpm);
        const motion::Line line{geometric_mm(e.start, setup_.diameter_x, state_.unit_scale()),
                                geometric_mm(e.end, setup_.diameter_x, state_.unit_scale())};
        if (feed_mm > 0) seconds = arc ? motion::css_feed_time(*arc, state_.css, feed_mm, clamp) : motion::css_feed_time(line, state_.css, feed_mm, clamp);
    } else if (e.kind == EventKind::thread && state_.thread_lead_change != 0) {
        // G34: revolutions from the integral of the lead (motion/time.hpp variable_lead).
        const auto v = motion::variable_lead(timed_length_mm, feed_mm, state_.thread_lead_change * state_.unit_scale());
        if (v && e.spindle_rpm > 0) seconds = v->revolutions / e.spindle_rpm * 60.0;
        if (v) e.lead_end = v->lead_end / state_.unit_scale();
    } else {
        const double mm_per_min = per_rev ? motion::feed_per_minute(feed_mm, e.spindle_rpm) : feed_mm;
        seconds = mm_per_min > 0 ? timed_length_mm / mm_per_min * 60.0 : 0;
    }
    if (e.kind == EventKind::thread && state_.thread_lead_change == 0) e.lead_end = e.feed;
    seconds *= feed.time_factor;   // [seed 004 G28 ramp] 1 except for a ramp piece
    if (seconds > 0 && std::isfinite(seconds) && accel_mm_s2 > 0) {
        // Exact-stop trapezoid at the move's mean speed (motion/time.hpp).
        const double v = timed_length_mm / seconds;
        seconds = motion::trapezoid_time(timed_length_mm, v, accel_mm_s2);
    }
    e.time_s = std::isfinite(seconds) ? seconds : 0;
}

// A feed move needs a feed rate: F0, or no F since power-on, stops the control with alarm 011
// ([FANUC] PS011 "feedrate zero"; semantics.md §4). A move that goes nowhere feeds nothing.
bool Executor::feed_commanded(bool moves, const BlockContext& ctx, double feed) {
    if (feed > 0 || !moves) return true;
    alarm(ctx, alarms::feed_zero,
          fmt::format("feed move with no feed rate commanded (F{:g}): alarm 011; program F before the first "
                      "G01/G02/G03", feed));
    return false;
}

void Executor::move(EventKind kind, const Position& to, const BlockContext& ctx, const FeedRate& feed) {
    // [seed 004 G28 K F] the last K mm of a G01 move at the reduced feed (executor_iso_specials.cpp).
    if (state_.slowdown && kind == EventKind::linear && ctx.motion_in(state_) == fn::linear &&
        slowed_move(to, ctx, feed) != Outcome::not_mine)
        return;
    run_move(kind, to, ctx, feed);
}

void Executor::run_move(EventKind kind, const Position& to, const BlockContext& ctx, const FeedRate& feed) {
    if (kind == EventKind::linear && !feed_commanded(to != state_.position, ctx, feed.value)) return;
    Event e;
    e.kind = kind;
    e.source = ctx.source();
    e.start = state_.position;
    e.end = to;
    if (!within_soft_limits(to, to, ctx)) return;
    // The axes travel from where they stand to the new machine position: an offset taken up by this
    // move (G43 H, a lathe T offset, G49) is part of it (differential A7: `G43 Z15. H1` at Z15 moves).
    const Position machine_to = machine_position_of(to);
    const Travel travel_total = travel_of(state_.machine_at, machine_to, setup_);
    e.length_mm = travel_total.linear;
    std::array<motion::AxisLimits, kAxisCount> limits{};
    std::array<double, kAxisCount> travel{};
    for (std::size_t a = 0; a < kAxisCount; ++a) {
        limits[a] = {setup_.rapid_mm_min[a], setup_.accel_mm_s2[a]};
        travel[a] = std::fabs(machine_to[a] - state_.machine_at[a]) * (a == 0 && setup_.diameter_x ? 0.5 : 1.0);
    }
    if (kind == EventKind::rapid) {
        // Each axis at its own rapid rate (dog-leg) or all scaled to the slowest (straight line),
        // with each axis' acceleration (gcode-tables.md §5, motion/time.hpp rapid_time).
        e.time_s = motion::rapid_time(travel, limits, setup_.rapid_dogleg ? motion::RapidMode::dog_leg
                                                                          : motion::RapidMode::straight);
        if (!std::isfinite(e.time_s)) e.time_s = 0;   // an axis without a rapid rate: not timed
        e.feed = feed.value;
        result_.rapid_distance_mm += e.length_mm;
    } else {
        const motion::Vec3 delta{travel[0], travel[1], travel[2]};
        const motion::AxisLimits3 l3{limits[0], limits[1], limits[2]};
        const double accel = motion::path_accel(delta, l3);
        // F applies to the composite of linear mm and rotary degrees ([FANUC] "feedrate of rotary
        // axes"): a C-only move at F100 turns 100°/min.
        const double timed = std::hypot(e.length_mm, travel_total.rotary);
        time_feed_move(e, timed, std::isfinite(accel) ? accel : 0.0, nullptr, feed);
        result_.feed_distance_mm += e.length_mm;
    }
    state_.position = to;
    const bool thread = kind == EventKind::thread;
    const double thread_speed = thread ? std::max(e.feed, e.lead_end) * state_.unit_scale() * e.spindle_rpm : 0.0;
    emit(std::move(e), machine_to);   // offsets unchanged since machine_to was computed from `to` (= e.end)
    if (thread && setup_.max_cutting_feed > 0 && thread_speed > setup_.max_cutting_feed) {
        // cycles.md §9: lead × rpm is the axis speed of a thread; the analyzer reads this event.
        Event w = event_at(EventKind::message, ctx);
        w.code = kerf_warning::thread_speed_over_limit;
        w.text = fmt::format("thread at {:g} mm/min (lead × rpm) is over the machine's maximum cutting feed {:g} mm/min",
                             thread_speed, setup_.max_cutting_feed);
        emit(std::move(w));
    }
}

// G32/G33 and G34 (cycles.md §9). The lead is F, or E where the block has one (seed 003 "E = lead
// in mm", ADV400 "pitch E"); G34 adds K, the lead change per revolution ([FANUC]), and a lead
// that would reach zero before the end is [FANUC] alarm 313 (lead level error).
void Executor::thread_move(const BlockContext& ctx, const Position& to) {
    const BlockWords& words = ctx.words;
    const auto* e = words.get('E');
    state_.thread_lead = e ? axis_value(state_, *e, 'E') : state_.feed;
    const auto* k = words.get('K');
    state_.thread_lead_change = state_.flags.motion == fn::variable_lead_thread_cutting && k ? axis_value(state_, *k, 'K') : 0;
    if (state_.thread_lead_change != 0) {
        const double length = travel_of(state_.position, to, setup_).linear;   // program units, like the lead
        if (!motion::variable_lead(length, state_.thread_lead, state_.thread_lead_change)) {
            alarm(ctx, 313,
                  fmt::format("G34 lead F{:g} K{:g} over {:g}: the lead reaches zero before the end (FANUC alarm 313, "
                              "lead level error)", state_.thread_lead, state_.thread_lead_change, length));
            return;
        }
    }
    move(EventKind::thread, to, ctx);
}

Outcome Executor::apply_motion(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    // [polar] G112/G107 modes: the block's path is in the Cartesian plane (polar.cpp).
    if (state_.transform || (ctx.scan.classes & kTransformCode)) {
        if (const Outcome o = apply_plane_transform(ctx); o != Outcome::not_mine) return o;
    }
    if (ctx.scan.classes & kOneShotCode) {   // G27–G30, G53 are group 00: the common block has none
        if (const Outcome o = apply_reference_motion(ctx); o != Outcome::not_mine) {
            state_.programmed.reset();
            return o;
        }
    }
    bool moves = false;
    // G45–G48 act only in their block (semantics.md §9.3): a block without them measures from where
    // the tool stands (its G91 increments, the axes it does not name), not from the point the
    // offset blocks programmed.
    if (state_.programmed_by_offset && !(ctx.scan.classes & kPositionOffsetCode)) state_.programmed.reset();
    state_.programmed_by_offset = false;
    // [path changers] After a corner of direct drawing the tool stands off the programmed point,
    // which the block's coordinates are measured from (executor_drawing.cpp).
    const Position& from = state_.programmed ? *state_.programmed : state_.position;   // no copy: every block passes here
    const Position to = target_position(state_, from, words, moves);
    // A cycle block is not a move block for G66 (done, not moved): the modal call does not follow it.
    if (const Outcome o = apply_cycle(ctx, moves, to); o != Outcome::not_mine) return o;
    // [seed 004 G43/G44 without H] the approach of §9.4 (executor_iso_specials.cpp).
    if (ctx.scan.classes & kApproachOffsetCode)
        if (const Outcome o = axial_offset_motion(ctx, to, moves); o != Outcome::not_mine) return o;
    if ((ctx.scan.classes & kArcApproachCode) && moves) return arc_approach_move(ctx, to);   // [seed 004 G12/G13]
    // [compensation] G40–G42 (executor_compensation.cpp): one test per block while it is off.
    if ((ctx.scan.classes & kRadiusCompCode) || compensating()) return compensate_motion(ctx, to, moves);
    if (drawing_words(ctx) && state_.flags.motion == fn::linear) return draw_block(ctx, state_.programmed.value_or(state_.position), to);
    if (const auto factor = position_offset_factor(ctx); factor && moves)
        return position_offset_move(ctx, *factor, state_.programmed.value_or(state_.position), to);
    if (moves) state_.programmed.reset();
    note_drawing_outside_g01(ctx);
    const dialects::FunctionId motion = state_.flags.motion;
    // G02/G03 with only I/J/K: a full circle from the current point ([FANUC]; semantics.md §3).
    if (!moves && !full_circle(motion, words)) return Outcome::done;
    if (motion == fn::rapid) move(EventKind::rapid, to, ctx);
    else if (motion == fn::linear) move(EventKind::linear, to, ctx);
    else if (motion == fn::circular_cw || motion == fn::circular_ccw) arc_move(motion == fn::circular_cw, to, ctx);
    else if (motion == fn::thread_cutting || motion == fn::variable_lead_thread_cutting) thread_move(ctx, to);
    else {
        Event e = event_at(EventKind::message, ctx);
        if (!motion.empty()) e.code = kerf_warning::not_modelled;
        e.text = motion.empty() ? std::string("axis words without a motion code (no G00/G01/G02/G03 active): no motion")
                                : fmt::format("motion '{}' is not expanded by kerf: no motion", motion);
        emit(e);
        return Outcome::done;
    }
    return unless_stopped(Outcome::moved);
}

void Executor::apply_dwell(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    if (!(ctx.scan.classes & kOneShotCode) || !has_function(ctx, fn::dwell)) return;
    // X and U in seconds, P in milliseconds (ADV400: P in seconds); `G4 F1` seconds with the
    // machine's dwell_f_word switch (semantics.md §8.2, §12.15).
    double seconds = 0;
    const auto* u = words.incremental.count('X') ? &words.incremental.at('X') : words.get('U');
    if (const auto* x = words.get('X')) seconds = x->value;
    else if (u) seconds = u->value;
    else if (const auto* p = words.get('P')) seconds = dwell_p_seconds(p->value);
    else if (const auto* f = words.get('F'); f && setup_.dwell_f_seconds) {
        seconds = f->value;
        Event warn = event_at(EventKind::message, ctx);
        warn.text = "G04 F is not a FANUC dwell address: read as seconds (semantics.md §8.2; use X, U or P)";
        emit(warn);
    }
    Event e = event_at(EventKind::dwell, ctx);
    e.time_s = std::max(0.0, seconds);
    emit(e);
}

std::optional<std::uint32_t> Executor::find_label(const Frame& f, double n) const {
    const LoadedFile& file = file_of(f);
    const std::uint32_t first = program_of(f).first_block;
    const auto has_label = [&](std::uint32_t b) {
        const auto seq = file.block(b).sequence_number();
        return seq && *seq == n;
    };
    // [Haas] forward from the jump, then from the top (dialects/SCHEMA.md label_search; the
    // references resolver's find_label_from searches the same way).
    const bool forward = dialect_.lexical.label_search == dialects::LabelSearch::forward && f.block > first;
    if (forward)
        for (std::uint32_t b = f.block; file.in_program(f.program.program, b); ++b)
            if (has_label(b)) return b;
    for (std::uint32_t b = first; file.in_program(f.program.program, b) && (!forward || b < f.block); ++b)
        if (has_label(b)) return b;
    return std::nullopt;
}

// M98 P (both forms, dialects.md §3.6) and [FANUC] M98 Q: Q is the sequence number where the
// called program starts; without P it is a label of the program being run (a local subroutine
// that ends with M99).
void Executor::call_subprogram(const BlockContext& ctx) {
    const Frame& frame = ctx.frame;
    const BlockWords& words = ctx.words;
    const auto call = ctx.view.subprogram_call();
    const auto* q = words.get('Q');
    if (!call && !q) {
        alarm(ctx, 76, "M98 without a program number P or a sequence number Q (alarm 076)");
        return;
    }
    std::optional<ProgramRef> target = frame.program;
    if (call) target = programs_.find_or_load(call->program, frame.program.file);
    if (!target) {
        if (!skip_resident_call(ctx, call->program, "M98"))
            alarm(ctx, 78, fmt::format("program O{:04} not found (alarm 078)", call->program));
        return;
    }
    if (static_cast<int>(frames_.size()) > setup_.max_call_depth) {
        alarm(ctx, 77, fmt::format("subprogram nesting deeper than {} (alarm 077)", setup_.max_call_depth));
        return;
    }
    Frame sub;
    sub.program = *target;
    sub.block = program_of(sub).first_block;
    if (q) {
        // Without P the label is one of the running program: searched from the call (Haas forward search).
        const auto label = find_label(call ? sub : frame, q->value);
        if (!label) {
            alarm(ctx, 78, fmt::format("M98 Q{}: no sequence number N{} in the called program (alarm 078)", q->value, q->value));
            return;
        }
        sub.block = *label;
    }
    sub.start_block = sub.block;
    const auto* l = words.get('L');
    sub.repeats_left = call ? call->repeats : (l ? std::max<std::int64_t>(1, std::lround(l->value)) : 1);
    Event e = event_at(EventKind::call, ctx);
    e.code = call ? static_cast<int>(call->program) : 0;
    e.text = q ? fmt::format("M98 Q{}", q->value) : "M98";
    emit(e);
    frames_.push_back(sub);
}

// M99 in a main program: back to its start, or to N p (dialects.md §3.6): the bar feeder's loop.
// The control runs it until the operator stops it; a dry run runs RunOptions::passes passes and
// ends with a note, so times and pictures are those of a pass, not of ten million blocks.
void Executor::main_program_pass(Frame& frame, const BlockContext& ctx, const Word* p) {
    std::optional<std::uint32_t> target = program_of(frame).first_block;
    if (p) target = find_label(frame, p->value);
    if (!target) {
        alarm(ctx, 78, fmt::format("M99 P{}: no N{} in this program (alarm 078)", p->value, p->value));
        return;
    }
    if (*target >= frame.block) {   // M99 P to a later block: a jump forward, not a new pass
        frame.block = *target;
        return;
    }
    if (result_.passes < options_.passes) {
        ++result_.passes;
        frame.block = *target;
        return;
    }
    Event e = event_at(EventKind::message, ctx);
    e.code = kerf_warning::program_repeats;
    e.text = fmt::format("the program repeats: M99 in the main program starts it again (a bar-feed loop); the dry run "
                         "stops after {} pass{}, and its times are for {} (kerf run --passes N)",
                         result_.passes, result_.passes == 1 ? "" : "es", result_.passes == 1 ? "one pass" : "these passes");
    emit(std::move(e));
    result_.repeats = true;
    result_.completed = true;
    frames_.clear();
}

void Executor::apply_m_codes(Frame& frame, const BlockContext& ctx, MPhase phase) {
    const BlockWords& words = ctx.words;
    for (const ast::CodeRef& c : ctx.scan.m) {
        if (!c.info || c.info->has(dialects::traits::after_motion) != (phase == MPhase::after_motion)) continue;
        const dialects::FunctionId f = c.info->function;
        Event e = event_at(EventKind::message, ctx);   // the kind is set per code below
        e.code = c.key ? *c.key / 10 : 0;
        if (f == fn::spindle_cw || f == fn::spindle_ccw || f == fn::spindle_stop) {
            state_.spindle_on = f != fn::spindle_stop;
            e.kind = EventKind::spindle;
            e.spindle_rpm = state_.spindle_on ? current_rpm(state_, state_.position[0]) : 0;
            e.spindle_running = state_.spindle_on;   // check3: start or stop, for the analyzer (K5010)
            emit(e);
        } else if (f == fn::tool_change) {
            state_.tool = state_.pending_tool;
            if (std::find(result_.tools.begin(), result_.tools.end(), state_.tool) == result_.tools.end())
                result_.tools.push_back(state_.tool);
            e.kind = EventKind::tool_change;
            e.tool = state_.tool;
            emit(e);
        } else if (f == fn::coolant_on || f == fn::coolant_off) {
            e.kind = EventKind::coolant;
            emit(e);
        } else if (f == fn::program_stop || f == fn::optional_stop) {
            e.kind = f == fn::program_stop ? EventKind::stop : EventKind::optional_stop;
            emit(e);
            if (options_.stop_at_m00) stopped_ = true;
        } else if (f == fn::program_end || f == fn::program_end_rewind) {
            e.kind = EventKind::end;
            emit(e);
            result_.completed = true;
            frames_.clear();
            return;
        } else if (f == fn::subprogram_call) {
            call_subprogram(ctx);
            return;
        } else if (f == fn::local_subprogram_call) {
            call_local_subprogram(ctx);   // [Haas] M97 (executor_local_call.cpp)
            return;
        } else if (f == fn::thread_chamfer_on || f == fn::thread_chamfer_off) {
            state_.thread_chamfer = f == fn::thread_chamfer_on;   // [Haas] M23 / M24 (cycles/haas_lathe.cpp)
        } else if (f == fn::subprogram_return) {
            e.kind = EventKind::return_;
            emit(e);
            const auto* p = words.get('P');
            if (frames_.size() == 1) {
                main_program_pass(frame, ctx, p);
                return;
            }
            if (--frame.repeats_left > 0) {
                frame.block = frame.start_block;
                return;
            }
            pop_frame();   // ctx.frame is gone: only ctx.source() is read below
            if (p) {
                // M99 P n: back to sequence number n of the caller (dialects.md §3.6).
                Frame& caller = frames_.back();
                if (const auto label = find_label(caller, p->value)) caller.block = *label;
                else alarm(ctx, 78, fmt::format("M99 P{}: no N{} in the calling program (alarm 078)", p->value, p->value));
            }
            return;
        }
    }
}

}  // namespace kerf::interpreter
