// Steps 7-9 of a block: motion, dwell, M codes (with calls and returns).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

namespace {
bool incremental_mode(std::string_view distance_function) { return distance_function == fn::incremental_programming; }

// Geometric length: lathe X is a diameter, the path runs at the radius.
double distance(const Position& a, const Position& b, bool diameter_x) {
    double sum = 0;
    for (std::size_t i = 0; i < kAxisCount; ++i) {
        if (i >= 3) continue;   // rotary axes add time, not length
        const double d = (b[i] - a[i]) * (i == 0 && diameter_x ? 0.5 : 1.0);
        sum += d * d;
    }
    return std::sqrt(sum);
}
}  // namespace

Position Executor::target_position(const BlockWords& words, bool& moves) const {
    Position to = position_;
    moves = false;
    const bool incremental = incremental_mode(modal_function("03"));
    for (const auto& [letter, w] : words.words) {
        const auto axis = axis_of_letter(letter);
        if (!axis || !dialect_.lexical.is_axis(letter)) continue;
        const std::size_t a = static_cast<std::size_t>(*axis);
        const double v = axis_value(w, letter);
        to[a] = incremental ? to[a] + v : v;
        moves = true;
    }
    // U W H: incremental in system A; "the later-specified word is used" with X/U together (§3.2).
    for (const auto& [axis_letter, w] : words.incremental) {
        const auto axis = axis_of_letter(axis_letter);
        if (!axis) continue;
        const std::size_t a = static_cast<std::size_t>(*axis);
        const auto absolute = words.words.find(axis_letter);
        if (absolute == words.words.end() || absolute->second.token < w.token) to[a] = position_[a] + axis_value(w, axis_letter);
        moves = true;
    }
    return to;
}

void Executor::move(EventKind kind, const Position& to, const Frame& f, const ast::BlockView& view) {
    Event e;
    e.kind = kind;
    e.source = source(f, view);
    e.start = position_;
    e.end = to;
    e.length_mm = distance(position_, to, setup_.diameter_x);
    e.feed = feed_;
    if (kind == EventKind::rapid) {
        // Each axis at its own rapid rate (dog-leg) or all scaled to the slowest (straight line):
        // either way the move lasts as long as its slowest axis needs (gcode-tables.md §5).
        double t = 0;
        for (std::size_t a = 0; a < kAxisCount; ++a) {
            const double rate = setup_.rapid_mm_min[a];
            const double d = std::fabs(to[a] - position_[a]) * (a == 0 && setup_.diameter_x ? 0.5 : 1.0);
            if (rate > 0) t = std::max(t, d / rate * 60.0);
        }
        e.time_s = t;
        result_.rapid_distance_mm += e.length_mm;
    } else {
        const bool per_rev = modal_function("05") == fn::feed_per_revolution;
        e.feed_per_rev = per_rev;
        const double rpm = current_rpm(to[0]);
        e.spindle_rpm = rpm;
        const double mm_per_min = per_rev ? feed_ * rpm : feed_;
        e.time_s = mm_per_min > 0 ? e.length_mm / mm_per_min * 60.0 : 0;
        result_.feed_distance_mm += e.length_mm;
    }
    position_ = to;
    emit(std::move(e));
}

void Executor::apply_motion(const ast::BlockView& view, const BlockWords& words) {
    bool moves = false;
    const Position to = target_position(words, moves);
    const Frame& f = *frame_;
    // One-shot motion codes first: G53 machine coordinates, G28 reference return.
    if (has_function(view, fn::machine_coordinate_select) || has_function(view, fn::machine_coordinate_select_g0_g1)) {
        if (!moves) return;
        const Position offset = machine_offset();
        Position target = position_;
        for (const auto& [letter, w] : words.words)
            if (const auto axis = axis_of_letter(letter); axis && dialect_.lexical.is_axis(letter))
                target[static_cast<std::size_t>(*axis)] = axis_value(w, letter) - offset[static_cast<std::size_t>(*axis)];
        move(EventKind::rapid, target, f, view);
        return;
    }
    if (has_function(view, fn::reference_return)) {
        if (!moves) return;
        // Via the intermediate point, then to reference point 1, programmed axes only (§2.8).
        move(EventKind::rapid, to, f, view);
        const Position offset = machine_offset();
        Position home = position_;
        for (std::size_t a = 0; a < kAxisCount; ++a) {
            const bool programmed = words.words.count(kAxisLetters[a]) || words.incremental.count(kAxisLetters[a]);
            if (programmed) home[a] = setup_.reference_points[0][a] - offset[a];
        }
        move(EventKind::rapid, home, f, view);
        return;
    }
    if (!moves) return;
    const std::string_view motion = modal_function("01");
    if (motion == fn::rapid) move(EventKind::rapid, to, f, view);
    else if (motion == fn::linear) move(EventKind::linear, to, f, view);
    else if (motion == fn::circular_cw || motion == fn::circular_ccw) arc_move(motion == fn::circular_cw, to, words, view);
    else if (motion == fn::thread_cutting) move(EventKind::thread, to, f, view);
    else {
        Event e = event_at(EventKind::message, f, view);
        e.text = fmt::format("motion of '{}' is not expanded yet (cycles: next issue); position kept", motion);
        emit(e);
    }
}

void Executor::apply_dwell(const ast::BlockView& view, const BlockWords& words) {
    if (!has_function(view, fn::dwell)) return;
    // X and U in seconds, P in milliseconds (ADV400: P in seconds) — semantics.md §8.2.
    double seconds = 0;
    if (const auto* x = words.get('X')) seconds = x->value;
    else if (const auto* u = words.incremental.count('X') ? &words.incremental.at('X') : words.get('U')) seconds = u->value;
    else if (const auto* p = words.get('P')) seconds = setup_.dwell_p_in_seconds ? p->value : p->value / 1000.0;
    Event e = event_at(EventKind::dwell, *frame_, view);
    e.time_s = seconds;
    emit(e);
}

std::optional<std::uint32_t> Executor::find_label(const Frame& f, double n) const {
    const ast::Program& p = program_of(f);
    const LoadedFile& file = file_of(f);
    for (std::uint32_t b = p.first_block; b < p.end_block; ++b)
        if (const auto seq = file.typed->block(b).sequence_number(); seq && *seq == n) return b;
    return std::nullopt;
}

void Executor::apply_m_codes(Frame& frame, const ast::BlockView& view, const BlockWords& words) {
    for (const ast::CodeRef& c : view.m_codes()) {
        if (!c.info) continue;
        const std::string& f = c.info->function;
        Event e = event_at(EventKind::message, frame, view);   // the kind is set per code below
        e.code = c.key ? *c.key / 10 : 0;
        if (f == fn::spindle_cw || f == fn::spindle_ccw || f == fn::spindle_stop) {
            spindle_on_ = f != fn::spindle_stop;
            e.kind = EventKind::spindle;
            e.spindle_rpm = spindle_on_ ? current_rpm(position_[0]) : 0;
            emit(e);
        } else if (f == fn::tool_change) {
            tool_ = pending_tool_;
            if (std::find(result_.tools.begin(), result_.tools.end(), tool_) == result_.tools.end())
                result_.tools.push_back(tool_);
            e.kind = EventKind::tool_change;
            e.tool = tool_;
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
            const auto call = view.subprogram_call();
            if (!call) {
                alarm(frame, view, 0, "M98 without a program number P");
                return;
            }
            const auto target = programs_.find_or_load(call->program, frame.program.file);
            if (!target) {
                alarm(frame, view, 78, fmt::format("program O{:04} not found (alarm 078)", call->program));
                return;
            }
            if (static_cast<int>(frames_.size()) > setup_.max_call_depth) {
                alarm(frame, view, 77, fmt::format("subprogram nesting deeper than {} (alarm 077)", setup_.max_call_depth));
                return;
            }
            e.kind = EventKind::call;
            e.code = static_cast<int>(call->program);
            emit(e);
            Frame sub;
            sub.program = *target;
            sub.block = program_of(sub).first_block;
            sub.repeats_left = call->repeats;
            frames_.push_back(sub);
            return;
        } else if (f == fn::subprogram_return) {
            e.kind = EventKind::return_;
            emit(e);
            const auto* p = words.get('P');
            if (frames_.size() == 1) {
                // M99 in a main program: back to its start, forever (the step limit bounds it).
                frame.block = program_of(frame).first_block;
                return;
            }
            if (--frame.repeats_left > 0) {
                frame.block = program_of(frame).first_block;
                return;
            }
            pop_frame();
            if (p) {
                // M99 P n: back to sequence number n of the caller (dialects.md §3.6).
                Frame& caller = frames_.back();
                if (const auto label = find_label(caller, p->value)) caller.block = *label;
                else alarm(caller, view, 0, fmt::format("M99 P{}: no N{} in the calling program", p->value, p->value));
            }
            return;
        }
    }
}

}  // namespace kerf::interpreter
