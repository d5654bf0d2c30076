// The trace: one event per motion or state change, each pointing back to its source block. Every
// consumer (CLI trace, plot, analyzer, language server, converter check) reads these events, so
// what they show cannot disagree (design.md "One interpreter").
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "ast/source.hpp"

namespace kerf::interpreter {

// Axes in a fixed order; positions are in work coordinates as programmed (lathe X as diameter).
enum class Axis : std::uint8_t { x, y, z, a, b, c };
inline constexpr std::size_t kAxisCount = 6;
inline constexpr char kAxisLetters[kAxisCount] = {'X', 'Y', 'Z', 'A', 'B', 'C'};
std::optional<Axis> axis_of_letter(char letter);

using Position = std::array<double, kAxisCount>;

struct SourceRef {
    std::uint32_t file = 0;     // index into the run's file table (RunResult::files)
    ast::Range range;           // the block
    std::uint32_t line = 0;     // 1-based line of the block start
};

enum class EventKind : std::uint8_t {
    rapid, linear, arc_cw, arc_ccw, thread, dwell,
    tool_change, spindle, coolant, coordinate_change, feed_mode,
    stop, optional_stop, end, alarm, message, call, return_,
    state,   // the modal state after a block (RunOptions::emit_state): text "G00 G18 ... F S T"
};
const char* to_string(EventKind k);

// Alarm numbers of kerf's own (check3), outside FANUC's ranges (PS/macro 000–5999 incl. #3000 user
// alarms and SPINNER 3011/3012, OT500/501), so a consumer can tell them from the control's alarms
// (docs/trace.md "Alarms").
namespace kerf_alarm {
inline constexpr int step_limit = 90001;     // the run's step limit: an endless loop?
inline constexpr int syntax_error = 90002;   // a block with syntax errors in a strict (not lenient) run
inline constexpr int internal = 90003;       // a tree the evaluator does not know (macro M0901)
inline constexpr int move_limit = 90004;     // the run's move limit (Setup::move_limit): a cycle or loop without end?
inline constexpr int time_limit = 90005;     // the run's wall-clock limit (RunOptions::time_limit)
// A system variable (#1000 and up) the interpreter's tables do not have: the control may well have
// it (O8200 reads #3101 as π), so the run stops there as kerf's limit, not the program's alarm 115.
inline constexpr int unknown_variable = 90006;
// The alarms that end a run at one of its bounds (interpreter/run_guard.hpp), not at a defect of
// the program at that block: the formatter's --verify compares two runs only up to them.
inline constexpr bool is_run_limit(int code) {
    return code == step_limit || code == move_limit || code == time_limit || code == unknown_variable;
}
}  // namespace kerf_alarm

// Codes of kerf's warning messages (`message` events that do not stop the run; docs/trace.md).
namespace kerf_warning {
// A thread's axis speed, lead × rpm (the larger lead of a G34), is over the machine's maximum
// cutting feed (cycles.md §9): the control cannot keep the lead at that speed.
inline constexpr int thread_speed_over_limit = 90101;
// The dry run does not model what the block does (a code whose meaning the reference leaves open,
// a cycle or motion no part of the interpreter expands): the trace is not the machine's there, and
// the analyzer's K5009 says so.
inline constexpr int not_modelled = 90102;
// M99 ended a pass of the main program: the control starts it again (a bar-feed loop); the dry
// run stops after RunOptions::passes passes and says so (times are for the passes run).
inline constexpr int program_repeats = 90103;
}  // namespace kerf_warning

struct Event {
    EventKind kind = EventKind::rapid;
    SourceRef source;
    Position start{};                    // motion: where it starts (work coordinates, program units)
    Position end{};                      // motion: where it ends; other events: the position then
    bool inch = false;                   // start, end, center, feed are in inches (G20, C: G70): the program's unit
    Position machine_end{};              // `end` in machine coordinates (offsets, shift, G52, G50 applied)
    std::optional<Position> center;      // arcs: the centre (X as diameter on lathes, like end)
    double radius = 0;                   // arcs
    double length_mm = 0;                // path length of the move
    double time_s = 0;                   // estimated time of this event
    double feed = 0;                     // motion: programmed feed (mm/min or mm/rev, see feed_per_rev)
    double lead_end = 0;                 // thread: the lead at the end (G34 variable lead; = feed otherwise)
    bool feed_per_rev = false;
    double spindle_rpm = 0;              // the rpm the time uses (G96: at the end point)
    bool spindle_running = true;         // feed moves: false when the spindle is stopped (M05); spindle: M03/M04 vs M05
    int tool = 0;                        // tool_change: the tool number; otherwise the active tool
    int code = 0;                        // alarm number, M code, call target ...
    // alarm: the number the control shows when its dialect numbers the alarm itself ([alarms],
    // dialects/SCHEMA.md: Haas NGC); 0 when it shows `code` (FANUC's numbering). `code` stays kerf's
    // number, the alarm's identity for the analyzer's rules and --verify.
    int control_alarm = 0;
    std::string text;                    // alarm/message text, DPRNT output
};

}  // namespace kerf::interpreter
