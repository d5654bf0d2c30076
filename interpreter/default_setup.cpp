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
        s.carries_tool[i] = axis.carries_tool;
        s.soft_limits[i] = {axis.min, axis.max};
    }
}


cycles::Settings cycle_settings(const machine::Machine& m) {
    const machine::CycleParameters& c = m.cycle_parameters;
    const machine::Switches& sw = m.switches;
    cycles::Settings s;
    s.initial = {c.g71_depth, c.g71_retract, c.g72_depth, c.g72_retract, c.g73_relief_x, c.g73_relief_z,
                 c.g73_divisions, c.g74_retract, c.g75_retract, c.g76_finishing_passes, c.g76_chamfer, c.g76_angle,
                 c.g76_min_depth, c.g76_allowance};
    s.allowance_u_radius = sw.finish_allowance_u == machine::AllowanceU::radius;
    // cycles.md §0: P/Q count the input increment, or a fixed micron / tenth of a micron.
    s.pq_unit_mm = sw.cycle_pq_units == machine::CyclePQUnits::micron         ? 0.001
                   : sw.cycle_pq_units == machine::CyclePQUnits::tenth_micron ? 0.0001
                                                                             : m.increment_mm();
    s.relief = sw.rough_relief == machine::Relief::rapid ? cycles::Relief::rapid : cycles::Relief::feed;
    s.rough_return = sw.rough_return == machine::RoughReturn::x_then_z   ? cycles::Return::x_then_z
                     : sw.rough_return == machine::RoughReturn::z_then_x ? cycles::Return::z_then_x
                                                                          : cycles::Return::simultaneous;
    s.infeed = sw.g76_infeed == machine::G76Infeed::radial           ? cycles::Infeed::radial
               : sw.g76_infeed == machine::G76Infeed::opposite_flank ? cycles::Infeed::opposite_flank
                                                                     : cycles::Infeed::flank;
    s.thread_chamfer_leads = sw.thread_chamfer;
    s.peck_clearance = sw.peck_clearance;
    s.high_speed_retract = sw.high_speed_retract;
    s.adv400_k_first_peck_only = sw.adv400_g83_k == machine::Adv400G83K::initial_depth;
    s.tapping_reverses = sw.adv400_g84 == machine::Adv400G84::tapping;
    s.repeat_l = sw.drill_repeat_l == machine::DrillRepeatL::fanuc;
    s.spinner.g38_stop_half_tolerance = sw.g38_stop == machine::G38Stop::half_tolerance;
    s.spinner.clamp_contact_target = sw.clamp_contact == machine::ClampContact::target;
    s.spinner.g238_a_after_clamp = sw.g238_a_timing == machine::G238ATiming::after_clamp;
    s.spinner.g384_radial_h_diameter = sw.g384_radial_h == machine::G384RadialH::diameter;
    s.spinner.g384_bottom_dwell_s = sw.g384_bottom_dwell;
    s.spinner.coupling_z = m.tailstock.coupling_z;
    s.spinner.coupling_z_second = m.tailstock.coupling_z_second;
    s.spinner.home_b = m.tailstock.home_b;
    return s;
}
// The power-on switches as the functions of the codes active at power-on (Setup::power_on).
std::vector<dialects::FunctionId> power_on_functions(const machine::Switches& sw) {
    namespace fn = dialects::functions;
    return {sw.power_on_units == machine::Units::inch ? fn::inch_input : fn::metric_input,
            sw.power_on_plane == machine::Plane::xy   ? fn::plane_xy
            : sw.power_on_plane == machine::Plane::zx ? fn::plane_zx
                                                      : fn::plane_yz,
            sw.power_on_distance == machine::Distance::incremental ? fn::incremental_programming : fn::absolute_programming,
            sw.power_on_return_level == machine::ReturnLevel::r_point ? fn::return_r_level : fn::return_initial_level};
}

}  // namespace

Setup make_setup(const machine::Machine& m) {
    Setup s;
    s.diameter_x = m.diameter_x;
    s.increment_mm = m.increment_mm();
    s.calculator_decimal = m.calculator_decimal;
    for (std::size_t i = 0; i < 6; ++i) s.work_offsets[i] = position_of(m.work_offsets[i]);
    s.additional_work_offset_count = m.additional_work_offset_count;
    for (const auto& [n, values] : m.additional_work_offsets) s.additional_work_offsets[n] = position_of(values);
    s.external_offset = position_of(m.external_offset);
    s.work_shift = position_of(m.work_shift);
    s.work_shift_sign = m.switches.work_shift_sign == machine::WorkShiftSign::add ? 1.0 : -1.0;
    for (std::size_t i = 0; i < 4; ++i) s.reference_points[i] = position_of(m.reference_points[i]);
    set_axes(s, m);
    s.max_rpm = m.max_spindle_rpm;
    s.max_cutting_feed = m.max_cutting_feed.value_or(0.0);
    const machine::Switches& sw = m.switches;
    s.rapid_dogleg = sw.rapid == machine::RapidMode::dog_leg;
    s.dwell_p_in_seconds = sw.dwell_p_unit == machine::DwellUnit::s;
    s.g52_current_point = sw.g52 != machine::G52Semantics::vector_shift;
    s.g52_zeros_cancel = sw.g52 != machine::G52Semantics::current_point_g152;
    s.g54_cancels_g52 = sw.g52 == machine::G52Semantics::current_point_g152;
    s.g28_point_in_machine = sw.g28_intermediate == machine::PointFrame::machine;
    s.g30_default_p = sw.g30_default_p;
    s.g68_positive_cw = sw.g68_positive == machine::RotationSign::cw;
    s.scaling_unit = sw.scaling_unit == machine::ScalingUnit::thousandth ? 0.001 : 0.00001;
    s.power_on = power_on_functions(sw);
    s.arc_tolerance = sw.arc_tolerance;
    s.transform_tolerance = sw.transform_tolerance;
    s.arc_negative_r = sw.arc_negative_r == machine::ArcLargeR::negative_r;
    s.arc_enlarge_small_r = sw.arc_radius_mismatch == machine::ArcMismatch::enlarge;
    s.atan_minus_180 = sw.atan_range == machine::AtanRange::minus_180_to_180;
    s.dwell_f_seconds = sw.dwell_f_word == machine::DwellF::seconds;
    s.radius_comp.start = sw.cutter_comp_startup == machine::CompStartup::type_a ? compensation::StartType::a
                                                                                  : compensation::StartType::b;
    s.radius_comp.corners = sw.cutter_comp_corners == machine::CompCorners::arc ? compensation::CornerStyle::arc
                                                                                : compensation::CornerStyle::intersection;
    s.radius_comp.end_tolerance = sw.arc_tolerance;
    s.comp_shift_without_motion = sw.comp_shift_without_motion;
    s.g41_g42_swapped = sw.g41_g42_swapped;
    s.corner_slowdown_step = sw.corner_slowdown == machine::CornerSlowdown::step;
    s.iso_g43_approach = sw.iso_g43 == machine::IsoG43::approach_shorten;
    s.length_offset_at_once = sw.length_offset_motion == machine::LengthOffsetMotion::at_once;
    s.tool_offset_count = m.tool_offset_count;
    s.m_codes = m.m_codes;
    for (const auto& [number, tool] : m.tools) s.tools[number] = tool_offset_of(tool);
    s.step_limit = static_cast<std::uint64_t>(sw.max_blocks);
    s.move_limit = static_cast<std::uint64_t>(sw.max_moves);
    s.max_call_depth = sw.subprogram_nesting;
    s.max_macro_depth = sw.macro_nesting;
    s.cycles = cycle_settings(m);
    return s;
}

Setup default_setup(const dialects::Dialect& dialect) {
    return make_setup(machine::default_machine_for(dialect));
}

}  // namespace kerf::interpreter
