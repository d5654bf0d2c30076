// Steps 2-5 of a block: words and their values, F S T, modal codes, coordinate systems.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dialects/alarms.hpp"
#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

namespace {

// Letters that are distances besides the axes: arc centre and radius words.
constexpr std::uint32_t kDistanceLetters = 1u << ('I' - 'A') | 1u << ('J' - 'A') | 1u << ('K' - 'A') | 1u << ('R' - 'A');

// [FANUC] Custom macro: "when a variable value is used in an address, it is rounded off to the
// least significant digit of the address": `#1=1.2345` then `X-#1` is X-1.235 on IS-B mm, X[1/3]
// is X0.333. Half away from zero; the nudge keeps 1.2345 (1.23449999... in binary) rounding up.
double round_to_increment(double value, double increment) {
    const double steps = value / increment;
    return std::round(steps + std::copysign(1e-9, steps)) * increment;
}

}  // namespace

macro::Options Executor::macro_options(const MachineState& s, bool address) const {
    macro::Options o;
    o.angle_range = setup_.atan_minus_180 ? macro::AngleRange::minus_180_to_180 : macro::AngleRange::zero_to_360;
    // ROUND in an address rounds to the least input increment; ADP undoes the increment scaling
    // of G65 arguments written without a point ([FANUC], macro/evaluate.hpp).
    if (address) o.round_increment = setup_.increment(s.flags.inch);
    if (!setup_.calculator_decimal) o.adp_factor = 1.0 / setup_.increment(s.flags.inch);
    return o;
}

std::optional<Alarm> Executor::read_words(const MachineState& s, const Position& at, const BlockContext& ctx,
                                          BlockWords& out) const {
    const ast::SyntaxTree& tree = ctx.view.tree();
    const dialects::LexicalRules& rules = dialect_.lexical;
    // Letters that are data of a code in this block (G04 X, G10 U/W, G71 U/W, SPINNER cycle words)
    // do not move the tool and do not set the modal F, S or T (the codes' parameter_words).
    const std::uint32_t data = ctx.scan.data_letters;
    const auto tokens = ctx.view.tokens();
    for (std::uint32_t i = 0; i < tokens.size(); ++i) {
        const ast::Token& t = tokens[i];
        if (t.kind != ast::TokenKind::word || t.has(ast::token_flags::value_none)) continue;
        if (t.role() == ast::Role::g_code || t.role() == ast::Role::m_code || t.role() == ast::Role::sequence ||
            t.role() == ast::Role::program)
            continue;
        BlockWords::Word w;
        w.token = ctx.view.first_token() + i;
        w.has_point = t.has(ast::token_flags::has_point);
        const bool letter = t.letter >= 'A' && t.letter <= 'Z';
        const std::uint32_t bit = letter ? 1u << (t.letter - 'A') : 0u;
        w.data = (data & bit) != 0 || (t.role() == ast::Role::parameter && (dialect_axes_ & bit) != 0);
        if (t.has(ast::token_flags::value_expr)) {
            ExecutorSystemVariables system(*this, s, at);   // #5001 and the like: of the reading
            const macro::Result r = macro::evaluate(tree, t.payload, variables_, system, macro_options(s, true));
            if (r.error) return Alarm{ctx.source(), at, r.error->alarm, r.error->message};
            if (r.value.vacant) continue;   // a vacant variable omits the address (FANUC macro B)
            w.value = letter && (kDistanceLetters >> (t.letter - 'A') & 1u || (dialect_axes_ & bit) != 0)
                          ? round_to_increment(r.value.number, increment(s, t.letter))
                          : r.value.number;
            w.has_point = true;             // macro values are never in least increments
        } else {
            w.value = tree.number_value(t);
        }
        if (t.role() == ast::Role::axis_incremental && !w.data) out.incremental.set(rules.incremental_axis_of(t.letter), w);
        else if (letter) out.words.set(t.letter, w);
    }
    return std::nullopt;
}

// An axis or distance value in mm: without a decimal point and without calculator-type input it
// counts least input increments (dialects.md §2 "Numbers", cycles.md §0).
double Executor::axis_value(const MachineState& s, const BlockWords::Word& w, char letter) const {
    if (w.has_point || setup_.calculator_decimal) return w.value;
    return w.value * increment(s, letter);
}

// The least input increment of an address in the unit it is read in: inch under G20 (0.0001 in on
// IS-B, not 0.001), degrees on a rotary axis (C360000 is 360°) ([FANUC] "Least input increment").
double Executor::increment(const MachineState& s, char letter) const {
    const auto axis = axis_of_letter(letter);
    if (axis && setup_.rotary[static_cast<std::size_t>(*axis)] && dialect_axes_ >> (letter - 'A') & 1u)
        return setup_.increment_deg();
    return setup_.increment(s.flags.inch);
}

double Executor::current_rpm(const MachineState& s, double x_diameter) const {
    if (!s.flags.css) return s.spindle_rpm;
    // G96: n = 1000·Vc / (π·D), clamped by G50/G92 S and the machine (semantics.md §4.1).
    const double d = std::fabs(setup_.diameter_x ? x_diameter : 2 * x_diameter);
    double rpm = d > 1e-9 ? 1000.0 * s.css / (M_PI * d) : 1e12;
    if (s.max_rpm > 0) rpm = std::min(rpm, s.max_rpm);
    if (setup_.max_rpm > 0) rpm = std::min(rpm, setup_.max_rpm);
    return rpm;
}

void Executor::apply_feed_speed_tool(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    if (const auto* f = words.get('F'); f && !f->data) state_.feed = f->value;
    if (const auto* s = words.get('S'); s && !s->data) {
        if (has_function(ctx, fn::coordinate_system_setting)) {
            state_.max_rpm = s->value;   // G50 S / G92 S: the clamp for G96 (semantics.md §4.1)
        } else if (has_function(ctx, fn::css_on) || (state_.flags.css && !has_function(ctx, fn::css_off))) {
            state_.css = s->value;
        } else {
            state_.spindle_rpm = s->value;
        }
    }
    if (const auto* t = words.get('T'); t && !t->data) apply_tool_word(ctx, static_cast<int>(std::lround(t->value)));
}

// T per the dialect's tool word (dialects.md §3.5): `mmnn` = tool mm, offset nn (`T0` / `Tmm00`
// cancel the offset; the offset applies at once, moving the machine position, not the work
// position); `number` = a tool number. A turret (lathe) indexes at the T word, a mill's magazine
// changes on M06.
void Executor::apply_tool_word(const BlockContext& ctx, int value) {
    const bool split = dialect_.lexical.tool_word == "mmnn";
    const int tool = split ? value / 100 : value;
    if (split) state_.tool_offset = value % 100;
    if (dialect_.machine != dialects::MachineKind::lathe) {
        state_.pending_tool = tool;
        return;
    }
    if (tool == 0 || tool == state_.tool) return;
    Event e = event_at(EventKind::tool_change, ctx);
    e.tool = tool;
    e.code = state_.tool_offset;
    state_.tool = tool;
    if (std::find(result_.tools.begin(), result_.tools.end(), tool) == result_.tools.end()) result_.tools.push_back(tool);
    emit(e);
}

void Executor::apply_modal_codes(const BlockContext& ctx) {
    // Several codes of one group in a block: the last one wins (semantics.md §1.1).
    bool changed = false;          // a group other than motion changed: derive every flag again
    for (const ast::CodeRef& c : ctx.scan.g) {
        if (!c.info || c.info->has(dialects::traits::one_shot) || c.info->group.empty()) continue;
        // Nearly every block has a G00/G01/G02/G03 and most repeat the active one.
        const bool motion_group = c.info->has(dialects::traits::motion_group);
        const dialects::CodeInfo*& slot = state_.modal[c.info->group_index];
        if (slot == c.info) continue;
        slot = c.info;
        if (motion_group) {
            state_.flags.motion = c.info->function;
            state_.flags.motion_cycle = (code_class_of(*c.info) & kCycleCode) ? c.info : nullptr;   // G90/G92/G94
        } else {
            changed = true;
        }
    }
    if (changed) update_flags();
    cancel_cycle_by_motion_code(ctx);   // drilling cycles (executor_cycles.cpp)
}

// What #4102..#4120 read: the last B D E F H M N O S T (FANUC "modal information").
void Executor::remember_words(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    for (const char letter : {'B', 'D', 'E', 'F', 'H', 'S', 'T'})
        if (const auto* w = words.get(letter)) state_.last_words[static_cast<std::size_t>(letter - 'A')] = w->value;
    for (const ast::CodeRef& c : ctx.scan.m)
        if (c.key) state_.last_words['M' - 'A'] = static_cast<double>(*c.key) / 10.0;
    if (ctx.scan.sequence) state_.last_words['N' - 'A'] = *ctx.scan.sequence;
}

Position Executor::machine_offset(const MachineState& s) const {
    // semantics.md §2.7: work offset + external − work shift + local shift + setting correction,
    // and on lathes the tool offset (geometry + wear) of the active T (dialects.md §3.5).
    const Position tool = tool_offset(s);
    const Position& work = active_work_offset(s);
    // [length offsets] G43/G44 H on Z, once taken up (executor_length.cpp). Added inside the loop,
    // in registers: a store to p[2] after the loop's vector stores (or to an array of lengths) and
    // a vector read across it stalled store forwarding, the most expensive instruction of a dry
    // run's move. x + -0.0 is x for every x (+0.0 would turn -0.0 into +0.0).
    const double length = s.length_applied_mm;
    Position p{};
    for (std::size_t a = 0; a < kAxisCount; ++a)
        p[a] = work[a] + s.external_offset[a] + setup_.work_shift_sign * s.work_shift[a] + s.local_shift[a] +
               s.setting_shift[a] + tool[a] + (a == 2 ? length : -0.0);
    return p;
}

const Position& Executor::active_work_offset(const MachineState& s) const {
    static const Position kZero{};
    if (s.additional_system == 0) return s.work_offsets[static_cast<std::size_t>(s.work_system)];
    const auto it = memory_.additional_offsets.find(s.additional_system);
    return it == memory_.additional_offsets.end() ? kZero : it->second;
}

std::optional<int> Executor::additional_number(const BlockContext& ctx, std::optional<double> p) {
    const long n = p ? std::lround(*p) : 1;
    if (n >= 1 && n <= setup_.additional_work_offset_count && (!p || *p == static_cast<double>(n)))
        return static_cast<int>(n);
    alarm(ctx, alarms::offset_number,
          fmt::format("additional work offset P{:g}: the machine has P1 to P{} (alarm 030, additional_work_offset_count)",
                      p.value_or(1.0), setup_.additional_work_offset_count));
    return std::nullopt;
}

Position Executor::tool_offset(const MachineState& s) const {
    // Mills offset the length with G43/G44 H (executor_length.cpp) and the radius with G41/G42 D, not by T.
    if (dialect_.machine != dialects::MachineKind::lathe || s.tool_offset == 0) return {};
    const auto it = memory_.tools.find(s.tool_offset);
    if (it == memory_.tools.end()) return {};
    Position p{};
    for (std::size_t a = 0; a < kAxisCount; ++a) p[a] = it->second.geometry[a] + it->second.wear[a];
    return p;
}

Outcome Executor::apply_coordinate_operations(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    for (const ast::CodeRef& c : ctx.scan.g) {
        if (!c.info || (code_class_of(*c.info) & kMotionCode)) continue;   // G00/G01...: none of these
        const dialects::FunctionId f = c.info->function;
        if (c.info->work_coordinate() != 0) {   // G54–G59
            const int n = c.info->work_coordinate() - 1;
            {
                change_offsets([&] {
                    state_.work_system = n;
                    state_.additional_system = 0;
                    if (setup_.g54_cancels_g52) state_.local_shift = {};   // pcnc: G54–G59 cancel G52 (§2.4)
                });
            }
        } else if (f == fn::work_coordinate_additional) {
            // G54.1 Pn ([FANUC]; no P is P1), Haas G154 Pn; Haas G110–G129 carry their P as data
            // (`implied = ["P1"]`, haas-mill.toml: G110 is G154 P1, haas.co.uk "Programmable Offsets").
            std::optional<double> p;
            if (const auto* w = words.get('P')) p = w->value;
            for (const auto& [letter, value] : c.info->implied)
                if (letter == 'P' && !p) p = value;
            const auto n = additional_number(ctx, p);
            if (!n) return Outcome::stopped;
            change_offsets([&] { state_.additional_system = *n; });
        } else if (f == fn::programmable_data_input) {
            apply_data_input(ctx);
            return unless_stopped(Outcome::done);   // no motion in a G10 block
        } else if (f == fn::coordinate_rotation || f == fn::coordinate_rotation_cw) {
            apply_rotation(ctx);
            return unless_stopped(Outcome::done);   // G68 sets the rotation; the next block moves (semantics.md §2.9)
        } else if (f == fn::coordinate_rotation_cancel) {
            state_.rotation.reset();
        } else if (f == fn::modal_macro_call_cancel) {
            state_.modal_call.reset();   // G67
        } else if (f == fn::stroke_check_on || f == fn::stroke_check_off) {
            state_.soft_limits_on = f == fn::stroke_check_on;
        } else if (f == fn::coordinate_system_setting && (words.get('X') || words.get('Z') || words.get('Y'))) {
            // G50/G92 X Z: the current point gets the programmed values (semantics.md §2.5); on
            // FANUC it also cancels G52 (§2.4).
            if (!setup_.g52_current_point) change_offsets([&] { state_.local_shift = {}; });
            for (const auto& [letter, w] : words.words) {
                const auto axis = axis_of_letter(letter);
                if (!axis) continue;
                const std::size_t a = static_cast<std::size_t>(*axis);
                const double value = axis_value(state_, w, letter);
                state_.setting_shift[a] += (state_.position[a] - value) * state_.axis_scale(a);   // offsets are mm
                state_.position[a] = value;
            }
            return unless_stopped(Outcome::done);
        } else if (f == fn::local_system_shift || f == fn::local_system_current_point) {
            apply_local_system(ctx, f == fn::local_system_current_point);
            return unless_stopped(Outcome::done);   // G52 does not move the tool (semantics.md §2.4)
        } else if (f == fn::local_system_cancel) {
            change_offsets([&] { state_.local_shift = {}; });   // G152 (pcnc-mill)
        } else if (f == fn::cancel_coordinate_setting) {
            // G50.3 / G92.1: the named axes (all when none is named) lose the G50/G92 correction;
            // no motion in the block ([FANUC] workpiece coordinate system preset).
            bool named = false;
            for (std::size_t a = 0; a < kAxisCount; ++a) named = named || words.get(kAxisLetters[a]);
            for (std::size_t a = 0; a < kAxisCount; ++a) {
                if (named && !words.get(kAxisLetters[a])) continue;
                state_.position[a] += state_.setting_shift[a] / state_.axis_scale(a);
                state_.setting_shift[a] = 0;
            }
            return unless_stopped(Outcome::done);
        }
    }
    return Outcome::not_mine;   // the block goes on to its motion
}

// G52, semantics.md §2.4. FANUC: the local origin is the work origin plus the programmed vector
// (G52 X0 Z0 cancels). pcnc/ADV400 (the machine's g52 switch, or the dialect's function id): the
// current point takes the programmed values on the programmed axes; all zeros cancel (ADV400).
void Executor::apply_local_system(const BlockContext& ctx, bool current_point_code) {
    const BlockWords& words = ctx.words;
    const bool current_point = current_point_code || setup_.g52_current_point;
    bool all_zero = true;
    for (const auto& [letter, w] : words.words)
        if (axis_of_letter(letter) && dialect_.lexical.is_axis(letter) && w.value != 0) all_zero = false;
    change_offsets([&] {
        if (current_point && all_zero && setup_.g52_zeros_cancel) {
            state_.local_shift = {};
            return;
        }
        for (const auto& [letter, w] : words.words) {
            const auto axis = axis_of_letter(letter);
            if (!axis || !dialect_.lexical.is_axis(letter)) continue;
            const std::size_t a = static_cast<std::size_t>(*axis);
            const double v = axis_value(state_, w, letter);
            // current point: program p maps to work p + L with L = position − value (§2.4);
            // FANUC: the vector itself, in the program's unit (§4.2; offsets are kept in mm).
            state_.local_shift[a] = current_point ? state_.local_shift[a] + (state_.position[a] - v) * state_.axis_scale(a) : v * state_.axis_scale(a);
        }
    });
    Event e = event_at(EventKind::coordinate_change, ctx);
    e.text = "local coordinate system (G52)";
    emit(e);
}

}  // namespace kerf::interpreter
