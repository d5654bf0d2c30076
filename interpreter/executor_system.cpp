// System variables (#1000 and up) of FANUC Custom Macro B, read from and written to the
// interpreter's state ([FANUC] 0i/16i/18i/30i operator manuals, "System variables"; the ranges
// are also listed in interpreter/macro/variables.hpp). The tables below are data: an entry names a
// range and what it maps to, so a control with other numbers needs a new table, not new code.
//
//   #1000-#1035 / #1100-#1135  interface signals: read 0, writes accepted (no PMC in a dry run)
//   #2001.. / #10001..          tool offsets (lathe: X Z R T wear and geometry; mill: H D)
//   #3000 = n (MSG)             macro alarm 3000 + n with the block's comment as message
//   #3001 / #3002               clock in ms / hours: the dry-run time, writable (preset)
//   #3003 #3004 #3005 #3901 #3902  stored and read back
//   #3006 = n (MSG)             stop with message (a stop event)
//   #3011 / #3012               date / time: 0 (a dry run has no date; deterministic traces)
//   #4001-#4030 (#4201..)       modal G code of group 1..30: its number (G01 → 1, G96 → 96)
//   #4102-#4130 (#4302..)       last B D E F H M N O S T
//   #5001.. #5021.. #5041..     end point, machine and work position per axis (axis order of the machine)
//   #5061.. #5081.. #5101..     skip position, tool offset, servo deviation: 0 / offset / 0
//   #5201.. #5221.. ... #5321.. external offset, G54..G59 per axis: read and write
//   #7001.. (P1–P48), #14001.. (P1–P300)  G54.1 Pn additional work offsets per axis: read and write
// Lengths are read and written in the program's unit (inches under G20; the registers keep mm),
// angles in degrees.
#include <fmt/format.h>

#include <cmath>
#include <span>

#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace {

enum class OffsetField { x_wear, z_wear, r_wear, tip, x_geometry, z_geometry, r_geometry, h_wear, h_geometry, d_wear, d_geometry };

struct OffsetRange {
    int first;    // variable of offset number 1
    int count;    // offsets in the range
    OffsetField field;
};

// [FANUC] T series, tool compensation memory (64 offsets or fewer, and the #10000 ranges).
constexpr OffsetRange kLatheOffsets[] = {
    {2001, 64, OffsetField::x_wear},      {2101, 64, OffsetField::z_wear},     {2201, 64, OffsetField::r_wear},
    {2301, 64, OffsetField::tip},         {2701, 64, OffsetField::x_geometry}, {2801, 64, OffsetField::z_geometry},
    {2901, 64, OffsetField::r_geometry},  {10001, 999, OffsetField::x_wear},   {11001, 999, OffsetField::z_wear},
    {12001, 999, OffsetField::r_wear},    {13001, 999, OffsetField::tip},      {15001, 999, OffsetField::x_geometry},
    {16001, 999, OffsetField::z_geometry}, {17001, 999, OffsetField::r_geometry},
};
// [FANUC] M series, tool compensation memory C (200 offsets or fewer, and the #10000 ranges).
constexpr OffsetRange kMillOffsets[] = {
    {2001, 200, OffsetField::h_wear},    {2201, 200, OffsetField::h_geometry}, {2401, 200, OffsetField::d_wear},
    {2601, 200, OffsetField::d_geometry}, {10001, 999, OffsetField::h_wear},   {11001, 999, OffsetField::h_geometry},
    {12001, 999, OffsetField::d_wear},   {13001, 999, OffsetField::d_geometry},
};

// The register a variable range maps to; nullptr for the tip number, an int (read and written apart).
template <class Offset>   // ToolOffset or const ToolOffset
auto field_of(Offset& t, OffsetField f) -> decltype(&t.length) {
    switch (f) {
        case OffsetField::x_wear: return &t.wear[0];
        case OffsetField::z_wear: return &t.wear[2];
        case OffsetField::r_wear: return &t.nose_radius_wear;
        case OffsetField::x_geometry: return &t.geometry[0];
        case OffsetField::z_geometry: return &t.geometry[2];
        case OffsetField::r_geometry: return &t.nose_radius;
        case OffsetField::h_wear: return &t.length_wear;
        case OffsetField::h_geometry: return &t.length;
        case OffsetField::d_wear: return &t.radius_wear;
        case OffsetField::d_geometry: return &t.radius;
        case OffsetField::tip: break;
    }
    return nullptr;
}

// Variable ranges per axis: #5001 + i, the i-th axis of the machine (0-based).
constexpr int kEndPoint = 5001, kMachinePosition = 5021, kWorkPosition = 5041, kSkipPosition = 5061,
              kToolOffsetValue = 5081, kServoDeviation = 5101, kWorkOffsets = 5201, kWorkOffsetsEnd = 5340;
constexpr int kAxesPerRange = 20;
// G54.1 P1..P48 (#7001 + 20 (n − 1) + axis) and P1..P300 (#14001 + ...): the additional work offsets.
struct AdditionalRange {
    int first, count;
};
constexpr AdditionalRange kAdditionalOffsets[] = {{7001, 48}, {14001, 300}};

}  // namespace

ExecutorSystemVariables::ExecutorSystemVariables(Executor& executor, const BlockContext& block)
    : executor_(executor), state_(executor.state_), at_(executor.state_.position), writer_(&executor), block_(&block) {}

std::optional<macro::Value> ExecutorSystemVariables::read(int number) { return executor_.read_system(state_, at_, number); }
macro::WriteResult ExecutorSystemVariables::write(int number, macro::Value value) {
    // Only a block's assignments write (executor_macro.cpp); a reader's hook refuses (a look-ahead,
    // RunOptions::after_block).
    if (!writer_) return macro::WriteResult::read_only;
    return writer_->write_system(*block_, number, value);
}
bool ExecutorSystemVariables::read_only(int number) const { return executor_.system_read_only(number); }
bool ExecutorSystemVariables::modelled(int number) const { return executor_.system_modelled(number); }

// Below #1000 (locals, commons) and in the tool offset tables kerf knows what exists (the offset
// count is the machine's); elsewhere in the system variables a number read_system does not answer
// may exist on the control: kerf's tables list the FANUC manual's variables, not all of them
// (O8200 reads #3101 as π).
bool Executor::system_modelled(int number) const {
    // The ranges read_system answers from the manual's tables: a number in them it does not answer
    // does not exist (a fourth axis's #5004 on three axes: alarm 115).
    constexpr std::pair<int, int> kTables[] = {{1000, 1035}, {1100, 1135}, {3000, 3012}, {3901, 3902}, {4001, 4330}};
    if (number < 1000 || dialect_.variable_range(number)) return true;
    if (number >= kEndPoint && number <= kWorkOffsetsEnd) return true;
    for (const auto& [first, last] : kTables)
        if (number >= first && number <= last) return true;
    const bool lathe = dialect_.machine == dialects::MachineKind::lathe;
    for (const OffsetRange& r : lathe ? std::span<const OffsetRange>(kLatheOffsets) : std::span<const OffsetRange>(kMillOffsets))
        if (number >= r.first && number < r.first + r.count) return true;
    return false;
}

bool Executor::system_read_only(int number) const {
    if (const dialects::VariableRange* range = dialect_.variable_range(number)) return range->read_only;
    // Modal information and positions are read-only (#4001-#4330, #5001-#5200); alarm 116.
    return (number >= 4001 && number <= 4330) || (number >= kEndPoint && number < kWorkOffsets) ||
           number == 3007 || number == 3011 || number == 3012;
}

std::optional<macro::Value> Executor::read_system(const MachineState& s, const Position& at, int number) const {
    using macro::Value;
    // The dialect's own ranges first (Haas NGC #10000..: executor_dialect_variables.cpp).
    if (const dialects::VariableRange* range = dialect_.variable_range(number)) return read_dialect_variable(s, at, *range, number);
    const bool lathe = dialect_.machine == dialects::MachineKind::lathe;
    // Tool offsets.
    for (const OffsetRange& r : lathe ? std::span<const OffsetRange>(kLatheOffsets) : std::span<const OffsetRange>(kMillOffsets)) {
        if (number < r.first || number >= r.first + r.count) continue;
        const int offset = number - r.first + 1;
        if (offset > setup_.tool_offset_count) return std::nullopt;
        const auto it = memory_.tools.find(offset);
        if (it == memory_.tools.end()) return Value::of(0);
        const ToolOffset& t = it->second;
        // Registers are mm; a macro reads them in the program's unit (G20: inches).
        return Value::of(r.field == OffsetField::tip ? t.tip : *field_of(t, r.field) / s.unit_scale());
    }
    if ((number >= 1000 && number <= 1035) || (number >= 1100 && number <= 1135)) return Value::of(0);
    if (number == 3000 || number == 3006) return Value::vacant_value();
    if (number == 3001) return Value::of(result_.total_time_s * 1000.0 - memory_.clock_ms_offset);
    if (number == 3002) return Value::of(result_.total_time_s / 3600.0 - memory_.clock_h_offset);
    if (number == 3011 || number == 3012 || number == 3007) return Value::of(0);
    if (const auto it = memory_.stored_system.find(number); it != memory_.stored_system.end()) return Value::of(it->second);
    if (number == 3003 || number == 3004 || number == 3005 || number == 3901 || number == 3902) return Value::of(0);
    // #4001-#4030 (and #4201-#4230, the block being executed: the same in a dry run).
    const int modal = number >= 4201 && number <= 4330 ? number - 200 : number;
    if (modal >= 4001 && modal <= 4030) {
        const auto group = dialect_.group_index(fmt::format("{:02}", modal - 4000));
        const dialects::CodeInfo* code = group ? s.modal[*group] : nullptr;
        if (!code) return Value::vacant_value();
        const std::string& spelling = code->spelling;
        return Value::of(std::strtod(spelling.c_str() + 1, nullptr));
    }
    if (modal >= 4102 && modal <= 4130) {
        // The numbers follow argument specification I: #4102 B, #4107 D, #4109 F, #4113 M, #4119 S ...
        constexpr std::pair<int, char> kLetters[] = {{2, 'B'}, {7, 'D'}, {8, 'E'}, {9, 'F'}, {11, 'H'}, {13, 'M'},
                                                     {14, 'N'}, {15, 'O'}, {19, 'S'}, {20, 'T'}};
        char letter = 0;
        for (const auto& [n, l] : kLetters)
            if (modal - 4100 == n) letter = l;
        if (!letter) return Value::vacant_value();
        if (letter == 'O') return Value::of(static_cast<double>(program_of(frames_.back()).number.value_or(0)));
        if (letter == 'T' && dialect_.machine == dialects::MachineKind::lathe) return Value::of(s.tool * 100 + s.tool_offset);
        const auto& last = s.last_words[static_cast<std::size_t>(letter - 'A')];
        return last ? Value::of(*last) : Value::vacant_value();
    }
    // Positions: per axis in the machine's order.
    const auto axis_at = [&](int base) -> std::optional<std::size_t> {
        const int i = number - base;
        if (i < 0 || i >= kAxesPerRange || static_cast<std::size_t>(i) >= setup_.axis_order.size()) return std::nullopt;
        const auto a = axis_of_letter(setup_.axis_order[static_cast<std::size_t>(i)]);
        return a ? std::optional<std::size_t>(static_cast<std::size_t>(*a)) : std::nullopt;
    };
    if (const auto a = axis_at(kEndPoint)) return Value::of(at[*a]);
    if (const auto a = axis_at(kWorkPosition)) return Value::of(at[*a]);
    if (const auto a = axis_at(kMachinePosition)) return Value::of(at[*a] + machine_offset(s)[*a] / s.axis_scale(*a));
    if (const auto a = axis_at(kSkipPosition)) return Value::of(0);
    if (const auto a = axis_at(kToolOffsetValue)) return Value::of(tool_offset(s)[*a] / s.axis_scale(*a));
    if (const auto a = axis_at(kServoDeviation)) return Value::of(0);
    if (number >= kWorkOffsets && number <= kWorkOffsetsEnd) {
        const int set = (number - kWorkOffsets) / kAxesPerRange;   // 0 = external, 1..6 = G54..G59
        if (const auto a = axis_at(kWorkOffsets + set * kAxesPerRange))
            return Value::of((set == 0 ? s.external_offset[*a] : s.work_offsets[static_cast<std::size_t>(set - 1)][*a]) /
                             s.axis_scale(*a));
    }
    if (const auto slot = additional_variable(number)) {
        const auto it = memory_.additional_offsets.find(slot->first);
        return Value::of(it == memory_.additional_offsets.end() ? 0.0 : it->second[slot->second] / s.axis_scale(slot->second));
    }
    return std::nullopt;
}

// #7001.. / #14001..: the additional work offset n and the axis a variable names; nullopt outside
// the ranges, past the machine's count (additional_work_offset_count) or its axes.
std::optional<std::pair<int, std::size_t>> Executor::additional_variable(int number) const {
    for (const AdditionalRange& r : kAdditionalOffsets) {
        if (number < r.first || number >= r.first + r.count * kAxesPerRange) continue;
        const int n = (number - r.first) / kAxesPerRange + 1;
        const int i = (number - r.first) % kAxesPerRange;
        if (n > setup_.additional_work_offset_count || static_cast<std::size_t>(i) >= setup_.axis_order.size()) return std::nullopt;
        const auto a = axis_of_letter(setup_.axis_order[static_cast<std::size_t>(i)]);
        if (!a) return std::nullopt;
        return std::pair<int, std::size_t>{n, static_cast<std::size_t>(*a)};
    }
    return std::nullopt;
}

macro::WriteResult Executor::write_system(const BlockContext& ctx, int number, macro::Value value) {
    using macro::WriteResult;
    if (const dialects::VariableRange* range = dialect_.variable_range(number)) {
        ExecutorSystemVariables system(*this, ctx);
        return write_dialect_variable(*range, number, value, system);
    }
    const double v = value.or_zero();
    const bool lathe = dialect_.machine == dialects::MachineKind::lathe;
    if (number == 3000) {
        // Macro alarm: number 3000 + n, the comment of the block is the message ([FANUC]).
        alarm(ctx, 3000 + static_cast<int>(std::lround(v)), block_comment(ctx.view));
        return WriteResult::ok;
    }
    if (number == 3006) {
        Event e = event_at(EventKind::stop, ctx);
        e.code = 3006;
        e.text = block_comment(ctx.view);
        emit(e);
        if (options_.stop_at_m00) stopped_ = true;
        return WriteResult::ok;
    }
    if (number == 3001) { memory_.clock_ms_offset = result_.total_time_s * 1000.0 - v; return WriteResult::ok; }
    if (number == 3002) { memory_.clock_h_offset = result_.total_time_s / 3600.0 - v; return WriteResult::ok; }
    if (number == 3003 || number == 3004 || number == 3005 || number == 3901 || number == 3902) {
        memory_.stored_system[number] = v;
        return WriteResult::ok;
    }
    if (number >= 1100 && number <= 1135) return WriteResult::ok;
    for (const OffsetRange& r : lathe ? std::span<const OffsetRange>(kLatheOffsets) : std::span<const OffsetRange>(kMillOffsets)) {
        if (number < r.first || number >= r.first + r.count) continue;
        const int offset = number - r.first + 1;
        if (offset > setup_.tool_offset_count) return WriteResult::undefined;
        ToolOffset& t = memory_.tools[offset];
        if (r.field == OffsetField::tip) t.tip = static_cast<int>(std::lround(v));
        else *field_of(t, r.field) = v * state_.unit_scale();
        return WriteResult::ok;
    }
    if (number >= kWorkOffsets && number <= kWorkOffsetsEnd) {
        const int set = (number - kWorkOffsets) / kAxesPerRange;
        const int i = (number - kWorkOffsets) % kAxesPerRange;
        if (static_cast<std::size_t>(i) >= setup_.axis_order.size()) return WriteResult::undefined;
        const auto a = axis_of_letter(setup_.axis_order[static_cast<std::size_t>(i)]);
        if (!a) return WriteResult::undefined;
        // The tool stays where it is; its work coordinates follow the new offset.
        change_offsets([&] {
            Position& reg = set == 0 ? state_.external_offset : state_.work_offsets[static_cast<std::size_t>(set - 1)];
            reg[static_cast<std::size_t>(*a)] = v * state_.axis_scale(static_cast<std::size_t>(*a));
        });
        return WriteResult::ok;
    }
    if (const auto at = additional_variable(number)) {
        change_offsets([&] { memory_.additional_offsets[at->first][at->second] = v * state_.axis_scale(at->second); });
        return WriteResult::ok;
    }
    return system_read_only(number) ? WriteResult::read_only : WriteResult::undefined;
}

}  // namespace kerf::interpreter
