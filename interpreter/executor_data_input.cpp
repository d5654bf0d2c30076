// G10 programmable data input (semantics.md §2.6; [FANUC] "Programmable data input"):
//   lathe  G10 P0 X Z (U W)        work shift register: X/Z replace it, U/W add to it
//          G10 P n X Z R Q (U W C) tool offset n: wear (P1..), geometry (P10000 + n)
//   mill   G10 L2 P0..6 X Y Z      external offset (P0) / G54..G59; G91 adds
//          G10 L20 P n X Y Z       additional work offset of G54.1 Pn; G91 adds
//          G10 L10..L13 P n R      H geometry / H wear / D geometry / D wear
//          G10 P n R               memory A: one value per register (seed 003, semantics.md §2.6)
#include <fmt/format.h>

#include <cmath>

#include "dialects/alarms.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace {

constexpr int kGeometryBase = 10000;   // lathe G10 P10000+n writes geometry offset n ([FANUC] T series)

// Writes the block's axis words into `reg`: absolute letters replace, incremental letters (U W H
// in the G10 block, or every letter under G91) add.
template <class Value>
void write_axes(Position& reg, const BlockWords& words, const dialects::LexicalRules& rules, bool add_all,
                const Value& value_of) {
    for (const auto& [letter, w] : words.words) {
        const char incremental_of = rules.incremental_axis_of(letter);
        const auto axis = axis_of_letter(incremental_of ? incremental_of : letter);
        if (!axis || letter == 'P' || letter == 'L' || letter == 'R') continue;
        double& r = reg[static_cast<std::size_t>(*axis)];
        const double v = value_of(w, letter, static_cast<std::size_t>(*axis));
        r = incremental_of || add_all ? r + v : v;
    }
}

}  // namespace

void Executor::apply_data_input(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    const auto* p = words.get('P');
    const auto* l = words.get('L');
    // Registers are kept in mm (degrees on rotary axes): a G20 program writes inches.
    const auto value_of = [this](const BlockWords::Word& w, char letter, std::size_t axis) {
        return axis_value(state_, w, kAxisLetters[axis]) * state_.axis_scale(axis);
    };
    const dialects::LexicalRules& rules = dialect_.lexical;
    Event e = event_at(EventKind::coordinate_change, ctx);
    if (!p) {
        alarm(ctx, 10, "G10 without P: which register? (alarm 010)");
        return;
    }
    const int n = static_cast<int>(std::lround(p->value));
    if (l && std::lround(l->value) == 2) {
        if (n < 0 || n > 6) {
            alarm(ctx, 10, fmt::format("G10 L2 P{}: P must be 0 (external) to 6 (G59)", n));
            return;
        }
        change_offsets([&] {
            Position& reg = n == 0 ? state_.external_offset : state_.work_offsets[static_cast<std::size_t>(n - 1)];
            write_axes(reg, words, rules, state_.flags.incremental, value_of);
        });
        e.text = n == 0 ? "external work offset" : fmt::format("work offset G{}", 53 + n);
    } else if (l && std::lround(l->value) == 20) {
        // G10 L20 Pn: the additional work offset of G54.1 Pn ([FANUC]); G91 adds.
        const auto number = additional_number(ctx, p ? std::optional<double>(p->value) : std::nullopt);
        if (!number) return;
        change_offsets([&] { write_axes(memory_.additional_offsets[*number], words, rules, state_.flags.incremental, value_of); });
        e.text = fmt::format("work offset G54.1 P{}", *number);
    } else if (l || dialect_.machine != dialects::MachineKind::lathe) {
        const int kind = l ? static_cast<int>(std::lround(l->value)) : 0;   // 0 = memory A
        const auto* r = words.get('R');
        if (!r) return;   // nothing to write
        if (n < 1 || n > setup_.tool_offset_count) {
            // Checked where it is written: #11299 would be alarm 115 later on a 64-offset machine.
            alarm(ctx, alarms::offset_number,
                  fmt::format("G10 P{}: no tool offset {} on this machine (1..{}, tool_offset_count; alarm 030)", n, n,
                              setup_.tool_offset_count));
            return;
        }
        ToolOffset& t = memory_.tools[n];
        const double v = axis_value(state_, *r, 'R') * state_.unit_scale();
        auto set = [&](double& reg) { reg = state_.flags.incremental ? reg + v : v; };
        if (kind == 0 || kind == 1 || kind == 10) set(t.length);
        if (kind == 0 || kind == 12) set(t.radius);
        if (kind == 11) set(t.length_wear);
        if (kind == 13) set(t.radius_wear);
        e.text = fmt::format("tool offset {}", n);
    } else if (n == 0) {
        change_offsets([&] { write_axes(state_.work_shift, words, rules, false, value_of); });
        e.text = "work shift";
    } else {
        const bool geometry = n > kGeometryBase;
        const int number = geometry ? n - kGeometryBase : n;
        if (number < 1 || number > setup_.tool_offset_count) {
            alarm(ctx, 10, fmt::format("G10 P{}: no tool offset {} (1..{})", n, number, setup_.tool_offset_count));
            return;
        }
        // The active offset changes the machine position, as a T word does (no change_offsets).
        ToolOffset& t = memory_.tools[number];
        write_axes(geometry ? t.geometry : t.wear, words, rules, false, value_of);
        if (const auto* r = words.get('R')) (geometry ? t.nose_radius : t.nose_radius_wear) = axis_value(state_, *r, 'R') * state_.unit_scale();
        if (const auto* q = words.get('Q')) t.tip = static_cast<int>(std::lround(q->value));
        e.text = fmt::format("tool offset {} {}", number, geometry ? "geometry" : "wear");
    }
    e.end = state_.position;
    emit(e);
}

}  // namespace kerf::interpreter
