// Steps 2-5 of a block: words and their values, F S T, modal codes, coordinate systems.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

bool Executor::evaluate_words(const ast::BlockView& view, BlockWords& out) {
    const LoadedFile& file = file_of(*frame_);
    const dialects::LexicalRules& rules = dialect_.lexical;
    const auto tokens = view.tokens();
    for (std::uint32_t i = 0; i < tokens.size(); ++i) {
        const ast::Token& t = tokens[i];
        if (t.kind != ast::TokenKind::word || t.has(ast::token_flags::value_none)) continue;
        if (t.role() == ast::Role::g_code || t.role() == ast::Role::m_code || t.role() == ast::Role::sequence ||
            t.role() == ast::Role::program)
            continue;
        BlockWords::Word w;
        w.token = view.first_token() + i;
        w.has_point = t.has(ast::token_flags::has_point);
        if (t.has(ast::token_flags::value_expr)) {
            const macro::Result r = macro::evaluate(file.tree, t.payload, variables_);
            if (r.error) {
                alarm(*frame_, view, r.error->alarm, r.error->message);
                return false;
            }
            if (r.value.vacant) continue;   // a vacant variable omits the address (FANUC macro B)
            w.value = r.value.number;
            w.has_point = true;             // macro values are never in least increments
        } else {
            w.value = file.tree.number_value(t);
        }
        if (t.role() == ast::Role::axis_incremental) out.incremental[rules.incremental_axis_of(t.letter)] = w;
        else out.words[t.letter] = w;
    }
    return true;
}

// An axis or distance value in mm: without a decimal point and without calculator-type input it
// counts least input increments (dialects.md §2 "Numbers", cycles.md §0).
double Executor::axis_value(const BlockWords::Word& w, char) const {
    if (w.has_point || setup_.calculator_decimal) return w.value;
    return w.value * setup_.increment_mm;
}

double Executor::current_rpm(double x_diameter) const {
    if (modal_function("02") != fn::css_on && modal_function("04") != fn::css_on) return spindle_rpm_;
    // G96: n = 1000·Vc / (π·D), clamped by G50/G92 S and the machine (semantics.md §4.1).
    const double d = std::fabs(setup_.diameter_x ? x_diameter : 2 * x_diameter);
    double rpm = d > 1e-9 ? 1000.0 * css_ / (M_PI * d) : 1e12;
    if (max_rpm_ > 0) rpm = std::min(rpm, max_rpm_);
    if (setup_.max_rpm > 0) rpm = std::min(rpm, setup_.max_rpm);
    return rpm;
}

void Executor::apply_feed_speed_tool(const ast::BlockView& view, const BlockWords& words) {
    if (const auto* f = words.get('F')) feed_ = f->value;
    if (const auto* s = words.get('S')) {
        if (has_function(view, fn::coordinate_system_setting)) {
            max_rpm_ = s->value;   // G50 S / G92 S: the clamp for G96 (semantics.md §4.1)
        } else if (has_function(view, fn::css_on) ||
                   ((modal_function("02") == fn::css_on || modal_function("04") == fn::css_on) &&
                    !has_function(view, fn::css_off))) {
            css_ = s->value;
        } else {
            spindle_rpm_ = s->value;
        }
    }
    if (const auto* t = words.get('T')) {
        // Tmmnn on lathes (dialects.md §3.5): mm = station, nn = offset; T0 / Tmm00 cancel the offset.
        const int value = static_cast<int>(std::lround(t->value));
        const bool lathe = dialect_.machine == dialects::MachineKind::lathe;
        const int station = lathe ? value / 100 : value;
        tool_offset_ = lathe ? value % 100 : tool_offset_;
        if (lathe && station != 0 && station != tool_) {
            Event e = event_at(EventKind::tool_change, *frame_, view);
            e.tool = station;
            e.code = tool_offset_;
            tool_ = station;
            if (std::find(result_.tools.begin(), result_.tools.end(), station) == result_.tools.end())
                result_.tools.push_back(station);
            emit(e);
        } else if (!lathe) {
            pending_tool_ = station;   // a mill changes tools on M06
        }
    }
}

void Executor::apply_modal_codes(const ast::BlockView& view) {
    // Several codes of one group in a block: the last one wins (semantics.md §1.1).
    for (const ast::CodeRef& c : view.g_codes())
        if (c.info && c.info->group != "00") modal_[c.info->group] = c.info;
}

Position Executor::machine_offset() const {
    // semantics.md §2.7: work offset + external − work shift + local shift + setting correction.
    Position p{};
    for (std::size_t a = 0; a < kAxisCount; ++a)
        p[a] = setup_.work_offsets[static_cast<std::size_t>(work_system_)][a] + setup_.external_offset[a] -
               work_shift_[a] + local_shift_[a] + setting_shift_[a];
    return p;
}

bool Executor::apply_coordinate_operations(const ast::BlockView& view, const BlockWords& words) {
    for (const ast::CodeRef& c : view.g_codes()) {
        if (!c.info) continue;
        const std::string& f = c.info->function;
        if (f.rfind(fn::work_coordinate_prefix, 0) == 0) {
            const int n = f.back() - '1';
            if (n >= 0 && n < 6) {
                change_offsets([&] {
                    work_system_ = n;
                    if (setup_.g52_current_point) local_shift_ = {};   // pcnc: G54–G59 cancel G52 (§2.4)
                });
            }
        } else if (f == fn::programmable_data_input) {
            const auto* p = words.get('P');
            if (p && p->value == 0) {
                // G10 P0: the work shift register; X/Z replace it, U/W add to it (semantics.md §2.6).
                // In the G10 block U/W are data words (parameter_words), so they arrive by letter.
                change_offsets([&] {
                    for (const auto& [letter, w] : words.words) {
                        const char incremental_of = dialect_.lexical.incremental_axis_of(letter);
                        const auto axis = axis_of_letter(incremental_of ? incremental_of : letter);
                        if (!axis || letter == 'P') continue;
                        double& reg = work_shift_[static_cast<std::size_t>(*axis)];
                        reg = incremental_of ? reg + axis_value(w, letter) : axis_value(w, letter);
                    }
                });
                Event e = event_at(EventKind::coordinate_change, *frame_, view);
                e.text = "work shift";
                emit(e);
            }
            return false;   // no motion in a G10 block
        } else if (f == fn::coordinate_system_setting && (words.get('X') || words.get('Z') || words.get('Y'))) {
            // G50/G92 X Z: the current point gets the programmed values (semantics.md §2.5).
            for (const auto& [letter, w] : words.words) {
                const auto axis = axis_of_letter(letter);
                if (!axis) continue;
                const std::size_t a = static_cast<std::size_t>(*axis);
                const double value = axis_value(w, letter);
                setting_shift_[a] += position_[a] - value;
                position_[a] = value;
            }
            return false;
        } else if (f == fn::local_system_shift || f == fn::local_system_current_point) {
            apply_local_system(view, words, f == fn::local_system_current_point);
            return false;   // G52 does not move the tool (semantics.md §2.4)
        } else if (f == fn::local_system_cancel) {
            change_offsets([&] { local_shift_ = {}; });   // G152 (pcnc-mill)
        } else if (f == fn::cancel_coordinate_setting) {
            for (std::size_t a = 0; a < kAxisCount; ++a) position_[a] += setting_shift_[a];
            setting_shift_ = {};
        }
    }
    return true;
}

// G52, semantics.md §2.4. FANUC: the local origin is the work origin plus the programmed vector
// (G52 X0 Z0 cancels). pcnc/ADV400 (the machine's g52 switch, or the dialect's function id): the
// current point takes the programmed values on the programmed axes; all zeros cancel (ADV400).
void Executor::apply_local_system(const ast::BlockView& view, const BlockWords& words, bool current_point_code) {
    const bool current_point = current_point_code || setup_.g52_current_point;
    bool all_zero = true;
    for (const auto& [letter, w] : words.words)
        if (axis_of_letter(letter) && dialect_.lexical.is_axis(letter) && w.value != 0) all_zero = false;
    change_offsets([&] {
        if (current_point && all_zero) {
            local_shift_ = {};
            return;
        }
        for (const auto& [letter, w] : words.words) {
            const auto axis = axis_of_letter(letter);
            if (!axis || !dialect_.lexical.is_axis(letter)) continue;
            const std::size_t a = static_cast<std::size_t>(*axis);
            const double v = axis_value(w, letter);
            // current point: program p maps to work p + L with L = position − value (§2.4);
            // FANUC: the vector itself.
            local_shift_[a] = current_point ? local_shift_[a] + (position_[a] - v) : v;
        }
    });
    Event e = event_at(EventKind::coordinate_change, *frame_, view);
    e.text = "local coordinate system (G52)";
    emit(e);
}

}  // namespace kerf::interpreter
