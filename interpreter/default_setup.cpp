#include "interpreter/default_setup.hpp"

namespace kerf::interpreter {

namespace {
Position position_of(const machine::AxisValues& values) {
    Position p{};
    for (std::size_t a = 0; a < kAxisCount; ++a) p[a] = machine::axis_value(values, kAxisLetters[a]);
    return p;
}
}  // namespace

Setup make_setup(const machine::Machine& m) {
    Setup s;
    s.diameter_x = m.diameter_x;
    s.increment_mm = m.increment_mm();
    s.calculator_decimal = m.calculator_decimal;
    for (std::size_t i = 0; i < 6; ++i) s.work_offsets[i] = position_of(m.work_offsets[i]);
    s.external_offset = position_of(m.external_offset);
    for (std::size_t i = 0; i < 4; ++i) s.reference_points[i] = position_of(m.reference_points[i]);
    for (std::size_t a = 0; a < kAxisCount; ++a)
        if (const machine::Axis* axis = m.axis(kAxisLetters[a])) s.rapid_mm_min[a] = axis->rapid;
    s.max_rpm = m.max_spindle_rpm;
    s.rapid_dogleg = m.switches.rapid == machine::RapidMode::dog_leg;
    s.dwell_p_in_seconds = m.switches.dwell_p_unit == machine::DwellUnit::s;
    s.g52_current_point = m.switches.g52 != machine::G52Semantics::vector_shift;
    for (const auto& [number, tool] : m.tools) {
        ToolOffset t;
        t.geometry = position_of(tool.geometry);
        t.wear = position_of(tool.wear);
        t.nose_radius = tool.nose_radius;
        t.tip = tool.tip;
        s.tools[number] = t;
    }
    s.step_limit = static_cast<std::uint64_t>(m.switches.max_blocks);
    s.max_call_depth = m.switches.subprogram_nesting;
    s.max_macro_depth = m.switches.macro_nesting;
    return s;
}

Setup default_setup(const dialects::Dialect& dialect) {
    return make_setup(machine::default_machine_for(dialect));
}

}  // namespace kerf::interpreter
