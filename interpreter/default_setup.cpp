#include "interpreter/default_setup.hpp"

namespace kerf::interpreter {

namespace {
Position position_of(const machine::AxisValues& values) {
    Position p{};
    for (std::size_t a = 0; a < kAxisCount; ++a) p[a] = machine::axis_value(values, kAxisLetters[a]);
    return p;
}

ToolOffset tool_offset_of(const machine::ToolOffset& tool) {
    ToolOffset t;
    t.geometry = position_of(tool.geometry);
    t.wear = position_of(tool.wear);
    t.nose_radius = tool.nose_radius;
    t.nose_radius_wear = tool.nose_radius_wear;
    t.tip = tool.tip;
    t.length = tool.length;
    t.length_wear = tool.length_wear;
    t.radius = tool.radius;
    t.radius_wear = tool.radius_wear;
    return t;
}

void set_axes(Setup& s, const machine::Machine& m) {
    s.axis_order.clear();
    for (const machine::Axis& axis : m.axes) {
        const auto a = axis_of_letter(axis.letter);
        if (!a) continue;   // U V W as separate axes: not modelled by the interpreter
        const std::size_t i = static_cast<std::size_t>(*a);
        s.axis_order += axis.letter;
        s.rapid_mm_min[i] = axis.rapid;
        s.accel_mm_s2[i] = axis.acceleration;
        s.rotary[i] = axis.rotary;
        s.soft_limits[i] = {axis.min, axis.max};
    }
}
}  // namespace

Setup make_setup(const machine::Machine& m) {
    Setup s;
    s.diameter_x = m.diameter_x;
    s.increment_mm = m.increment_mm();
    s.calculator_decimal = m.calculator_decimal;
    for (std::size_t i = 0; i < 6; ++i) s.work_offsets[i] = position_of(m.work_offsets[i]);
    s.external_offset = position_of(m.external_offset);
    s.work_shift = position_of(m.work_shift);
    for (std::size_t i = 0; i < 4; ++i) s.reference_points[i] = position_of(m.reference_points[i]);
    set_axes(s, m);
    s.max_rpm = m.max_spindle_rpm;
    const machine::Switches& sw = m.switches;
    s.rapid_dogleg = sw.rapid == machine::RapidMode::dog_leg;
    s.dwell_p_in_seconds = sw.dwell_p_unit == machine::DwellUnit::s;
    s.g52_current_point = sw.g52 != machine::G52Semantics::vector_shift;
    s.g52_zeros_cancel = sw.g52 != machine::G52Semantics::current_point_g152;
    s.g54_cancels_g52 = sw.g52 == machine::G52Semantics::current_point_g152;
    s.g28_point_in_machine = sw.g28_intermediate == machine::PointFrame::machine;
    s.g30_default_p = sw.g30_default_p;
    s.g68_positive_cw = sw.g68_positive == machine::RotationSign::cw;
    s.arc_tolerance = sw.arc_tolerance;
    s.arc_negative_r = sw.arc_negative_r == machine::ArcLargeR::negative_r;
    s.arc_enlarge_small_r = sw.arc_radius_mismatch == machine::ArcMismatch::enlarge;
    s.atan_minus_180 = sw.atan_range == machine::AtanRange::minus_180_to_180;
    s.dwell_f_seconds = sw.dwell_f_word == machine::DwellF::seconds;
    s.tool_offset_count = m.tool_offset_count;
    for (const auto& [number, tool] : m.tools) s.tools[number] = tool_offset_of(tool);
    s.step_limit = static_cast<std::uint64_t>(sw.max_blocks);
    s.max_call_depth = sw.subprogram_nesting;
    s.max_macro_depth = sw.macro_nesting;
    return s;
}

Setup default_setup(const dialects::Dialect& dialect) {
    return make_setup(machine::default_machine_for(dialect));
}

}  // namespace kerf::interpreter
