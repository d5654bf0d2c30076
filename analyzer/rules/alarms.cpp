// Rules whose findings are the alarms of the dry run (interpreter/executor*.cpp raise them with
// the FANUC numbers): the run stops at the first one, so each file shows at most one of these.
#include "analyzer/rules/common.hpp"
#include "dialects/alarms.hpp"

namespace kerf::analyzer::rules {

void add_alarms(Registry& r) {
    using S = Severity;
    // The run bounds have kerf's own alarm numbers (interpreter/events.hpp kerf_alarm), so no other
    // alarm of the run reads as an endless loop.
    namespace ka = interpreter::kerf_alarm;
    r.add(alarm_rule("K4004", "endless-loop", Category::macro, S::error,
        {{ka::step_limit, ka::step_limit}, {ka::move_limit, ka::move_limit}, {ka::time_limit, ka::time_limit}},
        {"The dry run reached one of its bounds (blocks executed, moves emitted, seconds): a loop that never ends, "
         "or a cycle whose step is far smaller than its stroke.",
         "On the machine the program never finishes (or repeats cuts forever).",
         "N1 GOTO 1", "#1=0\nWHILE [#1 LT 3] DO 1\n#1=#1+1\nEND 1",
         "interpreter/run_guard.hpp (Setup::step_limit, Setup::move_limit, RunOptions::time_limit)"}));
    r.add(alarm_rule("K4005", "macro-evaluation-error", Category::macro, S::error, {{alarms::macro_overflow, alarms::macro_overflow}, {alarms::macro_format, alarms::macro_format}, {alarms::macro_bracket_nesting, alarms::macro_argument}},
        {"A macro expression the control cannot evaluate: overflow, format, variable number, nesting, bad argument.",
         "The control stops with alarm 111, 114, 118 or 119.", "#1=SQRT[-1]", "#1=SQRT[1]",
         "interpreter/macro/evaluate.hpp"}));
    r.add(alarm_rule("K4006", "user-alarm", Category::macro, S::warning, {{alarms::user_alarm_first, alarms::user_alarm_last}},
        {"The program raised its own alarm with #3000 during the dry run.",
         "The control stops with the programmed message (with the default machine and variables of the dry run).",
         "#3000=1(NO TOOL)", "IF [#20 EQ #0] THEN #3000=1(NO TOOL)", "dialects.md §3.7 #3000"}));
    r.add(alarm_rule("K4007", "call-nesting-too-deep", Category::references, S::error, {{alarms::call_nesting, alarms::call_nesting}},
        {"Subprogram or macro calls nested deeper than the control allows.", "The control stops with alarm 077.",
         "O1000 calling itself with M98 P1000", "a loop with WHILE instead of recursion", "dialects.md §3.6"}));
    r.add(alarm_rule("K4008", "call-without-program", Category::references, S::error, {{alarms::program_number_missing, alarms::program_number_missing}},
        {"M98, G65 or G66 without the program number P.", "The control stops with alarm 076.",
         "G65 A1. B2.", "G65 P9000 A1. B2.", "dialects.md §3.6, §3.7"}));
    r.add(alarm_rule("K4009", "call-target-not-found", Category::references, S::error, {{alarms::program_not_found, alarms::program_not_found}},
        {"At run time a call or return found no target: M98 P program, M98 Q label or M99 P label.",
         "The control stops with alarm 078.", "M99 P50 (no N50 in the caller)", "M99 P40", "dialects.md §3.6"}));
    r.add(alarm_rule("K4010", "data-input-out-of-range", Category::dialect, S::error, {{alarms::improper_command, alarms::improper_command}},
        {"G10 without P or with a register number the machine does not have.", "The control stops with an alarm.",
         "G10 L2 P9 X0.", "G10 L2 P1 X0.", "semantics.md §2.6"}));
    r.add(alarm_rule("K4011", "reference-point-number", Category::dialect, S::error, {{alarms::reference_point_number, alarms::reference_point_number}},
        {"G30 with P other than 1 to 4.", "The control stops with alarm 046.", "G30 P5 Z0.", "G30 P3 Z0.",
         "semantics.md §2.8"}));
    r.add(alarm_rule("K4099", "interpreter-alarm", Category::dialect, S::error, {{1, 99999}},
        {"Any other alarm of the dry run, one without a rule of its own (alarm 115: variable number out of range ...; "
         "kerf's own 90003: an expression the interpreter cannot evaluate).",
         "The control stops at this block.", "#1=#[-5]", "#1=#5",
         "interpreter/executor*.cpp"}));
    r.add(alarm_rule("K5014", "arc-radius-mismatch", Category::motion, S::error, {{20, 21}},
        {"An arc whose start and end radius differ beyond the tolerance, or whose R is smaller than half the chord.",
         "The control stops with alarm 020, or cuts a different arc.", "G02 X20. Z-10. R2.", "G02 X20. Z-10. R10.",
         "semantics.md §3"}));
    r.add(alarm_rule("K5023", "compensation-overcut", Category::motion, S::error, {{alarms::comp_interference, alarms::comp_interference}},
        {"Cutter or nose radius compensation cannot follow a segment: it is shorter than the radius allows, or an "
         "inside arc is smaller than the radius (the offset path would run backwards and cut into the part).",
         "The control stops with alarm 041 (interference) before the block.",
         "G41 D1 (R5) in an 8 x 8 pocket", "a smaller tool, or a pocket wider than the cutter", "semantics.md §6"}));
    r.add(alarm_rule("K5015", "soft-limit", Category::motion, S::error, {{alarms::overtravel_plus, alarms::overtravel_minus}},
        {"A move beyond the machine's stored stroke limit.", "The control stops with OT500/OT501 before the axis hits the stop.",
         "G00 X900.", "G00 X200.", "machine/SCHEMA.md soft limits; semantics.md §2"}));
}

}  // namespace kerf::analyzer::rules
