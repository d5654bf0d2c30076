// [dialect variables] The macro variables a dialect defines beyond FANUC Custom Macro B
// (`[[variables]]`, dialects/SCHEMA.md): the Haas NGC numbers #10000+n of the legacy #n, its own
// general-purpose ranges, the additional work offsets of G154 (#14001 + 20·(n−1)), the settings and
// parameters a macro reads (#20000 + n, #30000 + n), the tool in the spindle (#3026) and the spindle
// speed (#3027). The interpreter asks the dialect before its own system variables
// (executor_system.cpp), so a control with other numbers is a data file, not code.
#include <fmt/format.h>

#include <cmath>

#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace {

// The additional work offset and axis of a work-offset variable: #from is axis 0 of offset first_set.
struct OffsetSlot {
    int number;
    std::size_t axis_index;   // into the range's axis letters, else the machine's axis order
};
OffsetSlot offset_slot(const dialects::VariableRange& range, int number) {
    const std::int64_t i = number - range.from;
    return {range.first_set + static_cast<int>(i / range.stride), static_cast<std::size_t>(i % range.stride)};
}

// The axis of a slot: the range's own letters (Haas: X Y Z A B C whatever the machine has), else
// the machine's axis order (FANUC #5221..: the machine's axes).
std::optional<Axis> slot_axis(const dialects::VariableRange& range, const OffsetSlot& slot, const std::string& machine_order) {
    const std::string& letters = range.axes.empty() ? machine_order : range.axes;
    if (slot.axis_index >= letters.size()) return std::nullopt;
    return axis_of_letter(letters[slot.axis_index]);
}

}  // namespace

std::optional<macro::Value> Executor::read_dialect_variable(const MachineState& s, const Position& at,
                                                           const dialects::VariableRange& range, int number) const {
    using macro::Value;
    switch (range.kind) {
        case dialects::VariableKind::alias:
        {
            ExecutorSystemVariables system(*this, s, at);   // an alias of a system variable reads the same state
            return variables_.read(static_cast<int>(range.alias_of + (number - range.from)), system);
        }
        case dialects::VariableKind::common:
        case dialects::VariableKind::setting:
        case dialects::VariableKind::parameter: {
            // Settings and parameters are the machine's: a dry run knows none (vacant) unless the
            // program wrote them first.
            const auto it = memory_.dialect_variables.find(number);
            return it == memory_.dialect_variables.end() ? Value::vacant_value() : it->second;
        }
        case dialects::VariableKind::work_offsets: {
            const OffsetSlot slot = offset_slot(range, number);
            const auto axis = slot_axis(range, slot, setup_.axis_order);
            if (!axis) return Value::vacant_value();
            // Registers hold mm (degrees); the program reads them in its own unit (G20: inches).
            const auto a = static_cast<std::size_t>(*axis);
            const auto it = memory_.additional_offsets.find(slot.number);
            return Value::of(it == memory_.additional_offsets.end() ? 0.0 : it->second[a] / s.axis_scale(a));
        }
        case dialects::VariableKind::tool_in_spindle:
            return Value::of(static_cast<double>(s.tool));
        case dialects::VariableKind::spindle_rpm:
            return Value::of(s.spindle_on ? current_rpm(s, at[0]) : 0.0);
    }
    return std::nullopt;
}

macro::WriteResult Executor::write_dialect_variable(const dialects::VariableRange& range, int number, macro::Value value,
                                                    macro::SystemVariables& system) {
    using macro::WriteResult;
    if (range.read_only) return WriteResult::read_only;
    switch (range.kind) {
        case dialects::VariableKind::alias:
            return variables_.write(static_cast<int>(range.alias_of + (number - range.from)), value, system);
        case dialects::VariableKind::common:
        case dialects::VariableKind::setting:
        case dialects::VariableKind::parameter:
            memory_.dialect_variables[number] = value;
            return WriteResult::ok;
        case dialects::VariableKind::work_offsets: {
            const OffsetSlot slot = offset_slot(range, number);
            const auto axis = slot_axis(range, slot, setup_.axis_order);
            if (!axis) return WriteResult::undefined;
            // The tool stays where it is; its work coordinates follow the new offset.
            const auto a = static_cast<std::size_t>(*axis);
            change_offsets([&] { memory_.additional_offsets[slot.number][a] = value.or_zero() * state_.axis_scale(a); });
            return WriteResult::ok;
        }
        case dialects::VariableKind::tool_in_spindle:
        case dialects::VariableKind::spindle_rpm:
            return WriteResult::read_only;
    }
    return WriteResult::undefined;
}

}  // namespace kerf::interpreter
