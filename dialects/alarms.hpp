// Alarm numbers the dry run raises: the control's (FANUC's numbers, and SPINNER's 3011/3012 of
// mcodes.md §3.3) and kerf's own 9xxxx, outside every range the controls use, so that the analyzer
// and the formatter's trace comparison tell them apart. One name per number, used wherever an alarm
// is raised (motion/, interpreter/) or mapped to a rule (analyzer/rules/alarms.cpp);
// docs/diagnostics.md lists them and tests/test_ids.cpp keeps the three in agreement.
// Header only: the motion kernel raises 020 and depends on nothing.
#pragma once

#include <string_view>

namespace kerf::alarms {

// [FANUC] alarm numbers (FANUC 0i/30i operator's manual alarm list; the reference cites them where
// it relies on one).
inline constexpr int improper_command = 10;         // an unknown G code; G10 without a valid P / register (alarm 010)
inline constexpr int feed_zero = 11;                // a feed move with no feed rate commanded (PS011)
inline constexpr int arc_radius_mismatch = 20;      // arc end off its circle, R too small (semantics.md §3)
inline constexpr int offset_number = 30;            // an offset number the machine does not have (PS0030: G54.1 P, G10 L10–L13/L20 P)
inline constexpr int comp_in_arc = 34;              // compensation started or cancelled in G02/G03 (semantics.md §5)
inline constexpr int comp_interference = 41;        // over-cut in cutter / nose radius compensation (semantics.md §6)
inline constexpr int reference_point_number = 46;   // G30 P not 1–4
inline constexpr int drawing_no_move = 51;          // direct drawing: no move after a chamfer/corner (semantics.md §10.1)
inline constexpr int drawing_not_g01 = 52;          // direct drawing: the next block is not G01
inline constexpr int drawing_corner_lines = 55;     // direct drawing: the corner does not fit between its lines
inline constexpr int drawing_angle_only = 56;       // direct drawing: an angle-only block without its successor
inline constexpr int drawing_no_intersection = 57;  // direct drawing: parallel lines, end never reached
inline constexpr int profile_sequence = 60;         // G70–G73 P/Q: the N is not found (cycles.md §5)
inline constexpr int cycle_value = 62;              // a cycle's depth/step/height missing, zero or negative
inline constexpr int profile_not_monotonic = 64;    // G71/G72 profile not monotonic (cycles.md §2)
inline constexpr int profile_no_move = 65;          // G70–G73 profile without a move
inline constexpr int program_number_missing = 76;   // M98/G65/G66 without P (or Q)
inline constexpr int call_nesting = 77;             // subprogram or macro calls nested too deep
inline constexpr int program_not_found = 78;        // the called program or N label is not there
inline constexpr int macro_overflow = 111;          // macro result out of range (M0111)
inline constexpr int macro_division_by_zero = 112;  // M0112
inline constexpr int macro_format = 114;            // a malformed expression or condition (M0114)
inline constexpr int macro_variable_number = 115;   // variable number out of range or undefined (M0115)
inline constexpr int macro_write_protected = 116;   // write to a read-only variable (M0116)
inline constexpr int macro_bracket_nesting = 118;   // brackets nested deeper than 5 (M0118)
inline constexpr int macro_argument = 119;          // illegal function argument (M0119)
inline constexpr int loop_nesting = 124;            // WHILE/DO nesting, DO without END (dialects.md §3.7)
inline constexpr int loop_number = 126;             // DO m with m not 1–3
inline constexpr int goto_target = 128;             // GOTO n: no N n in the program
inline constexpr int scaling_magnification = 142;   // G51 magnification out of range
inline constexpr int polar_conditions = 145;        // G112/G113 while an offset is held (cycles.md §18)
inline constexpr int polar_improper_code = 146;     // a code not allowed in G112 mode
inline constexpr int cylinder_axis = 175;           // G07.1 on an axis that is not rotary (cycles.md §19)
inline constexpr int cylinder_improper_code = 176;  // a code not allowed in G07.1 mode
inline constexpr int lead_level = 313;              // G34 lead reaches zero (cycles.md §9)
inline constexpr int overtravel_plus = 500;         // stored stroke limit + (OT500)
inline constexpr int overtravel_minus = 501;        // stored stroke limit − (OT501)
inline constexpr int user_alarm_first = 3000;       // #3000 = n: alarm 3000 + n (macro alarm, n < 1000)
inline constexpr int user_alarm_last = 3999;
// SPINNER's own (reference/mcodes.md §3.3; they lie in the #3000 range, as the builder's macros do).
inline constexpr int spinner_part_not_clamped = 3011;   // 3011 PART NOT CLAMPED (G38/G138/G238, G384 mode)
inline constexpr int spinner_illegal_command = 3012;    // 3012 ILLEGAL COMMAND

// kerf's own alarms (runs that stop) ...
inline constexpr int step_limit = 90001;     // the run's step limit: an endless loop?
inline constexpr int syntax_error = 90002;   // a block with syntax errors in a strict (not lenient) run
inline constexpr int internal = 90003;       // a tree the evaluator does not know (macro M0901)
inline constexpr int move_limit = 90004;     // the run's move limit (Setup::move_limit, machine switch max_moves)
inline constexpr int time_limit = 90005;     // the run's wall-clock limit (RunOptions::time_limit)
inline constexpr int unknown_variable = 90006;   // a system variable kerf's tables do not have (K5009)
// ... and warnings (`message` events that do not stop the run; docs/trace.md).
inline constexpr int thread_speed_over_limit = 90101;   // lead × rpm over the machine's maximum cutting feed
inline constexpr int not_modelled = 90102;              // the dry run does not model what the block does (K5009)
inline constexpr int program_repeats = 90103;           // M99 ended a pass of the main program (a bar-feed loop)

struct AlarmDef {
    int number;
    std::string_view name;   // the constant's name above
    std::string_view what;   // docs/diagnostics.md's "what" column
};

// Every number above, in order (docs/diagnostics.md "Alarms the dry run raises").
inline constexpr AlarmDef kAlarms[] = {
    {improper_command, "improper_command", "a G code the dialect does not have; G10 without a valid P or register number"},
    {feed_zero, "feed_zero", "a feed move (G01/G02/G03) with no feed rate commanded (F0, or no F yet)"},
    {arc_radius_mismatch, "arc_radius_mismatch", "arc end point off its circle, or R too small for the chord"},
    {offset_number, "offset_number", "an offset number the machine does not have (G54.1 P, G10 L10–L13/L20 P)"},
    {comp_in_arc, "comp_in_arc", "radius compensation started or cancelled in a G02/G03 block"},
    {comp_interference, "comp_interference", "over-cut in cutter / nose radius compensation"},
    {reference_point_number, "reference_point_number", "G30 P not 1 to 4"},
    {drawing_no_move, "drawing_no_move", "direct drawing: no move after a chamfer or corner"},
    {drawing_not_g01, "drawing_not_g01", "direct drawing: the block after a chamfer or corner is not G01"},
    {drawing_corner_lines, "drawing_corner_lines", "direct drawing: a corner without a line on both sides, or too large for them"},
    {drawing_angle_only, "drawing_angle_only", "direct drawing: an angle-only block not followed by a G01 with an end point"},
    {drawing_no_intersection, "drawing_no_intersection", "direct drawing: the lines do not meet"},
    {profile_sequence, "profile_sequence", "G70–G73 P/Q: the sequence number is not in the program"},
    {cycle_value, "cycle_value", "a cycle's depth, step or thread height missing, zero or negative"},
    {profile_not_monotonic, "profile_not_monotonic", "G71/G72 profile not monotonic"},
    {profile_no_move, "profile_no_move", "G70–G73 profile without a move"},
    {program_number_missing, "program_number_missing", "M98, G65 or G66 without a program number"},
    {call_nesting, "call_nesting", "subprogram or macro calls nested too deep"},
    {program_not_found, "program_not_found", "the called program, or the N label of M98 Q / M99 P, is not there"},
    {macro_overflow, "macro_overflow", "macro result out of range (M0111)"},
    {macro_division_by_zero, "macro_division_by_zero", "division by zero (M0112)"},
    {macro_format, "macro_format", "malformed expression or condition (M0114)"},
    {macro_variable_number, "macro_variable_number", "variable number out of range or undefined (M0115)"},
    {macro_write_protected, "macro_write_protected", "write to a read-only variable (M0116)"},
    {macro_bracket_nesting, "macro_bracket_nesting", "brackets nested deeper than 5 levels (M0118)"},
    {macro_argument, "macro_argument", "illegal function argument (M0119)"},
    {loop_nesting, "loop_nesting", "WHILE/DO nested deeper than 3, or DO/END unmatched"},
    {loop_number, "loop_number", "DO m with m not 1, 2 or 3"},
    {goto_target, "goto_target", "GOTO n: no sequence number n in the program"},
    {scaling_magnification, "scaling_magnification", "G51 magnification not allowed"},
    {polar_conditions, "polar_conditions", "G112/G113 while an offset is held"},
    {polar_improper_code, "polar_improper_code", "a code not allowed in polar coordinate interpolation"},
    {cylinder_axis, "cylinder_axis", "cylindrical interpolation on an axis that is not rotary"},
    {cylinder_improper_code, "cylinder_improper_code", "a code not allowed in cylindrical interpolation"},
    {lead_level, "lead_level", "G34: the lead reaches zero before the end"},
    {overtravel_plus, "overtravel_plus", "stored stroke limit, + side (OT500)"},
    {overtravel_minus, "overtravel_minus", "stored stroke limit, − side (OT501)"},
    {user_alarm_first, "user_alarm_first", "#3000 = n: macro alarm 3000 + n (n 0–999)"},
    {spinner_part_not_clamped, "spinner_part_not_clamped", "SPINNER 3011 PART NOT CLAMPED"},
    {spinner_illegal_command, "spinner_illegal_command", "SPINNER 3012 ILLEGAL COMMAND"},
    {user_alarm_last, "user_alarm_last", "the last macro alarm number"},
    {step_limit, "step_limit", "kerf: the run's step limit (an endless loop?)"},
    {syntax_error, "syntax_error", "kerf: a block with syntax errors in a strict run"},
    {internal, "internal", "kerf: an internal evaluation error (M0901)"},
    {move_limit, "move_limit", "kerf: the run's move limit (machine switch `max_moves`)"},
    {time_limit, "time_limit", "kerf: the run's wall-clock limit (`--time-limit`, `[limits] time_limit`)"},
    {unknown_variable, "unknown_variable", "kerf: a system variable kerf's tables do not have (the control may have it; the run stops)"},
    {thread_speed_over_limit, "thread_speed_over_limit", "kerf warning: a thread's lead × rpm over the maximum cutting feed"},
    {not_modelled, "not_modelled", "kerf warning: the dry run does not model what the block does"},
    {program_repeats, "program_repeats", "kerf note: M99 ended a pass of the main program; the control starts it again (bar feeder)"},
};

// kerf's own alarms, warnings and notes (90001 and up): no control shows them, so no dialect's
// [alarms] table maps them (dialects/SCHEMA.md).
constexpr bool is_kerf_own(int number) { return number >= 90000; }

// The number of the alarm whose constant is named `name` ("program_not_found" → 78), or 0: the
// names a dialect's [alarms] table maps to the control's own numbers (dialects/SCHEMA.md).
constexpr int number_of(std::string_view name) {
    for (const AlarmDef& a : kAlarms)
        if (a.name == name) return a.number;
    return 0;
}

}  // namespace kerf::alarms
