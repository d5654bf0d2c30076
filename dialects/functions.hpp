// Function ids the code refers to by name (the full vocabulary is in docs/functions.md).
// Code looks codes up by what they do, never by number, so that G32 (A) and G33 (B/C) are one thing.
#pragma once

#include <string_view>

namespace kerf::dialects::functions {

inline constexpr std::string_view rapid = "rapid";
inline constexpr std::string_view linear = "linear";
inline constexpr std::string_view dwell = "dwell";
inline constexpr std::string_view macro_call = "macro-call";
inline constexpr std::string_view modal_macro_call = "modal-macro-call";
inline constexpr std::string_view subprogram_call = "subprogram-call";
inline constexpr std::string_view subprogram_return = "subprogram-return";
inline constexpr std::string_view circular_cw = "circular-cw";
inline constexpr std::string_view circular_ccw = "circular-ccw";
inline constexpr std::string_view thread_cutting = "thread-cutting";
inline constexpr std::string_view absolute_programming = "absolute-programming";
inline constexpr std::string_view incremental_programming = "incremental-programming";
inline constexpr std::string_view feed_per_minute = "feed-per-minute";
inline constexpr std::string_view feed_per_revolution = "feed-per-revolution";
inline constexpr std::string_view css_on = "constant-surface-speed";
inline constexpr std::string_view css_off = "constant-surface-speed-cancel";
inline constexpr std::string_view coordinate_system_setting = "coordinate-system-setting";
inline constexpr std::string_view cancel_coordinate_setting = "cancel-coordinate-setting";
inline constexpr std::string_view machine_coordinate_select = "machine-coordinate-select";
inline constexpr std::string_view machine_coordinate_select_g0_g1 = "machine-coordinate-select-g0-g1";
inline constexpr std::string_view programmable_data_input = "programmable-data-input";
inline constexpr std::string_view reference_return = "reference-return";
inline constexpr std::string_view local_system_shift = "local-system-shift";
inline constexpr std::string_view local_system_current_point = "local-system-current-point";
inline constexpr std::string_view local_system_cancel = "local-system-cancel";
inline constexpr std::string_view plane_xy = "plane-xy";
inline constexpr std::string_view plane_zx = "plane-zx";
inline constexpr std::string_view plane_yz = "plane-yz";
inline constexpr std::string_view inch_input = "inch-input";
inline constexpr std::string_view metric_input = "metric-input";
inline constexpr std::string_view spindle_cw = "spindle-cw";
inline constexpr std::string_view spindle_ccw = "spindle-ccw";
inline constexpr std::string_view spindle_stop = "spindle-stop";
inline constexpr std::string_view coolant_on = "coolant-on";
inline constexpr std::string_view coolant_off = "coolant-off";
inline constexpr std::string_view program_stop = "program-stop";
inline constexpr std::string_view optional_stop = "optional-stop";
inline constexpr std::string_view program_end = "program-end";
inline constexpr std::string_view program_end_rewind = "program-end-rewind";
inline constexpr std::string_view tool_change = "tool-change";
inline constexpr std::string_view reference_return_nth = "reference-return-nth";
inline constexpr std::string_view return_from_reference = "return-from-reference";
inline constexpr std::string_view coordinate_rotation = "coordinate-rotation";
inline constexpr std::string_view coordinate_rotation_cw = "coordinate-rotation-cw";
inline constexpr std::string_view coordinate_rotation_cancel = "coordinate-rotation-cancel";
inline constexpr std::string_view modal_macro_call_cancel = "modal-macro-call-cancel";
inline constexpr std::string_view stroke_check_on = "stroke-check-on";
inline constexpr std::string_view stroke_check_off = "stroke-check-off";
inline constexpr std::string_view polar_interpolation_on = "polar-interpolation-on";     // G12.1/G112 (cycles.md §18)
inline constexpr std::string_view polar_interpolation_off = "polar-interpolation-off";   // G13.1/G113
inline constexpr std::string_view cylindrical_interpolation = "cylindrical-interpolation";   // G07.1/G107 (cycles.md §19)
// [FANUC] programmable transforms of mills (interpreter/executor_transforms.cpp).
inline constexpr std::string_view polar_coordinate_command = "polar-coordinate-command";                 // G16
inline constexpr std::string_view polar_coordinate_command_cancel = "polar-coordinate-command-cancel";   // G15
inline constexpr std::string_view scaling = "scaling";                                                   // G51
inline constexpr std::string_view scaling_cancel = "scaling-cancel";                                     // G50
inline constexpr std::string_view mirror = "mirror";                                                     // G51.1
inline constexpr std::string_view mirror_cancel = "mirror-cancel";                                       // G50.1
// "work-coordinate-1" ... "work-coordinate-6" are G54 ... G59.
inline constexpr std::string_view work_coordinate_prefix = "work-coordinate-";

// Compensation (reference/semantics.md §5–§7; interpreter/executor_compensation.cpp).
inline constexpr std::string_view radius_comp_cancel = "radius-comp-cancel";
inline constexpr std::string_view radius_comp_left = "radius-comp-left";
inline constexpr std::string_view radius_comp_right = "radius-comp-right";
inline constexpr std::string_view tool_length_comp_plus = "tool-length-comp-plus";
inline constexpr std::string_view tool_length_comp_minus = "tool-length-comp-minus";
inline constexpr std::string_view tool_length_comp_cancel = "tool-length-comp-cancel";

// Canned cycles (reference/cycles.md; interpreter/cycles/ expands them).
inline constexpr std::string_view finishing_cycle = "finishing-cycle";
inline constexpr std::string_view rough_turning_cycle = "rough-turning-cycle";
inline constexpr std::string_view rough_facing_cycle = "rough-facing-cycle";
inline constexpr std::string_view pattern_repeating_cycle = "pattern-repeating-cycle";
inline constexpr std::string_view face_peck_drilling_cycle = "face-peck-drilling-cycle";
inline constexpr std::string_view grooving_cycle = "grooving-cycle";
inline constexpr std::string_view multiple_threading_cycle = "multiple-threading-cycle";
inline constexpr std::string_view thread_cutting_cycle = "thread-cutting-cycle";
inline constexpr std::string_view variable_lead_thread_cutting = "variable-lead-thread-cutting";
inline constexpr std::string_view turning_cycle = "turning-cycle";
inline constexpr std::string_view facing_cycle = "facing-cycle";
inline constexpr std::string_view canned_cycle_cancel = "canned-cycle-cancel";
inline constexpr std::string_view return_initial_level = "return-initial-level";
inline constexpr std::string_view return_r_level = "return-r-level";
inline constexpr std::string_view drilling_cycle = "drilling-cycle";
inline constexpr std::string_view drilling_dwell_cycle = "drilling-dwell-cycle";
inline constexpr std::string_view peck_drilling_cycle = "peck-drilling-cycle";
inline constexpr std::string_view high_speed_peck_drilling_cycle = "high-speed-peck-drilling-cycle";
inline constexpr std::string_view tapping_cycle = "tapping-cycle";
inline constexpr std::string_view left_hand_tapping_cycle = "left-hand-tapping-cycle";
inline constexpr std::string_view boring_cycle = "boring-cycle";
inline constexpr std::string_view boring_dwell_cycle = "boring-dwell-cycle";
inline constexpr std::string_view boring_spindle_stop_cycle = "boring-spindle-stop-cycle";
inline constexpr std::string_view boring_manual_retract_cycle = "boring-manual-retract-cycle";
inline constexpr std::string_view back_boring_cycle = "back-boring-cycle";
// SPINNER cycles (cycles.md §12–§17, interpreter/cycles/spinner.cpp).
inline constexpr std::string_view workpiece_transfer_cycle = "workpiece-transfer-cycle";
inline constexpr std::string_view tailstock_clamping_cycle_1 = "tailstock-clamping-cycle-1";
inline constexpr std::string_view tailstock_clamping_cycle_2 = "tailstock-clamping-cycle-2";
inline constexpr std::string_view live_tool_rigid_tapping = "live-tool-rigid-tapping";
inline constexpr std::string_view live_tool_rigid_tapping_cancel = "live-tool-rigid-tapping-cancel";
inline constexpr std::string_view spindle_rigid_tapping_cycle = "spindle-rigid-tapping-cycle";
inline constexpr std::string_view tailstock_coupling_carry = "tailstock-coupling-carry";
inline constexpr std::string_view tailstock_coupling_position = "tailstock-coupling-position";
inline constexpr std::string_view parts_catcher_cycle = "parts-catcher-cycle";
inline constexpr std::string_view fine_boring_cycle = "fine-boring-cycle";
inline constexpr std::string_view face_drilling_cycle = "face-drilling-cycle";
inline constexpr std::string_view face_tapping_cycle = "face-tapping-cycle";
inline constexpr std::string_view face_boring_cycle = "face-boring-cycle";
inline constexpr std::string_view side_drilling_cycle = "side-drilling-cycle";
inline constexpr std::string_view side_tapping_cycle = "side-tapping-cycle";
inline constexpr std::string_view side_boring_cycle = "side-boring-cycle";

// seed 004 (iso-legacy-mill) specials (semantics.md §9.4–§9.6).
inline constexpr std::string_view corner_slowdown = "corner-slowdown";
inline constexpr std::string_view corner_slowdown_cancel = "corner-slowdown-cancel";
inline constexpr std::string_view axial_offset_plus = "axial-offset-direction-plus";
inline constexpr std::string_view axial_offset_minus = "axial-offset-direction-minus";
inline constexpr std::string_view arc_approach = "arc-approach";
inline constexpr std::string_view arc_exit = "arc-exit";

}  // namespace kerf::dialects::functions
